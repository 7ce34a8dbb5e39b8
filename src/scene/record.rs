//! What a scene run records per pose: the golden model's counters and answer, the exact
//! oracle's, and the cycle model's clocks and memory traffic (`--json`; the tables of
//! [`report`](crate::report) read them).

use crate::chip::timing::PeriodSource;
use crate::pose::Pose;
use crate::query::Accuracy;
use crate::traversal::{Counters, Host};
use serde::Serialize;

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
    /// The scene's clock period ([`Scene::clock`](crate::scene::Scene::clock)), in ns, and
    /// whether it is measured, estimated or assumed ([`Clock::source`](crate::chip::timing::Clock::source) says from what).
    pub period_ns: f64,
    pub period_source: PeriodSource,
    /// The chip's time for the query: cycles x period, in microseconds (as measured as its
    /// period; so are the speed-ups made of it).
    pub chip_us: f64,
    /// The host's share, measured on this machine (wall clock, noisy): its setup for the
    /// pose, and its settling of the chip's uncertain pairs with the exact oracle, in
    /// microseconds.
    pub host_setup_us: f64,
    pub settle_us: f64,
    /// The query end to end: host_setup_us + chip_us + settle_us.
    pub end_to_end_us: f64,
    /// The golden model's time for the same query on this machine (software), in
    /// microseconds.
    pub software_us: f64,
    /// software_us, host_setup_us and settle_us are each the fastest of this many runs of
    /// their work, one pose at a time (warm: the first run pays for cold caches).
    pub timing_runs: usize,
    /// Pairs the chip reported intersecting, and uncertain (for the host to settle), sorted;
    /// the JSON has their counts.
    #[serde(rename = "hits", serialize_with = "count")]
    pub hit_pairs: Vec<(u32, u32)>,
    #[serde(rename = "uncertain", serialize_with = "count")]
    pub uncertain_pairs: Vec<(u32, u32)>,
    /// DOP tests (node pairs through the DOP unit) and triangle tests (leaf pairs through
    /// TRI_UNIT) the chip ran: in all-pairs queries the golden model's counts.
    pub dop_tests: u64,
    pub tri_tests: u64,
    /// Most queue entries (two node pairs each) waiting at once; WSCG'03's chip: the
    /// deepest level of its lists.
    pub max_entries: u64,
    pub overflow: bool,
    /// The memory model's traffic.
    pub memory: MemoryRecord,
    /// The memory in the chip's clocks at `period_ns` (a DDR's nanoseconds rounded up to
    /// whole clocks: [`Memory::at`](crate::chip::memory::Memory::at)).
    pub memory_clocks: crate::chip::memory::MemClocks,
    /// Where the clocks went (scenes asking for cycles or memory).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stats: Option<crate::cycle::chip::Stats>,
    /// WSCG'03's chip: where its clocks went and its lists.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wscg03: Option<StackRecord>,
    /// The traversal VCD written, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vcd: Option<String>,
    /// The level that ran the pose beside the cycle model and agreed clock by clock.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cross_checked: Option<String>,
}

/// WSCG'03's chip clocked as its RTL: each clock booked once
/// ([`Booked`](crate::cycle::wscg03::clocked::Booked)), the lists it processed (WSCG'03
/// Eq. 5's tau), and A's triangle words fetched.
#[derive(Clone, Debug, Serialize)]
pub struct StackRecord {
    pub booked: crate::cycle::wscg03::clocked::Booked,
    pub lists: u64,
    /// A's triangle words fetched (its triangle cache's misses).
    pub tri_fetches_a: u64,
}

impl CycleRecord {
    /// The chip's answer once `host` has settled its uncertain pairs: its sure hits and the
    /// uncertain pairs that intersect, sorted.
    pub fn answer(&self, host: &Host) -> Vec<(u32, u32)> {
        let kept = self
            .uncertain_pairs
            .iter()
            .filter(|&&(a, b)| host.settle(a, b));
        let mut a: Vec<_> = self.hit_pairs.iter().chain(kept).copied().collect();
        a.sort_unstable();
        a
    }

    /// Adds the host's measured share and the end-to-end time it makes.
    pub fn add_host(&mut self, h: crate::query::HostTime) {
        (self.host_setup_us, self.settle_us) = (h.setup_us, h.settle_us);
        self.end_to_end_us = h.setup_us + self.chip_us + h.settle_us;
    }
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

/// A list of pairs serialized as its length.
fn count<S: serde::Serializer>(pairs: &[(u32, u32)], s: S) -> Result<S::Ok, S::Error> {
    s.serialize_u64(pairs.len() as u64)
}
