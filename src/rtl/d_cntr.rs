//! D_CNTR (DATE'05 §4.3): the pair queue, first block of the traversal controller.
//! Golden: [`cycle::d_cntr::QueueModel`](crate::cycle::d_cntr::QueueModel); entry word
//! layout: [`cycle::d_cntr`](crate::cycle::d_cntr) (`pack` / `unpack`).

use crate::chip::reg::Order;
use crate::cycle::d_cntr::{QueueIn, QueueModel, QueueOut};

use crate::chip::layout::ENTRY_BITS;
use rand::{Rng, SeedableRng};
use rust_hdl::prelude::*;
use std::fmt::Write;

/// Bits of an entry word ([`cycle::d_cntr`](crate::cycle::d_cntr) has the layout).
pub const W: usize = ENTRY_BITS as usize;

/// D_CNTR's queue of waiting node-pair entries: `2^N` entries of [`W`] = 67 bits, FIFO
/// (breadth first) or LIFO (depth first) as latched by `clear`; `NP1` must be `N + 1`
/// (the width of `count`), `NM1` `N - 1` (a RAM bank's address), `N >= 2`. Golden:
/// [`QueueModel`], equal on every output after every clock. The entry word is opaque here
/// (layout: [`cycle::d_cntr`](crate::cycle::d_cntr)).
///
/// Ports: in `clock`, `clear`, `lifo`, `push`, `push_data[67]`, `push2`, `push2_data[67]`,
/// `pop`; out `empty`, `full`, `count[NP1]`, `max_count[NP1]`, `overflow`, `top_data[67]`.
///
/// Timing: the inputs are sampled at a rising edge, which performs the cycle's operation;
/// every output is a function of registers only (no path from an input), so it changes
/// only at a rising edge and shows the state after it:
///
/// * `clear`: empties the queue, sets `max_count` to 0, clears `overflow` and latches
///   `lifo` as the order until the next clear; pushes and pop in that cycle are ignored.
///   Until the first clear the queue is an empty FIFO (the registers' initial values).
/// * `pop` removes the entry shown on `top_data` (FIFO: the oldest, LIFO: the newest);
///   a pop while `empty` is ignored (D_CNTR never issues one).
/// * `push` stores `push_data`, then `push2` stores `push2_data` (the second write port: a
///   DOP result's two child entries in one clock; alone, it pushes like `push`). With a pop
///   in the same cycle the pop happens first in both orders: FIFO removes the head and
///   appends the pushed entries; LIFO removes the top and the last pushed entry becomes the
///   new top (a push and pop on a one-entry LIFO leaves exactly the pushed entry). So a push
///   while `full` is stored if the same cycle pops.
/// * `overflow`: sticky until clear; set by a push that finds the queue full (after the
///   cycle's pop and any earlier push of the cycle), whose entry is not stored (the chip
///   ends the query with an error status).
/// * `count` = entries held (0 ..= 2^N), `empty` = count is 0, `full` = count is 2^N,
///   `max_count` = the largest count after any edge since the last clear.
/// * `top_data`: show-ahead, the entry a pop in the next cycle removes, valid from the
///   edge that made it the top; 0 while empty.
///
/// Structure: the top entry is held in the register `top_r`; the other `count - 1` entries
/// are in a RAM of `2^N` words in two banks by address parity (`bank0`, `bank1`, rust-hdl
/// `RAM`s with a registered read port), so that one edge writes two consecutive addresses:
/// FIFO: a ring from `rd_ptr` to `wr_ptr - 1`; LIFO: a stack at `0 .. wr_ptr - 1`. An edge
/// writes at most `wr_ptr` (port A) and `wr_ptr + 1` (port B). The read address of every
/// edge is the address of the *next* entry (the one a pop moves into `top_r`) in the state
/// after that edge (FIFO `rd_ptr`, LIFO `wr_ptr - 1`), read from both banks and chosen by
/// its parity one edge later, when a pop may need it; when the same edge writes that
/// address, the RAM returns the old word and the written word is taken from a bypass
/// register (`byp`, `byp_data`) instead. So pops and pushes run back to back at one pop
/// and two pushes per clock, in any mix, with no stall.
#[derive(LogicBlock)]
pub struct PairQueue<const N: usize, const NP1: usize, const NM1: usize> {
    pub clock: Signal<In, Clock>,
    pub clear: Signal<In, Bit>,
    pub lifo: Signal<In, Bit>,
    pub push: Signal<In, Bit>,
    pub push_data: Signal<In, Bits<W>>,
    pub push2: Signal<In, Bit>,
    pub push2_data: Signal<In, Bits<W>>,
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
    rsel: DFF<Bit>,
    order_lifo: DFF<Bit>,
    max_r: DFF<Bits<NP1>>,
    ovf_r: DFF<Bit>,
    bank0: RAM<Bits<W>, NM1>,
    bank1: RAM<Bits<W>, NM1>,
    // this cycle
    nonempty: Signal<Local, Bit>,
    many: Signal<Local, Bit>,
    do_pop: Signal<Local, Bit>,
    c0: Signal<Local, Bits<NP1>>,
    e1: Signal<Local, Bits<W>>,
    any: Signal<Local, Bit>,
    two: Signal<Local, Bit>,
    s1: Signal<Local, Bit>,
    s2: Signal<Local, Bit>,
    next_entry: Signal<Local, Bits<W>>,
    cnt_n: Signal<Local, Bits<NP1>>,
    rd_n: Signal<Local, Bits<N>>,
    wr_n: Signal<Local, Bits<N>>,
    wr1: Signal<Local, Bits<N>>,
    raddr: Signal<Local, Bits<N>>,
    we_a: Signal<Local, Bit>,
    we_b: Signal<Local, Bit>,
    wdata_a: Signal<Local, Bits<W>>,
    wdata_b: Signal<Local, Bits<W>>,
}

impl<const N: usize, const NP1: usize, const NM1: usize> Default for PairQueue<N, NP1, NM1> {
    fn default() -> Self {
        assert!(
            NP1 == N + 1 && NM1 + 1 == N && (2..=16).contains(&N),
            "PairQueue<N, NP1, NM1>: NP1 = N + 1, NM1 = N - 1, 2 <= N <= 16"
        );
        Self {
            clock: Default::default(),
            clear: Default::default(),
            lifo: Default::default(),
            push: Default::default(),
            push_data: Default::default(),
            push2: Default::default(),
            push2_data: Default::default(),
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
            rsel: Default::default(),
            order_lifo: Default::default(),
            max_r: Default::default(),
            ovf_r: Default::default(),
            bank0: Default::default(),
            bank1: Default::default(),
            nonempty: Default::default(),
            many: Default::default(),
            do_pop: Default::default(),
            c0: Default::default(),
            e1: Default::default(),
            any: Default::default(),
            two: Default::default(),
            s1: Default::default(),
            s2: Default::default(),
            next_entry: Default::default(),
            cnt_n: Default::default(),
            rd_n: Default::default(),
            wr_n: Default::default(),
            wr1: Default::default(),
            raddr: Default::default(),
            we_a: Default::default(),
            we_b: Default::default(),
            wdata_a: Default::default(),
            wdata_b: Default::default(),
        }
    }
}

impl<const N: usize, const NP1: usize, const NM1: usize> PairQueue<N, NP1, NM1> {
    /// Entries it holds when full.
    pub const CAPACITY: usize = 1 << N;
}

impl<const N: usize, const NP1: usize, const NM1: usize> Logic for PairQueue<N, NP1, NM1> {
    #[hdl_gen]
    fn update(&mut self) {
        // every register holds unless assigned below
        dff_setup!(self, clock, cnt, top_r, rd_ptr, wr_ptr, byp, byp_data, rsel, order_lifo, max_r, ovf_r);
        self.bank0.read_clock.next = self.clock.val();
        self.bank0.write_clock.next = self.clock.val();
        self.bank1.read_clock.next = self.clock.val();
        self.bank1.write_clock.next = self.clock.val();
        // ---- outputs: registers only
        self.empty.next = self.cnt.q.val() == 0;
        self.full.next = self.cnt.q.val() == self.c_cap.val();
        self.count.next = self.cnt.q.val();
        self.max_count.next = self.max_r.q.val();
        self.overflow.next = self.ovf_r.q.val();
        self.top_data.next = self.top_r.q.val();
        // ---- this cycle's operation: the pop, then up to two pushes (e1, then push2_data)
        self.nonempty.next = self.cnt.q.val() != 0;
        self.many.next = self.cnt.q.val() > 1; // the RAM holds the next entry
        self.do_pop.next = self.pop.val() & self.nonempty.val();
        self.c0.next = self.cnt.q.val() - bit_cast::<NP1, 1>(self.do_pop.val().into());
        self.e1.next = self.push2_data.val();
        if self.push.val() {
            self.e1.next = self.push_data.val();
        }
        self.any.next = self.push.val() | self.push2.val();
        self.two.next = self.push.val() & self.push2.val();
        // stored: the first push if the popped queue has room, the second if it has two
        self.s1.next = self.any.val() & (self.c0.val() != self.c_cap.val());
        self.s2.next = self.two.val() & (self.c0.val() + 1 < self.c_cap.val());
        // the entry after the top: the RAM's registered read (the bank of its parity), or
        // the word written at the edge that read it
        self.next_entry.next = self.bank0.read_data.val();
        if self.rsel.q.val() {
            self.next_entry.next = self.bank1.read_data.val();
        }
        if self.byp.q.val() {
            self.next_entry.next = self.byp_data.q.val();
        }
        self.cnt_n.next = self.c0.val() + bit_cast::<NP1, 1>(self.s1.val().into()) + bit_cast::<NP1, 1>(self.s2.val().into());
        self.rd_n.next = self.rd_ptr.q.val();
        self.wr_n.next = self.wr_ptr.q.val();
        self.wr1.next = self.wr_ptr.q.val() + 1;
        // port A writes wr_ptr, port B wr_ptr + 1 (only with A)
        self.we_a.next = false;
        self.we_b.next = false;
        self.wdata_a.next = self.e1.val();
        self.wdata_b.next = self.push2_data.val();
        if self.order_lifo.q.val() {
            self.wdata_b.next = self.e1.val();
            // LIFO: RAM[0 .. wr_ptr - 1] below the top; the last stored push is the new top
            if self.do_pop.val() {
                if !self.s1.val() {
                    self.top_r.d.next = 0.into();
                    if self.many.val() {
                        self.top_r.d.next = self.next_entry.val();
                        self.wr_n.next = self.wr_ptr.q.val() - 1;
                    }
                }
                if self.s1.val() {
                    self.top_r.d.next = self.e1.val();
                }
                if self.s2.val() {
                    // e1 goes where the popped top was
                    self.we_a.next = true;
                    self.wr_n.next = self.wr_ptr.q.val() + 1;
                    self.top_r.d.next = self.push2_data.val();
                }
            } else {
                if self.s1.val() {
                    self.top_r.d.next = self.e1.val();
                    if self.nonempty.val() {
                        // the old top goes down into the RAM
                        self.we_a.next = true;
                        self.wdata_a.next = self.top_r.q.val();
                        self.wr_n.next = self.wr_ptr.q.val() + 1;
                    }
                }
                if self.s2.val() {
                    self.top_r.d.next = self.push2_data.val();
                    self.we_a.next = true;
                    self.wr_n.next = self.wr_ptr.q.val() + 1;
                    if self.nonempty.val() {
                        // the old top at wr_ptr, e1 above it
                        self.we_b.next = true;
                        self.wr_n.next = self.wr_ptr.q.val() + 2;
                    }
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
            if self.c0.val() == 0 {
                // into an empty queue (or one the pop empties): the first becomes the head
                if self.s1.val() {
                    self.top_r.d.next = self.e1.val();
                }
                if self.s2.val() {
                    self.we_a.next = true;
                    self.wdata_a.next = self.push2_data.val();
                    self.wr_n.next = self.wr_ptr.q.val() + 1;
                }
            } else {
                if self.s1.val() {
                    self.we_a.next = true;
                    self.wr_n.next = self.wr_ptr.q.val() + 1;
                }
                if self.s2.val() {
                    self.we_b.next = true;
                    self.wr_n.next = self.wr_ptr.q.val() + 2;
                }
            }
        }
        self.cnt.d.next = self.cnt_n.val();
        if self.cnt_n.val() > self.max_r.q.val() {
            self.max_r.d.next = self.cnt_n.val();
        }
        if (self.any.val() & !self.s1.val()) | (self.two.val() & !self.s2.val()) {
            self.ovf_r.d.next = true;
        }
        if self.clear.val() {
            self.cnt.d.next = 0.into();
            self.top_r.d.next = 0.into();
            self.rd_n.next = 0.into();
            self.wr_n.next = 0.into();
            self.we_a.next = false;
            self.we_b.next = false;
            self.order_lifo.d.next = self.lifo.val();
            self.max_r.d.next = 0.into();
            self.ovf_r.d.next = false;
        }
        self.rd_ptr.d.next = self.rd_n.val();
        self.wr_ptr.d.next = self.wr_n.val();
        // ---- RAM: port A at wr_ptr, port B at wr_ptr + 1, each in the bank
        // of its parity; read the next entry of the state after this edge from both banks
        self.raddr.next = self.rd_n.val();
        if self.order_lifo.d.val() {
            self.raddr.next = self.wr_n.val() - 1;
        }
        self.bank0.write_enable.next = (self.we_a.val() & !self.wr_ptr.q.val().get_bit(0))
            | (self.we_b.val() & self.wr_ptr.q.val().get_bit(0));
        self.bank1.write_enable.next = (self.we_a.val() & self.wr_ptr.q.val().get_bit(0))
            | (self.we_b.val() & !self.wr_ptr.q.val().get_bit(0));
        self.bank0.write_address.next = self.wr_ptr.q.val().get_bits::<NM1>(1);
        self.bank0.write_data.next = self.wdata_a.val();
        self.bank1.write_address.next = self.wr_ptr.q.val().get_bits::<NM1>(1);
        self.bank1.write_data.next = self.wdata_a.val();
        if self.wr_ptr.q.val().get_bit(0) {
            self.bank0.write_address.next = self.wr1.val().get_bits::<NM1>(1);
            self.bank0.write_data.next = self.wdata_b.val();
        } else {
            self.bank1.write_address.next = self.wr1.val().get_bits::<NM1>(1);
            self.bank1.write_data.next = self.wdata_b.val();
        }
        self.bank0.read_address.next = self.raddr.val().get_bits::<NM1>(1);
        self.bank1.read_address.next = self.raddr.val().get_bits::<NM1>(1);
        self.rsel.d.next = self.raddr.val().get_bit(0);
        self.byp.d.next = (self.we_a.val() & (self.raddr.val() == self.wr_ptr.q.val()))
            | (self.we_b.val() & (self.raddr.val() == self.wr1.val()));
        self.byp_data.d.next = self.wdata_a.val();
        if self.we_b.val() & (self.raddr.val() == self.wr1.val()) {
            self.byp_data.d.next = self.wdata_b.val();
        }
    }
}

/// A pair queue of `2^N` entries ready to simulate as a top-level block (inputs claimed,
/// connected).
pub fn pair_queue_top<const N: usize, const NP1: usize, const NM1: usize>() -> PairQueue<N, NP1, NM1> {
    top_level!(PairQueue::<N, NP1, NM1>::default(); clock, clear, lifo, push, push_data, push2, push2_data, pop)
}

/// Verilog of a pair queue of `2^N` entries (top module `top`).
pub fn verilog_pair_queue<const N: usize, const NP1: usize, const NM1: usize>() -> String {
    generate_verilog(&pair_queue_top::<N, NP1, NM1>())
}

impl<const N: usize, const NP1: usize, const NM1: usize> PairQueue<N, NP1, NM1> {
    /// Drives the inputs of one cycle.
    pub fn set_inputs(&mut self, i: &QueueIn) {
        self.clear.next = i.clear;
        self.lifo.next = i.order == Order::Lifo;
        self.push.next = i.push;
        self.push_data.next = i.push_data.to_bits();
        self.push2.next = i.push2.is_some();
        self.push2_data.next = i.push2.unwrap_or_default().to_bits();
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
    ops.push(QueueIn { clear: true, order: order(lifo), ..Default::default() });
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
            let second = rng.random::<u128>() & ((1 << W) - 1);
            match rng.random_range(0..30) {
                0..10 if i.push => i.push2 = Some(second),
                10 if !i.push => i.push2 = Some(second),
                _ => {}
            }
            if rng.random_range(0..200) == 0 {
                lifo = rng.random_range(0..2) == 1;
                i = QueueIn { clear: true, order: order(lifo), ..i }; // push and pop ignored
            }
            model.step(&i);
            ops.push(i);
        }
        if rng.random_range(0..3) == 0 {
            lifo = !lifo;
            let i = QueueIn { clear: true, order: order(lifo), ..Default::default() };
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
            i.clear as u8, (i.order == Order::Lifo) as u8, i.push as u8, i.push_data, i.push2.is_some() as u8, i.push2.unwrap_or_default(), i.pop as u8,
            o.empty as u8, o.full as u8, o.count, o.max_count, o.overflow as u8, o.top_data
        );
    }
    out
}
