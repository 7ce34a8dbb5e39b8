//! `cchip figures` on a small plan: every file is written, the CSV has the columns the
//! docs read, and the data obey what must hold whatever the timing (LIFO and FIFO find
//! the same pairs, as do the list and recursive traversals; Algorithm 1 never transforms
//! less than Algorithm 2); each chip runs on its preset at its configuration's period, and
//! its times add up (end to end = host setup + clocks x period + host settling).

use collision_chip::chip::config::DopRounding;
use collision_chip::chip::preset::Preset;
use collision_chip::chip::timing::{Clock, Folds, Technology};
use collision_chip::format::Format;
use collision_chip::report::accuracy;
use collision_chip::report::figures::{generate, Plan};
use collision_chip::report::plot::Cell;
use collision_chip::pose::Sweep;
use std::collections::HashMap;

fn csv(path: &std::path::Path) -> (Vec<String>, Vec<HashMap<String, String>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let cols: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines.map(|l| cols.iter().cloned().zip(l.split(',').map(String::from)).collect()).collect();
    (cols, rows)
}

fn num(r: &HashMap<String, String>, c: &str) -> f64 {
    r[c].parse().unwrap_or_else(|_| panic!("{c} = {:?} is not a number", r[c]))
}

#[test]
fn figures_data_hold_what_the_papers_compare() {
    let out = std::env::temp_dir().join(format!("cchip-figures-test-{}", std::process::id()));
    let plan = Plan { meshes: vec!["teapot".into()], distances: vec![2.2, 1.4, 1.0], orientations: 2, seed: 3, min_seconds: 0.001, preset: None, technology: Technology::Osu018 };
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
            assert!(std::fs::metadata(&p).unwrap().len() > 100, "{} is empty", p.display());
        }
    }
    assert!(std::fs::read(out.join("date05_fig6_cycles.png")).unwrap().starts_with(b"\x89PNG"));

    let (cols, fig6) = csv(&out.join("date05_fig6_cycles.csv"));
    assert_eq!(cols, ["mesh", "triangles", "distance", "queries", "order", "mode", "pairs", "cycles", "cycles_max", "period_ns", "chip_us", "words"]);
    // DATE'05's figures on the date05 preset, at its configuration's measured period
    let period = |p: Preset| Clock::of(Technology::Osu018, &p.chip(), Folds::NONE, p).unwrap().period_ns;
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1.0);
    for r in &fig6 {
        assert_eq!(num(r, "period_ns"), period(Preset::Date05), "{r:?}");
        assert!(close(num(r, "chip_us"), num(r, "cycles") * num(r, "period_ns") / 1000.0), "{r:?}");
    }
    assert_eq!(fig6.len(), 3 * 2 * 2);
    for r in &fig6 {
        let twin = fig6
            .iter()
            .find(|q| q["distance"] == r["distance"] && q["mode"] == r["mode"] && q["order"] != r["order"])
            .unwrap();
        if r["mode"] == "all" {
            assert_eq!(r["pairs"], twin["pairs"], "LIFO and FIFO pairs differ: {r:?} {twin:?}");
        }
        assert!(num(r, "cycles") > 0.0 && num(r, "cycles") <= num(r, "cycles_max"));
    }
    // apart: no pairs; at 1.0 the copies penetrate
    let pairs = |d: &str| num(fig6.iter().find(|r| r["distance"] == d && r["mode"] == "all").unwrap(), "pairs");
    assert_eq!(pairs("2.2"), 0.0);
    assert!(pairs("1") > 0.0);

    let (cols, fig7) = csv(&out.join("date05_fig7_queue.csv"));
    assert_eq!(cols[4..], ["order", "mode", "pairs", "max_entries", "max_entries_max", "queue_bytes"]);
    assert!(fig7.iter().all(|r| num(r, "max_entries") >= 1.0));

    let (cols, fig8) = csv(&out.join("date05_fig8_speedup.csv"));
    assert_eq!(
        cols[4..],
        ["pairs", "cycles", "period_ns", "chip_us", "setup_us", "settle_us", "end_to_end_us", "golden_us", "parry_us", "speedup_golden", "speedup_parry", "e2e_speedup_golden", "e2e_speedup_parry"]
    );
    for r in &fig8 {
        let lifo_all = fig6.iter().find(|q| q["distance"] == r["distance"] && q["order"] == "lifo" && q["mode"] == "all").unwrap();
        assert_eq!((num(r, "cycles"), num(r, "chip_us")), (num(lifo_all, "cycles"), num(lifo_all, "chip_us")), "{r:?}");
        assert!(num(r, "setup_us") > 0.0 && num(r, "settle_us") > 0.0, "{r:?}");
        assert!(close(num(r, "end_to_end_us"), num(r, "setup_us") + num(r, "chip_us") + num(r, "settle_us")), "{r:?}");
        assert!(close(num(r, "speedup_golden"), num(r, "golden_us") / num(r, "chip_us")), "{r:?}");
        assert!(close(num(r, "e2e_speedup_golden"), num(r, "golden_us") / num(r, "end_to_end_us")), "{r:?}");
        assert_eq!(r["parry_us"].is_empty(), !cfg!(feature = "parry"), "{r:?}");
    }

    let (cols, fig11) = csv(&out.join("wscg03_fig11_nodes.csv"));
    assert_eq!(cols[4..], ["traversal", "mode", "pairs", "software_us", "node_fetches", "dop_transforms"]);
    for r in fig11.iter().filter(|r| r["traversal"] == "list") {
        let rec = fig11.iter().find(|q| q["traversal"] == "recursive" && q["distance"] == r["distance"] && q["mode"] == r["mode"]).unwrap();
        if r["mode"] == "all" {
            assert_eq!(r["pairs"], rec["pairs"]);
            assert!(num(rec, "dop_transforms") >= num(r, "dop_transforms"), "{r:?} {rec:?}");
        }
    }

    let (cols, fig13) = csv(&out.join("wscg03_fig13_speedup.csv"));
    assert_eq!(
        cols[4..],
        [
            "pairs", "software_us", "parry_us", "wscg03_cycles", "eq5_cycles", "date05_cycles", "lists", "alpha", "wscg03_clocks_per_list", "eq5_clocks_per_list", "period_ns", "setup_us", "settle_us",
            "speedup_wscg03", "speedup_eq5", "speedup_date05", "speedup_parry_wscg03", "speedup_parry_eq5", "speedup_parry_date05", "e2e_us_wscg03", "e2e_us_eq5", "e2e_us_date05"
        ]
    );
    for r in &fig13 {
        let eq5 = 100.0 * num(r, "lists") + 10.0 * (num(r, "alpha") - 2.0) * num(r, "lists");
        assert!((eq5 - num(r, "eq5_cycles")).abs() <= 1e-6 * eq5.abs().max(1.0), "{r:?}");
        assert!(num(r, "wscg03_cycles") > 0.0 && num(r, "date05_cycles") > 0.0, "{r:?}");
        // WSCG'03's figure on the wscg03 preset
        assert_eq!(num(r, "period_ns"), period(Preset::Wscg03), "{r:?}");
        for m in ["wscg03", "eq5", "date05"] {
            let chip_us = num(r, &format!("{m}_cycles")) * num(r, "period_ns") / 1000.0;
            assert!(close(num(r, &format!("speedup_{m}")), num(r, "software_us") / chip_us), "{m}: {r:?}");
            assert!(close(num(r, &format!("e2e_us_{m}")), num(r, "setup_us") + chip_us + num(r, "settle_us")), "{m}: {r:?}");
        }
    }
    let (cols, side) = csv(&out.join("wscg03_vs_date05.csv"));
    assert_eq!(cols[4..], ["wscg03_clocks", "date05_clocks", "wscg03_dop_per_clock", "date05_dop_per_clock", "wscg03_transforms_per_clock", "date05_transforms_per_clock", "wscg03_words", "date05_words", "wscg03_list_pointers", "date05_queue_entries"]);
    // DATE'05 transforms in every DOP test
    assert!(side.iter().all(|r| num(r, "date05_transforms_per_clock") == num(r, "date05_dop_per_clock")), "{side:?}");
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(out.join("wscg03_fig13_speedup.json")).unwrap()).unwrap();
    assert_eq!(json.as_array().unwrap().len(), fig13.len());
    let setup: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(out.join("plan.json")).unwrap()).unwrap();
    assert_eq!((&setup["runs"]["date"]["preset"], &setup["runs"]["wscg"]["preset"]), (&"date05".into(), &"wscg03".into()));
    assert!(setup["runs"]["date"]["clock_source"].as_str().unwrap().contains("docs/figures/timing.csv"), "{setup}");
    let _ = std::fs::remove_dir_all(&out);
}

/// `--preset` runs every figure's chips on that preset, and `--technology paper` at its
/// clock: the `rtl` preset's 800 MHz in DATE'05's figures and in Fig. 13 alike.
#[test]
fn figures_preset_overrides_both_papers() {
    let out = std::env::temp_dir().join(format!("cchip-figures-preset-{}", std::process::id()));
    let plan = Plan { meshes: vec!["teapot".into()], distances: vec![1.2], orientations: 1, seed: 3, min_seconds: 0.001, preset: Some(Preset::Rtl), technology: Technology::Paper };
    generate(&plan, &out, &indicatif::ProgressBar::hidden()).unwrap();
    for (stem, col) in [("date05_fig6_cycles", "period_ns"), ("date05_fig8_speedup", "period_ns"), ("wscg03_fig13_speedup", "period_ns")] {
        let (_, rows) = csv(&out.join(format!("{stem}.csv")));
        assert!(rows.iter().all(|r| num(r, col) == 1.25), "{stem}: {rows:?}");
    }
    let setup: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(out.join("plan.json")).unwrap()).unwrap();
    assert_eq!((&setup["runs"]["date"]["preset"], &setup["runs"]["wscg"]["preset"]), (&"rtl".into(), &"rtl".into()));
    let _ = std::fs::remove_dir_all(&out);
}

/// The accuracy study's plot data: one row per configuration, and a configuration is on the
/// Pareto front iff it has no misses and no other such one is at least as good in both
/// end-to-end time and uncertain share (or cells).
#[test]
fn accuracy_pareto_front() {
    let tris = collision_chip::mesh::resolve("teapot").unwrap().scaled_into_unit_cube().unwrap().triangles_f64();
    let sweep = Sweep { distances: vec![1.2], orientations: 2, seed: 1 };
    let formats = vec![Format::BINARY32.into(), "e8m10".parse().unwrap()];
    // the papers' clock: e8m10 has no RTL unit to take a period from
    let plan = |ks: Vec<usize>, bus_bits| accuracy::Plan { meshes: vec!["teapot".into()], presets: vec![Preset::Rtl], ks, formats: formats.clone(), roundings: vec![DopRounding::Outward], sweep: sweep.clone(), bus_bits, technology: Technology::Paper, folds: vec![Folds::NONE] };
    let rows = accuracy::study(&plan(vec![6, 24], None), 0, &tris, accuracy::Shard::ALL, || {}).unwrap();
    assert_eq!(rows.len(), 4);
    assert!(rows.iter().all(|r| r.sums.queries == 2 && r.sums.cycles > 0 && r.sums.misses == 0));
    // cells of the units by hand: DOP units 100 (k = 6) and 400 (k = 24), TRI_UNIT 1000;
    // e8m10 has no RTL, so no cells and no point on the area plot
    let file = std::env::temp_dir().join(format!("cchip-area-{}.csv", std::process::id()));
    std::fs::write(&file, "unit,cells\ndop_unit_k6_b32_ru,100\ndop_unit_k24_b32_ru,400\ntri_unit_b32_rne,1000\n").unwrap();
    let area = accuracy::Area::load(&file).unwrap();
    std::fs::remove_file(&file).unwrap();
    let figs = accuracy::figures(&rows, Some(&area));
    assert_eq!(figs.iter().map(|f| f.stem).collect::<Vec<_>>(), ["accuracy_cycles_uncertain", "accuracy_cycles_area"]);
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
    let b32 = |k: u64| t.rows.iter().find(|r| r[col("k")] == Cell::Int(k) && r[col("format")] == Cell::Text("binary32".into())).unwrap();
    assert!(num(b32(24), "cycles_per_query") < num(b32(6), "cycles_per_query"));
    // area: the units' sum; the smaller k = 6 is on the area front whatever the (measured) host time
    assert_eq!((&b32(6)[col("cells")], &b32(24)[col("cells")]), (&Cell::Int(1100), &Cell::Int(1400)));
    assert_eq!(&b32(6)[col("pareto_area")], &Cell::Text("true".into()));
    assert!(t.rows.iter().filter(|r| r[col("format")] == Cell::Text("e8m10".into())).all(|r| r[col("cells")] == Cell::None && r[col("pareto_area")] == Cell::None));

    // on a 64-bit bus a word costs clocks by its width: binary32's words slow down more
    let slow = accuracy::study(&plan(vec![24], Some(64)), 0, &tris, accuracy::Shard::ALL, || {}).unwrap();
    let wide: Vec<_> = rows.iter().filter(|r| r.k == 24).collect();
    let growth: Vec<f64> = slow.iter().zip(&wide).map(|(s, w)| s.sums.cycles as f64 / w.sums.cycles as f64).collect();
    assert!(growth[1] > 1.0 && growth[0] > growth[1], "clocks on a 64-bit bus / a word per clock: binary32, e8m10 {growth:?}");
}
