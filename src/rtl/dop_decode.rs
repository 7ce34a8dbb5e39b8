//! The decode stage of stored DOP precision (`DopDecode`), stamped out per format and code
//! width by `dop_decode!`: one plane of a node word of `b`-bit codes back to a distance,
//! [`dop::stored::decode`](crate::dop::stored::decode) bit for bit.

/// Stamps out `DopDecode` in the calling module (which must hold the format's `FpAdd`).
/// Arguments: `W`, `F` (fraction bits), `B` the code's bits (at most `F + 1`), `X` the
/// exponent field's bits ([`exp_field_bits`](crate::chip::layout::exp_field_bits)).
macro_rules! dop_decode {
    ($W:tt, $F:tt, $B:tt, $X:tt) => {
        /// `y = r ⊖ q 2^e`, `e = e_lo + ef` ([`exp_range`](crate::chip::layout::exp_range)):
        /// the record's reference distance `r` less the plane's code `q` in steps of `2^e`,
        /// in the format, rounded as `round_up` says (1: TowardPositive, 0: NearestEven: the DOP
        /// lanes' rounding; taken with the operands, it meets the adder's round stage through
        /// `r_add`) ([`dop::stored::decode`](crate::dop::stored::decode)).
        ///
        /// `q 2^e` is a value of the format whatever `q` and `ef` (the layout's exponent range:
        /// at least the smallest subnormal, at most the largest finite over `2^B - 1`), so it is
        /// made exactly, with no rounding, in front of the adder's first stage: `q` normalised
        /// by its leading zeros `lz` (a chain of `B - 1` one-bit shifts: `B` is small), then the
        /// biased exponent `ef + B - lz - F` and the bits below the leading one, or, where that
        /// exponent would be below 1, the subnormal `q 2^ef` (exponent field 0); `q = 0` is +0,
        /// so `y = r`. The inputs are registered first (`s0_*`: in a chip they come from the
        /// memory port's record multiplexer, whose path would otherwise run on through the
        /// step and the adder's alignment), then `FpAdd` with `sub`: latency 4
        /// ([`DOP_DECODE_LATENCY`](crate::chip::rtl::DOP_DECODE_LATENCY)), one plane a clock.
        /// Ports: in `clock`, `r[W]`, `q[B]`, `ef[X]`, `valid_in`, `round_up`; out `y[W]`,
        /// `valid_out`.
        #[derive(LogicBlock)]
        pub struct DopDecode {
            pub clock: Signal<In, Clock>,
            pub r: Signal<In, Bits<$W>>,
            pub q: Signal<In, Bits<$B>>,
            pub ef: Signal<In, Bits<$X>>,
            pub valid_in: Signal<In, Bit>,
            pub round_up: Signal<In, Bit>,
            pub y: Signal<Out, Bits<$W>>,
            pub valid_out: Signal<Out, Bit>,
            s0_r: DFF<Bits<$W>>,
            s0_q: DFF<Bits<$B>>,
            s0_ef: DFF<Bits<$X>>,
            s0_valid: DFF<Bit>,
            s0_round: DFF<Bit>,
            r_add: $crate::rtl::delay::Delay<Bit, 2>,
            c_f: Constant<Bits<16>>,
            c_b: Constant<Bits<16>>,
            /// `q` after i one-bit normalising shifts, and the shifts taken.
            norm: [Signal<Local, Bits<$B>>; $B],
            lz: [Signal<Local, Bits<16>>; $B],
            expo: Signal<Local, Bits<16>>,
            frac: Signal<Local, Bits<$F>>,
            step: Signal<Local, Bits<$W>>,
            add: FpAddModal,
        }

        impl DopDecode {
            pub const LATENCY: usize = 1 + FpAdd::LATENCY;
            /// The code's bits.
            pub const CODE_BITS: usize = $B;
            /// The exponent field's bits.
            pub const EXP_FIELD_BITS: usize = $X;

            pub fn new() -> Self {
                Self {
                    clock: Default::default(),
                    r: Default::default(),
                    q: Default::default(),
                    ef: Default::default(),
                    valid_in: Default::default(),
                    round_up: Default::default(),
                    y: Default::default(),
                    valid_out: Default::default(),
                    s0_r: Default::default(),
                    s0_q: Default::default(),
                    s0_ef: Default::default(),
                    s0_valid: Default::default(),
                    s0_round: Default::default(),
                    r_add: Default::default(),
                    c_f: Constant::new(($F as u64).into()),
                    c_b: Constant::new(($B as u64).into()),
                    norm: Default::default(),
                    lz: Default::default(),
                    expo: Default::default(),
                    frac: Default::default(),
                    step: Default::default(),
                    add: Default::default(),
                }
            }
        }

        impl Default for DopDecode {
            fn default() -> Self {
                Self::new()
            }
        }

        impl Logic for DopDecode {
            #[hdl_gen]
            fn update(&mut self) {
                clock!(self, clock, add, r_add);
                dff_setup!(self, clock, s0_r, s0_q, s0_ef, s0_valid, s0_round);
                self.s0_round.d.next = self.round_up.val();
                self.r_add.d.next = self.s0_round.q.val();
                self.add.round_up.next = self.r_add.q.val();
                self.s0_r.d.next = self.r.val();
                self.s0_q.d.next = self.q.val();
                self.s0_ef.d.next = self.ef.val();
                self.s0_valid.d.next = self.valid_in.val();
                self.norm[0].next = self.s0_q.q.val();
                self.lz[0].next = 0.into();
                for i in 1..$B {
                    self.norm[i].next = self.norm[i - 1].val();
                    self.lz[i].next = self.lz[i - 1].val();
                    if !self.norm[i - 1].val().get_bit($B - 1) {
                        self.norm[i].next = self.norm[i - 1].val() << 1;
                        self.lz[i].next = self.lz[i - 1].val() + 1;
                    }
                }
                // biased exponent ef + B - lz - F when at least 1, else a subnormal
                self.expo.next = 0.into();
                self.frac.next = bit_cast::<$F, $B>(self.s0_q.q.val()) << self.s0_ef.q.val();
                if bit_cast::<16, $X>(self.s0_ef.q.val()) + self.c_b.val()
                    > self.c_f.val() + self.lz[$B - 1].val()
                {
                    self.expo.next = bit_cast::<16, $X>(self.s0_ef.q.val()) + self.c_b.val()
                        - self.lz[$B - 1].val()
                        - self.c_f.val();
                    self.frac.next = bit_cast::<$F, $B>(self.norm[$B - 1].val()) << ($F + 1 - $B);
                }
                self.step.next = (bit_cast::<$W, 16>(self.expo.val()) << $F)
                    | bit_cast::<$W, $F>(self.frac.val());
                if self.s0_q.q.val() == 0 {
                    self.step.next = 0.into();
                }
                self.add.a.next = self.s0_r.q.val();
                self.add.b.next = self.step.val();
                self.add.sub.next = true;
                self.add.valid_in.next = self.s0_valid.q.val();
                self.y.next = self.add.y.val();
                self.valid_out.next = self.add.valid_out.val();
            }
        }

        /// A decode stage ready to simulate as a top-level block (inputs claimed, connected).
        pub fn dop_decode_top() -> DopDecode {
            top_level!(DopDecode::new(); clock, r, q, ef, valid_in, round_up)
        }

        /// Verilog of [`dop_decode_top`] (top module `top`).
        pub fn verilog_dop_decode() -> String {
            generate_verilog(&dop_decode_top())
        }
    };
}
pub(crate) use dop_decode;

/// Stamps out `DopUnitCoded24` in the calling module (which must hold `DopDecode` and
/// `DopUnit24`). Arguments: `W`, `B` (the code's bits), `X` (the exponent field's).
macro_rules! dop_unit_coded {
    ($W:tt, $B:tt, $X:tt) => {
        /// The k = 24 DOP unit behind the decode stage of stored DOPs: a `DopDecode` per
        /// plane of each node of the pair (B's `d`, A's `e`) turns the node words' codes
        /// back into distances ([`dop::stored::decode`](crate::dop::stored::decode)), then
        /// [`DopUnit24`]. Latency `DopDecode::LATENCY + DopUnit24::LATENCY` (4 + 15); the
        /// tag and valid bit wait beside the decode stage.
        ///
        /// Ports: [`DopUnit24`]'s, with `d[k]`, `e[k]` the codes (`B` bits) and per plane the
        /// record's reference distances `rd[k]`, `re[k]` (`W`) and exponent fields `efd[k]`,
        /// `efe[k]` (`X`: `e - e_lo`). Plane i's decode stages round as lane i does: `rnd[i]`
        /// holds bit 15 of lane i's setup field 4, written with it.
        #[derive(LogicBlock)]
        pub struct DopUnitCoded24 {
            pub clock: Signal<In, Clock>,
            pub load_en: Signal<In, Bit>,
            pub load_addr: Signal<In, Bits<8>>,
            pub load_data: Signal<In, Bits<$W>>,
            pub d: [Signal<In, Bits<$B>>; 24],
            pub e: [Signal<In, Bits<$B>>; 24],
            pub rd: [Signal<In, Bits<$W>>; 24],
            pub re: [Signal<In, Bits<$W>>; 24],
            pub efd: [Signal<In, Bits<$X>>; 24],
            pub efe: [Signal<In, Bits<$X>>; 24],
            pub tag: Signal<In, Bits<16>>,
            pub valid_in: Signal<In, Bit>,
            pub overlap: Signal<Out, Bit>,
            pub tag_out: Signal<Out, Bits<16>>,
            pub valid_out: Signal<Out, Bit>,
            at_rnd: [Constant<Bits<8>>; 24],
            rnd: [DFF<Bit>; 24],
            dec_d: [DopDecode; 24],
            dec_e: [DopDecode; 24],
            tag_dec: $crate::rtl::delay::Delay<Bits<16>, { DopDecode::LATENCY }>,
            unit: DopUnit24,
        }

        impl DopUnitCoded24 {
            pub const LATENCY: usize = DopDecode::LATENCY + DopUnit24::LATENCY;

            pub fn new() -> Self {
                Self {
                    clock: Default::default(),
                    load_en: Default::default(),
                    load_addr: Default::default(),
                    load_data: Default::default(),
                    d: Default::default(),
                    e: Default::default(),
                    rd: Default::default(),
                    re: Default::default(),
                    efd: Default::default(),
                    efe: Default::default(),
                    tag: Default::default(),
                    valid_in: Default::default(),
                    overlap: Default::default(),
                    tag_out: Default::default(),
                    valid_out: Default::default(),
                    at_rnd: std::array::from_fn(|i| Constant::new(((8 * i + 4) as u64).into())),
                    rnd: $crate::rtl::reg_ring::array_init(),
                    dec_d: std::array::from_fn(|_| DopDecode::new()),
                    dec_e: std::array::from_fn(|_| DopDecode::new()),
                    tag_dec: Default::default(),
                    unit: DopUnit24::new(),
                }
            }
        }

        impl Default for DopUnitCoded24 {
            fn default() -> Self {
                Self::new()
            }
        }

        impl Logic for DopUnitCoded24 {
            #[hdl_gen]
            fn update(&mut self) {
                clock!(self, clock, tag_dec, unit);
                for i in 0..24 {
                    self.rnd[i].clock.next = self.clock.val();
                    self.rnd[i].d.next = self.rnd[i].q.val();
                    if self.load_en.val() & (self.load_addr.val() == self.at_rnd[i].val()) {
                        self.rnd[i].d.next = self.load_data.val().get_bit(15);
                    }
                    self.dec_d[i].round_up.next = self.rnd[i].q.val();
                    self.dec_e[i].round_up.next = self.rnd[i].q.val();
                    self.dec_d[i].clock.next = self.clock.val();
                    self.dec_d[i].r.next = self.rd[i].val();
                    self.dec_d[i].q.next = self.d[i].val();
                    self.dec_d[i].ef.next = self.efd[i].val();
                    self.dec_d[i].valid_in.next = self.valid_in.val();
                    self.dec_e[i].clock.next = self.clock.val();
                    self.dec_e[i].r.next = self.re[i].val();
                    self.dec_e[i].q.next = self.e[i].val();
                    self.dec_e[i].ef.next = self.efe[i].val();
                    self.dec_e[i].valid_in.next = self.valid_in.val();
                    self.unit.d[i].next = self.dec_d[i].y.val();
                    self.unit.e[i].next = self.dec_e[i].y.val();
                }
                self.tag_dec.d.next = self.tag.val();
                self.unit.load_en.next = self.load_en.val();
                self.unit.load_addr.next = self.load_addr.val();
                self.unit.load_data.next = self.load_data.val();
                self.unit.tag.next = self.tag_dec.q.val();
                self.unit.valid_in.next = self.dec_d[0].valid_out.val();
                self.overlap.next = self.unit.overlap.val();
                self.tag_out.next = self.unit.tag_out.val();
                self.valid_out.next = self.unit.valid_out.val();
            }
        }
    };
}
pub(crate) use dop_unit_coded;
