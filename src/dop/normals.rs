//! The fixed DOP orientations B_1..B_k (DATE'05 Eq. 1) and the triangulated sphere of
//! normals used by the host to pick the correspondence j (WSCG'03 Eq. 3).
//!
//! Normals are small integer vectors (not normalised): B_j . x is then a sum of at most
//! three signed coordinates. They come in antiparallel pairs: B_{i+k/2} = -B_i, so the DOP
//! spans [-d_{i+k/2}, d_i] along B_i. Index `opp(i) = (i + k/2) mod k`.

use nalgebra::{Matrix3, Vector3};
use std::sync::OnceLock;

/// The k values the chip supports.
use crate::chip::config::{check_k, SUPPORTED_K};

const AXES: [[i8; 3]; 3] = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
const CORNERS4: [[i8; 3]; 4] = [[1, 1, 1], [1, -1, 1], [1, 1, -1], [1, -1, -1]];
const EDGES6: [[i8; 3]; 6] = [
    [1, 1, 0],
    [1, 0, 1],
    [0, 1, 1],
    [1, -1, 0],
    [1, 0, -1],
    [0, 1, -1],
];
/// The three corner diagonals of the 24-DOP (as in FCL): x+y-z, x-y+z, -x+y+z.
const CORNERS3: [[i8; 3]; 3] = [[1, 1, -1], [1, -1, 1], [-1, 1, 1]];

/// One k-DOP orientation set with its triangulated sphere of normals.
#[derive(Debug)]
pub struct DopNormals {
    pub k: usize,
    /// B_0..B_{k-1}; the second half is the negation of the first.
    pub b: Vec<Vector3<f64>>,
    /// Triangles (index triples into `b`) of the convex hull of the unit normals. Every
    /// direction lies in the cone of at least one of them.
    pub hull: Vec<HullTriangle>,
    /// The first half's components as columns (`x[i]`, `y[i]`, `z[i]` of B_i, i < k/2,
    /// zero beyond), so that a leaf's supports are computed for all normals at once in a
    /// loop the compiler vectorises ([`DopTree::dop`](super::DopTree::dop)).
    pub half: [[f64; HALF_LANES]; 3],
    /// The hull triangles' planes {x : plane . x = 1} as columns (x, y, z of triangle t's
    /// plane at `t`, zero beyond): the ray through a direction b leaves the hull through
    /// the triangle(s) with the largest plane . b, which the host's cone search computes for
    /// all at once in a loop the compiler vectorises.
    pub planes: [[f64; MAX_HULL]; 3],
}

/// The largest k/2 of [`SUPPORTED_K`] rounded up to even (whole pairs of vector lanes).
pub const HALF_LANES: usize = (SUPPORTED_K[SUPPORTED_K.len() - 1] / 2 + 1) & !1;

/// The most triangles [`DopNormals::hull`] has for any of [`SUPPORTED_K`] (48, k = 26;
/// checked when a set is built): the host's cone search keeps one value per triangle on
/// the stack.
pub const MAX_HULL: usize = 48;

/// One triangle of the hull of the unit normals.
#[derive(Debug)]
pub struct HullTriangle {
    pub j: [usize; 3],
    /// Inverse of the matrix with columns B_j0, B_j1, B_j2: lambda = inv * b.
    pub inv: Matrix3<f64>,
}

impl DopNormals {
    /// The normal set for `k` (one of [`SUPPORTED_K`]), built once per process.
    pub fn get(k: usize) -> Result<&'static DopNormals, String> {
        static SETS: [OnceLock<DopNormals>; 5] = [
            OnceLock::new(),
            OnceLock::new(),
            OnceLock::new(),
            OnceLock::new(),
            OnceLock::new(),
        ];
        check_k(k)?;
        let slot = SUPPORTED_K.iter().position(|&s| s == k).expect("checked");
        Ok(SETS[slot].get_or_init(|| DopNormals::build(k)))
    }

    fn build(k: usize) -> DopNormals {
        let half: Vec<[i8; 3]> = match k {
            6 => AXES.to_vec(),
            14 => [&AXES[..], &CORNERS4[..]].concat(),
            18 => [&AXES[..], &EDGES6[..]].concat(),
            24 => [&AXES[..], &EDGES6[..], &CORNERS3[..]].concat(),
            26 => [&AXES[..], &CORNERS4[..], &EDGES6[..]].concat(),
            _ => unreachable!("checked by get()"),
        };
        let to_v =
            |n: &[i8; 3], s: f64| Vector3::new(n[0] as f64 * s, n[1] as f64 * s, n[2] as f64 * s);
        let b: Vec<Vector3<f64>> = half
            .iter()
            .map(|n| to_v(n, 1.0))
            .chain(half.iter().map(|n| to_v(n, -1.0)))
            .collect();
        let js = convex_hull_triangles(&b);
        assert!(
            js.len() <= MAX_HULL,
            "k = {k}: {} hull triangles, more than MAX_HULL",
            js.len()
        );
        let mut planes = [[0.0; MAX_HULL]; 3];
        let hull = js
            .into_iter()
            .enumerate()
            .map(|(t, j)| {
                let m = Matrix3::from_columns(&[b[j[0]], b[j[1]], b[j[2]]]);
                let u = j.map(|i| b[i].normalize());
                let n = (u[1] - u[0]).cross(&(u[2] - u[0]));
                let n = if n.dot(&u[0]) < 0.0 { -n } else { n };
                let plane = n / n.dot(&u[0]);
                (0..3).for_each(|c| planes[c][t] = plane[c]);
                HullTriangle {
                    j,
                    inv: m.try_inverse().expect("hull triangles are not flat"),
                }
            })
            .collect();
        let mut cols = [[0.0; HALF_LANES]; 3];
        for (i, n) in half.iter().enumerate() {
            (0..3).for_each(|c| cols[c][i] = n[c] as f64);
        }
        DopNormals {
            k,
            b,
            hull,
            half: cols,
            planes,
        }
    }

    /// Index of the antiparallel normal.
    pub fn opp(&self, i: usize) -> usize {
        (i + self.k / 2) % self.k
    }
}

/// All triangles of the convex hull of the normalised points (brute force over triples:
/// k <= 26, done once). Faces with more than three coplanar points contribute every
/// triangle of the face; the host only needs some cone containing each direction.
fn convex_hull_triangles(b: &[Vector3<f64>]) -> Vec<[usize; 3]> {
    let u: Vec<Vector3<f64>> = b.iter().map(|v| v.normalize()).collect();
    let n = u.len();
    let mut out = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            for l in j + 1..n {
                let nrm = (u[j] - u[i]).cross(&(u[l] - u[i]));
                if nrm.norm() < 1e-9 {
                    continue;
                }
                let side: Vec<f64> = (0..n).map(|p| nrm.dot(&(u[p] - u[i]))).collect();
                if side.iter().all(|&s| s <= 1e-9) || side.iter().all(|&s| s >= -1e-9) {
                    out.push([i, j, l]);
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn antiparallel_pairs_and_counts() {
        for k in SUPPORTED_K {
            let s = DopNormals::get(k).unwrap();
            assert_eq!(s.b.len(), k);
            for i in 0..k {
                assert_eq!(s.b[i], -s.b[s.opp(i)]);
            }
            // all normals distinct
            for i in 0..k {
                for j in 0..i {
                    assert_ne!(s.b[i], s.b[j], "k={k}");
                }
            }
        }
    }

    #[test]
    fn k24_has_the_fcl_corner_diagonals() {
        let s = DopNormals::get(24).unwrap();
        for c in CORNERS3 {
            let v = Vector3::new(c[0] as f64, c[1] as f64, c[2] as f64);
            assert!(s.b.contains(&v));
        }
        assert!(!s.b.contains(&Vector3::new(1.0, 1.0, 1.0)));
    }

    #[test]
    fn hull_cones_cover_the_sphere() {
        // Fibonacci-sphere directions: each must lie in a hull cone (lambda >= 0).
        for k in SUPPORTED_K {
            let s = DopNormals::get(k).unwrap();
            for q in 0..500 {
                let z = 1.0 - 2.0 * (q as f64 + 0.5) / 500.0;
                let phi = q as f64 * 2.399963229728653;
                let r = (1.0 - z * z).sqrt();
                let d = Vector3::new(r * phi.cos(), r * phi.sin(), z);
                let covered = s
                    .hull
                    .iter()
                    .any(|t| (t.inv * d).iter().all(|&x| x >= -1e-12));
                assert!(covered, "k={k} direction {d:?} in no cone");
            }
        }
    }

    #[test]
    fn unsupported_k_is_an_error() {
        assert!(DopNormals::get(8)
            .unwrap_err()
            .contains("6, 14, 18, 24, 26"));
    }
}
