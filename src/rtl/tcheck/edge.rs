//! T.CHECK's stages 3-5 for one edge of the mapped triangle: values, bounds, signs,
//! crossing.

/// Stamps out `Edge` in the calling module (by `tcheck!`, tcheck/mod.rs, which also
/// brings `Delay` and `ABS_MASK` into scope).
macro_rules! edge {
    ($W:tt) => {
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

            pub fn new(
                rounding: Rounding,
                cert: &$crate::golden::certificate::Certificate,
            ) -> Self {
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

        $crate::rtl::kernel::kernel!([] Edge: Values, Bounds, Signs);

        /// The edge's values: the products, a, b, r_z and s = (a + b) - r_z.
        struct Values;

        impl $crate::rtl::kernel::Kernel<Values> for Edge {
            #[hdl_gen]
            fn update(&mut self) {
                clock!(self, clock, px_qz, qx_pz, py_qz, qy_pz, a, b, rz, rz_wait, ab, s);
                clock!(
                    self, clock, pf0_wait, qf0_wait, pf1_wait, qf1_wait, p0_wait, q0_wait, p1_wait,
                    q1_wait
                );
                clock!(self, clock, ba, bb, brz, brz_wait, rab, rabz, rs, brs, brs_wait, bab, bs);
                clock!(self, clock, pz_wait, qz_wait, a_wait, b_wait, s_wait);
                clock!(
                    self,
                    clock,
                    pz_sgn_wait,
                    qz_sgn_wait,
                    rz_sgn_wait,
                    a_sgn_wait,
                    b_sgn_wait
                );
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
            }
        }

        /// The error bounds of a, b, r_z and s.
        struct Bounds;

        impl $crate::rtl::kernel::Kernel<Bounds> for Edge {
            #[hdl_gen]
            fn update(&mut self) {
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
            }
        }

        /// The signs, surely right or uncertain, and the edge's verdict.
        struct Signs;

        impl $crate::rtl::kernel::Kernel<Signs> for Edge {
            #[hdl_gen]
            fn update(&mut self) {
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
                self.cross_t.next = (self.pz_n.val()
                    & self.qz_p.val()
                    & self.rz_p.val()
                    & self.a_p.val()
                    & self.b_p.val()
                    & self.s_n.val())
                    | (self.pz_p.val()
                        & self.qz_n.val()
                        & self.rz_n.val()
                        & self.a_n.val()
                        & self.b_n.val()
                        & self.s_p.val());
                self.cross_f.next = (self.pz_p.val()
                    | self.qz_n.val()
                    | self.rz_n.val()
                    | self.a_n.val()
                    | self.b_n.val()
                    | self.s_p.val())
                    & (self.pz_n.val()
                        | self.qz_p.val()
                        | self.rz_p.val()
                        | self.a_p.val()
                        | self.b_p.val()
                        | self.s_n.val());
                self.s_x.next = self.r_s_x.q.val();
                self.s_b.next = self.r_s_b.q.val();
            }
        }
    };
}
pub(crate) use edge;
