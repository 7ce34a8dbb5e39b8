//! Bit layouts every level agrees on: the memory words (node and triangle records) and
//! where each object's records start in the memory image, the memory port's destinations,
//! and D_CNTR's queue entry.
//!
//! Memory words, with W the width of the datapath's format (docs/explanation/architecture.md, "DOP tree
//! and memory image"):
//! - node word, `1 + k*W + 64` bits: `is_leaf`, d_0..d_{k-1}, then two 32-bit fields:
//!   the children's ids ([`node_ids`]; inner node) or triangle index and 0 (leaf;
//!   `records`: the triangle's record), pre-order, root at node 0;
//! - triangle word, `23*W + 2` bits: vertices v0, v1, v2 (x, y, z each), M_B row-major
//!   (3x4), the error words `alpha_m`, `alpha_f` ([`TriWord`](crate::golden::memory::TriWord)),
//!   the `v_exact` bit and the `degenerate` bit.
//!
//! The memory image holds A's node records, A's triangles, B's node records, B's triangles
//! ([`image_bases`]), in one of two layouts ([`MemLayout`]): `words`, one node word per
//! record, every record one memory word of the wider kind; `records`, the
//! two children of an inner node in one record ([`treelet_records`]), every record padded to
//! a power of two bytes, and the records of a DDR memory spread over its banks
//! ([`RecordMap`]): slot 0's node word in bits `0 .. node_bits`, slot 1's from `node_bits`
//! (a triangle word from bit 0), the chip naming a node `2 record + slot` ([`node_ids`]).
//! With stored DOP precision (`dop_bits = b`: [`DopBits`], [`dop::stored`](crate::dop::stored);
//! `records` only) a node word holds `b`-bit codes in place of its distances (`1 + k*b + 64`
//! bits); a record holds a treelet, [`Layout::levels`] levels below its treelet root
//! ([`treelet_records`]: slot s's node word from bit `s * node_bits`), and after its node
//! words what they share: the treelet root's k distances (`k*W` bits) and an exponent per
//! plane ([`exp_field_bits`] each, `e - e_lo`). The root's record holds its distances in full
//! (as its shared distances, below which its codes are 0).
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

use super::config::{ChipConfig, DopBits, MemLayout};
use super::memory::Memory;
use crate::format::Format;

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
    if n > t {
        n
    } else {
        t
    }
}

/// Bits of a [`MemLayout::Records`] memory word: a node pair or a triangle word, padded to a
/// power of two bytes.
pub const fn record_bits(k: usize, dop_w: usize, tri_w: usize) -> usize {
    padded_record(2 * node_bits(k, dop_w), tri_bits(tri_w))
}

/// The wider of a node pair's `pair` bits and a triangle word's `tri`, padded to a power of
/// two bytes.
const fn padded_record(pair: usize, tri: usize) -> usize {
    8 * (if pair > tri { pair } else { tri })
        .div_ceil(8)
        .next_power_of_two()
}

/// The exponents a record of `b`-bit codes ([`DopBits`]) may hold, `e_lo ..= e_hi`: from the
/// DOP format's smallest subnormal (so `q 2^e` is a value of the format) to the largest with
/// `(2^b - 1) 2^e` at most its largest finite value (so `q 2^e` never overflows; `b` at
/// most the format's precision).
pub const fn exp_range(fmt: Format, bits: u32) -> (i32, i32) {
    let emax = fmt.bias();
    (1 - emax - fmt.frac_bits() as i32, emax + 1 - bits as i32)
}

/// Bits of a record's exponent field: every exponent of [`exp_range`], stored as `e - e_lo`.
pub const fn exp_field_bits(fmt: Format, bits: u32) -> u32 {
    let (lo, hi) = exp_range(fmt, bits);
    ((hi - lo + 1) as u32).next_power_of_two().trailing_zeros()
}

/// Word sizes of one configuration, and its layout.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Layout {
    pub node_bits: u32,
    pub tri_bits: u32,
    /// Bits a `records` record holds once for its nodes: with stored DOP precision
    /// ([`DopBits`]), the treelet root's k distances and an exponent per plane
    /// ([`dop::stored`](crate::dop::stored)); else 0.
    pub shared_bits: u32,
    /// Tree levels a `records` record holds: as many as fit in the full-precision node pair's
    /// record with stored DOP precision (up to [`MAX_RECORD_LEVELS`]); 1, a node pair, else.
    pub levels: u32,
    pub kind: MemLayout,
}

/// The most tree levels a record holds.
pub const MAX_RECORD_LEVELS: u32 = 3;

/// Node words a record of `levels` levels holds: a node's children, grandchildren, ...
pub const fn record_nodes(levels: u32) -> u32 {
    (1 << (levels + 1)) - 2
}

/// Whether a node at `depth` (the root's 0) is a treelet root: its record holds its
/// descendants `1 ..= levels` below it.
pub const fn treelet_root(depth: u32, levels: u32) -> bool {
    depth.is_multiple_of(levels)
}

/// Levels a `records` record holds: with stored DOP precision, as many (up to
/// [`MAX_RECORD_LEVELS`]) as fit in the configuration's record of full precision, so that a
/// burst that carried a node pair carries a treelet; else 1.
const fn record_levels(full_record: usize, shared: usize, node: usize, tri: usize) -> u32 {
    let mut l = MAX_RECORD_LEVELS;
    while l > 1 && padded_record(shared + record_nodes(l) as usize * node, tri) > full_record {
        l -= 1;
    }
    l
}

impl Layout {
    pub const fn new(cfg: &ChipConfig) -> Layout {
        let (dop, tri_w) = (cfg.format.dop, cfg.format.tri.width() as usize);
        let (plane, shared) = match cfg.dop_bits {
            DopBits::Full => (dop.width(), 0),
            DopBits::Bits(b) => (b, dop.width() + exp_field_bits(dop, b)),
        };
        let (node, shared) = (node_bits(cfg.k, plane as usize), cfg.k * shared as usize);
        let full = record_bits(cfg.k, dop.width() as usize, tri_w);
        Layout {
            node_bits: node as u32,
            tri_bits: tri_bits(tri_w) as u32,
            shared_bits: shared as u32,
            levels: match cfg.dop_bits {
                DopBits::Full => 1,
                DopBits::Bits(_) => record_levels(full, shared, node, tri_bits(tri_w)),
            },
            kind: cfg.layout,
        }
    }
    /// Bits of a memory word: `words`, the wider of a node word and a triangle word;
    /// `records`, a node pair (and what it shares) or a triangle word padded to a power of
    /// two bytes.
    pub fn word_bits(&self) -> u32 {
        match self.kind {
            MemLayout::Words => self.node_bits.max(self.tri_bits),
            MemLayout::Records => padded_record(
                (record_nodes(self.levels) * self.node_bits + self.shared_bits) as usize,
                self.tri_bits as usize,
            ) as u32,
        }
    }
    pub fn node_bytes(&self) -> u64 {
        self.node_bits.div_ceil(8) as u64
    }
    pub fn tri_bytes(&self) -> u64 {
        self.tri_bits.div_ceil(8) as u64
    }
    /// Bytes a node record and a triangle record take in the image (and on the bus per fetch).
    pub fn record_bytes(&self) -> [u64; 2] {
        match self.kind {
            MemLayout::Words => [self.node_bytes(), self.tri_bytes()],
            MemLayout::Records => [self.word_bits() as u64 / 8; 2],
        }
    }
}

/// The record of every node of a tree whose node `n` has the children `children(n)` (none for
/// a leaf), nodes numbered in pre-order from the root 0. `words`: node n in record n.
/// `records` ([`treelet_records`]).
pub fn node_records(kind: MemLayout, levels: u32, children: &[Option<[u32; 2]>]) -> Vec<u32> {
    match kind {
        MemLayout::Words => (0..children.len() as u32).collect(),
        MemLayout::Records => treelet_records(children, levels).rec,
    }
}

/// The record of every triangle of an object whose leaves, in pre-order, hold the triangles
/// `leaves` (each triangle once). `words`: triangle t in record t. `records`: in leaf order,
/// so that the triangles of neighbouring leaves are neighbours in memory too.
pub fn tri_records(kind: MemLayout, leaves: &[u32]) -> Vec<u32> {
    let mut rec: Vec<u32> = (0..leaves.len() as u32).collect();
    if kind == MemLayout::Records {
        leaves
            .iter()
            .zip(0..)
            .for_each(|(&t, i)| rec[t as usize] = i);
    }
    rec
}

/// [`MemLayout::Records`]'s record and slot of every node: the root in record 0, alone; then
/// a record per treelet root (an inner node whose depth is a multiple of `levels`:
/// [`treelet_root`]), in pre-order from 1, holding its descendants 1 to `levels` below it
/// breadth first: slot `2^d - 2 + path` at depth d below it, `path` the d child choices (0:
/// first child) read as a binary number. One level: the j-th inner node's children in record
/// j + 1, slots 0 and 1. Also each node's treelet root, whose record holds it (the root its
/// own: record 0).
pub fn treelet_records(children: &[Option<[u32; 2]>], levels: u32) -> Treelets {
    let n = children.len();
    let (mut rec, mut slot, mut root) = (vec![0; n], vec![0; n], vec![0; n]);
    let (mut depth, mut path) = (vec![0u32; n], vec![0u32; n]);
    let mut next = 1;
    for p in 0..n {
        let Some(c) = children[p] else { continue };
        let (own, own_root) = if treelet_root(depth[p], levels) {
            next += 1;
            (next - 1, p as u32)
        } else {
            (rec[p], root[p])
        };
        let below = if treelet_root(depth[p], levels) {
            0
        } else {
            path[p] * 2
        };
        let d = depth[p] % levels + 1;
        for (which, &m) in c.iter().enumerate() {
            let m = m as usize;
            (depth[m], path[m]) = (depth[p] + 1, below + which as u32);
            (rec[m], slot[m], root[m]) = (own, (1 << d) - 2 + path[m], own_root);
        }
    }
    Treelets { rec, slot, root }
}

/// [`treelet_records`]' answer, by node.
pub struct Treelets {
    pub rec: Vec<u32>,
    pub slot: Vec<u32>,
    pub root: Vec<u32>,
}

/// Bits of a node id's slot field in the `records` layout: a record of `levels` levels'
/// node words numbered to the next power of two ([`node_ids`]).
pub const fn slot_bits(levels: u32) -> u32 {
    record_nodes(levels).next_power_of_two().trailing_zeros()
}

/// The id the chip knows each node by (in D_CNTR's entries and the children fields of node
/// words). `words`: its pre-order number. `records`: `record << s | slot`
/// ([`treelet_records`]), `s` the bits of a slot (1 for a node pair), the root in record 0,
/// slot 0, so that the RTL finds a node's record (`id >> s`) and its node word in the record
/// (`id & (2^s - 1)`) without a table.
pub fn node_ids(kind: MemLayout, levels: u32, children: &[Option<[u32; 2]>]) -> Vec<u32> {
    if kind == MemLayout::Words {
        return (0..children.len() as u32).collect();
    }
    let t = treelet_records(children, levels);
    let s = slot_bits(levels);
    t.rec.iter().zip(&t.slot).map(|(r, q)| r << s | q).collect()
}

/// Where a record lies: its word address in memory. `words`, and any layout on an ideal
/// memory or a DDR whose banks or page's records are not a power of two or fewer than 4
/// banks: the image in order, record `i` of a region (A's nodes, B's nodes, A's
/// triangles, B's triangles: [`image_bases`]) at word `base + i`. `records` on DDR: each
/// region in banks of its own ([`RecordMap::banks`]), so that the four streams of requests
/// do not close each other's rows, its records dealt round its banks a page's worth at a
/// time: record `i` of a region of `n` banks from bank `b0` is in bank `b0 + (i mod n)`,
/// column `(i / n) mod per_page`, row `i / (n * per_page)`, so that consecutive records (a
/// node's children, then a child's children: pre-order) are in different banks and requests
/// in flight rarely wait for a bank. Word `a` is in bank `(a / per_page) mod banks` (the DDR
/// model's page interleaving, [`Ddr`](super::memory::Ddr)), `per_page` the records of a
/// page. Banks, a region's banks and `per_page` are powers of two, so that the RTL's memory
/// port computes the address with shifts and masks ([`RecordMap::addr`]) from the host
/// register [`MAP`](super::reg::MAP) ([`RecordMap::word`]), `base` the region's first word
/// (`b0 per_page`, [`RecordMap::bases`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RecordMap {
    /// log2 of each region's banks, by [`Dst`].
    ln: [u32; 4],
    /// log2 of the records of a page.
    lp: u32,
    /// log2 of the banks; 0: the image in order.
    lb: u32,
}

impl RecordMap {
    /// The image in order: the register's reset value.
    pub const IN_ORDER: RecordMap = RecordMap {
        ln: [0; 4],
        lp: 0,
        lb: 0,
    };

    pub fn new(layout: &Layout, memory: &Memory) -> RecordMap {
        match (layout.kind, memory) {
            (MemLayout::Records, Memory::Ddr(d)) => {
                let per_page = d.page_bytes / (layout.word_bits() / 8);
                if d.banks < 4
                    || !d.banks.is_power_of_two()
                    || !per_page.is_power_of_two()
                    || per_page >= 1 << 16
                {
                    return RecordMap::IN_ORDER;
                }
                let ln = RecordMap::banks(d.banks).map(|(_, n)| n.trailing_zeros());
                RecordMap {
                    ln,
                    lp: per_page.trailing_zeros(),
                    lb: d.banks.trailing_zeros(),
                }
            }
            _ => RecordMap::IN_ORDER,
        }
    }

    /// The banks of each region by [`Dst`] on a DDR of `banks` (a power of two, at least 4)
    /// banks, as `(first, count)`: A's nodes a quarter, each triangle region an eighth (at
    /// least 1), B's nodes the rest (half from 8 banks on). Node records are most of the
    /// traffic; on DATE'05's 8 banks 2/4/1/1 tests more DOP pairs per clock than 4/2/1/1 or
    /// 2/2/2/2 (and powers of two let the RTL compute addresses with shifts) (docs/explanation/architecture.md, "Two
    /// layouts": measured with `scripts/memory-study.py`).
    pub fn banks(banks: u32) -> [(u32, u32); 4] {
        let (na, t) = (banks / 4, (banks / 8).max(1));
        let nb = banks - na - 2 * t;
        [(0, na), (na, nb), (na + nb, t), (na + nb + t, t)]
    }

    /// The first word of each region by [`Dst`], written to the base registers: `image`
    /// ([`image_bases`]) in order, else its first bank's first word.
    pub fn bases(&self, image: [u32; 4]) -> [u32; 4] {
        if !self.spread() {
            return image;
        }
        RecordMap::banks(1 << self.lb).map(|(b0, _)| b0 << self.lp)
    }

    /// The word address of record `i` of region `d`, whose first word is `base`: the row
    /// above the bank field, the bank within the region's, the column below; in order
    /// (all shifts 0) `base + i`.
    pub fn addr(&self, d: Dst, base: u32, i: u32) -> u32 {
        let (ln, lp) = (self.ln[d as usize], self.lp);
        let mask = |l: u32| (1 << l) - 1;
        base + ((i >> (ln + lp)) << (self.lb + lp))
            + ((i & mask(ln)) << lp)
            + ((i >> ln) & mask(lp))
    }

    /// Whether the regions have banks of their own.
    pub fn spread(&self) -> bool {
        self.lb != 0
    }

    /// The [`MAP`](super::reg::MAP) register's word: bits `3 d + 2 .. 3 d` the log2 of
    /// region d's banks, 15:12 of a page's records, 19:16 of the banks.
    pub fn word(&self) -> u32 {
        self.ln
            .iter()
            .enumerate()
            .map(|(d, l)| l << (3 * d))
            .sum::<u32>()
            | self.lp << 12
            | self.lb << 16
    }

    /// The map of a [`MAP`](super::reg::MAP) word.
    pub fn of_word(w: u32) -> RecordMap {
        RecordMap {
            ln: [0, 1, 2, 3].map(|d| w >> (3 * d) & 7),
            lp: w >> 12 & 0xf,
            lb: w >> 16 & 0xf,
        }
    }

    /// Word addresses an image of regions of `records` records (by [`Dst`]) spans.
    pub fn extent(&self, records: [u32; 4]) -> u32 {
        if !self.spread() {
            return records.iter().sum();
        }
        let page_row = |d: usize| 1 << (self.ln[d] + self.lp);
        let rows = (0..4)
            .map(|d| records[d].div_ceil(page_row(d)))
            .max()
            .unwrap_or(0);
        rows << (self.lb + self.lp)
    }
}

/// Where a memory word goes: the node words for the DOP unit (A's, B's) and the triangle
/// words held for TRI_UNIT (A's, B's). Triangle words are asked for first, A's before B's;
/// node words in the order of their pairs (docs/explanation/architecture.md, "Cycle semantics").
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

/// Record numbers of A's node record 0, B's node record 0, A's triangle 0, B's triangle 0
/// (indexed by [`Dst`]) for objects of `na`/`nb` node records and `ta` triangles in A: A's
/// node records, A's triangles, B's node records, B's triangles, one record each
/// ([`RecordMap::addr`] gives their word addresses).
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
        Entry {
            pairs: [Pair::default(); 2],
            len: 1,
        }
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
    assert!(
        p.a < 1 << NODE_BITS && p.b < 1 << NODE_BITS,
        "node ids of {p:?} do not fit {NODE_BITS} bits"
    );
    p.a as u128 | (p.b as u128) << NODE_BITS | (p.flip as u128) << (2 * NODE_BITS)
}

fn unpack_pair(w: u128) -> Pair {
    let m = (1u128 << NODE_BITS) - 1;
    Pair {
        a: (w & m) as u32,
        b: (w >> NODE_BITS & m) as u32,
        flip: w >> (2 * NODE_BITS) & 1 == 1,
    }
}

/// The entry word of `e` (layout in the module doc). Panics if a node id needs more than
/// 16 bits or `len` is not 1 or 2.
pub fn pack(e: &Entry) -> u128 {
    assert!(e.len == 1 || e.len == 2, "entry length {}", e.len);
    pack_pair(&e.pairs[0])
        | pack_pair(&e.pairs[1]) << PAIR_BITS
        | ((e.len - 1) as u128) << (2 * PAIR_BITS)
}

/// The entry of a word (bits above 66 ignored); the inverse of [`pack`].
pub fn unpack(w: u128) -> Entry {
    let m = (1u128 << PAIR_BITS) - 1;
    Entry {
        pairs: [unpack_pair(w & m), unpack_pair(w >> PAIR_BITS & m)],
        len: 1 + (w >> (2 * PAIR_BITS) & 1) as u8,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tree of 7 nodes by hand, pre-order: 0(1(2, 3), 4(5, 6)); leaves 2, 3, 5, 6 hold
    /// triangles 3, 0, 2, 1. Records: the root alone (0), the children of inner nodes 0, 1,
    /// 4 (the 1st, 2nd, 3rd inner node) in records 1, 2, 3; triangles in leaf order.
    #[test]
    fn siblings_share_a_record_by_hand() {
        let c = |a: u32, b: u32| Some([a, b]);
        let tree = [c(1, 4), c(2, 3), None, None, c(5, 6), None, None];
        assert_eq!(
            node_records(MemLayout::Records, 1, &tree),
            [0, 1, 2, 2, 1, 3, 3]
        );
        assert_eq!(
            node_records(MemLayout::Words, 1, &tree),
            [0, 1, 2, 3, 4, 5, 6]
        );
        assert_eq!(tri_records(MemLayout::Records, &[3, 0, 2, 1]), [1, 3, 2, 0]);
        assert_eq!(
            node_ids(MemLayout::Records, 1, &tree),
            [0, 2, 4, 5, 3, 6, 7]
        );
        assert_eq!(node_ids(MemLayout::Words, 1, &tree), [0, 1, 2, 3, 4, 5, 6]);
        assert_eq!(tri_records(MemLayout::Words, &[3, 0, 2, 1]), [0, 1, 2, 3]);
    }

    /// Treelets by hand, a full tree of 15 nodes, pre-order 0(1(2(3, 4), 5(6, 7)), 8(9(10, 11),
    /// 12(13, 14))). Two levels: the root alone; record 1 holds the root's children 1 and 8
    /// (slots 0 and 1) and its grandchildren 2, 5, 9, 12 (slots 2 to 5); the depth-2 nodes are
    /// treelet roots in pre-order, their children in records 2 to 5; ids are `record << 3 |
    /// slot`. One level: the inner nodes 0, 1, 2, 5, 8, 9, 12 hold their children in records
    /// 1 to 7.
    #[test]
    fn treelets_by_hand() {
        let c = |a: u32, b: u32| Some([a, b]);
        let tree = [
            c(1, 8),
            c(2, 5),
            c(3, 4),
            None,
            None,
            c(6, 7),
            None,
            None,
            c(9, 12),
            c(10, 11),
            None,
            None,
            c(13, 14),
            None,
            None,
        ];
        let two = [0, 1, 1, 2, 2, 1, 3, 3, 1, 1, 4, 4, 1, 5, 5];
        assert_eq!(node_records(MemLayout::Records, 2, &tree), two);
        assert_eq!(
            node_ids(MemLayout::Records, 2, &tree),
            [0, 8, 10, 16, 17, 11, 24, 25, 9, 12, 32, 33, 13, 40, 41]
        );
        let one = [0, 1, 2, 3, 3, 2, 4, 4, 1, 5, 6, 6, 5, 7, 7];
        assert_eq!(node_records(MemLayout::Records, 1, &tree), one);
        assert_eq!(record_nodes(2), 6);
    }

    /// Levels by hand at k = 24 binary32, whose full-precision record is 2,048 bits (a node
    /// pair of 2 x 833): a record shares 24 x (32 + 9) = 984 bits, and a node word is
    /// 1 + 24 b + 64. b = 1: 89 bits, three levels 984 + 14 x 89 = 2,230 do not fit, two
    /// (1,518) do; b = 4: 161, two levels 1,950; b = 8: 257, two levels 2,526 do not fit, one
    /// 1,498; b = 16: 449, one 1,882. Full: one level, no shared bits.
    #[test]
    fn levels_by_hand() {
        let at = |dop_bits| {
            let l = Layout::new(&ChipConfig {
                layout: MemLayout::Records,
                dop_bits,
                ..ChipConfig::default()
            });
            (l.levels, l.shared_bits, l.node_bits, l.word_bits())
        };
        assert_eq!(at(DopBits::Bits(1)), (2, 984, 89, 2048));
        assert_eq!(at(DopBits::Bits(4)), (2, 984, 161, 2048));
        assert_eq!(at(DopBits::Bits(8)), (1, 984, 257, 2048));
        assert_eq!(at(DopBits::Bits(16)), (1, 984, 449, 2048));
        assert_eq!(at(DopBits::Full), (1, 0, 833, 2048));
    }

    /// k = 24 binary32: a node pair is 1,666 bits (209 bytes), a record 256 bytes, one burst
    /// of WSCG'03 (8 x 256 bits) and of DATE'05 (4 x 756 bits); DATE'05's 8 KiB pages hold
    /// 32. Its 8 banks: A's nodes in 0..1, B's in 2..5, A's triangles in 6, B's in 7.
    #[test]
    fn records_are_dealt_round_their_banks_by_hand() {
        let l = Layout::new(&ChipConfig {
            layout: MemLayout::Records,
            ..ChipConfig::default()
        });
        assert_eq!((l.word_bits(), l.record_bytes()), (2048, [256, 256]));
        assert_eq!(
            Layout {
                kind: MemLayout::Words,
                ..l
            }
            .record_bytes(),
            [105, 93]
        );
        assert_eq!(RecordMap::banks(8), [(0, 2), (2, 4), (6, 1), (7, 1)]);
        assert_eq!(RecordMap::banks(4), [(0, 1), (1, 1), (2, 1), (3, 1)]);
        assert_eq!(RecordMap::banks(16), [(0, 4), (4, 8), (12, 2), (14, 2)]);
        let m = RecordMap::new(&l, &Memory::Ddr(super::super::memory::Ddr::DATE05));
        // the regions start at their first banks' first words; the register word
        assert_eq!(m.bases([9; 4]), [0, 2 * 32, 6 * 32, 7 * 32]);
        assert_eq!(m.word(), 1 | 2 << 3 | 5 << 12 | 3 << 16);
        assert_eq!(RecordMap::of_word(m.word()), m);
        // A's records 0, 1, 2, 3 in banks 0, 1, 0, 1 (word a is in bank (a / 32) mod 8)
        let bank = |a: u32| a / 32 % 8;
        let a: Vec<u32> = (0..4).map(|i| m.addr(Dst::NodeA, 0, i)).collect();
        assert_eq!(a, [0, 32, 1, 33]);
        assert_eq!(a.iter().map(|&a| bank(a)).collect::<Vec<_>>(), [0, 1, 0, 1]);
        // B's record 4 in bank 2 + 4 mod 4 = 2, column 1; record 128 in row 1 (4 banks x 32)
        assert_eq!(m.addr(Dst::NodeB, 64, 4), 2 * 32 + 1);
        assert_eq!(m.addr(Dst::NodeB, 64, 128), 256 + 2 * 32);
        assert_eq!(m.addr(Dst::TriB, 224, 33), 256 + 7 * 32 + 1);
        // rows of 8 banks x 32: A's triangles (33 records in 1 bank) and A's nodes (96 in 2) span 2
        assert_eq!(m.extent([96, 10, 33, 5]), 2 * 256);
        // the image in order on an ideal memory, on banks not a power of two, in the words layout
        let ideal = RecordMap::new(&l, &Memory::default());
        assert_eq!(
            (
                ideal.addr(Dst::NodeB, 1000, 4),
                ideal.extent([96, 10, 33, 5])
            ),
            (1004, 144)
        );
        let six = Memory::Ddr(super::super::memory::Ddr {
            banks: 6,
            ..super::super::memory::Ddr::DATE05
        });
        assert_eq!(RecordMap::new(&l, &six), RecordMap::IN_ORDER);
        assert_eq!(
            RecordMap::new(
                &Layout {
                    kind: MemLayout::Words,
                    ..l
                },
                &Memory::Ddr(super::super::memory::Ddr::DATE05)
            ),
            RecordMap::IN_ORDER
        );
        assert_eq!(
            (
                RecordMap::IN_ORDER.word(),
                RecordMap::IN_ORDER.bases([1, 2, 3, 4])
            ),
            (0, [1, 2, 3, 4])
        );
    }

    /// Every record of every region has its own word address.
    #[test]
    fn record_addresses_are_distinct() {
        let l = Layout::new(&ChipConfig {
            layout: MemLayout::Records,
            ..ChipConfig::default()
        });
        for d in [
            super::super::memory::Ddr::DATE05,
            super::super::memory::Ddr::WSCG03,
        ] {
            let m = RecordMap::new(&l, &Memory::Ddr(d));
            assert!(m.spread());
            let (sizes, base) = ([700, 500, 300, 200], m.bases([0; 4]));
            let mut all: Vec<u32> = (0..4)
                .flat_map(|r| (0..sizes[r]).map(move |i| (r, i)))
                .map(|(r, i)| {
                    m.addr(
                        [Dst::NodeA, Dst::NodeB, Dst::TriA, Dst::TriB][r],
                        base[r],
                        i,
                    )
                })
                .collect();
            assert!(all.iter().all(|&a| a < m.extent(sizes)));
            all.sort_unstable();
            all.dedup();
            assert_eq!(all.len(), 1700);
        }
    }

    #[test]
    fn pack_round_trips_and_places_the_fields() {
        let p = |a, b, flip| Pair { a, b, flip };
        let e = Entry {
            pairs: [p(0x1234, 0xffff, true), p(0, 0xabcd, false)],
            len: 2,
        };
        let w = pack(&e);
        assert_eq!(w & 0xffff, 0x1234);
        assert_eq!(w >> 16 & 0xffff, 0xffff);
        assert_eq!(w >> 32 & 1, 1);
        assert_eq!(w >> 49 & 0xffff, 0xabcd);
        assert_eq!(w >> 66, 1);
        assert_eq!(unpack(w), e);
        let root = Entry {
            pairs: [p(0, 0, false); 2],
            len: 1,
        };
        assert_eq!(pack(&root), 0);
        assert_eq!(unpack(pack(&root)), root);
        assert_eq!(
            unpack(ENTRY_MASK),
            Entry {
                pairs: [p(0xffff, 0xffff, true); 2],
                len: 2
            }
        );
    }
}
