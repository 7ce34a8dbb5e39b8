//! How the reports measure: the cycle model's and the golden model's counting work on every
//! core, the software's time one query at a time on an otherwise idle process.

use std::hint::black_box;

/// `f` over `items` on every core, results in the items' order (the output of a parallel
/// run is the serial run's).
pub fn parallel_map<T: Sync, R: Send>(items: &[T], f: impl Fn(usize, &T) -> R + Sync) -> Vec<R> {
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(items.len().max(1));
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
        workers
            .into_iter()
            .flat_map(|w| w.join().expect("a worker thread panicked"))
            .collect()
    });
    out.sort_by_key(|(i, _)| *i);
    out.into_iter().map(|(_, r)| r).collect()
}

/// Mean seconds per call of `f` over `items`, one call at a time, repeating the whole set
/// until `min_seconds` have passed (a query of a few microseconds is timed over many calls).
/// The clock is this thread's CPU time: on a machine shared with other processes, the time
/// the calls ran, not the time they waited for a core.
pub fn mean_seconds<T, R>(items: &[T], min_seconds: f64, mut f: impl FnMut(&T) -> R) -> f64 {
    let (t0, mut calls) = (thread_seconds(), 0usize);
    while calls == 0 || thread_seconds() - t0 < min_seconds {
        for x in items {
            black_box(f(x));
            calls += 1;
        }
    }
    (thread_seconds() - t0) / calls as f64
}

/// [`mean_seconds`] of each of `fs` over `items`, their rounds interleaved (a round of each
/// in turn, `rounds` times, each round `min_seconds / rounds` long), the fastest round of each
/// kept: on a noisy machine the sides of a ratio meet the same noise, and the best round
/// is the least disturbed.
pub fn interleaved_best<T, R, const N: usize>(
    items: &[T],
    min_seconds: f64,
    rounds: usize,
    fs: [&dyn Fn(&T) -> R; N],
) -> [f64; N] {
    let mut best = [f64::INFINITY; N];
    for _ in 0..rounds.max(1) {
        for (b, f) in best.iter_mut().zip(&fs) {
            *b = b.min(mean_seconds(items, min_seconds / rounds.max(1) as f64, f));
        }
    }
    best
}

/// How many times a reported wall-clock time runs its work (one pose's software query, the
/// host's setup, its settling): the first run pays for cold caches and first allocations,
/// the fastest is kept.
pub const TIMING_RUNS: usize = 3;

/// `f`'s result and its wall-clock time in microseconds, the fastest of [`TIMING_RUNS`] runs
/// (warm: other processes and the first run's cold start only ever add time).
pub fn fastest_us<R>(mut f: impl FnMut() -> R) -> (R, f64) {
    let (mut out, mut best) = (None, f64::INFINITY);
    for _ in 0..TIMING_RUNS {
        let t0 = std::time::Instant::now();
        let r = black_box(f());
        best = best.min(t0.elapsed().as_secs_f64() * 1e6);
        out = Some(r);
    }
    (out.expect("TIMING_RUNS > 0"), best)
}

/// This thread's CPU time in seconds.
#[cfg(unix)]
pub fn thread_seconds() -> f64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid timespec for clock_gettime to write.
    let r = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    assert_eq!(r, 0, "clock_gettime(CLOCK_THREAD_CPUTIME_ID) failed");
    ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
}

/// Wall-clock seconds since the first call (no thread CPU clock here).
#[cfg(not(unix))]
pub fn thread_seconds() -> f64 {
    static T0: std::sync::OnceLock<std::time::Instant> = std::sync::OnceLock::new();
    T0.get_or_init(std::time::Instant::now)
        .elapsed()
        .as_secs_f64()
}

/// The environment variables the library reads; `cchip` checks them before any work and
/// exits 2 on a bad value.
pub const MAX_MEMORY_MB: &str = "CCHIP_MAX_MEMORY_MB";
/// `1`: the fast paths' check mode (`golden::enclosure::checking`); `0` or unset: off.
pub const CHECK_FAST: &str = "CCHIP_CHECK_FAST";

/// Every environment variable of the library read once: an error names a bad value.
pub fn check_environment() -> Result<(), String> {
    max_memory()?;
    env_flag(CHECK_FAST)?;
    Ok(())
}

/// Whether the switch `name` is on: `1` on, `0` or unset off, anything else an error (a
/// misspelt value is not quietly off).
pub fn env_flag(name: &str) -> Result<bool, String> {
    match std::env::var_os(name) {
        None => Ok(false),
        Some(v) if v == "1" => Ok(true),
        Some(v) if v == "0" => Ok(false),
        Some(v) => Err(format!("{name}={v:?}: give 1 (on) or 0 (off), or unset it")),
    }
}

/// `CCHIP_MAX_MEMORY_MB` in bytes, if it is set: a whole number of MiB, within 2^64 bytes.
fn max_memory() -> Result<Option<u64>, String> {
    let Some(v) = std::env::var_os(MAX_MEMORY_MB) else {
        return Ok(None);
    };
    let bad = |why: &str| {
        format!("{MAX_MEMORY_MB}={v:?} {why}: give a whole number of MB (e.g. {MAX_MEMORY_MB}=2048), or unset it to use the memory this machine has available")
    };
    let mb: u64 = v
        .to_str()
        .and_then(|s| s.trim().parse().ok())
        .ok_or_else(|| bad("is not a whole number of MB"))?;
    mb.checked_mul(1 << 20)
        .map(Some)
        .ok_or_else(|| bad("is more than 2^64 bytes"))
}

/// Bytes this process may still allocate: the smaller of the kernel's `MemAvailable` and the
/// cgroup's `memory.max` (a container's limit); `CCHIP_MAX_MEMORY_MB` replaces both (an
/// error if it is not a number of MB). `None` where none of them can be read (then nothing
/// is refused).
pub fn memory_available() -> Result<Option<u64>, String> {
    if let Some(bytes) = max_memory()? {
        return Ok(Some(bytes));
    }
    let read = |p: &str| std::fs::read_to_string(p).ok();
    let kernel = read("/proc/meminfo").and_then(|m| {
        let line = m.lines().find(|l| l.starts_with("MemAvailable:"))?;
        line.split_whitespace()
            .nth(1)?
            .parse::<u64>()
            .ok()
            .map(|kb| kb << 10)
    });
    let cgroup = read("/sys/fs/cgroup/memory.max").and_then(|s| s.trim().parse::<u64>().ok());
    Ok([kernel, cgroup].into_iter().flatten().min())
}
