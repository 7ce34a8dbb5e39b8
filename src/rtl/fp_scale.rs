//! Multiplier by a constant `c = 2^k (1 + 2^-j + 2^-j2)` (`FpScale`), stamped out per
//! format by `fp_scale!`: T.CHECK's certificate multiplies magnitudes by constants only, and
//! these need shifts and two additions of significands instead of a `FpMul`.

/// Stamps out `FpScale` for one format in the calling module. Arguments: `W`, `E`, `F`,
/// `S` = 2 (F + 2) (the width of the significand sum).
macro_rules! fp_scale {
    ($W:tt, $E:tt, $F:tt, $S:tt) => {
        /// `y = |a| c` rounded upward and at least 2^emin for a nonzero `a`, with `c` one of
        /// two constants chosen by `sel` ([`ScaleConst`](crate::format::ScaleConst)s fixed
        /// at construction): golden [`Format::scale_up`](crate::format::Format::scale_up),
        /// bit for bit.
        ///
        /// With `a = 1.f 2^e` and `m = 1f` (F + 1 bits), `m c 2^(F+2-k) = (m << (F+2)) +
        /// (m << (F+2-j)) + (m << (F+2-j2))` (no third term when j2 = 0) is exact in `S`
        /// bits, below 2^(S-1) times 1.75; its top F + 1 bits (one normalising shift),
        /// plus one if any bit below them is set, are the result's significand, the
        /// exponent `e + k` plus the shift and the rounding's carry. Below 2^emin (a
        /// subnormal `a` too, since c < 1) the result is 2^emin; zero, infinity and NaN
        /// (canonical) pass. The sign of `a` is ignored. One combinational stage, then four
        /// registers: latency 4, as [`FpMul`]'s, so a constant multiplier swaps in without
        /// moving the schedule. Ports: in `clock`, `a[W]`, `sel`; out `y[W]`.
        #[derive(LogicBlock)]
        pub struct FpScale {
            pub clock: Signal<In, Clock>,
            pub a: Signal<In, Bits<$W>>,
            pub sel: Signal<In, Bit>,
            pub y: Signal<Out, Bits<$W>>,
            // the constants: exponent k (as 256 + k), the addends' shifts F + 2 - j and
            // F + 2 - j2, and whether there is a third
            c_k0: Constant<Bits<10>>,
            c_k1: Constant<Bits<10>>,
            c_sh0: Constant<Bits<8>>,
            c_sh1: Constant<Bits<8>>,
            c_t0: Constant<Bits<8>>,
            c_t1: Constant<Bits<8>>,
            c_en0: Constant<Bit>,
            c_en1: Constant<Bit>,
            c_j: Constant<Bits<8>>,
            c_j1: Constant<Bits<8>>,
            c_f: Constant<Bits<8>>,
            c_ofs: Constant<Bits<10>>,
            c_norm_min: Constant<Bits<10>>,
            c_min: Constant<Bits<$W>>,
            c_inf: Constant<Bits<$W>>,
            c_nan: Constant<Bits<$W>>,
            field: Signal<Local, Bits<$E>>,
            frac: Signal<Local, Bits<$F>>,
            m: Signal<Local, Bits<$S>>,
            lo_sh: Signal<Local, Bits<8>>,
            t_sh: Signal<Local, Bits<8>>,
            t_en: Signal<Local, Bit>,
            kk: Signal<Local, Bits<10>>,
            third: Signal<Local, Bits<$S>>,
            sum: Signal<Local, Bits<$S>>,
            top: Signal<Local, Bit>,
            sh: Signal<Local, Bits<8>>,
            hi: Signal<Local, Bits<$S>>,
            lost: Signal<Local, Bit>,
            rnd: Signal<Local, Bits<$S>>,
            eb: Signal<Local, Bits<10>>,
            e10: Signal<Local, Bits<10>>,
            res: Signal<Local, Bits<$W>>,
            out: Delay<Bits<$W>, 4>,
        }

        impl FpScale {
            pub const LATENCY: usize = 4;

            /// `c0` when `sel` is 0, `c1` when 1 (each `k < 0`, `1 <= j <= F + 2`, j2 = 0 or
            /// `j < j2 <= F + 2`).
            pub fn new(c0: crate::format::ScaleConst, c1: crate::format::ScaleConst) -> Self {
                let jmax = $F + 2;
                for c in [c0, c1] {
                    let ok = c.k < 0
                        && c.k > -200
                        && (1..=jmax).contains(&c.j)
                        && (c.j2 == 0 || (c.j + 1..=jmax).contains(&c.j2));
                    assert!(ok, "FpScale: constant {c:?} out of range");
                }
                let k = |c: crate::format::ScaleConst| Constant::new(((256 + c.k) as u64).into());
                let sh = |c: crate::format::ScaleConst| Constant::new(((jmax - c.j) as u64).into());
                let t = |c: crate::format::ScaleConst| {
                    Constant::new(((jmax - c.j2.max(c.j)) as u64).into())
                };
                let w = |x: f64| Constant::new(FORMAT.to_bits(x).into());
                Self {
                    clock: Default::default(),
                    a: Default::default(),
                    sel: Default::default(),
                    y: Default::default(),
                    c_k0: k(c0),
                    c_k1: k(c1),
                    c_sh0: sh(c0),
                    c_sh1: sh(c1),
                    c_t0: t(c0),
                    c_t1: t(c1),
                    c_en0: Constant::new(c0.j2 != 0),
                    c_en1: Constant::new(c1.j2 != 0),
                    c_j: Constant::new((jmax as u64).into()),
                    c_j1: Constant::new((jmax as u64 + 1).into()),
                    c_f: Constant::new(($F as u64).into()),
                    c_ofs: Constant::new(256u64.into()),
                    c_norm_min: Constant::new(257u64.into()),
                    c_min: w(FORMAT.min_positive_normal()),
                    c_inf: w(f64::INFINITY),
                    c_nan: w(f64::NAN),
                    field: Default::default(),
                    frac: Default::default(),
                    m: Default::default(),
                    lo_sh: Default::default(),
                    t_sh: Default::default(),
                    t_en: Default::default(),
                    kk: Default::default(),
                    third: Default::default(),
                    sum: Default::default(),
                    top: Default::default(),
                    sh: Default::default(),
                    hi: Default::default(),
                    lost: Default::default(),
                    rnd: Default::default(),
                    eb: Default::default(),
                    e10: Default::default(),
                    res: Default::default(),
                    out: Default::default(),
                }
            }
        }

        impl Logic for FpScale {
            #[hdl_gen]
            fn update(&mut self) {
                clock!(self, clock, out);
                self.field.next = self.a.val().get_bits::<$E>($F);
                self.frac.next = self.a.val().get_bits::<$F>(0);
                self.m.next = bit_cast::<$S, $F>(self.frac.val()).replace_bit($F, true);
                self.lo_sh.next = self.c_sh0.val();
                self.t_sh.next = self.c_t0.val();
                self.t_en.next = self.c_en0.val();
                self.kk.next = self.c_k0.val();
                if self.sel.val() {
                    self.lo_sh.next = self.c_sh1.val();
                    self.t_sh.next = self.c_t1.val();
                    self.t_en.next = self.c_en1.val();
                    self.kk.next = self.c_k1.val();
                }
                self.third.next = 0.into();
                if self.t_en.val() {
                    self.third.next = self.m.val() << self.t_sh.val();
                }
                self.sum.next = (self.m.val() << self.c_j.val())
                    + (self.m.val() << self.lo_sh.val())
                    + self.third.val();
                self.eb.next = bit_cast::<10, $E>(self.field.val()) + self.kk.val();
                // normalise by one bit, keep F + 1 bits, round up on any bit below them
                self.top.next = self.sum.val().get_bit($S - 1);
                self.sh.next = self.c_j.val();
                if self.top.val() {
                    self.sh.next = self.c_j1.val();
                }
                self.hi.next = self.sum.val() >> self.sh.val();
                self.lost.next = (self.hi.val() << self.sh.val()) != self.sum.val();
                self.rnd.next = self.hi.val() + self.lost.val();
                self.e10.next = self.eb.val() + self.top.val() + self.rnd.val().get_bit($F + 1);
                self.res.next = (bit_cast::<$W, 10>(self.e10.val() - self.c_ofs.val())
                    << self.c_f.val())
                    | bit_cast::<$W, $F>(bit_cast::<$F, $S>(self.rnd.val()));
                if (self.field.val() == 0) | (self.e10.val() < self.c_norm_min.val()) {
                    self.res.next = self.c_min.val();
                }
                if (self.field.val() == 0) & (self.frac.val() == 0) {
                    self.res.next = 0.into();
                }
                if self.field.val().all() {
                    self.res.next = self.c_inf.val();
                    if self.frac.val() != 0 {
                        self.res.next = self.c_nan.val();
                    }
                }
                self.out.d.next = self.res.val();
                self.y.next = self.out.q.val();
            }
        }
    };
}
pub(crate) use fp_scale;
