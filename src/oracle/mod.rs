//! Exact oracle: closed triangle–triangle intersection, the truth every chip result is
//! judged against.
//!
//! Two triangles intersect iff they share at least one point (boundaries included). All
//! decisions are exact signs of Shewchuk's adaptive predicates (`robust::orient3d`,
//! `robust::orient2d`) or exact `f64` comparisons — no epsilons. Precondition: every
//! coordinate is 0 or has magnitude in [[`MIN_COORD`], [`MAX_COORD`]] ([`check_range`]);
//! like Shewchuk's predicates, exactness needs no intermediate overflow or underflow.
//!
//! # Supported range
//! Coordinates of magnitude in [1e-60, 1e60] (or 0) are multiples of 2^-252 and below 2^200.
//! The predicates' expansion terms are products of at most three coordinate differences, so
//! they are multiples of 2^-756 (far above the 2^-1022 where underflow starts, error bounds
//! included) and below 2^603 (times Dekker's 2^27 splitter, far below 2^1024). Outside that
//! range the expansions can overflow or underflow and a sign can be wrong, so the geometry is
//! refused instead: loaders reject such coordinates, and `--unit-cube` results and posed
//! objects are checked with [`check_range`] before a query.
//!
//! # Case analysis
//! 1. **Classify** each triangle by the exact cross product `(b-a)×(c-a)`, whose components
//!    are the `orient2d` signs of the three axis projections:
//!    * some component ≠ 0 → *proper triangle*; remember that axis `k` (projection along `k`
//!      is an affine bijection of its plane, so 2D orientations there are exact) and the sign;
//!    * all zero and all vertices equal → *point*;
//!    * all zero otherwise → *segment* between the extreme vertices, found by ordering on
//!      an axis where the vertices differ (an exact parametrisation of the line).
//! 2. **Triangle–triangle** (both proper): a bit-equal common vertex → intersect (fast exit
//!    for mesh neighbours). Else signs of B's vertices against A's plane
//!    (`orient3d`); all strictly one side → disjoint. All zero → *coplanar*: in A's
//!    projection, intersect iff some edge pair meets (closed 2D segment test) or a vertex of
//!    one is in the other (containment). Otherwise also A's vertices against B's plane
//!    (strictly one side → disjoint), then: the intersection lies on the planes' common line,
//!    where it is the intersection of two intervals with endpoints on the triangles'
//!    boundaries, so the triangles meet iff some edge of one meets the other triangle
//!    (segment–triangle below, reusing the plane signs). This covers crossing, vertex–vertex,
//!    vertex–edge, vertex–face, edge–edge, shared edges.
//! 3. **Segment–triangle**: endpoint signs against the plane. Both zero → coplanar, 2D test
//!    in the triangle's projection (an endpoint inside, or the segment meets an edge). Same
//!    strict sign → disjoint. Otherwise the segment meets the plane in exactly one point X;
//!    X ∈ triangle iff the three Plücker side tests `orient3d(p, q, t_i, t_{i+1})` do not take
//!    both strict signs (zeros = on an edge / vertex).
//! 4. **Point–triangle**: `orient3d == 0` and point in closed triangle in its projection.
//! 5. **Segment–segment** (3D): `orient3d(p1, q1, p2, q2) ≠ 0` → skew, disjoint. Else if
//!    `p1 q1 p2` or `p1 q1 q2` projects non-degenerately along some axis, that projection is
//!    injective on the common plane: closed 2D segment test (proper crossing by strict
//!    `orient2d` signs, else an endpoint collinear with and between the other segment's
//!    endpoints). Else all four are collinear: interval overlap on an axis where `p1 ≠ q1`.
//! 6. **Point–segment**: all three cross-product components zero and coordinate-wise between.
//!    **Point–point**: coordinate equality.
//!
//! The broadphase ([`intersecting_pairs`]) uses a median-split AABB tree whose boxes are
//! exact coordinate min/max compared with closed `<=`, so it never drops a touching pair.

mod broadphase;
mod exact;

#[cfg(test)]
mod tests;

/// A triangle as a closed set (degenerate triangles are the segment or point they are).
pub type Tri = [nalgebra::Point3<f64>; 3];

/// Largest coordinate magnitude the oracle is exact for (see "Supported range").
pub const MAX_COORD: f64 = 1e60;
/// Smallest non-zero coordinate magnitude the oracle is exact for.
pub const MIN_COORD: f64 = 1e-60;

/// True iff `c` is 0 or finite with magnitude in [`MIN_COORD`, `MAX_COORD`].
pub fn in_range(c: f64) -> bool {
    c == 0.0 || (MIN_COORD..=MAX_COORD).contains(&c.abs())
}

/// The supported range as a phrase for error messages.
pub const RANGE_TEXT: &str =
    "the exact oracle supports coordinates that are 0 or of magnitude 1e-60 to 1e60";

/// Ok iff every coordinate of `tris` is [`in_range`]; else names `what`, the triangle and
/// the coordinate.
pub fn check_range(tris: &[Tri], what: &str) -> Result<(), String> {
    for (i, t) in tris.iter().enumerate() {
        if let Some(c) = t.iter().flat_map(|p| p.iter()).find(|c| !in_range(**c)) {
            return Err(format!(
                "{what}, triangle {i}: coordinate {c:e} is out of range ({RANGE_TEXT})"
            ));
        }
    }
    Ok(())
}

/// Exact: true iff the closed triangles `a` and `b` share at least one point.
pub fn tri_tri(a: &Tri, b: &Tri) -> bool {
    exact::boxes_overlap(&exact::tri_box(a), &exact::tri_box(b))
        && exact::shapes_intersect(&exact::classify(a), &exact::classify(b))
}

/// Exact: true iff some vertex of one triangle lies on the plane of the other (`orient3d`
/// is 0): touching, coplanar or with a vertex exactly on the other's plane, where a sign
/// T.CHECK decides from is exactly 0 and it must answer "uncertain". A triangle without a
/// plane (collinear vertices) gives false: it is degenerate, another cause.
pub fn vertex_on_plane(a: &Tri, b: &Tri) -> bool {
    let on = |t: &Tri, s: &Tri| {
        !exact::collinear(t) && s.iter().any(|p| exact::o3(&t[0], &t[1], &t[2], p) == 0)
    };
    on(a, b) || on(b, a)
}

/// [`tri_tri`] without the box pretest and the shared-vertex shortcut (tests only).
#[cfg(test)]
pub(crate) fn tri_tri_slow(a: &Tri, b: &Tri) -> bool {
    exact::shapes_intersect_no_shortcut(&exact::classify(a), &exact::classify(b))
}

/// All intersecting pairs `(i, j)` with `a[i] ∩ b[j] ≠ ∅`, sorted ascending, exact.
/// Median-split AABB tree over `b` (exact boxes, closed comparisons), queried with each
/// triangle of `a`.
pub fn intersecting_pairs(a: &[Tri], b: &[Tri]) -> Vec<(u32, u32)> {
    broadphase::intersecting_pairs(a, b)
}

/// O(n·m) reference for [`intersecting_pairs`].
pub fn brute_force_pairs(a: &[Tri], b: &[Tri]) -> Vec<(u32, u32)> {
    let mut out = Vec::new();
    for (i, ta) in a.iter().enumerate() {
        for (j, tb) in b.iter().enumerate() {
            if tri_tri(ta, tb) {
                out.push((i as u32, j as u32));
            }
        }
    }
    out
}
