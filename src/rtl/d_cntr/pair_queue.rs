//! D_CNTR's pair queue ([`PairQueue`]): the waiting node-pair entries, FIFO or LIFO, two
//! pushes and a pop per clock.

use crate::chip::layout::ENTRY_BITS;
use crate::chip::reg::Order;
use crate::cycle::d_cntr::{QueueIn, QueueOut};
use crate::rtl::kernel::kernel;
use rust_hdl::prelude::*;

/// Bits of an entry word ([`cycle::d_cntr`](crate::cycle::d_cntr) has the layout).
pub const W: usize = ENTRY_BITS as usize;

/// D_CNTR's queue of waiting node-pair entries: `2^N` entries of [`W`] = 67 bits, FIFO
/// (breadth first) or LIFO (depth first) as latched by `clear`; `NP1` must be `N + 1`
/// (the width of `count`), `NM1` `N - 1` (a RAM bank's address), `N >= 2`. Golden:
/// [`QueueModel`](crate::cycle::d_cntr::QueueModel), equal on every output after every clock.
/// The entry word is opaque here (layout: [`cycle::d_cntr`](crate::cycle::d_cntr)).
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
/// and two pushes per clock, in any mix, with no stall. The pop arrives last (D_CNTR's
/// decision): the read address, bypass and count after the edge are selected among registers.
/// So the count's flags (`count != 0`, `> 1`, `== 2^N`, `>= 2^N - 1`) and the pointers'
/// neighbours (`rd_ptr + 1`, `wr_ptr + 1`, `wr_ptr - 1`, `wr_ptr - 2`) are registers of their
/// own, written with the count and the pointers.
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
    c_last: Constant<Bits<N>>,
    c_one: Constant<Bits<N>>,
    c_m2: Constant<Bits<N>>,
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
    // count != 0, a register of its own: it decides the pop, which arrives last
    nonempty: DFF<Bit>,
    // and so is all that the read address is chosen by: the count's flags and the pointers'
    // neighbours, each held in an encoding whose reset value (0) is an empty queue's
    many_r: DFF<Bit>,
    full_r: DFF<Bit>,
    tight_r: DFF<Bit>,
    rd1_x: DFF<Bits<N>>,
    wr1_x: DFF<Bits<N>>,
    wr_m1_n: DFF<Bits<N>>,
    wr_m2_x: DFF<Bits<N>>,
    many: Signal<Local, Bit>,
    do_pop: Signal<Local, Bit>,
    nfull: Signal<Local, Bit>,
    spare: Signal<Local, Bit>,
    c0_zero: Signal<Local, Bit>,
    cnt_m1: Signal<Local, Bits<NP1>>,
    cnt_p1: Signal<Local, Bits<NP1>>,
    cnt_p2: Signal<Local, Bits<NP1>>,
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
    wr_m1: Signal<Local, Bits<N>>,
    wr_m2: Signal<Local, Bits<N>>,
    rd1: Signal<Local, Bits<N>>,
    pick: Signal<Local, Bit>,
    hit_a: Signal<Local, Bit>,
    hit_b: Signal<Local, Bit>,
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
            c_last: Constant::new(((1u64 << N) - 1).into()),
            c_one: Constant::new(1.into()),
            c_m2: Constant::new(((1u64 << N) - 2).into()),
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
            many_r: Default::default(),
            full_r: Default::default(),
            tight_r: Default::default(),
            rd1_x: Default::default(),
            wr1_x: Default::default(),
            wr_m1_n: Default::default(),
            wr_m2_x: Default::default(),
            many: Default::default(),
            do_pop: Default::default(),
            nfull: Default::default(),
            spare: Default::default(),
            c0_zero: Default::default(),
            cnt_m1: Default::default(),
            cnt_p1: Default::default(),
            cnt_p2: Default::default(),
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
            wr_m1: Default::default(),
            wr_m2: Default::default(),
            rd1: Default::default(),
            pick: Default::default(),
            hit_a: Default::default(),
            hit_b: Default::default(),
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

kernel!([const N: usize, const NP1: usize, const NM1: usize] PairQueue<N, NP1, NM1>: Operation, Moves, RamPorts);

/// The pair queue's outputs, this clock's pop and pushes, and the count after the edge.
struct Operation;

impl<const N: usize, const NP1: usize, const NM1: usize> crate::rtl::kernel::Kernel<Operation>
    for PairQueue<N, NP1, NM1>
{
    #[hdl_gen]
    fn update(&mut self) {
        // every register holds unless assigned below
        dff_setup!(
            self, clock, cnt, nonempty, top_r, rd_ptr, wr_ptr, byp, byp_data, rsel, order_lifo,
            max_r, ovf_r
        );
        dff_setup!(self, clock, many_r, full_r, tight_r, rd1_x, wr1_x, wr_m1_n, wr_m2_x);
        self.bank0.read_clock.next = self.clock.val();
        self.bank0.write_clock.next = self.clock.val();
        self.bank1.read_clock.next = self.clock.val();
        self.bank1.write_clock.next = self.clock.val();
        // ---- outputs: registers only
        self.empty.next = !self.nonempty.q.val();
        self.full.next = self.cnt.q.val() == self.c_cap.val();
        self.count.next = self.cnt.q.val();
        self.max_count.next = self.max_r.q.val();
        self.overflow.next = self.ovf_r.q.val();
        self.top_data.next = self.top_r.q.val();
        // ---- this cycle's operation: the pop, then up to two pushes (e1, then push2_data)
        self.many.next = self.many_r.q.val(); // count > 1: the RAM holds the next entry
        self.do_pop.next = self.pop.val() & self.nonempty.q.val();
        // Everything below that the pop and pushes decide is selected among registers
        // (the count's flags, the pointers and their neighbours), so that the pop, which
        // arrives last, passes through a few multiplexers only: the queue's read address
        // was on the path that set the chip's clock.
        self.nfull.next = !self.full_r.q.val(); // count != 2^N
        self.spare.next = !self.tight_r.q.val(); // count + 1 < 2^N: room for two, if no pop
        self.cnt_m1.next = self.cnt.q.val() - 1;
        self.cnt_p1.next = self.cnt.q.val() + 1;
        self.cnt_p2.next = self.cnt.q.val() + 2;
        // the count after the pop is 0 (into an empty queue, or one the pop empties)
        self.c0_zero.next = !self.nonempty.q.val() | (self.do_pop.val() & !self.many.val());
        self.e1.next = self.push2_data.val();
        if self.push.val() {
            self.e1.next = self.push_data.val();
        }
        self.any.next = self.push.val() | self.push2.val();
        self.two.next = self.push.val() & self.push2.val();
        // stored: the first push if the popped queue has room, the second if it has two
        self.s1.next = self.any.val() & (self.do_pop.val() | self.nfull.val());
        self.s2.next = self.two.val() & ((self.do_pop.val() & self.nfull.val()) | self.spare.val());
        // the entry after the top: the RAM's registered read (the bank of its parity), or
        // the word written at the edge that read it
        self.next_entry.next = self.bank0.read_data.val();
        if self.rsel.q.val() {
            self.next_entry.next = self.bank1.read_data.val();
        }
        if self.byp.q.val() {
            self.next_entry.next = self.byp_data.q.val();
        }
        // the count after the edge: the pop's -1, the stored pushes' +1 each
        self.cnt_n.next = self.cnt.q.val();
        if self.do_pop.val() {
            if !self.s1.val() {
                self.cnt_n.next = self.cnt_m1.val();
            }
            if self.s2.val() {
                self.cnt_n.next = self.cnt_p1.val();
            }
        } else {
            if self.s1.val() {
                self.cnt_n.next = self.cnt_p1.val();
            }
            if self.s2.val() {
                self.cnt_n.next = self.cnt_p2.val();
            }
        }
        self.rd_n.next = self.rd_ptr.q.val();
        self.wr_n.next = self.wr_ptr.q.val();
        // wr_ptr + 1; port A writes wr_ptr, port B wr_ptr + 1 (only with A)
        self.wr1.next = self.wr1_x.q.val() ^ self.c_one.val();
        self.we_a.next = false;
        self.we_b.next = false;
        self.wdata_a.next = self.e1.val();
        self.wdata_b.next = self.push2_data.val();
    }
}

/// Where the entries go: the new top, the RAM writes and the pointers, by order (LIFO or
/// FIFO), and the clear.
struct Moves;

impl<const N: usize, const NP1: usize, const NM1: usize> crate::rtl::kernel::Kernel<Moves>
    for PairQueue<N, NP1, NM1>
{
    #[hdl_gen]
    fn update(&mut self) {
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
                    if self.nonempty.q.val() {
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
                    if self.nonempty.q.val() {
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
            if self.c0_zero.val() {
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
        if (self.any.val() & !self.s1.val()) | (self.two.val() & !self.s2.val()) {
            self.ovf_r.d.next = true;
        }
        if self.clear.val() {
            self.cnt_n.next = 0.into();
            self.top_r.d.next = 0.into();
            self.rd_n.next = 0.into();
            self.wr_n.next = 0.into();
            self.we_a.next = false;
            self.we_b.next = false;
            self.order_lifo.d.next = self.lifo.val();
            self.max_r.d.next = 0.into();
            self.ovf_r.d.next = false;
        }
        // the state after the edge (a clear's count 0 leaves max_count cleared)
        self.cnt.d.next = self.cnt_n.val();
        self.nonempty.d.next = self.cnt_n.val() != 0;
        if self.cnt_n.val() > self.max_r.q.val() {
            self.max_r.d.next = self.cnt_n.val();
        }
        self.many_r.d.next = self.cnt_n.val() > 1;
        self.full_r.d.next = self.cnt_n.val() == self.c_cap.val();
        self.tight_r.d.next = self.cnt_n.val() >= self.c_cap.val() - 1;
        self.rd_ptr.d.next = self.rd_n.val();
        self.wr_ptr.d.next = self.wr_n.val();
        self.rd1_x.d.next = (self.rd_n.val() + 1) ^ self.c_one.val();
        self.wr1_x.d.next = (self.wr_n.val() + 1) ^ self.c_one.val();
        self.wr_m1_n.d.next = !(self.wr_n.val() - 1);
        self.wr_m2_x.d.next = (self.wr_n.val() - 2) ^ self.c_m2.val();
    }
}

/// The two banks' ports and the next entry's read address, with the bypass of a word
/// written at the edge that reads it.
struct RamPorts;

impl<const N: usize, const NP1: usize, const NM1: usize> crate::rtl::kernel::Kernel<RamPorts>
    for PairQueue<N, NP1, NM1>
{
    #[hdl_gen]
    fn update(&mut self) {
        // ---- RAM: port A at wr_ptr, port B at wr_ptr + 1, each in the bank
        // of its parity; read the next entry of the state after this edge from both banks:
        // FIFO rd_n, LIFO wr_n - 1 (after a clear: 0, or 2^N - 1), as the cases above move
        // them, from addresses made from the registers alone
        self.rd1.next = self.rd1_x.q.val() ^ self.c_one.val();
        self.wr_m1.next = !self.wr_m1_n.q.val();
        self.wr_m2.next = self.wr_m2_x.q.val() ^ self.c_m2.val();
        self.pick.next = self.do_pop.val() & self.many.val(); // FIFO: rd_n = rd_ptr + 1
        self.raddr.next = self.rd_ptr.q.val();
        if self.pick.val() {
            self.raddr.next = self.rd1.val();
        }
        if self.order_lifo.q.val() {
            self.raddr.next = self.wr_m1.val();
            if self.do_pop.val() {
                if !self.s1.val() & self.many.val() {
                    self.raddr.next = self.wr_m2.val();
                }
                if self.s2.val() {
                    self.raddr.next = self.wr_ptr.q.val();
                }
            } else {
                if self.s1.val() & self.nonempty.q.val() {
                    self.raddr.next = self.wr_ptr.q.val();
                }
                if self.s2.val() {
                    self.raddr.next = self.wr_ptr.q.val();
                    if self.nonempty.q.val() {
                        self.raddr.next = self.wr1.val();
                    }
                }
            }
        }
        if self.clear.val() {
            self.raddr.next = 0.into();
            if self.lifo.val() {
                self.raddr.next = self.c_last.val();
            }
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
        // the bypass: this edge writes the word read (port A: raddr = wr_ptr, B: wr_ptr + 1).
        // LIFO reads the word port A writes whenever it writes (B only with A: then B's);
        // FIFO compares rd_n, rd_ptr or rd_ptr + 1, with both write addresses
        self.hit_a.next = self.rd_ptr.q.val() == self.wr_ptr.q.val();
        self.hit_b.next = self.rd_ptr.q.val() == self.wr1.val();
        if self.pick.val() {
            self.hit_a.next = self.rd1.val() == self.wr_ptr.q.val();
            self.hit_b.next = self.rd_ptr.q.val() == self.wr_ptr.q.val();
        }
        if self.order_lifo.q.val() {
            self.hit_a.next = true;
            self.hit_b.next = true;
        }
        self.byp.d.next =
            (self.we_a.val() & self.hit_a.val()) | (self.we_b.val() & self.hit_b.val());
        self.byp_data.d.next = self.wdata_a.val();
        if self.we_b.val() & self.hit_b.val() {
            self.byp_data.d.next = self.wdata_b.val();
        }
    }
}

/// A pair queue of `2^N` entries ready to simulate as a top-level block (inputs claimed,
/// connected).
pub fn pair_queue_top<const N: usize, const NP1: usize, const NM1: usize>() -> PairQueue<N, NP1, NM1>
{
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
