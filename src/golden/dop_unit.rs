//! The DOP unit (DATE'05 Eq. 10, Fig. 3): k DOPTRF lanes fed by D.KLMSEL, their flags
//! NOR-reduced: B's node overlaps A's unless some lane says "separated".

use super::doptrf::{lane, separated, transformed};
use super::enclosure::{checking, count_checked};
use super::host::{DopLanes, HostSetup, Lane};
use super::klmsel::{klmsel, opposite};
use super::memory::Held;
use crate::dop::normals::HALF_LANES;
use crate::dop::{Dop, DopTree};
use crate::format::{Format, Rounding};
use std::borrow::Cow;
use std::cell::Cell;

/// B's transformed DOPs during one query, computed on a node's first test (or at every
/// test, [`forget_rows`](TransformCache::forget_rows)): per lane two f64 thresholds that
/// provably enclose -q - u_i, u_i the chip's value ([`transformed`]), and u_i itself only
/// for the lanes whose flag the thresholds leave open. The decisions equal
/// [`dop_overlap`]'s bit for bit (proof: docs/explanation/accuracy.md, "The DOP unit in f64"; checked
/// in check mode, [`checking`]); this only saves time.
pub struct TransformCache<'a> {
    /// A's DOPs last read (a leaf's is computed from its triangle when read, an inner node's
    /// widened from its stored format, and an A node meets several of B's in a row), kept
    /// for the thread's next query of the same object. Beside the rest, so that a test reads
    /// A's DOP in place while it works on B's side.
    held: Held<Dop>,
    b: BSide<'a>,
}

/// The lanes and B's transformed DOPs: the [`TransformCache`] but A's held DOPs.
struct BSide<'a> {
    f: Format,
    r: Rounding,
    /// The lanes' words (`j`, `cmat`, `cvec`); [`lazy`](TransformCache::lazy): filled in
    /// once `pending` is done.
    setup: Cow<'a, HostSetup>,
    /// The same words gathered for [`fill`](BSide::fill)'s loop.
    words: LaneWords,
    /// Lanes per half of a block of [`Rows::thresholds`] ([`half_block`]).
    hb: usize,
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
    /// B's DOP last read, and its node (`u32::MAX`: none).
    b_dop: (u32, Dop),
    /// Check mode ([`checking`]), read once.
    check: bool,
}

impl<'a> TransformCache<'a> {
    pub fn new(
        f: Format,
        r: Rounding,
        setup: &'a HostSetup,
        a: &'a DopTree,
        b: &'a DopTree,
    ) -> Self {
        Self::with(f, r, Cow::Borrowed(setup), None, a, b)
    }

    fn with(
        f: Format,
        r: Rounding,
        setup: Cow<'a, HostSetup>,
        lanes: Option<DopLanes>,
        a: &'a DopTree,
        b: &'a DopTree,
    ) -> Self {
        let k = lanes.as_ref().map_or(setup.j.len(), |l| l.k());
        let p = f.frac_bits() as i32 + 1;
        let hb = half_block(k);
        let b = BSide {
            f,
            r,
            words: LaneWords::of(&setup, hb),
            hb,
            setup,
            pending: lanes.map(|l| (l, vec![])),
            k,
            q: f.min_positive_subnormal(),
            rel: 2f64.powi(4 - p) + 2f64.powi(-50),
            rows: Rows::take(b.len()),
            memo: true,
            trees: [a, b],
            b_dop: (u32::MAX, Dop::default()),
            check: checking(),
        };
        TransformCache {
            held: SPARE_HELD.take().of(a.id()),
            b,
        }
    }

    /// With lanes computed when first needed, a mirror pair at a time (`frames`: the setup
    /// without lanes, [`HostSetup::frames`]): the first test computes pairs until a lane is
    /// surely separated, so that a query ending at the root pays for few cone searches.
    pub fn lazy(
        f: Format,
        r: Rounding,
        frames: &HostSetup,
        lanes: DopLanes,
        a: &'a DopTree,
        b: &'a DopTree,
    ) -> Self {
        Self::with(f, r, Cow::Owned(frames.clone()), Some(lanes), a, b)
    }

    /// The DOP's size.
    pub fn k(&self) -> usize {
        self.b.k
    }

    /// Transforms B's DOP anew at every test, as WSCG'03 Algorithm 1 does in software: the
    /// recursive traversal's time then is that algorithm's (the decisions are the same).
    pub fn forget_rows(&mut self) {
        self.b.memo = false;
    }

    /// The DOP unit: does B's node `nb` overlap A's node `na`? First every lane's interval
    /// at once (a loop the compiler vectorises), then the exact value of the lanes the
    /// intervals leave open, if no lane is surely separated. B's DOP is read only where a
    /// lane needs it (mostly its node's first test: its rows are then kept), A's through
    /// [`Held`] lines. In check mode ([`checking`]) the answer is compared with
    /// [`dop_overlap`]'s.
    pub fn overlap(&mut self, nb: u32, na: u32) -> bool {
        let a = self.b.trees[0];
        let b = &mut self.b;
        let e = self.held.get_in(na, |line| a.dop_into(na, line));
        let overlap = !(b.pending.is_some() && b.lazy_separated(nb, e)) && {
            b.complete();
            b.bounded(nb, e)
        };
        if b.check {
            b.check_overlap(nb, na, overlap);
        }
        overlap
    }

    /// [`prefetch`](crate::dop::prefetch) of what a test of A's node `na` reads first: its
    /// DOP, unless held.
    #[inline]
    pub fn prefetch_a(&self, na: u32) {
        if !self.held.holds(na) {
            self.b.trees[0].prefetch(na);
        }
    }

    /// [`prefetch`](crate::dop::prefetch) of what a test of B's node `nb` reads first: its
    /// rows or, before its first test, its DOP.
    #[inline]
    pub fn prefetch_b(&self, nb: u32) {
        let b = &self.b;
        match b.rows.slot[nb as usize] {
            u32::MAX => b.trees[1].prefetch(nb),
            n => crate::dop::prefetch(
                b.rows
                    .thresholds
                    .as_ptr()
                    .wrapping_add(n as usize * 4 * b.hb),
            ),
        }
    }
}

impl BSide<'_> {
    /// Check mode: `overlap`, the answer for B's node `nb` against A's `na`, is
    /// [`dop_overlap`]'s. A's DOP is read anew, not through the held lines, so that the
    /// check covers those too.
    fn check_overlap(&mut self, nb: u32, na: u32, overlap: bool) {
        self.complete();
        let (d, e) = (self.trees[1].dop(nb), self.trees[0].dop(na));
        let want = dop_overlap(self.f, self.r, &self.setup, &d, &e);
        assert_eq!(overlap, want, "check mode: the DOP unit's thresholds said overlap = {overlap}, the lanes {want}: d {d:?}, e {e:?}");
        count_checked(false);
    }

    /// Computes pending mirror pairs until a lane is surely separated (true), or all are.
    fn lazy_separated(&mut self, nb: u32, e: &[f64]) -> bool {
        let (h, q, est) = (self.k / 2, self.q, self.estimator());
        let d = read(self.trees[1], &mut self.b_dop, nb);
        let Some((lanes, pairs)) = &mut self.pending else {
            return false;
        };
        while pairs.len() < h {
            let i = pairs.len();
            let p = lanes.pair(i);
            pairs.push(p);
            for (l, ei) in [(p[0], e[i + h]), (p[1], e[i])] {
                let dj = klmsel(d, l.j);
                let (set, _) =
                    est.thresholds(q, [dj[0] * l.c[0], dj[1] * l.c[1], dj[2] * l.c[2]], l.cv);
                if flag_surely_set(set, ei) {
                    return true;
                }
            }
        }
        false
    }

    /// Every lane computed (lane 0 first: the first halves of the pairs, then the mirrors).
    #[inline]
    fn complete(&mut self) {
        if self.pending.is_some() {
            self.compute_lanes();
        }
    }

    #[cold]
    fn compute_lanes(&mut self) {
        if let Some((lanes, mut pairs)) = self.pending.take() {
            let h = self.k / 2;
            pairs.extend((pairs.len()..h).map(|i| lanes.pair(i)));
            let all: Vec<Lane> = pairs
                .iter()
                .map(|p| p[0])
                .chain(pairs.iter().map(|p| p[1]))
                .collect();
            self.setup.to_mut().set_lanes(&all);
            self.words = LaneWords::of(&self.setup, self.hb);
        }
    }

    /// [`overlap`](TransformCache::overlap) with every lane's words known, in blocks of
    /// the query's size (one branch, taken alike at every test).
    fn bounded(&mut self, nb: u32, e: &Dop) -> bool {
        match self.hb {
            4 => self.bounded_in::<4>(nb, e),
            8 => self.bounded_in::<8>(nb, e),
            12 => self.bounded_in::<12>(nb, e),
            _ => self.bounded_in::<H>(nb, e),
        }
    }

    /// [`bounded`](Self::bounded) with `HB` lanes per half of a block.
    #[inline(always)]
    fn bounded_in<const HB: usize>(&mut self, nb: u32, e: &Dop) -> bool {
        let h = self.k / 2;
        let block = self.block::<HB>(nb);
        let t = &self.rows.thresholds[block * 4 * HB..][..4 * HB];
        // Lane i meets e_opp(i): the first half e[h..], the second e[..h] (past h, the
        // padding lanes meet what follows, and never decide). Both halves without a branch
        // between them (which one decides is unpredictable).
        let ep = e.padded();
        let (s1, o1) = scan::<HB>(
            &t[..2 * HB],
            ep[h..h + HB].try_into().expect("h + HB <= 2H"),
        );
        let (s2, o2) = scan::<HB>(&t[2 * HB..], ep[..HB].try_into().expect("HB <= 2H"));
        !(s1 | s2) && (!(o1 | o2) || self.exact_lanes(block, nb, e))
    }

    /// The lanes the intervals leave open, bit for bit: false if one is separated.
    #[cold]
    fn exact_lanes(&mut self, block: usize, nb: u32, e: &[f64]) -> bool {
        let (k, rows, q) = (self.k, &mut self.rows, self.q);
        for i in 0..k {
            let ei = opposite(e, i);
            if flag_surely_clear(
                rows.thresholds[block * 4 * self.hb + clear_at(k / 2, self.hb, i)],
                ei,
            ) {
                continue;
            }
            let b = &mut rows.blocks[block];
            if b.exact == u32::MAX {
                b.exact = rows.exact.len() as u32;
                rows.exact.resize(rows.exact.len() + k, 0.0);
            }
            let at = b.exact as usize + i;
            if b.known & (1 << i) == 0 {
                let di = klmsel(read(self.trees[1], &mut self.b_dop, nb), self.setup.j[i]);
                rows.exact[at] =
                    transformed(self.f, self.r, di, self.setup.cmat[i], self.setup.cvec[i]);
                b.known |= 1 << i;
            }
            if separated(q, rows.exact[at], ei) {
                return false;
            }
        }
        true
    }

    /// The block of B's node `nb`, transformed on its first test.
    #[inline(always)]
    fn block<const HB: usize>(&mut self, nb: u32) -> usize {
        if !self.memo {
            self.rows.forget();
            return self.fill::<HB>(nb);
        }
        match self.rows.slot[nb as usize] {
            u32::MAX => {
                let b = self.fill::<HB>(nb);
                self.rows.slot[nb as usize] = b as u32;
                b
            }
            b => b as usize,
        }
    }

    /// Every lane's thresholds at once: the lanes' words and B's DOP in fixed-size arrays
    /// (padding lanes have zero words; `j % 32` selects within k < 32), so that the loop has
    /// no bounds checks and its arithmetic vectorises. Out of line: a node's first test
    /// only, and [`bounded`](Self::bounded) has a copy per block size.
    #[inline(never)]
    fn fill<const HB: usize>(&mut self, nb: u32) -> usize {
        let (k, h, q, est, w) = (self.k, self.k / 2, self.q, self.estimator(), &self.words);
        let mut d = [0.0; 32];
        d[..k].copy_from_slice(read(self.trees[1], &mut self.b_dop, nb));
        // The products gathered first: the thresholds' loop then vectorises.
        let mut p = [[0.0; LANES]; 3];
        for (l, p) in p.iter_mut().enumerate() {
            for (i, p) in p[..2 * HB].iter_mut().enumerate() {
                *p = d[w.j[l][i] as usize % 32] * w.c[l][i];
            }
        }
        let (mut set, mut clear) = ([0.0; LANES], [0.0; LANES]);
        for i in 0..2 * HB {
            (set[i], clear[i]) = est.thresholds(q, [p[0][i], p[1][i], p[2][i]], w.cv[i]);
        }
        // The padding lanes' thresholds never decide: -inf is above no e, below any other.
        for m in h..HB {
            for i in [m, HB + m] {
                (set[i], clear[i]) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
            }
        }
        let rows = &mut self.rows;
        let block = rows.blocks.len();
        rows.blocks.push(Block {
            node: nb,
            known: 0,
            exact: u32::MAX,
        });
        for half in [0, HB] {
            rows.thresholds.extend_from_slice(&set[half..half + HB]);
            rows.thresholds.extend_from_slice(&clear[half..half + HB]);
        }
        block
    }

    fn estimator(&self) -> Estimator {
        Estimator {
            max: self.f.max_finite() / 8.0,
            rel: self.rel,
            abs: 11.0 * self.q,
        }
    }
}

/// B's node `n`'s DOP, read from `tree` into `last` unless it is the one read last (a leaf's
/// is computed from its triangle, [`DopTree::dop`]; most tests find B's rows already
/// transformed and read none).
#[inline]
fn read<'d>(tree: &DopTree, last: &'d mut (u32, Dop), n: u32) -> &'d [f64] {
    if last.0 != n {
        tree.dop_into(n, &mut last.1);
        last.0 = n;
    }
    &last.1
}

/// B's transformed rows during one query, a block per node: per lane the f64 thresholds
/// of its flag and (once a test needed it) the chip's value. Kept per thread for
/// the next query, emptied, so that a query does not pay for allocating them anew and the
/// pages the allocator returned to the system (a quarter of a contact query's time before);
/// one larger than [`SPARE_BYTES`] is freed.
#[derive(Default)]
struct Rows {
    /// Per B node, its block (u32::MAX: not transformed in this query).
    slot: Vec<u32>,
    /// Per block, its thresholds in one run, so that a test reads a few neighbouring lines:
    /// per half of the lanes (the first half, then the mirrors) `hb` thresholds of a set
    /// flag, then `hb` of a clear one ([`clear_at`]), a half's lanes past k/2 padding
    /// ([`half_block`]).
    thresholds: Vec<f64>,
    /// The chip's values of the blocks that needed some, k each.
    exact: Vec<f64>,
    blocks: Vec<Block>,
}

/// A transformed node, its lanes whose exact value is known, and where its k exact values
/// are in [`Rows::exact`] (`u32::MAX`: none needed yet).
struct Block {
    node: u32,
    known: u32,
    exact: u32,
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
        self.thresholds.clear();
        self.exact.clear();
    }

    fn bytes(&self) -> usize {
        4 * self.slot.capacity()
            + 8 * self.thresholds.capacity()
            + 8 * self.exact.capacity()
            + 12 * self.blocks.capacity()
    }
}

impl Drop for TransformCache<'_> {
    fn drop(&mut self) {
        let mut rows = std::mem::take(&mut self.b.rows);
        rows.forget();
        if rows.bytes() <= SPARE_BYTES {
            SPARE_ROWS.set(rows);
        }
        SPARE_HELD.set(std::mem::take(&mut self.held));
    }
}

/// A lane's f64 thresholds of its flag (docs/explanation/accuracy.md, "The DOP unit in f64").
#[derive(Clone, Copy)]
struct Estimator {
    max: f64,
    rel: f64,
    abs: f64,
}

impl Estimator {
    /// `(set, clear)` with `set <= -q - u_i <= clear` for u_i of a lane whose exact products
    /// are `p` and whose offset is `c`: the f64 estimate `a = (p0 + p1) + (p2 + c)` widened
    /// by the bound `t = (2^(4-p) + 2^-50) S + 11q`, S the sum of the terms' magnitudes, as
    /// `fl(-q - a) -+ t`: t bounds |u_i - a| with room for the f64 roundings of t and of the
    /// thresholds. NaN thresholds (no bound: S possibly at overflow, or not finite) decide
    /// nothing.
    #[inline(always)]
    fn thresholds(&self, q: f64, p: [f64; 3], c: f64) -> (f64, f64) {
        let s = p[0].abs() + p[1].abs() + p[2].abs() + c.abs();
        let a = (p[0] + p[1]) + (p[2] + c);
        let t = if s <= self.max {
            self.rel * s + self.abs
        } else {
            f64::NAN
        };
        let m = -q - a;
        (m - t, m + t)
    }
}

/// The most lanes per half of a block: at least k/2 for every k, even.
const H: usize = HALF_LANES;

/// Lanes per half of a block of [`Rows::thresholds`] for k: k/2 rounded up to one of the
/// sizes [`BSide::bounded`] is compiled for (a multiple of four, so whole vectors, or
/// [`H`]). Blocks sized for the largest k cost k = 24 about 4.5% more instructions a
/// contact query (callgrind, `golden_loop bunny 1.0`: 5.31M against 5.07M).
fn half_block(k: usize) -> usize {
    (k / 2).next_multiple_of(4).min(H)
}

// Every size half_block gives has its arm in BSide::bounded (with H above 16, 16 would not).
const _: () = assert!(H <= 16, "a k above 32: give BSide::bounded an arm for 16");

/// Lanes in [`LaneWords`] and [`BSide::fill`]'s arrays: a half of H, then the
/// mirrors' half.
const LANES: usize = 2 * H;

/// Where the threshold of a clear flag of lane i (of 2h) is in a block of
/// [`Rows::thresholds`] of `hb` lanes a half (of a set flag: `hb` before).
#[inline]
fn clear_at(h: usize, hb: usize, i: usize) -> usize {
    (i / h) * 2 * hb + hb + i % h
}

/// The lanes' words as structure of arrays, lane i (of 2h) at `(i / h) hb + i % h`, zero
/// words in the padding lanes.
#[derive(Clone, Copy)]
struct LaneWords {
    j: [[u8; LANES]; 3],
    c: [[f64; LANES]; 3],
    cv: [f64; LANES],
}

impl LaneWords {
    fn of(setup: &HostSetup, hb: usize) -> LaneWords {
        let mut w = LaneWords {
            j: [[0; LANES]; 3],
            c: [[0.0; LANES]; 3],
            cv: [0.0; LANES],
        };
        let h = setup.j.len() / 2;
        for (i, ((j, c), cv)) in setup.j.iter().zip(&setup.cmat).zip(&setup.cvec).enumerate() {
            let at = (i / h) * hb + i % h;
            for l in 0..3 {
                (w.j[l][at], w.c[l][at]) = (j[l], c[l]);
            }
            w.cv[at] = *cv;
        }
        w
    }
}

/// The lanes of one half of a block, `t` (HB thresholds of set flags, then HB of clear
/// ones), against A's distances `e`: is one surely separated, is one open (its flag not
/// surely clear; a NaN threshold leaves its lane open)? Branch-free, vectorised, unrolled.
#[inline(always)]
fn scan<const HB: usize>(t: &[f64], e: &[f64; HB]) -> (bool, bool) {
    let (set, clear) = t[..2 * HB].split_at(HB);
    let (mut sure, mut open) = (false, false);
    for m in 0..HB {
        sure |= flag_surely_set(set[m], e[m]);
        open |= !flag_surely_clear(clear[m], e[m]);
    }
    (sure, open)
}

/// The lane's flag is surely set: `e < set <= -q - u` gives `u + e < -q`, the flag's
/// condition `u + e <= -q` ([`separated`]).
#[inline(always)]
fn flag_surely_set(set: f64, e: f64) -> bool {
    e < set
}

/// The lane's flag is surely clear: `e > clear >= -q - u` gives `u + e > -q`, hence
/// `u + e >= 0` (a multiple of q), so the flag's `u + e <= -q` fails.
#[inline(always)]
fn flag_surely_clear(clear: f64, e: f64) -> bool {
    e > clear
}

/// WSCG'03's DOP Unit (§4.1, Fig. 5) compares an aligned DOP `e`, in bundles of `n`
/// coefficients as the data bus brings them, with a tumbled DOP's transformed distances `dp`
/// (d'_i = [`transformed`], one per lane), held in its d' memory in the order of `e`: bundle
/// `b` pairs e_g with d'_opp(g) for g in b n .. b n + n (fewer in the last bundle), so that
/// each compare unit decides one lane's flag ([`separated`]). The pairs `(d', e)` per bundle;
/// NOR over every flag of every bundle is [`dop_overlap`]'s verdict (tb/rtl_dop.rs).
pub fn compare_bundles(dp: &[f64], e: &[f64], n: usize) -> Vec<Vec<(f64, f64)>> {
    let k = e.len();
    (0..k)
        .map(|g| (dp[crate::golden::klmsel::opposite_lane(k, g)], e[g]))
        .collect::<Vec<_>>()
        .chunks(n)
        .map(|c| c.to_vec())
        .collect()
}

/// d'_i of B's DOP `d`: D.KLMSEL's distances of lane `i` through its transform
/// ([`transformed`]), what WSCG'03's DOTADD unit writes for lane i.
pub fn dprime(f: Format, r: Rounding, setup: &HostSetup, d: &[f64], i: usize) -> f64 {
    transformed(f, r, klmsel(d, setup.j[i]), setup.cmat[i], setup.cvec[i])
}

/// The DOP unit, lane by lane as the pipeline computes it (the reference for the RTL).
pub fn dop_overlap(f: Format, r: Rounding, setup: &HostSetup, d: &[f64], e: &[f64]) -> bool {
    (0..d.len()).all(|i| {
        let s = lane(
            f,
            r,
            klmsel(d, setup.j[i]),
            setup.cmat[i],
            setup.cvec[i],
            opposite(e, i),
        );
        let flag = s < 0.0;
        !flag
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::golden::enclosure::check_tests::{fires, small_chip};
    use crate::golden::enclosure::checked;

    /// Check mode's comparison itself: the lanes' answer passes and is counted, its negation
    /// panics.
    #[test]
    fn check_mode_compares_the_answer() {
        let chip = small_chip();
        let setup = &chip.setup;
        let (f, r) = (chip.cfg.format.dop, chip.cfg.dop_rounding.op());
        let mut unit = TransformCache::new(f, r, setup, &chip.a.tree, &chip.b.tree);
        let want = dop_overlap(f, r, setup, &chip.b.tree.dop(0), &chip.a.tree.dop(0));
        let before = checked().dop_tests;
        unit.b.check_overlap(0, 0, want);
        assert_eq!(checked().dop_tests, before + 1);
        fires(|| unit.b.check_overlap(0, 0, !want));
    }
}
