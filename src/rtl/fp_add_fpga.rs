//! The floating-point adder at FPGA depth (`FpAddFpga`), stamped out per format by
//! `fp_add_fpga!`.

/// Stamps out `FpAddFpga` for one format in the calling module (which must also hold the
/// `fp_common!` blocks). Arguments as for `fp_add!`: `W`, `WM1`, `E`, `F`, `P`, `P2`, `P3`,
/// `P4`.
macro_rules! fp_add_fpga {
    ($W:tt, $WM1:tt, $E:tt, $F:tt, $P:tt, $P2:tt, $P3:tt, $P4:tt) => {
        /// `FpAdd` cut for an FPGA: the same operation bit for bit ([`Format::add`],
        /// [`Format::sub`](crate::format::Format::sub); rounding `round_up`, read at the
        /// round stage, 6), the same ports, latency
        /// [`Depth::Fpga`](crate::chip::rtl::Depth::Fpga)'s, 6. Each of
        /// `FpAdd`'s stages 1 and 2 is cut in two or three, so that a stage is a few LUT
        /// levels and one carry chain: on an ECP5 a LUT level and its routing cost about
        /// 1 ns, where an OSU 0.18 um gate costs a tenth of that.
        ///
        /// | stage | logic | registers |
        /// |---|---|---|
        /// | 1 | unpack; order by magnitude (`|a| < |b|` swaps); both exponent differences, each capped at `P+3`, the swap picks one | `s1_*` |
        /// | 2 | align the smaller significand, its sticky bit from a mask of the bits shifted out (a thermometer decode of the shift, no carry chain) | `s2_*` |
        /// | 3 | add / subtract (`P+4` bits); beside it a one-hot marker at bit `P+2 - (exp - 1)` | `s3_*` |
        /// | 4 | leading zeros ([`Lzc`](crate::rtl::Lzc)) of the sum OR the marker: the count capped at `exp - 1` without a compare, so the exponent stays at `emin` or above; exact-zero and infinity signs | `s4_*` |
        /// | 5 | normalise: right by one on carry, else left by stage 4's count; overflow, exponent field | `s5_*` |
        /// | 6 | round and pack (`round`, as `FpAdd`'s stage 3) | `s6_*` = outputs |
        ///
        /// [`Format::add`]: crate::format::Format::add
        #[derive(LogicBlock)]
        pub struct FpAddFpga<R: $crate::rtl::common::RoundUp = Constant<Bit>> {
            pub clock: Signal<In, Clock>,
            pub a: Signal<In, Bits<$W>>,
            pub b: Signal<In, Bits<$W>>,
            pub sub: Signal<In, Bit>,
            pub valid_in: Signal<In, Bit>,
            pub y: Signal<Out, Bits<$W>>,
            pub valid_out: Signal<Out, Bit>,
            pub round_up: R,
            c_align_cap: Constant<Bits<$E>>,
            c_exp_ones: Constant<Bits<10>>,
            c_ones: Constant<Bits<$P3>>,
            c_top: Constant<Bits<$P3>>,
            unpack_a: Unpack,
            unpack_b: Unpack,
            c1_b_sign: Signal<Local, Bit>,
            c1_swap: Signal<Local, Bit>,
            c1_d_ab: Signal<Local, Bits<$E>>,
            c1_d_ba: Signal<Local, Bits<$E>>,
            c1_sh_ab: Signal<Local, Bits<$E>>,
            c1_sh_ba: Signal<Local, Bits<$E>>,
            c1_inf_sign: Signal<Local, Bit>,
            s1_valid: DFF<Bit>,
            s1_nan: DFF<Bit>,
            s1_inf: DFF<Bit>,
            s1_inf_sign: DFF<Bit>,
            s1_zero_sign: DFF<Bit>,
            s1_sign: DFF<Bit>,
            s1_eff_sub: DFF<Bit>,
            s1_exp: DFF<Bits<$E>>,
            s1_big: DFF<Bits<$P>>,
            s1_small: DFF<Bits<$P>>,
            s1_shift: DFF<Bits<$E>>,
            c2_small_ext: Signal<Local, Bits<$P3>>,
            c2_aligned: Signal<Local, Bits<$P3>>,
            c2_mask: Signal<Local, Bits<$P3>>,
            c2_lost: Signal<Local, Bit>,
            s2_valid: DFF<Bit>,
            s2_nan: DFF<Bit>,
            s2_inf: DFF<Bit>,
            s2_inf_sign: DFF<Bit>,
            s2_zero_sign: DFF<Bit>,
            s2_sign: DFF<Bit>,
            s2_eff_sub: DFF<Bit>,
            s2_exp: DFF<Bits<$E>>,
            s2_big: DFF<Bits<$P3>>,
            s2_small: DFF<Bits<$P3>>,
            c3_sum: Signal<Local, Bits<$P4>>,
            c3_limit: Signal<Local, Bits<$E>>,
            s3_valid: DFF<Bit>,
            s3_nan: DFF<Bit>,
            s3_inf: DFF<Bit>,
            s3_inf_sign: DFF<Bit>,
            s3_zero_sign: DFF<Bit>,
            s3_sign: DFF<Bit>,
            s3_exp: DFF<Bits<$E>>,
            s3_sum: DFF<Bits<$P4>>,
            s3_marker: DFF<Bits<$P3>>,
            lzc: $crate::rtl::lzc::Lzc<$P3>,
            c4_zero: Signal<Local, Bit>,
            c4_sign: Signal<Local, Bit>,
            s4_valid: DFF<Bit>,
            s4_sign: DFF<Bit>,
            s4_nan: DFF<Bit>,
            s4_inf: DFF<Bit>,
            s4_zero: DFF<Bit>,
            s4_exp: DFF<Bits<$E>>,
            s4_shift: DFF<Bits<$E>>,
            s4_sum: DFF<Bits<$P4>>,
            c5_shifted: Signal<Local, Bits<$P3>>,
            c5_exp: Signal<Local, Bits<10>>,
            c5_nm: Signal<Local, Bits<$P2>>,
            s5_valid: DFF<Bit>,
            s5_sign: DFF<Bit>,
            s5_nan: DFF<Bit>,
            s5_inf: DFF<Bit>,
            s5_zero: DFF<Bit>,
            s5_ovf: DFF<Bit>,
            s5_efield: DFF<Bits<$E>>,
            s5_nm: DFF<Bits<$P2>>,
            round: RoundPack,
            s6_valid: DFF<Bit>,
            s6_y: DFF<Bits<$W>>,
        }

        impl FpAddFpga {
            pub const LATENCY: usize = $crate::chip::rtl::Depth::Fpga.fp_add_latency();

            /// An adder rounding with `rounding` (NearestEven or TowardPositive).
            pub fn new(rounding: Rounding) -> Self {
                Self::with(Constant::new($crate::rtl::common::round_up(
                    rounding,
                    "FpAddFpga",
                )))
            }
        }

        /// FpAddFpga whose rounding is an input, `round_up` (the DOP lanes').
        pub type FpAddFpgaModal = FpAddFpga<Signal<In, Bit>>;

        /// An adder rounding as its input `round_up` says.
        impl Default for FpAddFpgaModal {
            fn default() -> Self {
                Self::with(Default::default())
            }
        }

        impl<R: $crate::rtl::common::RoundUp> FpAddFpga<R> {
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
                    c_ones: Constant::new(((1u64 << $P3) - 1).into()),
                    c_top: Constant::new((1u64 << ($P3 - 1)).into()),
                    unpack_a: Default::default(),
                    unpack_b: Default::default(),
                    c1_b_sign: Default::default(),
                    c1_swap: Default::default(),
                    c1_d_ab: Default::default(),
                    c1_d_ba: Default::default(),
                    c1_sh_ab: Default::default(),
                    c1_sh_ba: Default::default(),
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
                    s1_shift: Default::default(),
                    c2_small_ext: Default::default(),
                    c2_aligned: Default::default(),
                    c2_mask: Default::default(),
                    c2_lost: Default::default(),
                    s2_valid: Default::default(),
                    s2_nan: Default::default(),
                    s2_inf: Default::default(),
                    s2_inf_sign: Default::default(),
                    s2_zero_sign: Default::default(),
                    s2_sign: Default::default(),
                    s2_eff_sub: Default::default(),
                    s2_exp: Default::default(),
                    s2_big: Default::default(),
                    s2_small: Default::default(),
                    c3_sum: Default::default(),
                    c3_limit: Default::default(),
                    s3_valid: Default::default(),
                    s3_nan: Default::default(),
                    s3_inf: Default::default(),
                    s3_inf_sign: Default::default(),
                    s3_zero_sign: Default::default(),
                    s3_sign: Default::default(),
                    s3_exp: Default::default(),
                    s3_sum: Default::default(),
                    s3_marker: Default::default(),
                    lzc: Default::default(),
                    c4_zero: Default::default(),
                    c4_sign: Default::default(),
                    s4_valid: Default::default(),
                    s4_sign: Default::default(),
                    s4_nan: Default::default(),
                    s4_inf: Default::default(),
                    s4_zero: Default::default(),
                    s4_exp: Default::default(),
                    s4_shift: Default::default(),
                    s4_sum: Default::default(),
                    c5_shifted: Default::default(),
                    c5_exp: Default::default(),
                    c5_nm: Default::default(),
                    s5_valid: Default::default(),
                    s5_sign: Default::default(),
                    s5_nan: Default::default(),
                    s5_inf: Default::default(),
                    s5_zero: Default::default(),
                    s5_ovf: Default::default(),
                    s5_efield: Default::default(),
                    s5_nm: Default::default(),
                    round: Default::default(),
                    s6_valid: Default::default(),
                    s6_y: Default::default(),
                }
            }
        }

        /// `FpAddFpga`'s kernel in two parts (`kernel!`): stages 1-3, then 4-6.
        struct FpAddFpgaFront;
        struct FpAddFpgaBack;
        $crate::rtl::kernel::kernel!([R: $crate::rtl::common::RoundUp] FpAddFpga<R>: FpAddFpgaFront, FpAddFpgaBack);

        impl<R: $crate::rtl::common::RoundUp> $crate::rtl::kernel::Kernel<FpAddFpgaFront> for FpAddFpga<R> {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, s1_valid, s1_nan, s1_inf, s1_inf_sign, s1_zero_sign, s1_sign, s1_eff_sub, s1_exp, s1_big, s1_small, s1_shift);
                dff_setup!(self, clock, s2_valid, s2_nan, s2_inf, s2_inf_sign, s2_zero_sign, s2_sign, s2_eff_sub, s2_exp, s2_big, s2_small);
                dff_setup!(self, clock, s3_valid, s3_nan, s3_inf, s3_inf_sign, s3_zero_sign, s3_sign, s3_exp, s3_sum, s3_marker);
                dff_setup!(self, clock, s4_valid, s4_sign, s4_nan, s4_inf, s4_zero, s4_exp, s4_shift, s4_sum);
                dff_setup!(self, clock, s5_valid, s5_sign, s5_nan, s5_inf, s5_zero, s5_ovf, s5_efield, s5_nm);
                dff_setup!(self, clock, s6_valid, s6_y);
                // ---- stage 1: unpack, compare magnitudes, exponent differences
                self.unpack_a.x.next = self.a.val();
                self.unpack_b.x.next = self.b.val();
                self.c1_b_sign.next = self.unpack_b.sign.val() ^ self.sub.val();
                self.c1_swap.next =
                    self.a.val().get_bits::<$WM1>(0) < self.b.val().get_bits::<$WM1>(0);
                self.c1_d_ab.next = self.unpack_a.exp.val() - self.unpack_b.exp.val();
                self.c1_d_ba.next = self.unpack_b.exp.val() - self.unpack_a.exp.val();
                self.c1_sh_ab.next = self.c1_d_ab.val();
                if self.c1_d_ab.val() > self.c_align_cap.val() {
                    self.c1_sh_ab.next = self.c_align_cap.val();
                }
                self.c1_sh_ba.next = self.c1_d_ba.val();
                if self.c1_d_ba.val() > self.c_align_cap.val() {
                    self.c1_sh_ba.next = self.c_align_cap.val();
                }
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
                self.s1_sign.d.next = self.unpack_a.sign.val();
                self.s1_exp.d.next = self.unpack_a.exp.val();
                self.s1_big.d.next = self.unpack_a.sig.val();
                self.s1_small.d.next = self.unpack_b.sig.val();
                self.s1_shift.d.next = self.c1_sh_ab.val();
                if self.c1_swap.val() {
                    self.s1_sign.d.next = self.c1_b_sign.val();
                    self.s1_exp.d.next = self.unpack_b.exp.val();
                    self.s1_big.d.next = self.unpack_b.sig.val();
                    self.s1_small.d.next = self.unpack_a.sig.val();
                    self.s1_shift.d.next = self.c1_sh_ba.val();
                }
                self.s1_eff_sub.d.next = self.unpack_a.sign.val() ^ self.c1_b_sign.val();
                // ---- stage 2: align (the sticky bit: a shifted-out bit is set)
                self.c2_small_ext.next = bit_cast::<$P3, $P>(self.s1_small.q.val()) << 3;
                self.c2_aligned.next = self.c2_small_ext.val() >> self.s1_shift.q.val();
                self.c2_mask.next = !(self.c_ones.val() << self.s1_shift.q.val());
                self.c2_lost.next = (self.c2_small_ext.val() & self.c2_mask.val()).any();
                self.s2_valid.d.next = self.s1_valid.q.val();
                self.s2_nan.d.next = self.s1_nan.q.val();
                self.s2_inf.d.next = self.s1_inf.q.val();
                self.s2_inf_sign.d.next = self.s1_inf_sign.q.val();
                self.s2_zero_sign.d.next = self.s1_zero_sign.q.val();
                self.s2_eff_sub.d.next = self.s1_eff_sub.q.val();
                self.s2_sign.d.next = self.s1_sign.q.val();
                self.s2_exp.d.next = self.s1_exp.q.val();
                self.s2_big.d.next = bit_cast::<$P3, $P>(self.s1_big.q.val()) << 3;
                self.s2_small.d.next = self
                    .c2_aligned
                    .val()
                    .replace_bit(0, self.c2_aligned.val().get_bit(0) | self.c2_lost.val());
                // ---- stage 3: add / subtract
                self.c3_sum.next = bit_cast::<$P4, $P3>(self.s2_big.q.val())
                    + bit_cast::<$P4, $P3>(self.s2_small.q.val());
                if self.s2_eff_sub.q.val() {
                    self.c3_sum.next = bit_cast::<$P4, $P3>(self.s2_big.q.val())
                        - bit_cast::<$P4, $P3>(self.s2_small.q.val());
                }
                self.s3_valid.d.next = self.s2_valid.q.val();
                self.s3_nan.d.next = self.s2_nan.q.val();
                self.s3_inf.d.next = self.s2_inf.q.val();
                self.s3_inf_sign.d.next = self.s2_inf_sign.q.val();
                self.s3_zero_sign.d.next = self.s2_zero_sign.q.val();
                self.s3_sign.d.next = self.s2_sign.q.val();
                self.s3_exp.d.next = self.s2_exp.q.val();
                self.s3_sum.d.next = self.c3_sum.val();
                // the limit marker: a one at leading-zero count exp - 1 (none past the sum),
                // so that stage 4's count stops there and the exponent at emin
                self.c3_limit.next = self.s2_exp.q.val() - 1;
                self.s3_marker.d.next = self.c_top.val() >> self.c3_limit.val();
            }
        }

        impl<R: $crate::rtl::common::RoundUp> $crate::rtl::kernel::Kernel<FpAddFpgaBack> for FpAddFpga<R> {
            #[hdl_gen]
            fn update(&mut self) {
                // ---- stage 4: leading zeros, capped at emin by the marker; the result's sign
                self.lzc.x.next = self.s3_sum.q.val().get_bits::<$P3>(0) | self.s3_marker.q.val();
                self.c4_zero.next = self.s3_sum.q.val() == 0;
                self.c4_sign.next = self.s3_sign.q.val();
                if self.c4_zero.val() {
                    self.c4_sign.next = self.s3_zero_sign.q.val();
                }
                if self.s3_inf.q.val() {
                    self.c4_sign.next = self.s3_inf_sign.q.val();
                }
                self.s4_valid.d.next = self.s3_valid.q.val();
                self.s4_sign.d.next = self.c4_sign.val();
                self.s4_nan.d.next = self.s3_nan.q.val();
                self.s4_inf.d.next = self.s3_inf.q.val();
                self.s4_zero.d.next = self.c4_zero.val();
                self.s4_exp.d.next = self.s3_exp.q.val();
                self.s4_shift.d.next = bit_cast::<$E, 5>(self.lzc.lz.val());
                self.s4_sum.d.next = self.s3_sum.q.val();
                // ---- stage 5: normalise
                self.c5_shifted.next =
                    self.s4_sum.q.val().get_bits::<$P3>(0) << self.s4_shift.q.val();
                self.c5_exp.next = bit_cast::<10, $E>(self.s4_exp.q.val())
                    - bit_cast::<10, $E>(self.s4_shift.q.val());
                self.c5_nm.next = bit_cast::<$P2, $P3>(self.c5_shifted.val() >> 1).replace_bit(
                    0,
                    self.c5_shifted.val().get_bit(1) | self.c5_shifted.val().get_bit(0),
                );
                if self.s4_sum.q.val().get_bit($P3) {
                    self.c5_exp.next = bit_cast::<10, $E>(self.s4_exp.q.val()) + 1;
                    self.c5_nm.next = bit_cast::<$P2, $P4>(self.s4_sum.q.val() >> 2).replace_bit(
                        0,
                        self.s4_sum.q.val().get_bit(2)
                            | self.s4_sum.q.val().get_bit(1)
                            | self.s4_sum.q.val().get_bit(0),
                    );
                }
                self.s5_valid.d.next = self.s4_valid.q.val();
                self.s5_sign.d.next = self.s4_sign.q.val();
                self.s5_nan.d.next = self.s4_nan.q.val();
                self.s5_inf.d.next = self.s4_inf.q.val();
                self.s5_zero.d.next = self.s4_zero.q.val();
                self.s5_ovf.d.next = self.c5_exp.val() >= self.c_exp_ones.val();
                self.s5_efield.d.next = 0.into();
                if self.c5_nm.val().get_bit($P + 1) {
                    self.s5_efield.d.next = bit_cast::<$E, 10>(self.c5_exp.val());
                }
                self.s5_nm.d.next = self.c5_nm.val();
                // ---- stage 6: round and pack
                self.round.round_up.next = self.round_up.val();
                self.round.sign.next = self.s5_sign.q.val();
                self.round.nan.next = self.s5_nan.q.val();
                self.round.inf.next = self.s5_inf.q.val();
                self.round.zero.next = self.s5_zero.q.val();
                self.round.ovf.next = self.s5_ovf.q.val();
                self.round.efield.next = self.s5_efield.q.val();
                self.round.nm.next = self.s5_nm.q.val();
                self.s6_valid.d.next = self.s5_valid.q.val();
                self.s6_y.d.next = self.round.y.val();
                self.y.next = self.s6_y.q.val();
                self.valid_out.next = self.s6_valid.q.val();
            }
        }
    };
}
pub(crate) use fp_add_fpga;
