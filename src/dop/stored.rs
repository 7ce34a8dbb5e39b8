//! Stored DOP precision ([`DopBits`](crate::chip::config::DopBits)): a node record below the root stores its DOPs as
//! `b`-bit integers relative to an ancestor's, the way GPU ray tracers store child boxes
//! (Ylitie, Karras and Laine, HPG 2017) and Raabe et al. store DOPs on their FPGA.
//!
//! A record (the `records` layout) holds a treelet: a node's children, and as many levels
//! below them as fit ([`Layout::levels`](crate::chip::layout::Layout)); once for all, the
//! treelet root's k distances `r_i` in the DOP format and a power of two `2^e_i` per plane.
//! A node's plane i is the code `q_i`, an integer in `0 .. 2^b`, and the chip's decode
//! stage gives
//!
//! `d'_i = r_i ⊖ q_i 2^e_i`,
//!
//! one subtraction in the DOP format with the DOP datapath's rounding ([`decode`]). The host
//! ([`encode`]) picks the largest `q_i` for which `d'_i >= d_i`, the node's stored distance,
//! so every decoded DOP contains the stored one, which contains the node's triangles
//! (docs/explanation/accuracy.md, "Stored DOP precision"): a coarser DOP can add overlaps,
//! never lose one. `q_i = 0` decodes to `r_i >= d_i` exactly, so a code always exists.

use crate::chip::layout::exp_range;
use crate::format::{Format, Rounding};

/// `2^e`, for the exponents of [`exp_range`] (within f64's normal range).
fn pow2(e: i32) -> f64 {
    f64::from_bits(((e + 1023) as u64) << 52)
}

/// The decode stage: `r ⊖ q 2^e` in `fmt`, rounded as the DOP datapath rounds.
pub fn decode(fmt: Format, rnd: Rounding, r: f64, q: u32, e: i32) -> f64 {
    fmt.sub(r, q as f64 * pow2(e), rnd)
}

/// The exponent of one plane of a record: the smallest of [`exp_range`] whose `b`-bit codes
/// reach the widest gap `gap = max(r - d)` of the record's nodes (or the largest).
pub fn plane_exp(fmt: Format, bits: u32, gap: f64) -> i32 {
    let (lo, hi) = exp_range(fmt, bits);
    let top = ((1u32 << bits) - 1) as f64;
    if gap.is_nan() || gap <= top * pow2(lo) {
        return lo;
    }
    // log2 is a guess within one of the answer, which the loops settle exactly.
    let mut e = ((gap / top).log2().ceil() as i32).clamp(lo, hi);
    while e > lo && top * pow2(e - 1) >= gap {
        e -= 1;
    }
    while e < hi && top * pow2(e) < gap {
        e += 1;
    }
    e
}

/// The host's code for a distance `d` below its record's reference `r` at exponent `e`: the
/// largest `q < 2^b` whose [`decode`] is at least `d` (the widest step that still contains
/// it). Non-finite distances keep `q = 0`, which decodes to `r` itself.
pub fn encode(fmt: Format, rnd: Rounding, bits: u32, r: f64, d: f64, e: i32) -> u32 {
    let top = (1u32 << bits) - 1;
    if !(r.is_finite() && d.is_finite()) {
        return 0;
    }
    let holds = |q: u32| decode(fmt, rnd, r, q, e) >= d;
    // The f64 quotient is the answer but where rounding moved it (decode is monotone in q):
    // then a binary search over [0, top], whose 0 always holds.
    let guess = ((r - d) / pow2(e)).floor().clamp(0.0, top as f64) as u32;
    if holds(guess) && (guess == top || !holds(guess + 1)) {
        return guess;
    }
    let (mut lo, mut hi) = (0, top);
    while lo < hi {
        let mid = lo + (hi - lo).div_ceil(2);
        if holds(mid) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    lo
}

/// One record's exponents: per plane, [`plane_exp`] of the widest gap of its nodes below
/// its reference `r` (`nodes`: their stored distances).
pub fn record_exps<'a>(
    fmt: Format,
    bits: u32,
    r: &[f64],
    nodes: impl Iterator<Item = &'a [f64]>,
) -> Vec<i16> {
    let mut gap = vec![0.0f64; r.len()];
    for d in nodes {
        for i in 0..r.len() {
            let g = r[i] - d[i];
            if g.is_finite() {
                gap[i] = gap[i].max(g);
            }
        }
    }
    gap.iter()
        .map(|&g| plane_exp(fmt, bits, g) as i16)
        .collect()
}

/// A node's decoded distances from its stored ones `d` (replaced), its record's reference
/// `r` and exponents `e`: [`encode`] then [`decode`], plane by plane.
pub fn round_trip(fmt: Format, rnd: Rounding, bits: u32, r: &[f64], e: &[i16], d: &mut [f64]) {
    for i in 0..d.len() {
        let q = encode(fmt, rnd, bits, r[i], d[i], e[i] as i32);
        d[i] = decode(fmt, rnd, r[i], q, e[i] as i32);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chip::layout::exp_field_bits;

    const B32: Format = Format::BINARY32;
    const UP: Rounding = Rounding::TowardPositive;

    /// By hand: r = 10 over children at 3 and 9 (gap 7), 4 bits: 15 steps of 2^-1 reach
    /// 7.5, at least 7, and 15 of 2^-2 only 3.75, so e = -1; d = 3 is 14 steps (10 - 7 = 3,
    /// exact), d = 3.1 is 13 (3.5: 14 steps would be 3, below 3.1), d = 9 is 2, d = 10 is 0.
    #[test]
    fn codes_by_hand() {
        assert_eq!(plane_exp(B32, 4, 7.0), -1);
        assert_eq!(plane_exp(B32, 4, 7.5), -1);
        assert_eq!(plane_exp(B32, 4, 7.6), 0);
        assert_eq!(plane_exp(B32, 4, 0.0), -149, "no gap: the smallest step");
        for (d, q, back) in [
            (3.0, 14, 3.0),
            (3.1, 13, 3.5),
            (9.0, 2, 9.0),
            (10.0, 0, 10.0),
        ] {
            assert_eq!(encode(B32, UP, 4, 10.0, d, -1), q, "d = {d}");
            assert_eq!(decode(B32, UP, 10.0, q, -1), back, "d = {d}");
        }
        // binary32 at 8 bits: exponents -149 ..= 120, 270 of them: 9 bits.
        assert_eq!(exp_range(B32, 8), (-149, 120));
        assert_eq!(exp_field_bits(B32, 8), 9);
    }

    /// Where the format cannot tell the steps apart (binary32 at 2^24: ulp 2, steps of 2^-3),
    /// many codes decode to the same value; the code is the largest that still holds, as a
    /// scan of all 256 finds.
    #[test]
    fn the_search_finds_the_widest_code_that_holds() {
        let (r, d) = (16_777_218.0, 16_777_214.0);
        for rnd in [UP, Rounding::NearestEven] {
            let q = encode(B32, rnd, 8, r, d, -3);
            let scan = (0..256u32)
                .filter(|&q| decode(B32, rnd, r, q, -3) >= d)
                .max()
                .unwrap();
            assert_eq!(q, scan, "{rnd:?}");
            assert!(decode(B32, rnd, r, q, -3) >= d);
        }
    }
}
