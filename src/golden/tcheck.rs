//! T.CHECK (DATE'05 §4.2, Eqs. 8, 9, 11-13; TRI_UNIT, two of them, is [`tri_unit`](super::tri_unit)), certified: each
//! sign the test depends on is decided only when it lies outside an error bound that the
//! chip computes *beside* the value, not behind it. Beside every value x the chip runs the
//! same expression on the absolute values of the operands, rounded upward: a magnitude
//! M_x >= |x| (and >= the exact expression on absolute values). The error of x is then at
//! most `g_x M_x` for a constant g_x of the format (a static filter, as Shewchuk's orient3d
//! bound `(7 + 56 eps) eps` times a permanent), plus input errors that the host folds into
//! two per-leaf and two per-pose words. A pair is reported intersecting only if some edge
//! surely crosses, separate only if every edge surely misses, and uncertain otherwise
//! (docs/explanation/accuracy.md, "T.CHECK's certificate", derives every constant).
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
//! where m = M_B (leaf of B) and b = M_AB (A's frame to B's frame). The magnitudes follow
//! the same order with every operand's sign cleared and every subtraction an addition,
//! except that the mapped vertex's translation term Mb_i3 gets `A' L1(x)` added (A' =
//! alpha_m beta_m + alpha_f beta_f, L1(x) = |x| + |y| + |z| + S_V: the input errors). Each
//! comparison is three-valued (sure, surely not, unknown) and combined in Kleene logic.
//! Derivation of stage 5: the edge meets z = 0 at X = P + (-Pz / r_z)(Q - P) = (a / r_z,
//! b / r_z, 0); X is in U iff a/r_z >= 0, b/r_z >= 0, (a+b)/r_z <= 1: Eq. 8 negated when
//! r_z > 0, and the mirrored signs when r_z < 0 (DATE'05's "other criterion": P and Q
//! swapped). Two triangles in general position intersect iff an edge of one meets the
//! other, so TRI_UNIT runs A's edges against U(B) and B's edges against U(A). A degenerate
//! triangle has no M_B: that direction is unknown.

use super::certificate::Certificate;
use super::enclosure::{add_down, down, mul_down, Upper};
use super::host::Affine;
use super::memory::TriWord;
use crate::format::{Format, Rounding};

const UP: Rounding = Rounding::TowardPositive;

/// `(a0 b0 + a1 b1) + a2 b2`, or `(a0 b0 + a1 b1) + (a2 b2 + c)` with a translation term,
/// every operation rounded with `r`: the one dot product of stages 1 and 2.
#[inline(always)]
fn dot(f: Format, r: Rounding, a: [f64; 3], b: [f64; 3], c: Option<f64>) -> f64 {
    // (products as plain calls, not a closure: the closure was not inlined)
    let (p0, p1, p2) = (
        f.mul(a[0], b[0], r),
        f.mul(a[1], b[1], r),
        f.mul(a[2], b[2], r),
    );
    let s01 = f.add(p0, p1, r);
    match c {
        None => f.add(s01, p2, r),
        Some(c) => f.add(s01, f.add(p2, c, r), r),
    }
}

/// [`dot`]'s magnitude: the same expression on absolute values, rounded upward.
#[inline(always)]
fn dot_mag(f: Format, a: [f64; 3], b: [f64; 3], c: Option<f64>) -> f64 {
    dot(f, UP, a.map(f64::abs), b.map(f64::abs), c.map(f64::abs))
}

/// [`dot_mag`] enclosed from above ([`Upper`]): operands already non-negative.
#[inline(always)]
fn dot_hi(up: &Upper, a: [f64; 3], b: [f64; 3], c: Option<f64>) -> f64 {
    let p = |k: usize| up.mul(a[k], b[k]);
    let s01 = up.add(p(0), p(1));
    match c {
        None => up.add(s01, p(2)),
        Some(c) => up.add(s01, up.add(p(2), c)),
    }
}

/// The sign of a value with bound `bound`: surely positive (`x > bound`), surely negative
/// (`x < -bound`), or unknown (`None`, also for a NaN x or an infinite bound).
#[inline(always)]
pub fn sign(x: f64, bound: f64) -> Option<bool> {
    if x > bound {
        Some(true)
    } else if x < -bound {
        Some(false)
    } else {
        None
    }
}

/// Stage 1's output: M_b and its magnitude.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stage1 {
    pub mb: Affine,
    pub mag: Affine,
    /// A' = alpha_m beta_m + alpha_f beta_f, rounded up: the input errors per unit of L1(x).
    pub a_err: f64,
    /// S_V, the scale of the vertices' object: L1(x) = |x| + |y| + |z| + S_V.
    pub scale: f64,
}

/// One dot product of M_b: entry (i, j), row i of M's 3 x 3 part, column j of the frame, and
/// M's translation `m[i][3]` in column 3.
type MbTerm = (usize, usize, [f64; 3], [f64; 3], Option<f64>);

/// The twelve dot products of M_b = M x frame in row order ([`MbTerm`]).
#[inline(always)]
fn mb_terms(m: &Affine, frame: &Affine) -> [MbTerm; 12] {
    std::array::from_fn(|n| {
        let (i, j) = (n / 4, n % 4);
        (
            i,
            j,
            [m[i][0], m[i][1], m[i][2]],
            [frame[0][j], frame[1][j], frame[2][j]],
            (j == 3).then_some(m[i][3]),
        )
    })
}

/// Stage 1: M_b = M_B . M_f (Eqs. 11, 12) and its magnitude for the leaf word `leaf` and
/// a frame map `frame` with its error words `beta` ([`HostSetup::beta_ab`](super::host::HostSetup::beta_ab)), `scale` the
/// vertices' object's ([`HostSetup::scale`](super::host::HostSetup::scale)).
pub fn stage1(
    f: Format,
    r: Rounding,
    leaf: &TriWord,
    frame: &Affine,
    beta: [f64; 2],
    scale: f64,
) -> Stage1 {
    let mut mb = [[0.0; 4]; 3];
    let mut mag = [[0.0; 4]; 3];
    for (i, j, row, col, c) in mb_terms(&leaf.m, frame) {
        mb[i][j] = dot(f, r, row, col, c);
        mag[i][j] = dot_mag(f, row, col, c);
    }
    let a_err = f.add(
        f.mul(leaf.alpha_m, beta[0], UP),
        f.mul(leaf.alpha_f, beta[1], UP),
        UP,
    );
    Stage1 {
        mb,
        mag,
        a_err,
        scale,
    }
}

/// Stage 1 for [`decide`]: M_b as the chip computes it, and upper enclosures ([`Upper`]) of
/// its magnitude and of A'. `fits`: every enclosure and value is below the format's
/// largest finite value (else nothing is proven).
#[derive(Clone, Copy, Debug)]
pub struct Stage1Hi {
    pub mb: Affine,
    pub mag: Affine,
    pub a_err: f64,
    pub scale: f64,
    pub fits: bool,
}

/// [`stage1`] with the magnitudes enclosed instead of rounded.
pub fn stage1_hi(
    f: Format,
    r: Rounding,
    up: &Upper,
    leaf: &TriWord,
    frame: &Affine,
    beta: [f64; 2],
    scale: f64,
) -> Stage1Hi {
    let (mut mb, mut mag, mut fits) = ([[0.0; 4]; 3], [[0.0; 4]; 3], true);
    for (i, j, row, col, c) in mb_terms(&leaf.m, frame) {
        mb[i][j] = dot(f, r, row, col, c);
        mag[i][j] = dot_hi(up, row.map(f64::abs), col.map(f64::abs), c.map(f64::abs));
        fits &= up.fits(mb[i][j]) & up.fits(mag[i][j]);
    }
    let a_err = up.add(up.mul(leaf.alpha_m, beta[0]), up.mul(leaf.alpha_f, beta[1]));
    Stage1Hi {
        mb,
        mag,
        a_err,
        scale,
        fits: fits & up.fits(a_err),
    }
}

/// One mapped vertex as [`decide`] sees it (docs/explanation/accuracy.md, "Values in f64"): each
/// coordinate's f64 value `c`, within `gap` of the chip's; `abs` >= both |c| and the chip
/// value's magnitude; and enclosures of the certificate's bounds, each widened by what the
/// f64 values may be off: `tz` >= E_z + gap_z, `ep` >= E + gap (x, y), `rz` >= E'_z +
/// delta, `h` >= H, `g` >= G + delta, where `delta` >= gap_z + round_rel |z|.
#[derive(Clone, Copy, Default)]
pub struct VertexHi {
    c: [f64; 3],
    gap: [f64; 3],
    abs: [f64; 3],
    tz: f64,
    ep: [f64; 2],
    delta: f64,
    rz: f64,
    h: f64,
    g: f64,
}

/// What [`decide`] proved.
pub enum Decision {
    /// The chip's verdict: intersecting, separate, or (never from `decide` itself) uncertain.
    Verdict(Option<bool>),
    /// The signs proven sure do not decide; [`settle`] may prove the verdict uncertain
    /// from the vertices [`decide`] wrote.
    Open,
    /// Nothing proven: a value or an enclosure may have overflowed.
    Unfit,
}

/// T.CHECK's verdict decided in f64 (docs/explanation/accuracy.md, "Deciding T.CHECK in f64" and
/// "Values in f64"): a verdict only where it equals `edges(..).result()` of the same inputs;
/// else the caller tries [`settle`], then the bit-exact path. Every value the chip computes
/// after stage 1 (the mapped vertices, a, b, r_z, s) is taken in f64 with a proven gap to
/// the chip's, every bound enclosed from above; a sign is sure when the f64 value lies
/// beyond the bound's enclosure plus the gap (then the chip's value lies beyond the chip's
/// bound), otherwise any. Kleene logic on the sets of results the signs may have
/// ([`Maybe`]) gives a set that holds the chip's verdict: one member is the chip's. With
/// `EXACT`, the mapped vertices are the chip's own words (gap 0): dearer, and decides more.
/// The vertices are written into `v`, every field before it is read: the caller's, kept
/// between calls (zeroing them was 1.3% of a bunny contact query's instructions: callgrind,
/// `golden_loop bunny 1.0`).
pub fn decide<const EXACT: bool>(
    cert: &Certificate,
    up: &Upper,
    s1: &Stage1Hi,
    tri: &TriWord,
    v: &mut [VertexHi; 3],
) -> Decision {
    let x = tri.v_exact as usize;
    let pa = tri.v.map(|p| p.map(f64::abs));
    // Coordinate i of mapped vertex k and its gap from magnitude m: in f64, its products
    // are exact (format numbers), so it is within `dot_gap` of the chip's value ("z before
    // the chip's z"); or the chip's own word. Its magnitude enclosed with the input errors
    // `err` = A' L1(p).
    let center = |k: usize, i: usize, m: f64| {
        let (mb, p) = (&s1.mb[i], tri.v[k]);
        if EXACT {
            (
                dot(cert.f, cert.r, [mb[0], mb[1], mb[2]], p, Some(mb[3])),
                0.0,
            )
        } else {
            (
                (mb[0] * p[0] + mb[1] * p[1]) + (mb[2] * p[2] + mb[3]),
                up.dot_gap(m),
            )
        }
    };
    let magnitude = |k: usize, i: usize, err: f64| {
        let mag = &s1.mag[i];
        dot_hi(
            up,
            [mag[0], mag[1], mag[2]],
            pa[k],
            Some(up.add(mag[3], err)),
        )
    };
    // z first: a vertex triangle surely on one side of the plane needs nothing else.
    let mut fits = s1.fits;
    let (mut err, mut mz, mut ez) = ([0.0; 3], [0.0; 3], [0.0; 3]);
    let mut sz = [None; 3];
    for (k, vk) in v.iter_mut().enumerate() {
        let l1 = up.add(up.add(pa[k][0], pa[k][1]), up.add(pa[k][2], s1.scale));
        err[k] = up.mul(s1.a_err, l1);
        mz[k] = magnitude(k, 2, err[k]);
        ez[k] = up.scale(mz[k], cert.c_e[x]);
        (vk.c[2], vk.gap[2]) = center(k, 2, mz[k]);
        vk.tz = up.add(ez[k], vk.gap[2]);
        sz[k] = sign(vk.c[2], vk.tz);
        fits &= up.fits(l1) & up.fits(mz[k]) & up.fits(ez[k]);
    }
    if !fits {
        return Decision::Unfit;
    }
    if sz[0].is_some() && sz[0] == sz[1] && sz[1] == sz[2] {
        return Decision::Verdict(Some(false));
    }
    for (k, vk) in v.iter_mut().enumerate() {
        let az = up.add(vk.c[2].abs(), vk.gap[2]);
        vk.delta = up.add(vk.gap[2], up.mul(az, up.round_rel()));
        vk.abs[2] = az;
        vk.rz = up.add(up.scale(mz[k], cert.c_z[x]), vk.delta);
        vk.h = up.add(az, 2.0 * ez[k]);
        vk.g = up.add(up.add(ez[k], up.scale(az, cert.c_s)), vk.delta);
        for i in 0..2 {
            let m = magnitude(k, i, err[k]);
            (vk.c[i], vk.gap[i]) = center(k, i, m);
            vk.abs[i] = up.add(vk.c[i].abs(), vk.gap[i]);
            vk.ep[i] = up.add(up.scale(m, cert.c_e[x]), vk.gap[i]);
            fits &= up.fits(m) & up.fits(vk.ep[i]);
        }
        fits &= vk.abs.iter().all(|&a| up.value_fits(a))
            & up.fits(vk.rz)
            & up.fits(vk.h)
            & up.fits(vk.g);
    }
    if !fits {
        return Decision::Unfit;
    }
    match edges_hi(
        cert,
        up,
        v,
        sz.map(|z| z.map_or(Maybe::ANY, Maybe::sure)),
        None,
    )
    .map(Maybe::single)
    {
        Some(Some(verdict)) => Decision::Verdict(verdict),
        Some(None) => Decision::Open,
        None => Decision::Unfit,
    }
}

/// [`decide`]'s open case taken further (docs/explanation/accuracy.md, "Proving T.CHECK uncertain"):
/// with lower bounds of the chip's bounds (stage 1's magnitudes from below: `mag_lo`,
/// [`mag_lo`]), a sign whose value lies provably within its bound is unknown on the chip.
/// The set of verdicts that holds the chip's (one member: proven); `None`: a bound may have
/// overflowed. `other`: the other direction's verdict, if proven (TRI_UNIT's result is the
/// OR of the two: `edges_hi` stops once that OR is decided or cannot be).
pub fn settle(
    cert: &Certificate,
    up: &Upper,
    mag_lo: &Affine,
    tri: &TriWord,
    v: &[VertexHi; 3],
    other: Option<Maybe>,
) -> Option<Maybe> {
    let lo = vertices_lo(cert, mag_lo, tri, v);
    let sz = std::array::from_fn(|k| sign_set(v[k].c[2], v[k].tz, Some((v[k].gap[2], lo[k].ez))));
    edges_hi(cert, up, v, sz, Some((&lo, other)))
}

/// Lower bounds of the chip's words of one mapped vertex: its |x|, |y|, |z| (`abs`); E_x,
/// E_y, E'_z (`e1`); E_z, G and H.
#[derive(Clone, Copy)]
struct VertexLo {
    abs: [f64; 3],
    e1: [f64; 3],
    ez: f64,
    g: f64,
    h: f64,
}

/// The chip's vertex bounds from below: each is an upward-rounded sum or product of
/// non-negative words (and `FpScale`'s `max(round_up(x c), 2^emin)`), at least the exact
/// operation on its operands, so the same expression on lower bounds of its operands,
/// evaluated with [`down`], is at most it; the error term A' L1 is left out (>= 0), and
/// the chip's |z| is at least |z^| - gap_z.
fn vertices_lo(
    cert: &Certificate,
    mag_lo: &Affine,
    tri: &TriWord,
    v: &[VertexHi; 3],
) -> [VertexLo; 3] {
    let x = tri.v_exact as usize;
    let (ce, cz, cs) = (cert.c_e[x].value(), cert.c_z[x].value(), cert.c_s.value());
    std::array::from_fn(|k| {
        let pa = tri.v[k].map(f64::abs);
        let m = |i: usize| dot_down([mag_lo[i][0], mag_lo[i][1], mag_lo[i][2]], pa, mag_lo[i][3]);
        let abs = std::array::from_fn(|i| down(v[k].c[i].abs() - v[k].gap[i]));
        let mz = m(2);
        let ez = mul_down(mz, ce);
        let (g, h) = (
            add_down(ez, mul_down(abs[2], cs)),
            add_down(abs[2], 2.0 * ez),
        );
        VertexLo {
            abs,
            e1: [mul_down(m(0), ce), mul_down(m(1), ce), mul_down(mz, cz)],
            ez,
            g,
            h,
        }
    })
}

/// `(a0 b0 + a1 b1) + (a2 b2 + c)` on non-negative operands, from below.
#[inline(always)]
fn dot_down(a: [f64; 3], b: [f64; 3], c: f64) -> f64 {
    add_down(
        add_down(mul_down(a[0], b[0]), mul_down(a[1], b[1])),
        add_down(mul_down(a[2], b[2]), c),
    )
}

/// Stage 1's magnitude M_b's entries from below: the exact sums of |m_ik| |frame_kj| (and
/// |m_i3|), which the chip's upward-rounded ones are at least.
pub fn mag_lo(leaf: &TriWord, frame: &Affine) -> Affine {
    let mut lo = [[0.0; 4]; 3];
    for (i, j, row, col, c) in mb_terms(&leaf.m, frame) {
        lo[i][j] = dot_down(
            row.map(f64::abs),
            col.map(f64::abs),
            c.map_or(0.0, f64::abs),
        );
    }
    lo
}

/// The results the chip's sign of a value may have against its bound B~: sure beyond
/// `hi` >= B~ + gap, as [`sign`]; else any, or, given `within` = (gap, lo) with gap >=
/// |x~ - x| and lo <= B~, not surely positive if x + gap <= lo (then x~ <= B~) and not
/// surely negative if gap - x <= lo. Each sum is taken with `next_up`: at least the exact
/// one.
#[inline(always)]
fn sign_set(x: f64, hi: f64, within: Option<(f64, f64)>) -> Maybe {
    match (sign(x, hi), within) {
        (Some(s), _) => Maybe::sure(s),
        (None, None) => Maybe::ANY,
        (None, Some((gap, lo))) => {
            let within = |d: f64| d.next_up() <= lo;
            let least = if within(gap - x) { Maybe::U } else { Maybe::F };
            Maybe {
                lo: least,
                hi: if within(x + gap) { Maybe::U } else { Maybe::T },
            }
        }
    }
}

/// [`decide`]'s stages 3-5 on the vertices in f64: per edge, a, b, r_z and s in f64 and an
/// enclosure of each one's bound plus its gap (the same expression tree as the chip's bound,
/// on the widened vertex bounds). An edge's signs are taken in the order P_z, Q_z, r_z, a,
/// b, s and the rest skipped once both directions' conjunctions are surely false
/// (docs/explanation/accuracy.md, "Deciding T.CHECK in f64": any sign then gives the same). The edges
/// left are skipped at a sure crossing, and with `lo` once what their z signs let them give
/// can no longer change the verdict's OR with the other direction's (`lo`'s second member,
/// if proven; else false), or make that OR one member ("Proving T.CHECK uncertain",
/// "Stopping early"; the second rule only with the other direction proven). The vertices'
/// z signs `sz` come from the caller, which has them already. With `lo` ([`settle`]), each
/// sign not sure also gets its gap and a lower bound of the chip's bound. The set returned
/// holds this direction's verdict; `None`: a bound may have overflowed. Inlined, so that
/// [`decide`]'s copy has no `lo` to test.
#[inline(always)]
fn edges_hi(
    cert: &Certificate,
    up: &Upper,
    v: &[VertexHi; 3],
    sz: [Maybe; 3],
    lo: Option<(&[VertexLo; 3], Option<Maybe>)>,
) -> Option<Maybe> {
    let (lo, other) = (lo.map(|l| l.0), lo.and_then(|l| l.1));
    // With `lo`, per edge, its conjunctions after the z signs alone: an interval that holds
    // what the edge gives, whatever its other signs. (`decide` stops at a sure crossing
    // alone: with the rest, callgrind counted more.)
    let ends: Option<[Maybe; 3]> = lo.map(|_| {
        std::array::from_fn(|e| {
            let edge = Conjunctions::of_z(sz, e);
            edge.up.or(edge.down)
        })
    });
    let mut verdict = Maybe::FALSE;
    for e in 0..3 {
        // The edges left give at most [rest_lo, rest_hi]: they can no longer change the OR,
        // or it can no longer have one member (its lower end stays below its upper).
        if let Some(ends) = &ends {
            let rest_lo = ends[e..].iter().map(|m| m.lo).max().unwrap_or(Maybe::F);
            let rest_hi = ends[e..].iter().map(|m| m.hi).max().unwrap_or(Maybe::F);
            let or = verdict.or(other.unwrap_or(Maybe::FALSE));
            if or.lo >= rest_hi {
                return Some(Maybe {
                    lo: verdict.lo,
                    hi: verdict.hi.max(rest_hi),
                });
            }
            if other.is_some() && or.hi > or.lo.max(rest_lo) {
                return Some(Maybe {
                    lo: verdict.lo,
                    hi: Maybe::T,
                });
            }
        } else if verdict == Maybe::TRUE {
            break;
        }
        let (pi, qi) = (e, (e + 1) % 3);
        let (p, q) = (&v[pi], &v[qi]);
        let mut edge = Conjunctions::of_z(sz, e);
        if !edge.open() {
            continue;
        }
        let rz = q.c[2] - p.c[2];
        let rz_bound = up.add(q.rz, p.rz);
        let rz_lo = lo.map(|l| (up.add(q.delta, p.delta), add_down(l[qi].e1[2], l[pi].e1[2])));
        if !edge.take(sign_set(rz, rz_bound, rz_lo), true) {
            continue;
        }
        let cross = |i: usize| {
            let x = p.c[i] * q.c[2] - q.c[i] * p.c[2];
            let pq = up.add(up.mul(p.ep[i], q.h), up.mul(p.abs[i], q.g));
            let qp = up.add(up.mul(q.ep[i], p.h), up.mul(q.abs[i], p.g));
            let bound = up.add(up.add(pq, qp), up.gap_abs());
            up.fits(bound).then_some((x, bound))
        };
        // gap_a (b's alike) and the chip's B_a from below
        let cross_lo = |i: usize| {
            let l = lo?;
            let pq = up.add(up.mul(p.gap[i], q.abs[2]), up.mul(p.abs[i], q.delta));
            let qp = up.add(up.mul(q.gap[i], p.abs[2]), up.mul(q.abs[i], p.delta));
            let (lp, lq) = (&l[pi], &l[qi]);
            let b = add_down(
                add_down(mul_down(lp.e1[i], lq.h), mul_down(lp.abs[i], lq.g)),
                add_down(mul_down(lq.e1[i], lp.h), mul_down(lq.abs[i], lp.g)),
            );
            Some((up.add(up.add(pq, qp), up.gap_abs()), b))
        };
        let (a, a_bound) = cross(0)?;
        let a_lo = cross_lo(0);
        if !edge.take(sign_set(a, a_bound, a_lo), true) {
            continue;
        }
        let (b, b_bound) = cross(1)?;
        let b_lo = cross_lo(1);
        if !edge.take(sign_set(b, b_bound, b_lo), true) {
            continue;
        }
        let s = (a + b) - rz;
        let s_sum = up.add(
            up.add(up.add(a.abs(), a_bound), up.add(b.abs(), b_bound)),
            up.add(rz.abs(), rz_bound),
        );
        let s_round = up.add(up.scale(s_sum, cert.c_s), up.mul(s_sum, up.round_rel()));
        let s_bound = up.add(up.add(a_bound, b_bound), up.add(rz_bound, s_round));
        if !up.fits(s_bound) {
            return None;
        }
        // gap_s = gap_a + gap_b + gap_rz + rr (U_a + U_b + U_rz); B_s >= B_a + B_b + B_rz
        let s_lo = a_lo
            .zip(b_lo)
            .zip(rz_lo)
            .map(|(((ga, la), (gb, lb)), (gr, lr))| {
                let u = up.add(
                    up.add(up.add(a.abs(), ga), up.add(b.abs(), gb)),
                    up.add(rz.abs(), gr),
                );
                (
                    up.add(up.add(ga, gb), up.add(gr, up.mul(u, up.round_rel()))),
                    add_down(add_down(la, lb), lr),
                )
            });
        edge.take(sign_set(s, s_bound, s_lo), false);
        verdict = verdict.or(edge.up.or(edge.down));
    }
    Some(verdict)
}

/// A set of three-valued results: an interval in Kleene's order false < unknown < true, in
/// which AND is the minimum, OR the maximum and NOT the reversal. An operation's results
/// over every choice of members of two intervals fill the interval of its results on
/// their ends (a value between them is the minimum, or maximum, of itself and an end of
/// the other interval); so an interval made from intervals that hold the chip's signs holds
/// the chip's result. Every set of signs made here is an interval.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Maybe {
    lo: u8,
    hi: u8,
}

impl Maybe {
    const F: u8 = 0;
    const U: u8 = 1;
    const T: u8 = 2;
    const TRUE: Maybe = Maybe {
        lo: Self::T,
        hi: Self::T,
    };
    const FALSE: Maybe = Maybe {
        lo: Self::F,
        hi: Self::F,
    };
    pub const ANY: Maybe = Maybe {
        lo: Self::F,
        hi: Self::T,
    };

    fn sure(s: bool) -> Maybe {
        if s {
            Self::TRUE
        } else {
            Self::FALSE
        }
    }

    /// The set of one verdict.
    pub fn of(verdict: Option<bool>) -> Maybe {
        verdict.map_or(
            Maybe {
                lo: Self::U,
                hi: Self::U,
            },
            Self::sure,
        )
    }

    /// Whether it holds `verdict`.
    pub fn holds(self, verdict: Option<bool>) -> bool {
        let c = Self::of(verdict).lo;
        self.lo <= c && c <= self.hi
    }

    fn not(self) -> Maybe {
        Maybe {
            lo: Self::T - self.hi,
            hi: Self::T - self.lo,
        }
    }

    fn and(self, o: Maybe) -> Maybe {
        Maybe {
            lo: self.lo.min(o.lo),
            hi: self.hi.min(o.hi),
        }
    }

    pub fn or(self, o: Maybe) -> Maybe {
        Maybe {
            lo: self.lo.max(o.lo),
            hi: self.hi.max(o.hi),
        }
    }

    /// The verdicts in both sets (both hold the chip's: never empty).
    pub fn meet(self, o: Maybe) -> Maybe {
        Maybe {
            lo: self.lo.max(o.lo),
            hi: self.hi.min(o.hi),
        }
    }

    /// The one member, if there is one (`Some(None)`: surely unknown).
    pub fn single(self) -> Option<Option<bool>> {
        (self.lo == self.hi).then_some(match self.lo {
            Self::T => Some(true),
            Self::F => Some(false),
            _ => None,
        })
    }
}

/// An edge's two conjunctions (stage 5) in Kleene logic over the signs taken so far: P
/// below and Q above (`up`), the mirror (`down`).
struct Conjunctions {
    up: Maybe,
    down: Maybe,
}

impl Default for Conjunctions {
    fn default() -> Self {
        Conjunctions {
            up: Maybe::TRUE,
            down: Maybe::TRUE,
        }
    }
}

impl Conjunctions {
    /// Edge `e`'s (P = vertex e, Q = the next) after its z signs alone: P_z, then Q_z.
    #[inline(always)]
    fn of_z(sz: [Maybe; 3], e: usize) -> Conjunctions {
        let mut edge = Conjunctions::default();
        edge.take(sz[e], false);
        edge.take(sz[(e + 1) % 3], true);
        edge
    }

    /// Whether some conjunction may still hold (else the edge surely misses, whatever the
    /// other signs).
    fn open(&self) -> bool {
        (self.up, self.down) != (Maybe::FALSE, Maybe::FALSE)
    }

    /// Takes a sign that `up` wants `want_up` and `down` the opposite; [`open`](Self::open)
    /// after it.
    fn take(&mut self, sign: Maybe, want_up: bool) -> bool {
        let (pos, neg) = (sign, sign.not());
        let (u, d) = if want_up { (pos, neg) } else { (neg, pos) };
        (self.up, self.down) = (self.up.and(u), self.down.and(d));
        self.open()
    }
}

/// Every intermediate of one T.CHECK that the RTL shows, for bit-exact comparison.
#[derive(Clone, Debug, PartialEq)]
pub struct Trace {
    pub stage1: Stage1,
    /// Mapped vertex k, coordinate i, and its magnitude; per vertex the bounds E_z
    /// (`e_z`), E_x, E_y and E'_z (`e1`), G and H.
    pub v: [[f64; 3]; 3],
    pub v_mag: [[f64; 3]; 3],
    pub e_z: [f64; 3],
    pub e1: [[f64; 3]; 3],
    pub g: [f64; 3],
    pub h: [f64; 3],
    /// Per edge: the values and their bounds.
    pub a: [f64; 3],
    pub b: [f64; 3],
    pub rz: [f64; 3],
    pub s: [f64; 3],
    pub a_bound: [f64; 3],
    pub b_bound: [f64; 3],
    pub rz_bound: [f64; 3],
    pub s_bound: [f64; 3],
    /// Per edge: crosses, misses, or unknown (`None`).
    pub crossing: [Option<bool>; 3],
}

impl Trace {
    /// Kleene OR over the edges.
    pub fn result(&self) -> Option<bool> {
        or3(self.crossing.iter().copied())
    }
}

pub(super) fn or3(it: impl Iterator<Item = Option<bool>>) -> Option<bool> {
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

/// Stages 2-5 on stage 1's output and the triangle word `tri` (its vertices and whether
/// they are exact), every intermediate computed.
pub fn edges(f: Format, r: Rounding, cert: &Certificate, s1: &Stage1, tri: &TriWord) -> Trace {
    edges_in(f, r, cert, s1, tri, true)
}

/// `complete = false` skips an edge whose ends are surely on one side of the plane (both
/// conjunctions are surely false, whatever the other signs: the chip's verdict is the same)
/// and leaves its trace entries at 0.
pub(super) fn edges_in(
    f: Format,
    r: Rounding,
    cert: &Certificate,
    s1: &Stage1,
    tri: &TriWord,
    complete: bool,
) -> Trace {
    let x = tri.v_exact as usize;
    let (mb, mag) = (&s1.mb, &s1.mag);
    let add = |x: f64, y: f64| f.add(x, y, UP);
    let mul = |x: f64, y: f64| f.mul(x, y, UP);
    let mut t = Trace {
        stage1: *s1,
        v: [[0.0; 3]; 3],
        v_mag: [[0.0; 3]; 3],
        e_z: [0.0; 3],
        e1: [[0.0; 3]; 3],
        g: [0.0; 3],
        h: [0.0; 3],
        a: [0.0; 3],
        b: [0.0; 3],
        rz: [0.0; 3],
        s: [0.0; 3],
        a_bound: [0.0; 3],
        b_bound: [0.0; 3],
        rz_bound: [0.0; 3],
        s_bound: [0.0; 3],
        crossing: [None; 3],
    };
    // Per vertex, from the magnitudes times constants: the bounds E of x, y and z,
    // E'_z >= E_z + u (1 + u) |z| (with r_z's rounding, since M_z >= |z|), G = E_z +
    // (2u + u^2) |z| (with the rounding of a's and b's products) and H = |z| + 2 E_z.
    for (k, p) in tri.v.iter().enumerate() {
        let l1 = add(add(p[0].abs(), p[1].abs()), add(p[2].abs(), s1.scale));
        let err = mul(s1.a_err, l1);
        for i in 0..3 {
            let row = [mb[i][0], mb[i][1], mb[i][2]];
            t.v[k][i] = dot(f, r, row, *p, Some(mb[i][3]));
            let mrow = [mag[i][0], mag[i][1], mag[i][2]];
            t.v_mag[k][i] = dot_mag(f, mrow, *p, Some(add(mag[i][3], err)));
            t.e1[k][i] = f.scale_up(t.v_mag[k][i], if i < 2 { cert.c_e[x] } else { cert.c_z[x] });
        }
        t.e_z[k] = f.scale_up(t.v_mag[k][2], cert.c_e[x]);
        t.g[k] = add(t.e_z[k], f.scale_up(t.v[k][2], cert.c_s));
        // 2 E_z is exact: E_z is 0, infinite or at least 2^emin, and far below the largest
        t.h[k] = add(t.v[k][2].abs(), 2.0 * t.e_z[k]);
    }
    let (v, ez, e1, g, hz) = (t.v, t.e_z, t.e1, t.g, t.h);
    for e in 0..3 {
        let (p, q) = (e, (e + 1) % 3);
        let (sp, sq) = (sign(v[p][2], ez[p]), sign(v[q][2], ez[q]));
        if !complete && sp.is_some() && sp == sq {
            t.crossing[e] = Some(false);
            continue;
        }
        // a = Px Qz - Qx Pz (coordinate 0), b the same with y (coordinate 1); the bound
        // E_Px H_Qz + |Px| G_Qz + E_Qx H_Pz + |Qx| G_Pz
        let cross = |i: usize| {
            let x = f.sub(f.mul(v[p][i], v[q][2], r), f.mul(v[q][i], v[p][2], r), r);
            let pq = add(mul(e1[p][i], hz[q]), mul(v[p][i].abs(), g[q]));
            let qp = add(mul(e1[q][i], hz[p]), mul(v[q][i].abs(), g[p]));
            (x, add(pq, qp))
        };
        let (a, a_bound) = cross(0);
        let (b, b_bound) = cross(1);
        let rz = f.sub(v[q][2], v[p][2], r);
        let rz_bound = add(e1[q][2], e1[p][2]);
        let s = f.sub(f.add(a, b, r), rz, r);
        let s_round = f.scale_up(add(add(a.abs(), b.abs()), rz.abs()), cert.c_s);
        let s_bound = add(add(a_bound, b_bound), add(rz_bound, s_round));
        (t.a[e], t.b[e], t.rz[e], t.s[e]) = (a, b, rz, s);
        (t.a_bound[e], t.b_bound[e], t.rz_bound[e], t.s_bound[e]) =
            (a_bound, b_bound, rz_bound, s_bound);
        let signs = [
            sp,
            sq,
            sign(rz, rz_bound),
            sign(a, a_bound),
            sign(b, b_bound),
            sign(s, s_bound),
        ];
        // Wanted signs (true = positive) of Pz, Qz, r_z, a, b, s for P below / Q below.
        let up = [false, true, true, true, true, false];
        let down = [true, false, false, false, false, true];
        let holds = |want: [bool; 6]| and3(signs.iter().zip(want).map(|(s, w)| s.map(|s| s == w)));
        t.crossing[e] = or3([holds(up), holds(down)].into_iter());
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`Maybe`]'s interval logic against the sets it stands for, member by member with the
    /// bit-exact path's Kleene logic (`and3`, `or3`).
    #[test]
    fn maybe_is_kleene_logic_on_sets() {
        let code = |x: Option<bool>| match x {
            Some(false) => Maybe::F,
            None => Maybe::U,
            Some(true) => Maybe::T,
        };
        let value = |c: u8| [Some(false), None, Some(true)][c as usize];
        let set = |m: Maybe| (m.lo..=m.hi).fold(0u8, |s, c| s | 1 << c);
        let intervals: Vec<Maybe> = (0..3)
            .flat_map(|lo| (lo..3).map(move |hi| Maybe { lo, hi }))
            .collect();
        for &a in &intervals {
            let not = (a.lo..=a.hi).fold(0, |s, x| s | 1 << code(value(x).map(|b| !b)));
            assert_eq!(set(a.not()), not);
            for &b in &intervals {
                let image = |op: fn([Option<bool>; 2]) -> Option<bool>| {
                    (a.lo..=a.hi)
                        .flat_map(|x| (b.lo..=b.hi).map(move |y| (x, y)))
                        .fold(0, |s, (x, y)| s | 1 << code(op([value(x), value(y)])))
                };
                assert_eq!(
                    set(a.and(b)),
                    image(|p| and3(p.into_iter())),
                    "{}..{} AND {}..{}",
                    a.lo,
                    a.hi,
                    b.lo,
                    b.hi
                );
                assert_eq!(
                    set(a.or(b)),
                    image(|p| or3(p.into_iter())),
                    "{}..{} OR {}..{}",
                    a.lo,
                    a.hi,
                    b.lo,
                    b.hi
                );
            }
        }
    }
}
