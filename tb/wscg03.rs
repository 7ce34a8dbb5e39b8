//! WSCG'03's chip in the cycle model (`src/cycle/wscg03`): its answers are the golden list
//! traversal's (WSCG'03 Algorithm 2) on random configurations and memories, every clock is
//! booked to one cause, and small lists follow timelines derived by hand.

mod common;
use collision_chip::chip::config::{ChipConfig, DopRounding, Formats};
use collision_chip::chip::memory::{Ddr, MemTiming, Memory};
use collision_chip::chip::params::Params;
use collision_chip::chip::probes::WSCG03;
use collision_chip::chip::reg::Mode;
use collision_chip::chip::rtl::ChipKind;
use collision_chip::chip::wscg03::StackParams;
use collision_chip::cycle::wscg03::{run_query, ListRecord};
use collision_chip::cycle::MAX_CYCLES;
use collision_chip::dop::tree::Tri;
use collision_chip::format::{Format, Rounding};
use collision_chip::golden::dop_unit::TransformCache;
use collision_chip::mesh::soup;
use collision_chip::pose::Pose;
use collision_chip::query::Chip;
use collision_chip::traversal::Traversal;
use nalgebra::Point3;
use proptest::prelude::*;

fn memory() -> impl Strategy<Value = Memory> {
    prop_oneof![
        (1u32..=6, 1u32..=3, prop::option::of(16u32..=1024)).prop_map(
            |(latency, interval, bus_bits)| Memory::Ideal(MemTiming {
                latency,
                interval,
                bus_bits
            })
        ),
        Just(Memory::Ddr(Ddr::WSCG03)),
        (
            (1u32..=4, 6u32..=12, 5u32..=8, 0u32..=3),
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

fn stack_params() -> impl Strategy<Value = StackParams> {
    (
        0u32..=4,
        0u32..=8,
        prop::sample::select(vec![64u32, 256, 1024]),
        1u32..=4,
        1u32..=6,
        1u32..=4,
        1u32..=60,
    )
        .prop_map(
            |(
                sram_latency,
                dotadd_stages,
                data_bus_bits,
                compare_latency,
                word_buffer,
                tri_interval,
                tri_latency,
            )| StackParams {
                sram_latency,
                dotadd_stages,
                data_bus_bits,
                compare_latency,
                word_buffer,
                tri_interval,
                tri_latency,
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 160, failure_persistence: None, .. ProptestConfig::default() })]

    /// Any k, formats, rounding, triangle cache, memory and WSCG'03 timing: the chip reports
    /// the golden list traversal's sure hits and uncertain pairs (first hit: pairs of it,
    /// and a hit exactly when it has one), and in all-pairs mode tests the same DOP pairs,
    /// overlaps, triangle pairs, lists and aligned node pairs (Eq. 5's tau and alpha); every
    /// clock is booked to one cause; a list's d' are never ready before its start. The chip
    /// clocked register by register (`cycle::wscg03::clocked`) answers the same.
    #[test]
    fn answers_as_the_golden_list_traversal(
        k in prop::sample::select(vec![6usize, 14, 18, 24, 26]), dop_b32: bool, tri_b32: bool, outward: bool,
        tri_cache in prop::sample::select(vec![1u32, 4, 128]),
        na in 1usize..=100, nb in 1usize..=100, sa: u64, sb: u64,
        rot in prop::array::uniform3(0.0f64..360.0), t in prop::array::uniform3(-0.4f64..0.4),
        first: bool, memory in memory(), sp in stack_params(),
    ) {
        let f = |b32| if b32 { Format::BINARY32 } else { Format::REDUCED };
        let cfg = ChipConfig {
            k,
            format: Formats { dop: f(dop_b32), tri: f(tri_b32) },
            dop_rounding: if outward { DopRounding::Outward } else { DopRounding::NearestEven },
            tri_rounding: Rounding::NearestEven,
            tri_cache,
            ..ChipConfig::default()
        };
        let chip = Chip::new(&soup(na, sa).triangles_f64(), &soup(nb, sb).triangles_f64(), cfg).unwrap();
        let pose = Pose::new(rot[0], rot[1], rot[2], t[0], t[1], t[2]);
        let mode = if first { Mode::First } else { Mode::All };
        let golden = chip.query(&pose, Mode::All, Traversal::List);
        let p = Params { memory, ..Params::RTL };
        let run = run_query(&chip, &chip.setup(&pose), mode, &p, &sp, MAX_CYCLES).unwrap();
        let (tr, s) = (&run.trace, &run.stats);
        prop_assert!(tr.check(mode, &golden).is_ok(), "{:?}\n{}", tr.check(mode, &golden), tr.text());
        // the chip clocked register by register answers the same
        let clocked = collision_chip::cycle::wscg03::clocked::run(&chip, &chip.setup(&pose), (first, &p), MAX_CYCLES, |_, _, _| {}, None).unwrap();
        prop_assert!(clocked.trace.check(mode, &golden).is_ok(), "clocked: {:?}", clocked.trace.check(mode, &golden));
        if !first {
            let g = golden.counters;
            prop_assert_eq!((s.dop_tests, s.dop_overlaps, tr.tri_tests), (g.dop_tests, g.dop_overlaps, g.tri_tests));
            prop_assert_eq!((s.lists, s.list_node_pairs), (g.lists, g.list_node_pairs));
            prop_assert_eq!(run.lists.len() as u64, s.lists);
        }
        prop_assert_eq!(s.compare + s.stall_memory + s.stall_transform + s.stall_list + s.drain, s.cycles, "{:?} {:?}", s, run.lists);
        prop_assert_eq!(tr.cycles, s.cycles);
        prop_assert!(tr.results.iter().all(|r| r.0 < tr.cycles));
        prop_assert!(run.lists.iter().all(|l| l.first_compare.is_none_or(|c| c >= l.ready && c > l.t0)));
    }
}

/// Two unit squares, one in the plane z = 0, one in y = 0 through it (two triangles each).
fn squares() -> (Vec<Tri>, Vec<Tri>) {
    let p = Point3::new;
    let flat = vec![
        [p(0., 0., 0.), p(1., 0., 0.), p(1., 1., 0.)],
        [p(0., 0., 0.), p(1., 1., 0.), p(0., 1., 0.)],
    ];
    let upright = vec![
        [p(0., 0.5, -0.5), p(1., 0.5, -0.5), p(1., 0.5, 0.5)],
        [p(0., 0.5, -0.5), p(1., 0.5, 0.5), p(0., 0.5, 0.5)],
    ];
    (upright, flat)
}

/// The hand-derived timelines on the k = 6 e8m15 chip (a node word of 209 bits: one clock
/// on the 256-bit data bus) with a memory answering in the next cycle, one word per clock,
/// and WSCG'03's timing (SRAM 2, DOTADD 6 stages, compare latency 2):
///
/// List 1 (B's root against [A's root]) starts at clock 1, its pointer reaches the Memory
/// Controller at 3; B's root asked for at 3 is answered in cycle 4, present at 5;
/// transformed by clock 5 + k + 6 = 17. The left parent (B's root) has children: asked for
/// at 4 and 5, present at 6 and 7; the left DOTADD is busy until 5 + k = 11, so child 1
/// is ready at 11 + 12 = 23, child 2 at 7 + 12 = 19: the speculative pair at 23. A's root
/// is asked for at 6 (after those), present at 8. The compare waits for the transform:
/// clock 17 (16 clocks of start latency after the list's start), flags at 17 + 2 = 19.
///
/// Apart (no overlap): nothing follows; the query ends at clock 20 (1 clock of start, 16
/// waiting for the transform, 1 compare, 2 of flags).
///
/// Overlapping: list 2 (B's children against A's root's children) starts at 20, its pair
/// already transformed (ready at 23, hidden behind list 1); its first word asked at 22
/// is present at 24, compared at 24: no transform wait.
#[test]
fn small_lists_follow_the_hand_derived_timeline() {
    let (a, b) = squares();
    let chip = Chip::new(&a, &b, ChipKind::K6E8m15.config()).unwrap();
    let p = Params {
        memory: Memory::Ideal(MemTiming {
            latency: 1,
            interval: 1,
            bus_bits: None,
        }),
        ..Params::RTL
    };
    let sp = StackParams::PAPER;
    let rec = |t0, held, ready, first, next, len| ListRecord {
        t0,
        held,
        ready,
        first_compare: Some(first),
        next,
        len,
    };

    let apart = Pose::new(0.0, 0.0, 0.0, 5.0, 0.0, 0.0);
    let run = run_query(&chip, &chip.setup(&apart), Mode::All, &p, &sp, MAX_CYCLES).unwrap();
    assert_eq!(run.lists, vec![rec(1, false, 17, 17, 20, 1)]);
    let s = run.stats;
    assert_eq!(
        (
            s.cycles,
            s.stall_list,
            s.stall_transform,
            s.compare,
            s.drain
        ),
        (20, 1, 16, 1, 2)
    );
    assert_eq!((s.transforms, s.spec_pairs, s.spec_used), (3, 1, 0));
    assert_eq!((s.cold_lists, s.cold_start), (1, 16));
    // the bound on a query's clocks stops WSCG'03's chip as it stops DATE'05's
    assert!(run_query(&chip, &chip.setup(&apart), Mode::All, &p, &sp, 20).is_ok());
    let e = run_query(&chip, &chip.setup(&apart), Mode::All, &p, &sp, 19)
        .err()
        .unwrap();
    assert_eq!(e, "the query did not finish within 19 cycles");

    let touching = Pose::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    let run = run_query(
        &chip,
        &chip.setup(&touching),
        Mode::All,
        &p,
        &sp,
        MAX_CYCLES,
    )
    .unwrap();
    assert_eq!(
        run.lists[..2],
        [
            rec(1, false, 17, 17, 20, 1),
            rec(20, true, 23, 24, run.lists[1].next, 2)
        ]
    );
    assert_eq!(run.stats.spec_used, 1);
    let golden = chip.query(&touching, Mode::All, Traversal::List);
    run.trace.check(Mode::All, &golden).unwrap();
    assert!(!golden.pairs.is_empty());
}

/// A long list hides the transform of the next pair: after a list of n aligned words at one
/// word per clock, the speculative pair (ready 6 + 2 (k + 6) clocks into the list at most)
/// is ready before the next list's first word, so that list waits for no transform. Checked
/// on the squares scaled up to a few hundred triangles.
#[test]
fn long_lists_hide_the_transforms() {
    let a = soup(300, 1).triangles_f64();
    let chip = Chip::new(&a, &a, ChipKind::K6E8m15.config()).unwrap();
    let p = Params {
        memory: Memory::Ideal(MemTiming {
            latency: 1,
            interval: 1,
            bus_bits: None,
        }),
        ..Params::RTL
    };
    let run = run_query(
        &chip,
        &chip.setup(&Pose::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0)),
        Mode::All,
        &p,
        &StackParams::PAPER,
        MAX_CYCLES,
    )
    .unwrap();
    let k = 6;
    let mut checked = 0;
    for w in run.lists.windows(2) {
        if w[1].held && w[0].len >= 2 * (k + 6) + 6 {
            assert!(w[1].ready <= w[1].first_compare.unwrap(), "{w:?}");
            assert!(
                w[1].ready <= w[1].t0 + StackParams::PAPER.sram_latency as u64 + 2,
                "the transform is not hidden: {w:?}"
            );
            checked += 1;
        }
    }
    assert!(checked > 0, "no long list followed by a speculated pair");
}

/// A scene on WSCG'03's chip (`[chip] preset = "wscg03"`, clocked as its RTL): the chip's
/// pairs are the golden list traversal's (the run's golden check fails the run otherwise),
/// whose pairs are the exact oracle's (no misses, no extras), every pose has its clocks
/// booked (summing to its clocks), and the explain names WSCG'03's units. Its waveforms:
/// a VCD per pose of the scopes asked for, in the window asked for, with the results; a
/// scope of DATE'05's chip is refused, naming WSCG'03's.
#[test]
fn a_scene_on_wscg03s_chip_answers_as_the_exact_oracle() {
    use collision_chip::scene::{graph::Plan, run::Prepared, Scene};
    let text = "[objects]\na = \"sphere:80\"\nb = \"torus:60\"\n[chip]\npreset = \"wscg03\"\n[sweep]\ndistances = [1.2, 0.6]\norientations = 2\n[outputs]\naccuracy = true\ncycles = true\nmemory = true\n";
    let s = Scene::parse(text, "test").unwrap();
    let explain = Plan::of(&s).explain(&s);
    assert!(
        explain.contains("  stack_engine")
            && explain.contains("  triangle_unit")
            && !explain.contains("  d_cntr"),
        "{explain}"
    );
    let run = Prepared::new(&s, |spec| {
        collision_chip::mesh::resolve(spec).map_err(|e| e.to_string())
    })
    .unwrap()
    .run(|| ())
    .unwrap();
    assert!(run.records.iter().any(|r| r.pair_count > 0));
    for r in &run.records {
        let a = r.accuracy.as_ref().unwrap();
        assert_eq!((a.misses, a.extras), (0, 0), "{r:?}");
        let c = r.cycles.as_ref().unwrap();
        assert!(
            c.stats.is_none()
                && c.wscg03
                    .as_ref()
                    .is_some_and(|w| w.booked.total() == c.cycles && w.lists > 0),
            "{c:?}"
        );
    }
    let e = Scene::parse(
        &format!("{text}waveforms = {{ dir = \"w\", scopes = [\"d_cntr\"] }}\n"),
        "t",
    )
    .unwrap_err();
    assert!(
        e.contains("no scope \"d_cntr\"; the scopes are host, stack_engine, memory_controller"),
        "{e}"
    );
    let dir =
        std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/test-vcd/wscg03_scene");
    let _ = std::fs::remove_dir_all(&dir);
    let waves = format!("{text}waveforms = {{ dir = {dir:?}, scopes = [\"stack_engine\", \"results\"], cycles = [10, 100000] }}\n");
    let s = Scene::parse(&waves, "t").unwrap();
    let run = Prepared::new(&s, |spec| {
        collision_chip::mesh::resolve(spec).map_err(|e| e.to_string())
    })
    .unwrap()
    .run(|| ())
    .unwrap();
    assert_eq!(run.activity.vcd_files, 4);
    let vcd = std::fs::read_to_string(dir.join("pose2.vcd")).unwrap();
    assert!(
        vcd.contains("$scope module stack_engine $end")
            && !vcd.contains("$scope module dop_unit $end"),
        "{vcd}"
    );
    assert!(
        vcd.contains("#10\n") && !vcd.contains("#9\n"),
        "the window starts at cycle 10"
    );
    let c = run.records[2].cycles.as_ref().unwrap();
    assert!(c.cycles < 100_000 && c.vcd.is_some());
    let mut shown: Vec<_> = (common::vcd_file::vcd_results(&dir.join("pose2.vcd")).iter())
        .map(|r| (r.1, r.2, r.3))
        .collect();
    let mut want: Vec<_> = (c.hit_pairs.iter().map(|p| (p.0, p.1, false)))
        .chain(c.uncertain_pairs.iter().map(|p| (p.0, p.1, true)))
        .collect();
    shown.sort();
    want.sort();
    assert!(
        !shown.is_empty() && shown == want,
        "the VCD's results {shown:?}, the run's {want:?}"
    );
    // a cross-check of a k its RTL is not built for is refused before anything runs
    let k14 = text.replace("preset = \"wscg03\"\n", "preset = \"wscg03\"\nk = 14\n");
    let s = Scene::parse(&format!("{k14}cross_check = \"rtl\"\n"), "t").unwrap();
    let e = Prepared::new(&s, |spec| {
        collision_chip::mesh::resolve(spec).map_err(|e| e.to_string())
    })
    .err()
    .expect("refused");
    assert!(
        e.contains("WSCG'03's RTL chip is binary32 with k = 24") && e.contains("k = 14"),
        "{e}"
    );
}

/// The lists of the list traversal as WSCG'03's Stack Engine makes them (a tumbled group
/// against a list; each member's new list one level down, left first), in order, and the
/// most pointers its SRAMs hold: a list's new lists and those of the lists on the way to
/// it, and the root's pointer (the list SRAMs free a level's lists only when they step up
/// past it).
fn recursion_lists(
    a: &collision_chip::dop::DopTree,
    b: &collision_chip::dop::DopTree,
    overlap: &mut dyn FnMut(u32, u32) -> bool,
) -> (Vec<Vec<u32>>, usize) {
    use collision_chip::dop::Node;
    struct Out {
        lists: Vec<Vec<u32>>,
        most: usize,
    }
    fn rec(
        a: &collision_chip::dop::DopTree,
        b: &collision_chip::dop::DopTree,
        overlap: &mut dyn FnMut(u32, u32) -> bool,
        // held: the pointers of the lists on the way to this one, the root's included
        (group, list, held): (Vec<u32>, Vec<u32>, usize),
        out: &mut Out,
    ) {
        let mut next = vec![vec![]; group.len()];
        for &n in &list {
            for (m, &x) in group.iter().enumerate() {
                if overlap(n, x) {
                    match (a.node(n), b.node(x)) {
                        (Node::Inner(ch), _) => next[m].extend(ch),
                        (Node::Leaf(_), Node::Inner(_)) => next[m].push(n),
                        _ => {}
                    }
                }
            }
        }
        out.lists.push(list);
        let held = held + next.iter().map(Vec::len).sum::<usize>();
        out.most = out.most.max(held);
        for (&x, l) in group.iter().zip(next) {
            if !l.is_empty() {
                let g = match b.node(x) {
                    Node::Inner(ch) => ch.to_vec(),
                    Node::Leaf(_) => vec![x],
                };
                rec(a, b, overlap, (g, l, held), out);
            }
        }
    }
    let mut out = Out {
        lists: vec![],
        most: 1,
    };
    rec(a, b, overlap, (vec![0], vec![0], 1), &mut out);
    (out.lists, out.most)
}

/// The query of two soups under a pose: the chip and its DOP verdicts `overlap(n, x)`.
fn soup_query(
    na: usize,
    nb: usize,
    seed: u64,
    pose: Pose,
) -> (Chip, collision_chip::golden::host::HostSetup) {
    let cfg = ChipConfig::default();
    let chip = Chip::new(
        &soup(na, seed).triangles_f64(),
        &soup(nb, seed + 1).triangles_f64(),
        cfg,
    )
    .unwrap();
    let setup = chip.setup(&pose);
    (chip, setup)
}

/// WSCG'03's Stack Engine's lists (`cycle::wscg03::stack_engine::ListStack`: two SRAMs,
/// the level register, a branch bit and markers per level), driven as the sequencer drives
/// them (`harness::wscg03_io::list_traffic`), give exactly the lists of the recursion, in
/// order, without overflow, and end done: soups of 20 to 300 triangles under poses that
/// overlap. (By hand: lists that took the right list first failed it.)
#[test]
fn stack_engine_lists_follow_the_recursion() {
    use collision_chip::chip::rtl::LIST_SRAM_BITS;
    use collision_chip::harness::wscg03_io::list_traffic;
    let (mut lists, mut clocks) = (0, 0);
    for (n, seed, pose) in [
        (20, 1, Pose::new(10.0, 20.0, 30.0, 0.1, 0.0, 0.0)),
        (120, 3, Pose::new(-35.0, 80.0, 5.0, 0.2, -0.1, 0.05)),
        (300, 5, Pose::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0)),
    ] {
        let (chip, setup) = soup_query(n, n, seed, pose);
        let (a, b) = (&chip.a.tree, &chip.b.tree);
        let cfg = &chip.cfg;
        let mut cache = TransformCache::new(cfg.format.dop, cfg.dop_rounding.op(), &setup, a, b);
        let mut overlap = |n: u32, x: u32| cache.overlap(x, n);
        let (want, _) = recursion_lists(a, b, &mut overlap);
        let tr = list_traffic(LIST_SRAM_BITS, a, b, &mut overlap, 1 << 20);
        let last = tr.outs.last().unwrap();
        assert!(last.done && !last.overflow, "{n} triangles: {last:?}");
        assert_eq!(tr.lists, want, "{n} triangles");
        assert!(want.len() > 3);
        lists += want.len();
        clocks += tr.cmds.len();
    }
    println!("ListStack: {lists} lists in the recursion's order, {clocks} clocks");
}

/// WSCG'03's Stack Engine's lists in RTL (`rtl::wscg03::stack_engine::ListStack`) equal
/// their clocked model on every port every clock, SRAMs of 256 pointers, on
/// `harness::wscg03_io::list_commands` (whole queries of soups of 20 and 120 triangles;
/// after a `clear`, appends past the left SRAM; after another, lists down past the last level), which overflow and end done.
/// (By hand: going down into the right list first failed it at clock 15.)
#[test]
fn stack_engine_lists_rtl_lockstep() {
    use collision_chip::cycle::wscg03::stack_engine::{ListCmd, ListStack};
    use collision_chip::harness::wscg03_io::{
        list_commands, list_outputs, set_list_inputs, LIST_TEST_BITS,
    };
    use collision_chip::rtl::wscg03::stack_engine::list_stack_top;
    use rust_hdl::prelude::*;
    let cmds = list_commands();
    let mut model = ListStack::new(LIST_TEST_BITS);
    let mut uut = list_stack_top::<LIST_TEST_BITS>();
    let mut overflowed = false;
    for (c, cmd) in cmds.iter().enumerate() {
        set_list_inputs(&mut uut, cmd);
        for high in [false, true] {
            uut.clock.next = Clock { clk: high };
            assert!(simulate(&mut uut, 1000), "logic did not settle");
        }
        let want = model.step(cmd);
        assert_eq!(list_outputs(&uut), want, "clock {c}: {cmd:?}");
        overflowed |= want.overflow;
    }
    let last = model.step(&ListCmd::default());
    assert!(overflowed && last.done && last.overflow, "{last:?}");
    println!("ListStack RTL: {} clocks as the model", cmds.len());
}

/// WSCG'03's Triangle Unit's input stage (`cycle::wscg03::tri_unit::ClockedTriInput`),
/// driven as the chip drives it (`harness::wscg03_io::tri_unit::tri_input_traffic`): every
/// pair TRI_UNIT takes carries the words of its leaf pair's ids, in the order offered; only a
/// halt or a start drops one; A's cache and B's two entries save most fetches. The model
/// names words by id, so the words' bits are checked in the RTL lockstep below (against
/// `tri_word`); here, which pair, in what order, and that none is lost.
/// (By hand: B's word taken from entry 1 whatever the entry that matched failed it.)
#[test]
fn triangle_unit_input_stage_keeps_pairs_and_words() {
    use collision_chip::harness::wscg03_io::tri_unit::tri_input_traffic;
    let tr = tri_input_traffic(0x7e1, 20_000);
    let mut next = 0;
    for &(tag, words, c) in &tr.taken {
        let (ids, _) = tr.offered[tag as usize];
        assert_eq!(words, ids.map(Some), "pair {tag}");
        assert!(tag as usize >= next, "pair {tag} after {next}");
        // a pair skipped was dropped by a halt or a start after it was offered
        if tag as usize > next {
            let from = tr.offered[next].1;
            let dropped = tr.ins[from..c].iter().any(|i| i.halt || i.clear);
            assert!(dropped, "pair {next} lost");
        }
        next = tag as usize + 1;
    }
    let fills = tr.ins.iter().filter(|i| i.fill.is_some()).count();
    assert!(tr.taken.len() > 2000, "{} pairs", tr.taken.len());
    assert!(
        fills < tr.taken.len(),
        "{fills} fills for {} pairs",
        tr.taken.len()
    );
    println!(
        "TriInput: {} pairs taken, {fills} words fetched",
        tr.taken.len()
    );
}

/// WSCG'03's Triangle Unit's input stage in RTL (`rtl::b32::TriInput`) equals its clocked
/// model on every port in every clock (before the rising edge: four outputs read `halt` and
/// `tri_ready`) over 3,000 clocks of `tri_input_traffic`.
/// (By hand: a pair register not dropped by `halt` failed it at clock 627.)
#[test]
fn triangle_unit_input_stage_rtl_lockstep() {
    use collision_chip::harness::wscg03_io::tri_unit::{
        set_tri_inputs, tri_input_traffic, tri_outputs_match,
    };
    use rust_hdl::prelude::*;
    let tr = tri_input_traffic(0x7e1, 3000);
    let mut uut = collision_chip::rtl::b32::tri_input_top();
    for (c, (i, o)) in tr.ins.iter().zip(&tr.outs).enumerate() {
        set_tri_inputs(&mut uut, i);
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 1000), "logic did not settle");
        assert!(tri_outputs_match(&uut, o), "clock {c}: {i:?} -> {o:?}");
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 1000), "logic did not settle");
    }
    println!("TriInput RTL: {} clocks as the model", tr.ins.len());
}

/// WSCG'03's chip clocked register by register (`cycle::wscg03::clocked`: the sequencer
/// around the lists, the Memory Controller reading a node pair per burst, the clocked DOP
/// Unit, Triangle Unit input stage and TRI_UNIT) answers as the golden list traversal in
/// all-pairs and first-hit mode, with as many DOP tests and lists, on soups of 1 to 300
/// triangles under poses that overlap and that do not, and on the teapot against itself;
/// all pairs, its list SRAMs hold at most as many pointers as the recursion's lists need
/// at once, and its count of tumbled DOPs transformed is the load bundles' over three.
/// (By hand: a list's group taken from the left member one level up, whatever its branch,
/// failed it on the soups of 20 and 30.)
#[test]
fn clocked_chip_answers_as_the_golden_list_traversal() {
    use collision_chip::cycle::wscg03::clocked;
    let mut queries = 0;
    for (n, m, seed, pose) in [
        (1, 1, 1, Pose::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0)),
        (20, 30, 1, Pose::new(10.0, 20.0, 30.0, 0.1, 0.0, 0.0)),
        (120, 80, 3, Pose::new(-35.0, 80.0, 5.0, 0.2, -0.1, 0.05)),
        (300, 300, 5, Pose::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0)),
        (60, 200, 7, Pose::new(90.0, 0.0, 45.0, 0.3, 0.3, 0.3)),
        (100, 100, 9, Pose::new(0.0, 0.0, 0.0, 3.0, 0.0, 0.0)),
    ] {
        let (chip, setup) = soup_query(n, m, seed, pose);
        let golden = chip.query(&pose, Mode::All, Traversal::List);
        for first in [false, true] {
            let mode = if first { Mode::First } else { Mode::All };
            let run = clocked::run(
                &chip,
                &setup,
                (first, &Params::RTL),
                MAX_CYCLES,
                |_, _, _| {},
                None,
            )
            .unwrap();
            let tr = &run.trace;
            assert!(
                tr.check(mode, &golden).is_ok(),
                "{n}/{m} {mode:?}: {:?}",
                tr.check(mode, &golden)
            );
            if !first {
                let g = golden.counters;
                assert_eq!(
                    (tr.dop_tests, tr.tri_tests, run.lists),
                    (g.dop_tests, g.tri_tests, g.lists),
                    "{n}/{m}"
                );
                let (a, b, cfg) = (&chip.a.tree, &chip.b.tree, &chip.cfg);
                let op = cfg.dop_rounding.op();
                let mut cache = TransformCache::new(cfg.format.dop, op, &setup, a, b);
                let (_, most) = recursion_lists(a, b, &mut |n, x| cache.overlap(x, n));
                assert_eq!(run.max_pointers, most as u64, "{n}/{m}: pointers held");
                // a tumbled DOP streams in three bundles (k = 24, binary32, 256 bits)
                assert_eq!(run.booked.load, 3 * run.transforms, "{n}/{m}: transforms");
            }
            assert_eq!(
                run.booked.total(),
                tr.cycles,
                "{n}/{m}: every clock booked once"
            );
            println!("{n}/{m} {mode:?}: {} clocks, {} results, {} lists, {} node records, {} triangle words", tr.cycles, tr.results.len(), run.lists, tr.node_fetches, tr.tri_fetches);
            queries += 1;
        }
    }
    // a vendored mesh against itself
    let mesh = |s: &str| collision_chip::mesh::resolve(s).unwrap().triangles_f64();
    let chip = Chip::new(
        &mesh("vectors/meshes/teapot.obj"),
        &mesh("vectors/meshes/teapot.obj"),
        ChipConfig::default(),
    )
    .unwrap();
    for pose in [
        Pose::new(10.0, 20.0, 30.0, 0.05, 0.0, 0.0),
        Pose::new(0.0, 90.0, 0.0, 0.0, 0.2, 0.0),
    ] {
        let setup = chip.setup(&pose);
        let golden = chip.query(&pose, Mode::All, Traversal::List);
        for first in [false, true] {
            let mode = if first { Mode::First } else { Mode::All };
            let run = clocked::run(
                &chip,
                &setup,
                (first, &Params::RTL),
                MAX_CYCLES,
                |_, _, _| {},
                None,
            )
            .unwrap();
            assert!(
                run.trace.check(mode, &golden).is_ok(),
                "teapot/teapot {mode:?}: {:?}",
                run.trace.check(mode, &golden)
            );
            // beside it, the event model's clocks and node fetches (a node word a request)
            let sp = StackParams::default();
            let ev = run_query(&chip, &setup, mode, &Params::RTL, &sp, MAX_CYCLES).unwrap();
            println!(
                "teapot/teapot {mode:?}: {} clocks, {} results, {} lists, {} node records; event model {} clocks, {} node words",
                run.trace.cycles,
                run.trace.results.len(),
                run.lists,
                run.trace.node_fetches,
                ev.trace.cycles,
                ev.trace.node_fetches
            );
            let (b, s) = (run.booked, ev.stats);
            assert_eq!(b.total(), run.trace.cycles);
            println!(
                "  clocks to compare / load / memory / transform / list / drain: {} / {} / {} / {} / {} / {}; event model's compare / memory / transform / list / drain: {} / {} / {} / {} / {}",
                b.compare, b.load, b.memory, b.transform, b.list, b.drain,
                s.compare, s.stall_memory, s.stall_transform, s.stall_list, s.drain
            );
            queries += 1;
        }
    }
    assert_eq!(queries, 16);
}

/// WSCG'03's Memory Controller in RTL (`rtl::b32::MemoryController`) equals its clocked
/// model on every port every clock, driven with the inputs the clocked chip gave it in two
/// whole queries (all pairs and first hit, a `clear` before each) on a memory of 5 clocks'
/// latency and 4 requests outstanding; the traffic is checked to reach every path (A's and
/// B's triangle words, pairs and leaves loaded, siblings sharing a record, busy sets, a
/// halt). (By hand: an aligned sibling that fetched its record again failed it.)
#[test]
fn memory_controller_rtl_lockstep() {
    use collision_chip::harness::wscg03_io::memory_controller::{mc_clocks, mc_lockstep};
    let tr = collision_chip::harness::wscg03_io::traffic();
    // the traffic reaches every path: triangle words, pairs and leaves loaded, aligned
    // siblings sharing a record, waits for a busy set, a halt
    let cs = mc_clocks(&tr);
    let count =
        |f: &dyn Fn(&collision_chip::harness::wscg03_io::memory_controller::McClock) -> bool| {
            cs.iter().filter(|c| f(c)).count()
        };
    // aligned asks whose record is the aligned ask's before them (no load between)
    use collision_chip::cycle::wscg03::memory_controller::Ask;
    let mut last = None;
    let shared = cs
        .iter()
        .filter_map(|c| c.i.push)
        .filter(|&a| {
            let same = matches!(a, Ask::Aligned { id, .. } if last == Some(id >> 1));
            last = match a {
                Ask::Aligned { id, .. } => Some(id >> 1),
                Ask::Load { .. } => None,
            };
            same
        })
        .count();
    let coverage = [
        count(&|c| c.o.fill.is_some_and(|f| !f.0)),
        count(&|c| c.o.fill.is_some_and(|f| f.0)),
        count(&|c| c.o.loaded.as_ref().is_some_and(|l| l.1.len() == 2)),
        count(&|c| c.o.loaded.as_ref().is_some_and(|l| l.1.len() == 1)),
        shared,
        count(&|c| c.i.busy != [false, false] && c.room < 8 && c.o.dop_in == Default::default()),
        count(&|c| c.i.halt),
    ];
    assert!(coverage.iter().all(|&n| n > 0), "{coverage:?}");
    let clocks = mc_lockstep(&tr).unwrap();
    println!("MemoryController RTL: {clocks} clocks as the model; coverage {coverage:?}");
}

/// WSCG'03's Stack Engine's sequencer in RTL (`rtl::wscg03::sequencer::Sequencer`) equals
/// its clocked model on every port every clock, driven with the inputs the clocked chip
/// gave it in the Memory Controller's two whole queries; the traffic is checked to reach
/// every path (lists entered on a held set and on a load, speculative loads, leaf pairs
/// offered and taken or refused, flags on both members, a halt).
#[test]
fn sequencer_rtl_lockstep() {
    use collision_chip::cycle::wscg03::memory_controller::Ask;
    use collision_chip::harness::wscg03_io::sequencer::{seq_clocks, seq_lockstep, SeqClock};
    let tr = collision_chip::harness::wscg03_io::traffic();
    let cs = seq_clocks(&tr);
    let count = |f: &dyn Fn(&SeqClock) -> bool| cs.iter().filter(|c| f(c)).count();
    let entered: Vec<_> = cs.windows(2).map(|w| w[1].lists > w[0].lists).collect();
    let loads = |c: &SeqClock| matches!(c.ask, Some(Ask::Load { .. }));
    let coverage = [
        entered
            .iter()
            .zip(&cs)
            .filter(|(&e, c)| e && !loads(c))
            .count(),
        entered
            .iter()
            .zip(&cs)
            .filter(|(&e, c)| e && loads(c))
            .count(),
        entered
            .iter()
            .zip(&cs)
            .filter(|(&e, c)| !e && loads(c))
            .count(),
        count(&|c| c.offer.is_some() && c.i.leaf_ready),
        count(&|c| c.offer.is_some() && !c.i.leaf_ready),
        count(&|c| c.i.flags_valid && c.i.overlap == [true, true]),
        count(&|c| c.i.halt && !c.clear),
    ];
    assert!(coverage.iter().all(|&n| n > 0), "{coverage:?}");
    let clocks = seq_lockstep(&tr).unwrap();
    println!("Sequencer RTL: {clocks} clocks as the model; coverage {coverage:?}");
}

/// WSCG'03's chip core in RTL (`rtl::wscg03::chip::ChipCore`: the Stack Engine, the Memory
/// Controller, the DOP Unit and the Triangle Unit's input stage joined, with the host
/// registers, `start` and the counters) equals the clocked chip on every port every clock
/// of the Memory Controller's two whole queries, from the DOP Unit's setup words on, with
/// TRI_UNIT's side (`in_ready`, a sure verdict, no pair open) as the model's.
#[test]
fn chip_core_rtl_lockstep() {
    use collision_chip::harness::wscg03_io::chip_core::core_lockstep;
    let clocks = std::thread::Builder::new()
        .stack_size(512 << 20)
        .spawn(|| core_lockstep(&collision_chip::harness::wscg03_io::traffic()))
        .unwrap()
        .join()
        .unwrap()
        .unwrap();
    println!("ChipCore RTL: {clocks} clocks as the clocked chip");
}

/// The clocked chip reads its records in order (base + record): a host write of a record
/// map (DATE'05's `MAP`, for records spread over DDR banks) is its fault, not a silent
/// wrong address.
#[test]
fn clocked_chip_refuses_a_record_map() {
    use collision_chip::chip::ports::{ChipIn, Clocked};
    use collision_chip::cycle::wscg03::clocked;
    let pose = Pose::new(5.0, 10.0, 0.0, 0.3, 0.2, 0.1);
    let (chip, setup) = soup_query(10, 10, 1, pose);
    let img = clocked::images(&chip);
    let mut c = clocked::Chip::new(&chip, &img, &setup, &Params::RTL).unwrap();
    let map = ChipIn {
        host_we: true,
        host_addr: collision_chip::chip::reg::MAP,
        host_data: 0x21,
        ..ChipIn::default()
    };
    assert_eq!(c.fault(), None);
    c.step(&map, false);
    assert!(c.fault().is_some_and(|f| f.contains("record map")));
}

/// WSCG'03's whole chip in RTL (`rtl::wscg03::chip::CollisionChip`: the core, TRI_UNIT
/// and the result port, behind DATE'05's ports) equals the clocked chip on every output
/// every clock of three queries, driven by DATE'05's driver from the memory image (real
/// triangle words) and with the setup words on the host port: a bunny patch against
/// itself (every pair tested uncertain, results back-pressuring TRI_UNIT), intersecting
/// pairs of all pairs, and a first hit that halts the query. Every traversal signal too
/// (`chip::probes::WSCG03`): the first query's VCD, target/rtl-vcd/chip_wscg03_patch_all.vcd
/// from rust-hdl, shows the trace's results and every signal of its GTKWave save file.
#[test]
fn chip_rtl_lockstep() {
    use collision_chip::chip::memory::{MemTiming, Memory};
    use collision_chip::harness::chip_io::query_mesh;
    use collision_chip::harness::wscg03_io::chip::cross_check;
    let p = Params {
        outstanding: 4,
        memory: Memory::Ideal(MemTiming {
            latency: 5,
            interval: 1,
            bus_bits: None,
        }),
        ..Params::RTL
    };
    let cfg = ChipConfig {
        layout: collision_chip::chip::config::MemLayout::Records,
        ..ChipConfig::default()
    };
    let moved = Pose::new(0.0, 0.0, 0.0, 0.5, 0.2, 0.1);
    let vcd = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("target/rtl-vcd/chip_wscg03_patch_all.vcd");
    for (mesh, pose, first) in [
        ("bunny-patch:12", Pose::default(), false),
        ("bunny-patch:24", moved, false),
        ("bunny-patch:24", moved, true),
    ] {
        let t0 = std::time::Instant::now();
        let tris = query_mesh(mesh).unwrap();
        let chip = Chip::new(&tris, &tris, cfg).unwrap();
        let path = (mesh == "bunny-patch:12").then_some(vcd.as_path());
        let trace = cross_check(&chip, &chip.setup(&pose), (first, &p), 100_000, path).unwrap();
        if path.is_some() {
            assert_eq!(
                common::vcd_file::vcd_results(&vcd),
                trace.results,
                "the VCD's results"
            );
            common::vcd_file::assert_shows(&vcd, WSCG03.gtkw);
            println!("wrote {}", vcd.display());
        }
        let uncertain = trace.results.iter().filter(|r| r.3).count();
        println!(
            "WSCG'03 chip RTL, {mesh}, first hit {first}: {} clocks, {} pairs tested, {} results ({uncertain} uncertain) as the clocked chip ({:.0?})",
            trace.cycles,
            trace.tri_tests,
            trace.results.len(),
            t0.elapsed()
        );
        assert!(!trace.results.is_empty());
    }
}

/// WSCG'03's queries of the RTL set (`harness::chip_io::queries`, architecture wscg03):
/// the clocked chip, driven as the Verilog testbench drives `rtl/chip_wscg03_b32_k24.v`,
/// finds the golden pairs and gives the checked-in trace (vectors/chip/<query>.expect, each
/// agreed by the exported Verilog under Verilator). Writes each query's memory requests to
/// target/chip-expect/ for scripts/run-chip.sh, and with `CCHIP_BLESS=1` its trace there
/// (`scripts/run-chip.sh --bless` copies it only where Verilator agrees).
#[test]
fn wscg03_checked_in_traces() {
    use collision_chip::chip::wscg03::Architecture;
    use collision_chip::harness::chip_io::queries;
    use collision_chip::harness::wscg03_io::chip::model_trace;
    let bless = std::env::var("CCHIP_BLESS").is_ok_and(|v| v == "1");
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let out = root.join("target/chip-expect");
    std::fs::create_dir_all(&out).unwrap();
    let w3: Vec<_> = queries()
        .into_iter()
        .filter(|q| q.architecture == Architecture::Wscg03)
        .collect();
    assert!(w3.len() >= 4);
    for q in w3 {
        let p = q.prepare().unwrap();
        let (tr, reqs) = model_trace(&q, &p, 5_000_000).unwrap();
        tr.check(q.mode, &p.golden_all)
            .unwrap_or_else(|e| panic!("{}: {e}", q.name));
        let (hits, unc) = tr.pairs();
        println!(
            "{}: {} clocks, {} sure hits, {} uncertain",
            q.name,
            tr.cycles,
            hits.len(),
            unc.len()
        );
        let expect = format!("{}.expect", q.name);
        if bless {
            std::fs::write(out.join(&expect), tr.text()).unwrap();
        } else {
            let path = root.join("vectors/chip").join(&expect);
            let want = std::fs::read_to_string(&path)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            assert_eq!(
                tr.text(),
                want,
                "{}: the clocked chip's trace differs",
                q.name
            );
        }
        std::fs::write(out.join(format!("{}.requests", q.name)), reqs).unwrap();
    }
}

/// WSCG'03's chip as scenes run it (the `wscg03` preset: clocked as its RTL on its DDR
/// SDRAM) on every vendored mesh, scaled into the unit cube, in contact: its pairs are the
/// golden list traversal's in all-pairs and first-hit mode (the run's golden check fails
/// the run otherwise), and in all-pairs mode the exact oracle's.
#[test]
fn wscg03s_chip_on_every_vendored_mesh() {
    use collision_chip::scene::{run::Prepared, Scene};
    for (a, b, d) in [
        ("bunny", "bunny", 1.4),
        ("teapot", "teapot", 1.4),
        ("dragon-11k", "dragon-11k", 1.4),
        ("bunny", "dragon-11k", 1.4),
    ] {
        for mode in ["all", "first"] {
            let text = format!("[objects]\na = \"{a}\"\nb = \"{b}\"\nunit_cube = true\n[chip]\npreset = \"wscg03\"\n[query]\nmode = \"{mode}\"\ntraversal = \"list\"\n[sweep]\ndistances = [{d}]\norientations = 1\nseed = 3\n[outputs]\naccuracy = true\ncycles = true\n");
            let s = Scene::parse(&text, "test").unwrap();
            let run = Prepared::new(&s, |spec| {
                let m = collision_chip::mesh::resolve(spec).map_err(|e| e.to_string())?;
                m.scaled_into_unit_cube().map_err(|e| e.to_string())
            })
            .unwrap()
            .run(|| ())
            .unwrap_or_else(|e| panic!("{a}/{b} {mode}: {e}"));
            for r in &run.records {
                let c = r.cycles.as_ref().unwrap();
                if mode == "all" {
                    let acc = r.accuracy.as_ref().unwrap();
                    assert_eq!((acc.misses, acc.extras), (0, 0), "{a}/{b}");
                }
                println!(
                    "{a}/{b} {mode}: {} clocks, {} pairs",
                    c.cycles, r.pair_count
                );
                assert!(r.pair_count > 0, "{a}/{b} at {d}: in contact");
            }
        }
    }
}
