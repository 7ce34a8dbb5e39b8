//! WSCG'03's Stack Engine (§4.2) in RTL: its lists (`ListStack`). Format-free: its words
//! are node pointers.

use crate::chip::rtl::LIST_LEVELS;
use rust_hdl::prelude::*;

const _: () = assert!(LIST_LEVELS == 32);

/// WSCG'03's Stack Engine's lists (§4.2): the left and the right list SRAM (`sram_l`,
/// `sram_r`, 2^A node pointers each; the chip's: `chip::rtl::LIST_SRAM_BITS`), the level register λ (`level`), a branch bit per
/// level (`br`) and marker registers per level and side, a list's start and length
/// (`start_l`, `len_l`, `start_r`, `len_r`), and the current list's pointers not yet read
/// (`rem`: a read takes one, entering a list sets its length), level λ's branch bit
/// (`cur_b`) and level λ + 1's write address per side (`wa_l`, `wa_r`: its start plus
/// its length), registers so that neither the sequencer nor an append waits for a
/// multiplexer of the levels' markers. Reads refer to λ, appends to λ + 1, whose lists
/// start where level λ's end: lists are written contiguously and the live ones never
/// overlap. Its clocked model is [`ListStack`](crate::cycle::wscg03::stack_engine::ListStack),
/// equal on every port every clock (tb/wscg03.rs).
///
/// One clock's commands: `clear` (a new query: level 0, every list empty), or any of
/// `append` (`wr_ptr` onto side `wr_side`'s list of level λ + 1; past the SRAM or the last
/// level it is dropped and `overflow` set, sticky), `read` (the current list's next pointer,
/// on `rd_ptr` with `rd_valid` the clock after: the SRAM's synchronous read) and `next_list`
/// (the current list is done: one level down, into its left list if not empty, else its
/// right one; if both are empty, `busy` while stepping up one level a clock, into a
/// level's right list if its branch was left and the list is not empty, `done` at level 0;
/// ignored with an `append`, which would go onto the list it enters).
/// The three are ignored while `busy` or `done`. Level 0 is the host's: the root's pointer
/// is appended onto level 1, then `next`.
///
/// Ports: in `clock`, `clear`, `append`, `wr_side`, `wr_ptr[16]`, `read`, `next_list`; out
/// `level[5]`, `branch`, `remaining[16]` (the current list's pointers not yet read; 0
/// while busy or done),
/// `busy`, `done`, `rd_valid`, `rd_ptr[16]` (0 unless valid), `overflow`.
#[derive(LogicBlock)]
pub struct ListStack<const A: usize> {
    pub clock: Signal<In, Clock>,
    pub clear: Signal<In, Bit>,
    pub append: Signal<In, Bit>,
    pub wr_side: Signal<In, Bit>,
    pub wr_ptr: Signal<In, Bits<16>>,
    pub read: Signal<In, Bit>,
    pub next_list: Signal<In, Bit>,
    pub level: Signal<Out, Bits<5>>,
    pub branch: Signal<Out, Bit>,
    pub remaining: Signal<Out, Bits<16>>,
    pub busy: Signal<Out, Bit>,
    pub done: Signal<Out, Bit>,
    pub rd_valid: Signal<Out, Bit>,
    pub rd_ptr: Signal<Out, Bits<16>>,
    pub overflow: Signal<Out, Bit>,
    sram_l: RAM<Bits<16>, A>,
    sram_r: RAM<Bits<16>, A>,
    idx: [Constant<Bits<5>>; 32],
    cap: Constant<Bits<16>>,
    lvl: DFF<Bits<5>>,
    pos: DFF<Bits<16>>,
    rem: DFF<Bits<16>>,
    cur_b: DFF<Bit>,
    wa_l: DFF<Bits<16>>,
    wa_r: DFF<Bits<16>>,
    up: DFF<Bit>,
    done_r: DFF<Bit>,
    ovf: DFF<Bit>,
    rd_v: DFF<Bit>,
    rd_side: DFF<Bit>,
    br: [DFF<Bit>; 32],
    start_l: [DFF<Bits<16>>; 32],
    start_r: [DFF<Bits<16>>; 32],
    len_l: [DFF<Bits<16>>; 32],
    len_r: [DFF<Bits<16>>; 32],
    // level λ's (current) and λ + 1's markers
    // the branch bit of level λ - 1 (the level stepped up to)
    c_b_up: Signal<Local, Bit>,
    c_cs_l: Signal<Local, Bits<16>>,
    c_cs_r: Signal<Local, Bits<16>>,
    c_cl_l: Signal<Local, Bits<16>>,
    c_cl_r: Signal<Local, Bits<16>>,
    c_ns_l: Signal<Local, Bits<16>>,
    c_ns_r: Signal<Local, Bits<16>>,
    c_nl_l: Signal<Local, Bits<16>>,
    c_nl_r: Signal<Local, Bits<16>>,
    c_l1: Signal<Local, Bits<5>>,
    c_cur_start: Signal<Local, Bits<16>>,
    c_raddr: Signal<Local, Bits<16>>,
    c_idle: Signal<Local, Bit>,
    c_read: Signal<Local, Bit>,
    c_waddr: Signal<Local, Bits<16>>,
    c_wok: Signal<Local, Bit>,
    // the step: down, or up into a right list; the level whose lists it opens
    c_next: Signal<Local, Bit>,
    c_desc: Signal<Local, Bit>,
    c_desc_b: Signal<Local, Bit>,
    c_u_right: Signal<Local, Bit>,
    c_u_zero: Signal<Local, Bit>,
    c_open: Signal<Local, Bit>,
    c_open_lvl: Signal<Local, Bits<5>>,
    c_open_l: Signal<Local, Bits<16>>,
    c_open_r: Signal<Local, Bits<16>>,
}

impl<const A: usize> Default for ListStack<A> {
    fn default() -> Self {
        use crate::rtl::reg_ring::array_init;
        Self {
            clock: Default::default(),
            clear: Default::default(),
            append: Default::default(),
            wr_side: Default::default(),
            wr_ptr: Default::default(),
            read: Default::default(),
            next_list: Default::default(),
            level: Default::default(),
            branch: Default::default(),
            remaining: Default::default(),
            busy: Default::default(),
            done: Default::default(),
            rd_valid: Default::default(),
            rd_ptr: Default::default(),
            overflow: Default::default(),
            sram_l: Default::default(),
            sram_r: Default::default(),
            idx: std::array::from_fn(|j| Constant::new((j as u64).into())),
            cap: Constant::new((1u64 << A).into()),
            lvl: Default::default(),
            pos: Default::default(),
            rem: Default::default(),
            cur_b: Default::default(),
            wa_l: Default::default(),
            wa_r: Default::default(),
            up: Default::default(),
            done_r: Default::default(),
            ovf: Default::default(),
            rd_v: Default::default(),
            rd_side: Default::default(),
            br: array_init(),
            start_l: array_init(),
            start_r: array_init(),
            len_l: array_init(),
            len_r: array_init(),
            c_b_up: Default::default(),
            c_cs_l: Default::default(),
            c_cs_r: Default::default(),
            c_cl_l: Default::default(),
            c_cl_r: Default::default(),
            c_ns_l: Default::default(),
            c_ns_r: Default::default(),
            c_nl_l: Default::default(),
            c_nl_r: Default::default(),
            c_l1: Default::default(),
            c_cur_start: Default::default(),
            c_raddr: Default::default(),
            c_idle: Default::default(),
            c_read: Default::default(),
            c_waddr: Default::default(),
            c_wok: Default::default(),
            c_next: Default::default(),
            c_desc: Default::default(),
            c_desc_b: Default::default(),
            c_u_right: Default::default(),
            c_u_zero: Default::default(),
            c_open: Default::default(),
            c_open_lvl: Default::default(),
            c_open_l: Default::default(),
            c_open_r: Default::default(),
        }
    }
}

/// The kernel, part 1: level λ's and λ + 1's markers; the read of λ's list, the append
/// onto λ + 1's.
struct ListAccess;

impl<const A: usize> crate::rtl::kernel::Kernel<ListAccess> for ListStack<A> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, ovf, rd_v, rd_side);
        self.c_l1.next = self.lvl.q.val() + 1;
        self.c_b_up.next = false;
        self.c_cs_l.next = 0.into();
        self.c_cs_r.next = 0.into();
        self.c_cl_l.next = 0.into();
        self.c_cl_r.next = 0.into();
        self.c_ns_l.next = 0.into();
        self.c_ns_r.next = 0.into();
        self.c_nl_l.next = 0.into();
        self.c_nl_r.next = 0.into();
        for j in 0..32 {
            if self.lvl.q.val() == self.idx[j].val() {
                self.c_cs_l.next = self.start_l[j].q.val();
                self.c_cs_r.next = self.start_r[j].q.val();
                self.c_cl_l.next = self.len_l[j].q.val();
                self.c_cl_r.next = self.len_r[j].q.val();
            }
            if self.lvl.q.val() == self.idx[j].val() + 1 {
                self.c_b_up.next = self.br[j].q.val();
            }
            // level 31 has no level below it: c_l1 wraps to 0 and nothing is appended
            if (self.c_l1.val() == self.idx[j].val()) & (self.lvl.q.val() != 31) {
                self.c_ns_l.next = self.start_l[j].q.val();
                self.c_ns_r.next = self.start_r[j].q.val();
                self.c_nl_l.next = self.len_l[j].q.val();
                self.c_nl_r.next = self.len_r[j].q.val();
            }
        }
        self.c_idle.next = !self.up.q.val() & !self.done_r.q.val();
        self.c_cur_start.next = self.c_cs_l.val();
        if self.cur_b.q.val() {
            self.c_cur_start.next = self.c_cs_r.val();
        }
        self.c_read.next = self.read.val() & self.c_idle.val() & (self.rem.q.val() != 0);
        self.c_waddr.next = self.wa_l.q.val();
        if self.wr_side.val() {
            self.c_waddr.next = self.wa_r.q.val();
        }
        self.c_wok.next = self.append.val()
            & self.c_idle.val()
            & (self.lvl.q.val() != 31)
            & (self.c_waddr.val() < self.cap.val());
        self.ovf.d.next =
            self.ovf.q.val() | (self.append.val() & self.c_idle.val() & !self.c_wok.val());
        self.sram_l.read_clock.next = self.clock.val();
        self.sram_r.read_clock.next = self.clock.val();
        self.sram_l.write_clock.next = self.clock.val();
        self.sram_r.write_clock.next = self.clock.val();
        self.c_raddr.next = self.c_cur_start.val() + self.pos.q.val();
        self.sram_l.read_address.next = self.c_raddr.val().get_bits::<A>(0);
        self.sram_r.read_address.next = self.c_raddr.val().get_bits::<A>(0);
        self.sram_l.write_address.next = self.c_waddr.val().get_bits::<A>(0);
        self.sram_r.write_address.next = self.c_waddr.val().get_bits::<A>(0);
        self.sram_l.write_data.next = self.wr_ptr.val();
        self.sram_r.write_data.next = self.wr_ptr.val();
        self.sram_l.write_enable.next = self.c_wok.val() & !self.wr_side.val();
        self.sram_r.write_enable.next = self.c_wok.val() & self.wr_side.val();
        self.rd_v.d.next = self.c_read.val();
        self.rd_side.d.next = self.cur_b.q.val();
        self.rd_ptr.next = 0.into();
        if self.rd_v.q.val() {
            self.rd_ptr.next = self.sram_l.read_data.val();
            if self.rd_side.q.val() {
                self.rd_ptr.next = self.sram_r.read_data.val();
            }
        }
    }
}

/// Part 2: the step (down on `next`, or up one level a clock), the markers of the level it
/// opens, the appended list's length; `clear`; the outputs.
struct ListStep;

impl<const A: usize> crate::rtl::kernel::Kernel<ListStep> for ListStack<A> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, lvl, pos, rem, cur_b, wa_l, wa_r, up, done_r);
        // down into λ + 1's left list, else its right one; else up
        self.c_next.next = self.next_list.val() & self.c_idle.val() & !self.append.val();
        self.c_desc.next = self.c_next.val()
            & (self.lvl.q.val() != 31)
            & ((self.c_nl_l.val() != 0) | (self.c_nl_r.val() != 0));
        self.c_desc_b.next = self.c_nl_l.val() == 0;
        self.c_u_right.next = self.up.q.val() & !self.cur_b.q.val() & (self.c_cl_r.val() != 0);
        self.c_u_zero.next = self.lvl.q.val() == 0;
        // the level whose lists open: λ + 2 going down (if there is one), λ + 1 going right
        self.c_open.next = (self.c_desc.val() & (self.lvl.q.val() < 30))
            | (self.c_u_right.val() & (self.lvl.q.val() != 31));
        self.c_open_lvl.next = self.lvl.q.val() + 1;
        self.c_open_l.next = self.c_cs_l.val() + self.c_cl_l.val();
        self.c_open_r.next = self.c_cs_r.val() + self.c_cl_r.val();
        if self.c_desc.val() {
            self.c_open_lvl.next = self.lvl.q.val() + 2;
            self.c_open_l.next = self.wa_l.q.val();
            self.c_open_r.next = self.wa_r.q.val();
        }
        // λ + 1's write addresses: one on an append; where the level stepped into opens its
        // next level's lists (down, right), or the level stepped up to's lists end (up)
        if self.c_wok.val() & !self.wr_side.val() {
            self.wa_l.d.next = self.wa_l.q.val() + 1;
        }
        if self.c_wok.val() & self.wr_side.val() {
            self.wa_r.d.next = self.wa_r.q.val() + 1;
        }
        if self.c_desc.val() | self.c_u_right.val() | (self.up.q.val() & !self.c_u_zero.val()) {
            self.wa_l.d.next = self.c_open_l.val();
            self.wa_r.d.next = self.c_open_r.val();
        }
        if self.c_read.val() {
            self.pos.d.next = self.pos.q.val() + 1;
            self.rem.d.next = self.rem.q.val() - 1;
        }
        if self.c_desc.val() | self.c_u_right.val() {
            self.pos.d.next = 0.into();
        }
        // the list entered: λ + 1's left one if not empty, else its right one; λ's right one
        if self.c_desc.val() {
            self.rem.d.next = self.c_nl_l.val();
            if self.c_desc_b.val() {
                self.rem.d.next = self.c_nl_r.val();
            }
        }
        if self.c_u_right.val() {
            self.rem.d.next = self.c_cl_r.val();
        }
        if self.c_desc.val() {
            self.lvl.d.next = self.c_l1.val();
            self.cur_b.d.next = self.c_desc_b.val();
        }
        if self.c_u_right.val() {
            self.cur_b.d.next = true;
        }
        if self.up.q.val() & !self.c_u_right.val() & !self.c_u_zero.val() {
            self.lvl.d.next = self.lvl.q.val() - 1;
            self.cur_b.d.next = self.c_b_up.val();
        }
        if self.c_next.val() & !self.c_desc.val() {
            self.up.d.next = true;
            self.pos.d.next = 0.into();
        }
        if self.up.q.val() & (self.c_u_right.val() | self.c_u_zero.val()) {
            self.up.d.next = false;
            self.done_r.d.next = !self.c_u_right.val();
        }
        for j in 0..32 {
            self.br[j].clock.next = self.clock.val();
            self.start_l[j].clock.next = self.clock.val();
            self.start_r[j].clock.next = self.clock.val();
            self.len_l[j].clock.next = self.clock.val();
            self.len_r[j].clock.next = self.clock.val();
            self.br[j].d.next = self.br[j].q.val();
            self.start_l[j].d.next = self.start_l[j].q.val();
            self.start_r[j].d.next = self.start_r[j].q.val();
            self.len_l[j].d.next = self.len_l[j].q.val();
            self.len_r[j].d.next = self.len_r[j].q.val();
            if self.c_l1.val() == self.idx[j].val() {
                if self.c_desc.val() {
                    self.br[j].d.next = self.c_desc_b.val();
                }
                if self.c_wok.val() & !self.wr_side.val() {
                    self.len_l[j].d.next = self.len_l[j].q.val() + 1;
                }
                if self.c_wok.val() & self.wr_side.val() {
                    self.len_r[j].d.next = self.len_r[j].q.val() + 1;
                }
            }
            if self.c_u_right.val() & (self.lvl.q.val() == self.idx[j].val()) {
                self.br[j].d.next = true;
            }
            if self.c_open.val() & (self.c_open_lvl.val() == self.idx[j].val()) {
                self.start_l[j].d.next = self.c_open_l.val();
                self.start_r[j].d.next = self.c_open_r.val();
                self.len_l[j].d.next = 0.into();
                self.len_r[j].d.next = 0.into();
            }
            if self.clear.val() {
                self.br[j].d.next = false;
                self.start_l[j].d.next = 0.into();
                self.start_r[j].d.next = 0.into();
                self.len_l[j].d.next = 0.into();
                self.len_r[j].d.next = 0.into();
            }
        }
        if self.clear.val() {
            self.lvl.d.next = 0.into();
            self.pos.d.next = 0.into();
            self.rem.d.next = 0.into();
            self.cur_b.d.next = false;
            self.wa_l.d.next = 0.into();
            self.wa_r.d.next = 0.into();
            self.up.d.next = false;
            self.done_r.d.next = false;
            self.ovf.d.next = false;
            self.rd_v.d.next = false;
        }
        self.level.next = self.lvl.q.val();
        self.branch.next = self.cur_b.q.val();
        self.remaining.next = 0.into();
        if self.c_idle.val() {
            self.remaining.next = self.rem.q.val();
        }
        self.busy.next = self.up.q.val();
        self.done.next = self.done_r.q.val();
        self.rd_valid.next = self.rd_v.q.val();
        self.overflow.next = self.ovf.q.val();
    }
}

crate::rtl::kernel::kernel!([const A: usize] ListStack<A>: ListAccess, ListStep);

/// The lists with SRAMs of 2^A pointers ready to simulate as a top-level block.
pub fn list_stack_top<const A: usize>() -> ListStack<A> {
    top_level!(ListStack::<A>::default(); clock, clear, append, wr_side, wr_ptr, read, next_list)
}

/// Verilog of [`list_stack_top`] with SRAMs of 256 pointers (top module `top`): the
/// exported unit, whose SRAMs a generic synthesis makes of flip-flops (the chip's are
/// external SRAMs, WSCG'03 §4).
pub fn verilog_list_stack8() -> String {
    generate_verilog(&list_stack_top::<8>())
}
