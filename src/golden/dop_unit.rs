//! The DOP unit (DATE'05 Eq. 10, Fig. 3): k DOPTRF lanes fed by D.KLMSEL, their flags
//! NOR-reduced: B's node overlaps A's unless some lane says "separated".

use super::doptrf::{lane, separated, transformed};
use super::enclosure::checking;
use super::host::{DopLanes, HostSetup, Lane};
use std::borrow::Cow;
use super::klmsel::{klmsel, opposite};
use super::memory::Held;
use crate::dop::{Dop, DopTree};
use crate::format::{Format, Rounding};
use std::cell::{Cell, OnceCell};

/// B's transformed DOPs during one query, computed on a node's first test (or at every
/// test, [`forget_rows`](TransformCache::forget_rows)): per lane an
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
    /// The lanes' words (`j`, `cmat`, `cvec`); [`lazy`](TransformCache::lazy): filled in
    /// once `pending` is done.
    setup: Cow<'a, HostSetup>,
    /// The lanes still to compute, and the mirror pairs computed so far.
    pending: Option<(DopLanes, Vec<[Lane; 2]>)>,
    k: usize,
    q: f64,
    rel: f64,
    /// B's rows transformed so far, kept for the thread's next query when this one ends.
    rows: Rows,
    /// Keep a node's rows for the query (false: one block, refilled by every test).
    memo: bool,
    /// A's and B's DOP trees.
    trees: [&'a DopTree; 2],
    /// A's DOPs last read (a leaf's is computed from its triangle when read, an inner node's
    /// widened from its stored format, and an A node meets several of B's in a row).
    held: Held<Dop>,
}

impl<'a> TransformCache<'a> {
    pub fn new(f: Format, r: Rounding, setup: &'a HostSetup, a: &'a DopTree, b: &'a DopTree) -> Self {
        Self::with(f, r, Cow::Borrowed(setup), None, a, b)
    }

    fn with(f: Format, r: Rounding, setup: Cow<'a, HostSetup>, lanes: Option<DopLanes>, a: &'a DopTree, b: &'a DopTree) -> Self {
        let k = lanes.as_ref().map_or(setup.j.len(), |l| l.k());
        let p = f.frac_bits() as i32 + 1;
        TransformCache {
            f,
            r,
            setup,
            pending: lanes.map(|l| (l, vec![])),
            k,
            q: f.min_positive_subnormal(),
            rel: 2f64.powi(4 - p) + 2f64.powi(-50),
            rows: Rows::take(b.len()),
            memo: true,
            trees: [a, b],
            held: SPARE_HELD.take(),
        }
    }

    /// With lanes computed when first needed, a mirror pair at a time (`frames`: the setup
    /// without lanes, [`HostSetup::frames`]): the first test computes pairs until a lane is
    /// surely separated, so that a query ending at the root pays for few cone searches.
    pub fn lazy(f: Format, r: Rounding, frames: &HostSetup, lanes: DopLanes, a: &'a DopTree, b: &'a DopTree) -> Self {
        Self::with(f, r, Cow::Owned(frames.clone()), Some(lanes), a, b)
    }

    /// The DOP's size.
    pub fn k(&self) -> usize {
        self.k
    }

    /// Transforms B's DOP anew at every test, as WSCG'03 Algorithm 1 does in software: the
    /// recursive traversal's time then is that algorithm's (the decisions are the same).
    pub fn forget_rows(&mut self) {
        self.memo = false;
    }

    /// The DOP unit: does B's node `nb` overlap A's node `na`? First every lane's estimate
    /// at once (a loop the compiler vectorises), then the exact value of the lanes the
    /// estimate leaves open, if no lane is surely separated. B's DOP is read only where a
    /// lane needs it (mostly its node's first test: its rows are then kept), A's through
    /// [`Held`] lines. In check mode ([`checking`]) the answer is compared with
    /// [`dop_overlap`]'s.
    pub fn overlap(&mut self, nb: u32, na: u32) -> bool {
        let [a, b] = self.trees;
        let d = LazyDop { tree: b, n: nb, dop: OnceCell::new() };
        let e = *self.held.get(na, || a.dop(na));
        let overlap = !(self.pending.is_some() && self.lazy_separated(d.get(), &e)) && {
            self.complete();
            self.estimated(&d, &e)
        };
        if checking() {
            self.complete();
            // A's DOP read anew, not the held one: the check covers the held lines too.
            let (d, e) = (b.dop(nb), a.dop(na));
            let want = dop_overlap(self.f, self.r, &self.setup, &d, &e);
            assert_eq!(overlap, want, "check mode: the DOP unit's estimate said overlap = {overlap}, the lanes {want}: d {d:?}, e {e:?}");
        }
        overlap
    }

    /// Computes pending mirror pairs until a lane is surely separated (true), or all are.
    fn lazy_separated(&mut self, d: &[f64], e: &[f64]) -> bool {
        let (h, q, est) = (self.k / 2, self.q, self.estimator());
        let Some((lanes, pairs)) = &mut self.pending else { return false };
        while pairs.len() < h {
            let i = pairs.len();
            let p = lanes.pair(i);
            pairs.push(p);
            for (l, ei) in [(p[0], e[i + h]), (p[1], e[i])] {
                let (a, t0) = est.lane(d, l.j, l.c, l.cv);
                if flags(q, a, t0, ei).0 {
                    return true;
                }
            }
        }
        false
    }

    /// Every lane computed (lane 0 first: the first halves of the pairs, then the mirrors).
    fn complete(&mut self) {
        if let Some((lanes, mut pairs)) = self.pending.take() {
            let h = self.k / 2;
            pairs.extend((pairs.len()..h).map(|i| lanes.pair(i)));
            let all: Vec<Lane> = pairs.iter().map(|p| p[0]).chain(pairs.iter().map(|p| p[1])).collect();
            self.setup.to_mut().set_lanes(&all);
        }
    }

    /// [`overlap`](Self::overlap) with every lane's words known.
    fn estimated(&mut self, d: &LazyDop, e: &[f64]) -> bool {
        let (k, h) = (self.k, self.k / 2);
        let block = self.block(d);
        let base = block * k;
        let (approx, err) = (&self.rows.approx[base..base + k], &self.rows.err[base..base + k]);
        // Lane i meets e_opp(i): the first half e[h..], the second e[..h].
        // Most pairs are separated: the second half waits for the first's answer.
        let (s1, o1) = scan(self.q, &approx[..h], &err[..h], &e[h..]);
        let overlap = !s1 && {
            let (s2, o2) = scan(self.q, &approx[h..], &err[h..], &e[..h]);
            !s2 && (!(o1 | o2) || self.exact_lanes(block, d, e))
        };
        overlap
    }

    /// The lanes the estimate leaves open, bit for bit: false if one is separated.
    #[cold]
    fn exact_lanes(&mut self, block: usize, d: &LazyDop, e: &[f64]) -> bool {
        let (base, rows) = (block * self.k, &mut self.rows);
        for i in 0..self.k {
            let ei = opposite(e, i);
            if !flags(self.q, rows.approx[base + i], rows.err[base + i], ei).1 {
                continue;
            }
            let known = &mut rows.blocks[block].known;
            if *known & (1 << i) == 0 {
                let di = klmsel(d.get(), self.setup.j[i]);
                rows.exact[base + i] = transformed(self.f, self.r, di, self.setup.cmat[i], self.setup.cvec[i]);
                *known |= 1 << i;
            }
            if separated(self.q, rows.exact[base + i], ei) {
                return false;
            }
        }
        true
    }

    /// The block of B's node `nb`, transformed on its first test.
    fn block(&mut self, d: &LazyDop) -> usize {
        if !self.memo {
            self.rows.forget();
            return self.fill(d);
        }
        match self.rows.slot[d.n as usize] {
            u32::MAX => {
                let b = self.fill(d);
                self.rows.slot[d.n as usize] = b as u32;
                b
            }
            b => b as usize,
        }
    }

    fn fill(&mut self, d: &LazyDop) -> usize {
        let (k, rows) = (self.k, &mut self.rows);
        let (block, base) = (rows.blocks.len(), rows.approx.len());
        rows.blocks.push(Block { node: d.n, known: 0 });
        rows.approx.resize(base + k, 0.0);
        rows.err.resize(base + k, 0.0);
        rows.exact.resize(base + k, 0.0);
        let est = self.estimator();
        let (d, rows) = (d.get(), &mut self.rows);
        let lanes = self.setup.j.iter().zip(&self.setup.cmat).zip(&self.setup.cvec);
        for ((a, t), ((j, cm), &c)) in rows.approx[base..].iter_mut().zip(&mut rows.err[base..]).zip(lanes) {
            (*a, *t) = est.lane(d, *j, *cm, c);
        }
        block
    }

    fn estimator(&self) -> Estimator {
        Estimator { max: self.f.max_finite() / 8.0, rel: self.rel, q8: 8.0 * self.q }
    }
}

/// B's node DOP, read from its tree when a lane first needs it: a leaf's is computed from its
/// triangle ([`DopTree::dop`]), and most tests find B's rows already transformed.
struct LazyDop<'t> {
    tree: &'t DopTree,
    n: u32,
    dop: OnceCell<Dop>,
}

impl LazyDop<'_> {
    fn get(&self) -> &[f64] {
        self.dop.get_or_init(|| self.tree.dop(self.n))
    }
}

/// B's transformed rows during one query, a block of k lanes per node: per lane the f64
/// estimate, its bound and (once a test needed it) the chip's value. Kept per thread for
/// the next query, emptied, so that a query does not pay for allocating them anew and the
/// pages the allocator returned to the system (a quarter of a contact query's time before);
/// one larger than [`SPARE_BYTES`] is freed.
#[derive(Default)]
struct Rows {
    /// Per B node, its block (u32::MAX: not transformed in this query).
    slot: Vec<u32>,
    approx: Vec<f64>,
    err: Vec<f64>,
    exact: Vec<f64>,
    blocks: Vec<Block>,
}

/// A transformed node and its lanes whose exact value is in [`Rows::exact`].
struct Block {
    node: u32,
    known: u32,
}

/// The largest [`Rows`] a thread keeps between queries.
const SPARE_BYTES: usize = 8 << 20;

thread_local! {
    static SPARE_ROWS: Cell<Rows> = Cell::default();
    static SPARE_HELD: Cell<Held<Dop>> = Cell::default();
}

impl Rows {
    /// The thread's spare rows for a tree of `nodes` nodes.
    fn take(nodes: usize) -> Rows {
        let mut rows = SPARE_ROWS.take();
        if rows.slot.len() != nodes {
            rows.slot = vec![u32::MAX; nodes];
        }
        rows
    }

    /// Every block dropped (its nodes untransformed).
    fn forget(&mut self) {
        for b in &self.blocks {
            self.slot[b.node as usize] = u32::MAX;
        }
        self.blocks.clear();
        self.approx.clear();
        self.err.clear();
        self.exact.clear();
    }

    fn bytes(&self) -> usize {
        4 * self.slot.capacity() + 8 * (self.approx.capacity() + self.err.capacity() + self.exact.capacity()) + 8 * self.blocks.capacity()
    }
}

impl Drop for TransformCache<'_> {
    fn drop(&mut self) {
        let mut rows = std::mem::take(&mut self.rows);
        rows.forget();
        if rows.bytes() <= SPARE_BYTES {
            SPARE_ROWS.set(rows);
        }
        SPARE_HELD.set(std::mem::take(&mut self.held).emptied());
    }
}

/// A lane's f64 estimate of u_i and its bound (the bound above).
#[derive(Clone, Copy)]
struct Estimator {
    max: f64,
    rel: f64,
    q8: f64,
}

impl Estimator {
    #[inline(always)]
    fn lane(&self, d: &[f64], j: [u8; 3], cm: [f64; 3], c: f64) -> (f64, f64) {
        let dj = klmsel(d, j);
        let p = [dj[0] * cm[0], dj[1] * cm[1], dj[2] * cm[2]];
        let s = p[0].abs() + p[1].abs() + p[2].abs() + c.abs();
        ((p[0] + p[1]) + (p[2] + c), if s <= self.max { self.rel * s + self.q8 } else { f64::NAN })
    }
}

/// 2^-52: the f64 addition of a lane's estimate and e, and its bound.
const EPS: f64 = f64::EPSILON;

/// Lanes with estimates `approx` (bounds `err`) against A's distances `e`: is one surely
/// separated (`approx + e` below -q by more than its bound), is one open (neither surely
/// separated nor surely not; a NaN bound leaves its lane open)? Branch-free, vectorised.
#[inline(always)]
fn scan(q: f64, approx: &[f64], err: &[f64], e: &[f64]) -> (bool, bool) {
    let (mut sure, mut open) = (false, false);
    for ((&a, &t0), &ei) in approx.iter().zip(err).zip(e) {
        let (s, o) = flags(q, a, t0, ei);
        sure |= s;
        open |= o;
    }
    (sure, open)
}

/// One lane: surely separated, open.
#[inline(always)]
fn flags(q: f64, a: f64, t0: f64, ei: f64) -> (bool, bool) {
    let x = a + ei;
    let t = t0 + EPS * (x.abs() + ei.abs());
    (x <= -q - t, !(x > -q + t))
}

/// The DOP unit, lane by lane as the pipeline computes it (the reference for the RTL).
pub fn dop_overlap(f: Format, r: Rounding, setup: &HostSetup, d: &[f64], e: &[f64]) -> bool {
    (0..d.len()).all(|i| {
        let s = lane(f, r, klmsel(d, setup.j[i]), setup.cmat[i], setup.cvec[i], opposite(e, i));
        let flag = s < 0.0;
        !flag
    })
}
