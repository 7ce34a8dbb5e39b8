//! STL: binary via stl_io; ASCII parsed here, because stl_io reads ASCII numbers as `f32`
//! while the decimals an ASCII file writes are read as the nearest `f64`.
//!
//! Binary vs ASCII: a file whose size is exactly `84 + 50·n` (n = the little-endian triangle
//! count at byte 80) is binary, even if it starts with `solid`.  Otherwise it is ASCII if it
//! starts (after an optional UTF-8 byte-order mark) with `solid` in any case and its first
//! bytes are text; anything else is binary.  Bytes after the declared binary triangles are
//! ignored.  Binary coordinates are `f32` by definition and are widened exactly.

use super::{check_coordinate, MeshError, Parsed};
use nalgebra::Point3;
use std::borrow::Cow;
use std::collections::HashMap;
use std::io::Cursor;

/// Bytes that never occur in an ASCII STL but in almost every binary one (zero bytes of small
/// counts and floats), looked for in the first 512 bytes.
fn looks_textual(bytes: &[u8]) -> bool {
    let head = &bytes[..bytes.len().min(512)];
    let body = head.strip_prefix("\u{feff}".as_bytes()).unwrap_or(head);
    body.len() >= 5
        && body[..5].eq_ignore_ascii_case(b"solid")
        && head
            .iter()
            .all(|&b| b >= 0x20 || b"\t\n\r\x0c".contains(&b))
}

pub(super) fn parse(file: &str, bytes: &[u8]) -> Result<Parsed, MeshError> {
    let len = bytes.len() as u64;
    let declared = bytes
        .get(80..84)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as u64);
    let exact_binary = declared.is_some_and(|n| 84 + 50 * n == len);
    if !exact_binary && looks_textual(bytes) {
        return ascii(file, bytes);
    }
    // Named in the binary errors, because such a file may have been meant as ASCII.
    let note = if bytes
        .get(..5)
        .is_some_and(|b| b.eq_ignore_ascii_case(b"solid"))
    {
        " (read as binary: it starts with 'solid' but contains non-text bytes)"
    } else {
        ""
    };
    let Some(n) = declared else {
        return Err(MeshError::new(
            file,
            None,
            format!("truncated binary STL: {len} bytes, shorter than the 84-byte header{note}"),
        ));
    };
    let need = 84 + 50 * n;
    if len < need {
        return Err(MeshError::new(
            file,
            None,
            format!(
                "truncated binary STL: header declares {n} triangles ({need} bytes) \
                 but the file has only {len} bytes{note}"
            ),
        ));
    }
    let need = need as usize;
    // stl_io sniffs "solid " to pick its ASCII reader; binary headers may start with it too.
    let data: Cow<[u8]> = if bytes.starts_with(b"solid ") {
        let mut v = bytes[..need].to_vec();
        v[0] = b'S';
        Cow::Owned(v)
    } else {
        Cow::Borrowed(&bytes[..need])
    };
    let mesh = stl_io::read_stl(&mut Cursor::new(&data[..]))
        .map_err(|e| MeshError::new(file, None, format!("binary STL: {e}")))?;
    for (i, f) in mesh.faces.iter().enumerate() {
        if f.vertices
            .iter()
            .any(|&v| mesh.vertices[v].0.iter().any(|c| !c.is_finite()))
        {
            return Err(MeshError::new(
                file,
                None,
                format!("binary STL triangle {i} has a NaN or infinite coordinate"),
            ));
        }
    }
    convert(file, mesh)
}

fn convert(file: &str, mesh: stl_io::IndexedMesh) -> Result<Parsed, MeshError> {
    let vertices = mesh
        .vertices
        .iter()
        .map(|v| Point3::new(v[0] as f64, v[1] as f64, v[2] as f64))
        .collect();
    let mut triangles = Vec::with_capacity(mesh.faces.len());
    for f in &mesh.faces {
        let mut t = [0u32; 3];
        for (dst, &src) in t.iter_mut().zip(&f.vertices) {
            *dst = u32::try_from(src)
                .map_err(|_| MeshError::new(file, None, "more than 2^32 vertices"))?;
        }
        triangles.push(t);
    }
    Ok((vertices, triangles))
}

/// ASCII STL: `solid`, then facets of 7 non-blank lines (`facet normal nx ny nz`,
/// `outer loop`, three `vertex x y z`, `endloop`, `endfacet`), then `endsolid`; keywords in
/// any case; further `solid … endsolid` blocks may follow.  Vertices are de-duplicated by
/// exact value in order of first use, as stl_io does for binary files.
fn ascii(file: &str, bytes: &[u8]) -> Result<Parsed, MeshError> {
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    let mut index: HashMap<[u64; 3], u32> = HashMap::new();
    let mut facet = 0usize;
    let mut pos = None::<usize>; // line within the current facet; None = between facets
    let mut in_solid = false;
    let mut corners = [0u32; 3];
    let bytes = bytes.strip_prefix("\u{feff}".as_bytes()).unwrap_or(bytes);
    let mut last = 1;
    for (i, raw) in bytes.split(|&b| b == b'\n').enumerate() {
        let lineno = i + 1;
        last = lineno;
        let err = |why: String| {
            MeshError::new(
                file,
                Some(lineno),
                format!("ASCII STL, facet {}: {why}", facet + 1),
            )
        };
        let text = std::str::from_utf8(raw)
            .map_err(|_| MeshError::new(file, Some(lineno), "invalid UTF-8"))?;
        let t: Vec<&str> = text.split_whitespace().collect();
        let Some(key) = t.first().map(|k| k.to_ascii_lowercase()) else {
            continue;
        };
        let expected = match pos {
            None if !in_solid => "solid",
            None if key == "endsolid" => {
                in_solid = false;
                continue;
            }
            None => "facet normal nx ny nz",
            Some(0) => "outer loop",
            Some(1..=3) => "vertex x y z",
            Some(4) => "endloop",
            Some(_) => "endfacet",
        };
        let words = |n: usize, second: Option<&str>| {
            t.len() == n && second.is_none_or(|w| t[1].eq_ignore_ascii_case(w))
        };
        let ok = match expected {
            "solid" => key == "solid",
            "facet normal nx ny nz" => {
                key == "facet"
                    && words(5, Some("normal"))
                    && t[2..].iter().all(|s| s.parse::<f64>().is_ok())
            }
            "outer loop" => key == "outer" && words(2, Some("loop")),
            "vertex x y z" => key == "vertex" && words(4, None),
            "endloop" => key == "endloop" && t.len() == 1,
            _ => key == "endfacet" && t.len() == 1,
        };
        if !ok {
            return Err(err(format!(
                "expected '{expected}', found '{}'",
                t.join(" ")
            )));
        }
        match pos {
            None if expected == "solid" => in_solid = true,
            None => pos = Some(0),
            Some(p @ 1..=3) => {
                let mut xyz = [0.0; 3];
                for k in 0..3 {
                    xyz[k] = t[k + 1]
                        .parse::<f64>()
                        .map_err(|_| err(format!("invalid vertex coordinate '{}'", t[k + 1])))?;
                    check_coordinate(xyz[k], t[k + 1]).map_err(err)?;
                }
                let next = u32::try_from(vertices.len())
                    .map_err(|_| MeshError::new(file, None, "more than 2^32 vertices"))?;
                corners[p - 1] = *index.entry(xyz.map(f64::to_bits)).or_insert_with(|| {
                    vertices.push(Point3::from(xyz));
                    next
                });
                pos = Some(p + 1);
            }
            Some(5) => {
                triangles.push(corners);
                facet += 1;
                pos = None;
            }
            Some(p) => pos = Some(p + 1),
        }
    }
    if pos.is_some() || in_solid {
        return Err(MeshError::new(
            file,
            Some(last),
            format!(
                "ASCII STL, facet {}: unexpected end of file (truncated? no 'endsolid')",
                facet + 1
            ),
        ));
    }
    Ok((vertices, triangles))
}
