//! The exported units: for each, its Verilog (`rtl/<name>.v`, by `generate_verilog`) and its
//! golden test vectors (`vectors/<name>.hex`, TestFloat style, see scripts/README.md),
//! written by `cchip export-verilog` and `cchip vectors` and checked in. CI regenerates both
//! and fails if they differ from the checked-in files, then runs every unit against its
//! vectors under Icarus Verilog and Verilator (`scripts/check-rtl.sh`).

use crate::chip::rtl::{dop_unit_name, format_tag, rounding_tag, tri_unit_name, ChipKind, Depth};
use crate::fold::plan::Binding;
use crate::format::{Format, Rounding};
use rand::{Rng, SeedableRng};
use std::fmt::Write;
use std::path::Path;

mod wscg03;

/// Vector cases per floating-point unit: every pair of the format's special patterns, then
/// random operands.
const RANDOM_CASES: usize = 3000;

/// One exported unit.
pub struct Unit {
    /// `<unit>_<format>_<rounding>` (`<unit>_<format>` for the constant multiplier, which
    /// rounds up), the file stem in rtl/ and vectors/.
    pub name: String,
    pub latency: u32,
    verilog: Text,
    vectors: Text,
}

/// A file's text, made on demand (any thread).
type Text = Box<dyn Fn() -> String + Send + Sync>;

impl Unit {
    /// The unit's Verilog: rust-hdl's, with modules identical up to their names merged
    /// ([`dedup_modules`](super::verilog::dedup_modules)).
    pub fn verilog(&self) -> String {
        verilog_of(&self.verilog)
    }

    pub fn vectors(&self) -> String {
        (self.vectors)()
    }
}

/// rust-hdl's Verilog with modules identical up to their names merged.
fn verilog_of(v: &Text) -> String {
    super::verilog::dedup_modules(&v())
}

/// A unit's Verilog for one rounding.
type VerilogFn = fn(Rounding) -> String;

/// One format's units as the RTL stamps them out (`fp_format!` in `crate::rtl`): their
/// Verilog makers.
struct FormatRtl {
    fmt: Format,
    fp_mul: VerilogFn,
    fp_add: VerilogFn,
    fp_mul_fpga: VerilogFn,
    fp_add_fpga: VerilogFn,
    fp_scale: fn() -> String,
    fp_cmp: fn() -> String,
    doptrf: fn() -> String,
    doptrf_fpga: fn() -> String,
    dotadd: fn() -> String,
    tcheck: VerilogFn,
    tri_unit: VerilogFn,
    dop_unit: fn(usize) -> Option<String>,
    dop_unit_fold: fn(usize, usize) -> Option<String>,
}

/// Every format the RTL is built in.
const FORMATS: [FormatRtl; 3] = {
    macro_rules! format_rtl {
        ($m:ident) => {
            FormatRtl {
                fmt: crate::rtl::$m::FORMAT,
                fp_mul: crate::rtl::$m::verilog_fp_mul,
                fp_add: crate::rtl::$m::verilog_fp_add,
                fp_mul_fpga: crate::rtl::$m::verilog_fp_mul_fpga,
                fp_add_fpga: crate::rtl::$m::verilog_fp_add_fpga,
                fp_scale: crate::rtl::$m::verilog_fp_scale,
                fp_cmp: crate::rtl::$m::verilog_fp_cmp,
                doptrf: crate::rtl::$m::verilog_doptrf,
                doptrf_fpga: crate::rtl::$m::verilog_doptrf_fpga,
                dotadd: crate::rtl::$m::verilog_dotadd,
                tcheck: crate::rtl::$m::verilog_tcheck,
                tri_unit: crate::rtl::$m::verilog_tri_unit,
                dop_unit: crate::rtl::$m::verilog_dop_unit,
                dop_unit_fold: crate::rtl::$m::verilog_dop_unit_fold,
            }
        };
    }
    [format_rtl!(b32), format_rtl!(e8m15), format_rtl!(e8m10)]
};

/// The RTL's units in `fmt`, if it is built in it.
fn rtl_of(fmt: Format) -> Option<&'static FormatRtl> {
    FORMATS.iter().find(|f| f.fmt == fmt)
}

/// The folded DOP unit's Verilog, where the RTL stamps out this k, interval and format.
pub fn dop_unit_fold_verilog(ii: usize, k: usize, fmt: Format) -> Option<String> {
    (rtl_of(fmt)?.dop_unit_fold)(k, ii)
}

/// The folded DOP units exported (`rtl::*::DopUnit<k>Fold<ii>`): (ii, k,
/// format), with the unfolded unit's vectors driven every ii clocks.
const DOP_FOLDS: [(usize, usize, Format); 3] = [
    (2, 6, Format::REDUCED),
    (3, 6, Format::REDUCED),
    (6, 6, Format::REDUCED),
];

/// The DOP unit's Verilog, where the RTL builds this k and format.
fn dop_unit_verilog(k: usize, fmt: Format) -> Option<String> {
    (rtl_of(fmt)?.dop_unit)(k)
}

/// The folded T.CHECKs and TRI_UNITs exported (binary32, nearest-even; `rtl::b32::TCheckFold`,
/// `rtl::b32::TriUnitFold`), each at these initiation intervals.
const FOLDED_II: [usize; 1] = [16];

/// `tcheck_fold<ii>_b32_rne`: T.CHECK folded for initiation interval `ii`, with T.CHECK's
/// vectors driven every `ii` clocks.
fn tcheck_fold_unit(ii: usize) -> Unit {
    let r = Rounding::NearestEven;
    let name = format!("tcheck_fold{ii}_b32_{}", rounding_tag(r));
    let latency = crate::fold::tcheck_plan(
        ii,
        crate::fold::plan::Binding::Shared,
        crate::chip::rtl::Depth::Asic,
    )
    .expect("T.CHECK schedules at every II")
    .latency;
    let n2 = name.clone();
    Unit {
        name,
        latency: latency as u32,
        verilog: Box::new(move || crate::rtl::b32::verilog_tcheck_fold(ii, r)),
        vectors: Box::new(move || {
            super::tri_io::tcheck_vectors(&n2, Format::BINARY32, r, latency, ii)
        }),
    }
}

/// `tri_unit_fold<ii>_b32_rne`: TRI_UNIT folded for a pair every `ii` clocks
/// (`rtl::b32::TriUnitFold`), with TRI_UNIT's vectors driven every `ii` clocks, on 12-triangle
/// soups (156 pairs: a verdict per pair checks less than T.CHECK's values).
fn tri_unit_fold_unit(ii: usize) -> Unit {
    let verilog = move |r| crate::rtl::b32::verilog_tri_unit_fold(ii, r);
    tri_unit_fold_at(Depth::Asic, Binding::Shared, Format::BINARY32, ii, verilog)
}

/// `tri_unit_fpga_fold32_e8m15_rne`: the FPGA chip's TRI_UNIT (`rtl::e8m15::TriUnitFoldFpga`,
/// registers per reader), with the same vectors.
fn tri_unit_fold_fpga_unit() -> Unit {
    let ii = 32;
    let verilog = move |r| crate::rtl::e8m15::verilog_tri_unit_fold_fpga(ii, r);
    tri_unit_fold_at(
        Depth::Fpga,
        Binding::PerReader,
        Format::REDUCED,
        ii,
        verilog,
    )
}

/// A folded TRI_UNIT in `fmt` at `depth`, nearest-even, its Verilog from `verilog`.
fn tri_unit_fold_at(
    depth: Depth,
    binding: Binding,
    fmt: Format,
    ii: usize,
    verilog: impl Fn(Rounding) -> Result<String, String> + Send + Sync + 'static,
) -> Unit {
    let r = Rounding::NearestEven;
    let name = crate::chip::rtl::tri_unit_name_at(depth, fmt, r, ii as u32);
    let plan = crate::fold::tri_unit_plan(ii, binding, depth).expect("an exported II folds");
    let latency = crate::fold::tri_unit_latency(&plan);
    let n2 = name.clone();
    Unit {
        name,
        latency: latency as u32,
        verilog: Box::new(move || verilog(r).expect("an exported II folds")),
        vectors: Box::new(move || super::tri_io::tri_unit_vectors(&n2, fmt, r, latency, ii, 12)),
    }
}

/// Every exported unit, in a fixed order.
pub fn all() -> Vec<Unit> {
    let mut units = doptrf_units();
    units.extend(dop_units());
    units.extend(fp_units());
    units.extend(tri_units());
    for ii in FOLDED_II {
        units.push(tcheck_fold_unit(ii));
        units.push(tri_unit_fold_unit(ii));
    }
    units.push(tri_unit_fold_fpga_unit());
    units.push(pair_queue_unit());
    units.push(dop_decode_unit());
    units.push(wscg03::compare_bank_unit());
    units.push(wscg03::dprime_memory_unit());
    units.push(wscg03::wscg03_dop_unit_unit());
    units.push(wscg03::list_stack_unit());
    units.push(wscg03::tri_input_unit());
    units.push(wscg03::memory_controller_unit());
    units.push(wscg03::sequencer_unit());
    units
}

/// The DOPTRF lanes, one per format and depth (their rounding an input): `doptrf_b32`,
/// `doptrf_fpga_b32`; then WSCG'03's DOTADD units, `dotadd_b32`.
fn doptrf_units() -> Vec<Unit> {
    use crate::chip::rtl::Depth;
    let mut units = vec![];
    for depth in Depth::ALL {
        for f in &FORMATS {
            let fmt = f.fmt;
            let v = match depth {
                Depth::Asic => f.doptrf,
                Depth::Fpga => f.doptrf_fpga,
            };
            let name = format!("doptrf{}_{}", depth.tag(), format_tag(fmt));
            let n2 = name.clone();
            let latency = depth.lane_latency() as u32;
            units.push(Unit {
                name,
                latency,
                verilog: Box::new(v),
                vectors: Box::new(move || lane_vectors(&n2, fmt, latency, false)),
            });
        }
    }
    for f in &FORMATS {
        let fmt = f.fmt;
        let name = format!("dotadd_{}", format_tag(fmt));
        let n2 = name.clone();
        let latency = crate::chip::rtl::DOTADD_LATENCY as u32;
        units.push(Unit {
            name,
            latency,
            verilog: Box::new(f.dotadd),
            vectors: Box::new(move || lane_vectors(&n2, fmt, latency, true)),
        });
    }
    units
}

/// The DOP units: k = 6 in e8m15 and k = 24 in binary32, then the folded ones.
fn dop_units() -> Vec<Unit> {
    let mut units = vec![];
    for (k, fmt) in [(6, Format::REDUCED), (24, Format::BINARY32)] {
        let name = dop_unit_name(k, fmt, 1);
        let n2 = name.clone();
        let verilog = move || dop_unit_verilog(k, fmt).expect("the RTL builds this k");
        units.push(Unit {
            name,
            latency: crate::chip::rtl::DOP_LATENCY as u32,
            verilog: Box::new(verilog),
            vectors: Box::new(move || {
                dop_unit_vectors(&n2, k, fmt, 1, crate::chip::rtl::DOP_LATENCY)
            }),
        });
    }
    for (ii, k, fmt) in DOP_FOLDS {
        let name = dop_unit_name(k, fmt, ii as u32);
        let n2 = name.clone();
        let verilog =
            move || dop_unit_fold_verilog(ii, k, fmt).expect("the RTL stamps out this fold");
        let latency = crate::chip::rtl::dop_fold_latency(ii);
        units.push(Unit {
            name,
            latency: latency as u32,
            verilog: Box::new(verilog),
            vectors: Box::new(move || dop_unit_vectors(&n2, k, fmt, ii, latency)),
        });
    }
    // the FPGA chip's: k = 6 in e8m15, one lane at FPGA depth
    let (ii, k, fmt) = (6, 6, Format::REDUCED);
    let depth = crate::chip::rtl::Depth::Fpga;
    let name = crate::chip::rtl::dop_unit_name_at(depth, k, fmt, ii as u32);
    let n2 = name.clone();
    let latency = depth.dop_fold_latency(ii);
    units.push(Unit {
        name,
        latency: latency as u32,
        verilog: Box::new(crate::rtl::e8m15::verilog_dop_unit6_fold6_fpga),
        vectors: Box::new(move || dop_unit_vectors(&n2, k, fmt, ii, latency)),
    });
    units
}

/// The FP multipliers and adders in every format and both roundings, at both depths
/// (`fp_mul_b32_rne`, `fp_mul_fpga_b32_rne`), then the scalers and WSCG'03's compare units.
fn fp_units() -> Vec<Unit> {
    use crate::chip::rtl::Depth;
    let mut units = vec![];
    for depth in Depth::ALL {
        for r in [Rounding::NearestEven, Rounding::TowardPositive] {
            for f in &FORMATS {
                let fmt = f.fmt;
                let (vm, va) = match depth {
                    Depth::Asic => (f.fp_mul, f.fp_add),
                    Depth::Fpga => (f.fp_mul_fpga, f.fp_add_fpga),
                };
                let (tags, d) = ((format_tag(fmt), rounding_tag(r)), depth.tag());
                for (op, add, latency, v) in [
                    ("mul", false, depth.fp_mul_latency() as u32, vm),
                    ("add", true, depth.fp_add_latency() as u32, va),
                ] {
                    let name = format!("fp_{op}{d}_{}_{}", tags.0, tags.1);
                    let n2 = name.clone();
                    units.push(Unit {
                        name,
                        latency,
                        verilog: Box::new(move || v(r)),
                        vectors: Box::new(move || fp_vectors(&n2, fmt, r, add, latency)),
                    });
                }
            }
        }
    }
    for f in &FORMATS {
        let fmt = f.fmt;
        let name = format!("fp_scale_{}", format_tag(fmt));
        let n2 = name.clone();
        units.push(Unit {
            name,
            latency: 4,
            verilog: Box::new(f.fp_scale),
            vectors: Box::new(move || fp_scale_vectors(&n2, fmt)),
        });
        let name = format!("fp_cmp_{}", format_tag(fmt));
        let n2 = name.clone();
        units.push(Unit {
            name,
            latency: crate::chip::rtl::FP_CMP_LATENCY as u32,
            verilog: Box::new(f.fp_cmp),
            vectors: Box::new(move || fp_cmp_vectors(&n2, fmt)),
        });
    }
    units
}

/// T.CHECK and TRI_UNIT in every format, rounding to nearest even.
fn tri_units() -> Vec<Unit> {
    let mut units = vec![];
    for f in &FORMATS {
        let (fmt, vt, vu) = (f.fmt, f.tcheck, f.tri_unit);
        let r = Rounding::NearestEven;
        let name = format!("tcheck_{}_{}", format_tag(fmt), rounding_tag(r));
        let n2 = name.clone();
        let latency = crate::rtl::b32::TCheck::LATENCY;
        units.push(Unit {
            name,
            latency: latency as u32,
            verilog: Box::new(move || vt(r)),
            vectors: Box::new(move || super::tri_io::tcheck_vectors(&n2, fmt, r, latency, 1)),
        });
        let name = tri_unit_name(fmt, r, 1);
        let n2 = name.clone();
        units.push(Unit {
            name,
            latency: crate::rtl::b32::TriUnit::LATENCY as u32,
            verilog: Box::new(move || vu(r)),
            vectors: Box::new(move || {
                super::tri_io::tri_unit_vectors(
                    &n2,
                    fmt,
                    r,
                    crate::rtl::b32::TriUnit::LATENCY,
                    1,
                    6,
                )
            }),
        });
    }
    units
}

/// D_CNTR's pair queue, 16 entries (format independent): one line per clock.
fn pair_queue_unit() -> Unit {
    let name = crate::chip::rtl::PAIR_QUEUE_UNIT.to_string();
    let n2 = name.clone();
    Unit {
        name,
        latency: 1,
        verilog: Box::new(crate::rtl::d_cntr::verilog_pair_queue::<4, 5, 3>),
        vectors: Box::new(move || crate::rtl::d_cntr::pair_queue_vectors(&n2, 4, RANDOM_CASES)),
    }
}

/// `dop_decode_q4_b32`: the decode stage of 4-bit stored DOPs in binary32
/// (`rtl::b32::DopDecode`; its rounding an input, the DOP lanes').
fn dop_decode_unit() -> Unit {
    let fmt = Format::BINARY32;
    let bits = crate::rtl::b32::DopDecode::CODE_BITS as u32;
    let name = crate::chip::rtl::dop_decode_name(fmt, bits);
    let n2 = name.clone();
    Unit {
        name,
        latency: crate::chip::rtl::DOP_DECODE_LATENCY as u32,
        verilog: Box::new(crate::rtl::b32::verilog_dop_decode),
        vectors: Box::new(move || dop_decode_vectors(&n2, fmt, bits)),
    }
}

/// The two roundings of a modal unit's `round_up` column in a random order: each case
/// runs in both, and a rounding that met the wrong case in the pipeline shows.
fn both_roundings(rng: &mut impl Rng) -> [Rounding; 2] {
    let r = [Rounding::TowardPositive, Rounding::NearestEven];
    if rng.random_range(0..2) == 0 {
        r
    } else {
        [r[1], r[0]]
    }
}

/// Vectors `round_up r q ef y` of a decode stage (golden [`decode`](crate::dop::stored::decode)), each case in both roundings ([`both_roundings`]):
/// every code at every exponent with `r = 0` (`y` is minus the step: each step the stage
/// makes, normal or subnormal, shows bit for bit), every special `r` with the extreme codes
/// and exponents, then random `r` (any pattern, or a multiple of the step, so that the
/// difference cancels or lands on a tie) with random codes and exponents.
fn dop_decode_vectors(name: &str, fmt: Format, bits: u32) -> String {
    use crate::chip::layout::{exp_field_bits, exp_range};
    use crate::dop::stored::decode;
    let (lo, hi) = exp_range(fmt, bits);
    let (top, efs) = ((1u32 << bits) - 1, (hi - lo) as u32);
    let digits = (fmt.width() as usize).div_ceil(4);
    let (qd, ed) = (
        bits.div_ceil(4) as usize,
        exp_field_bits(fmt, bits).div_ceil(4) as usize,
    );
    let mut out = String::new();
    let _ = writeln!(out, "// round_up r q ef y");
    let _ = writeln!(out, "// latency: {}", crate::chip::rtl::DOP_DECODE_LATENCY);
    let _ = writeln!(out, "// {name}: y = r - q 2^(ef {lo}) in {fmt}, round_up 1: TowardPositive, 0: NearestEven, q < 2^{bits}, ef <= {efs}; golden: collision_chip::dop::stored::decode");
    let mut cases: Vec<(u64, u32, u32)> = (0..=top)
        .flat_map(|q| (0..=efs).map(move |ef| (0, q, ef)))
        .collect();
    cases.extend(
        fmt.special_patterns()
            .into_iter()
            .flat_map(|x| [0, 1, top].map(|q| [0, 1, efs / 2, efs].map(|ef| (x, q, ef))))
            .flatten(),
    );
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0x5eed ^ name.len() as u64);
    cases.extend((0..RANDOM_CASES).map(|i| {
        let (q, ef) = (rng.random_range(0..=top), rng.random_range(0..=efs));
        let x = if i % 2 == 0 {
            operand(&mut rng, fmt)
        } else {
            let m = rng.random_range(0..=4 * top) as f64;
            let e = (lo + ef as i32 + rng.random_range(-2..3)).max(lo);
            fmt.to_bits(m * 2f64.powi(e))
        };
        (x, q, ef)
    }));
    for (x, q, ef) in cases {
        for r in both_roundings(&mut rng) {
            let y = fmt.to_bits(decode(fmt, r, fmt.from_bits(x), q, lo + ef as i32));
            let up = (r == Rounding::TowardPositive) as u8;
            let _ = writeln!(out, "{up} {x:0digits$x} {q:0qd$x} {ef:0ed$x} {y:0digits$x}");
        }
    }
    out
}

/// A random operand: any bit pattern, or a value near 1 (many ties and cancellations).
pub(crate) fn operand(rng: &mut impl Rng, fmt: Format) -> u64 {
    let w = fmt.width();
    match rng.random_range(0..4) {
        0 | 1 => rng.random_range(0..(1u64 << w)),
        _ => {
            let f = fmt.frac_bits();
            let ex = fmt.bias() as u64 + rng.random_range(0..4) - 2;
            let fr = rng.random_range(0..(1u64 << f)) & !((1u64 << rng.random_range(0..f)) - 1);
            fmt.pack(rng.random_range(0..2) == 1, ex, fr)
        }
    }
}

/// Vectors `a b [sub] y` of an adder or multiplier, from the golden `Format` ops.
fn fp_vectors(name: &str, fmt: Format, r: Rounding, add: bool, latency: u32) -> String {
    let digits = (fmt.width() as usize).div_ceil(4);
    let mut out = String::new();
    let _ = writeln!(out, "// a b{} y", if add { " sub" } else { "" });
    let _ = writeln!(out, "// latency: {latency}");
    let _ = writeln!(
        out,
        "// {name}: y = a {} b in {fmt}, rounding {r:?}; golden: collision_chip::format::Format::{}",
        if add { "+ (or - when sub)" } else { "*" },
        if add { "add / sub" } else { "mul" }
    );
    let sp = fmt.special_patterns();
    let mut cases: Vec<(u64, u64, bool)> = sp
        .iter()
        .flat_map(|&a| sp.iter().map(move |&b| (a, b, false)))
        .collect();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0x5eed ^ name.len() as u64);
    cases.extend((0..RANDOM_CASES).map(|i| {
        (
            operand(&mut rng, fmt),
            operand(&mut rng, fmt),
            add && i % 2 == 1,
        )
    }));
    for (a, b, sub) in cases {
        let (x, y) = (fmt.from_bits(a), fmt.from_bits(b));
        let z = match (add, sub) {
            (false, _) => fmt.mul(x, y, r),
            (true, false) => fmt.add(x, y, r),
            (true, true) => fmt.sub(x, y, r),
        };
        let z = fmt.to_bits(z);
        if add {
            let _ = writeln!(
                out,
                "{a:0digits$x} {b:0digits$x} {} {z:0digits$x}",
                sub as u8
            );
        } else {
            let _ = writeln!(out, "{a:0digits$x} {b:0digits$x} {z:0digits$x}");
        }
    }
    out
}

/// Vectors `a sel y` of the constant multiplier `fp_scale_<format>` (T.CHECK's C_V for
/// rounded and exact vertices, `rtl::*::fp_scale_top`): every special pattern and
/// [`RANDOM_CASES`] random operands, each with both constants.
fn fp_scale_vectors(name: &str, fmt: Format) -> String {
    let c = crate::golden::certificate::Certificate::new(fmt, Rounding::NearestEven).c_e;
    let digits = (fmt.width() as usize).div_ceil(4);
    let mut out = String::new();
    let _ = writeln!(out, "// a sel y");
    let _ = writeln!(out, "// latency: 4");
    let _ = writeln!(out, "// {name}: y = |a| c rounded up, at least 2^emin, in {fmt}, c = {:?} (sel 0) or {:?} (sel 1); golden: collision_chip::format::Format::scale_up", c[0], c[1]);
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0x5eed ^ name.len() as u64);
    let mut xs = fmt.special_patterns();
    xs.extend((0..RANDOM_CASES).map(|_| operand(&mut rng, fmt)));
    for a in xs {
        for sel in [false, true] {
            let y = fmt.to_bits(fmt.scale_up(fmt.from_bits(a), c[sel as usize]));
            let _ = writeln!(out, "{a:0digits$x} {} {y:0digits$x}", sel as u8);
        }
    }
    out
}

/// Vectors `a b flag` of WSCG'03's compare unit `fp_cmp_<format>` (`rtl::*::fp_cmp_top`):
/// every pair of special patterns, [`RANDOM_CASES`] random pairs, and as many with `b` a
/// few ulps from `-a`, where the sum's sign turns.
fn fp_cmp_vectors(name: &str, fmt: Format) -> String {
    use crate::golden::doptrf::separated;
    let digits = (fmt.width() as usize).div_ceil(4);
    let q = fmt.min_positive_subnormal();
    let mut out = String::new();
    let _ = writeln!(out, "// a b flag");
    let _ = writeln!(out, "// latency: {}", crate::chip::rtl::FP_CMP_LATENCY);
    let _ = writeln!(out, "// {name}: flag = a + b < 0 (exactly) in {fmt}; golden: collision_chip::golden::doptrf::separated");
    let sp = fmt.special_patterns();
    let mut cases: Vec<(u64, u64)> = sp
        .iter()
        .flat_map(|&a| sp.iter().map(move |&b| (a, b)))
        .collect();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0xc3b ^ name.len() as u64);
    for _ in 0..RANDOM_CASES {
        let a = operand(&mut rng, fmt);
        cases.push((a, operand(&mut rng, fmt)));
        let b = ulps_away(&mut rng, fmt, -fmt.from_bits(a), 2);
        if !b.is_nan() {
            cases.push((a, fmt.to_bits(b)));
        }
    }
    for (a, b) in cases {
        let flag = separated(q, fmt.from_bits(a), fmt.from_bits(b));
        let _ = writeln!(out, "{a:0digits$x} {b:0digits$x} {}", flag as u8);
    }
    out
}

/// `x` moved by up to `steps` ulps of the format, each step up or down at random: where a
/// sum with `-x` turns sign, is zero or ties.
fn ulps_away(rng: &mut impl Rng, fmt: Format, mut x: f64, steps: u32) -> f64 {
    for _ in 0..rng.random_range(0..steps + 1) {
        x = if rng.random_range(0..2) == 0 {
            fmt.next_up(x)
        } else {
            fmt.next_down(x)
        };
    }
    x
}

fn hex(fmt: Format, x: f64) -> String {
    format!(
        "{:0w$x}",
        fmt.to_bits(x),
        w = (fmt.width() as usize).div_ceil(4)
    )
}

/// A random format value: an operand bit pattern, or a small integer (exact cancellations).
fn value(rng: &mut impl Rng, fmt: Format) -> f64 {
    if rng.random_range(0..4) == 0 {
        rng.random_range(-8i32..8) as f64
    } else {
        fmt.from_bits(operand(rng, fmt))
    }
}

/// Vectors of one DOPTRF lane: `round_up d0 d1 d2 c0 c1 c2 c e s flag`
/// (golden::doptrf::lane), each case in both roundings ([`both_roundings`]), with C >= 0 as
/// the host sets it, and half of the cases with e = -u +- a few ulps (of the first rounding's
/// u) so that s lands on zero, a tie or the sign boundary. With `dot`, those of the DOTADD
/// unit on the same cases: `round_up d0 d1 d2 c0 c1 c2 c u` (golden::doptrf::transformed).
fn lane_vectors(name: &str, fmt: Format, latency: u32, dot: bool) -> String {
    use crate::golden::doptrf;
    let mut out = String::new();
    if dot {
        let _ = writeln!(out, "// round_up d0 d1 d2 c0 c1 c2 c u");
        let _ = writeln!(out, "// latency: {latency}");
        let _ = writeln!(out, "// {name}: u = (d0 c0 + d1 c1) + (d2 c2 + c) in {fmt}, round_up 1: TowardPositive, 0: NearestEven; golden: golden::doptrf::transformed");
    } else {
        let _ = writeln!(out, "// round_up d0 d1 d2 c0 c1 c2 c e s flag");
        let _ = writeln!(out, "// latency: {latency}");
        let _ = writeln!(out, "// {name}: s = ((d0 c0 + d1 c1) + (d2 c2 + c)) + e in {fmt}, round_up 1: TowardPositive, 0: NearestEven, flag = s < 0; golden: golden::doptrf::lane");
    }
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0xd0b ^ name.len() as u64);
    for i in 0..RANDOM_CASES {
        let d = [
            value(&mut rng, fmt),
            value(&mut rng, fmt),
            value(&mut rng, fmt),
        ];
        let cm = [0; 3].map(|_| value(&mut rng, fmt).abs());
        let c = value(&mut rng, fmt);
        let rs = both_roundings(&mut rng);
        let e = if i % 2 == 0 {
            value(&mut rng, fmt)
        } else {
            ulps_away(&mut rng, fmt, -doptrf::transformed(fmt, rs[0], d, cm, c), 3)
        };
        for r in rs {
            let h = |x| hex(fmt, x);
            if dot {
                let u = doptrf::transformed(fmt, r, d, cm, c);
                let (rb, ds, cs) = ((r == Rounding::TowardPositive) as u8, d.map(h), cm.map(h));
                let _ = writeln!(
                    out,
                    "{rb} {} {} {}",
                    ds.join(" "),
                    cs.join(" "),
                    h(c) + " " + &h(u)
                );
                continue;
            }
            let s = doptrf::lane(fmt, r, d, cm, c, e);
            let _ = writeln!(
                out,
                "{} {} {} {} {} {} {} {} {} {} {}",
                (r == Rounding::TowardPositive) as u8,
                h(d[0]),
                h(d[1]),
                h(d[2]),
                h(cm[0]),
                h(cm[1]),
                h(cm[2]),
                h(c),
                h(e),
                h(s),
                (s < 0.0) as u8
            );
        }
    }
    out
}

/// Vectors of the DOP unit: a preload of the host setup (lane i's field f at address 8i + f:
/// C_i0..2, c_i, j packed as j0 | j1 << 5 | j2 << 10), then every node pair of two small DOP
/// trees, `d$0.. e$0.. tag -> overlap tag_out` (golden::dop_unit::dop_overlap), for a unit
/// taking a pair every `interval` clocks with `latency` (a folded one: the testbench drives a
/// pair in cycles 0 mod `interval`, and a last column `in_ready` at a result's cycle is its
/// counter's, latency mod `interval`, being 0).
fn dop_unit_vectors(name: &str, k: usize, fmt: Format, interval: usize, latency: usize) -> String {
    use crate::chip::config::ChipConfig;
    use crate::dop::DopTree;
    use crate::golden::host::HostSetup;
    use crate::pose::Pose;
    let cfg = ChipConfig {
        k,
        format: fmt.into(),
        ..Default::default()
    };
    let r = cfg.dop_rounding.op();
    let n = if k == 6 { 16 } else { 8 };
    let ta = DopTree::build(&crate::mesh::soup(n, 11).triangles_f64(), &cfg);
    let tb = DopTree::build(&crate::mesh::soup(n, 12).triangles_f64(), &cfg);
    let pose = Pose::new(17.0, -41.0, 73.0, 0.05, -0.1, 0.02);
    let setup = HostSetup::new(
        &cfg,
        &pose,
        tb.coord_bound(),
        crate::golden::host::TriSide::UNUSED,
    );
    let w = (fmt.width() as usize).div_ceil(4);
    let mut out = String::new();
    let _ = writeln!(out, "// preload: load_en load_addr load_data");
    let names: Vec<String> = (0..k)
        .map(|i| format!("d${i}"))
        .chain((0..k).map(|i| format!("e${i}")))
        .collect();
    let ready = if interval > 1 {
        format!(" {}", latency.is_multiple_of(interval) as u8)
    } else {
        String::new()
    };
    let _ = writeln!(
        out,
        "// {} tag overlap tag_out{}",
        names.join(" "),
        if interval > 1 { " in_ready" } else { "" }
    );
    let _ = writeln!(out, "// latency: {latency}");
    if interval > 1 {
        let _ = writeln!(out, "// interval: {interval}");
    }
    let _ = writeln!(out, "// {name}: k = {k}, {fmt}, outward; all node pairs of two DOP trees of 'soup' meshes under one pose; golden: golden::dop_unit::dop_overlap");
    for (a, v) in super::chip_io::dop_unit_setup_words(fmt, r, &setup) {
        let _ = writeln!(out, "@ 1 {a:02x} {v:0w$x}");
    }
    let mut tag = 0u16;
    for nb in 0..tb.len() as u32 {
        for na in 0..ta.len() as u32 {
            let (d, e) = (tb.dop(nb), ta.dop(na));
            let overlap = crate::golden::dop_unit::dop_overlap(fmt, r, &setup, &d, &e);
            let vals: Vec<String> = d.iter().chain(e.iter()).map(|&x| hex(fmt, x)).collect();
            let _ = writeln!(
                out,
                "{} {tag:04x} {} {tag:04x}{ready}",
                vals.join(" "),
                overlap as u8
            );
            tag = tag.wrapping_add(1);
        }
    }
    out
}

/// Writes `<dir>/<unit>.v` for every unit, each chip's `<dir>/chip_<format>_k<k>.v`
/// ([`ChipKind`]) and WSCG'03's chip's ([`WSCG03_CHIP`](crate::chip::rtl::WSCG03_CHIP));
/// returns the paths written.
pub fn write_verilog(dir: &Path) -> std::io::Result<Vec<String>> {
    let mut written = write_all(
        dir,
        "v",
        all().into_iter().map(|u| (u.name, u.verilog)).collect(),
        verilog_of,
    )?;
    for &kind in ChipKind::ALL {
        let p = dir.join(format!("{}.v", kind.name()));
        std::fs::write(&p, super::chip_io::verilog(kind))?;
        written.push(p.display().to_string());
    }
    let p = dir.join(format!("{}.v", crate::chip::rtl::WSCG03_CHIP));
    std::fs::write(&p, super::wscg03_io::chip::verilog())?;
    written.push(p.display().to_string());
    Ok(written)
}

/// Writes `<dir>/<unit>.hex` for every unit and the chip's query files under `<dir>/chip/`
/// ([`chip_io::write_vectors`](super::chip_io::write_vectors)); returns the paths written.
pub fn write_vectors(dir: &Path) -> std::io::Result<Vec<String>> {
    let mut written = write_all(
        dir,
        "hex",
        all().into_iter().map(|u| (u.name, u.vectors)).collect(),
        |v| v(),
    )?;
    written
        .extend(super::chip_io::write_vectors(&dir.join("chip")).map_err(std::io::Error::other)?);
    Ok(written)
}

/// The units whose Yosys cells the area study counts (scripts/area-study.sh,
/// docs/explanation/accuracy-cost.md): the DOP unit for every k and format the RTL builds (those
/// in rtl/ are the same Verilog; the others are the same macro at another k; either DOP
/// rounding is a setup word's),
/// TRI_UNIT per format, and the decode stage of stored DOPs (one plane; a chip has 2k).
fn area_units() -> Vec<(String, Text)> {
    let mut units: Vec<(String, Text)> = vec![];
    for fmt in FORMATS.map(|f| f.fmt) {
        for k in crate::chip::config::SUPPORTED_K {
            units.push((
                dop_unit_name(k, fmt, 1),
                Box::new(move || {
                    dop_unit_verilog(k, fmt).expect("the RTL builds every supported k")
                }),
            ));
        }
    }
    for f in &FORMATS {
        let v = f.tri_unit;
        units.push((
            tri_unit_name(f.fmt, Rounding::NearestEven, 1),
            Box::new(move || v(Rounding::NearestEven)),
        ));
    }
    units.extend(area_fold_units());
    units.push((
        dop_decode_unit().name,
        Box::new(crate::rtl::b32::verilog_dop_decode),
    ));
    units
}

/// TRI_UNIT folded at every interval of the fold study (`AREA_TRI_FOLDS`) and the DOP unit
/// folded at every (k, interval) the RTL stamps out (`rtl::*::DOP_UNIT_FOLDS`), in both
/// formats.
fn area_fold_units() -> Vec<(String, Text)> {
    let mut units: Vec<(String, Text)> = vec![];
    for fmt in [Format::BINARY32, Format::REDUCED] {
        for ii in AREA_TRI_FOLDS {
            let v = if fmt == Format::BINARY32 {
                crate::rtl::b32::verilog_tri_unit_fold
            } else {
                crate::rtl::e8m15::verilog_tri_unit_fold
            };
            units.push((
                tri_unit_name(fmt, Rounding::NearestEven, ii as u32),
                Box::new(move || {
                    v(ii, Rounding::NearestEven).expect("the fold study's intervals fold")
                }),
            ));
        }
        for &(k, ii) in crate::rtl::b32::DOP_UNIT_FOLDS {
            units.push((
                dop_unit_name(k, fmt, ii as u32),
                Box::new(move || {
                    dop_unit_fold_verilog(ii, k, fmt).expect("the RTL stamps this fold")
                }),
            ));
        }
    }
    units
}

/// TRI_UNIT's pair intervals in the area study (`rtl::*::TriUnitFold`).
const AREA_TRI_FOLDS: [usize; 5] = [2, 4, 8, 16, 32];

/// Writes `<dir>/<unit>.v` for every unit of the area study; returns the paths written.
pub fn write_area_verilog(dir: &Path) -> std::io::Result<Vec<String>> {
    write_all(dir, "v", area_units(), verilog_of)
}

/// Writes `<dir>/<name>.<ext>` for each file, in parallel threads with stacks big enough for
/// the units (T.CHECK and TRI_UNIT are built on the stack, several MB).
fn write_all(
    dir: &Path,
    ext: &str,
    files: Vec<(String, Text)>,
    text: fn(&Text) -> String,
) -> std::io::Result<Vec<String>> {
    std::fs::create_dir_all(dir)?;
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let next = std::sync::atomic::AtomicUsize::new(0);
    let written = std::sync::Mutex::new((0..files.len()).map(|_| None).collect::<Vec<_>>());
    std::thread::scope(|s| {
        for _ in 0..threads {
            std::thread::Builder::new()
                .stack_size(1 << 30)
                .spawn_scoped(s, || loop {
                    let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    let Some((name, make)) = files.get(i) else {
                        break;
                    };
                    let p = dir.join(format!("{name}.{ext}"));
                    let res = std::fs::write(&p, text(make)).map(|_| p.display().to_string());
                    written.lock().unwrap()[i] = Some(res);
                })
                .expect("spawn a writer thread");
        }
    });
    written
        .into_inner()
        .unwrap()
        .into_iter()
        .map(|r| r.expect("every unit written"))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every exported unit is one top module of integer logic: no `real`, no float system
    /// functions (Icarus, Verilator and Yosys then prove the rest in scripts/check-rtl.sh),
    /// and its vectors name a latency equal to the unit's.
    #[test]
    fn exported_units_are_integer_logic() {
        let float = [
            "real",
            "shortreal",
            "$bitstoreal",
            "$realtobits",
            "$itor",
            "$rtoi",
        ];
        let units = std::thread::Builder::new()
            .stack_size(512 << 20) // the k = 24 DOP unit is built on the stack
            .spawn(|| {
                all()
                    .iter()
                    .map(|u| (u.name.clone(), u.latency, u.verilog(), u.vectors()))
                    .collect::<Vec<_>>()
            })
            .unwrap()
            .join()
            .unwrap();
        assert!(units.len() >= 13);
        for (name, latency, v, vec) in units {
            assert_eq!(v.matches("module top(").count(), 1, "{name}");
            for tok in v.split(|c: char| !(c.is_alphanumeric() || c == '_' || c == '$')) {
                assert!(!float.contains(&tok), "{name}: float construct {tok}");
            }
            assert!(vec.contains(&format!("// latency: {latency}\n")), "{name}");
        }
        // the chips as checked in (CI checks that rtl/ is what the code writes)
        for kind in crate::chip::rtl::ChipKind::ALL {
            let p = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("rtl/{}.v", kind.name()));
            let v = std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
            assert_eq!(v.matches("module top(").count(), 1, "{}", kind.name());
            for tok in v.split(|c: char| !(c.is_alphanumeric() || c == '_' || c == '$')) {
                assert!(
                    !float.contains(&tok),
                    "{}: float construct {tok}",
                    kind.name()
                );
            }
        }
    }
}
