//! Modulo list scheduling of a dataflow graph onto shared pipelined units: a new input set
//! every `ii` clocks (the initiation interval), each operation given a unit of its class
//! and a start cycle such that no unit is asked for two operations in the same cycle mod
//! `ii` and no operation starts before its operands are in registers.
//!
//! Cycle convention (the folded RTL's, `rtl::tcheck_fold`): the input words are in
//! registers in cycle 0; an operation started in cycle t presents its operands during
//! cycle t, its unit's result is on the unit's output in cycle t + L (L the unit's latency)
//! and in a register from cycle t + L + 1 ([`Schedule::ready`]).

use super::graph::{counts, Class, Op, Operand};
use crate::chip::rtl::{Depth, FP_SCALE_LATENCY};
use petgraph::graph::{DiGraph, NodeIndex};
use petgraph::Direction;

/// A unit's latency from its operands' selection to its result at `depth`: the
/// multiplier's, the adder's or `FpScale`'s pipeline (the RTL checks its units against
/// these), at FPGA depth behind a register that holds the selected operands (the operand
/// multiplexers registered, `rtl::tcheck_fold`).
pub fn latency(c: Class, depth: Depth) -> usize {
    let unit = match c {
        Class::Mul(_) => depth.fp_mul_latency(),
        Class::Add(_) => depth.fp_add_latency(),
        Class::Scale(_) => FP_SCALE_LATENCY,
    };
    unit + depth.operand_registers()
}

/// Units per class ([`Class::ALL`]'s order).
pub type Units = [usize; 7];

/// The fewest units that run every operation once per `ii` clocks: ceil(ops / ii) per class.
pub fn minimal_units(g: &DiGraph<Op, Operand>, ii: usize) -> Units {
    counts(g).map(|n| n.div_ceil(ii))
}

/// A schedule: per node (by index) its start cycle and unit instance within its class
/// (inputs: 0, 0), and the cycle in which every output is in a register.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Schedule {
    pub ii: usize,
    pub depth: Depth,
    pub units: Units,
    pub start: Vec<usize>,
    pub unit: Vec<usize>,
    pub out_at: usize,
}

impl Schedule {
    /// The first cycle node `n`'s value is in a register: 0 for an input.
    pub fn ready(&self, g: &DiGraph<Op, Operand>, n: NodeIndex) -> usize {
        match g[n] {
            Op::Input(_) => 0,
            Op::Fp { class, .. } => self.start[n.index()] + latency(class, self.depth) + 1,
        }
    }

    /// Register stages from an input set to its results, the project's latency (`TCheck`'s
    /// 52): the input registers (written at edge 0), then the outputs read in cycle
    /// [`Schedule::out_at`] into the output registers at edge `out_at + 1`.
    pub fn latency(&self) -> usize {
        self.out_at + 2
    }
}

/// Schedules `g` for initiation interval `ii` on `units` (per class) at `depth`, the outputs read
/// when all of `outputs` are ready. Operations are placed in order of their earliest
/// possible start (unlimited units; ties by node index), each in the first cycle at or
/// after its operands are ready where a unit of its class is free in that cycle mod `ii`.
/// Err if `ii` is 0, the graph has a cycle, or a class has more operations than its units
/// can start in `ii` clocks.
pub fn schedule(
    g: &DiGraph<Op, Operand>,
    outputs: &[NodeIndex],
    ii: usize,
    units: Units,
    depth: Depth,
) -> Result<Schedule, String> {
    if ii == 0 {
        return Err("the initiation interval must be at least 1".into());
    }
    for (c, (&n, &u)) in Class::ALL.iter().zip(counts(g).iter().zip(&units)) {
        if n > u * ii {
            return Err(format!(
                "{n} {c:?} operations need at least {} units at II {ii}, not {u}",
                n.div_ceil(ii)
            ));
        }
    }
    let topo = petgraph::algo::toposort(g, None)
        .map_err(|c| format!("the graph has a cycle through {:?}", c.node_id()))?;
    let mut asap = vec![0; g.node_count()];
    for &n in &topo {
        let lat = match g[n] {
            Op::Input(_) => 0,
            Op::Fp { class, .. } => latency(class, depth) + 1,
        };
        for s in g.neighbors_directed(n, Direction::Outgoing) {
            asap[s.index()] = asap[s.index()].max(asap[n.index()] + lat);
        }
    }
    let mut order = topo;
    order.sort_by_key(|n| (asap[n.index()], n.index()));
    let mut s = Schedule {
        ii,
        depth,
        units,
        start: vec![0; g.node_count()],
        unit: vec![0; g.node_count()],
        out_at: 0,
    };
    // busy[class][unit][cycle mod ii]
    let mut busy: Vec<Vec<Vec<bool>>> = units.iter().map(|&u| vec![vec![false; ii]; u]).collect();
    for n in order {
        let Op::Fp { class, .. } = g[n] else { continue };
        let earliest = g
            .neighbors_directed(n, Direction::Incoming)
            .map(|p| s.ready(g, p))
            .max()
            .unwrap_or(0);
        let table = &mut busy[class.index()];
        let (t, u) = (earliest..earliest + ii)
            .find_map(|t| table.iter().position(|b| !b[t % ii]).map(|u| (t, u)))
            .expect("a class within its capacity has a free unit in any ii consecutive cycles");
        table[u][t % ii] = true;
        (s.start[n.index()], s.unit[n.index()]) = (t, u);
    }
    s.out_at = outputs.iter().map(|&n| s.ready(g, n)).max().unwrap_or(0);
    Ok(s)
}

/// Checks a schedule's invariants: every operation starts at or after its operands are
/// ready, no later than the outputs are read where it is an output, and no unit of a class
/// starts two operations in the same cycle mod `ii`, nor is a unit used that does not
/// exist. Err names the first violation.
pub fn check(g: &DiGraph<Op, Operand>, outputs: &[NodeIndex], s: &Schedule) -> Result<(), String> {
    let mut used = std::collections::HashSet::new();
    for n in g.node_indices() {
        for p in g.neighbors_directed(n, Direction::Incoming) {
            if s.start[n.index()] < s.ready(g, p) {
                return Err(format!(
                    "{n:?} starts at {} before its operand {p:?} is ready at {}",
                    s.start[n.index()],
                    s.ready(g, p)
                ));
            }
        }
        if let Op::Fp { class, .. } = g[n] {
            let (c, u, slot) = (class.index(), s.unit[n.index()], s.start[n.index()] % s.ii);
            if u >= s.units[c] {
                return Err(format!("{n:?} on {class:?} unit {u} of {}", s.units[c]));
            }
            if !used.insert((c, u, slot)) {
                return Err(format!("{n:?}: {class:?} unit {u} twice in slot {slot}"));
            }
        }
    }
    match outputs.iter().find(|&&n| s.ready(g, n) > s.out_at) {
        Some(n) => Err(format!(
            "output {n:?} ready after the outputs are read at {}",
            s.out_at
        )),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fold::graph::Graph;
    use proptest::prelude::*;

    /// A random DAG: `inputs` input nodes, then operations of random classes whose
    /// operands are random earlier nodes; the last few nodes are the outputs.
    fn dag(
        inputs: usize,
        ops: Vec<(usize, usize, usize)>,
    ) -> (DiGraph<Op, Operand>, Vec<NodeIndex>) {
        let mut g = DiGraph::new();
        for i in 0..inputs {
            g.add_node(Op::Input(i));
        }
        for (c, a, b) in ops {
            let class = Class::ALL[c % 7];
            let n = g.add_node(Op::Fp { class, sub: false });
            let k = n.index();
            g.add_edge(
                NodeIndex::new(a % k),
                n,
                Operand {
                    port: 0,
                    abs: false,
                    dbl: false,
                },
            );
            if !matches!(class, Class::Scale(_)) {
                g.add_edge(
                    NodeIndex::new(b % k),
                    n,
                    Operand {
                        port: 1,
                        abs: false,
                        dbl: false,
                    },
                );
            }
        }
        let outs = (g.node_count().saturating_sub(3)..g.node_count())
            .map(NodeIndex::new)
            .collect();
        (g, outs)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]
        /// On random graphs, any II and any number of spare units, the schedule keeps
        /// every dependency under the units' latencies and never double-books a unit.
        #[test]
        fn random_graphs_schedule_validly(
            inputs in 1usize..6,
            ops in prop::collection::vec((0usize..7, 0usize..1000, 0usize..1000), 1..80),
            ii in prop::sample::select(vec![1usize, 2, 3, 4, 8, 16, 32]),
            spare in prop::array::uniform7(0usize..3),
            depth in prop::sample::select(Depth::ALL.to_vec()),
        ) {
            let (g, outs) = dag(inputs, ops);
            let mut units = minimal_units(&g, ii);
            for (u, s) in units.iter_mut().zip(spare) {
                *u += s;
            }
            let s = schedule(&g, &outs, ii, units, depth).unwrap();
            prop_assert_eq!(check(&g, &outs, &s), Ok(()));
        }
    }

    /// T.CHECK's graph schedules validly on the fewest units at every II the folds use,
    /// at either depth.
    #[test]
    fn tcheck_schedules_at_every_ii() {
        let g = Graph::tcheck();
        let outs = g.outputs.all();
        for (ii, depth) in [1, 2, 4, 8, 16, 32]
            .into_iter()
            .flat_map(|ii| Depth::ALL.map(|d| (ii, d)))
        {
            let s = schedule(&g.g, &outs, ii, minimal_units(&g.g, ii), depth).unwrap();
            assert_eq!(check(&g.g, &outs, &s), Ok(()), "II {ii} {depth:?}");
        }
        assert!(
            schedule(&g.g, &outs, 16, [1; 7], Depth::Asic).is_err(),
            "75 products do not fit one multiplier at II 16"
        );
    }

    /// The check catches a schedule broken by hand: an operation moved one cycle before
    /// its operand is ready, and two operations on one unit in the same slot.
    #[test]
    fn check_catches_broken_schedules() {
        let g = Graph::tcheck();
        let outs = g.outputs.all();
        let s = schedule(&g.g, &outs, 16, minimal_units(&g.g, 16), Depth::Asic).unwrap();
        let n = g.outputs.s_bound[2];
        let p =
            g.g.neighbors_directed(n, Direction::Incoming)
                .max_by_key(|&p| s.ready(&g.g, p))
                .unwrap();
        let mut early = s.clone();
        early.start[n.index()] = s.ready(&g.g, p) - 1;
        assert!(check(&g.g, &outs, &early)
            .unwrap_err()
            .contains("before its operand"));
        let mut twice = s.clone();
        let m = g.outputs.s_bound[1];
        twice.start[n.index()] = s.start[m.index()] + 16 * 4;
        twice.unit[n.index()] = s.unit[m.index()];
        assert!(check(&g.g, &outs, &twice)
            .unwrap_err()
            .contains("twice in slot"));
    }
}
