//! How the reports measure: the cycle model's and the golden model's counting work on every
//! core, the software's time one query at a time on an otherwise idle process.

use std::hint::black_box;
use std::time::Instant;

/// `f` over `items` on every core, results in the items' order (the output of a parallel
/// run is the serial run's).
pub fn parallel_map<T: Sync, R: Send>(items: &[T], f: impl Fn(usize, &T) -> R + Sync) -> Vec<R> {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get()).min(items.len().max(1));
    let next = std::sync::atomic::AtomicUsize::new(0);
    let mut out: Vec<(usize, R)> = std::thread::scope(|s| {
        let workers: Vec<_> = (0..threads)
            .map(|_| {
                s.spawn(|| {
                    let mut mine = vec![];
                    loop {
                        let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        let Some(item) = items.get(i) else { break };
                        mine.push((i, f(i, item)));
                    }
                    mine
                })
            })
            .collect();
        workers.into_iter().flat_map(|w| w.join().expect("a worker thread panicked")).collect()
    });
    out.sort_by_key(|(i, _)| *i);
    out.into_iter().map(|(_, r)| r).collect()
}

/// Mean seconds per call of `f` over `items`, one call at a time, repeating the whole set
/// until `min_seconds` have passed (a query of a few microseconds is timed over many calls).
pub fn mean_seconds<T, R>(items: &[T], min_seconds: f64, mut f: impl FnMut(&T) -> R) -> f64 {
    let (t0, mut calls) = (Instant::now(), 0usize);
    while calls == 0 || t0.elapsed().as_secs_f64() < min_seconds {
        for x in items {
            black_box(f(x));
            calls += 1;
        }
    }
    t0.elapsed().as_secs_f64() / calls as f64
}
