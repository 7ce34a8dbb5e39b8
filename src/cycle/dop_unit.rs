//! The DOP unit (DATE'05 Eq. 10: D.KLMSEL and k DOPTRF lanes, NOR of their flags) as the
//! cycle model sees it: a pipeline of [`Params::dop_latency`](super::Params) clocks (and a
//! decode stage's with stored DOP precision) whose
//! overlap comes from the golden model ([`TransformCache`]), with the RTL's side delay
//! line beside it (the pair and both nodes' leaf bits and children, what D_CNTR needs
//! when the result comes out).
//!
//! Folded (`dop_interval` ii > 1, `rtl::*::DopUnit<k>Fold<ii>`'s rhythm): its counter runs
//! 0 .. ii-1 from the first pair taken since reset and never stops, and `in_ready` is high
//! only while it is 0, so pairs are taken in cycles t0 + n ii; the latency is
//! [`Depth::dop_fold_latency`](crate::chip::rtl::Depth::dop_fold_latency)(ii) at the
//! parameters' depth, the RTL's.

use super::delay::Delay;
use crate::chip::config::ChipConfig;
use crate::chip::layout::Pair;
use crate::chip::params::Params;
use crate::chip::rtl::dop_decode_latency;
use crate::dop::Node;
use crate::golden::dop_unit::TransformCache;
use crate::golden::memory::ObjectImage;

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
    /// Clocks between pairs taken (`dop_interval`; 1: unfolded).
    interval: u64,
    /// The cycle of the first pair taken, where the folded unit's counter starts.
    first: Option<u64>,
}

impl<'a> DopUnit<'a> {
    /// The DOP unit with `p`'s interval and latency (the folded unit's for an interval over 1),
    /// after `cfg`'s decode stage ([`dop_decode_latency`]), for its k directions; Err if the
    /// interval does not divide k.
    pub fn new(
        a: &'a ObjectImage,
        b: &'a ObjectImage,
        values: TransformCache<'a>,
        p: &Params,
        cfg: &ChipConfig,
    ) -> Result<Self, String> {
        p.check_dop_interval(cfg.k)?;
        Ok(DopUnit {
            a,
            b,
            values,
            pipe: Delay::new(p.dop_unit_latency() + dop_decode_latency(cfg)),
            interval: p.dop_interval as u64,
            first: None,
        })
    }

    /// `in_ready` in cycle `now`: the folded unit's counter is 0 (always, unfolded).
    pub fn in_ready(&self, now: u64) -> bool {
        // unfolded without a division: this is asked every clock
        self.interval == 1
            || self
                .first
                .is_none_or(|t0| (now - t0).is_multiple_of(self.interval))
    }

    /// The first cycle after `now` where the folded unit's counter is 0 again, if it runs.
    pub fn next_slot(&self, now: u64) -> Option<u64> {
        self.first
            .filter(|_| self.interval > 1)
            .map(|t0| now + self.interval - (now - t0) % self.interval)
    }

    /// Takes the pair at edge `now`: B's node word as d, A's as e.
    pub fn issue(&mut self, now: u64, pair: Pair) {
        self.first.get_or_insert(now);
        let (na, nb) = (self.a.tree.node(pair.a), self.b.tree.node(pair.b));
        let overlap = self.values.overlap(pair.b, pair.a);
        self.pipe.push(
            now,
            DopResult {
                pair,
                na,
                nb,
                overlap,
            },
        );
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
