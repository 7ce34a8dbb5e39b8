//! T.CHECK (DATE'05 §4.2, Eqs. 8, 9, 11-13) and TRI_UNIT (two T.CHECKs), with the
//! uncertainty flag: every value carries a bound on its distance from the ideal value
//! (exact arithmetic on the exact inputs), and a sign decision within that bound is
//! "unknown". T.CHECK never guesses: a pair is reported intersecting only if some edge
//! surely crosses, separate only if every edge surely misses, and uncertain otherwise
//! (docs/ACCURACY.md has the derivation).
//!
//! T.CHECK maps triangle A's vertices into the space where triangle B is the unit
//! triangle U = {(u, v, 0) : u, v >= 0, u + v <= 1} and tests A's three edges against U.
//! In pipeline order (column-vector convention, M_b = M_B . M_AB):
//! ```text
//! stage 1  Mb_ij = (m_i0 b_0j + m_i1 b_1j) + m_i2 b_2j                 j < 3   (Eq. 11)
//!          Mb_i3 = (m_i0 b_03 + m_i1 b_13) + (m_i2 b_23 + m_i3)                (Eq. 12)
//! stage 2  V'_i  = (Mb_i0 x + Mb_i1 y) + (Mb_i2 z + Mb_i3)                     (Eq. 13)
//! stage 3  per edge P->Q (V0V1, V1V2, V2V0):
//!          a = Px Qz - Qx Pz,  b = Py Qz - Qy Pz,  r_z = Qz - Pz              (Eq. 9)
//! stage 4  s = (a + b) - r_z
//! stage 5  crossing = (Pz < 0, Qz > 0, r_z > 0, a > 0, b > 0, s < 0)   P below, Q above
//!                  or (Qz < 0, Pz > 0, r_z < 0, a < 0, b < 0, s > 0)   the mirror
//! ```
//! where m = M_B (leaf of B) and b = M_AB (A's frame to B's frame). Each comparison is
//! three-valued (sure, surely not, unknown) and combined in Kleene logic. Derivation of
//! stage 5: the edge meets z = 0 at X = P + (-Pz / r_z)(Q - P) = (a / r_z, b / r_z, 0); X is
//! in U iff a/r_z >= 0, b/r_z >= 0, (a+b)/r_z <= 1: Eq. 8 negated when r_z > 0, and the
//! mirrored signs when r_z < 0 (DATE'05's "other criterion": P and Q swapped). Two
//! triangles in general position intersect iff an edge of one meets the other, so TRI_UNIT
//! runs A's edges against U(B) and B's edges against U(A). A degenerate triangle has no
//! M_B: that direction is unknown.

use crate::dop::host::{Affine, HostSetup};
use crate::format::{Format, Rounding};
use crate::memory::TriWord;
use std::cell::Cell;

/// A datapath value and a bound on its distance from the ideal value: |x - x*| <= e.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Bounded {
    pub x: f64,
    pub e: f64,
}

impl Bounded {
    /// Surely positive, surely negative, or unknown (`None`): NaN is unknown.
    pub fn sign(self) -> Option<bool> {
        if self.x > self.e {
            Some(true)
        } else if self.x < -self.e {
            Some(false)
        } else {
            None
        }
    }

    fn neg(self) -> Bounded {
        Bounded { x: -self.x, e: self.e }
    }
}

/// The chip's bound addition (`rtl::*::BoundAdd`): `max(next_up(RNE(a + b)), m)`, m = the
/// format's smallest normal value; for bounds a, b >= 0 an upper bound of a + b that is a
/// normal value of the format or +inf. `f64::max` drops a NaN (IEEE maxNum): a NaN sum
/// (a NaN operand) gives m, and so does a negative one.
#[inline(always)]
pub fn bound_add(f: Format, a: f64, b: f64) -> f64 {
    f.next_up(f.add(a, b, Rounding::NearestEven)).max(f.min_positive_normal())
}

/// The chip's bound multiplication (`rtl::*::BoundMul`): `max(next_up(RNE(a * b)), m)`, as
/// [`bound_add`] (`inf * 0`, a NaN, gives m).
#[inline(always)]
pub fn bound_mul(f: Format, a: f64, b: f64) -> f64 {
    f.next_up(f.mul(a, b, Rounding::NearestEven)).max(f.min_positive_normal())
}

/// The chip's bound on the rounding error of a result x rounded with `r`
/// (`rtl::*::RoundErr`): `max(ulp(x)/2, m)` to nearest, `max(ulp(x), m)` directed, m the
/// smallest normal, so a power of two of the format: ±inf gives +inf, NaN gives m
/// (`f64::max`), zeros and subnormals give m.
#[inline(always)]
pub fn rounding_error(f: Format, r: Rounding, x: f64) -> f64 {
    let ulp = f.ulp(x);
    let m = f.min_positive_normal();
    if r == Rounding::NearestEven { (0.5 * ulp).max(m) } else { ulp.max(m) }
}

/// The datapath's arithmetic on bounded values. Values are rounded in the T.CHECK rounding.
/// The chip computes bounds in the same format: each operation rounded to nearest, stepped
/// up to the next value of the format and floored at the smallest normal m (an upper
/// bound of the exact result, cheaper than a directed-rounding unit, and never subnormal),
/// in this order: add: `(ea + eb) + err(x)`; mul: `(ea |b| + eb |a|) + (ea eb + err(x))`,
/// err(x) being the rounding error bound of x: ulp(x)/2 to nearest, ulp(x) directed.
#[derive(Clone, Copy)]
struct Arith<'c> {
    f: Format,
    r: Rounding,
    /// The smallest normal value of the format.
    m: f64,
    mode: BoundMode<'c>,
}

#[derive(Clone, Copy)]
enum BoundMode<'c> {
    /// The chip's bound arithmetic.
    Chip,
    /// An f64 estimate that decides most signs as the chip would, and says when it cannot.
    Estimate(&'c Estimate),
}

/// The f64 estimate e64 of a bound computes the same expression in f64 with the same floor.
/// Every chip bound operation is within a factor (1 + 2^(1-F)) of the exact one on normal
/// values, and no chain is deeper than 64 operations, so the chip's bound lies in
/// [e64 (1 - 2^-40), e64 hi] with hi = (1 + 2^(1-F))^64 (1 + 2^-40): a sign is the chip's
/// when |x| > e64 hi (sure) or |x| <= e64 (1 - 2^-40) (unknown); in between, or near
/// overflow, the T.CHECK is redone with the chip's arithmetic.
pub(crate) struct Estimate {
    hi: f64,
    lo: f64,
    max: f64,
    ambiguous: Cell<bool>,
}

impl Estimate {
    fn new(f: Format) -> Estimate {
        let hi = (1.0 + 2f64.powi(1 - f.frac_bits() as i32)).powi(64) * (1.0 + 2f64.powi(-40));
        Estimate { hi, lo: 1.0 - 2f64.powi(-40), max: f.max_finite() / (4.0 * hi), ambiguous: Cell::new(false) }
    }
}

impl<'c> Arith<'c> {
    fn new(f: Format, r: Rounding, mode: BoundMode<'c>) -> Self {
        Arith { f, r, m: f.min_positive_normal(), mode }
    }

    #[inline(always)]
    fn up(&self, a: f64, b: f64) -> f64 {
        match self.mode {
            BoundMode::Chip => bound_add(self.f, a, b),
            BoundMode::Estimate(_) => (a + b).max(self.m),
        }
    }

    #[inline(always)]
    fn upm(&self, a: f64, b: f64) -> f64 {
        match self.mode {
            BoundMode::Chip => bound_mul(self.f, a, b),
            BoundMode::Estimate(_) => (a * b).max(self.m),
        }
    }

    /// The sign decision of stage 5: surely positive, surely negative, unknown (`None`).
    #[inline(always)]
    fn sign(&self, v: Bounded) -> Option<bool> {
        match self.mode {
            BoundMode::Chip => v.sign(),
            BoundMode::Estimate(est) => {
                let ax = v.x.abs();
                if v.e <= est.max && ax > v.e * est.hi {
                    Some(v.x > 0.0)
                } else if v.e <= est.max && ax <= v.e * est.lo {
                    None
                } else {
                    est.ambiguous.set(true);
                    None
                }
            }
        }
    }

    /// `v <= limit` for a bound v, with the estimate's band.
    fn at_most(&self, v: f64, limit: f64) -> bool {
        match self.mode {
            BoundMode::Chip => v <= limit,
            BoundMode::Estimate(est) => {
                if v * est.hi <= limit {
                    true
                } else {
                    if v * est.lo <= limit {
                        est.ambiguous.set(true);
                    }
                    false
                }
            }
        }
    }

    fn rounding_error_nearest(&self, x: f64) -> f64 {
        rounding_error(self.f, Rounding::NearestEven, x)
    }

    /// Bound on the rounding error of a result x ([`rounding_error`]).
    #[inline(always)]
    fn rounding_error(&self, x: f64) -> f64 {
        rounding_error(self.f, self.r, x)
    }

    #[inline(always)]
    fn add(&self, a: Bounded, b: Bounded) -> Bounded {
        let x = self.f.add(a.x, b.x, self.r);
        Bounded { x, e: self.up(self.up(a.e, b.e), self.rounding_error(x)) }
    }

    #[inline(always)]
    fn sub(&self, a: Bounded, b: Bounded) -> Bounded {
        self.add(a, b.neg())
    }

    #[inline(always)]
    fn mul(&self, a: Bounded, b: Bounded) -> Bounded {
        let x = self.f.mul(a.x, b.x, self.r);
        let e = self.up(
            self.up(self.upm(a.e, b.x.abs()), self.upm(b.e, a.x.abs())),
            self.up(self.upm(a.e, b.e), self.rounding_error(x)),
        );
        Bounded { x, e }
    }
}

/// Stage 1 output: M_b with bounds.
pub type BoundedAffine = [[Bounded; 4]; 3];

/// Every intermediate of one T.CHECK, for bit-exact comparison with the RTL.
#[derive(Clone, Debug, PartialEq)]
pub struct Trace {
    pub mb: BoundedAffine,
    pub v: [[Bounded; 3]; 3],
    pub a: [Bounded; 3],
    pub b: [Bounded; 3],
    pub rz: [Bounded; 3],
    pub s: [Bounded; 3],
    /// Per edge: crosses, misses, or unknown (`None`).
    pub crossing: [Option<bool>; 3],
}

impl Trace {
    /// Kleene OR over the edges.
    pub fn result(&self) -> Option<bool> {
        or3(self.crossing.iter().copied())
    }
}

fn or3(it: impl Iterator<Item = Option<bool>>) -> Option<bool> {
    let mut acc = Some(false);
    for x in it {
        acc = match (acc, x) {
            (Some(true), _) | (_, Some(true)) => Some(true),
            (Some(false), Some(false)) => Some(false),
            _ => None,
        };
    }
    acc
}

fn and3(it: impl Iterator<Item = Option<bool>>) -> Option<bool> {
    or3(it.map(|x| x.map(|b| !b))).map(|b| !b)
}

/// The map of a leaf or a frame with its bounds [linear entries, translation entries].
fn bounded_affine(m: &Affine, err: [f64; 2]) -> BoundedAffine {
    let mut out = [[Bounded::default(); 4]; 3];
    for (row, mrow) in out.iter_mut().zip(m) {
        for (c, (o, &x)) in row.iter_mut().zip(mrow).enumerate() {
            *o = Bounded { x, e: err[(c == 3) as usize] };
        }
    }
    out
}

/// Stage 1: M_b = M_B . M_AB (Eqs. 11, 12) for the leaf word `leaf` and a frame map `b`
/// with bounds `b_err`.
pub fn stage1(f: Format, r: Rounding, leaf: &TriWord, b: &Affine, b_err: [f64; 2]) -> BoundedAffine {
    stage1_in(&Arith::new(f, r, BoundMode::Chip), leaf, b, b_err)
}

fn stage1_in(ar: &Arith, leaf: &TriWord, b: &Affine, b_err: [f64; 2]) -> BoundedAffine {
    let m = bounded_affine(&leaf.m, [leaf.e_lin, leaf.e_tr]);
    let b = bounded_affine(b, b_err);
    let mut mb = [[Bounded::default(); 4]; 3];
    for i in 0..3 {
        for j in 0..3 {
            mb[i][j] = ar.add(ar.add(ar.mul(m[i][0], b[0][j]), ar.mul(m[i][1], b[1][j])), ar.mul(m[i][2], b[2][j]));
        }
        mb[i][3] = ar.add(
            ar.add(ar.mul(m[i][0], b[0][3]), ar.mul(m[i][1], b[1][3])),
            ar.add(ar.mul(m[i][2], b[2][3]), m[i][3]),
        );
    }
    mb
}

/// Stages 2-5 on the output `mb` of stage 1 and the triangle word `tri` (its vertices and
/// whether they are exact). `gap` widens the bounds
/// of the mapped vertices for a unit triangle that is itself only known within `eta`
/// (direction A vs U(B): `Some((leaf of B, eta))`; see docs/ACCURACY.md).
pub fn edges(f: Format, r: Rounding, mb: &BoundedAffine, tri: &TriWord, gap: Option<(&TriWord, f64)>) -> Trace {
    edges_in(&Arith::new(f, r, BoundMode::Chip), mb, tri, gap)
}

fn edges_in(ar: &Arith, mb: &BoundedAffine, tri: &TriWord, gap: Option<(&TriWord, f64)>) -> Trace {
    let v = &tri.v;
    let mut vt = [[Bounded::default(); 3]; 3];
    for (p, out) in v.iter().zip(vt.iter_mut()) {
        // The host rounded the vertices to nearest (no error if it says they were exact).
        let p = p.map(|x| Bounded { x, e: if tri.v_exact { 0.0 } else { ar.rounding_error_nearest(x) } });
        for i in 0..3 {
            out[i] = ar.add(ar.add(ar.mul(mb[i][0], p[0]), ar.mul(mb[i][1], p[1])), ar.add(ar.mul(mb[i][2], p[2]), mb[i][3]));
        }
        if let Some((leaf, eta)) = gap {
            let g = vertex_gap(ar, leaf, eta, out[0], out[1]);
            for o in out.iter_mut() {
                o.e = ar.up(o.e, g);
            }
        }
    }
    let (mut a, mut bb, mut rz, mut s) = ([Bounded::default(); 3], [Bounded::default(); 3], [Bounded::default(); 3], [Bounded::default(); 3]);
    let mut crossing = [None; 3];
    for e in 0..3 {
        let (p, q) = (vt[e], vt[(e + 1) % 3]);
        if let BoundMode::Estimate(_) = ar.mode {
            // Both ends surely on one side: both conjunctions are surely false, whatever
            // the other signs; the chip's verdict is the same (its trace is complete).
            let (sp, sq) = (ar.sign(p[2]), ar.sign(q[2]));
            if sp.is_some() && sp == sq {
                crossing[e] = Some(false);
                continue;
            }
        }
        a[e] = ar.sub(ar.mul(p[0], q[2]), ar.mul(q[0], p[2]));
        bb[e] = ar.sub(ar.mul(p[1], q[2]), ar.mul(q[1], p[2]));
        rz[e] = ar.sub(q[2], p[2]);
        s[e] = ar.sub(ar.add(a[e], bb[e]), rz[e]);
        let signs = [p[2], q[2], rz[e], a[e], bb[e], s[e]].map(|v| ar.sign(v));
        // Wanted signs (true = positive) of Pz, Qz, r_z, a, b, s for P below / Q below.
        let up = [false, true, true, true, true, false];
        let down = [true, false, false, false, false, true];
        let holds = |want: [bool; 6]| and3(signs.iter().zip(want).map(|(s, w)| s.map(|s| s == w)));
        crossing[e] = or3([holds(up), holds(down)].into_iter());
    }
    Trace { mb: *mb, v: vt, a, b: bb, rz, s, crossing }
}

/// How far the mapped vertex (u, v, z) can move when B's vertices move by eta:
/// 2 lambda eta (1 + 2 (|u| + e_u) + 2 (|v| + e_v)) with lambda = l_norm + e_lin >= |L*|,
/// valid while 4 lambda eta <= 1/2 (else unbounded).
fn vertex_gap(ar: &Arith, leaf: &TriWord, eta: f64, u: Bounded, v: Bounded) -> f64 {
    let lambda = ar.up(leaf.l_norm, leaf.e_lin);
    if !ar.at_most(ar.upm(ar.upm(4.0, lambda), eta), 0.5) {
        return f64::INFINITY;
    }
    let uv = ar.up(ar.up(u.x.abs(), u.e), ar.up(v.x.abs(), v.e));
    let w = ar.up(1.0, ar.upm(2.0, uv));
    ar.upm(ar.upm(2.0, lambda), ar.upm(eta, w))
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
    let d1 = (!b.degenerate).then(|| edges(f, r, &stage1(f, r, b, &setup.m_ab, setup.e_ab), a, Some((b, setup.eta))).result());
    let d2 = (!a.degenerate).then(|| edges(f, r, &stage1(f, r, a, &setup.m_ba, setup.e_ba), b, None).result());
    TriResult::of(d1.flatten(), d2.flatten())
}

/// TRI_UNIT during one query: the same results as [`tri_unit`] bit for bit (tested),
/// faster: stage 1 depends on one leaf and the pose only and is kept per leaf, and the
/// bounds are first estimated in f64 ([`Estimate`]); only a T.CHECK whose signs the
/// estimate cannot settle is redone with the chip's bound arithmetic.
pub struct TriUnit<'a> {
    f: Format,
    r: Rounding,
    setup: &'a HostSetup,
    est: Estimate,
    /// Per triangle of B: M_B(b) . M_AB; per triangle of A: M_A(a) . M_BA (estimated bounds).
    mb_b: StageOneCache,
    mb_a: StageOneCache,
    /// T.CHECKs redone with the chip's bound arithmetic.
    pub exact_redos: u64,
}

struct StageOneCache {
    slot: Vec<u32>,
    values: Vec<BoundedAffine>,
}

impl StageOneCache {
    fn get(&mut self, t: u32, compute: impl FnOnce() -> BoundedAffine) -> &BoundedAffine {
        let mut s = self.slot[t as usize];
        if s == u32::MAX {
            s = self.values.len() as u32;
            self.slot[t as usize] = s;
            self.values.push(compute());
        }
        &self.values[s as usize]
    }
}

impl<'a> TriUnit<'a> {
    pub fn new(f: Format, r: Rounding, setup: &'a HostSetup, tris_a: usize, tris_b: usize) -> Self {
        let cache = |n| StageOneCache { slot: vec![u32::MAX; n], values: vec![] };
        TriUnit { f, r, setup, est: Estimate::new(f), mb_b: cache(tris_b), mb_a: cache(tris_a), exact_redos: 0 }
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
        let (f, r, setup) = (self.f, self.r, self.setup);
        let (frame, err, gap) = if ab { (&setup.m_ab, setup.e_ab, Some((leaf, setup.eta))) } else { (&setup.m_ba, setup.e_ba, None) };
        self.est.ambiguous.set(false);
        let ar = Arith::new(f, r, BoundMode::Estimate(&self.est));
        let cache = if ab { &mut self.mb_b } else { &mut self.mb_a };
        let mb = cache.get(t, || stage1_in(&ar, leaf, frame, err));
        let res = edges_in(&ar, mb, v, gap).result();
        if !self.est.ambiguous.get() {
            return res;
        }
        self.exact_redos += 1;
        let chip = Arith::new(f, r, BoundMode::Chip);
        edges_in(&chip, &stage1_in(&chip, leaf, frame, err), v, gap).result()
    }
}
