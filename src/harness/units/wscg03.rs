//! WSCG'03's units beside DATE'05's in the registry: their Verilog and golden vectors.

use super::{operand, Unit, RANDOM_CASES};
use crate::format::Format;
use rand::{Rng, SeedableRng};
use std::fmt::Write;

/// `compare_bank_b32`: WSCG'03's bank of 16 compare units (`rtl::b32::CompareBank`).
pub(super) fn compare_bank_unit() -> Unit {
    Unit {
        name: "compare_bank_b32".into(),
        latency: crate::chip::rtl::COMPARE_BANK_LATENCY as u32,
        verilog: Box::new(crate::rtl::b32::verilog_compare_bank),
        vectors: Box::new(compare_bank_vectors),
    }
}

/// Vectors `first lanes e dl dr overlap_l overlap_r` of the compare bank, a bundle per line:
/// DOPs of k = 24, 26, 6 and 14 (three, four, one and two bundles; the lanes past k masked
/// by `lanes` and filled with -1, which would flag). Half of them random format values; in
/// the other half the right sibling's d' equal the left's but for a few lanes, and each of
/// A's distances meets minus one sibling's d' (either's, per DOP) up to two ulps above (no flag) or, at one lane in k on
/// average, one ulp below (a flag), so that both verdicts come out. After each bundle: the
/// verdicts so far, NOR of `golden::doptrf::separated` over the DOP's bundles
/// (`golden::dop_unit::compare_bundles`).
fn compare_bank_vectors() -> String {
    use crate::golden::dop_unit::compare_bundles;
    use crate::golden::doptrf::separated;
    use crate::golden::klmsel::opposite_lane;
    let fmt = Format::BINARY32;
    let q = fmt.min_positive_subnormal();
    let mut out = String::new();
    let _ = writeln!(out, "// first lanes e dl dr overlap_l overlap_r");
    let _ = writeln!(
        out,
        "// latency: {}",
        crate::chip::rtl::COMPARE_BANK_LATENCY
    );
    let _ = writeln!(out, "// compare_bank_b32: per bundle of 8 lanes (lane t in bits 32 t..), overlap = no lane so far has d' + e < 0; golden: golden::doptrf::separated, golden::dop_unit::compare_bundles");
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0xc0b);
    let word = |xs: &[(f64, f64)], side: usize| -> String {
        (0..8)
            .rev()
            .map(|t| {
                xs.get(t)
                    .map_or(fmt.to_bits(-1.0), |p| fmt.to_bits([p.0, p.1][side]))
            })
            .map(|x| format!("{x:08x}"))
            .collect()
    };
    for n in 0..RANDOM_CASES / 4 {
        let k = [24, 26, 6, 14][n % 4];
        let draw = |rng: &mut rand_chacha::ChaCha8Rng| -> Vec<f64> {
            (0..k).map(|_| fmt.from_bits(operand(rng, fmt))).collect()
        };
        let dl = draw(&mut rng);
        let (mut dr, mut e) = (draw(&mut rng), draw(&mut rng));
        if n % 2 == 1 {
            for (i, x) in dr.iter_mut().enumerate() {
                if rng.random_range(0..k) != 0 {
                    *x = dl[i];
                }
            }
            let base = if rng.random() { dl.clone() } else { dr.clone() };
            for (g, x) in e.iter_mut().enumerate() {
                let mut y = -base[opposite_lane(k, g)];
                if rng.random_range(0..k) == 0 {
                    y = -fmt.next_up(-y);
                } else {
                    for _ in 0..rng.random_range(0..3) {
                        y = fmt.next_up(y);
                    }
                }
                if !y.is_nan() {
                    *x = y;
                }
            }
        }
        let (bl, br) = (compare_bundles(&dl, &e, 8), compare_bundles(&dr, &e, 8));
        let mut sep = [false; 2];
        for (b, (l, r)) in bl.iter().zip(&br).enumerate() {
            for (s, bundle) in [l, r].iter().enumerate() {
                sep[s] |= bundle.iter().any(|&(d, e)| separated(q, d, e));
            }
            let lanes = (1u32 << l.len()) - 1;
            let _ = writeln!(
                out,
                "{} {lanes:02x} {} {} {} {} {}",
                (b == 0) as u8,
                word(l, 1),
                word(l, 0),
                word(r, 0),
                !sep[0] as u8,
                !sep[1] as u8
            );
        }
    }
    out
}
