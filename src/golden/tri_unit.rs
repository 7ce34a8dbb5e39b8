//! TRI_UNIT (DATE'05 §4.2): two T.CHECKs, A's edges against U(B) and B's edges against
//! U(A), combined in Kleene logic into intersecting, separate or uncertain.

use super::certificate::Certificate;
use super::enclosure::{checking, Upper};
use super::host::{Affine, HostSetup};
use super::memory::TriWord;
use super::tcheck::{decide, edges, edges_in, mag_lo, or3, settle, stage1, stage1_hi, Decision, Stage1, Stage1Hi, VertexHi};
use crate::format::{Format, Rounding};
use std::cell::Cell;

/// One direction decided with the enclosures ([`decide`], `EXACT` as there) and, where that
/// leaves it open, proven uncertain if it can be ([`settle`]); `None`: neither.
fn attempt<const EXACT: bool>(cert: &Certificate, up: &Upper, s1: &mut Leaf, leaf: &TriWord, frame: &Affine, v: &TriWord, vs: &mut [VertexHi; 3]) -> Option<Option<bool>> {
    match decide::<EXACT>(cert, up, &s1.hi, v, vs) {
        Decision::Verdict(d) => Some(d),
        Decision::Open => settle(cert, up, s1.lo.get_or_insert_with(|| Box::new(mag_lo(leaf, frame))), v, vs),
        Decision::Unfit => None,
    }
}

/// Intersecting (surely), separate (surely), or uncertain.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct TriResult {
    pub hit: bool,
    pub uncertain: bool,
}

impl TriResult {
    fn of(dir1: Option<bool>, dir2: Option<bool>) -> TriResult {
        match or3([dir1, dir2].into_iter()) {
            Some(hit) => TriResult { hit, uncertain: false },
            None => TriResult { hit: false, uncertain: true },
        }
    }
}

/// TRI_UNIT: A's edges against U(B), then B's edges against U(A); a degenerate leaf
/// leaves its direction unknown.
pub fn tri_unit(f: Format, r: Rounding, a: &TriWord, b: &TriWord, setup: &HostSetup) -> TriResult {
    let cert = Certificate::new(f, r);
    let direction = |leaf: &TriWord, tri: &TriWord, ab: bool| {
        let (frame, beta, scale) = setup.tri_frame(ab);
        (!leaf.degenerate).then(|| edges(f, r, &cert, &stage1(f, r, leaf, frame, beta, scale), tri).result())
    };
    let (d1, d2) = (direction(b, a, true), direction(a, b, false));
    TriResult::of(d1.flatten(), d2.flatten())
}

/// TRI_UNIT during one query: the same results as [`tri_unit`] bit for bit (tested, and
/// checked at every test in check mode, [`checking`]), faster: stage 1 depends on one leaf
/// and the pose only and is kept per leaf; each direction is decided with the enclosure of
/// the certificate's bounds ([`decide`]) where it can be, proven uncertain with their lower
/// bounds ([`settle`]) where that can be, else bit for bit, where an edge
/// whose ends are surely on one side is not computed further.
pub struct TriUnit<'a> {
    f: Format,
    r: Rounding,
    cert: Certificate,
    up: Upper,
    setup: &'a HostSetup,
    /// Per triangle of B: M_B(b) . M_AB; per triangle of A: M_A(a) . M_BA.
    mb_b: StageOneCache,
    mb_a: StageOneCache,
    /// [`decide`]'s vertices, written anew by each call.
    vertices: [VertexHi; 3],
}

/// Stage 1 of one leaf (triangle `tri`): enclosed always; its magnitudes from below once
/// [`settle`] is tried, bit for bit once the enclosures failed to decide.
struct Leaf {
    tri: u32,
    hi: Stage1Hi,
    lo: Option<Box<Affine>>,
    exact: Option<Box<Stage1>>,
}

/// Per triangle, its slot in `values`. Kept per thread for the next query, emptied, so
/// that a query does not allocate the table of one word per triangle anew.
#[derive(Default)]
struct StageOneCache {
    slot: Vec<u32>,
    values: Vec<Leaf>,
}

thread_local! {
    static SPARE: Cell<[StageOneCache; 2]> = Cell::default();
}

/// The most leaves' room a thread keeps between queries (some 4 MB).
const SPARE_LEAVES: usize = 1 << 14;

impl StageOneCache {
    /// The table sized for `n` triangles.
    fn sized(mut self, n: usize) -> StageOneCache {
        if self.slot.len() != n {
            self.slot = vec![u32::MAX; n];
        }
        self
    }

    fn get(&mut self, t: u32, compute: impl FnOnce() -> Stage1Hi) -> &mut Leaf {
        let mut s = self.slot[t as usize];
        if s == u32::MAX {
            s = self.values.len() as u32;
            self.slot[t as usize] = s;
            self.values.push(Leaf { tri: t, hi: compute(), lo: None, exact: None });
        }
        &mut self.values[s as usize]
    }

    /// Every slot emptied.
    fn emptied(mut self) -> StageOneCache {
        for l in &self.values {
            self.slot[l.tri as usize] = u32::MAX;
        }
        self.values.clear();
        self.values.shrink_to(SPARE_LEAVES);
        self
    }
}

impl Drop for TriUnit<'_> {
    fn drop(&mut self) {
        SPARE.set([std::mem::take(&mut self.mb_a).emptied(), std::mem::take(&mut self.mb_b).emptied()]);
    }
}

impl<'a> TriUnit<'a> {
    pub fn new(f: Format, r: Rounding, setup: &'a HostSetup, tris_a: usize, tris_b: usize) -> Self {
        let [mb_a, mb_b] = SPARE.take();
        let (cert, up) = (Certificate::new(f, r), Upper::new(f));
        TriUnit { f, r, cert, up, setup, mb_b: mb_b.sized(tris_b), mb_a: mb_a.sized(tris_a), vertices: Default::default() }
    }

    /// Triangle `ta` of A (word `a`) against `tb` of B (word `b`). A sure hit in the first
    /// direction decides without the second (the result is the same).
    pub fn test(&mut self, ta: u32, a: &TriWord, tb: u32, b: &TriWord) -> TriResult {
        let d1 = if b.degenerate { None } else { self.direction(tb, b, a, true) };
        if d1 == Some(true) {
            return TriResult { hit: true, uncertain: false };
        }
        let d2 = if a.degenerate { None } else { self.direction(ta, a, b, false) };
        TriResult::of(d1, d2)
    }

    /// One T.CHECK: the edges of `v` against the unit triangle of `leaf` (triangle `t` of B
    /// when `ab`, else of A).
    fn direction(&mut self, t: u32, leaf: &TriWord, v: &TriWord, ab: bool) -> Option<bool> {
        let (f, r, up, setup) = (self.f, self.r, self.up, self.setup);
        let (frame, beta, scale) = setup.tri_frame(ab);
        let cache = if ab { &mut self.mb_b } else { &mut self.mb_a };
        let s1 = cache.get(t, || stage1_hi(f, r, &up, leaf, frame, beta, scale));
        // in f64 first, then with the chip's own vertex words
        let vs = &mut self.vertices;
        let fast = attempt::<false>(&self.cert, &up, s1, leaf, frame, v, vs).or_else(|| attempt::<true>(&self.cert, &up, s1, leaf, frame, v, vs));
        if let Some(d) = fast.filter(|_| !checking()) {
            return d;
        }
        let exact = s1.exact.get_or_insert_with(|| Box::new(stage1(f, r, leaf, frame, beta, scale)));
        let want = edges_in(f, r, &self.cert, exact, v, false).result();
        if let Some(d) = fast {
            assert_eq!(d, want, "check mode: T.CHECK's enclosure decided {d:?}, the bit-exact path {want:?}: leaf {leaf:?}, triangle {v:?}, {}", if ab { "M_AB" } else { "M_BA" });
        }
        want
    }
}
