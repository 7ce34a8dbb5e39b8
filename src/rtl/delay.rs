//! A fixed delay line, for the operands that wait for a slower path to meet them.

use rust_hdl::prelude::*;

/// `q` is `d` delayed by `N >= 1` clocks (`N` registers `line$0 .. line$N-1`).
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
        Self { clock: Default::default(), d: Default::default(), q: Default::default(), line: std::array::from_fn(|_| Default::default()) }
    }
}

impl<D: Synth, const N: usize> Logic for Delay<D, N> {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..N {
            self.line[i].clock.next = self.clock.val();
        }
        self.line[0].d.next = self.d.val();
        for i in 1..N {
            self.line[i].d.next = self.line[i - 1].q.val();
        }
        // The last assignment wins: q is line[N - 1].
        for i in 0..N {
            self.q.next = self.line[i].q.val();
        }
    }
}
