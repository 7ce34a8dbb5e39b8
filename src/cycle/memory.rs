//! The memory side of the chip: its memory port (requests outstanding and where each
//! response goes) and the memory model that serves it. The model is the testbench's
//! memory for every level: the cycle model, the rust-hdl driver and (the same rules in
//! Verilog) `scripts/verilog/chip_tb.v`.

use std::collections::VecDeque;

/// The memory model: a request accepted at rising edge `t` is answered in the cycle that
/// ends with edge `t + latency` (`mem_resp_valid` high, the chip takes it at that edge);
/// after an accepted request the next is accepted `interval` edges later at the earliest
/// (the memory's throughput is `1 / interval` words per clock). Responses come in request
/// order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MemTiming {
    pub latency: u32,
    pub interval: u32,
}

impl Default for MemTiming {
    fn default() -> Self {
        MemTiming { latency: 1, interval: 1 }
    }
}

impl MemTiming {
    /// Errors unless both are at least 1.
    pub fn check(&self) -> Result<(), String> {
        if self.latency == 0 || self.interval == 0 {
            return Err(format!(
                "memory latency and interval must be at least 1 clock (got latency {}, interval {})",
                self.latency, self.interval
            ));
        }
        Ok(())
    }
}

/// The memory model's state during a query (cycle numbers as in the chip's trace).
#[derive(Clone, Debug)]
pub struct MemModel {
    timing: MemTiming,
    /// `(cycle of the response, word address)` in request order.
    pending: VecDeque<(u64, u32)>,
    next_accept: u64,
    /// Words served.
    pub words: u64,
}

impl MemModel {
    pub fn new(timing: MemTiming) -> Self {
        MemModel { timing, pending: VecDeque::new(), next_accept: 0, words: 0 }
    }

    /// `mem_req_ready` in cycle `cyc`.
    pub fn ready(&self, cyc: u64) -> bool {
        cyc >= self.next_accept
    }

    /// The response in cycle `cyc` (the word address), taken out of the model.
    pub fn respond(&mut self, cyc: u64) -> Option<u32> {
        if self.pending.front().is_some_and(|p| p.0 <= cyc) {
            self.words += 1;
            self.pending.pop_front().map(|p| p.1)
        } else {
            None
        }
    }

    /// The chip's request in cycle `cyc` (taken if [`ready`](Self::ready)).
    pub fn request(&mut self, cyc: u64, addr: u32) {
        if self.ready(cyc) {
            self.pending.push_back((cyc + self.timing.latency as u64, addr));
            self.next_accept = cyc + self.timing.interval as u64;
        }
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

/// Where a memory word goes: the node words held for the DOP unit (A's, B's) and the
/// triangle words held for TRI_UNIT (A's, B's). Request priority is the reverse: triangle
/// words first, A's before B's (docs/ARCHITECTURE.md, "Cycle semantics").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum Dst {
    NodeA = 0,
    NodeB = 1,
    TriA = 2,
    TriB = 3,
}

impl Dst {
    /// Request priority, highest first.
    pub const PRIORITY: [Dst; 4] = [Dst::TriA, Dst::TriB, Dst::NodeA, Dst::NodeB];

    pub fn is_tri(self) -> bool {
        matches!(self, Dst::TriA | Dst::TriB)
    }
}

/// The chip's memory port: up to `max` requests outstanding, at most one per destination
/// (a response replaces the held word of its destination), responses in request order.
/// The RTL chip has `max` = 1.
#[derive(Clone, Debug)]
pub struct MemPort {
    max: usize,
    /// `(destination, id)` of the requests outstanding, oldest first.
    outstanding: VecDeque<(Dst, u32)>,
}

impl MemPort {
    pub fn new(max: u32) -> Self {
        assert!((1..=4).contains(&max), "1 to 4 requests outstanding (one per destination)");
        MemPort { max: max as usize, outstanding: VecDeque::new() }
    }

    /// Can a request go out now, and to `d`?
    pub fn free(&self, d: Dst) -> bool {
        self.outstanding.len() < self.max && !self.outstanding.iter().any(|o| o.0 == d)
    }

    /// An accepted request for the word `id` of `d`.
    pub fn accept(&mut self, d: Dst, id: u32) {
        self.outstanding.push_back((d, id));
    }

    /// The response arriving now belongs to the oldest request.
    pub fn respond(&mut self) -> Option<(Dst, u32)> {
        self.outstanding.pop_front()
    }

    /// Requests outstanding.
    pub fn len(&self) -> usize {
        self.outstanding.len()
    }

    pub fn is_empty(&self) -> bool {
        self.outstanding.is_empty()
    }

}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn model_answers_after_latency_and_spaces_requests() {
        let mut m = MemModel::new(MemTiming { latency: 3, interval: 2 });
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
        assert!(MemTiming { latency: 0, interval: 1 }.check().is_err());
    }

    #[test]
    fn port_keeps_one_request_per_destination() {
        let mut p = MemPort::new(2);
        assert!(p.free(Dst::NodeA));
        p.accept(Dst::NodeA, 5);
        assert!(!p.free(Dst::NodeA) && p.free(Dst::NodeB));
        p.accept(Dst::NodeB, 6);
        assert!(!p.free(Dst::TriA));
        assert_eq!(p.respond(), Some((Dst::NodeA, 5)));
    }
}
