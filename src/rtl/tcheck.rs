//! T.CHECK (DATE'05 §4.2, Eqs. 8, 9, 11-13) with its certificate, stamped out per format
//! by `tcheck!`: the value datapath of the paper's five macro stages and, beside it, the
//! magnitudes and error bounds that decide which signs are sure (golden
//! [`golden::tcheck`](crate::golden::tcheck), docs/ARCHITECTURE.md "T.CHECK in RTL",
//! docs/ACCURACY.md "T.CHECK's certificate").

/// Stamps out `Sign`, `Dot`, `Vertex`, `Edge` and `TCheck` in the calling module (which
/// must also hold `FpMul`, `FpAdd` and `FORMAT`). Arguments: `W`, `WM1` = W-1, `E`, `F`.
macro_rules! tcheck {
    ($W:tt, $WM1:tt, $E:tt, $F:tt) => {
        // Row i of M_b (`mb_i`, `mg_i` its magnitude, `in_m_i` M_B's input register, the
        // R1 registers `mbr_i`, `mgr_i`) and coordinate i of the mapped vertices (`vt_i`,
        // `vm_i`, `m3_i`, the R2 registers `vtr_i`, `vmr_i`): the kernel's wiring is written
        // once per row by repetition (rust-hdl kernels allow one loop level only).
        $crate::rtl::tcheck::tcheck!(@units $W, $WM1, $E, $F;
            (mb_0 mg_0 in_m_0 c3_0 mbr_0 mgr_0 mg3_0 vc_0 vt_0 vm_0 m3_0 vtr_0 vmr_0)
            (mb_1 mg_1 in_m_1 c3_1 mbr_1 mgr_1 mg3_1 vc_1 vt_1 vm_1 m3_1 vtr_1 vmr_1)
            (mb_2 mg_2 in_m_2 c3_2 mbr_2 mgr_2 mg3_2 vc_2 vt_2 vm_2 m3_2 vtr_2 vmr_2));
    };
    (@units $W:tt, $WM1:tt, $E:tt, $F:tt; $(($mb:ident $mg:ident $in_m:ident $c3:ident $mbr:ident $mgr:ident $mg3:ident $vc:ident $vt:ident $vm:ident $m3:ident $vtr:ident $vmr:ident))*) => {
        use $crate::rtl::delay::Delay;

        /// All ones but the sign bit: a word ANDed with it is its absolute value.
        const ABS_MASK: u64 = (1u64 << $WM1) - 1;

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
                let r = if magnitude { Rounding::TowardPositive } else { rounding };
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
                    mask: Constant::new(if magnitude { ABS_MASK } else { ABS_MASK | (1u64 << $WM1) }.into()),
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

        /// The certificate's terms of one mapped vertex (golden `edges_in`, per vertex),
        /// from its z coordinate `z` and the magnitudes `m0..m2` of its coordinates, with
        /// constant multipliers ([`FpScale`]) and adders, rounded upward: the bounds
        /// `E_i = c_e m_i`, `E'_z = c_z m2` (c_z >= C_V + u + u^2, r_z's rounding, since
        /// m2 >= |z|), `G = E_z + c_s |z|` (c_s >= 2u + u^2, the rounding of a's and b's
        /// products) and `H = |z| + 2 E_z` (the doubling exact: E_z is 0, infinite or at
        /// least 2^emin, and far below the largest value). `exact` picks the constants of
        /// exact vertices.
        ///
        /// Schedule: `e` = E_z after edge 4 ([`Vertex::E_AT`]), `g` 7 ([`Vertex::G_AT`]),
        /// `f0`, `f1`, `f2` = E_x, E_y, E'_z 7 ([`Vertex::F_AT`]; ready at 4, they wait for
        /// H, which the edges pair them with), `h` 10 ([`Vertex::H_AT`]: |z| waits 4 for
        /// E_z, the sum 3 more). Ports: in `clock`, `z`, `m0` .. `m2`, `exact`; out `e`,
        /// `g`, `f0` .. `f2`, `h`.
        #[derive(LogicBlock)]
        pub struct Vertex {
            pub clock: Signal<In, Clock>,
            pub z: Signal<In, Bits<$W>>,
            pub m0: Signal<In, Bits<$W>>,
            pub m1: Signal<In, Bits<$W>>,
            pub m2: Signal<In, Bits<$W>>,
            pub exact: Signal<In, Bit>,
            pub e: Signal<Out, Bits<$W>>,
            pub g: Signal<Out, Bits<$W>>,
            pub f0: Signal<Out, Bits<$W>>,
            pub f1: Signal<Out, Bits<$W>>,
            pub f2: Signal<Out, Bits<$W>>,
            pub h: Signal<Out, Bits<$W>>,
            mask: Constant<Bits<$W>>,
            ef: [FpScale; 3],
            ez: FpScale,
            cz: FpScale,
            gz: FpAdd,
            e2z: Signal<Local, Bits<$W>>,
            c_one: Constant<Bits<$W>>,
            hz: FpAdd,
            f_wait: [Delay<Bits<$W>, { Vertex::F_AT - Vertex::E_AT }>; 3],
            z_wait: Delay<Bits<$W>, { Vertex::E_AT }>,
            h_wait: Delay<Bits<$W>, 3>,
        }

        impl Vertex {
            pub const E_AT: usize = FpScale::LATENCY;
            pub const G_AT: usize = 7;
            pub const F_AT: usize = 7;
            pub const H_AT: usize = 10;

            pub fn new(cert: &$crate::golden::certificate::Certificate) -> Self {
                let c = |c: [$crate::format::ScaleConst; 2]| FpScale::new(c[0], c[1]);
                Self {
                    clock: Default::default(),
                    z: Default::default(),
                    m0: Default::default(),
                    m1: Default::default(),
                    m2: Default::default(),
                    exact: Default::default(),
                    e: Default::default(),
                    g: Default::default(),
                    f0: Default::default(),
                    f1: Default::default(),
                    f2: Default::default(),
                    h: Default::default(),
                    mask: Constant::new(ABS_MASK.into()),
                    ef: [c(cert.c_e), c(cert.c_e), c(cert.c_z)],
                    ez: c(cert.c_e),
                    cz: FpScale::new(cert.c_s, cert.c_s),
                    gz: FpAdd::new(Rounding::TowardPositive),
                    e2z: Default::default(),
                    c_one: Constant::new((1u64 << $F).into()),
                    hz: FpAdd::new(Rounding::TowardPositive),
                    f_wait: Default::default(),
                    z_wait: Default::default(),
                    h_wait: Default::default(),
                }
            }
        }

        impl Logic for Vertex {
            #[hdl_gen]
            fn update(&mut self) {
                clock!(self, clock, ez, cz, gz, hz, z_wait, h_wait);
                for i in 0..3 {
                    self.ef[i].clock.next = self.clock.val();
                    self.ef[i].sel.next = self.exact.val();
                    self.f_wait[i].clock.next = self.clock.val();
                    self.f_wait[i].d.next = self.ef[i].y.val();
                }
                self.ef[0].a.next = self.m0.val();
                self.ef[1].a.next = self.m1.val();
                self.ef[2].a.next = self.m2.val();
                self.ez.a.next = self.m2.val();
                self.ez.sel.next = self.exact.val();
                self.cz.a.next = self.z.val();
                self.cz.sel.next = false;
                self.gz.a.next = self.ez.y.val();
                self.gz.b.next = self.cz.y.val();
                self.gz.sub.next = false;
                self.gz.valid_in.next = false;
                // 2 E_z: one more in the exponent field (0 and infinity stay)
                self.e2z.next = self.ez.y.val();
                if (self.ez.y.val().get_bits::<$E>($F) != 0) & !self.ez.y.val().get_bits::<$E>($F).all() {
                    self.e2z.next = self.ez.y.val() + self.c_one.val();
                }
                self.z_wait.d.next = self.z.val() & self.mask.val();
                self.hz.a.next = self.z_wait.q.val();
                self.hz.b.next = self.e2z.val();
                self.hz.sub.next = false;
                self.hz.valid_in.next = false;
                self.h_wait.d.next = self.hz.y.val();
                self.e.next = self.ez.y.val();
                self.g.next = self.gz.y.val();
                self.f0.next = self.f_wait[0].q.val();
                self.f1.next = self.f_wait[1].q.val();
                self.f2.next = self.f_wait[2].q.val();
                self.h.next = self.h_wait.q.val();
            }
        }

        /// Stages 3-5 for one edge P -> Q of the mapped triangle (Eq. 9 and the derived
        /// crossing test, golden `edges_in`): `a = Px Qz - Qx Pz`, `b = Py Qz - Qy Pz`,
        /// `r_z = Qz - Pz`, `s = (a + b) - r_z`; beside them, from the vertices' terms
        /// ([`Vertex`]), rounded upward: `B_a = (E_Px H_Qz + |Px| G_Qz) + (E_Qx H_Pz +
        /// |Qx| G_Pz)`, B_b the same with y, `B_rz = E'_Qz + E'_Pz`, `B_s = (B_a + B_b) +
        /// (B_rz + c_s (|a| + |b| + |r_z|))`; then three-valued signs and
        /// `crossing = (Pz<0, Qz>0, r_z>0, a>0, b>0, s<0) or (Pz>0, Qz<0, r_z<0, a<0, b<0, s>0)`
        /// in Kleene logic: `cross_t` (surely crosses), `cross_f` (surely misses).
        ///
        /// Inputs arrive as the vertex terms are ready: `p*`, `q*` (coordinates) at 0, `pe`,
        /// `qe` (E_z) at [`Vertex::E_AT`], `pg`, `qg` (G) at [`Vertex::G_AT`], `pf*`, `qf*`
        /// (E_x, E_y, E'_z) at [`Vertex::F_AT`], `ph`, `qh` (H) at [`Vertex::H_AT`].
        /// Schedule: products after edge 4, `a`, `b` 7, `rz` 3 (waits 7), `ab` 10, `s` 13;
        /// bound products 14 (`|P| G` 11, waiting 3), their sums 17, `ba`, `bb` 20; `brz`
        /// 10 (waits 7); `rab` 10, `rabz` 13, `rs` 17, `brs` 20 (waits 3), `bab` 23, `bs`
        /// 26. Each sign is taken when its value and bound are ready (z at 4, r_z 10, a and
        /// b 20, s 26), its two bits wait for s's, and the six are registered with s and its
        /// bound after edge 27: latency [`Edge::LATENCY`] = 27 (`cross_t`, `cross_f`
        /// combinational from the sign register). Ports: in `clock`, `p0` .. `p2`, `q0` ..
        /// `q2`, `pe`, `qe`, `pg`, `qg`, `pf0` .. `pf2`, `qf0` .. `qf2`, `ph`, `qh`; out
        /// `s_x`, `s_b`, `cross_t`, `cross_f`.
        #[derive(LogicBlock)]
        pub struct Edge {
            pub clock: Signal<In, Clock>,
            pub p0: Signal<In, Bits<$W>>,
            pub p1: Signal<In, Bits<$W>>,
            pub p2: Signal<In, Bits<$W>>,
            pub q0: Signal<In, Bits<$W>>,
            pub q1: Signal<In, Bits<$W>>,
            pub q2: Signal<In, Bits<$W>>,
            pub pe: Signal<In, Bits<$W>>,
            pub qe: Signal<In, Bits<$W>>,
            pub pg: Signal<In, Bits<$W>>,
            pub qg: Signal<In, Bits<$W>>,
            pub pf0: Signal<In, Bits<$W>>,
            pub pf1: Signal<In, Bits<$W>>,
            pub pf2: Signal<In, Bits<$W>>,
            pub qf0: Signal<In, Bits<$W>>,
            pub qf1: Signal<In, Bits<$W>>,
            pub qf2: Signal<In, Bits<$W>>,
            pub ph: Signal<In, Bits<$W>>,
            pub qh: Signal<In, Bits<$W>>,
            pub s_x: Signal<Out, Bits<$W>>,
            pub s_b: Signal<Out, Bits<$W>>,
            pub cross_t: Signal<Out, Bit>,
            pub cross_f: Signal<Out, Bit>,
            mask: Constant<Bits<$W>>,
            // values
            px_qz: FpMul,
            qx_pz: FpMul,
            py_qz: FpMul,
            qy_pz: FpMul,
            a: FpAdd,
            b: FpAdd,
            rz: FpAdd,
            rz_wait: Delay<Bits<$W>, 7>,
            ab: FpAdd,
            s: FpAdd,
            // bounds
            // E waits for H, |P| for G, |P| G for E H (the vertices' schedule)
            pf0_wait: Delay<Bits<$W>, { Vertex::H_AT - Vertex::F_AT }>,
            qf0_wait: Delay<Bits<$W>, { Vertex::H_AT - Vertex::F_AT }>,
            pf1_wait: Delay<Bits<$W>, { Vertex::H_AT - Vertex::F_AT }>,
            qf1_wait: Delay<Bits<$W>, { Vertex::H_AT - Vertex::F_AT }>,
            p0_wait: Delay<Bits<$W>, { Vertex::G_AT }>,
            q0_wait: Delay<Bits<$W>, { Vertex::G_AT }>,
            p1_wait: Delay<Bits<$W>, { Vertex::G_AT }>,
            q1_wait: Delay<Bits<$W>, { Vertex::G_AT }>,
            ta: [FpMul; 4],
            tb: [FpMul; 4],
            ta_wait: [Delay<Bits<$W>, { Vertex::H_AT - Vertex::G_AT }>; 2],
            tb_wait: [Delay<Bits<$W>, { Vertex::H_AT - Vertex::G_AT }>; 2],
            sa: [FpAdd; 2],
            sb: [FpAdd; 2],
            ba: FpAdd,
            bb: FpAdd,
            brz: FpAdd,
            brz_wait: Delay<Bits<$W>, 7>,
            rab: FpAdd,
            rabz: FpAdd,
            rs: FpScale,
            brs: FpAdd,
            brs_wait: Delay<Bits<$W>, 3>,
            bab: FpAdd,
            bs: FpAdd,
            // signs
            pz_wait: Delay<Bits<$W>, { Vertex::E_AT }>,
            qz_wait: Delay<Bits<$W>, { Vertex::E_AT }>,
            a_wait: Delay<Bits<$W>, 13>,
            b_wait: Delay<Bits<$W>, 13>,
            s_wait: Delay<Bits<$W>, 13>,
            sign_pz: Sign,
            sign_qz: Sign,
            sign_rz: Sign,
            sign_a: Sign,
            sign_b: Sign,
            sign_s: Sign,
            pz_sgn_wait: Delay<Bits<2>, 22>,
            qz_sgn_wait: Delay<Bits<2>, 22>,
            rz_sgn_wait: Delay<Bits<2>, 16>,
            a_sgn_wait: Delay<Bits<2>, 6>,
            b_sgn_wait: Delay<Bits<2>, 6>,
            // the sign register, with s and its bound
            r_pz: DFF<Bits<2>>,
            r_qz: DFF<Bits<2>>,
            r_rz: DFF<Bits<2>>,
            r_a: DFF<Bits<2>>,
            r_b: DFF<Bits<2>>,
            r_s: DFF<Bits<2>>,
            r_s_x: DFF<Bits<$W>>,
            r_s_b: DFF<Bits<$W>>,
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
            pub const LATENCY: usize = 27;

            pub fn new(rounding: Rounding, cert: &$crate::golden::certificate::Certificate) -> Self {
                let up = Rounding::TowardPositive;
                Self {
                    clock: Default::default(),
                    p0: Default::default(),
                    p1: Default::default(),
                    p2: Default::default(),
                    q0: Default::default(),
                    q1: Default::default(),
                    q2: Default::default(),
                    pe: Default::default(),
                    qe: Default::default(),
                    pg: Default::default(),
                    qg: Default::default(),
                    pf0: Default::default(),
                    pf1: Default::default(),
                    pf2: Default::default(),
                    qf0: Default::default(),
                    qf1: Default::default(),
                    qf2: Default::default(),
                    ph: Default::default(),
                    qh: Default::default(),
                    s_x: Default::default(),
                    s_b: Default::default(),
                    cross_t: Default::default(),
                    cross_f: Default::default(),
                    mask: Constant::new(ABS_MASK.into()),
                    px_qz: FpMul::new(rounding),
                    qx_pz: FpMul::new(rounding),
                    py_qz: FpMul::new(rounding),
                    qy_pz: FpMul::new(rounding),
                    a: FpAdd::new(rounding),
                    b: FpAdd::new(rounding),
                    rz: FpAdd::new(rounding),
                    rz_wait: Default::default(),
                    ab: FpAdd::new(rounding),
                    s: FpAdd::new(rounding),
                    pf0_wait: Default::default(),
                    qf0_wait: Default::default(),
                    pf1_wait: Default::default(),
                    qf1_wait: Default::default(),
                    p0_wait: Default::default(),
                    q0_wait: Default::default(),
                    p1_wait: Default::default(),
                    q1_wait: Default::default(),
                    ta: std::array::from_fn(|_| FpMul::new(up)),
                    tb: std::array::from_fn(|_| FpMul::new(up)),
                    ta_wait: Default::default(),
                    tb_wait: Default::default(),
                    sa: std::array::from_fn(|_| FpAdd::new(up)),
                    sb: std::array::from_fn(|_| FpAdd::new(up)),
                    ba: FpAdd::new(up),
                    bb: FpAdd::new(up),
                    brz: FpAdd::new(up),
                    brz_wait: Default::default(),
                    rab: FpAdd::new(up),
                    rabz: FpAdd::new(up),
                    rs: FpScale::new(cert.c_s, cert.c_s),
                    brs: FpAdd::new(up),
                    brs_wait: Default::default(),
                    bab: FpAdd::new(up),
                    bs: FpAdd::new(up),
                    pz_wait: Default::default(),
                    qz_wait: Default::default(),
                    a_wait: Default::default(),
                    b_wait: Default::default(),
                    s_wait: Default::default(),
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
                    r_pz: Default::default(),
                    r_qz: Default::default(),
                    r_rz: Default::default(),
                    r_a: Default::default(),
                    r_b: Default::default(),
                    r_s: Default::default(),
                    r_s_x: Default::default(),
                    r_s_b: Default::default(),
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
                clock!(self, clock, px_qz, qx_pz, py_qz, qy_pz, a, b, rz, rz_wait, ab, s);
                clock!(self, clock, pf0_wait, qf0_wait, pf1_wait, qf1_wait, p0_wait, q0_wait, p1_wait, q1_wait);
                clock!(self, clock, ba, bb, brz, brz_wait, rab, rabz, rs, brs, brs_wait, bab, bs);
                clock!(self, clock, pz_wait, qz_wait, a_wait, b_wait, s_wait);
                clock!(self, clock, pz_sgn_wait, qz_sgn_wait, rz_sgn_wait, a_sgn_wait, b_sgn_wait);
                dff_setup!(self, clock, r_pz, r_qz, r_rz, r_a, r_b, r_s, r_s_x, r_s_b);
                // ---- values: products, a, b, r_z, then s = (a + b) - r_z
                self.px_qz.a.next = self.p0.val();
                self.px_qz.b.next = self.q2.val();
                self.qx_pz.a.next = self.q0.val();
                self.qx_pz.b.next = self.p2.val();
                self.py_qz.a.next = self.p1.val();
                self.py_qz.b.next = self.q2.val();
                self.qy_pz.a.next = self.q1.val();
                self.qy_pz.b.next = self.p2.val();
                self.px_qz.valid_in.next = false;
                self.qx_pz.valid_in.next = false;
                self.py_qz.valid_in.next = false;
                self.qy_pz.valid_in.next = false;
                self.a.a.next = self.px_qz.y.val();
                self.a.b.next = self.qx_pz.y.val();
                self.a.sub.next = true;
                self.a.valid_in.next = false;
                self.b.a.next = self.py_qz.y.val();
                self.b.b.next = self.qy_pz.y.val();
                self.b.sub.next = true;
                self.b.valid_in.next = false;
                self.rz.a.next = self.q2.val();
                self.rz.b.next = self.p2.val();
                self.rz.sub.next = true;
                self.rz.valid_in.next = false;
                self.rz_wait.d.next = self.rz.y.val();
                self.ab.a.next = self.a.y.val();
                self.ab.b.next = self.b.y.val();
                self.ab.sub.next = false;
                self.ab.valid_in.next = false;
                self.s.a.next = self.ab.y.val();
                self.s.b.next = self.rz_wait.q.val();
                self.s.sub.next = true;
                self.s.valid_in.next = false;
                // ---- bounds of a and b: (E_P H_Qz + |P| G_Qz) + (E_Q H_Pz + |Q| G_Pz)
                self.pf0_wait.d.next = self.pf0.val();
                self.qf0_wait.d.next = self.qf0.val();
                self.pf1_wait.d.next = self.pf1.val();
                self.qf1_wait.d.next = self.qf1.val();
                self.p0_wait.d.next = self.p0.val() & self.mask.val();
                self.q0_wait.d.next = self.q0.val() & self.mask.val();
                self.p1_wait.d.next = self.p1.val() & self.mask.val();
                self.q1_wait.d.next = self.q1.val() & self.mask.val();
                for k in 0..4 {
                    self.ta[k].clock.next = self.clock.val();
                    self.tb[k].clock.next = self.clock.val();
                    self.ta[k].valid_in.next = false;
                    self.tb[k].valid_in.next = false;
                }
                self.ta[0].a.next = self.pf0_wait.q.val();
                self.ta[0].b.next = self.qh.val();
                self.ta[1].a.next = self.p0_wait.q.val();
                self.ta[1].b.next = self.qg.val();
                self.ta[2].a.next = self.qf0_wait.q.val();
                self.ta[2].b.next = self.ph.val();
                self.ta[3].a.next = self.q0_wait.q.val();
                self.ta[3].b.next = self.pg.val();
                self.tb[0].a.next = self.pf1_wait.q.val();
                self.tb[0].b.next = self.qh.val();
                self.tb[1].a.next = self.p1_wait.q.val();
                self.tb[1].b.next = self.qg.val();
                self.tb[2].a.next = self.qf1_wait.q.val();
                self.tb[2].b.next = self.ph.val();
                self.tb[3].a.next = self.q1_wait.q.val();
                self.tb[3].b.next = self.pg.val();
                for k in 0..2 {
                    self.ta_wait[k].clock.next = self.clock.val();
                    self.tb_wait[k].clock.next = self.clock.val();
                    self.sa[k].clock.next = self.clock.val();
                    self.sb[k].clock.next = self.clock.val();
                    self.sa[k].sub.next = false;
                    self.sb[k].sub.next = false;
                    self.sa[k].valid_in.next = false;
                    self.sb[k].valid_in.next = false;
                }
                self.ta_wait[0].d.next = self.ta[1].y.val();
                self.ta_wait[1].d.next = self.ta[3].y.val();
                self.tb_wait[0].d.next = self.tb[1].y.val();
                self.tb_wait[1].d.next = self.tb[3].y.val();
                self.sa[0].a.next = self.ta[0].y.val();
                self.sa[0].b.next = self.ta_wait[0].q.val();
                self.sa[1].a.next = self.ta[2].y.val();
                self.sa[1].b.next = self.ta_wait[1].q.val();
                self.sb[0].a.next = self.tb[0].y.val();
                self.sb[0].b.next = self.tb_wait[0].q.val();
                self.sb[1].a.next = self.tb[2].y.val();
                self.sb[1].b.next = self.tb_wait[1].q.val();
                self.ba.a.next = self.sa[0].y.val();
                self.ba.b.next = self.sa[1].y.val();
                self.ba.sub.next = false;
                self.ba.valid_in.next = false;
                self.bb.a.next = self.sb[0].y.val();
                self.bb.b.next = self.sb[1].y.val();
                self.bb.sub.next = false;
                self.bb.valid_in.next = false;
                // ---- bound of r_z: E'_Qz + E'_Pz; of s: (B_a + B_b) + (B_rz + c (|a| + |b| + |r_z|))
                self.brz.a.next = self.qf2.val();
                self.brz.b.next = self.pf2.val();
                self.brz.sub.next = false;
                self.brz.valid_in.next = false;
                self.brz_wait.d.next = self.brz.y.val();
                self.rab.a.next = self.a.y.val() & self.mask.val();
                self.rab.b.next = self.b.y.val() & self.mask.val();
                self.rab.sub.next = false;
                self.rab.valid_in.next = false;
                self.rabz.a.next = self.rab.y.val();
                self.rabz.b.next = self.rz_wait.q.val() & self.mask.val();
                self.rabz.sub.next = false;
                self.rabz.valid_in.next = false;
                self.rs.a.next = self.rabz.y.val();
                self.rs.sel.next = false;
                self.brs.a.next = self.brz_wait.q.val();
                self.brs.b.next = self.rs.y.val();
                self.brs.sub.next = false;
                self.brs.valid_in.next = false;
                self.brs_wait.d.next = self.brs.y.val();
                self.bab.a.next = self.ba.y.val();
                self.bab.b.next = self.bb.y.val();
                self.bab.sub.next = false;
                self.bab.valid_in.next = false;
                self.bs.a.next = self.bab.y.val();
                self.bs.b.next = self.brs_wait.q.val();
                self.bs.sub.next = false;
                self.bs.valid_in.next = false;
                // ---- signs as value and bound are ready, waiting for s's
                self.pz_wait.d.next = self.p2.val();
                self.qz_wait.d.next = self.q2.val();
                self.sign_pz.x.next = self.pz_wait.q.val();
                self.sign_pz.e.next = self.pe.val();
                self.sign_qz.x.next = self.qz_wait.q.val();
                self.sign_qz.e.next = self.qe.val();
                self.sign_rz.x.next = self.rz_wait.q.val();
                self.sign_rz.e.next = self.brz.y.val();
                self.a_wait.d.next = self.a.y.val();
                self.b_wait.d.next = self.b.y.val();
                self.s_wait.d.next = self.s.y.val();
                self.sign_a.x.next = self.a_wait.q.val();
                self.sign_a.e.next = self.ba.y.val();
                self.sign_b.x.next = self.b_wait.q.val();
                self.sign_b.e.next = self.bb.y.val();
                self.sign_s.x.next = self.s_wait.q.val();
                self.sign_s.e.next = self.bs.y.val();
                self.pz_sgn_wait.d.next = self.sign_pz.sgn.val();
                self.qz_sgn_wait.d.next = self.sign_qz.sgn.val();
                self.rz_sgn_wait.d.next = self.sign_rz.sgn.val();
                self.a_sgn_wait.d.next = self.sign_a.sgn.val();
                self.b_sgn_wait.d.next = self.sign_b.sgn.val();
                // ---- the sign register
                self.r_pz.d.next = self.pz_sgn_wait.q.val();
                self.r_qz.d.next = self.qz_sgn_wait.q.val();
                self.r_rz.d.next = self.rz_sgn_wait.q.val();
                self.r_a.d.next = self.a_sgn_wait.q.val();
                self.r_b.d.next = self.b_sgn_wait.q.val();
                self.r_s.d.next = self.sign_s.sgn.val();
                self.r_s_x.d.next = self.s_wait.q.val();
                self.r_s_b.d.next = self.bs.y.val();
                self.pz_p.next = self.r_pz.q.val().get_bit(0);
                self.pz_n.next = self.r_pz.q.val().get_bit(1);
                self.qz_p.next = self.r_qz.q.val().get_bit(0);
                self.qz_n.next = self.r_qz.q.val().get_bit(1);
                self.rz_p.next = self.r_rz.q.val().get_bit(0);
                self.rz_n.next = self.r_rz.q.val().get_bit(1);
                self.a_p.next = self.r_a.q.val().get_bit(0);
                self.a_n.next = self.r_a.q.val().get_bit(1);
                self.b_p.next = self.r_b.q.val().get_bit(0);
                self.b_n.next = self.r_b.q.val().get_bit(1);
                self.s_p.next = self.r_s.q.val().get_bit(0);
                self.s_n.next = self.r_s.q.val().get_bit(1);
                // P below, Q above | P above, Q below; a conjunction is surely false as
                // soon as one sign is surely wrong.
                self.cross_t.next = (self.pz_n.val() & self.qz_p.val() & self.rz_p.val() & self.a_p.val() & self.b_p.val() & self.s_n.val())
                    | (self.pz_p.val() & self.qz_n.val() & self.rz_n.val() & self.a_n.val() & self.b_n.val() & self.s_p.val());
                self.cross_f.next = (self.pz_p.val() | self.qz_n.val() | self.rz_n.val() | self.a_n.val() | self.b_n.val() | self.s_p.val())
                    & (self.pz_n.val() | self.qz_p.val() | self.rz_p.val() | self.a_p.val() | self.b_p.val() | self.s_n.val());
                self.s_x.next = self.r_s_x.q.val();
                self.s_b.next = self.r_s_b.q.val();
            }
        }

        /// T.CHECK: do the edges of triangle A cross the unit triangle of B's leaf? (DATE'05
        /// §4.2; golden [`stage1`](crate::golden::tcheck::stage1) then
        /// [`edges`](crate::golden::tcheck::edges), bit for bit.) One triangle pair per
        /// clock, latency [`TCheck::LATENCY`] = 52, DATE'05's budget:
        ///
        /// | clocks | stage | values | certificate, beside them |
        /// |---|---|---|---|
        /// | 1 | input register | `in_*` | |
        /// | 2-11 | 1: M_b = M_B M_AB (Eqs. 11, 12) | `mb_0..2[j]` ([`Dot`]) | magnitudes `mg_0..2[j]`; A' = alpha_m beta_m + alpha_f beta_f, L1(x) = \|x\| + \|y\| + \|z\| + S per vertex |
        /// | 12 | fan-out register R1 | `mbr_*` | `mgr_*` |
        /// | 13-22 | 2: mapped vertices V'_k (Eq. 13) | `vt_0..2[k]` (coordinate i, vertex k) | `vm_0..2[k]`, with `m3_i[k]` = magnitude of Mb_i3 + A' L1 (clocks 13-16) |
        /// | 23 | fan-out register R2 | `vtr_*` | `vmr_*` |
        /// | 24-49 | 3, 4: a, b, r_z, s per edge (Eq. 9) | `edges[0..2]` ([`Edge`]) | `verts[k]` ([`Vertex`]): E, E', H; the edges' bounds |
        /// | 50 | sign register (in each [`Edge`]) | | |
        /// | 51 | 5: crossing per edge | `v_cross_t`, `v_cross_f` | |
        /// | 52 | OR over the edges; output register | `out_*` | |
        ///
        /// The value datapath takes 1 + 10 + 10 + 7 + 6 + 1 of the paper's 52 clocks; the
        /// fan-out registers (an M_b entry feeds three vertices' products, a coordinate
        /// two edges' and the certificate's units) and the sign and verdict registers are
        /// where the spare clocks buy clock rate, and the certificate's tail (the bounds
        /// of a, b and s, 13 clocks after s) fits in them.
        ///
        /// Ports, all words in the format:
        /// in `m_0[4]`, `m_1[4]`, `m_2[4]` (rows of B's M_B), `alpha_m`, `alpha_f` (its
        /// error words), `f_0[4]`, `f_1[4]`, `f_2[4]` (rows of the frame map M_AB),
        /// `beta_m`, `beta_f` (its error words), `scale` (S of A's object), `v_x[3]`,
        /// `v_y[3]`, `v_z[3]` (A's vertices), `v_exact`, `tag[32]`, `valid_in`;
        /// out `s_x[3]`, `s_b[3]` (stage 4's s per edge and its bound), `cross_t[3]`,
        /// `cross_f[3]`, `hit` (surely crosses), `miss` (surely does not), `tag_out`,
        /// `valid_out`.
        #[derive(LogicBlock)]
        pub struct TCheck {
            pub clock: Signal<In, Clock>,
            pub m_0: [Signal<In, Bits<$W>>; 4],
            pub m_1: [Signal<In, Bits<$W>>; 4],
            pub m_2: [Signal<In, Bits<$W>>; 4],
            pub alpha_m: Signal<In, Bits<$W>>,
            pub alpha_f: Signal<In, Bits<$W>>,
            pub f_0: [Signal<In, Bits<$W>>; 4],
            pub f_1: [Signal<In, Bits<$W>>; 4],
            pub f_2: [Signal<In, Bits<$W>>; 4],
            pub beta_m: Signal<In, Bits<$W>>,
            pub beta_f: Signal<In, Bits<$W>>,
            pub scale: Signal<In, Bits<$W>>,
            pub v_x: [Signal<In, Bits<$W>>; 3],
            pub v_y: [Signal<In, Bits<$W>>; 3],
            pub v_z: [Signal<In, Bits<$W>>; 3],
            pub v_exact: Signal<In, Bit>,
            pub tag: Signal<In, Bits<32>>,
            pub valid_in: Signal<In, Bit>,
            pub s_x: [Signal<Out, Bits<$W>>; 3],
            pub s_b: [Signal<Out, Bits<$W>>; 3],
            pub cross_t: [Signal<Out, Bit>; 3],
            pub cross_f: [Signal<Out, Bit>; 3],
            pub hit: Signal<Out, Bit>,
            pub miss: Signal<Out, Bit>,
            pub tag_out: Signal<Out, Bits<32>>,
            pub valid_out: Signal<Out, Bit>,
            mask: Constant<Bits<$W>>,
            // clock 1: input register
            in_m_0: [DFF<Bits<$W>>; 4],
            in_m_1: [DFF<Bits<$W>>; 4],
            in_m_2: [DFF<Bits<$W>>; 4],
            in_alpha_m: DFF<Bits<$W>>,
            in_alpha_f: DFF<Bits<$W>>,
            in_f_0: [DFF<Bits<$W>>; 4],
            in_f_1: [DFF<Bits<$W>>; 4],
            in_f_2: [DFF<Bits<$W>>; 4],
            in_beta_m: DFF<Bits<$W>>,
            in_beta_f: DFF<Bits<$W>>,
            in_scale: DFF<Bits<$W>>,
            in_v_x: [DFF<Bits<$W>>; 3],
            in_v_y: [DFF<Bits<$W>>; 3],
            in_v_z: [DFF<Bits<$W>>; 3],
            in_v_exact: DFF<Bit>,
            in_tag: DFF<Bits<32>>,
            in_valid: DFF<Bit>,
            // stage 1: row i of M_b and its magnitude, column j; M_B's translation waits
            // for the products (Dot::C_AT)
            mb_0: [Dot; 4],
            mb_1: [Dot; 4],
            mb_2: [Dot; 4],
            mg_0: [Dot; 4],
            mg_1: [Dot; 4],
            mg_2: [Dot; 4],
            c3_0: Delay<Bits<$W>, { Dot::C_AT }>,
            c3_1: Delay<Bits<$W>, { Dot::C_AT }>,
            c3_2: Delay<Bits<$W>, { Dot::C_AT }>,
            // the input errors: A' (clocks 2-8, waiting 1) and L1 per vertex (2-7, waiting 2),
            // err = A' L1 (10-13)
            am: FpMul,
            af: FpMul,
            aerr: FpAdd,
            aerr_wait: Delay<Bits<$W>, 1>,
            la: [FpAdd; 3],
            lb: [FpAdd; 3],
            l1: [FpAdd; 3],
            l1_wait: [Delay<Bits<$W>, 2>; 3],
            err: [FpMul; 3],
            // R1
            mbr_0: [DFF<Bits<$W>>; 4],
            mbr_1: [DFF<Bits<$W>>; 4],
            mbr_2: [DFF<Bits<$W>>; 4],
            mgr_0: [DFF<Bits<$W>>; 4],
            mgr_1: [DFF<Bits<$W>>; 4],
            mgr_2: [DFF<Bits<$W>>; 4],
            // stage 2: coordinate i of vertex k, its magnitude (translation term + A' L1),
            // the vertices waiting for M_b, Mb_i3 waiting for the products
            mg3_0: Delay<Bits<$W>, 1>,
            mg3_1: Delay<Bits<$W>, 1>,
            mg3_2: Delay<Bits<$W>, 1>,
            m3_0: [FpAdd; 3],
            m3_1: [FpAdd; 3],
            m3_2: [FpAdd; 3],
            vc_0: Delay<Bits<$W>, { Dot::C_AT }>,
            vc_1: Delay<Bits<$W>, { Dot::C_AT }>,
            vc_2: Delay<Bits<$W>, { Dot::C_AT }>,
            v_x_wait: [Delay<Bits<$W>, 11>; 3],
            v_y_wait: [Delay<Bits<$W>, 11>; 3],
            v_z_wait: [Delay<Bits<$W>, 11>; 3],
            vt_0: [Dot; 3],
            vt_1: [Dot; 3],
            vt_2: [Dot; 3],
            vm_0: [Dot; 3],
            vm_1: [Dot; 3],
            vm_2: [Dot; 3],
            // R2
            vtr_0: [DFF<Bits<$W>>; 3],
            vtr_1: [DFF<Bits<$W>>; 3],
            vtr_2: [DFF<Bits<$W>>; 3],
            vmr_0: [DFF<Bits<$W>>; 3],
            vmr_1: [DFF<Bits<$W>>; 3],
            vmr_2: [DFF<Bits<$W>>; 3],
            exact_wait: Delay<Bit, 22>,
            // stages 3-5
            verts: [Vertex; 3],
            edges: [Edge; 3],
            tag_wait: Delay<Bits<32>, 50>,
            valid_wait: Delay<Bit, 50>,
            v_cross_t: [DFF<Bit>; 3],
            v_cross_f: [DFF<Bit>; 3],
            v_s_x: [DFF<Bits<$W>>; 3],
            v_s_b: [DFF<Bits<$W>>; 3],
            hit_any: Signal<Local, Bit>,
            miss_all: Signal<Local, Bit>,
            out_s_x: [DFF<Bits<$W>>; 3],
            out_s_b: [DFF<Bits<$W>>; 3],
            out_cross_t: [DFF<Bit>; 3],
            out_cross_f: [DFF<Bit>; 3],
            out_hit: DFF<Bit>,
            out_miss: DFF<Bit>,
            out_tag: DFF<Bits<32>>,
            out_valid: DFF<Bit>,
        }

        impl TCheck {
            pub const LATENCY: usize = 1 + Dot::LATENCY + 1 + Dot::LATENCY + 1 + Edge::LATENCY + 2;

            /// A T.CHECK whose value datapath rounds with `rounding` (NearestEven or
            /// TowardPositive; the certificate's units always round upward).
            pub fn new(rounding: Rounding) -> Self {
                let cert = $crate::golden::certificate::Certificate::new(FORMAT, rounding);
                let up = Rounding::TowardPositive;
                Self {
                    clock: Default::default(),
                    m_0: Default::default(),
                    m_1: Default::default(),
                    m_2: Default::default(),
                    alpha_m: Default::default(),
                    alpha_f: Default::default(),
                    f_0: Default::default(),
                    f_1: Default::default(),
                    f_2: Default::default(),
                    beta_m: Default::default(),
                    beta_f: Default::default(),
                    scale: Default::default(),
                    v_x: Default::default(),
                    v_y: Default::default(),
                    v_z: Default::default(),
                    v_exact: Default::default(),
                    tag: Default::default(),
                    valid_in: Default::default(),
                    s_x: Default::default(),
                    s_b: Default::default(),
                    cross_t: Default::default(),
                    cross_f: Default::default(),
                    hit: Default::default(),
                    miss: Default::default(),
                    tag_out: Default::default(),
                    valid_out: Default::default(),
                    mask: Constant::new(ABS_MASK.into()),
                    in_m_0: Default::default(),
                    in_m_1: Default::default(),
                    in_m_2: Default::default(),
                    in_alpha_m: Default::default(),
                    in_alpha_f: Default::default(),
                    in_f_0: Default::default(),
                    in_f_1: Default::default(),
                    in_f_2: Default::default(),
                    in_beta_m: Default::default(),
                    in_beta_f: Default::default(),
                    in_scale: Default::default(),
                    in_v_x: Default::default(),
                    in_v_y: Default::default(),
                    in_v_z: Default::default(),
                    in_v_exact: Default::default(),
                    in_tag: Default::default(),
                    in_valid: Default::default(),
                    mb_0: std::array::from_fn(|j| Dot::new(rounding, j == 3, false)),
                    mb_1: std::array::from_fn(|j| Dot::new(rounding, j == 3, false)),
                    mb_2: std::array::from_fn(|j| Dot::new(rounding, j == 3, false)),
                    mg_0: std::array::from_fn(|j| Dot::new(rounding, j == 3, true)),
                    mg_1: std::array::from_fn(|j| Dot::new(rounding, j == 3, true)),
                    mg_2: std::array::from_fn(|j| Dot::new(rounding, j == 3, true)),
                    c3_0: Default::default(),
                    c3_1: Default::default(),
                    c3_2: Default::default(),
                    am: FpMul::new(up),
                    af: FpMul::new(up),
                    aerr: FpAdd::new(up),
                    aerr_wait: Default::default(),
                    la: std::array::from_fn(|_| FpAdd::new(up)),
                    lb: std::array::from_fn(|_| FpAdd::new(up)),
                    l1: std::array::from_fn(|_| FpAdd::new(up)),
                    l1_wait: Default::default(),
                    err: std::array::from_fn(|_| FpMul::new(up)),
                    mbr_0: Default::default(),
                    mbr_1: Default::default(),
                    mbr_2: Default::default(),
                    mgr_0: Default::default(),
                    mgr_1: Default::default(),
                    mgr_2: Default::default(),
                    mg3_0: Default::default(),
                    mg3_1: Default::default(),
                    mg3_2: Default::default(),
                    m3_0: std::array::from_fn(|_| FpAdd::new(up)),
                    m3_1: std::array::from_fn(|_| FpAdd::new(up)),
                    m3_2: std::array::from_fn(|_| FpAdd::new(up)),
                    vc_0: Default::default(),
                    vc_1: Default::default(),
                    vc_2: Default::default(),
                    v_x_wait: Default::default(),
                    v_y_wait: Default::default(),
                    v_z_wait: Default::default(),
                    vt_0: std::array::from_fn(|_| Dot::new(rounding, true, false)),
                    vt_1: std::array::from_fn(|_| Dot::new(rounding, true, false)),
                    vt_2: std::array::from_fn(|_| Dot::new(rounding, true, false)),
                    vm_0: std::array::from_fn(|_| Dot::new(rounding, true, true)),
                    vm_1: std::array::from_fn(|_| Dot::new(rounding, true, true)),
                    vm_2: std::array::from_fn(|_| Dot::new(rounding, true, true)),
                    vtr_0: Default::default(),
                    vtr_1: Default::default(),
                    vtr_2: Default::default(),
                    vmr_0: Default::default(),
                    vmr_1: Default::default(),
                    vmr_2: Default::default(),
                    exact_wait: Default::default(),
                    verts: std::array::from_fn(|_| Vertex::new(&cert)),
                    edges: std::array::from_fn(|_| Edge::new(rounding, &cert)),
                    tag_wait: Default::default(),
                    valid_wait: Default::default(),
                    v_cross_t: Default::default(),
                    v_cross_f: Default::default(),
                    v_s_x: Default::default(),
                    v_s_b: Default::default(),
                    hit_any: Default::default(),
                    miss_all: Default::default(),
                    out_s_x: Default::default(),
                    out_s_b: Default::default(),
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
                dff_setup!(self, clock, in_alpha_m, in_alpha_f, in_beta_m, in_beta_f, in_scale, in_v_exact, in_tag, in_valid);
                dff_setup!(self, clock, out_hit, out_miss, out_tag, out_valid);
                clock!(self, clock, c3_0, c3_1, c3_2, am, af, aerr, aerr_wait, mg3_0, mg3_1, mg3_2, vc_0, vc_1, vc_2);
                clock!(self, clock, exact_wait, tag_wait, valid_wait);
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
                self.in_alpha_m.d.next = self.alpha_m.val();
                self.in_alpha_f.d.next = self.alpha_f.val();
                self.in_beta_m.d.next = self.beta_m.val();
                self.in_beta_f.d.next = self.beta_f.val();
                self.in_scale.d.next = self.scale.val();
                self.in_v_exact.d.next = self.v_exact.val();
                self.in_tag.d.next = self.tag.val();
                self.in_valid.d.next = self.valid_in.val();
                for k in 0..3 {
                    self.in_v_x[k].clock.next = self.clock.val();
                    self.in_v_y[k].clock.next = self.clock.val();
                    self.in_v_z[k].clock.next = self.clock.val();
                    self.in_v_x[k].d.next = self.v_x[k].val();
                    self.in_v_y[k].d.next = self.v_y[k].val();
                    self.in_v_z[k].d.next = self.v_z[k].val();
                }
                // ---- stage 1: Mb_ij = (m_i0 f_0j + m_i1 f_1j) + m_i2 f_2j  (j < 3)
                //               Mb_i3 = (m_i0 f_03 + m_i1 f_13) + (m_i2 f_23 + m_i3)
                // and the same on absolute values, rounded upward; R1
                $(
                self.$c3.d.next = self.$in_m[3].q.val();
                for j in 0..4 {
                    self.$mb[j].clock.next = self.clock.val();
                    self.$mg[j].clock.next = self.clock.val();
                    self.$mb[j].a0.next = self.$in_m[0].q.val();
                    self.$mb[j].a1.next = self.$in_m[1].q.val();
                    self.$mb[j].a2.next = self.$in_m[2].q.val();
                    self.$mb[j].b0.next = self.in_f_0[j].q.val();
                    self.$mb[j].b1.next = self.in_f_1[j].q.val();
                    self.$mb[j].b2.next = self.in_f_2[j].q.val();
                    self.$mb[j].c.next = self.$c3.q.val();
                    self.$mg[j].a0.next = self.$in_m[0].q.val();
                    self.$mg[j].a1.next = self.$in_m[1].q.val();
                    self.$mg[j].a2.next = self.$in_m[2].q.val();
                    self.$mg[j].b0.next = self.in_f_0[j].q.val();
                    self.$mg[j].b1.next = self.in_f_1[j].q.val();
                    self.$mg[j].b2.next = self.in_f_2[j].q.val();
                    self.$mg[j].c.next = self.$c3.q.val();
                    self.$mbr[j].clock.next = self.clock.val();
                    self.$mgr[j].clock.next = self.clock.val();
                    self.$mbr[j].d.next = self.$mb[j].y.val();
                    self.$mgr[j].d.next = self.$mg[j].y.val();
                }
                )*
                // ---- the input errors: A' = alpha_m beta_m + alpha_f beta_f, and per vertex
                // L1 = (|x| + |y|) + (|z| + S), err = A' L1, all rounded upward
                self.am.a.next = self.in_alpha_m.q.val();
                self.am.b.next = self.in_beta_m.q.val();
                self.am.valid_in.next = false;
                self.af.a.next = self.in_alpha_f.q.val();
                self.af.b.next = self.in_beta_f.q.val();
                self.af.valid_in.next = false;
                self.aerr.a.next = self.am.y.val();
                self.aerr.b.next = self.af.y.val();
                self.aerr.sub.next = false;
                self.aerr.valid_in.next = false;
                self.aerr_wait.d.next = self.aerr.y.val();
                for k in 0..3 {
                    self.la[k].clock.next = self.clock.val();
                    self.lb[k].clock.next = self.clock.val();
                    self.l1[k].clock.next = self.clock.val();
                    self.l1_wait[k].clock.next = self.clock.val();
                    self.err[k].clock.next = self.clock.val();
                    self.la[k].a.next = self.in_v_x[k].q.val() & self.mask.val();
                    self.la[k].b.next = self.in_v_y[k].q.val() & self.mask.val();
                    self.lb[k].a.next = self.in_v_z[k].q.val() & self.mask.val();
                    self.lb[k].b.next = self.in_scale.q.val();
                    self.l1[k].a.next = self.la[k].y.val();
                    self.l1[k].b.next = self.lb[k].y.val();
                    self.la[k].sub.next = false;
                    self.lb[k].sub.next = false;
                    self.l1[k].sub.next = false;
                    self.la[k].valid_in.next = false;
                    self.lb[k].valid_in.next = false;
                    self.l1[k].valid_in.next = false;
                    self.l1_wait[k].d.next = self.l1[k].y.val();
                    self.err[k].a.next = self.aerr_wait.q.val();
                    self.err[k].b.next = self.l1_wait[k].q.val();
                    self.err[k].valid_in.next = false;
                    // the vertices wait for M_b
                    self.v_x_wait[k].clock.next = self.clock.val();
                    self.v_y_wait[k].clock.next = self.clock.val();
                    self.v_z_wait[k].clock.next = self.clock.val();
                    self.v_x_wait[k].d.next = self.in_v_x[k].q.val();
                    self.v_y_wait[k].d.next = self.in_v_y[k].q.val();
                    self.v_z_wait[k].d.next = self.in_v_z[k].q.val();
                }
                // ---- stage 2: V'_ik = (Mb_i0 x_k + Mb_i1 y_k) + (Mb_i2 z_k + Mb_i3), its
                // magnitude with |Mb_i3| + A' L1_k as the translation term; R2
                $(
                self.$mg3.d.next = self.$mgr[3].q.val();
                self.$vc.d.next = self.$mbr[3].q.val();
                for k in 0..3 {
                    self.$m3[k].clock.next = self.clock.val();
                    self.$m3[k].a.next = self.$mg3.q.val();
                    self.$m3[k].b.next = self.err[k].y.val();
                    self.$m3[k].sub.next = false;
                    self.$m3[k].valid_in.next = false;
                    self.$vt[k].clock.next = self.clock.val();
                    self.$vm[k].clock.next = self.clock.val();
                    self.$vt[k].a0.next = self.$mbr[0].q.val();
                    self.$vt[k].a1.next = self.$mbr[1].q.val();
                    self.$vt[k].a2.next = self.$mbr[2].q.val();
                    self.$vt[k].b0.next = self.v_x_wait[k].q.val();
                    self.$vt[k].b1.next = self.v_y_wait[k].q.val();
                    self.$vt[k].b2.next = self.v_z_wait[k].q.val();
                    self.$vt[k].c.next = self.$vc.q.val();
                    self.$vm[k].a0.next = self.$mgr[0].q.val();
                    self.$vm[k].a1.next = self.$mgr[1].q.val();
                    self.$vm[k].a2.next = self.$mgr[2].q.val();
                    self.$vm[k].b0.next = self.v_x_wait[k].q.val();
                    self.$vm[k].b1.next = self.v_y_wait[k].q.val();
                    self.$vm[k].b2.next = self.v_z_wait[k].q.val();
                    self.$vm[k].c.next = self.$m3[k].y.val();
                    self.$vtr[k].clock.next = self.clock.val();
                    self.$vmr[k].clock.next = self.clock.val();
                    self.$vtr[k].d.next = self.$vt[k].y.val();
                    self.$vmr[k].d.next = self.$vm[k].y.val();
                }
                )*
                // ---- the vertices' certificate terms, for rounded or exact vertices
                self.exact_wait.d.next = self.in_v_exact.q.val();
                for k in 0..3 {
                    self.verts[k].clock.next = self.clock.val();
                    self.verts[k].exact.next = self.exact_wait.q.val();
                    self.verts[k].z.next = self.vtr_2[k].q.val();
                    self.verts[k].m0.next = self.vmr_0[k].q.val();
                    self.verts[k].m1.next = self.vmr_1[k].q.val();
                    self.verts[k].m2.next = self.vmr_2[k].q.val();
                }
                // ---- stages 3-5: edges V0V1, V1V2, V2V0
                self.edges[0].p0.next = self.vtr_0[0].q.val();
                self.edges[0].p1.next = self.vtr_1[0].q.val();
                self.edges[0].p2.next = self.vtr_2[0].q.val();
                self.edges[0].q0.next = self.vtr_0[1].q.val();
                self.edges[0].q1.next = self.vtr_1[1].q.val();
                self.edges[0].q2.next = self.vtr_2[1].q.val();
                self.edges[0].pe.next = self.verts[0].e.val();
                self.edges[0].qe.next = self.verts[1].e.val();
                self.edges[0].pg.next = self.verts[0].g.val();
                self.edges[0].qg.next = self.verts[1].g.val();
                self.edges[0].pf0.next = self.verts[0].f0.val();
                self.edges[0].pf1.next = self.verts[0].f1.val();
                self.edges[0].pf2.next = self.verts[0].f2.val();
                self.edges[0].qf0.next = self.verts[1].f0.val();
                self.edges[0].qf1.next = self.verts[1].f1.val();
                self.edges[0].qf2.next = self.verts[1].f2.val();
                self.edges[0].ph.next = self.verts[0].h.val();
                self.edges[0].qh.next = self.verts[1].h.val();
                self.edges[1].p0.next = self.vtr_0[1].q.val();
                self.edges[1].p1.next = self.vtr_1[1].q.val();
                self.edges[1].p2.next = self.vtr_2[1].q.val();
                self.edges[1].q0.next = self.vtr_0[2].q.val();
                self.edges[1].q1.next = self.vtr_1[2].q.val();
                self.edges[1].q2.next = self.vtr_2[2].q.val();
                self.edges[1].pe.next = self.verts[1].e.val();
                self.edges[1].qe.next = self.verts[2].e.val();
                self.edges[1].pg.next = self.verts[1].g.val();
                self.edges[1].qg.next = self.verts[2].g.val();
                self.edges[1].pf0.next = self.verts[1].f0.val();
                self.edges[1].pf1.next = self.verts[1].f1.val();
                self.edges[1].pf2.next = self.verts[1].f2.val();
                self.edges[1].qf0.next = self.verts[2].f0.val();
                self.edges[1].qf1.next = self.verts[2].f1.val();
                self.edges[1].qf2.next = self.verts[2].f2.val();
                self.edges[1].ph.next = self.verts[1].h.val();
                self.edges[1].qh.next = self.verts[2].h.val();
                self.edges[2].p0.next = self.vtr_0[2].q.val();
                self.edges[2].p1.next = self.vtr_1[2].q.val();
                self.edges[2].p2.next = self.vtr_2[2].q.val();
                self.edges[2].q0.next = self.vtr_0[0].q.val();
                self.edges[2].q1.next = self.vtr_1[0].q.val();
                self.edges[2].q2.next = self.vtr_2[0].q.val();
                self.edges[2].pe.next = self.verts[2].e.val();
                self.edges[2].qe.next = self.verts[0].e.val();
                self.edges[2].pg.next = self.verts[2].g.val();
                self.edges[2].qg.next = self.verts[0].g.val();
                self.edges[2].pf0.next = self.verts[2].f0.val();
                self.edges[2].pf1.next = self.verts[2].f1.val();
                self.edges[2].pf2.next = self.verts[2].f2.val();
                self.edges[2].qf0.next = self.verts[0].f0.val();
                self.edges[2].qf1.next = self.verts[0].f1.val();
                self.edges[2].qf2.next = self.verts[0].f2.val();
                self.edges[2].ph.next = self.verts[2].h.val();
                self.edges[2].qh.next = self.verts[0].h.val();
                self.tag_wait.d.next = self.in_tag.q.val();
                self.valid_wait.d.next = self.in_valid.q.val();
                // ---- clock 51: the verdict per edge; 52: OR over the edges, output register
                self.hit_any.next = false;
                self.miss_all.next = true;
                for e in 0..3 {
                    self.edges[e].clock.next = self.clock.val();
                    self.v_cross_t[e].clock.next = self.clock.val();
                    self.v_cross_f[e].clock.next = self.clock.val();
                    self.v_s_x[e].clock.next = self.clock.val();
                    self.v_s_b[e].clock.next = self.clock.val();
                    self.out_s_x[e].clock.next = self.clock.val();
                    self.out_s_b[e].clock.next = self.clock.val();
                    self.out_cross_t[e].clock.next = self.clock.val();
                    self.out_cross_f[e].clock.next = self.clock.val();
                    self.v_cross_t[e].d.next = self.edges[e].cross_t.val();
                    self.v_cross_f[e].d.next = self.edges[e].cross_f.val();
                    self.v_s_x[e].d.next = self.edges[e].s_x.val();
                    self.v_s_b[e].d.next = self.edges[e].s_b.val();
                    self.out_s_x[e].d.next = self.v_s_x[e].q.val();
                    self.out_s_b[e].d.next = self.v_s_b[e].q.val();
                    self.out_cross_t[e].d.next = self.v_cross_t[e].q.val();
                    self.out_cross_f[e].d.next = self.v_cross_f[e].q.val();
                    if self.v_cross_t[e].q.val() {
                        self.hit_any.next = true;
                    }
                    if !self.v_cross_f[e].q.val() {
                        self.miss_all.next = false;
                    }
                    self.s_x[e].next = self.out_s_x[e].q.val();
                    self.s_b[e].next = self.out_s_b[e].q.val();
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
        /// Large: build it on a thread with a big stack.
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
            top_level!(uut; clock, alpha_m, alpha_f, beta_m, beta_f, scale, v_exact, tag, valid_in)
        }

        /// Verilog of T.CHECK (top module `top`).
        pub fn verilog_tcheck(rounding: Rounding) -> String {
            generate_verilog(&tcheck_top(rounding))
        }
    };
}
pub(crate) use tcheck;
