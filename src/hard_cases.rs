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

#[cfg(test)]
mod tests {
    use super::*;

    const V: &str = "[verdict]\nbinary32 = \"uncertain\"\ne8m15 = \"uncertain\"\nwhy = \"w\"\n";

    #[test]
    fn parse_errors_name_file_and_line() {
        let e = parse(
            "name = \"x\"\nfamily = \"vertex-face\"\nwhy = 3\n",
            "f.toml",
        )
        .unwrap_err();
        assert!(e.starts_with("f.toml:3:"), "{e}");
        let ok = "name = \"x\"\nfamily = \"vertex-face\"\nwhy = \"y\"\na = [[[0,0,0],[1,0,0],[0,1,0]]]\nb = [[[0,0,0],[1,0,0],[0,1,0]]]\n";
        assert!(parse(&format!("{ok}expected = [[0, 1]]\n{V}"), "f.toml")
            .unwrap_err()
            .contains("out of range"));
        assert!(
            parse(&format!("{ok}expected = [[0, 0], [0, 0]]\n{V}"), "f.toml")
                .unwrap_err()
                .contains("sorted")
        );
        assert!(parse(
            &format!("{ok}expected = []\n{V}").replace("vertex-face", "nope"),
            "f.toml"
        )
        .unwrap_err()
        .contains("unknown"));
        assert_eq!(
            parse(&format!("{ok}expected = [[0, 0]]\n{V}"), "f.toml")
                .unwrap()
                .expected,
            vec![(0, 0)]
        );
    }

    #[test]
    fn verdict_errors_name_file_and_line() {
        assert_eq!(
            VERDICT_FORMATS.map(|f| f.to_string()),
            ["binary32", "e8m15"],
            "the files' keys"
        );
        // Two triangles of A, one of B; pair (1, 0) intersects.
        let head = "name = \"x\"\nfamily = \"vertex-face\"\nwhy = \"y\"\na = [[[0,0,0],[1,0,0],[0,1,0]], [[0,0,0],[1,0,0],[0,1,0]]]\nb = [[[0,0,0],[1,0,0],[0,1,0]]]\nexpected = [[1, 0]]\n";
        let e = parse(head, "f.toml").unwrap_err();
        assert!(e.starts_with("f.toml: no [verdict] table"), "{e}");
        let e = parse(
            &format!(
                "{head}{}",
                V.replace("e8m15 = \"uncertain\"", "e8m15 = \"maybe\"")
            ),
            "f.toml",
        )
        .unwrap_err();
        assert!(e.starts_with("f.toml:9:") && e.contains("maybe"), "{e}");
        let e = parse(
            &format!("{head}{}", V.replace("e8m15 = \"uncertain\"\n", "")),
            "f.toml",
        )
        .unwrap_err();
        assert!(e.starts_with("f.toml:7:") && e.contains("e8m15"), "{e}");
        // The default says separate, which pair (1, 0) contradicts.
        let e = parse(
            &format!(
                "{head}{}",
                V.replace("e8m15 = \"uncertain\"", "e8m15 = \"separate-or-uncertain\"")
            ),
            "f.toml",
        )
        .unwrap_err();
        assert!(
            e.starts_with(
                "f.toml:9: e8m15 verdict `separate-or-uncertain` for pair [1, 0], which intersects"
            ),
            "{e}"
        );
        let ex = |pairs: &str, b32: &str| {
            format!("{head}{V}[[verdict.exception]]\npairs = {pairs}\nbinary32 = \"{b32}\"\ne8m15 = \"uncertain\"\nwhy = \"z\"\n")
        };
        let e = parse(&ex("[[0, 1]]", "separate"), "f.toml").unwrap_err();
        assert!(
            e.starts_with("f.toml:12: exception pair [0, 1] is out of range"),
            "{e}"
        );
        let e = parse(&ex("[[0, 0]]", "intersecting"), "f.toml").unwrap_err();
        assert!(e.starts_with("f.toml:13: binary32 verdict `intersecting` for pair [0, 0], which does not intersect"), "{e}");
        let e = parse(&ex("[[0, 0], [0, 0]]", "separate"), "f.toml").unwrap_err();
        assert!(
            e.starts_with("f.toml:12: pair [0, 0] is in two exceptions"),
            "{e}"
        );
        let e = parse(&format!("{head}{}", V.replace("\"w\"", "\" \"")), "f.toml").unwrap_err();
        assert!(
            e.starts_with("f.toml:10: the verdict's `why` must not be empty"),
            "{e}"
        );
        let c = parse(&ex("[[0, 0]]", "separate"), "f.toml").unwrap();
        assert_eq!(
            c.verdict((0, 0), Format::BINARY32),
            Some((Verdict::Separate, "z"))
        );
        assert_eq!(
            c.verdict((1, 0), Format::BINARY32),
            Some((Verdict::Uncertain, "w"))
        );
        assert_eq!(
            c.verdict((0, 0), Format::REDUCED),
            Some((Verdict::Uncertain, "z"))
        );
        assert_eq!(c.verdict((0, 0), Format::new(5, 4).unwrap()), None);
        let s = c.swapped();
        assert_eq!(
            s.verdict((0, 0), Format::BINARY32),
            Some((Verdict::Separate, "z"))
        );
        assert_eq!(
            s.verdict((0, 1), Format::BINARY32),
            Some((Verdict::Uncertain, "w"))
        );
    }

    #[test]
    #[should_panic(expected = "not exact")]
    fn generators_refuse_inexact_placements() {
        let p = Placement {
            offset: [0.0, 0.0, 1e7],
            scale: 1.0,
            turns: [0; 3],
        };
        vertex_face(&p, [0.25, 0.25], 2f64.powi(-40));
    }

    #[test]
    fn quarter_turn_placement_is_exact() {
        let p = Placement {
            offset: [1024.0, -3.0, 0.5],
            scale: 0.25,
            turns: [1, 2, 3],
        };
        let c = vertex_face(&p, [0.25, 0.25], 0.0);
        assert_eq!(c.placed_b()[0][0], Point3::new(1024.0625, -2.9375, 0.5));
    }
}
