//! WSCG'03's DOP Unit (§4.1, Fig. 5) in RTL: its bank of 16 compare units (`CompareBank`,
//! `compare_bank!`) and its d' memory (`DprimeMemory`, `dprime_memory!`), stamped out per
//! format; its DOTADD units are [`Dotadd`](crate::rtl::b32::Dotadd) (`doptrf!`).

/// Stamps out `CompareBank` in the calling module, which must hold the format's `FpCmp`.
/// Arguments: `W` word width, `W8` = 8 W; then, per compare unit pair, the left and right
/// unit's names, its lane `t` (0..7) and the lane's offset `t W` in a bundle.
macro_rules! compare_bank {
    ($W:tt, $W8:tt; $(($l:ident $r:ident $t:tt $off:tt))+) => {
        /// WSCG'03's bank of 16 compare units (§4.1): the aligned DOP arrives from the 256-bit
        /// data bus in bundles of eight coefficients, one a clock, and each is compared at
        /// once with the d' of both tumbled siblings, the left (`dl`) and the right (`dr`),
        /// which the d' memory holds in the bundle's order: lane `t` of a bundle pairs `e_g`
        /// with `d'_opp(g)` ([`compare_bundles`](crate::golden::dop_unit::compare_bundles)),
        /// so that its `FpCmp` decides lane opp(g)'s flag `d' + e < 0`
        /// ([`separated`](crate::golden::doptrf::separated)). `lanes` masks the lanes of a
        /// short last bundle.
        ///
        /// The flags are ORed over a DOP's bundles from the one marked `first`: for every
        /// valid bundle, `overlap_l` and `overlap_r` say whether each sibling still overlaps
        /// after it (NOR of the flags so far), so that the bundle a consumer marks as the last
        /// gives the verdicts, [`dop_overlap`](crate::golden::dop_unit::dop_overlap)'s. An
        /// idle clock (`valid_in` low) keeps them. Latency 2
        /// ([`COMPARE_BANK_LATENCY`](crate::chip::rtl::COMPARE_BANK_LATENCY)): the compare
        /// units' register, then the flags' (`s2_sep_*`, "separated along some lane").
        /// Ports: in `clock`, `valid_in`, `first`, `lanes[8]`, `e[8W]`, `dl[8W]`, `dr[8W]`
        /// (lane `t` in bits `t W ..`); out `overlap_l`, `overlap_r`, `valid_out`.
        #[derive(LogicBlock)]
        pub struct CompareBank {
            pub clock: Signal<In, Clock>,
            pub valid_in: Signal<In, Bit>,
            pub first: Signal<In, Bit>,
            pub lanes: Signal<In, Bits<8>>,
            pub e: Signal<In, Bits<$W8>>,
            pub dl: Signal<In, Bits<$W8>>,
            pub dr: Signal<In, Bits<$W8>>,
            pub overlap_l: Signal<Out, Bit>,
            pub overlap_r: Signal<Out, Bit>,
            pub valid_out: Signal<Out, Bit>,
            $($l: FpCmp,
            $r: FpCmp,)+
            s1_first: DFF<Bit>,
            s1_lanes: DFF<Bits<8>>,
            c2_any_l: Signal<Local, Bit>,
            c2_any_r: Signal<Local, Bit>,
            s2_sep_l: DFF<Bit>,
            s2_sep_r: DFF<Bit>,
            s2_valid: DFF<Bit>,
        }

        impl CompareBank {
            pub const LATENCY: usize = $crate::chip::rtl::COMPARE_BANK_LATENCY;

            pub fn new() -> Self {
                Self {
                    clock: Default::default(),
                    valid_in: Default::default(),
                    first: Default::default(),
                    lanes: Default::default(),
                    e: Default::default(),
                    dl: Default::default(),
                    dr: Default::default(),
                    overlap_l: Default::default(),
                    overlap_r: Default::default(),
                    valid_out: Default::default(),
                    $($l: FpCmp::new(),
                    $r: FpCmp::new(),)+
                    s1_first: Default::default(),
                    s1_lanes: Default::default(),
                    c2_any_l: Default::default(),
                    c2_any_r: Default::default(),
                    s2_sep_l: Default::default(),
                    s2_sep_r: Default::default(),
                    s2_valid: Default::default(),
                }
            }
        }

        impl Default for CompareBank {
            fn default() -> Self {
                Self::new()
            }
        }

        impl Logic for CompareBank {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, s1_first, s1_lanes, s2_sep_l, s2_sep_r, s2_valid);
                // ---- stage 1: the compare units
                $(self.$l.clock.next = self.clock.val();
                self.$l.a.next = self.dl.val().get_bits::<$W>($off);
                self.$l.b.next = self.e.val().get_bits::<$W>($off);
                self.$l.valid_in.next = self.valid_in.val();
                self.$r.clock.next = self.clock.val();
                self.$r.a.next = self.dr.val().get_bits::<$W>($off);
                self.$r.b.next = self.e.val().get_bits::<$W>($off);
                self.$r.valid_in.next = self.valid_in.val();)+
                self.s1_first.d.next = self.first.val();
                self.s1_lanes.d.next = self.lanes.val();
                // ---- stage 2: the flags of the lanes in use, ORed into the DOP's so far
                self.c2_any_l.next = false;
                self.c2_any_r.next = false;
                $(if self.$l.flag.val() & self.s1_lanes.q.val().get_bit($t) {
                    self.c2_any_l.next = true;
                }
                if self.$r.flag.val() & self.s1_lanes.q.val().get_bit($t) {
                    self.c2_any_r.next = true;
                })+
                self.s2_valid.d.next = self.cmp_l0.valid_out.val();
                if self.cmp_l0.valid_out.val() {
                    self.s2_sep_l.d.next =
                        self.c2_any_l.val() | (self.s2_sep_l.q.val() & !self.s1_first.q.val());
                    self.s2_sep_r.d.next =
                        self.c2_any_r.val() | (self.s2_sep_r.q.val() & !self.s1_first.q.val());
                }
                self.overlap_l.next = !self.s2_sep_l.q.val();
                self.overlap_r.next = !self.s2_sep_r.q.val();
                self.valid_out.next = self.s2_valid.q.val();
            }
        }

        /// A compare bank ready to simulate as a top-level block (inputs claimed, connected).
        pub fn compare_bank_top() -> CompareBank {
            top_level!(CompareBank::new(); clock, valid_in, first, lanes, e, dl, dr)
        }

        /// Verilog of [`compare_bank_top`] (top module `top`).
        pub fn verilog_compare_bank() -> String {
            generate_verilog(&compare_bank_top())
        }
    };
}
pub(crate) use compare_bank;

/// Stamps out `DprimeMemory` in the calling module. Arguments: `W` word width, `W8` = 8 W;
/// then, per slot of an entry, the left and right slot RAM's names, the slot `t` (0..7) and
/// its offset `t W` in an entry.
macro_rules! dprime_memory {
    ($W:tt, $W8:tt; $(($l:ident $r:ident $t:tt $off:tt))+) => {
        /// WSCG'03's d' memory (§4.1, Fig. 5): the dual-port memory between the two DOTADD
        /// units and the compare bank, with two sets (the current pair's d' and the
        /// speculative one's). The write port takes a pair a clock, lane `wr_lane`'s d' of
        /// the left and the right sibling (`wr_l`, `wr_r`, as both DOTADD units make them, lane
        /// by lane), into set `wr_set`; it stores lane i at the position of A's distance it
        /// meets, g = opp(i) (i + k/2 mod k), entry g / 8, slot g mod 8, so that the read port
        /// gives an entry of eight pairs in the order of a bundle of A's distances: "the
        /// dual-port memory layout" that the compare units need
        /// ([`compare_bundles`](crate::golden::dop_unit::compare_bundles)).
        ///
        /// One RAM per side and slot (16, each of two sets of four entries: k <= 32), written
        /// by the slot's enable. Reads are synchronous: entry `rd_entry` of set `rd_set` on
        /// `dl[8W]`, `dr[8W]` one clock after its address
        /// ([`DPRIME_READ_LATENCY`](crate::chip::rtl::DPRIME_READ_LATENCY)). Ports: in `clock`, `wr_valid`, `wr_set`,
        /// `wr_lane[5]`, `wr_l[W]`, `wr_r[W]`, `rd_set`, `rd_entry[2]`; out `dl[8W]`,
        /// `dr[8W]`.
        #[derive(LogicBlock)]
        pub struct DprimeMemory {
            pub clock: Signal<In, Clock>,
            pub wr_valid: Signal<In, Bit>,
            pub wr_set: Signal<In, Bits<1>>,
            pub wr_lane: Signal<In, Bits<5>>,
            pub wr_l: Signal<In, Bits<$W>>,
            pub wr_r: Signal<In, Bits<$W>>,
            pub rd_set: Signal<In, Bits<1>>,
            pub rd_entry: Signal<In, Bits<2>>,
            pub dl: Signal<Out, Bits<$W8>>,
            pub dr: Signal<Out, Bits<$W8>>,
            /// k / 2.
            c_half: Constant<Bits<5>>,
            pos: Signal<Local, Bits<5>>,
            wr_addr: Signal<Local, Bits<3>>,
            rd_addr: Signal<Local, Bits<3>>,
            $($l: RAM<Bits<$W>, 3>,
            $r: RAM<Bits<$W>, 3>,)+
        }

        impl DprimeMemory {
            /// Clocks from a read address to its entry.
            pub const READ_LATENCY: usize = $crate::chip::rtl::DPRIME_READ_LATENCY;

            /// The d' memory of a DOP with `k` directions (even, at most 32).
            pub fn new(k: usize) -> Self {
                assert!(k % 2 == 0 && k <= 32, "DprimeMemory: k = {k}, not even or above 32");
                Self {
                    clock: Default::default(),
                    wr_valid: Default::default(),
                    wr_set: Default::default(),
                    wr_lane: Default::default(),
                    wr_l: Default::default(),
                    wr_r: Default::default(),
                    rd_set: Default::default(),
                    rd_entry: Default::default(),
                    dl: Default::default(),
                    dr: Default::default(),
                    c_half: Constant::new((k as u64 / 2).into()),
                    pos: Default::default(),
                    wr_addr: Default::default(),
                    rd_addr: Default::default(),
                    $($l: Default::default(),
                    $r: Default::default(),)+
                }
            }
        }

        impl Logic for DprimeMemory {
            #[hdl_gen]
            fn update(&mut self) {
                // lane i's position g = opp(i): entry g / 8 (with the set: the RAMs' address),
                // slot g mod 8 (which RAMs write)
                self.pos.next = self.wr_lane.val() - self.c_half.val();
                if self.wr_lane.val() < self.c_half.val() {
                    self.pos.next = self.wr_lane.val() + self.c_half.val();
                }
                self.wr_addr.next = bit_cast::<3, 2>(self.pos.val().get_bits::<2>(3))
                    | (bit_cast::<3, 1>(self.wr_set.val()) << 2);
                self.rd_addr.next = bit_cast::<3, 2>(self.rd_entry.val())
                    | (bit_cast::<3, 1>(self.rd_set.val()) << 2);
                $(self.$l.read_clock.next = self.clock.val();
                self.$l.write_clock.next = self.clock.val();
                self.$l.read_address.next = self.rd_addr.val();
                self.$l.write_address.next = self.wr_addr.val();
                self.$l.write_data.next = self.wr_l.val();
                self.$l.write_enable.next =
                    self.wr_valid.val() & (self.pos.val().get_bits::<3>(0) == $t);
                self.$r.read_clock.next = self.clock.val();
                self.$r.write_clock.next = self.clock.val();
                self.$r.read_address.next = self.rd_addr.val();
                self.$r.write_address.next = self.wr_addr.val();
                self.$r.write_data.next = self.wr_r.val();
                self.$r.write_enable.next =
                    self.wr_valid.val() & (self.pos.val().get_bits::<3>(0) == $t);)+
                self.dl.next = $((bit_cast::<$W8, $W>(self.$l.read_data.val()) << $off))|+;
                self.dr.next = $((bit_cast::<$W8, $W>(self.$r.read_data.val()) << $off))|+;
            }
        }

        /// The d' memory of `k` directions ready to simulate as a top-level block.
        pub fn dprime_memory_top(k: usize) -> DprimeMemory {
            top_level!(DprimeMemory::new(k); clock, wr_valid, wr_set, wr_lane, wr_l, wr_r, rd_set, rd_entry)
        }

        /// Verilog of [`dprime_memory_top`] (top module `top`).
        pub fn verilog_dprime_memory(k: usize) -> String {
            generate_verilog(&dprime_memory_top(k))
        }
    };
}
pub(crate) use dprime_memory;
