//! DATE'05 D_CNTR (§4.3): node pairs wait in a FIFO (breadth first) or a LIFO (depth
//! first), pushed and popped pairwise. The children of an overlapping pair (X, N) are
//! generated in the order that shares one DOP between consecutive tests, the
//! serpentine `Xa Na, Xa Nb, Xb Nb, Xb Na`: each pair carries a flip bit, and a pair with the
//! flip bit set starts with its second child. This reproduces the paper's FIFO sequence
//! `A1 - B2 B3 C3 C2 - D4 D5 E5 E4 - E6 E7 D7 D6 - F6 F7 G7 G6 - G4 G5 F5 F4`.

use crate::chip::layout::{Entry, Pair};
use crate::chip::reg::Order;
use crate::dop::{DopTree, Node};
use std::collections::VecDeque;

/// The child pairs of an overlapping pair in the DOP-sharing order, as queue entries of
/// two pairs: two entries for inner/inner, one for inner/leaf, none for leaf/leaf.
pub fn children(p: Pair, na: Node, nb: Node) -> ([Entry; 2], usize) {
    let ord = |c: [u32; 2]| if p.flip { [c[1], c[0]] } else { c };
    let entry = |(a0, b0): (u32, u32), (a1, b1): (u32, u32)| Entry {
        pairs: [
            Pair {
                a: a0,
                b: b0,
                flip: false,
            },
            Pair {
                a: a1,
                b: b1,
                flip: true,
            },
        ],
        len: 2,
    };
    match (na, nb) {
        (Node::Inner(ca), Node::Inner(cb)) => {
            let [xa, xb] = ord(ca);
            let [n1, n2] = cb;
            ([entry((xa, n1), (xa, n2)), entry((xb, n2), (xb, n1))], 2)
        }
        (Node::Inner(ca), Node::Leaf(_)) => {
            let [xa, xb] = ord(ca);
            let e = entry((xa, p.b), (xb, p.b));
            ([e, e], 1)
        }
        (Node::Leaf(_), Node::Inner(cb)) => {
            let [na_, nb_] = ord(cb);
            let e = entry((p.a, na_), (p.a, nb_));
            ([e, e], 1)
        }
        (Node::Leaf(_), Node::Leaf(_)) => unreachable!("leaf pairs go to TRI_UNIT"),
    }
}

/// D_CNTR's queue of entries, taken in its order: the root pair's entry first, then the
/// child entries of every overlapping pair as [`children`] orders them.
pub struct Queue {
    order: Order,
    q: VecDeque<Entry>,
}

impl Queue {
    /// The queue at a query's start: the root pair (0, 0).
    pub fn new(order: Order) -> Queue {
        let root = Pair {
            a: DopTree::ROOT,
            b: DopTree::ROOT,
            flip: false,
        };
        Queue {
            order,
            q: VecDeque::from([Entry {
                pairs: [root, root],
                len: 1,
            }]),
        }
    }

    /// The next entry: the oldest (FIFO) or the newest (LIFO).
    pub fn pop(&mut self) -> Option<Entry> {
        match self.order {
            Order::Fifo => self.q.pop_front(),
            Order::Lifo => self.q.pop_back(),
        }
    }

    /// Pushes the child entries of the overlapping pair `p` of nodes `na`, `nb` (not both
    /// leaves); returns how many.
    pub fn push_children(&mut self, p: Pair, na: Node, nb: Node) -> usize {
        let (ch, n) = children(p, na, nb);
        match self.order {
            Order::Fifo => ch[..n].iter().for_each(|&c| self.q.push_back(c)),
            // Reversed so that the first entry is popped next.
            Order::Lifo => ch[..n].iter().rev().for_each(|&c| self.q.push_back(c)),
        }
        n
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The paper's example: A(B(D,E),C(F,G)) against 1(2(4,5),3(6,7)), every pair
    /// overlapping, FIFO order.
    #[test]
    fn fifo_order_is_the_papers_sequence() {
        // Node ids: letters A..G = 0..6 and digits 1..7 = 0..6, both trees alike.
        let node = |n: u32| {
            if n < 3 {
                Node::Inner([2 * n + 1, 2 * n + 2])
            } else {
                Node::Leaf(n)
            }
        };
        let name = |p: &Pair| format!("{}{}", (b'A' + p.a as u8) as char, p.b + 1);
        let mut q = Queue::new(Order::Fifo);
        let mut seq = vec![];
        while let Some(ent) = q.pop() {
            for p in &ent.pairs[..ent.len as usize] {
                seq.push(name(p));
                if p.a < 3 || p.b < 3 {
                    q.push_children(*p, node(p.a), node(p.b));
                }
            }
        }
        assert_eq!(
            seq.join(" "),
            "A1 B2 B3 C3 C2 D4 D5 E5 E4 E6 E7 D7 D6 F6 F7 G7 G6 G4 G5 F5 F4"
        );
    }
}
