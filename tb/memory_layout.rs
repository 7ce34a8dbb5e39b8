//! The memory image's two layouts (`chip::config::MemLayout`) on the default scene's bunnies:
//! the chip's answers do not depend on the layout (golden and cycle model, both layouts, the
//! papers' DDR memories), and the golden model's record fetches are the cycle model's. The
//! reuse study of node records is an ignored test that prints its table:
//! `cargo test --release --test memory_layout -- --ignored --nocapture`.

use collision_chip::chip::config::ChipConfig;
use collision_chip::chip::config::MemLayout;
use collision_chip::chip::layout::Dst;
use collision_chip::chip::preset::Preset;
use collision_chip::chip::probes::DATE05;
use collision_chip::chip::reg::{Mode, Order};
use collision_chip::cycle;
use collision_chip::cycle::drive::Reader;
use collision_chip::mesh;
use collision_chip::pose::Pose;
use collision_chip::query::Chip;
use collision_chip::scene::Scene;
use collision_chip::traversal::Traversal;
use std::path::Path;

/// The bunnies of the default scene and its poses at distance `d`, on its chip with `layout`
/// and `node_cache` records held per object.
fn bunnies(layout: MemLayout, node_cache: u32, d: f64) -> (Chip, Vec<Pose>) {
    let s = Scene::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/scenes/default.toml"))
        .unwrap();
    let m = mesh::resolve("bunny")
        .unwrap()
        .scaled_into_unit_cube()
        .unwrap()
        .triangles_f64();
    let cfg = ChipConfig {
        layout,
        node_cache,
        ..s.cfg
    };
    let chip = Chip::new(&m, &m, cfg).unwrap();
    (
        chip,
        s.poses
            .iter()
            .filter(|p| p.distance == Some(d))
            .map(|p| p.pose)
            .collect(),
    )
}

/// Under both layouts and on both papers' memories: the golden answers are the same, the
/// cycle model's sure hits and uncertain pairs are the golden model's, and in FIFO order the
/// golden model's node and triangle record fetches are the cycle model's.
#[test]
fn answers_do_not_depend_on_the_layout() {
    let [(words, poses), (records, _)] =
        [MemLayout::Words, MemLayout::Records].map(|l| bunnies(l, 16, 1.0));
    for pose in &poses[..2] {
        let golden = words.query(pose, Mode::All, Traversal::Lifo);
        assert!(golden.pairs.len() > 10, "an overlapping pose");
        for chip in [&words, &records] {
            for preset in [Preset::Date05, Preset::Wscg03] {
                for (order, traversal) in [
                    (Order::Lifo, Traversal::Lifo),
                    (Order::Fifo, Traversal::Fifo),
                ] {
                    let g = chip.query(pose, Mode::All, traversal);
                    assert_eq!((&g.pairs, &g.uncertain), (&golden.pairs, &golden.uncertain));
                    let p = preset.params();
                    let rec = cycle::Record::default();
                    let (tr, _) = cycle::run_query(
                        chip,
                        &chip.setup(pose),
                        order,
                        Mode::All,
                        p,
                        Reader::default(),
                        1 << 40,
                        rec,
                    )
                    .unwrap();
                    let (hits, unc) = tr.pairs();
                    assert_eq!(unc, golden.uncertain);
                    let mut found: Vec<_> = hits
                        .iter()
                        .chain(unc.iter().filter(|u| golden.pairs.contains(u)))
                        .copied()
                        .collect();
                    found.sort_unstable();
                    assert_eq!(
                        found, golden.pairs,
                        "{:?} {preset:?} {order:?}",
                        chip.cfg.layout
                    );
                    if order == Order::Fifo {
                        assert_eq!(
                            (tr.node_fetches, tr.tri_fetches),
                            (g.counters.node_fetches, g.counters.tri_fetches)
                        );
                    }
                }
            }
        }
        // sibling records: about half the fetches of node words
        let [w, r] = [&words, &records].map(|c| {
            c.query(pose, Mode::All, Traversal::Lifo)
                .counters
                .node_fetches
        });
        assert!(r * 10 < w * 6, "{r} node records against {w} node words");
    }
}

/// Reuse distance of the node records the port fetches (after the one record held per
/// side): for each fetch of a record on one side, the number of distinct records of that
/// side fetched since its last fetch (LRU stack distance; a first fetch has none). An LRU
/// cache of c records per side would have served every fetch at a distance below c.
#[test]
#[ignore]
fn reuse_distance_of_node_records() {
    let at = |name: &str| DATE05.signals.iter().position(|p| p.1 == name).unwrap();
    let (valid, ready, addr, dst) = (
        at("req_valid"),
        at("req_ready"),
        at("req_addr"),
        at("req_dst"),
    );
    let sizes = [2, 4, 8, 16, 32, 64, 256];
    println!("| preset | pose distance | node record fetches | first fetches | served by an LRU cache of {sizes:?} records per side |");
    for preset in [Preset::Date05, Preset::Wscg03] {
        for d in [1.4, 1.0, 0.6] {
            let (chip, poses) = bunnies(MemLayout::Records, 1, d);
            let (mut fetches, mut first, mut served) = (0u64, 0u64, [0u64; 7]);
            for pose in &poses {
                let mut stacks: [Vec<u64>; 2] = Default::default();
                let mut obs = |_: u64, v: &[u64]| {
                    let side = v[dst] as usize;
                    if v[valid] == 1 && v[ready] == 1 && side <= Dst::NodeB as usize {
                        fetches += 1;
                        let s = &mut stacks[side];
                        match s.iter().rposition(|&a| a == v[addr]) {
                            Some(i) => {
                                let dist = s.len() - 1 - i;
                                sizes
                                    .iter()
                                    .zip(&mut served)
                                    .filter(|(&c, _)| dist < c)
                                    .for_each(|(_, n)| *n += 1);
                                s.remove(i);
                            }
                            None => first += 1,
                        }
                        s.push(v[addr]);
                    }
                    Ok(())
                };
                let rec = cycle::Record {
                    probes: Some(&mut obs),
                    ..Default::default()
                };
                cycle::run_query(
                    &chip,
                    &chip.setup(pose),
                    Order::Lifo,
                    Mode::All,
                    preset.params(),
                    Reader::default(),
                    1 << 40,
                    rec,
                )
                .unwrap();
            }
            let pct: Vec<String> = served
                .iter()
                .map(|&n| format!("{:.0}%", 100.0 * n as f64 / fetches as f64))
                .collect();
            println!(
                "| {} | {d} | {fetches} | {first} | {} |",
                preset.name(),
                pct.join(" ")
            );
        }
    }
}

/// The papers' presets lay the image out for the bus and hold 16 node records per object;
/// the RTL's keeps the words and one; a scene's key overrides its preset's.
#[test]
fn presets_lay_out_for_the_bus() {
    let (d, r) = (Preset::Date05.chip(), Preset::Rtl.chip());
    assert_eq!(
        (d.layout, d.node_cache, Preset::Wscg03.chip().layout),
        (MemLayout::Records, 16, MemLayout::Records)
    );
    assert_eq!((r.layout, r.node_cache), (MemLayout::Words, 1));
    let text = "[objects]\na = \"sphere:8\"\nb = \"sphere:8\"\n[chip]\npreset = \"date05\"\nlayout = \"words\"\n[[pose]]\nrot_deg = [0, 0, 0]\nt = [0, 0, 0]\n";
    let s = Scene::parse(text, "s").unwrap();
    assert_eq!((s.cfg.layout, s.cfg.node_cache), (MemLayout::Words, 16));
    let e = Scene::parse(&text.replace("\"words\"", "\"pairs\""), "s").unwrap_err();
    assert!(
        e.contains("s:6") && e.contains("`words` or `records`"),
        "{e}"
    );
}

/// The presets' values, literal, each from the paper or derived here by hand (not from the
/// constants `preset.rs` is written with).
#[test]
fn presets_are_the_papers_values() {
    use collision_chip::chip::config::{DopBits, DopRounding, Formats};
    use collision_chip::chip::memory::{Ddr, MemTiming, Memory};
    use collision_chip::chip::params::Params;
    use collision_chip::format::{Format, Rounding};
    // WSCG'03 §4.3 and §4.5: "four standard 64-bit modules ... for a 256-bit data bus", "a total page size
    // across all modules of 4KBytes", "four internal banks", node pairs loaded "in a
    // double-data-rate burst transfer of length eight", "a page miss access to a node pair
    // to consume 20 clock cycles, a page hit to consume only 8 cycles"; the chip "clocked at
    // 266MHz"; "a direct mapped cache with 128 lines" for A's triangles. In ns: 133 MHz
    // DDR moves a beat every 7.5 / 2 ns; the paper's 8 and 20 clocks of its 266 MHz chip
    // (the burst rate) are 8 and 20 beats.
    let wscg03 = Ddr {
        banks: 4,
        page_bytes: 4096,
        bus_bits: 256,
        burst: 8,
        beat_ps: 7500 / 2,
        hit_ps: 8 * 3750,
        miss_ps: 20 * 3750,
    };
    assert_eq!(Ddr::WSCG03, wscg03);
    let clocks = |d: Ddr, ps| {
        let c = d.at(ps).unwrap();
        (c.burst_clocks, c.hit, c.miss)
    };
    assert_eq!(clocks(wscg03, Preset::Wscg03.clock_ps()), (8, 8, 20));
    // DATE'05 §4.1 gives "a 756-bit wide bus from the DDR2-RAM" and an 800 MHz target. The
    // rest is our assumption, DDR2-800 at 5-5-5 (CL = tRCD = tRP = 5 memory clocks, 12.5 ns)
    // a beat every 1.25 ns (800 MT/s): 8 banks of 8 KiB pages, bursts of 4 beats (5 ns); a
    // hit CL + burst = 12.5 + 5 ns, a miss tRP + tRCD + hit = 12.5 + 12.5 + 17.5 ns. At the
    // paper's 800 MHz, the data rate: 4, 14 and 34 clocks.
    let date05 = Ddr {
        banks: 8,
        page_bytes: 8192,
        bus_bits: 756,
        burst: 4,
        beat_ps: 1250,
        hit_ps: 12_500 + 4 * 1250,
        miss_ps: 12_500 + 12_500 + 17_500,
    };
    assert_eq!(clocks(date05, Preset::Date05.clock_ps()), (4, 14, 34));
    assert_eq!(Ddr::DATE05, date05);
    assert_eq!(
        (
            Ddr::preset("wscg03"),
            Ddr::preset("date05"),
            Ddr::preset("ddr")
        ),
        (Some(wscg03), Some(date05), None)
    );

    // Both papers' chips: DATE'05's "we chose to use 24-DOPs", of "single-precision
    // floating-point numbers", the DOP test rounded outward (never a
    // false "separated"), T.CHECK to nearest; records laid out for the bus, 16 held per object,
    // their DOPs stored in full.
    let papers = ChipConfig {
        k: 24,
        format: Formats::from(Format::BINARY32),
        dop_rounding: DopRounding::Outward,
        tri_rounding: Rounding::NearestEven,
        tri_cache: 1,
        tri_cache_b: 1,
        layout: MemLayout::Records,
        node_cache: 16,
        dop_bits: DopBits::Full,
    };
    assert_eq!(Preset::Date05.chip(), papers);
    assert_eq!(
        Preset::Wscg03.chip(),
        ChipConfig {
            tri_cache: 128,
            ..papers
        }
    );
    assert_eq!(
        Preset::Rtl.chip(),
        ChipConfig {
            layout: MemLayout::Words,
            node_cache: 1,
            ..papers
        }
    );
    // the memory port at full speed: an issue every clock, register `reg::PORT`'s most requests
    // outstanding (16) and pairs prefetched (14), a credit of 48; the RTL's reset point
    // otherwise (tb/cycle_chip.rs: `rtl_point_is_the_rtl`)
    let full = |memory, clock_ps| Params {
        issue_spacing: 1,
        outstanding: 16,
        prefetch: 14,
        credit: 48,
        memory,
        clock_ps,
        ..Params::RTL
    };
    // the papers' clocks, 1.25 ns and 1 / 266 MHz to the picosecond
    assert_eq!(Preset::Date05.params(), full(Memory::Ddr(date05), 1250));
    assert_eq!(Preset::Wscg03.params(), full(Memory::Ddr(wscg03), 3759));
    assert_eq!(
        Preset::Rtl.params(),
        Params {
            memory: Memory::Ideal(MemTiming {
                latency: 1,
                interval: 1,
                bus_bits: None
            }),
            ..Params::RTL
        }
    );
    assert_eq!(
        [Preset::Date05, Preset::Wscg03, Preset::Rtl].map(Preset::clock_mhz),
        [800.0, 266.0, 800.0]
    );
}
