//! T.CHECK's dot product of stages 1 and 2 (Eqs. 11-13), values and magnitudes.

/// Stamps out `Dot` in the calling module (by `tcheck!`, tcheck/mod.rs, which also
/// brings `Delay` and `ABS_MASK` into scope).
macro_rules! dot {
    ($W:tt, $WM1:tt) => {
        /// One dot product of stages 1 and 2 in the golden order (golden `dot`):
        /// `y = (a0 b0 + a1 b1) + a2 b2` (`affine` false: M_b's linear entries, Eq. 11) or
        /// `y = (a0 b0 + a1 b1) + (a2 b2 + c)` (`affine` true: M_b's translation column,
        /// Eq. 12, and a mapped vertex coordinate, Eq. 13). With `magnitude` every operand's
        /// sign is cleared first and the units round upward (golden `dot_mag`: the
        /// certificate's magnitude of the same expression).
        ///
        /// Schedule: products after edge 4, `s01` and `s2c` 7 (`c` is taken [`Dot::C_AT`]
        /// = 4 clocks after the a and b it belongs to, when the products are ready; `p2`
        /// waits 3 clocks in the linear shape), y after edge 10. Latency [`Dot::LATENCY`] =
        /// 10. Ports: in `clock`, `a0` .. `a2`, `b0` .. `b2`, `c`; out `y` (scalar ports:
        /// rust-hdl's Verilog cannot address an array port of a block that is itself an
        /// array element).
        #[derive(LogicBlock)]
        pub struct Dot {
            pub clock: Signal<In, Clock>,
            pub a0: Signal<In, Bits<$W>>,
            pub a1: Signal<In, Bits<$W>>,
            pub a2: Signal<In, Bits<$W>>,
            pub b0: Signal<In, Bits<$W>>,
            pub b1: Signal<In, Bits<$W>>,
            pub b2: Signal<In, Bits<$W>>,
            pub c: Signal<In, Bits<$W>>,
            pub y: Signal<Out, Bits<$W>>,
            affine: Constant<Bit>,
            mask: Constant<Bits<$W>>,
            p: [FpMul; 3],
            s01: FpAdd,
            s2c: FpAdd,
            s: FpAdd,
            p2_wait: Delay<Bits<$W>, 3>,
        }

        impl Dot {
            pub const LATENCY: usize = 10;
            pub const C_AT: usize = 4;

            pub fn new(rounding: Rounding, affine: bool, magnitude: bool) -> Self {
                let r = if magnitude {
                    Rounding::TowardPositive
                } else {
                    rounding
                };
                Self {
                    clock: Default::default(),
                    a0: Default::default(),
                    a1: Default::default(),
                    a2: Default::default(),
                    b0: Default::default(),
                    b1: Default::default(),
                    b2: Default::default(),
                    c: Default::default(),
                    y: Default::default(),
                    affine: Constant::new(affine),
                    mask: Constant::new(
                        if magnitude {
                            ABS_MASK
                        } else {
                            ABS_MASK | (1u64 << $WM1)
                        }
                        .into(),
                    ),
                    p: std::array::from_fn(|_| FpMul::new(r)),
                    s01: FpAdd::new(r),
                    s2c: FpAdd::new(r),
                    s: FpAdd::new(r),
                    p2_wait: Default::default(),
                }
            }
        }

        impl Logic for Dot {
            #[hdl_gen]
            fn update(&mut self) {
                clock!(self, clock, s01, s2c, s, p2_wait);
                for k in 0..3 {
                    self.p[k].clock.next = self.clock.val();
                    self.p[k].valid_in.next = false;
                }
                self.p[0].a.next = self.a0.val() & self.mask.val();
                self.p[0].b.next = self.b0.val() & self.mask.val();
                self.p[1].a.next = self.a1.val() & self.mask.val();
                self.p[1].b.next = self.b1.val() & self.mask.val();
                self.p[2].a.next = self.a2.val() & self.mask.val();
                self.p[2].b.next = self.b2.val() & self.mask.val();
                self.s01.a.next = self.p[0].y.val();
                self.s01.b.next = self.p[1].y.val();
                self.s01.sub.next = false;
                self.s01.valid_in.next = false;
                self.s2c.a.next = self.p[2].y.val();
                self.s2c.b.next = self.c.val() & self.mask.val();
                self.s2c.sub.next = false;
                self.s2c.valid_in.next = false;
                self.p2_wait.d.next = self.p[2].y.val();
                self.s.a.next = self.s01.y.val();
                self.s.b.next = self.p2_wait.q.val();
                if self.affine.val() {
                    self.s.b.next = self.s2c.y.val();
                }
                self.s.sub.next = false;
                self.s.valid_in.next = false;
                self.y.next = self.s.y.val();
            }
        }
    };
}
pub(crate) use dot;
