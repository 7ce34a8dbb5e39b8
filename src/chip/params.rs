//! The timing parameters of the chip's microarchitecture, the cycle model's knobs and the
//! RTL chip's point among them.

use super::memory::{MemClocks, MemTiming, Memory};
use super::rtl;
use serde::{Deserialize, Serialize};

/// The timing parameters of the chip's microarchitecture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Params {
    /// Queue entries (two node pairs each).
    pub queue_entries: u32,
    /// Clocks from a DOP test's issue to its result (the unfolded DOP unit's; a folded one's
    /// is [`rtl::dop_fold_latency`]).
    pub dop_latency: u32,
    /// Clocks between pairs the DOP unit takes: 1, the unfolded unit (k lanes), or
    /// ii dividing k, the folded one (`rtl::*::DopUnit<k>Fold<ii>`: k/ii lanes in ii passes, a
    /// pair taken only when its counter, running from the first pair taken, is 0).
    pub dop_interval: u32,
    /// Clocks from a pair entering TRI_UNIT to its verdict at the output (the unfolded
    /// TRI_UNIT's; a folded one's is its schedule's, `fold::tri_unit_latency`).
    pub tri_latency: u32,
    /// Clocks between pairs TRI_UNIT takes: 1, the unfolded TRI_UNIT (a pair
    /// every clock), or an even 2 to 32, the folded TRI_UNIT (`TriUnitFold`: both
    /// directions on one T.CHECK folded for `tri_interval` / 2, a pair taken only when its
    /// control counter, running from the first pair taken, is 0).
    pub tri_interval: u32,
    /// How deep the FP units are cut (`asic`: the standard-cell pipelines; `fpga`: six stages
    /// each, and T.CHECK's operands registered): the folded units' latencies follow. At FPGA
    /// depth TRI_UNIT is folded (`tri_interval` 2 to 32).
    pub depth: rtl::Depth,
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
    /// words. The RTL chip: 0 to 14 and `outstanding` 1 to 16, in host register [`PORT`](super::reg::PORT).
    pub prefetch: u32,
    /// A leaf pair's triangle words asked for as it enters the leaf FIFO (queued in order
    /// for the leaf register) instead of when it reaches the leaf register. Cycle model only:
    /// the RTL chips ask at the leaf register.
    pub tri_prefetch: bool,
    /// Not read with the others: a scene's `[memory]` is a section of its own.
    #[serde(skip_deserializing)]
    pub memory: Memory,
    /// The chip's clock period in picoseconds, in whose clocks the models count a DDR
    /// memory's nanoseconds ([`memory_clocks`](Self::memory_clocks)): the preset's paper
    /// clock until a scene or the study sets its clock's. Not a scene key: `[timing]`
    /// `clock_mhz` or `technology` set the clock.
    #[serde(skip_deserializing)]
    pub clock_ps: u64,
}

impl Params {
    /// The RTL chip (`rtl/chip_e8m15_k6.v`) after reset: 2^10 queue entries, the 15-clock
    /// DOP unit, TRI_UNIT unfolded with its 54 clocks and 256-entry FIFO, issues two clocks apart, a credit
    /// of 16, one request outstanding, no prefetch. `tb/rtl_chip.rs` checks these against
    /// the RTL; its host register [`PORT`](super::reg::PORT) sets the last four.
    pub const RTL: Params = Params {
        queue_entries: 1 << rtl::QUEUE_BITS,
        dop_latency: rtl::DOP_LATENCY as u32,
        dop_interval: 1,
        tri_latency: rtl::TRI_LATENCY as u32,
        tri_fifo: rtl::TRI_FIFO as u32,
        tri_interval: 1,
        depth: rtl::Depth::Asic,
        issue_spacing: 2,
        credit: rtl::CREDIT as u32,
        outstanding: 1,
        prefetch: 0,
        tri_prefetch: false,
        memory: Memory::Ideal(MemTiming {
            latency: 1,
            interval: 1,
            bus_bits: None,
        }),
        clock_ps: 1250,
    };

    /// RTL chip `kind` after reset: [`RTL`](Self::RTL) with its DOP unit's and TRI_UNIT's
    /// intervals and its depth.
    pub const fn of(kind: rtl::ChipKind) -> Params {
        Params {
            dop_interval: kind.dop_interval(),
            tri_interval: kind.tri_interval(),
            depth: kind.depth(),
            ..Params::RTL
        }
    }

    /// Pairs prefetched at most.
    pub const MAX_PREFETCH: u32 = 256;
    /// Memory requests outstanding at most.
    pub const MAX_OUTSTANDING: u32 = 64;
    /// The longest folded TRI_UNIT's pair interval (the folds built: 2 to 32).
    pub const MAX_TRI_INTERVAL: u32 = 32;

    /// The DOP unit's latency: `dop_latency` unfolded (at FPGA depth the lane's), the folded
    /// unit's (the RTL's [`Depth::dop_fold_latency`](rtl::Depth::dop_fold_latency)) at a
    /// `dop_interval` over 1.
    pub fn dop_unit_latency(&self) -> u32 {
        match (self.dop_interval, self.depth) {
            (1, rtl::Depth::Asic) => self.dop_latency,
            (1, d) => d.lane_latency() as u32,
            (ii, d) => d.dop_fold_latency(ii as usize) as u32,
        }
    }

    /// The folded DOP unit runs k / `dop_interval` lanes: Err unless the interval divides k.
    pub fn check_dop_interval(&self, k: usize) -> Result<(), String> {
        if !k.is_multiple_of(self.dop_interval.max(1) as usize) {
            return Err(format!("dop_interval {} does not divide k = {k} (the folded DOP unit runs k / dop_interval lanes): pick a divisor of k", self.dop_interval));
        }
        Ok(())
    }

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
        if self.tri_latency < rtl::FIFO_WRITE_TO_HEAD + 1 {
            return Err(format!(
                "tri_latency must be at least {} (the result FIFO's registers)",
                rtl::FIFO_WRITE_TO_HEAD + 1
            ));
        }
        if !(self.tri_interval == 1
            || (2..=Params::MAX_TRI_INTERVAL).contains(&self.tri_interval)
                && self.tri_interval.is_multiple_of(2))
        {
            return Err(format!(
                "tri_interval must be 1 (TRI_UNIT unfolded) or an even number of clocks from 2 to {} (the folded TRI_UNIT runs its two directions on one T.CHECK at tri_interval / 2), not {}",
                Params::MAX_TRI_INTERVAL, self.tri_interval
            ));
        }
        if self.tri_interval > 1 && self.tri_latency != rtl::TRI_LATENCY as u32 {
            return Err(format!(
                "tri_latency {} is the unfolded TRI_UNIT's; a folded one (tri_interval {}) has its schedule's latency: remove tri_latency, or set tri_interval = 1",
                self.tri_latency, self.tri_interval
            ));
        }
        if self.depth == rtl::Depth::Fpga && self.tri_interval == 1 {
            return Err("at depth = \"fpga\" TRI_UNIT is the folded one: set tri_interval to an even number of clocks from 2 to 32, or depth = \"asic\"".into());
        }
        if self.depth != rtl::Depth::Asic && self.dop_latency != rtl::DOP_LATENCY as u32 {
            return Err(format!(
                "dop_latency {} is the unfolded DOP unit's at ASIC depth; at depth = \"fpga\" the DOP unit's latency is its lanes' ({} clocks unfolded): remove dop_latency, or set depth = \"asic\"",
                self.dop_latency,
                self.depth.lane_latency()
            ));
        }
        if self.dop_interval == 0 {
            return Err("dop_interval must be at least 1 (1: the DOP unit unfolded)".into());
        }
        if self.dop_interval > 1 && self.dop_latency != rtl::DOP_LATENCY as u32 {
            return Err(format!(
                "dop_latency {} is the unfolded DOP unit's; a folded one (dop_interval {}) has latency {}: remove dop_latency, or set dop_interval = 1",
                self.dop_latency,
                self.dop_interval,
                self.depth.dop_fold_latency(self.dop_interval as usize)
            ));
        }
        if !(1..=2).contains(&self.issue_spacing) {
            return Err("issue_spacing must be 1 or 2 clocks".into());
        }
        if !(1..=Params::MAX_OUTSTANDING).contains(&self.outstanding) {
            return Err(format!(
                "outstanding must be 1 to {} requests",
                Params::MAX_OUTSTANDING
            ));
        }
        if self.prefetch > Params::MAX_PREFETCH {
            return Err(format!(
                "prefetch must be at most {} pairs",
                Params::MAX_PREFETCH
            ));
        }
        if self.clock_ps == 0 {
            return Err("the chip's clock period must be at least 1 ps".into());
        }
        self.memory_clocks().map(|_| ())
    }

    /// The memory in the chip's clocks, at `clock_ps`.
    pub fn memory_clocks(&self) -> Result<MemClocks, String> {
        self.memory.at(self.clock_ps)
    }
}

impl Default for Params {
    fn default() -> Self {
        Params::RTL
    }
}
