//! WSCG'03's CollisionChip clocked register by register: the Stack Engine's sequencer
//! around its lists ([`ListStack`]), the Memory Controller ([`Controller`]: a node pair per
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

use super::dop_unit::{AlignedBundle, ClockIn, ClockOut, ClockedDopUnit, TumbledBundle};
use super::stack_engine::{ListCmd, ListOut, ListStack};
use super::tri_unit::{ClockedTriInput, LeafPair, TriInputIn, TriInputOut};
use crate::chip::config::MemLayout::Records;
use crate::chip::layout::{node_ids, node_records, tri_records, Dst};
use crate::cycle::memory::MemModel;
use crate::cycle::tri_unit::TriUnit;
use crate::dop::{DopTree, Node};
use crate::golden::memory::ObjectImage;
use std::collections::VecDeque;

use crate::chip::rtl::{MC_ASKS, MC_RECORDS};

/// A node word as the chip reads it from its record (the memory image's node word, decoded):
/// its distances and its fields.
#[derive(Clone, Debug, Default)]
struct NodeWord {
    dop: Vec<f64>,
    fields: Fields,
}

/// What the sequencer keeps of a node word: the node's id (`record << 1 | slot`), the leaf
/// bit and the two 32-bit fields: an inner node's children's ids, or a leaf's triangle and
/// its triangle's record.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Fields {
    id: u32,
    leaf: bool,
    f: [u32; 2],
}

/// A record: a node pair's words in slots 0 and 1 (the root alone in slot 0 of record 0).
type Record = [NodeWord; 2];

/// What the Memory Controller is asked for, in order.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Ask {
    /// A tumbled group's DOPs into d' set `set`: the `n` nodes from id `id` (a sibling pair
    /// in slots 0 and 1 of a record, or a node alone).
    Load { set: usize, id: u32, n: usize },
    /// The aligned node `id` against d' set `set`.
    Aligned { set: usize, id: u32 },
}

/// An ask and its record: `Some(address)` fetched, `None` the one streamed before it (a
/// sibling of the aligned node before); whether it was requested.
#[derive(Clone, Debug)]
struct Entry {
    ask: Ask,
    addr: Option<u32>,
    requested: bool,
}

/// What the head ask's bundle gives besides the DOP Unit's inputs: an aligned node's fields
/// with its last bundle (for the sequencer when its flags come), a load's d' set and its
/// members' fields with its first bundle.
#[derive(Default)]
struct Streamed {
    dop_in: ClockIn,
    aligned: Option<Fields>,
    loaded: Option<(usize, Vec<Fields>)>,
}

/// WSCG'03's Memory Controller (§4.4): the ask list, requests to memory (A's and B's
/// triangle words first, for the Triangle Unit), the node records arrived (`held`) and the
/// one streamed (`cur`), and the stream of the head ask's DOPs into the DOP Unit, a 256-bit
/// bundle a clock.
pub struct Controller {
    asks: VecDeque<Entry>,
    /// Destinations and record numbers of the requests outstanding, oldest first.
    tags: VecDeque<(Dst, u32)>,
    /// Node records arrived and not streamed; the one being streamed; node records asked
    /// for and not arrived.
    held: VecDeque<Record>,
    cur: Record,
    node_inflight: usize,
    /// Bundles of the head ask streamed.
    beat: usize,
    /// The last aligned record asked for (a sibling shares it).
    last_aligned: Option<u32>,
    max_outstanding: usize,
    pub node_fetches: u64,
    pub tri_fetches: u64,
}

/// The memory the chip reads: A's and B's node records, the regions' first words, k.
struct Images {
    records: [Vec<Record>; 2],
    bases: [u32; 4],
    k: usize,
}

impl Images {
    fn addr(&self, d: Dst, record: u32) -> u32 {
        self.bases[d as usize] + record
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
            held: VecDeque::new(),
            cur: Default::default(),
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
        assert!(self.asks.len() < MC_ASKS, "the ask list overflows");
        let addr = match ask {
            Ask::Load { id, .. } => {
                self.last_aligned = None;
                Some(img.addr(Dst::NodeB, id >> 1))
            }
            Ask::Aligned { id, .. } => {
                let r = img.addr(Dst::NodeA, id >> 1);
                let new = self.last_aligned != Some(r);
                self.last_aligned = Some(r);
                new.then_some(r)
            }
        };
        self.asks.push_back(Entry {
            ask,
            addr,
            requested: addr.is_none(),
        });
    }

    /// The request this clock, if the memory takes one: a triangle word the input stage
    /// lacks (`need`, records `ids`; not one arriving now, `fill`), else the first node
    /// record not requested that has room. With its destination and record number.
    fn request(
        &self,
        need: [bool; 2],
        ids: [u16; 2],
        fill: Option<(bool, u16)>,
        img: &Images,
    ) -> Option<(Dst, u32, u32)> {
        if self.tags.len() >= self.max_outstanding {
            return None;
        }
        for (d, dst) in [(0, Dst::TriA), (1, Dst::TriB)] {
            let arriving = fill.is_some_and(|f| f.0 == (d == 1));
            if need[d] && !arriving && !self.tags.iter().any(|t| t.0 == dst) {
                let id = ids[d] as u32;
                return Some((dst, id, img.addr(dst, id)));
            }
        }
        let e = self.asks.iter().find(|e| !e.requested)?;
        let (dst, id) = match e.ask {
            Ask::Load { id, .. } => (Dst::NodeB, id),
            Ask::Aligned { id, .. } => (Dst::NodeA, id),
        };
        let room = self.held.len() + self.node_inflight < MC_RECORDS;
        room.then(|| (dst, id >> 1, e.addr.unwrap()))
    }

    fn accept(&mut self, dst: Dst, record: u32) {
        self.tags.push_back((dst, record));
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

    /// A response: a triangle word for the input stage (B's?, record), or a node record
    /// into `held`.
    fn respond(&mut self, img: &Images) -> Option<(bool, u16)> {
        let (dst, r) = self.tags.pop_front().expect("a response without a request");
        match dst {
            Dst::TriA | Dst::TriB => Some((dst == Dst::TriB, r as u16)),
            _ => {
                let rec = &img.records[(dst == Dst::NodeB) as usize][r as usize];
                self.held.push_back(rec.clone());
                self.node_inflight -= 1;
                None
            }
        }
    }

    /// The record the head ask reads this clock: the first one held as its first bundle
    /// streams, if it fetched one; else the one it streams.
    fn record(&self) -> Option<&Record> {
        let fetched = self.asks.front()?.addr.is_some();
        match self.beat == 0 && fetched {
            true => self.held.front(),
            false => Some(&self.cur),
        }
    }

    /// This clock's bundle from the head ask, given the sets' `busy` after the last edge.
    fn stream(&self, busy: [bool; 2], k: usize) -> Option<Streamed> {
        let (e, rec) = (self.asks.front()?, self.record()?);
        let (bs, beat) = (beats(k), self.beat);
        let set = match e.ask {
            Ask::Load { set, .. } | Ask::Aligned { set, .. } => set,
        };
        if beat == 0 && busy[set] {
            return None;
        }
        let slot = |id: u32| &rec[id as usize & 1];
        Some(match e.ask {
            Ask::Load { id, n, .. } => {
                let (side, entry) = (beat / bs, beat % bs);
                let t = TumbledBundle {
                    set,
                    side,
                    entry,
                    last: beat + 1 == n * bs,
                    data: bundle(&slot(id + side as u32).dop, entry),
                };
                let members = (0..n as u32).map(|m| slot(id + m).fields).collect();
                Streamed {
                    dop_in: ClockIn {
                        t: Some(t),
                        a: None,
                    },
                    aligned: None,
                    loaded: (beat == 0).then_some((set, members)),
                }
            }
            Ask::Aligned { id, .. } => {
                let lanes = (k - 8 * beat).min(8);
                let a = AlignedBundle {
                    set,
                    entry: beat,
                    first: beat == 0,
                    lanes: ((1u16 << lanes) - 1) as u8,
                    e: bundle(&slot(id).dop, beat),
                };
                Streamed {
                    dop_in: ClockIn {
                        t: None,
                        a: Some(a),
                    },
                    aligned: (beat + 1 == bs).then_some(slot(id).fields),
                    loaded: None,
                }
            }
        })
    }

    /// The edge after a bundle streamed.
    fn streamed(&mut self, k: usize) {
        let e = self.asks.front().unwrap();
        if self.beat == 0 && e.addr.is_some() {
            self.cur = self.held.pop_front().unwrap();
        }
        let n = match e.ask {
            Ask::Load { n, .. } => n,
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

    /// Asks for a load of `ids` into set `s`.
    fn load(&mut self, s: usize, ids: Vec<u32>, mc: &mut Controller, img: &Images) {
        let (id, n) = (ids[0], ids.len());
        self.holds[s] = ids;
        mc.push(Ask::Load { set: s, id, n }, img);
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
    img: Images,
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

impl<'a> Chip<'a> {
    fn new(
        chip: &'a crate::query::Chip,
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
        let (ra, rb) = (records(&chip.a), records(&chip.b));
        let bases = crate::chip::layout::image_bases(
            ra.len() as u32,
            chip.a.tri_count() as u32,
            rb.len() as u32,
        );
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
                records: [ra, rb],
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
        let fill = self
            .mem
            .respond(now)
            .and_then(|_| self.mc.respond(&self.img));
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

    /// The Memory Controller in clock `now`: a request, the bundle into the DOP Unit (a
    /// load's fields into the sequencer's register of its set).
    fn memory(&mut self, now: u64, to: &TriInputOut, fill: Option<(bool, u16)>) -> ClockIn {
        if self.mem.ready(now) {
            if let Some((dst, r, addr)) = self.mc.request(to.need, to.ids, fill, &self.img) {
                self.mem.request(now, addr);
                self.mc.accept(dst, r);
            }
        }
        let streamed = (!self.sq.halted)
            .then(|| self.mc.stream(self.dout.busy, self.img.k))
            .flatten();
        let Some(s) = streamed else {
            return ClockIn::default();
        };
        self.mc.streamed(self.img.k);
        if s.dop_in.a.is_some() {
            self.sq.compared.push_back(s.aligned);
        }
        if let Some((set, members)) = s.loaded {
            self.sq.loaded[set] = members;
        }
        s.dop_in
    }

    /// An aligned DOP's flags into actions (one per member it overlaps); the current
    /// list's group's fields kept for its level.
    fn flags(&mut self) {
        let flagged = self.dout.flags_valid.then(|| self.sq.compared.pop_front());
        let Some(n) = flagged.and_then(|n| n.expect("flags without an aligned bundle")) else {
            return;
        };
        let sq = &mut self.sq;
        let g = sq.fields(sq.cur).expect("flags before the set's load").to_vec();
        self.out.dop_tests += g.len() as u64;
        for (side, &x) in g.iter().enumerate() {
            if self.dout.overlap[side] {
                sq.actions.extend(actions(n, x, side));
            }
        }
        sq.groups[self.ls.level] = g;
        sq.inflight -= 1;
    }

    /// The sequencer's command to the lists this clock: an action (an append, or the leaf
    /// pair the input stage took, `offered` and `leaf_ready`), a read, the next list; a list
    /// entered; the speculative load asked for.
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
            let (set, id) = (sq.cur, n as u32);
            self.mc.push(Ask::Aligned { set, id }, &self.img);
        }
        if idle && sq.entered {
            speculate(sq, &mut self.mc, &self.img);
            let room = self.mc.room() > 1 + ls.rd.is_some() as usize;
            cmd.read = ls.remaining > 0 && room && sq.actions.len() < 4 && ls.level > 0;
            sq.inflight += cmd.read as usize;
            let done = ls.remaining == 0 && sq.inflight == 0 && sq.actions.is_empty();
            if done && cmd.append.is_none() {
                (cmd.next_list, sq.entered) = (true, false);
            }
        } else if idle && !sq.entered && ls.level > 0 && self.mc.room() >= 1 {
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
/// into the set the last list did not use).
fn enter(sq: &mut Sequencer, mc: &mut Controller, img: &Images, level: usize, branch: usize) {
    let g = match level {
        1 => vec![DopTree::ROOT],
        _ => match sq.groups[level - 1][branch] {
            m if m.leaf => vec![m.id],
            m => m.f.to_vec(),
        },
    };
    (sq.entered, sq.spec) = (true, true);
    match (0..2).find(|&s| sq.holds[s] == g) {
        Some(s) => sq.cur = s,
        None => {
            sq.cur = 1 - sq.cur;
            sq.load(sq.cur, g, mc, img);
        }
    }
}

/// Once the current group's fields are loaded: its left member's children loaded
/// speculatively into the other set, unless it holds them (or the member is a leaf).
fn speculate(sq: &mut Sequencer, mc: &mut Controller, img: &Images) {
    let Some(&[m0, ..]) = sq.fields(sq.cur) else {
        return;
    };
    if !sq.spec || mc.room() == 0 {
        return;
    }
    sq.spec = false;
    let other = 1 - sq.cur;
    if !m0.leaf && sq.holds[other] != m0.f {
        sq.load(other, m0.f.to_vec(), mc, img);
    }
}
