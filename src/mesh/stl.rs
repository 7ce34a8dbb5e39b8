//! STL (ASCII and binary) via stl_io.
//!
//! Binary vs ASCII: a file whose size is exactly `84 + 50·n` (n = the little-endian triangle
//! count at byte 80) is binary, even if it starts with `solid`; otherwise a file starting with
//! `solid` is ASCII, anything else binary.  Bytes after the declared binary triangles are
//! ignored.  For ASCII files the failing line is located after the fact: stl_io reports how many
//! facets it read, and the 7-line facet it stopped in is checked line by line.

use super::{MeshError, Parsed};
use nalgebra::Point3;
use std::borrow::Cow;
use std::io::Cursor;

pub(super) fn parse(file: &str, bytes: &[u8]) -> Result<Parsed, MeshError> {
    let len = bytes.len() as u64;
    let declared = bytes
        .get(80..84)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as u64);
    let exact_binary = declared.is_some_and(|n| 84 + 50 * n == len);
    if !exact_binary && bytes.starts_with(b"solid") {
        return ascii(file, bytes);
    }
    let Some(n) = declared else {
        return Err(MeshError::new(
            file,
            None,
            format!("truncated binary STL: {len} bytes, shorter than the 84-byte header"),
        ));
    };
    let need = 84 + 50 * n;
    if len < need {
        return Err(MeshError::new(
            file,
            None,
            format!(
                "truncated binary STL: header declares {n} triangles ({need} bytes) \
                 but the file has only {len} bytes"
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

fn ascii(file: &str, bytes: &[u8]) -> Result<Parsed, MeshError> {
    // stl_io wants the first line to start with "solid " (with a space); accept a bare "solid".
    let data: Cow<[u8]> = if bytes.starts_with(b"solid ") {
        Cow::Borrowed(bytes)
    } else {
        let mut v = b"solid ".to_vec();
        v.extend_from_slice(&bytes[5..]);
        Cow::Owned(v)
    };
    match stl_io::read_stl(&mut Cursor::new(&data[..])) {
        Ok(mesh) => convert(file, mesh),
        Err(e) => {
            let mut cursor = Cursor::new(&data[..]);
            let facets_ok = match stl_io::create_stl_reader(&mut cursor) {
                Ok(reader) => reader.take_while(|t| t.is_ok()).count(),
                Err(_) => 0,
            };
            let (line, why) = locate(bytes, facets_ok);
            let reason = match why {
                Some(why) => format!("ASCII STL, facet {}: {why}", facets_ok + 1),
                None => format!("ASCII STL, facet {}: {e}", facets_ok + 1),
            };
            Err(MeshError::new(file, Some(line), reason))
        }
    }
}

/// Finds the line of the first error in facet `k` (0-based) of an ASCII STL file, mirroring
/// stl_io's reader: the first line is the `solid` line, blank lines are skipped, and a facet is
/// 7 non-blank lines.  Returns the 1-based line and, when clearer than stl_io's message, a reason.
fn locate(bytes: &[u8], k: usize) -> (usize, Option<String>) {
    let lines = bytes.split(|&b| b == b'\n').enumerate().skip(1);
    let mut last = 1;
    let mut seen = 0usize;
    let start = 7 * k;
    let is_float = |s: &str| s.parse::<f32>().is_ok_and(|f| f.is_finite());
    let non_finite = |s: &str| s.parse::<f32>().is_ok_and(|f| !f.is_finite());
    for (i, raw) in lines {
        last = i + 1;
        let Ok(text) = std::str::from_utf8(raw) else {
            return (i + 1, Some("invalid UTF-8".to_string()));
        };
        let t: Vec<&str> = text.split_whitespace().collect();
        if t.is_empty() {
            continue;
        }
        seen += 1;
        if seen <= start {
            continue;
        }
        let pos = seen - start - 1; // position within the facet, 0..7
        if t[0] == "endsolid" && pos == 0 {
            return (i + 1, None);
        }
        let ok = match pos {
            0 => {
                t.len() == 5
                    && t[0] == "facet"
                    && t[1] == "normal"
                    && t[2..].iter().all(|s| is_float(s))
            }
            1 => t == ["outer", "loop"],
            2..=4 => t.len() == 4 && t[0] == "vertex" && t[1..].iter().all(|s| is_float(s)),
            5 => t == ["endloop"],
            _ => t == ["endfacet"],
        };
        if !ok {
            let why = t
                .iter()
                .find(|s| non_finite(s))
                .map(|s| format!("NaN or infinite coordinate '{s}'"));
            return (i + 1, why);
        }
        if pos == 6 {
            return (i + 1, None);
        }
    }
    (
        last,
        Some("unexpected end of file (truncated?)".to_string()),
    )
}
