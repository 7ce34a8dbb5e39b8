//! T.CHECK (DATE'05 §4.2, Eqs. 8, 9, 11-13) with the uncertainty flag, stamped out per
//! format by `tcheck!`: the value datapath of the paper's five macro stages, each value
//! carrying its error bound through a shadow datapath of bound units (golden
//! [`golden::tcheck`](crate::golden::tcheck), docs/ARCHITECTURE.md "T.CHECK in RTL").

/// Stamps out `Sign`, `BMul`, `BAdd`, `AffRow`, `Gap`, `Edge` and `TCheck` in the calling
/// module (which must also hold `FpMul`, `FpAdd`, `BoundMul`, `BoundAdd` and `RoundErr`).
/// Arguments: `W`, `WM1` = W-1, `E`, `F`.
macro_rules! tcheck {
    ($W:tt, $WM1:tt, $E:tt, $F:tt) => {
        // Row i of M_b (`mb_i`), of M_B's input register (`in_m_i`) and of the mapped
        // vertices (`vt_i`), and the gap's ports for coordinate i: the kernel's wiring is
        // written once per row by repetition (rust-hdl kernels allow one loop level only).
        $crate::rtl::tcheck::tcheck!(@units $W, $WM1, $E, $F;
            (mb_0 in_m_0 vt_0 x0 e0) (mb_1 in_m_1 vt_1 x1 e1) (mb_2 in_m_2 vt_2 x2 e2));
    };
    (@units $W:tt, $WM1:tt, $E:tt, $F:tt; $(($mb:ident $in_m:ident $vt:ident $gx:ident $ge:ident))*) => {
        use $crate::rtl::delay::Delay;

        /// A bit pattern of the format (`sign`, biased exponent field, fraction field).
        fn pattern(exp_field: u64, frac: u64) -> Bits<$W> {
            ((exp_field << $F) | frac).into()
        }

        /// The three-valued sign of a bounded value (golden [`Bounded::sign`](crate::golden::tcheck::Bounded::sign)),
        /// combinational: `sgn = 1` surely positive (`x > e`), `2` surely negative
        /// (`x < -e`), `0` unknown (also for a NaN x). The bound e is never negative (bound
        /// units floor at the smallest normal; an exact vertex has e = +0), so `|x| > e` is an
        /// unsigned compare of the patterns.
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

        impl Logic for Sign {
            #[hdl_gen]
            fn update(&mut self) {
                self.nan.next = self.x.val().get_bits::<$E>($F).all() & (self.x.val().get_bits::<$F>(0) != 0);
                self.big.next = bit_cast::<$W, $WM1>(self.x.val().get_bits::<$WM1>(0)) > self.e.val();
                self.sgn.next = 0.into();
                if self.big.val() & !self.nan.val() {
                    self.sgn.next = self.c_pos.val();
                    if self.x.val().get_bit($WM1) {
                        self.sgn.next = self.c_neg.val();
                    }
                }
            }
        }

        /// Multiplication of bounded values (golden `Arith::mul`): `x = a.x * b.x` in the
        /// datapath's rounding and
        /// `e = (a.e |b.x| + b.e |a.x|) + (a.e b.e + err(x))`, each `+` a [`BoundAdd`],
        /// each product a [`BoundMul`], err a [`RoundErr`].
        ///
        /// Schedule (inputs before rising edge 1): `mul` x after edge 4, `err` 5; the three
        /// bound products 5; `s_cross`, `s_err` 9; `s_all` = e after edge 13; x waits 9
        /// clocks in `x_wait`. Latency [`BMul::LATENCY`] = 13, one operation per clock.
        /// Ports: in `clock`, `ax`, `ae`, `bx`, `be`; out `x`, `e`.
        #[derive(LogicBlock)]
        pub struct BMul {
            pub clock: Signal<In, Clock>,
            pub ax: Signal<In, Bits<$W>>,
            pub ae: Signal<In, Bits<$W>>,
            pub bx: Signal<In, Bits<$W>>,
            pub be: Signal<In, Bits<$W>>,
            pub x: Signal<Out, Bits<$W>>,
            pub e: Signal<Out, Bits<$W>>,
            mul: FpMul,
            err: RoundErr,
            ae_bx: BoundMul,
            be_ax: BoundMul,
            ae_be: BoundMul,
            s_cross: BoundAdd,
            s_err: BoundAdd,
            s_all: BoundAdd,
            x_wait: Delay<Bits<$W>, 9>,
        }

        impl BMul {
            pub const LATENCY: usize = 13;

            pub fn new(rounding: Rounding) -> Self {
                Self {
                    clock: Default::default(),
                    ax: Default::default(),
                    ae: Default::default(),
                    bx: Default::default(),
                    be: Default::default(),
                    x: Default::default(),
                    e: Default::default(),
                    mul: FpMul::new(rounding),
                    err: RoundErr::new(rounding),
                    ae_bx: BoundMul::new(),
                    be_ax: BoundMul::new(),
                    ae_be: BoundMul::new(),
                    s_cross: BoundAdd::new(),
                    s_err: BoundAdd::new(),
                    s_all: BoundAdd::new(),
                    x_wait: Default::default(),
                }
            }
        }

        impl Logic for BMul {
            #[hdl_gen]
            fn update(&mut self) {
                clock!(self, clock, mul, err, ae_bx, be_ax, ae_be, s_cross, s_err, s_all, x_wait);
                self.mul.a.next = self.ax.val();
                self.mul.b.next = self.bx.val();
                self.mul.valid_in.next = false;
                self.err.x.next = self.mul.y.val();
                self.err.valid_in.next = false;
                self.ae_bx.a.next = self.ae.val();
                self.ae_bx.b.next = bit_cast::<$W, $WM1>(self.bx.val().get_bits::<$WM1>(0));
                self.ae_bx.valid_in.next = false;
                self.be_ax.a.next = self.be.val();
                self.be_ax.b.next = bit_cast::<$W, $WM1>(self.ax.val().get_bits::<$WM1>(0));
                self.be_ax.valid_in.next = false;
                self.ae_be.a.next = self.ae.val();
                self.ae_be.b.next = self.be.val();
                self.ae_be.valid_in.next = false;
                self.s_cross.a.next = self.ae_bx.y.val();
                self.s_cross.b.next = self.be_ax.y.val();
                self.s_cross.valid_in.next = false;
                self.s_err.a.next = self.ae_be.y.val();
                self.s_err.b.next = self.err.y.val();
                self.s_err.valid_in.next = false;
                self.s_all.a.next = self.s_cross.y.val();
                self.s_all.b.next = self.s_err.y.val();
                self.s_all.valid_in.next = false;
                self.x_wait.d.next = self.mul.y.val();
                self.x.next = self.x_wait.q.val();
                self.e.next = self.s_all.y.val();
            }
        }

        /// Addition (`sub` = 0) or subtraction (`sub` = 1) of bounded values (golden
        /// `Arith::add` / `Arith::sub`): `x = a.x ± b.x` in the datapath's rounding,
        /// `e = (a.e + b.e) + err(x)`.
        ///
        /// Schedule: `add` x after edge 3, `err` 4, `s_ab` 4, `s_err` = e after edge 8;
        /// x waits 5 clocks. Latency [`BAdd::LATENCY`] = 8. Ports: in `clock`, `ax`, `ae`,
        /// `bx`, `be`, `sub`; out `x`, `e`.
        #[derive(LogicBlock)]
        pub struct BAdd {
            pub clock: Signal<In, Clock>,
            pub ax: Signal<In, Bits<$W>>,
            pub ae: Signal<In, Bits<$W>>,
            pub bx: Signal<In, Bits<$W>>,
            pub be: Signal<In, Bits<$W>>,
            pub sub: Signal<In, Bit>,
            pub x: Signal<Out, Bits<$W>>,
            pub e: Signal<Out, Bits<$W>>,
            add: FpAdd,
            err: RoundErr,
            s_ab: BoundAdd,
            s_err: BoundAdd,
            x_wait: Delay<Bits<$W>, 5>,
        }

        impl BAdd {
            pub const LATENCY: usize = 8;

            pub fn new(rounding: Rounding) -> Self {
                Self {
                    clock: Default::default(),
                    ax: Default::default(),
                    ae: Default::default(),
                    bx: Default::default(),
                    be: Default::default(),
                    sub: Default::default(),
                    x: Default::default(),
                    e: Default::default(),
                    add: FpAdd::new(rounding),
                    err: RoundErr::new(rounding),
                    s_ab: BoundAdd::new(),
                    s_err: BoundAdd::new(),
                    x_wait: Default::default(),
                }
            }
        }

        impl Logic for BAdd {
            #[hdl_gen]
            fn update(&mut self) {
                clock!(self, clock, add, err, s_ab, s_err, x_wait);
                self.add.a.next = self.ax.val();
                self.add.b.next = self.bx.val();
                self.add.sub.next = self.sub.val();
                self.add.valid_in.next = false;
                self.err.x.next = self.add.y.val();
                self.err.valid_in.next = false;
                self.s_ab.a.next = self.ae.val();
                self.s_ab.b.next = self.be.val();
                self.s_ab.valid_in.next = false;
                self.s_err.a.next = self.s_ab.y.val();
                self.s_err.b.next = self.err.y.val();
                self.s_err.valid_in.next = false;
                self.x_wait.d.next = self.add.y.val();
                self.x.next = self.x_wait.q.val();
                self.e.next = self.s_err.y.val();
            }
        }

        /// One entry of an affine product on bounded values, the shape shared by Eqs. 11-13:
        /// `y = (a0 b0 + a1 b1) + a2 b2` (`affine` false: M_b's linear entries, Eq. 11) or
        /// `y = (a0 b0 + a1 b1) + (a2 b2 + c)` (`affine` true: M_b's translation column,
        /// Eq. 12, and a mapped vertex coordinate, Eq. 13), in the golden order.
        ///
        /// Schedule: products `p[k]` after edge 13; `s01` and `s2c` (`p2 + c`, c waiting 13
        /// clocks) after 21, `p2` waiting 8 clocks for the linear shape; `s` = y after edge
        /// 29. Latency [`AffRow::LATENCY`] = 29 = BMul + 2 BAdd. Ports: in `clock`,
        /// `a0_x`, `a0_e` .. `a2_x`, `a2_e`, `b0_x` .. `b2_e`, `c_x`, `c_e`; out `y_x`, `y_e`
        /// (scalar ports: rust-hdl's Verilog cannot address an array port of a block that
        /// is itself an array element).
        #[derive(LogicBlock)]
        pub struct AffRow {
            pub clock: Signal<In, Clock>,
            pub a0_x: Signal<In, Bits<$W>>,
            pub a0_e: Signal<In, Bits<$W>>,
            pub a1_x: Signal<In, Bits<$W>>,
            pub a1_e: Signal<In, Bits<$W>>,
            pub a2_x: Signal<In, Bits<$W>>,
            pub a2_e: Signal<In, Bits<$W>>,
            pub b0_x: Signal<In, Bits<$W>>,
            pub b0_e: Signal<In, Bits<$W>>,
            pub b1_x: Signal<In, Bits<$W>>,
            pub b1_e: Signal<In, Bits<$W>>,
            pub b2_x: Signal<In, Bits<$W>>,
            pub b2_e: Signal<In, Bits<$W>>,
            pub c_x: Signal<In, Bits<$W>>,
            pub c_e: Signal<In, Bits<$W>>,
            pub y_x: Signal<Out, Bits<$W>>,
            pub y_e: Signal<Out, Bits<$W>>,
            affine: Constant<Bit>,
            p: [BMul; 3],
            s01: BAdd,
            s2c: BAdd,
            s: BAdd,
            c_x_wait: Delay<Bits<$W>, 13>,
            c_e_wait: Delay<Bits<$W>, 13>,
            p2_x_wait: Delay<Bits<$W>, 8>,
            p2_e_wait: Delay<Bits<$W>, 8>,
        }

        impl AffRow {
            pub const LATENCY: usize = BMul::LATENCY + 2 * BAdd::LATENCY;

            pub fn new(rounding: Rounding, affine: bool) -> Self {
                Self {
                    clock: Default::default(),
                    a0_x: Default::default(),
                    a0_e: Default::default(),
                    a1_x: Default::default(),
                    a1_e: Default::default(),
                    a2_x: Default::default(),
                    a2_e: Default::default(),
                    b0_x: Default::default(),
                    b0_e: Default::default(),
                    b1_x: Default::default(),
                    b1_e: Default::default(),
                    b2_x: Default::default(),
                    b2_e: Default::default(),
                    c_x: Default::default(),
                    c_e: Default::default(),
                    y_x: Default::default(),
                    y_e: Default::default(),
                    affine: Constant::new(affine),
                    p: std::array::from_fn(|_| BMul::new(rounding)),
                    s01: BAdd::new(rounding),
                    s2c: BAdd::new(rounding),
                    s: BAdd::new(rounding),
                    c_x_wait: Default::default(),
                    c_e_wait: Default::default(),
                    p2_x_wait: Default::default(),
                    p2_e_wait: Default::default(),
                }
            }
        }

        impl Logic for AffRow {
            #[hdl_gen]
            fn update(&mut self) {
                clock!(self, clock, s01, s2c, s, c_x_wait, c_e_wait, p2_x_wait, p2_e_wait);
                self.p[0].clock.next = self.clock.val();
                self.p[0].ax.next = self.a0_x.val();
                self.p[0].ae.next = self.a0_e.val();
                self.p[0].bx.next = self.b0_x.val();
                self.p[0].be.next = self.b0_e.val();
                self.p[1].clock.next = self.clock.val();
                self.p[1].ax.next = self.a1_x.val();
                self.p[1].ae.next = self.a1_e.val();
                self.p[1].bx.next = self.b1_x.val();
                self.p[1].be.next = self.b1_e.val();
                self.p[2].clock.next = self.clock.val();
                self.p[2].ax.next = self.a2_x.val();
                self.p[2].ae.next = self.a2_e.val();
                self.p[2].bx.next = self.b2_x.val();
                self.p[2].be.next = self.b2_e.val();
                self.s01.ax.next = self.p[0].x.val();
                self.s01.ae.next = self.p[0].e.val();
                self.s01.bx.next = self.p[1].x.val();
                self.s01.be.next = self.p[1].e.val();
                self.s01.sub.next = false;
                self.c_x_wait.d.next = self.c_x.val();
                self.c_e_wait.d.next = self.c_e.val();
                self.s2c.ax.next = self.p[2].x.val();
                self.s2c.ae.next = self.p[2].e.val();
                self.s2c.bx.next = self.c_x_wait.q.val();
                self.s2c.be.next = self.c_e_wait.q.val();
                self.s2c.sub.next = false;
                self.p2_x_wait.d.next = self.p[2].x.val();
                self.p2_e_wait.d.next = self.p[2].e.val();
                self.s.ax.next = self.s01.x.val();
                self.s.ae.next = self.s01.e.val();
                self.s.bx.next = self.p2_x_wait.q.val();
                self.s.be.next = self.p2_e_wait.q.val();
                if self.affine.val() {
                    self.s.bx.next = self.s2c.x.val();
                    self.s.be.next = self.s2c.e.val();
                }
                self.s.sub.next = false;
                self.y_x.next = self.s.x.val();
                self.y_e.next = self.s.e.val();
            }
        }

        /// The vertex gap of the direction A vs U(B) (golden `vertex_gap`): B's vertices are
        /// known only within eta, so a mapped vertex (u, v, z) may move by
        /// `g = 2 lambda (eta (1 + 2 ((|u| + e_u) + (|v| + e_v))))`, and each coordinate's
        /// bound becomes `e + g` (`g = +inf` unless the T.CHECK's `ok`). With `en` low the
        /// bounds pass unchanged (direction B vs U(A)).
        ///
        /// Schedule (bound units): `bu`, `bv` after edge 4, `uv` 8, `t` = 2 uv 13, `w` =
        /// 1 + t 17, `q` = eta w 22, `g` = 2 lambda q 27, `eg[k]` = e_k + g 31. Latency
        /// [`Gap::LATENCY`] = 31. Ports: in `clock`, `x0`, `e0` .. `x2`, `e2` (the vertex),
        /// `two_lambda`, `eta`, `ok`, `en`; out `y0_x`, `y0_e` .. `y2_x`, `y2_e`.
        #[derive(LogicBlock)]
        pub struct Gap {
            pub clock: Signal<In, Clock>,
            pub x0: Signal<In, Bits<$W>>,
            pub e0: Signal<In, Bits<$W>>,
            pub x1: Signal<In, Bits<$W>>,
            pub e1: Signal<In, Bits<$W>>,
            pub x2: Signal<In, Bits<$W>>,
            pub e2: Signal<In, Bits<$W>>,
            pub two_lambda: Signal<In, Bits<$W>>,
            pub eta: Signal<In, Bits<$W>>,
            pub ok: Signal<In, Bit>,
            pub en: Signal<In, Bit>,
            pub y0_x: Signal<Out, Bits<$W>>,
            pub y0_e: Signal<Out, Bits<$W>>,
            pub y1_x: Signal<Out, Bits<$W>>,
            pub y1_e: Signal<Out, Bits<$W>>,
            pub y2_x: Signal<Out, Bits<$W>>,
            pub y2_e: Signal<Out, Bits<$W>>,
            c_one: Constant<Bits<$W>>,
            c_two: Constant<Bits<$W>>,
            c_inf: Constant<Bits<$W>>,
            bu: BoundAdd,
            bv: BoundAdd,
            uv: BoundAdd,
            t: BoundMul,
            w: BoundAdd,
            q: BoundMul,
            g: BoundMul,
            eg: [BoundAdd; 3],
            eta_wait: Delay<Bits<$W>, 17>,
            two_lambda_wait: Delay<Bits<$W>, 22>,
            ok_wait: Delay<Bit, 27>,
            en_wait: Delay<Bit, 31>,
            x_wait: [Delay<Bits<$W>, 31>; 3],
            e_wait: [Delay<Bits<$W>, 27>; 3],
            e_pass: [Delay<Bits<$W>, 4>; 3],
        }

        impl Gap {
            pub const LATENCY: usize = 31;

            pub fn new() -> Self {
                let bias: u64 = (1u64 << ($E - 1)) - 1;
                let ones: u64 = (1u64 << $E) - 1;
                Self {
                    clock: Default::default(),
                    x0: Default::default(),
                    e0: Default::default(),
                    x1: Default::default(),
                    e1: Default::default(),
                    x2: Default::default(),
                    e2: Default::default(),
                    two_lambda: Default::default(),
                    eta: Default::default(),
                    ok: Default::default(),
                    en: Default::default(),
                    y0_x: Default::default(),
                    y0_e: Default::default(),
                    y1_x: Default::default(),
                    y1_e: Default::default(),
                    y2_x: Default::default(),
                    y2_e: Default::default(),
                    c_one: Constant::new(pattern(bias, 0)),
                    c_two: Constant::new(pattern(bias + 1, 0)),
                    c_inf: Constant::new(pattern(ones, 0)),
                    bu: BoundAdd::new(),
                    bv: BoundAdd::new(),
                    uv: BoundAdd::new(),
                    t: BoundMul::new(),
                    w: BoundAdd::new(),
                    q: BoundMul::new(),
                    g: BoundMul::new(),
                    eg: std::array::from_fn(|_| BoundAdd::new()),
                    eta_wait: Default::default(),
                    two_lambda_wait: Default::default(),
                    ok_wait: Default::default(),
                    en_wait: Default::default(),
                    x_wait: Default::default(),
                    e_wait: Default::default(),
                    e_pass: Default::default(),
                }
            }
        }

        impl Logic for Gap {
            #[hdl_gen]
            fn update(&mut self) {
                clock!(self, clock, bu, bv, uv, t, w, q, g, eta_wait, two_lambda_wait, ok_wait, en_wait);
                self.bu.a.next = bit_cast::<$W, $WM1>(self.x0.val().get_bits::<$WM1>(0));
                self.bu.b.next = self.e0.val();
                self.bu.valid_in.next = false;
                self.bv.a.next = bit_cast::<$W, $WM1>(self.x1.val().get_bits::<$WM1>(0));
                self.bv.b.next = self.e1.val();
                self.bv.valid_in.next = false;
                self.uv.a.next = self.bu.y.val();
                self.uv.b.next = self.bv.y.val();
                self.uv.valid_in.next = false;
                self.t.a.next = self.c_two.val();
                self.t.b.next = self.uv.y.val();
                self.t.valid_in.next = false;
                self.w.a.next = self.c_one.val();
                self.w.b.next = self.t.y.val();
                self.w.valid_in.next = false;
                self.eta_wait.d.next = self.eta.val();
                self.q.a.next = self.eta_wait.q.val();
                self.q.b.next = self.w.y.val();
                self.q.valid_in.next = false;
                self.two_lambda_wait.d.next = self.two_lambda.val();
                self.g.a.next = self.two_lambda_wait.q.val();
                self.g.b.next = self.q.y.val();
                self.g.valid_in.next = false;
                self.ok_wait.d.next = self.ok.val();
                self.en_wait.d.next = self.en.val();
                self.x_wait[0].d.next = self.x0.val();
                self.e_wait[0].d.next = self.e0.val();
                self.x_wait[1].d.next = self.x1.val();
                self.e_wait[1].d.next = self.e1.val();
                self.x_wait[2].d.next = self.x2.val();
                self.e_wait[2].d.next = self.e2.val();
                for k in 0..3 {
                    self.eg[k].clock.next = self.clock.val();
                    self.x_wait[k].clock.next = self.clock.val();
                    self.e_wait[k].clock.next = self.clock.val();
                    self.e_pass[k].clock.next = self.clock.val();
                    self.e_pass[k].d.next = self.e_wait[k].q.val();
                    self.eg[k].a.next = self.e_wait[k].q.val();
                    self.eg[k].b.next = self.g.y.val();
                    if !self.ok_wait.q.val() {
                        self.eg[k].b.next = self.c_inf.val();
                    }
                    self.eg[k].valid_in.next = false;
                }
                self.y0_x.next = self.x_wait[0].q.val();
                self.y0_e.next = self.e_pass[0].q.val();
                if self.en_wait.q.val() {
                    self.y0_e.next = self.eg[0].y.val();
                }
                self.y1_x.next = self.x_wait[1].q.val();
                self.y1_e.next = self.e_pass[1].q.val();
                if self.en_wait.q.val() {
                    self.y1_e.next = self.eg[1].y.val();
                }
                self.y2_x.next = self.x_wait[2].q.val();
                self.y2_e.next = self.e_pass[2].q.val();
                if self.en_wait.q.val() {
                    self.y2_e.next = self.eg[2].y.val();
                }
            }
        }

        /// Stages 3-5 for one edge P -> Q of the mapped triangle (Eq. 9 and the derived
        /// crossing test, golden `edges`): `a = Px Qz - Qx Pz`, `b = Py Qz - Qy Pz`,
        /// `r_z = Qz - Pz`, `s = (a + b) - r_z`, then three-valued signs and
        /// `crossing = (Pz<0, Qz>0, r_z>0, a>0, b>0, s<0) or (Pz>0, Qz<0, r_z<0, a<0, b<0, s>0)`
        /// in Kleene logic: `cross_t` (surely crosses), `cross_f` (surely misses).
        ///
        /// Schedule: products after edge 13 (`Pz`, `Qz` wait 13 for `rz`); `a`, `b`, `rz`
        /// 21; `ab` = a + b 29 (`rz` waits 8); `s` 37. Each sign is taken when its value
        /// is ready and its two bits wait for `s`. Latency [`Edge::LATENCY`] = 37 (outputs
        /// combinational after the last adder). Ports: in `clock`, `p0_x`, `p0_e` .. `p2_e`
        /// (P's coordinates and bounds), `q0_x` .. `q2_e`; out `s_x`, `s_e`, `cross_t`,
        /// `cross_f`.
        #[derive(LogicBlock)]
        pub struct Edge {
            pub clock: Signal<In, Clock>,
            pub p0_x: Signal<In, Bits<$W>>,
            pub p0_e: Signal<In, Bits<$W>>,
            pub p1_x: Signal<In, Bits<$W>>,
            pub p1_e: Signal<In, Bits<$W>>,
            pub p2_x: Signal<In, Bits<$W>>,
            pub p2_e: Signal<In, Bits<$W>>,
            pub q0_x: Signal<In, Bits<$W>>,
            pub q0_e: Signal<In, Bits<$W>>,
            pub q1_x: Signal<In, Bits<$W>>,
            pub q1_e: Signal<In, Bits<$W>>,
            pub q2_x: Signal<In, Bits<$W>>,
            pub q2_e: Signal<In, Bits<$W>>,
            pub s_x: Signal<Out, Bits<$W>>,
            pub s_e: Signal<Out, Bits<$W>>,
            pub cross_t: Signal<Out, Bit>,
            pub cross_f: Signal<Out, Bit>,
            px_qz: BMul,
            qx_pz: BMul,
            py_qz: BMul,
            qy_pz: BMul,
            pz_x_wait: Delay<Bits<$W>, 13>,
            pz_e_wait: Delay<Bits<$W>, 13>,
            qz_x_wait: Delay<Bits<$W>, 13>,
            qz_e_wait: Delay<Bits<$W>, 13>,
            a: BAdd,
            b: BAdd,
            rz: BAdd,
            ab: BAdd,
            rz_x_wait: Delay<Bits<$W>, 8>,
            rz_e_wait: Delay<Bits<$W>, 8>,
            s: BAdd,
            sign_pz: Sign,
            sign_qz: Sign,
            sign_rz: Sign,
            sign_a: Sign,
            sign_b: Sign,
            sign_s: Sign,
            pz_sgn_wait: Delay<Bits<2>, 37>,
            qz_sgn_wait: Delay<Bits<2>, 37>,
            rz_sgn_wait: Delay<Bits<2>, 16>,
            a_sgn_wait: Delay<Bits<2>, 16>,
            b_sgn_wait: Delay<Bits<2>, 16>,
            pz_p: Signal<Local, Bit>,
            pz_n: Signal<Local, Bit>,
            qz_p: Signal<Local, Bit>,
            qz_n: Signal<Local, Bit>,
            rz_p: Signal<Local, Bit>,
            rz_n: Signal<Local, Bit>,
            a_p: Signal<Local, Bit>,
            a_n: Signal<Local, Bit>,
            b_p: Signal<Local, Bit>,
            b_n: Signal<Local, Bit>,
            s_p: Signal<Local, Bit>,
            s_n: Signal<Local, Bit>,
        }

        impl Edge {
            pub const LATENCY: usize = BMul::LATENCY + 3 * BAdd::LATENCY;

            pub fn new(rounding: Rounding) -> Self {
                Self {
                    clock: Default::default(),
                    p0_x: Default::default(),
                    p0_e: Default::default(),
                    p1_x: Default::default(),
                    p1_e: Default::default(),
                    p2_x: Default::default(),
                    p2_e: Default::default(),
                    q0_x: Default::default(),
                    q0_e: Default::default(),
                    q1_x: Default::default(),
                    q1_e: Default::default(),
                    q2_x: Default::default(),
                    q2_e: Default::default(),
                    s_x: Default::default(),
                    s_e: Default::default(),
                    cross_t: Default::default(),
                    cross_f: Default::default(),
                    px_qz: BMul::new(rounding),
                    qx_pz: BMul::new(rounding),
                    py_qz: BMul::new(rounding),
                    qy_pz: BMul::new(rounding),
                    pz_x_wait: Default::default(),
                    pz_e_wait: Default::default(),
                    qz_x_wait: Default::default(),
                    qz_e_wait: Default::default(),
                    a: BAdd::new(rounding),
                    b: BAdd::new(rounding),
                    rz: BAdd::new(rounding),
                    ab: BAdd::new(rounding),
                    rz_x_wait: Default::default(),
                    rz_e_wait: Default::default(),
                    s: BAdd::new(rounding),
                    sign_pz: Sign::new(),
                    sign_qz: Sign::new(),
                    sign_rz: Sign::new(),
                    sign_a: Sign::new(),
                    sign_b: Sign::new(),
                    sign_s: Sign::new(),
                    pz_sgn_wait: Default::default(),
                    qz_sgn_wait: Default::default(),
                    rz_sgn_wait: Default::default(),
                    a_sgn_wait: Default::default(),
                    b_sgn_wait: Default::default(),
                    pz_p: Default::default(),
                    pz_n: Default::default(),
                    qz_p: Default::default(),
                    qz_n: Default::default(),
                    rz_p: Default::default(),
                    rz_n: Default::default(),
                    a_p: Default::default(),
                    a_n: Default::default(),
                    b_p: Default::default(),
                    b_n: Default::default(),
                    s_p: Default::default(),
                    s_n: Default::default(),
                }
            }
        }

        impl Logic for Edge {
            #[hdl_gen]
            fn update(&mut self) {
                clock!(self, clock, px_qz, qx_pz, py_qz, qy_pz, pz_x_wait, pz_e_wait, qz_x_wait, qz_e_wait);
                clock!(self, clock, a, b, rz, ab, rz_x_wait, rz_e_wait, s);
                clock!(self, clock, pz_sgn_wait, qz_sgn_wait, rz_sgn_wait, a_sgn_wait, b_sgn_wait);
                // ---- stage 3: products, then a, b, r_z
                self.px_qz.ax.next = self.p0_x.val();
                self.px_qz.ae.next = self.p0_e.val();
                self.px_qz.bx.next = self.q2_x.val();
                self.px_qz.be.next = self.q2_e.val();
                self.qx_pz.ax.next = self.q0_x.val();
                self.qx_pz.ae.next = self.q0_e.val();
                self.qx_pz.bx.next = self.p2_x.val();
                self.qx_pz.be.next = self.p2_e.val();
                self.py_qz.ax.next = self.p1_x.val();
                self.py_qz.ae.next = self.p1_e.val();
                self.py_qz.bx.next = self.q2_x.val();
                self.py_qz.be.next = self.q2_e.val();
                self.qy_pz.ax.next = self.q1_x.val();
                self.qy_pz.ae.next = self.q1_e.val();
                self.qy_pz.bx.next = self.p2_x.val();
                self.qy_pz.be.next = self.p2_e.val();
                self.a.ax.next = self.px_qz.x.val();
                self.a.ae.next = self.px_qz.e.val();
                self.a.bx.next = self.qx_pz.x.val();
                self.a.be.next = self.qx_pz.e.val();
                self.a.sub.next = true;
                self.b.ax.next = self.py_qz.x.val();
                self.b.ae.next = self.py_qz.e.val();
                self.b.bx.next = self.qy_pz.x.val();
                self.b.be.next = self.qy_pz.e.val();
                self.b.sub.next = true;
                self.pz_x_wait.d.next = self.p2_x.val();
                self.pz_e_wait.d.next = self.p2_e.val();
                self.qz_x_wait.d.next = self.q2_x.val();
                self.qz_e_wait.d.next = self.q2_e.val();
                self.rz.ax.next = self.qz_x_wait.q.val();
                self.rz.ae.next = self.qz_e_wait.q.val();
                self.rz.bx.next = self.pz_x_wait.q.val();
                self.rz.be.next = self.pz_e_wait.q.val();
                self.rz.sub.next = true;
                // ---- stage 4: s = (a + b) - r_z
                self.ab.ax.next = self.a.x.val();
                self.ab.ae.next = self.a.e.val();
                self.ab.bx.next = self.b.x.val();
                self.ab.be.next = self.b.e.val();
                self.ab.sub.next = false;
                self.rz_x_wait.d.next = self.rz.x.val();
                self.rz_e_wait.d.next = self.rz.e.val();
                self.s.ax.next = self.ab.x.val();
                self.s.ae.next = self.ab.e.val();
                self.s.bx.next = self.rz_x_wait.q.val();
                self.s.be.next = self.rz_e_wait.q.val();
                self.s.sub.next = true;
                // ---- stage 5: signs as they are ready, waiting for s's
                self.sign_pz.x.next = self.p2_x.val();
                self.sign_pz.e.next = self.p2_e.val();
                self.sign_qz.x.next = self.q2_x.val();
                self.sign_qz.e.next = self.q2_e.val();
                self.pz_sgn_wait.d.next = self.sign_pz.sgn.val();
                self.qz_sgn_wait.d.next = self.sign_qz.sgn.val();
                self.sign_rz.x.next = self.rz.x.val();
                self.sign_rz.e.next = self.rz.e.val();
                self.sign_a.x.next = self.a.x.val();
                self.sign_a.e.next = self.a.e.val();
                self.sign_b.x.next = self.b.x.val();
                self.sign_b.e.next = self.b.e.val();
                self.rz_sgn_wait.d.next = self.sign_rz.sgn.val();
                self.a_sgn_wait.d.next = self.sign_a.sgn.val();
                self.b_sgn_wait.d.next = self.sign_b.sgn.val();
                self.sign_s.x.next = self.s.x.val();
                self.sign_s.e.next = self.s.e.val();
                self.pz_p.next = self.pz_sgn_wait.q.val().get_bit(0);
                self.pz_n.next = self.pz_sgn_wait.q.val().get_bit(1);
                self.qz_p.next = self.qz_sgn_wait.q.val().get_bit(0);
                self.qz_n.next = self.qz_sgn_wait.q.val().get_bit(1);
                self.rz_p.next = self.rz_sgn_wait.q.val().get_bit(0);
                self.rz_n.next = self.rz_sgn_wait.q.val().get_bit(1);
                self.a_p.next = self.a_sgn_wait.q.val().get_bit(0);
                self.a_n.next = self.a_sgn_wait.q.val().get_bit(1);
                self.b_p.next = self.b_sgn_wait.q.val().get_bit(0);
                self.b_n.next = self.b_sgn_wait.q.val().get_bit(1);
                self.s_p.next = self.sign_s.sgn.val().get_bit(0);
                self.s_n.next = self.sign_s.sgn.val().get_bit(1);
                // P below, Q above | P above, Q below; a conjunction is surely false as
                // soon as one sign is surely wrong.
                self.cross_t.next = (self.pz_n.val() & self.qz_p.val() & self.rz_p.val() & self.a_p.val() & self.b_p.val() & self.s_n.val())
                    | (self.pz_p.val() & self.qz_n.val() & self.rz_n.val() & self.a_n.val() & self.b_n.val() & self.s_p.val());
                self.cross_f.next = (self.pz_p.val() | self.qz_n.val() | self.rz_n.val() | self.a_n.val() | self.b_n.val() | self.s_p.val())
                    & (self.pz_n.val() | self.qz_p.val() | self.rz_p.val() | self.a_p.val() | self.b_p.val() | self.s_n.val());
                self.s_x.next = self.s.x.val();
                self.s_e.next = self.s.e.val();
            }
        }

        /// T.CHECK: do the edges of triangle A cross the unit triangle of B's leaf? (DATE'05
        /// §4.2; golden [`stage1`](crate::golden::tcheck::stage1) then
        /// [`edges`](crate::golden::tcheck::edges), bit for bit.) One triangle pair per
        /// clock, latency [`TCheck::LATENCY`] = 128:
        ///
        /// | clocks | stage | blocks |
        /// |---|---|---|
        /// | 1 | input register | `in_*` |
        /// | 2-30 | 1: M_b = M_B M_AB (Eqs. 11, 12) | `mb_0..2[j]` ([`AffRow`], j = 3 affine) |
        /// | 31-59 | 2: mapped vertices V'_k (Eq. 13) | `vt_0..2[k]` (row i, vertex k) |
        /// | 60-90 | vertex gap (`gap_en`) | `gap[k]` ([`Gap`]) |
        /// | 91-127 | 3, 4: a, b, r_z, s per edge (Eq. 9) | `edges[0..2]` ([`Edge`]) |
        /// | 128 | 5: crossing per edge, OR over the edges; output register | `out_*` |
        ///
        /// Beside the values, lambda = l_norm + e_lin, `two_lambda` = 2 lambda and
        /// `ok` = (4 lambda) eta <= 1/2 (clocks 2-15), the vertices' bounds (0 if
        /// `v_exact`, else err(v) to nearest) and the tag wait in delay lines.
        ///
        /// Ports, all words in the format (bounds are bound-unit words):
        /// in `m_0[4]`, `m_1[4]`, `m_2[4]` (rows of B's M_B), `e_lin`, `e_tr`, `l_norm`
        /// (its bounds and norm), `f_0[4]`, `f_1[4]`, `f_2[4]` (rows of the frame map
        /// M_AB), `f_lin`, `f_tr` (its bounds), `eta`, `gap_en`, `v_x[3]`, `v_y[3]`, `v_z[3]`
        /// (A's vertices), `v_exact`, `tag[32]`, `valid_in`;
        /// out `s_x[3]`, `s_e[3]` (stage 4's s per edge), `cross_t[3]`, `cross_f[3]`,
        /// `hit` (surely crosses), `miss` (surely does not), `tag_out`, `valid_out`.
        #[derive(LogicBlock)]
        pub struct TCheck {
            pub clock: Signal<In, Clock>,
            pub m_0: [Signal<In, Bits<$W>>; 4],
            pub m_1: [Signal<In, Bits<$W>>; 4],
            pub m_2: [Signal<In, Bits<$W>>; 4],
            pub e_lin: Signal<In, Bits<$W>>,
            pub e_tr: Signal<In, Bits<$W>>,
            pub l_norm: Signal<In, Bits<$W>>,
            pub f_0: [Signal<In, Bits<$W>>; 4],
            pub f_1: [Signal<In, Bits<$W>>; 4],
            pub f_2: [Signal<In, Bits<$W>>; 4],
            pub f_lin: Signal<In, Bits<$W>>,
            pub f_tr: Signal<In, Bits<$W>>,
            pub eta: Signal<In, Bits<$W>>,
            pub gap_en: Signal<In, Bit>,
            pub v_x: [Signal<In, Bits<$W>>; 3],
            pub v_y: [Signal<In, Bits<$W>>; 3],
            pub v_z: [Signal<In, Bits<$W>>; 3],
            pub v_exact: Signal<In, Bit>,
            pub tag: Signal<In, Bits<32>>,
            pub valid_in: Signal<In, Bit>,
            pub s_x: [Signal<Out, Bits<$W>>; 3],
            pub s_e: [Signal<Out, Bits<$W>>; 3],
            pub cross_t: [Signal<Out, Bit>; 3],
            pub cross_f: [Signal<Out, Bit>; 3],
            pub hit: Signal<Out, Bit>,
            pub miss: Signal<Out, Bit>,
            pub tag_out: Signal<Out, Bits<32>>,
            pub valid_out: Signal<Out, Bit>,
            c_two: Constant<Bits<$W>>,
            c_four: Constant<Bits<$W>>,
            c_half: Constant<Bits<$W>>,
            c_zero: Constant<Bits<$W>>,
            // clock 1: input register
            in_m_0: [DFF<Bits<$W>>; 4],
            in_m_1: [DFF<Bits<$W>>; 4],
            in_m_2: [DFF<Bits<$W>>; 4],
            in_e_lin: DFF<Bits<$W>>,
            in_e_tr: DFF<Bits<$W>>,
            in_l_norm: DFF<Bits<$W>>,
            in_f_0: [DFF<Bits<$W>>; 4],
            in_f_1: [DFF<Bits<$W>>; 4],
            in_f_2: [DFF<Bits<$W>>; 4],
            in_f_lin: DFF<Bits<$W>>,
            in_f_tr: DFF<Bits<$W>>,
            in_eta: DFF<Bits<$W>>,
            in_gap_en: DFF<Bit>,
            in_v_x: [DFF<Bits<$W>>; 3],
            in_v_y: [DFF<Bits<$W>>; 3],
            in_v_z: [DFF<Bits<$W>>; 3],
            in_v_exact: DFF<Bit>,
            in_tag: DFF<Bits<32>>,
            in_valid: DFF<Bit>,
            // stage 1: row i of M_b, column j
            mb_0: [AffRow; 4],
            mb_1: [AffRow; 4],
            mb_2: [AffRow; 4],
            // the vertices and their bounds wait for M_b
            v_err_x: [RoundErr; 3],
            v_err_y: [RoundErr; 3],
            v_err_z: [RoundErr; 3],
            v_x_wait: [Delay<Bits<$W>, 29>; 3],
            v_y_wait: [Delay<Bits<$W>, 29>; 3],
            v_z_wait: [Delay<Bits<$W>, 29>; 3],
            v_ex_wait: [Delay<Bits<$W>, 28>; 3],
            v_ey_wait: [Delay<Bits<$W>, 28>; 3],
            v_ez_wait: [Delay<Bits<$W>, 28>; 3],
            v_exact_wait: Delay<Bit, 29>,
            c_ve_x: [Signal<Local, Bits<$W>>; 3],
            c_ve_y: [Signal<Local, Bits<$W>>; 3],
            c_ve_z: [Signal<Local, Bits<$W>>; 3],
            // stage 2: coordinate i of vertex k
            vt_0: [AffRow; 3],
            vt_1: [AffRow; 3],
            vt_2: [AffRow; 3],
            // the gap's leaf terms (clocks 2-15) wait for the mapped vertices
            lambda: BoundAdd,
            two_lambda: BoundMul,
            four_lambda: BoundMul,
            reach: BoundMul,
            eta_early: Delay<Bits<$W>, 9>,
            eta_wait: Delay<Bits<$W>, 58>,
            two_lambda_wait: Delay<Bits<$W>, 49>,
            ok_wait: Delay<Bit, 44>,
            gap_en_wait: Delay<Bit, 58>,
            gap: [Gap; 3],
            // stages 3-5
            edges: [Edge; 3],
            tag_wait: Delay<Bits<32>, 126>,
            valid_wait: Delay<Bit, 126>,
            hit_any: Signal<Local, Bit>,
            miss_all: Signal<Local, Bit>,
            out_s_x: [DFF<Bits<$W>>; 3],
            out_s_e: [DFF<Bits<$W>>; 3],
            out_cross_t: [DFF<Bit>; 3],
            out_cross_f: [DFF<Bit>; 3],
            out_hit: DFF<Bit>,
            out_miss: DFF<Bit>,
            out_tag: DFF<Bits<32>>,
            out_valid: DFF<Bit>,
        }

        impl TCheck {
            pub const LATENCY: usize = 1 + 2 * AffRow::LATENCY + Gap::LATENCY + Edge::LATENCY + 1;

            /// A T.CHECK whose value datapath rounds with `rounding` (NearestEven or
            /// TowardPositive; the bound units always round to nearest and step up).
            pub fn new(rounding: Rounding) -> Self {
                let bias: u64 = (1u64 << ($E - 1)) - 1;
                Self {
                    clock: Default::default(),
                    m_0: Default::default(),
                    m_1: Default::default(),
                    m_2: Default::default(),
                    e_lin: Default::default(),
                    e_tr: Default::default(),
                    l_norm: Default::default(),
                    f_0: Default::default(),
                    f_1: Default::default(),
                    f_2: Default::default(),
                    f_lin: Default::default(),
                    f_tr: Default::default(),
                    eta: Default::default(),
                    gap_en: Default::default(),
                    v_x: Default::default(),
                    v_y: Default::default(),
                    v_z: Default::default(),
                    v_exact: Default::default(),
                    tag: Default::default(),
                    valid_in: Default::default(),
                    s_x: Default::default(),
                    s_e: Default::default(),
                    cross_t: Default::default(),
                    cross_f: Default::default(),
                    hit: Default::default(),
                    miss: Default::default(),
                    tag_out: Default::default(),
                    valid_out: Default::default(),
                    c_two: Constant::new(pattern(bias + 1, 0)),
                    c_four: Constant::new(pattern(bias + 2, 0)),
                    c_half: Constant::new(pattern(bias - 1, 0)),
                    c_zero: Constant::new(0u64.into()),
                    in_m_0: Default::default(),
                    in_m_1: Default::default(),
                    in_m_2: Default::default(),
                    in_e_lin: Default::default(),
                    in_e_tr: Default::default(),
                    in_l_norm: Default::default(),
                    in_f_0: Default::default(),
                    in_f_1: Default::default(),
                    in_f_2: Default::default(),
                    in_f_lin: Default::default(),
                    in_f_tr: Default::default(),
                    in_eta: Default::default(),
                    in_gap_en: Default::default(),
                    in_v_x: Default::default(),
                    in_v_y: Default::default(),
                    in_v_z: Default::default(),
                    in_v_exact: Default::default(),
                    in_tag: Default::default(),
                    in_valid: Default::default(),
                    mb_0: std::array::from_fn(|j| AffRow::new(rounding, j == 3)),
                    mb_1: std::array::from_fn(|j| AffRow::new(rounding, j == 3)),
                    mb_2: std::array::from_fn(|j| AffRow::new(rounding, j == 3)),
                    v_err_x: std::array::from_fn(|_| RoundErr::new(Rounding::NearestEven)),
                    v_err_y: std::array::from_fn(|_| RoundErr::new(Rounding::NearestEven)),
                    v_err_z: std::array::from_fn(|_| RoundErr::new(Rounding::NearestEven)),
                    v_x_wait: Default::default(),
                    v_y_wait: Default::default(),
                    v_z_wait: Default::default(),
                    v_ex_wait: Default::default(),
                    v_ey_wait: Default::default(),
                    v_ez_wait: Default::default(),
                    v_exact_wait: Default::default(),
                    c_ve_x: Default::default(),
                    c_ve_y: Default::default(),
                    c_ve_z: Default::default(),
                    vt_0: std::array::from_fn(|_| AffRow::new(rounding, true)),
                    vt_1: std::array::from_fn(|_| AffRow::new(rounding, true)),
                    vt_2: std::array::from_fn(|_| AffRow::new(rounding, true)),
                    lambda: BoundAdd::new(),
                    two_lambda: BoundMul::new(),
                    four_lambda: BoundMul::new(),
                    reach: BoundMul::new(),
                    eta_early: Default::default(),
                    eta_wait: Default::default(),
                    two_lambda_wait: Default::default(),
                    ok_wait: Default::default(),
                    gap_en_wait: Default::default(),
                    gap: std::array::from_fn(|_| Gap::new()),
                    edges: std::array::from_fn(|_| Edge::new(rounding)),
                    tag_wait: Default::default(),
                    valid_wait: Default::default(),
                    hit_any: Default::default(),
                    miss_all: Default::default(),
                    out_s_x: Default::default(),
                    out_s_e: Default::default(),
                    out_cross_t: Default::default(),
                    out_cross_f: Default::default(),
                    out_hit: Default::default(),
                    out_miss: Default::default(),
                    out_tag: Default::default(),
                    out_valid: Default::default(),
                }
            }
        }

        impl Logic for TCheck {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, in_e_lin, in_e_tr, in_l_norm, in_f_lin, in_f_tr, in_eta, in_gap_en, in_v_exact, in_tag, in_valid);
                dff_setup!(self, clock, out_hit, out_miss, out_tag, out_valid);
                clock!(self, clock, v_exact_wait, lambda, two_lambda, four_lambda, reach, eta_early, eta_wait);
                clock!(self, clock, two_lambda_wait, ok_wait, gap_en_wait, tag_wait, valid_wait);
                // ---- clock 1: input register
                for c in 0..4 {
                    self.in_m_0[c].clock.next = self.clock.val();
                    self.in_m_1[c].clock.next = self.clock.val();
                    self.in_m_2[c].clock.next = self.clock.val();
                    self.in_f_0[c].clock.next = self.clock.val();
                    self.in_f_1[c].clock.next = self.clock.val();
                    self.in_f_2[c].clock.next = self.clock.val();
                    self.in_m_0[c].d.next = self.m_0[c].val();
                    self.in_m_1[c].d.next = self.m_1[c].val();
                    self.in_m_2[c].d.next = self.m_2[c].val();
                    self.in_f_0[c].d.next = self.f_0[c].val();
                    self.in_f_1[c].d.next = self.f_1[c].val();
                    self.in_f_2[c].d.next = self.f_2[c].val();
                }
                self.in_e_lin.d.next = self.e_lin.val();
                self.in_e_tr.d.next = self.e_tr.val();
                self.in_l_norm.d.next = self.l_norm.val();
                self.in_f_lin.d.next = self.f_lin.val();
                self.in_f_tr.d.next = self.f_tr.val();
                self.in_eta.d.next = self.eta.val();
                self.in_gap_en.d.next = self.gap_en.val();
                self.in_v_exact.d.next = self.v_exact.val();
                self.in_tag.d.next = self.tag.val();
                self.in_valid.d.next = self.valid_in.val();
                // ---- stage 1: Mb_ij = (m_i0 f_0j + m_i1 f_1j) + m_i2 f_2j  (j < 3)
                //               Mb_i3 = (m_i0 f_03 + m_i1 f_13) + (m_i2 f_23 + m_i3)
                $(
                for j in 0..4 {
                    self.$mb[j].clock.next = self.clock.val();
                    self.$mb[j].a0_x.next = self.$in_m[0].q.val();
                    self.$mb[j].a1_x.next = self.$in_m[1].q.val();
                    self.$mb[j].a2_x.next = self.$in_m[2].q.val();
                    self.$mb[j].a0_e.next = self.in_e_lin.q.val();
                    self.$mb[j].a1_e.next = self.in_e_lin.q.val();
                    self.$mb[j].a2_e.next = self.in_e_lin.q.val();
                    self.$mb[j].b0_x.next = self.in_f_0[j].q.val();
                    self.$mb[j].b1_x.next = self.in_f_1[j].q.val();
                    self.$mb[j].b2_x.next = self.in_f_2[j].q.val();
                    self.$mb[j].b0_e.next = self.in_f_lin.q.val();
                    self.$mb[j].b1_e.next = self.in_f_lin.q.val();
                    self.$mb[j].b2_e.next = self.in_f_lin.q.val();
                    self.$mb[j].c_x.next = self.$in_m[3].q.val();
                    self.$mb[j].c_e.next = self.in_e_tr.q.val();
                }
                // the translation column's operands from the frame carry f_tr
                self.$mb[3].b0_e.next = self.in_f_tr.q.val();
                self.$mb[3].b1_e.next = self.in_f_tr.q.val();
                self.$mb[3].b2_e.next = self.in_f_tr.q.val();
                )*
                // ---- the vertices wait for M_b; their bound: 0 if exact, else err(v) to nearest
                self.v_exact_wait.d.next = self.in_v_exact.q.val();
                for k in 0..3 {
                    self.in_v_x[k].clock.next = self.clock.val();
                    self.in_v_y[k].clock.next = self.clock.val();
                    self.in_v_z[k].clock.next = self.clock.val();
                    self.in_v_x[k].d.next = self.v_x[k].val();
                    self.in_v_y[k].d.next = self.v_y[k].val();
                    self.in_v_z[k].d.next = self.v_z[k].val();
                    self.v_err_x[k].clock.next = self.clock.val();
                    self.v_err_y[k].clock.next = self.clock.val();
                    self.v_err_z[k].clock.next = self.clock.val();
                    self.v_x_wait[k].clock.next = self.clock.val();
                    self.v_y_wait[k].clock.next = self.clock.val();
                    self.v_z_wait[k].clock.next = self.clock.val();
                    self.v_ex_wait[k].clock.next = self.clock.val();
                    self.v_ey_wait[k].clock.next = self.clock.val();
                    self.v_ez_wait[k].clock.next = self.clock.val();
                    self.v_err_x[k].x.next = self.in_v_x[k].q.val();
                    self.v_err_y[k].x.next = self.in_v_y[k].q.val();
                    self.v_err_z[k].x.next = self.in_v_z[k].q.val();
                    self.v_err_x[k].valid_in.next = false;
                    self.v_err_y[k].valid_in.next = false;
                    self.v_err_z[k].valid_in.next = false;
                    self.v_x_wait[k].d.next = self.in_v_x[k].q.val();
                    self.v_y_wait[k].d.next = self.in_v_y[k].q.val();
                    self.v_z_wait[k].d.next = self.in_v_z[k].q.val();
                    self.v_ex_wait[k].d.next = self.v_err_x[k].y.val();
                    self.v_ey_wait[k].d.next = self.v_err_y[k].y.val();
                    self.v_ez_wait[k].d.next = self.v_err_z[k].y.val();
                    self.c_ve_x[k].next = self.v_ex_wait[k].q.val();
                    self.c_ve_y[k].next = self.v_ey_wait[k].q.val();
                    self.c_ve_z[k].next = self.v_ez_wait[k].q.val();
                    if self.v_exact_wait.q.val() {
                        self.c_ve_x[k].next = self.c_zero.val();
                        self.c_ve_y[k].next = self.c_zero.val();
                        self.c_ve_z[k].next = self.c_zero.val();
                    }
                }
                // ---- stage 2: V'_ik = (Mb_i0 x_k + Mb_i1 y_k) + (Mb_i2 z_k + Mb_i3)
                $(
                for k in 0..3 {
                    self.$vt[k].clock.next = self.clock.val();
                    self.$vt[k].a0_x.next = self.$mb[0].y_x.val();
                    self.$vt[k].a0_e.next = self.$mb[0].y_e.val();
                    self.$vt[k].a1_x.next = self.$mb[1].y_x.val();
                    self.$vt[k].a1_e.next = self.$mb[1].y_e.val();
                    self.$vt[k].a2_x.next = self.$mb[2].y_x.val();
                    self.$vt[k].a2_e.next = self.$mb[2].y_e.val();
                    self.$vt[k].c_x.next = self.$mb[3].y_x.val();
                    self.$vt[k].c_e.next = self.$mb[3].y_e.val();
                    self.$vt[k].b0_x.next = self.v_x_wait[k].q.val();
                    self.$vt[k].b0_e.next = self.c_ve_x[k].val();
                    self.$vt[k].b1_x.next = self.v_y_wait[k].q.val();
                    self.$vt[k].b1_e.next = self.c_ve_y[k].val();
                    self.$vt[k].b2_x.next = self.v_z_wait[k].q.val();
                    self.$vt[k].b2_e.next = self.c_ve_z[k].val();
                    self.gap[k].$gx.next = self.$vt[k].y_x.val();
                    self.gap[k].$ge.next = self.$vt[k].y_e.val();
                }
                )*
                // ---- the gap's leaf terms: lambda = l_norm + e_lin, 2 lambda, (4 lambda) eta <= 1/2
                self.lambda.a.next = self.in_l_norm.q.val();
                self.lambda.b.next = self.in_e_lin.q.val();
                self.lambda.valid_in.next = false;
                self.two_lambda.a.next = self.c_two.val();
                self.two_lambda.b.next = self.lambda.y.val();
                self.two_lambda.valid_in.next = false;
                self.four_lambda.a.next = self.c_four.val();
                self.four_lambda.b.next = self.lambda.y.val();
                self.four_lambda.valid_in.next = false;
                self.eta_early.d.next = self.in_eta.q.val();
                self.reach.a.next = self.four_lambda.y.val();
                self.reach.b.next = self.eta_early.q.val();
                self.reach.valid_in.next = false;
                self.ok_wait.d.next = self.reach.y.val() <= self.c_half.val();
                self.two_lambda_wait.d.next = self.two_lambda.y.val();
                self.eta_wait.d.next = self.in_eta.q.val();
                self.gap_en_wait.d.next = self.in_gap_en.q.val();
                for k in 0..3 {
                    self.gap[k].clock.next = self.clock.val();
                    self.gap[k].two_lambda.next = self.two_lambda_wait.q.val();
                    self.gap[k].eta.next = self.eta_wait.q.val();
                    self.gap[k].ok.next = self.ok_wait.q.val();
                    self.gap[k].en.next = self.gap_en_wait.q.val();
                }
                // ---- stages 3-5: edges V0V1, V1V2, V2V0
                self.edges[0].p0_x.next = self.gap[0].y0_x.val();
                self.edges[0].q0_x.next = self.gap[1].y0_x.val();
                self.edges[0].p0_e.next = self.gap[0].y0_e.val();
                self.edges[0].q0_e.next = self.gap[1].y0_e.val();
                self.edges[0].p1_x.next = self.gap[0].y1_x.val();
                self.edges[0].q1_x.next = self.gap[1].y1_x.val();
                self.edges[0].p1_e.next = self.gap[0].y1_e.val();
                self.edges[0].q1_e.next = self.gap[1].y1_e.val();
                self.edges[0].p2_x.next = self.gap[0].y2_x.val();
                self.edges[0].q2_x.next = self.gap[1].y2_x.val();
                self.edges[0].p2_e.next = self.gap[0].y2_e.val();
                self.edges[0].q2_e.next = self.gap[1].y2_e.val();
                self.edges[1].p0_x.next = self.gap[1].y0_x.val();
                self.edges[1].q0_x.next = self.gap[2].y0_x.val();
                self.edges[1].p0_e.next = self.gap[1].y0_e.val();
                self.edges[1].q0_e.next = self.gap[2].y0_e.val();
                self.edges[1].p1_x.next = self.gap[1].y1_x.val();
                self.edges[1].q1_x.next = self.gap[2].y1_x.val();
                self.edges[1].p1_e.next = self.gap[1].y1_e.val();
                self.edges[1].q1_e.next = self.gap[2].y1_e.val();
                self.edges[1].p2_x.next = self.gap[1].y2_x.val();
                self.edges[1].q2_x.next = self.gap[2].y2_x.val();
                self.edges[1].p2_e.next = self.gap[1].y2_e.val();
                self.edges[1].q2_e.next = self.gap[2].y2_e.val();
                self.edges[2].p0_x.next = self.gap[2].y0_x.val();
                self.edges[2].q0_x.next = self.gap[0].y0_x.val();
                self.edges[2].p0_e.next = self.gap[2].y0_e.val();
                self.edges[2].q0_e.next = self.gap[0].y0_e.val();
                self.edges[2].p1_x.next = self.gap[2].y1_x.val();
                self.edges[2].q1_x.next = self.gap[0].y1_x.val();
                self.edges[2].p1_e.next = self.gap[2].y1_e.val();
                self.edges[2].q1_e.next = self.gap[0].y1_e.val();
                self.edges[2].p2_x.next = self.gap[2].y2_x.val();
                self.edges[2].q2_x.next = self.gap[0].y2_x.val();
                self.edges[2].p2_e.next = self.gap[2].y2_e.val();
                self.edges[2].q2_e.next = self.gap[0].y2_e.val();
                self.tag_wait.d.next = self.in_tag.q.val();
                self.valid_wait.d.next = self.in_valid.q.val();
                // ---- stage 5: Kleene OR over the edges; output register
                self.hit_any.next = false;
                self.miss_all.next = true;
                for e in 0..3 {
                    self.edges[e].clock.next = self.clock.val();
                    self.out_s_x[e].clock.next = self.clock.val();
                    self.out_s_e[e].clock.next = self.clock.val();
                    self.out_cross_t[e].clock.next = self.clock.val();
                    self.out_cross_f[e].clock.next = self.clock.val();
                    self.out_s_x[e].d.next = self.edges[e].s_x.val();
                    self.out_s_e[e].d.next = self.edges[e].s_e.val();
                    self.out_cross_t[e].d.next = self.edges[e].cross_t.val();
                    self.out_cross_f[e].d.next = self.edges[e].cross_f.val();
                    if self.edges[e].cross_t.val() {
                        self.hit_any.next = true;
                    }
                    if !self.edges[e].cross_f.val() {
                        self.miss_all.next = false;
                    }
                    self.s_x[e].next = self.out_s_x[e].q.val();
                    self.s_e[e].next = self.out_s_e[e].q.val();
                    self.cross_t[e].next = self.out_cross_t[e].q.val();
                    self.cross_f[e].next = self.out_cross_f[e].q.val();
                }
                self.out_hit.d.next = self.hit_any.val();
                self.out_miss.d.next = self.miss_all.val();
                self.out_tag.d.next = self.tag_wait.q.val();
                self.out_valid.d.next = self.valid_wait.q.val();
                self.hit.next = self.out_hit.q.val();
                self.miss.next = self.out_miss.q.val();
                self.tag_out.next = self.out_tag.q.val();
                self.valid_out.next = self.out_valid.q.val();
            }
        }

        /// A T.CHECK ready to simulate as a top-level block (inputs claimed, connected).
        /// Large (about 10 MB in binary32): build it on a thread with a big stack.
        pub fn tcheck_top(rounding: Rounding) -> TCheck {
            let mut uut = TCheck::new(rounding);
            for c in 0..4 {
                uut.m_0[c].connect();
                uut.m_1[c].connect();
                uut.m_2[c].connect();
                uut.f_0[c].connect();
                uut.f_1[c].connect();
                uut.f_2[c].connect();
            }
            for k in 0..3 {
                uut.v_x[k].connect();
                uut.v_y[k].connect();
                uut.v_z[k].connect();
            }
            top_level!(uut; clock, e_lin, e_tr, l_norm, f_lin, f_tr, eta, gap_en, v_exact, tag, valid_in)
        }

        /// Verilog of T.CHECK (top module `top`).
        pub fn verilog_tcheck(rounding: Rounding) -> String {
            generate_verilog(&tcheck_top(rounding))
        }
    };
}
pub(crate) use tcheck;
