//! One collision query end to end on the golden model: the host builds both memory
//! images once, sets up C, c, j and the frame maps per pose, and a traversal runs.
//! With `oracle`, the exact answer for the same f64 geometry is computed too.

use crate::chip::config::{ChipConfig, DopBits};
use crate::chip::layout::Layout;
use crate::chip::params::Params;
use crate::chip::reg::{self, Mode, Order};
use crate::dop::tree::Tri;
use crate::golden::host::{DopLanes, HostSetup, TriSide};
use crate::golden::memory::ObjectImage;
use crate::oracle;
use crate::pose::Pose;
use crate::traversal::{self, Host, QueryResult, Traversal};
use serde::Serialize;

/// Peak bytes of a query's setup and its exact oracle for objects of `a` and `b` triangles at
/// `k` DOP directions: per triangle of either object, the f64 geometry (72), an inner
/// node's k distances (at most 8 bytes each), the tree's links, node ids and records, the
/// build's temporaries and the process's own share; and the exact oracle's placed chunk of B
/// with its search tree (`ORACLE_CHUNK`). An upper bound of what `cchip run` peaked at
/// (`/usr/bin/time -v`, the 871k dragon against itself, cycles and accuracy on): 200 bytes
/// per triangle per object at k = 6, 261 at k = 24 (docs/reference/limits.md). Stored DOP
/// precision (`codes`) adds per triangle its inner node's decoded distances (at most 8
/// bytes each), its record's exponents (2 bytes each) and its leaf's treelet root (4).
pub fn memory_estimate(a: usize, b: usize, k: usize, codes: bool) -> u64 {
    let coded = if codes { 10 * k as u64 + 4 } else { 0 };
    (a + b) as u64 * (160 + 8 * k as u64 + coded) + b.min(ORACLE_CHUNK) as u64 * 256
}

/// Refuses objects whose setup would not fit in `available` bytes, before anything is built.
fn check_memory(
    cfg: &ChipConfig,
    a: usize,
    b: usize,
    available: Option<u64>,
) -> Result<(), String> {
    let k = cfg.k;
    let need = memory_estimate(a, b, k, cfg.dop_bits != DopBits::Full);
    match available {
        Some(free) if need > free => Err(format!(
            "objects of {a} and {b} triangles at k = {k} need about {} MB of memory (trees, memory images, triangle words) and this machine has {} MB available: use smaller meshes or a smaller k, or set CCHIP_MAX_MEMORY_MB if more memory is free than /proc/meminfo and the cgroup's limit say",
            need >> 20,
            free >> 20
        )),
        _ => Ok(()),
    }
}

/// Both objects' memory images for one chip configuration, with the host's f64 geometry
/// (to settle uncertain pairs).
pub struct Chip {
    pub cfg: ChipConfig,
    pub a: ObjectImage,
    pub b: ObjectImage,
    pub layout: Layout,
    /// What T.CHECK's error words need of both objects, once (it scans B's triangles).
    tri_side: TriSide,
}

impl Chip {
    /// Errors name what is wrong (unsupported k, empty object, a coordinate outside the
    /// range the exact oracle is exact for).
    pub fn new(a: &[Tri], b: &[Tri], cfg: ChipConfig) -> Result<Chip, String> {
        Chip::of(a.to_vec(), b.to_vec(), cfg)
    }

    /// [`Chip::new`] keeping `a` and `b` in the images as the host's geometry (no copy).
    pub fn of(a: Vec<Tri>, b: Vec<Tri>, cfg: ChipConfig) -> Result<Chip, String> {
        cfg.check()?;
        if a.is_empty() || b.is_empty() {
            return Err("both objects need at least one triangle".into());
        }
        oracle::check_range(&a, "object A")?;
        oracle::check_range(&b, "object B")?;
        check_memory(&cfg, a.len(), b.len(), crate::measure::memory_available()?)?;
        // B the same triangles bit for bit as A (a mesh against itself; a signed zero counts):
        // A's image copied, not built again (the tree's build was most of a large mesh's setup)
        let bits = |t: &Tri| t.map(|p| p.coords.map(f64::to_bits));
        let same = a.len() == b.len() && a.iter().zip(&b).all(|(s, t)| bits(s) == bits(t));
        let a_image = ObjectImage::build(a, &cfg);
        let b_image = if same {
            drop(b);
            a_image.clone()
        } else {
            ObjectImage::build(b, &cfg)
        };
        let tri_side = a_image.tri_side(&b_image);
        Ok(Chip {
            cfg,
            a: a_image,
            b: b_image,
            layout: Layout::new(&cfg),
            tri_side,
        })
    }

    /// The host's f64 geometry of A (`0`) or B (`1`): the triangles the images were built from.
    pub fn geometry(&self, object: usize) -> &[Tri] {
        [&self.a, &self.b][object].geometry()
    }

    /// Ok iff B placed by `pose` stays in the range the exact oracle is exact for (a huge
    /// translation or a tiny rotation angle can leave it); check before [`Chip::query`].
    pub fn check_pose(&self, pose: &Pose) -> Result<(), String> {
        let (r, t, b) = (pose.rotation(), pose.translation(), self.geometry(1));
        // B placed one triangle at a time (a placed copy would be most of B's memory); the
        // prefix up to the first triangle out of range, if any, names it
        let bad = b.iter().position(|tri| {
            tri.iter()
                .any(|p| (r * p + t).iter().any(|&c| !oracle::in_range(c)))
        });
        bad.map_or(Ok(()), |i| {
            oracle::check_range(
                &place(&b[..=i], pose),
                &format!("object B at pose {}", pose.text()),
            )
        })
    }

    pub fn setup(&self, pose: &Pose) -> HostSetup {
        HostSetup::new(&self.cfg, pose, self.b.tree.coord_bound(), self.tri_side)
    }

    /// Word addresses of A's and B's first node and triangle words in the memory image
    /// (by [`Dst`](crate::chip::layout::Dst)).
    pub fn image_bases(&self) -> [u32; 4] {
        crate::golden::memory::image_bases(&self.a, &self.b)
    }

    /// Word addresses the memory image spans on `memory` (its records as
    /// [`RecordMap`](crate::chip::layout::RecordMap) places them).
    pub fn image_span(&self, memory: &crate::chip::memory::Memory) -> u32 {
        let records = [
            self.a.node_records(),
            self.b.node_records(),
            self.a.tri_count() as u32,
            self.b.tri_count() as u32,
        ];
        crate::chip::layout::RecordMap::new(&self.layout, memory).extent(records)
    }

    /// The register writes that start a query in `order` and `mode` on the port of `p`
    /// ([`reg::control_writes`]; the RTL host writes the DOP unit's and TRI_UNIT's setup
    /// before these).
    pub fn control_writes(&self, order: Order, mode: Mode, p: &Params) -> Vec<(u32, u32)> {
        reg::control_writes(self.image_bases(), order, mode, p, &self.cfg)
    }

    /// The host's setup as [`Chip::setup`] gives it, the DOP lanes computed when the DOP unit
    /// first needs them ([`DopLanes`]).
    pub fn query(&self, pose: &Pose, mode: Mode, traversal: Traversal) -> QueryResult {
        let (x, host) = (self.b.tree.coord_bound(), self.host(pose));
        let frames = HostSetup::frames(&self.cfg, &host.rot, &host.t, x, self.tri_side);
        let lanes = DopLanes::new(&self.cfg, &host.rot, &host.t, x);
        traversal::run(
            &self.cfg, &self.a, &self.b, &frames, lanes, &host, mode, traversal,
        )
    }

    /// What the host settles uncertain pairs with at `pose`: the pose's rotation, computed
    /// once per query.
    pub fn host(&self, pose: &Pose) -> Host<'_> {
        Host {
            a: self.geometry(0),
            b: self.geometry(1),
            rot: pose.rotation(),
            t: pose.translation(),
        }
    }
}

/// The host's share of one query, wall clock on this machine: the setup per pose (`b_i`, j,
/// C, c, the frame maps: DATE'05 Eq. 6) and the settling of the chip's uncertain pairs by
/// the exact oracle. A measurement, noisy: reported, never compared.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct HostTime {
    pub setup_us: f64,
    pub settle_us: f64,
}

impl Chip {
    /// Measures the host's setup for `pose` and its settling of `uncertain`, each the
    /// fastest of [`TIMING_RUNS`](crate::measure::TIMING_RUNS) runs.
    pub fn host_time(&self, pose: &Pose, uncertain: &[(u32, u32)]) -> HostTime {
        use crate::measure::fastest_us;
        HostTime {
            setup_us: fastest_us(|| self.setup(std::hint::black_box(pose))).1,
            settle_us: fastest_us(|| self.settle(std::hint::black_box(pose), uncertain)).1,
        }
    }

    /// The host's settling of `uncertain` at `pose` by the exact oracle: how many intersect.
    pub fn settle(&self, pose: &Pose, uncertain: &[(u32, u32)]) -> usize {
        let host = self.host(pose);
        uncertain
            .iter()
            .filter(|&&(a, b)| host.settle(a, b))
            .count()
    }
}

/// B's triangles in A's frame, in f64: the geometry the exact oracle judges.
pub fn place(b: &[Tri], pose: &Pose) -> Vec<Tri> {
    let (r, t) = (pose.rotation(), pose.translation());
    b.iter().map(|tri| tri.map(|p| r * p + t)).collect()
}

/// B's triangles the exact oracle places and indexes at a time in [`exact_pairs`]: its
/// placed copy and search tree (some 240 bytes a triangle) stay small beside the images.
const ORACLE_CHUNK: usize = 1 << 18;

/// The exact answer for B placed by `pose` against A: every intersecting pair of the f64
/// geometry (the oracle's exact predicates), sorted. B is placed and searched a chunk of
/// `ORACLE_CHUNK` triangles at a time.
pub fn exact_pairs(a: &[Tri], b: &[Tri], pose: &Pose) -> Vec<(u32, u32)> {
    exact_pairs_by(a, b, pose, ORACLE_CHUNK)
}

/// [`exact_pairs`] with B placed and searched `chunk` triangles at a time.
fn exact_pairs_by(a: &[Tri], b: &[Tri], pose: &Pose, chunk: usize) -> Vec<(u32, u32)> {
    let mut pairs: Vec<(u32, u32)> = b
        .chunks(chunk)
        .zip((0..).step_by(chunk))
        .flat_map(|(chunk, first)| {
            oracle::intersecting_pairs(a, &place(chunk, pose))
                .into_iter()
                .map(move |(i, j)| (i, j + first as u32))
        })
        .collect();
    pairs.sort_unstable();
    pairs
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
                extras: chip
                    .iter()
                    .filter(|p| exact.binary_search(p).is_err())
                    .count() as u64,
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

    /// Geometry outside the oracle's exact range is refused, not judged.
    #[test]
    fn out_of_range_geometry_is_refused() {
        use nalgebra::Point3;
        let tri = |s: f64, z: f64| {
            [
                Point3::new(0.0, 0.0, z),
                Point3::new(s, 0.0, z),
                Point3::new(0.0, s, z),
            ]
        };
        let cfg = ChipConfig::default();
        let e = Chip::new(&[tri(1.0, 0.0)], &[tri(1e-70, 0.0)], cfg)
            .err()
            .unwrap();
        assert!(
            e.starts_with("object B, triangle 0: coordinate 1e-70 is out of range"),
            "{e}"
        );
        let chip = Chip::new(&[tri(1.0, 0.0)], &[tri(1.0, 0.0)], cfg).unwrap();
        chip.check_pose(&Pose::new(30.0, 1e-10, 0.0, 1e60, 0.0, 0.0))
            .unwrap();
        // A translation beyond 1e60, and a rotation so small that its sine is 1.7e-302.
        for pose in [
            Pose::new(0.0, 0.0, 0.0, 2e60, 0.0, 0.0),
            Pose::new(1e-300, 0.0, 0.0, 0.0, 0.0, 0.0),
        ] {
            let e = chip.check_pose(&pose).unwrap_err();
            assert!(
                e.starts_with("object B at pose ") && e.contains("1e-60 to 1e60"),
                "{e}"
            );
        }
    }

    /// B the same triangles as A bit for bit is A's image copied (the same tree); a B that
    /// differs only in a zero's sign is built from its own triangles (a signed zero can
    /// change a support's sign). Both report the exact oracle's pairs. (Most checked-in chip
    /// traces are of a mesh against itself: the copy, run against the RTL in CI.)
    #[test]
    fn b_equal_to_a_bit_for_bit_is_a_copy() {
        use nalgebra::Point3;
        let mut a = crate::mesh::soup(30, 1).triangles_f64();
        a.push([
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
        ]);
        let cfg = ChipConfig::default();
        let same = Chip::new(&a, &a, cfg).unwrap();
        assert_eq!(same.a.tree.id(), same.b.tree.id(), "copied");
        let mut b = a.clone();
        b[30][0].x = -0.0;
        let other = Chip::new(&a, &b, cfg).unwrap();
        assert_ne!(other.a.tree.id(), other.b.tree.id(), "built");
        assert!(other.geometry(1)[30][0].x.is_sign_negative());
        let pose = Pose::new(10.0, 20.0, 30.0, 0.1, 0.0, 0.0);
        let exact = exact_pairs(&a, &a, &pose);
        assert!(!exact.is_empty(), "a test with pairs");
        for chip in [&same, &other] {
            assert_eq!(chip.query(&pose, Mode::All, Traversal::Lifo).pairs, exact);
        }
    }

    /// B searched a chunk at a time gives the pairs of B searched whole (the oracle on all of
    /// B placed), sorted, whatever the chunk: chunk offsets and order are checked where
    /// [`ORACLE_CHUNK`] is too large for a test's meshes to split.
    #[test]
    fn exact_pairs_by_chunk_equal_the_whole_search() {
        let (a, b) = (
            crate::mesh::soup(60, 1).triangles_f64(),
            crate::mesh::soup(60, 2).triangles_f64(),
        );
        let pose = Pose::new(10.0, 20.0, 30.0, 0.05, 0.0, 0.0);
        let mut whole = oracle::intersecting_pairs(&a, &place(&b, &pose));
        whole.sort_unstable();
        assert!(
            whole.len() > 5 && whole.iter().any(|p| p.1 >= 40),
            "a test with pairs in later chunks: {whole:?}"
        );
        for chunk in [1, 7, 32, 60, 1000] {
            assert_eq!(exact_pairs_by(&a, &b, &pose, chunk), whole, "chunk {chunk}");
        }
    }

    /// The estimate is checked against what is available, and the refusal says
    /// what to do.
    #[test]
    fn memory_beyond_the_available_is_refused() {
        let need = memory_estimate(1 << 20, 1 << 20, 24, false);
        let cfg = ChipConfig::default();
        assert_eq!(need, 2 * (1 << 20) * 352 + (1 << 18) * 256);
        // codes: 24 decoded distances (8 bytes), 24 exponents (2) and a root (4) a triangle
        let coded = memory_estimate(1 << 20, 1 << 20, 24, true);
        assert_eq!(coded - need, 2 * (1 << 20) * (24 * 10 + 4));
        check_memory(&cfg, 1 << 20, 1 << 20, Some(need)).unwrap();
        check_memory(&cfg, 1 << 20, 1 << 20, None).unwrap();
        let e = check_memory(&cfg, 1 << 20, 1 << 20, Some(need - 1)).unwrap_err();
        assert!(
            e.starts_with("objects of 1048576 and 1048576 triangles at k = 24 need about 768 MB")
                && e.contains("CCHIP_MAX_MEMORY_MB"),
            "{e}"
        );
    }

    #[test]
    fn accuracy_counts_misses_and_extras() {
        let exact = [(0, 1), (2, 2), (5, 0)];
        let chip = [(0, 1), (3, 3), (5, 0), (9, 9)];
        assert_eq!(
            Accuracy::of(Mode::All, &chip, &exact),
            Accuracy {
                misses: 1,
                extras: 2
            }
        );
        assert_eq!(
            Accuracy::of(Mode::All, &[], &exact),
            Accuracy {
                misses: 3,
                extras: 0
            }
        );
        assert_eq!(
            Accuracy::of(Mode::First, &[(2, 2)], &exact),
            Accuracy::default()
        );
        assert_eq!(
            Accuracy::of(Mode::First, &[], &exact),
            Accuracy {
                misses: 1,
                extras: 0
            }
        );
        assert_eq!(
            Accuracy::of(Mode::First, &[(1, 1)], &[]),
            Accuracy {
                misses: 0,
                extras: 1
            }
        );
    }
}
