//! A proven upper enclosure, in f64, of the chip's upward-rounded arithmetic on non-negative
//! operands (T.CHECK's certificate, DATE'05 §4.2; docs/explanation/accuracy.md, "Deciding T.CHECK in
//! f64"), so that software decides most signs without rounding every bound bit for bit,
//! and the switch that checks every such decision against the bit-exact path.
//!
//! Per operation: for x, y >= 0 and w = x + y or x y, the chip's `round_up(w)` is at most
//! `w (1 + 2^-F) + q` below overflow (q the smallest subnormal), and `FpScale`'s floor
//! `max(., 2^emin)` adds at most 2^emin. [`Upper::up`] evaluates `fl(fl(w) K) + Q` with
//! `K = 1 + 2^-F + 2^-49` and `Q = 2^(emin+1)`, which is at least that even after its own
//! three f64 roundings (each at most a factor 1 - 2^-53): by induction over the operations,
//! an enclosed value is at least the chip's. An enclosure at or above the format's largest
//! finite value proves nothing (the chip may have overflowed): [`Upper::fits`] says whether
//! every enclosed value stayed below it. [`down`] bounds such sums and products from
//! below instead, so that software can also prove a sign of the chip unknown.

use crate::format::{Format, ScaleConst};
use std::cell::Cell;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::OnceLock;

/// Upper bounds of upward-rounded operations of one format.
#[derive(Clone, Copy, Debug)]
pub struct Upper {
    k: f64,
    q: f64,
    limit: f64,
    /// [`Upper::dot_gap`]'s factors: (1 + 2^-F)^3 - 1 + 2^-49 and 7 times the smallest
    /// subnormal.
    gap_rel: f64,
    gap_abs: f64,
    /// [`Upper::round_rel`] and [`Upper::value_limit`].
    round_rel: f64,
    value_limit: f64,
}

impl Upper {
    pub fn new(f: Format) -> Upper {
        let p2 = |e: i32| 2f64.powi(e);
        let u = p2(-(f.frac_bits() as i32));
        Upper {
            k: 1.0 + u + p2(-49),
            q: 2.0 * f.min_positive_normal(),
            limit: f.max_finite(),
            gap_rel: 3.0 * u + 3.0 * u * u + u * u * u + p2(-49),
            gap_abs: 7.0 * f.min_positive_subnormal(),
            round_rel: 2.0 * u + u * u + p2(-51),
            value_limit: p2(f.max_finite().log2().floor() as i32 / 2 - 3),
        }
    }

    /// 2u + u^2 + 2^-51 (u = 2^-F, exact in f64): per unit of its operands' magnitudes, the
    /// chip's rounding of a product and a sum after it (any mode, above underflow) plus
    /// f64's rounding of the same two operations (docs/explanation/accuracy.md, "Values in f64").
    #[inline(always)]
    pub fn round_rel(&self) -> f64 {
        self.round_rel
    }

    /// [`Upper::dot_gap`]'s absolute term (7 times the smallest subnormal), which also covers
    /// the underflow of a's and b's two products.
    #[inline(always)]
    pub fn gap_abs(&self) -> f64 {
        self.gap_abs
    }

    /// Whether `x` (an upper bound of a mapped coordinate's magnitude) is at most
    /// 2^(floor(emax / 2) - 3): then no product of two such values, no difference of two
    /// products and no s can overflow (docs/explanation/accuracy.md, "Values in f64").
    #[inline(always)]
    pub fn value_fits(&self, x: f64) -> bool {
        x <= self.value_limit
    }

    /// An upper bound of the distance between the chip's value of a dot product
    /// `(a0 b0 + a1 b1) + (a2 b2 + c)` (its own rounding, any mode) and the same expression
    /// evaluated in f64, from an enclosure `mag` of `|a0 b0| + |a1 b1| + |a2 b2| + |c|`,
    /// while the chip does not overflow (docs/explanation/accuracy.md, "Deciding T.CHECK in f64").
    #[inline(always)]
    pub fn dot_gap(&self, mag: f64) -> f64 {
        self.add(self.mul(mag, self.gap_rel), self.gap_abs)
    }

    /// An upper bound of the chip's `round_up(w)` from the f64 `w` of enclosed operands.
    #[inline(always)]
    pub fn up(&self, w: f64) -> f64 {
        w * self.k + self.q
    }

    #[inline(always)]
    pub fn add(&self, x: f64, y: f64) -> f64 {
        self.up(x + y)
    }

    #[inline(always)]
    pub fn mul(&self, x: f64, y: f64) -> f64 {
        self.up(x * y)
    }

    /// [`Format::scale_up`]: c's value is an exact f64 (at most F + 3 significant bits).
    #[inline(always)]
    pub fn scale(&self, x: f64, c: ScaleConst) -> f64 {
        self.up(x * c.value())
    }

    /// Whether `x` (an enclosure, or a chip value) is below the largest finite value: false
    /// for infinities and NaN too.
    #[inline(always)]
    pub fn fits(&self, x: f64) -> bool {
        x.abs() < self.limit
    }
}

/// A lower bound of a sum or product of non-negative reals from the f64 result `w` of the
/// same operation on f64 numbers: the next f64 below `w`, or 0 (docs/explanation/accuracy.md, "Proving
/// T.CHECK uncertain"). Round to nearest leaves the exact result above the f64 number just
/// below its rounded one (else that number would be nearer), underflow and overflow too.
#[inline(always)]
pub fn down(w: f64) -> f64 {
    if w > 0.0 {
        f64::from_bits(w.to_bits() - 1)
    } else {
        0.0
    }
}

#[inline(always)]
pub fn add_down(x: f64, y: f64) -> f64 {
    down(x + y)
}

#[inline(always)]
pub fn mul_down(x: f64, y: f64) -> f64 {
    down(x * y)
}

static FORCED: AtomicBool = AtomicBool::new(false);

/// Check mode: every decision of a fast path (the DOP unit's f64 estimate, T.CHECK's
/// enclosure) is compared with the bit-exact path, and a difference panics. On when the
/// environment variable `CCHIP_CHECK_FAST` is `1` (`cchip` refuses a value but 1 or 0 before
/// any work; elsewhere it panics here), or after [`force_check`].
#[inline]
pub fn checking() -> bool {
    static ENV: OnceLock<bool> = OnceLock::new();
    FORCED.load(Ordering::Relaxed)
        || *ENV.get_or_init(|| {
            crate::measure::env_flag(crate::measure::CHECK_FAST).unwrap_or_else(|e| panic!("{e}"))
        })
}

/// Turns check mode on for the rest of the process (tests).
pub fn force_check() {
    FORCED.store(true, Ordering::Relaxed);
}

/// The decisions check mode has compared with the bit-exact path on this thread: DOP tests
/// and triangle-pair tests (tests read it to see that check mode is on and covers every test).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Checked {
    pub dop_tests: u64,
    pub tri_tests: u64,
}

thread_local! {
    static CHECKED: Cell<Checked> = const { Cell::new(Checked { dop_tests: 0, tri_tests: 0 }) };
}

/// The decisions compared on this thread so far.
pub fn checked() -> Checked {
    CHECKED.get()
}

/// Counts one compared decision (`tri`: a triangle pair's, else a DOP test's).
pub(crate) fn count_checked(tri: bool) {
    let mut c = CHECKED.get();
    if tri {
        c.tri_tests += 1;
    } else {
        c.dop_tests += 1;
    }
    CHECKED.set(c);
}

/// For the unit tests of check mode's comparisons (`dop_unit`, `tri_unit`).
#[cfg(test)]
pub(crate) mod check_tests {
    use crate::chip::config::ChipConfig;
    use crate::golden::host::HostSetup;
    use crate::golden::memory::ObjectImage;

    /// Two 6-triangle soups' images on the default chip, and B's setup under a rotation.
    pub struct Small {
        pub cfg: ChipConfig,
        pub a: ObjectImage,
        pub b: ObjectImage,
        pub setup: HostSetup,
    }

    pub fn small_chip() -> Small {
        let cfg = ChipConfig::default();
        let image = |seed| ObjectImage::build(crate::mesh::soup(6, seed).triangles_f64(), &cfg);
        let (a, b) = (image(1), image(2));
        let setup = HostSetup::new(
            &cfg,
            &crate::pose::Pose::new(10.0, 20.0, 30.0, 0.0, 0.0, 0.0),
            b.tree.coord_bound(),
            a.tri_side(&b),
        );
        Small { cfg, a, b, setup }
    }

    /// `compare` panics with a check-mode message.
    pub fn fires(compare: impl FnOnce()) {
        let msg = std::panic::catch_unwind(std::panic::AssertUnwindSafe(compare))
            .expect_err("a wrong answer must panic");
        assert!(
            msg.downcast_ref::<String>()
                .is_some_and(|m| m.contains("check mode")),
            "{msg:?}"
        );
    }
}
