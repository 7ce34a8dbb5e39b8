//! T.CHECK (DATE'05 §4.2, Eqs. 8, 9, 11-13) with its certificate, stamped out per format
//! by `tcheck!`: the value datapath of the paper's five macro stages and, beside it, the
//! magnitudes and error bounds that decide which signs are sure (golden
//! [`golden::tcheck`](crate::golden::tcheck), docs/explanation/architecture.md "T.CHECK in RTL",
//! docs/explanation/accuracy.md "T.CHECK's certificate").

mod dot;
mod edge;
mod sign;
mod vertex;
pub(crate) use dot::dot;
pub(crate) use edge::edge;
pub(crate) use sign::sign;
pub(crate) use vertex::vertex;

/// T.CHECK's ports (documented on `TCheck`), one list for every T.CHECK: declares the block
/// `name` (its doc attributes first) with them, then its own fields `rest`, then the output
/// registers every T.CHECK drives its outputs from. Arguments: `W` word width.
macro_rules! tcheck_ports {
    ($W:tt, $(#[$m:meta])* $name:ident { $($rest:tt)* }) => {
        $(#[$m])*
        #[derive(LogicBlock)]
        pub struct $name {
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
            $($rest)*
            // the output registers
            out_s_x: [DFF<Bits<$W>>; 3],
            out_s_b: [DFF<Bits<$W>>; 3],
            out_cross_t: [DFF<Bit>; 3],
            out_cross_f: [DFF<Bit>; 3],
            out_hit: DFF<Bit>,
            out_miss: DFF<Bit>,
            out_tag: DFF<Bits<32>>,
            out_valid: DFF<Bit>,
        }
    };
}
pub(crate) use tcheck_ports;

/// A T.CHECK block `name` with [`tcheck_ports!`]' ports and output registers at their
/// defaults and its own fields `rest` as given.
macro_rules! tcheck_new {
    ($name:ident { $($rest:tt)* }) => {
        $name {
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
            out_s_x: Default::default(),
            out_s_b: Default::default(),
            out_cross_t: Default::default(),
            out_cross_f: Default::default(),
            out_hit: Default::default(),
            out_miss: Default::default(),
            out_tag: Default::default(),
            out_valid: Default::default(),
            $($rest)*
        }
    };
}
pub(crate) use tcheck_new;

/// Stamps out `Sign`, `Dot`, `Vertex`, `Edge` and `TCheck` in the calling module (which
/// must also hold `FpMul`, `FpAdd` and `FORMAT`). Arguments: `W`, `WM1` = W-1, `E`, `F`.
macro_rules! tcheck {
    ($W:tt, $WM1:tt, $E:tt, $F:tt) => {
        use $crate::rtl::delay::Delay;

        /// All ones but the sign bit: a word ANDed with it is its absolute value.
        const ABS_MASK: u64 = (1u64 << $WM1) - 1;

        // the sub-blocks, one file each (src/rtl/tcheck/*.rs), then TCheck
        $crate::rtl::tcheck::sign!($W, $WM1, $E, $F);
        $crate::rtl::tcheck::dot!($W, $WM1);
        $crate::rtl::tcheck::vertex!($W, $E, $F);
        $crate::rtl::tcheck::edge!($W);
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
        $crate::rtl::tcheck::tcheck_ports! {
            $W,
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
            TCheck {
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
            }
        }

        impl TCheck {
            pub const LATENCY: usize = 1 + Dot::LATENCY + 1 + Dot::LATENCY + 1 + Edge::LATENCY + 2;

            /// A T.CHECK whose value datapath rounds with `rounding` (NearestEven or
            /// TowardPositive; the certificate's units always round upward).
            pub fn new(rounding: Rounding) -> Self {
                let cert = $crate::golden::certificate::Certificate::new(FORMAT, rounding);
                let up = Rounding::TowardPositive;
                $crate::rtl::tcheck::tcheck_new! { Self {
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
                } }
            }
        }

        $crate::rtl::kernel::kernel!([] TCheck: Inputs, Vertices, Edges);

        /// Clock 1's input register and stage 1, B's frame in A's: Mb = M_A^-1 M_B.
        struct Inputs;

        impl $crate::rtl::kernel::Kernel<Inputs> for TCheck {
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
            }
        }

        /// The input errors and stage 2: B's vertices in A's frame, with their error bounds and
        /// certificate terms.
        struct Vertices;

        impl $crate::rtl::kernel::Kernel<Vertices> for TCheck {
            #[hdl_gen]
            fn update(&mut self) {
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
            }
        }

        /// Stages 3-5, the three edges, and the verdict.
        struct Edges;

        impl $crate::rtl::kernel::Kernel<Edges> for TCheck {
            #[hdl_gen]
            fn update(&mut self) {
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
