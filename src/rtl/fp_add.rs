//! Pipelined floating-point adder (`FpAdd`), stamped out per format by `fp_add!`.

/// Stamps out `FpAdd` for one format in the calling module (which must also hold the
/// `fp_common!` blocks). Arguments: `W`, `WM1`, `E`, `F`, `P`, `P2`, `P3`, `P4`.
macro_rules! fp_add {
    ($W:tt, $WM1:tt, $E:tt, $F:tt, $P:tt, $P2:tt, $P3:tt, $P4:tt) => {
        /// Pipelined adder implementing [`Format::add`](crate::format::Format::add)
        /// (`sub` = 0) and [`Format::sub`](crate::format::Format::sub) (`sub` = 1, the
        /// sign of `b` is flipped) bit for bit, rounding as `round_up` says (1:
        /// TowardPositive, 0: NearestEven): a constant fixed at construction (`FpAdd::new`),
        /// or an input that the round stage (3) reads (`FpAddModal`, the DOP lanes', which
        /// give each operation's rounding there).
        ///
        /// One operation per clock; latency 3 (three register ranks): operands presented
        /// on `a`, `b`, `sub`, `valid_in` before rising edge 1 give `y`, `valid_out`
        /// right after rising edge 3.
        ///
        /// | stage | logic | registers |
        /// |---|---|---|
        /// | 1 | unpack, order by magnitude (`|a| < |b|` swaps), align the smaller significand (`P+3` bits: guard, round, sticky jammed into the LSB), special classes | `s1_*` |
        /// | 2 | add / subtract (`P+4` bits), normalise: right by one on carry, else left by the leading zeros but at most down to `emin` (gradual underflow); exact-zero sign | `s2_*` |
        /// | 3 | round (NearestEven or TowardPositive) and pack, specials (`round`) | `s3_*` = outputs |
        #[derive(LogicBlock)]
        pub struct FpAdd<R: $crate::rtl::common::RoundUp = Constant<Bit>> {
            pub clock: Signal<In, Clock>,
            pub a: Signal<In, Bits<$W>>,
            pub b: Signal<In, Bits<$W>>,
            pub sub: Signal<In, Bit>,
            pub valid_in: Signal<In, Bit>,
            pub y: Signal<Out, Bits<$W>>,
            pub valid_out: Signal<Out, Bit>,
            // configuration and constants
            pub round_up: R,
            c_align_cap: Constant<Bits<$E>>,
            c_exp_ones: Constant<Bits<10>>,
            // stage 1
            unpack_a: Unpack,
            unpack_b: Unpack,
            c1_b_sign: Signal<Local, Bit>,
            c1_swap: Signal<Local, Bit>,
            c1_big_sign: Signal<Local, Bit>,
            c1_big_exp: Signal<Local, Bits<$E>>,
            c1_big_sig: Signal<Local, Bits<$P>>,
            c1_small_sign: Signal<Local, Bit>,
            c1_small_exp: Signal<Local, Bits<$E>>,
            c1_small_sig: Signal<Local, Bits<$P>>,
            c1_diff: Signal<Local, Bits<$E>>,
            c1_shift: Signal<Local, Bits<$E>>,
            c1_small_ext: Signal<Local, Bits<$P3>>,
            c1_aligned: Signal<Local, Bits<$P3>>,
            c1_back: Signal<Local, Bits<$P3>>,
            c1_lost: Signal<Local, Bit>,
            c1_inf_sign: Signal<Local, Bit>,
            s1_valid: DFF<Bit>,
            s1_nan: DFF<Bit>,
            s1_inf: DFF<Bit>,
            s1_inf_sign: DFF<Bit>,
            s1_zero_sign: DFF<Bit>,
            s1_sign: DFF<Bit>,
            s1_eff_sub: DFF<Bit>,
            s1_exp: DFF<Bits<$E>>,
            s1_big: DFF<Bits<$P3>>,
            s1_small: DFF<Bits<$P3>>,
            // stage 2
            norm: NormP3,
            c2_sum: Signal<Local, Bits<$P4>>,
            c2_carry: Signal<Local, Bit>,
            c2_zero: Signal<Local, Bit>,
            c2_limit: Signal<Local, Bits<$E>>,
            c2_lz: Signal<Local, Bits<$E>>,
            c2_shift: Signal<Local, Bits<$E>>,
            c2_shifted: Signal<Local, Bits<$P3>>,
            c2_exp: Signal<Local, Bits<10>>,
            c2_nm: Signal<Local, Bits<$P2>>,
            c2_sign: Signal<Local, Bit>,
            s2_valid: DFF<Bit>,
            s2_sign: DFF<Bit>,
            s2_nan: DFF<Bit>,
            s2_inf: DFF<Bit>,
            s2_zero: DFF<Bit>,
            s2_ovf: DFF<Bit>,
            s2_efield: DFF<Bits<$E>>,
            s2_nm: DFF<Bits<$P2>>,
            // stage 3
            round: RoundPack,
            s3_valid: DFF<Bit>,
            s3_y: DFF<Bits<$W>>,
        }

        impl FpAdd {
            pub const LATENCY: usize = 3;

            /// An adder rounding with `rounding` (NearestEven or TowardPositive).
            pub fn new(rounding: Rounding) -> Self {
                Self::with(Constant::new($crate::rtl::common::round_up(
                    rounding, "FpAdd",
                )))
            }
        }

        /// FpAdd whose rounding is an input, `round_up` (the DOP lanes').
        pub type FpAddModal = FpAdd<Signal<In, Bit>>;

        /// An adder rounding as its input `round_up` says.
        impl Default for FpAddModal {
            fn default() -> Self {
                Self::with(Default::default())
            }
        }

        impl<R: $crate::rtl::common::RoundUp> FpAdd<R> {
            fn with(round_up: R) -> Self {
                let ones: u64 = (1u64 << $E) - 1;
                Self {
                    clock: Default::default(),
                    a: Default::default(),
                    b: Default::default(),
                    sub: Default::default(),
                    valid_in: Default::default(),
                    y: Default::default(),
                    valid_out: Default::default(),
                    round_up,
                    c_align_cap: Constant::new(($P3 as u64).into()),
                    c_exp_ones: Constant::new(ones.into()),
                    unpack_a: Default::default(),
                    unpack_b: Default::default(),
                    c1_b_sign: Default::default(),
                    c1_swap: Default::default(),
                    c1_big_sign: Default::default(),
                    c1_big_exp: Default::default(),
                    c1_big_sig: Default::default(),
                    c1_small_sign: Default::default(),
                    c1_small_exp: Default::default(),
                    c1_small_sig: Default::default(),
                    c1_diff: Default::default(),
                    c1_shift: Default::default(),
                    c1_small_ext: Default::default(),
                    c1_aligned: Default::default(),
                    c1_back: Default::default(),
                    c1_lost: Default::default(),
                    c1_inf_sign: Default::default(),
                    s1_valid: Default::default(),
                    s1_nan: Default::default(),
                    s1_inf: Default::default(),
                    s1_inf_sign: Default::default(),
                    s1_zero_sign: Default::default(),
                    s1_sign: Default::default(),
                    s1_eff_sub: Default::default(),
                    s1_exp: Default::default(),
                    s1_big: Default::default(),
                    s1_small: Default::default(),
                    norm: Default::default(),
                    c2_sum: Default::default(),
                    c2_carry: Default::default(),
                    c2_zero: Default::default(),
                    c2_limit: Default::default(),
                    c2_lz: Default::default(),
                    c2_shift: Default::default(),
                    c2_shifted: Default::default(),
                    c2_exp: Default::default(),
                    c2_nm: Default::default(),
                    c2_sign: Default::default(),
                    s2_valid: Default::default(),
                    s2_sign: Default::default(),
                    s2_nan: Default::default(),
                    s2_inf: Default::default(),
                    s2_zero: Default::default(),
                    s2_ovf: Default::default(),
                    s2_efield: Default::default(),
                    s2_nm: Default::default(),
                    round: Default::default(),
                    s3_valid: Default::default(),
                    s3_y: Default::default(),
                }
            }
        }

        impl<R: $crate::rtl::common::RoundUp> Logic for FpAdd<R> {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(
                    self,
                    clock,
                    s1_valid,
                    s1_nan,
                    s1_inf,
                    s1_inf_sign,
                    s1_zero_sign,
                    s1_sign,
                    s1_eff_sub,
                    s1_exp,
                    s1_big,
                    s1_small
                );
                dff_setup!(
                    self, clock, s2_valid, s2_sign, s2_nan, s2_inf, s2_zero, s2_ovf, s2_efield,
                    s2_nm
                );
                dff_setup!(self, clock, s3_valid, s3_y);
                // ---- stage 1: unpack, order by magnitude, align
                self.unpack_a.x.next = self.a.val();
                self.unpack_b.x.next = self.b.val();
                self.c1_b_sign.next = self.unpack_b.sign.val() ^ self.sub.val();
                self.c1_swap.next =
                    self.a.val().get_bits::<$WM1>(0) < self.b.val().get_bits::<$WM1>(0);
                self.c1_big_sign.next = self.unpack_a.sign.val();
                self.c1_big_exp.next = self.unpack_a.exp.val();
                self.c1_big_sig.next = self.unpack_a.sig.val();
                self.c1_small_sign.next = self.c1_b_sign.val();
                self.c1_small_exp.next = self.unpack_b.exp.val();
                self.c1_small_sig.next = self.unpack_b.sig.val();
                if self.c1_swap.val() {
                    self.c1_big_sign.next = self.c1_b_sign.val();
                    self.c1_big_exp.next = self.unpack_b.exp.val();
                    self.c1_big_sig.next = self.unpack_b.sig.val();
                    self.c1_small_sign.next = self.unpack_a.sign.val();
                    self.c1_small_exp.next = self.unpack_a.exp.val();
                    self.c1_small_sig.next = self.unpack_a.sig.val();
                }
                self.c1_diff.next = self.c1_big_exp.val() - self.c1_small_exp.val();
                self.c1_shift.next = self.c1_diff.val();
                if self.c1_diff.val() > self.c_align_cap.val() {
                    self.c1_shift.next = self.c_align_cap.val();
                }
                self.c1_small_ext.next = bit_cast::<$P3, $P>(self.c1_small_sig.val()) << 3;
                self.c1_aligned.next = self.c1_small_ext.val() >> self.c1_shift.val();
                self.c1_back.next = self.c1_aligned.val() << self.c1_shift.val();
                self.c1_lost.next = self.c1_back.val() != self.c1_small_ext.val();
                self.c1_inf_sign.next = self.c1_b_sign.val();
                if self.unpack_a.is_inf.val() {
                    self.c1_inf_sign.next = self.unpack_a.sign.val();
                }
                self.s1_valid.d.next = self.valid_in.val();
                self.s1_nan.d.next = self.unpack_a.is_nan.val()
                    | self.unpack_b.is_nan.val()
                    | (self.unpack_a.is_inf.val()
                        & self.unpack_b.is_inf.val()
                        & (self.unpack_a.sign.val() ^ self.c1_b_sign.val()));
                self.s1_inf.d.next = self.unpack_a.is_inf.val() | self.unpack_b.is_inf.val();
                self.s1_inf_sign.d.next = self.c1_inf_sign.val();
                self.s1_zero_sign.d.next = self.unpack_a.sign.val() & self.c1_b_sign.val();
                self.s1_sign.d.next = self.c1_big_sign.val();
                self.s1_eff_sub.d.next = self.c1_big_sign.val() ^ self.c1_small_sign.val();
                self.s1_exp.d.next = self.c1_big_exp.val();
                self.s1_big.d.next = bit_cast::<$P3, $P>(self.c1_big_sig.val()) << 3;
                self.s1_small.d.next = self
                    .c1_aligned
                    .val()
                    .replace_bit(0, self.c1_aligned.val().get_bit(0) | self.c1_lost.val());
                // ---- stage 2: add / subtract, normalise
                self.c2_sum.next = bit_cast::<$P4, $P3>(self.s1_big.q.val())
                    + bit_cast::<$P4, $P3>(self.s1_small.q.val());
                if self.s1_eff_sub.q.val() {
                    self.c2_sum.next = bit_cast::<$P4, $P3>(self.s1_big.q.val())
                        - bit_cast::<$P4, $P3>(self.s1_small.q.val());
                }
                self.c2_carry.next = self.c2_sum.val().get_bit($P3);
                self.c2_zero.next = self.c2_sum.val() == 0;
                self.norm.x.next = self.c2_sum.val().get_bits::<$P3>(0);
                self.c2_limit.next = self.s1_exp.q.val() - 1;
                self.c2_lz.next = bit_cast::<$E, 5>(self.norm.lz.val());
                self.c2_shift.next = self.c2_lz.val();
                if self.c2_lz.val() > self.c2_limit.val() {
                    self.c2_shift.next = self.c2_limit.val();
                }
                self.c2_shifted.next = self.c2_sum.val().get_bits::<$P3>(0) << self.c2_shift.val();
                self.c2_exp.next = bit_cast::<10, $E>(self.s1_exp.q.val())
                    - bit_cast::<10, $E>(self.c2_shift.val());
                self.c2_nm.next = bit_cast::<$P2, $P3>(self.c2_shifted.val() >> 1).replace_bit(
                    0,
                    self.c2_shifted.val().get_bit(1) | self.c2_shifted.val().get_bit(0),
                );
                if self.c2_carry.val() {
                    self.c2_exp.next = bit_cast::<10, $E>(self.s1_exp.q.val()) + 1;
                    self.c2_nm.next = bit_cast::<$P2, $P4>(self.c2_sum.val() >> 2).replace_bit(
                        0,
                        self.c2_sum.val().get_bit(2)
                            | self.c2_sum.val().get_bit(1)
                            | self.c2_sum.val().get_bit(0),
                    );
                }
                self.c2_sign.next = self.s1_sign.q.val();
                if self.c2_zero.val() {
                    self.c2_sign.next = self.s1_zero_sign.q.val();
                }
                if self.s1_inf.q.val() {
                    self.c2_sign.next = self.s1_inf_sign.q.val();
                }
                self.s2_valid.d.next = self.s1_valid.q.val();
                self.s2_sign.d.next = self.c2_sign.val();
                self.s2_nan.d.next = self.s1_nan.q.val();
                self.s2_inf.d.next = self.s1_inf.q.val();
                self.s2_zero.d.next = self.c2_zero.val();
                self.s2_ovf.d.next = self.c2_exp.val() >= self.c_exp_ones.val();
                self.s2_efield.d.next = 0.into();
                if self.c2_nm.val().get_bit($P + 1) {
                    self.s2_efield.d.next = bit_cast::<$E, 10>(self.c2_exp.val());
                }
                self.s2_nm.d.next = self.c2_nm.val();
                // ---- stage 3: round and pack
                self.round.round_up.next = self.round_up.val();
                self.round.sign.next = self.s2_sign.q.val();
                self.round.nan.next = self.s2_nan.q.val();
                self.round.inf.next = self.s2_inf.q.val();
                self.round.zero.next = self.s2_zero.q.val();
                self.round.ovf.next = self.s2_ovf.q.val();
                self.round.efield.next = self.s2_efield.q.val();
                self.round.nm.next = self.s2_nm.q.val();
                self.s3_valid.d.next = self.s2_valid.q.val();
                self.s3_y.d.next = self.round.y.val();
                self.y.next = self.s3_y.q.val();
                self.valid_out.next = self.s3_valid.q.val();
            }
        }
    };
}
pub(crate) use fp_add;
