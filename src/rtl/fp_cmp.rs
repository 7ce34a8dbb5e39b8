//! The floating-point compare unit (`FpCmp`), stamped out per format by `fp_cmp!`: WSCG'03's
//! DOP Unit (§4.1) tests an aligned DOP's coefficients, in bundles of eight, against the
//! transformed d' of both tumbled siblings in a bank of 16 of them.

/// Stamps out `FpCmp` for one format in the calling module. Arguments: `W` word width,
/// `WM1` = W-1, `E` exponent bits, `F` fraction bits.
macro_rules! fp_cmp {
    ($W:tt, $WM1:tt, $E:tt, $F:tt) => {
        /// `flag = a + b < 0`, decided by comparing `a` with `-b`, without an adder: the
        /// flag of a DOPTRF lane's last sum, `round(d' + e) < 0`, bit for bit (golden
        /// [`separated`](crate::golden::doptrf::separated)). The formats have subnormals, so
        /// the sum of two of their values rounds to zero only if it is zero, and rounding
        /// keeps the sign: the rounded sum is negative iff the exact one is
        /// (docs/explanation/accuracy.md, "The compare units"). A NaN, and the sum of
        /// opposite infinities, are not < 0; a zero's sign does not count.
        ///
        /// On sign and magnitude: with both signs set the sum is negative unless both are
        /// zeros; with neither, never; with one, iff the negative operand's magnitude is the
        /// larger. One register stage: latency 1
        /// ([`FP_CMP_LATENCY`](crate::chip::rtl::FP_CMP_LATENCY)). Ports: in `clock`,
        /// `a[W]`, `b[W]`, `valid_in`; out `flag`, `valid_out`.
        #[derive(LogicBlock)]
        pub struct FpCmp {
            pub clock: Signal<In, Clock>,
            pub a: Signal<In, Bits<$W>>,
            pub b: Signal<In, Bits<$W>>,
            pub valid_in: Signal<In, Bit>,
            pub flag: Signal<Out, Bit>,
            pub valid_out: Signal<Out, Bit>,
            /// The magnitude of infinity: a larger one is a NaN.
            c_inf: Constant<Bits<$WM1>>,
            mag_a: Signal<Local, Bits<$WM1>>,
            mag_b: Signal<Local, Bits<$WM1>>,
            s1_flag: DFF<Bit>,
            s1_valid: DFF<Bit>,
        }

        impl FpCmp {
            pub const LATENCY: usize = $crate::chip::rtl::FP_CMP_LATENCY;

            pub fn new() -> Self {
                Self {
                    clock: Default::default(),
                    a: Default::default(),
                    b: Default::default(),
                    valid_in: Default::default(),
                    flag: Default::default(),
                    valid_out: Default::default(),
                    c_inf: Constant::new((((1u64 << $E) - 1) << $F).into()),
                    mag_a: Default::default(),
                    mag_b: Default::default(),
                    s1_flag: Default::default(),
                    s1_valid: Default::default(),
                }
            }
        }

        impl Default for FpCmp {
            fn default() -> Self {
                Self::new()
            }
        }

        impl Logic for FpCmp {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, s1_flag, s1_valid);
                self.mag_a.next = self.a.val().get_bits::<$WM1>(0);
                self.mag_b.next = self.b.val().get_bits::<$WM1>(0);
                self.s1_flag.d.next = false;
                if (self.mag_a.val() <= self.c_inf.val()) & (self.mag_b.val() <= self.c_inf.val()) {
                    if self.a.val().get_bit($WM1) & self.b.val().get_bit($WM1) {
                        self.s1_flag.d.next = self.mag_a.val().any() | self.mag_b.val().any();
                    }
                    if self.a.val().get_bit($WM1) & !self.b.val().get_bit($WM1) {
                        self.s1_flag.d.next = self.mag_a.val() > self.mag_b.val();
                    }
                    if !self.a.val().get_bit($WM1) & self.b.val().get_bit($WM1) {
                        self.s1_flag.d.next = self.mag_b.val() > self.mag_a.val();
                    }
                }
                self.s1_valid.d.next = self.valid_in.val();
                self.flag.next = self.s1_flag.q.val();
                self.valid_out.next = self.s1_valid.q.val();
            }
        }
    };
}
pub(crate) use fp_cmp;
