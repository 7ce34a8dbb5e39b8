//! TRI_UNIT (DATE'05 §4.2: two T.CHECKs, the Kleene OR of their verdicts, the result
//! FIFO) as the cycle model sees it: a pair taken at edge `t` shows its verdict at the
//! output in cycle `t + tri_latency` (the RTL: T.CHECK's pipeline, then the FIFO's write
//! and read registers) and waits there until it is given out. `in_ready` is low while
//! `fifo` pairs are taken and not yet given out, so the FIFO never overflows. Verdicts come
//! from the golden TRI_UNIT ([`golden::tri_unit::TriUnit`](crate::golden::tri_unit::TriUnit)).
//!
//! Folded (`tri_interval` ii > 1, `rtl::b32::TriUnitFold`'s rhythm): its control counter
//! runs 0 .. ii-1 from the first pair taken since reset and never stops, and `in_ready` is
//! high only while it is 0, so pairs are taken in cycles t0 + n ii; the latency is the
//! folded unit's, [`fold::tri_unit_latency`].

use super::delay::Delay;
use crate::chip::params::Params;
use crate::fold;
use crate::golden::memory::{Held, ObjectImage, TriWord};
use crate::golden::tri_unit::TriResult;
use crate::golden::tri_unit::TriUnit as Values;
use crate::traversal::{keep_words, spare_words};

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
    /// The triangle words used last, as the golden model holds them: made from the f64
    /// triangle (M_B's inverse) only when not held, also by the thread's query before
    /// ([`spare_words`]).
    words: [Held<TriWord>; 2],
    values: Values<'a>,
    /// Pairs taken and not given out.
    open: Delay<TriOut>,
    /// Clocks between pairs taken (`tri_interval`; 1: unfolded).
    interval: u64,
    /// The cycle of the first pair taken, where the folded unit's counter starts.
    first: Option<u64>,
}

impl Drop for TriUnit<'_> {
    fn drop(&mut self) {
        keep_words(std::mem::take(&mut self.words));
    }
}

impl<'a> TriUnit<'a> {
    /// TRI_UNIT with `p`'s interval, latency (the folded unit's schedule's for an interval
    /// over 1) and FIFO depth.
    pub fn new(
        a: &'a ObjectImage,
        b: &'a ObjectImage,
        values: Values<'a>,
        p: &Params,
    ) -> Result<Self, String> {
        let latency = match p.tri_interval {
            1 => p.tri_latency,
            ii => fold::tri_unit_latency(&fold::tri_unit_plan(
                ii as usize,
                fold::plan::Binding::Shared,
                p.depth,
            )?) as u32,
        };
        let open = Delay::with_capacity(latency, p.tri_fifo as usize);
        Ok(TriUnit {
            a,
            b,
            words: spare_words(a, b),
            values,
            open,
            interval: p.tri_interval as u64,
            first: None,
        })
    }

    /// `in_ready` in cycle `now`: the result FIFO has room for one more pair, and the
    /// folded unit's counter is 0.
    pub fn in_ready(&self, now: u64) -> bool {
        // unfolded without a division: this is asked every clock
        self.open.has_room()
            && (self.interval == 1
                || self
                    .first
                    .is_none_or(|t0| (now - t0).is_multiple_of(self.interval)))
    }

    /// The first cycle after `now` where the folded unit's counter is 0 again, if it runs.
    pub fn next_slot(&self, now: u64) -> Option<u64> {
        self.first
            .filter(|_| self.interval > 1)
            .map(|t0| now + self.interval - (now - t0) % self.interval)
    }

    /// Takes the pair of triangles `(ta, tb)` at edge `now`.
    pub fn take(&mut self, now: u64, ta: u32, tb: u32) {
        self.first.get_or_insert(now);
        let ((a, b), [wa, wb]) = ((self.a, self.b), &mut self.words);
        let res = self
            .values
            .test(ta, wa.get(ta, || a.tri(ta)), tb, wb.get(tb, || b.tri(tb)));
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
