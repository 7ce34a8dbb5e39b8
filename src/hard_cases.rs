//! Hard cases for the triangle test: touching, coplanar, degenerate, sliver, near-parallel,
//! far-translated, quarter-turned and badly scaled triangle pairs, where T.CHECK's
//! arithmetic is weakest.
//!
//! Two sources, both giving [`Case`]s:
//! - the **catalogue** `vectors/hard-cases/*.toml` (one case per file, literal tiny meshes,
//!   the expected pairs reasoned out by hand and stated in the file), see [`load`];
//! - **generators** (proptest-free, deterministic: every parameter explicit), one per
//!   family, which build a configuration in a local unit frame from dyadic numbers and put
//!   it somewhere with a [`Placement`] (power-of-two scale, dyadic offset, quarter turns).
//!   Their `expected` is known by construction: every coordinate the generator computes is
//!   checked to be exact in f64 (a generator **panics** naming the inexact value otherwise),
//!   so the contact (or the gap) survives the placement and the exact oracle must agree.
//!   [`Case::moved_by`] leaves that regime (general rotations) and fills `expected` from the
//!   oracle instead.
//!
//! A catalogue file:
//! ```toml
//! name = "vertex touches face"
//! family = "vertex-face"                # one of FAMILIES
//! why = "one sentence: what makes it hard"
//! pose = { rot_deg = [0, 0, 0], t = [0, 0, 0] }   # B in A's frame, as src/pose.rs
//! a = [ [[0,0,0],[1,0,0],[0,1,0]] ]    # triangles of A (f64)
//! b = [ [[0.25,0.25,0],[0.25,0.25,1],[1,1,1]] ]   # triangles of B, in B's frame
//! expected = [[0, 0]]                  # exact intersecting pairs (a, b), sorted, closed triangles
//! ```

use crate::oracle::{self, Tri};
use crate::pose::Pose;
use crate::query::place;
use nalgebra::{Point3, Vector3};
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// The families of the catalogue (each has at least one case).
pub const FAMILIES: [&str; 13] = [
    "vertex-vertex",
    "vertex-edge",
    "vertex-face",
    "edge-edge",
    "coplanar-overlap",
    "coplanar-disjoint",
    "shared-edge",
    "sliver",
    "zero-area",
    "near-parallel",
    "translated",
    "rotated",
    "scale-ratio",
];

/// One hard case: A's triangles, B's triangles in B's frame, the pose placing B in A's frame,
/// and the exact intersecting pairs `(a index, b index)`, sorted.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    pub name: String,
    pub family: String,
    pub why: String,
    pub pose: Pose,
    pub a: Vec<Tri>,
    pub b: Vec<Tri>,
    pub expected: Vec<(u32, u32)>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    name: String,
    family: String,
    why: String,
    #[serde(default)]
    pose: Pose,
    a: Vec<[[f64; 3]; 3]>,
    b: Vec<[[f64; 3]; 3]>,
    expected: Vec<[u32; 2]>,
}

fn tris(v: &[[[f64; 3]; 3]]) -> Vec<Tri> {
    v.iter().map(|t| t.map(|p| Point3::new(p[0], p[1], p[2]))).collect()
}

/// Loads one catalogue file. Errors name the file (and the line, for syntax errors).
pub fn load(path: &Path) -> Result<Case, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: cannot read hard case: {e}", path.display()))?;
    parse(&text, &path.display().to_string())
}

/// Parses a catalogue file's text; `name` (the file name) is used in error messages.
pub fn parse(text: &str, name: &str) -> Result<Case, String> {
    let f: File = toml::from_str(text).map_err(|e| {
        match e.span().map(|s| text[..s.start].matches('\n').count() + 1) {
            Some(l) => format!("{name}:{l}: {}", e.message()),
            None => format!("{name}: {}", e.message()),
        }
    })?;
    let err = |m: String| format!("{name}: {m}");
    if f.name.trim().is_empty() || f.why.trim().is_empty() {
        return Err(err("`name` and `why` must not be empty".into()));
    }
    if !FAMILIES.contains(&f.family.as_str()) {
        return Err(err(format!("family `{}` unknown; use one of {}", f.family, FAMILIES.join(", "))));
    }
    if f.a.is_empty() || f.b.is_empty() {
        return Err(err("both `a` and `b` need at least one triangle".into()));
    }
    for (obj, ts) in [("a", &f.a), ("b", &f.b)] {
        if let Some(i) = ts.iter().position(|t| !t.iter().flatten().all(|x| x.is_finite())) {
            return Err(err(format!("{obj}[{i}] has a non-finite coordinate")));
        }
    }
    if !f.pose.rot_deg.iter().chain(&f.pose.t).all(|x| x.is_finite()) {
        return Err(err(format!("pose {} has a non-finite number", f.pose.text())));
    }
    let expected: Vec<(u32, u32)> = f.expected.iter().map(|p| (p[0], p[1])).collect();
    if let Some(p) = expected.iter().find(|p| p.0 as usize >= f.a.len() || p.1 as usize >= f.b.len()) {
        return Err(err(format!("expected pair [{}, {}] is out of range ({} x {} triangles)", p.0, p.1, f.a.len(), f.b.len())));
    }
    if expected.windows(2).any(|w| w[0] >= w[1]) {
        return Err(err("`expected` must be sorted ascending without duplicates".into()));
    }
    Ok(Case { name: f.name, family: f.family, why: f.why, pose: f.pose, a: tris(&f.a), b: tris(&f.b), expected })
}

/// `CARGO_MANIFEST_DIR/vectors/hard-cases`.
pub fn catalogue_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("vectors").join("hard-cases")
}

/// Every `*.toml` of [`catalogue_dir`], in file-name order.
pub fn load_catalogue() -> Result<Vec<Case>, String> {
    let dir = catalogue_dir();
    let rd = std::fs::read_dir(&dir).map_err(|e| format!("{}: cannot read the catalogue: {e}", dir.display()))?;
    let mut paths: Vec<PathBuf> = rd
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    if paths.is_empty() {
        return Err(format!("{}: no *.toml hard cases", dir.display()));
    }
    paths.iter().map(|p| load(p)).collect()
}

// ---------------------------------------------------------------------------------------
// Exact transformations of a case
// ---------------------------------------------------------------------------------------

/// An exact map of space: `x -> 2^scale_log2 * sign .* (x[perm[0]], x[perm[1]], x[perm[2]])`
/// (axis permutation, sign flips, power-of-two scale). Exact in f64 away from over/underflow.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExactMap {
    pub perm: [usize; 3],
    pub sign: [f64; 3],
    pub scale_log2: i32,
}

impl ExactMap {
    pub fn apply(&self, p: &Point3<f64>) -> Point3<f64> {
        let s = 2f64.powi(self.scale_log2);
        Point3::new(
            self.sign[0] * s * p[self.perm[0]],
            self.sign[1] * s * p[self.perm[1]],
            self.sign[2] * s * p[self.perm[2]],
        )
    }
}

/// The six orders of a triangle's vertices; index 0 is the identity.
pub const VERTEX_ORDERS: [[usize; 3]; 6] = [[0, 1, 2], [0, 2, 1], [1, 0, 2], [1, 2, 0], [2, 0, 1], [2, 1, 0]];

/// Rotation angles (multiples of 90 degrees) for every rotation of the cube group, or None.
fn quarter_turn_angles(r: &nalgebra::Matrix3<f64>) -> Option<[f64; 3]> {
    for i in 0..64 {
        let rot = [(i % 4) as f64 * 90.0, ((i / 4) % 4) as f64 * 90.0, (i / 16) as f64 * 90.0];
        if (Pose { rot_deg: rot, t: [0.0; 3] }).rotation() == *r {
            return Some(rot);
        }
    }
    None
}

fn exact_sum(a: f64, b: f64) -> Option<f64> {
    let s = a + b;
    let bb = s - a;
    let err = (a - (s - bb)) + (b - bb);
    (err == 0.0 && s.is_finite()).then_some(s)
}

impl Case {
    /// B's triangles in A's frame (f64, as the oracle sees them).
    pub fn placed_b(&self) -> Vec<Tri> {
        place(&self.b, &self.pose)
    }

    /// The exact oracle's pairs for this geometry.
    pub fn oracle_pairs(&self) -> Vec<(u32, u32)> {
        oracle::intersecting_pairs(&self.a, &self.placed_b())
    }

    /// Replaces `expected` by the oracle's answer (for geometry whose answer is not known by
    /// construction).
    pub fn with_oracle_expected(mut self) -> Case {
        self.expected = self.oracle_pairs();
        self
    }

    /// A and B exchanged with the identity pose: A' = B placed, B' = A. Always exact.
    pub fn swapped(&self) -> Case {
        let mut expected: Vec<(u32, u32)> = self.expected.iter().map(|&(i, j)| (j, i)).collect();
        expected.sort_unstable();
        Case {
            name: format!("{} (swapped)", self.name),
            family: self.family.clone(),
            why: self.why.clone(),
            pose: Pose::default(),
            a: self.placed_b(),
            b: self.a.clone(),
            expected,
        }
    }

    /// A and B exchanged with the inverse pose (A' = B in B's frame, B' = A, placed by
    /// `x_B = R^T x_A - R^T t`), when that is an exact rigid image of the original: the pose
    /// is a quarter turn, B's placement is exact and `a - t` is exact for A's vertices.
    /// None otherwise.
    pub fn swapped_inverse_pose(&self) -> Option<Case> {
        let r = self.pose.rotation();
        let rt = r.transpose();
        let rot = quarter_turn_angles(&rt)?;
        quarter_turn_angles(&r)?;
        let t = self.pose.translation();
        for tri in &self.b {
            for p in tri {
                let q = r * p;
                for i in 0..3 {
                    exact_sum(q[i], t[i])?;
                }
            }
        }
        for tri in &self.a {
            for p in tri {
                for i in 0..3 {
                    exact_sum(p[i], -t[i])?;
                }
            }
        }
        let ti: Vector3<f64> = -(rt * t);
        let mut c = self.swapped();
        c.name = format!("{} (swapped, inverse pose)", self.name);
        c.pose = Pose { rot_deg: rot, t: [ti.x, ti.y, ti.z] };
        c.a = self.b.clone();
        c.b = self.a.clone();
        Some(c)
    }

    /// The vertices of every triangle of A reordered by `VERTEX_ORDERS[oa]`, of B by
    /// `VERTEX_ORDERS[ob]`. The same closed sets: the answer must not change.
    pub fn with_vertex_orders(&self, oa: usize, ob: usize) -> Case {
        let (pa, pb) = (VERTEX_ORDERS[oa], VERTEX_ORDERS[ob]);
        let mut c = self.clone();
        c.name = format!("{} (vertex orders {pa:?} {pb:?})", self.name);
        c.a = self.a.iter().map(|t| pa.map(|i| t[i])).collect();
        c.b = self.b.iter().map(|t| pb.map(|i| t[i])).collect();
        c
    }

    /// A and B placed, both mapped by `m`, identity pose. Exact, so the answer must not change.
    pub fn mapped(&self, m: &ExactMap) -> Case {
        let mut c = self.clone();
        c.name = format!("{} (mapped by {m:?})", self.name);
        c.a = self.a.iter().map(|t| t.map(|p| m.apply(&p))).collect();
        c.b = self.placed_b().iter().map(|t| t.map(|p| m.apply(&p))).collect();
        c.pose = Pose::default();
        c
    }

    /// The whole configuration moved rigidly by `m` (any pose, in f64): A' = m(A), B' = B
    /// placed (in f64), pose' = m, so B' placed = m(B placed) rounded exactly as A' is. A
    /// general rotation does not keep contacts exact, so `expected` is **filled by the
    /// oracle** here.
    pub fn moved_by(&self, m: &Pose) -> Case {
        let mut c = self.clone();
        c.name = format!("{} (moved by {m:?})", self.name);
        c.a = place(&self.a, m);
        c.b = self.placed_b();
        c.pose = *m;
        c.with_oracle_expected()
    }
}

// ---------------------------------------------------------------------------------------
// Generators
// ---------------------------------------------------------------------------------------

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
    pub const IDENTITY: Placement = Placement { offset: [0.0; 3], scale: 1.0, turns: [0; 3] };

    pub fn pose(&self) -> Pose {
        Pose { rot_deg: self.turns.map(|q| (q % 4) as f64 * 90.0), t: self.offset }
    }

    fn scaled(&self, l: f64) -> f64 {
        assert!(
            self.scale > 0.0 && self.scale.is_finite() && self.scale.to_bits() & ((1u64 << 52) - 1) == 0,
            "placement scale {} is not a power of two",
            self.scale
        );
        let v = self.scale * l;
        assert!(v / self.scale == l && (v != 0.0 || l == 0.0), "scale {} * {l} is not exact", self.scale);
        v
    }

    fn point(&self, l: [f64; 3]) -> Point3<f64> {
        let mut out = [0.0; 3];
        for i in 0..3 {
            let v = self.scaled(l[i]);
            out[i] = exact_sum(v, self.offset[i])
                .unwrap_or_else(|| panic!("{v} + offset {} is not exact in f64 ({self:?})", self.offset[i]));
        }
        Point3::from(out)
    }

    /// Builds the case: A at `point(l)`, B written in its turned frame so that the pose
    /// places it exactly at `point(l)`.
    fn build(&self, name: String, family: &str, why: &str, a: &[[[f64; 3]; 3]], b: &[[[f64; 3]; 3]], expected: Vec<(u32, u32)>) -> Case {
        let pose = self.pose();
        let rt = pose.rotation().transpose();
        let a: Vec<Tri> = a.iter().map(|t| t.map(|l| self.point(l))).collect();
        let b_placed: Vec<Tri> = b.iter().map(|t| t.map(|l| self.point(l))).collect();
        let b_own: Vec<Tri> = b
            .iter()
            .map(|t| t.map(|l| Point3::from(rt * Vector3::new(self.scaled(l[0]), self.scaled(l[1]), self.scaled(l[2])))))
            .collect();
        assert_eq!(place(&b_own, &pose), b_placed, "placement of B is not exact ({self:?})");
        Case { name: format!("{name} at {self:?}"), family: family.into(), why: why.into(), pose, a, b: b_own, expected }
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
    p.build(format!("vertex-vertex gap {gap:e}"), "vertex-vertex", "B's apex at or just above A's vertex", &[U], &[b], pairs_if(gap == 0.0))
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
    let b = [[x, y, 0.0], [x, y, 1.0], [add(x, out[0]), add(y, out[1]), 1.0]];
    let expected = pairs_if(gap == 0.0 && (0.0..=1.0).contains(&s));
    p.build(format!("vertex-edge edge {} s {s:e} gap {gap:e}", edge % 3), "vertex-edge", "B's apex on or just outside an edge of A", &[U], &[b], expected)
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
        assert!(height >= -1.0 / 256.0 && u >= 0.0 && v >= 0.0 && add(u, v) <= 1.0 - 1.0 / 64.0, "piercing vertex_face needs a margin");
        true
    };
    let b = [[u, v, height], [u, v, 1.0], [add(u, 1.0), add(v, 1.0), 1.0]];
    p.build(format!("vertex-face uv {uv:?} height {height:e}"), "vertex-face", "B's apex at, above or just below A's face", &[U], &[b], pairs_if(expected))
}

/// Edge-edge: B in the plane x = s on the side y <= -gap, its vertical edge crossing A's edge
/// v0v1 (y = 0) at (s, 0, 0) when `gap == 0`. Touching iff `gap == 0` and `0 <= s <= 1`.
pub fn edge_edge(p: &Placement, s: f64, gap: f64) -> Case {
    assert!(gap >= 0.0);
    let b = [[s, -gap, -1.0], [s, -gap, 1.0], [s, add(-1.0, -gap), 0.0]];
    let expected = pairs_if(gap == 0.0 && (0.0..=1.0).contains(&s));
    p.build(format!("edge-edge s {s:e} gap {gap:e}"), "edge-edge", "an edge of B crossing, or skew to, an edge of A", &[U], &[b], expected)
}

/// Coplanar: A the unit triangle and B = A + (dx, dy) in the plane z = 0 (or, `tilted`, in
/// the plane z = x). They meet iff (dx, dy) lies in A - A = {|dx|, |dy|, |dx + dy| <= 1}.
pub fn coplanar(p: &Placement, shift: [f64; 2], tilted: bool) -> Case {
    let [dx, dy] = shift;
    let lift = |x: f64, y: f64| [x, y, if tilted { x } else { 0.0 }];
    let a = U.map(|q| lift(q[0], q[1]));
    let b = U.map(|q| lift(add(q[0], dx), add(q[1], dy)));
    let meet = dx.abs() <= 1.0 && dy.abs() <= 1.0 && add(dx, dy).abs() <= 1.0;
    let family = if meet { "coplanar-overlap" } else { "coplanar-disjoint" };
    p.build(format!("coplanar shift {shift:?} tilted {tilted}"), family, "coplanar triangles overlapping, touching or just apart", &[a], &[b], pairs_if(meet))
}

/// Shared edge: B = [(1,0,0), (0,1,0), apex] hinged on A's hypotenuse (coplanar when
/// apex.z == 0). Always intersecting. The apex must not be on the hypotenuse's line.
pub fn shared_edge(p: &Placement, apex: [f64; 3]) -> Case {
    assert!(apex[2] != 0.0 || add(apex[0], apex[1]) != 1.0, "apex on the shared edge's line");
    let b = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], apex];
    p.build(format!("shared-edge apex {apex:?}"), "shared-edge", "mesh neighbours sharing an edge", &[U], &[b], vec![(0, 0)])
}

/// Sliver needle: B = [(u, v, -1/2), (u, v, 1/2), (u + w, v, 1/2)], w = 2^-width_log2
/// (aspect about 2^width_log2), crossing A's plane in the segment x in [u, u + w/2], y = v.
/// Intersects iff `0 <= v <= 1`, `u <= 1 - v` and `u + w/2 >= 0`.
pub fn needle(p: &Placement, uv: [f64; 2], width_log2: i32) -> Case {
    let [u, v] = uv;
    let w = 2f64.powi(-width_log2);
    let b = [[u, v, -0.5], [u, v, 0.5], [add(u, w), v, 0.5]];
    let meet = (0.0..=1.0).contains(&v) && u <= add(1.0, -v) && add(u, w / 2.0) >= 0.0;
    p.build(format!("needle uv {uv:?} width 2^-{width_log2}"), "sliver", "a needle of aspect up to 1e6 crossing or missing A", &[U], &[b], pairs_if(meet))
}

/// Two slivers: A = [(0,0,0), (1,0,0), (1/2, w, 0)], B crossing A's plane in the segment
/// x in [1/4, 1/4 + w], y = y0, with w = 2^-width_log2 (width_log2 >= 3). Over that segment A
/// spans 0 <= y <= 2 w x, so they meet iff `0 <= y0 <= 2 w (1/4 + w)`.
pub fn sliver_pair(p: &Placement, width_log2: i32, y0: f64) -> Case {
    assert!(width_log2 >= 3);
    let w = 2f64.powi(-width_log2);
    let a = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, w, 0.0]];
    let b = [[0.25, add(y0, -0.5), -1.0], [0.25, add(y0, 0.5), 1.0], [add(0.25, w), y0, 0.0]];
    let meet = y0 >= 0.0 && y0 <= 2.0 * w * add(0.25, w);
    p.build(format!("sliver pair width 2^-{width_log2} y0 {y0:e}"), "sliver", "two slivers of aspect up to 1e6 crossing or just missing", &[a], &[b], pairs_if(meet))
}

/// Zero-area point: B = three copies of `pos`. Intersects iff pos.z == 0 and (x, y) in A.
pub fn point(p: &Placement, pos: [f64; 3]) -> Case {
    let meet = pos[2] == 0.0 && in_unit(pos[0], pos[1]);
    p.build(format!("point {pos:?}"), "zero-area", "B is a point: no plane, no unit-triangle map", &[U], &[[pos; 3]], pairs_if(meet))
}

/// Zero-area segment: B = vertical segment at (x, y) from z0 to z1 (z0 < z1; the third
/// vertex is the midpoint). Intersects iff z0 <= 0 <= z1 and (x, y) in A.
pub fn vertical_segment(p: &Placement, xy: [f64; 2], z0: f64, z1: f64) -> Case {
    assert!(z0 < z1);
    let [x, y] = xy;
    let mid = add(z0, z1) / 2.0;
    let b = [[x, y, z0], [x, y, z1], [x, y, mid]];
    let meet = z0 <= 0.0 && 0.0 <= z1 && in_unit(x, y);
    p.build(format!("segment at {xy:?} z {z0:e}..{z1:e}"), "zero-area", "B is a segment: no plane, no unit-triangle map", &[U], &[b], pairs_if(meet))
}

/// Two zero-area segments: A from (0,0,0) to (1,0,0) (third vertex (1/2,0,0)), B from
/// (s, y0, z) to (s, y1, z) (y0 < y1). Meet iff z == 0, 0 <= s <= 1 and y0 <= 0 <= y1.
pub fn segment_pair(p: &Placement, s: f64, y0: f64, y1: f64, z: f64) -> Case {
    assert!(y0 < y1);
    let a = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, 0.0, 0.0]];
    let b = [[s, y0, z], [s, y1, z], [s, add(y0, y1) / 2.0, z]];
    let meet = z == 0.0 && (0.0..=1.0).contains(&s) && y0 <= 0.0 && 0.0 <= y1;
    p.build(format!("segment pair s {s:e} y {y0:e}..{y1:e} z {z:e}"), "zero-area", "both triangles are segments: T.CHECK has no map at all", &[a], &[b], pairs_if(meet))
}

/// Near-parallel: B = [(0,0,gap), (1,0,gap + tilt), (0,1,gap)] over the unit triangle (the
/// same xy projection). They meet iff 0 lies between gap and gap + tilt.
pub fn near_parallel(p: &Placement, gap: f64, tilt: f64) -> Case {
    let top = add(gap, tilt);
    let b = [[0.0, 0.0, gap], [1.0, 0.0, top], [0.0, 1.0, gap]];
    let meet = gap.min(top) <= 0.0 && 0.0 <= gap.max(top);
    p.build(format!("near-parallel gap {gap:e} tilt {tilt:e}"), "near-parallel", "nearly parallel planes close together", &[U], &[b], pairs_if(meet))
}

/// Scale ratio: a big triangle 2^big_log2 * [(-1,-1,0), (2,-1,0), (-1,2,0)] (big_log2 >= 0)
/// and a tiny one [(1/4,1/4,h), (1/4,1/4,h+s), (1/4+s,1/4,h+s)], s = 2^-small_log2. They
/// meet iff h <= 0 <= h + s. `swap`: the tiny triangle is A and the big one B.
pub fn scale_ratio(p: &Placement, big_log2: i32, small_log2: i32, h: f64, swap: bool) -> Case {
    assert!(big_log2 >= 0);
    let (big, s) = (2f64.powi(big_log2), 2f64.powi(-small_log2));
    let bt = [[-big, -big, 0.0], [2.0 * big, -big, 0.0], [-big, 2.0 * big, 0.0]];
    let top = add(h, s);
    let tiny = [[0.25, 0.25, h], [0.25, 0.25, top], [add(0.25, s), 0.25, top]];
    let meet = h <= 0.0 && 0.0 <= top;
    let (a, b) = if swap { (tiny, bt) } else { (bt, tiny) };
    p.build(format!("scale 2^{big_log2} vs 2^-{small_log2} h {h:e} swap {swap}"), "scale-ratio", "triangle sizes apart by up to 1e8", &[a], &[b], pairs_if(meet))
}

/// Meshes: A the unit square split along its diagonal (a0 = {0 <= y <= x <= 1},
/// a1 = {0 <= x <= y <= 1}), B a tetrahedron with apex (x, y, h), h >= 0, and base 1 above
/// it. With h == 0 the three faces b0..b2 through the apex touch a0 iff the apex is in a0,
/// a1 iff in a1 (both on the diagonal); the base b3 never touches; with h > 0 nothing does.
pub fn tetra_on_square(p: &Placement, apex: [f64; 2], h: f64) -> Case {
    assert!(h >= 0.0);
    let [x, y] = apex;
    let a = [[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]], [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]]];
    let top = add(h, 1.0);
    let q = [[add(x, -0.5), add(y, -0.5), top], [add(x, 0.5), add(y, -0.5), top], [x, add(y, 0.5), top]];
    let ap = [x, y, h];
    let b = [[ap, q[0], q[1]], [ap, q[1], q[2]], [ap, q[2], q[0]], [q[0], q[1], q[2]]];
    let in_a0 = 0.0 <= y && y <= x && x <= 1.0;
    let in_a1 = 0.0 <= x && x <= y && y <= 1.0;
    let mut expected = vec![];
    for (i, inside) in [in_a0, in_a1].into_iter().enumerate() {
        if h == 0.0 && inside {
            expected.extend((0..3).map(|j| (i as u32, j)));
        }
    }
    p.build(format!("tetra apex {apex:?} h {h:e}"), "vertex-edge", "a tetrahedron's apex on a square's diagonal: several pairs meet in one point", &a, &b, expected)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parse_errors_name_file_and_line() {
        let e = parse("name = \"x\"\nfamily = \"vertex-face\"\nwhy = 3\n", "f.toml").unwrap_err();
        assert!(e.starts_with("f.toml:3:"), "{e}");
        let ok = "name = \"x\"\nfamily = \"vertex-face\"\nwhy = \"y\"\na = [[[0,0,0],[1,0,0],[0,1,0]]]\nb = [[[0,0,0],[1,0,0],[0,1,0]]]\n";
        assert!(parse(&format!("{ok}expected = [[0, 1]]\n"), "f.toml").unwrap_err().contains("out of range"));
        assert!(parse(&format!("{ok}expected = [[0, 0], [0, 0]]\n"), "f.toml").unwrap_err().contains("sorted"));
        assert!(parse(&format!("{ok}expected = []\n").replace("vertex-face", "nope"), "f.toml").unwrap_err().contains("unknown"));
        assert_eq!(parse(&format!("{ok}expected = [[0, 0]]\n"), "f.toml").unwrap().expected, vec![(0, 0)]);
    }

    #[test]
    #[should_panic(expected = "not exact")]
    fn generators_refuse_inexact_placements() {
        let p = Placement { offset: [0.0, 0.0, 1e7], scale: 1.0, turns: [0; 3] };
        vertex_face(&p, [0.25, 0.25], 2f64.powi(-40));
    }

    #[test]
    fn quarter_turn_placement_is_exact() {
        let p = Placement { offset: [1024.0, -3.0, 0.5], scale: 0.25, turns: [1, 2, 3] };
        let c = vertex_face(&p, [0.25, 0.25], 0.0);
        assert_eq!(c.placed_b()[0][0], Point3::new(1024.0625, -2.9375, 0.5));
    }
}
