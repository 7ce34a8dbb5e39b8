//! The binary k-DOP tree of one object, built by the host in the object's own frame,
//! one triangle per leaf (DATE'05 §3.1). Distances are stored in the chip's number format,
//! rounded outward (toward +inf) so the stored DOP contains the object (or to nearest in
//! the `nearest-even` mode).

use super::normals::{DopNormals, HALF_LANES};
use super::stored;
use super::values::Values;
use crate::chip::config::{ChipConfig, DopBits, DopRounding, SUPPORTED_K};
use crate::chip::layout::{treelet_root, Layout};
use crate::format::{Format, Rounding};
use nalgebra::Point3;
use std::cell::RefCell;
use std::sync::atomic::{AtomicU32, Ordering};

pub type Tri = [Point3<f64>; 3];

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Node {
    /// Children node indices.
    Inner([u32; 2]),
    /// Triangle index (0-based face order of the mesh).
    Leaf(u32),
}

/// Inner nodes hold their k distances; a leaf's are its triangle's, rounded when read
/// ([`DopTree::dop`]): a leaf DOP per triangle held would be half of a large object's memory
/// (docs/reference/limits.md), and reading one costs k supports of three vertices.
#[derive(Clone, Debug)]
pub struct DopTree {
    pub k: usize,
    /// The j-th inner node's (pre-order) k distances at `j*k .. (j+1)*k`, values of the
    /// chip's DOP format held in the narrowest float that holds them ([`Values`]).
    dops: Values,
    /// Node i in pre-order (the root is node 0, an inner node's first child the next
    /// node): an inner node's rank j among the inner nodes, or a leaf's triangle with
    /// [`LEAF`] set.
    links: Vec<u32>,
    /// The j-th inner node's second child.
    second: Vec<u32>,
    /// The triangles, in the object's frame, by triangle index.
    tris: Vec<Tri>,
    normals: &'static DopNormals,
    fmt: Format,
    rounding: Rounding,
    /// Number of levels (a single leaf has depth 1).
    pub depth: usize,
    /// This tree's number in the process ([`LeafLines`]' tags; a clone has the same leaves).
    id: u32,
    /// The DOPs the chip decodes, if its records store fewer bits.
    stored: Option<Stored>,
}

/// A tree whose node records store `b`-bit codes ([`stored`]): the values the chip's decode
/// stage gives, which [`DopTree::dop`] reads (the root is stored in full).
#[derive(Clone, Debug)]
struct Stored {
    /// Bits a plane of the codes.
    bits: u32,
    /// Tree levels a record holds ([`Layout::levels`]): its treelet root's descendants.
    levels: u32,
    /// The record of the j-th inner node's treelet, if it is a treelet root
    /// ([`treelet_root`]): its exponents at `j*k .. (j+1)*k`.
    exps: Vec<i16>,
    /// The j-th inner node's decoded distances, as `dops` (the root's row unused: it is
    /// stored in full).
    decoded: Values,
    /// Each triangle's leaf's treelet root's rank among the inner nodes ([`NO_ROOT`]: the
    /// leaf is the tree's root).
    leaf_root: Vec<u32>,
}

const NO_ROOT: u32 = u32::MAX;

/// A node's fields in a record of stored DOP precision ([`DopTree::stored_fields`]).
#[derive(Clone, Debug, PartialEq)]
pub struct StoredFields {
    /// The record's reference: its treelet root's k distances.
    pub r: Vec<f64>,
    /// The record's exponent per plane.
    pub e: Vec<i16>,
    /// The node's code per plane.
    pub q: Vec<u32>,
}

/// The bit of a leaf in [`DopTree`]'s links (so trees of up to 2^31 nodes).
const LEAF: u32 = 1 << 31;

/// [`DopTree`]'s numbers: the next tree's.
static NEXT_ID: AtomicU32 = AtomicU32::new(0);

/// Leaf distances made lately, per thread, for any tree (software only: a leaf's DOP is
/// made from its triangle when read, k supports of three vertices, and the same leaves are
/// read again by the next query of the same objects): [`HELD_LEAVES`] lines, direct mapped
/// by tree and triangle, each tagged `id << 32 | triangle` (`u64::MAX`: none), allocated at
/// the first read (some 3.5 MB).
struct LeafLines {
    tags: Vec<u64>,
    values: Vec<f64>,
}

const HELD_LEAVES: usize = 1 << 14;

thread_local! {
    static LEAVES: RefCell<LeafLines> = const { RefCell::new(LeafLines { tags: Vec::new(), values: Vec::new() }) };
}

/// The largest k of [`SUPPORTED_K`].
const MAX_K: usize = SUPPORTED_K[SUPPORTED_K.len() - 1];

/// A node's k distances as f64s, read out of its tree ([`DopTree::dop`]; the default:
/// none, k = 0), followed by zeros up to [`Dop::padded`]'s length.
#[derive(Clone, Copy)]
pub struct Dop {
    d: [f64; 2 * HALF_LANES],
    k: usize,
}

impl Default for Dop {
    fn default() -> Self {
        Dop {
            d: [0.0; 2 * HALF_LANES],
            k: 0,
        }
    }
}

/// The k distances only.
impl std::fmt::Debug for Dop {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(&self.d[..self.k]).finish()
    }
}

impl Dop {
    /// The k distances and zeros after them, in a fixed-size array (for loops without
    /// bounds checks).
    #[inline]
    pub fn padded(&self) -> &[f64; 2 * HALF_LANES] {
        &self.d
    }
}

impl std::ops::Deref for Dop {
    type Target = [f64];
    fn deref(&self) -> &[f64] {
        &self.d[..self.k]
    }
}

impl DopTree {
    pub const ROOT: u32 = 0;

    /// [`DopTree::of`] a copy of `tris`.
    pub fn build(tris: &[Tri], cfg: &ChipConfig) -> DopTree {
        DopTree::of(tris.to_vec(), cfg)
    }

    /// Builds the tree by recursive median split of the triangle centroids along the
    /// longest axis of their bounding box (ties broken by index, so the build is
    /// deterministic); the tree keeps `tris`, which must not be empty.
    ///
    /// A leaf's distances are its triangle's f64 supports rounded into the format, a
    /// parent's the max of its children's rounded distances: rounding is monotone, so this
    /// is the rounded max of the children's supports.
    pub fn of(tris: Vec<Tri>, cfg: &ChipConfig) -> DopTree {
        assert!(!tris.is_empty(), "DOP tree of an empty mesh");
        let centroids: Vec<[f64; 3]> = tris
            .iter()
            .map(|t| {
                let c = (t[0].coords + t[1].coords + t[2].coords) / 3.0;
                [c.x, c.y, c.z]
            })
            .collect();
        let rounding = match cfg.dop_rounding {
            DopRounding::Outward => Rounding::TowardPositive,
            DopRounding::NearestEven => Rounding::NearestEven,
        };
        let (n, k) = (tris.len(), cfg.k);
        let mut tree = DopTree {
            k,
            dops: Values::new(cfg.format.dop, (n - 1) * k),
            links: Vec::with_capacity(2 * n - 1),
            second: Vec::with_capacity(n - 1),
            tris,
            normals: DopNormals::get(k).expect("k validated by the caller"),
            fmt: cfg.format.dop,
            rounding,
            depth: 0,
            id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
            stored: match cfg.dop_bits {
                DopBits::Full => None,
                DopBits::Bits(bits) => Some(Stored {
                    bits,
                    exps: Vec::with_capacity((n - 1) * k),
                    decoded: Values::new(cfg.format.dop, (n - 1) * k),
                    levels: Layout::new(cfg).levels,
                    leaf_root: vec![NO_ROOT; n],
                }),
            },
        };
        let mut idx: Vec<u32> = (0..n as u32).collect();
        tree.grow(&centroids, &mut idx, 1);
        tree
    }

    pub fn dop(&self, node: u32) -> Dop {
        let mut d = Dop::default();
        self.dop_into(node, &mut d);
        d
    }

    /// [`DopTree::dop`] written into `out` (no copy of the 216 bytes of a [`Dop`]).
    #[inline]
    pub fn dop_into(&self, node: u32, out: &mut Dop) {
        out.k = self.k;
        let d = &mut out.d[..self.k];
        match (self.links[node as usize], &self.stored) {
            (l, _) if l & LEAF != 0 => self.leaf_held(l & !LEAF, d),
            // the root (the first inner node) is stored in full
            (j, Some(s)) if j > 0 => s.decoded.read(j as usize * self.k, d),
            (j, _) => self.dops.read(j as usize * self.k, d),
        }
    }

    /// What a record of stored DOP precision holds for node `n`, whose record is its
    /// treelet root `root`'s ([`treelet_records`](crate::chip::layout::treelet_records); the
    /// tree's root is its own): the record's shared fields, the root's distances as the host
    /// stored them and its exponents, and `n`'s codes ([`stored::encode`]); the tree's root
    /// has codes 0 at the smallest exponent, so that it decodes to its distances in full.
    /// None in full precision.
    pub fn stored_fields(&self, n: u32, root: u32) -> Option<StoredFields> {
        let s = self.stored.as_ref()?;
        let (k, j) = (self.k, self.links[root as usize]);
        let r = self.true_dop(root);
        let e = if n == 0 {
            let lo = crate::chip::layout::exp_range(self.fmt, s.bits).0;
            vec![lo as i16; k]
        } else {
            assert!(j & LEAF == 0, "a treelet root is an inner node");
            s.exps[j as usize * k..][..k].to_vec()
        };
        let d = self.true_dop(n);
        let q = (0..k)
            .map(|i| match n {
                0 => 0,
                _ => stored::encode(self.fmt, self.rounding, s.bits, r.d[i], d.d[i], e[i] as i32),
            })
            .collect();
        Some(StoredFields {
            r: r.d[..k].to_vec(),
            e,
            q,
        })
    }

    /// The distances the host computed for `node`, before any coding: an inner node's
    /// stored row, a leaf's rounded supports (not through [`LeafLines`], which hold what
    /// [`DopTree::dop`] reads).
    fn true_dop(&self, node: u32) -> Dop {
        let mut out = Dop {
            k: self.k,
            ..Dop::default()
        };
        let d = &mut out.d[..self.k];
        match self.links[node as usize] {
            l if l & LEAF != 0 => self.leaf_dop(&self.tris[(l & !LEAF) as usize], d),
            j => self.dops.read(j as usize * self.k, d),
        }
        out
    }

    /// Triangle `t`'s leaf distances ([`DopTree::leaf_dop`]) through the thread's
    /// [`LeafLines`]: most leaves meet again in the next query of the same objects.
    fn leaf_held(&self, t: u32, d: &mut [f64]) {
        LEAVES.with_borrow_mut(|lines| {
            let tag = (self.id as u64) << 32 | t as u64;
            let line = (t as usize).wrapping_add(self.id as usize * 0x9e37) % HELD_LEAVES;
            if lines.tags.is_empty() {
                (lines.tags, lines.values) =
                    (vec![u64::MAX; HELD_LEAVES], vec![0.0; HELD_LEAVES * MAX_K]);
            }
            let held = &mut lines.values[line * MAX_K..][..self.k];
            if lines.tags[line] != tag {
                self.leaf_dop(&self.tris[t as usize], held);
                self.decode_leaf(t, held);
                lines.tags[line] = tag;
            }
            d.copy_from_slice(held);
        })
    }

    /// The distances of triangle `t`'s leaf: max over the vertices of B.v along each normal B,
    /// computed in f64 and padded so that it is >= the exact value (B has entries in
    /// {-1, 0, 1}, so B.v is at most two f64 additions, each off by at most 2^-53 of a partial
    /// sum bounded by sum |v_i|: 2^-52 sum |v_i| covers both and the padding's addition),
    /// rounded into the format. The
    /// second half of the normals negates the first (`B_{i+k/2} = -B_i`), and negation is
    /// exact in every f64 operation of the support, so one pass over the first half gives
    /// both: the support along -B_i is the max of `-(B_i . v)` plus the same padding.
    ///
    /// Every normal at once, per vertex (columns of [`DopNormals::half`]: the compiler
    /// vectorises the loop), in the order of `B.v` as a dot product, `(B_x v_x + B_y v_y) +
    /// B_z v_z`: the same bits as one normal at a time (tested). The max is a comparison, not
    /// `f64::max`, whose choice between equal zeros is unspecified; a padded support is
    /// never -0 (the padding is >= +0), so the two agree.
    fn leaf_dop(&self, t: &Tri, d: &mut [f64]) {
        let [bx, by, bz] = &self.normals.half;
        let (mut up, mut down) = (
            [f64::NEG_INFINITY; HALF_LANES],
            [f64::NEG_INFINITY; HALF_LANES],
        );
        for v in t {
            let (x, y, z) = (v.x, v.y, v.z);
            let (ax, ay, az) = (x.abs(), y.abs(), z.abs());
            for i in 0..HALF_LANES {
                let s = (bx[i] * x + by[i] * y) + bz[i] * z;
                let pad = ((bx[i].abs() * ax + by[i].abs() * ay) + bz[i].abs() * az) * f64::EPSILON;
                let (u, w) = (s + pad, -s + pad);
                up[i] = if u > up[i] { u } else { up[i] };
                down[i] = if w > down[i] { w } else { down[i] };
            }
        }
        let h = self.k / 2;
        for i in 0..h {
            d[i] = self.fmt.round(up[i], self.rounding);
            d[i + h] = self.fmt.round(down[i], self.rounding);
        }
    }

    /// Triangle `t`'s leaf distances `d` as the chip decodes them from its record, if the
    /// tree's records store codes.
    fn decode_leaf(&self, t: u32, d: &mut [f64]) {
        let Some(s) = &self.stored else { return };
        let j = s.leaf_root[t as usize];
        if j != NO_ROOT {
            self.decode_member(s, j as usize, d);
        }
    }

    /// `d`, the distances of a node of the j-th inner node's treelet, decoded from their
    /// record ([`stored::round_trip`]: the treelet root's stored row and the record's
    /// exponents).
    fn decode_member(&self, s: &Stored, j: usize, d: &mut [f64]) {
        let k = self.k;
        let mut r = [0.0; 2 * HALF_LANES];
        self.dops.read(j * k, &mut r[..k]);
        stored::round_trip(
            self.fmt,
            self.rounding,
            s.bits,
            &r[..k],
            &s.exps[j * k..][..k],
            d,
        );
    }

    /// The record of the treelet of node `me`, the j-th inner node ([`Stored`]): its
    /// exponents over all its nodes, each inner node's decoded row, each leaf's root.
    fn store_treelet(&mut self, j: usize, me: u32) {
        let Some(mut s) = self.stored.take() else {
            return;
        };
        let (k, mut members, mut level) = (self.k, vec![], vec![me]);
        for _ in 0..s.levels {
            level = level
                .iter()
                .filter_map(|&n| match self.node(n) {
                    Node::Inner(c) => Some(c),
                    Node::Leaf(_) => None,
                })
                .flatten()
                .collect();
            members.extend_from_slice(&level);
        }
        let rows: Vec<Dop> = members.iter().map(|&n| self.true_dop(n)).collect();
        let mut r = [0.0; 2 * HALF_LANES];
        self.dops.read(j * k, &mut r[..k]);
        let e = stored::record_exps(self.fmt, s.bits, &r[..k], rows.iter().map(|d| &d[..]));
        s.exps[j * k..][..k].copy_from_slice(&e);
        for (&c, row) in members.iter().zip(&rows) {
            match self.links[c as usize] {
                l if l & LEAF != 0 => s.leaf_root[(l & !LEAF) as usize] = j as u32,
                jc => {
                    let mut d = row.d;
                    self.decode_member(&s, j, &mut d[..k]);
                    (0..k).for_each(|i| s.decoded.set(jc as usize * k + i, d[i]));
                }
            }
        }
        self.stored = Some(s);
    }

    /// [`prefetch`](super::prefetch) of what [`DopTree::dop`] reads of node `n` (an inner
    /// node's row, a leaf's triangle).
    #[inline]
    pub fn prefetch(&self, n: u32) {
        match self.links[n as usize] {
            l if l & LEAF != 0 => super::prefetch(&self.tris[(l & !LEAF) as usize]),
            j => self.dops.prefetch(j as usize * self.k),
        }
    }

    /// The tree's number in the process: the same for a clone, another for any other tree.
    pub fn id(&self) -> u32 {
        self.id
    }

    /// Node `n`.
    #[inline]
    pub fn node(&self, n: u32) -> Node {
        match self.links[n as usize] {
            l if l & LEAF != 0 => Node::Leaf(l & !LEAF),
            j => Node::Inner([n + 1, self.second[j as usize]]),
        }
    }

    /// Every node, in pre-order.
    pub fn nodes(&self) -> impl Iterator<Item = Node> + '_ {
        (0..self.len() as u32).map(|n| self.node(n))
    }

    /// Every node's children (`None`: a leaf), in pre-order: what the memory layouts place
    /// records by ([`chip::layout`](crate::chip::layout)).
    pub fn children(&self) -> Vec<Option<[u32; 2]>> {
        self.nodes()
            .map(|n| match n {
                Node::Inner(c) => Some(c),
                Node::Leaf(_) => None,
            })
            .collect()
    }

    /// The leaves' triangles, in pre-order.
    pub fn leaf_tris(&self) -> Vec<u32> {
        self.nodes()
            .filter_map(|n| match n {
                Node::Leaf(t) => Some(t),
                Node::Inner(_) => None,
            })
            .collect()
    }

    /// The triangles, by triangle index.
    pub fn tris(&self) -> &[Tri] {
        &self.tris
    }

    pub fn len(&self) -> usize {
        self.links.len()
    }

    pub fn is_empty(&self) -> bool {
        self.links.is_empty()
    }

    /// A bound X with |x|_inf <= X for every point of every node DOP (from the root's
    /// axis slabs: the first three normals of every set are the axes).
    pub fn coord_bound(&self) -> f64 {
        let d = self.dop(Self::ROOT);
        let h = self.k / 2;
        (0..3)
            .map(|a| d[a].abs().max(d[a + h].abs()))
            .fold(0.0, f64::max)
    }

    /// Adds the subtree of the triangles `idx` in pre-order; its root's number.
    fn grow(&mut self, centroids: &[[f64; 3]], idx: &mut [u32], level: usize) -> u32 {
        self.depth = self.depth.max(level);
        let me = self.links.len() as u32;
        if idx.len() == 1 {
            self.links.push(idx[0] | LEAF);
            return me;
        }
        let (j, k) = (self.second.len(), self.k);
        self.links.push(j as u32);
        self.second.push(0);
        (0..k).for_each(|_| self.dops.push(f64::NEG_INFINITY));
        if let Some(s) = &mut self.stored {
            (0..k).for_each(|_| s.decoded.push(f64::NEG_INFINITY));
            s.exps.extend(std::iter::repeat_n(0, k));
        }
        let axis = split_axis(centroids, idx);
        // The lower half by centroid (ties by index: a total order, so the halves are the
        // same sets as a sort's, in linear time; their order within is the children's to set).
        let half = idx.len() / 2;
        idx.select_nth_unstable_by(half, |&p, &q| {
            centroids[p as usize][axis]
                .total_cmp(&centroids[q as usize][axis])
                .then(p.cmp(&q))
        });
        let (lo, hi) = idx.split_at_mut(half);
        let l = self.grow(centroids, lo, level + 1);
        let r = self.grow(centroids, hi, level + 1);
        debug_assert_eq!(l, me + 1, "pre-order");
        self.second[j] = r;
        let (dl, dr) = (self.true_dop(l), self.true_dop(r));
        (0..k).for_each(|i| self.dops.set(j * k + i, dl[i].max(dr[i])));
        if self
            .stored
            .as_ref()
            .is_some_and(|s| treelet_root(level as u32 - 1, s.levels))
        {
            self.store_treelet(j, me);
        }
        me
    }
}

fn split_axis(centroids: &[[f64; 3]], idx: &[u32]) -> usize {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for &i in idx {
        for a in 0..3 {
            lo[a] = lo[a].min(centroids[i as usize][a]);
            hi[a] = hi[a].max(centroids[i as usize][a]);
        }
    }
    (0..3)
        .max_by(|&a, &b| (hi[a] - lo[a]).total_cmp(&(hi[b] - lo[b])).then(b.cmp(&a)))
        .unwrap()
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    /// Another formulation of a leaf's distances: each normal on its own, as the tree held
    /// them before leaves were computed when read.
    fn tri_support(t: &Tri, b: &Vector3<f64>) -> f64 {
        t.iter()
            .map(|v| b.dot(&v.coords) + v.coords.abs().dot(&b.abs()) * f64::EPSILON)
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// Every leaf of random soups (and a triangle on the axes through the origin, whose
    /// supports are signed zeros) equals the per-normal support rounded, for every k and
    /// both roundings; a parent is the max of its children.
    #[test]
    fn leaves_are_their_supports_rounded() {
        let mut tris = crate::mesh::soup(40, 3).triangles_f64();
        tris.push([
            Point3::origin(),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, -0.0, 1.0),
        ]);
        for k in SUPPORTED_K {
            for dop_rounding in [DopRounding::Outward, DopRounding::NearestEven] {
                let cfg = ChipConfig {
                    k,
                    dop_rounding,
                    ..ChipConfig::default()
                };
                let tree = DopTree::build(&tris, &cfg);
                let rnd = if dop_rounding == DopRounding::Outward {
                    Rounding::TowardPositive
                } else {
                    Rounding::NearestEven
                };
                for n in 0..tree.len() as u32 {
                    let d = tree.dop(n);
                    let want: Vec<f64> = match tree.node(n) {
                        Node::Leaf(t) => tree
                            .normals
                            .b
                            .iter()
                            .map(|b| cfg.format.dop.round(tri_support(&tris[t as usize], b), rnd))
                            .collect(),
                        Node::Inner([l, r]) => {
                            (0..k).map(|j| tree.dop(l)[j].max(tree.dop(r)[j])).collect()
                        }
                    };
                    assert_eq!(
                        d.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
                        want.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
                        "k = {k}, node {n}"
                    );
                }
            }
        }
    }
}
