//! The chip's parameterized binary floating-point format.
//!
//! # Encoding
//!
//! A [`Format`] with `E = exp_bits` and `F = frac_bits` is an IEEE-754 style
//! binary interchange format of `width = 1 + E + F` bits, laid out (MSB first) as
//!
//! ```text
//!   sign (1) | biased exponent (E) | fraction (F)
//! ```
//!
//! with `bias = 2^(E-1) - 1`, `emax = bias`, `emin = 1 - bias` and precision
//! `p = F + 1` (hidden bit). A word with biased exponent `b` and fraction `f` encodes
//!
//! * `b = 0`: zero (`f = 0`, signed) or a subnormal `(-1)^s * f * 2^(emin - F)`;
//! * `0 < b < 2^E - 1`: a normal `(-1)^s * (2^F + f) * 2^(b - bias - F)`;
//! * `b = 2^E - 1`, `f = 0`: `±inf`;
//! * `b = 2^E - 1`, `f != 0`: NaN. The only NaN the format ever produces is the
//!   *canonical quiet NaN*: sign 0, exponent all ones, fraction MSB set, rest 0.
//!
//! Derived quantities: `max_finite = (2 - 2^-F) * 2^emax`,
//! `min_positive_normal = 2^emin`, `min_positive_subnormal = 2^(emin - F)`.
//! `binary32` (`e8m23`) and `binary16` (`e5m10`) are exactly the IEEE formats.
//!
//! # Value carrier
//!
//! Values are carried as `f64` holding *exactly* a number of the format (every
//! format value is an `f64`, see the limits below). Zeros keep their sign, `±inf`
//! are `f64` infinities and every NaN is represented by `f64::NAN`
//! (the operations always return exactly `f64::NAN` for NaN results; [`Format::to_bits`]
//! maps any NaN to the canonical NaN pattern). Operands of the arithmetic operations
//! must be representable ([`Format::is_representable`]); this is checked by
//! `debug_assert!` only. [`Format::round`] is the entry point for arbitrary `f64`s.
//!
//! # Arithmetic semantics (what the RTL has to implement)
//!
//! `add`, `sub`, `mul` and `round` are *correctly rounded*: the exact real result is
//! computed with unbounded range and precision and rounded **once** to the format
//! using the rounding direction [`Rounding`]:
//!
//! * [`Rounding::NearestEven`]: nearest representable value, ties to the one with an
//!   even least significant fraction bit (IEEE roundTiesToEven);
//! * [`Rounding::TowardPositive`] / [`Rounding::TowardNegative`]: the nearest value
//!   `>=` / `<=` the exact result (IEEE roundTowardPositive / roundTowardNegative).
//!
//! Rounding uses the fixed grid of the format, so results below `2^emin` round onto
//! the subnormal grid (gradual underflow, never flush to zero); a nonzero exact result
//! may round to a zero, which then carries the sign of the exact result.
//!
//! Overflow: the exact result is first rounded as if the exponent were unbounded; if
//! that magnitude exceeds `max_finite` the result is
//!
//! | rounding        | positive overflow | negative overflow |
//! |-----------------|-------------------|-------------------|
//! | NearestEven     | `+inf`            | `-inf`            |
//! | TowardPositive  | `+inf`            | `-max_finite`     |
//! | TowardNegative  | `+max_finite`     | `-inf`            |
//!
//! (For NearestEven this means: `|exact| >= max_finite + ulp(max_finite)/2` overflows.)
//!
//! Special operands (all exact, no rounding):
//!
//! * any NaN operand → canonical NaN; `inf - inf`, `inf + (-inf)`, `0 * inf` → canonical NaN;
//! * `inf ± finite = inf` (with its sign), `inf * nonzero = ±inf` (sign = xor of signs);
//! * a product that is zero is a zero with sign = xor of the operand signs (all modes);
//! * an exactly zero sum of operands with opposite signs (`x + (-x)`, `(+0) + (-0)`)
//!   is `+0`, except `-0` under `TowardNegative`; `(+0) + (+0) = +0` and
//!   `(-0) + (-0) = -0` in all modes;
//! * `sub(a, b) = add(a, -b)` exactly (including zero signs and NaN).
//!
//! No exception flags are produced, so the tininess-detection choice of IEEE is
//! irrelevant.
//!
//! # Limits: `exp_bits` in `2..=9`, `frac_bits` in `1..=24`
//!
//! * `exp_bits >= 2`: with one exponent bit there would be no normal numbers at all
//!   (the only codes are subnormals and inf/NaN).
//! * `frac_bits >= 1`: with no fraction bit, infinity and NaN cannot be told apart.
//! * `frac_bits <= 24`: significands have at most 25 bits, so the exact product of two
//!   of them (at most 50 bits) fits the 53-bit `f64` significand; `binary32` (23) fits
//!   with a margin. It also keeps every rounding step (scaled values `< 2^26`) exact.
//! * `exp_bits <= 9`: the largest exact product is `< 2^(2*(emax+1)) = 2^512` and the
//!   smallest nonzero one is `>= 2^(2*(emin - F)) >= 2^-556`; both are normal `f64`s,
//!   so every product of two format numbers (including subnormals) is *exact* in `f64`.
//!   With 10 exponent bits the product of two large values would overflow `f64`.
//!
//! # Implementation (golden-model speed)
//!
//! * `binary32` + `NearestEven`: the native `f32` operation (IEEE by definition).
//! * Otherwise: the exact product `a*b` is one `f64`; the exact sum is the unevaluated
//!   pair `hi + lo` from TwoSum (error-free: `hi = fl(a+b)`, `lo = (a+b) - hi` exactly,
//!   `|lo| <= ulp64(hi)/2`). Then `round2(hi, lo)` rounds `hi + lo` once: with
//!   `q` = the format ulp at `|hi|` (a power of two, subnormal-aware), `t = |hi|/q` is
//!   exact, `m = floor(t)` and `fr = t - m` exact; because `|lo/q| < 2^-28` is below
//!   the resolution of `fr`, `fr` decides except when `fr` is exactly `0` or `1/2`, where
//!   the sign of `lo` (relative to `hi`) breaks the tie / decides whether the exact value
//!   lies strictly between two neighbours. Stepping *down in magnitude* from an exact
//!   power of two `2^e` with `e > emin` uses the half-size ulp of the binade below.
//!   No allocation and no big integers; a few ns per operation.
//! * Nearest-even with an exact `f64` operand or result (`lo == 0`) in the format's normal
//!   range: rounded on the `f64` bits (`nearest_normal`), fewer operations than `round2`
//!   (the reduced format's T.CHECK is most of its queries); subnormal and overflowing
//!   results still take `round2`.
use std::fmt;
use std::str::FromStr;

#[cfg(test)]
mod tests;

/// Rounding direction of an operation (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum Rounding {
    /// Round to nearest, ties to even (IEEE roundTiesToEven).
    NearestEven,
    /// Round toward `+inf` (IEEE roundTowardPositive).
    TowardPositive,
    /// Round toward `-inf` (IEEE roundTowardNegative).
    TowardNegative,
}

/// A binary floating-point format with `exp_bits` exponent and `frac_bits` fraction
/// bits (plus sign and hidden bit). See the module documentation for the semantics.
///
/// Serialized (serde) as its [`Display`](fmt::Display) string, e.g. `"binary32"`, `"e8m15"`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(try_from = "String", into = "String")]
pub struct Format {
    exp_bits: u32,
    frac_bits: u32,
}

/// A constant `c = 2^k (1 + 2^-j + 2^-j2)` (1 <= j < j2 <= F + 2, or j2 = 0 for no third
/// term; the RTL's `FpScale` takes k < 0): multiplying by it takes shifts and additions of
/// significands instead of a multiplier ([`Format::scale_up`]); T.CHECK's certificate
/// multiplies by such constants only. Shifts above F + 2 would round upward as F + 2 does
/// (their addend only sets the sticky bit).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ScaleConst {
    pub k: i32,
    pub j: u32,
    pub j2: u32,
}

impl ScaleConst {
    pub fn value(self) -> f64 {
        let t = if self.j2 == 0 {
            0.0
        } else {
            pow2(-(self.j2 as i32))
        };
        pow2(self.k) * (1.0 + pow2(-(self.j as i32)) + t)
    }
}

/// Magnitude rounding direction (after folding the sign into the mode).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Mag {
    Nearest,
    Away,
    TowardZero,
}

/// Smallest normal binary32 magnitude, 2^-126.
const F32_MIN_NORMAL: f64 = f32::MIN_POSITIVE as f64;

/// `2^e` for `-1022 <= e <= 1023`.
#[inline(always)]
fn pow2(e: i32) -> f64 {
    debug_assert!((-1022..=1023).contains(&e));
    f64::from_bits(((e + 1023) as u64) << 52)
}

/// Unbiased `f64` exponent of `x` (`-1023` for zeros and `f64` subnormals).
#[inline(always)]
fn exponent64(x: f64) -> i32 {
    ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023
}

impl Format {
    /// IEEE binary32: 8 exponent bits, 23 fraction bits (32-bit word).
    pub const BINARY32: Format = Format {
        exp_bits: 8,
        frac_bits: 23,
    };
    /// The chip's reduced format: 8 exponent bits, 15 fraction bits (24-bit word).
    pub const REDUCED: Format = Format {
        exp_bits: 8,
        frac_bits: 15,
    };
    /// The narrowest format the RTL builds: 8 exponent bits, 10 fraction bits (19-bit word).
    pub const E8M10: Format = Format {
        exp_bits: 8,
        frac_bits: 10,
    };

    /// Smallest / largest allowed exponent field width.
    pub const EXP_BITS_RANGE: std::ops::RangeInclusive<u32> = 2..=9;
    /// Smallest / largest allowed fraction field width.
    pub const FRAC_BITS_RANGE: std::ops::RangeInclusive<u32> = 1..=24;

    /// A format with `exp_bits` in `2..=9` and `frac_bits` in `1..=24`.
    ///
    /// The limits guarantee that every format value and every exact product of two
    /// format values is an exact `f64` (see the module documentation).
    pub fn new(exp_bits: u32, frac_bits: u32) -> Result<Format, String> {
        if !Self::EXP_BITS_RANGE.contains(&exp_bits) {
            return Err(format!(
                "exponent width {exp_bits} not supported: must be 2..=9 (at least 2 so that \
                 normal numbers exist, at most 9 so that every product of two values is \
                 exact in f64 without overflow)"
            ));
        }
        if !Self::FRAC_BITS_RANGE.contains(&frac_bits) {
            return Err(format!(
                "fraction width {frac_bits} not supported: must be 1..=24 (at least 1 so that \
                 inf and NaN differ, at most 24 so that the product of two 25-bit \
                 significands is exact in the 53-bit f64 significand)"
            ));
        }
        Ok(Format {
            exp_bits,
            frac_bits,
        })
    }

    /// Number of exponent bits.
    #[inline]
    pub const fn exp_bits(&self) -> u32 {
        self.exp_bits
    }

    /// Number of stored fraction bits (precision minus the hidden bit).
    #[inline]
    pub const fn frac_bits(&self) -> u32 {
        self.frac_bits
    }

    /// Word width `1 + exp_bits + frac_bits`.
    #[inline]
    pub const fn width(&self) -> u32 {
        1 + self.exp_bits + self.frac_bits
    }

    /// Exponent bias `2^(exp_bits-1) - 1` (= `emax`).
    #[inline]
    pub const fn bias(&self) -> i32 {
        (1i32 << (self.exp_bits - 1)) - 1
    }

    #[inline(always)]
    fn emax(&self) -> i32 {
        self.bias()
    }

    #[inline(always)]
    fn emin(&self) -> i32 {
        1 - self.bias()
    }

    /// Largest finite value `(2 - 2^-frac_bits) * 2^emax`.
    #[inline]
    pub fn max_finite(&self) -> f64 {
        let f = self.frac_bits;
        f64::from_bits((((self.emax() + 1023) as u64) << 52) | (((1u64 << f) - 1) << (52 - f)))
    }

    /// Smallest positive normal value `2^emin`.
    #[inline]
    pub fn min_positive_normal(&self) -> f64 {
        pow2(self.emin())
    }

    /// Smallest positive subnormal value `2^(emin - frac_bits)`.
    #[inline]
    pub fn min_positive_subnormal(&self) -> f64 {
        pow2(self.emin() - self.frac_bits as i32)
    }

    /// The ulp of `x` in this format: the spacing of representable numbers in the
    /// binade of `|x|`, i.e. `2^(max(e, emin) - frac_bits)` with `2^e <= |x| < 2^(e+1)`.
    /// Zeros (and subnormals) give `min_positive_subnormal`; finite `|x|` beyond the
    /// format's range give the ulp of the top binade; `±inf` gives `+inf`, NaN gives NaN.
    pub fn ulp(&self, x: f64) -> f64 {
        if x.is_nan() {
            return f64::NAN;
        }
        if x.is_infinite() {
            return f64::INFINITY;
        }
        let e = exponent64(x).clamp(self.emin(), self.emax());
        pow2(e - self.frac_bits as i32)
    }

    /// Whether `x` is exactly a value of this format. NaN and `±inf` count as
    /// representable (NaN by the canonical NaN).
    pub fn is_representable(&self, x: f64) -> bool {
        if !x.is_finite() {
            return true;
        }
        let a = x.abs();
        if a > self.max_finite() {
            return false;
        }
        let e = exponent64(a).max(self.emin());
        // |x| / ulp: exact (power-of-two scaling into the normal f64 range), < 2^25.
        let t = a * pow2(self.frac_bits as i32 - e);
        t == t.trunc()
    }

    #[inline(always)]
    fn is_binary32(&self) -> bool {
        self.exp_bits == 8 && self.frac_bits == 23
    }

    #[inline(always)]
    fn mag_mode(r: Rounding, neg: bool) -> Mag {
        match (r, neg) {
            (Rounding::NearestEven, _) => Mag::Nearest,
            (Rounding::TowardPositive, false) | (Rounding::TowardNegative, true) => Mag::Away,
            (Rounding::TowardPositive, true) | (Rounding::TowardNegative, false) => Mag::TowardZero,
        }
    }

    /// `x` (finite, nonzero, exact) rounded to nearest-even on its f64 bits, where x and the
    /// result are normal in the format (else `None`: `round2` handles subnormals and
    /// overflow): adding half a step less one, plus the last kept bit, carries into the
    /// kept bits exactly when the dropped bits exceed half a step, or equal it with the
    /// kept last bit odd; the carry may step the exponent, the sign bit is untouched.
    #[inline(always)]
    fn nearest_normal(&self, x: f64) -> Option<f64> {
        let shift = 52 - self.frac_bits;
        let bits = x.to_bits();
        let up = bits + (1u64 << (shift - 1)) - 1 + ((bits >> shift) & 1);
        let y = f64::from_bits(up & !((1u64 << shift) - 1));
        ((exponent64(x) >= self.emin()) & (exponent64(y) <= self.emax())).then_some(y)
    }

    /// Rounds the exact value `hi + lo` once into the format.
    ///
    /// Preconditions: `hi` finite and nonzero; `lo == 0` or `|lo| <= ulp64(hi)/2`
    /// (as produced by TwoSum), so `lo` never reaches the format's rounding position.
    #[inline(always)]
    fn round2(&self, hi: f64, lo: f64, r: Rounding) -> f64 {
        debug_assert!(hi.is_finite() && hi != 0.0);
        const SIGN: u64 = 1 << 63;
        let neg = hi.is_sign_negative();
        let frac = self.frac_bits as i32;
        let emax = self.emax();
        let emin = self.emin();
        let e_hi = exponent64(hi);
        if e_hi > emax {
            // |hi + lo| > 2^(emax+1) - 2^(emax-F-1) = max_finite + ulp/2: overflow.
            return self.overflow(neg, r);
        }
        let e = if e_hi < emin { emin } else { e_hi };
        // Scaled magnitude t = |hi| / q in [0, 2^(F+1)), exact (power-of-two scaling).
        let t = hi.abs() * pow2(frac - e);
        let m = t as i64; // floor(t)
        let fr = t - m as f64; // exact fraction in [0, 1)
                               // lo measured in the direction of |hi| (sign flipped if hi < 0).
        let lo_m = f64::from_bits(lo.to_bits() ^ (hi.to_bits() & SIGN));
        // The exact scaled magnitude is t + lo_m/q with |lo_m/q| < 2^-28 below the
        // resolution of fr, so lo_m only matters when fr is exactly 0 or 1/2.
        // Everything below is flag arithmetic (no data-dependent branches: signs and
        // fractions are random in a sweep). Units of half a grid step (q/2):
        //   nearest:  +2 if fr > 1/2, or fr == 1/2 and (lo_m > 0, or lo_m == 0 and m odd)
        //   away:     +2 if fr > 0 or lo_m > 0 (the exact value is above m*q)
        //   toward 0: -2 (or -1 at a power of two 2^e with e > emin, where the spacing
        //             below is q/2) if fr == 0 and lo_m < 0 (exact value just below m*q)
        // (With TwoSum operands lo != 0 needs an exact sum wider than 53 bits, which
        // implies e >= emin + 29 and fr != 1/2: the e > emin test and the lo_m tie
        // break are unreachable for add but keep round2 correct for any hi + lo.)
        let up_near =
            ((fr > 0.5) | ((fr == 0.5) & ((lo_m > 0.0) | ((lo_m == 0.0) & (m & 1 == 1))))) as i64;
        let up_away = ((fr > 0.0) | (lo_m > 0.0)) as i64;
        let down = ((fr == 0.0) & (lo_m < 0.0)) as i64;
        let half = ((m == (1i64 << frac)) & (e > emin)) as i64;
        let is_near = (r == Rounding::NearestEven) as i64;
        let is_away = ((r == Rounding::TowardPositive) ^ neg) as i64;
        let delta_dir = is_away * 2 * up_away - (1 - is_away) * down * (2 - half);
        let delta = is_near * 2 * up_near + (1 - is_near) * delta_dir;
        let units2 = 2 * m + delta; // result magnitude in units of q/2
        if (e == emax) & (units2 > (1i64 << (frac + 2)) - 2) {
            // Rounded up past max_finite = (2^(F+1) - 1) * q, i.e. to 2^(emax+1).
            return self.overflow(neg, r);
        }
        (units2 as f64 * pow2(e - frac - 1)).copysign(hi)
    }

    /// binary32, directed rounding of the exact `hi + lo` (callers keep |hi| >= 2^-126:
    /// converting f32 subnormals costs a microcode assist on x86, so tiny results take
    /// `round2`) (`hi` finite and nonzero, `lo`
    /// as in [`Self::round2`]): native f32 conversion (nearest) is within one step of the
    /// answer and the f32 grid points are f64s, so one exact comparison picks the
    /// neighbour. Covers subnormals (conversion rounds them), overflow (`next_up(-inf)`
    /// is `-max`) and tiny negatives rounding up to `-0`.
    #[inline(always)]
    fn round32_directed(hi: f64, lo: f64, up: bool) -> f64 {
        let f = hi as f32;
        let fd = f as f64;
        // Step one f32 toward +inf (up) or -inf (down)? Flag arithmetic, no branches:
        // the signs in a sweep are random.
        let step = if up {
            (fd < hi) | ((fd == hi) & (lo > 0.0))
        } else {
            (fd > hi) | ((fd == hi) & (lo < 0.0))
        };
        // Moving away from zero adds one to the magnitude bits, toward zero subtracts one;
        // a zero is first given the sign of the direction of travel.
        let b = f.to_bits();
        let zero = (b << 1) == 0;
        let b = if zero {
            if up {
                0
            } else {
                0x8000_0000
            }
        } else {
            b
        };
        let away = (b >> 31 == 0) == up;
        let delta = step as u32;
        let nb = if away {
            b.wrapping_add(delta)
        } else {
            b.wrapping_sub(delta)
        };
        // A zero that does not move keeps the sign the conversion gave it.
        let nb = if zero & !step { f.to_bits() } else { nb };
        f32::from_bits(nb) as f64
    }

    /// Overflow result for a result of sign `neg` (see the table in the module doc).
    #[cold]
    fn overflow(&self, neg: bool, r: Rounding) -> f64 {
        let mag = match Self::mag_mode(r, neg) {
            Mag::Nearest | Mag::Away => f64::INFINITY,
            Mag::TowardZero => self.max_finite(),
        };
        if neg {
            -mag
        } else {
            mag
        }
    }

    /// The next value of the format above `x` (IEEE nextUp): +inf stays, -inf gives
    /// -max_finite, NaN stays NaN, the largest finite gives +inf, -min_subnormal gives -0.
    #[inline(always)]
    pub fn next_up(&self, x: f64) -> f64 {
        if self.is_binary32() {
            return if x.is_nan() {
                f64::NAN
            } else {
                (x as f32).next_up() as f64
            };
        }
        self.next_up_general(x)
    }

    /// The next value of the format below `x` (IEEE nextDown): `-next_up(-x)`.
    pub fn next_down(&self, x: f64) -> f64 {
        -self.next_up(-x)
    }

    fn next_up_general(&self, x: f64) -> f64 {
        if x.is_nan() || x == f64::INFINITY {
            return x;
        }
        if x == f64::NEG_INFINITY {
            return -self.max_finite();
        }
        if x >= 0.0 {
            let y = x + self.ulp(x);
            return if y > self.max_finite() {
                f64::INFINITY
            } else {
                y
            };
        }
        // Below a power of two above the normal minimum the spacing halves.
        let m = -x;
        let below = if m.to_bits() << 12 == 0 && m > self.min_positive_normal() {
            self.ulp(m) / 2.0
        } else {
            self.ulp(m)
        };
        -(m - below)
    }

    /// Rounds an arbitrary `f64` (taken as exact) into the format. NaN gives the
    /// canonical NaN, `±inf` and `±0` are returned unchanged. binary32's cases inline, the
    /// rest a call.
    #[inline(always)]
    pub fn round(&self, x: f64, r: Rounding) -> f64 {
        if self.is_binary32() && r == Rounding::NearestEven {
            let y = x as f32 as f64;
            return if y.is_nan() { f64::NAN } else { y };
        }
        if self.is_binary32() && x.is_finite() && x.abs() >= F32_MIN_NORMAL {
            return Self::round32_directed(x, 0.0, r == Rounding::TowardPositive);
        }
        self.round_general(x, r)
    }

    #[inline(never)]
    fn round_general(&self, x: f64, r: Rounding) -> f64 {
        if x == 0.0 || !x.is_finite() {
            return if x.is_nan() { f64::NAN } else { x };
        }
        self.round2(x, 0.0, r)
    }

    /// Correctly rounded `a + b`. Operands must be representable.
    #[inline]
    pub fn add(&self, a: f64, b: f64, r: Rounding) -> f64 {
        debug_assert!(
            self.is_representable(a),
            "{a:e} not representable in {self}"
        );
        debug_assert!(
            self.is_representable(b),
            "{b:e} not representable in {self}"
        );
        if self.is_binary32() && r == Rounding::NearestEven {
            let s = (a as f32 + b as f32) as f64;
            return if s.is_nan() { f64::NAN } else { s };
        }
        self.add_general(a, b, r)
    }

    /// Correctly rounded `a - b` (= `a + (-b)`). Operands must be representable.
    #[inline]
    pub fn sub(&self, a: f64, b: f64, r: Rounding) -> f64 {
        self.add(a, -b, r)
    }

    /// The TwoSum + `round2` path (used for everything but binary32/NearestEven).
    #[inline(always)]
    fn add_general(&self, a: f64, b: f64, r: Rounding) -> f64 {
        let s = a + b;
        if s == 0.0 {
            // Exact zero sum (f64 has gradual underflow, so s == 0 iff a + b == 0).
            // f64 RNE already gives the IEEE sign for NearestEven / TowardPositive.
            if r == Rounding::TowardNegative && (a.is_sign_negative() || b.is_sign_negative()) {
                return -0.0;
            }
            return s;
        }
        if !s.is_finite() {
            // Only from inf/NaN operands (finite format sums are far below f64::MAX).
            return if s.is_nan() { f64::NAN } else { s };
        }
        // TwoSum (Knuth): s + lo == a + b exactly.
        let bb = s - a;
        let lo = (a - (s - bb)) + (b - bb);
        if self.is_binary32() && r != Rounding::NearestEven && s.abs() >= F32_MIN_NORMAL {
            return Self::round32_directed(s, lo, r == Rounding::TowardPositive);
        }
        if r == Rounding::NearestEven && lo == 0.0 {
            if let Some(y) = self.nearest_normal(s) {
                return y;
            }
        }
        self.round2(s, lo, r)
    }

    /// Correctly rounded `a * b`. Operands must be representable.
    #[inline]
    pub fn mul(&self, a: f64, b: f64, r: Rounding) -> f64 {
        debug_assert!(
            self.is_representable(a),
            "{a:e} not representable in {self}"
        );
        debug_assert!(
            self.is_representable(b),
            "{b:e} not representable in {self}"
        );
        if self.is_binary32() && r == Rounding::NearestEven {
            let p = (a as f32 * b as f32) as f64;
            return if p.is_nan() { f64::NAN } else { p };
        }
        self.mul_general(a, b, r)
    }

    /// The exact-product + `round2` path.
    #[inline(always)]
    fn mul_general(&self, a: f64, b: f64, r: Rounding) -> f64 {
        // Exact: significands <= 25 bits, exponents within f64's normal range.
        let p = a * b;
        if p == 0.0 || !p.is_finite() {
            return if p.is_nan() { f64::NAN } else { p };
        }
        if self.is_binary32() && r != Rounding::NearestEven && p.abs() >= F32_MIN_NORMAL {
            return Self::round32_directed(p, 0.0, r == Rounding::TowardPositive);
        }
        if r == Rounding::NearestEven {
            if let Some(y) = self.nearest_normal(p) {
                return y;
            }
        }
        self.round2(p, 0.0, r)
    }

    /// The smallest [`ScaleConst`] of this format at least `x` (positive, normal in f64;
    /// shifts at most F + 2; of two equal ones, the one without a second shift).
    pub fn scale_const_at_least(&self, x: f64) -> ScaleConst {
        assert!(
            x.is_normal() && x > 0.0 && x < 1e300,
            "scale constant {x:e} out of range"
        );
        let jmax = self.frac_bits + 2;
        let mut best: Option<ScaleConst> = None;
        for k in [exponent64(x), exponent64(x) + 1] {
            // x = 2^k (1 + r): per j, the third term is the smallest 2^-j2 >= r - 2^-j
            let r = x * pow2(-k) - 1.0;
            for j in 1..=jmax {
                let d = r - pow2(-(j as i32));
                let j2 = if d <= 0.0 {
                    0
                } else {
                    let e = exponent64(d);
                    let largest = if d == pow2(e) { -e } else { -e - 1 };
                    if largest <= j as i32 {
                        continue;
                    } else {
                        (largest as u32).min(jmax)
                    }
                };
                let c = ScaleConst { k, j, j2 };
                if best.is_none_or(|b| c.value() < b.value() || (c.value() == b.value() && j2 == 0))
                {
                    best = Some(c);
                }
            }
        }
        let c = best.expect("2^(k+1) (1 + 2^-jmax) is at least x");
        debug_assert!(c.value() >= x);
        c
    }

    /// `|x| c` rounded upward, and at least 2^emin when x is not zero: the golden function
    /// of `FpScale`, the chip's multiplier by a [`ScaleConst`] (shifts and two additions).
    /// Results below 2^emin (with c < 1, subnormal x included) become 2^emin, an upper
    /// bound that spares the unit the subnormal grid; infinity and NaN pass.
    pub fn scale_up(&self, x: f64, c: ScaleConst) -> f64 {
        let a = x.abs();
        if a == 0.0 || !a.is_finite() {
            return a;
        }
        // exact: a has at most F + 1 significant bits, c at most F + 3
        self.round(a * c.value(), Rounding::TowardPositive)
            .max(self.min_positive_normal())
    }

    /// The bit pattern `sign | exp | frac` (fields masked to their widths).
    pub fn pack(&self, sign: bool, exp: u64, frac: u64) -> u64 {
        let (e, f) = (self.exp_bits, self.frac_bits);
        ((sign as u64) << (e + f)) | ((exp & ((1 << e) - 1)) << f) | (frac & ((1 << f) - 1))
    }

    /// Special and boundary bit patterns, both signs: zeros, subnormals (smallest, largest,
    /// half), the normal boundary, values around 1, the largest finite values, infinities and
    /// NaNs. The corner cases every datapath test starts from.
    pub fn special_patterns(&self) -> Vec<u64> {
        let (ones, bias, fm, half) = (
            (1u64 << self.exp_bits) - 1,
            self.bias() as u64,
            (1u64 << self.frac_bits) - 1,
            1u64 << (self.frac_bits - 1),
        );
        let fields = [
            (0, 0),
            (0, 1),
            (0, 2),
            (0, fm),
            (0, half),
            (1, 0),
            (1, 1),
            (1, fm),
            (2, 0),
            (bias, 0),
            (bias, 1),
            (bias, fm),
            (bias - 1, fm),
            (ones - 1, fm),
            (ones - 1, 0),
            (ones - 2, fm),
            (ones, 0),
            (ones, half),
            (ones, 1),
            (ones, fm),
        ];
        [false, true]
            .iter()
            .flat_map(|&s| fields.iter().map(move |&(e, f)| self.pack(s, e, f)))
            .collect()
    }

    /// Encodes a representable value as `sign | biased exponent | fraction`
    /// (`width()` bits, right-aligned). Any NaN gives the canonical NaN pattern.
    /// Non-representable finite inputs are a logic error (debug assertion; the
    /// result is unspecified in release builds).
    pub fn to_bits(&self, x: f64) -> u64 {
        let f = self.frac_bits;
        let exp_ones = (1u64 << self.exp_bits) - 1;
        if x.is_nan() {
            return (exp_ones << f) | (1u64 << (f - 1));
        }
        debug_assert!(
            self.is_representable(x),
            "{x:e} not representable in {self}"
        );
        let sign = (x.is_sign_negative() as u64) << (self.exp_bits + f);
        let a = x.abs();
        if a == f64::INFINITY {
            return sign | (exp_ones << f);
        }
        if a < self.min_positive_normal() {
            // Zero or subnormal: fraction = |x| / min_subnormal (exact integer < 2^F).
            let m = (a * pow2(f as i32 - self.emin())) as u64;
            return sign | m;
        }
        let b = a.to_bits();
        let biased = (exponent64(a) + self.bias()) as u64;
        let fraction = (b >> (52 - f)) & ((1u64 << f) - 1);
        sign | (biased << f) | fraction
    }

    /// Decodes a `width()`-bit word (higher bits must be zero; they are ignored in
    /// release builds). NaN codes give `f64::NAN`.
    pub fn from_bits(&self, bits: u64) -> f64 {
        let f = self.frac_bits;
        debug_assert!(bits >> self.width() == 0, "{bits:#x} wider than {self}");
        let exp_ones = (1u64 << self.exp_bits) - 1;
        let neg = (bits >> (self.exp_bits + f)) & 1 == 1;
        let ef = (bits >> f) & exp_ones;
        let m = bits & ((1u64 << f) - 1);
        let mag = if ef == exp_ones {
            if m != 0 {
                return f64::NAN;
            }
            f64::INFINITY
        } else if ef == 0 {
            m as f64 * self.min_positive_subnormal()
        } else {
            let e = ef as i32 - self.bias();
            f64::from_bits((((e + 1023) as u64) << 52) | (m << (52 - f)))
        };
        if neg {
            -mag
        } else {
            mag
        }
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if *self == Format::BINARY32 {
            f.write_str("binary32")
        } else {
            write!(f, "e{}m{}", self.exp_bits, self.frac_bits)
        }
    }
}

impl FromStr for Format {
    type Err = String;

    /// Accepts `binary32`, `reduced` (= `e8m15`) or `e<exp_bits>m<frac_bits>` such as
    /// `e8m15` (case-insensitive, surrounding whitespace ignored).
    fn from_str(s: &str) -> Result<Format, String> {
        const SYNTAX: &str = "expected \"binary32\", \"reduced\" (= e8m15) or \
             \"e<exp_bits>m<frac_bits>\" such as \"e8m15\" (exp_bits 2..=9, frac_bits 1..=24)";
        let t = s.trim().to_ascii_lowercase();
        match t.as_str() {
            "binary32" => return Ok(Format::BINARY32),
            "reduced" => return Ok(Format::REDUCED),
            _ => {}
        }
        let parse = || -> Option<(u32, u32)> {
            let rest = t.strip_prefix('e')?;
            let (e, m) = rest.split_once('m')?;
            let digits =
                |d: &str| !d.is_empty() && d.len() <= 3 && d.bytes().all(|c| c.is_ascii_digit());
            if !digits(e) || !digits(m) {
                return None;
            }
            Some((e.parse().ok()?, m.parse().ok()?))
        };
        match parse() {
            Some((e, m)) => Format::new(e, m).map_err(|err| format!("format \"{s}\": {err}")),
            None => Err(format!("invalid number format \"{s}\": {SYNTAX}")),
        }
    }
}

impl TryFrom<String> for Format {
    type Error = String;
    fn try_from(s: String) -> Result<Format, String> {
        s.parse()
    }
}

impl From<Format> for String {
    fn from(f: Format) -> String {
        f.to_string()
    }
}
