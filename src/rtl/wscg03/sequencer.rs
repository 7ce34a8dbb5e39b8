//! WSCG'03's Stack Engine's sequencer (§4.2) in RTL: around the lists
//! ([`ListStack`](super::stack_engine::ListStack)) it enters each list, asks the Memory
//! Controller for loads and aligned nodes, reads the pointers and turns the DOP Unit's
//! flags into actions. Format-free: its words are node ids and a node word's fields.

use crate::chip::rtl::{LIST_LEVELS, SEQ_ACTIONS, SEQ_READS, WSCG03_COMPARE_LATENCY};
use rust_hdl::prelude::*;

const _: () = assert!(
    LIST_LEVELS == 32 && SEQ_ACTIONS == 35 && SEQ_READS == 8 && WSCG03_COMPARE_LATENCY == 3
);

/// WSCG'03's Stack Engine's sequencer (§4.2). Its clocked model is
/// [`Sequencer`](crate::cycle::wscg03::sequencer::Sequencer), equal on every port every
/// clock (tb/wscg03.rs).
///
/// * The action queue (`act_e`, [`SEQ_ACTIONS`] entries, the head in entry 0, shifted down
///   as it goes): `{leaf, side, a[16], b[16], tag[32]}`, an append of pointer `a` onto
///   side `side`'s list (`append`, `wr_side`, `wr_ptr`, when the lists are idle), or a leaf
///   pair offered to the Triangle Unit (`leaf_valid`, `leaf_ida` = `a`, `leaf_idb` = `b`,
///   `leaf_tag`, `leaf_side`; taken with `leaf_ready`). `clear` leaves the root's append.
/// * A list entered (the lists idle at a level past 0, the ask list not full): its group,
///   B's root at level 1, below the `branch` member of the group one level up (`grp`: per
///   level and member, its leaf bit and id, or its first child's if inner: a sibling pair
///   is a record's two slots). A d' set holding it (`hold`: valid, pair, first id) is
///   entered, else the set the last list did not use is, and the group's load asked for.
/// * Once the current set's group has streamed (`ld_*` into `ldd`, valid when its ids are
///   the set's), its left member's children are asked for into the other set, unless it
///   holds them or the member is a leaf.
/// * A pointer read (`rd_valid`) is asked for as an aligned node against the current set;
///   reads go on while the list has pointers, the ask list 3 free, fewer than [`SEQ_READS`]
///   nodes wait for their flags and fewer than 4 actions for their turn. The list is done
///   (`next_list`) when all are read, flagged and their actions done.
/// * The aligned bundles (`a_valid`) join `cmp` with the fields of a node's last
///   (`al_*`); the DOP Unit's flags (`flags_valid`, `overlap`) leave it in order. A last
///   bundle's flags add per member overlapped: a leaf pair (both leaves: the triangles'
///   records, the tag `n.f0 | x.f0 << 16`), the node's two children, or the node itself
///   (a leaf against an inner member), onto the member's side.
///
/// Outputs are read before the clock's edge (Mealy: they read this clock's inputs) and are
/// 0 when not valid; `idle` (no action waits), `lists` (lists entered) and `dop_tests` (an
/// aligned node against each member of its group) after the last edge.
#[derive(LogicBlock)]
pub struct Sequencer {
    pub clock: Signal<In, Clock>,
    pub clear: Signal<In, Bit>,
    pub halt: Signal<In, Bit>,
    pub level: Signal<In, Bits<5>>,
    pub branch: Signal<In, Bit>,
    pub remaining: Signal<In, Bits<16>>,
    pub ls_busy: Signal<In, Bit>,
    pub ls_done: Signal<In, Bit>,
    pub rd_valid: Signal<In, Bit>,
    pub rd_ptr: Signal<In, Bits<16>>,
    pub flags_valid: Signal<In, Bit>,
    pub overlap: Signal<In, Bits<2>>,
    pub room: Signal<In, Bits<4>>,
    pub a_valid: Signal<In, Bit>,
    pub al_valid: Signal<In, Bit>,
    pub al_id: Signal<In, Bits<16>>,
    pub al_leaf: Signal<In, Bit>,
    pub al_f0: Signal<In, Bits<32>>,
    pub al_f1: Signal<In, Bits<32>>,
    pub ld_valid: Signal<In, Bit>,
    pub ld_set: Signal<In, Bit>,
    pub ld_pair: Signal<In, Bit>,
    pub ld_id: Signal<In, Bits<16>>,
    pub ld_leaf0: Signal<In, Bit>,
    pub ld_leaf1: Signal<In, Bit>,
    pub ld_f00: Signal<In, Bits<32>>,
    pub ld_f01: Signal<In, Bits<32>>,
    pub ld_f10: Signal<In, Bits<32>>,
    pub ld_f11: Signal<In, Bits<32>>,
    pub leaf_ready: Signal<In, Bit>,
    pub append: Signal<Out, Bit>,
    pub wr_side: Signal<Out, Bit>,
    pub wr_ptr: Signal<Out, Bits<16>>,
    pub read: Signal<Out, Bit>,
    pub next_list: Signal<Out, Bit>,
    pub push: Signal<Out, Bit>,
    pub push_load: Signal<Out, Bit>,
    pub push_set: Signal<Out, Bit>,
    pub push_pair: Signal<Out, Bit>,
    pub push_id: Signal<Out, Bits<16>>,
    pub leaf_valid: Signal<Out, Bit>,
    pub leaf_ida: Signal<Out, Bits<16>>,
    pub leaf_idb: Signal<Out, Bits<16>>,
    pub leaf_tag: Signal<Out, Bits<32>>,
    pub leaf_side: Signal<Out, Bit>,
    pub idle: Signal<Out, Bit>,
    pub lists: Signal<Out, Bits<32>>,
    pub dop_tests: Signal<Out, Bits<32>>,
    idx_act: [Constant<Bits<6>>; SEQ_ACTIONS],
    idx_lvl: [Constant<Bits<5>>; LIST_LEVELS],
    idx_cmp: [Constant<Bits<2>>; WSCG03_COMPARE_LATENCY],
    // the actions: bit 0 leaf, 1 side, 2.. a, 18.. b, 34.. tag
    act_e: [DFF<Bits<66>>; SEQ_ACTIONS],
    act_n: DFF<Bits<6>>,
    // per level, members 0 and 1 from bit 0 and 17: leaf, id (its first child's if inner)
    grp: [DFF<Bits<34>>; LIST_LEVELS],
    entered: DFF<Bit>,
    spec: DFF<Bit>,
    cur: DFF<Bit>,
    // per d' set, the group it holds: bit 0 valid, 1 pair, 2.. first id; and the fields
    // last loaded into it: the same, then 18 leaf0, 19 leaf1, 20.. f00, f01, f10, f11
    hold: [DFF<Bits<18>>; 2],
    ldd: [DFF<Bits<148>>; 2],
    inflight: DFF<Bits<4>>,
    // the aligned bundles compared: bit 0 last, 1.. id, 17 leaf, 18.. f0, 50.. f1
    cmp_e: [DFF<Bits<82>>; WSCG03_COMPARE_LATENCY],
    cmp_n: DFF<Bits<2>>,
    n_lists: DFF<Bits<32>>,
    n_tests: DFF<Bits<32>>,
    c_idle: Signal<Local, Bit>,
    c_front: Signal<Local, Bits<66>>,
    c_has: Signal<Local, Bit>,
    c_taken: Signal<Local, Bit>,
    c_grp: Signal<Local, Bits<34>>,
    c_gm: Signal<Local, Bits<17>>,
    c_g_id: Signal<Local, Bits<16>>,
    c_g_pair: Signal<Local, Bit>,
    c_h0: Signal<Local, Bit>,
    c_h1: Signal<Local, Bit>,
    c_hc: Signal<Local, Bits<18>>,
    c_ho: Signal<Local, Bits<18>>,
    c_lc: Signal<Local, Bits<148>>,
    c_loaded: Signal<Local, Bit>,
    c_ho_children: Signal<Local, Bit>,
    c_gw0: Signal<Local, Bits<17>>,
    c_gw1: Signal<Local, Bits<17>>,
    c_gw: Signal<Local, Bits<34>>,
    c_hold_w: Signal<Local, Bits<18>>,
    c_ldd_w: Signal<Local, Bits<148>>,
    c_enter: Signal<Local, Bit>,
    c_enter_set: Signal<Local, Bit>,
    c_spec_done: Signal<Local, Bit>,
    c_flag: Signal<Local, Bit>,
    c_n: Signal<Local, Bits<82>>,
    c_nleaf: Signal<Local, Bit>,
    c_v0: Signal<Local, Bit>,
    c_v1: Signal<Local, Bit>,
    c_e0: Signal<Local, Bits<66>>,
    c_e1: Signal<Local, Bits<66>>,
    c_e2: Signal<Local, Bits<66>>,
    c_e3: Signal<Local, Bits<66>>,
    c_nv1: Signal<Local, Bit>,
    c_nv3: Signal<Local, Bit>,
    c_p0: Signal<Local, Bits<6>>,
    c_p2: Signal<Local, Bits<6>>,
    c_pm: Signal<Local, Bits<2>>,
}

/// The kernel, part 1: the head action, the ask, the lists' command.
struct SeqDecide;

impl crate::rtl::kernel::Kernel<SeqDecide> for Sequencer {
    #[hdl_gen]
    fn update(&mut self) {
        self.c_idle.next = !self.ls_busy.val() & !self.ls_done.val() & !self.halt.val();
        self.c_front.next = self.act_e[0].q.val();
        self.c_has.next = self.act_n.q.val() != 0;
        self.append.next = self.c_has.val() & !self.c_front.val().get_bit(0) & self.c_idle.val();
        self.leaf_valid.next = self.c_has.val() & self.c_front.val().get_bit(0) & !self.halt.val();
        self.c_taken.next = self.append.val() | (self.leaf_valid.val() & self.leaf_ready.val());
        self.wr_side.next = false;
        self.wr_ptr.next = 0.into();
        if self.append.val() {
            self.wr_side.next = self.c_front.val().get_bit(1);
            self.wr_ptr.next = self.c_front.val().get_bits::<16>(2);
        }
        self.leaf_side.next = false;
        self.leaf_ida.next = 0.into();
        self.leaf_idb.next = 0.into();
        self.leaf_tag.next = 0.into();
        if self.leaf_valid.val() {
            self.leaf_side.next = self.c_front.val().get_bit(1);
            self.leaf_ida.next = self.c_front.val().get_bits::<16>(2);
            self.leaf_idb.next = self.c_front.val().get_bits::<16>(18);
            self.leaf_tag.next = self.c_front.val().get_bits::<32>(34);
        }
        // the group a list at `level` would enter, and the sets holding it
        self.c_grp.next = 0.into();
        for j in 0..32 {
            if self.level.val() == self.idx_lvl[j].val() + 1 {
                self.c_grp.next = self.grp[j].q.val();
            }
        }
        if self.branch.val() {
            self.c_gm.next = self.c_grp.val().get_bits::<17>(17);
        } else {
            self.c_gm.next = self.c_grp.val().get_bits::<17>(0);
        }
        self.c_g_id.next = 0.into();
        self.c_g_pair.next = false;
        if self.level.val() != 1 {
            self.c_g_id.next = self.c_gm.val().get_bits::<16>(1);
            self.c_g_pair.next = !self.c_gm.val().get_bit(0);
        }
        self.c_h0.next = self.hold[0].q.val().get_bit(0)
            & (self.hold[0].q.val().get_bit(1) == self.c_g_pair.val())
            & (self.hold[0].q.val().get_bits::<16>(2) == self.c_g_id.val());
        self.c_h1.next = self.hold[1].q.val().get_bit(0)
            & (self.hold[1].q.val().get_bit(1) == self.c_g_pair.val())
            & (self.hold[1].q.val().get_bits::<16>(2) == self.c_g_id.val());
        // the current set's and the other's holds; the current set's fields
        if self.cur.q.val() {
            self.c_hc.next = self.hold[1].q.val();
            self.c_ho.next = self.hold[0].q.val();
            self.c_lc.next = self.ldd[1].q.val();
        } else {
            self.c_hc.next = self.hold[0].q.val();
            self.c_ho.next = self.hold[1].q.val();
            self.c_lc.next = self.ldd[0].q.val();
        }
        self.c_loaded.next = self.c_lc.val().get_bits::<18>(0) == self.c_hc.val();
        self.c_ho_children.next = self.c_ho.val().get_bit(0)
            & self.c_ho.val().get_bit(1)
            & (bit_cast::<32, 16>(self.c_ho.val().get_bits::<16>(2))
                == self.c_lc.val().get_bits::<32>(20));
        // the ask: an aligned node read, else a list entered, else the speculative load
        self.c_enter.next = false;
        self.c_enter_set.next = false;
        self.c_spec_done.next = false;
        self.push.next = false;
        self.push_load.next = false;
        self.push_set.next = false;
        self.push_pair.next = false;
        self.push_id.next = 0.into();
        if self.rd_valid.val() {
            self.push.next = true;
            self.push_set.next = self.cur.q.val();
            self.push_id.next = self.rd_ptr.val();
        } else if self.c_idle.val()
            & (self.room.val() != 0)
            & !self.entered.q.val()
            & (self.level.val() != 0)
        {
            self.c_enter.next = true;
            if self.c_h0.val() {
                self.c_enter_set.next = false;
            } else if self.c_h1.val() {
                self.c_enter_set.next = true;
            } else {
                self.c_enter_set.next = !self.cur.q.val();
                self.push.next = true;
                self.push_load.next = true;
                self.push_set.next = !self.cur.q.val();
                self.push_pair.next = self.c_g_pair.val();
                self.push_id.next = self.c_g_id.val();
            }
        } else if self.c_idle.val()
            & (self.room.val() != 0)
            & self.entered.q.val()
            & self.spec.q.val()
            & self.c_loaded.val()
            & self.c_lc.val().get_bit(0)
        {
            self.c_spec_done.next = true;
            if !self.c_lc.val().get_bit(18) & !self.c_ho_children.val() {
                self.push.next = true;
                self.push_load.next = true;
                self.push_set.next = !self.cur.q.val();
                self.push_pair.next = true;
                self.push_id.next = self.c_lc.val().get_bits::<16>(20);
            }
        }
        self.read.next = self.c_idle.val()
            & self.entered.q.val()
            & (self.remaining.val() != 0)
            & (self.room.val() > 2)
            & (self.inflight.q.val() < 8)
            & (self.act_n.q.val() < 4)
            & (self.level.val() != 0);
        self.next_list.next = self.c_idle.val()
            & self.entered.q.val()
            & (self.remaining.val() == 0)
            & (self.inflight.q.val() == 0)
            & !self.c_has.val();
        self.idle.next = !self.c_has.val();
        self.lists.next = self.n_lists.q.val();
        self.dop_tests.next = self.n_tests.q.val();
    }
}

/// Part 2: a last bundle's flags into up to four actions (per member overlapped, one or
/// two), their places in the queue.
struct SeqFlags;

impl crate::rtl::kernel::Kernel<SeqFlags> for Sequencer {
    #[hdl_gen]
    fn update(&mut self) {
        self.c_n.next = self.cmp_e[0].q.val();
        self.c_flag.next = self.flags_valid.val() & self.c_n.val().get_bit(0);
        self.c_nleaf.next = self.c_n.val().get_bit(17);
        self.c_v0.next =
            self.c_flag.val() & self.overlap.val().get_bit(0) & self.c_lc.val().get_bit(0);
        self.c_v1.next = self.c_flag.val()
            & self.overlap.val().get_bit(1)
            & self.c_lc.val().get_bit(0)
            & self.c_lc.val().get_bit(1);
        self.c_nv1.next = self.c_v0.val() & !self.c_nleaf.val();
        self.c_nv3.next = self.c_v1.val() & !self.c_nleaf.val();
        // side 0 against member 0, side 1 against member 1: its first action, then the
        // second child if the node is inner
        if self.c_nleaf.val() & self.c_lc.val().get_bit(18) {
            self.c_e0.next = 1
                | (bit_cast::<66, 16>(self.c_n.val().get_bits::<16>(50)) << 2)
                | (bit_cast::<66, 16>(self.c_lc.val().get_bits::<16>(52)) << 18)
                | (bit_cast::<66, 32>(
                    self.c_n.val().get_bits::<32>(18) | (self.c_lc.val().get_bits::<32>(20) << 16),
                ) << 34);
        } else if self.c_nleaf.val() {
            self.c_e0.next = bit_cast::<66, 16>(self.c_n.val().get_bits::<16>(1)) << 2;
        } else {
            self.c_e0.next = bit_cast::<66, 16>(self.c_n.val().get_bits::<16>(18)) << 2;
        }
        if self.c_nleaf.val() & self.c_lc.val().get_bit(19) {
            self.c_e2.next = 3
                | (bit_cast::<66, 16>(self.c_n.val().get_bits::<16>(50)) << 2)
                | (bit_cast::<66, 16>(self.c_lc.val().get_bits::<16>(116)) << 18)
                | (bit_cast::<66, 32>(
                    self.c_n.val().get_bits::<32>(18) | (self.c_lc.val().get_bits::<32>(84) << 16),
                ) << 34);
        } else if self.c_nleaf.val() {
            self.c_e2.next = 2 | (bit_cast::<66, 16>(self.c_n.val().get_bits::<16>(1)) << 2);
        } else {
            self.c_e2.next = 2 | (bit_cast::<66, 16>(self.c_n.val().get_bits::<16>(18)) << 2);
        }
        self.c_e1.next = bit_cast::<66, 16>(self.c_n.val().get_bits::<16>(50)) << 2;
        self.c_e3.next = 2 | (bit_cast::<66, 16>(self.c_n.val().get_bits::<16>(50)) << 2);
        self.c_p0.next = self.act_n.q.val() - bit_cast::<6, 1>(self.c_taken.val().into());
        self.c_p2.next = self.c_p0.val();
        if self.c_v0.val() {
            self.c_p2.next = self.c_p0.val() + 1 + bit_cast::<6, 1>(self.c_nv1.val().into());
        }
        self.c_pm.next = self.cmp_n.q.val() - bit_cast::<2, 1>(self.flags_valid.val().into());
        self.c_hold_w.next = 1
            | (bit_cast::<18, 1>(self.push_pair.val().into()) << 1)
            | (bit_cast::<18, 16>(self.push_id.val()) << 2);
        self.c_ldd_w.next = 1
            | (bit_cast::<148, 1>(self.ld_pair.val().into()) << 1)
            | (bit_cast::<148, 16>(self.ld_id.val()) << 2)
            | (bit_cast::<148, 1>(self.ld_leaf0.val().into()) << 18)
            | (bit_cast::<148, 1>(self.ld_leaf1.val().into()) << 19)
            | (bit_cast::<148, 32>(self.ld_f00.val()) << 20)
            | (bit_cast::<148, 32>(self.ld_f01.val()) << 52)
            | (bit_cast::<148, 32>(self.ld_f10.val()) << 84)
            | (bit_cast::<148, 32>(self.ld_f11.val()) << 116);
        // the group as the level keeps it: a leaf's id, an inner member's first child's
        if self.c_lc.val().get_bit(18) {
            self.c_gw0.next = 1 | (bit_cast::<17, 16>(self.c_lc.val().get_bits::<16>(2)) << 1);
        } else {
            self.c_gw0.next = bit_cast::<17, 16>(self.c_lc.val().get_bits::<16>(20)) << 1;
        }
        if self.c_lc.val().get_bit(19) {
            self.c_gw1.next = 1 | (bit_cast::<17, 16>(self.c_lc.val().get_bits::<16>(2) + 1) << 1);
        } else {
            self.c_gw1.next = bit_cast::<17, 16>(self.c_lc.val().get_bits::<16>(84)) << 1;
        }
        self.c_gw.next =
            bit_cast::<34, 17>(self.c_gw0.val()) | (bit_cast::<34, 17>(self.c_gw1.val()) << 17);
    }
}

/// Part 3: the edge.
struct SeqEdge;

impl crate::rtl::kernel::Kernel<SeqEdge> for Sequencer {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, act_n, entered, spec, cur, inflight, cmp_n, n_lists, n_tests);
        self.act_n.d.next = self.c_p2.val()
            + bit_cast::<6, 1>(self.c_v1.val().into())
            + bit_cast::<6, 1>(self.c_nv3.val().into());
        for j in 0..35 {
            self.act_e[j].clock.next = self.clock.val();
            self.act_e[j].d.next = self.act_e[j].q.val();
        }
        for j in 1..35 {
            if self.c_taken.val() {
                self.act_e[j - 1].d.next = self.act_e[j].q.val();
            }
        }
        for j in 0..35 {
            if self.c_v0.val() & (self.c_p0.val() == self.idx_act[j].val()) {
                self.act_e[j].d.next = self.c_e0.val();
            }
            if self.c_nv1.val() & (self.c_p0.val() + 1 == self.idx_act[j].val()) {
                self.act_e[j].d.next = self.c_e1.val();
            }
            if self.c_v1.val() & (self.c_p2.val() == self.idx_act[j].val()) {
                self.act_e[j].d.next = self.c_e2.val();
            }
            if self.c_nv3.val() & (self.c_p2.val() + 1 == self.idx_act[j].val()) {
                self.act_e[j].d.next = self.c_e3.val();
            }
        }
        // the group of the current list's level, from its set's fields
        for j in 0..32 {
            self.grp[j].clock.next = self.clock.val();
            self.grp[j].d.next = self.grp[j].q.val();
            if self.c_flag.val() & (self.level.val() == self.idx_lvl[j].val()) {
                self.grp[j].d.next = self.c_gw.val();
            }
        }
        if self.c_flag.val() {
            self.n_tests.d.next = self.n_tests.q.val()
                + bit_cast::<32, 1>(self.c_lc.val().get_bits::<1>(0))
                + bit_cast::<32, 1>(self.c_lc.val().get_bits::<1>(1));
        }
        self.inflight.d.next = self.inflight.q.val() + bit_cast::<4, 1>(self.read.val().into())
            - bit_cast::<4, 1>(self.c_flag.val().into());
        // the aligned bundles compared: the oldest leaves with its flags
        self.cmp_n.d.next = self.c_pm.val() + bit_cast::<2, 1>(self.a_valid.val().into());
        for j in 0..3 {
            self.cmp_e[j].clock.next = self.clock.val();
            self.cmp_e[j].d.next = self.cmp_e[j].q.val();
        }
        for j in 1..3 {
            if self.flags_valid.val() {
                self.cmp_e[j - 1].d.next = self.cmp_e[j].q.val();
            }
        }
        for j in 0..3 {
            if self.a_valid.val() & (self.c_pm.val() == self.idx_cmp[j].val()) {
                self.cmp_e[j].d.next = bit_cast::<82, 1>(self.al_valid.val().into())
                    | (bit_cast::<82, 16>(self.al_id.val()) << 1)
                    | (bit_cast::<82, 1>(self.al_leaf.val().into()) << 17)
                    | (bit_cast::<82, 32>(self.al_f0.val()) << 18)
                    | (bit_cast::<82, 32>(self.al_f1.val()) << 50);
            }
        }
    }
}

/// Part 4: the sets' registers, the list entered, `clear`.
struct SeqSets;

impl crate::rtl::kernel::Kernel<SeqSets> for Sequencer {
    #[hdl_gen]
    fn update(&mut self) {
        for j in 0..2 {
            self.hold[j].clock.next = self.clock.val();
            self.ldd[j].clock.next = self.clock.val();
            self.hold[j].d.next = self.hold[j].q.val();
            self.ldd[j].d.next = self.ldd[j].q.val();
        }
        if self.push_load.val() & !self.push_set.val() {
            self.hold[0].d.next = self.c_hold_w.val();
        }
        if self.push_load.val() & self.push_set.val() {
            self.hold[1].d.next = self.c_hold_w.val();
        }
        if self.ld_valid.val() & !self.ld_set.val() {
            self.ldd[0].d.next = self.c_ldd_w.val();
        }
        if self.ld_valid.val() & self.ld_set.val() {
            self.ldd[1].d.next = self.c_ldd_w.val();
        }
        if self.c_enter.val() {
            self.entered.d.next = true;
            self.spec.d.next = true;
            self.cur.d.next = self.c_enter_set.val();
            self.n_lists.d.next = self.n_lists.q.val() + 1;
        }
        if self.c_spec_done.val() {
            self.spec.d.next = false;
        }
        if self.next_list.val() {
            self.entered.d.next = false;
        }
        if self.clear.val() {
            self.act_n.d.next = 1.into();
            self.act_e[0].d.next = 0.into();
            self.entered.d.next = true;
            self.spec.d.next = false;
            self.cur.d.next = false;
            self.hold[0].d.next = 0.into();
            self.hold[1].d.next = 0.into();
            self.ldd[0].d.next = 0.into();
            self.ldd[1].d.next = 0.into();
            self.inflight.d.next = 0.into();
            self.cmp_n.d.next = 0.into();
            self.n_lists.d.next = 0.into();
            self.n_tests.d.next = 0.into();
        }
    }
}

crate::rtl::kernel::kernel!([] Sequencer: SeqDecide, SeqFlags, SeqEdge, SeqSets);

impl Default for Sequencer {
    fn default() -> Self {
        Sequencer {
            clock: Default::default(),
            clear: Default::default(),
            halt: Default::default(),
            level: Default::default(),
            branch: Default::default(),
            remaining: Default::default(),
            ls_busy: Default::default(),
            ls_done: Default::default(),
            rd_valid: Default::default(),
            rd_ptr: Default::default(),
            flags_valid: Default::default(),
            overlap: Default::default(),
            room: Default::default(),
            a_valid: Default::default(),
            al_valid: Default::default(),
            al_id: Default::default(),
            al_leaf: Default::default(),
            al_f0: Default::default(),
            al_f1: Default::default(),
            ld_valid: Default::default(),
            ld_set: Default::default(),
            ld_pair: Default::default(),
            ld_id: Default::default(),
            ld_leaf0: Default::default(),
            ld_leaf1: Default::default(),
            ld_f00: Default::default(),
            ld_f01: Default::default(),
            ld_f10: Default::default(),
            ld_f11: Default::default(),
            leaf_ready: Default::default(),
            append: Default::default(),
            wr_side: Default::default(),
            wr_ptr: Default::default(),
            read: Default::default(),
            next_list: Default::default(),
            push: Default::default(),
            push_load: Default::default(),
            push_set: Default::default(),
            push_pair: Default::default(),
            push_id: Default::default(),
            leaf_valid: Default::default(),
            leaf_ida: Default::default(),
            leaf_idb: Default::default(),
            leaf_tag: Default::default(),
            leaf_side: Default::default(),
            idle: Default::default(),
            lists: Default::default(),
            dop_tests: Default::default(),
            idx_act: std::array::from_fn(|j| Constant::new((j as u64).into())),
            idx_lvl: std::array::from_fn(|j| Constant::new((j as u64).into())),
            idx_cmp: std::array::from_fn(|j| Constant::new((j as u64).into())),
            act_e: std::array::from_fn(|_| Default::default()),
            act_n: Default::default(),
            grp: Default::default(),
            entered: Default::default(),
            spec: Default::default(),
            cur: Default::default(),
            hold: Default::default(),
            ldd: Default::default(),
            inflight: Default::default(),
            cmp_e: Default::default(),
            cmp_n: Default::default(),
            n_lists: Default::default(),
            n_tests: Default::default(),
            c_idle: Default::default(),
            c_front: Default::default(),
            c_has: Default::default(),
            c_taken: Default::default(),
            c_grp: Default::default(),
            c_gm: Default::default(),
            c_g_id: Default::default(),
            c_g_pair: Default::default(),
            c_h0: Default::default(),
            c_h1: Default::default(),
            c_hc: Default::default(),
            c_ho: Default::default(),
            c_lc: Default::default(),
            c_loaded: Default::default(),
            c_ho_children: Default::default(),
            c_gw0: Default::default(),
            c_gw1: Default::default(),
            c_gw: Default::default(),
            c_hold_w: Default::default(),
            c_ldd_w: Default::default(),
            c_enter: Default::default(),
            c_enter_set: Default::default(),
            c_spec_done: Default::default(),
            c_flag: Default::default(),
            c_n: Default::default(),
            c_nleaf: Default::default(),
            c_v0: Default::default(),
            c_v1: Default::default(),
            c_e0: Default::default(),
            c_e1: Default::default(),
            c_e2: Default::default(),
            c_e3: Default::default(),
            c_nv1: Default::default(),
            c_nv3: Default::default(),
            c_p0: Default::default(),
            c_p2: Default::default(),
            c_pm: Default::default(),
        }
    }
}

/// The sequencer ready to simulate as a top-level block.
pub fn sequencer_top() -> Sequencer {
    top_level!(Sequencer::default(); clock, clear, halt, level, branch, remaining, ls_busy, ls_done, rd_valid, rd_ptr, flags_valid, overlap, room, a_valid, al_valid, al_id, al_leaf, al_f0, al_f1, ld_valid, ld_set, ld_pair, ld_id, ld_leaf0, ld_leaf1, ld_f00, ld_f01, ld_f10, ld_f11, leaf_ready)
}

/// Verilog of [`sequencer_top`] (top module `top`).
pub fn verilog_sequencer() -> String {
    generate_verilog(&sequencer_top())
}
