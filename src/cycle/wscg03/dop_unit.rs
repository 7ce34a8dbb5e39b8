//! WSCG'03's DOP Unit (§4.1, Fig. 5) as the cycle model sees it: two DOTADD units (the left
//! and the right tumbled sibling's pipelines) that transform a tumbled DOP into the
//! dual-port d' memory, one coefficient per clock each, behind `dotadd_stages` stages; the
//! memory's two sets (the current pair's d', the speculatively transformed children of the
//! left parent); and the 16 compare units, which take an aligned DOP from the 256-bit data
//! bus in bundles of eight and test it against both tumbled siblings at once. Overlaps come
//! from the golden model ([`TransformCache`]): the clock adds only when. The same unit
//! clocked register by register as its RTL is [`ClockedDopUnit`].

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

/// A tumbled DOP's bundle on the bus: distances `8 entry ..` of the `side` (0 left, 1 right)
/// sibling into input register set `set`; `last` completes the set's pair.
#[derive(Clone, Debug, PartialEq)]
pub struct TumbledBundle {
    pub set: usize,
    pub side: usize,
    pub entry: usize,
    pub last: bool,
    pub data: [f64; 8],
}

/// An aligned DOP's bundle: A's distances `8 entry ..` (lanes in `lanes`, a bit each) against
/// d' set `set`; `first` starts a DOP.
#[derive(Clone, Debug, PartialEq)]
pub struct AlignedBundle {
    pub set: usize,
    pub entry: usize,
    pub first: bool,
    pub lanes: u8,
    pub e: [f64; 8],
}

/// The DOP Unit's inputs in one clock (besides the MMM, loaded before).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ClockIn {
    pub t: Option<TumbledBundle>,
    pub a: Option<AlignedBundle>,
}

/// The DOP Unit's outputs after a clock's rising edge: the sets' busy bits, each sibling's
/// verdict so far, and whether a bundle's verdicts came out.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClockOut {
    pub busy: [bool; 2],
    pub overlap: [bool; 2],
    pub flags_valid: bool,
}

/// A d' pair on its way through the DOTADD units: its set, lane, the set's last, the left
/// and right sibling's d'.
#[derive(Clone, Copy, Debug)]
struct Write {
    set: usize,
    lane: usize,
    last: bool,
    d: [f64; 2],
}

/// An aligned bundle beside the d' it meets (left, right), read from the d' memory.
#[derive(Clone, Copy, Debug)]
struct Beside {
    first: bool,
    lanes: u8,
    e: [f64; 8],
    d: [[f64; 8]; 2],
}

/// WSCG'03's DOP Unit clocked register by register, as the RTL (`rtl::b32::Wscg03DopUnit`)
/// is: the input register sets, the address generator (`gen_*`, `pend`), the DOTADD units'
/// pipeline, the d' memory and the compare bank's two stages. Values are the golden
/// functions' ([`transformed`](crate::golden::doptrf::transformed),
/// [`separated`](crate::golden::doptrf::separated)); the tests hold it equal to the RTL on
/// every port every clock.
pub struct ClockedDopUnit<'a> {
    fmt: crate::format::Format,
    rounding: crate::format::Rounding,
    setup: &'a crate::golden::host::HostSetup,
    k: usize,
    /// `[set][side][distance]`.
    tin: [[Vec<f64>; 2]; 2],
    gen_run: bool,
    gen_cnt: usize,
    gen_set: usize,
    pend: [bool; 2],
    busy: [bool; 2],
    /// The direction at the DOTADD units' inputs: set, lane, the set's last.
    s1: Option<(usize, usize, bool)>,
    /// The DOTADD units' stages, the output first.
    dotadd: std::collections::VecDeque<Option<Write>>,
    /// `[set][side][lane]`.
    dprime: [[Vec<f64>; 2]; 2],
    /// The bundle beside its d'.
    sa: Option<Beside>,
    /// The compare units' register: first, lanes, the flags per sibling.
    bank1: Option<(bool, u8, [[bool; 8]; 2])>,
    sep: [bool; 2],
    flags_valid: bool,
}

impl<'a> ClockedDopUnit<'a> {
    /// After reset, its MMM holding `setup`'s C, c and selects, every lane rounding `r`.
    pub fn new(
        fmt: crate::format::Format,
        rounding: crate::format::Rounding,
        setup: &'a crate::golden::host::HostSetup,
    ) -> Self {
        let k = setup.j.len();
        let zeros = || [vec![0.0; k], vec![0.0; k]];
        ClockedDopUnit {
            fmt,
            rounding,
            setup,
            k,
            tin: [zeros(), zeros()],
            gen_run: false,
            gen_cnt: 0,
            gen_set: 0,
            pend: [false; 2],
            busy: [false; 2],
            s1: None,
            dotadd: vec![None; crate::chip::rtl::DOTADD_LATENCY].into(),
            dprime: [zeros(), zeros()],
            sa: None,
            bank1: None,
            sep: [false; 2],
            flags_valid: false,
        }
    }

    /// One clock: `inp` before the rising edge; the outputs after it. An aligned bundle
    /// against a busy set would meet d' of two pairs (the RTL does not check): a panic.
    pub fn step(&mut self, inp: &ClockIn) -> ClockOut {
        if let Some(a) = &inp.a {
            assert!(
                !self.busy[a.set],
                "an aligned bundle against busy d' set {}",
                a.set
            );
        }
        let written = self.dotadd.pop_front().flatten();
        let entering = self.s1.map(|(set, lane, last)| Write {
            set,
            lane,
            last,
            d: [0, 1].map(|side| self.dprime_of(set, side, lane)),
        });
        self.dotadd.push_back(entering);
        self.compare(inp.a.as_ref());
        self.generate(inp.t.as_ref());
        if let Some(t) = &inp.t {
            let regs = &mut self.tin[t.set][t.side];
            for (g, &x) in (8 * t.entry..regs.len()).zip(&t.data) {
                regs[g] = x;
            }
        }
        if let Some(w) = written {
            for side in 0..2 {
                self.dprime[w.set][side][w.lane] = w.d[side];
            }
            self.busy[w.set] &= !w.last;
        }
        if let Some(t) = &inp.t {
            self.busy[t.set] = true;
        }
        ClockOut {
            busy: self.busy,
            overlap: self.sep.map(|s| !s),
            flags_valid: self.flags_valid,
        }
    }

    /// d'_lane of a sibling of an input register set: D.KLMSEL and the DOTADD unit.
    fn dprime_of(&self, set: usize, side: usize, lane: usize) -> f64 {
        let d = &self.tin[set][side];
        crate::golden::dop_unit::dprime(self.fmt, self.rounding, self.setup, d, lane)
    }

    /// The address generator at the edge: the pending set (set 0 first) or the pair
    /// completed by `t`, when the last row of the one before is read.
    fn generate(&mut self, t: Option<&TumbledBundle>) {
        let row_last = self.gen_run && self.gen_cnt == self.k - 1;
        let completed = t.filter(|t| t.last).map(|t| t.set);
        let go = (!self.gen_run || row_last) && (self.pend.contains(&true) || completed.is_some());
        let go_set = match self.pend {
            [true, _] => 0,
            [false, true] => 1,
            _ => completed.unwrap_or(0),
        };
        self.s1 = self
            .gen_run
            .then_some((self.gen_set, self.gen_cnt, row_last));
        if let Some(s) = completed {
            self.pend[s] = true;
        }
        self.gen_cnt = if self.gen_run && !row_last {
            self.gen_cnt + 1
        } else {
            0
        };
        self.gen_run &= !row_last;
        if go {
            self.pend[go_set] = false;
            (self.gen_run, self.gen_set) = (true, go_set);
        }
    }

    /// The compare side at the edge: the bundle reads its d' (the memory before this edge's
    /// write), the compare units flag, the verdicts so far.
    fn compare(&mut self, a: Option<&AlignedBundle>) {
        let q = self.fmt.min_positive_subnormal();
        if let Some((first, lanes, flags)) = self.bank1 {
            for (sep, f) in self.sep.iter_mut().zip(flags) {
                let any = (0..8).any(|t| f[t] && lanes >> t & 1 == 1);
                *sep = any || (*sep && !first);
            }
        }
        self.flags_valid = self.bank1.is_some();
        self.bank1 = self.sa.map(|Beside { first, lanes, e, d }| {
            let flags =
                d.map(|d| std::array::from_fn(|t| crate::golden::doptrf::separated(q, d[t], e[t])));
            (first, lanes, flags)
        });
        self.sa = a.map(|a| Beside {
            first: a.first,
            lanes: a.lanes,
            e: a.e,
            d: [0, 1].map(|side| self.entry(a.set, side, a.entry)),
        });
    }

    /// Entry `entry` of a set's side: slot t holds d'_opp(8 entry + t) (0 past k).
    fn entry(&self, set: usize, side: usize, entry: usize) -> [f64; 8] {
        std::array::from_fn(|t| {
            let g = 8 * entry + t;
            if g < self.k {
                self.dprime[set][side][crate::golden::klmsel::opposite_lane(self.k, g)]
            } else {
                0.0
            }
        })
    }
}
