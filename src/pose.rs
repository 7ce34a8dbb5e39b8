//! The relative pose of object B (the tumbled object Q of DATE'05) in A's frame (O).
//!
//! `x_A = Rz(rz) * Ry(ry) * Rx(rx) * x_B + t`, angles in degrees, everything in f64.
//! The f64 images of B's vertices under this map are, by definition, the input geometry
//! that the exact oracle judges.

use nalgebra::{Matrix3, Point3, Vector3};
use rand::{Rng, SeedableRng};
use serde::{Deserialize, Serialize};

/// Rotation angles in degrees (applied x, then y, then z) and translation of B in A's frame.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Pose {
    pub rot_deg: [f64; 3],
    pub t: [f64; 3],
}

impl Default for Pose {
    fn default() -> Self {
        Pose {
            rot_deg: [0.0; 3],
            t: [0.0; 3],
        }
    }
}

impl Pose {
    pub fn new(rx: f64, ry: f64, rz: f64, tx: f64, ty: f64, tz: f64) -> Pose {
        Pose {
            rot_deg: [rx, ry, rz],
            t: [tx, ty, tz],
        }
    }

    /// Parses `rx,ry,rz,tx,ty,tz` (degrees, then lengths).
    pub fn parse(s: &str) -> Result<Pose, String> {
        let v: Result<Vec<f64>, _> = s.split(',').map(|x| x.trim().parse::<f64>()).collect();
        match v {
            Ok(v) if v.len() == 6 && v.iter().all(|x| x.is_finite()) => {
                Ok(Pose::new(v[0], v[1], v[2], v[3], v[4], v[5]))
            }
            Ok(v) if v.len() != 6 => Err(format!(
                "pose `{s}` has {} numbers; expected six: rx,ry,rz,tx,ty,tz (degrees, then lengths)",
                v.len()
            )),
            _ => Err(format!(
                "pose `{s}` is not six finite numbers rx,ry,rz,tx,ty,tz (degrees, then lengths)"
            )),
        }
    }

    /// The pose as `rx,ry,rz,tx,ty,tz`, the form [`Pose::parse`] reads (shortest round trip).
    pub fn text(&self) -> String {
        let v: Vec<String> = self
            .rot_deg
            .iter()
            .chain(&self.t)
            .map(|x| format!("{x:?}"))
            .collect();
        v.join(",")
    }

    /// The rotation matrix R = Rz * Ry * Rx. Angles that are multiples of 90 degrees give
    /// exact 0 and +-1 entries, so axis-aligned poses stay exact.
    pub fn rotation(&self) -> Matrix3<f64> {
        let [cx, sx] = cos_sin_deg(self.rot_deg[0]);
        let [cy, sy] = cos_sin_deg(self.rot_deg[1]);
        let [cz, sz] = cos_sin_deg(self.rot_deg[2]);
        let rx = Matrix3::new(1.0, 0.0, 0.0, 0.0, cx, -sx, 0.0, sx, cx);
        let ry = Matrix3::new(cy, 0.0, sy, 0.0, 1.0, 0.0, -sy, 0.0, cy);
        let rz = Matrix3::new(cz, -sz, 0.0, sz, cz, 0.0, 0.0, 0.0, 1.0);
        rz * ry * rx
    }

    pub fn translation(&self) -> Vector3<f64> {
        Vector3::new(self.t[0], self.t[1], self.t[2])
    }

    /// Maps a point of B's frame into A's frame (f64).
    pub fn apply(&self, p: &Point3<f64>) -> Point3<f64> {
        self.rotation() * p + self.translation()
    }

    /// Maps many points at once (the rotation is built once).
    pub fn apply_all(&self, pts: &[Point3<f64>]) -> Vec<Point3<f64>> {
        let (r, t) = (self.rotation(), self.translation());
        pts.iter().map(|p| r * p + t).collect()
    }
}

/// cos and sin of an angle in degrees, exact at multiples of 90 degrees.
///
/// The angle is reduced with `%`, which is exact (so 1e20 degrees is exactly 280), into
/// (-360, 360); `rem_euclid` would round a tiny negative angle up to 360.0 and treat it as a
/// multiple of 90.
fn cos_sin_deg(deg: f64) -> [f64; 2] {
    let r = deg % 360.0;
    if r % 90.0 == 0.0 {
        match (r / 90.0) as i32 {
            0 => [1.0, 0.0],
            1 | -3 => [0.0, 1.0],
            2 | -2 => [-1.0, 0.0],
            _ => [0.0, -1.0],
        }
    } else {
        let rad = r.to_radians();
        [rad.cos(), rad.sin()]
    }
}

#[derive(Debug, Clone, PartialEq, serde::Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Sweep {
    pub distances: Vec<f64>,
    pub orientations: usize,
    #[serde(default = "one")]
    pub seed: u64,
}

fn one() -> u64 {
    1
}

/// One pose of a scene or study, with the sweep distance it belongs to (if any).
#[derive(Debug, Clone, Copy)]
pub struct ScenePose {
    pub pose: Pose,
    pub distance: Option<f64>,
}

/// The most poses a sweep may have: each is a full query, and the poses are held in memory.
pub const MAX_POSES: usize = 1_000_000;

/// The WSCG'03 benchmark protocol: at each distance (centres apart along x), B takes
/// `orientations` rotations with angles drawn uniformly from [0, 360) degrees (seeded).
pub fn sweep_poses(s: &Sweep) -> Result<Vec<ScenePose>, String> {
    if s.distances.is_empty() || s.orientations == 0 {
        return Err("a sweep needs at least one distance and one orientation".into());
    }
    if let Some(d) = s.distances.iter().find(|d| !d.is_finite()) {
        return Err(format!("sweep distance {d} is not finite"));
    }
    let n = s.distances.len().saturating_mul(s.orientations);
    if n > MAX_POSES {
        return Err(format!(
            "a sweep of {} distances x {} orientations is {n} poses; at most {MAX_POSES} poses \
             (each is a full query): use fewer orientations",
            s.distances.len(),
            s.orientations
        ));
    }
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(s.seed);
    let rots: Vec<[f64; 3]> = (0..s.orientations)
        .map(|_| {
            [
                rng.random_range(0.0..360.0),
                rng.random_range(0.0..360.0),
                rng.random_range(0.0..360.0),
            ]
        })
        .collect();
    Ok(s.distances
        .iter()
        .flat_map(|&d| {
            rots.iter().map(move |&r| ScenePose {
                pose: Pose {
                    rot_deg: r,
                    t: [d, 0.0, 0.0],
                },
                distance: Some(d),
            })
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quarter_turn_about_z_is_exact() {
        let p = Pose::new(0.0, 0.0, 90.0, 1.0, 0.0, 0.0);
        assert_eq!(
            p.apply(&Point3::new(1.0, 0.0, 0.0)),
            Point3::new(1.0, 1.0, 0.0)
        );
    }

    #[test]
    fn order_is_x_then_y_then_z() {
        // Rx(90) sends y to z; then Ry(90) sends z to x.
        let p = Pose::new(90.0, 90.0, 0.0, 0.0, 0.0, 0.0);
        assert_eq!(
            p.apply(&Point3::new(0.0, 1.0, 0.0)),
            Point3::new(1.0, 0.0, 0.0)
        );
    }

    /// -1e-15 degrees was reduced to 360.0 and taken for a quarter-turn multiple,
    /// giving the rotation of 270 degrees.
    #[test]
    fn tiny_and_huge_angles_are_reduced_exactly() {
        let tiny = Pose::new(-1e-15, 0.0, 0.0, 0.0, 0.0, 0.0).rotation();
        assert!((tiny - Matrix3::identity()).amax() < 1e-16, "{tiny}");
        assert_eq!(tiny[(2, 1)], -(1e-15f64.to_radians()).sin());
        // 1e20 = 2^20 * 5^20 is an f64, and 1e20 mod 360 = 280 (1e20 = 0 mod 40, 1 mod 9).
        assert_eq!(
            Pose::new(0.0, 0.0, 1e20, 0.0, 0.0, 0.0).rotation(),
            Pose::new(0.0, 0.0, 280.0, 0.0, 0.0, 0.0).rotation()
        );
        for (neg, pos) in [
            (-90.0, 270.0),
            (-180.0, 180.0),
            (-270.0, 90.0),
            (-360.0, 0.0),
            (-450.0, 270.0),
        ] {
            assert_eq!(
                Pose::new(neg, 0.0, 0.0, 0.0, 0.0, 0.0).rotation(),
                Pose::new(pos, 0.0, 0.0, 0.0, 0.0, 0.0).rotation(),
                "{neg}"
            );
        }
    }

    #[test]
    fn parse_rejects_wrong_count_and_nan() {
        assert!(Pose::parse("1,2,3").unwrap_err().contains("3 numbers"));
        assert!(Pose::parse("1,2,3,4,5,nan").is_err());
        assert_eq!(Pose::parse("10,20,30,0.02,0,0").unwrap().t[0], 0.02);
    }

    #[test]
    fn sweep_size_is_checked_first() {
        let e = sweep_poses(&Sweep {
            distances: vec![1.0, 2.0],
            orientations: usize::MAX,
            seed: 1,
        })
        .unwrap_err();
        assert!(e.contains("at most 1000000 poses"), "{e}");
        assert_eq!(
            sweep_poses(&Sweep {
                distances: vec![1.0],
                orientations: MAX_POSES,
                seed: 1
            })
            .unwrap()
            .len(),
            MAX_POSES
        );
    }

    #[test]
    fn sweep_is_distances_times_orientations_and_seeded() {
        let s = Sweep {
            distances: vec![2.0, 1.0],
            orientations: 3,
            seed: 7,
        };
        let p = sweep_poses(&s).unwrap();
        assert_eq!(p.len(), 6);
        assert_eq!(p[0].pose.rot_deg, p[3].pose.rot_deg);
        assert_eq!(p[4].pose.t, [1.0, 0.0, 0.0]);
        let q = sweep_poses(&Sweep { seed: 8, ..s }).unwrap();
        assert_ne!(p[0].pose.rot_deg, q[0].pose.rot_deg);
    }
}
