//! The memory image the chip fetches: per object, one node word per DOP-tree node and one
//! triangle word per triangle. Defined once here; the traversals count fetches in these
//! words and `docs/ARCHITECTURE.md` documents the same layout.
//!
//! With W = 1 + exp_bits + frac_bits (the format's width):
//! - node word, `1 + k*W + 64` bits: `is_leaf`, d_0..d_{k-1}, then two 32-bit fields:
//!   children (inner node) or triangle index and 0 (leaf). Node i lives at
//!   `base + i * node_bytes`, pre-order, root at node 0.
//! - triangle word, `21*W + 1` bits: vertices v0, v1, v2 (x, y, z each), M_B row-major
//!   (3x4: the affine map sending the triangle to the unit triangle), and the
//!   `degenerate` bit (zero area: M_B does not exist and is stored as zeros).
//!   Triangle t lives at `base + t * tri_bytes`.

use crate::config::ChipConfig;
use crate::dop::host::Affine;
use crate::dop::tree::{DopTree, Tri};
use crate::format::{Format, Rounding};
use nalgebra::{Matrix3, Vector3};

/// Word sizes of one configuration.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Layout {
    pub node_bits: u32,
    pub tri_bits: u32,
}

impl Layout {
    pub fn new(cfg: &ChipConfig) -> Layout {
        let w = cfg.format.width();
        Layout { node_bits: 1 + cfg.k as u32 * w + 64, tri_bits: 21 * w + 1 }
    }
    pub fn node_bytes(&self) -> u64 {
        self.node_bits.div_ceil(8) as u64
    }
    pub fn tri_bytes(&self) -> u64 {
        self.tri_bits.div_ceil(8) as u64
    }
}

/// The triangle word of one leaf (DATE'05 §4.2: the triangle and its M_B).
#[derive(Clone, Debug, PartialEq)]
pub struct TriWord {
    /// Vertices in the object's frame, rounded to nearest in the chip format.
    pub v: [[f64; 3]; 3],
    /// M_B: sends v0 to (0,0,0), v1 to (1,0,0), v2 to (0,1,0) and the unit normal to z.
    pub m: Affine,
    pub degenerate: bool,
}

impl TriWord {
    /// Built by the host in f64 from the input geometry, then rounded to the format.
    pub fn new(t: &Tri, fmt: Format) -> TriWord {
        let rn = |x: f64| fmt.round(x, Rounding::NearestEven);
        let v = t.map(|p| [rn(p.x), rn(p.y), rn(p.z)]);
        let e1 = t[1] - t[0];
        let e2 = t[2] - t[0];
        let n = e1.cross(&e2);
        let inv = if n.norm() > 0.0 && n.norm().is_finite() {
            Matrix3::from_columns(&[e1, e2, n / n.norm()]).try_inverse()
        } else {
            None
        };
        match inv.filter(|i| i.iter().all(|x| x.is_finite())) {
            Some(li) => {
                let tr: Vector3<f64> = -(li * t[0].coords);
                let mut m = [[0.0; 4]; 3];
                for (r, row) in m.iter_mut().enumerate() {
                    for (c, x) in row.iter_mut().enumerate() {
                        *x = rn(if c < 3 { li[(r, c)] } else { tr[r] });
                    }
                }
                TriWord { v, m, degenerate: false }
            }
            None => TriWord { v, m: [[0.0; 4]; 3], degenerate: true },
        }
    }
}

/// Everything the chip reads about one object.
#[derive(Clone, Debug)]
pub struct ObjectImage {
    pub tree: DopTree,
    /// Indexed by triangle index.
    pub tris: Vec<TriWord>,
}

impl ObjectImage {
    /// `tris` must not be empty (mesh loaders reject empty meshes).
    pub fn build(tris: &[Tri], cfg: &ChipConfig) -> ObjectImage {
        ObjectImage {
            tree: DopTree::build(tris, cfg),
            tris: tris.iter().map(|t| TriWord::new(t, cfg.format)).collect(),
        }
    }

    /// Bytes of this object's image in memory.
    pub fn bytes(&self, layout: &Layout) -> u64 {
        self.tree.len() as u64 * layout.node_bytes() + self.tris.len() as u64 * layout.tri_bytes()
    }
}
