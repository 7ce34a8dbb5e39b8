//! D_CNTR's pair queue in RTL (`collision_chip::rtl::d_cntr::PairQueue`) against the golden
//! cycle model `cycle::d_cntr::QueueModel`: every output after every clock, bit for bit.
//!
//! * proptest-generated operation sequences (phases of push-heavy, pop-heavy, balanced and
//!   push+pop mixes, a third of the pushes with a second entry on the second write port,
//!   fills past full and drains, clears while not empty, both orders) with 2^3 entries (many
//!   overflows) and 2^8 entries (long fills to overflow);
//! * the coverage of those sequences: overflow, full, push+pop on one entry and on a full
//!   queue, clear while not empty, two pushes with and without a pop and with the second
//!   lost to a full queue, in both orders;
//! * directed, hand-derived: two pushes a clock in both orders;
//! * wrong models are caught: LIFO treated as FIFO, half the capacity;
//! * directed: push and pop on a one-entry LIFO, a pop on an empty queue is ignored;
//! * the traversal order: the entries `golden::d_cntr::children` makes for the paper's
//!   example tree, pushed into and popped from the RTL queue, give the paper's FIFO
//!   sequence, and in LIFO order the golden depth-first sequence.
//!
//! Outputs are also checked to be functions of registers only: after the next cycle's
//! inputs are applied, before the rising edge, they still show the state after the last edge.

use collision_chip::chip::layout::{pack, unpack, Entry, Pair, ENTRY_BITS};
use collision_chip::chip::reg::Order;
use collision_chip::cycle::d_cntr::{QueueIn, QueueModel, QueueOut};
use collision_chip::dop::Node;
use collision_chip::golden::d_cntr::{children, Queue};
use collision_chip::rtl::d_cntr::{pair_queue_top, PairQueue};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, TestRunner};
use rust_hdl::prelude::*;

mod common;
use common::settle;

const MASK: u128 = (1 << ENTRY_BITS) - 1;

/// The queue under test and its driver: one `cycle` per clock.
struct Dut<const N: usize, const NP1: usize, const NM1: usize> {
    uut: PairQueue<N, NP1, NM1>,
    last: QueueOut,
}

impl<const N: usize, const NP1: usize, const NM1: usize> Dut<N, NP1, NM1> {
    fn new() -> Self {
        let mut uut = pair_queue_top::<N, NP1, NM1>();
        uut.clock.next = Clock { clk: true };
        settle(&mut uut);
        let last = uut.outputs();
        Dut { uut, last }
    }

    /// Applies `i` (clock high, then low: the outputs must not move), then the rising
    /// edge; returns the outputs after it.
    fn cycle(&mut self, i: &QueueIn) -> QueueOut {
        self.uut.set_inputs(i);
        settle(&mut self.uut);
        assert_eq!(
            self.uut.outputs(),
            self.last,
            "outputs moved with the inputs, before the edge: {i:?}"
        );
        self.uut.clock.next = Clock { clk: false };
        settle(&mut self.uut);
        assert_eq!(
            self.uut.outputs(),
            self.last,
            "outputs moved at the falling edge: {i:?}"
        );
        self.uut.clock.next = Clock { clk: true };
        settle(&mut self.uut);
        self.last = self.uut.outputs();
        self.last
    }
}

/// What a run exercised, per order (index 0 FIFO, 1 LIFO).
#[derive(Default, Debug, Clone, Copy)]
struct Coverage {
    clocks: usize,
    overflows: [usize; 2],
    full: [usize; 2],
    push_pop_one: [usize; 2],
    push_pop_full: [usize; 2],
    push_pop_many: [usize; 2],
    pops_to_empty: [usize; 2],
    clear_nonempty: [usize; 2],
    /// Two pushes in a clock: without a pop, with one, the second overflowing.
    two: [usize; 2],
    two_pop: [usize; 2],
    two_second_lost: [usize; 2],
}

impl Coverage {
    fn add(&mut self, o: &Coverage) {
        self.clocks += o.clocks;
        for k in 0..2 {
            self.overflows[k] += o.overflows[k];
            self.full[k] += o.full[k];
            self.push_pop_one[k] += o.push_pop_one[k];
            self.push_pop_full[k] += o.push_pop_full[k];
            self.push_pop_many[k] += o.push_pop_many[k];
            self.pops_to_empty[k] += o.pops_to_empty[k];
            self.clear_nonempty[k] += o.clear_nonempty[k];
            self.two[k] += o.two[k];
            self.two_pop[k] += o.two_pop[k];
            self.two_second_lost[k] += o.two_second_lost[k];
        }
    }

    fn all_hit(&self) -> bool {
        (0..2).all(|k| {
            [
                self.overflows[k],
                self.full[k],
                self.push_pop_one[k],
                self.push_pop_full[k],
                self.push_pop_many[k],
                self.pops_to_empty[k],
                self.clear_nonempty[k],
                self.two[k],
                self.two_pop[k],
                self.two_second_lost[k],
            ]
            .iter()
            .all(|&n| n > 0)
        })
    }
}

/// Runs `ops` through a fresh RTL queue of 2^N entries and through `model` (one call per
/// clock, returning its outputs after the edge); the first clock whose outputs differ is
/// an error. Unless `pop_on_empty`, asserts that no op pops an empty queue.
fn compare<const N: usize, const NP1: usize, const NM1: usize>(
    ops: &[QueueIn],
    mut model: impl FnMut(&QueueIn) -> QueueOut,
    pop_on_empty: bool,
) -> Result<Coverage, String> {
    let mut dut = Dut::<N, NP1, NM1>::new();
    let mut cov = Coverage::default();
    let cap = 1u32 << N;
    let mut lifo = 0;
    for (t, i) in ops.iter().enumerate() {
        let before = dut.last;
        if !pop_on_empty {
            assert!(
                !(i.pop && !i.clear && before.empty),
                "clock {t}: the testbench pops an empty queue"
            );
        }
        let got = dut.cycle(i);
        let want = model(i);
        if got != want {
            return Err(format!("clock {t}: inputs {i:x?}\n  before {before:x?}\n  golden {want:x?}\n  rtl    {got:x?}"));
        }
        cov.clocks += 1;
        if i.clear {
            cov.clear_nonempty[lifo] += !before.empty as usize;
            lifo = (i.order == Order::Lifo) as usize;
            continue;
        }
        cov.overflows[lifo] += (got.overflow && !before.overflow) as usize;
        cov.full[lifo] += (got.full && !before.full) as usize;
        if i.push && i.pop {
            cov.push_pop_one[lifo] += (before.count == 1) as usize;
            cov.push_pop_full[lifo] += (before.count == cap) as usize;
            cov.push_pop_many[lifo] += (before.count > 1 && before.count < cap) as usize;
        }
        cov.pops_to_empty[lifo] += (i.pop && !i.push && before.count == 1) as usize;
        if i.push && i.push2.is_some() {
            let after_pop = before.count - (i.pop && before.count > 0) as u32;
            cov.two[lifo] += (!i.pop && before.count > 0 && after_pop + 2 <= cap) as usize;
            cov.two_pop[lifo] += (i.pop && before.count > 1 && after_pop + 2 <= cap) as usize;
            cov.two_second_lost[lifo] += (after_pop + 1 == cap) as usize;
        }
    }
    Ok(cov)
}

/// [`compare`] against the golden model.
fn check<const N: usize, const NP1: usize, const NM1: usize>(
    ops: &[QueueIn],
) -> Result<Coverage, String> {
    let mut m = QueueModel::new(N as u32);
    compare::<N, NP1, NM1>(ops, |i| m.step(i), false)
}

// ---- generated sequences -------------------------------------------------------------

fn order(lifo: bool) -> Order {
    if lifo {
        Order::Lifo
    } else {
        Order::Fifo
    }
}

fn clear(lifo: bool) -> QueueIn {
    QueueIn {
        clear: true,
        order: order(lifo),
        ..Default::default()
    }
}

/// One clock: push and pop with the given probabilities, a random entry word, a third of
/// the pushes with a second entry (the second write port), rarely a clear (pushes and pop
/// then ignored).
fn op(p_push: f64, p_pop: f64) -> impl Strategy<Value = QueueIn> {
    let two = (prop::bool::weighted(1.0 / 3.0), any::<u128>());
    (
        prop::bool::weighted(p_push),
        prop::bool::weighted(p_pop),
        any::<u128>(),
        two,
        prop::bool::weighted(0.004),
        any::<bool>(),
    )
        .prop_map(|(push, pop, d, (two, d2), clear, lifo)| QueueIn {
            clear,
            order: order(lifo),
            push,
            pop,
            push_data: d & MASK,
            push2: (push && two).then_some(d2 & MASK),
        })
}

/// A phase of one mix, long enough to fill or drain a queue of `cap` entries.
fn phase(cap: usize) -> impl Strategy<Value = Vec<QueueIn>> {
    let v = move |p_push, p_pop, lo: usize, hi: usize| {
        prop::collection::vec(op(p_push, p_pop), lo..=hi)
    };
    prop_oneof![
        2 => v(1.0, 0.0, cap, cap + 6),        // fill past full: overflow
        1 => v(0.0, 1.0, cap / 2, cap + 2),    // drain
        2 => v(0.85, 0.1, cap / 2, 2 * cap + 4),
        2 => v(0.15, 0.8, cap / 2, 2 * cap + 4),
        2 => v(0.5, 0.5, cap / 2, 2 * cap + 4),
        2 => v(0.9, 0.9, cap / 2, 2 * cap + 4), // mostly push and pop together
        1 => any::<bool>().prop_map(|l| vec![clear(l)]),
    ]
}

/// Drops the pops on an empty queue (by the golden model's count), which D_CNTR never issues.
fn legalize(n: u32, ops: impl IntoIterator<Item = QueueIn>) -> Vec<QueueIn> {
    let mut m = QueueModel::new(n);
    ops.into_iter()
        .map(|mut i| {
            if !i.clear && m.outputs().empty {
                i.pop = false;
            }
            m.step(&i);
            i
        })
        .collect()
}

/// A clear (either order), then `phases` phases.
fn ops(n: u32, phases: std::ops::Range<usize>) -> impl Strategy<Value = Vec<QueueIn>> {
    (any::<bool>(), prop::collection::vec(phase(1 << n), phases)).prop_map(move |(l, ph)| {
        legalize(n, std::iter::once(clear(l)).chain(ph.into_iter().flatten()))
    })
}

/// Samples `k` values of `strat` (deterministic seed).
fn sample<T: std::fmt::Debug>(strat: impl Strategy<Value = T>, k: usize) -> Vec<T> {
    let mut runner = TestRunner::new_with_rng(
        Config::default(),
        proptest::test_runner::TestRng::deterministic_rng(
            proptest::test_runner::RngAlgorithm::ChaCha,
        ),
    );
    (0..k)
        .map(|_| strat.new_tree(&mut runner).unwrap().current())
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// 8 entries: many fills to overflow, drains, clears, both orders.
    #[test]
    fn random_ops_n3(ops in ops(3, 1..16)) {
        if let Err(e) = check::<3, 4, 2>(&ops) {
            return Err(TestCaseError::fail(e));
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, ..ProptestConfig::default() })]

    /// 256 entries: long runs, fills to overflow.
    #[test]
    fn random_ops_n8(ops in ops(8, 2..8)) {
        if let Err(e) = check::<8, 9, 7>(&ops) {
            return Err(TestCaseError::fail(e));
        }
    }
}

/// The generated sequences reach every corner in both orders (and equal the golden model).
#[test]
fn generated_ops_cover_the_corners() {
    let mut cov = Coverage::default();
    for ops in sample(ops(3, 8..16), 12) {
        cov.add(&check::<3, 4, 2>(&ops).unwrap());
    }
    eprintln!("2^3 entries: {cov:?}");
    assert!(cov.all_hit(), "{cov:?}");
    let mut cov = Coverage::default();
    for ops in sample(ops(8, 6..10), 8) {
        cov.add(&check::<8, 9, 7>(&ops).unwrap());
    }
    eprintln!("2^8 entries: {cov:?}");
    assert!(
        (0..2).all(|k| cov.overflows[k] > 0 && cov.full[k] > 0 && cov.push_pop_one[k] > 0),
        "{cov:?}"
    );
}

/// The exported vectors' own sequence (the inputs of every line of vectors/pair_queue_n4.hex,
/// read back from the file Icarus and Verilator run) covers the corners too, run through the
/// RTL against the golden model.
#[test]
fn vector_ops_cover_the_corners() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/pair_queue_n4.hex");
    let text = std::fs::read_to_string(&path).unwrap();
    let hex = |f: &str| u128::from_str_radix(f, 16).unwrap();
    let ops: Vec<QueueIn> = text
        .lines()
        .filter(|l| !l.starts_with("//"))
        .map(|l| {
            // clear lifo push push_data push2 push2_data pop, then the outputs
            let f: Vec<&str> = l.split_whitespace().collect();
            QueueIn {
                clear: f[0] == "1",
                order: if f[1] == "1" {
                    Order::Lifo
                } else {
                    Order::Fifo
                },
                push: f[2] == "1",
                push_data: hex(f[3]),
                push2: (f[4] == "1").then(|| hex(f[5])),
                pop: f[6] == "1",
            }
        })
        .collect();
    assert!(ops.len() >= 3000, "{}: {} lines", path.display(), ops.len());
    let cov = check::<4, 5, 3>(&ops).unwrap();
    eprintln!("2^4 entries, exported vectors: {cov:?}");
    assert!(cov.all_hit(), "{cov:?}");
}

/// The comparison can fail: a golden model that treats LIFO as FIFO differs from the RTL on
/// every sequence that holds two entries in LIFO order, and one with half the capacity on
/// every sequence that holds 4 entries (then full for it, not for the RTL).
#[test]
fn wrong_models_are_caught() {
    let (mut lifo_seqs, mut big_seqs) = (0, 0);
    for ops in sample(ops(3, 8..12), 8) {
        let (mut m, mut lifo2, mut over4) = (QueueModel::new(3), false, false);
        for i in &ops {
            let o = m.step(i);
            lifo2 |= m.order() == Order::Lifo && o.count >= 2;
            over4 |= o.count >= 4;
        }
        let mut m = QueueModel::new(3);
        let r = compare::<3, 4, 2>(
            &ops,
            |i| {
                m.step(&QueueIn {
                    order: Order::Fifo,
                    ..*i
                })
            },
            false,
        );
        assert_eq!(r.is_err(), lifo2, "FIFO-only model on {} clocks", ops.len());
        let mut m = QueueModel::new(2);
        let r = compare::<3, 4, 2>(&ops, |i| m.step(i), false);
        assert_eq!(r.is_err(), over4, "4-entry model on {} clocks", ops.len());
        lifo_seqs += lifo2 as usize;
        big_seqs += over4 as usize;
    }
    assert!(
        lifo_seqs >= 2 && big_seqs >= 2,
        "{lifo_seqs} LIFO, {big_seqs} big sequences"
    );
}

// ---- directed ------------------------------------------------------------------------

/// A push and a pop on a one-entry LIFO leave exactly the pushed entry; on a FIFO too.
#[test]
fn push_pop_on_one_entry() {
    for lifo in [false, true] {
        let mut dut = Dut::<3, 4, 2>::new();
        let mut m = QueueModel::new(3);
        let mut go = |i: QueueIn| {
            let o = dut.cycle(&i);
            assert_eq!(o, m.step(&i));
            o
        };
        go(clear(lifo));
        go(QueueIn {
            push: true,
            push_data: 0x1_2345_6789_abcd_ef01,
            ..Default::default()
        });
        let o = go(QueueIn {
            push: true,
            pop: true,
            push_data: MASK,
            ..Default::default()
        });
        assert_eq!((o.count, o.top_data, o.max_count), (1, MASK, 1));
        let o = go(QueueIn {
            pop: true,
            ..Default::default()
        });
        assert!(o.empty && o.top_data == 0 && o.max_count == 1 && !o.overflow);
    }
}

/// A pop on an empty queue is ignored (with and without a push in the same cycle).
#[test]
fn pop_on_empty_is_ignored() {
    for lifo in [false, true] {
        let ops = [
            clear(lifo),
            QueueIn {
                pop: true,
                ..Default::default()
            },
            QueueIn {
                pop: true,
                push: true,
                push_data: 5,
                ..Default::default()
            },
            QueueIn {
                pop: true,
                ..Default::default()
            },
            QueueIn {
                pop: true,
                ..Default::default()
            },
            QueueIn {
                push: true,
                push_data: 6,
                ..Default::default()
            },
        ];
        let mut m = QueueModel::new(3);
        compare::<3, 4, 2>(&ops, |i| m.step(i), true).unwrap();
        let mut dut = Dut::<3, 4, 2>::new();
        let outs: Vec<QueueOut> = ops.iter().map(|i| dut.cycle(i)).collect();
        assert_eq!((outs[2].count, outs[2].top_data), (1, 5));
        assert!(outs[4].empty && outs[5].count == 1 && outs[5].max_count == 1);
    }
}

/// Two pushes in one clock (the second write port), hand-derived: the second entry is the
/// later one (LIFO: on top); with a pop, the pop goes first; a second push that finds the
/// queue full is lost and sets `overflow`; the RAM's two banks take consecutive words.
#[test]
fn two_pushes_in_one_clock() {
    for lifo in [false, true] {
        let mut dut = Dut::<3, 4, 2>::new();
        let mut m = QueueModel::new(3);
        let mut go = |i: QueueIn| {
            let o = dut.cycle(&i);
            assert_eq!(o, m.step(&i), "{i:x?}");
            o
        };
        let two = |a: u128, b: u128, pop: bool| QueueIn {
            push: true,
            push_data: a,
            push2: Some(b),
            pop,
            ..Default::default()
        };
        let pop = QueueIn {
            pop: true,
            ..Default::default()
        };
        go(clear(lifo));
        let o = go(two(1, 2, false));
        assert_eq!((o.count, o.top_data), (2, if lifo { 2 } else { 1 }));
        let o = go(two(3, 4, false));
        assert_eq!((o.count, o.top_data), (4, if lifo { 4 } else { 1 }));
        // pop and two pushes: LIFO 4 leaves, 5 and 6 on top; FIFO 1 leaves, 2 is the head
        let o = go(two(5, 6, true));
        assert_eq!((o.count, o.top_data), (5, if lifo { 6 } else { 2 }));
        go(two(7, 8, false));
        // 7 entries: the first push fits, the second is lost
        let o = go(two(9, 10, false));
        assert!(o.full && o.overflow);
        // drained in order: LIFO 9 8 7 6 5 3 2 1 (4 and 10 gone), FIFO 2 3 4 5 6 7 8 9
        let mut seq = vec![];
        for _ in 0..8 {
            seq.push(go(pop).top_data);
        }
        let want: Vec<u128> = if lifo {
            vec![8, 7, 6, 5, 3, 2, 1, 0]
        } else {
            vec![3, 4, 5, 6, 7, 8, 9, 0]
        };
        assert_eq!(seq, want, "the tops after each pop");
    }
}

// ---- the traversal order ---------------------------------------------------------------

/// The paper's example: A(B(D,E),C(F,G)) against 1(2(4,5),3(6,7)), every pair overlapping
/// (node ids A..G = 0..6 and 1..7 = 0..6).
fn node(n: u32) -> Node {
    if n < 3 {
        Node::Inner([2 * n + 1, 2 * n + 2])
    } else {
        Node::Leaf(n)
    }
}

fn name(p: &Pair) -> String {
    format!("{}{}", (b'A' + p.a as u8) as char, p.b + 1)
}

/// The child entries of a popped entry in push order: per pair, `children` (LIFO: reversed,
/// so the first is popped next), as `golden::d_cntr::Queue` pushes them.
fn child_entries(ent: &Entry, lifo: bool) -> Vec<Entry> {
    let mut out = vec![];
    for p in &ent.pairs[..ent.len as usize] {
        if p.a < 3 || p.b < 3 {
            let (ch, n) = children(*p, node(p.a), node(p.b));
            if lifo {
                out.extend(ch[..n].iter().rev());
            } else {
                out.extend(&ch[..n]);
            }
        }
    }
    out
}

/// The tested pairs in order, with the golden D_CNTR's queue.
fn software_order(lifo: bool) -> Vec<String> {
    let mut q = Queue::new(order(lifo));
    let mut seq = vec![];
    while let Some(ent) = q.pop() {
        for p in &ent.pairs[..ent.len as usize] {
            seq.push(name(p));
            if p.a < 3 || p.b < 3 {
                q.push_children(*p, node(p.a), node(p.b));
            }
        }
    }
    seq
}

/// The same with the RTL queue (and the golden model alongside, every clock): the entry on
/// `top_data` is popped while its first child entry is pushed in the same clock, the other
/// children follow one per clock.
fn rtl_order(lifo: bool) -> (Vec<String>, u32) {
    let mut dut = Dut::<4, 5, 3>::new();
    let mut m = QueueModel::new(4);
    let mut go = |i: QueueIn| {
        let o = dut.cycle(&i);
        assert_eq!(o, m.step(&i), "{i:x?}");
        o
    };
    go(clear(lifo));
    let root = Pair {
        a: 0,
        b: 0,
        flip: false,
    };
    let mut o = go(QueueIn {
        push: true,
        push_data: pack(&Entry {
            pairs: [root, root],
            len: 1,
        }),
        ..Default::default()
    });
    let mut seq = vec![];
    while !o.empty {
        let ent = unpack(o.top_data);
        seq.extend(ent.pairs[..ent.len as usize].iter().map(name));
        let ch = child_entries(&ent, lifo);
        o = go(QueueIn {
            pop: true,
            push: !ch.is_empty(),
            push_data: ch.first().map_or(0, pack),
            ..Default::default()
        });
        for c in ch.iter().skip(1) {
            o = go(QueueIn {
                push: true,
                push_data: pack(c),
                ..Default::default()
            });
        }
    }
    assert!(!o.overflow);
    (seq, o.max_count)
}

#[test]
fn papers_fifo_sequence_through_the_rtl_queue() {
    let (seq, max) = rtl_order(false);
    assert_eq!(
        seq.join(" "),
        "A1 B2 B3 C3 C2 D4 D5 E5 E4 E6 E7 D7 D6 F6 F7 G7 G6 G4 G5 F5 F4"
    );
    assert_eq!(seq, software_order(false));
    eprintln!("FIFO: max {max} entries");
}

#[test]
fn lifo_sequence_through_the_rtl_queue() {
    let (seq, max) = rtl_order(true);
    assert_eq!(seq, software_order(true));
    assert_eq!(seq.len(), 21);
    assert_ne!(seq, software_order(false));
    eprintln!("LIFO: {} (max {max} entries)", seq.join(" "));
}
