//! Folded units (issue 33): a unit's operations, written once in the golden order
//! ([`ops`]), form a dataflow graph ([`graph`]); a modulo scheduler maps it onto a given
//! number of shared multipliers, adders and constant multipliers under their latencies
//! for an initiation interval `ii` ([`schedule`]); the schedule becomes registers,
//! operand multiplexers and a control counter ([`plan`]) that the RTL
//! (`rtl::tcheck_fold`) builds. Pure functions: the cycle model can take II and latency
//! from here too (docs/ARCHITECTURE.md, "Folded T.CHECK").

pub mod graph;
pub mod ops;
pub mod plan;
pub mod schedule;

/// T.CHECK folded for initiation interval `ii` on the fewest units that allow it.
pub fn tcheck_plan(ii: usize) -> Result<plan::Plan, String> {
    let g = graph::Graph::tcheck();
    let s = schedule::schedule(&g.g, &g.outputs.all(), ii, schedule::minimal_units(&g.g, ii))?;
    Ok(plan::Plan::new(&g, &s))
}
