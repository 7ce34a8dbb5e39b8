//! WSCG'03's DOP Unit (§4.1, Fig. 5) as the cycle model sees it: two DOTADD units (the left
//! and the right tumbled sibling's pipelines) that transform a tumbled DOP into the
//! dual-port d' memory, one coefficient per clock each, behind `dotadd_stages` stages; the
//! memory's two sets (the current pair's d', the speculatively transformed children of the
//! left parent); and the 16 compare units, which take an aligned DOP from the 256-bit data
//! bus in bundles of eight and test it against both tumbled siblings at once. Overlaps come
//! from the golden model ([`TransformCache`]): the clock adds only when.

use crate::chip::wscg03::StackParams;
use crate::golden::dop_unit::TransformCache;

/// A d' set of the dual-port memory: its tumbled nodes and the clock they are all present.
#[derive(Clone, Debug)]
struct Set {
    nodes: Vec<u32>,
    ready: u64,
}

pub struct DopUnit<'a> {
    values: TransformCache<'a>,
    k: u64,
    stages: u64,
    /// Clocks an aligned word occupies the compare units, and from its last bundle to the flags.
    beats: u64,
    compare_latency: u64,
    /// The first clock each DOTADD unit (left, right) takes a new DOP.
    dotadd_free: [u64; 2],
    cur: Option<Set>,
    spec: Option<Set>,
    compare_free: u64,
    /// Tumbled DOPs transformed (for a list and speculatively), speculative pairs
    /// transformed, and of them used by the list that followed.
    pub transforms: u64,
    pub spec_pairs: u64,
    pub spec_used: u64,
    pub tests: u64,
    pub overlaps: u64,
}

impl<'a> DopUnit<'a> {
    pub fn new(values: TransformCache<'a>, p: &StackParams, node_bits: u32) -> Self {
        DopUnit {
            k: values.k() as u64,
            values,
            stages: p.dotadd_stages as u64,
            beats: node_bits.div_ceil(p.data_bus_bits) as u64,
            compare_latency: p.compare_latency as u64,
            dotadd_free: [0; 2],
            cur: None,
            spec: None,
            compare_free: 0,
            transforms: 0,
            spec_pairs: 0,
            spec_used: 0,
            tests: 0,
            overlaps: 0,
        }
    }

    /// The tumbled nodes whose words are present at the given clocks, one per DOTADD unit:
    /// the clock all their d' are in the dual-port memory.
    fn transform(&mut self, words: &[(u32, u64)]) -> u64 {
        let mut ready = 0;
        for (side, &(_, present)) in words.iter().enumerate() {
            let start = present.max(self.dotadd_free[side]);
            self.dotadd_free[side] = start + self.k;
            ready = ready.max(start + self.k + self.stages);
        }
        self.transforms += words.len() as u64;
        ready
    }

    /// If the d' of `group` are in the memory (the current set, or the speculative one,
    /// which becomes current): the clock they are ready.
    pub fn held(&mut self, group: &[u32]) -> Option<u64> {
        if let Some(c) = self
            .cur
            .as_ref()
            .filter(|c| group.iter().all(|x| c.nodes.contains(x)))
        {
            return Some(c.ready);
        }
        let s = self.spec.take_if(|s| s.nodes == group)?;
        self.spec_used += 1;
        let ready = s.ready;
        self.cur = Some(s);
        Some(ready)
    }

    /// Transforms a list's tumbled group into the current set: the clock it is ready.
    pub fn load(&mut self, words: &[(u32, u64)]) -> u64 {
        let ready = self.transform(words);
        self.cur = Some(Set {
            nodes: words.iter().map(|w| w.0).collect(),
            ready,
        });
        ready
    }

    /// The children pair of the left parent, transformed into the other set while the list runs.
    pub fn speculate(&mut self, words: &[(u32, u64)]) {
        let ready = self.transform(words);
        self.spec_pairs += 1;
        self.spec = Some(Set {
            nodes: words.iter().map(|w| w.0).collect(),
            ready,
        });
    }

    /// Is this pair already speculated?
    pub fn speculated(&self, group: &[u32]) -> bool {
        self.spec.as_ref().is_some_and(|s| s.nodes == group)
    }

    /// An aligned word present from clock `present` against the tumbled pair ready at
    /// `ready`: the clocks it starts and ends on the compare units.
    pub fn compare(&mut self, present: u64, ready: u64) -> (u64, u64) {
        let start = self.start(present, ready);
        self.compare_free = start + self.beats;
        (start, self.compare_free)
    }

    /// The clock [`compare`](Self::compare) would start.
    pub fn start(&self, present: u64, ready: u64) -> u64 {
        present.max(ready).max(self.compare_free)
    }

    /// The clock an aligned DOP compared up to `end` shows its flags at the Stack Engine.
    pub fn flags(&self, end: u64) -> u64 {
        end - 1 + self.compare_latency
    }

    /// Clocks an aligned word takes on the compare units.
    pub fn beats(&self) -> u64 {
        self.beats
    }

    /// The first clock the compare units are free.
    pub fn compare_free(&self) -> u64 {
        self.compare_free
    }

    /// The golden overlap of A's aligned node `n` and B's tumbled node `x`.
    pub fn overlap(&mut self, n: u32, x: u32) -> bool {
        let hit = self.values.overlap(x, n);
        self.tests += 1;
        self.overlaps += hit as u64;
        hit
    }
}
