//! D_CNTR (DATE'05 §4.3): the pair queue, first block of the traversal controller.
//! Golden: [`cycle::d_cntr::QueueModel`](crate::cycle::d_cntr::QueueModel); entry word
//! layout: [`cycle::d_cntr`](crate::cycle::d_cntr) (`pack` / `unpack`).

use crate::cycle::d_cntr::{QueueIn, QueueModel, QueueOut, ENTRY_BITS};
use rand::{Rng, SeedableRng};
use rust_hdl::prelude::*;
use std::fmt::Write;

/// Bits of an entry word ([`cycle::d_cntr`](crate::cycle::d_cntr) has the layout).
pub const W: usize = ENTRY_BITS as usize;

/// D_CNTR's queue of waiting node-pair entries: `2^N` entries of [`W`] = 67 bits, FIFO
/// (breadth first) or LIFO (depth first) as latched by `clear`; `NP1` must be `N + 1`
/// (the width of `count`). Golden: [`QueueModel`], equal on every output after every
/// clock. The entry word is opaque here (layout: [`cycle::d_cntr`](crate::cycle::d_cntr)).
///
/// Ports: in `clock`, `clear`, `lifo`, `push`, `push_data[67]`, `pop`; out `empty`,
/// `full`, `count[NP1]`, `max_count[NP1]`, `overflow`, `top_data[67]`.
///
/// Timing: the inputs are sampled at a rising edge, which performs the cycle's operation;
/// every output is a function of registers only (no path from an input), so it changes
/// only at a rising edge and shows the state after it:
///
/// * `clear`: empties the queue, sets `max_count` to 0, clears `overflow` and latches
///   `lifo` as the order until the next clear; `push` and `pop` in that cycle are ignored.
///   Until the first clear the queue is an empty FIFO (the registers' initial values).
/// * `pop` removes the entry shown on `top_data` (FIFO: the oldest, LIFO: the newest);
///   a pop while `empty` is ignored (D_CNTR never issues one).
/// * `push` stores `push_data`. With a pop in the same cycle the pop happens first in both
///   orders: FIFO removes the head and appends the pushed entry; LIFO removes the top and
///   the pushed entry becomes the new top (a push and pop on a one-entry LIFO leaves
///   exactly the pushed entry). So a push while `full` is stored if the same cycle pops.
/// * `overflow`: sticky until clear; set by a push while `full` without a pop in the same
///   cycle, whose entry is not stored (the chip ends the query with an error status).
/// * `count` = entries held (0 ..= 2^N), `empty` = count is 0, `full` = count is 2^N,
///   `max_count` = the largest count after any edge since the last clear.
/// * `top_data`: show-ahead, the entry a pop in the next cycle removes, valid from the
///   edge that made it the top; 0 while empty.
///
/// Structure: the top entry is held in the register `top_r`; the other `count - 1` entries
/// are in a RAM of `2^N` words with a registered read port (`ram`, rust-hdl's `RAM`):
/// FIFO: a ring from `rd_ptr` to `wr_ptr - 1`; LIFO: a stack at `0 .. wr_ptr - 1`. The
/// read address of every edge is the address of the *next* entry (the one a pop moves into
/// `top_r`) in the state after that edge (FIFO `rd_ptr`, LIFO `wr_ptr - 1`), so the entry
/// is ready one edge later, when a pop may need it; when the same edge writes that address,
/// the RAM returns the old word and the written word is taken from a bypass register
/// (`byp`, `byp_data`) instead. So pops and pushes run back to back at one per clock, in
/// any mix, with no stall.
#[derive(LogicBlock)]
pub struct PairQueue<const N: usize, const NP1: usize> {
    pub clock: Signal<In, Clock>,
    pub clear: Signal<In, Bit>,
    pub lifo: Signal<In, Bit>,
    pub push: Signal<In, Bit>,
    pub push_data: Signal<In, Bits<W>>,
    pub pop: Signal<In, Bit>,
    pub empty: Signal<Out, Bit>,
    pub full: Signal<Out, Bit>,
    pub count: Signal<Out, Bits<NP1>>,
    pub max_count: Signal<Out, Bits<NP1>>,
    pub overflow: Signal<Out, Bit>,
    pub top_data: Signal<Out, Bits<W>>,
    c_cap: Constant<Bits<NP1>>,
    // state
    cnt: DFF<Bits<NP1>>,
    top_r: DFF<Bits<W>>,
    rd_ptr: DFF<Bits<N>>,
    wr_ptr: DFF<Bits<N>>,
    byp: DFF<Bit>,
    byp_data: DFF<Bits<W>>,
    order_lifo: DFF<Bit>,
    max_r: DFF<Bits<NP1>>,
    ovf_r: DFF<Bit>,
    ram: RAM<Bits<W>, N>,
    // this cycle
    nonempty: Signal<Local, Bit>,
    many: Signal<Local, Bit>,
    is_full: Signal<Local, Bit>,
    do_pop: Signal<Local, Bit>,
    do_push: Signal<Local, Bit>,
    next_entry: Signal<Local, Bits<W>>,
    cnt_n: Signal<Local, Bits<NP1>>,
    rd_n: Signal<Local, Bits<N>>,
    wr_n: Signal<Local, Bits<N>>,
    raddr: Signal<Local, Bits<N>>,
    we: Signal<Local, Bit>,
    wdata: Signal<Local, Bits<W>>,
}

impl<const N: usize, const NP1: usize> Default for PairQueue<N, NP1> {
    fn default() -> Self {
        assert!(NP1 == N + 1 && (1..=16).contains(&N), "PairQueue<N, NP1>: NP1 = N + 1, 1 <= N <= 16");
        Self {
            clock: Default::default(),
            clear: Default::default(),
            lifo: Default::default(),
            push: Default::default(),
            push_data: Default::default(),
            pop: Default::default(),
            empty: Default::default(),
            full: Default::default(),
            count: Default::default(),
            max_count: Default::default(),
            overflow: Default::default(),
            top_data: Default::default(),
            c_cap: Constant::new((1u64 << N).into()),
            cnt: Default::default(),
            top_r: Default::default(),
            rd_ptr: Default::default(),
            wr_ptr: Default::default(),
            byp: Default::default(),
            byp_data: Default::default(),
            order_lifo: Default::default(),
            max_r: Default::default(),
            ovf_r: Default::default(),
            ram: Default::default(),
            nonempty: Default::default(),
            many: Default::default(),
            is_full: Default::default(),
            do_pop: Default::default(),
            do_push: Default::default(),
            next_entry: Default::default(),
            cnt_n: Default::default(),
            rd_n: Default::default(),
            wr_n: Default::default(),
            raddr: Default::default(),
            we: Default::default(),
            wdata: Default::default(),
        }
    }
}

impl<const N: usize, const NP1: usize> PairQueue<N, NP1> {
    /// Entries it holds when full.
    pub const CAPACITY: usize = 1 << N;
}

impl<const N: usize, const NP1: usize> Logic for PairQueue<N, NP1> {
    #[hdl_gen]
    fn update(&mut self) {
        // every register holds unless assigned below
        dff_setup!(self, clock, cnt, top_r, rd_ptr, wr_ptr, byp, byp_data, order_lifo, max_r, ovf_r);
        self.ram.read_clock.next = self.clock.val();
        self.ram.write_clock.next = self.clock.val();
        // ---- outputs: registers only
        self.empty.next = self.cnt.q.val() == 0;
        self.full.next = self.cnt.q.val() == self.c_cap.val();
        self.count.next = self.cnt.q.val();
        self.max_count.next = self.max_r.q.val();
        self.overflow.next = self.ovf_r.q.val();
        self.top_data.next = self.top_r.q.val();
        // ---- this cycle's operation
        self.nonempty.next = self.cnt.q.val() != 0;
        self.many.next = self.cnt.q.val() > 1; // the RAM holds the next entry
        self.is_full.next = self.cnt.q.val() == self.c_cap.val();
        self.do_pop.next = self.pop.val() & self.nonempty.val();
        self.do_push.next = self.push.val() & (!self.is_full.val() | self.do_pop.val());
        // the entry after the top: the RAM's registered read, or the word written at the
        // edge that read it
        self.next_entry.next = self.ram.read_data.val();
        if self.byp.q.val() {
            self.next_entry.next = self.byp_data.q.val();
        }
        self.cnt_n.next = self.cnt.q.val();
        if self.do_push.val() & !self.do_pop.val() {
            self.cnt_n.next = self.cnt.q.val() + 1;
        }
        if self.do_pop.val() & !self.do_push.val() {
            self.cnt_n.next = self.cnt.q.val() - 1;
        }
        self.rd_n.next = self.rd_ptr.q.val();
        self.wr_n.next = self.wr_ptr.q.val();
        self.we.next = false;
        self.wdata.next = self.push_data.val();
        if self.order_lifo.q.val() {
            // LIFO: RAM[0 .. wr_ptr - 1] below the top
            if self.do_pop.val() & !self.do_push.val() {
                self.top_r.d.next = 0.into();
                if self.many.val() {
                    self.top_r.d.next = self.next_entry.val();
                    self.wr_n.next = self.wr_ptr.q.val() - 1;
                }
            }
            if self.do_push.val() {
                self.top_r.d.next = self.push_data.val();
                if self.nonempty.val() & !self.do_pop.val() {
                    // the old top goes down into the RAM
                    self.we.next = true;
                    self.wdata.next = self.top_r.q.val();
                    self.wr_n.next = self.wr_ptr.q.val() + 1;
                }
            }
        } else {
            // FIFO: RAM[rd_ptr .. wr_ptr - 1] behind the head
            if self.do_pop.val() {
                self.top_r.d.next = 0.into();
                if self.many.val() {
                    self.top_r.d.next = self.next_entry.val();
                    self.rd_n.next = self.rd_ptr.q.val() + 1;
                }
            }
            if self.do_push.val() {
                if self.many.val() | (self.nonempty.val() & !self.do_pop.val()) {
                    self.we.next = true;
                    self.wr_n.next = self.wr_ptr.q.val() + 1;
                } else {
                    // into an empty queue (or one the pop empties)
                    self.top_r.d.next = self.push_data.val();
                }
            }
        }
        self.cnt.d.next = self.cnt_n.val();
        if self.cnt_n.val() > self.max_r.q.val() {
            self.max_r.d.next = self.cnt_n.val();
        }
        if self.push.val() & self.is_full.val() & !self.do_pop.val() {
            self.ovf_r.d.next = true;
        }
        if self.clear.val() {
            self.cnt.d.next = 0.into();
            self.top_r.d.next = 0.into();
            self.rd_n.next = 0.into();
            self.wr_n.next = 0.into();
            self.we.next = false;
            self.order_lifo.d.next = self.lifo.val();
            self.max_r.d.next = 0.into();
            self.ovf_r.d.next = false;
        }
        self.rd_ptr.d.next = self.rd_n.val();
        self.wr_ptr.d.next = self.wr_n.val();
        // ---- RAM: write at wr_ptr; read the next entry of the state after this edge
        self.raddr.next = self.rd_n.val();
        if self.order_lifo.d.val() {
            self.raddr.next = self.wr_n.val() - 1;
        }
        self.ram.write_enable.next = self.we.val();
        self.ram.write_address.next = self.wr_ptr.q.val();
        self.ram.write_data.next = self.wdata.val();
        self.ram.read_address.next = self.raddr.val();
        self.byp.d.next = self.we.val() & (self.raddr.val() == self.wr_ptr.q.val());
        self.byp_data.d.next = self.wdata.val();
    }
}

/// A pair queue of `2^N` entries ready to simulate as a top-level block (inputs claimed,
/// connected).
pub fn pair_queue_top<const N: usize, const NP1: usize>() -> PairQueue<N, NP1> {
    top_level!(PairQueue::<N, NP1>::default(); clock, clear, lifo, push, push_data, pop)
}

/// Verilog of a pair queue of `2^N` entries (top module `top`).
pub fn verilog_pair_queue<const N: usize, const NP1: usize>() -> String {
    generate_verilog(&pair_queue_top::<N, NP1>())
}

impl<const N: usize, const NP1: usize> PairQueue<N, NP1> {
    /// Drives the inputs of one cycle (one write port: `push2` is the cycle model's).
    pub fn set_inputs(&mut self, i: &QueueIn) {
        assert!(i.push2.is_none(), "the RTL pair queue has one write port");
        self.clear.next = i.clear;
        self.lifo.next = i.lifo;
        self.push.next = i.push;
        self.push_data.next = i.push_data.to_bits();
        self.pop.next = i.pop;
    }

    /// The outputs, as the golden model gives them.
    pub fn outputs(&self) -> QueueOut {
        QueueOut {
            empty: self.empty.val(),
            full: self.full.val(),
            count: self.count.val().to_u64() as u32,
            max_count: self.max_count.val().to_u64() as u32,
            overflow: self.overflow.val(),
            top_data: self.top_data.val().to_u128(),
        }
    }
}

/// A random operation sequence for a queue of `2^n` entries: phases of push-heavy,
/// pop-heavy and balanced mixes (push and pop in one cycle included), each long enough to
/// fill or drain the queue, both orders, clears in between and while not empty; never a
/// pop on an empty queue. Starts with a clear.
pub fn random_ops(rng: &mut impl Rng, n: u32, len: usize) -> Vec<QueueIn> {
    let cap = 1usize << n;
    let mut model = QueueModel::new(n);
    let mut ops = vec![];
    let mut lifo = rng.random_range(0..2) == 1;
    ops.push(QueueIn { clear: true, lifo, ..Default::default() });
    model.step(&ops[0]);
    while ops.len() < len {
        // (push %, pop %) of a phase: fill past full, drain, balanced, push+pop
        let (p_push, p_pop) = [(85, 10), (15, 80), (50, 50), (90, 90), (60, 30)][rng.random_range(0..5)];
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
            if rng.random_range(0..200) == 0 {
                lifo = rng.random_range(0..2) == 1;
                i = QueueIn { clear: true, lifo, ..i }; // push and pop ignored
            }
            model.step(&i);
            ops.push(i);
        }
        if rng.random_range(0..3) == 0 {
            lifo = !lifo;
            let i = QueueIn { clear: true, lifo, ..Default::default() };
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
    let _ = writeln!(out, "// clear lifo push push_data pop empty full count max_count overflow top_data");
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
            "{:x} {:x} {:x} {:0dw$x} {:x} {:x} {:x} {:0dc$x} {:0dc$x} {:x} {:0dw$x}",
            i.clear as u8, i.lifo as u8, i.push as u8, i.push_data, i.pop as u8,
            o.empty as u8, o.full as u8, o.count, o.max_count, o.overflow as u8, o.top_data
        );
    }
    out
}
