//! WSCG'03's CollisionChip clocked register by register: the Stack Engine's sequencer
//! around its lists ([`ListStack`]), the Memory Controller ([`Controller`]: a node pair per
//! burst), the DOP Unit ([`ClockedDopUnit`]), the Triangle Unit's input stage
//! ([`ClockedTriInput`]) and TRI_UNIT ([`TriUnit`]), each
//! clock's decisions read from the state before its edge. It is the design the chip's RTL
//! is to follow; values come from the golden functions through the clocked units.
//!
//! The memory holds a node pair per record (the `records` layout, one level: an inner
//! node's two children in one record, the root alone in record 0). The sequencer, per list
//! (level λ, branch b): the tumbled group G (B's root at level 1; below, the children of the
//! group one level up's member b, or that member itself if it is a leaf) is in a d' set
//! already, or is loaded into one; then the children of G's left member are loaded
//! speculatively into the other set. The list's pointers are read one a clock and asked for
//! as aligned DOPs against G's set; each one's flags turn into actions (appends onto the
//! next level's lists, leaf pairs for the Triangle Unit), one a clock. The list is done when
//! every pointer is read, compared and its actions done: `next_list`.

use super::dop_unit::{AlignedBundle, ClockIn, ClockOut, ClockedDopUnit, TumbledBundle};
use super::stack_engine::{appended, expand, ListCmd, ListOut, ListStack};
use super::tri_unit::{ClockedTriInput, LeafPair, TriInputIn, TriInputOut};
use crate::chip::layout::Dst;
use crate::cycle::memory::MemModel;
use crate::cycle::tri_unit::TriUnit;
use crate::dop::{DopTree, Node};
use crate::golden::memory::ObjectImage;
use std::collections::VecDeque;

use crate::chip::rtl::{MC_ASKS, MC_RECORDS};

/// What the Memory Controller is asked for, in order.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Ask {
    /// A tumbled group's DOPs (a sibling pair, or a leaf alone) into d' set `set`.
    Load { set: usize, group: Vec<u32> },
    /// An aligned node against d' set `set`.
    Aligned { set: usize, node: u32 },
}

/// An ask and its record: `Some(address)` fetched, `None` the one streamed before it (a
/// sibling of the aligned node before); whether it was requested.
#[derive(Clone, Debug)]
struct Entry {
    ask: Ask,
    addr: Option<u32>,
    requested: bool,
}

/// WSCG'03's Memory Controller (§4.4): the ask list, requests to memory (A's and B's
/// triangle words first, for the Triangle Unit), the node records arrived, and the stream of
/// the head ask's DOPs into the DOP Unit, a 256-bit bundle a clock.
pub struct Controller {
    asks: VecDeque<Entry>,
    /// Destinations and word ids of the requests outstanding, oldest first.
    tags: VecDeque<(Dst, u32)>,
    /// Node records arrived and not streamed; node records asked for and not arrived.
    records: usize,
    node_inflight: usize,
    /// Bundles of the head ask streamed.
    beat: usize,
    /// The last aligned record asked for (a sibling shares it).
    last_aligned: Option<u32>,
    max_outstanding: usize,
    pub node_fetches: u64,
    pub tri_fetches: u64,
}

/// Trees, records and bases the chip reads.
struct Images<'a> {
    a: &'a ObjectImage,
    b: &'a ObjectImage,
    rec: [Vec<u32>; 2],
    bases: [u32; 4],
    k: usize,
}

impl Images<'_> {
    fn record(&self, d: Dst, node: u32) -> u32 {
        self.bases[d as usize] + self.rec[(d == Dst::NodeB) as usize][node as usize]
    }

    fn dop(&self, b: bool, node: u32) -> Vec<f64> {
        let t = if b { &self.b.tree } else { &self.a.tree };
        t.dop(node).to_vec()
    }
}

/// Bundles of eight distances a DOP takes on the 256-bit bus.
fn beats(k: usize) -> usize {
    k.div_ceil(8)
}

fn bundle(d: &[f64], entry: usize) -> [f64; 8] {
    std::array::from_fn(|t| d.get(8 * entry + t).copied().unwrap_or(0.0))
}

impl Controller {
    fn new(max_outstanding: usize) -> Self {
        Controller {
            asks: VecDeque::new(),
            tags: VecDeque::new(),
            records: 0,
            node_inflight: 0,
            beat: 0,
            last_aligned: None,
            max_outstanding,
            node_fetches: 0,
            tri_fetches: 0,
        }
    }

    fn room(&self) -> usize {
        MC_ASKS - self.asks.len()
    }

    fn push(&mut self, ask: Ask, img: &Images) {
        let addr = match &ask {
            Ask::Load { group, .. } => Some(img.record(Dst::NodeB, group[0])),
            Ask::Aligned { node, .. } => {
                let r = img.record(Dst::NodeA, *node);
                let new = self.last_aligned != Some(r);
                self.last_aligned = Some(r);
                new.then_some(r)
            }
        };
        if matches!(ask, Ask::Load { .. }) {
            self.last_aligned = None;
        }
        self.asks.push_back(Entry {
            ask,
            addr,
            requested: addr.is_none(),
        });
    }

    /// The request this clock, if the memory takes one: a triangle word the input stage
    /// lacks (`need`, ids; not one arriving now, `fill`), else the first node record not
    /// requested that has room.
    fn request(
        &self,
        need: [bool; 2],
        ids: [u16; 2],
        fill: Option<(bool, u16)>,
        bases: &[u32; 4],
    ) -> Option<(Dst, u32, u32)> {
        if self.tags.len() >= self.max_outstanding {
            return None;
        }
        for (d, dst) in [(0, Dst::TriA), (1, Dst::TriB)] {
            let arriving = fill.is_some_and(|f| f.0 == (d == 1));
            if need[d] && !arriving && !self.tags.iter().any(|t| t.0 == dst) {
                let id = ids[d] as u32;
                return Some((dst, id, bases[dst as usize] + id));
            }
        }
        let e = self.asks.iter().find(|e| !e.requested)?;
        let dst = match e.ask {
            Ask::Load { .. } => Dst::NodeB,
            Ask::Aligned { .. } => Dst::NodeA,
        };
        (self.records + self.node_inflight < MC_RECORDS).then(|| (dst, 0, e.addr.unwrap()))
    }

    fn accept(&mut self, dst: Dst, id: u32) {
        self.tags.push_back((dst, id));
        if dst.is_tri() {
            self.tri_fetches += 1;
        } else {
            self.node_inflight += 1;
            self.node_fetches += 1;
            self.asks
                .iter_mut()
                .find(|e| !e.requested)
                .unwrap()
                .requested = true;
        }
    }

    /// A response: a triangle word for the input stage (B's?, id), or a node record.
    fn respond(&mut self) -> Option<(bool, u16)> {
        let (dst, id) = self.tags.pop_front().expect("a response without a request");
        match dst {
            Dst::TriA | Dst::TriB => Some((dst == Dst::TriB, id as u16)),
            _ => {
                (self.records, self.node_inflight) = (self.records + 1, self.node_inflight - 1);
                None
            }
        }
    }

    /// This clock's bundle from the head ask, given the sets' `busy` after the last edge:
    /// the DOP Unit's inputs, and the aligned node whose last bundle this is.
    fn stream(&self, busy: [bool; 2], img: &Images) -> Option<(ClockIn, Option<u32>)> {
        let e = self.asks.front()?;
        let bs = beats(img.k);
        if self.beat == 0 && (e.addr.is_some() && self.records == 0) {
            return None;
        }
        let set = match e.ask {
            Ask::Load { set, .. } | Ask::Aligned { set, .. } => set,
        };
        if self.beat == 0 && busy[set] {
            return None;
        }
        Some(match &e.ask {
            Ask::Load { group, .. } => {
                let (side, entry) = (self.beat / bs, self.beat % bs);
                let t = TumbledBundle {
                    set,
                    side,
                    entry,
                    last: self.beat + 1 == group.len() * bs,
                    data: bundle(&img.dop(true, group[side]), entry),
                };
                (
                    ClockIn {
                        t: Some(t),
                        a: None,
                    },
                    None,
                )
            }
            &Ask::Aligned { node, .. } => {
                let lanes = (img.k - 8 * self.beat).min(8);
                let a = AlignedBundle {
                    set,
                    entry: self.beat,
                    first: self.beat == 0,
                    lanes: ((1u16 << lanes) - 1) as u8,
                    e: bundle(&img.dop(false, node), self.beat),
                };
                let last = (self.beat + 1 == bs).then_some(node);
                (
                    ClockIn {
                        t: None,
                        a: Some(a),
                    },
                    last,
                )
            }
        })
    }

    /// The edge after a bundle streamed.
    fn streamed(&mut self, k: usize) {
        let e = self.asks.front().unwrap();
        if self.beat == 0 && e.addr.is_some() {
            self.records -= 1;
        }
        let n = match &e.ask {
            Ask::Load { group, .. } => group.len(),
            Ask::Aligned { .. } => 1,
        };
        self.beat += 1;
        if self.beat == n * beats(k) {
            self.beat = 0;
            self.asks.pop_front();
        }
    }
}

/// What an aligned node's flags make the sequencer do, one a clock.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Action {
    Append(usize, u32),
    Leaf(LeafPair),
}

/// The Stack Engine's sequencer's registers.
struct Sequencer {
    /// The tumbled group per level.
    groups: Vec<Vec<u32>>,
    /// The current list has its group (its set chosen, loads asked for).
    entered: bool,
    cur: usize,
    /// The group each d' set holds or is being loaded with.
    holds: [Option<Vec<u32>>; 2],
    /// Aligned nodes read and not yet flagged; the aligned bundles compared, in order, each
    /// the node whose last bundle it is.
    inflight: usize,
    compared: VecDeque<Option<u32>>,
    /// What the flags made the sequencer do, in order.
    actions: VecDeque<Action>,
    halted: bool,
}

/// The query's run: the trace in DATE'05's format, and the lists processed.
pub struct ClockedRun {
    pub trace: crate::cycle::drive::ChipTrace,
    pub lists: u64,
}

/// The chip's units and the sequencer's registers, with the units' outputs after the last
/// edge (`ls`, `dout`) and what the query did so far.
struct Chip<'a> {
    img: Images<'a>,
    mem: MemModel,
    dop: ClockedDopUnit<'a>,
    lists: ListStack,
    tin: ClockedTriInput,
    tri: TriUnit<'a>,
    mc: Controller,
    sq: Sequencer,
    ls: ListOut,
    dout: ClockOut,
    first: bool,
    /// A's triangle cache's lines less one.
    mask: u8,
    out: crate::cycle::drive::ChipTrace,
    n_lists: u64,
}

/// Each node's record in the `records` layout of one level (a node pair a record).
fn records(t: &DopTree) -> Vec<u32> {
    let ch: Vec<Option<[u32; 2]>> = t
        .nodes()
        .map(|n| match n {
            Node::Inner(c) => Some(c),
            Node::Leaf(_) => None,
        })
        .collect();
    crate::chip::layout::node_records(crate::chip::config::MemLayout::Records, 1, &ch)
}

impl<'a> Chip<'a> {
    fn new(
        chip: &'a crate::query::Chip,
        setup: &'a crate::golden::host::HostSetup,
        first: bool,
        p: &crate::chip::params::Params,
    ) -> Result<Self, String> {
        let cfg = &chip.cfg;
        let layout = crate::chip::layout::Layout::new(&crate::chip::config::ChipConfig {
            layout: crate::chip::config::MemLayout::Records,
            dop_bits: crate::chip::config::DopBits::Full,
            ..*cfg
        });
        let (ra, rb) = (records(&chip.a.tree), records(&chip.b.tree));
        let count = |r: &[u32]| r.iter().max().unwrap() + 1;
        let bases =
            crate::chip::layout::image_bases(count(&ra), chip.a.tri_count() as u32, count(&rb));
        let values = crate::golden::tri_unit::TriUnit::new(
            cfg.format.tri,
            cfg.tri_rounding,
            setup,
            chip.a.tri_count(),
            chip.b.tri_count(),
        );
        let root = DopTree::ROOT;
        Ok(Chip {
            img: Images {
                a: &chip.a,
                b: &chip.b,
                rec: [ra, rb],
                bases,
                k: cfg.k,
            },
            mem: MemModel::new(p.memory_clocks()?, layout.word_bits()),
            dop: ClockedDopUnit::new(cfg.format.dop, cfg.dop_rounding.op(), setup),
            lists: ListStack::new(crate::chip::rtl::LIST_SRAM_BITS),
            tin: ClockedTriInput::default(),
            tri: TriUnit::new(&chip.a, &chip.b, values, p)?,
            mc: Controller::new(p.outstanding as usize),
            // level 0 is the host's: the root's pointer onto level 1, then the next list
            sq: Sequencer {
                groups: vec![vec![root]; crate::chip::rtl::LIST_LEVELS],
                entered: true,
                cur: 0,
                holds: [None, None],
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
        })
    }

    /// Nothing left to do (after a halt: nothing left in flight).
    fn finished(&self) -> bool {
        let (sq, mc) = (&self.sq, &self.mc);
        let idle = !self.tin.busy() && self.tri.open() == 0 && mc.tags.is_empty();
        idle && (sq.halted || self.ls.done && sq.actions.is_empty() && mc.asks.is_empty())
    }

    /// The Triangle Unit in clock `now`: a response from memory, the input stage (offered
    /// the leaf pair at the front of the actions), TRI_UNIT, the host reading its verdicts.
    fn triangles(&mut self, now: u64) -> (TriInputOut, Option<(bool, u16)>, bool) {
        let fill = self.mem.respond(now).and_then(|_| self.mc.respond());
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
        (to, fill, leaf.is_some())
    }

    /// The Memory Controller in clock `now`: a request, the bundle into the DOP Unit.
    fn memory(&mut self, now: u64, to: &TriInputOut, fill: Option<(bool, u16)>) -> ClockIn {
        if self.mem.ready(now) {
            if let Some((dst, id, addr)) = self.mc.request(to.need, to.ids, fill, &self.img.bases) {
                self.mem.request(now, addr);
                self.mc.accept(dst, id);
            }
        }
        let streamed = (!self.sq.halted)
            .then(|| self.mc.stream(self.dout.busy, &self.img))
            .flatten();
        let Some((dop_in, last)) = streamed else {
            return ClockIn::default();
        };
        self.mc.streamed(self.img.k);
        if dop_in.a.is_some() {
            self.sq.compared.push_back(last);
        }
        dop_in
    }

    /// An aligned DOP's flags into actions (one per member it overlaps).
    fn flags(&mut self) {
        let flagged = self.dout.flags_valid.then(|| self.sq.compared.pop_front());
        let Some(n) = flagged.and_then(|n| n.expect("flags without an aligned bundle")) else {
            return;
        };
        let (a, b) = (&self.img.a.tree, &self.img.b.tree);
        let g = &self.sq.groups[self.ls.level];
        self.out.dop_tests += g.len() as u64;
        for (side, &x) in g.iter().enumerate() {
            if self.dout.overlap[side] {
                self.sq.actions.extend(actions(a, b, n, x, side));
            }
        }
        self.sq.inflight -= 1;
    }

    /// The sequencer's command to the lists this clock: an action (an append, or the leaf
    /// pair the input stage took, `offered` and `leaf_ready`), a read, the next list; a list
    /// entered.
    fn sequence(&mut self, offered: bool, leaf_ready: bool) -> ListCmd {
        let (sq, ls) = (&mut self.sq, &self.ls);
        let mut cmd = ListCmd::default();
        let idle = !ls.busy && !ls.done && !sq.halted;
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
        if let Some(n) = ls.rd {
            let (set, node) = (sq.cur, n as u32);
            self.mc.push(Ask::Aligned { set, node }, &self.img);
        }
        if idle && sq.entered {
            let room = self.mc.room() > 1 + ls.rd.is_some() as usize;
            cmd.read = ls.remaining > 0 && room && sq.actions.len() < 4 && ls.level > 0;
            sq.inflight += cmd.read as usize;
            let done = ls.remaining == 0 && sq.inflight == 0 && sq.actions.is_empty();
            if done && cmd.append.is_none() {
                (cmd.next_list, sq.entered) = (true, false);
            }
        } else if idle && !sq.entered && ls.level > 0 && self.mc.room() >= 2 {
            enter(sq, &mut self.mc, &self.img, ls.level, ls.branch);
            self.n_lists += 1;
        }
        cmd
    }

    /// One clock, then its edge.
    fn step(&mut self, now: u64) {
        let (to, fill, offered) = self.triangles(now);
        let dop_in = self.memory(now, &to, fill);
        self.flags();
        let cmd = self.sequence(offered, to.leaf_ready);
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
    let mut c = Chip::new(chip, setup, first, p)?;
    for now in 0..max_cycles {
        if c.finished() {
            let o = &mut c.out;
            (o.cycles, o.node_fetches, o.tri_fetches) = (now, c.mc.node_fetches, c.mc.tri_fetches);
            o.memory = c.mem.counters;
            return Ok(ClockedRun {
                trace: c.out,
                lists: c.n_lists,
            });
        }
        c.step(now);
    }
    Err(crate::cycle::drive::not_finished(max_cycles))
}

/// What an overlap of aligned node `n` with the tumbled member `x` (on side `side`) does:
/// the appends onto x's new list, or a leaf pair.
fn actions(a: &DopTree, b: &DopTree, n: u32, x: u32, side: usize) -> Vec<Action> {
    match (a.node(n), b.node(x)) {
        (Node::Leaf(ta), Node::Leaf(tb)) => vec![Action::Leaf(LeafPair {
            ids: [ta as u16, tb as u16],
            tag: ta | tb << 16,
            side,
        })],
        _ => appended(a, b, n, x)
            .into_iter()
            .map(|p| Action::Append(side, p))
            .collect(),
    }
}

/// A list entered at `level`, `branch`: its group, its set (held, or loaded into the set
/// the last list did not use), the speculative load of its left member's children.
fn enter(sq: &mut Sequencer, mc: &mut Controller, img: &Images, level: usize, branch: usize) {
    let b = &img.b.tree;
    let g = match level {
        1 => vec![DopTree::ROOT],
        _ => expand(b, sq.groups[level - 1][branch]),
    };
    sq.groups[level] = g.clone();
    sq.entered = true;
    match (0..2).find(|&s| sq.holds[s].as_ref() == Some(&g)) {
        Some(s) => sq.cur = s,
        None => {
            sq.cur = 1 - sq.cur;
            sq.holds[sq.cur] = Some(g.clone());
            mc.push(
                Ask::Load {
                    set: sq.cur,
                    group: g.clone(),
                },
                img,
            );
        }
    }
    if let Node::Inner(_) = b.node(g[0]) {
        let s = expand(b, g[0]);
        let other = 1 - sq.cur;
        if sq.holds[other].as_ref() != Some(&s) {
            sq.holds[other] = Some(s.clone());
            mc.push(
                Ask::Load {
                    set: other,
                    group: s,
                },
                img,
            );
        }
    }
}
