//! The folded DOP unit: the DOP unit's function and ports on L DOPTRF lanes, each
//! doing k/L of the k directions in successive clocks, a pair taken every k/L clocks; stamped
//! out per format by `dop_unit_fold!` for the (k, L) pairs listed there.

/// Stamps out the folded DOP units `DopUnit<k>Fold<ii>` (k directions, a pair
/// every ii = k/L clocks on L lanes) in the calling module, which must also hold that format's
/// `Doptrf`, `KlmSel<K, N>` and `DopSetup<K>`, with their constructors and Verilog export. Argument: `W` word
/// width.
macro_rules! dop_unit_fold {
    ($W:tt) => {
        /// The folded DOP unit of `K` directions taking a pair every `II` clocks, by its
        /// numbers: `<DopFold<6, 6> as FoldedDop>::Unit` is [`DopUnit6Fold6`], so that a chip
        /// picks its DOP unit from its `ChipKind`'s `dop_interval`.
        pub struct DopFold<const K: usize, const II: usize>;
        /// See [`DopFold`].
        pub trait FoldedDop {
            type Unit;
        }

        // Each unit: k, L lanes, ii = k/L passes, k/2 (the opposite direction's offset).
        $crate::rtl::dop_unit_fold::dop_unit_fold!(@units $W;
            (DopUnit6Fold2, dop_unit6_fold2_top, 6, 3, 2, 3)
            (DopUnit6Fold3, dop_unit6_fold3_top, 6, 2, 3, 3)
            (DopUnit6Fold6, dop_unit6_fold6_top, 6, 1, 6, 3)
            (DopUnit24Fold4, dop_unit24_fold4_top, 24, 6, 4, 12)
            (DopUnit24Fold6, dop_unit24_fold6_top, 24, 4, 6, 12)
            (DopUnit24Fold8, dop_unit24_fold8_top, 24, 3, 8, 12)
            (DopUnit24Fold12, dop_unit24_fold12_top, 24, 2, 12, 12)
            (DopUnit24Fold24, dop_unit24_fold24_top, 24, 1, 24, 12)
        );
        // The FPGA chip's: one lane at FPGA depth.
        $crate::rtl::dop_unit_fold::dop_unit_fold!(@unit $W, DopUnit6Fold6Fpga,
            dop_unit6_fold6_fpga_top, 6, 1, 6, 3, DoptrfFpga);

        /// Verilog of [`DopUnit6Fold6Fpga`] (top module `top`).
        pub fn verilog_dop_unit6_fold6_fpga() -> String {
            generate_verilog(&dop_unit6_fold6_fpga_top())
        }
    };
    // The units of one list, the (k, ii) they are stamped out for and their Verilog by (k, ii).
    (@units $W:tt; $(($name:ident, $top:ident, $K:tt, $L:tt, $P:tt, $H:tt))+) => {
        $($crate::rtl::dop_unit_fold::dop_unit_fold!(@unit $W, $name, $top, $K, $L, $P, $H, Doptrf);)+
        $(impl FoldedDop for DopFold<$K, $P> {
            type Unit = $name;
        })+

        /// The (k, ii) of every folded DOP unit stamped out here.
        pub const DOP_UNIT_FOLDS: &[(usize, usize)] = &[$(($K, $P)),+];

        /// Verilog of the DOP unit for k directions folded to a pair every `ii` clocks (top
        /// module `top`); `None` for a (k, ii) not in [`DOP_UNIT_FOLDS`].
        pub fn verilog_dop_unit_fold(k: usize, ii: usize) -> Option<String> {
            Some(match (k, ii) {
                $(($K, $P) => generate_verilog(&$top()),)+
                _ => return None,
            })
        }
    };
    // One unit: `$K` directions on `$L` lanes (of type `$Lane`) in `$P` = K/L passes; `$H` =
    // K/2. Lane l does direction p L + l in pass p (kernel indexes are loop variables and
    // literals, evaluated when the Verilog is written).
    (@unit $W:tt, $name:ident, $top:ident, $K:tt, $L:tt, $P:tt, $H:tt, $Lane:ident) => {
        /// The DOP unit folded (docs/explanation/architecture.md, "Folded DOP unit"): [`DopUnit6`]'s
        /// function and ports, bit for bit [`dop_overlap`](crate::golden::dop_unit::dop_overlap),
        /// on fewer DOPTRF lanes, a node pair taken every ii clocks, plus `in_ready`.
        ///
        /// A counter runs 0 .. ii-1 from the first pair taken (0 until then); `in_ready` is high
        /// while it is 0, and a pair is taken when `valid_in` is high then (a writer holds
        /// `valid_in` until `in_ready`). In pass p (counter p) lane l computes direction
        /// i = p L + l: D.KLMSEL routes `d` with direction i's selects `j_i` and the lane meets
        /// `C_i`, `c_i` and `e[(i + k/2) mod k]`. Pass 0 reads `d`, `e` from the ports; the
        /// later passes read them from `held_d`, `held_e`, registered when the pair is taken
        /// (with its tag and valid bit). The setup registers are read at every pass: the host
        /// writes them between queries, not while a pair is in its passes.
        ///
        /// The lanes' flags of pass p come out at counter (λ + p) mod ii, λ the lanes' latency
        /// (15; 26 at FPGA depth); passes 0 .. ii-2 are ORed into `acc`, and with the last
        /// pass's flags give `overlap` (their NOR, combinational, as in the unfolded unit),
        /// `tag_out` and `valid_out` in the cycle λ - 1 + ii clocks after the pair was taken
        /// ([`dop_fold_latency`](crate::chip::rtl::dop_fold_latency)(ii) at ASIC depth).
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
            pub in_ready: Signal<Out, Bit>,
            idx: [Constant<Bits<5>>; $K],
            // counter values: the last pass, the first and the last pass's flags at the lanes' outputs
            last_pass: Constant<Bits<5>>,
            first_out: Constant<Bits<5>>,
            last_out: Constant<Bits<5>>,
            // the counter starts with the first pair (`run`), then runs freely
            run: DFF<Bit>,
            counter: DFF<Bits<5>>,
            c_zero: Signal<Local, Bit>,
            c_take: Signal<Local, Bit>,
            setup: DopSetup<$K>,
            // the pair, held for passes 1 .. ii-1
            held_d: [DFF<Bits<$W>>; $K],
            held_e: [DFF<Bits<$W>>; $K],
            held_tag: DFF<Bits<16>>,
            held_valid: DFF<Bit>,
            klmsel: KlmSel<$K, $L>,
            // the selects of each lane's direction this pass, given to D.KLMSEL once: a select
            // written twice per evaluation would glitch its combinational outputs, which this
            // block reads, and Icarus would never settle
            c_j0: [Signal<Local, Bits<5>>; $L],
            c_j1: [Signal<Local, Bits<5>>; $L],
            c_j2: [Signal<Local, Bits<5>>; $L],
            doptrf: [$Lane; $L],
            tag_line: $crate::rtl::delay::Delay<Bits<16>, { $Lane::LATENCY }>,
            // the flags of the pair's passes so far
            acc: DFF<Bit>,
            c_any: Signal<Local, Bit>,
            c_first: Signal<Local, Bit>,
        }

        impl $name {
            /// Clocks between pairs taken.
            pub const INTERVAL: usize = $P;
            /// Clocks from a pair taken to its verdict.
            pub const LATENCY: usize = $Lane::LATENCY + $P - 1;

            pub fn new() -> Self {
                use $crate::rtl::reg_ring::array_init;
                const _: () = assert!($K == $L * $P && $H * 2 == $K);
                let at = |c: usize| Constant::new((c as u64).into());
                let dop = $Lane::LATENCY;
                Self {
                    clock: Default::default(),
                    load_en: Default::default(),
                    load_addr: Default::default(),
                    load_data: Default::default(),
                    d: array_init(),
                    e: array_init(),
                    tag: Default::default(),
                    valid_in: Default::default(),
                    overlap: Default::default(),
                    tag_out: Default::default(),
                    valid_out: Default::default(),
                    in_ready: Default::default(),
                    idx: std::array::from_fn(at),
                    last_pass: at($P - 1),
                    first_out: at(dop % $P),
                    last_out: at(Self::LATENCY % $P),
                    run: Default::default(),
                    counter: Default::default(),
                    c_zero: Default::default(),
                    c_take: Default::default(),
                    setup: Default::default(),
                    held_d: array_init(),
                    held_e: array_init(),
                    held_tag: Default::default(),
                    held_valid: Default::default(),
                    klmsel: KlmSel::new(),
                    c_j0: array_init(),
                    c_j1: array_init(),
                    c_j2: array_init(),
                    doptrf: array_init(),
                    tag_line: Default::default(),
                    acc: Default::default(),
                    c_any: Default::default(),
                    c_first: Default::default(),
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
                dff_setup!(self, clock, run, counter, held_tag, held_valid, acc);
                // ---- the counter: 0 .. ii-1 from the first pair taken
                self.c_zero.next = self.counter.q.val() == 0;
                self.c_take.next = self.valid_in.val() & self.c_zero.val();
                self.in_ready.next = self.c_zero.val();
                self.run.d.next = self.run.q.val() | self.c_take.val();
                self.counter.d.next = 0.into();
                if (self.run.q.val() | self.c_take.val()) & (self.counter.q.val() != self.last_pass.val()) {
                    self.counter.d.next = self.counter.q.val() + 1;
                }
                self.setup.clock.next = self.clock.val();
                self.setup.load_en.next = self.load_en.val();
                self.setup.load_addr.next = self.load_addr.val();
                self.setup.load_data.next = self.load_data.val();
                // ---- the pair: from the ports in pass 0, held for the later passes
                self.tag_line.d.next = self.held_tag.q.val();
                if self.c_zero.val() {
                    self.held_tag.d.next = self.tag.val();
                    self.held_valid.d.next = self.c_take.val();
                    self.tag_line.d.next = self.tag.val();
                }
                self.tag_line.clock.next = self.clock.val();
                for a in 0..$K {
                    self.held_d[a].clock.next = self.clock.val();
                    self.held_e[a].clock.next = self.clock.val();
                    self.held_d[a].d.next = self.held_d[a].q.val();
                    self.held_e[a].d.next = self.held_e[a].q.val();
                    if self.c_zero.val() {
                        self.held_d[a].d.next = self.d[a].val();
                        self.held_e[a].d.next = self.e[a].val();
                        self.klmsel.d[a].next = self.d[a].val();
                    } else {
                        self.klmsel.d[a].next = self.held_d[a].q.val();
                    }
                }
                // ---- lane l, pass p: direction p L + l (pass 0 the default)
                for l in 0..$L {
                    self.doptrf[l].clock.next = self.clock.val();
                    self.doptrf[l].round_up.next = self.setup.round_up[l].val();
                    self.doptrf[l].valid_in.next = self.held_valid.q.val();
                    if self.c_zero.val() {
                        self.doptrf[l].valid_in.next = self.c_take.val();
                    }
                    self.c_j0[l].next = self.setup.j0[l].val();
                    self.c_j1[l].next = self.setup.j1[l].val();
                    self.c_j2[l].next = self.setup.j2[l].val();
                    self.doptrf[l].c0.next = self.setup.c0[l].val();
                    self.doptrf[l].c1.next = self.setup.c1[l].val();
                    self.doptrf[l].c2.next = self.setup.c2[l].val();
                    self.doptrf[l].c.next = self.setup.c[l].val();
                    self.doptrf[l].e.next = self.e[(l + $H) % $K].val();
                    for p in 1..$P {
                        if self.counter.q.val() == self.idx[p].val() {
                            self.c_j0[l].next = self.setup.j0[p * $L + l].val();
                            self.c_j1[l].next = self.setup.j1[p * $L + l].val();
                            self.c_j2[l].next = self.setup.j2[p * $L + l].val();
                            self.doptrf[l].c0.next = self.setup.c0[p * $L + l].val();
                            self.doptrf[l].c1.next = self.setup.c1[p * $L + l].val();
                            self.doptrf[l].c2.next = self.setup.c2[p * $L + l].val();
                            self.doptrf[l].c.next = self.setup.c[p * $L + l].val();
                            self.doptrf[l].e.next = self.held_e[(p * $L + l + $H) % $K].q.val();
                        }
                    }
                    self.klmsel.j0[l].next = self.c_j0[l].val();
                    self.klmsel.j1[l].next = self.c_j1[l].val();
                    self.klmsel.j2[l].next = self.c_j2[l].val();
                    self.doptrf[l].d0.next = self.klmsel.y0[l].val();
                    self.doptrf[l].d1.next = self.klmsel.y1[l].val();
                    self.doptrf[l].d2.next = self.klmsel.y2[l].val();
                }
                // ---- overlap = NOR of every pass's flags (acc: passes 0 .. ii-2)
                self.c_any.next = false;
                for l in 0..$L {
                    if self.doptrf[l].flag.val() {
                        self.c_any.next = true;
                    }
                }
                self.c_first.next = self.counter.q.val() == self.first_out.val();
                self.acc.d.next = self.acc.q.val() | self.c_any.val();
                if self.c_first.val() {
                    self.acc.d.next = self.c_any.val();
                }
                self.overlap.next = !(self.c_any.val() | (self.acc.q.val() & !self.c_first.val()));
                self.tag_out.next = self.tag_line.q.val();
                self.valid_out.next = self.doptrf[0].valid_out.val() & (self.counter.q.val() == self.last_out.val());
            }
        }

        /// A folded DOP unit ready to simulate as a top-level block (inputs claimed, connected).
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
pub(crate) use dop_unit_fold;
