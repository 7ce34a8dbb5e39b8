//! Host setup per query pose (DATE'05 Eq. 6, WSCG'03 Eq. 3): for each lane i the
//! correspondence j_i (three normals of B's DOP, the D.KLMSEL MUX control), the
//! coefficients C_i (lambda >= 0) and the offset c_i, plus the two 3x4 frame maps that
//! T.CHECK uses.
//!
//! Why the bound holds for every DOP: with b_i = R^T B_i = sum_l lambda_l B_{j_l} + r_i
//! and lambda >= 0, every x of B's DOP (B_j . x <= d_j) satisfies
//! B_i . (R x + t) = b_i . x + B_i . t <= sum_l lambda_l d_{j_l} + |r_i|_1 |x|_inf + B_i . t.
//! The host rounds lambda to the format (C), measures the residual r_i of that rounding
//! and pads c_i with |r_i|_1 X (X bounds |x|_inf over B's root DOP) and with the f64
//! rounding of B's vertices into A's frame, so that d'_i bounds the f64 geometry the
//! oracle judges. c_i is then rounded up. In `nearest-even` mode nothing is padded.

use crate::chip::config::{ChipConfig, DopRounding};
use crate::dop::normals::{DopNormals, MAX_HULL};
use crate::format::{Format, Rounding};
use crate::golden::certificate::Certificate;
use crate::pose::Pose;
use nalgebra::{Matrix3, Vector3};

/// A 3x4 affine map [L | t] in the chip format (row-major, column 3 = translation).
pub type Affine = [[f64; 4]; 3];

#[derive(Clone, Debug)]
pub struct HostSetup {
    /// j_i: the three normal indices of B's DOP feeding lane i (D.KLMSEL control).
    pub j: Vec<[u8; 3]>,
    /// C_i: the three non-negative coefficients of lane i.
    pub cmat: Vec<[f64; 3]>,
    /// c_i: the offset of lane i (B_i . t plus padding).
    pub cvec: Vec<f64>,
    /// A's frame to B's frame: x_B = R^T (x_A - t)  (M_AB of DATE'05 §4.2).
    pub m_ab: Affine,
    /// B's frame to A's frame: x_A = R x_B + t.
    pub m_ba: Affine,
    /// The error words of M_AB for T.CHECK's certificate, `[beta_m, beta_f]` (rounded
    /// up; docs/explanation/accuracy.md, "T.CHECK's certificate"): M_AB* is the exact [R^T | -R^T t]
    /// of the f64 pose, and beta_f also covers the f64 placement of B's vertices into A's
    /// frame (the geometry the oracle judges), seen in B's frame.
    pub beta_ab: [f64; 2],
    /// The same for M_BA = [R | t]; its translation error covers B's placement.
    pub beta_ba: [f64; 2],
    /// [S_A, S_B], the objects' scales ([`crate::golden::memory::object_scale`]).
    pub scale: [f64; 2],
}

/// What T.CHECK's error words need of the two objects
/// ([`ObjectImage::tri_side`](crate::golden::memory::ObjectImage::tri_side)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriSide {
    /// [S_A, S_B].
    pub scale: [f64; 2],
    /// The largest lambda >= |L*|_inf of B's triangles: the placement bound needs
    /// 4 lambda eta <= 1/2.
    pub lambda_max_b: f64,
}

impl TriSide {
    /// For a setup whose T.CHECK words nobody reads (the DOP unit's): unknown lambda.
    pub const UNUSED: TriSide = TriSide {
        scale: [1.0, 1.0],
        lambda_max_b: f64::INFINITY,
    };
}

impl HostSetup {
    /// One direction of TRI_UNIT: the frame map into the leaf's object, its error words and
    /// the scale of the vertices' object; `ab`: A's edges against U(B) (M_AB, S_A), else B's
    /// against U(A) (M_BA, S_B).
    pub fn tri_frame(&self, ab: bool) -> (&Affine, [f64; 2], f64) {
        if ab {
            (&self.m_ab, self.beta_ab, self.scale[0])
        } else {
            (&self.m_ba, self.beta_ba, self.scale[1])
        }
    }

    /// `b_coord_bound` is X = max |x|_inf over B's root DOP ([`DopTree::coord_bound`](crate::dop::DopTree::coord_bound)).
    pub fn new(cfg: &ChipConfig, pose: &Pose, b_coord_bound: f64, tri: TriSide) -> HostSetup {
        let (rot, t) = (pose.rotation(), pose.translation());
        let mut s = HostSetup::frames(cfg, &rot, &t, b_coord_bound, tri);
        s.set_lanes(&DopLanes::new(cfg, &rot, &t, b_coord_bound).all());
        s
    }

    /// TRI_UNIT's part of the setup only, its DOP lanes empty: for a query whose DOP unit
    /// computes its lanes when it needs them ([`DopLanes`]). `rot`, `t`: the pose's
    /// [`rotation`](Pose::rotation) and [`translation`](Pose::translation), which the caller
    /// computes once for the whole setup (its sines, cosines and angle reductions are a
    /// noticeable part of a query that ends at the root).
    pub fn frames(
        cfg: &ChipConfig,
        rot: &Matrix3<f64>,
        t: &Vector3<f64>,
        b_coord_bound: f64,
        tri: TriSide,
    ) -> HostSetup {
        let t_inf = t.amax();
        let rt = rot.transpose();
        let tab = -(rt * t);
        // T.CHECK's maps and their error words, in its format.
        let fmt = cfg.format.tri;
        let u = 2f64.powi(-53);
        // |fl(R x + t) - (R x + t)| <= 4u (|R| |x| + |t|), |R|_inf <= sqrt 3, |x|_inf <= X;
        // eta: the same move seen in B's frame.
        let place = 4.0 * u * (3f64.sqrt() * b_coord_bound + t_inf);
        let eta = 3f64.sqrt() * place;
        // The f64 products and sums: |fl(R^T t) - R^T t| <= 4u |R^T| |t| per entry.
        let tab_err = 4.0 * u * (rt.abs() * t.abs()).max();
        let m_ab = affine(fmt, &rt, &tab);
        let m_ba = affine(fmt, rot, t);
        // The placement bound needs 4 lambda eta <= 1/2 for every leaf of B.
        let eta_ab = if 4.0 * tri.lambda_max_b * eta <= 0.5 {
            eta
        } else {
            f64::INFINITY
        };
        let [sa, sb] = tri.scale;
        HostSetup {
            j: vec![],
            cmat: vec![],
            cvec: vec![],
            m_ab,
            m_ba,
            beta_ab: betas(fmt, &m_ab, tab_err, eta_ab, sb, sa),
            beta_ba: betas(fmt, &m_ba, place, 0.0, sa, sb),
            scale: tri.scale,
        }
    }

    /// The DOP lanes' words, lane 0 first.
    pub fn set_lanes(&mut self, lanes: &[Lane]) {
        self.j = lanes.iter().map(|l| l.j).collect();
        self.cmat = lanes.iter().map(|l| l.c).collect();
        self.cvec = lanes.iter().map(|l| l.cv).collect();
    }
}

/// One DOP lane's words: j_i (the D.KLMSEL control), C_i and c_i.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lane {
    pub j: [u8; 3],
    pub c: [f64; 3],
    pub cv: f64,
}

/// The DOP unit's part of the host setup of one pose (DATE'05 Eq. 6), a mirror pair of lanes
/// at a time: lane i < k/2 and lane i + k/2 share one cone search, the setup's main cost, so
/// that a query whose root pair some lane separates computes few of them.
#[derive(Clone, Debug)]
pub struct DopLanes {
    normals: &'static DopNormals,
    rt: Matrix3<f64>,
    t: Vector3<f64>,
    fmt: Format,
    outward: bool,
    x: f64,
}

impl DopLanes {
    /// `rot`, `t` as [`HostSetup::frames`] takes them.
    pub fn new(
        cfg: &ChipConfig,
        rot: &Matrix3<f64>,
        t: &Vector3<f64>,
        b_coord_bound: f64,
    ) -> DopLanes {
        DopLanes {
            normals: DopNormals::get(cfg.k).expect("k validated by the caller"),
            rt: rot.transpose(),
            t: *t,
            fmt: cfg.format.dop,
            outward: cfg.dop_rounding == DopRounding::Outward,
            x: b_coord_bound,
        }
    }

    pub fn k(&self) -> usize {
        self.normals.k
    }

    /// Every lane, lane 0 first.
    pub fn all(&self) -> Vec<Lane> {
        let pairs: Vec<[Lane; 2]> = (0..self.k() / 2).map(|i| self.pair(i)).collect();
        pairs
            .iter()
            .map(|p| p[0])
            .chain(pairs.iter().map(|p| p[1]))
            .collect()
    }

    /// Lanes i and i + k/2 (i < k/2). The hull is centrally symmetric: -b_i lies in the
    /// antipodal cone with the same lambdas, so the second lane mirrors the first.
    pub fn pair(&self, i: usize) -> [Lane; 2] {
        let n = self.normals;
        let (tri, lambda) = best_cone(n, &(self.rt * n.b[i]));
        [
            self.lane(i, tri, lambda),
            self.lane(i + self.k() / 2, tri.map(|x| n.opp(x)), lambda),
        ]
    }

    fn lane(&self, i: usize, tri: [usize; 3], lambda: [f64; 3]) -> Lane {
        let (normals, fmt, t, b_coord_bound) = (self.normals, self.fmt, &self.t, self.x);
        let eps = f64::EPSILON; // 2^-52
        let t_inf = t.amax();
        let bi = &normals.b[i];
        let b = self.rt * bi;
        let c3 = lambda.map(|l| fmt.round(l, Rounding::NearestEven));
        let bt = bi.dot(t);
        let c = if self.outward {
            let approx: Vector3<f64> = (0..3).map(|l| normals.b[tri[l]] * c3[l]).sum();
            let r = b - approx;
            // f64 error of b (3 products, 2 sums per entry) and of approx, generously.
            let scale: f64 = b.abs().sum()
                + (0..3)
                    .map(|l| c3[l] * normals.b[tri[l]].abs().sum())
                    .sum::<f64>();
            let resid = r.abs().sum() + 8.0 * eps * scale;
            let bi1 = bi.abs().sum();
            let transform_err = bi1 * 2.0 * eps * (3.0 * b_coord_bound + t_inf);
            let pad = resid * b_coord_bound + transform_err + bi1 * t_inf * eps;
            let pad = if pad.is_nan() { f64::INFINITY } else { pad };
            // next_up covers the rounding of this last f64 addition.
            fmt.round((bt + pad).next_up(), Rounding::TowardPositive)
        } else {
            fmt.round(bt, Rounding::NearestEven)
        };
        Lane {
            j: tri.map(|x| x as u8),
            c: c3,
            cv: c,
        }
    }
}

/// `[beta_m, beta_f]` of a frame map `b` (rounded to nearest from the f64 one, whose
/// translation is within `tr_err` of the ideal) into the leaf's object (scale `s_l`) from
/// the vertices' object (scale `s_v`), `eta` the placement move of the leaf's vertices (0
/// for the direction B vs U(A)), rounded up (docs/explanation/accuracy.md, "T.CHECK's certificate").
fn betas(fmt: Format, b: &Affine, tr_err: f64, eta: f64, s_l: f64, s_v: f64) -> [f64; 2] {
    let cert = Certificate::new(fmt, Rounding::NearestEven);
    let u1 = cert.u1;
    // the stored words' subnormal rounding; the vertices' too (a_x)
    let (a_lin, a_tr, a_x) = (cert.eta_s, cert.eta_s + tr_err, cert.eta_s);
    let col = |j: usize, a: f64| (0..3).map(|k| (1.0 + u1) * b[k][j].abs() + a).sum::<f64>();
    let b_lin = (0..3).map(|j| col(j, a_lin)).fold(0.0, f64::max);
    let b_tr = col(3, a_tr);
    let bm = (1.0 + u1) * b_lin + (b_tr + s_l) / s_v + 1.0;
    let bf = (1.0 + u1) * a_lin
        + (a_tr + 3.0 * a_x * b_lin + eta) / s_v
        + eta * (1.0 + u1) * b_lin / s_l
        + eta * b_tr / (s_l * s_v);
    [cert.word_up(bm), cert.word_up(bf)]
}

/// [l | t] rounded to nearest.
fn affine(fmt: Format, l: &Matrix3<f64>, t: &Vector3<f64>) -> Affine {
    let mut m = [[0.0; 4]; 3];
    for (r, row) in m.iter_mut().enumerate() {
        for (c, x) in row.iter_mut().enumerate() {
            *x = fmt.round(if c < 3 { l[(r, c)] } else { t[r] }, Rounding::NearestEven);
        }
    }
    m
}

/// The hull triangle whose cone contains `b`: the one the ray through b leaves the hull
/// of the unit normals by (largest `plane . b`; among coplanar triangles of one face, one
/// whose lambdas are >= 0), and its lambdas clamped to >= 0 (the clamping residual is padded).
/// Each `plane . b` is computed once, for all triangles in one vectorised loop (nalgebra's
/// `dot` order, `(x + y) + z`), and their largest taken with `>` (which skips a NaN as
/// `f64::max` does, in one instruction): this search is most of a lane pair's setup.
fn best_cone(n: &DopNormals, b: &Vector3<f64>) -> ([usize; 3], [f64; 3]) {
    let [px, py, pz] = &n.planes;
    let dots: [f64; MAX_HULL] = std::array::from_fn(|t| (px[t] * b.x + py[t] * b.y) + pz[t] * b.z);
    let dots = &dots[..n.hull.len()];
    let top = dots
        .iter()
        .fold(f64::NEG_INFINITY, |m, &d| if d > m { d } else { m });
    let (t, l) = n
        .hull
        .iter()
        .zip(dots)
        .filter(|&(_, &d)| d >= top - 1e-12 * top.abs())
        .map(|(t, _)| (t, t.inv * b))
        .max_by(|x, y| x.1.min().total_cmp(&y.1.min()))
        .expect("the hull is not empty");
    debug_assert!(
        l.min() >= -1e-12 * b.norm(),
        "direction {b:?} outside its cone: {l:?}"
    );
    (t.j, [l.x.max(0.0), l.y.max(0.0), l.z.max(0.0)])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chip::config::SUPPORTED_K;
    use rand::{Rng, SeedableRng};

    /// The cone search as it was first written: nalgebra's `dot` per triangle, computed
    /// again in the filter, and `f64::max`: another implementation of the same rule.
    fn best_cone_by_dot(n: &DopNormals, b: &Vector3<f64>) -> ([usize; 3], [f64; 3]) {
        let plane = |t: usize| Vector3::new(n.planes[0][t], n.planes[1][t], n.planes[2][t]);
        let top = (0..n.hull.len())
            .map(|t| plane(t).dot(b))
            .fold(f64::NEG_INFINITY, f64::max);
        let (t, l) = (0..n.hull.len())
            .filter(|&t| plane(t).dot(b) >= top - 1e-12 * top.abs())
            .map(|t| (&n.hull[t], n.hull[t].inv * b))
            .max_by(|x, y| x.1.min().total_cmp(&y.1.min()))
            .unwrap();
        (t.j, [l.x.max(0.0), l.y.max(0.0), l.z.max(0.0)])
    }

    /// The same cone and lambdas, bit for bit, for every k: on the normals themselves and
    /// sums of two (where triangles of a face tie), rotated by every multiple of 90 degrees
    /// about each axis, and on random directions and poses. Independently of how either
    /// search reads the planes, the cone contains the direction: its normals weighted by the
    /// lambdas give it back.
    #[test]
    fn best_cone_matches_the_search_by_dot() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        for k in SUPPORTED_K {
            let n = DopNormals::get(k).unwrap();
            let mut dirs: Vec<Vector3<f64>> =
                n.b.iter()
                    .flat_map(|x| n.b.iter().map(move |y| x + y))
                    .filter(|d| d.norm() > 0.0)
                    .collect();
            dirs.extend(n.b.iter().copied());
            for q in 0..4 {
                for axis in 0..3 {
                    let mut deg = [0.0; 3];
                    deg[axis] = 90.0 * q as f64;
                    let r = Pose {
                        rot_deg: deg,
                        t: [0.0; 3],
                    }
                    .rotation()
                    .transpose();
                    dirs.extend(n.b.iter().map(|b| r * b));
                }
            }
            for _ in 0..2000 {
                let pose = Pose {
                    rot_deg: std::array::from_fn(|_| rng.random_range(-180.0..180.0)),
                    t: [0.0; 3],
                };
                let b = n.b[rng.random_range(0..k)];
                dirs.push(pose.rotation().transpose() * b);
                dirs.push(Vector3::new(
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                ));
            }
            for d in &dirs {
                let (fast, slow) = (best_cone(n, d), best_cone_by_dot(n, d));
                assert_eq!(
                    (fast.0, fast.1.map(f64::to_bits)),
                    (slow.0, slow.1.map(f64::to_bits)),
                    "k = {k}, direction {d:?}"
                );
                let back: Vector3<f64> = (0..3).map(|l| n.b[fast.0[l]] * fast.1[l]).sum();
                assert!(
                    (back - d).norm() <= 1e-9 * d.norm(),
                    "k = {k}: direction {d:?} not in its cone {:?} ({back:?})",
                    fast.0
                );
            }
        }
    }
}
