//! The cycle model on one query of `vectors/chip`, run N times in a loop (the chip made and
//! dropped each time, as in a scene): wall-clock rate, and a target for profilers.
//!
//! ```sh
//! cargo run --release --example cycle_loop -- big_patch_lifo_all_slow_host 30
//! valgrind --tool=callgrind target/release/examples/cycle_loop k24_big_rec_patch_lifo_all 3
//! ```
//!
//! (`cargo bench --bench chip_sim` compares the same queries with Verilator and rust-hdl.)

use collision_chip::cycle;
use collision_chip::harness::chip_io::queries;

fn main() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let name = args.next().unwrap_or("big_patch_lifo_all_slow_host".into());
    let reps: usize = args.next().map_or(Ok(20), |s| {
        s.parse().map_err(|e| format!("the repetitions {s:?}: {e}"))
    })?;
    let q = queries()
        .into_iter()
        .find(|q| q.name == name)
        .ok_or(format!(
            "{name}: no such query in vectors/chip (see harness::chip_io::queries)"
        ))?;
    let p = q.prepare()?;
    let (params, setup) = (q.params(), p.chip.setup(&q.pose));
    let t = std::time::Instant::now();
    let mut cycles = 0;
    for _ in 0..reps.max(1) {
        let record = cycle::Record {
            counters: true,
            ..Default::default()
        };
        cycles = cycle::run_query(
            &p.chip, &setup, q.order, q.mode, params, q.reader, 10_000_000, record,
        )?
        .0
        .cycles;
    }
    let s = t.elapsed().as_secs_f64() / reps.max(1) as f64;
    println!(
        "{name}: {cycles} cycles, {s:.4} s a query, {:.0} clocks/s",
        cycles as f64 / s
    );
    Ok(())
}
