//! Cross-check of the exact oracle against parry3d-f64's BVH candidate filter.
//!
//! For every scene (procedural sphere vs torus, bunny vs rotated bunny) and pose:
//! * the truth is `oracle::intersecting_pairs(A, f64-image of B under the pose)`;
//! * parry with the identity pose on exactly those vertices (AABBs loosened by 1e-9 of the
//!   scene size), candidates filtered by `oracle::tri_tri`, must give the same set;
//! * parry with the real `pos12` on B's untransformed vertices must produce a candidate set
//!   containing the truth, and filtering it with `tri_tri` on the same f64 geometry must give
//!   the same set;
//! * for one scene, `brute_force_pairs` agrees too.

use collision_chip::mesh::{self, Mesh};
use collision_chip::oracle::{brute_force_pairs, intersecting_pairs, tri_tri, Tri};
use collision_chip::pose::Pose;
use nalgebra::Point3;
use parry3d_f64::bounding_volume::BoundingVolume;
use parry3d_f64::glamx::{DMat3, DQuat};
use parry3d_f64::math::{Pose as PPose, Vector};
use parry3d_f64::shape::TriMesh;

/// Triangles of a mesh whose vertices were replaced (e.g. placed by a pose).
fn tris_with(m: &Mesh, v: &[Point3<f64>]) -> Vec<Tri> {
    m.triangles
        .iter()
        .map(|t| t.map(|i| v[i as usize]))
        .collect()
}

fn parry_mesh(v: &[Point3<f64>], f: &[[u32; 3]]) -> TriMesh {
    let vs = v.iter().map(|p| Vector::new(p.x, p.y, p.z)).collect();
    TriMesh::new(vs, f.to_vec()).expect("parry trimesh")
}

fn parry_pose(p: &Pose) -> PPose {
    let r = p.rotation();
    let m = DMat3::from_cols_array(&[
        r[(0, 0)],
        r[(1, 0)],
        r[(2, 0)],
        r[(0, 1)],
        r[(1, 1)],
        r[(2, 1)],
        r[(0, 2)],
        r[(1, 2)],
        r[(2, 2)],
    ]);
    PPose::from_parts(Vector::new(p.t[0], p.t[1], p.t[2]), DQuat::from_mat3(&m))
}

fn scene_size(a: &[Point3<f64>], b: &[Point3<f64>]) -> f64 {
    a.iter()
        .chain(b)
        .flat_map(|p| [p.x.abs(), p.y.abs(), p.z.abs()])
        .fold(0.0, f64::max)
}

/// Runs all checks for one scene and pose; returns the number of intersecting pairs.
fn check_scene(name: &str, a: &Mesh, b: &Mesh, pose: &Pose, brute: bool) -> usize {
    let vb = pose.apply_all(&b.vertices);
    let (ta, tb) = (a.triangles_f64(), tris_with(b, &vb));
    let truth = intersecting_pairs(&ta, &tb);
    let margin = 1e-9 * scene_size(&a.vertices, &vb);

    // Parry, identity pose on the same f64 geometry.
    let (ma, mb) = (
        parry_mesh(&a.vertices, &a.triangles),
        parry_mesh(&vb, &b.triangles),
    );
    let cand: Vec<(u32, u32)> = ma
        .bvh()
        .leaf_pairs(mb.bvh(), |n1, n2| {
            n1.aabb().loosened(margin).intersects(&n2.aabb())
        })
        .collect();
    let mut got: Vec<(u32, u32)> = cand
        .iter()
        .copied()
        .filter(|&(i, j)| tri_tri(&ta[i as usize], &tb[j as usize]))
        .collect();
    got.sort_unstable();
    got.dedup();
    assert_eq!(
        got, truth,
        "{name} {pose:?}: parry (identity pose) + tri_tri != intersecting_pairs"
    );

    // Parry with the real relative pose on B's own vertices.
    let mb0 = parry_mesh(&b.vertices, &b.triangles);
    let pos12 = parry_pose(pose);
    let cand: Vec<(u32, u32)> = ma
        .bvh()
        .leaf_pairs(mb0.bvh(), |n1, n2| {
            n1.aabb()
                .loosened(margin)
                .intersects(&n2.aabb().transform_by(&pos12).loosened(margin))
        })
        .collect();
    let mut cs = cand.clone();
    cs.sort_unstable();
    cs.dedup();
    let missing = truth
        .iter()
        .filter(|p| cs.binary_search(p).is_err())
        .count();
    assert_eq!(
        missing, 0,
        "{name} {pose:?}: parry (pos12) candidates miss true pairs"
    );
    let mut got2: Vec<(u32, u32)> = cs
        .iter()
        .copied()
        .filter(|&(i, j)| tri_tri(&ta[i as usize], &tb[j as usize]))
        .collect();
    got2.sort_unstable();
    assert_eq!(
        got2, truth,
        "{name} {pose:?}: parry (pos12) + tri_tri != intersecting_pairs"
    );

    if brute {
        assert_eq!(
            brute_force_pairs(&ta, &tb),
            truth,
            "{name} {pose:?}: brute force disagrees"
        );
    }
    eprintln!(
        "{name:>18} {:>5} x {:>5} tris, pose {:?}: {} pairs, parry candidates {}",
        ta.len(),
        tb.len(),
        pose,
        truth.len(),
        cs.len()
    );
    truth.len()
}

#[test]
fn oracle_vs_parry_sphere_torus() {
    let a = mesh::sphere(2000);
    let b = mesh::torus(2000);
    let poses = [
        Pose::default(),
        Pose::new(0.0, 0.0, 90.0, 0.0, 0.0, 0.0), // exact quarter turn: shared geometry stays exact
        Pose::new(90.0, 0.0, 0.0, 0.25, 0.0, 0.5),
        Pose::new(17.0, -33.0, 71.0, 0.3, -0.2, 0.1),
        Pose::new(45.0, 45.0, 0.0, 1.1, 0.0, 0.0),
        Pose::new(-120.0, 10.0, 200.0, 0.0, 0.9, -0.4),
        Pose::new(0.0, 0.0, 0.0, 5.0, 0.0, 0.0), // disjoint
    ];
    let mut total = 0;
    for (k, p) in poses.iter().enumerate() {
        total += check_scene("sphere/torus", &a, &b, p, k == 3);
    }
    assert!(total > 0);
    // Sphere vs itself at the identity: every pair of neighbours touches exactly.
    let n = check_scene("sphere/sphere", &a, &a, &Pose::default(), true);
    assert!(n >= a.len() * 10, "{n} pairs: neighbours must touch");
    // Sphere vs a quarter-turned copy of itself (exact quarter turn, nearly coincident surfaces).
    check_scene(
        "sphere/sphere90",
        &a,
        &a,
        &Pose::new(0.0, 0.0, 90.0, 0.0, 0.0, 0.0),
        false,
    );
}

#[test]
fn oracle_vs_parry_bunny() {
    let a = mesh::resolve("bunny")
        .expect("bunny")
        .scaled_into_unit_cube()
        .expect("in range");
    let poses = [
        Pose::default(), // identical meshes: all neighbour contacts
        Pose::new(0.0, 90.0, 0.0, 0.0, 0.0, 0.0),
        Pose::new(30.0, 60.0, 90.0, 0.05, 0.0, 0.0),
        Pose::new(-11.0, 7.0, 123.0, 0.2, -0.1, 0.15),
        Pose::new(180.0, 0.0, 0.0, 0.0, 0.3, 0.0),
    ];
    for p in &poses {
        check_scene("bunny/bunny", &a, &a, p, false);
    }
}
