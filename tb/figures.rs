//! `cchip figures` on a small plan: every file is written, the CSV has the columns the
//! docs read, and the data obey what must hold whatever the timing (LIFO and FIFO find
//! the same pairs, as do the list and recursive traversals; Algorithm 1 never transforms
//! less than Algorithm 2); each chip runs on its preset at its configuration's period, and
//! its times add up (end to end = host setup + clocks x period + host settling). The
//! counts are the golden model's, queried here pose by pose, and follow what the papers
//! report: more pairs, fetches and transforms as the copies close in, LIFO's queue far
//! smaller than FIFO's (DATE'05 Fig. 7), the first hit no later with LIFO (Fig. 6b).

use collision_chip::chip::config::{ChipConfig, DopBits, DopRounding};
use collision_chip::chip::preset::Preset;
use collision_chip::chip::reg::Mode;
use collision_chip::chip::timing::{Folds, Technology};
use collision_chip::format::Format;
use collision_chip::pose::{sweep_poses, Sweep};
use collision_chip::query::Chip;
use collision_chip::report::accuracy;
use collision_chip::report::figures::{generate, Plan};
use collision_chip::report::plot::Cell;
use collision_chip::traversal::{Counters, Traversal};
use std::collections::HashMap;

fn csv(path: &std::path::Path) -> (Vec<String>, Vec<HashMap<String, String>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let cols: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| {
            cols.iter()
                .cloned()
                .zip(l.split(',').map(String::from))
                .collect()
        })
        .collect();
    (cols, rows)
}

fn num(r: &HashMap<String, String>, c: &str) -> f64 {
    r[c].parse()
        .unwrap_or_else(|_| panic!("{c} = {:?} is not a number", r[c]))
}

/// The measured clock period of an RTL chip in the timing study's table: `chip_b32_k24`,
/// DATE'05's chip of the papers' configuration (k = 24, binary32), or `chip_wscg03_b32_k24`,
/// WSCG'03's.
fn period_ns(chip: &str) -> f64 {
    let (cols, rows) =
        csv(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/figures/timing.csv"));
    assert!(cols.iter().any(|c| c == "min_period_ns"));
    num(
        rows.iter()
            .find(|r| r["unit"] == chip)
            .expect("a row of the chip"),
        "min_period_ns",
    )
}

/// A golden query's counts, as the figures' tables give them (means over a distance's poses).
#[derive(Clone, Copy, Debug, Default)]
struct Means {
    pairs: f64,
    dop_tests: f64,
    node_fetches: f64,
    dop_transforms: f64,
}

/// The golden model's counts on `plan`'s poses, queried here one by one, mean per distance:
/// [distance][traversal: LIFO, FIFO, list, recursive][mode: all, first].
fn golden_means(plan: &Plan, cfg: ChipConfig) -> Vec<[[Means; 2]; 4]> {
    let tris = collision_chip::mesh::resolve(&plan.meshes[0])
        .unwrap()
        .scaled_into_unit_cube()
        .unwrap()
        .triangles_f64();
    let chip = Chip::new(&tris, &tris, cfg).unwrap();
    let poses = sweep_poses(&Sweep {
        distances: plan.distances.clone(),
        orientations: plan.orientations,
        seed: plan.seed,
    })
    .unwrap();
    let n = plan.orientations as f64;
    poses
        .chunks(plan.orientations)
        .map(|group| {
            [
                Traversal::Lifo,
                Traversal::Fifo,
                Traversal::List,
                Traversal::Recursive,
            ]
            .map(|t| {
                [Mode::All, Mode::First].map(|m| {
                    let mut s = Means::default();
                    for sp in group {
                        let r = chip.query(&sp.pose, m, t);
                        let c: Counters = r.counters;
                        s.pairs += r.pairs.len() as f64 / n;
                        s.dop_tests += c.dop_tests as f64 / n;
                        s.node_fetches += c.node_fetches as f64 / n;
                        s.dop_transforms += c.dop_transforms as f64 / n;
                    }
                    s
                })
            })
        })
        .collect()
}

#[test]
fn figures_data_hold_what_the_papers_compare() {
    let out = std::env::temp_dir().join(format!("cchip-figures-test-{}", std::process::id()));
    let plan = Plan {
        meshes: vec!["teapot".into()],
        distances: vec![2.2, 1.4, 1.0],
        orientations: 2,
        seed: 3,
        min_seconds: 0.001,
        preset: None,
        technology: Technology::Osu018,
    };
    let written = generate(&plan, &out, &indicatif::ProgressBar::hidden()).unwrap();
    let stems = [
        "date05_fig6_cycles",
        "date05_fig7_queue",
        "date05_fig8_speedup",
        "wscg03_fig9_first_witness",
        "wscg03_fig10_all_pairs",
        "wscg03_fig11_nodes",
        "wscg03_fig12_transforms",
        "wscg03_fig13_speedup",
        "wscg03_vs_date05",
    ];
    for s in stems {
        for ext in ["svg", "png", "csv", "json"] {
            let p = out.join(format!("{s}.{ext}"));
            assert!(written.contains(&p), "{} not written", p.display());
            assert!(
                std::fs::metadata(&p).unwrap().len() > 100,
                "{} is empty",
                p.display()
            );
        }
    }
    assert!(std::fs::read(out.join("date05_fig6_cycles.png"))
        .unwrap()
        .starts_with(b"\x89PNG"));

    let (cols, fig6) = csv(&out.join("date05_fig6_cycles.csv"));
    assert_eq!(
        cols,
        [
            "mesh",
            "triangles",
            "distance",
            "queries",
            "order",
            "mode",
            "pairs",
            "cycles",
            "cycles_max",
            "period_ns",
            "chip_us",
            "words"
        ]
    );
    // DATE'05's figures on the date05 preset, at its configuration's measured period
    let period = period_ns("chip_b32_k24");
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1.0);
    for r in &fig6 {
        assert_eq!(num(r, "period_ns"), period, "{r:?}");
        assert!(
            close(
                num(r, "chip_us"),
                num(r, "cycles") * num(r, "period_ns") / 1000.0
            ),
            "{r:?}"
        );
    }
    // the counts: the golden model's, pose by pose (the date05 chip's for Figs. 6-7, the
    // software's for Figs. 9-12)
    let date = golden_means(&plan, Preset::Date05.chip());
    let soft = golden_means(&plan, ChipConfig::default());
    let at = |r: &HashMap<String, String>| {
        plan.distances
            .iter()
            .position(|&d| d == num(r, "distance"))
            .expect("a distance of the plan")
    };
    let traversal = |r: &HashMap<String, String>, c: &str| {
        ["lifo", "fifo", "list", "recursive"]
            .iter()
            .position(|t| *t == r[c])
            .unwrap()
    };
    let mode = |r: &HashMap<String, String>| {
        ["all", "first"]
            .iter()
            .position(|m| *m == r["mode"])
            .unwrap()
    };
    for r in &fig6 {
        let g = date[at(r)][traversal(r, "order")][mode(r)];
        assert!(close(num(r, "pairs"), g.pairs), "{r:?}: golden {g:?}");
        // one DOP test issued per clock at the most
        assert!(num(r, "cycles") >= g.dop_tests, "{r:?}: golden {g:?}");
    }
    assert_eq!(fig6.len(), 3 * 2 * 2);
    for r in &fig6 {
        let twin = fig6
            .iter()
            .find(|q| {
                q["distance"] == r["distance"] && q["mode"] == r["mode"] && q["order"] != r["order"]
            })
            .unwrap();
        if r["mode"] == "all" {
            assert_eq!(
                r["pairs"], twin["pairs"],
                "LIFO and FIFO pairs differ: {r:?} {twin:?}"
            );
        }
        assert!(num(r, "cycles") > 0.0 && num(r, "cycles") <= num(r, "cycles_max"));
    }
    // apart: no pairs; at 1.0 the copies penetrate; more pairs as they close in
    let pairs = |d: &str| {
        num(
            fig6.iter()
                .find(|r| r["distance"] == d && r["mode"] == "all")
                .unwrap(),
            "pairs",
        )
    };
    assert_eq!(pairs("2.2"), 0.0);
    assert!(pairs("1") > 0.0 && pairs("1") >= pairs("1.4"), "{fig6:?}");
    let row = |t: &[HashMap<String, String>], d: &str, c: &str, o: &str, m: &str| {
        t.iter()
            .find(|r| r["distance"] == d && r[c] == o && r["mode"] == m)
            .unwrap()
            .clone()
    };
    // DATE'05 Fig. 6b: LIFO "far superior to FIFO control when finding the first intersecting primitive"
    for d in ["1.4", "1"] {
        assert!(
            num(&row(&fig6, d, "order", "lifo", "first"), "cycles")
                <= num(&row(&fig6, d, "order", "fifo", "first"), "cycles"),
            "{fig6:?}"
        );
    }

    let (cols, fig7) = csv(&out.join("date05_fig7_queue.csv"));
    assert_eq!(
        cols[4..],
        [
            "order",
            "mode",
            "pairs",
            "max_entries",
            "max_entries_max",
            "queue_bytes"
        ]
    );
    for r in &fig7 {
        assert!(
            num(r, "max_entries") >= 1.0 && num(r, "max_entries") <= num(r, "max_entries_max"),
            "{r:?}"
        );
        assert!(
            close(
                num(r, "pairs"),
                date[at(r)][traversal(r, "order")][mode(r)].pairs
            ),
            "{r:?}"
        );
        // an entry: two node pairs of two 16-bit ids and a flip bit each, and a bit for one
        // pair or two: 2 (16 + 16 + 1) + 1 = 67 bits
        assert!(
            close(num(r, "queue_bytes"), num(r, "max_entries") * 67.0 / 8.0),
            "{r:?}"
        );
    }
    // DATE'05 Fig. 7: LIFO "uses still only very few memory, compared to a FIFO"; the
    // root's pair alone while the copies are apart
    for d in ["1.4", "1"] {
        assert!(
            num(&row(&fig7, d, "order", "lifo", "all"), "max_entries")
                < num(&row(&fig7, d, "order", "fifo", "all"), "max_entries"),
            "{fig7:?}"
        );
    }
    assert!(
        fig7.iter()
            .filter(|r| r["distance"] == "2.2")
            .all(|r| num(r, "max_entries") == 1.0),
        "{fig7:?}"
    );

    let (cols, fig8) = csv(&out.join("date05_fig8_speedup.csv"));
    assert_eq!(
        cols[4..],
        [
            "pairs",
            "cycles",
            "period_ns",
            "chip_us",
            "setup_us",
            "settle_us",
            "end_to_end_us",
            "golden_us",
            "parry_us",
            "speedup_golden",
            "speedup_parry",
            "e2e_speedup_golden",
            "e2e_speedup_parry"
        ]
    );
    for r in &fig8 {
        let lifo_all = fig6
            .iter()
            .find(|q| q["distance"] == r["distance"] && q["order"] == "lifo" && q["mode"] == "all")
            .unwrap();
        assert_eq!(
            (num(r, "cycles"), num(r, "chip_us")),
            (num(lifo_all, "cycles"), num(lifo_all, "chip_us")),
            "{r:?}"
        );
        assert!(
            num(r, "setup_us") > 0.0 && num(r, "settle_us") > 0.0,
            "{r:?}"
        );
        assert!(
            close(
                num(r, "end_to_end_us"),
                num(r, "setup_us") + num(r, "chip_us") + num(r, "settle_us")
            ),
            "{r:?}"
        );
        assert!(
            close(
                num(r, "speedup_golden"),
                num(r, "golden_us") / num(r, "chip_us")
            ),
            "{r:?}"
        );
        assert!(
            close(
                num(r, "e2e_speedup_golden"),
                num(r, "golden_us") / num(r, "end_to_end_us")
            ),
            "{r:?}"
        );
        assert_eq!(r["parry_us"].is_empty(), !cfg!(feature = "parry"), "{r:?}");
    }

    let (cols, fig11) = csv(&out.join("wscg03_fig11_nodes.csv"));
    assert_eq!(
        cols[4..],
        [
            "traversal",
            "mode",
            "pairs",
            "software_us",
            "node_fetches",
            "dop_transforms"
        ]
    );
    for r in fig11.iter().filter(|r| r["traversal"] == "list") {
        let rec = fig11
            .iter()
            .find(|q| {
                q["traversal"] == "recursive"
                    && q["distance"] == r["distance"]
                    && q["mode"] == r["mode"]
            })
            .unwrap();
        if r["mode"] == "all" {
            assert_eq!(r["pairs"], rec["pairs"]);
            assert!(
                num(rec, "dop_transforms") >= num(r, "dop_transforms"),
                "{r:?} {rec:?}"
            );
        }
    }
    // Figs. 9-12 are rows of one table: each the golden software's counts; the first witness
    // no more work than all pairs; more fetches and transforms as the copies close in
    let (_, fig9) = csv(&out.join("wscg03_fig9_first_witness.csv"));
    let (_, fig10) = csv(&out.join("wscg03_fig10_all_pairs.csv"));
    let (_, fig12) = csv(&out.join("wscg03_fig12_transforms.csv"));
    assert!(fig9.iter().all(|r| r["mode"] == "first") && fig10.iter().all(|r| r["mode"] == "all"));
    assert_eq!(
        (fig9.len() + fig10.len(), fig11.len(), fig12.len()),
        (3 * 4, 3 * 4, 3 * 4)
    );
    for r in fig9.iter().chain(&fig10).chain(&fig11).chain(&fig12) {
        let g = soft[at(r)][traversal(r, "traversal")][mode(r)];
        let got = (
            num(r, "pairs"),
            num(r, "node_fetches"),
            num(r, "dop_transforms"),
        );
        assert!(
            close(got.0, g.pairs) && close(got.1, g.node_fetches) && close(got.2, g.dop_transforms),
            "{r:?}: golden {g:?}"
        );
        let all = row(&fig12, &r["distance"], "traversal", &r["traversal"], "all");
        assert!(
            got.1 <= num(&all, "node_fetches") && got.2 <= num(&all, "dop_transforms"),
            "{r:?} {all:?}"
        );
    }
    for t in ["list", "recursive"] {
        let series =
            |c: &str| ["2.2", "1.4", "1"].map(|d| num(&row(&fig12, d, "traversal", t, "all"), c));
        for c in ["node_fetches", "dop_transforms"] {
            let v = series(c);
            assert!(v[0] <= v[1] && v[1] <= v[2], "{t} {c} {v:?}");
        }
    }

    let (cols, fig13) = csv(&out.join("wscg03_fig13_speedup.csv"));
    assert_eq!(
        cols[4..],
        [
            "pairs",
            "software_us",
            "parry_us",
            "wscg03_cycles",
            "event_cycles",
            "eq5_cycles",
            "date05_cycles",
            "lists",
            "alpha",
            "wscg03_clocks_per_list",
            "event_clocks_per_list",
            "eq5_clocks_per_list",
            "period_ns",
            "date05_period_ns",
            "setup_us",
            "settle_us",
            "speedup_wscg03",
            "speedup_event",
            "speedup_eq5",
            "speedup_date05",
            "speedup_parry_wscg03",
            "speedup_parry_event",
            "speedup_parry_eq5",
            "speedup_parry_date05",
            "e2e_us_wscg03",
            "e2e_us_event",
            "e2e_us_eq5",
            "e2e_us_date05"
        ]
    );
    // WSCG'03's chip, its event model and Eq. 5 at its RTL chip's measured period; DATE'05's
    // at its own
    let wscg03_period = period_ns("chip_wscg03_b32_k24");
    for r in &fig13 {
        let eq5 = 100.0 * num(r, "lists") + 10.0 * (num(r, "alpha") - 2.0) * num(r, "lists");
        assert!(
            (eq5 - num(r, "eq5_cycles")).abs() <= 1e-6 * eq5.abs().max(1.0),
            "{r:?}"
        );
        assert!(
            ["wscg03", "event", "date05"].map(|m| num(r, &format!("{m}_cycles")) > 0.0)
                == [true; 3],
            "{r:?}"
        );
        for m in ["wscg03", "event", "eq5"] {
            let per_list = num(r, &format!("{m}_cycles")) / num(r, "lists");
            assert!(
                close(num(r, &format!("{m}_clocks_per_list")), per_list),
                "{r:?}"
            );
        }
        // WSCG'03's figure on the wscg03 preset: DATE'05's chip of the same configuration,
        // its triangle cache aside
        assert_eq!(
            [num(r, "period_ns"), num(r, "date05_period_ns")],
            [wscg03_period, period],
            "{r:?}"
        );
        for m in ["wscg03", "event", "eq5", "date05"] {
            let p = num(
                r,
                if m == "date05" {
                    "date05_period_ns"
                } else {
                    "period_ns"
                },
            );
            let chip_us = num(r, &format!("{m}_cycles")) * p / 1000.0;
            assert!(
                close(
                    num(r, &format!("speedup_{m}")),
                    num(r, "software_us") / chip_us
                ),
                "{m}: {r:?}"
            );
            assert!(
                close(
                    num(r, &format!("e2e_us_{m}")),
                    num(r, "setup_us") + chip_us + num(r, "settle_us")
                ),
                "{m}: {r:?}"
            );
        }
    }
    let (cols, side) = csv(&out.join("wscg03_vs_date05.csv"));
    assert_eq!(
        cols[4..],
        [
            "wscg03_clocks",
            "date05_clocks",
            "wscg03_us",
            "date05_us",
            "wscg03_dop_per_clock",
            "date05_dop_per_clock",
            "wscg03_transforms_per_clock",
            "date05_transforms_per_clock",
            "wscg03_words",
            "date05_words",
            "wscg03_list_pointers",
            "date05_queue_entries"
        ]
    );
    // DATE'05 transforms in every DOP test; each chip's time at its own period; the same
    // clocks as Fig. 13's
    assert!(
        side.iter()
            .all(|r| num(r, "date05_transforms_per_clock") == num(r, "date05_dop_per_clock")),
        "{side:?}"
    );
    for (r, f) in side.iter().zip(&fig13) {
        assert_eq!(
            [num(r, "wscg03_clocks"), num(r, "date05_clocks")],
            [num(f, "wscg03_cycles"), num(f, "date05_cycles")]
        );
        for (m, p) in [("wscg03", wscg03_period), ("date05", period)] {
            let us = num(r, &format!("{m}_clocks")) * p / 1000.0;
            assert!(close(num(r, &format!("{m}_us")), us), "{m}: {r:?}");
        }
    }
    let json: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(out.join("wscg03_fig13_speedup.json")).unwrap(),
    )
    .unwrap();
    assert_eq!(json.as_array().unwrap().len(), fig13.len());
    let setup: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("plan.json")).unwrap()).unwrap();
    assert_eq!(
        ["date", "wscg", "stack"].map(|r| (
            setup["runs"][r]["preset"].clone(),
            setup["runs"][r]["architecture"].clone()
        )),
        [
            ("date05", "date05"),
            ("wscg03", "date05"),
            ("wscg03", "wscg03")
        ]
        .map(|(p, a)| (p.into(), a.into()))
    );
    assert!(
        setup["runs"]["date"]["clock_source"]
            .as_str()
            .unwrap()
            .contains("docs/figures/timing.csv"),
        "{setup}"
    );
    let _ = std::fs::remove_dir_all(&out);
}

/// `--preset` runs every figure's chips on that preset, and `--technology paper` at its
/// clock: the `rtl` preset's 800 MHz in DATE'05's figures and in Fig. 13 alike.
#[test]
fn figures_preset_overrides_both_papers() {
    let out = std::env::temp_dir().join(format!("cchip-figures-preset-{}", std::process::id()));
    let plan = Plan {
        meshes: vec!["teapot".into()],
        distances: vec![1.2],
        orientations: 1,
        seed: 3,
        min_seconds: 0.001,
        preset: Some(Preset::Rtl),
        technology: Technology::Paper,
    };
    generate(&plan, &out, &indicatif::ProgressBar::hidden()).unwrap();
    for (stem, col) in [
        ("date05_fig6_cycles", "period_ns"),
        ("date05_fig8_speedup", "period_ns"),
        ("wscg03_fig13_speedup", "period_ns"),
        ("wscg03_fig13_speedup", "date05_period_ns"),
    ] {
        let (_, rows) = csv(&out.join(format!("{stem}.csv")));
        assert!(rows.iter().all(|r| num(r, col) == 1.25), "{stem}: {rows:?}");
    }
    let setup: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("plan.json")).unwrap()).unwrap();
    assert_eq!(
        ["date", "wscg", "stack"].map(|r| setup["runs"][r]["preset"].clone()),
        ["rtl"; 3].map(serde_json::Value::from)
    );
    let _ = std::fs::remove_dir_all(&out);
}

/// The accuracy study's plot data: one row per configuration, and a configuration is on the
/// Pareto front iff it has no misses and no other such one is at least as good in both
/// end-to-end time and uncertain share (or cells).
#[test]
fn accuracy_pareto_front() {
    let tris = collision_chip::mesh::resolve("teapot")
        .unwrap()
        .scaled_into_unit_cube()
        .unwrap()
        .triangles_f64();
    let sweep = Sweep {
        distances: vec![1.2],
        orientations: 2,
        seed: 1,
    };
    let formats = vec![Format::BINARY32.into(), "e8m10".parse().unwrap()];
    // the papers' clock: no configuration needs a measured period
    let plan = |ks: Vec<usize>, bus_bits| accuracy::Plan {
        meshes: vec!["teapot".into()],
        presets: vec![Preset::Rtl],
        ks,
        formats: formats.clone(),
        roundings: vec![DopRounding::Outward],
        sweep: sweep.clone(),
        bus_bits,
        technology: Technology::Paper,
        folds: vec![Folds::NONE],
        dop_bits: vec![DopBits::Full],
        node_cache: accuracy::NodeCache::Preset,
    };
    let rows = accuracy::study(
        &plan(vec![6, 24], None),
        0,
        &tris,
        accuracy::Shard::ALL,
        || {},
    )
    .unwrap();
    assert_eq!(rows.len(), 4);
    assert!(rows
        .iter()
        .all(|r| r.sums.queries == 2 && r.sums.cycles > 0 && r.sums.misses == 0));
    // cells of the units by hand: DOP units 100 (k = 6) and 400 (k = 24), TRI_UNIT 1000;
    // none for e8m10, so no point of it on the area plot
    let file = std::env::temp_dir().join(format!("cchip-area-{}.csv", std::process::id()));
    std::fs::write(
        &file,
        "unit,cells\ndop_unit_k6_b32,100\ndop_unit_k24_b32,400\ntri_unit_b32_rne,1000\n",
    )
    .unwrap();
    let area = accuracy::Area::load(&file).unwrap();
    std::fs::remove_file(&file).unwrap();
    let figs = accuracy::figures(&rows, Some(&area));
    assert_eq!(
        figs.iter().map(|f| f.stem).collect::<Vec<_>>(),
        ["accuracy_cycles_uncertain", "accuracy_cycles_area"]
    );
    let t = figs[0].table.clone();
    let col = |c: &str| t.columns.iter().position(|x| *x == c).unwrap();
    let num = |r: &[Cell], c: &str| match &r[col(c)] {
        Cell::Num(x) => *x,
        other => panic!("{c}: {other:?}"),
    };
    for r in &t.rows {
        let (x, y) = (num(r, "uncertain_share"), num(r, "end_to_end_us"));
        let beaten = t.rows.iter().any(|q| {
            let (qx, qy) = (num(q, "uncertain_share"), num(q, "end_to_end_us"));
            qx <= x && qy <= y && (qx, qy) != (x, y)
        });
        assert_eq!(r[col("pareto")], Cell::Text((!beaten).to_string()), "{r:?}");
    }
    // tighter DOPs, fewer clocks
    let b32 = |k: u64| {
        t.rows
            .iter()
            .find(|r| {
                r[col("k")] == Cell::Int(k) && r[col("format")] == Cell::Text("binary32".into())
            })
            .unwrap()
    };
    assert!(num(b32(24), "cycles_per_query") < num(b32(6), "cycles_per_query"));
    // area: the units' sum; the smaller k = 6 is on the area front whatever the (measured) host time
    assert_eq!(
        (&b32(6)[col("cells")], &b32(24)[col("cells")]),
        (&Cell::Int(1100), &Cell::Int(1400))
    );
    assert_eq!(&b32(6)[col("pareto_area")], &Cell::Text("true".into()));
    assert!(t
        .rows
        .iter()
        .filter(|r| r[col("format")] == Cell::Text("e8m10".into()))
        .all(|r| r[col("cells")] == Cell::None && r[col("pareto_area")] == Cell::None));

    // on a 64-bit bus a word costs clocks by its width: binary32's words slow down more
    let slow = accuracy::study(
        &plan(vec![24], Some(64)),
        0,
        &tris,
        accuracy::Shard::ALL,
        || {},
    )
    .unwrap();
    let wide: Vec<_> = rows.iter().filter(|r| r.k == 24).collect();
    let growth: Vec<f64> = slow
        .iter()
        .zip(&wide)
        .map(|(s, w)| s.sums.cycles as f64 / w.sums.cycles as f64)
        .collect();
    assert!(
        growth[1] > 1.0 && growth[0] > growth[1],
        "clocks on a 64-bit bus / a word per clock: binary32, e8m10 {growth:?}"
    );
}

/// `cchip accuracy --shard K/N` prints JSON that `--merge` reads back from the files a user
/// saves: the merged rows are the serial run's (the host's measured times aside), and a
/// file that is not a shard's is refused naming it.
#[test]
fn accuracy_shards_merge_through_their_files() {
    let dir = std::env::temp_dir().join(format!("cchip-shards-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let cchip = |args: &[&str]| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_cchip"))
            .arg("accuracy")
            .args(args)
            .output()
            .unwrap();
        (
            out.status.code(),
            String::from_utf8(out.stdout).unwrap(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    let study = [
        "--meshes",
        "sphere:40,torus:40",
        "--distances",
        "1.0,0.5",
        "--orientations",
        "2",
        "--k",
        "6",
        "--formats",
        "reduced",
        "--presets",
        "rtl,wscg03",
        "--technology",
        "paper",
    ];
    let rows = |json: &str| -> Vec<serde_json::Value> {
        let mut v: Vec<serde_json::Value> = serde_json::from_str(json).unwrap();
        v.iter_mut()
            .for_each(|r| drop(r.as_object_mut().unwrap().remove("host")));
        v
    };
    let (code, serial, err) = cchip(&[&study[..], &["--json"]].concat());
    assert_eq!(code, Some(0), "{err}");
    let serial = rows(&serial);
    let files: Vec<String> = (1..=3)
        .map(|k| {
            let (code, json, err) = cchip(&[&study[..], &["--shard", &format!("{k}/3")]].concat());
            assert_eq!(code, Some(0), "{err}");
            let f = dir.join(format!("shard{k}.json"));
            std::fs::write(&f, json).unwrap();
            f.display().to_string()
        })
        .collect();
    let (code, merged, err) = cchip(&["--json", "--merge", &files[0], &files[1], &files[2]]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(rows(&merged), serial);
    // per mesh, preset and DOP rounding: 2 distances x 2 orientations
    assert!(
        serial.len() == 8 && serial.iter().all(|r| r["queries"] == 4),
        "{serial:?}"
    );
    std::fs::write(&files[2], "{}").unwrap();
    let (code, _, err) = cchip(&["--merge", &files[0], &files[1], &files[2]]);
    assert!(
        code == Some(2) && err.contains("shard3.json") && err.contains("not a shard's output"),
        "{code:?} {err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
