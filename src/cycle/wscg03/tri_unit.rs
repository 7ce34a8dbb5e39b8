//! WSCG'03's Triangle Unit (§4.3, Figs. 6, 7) as the cycle model sees it: triangle pairs
//! enter every `tri_interval` clocks at the most (§4.3: 3) and show their verdict
//! `tri_latency` clocks later; its input stage holds A's triangle words in the 128-line
//! cache (`[chip] tri_cache`, [`TriCache`]) and the tumbled pair's in a two-entry SRAM,
//! loaded at a list's first overlapping leaves. Verdicts are the golden TRI_UNIT's (the
//! same T.CHECKs as DATE'05's chip, so the host settles the same uncertain pairs).
//! [`ClockedTriInput`] is the input stage clocked register by register as the RTL builds
//! it; the event model does not use it yet.

use crate::chip::wscg03::StackParams;
use crate::golden::memory::{ObjectImage, TriCache};
use crate::golden::tri_unit::{TriResult, TriUnit as Values};

pub struct TriUnit<'a> {
    a: &'a ObjectImage,
    b: &'a ObjectImage,
    values: Values<'a>,
    interval: u64,
    latency: u64,
    /// A's cache; B's two-entry SRAM (the tumbled pair's leaves).
    held_a: TriCache,
    held_b: Vec<u32>,
    next_take: u64,
    pub tests: u64,
}

impl<'a> TriUnit<'a> {
    pub fn new(
        a: &'a ObjectImage,
        b: &'a ObjectImage,
        values: Values<'a>,
        p: &StackParams,
        cache_lines: u32,
    ) -> Self {
        TriUnit {
            a,
            b,
            values,
            interval: p.tri_interval as u64,
            latency: p.tri_latency as u64,
            held_a: TriCache::new(cache_lines),
            held_b: vec![],
            next_take: 0,
            tests: 0,
        }
    }

    /// A new list: B's SRAM keeps only the words of this tumbled group's leaves.
    pub fn new_group(&mut self, leaves: &[u32]) {
        self.held_b.retain(|t| leaves.contains(t));
    }

    /// Which of the pair's words must come from memory (A's, B's); they are held from now on.
    pub fn misses(&mut self, ta: u32, tb: u32) -> [bool; 2] {
        let miss_b = !self.held_b.contains(&tb);
        if miss_b {
            self.held_b.push(tb);
        }
        [self.held_a.fetch(ta), miss_b]
    }

    /// The pair `(ta, tb)`, its words present from clock `present`: the clock it enters
    /// and its verdict.
    pub fn take(&mut self, present: u64, ta: u32, tb: u32) -> (u64, TriResult) {
        let t = self.when(present);
        self.next_take = t + self.interval;
        self.tests += 1;
        (
            t,
            self.values.test(ta, &self.a.tri(ta), tb, &self.b.tri(tb)),
        )
    }

    /// The clock a pair whose words are present from `present` would enter.
    pub fn when(&self, present: u64) -> u64 {
        present.max(self.next_take)
    }

    /// The clock a pair taken at `t` shows its verdict.
    pub fn verdict(&self, t: u64) -> u64 {
        t + self.latency
    }
}

/// A leaf pair offered to the Triangle Unit's input stage: the ids of A's and B's triangle
/// words, the tag the host sees, B's side in the tumbled pair (the entry its word fills).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LeafPair {
    pub ids: [u16; 2],
    pub tag: u32,
    pub side: usize,
}

/// One clock's inputs to [`ClockedTriInput`]: `clear`, A's cache lines less one (`mask`),
/// `halt`, a leaf pair offered, a triangle word arriving (`(b, id)`: B's if `b`), TRI_UNIT's
/// `in_ready`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TriInputIn {
    pub clear: bool,
    pub mask: u8,
    pub halt: bool,
    pub leaf: Option<LeafPair>,
    pub fill: Option<(bool, u16)>,
    pub tri_ready: bool,
}

/// [`ClockedTriInput`]'s outputs in a clock (before its rising edge): whether a leaf pair
/// is taken, which words the leaf pair lacks and its ids, the pair register (its words
/// named by their ids: `None`, never loaded, is all zeros), `busy`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TriInputOut {
    pub leaf_ready: bool,
    pub need: [bool; 2],
    pub ids: [u16; 2],
    pub pair_valid: bool,
    pub pair_tag: u32,
    pub words: [Option<u16>; 2],
    pub busy: bool,
}

/// WSCG'03's Triangle Unit's input stage (§4.3), clocked register by register as the RTL
/// (`rtl::b32::TriInput`): the leaf register, A's direct-mapped triangle cache (line `id &
/// mask`, tagged with the id; as the RTL's `TriCache`, a hit is the line's valid bit now and
/// the id read from the line at the last edge, under the last clock's mask), B's two entries
/// (filled at the leaf's side, either matches),
/// the pair register TRI_UNIT reads. The words are named by their ids: a word in memory is a
/// function of its id. The outputs are the RTL's in the same clock (some read `halt` and
/// `tri_ready`), then [`step`](Self::step) clocks the edge.
pub struct ClockedTriInput {
    /// A's cache: each line's valid bit and id (a start clears the valid bits only).
    lines: Vec<(bool, u16)>,
    /// The mask of the last clock, with which the RTL read the line it compares now.
    mask_q: u8,
    b: [(bool, u16); 2],
    leaf_v: bool,
    leaf: LeafPair,
    pair_v: bool,
    pair_tag: u32,
    pair_words: [Option<u16>; 2],
}

impl Default for ClockedTriInput {
    fn default() -> Self {
        ClockedTriInput {
            lines: vec![(false, 0); crate::chip::rtl::TRI_CACHE_LINES],
            mask_q: 0,
            b: [(false, 0); 2],
            leaf_v: false,
            leaf: LeafPair::default(),
            pair_v: false,
            pair_tag: 0,
            pair_words: [None; 2],
        }
    }
}

/// A's cache line of word `id` under `mask`.
fn line(id: u16, mask: u8) -> usize {
    (id & mask as u16 & 0x7f) as usize
}

impl ClockedTriInput {
    /// A leaf pair or a pair held (`busy`).
    pub fn busy(&self) -> bool {
        self.leaf_v || self.pair_v
    }

    /// The leaf pair's triangle words held: A's (in its cache, under `mask`) and B's.
    fn held(&self, mask: u8) -> [bool; 2] {
        let [ta, tb] = self.leaf.ids;
        // the valid bit of ta's line now, the id read from its line at the last edge
        let hit_a = self.lines[line(ta, mask)].0 && self.lines[line(ta, self.mask_q)].1 == ta;
        [hit_a, self.b.iter().any(|&(ok, id)| ok && id == tb)]
    }

    /// The words the leaf pair lacks and their ids (the outputs `need`, `ids`): a function
    /// of the registers, `halt` and `mask`.
    pub fn need(&self, halt: bool, mask: u8) -> ([bool; 2], [u16; 2]) {
        let live = self.leaf_v && !halt;
        let held = self.held(mask);
        ([live && !held[0], live && !held[1]], self.leaf.ids)
    }

    /// One clock: the outputs under `i`, then the rising edge.
    pub fn step(&mut self, i: &TriInputIn) -> TriInputOut {
        let [ta, tb] = self.leaf.ids;
        let live = self.leaf_v && !i.halt;
        let held = self.held(i.mask) == [true, true];
        let go = live && held && (!self.pair_v || i.tri_ready);
        let leaf_ready = !i.halt && (!self.leaf_v || go);
        let (need, ids) = self.need(i.halt, i.mask);
        let out = TriInputOut {
            leaf_ready,
            need,
            ids,
            pair_valid: self.pair_v && !i.halt,
            pair_tag: self.pair_tag,
            words: self.pair_words,
            busy: self.leaf_v || self.pair_v,
        };
        match i.fill {
            Some((false, id)) => self.lines[line(id, i.mask)] = (true, id),
            Some((true, id)) => self.b[self.leaf.side] = (true, id),
            None => {}
        }
        self.pair_v &= !i.tri_ready;
        if go {
            self.leaf_v = false;
            (self.pair_v, self.pair_tag, self.pair_words) =
                (true, self.leaf.tag, [Some(ta), Some(tb)]);
        }
        if let Some(l) = i.leaf.filter(|_| leaf_ready) {
            (self.leaf_v, self.leaf) = (true, l);
        }
        if i.halt || i.clear {
            (self.leaf_v, self.pair_v) = (false, false);
        }
        self.mask_q = i.mask;
        if i.clear {
            self.lines.iter_mut().for_each(|l| l.0 = false);
            self.b.iter_mut().for_each(|e| e.0 = false);
        }
        out
    }
}
