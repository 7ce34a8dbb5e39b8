//! The generators: one per family, a configuration built in a local unit frame from dyadic
//! numbers and put somewhere by a [`Placement`], its `expected` known by construction.

use super::{exact_sum, Case};
use crate::oracle::Tri;
use crate::pose::Pose;
use crate::query::place;
use nalgebra::{Point3, Vector3};

/// Where a generator puts its local configuration: local point `l` goes to
/// `scale * l + offset` in A's frame; B is written in its own frame turned by
/// `turns * 90` degrees (x, y, z), with the pose `(turns * 90, offset)` bringing it back.
/// `scale` must be a power of two; every `scale * l + offset` must be exact in f64
/// (generators panic otherwise): take `offset` on a grid no finer than the configuration's
/// smallest feature times `scale`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    pub offset: [f64; 3],
    pub scale: f64,
    pub turns: [u8; 3],
}

impl Placement {
    pub const IDENTITY: Placement = Placement {
        offset: [0.0; 3],
        scale: 1.0,
        turns: [0; 3],
    };

    pub fn pose(&self) -> Pose {
        Pose {
            rot_deg: self.turns.map(|q| (q % 4) as f64 * 90.0),
            t: self.offset,
        }
    }

    fn scaled(&self, l: f64) -> f64 {
        assert!(
            self.scale > 0.0
                && self.scale.is_finite()
                && self.scale.to_bits() & ((1u64 << 52) - 1) == 0,
            "placement scale {} is not a power of two",
            self.scale
        );
        let v = self.scale * l;
        assert!(
            v / self.scale == l && (v != 0.0 || l == 0.0),
            "scale {} * {l} is not exact",
            self.scale
        );
        v
    }

    fn point(&self, l: [f64; 3]) -> Point3<f64> {
        let mut out = [0.0; 3];
        for i in 0..3 {
            let v = self.scaled(l[i]);
            out[i] = exact_sum(v, self.offset[i]).unwrap_or_else(|| {
                panic!(
                    "{v} + offset {} is not exact in f64 ({self:?})",
                    self.offset[i]
                )
            });
        }
        Point3::from(out)
    }

    /// Builds the case: A at `point(l)`, B written in its turned frame so that the pose
    /// places it exactly at `point(l)`.
    fn build(
        &self,
        name: String,
        family: &str,
        why: &str,
        a: &[[[f64; 3]; 3]],
        b: &[[[f64; 3]; 3]],
        expected: Vec<(u32, u32)>,
    ) -> Case {
        let pose = self.pose();
        let rt = pose.rotation().transpose();
        let a: Vec<Tri> = a.iter().map(|t| t.map(|l| self.point(l))).collect();
        let b_placed: Vec<Tri> = b.iter().map(|t| t.map(|l| self.point(l))).collect();
        let b_own: Vec<Tri> = b
            .iter()
            .map(|t| {
                t.map(|l| {
                    Point3::from(
                        rt * Vector3::new(self.scaled(l[0]), self.scaled(l[1]), self.scaled(l[2])),
                    )
                })
            })
            .collect();
        assert_eq!(
            place(&b_own, &pose),
            b_placed,
            "placement of B is not exact ({self:?})"
        );
        Case {
            name: format!("{name} at {self:?}"),
            family: family.into(),
            why: why.into(),
            pose,
            a,
            b: b_own,
            expected,
            verdicts: vec![],
        }
    }
}

/// `a + b`, panicking if not exact in f64 (generators build only exact geometry).
fn add(a: f64, b: f64) -> f64 {
    exact_sum(a, b).unwrap_or_else(|| panic!("{a} + {b} is not exact in f64"))
}

const U: [[f64; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];

fn pairs_if(b: bool) -> Vec<(u32, u32)> {
    if b {
        vec![(0, 0)]
    } else {
        vec![]
    }
}

/// In the closed unit triangle {x, y >= 0, x + y <= 1} (x + y computed exactly).
fn in_unit(x: f64, y: f64) -> bool {
    x >= 0.0 && y >= 0.0 && add(x, y) <= 1.0
}

/// Vertex-vertex: A the unit triangle, B's apex `gap >= 0` above A's vertex (1,0,0), B's
/// other vertices at height 1. Touching (one common point) iff `gap == 0`.
pub fn vertex_vertex(p: &Placement, gap: f64) -> Case {
    assert!(gap >= 0.0);
    let b = [[1.0, 0.0, gap], [1.5, -0.5, 1.0], [2.0, 0.5, 1.0]];
    p.build(
        format!("vertex-vertex gap {gap:e}"),
        "vertex-vertex",
        "B's apex at or just above A's vertex",
        &[U],
        &[b],
        pairs_if(gap == 0.0),
    )
}

/// Vertex-edge: B's apex in A's plane at parameter `s` along A's edge `edge` (0: v0v1,
/// 1: v1v2, 2: v2v0), moved `gap >= 0` outward (perpendicular to the edge in A's plane, by
/// (0,-1), (1,1) or (-1,0) times gap); B's other vertices at height 1 further out. Touching
/// iff `gap == 0` and `0 <= s <= 1`.
pub fn vertex_edge(p: &Placement, edge: u8, s: f64, gap: f64) -> Case {
    assert!(gap >= 0.0);
    let (x, y, out) = match edge % 3 {
        0 => (s, -gap, [0.0, -1.0]),
        1 => (add(add(1.0, -s), gap), add(s, gap), [1.0, 1.0]),
        _ => (-gap, add(1.0, -s), [-1.0, 0.0]),
    };
    let b = [
        [x, y, 0.0],
        [x, y, 1.0],
        [add(x, out[0]), add(y, out[1]), 1.0],
    ];
    let expected = pairs_if(gap == 0.0 && (0.0..=1.0).contains(&s));
    p.build(
        format!("vertex-edge edge {} s {s:e} gap {gap:e}", edge % 3),
        "vertex-edge",
        "B's apex on or just outside an edge of A",
        &[U],
        &[b],
        expected,
    )
}

/// Vertex-face: B = [(u, v, height), (u, v, 1), (u + 1, v + 1, 1)] against the unit
/// triangle. `height > 0`: apart; `height == 0`: touching iff (u, v) in A (closed);
/// `height < 0` (piercing) requires `-2^-8 <= height` and (u, v) inside with margin
/// (`u, v >= 0`, `u + v <= 1 - 2^-6`; panics otherwise), and then always intersects.
pub fn vertex_face(p: &Placement, uv: [f64; 2], height: f64) -> Case {
    let [u, v] = uv;
    let expected = if height > 0.0 {
        false
    } else if height == 0.0 {
        in_unit(u, v)
    } else {
        assert!(
            height >= -1.0 / 256.0 && u >= 0.0 && v >= 0.0 && add(u, v) <= 1.0 - 1.0 / 64.0,
            "piercing vertex_face needs a margin"
        );
        true
    };
    let b = [[u, v, height], [u, v, 1.0], [add(u, 1.0), add(v, 1.0), 1.0]];
    p.build(
        format!("vertex-face uv {uv:?} height {height:e}"),
        "vertex-face",
        "B's apex at, above or just below A's face",
        &[U],
        &[b],
        pairs_if(expected),
    )
}

/// Edge-edge: B in the plane x = s on the side y <= -gap, its vertical edge crossing A's edge
/// v0v1 (y = 0) at (s, 0, 0) when `gap == 0`. Touching iff `gap == 0` and `0 <= s <= 1`.
pub fn edge_edge(p: &Placement, s: f64, gap: f64) -> Case {
    assert!(gap >= 0.0);
    let b = [[s, -gap, -1.0], [s, -gap, 1.0], [s, add(-1.0, -gap), 0.0]];
    let expected = pairs_if(gap == 0.0 && (0.0..=1.0).contains(&s));
    p.build(
        format!("edge-edge s {s:e} gap {gap:e}"),
        "edge-edge",
        "an edge of B crossing, or skew to, an edge of A",
        &[U],
        &[b],
        expected,
    )
}

/// Coplanar: A the unit triangle and B = A + (dx, dy) in the plane z = 0 (or, `tilted`, in
/// the plane z = x). They meet iff (dx, dy) lies in A - A = {|dx|, |dy|, |dx + dy| <= 1}.
pub fn coplanar(p: &Placement, shift: [f64; 2], tilted: bool) -> Case {
    let [dx, dy] = shift;
    let lift = |x: f64, y: f64| [x, y, if tilted { x } else { 0.0 }];
    let a = U.map(|q| lift(q[0], q[1]));
    let b = U.map(|q| lift(add(q[0], dx), add(q[1], dy)));
    let meet = dx.abs() <= 1.0 && dy.abs() <= 1.0 && add(dx, dy).abs() <= 1.0;
    let family = if meet {
        "coplanar-overlap"
    } else {
        "coplanar-disjoint"
    };
    p.build(
        format!("coplanar shift {shift:?} tilted {tilted}"),
        family,
        "coplanar triangles overlapping, touching or just apart",
        &[a],
        &[b],
        pairs_if(meet),
    )
}

/// Shared edge: B = [(1,0,0), (0,1,0), apex] hinged on A's hypotenuse (coplanar when
/// apex.z == 0). Always intersecting. The apex must not be on the hypotenuse's line.
pub fn shared_edge(p: &Placement, apex: [f64; 3]) -> Case {
    assert!(
        apex[2] != 0.0 || add(apex[0], apex[1]) != 1.0,
        "apex on the shared edge's line"
    );
    let b = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], apex];
    p.build(
        format!("shared-edge apex {apex:?}"),
        "shared-edge",
        "mesh neighbours sharing an edge",
        &[U],
        &[b],
        vec![(0, 0)],
    )
}

/// Sliver needle: B = [(u, v, -1/2), (u, v, 1/2), (u + w, v, 1/2)], w = 2^-width_log2
/// (aspect about 2^width_log2), crossing A's plane in the segment x in [u, u + w/2], y = v.
/// Intersects iff `0 <= v <= 1`, `u <= 1 - v` and `u + w/2 >= 0`.
pub fn needle(p: &Placement, uv: [f64; 2], width_log2: i32) -> Case {
    let [u, v] = uv;
    let w = 2f64.powi(-width_log2);
    let b = [[u, v, -0.5], [u, v, 0.5], [add(u, w), v, 0.5]];
    let meet = (0.0..=1.0).contains(&v) && u <= add(1.0, -v) && add(u, w / 2.0) >= 0.0;
    p.build(
        format!("needle uv {uv:?} width 2^-{width_log2}"),
        "sliver",
        "a needle of aspect up to 1e6 crossing or missing A",
        &[U],
        &[b],
        pairs_if(meet),
    )
}

/// Two slivers: A = [(0,0,0), (1,0,0), (1/2, w, 0)], B crossing A's plane in the segment
/// x in [1/4, 1/4 + w], y = y0, with w = 2^-width_log2 (width_log2 >= 3). Over that segment A
/// spans 0 <= y <= 2 w x, so they meet iff `0 <= y0 <= 2 w (1/4 + w)`.
pub fn sliver_pair(p: &Placement, width_log2: i32, y0: f64) -> Case {
    assert!(width_log2 >= 3);
    let w = 2f64.powi(-width_log2);
    let a = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, w, 0.0]];
    let b = [
        [0.25, add(y0, -0.5), -1.0],
        [0.25, add(y0, 0.5), 1.0],
        [add(0.25, w), y0, 0.0],
    ];
    let meet = y0 >= 0.0 && y0 <= 2.0 * w * add(0.25, w);
    p.build(
        format!("sliver pair width 2^-{width_log2} y0 {y0:e}"),
        "sliver",
        "two slivers of aspect up to 1e6 crossing or just missing",
        &[a],
        &[b],
        pairs_if(meet),
    )
}

/// Zero-area point: B = three copies of `pos`. Intersects iff pos.z == 0 and (x, y) in A.
pub fn point(p: &Placement, pos: [f64; 3]) -> Case {
    let meet = pos[2] == 0.0 && in_unit(pos[0], pos[1]);
    p.build(
        format!("point {pos:?}"),
        "zero-area",
        "B is a point: no plane, no unit-triangle map",
        &[U],
        &[[pos; 3]],
        pairs_if(meet),
    )
}

/// Zero-area segment: B = vertical segment at (x, y) from z0 to z1 (z0 < z1; the third
/// vertex is the midpoint). Intersects iff z0 <= 0 <= z1 and (x, y) in A.
pub fn vertical_segment(p: &Placement, xy: [f64; 2], z0: f64, z1: f64) -> Case {
    assert!(z0 < z1);
    let [x, y] = xy;
    let mid = add(z0, z1) / 2.0;
    let b = [[x, y, z0], [x, y, z1], [x, y, mid]];
    let meet = z0 <= 0.0 && 0.0 <= z1 && in_unit(x, y);
    p.build(
        format!("segment at {xy:?} z {z0:e}..{z1:e}"),
        "zero-area",
        "B is a segment: no plane, no unit-triangle map",
        &[U],
        &[b],
        pairs_if(meet),
    )
}

/// Two zero-area segments: A from (0,0,0) to (1,0,0) (third vertex (1/2,0,0)), B from
/// (s, y0, z) to (s, y1, z) (y0 < y1). Meet iff z == 0, 0 <= s <= 1 and y0 <= 0 <= y1.
pub fn segment_pair(p: &Placement, s: f64, y0: f64, y1: f64, z: f64) -> Case {
    assert!(y0 < y1);
    let a = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, 0.0, 0.0]];
    let b = [[s, y0, z], [s, y1, z], [s, add(y0, y1) / 2.0, z]];
    let meet = z == 0.0 && (0.0..=1.0).contains(&s) && y0 <= 0.0 && 0.0 <= y1;
    p.build(
        format!("segment pair s {s:e} y {y0:e}..{y1:e} z {z:e}"),
        "zero-area",
        "both triangles are segments: T.CHECK has no map at all",
        &[a],
        &[b],
        pairs_if(meet),
    )
}

/// Near-parallel: B = [(0,0,gap), (1,0,gap + tilt), (0,1,gap)] over the unit triangle (the
/// same xy projection). They meet iff 0 lies between gap and gap + tilt.
pub fn near_parallel(p: &Placement, gap: f64, tilt: f64) -> Case {
    let top = add(gap, tilt);
    let b = [[0.0, 0.0, gap], [1.0, 0.0, top], [0.0, 1.0, gap]];
    let meet = gap.min(top) <= 0.0 && 0.0 <= gap.max(top);
    p.build(
        format!("near-parallel gap {gap:e} tilt {tilt:e}"),
        "near-parallel",
        "nearly parallel planes close together",
        &[U],
        &[b],
        pairs_if(meet),
    )
}

/// Scale ratio: a big triangle 2^big_log2 * [(-1,-1,0), (2,-1,0), (-1,2,0)] (big_log2 >= 0)
/// and a tiny one [(1/4,1/4,h), (1/4,1/4,h+s), (1/4+s,1/4,h+s)], s = 2^-small_log2. They
/// meet iff h <= 0 <= h + s. `swap`: the tiny triangle is A and the big one B.
pub fn scale_ratio(p: &Placement, big_log2: i32, small_log2: i32, h: f64, swap: bool) -> Case {
    assert!(big_log2 >= 0);
    let (big, s) = (2f64.powi(big_log2), 2f64.powi(-small_log2));
    let bt = [
        [-big, -big, 0.0],
        [2.0 * big, -big, 0.0],
        [-big, 2.0 * big, 0.0],
    ];
    let top = add(h, s);
    let tiny = [
        [0.25, 0.25, h],
        [0.25, 0.25, top],
        [add(0.25, s), 0.25, top],
    ];
    let meet = h <= 0.0 && 0.0 <= top;
    let (a, b) = if swap { (tiny, bt) } else { (bt, tiny) };
    p.build(
        format!("scale 2^{big_log2} vs 2^-{small_log2} h {h:e} swap {swap}"),
        "scale-ratio",
        "triangle sizes apart by up to 1e8",
        &[a],
        &[b],
        pairs_if(meet),
    )
}

/// Meshes: A the unit square split along its diagonal (a0 = {0 <= y <= x <= 1},
/// a1 = {0 <= x <= y <= 1}), B a tetrahedron with apex (x, y, h), h >= 0, and base 1 above
/// it. With h == 0 the three faces b0..b2 through the apex touch a0 iff the apex is in a0,
/// a1 iff in a1 (both on the diagonal); the base b3 never touches; with h > 0 nothing does.
pub fn tetra_on_square(p: &Placement, apex: [f64; 2], h: f64) -> Case {
    assert!(h >= 0.0);
    let [x, y] = apex;
    let a = [
        [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]],
        [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]],
    ];
    let top = add(h, 1.0);
    let q = [
        [add(x, -0.5), add(y, -0.5), top],
        [add(x, 0.5), add(y, -0.5), top],
        [x, add(y, 0.5), top],
    ];
    let ap = [x, y, h];
    let b = [
        [ap, q[0], q[1]],
        [ap, q[1], q[2]],
        [ap, q[2], q[0]],
        [q[0], q[1], q[2]],
    ];
    let in_a0 = 0.0 <= y && y <= x && x <= 1.0;
    let in_a1 = 0.0 <= x && x <= y && y <= 1.0;
    let mut expected = vec![];
    for (i, inside) in [in_a0, in_a1].into_iter().enumerate() {
        if h == 0.0 && inside {
            expected.extend((0..3).map(|j| (i as u32, j)));
        }
    }
    p.build(
        format!("tetra apex {apex:?} h {h:e}"),
        "vertex-edge",
        "a tetrahedron's apex on a square's diagonal: several pairs meet in one point",
        &a,
        &b,
        expected,
    )
}
