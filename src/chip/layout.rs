//! Bit layouts every level agrees on: the memory words (node and triangle records) and
//! where each object's records start in the memory image, the memory port's destinations,
//! and D_CNTR's queue entry.
//!
//! Memory words, with W the width of the datapath's format (docs/ARCHITECTURE.md, "DOP tree
//! and memory image"):
//! - node word, `1 + k*W + 64` bits: `is_leaf`, d_0..d_{k-1}, then two 32-bit fields:
//!   children (inner node) or triangle index and 0 (leaf), pre-order, root at node 0;
//! - triangle word, `23*W + 2` bits: vertices v0, v1, v2 (x, y, z each), M_B row-major
//!   (3x4), the error words `alpha_m`, `alpha_f` ([`TriWord`](crate::golden::memory::TriWord)),
//!   the `v_exact` bit and the `degenerate` bit.
//!
//! The memory image holds one word per record: A's nodes, A's triangles, B's nodes, B's
//! triangles ([`image_bases`]).
//!
//! D_CNTR's entry ([`Entry`]) is two node pairs, pushed and popped together; a pair is A's
//! node, B's node (16 bits each) and the flip bit that orders its children
//! ([`golden::d_cntr`](crate::golden::d_cntr)). Entry word, bit 0 first:
//!
//! | bits | field |
//! |---|---|
//! | 15:0 | `pairs[0].a` |
//! | 31:16 | `pairs[0].b` |
//! | 32 | `pairs[0].flip` |
//! | 48:33 | `pairs[1].a` |
//! | 64:49 | `pairs[1].b` |
//! | 65 | `pairs[1].flip` |
//! | 66 | `len - 1` (0: one pair, the root entry; 1: two pairs) |
//!
//! i.e. in Verilog `{len-1, p1.flip, p1.b, p1.a, p0.flip, p0.b, p0.a}`. `pairs[1]` is
//! stored as it is also when `len` is 1, so `unpack(pack(e)) == e` for every entry.
//! Node ids are 16 bits: trees of up to 65,536 nodes.

use super::config::ChipConfig;

/// Bits of a node word: the leaf bit, k distances of `w` bits, two 32-bit fields.
pub const fn node_bits(k: usize, w: usize) -> usize {
    1 + k * w + 64
}

/// Bits of a triangle word: 23 values of `w` bits and two flags.
pub const fn tri_bits(w: usize) -> usize {
    23 * w + 2
}

/// Bits of a memory word: the wider record.
pub const fn word_bits(k: usize, dop_w: usize, tri_w: usize) -> usize {
    let (n, t) = (node_bits(k, dop_w), tri_bits(tri_w));
    if n > t { n } else { t }
}

/// Word sizes of one configuration.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Layout {
    pub node_bits: u32,
    pub tri_bits: u32,
}

impl Layout {
    pub fn new(cfg: &ChipConfig) -> Layout {
        let (dop_w, tri_w) = (cfg.format.dop.width() as usize, cfg.format.tri.width() as usize);
        Layout { node_bits: node_bits(cfg.k, dop_w) as u32, tri_bits: tri_bits(tri_w) as u32 }
    }
    /// A memory word holds either record: the wider one.
    pub fn word_bits(&self) -> u32 {
        self.node_bits.max(self.tri_bits)
    }
    pub fn node_bytes(&self) -> u64 {
        self.node_bits.div_ceil(8) as u64
    }
    pub fn tri_bytes(&self) -> u64 {
        self.tri_bits.div_ceil(8) as u64
    }
}


/// Where a memory word goes: the node words for the DOP unit (A's, B's) and the triangle
/// words held for TRI_UNIT (A's, B's). Triangle words are asked for first, A's before B's;
/// node words in the order of their pairs (docs/ARCHITECTURE.md, "Cycle semantics").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum Dst {
    NodeA = 0,
    NodeB = 1,
    TriA = 2,
    TriB = 3,
}

impl Dst {
    pub fn is_tri(self) -> bool {
        matches!(self, Dst::TriA | Dst::TriB)
    }
}

/// Word addresses of A's node 0, B's node 0, A's triangle 0, B's triangle 0 (indexed by
/// [`Dst`]) for objects of `na`/`nb` nodes and `ta` triangles in A: A's nodes, A's
/// triangles, B's nodes, B's triangles, one word each.
pub fn image_bases(na: u32, ta: u32, nb: u32) -> [u32; 4] {
    [0, na + ta, na, na + ta + nb]
}

/// A node pair: A's node, B's node, the flip bit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Pair {
    pub a: u32,
    pub b: u32,
    pub flip: bool,
}

/// One queue entry: two pairs (one for the root pair), pushed and popped together.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Entry {
    pub pairs: [Pair; 2],
    pub len: u8,
}

/// The entry of the all-zero word: one pair, (0, 0) (what an empty queue shows).
impl Default for Entry {
    fn default() -> Self {
        Entry { pairs: [Pair::default(); 2], len: 1 }
    }
}

/// Bits of an entry word.
pub const ENTRY_BITS: u32 = 67;
/// Bits of a node id in an entry word.
pub const NODE_BITS: u32 = 16;
const PAIR_BITS: u32 = 2 * NODE_BITS + 1;
/// The entry word's bits in a `u128`.
pub const ENTRY_MASK: u128 = (1 << ENTRY_BITS) - 1;

fn pack_pair(p: &Pair) -> u128 {
    assert!(p.a < 1 << NODE_BITS && p.b < 1 << NODE_BITS, "node ids of {p:?} do not fit {NODE_BITS} bits");
    p.a as u128 | (p.b as u128) << NODE_BITS | (p.flip as u128) << (2 * NODE_BITS)
}

fn unpack_pair(w: u128) -> Pair {
    let m = (1u128 << NODE_BITS) - 1;
    Pair { a: (w & m) as u32, b: (w >> NODE_BITS & m) as u32, flip: w >> (2 * NODE_BITS) & 1 == 1 }
}

/// The entry word of `e` (layout in the module doc). Panics if a node id needs more than
/// 16 bits or `len` is not 1 or 2.
pub fn pack(e: &Entry) -> u128 {
    assert!(e.len == 1 || e.len == 2, "entry length {}", e.len);
    pack_pair(&e.pairs[0]) | pack_pair(&e.pairs[1]) << PAIR_BITS | ((e.len - 1) as u128) << (2 * PAIR_BITS)
}

/// The entry of a word (bits above 66 ignored); the inverse of [`pack`].
pub fn unpack(w: u128) -> Entry {
    let m = (1u128 << PAIR_BITS) - 1;
    Entry { pairs: [unpack_pair(w & m), unpack_pair(w >> PAIR_BITS & m)], len: 1 + (w >> (2 * PAIR_BITS) & 1) as u8 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pack_round_trips_and_places_the_fields() {
        let p = |a, b, flip| Pair { a, b, flip };
        let e = Entry { pairs: [p(0x1234, 0xffff, true), p(0, 0xabcd, false)], len: 2 };
        let w = pack(&e);
        assert_eq!(w & 0xffff, 0x1234);
        assert_eq!(w >> 16 & 0xffff, 0xffff);
        assert_eq!(w >> 32 & 1, 1);
        assert_eq!(w >> 49 & 0xffff, 0xabcd);
        assert_eq!(w >> 66, 1);
        assert_eq!(unpack(w), e);
        let root = Entry { pairs: [p(0, 0, false); 2], len: 1 };
        assert_eq!(pack(&root), 0);
        assert_eq!(unpack(pack(&root)), root);
        assert_eq!(unpack(ENTRY_MASK), Entry { pairs: [p(0xffff, 0xffff, true); 2], len: 2 });
    }
}
