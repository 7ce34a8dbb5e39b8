//! Pipelined floating-point multiplier (`FpMul`), stamped out per format by `fp_mul!`.

/// Stamps out `FpMul` for one format in the calling module (which must also hold the
/// `fp_common!` blocks). Arguments as for `fp_common!`: `W`, `E`, `F`, `P`, `P2`.
macro_rules! fp_mul {
    ($W:tt, $E:tt, $F:tt, $P:tt, $P2:tt) => {
        /// Pipelined multiplier implementing [`Format::mul`](crate::format::Format::mul)
        /// bit for bit, rounding as `round_up` says (1: TowardPositive, 0: NearestEven): a
        /// constant fixed at construction (`FpMul::new`), or an input that the round stage
        /// (4) reads (`FpMulModal`, the DOP lanes', which give each operation's rounding there).
        ///
        /// One operation per clock; latency 4 (four register ranks): operands presented
        /// on `a`, `b`, `valid_in` before rising edge 1 give `y`, `valid_out` right after
        /// rising edge 4.
        ///
        /// | stage | logic | registers |
        /// |---|---|---|
        /// | 1 | unpack both operands, normalise subnormal significands (`norm_a`, `norm_b`), exponent sum, special classes | `s1_*` |
        /// | 2 | `P x P` significand product (`sig_mul`), kept as top `P+2` bits + sticky | `s2_*` |
        /// | 3 | 1-bit product normalisation, exponent; right shift (with sticky) onto the subnormal grid when the exponent is below `emin`; pre-rounding overflow | `s3_*` |
        /// | 4 | round (NearestEven or TowardPositive) and pack, specials (`round`) | `s4_*` = outputs |
        ///
        /// Exponents inside the pipeline are 10-bit with an offset of 256 (biased
        /// exponent `e` is held as `e + 256`), so products of subnormals stay positive.
        #[derive(LogicBlock)]
        pub struct FpMul<R: $crate::rtl::common::RoundUp = Constant<Bit>> {
            pub clock: Signal<In, Clock>,
            pub a: Signal<In, Bits<$W>>,
            pub b: Signal<In, Bits<$W>>,
            pub valid_in: Signal<In, Bit>,
            pub y: Signal<Out, Bits<$W>>,
            pub valid_out: Signal<Out, Bit>,
            // configuration and constants
            pub round_up: R,
            c_exp_adj: Constant<Bits<10>>,
            c_exp_ofs: Constant<Bits<10>>,
            c_exp_norm_min: Constant<Bits<10>>,
            c_exp_ovf: Constant<Bits<10>>,
            c_shift_cap: Constant<Bits<10>>,
            // stage 1
            unpack_a: Unpack,
            unpack_b: Unpack,
            norm_a: NormP,
            norm_b: NormP,
            c1_exp: Signal<Local, Bits<10>>,
            s1_valid: DFF<Bit>,
            s1_sign: DFF<Bit>,
            s1_nan: DFF<Bit>,
            s1_inf: DFF<Bit>,
            s1_zero: DFF<Bit>,
            s1_exp: DFF<Bits<10>>,
            s1_sig_a: DFF<Bits<$P>>,
            s1_sig_b: DFF<Bits<$P>>,
            // stage 2
            sig_mul: SigMul,
            s2_valid: DFF<Bit>,
            s2_sign: DFF<Bit>,
            s2_nan: DFF<Bit>,
            s2_inf: DFF<Bit>,
            s2_zero: DFF<Bit>,
            s2_exp: DFF<Bits<10>>,
            s2_hi: DFF<Bits<$P2>>,
            s2_sticky: DFF<Bit>,
            // stage 3
            c3_top: Signal<Local, Bit>,
            c3_nm: Signal<Local, Bits<$P2>>,
            c3_exp: Signal<Local, Bits<10>>,
            c3_shift: Signal<Local, Bits<10>>,
            c3_shift_cap: Signal<Local, Bits<10>>,
            c3_shifted: Signal<Local, Bits<$P2>>,
            c3_back: Signal<Local, Bits<$P2>>,
            c3_lost: Signal<Local, Bit>,
            c3_efield: Signal<Local, Bits<$E>>,
            s3_valid: DFF<Bit>,
            s3_sign: DFF<Bit>,
            s3_nan: DFF<Bit>,
            s3_inf: DFF<Bit>,
            s3_zero: DFF<Bit>,
            s3_ovf: DFF<Bit>,
            s3_efield: DFF<Bits<$E>>,
            s3_nm: DFF<Bits<$P2>>,
            // stage 4
            round: RoundPack,
            s4_valid: DFF<Bit>,
            s4_y: DFF<Bits<$W>>,
        }

        impl FpMul {
            pub const LATENCY: usize = 4;

            /// A multiplier rounding with `rounding` (NearestEven or TowardPositive).
            pub fn new(rounding: Rounding) -> Self {
                Self::with(Constant::new($crate::rtl::common::round_up(
                    rounding, "FpMul",
                )))
            }
        }

        /// FpMul whose rounding is an input, `round_up` (the DOP lanes').
        pub type FpMulModal = FpMul<Signal<In, Bit>>;

        /// A multiplier rounding as its input `round_up` says.
        impl Default for FpMulModal {
            fn default() -> Self {
                Self::with(Default::default())
            }
        }

        impl<R: $crate::rtl::common::RoundUp> FpMul<R> {
            fn with(round_up: R) -> Self {
                let bias: u64 = (1u64 << ($E - 1)) - 1;
                let ones: u64 = (1u64 << $E) - 1;
                Self {
                    clock: Default::default(),
                    a: Default::default(),
                    b: Default::default(),
                    valid_in: Default::default(),
                    y: Default::default(),
                    valid_out: Default::default(),
                    round_up,
                    c_exp_adj: Constant::new((256 - bias).into()),
                    c_exp_ofs: Constant::new(256u64.into()),
                    c_exp_norm_min: Constant::new(257u64.into()),
                    c_exp_ovf: Constant::new((256 + ones).into()),
                    c_shift_cap: Constant::new(($P2 as u64).into()),
                    unpack_a: Default::default(),
                    unpack_b: Default::default(),
                    norm_a: Default::default(),
                    norm_b: Default::default(),
                    c1_exp: Default::default(),
                    s1_valid: Default::default(),
                    s1_sign: Default::default(),
                    s1_nan: Default::default(),
                    s1_inf: Default::default(),
                    s1_zero: Default::default(),
                    s1_exp: Default::default(),
                    s1_sig_a: Default::default(),
                    s1_sig_b: Default::default(),
                    sig_mul: Default::default(),
                    s2_valid: Default::default(),
                    s2_sign: Default::default(),
                    s2_nan: Default::default(),
                    s2_inf: Default::default(),
                    s2_zero: Default::default(),
                    s2_exp: Default::default(),
                    s2_hi: Default::default(),
                    s2_sticky: Default::default(),
                    c3_top: Default::default(),
                    c3_nm: Default::default(),
                    c3_exp: Default::default(),
                    c3_shift: Default::default(),
                    c3_shift_cap: Default::default(),
                    c3_shifted: Default::default(),
                    c3_back: Default::default(),
                    c3_lost: Default::default(),
                    c3_efield: Default::default(),
                    s3_valid: Default::default(),
                    s3_sign: Default::default(),
                    s3_nan: Default::default(),
                    s3_inf: Default::default(),
                    s3_zero: Default::default(),
                    s3_ovf: Default::default(),
                    s3_efield: Default::default(),
                    s3_nm: Default::default(),
                    round: Default::default(),
                    s4_valid: Default::default(),
                    s4_y: Default::default(),
                }
            }
        }

        impl<R: $crate::rtl::common::RoundUp> Logic for FpMul<R> {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(
                    self, clock, s1_valid, s1_sign, s1_nan, s1_inf, s1_zero, s1_exp, s1_sig_a,
                    s1_sig_b
                );
                dff_setup!(
                    self, clock, s2_valid, s2_sign, s2_nan, s2_inf, s2_zero, s2_exp, s2_hi,
                    s2_sticky
                );
                dff_setup!(
                    self, clock, s3_valid, s3_sign, s3_nan, s3_inf, s3_zero, s3_ovf, s3_efield,
                    s3_nm
                );
                dff_setup!(self, clock, s4_valid, s4_y);
                // ---- stage 1: unpack, normalise subnormal significands, exponent sum
                self.unpack_a.x.next = self.a.val();
                self.unpack_b.x.next = self.b.val();
                self.norm_a.x.next = self.unpack_a.sig.val();
                self.norm_b.x.next = self.unpack_b.sig.val();
                self.c1_exp.next = bit_cast::<10, $E>(self.unpack_a.exp.val())
                    + bit_cast::<10, $E>(self.unpack_b.exp.val())
                    - bit_cast::<10, 5>(self.norm_a.lz.val())
                    - bit_cast::<10, 5>(self.norm_b.lz.val())
                    + self.c_exp_adj.val();
                self.s1_valid.d.next = self.valid_in.val();
                self.s1_sign.d.next = self.unpack_a.sign.val() ^ self.unpack_b.sign.val();
                self.s1_nan.d.next = self.unpack_a.is_nan.val()
                    | self.unpack_b.is_nan.val()
                    | (self.unpack_a.is_inf.val() & self.unpack_b.is_zero.val())
                    | (self.unpack_a.is_zero.val() & self.unpack_b.is_inf.val());
                self.s1_inf.d.next = self.unpack_a.is_inf.val() | self.unpack_b.is_inf.val();
                self.s1_zero.d.next = self.unpack_a.is_zero.val() | self.unpack_b.is_zero.val();
                self.s1_exp.d.next = self.c1_exp.val();
                self.s1_sig_a.d.next = self.norm_a.y.val();
                self.s1_sig_b.d.next = self.norm_b.y.val();
                // ---- stage 2: significand product
                self.sig_mul.a.next = self.s1_sig_a.q.val();
                self.sig_mul.b.next = self.s1_sig_b.q.val();
                self.s2_valid.d.next = self.s1_valid.q.val();
                self.s2_sign.d.next = self.s1_sign.q.val();
                self.s2_nan.d.next = self.s1_nan.q.val();
                self.s2_inf.d.next = self.s1_inf.q.val();
                self.s2_zero.d.next = self.s1_zero.q.val();
                self.s2_exp.d.next = self.s1_exp.q.val();
                self.s2_hi.d.next = self.sig_mul.hi.val();
                self.s2_sticky.d.next = self.sig_mul.sticky.val();
                // ---- stage 3: normalise by one bit, shift onto the subnormal grid
                self.c3_top.next = self.s2_hi.q.val().get_bit($P + 1);
                self.c3_nm.next = (self.s2_hi.q.val() << 1).replace_bit(0, self.s2_sticky.q.val());
                if self.c3_top.val() {
                    self.c3_nm.next = self
                        .s2_hi
                        .q
                        .val()
                        .replace_bit(0, self.s2_hi.q.val().get_bit(0) | self.s2_sticky.q.val());
                }
                self.c3_exp.next = self.s2_exp.q.val() + self.c3_top.val();
                self.c3_shift.next = 0.into();
                if self.c3_exp.val() < self.c_exp_norm_min.val() {
                    self.c3_shift.next = self.c_exp_norm_min.val() - self.c3_exp.val();
                }
                self.c3_shift_cap.next = self.c3_shift.val();
                if self.c3_shift.val() > self.c_shift_cap.val() {
                    self.c3_shift_cap.next = self.c_shift_cap.val();
                }
                self.c3_shifted.next = self.c3_nm.val() >> self.c3_shift_cap.val();
                self.c3_back.next = self.c3_shifted.val() << self.c3_shift_cap.val();
                self.c3_lost.next = self.c3_back.val() != self.c3_nm.val();
                self.c3_efield.next = 0.into();
                if self.c3_shift.val() == 0 {
                    self.c3_efield.next =
                        bit_cast::<$E, 10>(self.c3_exp.val() - self.c_exp_ofs.val());
                }
                self.s3_valid.d.next = self.s2_valid.q.val();
                self.s3_sign.d.next = self.s2_sign.q.val();
                self.s3_nan.d.next = self.s2_nan.q.val();
                self.s3_inf.d.next = self.s2_inf.q.val();
                self.s3_zero.d.next = self.s2_zero.q.val();
                self.s3_ovf.d.next = self.c3_exp.val() >= self.c_exp_ovf.val();
                self.s3_efield.d.next = self.c3_efield.val();
                self.s3_nm.d.next = self
                    .c3_shifted
                    .val()
                    .replace_bit(0, self.c3_shifted.val().get_bit(0) | self.c3_lost.val());
                // ---- stage 4: round and pack
                self.round.round_up.next = self.round_up.val();
                self.round.sign.next = self.s3_sign.q.val();
                self.round.nan.next = self.s3_nan.q.val();
                self.round.inf.next = self.s3_inf.q.val();
                self.round.zero.next = self.s3_zero.q.val();
                self.round.ovf.next = self.s3_ovf.q.val();
                self.round.efield.next = self.s3_efield.q.val();
                self.round.nm.next = self.s3_nm.q.val();
                self.s4_valid.d.next = self.s3_valid.q.val();
                self.s4_y.d.next = self.round.y.val();
                self.y.next = self.s4_y.q.val();
                self.valid_out.next = self.s4_valid.q.val();
            }
        }
    };
}
pub(crate) use fp_mul;
