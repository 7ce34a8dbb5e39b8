//! A pipeline of fixed latency as the cycle model sees it (the RTL's
//! [`Delay`](crate::rtl::delay::Delay) and every pipelined unit): what enters at rising
//! edge `t` is at the output in cycle `t + latency` and leaves at that cycle's edge. Only
//! the occupied stages are stored, so an idle pipeline costs nothing per clock (a
//! self-stalling pipe in the manner of gem5's minor CPU buffers).

use std::collections::VecDeque;

#[derive(Clone, Debug)]
pub struct Delay<T> {
    latency: u64,
    /// `(cycle at the output, value)`, oldest first.
    items: VecDeque<(u64, T)>,
}

impl<T> Delay<T> {
    pub fn new(latency: u32) -> Self {
        assert!(latency >= 1, "a pipeline has at least one register");
        Delay { latency: latency as u64, items: VecDeque::new() }
    }

    /// Enters `v` at edge `now`.
    pub fn push(&mut self, now: u64, v: T) {
        self.items.push_back((now + self.latency, v));
    }

    /// The value at the output in cycle `now`, if any.
    pub fn out(&self, now: u64) -> Option<&T> {
        self.items.front().filter(|(at, _)| *at == now).map(|(_, v)| v)
    }

    /// Removes the value at the output in cycle `now` (at its edge).
    pub fn pop(&mut self, now: u64) -> Option<T> {
        if self.items.front().is_some_and(|(at, _)| *at == now) {
            self.items.pop_front().map(|(_, v)| v)
        } else {
            None
        }
    }

    /// Values in flight.
    pub fn len(&self) -> usize {
        self.items.len()
    }

    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// The cycle at which the oldest value reaches the output.
    pub fn next_out(&self) -> Option<u64> {
        self.items.front().map(|(at, _)| *at)
    }

    pub fn clear(&mut self) {
        self.items.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_value_comes_out_latency_cycles_later() {
        let mut d = Delay::new(3);
        d.push(10, 'a');
        d.push(11, 'b');
        assert_eq!(d.out(12), None);
        assert_eq!(d.out(13), Some(&'a'));
        assert_eq!(d.pop(13), Some('a'));
        assert_eq!(d.pop(13), None);
        assert_eq!(d.pop(14), Some('b'));
        assert!(d.is_empty());
    }
}
