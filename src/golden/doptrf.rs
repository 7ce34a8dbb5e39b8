//! The DOPTRF lane (DATE'05 Eq. 10); the DOP unit of k lanes is [`dop_unit`](super::dop_unit),
//! its operand selection [`klmsel`](super::klmsel).
//!
//! Lane i computes, in this order (the order of the 15-stage pipeline, see
//! docs/explanation/architecture.md):
//! ```text
//! p0 = d_j0 * C_i0    p1 = d_j1 * C_i1    p2 = d_j2 * C_i2      (3 multipliers)
//! u0 = p0 + p1        u1 = p2 + c_i                              (2 adders)
//! u  = u0 + u1                                                  (adder)
//! s  = u + e_opp(i)                                             (adder)
//! flag_i = s < 0                                                (sign test; NaN is not < 0)
//! ```
//! d is the tumbled DOP (object B), e the aligned DOP (object A). flag_i says "separated
//! along B_i": the bound d'_i = u of B's DOP along B_i lies below A's lower end -e_opp(i).
//! The pair overlaps iff no flag is set (NOR).
//!
//! u depends on B's node only (it is row i of the transformed DOP, WSCG'03 Eq. 1), so the
//! traversal engine keeps it per node and query
//! ([`TransformCache`](super::dop_unit::TransformCache)) and decides the flag with
//! [`separated`], which equals `lane(..) < 0` bit for bit (tested).

use crate::format::{Format, Rounding};

/// u_i of lane i: the transformed distance d'_i.
#[inline]
pub fn transformed(f: Format, r: Rounding, d: [f64; 3], cm: [f64; 3], c: f64) -> f64 {
    let p0 = f.mul(d[0], cm[0], r);
    let p1 = f.mul(d[1], cm[1], r);
    let p2 = f.mul(d[2], cm[2], r);
    let u0 = f.add(p0, p1, r);
    let u1 = f.add(p2, c, r);
    f.add(u0, u1, r)
}

/// s_i of one lane.
#[inline]
pub fn lane(f: Format, r: Rounding, d: [f64; 3], cm: [f64; 3], c: f64, e: f64) -> f64 {
    f.add(transformed(f, r, d, cm, c), e, r)
}

/// The flag of lane i, `round(u + e) < 0`, decided exactly in f64: u and e are format
/// values, so u + e is a multiple of the format's smallest subnormal q, and both
/// nearest-even and upward rounding give a negative non-zero result iff u + e <= -q;
/// f64 rounding is monotone and -q is an f64, so the f64 comparison is exact. A NaN or
/// +inf u (overflow) is never separated.
#[inline]
pub fn separated(q: f64, u: f64, e: f64) -> bool {
    u + e <= -q
}
