//! The DOPTRF lane (DATE'05 Eq. 10) and WSCG'03's DOTADD unit (the lane's transform without
//! A's distance), stamped out per format by `doptrf!`.

/// Stamps out in the calling module the DOPTRF lane at both depths, `Doptrf` on `FpMulModal`
/// and `FpAddModal` (latency 15) and `DoptrfFpga` on `FpMulFpgaModal` and `FpAddFpgaModal`
/// (latency 26), and WSCG'03's DOTADD unit `Dotadd` (latency 12), its first stages; the
/// module must also hold those units. Arguments: `W` word width, `WM1` = W-1, `E` exponent
/// bits, `F` fraction bits.
macro_rules! doptrf {
    ($W:tt, $WM1:tt, $E:tt, $F:tt) => {
        $crate::rtl::doptrf::doptrf!(@lane
            /// One DOPTRF lane: `s = ((d0 C0 + d1 C1) + (d2 C2 + c)) + e` and `flag = s < 0`,
            /// every operation rounded as `round_up` says (1: TowardPositive, 0: NearestEven),
            /// bit for bit the golden [`lane`](crate::golden::doptrf::lane) (same order of
            /// operations). `round_up` is taken with the operands and travels beside them
            /// (`s1_round`, then `r_mul`, `r_sum`, `r_u`, `r_s`) to each unit's round stage, which
            /// reads it there (the units' `Modal` types).
            ///
            /// Ports: in `clock`, `d0 d1 d2` (the routed distances of B's DOP, from D.KLMSEL),
            /// `c0 c1 c2` (row i of C), `c` (c_i), `e` (e_opp(i), A's DOP), `valid_in`, `round_up`;
            /// out `s`, `flag` (sign set, not zero, not NaN; so -inf is < 0), `valid_out`.
            ///
            /// One lane evaluation per clock; latency `LATENCY` (15 for `Doptrf`, 26 for
            /// `DoptrfFpga`: inputs presented before rising edge 1 give `s`, `flag`, `valid_out`
            /// right after edge `LATENCY`). Stage budget, with M and A the multiplier's and the
            /// adder's latencies (4 and 3, at FPGA depth 6 and 6):
            ///
            /// | stage(s) | logic | registers |
            /// |---|---|---|
            /// | 1 | input register | `s1_*` |
            /// | 2 .. M+1 | `p_l = d_l C_l`, three multipliers (`mul_0..2`); `c` delayed | `c_2..` |
            /// | next A | `u0 = p0 + p1` (`add_0`), `u1 = p2 + c` (`add_1`) | |
            /// | next A | `u = u0 + u1` (`add_2`) | |
            /// | next A | `s = u + e` (`add_3`); `e` delayed through stages 2 .. M+2A+1 to meet it | `e_2..` |
            /// | last | sign test, output register | `s15_*` (`s26_*`) = outputs |
            ///
            /// The valid bit travels with `mul_0` and the adders of the `u0` path.
            Doptrf, doptrf_top, verilog_doptrf; $W, $WM1, $E, $F;
            FpMulModal, FpAddModal, 15, 3, 3;
            c(c_2; (c_3 c_2) (c_4 c_3) (c_5 c_4); c_5);
            e(e, s1_e, r_s, add_3; e_2; (e_3 e_2) (e_4 e_3) (e_5 e_4) (e_6 e_5) (e_7 e_6)
                (e_8 e_7) (e_9 e_8) (e_10 e_9) (e_11 e_10); e_11;
                s15_valid, s15_s, s15_flag; s, flag; c15_exp, c15_frac, c15_mag, c15_nan););
        $crate::rtl::doptrf::doptrf!(@lane
            /// The DOPTRF lane at FPGA depth: see [`Doptrf`].
            DoptrfFpga, doptrf_fpga_top, verilog_doptrf_fpga; $W, $WM1, $E, $F;
            FpMulFpgaModal, FpAddFpgaModal, 26, 5, 6;
            c(c_2; (c_3 c_2) (c_4 c_3) (c_5 c_4) (c_6 c_5) (c_7 c_6); c_7);
            e(e, s1_e, r_s, add_3; e_2; (e_3 e_2) (e_4 e_3) (e_5 e_4) (e_6 e_5) (e_7 e_6)
                (e_8 e_7) (e_9 e_8) (e_10 e_9) (e_11 e_10) (e_12 e_11) (e_13 e_12) (e_14 e_13)
                (e_15 e_14) (e_16 e_15) (e_17 e_16) (e_18 e_17) (e_19 e_18); e_19;
                s26_valid, s26_s, s26_flag; s, flag; c15_exp, c15_frac, c15_mag, c15_nan););
        $crate::rtl::doptrf::doptrf!(@lane
            /// WSCG'03's DOTADD unit (§4.1, Fig. 5): one transformed distance per clock,
            /// `u = (d0 C0 + d1 C1) + (d2 C2 + c)`, every operation rounded as `round_up`
            /// says, bit for bit the golden
            /// [`transformed`](crate::golden::doptrf::transformed) (d'_i, WSCG'03 Eq. 1):
            /// [`Doptrf`]'s stages up to `u`, then the output register (`s12_*`); latency
            /// 12 = 1 + M + 2A + 1 ([`DOTADD_LATENCY`](crate::chip::rtl::DOTADD_LATENCY)).
            /// Ports: in `clock`, `d0 d1 d2`, `c0 c1 c2`, `c`, `valid_in`, `round_up`; out
            /// `u`, `valid_out`.
            Dotadd, dotadd_top, verilog_dotadd; $W, $WM1, $E, $F;
            FpMulModal, FpAddModal, 12, 3, 3;
            c(c_2; (c_3 c_2) (c_4 c_3) (c_5 c_4); c_5);
            dot(s12_valid, s12_u; u););
    };
    // One lane: its doc, name, top-level builder and Verilog export; its multiplier and adder
    // types; its latency `LAT`; the rounding's delay to the multipliers' round stage (M - 1)
    // and from one round stage to the next (A); the chain that holds `c` (M registers) for
    // the sums, as its first register, the (register, the one before it) links and its last
    // register. Then either the DOPTRF lane's tail, `e(...)`: A's distance's port, input
    // register, rounding delay and adder; its chain (M + 2A registers); the output registers,
    // ports and the sign test's signals (LAT = 1 + M + 3A + 1); or the DOTADD unit's, `dot(...)`:
    // the output registers and port (LAT = 1 + M + 2A + 1). The tail's names are arguments
    // so that each optional field and statement holds a metavariable of its group (what
    // `$(...)?` repeats on); they are the same names for every lane.
    (@lane $(#[$doc:meta])* $name:ident, $top:ident, $verilog:ident; $W:tt, $WM1:tt, $E:tt, $F:tt;
     $Mul:ident, $Add:ident, $LAT:tt, $RM:tt, $RA:tt;
     c($c0:ident; $(($cn:ident $cp:ident))+; $cl:ident);
     $(e($ein:ident, $s1e:ident, $rs:ident, $add3:ident; $e0:ident; $(($en:ident $ep:ident))+;
         $el:ident; $ov:ident, $os:ident, $of:ident; $sport:ident, $fport:ident;
         $c15e:ident, $c15f:ident, $c15m:ident, $c15n:ident);)?
     $(dot($dv:ident, $du:ident; $uport:ident);)?) => {
        $(#[$doc])*
        #[derive(LogicBlock, Default)]
        pub struct $name {
            pub clock: Signal<In, Clock>,
            pub d0: Signal<In, Bits<$W>>,
            pub d1: Signal<In, Bits<$W>>,
            pub d2: Signal<In, Bits<$W>>,
            pub c0: Signal<In, Bits<$W>>,
            pub c1: Signal<In, Bits<$W>>,
            pub c2: Signal<In, Bits<$W>>,
            pub c: Signal<In, Bits<$W>>,
            $(pub $ein: Signal<In, Bits<$W>>,)?
            pub valid_in: Signal<In, Bit>,
            pub round_up: Signal<In, Bit>,
            $(pub $sport: Signal<Out, Bits<$W>>,
            pub $fport: Signal<Out, Bit>,)?
            $(pub $uport: Signal<Out, Bits<$W>>,)?
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
            $($s1e: DFF<Bits<$W>>,)?
            s1_round: DFF<Bit>,
            // the rounding at the multipliers' round stage and the adders'
            r_mul: $crate::rtl::delay::Delay<Bit, $RM>,
            r_sum: $crate::rtl::delay::Delay<Bit, $RA>,
            r_u: $crate::rtl::delay::Delay<Bit, $RA>,
            $($rs: $crate::rtl::delay::Delay<Bit, $RA>,)?
            // the products; c waits for p2
            mul_0: $Mul,
            mul_1: $Mul,
            mul_2: $Mul,
            $c0: DFF<Bits<$W>>,
            $($cn: DFF<Bits<$W>>,)+
            // the sums; e waits for u
            add_0: $Add,
            add_1: $Add,
            add_2: $Add,
            $($add3: $Add,
            $e0: DFF<Bits<$W>>,
            $($en: DFF<Bits<$W>>,)+
            // the last stage: sign test
            $c15e: Signal<Local, Bits<$E>>,
            $c15f: Signal<Local, Bits<$F>>,
            $c15m: Signal<Local, Bits<$WM1>>,
            $c15n: Signal<Local, Bit>,
            $ov: DFF<Bit>,
            $os: DFF<Bits<$W>>,
            $of: DFF<Bit>,)?
            // the DOTADD unit's output register
            $($dv: DFF<Bit>,
            $du: DFF<Bits<$W>>,)?
        }

        impl $name {
            pub const LATENCY: usize = $LAT;
        }

        impl Logic for $name {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, s1_valid, s1_d0, s1_d1, s1_d2, s1_c0, s1_c1, s1_c2, s1_c, $($s1e,)? s1_round);
                clock!(self, clock, r_mul, r_sum, r_u $(, $rs)?);
                dff_setup!(self, clock, $c0, $($cn),+);
                $(dff_setup!(self, clock, $e0, $($en),+);
                dff_setup!(self, clock, $ov, $os, $of);)?
                $(dff_setup!(self, clock, $dv, $du);)?
                self.mul_0.clock.next = self.clock.val();
                self.mul_1.clock.next = self.clock.val();
                self.mul_2.clock.next = self.clock.val();
                self.add_0.clock.next = self.clock.val();
                self.add_1.clock.next = self.clock.val();
                self.add_2.clock.next = self.clock.val();
                $(self.$add3.clock.next = self.clock.val();)?
                self.mul_0.round_up.next = self.r_mul.q.val();
                self.mul_1.round_up.next = self.r_mul.q.val();
                self.mul_2.round_up.next = self.r_mul.q.val();
                self.add_0.round_up.next = self.r_sum.q.val();
                self.add_1.round_up.next = self.r_sum.q.val();
                self.add_2.round_up.next = self.r_u.q.val();
                $(self.$add3.round_up.next = self.$rs.q.val();)?
                // ---- stage 1: input register
                self.s1_valid.d.next = self.valid_in.val();
                self.s1_d0.d.next = self.d0.val();
                self.s1_d1.d.next = self.d1.val();
                self.s1_d2.d.next = self.d2.val();
                self.s1_c0.d.next = self.c0.val();
                self.s1_c1.d.next = self.c1.val();
                self.s1_c2.d.next = self.c2.val();
                self.s1_c.d.next = self.c.val();
                $(self.$s1e.d.next = self.$ein.val();)?
                self.s1_round.d.next = self.round_up.val();
                self.r_mul.d.next = self.s1_round.q.val();
                self.r_sum.d.next = self.r_mul.q.val();
                self.r_u.d.next = self.r_sum.q.val();
                $(self.$rs.d.next = self.r_u.q.val();)?
                // ---- p_l = d_l * C_l
                self.mul_0.a.next = self.s1_d0.q.val();
                self.mul_0.b.next = self.s1_c0.q.val();
                self.mul_0.valid_in.next = self.s1_valid.q.val();
                self.mul_1.a.next = self.s1_d1.q.val();
                self.mul_1.b.next = self.s1_c1.q.val();
                self.mul_1.valid_in.next = self.s1_valid.q.val();
                self.mul_2.a.next = self.s1_d2.q.val();
                self.mul_2.b.next = self.s1_c2.q.val();
                self.mul_2.valid_in.next = self.s1_valid.q.val();
                self.$c0.d.next = self.s1_c.q.val();
                $(self.$cn.d.next = self.$cp.q.val();)+
                // ---- u0 = p0 + p1, u1 = p2 + c
                self.add_0.a.next = self.mul_0.y.val();
                self.add_0.b.next = self.mul_1.y.val();
                self.add_0.sub.next = false;
                self.add_0.valid_in.next = self.mul_0.valid_out.val();
                self.add_1.a.next = self.mul_2.y.val();
                self.add_1.b.next = self.$cl.q.val();
                self.add_1.sub.next = false;
                self.add_1.valid_in.next = self.mul_0.valid_out.val();
                // ---- u = u0 + u1
                self.add_2.a.next = self.add_0.y.val();
                self.add_2.b.next = self.add_1.y.val();
                self.add_2.sub.next = false;
                self.add_2.valid_in.next = self.add_0.valid_out.val();
                $(
                // ---- s = u + e
                self.$e0.d.next = self.$s1e.q.val();
                $(self.$en.d.next = self.$ep.q.val();)+
                self.$add3.a.next = self.add_2.y.val();
                self.$add3.b.next = self.$el.q.val();
                self.$add3.sub.next = false;
                self.$add3.valid_in.next = self.add_2.valid_out.val();
                // ---- the last stage: flag = s < 0 (sign set, not zero, not NaN)
                self.$c15e.next = self.$add3.y.val().get_bits::<$E>($F);
                self.$c15f.next = self.$add3.y.val().get_bits::<$F>(0);
                self.$c15m.next = self.$add3.y.val().get_bits::<$WM1>(0);
                self.$c15n.next = self.$c15e.val().all() & (self.$c15f.val() != 0);
                self.$ov.d.next = self.$add3.valid_out.val();
                self.$os.d.next = self.$add3.y.val();
                self.$of.d.next = self.$add3.y.val().get_bit($WM1)
                    & (self.$c15m.val() != 0)
                    & !self.$c15n.val();
                self.$sport.next = self.$os.q.val();
                self.$fport.next = self.$of.q.val();
                self.valid_out.next = self.$ov.q.val();
                )?
                // ---- the DOTADD unit: u to the output register
                $(self.$dv.d.next = self.add_2.valid_out.val();
                self.$du.d.next = self.add_2.y.val();
                self.$uport.next = self.$du.q.val();
                self.valid_out.next = self.$dv.q.val();)?
            }
        }

        /// A lane ready to simulate as a top-level block (inputs claimed, connected).
        pub fn $top() -> $name {
            top_level!($name::default(); clock, d0, d1, d2, c0, c1, c2, c, $($ein,)? valid_in, round_up)
        }

        /// Verilog of the block (top module `top`).
        pub fn $verilog() -> String {
            generate_verilog(&$top())
        }
    };
}
pub(crate) use doptrf;
