//! T.CHECK's bound arithmetic in RTL (`BoundAdd`, `BoundMul`, `RoundErr` of
//! `collision_chip::rtl::{b32, e8m15}`) against the golden `golden::tcheck::{bound_add,
//! bound_mul, rounding_error}`, bit for bit: both formats, one operation per clock through
//! the pipeline, fixed latency checked on the `valid` bit. Bound operands are non-negative
//! format values (zeros, subnormals, the largest finite, +inf, NaN included); the units are
//! also bit-exact on negative words, which the all-specials test includes.

use collision_chip::format::{Format, Rounding};
use collision_chip::golden::tcheck::{bound_add, bound_mul, rounding_error};
use collision_chip::rtl::{b32, e8m15};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, TestRunner};
use rust_hdl::prelude::*;

mod common;
use common::{operand, run, Fmt, Pipelined};

/// The bound units: inputs (a, b) (RoundErr reads a as x), output y.
trait Unit: Pipelined<In = (u64, u64), Out = u64> {}
impl<T: Pipelined<In = (u64, u64), Out = u64>> Unit for T {}

/// One pipelined unit as the testbench drives it (`b` is ignored by `RoundErr`).
macro_rules! impl_unit {
    ($t:ty, $lat:expr, two) => {
        impl_unit!(@impl $t, $lat, |s: &mut $t, a: u64, b: u64| { s.a.next = a.into(); s.b.next = b.into(); });
    };
    ($t:ty, $lat:expr, one) => {
        impl_unit!(@impl $t, $lat, |s: &mut $t, a: u64, _b: u64| { s.x.next = a.into(); });
    };
    (@impl $t:ty, $lat:expr, $drive:expr) => {
        impl Pipelined for $t {
            type In = (u64, u64);
            type Out = u64;
            const LATENCY: usize = $lat;
            fn set(&mut self, (a, b): (u64, u64), valid: bool) {
                ($drive)(self, a, b);
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
}

impl_unit!(b32::BoundAdd, 4, two);
impl_unit!(e8m15::BoundAdd, 4, two);
impl_unit!(b32::BoundMul, 5, two);
impl_unit!(e8m15::BoundMul, 5, two);
impl_unit!(b32::RoundErr, 1, one);
impl_unit!(e8m15::RoundErr, 1, one);
// The plain adder, as a wrong bound adder.
impl_unit!(b32::FpAdd, 3, two);


/// A golden operation on words.
type Golden = Box<dyn Fn(u64, u64) -> u64>;

fn golden_add(fmt: Format) -> Golden {
    Box::new(move |a, b| fmt.to_bits(bound_add(fmt, fmt.from_bits(a), fmt.from_bits(b))))
}

fn golden_mul(fmt: Format) -> Golden {
    Box::new(move |a, b| fmt.to_bits(bound_mul(fmt, fmt.from_bits(a), fmt.from_bits(b))))
}

fn golden_err(fmt: Format, r: Rounding) -> Golden {
    Box::new(move |x, _| fmt.to_bits(rounding_error(fmt, r, fmt.from_bits(x))))
}

/// Runs `ops` through `uut` and compares every output with `golden`.
fn check<U: Unit>(uut: &mut U, fmt: Format, golden: &Golden, ops: &[(u64, u64)]) -> Result<usize, TestCaseError> {
    let outs = run(uut, ops);
    let w = (fmt.width() as usize).div_ceil(4);
    for (&(a, b), &y) in ops.iter().zip(&outs) {
        let want = golden(a, b);
        prop_assert_eq!(y, want, "{}: a={:0w$x} b={:0w$x}: rtl {:0w$x}, golden {:0w$x}", fmt, a, b, y, want, w = w);
    }
    Ok(ops.len())
}

/// A non-negative operand (a bound): `operand` with the sign cleared.
fn bound(t: Fmt) -> BoxedStrategy<u64> {
    let sign = 1u64 << (t.e + t.f);
    operand(t).prop_map(move |x| x & !sign).boxed()
}

/// Bound pairs: independent, one equal to the other (ties, binade steps), and pairs whose
/// exact sum / product lands near the overflow threshold or the smallest normal m.
fn pair(t: Fmt, mul: bool) -> BoxedStrategy<(u64, u64)> {
    let bias = t.bias() as i64;
    let ones = t.ones() as i64;
    let f = t.f as i64;
    let frac = 0u64..(1 << t.f);
    let near = prop_oneof![(ones - 3)..(ones + 2), (-f - 3)..3i64];
    prop_oneof![
        5 => (bound(t), bound(t)),
        1 => bound(t).prop_map(|a| (a, a)),
        3 => (1..ones, frac.clone(), frac, near).prop_map(move |(ea, fa, fb, target)| {
            // mul: biased result exponent ea + eb - bias = target; add: eb = target
            let eb = if mul { (target + bias - ea).clamp(0, ones - 1) } else { target.clamp(0, ones - 1) };
            let ea = if mul { ea } else { (target + ea % 3 - 1).clamp(0, ones - 1) };
            (t.pack(false, ea as u64, fa), t.pack(false, eb as u64, fb))
        }),
    ]
    .boxed()
}

/// Cases per unit and format: `CASES` proptest cases of `BATCH` operand pairs.
const CASES: u32 = 32;
const BATCH: usize = 1000;

fn prop_unit<U: Unit>(name: &str, make: impl Fn() -> U, fmt: Format, mul: bool) {
    let strat = prop::collection::vec(pair(Fmt::of(fmt), mul), BATCH);
    let golden = if mul { golden_mul(fmt) } else { golden_add(fmt) };
    let mut runner = TestRunner::new(Config { cases: CASES, failure_persistence: None, ..Config::default() });
    let ops = std::cell::Cell::new(0usize);
    // coverage of the step-up-and-floor cases: results +inf, m, above m; NaN operands
    let t = Fmt::of(fmt);
    let (inf, m) = (t.pack(false, t.ones(), 0), t.pack(false, 1, 0));
    let nan = |x: u64| x >> t.f & t.ones() == t.ones() && x & ((1 << t.f) - 1) != 0;
    let seen = std::cell::Cell::new([0usize; 4]);
    let res = runner.run(&strat, |pairs| {
        ops.set(ops.get() + check(&mut make(), fmt, &golden, &pairs)?);
        let mut c = seen.get();
        for &(a, b) in &pairs {
            let y = golden(a, b);
            c[if nan(a) || nan(b) { 3 } else if y == inf { 0 } else if y == m { 1 } else { 2 }] += 1;
        }
        seen.set(c);
        Ok(())
    });
    if let Err(e) = res {
        panic!("{e}");
    }
    let c = seen.get();
    println!("{name} {fmt}: {} operations ok (results +inf {}, m {}, above m {}; NaN operand {})", ops.get(), c[0], c[1], c[2], c[3]);
    assert!(c.iter().all(|&k| k > 0), "coverage: {c:?}");
}

/// Every special / boundary pattern of the format (negative ones included) against every
/// other.
fn specials_unit<U: Unit>(name: &str, mut uut: U, fmt: Format, mul: bool) {
    let sp = Fmt::of(fmt).specials();
    let pairs: Vec<(u64, u64)> = sp.iter().flat_map(|&a| sp.iter().map(move |&b| (a, b))).collect();
    let golden = if mul { golden_mul(fmt) } else { golden_add(fmt) };
    let n = check(&mut uut, fmt, &golden, &pairs).unwrap_or_else(|e| panic!("{e}"));
    println!("{name} {fmt}: {n} special operations ok");
}

#[test]
fn bound_add_b32_random() {
    prop_unit("BoundAdd", b32::bound_add_top, Format::BINARY32, false);
}

#[test]
fn bound_add_e8m15_random() {
    prop_unit("BoundAdd", e8m15::bound_add_top, Format::REDUCED, false);
}

#[test]
fn bound_mul_b32_random() {
    prop_unit("BoundMul", b32::bound_mul_top, Format::BINARY32, true);
}

#[test]
fn bound_mul_e8m15_random() {
    prop_unit("BoundMul", e8m15::bound_mul_top, Format::REDUCED, true);
}

#[test]
fn bound_specials() {
    specials_unit("BoundAdd", b32::bound_add_top(), Format::BINARY32, false);
    specials_unit("BoundAdd", e8m15::bound_add_top(), Format::REDUCED, false);
    specials_unit("BoundMul", b32::bound_mul_top(), Format::BINARY32, true);
    specials_unit("BoundMul", e8m15::bound_mul_top(), Format::REDUCED, true);
}

/// The words RoundErr is checked on: every exponent field, both signs, with fractions 0, 1,
/// the largest and a few random ones (the result depends on the exponent field and, for the
/// all-ones field, on whether the fraction is zero), plus random words.
fn round_err_words(fmt: Format) -> Vec<(u64, u64)> {
    let t = Fmt::of(fmt);
    let mut runner = TestRunner::deterministic();
    let mut words = vec![];
    for s in [false, true] {
        for e in 0..=t.ones() {
            for fr in [0, 1, (1 << t.f) - 1, 1 << (t.f - 1)] {
                words.push((t.pack(s, e, fr), 0));
            }
        }
    }
    let random = prop::collection::vec(operand(t), 4000).new_tree(&mut runner).unwrap().current();
    words.extend(random.into_iter().map(|x| (x, 0)));
    words
}

fn round_err_unit<U: Unit>(make: impl Fn(Rounding) -> U, fmt: Format) {
    for r in [Rounding::NearestEven, Rounding::TowardPositive] {
        let words = round_err_words(fmt);
        let n = check(&mut make(r), fmt, &golden_err(fmt, r), &words).unwrap_or_else(|e| panic!("{e}"));
        println!("RoundErr {fmt} {r:?}: {n} words ok");
    }
}

#[test]
fn round_err_all_exponents() {
    round_err_unit(b32::round_err_top, Format::BINARY32);
    round_err_unit(e8m15::round_err_top, Format::REDUCED);
}

/// The testbench sees a wrong unit: the plain adder (no step-up, no floor) as a bound adder,
/// a bound adder as a bound multiplier, and a bound multiplier against a golden without the
/// step-up; a RoundErr for directed results against the nearest-even golden.
#[test]
fn testbench_detects_mismatch() {
    let fmt = Format::BINARY32;
    let t = Fmt::of(fmt);
    let mut runner = TestRunner::deterministic();
    let pairs = prop::collection::vec(pair(t, false), 200).new_tree(&mut runner).unwrap().current();
    assert!(check(&mut b32::fp_add_top(Rounding::NearestEven), fmt, &golden_add(fmt), &pairs).is_err());
    assert!(check(&mut b32::bound_add_top(), fmt, &golden_mul(fmt), &pairs).is_err());
    let no_step: Golden = Box::new(move |a, b| {
        let y = fmt.mul(fmt.from_bits(a), fmt.from_bits(b), Rounding::NearestEven);
        fmt.to_bits(y.max(fmt.min_positive_normal()))
    });
    let pairs = prop::collection::vec(pair(t, true), 200).new_tree(&mut runner).unwrap().current();
    assert!(check(&mut b32::bound_mul_top(), fmt, &no_step, &pairs).is_err());
    let words = round_err_words(fmt);
    let wrong = golden_err(fmt, Rounding::NearestEven);
    assert!(check(&mut b32::round_err_top(Rounding::TowardPositive), fmt, &wrong, &words).is_err());
    // and the right ones pass on the same operands
    assert!(check(&mut b32::bound_mul_top(), fmt, &golden_mul(fmt), &pairs).is_ok());
    assert!(check(&mut b32::round_err_top(Rounding::NearestEven), fmt, &wrong, &words).is_ok());
}
