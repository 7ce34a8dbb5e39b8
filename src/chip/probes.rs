//! The traversal signals every level shows, for VCDs and for lockstep comparison.

/// The traversal signals every level shows (VCD scopes under `chip`, GTKWave save file
/// scripts/gtkw/chip_e8m15_k6.gtkw): `(scope, name, width)`. [`probe_valid`] says which
/// signal qualifies a value (a value nobody reads is left unspecified). Nodes are shown by
/// the chip's ids ([`node_ids`](super::layout::node_ids)), triangles by their indices.
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

/// The index in [`PROBES`] of `scope`'s signal `name`.
pub fn probe_index(scope: &str, name: &str) -> Option<usize> {
    PROBES.iter().position(|p| (p.0, p.1) == (scope, name))
}

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
    let idx = probe_index;
    match (PROBES[i].0, PROBES[i].1) {
        ("d_cntr", "pair_a" | "pair_b") => idx("d_cntr", "entry_valid"),
        ("memory", "req_addr" | "req_dst") => idx("memory", "req_valid"),
        ("dop", "overlap" | "result_a" | "result_b" | "a_leaf" | "b_leaf") => {
            idx("dop", "valid_out")
        }
        ("tri_unit", "out_hit" | "out_uncertain" | "out_a" | "out_b") => {
            idx("tri_unit", "out_valid")
        }
        ("results", "res_uncertain" | "res_a" | "res_b") => idx("results", "res_valid"),
        _ => None,
    }
}
