//! Reports: per-pose records of a scene run and the readable summary table; the
//! accuracy study; the papers' figures.

pub mod accuracy;
pub mod figures;

use crate::cycle::chip::Stats;
use crate::pose::Pose;
use crate::query::Accuracy;
use crate::traversal::Counters;
use serde::Serialize;
use std::fmt::Write;

/// What one pose of a scene produced.
#[derive(Clone, Debug, Serialize)]
pub struct PoseRecord {
    pub pose: Pose,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub distance: Option<f64>,
    pub pair_count: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pairs: Option<Vec<(u32, u32)>>,
    pub counters: Counters,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact_pair_count: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub accuracy: Option<Accuracy>,
    /// The pose on the cycle model (scenes asking for `cycles`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cycles: Option<CycleRecord>,
}

/// One pose on the cycle model.
#[derive(Clone, Debug, Serialize)]
pub struct CycleRecord {
    /// Clocks from start to done.
    pub cycles: u64,
    /// The chip's time for the query at the scene's clock, in microseconds.
    pub chip_us: f64,
    /// The golden model's time for the same query on this machine (software), in
    /// microseconds.
    pub software_us: f64,
    /// Pairs the chip reported intersecting, and uncertain (for the host to settle).
    pub hits: usize,
    pub uncertain: usize,
    /// DOP tests (node pairs through the DOP unit) and triangle tests (leaf pairs through
    /// TRI_UNIT) the chip ran: in all-pairs queries the golden model's counts.
    pub dop_tests: u64,
    pub tri_tests: u64,
    /// Most queue entries (two node pairs each) waiting at once.
    pub max_entries: u64,
    pub overflow: bool,
    /// The memory model's traffic.
    pub memory: MemoryRecord,
    /// Where the clocks went (scenes asking for cycles or memory).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stats: Option<crate::cycle::chip::Stats>,
    /// The traversal VCD written, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vcd: Option<String>,
    /// The level that ran the pose beside the cycle model and agreed clock by clock.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cross_checked: Option<String>,
}

/// What one pose moved through the memory port.
#[derive(Clone, Copy, Debug, Default, Serialize)]
pub struct MemoryRecord {
    pub node_words: u64,
    pub tri_words: u64,
    /// Bytes of those words at the configuration's node and triangle widths.
    pub bytes: u64,
    /// DDR: page hits, misses and bank conflicts (0 with the ideal memory).
    pub page_hits: u64,
    pub page_misses: u64,
    pub bank_conflicts: u64,
}

/// Records grouped by sweep distance (or one group per pose without a sweep).
fn groups(records: &[PoseRecord]) -> Vec<(String, Vec<&PoseRecord>)> {
    let mut groups: Vec<(String, Vec<&PoseRecord>)> = vec![];
    for r in records {
        let key = match r.distance {
            Some(d) => format!("d={d}"),
            // the --pose syntax, which also fits the column
            None => r.pose.text(),
        };
        match groups.iter_mut().find(|(k, _)| *k == key) {
            Some((_, v)) => v.push(r),
            None => groups.push((key, vec![r])),
        }
    }
    groups
}

/// One table row per sweep distance (or one per pose without a sweep): means of the
/// counters, sums of misses and extra pairs; with `cycles`, the cycle model's mean clocks,
/// the chip's time at its clock, the software's, and their ratio.
pub fn summary_table(records: &[PoseRecord], cycles: bool) -> String {
    let groups = groups(records);
    let with_acc = records.iter().any(|r| r.accuracy.is_some());
    let with_cycles = cycles && records.iter().any(|r| r.cycles.is_some());
    let mut out = String::new();
    let _ = write!(
        out,
        "{:<28} {:>5} {:>9} {:>10} {:>10} {:>9} {:>9} {:>9} {:>10} {:>7}",
        "pose", "n", "pairs", "dop_tests", "overlaps", "tri_tests", "uncertain", "fetches", "mem_KiB", "queue"
    );
    if with_acc {
        let _ = write!(out, " {:>9} {:>7} {:>7}", "exact", "misses", "extras");
    }
    if with_cycles {
        let _ = write!(out, " {:>10} {:>9} {:>9} {:>8}", "cycles", "chip_us", "sw_us", "speedup");
    }
    out.push('\n');
    for (key, g) in &groups {
        let n = g.len() as f64;
        let mean = |f: &dyn Fn(&PoseRecord) -> f64| g.iter().map(|r| f(r)).sum::<f64>() / n;
        let _ = write!(
            out,
            "{:<28} {:>5} {:>9.1} {:>10.0} {:>10.0} {:>9.1} {:>9.1} {:>9.0} {:>10.1} {:>7.0}",
            key,
            g.len(),
            mean(&|r| r.pair_count as f64),
            mean(&|r| r.counters.dop_tests as f64),
            mean(&|r| r.counters.dop_overlaps as f64),
            mean(&|r| r.counters.tri_tests as f64),
            mean(&|r| r.counters.uncertain as f64),
            mean(&|r| (r.counters.node_fetches + r.counters.tri_fetches) as f64),
            mean(&|r| r.counters.memory_bytes as f64 / 1024.0),
            g.iter().map(|r| r.counters.max_queue_depth).max().unwrap_or(0) as f64,
        );
        if with_acc {
            let sum = |f: &dyn Fn(&Accuracy) -> u64| g.iter().filter_map(|r| r.accuracy.as_ref()).map(f).sum::<u64>();
            let _ = write!(
                out,
                " {:>9.1} {:>7} {:>7}",
                mean(&|r| r.exact_pair_count.unwrap_or(0) as f64),
                sum(&|a| a.misses),
                sum(&|a| a.extras)
            );
        }
        if with_cycles {
            let c: Vec<_> = g.iter().filter_map(|r| r.cycles.as_ref()).collect();
            let m = |f: &dyn Fn(&CycleRecord) -> f64| c.iter().map(|r| f(r)).sum::<f64>() / c.len().max(1) as f64;
            let (chip, sw) = (m(&|r| r.chip_us), m(&|r| r.software_us));
            let _ = write!(out, " {:>10.0} {:>9.2} {:>9.1} {:>8.1}", m(&|r| r.cycles as f64), chip, sw, sw / chip);
        }
        out.push('\n');
    }
    out
}

/// Where the chip's clocks went, one row per sweep distance (or pose): the share of
/// running clocks by what the DOP unit's input did (issue, or the stall's cause), TRI_UNIT
/// back-pressure, the DOP unit's and TRI_UNIT's mean occupancy, DOP and triangle tests per
/// clock (the papers' throughput measures) and memory words per clock. Empty without cycle
/// records.
pub fn stall_table(records: &[PoseRecord]) -> String {
    let mut out = String::new();
    if !records.iter().any(|r| r.cycles.is_some()) {
        return out;
    }
    let _ = writeln!(
        out,
        "{:<28} {:>6} {:>7} {:>8} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7}",
        "pose", "issue%", "memory%", "spacing%", "credit%", "refill%", "empty%", "drain%", "halted%", "bkpres%", "dop_occ", "tri_occ", "dop/c", "tri/c", "words/c"
    );
    for (key, g) in groups(records) {
        let c: Vec<_> = g.iter().filter_map(|r| r.cycles.as_ref()).collect();
        let st: Vec<Stats> = c.iter().filter_map(|r| r.stats).collect();
        let sum = |f: &dyn Fn(&Stats) -> u64| st.iter().map(f).sum::<u64>() as f64;
        let cycles = sum(&|r| r.cycles).max(1.0);
        let pc = |f: &dyn Fn(&Stats) -> u64| 100.0 * sum(f) / cycles;
        let words = c.iter().map(|r| r.memory.node_words + r.memory.tri_words).sum::<u64>() as f64;
        let per_clock = |f: &dyn Fn(&CycleRecord) -> u64| c.iter().map(|r| f(r)).sum::<u64>() as f64 / cycles;
        let _ = writeln!(
            out,
            "{:<28} {:>6.1} {:>7.1} {:>8.1} {:>7.1} {:>7.1} {:>7.1} {:>7.1} {:>7.1} {:>7.1} {:>7.2} {:>7.1} {:>7.3} {:>7.3} {:>7.3}",
            key,
            pc(&|r| r.issue),
            pc(&|r| r.stall_memory),
            pc(&|r| r.stall_spacing),
            pc(&|r| r.stall_credit),
            pc(&|r| r.stall_refill),
            pc(&|r| r.stall_empty_queue),
            pc(&|r| r.drain),
            pc(&|r| r.halted),
            pc(&|r| r.back_pressure),
            sum(&|r| r.dop_occupancy) / cycles,
            sum(&|r| r.tri_occupancy) / cycles,
            per_clock(&|r| r.dop_tests),
            per_clock(&|r| r.tri_tests),
            words / cycles,
        );
    }
    out
}

/// The memory model's traffic, one row per sweep distance (or pose): mean node and
/// triangle words and KiB per query, the share of triangle tests whose A word was held
/// (the triangle cache's hit rate, `[chip] tri_cache`), words per clock, and the share of
/// clocks with a request outstanding and with the DOP unit's input waiting for a word.
/// Empty without cycle records.
pub fn memory_table(records: &[PoseRecord]) -> String {
    let mut out = String::new();
    if !records.iter().any(|r| r.cycles.is_some()) {
        return out;
    }
    let _ = writeln!(
        out,
        "{:<28} {:>10} {:>10} {:>7} {:>10} {:>8} {:>7} {:>8} {:>9} {:>9} {:>9}",
        "pose", "node_words", "tri_words", "a_hit%", "KiB", "words/c", "busy%", "waiting%", "page_hit", "page_miss", "conflicts"
    );
    for (key, g) in groups(records) {
        let c: Vec<_> = g.iter().filter_map(|r| r.cycles.as_ref()).collect();
        let n = c.len().max(1) as f64;
        let sum = |f: &dyn Fn(&CycleRecord) -> u64| c.iter().map(|r| f(r)).sum::<u64>() as f64;
        let cycles = sum(&|r| r.cycles).max(1.0);
        let st = |f: &dyn Fn(&Stats) -> u64| c.iter().filter_map(|r| r.stats.as_ref()).map(f).sum::<u64>() as f64;
        let _ = writeln!(
            out,
            "{:<28} {:>10.0} {:>10.0} {:>7} {:>10.1} {:>8.3} {:>7.1} {:>8.1} {:>9.0} {:>9.0} {:>9.0}",
            key,
            sum(&|r| r.memory.node_words) / n,
            sum(&|r| r.memory.tri_words) / n,
            match sum(&|r| r.tri_tests) {
                0.0 => "-".to_string(),
                t => format!("{:.1}", 100.0 * (1.0 - st(&|s| s.tri_fetches_a) / t)),
            },
            sum(&|r| r.memory.bytes) / n / 1024.0,
            sum(&|r| r.memory.node_words + r.memory.tri_words) / cycles,
            100.0 * st(&|s| s.memory_busy) / cycles,
            100.0 * st(&|s| s.stall_memory) / cycles,
            sum(&|r| r.memory.page_hits) / n,
            sum(&|r| r.memory.page_misses) / n,
            sum(&|r| r.memory.bank_conflicts) / n,
        );
    }
    out
}
