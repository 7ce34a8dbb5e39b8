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
