//! A bench's rows as data: one JSON line per row, with the date, the CPU model and the
//! commit, appended to `target/bench/<bench>.jsonl` (docs/explanation/speed.md: a run is
//! published by appending its lines to docs/figures/bench.jsonl; scripts/tables.py makes the
//! tables from them).

use serde_json::{json, Map, Value};
use std::io::Write;
use std::path::Path;
use std::process::Command;

fn output(cmd: &str, args: &[&str]) -> Option<String> {
    let out = Command::new(cmd).args(args).output().ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// The date, the CPU and the commit of this run ("+changes" when the work tree differs).
fn stamp() -> Map<String, Value> {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown".into());
    let commit = output("git", &["rev-parse", "--short=12", "HEAD"]).unwrap_or_default();
    let dirty = output("git", &["status", "--porcelain", "--untracked-files=no"])
        .is_some_and(|s| !s.is_empty());
    let date = output("date", &["-u", "+%Y-%m-%d"]).unwrap_or_default();
    let commit = if dirty { commit + "+changes" } else { commit };
    let Value::Object(m) = json!({ "date": date, "cpu": cpu, "commit": commit }) else {
        unreachable!()
    };
    m
}

/// Appends `row` (a JSON object) to target/bench/`bench`.jsonl with the run's stamp.
pub fn row(bench: &str, row: Value) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = root.join("target/bench");
    let mut line = Map::new();
    line.insert("bench".into(), bench.into());
    line.extend(stamp());
    if let Value::Object(fields) = row {
        line.extend(fields);
    }
    std::fs::create_dir_all(&dir).expect("target/bench");
    let path = dir.join(format!("{bench}.jsonl"));
    let mut f = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(&path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    writeln!(f, "{}", Value::Object(line)).expect("write a bench row");
}
