//! Check mode: the golden model's fast paths (the DOP unit's f64 estimate,
//! T.CHECK decided with the enclosure of its certificate, docs/explanation/accuracy.md) run beside the
//! bit-exact path, and every decision is compared (a difference panics inside the query).
//! Run on random soups, the vendored meshes and the hard-case catalogue, in binary32, the
//! reduced format and e5m4, both DOP roundings, T.CHECK rounding to nearest and directed
//! (every mode on soups, upward on meshes too), every traversal. Each query must have
//! compared every one of its DOP and triangle-pair tests (`enclosure::checked`): check mode
//! is on and covers the query; that a comparison fires on a wrong answer is tested beside
//! it (`golden::dop_unit`, `golden::tri_unit`).

use collision_chip::chip::config::{ChipConfig, DopRounding, SUPPORTED_K};
use collision_chip::chip::reg::Mode;
use collision_chip::format::{Format, Rounding};
use collision_chip::golden::enclosure::{checked, force_check};
use collision_chip::mesh;
use collision_chip::pose::{sweep_poses, Pose, Sweep};
use collision_chip::query::Chip;
use collision_chip::traversal::{QueryResult, Traversal};
use proptest::prelude::*;

/// `query` run in check mode, which must compare every DOP and triangle-pair test it makes.
fn checked_query(query: impl FnOnce() -> QueryResult) -> QueryResult {
    force_check();
    let before = checked();
    let r = query();
    let after = checked();
    let made = (
        after.dop_tests - before.dop_tests,
        after.tri_tests - before.tri_tests,
    );
    assert_eq!(
        made,
        (r.counters.dop_tests, r.counters.tri_tests),
        "decisions compared in check mode against the tests made"
    );
    r
}

fn formats() -> [Format; 3] {
    [
        Format::BINARY32,
        Format::REDUCED,
        Format::new(5, 4).unwrap(),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, .. ProptestConfig::default() })]

    #[test]
    fn fast_paths_equal_the_bit_exact_path_on_soups(
        seed in 0u64..10_000, n in 1usize..40,
        rot in prop::array::uniform3(-180.0..180.0f64), t in prop::array::uniform3(-0.6..0.6f64),
        k in prop::sample::select(SUPPORTED_K.to_vec()), format in 0usize..3, outward in any::<bool>(),
        traversal in prop::sample::select(Traversal::ALL.to_vec()),
        tri_rounding in prop::sample::select(vec![Rounding::NearestEven, Rounding::TowardPositive, Rounding::TowardNegative]),
    ) {
        let cfg = ChipConfig {
            k,
            format: formats()[format].into(),
            dop_rounding: if outward { DopRounding::Outward } else { DopRounding::NearestEven },
            tri_rounding,
            ..Default::default()
        };
        let (a, b) = (mesh::soup(n, seed).triangles_f64(), mesh::soup(n, seed + 1).triangles_f64());
        let chip = Chip::new(&a, &b, cfg).unwrap();
        checked_query(|| chip.query(&Pose { rot_deg: rot, t }, Mode::All, traversal));
    }
}

#[test]
fn fast_paths_equal_the_bit_exact_path_on_meshes() {
    let poses = sweep_poses(&Sweep {
        distances: vec![2.2, 1.4, 1.0, 0.6],
        orientations: 2,
        seed: 3,
    })
    .unwrap();
    for name in ["bunny", "teapot", "dragon-11k"] {
        let tris = mesh::resolve(name)
            .unwrap()
            .scaled_into_unit_cube()
            .unwrap()
            .triangles_f64();
        for (format, tri_rounding) in formats()
            .into_iter()
            .flat_map(|f| [(f, Rounding::NearestEven), (f, Rounding::TowardPositive)])
        {
            let chip = Chip::new(
                &tris,
                &tris,
                ChipConfig {
                    format: format.into(),
                    tri_rounding,
                    ..Default::default()
                },
            )
            .unwrap();
            let tri_tests: u64 = poses
                .iter()
                .map(|sp| {
                    checked_query(|| chip.query(&sp.pose, Mode::All, Traversal::Lifo))
                        .counters
                        .tri_tests
                })
                .sum();
            assert!(tri_tests > 0, "{name}: no triangle pair tested");
        }
    }
}

#[test]
fn fast_paths_equal_the_bit_exact_path_on_hard_cases() {
    let moves = [
        Pose::new(13.0, -71.0, 33.0, 0.0, 0.0, 0.0),
        Pose::new(90.0, 0.0, 0.0, 0.0, 0.0, 0.0),
    ];
    for case in collision_chip::hard_cases::load_catalogue().unwrap() {
        let cases = [
            case.clone(),
            case.moved_by(&moves[0]),
            case.moved_by(&moves[1]),
        ];
        for c in &cases {
            for format in formats() {
                let chip = Chip::new(
                    &c.a,
                    &c.b,
                    ChipConfig {
                        format: format.into(),
                        ..Default::default()
                    },
                )
                .unwrap();
                for traversal in Traversal::ALL {
                    checked_query(|| chip.query(&c.pose, Mode::All, traversal));
                }
            }
        }
    }
}
