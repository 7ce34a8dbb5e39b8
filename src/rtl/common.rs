//! Shared combinational pieces of the floating-point units, stamped out per format by
//! [`fp_common!`](crate::rtl): operand unpacking, the leading-zero normaliser, the
//! significand multiplier (the one `Verilog::Custom` block) and the round-and-pack stage.

/// Stamps out, inside the calling module, the shared blocks for one format.
///
/// Arguments (all literal tokens, because stable Rust has no const-generic arithmetic):
/// `W` word width, `WM1` = W-1, `E` exponent bits, `F` fraction bits, `P` = F+1,
/// `P2` = P+2, `P3` = P+3, `P4` = P+4, `PP` = 2P, and the normaliser offsets for
/// widths P and P3 (`N-16`, `N-8`, `N-4`, `N-2`, `N-1`; without `N-16` below 16 bits).
macro_rules! fp_common {
    ($W:tt, $WM1:tt, $E:tt, $F:tt, $P:tt, $P2:tt, $P3:tt, $P4:tt, $PP:tt,
     norm_p($($np:tt),+),
     norm_p3($($nq:tt),+)) => {
        use rust_hdl::prelude::*;

        /// Unpacks one operand (combinational): sign, effective biased exponent
        /// (`max(field, 1)`, so subnormals share the exponent of the smallest normal),
        /// significand with the hidden bit, and the zero / inf / NaN class bits.
        #[derive(LogicBlock, Default)]
        pub struct Unpack {
            pub x: Signal<In, Bits<$W>>,
            pub sign: Signal<Out, Bit>,
            pub exp: Signal<Out, Bits<$E>>,
            pub sig: Signal<Out, Bits<$P>>,
            pub is_zero: Signal<Out, Bit>,
            pub is_inf: Signal<Out, Bit>,
            pub is_nan: Signal<Out, Bit>,
            field: Signal<Local, Bits<$E>>,
            frac: Signal<Local, Bits<$F>>,
            exp_zero: Signal<Local, Bit>,
            exp_ones: Signal<Local, Bit>,
            frac_zero: Signal<Local, Bit>,
        }

        impl Logic for Unpack {
            #[hdl_gen]
            fn update(&mut self) {
                self.field.next = self.x.val().get_bits::<$E>($F);
                self.frac.next = self.x.val().get_bits::<$F>(0);
                self.sign.next = self.x.val().get_bit($WM1);
                self.exp_zero.next = self.field.val() == 0;
                self.exp_ones.next = self.field.val().all();
                self.frac_zero.next = self.frac.val() == 0;
                self.is_zero.next = self.exp_zero.val() & self.frac_zero.val();
                self.is_inf.next = self.exp_ones.val() & self.frac_zero.val();
                self.is_nan.next = self.exp_ones.val() & !self.frac_zero.val();
                self.exp.next = self.field.val();
                self.sig.next = bit_cast::<$P, $F>(self.frac.val()).replace_bit($F, true);
                if self.exp_zero.val() {
                    self.exp.next = 1.into();
                    self.sig.next = bit_cast::<$P, $F>(self.frac.val());
                }
            }
        }

        $crate::rtl::common::fp_common!(@norm NormP, $P, $($np),+);
        $crate::rtl::common::fp_common!(@norm NormP3, $P3, $($nq),+);

        /// Significand multiplier (combinational, `P x P -> 2P` bits), reduced to what
        /// rounding needs: the top `P+2` product bits and the OR of the rest.
        /// `*` in rust-hdl kernels stops at 16x16 bits, so this is a `Verilog::Custom`
        /// block: an integer `update()` and one hand-written Verilog `*`.
        #[derive(LogicBlock, Default)]
        pub struct SigMul {
            pub a: Signal<In, Bits<$P>>,
            pub b: Signal<In, Bits<$P>>,
            pub hi: Signal<Out, Bits<$P2>>,
            pub sticky: Signal<Out, Bit>,
        }

        impl Logic for SigMul {
            fn update(&mut self) {
                let p: u64 = self.a.val().to_u64() * self.b.val().to_u64();
                self.hi.next = (p >> ($P - 2)).into();
                self.sticky.next = (p & ((1u64 << ($P - 2)) - 1)) != 0;
            }
            fn connect(&mut self) {
                self.hi.connect();
                self.sticky.connect();
            }
            fn hdl(&self) -> Verilog {
                Verilog::Custom(format!(
                    "wire [{top}:0] prod;\nassign prod = a * b;\nalways @(*) begin\n    hi = prod[{top}:{lo}];\n    sticky = |prod[{lm1}:0];\nend\n",
                    top = $PP - 1,
                    lo = $P - 2,
                    lm1 = $P - 3
                ))
            }
        }

        /// Round and pack (combinational): rounds the significand `nm` = `{m (P bits),
        /// guard, sticky}` with biased exponent field `efield` (0 for subnormals) and
        /// packs the word. Rounding adds the increment to the packed magnitude
        /// `{efield, m[F-1:0]}`, so a carry moves into the exponent (subnormal to normal,
        /// binade step, overflow to all ones) by itself. `ovf` = exponent already too
        /// large before rounding. Priority: NaN (canonical) > inf > zero > overflow.
        /// `round_up` = 1: TowardPositive, 0: NearestEven.
        #[derive(LogicBlock)]
        pub struct RoundPack {
            pub round_up: Signal<In, Bit>,
            pub sign: Signal<In, Bit>,
            pub nan: Signal<In, Bit>,
            pub inf: Signal<In, Bit>,
            pub zero: Signal<In, Bit>,
            pub ovf: Signal<In, Bit>,
            pub efield: Signal<In, Bits<$E>>,
            pub nm: Signal<In, Bits<$P2>>,
            pub y: Signal<Out, Bits<$W>>,
            c_nan: Constant<Bits<$W>>,
            c_sign: Constant<Bits<$W>>,
            c_inf: Constant<Bits<$WM1>>,
            c_max_finite: Constant<Bits<$WM1>>,
            lsb: Signal<Local, Bit>,
            guard: Signal<Local, Bit>,
            sticky: Signal<Local, Bit>,
            inc: Signal<Local, Bit>,
            pack_word: Signal<Local, Bits<$WM1>>,
            rounded: Signal<Local, Bits<$WM1>>,
            rexp_ones: Signal<Local, Bit>,
            mag: Signal<Local, Bits<$WM1>>,
        }

        impl Default for RoundPack {
            fn default() -> Self {
                let ones: u64 = (1u64 << $E) - 1;
                Self {
                    round_up: Default::default(),
                    sign: Default::default(),
                    nan: Default::default(),
                    inf: Default::default(),
                    zero: Default::default(),
                    ovf: Default::default(),
                    efield: Default::default(),
                    nm: Default::default(),
                    y: Default::default(),
                    c_nan: Constant::new(((ones << $F) | (1u64 << ($F - 1))).into()),
                    c_sign: Constant::new((1u64 << $WM1).into()),
                    c_inf: Constant::new((ones << $F).into()),
                    c_max_finite: Constant::new(((ones << $F) - 1).into()),
                    lsb: Default::default(),
                    guard: Default::default(),
                    sticky: Default::default(),
                    inc: Default::default(),
                    pack_word: Default::default(),
                    rounded: Default::default(),
                    rexp_ones: Default::default(),
                    mag: Default::default(),
                }
            }
        }

        impl Logic for RoundPack {
            #[hdl_gen]
            fn update(&mut self) {
                self.lsb.next = self.nm.val().get_bit(2);
                self.guard.next = self.nm.val().get_bit(1);
                self.sticky.next = self.nm.val().get_bit(0);
                self.inc.next = self.guard.val() & (self.sticky.val() | self.lsb.val());
                if self.round_up.val() {
                    self.inc.next = !self.sign.val() & (self.guard.val() | self.sticky.val());
                }
                self.pack_word.next = (bit_cast::<$WM1, $E>(self.efield.val()) << $F)
                    | bit_cast::<$WM1, $F>(self.nm.val().get_bits::<$F>(2));
                self.rounded.next = self.pack_word.val() + self.inc.val();
                self.rexp_ones.next = self.rounded.val().get_bits::<$E>($F).all();
                self.mag.next = self.rounded.val();
                if self.ovf.val() | self.rexp_ones.val() {
                    self.mag.next = self.c_inf.val();
                    if self.round_up.val() & self.sign.val() {
                        self.mag.next = self.c_max_finite.val();
                    }
                }
                if self.zero.val() {
                    self.mag.next = 0.into();
                }
                if self.inf.val() {
                    self.mag.next = self.c_inf.val();
                }
                self.y.next = bit_cast::<$W, $WM1>(self.mag.val());
                if self.sign.val() {
                    self.y.next = bit_cast::<$W, $WM1>(self.mag.val()) | self.c_sign.val();
                }
                if self.nan.val() {
                    self.y.next = self.c_nan.val();
                }
            }
        }
    };

    (@norm $name:ident, $n:tt, $o16:tt, $o8:tt, $o4:tt, $o2:tt, $o1:tt) => {
        /// Leading-zero normaliser (combinational): `y = x << lz`, `lz` = leading zeros
        /// of `x` (five shift steps 16/8/4/2/1; `lz` is meaningless for `x = 0`).
        #[derive(LogicBlock, Default)]
        pub struct $name {
            pub x: Signal<In, Bits<$n>>,
            pub y: Signal<Out, Bits<$n>>,
            pub lz: Signal<Out, Bits<5>>,
            z16: Signal<Local, Bit>,
            z8: Signal<Local, Bit>,
            z4: Signal<Local, Bit>,
            z2: Signal<Local, Bit>,
            z1: Signal<Local, Bit>,
            x16: Signal<Local, Bits<$n>>,
            x8: Signal<Local, Bits<$n>>,
            x4: Signal<Local, Bits<$n>>,
            x2: Signal<Local, Bits<$n>>,
        }

        impl Logic for $name {
            #[hdl_gen]
            fn update(&mut self) {
                self.z16.next = self.x.val().get_bits::<16>($o16) == 0;
                self.x16.next = self.x.val();
                if self.z16.val() {
                    self.x16.next = self.x.val() << 16;
                }
                self.z8.next = self.x16.val().get_bits::<8>($o8) == 0;
                self.x8.next = self.x16.val();
                if self.z8.val() {
                    self.x8.next = self.x16.val() << 8;
                }
                self.z4.next = self.x8.val().get_bits::<4>($o4) == 0;
                self.x4.next = self.x8.val();
                if self.z4.val() {
                    self.x4.next = self.x8.val() << 4;
                }
                self.z2.next = self.x4.val().get_bits::<2>($o2) == 0;
                self.x2.next = self.x4.val();
                if self.z2.val() {
                    self.x2.next = self.x4.val() << 2;
                }
                self.z1.next = !self.x2.val().get_bit($o1);
                self.y.next = self.x2.val();
                if self.z1.val() {
                    self.y.next = self.x2.val() << 1;
                }
                self.lz.next = bits::<5>(0)
                    .replace_bit(4, self.z16.val())
                    .replace_bit(3, self.z8.val())
                    .replace_bit(2, self.z4.val())
                    .replace_bit(1, self.z2.val())
                    .replace_bit(0, self.z1.val());
            }
        }
    };

    // The arm above without its 16 step. One arm cannot serve both: `#[hdl_gen]` reads the
    // body before any macro inside it expands, and stable `macro_rules!` cannot drop the 16
    // step's fields and statements without changing the other formats' Verilog.
    (@norm $name:ident, $n:tt, $o8:tt, $o4:tt, $o2:tt, $o1:tt) => {
        /// Leading-zero normaliser (combinational) of fewer than 16 bits: `y = x << lz`,
        /// `lz` = leading zeros of `x` (four shift steps 8/4/2/1, `lz` bit 4 zero; `lz` is
        /// meaningless for `x = 0`).
        #[derive(LogicBlock, Default)]
        pub struct $name {
            pub x: Signal<In, Bits<$n>>,
            pub y: Signal<Out, Bits<$n>>,
            pub lz: Signal<Out, Bits<5>>,
            z8: Signal<Local, Bit>,
            z4: Signal<Local, Bit>,
            z2: Signal<Local, Bit>,
            z1: Signal<Local, Bit>,
            x8: Signal<Local, Bits<$n>>,
            x4: Signal<Local, Bits<$n>>,
            x2: Signal<Local, Bits<$n>>,
        }

        impl Logic for $name {
            #[hdl_gen]
            fn update(&mut self) {
                self.z8.next = self.x.val().get_bits::<8>($o8) == 0;
                self.x8.next = self.x.val();
                if self.z8.val() {
                    self.x8.next = self.x.val() << 8;
                }
                self.z4.next = self.x8.val().get_bits::<4>($o4) == 0;
                self.x4.next = self.x8.val();
                if self.z4.val() {
                    self.x4.next = self.x8.val() << 4;
                }
                self.z2.next = self.x4.val().get_bits::<2>($o2) == 0;
                self.x2.next = self.x4.val();
                if self.z2.val() {
                    self.x2.next = self.x4.val() << 2;
                }
                self.z1.next = !self.x2.val().get_bit($o1);
                self.y.next = self.x2.val();
                if self.z1.val() {
                    self.y.next = self.x2.val() << 1;
                }
                self.lz.next = bits::<5>(0)
                    .replace_bit(3, self.z8.val())
                    .replace_bit(2, self.z4.val())
                    .replace_bit(1, self.z2.val())
                    .replace_bit(0, self.z1.val());
            }
        }
    };
}
pub(crate) use fp_common;

/// Where a floating-point unit's rounding comes from, `round_up` (1: TowardPositive, 0:
/// NearestEven): a constant fixed at construction (`Constant<Bit>`: the exported FP units,
/// T.CHECK's) or an input (`Signal<In, Bit>`: the DOP lanes', whose rounding the host sets
/// per query with the setup words).
pub trait RoundUp: rust_hdl::prelude::Block {
    fn val(&self) -> bool;
}

impl RoundUp for rust_hdl::prelude::Constant<bool> {
    fn val(&self) -> bool {
        rust_hdl::prelude::Constant::val(self)
    }
}

impl RoundUp for rust_hdl::prelude::Signal<rust_hdl::prelude::In, bool> {
    fn val(&self) -> bool {
        rust_hdl::prelude::Signal::<rust_hdl::prelude::In, bool>::val(self)
    }
}

/// `round_up` for `rounding` in the unit `unit` (which implements the two roundings).
pub fn round_up(rounding: crate::format::Rounding, unit: &str) -> bool {
    use crate::format::Rounding;
    match rounding {
        Rounding::NearestEven => false,
        Rounding::TowardPositive => true,
        Rounding::TowardNegative => panic!("{unit}: TowardNegative is not implemented"),
    }
}
