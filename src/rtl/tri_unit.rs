//! TRI_UNIT (DATE'05 §4.2): two T.CHECKs and the result FIFO, stamped out per format by
//! `tri_unit!`.

/// TRI_UNIT's ports (documented on `TriUnit`), one list for every TRI_UNIT: declares the
/// block `name` (its doc attributes first) with them, then its own fields `rest`.
/// Arguments: `W` word width.
macro_rules! tri_unit_ports {
    ($W:tt, $(#[$m:meta])* $name:ident { $($rest:tt)* }) => {
        $(#[$m])*
        #[derive(LogicBlock)]
        pub struct $name {
            pub clock: Signal<In, Clock>,
            pub load_en: Signal<In, Bit>,
            pub load_addr: Signal<In, Bits<5>>,
            pub load_data: Signal<In, Bits<$W>>,
            pub a_m_0: [Signal<In, Bits<$W>>; 4],
            pub a_m_1: [Signal<In, Bits<$W>>; 4],
            pub a_m_2: [Signal<In, Bits<$W>>; 4],
            pub a_alpha_m: Signal<In, Bits<$W>>,
            pub a_alpha_f: Signal<In, Bits<$W>>,
            pub a_v_x: [Signal<In, Bits<$W>>; 3],
            pub a_v_y: [Signal<In, Bits<$W>>; 3],
            pub a_v_z: [Signal<In, Bits<$W>>; 3],
            pub a_v_exact: Signal<In, Bit>,
            pub a_degenerate: Signal<In, Bit>,
            pub b_m_0: [Signal<In, Bits<$W>>; 4],
            pub b_m_1: [Signal<In, Bits<$W>>; 4],
            pub b_m_2: [Signal<In, Bits<$W>>; 4],
            pub b_alpha_m: Signal<In, Bits<$W>>,
            pub b_alpha_f: Signal<In, Bits<$W>>,
            pub b_v_x: [Signal<In, Bits<$W>>; 3],
            pub b_v_y: [Signal<In, Bits<$W>>; 3],
            pub b_v_z: [Signal<In, Bits<$W>>; 3],
            pub b_v_exact: Signal<In, Bit>,
            pub b_degenerate: Signal<In, Bit>,
            pub tag: Signal<In, Bits<32>>,
            pub in_valid: Signal<In, Bit>,
            pub in_ready: Signal<Out, Bit>,
            pub out_tag: Signal<Out, Bits<32>>,
            pub out_hit: Signal<Out, Bit>,
            pub out_uncertain: Signal<Out, Bit>,
            pub out_valid: Signal<Out, Bit>,
            pub out_ready: Signal<In, Bit>,
            $($rest)*
        }
    };
}
pub(crate) use tri_unit_ports;

/// A TRI_UNIT block `name` with [`tri_unit_ports!`]' ports at their defaults and its own
/// fields `rest` as given.
macro_rules! tri_unit_new {
    ($name:ident { $($rest:tt)* }) => {
        $name {
            clock: Default::default(),
            load_en: Default::default(),
            load_addr: Default::default(),
            load_data: Default::default(),
            a_m_0: Default::default(),
            a_m_1: Default::default(),
            a_m_2: Default::default(),
            a_alpha_m: Default::default(),
            a_alpha_f: Default::default(),
            a_v_x: Default::default(),
            a_v_y: Default::default(),
            a_v_z: Default::default(),
            a_v_exact: Default::default(),
            a_degenerate: Default::default(),
            b_m_0: Default::default(),
            b_m_1: Default::default(),
            b_m_2: Default::default(),
            b_alpha_m: Default::default(),
            b_alpha_f: Default::default(),
            b_v_x: Default::default(),
            b_v_y: Default::default(),
            b_v_z: Default::default(),
            b_v_exact: Default::default(),
            b_degenerate: Default::default(),
            tag: Default::default(),
            in_valid: Default::default(),
            in_ready: Default::default(),
            out_tag: Default::default(),
            out_hit: Default::default(),
            out_uncertain: Default::default(),
            out_valid: Default::default(),
            out_ready: Default::default(),
            $($rest)*
        }
    };
}
pub(crate) use tri_unit_new;

/// Stamps out `TriUnit` in the calling module (which must also hold `TCheck`).
/// Arguments: `W` word width.
macro_rules! tri_unit {
    ($W:tt) => {
        /// log2 of the result FIFO's entries.
        const TRI_FIFO_BITS: usize = $crate::chip::rtl::TRI_FIFO_BITS;
        declare_sync_fifo!(TriFifo, Bits<34>, 256, 1);

        $crate::rtl::tri_unit::tri_unit_ports! {
            $W,
            /// TRI_UNIT: is triangle a of A intersecting triangle b of B? Golden
            /// [`tri_unit`](crate::golden::tri_unit::tri_unit), bit for bit: `tc_ab` tests A's
            /// edges against U(B) (B's leaf, the frame map M_AB), `tc_ba`
            /// B's edges against U(A) (A's leaf, M_BA); a degenerate leaf leaves its direction
            /// unknown; the verdict is the Kleene OR of the two: intersecting (`hit`), separate,
            /// or `uncertain` (the host settles it with the exact oracle).
            ///
            /// Ports (words in the format):
            ///
            /// * per query, a write port for the frame maps: in `load_en`, `load_addr[5]`,
            ///   `load_data[W]`; address `4 i + c` (i < 3, c < 4) writes `M_AB[i][c]`, 12 and 13
            ///   its error words (beta_m, beta_f), 14 A's scale, `16 + 4 i + c` `M_BA[i][c]`, 28
            ///   and 29 its error words, 30 B's scale. Written on the rising edge while
            ///   `load_en` is high.
            /// * per pair (valid/ready): in `a_*`, `b_*` = the two leaves' triangle words
            ///   (`m_0[4]`, `m_1[4]`, `m_2[4]` = M rows, `alpha_m`, `alpha_f`,
            ///   `v_x[3]`, `v_y[3]`, `v_z[3]` = vertices, `v_exact`, `degenerate`),
            ///   `tag[32]` (the pair id), `in_valid`; out `in_ready`. A pair is taken on a
            ///   rising edge with `in_valid` and `in_ready` high.
            /// * results (valid/ready): out `out_tag[32]`, `out_hit`, `out_uncertain`,
            ///   `out_valid`; in `out_ready`. A result leaves on a rising edge with
            ///   `out_valid` and `out_ready` high, in the order the pairs came in.
            ///
            /// Timing: a pair taken at edge t (presented in cycle t) is at the FIFO's write
            /// port in cycle t + 52 (the T.CHECKs, [`TCheck::LATENCY`]) and at the output
            /// (`out_valid`) in cycle t + 54 (the FIFO's write and read registers).
            /// Back-pressure: `in_ready` is low while 256 pairs (the FIFO's depth) are taken
            /// and not yet read out (`count`), so the FIFO never overflows and no result is
            /// lost; a reader that is always ready sees one result per clock.
            TriUnit {
                // per-query registers: rows of M_AB, M_BA; their error words; the scales
                addr_0: [Constant<Bits<5>>; 4],
                addr_1: [Constant<Bits<5>>; 4],
                addr_2: [Constant<Bits<5>>; 4],
                ab_0: [DFF<Bits<$W>>; 4],
                ab_1: [DFF<Bits<$W>>; 4],
                ab_2: [DFF<Bits<$W>>; 4],
                ab_bm: DFF<Bits<$W>>,
                ab_bf: DFF<Bits<$W>>,
                ab_s: DFF<Bits<$W>>,
                ba_0: [DFF<Bits<$W>>; 4],
                ba_1: [DFF<Bits<$W>>; 4],
                ba_2: [DFF<Bits<$W>>; 4],
                ba_bm: DFF<Bits<$W>>,
                ba_bf: DFF<Bits<$W>>,
                ba_s: DFF<Bits<$W>>,
                // the two directions
                tc_ab: TCheck,
                tc_ba: TCheck,
                degenerate_wait: Delay<Bits<2>, { TCheck::LATENCY }>,
                d1_t: Signal<Local, Bit>,
                d1_f: Signal<Local, Bit>,
                d2_t: Signal<Local, Bit>,
                d2_f: Signal<Local, Bit>,
                c_hit: Constant<Bits<34>>,
                c_uncertain: Constant<Bits<34>>,
                c_full: Constant<Bits<9>>,
                result: Signal<Local, Bits<34>>,
                fifo: TriFifo,
                // pairs taken and not yet read out
                count: DFF<Bits<9>>,
                take: Signal<Local, Bit>,
                give: Signal<Local, Bit>,
            }
        }

        impl TriUnit {
            /// Pair in to result visible at the output, with a reader always ready.
            pub const LATENCY: usize = TCheck::LATENCY + 2;
            /// Result FIFO entries: pairs taken and not yet read out.
            pub const FIFO_DEPTH: usize = 1 << TRI_FIFO_BITS;

            /// Both T.CHECKs' value datapaths round with `rounding`.
            pub fn new(rounding: Rounding) -> Self {
                $crate::rtl::tri_unit::tri_unit_new! { Self {
                    addr_0: std::array::from_fn(|c| Constant::new((c as u64).into())),
                    addr_1: std::array::from_fn(|c| Constant::new((4 + c as u64).into())),
                    addr_2: std::array::from_fn(|c| Constant::new((8 + c as u64).into())),
                    ab_0: Default::default(),
                    ab_1: Default::default(),
                    ab_2: Default::default(),
                    ab_bm: Default::default(),
                    ab_bf: Default::default(),
                    ab_s: Default::default(),
                    ba_0: Default::default(),
                    ba_1: Default::default(),
                    ba_2: Default::default(),
                    ba_bm: Default::default(),
                    ba_bf: Default::default(),
                    ba_s: Default::default(),
                    tc_ab: TCheck::new(rounding),
                    tc_ba: TCheck::new(rounding),
                    degenerate_wait: Default::default(),
                    d1_t: Default::default(),
                    d1_f: Default::default(),
                    d2_t: Default::default(),
                    d2_f: Default::default(),
                    c_hit: Constant::new(2u64.into()),
                    c_uncertain: Constant::new(1u64.into()),
                    c_full: Constant::new((1u64 << TRI_FIFO_BITS).into()),
                    result: Default::default(),
                    fifo: Default::default(),
                    count: Default::default(),
                    take: Default::default(),
                    give: Default::default(),
                } }
            }
        }

        impl Logic for TriUnit {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, ab_bm, ab_bf, ab_s, ba_bm, ba_bf, ba_s, count);
                clock!(self, clock, tc_ab, tc_ba, degenerate_wait, fifo);
                // ---- per-query registers: hold, or load through the write port
                self.ab_bm.d.next = self.ab_bm.q.val();
                self.ab_bf.d.next = self.ab_bf.q.val();
                self.ab_s.d.next = self.ab_s.q.val();
                self.ba_bm.d.next = self.ba_bm.q.val();
                self.ba_bf.d.next = self.ba_bf.q.val();
                self.ba_s.d.next = self.ba_s.q.val();
                if self.load_en.val() {
                    if self.load_addr.val() == 12 {
                        self.ab_bm.d.next = self.load_data.val();
                    }
                    if self.load_addr.val() == 13 {
                        self.ab_bf.d.next = self.load_data.val();
                    }
                    if self.load_addr.val() == 14 {
                        self.ab_s.d.next = self.load_data.val();
                    }
                    if self.load_addr.val() == 28 {
                        self.ba_bm.d.next = self.load_data.val();
                    }
                    if self.load_addr.val() == 29 {
                        self.ba_bf.d.next = self.load_data.val();
                    }
                    if self.load_addr.val() == 30 {
                        self.ba_s.d.next = self.load_data.val();
                    }
                }
                for c in 0..4 {
                    self.ab_0[c].clock.next = self.clock.val();
                    self.ab_1[c].clock.next = self.clock.val();
                    self.ab_2[c].clock.next = self.clock.val();
                    self.ba_0[c].clock.next = self.clock.val();
                    self.ba_1[c].clock.next = self.clock.val();
                    self.ba_2[c].clock.next = self.clock.val();
                    self.ab_0[c].d.next = self.ab_0[c].q.val();
                    self.ab_1[c].d.next = self.ab_1[c].q.val();
                    self.ab_2[c].d.next = self.ab_2[c].q.val();
                    self.ba_0[c].d.next = self.ba_0[c].q.val();
                    self.ba_1[c].d.next = self.ba_1[c].q.val();
                    self.ba_2[c].d.next = self.ba_2[c].q.val();
                    if self.load_en.val() & (self.load_addr.val() == self.addr_0[c].val()) {
                        self.ab_0[c].d.next = self.load_data.val();
                    }
                    if self.load_en.val() & (self.load_addr.val() == self.addr_1[c].val()) {
                        self.ab_1[c].d.next = self.load_data.val();
                    }
                    if self.load_en.val() & (self.load_addr.val() == self.addr_2[c].val()) {
                        self.ab_2[c].d.next = self.load_data.val();
                    }
                    if self.load_en.val() & (self.load_addr.val() == (self.addr_0[c].val() | 16)) {
                        self.ba_0[c].d.next = self.load_data.val();
                    }
                    if self.load_en.val() & (self.load_addr.val() == (self.addr_1[c].val() | 16)) {
                        self.ba_1[c].d.next = self.load_data.val();
                    }
                    if self.load_en.val() & (self.load_addr.val() == (self.addr_2[c].val() | 16)) {
                        self.ba_2[c].d.next = self.load_data.val();
                    }
                    // ---- A's edges against U(B): B's leaf, M_AB
                    self.tc_ab.m_0[c].next = self.b_m_0[c].val();
                    self.tc_ab.m_1[c].next = self.b_m_1[c].val();
                    self.tc_ab.m_2[c].next = self.b_m_2[c].val();
                    self.tc_ab.f_0[c].next = self.ab_0[c].q.val();
                    self.tc_ab.f_1[c].next = self.ab_1[c].q.val();
                    self.tc_ab.f_2[c].next = self.ab_2[c].q.val();
                    // ---- B's edges against U(A): A's leaf, M_BA
                    self.tc_ba.m_0[c].next = self.a_m_0[c].val();
                    self.tc_ba.m_1[c].next = self.a_m_1[c].val();
                    self.tc_ba.m_2[c].next = self.a_m_2[c].val();
                    self.tc_ba.f_0[c].next = self.ba_0[c].q.val();
                    self.tc_ba.f_1[c].next = self.ba_1[c].q.val();
                    self.tc_ba.f_2[c].next = self.ba_2[c].q.val();
                }
                for k in 0..3 {
                    self.tc_ab.v_x[k].next = self.a_v_x[k].val();
                    self.tc_ab.v_y[k].next = self.a_v_y[k].val();
                    self.tc_ab.v_z[k].next = self.a_v_z[k].val();
                    self.tc_ba.v_x[k].next = self.b_v_x[k].val();
                    self.tc_ba.v_y[k].next = self.b_v_y[k].val();
                    self.tc_ba.v_z[k].next = self.b_v_z[k].val();
                }
                self.tc_ab.alpha_m.next = self.b_alpha_m.val();
                self.tc_ab.alpha_f.next = self.b_alpha_f.val();
                self.tc_ab.beta_m.next = self.ab_bm.q.val();
                self.tc_ab.beta_f.next = self.ab_bf.q.val();
                self.tc_ab.scale.next = self.ab_s.q.val();
                self.tc_ab.v_exact.next = self.a_v_exact.val();
                self.tc_ab.tag.next = self.tag.val();
                self.tc_ba.alpha_m.next = self.a_alpha_m.val();
                self.tc_ba.alpha_f.next = self.a_alpha_f.val();
                self.tc_ba.beta_m.next = self.ba_bm.q.val();
                self.tc_ba.beta_f.next = self.ba_bf.q.val();
                self.tc_ba.scale.next = self.ba_s.q.val();
                self.tc_ba.v_exact.next = self.b_v_exact.val();
                self.tc_ba.tag.next = self.tag.val();
                // ---- back-pressure: take a pair only while the FIFO has room for it
                self.in_ready.next = self.count.q.val() != self.c_full.val();
                self.take.next = self.in_valid.val() & (self.count.q.val() != self.c_full.val());
                self.give.next = self.out_ready.val() & !self.fifo.empty.val();
                self.count.d.next = self.count.q.val();
                if self.take.val() & !self.give.val() {
                    self.count.d.next = self.count.q.val() + 1;
                }
                if self.give.val() & !self.take.val() {
                    self.count.d.next = self.count.q.val() - 1;
                }
                self.tc_ab.valid_in.next = self.take.val();
                self.tc_ba.valid_in.next = self.take.val();
                self.degenerate_wait.d.next = 0.into();
                if self.a_degenerate.val() {
                    self.degenerate_wait.d.next = 1.into();
                }
                if self.b_degenerate.val() {
                    self.degenerate_wait.d.next = 2.into();
                    if self.a_degenerate.val() {
                        self.degenerate_wait.d.next = 3.into();
                    }
                }
                // ---- verdict: Kleene OR of the directions (a degenerate leaf: unknown)
                self.d1_t.next = self.tc_ab.hit.val() & !self.degenerate_wait.q.val().get_bit(1);
                self.d1_f.next = self.tc_ab.miss.val() & !self.degenerate_wait.q.val().get_bit(1);
                self.d2_t.next = self.tc_ba.hit.val() & !self.degenerate_wait.q.val().get_bit(0);
                self.d2_f.next = self.tc_ba.miss.val() & !self.degenerate_wait.q.val().get_bit(0);
                self.result.next = bit_cast::<34, 32>(self.tc_ab.tag_out.val()) << 2;
                if self.d1_t.val() | self.d2_t.val() {
                    self.result.next =
                        (bit_cast::<34, 32>(self.tc_ab.tag_out.val()) << 2) | self.c_hit.val();
                }
                if !(self.d1_t.val() | self.d2_t.val()) & !(self.d1_f.val() & self.d2_f.val()) {
                    self.result.next = (bit_cast::<34, 32>(self.tc_ab.tag_out.val()) << 2)
                        | self.c_uncertain.val();
                }
                self.fifo.write.next = self.tc_ab.valid_out.val();
                self.fifo.data_in.next = self.result.val();
                self.fifo.read.next = self.give.val();
                self.out_valid.next = !self.fifo.empty.val();
                self.out_tag.next = self.fifo.data_out.val().get_bits::<32>(2);
                self.out_hit.next = self.fifo.data_out.val().get_bit(1);
                self.out_uncertain.next = self.fifo.data_out.val().get_bit(0);
            }
        }

        /// A TRI_UNIT ready to simulate as a top-level block (inputs claimed, connected).
        /// Large (two T.CHECKs): build it on a thread with a big stack.
        pub fn tri_unit_top(rounding: Rounding) -> TriUnit {
            $crate::rtl::tri_unit::tri_unit_top_level!(TriUnit::new(rounding))
        }

        /// Verilog of TRI_UNIT (top module `top`).
        pub fn verilog_tri_unit(rounding: Rounding) -> String {
            generate_verilog(&tri_unit_top(rounding))
        }
    };
}
pub(crate) use tri_unit;

/// A block with TRI_UNIT's ports (`TriUnit`, `TriUnitFold`) ready to simulate as a top-level
/// block: its inputs claimed, connected.
macro_rules! tri_unit_top_level {
    ($uut:expr) => {{
        let mut uut = $uut;
        for c in 0..4 {
            uut.a_m_0[c].connect();
            uut.a_m_1[c].connect();
            uut.a_m_2[c].connect();
            uut.b_m_0[c].connect();
            uut.b_m_1[c].connect();
            uut.b_m_2[c].connect();
        }
        for k in 0..3 {
            uut.a_v_x[k].connect();
            uut.a_v_y[k].connect();
            uut.a_v_z[k].connect();
            uut.b_v_x[k].connect();
            uut.b_v_y[k].connect();
            uut.b_v_z[k].connect();
        }
        top_level!(uut; clock, load_en, load_addr, load_data, a_alpha_m, a_alpha_f, a_v_exact, a_degenerate,
            b_alpha_m, b_alpha_f, b_v_exact, b_degenerate, tag, in_valid, out_ready)
    }};
}
pub(crate) use tri_unit_top_level;

/// A kernel part `Part` of a chip `Block` (its generics `[..]`) that drives TRI_UNIT
/// `self.$tri` from A's and B's held triangle words (`[a]`, `[b]`: expressions on `self`
/// without it, of `WT`-bit fields in [`TriWord`](crate::golden::memory::TriWord) order),
/// the pair's `[tag]` and `[valid]` (macro hygiene keeps `self` to the macro). One wiring for every chip with a TRI_UNIT.
macro_rules! tri_operands {
    ([$($g:tt)*] $block:ty, $part:ident, $tri:ident, $WT:tt, [$($a:tt)*], [$($b:tt)*], [$($tag:tt)*], [$($valid:tt)*]) => {
        /// TRI_UNIT's ports from the held triangle words.
        struct $part;

        impl<$($g)*> $crate::rtl::kernel::Kernel<$part> for $block {
            #[hdl_gen]
            fn update(&mut self) {
                // TRI_UNIT's ports from the held triangle words (crate::golden::memory::TriWord order)
                for k in 0..3 {
                    self.$tri.a_v_x[k].next = self.$($a)*.get_bits::<$WT>(3 * k * $WT);
                    self.$tri.a_v_y[k].next = self.$($a)*.get_bits::<$WT>((3 * k + 1) * $WT);
                    self.$tri.a_v_z[k].next = self.$($a)*.get_bits::<$WT>((3 * k + 2) * $WT);
                    self.$tri.b_v_x[k].next = self.$($b)*.get_bits::<$WT>(3 * k * $WT);
                    self.$tri.b_v_y[k].next = self.$($b)*.get_bits::<$WT>((3 * k + 1) * $WT);
                    self.$tri.b_v_z[k].next = self.$($b)*.get_bits::<$WT>((3 * k + 2) * $WT);
                }
                for c in 0..4 {
                    self.$tri.a_m_0[c].next = self.$($a)*.get_bits::<$WT>((9 + c) * $WT);
                    self.$tri.a_m_1[c].next = self.$($a)*.get_bits::<$WT>((13 + c) * $WT);
                    self.$tri.a_m_2[c].next = self.$($a)*.get_bits::<$WT>((17 + c) * $WT);
                    self.$tri.b_m_0[c].next = self.$($b)*.get_bits::<$WT>((9 + c) * $WT);
                    self.$tri.b_m_1[c].next = self.$($b)*.get_bits::<$WT>((13 + c) * $WT);
                    self.$tri.b_m_2[c].next = self.$($b)*.get_bits::<$WT>((17 + c) * $WT);
                }
                self.$tri.a_alpha_m.next = self.$($a)*.get_bits::<$WT>(21 * $WT);
                self.$tri.a_alpha_f.next = self.$($a)*.get_bits::<$WT>(22 * $WT);
                self.$tri.a_v_exact.next = self.$($a)*.get_bit(23 * $WT);
                self.$tri.a_degenerate.next = self.$($a)*.get_bit(23 * $WT + 1);
                self.$tri.b_alpha_m.next = self.$($b)*.get_bits::<$WT>(21 * $WT);
                self.$tri.b_alpha_f.next = self.$($b)*.get_bits::<$WT>(22 * $WT);
                self.$tri.b_v_exact.next = self.$($b)*.get_bit(23 * $WT);
                self.$tri.b_degenerate.next = self.$($b)*.get_bit(23 * $WT + 1);
                self.$tri.tag.next = self.$($tag)*;
                self.$tri.in_valid.next = self.$($valid)*;
            }
        }
    };
}
pub(crate) use tri_operands;

use rust_hdl::prelude::*;

/// The result port (the host's read side of TRI_UNIT's result FIFO, DATE'05 Fig. 4's
/// output): an intersecting or uncertain pair at the FIFO's head is shown to the host and
/// leaves when it is read (`res_ready`), holding the FIFO until then, which back-pressures
/// the traversal; a separate pair leaves unseen. It lives here, beside the FIFO it reads,
/// and outside `tri_unit!` because nothing in it depends on the format; it is a block of
/// its own so that the chip's kernel keeps to D_CNTR's and the memory port's wiring.
/// Golden: `cycle::chip`'s `give` and `kept()` (no unit there of its own; checked in the
/// chip, tb/rtl_chip.rs).
///
/// Ports: in `clock`, `take` (a pair entered TRI_UNIT), TRI_UNIT's `out_valid`,
/// `out_hit`, `out_uncertain`, `out_tag[32]`, the host's `res_ready`; out `out_ready`
/// (to TRI_UNIT), `res_valid`, `res_tag[32]`, `res_uncertain` (to the host), `give` (the
/// head leaves at this edge), `sure_hit` (the head is a sure hit, shown or not: first-hit
/// mode stops there), `open[9]` (pairs taken whose results have not left; registered).
#[derive(LogicBlock, Default)]
pub struct ResultPort {
    pub clock: Signal<In, Clock>,
    pub take: Signal<In, Bit>,
    pub out_valid: Signal<In, Bit>,
    pub out_hit: Signal<In, Bit>,
    pub out_uncertain: Signal<In, Bit>,
    pub out_tag: Signal<In, Bits<32>>,
    pub res_ready: Signal<In, Bit>,
    pub out_ready: Signal<Out, Bit>,
    pub res_valid: Signal<Out, Bit>,
    pub res_tag: Signal<Out, Bits<32>>,
    pub res_uncertain: Signal<Out, Bit>,
    pub give: Signal<Out, Bit>,
    pub sure_hit: Signal<Out, Bit>,
    pub open: Signal<Out, Bits<9>>,
    open_r: DFF<Bits<9>>,
    keep: Signal<Local, Bit>,
}

impl Logic for ResultPort {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, open_r);
        // separate pairs leave TRI_UNIT unseen, the others wait for the host
        self.keep.next = self.out_hit.val() | self.out_uncertain.val();
        self.res_valid.next = self.out_valid.val() & self.keep.val();
        self.res_tag.next = self.out_tag.val();
        self.res_uncertain.next = self.out_uncertain.val();
        self.out_ready.next = self.res_ready.val() | !self.keep.val();
        self.give.next = self.out_valid.val() & (self.res_ready.val() | !self.keep.val());
        if self.take.val() & !self.give.val() {
            self.open_r.d.next = self.open_r.q.val() + 1;
        }
        if self.give.val() & !self.take.val() {
            self.open_r.d.next = self.open_r.q.val() - 1;
        }
        self.sure_hit.next = self.out_valid.val() & self.out_hit.val() & !self.out_uncertain.val();
        self.open.next = self.open_r.q.val();
    }
}
