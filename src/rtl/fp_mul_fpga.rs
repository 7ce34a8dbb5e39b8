//! The floating-point multiplier at FPGA depth (`FpMulFpga`), stamped out per format by
//! `fp_mul_fpga!`.

/// Stamps out `FpMulFpga` for one format in the calling module (which must also hold the
/// `fp_common!` blocks). Arguments: `W`, `E`, `F`, `P`, `P2` as for `fp_mul!`, `PP` = 2P,
/// `PM2` = P-2, and the significand's split for the partial products: `H` low bits, `HH` =
/// P-H high bits (each at most 16, rust-hdl's widest `*`), `H2` = 2H.
macro_rules! fp_mul_fpga {
    ($W:tt, $E:tt, $F:tt, $P:tt, $P2:tt, $PP:tt, $PM2:tt, $H:tt, $HH:tt, $H2:tt) => {
        /// `FpMul` cut for an FPGA: the same operation bit for bit ([`Format::mul`]; rounding
        /// `round_up`, read at the round stage, 6), the same ports, latency
        /// [`Depth::Fpga`](crate::chip::rtl::Depth::Fpga)'s, 6. The significand
        /// product is four partial products of at most 16 x 16 bits (an ECP5 MULT18X18D
        /// each) registered before their sum, and the subnormal shift of the result is set
        /// up while the product is formed, for both normalisations (`0`: product below 2,
        /// `1`: at 2 or above).
        ///
        /// | stage | logic | registers |
        /// |---|---|---|
        /// | 1 | unpack; leading zeros of both significands ([`Lzc`](crate::rtl::Lzc)), special classes | `s1_*` |
        /// | 2 | normalise subnormal significands; exponent sum (10 bits, offset 256 as in `FpMul`) | `s2_*` |
        /// | 3 | partial products `lo x lo`, `lo x hi`, `hi x lo`, `hi x hi`; for both normalisations: below `emin`?, the distance to it, overflow, exponent field | `s3_*` |
        /// | 4 | the product's top `P+2` bits and sticky, normalised by one bit, which picks the case: its shift capped at `P+2` | `s4_*` |
        /// | 5 | right shift onto the subnormal grid, sticky from a mask of the bits shifted out (a thermometer decode of the shift) | `s5_*` |
        /// | 6 | round and pack (`round`, as `FpMul`'s stage 4) | `s6_*` = outputs |
        ///
        /// [`Format::mul`]: crate::format::Format::mul
        #[derive(LogicBlock)]
        pub struct FpMulFpga<R: $crate::rtl::common::RoundUp = Constant<Bit>> {
            pub clock: Signal<In, Clock>,
            pub a: Signal<In, Bits<$W>>,
            pub b: Signal<In, Bits<$W>>,
            pub valid_in: Signal<In, Bit>,
            pub y: Signal<Out, Bits<$W>>,
            pub valid_out: Signal<Out, Bit>,
            pub round_up: R,
            c_exp_adj: Constant<Bits<10>>,
            c_exp_ofs: Constant<Bits<10>>,
            c_exp_norm_min: Constant<Bits<10>>,
            c_exp_ovf: Constant<Bits<10>>,
            c_shift_cap: Constant<Bits<10>>,
            c_ones: Constant<Bits<$P2>>,
            unpack_a: Unpack,
            unpack_b: Unpack,
            lzc_a: $crate::rtl::lzc::Lzc<$P>,
            lzc_b: $crate::rtl::lzc::Lzc<$P>,
            s1_valid: DFF<Bit>,
            s1_sign: DFF<Bit>,
            s1_nan: DFF<Bit>,
            s1_inf: DFF<Bit>,
            s1_zero: DFF<Bit>,
            s1_exp_a: DFF<Bits<$E>>,
            s1_exp_b: DFF<Bits<$E>>,
            s1_sig_a: DFF<Bits<$P>>,
            s1_sig_b: DFF<Bits<$P>>,
            s1_lz_a: DFF<Bits<5>>,
            s1_lz_b: DFF<Bits<5>>,
            s2_valid: DFF<Bit>,
            s2_sign: DFF<Bit>,
            s2_nan: DFF<Bit>,
            s2_inf: DFF<Bit>,
            s2_zero: DFF<Bit>,
            s2_exp: DFF<Bits<10>>,
            s2_sig_a: DFF<Bits<$P>>,
            s2_sig_b: DFF<Bits<$P>>,
            c3_a_lo: Signal<Local, Bits<16>>,
            c3_a_hi: Signal<Local, Bits<16>>,
            c3_b_lo: Signal<Local, Bits<16>>,
            c3_b_hi: Signal<Local, Bits<16>>,
            c3_e1: Signal<Local, Bits<10>>,
            s3_valid: DFF<Bit>,
            s3_sign: DFF<Bit>,
            s3_nan: DFF<Bit>,
            s3_inf: DFF<Bit>,
            s3_zero: DFF<Bit>,
            s3_ll: DFF<Bits<32>>,
            s3_lh: DFF<Bits<32>>,
            s3_hl: DFF<Bits<32>>,
            s3_hh: DFF<Bits<32>>,
            s3_lt0: DFF<Bit>,
            s3_lt1: DFF<Bit>,
            s3_u0: DFF<Bits<10>>,
            s3_u1: DFF<Bits<10>>,
            s3_ovf0: DFF<Bit>,
            s3_ovf1: DFF<Bit>,
            s3_efield0: DFF<Bits<$E>>,
            s3_efield1: DFF<Bits<$E>>,
            c4_prod: Signal<Local, Bits<$PP>>,
            c4_hi: Signal<Local, Bits<$P2>>,
            c4_sticky: Signal<Local, Bit>,
            c4_cap0: Signal<Local, Bits<10>>,
            c4_cap1: Signal<Local, Bits<10>>,
            s4_valid: DFF<Bit>,
            s4_sign: DFF<Bit>,
            s4_nan: DFF<Bit>,
            s4_inf: DFF<Bit>,
            s4_zero: DFF<Bit>,
            s4_nm: DFF<Bits<$P2>>,
            s4_cap: DFF<Bits<10>>,
            s4_ovf: DFF<Bit>,
            s4_efield: DFF<Bits<$E>>,
            c5_shifted: Signal<Local, Bits<$P2>>,
            c5_mask: Signal<Local, Bits<$P2>>,
            c5_lost: Signal<Local, Bit>,
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

        impl FpMulFpga {
            pub const LATENCY: usize = $crate::chip::rtl::Depth::Fpga.fp_mul_latency();

            /// A multiplier rounding with `rounding` (NearestEven or TowardPositive).
            pub fn new(rounding: Rounding) -> Self {
                Self::with(Constant::new($crate::rtl::common::round_up(
                    rounding,
                    "FpMulFpga",
                )))
            }
        }

        /// FpMulFpga whose rounding is an input, `round_up` (the DOP lanes').
        pub type FpMulFpgaModal = FpMulFpga<Signal<In, Bit>>;

        /// A multiplier rounding as its input `round_up` says.
        impl Default for FpMulFpgaModal {
            fn default() -> Self {
                Self::with(Default::default())
            }
        }

        impl<R: $crate::rtl::common::RoundUp> FpMulFpga<R> {
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
                    c_ones: Constant::new(((1u64 << $P2) - 1).into()),
                    unpack_a: Default::default(),
                    unpack_b: Default::default(),
                    lzc_a: Default::default(),
                    lzc_b: Default::default(),
                    s1_valid: Default::default(),
                    s1_sign: Default::default(),
                    s1_nan: Default::default(),
                    s1_inf: Default::default(),
                    s1_zero: Default::default(),
                    s1_exp_a: Default::default(),
                    s1_exp_b: Default::default(),
                    s1_sig_a: Default::default(),
                    s1_sig_b: Default::default(),
                    s1_lz_a: Default::default(),
                    s1_lz_b: Default::default(),
                    s2_valid: Default::default(),
                    s2_sign: Default::default(),
                    s2_nan: Default::default(),
                    s2_inf: Default::default(),
                    s2_zero: Default::default(),
                    s2_exp: Default::default(),
                    s2_sig_a: Default::default(),
                    s2_sig_b: Default::default(),
                    c3_a_lo: Default::default(),
                    c3_a_hi: Default::default(),
                    c3_b_lo: Default::default(),
                    c3_b_hi: Default::default(),
                    c3_e1: Default::default(),
                    s3_valid: Default::default(),
                    s3_sign: Default::default(),
                    s3_nan: Default::default(),
                    s3_inf: Default::default(),
                    s3_zero: Default::default(),
                    s3_ll: Default::default(),
                    s3_lh: Default::default(),
                    s3_hl: Default::default(),
                    s3_hh: Default::default(),
                    s3_lt0: Default::default(),
                    s3_lt1: Default::default(),
                    s3_u0: Default::default(),
                    s3_u1: Default::default(),
                    s3_ovf0: Default::default(),
                    s3_ovf1: Default::default(),
                    s3_efield0: Default::default(),
                    s3_efield1: Default::default(),
                    c4_prod: Default::default(),
                    c4_hi: Default::default(),
                    c4_sticky: Default::default(),
                    c4_cap0: Default::default(),
                    c4_cap1: Default::default(),
                    s4_valid: Default::default(),
                    s4_sign: Default::default(),
                    s4_nan: Default::default(),
                    s4_inf: Default::default(),
                    s4_zero: Default::default(),
                    s4_nm: Default::default(),
                    s4_cap: Default::default(),
                    s4_ovf: Default::default(),
                    s4_efield: Default::default(),
                    c5_shifted: Default::default(),
                    c5_mask: Default::default(),
                    c5_lost: Default::default(),
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

        impl<R: $crate::rtl::common::RoundUp> Logic for FpMulFpga<R> {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(
                    self, clock, s1_valid, s1_sign, s1_nan, s1_inf, s1_zero, s1_exp_a, s1_exp_b,
                    s1_sig_a, s1_sig_b, s1_lz_a, s1_lz_b
                );
                dff_setup!(
                    self, clock, s2_valid, s2_sign, s2_nan, s2_inf, s2_zero, s2_exp, s2_sig_a,
                    s2_sig_b
                );
                dff_setup!(
                    self, clock, s3_valid, s3_sign, s3_nan, s3_inf, s3_zero, s3_ll, s3_lh, s3_hl,
                    s3_hh, s3_lt0, s3_lt1, s3_u0, s3_u1, s3_ovf0, s3_ovf1, s3_efield0, s3_efield1
                );
                dff_setup!(
                    self, clock, s4_valid, s4_sign, s4_nan, s4_inf, s4_zero, s4_nm, s4_cap, s4_ovf,
                    s4_efield
                );
                dff_setup!(
                    self, clock, s5_valid, s5_sign, s5_nan, s5_inf, s5_zero, s5_ovf, s5_efield,
                    s5_nm
                );
                dff_setup!(self, clock, s6_valid, s6_y);
                // ---- stage 1: unpack, leading zeros
                self.unpack_a.x.next = self.a.val();
                self.unpack_b.x.next = self.b.val();
                self.lzc_a.x.next = self.unpack_a.sig.val();
                self.lzc_b.x.next = self.unpack_b.sig.val();
                self.s1_valid.d.next = self.valid_in.val();
                self.s1_sign.d.next = self.unpack_a.sign.val() ^ self.unpack_b.sign.val();
                self.s1_nan.d.next = self.unpack_a.is_nan.val()
                    | self.unpack_b.is_nan.val()
                    | (self.unpack_a.is_inf.val() & self.unpack_b.is_zero.val())
                    | (self.unpack_a.is_zero.val() & self.unpack_b.is_inf.val());
                self.s1_inf.d.next = self.unpack_a.is_inf.val() | self.unpack_b.is_inf.val();
                self.s1_zero.d.next = self.unpack_a.is_zero.val() | self.unpack_b.is_zero.val();
                self.s1_exp_a.d.next = self.unpack_a.exp.val();
                self.s1_exp_b.d.next = self.unpack_b.exp.val();
                self.s1_sig_a.d.next = self.unpack_a.sig.val();
                self.s1_sig_b.d.next = self.unpack_b.sig.val();
                self.s1_lz_a.d.next = self.lzc_a.lz.val();
                self.s1_lz_b.d.next = self.lzc_b.lz.val();
                // ---- stage 2: normalise subnormal significands, exponent sum
                self.s2_valid.d.next = self.s1_valid.q.val();
                self.s2_sign.d.next = self.s1_sign.q.val();
                self.s2_nan.d.next = self.s1_nan.q.val();
                self.s2_inf.d.next = self.s1_inf.q.val();
                self.s2_zero.d.next = self.s1_zero.q.val();
                self.s2_exp.d.next = bit_cast::<10, $E>(self.s1_exp_a.q.val())
                    + bit_cast::<10, $E>(self.s1_exp_b.q.val())
                    - bit_cast::<10, 5>(self.s1_lz_a.q.val())
                    - bit_cast::<10, 5>(self.s1_lz_b.q.val())
                    + self.c_exp_adj.val();
                self.s2_sig_a.d.next = self.s1_sig_a.q.val() << self.s1_lz_a.q.val();
                self.s2_sig_b.d.next = self.s1_sig_b.q.val() << self.s1_lz_b.q.val();
                // ---- stage 3: partial products; the exponent's cases for both normalisations
                self.c3_a_lo.next = bit_cast::<16, $H>(self.s2_sig_a.q.val().get_bits::<$H>(0));
                self.c3_a_hi.next = bit_cast::<16, $HH>(self.s2_sig_a.q.val().get_bits::<$HH>($H));
                self.c3_b_lo.next = bit_cast::<16, $H>(self.s2_sig_b.q.val().get_bits::<$H>(0));
                self.c3_b_hi.next = bit_cast::<16, $HH>(self.s2_sig_b.q.val().get_bits::<$HH>($H));
                self.s3_ll.d.next = self.c3_a_lo.val() * self.c3_b_lo.val();
                self.s3_lh.d.next = self.c3_a_lo.val() * self.c3_b_hi.val();
                self.s3_hl.d.next = self.c3_a_hi.val() * self.c3_b_lo.val();
                self.s3_hh.d.next = self.c3_a_hi.val() * self.c3_b_hi.val();
                self.c3_e1.next = self.s2_exp.q.val() + 1;
                self.s3_lt0.d.next = self.s2_exp.q.val() < self.c_exp_norm_min.val();
                self.s3_lt1.d.next = self.c3_e1.val() < self.c_exp_norm_min.val();
                self.s3_u0.d.next = self.c_exp_norm_min.val() - self.s2_exp.q.val();
                self.s3_u1.d.next = self.c_exp_norm_min.val() - self.c3_e1.val();
                self.s3_ovf0.d.next = self.s2_exp.q.val() >= self.c_exp_ovf.val();
                self.s3_ovf1.d.next = self.c3_e1.val() >= self.c_exp_ovf.val();
                self.s3_efield0.d.next =
                    bit_cast::<$E, 10>(self.s2_exp.q.val() - self.c_exp_ofs.val());
                self.s3_efield1.d.next =
                    bit_cast::<$E, 10>(self.c3_e1.val() - self.c_exp_ofs.val());
                self.s3_valid.d.next = self.s2_valid.q.val();
                self.s3_sign.d.next = self.s2_sign.q.val();
                self.s3_nan.d.next = self.s2_nan.q.val();
                self.s3_inf.d.next = self.s2_inf.q.val();
                self.s3_zero.d.next = self.s2_zero.q.val();
                // ---- stage 4: the product's top bits and sticky, normalised by one bit; its
                // shift onto the subnormal grid, capped
                self.c4_prod.next = bit_cast::<$PP, 32>(self.s3_ll.q.val())
                    + (bit_cast::<$PP, 32>(self.s3_lh.q.val()) << $H)
                    + (bit_cast::<$PP, 32>(self.s3_hl.q.val()) << $H)
                    + (bit_cast::<$PP, 32>(self.s3_hh.q.val()) << $H2);
                self.c4_hi.next = bit_cast::<$P2, $PP>(self.c4_prod.val() >> $PM2);
                self.c4_sticky.next = self.c4_prod.val().get_bits::<$PM2>(0).any();
                self.c4_cap0.next = 0.into();
                if self.s3_lt0.q.val() {
                    self.c4_cap0.next = self.s3_u0.q.val();
                    if self.s3_u0.q.val() > self.c_shift_cap.val() {
                        self.c4_cap0.next = self.c_shift_cap.val();
                    }
                }
                self.c4_cap1.next = 0.into();
                if self.s3_lt1.q.val() {
                    self.c4_cap1.next = self.s3_u1.q.val();
                    if self.s3_u1.q.val() > self.c_shift_cap.val() {
                        self.c4_cap1.next = self.c_shift_cap.val();
                    }
                }
                self.s4_nm.d.next = (self.c4_hi.val() << 1).replace_bit(0, self.c4_sticky.val());
                self.s4_cap.d.next = self.c4_cap0.val();
                self.s4_ovf.d.next = self.s3_ovf0.q.val();
                self.s4_efield.d.next = 0.into();
                if !self.s3_lt0.q.val() {
                    self.s4_efield.d.next = self.s3_efield0.q.val();
                }
                if self.c4_hi.val().get_bit($P + 1) {
                    self.s4_nm.d.next = self
                        .c4_hi
                        .val()
                        .replace_bit(0, self.c4_hi.val().get_bit(0) | self.c4_sticky.val());
                    self.s4_cap.d.next = self.c4_cap1.val();
                    self.s4_ovf.d.next = self.s3_ovf1.q.val();
                    self.s4_efield.d.next = 0.into();
                    if !self.s3_lt1.q.val() {
                        self.s4_efield.d.next = self.s3_efield1.q.val();
                    }
                }
                self.s4_valid.d.next = self.s3_valid.q.val();
                self.s4_sign.d.next = self.s3_sign.q.val();
                self.s4_nan.d.next = self.s3_nan.q.val();
                self.s4_inf.d.next = self.s3_inf.q.val();
                self.s4_zero.d.next = self.s3_zero.q.val();
                // ---- stage 5: shift onto the subnormal grid
                self.s5_ovf.d.next = self.s4_ovf.q.val();
                self.s5_efield.d.next = self.s4_efield.q.val();
                self.c5_shifted.next = self.s4_nm.q.val() >> self.s4_cap.q.val();
                self.c5_mask.next = !(self.c_ones.val() << self.s4_cap.q.val());
                self.c5_lost.next = (self.s4_nm.q.val() & self.c5_mask.val()).any();
                self.s5_valid.d.next = self.s4_valid.q.val();
                self.s5_sign.d.next = self.s4_sign.q.val();
                self.s5_nan.d.next = self.s4_nan.q.val();
                self.s5_inf.d.next = self.s4_inf.q.val();
                self.s5_zero.d.next = self.s4_zero.q.val();
                self.s5_nm.d.next = self
                    .c5_shifted
                    .val()
                    .replace_bit(0, self.c5_shifted.val().get_bit(0) | self.c5_lost.val());
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
pub(crate) use fp_mul_fpga;
