//! A fixed delay line, for the operands that wait for a slower path to meet them.

use rust_hdl::prelude::*;

/// `q` is `d` delayed by `N >= 1` clocks (`N` registers, `d` enters `line$N-1`, `q` is `line$0`).
#[derive(LogicBlock)]
pub struct Delay<D: Synth, const N: usize> {
    pub clock: Signal<In, Clock>,
    pub d: Signal<In, D>,
    pub q: Signal<Out, D>,
    line: [DFF<D>; N],
}

impl<D: Synth, const N: usize> Default for Delay<D, N> {
    fn default() -> Self {
        assert!(N >= 1, "Delay: N >= 1");
        Self {
            clock: Default::default(),
            d: Default::default(),
            q: Default::default(),
            line: crate::rtl::reg_ring::array_init(),
        }
    }
}

impl<D: Synth, const N: usize> Logic for Delay<D, N> {
    /// The line runs from `line[N-1]` (input) down to `line[0]` (output), so that `q` is
    /// assigned once: an output written many times in one Verilog `always` block (a
    /// last-assignment-wins loop) makes Icarus wake its readers at every intermediate
    /// value, which slowed TRI_UNIT's simulation tenfold.
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..N {
            self.line[i].clock.next = self.clock.val();
            self.line[i].d.next = self.d.val();
        }
        // Every stage but the last (line[N-1], which keeps d) takes the one above it.
        for i in 1..N {
            self.line[i - 1].d.next = self.line[i].q.val();
        }
        self.q.next = self.line[0].q.val();
    }
}
