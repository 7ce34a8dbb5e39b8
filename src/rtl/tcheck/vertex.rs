//! T.CHECK's certificate terms of one mapped vertex (the bounds its edges combine).

/// Stamps out `Vertex` in the calling module (by `tcheck!`, tcheck/mod.rs, which also
/// brings `Delay` and `ABS_MASK` into scope).
macro_rules! vertex {
    ($W:tt, $E:tt, $F:tt) => {
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
                if (self.ez.y.val().get_bits::<$E>($F) != 0)
                    & !self.ez.y.val().get_bits::<$E>($F).all()
                {
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
    };
}
pub(crate) use vertex;
