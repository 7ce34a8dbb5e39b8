//! DOPTRF lane (DATE'05 Eq. 10) and the DOP unit (k lanes, NOR-reduced).
//!
//! Lane i computes, in this order (the order of the 15-stage pipeline, see
//! docs/ARCHITECTURE.md):
//! ```text
//! p0 = d_j0 * C_i0    p1 = d_j1 * C_i1    p2 = d_j2 * C_i2      (3 multipliers)
//! u0 = p0 + p1        u1 = p2 + c_i                              (2 adders)
//! u  = u0 + u1                                                  (adder)
//! s  = u + e_opp(i)                                             (adder)
//! flag_i = s < 0                                                (sign test; NaN is not < 0)
//! ```
//! d is the tumbled DOP (object B), e the aligned DOP (object A). flag_i says "separated
//! along B_i": the bound d'_i of B's DOP along B_i lies below A's lower end -e_opp(i).
//! The pair overlaps iff no flag is set (NOR).

use crate::dop::HostSetup;
use crate::format::{Format, Rounding};

/// s_i of one lane.
#[inline]
pub fn lane(f: Format, r: Rounding, d: [f64; 3], cm: [f64; 3], c: f64, e: f64) -> f64 {
    let p0 = f.mul(d[0], cm[0], r);
    let p1 = f.mul(d[1], cm[1], r);
    let p2 = f.mul(d[2], cm[2], r);
    let u0 = f.add(p0, p1, r);
    let u1 = f.add(p2, c, r);
    let u = f.add(u0, u1, r);
    f.add(u, e, r)
}

/// The DOP unit: D.KLMSEL routes d_j0, d_j1, d_j2 to each lane, the k flags are NOR-ed.
/// `d` is B's (tumbled) DOP, `e` A's (aligned) DOP.
pub fn dop_overlap(f: Format, r: Rounding, setup: &HostSetup, d: &[f64], e: &[f64]) -> bool {
    let k = d.len();
    (0..k).all(|i| {
        let j = setup.j[i];
        let s = lane(f, r, [d[j[0] as usize], d[j[1] as usize], d[j[2] as usize]], setup.cmat[i], setup.cvec[i], e[(i + k / 2) % k]);
        let separated = s < 0.0;
        !separated
    })
}
