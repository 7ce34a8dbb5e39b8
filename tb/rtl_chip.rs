//! The RTL collision chip in rust-hdl, clocked in lockstep with the cycle model
//! (`cycle::drive::Lockstep`): every output and every traversal signal of
//! `chip::probes::DATE05` equal after every clock, on queries of the checked-in set, one of
//! them on the papers' chip (k = 24, binary32), one on the k = 6 chip with a folded TRI_UNIT
//! (the traces the exported Verilog must
//! reproduce under Verilator, scripts/run-chip.sh), on a
//! query drawn from a fixed seed (DDR memory), on a leaf pair that is the query's last event
//! and on an overflowing queue. The answers are checked against the golden model too.
//!
//! `CCHIP_BLESS=1 cargo test --release --test rtl_chip` rewrites the expected traces of the
//! queries it runs, but only from a run in which rust-hdl and the cycle model agreed.

mod common;
use collision_chip::chip::memory::Ddr;
use collision_chip::chip::memory::Memory;
use collision_chip::chip::params::Params;
use collision_chip::chip::probes::DATE05;
use collision_chip::chip::reg::Mode;
use collision_chip::chip::reg::Order;
use collision_chip::chip::rtl::{ChipKind, Depth};
use collision_chip::cycle::chip::Chip as CycleChip;
use collision_chip::cycle::drive::open_vcd;
use collision_chip::cycle::drive::{run_query, ChipTrace, Drive, Lockstep, Reader};
use collision_chip::golden::host::HostSetup;
use collision_chip::harness::chip_io::{
    drive, queries, with_chip, ChipQuery, OnChip, QueryImage, RtlChip, RtlPorts,
};
use collision_chip::pose::Pose;
use collision_chip::query::Chip;
use collision_chip::traversal::{QueryResult, Traversal};
use common::vcd_file::{assert_shows, vcd_results};
use std::path::PathBuf;

/// Generous: the longest query takes about 2,000 cycles.
const MAX_CYCLES: u64 = 20_000;

/// One query to run in lockstep: the golden images, the pose's setup, the RTL's memory
/// image and writes, and how it is driven.
struct Case {
    name: String,
    chip: Chip,
    setup: HostSetup,
    image: QueryImage,
    golden: QueryResult,
    order: Order,
    mode: Mode,
    /// The RTL chip's parameters: its memory and memory port (register `reg::PORT`).
    params: Params,
    reader: Reader,
}

impl Case {
    fn new(
        name: &str,
        chip: Chip,
        pose: Pose,
        order: Order,
        mode: Mode,
        params: Params,
        reader: Reader,
    ) -> Case {
        let setup = chip.setup(&pose);
        let kind = ChipKind::of(
            &chip.cfg,
            params.dop_interval,
            params.tri_interval,
            params.depth,
        )
        .expect("an RTL chip's configuration");
        let image = QueryImage::new(
            kind, &chip.a, &chip.b, &setup, order, mode, &params, &chip.cfg,
        )
        .unwrap();
        let golden = chip.query(
            &pose,
            Mode::All,
            if order == Order::Lifo {
                Traversal::Lifo
            } else {
                Traversal::Fifo
            },
        );
        Case {
            name: name.into(),
            chip,
            setup,
            image,
            golden,
            order,
            mode,
            params,
            reader,
        }
    }

    fn of(q: &ChipQuery) -> Case {
        let p = q.prepare().unwrap();
        Case::new(
            q.name,
            p.chip,
            q.pose,
            q.order,
            q.mode,
            q.params(),
            q.reader,
        )
    }

    fn drive(&self) -> Drive {
        drive(
            &self.image,
            self.params.memory_clocks().unwrap(),
            self.reader,
            MAX_CYCLES,
        )
    }

    /// Runs the query `runs` times back to back on one rust-hdl chip (of the image's kind)
    /// of `2^N` queue entries and one cycle model, in lockstep; with `vcd`, the first run's
    /// traversal VCD.
    fn lockstep<const N: usize, const NP1: usize, const NM1: usize>(
        &self,
        runs: usize,
        vcd: Option<PathBuf>,
    ) -> Vec<ChipTrace> {
        std::thread::scope(|s| {
            std::thread::Builder::new()
                .stack_size(1 << 30)
                .spawn_scoped(s, || {
                    struct Run<'c> {
                        case: &'c Case,
                        queue_entries: u32,
                        runs: usize,
                        vcd: Option<PathBuf>,
                    }
                    impl OnChip for Run<'_> {
                        type Out = Vec<ChipTrace>;
                        fn run<C: RtlPorts>(self, chip: C) -> Vec<ChipTrace> {
                            self.case
                                .run_on(chip, self.queue_entries, self.runs, self.vcd)
                        }
                    }
                    with_chip::<N, NP1, NM1, _>(
                        self.image.kind,
                        Run {
                            case: self,
                            queue_entries: 1 << N,
                            runs,
                            vcd,
                        },
                    )
                })
                .unwrap()
                .join()
                .unwrap()
        })
    }

    fn run_on<C: RtlPorts>(
        &self,
        mut rtl: C,
        queue_entries: u32,
        runs: usize,
        vcd: Option<PathBuf>,
    ) -> Vec<ChipTrace> {
        let p = Params {
            queue_entries,
            ..self.params
        };
        let mut cyc = CycleChip::new(
            &self.chip.cfg,
            p,
            &self.chip.a,
            &self.chip.b,
            &self.setup,
            false,
        )
        .unwrap();
        let mut out = vec![];
        for run in 0..runs {
            let mut ls = Lockstep::new(
                RtlChip::new(&mut rtl, &self.image),
                &mut cyc,
                ("rust-hdl", "cycle model"),
            );
            let mut w = vcd
                .as_ref()
                .filter(|_| run == 0)
                .map(|p| open_vcd(p, &DATE05, &[], 0..u64::MAX).unwrap());
            let tr = run_query(
                &mut ls,
                &self.image.writes,
                &self.drive(),
                true,
                |t, p| {
                    if let Some(w) = w.as_mut() {
                        w.cycle(t, &p.unwrap())?;
                    }
                    Ok(())
                },
                false,
            )
            .unwrap_or_else(|e| panic!("{}: {e}", self.name));
            out.push(tr);
        }
        out
    }

    /// The answer is the golden model's, and in all-pairs mode so are the test counts.
    fn check(&self, tr: &ChipTrace) {
        let name = &self.name;
        println!("{name}: {}", tr.text().lines().last().unwrap());
        tr.check(self.mode, &self.golden)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        if self.mode == Mode::All {
            let g = self.golden.counters;
            assert_eq!(
                (tr.dop_tests, tr.tri_tests),
                (g.dop_tests, g.tri_tests),
                "{name}: tests"
            );
            if self.order == Order::Fifo {
                // FIFO order tests pairs in exactly the golden D_CNTR's order
                assert_eq!(
                    (tr.node_fetches, tr.tri_fetches),
                    (g.node_fetches, g.tri_fetches),
                    "{name}: fetches"
                );
            }
        }
    }
}

fn query(name: &str) -> ChipQuery {
    queries().into_iter().find(|q| q.name == name).unwrap()
}

fn expect_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("vectors/chip")
        .join(format!("{name}.expect"))
}

/// The lockstep trace equals the checked-in one (the Verilog's reference), or is blessed
/// into it: rust-hdl and the cycle model agreed on every clock of it.
fn compare_with_expect(name: &str, tr: &ChipTrace) {
    let path = expect_path(name);
    if std::env::var("CCHIP_BLESS").is_ok_and(|v| v == "1") {
        std::fs::write(&path, tr.text()).unwrap();
        return;
    }
    let want = std::fs::read_to_string(&path).unwrap_or_else(|e| {
        panic!(
            "{}: {e} (write it with CCHIP_BLESS=1 cargo test --release --test rtl_chip)",
            path.display()
        )
    });
    assert_eq!(
        tr.text(),
        want,
        "{name}: the trace differs from {}",
        path.display()
    );
}

/// The LIFO first-hit query, traced: target/rtl-vcd/chip_sphere_lifo_first.vcd (open it with
/// scripts/gtkw/chip_e8m15_k6.gtkw) holds the signals the save file shows.
/// (rust-hdl runs the chip at about 14 clocks per second, so of the set's queries it runs
/// this one and `apart_lifo_first`, FIFO order in the queries further down; every query of
/// the set is reproduced by the cycle model in tb/cycle_chip.rs and by the exported Verilog
/// under Verilator in CI, against the same traces.)
#[test]
fn sphere_lifo_first() {
    let q = query("sphere_lifo_first");
    let case = Case::of(&q);
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/rtl-vcd/chip_sphere_lifo_first.vcd");
    let tr = &case.lockstep::<10, 11, 9>(1, Some(path.clone()))[0];
    println!("wrote {}", path.display());
    case.check(tr);
    compare_with_expect(q.name, tr);
    assert_eq!(
        vcd_results(&path),
        tr.results,
        "the VCD's results differ from the trace"
    );
    assert_shows(&path, DATE05.gtkw);
}

/// The papers' chip (k = 24 DOPTRF lanes, binary32 throughout) on a first-hit query with
/// the memory port at full speed (register `reg::PORT`: 3 pairs ahead, 4 requests outstanding, an
/// issue every clock, a credit of 24; a memory latency of 8): node words asked for pairs
/// before they reach the DOP unit, several in flight, responses into the node-word FIFOs, a
/// DOP result's two child entries pushed in one clock; every signal equal to the cycle
/// model's, clock by clock, and the trace the checked-in one (which Verilator reproduces in
/// CI). (The small chip's port at full speed: `seeded_random_query`, and
/// `bunny_fifo_prefetch` under Verilator.)
#[test]
fn k24_sphere_lifo_first() {
    let q = query("k24_sphere_lifo_first");
    assert_eq!(q.chip, ChipKind::K24B32);
    let case = Case::of(&q);
    let tr = &case.lockstep::<10, 11, 9>(1, None)[0];
    case.check(tr);
    compare_with_expect(q.name, tr);
}

/// The papers' chip reading the `records` layout (register `reg::MODE` bit 2): the
/// two children of a node in one 2,048-bit record (a pair reads its node word from the slot
/// its id's bit 0 names, and fetches a record only if the pair before used another), a
/// leaf's triangle fetched by its record (triangles in leaf order) through a 2-line cache;
/// the memory port at full speed. Every signal equal to the cycle model's, clock by clock;
/// in FIFO order the record fetches are the golden traversal's (`Case::check`), fewer than
/// the `words` layout's node fetches on the same query.
#[test]
fn k24_rec_patch_fifo_all() {
    use collision_chip::chip::config::MemLayout;
    let q = query("k24_rec_patch_fifo_all");
    assert_eq!((q.chip, q.layout), (ChipKind::K24B32, MemLayout::Records));
    let case = Case::of(&q);
    // leaf order is not index order: a chip fetching triangles by index would differ
    assert!(case
        .chip
        .a
        .tri_records
        .iter()
        .enumerate()
        .any(|(t, &r)| r != t as u32));
    let tr = &case.lockstep::<10, 11, 9>(1, None)[0];
    case.check(tr);
    let words = ChipQuery {
        layout: MemLayout::Words,
        ..q.clone()
    }
    .prepare()
    .unwrap()
    .golden_all
    .counters
    .node_fetches;
    assert!(
        tr.tri_tests > 0 && tr.node_fetches < words,
        "{} record fetches, {words} node words",
        tr.node_fetches
    );
    compare_with_expect(q.name, tr);
}

/// The papers' chip reading records of 4-bit stored DOPs (`chip_b32_k24_q4`): node words of
/// codes, a node's children and grandchildren in one record, the decode stage ahead of the
/// DOP unit (3 clocks more to each verdict). Every signal equal to the cycle model's, clock
/// by clock; the answer, tests and record fetches the golden model's.
#[test]
fn k24q4_patch_fifo_all() {
    let q = query("k24q4_patch_fifo_all");
    assert_eq!(q.chip, ChipKind::K24B32Q4);
    let case = Case::of(&q);
    let tr = &case.lockstep::<10, 11, 9>(1, None)[0];
    case.check(tr);
    assert!(tr.tri_tests > 0, "the patch meets itself");
    compare_with_expect(q.name, tr);
}

/// The `records` layout on a DDR of 8 banks (2 records a page), its regions in banks of
/// their own (A's nodes 2, B's 4, the triangles 1 each: register `reg::MAP`, the memory port's
/// shifts and masks, `chip::layout::RecordMap`): the same query as
/// [`k24_rec_patch_fifo_all`], every signal (the request addresses too) equal to the cycle
/// model's, clock by clock, and the answer the golden model's.
#[test]
fn k24_rec_patch_fifo_ddr_banks() {
    use collision_chip::chip::reg::MAP;
    let q = query("k24_rec_patch_fifo_all");
    let ddr = Memory::Ddr(Ddr {
        banks: 8,
        page_bytes: 512,
        bus_bits: 1024,
        burst: 2,
        // at the `rtl` preset's 1.25 ns: a burst 2 clocks, a hit 3, a miss 6
        beat_ps: 1250,
        hit_ps: 3750,
        miss_ps: 7500,
    });
    let p = q.prepare().unwrap();
    let case = Case::new(
        "k24_rec_patch_fifo_ddr_banks",
        p.chip,
        q.pose,
        q.order,
        q.mode,
        Params {
            memory: ddr,
            ..q.params()
        },
        q.reader,
    );
    let map = case
        .image
        .writes
        .iter()
        .find(|w| w.0 == MAP)
        .expect("the record map written")
        .1;
    assert_eq!(
        map,
        1 | 2 << 3 | 1 << 12 | 3 << 16,
        "A's nodes 2 banks, B's 4, a page 2 records, 8 banks"
    );
    let tr = &case.lockstep::<10, 11, 9>(1, None)[0];
    case.check(tr);
}

/// A's triangle cache with 4 lines (register `reg::TRI_CACHE`): triangle words fetched only when
/// their line holds another, a fill bypassed to the leaf pair that reads its line in the
/// next clock; in lockstep with the cycle model, and in FIFO order A's and B's fetches are
/// the golden traversal's (`Case::check`), fewer than with the single word held.
#[test]
fn sphere_fifo_cache() {
    let q = query("sphere_fifo_cache");
    assert_eq!(q.tri_cache, 4);
    let case = Case::of(&q);
    let tr = &case.lockstep::<10, 11, 9>(1, None)[0];
    case.check(tr);
    let one_line = ChipQuery {
        tri_cache: 1,
        ..q.clone()
    }
    .prepare()
    .unwrap()
    .golden_all
    .counters
    .tri_fetches;
    assert!(
        tr.tri_fetches < one_line,
        "{} triangle fetches with 4 lines, {one_line} with one",
        tr.tri_fetches
    );
    compare_with_expect(q.name, tr);
}

/// The papers' chip with its DOP unit in e8m15 and TRI_UNIT in binary32:
/// 641-bit node words in 2,048-bit memory words, each unit fed its own format's fields, the
/// DOP lanes rounding to nearest-even; in lockstep with the cycle model, whose DOP and
/// T.CHECK verdicts are the golden model's in those formats and roundings.
#[test]
fn k24r_rne_patch_fifo_all() {
    let q = query("k24r_rne_patch_fifo_all");
    assert_eq!(q.chip, ChipKind::K24E8m15B32);
    let case = Case::of(&q);
    let tr = &case.lockstep::<10, 11, 9>(1, None)[0];
    case.check(tr);
    assert!(tr.tri_tests > 0, "the query tests triangles");
    compare_with_expect(q.name, tr);
}

/// The papers' chip in one narrow format throughout, e8m15 and e8m10 (641- and 521-bit node
/// words, each unit in that format), the DOP lanes rounding to nearest-even: a bunny patch
/// at full speed in lockstep with the cycle model, whose verdicts are the golden model's in
/// that format and rounding, and the trace the checked-in one (which Verilator reproduces in
/// CI).
#[test]
fn k24_narrow_rne_patch_fifo_all() {
    for (name, chip) in [
        ("k24e_rne_patch_fifo_all", ChipKind::K24E8m15),
        ("k24m10_rne_patch_fifo_all", ChipKind::K24E8m10),
    ] {
        let q = query(name);
        assert_eq!(q.chip, chip);
        let case = Case::of(&q);
        let tr = &case.lockstep::<10, 11, 9>(1, None)[0];
        case.check(tr);
        assert!(tr.tri_tests > 0, "{name} tests triangles");
        compare_with_expect(q.name, tr);
    }
}

/// The k = 6 chip with TRI_UNIT folded (`TriUnitFold`, a pair every 16 clocks) on a
/// bunny patch at full speed: leaf pairs wait in the leaf register for the unit's slots
/// (`in_ready` high one clock in 16 from the first pair), every signal equal to the cycle
/// model's (`[timing] tri_interval = 16`, its latency `fold::tri_unit_latency`) clock by
/// clock, the answer the golden model's, and the trace the checked-in one (which Verilator
/// reproduces in CI).
#[test]
fn fold16_patch_fifo_all() {
    let q = query("fold16_patch_fifo_all");
    assert_eq!(
        (q.chip, q.params().tri_interval),
        (ChipKind::K6E8m15Fold16, 16)
    );
    let case = Case::of(&q);
    let tr = &case.lockstep::<10, 11, 9>(1, None)[0];
    case.check(tr);
    // pairs back to back at one a clock would need fewer clocks than 16 per pair
    assert!(tr.tri_tests > 4, "{} triangle tests", tr.tri_tests);
    compare_with_expect(q.name, tr);
}

/// The k = 6 chip with both units folded: the DOP unit on one lane
/// (`DopUnit6Fold6`, a pair every 6 clocks, latency 20) and TRI_UNIT a pair every 32 clocks,
/// on a bunny patch at full speed: D_CNTR's pairs wait with both node words held for the DOP
/// unit's `in_ready` (high one clock in 6 from the first pair taken since reset), every
/// signal equal to the cycle model's (`[timing] dop_interval = 6, tri_interval = 32`) clock
/// by clock, the answer the golden model's, and the trace the checked-in one (which
/// Verilator reproduces).
#[test]
fn dop6tri32_patch_fifo_all() {
    let q = query("dop6tri32_patch_fifo_all");
    let p = q.params();
    assert_eq!(
        (q.chip, p.dop_interval, p.tri_interval),
        (ChipKind::K6E8m15Dop6Tri32, 6, 32)
    );
    let case = Case::of(&q);
    let tr = &case.lockstep::<10, 11, 9>(1, None)[0];
    case.check(tr);
    // issued every clock, the tests would need fewer clocks than 6 per DOP test
    assert!(
        tr.dop_tests > 6 && tr.tri_tests > 4,
        "{} DOP tests, {} triangle tests",
        tr.dop_tests,
        tr.tri_tests
    );
    compare_with_expect(q.name, tr);
}

/// The same chip at FPGA depth (`chip_e8m15_k6_dop6_tri32_fpga`: the DOP unit's lane of
/// six-stage FP units, latency 31; TRI_UNIT's T.CHECK at FPGA depth with its operands
/// registered) on the same patch: every signal equal to the cycle model's at `[timing] depth =
/// "fpga"` clock by clock, the answer the golden model's, the trace the checked-in one.
#[test]
fn dop6tri32fpga_patch_fifo_all() {
    let q = query("dop6tri32fpga_patch_fifo_all");
    let p = q.params();
    assert_eq!(
        (q.chip, p.dop_interval, p.tri_interval, p.depth),
        (ChipKind::K6E8m15Dop6Tri32Fpga, 6, 32, Depth::Fpga)
    );
    let case = Case::of(&q);
    let tr = &case.lockstep::<10, 11, 9>(1, None)[0];
    case.check(tr);
    assert!(tr.dop_tests > 6 && tr.tri_tests > 4);
    compare_with_expect(q.name, tr);
}

/// Two objects apart: the root pair fails the DOP test and nothing is reported. The same
/// chip then runs the query again: a finished query leaves no state behind.
#[test]
fn apart_lifo_first() {
    let case = Case::of(&query("apart_lifo_first"));
    assert!(case.golden.pairs.is_empty());
    let tr = case.lockstep::<10, 11, 9>(2, None);
    assert_eq!(tr[0], tr[1]);
    assert!(tr[0].results.is_empty());
    assert_eq!(
        (tr[0].dop_tests, tr[0].node_fetches, tr[0].tri_tests),
        (1, 2, 0)
    );
    case.check(&tr[0]);
    compare_with_expect("apart_lifo_first", &tr[0]);
}

/// One triangle each, crossing: the root pair is a leaf pair, the query's last DOP result,
/// and TRI_UNIT is empty when it enters the leaf FIFO. The chip must not end the query in
/// the clock in which the FIFO does not show the pair yet (hand-derived: one sure hit).
#[test]
fn a_last_leaf_pair_is_tested() {
    let p = |x: f64, y: f64, z: f64| nalgebra::Point3::new(x, y, z);
    let a = vec![[p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0)]];
    let b = vec![[p(0.2, 0.2, -1.0), p(0.3, 0.2, 1.0), p(0.2, 0.3, 1.0)]];
    let pose = Pose::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    for order in [Order::Fifo, Order::Lifo] {
        let case = Case::new(
            "one_leaf_pair",
            Chip::new(&a, &b, ChipKind::K6E8m15.config()).unwrap(),
            pose,
            order,
            Mode::All,
            Params::RTL,
            Reader::default(),
        );
        let tr = &case.lockstep::<10, 11, 9>(1, None)[0];
        assert_eq!(
            tr.results
                .iter()
                .map(|r| (r.1, r.2, r.3))
                .collect::<Vec<_>>(),
            [(0, 0, false)],
            "{}",
            tr.text()
        );
        case.check(tr);
    }
}

/// A queue of 4 entries cannot hold the spheres' traversal: the chip ends the query with
/// `overflow` and what it must: the traversal stops (fewer DOP tests than the golden
/// query), every pair it reported is a golden one, and the trace does not pass for a
/// complete answer.
#[test]
fn a_small_queue_overflows_with_an_error_status() {
    let case = Case::of(&query("sphere_fifo_all"));
    let tr = &case.lockstep::<2, 3, 1>(1, None)[0];
    println!("{}", tr.text());
    assert!(tr.overflow, "no overflow reported");
    assert_eq!(tr.max_depth, 4);
    assert_eq!(
        tr.check(Mode::All, &case.golden),
        Err("the queue overflowed: the answer is incomplete".into())
    );
    let (hits, unc) = tr.pairs();
    assert!(hits
        .iter()
        .chain(&unc)
        .all(|x| case.golden.pairs.contains(x) || case.golden.uncertain.contains(x)));
    assert!(
        tr.dop_tests < case.golden.counters.dop_tests / 4,
        "the traversal went on after the overflow"
    );
}

/// A random soup pair, pose, order, mode and result reader from a fixed seed, with a small
/// DDR SDRAM (3 words per page, 2 banks) and the memory port at full speed: rust-hdl and the
/// cycle model in lockstep, through
/// the one driver and DDR model, and the answer the golden model's. (Volume: tb/cycle_chip.rs
/// draws 256 such configurations for the cycle model, and CI's Verilog scenes.)
#[test]
fn seeded_random_query() {
    use collision_chip::mesh::soup;
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(2);
    // small: rust-hdl runs the chip at about 25 clocks per second
    let (na, nb) = (rng.random_range(3..=6), rng.random_range(3..=6));
    let chip = Chip::new(
        &soup(na, rng.random()).triangles_f64(),
        &soup(nb, rng.random()).triangles_f64(),
        ChipKind::K6E8m15.config(),
    )
    .unwrap();
    let r = |rng: &mut rand_chacha::ChaCha8Rng| rng.random_range(0.0..360.0);
    let t = |rng: &mut rand_chacha::ChaCha8Rng| rng.random_range(-0.3..0.3);
    let pose = Pose::new(
        r(&mut rng),
        r(&mut rng),
        r(&mut rng),
        t(&mut rng),
        t(&mut rng),
        t(&mut rng),
    );
    let (lifo, first) = (rng.random::<bool>(), rng.random_range(0..3) == 0);
    let ddr = Memory::Ddr(Ddr {
        banks: 2,
        page_bytes: 256,
        bus_bits: 64,
        burst: 2,
        // at Params::RTL's 1.25 ns: a burst 2 clocks, a hit 2, a miss 5
        beat_ps: 1250,
        hit_ps: 2500,
        miss_ps: 6250,
    });
    let reader = Reader {
        period: [1, 1, 2, 5][rng.random_range(0..4)],
    };
    let mode = if first { Mode::First } else { Mode::All };
    // and the memory port at full speed: 2 pairs prefetched, 3 requests, an issue every
    // clock, a credit of 20
    let params = Params {
        memory: ddr,
        prefetch: 2,
        outstanding: 3,
        issue_spacing: 1,
        credit: 20,
        ..Params::RTL
    };
    let order = if lifo { Order::Lifo } else { Order::Fifo };
    let case = Case::new("seed 2", chip, pose, order, mode, params, reader);
    println!(
        "seed 2: {na} x {nb} triangles, {}, {mode:?}, reader period {}",
        if lifo { "LIFO" } else { "FIFO" },
        reader.period
    );
    let tr = &case.lockstep::<10, 11, 9>(1, None)[0];
    case.check(tr);
}
