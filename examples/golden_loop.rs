//! The golden model on `golden_vs_parry`'s queries of one mesh at one centre distance, run N
//! times over the bench's orientations: time per query, and a target for profilers.
//!
//! ```sh
//! cargo run --release --example golden_loop -- bunny 1.0 20
//! valgrind --tool=callgrind target/release/examples/golden_loop bunny 1.0 1
//! ```

use collision_chip::chip::config::ChipConfig;
use collision_chip::chip::reg::Mode;
use collision_chip::mesh;
use collision_chip::pose::{sweep_poses, Sweep};
use collision_chip::query::Chip;
use collision_chip::traversal::Traversal;

fn main() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let name = args.next().unwrap_or("bunny".into());
    let d: f64 = args.next().map_or(Ok(1.0), |s| {
        s.parse().map_err(|e| format!("the distance {s:?}: {e}"))
    })?;
    let reps: usize = args.next().map_or(Ok(20), |s| {
        s.parse().map_err(|e| format!("the repetitions {s:?}: {e}"))
    })?;
    let m = mesh::resolve(&name)
        .and_then(|m| m.scaled_into_unit_cube())
        .map_err(|e| e.to_string())?;
    let tris = m.triangles_f64();
    let chip = Chip::new(&tris, &tris, ChipConfig::default())?;
    let poses = sweep_poses(&Sweep {
        distances: vec![d],
        orientations: 16,
        seed: 1,
    })?;
    let t = std::time::Instant::now();
    let mut pairs = 0;
    for _ in 0..reps.max(1) {
        pairs = poses
            .iter()
            .map(|p| chip.query(&p.pose, Mode::All, Traversal::Lifo).pairs.len())
            .sum::<usize>();
    }
    let n = (reps.max(1) * poses.len()) as f64;
    println!(
        "{name} at d = {d}: {:.1} pairs, {:.1} us a query",
        pairs as f64 / poses.len() as f64,
        t.elapsed().as_secs_f64() / n * 1e6
    );
    Ok(())
}
