//! WSCG'03's Triangle Unit (§4.3, Figs. 6, 7) as the cycle model sees it: triangle pairs
//! enter every `tri_interval` clocks at the most (§4.3: 3) and show their verdict
//! `tri_latency` clocks later; its input stage holds A's triangle words in the 128-line
//! cache (`[chip] tri_cache`, [`TriCache`]) and the tumbled pair's in a two-entry SRAM,
//! loaded at a list's first overlapping leaves. Verdicts are the golden TRI_UNIT's (the
//! same T.CHECKs as DATE'05's chip, so the host settles the same uncertain pairs).

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
