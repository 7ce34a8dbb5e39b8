//! WSCG'03 Algorithm 1: simultaneous recursive descent; a leaf meets the children of an
//! inner node (the "mixed" cases the paper omits). Each DOP test transforms B's DOP anew.

use super::Engine;
use crate::dop::{DopTree, Node};

pub(crate) fn run(e: &mut Engine) {
    descend(e, DopTree::ROOT, DopTree::ROOT);
}

fn descend(e: &mut Engine, na: u32, nb: u32) {
    if e.stop {
        return;
    }
    e.counters.dop_transforms += 1;
    if !e.dop_test(na, nb) {
        return;
    }
    match (e.node_a(na), e.node_b(nb)) {
        (Node::Leaf(ta), Node::Leaf(tb)) => e.leaf_pair(ta, tb),
        (Node::Inner(ca), Node::Inner(cb)) => {
            for a in ca {
                for b in cb {
                    descend(e, a, b);
                }
            }
        }
        (Node::Inner(ca), Node::Leaf(_)) => ca.iter().for_each(|&a| descend(e, a, nb)),
        (Node::Leaf(_), Node::Inner(cb)) => cb.iter().for_each(|&b| descend(e, na, b)),
    }
}
