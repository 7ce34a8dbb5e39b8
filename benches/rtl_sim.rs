//! Simulated clock cycles per second of the k = 24 binary32 DOP unit (`dop_unit_k24_b32`)
//! in rust-hdl's simulator and in Verilator, on the same golden vectors, as a ratio.
//!
//! ```sh
//! cargo bench --bench rtl_sim
//! ```
//!
//! 1. rust-hdl: the unit's golden vectors (`units::all()`, `.vectors()`: the host-setup
//!    preload, then every node pair of two small DOP trees) through `b32::DopUnit24` with
//!    `harness::sim::run_dop_vectors`; every output is checked against the expected fields
//!    (the bench panics on a mismatch), and the run is timed (a few hundred cycles: the
//!    k = 24 model simulates some hundreds of cycles per second).
//! 2. Verilator (skipped, with a note, if `verilator` is not on PATH): the unit's Verilog
//!    (`.verilog()`) and a long vector file (the same preload, then the golden case lines
//!    repeated to `BIG_CASES` cases) under `target/rtl-sim/`, built and run once by
//!    `scripts/run-verilator.sh` (which checks every case). The testbench has the case count
//!    built in, so the build is for the long file; it covers every golden case. Then the built
//!    binary is run again and timed (wall clock of the process, so it includes the testbench's
//!    `$readmemh` of the packed vectors and its checking: a lower bound of the model's speed).
//!
//! Prints a Markdown table (simulator, cycles, seconds, cycles/s) and the ratio
//! Verilator / rust-hdl.

#[path = "common/record.rs"]
mod record;

use collision_chip::harness::sim::{parse_dop_vectors, run_dop_vectors, DopVectors};
use collision_chip::harness::units;
use collision_chip::rtl::b32;
use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

const UNIT: &str = "dop_unit_k24_b32";
/// Cases of the long vector file for Verilator.
const BIG_CASES: usize = 100_000;

struct Row {
    sim: &'static str,
    cycles: u64,
    secs: f64,
}

impl Row {
    fn rate(&self) -> f64 {
        self.cycles as f64 / self.secs
    }
}

fn main() {
    // the k = 24 unit is about 2 MB, built on the stack
    std::thread::Builder::new()
        .stack_size(512 << 20)
        .spawn(bench)
        .unwrap()
        .join()
        .unwrap_or_else(|e| std::panic::resume_unwind(e));
}

fn bench() {
    let all = units::all();
    let unit = all
        .iter()
        .find(|u| u.name == UNIT)
        .unwrap_or_else(|| panic!("no unit {UNIT} in harness::units::all()"));
    let text = unit.vectors();
    let v = parse_dop_vectors(&text, b32::WIDTH).unwrap_or_else(|e| panic!("{UNIT} vectors: {e}"));
    assert_eq!((v.k, v.latency), (24, unit.latency as usize));
    let overlaps = v.cases.iter().filter(|c| c.overlap).count();
    println!(
        "{UNIT}: {} preload cycles, {} cases ({overlaps} overlap), latency {}",
        v.preload.len(),
        v.cases.len(),
        v.latency
    );
    assert!(
        overlaps > 0 && overlaps < v.cases.len(),
        "the golden vectors should hold both verdicts"
    );

    let mut rows = vec![rust_hdl_row(&v)];
    match verilator_row(unit, &text, &v) {
        Ok(row) => rows.push(row),
        Err(note) => println!("\nVerilator: {note}; only the rust-hdl row is measured."),
    }

    println!("\n| simulator | cycles simulated | seconds | cycles/s |\n|---|---:|---:|---:|");
    for r in &rows {
        println!(
            "| {} | {} | {:.3} | {:.0} |",
            r.sim,
            r.cycles,
            r.secs,
            r.rate()
        );
        record::row(
            "rtl_sim",
            json!({ "unit": UNIT, "simulator": r.sim, "cycles": r.cycles, "seconds": r.secs,
                    "clocks_per_s": r.rate().round() }),
        );
    }
    if let [hdl, vl] = &rows[..] {
        println!(
            "\nVerilator / rust-hdl: {:.0}x cycles/s ({UNIT})",
            vl.rate() / hdl.rate()
        );
    }
}

/// The golden vectors through rust-hdl's simulator, checked and timed.
fn rust_hdl_row(v: &DopVectors) -> Row {
    let t = Instant::now();
    let mut uut = b32::dop_unit24_top();
    println!(
        "rust-hdl: DopUnit24 built in {:.2} s",
        t.elapsed().as_secs_f64()
    );
    let t = Instant::now();
    let run = run_dop_vectors(&mut uut, v).unwrap_or_else(|e| panic!("rust-hdl {UNIT}: {e}"));
    let secs = t.elapsed().as_secs_f64();
    assert_eq!(run.outputs.len(), v.cases.len());
    let bad: Vec<_> = run.mismatches(v).collect();
    for &(i, o) in bad.iter().take(10) {
        let c = &v.cases[i];
        println!(
            "MISMATCH case {i} (line {}): overlap {} tag_out {:04x} (expected {} {:04x})",
            c.line, o.overlap as u8, o.tag, c.overlap as u8, c.tag_out
        );
    }
    assert!(
        bad.is_empty(),
        "rust-hdl {UNIT}: {} of {} cases differ from the golden vectors",
        bad.len(),
        v.cases.len()
    );
    // the compare itself: one flipped expectation must be caught
    let mut wrong = v.clone();
    wrong.cases[7].overlap ^= true;
    assert_eq!(
        run.mismatches(&wrong).map(|(i, _)| i).collect::<Vec<_>>(),
        [7],
        "mismatches() missed a flipped overlap"
    );
    println!(
        "rust-hdl: {} cases passed, {} cycles in {secs:.2} s",
        v.cases.len(),
        run.cycles
    );
    Row {
        sim: "rust-hdl 0.46 (`simulate`)",
        cycles: run.cycles,
        secs,
    }
}

fn verilator_version() -> Option<String> {
    let out = Command::new("verilator").arg("--version").output().ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// `N passed, M failed` (the testbench's summary line) from a run's stdout.
fn summary(stdout: &str) -> Option<(usize, usize)> {
    let l = stdout.lines().rev().find(|l| l.contains(" passed, "))?;
    let mut w = l.split_whitespace();
    let p = w.next()?.parse().ok()?;
    let f = w.nth(1)?.parse().ok()?;
    Some((p, f))
}

/// The unit's Verilog and a long vector file under Verilator: build and check with
/// `scripts/run-verilator.sh`, then time one more run of the built binary.
/// `Err` (a note, not a failure) only if verilator is not installed.
fn verilator_row(unit: &units::Unit, text: &str, v: &DopVectors) -> Result<Row, String> {
    let version =
        verilator_version().ok_or("verilator not installed (apt-get install verilator)")?;
    println!("\n{version}");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = root.join("target").join("rtl-sim");
    std::fs::create_dir_all(&dir).unwrap();

    let t = Instant::now();
    let vpath = dir.join(format!("{UNIT}.v"));
    write_if_changed(&vpath, &unit.verilog());
    println!(
        "Verilog from .verilog() in {:.1} s: {}",
        t.elapsed().as_secs_f64(),
        vpath.display()
    );

    // the long file: everything before the first case (headers, latency, preload), then the
    // case lines over and over
    let lines: Vec<&str> = text.lines().collect();
    let first = v.cases[0].line - 1;
    let case_lines: Vec<&str> = v.cases.iter().map(|c| lines[c.line - 1]).collect();
    let mut big = lines[..first].join("\n");
    big.push('\n');
    for i in 0..BIG_CASES {
        big += case_lines[i % case_lines.len()];
        big.push('\n');
    }
    let hpath = dir.join(format!("{UNIT}_x{BIG_CASES}.hex"));
    write_if_changed(&hpath, &big);

    let out_dir = dir.join("verilator");
    let t = Instant::now();
    let out = Command::new(root.join("scripts").join("run-verilator.sh"))
        .arg(&vpath)
        .arg(&hpath)
        .args([
            "--name",
            UNIT,
            "--in-valid",
            "valid_in",
            "--out-valid",
            "valid_out",
            "--out",
        ])
        .arg(&out_dir)
        .env("VERILATOR_WNO", "-Wno-WIDTH -Wno-UNOPTFLAT")
        .current_dir(root)
        .output()
        .expect("scripts/run-verilator.sh");
    let stdout = String::from_utf8_lossy(&out.stdout);
    if !out.status.success() {
        panic!(
            "scripts/run-verilator.sh failed ({}):\n{stdout}\n{}",
            out.status,
            String::from_utf8_lossy(&out.stderr)
        );
    }
    assert_eq!(
        summary(&stdout),
        Some((BIG_CASES, 0)),
        "run-verilator.sh output:\n{stdout}"
    );
    println!(
        "run-verilator.sh: built and ran in {:.1} s: {BIG_CASES} passed, 0 failed",
        t.elapsed().as_secs_f64()
    );

    let bin = out_dir.join("obj").join(format!("V{UNIT}"));
    let t = Instant::now();
    let out = Command::new(&bin)
        .output()
        .unwrap_or_else(|e| panic!("{}: {e}", bin.display()));
    let secs = t.elapsed().as_secs_f64();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{} failed ({}):\n{stdout}",
        bin.display(),
        out.status
    );
    assert_eq!(
        summary(&stdout),
        Some((BIG_CASES, 0)),
        "{} output:\n{stdout}",
        bin.display()
    );
    // the testbench's cycles: one per preload line and case, then latency + 1 to flush
    let cycles = (v.preload.len() + BIG_CASES + v.latency + 1) as u64;
    println!(
        "Verilator: {} ({BIG_CASES} cases) in {secs:.2} s",
        bin.display()
    );
    Ok(Row {
        sim: "Verilator (`--binary -O3`)",
        cycles,
        secs,
    })
}

/// Writes `text` to `path` unless it already holds it (keeps the mtime for Verilator's make).
fn write_if_changed(path: &PathBuf, text: &str) {
    if std::fs::read_to_string(path).ok().as_deref() != Some(text) {
        std::fs::write(path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    }
}
