//! Stored DOP precision (`[chip] dop_bits`): every decoded DOP contains the DOP the host
//! stored for the node, and lies within its record's reference (an ancestor's), on every node of the vendored meshes
//! and of random soups, in every format and both roundings; queries on decoded DOPs give the
//! exact pairs (against the exact oracle) with at least the full records' DOP tests.

use collision_chip::chip::config::{ChipConfig, DopBits, DopRounding, Formats, MemLayout};
use collision_chip::chip::layout::Layout;
use collision_chip::chip::reg::Mode;
use collision_chip::dop::{DopTree, Node};
use collision_chip::format::Format;
use collision_chip::mesh;
use collision_chip::oracle;
use collision_chip::pose::{sweep_poses, Sweep};
use collision_chip::query::{place, Chip};
use collision_chip::traversal::Traversal;
use nalgebra::Point3;
use proptest::prelude::*;

type Tri = [Point3<f64>; 3];

/// `cfg` with `b`-bit codes (the `records` layout they need).
fn stored(cfg: ChipConfig, b: u32) -> ChipConfig {
    ChipConfig {
        layout: MemLayout::Records,
        dop_bits: DopBits::Bits(b),
        ..cfg
    }
}

/// Every node of the tree of `tris` under `cfg` with `b`-bit codes against the same tree in
/// full (the build is deterministic: the same nodes): per plane, the stored distance <=
/// decoded <= its record's reference, the stored distance of its ancestor whose depth is the
/// last multiple of the record's levels above it (so within the root's DOP); the root in
/// full. The first failure, if any.
fn check_tree(tris: &[Tri], cfg: ChipConfig, b: u32) -> Result<(), String> {
    let full = DopTree::build(tris, &cfg);
    let coded = DopTree::build(tris, &stored(cfg, b));
    let levels = Layout::new(&stored(cfg, b)).levels as usize;
    let mut up: Vec<Vec<u32>> = vec![vec![]; full.len()];
    for (n, node) in full.nodes().enumerate() {
        if let Node::Inner(c) = node {
            let mut path = up[n].clone();
            path.push(n as u32);
            c.iter().for_each(|&c| up[c as usize] = path.clone());
        }
    }
    for n in 0..full.len() as u32 {
        let (d, got) = (full.dop(n), coded.dop(n));
        let path = &up[n as usize];
        let top = (!path.is_empty()).then(|| full.dop(path[(path.len() - 1) / levels * levels]));
        for i in 0..cfg.k {
            let within = match &top {
                None => got[i].to_bits() == d[i].to_bits(),
                Some(r) => got[i] >= d[i] && got[i] <= r[i],
            };
            if !within {
                return Err(format!(
                    "{} k = {} {:?} dop_bits = {b} ({levels} levels): node {n} plane {i}: decoded {:e}, stored {:e}, reference {:?}",
                    cfg.format, cfg.k, cfg.dop_rounding, got[i], d[i], top.map(|r| r[i])
                ));
            }
        }
    }
    Ok(())
}

/// The codes a format takes: 1, 2, 4, 8 and 16 bits, up to its significand's.
fn widths(f: Format) -> impl Iterator<Item = u32> {
    [1, 2, 4, 8, 16]
        .into_iter()
        .filter(move |&b| b <= f.frac_bits() + 1)
}

/// The vendored meshes, at k = 6 and 24, in binary32, e8m15, e8m10 and a DOP format of 5
/// exponent bits apart from T.CHECK's, both roundings, every width.
#[test]
fn decoded_dops_hold_on_every_node_of_the_vendored_meshes() {
    let formats = ["binary32", "e8m15", "e8m10", "e5m10/binary32"];
    let mut treelets = 0;
    for name in ["bunny", "teapot", "dragon-11k"] {
        let tris = mesh::resolve(name).unwrap().triangles_f64();
        for (f, k, dop_rounding) in formats.iter().flat_map(|f| {
            [6, 24].into_iter().flat_map(move |k| {
                [DopRounding::Outward, DopRounding::NearestEven].map(|r| (f, k, r))
            })
        }) {
            let format: Formats = f.parse().unwrap();
            let cfg = ChipConfig {
                k,
                format,
                dop_rounding,
                ..Default::default()
            };
            for b in widths(format.dop) {
                check_tree(&tris, cfg, b).unwrap_or_else(|e| panic!("{name}: {e}"));
                treelets += (Layout::new(&stored(cfg, b)).levels > 1) as usize;
            }
        }
    }
    assert!(
        treelets > 0,
        "no configuration stores a treelet of two levels"
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, .. ProptestConfig::default() })]

    /// Random soups, of any size and scale (so that subnormal and huge distances occur),
    /// in any DOP format of 2 to 9 exponent bits: every node, every width.
    #[test]
    fn decoded_dops_hold_on_random_trees(
        n in 1usize..200, seed in 0u64..1000, scale in -60i32..60,
        e in 2u32..=9, m in 1u32..=23, k in prop::sample::select(vec![6usize, 14, 18, 24, 26]),
        nearest: bool,
    ) {
        let s = 2f64.powi(scale);
        let tris: Vec<Tri> = mesh::soup(n, seed).triangles_f64().iter()
            .map(|t| t.map(|v| Point3::from(v.coords * s))).collect();
        let cfg = ChipConfig {
            k,
            format: Formats { dop: Format::new(e, m).unwrap(), tri: Format::BINARY32 },
            dop_rounding: if nearest { DopRounding::NearestEven } else { DopRounding::Outward },
            ..Default::default()
        };
        for b in widths(cfg.format.dop) {
            prop_assert!(check_tree(&tris, cfg, b).is_ok(), "{}", check_tree(&tris, cfg, b).unwrap_err());
        }
    }
}

/// The bunny and dragon-11k against themselves at four distances: with 1, 4 and 8 bits a
/// plane, in binary32 and e8m15, the pairs are the exact oracle's, and the coarser DOPs test
/// at least as many pairs as the full records (a decoded DOP contains the stored one, so it
/// overlaps wherever the stored one does).
#[test]
fn stored_precision_keeps_the_exact_pairs() {
    let sweep = Sweep {
        distances: vec![2.2, 1.4, 0.8, 0.2],
        orientations: 1,
        seed: 5,
    };
    let poses = sweep_poses(&sweep).unwrap();
    for name in ["bunny", "dragon-11k"] {
        let tris = mesh::resolve(name)
            .unwrap()
            .scaled_into_unit_cube()
            .unwrap()
            .triangles_f64();
        let exact: Vec<_> = poses
            .iter()
            .map(|sp| oracle::intersecting_pairs(&tris, &place(&tris, &sp.pose)))
            .collect();
        for format in [Format::BINARY32, Format::REDUCED] {
            let full = ChipConfig {
                format: format.into(),
                layout: MemLayout::Records,
                ..Default::default()
            };
            let base = Chip::new(&tris, &tris, full).unwrap();
            for b in [1, 4, 8] {
                let chip = Chip::new(&tris, &tris, stored(full, b)).unwrap();
                for (sp, want) in poses.iter().zip(&exact) {
                    let r = chip.query(&sp.pose, Mode::All, Traversal::Lifo);
                    let f = base.query(&sp.pose, Mode::All, Traversal::Lifo);
                    let at = format!("{name} {format} dop_bits = {b} at {}", sp.pose.text());
                    assert_eq!(&r.pairs, want, "{at}");
                    assert!(r.counters.dop_tests >= f.counters.dop_tests, "{at}");
                    assert!(r.counters.dop_overlaps >= f.counters.dop_overlaps, "{at}");
                }
            }
        }
    }
}
