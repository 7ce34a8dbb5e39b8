//! The register ring: the DFF array behind the chip's small FIFOs (D_CNTR's pair buffer,
//! the memory port's node-word FIFOs and request tags), with its clock, hold, one-hot write
//! and one-hot read written once instead of once per array.

use rust_hdl::prelude::*;

/// `N` registers of `W` bits that hold their value unless written. Whoever owns the ring
/// keeps its pointers and decodes them (`c_one << ptr`): at the rising edge `wdata` is
/// written into every row whose bit of `wsel` is set (one-hot, or 0: none); `rdata` shows
/// the row of `rsel`'s set bit (one-hot; 0 when `rsel` is 0), a function of the registers
/// and `rsel` only, so a row written at an edge is read from the next cycle on.
///
/// Ports: in `clock`, `wsel[N]`, `wdata[W]`, `rsel[N]`; out `rdata[W]`.
#[derive(LogicBlock)]
pub struct RegRing<const W: usize, const N: usize> {
    pub clock: Signal<In, Clock>,
    pub wsel: Signal<In, Bits<N>>,
    pub wdata: Signal<In, Bits<W>>,
    pub rsel: Signal<In, Bits<N>>,
    pub rdata: Signal<Out, Bits<W>>,
    row: [DFF<Bits<W>>; N],
    picked: Signal<Local, Bits<W>>,
}

impl<const W: usize, const N: usize> Default for RegRing<W, N> {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            wsel: Default::default(),
            wdata: Default::default(),
            rsel: Default::default(),
            rdata: Default::default(),
            row: array_init(),
            picked: Default::default(),
        }
    }
}

impl<const W: usize, const N: usize> Logic for RegRing<W, N> {
    #[hdl_gen]
    fn update(&mut self) {
        // `rdata` assigned once (Icarus wakes an output's readers at every assignment)
        self.picked.next = 0.into();
        for i in 0..N {
            self.row[i].clock.next = self.clock.val();
            self.row[i].d.next = self.row[i].q.val();
            if self.wsel.val().get_bit(i) {
                self.row[i].d.next = self.wdata.val();
            }
            if self.rsel.val().get_bit(i) {
                self.picked.next = self.row[i].q.val();
            }
        }
        self.rdata.next = self.picked.val();
    }
}

/// An array of `N` default blocks or signals (rust-hdl's `[T; N]: Default` stops at 32
/// elements): the constructors' `std::array::from_fn(|_| Default::default())`, once.
pub fn array_init<T: Default, const N: usize>() -> [T; N] {
    std::array::from_fn(|_| T::default())
}
