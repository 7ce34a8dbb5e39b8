//! Reports: per-pose records of a scene run and the readable summary table; the
//! accuracy study.

pub mod accuracy;

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
    /// The pose on the RTL chip (scenes asking for `cycles`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rtl: Option<crate::rtl::chip_io::RtlRecord>,
}

/// One table row per sweep distance (or one per pose without a sweep): means of the
/// counters, sums of misses and extra pairs.
pub fn summary_table(records: &[PoseRecord]) -> String {
    let mut groups: Vec<(String, Vec<&PoseRecord>)> = vec![];
    for r in records {
        let key = match r.distance {
            Some(d) => format!("d={d}"),
            None => format!("{:?} {:?}", r.pose.rot_deg, r.pose.t),
        };
        match groups.iter_mut().find(|(k, _)| *k == key) {
            Some((_, v)) => v.push(r),
            None => groups.push((key, vec![r])),
        }
    }
    let with_acc = records.iter().any(|r| r.accuracy.is_some());
    let with_rtl = records.iter().any(|r| r.rtl.is_some());
    let mut out = String::new();
    let _ = write!(
        out,
        "{:<28} {:>5} {:>9} {:>10} {:>10} {:>9} {:>9} {:>9} {:>10} {:>7}",
        "pose", "n", "pairs", "dop_tests", "overlaps", "tri_tests", "uncertain", "fetches", "mem_KiB", "queue"
    );
    if with_acc {
        let _ = write!(out, " {:>9} {:>7} {:>7}", "exact", "misses", "extras");
    }
    if with_rtl {
        let _ = write!(out, " {:>10} {:>9}", "rtl_cycles", "rtl_queue");
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
        if with_rtl {
            let rtl: Vec<_> = g.iter().filter_map(|r| r.rtl.as_ref()).collect();
            let _ = write!(
                out,
                " {:>10.0} {:>9}",
                rtl.iter().map(|r| r.cycles as f64).sum::<f64>() / rtl.len().max(1) as f64,
                rtl.iter().map(|r| r.max_depth).max().unwrap_or(0)
            );
        }
        out.push('\n');
    }
    out
}
