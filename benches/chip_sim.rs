//! Simulated clocks per second of the whole collision chip in the three simulators of
//! this project, on the same queries, every trace checked against the checked-in one
//! (`vectors/chip/<query>.expect`), the ratios measured in one run:
//!
//! ```sh
//! cargo bench --bench chip_sim
//! ```
//!
//! * the cycle model (`src/cycle`), clock by clock (no idle stretch skipped) and as
//!   `cycle::run_query` runs it (waits skipped), best of several runs;
//! * Verilator (skipped, with a note, if `verilator` is not on PATH): `scripts/run-chip.sh`
//!   builds the exported chip (about 5 minutes, stated) and checks the traces; the binary
//!   is then timed as a whole process, best of 3. Its start-up (reading the memory image,
//!   building the model) is the time of the shortest query and is stated apart; the
//!   steady state is the long query's time less the start-up;
//! * rust-hdl's simulator on the short query (it runs the chip at about 25 clocks per
//!   second: the long one would take an hour).

use collision_chip::cycle::chip::Chip;
use collision_chip::cycle::drive::{run_query as drive_query, Drive};
use collision_chip::cycle;
use collision_chip::chip::rtl::QUEUE_BITS;
use collision_chip::harness::chip_io::{big_stack, drive, queries, run_query, with_chip, ChipQuery, ChipTrace, OnChip, PreparedQuery, QueryImage, RtlPorts};
use std::path::Path;
use std::process::Command;
use std::time::Instant;

/// Short (every simulator), empty (Verilator's start-up), long (at least 10^5 cycles).
const SHORT: &str = "sphere_fifo_first";
const EMPTY: &str = "apart_lifo_first";
const LONG: &str = "big_patch_lifo_all_slow_host";

fn expect(root: &Path, q: &str) -> String {
    std::fs::read_to_string(root.join(format!("vectors/chip/{q}.expect"))).expect("the expected trace")
}

fn query(name: &str) -> (ChipQuery, PreparedQuery) {
    let q = queries().into_iter().find(|q| q.name == name).expect("the query is in the set");
    let p = q.prepare().unwrap_or_else(|e| panic!("{name}: {e}"));
    (q, p)
}

/// The cycle model on a query, best of `reps`: (seconds clock by clock, seconds skipping).
fn cycle_model(root: &Path, name: &str, reps: usize) -> (u64, f64, f64) {
    let (q, p) = query(name);
    let want = expect(root, name);
    let params = q.params();
    let setup = p.chip.setup(&q.pose);
    let (mut by_clock, mut skipping, mut cycles) = (f64::INFINITY, f64::INFINITY, 0);
    for _ in 0..reps {
        let t = Instant::now();
        let mut c = Chip::new(&p.chip.cfg, params, &p.chip.a, &p.chip.b, &setup, true).unwrap();
        let d = Drive { memory: q.timing.into(), word_bits: p.chip.layout.word_bits(), reader: q.reader, words: p.chip.image_words(), max_cycles: 10_000_000 };
        let writes = p.chip.control_writes(q.order, q.mode, &params);
        let tr = drive_query(&mut c, &writes, &d, false, |_, _| Ok(()), None).unwrap();
        by_clock = by_clock.min(t.elapsed().as_secs_f64());
        assert_eq!(tr.text(), want, "{name}: the cycle model's trace (clock by clock)");
        cycles = tr.cycles;
        let t = Instant::now();
        let (tr, _) = cycle::run_query(&p.chip, &setup, q.order, q.mode, params, q.reader, 10_000_000, cycle::Record { counters: true, ..Default::default() }).unwrap();
        skipping = skipping.min(t.elapsed().as_secs_f64());
        assert_eq!(tr.text(), want, "{name}: the cycle model's trace (waits skipped)");
    }
    (cycles, by_clock, skipping)
}

fn rust_hdl(root: &Path, name: &str) -> (u64, f64) {
    let (q, p) = query(name);
    let img = p.image.clone();
    struct Timed(QueryImage, ChipQuery);
    impl OnChip for Timed {
        type Out = (ChipTrace, f64);
        fn run<C: RtlPorts>(self, mut chip: C) -> Self::Out {
            let (img, q) = (self.0, self.1);
            let t = Instant::now();
            let tr = run_query(&mut chip, &img, &drive(&img, q.timing.into(), q.reader, 1_000_000)).expect("the query finishes");
            (tr, t.elapsed().as_secs_f64())
        }
    }
    let kind = q.chip;
    let (tr, secs) = big_stack(move || with_chip::<QUEUE_BITS, { QUEUE_BITS + 1 }, { QUEUE_BITS - 1 }, _>(kind, Timed(img, q)));
    assert_eq!(tr.text(), expect(root, name), "rust-hdl's trace of {name}");
    (tr.cycles, secs)
}

/// Builds and checks the exported chip on the three queries with scripts/run-chip.sh, then
/// times its binary per query (best of 3). `Err` (a note) only if verilator is missing.
fn verilator(root: &Path) -> Result<Vec<f64>, String> {
    if !Command::new("verilator").arg("--version").output().is_ok_and(|o| o.status.success()) {
        return Err("verilator not installed (apt-get install verilator)".into());
    }
    let t = Instant::now();
    let out = Command::new(root.join("scripts/run-chip.sh")).args([SHORT, EMPTY, LONG]).current_dir(root).output().expect("scripts/run-chip.sh");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success() && stdout.contains("3 passed, 0 failed"), "scripts/run-chip.sh:\n{stdout}{}", String::from_utf8_lossy(&out.stderr));
    println!("Verilator: built (if not yet built) and checked the traces in {:.0} s", t.elapsed().as_secs_f64());
    let bin = root.join("target/verilog/verilator/chip_e8m15_k6/obj/Vchip");
    let mut times = vec![];
    for name in [SHORT, EMPTY, LONG] {
        let (q, _) = query(name);
        let args = [
            format!("+mem=vectors/chip/{name}.mem"),
            format!("+host=vectors/chip/{name}.host"),
            format!("+latency={}", q.timing.latency),
            format!("+interval={}", q.timing.interval),
            format!("+reader={}", q.reader.period),
            "+max_cycles=2000000".into(),
        ];
        let mut best = f64::INFINITY;
        for _ in 0..3 {
            let t = Instant::now();
            let out = Command::new(&bin).args(&args).current_dir(root).output().unwrap_or_else(|e| panic!("{}: {e}", bin.display()));
            best = best.min(t.elapsed().as_secs_f64());
            assert!(out.status.success() && String::from_utf8_lossy(&out.stdout).contains("done "), "{} failed", bin.display());
        }
        times.push(best);
    }
    Ok(times)
}

fn main() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let (short_cycles, c_short, c_short_skip) = cycle_model(root, SHORT, 20);
    let (long_cycles, c_long, c_long_skip) = cycle_model(root, LONG, 5);
    let (_, hdl) = rust_hdl(root, SHORT);
    let rate = |cycles: u64, s: f64| cycles as f64 / s;
    println!("| simulator | query | cycles | seconds | clocks/s |\n|---|---|---:|---:|---:|");
    let row = |sim: &str, q: &str, cycles: u64, s: f64| println!("| {sim} | {q} | {cycles} | {s:.4} | {:.0} |", rate(cycles, s));
    row("cycle model, clock by clock", SHORT, short_cycles, c_short);
    row("cycle model, waits skipped", SHORT, short_cycles, c_short_skip);
    row("rust-hdl 0.46", SHORT, short_cycles, hdl);
    row("cycle model, clock by clock", LONG, long_cycles, c_long);
    row("cycle model, waits skipped", LONG, long_cycles, c_long_skip);
    let vl = verilator(root);
    match &vl {
        Ok(t) => {
            let (short, empty, long) = (t[0], t[1], t[2]);
            row("Verilator -O3, whole process", SHORT, short_cycles, short);
            row("Verilator -O3, whole process", LONG, long_cycles, long);
            let steady = long - empty;
            println!("| Verilator -O3, steady state (less start-up {empty:.3} s) | {LONG} | {long_cycles} | {steady:.4} | {:.0} |", rate(long_cycles, steady));
            println!(
                "\ncycle model (clock by clock) / Verilator steady state: {:.0}x clocks/s on {LONG}",
                rate(long_cycles, c_long) / rate(long_cycles, steady)
            );
        }
        Err(note) => println!("\nVerilator: {note}; its rows are not measured."),
    }
    println!("cycle model (clock by clock) / rust-hdl: {:.0}x clocks/s on {SHORT}", rate(short_cycles, c_short) / rate(short_cycles, hdl));
}
