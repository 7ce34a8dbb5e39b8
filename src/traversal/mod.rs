//! Traversals of the two DOP trees. All of them test exactly the same set of node pairs
//! in all-pairs mode (an overlapping inner/inner pair leads to its four child pairs, an
//! inner/leaf pair to two), only in different orders, so they return the same pairs:
//! - [`recursive`]: the classic simultaneous recursion (WSCG'03 Algorithm 1), software baseline;
//! - [`list`]: the list-based scheme that transforms each tumbled node once (WSCG'03 Algorithm 2);
//! - DATE'05's D_CNTR ([`golden::d_cntr`](crate::golden::d_cntr)), a FIFO or LIFO of node
//!   pairs pushed and popped pairwise in the order that shares one DOP between consecutive
//!   tests.
//!
//! Object A is aligned (its DOPs are the e of Eq. 10), object B tumbled (its DOPs are the d).
//! Leaf/leaf pairs are DOP-tested before the triangle test (the leaf DOP is in the node word
//! anyway and filters most triangle tests at one DOP test per cycle).

pub mod list;
pub mod recursive;

use crate::chip::config::ChipConfig;
use crate::chip::layout::{Layout, Pair};
use crate::chip::reg::{Mode, Order};
use crate::dop::tree::Tri;
use crate::dop::Node;
use crate::golden::host::{DopLanes, HostSetup};
use crate::golden::memory::{Held, NodeCache, ObjectImage, TriCache, TriWord};
use crate::golden::{d_cntr, dop_unit, tri_unit};
use crate::oracle;
use nalgebra::{Matrix3, Vector3};
use serde::{Deserialize, Serialize};
use std::cell::Cell;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum Traversal {
    /// WSCG'03 Algorithm 1: simultaneous recursion, every test transforms the tumbled DOP.
    Recursive,
    /// WSCG'03 Algorithm 2: one tumbled node against a list of aligned nodes.
    List,
    /// DATE'05 D_CNTR with a FIFO (breadth first).
    Fifo,
    /// DATE'05 D_CNTR with a LIFO (depth first).
    Lifo,
}

impl Traversal {
    pub const ALL: [Traversal; 4] = [
        Traversal::Recursive,
        Traversal::List,
        Traversal::Fifo,
        Traversal::Lifo,
    ];

    /// The name scenes and the CLI use (`recursive`, `list`, `fifo`, `lifo`).
    pub fn name(self) -> &'static str {
        match self {
            Traversal::Recursive => "recursive",
            Traversal::List => "list",
            Traversal::Fifo => "fifo",
            Traversal::Lifo => "lifo",
        }
    }

    /// D_CNTR's order, for the traversals the chip runs.
    pub fn order(self) -> Option<Order> {
        match self {
            Traversal::Fifo => Some(Order::Fifo),
            Traversal::Lifo => Some(Order::Lifo),
            Traversal::Recursive | Traversal::List => None,
        }
    }
}

/// What one query did, in the units the hardware pays for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Counters {
    pub dop_tests: u64,
    pub dop_overlaps: u64,
    /// DOP transforms of the tumbled object (DATE'05 fuses one into every DOP test).
    pub dop_transforms: u64,
    /// Node records fetched (a node word or, `[chip] layout = "records"`, a sibling pair;
    /// a record held for the DOP unit, per object, is not fetched again: the previous pair's,
    /// or one of `ChipConfig::node_cache`'s lines). The lookups that hit are the other
    /// `2 * dop_tests - node_fetches`.
    pub node_fetches: u64,
    pub tri_tests: u64,
    /// Triangle words fetched (same holding rule as nodes; A's through the triangle cache,
    /// `ChipConfig::tri_cache`).
    pub tri_fetches: u64,
    /// A's triangle words fetched: the triangle cache's misses (of `tri_tests` uses).
    #[serde(default)]
    pub tri_fetches_a: u64,
    pub tri_hits: u64,
    /// Triangle pairs T.CHECK could not decide within its error bounds (or with a
    /// degenerate triangle), settled by the host with the exact oracle.
    pub uncertain: u64,
    /// Largest number of node pairs (or list entries) waiting in the queue, stack or lists.
    pub max_queue_depth: u64,
    pub memory_bytes: u64,
    /// WSCG'03 Eq. 5's tau and sum of alpha (list traversal only): lists processed, and
    /// their aligned node pairs (two sibling nodes each, as the memory stores them).
    pub lists: u64,
    pub list_node_pairs: u64,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct QueryResult {
    /// (triangle of A, triangle of B), sorted: the chip's sure hits and the uncertain
    /// pairs the host found intersecting.
    pub pairs: Vec<(u32, u32)>,
    /// The pairs the chip flagged uncertain (whatever the host then found), sorted.
    pub uncertain: Vec<(u32, u32)>,
    pub counters: Counters,
}

/// What the host needs to settle uncertain pairs: both objects' f64 triangles and the
/// pose that places B in A's frame (the oracle's geometry).
pub struct Host<'a> {
    pub a: &'a [Tri],
    pub b: &'a [Tri],
    pub rot: Matrix3<f64>,
    pub t: Vector3<f64>,
}

impl Host<'_> {
    /// Whether triangle `ta` of A and `tb` of B intersect: the exact oracle on the f64
    /// geometry (DATE'05 §4.2: the host decides what TRI_UNIT cannot).
    pub fn settle(&self, ta: u32, tb: u32) -> bool {
        let (r, t) = (&self.rot, &self.t);
        oracle::tri_tri(
            &self.a[ta as usize],
            &self.b[tb as usize].map(|p| r * p + t),
        )
    }
}

/// The state a traversal drives: the two images, the per-pose setup, the DOP unit and
/// TRI_UNIT as golden functions, the held words and the counters.
pub(crate) struct Engine<'a> {
    a: &'a ObjectImage,
    b: &'a ObjectImage,
    layout: Layout,
    mode: Mode,
    held_node: [NodeCache; 2],
    /// A's and B's triangle words held (their triangle caches).
    held_tri: [TriCache; 2],
    /// A's and B's triangle words last made (software only: a word is made from the f64
    /// triangle when read, and a leaf meets several of the other object's in a row), kept
    /// for the thread's next query of the same objects.
    words: [Held<TriWord>; 2],
    host: &'a Host<'a>,
    pairs: Vec<(u32, u32)>,
    uncertain: Vec<(u32, u32)>,
    live: u64,
    dop_unit: dop_unit::TransformCache<'a>,
    /// TRI_UNIT, made at the first leaf pair (a query that ends among inner nodes, at the
    /// root say, does not pay for its tables and constants), with what it is made from.
    tri_unit: Option<tri_unit::TriUnit<'a>>,
    tri_setup: (&'a ChipConfig, &'a HostSetup),
    pub(crate) counters: Counters,
    pub(crate) stop: bool,
}

impl<'a> Engine<'a> {
    fn node_a(&self, n: u32) -> Node {
        self.a.tree.node(n)
    }

    fn node_b(&self, n: u32) -> Node {
        self.b.tree.node(n)
    }

    /// One DOP test of A's node `na` against B's node `nb`. B's transformed distances are
    /// computed on first use and kept for the query (the recursive traversal recomputes them
    /// at every test, as WSCG'03 Algorithm 1 does): the same values the lane computes (the
    /// `dop_transforms` counter still counts what the hardware does).
    fn dop_test(&mut self, na: u32, nb: u32) -> bool {
        let c = &mut self.counters;
        c.dop_tests += 1;
        c.node_fetches += self.held_node[0].fetch(self.a.record(na)) as u64
            + self.held_node[1].fetch(self.b.record(nb)) as u64;
        let hit = self.dop_unit.overlap(nb, na);
        c.dop_overlaps += hit as u64;
        hit
    }

    /// TRI_UNIT on a leaf pair; the host settles an uncertain one; records the pair and
    /// stops a first-hit query.
    fn leaf_pair(&mut self, ta: u32, tb: u32) {
        let c = &mut self.counters;
        c.tri_tests += 1;
        let fetch_a = self.held_tri[0].fetch(self.a.tri_record(ta)) as u64;
        c.tri_fetches_a += fetch_a;
        c.tri_fetches += fetch_a + self.held_tri[1].fetch(self.b.tri_record(tb)) as u64;
        let (a, b, [words_a, words_b]) = (self.a, self.b, &mut self.words);
        let (cfg, setup) = self.tri_setup;
        let tri_unit = self.tri_unit.get_or_insert_with(|| {
            tri_unit::TriUnit::new(
                cfg.format.tri,
                cfg.tri_rounding,
                setup,
                a.tri_count(),
                b.tri_count(),
            )
        });
        let res = tri_unit.test(
            ta,
            words_a.get(ta, || a.tri(ta)),
            tb,
            words_b.get(tb, || b.tri(tb)),
        );
        let hit = if res.uncertain {
            self.counters.uncertain += 1;
            self.uncertain.push((ta, tb));
            self.host.settle(ta, tb)
        } else {
            res.hit
        };
        if hit {
            self.counters.tri_hits += 1;
            self.pairs.push((ta, tb));
            self.stop = self.mode == Mode::First;
        }
    }

    /// Prefetches the DOP unit's reads for the child pairs of the overlapping pair `p` of
    /// nodes `na`, `nb` (software only: they are tested soon).
    fn prefetch_children(&self, p: Pair, na: Node, nb: Node) {
        let kids = |n: Node, own: u32| if let Node::Inner(c) = n { c } else { [own; 2] };
        let (ca, cb) = (kids(na, p.a), kids(nb, p.b));
        ca.into_iter().for_each(|a| self.dop_unit.prefetch_a(a));
        cb.into_iter().for_each(|b| self.dop_unit.prefetch_b(b));
    }

    /// Bookkeeping of waiting pairs (queue, stack or lists).
    fn queue_add(&mut self, n: u64) {
        self.live += n;
        self.counters.max_queue_depth = self.counters.max_queue_depth.max(self.live);
    }

    fn queue_remove(&mut self, n: u64) {
        self.live -= n;
    }
}

/// Runs one query on the golden model: `setup` holds TRI_UNIT's part of the host setup
/// ([`HostSetup::frames`]), and the DOP unit computes its lanes from `lanes` when it needs them.
pub fn run(
    cfg: &ChipConfig,
    a: &ObjectImage,
    b: &ObjectImage,
    setup: &HostSetup,
    lanes: DopLanes,
    host: &Host,
    mode: Mode,
    traversal: Traversal,
) -> QueryResult {
    let [words_a, words_b] = spare_words(a, b);
    let mut e = Engine {
        a,
        b,
        layout: Layout::new(cfg),
        mode,
        held_node: [
            NodeCache::new(cfg.node_cache),
            NodeCache::new(cfg.node_cache),
        ],
        held_tri: [TriCache::new(cfg.tri_cache), TriCache::new(cfg.tri_cache_b)],
        words: [words_a, words_b],
        host,
        pairs: vec![],
        uncertain: vec![],
        live: 0,
        dop_unit: dop_unit::TransformCache::lazy(
            cfg.format.dop,
            cfg.dop_rounding.op(),
            setup,
            lanes,
            &a.tree,
            &b.tree,
        ),
        tri_unit: None,
        tri_setup: (cfg, setup),
        counters: Counters::default(),
        stop: false,
    };
    if traversal == Traversal::Recursive {
        e.dop_unit.forget_rows();
    }
    match traversal {
        Traversal::Recursive => recursive::run(&mut e),
        Traversal::List => list::run(&mut e),
        Traversal::Fifo => run_d_cntr(&mut e, Order::Fifo),
        Traversal::Lifo => run_d_cntr(&mut e, Order::Lifo),
    }
    keep_words(e.words);
    let mut c = e.counters;
    let [node_bytes, tri_bytes] = e.layout.record_bytes();
    c.memory_bytes = c.node_fetches * node_bytes + c.tri_fetches * tri_bytes;
    let (mut pairs, mut uncertain) = (e.pairs, e.uncertain);
    pairs.sort_unstable();
    uncertain.sort_unstable();
    QueryResult {
        pairs,
        uncertain,
        counters: c,
    }
}

thread_local! {
    /// [`Engine::words`]' lines, kept for the thread's next query.
    static SPARE_WORDS: Cell<[Held<TriWord>; 2]> = Cell::default();
}

/// The thread's triangle-word lines for a query of `a` against `b`, A's and B's: what the
/// thread's query before made of these objects is held. The golden traversal and the cycle
/// model's TRI_UNIT take them, and give them back with [`keep_words`] (made anew per chip,
/// they were two thirds of the cycle model's time on a 447-clock query: `cycle_loop
/// sphere_fifo_first 2000`, 2.1M clocks/s before, 6.1-6.6M after).
pub fn spare_words(a: &ObjectImage, b: &ObjectImage) -> [Held<TriWord>; 2] {
    let [wa, wb] = SPARE_WORDS.take();
    [wa.of(a.tree.id()), wb.of(b.tree.id())]
}

/// Keeps the lines of [`spare_words`] for the thread's next query.
pub fn keep_words(words: [Held<TriWord>; 2]) {
    SPARE_WORDS.set(words);
}

/// DATE'05's traversal: every pair of D_CNTR's queue DOP-tested in turn, a leaf pair's
/// triangles tested, the child entries of an overlapping pair pushed.
fn run_d_cntr(e: &mut Engine, order: Order) {
    let mut q = d_cntr::Queue::new(order);
    e.queue_add(1);
    while let Some(ent) = q.pop() {
        e.queue_remove(ent.len as u64);
        for &p in &ent.pairs[..ent.len as usize] {
            if e.stop {
                return;
            }
            e.counters.dop_transforms += 1; // DOPTRF transforms within every test
            if !e.dop_test(p.a, p.b) {
                continue;
            }
            let (na, nb) = (e.node_a(p.a), e.node_b(p.b));
            if let (Node::Leaf(ta), Node::Leaf(tb)) = (na, nb) {
                e.leaf_pair(ta, tb);
                continue;
            }
            let n = q.push_children(p, na, nb);
            e.queue_add(2 * n as u64);
            e.prefetch_children(p, na, nb);
        }
    }
}
