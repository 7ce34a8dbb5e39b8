//! The DOP unit (k DOPTRF lanes behind D.KLMSEL, NOR of the k flags), stamped out per
//! format by `dop_unit!` for the k of the k-DOPs (6, 14, 18, 24, 26).

/// Stamps out `DopSetup<K>` and `DopUnit6`, `DopUnit14`, `DopUnit18`, `DopUnit24`, `DopUnit26`
/// in the calling module (which must also hold that format's `Doptrf` and `KlmSel<K, N>`) with
/// their constructors and Verilog export.
/// Argument: `W` word width.
macro_rules! dop_unit {
    ($W:tt) => {
        /// The DOP unit's per-query registers (DATE'05 Eq. 10's C, c and D.KLMSEL's controls j,
        /// one set per direction i), written through the host's setup port: in `load_en`, `load_addr[8]`, `load_data[W]`;
        /// `load_addr = 8 i + f` writes direction i's field f (0, 1, 2: `C_i0..2`; 3: `c_i`; 4:
        /// `j_i0 | j_i1 << 5 | j_i2 << 10 | round_up << 15`, the lane's rounding: 1 TowardPositive,
        /// 0 NearestEven) at the rising edge. Out `c0[K] c1[K] c2[K] c[K]`, `j0[K] j1[K] j2[K]`,
        /// `round_up[K]`, the registers' contents (a rounding register per direction: each
        /// feeds one lane's FP units, no fanout across the unit).
        #[derive(LogicBlock)]
        pub struct DopSetup<const K: usize> {
            pub clock: Signal<In, Clock>,
            pub load_en: Signal<In, Bit>,
            pub load_addr: Signal<In, Bits<8>>,
            pub load_data: Signal<In, Bits<$W>>,
            pub c0: [Signal<Out, Bits<$W>>; K],
            pub c1: [Signal<Out, Bits<$W>>; K],
            pub c2: [Signal<Out, Bits<$W>>; K],
            pub c: [Signal<Out, Bits<$W>>; K],
            pub j0: [Signal<Out, Bits<5>>; K],
            pub j1: [Signal<Out, Bits<5>>; K],
            pub j2: [Signal<Out, Bits<5>>; K],
            pub round_up: [Signal<Out, Bit>; K],
            idx: [Constant<Bits<5>>; K],
            c_lane: Signal<Local, Bits<5>>,
            c_field: Signal<Local, Bits<3>>,
            cmat_0: [DFF<Bits<$W>>; K],
            cmat_1: [DFF<Bits<$W>>; K],
            cmat_2: [DFF<Bits<$W>>; K],
            cvec: [DFF<Bits<$W>>; K],
            jsel_0: [DFF<Bits<5>>; K],
            jsel_1: [DFF<Bits<5>>; K],
            jsel_2: [DFF<Bits<5>>; K],
            rnd: [DFF<Bit>; K],
        }

        impl<const K: usize> Default for DopSetup<K> {
            fn default() -> Self {
                use $crate::rtl::reg_ring::array_init;
                assert!(K <= 32, "DopSetup: k > 32 needs wider addresses");
                Self {
                    clock: Default::default(),
                    load_en: Default::default(),
                    load_addr: Default::default(),
                    load_data: Default::default(),
                    c0: array_init(),
                    c1: array_init(),
                    c2: array_init(),
                    c: array_init(),
                    j0: array_init(),
                    j1: array_init(),
                    j2: array_init(),
                    round_up: array_init(),
                    idx: std::array::from_fn(|a| Constant::new((a as u64).into())),
                    c_lane: Default::default(),
                    c_field: Default::default(),
                    cmat_0: array_init(),
                    cmat_1: array_init(),
                    cmat_2: array_init(),
                    cvec: array_init(),
                    jsel_0: array_init(),
                    jsel_1: array_init(),
                    jsel_2: array_init(),
                    rnd: array_init(),
                }
            }
        }

        impl<const K: usize> Logic for DopSetup<K> {
            #[hdl_gen]
            fn update(&mut self) {
                self.c_lane.next = self.load_addr.val().get_bits::<5>(3);
                self.c_field.next = self.load_addr.val().get_bits::<3>(0);
                for i in 0..K {
                    self.cmat_0[i].clock.next = self.clock.val();
                    self.cmat_1[i].clock.next = self.clock.val();
                    self.cmat_2[i].clock.next = self.clock.val();
                    self.cvec[i].clock.next = self.clock.val();
                    self.jsel_0[i].clock.next = self.clock.val();
                    self.jsel_1[i].clock.next = self.clock.val();
                    self.jsel_2[i].clock.next = self.clock.val();
                    self.rnd[i].clock.next = self.clock.val();
                    self.cmat_0[i].d.next = self.cmat_0[i].q.val();
                    self.cmat_1[i].d.next = self.cmat_1[i].q.val();
                    self.cmat_2[i].d.next = self.cmat_2[i].q.val();
                    self.cvec[i].d.next = self.cvec[i].q.val();
                    self.jsel_0[i].d.next = self.jsel_0[i].q.val();
                    self.jsel_1[i].d.next = self.jsel_1[i].q.val();
                    self.jsel_2[i].d.next = self.jsel_2[i].q.val();
                    self.rnd[i].d.next = self.rnd[i].q.val();
                    if self.load_en.val() & (self.c_lane.val() == self.idx[i].val()) {
                        if self.c_field.val() == 0 {
                            self.cmat_0[i].d.next = self.load_data.val();
                        }
                        if self.c_field.val() == 1 {
                            self.cmat_1[i].d.next = self.load_data.val();
                        }
                        if self.c_field.val() == 2 {
                            self.cmat_2[i].d.next = self.load_data.val();
                        }
                        if self.c_field.val() == 3 {
                            self.cvec[i].d.next = self.load_data.val();
                        }
                        if self.c_field.val() == 4 {
                            self.jsel_0[i].d.next = self.load_data.val().get_bits::<5>(0);
                            self.jsel_1[i].d.next = self.load_data.val().get_bits::<5>(5);
                            self.jsel_2[i].d.next = self.load_data.val().get_bits::<5>(10);
                            self.rnd[i].d.next = self.load_data.val().get_bit(15);
                        }
                    }
                    self.c0[i].next = self.cmat_0[i].q.val();
                    self.c1[i].next = self.cmat_1[i].q.val();
                    self.c2[i].next = self.cmat_2[i].q.val();
                    self.c[i].next = self.cvec[i].q.val();
                    self.j0[i].next = self.jsel_0[i].q.val();
                    self.j1[i].next = self.jsel_1[i].q.val();
                    self.j2[i].next = self.jsel_2[i].q.val();
                    self.round_up[i].next = self.rnd[i].q.val();
                }
            }
        }

        $crate::rtl::dop_unit::dop_unit!(@unit $W, DopUnit6, dop_unit6_top, 6;
            lanes(0 1 2 3 4 5);
            opp(3 4 5 0 1 2));
        $crate::rtl::dop_unit::dop_unit!(@unit $W, DopUnit14, dop_unit14_top, 14;
            lanes(0 1 2 3 4 5 6 7 8 9 10 11 12 13);
            opp(7 8 9 10 11 12 13 0 1 2 3 4 5 6));
        $crate::rtl::dop_unit::dop_unit!(@unit $W, DopUnit18, dop_unit18_top, 18;
            lanes(0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17);
            opp(9 10 11 12 13 14 15 16 17 0 1 2 3 4 5 6 7 8));
        $crate::rtl::dop_unit::dop_unit!(@unit $W, DopUnit24, dop_unit24_top, 24;
            lanes(0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23);
            opp(12 13 14 15 16 17 18 19 20 21 22 23 0 1 2 3 4 5 6 7 8 9 10 11));
        $crate::rtl::dop_unit::dop_unit!(@unit $W, DopUnit26, dop_unit26_top, 26;
            lanes(0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25);
            opp(13 14 15 16 17 18 19 20 21 22 23 24 25 0 1 2 3 4 5 6 7 8 9 10 11 12));

        /// Verilog of the DOP unit for k = 6, 14, 18, 24 or 26 (top module `top`); `None` for
        /// another k. k = 6 and 24 are exported to rtl/ with vectors; the others are
        /// synthesized for the area study (scripts/area-study.sh).
        pub fn verilog_dop_unit(k: usize) -> Option<String> {
            Some(match k {
                6 => generate_verilog(&dop_unit6_top()),
                14 => generate_verilog(&dop_unit14_top()),
                18 => generate_verilog(&dop_unit18_top()),
                24 => generate_verilog(&dop_unit24_top()),
                26 => generate_verilog(&dop_unit26_top()),
                _ => return None,
            })
        }
    };
    // One unit for one k; `lanes` and `opp` list i and (i + k/2) mod k as literals
    // (the fixed e wiring: kernel indexes must be loop variables or literals).
    (@unit $W:tt, $name:ident, $top:ident, $K:tt; lanes($($i:tt)*); opp($($o:tt)*)) => {
        /// The DOP unit (DATE'05 Eq. 10): does B's node DOP `d` (transformed on the fly)
        /// overlap A's node DOP `e`? One node pair per clock, latency 15; bit for bit
        /// [`dop_overlap`](crate::golden::dop_unit::dop_overlap) (`DopUnit6` for k = 6, and so on).
        ///
        /// Ports (arrays are flat, numbered ports in Verilog: `d$0`, `d$1`, ...):
        ///
        /// * per query, a write port for the host setup: in `load_en`, `load_addr[8]`,
        ///   `load_data[W]`. `load_addr = 8 i + f` writes lane i's field f:
        ///   0, 1, 2: `C_i0`, `C_i1`, `C_i2`; 3: `c_i`; 4: the D.KLMSEL control
        ///   `j_i` and the lane's rounding, packed as `j_i0 | j_i1 << 5 | j_i2 << 10 |
        ///   round_up << 15` (1: TowardPositive, the outward DOPs; 0: NearestEven). Written
        ///   on the rising edge while `load_en` is high ([`DopSetup`]); other addresses are
        ///   ignored.
        /// * per pair: in `d[k]` (B's DOP), `e[k]` (A's DOP), `tag[16]`, `valid_in`;
        ///   out `overlap` (NOR of the k lane flags), `tag_out`, `valid_out`.
        ///
        /// Pipeline: `d` goes through D.KLMSEL (`klmsel`, combinational, controlled by the
        /// `setup`'s selects) into the lanes' input registers; lane i (`doptrf$i`) meets
        /// `e[(i + k/2) mod k]` (fixed wiring), `C`, `c` and its rounding from `setup`. The 15 stages are the lanes' (see [`Doptrf`]); the tag travels in
        /// `tag_1 .. tag_15`; the NOR is combinational after the lanes' stage-15
        /// registers, so a pair presented before rising edge 1 has its `overlap`,
        /// `tag_out`, `valid_out` right after edge 15.
        ///
        /// The block is a large value (k = 24: about 2 MB in binary32), built on the stack:
        /// construct it in a thread with a big stack (the testbench uses 512 MB).
        #[derive(LogicBlock)]
        pub struct $name {
            pub clock: Signal<In, Clock>,
            pub load_en: Signal<In, Bit>,
            pub load_addr: Signal<In, Bits<8>>,
            pub load_data: Signal<In, Bits<$W>>,
            pub d: [Signal<In, Bits<$W>>; $K],
            pub e: [Signal<In, Bits<$W>>; $K],
            pub tag: Signal<In, Bits<16>>,
            pub valid_in: Signal<In, Bit>,
            pub overlap: Signal<Out, Bit>,
            pub tag_out: Signal<Out, Bits<16>>,
            pub valid_out: Signal<Out, Bit>,
            // per-query registers
            setup: DopSetup<$K>,
            // datapath
            klmsel: KlmSel<$K, $K>,
            doptrf: [Doptrf; $K],
            tag_1: DFF<Bits<16>>,
            tag_2: DFF<Bits<16>>,
            tag_3: DFF<Bits<16>>,
            tag_4: DFF<Bits<16>>,
            tag_5: DFF<Bits<16>>,
            tag_6: DFF<Bits<16>>,
            tag_7: DFF<Bits<16>>,
            tag_8: DFF<Bits<16>>,
            tag_9: DFF<Bits<16>>,
            tag_10: DFF<Bits<16>>,
            tag_11: DFF<Bits<16>>,
            tag_12: DFF<Bits<16>>,
            tag_13: DFF<Bits<16>>,
            tag_14: DFF<Bits<16>>,
            tag_15: DFF<Bits<16>>,
            c_any: Signal<Local, Bit>,
        }

        impl $name {
            /// Clocks from a pair taken to its verdict.
            pub const LATENCY: usize = $crate::chip::rtl::DOP_LATENCY;

            pub fn new() -> Self {
                Self {
                    clock: Default::default(),
                    load_en: Default::default(),
                    load_addr: Default::default(),
                    load_data: Default::default(),
                    d: $crate::rtl::reg_ring::array_init(),
                    e: $crate::rtl::reg_ring::array_init(),
                    tag: Default::default(),
                    valid_in: Default::default(),
                    overlap: Default::default(),
                    tag_out: Default::default(),
                    valid_out: Default::default(),
                    setup: Default::default(),
                    klmsel: KlmSel::new(),
                    doptrf: $crate::rtl::reg_ring::array_init(),
                    tag_1: Default::default(),
                    tag_2: Default::default(),
                    tag_3: Default::default(),
                    tag_4: Default::default(),
                    tag_5: Default::default(),
                    tag_6: Default::default(),
                    tag_7: Default::default(),
                    tag_8: Default::default(),
                    tag_9: Default::default(),
                    tag_10: Default::default(),
                    tag_11: Default::default(),
                    tag_12: Default::default(),
                    tag_13: Default::default(),
                    tag_14: Default::default(),
                    tag_15: Default::default(),
                    c_any: Default::default(),
                }
            }
        }

        impl Default for $name {
            fn default() -> Self {
                Self::new()
            }
        }

        impl Logic for $name {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, tag_1, tag_2, tag_3, tag_4, tag_5, tag_6, tag_7, tag_8);
                dff_setup!(self, clock, tag_9, tag_10, tag_11, tag_12, tag_13, tag_14, tag_15);
                // ---- per-query registers (C, c, j, rounding), loaded through the write port
                self.setup.clock.next = self.clock.val();
                self.setup.load_en.next = self.load_en.val();
                self.setup.load_addr.next = self.load_addr.val();
                self.setup.load_data.next = self.load_data.val();
                for i in 0..$K {
                    self.doptrf[i].clock.next = self.clock.val();
                    // ---- D.KLMSEL into the lanes' input registers
                    self.klmsel.d[i].next = self.d[i].val();
                    self.klmsel.j0[i].next = self.setup.j0[i].val();
                    self.klmsel.j1[i].next = self.setup.j1[i].val();
                    self.klmsel.j2[i].next = self.setup.j2[i].val();
                    self.doptrf[i].d0.next = self.klmsel.y0[i].val();
                    self.doptrf[i].d1.next = self.klmsel.y1[i].val();
                    self.doptrf[i].d2.next = self.klmsel.y2[i].val();
                    self.doptrf[i].c0.next = self.setup.c0[i].val();
                    self.doptrf[i].c1.next = self.setup.c1[i].val();
                    self.doptrf[i].c2.next = self.setup.c2[i].val();
                    self.doptrf[i].c.next = self.setup.c[i].val();
                    self.doptrf[i].round_up.next = self.setup.round_up[i].val();
                    self.doptrf[i].valid_in.next = self.valid_in.val();
                }
                // ---- lane i meets e_opp(i) = e[(i + k/2) mod k]
                $( self.doptrf[$i].e.next = self.e[$o].val(); )*
                // ---- the tag travels alongside the lanes' 15 stages
                self.tag_1.d.next = self.tag.val();
                self.tag_2.d.next = self.tag_1.q.val();
                self.tag_3.d.next = self.tag_2.q.val();
                self.tag_4.d.next = self.tag_3.q.val();
                self.tag_5.d.next = self.tag_4.q.val();
                self.tag_6.d.next = self.tag_5.q.val();
                self.tag_7.d.next = self.tag_6.q.val();
                self.tag_8.d.next = self.tag_7.q.val();
                self.tag_9.d.next = self.tag_8.q.val();
                self.tag_10.d.next = self.tag_9.q.val();
                self.tag_11.d.next = self.tag_10.q.val();
                self.tag_12.d.next = self.tag_11.q.val();
                self.tag_13.d.next = self.tag_12.q.val();
                self.tag_14.d.next = self.tag_13.q.val();
                self.tag_15.d.next = self.tag_14.q.val();
                // ---- overlap = NOR of the k flags
                self.c_any.next = false;
                for i in 0..$K {
                    if self.doptrf[i].flag.val() {
                        self.c_any.next = true;
                    }
                }
                self.overlap.next = !self.c_any.val();
                self.tag_out.next = self.tag_15.q.val();
                self.valid_out.next = self.doptrf[0].valid_out.val();
            }
        }

        /// A DOP unit ready to simulate as a top-level block (inputs claimed, connected).
        pub fn $top() -> $name {
            let mut uut = $name::new();
            uut.clock.connect();
            uut.load_en.connect();
            uut.load_addr.connect();
            uut.load_data.connect();
            for i in 0..$K {
                uut.d[i].connect();
                uut.e[i].connect();
            }
            uut.tag.connect();
            uut.valid_in.connect();
            uut.connect_all();
            uut
        }
    };
}
pub(crate) use dop_unit;
