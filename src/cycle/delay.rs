//! What enters at rising edge `t` is at the output from cycle `t + latency` until it is
//! taken out: the cycle model's view of a pipeline (the RTL's
//! [`Delay`](crate::rtl::delay::Delay) and every pipelined unit, whose output is taken in
//! the cycle it shows) and of rust-hdl's synchronous FIFO (`declare_sync_fifo!`: the write
//! pointer reaches the read side through one more register, so an entry written at edge
//! `w` is at the head from cycle `w + 2`, [`FIFO_WRITE_TO_HEAD`](crate::chip::rtl::FIFO_WRITE_TO_HEAD), and stays until read).
//! Only the occupied stages are stored, so an idle pipeline costs nothing per clock (a
//! self-stalling pipe in the manner of gem5's minor CPU buffers).

use std::collections::VecDeque;

#[derive(Clone, Debug)]
pub struct Delay<T> {
    latency: u64,
    cap: usize,
    /// `(first cycle at the output, value)`, oldest first.
    items: VecDeque<(u64, T)>,
}

impl<T> Delay<T> {
    /// A pipeline of `latency` clocks holding any number of values.
    pub fn new(latency: u32) -> Self {
        Self::with_capacity(latency, usize::MAX)
    }

    /// At most `cap` values at once (a FIFO's entries).
    pub fn with_capacity(latency: u32, cap: usize) -> Self {
        assert!(latency >= 1, "a pipeline has at least one register");
        Delay {
            latency: latency as u64,
            cap,
            items: VecDeque::new(),
        }
    }

    /// Enters `v` at edge `now`. Panics if full: the chip's credits must prevent that (an
    /// RTL FIFO would drop the entry).
    pub fn push(&mut self, now: u64, v: T) {
        assert!(
            self.items.len() < self.cap,
            "a write into a full FIFO of {} entries",
            self.cap
        );
        self.items.push_back((now + self.latency, v));
    }

    /// The value at the output in cycle `now`, if any (a FIFO: not `empty`).
    pub fn out(&self, now: u64) -> Option<&T> {
        self.items
            .front()
            .filter(|(at, _)| *at <= now)
            .map(|(_, v)| v)
    }

    /// Takes out the value shown in cycle `now` (at its edge).
    pub fn pop(&mut self, now: u64) -> Option<T> {
        self.out(now)?;
        self.items.pop_front().map(|(_, v)| v)
    }

    /// Values in flight or waiting at the output.
    pub fn len(&self) -> usize {
        self.items.len()
    }

    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// Room for one more value.
    pub fn has_room(&self) -> bool {
        self.items.len() < self.cap
    }

    /// The first cycle the oldest value is at the output.
    pub fn next_out(&self) -> Option<u64> {
        self.items.front().map(|(at, _)| *at)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_value_comes_out_latency_cycles_later_and_waits_there() {
        let mut d = Delay::new(3);
        d.push(10, 'a');
        d.push(11, 'b');
        assert_eq!(d.out(12), None);
        assert_eq!(d.out(13), Some(&'a'));
        assert_eq!(d.pop(13), Some('a'));
        assert_eq!(d.out(13), None, "b is not out before cycle 14");
        assert_eq!(d.pop(20), Some('b'));
        assert!(d.is_empty());
    }

    #[test]
    fn a_fifo_entry_shows_two_cycles_after_its_write() {
        let mut f = Delay::with_capacity(crate::chip::rtl::FIFO_WRITE_TO_HEAD, 2);
        f.push(5, 1);
        f.push(6, 2);
        assert!(!f.has_room());
        assert_eq!(f.out(6), None);
        assert_eq!(f.pop(7), Some(1));
        assert_eq!(f.pop(8), Some(2));
        assert_eq!(f.pop(9), None);
    }
}
