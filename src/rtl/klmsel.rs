//! D.KLMSEL, the DOP unit's distance router, stamped out per format by `klmsel!`.

/// Stamps out `KlmSel<K, N>` in the calling module. Argument: `W` word width.
macro_rules! klmsel {
    ($W:tt) => {
        /// D.KLMSEL (combinational): for each of N lanes i, routes `d[j0[i]]`, `d[j1[i]]`,
        /// `d[j2[i]]` of the K distances of B's node to `y0[i]`, `y1[i]`, `y2[i]` (N = K in the
        /// DOP unit; N = L lanes in the folded one, whose selects change with the pass).
        /// The MUX controls `j0..j2` are the per-query [`HostSetup::j`](crate::golden::host::HostSetup)
        /// (`j0[i] = j[i][0]`, ...). A select of k or more routes 0.
        ///
        /// Each output is a k:1 multiplexer written as a loop comparing the select with
        /// every constant index `idx[a] = a` (rust-hdl kernels index arrays only with loop
        /// variables or literals). Ports (arrays become `d$0 .. d$K-1` in Verilog):
        /// in `d[K]`, `j0[N]`, `j1[N]`, `j2[N]` (5 bits); out `y0[N]`, `y1[N]`, `y2[N]`.
        #[derive(LogicBlock)]
        pub struct KlmSel<const K: usize, const N: usize> {
            pub d: [Signal<In, Bits<$W>>; K],
            pub j0: [Signal<In, Bits<5>>; N],
            pub j1: [Signal<In, Bits<5>>; N],
            pub j2: [Signal<In, Bits<5>>; N],
            pub y0: [Signal<Out, Bits<$W>>; N],
            pub y1: [Signal<Out, Bits<$W>>; N],
            pub y2: [Signal<Out, Bits<$W>>; N],
            idx: [Constant<Bits<5>>; K],
        }

        impl<const K: usize, const N: usize> KlmSel<K, N> {
            pub fn new() -> Self {
                assert!(K <= 32, "KlmSel: k > 32 needs wider selects");
                Self {
                    d: $crate::rtl::reg_ring::array_init(),
                    j0: $crate::rtl::reg_ring::array_init(),
                    j1: $crate::rtl::reg_ring::array_init(),
                    j2: $crate::rtl::reg_ring::array_init(),
                    y0: $crate::rtl::reg_ring::array_init(),
                    y1: $crate::rtl::reg_ring::array_init(),
                    y2: $crate::rtl::reg_ring::array_init(),
                    idx: std::array::from_fn(|a| Constant::new((a as u64).into())),
                }
            }
        }

        impl<const K: usize, const N: usize> Default for KlmSel<K, N> {
            fn default() -> Self {
                Self::new()
            }
        }

        impl<const K: usize, const N: usize> Logic for KlmSel<K, N> {
            #[hdl_gen]
            fn update(&mut self) {
                for i in 0..N {
                    self.y0[i].next = 0.into();
                    self.y1[i].next = 0.into();
                    self.y2[i].next = 0.into();
                    for a in 0..K {
                        if self.j0[i].val() == self.idx[a].val() {
                            self.y0[i].next = self.d[a].val();
                        }
                        if self.j1[i].val() == self.idx[a].val() {
                            self.y1[i].next = self.d[a].val();
                        }
                        if self.j2[i].val() == self.idx[a].val() {
                            self.y2[i].next = self.d[a].val();
                        }
                    }
                }
            }
        }
    };
}
pub(crate) use klmsel;
