//! The binary k-DOP tree of one object, built by the host in the object's own frame,
//! one triangle per leaf (DATE'05 §3.1). Distances are stored in the chip's number format,
//! rounded outward (toward +inf) so the stored DOP contains the object (or to nearest in
//! the `nearest-even` mode).

use super::normals::DopNormals;
use crate::chip::config::{ChipConfig, DopRounding};
use crate::format::Rounding;
use nalgebra::Point3;

pub type Tri = [Point3<f64>; 3];

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Node {
    /// Children node indices.
    Inner([u32; 2]),
    /// Triangle index (0-based face order of the mesh).
    Leaf(u32),
}

#[derive(Clone, Debug)]
pub struct DopTree {
    pub k: usize,
    /// Node i's k distances at `dops[i*k .. (i+1)*k]`, values of the chip format.
    dops: Vec<f64>,
    /// Pre-order: the root is node 0.
    pub nodes: Vec<Node>,
    /// Number of levels (a single leaf has depth 1).
    pub depth: usize,
}

impl DopTree {
    pub const ROOT: u32 = 0;

    /// Builds the tree by recursive median split of the triangle centroids along the
    /// longest axis of their bounding box (ties broken by index, so the build is
    /// deterministic). `tris` must not be empty.
    pub fn build(tris: &[Tri], cfg: &ChipConfig) -> DopTree {
        assert!(!tris.is_empty(), "DOP tree of an empty mesh");
        let normals = DopNormals::get(cfg.k).expect("k validated by the caller");
        let k = cfg.k;
        // Exact-or-above f64 support of every triangle along every normal.
        let support: Vec<f64> = tris
            .iter()
            .flat_map(|t| normals.b.iter().map(move |b| tri_support(t, b)))
            .collect();
        let centroids: Vec<[f64; 3]> = tris
            .iter()
            .map(|t| {
                let c = (t[0].coords + t[1].coords + t[2].coords) / 3.0;
                [c.x, c.y, c.z]
            })
            .collect();
        let mut b = Builder { k, support: &support, centroids: &centroids, nodes: vec![], raw: vec![], depth: 0 };
        let mut idx: Vec<u32> = (0..tris.len() as u32).collect();
        b.build(&mut idx, 1);
        let rnd = match cfg.dop_rounding {
            DopRounding::Outward => Rounding::TowardPositive,
            DopRounding::NearestEven => Rounding::NearestEven,
        };
        let dops = b.raw.iter().map(|&x| cfg.format.dop.round(x, rnd)).collect();
        DopTree { k, dops, nodes: b.nodes, depth: b.depth }
    }

    pub fn dop(&self, node: u32) -> &[f64] {
        let i = node as usize * self.k;
        &self.dops[i..i + self.k]
    }

    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// A bound X with |x|_inf <= X for every point of every node DOP (from the root's
    /// axis slabs: the first three normals of every set are the axes).
    pub fn coord_bound(&self) -> f64 {
        let d = self.dop(Self::ROOT);
        let h = self.k / 2;
        (0..3).map(|a| d[a].abs().max(d[a + h].abs())).fold(0.0, f64::max)
    }
}

/// max over the vertices of B.v, computed in f64 and padded so that it is >= the exact
/// value: B has entries in {-1, 0, 1}, so B.v is at most two f64 additions, each off by at
/// most 2^-53 of a partial sum bounded by sum |v_i|.
fn tri_support(t: &Tri, b: &nalgebra::Vector3<f64>) -> f64 {
    t.iter()
        .map(|v| {
            let s = b.dot(&v.coords);
            let mag = v.coords.abs().dot(&b.abs());
            s + mag * f64::EPSILON // 2^-52 * mag covers both additions and this one
        })
        .fold(f64::NEG_INFINITY, f64::max)
}

struct Builder<'a> {
    k: usize,
    support: &'a [f64],
    centroids: &'a [[f64; 3]],
    nodes: Vec<Node>,
    raw: Vec<f64>,
    depth: usize,
}

impl Builder<'_> {
    fn build(&mut self, idx: &mut [u32], level: usize) -> u32 {
        self.depth = self.depth.max(level);
        let me = self.nodes.len() as u32;
        let k = self.k;
        if idx.len() == 1 {
            self.nodes.push(Node::Leaf(idx[0]));
            let t = idx[0] as usize;
            self.raw.extend_from_slice(&self.support[t * k..(t + 1) * k]);
            return me;
        }
        self.nodes.push(Node::Inner([0, 0]));
        self.raw.extend(std::iter::repeat_n(f64::NEG_INFINITY, k));
        let axis = self.split_axis(idx);
        let c = self.centroids;
        idx.sort_unstable_by(|&p, &q| {
            c[p as usize][axis].total_cmp(&c[q as usize][axis]).then(p.cmp(&q))
        });
        let (lo, hi) = idx.split_at_mut(idx.len() / 2);
        let l = self.build(lo, level + 1);
        let r = self.build(hi, level + 1);
        self.nodes[me as usize] = Node::Inner([l, r]);
        for j in 0..k {
            let m = self.raw[l as usize * k + j].max(self.raw[r as usize * k + j]);
            self.raw[me as usize * k + j] = m;
        }
        me
    }

    fn split_axis(&self, idx: &[u32]) -> usize {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for &i in idx {
            for a in 0..3 {
                lo[a] = lo[a].min(self.centroids[i as usize][a]);
                hi[a] = hi[a].max(self.centroids[i as usize][a]);
            }
        }
        (0..3).max_by(|&a, &b| (hi[a] - lo[a]).total_cmp(&(hi[b] - lo[b])).then(b.cmp(&a))).unwrap()
    }
}
