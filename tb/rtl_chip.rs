//! The RTL collision chip end to end: whole queries of `chip_io::queries` in rust-hdl
//! against the golden model, in both orders and modes, and against the checked-in traces
//! that the exported Verilog must reproduce under Verilator (scripts/run-chip.sh).
//!
//! `CCHIP_BLESS=1 cargo test --release --test rtl_chip` rewrites vectors/chip/*.expect
//! from the rust-hdl runs (after a deliberate change of the cycle semantics).

use collision_chip::rtl::chip_io::{queries, run_query, run_query_vcd, ChipQuery, ChipTrace, PreparedQuery, QueryImage, CHIP_CONFIG};
use collision_chip::rtl::e8m15::{chip_top, CollisionChip};
use collision_chip::traversal::{Mode, Traversal};
use std::path::PathBuf;

/// Generous: the longest query takes about 1,000 cycles.
const MAX_CYCLES: u64 = 20_000;

fn big_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new().stack_size(1 << 30).spawn(f).unwrap().join().unwrap()
}

fn chip<const N: usize, const NP1: usize>() -> CollisionChip<N, NP1> {
    chip_top::<N, NP1>(CHIP_CONFIG.dop_rounding.op(), CHIP_CONFIG.tri_rounding)
}

fn query(name: &str) -> ChipQuery {
    queries().into_iter().find(|q| q.name == name).unwrap()
}

fn expect_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("vectors/chip").join(format!("{name}.expect"))
}

/// The trace equals the checked-in one (the Verilog's reference), or is blessed into it.
fn compare_with_expect(name: &str, tr: &ChipTrace) {
    let path = expect_path(name);
    if std::env::var("CCHIP_BLESS").is_ok_and(|v| v == "1") {
        std::fs::write(&path, tr.text()).unwrap();
        return;
    }
    let want = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("{}: {e} (write it with CCHIP_BLESS=1 cargo test --release --test rtl_chip)", path.display()));
    assert_eq!(
        tr.text(),
        want,
        "{name}: the rust-hdl trace differs from {} (if the cycle semantics changed on purpose, bless it and update docs/ARCHITECTURE.md)",
        path.display()
    );
}

/// Runs a query of the set on a fresh chip and checks it against the golden model:
/// the pairs (all pairs: equal; first hit: see `ChipTrace::check`), and in all-pairs mode
/// the tests the hardware pays for. FIFO order tests the pairs in exactly the golden
/// D_CNTR's order, so even the fetch counts agree; LIFO pops entries while earlier tests
/// are in flight, so only the test counts must.
fn run_and_check(name: &str) {
    let q = query(name);
    let p = q.prepare().unwrap();
    let img = p.image.clone();
    let timing = q.timing;
    let tr = big_stack(move || run_query(&mut chip::<8, 9>(), &img, timing, MAX_CYCLES, |_, _| {})).unwrap();
    check(&q, &p, &tr);
}

fn check(q: &ChipQuery, p: &PreparedQuery, tr: &ChipTrace) {
    let name = q.name;
    println!("{name}: {}", tr.text().lines().last().unwrap());
    tr.check(q.mode, &p.golden_all).unwrap_or_else(|e| panic!("{name}: {e}"));
    if q.mode == Mode::All {
        let order = if q.lifo { Traversal::Lifo } else { Traversal::Fifo };
        let g = p.chip.query(&q.pose, Mode::All, order).counters;
        assert_eq!((tr.dop_tests, tr.tri_tests), (g.dop_tests, g.tri_tests), "{name}: tests");
        if !q.lifo {
            assert_eq!((tr.node_fetches, tr.tri_fetches), (g.node_fetches, g.tri_fetches), "{name}: fetches");
        }
    }
    compare_with_expect(name, tr);
}

macro_rules! query_tests {
    ($($name:ident)*) => {
        $(
            #[test]
            fn $name() {
                run_and_check(stringify!($name));
            }
        )*
        /// Every query of the set has its test here (the Verilog runs the whole set).
        #[test]
        fn every_query_is_tested() {
            let mut tested = vec![$(stringify!($name),)* "sphere_lifo_first", "apart_lifo_first"];
            let mut names: Vec<&str> = queries().iter().map(|q| q.name).collect();
            names.sort_unstable();
            tested.sort_unstable();
            assert_eq!(names, tested);
        }
    };
}

query_tests!(sphere_fifo_all sphere_lifo_all sphere_fifo_first bunny_lifo_all bunny_fifo_first);

/// The LIFO first-hit query, traced: target/rtl-vcd/chip_sphere_lifo_first.vcd (open it with
/// scripts/gtkw/chip_e8m15_k6.gtkw) holds the signals the save file shows.
#[test]
fn sphere_lifo_first() {
    let q = query("sphere_lifo_first");
    let p = q.prepare().unwrap();
    let img = p.image.clone();
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/rtl-vcd/chip_sphere_lifo_first.vcd");
    let vcd = path.clone();
    let tr = big_stack(move || run_query_vcd(&mut chip::<8, 9>(), &img, q.timing, MAX_CYCLES, &vcd)).unwrap();
    println!("wrote {}", path.display());
    check(&query("sphere_lifo_first"), &p, &tr);
    assert_eq!(vcd_results(&path), tr.results, "the VCD's results differ from the trace");
}

/// The results a traversal VCD shows: `(cycle, a, b, uncertain)` for every time step
/// (= cycle) with `chip.results.res_valid` high.
fn vcd_results(path: &std::path::Path) -> Vec<(u64, u32, u32, bool)> {
    use vcd::{Command, Value};
    let mut p = vcd::Parser::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let h = p.parse_header().unwrap();
    let id = |n: &str| h.find_var(&["chip", "results", n]).unwrap_or_else(|| panic!("no chip.results.{n}")).code;
    let ids = [id("res_valid"), id("res_a"), id("res_b"), id("res_uncertain")];
    let num = |v: &[Value]| v.iter().fold(0u64, |a, x| a << 1 | (*x == Value::V1) as u64);
    let (mut cur, mut time, mut out) = ([0u64; 4], None, vec![]);
    let mut flush = |t: Option<u64>, cur: &[u64; 4]| {
        if let Some(t) = t {
            if cur[0] == 1 {
                out.push((t, cur[1] as u32, cur[2] as u32, cur[3] == 1));
            }
        }
    };
    for c in p {
        match c.unwrap() {
            Command::Timestamp(t) => {
                // values hold until they change: every step from the last time to t
                if let Some(t0) = time {
                    for s in t0..t {
                        flush(Some(s), &cur);
                    }
                }
                time = Some(t);
            }
            Command::ChangeVector(i, v) => {
                if let Some(k) = ids.iter().position(|&x| x == i) {
                    cur[k] = num(&v);
                }
            }
            _ => {}
        }
    }
    flush(time, &cur);
    out
}

/// Two objects apart: the root pair fails the DOP test and nothing is reported. The same
/// chip then runs the query again: a finished query leaves no state behind.
#[test]
fn apart_lifo_first() {
    let q = query("apart_lifo_first");
    let p = q.prepare().unwrap();
    assert!(p.golden_all.pairs.is_empty());
    let img = p.image.clone();
    let (a, b) = big_stack(move || {
        let mut c = chip::<8, 9>();
        let a = run_query(&mut c, &img, q.timing, MAX_CYCLES, |_, _| {}).unwrap();
        let b = run_query(&mut c, &img, q.timing, MAX_CYCLES, |_, _| {}).unwrap();
        (a, b)
    });
    assert_eq!(a, b);
    assert!(a.results.is_empty());
    assert_eq!((a.dop_tests, a.node_fetches, a.tri_tests), (1, 2, 0));
    a.check(Mode::First, &p.golden_all).unwrap();
    compare_with_expect("apart_lifo_first", &a);
}

/// A queue of 2 entries cannot hold the spheres' traversal: the chip ends the query with
/// `overflow` and whatever it reported is still right (a subset of the golden pairs) —
/// never a silently dropped pair taken for a complete answer.
#[test]
fn a_small_queue_overflows_with_an_error_status() {
    let q = query("sphere_fifo_all");
    let p = q.prepare().unwrap();
    let img: QueryImage = p.image.clone();
    let tr = big_stack(move || run_query(&mut chip::<1, 2>(), &img, q.timing, MAX_CYCLES, |_, _| {})).unwrap();
    println!("{}", tr.text());
    assert!(tr.overflow, "no overflow reported");
    assert_eq!(tr.max_depth, 2);
    assert!(tr.check(Mode::All, &p.golden_all).is_err());
    let (hits, unc) = tr.pairs();
    assert!(hits.iter().chain(&unc).all(|x| p.golden_all.pairs.contains(x) || p.golden_all.uncertain.contains(x)));
    assert!(tr.dop_tests < p.golden_all.counters.dop_tests, "the traversal went on after the overflow");
}

mod random_queries {
    use super::*;
    use collision_chip::mesh::soup;
    use collision_chip::pose::Pose;
    use collision_chip::query::Chip;
    use collision_chip::rtl::chip_io::MemTiming;
    use proptest::prelude::*;

    proptest! {
        // Each case is a whole query in rust-hdl (10-40 s): few cases, every run new ones.
        #![proptest_config(ProptestConfig { cases: 3, failure_persistence: None, .. ProptestConfig::default() })]

        /// Random soups, pose, order, mode and memory timing: the chip answers as the
        /// golden model does, with no overflow, and in all-pairs mode with its test counts.
        #[test]
        fn random_soups_equal_golden(
            na in 3usize..=7, nb in 3usize..=7, sa: u64, sb: u64,
            rot in prop::array::uniform3(0.0f64..360.0), t in prop::array::uniform3(-0.4f64..0.4),
            lifo: bool, first: bool, latency in 1u32..=4, interval in 1u32..=3,
        ) {
            let chip = Chip::new(&soup(na, sa).triangles_f64(), &soup(nb, sb).triangles_f64(), CHIP_CONFIG).unwrap();
            let pose = Pose::new(rot[0], rot[1], rot[2], t[0], t[1], t[2]);
            let mode = if first { Mode::First } else { Mode::All };
            let order = if lifo { Traversal::Lifo } else { Traversal::Fifo };
            let golden = chip.query(&pose, Mode::All, order);
            let img = QueryImage::new(&chip.a, &chip.b, &chip.setup(&pose), lifo, mode).unwrap();
            let timing = MemTiming { latency, interval };
            let tr = big_stack(move || run_query(&mut super::chip::<8, 9>(), &img, timing, MAX_CYCLES, |_, _| {})).unwrap();
            prop_assert!(tr.check(mode, &golden).is_ok(), "{:?}\n{}", tr.check(mode, &golden), tr.text());
            if !first {
                prop_assert_eq!((tr.dop_tests, tr.tri_tests), (golden.counters.dop_tests, golden.counters.tri_tests));
            }
        }
    }
}
