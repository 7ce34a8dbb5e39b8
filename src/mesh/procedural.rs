//! Procedural meshes: UV sphere, torus, random triangle soup.

use super::Mesh;
use nalgebra::Point3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::PI;

fn ceil_div(a: usize, b: usize) -> usize {
    a.div_ceil(b)
}

/// A closed UV sphere of radius 1 centred at the origin with at least `n` triangles.
///
/// Exact rule: `s = max(2, ceil(sqrt(n / 4)))` stacks (latitude bands) and
/// `m = max(3, ceil(n / (2 (s - 1))))` slices; the mesh has exactly `2 · m · (s - 1)` triangles
/// (`m` per polar cap, `2m` per inner band) and `2 + m · (s - 1)` vertices (two poles plus
/// `s - 1` rings of `m`).  E.g. `sphere(1000)`: s = 16, m = 34, 1,020 triangles.
/// `n = 0` gives the minimum, a 6-triangle bipyramid.  All triangles are wound counter-clockwise
/// seen from outside, and every edge is shared by exactly two triangles.
pub fn sphere(n: usize) -> Mesh {
    let s = 2usize.max((n as f64 / 4.0).sqrt().ceil() as usize);
    let m = 3usize.max(ceil_div(n, 2 * (s - 1)));
    let mut vertices = Vec::with_capacity(2 + m * (s - 1));
    vertices.push(Point3::new(0.0, 0.0, 1.0));
    for i in 1..s {
        let theta = PI * i as f64 / s as f64;
        for j in 0..m {
            let phi = 2.0 * PI * j as f64 / m as f64;
            vertices.push(Point3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            ));
        }
    }
    let south = vertices.len() as u32;
    vertices.push(Point3::new(0.0, 0.0, -1.0));
    // ring i (1-based), slice j (mod m)
    let v = |i: usize, j: usize| (1 + (i - 1) * m + j % m) as u32;
    let mut triangles = Vec::with_capacity(2 * m * (s - 1));
    for j in 0..m {
        triangles.push([0, v(1, j), v(1, j + 1)]);
    }
    for i in 1..s - 1 {
        for j in 0..m {
            let (a, b, c, d) = (v(i, j), v(i, j + 1), v(i + 1, j), v(i + 1, j + 1));
            triangles.push([a, c, d]);
            triangles.push([a, d, b]);
        }
    }
    for j in 0..m {
        triangles.push([south, v(s - 1, j + 1), v(s - 1, j)]);
    }
    Mesh {
        name: format!("sphere:{n}"),
        vertices,
        triangles,
    }
}

/// A closed torus around the z axis (major radius 1, minor radius 0.4) with at least `n`
/// triangles.
///
/// Exact rule: `v = max(3, ceil(sqrt(n / 5)))` segments around the tube and
/// `u = max(3, ceil(n / (2 v)))` segments around the axis (so u ≈ 2.5 v, matching the radii);
/// exactly `2 · u · v` triangles and `u · v` vertices.  E.g. `torus(1000)`: v = 15, u = 34,
/// 1,020 triangles.  Wound counter-clockwise seen from outside; every edge is shared by exactly
/// two triangles.
pub fn torus(n: usize) -> Mesh {
    const R: f64 = 1.0;
    const RR: f64 = 0.4;
    let v = 3usize.max((n as f64 / 5.0).sqrt().ceil() as usize);
    let u = 3usize.max(ceil_div(n, 2 * v));
    let mut vertices = Vec::with_capacity(u * v);
    for i in 0..u {
        let phi = 2.0 * PI * i as f64 / u as f64;
        for j in 0..v {
            let theta = 2.0 * PI * j as f64 / v as f64;
            let rho = R + RR * theta.cos();
            vertices.push(Point3::new(
                rho * phi.cos(),
                rho * phi.sin(),
                RR * theta.sin(),
            ));
        }
    }
    let idx = |i: usize, j: usize| ((i % u) * v + j % v) as u32;
    let mut triangles = Vec::with_capacity(2 * u * v);
    for i in 0..u {
        for j in 0..v {
            let (a, b, c, d) = (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    Mesh {
        name: format!("torus:{n}"),
        vertices,
        triangles,
    }
}

/// `n` random small triangles in [-1,1]^3, deterministic for a given `seed` (ChaCha8).
///
/// With `h = 1 / cbrt(n)`, triangle `i` draws a centre uniformly from `[-1+h, 1-h]^3`, then its
/// three corners as centre + an offset uniform in `[-h, h]^3` (per-axis extent at most
/// `2 / cbrt(n)`, so the soup has roughly constant density), in this order, from
/// `ChaCha8Rng::seed_from_u64(seed)` with `random_range`.  Vertices are not shared:
/// vertex `3i + k` is corner `k` of triangle `i`.
pub fn soup(n: usize, seed: u64) -> Mesh {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let h = if n == 0 { 1.0 } else { 1.0 / (n as f64).cbrt() };
    let c_max = (1.0 - h).max(0.0);
    let mut vertices = Vec::with_capacity(3 * n);
    let mut triangles = Vec::with_capacity(n);
    for i in 0..n {
        let c = Point3::new(
            rng.random_range(-c_max..=c_max),
            rng.random_range(-c_max..=c_max),
            rng.random_range(-c_max..=c_max),
        );
        for _ in 0..3 {
            let p = Point3::new(
                c.x + rng.random_range(-h..=h),
                c.y + rng.random_range(-h..=h),
                c.z + rng.random_range(-h..=h),
            );
            vertices.push(p.map(|x: f64| x.clamp(-1.0, 1.0)));
        }
        let b = 3 * i as u32;
        triangles.push([b, b + 1, b + 2]);
    }
    Mesh {
        name: format!("soup:{n}:{seed}"),
        vertices,
        triangles,
    }
}
