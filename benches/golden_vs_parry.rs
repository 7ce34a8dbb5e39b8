//! All-pairs queries: the golden model of the chip against the parry3d-f64 peer, WSCG'03
//! protocol (two copies scaled into [-1,1]^3, B tumbling through seeded orientations at a
//! series of centre distances from apart to penetrating). Prints a Markdown table of mean
//! times per query measured in this one run, and their ratio: per row the three are timed
//! in turn, 20 rounds each of 0.05 s CPU time (at least one pass over the poses), and each one's fastest round kept
//! ([`interleaved_best`]), so that both sides of a ratio meet the machine's noise alike.
//!
//! The peer ([`collision_chip::peer`]): parry's BVH `leaf_pairs` with the relative pose on
//! the AABBs, then the exact triangle test: exact all pairs.
//! The exact oracle's own all-pairs query (AABB tree on the placed geometry) is timed too.
//! The work per query is counted beside the times (not timed): the golden model's DOP tests
//! and leaf pairs (TRI_UNIT tests), the peer's box tests and leaf pairs (exact tests).
//!
//! Run: `cargo bench --features parry --bench golden_vs_parry` (add `-- --quick` for fewer
//! orientations).

#[path = "common/record.rs"]
mod record;

use collision_chip::chip::config::ChipConfig;
use collision_chip::chip::reg::Mode;
use collision_chip::measure::interleaved_best;
use collision_chip::mesh;
use collision_chip::oracle;
use collision_chip::peer::{self, PeerMesh};
use collision_chip::pose::Pose;
use collision_chip::pose::{sweep_poses, Sweep};
use collision_chip::query::{place, Chip};
use collision_chip::traversal::Traversal;
use serde_json::json;

fn main() {
    let quick = std::env::args().any(|a| a == "--quick");
    let orientations = if quick { 4 } else { 16 };
    let distances = [2.2, 1.8, 1.4, 1.2, 1.0, 0.8];
    println!("| mesh | distance | pairs | golden (us) | parry peer (us) | oracle (us) | parry / golden | golden DOP tests / leaf pairs | peer box tests / leaf pairs |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for name in ["bunny", "dragon-11k"] {
        let m = mesh::resolve(name)
            .expect("built-in mesh")
            .scaled_into_unit_cube()
            .expect("in range");
        let tris = m.triangles_f64();
        let chip = Chip::new(&tris, &tris, ChipConfig::default()).expect("chip");
        let pm = PeerMesh::new(&m);
        for d in distances {
            let poses: Vec<Pose> = sweep_poses(&Sweep {
                distances: vec![d],
                orientations,
                seed: 1,
            })
            .expect("sweep")
            .iter()
            .map(|p| p.pose)
            .collect();
            let per = |x: usize| x as f64 / poses.len() as f64;
            let (mut pairs, mut dop_tests, mut tri_tests) = (0, 0, 0);
            for p in &poses {
                let r = chip.query(p, Mode::All, Traversal::Lifo);
                (pairs, dop_tests, tri_tests) = (
                    pairs + r.pairs.len(),
                    dop_tests + r.counters.dop_tests as usize,
                    tri_tests + r.counters.tri_tests as usize,
                );
            }
            let peer_work = poses.iter().fold([0; 3], |s, p| {
                let w = peer::work(&pm, &pm, p);
                [s[0] + w[0], s[1] + w[1], s[2] + w[2]]
            });
            assert_eq!(
                peer_work[2], pairs,
                "the peer and the golden model find the same pairs"
            );
            let [golden, peer, exact] = interleaved_best(
                &poses,
                1.0,
                20,
                [
                    &|p: &Pose| chip.query(p, Mode::All, Traversal::Lifo).pairs.len(),
                    &|p: &Pose| peer::all_pairs(&pm, &pm, p),
                    &|p: &Pose| oracle::intersecting_pairs(&tris, &place(&tris, p)).len(),
                ],
            );
            println!(
                "| {name} ({} tris) | {d} | {:.1} | {:.1} | {:.1} | {:.1} | {:.2} | {:.0} / {:.0} | {:.0} / {:.0} |",
                tris.len(),
                per(pairs),
                golden * 1e6,
                peer * 1e6,
                exact * 1e6,
                peer / golden,
                per(dop_tests),
                per(tri_tests),
                per(peer_work[0]),
                per(peer_work[1]),
            );
            record::row(
                "golden_vs_parry",
                json!({ "mesh": name, "triangles": tris.len(), "distance": d, "pairs": per(pairs),
                        "golden_us": golden * 1e6, "parry_us": peer * 1e6, "oracle_us": exact * 1e6,
                        "dop_tests": per(dop_tests), "leaf_pairs": per(tri_tests),
                        "box_tests": per(peer_work[0]), "peer_leaf_pairs": per(peer_work[1]),
                        "orientations": orientations }),
            );
        }
    }
}
