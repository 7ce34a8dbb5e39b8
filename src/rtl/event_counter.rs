//! The chip's 32-bit event counters (its ports `dop_tests`, `tri_tests`, `node_fetches`,
//! `tri_fetches`), with the event registered before it is added.

use rust_hdl::prelude::*;

/// A counter that shows, every clock, the events seen at the edges since its last `clear`,
/// as a plain `count <= count + inc` would. The event is first held in a 1-bit register
/// and added a clock later: the logic that decides an event (the memory port's accept, the
/// pair queue's issue) and the 32-bit carry chain then lie in different clocks, where the
/// plain counter put both in one and set the narrow chips' period. `count` adds the held
/// event back (`total + pending`), so the port is exact every clock.
///
/// Ports: in `clock`, `clear` (to 0 at the edge, the event of this clock dropped), `inc` (an event);
/// out `count[32]`.
#[derive(LogicBlock, Default)]
pub struct EventCounter {
    pub clock: Signal<In, Clock>,
    pub clear: Signal<In, Bit>,
    pub inc: Signal<In, Bit>,
    pub count: Signal<Out, Bits<32>>,
    total: DFF<Bits<32>>,
    pending: DFF<Bit>,
}

impl Logic for EventCounter {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, total);
        self.pending.clock.next = self.clock.val();
        self.pending.d.next = self.inc.val();
        if self.pending.q.val() {
            self.total.d.next = self.total.q.val() + 1;
        }
        if self.clear.val() {
            self.total.d.next = 0.into();
            self.pending.d.next = false;
        }
        self.count.next = self.total.q.val() + bit_cast::<32, 1>(self.pending.q.val().into());
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn settle(uut: &mut EventCounter) {
        assert!(simulate(uut, 100), "logic did not settle");
    }

    /// Against the plain counter, every clock, with random events and clears.
    #[test]
    fn counts_as_the_plain_counter_every_clock() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let mut uut = EventCounter::default();
        uut.clock.connect();
        uut.clear.connect();
        uut.inc.connect();
        uut.connect_all();
        let mut plain = 0u64;
        for now in 0..4000 {
            let (event, clear) = (rng.random_bool(0.7), rng.random_bool(0.02));
            uut.inc.next = event;
            uut.clear.next = clear;
            uut.clock.next = Clock { clk: false };
            settle(&mut uut);
            assert_eq!(uut.count.val().to_u64(), plain, "clock {now}");
            uut.clock.next = Clock { clk: true };
            settle(&mut uut);
            plain = if clear { 0 } else { plain + event as u64 };
        }
    }
}
