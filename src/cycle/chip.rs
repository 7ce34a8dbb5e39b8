//! The chip in the cycle model: D_CNTR's pair queue and pair buffer, the node words asked
//! for and arrived, the triangle words held for TRI_UNIT, the memory port, the leaf FIFO and
//! leaf register, the result port, and the end of a query, register for register as
//! [`rtl::chip`](crate::rtl) builds them (docs/explanation/architecture.md, "Cycle semantics"). Each
//! [`step`](Clocked::step) computes the cycle's logic from the registers and inputs, then
//! clocks every register once.

use super::d_cntr::{QueueIn, QueueModel, QueueOut};
use super::delay::Delay;
use super::dop_unit::DopUnit;
use super::memory_port::MemPort;
use super::tri_unit::{TriOut, TriUnit};
use crate::chip::config::ChipConfig;
use crate::chip::layout::{Dst, Entry, Pair, RecordMap};
use crate::chip::params::Params;
use crate::chip::ports::{ChipIn, ChipOut, Clocked, MemorySide};
use crate::chip::reg::{self, Order};
use crate::chip::rtl::FIFO_WRITE_TO_HEAD;
use crate::dop::Node;
use crate::golden::d_cntr::children;
use crate::golden::host::HostSetup;
use crate::golden::memory::{NodeCache, ObjectImage, TriCache};
use crate::golden::{dop_unit, tri_unit};
use serde::Serialize;
use std::collections::VecDeque;

/// Where the clocks of a running query went, one cause per cycle for the DOP unit's
/// input, plus the other units' occupancy.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Stats {
    /// Cycles from start to done.
    pub cycles: u64,
    /// A DOP test issued.
    pub issue: u64,
    /// The entry's pair waits for a node word (the memory port).
    pub stall_memory: u64,
    /// Both words held, but the last issue was too recent (issue spacing), or a folded DOP
    /// unit's counter is not 0 (`dop_interval`).
    pub stall_spacing: u64,
    /// Both words held, but DOP tests in flight + leaf pairs waiting fill the credit.
    pub stall_credit: u64,
    /// No entry: one is popped in this cycle (or, LIFO, waits for a child entry's push).
    pub stall_refill: u64,
    /// No entry and the queue empty while DOP results that may refill it are in flight.
    pub stall_empty_queue: u64,
    /// The traversal is over: leaf pairs and TRI_UNIT finish.
    pub drain: u64,
    /// Halted (first hit or overflow): what is in flight finishes.
    pub halted: u64,
    /// A leaf pair with both triangle words waits for TRI_UNIT's `in_ready`.
    pub back_pressure: u64,
    /// A result is shown and the host does not take it.
    pub result_wait: u64,
    /// Cycles with a memory request outstanding.
    pub memory_busy: u64,
    /// Sum over cycles of the DOP tests in flight (mean occupancy = this / cycles).
    pub dop_occupancy: u64,
    /// Sum over cycles of TRI_UNIT's open pairs.
    pub tri_occupancy: u64,
    /// A's triangle words requested: the triangle cache's misses.
    pub tri_fetches_a: u64,
}

/// The chip. Values come from the golden model of `cfg` on the images `a`, `b` with
/// `setup`; timing from `p`.
pub struct Chip<'a> {
    p: Params,
    // ---- host registers
    order: Order,
    first: bool,
    root: u32,
    base: [u32; 4],
    /// Where the image's records lie in memory (register `MAP`).
    map: RecordMap,
    /// The record of each node of A and B, and of each triangle.
    records: [&'a [u32]; 2],
    /// The id the chip knows each node of A and B by (what the traversal signals show).
    ids: [&'a [u32]; 2],
    tri_records: [&'a [u32]; 2],
    // ---- query state
    run: bool,
    done: bool,
    push_root: bool,
    stop: bool,
    // ---- D_CNTR
    queue: QueueModel<Entry>,
    q: QueueOut<Entry>,
    /// The pairs popped from the queue and not yet issued, oldest (the DOP unit's input)
    /// first: the RTL's pair buffer.
    ahead: VecDeque<Ahead>,
    /// The node records held, A's and B's, as the pairs put into `ahead` left them.
    held_nodes: [NodeCache; 2],
    /// Node records of `ahead`'s pairs not yet requested, in order: destination, record, pair.
    to_ask: VecDeque<(Dst, u32, u64)>,
    /// Node records arrived and not yet used, in order (the RTL's two node-word FIFOs, A's and
    /// B's: a pair's words are at their heads when they are at this queue's).
    words: VecDeque<u32>,
    /// Pairs put into `ahead` since start (each pair's number).
    seq: u64,
    /// The first cycle the issue spacing lets a pair issue.
    next_issue: u64,
    /// Child entries not yet pushed (the RTL's `pend`: one at most; none at issue spacing
    /// 1, where the queue takes two entries a clock).
    pend: VecDeque<Entry>,
    // ---- triangle words (held in A's and B's triangle caches) and the memory port
    /// The triangle words held, A's and B's, as the leaf pairs put into the leaf FIFO left
    /// them.
    held_tris: [TriCache; 2],
    /// Triangle words of the leaf pairs not yet requested, in order: destination, record,
    /// leaf pair.
    tri_ask: VecDeque<(Dst, u32, u64)>,
    /// Triangle words arrived and not yet used, in order: a leaf pair's are at the head
    /// when it is in the leaf register.
    tri_words: VecDeque<u32>,
    port: MemPort,
    // ---- units
    dop: DopUnit<'a>,
    leaf_fifo: Delay<Leaf>,
    leaf_valid: bool,
    /// The leaf register.
    leaf: Leaf,
    /// Leaf pairs put into the leaf FIFO since start.
    leaf_seq: u64,
    tri: TriUnit<'a>,
    // ---- counters: DOP tests, triangle tests, node fetches, triangle fetches
    cnt: [u64; 4],
    now: u64,
    /// The cycle's logic as far as it depends on the registers alone ([`logic`](Self::logic)),
    /// computed once per state change: the driver asks for the outputs, whether the chip
    /// waits and then clocks it, all from one evaluation.
    logic: Comb,
    /// Where the clocks went, if counted (a scene that asks for no cycles leaves them out).
    pub stats: Option<Stats>,
}

/// A pair waiting for the DOP unit: its number since start, and which of its node records
/// come from memory (A's, B's; the others repeat the previous pair's).
#[derive(Clone, Copy, Debug)]
struct Ahead {
    pair: Pair,
    seq: u64,
    fetch: [bool; 2],
}

/// A leaf pair: its triangles, its number since start, and which of its triangle words
/// come from memory (A's, B's; the others are held).
#[derive(Clone, Copy, Debug, Default)]
struct Leaf {
    tag: (u32, u32),
    seq: u64,
    fetch: [bool; 2],
}

/// The cycle's logic as far as it depends on the registers alone ([`Chip::logic`]); the
/// inputs add `accept` and `give` ([`accepts`](Self::accepts), [`gives`](Self::gives)).
/// Flags, not copies of the values they point at (the pair at the DOP unit's input, the DOP
/// result: read at the edge), so that the logic stays small to write and read every clock.
#[derive(Clone, Copy, Default)]
struct Comb {
    halt: bool,
    /// A pair waits at the DOP unit's input (`ahead`'s head).
    cur: bool,
    need: [bool; 4],
    req: Option<(Dst, u32)>,
    issue: bool,
    leaf_in: Option<(u32, u32)>,
    /// The DOP result has child entries ([`children`], made at the edge).
    grows: bool,
    pop: bool,
    tri_in: bool,
    tri_take: bool,
    leaf_out: bool,
    out: Option<TriOut>,
    finish: bool,
    /// The chip acts in this cycle whatever its inputs (the part of
    /// [`quiet_until`](Chip::quiet_until)'s test that depends on the registers alone, made
    /// with the rest of the logic: most clocks act, and this one load answers for them).
    acts: bool,
}

impl Comb {
    /// The memory takes the request.
    fn accepts(&self, i: &ChipIn) -> bool {
        self.req.is_some() && i.mem_req_ready
    }

    /// TRI_UNIT gives out its verdict: the host reads it, or it is not shown (a separate pair).
    fn gives(&self, i: &ChipIn) -> bool {
        self.out.is_some_and(|o| i.res_ready || !o.kept())
    }
}

impl<'a> Chip<'a> {
    /// A chip after reset (its host registers zero: write [`control_writes`](crate::chip::reg::control_writes) before
    /// `start`); `counters`: count [`Stats`].
    pub fn new(
        cfg: &ChipConfig,
        p: Params,
        a: &'a ObjectImage,
        b: &'a ObjectImage,
        setup: &'a HostSetup,
        counters: bool,
    ) -> Result<Self, String> {
        p.check()?;
        let dop_values = dop_unit::TransformCache::new(
            cfg.format.dop,
            cfg.dop_rounding.op(),
            setup,
            &a.tree,
            &b.tree,
        );
        let tri_values = tri_unit::TriUnit::new(
            cfg.format.tri,
            cfg.tri_rounding,
            setup,
            a.tri_count(),
            b.tri_count(),
        );
        let queue = QueueModel::with_capacity(p.queue_entries as usize);
        let mut chip = Chip {
            p,
            order: Order::Fifo,
            first: false,
            root: 0,
            base: [0; 4],
            map: RecordMap::IN_ORDER,
            records: [&a.records, &b.records],
            ids: [&a.ids, &b.ids],
            tri_records: [&a.tri_records, &b.tri_records],
            run: false,
            done: false,
            push_root: false,
            stop: false,
            q: queue.outputs(),
            queue,
            ahead: VecDeque::new(),
            held_nodes: [
                NodeCache::new(cfg.node_cache),
                NodeCache::new(cfg.node_cache),
            ],
            to_ask: VecDeque::new(),
            words: VecDeque::new(),
            seq: 0,
            next_issue: 0,
            pend: VecDeque::new(),
            held_tris: [TriCache::new(cfg.tri_cache), TriCache::new(cfg.tri_cache_b)],
            tri_ask: VecDeque::new(),
            tri_words: VecDeque::new(),
            port: MemPort::new(p.outstanding),
            dop: DopUnit::new(a, b, dop_values, &p, cfg)?,
            leaf_fifo: Delay::with_capacity(FIFO_WRITE_TO_HEAD, p.credit as usize),
            leaf_valid: false,
            leaf: Leaf::default(),
            leaf_seq: 0,
            tri: TriUnit::new(a, b, tri_values, &p)?,
            cnt: [0; 4],
            now: 0,
            logic: Comb::default(),
            stats: counters.then(Stats::default),
        };
        chip.logic = chip.logic();
        Ok(chip)
    }

    /// The cycle's logic from the registers (the inputs' part: [`Comb::accepts`],
    /// [`Comb::gives`]). Inlined so that `self.logic = self.logic()` writes the fields in
    /// place: a copy of the returned value, read right after its bytes were written, stalls
    /// the store buffer (`perf annotate`: a sixth of `step`).
    #[inline(always)]
    fn logic(&self) -> Comb {
        let run = self.run;
        let halt = self.stop || self.q.overflow;
        let go = run && !halt;
        let cur = self.ahead.front();
        let need = self.need(go, cur);
        let req = self.request(go, cur);
        let in_flight = self.dop.in_flight();
        // the issue spacing, and a folded DOP unit's `in_ready`
        let spaced = self.now >= self.next_issue && self.dop.in_ready(self.now);
        let issue = go
            && cur.is_some()
            && !need[0]
            && !need[1]
            && spaced
            && in_flight + self.leaf_fifo.len() < self.p.credit as usize;
        // a DOP result: child entries, or a leaf pair
        let dop_out = self.dop.out(self.now);
        let (mut leaf_in, mut grows) = (None, false);
        if let Some(r) = dop_out.filter(|r| r.overlap) {
            match (r.na, r.nb) {
                (Node::Leaf(ta), Node::Leaf(tb)) => leaf_in = Some((ta, tb)),
                _ => grows = true,
            }
        }
        let child_push = !self.pend.is_empty() || grows;
        // room in the buffer of prefetch + 2 pairs for an entry's two, counted before this
        // cycle's issue (a register compare: the issue is not on the pop's path)
        let room = self.ahead.len() <= self.p.prefetch as usize;
        let pop = go && !self.q.empty && room && !(self.order == Order::Lifo && child_push);
        // leaf pairs and TRI_UNIT
        let tri_in = go && self.leaf_valid && !need[2] && !need[3];
        let tri_take = tri_in && self.tri.in_ready(self.now);
        let leaf_out = self.leaf_fifo.out(self.now).is_some()
            && (halt || (run && (!self.leaf_valid || tri_take)));
        let out = self.tri.out(self.now).copied();
        let halt_idle = in_flight == 0
            && self.pend.is_empty()
            && self.port.is_empty()
            && self.tri.open() == 0
            && !self.push_root
            && self.leaf_fifo.is_empty();
        let all_idle = halt_idle && self.q.empty && cur.is_none() && !self.leaf_valid;
        let finish = run && (all_idle || (halt && halt_idle));
        let acts = !run
            || self.push_root
            || issue
            || pop
            || child_push
            || dop_out.is_some()
            || tri_take
            || leaf_out
            || finish
            // a first hit shown halts the traversal (a register), read or not
            || (self.first && !self.stop && out.is_some_and(|o| o.sure_hit()));
        Comb {
            halt,
            cur: cur.is_some(),
            need,
            req,
            issue,
            leaf_in,
            grows,
            pop,
            tri_in,
            tri_take,
            leaf_out,
            out,
            finish,
            acts,
        }
    }

    /// The words that the pair at the DOP unit's input (`cur`) and the leaf pair wait for:
    /// A's and B's node words, A's and B's triangle words (each queue in request order,
    /// the waiting pair's words first).
    #[inline(always)]
    fn need(&self, go: bool, cur: Option<&Ahead>) -> [bool; 4] {
        let [fa, fb] = cur.map_or([false; 2], |c| c.fetch);
        let [ta, tb] = if self.leaf_valid {
            self.leaf.fetch
        } else {
            [false; 2]
        };
        let (words, tris) = (self.words.len(), self.tri_words.len());
        [
            go && fa && words == 0,
            go && fb && words < 1 + fa as usize,
            go && ta && tris == 0,
            go && tb && tris < 1 + ta as usize,
        ]
    }

    /// The memory request, in each queue's order: the leaf register's triangle words first
    /// (the leaf pair waits for them), then the next node word (the current pair's only at
    /// prefetch 0, any pair's in the buffer else), then, with `tri_prefetch`, the triangle
    /// words of the leaf pairs in the leaf FIFO.
    #[inline(always)]
    fn request(&self, go: bool, cur: Option<&Ahead>) -> Option<(Dst, u32)> {
        if !go {
            return None;
        }
        let tri = self.tri_ask.front();
        let leaf = tri.filter(|w| self.leaf_valid && self.leaf.seq == w.2);
        let node = self
            .to_ask
            .front()
            .filter(|w| self.p.prefetch > 0 || cur.is_some_and(|c| c.seq == w.2));
        let ahead = tri.filter(|_| self.p.tri_prefetch);
        leaf.or(node)
            .or(ahead)
            .filter(|w| self.port.free(w.0))
            .map(|w| (w.0, w.1))
    }

    /// The logic after a clock in which only the memory port moved, before cycle `until`
    /// (the chip's next event: the logic's parts that depend on the clock stay as they
    /// are). The port and the words held are read only by the request, by `need`, and,
    /// through the port's emptiness, by the end of the query: unless `need` changed or
    /// the port emptied, the request alone is new (most such clocks). True if the whole
    /// logic was evaluated anew.
    #[inline(always)]
    fn after_memory(&mut self, until: u64) -> bool {
        let go = self.run && !self.logic.halt;
        let cur = self.ahead.front();
        let need = self.need(go, cur);
        let anew = need != self.logic.need || self.port.is_empty() || self.now >= until;
        if anew {
            self.logic = self.logic();
        } else {
            self.logic.req = self.request(go, cur);
        }
        anew
    }

    /// The word address of record `id` of `d`.
    fn addr(&self, d: Dst, id: u32) -> u32 {
        self.map.addr(d, self.base[d as usize], id)
    }

    /// The records of a pair's nodes, A's and B's.
    fn pair_records(&self, p: Pair) -> [u32; 2] {
        [self.records[0][p.a as usize], self.records[1][p.b as usize]]
    }

    /// The triangle records of a leaf pair's triangles, A's and B's.
    fn tri_recs(&self, (ta, tb): (u32, u32)) -> [u32; 2] {
        [
            self.tri_records[0][ta as usize],
            self.tri_records[1][tb as usize],
        ]
    }

    /// Books `n` cycles with the current logic (the same in each) and inputs `i` to [`Stats`].
    #[inline]
    fn tally(&mut self, i: &ChipIn, n: u64) {
        let Some(s) = &mut self.stats else { return };
        let c = &self.logic;
        s.cycles += n;
        s.memory_busy += n * !self.port.is_empty() as u64;
        s.dop_occupancy += n * self.dop.in_flight() as u64;
        s.tri_occupancy += n * self.tri.open() as u64;
        s.back_pressure += n * (c.tri_in && !c.tri_take) as u64;
        s.result_wait += n * c.out.is_some_and(|o| o.kept() && !i.res_ready) as u64;
        let cause = if c.halt {
            &mut s.halted
        } else if c.issue {
            &mut s.issue
        } else if c.cur {
            if c.need[0] || c.need[1] {
                &mut s.stall_memory
            } else if self.now < self.next_issue || !self.dop.in_ready(self.now) {
                &mut s.stall_spacing
            } else {
                &mut s.stall_credit
            }
        } else if !self.q.empty {
            &mut s.stall_refill
        } else if self.dop.in_flight() > 0 || !self.pend.is_empty() || self.push_root {
            &mut s.stall_empty_queue
        } else {
            &mut s.drain
        };
        *cause += n;
    }

    fn probe(&self, c: &Comb, i: &ChipIn, push: bool) -> Vec<u64> {
        let b = |x: bool| x as u64;
        let dop = self.dop.out(self.now).copied();
        let cur = self.ahead.front();
        let res = c.out.filter(|o| o.kept());
        let leaf = |n: Option<Node>| b(matches!(n, Some(Node::Leaf(_))));
        let (req_addr, req_dst) = c
            .req
            .map_or((0, 0), |(d, id)| (self.addr(d, id) as u64, d as u64));
        vec![
            b(i.start),
            b(self.run),
            b(self.done),
            b(self.q.overflow),
            b(c.halt),
            self.q.count as u64,
            self.q.max_count as u64,
            b(push),
            b(c.pop),
            b(c.cur),
            cur.map_or(0, |c| self.ids[0][c.pair.a as usize] as u64),
            cur.map_or(0, |c| self.ids[1][c.pair.b as usize] as u64),
            b(c.need[0]),
            b(c.need[1]),
            b(c.issue),
            self.dop.in_flight() as u64,
            b(c.req.is_some()),
            b(i.mem_req_ready),
            req_addr,
            req_dst,
            b(!self.port.is_empty()),
            b(i.mem_resp.is_some()),
            b(dop.is_some()),
            b(dop.is_some_and(|r| r.overlap)),
            dop.map_or(0, |r| self.ids[0][r.pair.a as usize] as u64),
            dop.map_or(0, |r| self.ids[1][r.pair.b as usize] as u64),
            leaf(dop.map(|r| r.na)),
            leaf(dop.map(|r| r.nb)),
            b(c.leaf_in.is_some()),
            self.leaf_fifo.len() as u64,
            b(self.leaf_valid),
            self.leaf.tag.0 as u64,
            self.leaf.tag.1 as u64,
            b(c.tri_in),
            b(self.tri.in_ready(self.now)),
            b(c.tri_take),
            self.tri.open() as u64,
            b(c.out.is_some()),
            b(c.out.is_some_and(|o| o.res.hit)),
            b(c.out.is_some_and(|o| o.res.uncertain)),
            c.out.map_or(0, |o| o.a as u64),
            c.out.map_or(0, |o| o.b as u64),
            b(res.is_some()),
            b(res.is_some_and(|o| o.res.uncertain)),
            res.map_or(0, |o| o.a as u64),
            res.map_or(0, |o| o.b as u64),
            self.cnt[0],
            self.cnt[1],
            self.cnt[2],
            self.cnt[3],
        ]
    }

    /// With `res_ready` as in `i`, the chip does nothing but wait until this cycle, but
    /// for its memory port (requests taken, responses arriving): no other register but the
    /// clock changes before it (the next DOP result, leaf pair at the FIFO's head, TRI_UNIT
    /// verdict, the folded TRI_UNIT's next slot for the leaf pair waiting at its input, the
    /// folded DOP unit's for the pair waiting at its input, or the end of the issue
    /// spacing; `u64::MAX`: nothing inside the chip is under way). `None`: it may act in
    /// the current cycle. Lets [`wait`](Clocked::wait) skip to it in one step, the trace
    /// exact.
    #[inline]
    pub fn quiet_until(&self, i: &ChipIn) -> Option<u64> {
        let c = &self.logic;
        if c.acts || c.gives(i) {
            return None;
        }
        let now = self.now;
        // a time after the current cycle, else none (u64::MAX)
        let after = |t: Option<u64>| t.filter(|&t| t > now).unwrap_or(u64::MAX);
        let slot = self.tri.next_slot(now).filter(|_| c.tri_in);
        let dop_slot = self.dop.next_slot(now).filter(|_| c.cur);
        let events = after(self.dop.next_out())
            .min(after(self.leaf_fifo.next_out()))
            .min(after(self.tri.next_out()));
        Some(
            events
                .min(after(Some(self.next_issue)))
                .min(after(slot))
                .min(after(dop_slot)),
        )
    }

    /// The memory port's edge: the request `taken` (destination, record), a response
    /// arriving (`resp`: it answers the oldest request).
    #[inline(always)]
    fn memory_port(&mut self, taken: Option<(Dst, u32)>, resp: bool) {
        if let Some((d, id)) = taken {
            self.port.accept(d, id);
            self.cnt[if d.is_tri() { 3 } else { 2 }] += 1;
            if d.is_tri() {
                self.tri_ask.pop_front();
            } else {
                self.to_ask.pop_front();
            }
            if let Some(s) = self.stats.as_mut().filter(|_| d == Dst::TriA) {
                s.tri_fetches_a += 1;
            }
        }
        if resp {
            match self.port.respond() {
                Some((d, id)) if d.is_tri() => self.tri_words.push_back(id),
                Some((_, id)) => self.words.push_back(id),
                None => {}
            }
        }
    }

    /// A leaf pair into the leaf FIFO: which of its triangle words are held when it reaches
    /// the leaf register (the leaf pairs before it fill the caches in the same order), and
    /// the others asked for.
    fn push_leaf(&mut self, now: u64, tag: (u32, u32)) {
        let recs = self.tri_recs(tag);
        let fetch = [0, 1].map(|k| self.held_tris[k].fetch(recs[k]));
        for k in (0..2).filter(|&k| fetch[k]) {
            let d = [Dst::TriA, Dst::TriB][k];
            self.tri_ask.push_back((d, recs[k], self.leaf_seq));
        }
        let seq = self.leaf_seq;
        self.leaf_fifo.push(now, Leaf { tag, seq, fetch });
        self.leaf_seq += 1;
    }

    /// The leaf register's triangle words fetched are the heads of the word queue.
    fn take_tri_words(&mut self) {
        let recs = self.tri_recs(self.leaf.tag);
        for k in (0..2).filter(|&k| self.leaf.fetch[k]) {
            let w = self.tri_words.pop_front();
            assert_eq!(w, Some(recs[k]), "triangle word {k} of {:?}", self.leaf.tag);
        }
    }

    /// Skips `n` clocks before `until`, [`quiet_until`](Self::quiet_until)'s cycle, with
    /// the inputs `i`: the same state as `n` steps. The cycle's logic depends on the clock
    /// only through the times `quiet_until` takes the earliest of, so it is the same until
    /// then and is evaluated anew only if the skip reaches `until` (most skips end earlier,
    /// at a memory request or response that `wait` serves: evaluating it was a skip's largest cost).
    fn skip(&mut self, n: u64, until: u64, i: &ChipIn) {
        self.tally(i, n);
        self.now += n;
        if self.now >= until {
            self.logic = self.logic();
        }
    }
}

impl Clocked for Chip<'_> {
    #[inline]
    fn outputs(&self) -> ChipOut {
        let c = &self.logic;
        let res = c.out.filter(|o| o.kept());
        ChipOut {
            busy: self.run,
            done: self.done,
            overflow: self.q.overflow,
            max_depth: self.q.max_count as u64,
            dop_tests: self.cnt[0],
            tri_tests: self.cnt[1],
            node_fetches: self.cnt[2],
            tri_fetches: self.cnt[3],
            mem_req_valid: c.req.is_some(),
            mem_req_addr: c.req.map_or(0, |(d, id)| self.addr(d, id)),
            res_valid: res.is_some(),
            res_tag: res.map_or((0, 0), |o| (o.a, o.b)),
            res_uncertain: res.is_some_and(|o| o.res.uncertain),
        }
    }

    /// Runs the chip on its own from the driver's cycle `cyc` (inputs `i`, the memory
    /// served for it) until the driver has something to do: a result shown that was not
    /// shown at `cyc` (the host may read it), the end of the query, or `limit`. On the way
    /// it serves the memory from `mem` as the driver would, clocks the cycles in which the
    /// chip acts ([`step`](Clocked::step)), serves those in which only its memory port moves
    /// (a request taken, a response arriving: a third to a half of a memory-bound query's
    /// clocks) without evaluating the rest of the logic (`Chip::after_memory`),
    /// and skips the stretches in which nothing moves in one step
    /// ([`quiet_until`](Chip::quiet_until)): the driver's turn is paid only at a result.
    /// A result shown at `cyc` is not read before `limit` (`i.res_ready`, false, holds).
    fn wait<M: MemorySide>(
        &mut self,
        i: &ChipIn,
        mem: &mut M,
        cyc: u64,
        limit: u64,
    ) -> Result<u64, String> {
        if i.start || i.host_we {
            return Ok(0);
        }
        // the chip's clock runs `base` ahead of the driver's (the host's writes)
        let (start, base) = (self.now, self.now - cyc);
        let limit = limit.saturating_add(base);
        let shown = self.outputs().res_valid;
        let mut i = *i;
        // the chip's next event, kept while only the request is evaluated anew
        let mut quiet = None;
        loop {
            quiet = quiet
                .filter(|&u| u > self.now)
                .or_else(|| self.quiet_until(&i));
            match quiet {
                None => {
                    self.step(&i, false);
                }
                Some(until) => {
                    let taken = self.logic.req.filter(|_| i.mem_req_ready);
                    if taken.is_some() || i.mem_resp.is_some() {
                        self.tally(&i, 1);
                        self.memory_port(taken, i.mem_resp.is_some());
                        self.now += 1;
                        if self.after_memory(until) {
                            quiet = None;
                        }
                    } else {
                        let next_resp = mem
                            .next_response()
                            .map_or(u64::MAX, |r| (r + base).max(self.now + 1));
                        let next_ready = if self.logic.req.is_some() {
                            (mem.next_ready() + base).max(self.now + 1)
                        } else {
                            u64::MAX
                        };
                        let t = until.min(limit).min(next_resp).min(next_ready);
                        self.skip(t - self.now, until, &i);
                    }
                }
            }
            // a new cycle: the driver's turn, or its memory served here
            if self.done || self.now >= limit || (!shown && self.outputs().res_valid) {
                return Ok(self.now - start);
            }
            let m = self.now - base;
            i.mem_resp = mem.respond(m);
            i.mem_req_ready = mem.ready(m);
            if let Some((d, id)) = self.logic.req.filter(|_| i.mem_req_ready) {
                mem.request(m, self.addr(d, id))?;
            }
        }
    }

    fn probe_list(&self) -> &'static crate::chip::probes::Probes {
        &crate::chip::probes::DATE05
    }

    fn step(&mut self, i: &ChipIn, probe: bool) -> Option<Vec<u64>> {
        let c = self.logic;
        let (accept, give) = (c.accepts(i), c.gives(i));
        let now = self.now;
        if self.run {
            self.tally(i, 1);
        }
        // the queue's push: the root entry, else a pending child entry, else a new one
        // (FIFO pushes a result's first entry first, LIFO its second, so that the first
        // is popped first)
        if c.grows {
            let r = self.dop.out(now).expect("a growing result is out");
            let (ch, n) = children(r.pair, r.na, r.nb);
            if self.order == Order::Lifo {
                self.pend.extend(ch[..n].iter().rev());
            } else {
                self.pend.extend(&ch[..n]);
            }
        }
        let push = if self.push_root {
            Some(Entry {
                pairs: [
                    Pair {
                        a: self.root & 0xffff,
                        b: self.root >> 16,
                        flip: false,
                    },
                    Pair::default(),
                ],
                len: 1,
            })
        } else {
            self.pend.pop_front()
        };
        let push2 = if self.p.issue_spacing == 1 {
            self.pend.pop_front()
        } else {
            None
        };
        let probed = probe.then(|| self.probe(&c, i, push.is_some()));
        if i.host_we {
            self.host_write(i.host_addr, i.host_data);
        }
        // ---- memory port
        self.memory_port(c.req.filter(|_| accept), i.mem_resp.is_some());
        // ---- issue, DOP results
        if c.issue {
            let cur = self.ahead.pop_front().expect("an issue has a pair");
            self.dop.issue(now, cur.pair);
            self.cnt[0] += 1;
            self.next_issue = now + self.p.issue_spacing as u64;
            for (k, id) in self
                .pair_records(cur.pair)
                .into_iter()
                .enumerate()
                .filter(|&(k, _)| cur.fetch[k])
            {
                // the word queue is in pair order: the head's words are its own
                let w = self.words.pop_front();
                assert_eq!(w, Some(id), "node word {k} of {:?}", cur.pair);
            }
        }
        self.dop.retire(now);
        if c.pop {
            self.pop_ahead();
        }
        // a clock with no clear, push or pop leaves the queue as it is (a second push comes
        // only with a first)
        let clear = i.start && !self.run;
        if clear || push.is_some() || c.pop {
            self.q = self.queue.step(&QueueIn {
                clear,
                order: self.order,
                push: push.is_some(),
                push_data: push.unwrap_or_default(),
                push2,
                pop: c.pop,
            });
        }
        self.push_root = false;
        // ---- leaf pairs and TRI_UNIT
        if c.tri_take {
            let (ta, tb) = self.leaf.tag;
            self.tri.take(now, ta, tb);
            self.leaf_valid = false;
            self.cnt[1] += 1;
            self.take_tri_words();
        }
        if c.leaf_out {
            let leaf = self
                .leaf_fifo
                .pop(now)
                .expect("leaf_out reads a visible head");
            if !c.halt {
                self.leaf_valid = true;
                self.leaf = leaf;
            }
        }
        if let Some(tag) = c.leaf_in {
            self.push_leaf(now, tag);
        }
        if give {
            self.tri.give(now);
        }
        // ---- first hit, end of query, start
        if self.run && self.first && c.out.is_some_and(|o| o.sure_hit()) {
            self.stop = true;
        }
        if c.finish {
            self.run = false;
            self.done = true;
        }
        if i.start && !self.run {
            self.start();
        }
        self.now += 1;
        self.logic = self.logic();
        probed
    }
}

impl Chip<'_> {
    /// A host write to one of the chip's registers (`chip::reg`).
    fn host_write(&mut self, addr: u32, data: u32) {
        match addr {
            reg::MODE => {
                let (order, mode) = reg::mode_fields(data);
                (self.order, self.first) = (order, mode == reg::Mode::First);
            }
            reg::ROOT => self.root = data,
            reg::BASE_NA..=reg::BASE_TB => {
                // registers in the order NA, NB, TA, TB = Dst order
                self.base[(addr - reg::BASE_NA) as usize] = data & 0xff_ffff;
            }
            reg::MAP => self.map = RecordMap::of_word(data),
            _ => {} // the DOP unit's and TRI_UNIT's setup: the golden HostSetup
        }
    }

    /// A pop: the top entry's pairs join the pair buffer, and the node words they fetch
    /// (those the held records do not hold) join the ask list, in pair order.
    fn pop_ahead(&mut self) {
        let e = self.q.top_data;
        for &pair in &e.pairs[..e.len as usize] {
            let ids = self.pair_records(pair);
            let fetch = [0, 1].map(|k| self.held_nodes[k].fetch(ids[k]));
            for (k, d) in [Dst::NodeA, Dst::NodeB]
                .into_iter()
                .enumerate()
                .filter(|&(k, _)| fetch[k])
            {
                self.to_ask.push_back((d, ids[k], self.seq));
            }
            self.ahead.push_back(Ahead {
                pair,
                seq: self.seq,
                fetch,
            });
            self.seq += 1;
        }
    }

    /// A start: the query runs from the root pair, with every buffer, cache and counter
    /// empty.
    fn start(&mut self) {
        self.run = true;
        self.done = false;
        self.push_root = true;
        self.stop = false;
        self.ahead.clear();
        self.to_ask.clear();
        self.words.clear();
        self.held_nodes.iter_mut().for_each(NodeCache::clear);
        self.leaf_valid = false;
        self.leaf_seq = 0;
        self.tri_ask.clear();
        self.tri_words.clear();
        self.held_tris.iter_mut().for_each(TriCache::clear);
        self.cnt = [0; 4];
        self.stats = self.stats.map(|_| Stats::default());
        self.next_issue = 0;
    }
}
