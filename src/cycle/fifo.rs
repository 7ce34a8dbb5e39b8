//! The synchronous FIFO of the RTL (rust-hdl's `SynchronousFIFO`, `declare_sync_fifo!`)
//! as the cycle model sees it: the write pointer reaches the read side through one more
//! register, so an entry written at rising edge `w` is at the head (not `empty`) from
//! cycle `w + 2`; a read at edge `t` removes the head shown in cycle `t`. Used for D_CNTR's
//! leaf FIFO and TRI_UNIT's result FIFO. The chip's credit rules keep both from filling,
//! so a write is never refused (checked).

use std::collections::VecDeque;

/// Clocks from a write to the entry's visibility at the head.
pub const WRITE_TO_HEAD: u64 = 2;

#[derive(Clone, Debug)]
pub struct SyncFifo<T> {
    cap: usize,
    /// `(first cycle at the head, value)`, oldest first.
    items: VecDeque<(u64, T)>,
}

impl<T> SyncFifo<T> {
    pub fn new(cap: usize) -> Self {
        SyncFifo { cap, items: VecDeque::new() }
    }

    /// Writes `v` at edge `now`. Panics if the FIFO is full: the chip's credit must
    /// prevent that (an RTL FIFO would drop the entry).
    pub fn write(&mut self, now: u64, v: T) {
        assert!(self.items.len() < self.cap, "a write into a full FIFO of {} entries", self.cap);
        self.items.push_back((now + WRITE_TO_HEAD, v));
    }

    /// The head in cycle `now` (`None`: the RTL's `empty`).
    pub fn head(&self, now: u64) -> Option<&T> {
        self.items.front().filter(|(at, _)| *at <= now).map(|(_, v)| v)
    }

    /// Reads the head shown in cycle `now` (at its edge).
    pub fn read(&mut self, now: u64) -> Option<T> {
        if self.head(now).is_some() {
            self.items.pop_front().map(|(_, v)| v)
        } else {
            None
        }
    }

    /// Entries written and not read (visible or not).
    pub fn len(&self) -> usize {
        self.items.len()
    }

    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// The first cycle the head is visible, if there is an entry.
    pub fn next_head(&self) -> Option<u64> {
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
    fn an_entry_shows_two_cycles_after_its_write() {
        let mut f = SyncFifo::new(2);
        f.write(5, 1);
        f.write(6, 2);
        assert_eq!(f.head(6), None);
        assert_eq!(f.head(7), Some(&1));
        assert_eq!(f.read(7), Some(1));
        assert_eq!(f.read(8), Some(2));
        assert_eq!(f.read(9), None);
    }
}
