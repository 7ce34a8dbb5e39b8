//! WSCG'03 Algorithm 2: visit each tumbled node X of B once (one DOP transform) and test it
//! against a list L of aligned nodes of A. Overlapping (X, N) puts N's children (or N itself
//! if N is a leaf) on the list for X's children; if X is a leaf, N's children go on a new
//! list for X itself (the paper's "overloaded" call), with no new transform.

use super::Engine;
use crate::dop::{DopTree, Node};

pub(crate) fn run(e: &mut Engine) {
    e.queue_add(1);
    count_list(e, 1);
    visit(e, DopTree::ROOT, vec![DopTree::ROOT]);
}

/// WSCG'03 Eq. 5 counts lists of aligned node pairs (sibling nodes are stored as one pair);
/// a list shared by two tumbled siblings is one list.
fn count_list(e: &mut Engine, nodes: usize) {
    e.counters.lists += 1;
    e.counters.list_node_pairs += nodes.div_ceil(2) as u64;
}

/// `list` is already counted as waiting; it is released here.
fn visit(e: &mut Engine, x: u32, list: Vec<u32>) {
    e.counters.dop_transforms += 1;
    let mut cur = list;
    loop {
        let mut for_children = Vec::new();
        let mut for_self = Vec::new();
        for &n in &cur {
            if e.stop {
                break;
            }
            if e.dop_test(n, x) {
                match (e.node_a(n), e.node_b(x)) {
                    (Node::Leaf(ta), Node::Leaf(tb)) => e.leaf_pair(ta, tb),
                    (Node::Inner(ch), Node::Leaf(_)) => for_self.extend(ch),
                    (Node::Leaf(_), Node::Inner(_)) => for_children.push(n),
                    (Node::Inner(ch), Node::Inner(_)) => for_children.extend(ch),
                }
            }
        }
        e.queue_remove(cur.len() as u64);
        if e.stop {
            return;
        }
        match e.node_b(x) {
            Node::Inner([x1, x2]) => {
                if !for_children.is_empty() {
                    // Both children's lists wait until they are processed.
                    e.queue_add(2 * for_children.len() as u64);
                    count_list(e, for_children.len());
                    let copy = for_children.clone();
                    visit(e, x1, copy);
                    if e.stop {
                        return;
                    }
                    visit(e, x2, for_children);
                }
                return;
            }
            Node::Leaf(_) => {
                if for_self.is_empty() {
                    return;
                }
                e.queue_add(for_self.len() as u64);
                count_list(e, for_self.len());
                cur = for_self;
            }
        }
    }
}
