//! WSCG'03's CollisionChip (§4, Fig. 4) in RTL, binary32, k = 24 (`CollisionChip`): its
//! core (`ChipCore`), every unit but TRI_UNIT and the result port joined, with DATE'05's
//! host registers, `start`, the memory port and the counters; then TRI_UNIT and the
//! result port around it. Its clocked model is
//! [`cycle::wscg03::clocked::Chip`](crate::cycle::wscg03::clocked::Chip).

use super::sequencer::Sequencer;
use super::stack_engine::ListStack;
use crate::chip::reg;
use crate::chip::rtl::LIST_SRAM_BITS;
use crate::format::Rounding;
use crate::rtl::b32::{MemoryController, TriInput, TriUnit, Wscg03DopUnit};
use crate::rtl::tri_unit::ResultPort;
use rust_hdl::prelude::*;

/// WSCG'03's CollisionChip without TRI_UNIT and its result port: the Stack Engine (its
/// lists, `lists`, and sequencer, `seq`), the Memory Controller (`mc`), the DOP Unit
/// (`dop`) and the Triangle Unit's input stage (`tin`), as the clocked model joins them.
///
/// * Host registers (`host_we`, `host_addr[10]`, `host_data`; `chip::reg`): `MODE` bit 1
///   (first hit), `BASE_*` (24 bits), `PORT` bits 7:4 (requests outstanding less one),
///   `TRI_CACHE` bits 6:0 (A's cache lines less one); below 0x100 the DOP Unit's MMM.
/// * `start` (not running): every unit cleared, the query runs; `busy` until it is done
///   (nothing left in the lists, the sequencer, the ask list, the input stage, TRI_UNIT
///   (`tri_idle`) or memory; after a halt, nothing in flight), then `done`.
/// * First hit: `tri_sure` (a sure verdict at TRI_UNIT's output) halts the query from
///   that clock (`halted` after it): nothing more streams or is offered.
/// * TRI_UNIT's side: the pair register (`pair_valid`, `pair_tag`, `a_word`, `b_word`),
///   taken with `tri_ready`.
/// * Out: the memory port (`mem_req_*`, from registers), the lists' `overflow`, the
///   deepest level (`max_depth`), the counters of aligned DOP tests, pairs into TRI_UNIT,
///   node records and triangle words fetched.
#[derive(LogicBlock)]
pub struct ChipCore {
    pub clock: Signal<In, Clock>,
    pub host_we: Signal<In, Bit>,
    pub host_addr: Signal<In, Bits<10>>,
    pub host_data: Signal<In, Bits<32>>,
    pub start: Signal<In, Bit>,
    pub mem_req_ready: Signal<In, Bit>,
    pub mem_resp_valid: Signal<In, Bit>,
    pub mem_resp_data: Signal<In, Bits<2048>>,
    pub tri_ready: Signal<In, Bit>,
    pub tri_sure: Signal<In, Bit>,
    pub tri_idle: Signal<In, Bit>,
    pub busy: Signal<Out, Bit>,
    pub done: Signal<Out, Bit>,
    pub overflow: Signal<Out, Bit>,
    pub max_depth: Signal<Out, Bits<5>>,
    pub dop_tests: Signal<Out, Bits<32>>,
    pub tri_tests: Signal<Out, Bits<32>>,
    pub node_fetches: Signal<Out, Bits<32>>,
    pub tri_fetches: Signal<Out, Bits<32>>,
    pub mem_req_valid: Signal<Out, Bit>,
    pub mem_req_addr: Signal<Out, Bits<24>>,
    pub pair_valid: Signal<Out, Bit>,
    pub pair_tag: Signal<Out, Bits<32>>,
    pub a_word: Signal<Out, Bits<738>>,
    pub b_word: Signal<Out, Bits<738>>,
    lists: ListStack<LIST_SRAM_BITS>,
    seq: Sequencer,
    mc: MemoryController,
    dop: Wscg03DopUnit<24>,
    tin: TriInput,
    r_mode: Constant<Bits<10>>,
    r_base_na: Constant<Bits<10>>,
    r_base_nb: Constant<Bits<10>>,
    r_base_ta: Constant<Bits<10>>,
    r_base_tb: Constant<Bits<10>>,
    r_port: Constant<Bits<10>>,
    r_tri_cache: Constant<Bits<10>>,
    first: DFF<Bit>,
    base_na: DFF<Bits<24>>,
    base_nb: DFF<Bits<24>>,
    base_ta: DFF<Bits<24>>,
    base_tb: DFF<Bits<24>>,
    port_out: DFF<Bits<4>>,
    mask: DFF<Bits<7>>,
    run: DFF<Bit>,
    done_r: DFF<Bit>,
    halted: DFF<Bit>,
    max_lvl: DFF<Bits<5>>,
    cnt_tri: DFF<Bits<32>>,
    cnt_nf: DFF<Bits<32>>,
    cnt_tf: DFF<Bits<32>>,
    c_clear: Signal<Local, Bit>,
    c_halt: Signal<Local, Bit>,
    c_finished: Signal<Local, Bit>,
}

/// The kernel, part 1: the host registers, start, halt and the end of a query.
struct CoreHost;

impl crate::rtl::kernel::Kernel<CoreHost> for ChipCore {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, first, base_na, base_nb, base_ta, base_tb, port_out, mask);
        dff_setup!(self, clock, run, done_r, halted, max_lvl, cnt_tri, cnt_nf, cnt_tf);
        clock!(self, clock, lists, seq, mc, dop, tin);
        if self.host_we.val() {
            if self.host_addr.val() == self.r_mode.val() {
                self.first.d.next = self.host_data.val().get_bit(1);
            }
            if self.host_addr.val() == self.r_base_na.val() {
                self.base_na.d.next = self.host_data.val().get_bits::<24>(0);
            }
            if self.host_addr.val() == self.r_base_nb.val() {
                self.base_nb.d.next = self.host_data.val().get_bits::<24>(0);
            }
            if self.host_addr.val() == self.r_base_ta.val() {
                self.base_ta.d.next = self.host_data.val().get_bits::<24>(0);
            }
            if self.host_addr.val() == self.r_base_tb.val() {
                self.base_tb.d.next = self.host_data.val().get_bits::<24>(0);
            }
            if self.host_addr.val() == self.r_port.val() {
                self.port_out.d.next = self.host_data.val().get_bits::<4>(4);
            }
            if self.host_addr.val() == self.r_tri_cache.val() {
                self.mask.d.next = self.host_data.val().get_bits::<7>(0);
            }
        }
        self.dop.load_en.next = self.host_we.val() & (self.host_addr.val().get_bits::<2>(8) == 0);
        self.dop.load_addr.next = self.host_addr.val().get_bits::<8>(0);
        self.dop.load_data.next = self.host_data.val();
        // a start clears every unit; a sure verdict halts from its clock
        self.c_clear.next = self.start.val() & !self.run.q.val();
        self.c_halt.next = self.halted.q.val() | (self.first.q.val() & self.tri_sure.val());
        self.c_finished.next = !self.tin.busy.val()
            & self.tri_idle.val()
            & !self.mc.pending.val()
            & (self.halted.q.val()
                | (self.lists.done.val() & self.seq.idle.val() & (self.mc.room.val() == 8)));
        if self.run.q.val() {
            self.halted.d.next = self.c_halt.val();
        }
        if self.run.q.val() & self.c_finished.val() {
            self.run.d.next = false;
            self.done_r.d.next = true;
        }
        if self.c_clear.val() {
            self.run.d.next = true;
            self.done_r.d.next = false;
            self.halted.d.next = false;
        }
        self.busy.next = self.run.q.val() & !self.c_finished.val();
        self.done.next = self.done_r.q.val() | (self.run.q.val() & self.c_finished.val());
    }
}

/// Part 2: the units joined.
struct CoreWire;

impl crate::rtl::kernel::Kernel<CoreWire> for ChipCore {
    #[hdl_gen]
    fn update(&mut self) {
        // the Stack Engine: the sequencer around its lists
        self.lists.clear.next = self.c_clear.val();
        self.lists.append.next = self.seq.append.val();
        self.lists.wr_side.next = self.seq.wr_side.val();
        self.lists.wr_ptr.next = self.seq.wr_ptr.val();
        self.lists.read.next = self.seq.read.val();
        self.lists.next_list.next = self.seq.next_list.val();
        self.seq.clear.next = self.c_clear.val();
        self.seq.halt.next = self.c_halt.val();
        self.seq.level.next = self.lists.level.val();
        self.seq.branch.next = self.lists.branch.val();
        self.seq.remaining.next = self.lists.remaining.val();
        self.seq.ls_busy.next = self.lists.busy.val();
        self.seq.ls_done.next = self.lists.done.val();
        self.seq.rd_valid.next = self.lists.rd_valid.val();
        self.seq.rd_ptr.next = self.lists.rd_ptr.val();
        self.seq.flags_valid.next = self.dop.flags_valid.val();
        self.seq.overlap.next = bit_cast::<2, 1>(self.dop.overlap_l.val().into())
            | (bit_cast::<2, 1>(self.dop.overlap_r.val().into()) << 1);
        self.seq.room.next = self.mc.room.val();
        self.seq.a_valid.next = self.mc.a_valid.val();
        self.seq.al_valid.next = self.mc.al_valid.val();
        self.seq.al_id.next = self.mc.al_id.val();
        self.seq.al_leaf.next = self.mc.al_leaf.val();
        self.seq.al_f0.next = self.mc.al_f0.val();
        self.seq.al_f1.next = self.mc.al_f1.val();
        self.seq.ld_valid.next = self.mc.ld_valid.val();
        self.seq.ld_set.next = self.mc.ld_set.val();
        self.seq.ld_pair.next = self.mc.ld_pair.val();
        self.seq.ld_id.next = self.mc.ld_id.val();
        self.seq.ld_leaf0.next = self.mc.ld_leaf0.val();
        self.seq.ld_leaf1.next = self.mc.ld_leaf1.val();
        self.seq.ld_f00.next = self.mc.ld_f00.val();
        self.seq.ld_f01.next = self.mc.ld_f01.val();
        self.seq.ld_f10.next = self.mc.ld_f10.val();
        self.seq.ld_f11.next = self.mc.ld_f11.val();
        self.seq.leaf_ready.next = self.tin.leaf_ready.val();
        // the Memory Controller
        self.mc.clear.next = self.c_clear.val();
        self.mc.halt.next = self.c_halt.val();
        self.mc.push.next = self.seq.push.val();
        self.mc.push_load.next = self.seq.push_load.val();
        self.mc.push_set.next = self.seq.push_set.val();
        self.mc.push_pair.next = self.seq.push_pair.val();
        self.mc.push_id.next = self.seq.push_id.val();
        self.mc.need_a.next = self.tin.need_a.val();
        self.mc.need_b.next = self.tin.need_b.val();
        self.mc.ta_id.next = self.tin.ta_id.val();
        self.mc.tb_id.next = self.tin.tb_id.val();
        self.mc.base_na.next = self.base_na.q.val();
        self.mc.base_nb.next = self.base_nb.q.val();
        self.mc.base_ta.next = self.base_ta.q.val();
        self.mc.base_tb.next = self.base_tb.q.val();
        self.mc.port_out.next = self.port_out.q.val();
        self.mc.mem_req_ready.next = self.mem_req_ready.val();
        self.mc.mem_resp_valid.next = self.mem_resp_valid.val();
        self.mc.mem_resp_data.next = self.mem_resp_data.val();
        self.mc.busy.next = self.dop.busy.val();
        // the DOP Unit: k = 24, three full bundles a DOP
        self.dop.t_valid.next = self.mc.t_valid.val();
        self.dop.t_set.next = bit_cast::<1, 1>(self.mc.t_set.val().into());
        self.dop.t_side.next = self.mc.t_side.val();
        self.dop.t_entry.next = self.mc.t_entry.val();
        self.dop.t_last.next = self.mc.t_last.val();
        self.dop.t_data.next = self.mc.t_data.val();
        self.dop.a_valid.next = self.mc.a_valid.val();
        self.dop.a_first.next = self.mc.a_first.val();
        self.dop.a_lanes.next = 0xff.into();
        self.dop.a_set.next = bit_cast::<1, 1>(self.mc.a_set.val().into());
        self.dop.a_entry.next = self.mc.a_entry.val();
        self.dop.e.next = self.mc.e.val();
        // the Triangle Unit's input stage
        self.tin.clear.next = self.c_clear.val();
        self.tin.mask.next = self.mask.q.val();
        self.tin.halt.next = self.c_halt.val();
        self.tin.leaf_in.next = self.seq.leaf_valid.val();
        self.tin.leaf_ids.next = bit_cast::<32, 16>(self.seq.leaf_ida.val())
            | (bit_cast::<32, 16>(self.seq.leaf_idb.val()) << 16);
        self.tin.leaf_tag.next = self.seq.leaf_tag.val();
        self.tin.leaf_side.next = self.seq.leaf_side.val();
        self.tin.fill_a.next = self.mc.fill_a.val();
        self.tin.fill_b.next = self.mc.fill_b.val();
        self.tin.fill_id.next = self.mc.fill_id.val();
        self.tin.fill_word.next = self.mc.fill_word.val();
        self.tin.tri_ready.next = self.tri_ready.val();
    }
}

/// Part 3: the counters and the outputs.
struct CoreOut;

impl crate::rtl::kernel::Kernel<CoreOut> for ChipCore {
    #[hdl_gen]
    fn update(&mut self) {
        if self.lists.level.val() > self.max_lvl.q.val() {
            self.max_lvl.d.next = self.lists.level.val();
        }
        if self.tin.pair_valid.val() & self.tri_ready.val() {
            self.cnt_tri.d.next = self.cnt_tri.q.val() + 1;
        }
        if self.mc.mem_req_valid.val() & self.mem_req_ready.val() & self.mc.req_tri.val() {
            self.cnt_tf.d.next = self.cnt_tf.q.val() + 1;
        }
        if self.mc.mem_req_valid.val() & self.mem_req_ready.val() & !self.mc.req_tri.val() {
            self.cnt_nf.d.next = self.cnt_nf.q.val() + 1;
        }
        if self.c_clear.val() {
            self.max_lvl.d.next = 0.into();
            self.cnt_tri.d.next = 0.into();
            self.cnt_nf.d.next = 0.into();
            self.cnt_tf.d.next = 0.into();
        }
        self.overflow.next = self.lists.overflow.val();
        self.max_depth.next = self.max_lvl.q.val();
        if self.lists.level.val() > self.max_lvl.q.val() {
            self.max_depth.next = self.lists.level.val();
        }
        self.dop_tests.next = self.seq.dop_tests.val();
        self.tri_tests.next = self.cnt_tri.q.val();
        self.node_fetches.next = self.cnt_nf.q.val();
        self.tri_fetches.next = self.cnt_tf.q.val();
        self.mem_req_valid.next = self.mc.mem_req_valid.val() & self.run.q.val();
        self.mem_req_addr.next = self.mc.mem_req_addr.val();
        self.pair_valid.next = self.tin.pair_valid.val();
        self.pair_tag.next = self.tin.pair_tag.val();
        self.a_word.next = self.tin.a_word.val();
        self.b_word.next = self.tin.b_word.val();
    }
}

crate::rtl::kernel::kernel!([] ChipCore: CoreHost, CoreWire, CoreOut);

impl Default for ChipCore {
    fn default() -> Self {
        let c = |a: u32| Constant::new((a as u64).into());
        ChipCore {
            clock: Default::default(),
            host_we: Default::default(),
            host_addr: Default::default(),
            host_data: Default::default(),
            start: Default::default(),
            mem_req_ready: Default::default(),
            mem_resp_valid: Default::default(),
            mem_resp_data: Default::default(),
            tri_ready: Default::default(),
            tri_sure: Default::default(),
            tri_idle: Default::default(),
            busy: Default::default(),
            done: Default::default(),
            overflow: Default::default(),
            max_depth: Default::default(),
            dop_tests: Default::default(),
            tri_tests: Default::default(),
            node_fetches: Default::default(),
            tri_fetches: Default::default(),
            mem_req_valid: Default::default(),
            mem_req_addr: Default::default(),
            pair_valid: Default::default(),
            pair_tag: Default::default(),
            a_word: Default::default(),
            b_word: Default::default(),
            lists: Default::default(),
            seq: Default::default(),
            mc: Default::default(),
            dop: Wscg03DopUnit::<24>::new(),
            tin: Default::default(),
            r_mode: c(reg::MODE),
            r_base_na: c(reg::BASE_NA),
            r_base_nb: c(reg::BASE_NB),
            r_base_ta: c(reg::BASE_TA),
            r_base_tb: c(reg::BASE_TB),
            r_port: c(reg::PORT),
            r_tri_cache: c(reg::TRI_CACHE),
            first: Default::default(),
            base_na: Default::default(),
            base_nb: Default::default(),
            base_ta: Default::default(),
            base_tb: Default::default(),
            port_out: Default::default(),
            mask: Default::default(),
            run: Default::default(),
            done_r: Default::default(),
            halted: Default::default(),
            max_lvl: Default::default(),
            cnt_tri: Default::default(),
            cnt_nf: Default::default(),
            cnt_tf: Default::default(),
            c_clear: Default::default(),
            c_halt: Default::default(),
            c_finished: Default::default(),
        }
    }
}

/// The core ready to simulate as a top-level block.
pub fn chip_core_top() -> ChipCore {
    top_level!(ChipCore::default(); clock, host_we, host_addr, host_data, start, mem_req_ready,
        mem_resp_valid, mem_resp_data, tri_ready, tri_sure, tri_idle)
}

/// WSCG'03's CollisionChip (§4, Fig. 4), binary32, k = 24: [`ChipCore`] joined with
/// TRI_UNIT (DATE'05's binary32 `TriUnit`, T.CHECK to nearest-even: the Triangle Unit's
/// tests) and its result port, behind DATE'05's chip's ports
/// ([`crate::rtl::b32::CollisionChip`]: host registers, `start`, `busy`, `done`, the
/// counters, the memory port of 2,048-bit words, the result port). TRI_UNIT's setup words
/// are the host's writes at [`TRI_SETUP`](crate::chip::reg::TRI_SETUP) (address bits 9:5
/// = 8). `max_depth` is the deepest level of the Stack Engine's lists.
#[derive(LogicBlock)]
pub struct CollisionChip {
    pub clock: Signal<In, Clock>,
    pub host_we: Signal<In, Bit>,
    pub host_addr: Signal<In, Bits<10>>,
    pub host_data: Signal<In, Bits<32>>,
    pub start: Signal<In, Bit>,
    pub busy: Signal<Out, Bit>,
    pub done: Signal<Out, Bit>,
    pub overflow: Signal<Out, Bit>,
    pub max_depth: Signal<Out, Bits<5>>,
    pub dop_tests: Signal<Out, Bits<32>>,
    pub tri_tests: Signal<Out, Bits<32>>,
    pub node_fetches: Signal<Out, Bits<32>>,
    pub tri_fetches: Signal<Out, Bits<32>>,
    pub mem_req_valid: Signal<Out, Bit>,
    pub mem_req_addr: Signal<Out, Bits<24>>,
    pub mem_req_ready: Signal<In, Bit>,
    pub mem_resp_valid: Signal<In, Bit>,
    pub mem_resp_data: Signal<In, Bits<2048>>,
    pub res_valid: Signal<Out, Bit>,
    pub res_tag: Signal<Out, Bits<32>>,
    pub res_uncertain: Signal<Out, Bit>,
    pub res_ready: Signal<In, Bit>,
    core: ChipCore,
    tri_unit: TriUnit,
    result: ResultPort,
}

/// The core, TRI_UNIT's setup port and the result port.
struct TopWire;

impl crate::rtl::kernel::Kernel<TopWire> for CollisionChip {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, core, tri_unit, result);
        self.core.host_we.next = self.host_we.val();
        self.core.host_addr.next = self.host_addr.val();
        self.core.host_data.next = self.host_data.val();
        self.core.start.next = self.start.val();
        self.core.mem_req_ready.next = self.mem_req_ready.val();
        self.core.mem_resp_valid.next = self.mem_resp_valid.val();
        self.core.mem_resp_data.next = self.mem_resp_data.val();
        self.core.tri_ready.next = self.tri_unit.in_ready.val();
        self.core.tri_sure.next = self.result.sure_hit.val();
        self.core.tri_idle.next = self.result.open.val() == 0;
        self.tri_unit.load_en.next =
            self.host_we.val() & (self.host_addr.val().get_bits::<5>(5) == 8);
        self.tri_unit.load_addr.next = self.host_addr.val().get_bits::<5>(0);
        self.tri_unit.load_data.next = self.host_data.val();
        self.result.take.next = self.core.pair_valid.val() & self.tri_unit.in_ready.val();
        self.result.out_valid.next = self.tri_unit.out_valid.val();
        self.result.out_hit.next = self.tri_unit.out_hit.val();
        self.result.out_uncertain.next = self.tri_unit.out_uncertain.val();
        self.result.out_tag.next = self.tri_unit.out_tag.val();
        self.result.res_ready.next = self.res_ready.val();
        self.tri_unit.out_ready.next = self.result.out_ready.val();
        self.busy.next = self.core.busy.val();
        self.done.next = self.core.done.val();
        self.overflow.next = self.core.overflow.val();
        self.max_depth.next = self.core.max_depth.val();
        self.dop_tests.next = self.core.dop_tests.val();
        self.tri_tests.next = self.core.tri_tests.val();
        self.node_fetches.next = self.core.node_fetches.val();
        self.tri_fetches.next = self.core.tri_fetches.val();
        self.mem_req_valid.next = self.core.mem_req_valid.val();
        self.mem_req_addr.next = self.core.mem_req_addr.val();
        self.res_valid.next = self.result.res_valid.val();
        self.res_tag.next = self.result.res_tag.val();
        self.res_uncertain.next = self.result.res_uncertain.val();
    }
}

crate::rtl::tri_unit::tri_operands!(
    [] CollisionChip, TriOperands, tri_unit, 32, [core.a_word.val()],
    [core.b_word.val()], [core.pair_tag.val()], [core.pair_valid.val()]
);

crate::rtl::kernel::kernel!([] CollisionChip: TopWire, TriOperands);

impl CollisionChip {
    pub fn new() -> Self {
        CollisionChip {
            clock: Default::default(),
            host_we: Default::default(),
            host_addr: Default::default(),
            host_data: Default::default(),
            start: Default::default(),
            busy: Default::default(),
            done: Default::default(),
            overflow: Default::default(),
            max_depth: Default::default(),
            dop_tests: Default::default(),
            tri_tests: Default::default(),
            node_fetches: Default::default(),
            tri_fetches: Default::default(),
            mem_req_valid: Default::default(),
            mem_req_addr: Default::default(),
            mem_req_ready: Default::default(),
            mem_resp_valid: Default::default(),
            mem_resp_data: Default::default(),
            res_valid: Default::default(),
            res_tag: Default::default(),
            res_uncertain: Default::default(),
            res_ready: Default::default(),
            core: Default::default(),
            tri_unit: TriUnit::new(Rounding::NearestEven),
            result: Default::default(),
        }
    }
}

impl CollisionChip {
    /// The values of its traversal signals [`WSCG03`](crate::chip::probes::WSCG03) (in
    /// that order) as the logic shows them now: what the lockstep check compares and the
    /// traversal VCD shows (scripts/gtkw/chip_wscg03_b32_k24.gtkw).
    pub fn probe(&self) -> Vec<u64> {
        let x = |v: bool| v as u64;
        let c = &self.core;
        let (ls, seq, mc, dop, t) = (&c.lists, &c.seq, &c.mc, &c.dop, &self.tri_unit);
        let (leaf, out) = (seq.leaf_tag.val().to_u64(), t.out_tag.val().to_u64());
        vec![
            x(self.start.val()),
            x(self.busy.val()),
            x(self.done.val()),
            x(self.overflow.val()),
            x(c.c_halt.val()),
            ls.level.val().to_u64(),
            x(ls.branch.val()),
            ls.remaining.val().to_u64(),
            x(ls.busy.val()),
            x(ls.done.val()),
            x(seq.read.val()),
            x(seq.next_list.val()),
            x(seq.append.val()),
            x(seq.wr_side.val()),
            seq.wr_ptr.val().to_u64(),
            x(ls.rd_valid.val()),
            ls.rd_ptr.val().to_u64(),
            seq.lists.val().to_u64(),
            x(seq.push.val()),
            x(seq.push_load.val()),
            x(seq.push_set.val()),
            x(seq.push_pair.val()),
            seq.push_id.val().to_u64(),
            mc.room.val().to_u64(),
            x(self.mem_req_valid.val()),
            x(self.mem_req_ready.val()),
            self.mem_req_addr.val().to_u64(),
            x(self.mem_resp_valid.val()),
            x(mc.t_valid.val()),
            x(mc.a_valid.val()),
            dop.busy.val().to_u64(),
            x(dop.flags_valid.val()),
            x(dop.overlap_l.val()) | x(dop.overlap_r.val()) << 1,
            x(seq.leaf_valid.val()),
            x(c.tin.leaf_ready.val()),
            leaf & 0xffff,
            leaf >> 16 & 0xffff,
            x(c.pair_valid.val()),
            x(t.in_ready.val()),
            x(t.out_valid.val()),
            x(t.out_hit.val()),
            x(t.out_uncertain.val()),
            out & 0xffff,
            out >> 16 & 0xffff,
            x(self.res_valid.val()),
            x(self.res_uncertain.val()),
            self.res_tag.val().to_u64() & 0xffff,
            self.res_tag.val().to_u64() >> 16,
            self.dop_tests.val().to_u64(),
            self.tri_tests.val().to_u64(),
            self.node_fetches.val().to_u64(),
            self.tri_fetches.val().to_u64(),
        ]
    }
}

impl Default for CollisionChip {
    fn default() -> Self {
        Self::new()
    }
}

/// The chip ready to simulate as a top-level block. Large (TRI_UNIT): build it on a thread
/// with a big stack.
pub fn chip_top() -> CollisionChip {
    top_level!(CollisionChip::new(); clock, host_we, host_addr, host_data, start,
        mem_req_ready, mem_resp_valid, mem_resp_data, res_ready)
}
