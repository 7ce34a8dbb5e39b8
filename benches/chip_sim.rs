//! Simulated clocks per second of the whole collision chip in the three simulators of
//! this project, on the same queries, every trace checked against the checked-in one
//! (`vectors/chip/<query>.expect`), the ratios measured in one run, on both chips: the
//! k = 6 e8m15 chip and the papers' k = 24 binary32 chip (`chip_b32_k24`). Every time is
//! CPU seconds of the simulator (this machine is shared: wall time would count the other
//! processes' turns), best of several runs, Verilator's and the cycle model's taken in turns
//! (four rounds; in each, Verilator once per level and query, then the cycle model five
//! times per query) so that both sides of a ratio meet the machine's changing speed alike:
//!
//! ```sh
//! cargo bench --bench chip_sim
//! ```
//!
//! * the cycle model (`src/cycle`) as `cycle::run_query` runs it in
//!   every scene (stretches in which no unit changes state skipped in one step: the
//!   model's speed) and clock by clock (no stretch skipped);
//! * the golden query of the same pose (`query::Chip::query`, the chip's traversal order):
//!   the same DOP tests and leaf pairs (checked), their values computed as the cycle model's
//!   units call them, with no clock, and the golden traversal's own bookkeeping (a few
//!   percent): near what a cycle model whose control cost nothing would take, so its ratio
//!   to Verilator nearly bounds the cycle model's;
//! * Verilator (skipped, with a note, if `verilator` is not on PATH): the hierarchical
//!   build of `scripts/run-chip.sh` with its C++ at -O1 (the script's default) and at -O3
//!   (`CHIP_OPT_FAST=-O3` on a copy of the chip's Verilog, so that both builds stay
//!   cached), each checked on the queries' traces and then timed as a whole process
//!   (its CPU time as a child process). Its start-up (reading the memory image, building the model) is the time of the
//!   root-only query and is subtracted: the steady state is each long query's time less the
//!   start-up. The ratio is against the faster of the two levels. A first build takes
//!   minutes per chip and level (stated);
//! * rust-hdl's simulator on the k = 6 chip's short query (it runs that chip at about 20
//!   clocks per second: a long query would take an hour; the k = 24 chip, slower still, is
//!   left out).

use collision_chip::chip::reg::{Mode, Order};
use collision_chip::chip::rtl::QUEUE_BITS;
use collision_chip::cycle;
use collision_chip::cycle::chip::Chip;
use collision_chip::cycle::drive::{run_query as drive_query, Drive};
use collision_chip::harness::chip_io::{
    big_stack, drive, queries, run_query, with_chip, ChipQuery, ChipTrace, OnChip, PreparedQuery,
    QueryImage, RtlPorts,
};
use collision_chip::traversal::Traversal;
#[path = "common/record.rs"]
mod record;

use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// CPU seconds of this thread: the cycle model's and rust-hdl's time. The machine may be
/// shared: CPU time, not wall time, is what each simulator spends on the query.
fn cpu() -> f64 {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: clock_gettime writes the timespec it is given
    assert_eq!(
        unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) },
        0
    );
    t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9
}

/// CPU seconds (user and system) of the child processes waited for so far: Verilator's.
fn children_cpu() -> f64 {
    // SAFETY: getrusage fills the zeroed rusage it is given
    let mut u: libc::rusage = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { libc::getrusage(libc::RUSAGE_CHILDREN, &mut u) }, 0);
    let secs = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    secs(u.ru_utime) + secs(u.ru_stime)
}

/// The k = 6 chip's short query (every simulator, rust-hdl's).
const SHORT: &str = "sphere_fifo_first";

/// A chip and its queries: the root test only (Verilator's start-up) and long ones (10^4
/// to 10^5 cycles).
struct Bench {
    chip: &'static str,
    empty: &'static str,
    long: &'static [&'static str],
}

/// At k = 6 two long queries: the bunny patch against itself, whose 1,617 reported pairs
/// are all uncertain in e8m15 (T.CHECK's dearest values: both tries and the proof of
/// uncertainty), behind a slow host; and two spheres, 5 of 93 uncertain.
const CHIPS: [Bench; 2] = [
    Bench {
        chip: "chip_e8m15_k6",
        empty: "apart_lifo_first",
        long: &["big_patch_lifo_all_slow_host", "big_sphere_lifo_all"],
    },
    Bench {
        chip: "chip_b32_k24",
        empty: "k24_apart_lifo_first",
        long: &["k24_big_rec_patch_lifo_all"],
    },
];

fn expect(root: &Path, q: &str) -> String {
    std::fs::read_to_string(root.join(format!("vectors/chip/{q}.expect")))
        .expect("the expected trace")
}

fn query(name: &str) -> (ChipQuery, PreparedQuery) {
    let q = queries()
        .into_iter()
        .find(|q| q.name == name)
        .expect("the query is in the set");
    let p = q.prepare().unwrap_or_else(|e| panic!("{name}: {e}"));
    (q, p)
}

/// The cycle model on a query, best of `reps`: (cycles, seconds clock by clock, seconds
/// as `run_query` runs it, seconds of the golden query of the same pairs if the query asks
/// for all pairs: a first-hit query halts where its clocks say, the golden one elsewhere).
fn cycle_model(root: &Path, name: &str, reps: usize) -> (u64, f64, f64, Option<f64>) {
    let (q, p) = query(name);
    let want = expect(root, name);
    let params = q.params();
    let setup = p.chip.setup(&q.pose);
    let (mut by_clock, mut skipping, mut golden, mut cycles) =
        (f64::INFINITY, f64::INFINITY, f64::INFINITY, 0);
    let traversal = if q.order == Order::Lifo {
        Traversal::Lifo
    } else {
        Traversal::Fifo
    };
    for _ in 0..reps {
        // the golden query of the same pose: the DOP tests and leaf pairs the chip makes,
        // their values computed as the cycle model's units call them, without clocks
        let t = cpu();
        let g = (q.mode == Mode::All).then(|| p.chip.query(&q.pose, q.mode, traversal));
        golden = golden.min(cpu() - t);
        // each run's chip dropped before the next is made, as in a scene's sequence of
        // queries: the golden values' per-thread tables are then reused, not allocated anew
        let t = cpu();
        let tr = {
            let mut c = Chip::new(&p.chip.cfg, params, &p.chip.a, &p.chip.b, &setup, true).unwrap();
            let d = Drive {
                memory: q.timing.into(),
                word_bits: p.chip.layout.word_bits(),
                reader: q.reader,
                words: p.chip.image_span(&params.memory),
                max_cycles: 10_000_000,
            };
            let writes = p.chip.control_writes(q.order, q.mode, &params);
            drive_query(&mut c, &writes, &d, false, |_, _| Ok(()), false).unwrap()
        };
        by_clock = by_clock.min(cpu() - t);
        assert_eq!(
            tr.text(),
            want,
            "{name}: the cycle model's trace (clock by clock)"
        );
        cycles = tr.cycles;
        let t = cpu();
        let (tr, _) = cycle::run_query(
            &p.chip,
            &setup,
            q.order,
            q.mode,
            params,
            q.reader,
            10_000_000,
            cycle::Record {
                counters: true,
                ..Default::default()
            },
        )
        .unwrap();
        skipping = skipping.min(cpu() - t);
        assert_eq!(
            tr.text(),
            want,
            "{name}: the cycle model's trace (waits skipped)"
        );
        if let Some(g) = g {
            let c = g.counters;
            assert_eq!(
                (c.dop_tests, c.tri_tests),
                (tr.dop_tests, tr.tri_tests),
                "{name}: the golden query tests the chip's pairs"
            );
        }
    }
    (
        cycles,
        by_clock,
        skipping,
        (q.mode == Mode::All).then_some(golden),
    )
}

fn rust_hdl(root: &Path, name: &str) -> (u64, f64) {
    let (q, p) = query(name);
    let img = p.image.clone();
    struct Timed(QueryImage, ChipQuery);
    impl OnChip for Timed {
        type Out = (ChipTrace, f64);
        fn run<C: RtlPorts>(self, mut chip: C) -> Self::Out {
            let (img, q) = (self.0, self.1);
            let t = cpu();
            let tr = run_query(
                &mut chip,
                &img,
                &drive(&img, q.timing.into(), q.reader, 1_000_000),
            )
            .expect("the query finishes");
            (tr, cpu() - t)
        }
    }
    let kind = q.chip;
    let (tr, secs) = big_stack(move || {
        with_chip::<QUEUE_BITS, { QUEUE_BITS + 1 }, { QUEUE_BITS - 1 }, _>(kind, Timed(img, q))
    });
    assert_eq!(tr.text(), expect(root, name), "rust-hdl's trace of {name}");
    (tr.cycles, secs)
}

/// Builds (if not cached) and checks the exported chip `b.chip` with scripts/run-chip.sh,
/// its C++ at `opt`; its binary. `Err` (a note) only if verilator is missing.
fn verilator(root: &Path, b: &Bench, opt: &str) -> Result<PathBuf, String> {
    if !Command::new("verilator")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
    {
        return Err("verilator not installed (apt-get install verilator)".into());
    }
    let src = root.join(format!("rtl/{}.v", b.chip));
    // the -O1 build is run-chip.sh's own; another level builds from a copy of the Verilog
    // named after it, so that each build keeps its own cache
    let (chip, name) = if opt == "-O1" {
        (src, b.chip.to_string())
    } else {
        let name = format!("{}{}", b.chip, opt.replace('-', "_"));
        let dir = root.join("target/verilog/opt");
        std::fs::create_dir_all(&dir).expect("target/verilog/opt");
        let copy = dir.join(format!("{name}.v"));
        let text = std::fs::read(&src).unwrap_or_else(|e| panic!("{}: {e}", src.display()));
        if std::fs::read(&copy).ok().as_ref() != Some(&text) {
            std::fs::write(&copy, &text).unwrap_or_else(|e| panic!("{}: {e}", copy.display()));
        }
        (copy, name)
    };
    let t = Instant::now();
    let out = Command::new(root.join("scripts/run-chip.sh"))
        .arg("--chip")
        .arg(&chip)
        .arg(b.empty)
        .args(b.long)
        .env("CHIP_OPT_FAST", opt)
        .current_dir(root)
        .output()
        .expect("scripts/run-chip.sh");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let passed = format!("{} passed, 0 failed", b.long.len() + 1);
    assert!(
        out.status.success() && stdout.contains(&passed),
        "scripts/run-chip.sh:\n{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    println!(
        "Verilator {opt} {}: built (if not yet built) and checked the traces in {:.0} s",
        b.chip,
        t.elapsed().as_secs_f64()
    );
    Ok(root.join(format!("target/verilog/verilator/{name}/obj/Vchip")))
}

/// One run of Verilator's binary `bin` on query `q_name`: its CPU seconds, the whole process.
fn verilator_run(root: &Path, bin: &Path, q_name: &str) -> f64 {
    let (q, _) = query(q_name);
    let args = [
        format!("+mem=vectors/chip/{q_name}.mem"),
        format!("+host=vectors/chip/{q_name}.host"),
        format!("+latency={}", q.timing.latency),
        format!("+interval={}", q.timing.interval),
        format!("+reader={}", q.reader.period),
        "+max_cycles=2000000".into(),
    ];
    let t = children_cpu();
    let out = Command::new(bin)
        .args(&args)
        .current_dir(root)
        .output()
        .unwrap_or_else(|e| panic!("{}: {e}", bin.display()));
    assert!(
        out.status.success() && String::from_utf8_lossy(&out.stdout).contains("done "),
        "{} failed",
        bin.display()
    );
    children_cpu() - t
}

fn rate(cycles: u64, s: f64) -> f64 {
    cycles as f64 / s
}

/// A table row printed, and as data (`record::row`): the chip, the simulator, the query.
fn row(chip: &str, sim: &str, q: &str, cycles: u64, s: f64) {
    println!(
        "| {sim} | {q} | {cycles} | {s:.4} | {:.0} |",
        rate(cycles, s)
    );
    record::row(
        "chip_sim",
        json!({ "chip": chip, "simulator": sim, "query": q, "cycles": cycles, "cpu_s": s,
                "clocks_per_s": rate(cycles, s).round() }),
    );
}

/// One chip's rows and, per long query, its ratios to Verilator's faster steady state.
/// The simulators are timed in turns (`ROUNDS` rounds: each Verilator level once on every
/// query, then the cycle model `REPS` times on each), and each keeps its best, so that both
/// sides of a ratio meet the machine's changing speed alike.
fn bench_chip(root: &Path, b: &Bench) {
    const ROUNDS: usize = 4;
    const REPS: usize = 5;
    let levels: Result<Vec<_>, String> = ["-O1", "-O3"]
        .into_iter()
        .map(|opt| verilator(root, b, opt).map(|bin| (opt, bin)))
        .collect();
    let queries: Vec<&str> = std::iter::once(b.empty)
        .chain(b.long.iter().copied())
        .collect();
    let mut models = vec![(0, f64::INFINITY, f64::INFINITY, f64::INFINITY); b.long.len()];
    let mut verilator_best =
        vec![vec![f64::INFINITY; queries.len()]; levels.as_ref().map_or(0, Vec::len)];
    for _ in 0..ROUNDS {
        for ((_, bin), best) in levels.iter().flatten().zip(&mut verilator_best) {
            for (q, best) in queries.iter().zip(best) {
                *best = best.min(verilator_run(root, bin, q));
            }
        }
        for (q, m) in b.long.iter().zip(&mut models) {
            let (cycles, by_clock, skipping, golden) = cycle_model(root, q, REPS);
            *m = (
                cycles,
                m.1.min(by_clock),
                m.2.min(skipping),
                m.3.min(golden.expect("the long queries ask for all pairs")),
            );
        }
    }
    println!("\n{}:\n\n| simulator | query | cycles | CPU seconds | clocks/s |\n|---|---|---:|---:|---:|", b.chip);
    for (q, &(cycles, by_clock, skipping, golden)) in b.long.iter().zip(&models) {
        row(b.chip, "cycle model (run_query)", q, cycles, skipping);
        row(b.chip, "cycle model, clock by clock", q, cycles, by_clock);
        // Its values and the golden traversal, no clocks.
        row(b.chip, "golden query of the same pairs", q, cycles, golden);
    }
    let levels = match levels {
        Ok(levels) => levels,
        Err(note) => {
            println!("\nVerilator: {note}; its rows are not measured.");
            return;
        }
    };
    let mut best: Vec<Option<(&str, f64)>> = vec![None; b.long.len()];
    for ((opt, _), times) in levels.iter().zip(&verilator_best) {
        let empty = times[0];
        println!("| (Verilator {opt}'s start-up, the root-only query: {empty:.3} s) | | | | |");
        for (((q, &secs), &(cycles, ..)), best) in
            b.long.iter().zip(&times[1..]).zip(&models).zip(&mut best)
        {
            let steady = secs - empty;
            row(
                b.chip,
                &format!("Verilator {opt}, whole process"),
                q,
                cycles,
                secs,
            );
            // Less its start-up, the root-only query's time.
            row(
                b.chip,
                &format!("Verilator {opt}, steady state"),
                q,
                cycles,
                steady,
            );
            if best.is_none_or(|(_, s)| steady < s) {
                *best = Some((*opt, steady));
            }
        }
    }
    for ((q, &(_, by_clock, skipping, golden)), best) in b.long.iter().zip(&models).zip(best) {
        let (opt, steady) = best.expect("two levels timed");
        println!(
            "\n{}: cycle model / Verilator {opt} steady state (the faster level): {:.0}x as run_query runs it, {:.0}x clock by clock, on {q}; \
             the golden query of the same pairs (values and the golden traversal, no clocks) is {:.0}x",
            b.chip,
            steady / skipping,
            steady / by_clock,
            steady / golden
        );
    }
}

fn main() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for b in &CHIPS {
        bench_chip(root, b);
    }
    let (cycles, by_clock, skipping, _) = cycle_model(root, SHORT, 20);
    let (_, hdl) = rust_hdl(root, SHORT);
    println!("\nchip_e8m15_k6, short query:\n\n| simulator | query | cycles | CPU seconds | clocks/s |\n|---|---|---:|---:|---:|");
    let chip = "chip_e8m15_k6";
    row(chip, "cycle model (run_query)", SHORT, cycles, skipping);
    row(chip, "cycle model, clock by clock", SHORT, cycles, by_clock);
    row(chip, "rust-hdl 0.46", SHORT, cycles, hdl);
    println!(
        "\ncycle model (run_query) / rust-hdl: {:.0}x clocks/s on {SHORT}",
        hdl / skipping
    );
}
