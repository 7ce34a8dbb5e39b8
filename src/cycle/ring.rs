//! A double-ended queue in a buffer of a power-of-two size, its slots found with a mask:
//! the cycle model's queues (pipelines, FIFOs, the pair buffer, the requests outstanding,
//! D_CNTR's queue) are asked for their head and length several times a clock, and
//! `VecDeque`'s wrap-around (a compare and a conditional move at each access) was a fifth
//! of a clock's instructions (callgrind on `cycle::run_query`). It grows when full, so a
//! queue's bound stays its owner's to check.

#[derive(Clone, Debug)]
pub struct Ring<T> {
    /// The slots: empty, or a power of two of them.
    buf: Vec<T>,
    head: usize,
    len: usize,
}

impl<T: Copy> Default for Ring<T> {
    fn default() -> Self {
        Ring { buf: Vec::new(), head: 0, len: 0 }
    }
}

impl<T: Copy> Ring<T> {
    #[inline]
    fn slot(&self, i: usize) -> usize {
        (self.head + i) & (self.buf.len() - 1)
    }

    #[inline]
    pub fn len(&self) -> usize {
        self.len
    }

    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    #[inline]
    pub fn front(&self) -> Option<&T> {
        (self.len > 0).then(|| &self.buf[self.head])
    }

    #[inline]
    pub fn back(&self) -> Option<&T> {
        (self.len > 0).then(|| &self.buf[self.slot(self.len - 1)])
    }

    #[inline]
    pub fn push_back(&mut self, v: T) {
        if self.len == self.buf.len() {
            self.grow(v);
        }
        let s = self.slot(self.len);
        self.buf[s] = v;
        self.len += 1;
    }

    #[inline]
    pub fn pop_front(&mut self) -> Option<T> {
        let v = *self.front()?;
        self.head = self.slot(1);
        self.len -= 1;
        Some(v)
    }

    #[inline]
    pub fn pop_back(&mut self) -> Option<T> {
        let v = *self.back()?;
        self.len -= 1;
        Some(v)
    }

    pub fn clear(&mut self) {
        (self.head, self.len) = (0, 0);
    }

    /// Oldest first.
    pub fn iter(&self) -> impl Iterator<Item = &T> + '_ {
        (0..self.len).map(|i| &self.buf[self.slot(i)])
    }

    /// Twice the slots (8 at first), the entries from slot 0; `fill` fills the new slots.
    #[cold]
    fn grow(&mut self, fill: T) {
        let size = (2 * self.buf.len()).max(8);
        let mut buf: Vec<T> = self.iter().copied().collect();
        buf.resize(size, fill);
        (self.buf, self.head) = (buf, 0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against `VecDeque` through growth and wrap-around, from both ends.
    #[test]
    fn ring_is_a_deque() {
        let (mut r, mut q) = (Ring::default(), std::collections::VecDeque::new());
        for i in 0..200u32 {
            match i % 7 {
                0 | 3 => assert_eq!(r.pop_front(), q.pop_front()),
                5 => assert_eq!(r.pop_back(), q.pop_back()),
                _ => {
                    r.push_back(i);
                    q.push_back(i);
                }
            }
            assert_eq!((r.len(), r.front(), r.back()), (q.len(), q.front(), q.back()));
            assert!(r.iter().eq(q.iter()));
        }
        r.clear();
        assert!(r.is_empty() && r.front().is_none() && r.pop_front().is_none());
    }
}
