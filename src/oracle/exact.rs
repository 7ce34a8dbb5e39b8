//! Exact narrow phase: classification of a triangle into point / segment / proper triangle,
//! and the exact intersection test for every pair of those kinds. See the module doc of
//! [`crate::oracle`] for the case analysis.

use nalgebra::Point3;
use robust::{orient2d, orient3d, Coord, Coord3D};

use super::Tri;

type P = Point3<f64>;

/// Exact sign of a robust predicate value (its sign, including zero, is exact).
#[inline(always)]
fn sign(v: f64) -> i8 {
    if v > 0.0 {
        1
    } else if v < 0.0 {
        -1
    } else {
        0
    }
}

#[inline(always)]
fn c3(p: &P) -> Coord3D<f64> {
    Coord3D {
        x: p.x,
        y: p.y,
        z: p.z,
    }
}

/// Exact sign of orient3d(a, b, c, d).
#[inline(always)]
pub(crate) fn o3(a: &P, b: &P, c: &P, d: &P) -> i8 {
    sign(orient3d(c3(a), c3(b), c3(c), c3(d)))
}

/// Exact: the three vertices are collinear (or equal): the triangle has no plane.
pub(crate) fn collinear(t: &Tri) -> bool {
    !matches!(classify(t), Shape::Tri(..))
}

/// Projection along axis `k` (dropping coordinate `k`); an affine map, so on any plane whose
/// normal has a non-zero `k` component it is a bijection and orientations are preserved
/// up to one global sign.
#[inline(always)]
fn proj(p: &P, k: u8) -> Coord<f64> {
    match k {
        0 => Coord { x: p.y, y: p.z },
        1 => Coord { x: p.z, y: p.x },
        _ => Coord { x: p.x, y: p.y },
    }
}

/// Exact sign of orient2d of the projections along axis `k`. For k = 0, 1, 2 this is the
/// sign of the x, y, z component of (b - a) x (c - a).
#[inline(always)]
fn o2(a: &P, b: &P, c: &P, k: u8) -> i8 {
    sign(orient2d(proj(a, k), proj(b, k), proj(c, k)))
}

/// A triangle after exact classification by its affine dimension.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Shape {
    /// All three vertices equal.
    Point(P),
    /// Collinear, not all equal: the segment between the two extreme vertices.
    Seg(P, P),
    /// Proper triangle; `k` is an axis along which it projects non-degenerately and `s` the
    /// (non-zero) sign of its projected orientation.
    Tri(Tri, u8, i8),
}

/// Exact classification (no epsilons).
pub(crate) fn classify(t: &Tri) -> Shape {
    let [a, b, c] = t;
    for k in [2u8, 0, 1] {
        let s = o2(a, b, c, k);
        if s != 0 {
            return Shape::Tri(*t, k, s);
        }
    }
    // (b - a) x (c - a) == 0 exactly: collinear or coincident.
    if a == b && b == c {
        return Shape::Point(*a);
    }
    // An axis on which the vertices are not all equal: the line's direction has a non-zero
    // component there, so that coordinate orders the points along the line exactly.
    let ax = (0..3)
        .find(|&i| !(a[i] == b[i] && b[i] == c[i]))
        .unwrap_or(0);
    let mut lo = a;
    let mut hi = a;
    for p in [b, c] {
        if p[ax] < lo[ax] {
            lo = p;
        }
        if p[ax] > hi[ax] {
            hi = p;
        }
    }
    Shape::Seg(*lo, *hi)
}

// ---------------------------------------------------------------------------------------
// 2D tests on a projection that is injective on the affine hull of all points involved.
// ---------------------------------------------------------------------------------------

/// `x` on closed segment `pq`, given that the (projected) three points are collinear:
/// coordinate-wise betweenness (exact comparisons).
#[inline]
fn between2(p: &P, q: &P, x: &P, k: u8) -> bool {
    let (p, q, x) = (proj(p, k), proj(q, k), proj(x, k));
    p.x.min(q.x) <= x.x && x.x <= p.x.max(q.x) && p.y.min(q.y) <= x.y && x.y <= p.y.max(q.y)
}

/// Closed segments `p1q1`, `p2q2` (either may be degenerate) in projection `k`.
fn seg_seg2(p1: &P, q1: &P, p2: &P, q2: &P, k: u8) -> bool {
    let d1 = o2(p2, q2, p1, k);
    let d2 = o2(p2, q2, q1, k);
    let d3 = o2(p1, q1, p2, k);
    let d4 = o2(p1, q1, q2, k);
    if d1 * d2 < 0 && d3 * d4 < 0 {
        return true;
    }
    (d1 == 0 && between2(p2, q2, p1, k))
        || (d2 == 0 && between2(p2, q2, q1, k))
        || (d3 == 0 && between2(p1, q1, p2, k))
        || (d4 == 0 && between2(p1, q1, q2, k))
}

/// `p` in closed triangle `t` whose projected orientation along `k` has sign `s != 0`.
#[inline]
fn pt_in_tri2(p: &P, t: &Tri, k: u8, s: i8) -> bool {
    o2(&t[0], &t[1], p, k) != -s && o2(&t[1], &t[2], p, k) != -s && o2(&t[2], &t[0], p, k) != -s
}

/// Closed segment `pq` vs closed triangle `t` (all in `t`'s plane), projection `k`, sign `s`.
fn seg_tri2(p: &P, q: &P, t: &Tri, k: u8, s: i8) -> bool {
    pt_in_tri2(p, t, k, s)
        || pt_in_tri2(q, t, k, s)
        || seg_seg2(p, q, &t[0], &t[1], k)
        || seg_seg2(p, q, &t[1], &t[2], k)
        || seg_seg2(p, q, &t[2], &t[0], k)
}

// ---------------------------------------------------------------------------------------
// 3D tests.
// ---------------------------------------------------------------------------------------

/// Segment `pq` vs proper triangle `t`, with `sp`, `sq` the exact orient3d signs of `p`, `q`
/// against `t`'s plane.
fn seg_tri_signs(p: &P, q: &P, sp: i8, sq: i8, t: &Tri, k: u8, s: i8) -> bool {
    if sp == 0 && sq == 0 {
        return seg_tri2(p, q, t, k, s);
    }
    if sp == sq {
        return false; // both strictly on the same side
    }
    // The line pq is not parallel to the plane and meets it in exactly one point X of the
    // closed segment. X is in the closed triangle iff the three Pluecker side tests of the
    // line against the (consistently oriented) edges do not take both strict signs.
    let e0 = o3(p, q, &t[0], &t[1]);
    let e1 = o3(p, q, &t[1], &t[2]);
    if e0 * e1 < 0 {
        return false;
    }
    let e2 = o3(p, q, &t[2], &t[0]);
    !(e0 * e2 < 0 || e1 * e2 < 0)
}

fn seg_tri(p: &P, q: &P, t: &Tri, k: u8, s: i8) -> bool {
    let sp = o3(&t[0], &t[1], &t[2], p);
    let sq = o3(&t[0], &t[1], &t[2], q);
    seg_tri_signs(p, q, sp, sq, t, k, s)
}

fn pt_tri(p: &P, t: &Tri, k: u8, s: i8) -> bool {
    o3(&t[0], &t[1], &t[2], p) == 0 && pt_in_tri2(p, t, k, s)
}

/// Point `x` on closed 3D segment `pq` (`p != q`): cross product exactly zero, then betweenness.
fn pt_seg(x: &P, p: &P, q: &P) -> bool {
    (0..3).all(|i| p[i].min(q[i]) <= x[i] && x[i] <= p[i].max(q[i]))
        && o2(p, q, x, 0) == 0
        && o2(p, q, x, 1) == 0
        && o2(p, q, x, 2) == 0
}

/// Closed 3D segments, both non-degenerate.
fn seg_seg(p1: &P, q1: &P, p2: &P, q2: &P) -> bool {
    if o3(p1, q1, p2, q2) != 0 {
        return false; // skew lines
    }
    // Coplanar. If p1 q1 p2 or p1 q1 q2 is a proper triangle, an axis where it projects
    // non-degenerately is injective on the common plane.
    for k in [2u8, 0, 1] {
        if o2(p1, q1, p2, k) != 0 || o2(p1, q1, q2, k) != 0 {
            return seg_seg2(p1, q1, p2, q2, k);
        }
    }
    // All four collinear: compare intervals on an axis along which p1 != q1 (an exact
    // affine parametrisation of the common line).
    let ax = (0..3).find(|&i| p1[i] != q1[i]).unwrap_or(0);
    let (l1, h1) = (p1[ax].min(q1[ax]), p1[ax].max(q1[ax]));
    let (l2, h2) = (p2[ax].min(q2[ax]), p2[ax].max(q2[ax]));
    l1 <= h2 && l2 <= h1
}

/// Two proper triangles.
fn tri_tri_proper(a: &Tri, ka: u8, sa: i8, b: &Tri, kb: u8, sb: i8) -> bool {
    // Signs of B's vertices against A's plane.
    let db = [
        o3(&a[0], &a[1], &a[2], &b[0]),
        o3(&a[0], &a[1], &a[2], &b[1]),
        o3(&a[0], &a[1], &a[2], &b[2]),
    ];
    if (db[0] == db[1] && db[1] == db[2]) && db[0] != 0 {
        return false;
    }
    if db == [0, 0, 0] {
        // Coplanar: in A's projection (injective on the common plane) the triangles meet
        // iff two edges meet or one contains a vertex of the other.
        let sbk = o2(&b[0], &b[1], &b[2], ka);
        for i in 0..3 {
            let (a0, a1) = (&a[i], &a[(i + 1) % 3]);
            for j in 0..3 {
                if seg_seg2(a0, a1, &b[j], &b[(j + 1) % 3], ka) {
                    return true;
                }
            }
        }
        return pt_in_tri2(&a[0], b, ka, sbk) || pt_in_tri2(&b[0], a, ka, sa);
    }
    let da = [
        o3(&b[0], &b[1], &b[2], &a[0]),
        o3(&b[0], &b[1], &b[2], &a[1]),
        o3(&b[0], &b[1], &b[2], &a[2]),
    ];
    if (da[0] == da[1] && da[1] == da[2]) && da[0] != 0 {
        return false;
    }
    // Not coplanar: A ∩ B lies on the line of the two planes, where it is the intersection
    // of two intervals whose endpoints lie on the boundaries of A and B; a non-empty
    // intersection of two intervals contains an endpoint of one. So: some edge of A meets B
    // or some edge of B meets A.
    for i in 0..3 {
        let j = (i + 1) % 3;
        if seg_tri_signs(&a[i], &a[j], da[i], da[j], b, kb, sb)
            || seg_tri_signs(&b[i], &b[j], db[i], db[j], a, ka, sa)
        {
            return true;
        }
    }
    false
}

/// Exact intersection of two classified (closed) shapes.
pub(crate) fn shapes_intersect(a: &Shape, b: &Shape) -> bool {
    use Shape::*;
    match (a, b) {
        (Tri(ta, ka, sa), Tri(tb, kb, sb)) => {
            // A common vertex is a common point (fast exit for mesh neighbours, which
            // would otherwise take the slow exact path of the predicates).
            ta.iter().any(|p| tb.contains(p)) || tri_tri_proper(ta, *ka, *sa, tb, *kb, *sb)
        }
        (Tri(t, k, s), Seg(p, q)) | (Seg(p, q), Tri(t, k, s)) => seg_tri(p, q, t, *k, *s),
        (Tri(t, k, s), Point(p)) | (Point(p), Tri(t, k, s)) => pt_tri(p, t, *k, *s),
        (Seg(p1, q1), Seg(p2, q2)) => seg_seg(p1, q1, p2, q2),
        (Seg(p, q), Point(x)) | (Point(x), Seg(p, q)) => pt_seg(x, p, q),
        (Point(p), Point(q)) => p == q,
    }
}

/// [`shapes_intersect`] without the shared-vertex shortcut, so that tests also exercise the
/// predicate path on shared-vertex inputs.
#[cfg(test)]
pub(crate) fn shapes_intersect_no_shortcut(a: &Shape, b: &Shape) -> bool {
    match (a, b) {
        (Shape::Tri(ta, ka, sa), Shape::Tri(tb, kb, sb)) => {
            tri_tri_proper(ta, *ka, *sa, tb, *kb, *sb)
        }
        _ => shapes_intersect(a, b),
    }
}

/// Exact closed axis-aligned box of a triangle: `[min, max]`.
#[inline]
pub(crate) fn tri_box(t: &Tri) -> [[f64; 3]; 2] {
    let mut lo = [0.0; 3];
    let mut hi = [0.0; 3];
    for i in 0..3 {
        lo[i] = t[0][i].min(t[1][i]).min(t[2][i]);
        hi[i] = t[0][i].max(t[1][i]).max(t[2][i]);
    }
    [lo, hi]
}

/// Closed box overlap (exact comparisons).
#[inline(always)]
pub(crate) fn boxes_overlap(a: &[[f64; 3]; 2], b: &[[f64; 3]; 2]) -> bool {
    a[0][0] <= b[1][0]
        && b[0][0] <= a[1][0]
        && a[0][1] <= b[1][1]
        && b[0][1] <= a[1][1]
        && a[0][2] <= b[1][2]
        && b[0][2] <= a[1][2]
}
