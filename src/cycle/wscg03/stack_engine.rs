//! WSCG'03's Stack Engine (§4.2): it processes a list of aligned node pointers against a
//! tumbled sibling pair, reading the pointers one per clock from its list SRAM and passing
//! them to the Memory Controller; each overlap flag appends the aligned node's children
//! (or the node itself, a leaf) to the new list of the tumbled sibling it overlaps, the
//! left sibling's list in the left SRAM, the right's in the right SRAM (§3: two lists
//! produced at once). When a list is done it recurses one level down, left list first,
//! then the right one, then steps up (its stack of list pointers per level and branch is
//! this recursion). Overlapping leaves go to the Triangle Unit; if its words are not held,
//! list processing is interrupted until they arrive. A tumbled leaf's list holds the
//! aligned nodes to test against that leaf itself (Algorithm 2's overloaded call).
//! The lists, tests and verdicts are those of the golden list traversal
//! ([`traversal::list`](crate::traversal::list)).

use super::dop_unit::DopUnit;
use super::tri_unit::TriUnit;
use super::{ListRecord, MemCtl, Stats};
use crate::chip::layout::Dst;
use crate::dop::{DopTree, Node};
use crate::golden::memory::ObjectImage;

pub(super) struct StackEngine<'a> {
    pub a: &'a ObjectImage,
    pub b: &'a ObjectImage,
    pub sram_latency: u64,
    pub word_buffer: usize,
    pub mem: MemCtl,
    pub dop: DopUnit<'a>,
    pub tri: TriUnit<'a>,
    /// `(clock of the verdict, A's triangle, B's triangle, uncertain)`.
    pub results: Vec<(u64, u32, u32, bool)>,
    /// First-hit mode: the clock of the first sure verdict stops the traversal.
    pub first: bool,
    stop_at: Option<u64>,
    halted: bool,
    /// The clock the next list starts; the last verdict's clock.
    next_list: u64,
    last_verdict: u64,
    /// Aligned pointers in the list SRAMs (lists written and not yet done).
    live_words: u64,
    pub stats: Stats,
    /// Each list's timeline, in the order processed.
    pub timeline: Vec<ListRecord>,
}

/// One list being processed: its start, its first pointer's clock at the Memory
/// Controller, when its tumbled pair's d' are ready, and its aligned words' clocks.
struct ListRun {
    t0: u64,
    ptr: u64,
    ready: u64,
    present: Vec<u64>,
    ends: Vec<u64>,
    /// The list resumes fetching aligned words after an interrupt from this clock.
    resume: u64,
}

impl<'a> StackEngine<'a> {
    pub fn new(
        a: &'a ObjectImage,
        b: &'a ObjectImage,
        sram_latency: u32,
        word_buffer: u32,
        mem: MemCtl,
        dop: DopUnit<'a>,
        tri: TriUnit<'a>,
        first: bool,
    ) -> Self {
        StackEngine {
            a,
            b,
            sram_latency: sram_latency as u64,
            word_buffer: word_buffer as usize,
            mem,
            dop,
            tri,
            results: vec![],
            first,
            stop_at: None,
            halted: false,
            next_list: 1,
            last_verdict: 0,
            live_words: 0,
            stats: Stats::default(),
            timeline: vec![],
        }
    }

    /// The traversal from the roots (the first list: B's root against A's root), started
    /// at clock 0; books the clocks to [`Stats`].
    pub fn run(&mut self) {
        self.live_words = 1;
        self.list(vec![DopTree::ROOT], vec![DopTree::ROOT], 0);
        let s = &mut self.stats;
        s.cycles = self.next_list.max(self.last_verdict + 1);
        s.drain = s.cycles - self.dop.compare_free().min(s.cycles);
    }

    /// One list of aligned nodes against the tumbled `group` (a sibling pair, or a leaf
    /// alone), then the lists it produced, left first.
    fn list(&mut self, group: Vec<u32>, list: Vec<u32>, level: u32) {
        if self.halted {
            return;
        }
        let s = &mut self.stats;
        s.lists += 1;
        s.list_node_pairs += list.len().div_ceil(2) as u64;
        s.max_level = s.max_level.max(level as u64);
        let t0 = self.next_list;
        let leaves: Vec<u32> = group.iter().filter_map(|&x| leaf(self.b, x)).collect();
        self.tri.new_group(&leaves);
        let ptr = t0 + self.sram_latency;
        let (ready, held) = self.tumbled(&group, ptr);
        let mut run = ListRun {
            t0,
            ptr,
            ready,
            present: vec![],
            ends: vec![],
            resume: 0,
        };
        let out = self.stream(&group, &list, &mut run);
        let first_compare = run.ends.first().map(|&e| e - self.dop.beats());
        if let Some(c) = first_compare.filter(|_| !held) {
            self.stats.cold_lists += 1;
            self.stats.cold_start += c - t0;
        }
        self.timeline.push(ListRecord {
            t0,
            held,
            ready,
            first_compare,
            next: self.next_list,
            len: list.len(),
        });
        self.stats.list_clocks += self.next_list - t0;
        self.live_words += out.iter().map(|l| l.len() as u64).sum::<u64>();
        self.stats.max_list_words = self.stats.max_list_words.max(self.live_words);
        self.live_words -= list.len() as u64;
        for (&x, l) in group.iter().zip(out) {
            if l.is_empty() {
                continue;
            }
            self.list(expand(&self.b.tree, x), l, level + 1);
        }
    }

    /// The tumbled group's d' (held, or fetched and transformed) and the speculative
    /// prefetch of the left parent's children: the clock the group is ready, and whether
    /// it was held.
    fn tumbled(&mut self, group: &[u32], ptr: u64) -> (u64, bool) {
        let held = self.dop.held(group);
        let ready = held.unwrap_or_else(|| {
            let words: Vec<(u32, u64)> = group
                .iter()
                .map(|&x| (x, self.mem.fetch(ptr, Dst::NodeB, x)))
                .collect();
            self.dop.load(&words)
        });
        if let Node::Inner(ch) = self.b.tree.node(group[0]) {
            if !self.dop.speculated(&ch) {
                let words: Vec<(u32, u64)> = ch
                    .iter()
                    .map(|&x| (x, self.mem.fetch(ptr, Dst::NodeB, x)))
                    .collect();
                self.dop.speculate(&words);
            }
        }
        (ready, held.is_some())
    }

    /// The earliest clock aligned word `j` may be asked for: its pointer read, a place in
    /// the Memory Controller's buffer, no interrupt.
    fn earliest(&self, r: &ListRun, j: usize) -> u64 {
        let room = if j >= self.word_buffer {
            r.ends[j - self.word_buffer]
        } else {
            0
        };
        (r.ptr + j as u64).max(room).max(r.resume)
    }

    fn ask(&mut self, r: &mut ListRun, list: &[u32]) {
        let j = r.present.len();
        let t = self.earliest(r, j);
        r.present.push(self.mem.fetch(t, Dst::NodeA, list[j]));
    }

    /// Streams `list` through the compare units: the lists for each member of `group`.
    fn stream(&mut self, group: &[u32], list: &[u32], r: &mut ListRun) -> Vec<Vec<u32>> {
        let mut out = vec![vec![]; group.len()];
        let mut last_flags = r.t0;
        for (i, &n) in list.iter().enumerate() {
            while r.present.len() <= i {
                self.ask(r, list);
            }
            if self
                .stop_at
                .is_some_and(|v| self.dop.start(r.present[i], r.ready) > v)
            {
                self.halted = true;
                break;
            }
            let from = self.dop.compare_free();
            let (start, end) = self.dop.compare(r.present[i], r.ready);
            self.book(r, from, start, end, r.present[i]);
            r.ends.push(end);
            let f = self.dop.flags(end);
            last_flags = f;
            // the words asked for before these flags (and an interrupt they cause)
            while r.present.len() < list.len().min(i + 1 + self.word_buffer)
                && self.earliest(r, r.present.len()) <= f
            {
                self.ask(r, list);
            }
            for (m, &x) in group.iter().enumerate() {
                if !self.dop.overlap(n, x) {
                    continue;
                }
                match (self.a.tree.node(n), self.b.tree.node(x)) {
                    (Node::Leaf(ta), Node::Leaf(tb)) => self.leaf_pair(f, ta, tb, r),
                    _ => out[m].extend(appended(&self.a.tree, &self.b.tree, n, x)),
                }
            }
        }
        self.next_list = last_flags + 1;
        out
    }

    /// An overlapping leaf pair flagged at clock `f`: its triangle words (an interrupt if
    /// one is not held), the Triangle Unit, a result for the host.
    fn leaf_pair(&mut self, f: u64, ta: u32, tb: u32, r: &mut ListRun) {
        let misses = self.tri.misses(ta, tb);
        let mut present = f + 1;
        for (miss, d, id) in [(misses[0], Dst::TriA, ta), (misses[1], Dst::TriB, tb)] {
            if miss {
                present = present.max(self.mem.fetch(f, d, id));
            }
        }
        if misses[0] || misses[1] {
            self.stats.interrupts += 1;
            self.stats.tri_fetches_a += misses[0] as u64;
            r.resume = r.resume.max(present);
        }
        if self.stop_at.is_some_and(|v| self.tri.when(present) > v) {
            return;
        }
        let (take, res) = self.tri.take(present, ta, tb);
        let v = self.tri.verdict(take);
        self.last_verdict = self.last_verdict.max(v);
        if res.hit || res.uncertain {
            self.results.push((v, ta, tb, res.uncertain));
        }
        if self.first && res.hit && !res.uncertain && self.stop_at.is_none() {
            self.stop_at = Some(v);
        }
    }

    /// Books the compare units' clocks from `from` to `end`: between lists (the Stack
    /// Engine's switch), waiting for what came last (the tumbled pair's d', or the aligned
    /// word), comparing.
    fn book(&mut self, r: &ListRun, from: u64, start: u64, end: u64, present: u64) {
        let s = &mut self.stats;
        let switched = r.t0.max(from).min(start);
        s.stall_list += switched - from;
        let gap = start - switched;
        if r.ready >= present {
            s.stall_transform += gap;
        } else {
            s.stall_memory += gap;
        }
        s.compare += end - start;
    }
}

/// What a tumbled node's list is tested against one level down: its children, or the node
/// alone if it is a leaf (Algorithm 2's overloaded call).
pub fn expand(b: &DopTree, x: u32) -> Vec<u32> {
    match b.node(x) {
        Node::Inner(ch) => ch.to_vec(),
        Node::Leaf(_) => vec![x],
    }
}

/// What an overlap of aligned node `n` with tumbled node `x` appends to x's new list: n's
/// children, or n itself (a leaf against an inner node), or nothing (a leaf pair: the
/// Triangle Unit's).
pub fn appended(a: &DopTree, b: &DopTree, n: u32, x: u32) -> Vec<u32> {
    match (a.node(n), b.node(x)) {
        (Node::Inner(ch), _) => ch.to_vec(),
        (Node::Leaf(_), Node::Inner(_)) => vec![n],
        (Node::Leaf(_), Node::Leaf(_)) => vec![],
    }
}

fn leaf(o: &ObjectImage, x: u32) -> Option<u32> {
    match o.tree.node(x) {
        Node::Leaf(t) => Some(t),
        Node::Inner(_) => None,
    }
}

/// One clock's command to the Stack Engine's lists ([`ListStack`]): `clear` (a new query),
/// or any of `append` (a node pointer onto the left (0) or right (1) list of the next
/// level), `read` (the current list's next pointer, if it has one) and `next_list` (the
/// current list is done; ignored with an append, which would go onto the list it enters);
/// all three are ignored while the lists step up or are done.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ListCmd {
    pub clear: bool,
    pub append: Option<(usize, u16)>,
    pub read: bool,
    pub next_list: bool,
}

/// The lists' outputs after a clock's rising edge: the current list (its level, branch
/// and the pointers not yet read), `busy` while stepping up, `done` when the traversal has
/// no list left, a pointer read the clock before, `overflow` (sticky until `clear`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ListOut {
    pub level: usize,
    pub branch: usize,
    pub remaining: u16,
    pub busy: bool,
    pub done: bool,
    pub rd: Option<u16>,
    pub overflow: bool,
}

/// WSCG'03's Stack Engine's lists (§4.2), clocked register by register as the RTL
/// (`rtl::wscg03::stack_engine::ListStack`): two SRAMs (the left and the right lists), the
/// level register λ, a branch bit per level and marker registers per level and side (a
/// list's start and length). Reads refer to λ (its branch's SRAM), appends to λ + 1, whose
/// lists start where level λ's end (`start[λ+1] = start[λ] + len[λ]`, per side): lists
/// are written contiguously, and the live ones never overlap.
///
/// `next_list` recurses one level down, into the left list if it is not empty, else the right;
/// if both are empty the lists step up (`busy`), one level a clock: at a level whose branch
/// is left and whose right list is not empty, into that right list; at level 0, done.
/// Level 0 is the host's: the root's pointer is appended to level 1, then `next_list`.
pub struct ListStack {
    sram: [Vec<u16>; 2],
    start: [[u16; LIST_LEVELS]; 2],
    len: [[u16; LIST_LEVELS]; 2],
    branch: [bool; LIST_LEVELS],
    level: usize,
    pos: u16,
    up: bool,
    done: bool,
    overflow: bool,
    rd: Option<u16>,
}

use crate::chip::rtl::LIST_LEVELS;

impl ListStack {
    /// After a `clear`, with SRAMs of 2^`sram_bits` pointers (the chip's:
    /// [`LIST_SRAM_BITS`](crate::chip::rtl::LIST_SRAM_BITS)).
    pub fn new(sram_bits: usize) -> Self {
        let cap = 1 << sram_bits;
        ListStack::with(&mut [vec![0; cap], vec![0; cap]])
    }

    /// After a `clear`, with these SRAMs (taken).
    fn with(sram: &mut [Vec<u16>; 2]) -> Self {
        ListStack {
            sram: std::mem::take(sram),
            start: [[0; LIST_LEVELS]; 2],
            len: [[0; LIST_LEVELS]; 2],
            branch: [false; LIST_LEVELS],
            level: 0,
            pos: 0,
            up: false,
            done: false,
            overflow: false,
            rd: None,
        }
    }

    /// One clock: `cmd` before the rising edge, the outputs after it. Every decision reads
    /// the state before the edge, as the RTL's registers do.
    pub fn step(&mut self, cmd: &ListCmd) -> ListOut {
        if cmd.clear {
            *self = ListStack::with(&mut self.sram);
            return self.out();
        }
        let (lv, b) = (self.level, self.branch[self.level] as usize);
        let idle = !self.up && !self.done;
        self.rd = None;
        if cmd.read && idle && self.remaining() > 0 {
            self.rd = Some(self.sram[b][(self.start[b][lv] + self.pos) as usize]);
            self.pos += 1;
        }
        // an append goes after the list of level λ + 1 as it was before the edge
        let append = cmd.append.filter(|_| idle).map(|(s, p)| {
            let at = self.start[s]
                .get(lv + 1)
                .map(|&st| st + self.len[s][lv + 1]);
            (s, p, at.filter(|&a| (a as usize) < self.sram[s].len()))
        });
        if cmd.next_list && idle && cmd.append.is_none() {
            self.descend();
        } else if self.up {
            self.step_up();
        }
        match append {
            Some((s, p, Some(a))) => {
                self.sram[s][a as usize] = p;
                self.len[s][lv + 1] += 1;
            }
            Some((_, _, None)) => self.overflow = true,
            None => {}
        }
        self.out()
    }

    /// Into level λ + 1's left list, else its right one, else step up.
    fn descend(&mut self) {
        let l1 = self.level + 1;
        let side = (0..2).find(|&s| l1 < LIST_LEVELS && self.len[s][l1] > 0);
        match side {
            Some(s) => {
                (self.level, self.branch[l1], self.pos) = (l1, s == 1, 0);
                self.open(l1 + 1);
            }
            None => (self.up, self.pos) = (true, 0),
        }
    }

    /// One level of stepping up: the right list of this level if it is due, else done at
    /// level 0, else the level above.
    fn step_up(&mut self) {
        let j = self.level;
        if !self.branch[j] && self.len[1][j] > 0 {
            (self.branch[j], self.pos, self.up) = (true, 0, false);
            self.open(j + 1);
        } else if j == 0 {
            (self.done, self.up) = (true, false);
        } else {
            self.level = j - 1;
        }
    }

    /// Level `l`'s lists emptied, starting where level l - 1's end.
    fn open(&mut self, l: usize) {
        if l < LIST_LEVELS {
            for s in 0..2 {
                self.start[s][l] = self.start[s][l - 1] + self.len[s][l - 1];
                self.len[s][l] = 0;
            }
        }
    }

    /// Pointers the SRAMs hold: each one's lists up to the next level's end (the lists of
    /// the levels below were freed when the lists stepped up).
    pub fn held(&self) -> u64 {
        let l = (self.level + 1).min(LIST_LEVELS - 1);
        (0..2)
            .map(|s| (self.start[s][l] + self.len[s][l]) as u64)
            .sum()
    }

    /// The current list's pointers not yet read (none while stepping up or done).
    fn remaining(&self) -> u16 {
        let b = self.branch[self.level] as usize;
        match self.up || self.done {
            true => 0,
            false => self.len[b][self.level] - self.pos,
        }
    }

    fn out(&self) -> ListOut {
        ListOut {
            level: self.level,
            branch: self.branch[self.level] as usize,
            remaining: self.remaining(),
            busy: self.up,
            done: self.done,
            rd: self.rd,
            overflow: self.overflow,
        }
    }
}
