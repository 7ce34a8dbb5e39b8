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
/// A's distances meets minus one sibling's d' (either's, per DOP) up to two ulps above (no
/// flag) or, at one lane in k on average, one ulp below (a flag), so that both verdicts
/// come out. After each bundle: the
/// verdicts so far, NOR of `golden::doptrf::separated` over the DOP's bundles
/// (`golden::dop_unit::compare_bundles`).
fn compare_bank_vectors() -> String {
    use crate::golden::dop_unit::compare_bundles;
    use crate::golden::doptrf::separated;
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
            let base = if rng.random() { &dl } else { &dr };
            crate::harness::wscg03_io::near_flags(&mut rng, fmt, base, &mut e);
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

/// `dprime_memory_k24_b32`: WSCG'03's d' memory for k = 24 (`rtl::b32::DprimeMemory`).
pub(super) fn dprime_memory_unit() -> Unit {
    Unit {
        name: "dprime_memory_k24_b32".into(),
        latency: crate::chip::rtl::DPRIME_READ_LATENCY as u32,
        verilog: Box::new(|| crate::rtl::b32::verilog_dprime_memory(24)),
        vectors: Box::new(|| dprime_memory_vectors(24)),
    }
}

/// Vectors of the d' memory of `k` directions: a preload of the write port, three DOPs'
/// random d' (left and right) in the DOTADD units' lane order into sets 0, 1 and 0 again,
/// then `rd_set rd_entry dl dr` for every entry of both sets: the last DOP of each set in
/// the order of A's distances (`golden::dop_unit::compare_bundles`; slots past k are never
/// written and not read: k = 24 fills three entries).
fn dprime_memory_vectors(k: usize) -> String {
    use crate::golden::dop_unit::compare_bundles;
    let fmt = Format::BINARY32;
    let mut out = String::new();
    let _ = writeln!(out, "// preload: wr_valid wr_set wr_lane wr_l wr_r");
    let _ = writeln!(out, "// rd_set rd_entry dl dr");
    let _ = writeln!(out, "// latency: {}", crate::chip::rtl::DPRIME_READ_LATENCY);
    let _ = writeln!(out, "// dprime_memory_k{k}_b32: lane i's d' stored at opp(i), read an entry of 8 per clock; golden: golden::dop_unit::compare_bundles");
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0xd9);
    let mut sets: [Vec<Vec<f64>>; 2] = [vec![], vec![]];
    for set in [0, 1, 0] {
        let dop: Vec<Vec<f64>> = (0..2)
            .map(|_| {
                (0..k)
                    .map(|_| fmt.from_bits(operand(&mut rng, fmt)))
                    .collect()
            })
            .collect();
        for (i, (l, r)) in dop[0].iter().zip(&dop[1]).enumerate() {
            let (l, r) = (fmt.to_bits(*l), fmt.to_bits(*r));
            let _ = writeln!(out, "@ 1 {set} {i:02x} {l:08x} {r:08x}");
        }
        sets[set] = dop;
    }
    let e = vec![0.0; k];
    for (set, dop) in sets.iter().enumerate() {
        let bundles = [0, 1].map(|s| compare_bundles(&dop[s], &e, 8));
        for (entry, (bl, br)) in bundles[0].iter().zip(&bundles[1]).enumerate() {
            let word = |s: usize| -> String {
                [bl, br][s]
                    .iter()
                    .rev()
                    .map(|&(d, _)| format!("{:08x}", fmt.to_bits(d)))
                    .collect()
            };
            let _ = writeln!(out, "{set} {entry} {} {}", word(0), word(1));
        }
    }
    out
}

/// `wscg03_dop_unit_k24_b32`: WSCG'03's DOP Unit for k = 24 (`rtl::b32::Wscg03DopUnit`).
pub(super) fn wscg03_dop_unit_unit() -> Unit {
    Unit {
        name: "wscg03_dop_unit_k24_b32".into(),
        latency: 1,
        verilog: Box::new(crate::rtl::b32::verilog_wscg03_dop_unit24),
        vectors: Box::new(|| wscg03_dop_unit_vectors(24)),
    }
}

/// Vectors of WSCG'03's DOP Unit of `k` directions, a clock per line: a preload of its MMM
/// (a random host setup, every lane rounding upward), then 1,500 clocks of
/// `harness::wscg03_io::dop_unit_traffic` (loads into one d' set while aligned DOPs meet the
/// other's d', with idle clocks), each line its inputs and the outputs after its rising edge,
/// the clocked model's (`cycle::wscg03::dop_unit::ClockedDopUnit`), which the rust-hdl unit
/// equals every clock (tb/rtl_dop.rs).
fn wscg03_dop_unit_vectors(k: usize) -> String {
    use crate::harness::wscg03_io::{dop_unit_traffic, FORMAT};
    let r = crate::format::Rounding::TowardPositive;
    let traffic = dop_unit_traffic(k, r, 0xd0, 1500);
    let bus = |xs: &[f64; 8]| -> String {
        xs.iter()
            .rev()
            .map(|&x| format!("{:08x}", FORMAT.to_bits(x)))
            .collect()
    };
    let mut out = String::new();
    let _ = writeln!(out, "// preload: load_en load_addr load_data");
    let _ = writeln!(out, "// t_valid t_set t_side t_entry t_last t_data a_valid a_first a_lanes a_set a_entry e busy overlap_l overlap_r flags_valid");
    let _ = writeln!(out, "// latency: 1");
    let _ = writeln!(out, "// wscg03_dop_unit_k{k}_b32: WSCG'03's DOP Unit, one line per clock: inputs, then the outputs after that clock's rising edge; golden: cycle::wscg03::dop_unit::ClockedDopUnit (golden::doptrf::transformed, separated)");
    for (a, d) in crate::harness::chip_io::dop_unit_setup_words(FORMAT, r, &traffic.setup) {
        let _ = writeln!(out, "@ 1 {a:02x} {d:08x}");
    }
    let zero = "0".repeat(64);
    for (c, o) in traffic.clocks.iter().zip(&traffic.outs) {
        let t = c.t.as_ref().map_or(format!("0 0 0 0 0 {zero}"), |t| {
            let (set, side, entry, last) = (t.set, t.side, t.entry, t.last as u8);
            format!("1 {set} {side} {entry} {last} {}", bus(&t.data))
        });
        let a = c.a.as_ref().map_or(format!("0 0 00 0 0 {zero}"), |a| {
            let (first, lanes, set, entry) = (a.first as u8, a.lanes, a.set, a.entry);
            format!("1 {first} {lanes:02x} {set} {entry} {}", bus(&a.e))
        });
        let busy = o.busy[0] as u8 | (o.busy[1] as u8) << 1;
        let [l, r] = o.overlap.map(|v| v as u8);
        let _ = writeln!(out, "{t} {a} {busy} {l} {r} {}", o.flags_valid as u8);
    }
    out
}

/// `list_stack_a8`: WSCG'03's Stack Engine's lists with SRAMs of 256 pointers
/// (`rtl::wscg03::stack_engine::ListStack<8>`).
pub(super) fn list_stack_unit() -> Unit {
    Unit {
        name: "list_stack_a8".into(),
        latency: 1,
        verilog: Box::new(crate::rtl::wscg03::stack_engine::verilog_list_stack8),
        vectors: Box::new(crate::harness::wscg03_io::list_stack_vectors),
    }
}

/// `tri_input_b32`: WSCG'03's Triangle Unit's input stage (`rtl::b32::TriInput`).
pub(super) fn tri_input_unit() -> Unit {
    Unit {
        name: "tri_input_b32".into(),
        latency: 0,
        verilog: Box::new(crate::rtl::b32::verilog_tri_input),
        vectors: Box::new(crate::harness::wscg03_io::tri_unit::tri_input_vectors),
    }
}

/// `memory_controller_b32`: WSCG'03's Memory Controller (`rtl::b32::MemoryController`).
pub(super) fn memory_controller_unit() -> Unit {
    Unit {
        name: "memory_controller_b32".into(),
        latency: 0,
        verilog: Box::new(crate::rtl::b32::verilog_memory_controller),
        vectors: Box::new(crate::harness::wscg03_io::memory_controller::memory_controller_vectors),
    }
}

/// `sequencer`: WSCG'03's Stack Engine's sequencer (`rtl::wscg03::sequencer::Sequencer`).
pub(super) fn sequencer_unit() -> Unit {
    Unit {
        name: "sequencer".into(),
        latency: 0,
        verilog: Box::new(crate::rtl::wscg03::sequencer::verilog_sequencer),
        vectors: Box::new(crate::harness::wscg03_io::sequencer::sequencer_vectors),
    }
}
