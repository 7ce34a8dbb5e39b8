//! The fast cycle-exact model of the chip (fidelity level "cycle", DESIGN §2): the same
//! microarchitecture as the RTL chip ([`rtl::chip`](crate::rtl)), unit by unit, each unit's
//! state changing once per clock from the previous clock's registers as
//! docs/ARCHITECTURE.md "Cycle semantics" says. Values (DOP overlaps, TRI_UNIT verdicts)
//! come from [`golden`](crate::golden): this model adds *when* things happen, never a
//! second copy of the arithmetic (as gem5's timing CPUs call `StaticInst::execute`).
//!
//! | file | unit |
//! |---|---|
//! | [`d_cntr`] | D_CNTR's pair queue (and the RTL queue's reference) |
//! | [`chip`] | the chip: D_CNTR's entry and issue control, held words, leaf pairs, results |
//! | [`dop_unit`] | DOP unit pipeline with the side delay line |
//! | [`tri_unit`] | TRI_UNIT pipeline and result FIFO |
//! | [`memory`] | memory port and memory model |
//! | [`delay`] | a fixed-latency pipeline, and the RTL's synchronous FIFO as one |
//! | [`drive`] | one driver for every level: host, memory model, result reader, lockstep |
//!
//! The model runs any configuration the golden model runs (k, format, rounding) with any
//! [`Params`]; [`Params::RTL`] is the RTL chip's point.

pub mod chip;
pub mod d_cntr;
pub mod delay;
pub mod dop_unit;
pub mod drive;
pub mod memory;
pub mod tri_unit;

pub use memory::{Ddr, MemCounters, MemTiming, Memory};

use serde::{Deserialize, Serialize};

/// The timing parameters of the chip's microarchitecture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Params {
    /// Queue entries (two node pairs each).
    pub queue_entries: u32,
    /// Clocks from a DOP test's issue to its result.
    pub dop_latency: u32,
    /// Clocks from a pair entering TRI_UNIT to its verdict at the output.
    pub tri_latency: u32,
    /// TRI_UNIT's result FIFO: pairs taken and not yet given out.
    pub tri_fifo: u32,
    /// Clocks between two DOP issues at the least (the RTL: 2, so that the two child
    /// entries of a result are pushed one per clock; at 1 the queue has a second write
    /// port and takes both in one clock).
    pub issue_spacing: u32,
    /// DOP tests in flight plus leaf pairs waiting: the leaf FIFO's entries.
    pub credit: u32,
    /// Memory requests outstanding (at most one per triangle destination).
    pub outstanding: u32,
    /// Node pairs popped from the queue ahead of the current entry, whose node words the
    /// port asks for before they reach the DOP unit (a pair buffer of `prefetch + 2` pairs,
    /// their words queued in request order). 0: the port asks only for the current pair's
    /// words. The RTL chip: 0 to 14 and `outstanding` 1 to 16, in host register 0x126.
    pub prefetch: u32,
    pub memory: Memory,
}

impl Params {
    /// The RTL chip (`rtl/chip_e8m15_k6.v`) after reset: 2^10 queue entries, the 15-clock
    /// DOP unit, TRI_UNIT's 130 clocks and 256-entry FIFO, issues two clocks apart, a credit
    /// of 16, one request outstanding, no prefetch. `tb/rtl_chip.rs` checks these against
    /// the RTL; its host register 0x126 sets the last four (`cycle::chip::reg::PORT`).
    pub const RTL: Params = Params {
        queue_entries: 1 << crate::harness::chip_io::QUEUE_BITS,
        dop_latency: crate::rtl::DOP_LATENCY as u32,
        tri_latency: crate::rtl::e8m15::TriUnit::LATENCY as u32,
        tri_fifo: crate::rtl::e8m15::TriUnit::FIFO_DEPTH as u32,
        issue_spacing: 2,
        credit: crate::rtl::CREDIT as u32,
        outstanding: 1,
        prefetch: 0,
        memory: Memory::Ideal(MemTiming { latency: 1, interval: 1, bus_bits: None }),
    };

    /// Pairs prefetched at most.
    pub const MAX_PREFETCH: u32 = 256;

    /// Errors name a parameter out of range.
    pub fn check(&self) -> Result<(), String> {
        let nonzero = [
            ("queue_entries", self.queue_entries),
            ("dop_latency", self.dop_latency),
            ("tri_latency", self.tri_latency),
            ("tri_fifo", self.tri_fifo),
            ("credit", self.credit),
        ];
        if let Some((n, _)) = nonzero.iter().find(|(_, v)| *v == 0) {
            return Err(format!("chip parameter {n} must be at least 1"));
        }
        if self.tri_latency < delay::FIFO_WRITE_TO_HEAD + 1 {
            return Err(format!("tri_latency must be at least {} (the result FIFO's registers)", delay::FIFO_WRITE_TO_HEAD + 1));
        }
        if !(1..=2).contains(&self.issue_spacing) {
            return Err("issue_spacing must be 1 or 2 clocks".into());
        }
        if !(1..=memory::MemPort::MAX).contains(&self.outstanding) {
            return Err(format!("outstanding must be 1 to {} requests", memory::MemPort::MAX));
        }
        if self.prefetch > Params::MAX_PREFETCH {
            return Err(format!("prefetch must be at most {} pairs", Params::MAX_PREFETCH));
        }
        self.memory.check()
    }
}

impl Default for Params {
    fn default() -> Self {
        Params::RTL
    }
}

/// The chip's inputs in one clock cycle (the RTL's input ports; a memory response names
/// the word address it answers, which a level that needs the data looks up).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChipIn {
    pub host_we: bool,
    pub host_addr: u32,
    pub host_data: u32,
    pub start: bool,
    pub mem_req_ready: bool,
    /// `mem_resp_valid`, with the address of the word on `mem_resp_data`.
    pub mem_resp: Option<u32>,
    pub res_ready: bool,
}

/// The chip's outputs in one clock cycle: functions of its registers only, so they show
/// the state after the last rising edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChipOut {
    pub busy: bool,
    pub done: bool,
    pub overflow: bool,
    pub max_depth: u64,
    pub dop_tests: u64,
    pub tri_tests: u64,
    pub node_fetches: u64,
    pub tri_fetches: u64,
    pub mem_req_valid: bool,
    pub mem_req_addr: u32,
    pub res_valid: bool,
    /// A's triangle, B's triangle.
    pub res_tag: (u32, u32),
    pub res_uncertain: bool,
}

impl ChipOut {
    /// With the values nobody may read zeroed: the request address without a request,
    /// the result's fields without a result.
    pub fn specified(&self) -> ChipOut {
        let mut o = *self;
        if !o.mem_req_valid {
            o.mem_req_addr = 0;
        }
        if !o.res_valid {
            (o.res_tag, o.res_uncertain) = ((0, 0), false);
        }
        o
    }
}

/// The chip at any level: outputs from registers, one rising edge per [`step`](Self::step).
pub trait Clocked {
    /// The outputs in the current cycle.
    fn outputs(&self) -> ChipOut;
    /// Applies `i` for the current cycle and clocks one rising edge. With `probe`, returns
    /// the [`PROBES`] signals' values in that cycle (inputs applied, before the edge).
    fn step(&mut self, i: &ChipIn, probe: bool) -> Option<Vec<u64>>;
    /// Why this level cannot go on (a lockstep difference), if so.
    fn fault(&self) -> Option<String> {
        None
    }
}

impl<C: Clocked + ?Sized> Clocked for &mut C {
    fn outputs(&self) -> ChipOut {
        (**self).outputs()
    }

    fn step(&mut self, i: &ChipIn, probe: bool) -> Option<Vec<u64>> {
        (**self).step(i, probe)
    }

    fn fault(&self) -> Option<String> {
        (**self).fault()
    }
}

/// The traversal signals every level shows (VCD scopes under `chip`, GTKWave save file
/// scripts/gtkw/chip_e8m15_k6.gtkw): `(scope, name, width)`. [`probe_valid`] says which
/// signal qualifies a value (a value nobody reads is left unspecified).
pub const PROBES: [(&str, &str, u32); 50] = [
    ("host", "start", 1),
    ("host", "busy", 1),
    ("host", "done", 1),
    ("host", "overflow", 1),
    ("host", "halt", 1),
    ("d_cntr", "depth", 16),
    ("d_cntr", "max_depth", 16),
    ("d_cntr", "push", 1),
    ("d_cntr", "pop", 1),
    ("d_cntr", "entry_valid", 1),
    ("d_cntr", "pair_a", 16),
    ("d_cntr", "pair_b", 16),
    ("d_cntr", "need_a", 1),
    ("d_cntr", "need_b", 1),
    ("d_cntr", "issue", 1),
    ("d_cntr", "in_flight", 8),
    ("memory", "req_valid", 1),
    ("memory", "req_ready", 1),
    ("memory", "req_addr", 24),
    ("memory", "req_dst", 2),
    ("memory", "outstanding", 1),
    ("memory", "resp_valid", 1),
    ("dop", "valid_out", 1),
    ("dop", "overlap", 1),
    ("dop", "result_a", 16),
    ("dop", "result_b", 16),
    ("dop", "a_leaf", 1),
    ("dop", "b_leaf", 1),
    ("leaves", "leaf_in", 1),
    ("leaves", "waiting", 8),
    ("leaves", "leaf_valid", 1),
    ("leaves", "tri_a", 16),
    ("leaves", "tri_b", 16),
    ("tri_unit", "in_valid", 1),
    ("tri_unit", "in_ready", 1),
    ("tri_unit", "take", 1),
    ("tri_unit", "in_flight", 16),
    ("tri_unit", "out_valid", 1),
    ("tri_unit", "out_hit", 1),
    ("tri_unit", "out_uncertain", 1),
    ("tri_unit", "out_a", 16),
    ("tri_unit", "out_b", 16),
    ("results", "res_valid", 1),
    ("results", "res_uncertain", 1),
    ("results", "res_a", 16),
    ("results", "res_b", 16),
    ("counters", "dop_tests", 32),
    ("counters", "tri_tests", 32),
    ("counters", "node_fetches", 32),
    ("counters", "tri_fetches", 32),
];

/// The scopes of [`PROBES`], in order.
pub fn probe_scopes() -> Vec<&'static str> {
    let mut v: Vec<&str> = PROBES.iter().map(|p| p.0).collect();
    v.dedup();
    v
}

/// For each of [`PROBES`], the index of the signal that must be 1 for its value to be
/// specified (`None`: always specified): the current pair's nodes, a request's address and
/// destination, a DOP result's fields, TRI_UNIT's output and the result port's fields.
pub fn probe_valid(i: usize) -> Option<usize> {
    let idx = |scope: &str, name: &str| PROBES.iter().position(|p| p.0 == scope && p.1 == name);
    match (PROBES[i].0, PROBES[i].1) {
        ("d_cntr", "pair_a" | "pair_b") => idx("d_cntr", "entry_valid"),
        ("memory", "req_addr" | "req_dst") => idx("memory", "req_valid"),
        ("dop", "overlap" | "result_a" | "result_b" | "a_leaf" | "b_leaf") => idx("dop", "valid_out"),
        ("tri_unit", "out_hit" | "out_uncertain" | "out_a" | "out_b") => idx("tri_unit", "out_valid"),
        ("results", "res_uncertain" | "res_a" | "res_b") => idx("results", "res_valid"),
        _ => None,
    }
}

/// A bound on one query's clocks on the cycle model (waits are skipped, so a long memory
/// latency costs no time; the bound only catches a hung model).
pub const MAX_CYCLES: u64 = 1 << 50;

/// What a cycle-model run records besides its trace.
#[derive(Default)]
pub struct Record<'p> {
    /// Count where the clocks went ([`chip::Stats`]).
    pub counters: bool,
    /// Write a traversal VCD here: the [`PROBES`] of these scopes (all if empty) in this
    /// window of cycles.
    pub vcd: Option<(&'p std::path::Path, &'p [String], std::ops::Range<u64>)>,
    /// Call with every cycle's [`PROBES`] values (a cross-check).
    pub probes: Option<&'p mut dyn FnMut(u64, &[u64]) -> Result<(), String>>,
}

/// One query on the cycle model: `chip`'s images and configuration, B placed by `setup`,
/// order `lifo`, `mode`, timing `p`, results read by `reader`. Returns the trace and, if
/// `rec.counters`, where the clocks went. Without a VCD or a probe observer, waits are
/// skipped in one step (the trace is the same); with one, the query runs clock by clock
/// ([`drive::ProbeVcd`] writes the RTL's signal names: scripts/gtkw/chip_e8m15_k6.gtkw opens
/// it).
#[allow(clippy::too_many_arguments)]
pub fn run_query(
    chip: &crate::query::Chip,
    setup: &crate::dop::HostSetup,
    lifo: bool,
    mode: crate::traversal::Mode,
    p: Params,
    reader: drive::Reader,
    max_cycles: u64,
    rec: Record,
) -> Result<(drive::ChipTrace, Option<chip::Stats>), String> {
    let mut c = chip::Chip::new(&chip.cfg, p, &chip.a, &chip.b, setup, rec.counters)?;
    let d = drive::Drive { memory: p.memory, word_bits: chip.layout.word_bits(), reader, words: chip::image_words(&chip.a, &chip.b), max_cycles };
    let writes = chip::control_writes(&chip.a, &chip.b, lifo, mode, &p, chip.cfg.tri_cache);
    let Record { vcd, probes: mut observer, .. } = rec;
    let trace = if vcd.is_none() && observer.is_none() {
        let mut skip = |c: &mut chip::Chip, i: &ChipIn, max: u64| match c.quiet_until(i) {
            Some(t) => {
                let n = (t - c.now()).min(max);
                c.skip(n, i);
                n
            }
            None => 0,
        };
        drive::run_query(&mut c, &writes, &d, false, |_, _| Ok(()), Some(&mut skip))
    } else {
        let mut w = match vcd {
            Some((path, scopes, window)) => Some((drive::open_vcd(path, scopes, window).map_err(|e| e.0)?, path)),
            None => None,
        };
        drive::run_query(&mut c, &writes, &d, true, |t, v| {
            let v = v.unwrap_or_default();
            if let Some((w, path)) = &mut w {
                w.cycle(t, &v).map_err(|e| format!("{}: {e}", path.display()))?;
            }
            match observer.as_deref_mut() {
                Some(f) => f(t, &v),
                None => Ok(()),
            }
        }, None)
    }
    .map_err(|e| e.0)?;
    Ok((trace, c.stats))
}
