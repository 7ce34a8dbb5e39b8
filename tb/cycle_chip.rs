//! The fast cycle model of the chip (`src/cycle`): it reproduces every checked-in chip
//! trace (vectors/chip/*.expect: each also agreed by the exported Verilog under
//! Verilator, six by rust-hdl in lockstep, tb/rtl_chip.rs), answers as the golden model does in
//! configurations beyond the RTL (k, format, latencies, spacing, credit, requests
//! outstanding, prefetch, memory timing, a slow host), skips idle stretches without changing a
//! trace, reports an overflowing queue, and prefetches as derived by hand.
//!
//! `CCHIP_BLESS=1 cargo test --release --test cycle_chip` writes the cycle model's traces
//! of every query to target/chip-expect/ for `scripts/run-chip.sh --bless`, which copies
//! each into vectors/chip/ only if Verilator's trace equals it. Every run writes there the
//! memory requests of each query (`<query>.requests`), which run-chip.sh compares with the
//! exported Verilog's.

use collision_chip::chip::config::{ChipConfig, DopRounding, Formats};
use collision_chip::chip::config::{DopBits, MemLayout};
use collision_chip::chip::layout::Dst;
use collision_chip::chip::memory::{Ddr, MemTiming, Memory};
use collision_chip::chip::params::Params;
use collision_chip::chip::probes::DATE05;
use collision_chip::chip::reg::{Mode, Order};
use collision_chip::chip::rtl::{ChipKind, Depth};
use collision_chip::chip::wscg03::Architecture;
use collision_chip::cycle::chip::Chip as CycleChip;
use collision_chip::cycle::drive::{run_query, ChipTrace, Drive, Reader};
use collision_chip::cycle::{self, ProbeObserver};
use collision_chip::format::{Format, Rounding};
use collision_chip::harness::chip_io::{queries, ChipQuery, PreparedQuery};
use collision_chip::mesh::soup;
use collision_chip::pose::Pose;
use collision_chip::query::Chip;
use collision_chip::traversal::Traversal;

/// The small RTL chip's configuration (k = 6, e8m15).
const CHIP_CONFIG: ChipConfig = ChipKind::K6E8m15.config();

fn order(lifo: bool) -> Order {
    if lifo {
        Order::Lifo
    } else {
        Order::Fifo
    }
}
use proptest::prelude::*;
use std::path::PathBuf;

const MAX_CYCLES: u64 = 5_000_000;

/// A cycle-model run that counts where the clocks went.
fn counted() -> cycle::Record<'static> {
    cycle::Record {
        counters: true,
        ..Default::default()
    }
}

fn vectors() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("vectors/chip")
}

/// The memory requests a query's chip makes that the memory accepts, as the testbench
/// prints them with `+requests` (`request <cycle> <word address>`), clock by clock.
fn requests(p: &PreparedQuery, q: &ChipQuery) -> (ChipTrace, String) {
    let (valid, ready, addr) = (
        probe("memory", "req_valid"),
        probe("memory", "req_ready"),
        probe("memory", "req_addr"),
    );
    let mut text = String::new();
    let mut obs = |t: u64, v: &[u64]| {
        if t > 0 && v[valid] == 1 && v[ready] == 1 {
            text += &format!("request {t} {}\n", v[addr]);
        }
        Ok(())
    };
    let rec = cycle::Record {
        probes: Some(&mut obs),
        ..Default::default()
    };
    let (tr, _) = cycle::run_query(
        &p.chip,
        &p.chip.setup(&q.pose),
        q.order,
        q.mode,
        q.params(),
        q.reader,
        MAX_CYCLES,
        rec,
    )
    .unwrap();
    (tr, text)
}

/// The queries of DATE'05's chips (WSCG'03's: tb/wscg03.rs).
fn date05_queries() -> Vec<ChipQuery> {
    let date05 = |q: &ChipQuery| q.architecture == Architecture::Date05;
    queries().into_iter().filter(date05).collect()
}

/// Every query of the set, small and large: the cycle model's trace is the checked-in one
/// (with idle stretches skipped, and clock by clock while its memory requests are written
/// for run-chip.sh).
#[test]
fn every_checked_in_trace() {
    let bless = std::env::var("CCHIP_BLESS").is_ok_and(|v| v == "1");
    let out = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/chip-expect");
    std::fs::create_dir_all(&out).unwrap();
    for q in date05_queries() {
        let p = q.prepare().unwrap();
        let params = q.params();
        let (tr, stats) = cycle::run_query(
            &p.chip,
            &p.chip.setup(&q.pose),
            q.order,
            q.mode,
            params,
            q.reader,
            MAX_CYCLES,
            counted(),
        )
        .unwrap();
        let stats = stats.expect("counted");
        println!(
            "{}: {} ({stats:?})",
            q.name,
            tr.text().lines().last().unwrap()
        );
        tr.check(q.mode, &p.golden_all)
            .unwrap_or_else(|e| panic!("{}: {e}", q.name));
        let (clocked, reqs) = requests(&p, &q);
        assert_eq!(clocked, tr, "{}: clock by clock", q.name);
        assert_eq!(
            reqs.lines().count() as u64,
            tr.node_fetches + tr.tri_fetches,
            "{}: a request per word fetched",
            q.name
        );
        if bless {
            std::fs::write(out.join(format!("{}.expect", q.name)), tr.text()).unwrap();
        } else {
            let path = vectors().join(format!("{}.expect", q.name));
            let want = std::fs::read_to_string(&path)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            assert_eq!(
                tr.text(),
                want,
                "{}: the cycle model's trace differs from {}",
                q.name,
                path.display()
            );
        }
        // with the trace it belongs to: the checked-in one, or the one being blessed
        std::fs::write(out.join(format!("{}.requests", q.name)), reqs).unwrap();
    }
}

/// Every expected trace in vectors/chip/ belongs to a query of the set (no stale trace).
#[test]
fn no_stale_expected_trace() {
    let names: Vec<String> = queries()
        .iter()
        .map(|q| format!("{}.expect", q.name))
        .collect();
    for e in std::fs::read_dir(vectors()).unwrap() {
        let f = e.unwrap().file_name().into_string().unwrap();
        assert!(
            !f.ends_with(".expect") || names.contains(&f),
            "vectors/chip/{f}: no query of chip_io::queries() has it: delete it"
        );
    }
}

/// The large queries do what they are in the set for: too long for rust-hdl (more than
/// 500 s at its speed on their chip: 10^4 cycles and more on the k = 6 chip, 2 * 10^3 on
/// the k = 24 one), results that back-pressure the traversal, and sure hits mixed with
/// uncertain pairs.
#[test]
fn large_queries_cover_what_they_claim() {
    let large: Vec<_> = date05_queries().into_iter().filter(|q| q.large).collect();
    assert!(large.len() >= 4);
    let (mut back_pressure, mut mixed, mut orders_modes) =
        (false, false, std::collections::BTreeSet::new());
    for q in &large {
        let p = q.prepare().unwrap();
        let params = q.params();
        let (tr, st) = cycle::run_query(
            &p.chip,
            &p.chip.setup(&q.pose),
            q.order,
            q.mode,
            params,
            q.reader,
            MAX_CYCLES,
            counted(),
        )
        .unwrap();
        let st = st.expect("counted");
        let rust_hdl_seconds = tr.cycles as f64 / q.chip.rtl_clocks_per_second();
        assert!(
            rust_hdl_seconds > 500.0 && tr.cycles <= 200_000,
            "{}: {} cycles",
            q.name,
            tr.cycles
        );
        back_pressure |= st.back_pressure > 0 && st.result_wait > 0;
        let (hits, unc) = tr.pairs();
        mixed |= !hits.is_empty() && !unc.is_empty();
        orders_modes.insert((q.order == Order::Lifo, q.mode == Mode::First));
    }
    assert!(
        back_pressure,
        "no large query stalls TRI_UNIT on a slow host"
    );
    assert!(mixed, "no large query mixes sure hits with uncertain pairs");
    assert_eq!(orders_modes.len(), 4, "both orders in both modes");
}

/// A configuration to run: k, the DOP and T.CHECK formats (binary32 or e8m15 each), DOP
/// rounding, the triangle cache's lines, the memory layout, node records held and (`records`)
/// the stored DOP precision (0: full).
fn config(
    k: usize,
    dop_binary32: bool,
    tri_binary32: bool,
    outward: bool,
    (tri_cache, tri_cache_b): (u32, u32),
    (records, node_cache, dop_bits): (bool, u32, u32),
) -> ChipConfig {
    let f = |b32| {
        if b32 {
            Format::BINARY32
        } else {
            Format::REDUCED
        }
    };
    ChipConfig {
        k,
        format: Formats {
            dop: f(dop_binary32),
            tri: f(tri_binary32),
        },
        dop_rounding: if outward {
            DopRounding::Outward
        } else {
            DopRounding::NearestEven
        },
        tri_rounding: Rounding::NearestEven,
        tri_cache,
        tri_cache_b,
        layout: if records {
            MemLayout::Records
        } else {
            MemLayout::Words
        },
        node_cache,
        dop_bits: match dop_bits {
            b if b > 0 && records => DopBits::Bits(b),
            _ => DopBits::Full,
        },
    }
}

/// The ideal memory, or DDR SDRAM of random geometry and costs (small pages and buses too,
/// so that words span bursts and banks conflict).
fn memory() -> impl Strategy<Value = Memory> {
    prop_oneof![
        (1u32..=6, 1u32..=3, prop::option::of(16u32..=1024)).prop_map(
            |(latency, interval, bus_bits)| Memory::Ideal(MemTiming {
                latency,
                interval,
                bus_bits
            })
        ),
        (
            (1u32..=8, 6u32..=12, 5u32..=8, 0u32..=3),
            (600u32..=4000, 0u32..=5000, 0u32..=15000)
        )
            .prop_map(|((banks, page, bus, burst), (beat_ps, hit, miss))| {
                let burst = 1 << burst;
                Memory::Ddr(Ddr {
                    banks,
                    page_bytes: 1 << page,
                    bus_bits: 1 << bus,
                    burst,
                    beat_ps,
                    hit_ps: burst * beat_ps + hit,
                    miss_ps: burst * beat_ps + hit + miss,
                })
            }),
    ]
}

fn params() -> impl Strategy<Value = Params> {
    (
        (
            10u32..=14,
            1u32..=20,
            3u32..=140,
            1u32..=64,
            prop_oneof![3 => Just(1u32), 1 => (1u32..=16).prop_map(|h| 2 * h)],
            any::<bool>(),
        ),
        (
            1u32..=2,
            1u32..=32,
            1u32..=16,
            prop_oneof![Just(0u32), 1u32..=12],
            memory(),
            prop_oneof![3 => Just(1u32), 1 => prop::sample::select(vec![2u32, 3, 6])],
            500u64..=10_000,
            any::<bool>(),
        ),
    )
        .prop_map(
            |((q, dl, tl, tf, ti, fpga), (sp, cr, os, pf, memory, di, clock_ps, tpf))| {
                // FPGA depth folds TRI_UNIT; its DOP unit's latency is its lanes'
                let depth = if fpga && ti > 1 {
                    Depth::Fpga
                } else {
                    Depth::Asic
                };
                Params {
                    queue_entries: 1 << q,
                    // a folded DOP unit's latency is its own (k = 6: a pair every 2, 3 or 6 clocks)
                    dop_latency: if di == 1 && depth == Depth::Asic {
                        dl
                    } else {
                        Params::RTL.dop_latency
                    },
                    dop_interval: di,
                    depth,
                    // a folded TRI_UNIT's latency is its schedule's
                    tri_latency: if ti == 1 { tl } else { Params::RTL.tri_latency },
                    tri_fifo: tf,
                    tri_interval: ti,
                    issue_spacing: sp,
                    credit: cr,
                    outstanding: os,
                    prefetch: pf,
                    tri_prefetch: tpf,
                    memory,
                    clock_ps,
                }
            },
        )
}

/// Sphere against torus (200 triangles each) on `cfg`, and a pose where they overlap: the
/// by-hand tests' query.
fn sphere_torus(cfg: ChipConfig) -> (Chip, Pose) {
    let tris = |m: &str| collision_chip::mesh::builtin(m).unwrap().triangles_f64();
    let chip = Chip::new(&tris("sphere:200"), &tris("torus:200"), cfg).unwrap();
    (chip, Pose::new(10.0, 20.0, 30.0, 0.5, 0.0, 0.0))
}

/// The index of probe `scope`.`name` in a clock's values.
fn probe(scope: &str, name: &str) -> usize {
    DATE05.index(scope, name).expect("a probe")
}

/// A LIFO all-pairs query at `p` on the cycle model, clock by clock, `obs` seeing every
/// clock's probes.
fn lifo_probed<'p>(
    chip: &Chip,
    pose: &Pose,
    p: Params,
    obs: &'p mut ProbeObserver<'p>,
) -> ChipTrace {
    let rec = cycle::Record {
        probes: Some(obs),
        ..Default::default()
    };
    cycle::run_query(
        chip,
        &chip.setup(pose),
        Order::Lifo,
        Mode::All,
        p,
        Reader::default(),
        MAX_CYCLES,
        rec,
    )
    .unwrap()
    .0
}

/// Runs a query on the cycle model, with idle stretches skipped or (`probe`) clock by clock.
fn run(
    chip: &Chip,
    pose: &Pose,
    lifo: bool,
    mode: Mode,
    p: Params,
    reader: Reader,
    probe: bool,
) -> Result<ChipTrace, String> {
    if !probe {
        return cycle::run_query(
            chip,
            &chip.setup(pose),
            order(lifo),
            mode,
            p,
            reader,
            MAX_CYCLES,
            counted(),
        )
        .map(|r| r.0);
    }
    let setup = chip.setup(pose);
    let mut c = CycleChip::new(&chip.cfg, p, &chip.a, &chip.b, &setup, true)?;
    let d = Drive {
        memory: p.memory_clocks()?,
        word_bits: chip.layout.word_bits(),
        reader,
        words: chip.image_span(&p.memory),
        max_cycles: MAX_CYCLES,
    };
    run_query(
        &mut c,
        &chip.control_writes(order(lifo), mode, &p),
        &d,
        true,
        |_, p| {
            assert_eq!(p.map(|v| v.len()), Some(DATE05.signals.len()));
            Ok(())
        },
        false,
    )
    .map_err(|e| e.0)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, .. ProptestConfig::default() })]

    /// Any k, formats (the DOP's apart from T.CHECK's), rounding, triangle caches (A's, B's) and
    /// microarchitecture: the cycle model's answer is the golden model's (all pairs: the
    /// same sure hits, uncertain pairs and test counts; FIFO order even the fetch counts,
    /// each level's triangle cache on its own leaf-pair order), the same with idle
    /// stretches skipped as clock by clock, and every running clock is booked to exactly
    /// one cause. A cache with a line for each of A's triangles fetches each at most once.
    /// Either memory layout, 1 to 16 node records held, records in full or at 1 (LIFO), 4
    /// (FIFO) or 8 bits a plane (their decode stage on the DOP unit's path), triangle words
    /// asked for at the leaf register or prefetched as leaf pairs enter the leaf FIFO.
    #[test]
    fn any_configuration_answers_as_golden(
        k in prop::sample::select(vec![6usize, 14, 18, 24, 26]), dop_b32: bool, tri_b32: bool, outward: bool,
        tri_cache in prop::sample::select(vec![1u32, 1, 4, 32, 128]),
        tri_cache_b in prop::sample::select(vec![1u32, 1, 4, 128]),
        na in 4usize..=120, nb in 4usize..=120, sa: u64, sb: u64,
        rot in prop::array::uniform3(0.0f64..360.0), t in prop::array::uniform3(-0.4f64..0.4),
        lifo: bool, first: bool, p in params(), period in 1u32..=12,
        layout in (any::<bool>(), prop::sample::select(vec![1u32, 1, 3, 16]), prop::sample::select(vec![0u32, 0, 1, 8])),
    ) {
        // 1-bit codes overlap nearly everywhere: breadth first, their pairs outgrow the queue
        // (the chip flags it; not this test's subject), so FIFO runs take 4 bits instead
        let layout = (layout.0, layout.1, if lifo || layout.2 != 1 { layout.2 } else { 4 });
        let chip = Chip::new(&soup(na, sa).triangles_f64(), &soup(nb, sb).triangles_f64(), config(k, dop_b32, tri_b32, outward, (tri_cache, tri_cache_b), layout)).unwrap();
        let pose = Pose::new(rot[0], rot[1], rot[2], t[0], t[1], t[2]);
        let mode = if first { Mode::First } else { Mode::All };
        // a DOP interval that does not divide this k: 2 (every supported k is even)
        let p = Params { dop_interval: if k % p.dop_interval as usize == 0 { p.dop_interval } else { 2 }, ..p };
        let golden = chip.query(&pose, Mode::All, if lifo { Traversal::Lifo } else { Traversal::Fifo });
        let reader = Reader { period };
        let (tr, st) = cycle::run_query(&chip, &chip.setup(&pose), order(lifo), mode, p, reader, MAX_CYCLES, counted()).unwrap();
        let st = st.expect("counted");
        prop_assert!(!tr.overflow, "a queue of {} entries overflowed", p.queue_entries);
        prop_assert!(tr.check(mode, &golden).is_ok(), "{:?}\n{}", tr.check(mode, &golden), tr.text());
        if !first {
            let g = golden.counters;
            prop_assert_eq!((tr.dop_tests, tr.tri_tests), (g.dop_tests, g.tri_tests));
            if !lifo {
                prop_assert_eq!((tr.node_fetches, tr.tri_fetches), (g.node_fetches, g.tri_fetches));
                prop_assert_eq!(st.tri_fetches_a, g.tri_fetches_a);
            }
        }
        if tri_cache as usize >= na {
            prop_assert!(st.tri_fetches_a <= na as u64, "{} of A's {na} triangles fetched through {tri_cache} lines", st.tri_fetches_a);
        }
        let booked = st.issue + st.stall_memory + st.stall_spacing + st.stall_credit + st.stall_refill
            + st.stall_empty_queue + st.drain + st.halted;
        prop_assert_eq!((st.cycles, booked, st.issue), (tr.cycles, tr.cycles, tr.dop_tests));
        let clocked = run(&chip, &pose, lifo, mode, p, reader, true).unwrap();
        prop_assert_eq!(clocked, tr);
    }
}

/// The folded DOP unit's rhythm by hand: issues a multiple of ii clocks apart (some exactly
/// ii), the first result 15 + ii - 1 clocks after the first issue (DATE'05 §4.1's lane
/// pipeline "of 15 stages"; the folded unit's last pass enters its lanes ii - 1 clocks after
/// the first: 16, 17, 20); the answers golden's, clock by clock equal to the skipping run.
#[test]
fn folded_dop_unit_takes_a_pair_every_interval() {
    let (chip, pose) = sphere_torus(CHIP_CONFIG);
    let golden = chip.query(&pose, Mode::All, Traversal::Lifo);
    let (issue, valid) = (probe("d_cntr", "issue"), probe("dop", "valid_out"));
    for (ii, latency) in [(2u32, 16u64), (3, 17), (6, 20)] {
        // one request outstanding would space issues by the memory; prefetch keeps words ready
        let p = Params {
            dop_interval: ii,
            prefetch: 8,
            outstanding: 8,
            ..Params::RTL
        };
        let (mut issues, mut first_out) = (vec![], None);
        let mut obs = |t: u64, v: &[u64]| {
            if v[issue] == 1 {
                issues.push(t);
            }
            if v[valid] == 1 && first_out.is_none() {
                first_out = Some(t);
            }
            Ok(())
        };
        let clocked = lifo_probed(&chip, &pose, p, &mut obs);
        clocked.check(Mode::All, &golden).unwrap();
        assert_eq!(issues.len() as u64, clocked.dop_tests, "ii {ii}");
        let gaps: Vec<u64> = issues.windows(2).map(|w| w[1] - w[0]).collect();
        let odd = issues.windows(2).find(|w| (w[1] - w[0]) % ii as u64 != 0);
        assert!(
            odd.is_none(),
            "ii {ii}: pairs issued in cycles {odd:?}, not a multiple of {ii} apart"
        );
        assert!(
            gaps.contains(&(ii as u64)),
            "ii {ii}: no two pairs back to back"
        );
        assert_eq!(
            first_out,
            Some(issues[0] + latency),
            "ii {ii}: the first result {latency} clocks after the first pair"
        );
        let skipped = cycle::run_query(
            &chip,
            &chip.setup(&pose),
            Order::Lifo,
            Mode::All,
            p,
            Reader::default(),
            MAX_CYCLES,
            counted(),
        )
        .unwrap()
        .0;
        assert_eq!(skipped, clocked, "ii {ii}");
    }
}

/// Stored DOP precision's decode stage by hand: a DOP verdict comes out 15 clocks after its
/// pair (DATE'05's lane pipeline) from full records and 19 from 8-bit codes: the decode
/// stage's input registers, then the 3 stages of the DOP format's adder (`FpAdd`) that
/// subtracts `q 2^e` from the parent's distance; the answers stay golden's.
#[test]
fn the_decode_stage_delays_each_dop_verdict_by_an_adder() {
    let (issue, valid) = (probe("d_cntr", "issue"), probe("dop", "valid_out"));
    for (dop_bits, latency) in [(DopBits::Full, 15u64), (DopBits::Bits(8), 19)] {
        let cfg = ChipConfig {
            layout: MemLayout::Records,
            dop_bits,
            ..CHIP_CONFIG
        };
        let (chip, pose) = sphere_torus(cfg);
        let (mut first_issue, mut first_out) = (None, None);
        let mut obs = |t: u64, v: &[u64]| {
            if v[issue] == 1 {
                first_issue.get_or_insert(t);
            }
            if v[valid] == 1 {
                first_out.get_or_insert(t);
            }
            Ok(())
        };
        let tr = lifo_probed(&chip, &pose, Params::RTL, &mut obs);
        tr.check(Mode::All, &chip.query(&pose, Mode::All, Traversal::Lifo))
            .unwrap();
        assert_eq!(first_out, first_issue.map(|t| t + latency), "{dop_bits}");
    }
}

/// Triangle words prefetched by hand: without `tri_prefetch` every triangle-word request
/// goes out while its leaf pair is in the leaf register (the RTL's rule); with it some go
/// out before (as leaf pairs enter the leaf FIFO), and the fetches and answers stay
/// golden's.
#[test]
fn prefetched_triangle_words_are_asked_for_before_the_leaf_register() {
    let (chip, pose) = sphere_torus(CHIP_CONFIG);
    let golden = chip.query(&pose, Mode::All, Traversal::Lifo);
    let (valid, ready, dst) = (
        probe("memory", "req_valid"),
        probe("memory", "req_ready"),
        probe("memory", "req_dst"),
    );
    let leaf = probe("leaves", "leaf_valid");
    for tri_prefetch in [false, true] {
        let p = Params {
            outstanding: 4,
            prefetch: 3,
            tri_prefetch,
            ..Params::RTL
        };
        let (mut early, mut asked) = (0, 0);
        let mut obs = |_: u64, v: &[u64]| {
            if v[valid] == 1 && v[ready] == 1 && v[dst] >= Dst::TriA as u64 {
                asked += 1;
                early += (v[leaf] == 0) as u64;
            }
            Ok(())
        };
        let tr = lifo_probed(&chip, &pose, p, &mut obs);
        tr.check(Mode::All, &golden).unwrap();
        assert_eq!(tr.tri_fetches, asked);
        assert!(asked > 10, "{asked} triangle words");
        assert_eq!(
            early > 0,
            tri_prefetch,
            "{early} of {asked} asked for early"
        );
    }
}

/// The RTL configuration's parameters are the RTL's own constants, and these values,
/// literal: DATE'05 §4.1's DOP pipeline "of 15 stages"; TRI_UNIT §4.2's T.CHECK "pipeline
/// with 52 clock cycles delay" plus the pair register before it and the result FIFO's write
/// after it, 54; the rest the RTL's choices (docs/explanation/architecture.md): a queue of 2^10 entries,
/// a result FIFO of 256, issues two clocks apart, a credit of 16, one request outstanding,
/// no prefetch, a memory word one clock after its request.
#[test]
fn rtl_point_is_the_rtl() {
    use collision_chip::chip::rtl::{CREDIT, DOP_LATENCY};
    use collision_chip::rtl::{b32, e8m15::TriUnit};
    let p = Params::RTL;
    assert_eq!(
        (p.dop_latency, p.tri_latency, p.tri_fifo, p.credit),
        (
            DOP_LATENCY as u32,
            TriUnit::LATENCY as u32,
            TriUnit::FIFO_DEPTH as u32,
            CREDIT as u32
        )
    );
    assert_eq!(
        (b32::TriUnit::LATENCY, b32::TriUnit::FIFO_DEPTH),
        (TriUnit::LATENCY, TriUnit::FIFO_DEPTH)
    );
    let literal = Params {
        queue_entries: 1024,
        dop_latency: 15,
        dop_interval: 1,
        tri_latency: 52 + 2,
        tri_fifo: 256,
        tri_interval: 1,
        depth: Depth::Asic,
        issue_spacing: 2,
        credit: 16,
        outstanding: 1,
        prefetch: 0,
        tri_prefetch: false,
        memory: Memory::Ideal(MemTiming {
            latency: 1,
            interval: 1,
            bus_bits: None,
        }),
        // 800 MHz, the `rtl` preset's assumed clock
        clock_ps: 1250,
    };
    assert_eq!(p, literal);
}

/// A queue too small for the traversal: the query ends with `overflow`, having reported
/// only golden pairs, and its trace does not pass for an answer.
#[test]
fn a_small_queue_overflows() {
    let q = queries()
        .into_iter()
        .find(|q| q.name == "sphere_fifo_all")
        .unwrap();
    let p = q.prepare().unwrap();
    for order in [Order::Fifo, Order::Lifo] {
        let params = Params {
            queue_entries: 3,
            ..Params::RTL
        };
        let (tr, st) = cycle::run_query(
            &p.chip,
            &p.chip.setup(&q.pose),
            order,
            Mode::All,
            params,
            Reader::default(),
            MAX_CYCLES,
            counted(),
        )
        .unwrap();
        let st = st.expect("counted");
        assert!(tr.overflow && tr.max_depth == 3, "{}", tr.text());
        assert!(tr.check(Mode::All, &p.golden_all).is_err());
        let (hits, unc) = tr.pairs();
        assert!(hits
            .iter()
            .chain(&unc)
            .all(|x| p.golden_all.pairs.contains(x) || p.golden_all.uncertain.contains(x)));
        assert!(st.halted > 0 && tr.dop_tests < p.golden_all.counters.dop_tests);
    }
}

/// Bad parameters are refused before anything runs, naming the parameter.
#[test]
fn bad_parameters_are_refused() {
    let chip = Chip::new(
        &soup(4, 1).triangles_f64(),
        &soup(4, 2).triangles_f64(),
        CHIP_CONFIG,
    )
    .unwrap();
    let setup = chip.setup(&Pose::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0));
    for (p, what) in [
        (
            Params {
                queue_entries: 0,
                ..Params::RTL
            },
            "queue_entries",
        ),
        (
            Params {
                issue_spacing: 3,
                ..Params::RTL
            },
            "issue_spacing",
        ),
        (
            Params {
                outstanding: 65,
                ..Params::RTL
            },
            "outstanding",
        ),
        (
            Params {
                prefetch: 257,
                ..Params::RTL
            },
            "prefetch",
        ),
        (
            Params {
                tri_interval: 5,
                ..Params::RTL
            },
            "tri_interval",
        ),
        (
            Params {
                dop_interval: 0,
                ..Params::RTL
            },
            "dop_interval must be at least 1",
        ),
        (
            Params {
                dop_interval: 4,
                ..Params::RTL
            },
            "dop_interval 4 does not divide k = 6",
        ),
        (
            Params {
                dop_interval: 2,
                dop_latency: 9,
                ..Params::RTL
            },
            "dop_latency 9 is the unfolded",
        ),
        (
            Params {
                memory: MemTiming {
                    latency: 0,
                    ..Default::default()
                }
                .into(),
                ..Params::RTL
            },
            "latency",
        ),
        (
            Params {
                memory: Memory::Ddr(Ddr {
                    burst: 9,
                    ..Ddr::WSCG03
                }),
                ..Params::RTL
            },
            "burst x beat_ns <= hit_ns <= miss_ns",
        ),
    ] {
        let e = CycleChip::new(&CHIP_CONFIG, p, &chip.a, &chip.b, &setup, true)
            .err()
            .expect("refused");
        assert!(e.contains(what), "{e}");
    }
}

/// Prefetch by hand. A = B = two triangles (root 0, leaves 1 and 2), at the identity: every
/// DOP overlaps. Ideal memory of latency 3 (a request accepted at edge t answered in cycle
/// t + 3), DOP latency 2, issues one clock apart, 4 requests outstanding, 2 pairs prefetched,
/// LIFO. Start at 0, the root pushed at edge 1, popped in cycle 2; its words A0, B0 asked in
/// cycles 3, 4, arrive at edges 6, 7; the root issues in cycle 8, its result in cycle 10 pushes
/// both child entries at once: E1 = (1,1), (1,2), E2 = (2,2), (2,1) (the DOP-sharing order,
/// `golden::d_cntr::children`), E1 on top. E1 is popped in cycle 11, E2 in 12 (the buffer
/// holds 4 pairs) while E1's first word goes out: A1, B1, B2, A2, B1 in cycles 12..=16 (the
/// pair (2,2) reuses B2), one a clock, answered at edges 15..=19; each pair issues the clock
/// after its last word: cycles 17, 18, 19, 20. Without prefetch the words go one pair at a
/// time (the RTL's rule: only the current pair's words).
#[test]
fn prefetch_keeps_requests_back_to_back_by_hand() {
    use collision_chip::dop::Node;
    let p3 = |x: f64, y: f64| nalgebra::Point3::new(x, y, 0.0);
    let tris = vec![
        [p3(0.0, 0.0), p3(1.0, 0.0), p3(0.0, 1.0)],
        [p3(2.0, 0.0), p3(3.0, 0.0), p3(2.0, 1.0)],
    ];
    let chip = Chip::new(&tris, &tris, CHIP_CONFIG).unwrap();
    assert_eq!(
        chip.a.tree.node(0),
        Node::Inner([1, 2]),
        "the tree this derivation assumes"
    );
    let pose = Pose::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    let base = chip.image_bases();
    let (na, nb) = (base[0], base[1]);
    let (req, addr, issue) = (
        probe("memory", "req_valid"),
        probe("memory", "req_addr"),
        probe("d_cntr", "issue"),
    );
    let timeline = |prefetch: u32| {
        let p = Params {
            dop_latency: 2,
            issue_spacing: 1,
            outstanding: 4,
            prefetch,
            memory: MemTiming {
                latency: 3,
                interval: 1,
                bus_bits: None,
            }
            .into(),
            ..Params::RTL
        };
        let (mut reqs, mut issues) = (vec![], vec![]);
        let mut obs = |t: u64, v: &[u64]| {
            if v[req] == 1 && reqs.len() < 7 {
                reqs.push((t, v[addr] as u32));
            }
            if v[issue] == 1 {
                issues.push(t);
            }
            Ok(())
        };
        let tr = lifo_probed(&chip, &pose, p, &mut obs);
        assert_eq!(tr.dop_tests, 5);
        (reqs, issues)
    };
    let (reqs, issues) = timeline(2);
    let want = [
        (3, na),
        (4, nb),
        (12, na + 1),
        (13, nb + 1),
        (14, nb + 2),
        (15, na + 2),
        (16, nb + 1),
    ];
    assert_eq!(reqs, want);
    assert_eq!(issues, [8, 17, 18, 19, 20]);
    // without prefetch: (1,1)'s words A1, B1 in cycles 12, 13 (answered 15, 16), it issues
    // in 17; (1,2) is current from 18, asks for B2 then (answered 21) and issues in 22
    let (reqs, issues) = timeline(0);
    assert_eq!(reqs[2..5], [(12, na + 1), (13, nb + 1), (18, nb + 2)]);
    assert_eq!(issues[..3], [8, 17, 22]);
}

/// A wait costs no time, however long: memory latency, memory interval and the
/// host's reading period at 2^32 - 1 clocks each are skipped in one step, on two
/// 210-triangle meshes (the scene that walked its waits clock by clock). Run on a thread
/// with a generous bound so that a regression fails here instead of hanging the suite.
#[test]
fn the_longest_waits_are_skipped() {
    let (chip, pose) = sphere_torus(CHIP_CONFIG);
    let golden = chip.query(&pose, Mode::All, Traversal::Lifo);
    let long = u32::MAX;
    let cases = [
        (
            MemTiming {
                latency: long,
                ..Default::default()
            },
            Reader::default(),
        ),
        (
            MemTiming {
                interval: long,
                ..Default::default()
            },
            Reader::default(),
        ),
        (MemTiming::default(), Reader { period: long }),
    ];
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for (timing, reader) in cases {
            let p = Params {
                memory: timing.into(),
                ..Params::RTL
            };
            let r = cycle::run_query(
                &chip,
                &chip.setup(&pose),
                Order::Lifo,
                Mode::All,
                p,
                reader,
                cycle::MAX_CYCLES,
                counted(),
            )
            .map(|r| r.0);
            tx.send((timing, reader, r)).unwrap();
        }
    });
    for _ in 0..3 {
        let (timing, reader, r) = rx
            .recv_timeout(std::time::Duration::from_secs(60))
            .expect("a wait of 2^32 - 1 clocks was walked, not skipped");
        let tr = r.unwrap();
        tr.check(Mode::All, &golden).unwrap();
        assert!(
            tr.cycles > long as u64,
            "{timing:?} {reader:?}: {} cycles",
            tr.cycles
        );
    }
}

/// The folded TRI_UNIT's rhythm, derived from `rtl::b32::TriUnitFold`'s rule, not from the
/// model: its counter runs from the first pair taken, so pairs enter in cycles t0 + n ii
/// (from ii 4 some exactly ii apart: pairs queue behind the unit on these meshes), and the
/// first verdict is at the output ii/2 + L + 2 clocks after t0: the second direction enters
/// the shared T.CHECK ii/2 clocks after the first, L is that T.CHECK's latency at II ii/2,
/// and the result FIFO's write and read registers add 2. L = 58, 61, 85, 89 at II 1, 2, 8,
/// 16 (the modulo schedules', docs/explanation/architecture.md "Folded TRI_UNIT"; the exported Verilog
/// runs its vectors at 89 for T.CHECK at II 16 and 95 for TRI_UNIT at ii 16 under Icarus and
/// Verilator, vectors/tcheck_fold16_b32_rne.hex, tri_unit_fold16_b32_rne.hex). The answer is
/// golden's, and the same with idle stretches skipped as clock by clock.
#[test]
fn folded_tri_unit_takes_a_pair_every_interval() {
    let (chip, pose) = sphere_torus(CHIP_CONFIG);
    let golden = chip.query(&pose, Mode::All, Traversal::Lifo);
    let (take, out_valid) = (probe("tri_unit", "take"), probe("tri_unit", "out_valid"));
    for (ii, t_check) in [(2u32, 58u64), (4, 61), (16, 85), (32, 89)] {
        let p = Params {
            tri_interval: ii,
            ..Params::RTL
        };
        let latency = ii as u64 / 2 + t_check + 2;
        let (mut takes, mut first_out) = (vec![], None);
        let mut obs = |t: u64, v: &[u64]| {
            if v[take] == 1 {
                takes.push(t);
            }
            if v[out_valid] == 1 && first_out.is_none() {
                first_out = Some(t);
            }
            Ok(())
        };
        let clocked = lifo_probed(&chip, &pose, p, &mut obs);
        clocked.check(Mode::All, &golden).unwrap();
        assert_eq!(takes.len() as u64, clocked.tri_tests, "ii {ii}");
        let gaps: Vec<u64> = takes.windows(2).map(|w| w[1] - w[0]).collect();
        assert!(
            gaps.iter().all(|g| g % ii as u64 == 0),
            "ii {ii}: pairs taken {takes:?}"
        );
        // (at ii 2 the triangle words' fetches keep pairs at least 4 clocks apart here)
        assert!(
            ii < 4 || gaps.contains(&(ii as u64)),
            "ii {ii}: no two pairs back to back: {gaps:?}"
        );
        assert_eq!(
            first_out,
            Some(takes[0] + latency),
            "ii {ii}: the first verdict {latency} clocks after the first pair"
        );
        let skipped = cycle::run_query(
            &chip,
            &chip.setup(&pose),
            Order::Lifo,
            Mode::All,
            p,
            Reader::default(),
            MAX_CYCLES,
            counted(),
        )
        .unwrap()
        .0;
        assert_eq!(skipped, clocked, "ii {ii}");
    }
}
