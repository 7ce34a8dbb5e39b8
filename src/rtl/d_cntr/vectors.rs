//! The pair queue's test vectors (rtl/pair_queue_n4.v's): random operation sequences and
//! the golden [`QueueModel`]'s outputs on them.

use super::W;
use crate::chip::reg::Order;
use crate::cycle::d_cntr::{QueueIn, QueueModel};
use rand::{Rng, SeedableRng};
use std::fmt::Write;

/// A random operation sequence for a queue of `2^n` entries: phases of push-heavy,
/// pop-heavy and balanced mixes (push and pop in one cycle included, a third of the pushes
/// with a second entry on the second write port, a few of those alone), each long enough to
/// fill or drain the queue, both orders, clears in between and while not empty; never a
/// pop on an empty queue. Starts with a clear.
pub fn random_ops(rng: &mut impl Rng, n: u32, len: usize) -> Vec<QueueIn> {
    let cap = 1usize << n;
    let mut model = QueueModel::new(n);
    let mut ops = vec![];
    let order = |lifo| if lifo { Order::Lifo } else { Order::Fifo };
    let mut lifo = rng.random_range(0..2) == 1;
    ops.push(QueueIn {
        clear: true,
        order: order(lifo),
        ..Default::default()
    });
    model.step(&ops[0]);
    while ops.len() < len {
        // (push %, pop %) of a phase: fill past full, drain, balanced, push+pop
        let (p_push, p_pop) =
            [(85, 10), (15, 80), (50, 50), (90, 90), (60, 30)][rng.random_range(0..5)];
        let phase = rng.random_range(cap / 2..=2 * cap + 4);
        for _ in 0..phase {
            if ops.len() == len {
                break;
            }
            let mut i = QueueIn {
                push: rng.random_range(0..100) < p_push,
                pop: rng.random_range(0..100) < p_pop && model.outputs().count > 0,
                push_data: rng.random::<u128>() & ((1 << W) - 1),
                ..Default::default()
            };
            let second = rng.random::<u128>() & ((1 << W) - 1);
            match rng.random_range(0..30) {
                0..10 if i.push => i.push2 = Some(second),
                10 if !i.push => i.push2 = Some(second),
                _ => {}
            }
            if rng.random_range(0..200) == 0 {
                lifo = rng.random_range(0..2) == 1;
                i = QueueIn {
                    clear: true,
                    order: order(lifo),
                    ..i
                }; // push and pop ignored
            }
            model.step(&i);
            ops.push(i);
        }
        if rng.random_range(0..3) == 0 {
            lifo = !lifo;
            let i = QueueIn {
                clear: true,
                order: order(lifo),
                ..Default::default()
            };
            model.step(&i);
            ops.push(i);
        }
    }
    ops
}

/// Vectors of the pair queue: one line per clock, the inputs and the outputs after that
/// clock's rising edge (`// latency: 1`), from [`QueueModel`] on [`random_ops`].
pub fn pair_queue_vectors(name: &str, n: u32, len: usize) -> String {
    let digits = |bits: usize| bits.div_ceil(4);
    let (dw, dc) = (digits(W), digits(n as usize + 1));
    let mut out = String::new();
    let _ = writeln!(out, "// clear lifo push push_data push2 push2_data pop empty full count max_count overflow top_data");
    let _ = writeln!(out, "// latency: 1");
    let _ = writeln!(
        out,
        "// {name}: D_CNTR pair queue, 2^{n} entries of {W} bits; one line per clock: inputs, then the outputs after that clock's rising edge; golden: collision_chip::cycle::d_cntr::QueueModel"
    );
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0xd_c47 ^ name.len() as u64);
    let mut model = QueueModel::new(n);
    for i in random_ops(&mut rng, n, len) {
        let o = model.step(&i);
        let _ = writeln!(
            out,
            "{:x} {:x} {:x} {:0dw$x} {:x} {:0dw$x} {:x} {:x} {:x} {:0dc$x} {:0dc$x} {:x} {:0dw$x}",
            i.clear as u8,
            (i.order == Order::Lifo) as u8,
            i.push as u8,
            i.push_data,
            i.push2.is_some() as u8,
            i.push2.unwrap_or_default(),
            i.pop as u8,
            o.empty as u8,
            o.full as u8,
            o.count,
            o.max_count,
            o.overflow as u8,
            o.top_data
        );
    }
    out
}
