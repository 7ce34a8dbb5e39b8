//! The DOPTRF lane (DATE'05 Eq. 10), stamped out per format by `doptrf!`.

/// Stamps out `Doptrf` (one lane) in the calling module, which must also hold that
/// format's `FpMul` and `FpAdd`. Arguments: `W` word width, `WM1` = W-1, `E` exponent
/// bits, `F` fraction bits.
macro_rules! doptrf {
    ($W:tt, $WM1:tt, $E:tt, $F:tt) => {
        /// One DOPTRF lane: `s = ((d0 C0 + d1 C1) + (d2 C2 + c)) + e` and `flag = s < 0`,
        /// every operation rounded as `round_up` says (1: TowardPositive, 0: NearestEven),
        /// bit for bit the golden [`lane`](crate::golden::doptrf::lane) (same order of
        /// operations). `round_up` is taken with the operands and travels beside them
        /// (`s1_round`, then `r_mul`, `r_sum`, `r_u`, `r_s`: three clocks each) to each
        /// unit's round stage, which reads it there (`FpMulModal`, `FpAddModal`).
        ///
        /// Ports: in `clock`, `d0 d1 d2` (the routed distances of B's DOP, from D.KLMSEL),
        /// `c0 c1 c2` (row i of C), `c` (c_i), `e` (e_opp(i), A's DOP), `valid_in`, `round_up`;
        /// out `s`, `flag` (sign set, not zero, not NaN; so -inf is < 0), `valid_out`.
        ///
        /// One lane evaluation per clock; latency 15 (inputs presented before rising
        /// edge 1 give `s`, `flag`, `valid_out` right after edge 15). Stage budget:
        ///
        /// | stage(s) | logic | registers |
        /// |---|---|---|
        /// | 1 | input register | `s1_*` |
        /// | 2-5 | `p_l = d_l C_l`, three multipliers (`mul_0..2`, latency 4); `c` delayed | `c_2..c_5` |
        /// | 6-8 | `u0 = p0 + p1` (`add_0`), `u1 = p2 + c` (`add_1`), latency 3 | |
        /// | 9-11 | `u = u0 + u1` (`add_2`) | |
        /// | 12-14 | `s = u + e` (`add_3`); `e` delayed through stages 2-11 to meet it | `e_2..e_11` |
        /// | 15 | sign test, output register | `s15_*` = outputs |
        ///
        /// The valid bit travels with `mul_0` and the adders of the `u0` path.
        #[derive(LogicBlock, Default)]
        pub struct Doptrf {
            pub clock: Signal<In, Clock>,
            pub d0: Signal<In, Bits<$W>>,
            pub d1: Signal<In, Bits<$W>>,
            pub d2: Signal<In, Bits<$W>>,
            pub c0: Signal<In, Bits<$W>>,
            pub c1: Signal<In, Bits<$W>>,
            pub c2: Signal<In, Bits<$W>>,
            pub c: Signal<In, Bits<$W>>,
            pub e: Signal<In, Bits<$W>>,
            pub valid_in: Signal<In, Bit>,
            pub round_up: Signal<In, Bit>,
            pub s: Signal<Out, Bits<$W>>,
            pub flag: Signal<Out, Bit>,
            pub valid_out: Signal<Out, Bit>,
            // stage 1: input register
            s1_valid: DFF<Bit>,
            s1_d0: DFF<Bits<$W>>,
            s1_d1: DFF<Bits<$W>>,
            s1_d2: DFF<Bits<$W>>,
            s1_c0: DFF<Bits<$W>>,
            s1_c1: DFF<Bits<$W>>,
            s1_c2: DFF<Bits<$W>>,
            s1_c: DFF<Bits<$W>>,
            s1_e: DFF<Bits<$W>>,
            s1_round: DFF<Bit>,
            // the rounding at the multipliers' round stage (stage 5) and the adders' (8, 11, 14)
            r_mul: $crate::rtl::delay::Delay<Bit, 3>,
            r_sum: $crate::rtl::delay::Delay<Bit, 3>,
            r_u: $crate::rtl::delay::Delay<Bit, 3>,
            r_s: $crate::rtl::delay::Delay<Bit, 3>,
            // stages 2-5: products; c waits for p2
            mul_0: FpMulModal,
            mul_1: FpMulModal,
            mul_2: FpMulModal,
            c_2: DFF<Bits<$W>>,
            c_3: DFF<Bits<$W>>,
            c_4: DFF<Bits<$W>>,
            c_5: DFF<Bits<$W>>,
            // stages 6-14: sums; e waits for u
            add_0: FpAddModal,
            add_1: FpAddModal,
            add_2: FpAddModal,
            add_3: FpAddModal,
            e_2: DFF<Bits<$W>>,
            e_3: DFF<Bits<$W>>,
            e_4: DFF<Bits<$W>>,
            e_5: DFF<Bits<$W>>,
            e_6: DFF<Bits<$W>>,
            e_7: DFF<Bits<$W>>,
            e_8: DFF<Bits<$W>>,
            e_9: DFF<Bits<$W>>,
            e_10: DFF<Bits<$W>>,
            e_11: DFF<Bits<$W>>,
            // stage 15: sign test
            c15_exp: Signal<Local, Bits<$E>>,
            c15_frac: Signal<Local, Bits<$F>>,
            c15_mag: Signal<Local, Bits<$WM1>>,
            c15_nan: Signal<Local, Bit>,
            s15_valid: DFF<Bit>,
            s15_s: DFF<Bits<$W>>,
            s15_flag: DFF<Bit>,
        }

        impl Logic for Doptrf {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, s1_valid, s1_d0, s1_d1, s1_d2, s1_c0, s1_c1, s1_c2, s1_c, s1_e, s1_round);
                clock!(self, clock, r_mul, r_sum, r_u, r_s);
                dff_setup!(self, clock, c_2, c_3, c_4, c_5);
                dff_setup!(self, clock, e_2, e_3, e_4, e_5, e_6, e_7, e_8, e_9, e_10, e_11);
                dff_setup!(self, clock, s15_valid, s15_s, s15_flag);
                self.mul_0.clock.next = self.clock.val();
                self.mul_1.clock.next = self.clock.val();
                self.mul_2.clock.next = self.clock.val();
                self.add_0.clock.next = self.clock.val();
                self.add_1.clock.next = self.clock.val();
                self.add_2.clock.next = self.clock.val();
                self.add_3.clock.next = self.clock.val();
                self.mul_0.round_up.next = self.r_mul.q.val();
                self.mul_1.round_up.next = self.r_mul.q.val();
                self.mul_2.round_up.next = self.r_mul.q.val();
                self.add_0.round_up.next = self.r_sum.q.val();
                self.add_1.round_up.next = self.r_sum.q.val();
                self.add_2.round_up.next = self.r_u.q.val();
                self.add_3.round_up.next = self.r_s.q.val();
                // ---- stage 1: input register
                self.s1_valid.d.next = self.valid_in.val();
                self.s1_d0.d.next = self.d0.val();
                self.s1_d1.d.next = self.d1.val();
                self.s1_d2.d.next = self.d2.val();
                self.s1_c0.d.next = self.c0.val();
                self.s1_c1.d.next = self.c1.val();
                self.s1_c2.d.next = self.c2.val();
                self.s1_c.d.next = self.c.val();
                self.s1_e.d.next = self.e.val();
                self.s1_round.d.next = self.round_up.val();
                self.r_mul.d.next = self.s1_round.q.val();
                self.r_sum.d.next = self.r_mul.q.val();
                self.r_u.d.next = self.r_sum.q.val();
                self.r_s.d.next = self.r_u.q.val();
                // ---- stages 2-5: p_l = d_l * C_l
                self.mul_0.a.next = self.s1_d0.q.val();
                self.mul_0.b.next = self.s1_c0.q.val();
                self.mul_0.valid_in.next = self.s1_valid.q.val();
                self.mul_1.a.next = self.s1_d1.q.val();
                self.mul_1.b.next = self.s1_c1.q.val();
                self.mul_1.valid_in.next = self.s1_valid.q.val();
                self.mul_2.a.next = self.s1_d2.q.val();
                self.mul_2.b.next = self.s1_c2.q.val();
                self.mul_2.valid_in.next = self.s1_valid.q.val();
                self.c_2.d.next = self.s1_c.q.val();
                self.c_3.d.next = self.c_2.q.val();
                self.c_4.d.next = self.c_3.q.val();
                self.c_5.d.next = self.c_4.q.val();
                // ---- stages 6-8: u0 = p0 + p1, u1 = p2 + c
                self.add_0.a.next = self.mul_0.y.val();
                self.add_0.b.next = self.mul_1.y.val();
                self.add_0.sub.next = false;
                self.add_0.valid_in.next = self.mul_0.valid_out.val();
                self.add_1.a.next = self.mul_2.y.val();
                self.add_1.b.next = self.c_5.q.val();
                self.add_1.sub.next = false;
                self.add_1.valid_in.next = self.mul_0.valid_out.val();
                // ---- stages 9-11: u = u0 + u1
                self.add_2.a.next = self.add_0.y.val();
                self.add_2.b.next = self.add_1.y.val();
                self.add_2.sub.next = false;
                self.add_2.valid_in.next = self.add_0.valid_out.val();
                // ---- stages 12-14: s = u + e
                self.e_2.d.next = self.s1_e.q.val();
                self.e_3.d.next = self.e_2.q.val();
                self.e_4.d.next = self.e_3.q.val();
                self.e_5.d.next = self.e_4.q.val();
                self.e_6.d.next = self.e_5.q.val();
                self.e_7.d.next = self.e_6.q.val();
                self.e_8.d.next = self.e_7.q.val();
                self.e_9.d.next = self.e_8.q.val();
                self.e_10.d.next = self.e_9.q.val();
                self.e_11.d.next = self.e_10.q.val();
                self.add_3.a.next = self.add_2.y.val();
                self.add_3.b.next = self.e_11.q.val();
                self.add_3.sub.next = false;
                self.add_3.valid_in.next = self.add_2.valid_out.val();
                // ---- stage 15: flag = s < 0 (sign set, not zero, not NaN)
                self.c15_exp.next = self.add_3.y.val().get_bits::<$E>($F);
                self.c15_frac.next = self.add_3.y.val().get_bits::<$F>(0);
                self.c15_mag.next = self.add_3.y.val().get_bits::<$WM1>(0);
                self.c15_nan.next = self.c15_exp.val().all() & (self.c15_frac.val() != 0);
                self.s15_valid.d.next = self.add_3.valid_out.val();
                self.s15_s.d.next = self.add_3.y.val();
                self.s15_flag.d.next = self.add_3.y.val().get_bit($WM1)
                    & (self.c15_mag.val() != 0)
                    & !self.c15_nan.val();
                self.s.next = self.s15_s.q.val();
                self.flag.next = self.s15_flag.q.val();
                self.valid_out.next = self.s15_valid.q.val();
            }
        }

        /// A lane ready to simulate as a top-level block (inputs claimed, connected).
        pub fn doptrf_top() -> Doptrf {
            top_level!(Doptrf::default(); clock, d0, d1, d2, c0, c1, c2, c, e, valid_in, round_up)
        }

        /// Verilog of one DOPTRF lane (top module `top`).
        pub fn verilog_doptrf() -> String {
            generate_verilog(&doptrf_top())
        }
    };
}
pub(crate) use doptrf;
