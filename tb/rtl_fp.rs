//! RTL floating-point units (`collision_chip::rtl`) against the golden `Format` operations,
//! bit for bit: every unit, both formats (binary32, e8m15), both rounding modes
//! (NearestEven, TowardPositive), one operation per clock through the pipeline, fixed
//! latency checked on the `valid` bit. Also: a VCD per unit under `target/rtl-vcd/`,
//! (Verilog export and its checks: `harness::units`, scripts/check-rtl.sh.)

use collision_chip::format::{Format, Rounding};
use collision_chip::rtl::{b32, e8m10, e8m15};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, TestRunner};
use rust_hdl::prelude::*;
use std::time::Instant;

mod common;
use common::{operand, run, run_vcd, vcd_outputs, vcd_path, Fmt, Pipelined};

/// The FP units: inputs (a, b, sub), output y.
trait Unit: Pipelined<In = (u64, u64, bool), Out = u64> {}
impl<T: Pipelined<In = (u64, u64, bool), Out = u64>> Unit for T {}

const MODES: [Rounding; 2] = [Rounding::NearestEven, Rounding::TowardPositive];

#[derive(Clone, Copy, Debug, PartialEq)]
enum Op {
    Mul,
    Add,
    Sub,
}

macro_rules! impl_unit {
    ($t:ty, $lat:expr, $sub:ident) => {
        impl Pipelined for $t {
            type In = (u64, u64, bool);
            type Out = u64;
            const LATENCY: usize = $lat;
            fn set(&mut self, (a, b, sub): (u64, u64, bool), valid: bool) {
                self.a.next = a.into();
                self.b.next = b.into();
                impl_unit!(@sub $sub, self, sub);
                self.valid_in.next = valid;
            }
            fn out(&self) -> (bool, u64) {
                (self.valid_out.val(), self.y.val().to_u64())
            }
            fn clock(&mut self, high: bool) {
                self.clock.next = Clock { clk: high };
            }
        }
    };
    (@sub yes, $s:ident, $v:ident) => { $s.sub.next = $v; };
    (@sub no, $s:ident, $v:ident) => { assert!(!$v, "the multiplier has no sub input"); };
}

impl_unit!(b32::FpMul, 4, no);
impl_unit!(e8m15::FpMul, 4, no);
impl_unit!(e8m10::FpMul, 4, no);
impl_unit!(b32::FpAdd, 3, yes);
impl_unit!(e8m15::FpAdd, 3, yes);
impl_unit!(e8m10::FpAdd, 3, yes);
impl_unit!(b32::FpMulFpga, 6, no);
impl_unit!(e8m15::FpMulFpga, 6, no);
impl_unit!(e8m10::FpMulFpga, 6, no);
impl_unit!(b32::FpAddFpga, 6, yes);
impl_unit!(e8m15::FpAddFpga, 6, yes);
impl_unit!(e8m10::FpAddFpga, 6, yes);

fn golden(fmt: Format, op: Op, r: Rounding, a: u64, b: u64) -> u64 {
    let (x, y) = (fmt.from_bits(a), fmt.from_bits(b));
    fmt.to_bits(match op {
        Op::Mul => fmt.mul(x, y, r),
        Op::Add => fmt.add(x, y, r),
        Op::Sub => fmt.sub(x, y, r),
    })
}

/// Runs `pairs` through `uut` (each pair as add and sub for an adder) and compares every
/// output with the golden model. Returns the number of operations.
fn check<U: Unit>(
    uut: &mut U,
    fmt: Format,
    is_mul: bool,
    r: Rounding,
    pairs: &[(u64, u64)],
) -> Result<usize, TestCaseError> {
    let mut ops = Vec::with_capacity(2 * pairs.len());
    let mut kinds = Vec::with_capacity(2 * pairs.len());
    for &(a, b) in pairs {
        if is_mul {
            ops.push((a, b, false));
            kinds.push(Op::Mul);
        } else {
            ops.push((a, b, false));
            kinds.push(Op::Add);
            ops.push((a, b, true));
            kinds.push(Op::Sub);
        }
    }
    let outs = run(uut, &ops);
    let w = fmt.width() as usize;
    for (i, (&(a, b, _), &op)) in ops.iter().zip(&kinds).enumerate() {
        let want = golden(fmt, op, r, a, b);
        prop_assert_eq!(
            outs[i],
            want,
            "{} {:?} {:?}: a={:0w$x} b={:0w$x}: rtl {:0w$x}, golden {:0w$x}",
            fmt,
            op,
            r,
            a,
            b,
            outs[i],
            want,
            w = w / 4
        );
    }
    Ok(ops.len())
}

// ---------------------------------------------------------------------------------------
// Operand generators (bit patterns of a format with `e` exponent and `f` fraction bits).

/// Pairs for the multiplier: independent operands, and exponent sums placed at the
/// overflow and underflow (subnormal) thresholds.
fn mul_pair(t: Fmt) -> BoxedStrategy<(u64, u64)> {
    let bias = t.bias() as i64;
    let ones = t.ones() as i64;
    let f = t.f as i64;
    let frac = 0u64..(1 << t.f);
    prop_oneof![
        4 => (operand(t), operand(t)),
        3 => (any::<bool>(), any::<bool>(), 1..ones, frac.clone(), frac.clone(),
              prop_oneof![(ones - 3)..(ones + 2), (-f - 3)..3i64])
            .prop_map(move |(sa, sb, ea, fa, fb, target)| {
                // biased result exponent ea + eb - bias = target
                let eb = (target + bias - ea).clamp(0, ones - 1);
                (t.pack(sa, ea as u64, fa), t.pack(sb, eb as u64, fb))
            }),
    ]
    .boxed()
}

/// Pairs for the adder: independent operands, near-cancellation (b = a with a few low bits
/// changed), and alignment around the guard/round/sticky boundary (ties).
fn add_pair(t: Fmt) -> BoxedStrategy<(u64, u64)> {
    let f = t.f as u64;
    prop_oneof![
        4 => (operand(t), operand(t)),
        3 => (operand(t), 0u64..16, any::<bool>(), any::<bool>())
            .prop_map(move |(a, d, flip, up)| {
                let mag = a & ((1 << (t.e + t.f)) - 1);
                let m2 = if up { mag.wrapping_add(d) } else { mag.wrapping_sub(d) } & ((1 << (t.e + t.f)) - 1);
                let s = (a >> (t.e + t.f)) & 1 != 0;
                (a, t.pack(s ^ flip, m2 >> t.f, m2))
            }),
        3 => (any::<bool>(), any::<bool>(), 1..t.ones(), 0..(f + 6), 0u64..(1 << t.f),
              prop_oneof![Just(0u64), Just(1u64 << (t.f - 1)), 0u64..(1 << t.f), (0..t.f).prop_map(|i| 1u64 << i)])
            .prop_map(move |(sa, sb, ea, d, fa, fb)| {
                let eb = ea.saturating_sub(d);
                (t.pack(sa, ea, fa), t.pack(sb, eb, fb))
            }),
    ]
    .boxed()
}

// ---------------------------------------------------------------------------------------

/// Cases per unit, format and mode: `CASES` proptest cases of `BATCH` operand pairs.
const CASES: u32 = 24;
const BATCH: usize = 1000;

fn prop_unit<U: Unit>(make: impl Fn(Rounding) -> U, fmt: Format, is_mul: bool) {
    let t = Fmt::of(fmt);
    for r in MODES {
        let strat = prop::collection::vec(if is_mul { mul_pair(t) } else { add_pair(t) }, BATCH);
        let mut runner = TestRunner::new(Config {
            cases: CASES,
            failure_persistence: None,
            ..Config::default()
        });
        let ops = std::cell::Cell::new(0usize);
        let cycles = std::cell::Cell::new(0usize);
        let start = Instant::now();
        let res = runner.run(&strat, |pairs| {
            let mut uut = make(r);
            let n = check(&mut uut, fmt, is_mul, r, &pairs)?;
            ops.set(ops.get() + n);
            cycles.set(cycles.get() + n + U::LATENCY + 1);
            Ok(())
        });
        let dt = start.elapsed().as_secs_f64();
        if let Err(e) = res {
            panic!("{}", e);
        }
        println!(
            "{} {} {:?}: {} operations (incl. shrinking), {} cycles, {:.0} cycles/s",
            if is_mul { "FpMul" } else { "FpAdd" },
            fmt,
            r,
            ops.get(),
            cycles.get(),
            cycles.get() as f64 / dt
        );
    }
}

/// Every special / boundary operand against every other, per unit, format and mode.
fn specials_unit<U: Unit>(make: impl Fn(Rounding) -> U, fmt: Format, is_mul: bool) {
    let sp = Fmt::of(fmt).specials();
    let pairs: Vec<(u64, u64)> = sp
        .iter()
        .flat_map(|&a| sp.iter().map(move |&b| (a, b)))
        .collect();
    for r in MODES {
        let mut uut = make(r);
        let n = check(&mut uut, fmt, is_mul, r, &pairs).unwrap_or_else(|e| panic!("{}", e));
        println!(
            "{} {} {:?}: {} special operations ok",
            if is_mul { "FpMul" } else { "FpAdd" },
            fmt,
            r,
            n
        );
    }
}

/// The testbench sees a wrong result: an adder and a multiplier rounding to nearest,
/// checked against the golden TowardPositive, must fail on random operands.
#[test]
fn testbench_detects_mismatch() {
    let t = Fmt::of(Format::BINARY32);
    let mut runner = TestRunner::deterministic();
    let pairs = prop::collection::vec(add_pair(t), 200)
        .new_tree(&mut runner)
        .unwrap()
        .current();
    let mut uut = b32::fp_add_top(Rounding::NearestEven);
    assert!(check(
        &mut uut,
        Format::BINARY32,
        false,
        Rounding::TowardPositive,
        &pairs
    )
    .is_err());
    let pairs = prop::collection::vec(mul_pair(t), 200)
        .new_tree(&mut runner)
        .unwrap()
        .current();
    let mut uut = b32::fp_mul_top(Rounding::NearestEven);
    assert!(check(
        &mut uut,
        Format::BINARY32,
        true,
        Rounding::TowardPositive,
        &pairs
    )
    .is_err());
}

#[test]
fn mul_b32_random() {
    prop_unit(b32::fp_mul_top, Format::BINARY32, true);
}

#[test]
fn mul_e8m15_random() {
    prop_unit(e8m15::fp_mul_top, Format::REDUCED, true);
}

#[test]
fn mul_e8m10_random() {
    prop_unit(e8m10::fp_mul_top, Format::E8M10, true);
}

#[test]
fn add_b32_random() {
    prop_unit(b32::fp_add_top, Format::BINARY32, false);
}

#[test]
fn add_e8m15_random() {
    prop_unit(e8m15::fp_add_top, Format::REDUCED, false);
}

#[test]
fn add_e8m10_random() {
    prop_unit(e8m10::fp_add_top, Format::E8M10, false);
}

/// The units at FPGA depth: the same values, six clocks each.
#[test]
fn fpga_depth_random() {
    prop_unit(b32::fp_mul_fpga_top, Format::BINARY32, true);
    prop_unit(b32::fp_add_fpga_top, Format::BINARY32, false);
    prop_unit(e8m15::fp_mul_fpga_top, Format::REDUCED, true);
    prop_unit(e8m15::fp_add_fpga_top, Format::REDUCED, false);
    prop_unit(e8m10::fp_mul_fpga_top, Format::E8M10, true);
    prop_unit(e8m10::fp_add_fpga_top, Format::E8M10, false);
}

#[test]
fn fpga_depth_specials() {
    specials_unit(b32::fp_mul_fpga_top, Format::BINARY32, true);
    specials_unit(b32::fp_add_fpga_top, Format::BINARY32, false);
    specials_unit(e8m15::fp_mul_fpga_top, Format::REDUCED, true);
    specials_unit(e8m15::fp_add_fpga_top, Format::REDUCED, false);
    specials_unit(e8m10::fp_mul_fpga_top, Format::E8M10, true);
    specials_unit(e8m10::fp_add_fpga_top, Format::E8M10, false);
}

#[test]
fn specials_all_units() {
    specials_unit(b32::fp_mul_top, Format::BINARY32, true);
    specials_unit(e8m15::fp_mul_top, Format::REDUCED, true);
    specials_unit(b32::fp_add_top, Format::BINARY32, false);
    specials_unit(e8m15::fp_add_top, Format::REDUCED, false);
    specials_unit(e8m10::fp_mul_top, Format::E8M10, true);
    specials_unit(e8m10::fp_add_top, Format::E8M10, false);
}

/// A short traced run per unit (TowardPositive), for GTKWave: its results the golden
/// model's, and the VCD's `y` at each `valid_out` those results.
fn vcd_unit<U: Unit>(mut uut: U, name: &str, fmt: Format, ops: &[(u64, u64, bool)]) {
    let outs = run_vcd(&mut uut, ops, name, name);
    let is_mul = name.starts_with("fp_mul");
    let op = |sub| {
        if is_mul {
            Op::Mul
        } else if sub {
            Op::Sub
        } else {
            Op::Add
        }
    };
    let want: Vec<u64> = ops
        .iter()
        .map(|&(a, b, sub)| golden(fmt, op(sub), Rounding::TowardPositive, a, b))
        .collect();
    assert_eq!(outs, want, "{name}");
    assert_eq!(
        vcd_outputs(&vcd_path(name), name, "valid_out", "y"),
        want,
        "{name}.vcd: y at valid_out"
    );
}

#[test]
fn vcd_traces() {
    let one = 0x3f80_0000u64;
    let ops = [
        (one, one, false),
        (0x4049_0fdb, 0xc02d_f854, false),
        (0x0000_0001, 0x3f00_0000, false),
        (0x7f7f_ffff, 0x4000_0000, false),
        (0x7f80_0000, 0x0000_0000, false),
        (0x3f80_0001, 0x3f80_0000, true),
    ];
    let mul_ops: Vec<_> = ops.iter().map(|&(a, b, _)| (a, b, false)).collect();
    vcd_unit(
        b32::fp_mul_top(Rounding::TowardPositive),
        "fp_mul_b32",
        Format::BINARY32,
        &mul_ops,
    );
    vcd_unit(
        b32::fp_add_top(Rounding::TowardPositive),
        "fp_add_b32",
        Format::BINARY32,
        &ops,
    );
    let h = |x: u64| x >> 8; // the e8m15 word is the top 24 bits of the binary32 word
    let ops15: Vec<_> = ops.iter().map(|&(a, b, s)| (h(a), h(b), s)).collect();
    let mul15: Vec<_> = ops15.iter().map(|&(a, b, _)| (a, b, false)).collect();
    vcd_unit(
        e8m15::fp_mul_top(Rounding::TowardPositive),
        "fp_mul_e8m15",
        Format::REDUCED,
        &mul15,
    );
    vcd_unit(
        e8m15::fp_add_top(Rounding::TowardPositive),
        "fp_add_e8m15",
        Format::REDUCED,
        &ops15,
    );
}

/// Runs `ops` (operand, sel) through a constant multiplier one per clock and returns the
/// mismatches against `golden` (its result for each op), as messages.
fn scale_mismatches<U: Block>(
    uut: &mut U,
    set: impl Fn(&mut U, u64, bool),
    y: impl Fn(&U) -> u64,
    clock: impl Fn(&mut U, bool),
    ops: &[(u64, bool)],
    golden: impl Fn(u64, bool) -> u64,
) -> Vec<String> {
    const LATENCY: usize = 4;
    let mut bad = vec![];
    for cyc in 0..ops.len() + LATENCY - 1 {
        let (a, sel) = ops.get(cyc).copied().unwrap_or((0, false));
        set(uut, a, sel);
        for high in [false, true] {
            clock(uut, high);
            common::settle(uut);
        }
        if cyc + 1 >= LATENCY {
            let (a, sel) = ops[cyc + 1 - LATENCY];
            let (got, want) = (y(uut), golden(a, sel));
            if got != want {
                bad.push(format!("a={a:x} sel={sel}: rtl {got:x}, golden {want:x}"));
            }
        }
    }
    bad
}

/// Operands of a constant multiplier: every special pattern and 2,000 random ones (any
/// pattern, subnormals, values whose product lands near 2^emin), each with both `sel`s.
fn scale_ops(t: Fmt) -> Vec<(u64, bool)> {
    let mut runner = TestRunner::deterministic();
    let near_min =
        (any::<bool>(), 0..(1u64 << t.f), 1u64..40).prop_map(move |(s, f, e)| t.pack(s, e, f));
    let mut xs = t.specials();
    xs.extend(
        prop::collection::vec(prop_oneof![operand(t), near_min], 2000)
            .new_tree(&mut runner)
            .unwrap()
            .current(),
    );
    xs.iter().flat_map(|&a| [(a, false), (a, true)]).collect()
}

macro_rules! scale_test {
    ($name:ident, $m:ident, $fmt:expr) => {
        /// `FpScale` with each of T.CHECK's constant pairs against `Format::scale_up`; and
        /// the testbench sees a wrong constant (the pair swapped).
        #[test]
        fn $name() {
            let fmt = $fmt;
            let cert =
                collision_chip::golden::certificate::Certificate::new(fmt, Rounding::NearestEven);
            let ops = scale_ops(Fmt::of(fmt));
            let pairs = [cert.c_e, cert.c_z, [cert.c_s, cert.c_s]];
            for (i, c) in pairs.iter().enumerate() {
                let mut uut = $m::FpScale::new(c[0], c[1]);
                uut.clock.connect();
                uut.a.connect();
                uut.sel.connect();
                uut.connect_all();
                let golden = |c: [collision_chip::format::ScaleConst; 2]| {
                    move |a: u64, sel: bool| {
                        fmt.to_bits(fmt.scale_up(fmt.from_bits(a), c[sel as usize]))
                    }
                };
                let mut run = |g: &dyn Fn(u64, bool) -> u64| {
                    scale_mismatches(
                        &mut uut,
                        |u, a, sel| {
                            u.a.next = a.into();
                            u.sel.next = sel;
                        },
                        |u| u.y.val().to_u64(),
                        |u, high| u.clock.next = Clock { clk: high },
                        &ops,
                        g,
                    )
                };
                let bad = run(&golden(*c));
                assert!(
                    bad.is_empty(),
                    "{fmt} constants {c:?}: {} mismatches, first {:?}",
                    bad.len(),
                    &bad[..bad.len().min(5)]
                );
                if c[0] != c[1] {
                    assert!(
                        !run(&golden([c[1], c[0]])).is_empty(),
                        "pair {i}: a swapped constant went unnoticed"
                    );
                }
            }
            println!(
                "FpScale {fmt}: {} operations per constant pair ok",
                ops.len()
            );
        }
    };
}

scale_test!(scale_b32, b32, Format::BINARY32);
scale_test!(scale_e8m15, e8m15, Format::REDUCED);

impl Pipelined for b32::DopDecode {
    type In = (u64, u32, u32);
    type Out = u64;
    const LATENCY: usize = b32::DopDecode::LATENCY;
    fn set(&mut self, (r, q, ef): (u64, u32, u32), valid: bool) {
        self.r.next = r.into();
        self.q.next = (q as u64).into();
        self.ef.next = (ef as u64).into();
        self.valid_in.next = valid;
    }
    fn out(&self) -> (bool, u64) {
        (self.valid_out.val(), self.y.val().to_u64())
    }
    fn clock(&mut self, high: bool) {
        self.clock.next = Clock { clk: high };
    }
}

/// The decode stage of stored DOPs (`DopDecode`, 4-bit codes in binary32) against
/// `dop::stored::decode`: every code at every exponent from r = 0 (y is minus the step
/// itself), then random references; and the comparison sees a step one bit off (the code's
/// lowest bit flipped, the exponent one higher), as a stage off by one bit would give.
#[test]
fn decode_b32_q4() {
    use collision_chip::chip::layout::exp_range;
    use collision_chip::dop::stored::decode;
    let fmt = Format::BINARY32;
    let bits = b32::DopDecode::CODE_BITS as u32;
    let (lo, hi) = exp_range(fmt, bits);
    assert_eq!(
        b32::DopDecode::EXP_FIELD_BITS as u32,
        collision_chip::chip::layout::exp_field_bits(fmt, bits),
        "the stage's exponent field is the layout's"
    );
    let (top, efs) = ((1u32 << bits) - 1, (hi - lo) as u32);
    let mut ops: Vec<(u64, u32, u32)> = (0..=top)
        .flat_map(|q| (0..=efs).map(move |ef| (0, q, ef)))
        .collect();
    let mut runner = TestRunner::deterministic();
    let rand = prop::collection::vec((operand(Fmt::of(fmt)), 0..=top, 0..=efs), 2000);
    ops.extend(rand.new_tree(&mut runner).unwrap().current());
    // both roundings, each held (the chip's is a setup word's): the mixed-case order is the
    // exported vectors' (vectors/dop_decode_q4_b32.hex)
    for rnd in [Rounding::NearestEven, Rounding::TowardPositive] {
        let want = |(r, q, ef): (u64, u32, u32)| {
            fmt.to_bits(decode(fmt, rnd, fmt.from_bits(r), q, lo + ef as i32))
        };
        let mut uut = b32::dop_decode_top();
        uut.round_up.next = rnd == Rounding::TowardPositive;
        let got = run(&mut uut, &ops);
        let bad: Vec<_> = ops
            .iter()
            .zip(&got)
            .filter(|&(&op, &y)| y != want(op))
            .collect();
        assert!(
            bad.is_empty(),
            "{} mismatches, first {:?}",
            bad.len(),
            &bad[..bad.len().min(5)]
        );
        for off in [
            |(r, q, ef)| (r, q ^ 1, ef),
            |(r, q, ef): (u64, u32, u32)| (r, q, ef + 1),
        ] {
            let seen = ops
                .iter()
                .zip(&got)
                .filter(|&(&op, &y)| op.2 < efs && y != want(off(op)))
                .count();
            assert!(seen > 1000, "a step one bit off shows in only {seen} cases");
        }
        println!(
            "DopDecode binary32, 4-bit codes, {rnd:?}: {} decodes ok",
            ops.len()
        );
    }
}

macro_rules! cmp_pipelined {
    ($($m:ident),*) => {$(
        impl Pipelined for $m::FpCmp {
            type In = (u64, u64);
            type Out = bool;
            const LATENCY: usize = $m::FpCmp::LATENCY;
            fn set(&mut self, (a, b): (u64, u64), valid: bool) {
                self.a.next = a.into();
                self.b.next = b.into();
                self.valid_in.next = valid;
            }
            fn out(&self) -> (bool, bool) {
                (self.valid_out.val(), self.flag.val())
            }
            fn clock(&mut self, high: bool) {
                self.clock.next = Clock { clk: high };
            }
        }
    )*};
}
cmp_pipelined!(b32, e8m15, e8m10);

/// Compare-unit operands: every pair of special patterns, and 3,000 random pairs, a third
/// of them with `b` at `-a` or one ulp from it (where the sum's sign turns).
fn cmp_ops(t: Fmt) -> Vec<(u64, u64)> {
    let fmt = t.fmt;
    let sp = t.specials();
    let mut ops: Vec<(u64, u64)> = sp
        .iter()
        .flat_map(|&a| sp.iter().map(move |&b| (a, b)))
        .collect();
    let mut runner = TestRunner::deterministic();
    let pairs = prop::collection::vec((operand(t), operand(t), 0u8..6), 3000);
    for (a, b, near) in pairs.new_tree(&mut runner).unwrap().current() {
        let x = -fmt.from_bits(a);
        let b = match near {
            0 if !x.is_nan() => fmt.to_bits(x),
            1 if !x.is_nan() => fmt.to_bits(fmt.next_up(x)),
            2 if !x.is_nan() => fmt.to_bits(fmt.next_down(x)),
            _ => b,
        };
        ops.push((a, b));
    }
    ops
}

/// WSCG'03's compare unit (`FpCmp`) against two references: the golden `separated` (an
/// exact comparison in f64) and the sign of the lane's rounded sum `round(a + b) < 0` in
/// both roundings, which the comparison stands for. And the testbench sees a unit that
/// took `a + b <= 0` (a zero sum flagged).
fn cmp_unit<U: Pipelined<In = (u64, u64), Out = bool>>(mut uut: U, fmt: Format) {
    use collision_chip::golden::doptrf::separated;
    let q = fmt.min_positive_subnormal();
    let ops = cmp_ops(Fmt::of(fmt));
    let got = run(&mut uut, &ops);
    let x = |a: u64| fmt.from_bits(a);
    let bad: Vec<_> = ops
        .iter()
        .zip(&got)
        .filter(|&(&(a, b), &g)| {
            let want = separated(q, x(a), x(b));
            let rounded = MODES.map(|r| fmt.add(x(a), x(b), r) < 0.0);
            g != want || rounded.iter().any(|&s| s != want)
        })
        .collect();
    assert!(
        bad.is_empty(),
        "{fmt}: {} mismatches, first {:?}",
        bad.len(),
        &bad[..bad.len().min(5)]
    );
    let le_zero = |&(a, b): &(u64, u64)| {
        let s = x(a) + x(b);
        s <= 0.0 && !(x(a).is_infinite() && x(b).is_infinite())
    };
    let seen = ops.iter().zip(&got).any(|(op, &g)| g != le_zero(op));
    assert!(seen, "{fmt}: a unit flagging a zero sum went unnoticed");
    println!("FpCmp {fmt}: {} pairs ok", ops.len());
}

#[test]
fn cmp_all_formats() {
    cmp_unit(b32::fp_cmp_top(), Format::BINARY32);
    cmp_unit(e8m15::fp_cmp_top(), Format::REDUCED);
    cmp_unit(e8m10::fp_cmp_top(), Format::E8M10);
}
