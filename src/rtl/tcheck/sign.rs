//! T.CHECK's three-valued sign of a value against its bound (golden
//! [`sign`](crate::golden::tcheck::sign)), used by each `Edge` for its six signs.

/// Stamps out `Sign` in the calling module (by `tcheck!`, tcheck/mod.rs, which also
/// brings `Delay` and `ABS_MASK` into scope).
macro_rules! sign {
    ($W:tt, $WM1:tt, $E:tt, $F:tt) => {
        /// The three-valued sign of a value against its bound (golden
        /// [`sign`](crate::golden::tcheck::sign)), combinational: `sgn = 1` surely positive
        /// (`x > e`), `2` surely negative (`x < -e`), `0` unknown (also for a NaN x or a
        /// NaN bound). Bounds are never negative (every bound operation rounds upward on
        /// non-negative operands), so `|x| > e` is an unsigned compare of the patterns
        /// (a NaN bound's pattern is above every |x| but a NaN's).
        #[derive(LogicBlock)]
        pub struct Sign {
            pub x: Signal<In, Bits<$W>>,
            pub e: Signal<In, Bits<$W>>,
            pub sgn: Signal<Out, Bits<2>>,
            c_pos: Constant<Bits<2>>,
            c_neg: Constant<Bits<2>>,
            nan: Signal<Local, Bit>,
            big: Signal<Local, Bit>,
        }

        impl Sign {
            pub fn new() -> Self {
                Self {
                    x: Default::default(),
                    e: Default::default(),
                    sgn: Default::default(),
                    c_pos: Constant::new(1u64.into()),
                    c_neg: Constant::new(2u64.into()),
                    nan: Default::default(),
                    big: Default::default(),
                }
            }
        }

        impl Default for Sign {
            fn default() -> Self {
                Self::new()
            }
        }

        impl Logic for Sign {
            #[hdl_gen]
            fn update(&mut self) {
                self.nan.next =
                    self.x.val().get_bits::<$E>($F).all() & (self.x.val().get_bits::<$F>(0) != 0);
                self.big.next =
                    bit_cast::<$W, $WM1>(self.x.val().get_bits::<$WM1>(0)) > self.e.val();
                self.sgn.next = 0.into();
                if self.big.val() & !self.nan.val() {
                    self.sgn.next = self.c_pos.val();
                    if self.x.val().get_bit($WM1) {
                        self.sgn.next = self.c_neg.val();
                    }
                }
            }
        }
    };
}
pub(crate) use sign;
