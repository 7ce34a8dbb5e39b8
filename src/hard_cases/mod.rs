//! Hard cases for the triangle test: touching, coplanar, degenerate, sliver, near-parallel,
//! far-translated, quarter-turned and badly scaled triangle pairs, where T.CHECK's
//! arithmetic is weakest.
//!
//! Two sources, both giving [`Case`]s:
//! - the **catalogue** `vectors/hard-cases/*.toml` (one case per file, literal tiny meshes,
//!   the expected pairs and TRI_UNIT's verdict on every pair per format reasoned out by
//!   hand and stated in the file), see [`load`];
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
//!
//! [verdict]         # TRI_UNIT's verdict on every pair per format, derived by hand (docs/explanation/accuracy.md)
//! binary32 = "uncertain"                # intersecting, separate, uncertain, or a documented
//! e8m15 = "uncertain"                   # intersecting-or-uncertain / separate-or-uncertain
//! why = "B's apex is in A's plane: its height is exactly 0"
//! [[verdict.exception]]                 # optional: other verdicts for some pairs
//! pairs = [[0, 0]]
//! binary32 = "separate"
//! e8m15 = "separate"
//! why = "one line: the deciding value, its margin and its error"
//! ```

use crate::format::Format;
use crate::golden::tri_unit::TriResult;
use crate::oracle::{self, Tri};
use crate::pose::Pose;
use crate::query::place;
use nalgebra::{Point3, Vector3};
use serde::Deserialize;
use std::ops::Range;
use std::path::{Path, PathBuf};
use toml::Spanned;

mod generators;
pub use generators::*;
#[cfg(test)]
mod tests;

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

/// The formats a catalogue file states TRI_UNIT's verdicts for (the file's keys are their
/// names: `binary32`, `e8m15`), the formats the chip tests in tb/hard_cases.rs use.
pub const VERDICT_FORMATS: [Format; 2] = [Format::BINARY32, Format::REDUCED];

/// TRI_UNIT's verdict on one pair, as a catalogue file states it: derived by hand from the
/// geometry (docs/explanation/accuracy.md, "Expected verdicts"), not taken from the chip. The two
/// "or uncertain" verdicts are for margins too close to the error bound to call by hand.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    Intersecting,
    Separate,
    Uncertain,
    IntersectingOrUncertain,
    SeparateOrUncertain,
}

impl Verdict {
    /// TRI_UNIT's answer as a verdict (intersecting, separate or uncertain).
    pub fn of(r: TriResult) -> Verdict {
        match (r.uncertain, r.hit) {
            (true, _) => Verdict::Uncertain,
            (false, true) => Verdict::Intersecting,
            (false, false) => Verdict::Separate,
        }
    }

    /// Whether TRI_UNIT's verdict `got` (one of the three of [`Verdict::of`]) is this one.
    pub fn admits(self, got: Verdict) -> bool {
        match self {
            Verdict::IntersectingOrUncertain => {
                matches!(got, Verdict::Intersecting | Verdict::Uncertain)
            }
            Verdict::SeparateOrUncertain => matches!(got, Verdict::Separate | Verdict::Uncertain),
            v => v == got,
        }
    }

    /// Whether the verdict can be right for a pair that does (or does not) intersect.
    pub fn fits(self, intersects: bool) -> bool {
        match self {
            Verdict::Intersecting | Verdict::IntersectingOrUncertain => intersects,
            Verdict::Separate | Verdict::SeparateOrUncertain => !intersects,
            Verdict::Uncertain => true,
        }
    }

    /// The verdict with "or uncertain" added to a decided one.
    pub fn or_uncertain(self) -> Verdict {
        match self {
            Verdict::Intersecting => Verdict::IntersectingOrUncertain,
            Verdict::Separate => Verdict::SeparateOrUncertain,
            v => v,
        }
    }

    /// The name used in catalogue files.
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Intersecting => "intersecting",
            Verdict::Separate => "separate",
            Verdict::Uncertain => "uncertain",
            Verdict::IntersectingOrUncertain => "intersecting-or-uncertain",
            Verdict::SeparateOrUncertain => "separate-or-uncertain",
        }
    }
}

/// The stated verdicts of one pair `(a index, b index)`, per format of [`VERDICT_FORMATS`].
#[derive(Clone, Debug, PartialEq)]
pub struct PairVerdict {
    pub pair: (u32, u32),
    pub verdicts: [Verdict; 2],
    pub why: String,
}

/// One hard case: A's triangles, B's triangles in B's frame, the pose placing B in A's frame,
/// the exact intersecting pairs `(a index, b index)`, sorted, and TRI_UNIT's verdicts.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    pub name: String,
    pub family: String,
    pub why: String,
    pub pose: Pose,
    pub a: Vec<Tri>,
    pub b: Vec<Tri>,
    pub expected: Vec<(u32, u32)>,
    /// Every pair's verdicts, sorted by pair (catalogue cases and their exact variants);
    /// empty for generated or moved cases, whose verdicts nobody derived.
    pub verdicts: Vec<PairVerdict>,
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
    verdict: Option<VerdictTable>,
}

/// `[verdict]`: the verdict of every pair, but those of the exceptions.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct VerdictTable {
    binary32: Spanned<Verdict>,
    e8m15: Spanned<Verdict>,
    why: Spanned<String>,
    #[serde(default)]
    exception: Vec<VerdictException>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct VerdictException {
    pairs: Spanned<Vec<[u32; 2]>>,
    binary32: Spanned<Verdict>,
    e8m15: Spanned<Verdict>,
    why: Spanned<String>,
}

fn tris(v: &[[[f64; 3]; 3]]) -> Vec<Tri> {
    v.iter()
        .map(|t| t.map(|p| Point3::new(p[0], p[1], p[2])))
        .collect()
}

/// Loads one catalogue file. Errors name the file (and the line, for syntax errors).
pub fn load(path: &Path) -> Result<Case, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("{}: cannot read hard case: {e}", path.display()))?;
    parse(&text, &path.display().to_string())
}

/// Parses a catalogue file's text; `name` (the file name) is used in error messages.
pub fn parse(text: &str, name: &str) -> Result<Case, String> {
    let line = |s: &Range<usize>| text[..s.start].matches('\n').count() + 1;
    let f: File = toml::from_str(text).map_err(|e| match e.span() {
        Some(s) => format!("{name}:{}: {}", line(&s), e.message()),
        None => format!("{name}: {}", e.message()),
    })?;
    let err = |m: String| format!("{name}: {m}");
    if f.name.trim().is_empty() || f.why.trim().is_empty() {
        return Err(err("`name` and `why` must not be empty".into()));
    }
    if !FAMILIES.contains(&f.family.as_str()) {
        return Err(err(format!(
            "family `{}` unknown; use one of {}",
            f.family,
            FAMILIES.join(", ")
        )));
    }
    if f.a.is_empty() || f.b.is_empty() {
        return Err(err("both `a` and `b` need at least one triangle".into()));
    }
    for (obj, ts) in [("a", &f.a), ("b", &f.b)] {
        if let Some(i) = ts
            .iter()
            .position(|t| !t.iter().flatten().all(|x| x.is_finite()))
        {
            return Err(err(format!("{obj}[{i}] has a non-finite coordinate")));
        }
    }
    if !f
        .pose
        .rot_deg
        .iter()
        .chain(&f.pose.t)
        .all(|x| x.is_finite())
    {
        return Err(err(format!(
            "pose {} has a non-finite number",
            f.pose.text()
        )));
    }
    let expected: Vec<(u32, u32)> = f.expected.iter().map(|p| (p[0], p[1])).collect();
    if let Some(p) = expected
        .iter()
        .find(|p| p.0 as usize >= f.a.len() || p.1 as usize >= f.b.len())
    {
        return Err(err(format!(
            "expected pair [{}, {}] is out of range ({} x {} triangles)",
            p.0,
            p.1,
            f.a.len(),
            f.b.len()
        )));
    }
    if expected.windows(2).any(|w| w[0] >= w[1]) {
        return Err(err(
            "`expected` must be sorted ascending without duplicates".into(),
        ));
    }
    let Some(vt) = f.verdict else {
        return Err(err("no [verdict] table: every hard case states TRI_UNIT's verdict on its pairs in binary32 and e8m15, and why (docs/explanation/accuracy.md)".into()));
    };
    let verdicts = pair_verdicts(vt, (f.a.len(), f.b.len()), &expected, &|s, m| {
        format!("{name}:{}: {m}", line(s))
    })?;
    Ok(Case {
        name: f.name,
        family: f.family,
        why: f.why,
        pose: f.pose,
        a: tris(&f.a),
        b: tris(&f.b),
        expected,
        verdicts,
    })
}

/// Every pair's verdicts from `[verdict]` (`dims` = triangles of A and B), checked against
/// `expected`; `at(span, message)` names the file and line.
fn pair_verdicts(
    vt: VerdictTable,
    dims: (usize, usize),
    expected: &[(u32, u32)],
    at: &dyn Fn(&Range<usize>, String) -> String,
) -> Result<Vec<PairVerdict>, String> {
    type Stated = (PairVerdict, [Range<usize>; 2], bool);
    let entry = |pair,
                 b32: &Spanned<Verdict>,
                 e8: &Spanned<Verdict>,
                 why: &Spanned<String>|
     -> Result<Stated, String> {
        if why.get_ref().trim().is_empty() {
            return Err(at(
                &why.span(),
                "the verdict's `why` must not be empty".into(),
            ));
        }
        let pv = PairVerdict {
            pair,
            verdicts: [*b32.get_ref(), *e8.get_ref()],
            why: why.get_ref().clone(),
        };
        Ok((pv, [b32.span(), e8.span()], false))
    };
    let mut all = Vec::with_capacity(dims.0 * dims.1);
    for i in 0..dims.0 as u32 {
        for j in 0..dims.1 as u32 {
            all.push(entry((i, j), &vt.binary32, &vt.e8m15, &vt.why)?);
        }
    }
    for ex in &vt.exception {
        if ex.pairs.get_ref().is_empty() {
            return Err(at(
                &ex.pairs.span(),
                "an exception needs at least one pair".into(),
            ));
        }
        for p in ex.pairs.get_ref() {
            let (i, j) = (p[0] as usize, p[1] as usize);
            if i >= dims.0 || j >= dims.1 {
                return Err(at(
                    &ex.pairs.span(),
                    format!(
                        "exception pair [{i}, {j}] is out of range ({} x {} triangles)",
                        dims.0, dims.1
                    ),
                ));
            }
            let slot = &mut all[i * dims.1 + j];
            if slot.2 {
                return Err(at(
                    &ex.pairs.span(),
                    format!("pair [{i}, {j}] is in two exceptions"),
                ));
            }
            *slot = entry((p[0], p[1]), &ex.binary32, &ex.e8m15, &ex.why)?;
            slot.2 = true;
        }
    }
    for (pv, spans, _) in &all {
        let hit = expected.contains(&pv.pair);
        for (k, v) in pv.verdicts.iter().enumerate() {
            if !v.fits(hit) {
                let (i, j) = pv.pair;
                let truth = if hit {
                    "intersects"
                } else {
                    "does not intersect"
                };
                return Err(at(&spans[k], format!("{} verdict `{}` for pair [{i}, {j}], which {truth} (`expected`): a decided verdict must be exact", VERDICT_FORMATS[k], v.name())));
            }
        }
    }
    Ok(all.into_iter().map(|e| e.0).collect())
}

/// `CARGO_MANIFEST_DIR/vectors/hard-cases`.
pub fn catalogue_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("vectors")
        .join("hard-cases")
}

/// Every `*.toml` of [`catalogue_dir`], in file-name order.
pub fn load_catalogue() -> Result<Vec<Case>, String> {
    let dir = catalogue_dir();
    let rd = std::fs::read_dir(&dir)
        .map_err(|e| format!("{}: cannot read the catalogue: {e}", dir.display()))?;
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
pub const VERTEX_ORDERS: [[usize; 3]; 6] = [
    [0, 1, 2],
    [0, 2, 1],
    [1, 0, 2],
    [1, 2, 0],
    [2, 0, 1],
    [2, 1, 0],
];

/// Rotation angles (multiples of 90 degrees) for every rotation of the cube group, or None.
fn quarter_turn_angles(r: &nalgebra::Matrix3<f64>) -> Option<[f64; 3]> {
    for i in 0..64 {
        let rot = [
            (i % 4) as f64 * 90.0,
            ((i / 4) % 4) as f64 * 90.0,
            (i / 16) as f64 * 90.0,
        ];
        if (Pose {
            rot_deg: rot,
            t: [0.0; 3],
        })
        .rotation()
            == *r
        {
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
    /// construction) and drops the verdicts (derived for the original geometry only).
    pub fn with_oracle_expected(mut self) -> Case {
        self.expected = self.oracle_pairs();
        self.verdicts.clear();
        self
    }

    /// The stated verdict of `pair` in `format` and why; None if the case states none.
    pub fn verdict(&self, pair: (u32, u32), format: Format) -> Option<(Verdict, &str)> {
        let k = VERDICT_FORMATS.iter().position(|&f| f == format)?;
        let i = self.verdicts.binary_search_by_key(&pair, |v| v.pair).ok()?;
        Some((self.verdicts[i].verdicts[k], self.verdicts[i].why.as_str()))
    }

    /// A and B exchanged with the identity pose: A' = B placed, B' = A. Always exact.
    pub fn swapped(&self) -> Case {
        let mut expected: Vec<(u32, u32)> = self.expected.iter().map(|&(i, j)| (j, i)).collect();
        expected.sort_unstable();
        // Swapping only relabels TRI_UNIT's two directions: the derivations carry over.
        let mut verdicts: Vec<PairVerdict> = self
            .verdicts
            .iter()
            .map(|v| PairVerdict {
                pair: (v.pair.1, v.pair.0),
                ..v.clone()
            })
            .collect();
        verdicts.sort_unstable_by_key(|v| v.pair);
        Case {
            name: format!("{} (swapped)", self.name),
            family: self.family.clone(),
            why: self.why.clone(),
            pose: Pose::default(),
            a: self.placed_b(),
            b: self.a.clone(),
            expected,
            verdicts,
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
        c.pose = Pose {
            rot_deg: rot,
            t: [ti.x, ti.y, ti.z],
        };
        c.a = self.b.clone();
        c.b = self.a.clone();
        Some(c)
    }

    /// The vertices of every triangle of A reordered by `VERTEX_ORDERS[oa]`, of B by
    /// `VERTEX_ORDERS[ob]`. The same closed sets: the answer must not change. A decided
    /// verdict may become uncertain (unless the order is unchanged): a unit-triangle map
    /// that starts at another vertex has another translation, so its terms change size
    /// (vv-gap-2e-30 is decided only while B's map starts at its apex, docs/explanation/accuracy.md).
    pub fn with_vertex_orders(&self, oa: usize, ob: usize) -> Case {
        let (pa, pb) = (VERTEX_ORDERS[oa], VERTEX_ORDERS[ob]);
        let mut c = self.clone();
        c.name = format!("{} (vertex orders {pa:?} {pb:?})", self.name);
        c.a = self.a.iter().map(|t| pa.map(|i| t[i])).collect();
        c.b = self.b.iter().map(|t| pb.map(|i| t[i])).collect();
        if oa + ob > 0 {
            for v in &mut c.verdicts {
                v.verdicts = v.verdicts.map(Verdict::or_uncertain);
            }
        }
        c
    }

    /// A and B placed, both mapped by `m`, identity pose. Exact, so the answer must not change
    /// (nor the verdicts: floating point is blind to power-of-two scales and axis changes).
    pub fn mapped(&self, m: &ExactMap) -> Case {
        let mut c = self.clone();
        c.name = format!("{} (mapped by {m:?})", self.name);
        c.a = self.a.iter().map(|t| t.map(|p| m.apply(&p))).collect();
        c.b = self
            .placed_b()
            .iter()
            .map(|t| t.map(|p| m.apply(&p)))
            .collect();
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
