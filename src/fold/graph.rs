//! T.CHECK's dataflow graph (petgraph), traced from [`ops::tcheck`]:
//! nodes are the input words and the floating-point operations in the golden order, edges
//! the operands (with the free sign-clearing and doubling applied on the way in).

use super::ops::{self, Arith, Const, Inputs, Rnd};
use petgraph::graph::{DiGraph, NodeIndex};
use petgraph::Direction;

/// The kind of shared unit an operation needs: multipliers and adders per rounding,
/// constant multipliers per constant (each `FpScale` holds its constants).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Class {
    Mul(Rnd),
    Add(Rnd),
    Scale(Const),
}

impl Class {
    /// Every class, in the order the RTL instantiates their units.
    pub const ALL: [Class; 7] = [
        Class::Mul(Rnd::Value),
        Class::Mul(Rnd::Up),
        Class::Add(Rnd::Value),
        Class::Add(Rnd::Up),
        Class::Scale(Const::Ce),
        Class::Scale(Const::Cz),
        Class::Scale(Const::Cs),
    ];

    /// Index in [`Class::ALL`].
    pub fn index(self) -> usize {
        Class::ALL
            .iter()
            .position(|&c| c == self)
            .expect("every class is in ALL")
    }
}

/// A node: input word `i` ([`Inputs::from_words`]'s order) or an operation (`sub`: the
/// adder subtracts).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    Input(usize),
    Fp { class: Class, sub: bool },
}

/// An operand edge: port 0 (`a`) or 1 (`b`), the value's sign cleared (`abs`) or doubled
/// (`dbl`) on the way into the unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Operand {
    pub port: usize,
    pub abs: bool,
    pub dbl: bool,
}

/// A traced value: the node computing it and the modifiers applied since.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Val {
    pub node: NodeIndex,
    pub abs: bool,
    pub dbl: bool,
}

/// T.CHECK's graph and its outputs ([`ops::Outputs`], every one a node taken as computed).
pub struct Graph {
    pub g: DiGraph<Op, Operand>,
    pub outputs: ops::Outputs<NodeIndex>,
}

struct Tracer(DiGraph<Op, Operand>);

impl Tracer {
    fn op(&mut self, class: Class, sub: bool, operands: &[Val]) -> Val {
        let n = self.0.add_node(Op::Fp { class, sub });
        for (port, v) in operands.iter().enumerate() {
            self.0.add_edge(
                v.node,
                n,
                Operand {
                    port,
                    abs: v.abs,
                    dbl: v.dbl,
                },
            );
        }
        Val {
            node: n,
            abs: false,
            dbl: false,
        }
    }
}

impl Arith for Tracer {
    type V = Val;
    fn mul(&mut self, a: Val, b: Val, r: Rnd) -> Val {
        self.op(Class::Mul(r), false, &[a, b])
    }
    fn add(&mut self, a: Val, b: Val, r: Rnd) -> Val {
        self.op(Class::Add(r), false, &[a, b])
    }
    fn sub(&mut self, a: Val, b: Val, r: Rnd) -> Val {
        self.op(Class::Add(r), true, &[a, b])
    }
    fn scale(&mut self, a: Val, c: Const) -> Val {
        self.op(Class::Scale(c), false, &[a])
    }
    fn abs(&mut self, a: Val) -> Val {
        assert!(!a.dbl, "|2x| is not a hardware operand modifier");
        Val { abs: true, ..a }
    }
    fn dbl(&mut self, a: Val) -> Val {
        Val { dbl: true, ..a }
    }
}

impl Graph {
    /// T.CHECK's graph, traced from [`ops::tcheck`]: nodes 0 .. [`Inputs::WORDS`] are the
    /// input words, then the operations in the golden order.
    pub fn tcheck() -> Graph {
        let mut t = Tracer(DiGraph::new());
        let nodes: Vec<NodeIndex> = (0..Inputs::<Val>::WORDS)
            .map(|i| t.0.add_node(Op::Input(i)))
            .collect();
        let inputs = Inputs::from_words(|i| Val {
            node: nodes[i],
            abs: false,
            dbl: false,
        });
        let out = ops::tcheck(&mut t, &inputs);
        let node = |v: Val| {
            assert!(!v.abs && !v.dbl, "an output is a unit's result");
            v.node
        };
        let outputs = out.map(node);
        Graph { g: t.0, outputs }
    }

    /// The class of node `n` (`None` for an input).
    pub fn class(&self, n: NodeIndex) -> Option<Class> {
        match self.g[n] {
            Op::Fp { class, .. } => Some(class),
            Op::Input(_) => None,
        }
    }

    /// The operands of `n` by port: (source node, operand).
    pub fn operands(&self, n: NodeIndex) -> Vec<(NodeIndex, Operand)> {
        let mut v: Vec<_> = self
            .g
            .edges_directed(n, Direction::Incoming)
            .map(|e| (petgraph::visit::EdgeRef::source(&e), *e.weight()))
            .collect();
        v.sort_by_key(|(_, o)| o.port);
        v
    }
}

/// Operations per class ([`Class::ALL`]'s order) of a graph.
pub fn counts(g: &DiGraph<Op, Operand>) -> [usize; 7] {
    let mut c = [0; 7];
    for op in g.node_weights() {
        if let Op::Fp { class, .. } = op {
            c[class.index()] += 1;
        }
    }
    c
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The graph has T.CHECK's operation counts (derived by hand from the golden order,
    /// value + magnitude: stage 1 36 + 36 products, 27 + 27 sums (9 dot products of 2
    /// sums, 3 of 3), A' 2 products + 1 sum; per vertex 9 + 9 products and A' L1, 9 + 9
    /// sums, L1 3, the translation terms 3, G and H 2, 5 constant products; per edge 4 + 8
    /// products, 5 + 12 sums, one constant product) and is acyclic with every input used.
    #[test]
    fn tcheck_graph_counts() {
        let g = Graph::tcheck();
        assert_eq!(
            counts(&g.g),
            [
                36 + 27 + 12,
                36 + 2 + 3 * 10 + 3 * 8,
                27 + 27 + 3 * 5,
                27 + 1 + 3 * 17 + 3 * 12,
                9,
                3,
                6
            ]
        );
        assert!(!petgraph::algo::is_cyclic_directed(&g.g));
        for n in g.g.node_indices() {
            assert!(
                g.g.edges_directed(n, Direction::Outgoing).count() > 0
                    || g.outputs.all().contains(&n),
                "{n:?} unused"
            );
        }
    }
}
