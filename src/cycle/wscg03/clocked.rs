//! WSCG'03's CollisionChip clocked register by register: the Stack Engine's sequencer
//! around its lists ([`ListStack`]), the Memory Controller ([`MemoryController`]: a node pair per
//! burst), the DOP Unit ([`ClockedDopUnit`]), the Triangle Unit's input stage
//! ([`ClockedTriInput`]) and TRI_UNIT ([`TriUnit`]), each
//! clock's decisions read from the state before its edge. It is the design the chip's RTL
//! is to follow; values come from the golden functions through the clocked units.
//!
//! The memory holds a node pair per record (the `records` layout, one level: an inner
//! node's two children in one record, the root alone in record 0), node words as the
//! memory image has them, and the chip knows a node by its id (`record << 1 | slot`): it
//! reads what it decides from the node words it fetched, as the RTL will, never the tree.
//! The sequencer, per list (level λ, branch b): the tumbled group G (B's root at level 1;
//! below, the children of the group one level up's member b, or that member itself if it is
//! a leaf) is in a d' set already, or is loaded into one; once G's words have streamed, the
//! children of G's left member are loaded speculatively into the other set. The list's
//! pointers are read one a clock and asked for as aligned DOPs against G's set; each one's
//! flags, with the aligned node's fields that streamed with its last bundle, turn into
//! actions (appends onto the next level's lists, leaf pairs for the Triangle Unit), one a
//! clock. The list is done when every pointer is read, compared and its actions done:
//! `next_list`.

use super::dop_unit::{ClockIn, ClockOut, ClockedDopUnit};
use super::memory_controller::{Ask, Fields, Images, McIn, MemoryController, NodeWord, Record};
use super::stack_engine::{ListCmd, ListOut, ListStack};
use super::tri_unit::{ClockedTriInput, LeafPair, TriInputIn, TriInputOut};
use crate::chip::config::MemLayout::Records;
use crate::chip::layout::{node_ids, node_records, tri_records};
use crate::cycle::memory::MemModel;
use crate::cycle::tri_unit::TriUnit;
use crate::dop::{DopTree, Node};
use crate::golden::memory::ObjectImage;
use std::collections::VecDeque;

/// What an aligned node's flags make the sequencer do, one a clock.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Action {
    Append(usize, u32),
    Leaf(LeafPair),
}

/// The Stack Engine's sequencer's registers.
struct Sequencer {
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
    /// Aligned nodes read and not yet flagged; the aligned bundles compared, in order, each
    /// with the fields of the node whose last bundle it is.
    inflight: usize,
    compared: VecDeque<Option<Fields>>,
    /// What the flags made the sequencer do, in order.
    actions: VecDeque<Action>,
    halted: bool,
}

impl Sequencer {
    /// The fields of set `s`'s group, once its load has streamed.
    fn fields(&self, s: usize) -> Option<&[Fields]> {
        let ids = self.loaded[s].iter().map(|m| m.id);
        ids.eq(self.holds[s].iter().copied())
            .then_some(&self.loaded[s][..])
    }

    /// The ask for a load of `ids` into set `s`.
    fn load(&mut self, s: usize, ids: Vec<u32>) -> Ask {
        let (id, n) = (ids[0], ids.len());
        self.holds[s] = ids;
        Ask::Load { set: s, id, n }
    }
}

/// The query's run: the trace in DATE'05's format, and the lists processed.
pub struct ClockedRun {
    pub trace: crate::cycle::drive::ChipTrace,
    pub lists: u64,
}

/// The chip's units and the sequencer's registers, with the units' outputs after the last
/// edge (`ls`, `dout`) and what the query did so far.
struct Chip<'a> {
    mem: MemModel,
    dop: ClockedDopUnit<'a>,
    lists: ListStack,
    tin: ClockedTriInput,
    tri: TriUnit<'a>,
    mc: MemoryController<'a>,
    sq: Sequencer,
    ls: ListOut,
    dout: ClockOut,
    first: bool,
    /// A's triangle cache's lines less one.
    mask: u8,
    out: crate::cycle::drive::ChipTrace,
    n_lists: u64,
    /// The Memory Controller's inputs, each clock, if asked for.
    mc_log: Option<Vec<McIn>>,
}

/// An object's node records in the `records` layout of one level (a node pair a record),
/// each node word's fields as the memory image holds them (the ids of
/// [`node_ids`], the triangle records of [`tri_records`]).
fn records(o: &ObjectImage) -> Vec<Record> {
    let t = &o.tree;
    let children: Vec<Option<[u32; 2]>> = t
        .nodes()
        .map(|n| match n {
            Node::Inner(c) => Some(c),
            Node::Leaf(_) => None,
        })
        .collect();
    let leaves: Vec<u32> = t
        .nodes()
        .filter_map(|n| match n {
            Node::Leaf(tri) => Some(tri),
            Node::Inner(_) => None,
        })
        .collect();
    let (rec, ids) = (
        node_records(Records, 1, &children),
        node_ids(Records, 1, &children),
    );
    let tris = tri_records(Records, &leaves);
    let mut out = vec![Record::default(); *rec.iter().max().unwrap() as usize + 1];
    for n in 0..t.len() as u32 {
        let (leaf, f) = match t.node(n) {
            Node::Inner([c0, c1]) => (false, [ids[c0 as usize], ids[c1 as usize]]),
            Node::Leaf(tri) => (true, [tri, tris[tri as usize]]),
        };
        let id = ids[n as usize];
        out[rec[n as usize] as usize][id as usize & 1] = NodeWord {
            dop: t.dop(n).to_vec(),
            fields: Fields { id, leaf, f },
        };
    }
    out
}

/// The memory of `chip`'s query: A's and B's node records, the regions' first words.
pub fn images(chip: &crate::query::Chip) -> Images {
    let (ra, rb) = (records(&chip.a), records(&chip.b));
    let (na, nb) = (ra.len() as u32, rb.len() as u32);
    Images {
        records: [ra, rb],
        bases: crate::chip::layout::image_bases(na, chip.a.tri_count() as u32, nb),
        k: chip.cfg.k,
    }
}

impl<'a> Chip<'a> {
    fn new(
        chip: &'a crate::query::Chip,
        img: &'a Images,
        setup: &'a crate::golden::host::HostSetup,
        first: bool,
        p: &crate::chip::params::Params,
    ) -> Result<Self, String> {
        let cfg = &chip.cfg;
        let layout = crate::chip::layout::Layout::new(&crate::chip::config::ChipConfig {
            layout: Records,
            dop_bits: crate::chip::config::DopBits::Full,
            ..*cfg
        });
        let values = crate::golden::tri_unit::TriUnit::new(
            cfg.format.tri,
            cfg.tri_rounding,
            setup,
            chip.a.tri_count(),
            chip.b.tri_count(),
        );
        let root = DopTree::ROOT;
        Ok(Chip {
            mem: MemModel::new(p.memory_clocks()?, layout.word_bits()),
            dop: ClockedDopUnit::new(cfg.format.dop, cfg.dop_rounding.op(), setup),
            lists: ListStack::new(crate::chip::rtl::LIST_SRAM_BITS),
            tin: ClockedTriInput::default(),
            tri: TriUnit::new(&chip.a, &chip.b, values, p)?,
            mc: MemoryController::new(img, p.outstanding as usize),
            // level 0 is the host's: the root's pointer onto level 1, then the next list
            sq: Sequencer {
                groups: vec![vec![]; crate::chip::rtl::LIST_LEVELS],
                entered: true,
                spec: false,
                cur: 0,
                holds: [vec![], vec![]],
                loaded: [vec![], vec![]],
                inflight: 0,
                compared: VecDeque::new(),
                actions: VecDeque::from([Action::Append(0, root)]),
                halted: false,
            },
            ls: ListOut::default(),
            dout: ClockOut::default(),
            first,
            mask: (cfg.tri_cache - 1) as u8,
            out: crate::cycle::drive::ChipTrace {
                results: vec![],
                cycles: 0,
                overflow: false,
                max_depth: 0,
                dop_tests: 0,
                tri_tests: 0,
                node_fetches: 0,
                tri_fetches: 0,
                memory: Default::default(),
            },
            n_lists: 0,
            mc_log: None,
        })
    }

    /// Nothing left to do (after a halt: nothing left in flight).
    fn finished(&self) -> bool {
        let sq = &self.sq;
        let idle = !self.tin.busy() && self.tri.open() == 0 && self.mc.outstanding() == 0;
        let asks = self.mc.room() < crate::chip::rtl::MC_ASKS;
        idle && (sq.halted || self.ls.done && sq.actions.is_empty() && !asks)
    }

    /// The Triangle Unit in clock `now`: a response from memory (`resp`: a triangle word
    /// for the input stage), the input stage (offered the leaf pair at the front of the
    /// actions), TRI_UNIT, the host reading its verdicts.
    fn triangles(&mut self, now: u64, resp: bool) -> (TriInputOut, bool) {
        let fill = self.mc.fill(resp);
        let leaf = match self.sq.actions.front() {
            Some(Action::Leaf(l)) if !self.sq.halted => Some(*l),
            _ => None,
        };
        let ready = self.tri.in_ready(now);
        let to = self.tin.step(&TriInputIn {
            clear: false,
            mask: self.mask,
            halt: self.sq.halted,
            leaf,
            fill,
            tri_ready: ready,
        });
        if to.pair_valid && ready {
            self.tri.take(now, to.pair_tag & 0xffff, to.pair_tag >> 16);
            self.out.tri_tests += 1;
        }
        if let Some(r) = self.tri.out(now) {
            if r.res.hit || r.res.uncertain {
                self.out.results.push((now, r.a, r.b, r.res.uncertain));
            }
            self.sq.halted |= self.first && r.sure_hit();
            self.tri.give(now);
        }
        (to, leaf.is_some())
    }

    /// The Memory Controller in clock `now`: the sequencer's ask, a request, a response,
    /// the bundle into the DOP Unit (a load's fields into the sequencer's register of its
    /// set).
    fn memory(&mut self, now: u64, to: &TriInputOut, resp: bool, push: Option<Ask>) -> ClockIn {
        let mem_ready = self.mem.ready(now);
        let i = McIn {
            halt: self.sq.halted,
            push,
            need: to.need,
            ids: to.ids,
            mem_ready,
            resp,
            busy: self.dout.busy,
        };
        if let Some(log) = &mut self.mc_log {
            log.push(i);
        }
        let o = self.mc.step(&i);
        if let Some(addr) = o.req.filter(|_| mem_ready) {
            self.mem.request(now, addr);
        }
        if o.dop_in.a.is_some() {
            self.sq.compared.push_back(o.aligned);
        }
        if let Some((set, members)) = o.loaded {
            self.sq.loaded[set] = members;
        }
        o.dop_in
    }

    /// An aligned DOP's flags into actions (one per member it overlaps); the current
    /// list's group's fields kept for its level.
    fn flags(&mut self) {
        let flagged = self.dout.flags_valid.then(|| self.sq.compared.pop_front());
        let Some(n) = flagged.and_then(|n| n.expect("flags without an aligned bundle")) else {
            return;
        };
        let sq = &mut self.sq;
        let g = sq
            .fields(sq.cur)
            .expect("flags before the set's load")
            .to_vec();
        self.out.dop_tests += g.len() as u64;
        for (side, &x) in g.iter().enumerate() {
            if self.dout.overlap[side] {
                sq.actions.extend(actions(n, x, side));
            }
        }
        sq.groups[self.ls.level] = g;
        sq.inflight -= 1;
    }

    /// Whether the sequencer is free to act on its lists (not stepping, done or halted).
    fn idle(&self) -> bool {
        !self.ls.busy && !self.ls.done && !self.sq.halted
    }

    /// The sequencer's ask to the Memory Controller this clock, with `room` free entries
    /// (one a clock): the aligned node read last clock; else, a list entered, its load;
    /// else the speculative load of the current group's left member's children.
    fn ask(&mut self, room: usize) -> Option<Ask> {
        let (sq, ls) = (&mut self.sq, &self.ls);
        if let Some(n) = ls.rd {
            return Some(Ask::Aligned {
                set: sq.cur,
                id: n as u32,
            });
        }
        let idle = !ls.busy && !ls.done && !sq.halted;
        if !idle || room == 0 {
            return None;
        }
        match (sq.entered, ls.level) {
            (true, _) => speculate(sq),
            (false, 0) => None,
            (false, level) => {
                self.n_lists += 1;
                enter(sq, level, ls.branch)
            }
        }
    }

    /// The sequencer's command to the lists this clock: an action (an append, or the leaf
    /// pair the input stage took, `offered` and `leaf_ready`), a read (three asks free
    /// before the edge: this clock's ask, the read's next clock, and one left for a list's
    /// load; two would do, but let reads crowd out the loads: teapot 1% more clocks), the
    /// next list.
    fn sequence(&mut self, offered: bool, leaf_ready: bool, room: usize) -> ListCmd {
        let idle = self.idle();
        let (sq, ls) = (&mut self.sq, &self.ls);
        let mut cmd = ListCmd::default();
        match sq.actions.front() {
            Some(Action::Append(s, p)) if idle => {
                cmd.append = Some((*s, *p as u16));
                sq.actions.pop_front();
            }
            // the leaf pair offered at the clock's start (not one these flags made)
            Some(Action::Leaf(_)) if offered && leaf_ready => {
                sq.actions.pop_front();
            }
            _ => {}
        }
        if idle && sq.entered {
            cmd.read = ls.remaining > 0 && room > 2 && sq.actions.len() < 4 && ls.level > 0;
            sq.inflight += cmd.read as usize;
            let done = ls.remaining == 0 && sq.inflight == 0 && sq.actions.is_empty();
            if done && cmd.append.is_none() {
                (cmd.next_list, sq.entered) = (true, false);
            }
        }
        cmd
    }

    /// One clock, then its edge.
    fn step(&mut self, now: u64) {
        let resp = self.mem.respond(now).is_some();
        let (to, offered) = self.triangles(now, resp);
        let room = self.mc.room();
        let push = self.ask(room);
        let dop_in = self.memory(now, &to, resp, push);
        self.flags();
        let cmd = self.sequence(offered, to.leaf_ready, room);
        self.ls = self.lists.step(&cmd);
        self.dout = self.dop.step(&dop_in);
    }
}

/// One query on WSCG'03's chip clocked register by register: `chip`'s trees, B placed by
/// `setup`, all pairs or the first hit (`first`), the memory and TRI_UNIT of `p`, at most
/// `max_cycles` clocks.
pub fn run(
    chip: &crate::query::Chip,
    setup: &crate::golden::host::HostSetup,
    first: bool,
    p: &crate::chip::params::Params,
    max_cycles: u64,
) -> Result<ClockedRun, String> {
    let img = images(chip);
    let mut c = Chip::new(chip, &img, setup, first, p)?;
    c.run(max_cycles)?;
    Ok(ClockedRun {
        trace: c.out,
        lists: c.n_lists,
    })
}

/// The Memory Controller's inputs in every clock of [`run`]'s query on the memory `img`
/// ([`images`] of `chip`): traffic for its RTL.
pub fn memory_controller_inputs(
    chip: &crate::query::Chip,
    img: &Images,
    setup: &crate::golden::host::HostSetup,
    first: bool,
    p: &crate::chip::params::Params,
    max_cycles: u64,
) -> Result<Vec<McIn>, String> {
    let mut c = Chip::new(chip, img, setup, first, p)?;
    c.mc_log = Some(vec![]);
    c.run(max_cycles)?;
    Ok(c.mc_log.unwrap_or_default())
}

impl Chip<'_> {
    /// Clocks until the query is finished, at most `max_cycles`.
    fn run(&mut self, max_cycles: u64) -> Result<(), String> {
        for now in 0..max_cycles {
            if self.finished() {
                let o = &mut self.out;
                (o.cycles, o.node_fetches) = (now, self.mc.node_fetches);
                (o.tri_fetches, o.memory) = (self.mc.tri_fetches, self.mem.counters);
                return Ok(());
            }
            self.step(now);
        }
        Err(crate::cycle::drive::not_finished(max_cycles))
    }
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

/// A list entered at `level`, `branch`: its group (B's root at level 1; below, the children
/// of member `branch` of the group one level up, or that member itself if it is a leaf: the
/// rule of [`expand`](super::stack_engine::expand), on node words), its set (held, or loaded
/// into the set the last list did not use: the ask).
fn enter(sq: &mut Sequencer, level: usize, branch: usize) -> Option<Ask> {
    let g = match level {
        1 => vec![DopTree::ROOT],
        _ => match sq.groups[level - 1][branch] {
            m if m.leaf => vec![m.id],
            m => m.f.to_vec(),
        },
    };
    (sq.entered, sq.spec) = (true, true);
    match (0..2).find(|&s| sq.holds[s] == g) {
        Some(s) => {
            sq.cur = s;
            None
        }
        None => {
            sq.cur = 1 - sq.cur;
            Some(sq.load(sq.cur, g))
        }
    }
}

/// Once the current group's fields are loaded: the ask for its left member's children into
/// the other set, unless it holds them (or the member is a leaf).
fn speculate(sq: &mut Sequencer) -> Option<Ask> {
    let &[m0, ..] = sq.fields(sq.cur)? else {
        return None;
    };
    if !sq.spec {
        return None;
    }
    sq.spec = false;
    let other = 1 - sq.cur;
    (!m0.leaf && sq.holds[other] != m0.f).then(|| sq.load(other, m0.f.to_vec()))
}
