//! D_CNTR (DATE'05 §4.3), the traversal controller: the pair queue ([`PairQueue`], golden
//! [`cycle::d_cntr::QueueModel`](crate::cycle::d_cntr::QueueModel)) and around it the
//! control that pops entries ahead, issues their pairs to the DOP unit and pushes the
//! children of its results ([`DCntr`], the chip's). Entry word layout:
//! [`cycle::d_cntr`](crate::cycle::d_cntr) (`pack` / `unpack`).

use crate::rtl::kernel::kernel;
use crate::rtl::reg_ring::RegRing;
use rust_hdl::prelude::*;

mod pair_queue;
mod vectors;
pub use pair_queue::{pair_queue_top, verilog_pair_queue, PairQueue, W};
pub use vectors::{pair_queue_vectors, random_ops};

// DCntr reads the entry word's fields (`cycle::d_cntr::pack`): node ids at bits 0, 16
// (pair 0's a, b), 33, 49 (pair 1's), flips at 32, 65, `len - 1` at 66.
const _: () = assert!(W == 67);

/// D_CNTR (DATE'05 §4.3), the traversal controller around its [`PairQueue`]: the pair
/// buffer of entries popped ahead of the DOP unit, the issue of their pairs to the DOP
/// unit, and the child entries its results push. Golden: the entry and issue logic of
/// [`cycle::chip`](crate::cycle::chip) (no unit there of its own: it shares its state with
/// the memory port and the held words, so it is checked in the chip, tb/rtl_chip.rs);
/// cycle semantics: docs/explanation/architecture.md, "Cycle semantics" (Pop, Issue, DOP result).
///
/// Ports:
///
/// * query: in `clear` (a start: the queue cleared with `lifo` latched, the pair buffer
///   emptied), `lifo`, `push_root`, `root[32]` (the root pair, pushed as a one-pair entry
///   while `push_root`), `go` (running, not halted), the limits of host register [`PORT`](crate::chip::reg::PORT):
///   `pf[5]` (pairs prefetched), `one` (an issue every clock), `credit_lim[6]`;
///   `leaf_count[6]` (leaf pairs waiting, counted against the credit), `id_mask[16]` (the
///   bits of a node id that name its record: all of them in the `words` layout; in
///   `records` all but the slot field, `id = record << s | slot`, so that a pair shares the
///   pair before's record, not only its node).
/// * the queue's state: out `empty`, `count[NP1]`, `max_count[NP1]`, `overflow`, `push`.
/// * pop: out `pop`, `pop_entry[67]` (the entry popped), `pop_fetch[4]` (which of its node
///   records A0 B0 A1 B1 the memory port must fetch: those the pair before does not share).
/// * the current pair (pair 0, then 1, of the buffer's head entry): out `ent_valid`,
///   `cur_a[16]`, `cur_b[16]`, `cur_flip`, `cur_fa`, `cur_fb` (it takes its A, B word from
///   the node-word FIFOs, not the last pair's); in `wa_empty`, `wb_empty` (those FIFOs);
///   out `need_na`, `need_nb` (it waits for them), `issue` (it enters the DOP unit).
/// * DOP results: in `dop_valid`, `dop_overlap`, `side[99]` (the pair's ids, flip, leaf
///   bits and children from the DOP unit's side delay line); out `r_a`, `r_b`,
///   `r_a_leaf`, `r_b_leaf`, `leaf_in` and `leaf_pair[64]` (an overlapping leaf pair for
///   TRI_UNIT: A's and B's first leaf field, the triangle index, in bits 31:0, their
///   second, the triangle's record in the `records` layout, in 63:32), `inflight[5]` (DOP
///   tests in flight), `pend` (a second child entry waits).
#[derive(LogicBlock)]
pub struct DCntr<const N: usize, const NP1: usize, const NM1: usize> {
    pub clock: Signal<In, Clock>,
    pub clear: Signal<In, Bit>,
    pub lifo: Signal<In, Bit>,
    pub push_root: Signal<In, Bit>,
    pub root: Signal<In, Bits<32>>,
    pub go: Signal<In, Bit>,
    pub pf: Signal<In, Bits<5>>,
    pub one: Signal<In, Bit>,
    pub credit_lim: Signal<In, Bits<6>>,
    pub leaf_count: Signal<In, Bits<6>>,
    pub id_mask: Signal<In, Bits<16>>,
    pub wa_empty: Signal<In, Bit>,
    pub wb_empty: Signal<In, Bit>,
    pub dop_valid: Signal<In, Bit>,
    pub dop_overlap: Signal<In, Bit>,
    pub side: Signal<In, Bits<99>>,
    pub empty: Signal<Out, Bit>,
    pub count: Signal<Out, Bits<NP1>>,
    pub max_count: Signal<Out, Bits<NP1>>,
    pub overflow: Signal<Out, Bit>,
    pub push: Signal<Out, Bit>,
    pub pop: Signal<Out, Bit>,
    pub pop_entry: Signal<Out, Bits<W>>,
    pub pop_fetch: Signal<Out, Bits<4>>,
    pub ent_valid: Signal<Out, Bit>,
    pub cur_a: Signal<Out, Bits<16>>,
    pub cur_b: Signal<Out, Bits<16>>,
    pub cur_flip: Signal<Out, Bits<1>>,
    pub cur_fa: Signal<Out, Bit>,
    pub cur_fb: Signal<Out, Bit>,
    pub need_na: Signal<Out, Bit>,
    pub need_nb: Signal<Out, Bit>,
    pub issue: Signal<Out, Bit>,
    pub r_a: Signal<Out, Bits<16>>,
    pub r_b: Signal<Out, Bits<16>>,
    pub r_a_leaf: Signal<Out, Bit>,
    pub r_b_leaf: Signal<Out, Bit>,
    pub leaf_in: Signal<Out, Bit>,
    pub leaf_pair: Signal<Out, Bits<64>>,
    pub inflight: Signal<Out, Bits<5>>,
    pub pend: Signal<Out, Bit>,
    queue: PairQueue<N, NP1, NM1>,
    // the pair buffer: a ring of PAIR_BUF entries, each with its pairs' fetch bits A0 B0 A1 B1
    ahd_ent: RegRing<W, { crate::chip::rtl::PAIR_BUF }>,
    ahd_fetch: RegRing<4, { crate::chip::rtl::PAIR_BUF }>,
    ahd_head: DFF<Bits<4>>,
    ahd_tail: DFF<Bits<4>>,
    ahd_pairs: DFF<Bits<5>>,
    ent_second: DFF<Bit>,
    // the last pair popped (its node words are the next pair's if the ids repeat)
    last_ok: DFF<Bit>,
    last_a: DFF<Bits<16>>,
    last_b: DFF<Bits<16>>,
    last_issue: DFF<Bit>,
    inflight_r: DFF<Bits<5>>,
    pend_r: DFF<Bit>,
    pend_data: DFF<Bits<W>>,
    c_one16: Constant<Bits<16>>,
    c_two: Constant<Bits<W>>,
    head_ent: Signal<Local, Bits<W>>,
    head_fetch: Signal<Local, Bits<4>>,
    ent_last: Signal<Local, Bit>,
    credit: Signal<Local, Bits<6>>,
    room: Signal<Local, Bit>,
    child_push: Signal<Local, Bit>,
    top: Signal<Local, Bits<W>>,
    top_two: Signal<Local, Bit>,
    fetch_a0: Signal<Local, Bit>,
    fetch_b0: Signal<Local, Bit>,
    fetch_a1: Signal<Local, Bit>,
    fetch_b1: Signal<Local, Bit>,
    // a DOP result: its pair and nodes, the child entries
    r_flip: Signal<Local, Bit>,
    r_a0: Signal<Local, Bits<16>>,
    r_a1: Signal<Local, Bits<16>>,
    r_b0: Signal<Local, Bits<16>>,
    r_b1: Signal<Local, Bits<16>>,
    r_hit: Signal<Local, Bit>,
    xa: Signal<Local, Bits<16>>,
    xb: Signal<Local, Bits<16>>,
    ya: Signal<Local, Bits<16>>,
    yb: Signal<Local, Bits<16>>,
    p0a: Signal<Local, Bits<16>>,
    p0b: Signal<Local, Bits<16>>,
    p1a: Signal<Local, Bits<16>>,
    p1b: Signal<Local, Bits<16>>,
    e0: Signal<Local, Bits<W>>,
    e1: Signal<Local, Bits<W>>,
}

impl<const N: usize, const NP1: usize, const NM1: usize> Default for DCntr<N, NP1, NM1> {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            clear: Default::default(),
            lifo: Default::default(),
            push_root: Default::default(),
            root: Default::default(),
            go: Default::default(),
            pf: Default::default(),
            one: Default::default(),
            credit_lim: Default::default(),
            leaf_count: Default::default(),
            id_mask: Default::default(),
            wa_empty: Default::default(),
            wb_empty: Default::default(),
            dop_valid: Default::default(),
            dop_overlap: Default::default(),
            side: Default::default(),
            empty: Default::default(),
            count: Default::default(),
            max_count: Default::default(),
            overflow: Default::default(),
            push: Default::default(),
            pop: Default::default(),
            pop_entry: Default::default(),
            pop_fetch: Default::default(),
            ent_valid: Default::default(),
            cur_a: Default::default(),
            cur_b: Default::default(),
            cur_flip: Default::default(),
            cur_fa: Default::default(),
            cur_fb: Default::default(),
            need_na: Default::default(),
            need_nb: Default::default(),
            issue: Default::default(),
            r_a: Default::default(),
            r_b: Default::default(),
            r_a_leaf: Default::default(),
            r_b_leaf: Default::default(),
            leaf_in: Default::default(),
            leaf_pair: Default::default(),
            inflight: Default::default(),
            pend: Default::default(),
            queue: Default::default(),
            ahd_ent: Default::default(),
            ahd_fetch: Default::default(),
            ahd_head: Default::default(),
            ahd_tail: Default::default(),
            ahd_pairs: Default::default(),
            ent_second: Default::default(),
            last_ok: Default::default(),
            last_a: Default::default(),
            last_b: Default::default(),
            last_issue: Default::default(),
            inflight_r: Default::default(),
            pend_r: Default::default(),
            pend_data: Default::default(),
            c_one16: Constant::new(1.into()),
            c_two: Constant::new(
                Bits::<W>::default()
                    .replace_bit(65, true)
                    .replace_bit(66, true),
            ),
            head_ent: Default::default(),
            head_fetch: Default::default(),
            ent_last: Default::default(),
            credit: Default::default(),
            room: Default::default(),
            child_push: Default::default(),
            top: Default::default(),
            top_two: Default::default(),
            fetch_a0: Default::default(),
            fetch_b0: Default::default(),
            fetch_a1: Default::default(),
            fetch_b1: Default::default(),
            r_flip: Default::default(),
            r_a0: Default::default(),
            r_a1: Default::default(),
            r_b0: Default::default(),
            r_b1: Default::default(),
            r_hit: Default::default(),
            xa: Default::default(),
            xb: Default::default(),
            ya: Default::default(),
            yb: Default::default(),
            p0a: Default::default(),
            p0b: Default::default(),
            p1a: Default::default(),
            p1b: Default::default(),
            e0: Default::default(),
            e1: Default::default(),
        }
    }
}

kernel!([const N: usize, const NP1: usize, const NM1: usize] DCntr<N, NP1, NM1>: Issue, Pop, Children);

/// The pair buffer's head entry, its current pair's node words, and the issue of that pair
/// to the DOP unit.
struct Issue;

impl<const N: usize, const NP1: usize, const NM1: usize> crate::rtl::kernel::Kernel<Issue>
    for DCntr<N, NP1, NM1>
{
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, ahd_head, ahd_tail, ahd_pairs, ent_second, last_ok, last_a, last_b);
        dff_setup!(self, clock, last_issue, inflight_r, pend_r, pend_data);
        clock!(self, clock, queue, ahd_ent, ahd_fetch);
        // ---- the head entry of the pair buffer and its current pair (fetch bits: which node
        // words the pair takes from the word FIFOs, the others are the last pair's)
        self.ahd_ent.rsel.next = self.c_one16.val() << self.ahd_head.q.val();
        self.ahd_fetch.rsel.next = self.c_one16.val() << self.ahd_head.q.val();
        self.head_ent.next = self.ahd_ent.rdata.val();
        self.head_fetch.next = self.ahd_fetch.rdata.val();
        self.ent_valid.next = self.ahd_pairs.q.val() != 0;
        self.cur_a.next = self.head_ent.val().get_bits::<16>(0);
        self.cur_b.next = self.head_ent.val().get_bits::<16>(16);
        self.cur_flip.next = self.head_ent.val().get_bits::<1>(32);
        self.cur_fa.next = self.head_fetch.val().get_bit(0);
        self.cur_fb.next = self.head_fetch.val().get_bit(1);
        if self.ent_second.q.val() {
            self.cur_a.next = self.head_ent.val().get_bits::<16>(33);
            self.cur_b.next = self.head_ent.val().get_bits::<16>(49);
            self.cur_flip.next = self.head_ent.val().get_bits::<1>(65);
            self.cur_fa.next = self.head_fetch.val().get_bit(2);
            self.cur_fb.next = self.head_fetch.val().get_bit(3);
        }
        self.ent_last.next = self.ent_second.q.val() | !self.head_ent.val().get_bit(66);
        self.need_na.next =
            self.go.val() & (self.ahd_pairs.q.val() != 0) & self.cur_fa.val() & self.wa_empty.val();
        self.need_nb.next =
            self.go.val() & (self.ahd_pairs.q.val() != 0) & self.cur_fb.val() & self.wb_empty.val();
        // ---- issue a pair to the DOP unit once both words are held. Issues are at least two
        // clocks apart (so child entries can be pushed one per clock) unless `one` (the
        // queue's second write port takes both in one clock), and every test in flight has
        // a place in the leaf FIFO (the credit).
        self.credit.next = bit_cast::<6, 5>(self.inflight_r.q.val()) + self.leaf_count.val();
        self.issue.next = self.go.val()
            & (self.ahd_pairs.q.val() != 0)
            & !self.need_na.val()
            & !self.need_nb.val()
            & !(self.last_issue.q.val() & !self.one.val())
            & (self.credit.val() < self.credit_lim.val());
        self.last_issue.d.next = self.issue.val();
        // an issue moves to the entry's second pair, or to the next entry
        if self.issue.val() {
            self.ent_second.d.next = true;
            if self.ent_last.val() {
                self.ent_second.d.next = false;
                self.ahd_head.d.next = self.ahd_head.q.val() + 1;
            }
        }
    }
}

/// A DOP result taken apart, and the pop of the next entry into the pair buffer with the
/// node words its pairs fetch.
struct Pop;

impl<const N: usize, const NP1: usize, const NM1: usize> crate::rtl::kernel::Kernel<Pop>
    for DCntr<N, NP1, NM1>
{
    #[hdl_gen]
    fn update(&mut self) {
        // ---- a DOP result: child entries (DOP-sharing order), or a leaf pair
        self.r_a.next = self.side.val().get_bits::<16>(0);
        self.r_b.next = self.side.val().get_bits::<16>(16);
        self.r_flip.next = self.side.val().get_bit(32);
        self.r_a_leaf.next = self.side.val().get_bit(33);
        self.r_a0.next = self.side.val().get_bits::<16>(34);
        self.r_a1.next = self.side.val().get_bits::<16>(50);
        self.r_b_leaf.next = self.side.val().get_bit(66);
        self.r_b0.next = self.side.val().get_bits::<16>(67);
        self.r_b1.next = self.side.val().get_bits::<16>(83);
        self.r_hit.next = self.dop_valid.val() & self.dop_overlap.val();
        // ---- pop the next entry when the current one is done (or issues its last pair);
        // in LIFO order not while a child entry is pushed, so that the children are on top
        // when popped, the first child first (depth first as far as the DOP pipeline allows)
        self.child_push.next =
            self.pend_r.q.val() | (self.r_hit.val() & !(self.r_a_leaf.val() & self.r_b_leaf.val()));
        // ... while the pair buffer holds at most `pf` pairs (0: empty), counted before this
        // clock's issue, so that the issue's logic is not on the path into the queue's read
        // address (it set the chip's clock)
        self.room.next = self.ahd_pairs.q.val() <= self.pf.val();
        self.pop.next = self.go.val()
            & !self.queue.empty.val()
            & self.room.val()
            & !(self.lifo.val() & self.child_push.val());
        self.queue.pop.next = self.pop.val();
        // the popped entry's pairs fetch the node words the pair before did not use (one
        // bit each: a `!` inside a wider Verilog expression would invert the zero-extended
        // bits too)
        self.top.next = self.queue.top_data.val();
        self.top_two.next = self.top.val().get_bit(66);
        // (ids compared under `id_mask`, without their slot field in the `records` layout:
        // the record's)
        self.fetch_a0.next = !(self.last_ok.q.val()
            & ((self.last_a.q.val() & self.id_mask.val())
                == (self.top.val().get_bits::<16>(0) & self.id_mask.val())));
        self.fetch_b0.next = !(self.last_ok.q.val()
            & ((self.last_b.q.val() & self.id_mask.val())
                == (self.top.val().get_bits::<16>(16) & self.id_mask.val())));
        self.fetch_a1.next = self.top_two.val()
            & ((self.top.val().get_bits::<16>(33) & self.id_mask.val())
                != (self.top.val().get_bits::<16>(0) & self.id_mask.val()));
        self.fetch_b1.next = self.top_two.val()
            & ((self.top.val().get_bits::<16>(49) & self.id_mask.val())
                != (self.top.val().get_bits::<16>(16) & self.id_mask.val()));
        self.pop_fetch.next = bit_cast::<4, 1>(self.fetch_a0.val().into())
            | (bit_cast::<4, 1>(self.fetch_b0.val().into()) << 1)
            | (bit_cast::<4, 1>(self.fetch_a1.val().into()) << 2)
            | (bit_cast::<4, 1>(self.fetch_b1.val().into()) << 3);
        self.pop_entry.next = self.top.val();
        self.ahd_ent.wsel.next = 0.into();
        self.ahd_fetch.wsel.next = 0.into();
        if self.pop.val() {
            self.ahd_ent.wsel.next = self.c_one16.val() << self.ahd_tail.q.val();
            self.ahd_fetch.wsel.next = self.c_one16.val() << self.ahd_tail.q.val();
        }
        self.ahd_ent.wdata.next = self.top.val();
        self.ahd_fetch.wdata.next = self.pop_fetch.val();
        self.ahd_pairs.d.next = self.ahd_pairs.q.val() - bit_cast::<5, 1>(self.issue.val().into());
        if self.pop.val() {
            self.ahd_tail.d.next = self.ahd_tail.q.val() + 1;
            self.ahd_pairs.d.next = self.ahd_pairs.q.val()
                - bit_cast::<5, 1>(self.issue.val().into())
                + 1
                + bit_cast::<5, 1>(self.top_two.val().into());
            self.last_ok.d.next = true;
            self.last_a.d.next = self.top.val().get_bits::<16>(0);
            self.last_b.d.next = self.top.val().get_bits::<16>(16);
            if self.top_two.val() {
                self.last_a.d.next = self.top.val().get_bits::<16>(33);
                self.last_b.d.next = self.top.val().get_bits::<16>(49);
            }
        }
    }
}

/// A hit's child entries (or leaf pair) pushed, the tests in flight counted, the start, and
/// the outputs.
struct Children;

impl<const N: usize, const NP1: usize, const NM1: usize> crate::rtl::kernel::Kernel<Children>
    for DCntr<N, NP1, NM1>
{
    #[hdl_gen]
    fn update(&mut self) {
        // (xa, xb): A's children, (ya, yb): B's, in the pair's flip order
        self.xa.next = self.r_a0.val();
        self.xb.next = self.r_a1.val();
        self.ya.next = self.r_b0.val();
        self.yb.next = self.r_b1.val();
        if self.r_flip.val() {
            self.xa.next = self.r_a1.val();
            self.xb.next = self.r_a0.val();
            self.ya.next = self.r_b1.val();
            self.yb.next = self.r_b0.val();
        }
        // entry 0's pairs (p0a, p0b), (p1a, p1b); entry 1 only for inner/inner
        // inner/inner: [(xa, b0), (xa, b1)], [(xb, b1), (xb, b0)]
        self.p0a.next = self.xa.val();
        self.p0b.next = self.r_b0.val();
        self.p1a.next = self.xa.val();
        self.p1b.next = self.r_b1.val();
        if self.r_b_leaf.val() {
            // inner/leaf: [(xa, b), (xb, b)]
            self.p0b.next = self.r_b.val();
            self.p1a.next = self.xb.val();
            self.p1b.next = self.r_b.val();
        }
        if self.r_a_leaf.val() {
            // leaf/inner: [(a, ya), (a, yb)]
            self.p0a.next = self.r_a.val();
            self.p0b.next = self.ya.val();
            self.p1a.next = self.r_a.val();
            self.p1b.next = self.yb.val();
        }
        self.e0.next = self.c_two.val()
            | bit_cast::<W, 16>(self.p0a.val())
            | (bit_cast::<W, 16>(self.p0b.val()) << 16)
            | (bit_cast::<W, 16>(self.p1a.val()) << 33)
            | (bit_cast::<W, 16>(self.p1b.val()) << 49);
        self.e1.next = self.c_two.val()
            | bit_cast::<W, 16>(self.xb.val())
            | (bit_cast::<W, 16>(self.r_b1.val()) << 16)
            | (bit_cast::<W, 16>(self.xb.val()) << 33)
            | (bit_cast::<W, 16>(self.r_b0.val()) << 49);
        self.queue.clear.next = self.clear.val();
        self.queue.lifo.next = self.lifo.val();
        self.queue.push.next = false;
        self.queue.push_data.next = self.e0.val();
        self.queue.push2.next = false;
        self.queue.push2_data.next = self.e1.val();
        self.pend_r.d.next = false;
        if self.pend_r.q.val() {
            self.queue.push.next = true;
            self.queue.push_data.next = self.pend_data.q.val();
        }
        self.leaf_in.next = self.r_hit.val() & self.r_a_leaf.val() & self.r_b_leaf.val();
        self.leaf_pair.next = bit_cast::<64, 16>(self.r_a0.val())
            | (bit_cast::<64, 16>(self.r_b0.val()) << 16)
            | (bit_cast::<64, 16>(self.r_a1.val()) << 32)
            | (bit_cast::<64, 16>(self.r_b1.val()) << 48);
        if self.r_hit.val() & !(self.r_a_leaf.val() & self.r_b_leaf.val()) {
            self.queue.push.next = true;
            if self.r_a_leaf.val() | self.r_b_leaf.val() {
                self.queue.push_data.next = self.e0.val();
            } else {
                // two entries, in one clock (second write port) or one per clock; LIFO
                // pushes the second first, so that the first is popped first
                self.queue.push2.next = self.one.val();
                self.pend_r.d.next = !self.one.val();
                if self.lifo.val() {
                    self.queue.push_data.next = self.e1.val();
                    self.queue.push2_data.next = self.e0.val();
                    self.pend_data.d.next = self.e0.val();
                } else {
                    self.queue.push_data.next = self.e0.val();
                    self.pend_data.d.next = self.e1.val();
                }
            }
        }
        if self.push_root.val() {
            self.queue.push.next = true;
            self.queue.push_data.next = bit_cast::<W, 32>(self.root.val());
        }
        self.inflight_r.d.next = self.inflight_r.q.val();
        if self.issue.val() & !self.dop_valid.val() {
            self.inflight_r.d.next = self.inflight_r.q.val() + 1;
        }
        if self.dop_valid.val() & !self.issue.val() {
            self.inflight_r.d.next = self.inflight_r.q.val() - 1;
        }
        // ---- a start: the pair buffer empty
        if self.clear.val() {
            self.ahd_head.d.next = 0.into();
            self.ahd_tail.d.next = 0.into();
            self.ahd_pairs.d.next = 0.into();
            self.ent_second.d.next = false;
            self.last_ok.d.next = false;
        }
        self.push.next = self.queue.push.val();
        self.empty.next = self.queue.empty.val();
        self.count.next = self.queue.count.val();
        self.max_count.next = self.queue.max_count.val();
        self.overflow.next = self.queue.overflow.val();
        self.inflight.next = self.inflight_r.q.val();
        self.pend.next = self.pend_r.q.val();
    }
}
