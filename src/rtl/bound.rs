//! The bound arithmetic of T.CHECK's uncertainty flag (docs/ACCURACY.md, "The chip's bound
//! arithmetic"): `BoundAdd`, `BoundMul` and `RoundErr`, stamped out per format by `bound!`.

/// Stamps out `StepUp`, `BoundAdd`, `BoundMul` and `RoundErr` for one format in the calling
/// module (which must also hold `FpAdd` and `FpMul`). Arguments: `W`, `WM1`, `E`, `F`.
macro_rules! bound {
    ($W:tt, $WM1:tt, $E:tt, $F:tt) => {
        /// Step up and floor (combinational): `y = max(next_up(x), m)`, m the smallest normal
        /// value, with `max` as `f64::max` (IEEE maxNum, a NaN gives the other operand), i.e.
        /// bit for bit what the golden `next_up(..).max(m)` gives for every word x:
        ///
        /// * `+0`, positive subnormal or normal x below `+max_finite`: the bit pattern
        ///   plus one (the carry moves into the exponent by itself; `+max_finite` gives the
        ///   `+inf` pattern), then m if the result's exponent field is still 0;
        /// * `+inf`: `+inf`;
        /// * NaN, or any negative word (next_up of which is `<= 0`): m.
        #[derive(LogicBlock)]
        pub struct StepUp {
            pub x: Signal<In, Bits<$W>>,
            pub y: Signal<Out, Bits<$W>>,
            c_min_normal: Constant<Bits<$W>>,
            c_inf: Constant<Bits<$W>>,
            inc: Signal<Local, Bits<$W>>,
            nan: Signal<Local, Bit>,
        }

        impl Default for StepUp {
            fn default() -> Self {
                let ones: u64 = (1u64 << $E) - 1;
                Self {
                    x: Default::default(),
                    y: Default::default(),
                    c_min_normal: Constant::new((1u64 << $F).into()),
                    c_inf: Constant::new((ones << $F).into()),
                    inc: Default::default(),
                    nan: Default::default(),
                }
            }
        }

        impl Logic for StepUp {
            #[hdl_gen]
            fn update(&mut self) {
                self.inc.next = self.x.val() + 1;
                self.nan.next = self.x.val().get_bits::<$E>($F).all() & (self.x.val().get_bits::<$F>(0) != 0);
                self.y.next = self.inc.val();
                if self.inc.val().get_bits::<$E>($F) == 0 {
                    self.y.next = self.c_min_normal.val();
                }
                if self.x.val() == self.c_inf.val() {
                    self.y.next = self.c_inf.val();
                }
                if self.x.val().get_bit($WM1) | self.nan.val() {
                    self.y.next = self.c_min_normal.val();
                }
            }
        }

        $crate::rtl::bound::bound!(@unit $W, BoundAdd, FpAdd, 4, "FpAdd", "3", "bound_add", "+", tie(sub));
        $crate::rtl::bound::bound!(@unit $W, BoundMul, FpMul, 5, "FpMul", "4", "bound_mul", "*", tie());

        /// The rounding-error bound of a result (golden
        /// [`tcheck::rounding_error`](crate::golden::tcheck::rounding_error)):
        /// `err(x) = max(ulp(x)/2, m)` to nearest (`max(ulp(x), m)` for a directed rounding),
        /// m the smallest normal value, from x's exponent field alone: a positive power of
        /// two, `2^(ef - bias - F - 1)` for a biased exponent field `ef >= F + 2` (to
        /// nearest; `ef >= F + 1` and `2^(ef - bias - F)` directed), else m; `±inf` gives
        /// `+inf`, NaN gives m (as the golden `f64::max`). The sign of x is ignored.
        ///
        /// Ports: in `clock`, `x[W]`, `valid_in`; out `y[W]`, `valid_out`. One result per
        /// clock; latency 1 (the register `s1_*` = outputs), so that err(x) of a value from
        /// `FpAdd` (latency 3) / `FpMul` (4) arrives with the `BoundAdd` (4) / `BoundMul`
        /// (5) of the operands' bounds started together with the value.
        #[derive(LogicBlock)]
        pub struct RoundErr {
            pub clock: Signal<In, Clock>,
            pub x: Signal<In, Bits<$W>>,
            pub valid_in: Signal<In, Bit>,
            pub y: Signal<Out, Bits<$W>>,
            pub valid_out: Signal<Out, Bit>,
            /// `F + 1` to nearest, `F` directed: the exponent distance from x to err(x).
            c_shift: Constant<Bits<$E>>,
            c_min_normal: Constant<Bits<$W>>,
            c_inf: Constant<Bits<$W>>,
            c1_ef: Signal<Local, Bits<$E>>,
            c1_frac_zero: Signal<Local, Bit>,
            c1_y: Signal<Local, Bits<$W>>,
            s1_valid: DFF<Bit>,
            s1_y: DFF<Bits<$W>>,
        }

        impl RoundErr {
            /// The bound for results rounded with `rounding`.
            pub fn new(rounding: Rounding) -> Self {
                let ones: u64 = (1u64 << $E) - 1;
                let shift: u64 = if rounding == Rounding::NearestEven { $F + 1 } else { $F };
                Self {
                    clock: Default::default(),
                    x: Default::default(),
                    valid_in: Default::default(),
                    y: Default::default(),
                    valid_out: Default::default(),
                    c_shift: Constant::new(shift.into()),
                    c_min_normal: Constant::new((1u64 << $F).into()),
                    c_inf: Constant::new((ones << $F).into()),
                    c1_ef: Default::default(),
                    c1_frac_zero: Default::default(),
                    c1_y: Default::default(),
                    s1_valid: Default::default(),
                    s1_y: Default::default(),
                }
            }
        }

        impl Logic for RoundErr {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, s1_valid, s1_y);
                self.c1_ef.next = self.x.val().get_bits::<$E>($F);
                self.c1_frac_zero.next = self.x.val().get_bits::<$F>(0) == 0;
                self.c1_y.next = self.c_min_normal.val();
                if self.c1_ef.val() > self.c_shift.val() {
                    self.c1_y.next = bit_cast::<$W, $E>(self.c1_ef.val() - self.c_shift.val()) << $F;
                }
                if self.c1_ef.val().all() {
                    self.c1_y.next = self.c_min_normal.val();
                    if self.c1_frac_zero.val() {
                        self.c1_y.next = self.c_inf.val();
                    }
                }
                self.s1_valid.d.next = self.valid_in.val();
                self.s1_y.d.next = self.c1_y.val();
                self.y.next = self.s1_y.q.val();
                self.valid_out.next = self.s1_valid.q.val();
            }
        }

        /// A bound adder ready to simulate as a top-level block (inputs claimed, connected).
        pub fn bound_add_top() -> BoundAdd {
            top_level!(BoundAdd::new(); clock, a, b, valid_in)
        }

        /// A bound multiplier ready to simulate as a top-level block.
        pub fn bound_mul_top() -> BoundMul {
            top_level!(BoundMul::new(); clock, a, b, valid_in)
        }

        /// A rounding-error bound ready to simulate as a top-level block.
        pub fn round_err_top(rounding: Rounding) -> RoundErr {
            top_level!(RoundErr::new(rounding); clock, x, valid_in)
        }

        /// Verilog of the bound adder (top module `top`).
        pub fn verilog_bound_add() -> String {
            generate_verilog(&bound_add_top())
        }

        /// Verilog of the bound multiplier (top module `top`).
        pub fn verilog_bound_mul() -> String {
            generate_verilog(&bound_mul_top())
        }

        /// Verilog of the rounding-error bound (top module `top`).
        pub fn verilog_round_err(rounding: Rounding) -> String {
            generate_verilog(&round_err_top(rounding))
        }
    };

    (@unit $W:tt, $name:ident, $op:ident, $lat:tt, $ops:expr, $oplat:expr, $golden:expr, $sym:expr, tie($($tie:ident),*)) => {
        impl Logic for $name {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, s_step_valid, s_step_y);
                self.op.clock.next = self.clock.val();
                self.op.a.next = self.a.val();
                self.op.b.next = self.b.val();
                $(self.op.$tie.next = false;)*
                self.op.valid_in.next = self.valid_in.val();
                self.step.x.next = self.op.y.val();
                self.s_step_valid.d.next = self.op.valid_out.val();
                self.s_step_y.d.next = self.step.y.val();
                self.y.next = self.s_step_y.q.val();
                self.valid_out.next = self.s_step_valid.q.val();
            }
        }

        #[doc = concat!("Bound ", $golden, " (golden [`tcheck::", $golden, "`](crate::golden::tcheck::", $golden, ")): ")]
        #[doc = concat!("`y = max(next_up(RNE(a ", $sym, " b)), m)` for bounds a, b >= 0, bit for bit for every pair of words.")]
        #[doc = ""]
        #[doc = concat!("The format's `", $ops, "` rounding to nearest (latency ", $oplat, "), then one more register ")]
        #[doc = "stage holding [`StepUp`] (`s_step_*` = outputs): the step-up's incrementer would otherwise"]
        #[doc = "sit in front of the next unit's first stage. One operation per clock;"]
        #[doc = concat!("latency ", stringify!($lat), " (inputs before rising edge 1, `y`, `valid_out` right after edge ", stringify!($lat), ").")]
        #[doc = ""]
        #[doc = "Ports: in `clock`, `a[W]`, `b[W]`, `valid_in`; out `y[W]`, `valid_out`."]
        #[derive(LogicBlock)]
        pub struct $name {
            pub clock: Signal<In, Clock>,
            pub a: Signal<In, Bits<$W>>,
            pub b: Signal<In, Bits<$W>>,
            pub valid_in: Signal<In, Bit>,
            pub y: Signal<Out, Bits<$W>>,
            pub valid_out: Signal<Out, Bit>,
            op: $op,
            step: StepUp,
            s_step_valid: DFF<Bit>,
            s_step_y: DFF<Bits<$W>>,
        }

        impl $name {
            /// Latency in clocks.
            pub const LATENCY: usize = $lat;

            /// The unit (its operation always rounds to nearest).
            pub fn new() -> Self {
                Self {
                    clock: Default::default(),
                    a: Default::default(),
                    b: Default::default(),
                    valid_in: Default::default(),
                    y: Default::default(),
                    valid_out: Default::default(),
                    op: $op::new(Rounding::NearestEven),
                    step: Default::default(),
                    s_step_valid: Default::default(),
                    s_step_y: Default::default(),
                }
            }
        }

        impl Default for $name {
            fn default() -> Self {
                Self::new()
            }
        }

    };
}
pub(crate) use bound;
