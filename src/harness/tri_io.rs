//! T.CHECK's operands and results as the RTL sees them (bit patterns of the format), built
//! from the golden memory words and host setup, with the golden results they must give:
//! one source for the testbenches (`tb/rtl_tcheck.rs`) and the exported vectors.

use crate::dop::host::{Affine, HostSetup};
use crate::format::{Format, Rounding};
use crate::golden::tcheck::{self, Trace};
use crate::memory::TriWord;

/// The inputs of one T.CHECK: the leaf whose unit triangle is the target (`m` = its M_B,
/// row-major 3x4, with `e_lin`, `e_tr`, `l_norm`), the frame map into that leaf's object
/// (`f`, row-major, with bounds `f_lin`, `f_tr`), the vertices `v[k][c]` of the other
/// triangle, and the vertex gap (`gap_en`, `eta`) of the direction A vs U(B).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TCheckIn {
    pub m: [u64; 12],
    pub e_lin: u64,
    pub e_tr: u64,
    pub l_norm: u64,
    pub f: [u64; 12],
    pub f_lin: u64,
    pub f_tr: u64,
    pub eta: u64,
    pub gap_en: bool,
    pub v: [[u64; 3]; 3],
    pub v_exact: bool,
}

/// The outputs of one T.CHECK: per edge s = (a + b) - r_z and its bound, surely crosses,
/// surely misses; over the edges `hit` (some edge surely crosses) and `miss` (every edge
/// surely misses); neither: unknown.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TCheckOut {
    pub s_x: [u64; 3],
    pub s_e: [u64; 3],
    pub cross_t: [bool; 3],
    pub cross_f: [bool; 3],
    pub hit: bool,
    pub miss: bool,
}

fn words(f: Format, m: &Affine) -> [u64; 12] {
    std::array::from_fn(|i| f.to_bits(m[i / 4][i % 4]))
}

/// One direction of TRI_UNIT: the edges of `tri` against the unit triangle of `leaf`,
/// `frame` (with bounds `frame_err`) mapping `tri`'s object into `leaf`'s; `eta` for the
/// direction A vs U(B). Returns the RTL inputs and the golden outputs (golden
/// [`tcheck::stage1`] then [`tcheck::edges`]).
pub fn direction(
    f: Format,
    r: Rounding,
    leaf: &TriWord,
    frame: &Affine,
    frame_err: [f64; 2],
    tri: &TriWord,
    eta: Option<f64>,
) -> (TCheckIn, TCheckOut) {
    let input = TCheckIn {
        m: words(f, &leaf.m),
        e_lin: f.to_bits(leaf.e_lin),
        e_tr: f.to_bits(leaf.e_tr),
        l_norm: f.to_bits(leaf.l_norm),
        f: words(f, frame),
        f_lin: f.to_bits(frame_err[0]),
        f_tr: f.to_bits(frame_err[1]),
        eta: f.to_bits(eta.unwrap_or(0.0)),
        gap_en: eta.is_some(),
        v: tri.v.map(|p| p.map(|x| f.to_bits(x))),
        v_exact: tri.v_exact,
    };
    let trace = tcheck::edges(f, r, &tcheck::stage1(f, r, leaf, frame, frame_err), tri, eta.map(|e| (leaf, e)));
    (input, output(f, &trace))
}

fn output(f: Format, t: &Trace) -> TCheckOut {
    let res = t.result();
    TCheckOut {
        s_x: t.s.map(|v| f.to_bits(v.x)),
        s_e: t.s.map(|v| f.to_bits(v.e)),
        cross_t: t.crossing.map(|c| c == Some(true)),
        cross_f: t.crossing.map(|c| c == Some(false)),
        hit: res == Some(true),
        miss: res == Some(false),
    }
}

/// Both directions of TRI_UNIT for triangle `a` of A against `b` of B under `setup`:
/// A's edges against U(B) (with the vertex gap), then B's edges against U(A).
pub fn tri_unit_directions(f: Format, r: Rounding, a: &TriWord, b: &TriWord, setup: &HostSetup) -> [(TCheckIn, TCheckOut); 2] {
    [
        direction(f, r, b, &setup.m_ab, setup.e_ab, a, Some(setup.eta)),
        direction(f, r, a, &setup.m_ba, setup.e_ba, b, None),
    ]
}

/// TRI_UNIT's per-query write port: `(load_addr, load_data)` for M_AB (address 4 i + c),
/// its bounds (12, 13), M_BA (16 + 4 i + c), its bounds (28, 29) and eta (30).
pub fn tri_unit_setup_words(f: Format, setup: &HostSetup) -> Vec<(u64, u64)> {
    let mut out = vec![];
    for (base, m, e) in [(0u64, &setup.m_ab, setup.e_ab), (16, &setup.m_ba, setup.e_ba)] {
        for (i, w) in words(f, m).into_iter().enumerate() {
            out.push((base + i as u64, w));
        }
        out.push((base + 12, f.to_bits(e[0])));
        out.push((base + 13, f.to_bits(e[1])));
    }
    out.push((30, f.to_bits(setup.eta)));
    out
}

/// One leaf's triangle word on TRI_UNIT's `a_*` / `b_*` ports.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LeafIn {
    pub m: [u64; 12],
    pub e_lin: u64,
    pub e_tr: u64,
    pub l_norm: u64,
    pub v: [[u64; 3]; 3],
    pub v_exact: bool,
    pub degenerate: bool,
}

impl LeafIn {
    pub fn of(f: Format, w: &TriWord) -> LeafIn {
        LeafIn {
            m: words(f, &w.m),
            e_lin: f.to_bits(w.e_lin),
            e_tr: f.to_bits(w.e_tr),
            l_norm: f.to_bits(w.l_norm),
            v: w.v.map(|p| p.map(|x| f.to_bits(x))),
            v_exact: w.v_exact,
            degenerate: w.degenerate,
        }
    }
}

// ---------------------------------------------------------------------------------------
// Vector files (scripts/README.md): `cchip vectors` writes them, Icarus and Verilator run
// the exported T.CHECK and TRI_UNIT against them.
// ---------------------------------------------------------------------------------------

/// Triangle pairs for the vector files: every pair of two n-triangle soups under one pose
/// (crossing, separate and uncertain pairs), A with one zero-area triangle more.
fn vector_scene(f: Format, n: usize) -> (Vec<TriWord>, Vec<TriWord>, HostSetup) {
    use crate::config::ChipConfig;
    use crate::pose::Pose;
    use nalgebra::Point3;
    let mut a = crate::mesh::soup(n, 21).triangles_f64();
    a.push([Point3::new(0.1, 0.2, 0.3), Point3::new(0.3, 0.4, 0.5), Point3::new(0.7, 0.8, 0.9)]);
    let b = crate::mesh::soup(n, 22).triangles_f64();
    let chip = crate::query::Chip::new(&a, &b, ChipConfig { format: f.into(), ..Default::default() }).expect("two non-empty soups");
    let setup = chip.setup(&Pose::new(23.0, -61.0, 11.0, 0.05, -0.08, 0.03));
    (chip.a.tris, chip.b.tris, setup)
}

fn hexw(f: Format, w: u64) -> String {
    format!("{w:0n$x}", n = (f.width() as usize).div_ceil(4))
}

fn port_names(prefix: &str, n: usize) -> Vec<String> {
    (0..n).map(|i| format!("{prefix}${i}")).collect()
}

/// The input names of a leaf's map: `m_0$0 .. m_2$3 e_lin e_tr l_norm` (prefixed).
fn leaf_names(pre: &str) -> Vec<String> {
    let mut v: Vec<String> = (0..3).flat_map(|r| port_names(&format!("{pre}m_{r}"), 4)).collect();
    v.extend(["e_lin", "e_tr", "l_norm"].map(|n| format!("{pre}{n}")));
    v
}

/// The input names of a triangle's vertices: `v_x$0 .. v_z$2 v_exact` (prefixed).
fn vertex_names(pre: &str) -> Vec<String> {
    let mut v: Vec<String> = ["x", "y", "z"].iter().flat_map(|c| port_names(&format!("{pre}v_{c}"), 3)).collect();
    v.push(format!("{pre}v_exact"));
    v
}

fn vertex_words(f: Format, v: &[[u64; 3]; 3]) -> Vec<String> {
    (0..3).flat_map(|c| (0..3).map(move |k| v[k][c])).map(|w| hexw(f, w)).collect()
}

/// T.CHECK's vectors (latency 128): both directions of every pair of the vector scene (12
/// soup triangles each) and
/// of every catalogue case, `inputs -> s_x$e s_e$e cross_t$e cross_f$e hit miss tag_out`.
pub fn tcheck_vectors(name: &str, f: Format, r: Rounding) -> String {
    use std::fmt::Write;
    let mut names = leaf_names("");
    for row in 0..3 {
        names.extend(port_names(&format!("f_{row}"), 4));
    }
    names.extend(["f_lin", "f_tr", "eta", "gap_en"].map(String::from));
    names.extend(vertex_names(""));
    names.push("tag".into());
    for o in ["s_x", "s_e", "cross_t", "cross_f"] {
        names.extend(port_names(o, 3));
    }
    names.extend(["hit", "miss", "tag_out"].map(String::from));
    let mut out = String::new();
    let _ = writeln!(out, "// {}", names.join(" "));
    let _ = writeln!(out, "// latency: 128");
    let _ = writeln!(out, "// {name}: T.CHECK in {f}, rounding {r:?}: both directions of every pair of two 12-triangle soups under one pose, then of every hard case; golden: golden::tcheck::{{stage1, edges}}");
    let mut triples = vec![];
    let (a, b, setup) = vector_scene(f, 12);
    for ta in &a {
        for tb in &b {
            triples.push((ta.clone(), tb.clone(), setup.clone()));
        }
    }
    for case in crate::hard_cases::load_catalogue().expect("the hard-case catalogue loads") {
        let chip = crate::query::Chip::new(&case.a, &case.b, crate::config::ChipConfig { format: f.into(), ..Default::default() }).expect("catalogue objects are non-empty");
        let setup = chip.setup(&case.pose);
        for ta in &chip.a.tris {
            for tb in &chip.b.tris {
                triples.push((ta.clone(), tb.clone(), setup.clone()));
            }
        }
    }
    let mut tag = 0u32;
    for (ta, tb, s) in &triples {
        for (x, y) in tri_unit_directions(f, r, ta, tb, s) {
            let mut w: Vec<String> = x.m.iter().map(|&v| hexw(f, v)).collect();
            w.extend([x.e_lin, x.e_tr, x.l_norm].map(|v| hexw(f, v)));
            w.extend(x.f.iter().map(|&v| hexw(f, v)));
            w.extend([x.f_lin, x.f_tr, x.eta].map(|v| hexw(f, v)));
            w.push((x.gap_en as u8).to_string());
            w.extend(vertex_words(f, &x.v));
            w.push((x.v_exact as u8).to_string());
            w.push(format!("{tag:08x}"));
            w.extend(y.s_x.iter().chain(&y.s_e).map(|&v| hexw(f, v)));
            w.extend(y.cross_t.iter().chain(&y.cross_f).map(|&b| (b as u8).to_string()));
            w.extend([y.hit, y.miss].map(|b| (b as u8).to_string()));
            w.push(format!("{tag:08x}"));
            let _ = writeln!(out, "{}", w.join(" "));
            tag += 1;
        }
    }
    out
}

/// TRI_UNIT's vectors (latency 130, reader always ready): a preload of the frame setup,
/// then every pair of the vector scene (6 soup triangles each; Icarus runs TRI_UNIT at a few
/// clocks per second), `a_* b_* tag out_ready -> out_tag out_hit
/// out_uncertain in_ready` (golden::tcheck::tri_unit).
pub fn tri_unit_vectors(name: &str, f: Format, r: Rounding) -> String {
    use std::fmt::Write;
    let (a, b, setup) = vector_scene(f, 6);
    let mut names = vec![];
    for pre in ["a_", "b_"] {
        names.extend(leaf_names(pre));
        names.extend(vertex_names(pre));
        names.push(format!("{pre}degenerate"));
    }
    names.extend(["tag", "out_ready", "out_tag", "out_hit", "out_uncertain", "in_ready"].map(String::from));
    let mut out = String::new();
    let _ = writeln!(out, "// preload: load_en load_addr load_data");
    let _ = writeln!(out, "// {}", names.join(" "));
    let _ = writeln!(out, "// latency: 130");
    let _ = writeln!(out, "// {name}: TRI_UNIT in {f}, rounding {r:?}: every pair of two 6-triangle soups (A with a zero-area triangle) under one pose; golden: golden::tcheck::tri_unit");
    for (addr, data) in tri_unit_setup_words(f, &setup) {
        let _ = writeln!(out, "@ 1 {addr:02x} {}", hexw(f, data));
    }
    let mut tag = 0u32;
    for ta in &a {
        for tb in &b {
            let mut w = vec![];
            for t in [ta, tb] {
                let l = LeafIn::of(f, t);
                w.extend(l.m.iter().map(|&v| hexw(f, v)));
                w.extend([l.e_lin, l.e_tr, l.l_norm].map(|v| hexw(f, v)));
                w.extend(vertex_words(f, &l.v));
                w.push((l.v_exact as u8).to_string());
                w.push((l.degenerate as u8).to_string());
            }
            let res = tcheck::tri_unit(f, r, ta, tb, &setup);
            w.push(format!("{tag:08x}"));
            w.push("1".into());
            w.push(format!("{tag:08x}"));
            w.push((res.hit as u8).to_string());
            w.push((res.uncertain as u8).to_string());
            w.push("1".into());
            let _ = writeln!(out, "{}", w.join(" "));
            tag += 1;
        }
    }
    out
}
