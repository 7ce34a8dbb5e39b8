//! Tests of `format` against `rustc_apfloat` (independent soft-float), native `f32`,
//! and exhaustive checks of tiny formats.

use super::*;
use proptest::prelude::*;
use rustc_apfloat::ieee::{Double, Half, IeeeFloat, Semantics, Single};
use rustc_apfloat::{Float, FloatConvert, Round};

// ---------------------------------------------------------------------------
// apfloat semantics of the non-standard formats
// ---------------------------------------------------------------------------

/// apfloat semantics for a format with `$bits` bits of which `$exp` are exponent.
macro_rules! semantics {
    ($($(#[$doc:meta])* $name:ident = ($bits:expr, $exp:expr);)*) => {$(
        $(#[$doc])*
        struct $name;
        impl Semantics for $name {
            const BITS: usize = $bits;
            const EXP_BITS: usize = $exp;
        }
    )*};
}

semantics! {
    /// e8m15 (the chip's reduced format).
    E8M15S = (24, 8);
    /// e9m24, the largest allowed format.
    E9M24S = (34, 9);
    /// e4m3 with IEEE inf/NaN (unlike apfloat's Float8E4M3FN).
    E4M3S = (8, 4);
    E3M2S = (6, 3);
    E2M1S = (4, 2);
    E2M3S = (6, 2);
}

const MODES: [Rounding; 3] = [
    Rounding::NearestEven,
    Rounding::TowardPositive,
    Rounding::TowardNegative,
];

fn ap_round(r: Rounding) -> Round {
    match r {
        Rounding::NearestEven => Round::NearestTiesToEven,
        Rounding::TowardPositive => Round::TowardPositive,
        Rounding::TowardNegative => Round::TowardNegative,
    }
}

fn fmt_of<S: Semantics>() -> Format {
    Format::new(S::EXP_BITS as u32, (S::BITS - 1 - S::EXP_BITS) as u32).unwrap()
}

/// Exact conversion f64 -> apfloat format (through apfloat's own Double decoding).
fn to_ap<S: Semantics>(x: f64) -> IeeeFloat<S>
where
    Double: FloatConvert<IeeeFloat<S>>,
{
    let mut loses = false;
    let v: IeeeFloat<S> = Double::from_bits(x.to_bits() as u128)
        .convert_r(Round::NearestTiesToEven, &mut loses)
        .value;
    assert!(
        x.is_nan() || !loses,
        "operand {x:e} not exact in the apfloat format"
    );
    v
}

/// Compares our result with apfloat's: bits for non-NaN, is-NaN for NaN.
fn same<S: Semantics>(fmt: Format, mine: f64, theirs: IeeeFloat<S>) -> Result<(), String> {
    if theirs.is_nan() {
        return if mine.is_nan() {
            Ok(())
        } else {
            Err(format!("expected NaN, got {mine:e}"))
        };
    }
    if mine.is_nan() {
        return Err(format!("got NaN, expected bits {:#x}", theirs.to_bits()));
    }
    if !fmt.is_representable(mine) {
        return Err(format!("result {mine:e} not representable"));
    }
    let want = theirs.to_bits() as u64;
    let got = fmt.to_bits(mine);
    if got != want {
        return Err(format!(
            "bits {got:#x} ({mine:e}) != apfloat {want:#x} ({:e})",
            fmt.from_bits(want)
        ));
    }
    // from_bits must give back exactly our f64 (incl. zero sign).
    if fmt.from_bits(want).to_bits() != mine.to_bits() {
        return Err(format!("from_bits({want:#x}) != {mine:e}"));
    }
    Ok(())
}

fn check_add_sub<S: Semantics>(fmt: Format, a: f64, b: f64) -> Result<(), String>
where
    Double: FloatConvert<IeeeFloat<S>>,
{
    let (x, y) = (to_ap::<S>(a), to_ap::<S>(b));
    for r in MODES {
        let ctx = |e: String| format!("{fmt} {r:?}: {a:e} ± {b:e}: {e}");
        same(fmt, fmt.add(a, b, r), x.add_r(y, ap_round(r)).value)
            .map_err(|e| ctx(format!("add {e}")))?;
        same(fmt, fmt.sub(a, b, r), x.sub_r(y, ap_round(r)).value)
            .map_err(|e| ctx(format!("sub {e}")))?;
        // The general (TwoSum) path must agree too, also where a fast path exists.
        same(fmt, fmt.add_general(a, b, r), x.add_r(y, ap_round(r)).value)
            .map_err(|e| ctx(format!("add_general {e}")))?;
    }
    Ok(())
}

fn check_mul<S: Semantics>(fmt: Format, a: f64, b: f64) -> Result<(), String>
where
    Double: FloatConvert<IeeeFloat<S>>,
{
    let (x, y) = (to_ap::<S>(a), to_ap::<S>(b));
    for r in MODES {
        let want = x.mul_r(y, ap_round(r)).value;
        let ctx = |e: String| format!("{fmt} {r:?}: {a:e} * {b:e}: {e}");
        same(fmt, fmt.mul(a, b, r), want).map_err(|e| ctx(format!("mul {e}")))?;
        same(fmt, fmt.mul_general(a, b, r), want).map_err(|e| ctx(format!("mul_general {e}")))?;
    }
    Ok(())
}

fn check_round<S: Semantics>(fmt: Format, x: f64) -> Result<(), String>
where
    Double: FloatConvert<IeeeFloat<S>>,
{
    let d = Double::from_bits(x.to_bits() as u128);
    for r in MODES {
        let mut loses = false;
        let want: IeeeFloat<S> = d.convert_r(ap_round(r), &mut loses).value;
        let ctx = |e: String| format!("{fmt} {r:?}: round({x:e} = {:#x}): {e}", x.to_bits());
        same(fmt, fmt.round(x, r), want).map_err(&ctx)?;
        same(fmt, fmt.round_general(x, r), want).map_err(|e| ctx(format!("general {e}")))?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// Generators favouring hard cases. Raw random words are turned into format values
// by bit construction (so every operand is representable by construction).
// ---------------------------------------------------------------------------

/// Value with the given sign, unbiased exponent `e` (may be below emin: then the
/// significand is shifted into the subnormal range) and fraction bits `sig`.
fn mk(fmt: Format, neg: bool, e: i32, sig: u64) -> f64 {
    let f = fmt.frac_bits();
    let emin = 1 - fmt.bias();
    let e = e.min(fmt.bias());
    let mask = (1u64 << f) - 1;
    let bits = if e >= emin {
        (((e + fmt.bias()) as u64) << f) | (sig & mask)
    } else {
        let sh = (emin - e) as u32;
        if sh > f {
            1 // smallest subnormal
        } else {
            ((sig & mask) | (1u64 << f)) >> sh
        }
    };
    fmt.from_bits(((neg as u64) << (fmt.width() - 1)) | bits)
}

fn exp_field(fmt: Format, x: f64) -> i64 {
    ((fmt.to_bits(x) >> fmt.frac_bits()) & ((1u64 << fmt.exp_bits()) - 1)) as i64
}

/// One operand: random patterns, specials, subnormals, extreme exponents.
fn value(fmt: Format, kind: u32, w: u64) -> f64 {
    let f = fmt.frac_bits();
    let ones = (1u64 << fmt.exp_bits()) - 1;
    let sign = (w >> 63) << (fmt.width() - 1);
    let frac = w & ((1u64 << f) - 1);
    let pick = |n: u64| (w >> 40) % n;
    match kind % 8 {
        0..=3 => fmt.from_bits(w & ((1u64 << fmt.width()) - 1)),
        4 => {
            let largest_subnormal = fmt.min_positive_normal() - fmt.min_positive_subnormal();
            [
                0.0,
                -0.0,
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::NAN,
                fmt.max_finite(),
                -fmt.max_finite(),
                fmt.min_positive_subnormal(),
                -fmt.min_positive_normal(),
                1.0,
                -1.0,
                largest_subnormal,
            ][pick(12) as usize]
        }
        5 => fmt.from_bits(sign | frac), // subnormal or zero
        6 => {
            // extreme exponent fields: 1, 2, max-2, max-1
            let ef =
                [1, 2.min(ones - 1), ones.saturating_sub(2).max(1), ones - 1][pick(4) as usize];
            fmt.from_bits(sign | (ef << f) | frac)
        }
        _ => {
            // fraction patterns near all-zeros / all-ones
            let fr = [0, 1, (1u64 << f) - 1, (1u64 << f) - 2, 1u64 << (f - 1)][pick(5) as usize];
            let ef = (w >> 20) % (ones + 1);
            fmt.from_bits(sign | (ef << f) | fr)
        }
    }
}

fn finite(fmt: Format, x: f64, w: u64) -> f64 {
    if x.is_finite() {
        x
    } else {
        mk(fmt, w & 1 == 1, ((w >> 8) % 5) as i32, w >> 16)
    }
}

/// Operand pair for add/sub.
fn add_pair(fmt: Format, kind: u32, w1: u64, w2: u64) -> (f64, f64) {
    let f = fmt.frac_bits() as i64;
    let ones = (1i64 << fmt.exp_bits()) - 1;
    match kind % 6 {
        0 | 1 => (
            value(fmt, (w1 >> 3) as u32, w1),
            value(fmt, (w2 >> 3) as u32, w2),
        ),
        2 => {
            // b about half an ulp of a (ties and near-ties), either sign
            let a = finite(fmt, value(fmt, (w1 >> 3) as u32, w1), w1);
            let ea = exp_field(fmt, a).max(1);
            let d = (w2 % 5) as i64 - 2;
            let eb = (ea - f - 1 + d).clamp(0, ones - 1) as u64;
            let fr = match (w2 >> 3) % 4 {
                0 => 0,
                1 => 1,
                2 => (1u64 << f) - 1,
                _ => w2 >> 8,
            } & ((1u64 << f) - 1);
            let b = fmt.from_bits(((w2 >> 63) << (fmt.width() - 1)) | (eb << f) | fr);
            if w2 & 4 == 0 {
                (a, b)
            } else {
                (b, a)
            }
        }
        3 => {
            // cancellation: b = -(a +- k codes)
            let a = finite(fmt, value(fmt, (w1 >> 3) as u32, w1), w1);
            let k = (w2 % 9) as i64 - 4;
            let bits = fmt.to_bits(a) as i64 + k;
            let max_code = fmt.to_bits(fmt.max_finite()) as i64;
            let sign = fmt.to_bits(a) & (1u64 << (fmt.width() - 1));
            let mag = (bits - sign as i64).clamp(0, max_code) as u64;
            (a, -fmt.from_bits(sign | mag))
        }
        4 => {
            // same or nearby binades, random fractions, both signs
            let ea = (w1 >> 40) as i64 % (ones + 1);
            let eb = (ea + (w2 >> 40) as i64 % (f + 6) - (f + 6) / 2).clamp(0, ones);
            let m = (1u64 << f) - 1;
            let a =
                fmt.from_bits(((w1 >> 63) << (fmt.width() - 1)) | ((ea as u64) << f) | (w1 & m));
            let b =
                fmt.from_bits(((w2 >> 63) << (fmt.width() - 1)) | ((eb as u64) << f) | (w2 & m));
            (a, b)
        }
        _ => {
            // sums near overflow: both near max_finite
            let e = fmt.bias() - (w1 % 3) as i32;
            let a = mk(
                fmt,
                w1 >> 63 == 1,
                e,
                w1 >> 4 | if w1 & 8 != 0 { u64::MAX } else { 0 },
            );
            let b = mk(
                fmt,
                w2 >> 63 == 1,
                e - (w2 % (f as u64 + 3)) as i32,
                w2 >> 4,
            );
            (a, b)
        }
    }
}

/// Operand pair for mul: random, products near overflow and near underflow.
fn mul_pair(fmt: Format, kind: u32, w1: u64, w2: u64) -> (f64, f64) {
    let f = fmt.frac_bits() as i32;
    let emax = fmt.bias();
    let emin = 1 - emax;
    let (n1, n2) = (w1 >> 63 == 1, w2 >> 63 == 1);
    match kind % 5 {
        0 | 1 => (
            value(fmt, (w1 >> 3) as u32, w1),
            value(fmt, (w2 >> 3) as u32, w2),
        ),
        2 => {
            // ea + eb in [emax - 2, emax + 1]
            let s = emax - 2 + (w1 % 4) as i32;
            let ea = emin - f + ((w2 >> 32) % (emax - emin + f + 1) as u64) as i32;
            let eb = s - ea;
            (mk(fmt, n1, ea, w1 >> 3), mk(fmt, n2, eb, w2 >> 3))
        }
        3 => {
            // ea + eb around the subnormal range [emin - f - 3, emin + 1]
            let s = emin - f - 3 + ((w1 >> 3) % (f as u64 + 5)) as i32;
            let ea = emin - f + ((w2 >> 32) % (emax - emin + f + 1) as u64) as i32;
            let eb = s - ea;
            (mk(fmt, n1, ea, w1 >> 8), mk(fmt, n2, eb, w2 >> 8))
        }
        _ => {
            // short significands: exact products, ties from few bits
            let sh = f as u32 - ((w1 >> 20) % (f as u64 + 1)) as u32;
            let a = value(fmt, 0, w1 & !((1u64 << sh) - 1));
            let b = value(
                fmt,
                0,
                w2 & !((1u64 << sh) - 1) | ((w2 >> 62) << fmt.frac_bits()),
            );
            (a, b)
        }
    }
}

/// Arbitrary f64 for `round`: raw bits, near format values and midpoints, overflow
/// threshold, subnormal range, f64 subnormals.
fn round_input(fmt: Format, kind: u32, w1: u64, w2: u64) -> f64 {
    let f = fmt.frac_bits();
    let emax = fmt.bias();
    let emin = 1 - emax;
    let neg = (w2 >> 63) << 63;
    match kind % 6 {
        0 => f64::from_bits(w1),
        1 | 2 => {
            // near a format value: +- up to 2 ulps (in f64 bit units), midpoints exact
            let v = finite(fmt, value(fmt, (w1 >> 3) as u32, w1), w1).abs();
            let v = if v == 0.0 {
                fmt.min_positive_subnormal()
            } else {
                v
            };
            let u = fmt.ulp(v);
            let x = match (w2 >> 1) % 4 {
                0 => v + u * 0.5,
                1 => v - u * 0.25, // below a power of two this is the midpoint
                2 => v + u * 0.5 * (1.0 + f64::EPSILON * (((w2 >> 8) % 5) as f64 - 2.0)),
                _ => {
                    let span = 1i64 << (53 - f);
                    let off = (w2 >> 10) as i64 % (2 * span + 1) - span;
                    f64::from_bits((v.to_bits() as i64 + off) as u64)
                }
            };
            f64::from_bits(x.to_bits() | neg)
        }
        3 => {
            // log-uniform over the format's range plus margins, random 52-bit mantissa
            let e = emin - f as i32 - 4 + ((w2 >> 8) % (emax - emin + f as i32 + 8) as u64) as i32;
            f64::from_bits(neg | (((e + 1023) as u64) << 52) | (w1 >> 12))
        }
        4 => {
            // around the overflow threshold max + ulp/2 and around 2^(emax+1)
            let m = fmt.max_finite();
            let u = fmt.ulp(m);
            let base = [m, m + u * 0.5, m + u, m - u * 0.5][(w2 % 4) as usize];
            let off = (w1 % 2001) as i64 - 1000;
            f64::from_bits((base.to_bits() as i64 + off) as u64 | neg)
        }
        _ => {
            // tiny: around min subnormal / 2, f64 subnormals
            let s = fmt.min_positive_subnormal();
            let base = [s * 0.5, s, s * 1.5, 2.0f64.powi(-1074)][(w2 % 4) as usize];
            let off = (w1 % 2001) as i64 - 1000;
            f64::from_bits(((base.to_bits() as i64 + off).max(0) as u64) | neg)
        }
    }
}

/// Random cases per (format, operation); every case checks all three modes.
const CASES: u32 = 20_000;

fn cfg() -> ProptestConfig {
    ProptestConfig {
        cases: CASES,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

macro_rules! apfloat_suite {
    ($name:ident, $S:ty) => {
        mod $name {
            use super::*;
            proptest! {
                #![proptest_config(cfg())]
                #[test]
                fn add_sub(kind in any::<u32>(), w1 in any::<u64>(), w2 in any::<u64>()) {
                    let fmt = fmt_of::<$S>();
                    let (a, b) = add_pair(fmt, kind, w1, w2);
                    if let Err(e) = check_add_sub::<$S>(fmt, a, b) { return Err(TestCaseError::fail(e)); }
                }
                #[test]
                fn mul(kind in any::<u32>(), w1 in any::<u64>(), w2 in any::<u64>()) {
                    let fmt = fmt_of::<$S>();
                    let (a, b) = mul_pair(fmt, kind, w1, w2);
                    if let Err(e) = check_mul::<$S>(fmt, a, b) { return Err(TestCaseError::fail(e)); }
                }
                #[test]
                fn round(kind in any::<u32>(), w1 in any::<u64>(), w2 in any::<u64>()) {
                    let fmt = fmt_of::<$S>();
                    let x = round_input(fmt, kind, w1, w2);
                    if let Err(e) = check_round::<$S>(fmt, x) { return Err(TestCaseError::fail(e)); }
                }
            }
        }
    };
}

apfloat_suite!(apfloat_binary32, rustc_apfloat::ieee::SingleS);
apfloat_suite!(apfloat_e8m15, E8M15S);
apfloat_suite!(apfloat_e5m10, rustc_apfloat::ieee::HalfS);
apfloat_suite!(apfloat_e4m3, E4M3S);
apfloat_suite!(apfloat_e9m24, E9M24S);

#[test]
fn semantics_match_named_formats() {
    assert_eq!(fmt_of::<rustc_apfloat::ieee::SingleS>(), Format::BINARY32);
    assert_eq!(fmt_of::<E8M15S>(), Format::REDUCED);
    // apfloat's exponent conventions are the ones documented in the module.
    assert_eq!(
        Single::largest().to_bits() as u64,
        Format::BINARY32.to_bits(Format::BINARY32.max_finite())
    );
    assert_eq!(Half::SMALLEST.to_bits() as u64, 1);
    assert_eq!(
        fmt_of::<rustc_apfloat::ieee::HalfS>().min_positive_subnormal(),
        2f64.powi(-24)
    );
    assert_eq!(fmt_of::<rustc_apfloat::ieee::HalfS>().max_finite(), 65504.0);
}

// ---------------------------------------------------------------------------
// Exhaustive checks of tiny formats
// ---------------------------------------------------------------------------

fn all_values(fmt: Format) -> Vec<f64> {
    (0..1u64 << fmt.width()).map(|b| fmt.from_bits(b)).collect()
}

fn exhaustive_binops<S: Semantics>() -> usize
where
    Double: FloatConvert<IeeeFloat<S>>,
{
    let fmt = fmt_of::<S>();
    let vals = all_values(fmt);
    let mut n = 0;
    for &a in &vals {
        for &b in &vals {
            check_add_sub::<S>(fmt, a, b).unwrap();
            check_mul::<S>(fmt, a, b).unwrap();
            n += 1;
        }
    }
    n
}

#[test]
fn exhaustive_add_sub_mul_tiny_formats() {
    assert_eq!(exhaustive_binops::<E2M1S>(), 1 << 8);
    assert_eq!(exhaustive_binops::<E2M3S>(), 1 << 12);
    assert_eq!(exhaustive_binops::<E3M2S>(), 1 << 12);
    assert_eq!(exhaustive_binops::<E4M3S>(), 1 << 16);
}

/// Every f64 on a grid 8x finer than the subnormal spacing (plus tiny offsets that
/// only the sign of a discarded tail can resolve), rounded into e3m2 and e4m3.
fn exhaustive_round<S: Semantics>()
where
    Double: FloatConvert<IeeeFloat<S>>,
{
    let fmt = fmt_of::<S>();
    let step = fmt.min_positive_subnormal() / 8.0;
    let top = (fmt.max_finite() * 2.5 / step) as i64;
    for i in 0..=top {
        let base = i as f64 * step;
        for x in [
            base,
            base + step * 2f64.powi(-30),
            base - step * 2f64.powi(-30),
        ] {
            check_round::<S>(fmt, x).unwrap();
            check_round::<S>(fmt, -x).unwrap();
        }
    }
}

#[test]
fn exhaustive_round_tiny_formats() {
    exhaustive_round::<E2M1S>();
    exhaustive_round::<E3M2S>();
    exhaustive_round::<E4M3S>();
}

/// to_bits(from_bits(b)) == b for every non-NaN pattern of every format up to 16 bits
/// (and e8m15 completely); NaN patterns decode to NaN and encode canonically.
#[test]
fn bits_round_trip_exhaustive() {
    let mut formats: Vec<Format> = Vec::new();
    for e in 2..=9 {
        for m in 1..=24 {
            let fmt = Format::new(e, m).unwrap();
            if fmt.width() <= 16 {
                formats.push(fmt);
            }
        }
    }
    formats.push(Format::REDUCED);
    for fmt in formats {
        let f = fmt.frac_bits();
        let ones = (1u64 << fmt.exp_bits()) - 1;
        let canonical = (ones << f) | (1 << (f - 1));
        let mut prev = -1.0f64;
        for b in 0..1u64 << fmt.width() {
            let x = fmt.from_bits(b);
            let is_nan_code = (b >> f) & ones == ones && b & ((1 << f) - 1) != 0;
            if is_nan_code {
                assert!(x.is_nan(), "{fmt} {b:#x}");
                assert_eq!(fmt.to_bits(x), canonical);
                continue;
            }
            assert!(fmt.is_representable(x), "{fmt} {b:#x} -> {x:e}");
            assert_eq!(fmt.to_bits(x), b, "{fmt} {x:e}");
            // positive codes are strictly increasing
            if b >> (fmt.width() - 1) == 0 {
                assert!(x > prev || b == 0, "{fmt} {b:#x}");
                prev = x;
                assert_eq!(fmt.round(x, Rounding::TowardPositive), x);
                assert_eq!(fmt.round(x, Rounding::TowardNegative), x);
                assert_eq!(fmt.round(x, Rounding::NearestEven), x);
            }
        }
        assert_eq!(prev, f64::INFINITY);
    }
}

/// Decoding agrees with apfloat's decoding for every pattern of the small formats.
fn decode_matches_apfloat<S: Semantics>()
where
    IeeeFloat<S>: FloatConvert<Double>,
{
    let fmt = fmt_of::<S>();
    for b in 0..1u64 << fmt.width() {
        let mut loses = false;
        let d: Double = IeeeFloat::<S>::from_bits(b as u128)
            .convert(&mut loses)
            .value;
        let x = fmt.from_bits(b);
        if d.is_nan() {
            assert!(x.is_nan());
        } else {
            assert_eq!(x.to_bits(), d.to_bits() as u64, "{fmt} {b:#x}");
        }
    }
}

#[test]
fn decode_matches_apfloat_exhaustive() {
    decode_matches_apfloat::<E2M1S>();
    decode_matches_apfloat::<E3M2S>();
    decode_matches_apfloat::<E4M3S>();
    decode_matches_apfloat::<rustc_apfloat::ieee::HalfS>();
    decode_matches_apfloat::<E8M15S>();
}

// ---------------------------------------------------------------------------
// binary32 against native f32
// ---------------------------------------------------------------------------

struct SplitMix(u64);
impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
}

/// Random f32 bit pattern.
fn random_f32(rng: &mut SplitMix) -> f32 {
    f32::from_bits(rng.next() as u32)
}

const NATIVE_CASES: usize = 1_000_000;

#[test]
fn binary32_nearest_equals_native_f32() {
    let fmt = Format::BINARY32;
    let rne = Rounding::NearestEven;
    let mut rng = SplitMix(0x5eed);
    let check = |got: f64, want: f32, what: &str| {
        if want.is_nan() {
            assert!(got.is_nan(), "{what}");
        } else {
            assert_eq!((got as f32).to_bits(), want.to_bits(), "{what}");
            assert_eq!(got, want as f64, "{what}");
        }
    };
    for i in 0..NATIVE_CASES {
        let a = random_f32(&mut rng);
        let mut b = random_f32(&mut rng);
        if i % 2 == 1 {
            // same or nearby binade
            let e = (a.to_bits() >> 23) & 0xff;
            let d = (rng.next() % 30) as i64 - 15;
            let eb = (e as i64 + d).clamp(0, 254) as u32;
            b = f32::from_bits((b.to_bits() & 0x807f_ffff) | (eb << 23));
        }
        let (x, y) = (a as f64, b as f64);
        let what = format!("{a:e} {b:e}");
        check(fmt.add(x, y, rne), a + b, &what);
        check(fmt.add_general(x, y, rne), a + b, &what);
        check(fmt.sub(x, y, rne), a - b, &what);
        check(fmt.mul(x, y, rne), a * b, &what);
        check(fmt.mul_general(x, y, rne), a * b, &what);
        let z = f64::from_bits(rng.next());
        check(fmt.round(z, rne), z as f32, "round");
        check(fmt.round_general(z, rne), z as f32, "round_general");
        // conversion of f32 values and their encodings
        if !a.is_nan() {
            assert_eq!(fmt.to_bits(x), a.to_bits() as u64);
            assert_eq!(fmt.from_bits(a.to_bits() as u64).to_bits(), x.to_bits());
        }
    }
}

// ---------------------------------------------------------------------------
// Documented special cases, ulp, parsing, serde
// ---------------------------------------------------------------------------

#[test]
fn documented_special_cases() {
    use Rounding::*;
    for fmt in [
        Format::BINARY32,
        Format::REDUCED,
        Format::new(3, 2).unwrap(),
    ] {
        let max = fmt.max_finite();
        let inf = f64::INFINITY;
        let canonical = fmt.to_bits(f64::NAN);
        assert_eq!(canonical >> (fmt.width() - 1), 0);
        assert_eq!(canonical, fmt.to_bits(-f64::NAN));
        for r in MODES {
            assert!(fmt.add(inf, -inf, r).is_nan());
            assert!(fmt.mul(0.0, -inf, r).is_nan());
            assert!(fmt.add(f64::NAN, 1.0, r).is_nan());
            assert_eq!(fmt.add(f64::NAN, 1.0, r).to_bits(), f64::NAN.to_bits());
            assert_eq!(fmt.add(-0.0, -0.0, r).to_bits(), (-0.0f64).to_bits());
            assert_eq!(fmt.add(0.0, 0.0, r).to_bits(), 0.0f64.to_bits());
            let z = if r == TowardNegative { -0.0f64 } else { 0.0 };
            assert_eq!(fmt.add(1.0, -1.0, r).to_bits(), z.to_bits());
            assert_eq!(fmt.add(0.0, -0.0, r).to_bits(), z.to_bits());
            assert_eq!(fmt.sub(0.0, 0.0, r).to_bits(), z.to_bits());
            assert_eq!(fmt.mul(-0.0, 3.0, r).to_bits(), (-0.0f64).to_bits());
        }
        assert_eq!(fmt.mul(max, 2.0, NearestEven), inf);
        assert_eq!(fmt.mul(max, 2.0, TowardPositive), inf);
        assert_eq!(fmt.mul(max, 2.0, TowardNegative), max);
        assert_eq!(fmt.mul(-max, 2.0, TowardPositive), -max);
        assert_eq!(fmt.mul(-max, 2.0, TowardNegative), -inf);
        let s = fmt.min_positive_subnormal();
        assert_eq!(fmt.mul(s, 0.5, TowardPositive), s);
        assert_eq!(fmt.mul(s, 0.5, NearestEven), 0.0);
        assert_eq!(fmt.mul(-s, 0.5, NearestEven).to_bits(), (-0.0f64).to_bits());
        assert_eq!(fmt.ulp(0.0), s);
        assert_eq!(fmt.ulp(1.0), 2f64.powi(-(fmt.frac_bits() as i32)));
        assert_eq!(fmt.ulp(max), max - fmt.from_bits(fmt.to_bits(max) - 1));
        assert_eq!(fmt.ulp(f64::MAX), fmt.ulp(max));
        assert_eq!(fmt.ulp(fmt.min_positive_normal()), s);
        assert!(!fmt.is_representable(1.0 + 2f64.powi(-(fmt.frac_bits() as i32) - 1)));
        assert!(!fmt.is_representable(s * 0.5));
        assert!(!fmt.is_representable(max * 1.5));
    }
}

#[test]
fn limits_and_parsing() {
    assert!(Format::new(1, 10).is_err());
    assert!(Format::new(10, 10).is_err());
    assert!(Format::new(8, 0).is_err());
    assert!(Format::new(8, 25).is_err());
    assert_eq!(Format::BINARY32.width(), 32);
    assert_eq!(Format::REDUCED.width(), 24);
    assert_eq!(Format::REDUCED.bias(), 127);
    assert_eq!(Format::BINARY32.max_finite(), f32::MAX as f64);
    assert_eq!(
        Format::BINARY32.min_positive_normal(),
        f32::MIN_POSITIVE as f64
    );
    assert_eq!(Format::BINARY32.min_positive_subnormal(), 2f64.powi(-149));
    for (s, f) in [
        ("binary32", Format::BINARY32),
        ("reduced", Format::REDUCED),
        ("e8m15", Format::REDUCED),
        ("E8M23", Format::BINARY32),
        (" e5m10 ", Format::new(5, 10).unwrap()),
    ] {
        assert_eq!(s.parse::<Format>().unwrap(), f);
    }
    assert_eq!(Format::BINARY32.to_string(), "binary32");
    assert_eq!(Format::REDUCED.to_string(), "e8m15");
    for bad in [
        "",
        "e8",
        "m15",
        "e8m",
        "e8m15x",
        "f8m15",
        "e-1m3",
        "e10m3",
        "e8m0",
        "e99999999999m1",
    ] {
        let err = bad.parse::<Format>().unwrap_err();
        assert!(
            err.contains("e8m15") || err.contains("2..=9") || err.contains("1..=24"),
            "{bad}: {err}"
        );
    }
    let json = serde_json::to_string(&Format::REDUCED).unwrap();
    assert_eq!(json, "\"e8m15\"");
    assert_eq!(
        serde_json::from_str::<Format>(&json).unwrap(),
        Format::REDUCED
    );
    assert_eq!(
        serde_json::from_str::<Format>("\"binary32\"").unwrap(),
        Format::BINARY32
    );
    assert!(serde_json::from_str::<Format>("\"e12m3\"").is_err());
    assert_eq!(
        serde_json::to_string(&Rounding::TowardNegative).unwrap(),
        "\"TowardNegative\""
    );
}

// ---------------------------------------------------------------------------
// Micro-benchmark (run: cargo test --release --lib format::tests::bench -- --ignored --nocapture)
// ---------------------------------------------------------------------------

fn bench_loop(name: &str, vals: &[f64], op: impl Fn(f64, f64) -> f64) {
    use std::hint::black_box;
    let reps = 500usize;
    let mask = vals.len() - 1;
    let start = std::time::Instant::now();
    let mut acc = [0.0f64; 4];
    for _ in 0..reps {
        for i in (0..vals.len()).step_by(4) {
            for (k, acc_k) in acc.iter_mut().enumerate() {
                let j = i + k;
                *acc_k += op(vals[j], vals[(j * 7 + 1) & mask]);
            }
        }
    }
    let dt = start.elapsed().as_secs_f64();
    black_box(acc);
    println!("{name}: {:.2} ns/op", dt * 1e9 / (reps * vals.len()) as f64);
}

#[test]
#[ignore]
fn bench_ns_per_op() {
    use std::hint::black_box;
    let mut rng = SplitMix(42);
    for (fmt, r) in [
        (Format::BINARY32, Rounding::NearestEven),
        (Format::BINARY32, Rounding::TowardPositive),
        (Format::BINARY32, Rounding::TowardNegative),
        (Format::REDUCED, Rounding::NearestEven),
        (Format::REDUCED, Rounding::TowardPositive),
        (Format::REDUCED, Rounding::TowardNegative),
    ] {
        // normal-range operands of moderate magnitude and random sign (the golden
        // model's typical case); format and mode are opaque to the optimizer.
        let vals: Vec<f64> = (0..4096)
            .map(|_| {
                mk(
                    fmt,
                    rng.next() & 1 == 1,
                    (rng.next() % 20) as i32 - 10,
                    rng.next(),
                )
            })
            .collect();
        let (f, r) = (black_box(fmt), black_box(r));
        bench_loop(&format!("{fmt} {r:?} add"), &vals, |a, b| f.add(a, b, r));
        bench_loop(&format!("{fmt} {r:?} mul"), &vals, |a, b| f.mul(a, b, r));
        let xs: Vec<f64> = vals.iter().map(|v| v * (1.0 + 1e-9)).collect();
        bench_loop(&format!("{fmt} {r:?} round"), &xs, |a, _| f.round(a, r));
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 20000, .. ProptestConfig::default() })]

    /// next_up against apfloat's next_up, on random bit patterns of binary32, e8m15, e4m3.
    #[test]
    fn next_up_matches_apfloat(bits in any::<u64>()) {
        fn check<S: Semantics>(fmt: Format, bits: u64) -> Result<(), TestCaseError> {
            let b = bits & ((1u64 << fmt.width()) - 1);
            let x = fmt.from_bits(b);
            let want = IeeeFloat::<S>::from_bits(b as u128).next_up().value;
            let got = fmt.next_up(x);
            if want.is_nan() {
                prop_assert!(got.is_nan());
            } else {
                prop_assert_eq!(fmt.to_bits(got), want.to_bits() as u64, "next_up({:e})", x);
            }
            Ok(())
        }
        check::<rustc_apfloat::ieee::SingleS>(Format::BINARY32, bits)?;
        check::<E8M15S>(Format::REDUCED, bits)?;
        check::<E4M3S>(Format::new(4, 3).unwrap(), bits)?;
    }
}

/// `scale_const_at_least` and `scale_up` on hand-derived cases.
#[test]
fn scale_by_hand() {
    let f = Format::BINARY32;
    let u = 2f64.powi(-24);
    let c = |k, j, j2| ScaleConst { k, j, j2 };
    // 9u (1 + tiny) lies just above 8u (1 + 2^-3): add the smallest third term, 2^-25
    assert_eq!(
        f.scale_const_at_least(9.0 * u * (1.0 + 2f64.powi(-40))),
        c(-21, 3, 25)
    );
    // exactly 10u takes two terms; just above 2^-21 the shift caps at F + 2 = 25
    assert_eq!(f.scale_const_at_least(10.0 * u), c(-21, 2, 0));
    assert_eq!(
        f.scale_const_at_least(8.0 * u * (1.0 + 2f64.powi(-30))),
        c(-21, 25, 0)
    );
    // 11u (1 + tiny) = 8u (1 + 2^-2 + 2^-3 + tiny): three terms cannot hold it; 12u
    assert_eq!(
        f.scale_const_at_least(11.0 * u * (1.0 + 2f64.powi(-40))),
        c(-21, 1, 0)
    );
    // 0.2 = 2^-3 1.6: 1 + 2^-1 + 2^-3 = 1.625
    assert_eq!(f.scale_const_at_least(0.2), c(-3, 1, 3));
    // exact: 1.5 * 0.1875
    assert_eq!(f.scale_up(-1.5, c(-3, 1, 0)), 0.28125);
    // (1 + 2^-23) 2^-1 (1 + 2^-25) = 2^-1 (1 + 2^-23 + 2^-25 + 2^-48): up to 2^-1 (1 + 2^-22)
    assert_eq!(
        f.scale_up(1.0 + 2f64.powi(-23), c(-1, 25, 0)),
        0.5 * (1.0 + 2f64.powi(-22))
    );
    // 1.75 2^-2 (1 + 2^-1 + 2^-2) = 1.75 * 1.75 / 4, exact
    assert_eq!(f.scale_up(1.75, c(-2, 1, 2)), 1.75 * 1.75 / 4.0);
    // below 2^emin, and any subnormal: 2^emin; zero, inf and NaN pass
    assert_eq!(f.scale_up(2f64.powi(-126), c(-2, 2, 0)), 2f64.powi(-126));
    assert_eq!(f.scale_up(2f64.powi(-149), c(-2, 2, 0)), 2f64.powi(-126));
    assert_eq!(
        f.scale_up(2f64.powi(-120), c(-2, 2, 0)),
        2f64.powi(-122) * 1.25
    );
    assert_eq!(f.scale_up(0.0, c(-2, 2, 0)), 0.0);
    assert_eq!(f.scale_up(f64::NEG_INFINITY, c(-2, 2, 0)), f64::INFINITY);
    assert!(f.scale_up(f64::NAN, c(-2, 2, 0)).is_nan());
}

/// `scale_const_at_least` against a search over every constant of the shape.
#[test]
fn scale_const_is_the_smallest() {
    for f in [
        Format::BINARY32,
        Format::REDUCED,
        Format::new(5, 4).unwrap(),
    ] {
        let jmax = f.frac_bits() + 2;
        for i in 0..2000 {
            let x = 2f64.powi(-(i % 40) - 2) * (1.0 + (i as f64 * 0.618034).fract());
            let k = x.log2().floor() as i32;
            let all = (k..=k + 1).flat_map(|k| {
                (1..=jmax).flat_map(move |j| {
                    std::iter::once(0)
                        .chain(j + 1..=jmax)
                        .map(move |j2| ScaleConst { k, j, j2 })
                })
            });
            let want = all
                .filter(|c| c.value() >= x)
                .map(|c| c.value())
                .fold(f64::INFINITY, f64::min);
            let got = f.scale_const_at_least(x);
            assert_eq!(got.value(), want, "{f} x = {x:e}: {got:?}");
        }
    }
}
