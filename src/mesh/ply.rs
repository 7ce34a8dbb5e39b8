//! PLY (ASCII, binary little/big endian) via ply-rs.
//!
//! The header is located and sanity-checked first (ply-rs panics on header numbers that do not
//! fit 64 bits), then parsed by ply-rs.  The payload is fed to ply-rs one element at a time
//! (`read_ascii_element` per line, `read_*_endian_element` per binary record) so that every error
//! can name its line (ASCII: header lines + element position) or its element (binary), and so
//! that a binary payload shorter than the header demands is reported as truncated before
//! reading.  Data after the declared elements is an error (the header's counts would silently
//! drop it).  ASCII `float` properties are read as `f64`: the file writes decimals, and the
//! nearest `f64` is what it states; binary `float` values are `f32` by definition.

use super::{check_coordinate, MeshError, Parsed};
use nalgebra::Point3;
use ply_rs::parser::Parser;
use ply_rs::ply::{ElementDef, Encoding, Property, PropertyAccess, PropertyType, ScalarType};
use std::io::Cursor;

fn scalar_size(t: &ScalarType) -> u128 {
    match t {
        ScalarType::Char | ScalarType::UChar => 1,
        ScalarType::Short | ScalarType::UShort => 2,
        ScalarType::Int | ScalarType::UInt | ScalarType::Float => 4,
        ScalarType::Double => 8,
    }
}

fn scalar_f64(p: &Property) -> Option<f64> {
    Some(match *p {
        Property::Char(v) => v as f64,
        Property::UChar(v) => v as f64,
        Property::Short(v) => v as f64,
        Property::UShort(v) => v as f64,
        Property::Int(v) => v as f64,
        Property::UInt(v) => v as f64,
        Property::Float(v) => v as f64,
        Property::Double(v) => v,
        _ => return None,
    })
}

fn int_list(p: &Property) -> Option<Vec<i64>> {
    Some(match p {
        Property::ListChar(v) => v.iter().map(|&x| x as i64).collect(),
        Property::ListUChar(v) => v.iter().map(|&x| x as i64).collect(),
        Property::ListShort(v) => v.iter().map(|&x| x as i64).collect(),
        Property::ListUShort(v) => v.iter().map(|&x| x as i64).collect(),
        Property::ListInt(v) => v.iter().map(|&x| x as i64).collect(),
        Property::ListUInt(v) => v.iter().map(|&x| x as i64).collect(),
        _ => return None,
    })
}

/// `def` with its `float` scalars read as `double` (for ASCII data, see the module doc).
fn decimals_as_f64(def: &ElementDef) -> ElementDef {
    let mut d = def.clone();
    for (_, p) in d.properties.iter_mut() {
        if p.data_type == PropertyType::Scalar(ScalarType::Float) {
            p.data_type = PropertyType::Scalar(ScalarType::Double);
        }
    }
    d
}

/// One-line version of a ply-rs message, with its "Line N: " prefix split off.
fn split_msg(msg: &str) -> (Option<usize>, String) {
    let flat = msg.split_whitespace().collect::<Vec<_>>().join(" ");
    if let Some(rest) = flat.strip_prefix("Line ") {
        if let Some((n, text)) = rest.split_once(": ") {
            if let Ok(n) = n.parse::<usize>() {
                return (Some(n), text.to_string());
            }
        }
    }
    (None, flat)
}

/// What the loader reads of an element, as ply-rs sets it (`PropertyAccess`): a vertex's
/// x, y, z, a face's `vertex_indices` or `vertex_index`, the last of each name; any other
/// property dropped. (ply-rs's own element, a hashed map of every property, was a third of
/// reading a large ASCII PLY.)
#[derive(Default)]
struct Item {
    xyz: [Option<Property>; 3],
    indices: Option<Property>,
    index: Option<Property>,
}

impl PropertyAccess for Item {
    fn new() -> Self {
        Item::default()
    }

    fn set_property(&mut self, name: String, p: Property) {
        let slot = match name.as_str() {
            "x" => &mut self.xyz[0],
            "y" => &mut self.xyz[1],
            "z" => &mut self.xyz[2],
            "vertex_indices" => &mut self.indices,
            "vertex_index" => &mut self.index,
            _ => return,
        };
        *slot = Some(p);
    }
}

/// Accumulates vertices and fan-triangulated faces from parsed elements.
struct Builder<'a> {
    file: &'a str,
    n_vertices: u64,
    vertices: Vec<Point3<f64>>,
    triangles: Vec<[u32; 3]>,
}

impl Builder<'_> {
    /// Element `j` of `name`; `line` is the ASCII line number. (An error names the element
    /// "{name} {j}", written only then: formatting it for every element was a tenth of
    /// loading a large ASCII PLY.)
    fn take(
        &mut self,
        name: &str,
        j: usize,
        e: &Item,
        line: Option<usize>,
    ) -> Result<(), MeshError> {
        let what = format_args!("{name} {j}");
        let err = |reason: String| MeshError::new(self.file, line, reason);
        match name {
            "vertex" => {
                let mut xyz = [0.0; 3];
                for (k, axis) in ["x", "y", "z"].iter().enumerate() {
                    let p = e.xyz[k]
                        .as_ref()
                        .ok_or_else(|| err(format!("{what}: vertex has no property '{axis}'")))?;
                    xyz[k] = scalar_f64(p)
                        .ok_or_else(|| err(format!("{what}: property '{axis}' is a list")))?;
                    check_coordinate(xyz[k], format_args!("{axis} = {:e}", xyz[k]))
                        .map_err(|r| err(format!("{what}: {r}")))?;
                }
                self.vertices.push(Point3::from(xyz));
            }
            "face" => {
                let p = e.indices.as_ref().or(e.index.as_ref()).ok_or_else(|| {
                    err(format!(
                        "{what}: face has no list property 'vertex_indices'"
                    ))
                })?;
                let idx = int_list(p).ok_or_else(|| {
                    err(format!(
                        "{what}: 'vertex_indices' is not a list of integers"
                    ))
                })?;
                if idx.len() < 3 {
                    return Err(err(format!(
                        "{what}: face with {} vertices (at least 3 needed)",
                        idx.len()
                    )));
                }
                let mut v = Vec::with_capacity(idx.len());
                for &i in &idx {
                    if i < 0 || i as u64 >= self.n_vertices || i > u32::MAX as i64 {
                        return Err(err(format!(
                            "{what}: vertex index {i} out of range (the file has {} vertices)",
                            self.n_vertices
                        )));
                    }
                    v.push(i as u32);
                }
                for k in 1..v.len() - 1 {
                    self.triangles.push([v[0], v[k], v[k + 1]]);
                }
            }
            _ => {}
        }
        Ok(())
    }
}

/// "header declares 3 'vertex' and 1 'face' elements".
fn declared(elements: &[(&String, &ElementDef)]) -> String {
    let counts: Vec<String> = elements
        .iter()
        .map(|(n, d)| format!("{} '{n}'", d.count))
        .collect();
    format!("header declares {} elements", counts.join(" and "))
}

/// [`MeshError::new`] for `file`.
fn errors_in(file: &str) -> impl Fn(Option<usize>, String) -> MeshError + '_ {
    move |line, reason| MeshError::new(file, line, reason)
}

pub(super) fn parse(file: &str, bytes: &[u8]) -> Result<Parsed, MeshError> {
    let err = errors_in(file);
    let (offset, header_lines) = header_end(file, bytes)?;
    let parser = Parser::<Item>::new();
    let header = parser.read_header(&mut &bytes[..offset]).map_err(|e| {
        let (line, msg) = split_msg(&e.to_string());
        // Drop the parser generator's long "expected one of …" set.
        let msg = msg.split(" Error: ParseError").next().unwrap_or_default();
        err(line, format!("PLY header: {msg}"))
    })?;
    let payload = &bytes[offset..];
    let n_vertices = header.elements.get("vertex").map_or(0, |e| e.count as u64);
    let mut b = Builder {
        file,
        n_vertices,
        vertices: Vec::new(),
        triangles: Vec::new(),
    };
    let elements: Vec<(&String, &ElementDef)> = header.elements.iter().collect();
    match header.encoding {
        Encoding::Ascii => b.read_ascii(&parser, payload, header_lines, &elements)?,
        Encoding::BinaryLittleEndian => b.read_binary(&parser, payload, true, &elements)?,
        Encoding::BinaryBigEndian => b.read_binary(&parser, payload, false, &elements)?,
    }
    Ok((b.vertices, b.triangles))
}

/// The header's end: its bytes and lines. Checks first the numbers ply-rs would `unwrap`.
fn header_end(file: &str, bytes: &[u8]) -> Result<(usize, usize), MeshError> {
    let err = errors_in(file);
    let mut offset = 0;
    let mut header_lines = 0;
    let mut found = false;
    while offset < bytes.len() {
        let end = bytes[offset..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(bytes.len(), |p| offset + p + 1);
        let line = &bytes[offset..end];
        header_lines += 1;
        offset = end;
        if line.starts_with(b"element") || line.starts_with(b"format") {
            let too_big = line.split(|b| !b.is_ascii_digit()).any(|run| {
                !run.is_empty()
                    && std::str::from_utf8(run).map_or(true, |s| s.parse::<u64>().is_err())
            });
            if too_big {
                return Err(err(
                    Some(header_lines),
                    "number too large in PLY header".into(),
                ));
            }
        }
        if line.trim_ascii() == b"end_header" {
            found = true;
            break;
        }
    }
    if !found {
        return Err(err(
            Some(header_lines.max(1)),
            "no 'end_header' line: not a PLY file or truncated header".into(),
        ));
    }
    Ok((offset, header_lines))
}

impl Builder<'_> {
    /// The elements of an ASCII payload, one a line after the header's `header_lines`.
    fn read_ascii(
        &mut self,
        parser: &Parser<Item>,
        payload: &[u8],
        header_lines: usize,
        elements: &[(&String, &ElementDef)],
    ) -> Result<(), MeshError> {
        let file = self.file;
        let err = errors_in(file);
        let mut lines = payload.split(|&b| b == b'\n');
        let mut lineno = header_lines;
        for &(name, def) in elements {
            let def = &decimals_as_f64(def);
            for j in 0..def.count {
                lineno += 1;
                let raw = match lines.next() {
                    Some(l) if !(l.is_empty() && lines.clone().next().is_none()) => l,
                    _ => {
                        return Err(err(
                            Some(lineno),
                            format!(
                                "truncated ASCII PLY: file ends after {j} of {} '{name}' elements",
                                def.count
                            ),
                        ))
                    }
                };
                let text = std::str::from_utf8(raw)
                    .map_err(|_| err(Some(lineno), "invalid UTF-8".into()))?;
                let text = text.strip_suffix('\r').unwrap_or(text);
                let e = parser.read_ascii_element(text, def).map_err(|e| {
                    let non_finite = text
                        .split_whitespace()
                        .find(|s| s.parse::<f64>().is_ok_and(|f| !f.is_finite()));
                    match non_finite {
                        Some(s) => err(Some(lineno), format!("NaN or infinite value '{s}'")),
                        None => err(
                            Some(lineno),
                            format!("{name} {j}: {}", split_msg(&e.to_string()).1),
                        ),
                    }
                })?;
                self.take(name, j, &e, Some(lineno))?;
            }
        }
        if let Some(k) = lines.position(|l| !l.trim_ascii().is_empty()) {
            return Err(err(
                Some(lineno + k + 1),
                format!(
                    "data after the {}; correct the counts in the header",
                    declared(elements)
                ),
            ));
        }
        Ok(())
    }

    /// The elements of a binary payload (`little` or big endian).
    fn read_binary(
        &mut self,
        parser: &Parser<Item>,
        payload: &[u8],
        little: bool,
        elements: &[(&String, &ElementDef)],
    ) -> Result<(), MeshError> {
        let file = self.file;
        let err = errors_in(file);
        let mut need: u128 = 0;
        for (_, def) in elements {
            let size: u128 = def
                .properties
                .iter()
                .map(|(_, p)| match &p.data_type {
                    PropertyType::Scalar(t) => scalar_size(t),
                    PropertyType::List(t, _) => scalar_size(t),
                })
                .sum();
            need = need.saturating_add(size.saturating_mul(def.count as u128));
        }
        if need > payload.len() as u128 {
            return Err(err(
                None,
                format!(
                    "truncated binary PLY: {} (at least {need} bytes) but only {} bytes \
                     follow the header",
                    declared(elements),
                    payload.len()
                ),
            ));
        }
        let mut cursor = Cursor::new(payload);
        for &(name, def) in elements {
            if def.properties.is_empty() {
                continue; // occupies no bytes
            }
            for j in 0..def.count {
                let r = if little {
                    parser.read_little_endian_element(&mut cursor, def)
                } else {
                    parser.read_big_endian_element(&mut cursor, def)
                };
                let e = r.map_err(|e| {
                    let left = payload.len().saturating_sub(cursor.position() as usize);
                    if e.kind() == std::io::ErrorKind::UnexpectedEof
                        || left < 8
                        || e.to_string().contains("Couldn't find a list element")
                    {
                        err(
                            None,
                            format!("truncated binary PLY: file ends inside {name} {j}"),
                        )
                    } else {
                        err(None, format!("{name} {j}: {}", split_msg(&e.to_string()).1))
                    }
                })?;
                self.take(name, j, &e, None)?;
            }
        }
        let left = payload.len() as u64 - cursor.position();
        if left > 0 {
            return Err(err(
                None,
                format!(
                    "{left} bytes after the {}; correct the counts in the header",
                    declared(elements)
                ),
            ));
        }
        Ok(())
    }
}
