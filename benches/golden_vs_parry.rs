//! All-pairs queries: the golden model of the chip against the parry3d-f64 peer, WSCG'03
//! protocol (two copies scaled into [-1,1]^3, B tumbling through seeded orientations at a
//! series of centre distances from apart to penetrating). Prints a Markdown table of mean
//! times per query measured in this one run, and their ratio.
//!
//! The peer: parry's BVH `leaf_pairs` with the relative pose on the AABBs, then the exact
//! triangle test (`oracle::tri_tri` on the f64-placed triangles): exact all pairs.
//! The exact oracle's own all-pairs query (AABB tree on the placed geometry) is timed too.
//!
//! Run: `cargo bench --bench golden_vs_parry` (add `-- --quick` for fewer orientations).

use collision_chip::config::ChipConfig;
use collision_chip::mesh::{self, Mesh};
use collision_chip::oracle::{self, Tri};
use collision_chip::pose::Pose;
use collision_chip::query::{place, Chip};
use collision_chip::scene::{sweep_poses, Sweep};
use collision_chip::traversal::{Mode, Traversal};
use parry3d_f64::bounding_volume::BoundingVolume;
use parry3d_f64::glamx::{DMat3, DQuat};
use parry3d_f64::math::{Pose as PPose, Vector};
use parry3d_f64::shape::TriMesh;
use std::hint::black_box;
use std::time::Instant;

fn parry_mesh(m: &Mesh) -> TriMesh {
    let vs = m.vertices.iter().map(|p| Vector::new(p.x, p.y, p.z)).collect();
    TriMesh::new(vs, m.triangles.clone()).expect("parry trimesh")
}

fn parry_pose(p: &Pose) -> PPose {
    let r = p.rotation();
    let m = DMat3::from_cols_array(&[
        r[(0, 0)], r[(1, 0)], r[(2, 0)], r[(0, 1)], r[(1, 1)], r[(2, 1)], r[(0, 2)], r[(1, 2)], r[(2, 2)],
    ]);
    PPose::from_parts(Vector::new(p.t[0], p.t[1], p.t[2]), DQuat::from_mat3(&m))
}

/// The parry peer: exact all pairs. AABBs are loosened by 1e-9 so parry's own f64
/// rounding cannot drop a touching pair.
fn parry_all_pairs(ma: &TriMesh, mb: &TriMesh, ta: &[Tri], tb: &[Tri], pose: &Pose) -> usize {
    let pos12 = parry_pose(pose);
    let (r, t) = (pose.rotation(), pose.translation());
    ma.bvh()
        .leaf_pairs(mb.bvh(), |n1, n2| n1.aabb().loosened(1e-9).intersects(&n2.aabb().transform_by(&pos12)))
        .filter(|&(i, j)| oracle::tri_tri(&ta[i as usize], &tb[j as usize].map(|p| r * p + t)))
        .count()
}

/// Mean seconds per call over `poses`, repeating the whole set until 0.2 s have passed.
fn time_per_query(poses: &[Pose], mut f: impl FnMut(&Pose) -> usize) -> f64 {
    let (t0, mut calls) = (Instant::now(), 0usize);
    while calls == 0 || t0.elapsed().as_secs_f64() < 0.2 {
        for p in poses {
            black_box(f(p));
            calls += 1;
        }
    }
    t0.elapsed().as_secs_f64() / calls as f64
}

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
        let pm = parry_mesh(&m);
        for d in distances {
            let poses: Vec<Pose> = sweep_poses(&Sweep { distances: vec![d], orientations, seed: 1 })
                .expect("sweep")
                .iter()
                .map(|p| p.pose)
                .collect();
            let pairs: usize = poses.iter().map(|p| chip.query(p, Mode::All, Traversal::Lifo).pairs.len()).sum();
            let golden = time_per_query(&poses, |p| chip.query(p, Mode::All, Traversal::Lifo).pairs.len());
            let peer = time_per_query(&poses, |p| parry_all_pairs(&pm, &pm, &tris, &tris, p));
            let exact = time_per_query(&poses, |p| oracle::intersecting_pairs(&tris, &place(&tris, p)).len());
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
