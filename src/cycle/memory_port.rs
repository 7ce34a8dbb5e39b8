//! The chip's memory port in the cycle model: the requests outstanding and where each
//! response goes ([`rtl::memory_port`](crate::rtl) builds the same port in RTL).

use crate::chip::layout::Dst;
use crate::chip::params::Params;
use std::collections::VecDeque;

/// The chip's memory port: up to `max` requests outstanding, at most one per triangle
/// destination (a response replaces its held word; node words queue for their pairs),
/// responses in request order. The RTL chip: `max` from host register [`PORT`](crate::chip::reg::PORT) (1 to 16).
#[derive(Clone, Debug)]
pub struct MemPort {
    max: usize,
    /// `(destination, id)` of the requests outstanding, oldest first.
    outstanding: VecDeque<(Dst, u32)>,
}

impl MemPort {
    pub fn new(max: u32) -> Self {
        assert!(
            (1..=Params::MAX_OUTSTANDING).contains(&max),
            "1 to {} requests outstanding",
            Params::MAX_OUTSTANDING
        );
        MemPort {
            max: max as usize,
            outstanding: VecDeque::new(),
        }
    }

    /// Can a request go out now, and to `d`?
    pub fn free(&self, d: Dst) -> bool {
        self.outstanding.len() < self.max
            && !(d.is_tri() && self.outstanding.iter().any(|o| o.0 == d))
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
    fn port_keeps_one_request_per_triangle_destination() {
        let mut p = MemPort::new(3);
        p.accept(Dst::TriA, 5);
        assert!(!p.free(Dst::TriA) && p.free(Dst::TriB) && p.free(Dst::NodeA));
        p.accept(Dst::NodeA, 6);
        assert!(p.free(Dst::NodeA));
        p.accept(Dst::NodeA, 7);
        assert!(!p.free(Dst::NodeB));
        assert_eq!(p.respond(), Some((Dst::TriA, 5)));
    }
}
