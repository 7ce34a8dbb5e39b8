//! One collision query end to end on the golden model: the host builds both memory
//! images once, sets up C, c, j and the frame maps per pose, and a traversal runs.
//! With `oracle`, the exact answer for the same f64 geometry is computed too.

use crate::chip::config::ChipConfig;
use crate::chip::layout::Layout;
use crate::chip::params::Params;
use crate::chip::reg::{self, Mode, Order};
use crate::dop::tree::Tri;
use crate::golden::host::HostSetup;
use crate::golden::memory::ObjectImage;
use crate::oracle;
use crate::pose::Pose;
use crate::traversal::{self, Host, QueryResult, Traversal};
use serde::Serialize;

/// Both objects' memory images for one chip configuration, and the host's f64 geometry
/// (to settle uncertain pairs).
pub struct Chip {
    pub cfg: ChipConfig,
    pub a: ObjectImage,
    pub b: ObjectImage,
    pub layout: Layout,
    geometry: [Vec<Tri>; 2],
}

impl Chip {
    /// Errors name what is wrong (unsupported k, empty object, a coordinate outside the
    /// range the exact oracle is exact for).
    pub fn new(a: &[Tri], b: &[Tri], cfg: ChipConfig) -> Result<Chip, String> {
        cfg.check()?;
        if a.is_empty() || b.is_empty() {
            return Err("both objects need at least one triangle".into());
        }
        oracle::check_range(a, "object A")?;
        oracle::check_range(b, "object B")?;
        Ok(Chip {
            cfg,
            a: ObjectImage::build(a, &cfg),
            b: ObjectImage::build(b, &cfg),
            layout: Layout::new(&cfg),
            geometry: [a.to_vec(), b.to_vec()],
        })
    }

    /// Ok iff B placed by `pose` stays in the range the exact oracle is exact for (a huge
    /// translation or a tiny rotation angle can leave it); check before [`Chip::query`].
    pub fn check_pose(&self, pose: &Pose) -> Result<(), String> {
        oracle::check_range(&place(&self.geometry[1], pose), &format!("object B at pose {}", pose.text()))
    }

    pub fn setup(&self, pose: &Pose) -> HostSetup {
        HostSetup::new(&self.cfg, pose, self.b.tree.coord_bound(), self.a.tri_side(&self.b))
    }

    /// Word addresses of A's and B's first node and triangle words in the memory image
    /// (by [`Dst`](crate::chip::layout::Dst)).
    pub fn image_bases(&self) -> [u32; 4] {
        crate::golden::memory::image_bases(&self.a, &self.b)
    }

    /// Records in the memory image (node records and triangles of both objects).
    pub fn image_words(&self) -> u32 {
        self.image_bases()[crate::chip::layout::Dst::TriB as usize] + self.b.tris.len() as u32
    }

    /// Word addresses the memory image spans on `memory` (its records as
    /// [`RecordMap`](crate::chip::layout::RecordMap) places them).
    pub fn image_span(&self, memory: &crate::chip::memory::Memory) -> u32 {
        let records = [self.a.node_records(), self.b.node_records(), self.a.tris.len() as u32, self.b.tris.len() as u32];
        crate::chip::layout::RecordMap::new(&self.layout, memory).extent(records)
    }

    /// The register writes that start a query in `order` and `mode` on the port of `p`
    /// ([`reg::control_writes`]; the RTL host writes the DOP unit's and TRI_UNIT's setup
    /// before these).
    pub fn control_writes(&self, order: Order, mode: Mode, p: &Params) -> Vec<(u32, u32)> {
        reg::control_writes(self.image_bases(), order, mode, p, self.cfg.tri_cache)
    }

    pub fn query(&self, pose: &Pose, mode: Mode, traversal: Traversal) -> QueryResult {
        let setup = self.setup(pose);
        let host = Host { a: &self.geometry[0], b: &self.geometry[1], rot: pose.rotation(), t: pose.translation() };
        traversal::run(&self.cfg, &self.a, &self.b, &setup, &host, mode, traversal)
    }
}

/// B's triangles in A's frame, in f64: the geometry the exact oracle judges.
pub fn place(b: &[Tri], pose: &Pose) -> Vec<Tri> {
    let (r, t) = (pose.rotation(), pose.translation());
    b.iter().map(|tri| tri.map(|p| r * p + t)).collect()
}

/// The exact answer for B placed by `pose` against A: every intersecting pair of the f64
/// geometry (the oracle's exact predicates).
pub fn exact_pairs(a: &[Tri], b: &[Tri], pose: &Pose) -> Vec<(u32, u32)> {
    oracle::intersecting_pairs(a, &place(b, pose))
}

/// Chip pairs against the exact pairs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Accuracy {
    /// Exact pairs the chip did not report (false negatives).
    pub misses: u64,
    /// Pairs the chip reported that do not intersect (false positives).
    pub extras: u64,
}

impl Accuracy {
    /// Both lists sorted. In first-hit mode the chip's one pair must be exact, and a miss
    /// is reporting none when there is one.
    pub fn of(mode: Mode, chip: &[(u32, u32)], exact: &[(u32, u32)]) -> Accuracy {
        match mode {
            Mode::All => Accuracy::compare(chip, exact),
            Mode::First => Accuracy {
                misses: (chip.is_empty() && !exact.is_empty()) as u64,
                extras: chip.iter().filter(|p| exact.binary_search(p).is_err()).count() as u64,
            },
        }
    }

    fn compare(chip: &[(u32, u32)], exact: &[(u32, u32)]) -> Accuracy {
        let (mut i, mut j, mut acc) = (0, 0, Accuracy::default());
        while i < chip.len() || j < exact.len() {
            match (chip.get(i), exact.get(j)) {
                (Some(c), Some(x)) if c == x => (i, j) = (i + 1, j + 1),
                (Some(c), Some(x)) if c < x => (i, acc.extras) = (i + 1, acc.extras + 1),
                (Some(_), None) => (i, acc.extras) = (i + 1, acc.extras + 1),
                _ => (j, acc.misses) = (j + 1, acc.misses + 1),
            }
        }
        acc
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 16: geometry outside the oracle's exact range is refused, not judged.
    #[test]
    fn out_of_range_geometry_is_refused() {
        use nalgebra::Point3;
        let tri = |s: f64, z: f64| [Point3::new(0.0, 0.0, z), Point3::new(s, 0.0, z), Point3::new(0.0, s, z)];
        let cfg = ChipConfig::default();
        let e = Chip::new(&[tri(1.0, 0.0)], &[tri(1e-70, 0.0)], cfg).err().unwrap();
        assert!(e.starts_with("object B, triangle 0: coordinate 1e-70 is out of range"), "{e}");
        let chip = Chip::new(&[tri(1.0, 0.0)], &[tri(1.0, 0.0)], cfg).unwrap();
        chip.check_pose(&Pose::new(30.0, 1e-10, 0.0, 1e60, 0.0, 0.0)).unwrap();
        // A translation beyond 1e60, and a rotation so small that its sine is 1.7e-302.
        for pose in [Pose::new(0.0, 0.0, 0.0, 2e60, 0.0, 0.0), Pose::new(1e-300, 0.0, 0.0, 0.0, 0.0, 0.0)] {
            let e = chip.check_pose(&pose).unwrap_err();
            assert!(e.starts_with("object B at pose ") && e.contains("1e-60 to 1e60"), "{e}");
        }
    }

    #[test]
    fn accuracy_counts_misses_and_extras() {
        let exact = [(0, 1), (2, 2), (5, 0)];
        let chip = [(0, 1), (3, 3), (5, 0), (9, 9)];
        assert_eq!(Accuracy::of(Mode::All, &chip, &exact), Accuracy { misses: 1, extras: 2 });
        assert_eq!(Accuracy::of(Mode::All, &[], &exact), Accuracy { misses: 3, extras: 0 });
        assert_eq!(Accuracy::of(Mode::First, &[(2, 2)], &exact), Accuracy::default());
        assert_eq!(Accuracy::of(Mode::First, &[], &exact), Accuracy { misses: 1, extras: 0 });
        assert_eq!(Accuracy::of(Mode::First, &[(1, 1)], &[]), Accuracy { misses: 0, extras: 1 });
    }
}
