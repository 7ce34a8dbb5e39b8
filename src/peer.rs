//! The software peer of the speed comparisons (feature `parry`, off by default so that the
//! library does not depend on parry): parry3d-f64's BVH `leaf_pairs` with the relative pose
//! on the AABBs, then the exact triangle test (`oracle::tri_tri` on the f64-placed
//! triangles): exact all pairs, as the golden model answers.

use crate::mesh::Mesh;
use crate::oracle::{self, Tri};
use crate::pose::Pose;
use parry3d_f64::bounding_volume::BoundingVolume;
use parry3d_f64::glamx::{DMat3, DQuat};
use parry3d_f64::math::{Pose as PPose, Vector};
use parry3d_f64::shape::TriMesh;

/// One object as the peer holds it: parry's mesh (with its BVH) and the f64 triangles.
pub struct PeerMesh {
    mesh: TriMesh,
    tris: Vec<Tri>,
}

impl PeerMesh {
    pub fn new(m: &Mesh) -> PeerMesh {
        let vs = m
            .vertices
            .iter()
            .map(|p| Vector::new(p.x, p.y, p.z))
            .collect();
        PeerMesh {
            mesh: TriMesh::new(vs, m.triangles.clone()).expect("parry trimesh"),
            tris: m.triangles_f64(),
        }
    }
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

/// The intersecting pairs of `a` and `b` placed by `pose` (exact), counted. AABBs are
/// loosened by 1e-9 so parry's own f64 rounding cannot drop a touching pair.
pub fn all_pairs(a: &PeerMesh, b: &PeerMesh, pose: &Pose) -> usize {
    traverse(a, b, pose, || ()).1
}

/// The peer's work in [`all_pairs`] at `pose`, counted (not timed): box tests, leaf pairs
/// tested exactly, intersecting pairs.
pub fn work(a: &PeerMesh, b: &PeerMesh, pose: &Pose) -> [usize; 3] {
    let boxes = std::cell::Cell::new(0);
    let (leaves, hits) = traverse(a, b, pose, || boxes.set(boxes.get() + 1));
    [boxes.get(), leaves, hits]
}

/// parry's BVH traversal and the exact test: leaf pairs and hits; `on_box` at each box test.
#[inline(always)]
fn traverse(a: &PeerMesh, b: &PeerMesh, pose: &Pose, on_box: impl Fn()) -> (usize, usize) {
    let pos12 = parry_pose(pose);
    let (r, t) = (pose.rotation(), pose.translation());
    let leaves = a.mesh.bvh().leaf_pairs(b.mesh.bvh(), |n1, n2| {
        on_box();
        n1.aabb()
            .loosened(1e-9)
            .intersects(&n2.aabb().transform_by(&pos12))
    });
    leaves.fold((0, 0), |(n, hits), (i, j)| {
        (
            n + 1,
            hits + oracle::tri_tri(&a.tris[i as usize], &b.tris[j as usize].map(|p| r * p + t))
                as usize,
        )
    })
}
