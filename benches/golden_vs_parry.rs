//! All-pairs queries: the golden model of the chip against the parry3d-f64 peer, WSCG'03
//! protocol (two copies scaled into [-1,1]^3, B tumbling through seeded orientations at a
//! series of centre distances from apart to penetrating). Prints a Markdown table of mean
//! times per query measured in this one run, and their ratio.
//!
//! The peer ([`collision_chip::peer`]): parry's BVH `leaf_pairs` with the relative pose on
//! the AABBs, then the exact triangle test: exact all pairs.
//! The exact oracle's own all-pairs query (AABB tree on the placed geometry) is timed too.
//!
//! Run: `cargo bench --features parry --bench golden_vs_parry` (add `-- --quick` for fewer
//! orientations).

use collision_chip::chip::config::ChipConfig;
use collision_chip::measure::mean_seconds;
use collision_chip::mesh;
use collision_chip::oracle;
use collision_chip::peer::{self, PeerMesh};
use collision_chip::pose::Pose;
use collision_chip::query::{place, Chip};
use collision_chip::pose::{sweep_poses, Sweep};
use collision_chip::traversal::Traversal;
use collision_chip::chip::reg::Mode;

fn main() {
    let quick = std::env::args().any(|a| a == "--quick");
    let orientations = if quick { 4 } else { 16 };
    let distances = [2.2, 1.8, 1.4, 1.2, 1.0, 0.8];
    println!("| mesh | distance | pairs | golden (us) | parry peer (us) | oracle (us) | parry / golden |");
    println!("|---|---|---|---|---|---|---|");
    for name in ["bunny", "dragon-11k"] {
        let m = mesh::resolve(name).expect("built-in mesh").scaled_into_unit_cube().expect("in range");
        let tris = m.triangles_f64();
        let chip = Chip::new(&tris, &tris, ChipConfig::default()).expect("chip");
        let pm = PeerMesh::new(&m);
        for d in distances {
            let poses: Vec<Pose> = sweep_poses(&Sweep { distances: vec![d], orientations, seed: 1 })
                .expect("sweep")
                .iter()
                .map(|p| p.pose)
                .collect();
            let pairs: usize = poses.iter().map(|p| chip.query(p, Mode::All, Traversal::Lifo).pairs.len()).sum();
            let golden = mean_seconds(&poses, 0.2, |p| chip.query(p, Mode::All, Traversal::Lifo).pairs.len());
            let peer = mean_seconds(&poses, 0.2, |p| peer::all_pairs(&pm, &pm, p));
            let exact = mean_seconds(&poses, 0.2, |p| oracle::intersecting_pairs(&tris, &place(&tris, p)).len());
            println!(
                "| {name} ({} tris) | {d} | {:.1} | {:.1} | {:.1} | {:.1} | {:.2} |",
                tris.len(),
                pairs as f64 / poses.len() as f64,
                golden * 1e6,
                peer * 1e6,
                exact * 1e6,
                peer / golden
            );
        }
    }
}
