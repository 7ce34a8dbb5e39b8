//! The memory models that serve the chip's memory port ([`memory_port`](super::memory_port)),
//! of the parameters in [`chip::memory`](crate::chip::memory). The model is the testbench's
//! memory for every level: the cycle model, the rust-hdl driver and (the same rules in
//! Verilog) `scripts/verilog/chip_tb.v`.

use crate::chip::memory::{DdrClocks, MemClocks, MemTiming};
use std::collections::VecDeque;

/// What the memory did during a query.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct MemCounters {
    /// Words served.
    pub words: u64,
    /// DDR: accesses to an open row, to a closed or other row, and accesses that waited for
    /// their bank's previous access.
    pub page_hits: u64,
    pub page_misses: u64,
    pub bank_conflicts: u64,
}

/// DDR state: per bank its open row, the cycle it takes its next read of that row and the
/// cycle its last transfer ends; the data bus's free cycle.
#[derive(Clone, Debug)]
struct DdrState {
    d: DdrClocks,
    word_bytes: u64,
    bursts: u64,
    open: Vec<Option<u64>>,
    bank_ready: Vec<u64>,
    bank_idle: Vec<u64>,
    bus_free: u64,
}

/// The memory model's state during a query (cycle numbers as in the chip's trace).
/// Ideal: [`MemTiming`]. DDR ([`DdrClocks`]): a request is accepted in any cycle and answered
/// when its word is complete. Responses come in request order.
#[derive(Clone, Debug)]
pub struct MemModel {
    /// The ideal model's timing; with DDR, latency 1 and interval 1 (only the interval is
    /// used: one request accepted per clock).
    timing: MemTiming,
    /// Ideal: clocks a word takes on the bus (1 with DDR, whose bursts are its own).
    beats: u64,
    ddr: Option<DdrState>,
    /// `(cycle of the response, word address)` in request order.
    pending: VecDeque<(u64, u32)>,
    next_accept: u64,
    pub counters: MemCounters,
}

impl MemModel {
    /// The model of `m` for memory words of `word_bits` bits.
    pub fn new(m: MemClocks, word_bits: u32) -> Self {
        let (timing, beats, ddr) = match m {
            MemClocks::Ideal(t) => (
                t,
                t.bus_bits
                    .map_or(1, |b| (word_bits as u64).div_ceil(b as u64).max(1)),
                None,
            ),
            MemClocks::Ddr(d) => {
                let banks = d.part.banks as usize;
                let beat_bits = d.part.bus_bits as u64 * d.part.burst as u64;
                let state = DdrState {
                    d,
                    word_bytes: (word_bits as u64).div_ceil(8),
                    bursts: (word_bits as u64).div_ceil(beat_bits).max(1),
                    open: vec![None; banks],
                    bank_ready: vec![0; banks],
                    bank_idle: vec![0; banks],
                    bus_free: 0,
                };
                (MemTiming::default(), 1, Some(state))
            }
        };
        MemModel {
            timing,
            beats,
            ddr,
            pending: VecDeque::new(),
            next_accept: 0,
            counters: MemCounters::default(),
        }
    }

    /// `mem_req_ready` in cycle `cyc`.
    pub fn ready(&self, cyc: u64) -> bool {
        cyc >= self.next_accept
    }

    /// The response in cycle `cyc` (the word address), taken out of the model.
    pub fn respond(&mut self, cyc: u64) -> Option<u32> {
        if self.pending.front().is_some_and(|p| p.0 <= cyc) {
            self.counters.words += 1;
            self.pending.pop_front().map(|p| p.1)
        } else {
            None
        }
    }

    /// The chip's request in cycle `cyc` (taken if [`ready`](Self::ready)).
    pub fn request(&mut self, cyc: u64, addr: u32) {
        if !self.ready(cyc) {
            return;
        }
        let done = match &mut self.ddr {
            None => cyc + self.timing.latency as u64 + self.beats - 1,
            Some(s) => {
                let page = addr as u64 * s.word_bytes / s.d.part.page_bytes as u64;
                let (bank, row) = (
                    (page % s.d.part.banks as u64) as usize,
                    page / s.d.part.banks as u64,
                );
                let data = s.bursts * s.d.burst_clocks as u64;
                let hit = s.open[bank] == Some(row);
                let (cost, free) = if hit {
                    (s.d.hit as u64, s.bank_ready[bank])
                } else {
                    (s.d.miss as u64, s.bank_idle[bank])
                };
                let start = cyc.max(free);
                if start > cyc {
                    self.counters.bank_conflicts += 1;
                }
                if hit {
                    self.counters.page_hits += 1;
                } else {
                    self.counters.page_misses += 1;
                }
                let done = (start + cost + data - s.d.burst_clocks as u64).max(s.bus_free + data);
                s.open[bank] = Some(row);
                // the read command goes out `cost - hit` after the start (the row opened);
                // the next read of the row a transfer after it, its CAS latency overlapping
                s.bank_ready[bank] = start + cost - s.d.hit as u64 + data;
                s.bank_idle[bank] = done;
                s.bus_free = done;
                done
            }
        };
        self.pending.push_back((done, addr));
        self.next_accept = cyc + (self.timing.interval as u64).max(self.beats);
    }

    /// The cycle of the next response, if a request is pending.
    pub fn next_response(&self) -> Option<u64> {
        self.pending.front().map(|p| p.0)
    }

    /// The first cycle a request is accepted.
    pub fn next_ready(&self) -> u64 {
        self.next_accept
    }

    /// Nothing requested and unanswered.
    pub fn is_idle(&self) -> bool {
        self.pending.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chip::memory::{Ddr, Memory};

    /// WSCG'03's memory at the paper's 266 MHz: 8 clocks a burst and a hit, 20 a miss.
    fn wscg03() -> MemClocks {
        Memory::Ddr(Ddr::WSCG03).at(3759).unwrap()
    }

    #[test]
    fn model_answers_after_latency_and_spaces_requests() {
        let mut m = MemModel::new(
            MemTiming {
                latency: 3,
                interval: 2,
                bus_bits: None,
            }
            .into(),
            64,
        );
        assert!(m.ready(0));
        m.request(1, 7);
        assert!(!m.ready(2) && m.ready(3));
        m.request(2, 8); // not ready: ignored
        m.request(3, 9);
        assert_eq!(m.respond(3), None);
        assert_eq!(m.respond(4), Some(7));
        assert_eq!(m.respond(5), None);
        assert_eq!(m.respond(6), Some(9));
        assert!(m.is_idle());
        assert!(MemTiming {
            latency: 0,
            ..Default::default()
        }
        .check()
        .is_err());
        assert!(MemTiming {
            bus_bits: Some(0),
            ..Default::default()
        }
        .check()
        .is_err());
    }

    /// A 200-bit word on a 64-bit bus moves in 4 clocks: latency 3 answers a request at 1 in
    /// the cycle ending with edge 1 + 3 + 3 = 7, and the bus takes the next request at 5,
    /// although the memory could take one every clock; on a 256-bit bus, as without a width.
    #[test]
    fn a_narrow_bus_moves_a_word_in_several_clocks() {
        let mut m = MemModel::new(
            MemTiming {
                latency: 3,
                interval: 1,
                bus_bits: Some(64),
            }
            .into(),
            200,
        );
        m.request(1, 7);
        assert!(!m.ready(4) && m.ready(5));
        m.request(5, 8);
        assert_eq!((m.respond(6), m.respond(7)), (None, Some(7)));
        assert_eq!((m.respond(10), m.respond(11)), (None, Some(8)));
        let mut m = MemModel::new(
            MemTiming {
                latency: 3,
                interval: 1,
                bus_bits: Some(256),
            }
            .into(),
            200,
        );
        m.request(1, 7);
        assert!(m.ready(2));
        assert_eq!((m.respond(3), m.respond(4)), (None, Some(7)));
    }

    /// WSCG'03's numbers by hand: 256-byte words (one burst of 8 beats of 256 bits), 4 KiB
    /// pages, so words 0..15 are page 0 (bank 0), 16..31 page 1 (bank 1), ..., 64.. page 4
    /// (bank 0, row 1).
    #[test]
    fn ddr_pages_banks_and_the_bus_by_hand() {
        let mut m = MemModel::new(wscg03(), 2048);
        // a miss at 0: done at 0 + 20
        m.request(0, 0);
        // page 0 is now open: a hit requested at 1 waits for bank 0 (free at 20): 20 + 8
        m.request(1, 1);
        // bank 1, a miss at 2: its command part (12) overlaps, its data waits for the bus
        // (free at 28): max(2 + 20, 28 + 8) = 36
        m.request(2, 16);
        // bank 0 again, row 1: a miss after bank 0's last access (28): max(28 + 20, 36 + 8) = 48
        m.request(3, 64);
        for (cyc, addr) in [(20, 0), (28, 1), (36, 16), (48, 64)] {
            assert_eq!(m.next_response(), Some(cyc));
            assert_eq!(m.respond(cyc - 1), None);
            assert_eq!(m.respond(cyc), Some(addr));
        }
        assert_eq!(
            m.counters,
            MemCounters {
                words: 4,
                page_hits: 1,
                page_misses: 3,
                bank_conflicts: 2
            }
        );
        // a word of 2 bursts (257 bytes) moves in 16 clocks: a miss costs 20 + 8
        let mut m = MemModel::new(wscg03(), 2056);
        m.request(5, 0);
        assert_eq!(m.next_response(), Some(33));
        assert!(Ddr {
            hit_ps: 29_999,
            ..Ddr::WSCG03
        }
        .check()
        .unwrap_err()
        .contains("burst x beat_ns <= hit_ns <= miss_ns"));
        assert!(Ddr {
            banks: 0,
            ..Ddr::WSCG03
        }
        .check()
        .unwrap_err()
        .contains("banks"));
        assert!(Ddr {
            banks: 65,
            ..Ddr::WSCG03
        }
        .check()
        .unwrap_err()
        .contains("at most 64 banks"));
        assert_eq!(Ddr::preset("wscg03"), Some(Ddr::WSCG03));
        assert_eq!(Ddr::preset("ddr9"), None);
    }

    /// DATE'05's DDR2 at 800 MHz by hand (a burst 4 clocks, a hit 14, a miss 34; 3024-bit
    /// words of 378 bytes, one burst each; 8 KiB pages, so words 0..=21 are page 0, bank 0): reads of an
    /// open row stream a burst apart, their CAS latency overlapping; a row change waits for
    /// its bank's last transfer.
    #[test]
    fn reads_of_an_open_row_stream_at_the_bus_rate() {
        let mut m = MemModel::new(Memory::Ddr(Ddr::DATE05).at(1250).unwrap(), 3024);
        // a miss at 0: its read command at 34 - 14 = 20, data done at 34
        m.request(0, 0);
        // hits at 1, 2, 3: each read a burst after the last (24, 28, 32), data 4 apart
        for (cyc, addr) in [(1, 1), (2, 2), (3, 3)] {
            m.request(cyc, addr);
        }
        // word 176 (page 8: bank 0, row 1): a miss after bank 0's last transfer (46): 80
        m.request(4, 176);
        // bank 1 (word 22: page 1), a miss at 5: its command part overlaps, 5 + 34 = 39,
        // but the bus is busy until 80: 84
        m.request(5, 22);
        for (cyc, addr) in [(34, 0), (38, 1), (42, 2), (46, 3), (80, 176), (84, 22)] {
            assert_eq!(m.respond(cyc - 1), None);
            assert_eq!(m.respond(cyc), Some(addr));
        }
        assert_eq!(
            (
                m.counters.page_hits,
                m.counters.page_misses,
                m.counters.bank_conflicts
            ),
            (3, 3, 4)
        );
    }

    /// The same DDR2 nanoseconds in the clocks of three chips, by hand: DATE'05's DDR2-800
    /// (a burst 4 x 1.25 = 5 ns, a hit 17.5 ns, a miss 42.5 ns) at the paper's 1.25 ns is
    /// 4, 14 and 34 clocks; at half the period twice as many; at 6.944 ns, rounded up,
    /// ceil(0.72) = 1, ceil(2.52) = 3, ceil(6.12) = 7.
    #[test]
    fn a_faster_clock_waits_more_clocks_for_the_same_ddr() {
        let at = |ps| match Memory::Ddr(Ddr::DATE05).at(ps).unwrap() {
            MemClocks::Ddr(c) => (c.burst_clocks, c.hit, c.miss),
            _ => unreachable!(),
        };
        assert_eq!(at(1250), (4, 14, 34));
        assert_eq!(at(625), (8, 28, 68));
        assert_eq!(at(6944), (1, 3, 7));
        // a query's first access, a page miss, answered after twice the clocks
        let first = |ps| {
            let mut m = MemModel::new(Memory::Ddr(Ddr::DATE05).at(ps).unwrap(), 3024);
            m.request(0, 0);
            m.next_response()
        };
        assert_eq!((first(1250), first(625)), (Some(34), Some(68)));
        let slow = Ddr {
            miss_ps: 2_000_000,
            ..Ddr::DATE05
        };
        assert!(slow.at(2).is_ok() && slow.at(1).unwrap_err().contains("over the"));
    }
}
