//! Proptest strategies for the hard-case families of src/hard_cases/ (placements,
//! exact tiny offsets, every family) and general poses, shared by the hard-case and RTL
//! triangle testbenches.
#![allow(dead_code)] // each testbench uses its own subset

use collision_chip::hard_cases::{self as hc, Case, Placement};
use proptest::prelude::*;

/// Placements: offsets 0 or of magnitude 1e3, 1e5, 1e7 (integers), power-of-two scale
/// 2^-8..2^8, any quarter turns.
pub fn placement() -> impl Strategy<Value = Placement> {
    (
        prop::sample::select(vec![0.0, 1e3, 1e5, 1e7]),
        prop::array::uniform3(-1.0..1.0f64),
        -8i32..=8,
        prop::array::uniform3(0u8..4),
    )
        .prop_map(|(mag, f, sl, turns)| Placement {
            offset: f.map(|x| (x * mag).round()),
            scale: 2f64.powi(sl),
            turns,
        })
}

/// The finest local grid 2^e such that `scale * l + offset` stays exact for local
/// coordinates |l| <= extent that are multiples of 2^e.
pub fn floor_log2(p: &Placement, extent: f64) -> i32 {
    let m = p.offset.iter().fold(0.0f64, |a, &b| a.max(b.abs())) + extent * p.scale;
    (m.log2().floor() as i32 + 1 - 52) - p.scale.log2() as i32
}

/// A small positive dyadic 1..3 * 2^e with floor <= e <= -9 (1e-9 is about 2^-30).
pub fn tiny(floor: i32) -> BoxedStrategy<f64> {
    let lo = floor.max(-50);
    (1u32..4, lo..=(-9).max(lo))
        .prop_map(|(m, e)| m as f64 * 2f64.powi(e))
        .boxed()
}

/// 0 or +-tiny.
pub fn near_zero(floor: i32) -> BoxedStrategy<f64> {
    prop_oneof![2 => Just(0.0), 1 => tiny(floor), 1 => tiny(floor).prop_map(|x| -x)].boxed()
}

pub fn grid(n: i32, lo: i32, hi: i32) -> BoxedStrategy<f64> {
    (lo..=hi).prop_map(move |k| k as f64 / 2f64.powi(n)).boxed()
}

pub fn pv_vertex_vertex() -> BoxedStrategy<Case> {
    placement()
        .prop_flat_map(|p| (Just(p), prop_oneof![Just(0.0), tiny(floor_log2(&p, 4.0))]))
        .prop_map(|(p, g)| hc::vertex_vertex(&p, g))
        .boxed()
}

pub fn pv_vertex_edge() -> BoxedStrategy<Case> {
    placement()
        .prop_flat_map(|p| {
            let f = floor_log2(&p, 4.0);
            let s = prop_oneof![
                grid(8, 0, 256),
                Just(0.0),
                Just(1.0),
                near_zero(f),
                near_zero(f).prop_map(|d| 1.0 + d)
            ];
            (Just(p), 0u8..3, s, prop_oneof![Just(0.0), tiny(f)])
        })
        .prop_map(|(p, e, s, g)| hc::vertex_edge(&p, e, s, g))
        .boxed()
}

pub fn pv_vertex_face() -> BoxedStrategy<Case> {
    placement()
        .prop_flat_map(|p| {
            let f = floor_log2(&p, 4.0);
            // touching or hovering anywhere near A, or piercing inside with a margin
            let touch = (
                grid(6, -8, 72),
                grid(6, -8, 72),
                prop_oneof![Just(0.0), tiny(f)],
            )
                .prop_map(|(u, v, h)| ([u, v], h));
            let pierce = (
                1i32..=30,
                1i32..=30,
                tiny(f.max(-40)).prop_map(|x| -(x.min(1.0 / 256.0))),
            )
                .prop_filter("inside with margin", |(i, j, _)| i + j <= 63)
                .prop_map(|(i, j, h)| ([i as f64 / 64.0, j as f64 / 64.0], h));
            (Just(p), prop_oneof![touch, pierce])
        })
        .prop_map(|(p, (uv, h))| hc::vertex_face(&p, uv, h))
        .boxed()
}

pub fn pv_edge_edge() -> BoxedStrategy<Case> {
    placement()
        .prop_flat_map(|p| {
            let f = floor_log2(&p, 4.0);
            let s = prop_oneof![
                grid(8, 0, 256),
                near_zero(f),
                near_zero(f).prop_map(|d| 1.0 + d)
            ];
            (Just(p), s, prop_oneof![Just(0.0), tiny(f)])
        })
        .prop_map(|(p, s, g)| hc::edge_edge(&p, s, g))
        .boxed()
}

pub fn pv_coplanar() -> BoxedStrategy<Case> {
    placement()
        .prop_flat_map(|p| {
            let f = floor_log2(&p, 4.0);
            (
                Just(p),
                -20i32..=20,
                0u8..5,
                near_zero(f),
                grid(4, -20, 20),
                any::<bool>(),
            )
        })
        .prop_map(|(p, k, which, d, free, tilted)| {
            let dx = k as f64 / 16.0;
            // dy on (or just off) a face of the hexagon A - A, or free
            let dy = match which {
                0 => (1.0 - dx) + d,
                1 => (-1.0 - dx) + d,
                2 => 1.0 + d,
                3 => -1.0 + d,
                _ => free,
            };
            hc::coplanar(&p, [dx, dy], tilted)
        })
        .boxed()
}

pub fn pv_shared_edge() -> BoxedStrategy<Case> {
    (placement(), prop::array::uniform3(-8i32..=8))
        .prop_filter("apex off the shared line", |(_, a)| {
            a[2] != 0 || a[0] + a[1] != 4
        })
        .prop_map(|(p, a)| hc::shared_edge(&p, a.map(|x| x as f64 / 4.0)))
        .boxed()
}

pub fn pv_needle() -> BoxedStrategy<Case> {
    placement()
        .prop_flat_map(|p| {
            let f = floor_log2(&p, 4.0);
            let wmax = 20.min(-f - 2).max(4);
            (
                Just(p),
                grid(6, -4, 68),
                near_zero(f),
                any::<bool>(),
                4..=wmax,
                grid(6, -4, 68),
            )
        })
        .prop_map(|(p, v, d, at_edge, w, u)| {
            let u = if at_edge { (1.0 - v) + d } else { u };
            hc::needle(&p, [u, v], w)
        })
        .boxed()
}

pub fn pv_sliver_pair() -> BoxedStrategy<Case> {
    placement()
        .prop_flat_map(|p| {
            let f = floor_log2(&p, 4.0);
            let wmax = ((1 - f) / 2).clamp(3, 20);
            (Just(p), 3..=wmax, 0u8..3, near_zero(f))
        })
        .prop_map(|(p, wl, which, d)| {
            let w = 2f64.powi(-wl);
            let top = w / 2.0 + 2.0 * w * w;
            let y0 = match which {
                0 => d,
                1 => top + d,
                _ => top / 2.0,
            };
            hc::sliver_pair(&p, wl, y0)
        })
        .boxed()
}

pub fn pv_zero_area() -> BoxedStrategy<Case> {
    placement()
        .prop_flat_map(|p| {
            let f = floor_log2(&p, 4.0);
            let xy = (grid(4, -4, 20), grid(4, -4, 20));
            let pt = (xy.clone(), near_zero(f)).prop_map(|((x, y), z)| (0u8, [x, y, z, 0.0]));
            let seg = (xy, near_zero(f), 1i32..4)
                .prop_map(|((x, y), z0, l)| (1u8, [x, y, z0, z0 + l as f64 / 4.0]));
            let segseg = (grid(4, -4, 20), near_zero(f), near_zero(f), 1i32..4)
                .prop_map(|(s, y0, z, l)| (2u8, [s, y0, y0 + l as f64 / 4.0, z]));
            (Just(p), prop_oneof![pt, seg, segseg])
        })
        .prop_map(|(p, (kind, v))| match kind {
            0 => hc::point(&p, [v[0], v[1], v[2]]),
            1 => hc::vertical_segment(&p, [v[0], v[1]], v[2], v[3]),
            _ => hc::segment_pair(&p, v[0], v[1], v[2], v[3]),
        })
        .boxed()
}

pub fn pv_near_parallel() -> BoxedStrategy<Case> {
    placement()
        .prop_flat_map(|p| {
            let f = floor_log2(&p, 4.0);
            (Just(p), near_zero(f), near_zero(f), any::<bool>())
        })
        .prop_map(|(p, gap, t, cross)| {
            // tilt either independent or exactly reaching through the plane (-2 gap)
            let tilt = if cross { -2.0 * gap } else { t };
            hc::near_parallel(&p, gap, tilt)
        })
        .boxed()
}

pub fn pv_scale_ratio() -> BoxedStrategy<Case> {
    (placement(), 0i32..=13, 0i32..=13)
        .prop_flat_map(|(p, big, small)| {
            let f = floor_log2(&p, 4.0 * 2f64.powi(big)).max(-small - 20);
            let s = 2f64.powi(-small);
            let h = prop_oneof![
                Just(0.0),
                tiny(f),
                tiny(f).prop_map(|x| -x),
                Just(-s),
                tiny(f).prop_map(move |x| -s - x)
            ];
            (Just(p), Just(big), Just(small), h, any::<bool>())
        })
        .prop_map(|(p, big, small, h, swap)| hc::scale_ratio(&p, big, small, h, swap))
        .boxed()
}

pub fn pv_tetra() -> BoxedStrategy<Case> {
    placement()
        .prop_flat_map(|p| {
            let f = floor_log2(&p, 4.0);
            (
                Just(p),
                grid(4, -2, 18),
                near_zero(f),
                prop_oneof![Just(0.0), tiny(f)],
            )
        })
        .prop_map(|(p, x, d, h)| hc::tetra_on_square(&p, [x, x + d], h))
        .boxed()
}

pub fn any_case() -> BoxedStrategy<Case> {
    prop_oneof![
        pv_vertex_vertex(),
        pv_vertex_edge(),
        pv_vertex_face(),
        pv_edge_edge(),
        pv_coplanar(),
        pv_shared_edge(),
        pv_needle(),
        pv_sliver_pair(),
        pv_zero_area(),
        pv_near_parallel(),
        pv_scale_ratio(),
        pv_tetra(),
    ]
    .boxed()
}

/// Generic rotations (not placement-exact): the answer is the oracle's.
pub fn general_pose() -> impl Strategy<Value = collision_chip::pose::Pose> {
    (
        prop::array::uniform3(-180.0..180.0f64),
        prop::array::uniform3(-2.0..2.0f64),
    )
        .prop_map(|(r, t)| collision_chip::pose::Pose { rot_deg: r, t })
}
