//! TRI_UNIT (DATE'05 §4.2: two T.CHECKs, the Kleene OR of their verdicts, the result
//! FIFO) as the cycle model sees it: a pair taken at edge `t` shows its verdict at the
//! output in cycle `t + tri_latency` (the RTL: T.CHECK's pipeline, then the FIFO's write
//! and read registers) and waits there until it is given out. `in_ready` is low while
//! `fifo` pairs are taken and not yet given out, so the FIFO never overflows. Verdicts come
//! from the golden TRI_UNIT ([`golden::tri_unit::TriUnit`](crate::golden::tri_unit::TriUnit)).

use super::delay::Delay;
use crate::golden::tri_unit::TriUnit as Values;
use crate::golden::tri_unit::TriResult;
use crate::golden::memory::ObjectImage;

/// A verdict at TRI_UNIT's output: the triangle pair (A's, B's) and the result.
#[derive(Clone, Copy, Debug)]
pub struct TriOut {
    pub a: u32,
    pub b: u32,
    pub res: TriResult,
}

impl TriOut {
    /// Intersecting or uncertain: shown at the result port (a separate pair is not).
    pub fn kept(&self) -> bool {
        self.res.hit || self.res.uncertain
    }

    /// A sure hit (stops a first-hit query).
    pub fn sure_hit(&self) -> bool {
        self.res.hit && !self.res.uncertain
    }
}

pub struct TriUnit<'a> {
    a: &'a ObjectImage,
    b: &'a ObjectImage,
    values: Values<'a>,
    /// Pairs taken and not given out.
    open: Delay<TriOut>,
}

impl<'a> TriUnit<'a> {
    pub fn new(a: &'a ObjectImage, b: &'a ObjectImage, values: Values<'a>, latency: u32, depth: u32) -> Self {
        TriUnit { a, b, values, open: Delay::with_capacity(latency, depth as usize) }
    }

    /// `in_ready`: the result FIFO has room for one more pair.
    pub fn in_ready(&self) -> bool {
        self.open.has_room()
    }

    /// Takes the pair of triangles `(ta, tb)` at edge `now`.
    pub fn take(&mut self, now: u64, ta: u32, tb: u32) {
        let res = self.values.test(ta, &self.a.tri(ta), tb, &self.b.tri(tb));
        self.open.push(now, TriOut { a: ta, b: tb, res });
    }

    /// The verdict at the output in cycle `now` (`out_valid`).
    pub fn out(&self, now: u64) -> Option<&TriOut> {
        self.open.out(now)
    }

    /// Gives out the verdict shown in cycle `now` (at its edge).
    pub fn give(&mut self, now: u64) {
        self.open.pop(now);
    }

    /// Pairs taken and not given out (the RTL's `tri_open`, and TRI_UNIT's `count`).
    pub fn open(&self) -> usize {
        self.open.len()
    }

    /// The first cycle a verdict is at the output, if any pair is open.
    pub fn next_out(&self) -> Option<u64> {
        self.open.next_out()
    }
}
