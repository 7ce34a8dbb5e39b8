//! The folded T.CHECK's registers and control, from a [`Schedule`]: what the RTL
//! (`rtl::tcheck_fold`) builds, read by its simulation and by its Verilog alike.
//!
//! A free-running counter `c` counts 0 .. ii-1; during cycle t of an input set taken at
//! counter 0 (edge 0) it holds (t + 1) mod ii. Every value (an input word or an
//! operation's result) lives in a *chain* of registers: at each edge where the counter
//! equals the chain's slot (the value's ready cycle mod ii), the first register takes the
//! value's source (input port or unit output) and each other one its predecessor's. A
//! value ready in cycle T is then in register `first + (t - T) / ii` in cycle t, and a
//! chain is as long as its last read needs. An operation started in cycle t is issued
//! while the counter is (t + 1) mod ii: its unit's operand multiplexers select the
//! registers of that cycle.
//!
//! How values are bound to chains is a parameter, [`Binding`]: one chain per value (the
//! fewest registers), or one per value and reader (routable on an FPGA).

use super::graph::{Class, Graph, Op};
use super::ops::{Const, Outputs};
use super::schedule::Schedule;
use petgraph::graph::NodeIndex;
use petgraph::Direction;

/// What the first register of a chain takes: input word `i`, the result of a unit (class
/// index, unit), or one of the pair's side inputs (`v_exact`, `tag`, `valid_in`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Src {
    Input(usize),
    Unit(usize, usize),
    Side,
}

/// How a plan binds values to chains.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Binding {
    /// One chain per value, read by every unit that needs it: the fewest registers (the
    /// exported units and the area study).
    Shared,
    /// One chain per value and `Reader` (each unit, and the output registers): a unit's
    /// operand multiplexers select only among registers no other unit reads, which a placer
    /// puts beside it, and what crosses the chip is the units' outputs to the chains' first
    /// registers. Shared chains made every multiplexer reach across the whole register
    /// file, which nextpnr could not route on the LFE5U-85F (docs/guide/timing-and-fpga.md). The RTL marks
    /// these registers `keep` so that synthesis does not merge the copies back.
    PerReader,
}

/// Who reads a value's chain: a unit (class index, unit) or the output registers (all
/// readers are one under [`Binding::Shared`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
enum Reader {
    Unit(usize, usize),
    Outputs,
}

/// A chain of registers: `first .. first + len` in its register file, written at counter
/// value `slot`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Chain {
    pub first: usize,
    pub len: usize,
    pub slot: usize,
    pub src: Src,
}

/// A word register read into a unit or an output, with its sign cleared (`abs`) or the
/// value doubled (`dbl`, one more in the exponent field unless it is 0 or all ones).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Read {
    pub reg: usize,
    pub abs: bool,
    pub dbl: bool,
}

/// One operation issued to a unit: operands `a`, `b` (none for a constant multiplier),
/// the adder's `sub`, and the constant multiplier's `sel` (the `v_exact` register, or 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Issue {
    pub a: Read,
    pub b: Option<Read>,
    pub sub: bool,
    pub sel: Option<usize>,
}

/// The folded unit: word registers, the three side chains (1-bit `v_exact` and `valid`
/// registers, 32-bit tag registers), each unit's issue per counter value, and the output
/// registers' reads (words in `outputs`, the tag and valid registers `side_out`), taken at
/// counter value `out_slot`.
#[derive(Clone, Debug)]
pub struct Plan {
    pub ii: usize,
    pub binding: Binding,
    /// The FP units' depth, and with it the operand registers (`Depth::operand_registers`).
    pub depth: crate::chip::rtl::Depth,
    pub latency: usize,
    pub units: [usize; 7],
    pub words: Vec<Chain>,
    pub exact: Chain,
    pub valid: Chain,
    pub tag: Chain,
    /// `issues[class][unit][counter]`.
    pub issues: Vec<Vec<Vec<Option<Issue>>>>,
    pub out_slot: usize,
    pub outputs: Outputs<usize>,
    pub side_out: usize,
}

impl Plan {
    /// Registers between the operand multiplexers and the units: 0, or 1 at FPGA depth,
    /// where the counter's decode is also spread over copies of it ([`counter_copy`](Self::counter_copy)).
    pub fn operand_regs(&self) -> usize {
        self.depth.operand_registers()
    }

    /// Copies of the control counter at FPGA depth (none at ASIC depth): per unit one for its
    /// operands' `case` (2 `flat`) and one for its results' chains (2 `flat` + 1), then one
    /// per input word for its chains.
    pub fn counter_copies(&self) -> usize {
        match self.operand_regs() {
            0 => 0,
            _ => 2 * self.unit_count() + super::ops::Inputs::<u64>::WORDS,
        }
    }

    /// The copy of the counter that enables the chains of `src`, if there are copies and
    /// `src` has one (a unit's results, an input word).
    pub fn counter_copy(&self, src: Src) -> Option<usize> {
        match (self.counter_copies(), src) {
            (0, _) | (_, Src::Side) => None,
            (_, Src::Unit(k, u)) => Some(2 * self.flat(k, u) + 1),
            (_, Src::Input(n)) => Some(2 * self.unit_count() + n),
        }
    }

    /// The operand registers of a unit of class `k` at FPGA depth: `a` and `b` of a
    /// multiplier, those and `sub` of an adder, `a` and `sel` of a constant multiplier.
    pub fn operand_ports(k: usize) -> &'static [&'static str] {
        match k {
            0 | 1 => &["a", "b"],
            2 | 3 => &["a", "b", "sub"],
            _ => &["a", "sel"],
        }
    }

    /// Operand `port`'s register of unit `u` of class `k`, the registers of each port numbered
    /// over the units that have it (classes in [`Class::ALL`]'s order: multipliers, adders,
    /// constant multipliers).
    pub fn operand_reg(&self, k: usize, u: usize, port: &str) -> usize {
        let g = self.flat(k, u);
        match port {
            "sub" => g - self.units[..2].iter().sum::<usize>(),
            "sel" => g - self.units[..4].iter().sum::<usize>(),
            _ => g,
        }
    }

    /// Operand `port`'s registers in all: none at ASIC depth.
    pub fn operand_reg_count(&self, port: &str) -> usize {
        (0..7)
            .filter(|&k| Plan::operand_ports(k).contains(&port))
            .map(|k| self.units[k] * self.operand_regs())
            .sum()
    }

    /// The copy of the counter on which unit `u` of class `k` selects its operands.
    pub fn operand_counter_copy(&self, k: usize, u: usize) -> usize {
        2 * self.flat(k, u)
    }

    /// Unit `u` of class `k` numbered over all units ([`Class::ALL`]'s order).
    pub fn flat(&self, k: usize, u: usize) -> usize {
        self.units[..k].iter().sum::<usize>() + u
    }

    /// Units in all.
    pub fn unit_count(&self) -> usize {
        self.units.iter().sum()
    }

    /// Word registers in all.
    pub fn word_regs(&self) -> usize {
        self.words.iter().map(|c| c.len).sum()
    }

    /// The plan of `g` under schedule `s`, values bound to chains by `binding`.
    pub fn new(g: &Graph, s: &Schedule, binding: Binding) -> Plan {
        let ii = s.ii;
        let ready = |n: NodeIndex| s.ready(&g.g, n);
        // the reader of operation n's operands (shared: one reader, the outputs', for all)
        let reader = |n: NodeIndex| match (binding, g.class(n)) {
            (Binding::PerReader, Some(class)) => Reader::Unit(class.index(), s.unit[n.index()]),
            _ => Reader::Outputs,
        };
        // the last cycle each reader reads each value (in order: a reader's registers together)
        let mut last = std::collections::BTreeMap::<(Reader, usize), usize>::new();
        for n in g.g.node_indices() {
            for p in g.g.neighbors_directed(n, Direction::Incoming) {
                let l = last.entry((reader(n), p.index())).or_default();
                *l = (*l).max(s.start[n.index()]);
            }
        }
        for n in g.outputs.all() {
            let l = last.entry((Reader::Outputs, n.index())).or_default();
            *l = (*l).max(s.out_at);
        }
        let (mut words, mut chain_of, mut next) = (vec![], std::collections::HashMap::new(), 0);
        for (&(r, i), &l) in &last {
            let n = NodeIndex::new(i);
            let src = match g.g[n] {
                Op::Input(i) => Src::Input(i),
                Op::Fp { class, .. } => Src::Unit(class.index(), s.unit[n.index()]),
            };
            let len = (l - ready(n)) / ii + 1;
            chain_of.insert((r, i), words.len());
            words.push(Chain {
                first: next,
                len,
                slot: ready(n) % ii,
                src,
            });
            next += len;
        }
        let read = |n: NodeIndex, r: Reader, t: usize, abs: bool, dbl: bool| Read {
            reg: words[chain_of[&(r, n.index())]].first + (t - ready(n)) / ii,
            abs,
            dbl,
        };
        // v_exact: read by the c_e and c_z multipliers; valid and tag at the outputs
        let exact_last =
            g.g.node_indices()
                .filter(|&n| matches!(g.class(n), Some(Class::Scale(Const::Ce | Const::Cz))))
                .map(|n| s.start[n.index()])
                .max()
                .unwrap_or(0);
        let side = |last: usize| Chain {
            first: 0,
            len: last / ii + 1,
            slot: 0,
            src: Src::Side,
        };
        let mut issues: Vec<Vec<Vec<Option<Issue>>>> =
            s.units.iter().map(|&u| vec![vec![None; ii]; u]).collect();
        for n in g.g.node_indices() {
            let Op::Fp { class, sub } = g.g[n] else {
                continue;
            };
            let t = s.start[n.index()];
            let ops: Vec<Read> = g
                .operands(n)
                .into_iter()
                .map(|(p, o)| read(p, reader(n), t, o.abs, o.dbl))
                .collect();
            let sel = matches!(class, Class::Scale(Const::Ce | Const::Cz)).then_some(t / ii);
            issues[class.index()][s.unit[n.index()]][(t + 1) % ii] = Some(Issue {
                a: ops[0],
                b: ops.get(1).copied(),
                sub,
                sel,
            });
        }
        let outputs = g
            .outputs
            .map(|n| read(n, Reader::Outputs, s.out_at, false, false).reg);
        Plan {
            ii,
            binding,
            depth: s.depth,
            latency: s.latency(),
            units: s.units,
            words,
            exact: side(exact_last),
            valid: side(s.out_at),
            tag: side(s.out_at),
            issues,
            out_slot: (s.out_at + 1) % ii,
            outputs,
            side_out: s.out_at / ii,
        }
    }
}

#[cfg(test)]
mod tests {
    /// At every II the folds use (2 to 32) the plan reads only registers that exist, issues at most one
    /// operation per unit and counter value (a table of ii entries), and prints its size
    /// (docs/explanation/architecture.md, "Folded T.CHECK", has the table), under either
    /// binding and at either depth.
    #[test]
    fn tcheck_plans() {
        use crate::chip::rtl::Depth;
        let bindings = [super::Binding::Shared, super::Binding::PerReader];
        for (ii, binding, depth) in [1, 2, 4, 8, 16, 32]
            .into_iter()
            .flat_map(|ii| bindings.map(|b| (ii, b)))
            .flat_map(|(ii, b)| Depth::ALL.map(|d| (ii, b, d)))
        {
            let p = crate::fold::tcheck_plan(ii, binding, depth).unwrap();
            let n = p.word_regs();
            let reads = p
                .issues
                .iter()
                .flatten()
                .flatten()
                .flatten()
                .flat_map(|i| [Some(i.a), i.b])
                .flatten();
            assert!(
                reads.map(|r| r.reg).chain(p.outputs.all()).all(|r| r < n),
                "II {ii} {depth:?}"
            );
            assert!(p.issues.iter().flatten().all(|slots| slots.len() == ii));
            assert!(
                [p.exact, p.valid, p.tag].iter().all(|c| c.slot < ii)
                    && p.words.iter().all(|c| c.slot < ii && c.len > 0)
            );
            eprintln!(
                "II {ii} {binding:?} {depth:?}: units {:?}, latency {}, word registers {n}",
                p.units, p.latency
            );
        }
    }
}
