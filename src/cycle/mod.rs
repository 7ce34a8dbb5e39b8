//! The fast cycle-exact model of the chip (the level "cycle" of docs/introduction.md): the same
//! microarchitecture as the RTL chip ([`rtl::chip`](crate::rtl)), unit by unit, each unit's
//! state changing once per clock from the previous clock's registers as
//! docs/explanation/architecture.md "Cycle semantics" says. Values (DOP overlaps, TRI_UNIT verdicts)
//! come from [`golden`](crate::golden): this model adds *when* things happen, never a
//! second copy of the arithmetic (as gem5's timing CPUs call `StaticInst::execute`).
//!
//! | file | unit |
//! |---|---|
//! | [`d_cntr`] | D_CNTR's pair queue (and the RTL queue's reference) |
//! | [`chip`] | the chip: D_CNTR's entry and issue control, held words, leaf pairs, results |
//! | [`dop_unit`] | DOP unit pipeline with the side delay line |
//! | [`tri_unit`] | TRI_UNIT pipeline and result FIFO |
//! | [`memory_port`] | the memory port: requests outstanding, where responses go |
//! | [`memory`] | the memory models (ideal, DDR SDRAM) |
//! | [`delay`] | a fixed-latency pipeline, and the RTL's synchronous FIFO as one |
//! | [`drive`] | one driver for every level: host, memory model, result reader, lockstep |
//! | [`wscg03`] | WSCG'03's chip: Stack Engine, DOP Unit, Triangle Unit, Memory Controller |
//!
//! The model runs any configuration the golden model runs (k, format, rounding) with any
//! [`Params`]; [`Params::RTL`] is the RTL chip's point.

pub mod chip;
pub mod d_cntr;
pub mod delay;
pub mod dop_unit;
pub mod drive;
pub mod memory;
pub mod memory_port;
pub mod tri_unit;
pub mod wscg03;

use crate::chip::params::Params;
use crate::chip::reg::{Mode, Order};

/// A bound on one query's clocks on the cycle model (waits are skipped, so a long memory
/// latency costs no time; the bound only catches a hung model).
pub const MAX_CYCLES: u64 = 1 << 50;

/// Called with every cycle's traversal signals' values ([`DATE05`](crate::chip::probes::DATE05)); an Err stops the run.
pub type ProbeObserver<'p> = dyn FnMut(u64, &[u64]) -> Result<(), String> + 'p;

/// A traversal VCD asked for: its path, the scopes written (all if empty), the window of
/// cycles.
pub struct VcdOut<'p>(
    pub &'p std::path::Path,
    pub &'p [String],
    pub std::ops::Range<u64>,
);

impl VcdOut<'_> {
    /// The VCD file of `probes`, opened.
    pub fn open(
        self,
        probes: &'static crate::chip::probes::Probes,
    ) -> Result<drive::VcdFile, String> {
        drive::open_vcd(self.0, probes, self.1, self.2).map_err(|e| e.0)
    }
}

/// What a cycle-model run records besides its trace.
#[derive(Default)]
pub struct Record<'p> {
    /// Count where the clocks went ([`chip::Stats`]).
    pub counters: bool,
    /// Write a traversal VCD of the [`DATE05`](crate::chip::probes::DATE05) signals.
    pub vcd: Option<VcdOut<'p>>,
    /// Call with every cycle's [`DATE05`](crate::chip::probes::DATE05) values (a cross-check).
    pub probes: Option<&'p mut ProbeObserver<'p>>,
}

/// One query on the cycle model: `chip`'s images and configuration, B placed by `setup`,
/// `order`, `mode`, timing `p`, results read by `reader`. Returns the trace and, if
/// `rec.counters`, where the clocks went. Without a VCD or a probe observer, waits are
/// skipped in one step (the trace is the same); with one, the query runs clock by clock
/// ([`drive::ProbeVcd`] writes the RTL's signal names: scripts/gtkw/chip_e8m15_k6.gtkw opens
/// it).
pub fn run_query(
    chip: &crate::query::Chip,
    setup: &crate::golden::host::HostSetup,
    order: Order,
    mode: Mode,
    p: Params,
    reader: drive::Reader,
    max_cycles: u64,
    rec: Record,
) -> Result<(drive::ChipTrace, Option<chip::Stats>), String> {
    let mut c = chip::Chip::new(&chip.cfg, p, &chip.a, &chip.b, setup, rec.counters)?;
    let d = drive::Drive {
        memory: p.memory_clocks()?,
        word_bits: chip.layout.word_bits(),
        reader,
        words: chip.image_span(&p.memory),
        max_cycles,
    };
    let writes = chip.control_writes(order, mode, &p);
    let Record {
        vcd,
        probes: mut observer,
        ..
    } = rec;
    let trace = if vcd.is_none() && observer.is_none() {
        drive::run_query(&mut c, &writes, &d, false, |_, _| Ok(()), true)
    } else {
        let mut w = vcd
            .map(|v| v.open(&crate::chip::probes::DATE05))
            .transpose()?;
        drive::run_query(
            &mut c,
            &writes,
            &d,
            true,
            |t, v| {
                let v = v.unwrap_or_default();
                if let Some(w) = &mut w {
                    w.cycle(t, &v)?;
                }
                match observer.as_deref_mut() {
                    Some(f) => f(t, &v),
                    None => Ok(()),
                }
            },
            false,
        )
    }
    .map_err(|e| e.0)?;
    Ok((trace, c.stats))
}
