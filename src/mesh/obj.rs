//! Wavefront OBJ via tobj, behind a line-numbering validation pass.
//!
//! The validation pass walks the text once, reports bad `v`/`f` lines with their line number and
//! hands tobj a same-length copy of the text (line numbers stay valid) that keeps only what the
//! mesh needs: `v x y z [w]` (colours dropped), `f` with position references only, `o`/`g`.
//! Everything else (`vt`, `vn`, `l`, `p`, `mtllib`, `usemtl`, `s`, comments, unknown keywords)
//! becomes an empty line.  tobj then does the parsing, the relative-index resolution and the
//! fan triangulation (`triangulate: true`).  Coordinates are parsed as `f64` (tobj's `use_f64`
//! feature), so the decimal the file states is rounded once, to the nearest `f64`.

use super::{check_coordinate, MeshError, Parsed};
use nalgebra::Point3;

pub(super) fn parse(file: &str, bytes: &[u8]) -> Result<Parsed, MeshError> {
    let err = |line: usize, reason: String| MeshError::new(file, Some(line), reason);
    let text = std::str::from_utf8(bytes).map_err(|e| {
        let line = bytes[..e.valid_up_to()]
            .iter()
            .filter(|&&b| b == b'\n')
            .count()
            + 1;
        err(line, "invalid UTF-8".to_string())
    })?;
    // A byte-order mark would glue itself to the first keyword and hide that line from tobj.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);

    let mut clean = String::with_capacity(text.len());
    let mut n_vertices: usize = 0;
    for (i, line) in text.lines().enumerate() {
        let lineno = i + 1;
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                let t: Vec<&str> = words.collect();
                if t.len() < 3 {
                    return Err(err(
                        lineno,
                        format!("vertex needs 3 coordinates, found {}", t.len()),
                    ));
                }
                let mut xyz = [0f64; 3];
                for k in 0..3 {
                    xyz[k] = t[k].parse::<f64>().map_err(|_| {
                        err(lineno, format!("invalid vertex coordinate '{}'", t[k]))
                    })?;
                    check_coordinate(xyz[k], t[k]).map_err(|r| err(lineno, r))?;
                }
                clean.push_str("v ");
                clean.push_str(&t[..3].join(" "));
                if t.len() == 4 {
                    // `v x y z w`: tobj divides by w.
                    let w = t[3]
                        .parse::<f64>()
                        .map_err(|_| err(lineno, format!("invalid vertex weight '{}'", t[3])))?;
                    if w == 0.0 || !w.is_finite() {
                        return Err(err(
                            lineno,
                            format!("vertex weight w = {} is 0 or not finite", t[3]),
                        ));
                    }
                    for c in xyz {
                        check_coordinate(c / w, format_args!("{c} / {w}"))
                            .map_err(|r| err(lineno, r))?;
                    }
                    clean.push(' ');
                    clean.push_str(t[3]);
                }
                n_vertices += 1;
            }
            Some("f") => {
                let t: Vec<&str> = words.collect();
                if t.len() < 3 {
                    return Err(err(
                        lineno,
                        format!("face with {} vertices (at least 3 needed)", t.len()),
                    ));
                }
                clean.push('f');
                for tok in t {
                    let parts: Vec<&str> = tok.split('/').collect();
                    if parts.len() > 3
                        || parts
                            .iter()
                            .enumerate()
                            .any(|(k, p)| (k == 0 || !p.is_empty()) && p.parse::<isize>().is_err())
                    {
                        return Err(err(lineno, format!("invalid face vertex '{tok}'")));
                    }
                    let idx: isize = parts[0].parse().unwrap_or(0);
                    // OBJ references are to vertices defined earlier: 1..=n, or -n..=-1.
                    let ok = (idx > 0 && idx as usize <= n_vertices)
                        || (idx < 0 && idx.unsigned_abs() <= n_vertices);
                    if !ok {
                        return Err(err(
                            lineno,
                            format!(
                                "vertex index {idx} out of range ({n_vertices} vertices defined \
                                 so far; OBJ indices are 1-based, negative ones relative)"
                            ),
                        ));
                    }
                    clean.push(' ');
                    clean.push_str(parts[0]);
                }
            }
            Some("o") | Some("g") => clean.push_str(line),
            _ => {}
        }
        clean.push('\n');
    }

    // `..Default::default()` keeps this compiling if tobj's `merging`/`reordering` features
    // get enabled by feature unification.
    #[allow(clippy::needless_update)]
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: false,
        ignore_points: true,
        ignore_lines: true,
        ..Default::default()
    };
    let (models, _) = tobj::load_obj_buf(&mut clean.as_bytes(), &options, |_| {
        Err(tobj::LoadError::OpenFileFailed)
    })
    .map_err(|e| MeshError::new(file, None, format!("OBJ parse error (tobj): {e}")))?;

    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    for model in models {
        let m = model.mesh;
        let base = u32::try_from(vertices.len())
            .map_err(|_| MeshError::new(file, None, "more than 2^32 vertices"))?;
        vertices.extend(
            m.positions
                .chunks_exact(3)
                .map(|p| Point3::new(p[0], p[1], p[2])),
        );
        for t in m.indices.chunks_exact(3) {
            let mut tri = [0u32; 3];
            for k in 0..3 {
                tri[k] = base
                    .checked_add(t[k])
                    .ok_or_else(|| MeshError::new(file, None, "more than 2^32 vertices"))?;
            }
            triangles.push(tri);
        }
    }
    Ok((vertices, triangles))
}
