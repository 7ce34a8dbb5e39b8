//! Exact broadphase: a median-split AABB tree over one triangle set, queried with each
//! triangle of the other. Boxes are exact (min/max of coordinates) and compared with closed
//! comparisons, so no intersecting pair is ever culled; survivors go to the exact test.

use super::exact::{boxes_overlap, classify, shapes_intersect, tri_box, Shape};
use super::Tri;

type Box3 = [[f64; 3]; 2];

const LEAF_SIZE: usize = 4;

/// One triangle of the tree side, in tree order.
struct Item {
    bb: Box3,
    shape: Shape,
    idx: u32,
}

/// Node in depth-first order: an inner node's left child is the next node, `right` the other;
/// a leaf has `count > 0` items starting at `start`.
struct Node {
    bb: Box3,
    start_or_right: u32,
    count: u32,
}

pub(crate) struct Tree {
    nodes: Vec<Node>,
    items: Vec<Item>,
}

fn merge(a: &Box3, b: &Box3) -> Box3 {
    let mut r = *a;
    for i in 0..3 {
        r[0][i] = r[0][i].min(b[0][i]);
        r[1][i] = r[1][i].max(b[1][i]);
    }
    r
}

impl Tree {
    pub(crate) fn new(tris: &[Tri]) -> Tree {
        let mut items: Vec<Item> = tris
            .iter()
            .enumerate()
            .map(|(i, t)| Item {
                bb: tri_box(t),
                shape: classify(t),
                idx: i as u32,
            })
            .collect();
        let mut nodes = Vec::with_capacity(2 * tris.len() / LEAF_SIZE + 2);
        if !items.is_empty() {
            build(&mut items, 0, &mut nodes);
        }
        Tree { nodes, items }
    }

    /// Calls `hit(j)` for every tree triangle `j` intersecting `shape` (with box `bb`).
    /// `stack` is a reusable scratch buffer.
    #[inline]
    pub(crate) fn query(
        &self,
        bb: &Box3,
        shape: &Shape,
        stack: &mut Vec<u32>,
        mut hit: impl FnMut(u32),
    ) {
        if self.nodes.is_empty() {
            return;
        }
        stack.clear();
        stack.push(0);
        while let Some(n) = stack.pop() {
            let node = &self.nodes[n as usize];
            if !boxes_overlap(&node.bb, bb) {
                continue;
            }
            if node.count > 0 {
                let s = node.start_or_right as usize;
                for it in &self.items[s..s + node.count as usize] {
                    if boxes_overlap(&it.bb, bb) && shapes_intersect(shape, &it.shape) {
                        hit(it.idx);
                    }
                }
            } else {
                stack.push(node.start_or_right);
                stack.push(n + 1);
            }
        }
    }
}

fn build(items: &mut [Item], offset: usize, nodes: &mut Vec<Node>) -> usize {
    let me = nodes.len();
    let mut bb = items[0].bb;
    // Box of the centroids (times two) for the split axis; only a heuristic.
    let mut cl = [f64::INFINITY; 3];
    let mut ch = [f64::NEG_INFINITY; 3];
    for it in items.iter() {
        bb = merge(&bb, &it.bb);
        for i in 0..3 {
            let c = it.bb[0][i] + it.bb[1][i];
            cl[i] = cl[i].min(c);
            ch[i] = ch[i].max(c);
        }
    }
    nodes.push(Node {
        bb,
        start_or_right: offset as u32,
        count: items.len() as u32,
    });
    if items.len() <= LEAF_SIZE {
        return me;
    }
    let ext = [ch[0] - cl[0], ch[1] - cl[1], ch[2] - cl[2]];
    let ax = if ext[0] >= ext[1] && ext[0] >= ext[2] {
        0
    } else if ext[1] >= ext[2] {
        1
    } else {
        2
    };
    let mid = items.len() / 2;
    items.select_nth_unstable_by(mid, |a, b| {
        let ka = a.bb[0][ax] + a.bb[1][ax];
        let kb = b.bb[0][ax] + b.bb[1][ax];
        ka.total_cmp(&kb)
    });
    let (l, r) = items.split_at_mut(mid);
    build(l, offset, nodes);
    let right = build(r, offset + mid, nodes);
    nodes[me].count = 0;
    nodes[me].start_or_right = right as u32;
    me
}

/// See [`super::intersecting_pairs`].
pub(crate) fn intersecting_pairs(a: &[Tri], b: &[Tri]) -> Vec<(u32, u32)> {
    let tree = Tree::new(b);
    let mut out = Vec::new();
    let mut stack = Vec::with_capacity(64);
    let mut js: Vec<u32> = Vec::with_capacity(64);
    for (i, t) in a.iter().enumerate() {
        let bb = tri_box(t);
        let shape = classify(t);
        js.clear();
        tree.query(&bb, &shape, &mut stack, |j| js.push(j));
        js.sort_unstable();
        out.extend(js.iter().map(|&j| (i as u32, j)));
    }
    out
}
