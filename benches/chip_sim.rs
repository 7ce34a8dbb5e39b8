//! Simulated clocks per second of the whole collision chip (`rtl/chip_e8m15_k6.v`) on one
//! query of `vectors/chip/` in rust-hdl's simulator and in Verilator, as a ratio: the
//! baseline the fast cycle model is to beat (DESIGN.md: at least 10x Verilator).
//!
//! ```sh
//! cargo bench --bench chip_sim
//! ```
//!
//! 1. rust-hdl: the query through `e8m15::CollisionChip` with `chip_io::run_query`, timed
//!    (the chip is built first, untimed); its trace must equal `vectors/chip/<query>.expect`.
//! 2. Verilator (skipped, with a note, if `verilator` is not on PATH): `scripts/run-chip.sh`
//!    builds the exported chip (about 5 minutes the first time) and checks the same trace;
//!    then the built binary runs the query again, best of 5, timed as a whole process (so it
//!    includes reading the memory image: a lower bound of the model's speed).
//!
//! Both simulate the register writes, the start clock and the query; the table counts them
//! all.

use collision_chip::rtl::chip_io::{queries, run_query, CHIP_CONFIG};
use collision_chip::rtl::e8m15::chip_top;
use std::path::Path;
use std::process::Command;
use std::time::Instant;

const QUERY: &str = "sphere_fifo_first";

fn main() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let q = queries().into_iter().find(|q| q.name == QUERY).expect("the query is in the set");
    let p = q.prepare().unwrap_or_else(|e| panic!("{QUERY}: {e}"));
    let expect = std::fs::read_to_string(root.join(format!("vectors/chip/{QUERY}.expect"))).expect("the expected trace");
    let img = p.image.clone();
    let (trace, secs) = std::thread::Builder::new()
        .stack_size(1 << 30)
        .spawn(move || {
            let mut chip = chip_top::<8, 9>(CHIP_CONFIG.dop_rounding.op(), CHIP_CONFIG.tri_rounding);
            let t = Instant::now();
            let tr = run_query(&mut chip, &img, q.timing, 100_000, |_, _| {}).expect("the query finishes");
            (tr, t.elapsed().as_secs_f64())
        })
        .unwrap()
        .join()
        .unwrap();
    assert_eq!(trace.text(), expect, "rust-hdl's trace differs from vectors/chip/{QUERY}.expect");
    let clocks = (p.image.writes.len() + 1) as u64 + trace.cycles;
    println!("{QUERY}: {} query cycles, {clocks} clocks with the register writes", trace.cycles);
    let mut rows = vec![("rust-hdl 0.46 (`simulate`)", secs)];
    match verilator(root, q.timing.latency, q.timing.interval) {
        Ok(s) => rows.push(("Verilator (`--binary -O3`)", s)),
        Err(note) => println!("\nVerilator: {note}; only the rust-hdl row is measured."),
    }
    println!("\n| simulator | clocks | seconds | clocks/s |\n|---|---:|---:|---:|");
    for (sim, s) in &rows {
        println!("| {sim} | {clocks} | {s:.3} | {:.0} |", clocks as f64 / s);
    }
    if let [(_, hdl), (_, vl)] = rows[..] {
        println!("\nVerilator / rust-hdl: {:.0}x clocks/s (the collision chip, {QUERY})", hdl / vl);
    }
}

/// Builds and checks the exported chip with scripts/run-chip.sh, then times its binary.
/// `Err` (a note, not a failure) only if verilator is not installed.
fn verilator(root: &Path, latency: u32, interval: u32) -> Result<f64, String> {
    let ok = Command::new("verilator").arg("--version").output().is_ok_and(|o| o.status.success());
    if !ok {
        return Err("verilator not installed (apt-get install verilator)".into());
    }
    let t = Instant::now();
    let out = Command::new(root.join("scripts/run-chip.sh")).arg(QUERY).current_dir(root).output().expect("scripts/run-chip.sh");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success() && stdout.contains("1 passed, 0 failed"), "scripts/run-chip.sh {QUERY}:\n{stdout}{}", String::from_utf8_lossy(&out.stderr));
    println!("run-chip.sh: built and checked in {:.1} s", t.elapsed().as_secs_f64());
    let bin = root.join("target/verilog/verilator/chip/obj/Vchip");
    let args = [
        format!("+mem=vectors/chip/{QUERY}.mem"),
        format!("+host=vectors/chip/{QUERY}.host"),
        format!("+latency={latency}"),
        format!("+interval={interval}"),
    ];
    let mut best = f64::INFINITY;
    for _ in 0..5 {
        let t = Instant::now();
        let out = Command::new(&bin).args(&args).current_dir(root).output().unwrap_or_else(|e| panic!("{}: {e}", bin.display()));
        best = best.min(t.elapsed().as_secs_f64());
        assert!(out.status.success() && String::from_utf8_lossy(&out.stdout).contains("done "), "{} failed", bin.display());
    }
    Ok(best)
}
