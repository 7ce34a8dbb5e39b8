//! Tests of the exact oracle: hand-made cases for every kind of contact, ulp near misses,
//! property tests against an independent exact separating-axis reference in integer
//! arithmetic, exact-symmetry invariances and broadphase == brute force.

use super::*;
use nalgebra::Point3;
use proptest::prelude::*;

fn p(x: f64, y: f64, z: f64) -> Point3<f64> {
    Point3::new(x, y, z)
}
fn t(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Tri {
    [
        p(a[0], a[1], a[2]),
        p(b[0], b[1], b[2]),
        p(c[0], c[1], c[2]),
    ]
}
/// Both orders and all 6 vertex orders of each triangle must give `want`.
fn check(a: &Tri, b: &Tri, want: bool) {
    let perms = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    for pa in perms {
        for pb in perms {
            let a2 = [a[pa[0]], a[pa[1]], a[pa[2]]];
            let b2 = [b[pb[0]], b[pb[1]], b[pb[2]]];
            assert_eq!(tri_tri(&a2, &b2), want, "a={a2:?} b={b2:?}");
            assert_eq!(tri_tri(&b2, &a2), want, "b={b2:?} a={a2:?}");
            assert_eq!(tri_tri_slow(&a2, &b2), want, "slow a={a2:?} b={b2:?}");
            assert_eq!(tri_tri_slow(&b2, &a2), want, "slow b={b2:?} a={a2:?}");
        }
    }
}
fn pt(x: f64, y: f64, z: f64) -> Tri {
    t([x, y, z], [x, y, z], [x, y, z])
}

const E: f64 = f64::EPSILON;
/// next representable below 1.0 and above 1.0
const DN1: f64 = 1.0 - E / 2.0;
const UP1: f64 = 1.0 + E;

/// A: proper triangle in the plane z = 1, vertices (1,1), (5,1), (1,5); hypotenuse x + y = 6.
fn a_z1() -> Tri {
    t([1.0, 1.0, 1.0], [5.0, 1.0, 1.0], [1.0, 5.0, 1.0])
}

// ------------------------------------------------------------------ hand-made cases

#[test]
fn oracle_general_crossing() {
    let a = a_z1();
    // B's edge (2,2,0)-(2,2,2) pierces A's interior at (2,2,1).
    check(
        &a,
        &t([2.0, 2.0, 0.0], [2.0, 2.0, 2.0], [4.0, 4.0, 1.5]),
        true,
    );
    // Same B but entirely above / below.
    check(
        &a,
        &t([2.0, 2.0, 1.5], [2.0, 2.0, 2.0], [4.0, 4.0, 1.5]),
        false,
    );
    check(
        &a,
        &t([2.0, 2.0, 0.0], [2.0, 2.0, 0.5], [4.0, 4.0, 0.5]),
        false,
    );
    // B crosses A's plane but only outside A (beyond the hypotenuse).
    check(
        &a,
        &t([4.0, 4.0, 0.0], [4.0, 4.0, 2.0], [6.0, 6.0, 1.0]),
        false,
    );
    // Two triangles crossing each other through both interiors ("X" configuration).
    check(
        &a,
        &t([2.0, 1.5, 0.0], [2.0, 1.5, 3.0], [2.0, 10.0, 1.5]),
        true,
    );
}

#[test]
fn oracle_vertex_vertex() {
    let a = a_z1();
    // B touches the plane z = 1 only at its vertex (1,1,1) = A's vertex.
    check(
        &a,
        &t([1.0, 1.0, 1.0], [0.0, 0.0, 2.0], [0.0, 1.0, 3.0]),
        true,
    );
    // One ulp outside in x (x < 1 is outside A), and one ulp above the plane.
    check(
        &a,
        &t([DN1, 1.0, 1.0], [0.0, 0.0, 2.0], [0.0, 1.0, 3.0]),
        false,
    );
    check(
        &a,
        &t([1.0, 1.0, UP1], [0.0, 0.0, 2.0], [0.0, 1.0, 3.0]),
        false,
    );
}

#[test]
fn oracle_vertex_edge_and_vertex_face() {
    let a = a_z1();
    // Vertex on A's edge y = 1.
    let b = |y: f64, z: f64| t([3.0, y, z], [3.0, 0.0, 2.0], [2.0, 0.0, 3.0]);
    check(&a, &b(1.0, 1.0), true);
    check(&a, &b(DN1, 1.0), false); // one ulp outside the edge
    check(&a, &b(UP1, 1.0), true); // one ulp inside: vertex-face
    check(&a, &b(1.0, UP1), false); // one ulp above
                                    // Vertex on the hypotenuse x + y = 6 at (3,3); next_up(3) is outside.
    let c = |x: f64| t([x, 3.0, 1.0], [x, 3.0, 2.0], [x + 1.0, 4.0, 3.0]);
    check(&a, &c(3.0), true);
    check(&a, &c(3.0f64.next_up()), false);
    check(&a, &c(3.0f64.next_down()), true);
    // Vertex-face in the interior, ulp above / below the plane.
    let d = |z: f64| t([2.0, 2.0, z], [2.0, 2.0, 3.0], [3.0, 3.0, 2.0]);
    check(&a, &d(1.0), true);
    check(&a, &d(UP1), false);
    check(&a, &d(DN1), true); // now pierces the face
}

#[test]
fn oracle_edge_edge() {
    let a = a_z1();
    // B in the plane x = 3; its edge (3,y,0)-(3,y,2) crosses A's edge y = 1 at (3,1,1);
    // B ∩ {z=1} is y ∈ [-1, y], A ∩ {x=3, z=1} is y ∈ [1, 3].
    let b = |y: f64| t([3.0, y, 0.0], [3.0, y, 2.0], [3.0, -1.0, 1.0]);
    check(&a, &b(1.0), true);
    check(&a, &b(DN1), false);
    check(&a, &b(UP1), true);
    // Skew edges meeting exactly: A's hypotenuse point (2,4,1) and B's edge through it.
    let c = |z: f64| t([1.0, 3.0, z], [3.0, 5.0, z], [2.0, 6.0, 4.0]);
    check(&a, &c(1.0), true); // B's edge (1,3,1)-(3,5,1) crosses the hypotenuse in-plane
    check(&a, &c(UP1), false);
}

#[test]
fn oracle_shared_edge_and_vertex() {
    let a = a_z1();
    // Shared edge, B leaving the plane.
    check(
        &a,
        &t([1.0, 1.0, 1.0], [5.0, 1.0, 1.0], [3.0, 0.0, 4.0]),
        true,
    );
    // Shared edge, coplanar on the other side.
    check(
        &a,
        &t([1.0, 1.0, 1.0], [5.0, 1.0, 1.0], [3.0, -2.0, 1.0]),
        true,
    );
    // Coplanar, parallel edge one ulp away.
    check(
        &a,
        &t([1.0, DN1, 1.0], [5.0, DN1, 1.0], [3.0, -2.0, 1.0]),
        false,
    );
    // Identical triangles.
    check(&a, &a_z1(), true);
}

#[test]
fn oracle_coplanar() {
    let a = a_z1();
    check(
        &a,
        &t([2.0, 2.0, 1.0], [6.0, 2.0, 1.0], [2.0, 6.0, 1.0]),
        true,
    ); // overlap
    check(
        &a,
        &t([2.0, 2.0, 1.0], [3.0, 2.0, 1.0], [2.0, 3.0, 1.0]),
        true,
    ); // B inside A
    check(
        &a,
        &t([0.0, 0.0, 1.0], [9.0, 0.0, 1.0], [0.0, 9.0, 1.0]),
        true,
    ); // A inside B
    check(
        &a,
        &t([4.0, 4.0, 1.0], [6.0, 4.0, 1.0], [4.0, 6.0, 1.0]),
        false,
    ); // disjoint
    check(
        &a,
        &t([3.0, 3.0, 1.0], [6.0, 3.0, 1.0], [3.0, 6.0, 1.0]),
        true,
    ); // vertex on edge
    let n3 = 3.0f64.next_up();
    check(
        &a,
        &t([n3, 3.0, 1.0], [6.0, 3.0, 1.0], [n3, 6.0, 1.0]),
        false,
    );
    // Vertex-vertex coplanar.
    check(
        &a,
        &t([5.0, 1.0, 1.0], [7.0, 0.0, 1.0], [7.0, 2.0, 1.0]),
        true,
    );
    check(
        &a,
        &t(
            [5.0f64.next_up(), 1.0, 1.0],
            [7.0, 0.0, 1.0],
            [7.0, 2.0, 1.0],
        ),
        false,
    );
    // Star of David: no vertex inside the other, edges cross.
    let s = t([0.0, 2.0, 1.0], [4.0, 2.0, 1.0], [2.0, -1.0, 1.0]);
    check(
        &s,
        &t([0.0, 0.0, 1.0], [4.0, 0.0, 1.0], [2.0, 3.0, 1.0]),
        true,
    );
    // Tilted common plane x + y + z = 1.
    let tl = t([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    check(
        &tl,
        &t([0.25, 0.25, 0.5], [1.0, 1.0, -1.0], [2.0, 0.0, -1.0]),
        true,
    ); // vertex inside
    check(
        &tl,
        &t([1.0, 0.0, 0.0], [1.0, 1.0, -1.0], [2.0, 0.0, -1.0]),
        true,
    ); // shared vertex
    check(
        &tl,
        &t([0.5, 0.5, 0.0], [1.0, 1.0, -1.0], [2.0, 0.0, -1.0]),
        true,
    ); // on edge
    check(
        &tl,
        &t([2.0, 0.0, -1.0], [1.0, 1.0, -1.0], [1.0, 2.0, -2.0]),
        false,
    ); // disjoint
       // Same plane in the vertical orientation x = 2 (normal along x).
    let v = t([2.0, 0.0, 0.0], [2.0, 4.0, 0.0], [2.0, 0.0, 4.0]);
    check(
        &v,
        &t([2.0, 2.0, 2.0], [2.0, 5.0, 5.0], [2.0, 2.0, 6.0]),
        true,
    );
    check(
        &v,
        &t(
            [2.0, 2.0f64.next_up(), 2.0],
            [2.0, 5.0, 5.0],
            [2.0, 2.0, 6.0],
        ),
        false,
    );
}

#[test]
fn oracle_near_miss_tilted_plane() {
    // Plane x + y + z = 1; (0.25, 0.25, 0.5) lies exactly on it, inside the triangle.
    let tl = t([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    let b = |z: f64| t([0.25, 0.25, z], [1.0, 1.0, 1.0], [0.0, 1.0, 2.0]);
    check(&tl, &b(0.5), true);
    check(&tl, &b(0.5f64.next_up()), false);
    check(&tl, &b(0.5f64.next_down()), true);
}

#[test]
fn oracle_degenerate_segment_triangle() {
    let a = a_z1();
    // Vertical collinear "triangles" (middle vertex last) through (2,2).
    check(
        &a,
        &t([2.0, 2.0, 0.0], [2.0, 2.0, 2.0], [2.0, 2.0, 1.5]),
        true,
    );
    check(
        &a,
        &t([2.0, 2.0, 1.0], [2.0, 2.0, 3.0], [2.0, 2.0, 2.0]),
        true,
    );
    check(
        &a,
        &t([2.0, 2.0, UP1], [2.0, 2.0, 3.0], [2.0, 2.0, 2.0]),
        false,
    );
    // The middle-vertex choice matters: segment from z=0.5 to z=2 with extra point at 1.5.
    check(
        &a,
        &t([2.0, 2.0, 1.5], [2.0, 2.0, 0.5], [2.0, 2.0, 2.0]),
        true,
    );
    // Repeated vertex.
    check(
        &a,
        &t([2.0, 2.0, 0.0], [2.0, 2.0, 0.0], [2.0, 2.0, 1.0]),
        true,
    );
    check(
        &a,
        &t([2.0, 2.0, 0.0], [2.0, 2.0, 0.0], [2.0, 2.0, DN1]),
        false,
    );
    // Coplanar segment crossing A.
    check(
        &a,
        &t([0.0, 3.0, 1.0], [6.0, 3.0, 1.0], [3.0, 3.0, 1.0]),
        true,
    );
    // Coplanar segment outside A (y = 4: A spans x ∈ [1, 2]).
    check(
        &a,
        &t([4.0, 4.0, 1.0], [6.0, 4.0, 1.0], [5.0, 4.0, 1.0]),
        false,
    );
    // Coplanar segment touching A's vertex (1,5) from above.
    check(
        &a,
        &t([1.0, 5.0, 1.0], [1.0, 7.0, 1.0], [1.0, 6.0, 1.0]),
        true,
    );
    check(
        &a,
        &t(
            [1.0, 5.0f64.next_up(), 1.0],
            [1.0, 7.0, 1.0],
            [1.0, 6.0, 1.0],
        ),
        false,
    );
    // Diagonal segment touching the edge y = 1 from below at (3,1,1), in 3D.
    check(
        &a,
        &t([3.0, 1.0, 1.0], [2.0, 0.0, 2.0], [2.5, 0.5, 1.5]),
        true,
    );
    check(
        &a,
        &t([3.0, DN1, 1.0], [2.0, 0.0, 2.0], [2.0, 0.0, 2.0]),
        false,
    );
    // Segment lying along A's edge (collinear overlap).
    check(
        &a,
        &t([4.0, 1.0, 1.0], [9.0, 1.0, 1.0], [6.0, 1.0, 1.0]),
        true,
    );
    check(
        &a,
        &t(
            [5.0f64.next_up(), 1.0, 1.0],
            [9.0, 1.0, 1.0],
            [6.0, 1.0, 1.0],
        ),
        false,
    );
}

#[test]
fn oracle_degenerate_point_triangle() {
    let a = a_z1();
    check(&a, &pt(2.0, 2.0, 1.0), true); // interior
    check(&a, &pt(2.0, 2.0, UP1), false);
    check(&a, &pt(2.0, 2.0, DN1), false);
    check(&a, &pt(3.0, 1.0, 1.0), true); // on an edge
    check(&a, &pt(3.0, DN1, 1.0), false);
    check(&a, &pt(5.0, 1.0, 1.0), true); // a vertex
    check(&a, &pt(5.0f64.next_up(), 1.0, 1.0), false);
    check(&a, &pt(2.0, 4.0, 1.0), true); // on the hypotenuse
    check(&a, &pt(2.0, 4.0f64.next_up(), 1.0), false);
}

#[test]
fn oracle_degenerate_segment_segment() {
    let s1 = t([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
    check(
        &s1,
        &t([1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [1.0, 0.0, 0.0]),
        true,
    ); // cross
    let h = 2f64.powi(-40);
    check(&s1, &t([1.0, -1.0, h], [1.0, 1.0, h], [1.0, 0.0, h]), false); // skew
    check(
        &s1,
        &t([1.0, -1.0, -1.0], [1.0, 1.0, 1.0], [1.0, 0.5, 0.5]),
        true,
    ); // skew dirs, meet
    check(
        &s1,
        &t([2.0, 0.0, 0.0], [3.0, 0.0, 0.0], [2.5, 0.0, 0.0]),
        true,
    ); // collinear touch
    check(
        &s1,
        &t([2f64.next_up(), 0.0, 0.0], [3.0, 0.0, 0.0], [2.5, 0.0, 0.0]),
        false,
    );
    check(
        &s1,
        &t([0.0, 1.0, 0.0], [2.0, 1.0, 0.0], [1.0, 1.0, 0.0]),
        false,
    ); // parallel
    check(
        &s1,
        &t([2.0, 0.0, 0.0], [3.0, 1.0, 0.0], [4.0, 2.0, 0.0]),
        true,
    ); // end-to-end, bent
    check(
        &s1,
        &t([2.0, 1.0, 0.0], [3.0, 1.0, 0.0], [3.0, 1.0, 0.0]),
        false,
    ); // coplanar miss
       // T-junction: endpoint of S2 on the interior of S1.
    check(
        &s1,
        &t([1.5, 0.0, 0.0], [1.5, 0.0, 3.0], [1.5, 0.0, 2.0]),
        true,
    );
    check(
        &s1,
        &t([1.5, 0.0, h], [1.5, 0.0, 3.0], [1.5, 0.0, 2.0]),
        false,
    );
    // Collinear along the (1,1,1) diagonal (no axis-aligned direction).
    let d = t([0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]);
    check(
        &d,
        &t([2.0, 2.0, 2.0], [3.0, 3.0, 3.0], [4.0, 4.0, 4.0]),
        true,
    );
    check(
        &d,
        &t([3.0, 3.0, 3.0], [4.0, 4.0, 4.0], [5.0, 5.0, 5.0]),
        false,
    );
    check(
        &d,
        &t([0.5, 0.5, 0.5], [4.0, 4.0, 4.0], [5.0, 5.0, 5.0]),
        true,
    );
    // Crossing in a tilted plane.
    check(
        &d,
        &t([2.0, 0.0, 1.0], [0.0, 2.0, 1.0], [1.0, 1.0, 1.0]),
        true,
    );
    check(
        &d,
        &t([2.0, 0.0, 1.5], [0.0, 2.0, 0.5], [1.0, 1.0, 1.0]),
        true,
    );
    check(
        &d,
        &t(
            [2.0, 0.0, 1.5],
            [0.0, 2.0, 0.5 + h],
            [1.0, 1.0, 1.0 + h / 2.0],
        ),
        false,
    );
}

#[test]
fn oracle_degenerate_points() {
    let s1 = t([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
    check(&s1, &pt(1.0, 0.0, 0.0), true);
    check(&s1, &pt(2.0, 0.0, 0.0), true);
    check(&s1, &pt(1.0, 2f64.powi(-60), 0.0), false);
    check(&s1, &pt(3.0, 0.0, 0.0), false); // collinear beyond the end
    check(&s1, &pt(2f64.next_up(), 0.0, 0.0), false);
    let d = t([1.0, 1.0, 1.0], [3.0, 5.0, 7.0], [2.0, 3.0, 4.0]);
    check(&d, &pt(2.5, 4.0, 5.5), true);
    check(&d, &pt(2.5, 4.0f64.next_up(), 5.5), false);
    check(&pt(1.0, 2.0, 3.0), &pt(1.0, 2.0, 3.0), true);
    check(&pt(1.0, 2.0, 3.0), &pt(1.0, 2.0, 3f64.next_up()), false);
    check(&pt(0.0, 0.0, 0.0), &pt(-0.0, 0.0, -0.0), true);
}

#[test]
fn oracle_pairs_small() {
    let a = vec![
        a_z1(),
        pt(2.0, 2.0, 1.0),
        t([9.0, 9.0, 9.0], [9.5, 9.0, 9.0], [9.0, 9.5, 9.0]),
    ];
    let b = vec![
        pt(9.0, 9.0, 9.0),
        a_z1(),
        t([3.0, 1.0, 1.0], [3.0, 0.0, 2.0], [2.0, 0.0, 3.0]),
    ];
    let want = vec![(0, 1), (0, 2), (1, 1), (2, 0)];
    assert_eq!(intersecting_pairs(&a, &b), want);
    assert_eq!(brute_force_pairs(&a, &b), want);
    assert!(intersecting_pairs(&[], &b).is_empty());
    assert!(intersecting_pairs(&a, &[]).is_empty());
}

// ------------------------------------------------------------------ independent reference

/// Exact separating-axis reference in i128, independent of the implementation. Two compact
/// convex polytopes are disjoint iff some direction strictly separates their projections;
/// the Minkowski difference A − B is a polytope whose affine hull and facets are spanned by
/// vectors from V = {edges of A, edges of B, a_i − b_j}, so it suffices to try
/// V ∪ {u×v} ∪ {(u×v)×w} for u, v, w ∈ V (facet normals when full-dimensional, the hull's
/// normal and in-hull facet normals otherwise, and for collinear/point cases a vector along
/// the line or to the point).
mod sat {
    pub type I3 = [i128; 3];
    fn sub(a: I3, b: I3) -> I3 {
        [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
    }
    fn cross(a: I3, b: I3) -> I3 {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    }
    fn dot(a: I3, b: I3) -> i128 {
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    }
    fn separates(w: I3, a: &[I3; 3], b: &[I3; 3]) -> bool {
        let pa = a.map(|x| dot(w, x));
        let pb = b.map(|x| dot(w, x));
        let (amin, amax) = (*pa.iter().min().unwrap(), *pa.iter().max().unwrap());
        let (bmin, bmax) = (*pb.iter().min().unwrap(), *pb.iter().max().unwrap());
        amax < bmin || bmax < amin
    }
    pub fn intersect(a: &[I3; 3], b: &[I3; 3]) -> bool {
        let mut v: Vec<I3> = Vec::new();
        for t in [a, b] {
            for i in 0..3 {
                for j in i + 1..3 {
                    v.push(sub(t[j], t[i]));
                }
            }
        }
        for x in a {
            for y in b {
                v.push(sub(*x, *y));
            }
        }
        v.retain(|x| *x != [0, 0, 0]);
        v.sort();
        v.dedup();
        for &u in &v {
            if separates(u, a, b) {
                return false;
            }
        }
        for &u in &v {
            for &w in &v {
                let n = cross(u, w);
                if n == [0, 0, 0] {
                    continue;
                }
                if separates(n, a, b) {
                    return false;
                }
                for &x in &v {
                    let m = cross(n, x);
                    if m != [0, 0, 0] && separates(m, a, b) {
                        return false;
                    }
                }
            }
        }
        true
    }
}

fn to_tri(a: &[sat::I3; 3]) -> Tri {
    a.map(|v| p(v[0] as f64, v[1] as f64, v[2] as f64))
}

#[test]
fn sat_reference_sanity() {
    // The reference itself on a few cases reasoned out by hand.
    let a = [[0, 0, 0], [4, 0, 0], [0, 4, 0]];
    assert!(sat::intersect(&a, &[[2, 2, 0], [5, 5, 5], [5, 0, 5]])); // vertex on hypotenuse
    assert!(!sat::intersect(&a, &[[3, 2, 0], [5, 5, 5], [5, 0, 5]])); // just beyond
    assert!(sat::intersect(&a, &[[1, 1, -1], [1, 1, 1], [1, 1, 0]])); // segment through
    assert!(!sat::intersect(&a, &[[1, 1, 1], [1, 1, 2], [1, 1, 3]])); // segment above
    assert!(!sat::intersect(&[[0, 0, 0]; 3], &[[1, 0, 0]; 3]));
    assert!(sat::intersect(&[[1, 0, 0]; 3], &[[1, 0, 0]; 3]));
    assert!(!sat::intersect(
        &[[0, 0, 0], [2, 0, 0], [1, 0, 0]],
        &[[0, 1, 0], [2, 1, 0], [1, 1, 0]]
    ));
}

fn small_tri(r: i128) -> impl Strategy<Value = [sat::I3; 3]> {
    prop::array::uniform3(prop::array::uniform3(-r..=r))
}

/// Pairs of small-integer triangles biased towards touching / coplanar / degenerate cases.
fn touchy_pair() -> impl Strategy<Value = ([sat::I3; 3], [sat::I3; 3])> {
    (small_tri(3), small_tri(3), 0u8..8, 0u8..6, 0u8..8).prop_map(
        |(a, mut b, share, flat, degen)| {
            let mut a = a;
            // Copy some of A's vertices into B (shared vertices / edges / identical).
            for i in 0..3 {
                if share & (1 << i) != 0 && (share != 7 || degen == 0) {
                    b[i] = a[(i + degen as usize) % 3];
                }
            }
            // Flatten into a common plane.
            match flat {
                0 => {
                    for v in a.iter_mut().chain(b.iter_mut()) {
                        v[2] = 0;
                    }
                }
                1 => {
                    for v in a.iter_mut().chain(b.iter_mut()) {
                        v[2] = v[0] - v[1];
                    }
                }
                2 => {
                    for v in b.iter_mut() {
                        v[1] = 1;
                    }
                }
                _ => {}
            }
            // Degenerate: collinear / point B.
            match degen {
                1 => {
                    b[2] = [
                        2 * b[1][0] - b[0][0],
                        2 * b[1][1] - b[0][1],
                        2 * b[1][2] - b[0][2],
                    ]
                }
                2 => b[1] = b[0],
                3 => b = [b[0]; 3],
                _ => {}
            }
            (a, b)
        },
    )
}

// ------------------------------------------------------------------ exact transforms

/// Exact map on f64: axis permutation, sign flips, power-of-two scale.
fn exact_map(t: &Tri, perm: [usize; 3], flips: u8, scale_exp: i32) -> Tri {
    let s = 2f64.powi(scale_exp);
    t.map(|v| {
        let mut w = [v[perm[0]], v[perm[1]], v[perm[2]]];
        for (i, c) in w.iter_mut().enumerate() {
            if flips & (1 << i) != 0 {
                *c = -*c;
            }
            *c *= s;
        }
        p(w[0], w[1], w[2])
    })
}

const PERMS: [[usize; 3]; 6] = [
    [0, 1, 2],
    [0, 2, 1],
    [1, 0, 2],
    [1, 2, 0],
    [2, 0, 1],
    [2, 1, 0],
];

fn float_tri() -> impl Strategy<Value = Tri> {
    prop::array::uniform3(prop::array::uniform3(-1.0f64..1.0))
        .prop_map(|v| v.map(|c| p(c[0], c[1], c[2])))
}

/// Float pairs with some exact contacts built in (midpoints, shared vertices, ...).
fn float_pair() -> impl Strategy<Value = (Tri, Tri)> {
    (float_tri(), float_tri(), 0u8..5, 0.0f64..1.0).prop_map(|(a, mut b, kind, s)| {
        match kind {
            0 => b[0] = a[0],
            1 => {
                b[0] = a[0];
                b[1] = a[1];
            }
            2 => b[0] = a[0] + (a[1] - a[0]) * s,
            3 => b[2] = b[0] + (b[1] - b[0]) * s,
            _ => {}
        }
        (a, b)
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 20000, ..ProptestConfig::default() })]

    #[test]
    fn oracle_prop_matches_sat_small_int((a, b) in touchy_pair()) {
        let want = sat::intersect(&a, &b);
        prop_assert_eq!(tri_tri(&to_tri(&a), &to_tri(&b)), want, "a={:?} b={:?}", a, b);
        prop_assert_eq!(tri_tri_slow(&to_tri(&a), &to_tri(&b)), want, "slow a={:?} b={:?}", a, b);
    }

    #[test]
    fn oracle_prop_matches_sat_plain_small_int(a in small_tri(3), b in small_tri(3)) {
        let want = sat::intersect(&a, &b);
        prop_assert_eq!(tri_tri(&to_tri(&a), &to_tri(&b)), want, "a={:?} b={:?}", a, b);
        prop_assert_eq!(tri_tri_slow(&to_tri(&a), &to_tri(&b)), want, "slow a={:?} b={:?}", a, b);
    }

    #[test]
    fn oracle_prop_symmetric_and_order_invariant((a, b) in float_pair(), pa in 0usize..6, pb in 0usize..6) {
        let r = tri_tri(&a, &b);
        prop_assert_eq!(tri_tri(&b, &a), r);
        let (x, y) = (PERMS[pa], PERMS[pb]);
        let a2 = [a[x[0]], a[x[1]], a[x[2]]];
        let b2 = [b[y[0]], b[y[1]], b[y[2]]];
        prop_assert_eq!(tri_tri(&a2, &b2), r);
        prop_assert_eq!(tri_tri(&b2, &a2), r);
    }

    #[test]
    fn oracle_prop_exact_map_invariant((a, b) in float_pair(), perm in 0usize..6, flips in 0u8..8, e in -30i32..30) {
        let r = tri_tri(&a, &b);
        let (a2, b2) = (exact_map(&a, PERMS[perm], flips, e), exact_map(&b, PERMS[perm], flips, e));
        prop_assert_eq!(tri_tri(&a2, &b2), r);
    }

    #[test]
    fn oracle_prop_exact_map_invariant_small_int((a, b) in touchy_pair(), perm in 0usize..6, flips in 0u8..8, e in -30i32..30) {
        let (a, b) = (to_tri(&a), to_tri(&b));
        let r = tri_tri(&a, &b);
        let (a2, b2) = (exact_map(&a, PERMS[perm], flips, e), exact_map(&b, PERMS[perm], flips, e));
        prop_assert_eq!(tri_tri(&a2, &b2), r);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1000, ..ProptestConfig::default() })]

    /// General-position geometry with large integer coordinates (exact in f64 and i128).
    #[test]
    fn oracle_prop_matches_sat_large_int(a in small_tri(1 << 20), b in small_tri(1 << 20), share in 0u8..3) {
        let mut b = b;
        if share == 1 { b[0] = a[1]; }
        if share == 2 { b[1] = [(a[0][0] + a[1][0]) / 2 * 2 - a[0][0], a[1][1], a[1][2]]; }
        let want = sat::intersect(&a, &b);
        prop_assert_eq!(tri_tri(&to_tri(&a), &to_tri(&b)), want, "a={:?} b={:?}", a, b);
        prop_assert_eq!(tri_tri_slow(&to_tri(&a), &to_tri(&b)), want, "slow a={:?} b={:?}", a, b);
    }
}

// ------------------------------------------------------------------ broadphase vs brute force

fn int_soup(n: usize) -> impl Strategy<Value = Vec<Tri>> {
    prop::collection::vec(
        (
            prop::array::uniform3(-12i32..=12),
            prop::array::uniform3(prop::array::uniform3(-2i32..=2)),
            0u8..6,
        ),
        n,
    )
    .prop_map(|v| {
        v.into_iter()
            .map(|(c, d, kind)| {
                let mut tri = d.map(|o| {
                    p(
                        (c[0] + o[0]) as f64,
                        (c[1] + o[1]) as f64,
                        (c[2] + o[2]) as f64,
                    )
                });
                match kind {
                    0 => tri[2] = tri[1],
                    1 => tri[2] = tri[0] + (tri[1] - tri[0]) * 2.0,
                    2 => {
                        for q in tri.iter_mut() {
                            q.z = (c[2] & !3) as f64;
                        }
                    }
                    _ => {}
                }
                tri
            })
            .collect()
    })
}

fn float_soup(n: usize) -> impl Strategy<Value = Vec<Tri>> {
    prop::collection::vec(
        (
            prop::array::uniform3(-4.0f64..4.0),
            prop::array::uniform3(prop::array::uniform3(-0.6f64..0.6)),
        ),
        n,
    )
    .prop_map(|v| {
        v.into_iter()
            .map(|(c, d)| d.map(|o| p(c[0] + o[0], c[1] + o[1], c[2] + o[2])))
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn oracle_prop_pairs_eq_brute_int(a in int_soup(300), b in int_soup(250)) {
        let got = intersecting_pairs(&a, &b);
        prop_assert!(got.windows(2).all(|w| w[0] < w[1]));
        prop_assert_eq!(got, brute_force_pairs(&a, &b));
    }

    #[test]
    fn oracle_prop_pairs_eq_brute_float(a in float_soup(200), b in float_soup(300)) {
        prop_assert_eq!(intersecting_pairs(&a, &b), brute_force_pairs(&a, &b));
    }
}

/// Hand-made: which pairs have a vertex exactly on the other's plane (the "on plane" cause of
/// an uncertain T.CHECK), in both orders.
#[test]
fn vertex_on_plane_cases() {
    let a = t([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let cases = [
        // a vertex of the second triangle on z = 0, outside the first: on its plane all the same
        (t([5.0, 5.0, 0.0], [5.0, 6.0, 1.0], [6.0, 5.0, 1.0]), true),
        // coplanar, disjoint
        (t([5.0, 5.0, 0.0], [6.0, 5.0, 0.0], [5.0, 6.0, 0.0]), true),
        // crossing through the interior: no vertex on either plane
        (
            t([0.25, 0.25, -1.0], [0.25, 0.25, 1.0], [3.0, 0.25, 1.0]),
            false,
        ),
        // 2^-60 above the plane: not on it
        (
            t(
                [0.25, 0.25, 2f64.powi(-60)],
                [0.25, 0.75, 1.0],
                [0.75, 0.25, 1.0],
            ),
            false,
        ),
        // the first triangle's vertex (0,0,0) lies on the second's plane x = 0
        (
            t([0.0, -1.0, -1.0], [0.0, 1.0, -1.0], [0.0, 0.0, 1.0]),
            true,
        ),
        // a segment (collinear) off the plane: no plane of its own, and no vertex on a's
        (t([0.5, 0.5, 1.0], [0.5, 0.5, 2.0], [0.5, 0.5, 3.0]), false),
    ];
    for (i, (b, want)) in cases.iter().enumerate() {
        assert_eq!(vertex_on_plane(&a, b), *want, "case {i}");
        assert_eq!(vertex_on_plane(b, &a), *want, "case {i} swapped");
    }
}
