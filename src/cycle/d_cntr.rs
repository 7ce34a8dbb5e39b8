//! D_CNTR's pair queue (DATE'05 §4.3) in the cycle model: the reference the RTL
//! [`PairQueue`](crate::rtl::d_cntr::PairQueue) must equal on every output after every
//! clock (on entry words), the queue of the cycle-model chip (on [`Entry`] values, so
//! that trees of any size fit).
//!
//! The entry and its word are [`chip::layout`](crate::chip::layout)'s.

use crate::chip::layout::{Entry, ENTRY_MASK};
use crate::chip::reg::Order;
use std::collections::VecDeque;

/// The queue's inputs in one clock cycle (the RTL's ports; `T` the entry: the RTL's
/// 67-bit word, or an [`Entry`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QueueIn<T = u128> {
    /// Empty the queue, reset `max_count` and `overflow`, latch `order`; push and pop of
    /// the same cycle are ignored.
    pub clear: bool,
    /// The order for the query, latched by `clear`: LIFO (depth first) or FIFO (the RTL's
    /// `lifo` bit).
    pub order: Order,
    pub push: bool,
    /// The entry pushed (a word: bits above 66 ignored).
    pub push_data: T,
    /// Remove the entry shown on `top_data`; ignored while empty.
    pub pop: bool,
    /// An entry pushed after `push_data` by the second write port (the chip at issue
    /// spacing 1 pushes both child entries of a DOP result in one clock).
    pub push2: Option<T>,
}

/// The queue's outputs after a rising edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QueueOut<T = u128> {
    pub empty: bool,
    pub full: bool,
    /// Entries held, 0..=2^N.
    pub count: u32,
    /// The largest `count` since the last clear.
    pub max_count: u32,
    /// Sticky until clear: a push while full without a pop in the same cycle (the entry
    /// was not stored).
    pub overflow: bool,
    /// The entry a pop in the next cycle removes (FIFO: the oldest, LIFO: the newest); 0
    /// while empty (`T::default()`).
    pub top_data: T,
}

/// What the queue stores: bits above the entry word's are dropped from a word.
pub trait QueueEntry: Copy + Default {
    fn masked(self) -> Self;
}

impl QueueEntry for u128 {
    fn masked(self) -> Self {
        self & ENTRY_MASK
    }
}

impl QueueEntry for Entry {
    fn masked(self) -> Self {
        self
    }
}

/// The pair queue, one rising clock edge per [`step`](Self::step). Initial state: empty,
/// FIFO, `max_count` 0, no overflow (as after a clear in FIFO order; the RTL's
/// registers start there too).
#[derive(Clone, Debug)]
pub struct QueueModel<T = u128> {
    cap: usize,
    order: Order,
    q: VecDeque<T>,
    max_count: u32,
    overflow: bool,
}

impl<T: QueueEntry> QueueModel<T> {
    /// A queue of `2^n` entries (the RTL's `PairQueue<N>`).
    pub fn new(n: u32) -> Self {
        assert!(n <= 16, "capacity 2^{n}");
        Self::with_capacity(1 << n)
    }

    /// A queue of `cap` entries (at least 1).
    pub fn with_capacity(cap: usize) -> Self {
        assert!(cap >= 1, "a queue of no entries");
        QueueModel {
            cap,
            order: Order::Fifo,
            q: VecDeque::new(),
            max_count: 0,
            overflow: false,
        }
    }

    /// Entries it holds when full.
    pub fn capacity(&self) -> usize {
        self.cap
    }

    /// The order latched by the last clear.
    pub fn order(&self) -> Order {
        self.order
    }

    /// The outputs in the current state.
    pub fn outputs(&self) -> QueueOut<T> {
        let top = if self.order == Order::Lifo {
            self.q.back()
        } else {
            self.q.front()
        };
        QueueOut {
            empty: self.q.is_empty(),
            full: self.q.len() == self.cap,
            count: self.q.len() as u32,
            max_count: self.max_count,
            overflow: self.overflow,
            top_data: top.copied().unwrap_or_default(),
        }
    }

    /// One rising edge with inputs `i`; returns the outputs after it. A pop (if not
    /// empty) happens before the push, in both orders: FIFO pop removes the head and the
    /// push appends; LIFO pop removes the top and the pushed entry becomes the new top.
    /// So a push while full succeeds if the same cycle pops. `push2` follows `push`.
    pub fn step(&mut self, i: &QueueIn<T>) -> QueueOut<T> {
        if i.clear {
            self.q.clear();
            self.order = i.order;
            self.max_count = 0;
            self.overflow = false;
        } else {
            if i.pop {
                if self.order == Order::Lifo {
                    self.q.pop_back();
                } else {
                    self.q.pop_front();
                }
            }
            if i.push {
                self.push(i.push_data);
            }
            if let Some(d) = i.push2 {
                self.push(d);
            }
            self.max_count = self.max_count.max(self.q.len() as u32);
        }
        self.outputs()
    }

    /// Stores `d`, or sets `overflow` if full.
    fn push(&mut self, d: T) {
        if self.q.len() < self.cap {
            self.q.push_back(d.masked());
        } else {
            self.overflow = true;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn model_orders_and_overflow() {
        let (push, pop) = (
            |d| QueueIn {
                push: true,
                push_data: d,
                ..Default::default()
            },
            QueueIn {
                pop: true,
                ..Default::default()
            },
        );
        for order in [Order::Fifo, Order::Lifo] {
            let lifo = order == Order::Lifo;
            let mut m = QueueModel::<u128>::new(1);
            m.step(&QueueIn {
                clear: true,
                order,
                ..Default::default()
            });
            m.step(&push(1));
            m.step(&push(2));
            let o = m.step(&push(3));
            assert!(o.full && o.overflow && o.count == 2 && o.max_count == 2);
            assert_eq!(o.top_data, if lifo { 2 } else { 1 });
            // push and pop while full: no overflow needed, both happen
            let o = m.step(&QueueIn {
                push: true,
                push_data: 4,
                pop: true,
                ..Default::default()
            });
            assert_eq!((o.count, o.top_data), (2, if lifo { 4 } else { 2 }));
            m.step(&pop);
            let o = m.step(&pop);
            assert!(o.empty && o.top_data == 0 && o.overflow && o.max_count == 2);
            let o = m.step(&QueueIn {
                clear: true,
                order,
                ..Default::default()
            });
            assert!(!o.overflow && o.max_count == 0);
            // two pushes in one clock, the second last in (LIFO: on top); the second
            // overflows a queue with room for one
            m.step(&push(5));
            let o = m.step(&QueueIn {
                push2: Some(7),
                ..push(6)
            });
            assert!(o.full && o.overflow && o.count == 2);
            assert_eq!(o.top_data, if lifo { 6 } else { 5 });
            m.step(&QueueIn {
                clear: true,
                order,
                ..Default::default()
            });
            let o = m.step(&QueueIn {
                push2: Some(7),
                ..push(6)
            });
            assert_eq!((o.count, o.top_data), (2, if lifo { 7 } else { 6 }));
        }
    }
}
