//! A leading-zero counter in logarithmic depth, for the FPGA-depth FP units.

use rust_hdl::prelude::*;

/// Leading zeros of `x` (combinational; `N` <= 32, `lz` meaningless for `x = 0`), computed
/// without shifting `x`: `p` smears every one bit down to bit 0 (`p[i]` = any `x[j]`,
/// `j >= i`, five OR steps), `lead` keeps its top bit alone, and bit `k` of `lz` is the OR of
/// the `lead` bits whose count `N - 1 - i` has bit `k` (`mask<k>`). Every step is a balanced
/// OR tree, where the ASIC units' normaliser (`NormP`) is a chain of five shift-and-test
/// steps: on an FPGA that chain costs a LUT level and a routing hop per bit of the test.
#[derive(LogicBlock)]
pub struct Lzc<const N: usize> {
    pub x: Signal<In, Bits<N>>,
    pub lz: Signal<Out, Bits<5>>,
    mask0: Constant<Bits<N>>,
    mask1: Constant<Bits<N>>,
    mask2: Constant<Bits<N>>,
    mask3: Constant<Bits<N>>,
    mask4: Constant<Bits<N>>,
    p1: Signal<Local, Bits<N>>,
    p2: Signal<Local, Bits<N>>,
    p4: Signal<Local, Bits<N>>,
    p8: Signal<Local, Bits<N>>,
    p16: Signal<Local, Bits<N>>,
    lead: Signal<Local, Bits<N>>,
}

impl<const N: usize> Default for Lzc<N> {
    fn default() -> Self {
        assert!((1..=32).contains(&N), "Lzc: 1 <= N <= 32");
        let mask = |k: usize| {
            let m = (0..N).filter(|i| (N - 1 - i) >> k & 1 == 1);
            Constant::new(m.fold(0u64, |m, i| m | 1 << i).into())
        };
        Self {
            x: Default::default(),
            lz: Default::default(),
            mask0: mask(0),
            mask1: mask(1),
            mask2: mask(2),
            mask3: mask(3),
            mask4: mask(4),
            p1: Default::default(),
            p2: Default::default(),
            p4: Default::default(),
            p8: Default::default(),
            p16: Default::default(),
            lead: Default::default(),
        }
    }
}

impl<const N: usize> Logic for Lzc<N> {
    #[hdl_gen]
    fn update(&mut self) {
        self.p1.next = self.x.val() | (self.x.val() >> 1);
        self.p2.next = self.p1.val() | (self.p1.val() >> 2);
        self.p4.next = self.p2.val() | (self.p2.val() >> 4);
        self.p8.next = self.p4.val() | (self.p4.val() >> 8);
        self.p16.next = self.p8.val() | (self.p8.val() >> 16);
        self.lead.next = self.p16.val() & !(self.p16.val() >> 1);
        self.lz.next = bits::<5>(0)
            .replace_bit(4, (self.lead.val() & self.mask4.val()).any())
            .replace_bit(3, (self.lead.val() & self.mask3.val()).any())
            .replace_bit(2, (self.lead.val() & self.mask2.val()).any())
            .replace_bit(1, (self.lead.val() & self.mask1.val()).any())
            .replace_bit(0, (self.lead.val() & self.mask0.val()).any());
    }
}
