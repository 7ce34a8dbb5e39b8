//! Folded units: a unit's operations, written once in the golden order
//! ([`ops`]), form a dataflow graph ([`graph`]); a modulo scheduler maps it onto a given
//! number of shared multipliers, adders and constant multipliers under their latencies
//! for an initiation interval `ii` ([`schedule`]); the schedule becomes registers,
//! operand multiplexers and a control counter ([`plan`]) that the RTL
//! (`rtl::tcheck_fold`) builds. Pure functions: the cycle model can take II and latency
//! from here too (docs/explanation/architecture.md, "Folded T.CHECK").

use crate::chip::rtl::Depth;

pub mod graph;
pub mod ops;
pub mod plan;
pub mod schedule;

/// T.CHECK folded for initiation interval `ii` on the fewest units that allow it at
/// `depth`, values bound to registers by `binding`.
pub fn tcheck_plan(ii: usize, binding: plan::Binding, depth: Depth) -> Result<plan::Plan, String> {
    let g = graph::Graph::tcheck();
    let s = schedule::schedule(
        &g.g,
        &g.outputs.all(),
        ii,
        schedule::minimal_units(&g.g, ii),
        depth,
    )?;
    Ok(plan::Plan::new(&g, &s, binding))
}

/// TRI_UNIT folded for initiation interval `ii` (a pair every `ii` clocks): both directions
/// on one T.CHECK folded for ii / 2, A's edges against U(B) when the pair is taken, B's
/// against U(A) ii / 2 clocks later (docs/explanation/architecture.md, "Folded TRI_UNIT"). The shared
/// T.CHECK's plan; Err for an odd or zero `ii`.
pub fn tri_unit_plan(
    ii: usize,
    binding: plan::Binding,
    depth: Depth,
) -> Result<plan::Plan, String> {
    if ii < 2 || ii % 2 == 1 {
        return Err(format!("a folded TRI_UNIT runs its two directions on one T.CHECK at II ii / 2, so ii must be even and at least 2, not {ii}"));
    }
    tcheck_plan(ii / 2, binding, depth)
}

/// The folded TRI_UNIT's latency from its shared T.CHECK's plan `p`: a pair taken at edge t
/// has its second direction in the T.CHECK at t + p.ii (at FPGA depth a clock later, behind
/// the T.CHECK's input registers), its result at the result FIFO's write port p.latency
/// clocks later and at the output two clocks after (the FIFO's write and read registers, as
/// in `TriUnit`).
pub fn tri_unit_latency(p: &plan::Plan) -> usize {
    p.ii + p.operand_regs() + p.latency + 2
}
