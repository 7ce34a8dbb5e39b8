//! WSCG'03's CollisionChip (§4, Fig. 4) in the cycle model, beside DATE'05's
//! ([`chip`](super::chip)): the Stack Engine's lists ([`stack_engine`]), the DOP Unit's
//! DOTADD transforms and compare units ([`dop_unit`]), the Triangle Unit
//! ([`tri_unit`]) and the Memory Controller (here: [`MemCtl`]) on the same memory models
//! ([`memory`](super::memory)), memory image and triangle words as DATE'05's chip. Values
//! come from the golden model (the list traversal's overlaps, TRI_UNIT's verdicts): this
//! model adds only *when*. It is an event model in program order (each unit keeps the
//! clock it is free; the Memory Controller asks for words in order), not clocked register
//! by register: of its units only the DOP Unit, the Stack Engine's lists, the Memory
//! Controller and the Triangle Unit's input stage are RTL so far, clocked here as
//! [`ClockedDopUnit`](dop_unit::ClockedDopUnit), [`ListStack`](stack_engine::ListStack) and
//! [`ClockedTriInput`](tri_unit::ClockedTriInput), which the event model does not use yet;
//! [`clocked`] runs the chip on them and on the Memory Controller clocked register by
//! register ([`memory_controller`]) (docs/explanation/architecture.md, "WSCG'03's chip").

pub mod clocked;
pub mod dop_unit;
pub mod memory_controller;
pub mod sequencer;
pub mod stack_engine;
pub mod tri_unit;

use super::drive::ChipTrace;
use super::memory::MemModel;
use crate::chip::layout::Dst;
use crate::chip::params::Params;
use crate::chip::reg::Mode;
use crate::chip::wscg03::StackParams;
use crate::golden::host::HostSetup;
use crate::golden::{dop_unit as gdop, tri_unit as gtri};
use serde::Serialize;

/// Where WSCG'03's clocks went: one cause per clock for the compare units (the DOP Unit's
/// input), and what the chip did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Stats {
    /// Clocks from start to done.
    pub cycles: u64,
    /// An aligned DOP streams through the compare units.
    pub compare: u64,
    /// Waiting for an aligned node word (the memory, or an interrupt for triangle words).
    pub stall_memory: u64,
    /// Waiting for the tumbled pair's transform (the start latency).
    pub stall_transform: u64,
    /// The Stack Engine between lists (the last flags, the next list's first pointer).
    pub stall_list: u64,
    /// After the last compare: the Triangle Unit finishes.
    pub drain: u64,
    /// Lists and their aligned node pairs (WSCG'03 Eq. 5's tau and sum of alpha).
    pub lists: u64,
    pub list_node_pairs: u64,
    /// Clocks from each list's start to the next's, summed.
    pub list_clocks: u64,
    /// Lists whose tumbled pair was not in the DOP Unit (fetched and transformed at their
    /// start), and their clocks from the start to the first compare, summed: WSCG'03's
    /// start latency (§4.1 estimates 64 clocks).
    pub cold_lists: u64,
    pub cold_start: u64,
    /// Tumbled DOPs transformed; speculative children pairs transformed, and used.
    pub transforms: u64,
    pub spec_pairs: u64,
    pub spec_used: u64,
    pub dop_tests: u64,
    pub dop_overlaps: u64,
    /// List processing interrupted for triangle words.
    pub interrupts: u64,
    pub tri_fetches_a: u64,
    /// The deepest hierarchy level reached, and the most aligned pointers in the SRAMs.
    pub max_level: u64,
    pub max_list_words: u64,
}

/// One list's timeline: its start (the Stack Engine's first read), whether its tumbled
/// pair's d' were in the DOP Unit already (transformed speculatively, or the same leaf),
/// when they are ready, its first compare (none if halted), the next list's start, and
/// its aligned nodes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct ListRecord {
    pub t0: u64,
    pub held: bool,
    pub ready: u64,
    pub first_compare: Option<u64>,
    pub next: u64,
    pub len: usize,
}

/// A query on WSCG'03's chip: the trace in DATE'05's format, where the clocks went, the
/// lists' timelines.
pub struct Run {
    pub trace: ChipTrace,
    pub stats: Stats,
    pub lists: Vec<ListRecord>,
}

/// WSCG'03's Memory Controller (§4.4): node and triangle words asked for in order, each
/// when the memory takes a request; a word answered in cycle r is present from r + 1.
pub struct MemCtl {
    mem: MemModel,
    bases: [u32; 4],
    last: u64,
    /// Node words and triangle words fetched.
    fetches: [u64; 2],
}

impl MemCtl {
    pub fn new(mem: MemModel, bases: [u32; 4]) -> Self {
        MemCtl {
            mem,
            bases,
            last: 0,
            fetches: [0; 2],
        }
    }

    /// Word `id` of `d`, asked for at clock `t` or later (after the previous request): the
    /// clock it is present.
    pub fn fetch(&mut self, t: u64, d: Dst, id: u32) -> u64 {
        let t = t.max(self.last).max(self.mem.next_ready());
        self.mem.request(t, self.bases[d as usize] + id);
        self.last = t;
        let mut done = t;
        // responses in request order: this one is the last
        while let Some(r) = self.mem.next_response() {
            self.mem.respond(r);
            done = r;
        }
        self.fetches[d.is_tri() as usize] += 1;
        done + 1
    }
}

/// WSCG'03's chip reads a node word per request (its Stack Engine asks for each node of a
/// list, §4.2) from an image of one node or triangle word per record: the `words` layout,
/// whatever layout `cfg` gives DATE'05's chip.
fn layout(cfg: &crate::chip::config::ChipConfig) -> crate::chip::layout::Layout {
    crate::chip::layout::Layout::new(&crate::chip::config::ChipConfig {
        layout: crate::chip::config::MemLayout::Words,
        ..*cfg
    })
}

/// One query on WSCG'03's chip: `chip`'s images, B placed by `setup`, `mode`, the memory
/// of `p`, the timing `sp`. All pairs or first hit; the host reads every result at once.
/// An error past `max_cycles` clocks, as DATE'05's chip ([`super::MAX_CYCLES`]; the event
/// model reaches its end in steps of events, so it is checked there).
pub fn run_query(
    chip: &crate::query::Chip,
    setup: &HostSetup,
    mode: Mode,
    p: &Params,
    sp: &StackParams,
    max_cycles: u64,
) -> Result<Run, String> {
    sp.check()?;
    let memory = p.memory_clocks()?;
    let cfg = &chip.cfg;
    let words = layout(cfg);
    let bases = crate::chip::layout::image_bases(
        chip.a.tree.len() as u32,
        chip.a.tri_count() as u32,
        chip.b.tree.len() as u32,
    );
    let mem = MemCtl::new(MemModel::new(memory, words.word_bits()), bases);
    let values = gdop::TransformCache::new(
        cfg.format.dop,
        cfg.dop_rounding.op(),
        setup,
        &chip.a.tree,
        &chip.b.tree,
    );
    let dop = dop_unit::DopUnit::new(values, sp, chip.layout.node_bits);
    let verdicts = gtri::TriUnit::new(
        cfg.format.tri,
        cfg.tri_rounding,
        setup,
        chip.a.tri_count(),
        chip.b.tri_count(),
    );
    let tri = tri_unit::TriUnit::new(&chip.a, &chip.b, verdicts, sp, cfg.tri_cache);
    let mut e = stack_engine::StackEngine::new(
        &chip.a,
        &chip.b,
        sp.sram_latency,
        sp.word_buffer,
        mem,
        dop,
        tri,
        mode == Mode::First,
    );
    e.run();
    if e.stats.cycles > max_cycles {
        return Err(super::drive::not_finished(max_cycles));
    }
    let mut s = e.stats;
    (s.transforms, s.spec_pairs, s.spec_used) =
        (e.dop.transforms, e.dop.spec_pairs, e.dop.spec_used);
    (s.dop_tests, s.dop_overlaps) = (e.dop.tests, e.dop.overlaps);
    let mut results = e.results;
    results.sort_by_key(|r| r.0);
    let trace = ChipTrace {
        results,
        cycles: s.cycles,
        overflow: false,
        max_depth: s.max_list_words,
        dop_tests: s.dop_tests,
        tri_tests: e.tri.tests,
        node_fetches: e.mem.fetches[0],
        tri_fetches: e.mem.fetches[1],
        memory: e.mem.mem.counters,
    };
    Ok(Run {
        trace,
        stats: s,
        lists: e.timeline,
    })
}
