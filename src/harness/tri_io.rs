//! T.CHECK's operands and results as the RTL sees them (bit patterns of the format), built
//! from the golden memory words and host setup, with the golden results they must give:
//! one source for the testbenches (`tb/rtl_tri.rs`) and the exported vectors.

use crate::format::{Format, Rounding};
use crate::golden::certificate::Certificate;
use crate::golden::host::{Affine, HostSetup};
use crate::golden::memory::TriWord;
use crate::golden::tcheck::{self, Trace};

/// The inputs of one T.CHECK: the leaf whose unit triangle is the target (`m` = its M_B,
/// row-major 3x4, with its error words `alpha_m`, `alpha_f`), the frame map into that
/// leaf's object (`f`, row-major, with its error words `beta_m`, `beta_f`) and the
/// vertices `v[k][c]` of the other triangle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TCheckIn {
    pub m: [u64; 12],
    pub alpha_m: u64,
    pub alpha_f: u64,
    pub f: [u64; 12],
    pub beta_m: u64,
    pub beta_f: u64,
    pub scale: u64,
    pub v: [[u64; 3]; 3],
    pub v_exact: bool,
}

/// The outputs of one T.CHECK: per edge s = (a + b) - r_z and its bound, surely crosses,
/// surely misses; over the edges `hit` (some edge surely crosses) and `miss` (every edge
/// surely misses); neither: unknown.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TCheckOut {
    pub s_x: [u64; 3],
    pub s_b: [u64; 3],
    pub cross_t: [bool; 3],
    pub cross_f: [bool; 3],
    pub hit: bool,
    pub miss: bool,
}

fn words(f: Format, m: &Affine) -> [u64; 12] {
    std::array::from_fn(|i| f.to_bits(m[i / 4][i % 4]))
}

/// One direction of TRI_UNIT: the edges of `tri` against the unit triangle of `leaf`,
/// `frame` (with error words `beta`) mapping `tri`'s object (of scale `scale`) into
/// `leaf`'s. Returns the RTL inputs and the golden outputs (golden [`tcheck::stage1`] then
/// [`tcheck::edges`]).
pub fn direction(
    f: Format,
    r: Rounding,
    leaf: &TriWord,
    frame: &Affine,
    beta: [f64; 2],
    scale: f64,
    tri: &TriWord,
) -> (TCheckIn, TCheckOut) {
    let input = TCheckIn {
        m: words(f, &leaf.m),
        alpha_m: f.to_bits(leaf.alpha_m),
        alpha_f: f.to_bits(leaf.alpha_f),
        f: words(f, frame),
        beta_m: f.to_bits(beta[0]),
        beta_f: f.to_bits(beta[1]),
        scale: f.to_bits(scale),
        v: tri.v.map(|p| p.map(|x| f.to_bits(x))),
        v_exact: tri.v_exact,
    };
    let trace = tcheck::edges(
        f,
        r,
        &Certificate::new(f, r),
        &tcheck::stage1(f, r, leaf, frame, beta, scale),
        tri,
    );
    (input, output(f, &trace))
}

fn output(f: Format, t: &Trace) -> TCheckOut {
    let res = t.result();
    TCheckOut {
        s_x: t.s.map(|v| f.to_bits(v)),
        s_b: t.s_bound.map(|v| f.to_bits(v)),
        cross_t: t.crossing.map(|c| c == Some(true)),
        cross_f: t.crossing.map(|c| c == Some(false)),
        hit: res == Some(true),
        miss: res == Some(false),
    }
}

/// Both directions of TRI_UNIT for triangle `a` of A against `b` of B under `setup`:
/// A's edges against U(B), then B's edges against U(A).
pub fn tri_unit_directions(
    f: Format,
    r: Rounding,
    a: &TriWord,
    b: &TriWord,
    setup: &HostSetup,
) -> [(TCheckIn, TCheckOut); 2] {
    [(b, a, true), (a, b, false)].map(|(leaf, tri, ab)| {
        let (frame, beta, scale) = setup.tri_frame(ab);
        direction(f, r, leaf, frame, beta, scale, tri)
    })
}

/// TRI_UNIT's per-query write port: `(load_addr, load_data)` for M_AB (address 4 i + c),
/// its error words (12, 13), A's scale (14), M_BA (16 + 4 i + c), its error words (28, 29)
/// and B's scale (30).
pub fn tri_unit_setup_words(f: Format, setup: &HostSetup) -> Vec<(u64, u64)> {
    let mut out = vec![];
    for (base, ab) in [(0u64, true), (16, false)] {
        let (m, e, s) = setup.tri_frame(ab);
        for (i, w) in words(f, m).into_iter().enumerate() {
            out.push((base + i as u64, w));
        }
        out.push((base + 12, f.to_bits(e[0])));
        out.push((base + 13, f.to_bits(e[1])));
        out.push((base + 14, f.to_bits(s)));
    }
    out
}

/// One leaf's triangle word on TRI_UNIT's `a_*` / `b_*` ports.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LeafIn {
    pub m: [u64; 12],
    pub alpha_m: u64,
    pub alpha_f: u64,
    pub v: [[u64; 3]; 3],
    pub v_exact: bool,
    pub degenerate: bool,
}

impl LeafIn {
    pub fn of(f: Format, w: &TriWord) -> LeafIn {
        LeafIn {
            m: words(f, &w.m),
            alpha_m: f.to_bits(w.alpha_m),
            alpha_f: f.to_bits(w.alpha_f),
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
    use crate::chip::config::ChipConfig;
    use crate::pose::Pose;
    use nalgebra::Point3;
    let mut a = crate::mesh::soup(n, 21).triangles_f64();
    a.push([
        Point3::new(0.1, 0.2, 0.3),
        Point3::new(0.3, 0.4, 0.5),
        Point3::new(0.7, 0.8, 0.9),
    ]);
    let b = crate::mesh::soup(n, 22).triangles_f64();
    let chip = crate::query::Chip::new(
        &a,
        &b,
        ChipConfig {
            format: f.into(),
            ..Default::default()
        },
    )
    .expect("two non-empty soups");
    let setup = chip.setup(&Pose::new(23.0, -61.0, 11.0, 0.05, -0.08, 0.03));
    (chip.a.tris().collect(), chip.b.tris().collect(), setup)
}

fn hexw(f: Format, w: u64) -> String {
    format!("{w:0n$x}", n = (f.width() as usize).div_ceil(4))
}

fn port_names(prefix: &str, n: usize) -> Vec<String> {
    (0..n).map(|i| format!("{prefix}${i}")).collect()
}

/// The input names of a leaf's map: `m_0$0 .. m_2$3 alpha_m alpha_f` (prefixed).
fn leaf_names(pre: &str) -> Vec<String> {
    let mut v: Vec<String> = (0..3)
        .flat_map(|r| port_names(&format!("{pre}m_{r}"), 4))
        .collect();
    v.extend(["alpha_m", "alpha_f"].map(|n| format!("{pre}{n}")));
    v
}

/// The input names of a triangle's vertices: `v_x$0 .. v_z$2 v_exact` (prefixed).
fn vertex_names(pre: &str) -> Vec<String> {
    let mut v: Vec<String> = ["x", "y", "z"]
        .iter()
        .flat_map(|c| port_names(&format!("{pre}v_{c}"), 3))
        .collect();
    v.push(format!("{pre}v_exact"));
    v
}

fn vertex_words(f: Format, v: &[[u64; 3]; 3]) -> Vec<String> {
    (0..3)
        .flat_map(|c| (0..3).map(move |k| v[k][c]))
        .map(|w| hexw(f, w))
        .collect()
}

/// T.CHECK's vectors: both directions of every pair of the vector scene (12
/// soup triangles each) and
/// of every catalogue case, `inputs -> s_x$e s_e$e cross_t$e cross_f$e hit miss tag_out`,
/// for a T.CHECK of `latency` taking a pair every `interval` clocks (a folded one,
/// `rtl::b32::TCheckFold`: the testbench then drives a case in cycles 0 mod `interval`).
pub fn tcheck_vectors(
    name: &str,
    f: Format,
    r: Rounding,
    latency: usize,
    interval: usize,
) -> String {
    use std::fmt::Write;
    let mut names = leaf_names("");
    for row in 0..3 {
        names.extend(port_names(&format!("f_{row}"), 4));
    }
    names.extend(["beta_m", "beta_f", "scale"].map(String::from));
    names.extend(vertex_names(""));
    names.push("tag".into());
    for o in ["s_x", "s_b", "cross_t", "cross_f"] {
        names.extend(port_names(o, 3));
    }
    names.extend(["hit", "miss", "tag_out"].map(String::from));
    let mut out = String::new();
    let _ = writeln!(out, "// {}", names.join(" "));
    let _ = writeln!(out, "// latency: {latency}");
    if interval > 1 {
        let _ = writeln!(out, "// interval: {interval}");
    }
    let _ = writeln!(out, "// {name}: T.CHECK in {f}, rounding {r:?}: both directions of every pair of two 12-triangle soups under one pose, then of every hard case; golden: golden::tcheck::{{stage1, edges}}");
    let mut triples = vec![];
    let (a, b, setup) = vector_scene(f, 12);
    for ta in &a {
        for tb in &b {
            triples.push((*ta, *tb, setup.clone()));
        }
    }
    for case in crate::hard_cases::load_catalogue().expect("the hard-case catalogue loads") {
        let chip = crate::query::Chip::new(
            &case.a,
            &case.b,
            crate::chip::config::ChipConfig {
                format: f.into(),
                ..Default::default()
            },
        )
        .expect("catalogue objects are non-empty");
        let setup = chip.setup(&case.pose);
        for ta in chip.a.tris() {
            for tb in chip.b.tris() {
                triples.push((ta, tb, setup.clone()));
            }
        }
    }
    let mut tag = 0u32;
    for (ta, tb, s) in &triples {
        for (x, y) in tri_unit_directions(f, r, ta, tb, s) {
            let mut w: Vec<String> = x.m.iter().map(|&v| hexw(f, v)).collect();
            w.extend([x.alpha_m, x.alpha_f].map(|v| hexw(f, v)));
            w.extend(x.f.iter().map(|&v| hexw(f, v)));
            w.extend([x.beta_m, x.beta_f, x.scale].map(|v| hexw(f, v)));
            w.extend(vertex_words(f, &x.v));
            w.push((x.v_exact as u8).to_string());
            w.push(format!("{tag:08x}"));
            w.extend(y.s_x.iter().chain(&y.s_b).map(|&v| hexw(f, v)));
            w.extend(
                y.cross_t
                    .iter()
                    .chain(&y.cross_f)
                    .map(|&b| (b as u8).to_string()),
            );
            w.extend([y.hit, y.miss].map(|b| (b as u8).to_string()));
            w.push(format!("{tag:08x}"));
            let _ = writeln!(out, "{}", w.join(" "));
            tag += 1;
        }
    }
    out
}

/// TRI_UNIT's vectors (reader always ready): a preload of the frame setup,
/// then every pair of the vector scene (`n` soup triangles each: Icarus runs TRI_UNIT at a few
/// clocks per second, the folded one much faster), `a_* b_* tag out_ready -> out_tag out_hit
/// out_uncertain in_ready` (golden::tcheck::tri_unit), for a TRI_UNIT of `latency` taking a
/// pair every `interval` clocks (the folded one, `rtl::b32::TriUnitFold`: the testbench drives
/// a pair in cycles 0 mod `interval`, and `in_ready` at a result's cycle is its counter's,
/// `latency` mod `interval`, being 0).
pub fn tri_unit_vectors(
    name: &str,
    f: Format,
    r: Rounding,
    latency: usize,
    interval: usize,
    n: usize,
) -> String {
    use std::fmt::Write;
    let (a, b, setup) = vector_scene(f, n);
    let mut names = vec![];
    for pre in ["a_", "b_"] {
        names.extend(leaf_names(pre));
        names.extend(vertex_names(pre));
        names.push(format!("{pre}degenerate"));
    }
    names.extend(
        [
            "tag",
            "out_ready",
            "out_tag",
            "out_hit",
            "out_uncertain",
            "in_ready",
        ]
        .map(String::from),
    );
    let mut out = String::new();
    let _ = writeln!(out, "// preload: load_en load_addr load_data");
    let _ = writeln!(out, "// {}", names.join(" "));
    let _ = writeln!(out, "// latency: {latency}");
    if interval > 1 {
        let _ = writeln!(out, "// interval: {interval}");
    }
    let _ = writeln!(out, "// {name}: TRI_UNIT in {f}, rounding {r:?}: every pair of two {n}-triangle soups (A with a zero-area triangle) under one pose; golden: golden::tcheck::tri_unit");
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
                w.extend([l.alpha_m, l.alpha_f].map(|v| hexw(f, v)));
                w.extend(vertex_words(f, &l.v));
                w.push((l.v_exact as u8).to_string());
                w.push((l.degenerate as u8).to_string());
            }
            let res = crate::golden::tri_unit::tri_unit(f, r, ta, tb, &setup);
            w.push(format!("{tag:08x}"));
            w.push("1".into());
            w.push(format!("{tag:08x}"));
            w.push((res.hit as u8).to_string());
            w.push((res.uncertain as u8).to_string());
            w.push((latency.is_multiple_of(interval) as u8).to_string());
            let _ = writeln!(out, "{}", w.join(" "));
            tag += 1;
        }
    }
    out
}
