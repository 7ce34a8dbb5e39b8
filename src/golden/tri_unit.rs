//! TRI_UNIT (DATE'05 §4.2): two T.CHECKs, A's edges against U(B) and B's edges against
//! U(A), combined in Kleene logic into intersecting, separate or uncertain.

use super::certificate::Certificate;
use super::enclosure::{checking, count_checked, Upper};
use super::host::{Affine, HostSetup};
use super::memory::TriWord;
use super::tcheck::{
    decide, edges, edges_in, mag_lo, or3, settle, stage1, stage1_hi, Decision, Maybe, Stage1,
    Stage1Hi, VertexHi,
};
use crate::format::{Format, Rounding};
use std::cell::Cell;

/// TRI_UNIT's tries at one direction, cheapest first: the enclosures in f64 ([`decide`], then
/// [`settle`] where it leaves the direction open), the same with the chip's own vertex
/// words, and bit for bit.
#[derive(Clone, Copy)]
enum Try {
    F64,
    ChipWords,
    BitExact,
}

/// Intersecting (surely), separate (surely), or uncertain.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct TriResult {
    pub hit: bool,
    pub uncertain: bool,
}

impl TriResult {
    /// The pair's result from its two directions' verdicts: their OR.
    fn of(dir1: Option<bool>, dir2: Option<bool>) -> TriResult {
        Self::verdict(or3([dir1, dir2].into_iter()))
    }

    /// The result of the verdict `v` (`None`: uncertain).
    fn verdict(v: Option<bool>) -> TriResult {
        match v {
            Some(hit) => TriResult {
                hit,
                uncertain: false,
            },
            None => TriResult {
                hit: false,
                uncertain: true,
            },
        }
    }
}

/// TRI_UNIT: A's edges against U(B), then B's edges against U(A); a degenerate leaf
/// leaves its direction unknown.
pub fn tri_unit(f: Format, r: Rounding, a: &TriWord, b: &TriWord, setup: &HostSetup) -> TriResult {
    let cert = Certificate::new(f, r);
    let direction = |leaf: &TriWord, tri: &TriWord, ab: bool| {
        let (frame, beta, scale) = setup.tri_frame(ab);
        (!leaf.degenerate)
            .then(|| edges(f, r, &cert, &stage1(f, r, leaf, frame, beta, scale), tri).result())
    };
    let (d1, d2) = (direction(b, a, true), direction(a, b, false));
    TriResult::of(d1.flatten(), d2.flatten())
}

/// TRI_UNIT during one query: the same results as [`tri_unit`] bit for bit (tested, and
/// checked at every test in check mode, [`checking`]), faster: stage 1 depends on one leaf
/// and the pose only and is kept per leaf; each direction's set of verdicts is narrowed
/// with the enclosure of the certificate's bounds ([`decide`]) and their lower bounds
/// ([`settle`]), first in f64, then with the chip's vertex words, until the two directions'
/// OR has one member, else bit for bit, where an edge whose ends are surely on one side is
/// not computed further.
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
            self.values.push(Leaf {
                tri: t,
                hi: compute(),
                lo: None,
                exact: None,
            });
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
        SPARE.set([
            std::mem::take(&mut self.mb_a).emptied(),
            std::mem::take(&mut self.mb_b).emptied(),
        ]);
    }
}

impl<'a> TriUnit<'a> {
    pub fn new(f: Format, r: Rounding, setup: &'a HostSetup, tris_a: usize, tris_b: usize) -> Self {
        let [mb_a, mb_b] = SPARE.take();
        let (cert, up) = (Certificate::new(f, r), Upper::new(f));
        TriUnit {
            f,
            r,
            cert,
            up,
            setup,
            mb_b: mb_b.sized(tris_b),
            mb_a: mb_a.sized(tris_a),
            vertices: Default::default(),
        }
    }

    /// Triangle `ta` of A (word `a`) against `tb` of B (word `b`). Each direction's set of
    /// verdicts is narrowed in turn, in f64, with the chip's own vertex words, then bit for
    /// bit, until their OR (the chip's result, `TriResult::of`) has one member: a sure
    /// hit in the first direction decides without the second, and an uncertain one needs
    /// of the second only that it cannot be a sure hit (docs/explanation/accuracy.md, "Two directions").
    pub fn test(&mut self, ta: u32, a: &TriWord, tb: u32, b: &TriWord) -> TriResult {
        let dirs = [(tb, b, a, true), (ta, a, b, false)];
        let mut sets = [Maybe::ANY; 2];
        let result = self.narrowed(&dirs, &mut sets);
        if checking() {
            self.check(dirs, sets, result);
        }
        TriResult::verdict(result)
    }

    /// [`test`](Self::test)'s tries: the OR of the two directions' sets once it has one
    /// member.
    fn narrowed(
        &mut self,
        dirs: &[(u32, &TriWord, &TriWord, bool); 2],
        sets: &mut [Maybe; 2],
    ) -> Option<bool> {
        for attempt in [Try::F64, Try::ChipWords, Try::BitExact] {
            for k in 0..2 {
                let (t, leaf, v, ab) = dirs[k];
                if sets[k].single().is_none() {
                    // the other direction's verdict, once proven, tells `settle` when to stop
                    let other = Some(sets[1 - k]).filter(|o| o.single().is_some());
                    // a degenerate leaf's direction is unknown
                    let set = if leaf.degenerate {
                        Maybe::of(None)
                    } else {
                        self.narrow(attempt, t, leaf, v, ab, other)
                    };
                    sets[k] = set.meet(sets[k]);
                }
                if let Some(result) = sets[0].or(sets[1]).single() {
                    return result;
                }
            }
        }
        unreachable!("bit for bit, both directions have one verdict")
    }

    /// One direction's set of verdicts after `attempt`: the edges of `v` against the unit
    /// triangle of `leaf` (triangle `t` of B when `ab`, else of A); every verdict if the
    /// enclosures prove nothing (a bound may have overflowed). `other`: the other
    /// direction's verdict, if proven.
    fn narrow(
        &mut self,
        attempt: Try,
        t: u32,
        leaf: &TriWord,
        v: &TriWord,
        ab: bool,
        other: Option<Maybe>,
    ) -> Maybe {
        let (f, r) = (self.f, self.r);
        let (frame, beta, scale) = self.setup.tri_frame(ab);
        let (s1, cert, up, vs) = self.parts(t, leaf, ab);
        let decision = match attempt {
            Try::F64 => decide::<false>(cert, up, &s1.hi, v, vs),
            Try::ChipWords => decide::<true>(cert, up, &s1.hi, v, vs),
            Try::BitExact => {
                let exact = s1
                    .exact
                    .get_or_insert_with(|| Box::new(stage1(f, r, leaf, frame, beta, scale)));
                return Maybe::of(edges_in(f, r, cert, exact, v, false).result());
            }
        };
        match decision {
            Decision::Verdict(d) => Maybe::of(d),
            Decision::Open => settle(
                cert,
                up,
                s1.lo.get_or_insert_with(|| Box::new(mag_lo(leaf, frame))),
                v,
                vs,
                other,
            )
            .unwrap_or(Maybe::ANY),
            Decision::Unfit => Maybe::ANY,
        }
    }

    /// Stage 1 of triangle `t` (word `leaf`: B's when `ab`, else A's), enclosed; the
    /// certificate, the enclosures, the vertices' scratch.
    fn parts(
        &mut self,
        t: u32,
        leaf: &TriWord,
        ab: bool,
    ) -> (&mut Leaf, &Certificate, &Upper, &mut [VertexHi; 3]) {
        let (f, r, up) = (self.f, self.r, &self.up);
        let (frame, beta, scale) = self.setup.tri_frame(ab);
        let cache = if ab { &mut self.mb_b } else { &mut self.mb_a };
        (
            cache.get(t, || stage1_hi(f, r, up, leaf, frame, beta, scale)),
            &self.cert,
            up,
            &mut self.vertices,
        )
    }

    /// Check mode: each direction's set holds its verdict bit for bit, and the result is the
    /// bit-exact path's.
    fn check(
        &mut self,
        dirs: [(u32, &TriWord, &TriWord, bool); 2],
        sets: [Maybe; 2],
        result: Option<bool>,
    ) {
        let mut want = [None; 2];
        for (k, &(t, leaf, v, ab)) in dirs.iter().enumerate().filter(|(_, d)| !d.1.degenerate) {
            want[k] = self
                .narrow(Try::BitExact, t, leaf, v, ab, None)
                .single()
                .expect("bit for bit: one verdict");
            assert!(sets[k].holds(want[k]), "check mode: T.CHECK's enclosure gave {:?}, the bit-exact path {:?}: leaf {leaf:?}, triangle {v:?}, {}", sets[k], want[k], if ab { "M_AB" } else { "M_BA" });
        }
        assert_eq!(
            result,
            or3(want.into_iter()),
            "check mode: TRI_UNIT's verdict"
        );
        count_checked(true);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::golden::enclosure::check_tests::{fires, small_chip};
    use crate::golden::enclosure::checked;

    /// Check mode's comparison itself: the bit-exact verdict passes and is counted; a
    /// direction's set without it, or a wrong result, panics.
    #[test]
    fn check_mode_compares_each_direction_and_the_verdict() {
        let chip = small_chip();
        let setup = &chip.setup;
        let (f, r) = (chip.cfg.format.tri, chip.cfg.tri_rounding);
        let (a, b) = (chip.a.tri(0), chip.b.tri(0));
        let mut unit = TriUnit::new(f, r, setup, chip.a.tri_count(), chip.b.tri_count());
        let dirs = [(0, &b, &a, true), (0, &a, &b, false)];
        let exact = |u: &mut TriUnit, k: usize| {
            let (t, leaf, v, ab) = dirs[k];
            u.narrow(Try::BitExact, t, leaf, v, ab, None)
                .single()
                .unwrap()
        };
        let want = [exact(&mut unit, 0), exact(&mut unit, 1)];
        let verdict = or3(want.into_iter());
        assert_eq!(TriResult::verdict(verdict), tri_unit(f, r, &a, &b, setup));
        let before = checked().tri_tests;
        unit.check(dirs, [Maybe::ANY; 2], verdict);
        assert_eq!(checked().tri_tests, before + 1);
        let not = |v: Option<bool>| Some(v != Some(true));
        fires(|| unit.check(dirs, [Maybe::of(not(want[0])), Maybe::ANY], verdict));
        fires(|| unit.check(dirs, [Maybe::ANY; 2], not(verdict)));
    }
}
