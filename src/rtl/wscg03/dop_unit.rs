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

/// Stamps out `Wscg03DopUnit<K>` in the calling module, which must hold the format's
/// `Dotadd`, `KlmSel`, `CompareBank` and `DprimeMemory`. Arguments: `W` word width, `W8` =
/// 8 W; then, per slot of a bundle, its index `t` (0..7) and offset `t W`.
macro_rules! wscg03_dop_unit {
    ($W:tt, $W8:tt; $(($t:tt $off:tt))+) => {
        /// WSCG'03's DOP Unit (§4.1, Fig. 5): two tumbled sibling DOPs transformed once into
        /// the d' memory, then compared with every aligned DOP of a list, a bundle of eight
        /// distances a clock, against both at once.
        ///
        /// - **The MMM** (Matrix- and MUX-Control Memory): five RAMs of k rows, C_i0..2, c_i
        ///   and the control word `j_i0 | j_i1 << 5 | j_i2 << 10 | round_up << 15`, written
        ///   through the host's setup port as DATE'05's DOP unit's (`load_addr = 8 i + f`).
        /// - **The input registers**, two sets (the current pair and the speculative one), each
        ///   a left and a right DOP of k distances, written a bundle a clock from the bus
        ///   (`t_valid`, `t_set`, `t_side`: 0 left, `t_entry`: distances 8 t_entry .., `t_data`).
        ///   The bundle marked `t_last` completes the set's pair: it waits for the address
        ///   generator (`pend`), or starts it at once.
        /// - **The address generator** cycles i = 0 .. k-1 through the MMM, a direction a clock
        ///   (`gen_cnt`); D.KLMSEL routes d_j0..2 of each sibling to its **DOTADD unit**
        ///   (`dot_l`, `dot_r`), which writes d'_i, both siblings' at once, into the **d'
        ///   memory** (`dprime`), the pair's set, at lane i. A set is `busy` from its first bundle
        ///   to its last write: [`wscg03_transform_clocks`](crate::chip::rtl::wscg03_transform_clocks)(k)
        ///   clocks after `t_last` if the generator was free. A set must not be loaded while busy.
        /// - **The compare side**: an aligned DOP's bundle (`a_valid`, `a_first`, `a_lanes`, `e`)
        ///   reads entry `a_entry` of set `a_set` (the d' it meets, in its order) and goes with
        ///   it to the **compare bank** (`bank`), whose `overlap_l`, `overlap_r` after the bundle
        ///   a consumer knows to be the DOP's last are [`dop_overlap`](crate::golden::dop_unit::dop_overlap)'s
        ///   for the left and the right sibling, `flags_valid` a bundle's verdicts so far,
        ///   [`WSCG03_COMPARE_LATENCY`](crate::chip::rtl::WSCG03_COMPARE_LATENCY) clocks after it.
        ///   A read of a set that a transform is writing gives old and new d' mixed: the Stack
        ///   Engine compares with a set only while it is not busy.
        ///
        /// Ports: in `clock`, `load_en`, `load_addr[8]`, `load_data[W]`, `t_valid`, `t_set[1]`,
        /// `t_side`, `t_entry[2]`, `t_last`, `t_data[8W]`, `a_valid`, `a_first`, `a_lanes[8]`,
        /// `a_set[1]`, `a_entry[2]`, `e[8W]` (slot `t` in bits `t W ..`); out `busy[2]` (bit s:
        /// set s), `overlap_l`, `overlap_r`, `flags_valid`.
        #[derive(LogicBlock)]
        pub struct Wscg03DopUnit<const K: usize> {
            pub clock: Signal<In, Clock>,
            pub load_en: Signal<In, Bit>,
            pub load_addr: Signal<In, Bits<8>>,
            pub load_data: Signal<In, Bits<$W>>,
            pub t_valid: Signal<In, Bit>,
            pub t_set: Signal<In, Bits<1>>,
            pub t_side: Signal<In, Bit>,
            pub t_entry: Signal<In, Bits<2>>,
            pub t_last: Signal<In, Bit>,
            pub t_data: Signal<In, Bits<$W8>>,
            pub a_valid: Signal<In, Bit>,
            pub a_first: Signal<In, Bit>,
            pub a_lanes: Signal<In, Bits<8>>,
            pub a_set: Signal<In, Bits<1>>,
            pub a_entry: Signal<In, Bits<2>>,
            pub e: Signal<In, Bits<$W8>>,
            pub busy: Signal<Out, Bits<2>>,
            pub overlap_l: Signal<Out, Bit>,
            pub overlap_r: Signal<Out, Bit>,
            pub flags_valid: Signal<Out, Bit>,
            // the MMM
            /// By field: C_i0, C_i1, C_i2, c_i, the control word.
            mmm: [RAM<Bits<$W>, 5>; 5],
            mmm_field: [Constant<Bits<3>>; 5],
            c_row: Signal<Local, Bits<5>>,
            c_field: Signal<Local, Bits<3>>,
            // the input registers: set 0 and 1, left and right
            c_slot: [Signal<Local, Bits<$W>>; 8],
            entry_of: [Constant<Bits<2>>; K],
            tin_l0: [DFF<Bits<$W>>; K],
            tin_r0: [DFF<Bits<$W>>; K],
            tin_l1: [DFF<Bits<$W>>; K],
            tin_r1: [DFF<Bits<$W>>; K],
            // the address generator and the sets' state
            last_row: Constant<Bits<5>>,
            gen_run: DFF<Bit>,
            gen_cnt: DFF<Bits<5>>,
            gen_set: DFF<Bits<1>>,
            pend: DFF<Bits<2>>,
            busy_r: DFF<Bits<2>>,
            c_row_last: Signal<Local, Bit>,
            c_go: Signal<Local, Bit>,
            c_go_set: Signal<Local, Bits<1>>,
            c_t_set: Signal<Local, Bits<2>>,
            c_go_mask: Signal<Local, Bits<2>>,
            c_pend_set: Signal<Local, Bits<2>>,
            c_busy_set: Signal<Local, Bits<2>>,
            c_busy_clr: Signal<Local, Bits<2>>,
            c_ctl: Signal<Local, Bits<$W>>,
            // a direction at the DOTADD units: valid, set, lane, the set's last
            s1_valid: DFF<Bit>,
            s1_set: DFF<Bits<1>>,
            s1_lane: DFF<Bits<5>>,
            s1_last: DFF<Bits<1>>,
            klm_l: KlmSel<K, 1>,
            klm_r: KlmSel<K, 1>,
            dot_l: Dotadd,
            dot_r: Dotadd,
            // the set, lane and last bit of each d' the DOTADD units make
            wr_tag: $crate::rtl::delay::Delay<Bits<7>, { $crate::chip::rtl::DOTADD_LATENCY }>,
            c_wr_set: Signal<Local, Bits<1>>,
            dprime: DprimeMemory,
            // an aligned bundle while its d' are read
            sa_valid: DFF<Bit>,
            sa_first: DFF<Bit>,
            sa_lanes: DFF<Bits<8>>,
            sa_e: DFF<Bits<$W8>>,
            bank: CompareBank,
        }

        impl<const K: usize> Wscg03DopUnit<K> {
            /// The DOP Unit of `K` directions (even, at most 32).
            pub fn new() -> Self {
                use $crate::rtl::reg_ring::array_init;
                Self {
                    clock: Default::default(),
                    load_en: Default::default(),
                    load_addr: Default::default(),
                    load_data: Default::default(),
                    t_valid: Default::default(),
                    t_set: Default::default(),
                    t_side: Default::default(),
                    t_entry: Default::default(),
                    t_last: Default::default(),
                    t_data: Default::default(),
                    a_valid: Default::default(),
                    a_first: Default::default(),
                    a_lanes: Default::default(),
                    a_set: Default::default(),
                    a_entry: Default::default(),
                    e: Default::default(),
                    busy: Default::default(),
                    overlap_l: Default::default(),
                    overlap_r: Default::default(),
                    flags_valid: Default::default(),
                    mmm: array_init(),
                    mmm_field: std::array::from_fn(|f| Constant::new((f as u64).into())),
                    c_row: Default::default(),
                    c_field: Default::default(),
                    c_slot: array_init(),
                    entry_of: std::array::from_fn(|a| Constant::new(((a / 8) as u64).into())),
                    tin_l0: array_init(),
                    tin_r0: array_init(),
                    tin_l1: array_init(),
                    tin_r1: array_init(),
                    last_row: Constant::new(((K - 1) as u64).into()),
                    gen_run: Default::default(),
                    gen_cnt: Default::default(),
                    gen_set: Default::default(),
                    pend: Default::default(),
                    busy_r: Default::default(),
                    c_row_last: Default::default(),
                    c_go: Default::default(),
                    c_go_set: Default::default(),
                    c_t_set: Default::default(),
                    c_go_mask: Default::default(),
                    c_pend_set: Default::default(),
                    c_busy_set: Default::default(),
                    c_busy_clr: Default::default(),
                    c_ctl: Default::default(),
                    s1_valid: Default::default(),
                    s1_set: Default::default(),
                    s1_lane: Default::default(),
                    s1_last: Default::default(),
                    klm_l: KlmSel::new(),
                    klm_r: KlmSel::new(),
                    dot_l: Default::default(),
                    dot_r: Default::default(),
                    wr_tag: Default::default(),
                    c_wr_set: Default::default(),
                    dprime: DprimeMemory::new(K),
                    sa_valid: Default::default(),
                    sa_first: Default::default(),
                    sa_lanes: Default::default(),
                    sa_e: Default::default(),
                    bank: CompareBank::new(),
                }
            }
        }

        impl<const K: usize> Default for Wscg03DopUnit<K> {
            fn default() -> Self {
                Self::new()
            }
        }

        $crate::rtl::kernel::kernel!([const K: usize] Wscg03DopUnit<K>: Wscg03Load, Wscg03Transform, Wscg03Compare);

        /// WSCG'03's DOP Unit's kernel, part 1: the MMM and the input registers.
        struct Wscg03Load;

        impl<const K: usize> $crate::rtl::kernel::Kernel<Wscg03Load> for Wscg03DopUnit<K> {
            #[hdl_gen]
            fn update(&mut self) {
                // ---- the MMM: the host writes row i's field f; the generator reads row gen_cnt
                self.c_row.next = self.load_addr.val().get_bits::<5>(3);
                self.c_field.next = self.load_addr.val().get_bits::<3>(0);
                for f in 0..5 {
                    self.mmm[f].read_clock.next = self.clock.val();
                    self.mmm[f].write_clock.next = self.clock.val();
                    self.mmm[f].read_address.next = self.gen_cnt.q.val();
                    self.mmm[f].write_address.next = self.c_row.val();
                    self.mmm[f].write_data.next = self.load_data.val();
                    self.mmm[f].write_enable.next =
                        self.load_en.val() & (self.c_field.val() == self.mmm_field[f].val());
                }
                // ---- the input registers: a tumbled bundle into its set and side
                $(self.c_slot[$t].next = self.t_data.val().get_bits::<$W>($off);)+
                for a in 0..K {
                    self.tin_l0[a].clock.next = self.clock.val();
                    self.tin_r0[a].clock.next = self.clock.val();
                    self.tin_l1[a].clock.next = self.clock.val();
                    self.tin_r1[a].clock.next = self.clock.val();
                    self.tin_l0[a].d.next = self.tin_l0[a].q.val();
                    self.tin_r0[a].d.next = self.tin_r0[a].q.val();
                    self.tin_l1[a].d.next = self.tin_l1[a].q.val();
                    self.tin_r1[a].d.next = self.tin_r1[a].q.val();
                    if self.t_valid.val() & (self.t_entry.val() == self.entry_of[a].val()) {
                        if self.t_set.val() == 1 {
                            if self.t_side.val() {
                                self.tin_r1[a].d.next = self.c_slot[a % 8].val();
                            } else {
                                self.tin_l1[a].d.next = self.c_slot[a % 8].val();
                            }
                        } else if self.t_side.val() {
                            self.tin_r0[a].d.next = self.c_slot[a % 8].val();
                        } else {
                            self.tin_l0[a].d.next = self.c_slot[a % 8].val();
                        }
                    }
                }
            }
        }

        /// Part 2: the address generator, D.KLMSEL and the DOTADD units.
        struct Wscg03Transform;

        impl<const K: usize> $crate::rtl::kernel::Kernel<Wscg03Transform> for Wscg03DopUnit<K> {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, gen_run, gen_cnt, gen_set, pend, s1_valid, s1_set, s1_lane, s1_last);
                // ---- the address generator: the pending set (set 0 first), or the pair
                // completed now, when the last row of the one before is read
                self.c_row_last.next = self.gen_run.q.val() & (self.gen_cnt.q.val() == self.last_row.val());
                self.c_go.next = (!self.gen_run.q.val() | self.c_row_last.val())
                    & ((self.pend.q.val() != 0) | (self.t_valid.val() & self.t_last.val()));
                self.c_go_set.next = self.t_set.val();
                if self.pend.q.val().get_bit(1) {
                    self.c_go_set.next = 1.into();
                }
                if self.pend.q.val().get_bit(0) {
                    self.c_go_set.next = 0.into();
                }
                self.c_t_set.next = 1.into();
                if self.t_set.val() == 1 {
                    self.c_t_set.next = 2.into();
                }
                self.c_go_mask.next = 0.into();
                if self.c_go.val() {
                    self.c_go_mask.next = 1.into();
                    if self.c_go_set.val() == 1 {
                        self.c_go_mask.next = 2.into();
                    }
                }
                self.c_pend_set.next = 0.into();
                self.c_busy_set.next = 0.into();
                if self.t_valid.val() {
                    self.c_busy_set.next = self.c_t_set.val();
                    if self.t_last.val() {
                        self.c_pend_set.next = self.c_t_set.val();
                    }
                }
                self.pend.d.next = (self.pend.q.val() | self.c_pend_set.val()) & !self.c_go_mask.val();
                self.gen_run.d.next = self.gen_run.q.val() & !self.c_row_last.val();
                self.gen_cnt.d.next = 0.into();
                if self.gen_run.q.val() & !self.c_row_last.val() {
                    self.gen_cnt.d.next = self.gen_cnt.q.val() + 1;
                }
                self.gen_set.d.next = self.gen_set.q.val();
                if self.c_go.val() {
                    self.gen_run.d.next = true;
                    self.gen_set.d.next = self.c_go_set.val();
                }
                // ---- row i at the DOTADD units: D.KLMSEL routes the set's distances
                self.s1_valid.d.next = self.gen_run.q.val();
                self.s1_set.d.next = self.gen_set.q.val();
                self.s1_lane.d.next = self.gen_cnt.q.val();
                self.s1_last.d.next = 0.into();
                if self.c_row_last.val() {
                    self.s1_last.d.next = 1.into();
                }
                self.c_ctl.next = self.mmm[4].read_data.val();
                for a in 0..K {
                    if self.s1_set.q.val() == 1 {
                        self.klm_l.d[a].next = self.tin_l1[a].q.val();
                        self.klm_r.d[a].next = self.tin_r1[a].q.val();
                    } else {
                        self.klm_l.d[a].next = self.tin_l0[a].q.val();
                        self.klm_r.d[a].next = self.tin_r0[a].q.val();
                    }
                }
                self.klm_l.j0[0].next = self.c_ctl.val().get_bits::<5>(0);
                self.klm_l.j1[0].next = self.c_ctl.val().get_bits::<5>(5);
                self.klm_l.j2[0].next = self.c_ctl.val().get_bits::<5>(10);
                self.klm_r.j0[0].next = self.c_ctl.val().get_bits::<5>(0);
                self.klm_r.j1[0].next = self.c_ctl.val().get_bits::<5>(5);
                self.klm_r.j2[0].next = self.c_ctl.val().get_bits::<5>(10);
                self.dot_l.clock.next = self.clock.val();
                self.dot_l.valid_in.next = self.s1_valid.q.val();
                self.dot_l.round_up.next = self.c_ctl.val().get_bit(15);
                self.dot_l.c0.next = self.mmm[0].read_data.val();
                self.dot_l.c1.next = self.mmm[1].read_data.val();
                self.dot_l.c2.next = self.mmm[2].read_data.val();
                self.dot_l.c.next = self.mmm[3].read_data.val();
                self.dot_l.d0.next = self.klm_l.y0[0].val();
                self.dot_l.d1.next = self.klm_l.y1[0].val();
                self.dot_l.d2.next = self.klm_l.y2[0].val();
                self.dot_r.clock.next = self.clock.val();
                self.dot_r.valid_in.next = self.s1_valid.q.val();
                self.dot_r.round_up.next = self.c_ctl.val().get_bit(15);
                self.dot_r.c0.next = self.mmm[0].read_data.val();
                self.dot_r.c1.next = self.mmm[1].read_data.val();
                self.dot_r.c2.next = self.mmm[2].read_data.val();
                self.dot_r.c.next = self.mmm[3].read_data.val();
                self.dot_r.d0.next = self.klm_r.y0[0].val();
                self.dot_r.d1.next = self.klm_r.y1[0].val();
                self.dot_r.d2.next = self.klm_r.y2[0].val();
            }
        }

        /// Part 3: the d' memory's writes and the busy bits; the compare side.
        struct Wscg03Compare;

        impl<const K: usize> $crate::rtl::kernel::Kernel<Wscg03Compare> for Wscg03DopUnit<K> {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, busy_r, sa_valid, sa_first, sa_lanes, sa_e);
                // ---- d'_i of both siblings into the d' memory; the set's last ends its busy
                self.wr_tag.clock.next = self.clock.val();
                self.wr_tag.d.next = bit_cast::<7, 5>(self.s1_lane.q.val())
                    | (bit_cast::<7, 1>(self.s1_set.q.val()) << 5)
                    | (bit_cast::<7, 1>(self.s1_last.q.val()) << 6);
                self.c_wr_set.next = self.wr_tag.q.val().get_bits::<1>(5);
                self.dprime.clock.next = self.clock.val();
                self.dprime.wr_valid.next = self.dot_l.valid_out.val();
                self.dprime.wr_set.next = self.c_wr_set.val();
                self.dprime.wr_lane.next = self.wr_tag.q.val().get_bits::<5>(0);
                self.dprime.wr_l.next = self.dot_l.u.val();
                self.dprime.wr_r.next = self.dot_r.u.val();
                self.c_busy_clr.next = 0.into();
                if self.dot_l.valid_out.val() & self.wr_tag.q.val().get_bit(6) {
                    self.c_busy_clr.next = 1.into();
                    if self.c_wr_set.val() == 1 {
                        self.c_busy_clr.next = 2.into();
                    }
                }
                self.busy_r.d.next = (self.busy_r.q.val() & !self.c_busy_clr.val()) | self.c_busy_set.val();
                self.busy.next = self.busy_r.q.val();
                // ---- the compare side: the bundle waits a clock for its d'
                self.dprime.rd_set.next = self.a_set.val();
                self.dprime.rd_entry.next = self.a_entry.val();
                self.sa_valid.d.next = self.a_valid.val();
                self.sa_first.d.next = self.a_first.val();
                self.sa_lanes.d.next = self.a_lanes.val();
                self.sa_e.d.next = self.e.val();
                self.bank.clock.next = self.clock.val();
                self.bank.valid_in.next = self.sa_valid.q.val();
                self.bank.first.next = self.sa_first.q.val();
                self.bank.lanes.next = self.sa_lanes.q.val();
                self.bank.e.next = self.sa_e.q.val();
                self.bank.dl.next = self.dprime.dl.val();
                self.bank.dr.next = self.dprime.dr.val();
                self.overlap_l.next = self.bank.overlap_l.val();
                self.overlap_r.next = self.bank.overlap_r.val();
                self.flags_valid.next = self.bank.valid_out.val();
            }
        }


        /// WSCG'03's DOP Unit of `K` directions ready to simulate as a top-level block.
        pub fn wscg03_dop_unit_top<const K: usize>() -> Wscg03DopUnit<K> {
            top_level!(Wscg03DopUnit::<K>::new(); clock, load_en, load_addr, load_data, t_valid,
                t_set, t_side, t_entry, t_last, t_data, a_valid, a_first, a_lanes, a_set, a_entry, e)
        }

        /// Verilog of [`wscg03_dop_unit_top`] for k = 24 (top module `top`).
        pub fn verilog_wscg03_dop_unit24() -> String {
            generate_verilog(&wscg03_dop_unit_top::<24>())
        }
    };
}
pub(crate) use wscg03_dop_unit;
