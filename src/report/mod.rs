//! Reports: the readable tables of a scene run's records; the accuracy study; the papers'
//! figures.

pub mod accuracy;
pub mod figures;
pub mod plot;

use crate::cycle::chip::Stats;
use crate::query::Accuracy;
use crate::scene::record::{CycleRecord, PoseRecord};
use std::fmt::Write;

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
/// the chip's time at its clock, the host's measured setup and settling, the end-to-end
/// time, the software's, and its ratio to the chip's and to the end-to-end time. A pose
/// whose pair queue overflowed halted early with an incomplete answer: its clocks would
/// make the chip look faster, so the cycle columns leave it out, an `ovf` column counts
/// such poses, and a row of them only has `-` there.
pub fn summary_table(records: &[PoseRecord], cycles: bool) -> String {
    let groups = groups(records);
    let with_acc = records.iter().any(|r| r.accuracy.is_some());
    let with_cycles = cycles && records.iter().any(|r| r.cycles.is_some());
    let mut out = String::new();
    let _ = write!(
        out,
        "{:<28} {:>5} {:>9} {:>10} {:>10} {:>9} {:>9} {:>9} {:>10} {:>7}",
        "pose",
        "n",
        "pairs",
        "dop_tests",
        "overlaps",
        "tri_tests",
        "uncertain",
        "fetches",
        "mem_KiB",
        "queue"
    );
    if with_acc {
        let _ = write!(out, " {:>9} {:>7} {:>7}", "exact", "misses", "extras");
    }
    if with_cycles {
        let _ = write!(
            out,
            " {:>10} {:>9} {:>9} {:>9} {:>9} {:>9} {:>8} {:>7}",
            "cycles", "chip_us", "setup_us", "settle_us", "e2e_us", "sw_us", "speedup", "e2e_x"
        );
    }
    let overflowed = |r: &PoseRecord| r.cycles.as_ref().is_some_and(|c| c.overflow);
    let with_ovf = with_cycles && records.iter().any(overflowed);
    if with_ovf {
        let _ = write!(out, " {:>4}", "ovf");
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
            g.iter()
                .map(|r| r.counters.max_queue_depth)
                .max()
                .unwrap_or(0) as f64,
        );
        if with_acc {
            let sum = |f: &dyn Fn(&Accuracy) -> u64| {
                g.iter()
                    .filter_map(|r| r.accuracy.as_ref())
                    .map(f)
                    .sum::<u64>()
            };
            let _ = write!(
                out,
                " {:>9.1} {:>7} {:>7}",
                mean(&|r| r.exact_pair_count.unwrap_or(0) as f64),
                sum(&|a| a.misses),
                sum(&|a| a.extras)
            );
        }
        if with_cycles {
            let c: Vec<_> = g
                .iter()
                .filter(|r| !overflowed(r))
                .filter_map(|r| r.cycles.as_ref())
                .collect();
            if c.is_empty() {
                let _ = write!(
                    out,
                    " {:>10} {:>9} {:>9} {:>9} {:>9} {:>9} {:>8} {:>7}",
                    "-", "-", "-", "-", "-", "-", "-", "-"
                );
            } else {
                let m = |f: &dyn Fn(&CycleRecord) -> f64| {
                    c.iter().map(|r| f(r)).sum::<f64>() / c.len() as f64
                };
                let (chip, sw, e2e) = (
                    m(&|r| r.chip_us),
                    m(&|r| r.software_us),
                    m(&|r| r.end_to_end_us),
                );
                let (setup, settle) = (m(&|r| r.host_setup_us), m(&|r| r.settle_us));
                let _ = write!(
                    out,
                    " {:>10.0} {:>9.2} {:>9.2} {:>9.2} {:>9.2} {:>9.1} {:>8.1} {:>7.1}",
                    m(&|r| r.cycles as f64),
                    chip,
                    setup,
                    settle,
                    e2e,
                    sw,
                    sw / chip,
                    sw / e2e
                );
            }
        }
        if with_ovf {
            let _ = write!(out, " {:>4}", g.iter().filter(|r| overflowed(r)).count());
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
        let words = c
            .iter()
            .map(|r| r.memory.node_words + r.memory.tri_words)
            .sum::<u64>() as f64;
        let per_clock =
            |f: &dyn Fn(&CycleRecord) -> u64| c.iter().map(|r| f(r)).sum::<u64>() as f64 / cycles;
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

/// WSCG'03's chip (`[chip] architecture = "wscg03"`, clocked as its RTL): where its clocks
/// went, each booked once (`cycle::wscg03::clocked::Booked`: an aligned bundle into the
/// compare units, a tumbled bundle into the DOTADD units, the head ask waiting for its
/// record or for its d' set, no ask, the drain), DOP tests and words per clock, its lists
/// (tau), their mean aligned node pairs (alpha), clocks per list against WSCG'03 Eq. 5's.
pub fn stack_table(records: &[PoseRecord]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<28} {:>8} {:>6} {:>7} {:>10} {:>6} {:>7} {:>7} {:>7} {:>7} {:>6} {:>9} {:>9}",
        "pose",
        "compare%",
        "load%",
        "memory%",
        "transform%",
        "list%",
        "drain%",
        "dop/c",
        "words/c",
        "lists",
        "alpha",
        "clk/list",
        "eq5/list"
    );
    for (key, g) in groups(records) {
        let c: Vec<&CycleRecord> = g.iter().filter_map(|r| r.cycles.as_ref()).collect();
        let st: Vec<(&CycleRecord, &crate::scene::record::StackRecord)> = c
            .iter()
            .filter_map(|r| Some((*r, r.wscg03.as_ref()?)))
            .collect();
        if st.is_empty() {
            continue;
        }
        let sum = |f: &dyn Fn(&CycleRecord, &crate::scene::record::StackRecord) -> u64| {
            st.iter().map(|(r, s)| f(r, s)).sum::<u64>() as f64
        };
        let cycles = sum(&|r, _| r.cycles).max(1.0);
        let pc = |f: &dyn Fn(&crate::cycle::wscg03::clocked::Booked) -> u64| {
            100.0 * sum(&|_, s| f(&s.booked)) / cycles
        };
        let lists = sum(&|_, s| s.lists).max(1.0);
        let dop_tests = sum(&|r, _| r.dop_tests);
        let words = sum(&|r, _| r.memory.node_words + r.memory.tri_words);
        let _ = writeln!(
            out,
            "{:<28} {:>8.1} {:>6.1} {:>7.1} {:>10.1} {:>6.1} {:>7.1} {:>7.3} {:>7.3} {:>7.1} {:>6.2} {:>9.1} {:>9.1}",
            key,
            pc(&|b| b.compare),
            pc(&|b| b.load),
            pc(&|b| b.memory),
            pc(&|b| b.transform),
            pc(&|b| b.list),
            pc(&|b| b.drain),
            dop_tests / cycles,
            words / cycles,
            lists / st.len() as f64,
            dop_tests / lists,
            cycles / lists,
            figures::eq5_cycles(lists as u64, dop_tests as u64) / lists,
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
        "pose",
        "node_words",
        "tri_words",
        "a_hit%",
        "KiB",
        "words/c",
        "busy%",
        "waiting%",
        "page_hit",
        "page_miss",
        "conflicts"
    );
    for (key, g) in groups(records) {
        let c: Vec<_> = g.iter().filter_map(|r| r.cycles.as_ref()).collect();
        let n = c.len().max(1) as f64;
        let sum = |f: &dyn Fn(&CycleRecord) -> u64| c.iter().map(|r| f(r)).sum::<u64>() as f64;
        let cycles = sum(&|r| r.cycles).max(1.0);
        let st = |f: &dyn Fn(&Stats) -> u64| {
            c.iter()
                .filter_map(|r| r.stats.as_ref())
                .map(f)
                .sum::<u64>() as f64
        };
        // A's triangle words fetched (the cache's misses), on either chip
        let wscg = |f: &dyn Fn(&crate::scene::record::StackRecord) -> u64| {
            c.iter()
                .filter_map(|r| r.wscg03.as_ref())
                .map(f)
                .sum::<u64>() as f64
        };
        let fetches_a = st(&|s| s.tri_fetches_a) + wscg(&|s| s.tri_fetches_a);
        // WSCG'03's Memory Controller keeps no count of clocks with a request outstanding
        let busy = match c.iter().any(|r| r.stats.is_some()) {
            true => format!("{:.1}", 100.0 * st(&|s| s.memory_busy) / cycles),
            false => "-".into(),
        };
        let _ = writeln!(
            out,
            "{:<28} {:>10.0} {:>10.0} {:>7} {:>10.1} {:>8.3} {:>7} {:>8.1} {:>9.0} {:>9.0} {:>9.0}",
            key,
            sum(&|r| r.memory.node_words) / n,
            sum(&|r| r.memory.tri_words) / n,
            match sum(&|r| r.tri_tests) {
                0.0 => "-".to_string(),
                t => format!("{:.1}", 100.0 * (1.0 - fetches_a / t)),
            },
            sum(&|r| r.memory.bytes) / n / 1024.0,
            sum(&|r| r.memory.node_words + r.memory.tri_words) / cycles,
            busy,
            100.0 * (st(&|s| s.stall_memory) + wscg(&|s| s.booked.memory)) / cycles,
            sum(&|r| r.memory.page_hits) / n,
            sum(&|r| r.memory.page_misses) / n,
            sum(&|r| r.memory.bank_conflicts) / n,
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use crate::scene::record::CycleRecord;
    use crate::scene::{run::Prepared, Scene};

    /// The stall table's tests per clock: the pose group's tests over its clocks.
    #[test]
    fn stall_table_tests_per_clock() {
        let text = "[objects]\na = \"sphere:80\"\nb = \"torus:60\"\n[chip]\nk = 14\n[sweep]\ndistances = [1.2, 0.6]\norientations = 2\n[outputs]\ncycles = true\n";
        let s = Scene::parse(text, "test").unwrap();
        let cyc = Prepared::new(&s, |spec| {
            crate::mesh::resolve(spec).map_err(|e| e.to_string())
        })
        .unwrap()
        .run(|| ())
        .unwrap();
        let d06: Vec<_> = cyc
            .records
            .iter()
            .filter(|r| r.distance == Some(0.6))
            .map(|r| r.cycles.as_ref().unwrap())
            .collect();
        let clocks = d06.iter().map(|c| c.cycles).sum::<u64>() as f64;
        let per = |f: fn(&&CycleRecord) -> u64| {
            format!("{:.3}", d06.iter().map(f).sum::<u64>() as f64 / clocks)
        };
        let row = super::stall_table(&cyc.records)
            .lines()
            .find(|l| l.starts_with("d=0.6"))
            .unwrap()
            .to_string();
        let cols: Vec<&str> = row.split_whitespace().collect();
        assert_eq!(
            cols[cols.len() - 3..cols.len() - 1],
            [per(|c| c.dop_tests), per(|c| c.tri_tests)],
            "{row}"
        );
    }

    /// A pose whose pair queue overflowed halts early: the summary's cycle columns leave it
    /// out and count it in `ovf`, and its misses are the chip's incomplete answer's (a
    /// 16-entry FIFO queue overflows in contact, not apart).
    #[test]
    fn summary_leaves_overflowed_poses_out_of_the_clocks() {
        let text = "[objects]\na = \"bunny\"\nb = \"bunny\"\n[query]\ntraversal = \"fifo\"\n[timing]\nqueue_entries = 16\n[sweep]\ndistances = [0.8, 2.2]\norientations = 2\n[outputs]\ncycles = true\naccuracy = true\n";
        let s = Scene::parse(text, "test").unwrap();
        let unit = |spec: &str| {
            crate::mesh::resolve(spec)
                .map_err(|e| e.to_string())?
                .scaled_into_unit_cube()
                .map_err(|e| e.to_string())
        };
        let cyc = Prepared::new(&s, unit).unwrap().run(|| ()).unwrap();
        let table = super::summary_table(&cyc.records, true);
        let row = |d: &str| {
            table
                .lines()
                .find(|l| l.starts_with(d))
                .unwrap()
                .split_whitespace()
                .map(String::from)
                .collect::<Vec<_>>()
        };
        let (near, far) = (row("d=0.8"), row("d=2.2"));
        assert_eq!(
            table.lines().next().unwrap().split_whitespace().last(),
            Some("ovf"),
            "{table}"
        );
        assert_eq!(
            near[near.len() - 9..],
            ["-", "-", "-", "-", "-", "-", "-", "-", "2"],
            "{table}"
        );
        let clocks: Vec<u64> = cyc
            .records
            .iter()
            .filter(|r| r.distance == Some(2.2))
            .map(|r| r.cycles.as_ref().unwrap().cycles)
            .collect();
        assert_eq!(
            far[far.len() - 9],
            format!("{:.0}", clocks.iter().sum::<u64>() as f64 / 2.0),
            "{table}"
        );
        assert_eq!(far.last().map(String::as_str), Some("0"), "{table}");
        // misses and extras, before the cycle columns: the chip missed pairs near, none far
        let near_misses: u64 = near[near.len() - 11].parse().unwrap();
        assert!(near_misses > 0 && far[far.len() - 11] == "0", "{table}");
    }
}
