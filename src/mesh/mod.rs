//! Triangle meshes: file loaders (OBJ, STL, PLY), vendored meshes and procedural meshes.
//!
//! # Data model
//!
//! A [`Mesh`] is an indexed triangle list: `vertices` (as `f64` points) and `triangles`
//! (three 0-based vertex indices each).
//!
//! * **Triangle order** is the face order of the file: triangle `i` comes from the `i`-th face
//!   (or, for polygons, from the `i`-th triangle of the fan expansion described below), so
//!   triangle indices reported by the chip can be traced back to the file.
//! * **Polygons** with `k > 3` vertices `v0 … v(k-1)` are fan-triangulated into the `k - 2`
//!   triangles `(v0, v_i, v_(i+1))` for `i = 1 … k-2`, in that order, in place of the polygon.
//!   (For OBJ this is exactly tobj's `triangulate` option.)  Which faces were split is not
//!   recorded.
//! * **Vertex order** — PLY: as in the file (indices identical to the file's).  STL: vertices are
//!   de-duplicated by exact bit pattern in order of first use (stl_io's `read_stl`).  OBJ: per
//!   object/group in order of first use by a face (tobj); unreferenced `v` lines are dropped.
//! * **Coordinates** written as decimals (OBJ, ASCII STL, ASCII PLY, whatever type the PLY
//!   header declares) are read as the nearest `f64`: the file's numbers, not an `f32` rounding
//!   of them.  Binary STL and binary PLY `float` values are `f32` by definition and are widened
//!   exactly; binary PLY `double` values are kept.
//! * **Accepted**: degenerate (zero-area) triangles, repeated indices in a triangle, repeated
//!   vertices, non-manifold meshes, holes and inconsistent winding — real scanned data (e.g. the
//!   Stanford dragon) has all of these.
//! * **Rejected** (a [`MeshError`] naming the file and, for textual formats, the 1-based line):
//!   a NaN or infinite coordinate (even in an unused vertex), a coordinate outside the range the
//!   exact oracle is exact for (0 or magnitude 1e-60 to 1e60, see [`crate::oracle`]), data
//!   beyond the element counts of a PLY header, an index out of range, a face with
//!   fewer than 3 vertices, a truncated file (binary STL/PLY shorter than its header says, or an
//!   ASCII PLY/STL ending early), a mesh without triangles, an unsupported extension, an
//!   unreadable file, and any syntax error the parsing crates report.  No input makes the loaders
//!   panic (there is a property test feeding random and mutated files).
//!
//! # Formats
//!
//! * `.obj` (tobj): `v x y z [w]` (a `w` divides x, y, z; vertex colours are ignored), `f` with
//!   `v`, `v/vt`, `v//vn`, `v/vt/vn` references, negative (relative) references allowed.  `vt`,
//!   `vn`, `o`, `g`, `s`, `p` lines are parsed or skipped; `l` (polyline), `mtllib` and `usemtl`
//!   lines are ignored (materials are never loaded); a leading byte-order mark is skipped.
//!   Before tobj runs, a validation pass over the
//!   text checks every `v` and `f` line so that errors carry a line number.
//! * `.stl`: binary (stl_io) or ASCII (parsed here, keywords in any case).  A file is read as
//!   binary when its size is exactly `84 + 50·n` for the triangle count `n` in its header —
//!   even when it starts with `solid`, as many binary exporters write — and as ASCII otherwise
//!   if it starts with `solid` (any case, after an optional byte-order mark) and its first 512
//!   bytes are text.
//! * `.ply` (ply-rs): `ascii`, `binary_little_endian`, `binary_big_endian`.  Element `vertex`
//!   with scalar properties `x y z` (any numeric type), element `face` with a list property
//!   `vertex_indices` (or `vertex_index`) of any integer type; other elements and properties are
//!   read and ignored.
//!
//! Extensions are matched case-insensitively.  [`Mesh::name`] is the file stem for loaded files
//! and the spec for built-ins.
//!
//! # Built-in meshes ([`builtin`], [`resolve`])
//!
//! * `bunny` (3,674 triangles), `teapot` (992), `dragon-11k` (11,102): vendored OBJ files from
//!   `vectors/meshes/` embedded with `include_str!` (origin and licence in
//!   `vectors/meshes/README.md`).  Larger dragons: `scripts/fetch-dragon.sh` writes PLY files to
//!   `vectors/meshes/large/` which [`load`] reads.
//! * `sphere:N`, `torus:N`: closed procedural meshes with at least `N` triangles ([`sphere`],
//!   [`torus`] document the exact count).
//! * `soup:N`, `soup:N:SEED`: `N` random small triangles ([`soup`]); the default seed is 0.
//!
//! `N` must be between 1 and [`MAX_PROCEDURAL_TRIANGLES`].

use nalgebra::Point3;
use std::fmt;
use std::path::Path;

mod obj;
mod ply;
mod procedural;
mod stl;
#[cfg(test)]
mod tests;

pub use procedural::{soup, sphere, torus};

/// What a format parser returns: vertices and triangles, before the common checks.
type Parsed = (Vec<Point3<f64>>, Vec<[u32; 3]>);

/// Upper limit for `N` in the procedural built-in specs (`sphere:N`, `torus:N`, `soup:N`).
/// A query holds about 1 KB per triangle of each object (f64 geometry, DOP tree, memory
/// image: 365 MB for two 200k-triangle spheres), so two objects at the limit need about
/// 4 GB (2^24 needed tens of GB).
pub const MAX_PROCEDURAL_TRIANGLES: usize = 1 << 21;

/// Names accepted by [`builtin`] (for error messages and `--help` texts).
pub const BUILTIN_NAMES: &[&str] = &[
    "bunny",
    "teapot",
    "dragon-11k",
    "sphere:N",
    "torus:N",
    "soup:N",
    "soup:N:SEED",
];

const BUNNY_OBJ: &str = include_str!("../../vectors/meshes/bunny.obj");
const TEAPOT_OBJ: &str = include_str!("../../vectors/meshes/teapot.obj");
const DRAGON_11K_OBJ: &str = include_str!("../../vectors/meshes/dragon-11k.obj");

/// An indexed triangle mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    pub name: String,
    pub vertices: Vec<Point3<f64>>,
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    /// Number of triangles.
    pub fn len(&self) -> usize {
        self.triangles.len()
    }

    /// True if the mesh has no triangles.
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    /// The three corners of triangle `i` (panics if `i >= len()`).
    pub fn triangle(&self, i: usize) -> [Point3<f64>; 3] {
        let t = self.triangles[i];
        [
            self.vertices[t[0] as usize],
            self.vertices[t[1] as usize],
            self.vertices[t[2] as usize],
        ]
    }

    /// All triangles as corner triples, in triangle order.
    pub fn triangles_f64(&self) -> Vec<[Point3<f64>; 3]> {
        (0..self.len()).map(|i| self.triangle(i)).collect()
    }

    /// Axis-aligned bounding box `(min, max)` of the triangles (vertices not referenced by any
    /// triangle are not included).  For an empty mesh both corners are the origin.
    pub fn aabb(&self) -> (Point3<f64>, Point3<f64>) {
        let mut lo = Point3::new(f64::INFINITY, f64::INFINITY, f64::INFINITY);
        let mut hi = Point3::new(f64::NEG_INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
        for t in &self.triangles {
            for &v in t {
                let p = self.vertices[v as usize];
                for k in 0..3 {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
        }
        if self.triangles.is_empty() {
            (Point3::origin(), Point3::origin())
        } else {
            (lo, hi)
        }
    }

    /// Uniformly scaled and centred copy whose bounding box fits [-1,1]^3 (longest side = 2).
    ///
    /// The centre of [`Mesh::aabb`] moves to the origin and all coordinates are multiplied by
    /// `2 / longest side` (clamped to [-1,1] against rounding).  A mesh whose box has zero size
    /// is only translated.  Topology, vertex and triangle order are unchanged.  An error if a
    /// scaled coordinate leaves the oracle's range (a mesh spanning 1e60 with details of
    /// 1e-60 scales them to 1e-120).  Loaded meshes are in range, so the box and the scale are
    /// finite and non-zero.
    pub fn scaled_into_unit_cube(&self) -> Result<Mesh, MeshError> {
        let (lo, hi) = self.aabb();
        let centre = Point3::from((lo.coords + hi.coords) * 0.5);
        let side = (hi - lo).max();
        let scale = if side > 0.0 { 2.0 / side } else { 1.0 };
        let vertices: Vec<_> = self
            .vertices
            .iter()
            .map(|p| Point3::from(((p - centre) * scale).map(|c| c.clamp(-1.0, 1.0))))
            .collect();
        for (i, p) in vertices.iter().enumerate() {
            for c in p.iter() {
                check_coordinate(*c, format_args!("{c:e}")).map_err(|r| {
                    MeshError::new(
                        &self.name,
                        None,
                        format!("scaled into [-1,1]^3, vertex {i}: {r}"),
                    )
                })?;
            }
        }
        Ok(Mesh {
            name: self.name.clone(),
            vertices,
            triangles: self.triangles.clone(),
        })
    }
}

/// A mesh loading error: which file, which line (textual formats), and why.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshError {
    pub file: String,
    pub line: Option<usize>,
    pub reason: String,
}

impl MeshError {
    pub(crate) fn new(file: &str, line: Option<usize>, reason: impl Into<String>) -> MeshError {
        MeshError {
            file: file.to_string(),
            line,
            reason: reason.into(),
        }
    }
}

impl fmt::Display for MeshError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(line) => write!(f, "{}:{}: {}", self.file, line, self.reason),
            None => write!(f, "{}: {}", self.file, self.reason),
        }
    }
}

impl std::error::Error for MeshError {}

/// Loads a mesh file, choosing the parser by extension (`.obj`, `.stl`, `.ply`, any case).
pub fn load(path: &Path) -> Result<Mesh, MeshError> {
    // Read first: a missing file is reported as missing, whatever its name.
    let bytes = std::fs::read(path).map_err(|e| {
        MeshError::new(
            &path.display().to_string(),
            None,
            format!("cannot read file: {e}"),
        )
    })?;
    parse(path, &bytes)
}

/// A mesh from the `bytes` of the file at `path` (not read: its name picks the parser and
/// names it in errors), as [`load`] reads it; for the fuzzers, which hand over bytes.
pub fn parse(path: &Path, bytes: &[u8]) -> Result<Mesh, MeshError> {
    let file = path.display().to_string();
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    let parser: fn(&str, &[u8]) -> Result<Parsed, MeshError> = match ext.as_deref() {
        Some("obj") => obj::parse,
        Some("stl") => stl::parse,
        Some("ply") => ply::parse,
        Some(e) => {
            return Err(MeshError::new(
                &file,
                None,
                format!("unsupported extension '.{e}' (expected .obj, .stl or .ply)"),
            ))
        }
        None => {
            return Err(MeshError::new(
                &file,
                None,
                "no file extension (expected .obj, .stl or .ply)",
            ))
        }
    };
    let (vertices, triangles) = parser(&file, bytes)?;
    let name = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| file.clone());
    finish(&file, name, vertices, triangles)
}

/// The per-coordinate check of every parser: finite, and in the range the exact oracle is
/// exact for (`token` is the coordinate as the file writes it, written out only in an error:
/// formatting every coordinate was most of a large mesh's checks).
pub(crate) fn check_coordinate(c: f64, token: impl std::fmt::Display) -> Result<(), String> {
    if !c.is_finite() {
        Err(format!("NaN or infinite coordinate '{token}'"))
    } else if !crate::oracle::in_range(c) {
        Err(format!(
            "coordinate '{token}' is out of range ({}); rescale the model",
            crate::oracle::RANGE_TEXT
        ))
    } else {
        Ok(())
    }
}

/// Common final checks of every loader: at least one triangle, all indices in range, all
/// coordinates finite and in the oracle's range (the format parsers already report these with line numbers; this is the
/// safety net so that no loaded [`Mesh`] ever violates them).
fn finish(
    file: &str,
    name: String,
    vertices: Vec<Point3<f64>>,
    triangles: Vec<[u32; 3]>,
) -> Result<Mesh, MeshError> {
    if triangles.is_empty() {
        return Err(MeshError::new(file, None, "empty mesh: no triangles"));
    }
    for (i, p) in vertices.iter().enumerate() {
        for c in p.iter() {
            check_coordinate(*c, format_args!("{c:e}"))
                .map_err(|r| MeshError::new(file, None, format!("vertex {i}: {r}")))?;
        }
    }
    if let Some(i) = triangles
        .iter()
        .position(|t| t.iter().any(|&v| v as usize >= vertices.len()))
    {
        return Err(MeshError::new(
            file,
            None,
            format!("triangle {i}: vertex index out of range"),
        ));
    }
    Ok(Mesh {
        name,
        vertices,
        triangles,
    })
}

fn builtin_error(name: &str, reason: &str) -> MeshError {
    MeshError::new(
        name,
        None,
        format!(
            "{reason}; valid built-in meshes: {} (N = 1..={MAX_PROCEDURAL_TRIANGLES}); \
             a path to an existing .obj, .stl or .ply file is also accepted",
            BUILTIN_NAMES.join(", ")
        ),
    )
}

/// A built-in mesh by name: `bunny`, `teapot`, `dragon-11k`, `sphere:N`, `torus:N`, `soup:N`,
/// `soup:N:SEED` (see the module documentation).
pub fn builtin(name: &str) -> Result<Mesh, MeshError> {
    let embedded = match name {
        "bunny" => Some(BUNNY_OBJ),
        "teapot" => Some(TEAPOT_OBJ),
        "dragon-11k" => Some(DRAGON_11K_OBJ),
        _ => None,
    };
    if let Some(text) = embedded {
        let label = format!("vectors/meshes/{name}.obj");
        let (v, t) = obj::parse(&label, text.as_bytes())?;
        return finish(&label, name.to_string(), v, t);
    }
    let parts: Vec<&str> = name.split(':').collect();
    let count = |s: &str| -> Result<usize, MeshError> {
        match s.parse::<usize>() {
            Ok(n) if (1..=MAX_PROCEDURAL_TRIANGLES).contains(&n) => Ok(n),
            _ => Err(builtin_error(
                name,
                &format!(
                    "triangle count '{s}' is not an integer in 1..={MAX_PROCEDURAL_TRIANGLES}"
                ),
            )),
        }
    };
    let mut mesh = match parts.as_slice() {
        ["sphere", n] => sphere(count(n)?),
        ["torus", n] => torus(count(n)?),
        ["soup", n] => soup(count(n)?, 0),
        ["soup", n, seed] => {
            let seed = seed.parse::<u64>().map_err(|_| {
                builtin_error(
                    name,
                    &format!("seed '{seed}' is not an unsigned 64-bit integer"),
                )
            })?;
            soup(count(n)?, seed)
        }
        _ => return Err(builtin_error(name, "unknown built-in mesh")),
    };
    mesh.name = name.to_string();
    Ok(mesh)
}

/// True if `spec` is of a built-in family (`bunny`, `sphere:…`, …), valid or not.
pub fn is_builtin_name(spec: &str) -> bool {
    let family = spec.split(':').next();
    BUILTIN_NAMES.iter().any(|b| b.split(':').next() == family)
}

/// The meshes of specs `a` and `b` by `load`: B read only if its spec differs from A's (a
/// mesh against itself read once: parsing was most of a large file's setup).
pub fn pair<E>(
    a: &str,
    b: &str,
    load: impl Fn(&str) -> Result<Mesh, E>,
) -> Result<(Mesh, Mesh), E> {
    let ma = load(a)?;
    let mb = if b == a { ma.clone() } else { load(b)? };
    Ok((ma, mb))
}

/// A mesh spec from the CLI: an existing file path, or a built-in name.
///
/// An existing file always wins.  Otherwise the spec is tried as a built-in name; if it is not
/// one but looks like a path (has an extension or a path separator), the file error
/// ("cannot read file: …") is returned instead of the list of built-in names.
pub fn resolve(spec: &str) -> Result<Mesh, MeshError> {
    let path = Path::new(spec);
    if path.exists() {
        return load(path);
    }
    match builtin(spec) {
        Ok(m) => Ok(m),
        Err(e) => {
            let looks_like_path = spec.contains('/')
                || spec.contains(std::path::MAIN_SEPARATOR)
                || (path.extension().is_some() && !spec.contains(':'));
            if looks_like_path {
                load(path)
            } else {
                Err(e)
            }
        }
    }
}
