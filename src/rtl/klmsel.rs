//! D.KLMSEL, the DOP unit's distance router, stamped out per format by `klmsel!`.

/// Stamps out `KlmSel<K>` in the calling module. Argument: `W` word width.
macro_rules! klmsel {
    ($W:tt) => {
        /// D.KLMSEL (combinational): for every lane i, routes `d[j0[i]]`, `d[j1[i]]`,
        /// `d[j2[i]]` of the k distances of B's node to `y0[i]`, `y1[i]`, `y2[i]`.
        /// The MUX controls `j0..j2` are the per-query [`HostSetup::j`](crate::golden::host::HostSetup)
        /// (`j0[i] = j[i][0]`, ...). A select of k or more routes 0.
        ///
        /// Each output is a k:1 multiplexer written as a loop comparing the select with
        /// every constant index `idx[a] = a` (rust-hdl kernels index arrays only with loop
        /// variables or literals). Ports (arrays become `d$0 .. d$K-1` in Verilog):
        /// in `d[K]`, `j0[K]`, `j1[K]`, `j2[K]` (5 bits); out `y0[K]`, `y1[K]`, `y2[K]`.
        #[derive(LogicBlock)]
        pub struct KlmSel<const K: usize> {
            pub d: [Signal<In, Bits<$W>>; K],
            pub j0: [Signal<In, Bits<5>>; K],
            pub j1: [Signal<In, Bits<5>>; K],
            pub j2: [Signal<In, Bits<5>>; K],
            pub y0: [Signal<Out, Bits<$W>>; K],
            pub y1: [Signal<Out, Bits<$W>>; K],
            pub y2: [Signal<Out, Bits<$W>>; K],
            idx: [Constant<Bits<5>>; K],
        }

        impl<const K: usize> KlmSel<K> {
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

        impl<const K: usize> Default for KlmSel<K> {
            fn default() -> Self {
                Self::new()
            }
        }

        impl<const K: usize> Logic for KlmSel<K> {
            #[hdl_gen]
            fn update(&mut self) {
                for i in 0..K {
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
