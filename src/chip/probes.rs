//! The traversal signals every level of a chip shows, for VCDs and for lockstep comparison:
//! DATE'05's chip's ([`DATE05`]) and WSCG'03's ([`WSCG03`]).

/// A traversal signal: `(scope, name, width)`.
pub type Probe = (&'static str, &'static str, u32);

type Qualified = (
    (&'static str, &'static str),
    &'static str,
    &'static [&'static str],
);

/// A chip's traversal signals, which every level of it shows (VCD scopes under `chip`, one
/// per unit), and which signal qualifies which (a value nobody reads is left unspecified).
/// Nodes are shown by the chip's ids ([`node_ids`](super::layout::node_ids)), triangles by
/// their indices.
pub struct Probes {
    /// The signals, in the order every level gives their values.
    pub signals: &'static [Probe],
    /// `((scope, qualifier), scope, names)`: `scope`'s `names` are specified only while the
    /// qualifier (a 1-bit signal of the list) is 1, and it is specified.
    qualified: &'static [Qualified],
    /// The GTKWave save file that shows its VCDs.
    pub gtkw: &'static str,
}

impl Probes {
    /// The index of `scope`'s signal `name`.
    pub fn index(&self, scope: &str, name: &str) -> Option<usize> {
        self.signals
            .iter()
            .position(|p| (p.0, p.1) == (scope, name))
    }

    /// The scopes, in order.
    pub fn scopes(&self) -> Vec<&'static str> {
        let mut v: Vec<&str> = self.signals.iter().map(|p| p.0).collect();
        v.dedup();
        v
    }

    /// The index of the signal that must be 1 for signal `i`'s value to be specified
    /// (`None`: always specified).
    pub fn valid(&self, i: usize) -> Option<usize> {
        let (scope, name, _) = self.signals[i];
        let ((qs, q), _, _) = self
            .qualified
            .iter()
            .find(|q| q.1 == scope && q.2.contains(&name))?;
        self.index(qs, q)
    }

    /// Whether signal `i`'s value in `values` is specified: each qualifier up the chain is 1.
    pub fn specified(&self, i: usize, values: &[u64]) -> bool {
        self.valid(i)
            .is_none_or(|v| values[v] == 1 && self.specified(v, values))
    }
}

/// DATE'05's chip's traversal signals (GTKWave save file scripts/gtkw/chip_e8m15_k6.gtkw):
/// the current pair's nodes, a request's address and destination, a DOP result's fields,
/// TRI_UNIT's output and the result port's fields are qualified.
pub const DATE05: Probes = Probes {
    signals: &DATE05_SIGNALS,
    qualified: &[
        (("d_cntr", "entry_valid"), "d_cntr", &["pair_a", "pair_b"]),
        (("memory", "req_valid"), "memory", &["req_addr", "req_dst"]),
        (
            ("dop", "valid_out"),
            "dop",
            &["overlap", "result_a", "result_b", "a_leaf", "b_leaf"],
        ),
        (
            ("tri_unit", "out_valid"),
            "tri_unit",
            &["out_hit", "out_uncertain", "out_a", "out_b"],
        ),
        (
            ("results", "res_valid"),
            "results",
            &["res_uncertain", "res_a", "res_b"],
        ),
    ],
    gtkw: "scripts/gtkw/chip_e8m15_k6.gtkw",
};

const DATE05_SIGNALS: [Probe; 50] = [
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

/// WSCG'03's CollisionChip's traversal signals, named after its units (§4): the host's,
/// the Stack Engine's lists and the sequencer's commands to them, the Memory Controller's
/// asks and port, the DOP Unit's input and flags, the Triangle Unit's leaf pairs and
/// TRI_UNIT, the result port, the counters (GTKWave save file
/// scripts/gtkw/chip_wscg03_b32_k24.gtkw). What a working clock decides (the lists'
/// commands, asks, bundles, leaf pairs) is specified while the query runs (`host.busy`).
pub const WSCG03: Probes = Probes {
    signals: &WSCG03_SIGNALS,
    qualified: &[
        (
            ("host", "busy"),
            "stack_engine",
            &["read", "next_list", "append"],
        ),
        (
            ("stack_engine", "append"),
            "stack_engine",
            &["append_side", "append_ptr"],
        ),
        (("stack_engine", "rd_valid"), "stack_engine", &["rd_ptr"]),
        (("host", "busy"), "memory_controller", &["ask"]),
        (
            ("memory_controller", "ask"),
            "memory_controller",
            &["ask_load", "ask_set", "ask_pair", "ask_id"],
        ),
        (
            ("memory_controller", "req_valid"),
            "memory_controller",
            &["req_addr"],
        ),
        (("host", "busy"), "dop_unit", &["load", "compare"]),
        (("dop_unit", "flags_valid"), "dop_unit", &["overlap"]),
        (
            ("host", "busy"),
            "triangle_unit",
            &["leaf_valid", "leaf_ready", "in_valid"],
        ),
        (
            ("triangle_unit", "leaf_valid"),
            "triangle_unit",
            &["leaf_a", "leaf_b"],
        ),
        (
            ("triangle_unit", "out_valid"),
            "triangle_unit",
            &["out_hit", "out_uncertain", "out_a", "out_b"],
        ),
        (
            ("results", "res_valid"),
            "results",
            &["res_uncertain", "res_a", "res_b"],
        ),
    ],
    gtkw: "scripts/gtkw/chip_wscg03_b32_k24.gtkw",
};

const WSCG03_SIGNALS: [Probe; 52] = [
    ("host", "start", 1),
    ("host", "busy", 1),
    ("host", "done", 1),
    ("host", "overflow", 1),
    ("host", "halt", 1),
    ("stack_engine", "level", 5),
    ("stack_engine", "branch", 1),
    ("stack_engine", "remaining", 16),
    ("stack_engine", "stepping_up", 1),
    ("stack_engine", "lists_done", 1),
    ("stack_engine", "read", 1),
    ("stack_engine", "next_list", 1),
    ("stack_engine", "append", 1),
    ("stack_engine", "append_side", 1),
    ("stack_engine", "append_ptr", 16),
    ("stack_engine", "rd_valid", 1),
    ("stack_engine", "rd_ptr", 16),
    ("stack_engine", "lists", 32),
    ("memory_controller", "ask", 1),
    ("memory_controller", "ask_load", 1),
    ("memory_controller", "ask_set", 1),
    ("memory_controller", "ask_pair", 1),
    ("memory_controller", "ask_id", 16),
    ("memory_controller", "room", 4),
    ("memory_controller", "req_valid", 1),
    ("memory_controller", "req_ready", 1),
    ("memory_controller", "req_addr", 24),
    ("memory_controller", "resp_valid", 1),
    ("dop_unit", "load", 1),
    ("dop_unit", "compare", 1),
    ("dop_unit", "busy", 2),
    ("dop_unit", "flags_valid", 1),
    ("dop_unit", "overlap", 2),
    ("triangle_unit", "leaf_valid", 1),
    ("triangle_unit", "leaf_ready", 1),
    ("triangle_unit", "leaf_a", 16),
    ("triangle_unit", "leaf_b", 16),
    ("triangle_unit", "in_valid", 1),
    ("triangle_unit", "in_ready", 1),
    ("triangle_unit", "out_valid", 1),
    ("triangle_unit", "out_hit", 1),
    ("triangle_unit", "out_uncertain", 1),
    ("triangle_unit", "out_a", 16),
    ("triangle_unit", "out_b", 16),
    ("results", "res_valid", 1),
    ("results", "res_uncertain", 1),
    ("results", "res_a", 16),
    ("results", "res_b", 16),
    ("counters", "dop_tests", 32),
    ("counters", "tri_tests", 32),
    ("counters", "node_fetches", 32),
    ("counters", "tri_fetches", 32),
];

#[cfg(test)]
mod tests {
    use super::*;

    /// Each list's signals are named once; every qualifier is a 1-bit signal of the list,
    /// and every name it qualifies is one.
    #[test]
    fn qualifiers_are_signals_of_the_list() {
        for p in [&DATE05, &WSCG03] {
            for (i, s) in p.signals.iter().enumerate() {
                assert_eq!(p.index(s.0, s.1), Some(i), "{s:?} twice");
            }
            for &((qs, q), scope, names) in p.qualified {
                let v = p
                    .index(qs, q)
                    .unwrap_or_else(|| panic!("no qualifier {qs}.{q}"));
                assert_eq!(p.signals[v].2, 1, "{qs}.{q}");
                for n in names {
                    let i = p
                        .index(scope, n)
                        .unwrap_or_else(|| panic!("no {scope}.{n}"));
                    assert_eq!(p.valid(i), Some(v), "{scope}.{n}");
                }
            }
        }
    }
}
