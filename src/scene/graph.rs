//! A scene's work as a dataflow graph (`petgraph`): the chip's units at the level each runs
//! at (DATE'05 Fig. 4: D_CNTR, the memory port, the DOP unit, TRI_UNIT, the result port),
//! the memory model, and the effects around them (host, exact oracle, counters, waveform
//! writer, the levels a cross-check runs). The scene's outputs name sinks; only their
//! ancestors are kept ([`Plan::of`]), and the kept graph becomes a plain schedule (stages in
//! dataflow order; a feedback loop, the clocked units, is one stage). Nothing walks the
//! graph per clock: the run asks the plan once which units it builds.

use super::{CrossCheck, Scene};
use petgraph::graph::{DiGraph, NodeIndex};
use petgraph::visit::{Dfs, Reversed};
use serde::Serialize;
use std::collections::BTreeSet;
use std::fmt::Write;

/// Where a unit runs: the golden model, the cycle model, rust-hdl, or the exported Verilog
/// under Verilator.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Level {
    Functional,
    Cycle,
    Rtl,
    Verilog,
}

/// A node of the graph: a unit or effect, or one of the outputs a scene names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Unit {
    Meshes,
    HostTrees,
    HostSetup,
    Golden,
    HostSettle,
    ExactOracle,
    AccuracyCounter,
    DCntr,
    MemoryPort,
    MemoryModel,
    DopUnit,
    TriUnit,
    ResultPort,
    GoldenCheck,
    Counters,
    WaveformWriter,
    RtlChip,
    VerilogChip,
    // outputs (sinks)
    OutPairs,
    OutCycles,
    OutMemory,
    OutWaveforms,
    OutAccuracy,
    OutCrossCheck,
}

impl Unit {
    pub const ALL: [Unit; 24] = [
        Unit::Meshes,
        Unit::HostTrees,
        Unit::HostSetup,
        Unit::Golden,
        Unit::HostSettle,
        Unit::ExactOracle,
        Unit::AccuracyCounter,
        Unit::DCntr,
        Unit::MemoryPort,
        Unit::MemoryModel,
        Unit::DopUnit,
        Unit::TriUnit,
        Unit::ResultPort,
        Unit::GoldenCheck,
        Unit::Counters,
        Unit::WaveformWriter,
        Unit::RtlChip,
        Unit::VerilogChip,
        Unit::OutPairs,
        Unit::OutCycles,
        Unit::OutMemory,
        Unit::OutWaveforms,
        Unit::OutAccuracy,
        Unit::OutCrossCheck,
    ];

    /// The name `--explain` and the DOT graph show (the papers' names for the chip's units).
    pub fn name(self) -> &'static str {
        match self {
            Unit::Meshes => "meshes",
            Unit::HostTrees => "host_trees",
            Unit::HostSetup => "host_setup",
            Unit::Golden => "golden",
            Unit::HostSettle => "host_settle",
            Unit::ExactOracle => "exact_oracle",
            Unit::AccuracyCounter => "accuracy_counter",
            Unit::DCntr => "d_cntr",
            Unit::MemoryPort => "memory_port",
            Unit::MemoryModel => "memory_model",
            Unit::DopUnit => "dop_unit",
            Unit::TriUnit => "tri_unit",
            Unit::ResultPort => "result_port",
            Unit::GoldenCheck => "golden_check",
            Unit::Counters => "counters",
            Unit::WaveformWriter => "waveform_writer",
            Unit::RtlChip => "rtl_chip",
            Unit::VerilogChip => "verilog_chip",
            Unit::OutPairs => "pairs",
            Unit::OutCycles => "cycles",
            Unit::OutMemory => "memory",
            Unit::OutWaveforms => "waveforms",
            Unit::OutAccuracy => "accuracy",
            Unit::OutCrossCheck => "cross_check",
        }
    }

    /// The name `--explain` shows in `s`: WSCG'03's units for its chip (the Stack Engine in
    /// D_CNTR's place, the Memory Controller in the port's, the Triangle Unit, the Pointer
    /// FIFO).
    pub fn name_in(self, s: &Scene) -> &'static str {
        if s.architecture != crate::chip::wscg03::Architecture::Wscg03 {
            return self.name();
        }
        match self {
            Unit::DCntr => "stack_engine",
            Unit::MemoryPort => "memory_controller",
            Unit::TriUnit => "triangle_unit",
            Unit::ResultPort => "pointer_fifo",
            u => u.name(),
        }
    }

    /// What WSCG'03's units do in `s` (`None`: the unit is the same as DATE'05's).
    fn does_wscg03(self, s: &Scene) -> Option<String> {
        use crate::chip::rtl as r;
        let (k, p) = (s.cfg.k, &s.params);
        Some(match self {
            Unit::DCntr => format!("WSCG'03's Stack Engine, clocked as its RTL: lists of aligned pointers in two SRAMs of {} (read latency 1), its sequencer taking one list per tumbled sibling group, left list first, stepping up when both are done", 1 << r::LIST_SRAM_BITS),
            Unit::MemoryPort => format!("WSCG'03's Memory Controller: a node pair per record and burst, {} asks, {} records held or in flight, at most {} requests outstanding; triangle words first, A's through a {}-line cache, B's in a two-entry SRAM", r::MC_ASKS, r::MC_RECORDS, p.outstanding, s.cfg.tri_cache),
            Unit::DopUnit => format!("WSCG'03's DOP Unit: two DOTADD units transform a tumbled group into one of two d' sets in {} clocks, the left member's children speculatively into the other; an aligned DOP against both siblings in {} bundles of 256 bits, flags {} clocks after its last", r::wscg03_transform_clocks(k), k.div_ceil(8), r::WSCG03_COMPARE_LATENCY),
            Unit::TriUnit => format!("WSCG'03's Triangle Unit: the input stage, then TRI_UNIT's two T.CHECKs (a pair a clock, verdict {} clocks later)", p.tri_latency),
            Unit::ResultPort => "intersecting and uncertain pairs to the host, read at once".into(),
            Unit::GoldenCheck => "the cycle model's pairs against the golden list traversal's (WSCG'03 Algorithm 2)".into(),
            _ => return None,
        })
    }

    /// The level the unit runs at; `None` for an output.
    pub fn level(self) -> Option<Level> {
        use Unit::*;
        match self {
            Meshes | HostTrees | HostSetup | Golden | HostSettle | ExactOracle
            | AccuracyCounter => Some(Level::Functional),
            DCntr | MemoryPort | MemoryModel | DopUnit | TriUnit | ResultPort | GoldenCheck
            | Counters | WaveformWriter => Some(Level::Cycle),
            RtlChip => Some(Level::Rtl),
            VerilogChip => Some(Level::Verilog),
            OutPairs | OutCycles | OutMemory | OutWaveforms | OutAccuracy | OutCrossCheck => None,
        }
    }

    /// What the unit does in `scene` (one line).
    pub fn does(self, s: &Scene) -> String {
        if let Some(d) = (s.architecture == crate::chip::wscg03::Architecture::Wscg03)
            .then(|| self.does_wscg03(s))
            .flatten()
        {
            return d;
        }
        let p = &s.params;
        let o = &s.outputs;
        match self {
            Unit::Meshes => format!(
                "read A = {} and B = {}{}",
                s.objects.a,
                s.objects.b,
                if s.objects.unit_cube { ", each scaled into [-1,1]^3" } else { "" }
            ),
            Unit::HostTrees => format!("{}-DOP trees and memory images of A and B ({})", s.cfg.k, s.cfg.format),
            Unit::HostSetup => format!("per pose ({}): B's placement, the DOP unit's C, c and D.KLMSEL, TRI_UNIT's frame maps", s.poses.len()),
            Unit::Golden => format!(
                "the golden model's {} traversal ({} mode): DOPTRF, T.CHECK, in software, one pose at a time (timed: the fastest of {} runs)",
                s.traversal.name(),
                format!("{:?}", s.mode).to_lowercase(),
                crate::measure::TIMING_RUNS
            ),
            Unit::HostSettle => "exact predicates on the pairs T.CHECK left uncertain".into(),
            Unit::ExactOracle => "every intersecting pair exactly (AABB broad phase, exact predicates on the f64 geometry)".into(),
            Unit::AccuracyCounter => "misses and extra pairs of the chip against the exact oracle".into(),
            Unit::DCntr => format!("the pair queue ({} entries), pair buffer and issue control (every {} clock(s), credit {})", p.queue_entries, p.issue_spacing, p.credit),
            Unit::MemoryPort => {
                let prefetch = if p.prefetch > 0 { format!(", node words of {} pairs prefetched", p.prefetch) } else { String::new() };
                let cache = |side: &str, lines: u32| if lines > 1 { format!(", {side}'s triangle words through a {lines}-line direct-mapped cache") } else { String::new() };
                let (ca, cb) = (cache("A", s.cfg.tri_cache), cache("B", s.cfg.tri_cache_b));
                let tri = if p.tri_prefetch { ", a leaf pair's triangle words asked for as it enters the leaf FIFO" } else { "" };
                format!("node and triangle word requests, {} outstanding{prefetch}{ca}{cb}{tri}", p.outstanding)
            }
            Unit::MemoryModel => p.memory.describe_at(p.clock_ps),
            Unit::DopUnit => {
                let decode = match crate::chip::rtl::dop_decode_latency(&s.cfg) {
                    0 => String::new(),
                    d => format!(" after the stored DOPs' decode stage, {d} clocks"),
                };
                match p.dop_interval {
                    1 => format!("DOPTRF transform and compare, {} clocks{decode}", p.dop_latency),
                    ii => format!("DOPTRF transform and compare on k/{ii} lanes, a pair every {ii} clocks, {} clocks{decode}", p.dop_unit_latency()),
                }
            }
            Unit::TriUnit => format!("T.CHECK both ways, {} clocks, {}-entry result FIFO", p.tri_latency, p.tri_fifo),
            Unit::ResultPort => "intersecting and uncertain pairs to the host, read every clock".into(),
            Unit::GoldenCheck => "the cycle model's pairs against the golden model's".into(),
            Unit::Counters => "where the clocks went (stall causes, occupancy) and memory traffic".into(),
            Unit::WaveformWriter => match &o.waveforms {
                Some(w) => format!("a VCD per pose into {} ({}, {})", w.dir.display(), w.scopes_text(), w.window_text()),
                None => "a VCD per pose".into(),
            },
            Unit::RtlChip => format!("the rust-hdl chip{}, in lockstep with the cycle model (every output and probe, every clock)", chip_name(s)),
            Unit::VerilogChip => format!("the exported Verilog{} under Verilator (built once, cached under target/), every port every clock against the cycle model", chip_name(s)),
            Unit::OutPairs => format!("the summary table{}", if o.pairs { " and every pose's pairs" } else { "" }),
            Unit::OutCycles => format!(
                "clocks per query; the chip's time at {}; the software's time and the host's setup and settling (measured, warm: the fastest of {} runs); end to end; speed-up; stall table",
                s.clock.as_ref().map_or("-".into(), crate::chip::timing::Clock::source),
                crate::measure::TIMING_RUNS
            ),
            Unit::OutMemory => "memory words and bytes, words per clock, port busy share".into(),
            Unit::OutWaveforms => format!("VCD files for GTKWave ({})", s.architecture.probes().gtkw),
            Unit::OutAccuracy => "exact pairs, misses, extras per pose".into(),
            Unit::OutCrossCheck => "agreement of the levels, or the pose, cycle and signal of the first difference".into(),
        }
    }
}

/// ` (rtl/<chip>.v)`: the RTL chip a scene's configuration runs on, if one is built for it
/// (otherwise the run stops with `chip_io::rtl_order`'s error).
fn chip_name(s: &Scene) -> String {
    crate::chip::rtl::ChipKind::of(
        &s.cfg,
        s.params.dop_interval,
        s.params.tri_interval,
        s.params.depth,
    )
    .map_or(String::new(), |k| format!(" (rtl/{}.v)", k.name()))
}

/// The whole graph: every unit, an edge for each flow of data.
pub fn full_graph() -> (DiGraph<Unit, ()>, Vec<NodeIndex>) {
    use Unit::*;
    let mut g = DiGraph::new();
    let ix: Vec<NodeIndex> = Unit::ALL.iter().map(|&u| g.add_node(u)).collect();
    let n = |u: Unit| ix[Unit::ALL.iter().position(|&x| x == u).expect("listed")];
    let clocked = [DCntr, MemoryPort, MemoryModel, DopUnit, TriUnit, ResultPort];
    let mut edges = vec![
        (Meshes, HostTrees),
        (HostTrees, HostSetup),
        (HostSetup, Golden),
        (Golden, HostSettle),
        (HostSettle, OutPairs),
        (Meshes, ExactOracle),
        (ExactOracle, AccuracyCounter),
        (HostSettle, AccuracyCounter),
        (AccuracyCounter, OutAccuracy),
        // the clocked loop: register writes and memory image in, pairs to DOP tests,
        // children back to the queue, leaf pairs with their triangle words to TRI_UNIT,
        // results out, a first hit halting D_CNTR
        (HostSetup, DCntr),
        (HostTrees, MemoryModel),
        (DCntr, MemoryPort),
        (MemoryPort, MemoryModel),
        (MemoryModel, MemoryPort),
        (MemoryPort, DopUnit),
        (DopUnit, DCntr),
        (MemoryPort, TriUnit),
        (DCntr, TriUnit),
        (TriUnit, ResultPort),
        (ResultPort, DCntr),
        (ResultPort, GoldenCheck),
        (Golden, GoldenCheck),
        (GoldenCheck, OutCycles),
        (Counters, OutCycles),
        (Counters, OutMemory),
        (MemoryModel, OutMemory),
        (WaveformWriter, OutWaveforms),
        (HostSetup, RtlChip),
        (HostTrees, RtlChip),
        (RtlChip, OutCrossCheck),
        (HostSetup, VerilogChip),
        (HostTrees, VerilogChip),
        (VerilogChip, OutCrossCheck),
    ];
    for u in clocked {
        edges.extend([(u, Counters), (u, WaveformWriter), (u, OutCrossCheck)]);
    }
    for (a, b) in edges {
        g.add_edge(n(a), n(b), ());
    }
    (g, ix)
}

/// The outputs a scene asks for: always the pairs (the summary), and the sinks its
/// `[outputs]` name.
pub fn sinks(s: &Scene) -> Vec<Unit> {
    let o = &s.outputs;
    let mut v = vec![Unit::OutPairs];
    for (on, u) in [
        (o.cycles, Unit::OutCycles),
        (o.memory, Unit::OutMemory),
        (o.waveforms.is_some(), Unit::OutWaveforms),
        (o.accuracy, Unit::OutAccuracy),
        (o.cross_check.is_some(), Unit::OutCrossCheck),
    ] {
        if on {
            v.push(u);
        }
    }
    v
}

/// A scene's pruned graph and its schedule.
#[derive(Debug)]
pub struct Plan {
    /// The units the sinks need, the sinks included.
    pub kept: BTreeSet<Unit>,
    /// The kept units in stages, each stage after the ones it reads from; the units of a
    /// feedback loop (the clocked chip) share a stage and run together, clock by clock.
    pub stages: Vec<Vec<Unit>>,
    /// The level a cross-check runs beside the cycle model.
    pub cross_check: Option<CrossCheck>,
}

impl Plan {
    /// The ancestors of the scene's sinks, in stages. The cross-check level keeps only its
    /// own chip (rust-hdl or Verilog).
    pub fn of(s: &Scene) -> Plan {
        let (mut g, ix) = full_graph();
        let drop = match s.outputs.cross_check {
            Some(CrossCheck::Rtl) => Some(Unit::VerilogChip),
            Some(CrossCheck::Verilog) => Some(Unit::RtlChip),
            None => None,
        };
        if let Some(u) = drop {
            let i = ix[Unit::ALL.iter().position(|&x| x == u).expect("listed")];
            g.retain_edges(|g, e| g.edge_endpoints(e).is_some_and(|(a, _)| a != i));
        }
        let mut kept = BTreeSet::new();
        for sink in sinks(s) {
            let start = ix[Unit::ALL.iter().position(|&x| x == sink).expect("listed")];
            let rev = Reversed(&g);
            let mut dfs = Dfs::new(rev, start);
            while let Some(n) = dfs.next(rev) {
                kept.insert(g[n]);
            }
        }
        let sub = g.filter_map(|_, &u| kept.contains(&u).then_some(u), |_, &e| Some(e));
        // strongly connected components come out in reverse topological order
        let mut sccs = petgraph::algo::tarjan_scc(&sub);
        sccs.reverse();
        let stages = sccs
            .into_iter()
            .map(|c| {
                let mut units: Vec<Unit> = c.into_iter().map(|n| sub[n]).collect();
                units.sort();
                units
            })
            .collect();
        Plan {
            kept,
            stages,
            cross_check: s.outputs.cross_check,
        }
    }

    /// Whether the run builds and runs `u`.
    pub fn runs(&self, u: Unit) -> bool {
        self.kept.contains(&u)
    }

    /// `cchip run --explain`: the stages, what each unit will do, and what is skipped.
    pub fn explain(&self, s: &Scene) -> String {
        let mut out = String::new();
        let asked: Vec<&str> = sinks(s).iter().map(|u| u.name()).collect();
        let _ = writeln!(
            out,
            "scene: {}\noutputs: {}\n{}\n",
            s.name,
            asked.join(", "),
            s.configuration()
        );
        let mut k = 0;
        for stage in &self.stages {
            let units: Vec<Unit> = stage
                .iter()
                .copied()
                .filter(|u| u.level().is_some())
                .collect();
            if units.is_empty() {
                continue;
            }
            k += 1;
            let together = if units.len() > 1 {
                " (clocked together, every clock)"
            } else {
                ""
            };
            let _ = writeln!(out, "stage {k}{together}");
            for u in units {
                let level = format!("{:?}", u.level().expect("a unit")).to_lowercase();
                let _ = writeln!(out, "  {:<17} {:<10} {}", u.name_in(s), level, u.does(s));
            }
        }
        let _ = writeln!(out, "outputs");
        for u in Unit::ALL
            .iter()
            .filter(|u| u.level().is_none() && self.runs(**u))
        {
            let _ = writeln!(out, "  {:<17} {}", u.name_in(s), u.does(s));
        }
        let skipped: Vec<&str> = Unit::ALL
            .iter()
            .filter(|u| !self.runs(**u))
            .map(|u| u.name())
            .collect();
        if !skipped.is_empty() {
            let _ = writeln!(out, "skipped (not built, not run): {}", skipped.join(", "));
        }
        out
    }

    /// The pruned graph of `s` in Graphviz DOT, its units named as in `--explain`; skipped
    /// units dashed and grey.
    pub fn dot(&self, s: &Scene) -> String {
        let (g, _) = full_graph();
        let mut out =
            String::from("digraph scene {\n  rankdir=LR;\n  node [fontname=\"Helvetica\"];\n");
        for u in Unit::ALL {
            let shape = if u.level().is_none() { "note" } else { "box" };
            let level = u
                .level()
                .map_or(String::new(), |l| format!("\\n{l:?}").to_lowercase());
            let style = if self.runs(u) {
                "solid"
            } else {
                "dashed\", color=\"grey\", fontcolor=\"grey"
            };
            let _ = writeln!(
                out,
                "  {} [label=\"{}{}\", shape={shape}, style=\"{style}\"];",
                u.name(),
                u.name_in(s),
                level
            );
        }
        for e in g.edge_indices() {
            let (a, b) = g.edge_endpoints(e).expect("an edge");
            let (a, b) = (g[a], g[b]);
            let on = self.runs(a) && self.runs(b);
            let style = if on {
                ""
            } else {
                " [style=dashed, color=grey]"
            };
            let _ = writeln!(out, "  {} -> {}{style};", a.name(), b.name());
        }
        out.push_str("}\n");
        out
    }
}
