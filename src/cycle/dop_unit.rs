//! The DOP unit (DATE'05 Eq. 10: D.KLMSEL and k DOPTRF lanes, NOR of their flags) as the
//! cycle model sees it: a pipeline of [`Params::dop_latency`](super::Params) clocks whose
//! overlap comes from the golden model ([`TransformCache`]), with the RTL's side delay
//! line beside it (the pair and both nodes' leaf bits and children, what D_CNTR needs
//! when the result comes out).

use super::delay::Delay;
use crate::dop::Node;
use crate::golden::dop_unit::TransformCache;
use crate::golden::memory::ObjectImage;
use crate::chip::layout::Pair;

/// A DOP test at the unit's output: its pair, both nodes and the verdict.
#[derive(Clone, Copy, Debug)]
pub struct DopResult {
    pub pair: Pair,
    pub na: Node,
    pub nb: Node,
    pub overlap: bool,
}

pub struct DopUnit<'a> {
    a: &'a ObjectImage,
    b: &'a ObjectImage,
    values: TransformCache<'a>,
    pipe: Delay<DopResult>,
}

impl<'a> DopUnit<'a> {
    pub fn new(a: &'a ObjectImage, b: &'a ObjectImage, values: TransformCache<'a>, latency: u32) -> Self {
        DopUnit { a, b, values, pipe: Delay::new(latency) }
    }

    /// Takes the pair at edge `now`: B's node word as d, A's as e.
    pub fn issue(&mut self, now: u64, pair: Pair) {
        let (na, nb) = (self.a.tree.node(pair.a), self.b.tree.node(pair.b));
        let overlap = self.values.overlap(pair.b, &self.b.tree.dop(pair.b), &self.a.tree.dop(pair.a));
        self.pipe.push(now, DopResult { pair, na, nb, overlap });
    }

    /// The result at the output in cycle `now` (`valid_out`).
    pub fn out(&self, now: u64) -> Option<&DopResult> {
        self.pipe.out(now)
    }

    /// Removes the result shown in cycle `now` (a result is out for that cycle only).
    pub fn retire(&mut self, now: u64) -> Option<DopResult> {
        self.pipe.pop(now)
    }

    /// Tests in flight.
    pub fn in_flight(&self) -> usize {
        self.pipe.len()
    }

    pub fn next_out(&self) -> Option<u64> {
        self.pipe.next_out()
    }
}
