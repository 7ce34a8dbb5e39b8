//! WSCG'03's Stack Engine's sequencer (§4.2) clocked register by register: around its lists
//! ([`ListStack`](super::stack_engine::ListStack)) it enters each list (its tumbled group in
//! a d' set, loaded if not held), asks the Memory Controller for the speculative load and
//! the list's aligned nodes, reads the pointers, turns the DOP Unit's flags into actions
//! (appends onto the next level's lists, leaf pairs for the Triangle Unit) and ends the
//! list. It decides from node words' fields ([`Fields`]), never the tree: an aligned node's
//! stream with its last bundle, a group's with its load's first. Every output reads the
//! state before the clock's edge and the clock's inputs; the unit the RTL is to follow.

use super::memory_controller::{Ask, Fields};
use super::stack_engine::{ListCmd, ListOut};
use super::tri_unit::LeafPair;
use crate::chip::rtl::{SEQ_ACTIONS, SEQ_READS, WSCG03_COMPARE_LATENCY as COMPARED};
use crate::dop::DopTree;
use std::collections::VecDeque;

/// What an aligned node's flags make the sequencer do, one a clock.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    Append(usize, u32),
    Leaf(LeafPair),
}

/// One clock's inputs: `halt` (first hit), the lists' outputs after the last edge, the DOP
/// Unit's flags after the last edge, the Memory Controller's free asks (after the last
/// edge) and this clock's outputs (`aligned`: an aligned bundle streamed, with its node's
/// fields if it is the last; `loaded`: a load's set and members' fields), the Triangle
/// Unit's input stage's `leaf_ready` this clock.
#[derive(Clone, Debug, Default)]
pub struct SeqIn {
    pub halt: bool,
    pub ls: ListOut,
    pub flags_valid: bool,
    pub overlap: [bool; 2],
    pub room: usize,
    pub aligned: Option<Option<Fields>>,
    pub loaded: Option<(usize, Vec<Fields>)>,
    pub leaf_ready: bool,
}

/// What a clock decides, from the state before its edge: the lists' command, the ask, the
/// list entered (its set, whether it is loaded), the speculation resolved, the front
/// action done.
#[derive(Default)]
struct Decision {
    cmd: ListCmd,
    push: Option<Ask>,
    enter: Option<usize>,
    spec_done: bool,
    taken: bool,
}

/// The Stack Engine's sequencer's registers.
pub struct Sequencer {
    /// The tumbled group per level, as its words' fields (those of the current list's
    /// level from its set's, once flags come).
    groups: Vec<Vec<Fields>>,
    /// The current list has its group (its set chosen, its load asked for); the speculative
    /// load of its left member's children is still to be asked for.
    entered: bool,
    spec: bool,
    cur: usize,
    /// The ids of the group each d' set holds or is being loaded with; the fields of the
    /// group last loaded into it (valid when their ids are `holds`').
    holds: [Vec<u32>; 2],
    loaded: [Vec<Fields>; 2],
    /// Aligned nodes read and not yet flagged (at most [`SEQ_READS`]); the aligned bundles
    /// compared, in order, each with the fields of the node whose last bundle it is (at most
    /// the DOP Unit's compare latency).
    inflight: usize,
    compared: VecDeque<Option<Fields>>,
    /// What the flags made the sequencer do, in order (at most [`SEQ_ACTIONS`]).
    actions: VecDeque<Action>,
    /// Lists entered; DOP tests (an aligned node against each member of its group).
    pub lists: u64,
    pub dop_tests: u64,
}

impl Sequencer {
    /// A query's sequencer with `levels` levels: level 0 is the host's, the root's pointer
    /// onto level 1, then the next list.
    pub fn new(levels: usize) -> Self {
        Sequencer {
            groups: vec![vec![]; levels],
            entered: true,
            spec: false,
            cur: 0,
            holds: [vec![], vec![]],
            loaded: [vec![], vec![]],
            inflight: 0,
            compared: VecDeque::new(),
            actions: VecDeque::from([Action::Append(0, DopTree::ROOT)]),
            lists: 0,
            dop_tests: 0,
        }
    }

    /// Nothing left to do.
    pub fn idle(&self) -> bool {
        self.actions.is_empty()
    }

    /// The leaf pair offered to the Triangle Unit's input stage this clock.
    pub fn offer(&self, halt: bool) -> Option<LeafPair> {
        match self.actions.front() {
            Some(Action::Leaf(l)) if !halt => Some(*l),
            _ => None,
        }
    }

    /// The ask to the Memory Controller this clock (`i`'s Memory Controller outputs unused).
    pub fn ask(&self, i: &SeqIn) -> Option<Ask> {
        self.decide(i).push
    }

    /// One clock: the lists' command, then the edge.
    pub fn step(&mut self, i: &SeqIn) -> ListCmd {
        let d = self.decide(i);
        self.flags(i);
        if d.taken {
            self.actions.pop_front();
        }
        if let Some(Ask::Load { set, id, n }) = d.push {
            self.holds[set] = (id..id + n as u32).collect();
        }
        if let Some(cur) = d.enter {
            (self.entered, self.spec, self.cur) = (true, true, cur);
            self.lists += 1;
        }
        self.spec &= !d.spec_done;
        self.entered &= !d.cmd.next_list;
        self.inflight += d.cmd.read as usize;
        if let Some(a) = i.aligned {
            self.compared.push_back(a);
        }
        if let Some((set, m)) = &i.loaded {
            self.loaded[*set] = m.clone();
        }
        assert!(self.actions.len() <= SEQ_ACTIONS && self.compared.len() <= COMPARED);
        d.cmd
    }

    /// The fields of set `s`'s group, once its load has streamed.
    fn fields(&self, s: usize) -> Option<&[Fields]> {
        let ids = self.loaded[s].iter().map(|m| m.id);
        ids.eq(self.holds[s].iter().copied())
            .then_some(&self.loaded[s][..])
    }

    fn decide(&self, i: &SeqIn) -> Decision {
        let ls = &i.ls;
        let idle = !ls.busy && !ls.done && !i.halt;
        let mut d = Decision::default();
        match self.actions.front() {
            Some(Action::Append(s, p)) if idle => {
                (d.cmd.append, d.taken) = (Some((*s, *p as u16)), true);
            }
            Some(Action::Leaf(_)) => d.taken = !i.halt && i.leaf_ready,
            _ => {}
        }
        if let Some(n) = ls.rd {
            d.push = Some(Ask::Aligned {
                set: self.cur,
                id: n as u32,
            });
        } else if idle && i.room > 0 && !self.entered && ls.level > 0 {
            self.enter(&mut d, ls.level, ls.branch);
        } else if idle && i.room > 0 && self.entered {
            self.speculate(&mut d);
        }
        if idle && self.entered {
            let room = i.room > 2 && self.inflight < SEQ_READS;
            d.cmd.read = ls.remaining > 0 && room && self.actions.len() < 4 && ls.level > 0;
            let done = ls.remaining == 0 && self.inflight == 0 && self.actions.is_empty();
            d.cmd.next_list = done;
        }
        d
    }

    /// A list entered at `level`, `branch`: its group (B's root at level 1; below, the
    /// children of member `branch` of the group one level up, or that member itself if it is
    /// a leaf: the rule of [`expand`](super::stack_engine::expand), on node words), its set
    /// (held, or loaded into the set the last list did not use: the ask).
    fn enter(&self, d: &mut Decision, level: usize, branch: usize) {
        let g = match level {
            1 => vec![DopTree::ROOT],
            _ => match self.groups[level - 1][branch] {
                m if m.leaf => vec![m.id],
                m => pair(m.f[0]),
            },
        };
        match (0..2).find(|&s| self.holds[s] == g) {
            Some(s) => d.enter = Some(s),
            None => {
                let set = 1 - self.cur;
                d.enter = Some(set);
                let (id, n) = (g[0], g.len());
                d.push = Some(Ask::Load { set, id, n });
            }
        }
    }

    /// Once the current group's fields are loaded: the ask for its left member's children
    /// into the other set, unless it holds them (or the member is a leaf).
    fn speculate(&self, d: &mut Decision) {
        let Some(&[m0, ..]) = self.fields(self.cur).filter(|_| self.spec) else {
            return;
        };
        d.spec_done = true;
        let set = 1 - self.cur;
        if !m0.leaf && self.holds[set] != pair(m0.f[0]) {
            d.push = Some(Ask::Load {
                set,
                id: m0.f[0],
                n: 2,
            });
        }
    }

    /// An aligned DOP's flags (`i`, the DOP Unit's after the last edge) into actions, one per
    /// member it overlaps; the current list's group's fields kept for its level.
    fn flags(&mut self, i: &SeqIn) {
        if !i.flags_valid {
            return;
        }
        let c = self.compared.pop_front();
        let Some(n) = c.expect("flags without an aligned bundle") else {
            return;
        };
        let g = self
            .fields(self.cur)
            .expect("flags before the set's load")
            .to_vec();
        self.dop_tests += g.len() as u64;
        for (side, &x) in g.iter().enumerate() {
            if i.overlap[side] {
                self.actions.extend(actions(n, x, side));
            }
        }
        self.groups[i.ls.level] = g;
        self.inflight -= 1;
    }
}

/// A sibling pair's ids from the first's: a record's two slots (the RTL keeps the first).
fn pair(id: u32) -> Vec<u32> {
    vec![id, id + 1]
}

/// What an overlap of aligned node `n` with the tumbled member `x` (on side `side`) does,
/// from their words' fields: a leaf pair (A's and B's triangle records, the triangles as its
/// tag), or the appends onto x's new list: n's children, or n itself (a leaf against an inner
/// node). The rule of [`appended`](super::stack_engine::appended), on node words.
fn actions(n: Fields, x: Fields, side: usize) -> Vec<Action> {
    match (n.leaf, x.leaf) {
        (true, true) => vec![Action::Leaf(LeafPair {
            ids: [n.f[1] as u16, x.f[1] as u16],
            tag: n.f[0] | x.f[0] << 16,
            side,
        })],
        (false, _) => n.f.iter().map(|&c| Action::Append(side, c)).collect(),
        (true, false) => vec![Action::Append(side, n.id)],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first lists, clock by clock (hand-derived): the root's pointer appended, the
    /// host's list done, level 1 entered with the root loaded into set 1, its pointer read
    /// and asked for, then (its fields loaded) its children speculated into set 0.
    #[test]
    fn enters_the_root_list_and_speculates_its_children() {
        let mut sq = Sequencer::new(4);
        let mut i = SeqIn {
            room: 8,
            ..SeqIn::default()
        };
        assert_eq!(sq.step(&i).append, Some((0, DopTree::ROOT as u16)));
        assert!(
            sq.step(&i).next_list,
            "the host's list is done once its append is"
        );
        i.ls = ListOut {
            level: 1,
            remaining: 1,
            ..ListOut::default()
        };
        let root = Ask::Load {
            set: 1,
            id: 0,
            n: 1,
        };
        assert_eq!(sq.ask(&i), Some(root));
        assert!(!sq.step(&i).read, "no read before the list is entered");
        let fields = Fields {
            id: 0,
            leaf: false,
            f: [2, 3],
        };
        i.loaded = Some((1, vec![fields]));
        assert_eq!(sq.ask(&i), None, "the root's fields come at this edge");
        assert!(sq.step(&i).read);
        (i.loaded, i.ls.remaining, i.ls.rd) = (None, 0, Some(0));
        assert_eq!(sq.ask(&i), Some(Ask::Aligned { set: 1, id: 0 }));
        sq.step(&i);
        i.ls.rd = None;
        assert_eq!(
            sq.ask(&i),
            Some(Ask::Load {
                set: 0,
                id: 2,
                n: 2
            })
        );
        assert_eq!(
            sq.step(&i),
            ListCmd::default(),
            "the list waits for its flags"
        );
    }
}
