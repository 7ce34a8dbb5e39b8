//! The DOP unit (DATE'05 Eq. 10, Fig. 3): k DOPTRF lanes fed by D.KLMSEL, their flags
//! NOR-reduced: B's node overlaps A's unless some lane says "separated".

use super::doptrf::{lane, separated, transformed};
use super::host::HostSetup;
use super::klmsel::{klmsel, opposite};
use crate::format::{Format, Rounding};

/// B's transformed DOPs during one query, computed on a node's first test (or at every
/// test, [`without_memo`](TransformCache::without_memo)): per lane an
/// f64 estimate `approx` of u_i with a bound `err` on |u_i - approx|, and the exact u_i
/// (the chip's value, [`transformed`]) only for the lanes whose flag falls within the bound.
/// The decisions equal [`dop_overlap`]'s bit for bit (tested); this only saves time.
///
/// The bound: the products d C are exact in f64 (significands of at most 25 bits), the
/// three f64 additions are off by at most 2^-50 S with S = |p0| + |p1| + |p2| + |c|, and each
/// of the chip's six roundings by at most one ulp, 2^(1-p) |x| + q (precision p, smallest
/// subnormal q): in all at most 2^(4-p) S + 8q, generously. A non-finite S (inf, NaN or
/// possible overflow) has no bound: those lanes always take the exact path.
pub struct TransformCache<'a> {
    f: Format,
    r: Rounding,
    setup: &'a HostSetup,
    k: usize,
    q: f64,
    rel: f64,
    /// Per B node, the index of its block of k lanes (u32::MAX: not yet computed).
    slot: Vec<u32>,
    approx: Vec<f64>,
    err: Vec<f64>,
    exact: Vec<f64>,
    /// Per block, the lanes whose exact value is in `exact`.
    known: Vec<u32>,
    /// Keep a node's rows for the query (false: one block, refilled by every test).
    memo: bool,
}

impl<'a> TransformCache<'a> {
    pub fn new(f: Format, r: Rounding, setup: &'a HostSetup, nodes: usize) -> Self {
        let k = setup.j.len();
        let p = f.frac_bits() as i32 + 1;
        TransformCache {
            f,
            r,
            setup,
            k,
            q: f.min_positive_subnormal(),
            rel: 2f64.powi(4 - p) + 2f64.powi(-50),
            slot: vec![u32::MAX; nodes],
            approx: vec![],
            err: vec![],
            exact: vec![],
            known: vec![],
            memo: true,
        }
    }

    /// Transforms B's DOP anew at every test, as WSCG'03 Algorithm 1 does in software: the
    /// recursive traversal's time then is that algorithm's (the decisions are the same).
    pub fn without_memo(self) -> Self {
        TransformCache { memo: false, ..self }
    }

    /// The DOP unit: does B's node `nb` (DOP `d`) overlap A's DOP `e`?
    pub fn overlap(&mut self, nb: u32, d: &[f64], e: &[f64]) -> bool {
        let k = self.k;
        let block = match self.slot[nb as usize] {
            u32::MAX => self.fill(nb, d),
            b => b as usize,
        };
        let base = block * k;
        for i in 0..k {
            let ei = opposite(e, i);
            let x = self.approx[base + i] + ei;
            // NaN bounds fail both comparisons: exact path.
            let t = self.err[base + i] + 2f64.powi(-52) * (x.abs() + ei.abs());
            if x <= -self.q - t {
                return false;
            }
            if x > -self.q + t {
                continue;
            }
            if self.known[block] & (1 << i) == 0 {
                let di = klmsel(d, self.setup.j[i]);
                self.exact[base + i] = transformed(self.f, self.r, di, self.setup.cmat[i], self.setup.cvec[i]);
                self.known[block] |= 1 << i;
            }
            if separated(self.q, self.exact[base + i], ei) {
                return false;
            }
        }
        true
    }

    fn fill(&mut self, nb: u32, d: &[f64]) -> usize {
        if self.memo {
            self.slot[nb as usize] = self.known.len() as u32;
        } else {
            self.approx.clear();
            self.err.clear();
            self.known.clear();
        }
        let block = self.known.len();
        self.known.push(0);
        let max = self.f.max_finite() / 8.0;
        for ((j, cm), &c) in self.setup.j.iter().zip(&self.setup.cmat).zip(&self.setup.cvec) {
            let dj = klmsel(d, *j);
            let p = [dj[0] * cm[0], dj[1] * cm[1], dj[2] * cm[2]];
            self.approx.push((p[0] + p[1]) + (p[2] + c));
            let s = p[0].abs() + p[1].abs() + p[2].abs() + c.abs();
            self.err.push(if s <= max { self.rel * s + 8.0 * self.q } else { f64::NAN });
        }
        self.exact.resize(self.approx.len(), 0.0);
        block
    }
}

/// The DOP unit, lane by lane as the pipeline computes it (the reference for the RTL).
pub fn dop_overlap(f: Format, r: Rounding, setup: &HostSetup, d: &[f64], e: &[f64]) -> bool {
    (0..d.len()).all(|i| {
        let s = lane(f, r, klmsel(d, setup.j[i]), setup.cmat[i], setup.cvec[i], opposite(e, i));
        let flag = s < 0.0;
        !flag
    })
}
