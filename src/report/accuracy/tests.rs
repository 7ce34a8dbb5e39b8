use super::*;

/// A mesh scaled into the unit cube, as `cchip accuracy` loads it.
fn load(m: &str) -> Result<Vec<Tri>, String> {
    crate::mesh::resolve(m)
        .map_err(|e| e.to_string())?
        .scaled_into_unit_cube()
        .map(|m| m.triangles_f64())
        .map_err(|e| e.to_string())
}

/// A study of `mesh` on the `date05` memory at the paper's clock, small: k = 6, e8m15,
/// outward, one distance in two orientations, unfolded, full records.
fn small_date05(mesh: &str) -> Plan {
    Plan {
        meshes: vec![mesh.into()],
        presets: vec![Preset::Date05],
        ks: vec![6],
        formats: vec![Formats::from(crate::format::Format::REDUCED)],
        roundings: vec![DopRounding::Outward],
        sweep: Sweep {
            distances: vec![0.5],
            orientations: 2,
            seed: 1,
        },
        bus_bits: None,
        technology: Technology::Paper,
        folds: vec![Folds::NONE],
        dop_bits: vec![DopBits::Full],
        node_cache: NodeCache::Preset,
    }
}

/// Three shards merged give the serial run's rows and table (the host's measured times
/// aside); a shard missing or given twice is an error.
#[test]
fn shards_merge_into_the_serial_run() {
    let plan = Plan {
        meshes: vec!["sphere:40".into(), "torus:40".into()],
        presets: vec![Preset::Rtl, Preset::Wscg03],
        ks: vec![6],
        formats: vec![Formats::from(crate::format::Format::REDUCED)],
        roundings: vec![DopRounding::Outward],
        sweep: Sweep {
            distances: vec![1.0, 0.5],
            orientations: 2,
            seed: 1,
        },
        bus_bits: None,
        technology: Technology::Osu018,
        folds: vec![Folds::NONE],
        dop_bits: vec![DopBits::Full],
        node_cache: NodeCache::Preset,
    };
    let unmeasured = |rows: Vec<Row>| -> Vec<Row> {
        rows.into_iter()
            .map(|r| Row {
                host: HostSums::default(),
                ..r
            })
            .collect()
    };
    let serial = unmeasured(run(&plan, load, Shard::ALL, || ()).unwrap());
    let shard = |k| ShardFile {
        plan: plan.clone(),
        shard: Shard { k, n: 3 },
        rows: run(&plan, load, Shard { k, n: 3 }, || ()).unwrap(),
    };
    let files: Vec<ShardFile> = (1..=3).map(shard).collect();
    let (p, merged) = merge(files.clone()).unwrap();
    let merged = unmeasured(merged);
    assert_eq!(p, plan);
    assert!(serial.iter().all(|r| r.sums.queries == 4) && serial.iter().any(|r| r.sums.cycles > 0));
    assert_eq!(
        serial.iter().map(|r| r.sums).collect::<Vec<_>>(),
        merged.iter().map(|r| r.sums).collect::<Vec<_>>()
    );
    assert_eq!(
        table(&plan, &serial, None).unwrap(),
        table(&plan, &merged, None).unwrap()
    );
    assert!(merge(files[..2].to_vec())
        .unwrap_err()
        .contains("shard 3/3 is missing"));
    assert!(
        merge(vec![files[0].clone(), files[0].clone(), files[1].clone()])
            .unwrap_err()
            .contains("given twice")
    );
    // N is the file's: a huge one is a study with shards missing, not an allocation of N
    let huge = ShardFile {
        shard: Shard {
            k: 1,
            n: usize::MAX,
        },
        ..files[0].clone()
    };
    let e = merge(vec![huge]).unwrap_err();
    assert!(
        e.contains(&format!("shard 2/{} is missing", usize::MAX)),
        "{e}"
    );
}

/// Counts no study writes are refused, naming the shard, before the merge's sums or the
/// table's rates overflow on them (afl found both: fuzz/regressions/merge/).
#[test]
fn merge_refuses_counts_no_study_writes() {
    let text = include_str!("../../../fuzz/corpus/merge/one-shard-folds");
    let file = ShardFile::parse(text, std::path::Path::new("s.json")).unwrap();
    let (_, rows) = merge(vec![file.clone()]).unwrap();
    assert!(table(&file.plan, &rows, None).is_ok());
    let mut missed = file.clone();
    missed.rows[1].sums.misses = missed.rows[1].sums.exact_pairs + 1;
    let e = merge(vec![missed]).unwrap_err();
    assert!(
        e.starts_with("--merge: shard 1/1, ") && e.contains("misses of"),
        "{e}"
    );
    // each shard's count fits, their sum does not
    let halves = (1..=2).map(|k| {
        let mut f = file.clone();
        f.shard = Shard { k, n: 2 };
        f.rows[0].sums.cycles = u64::MAX / 2 + 1;
        f
    });
    let e = merge(halves.collect()).unwrap_err();
    assert!(
        e.starts_with("--merge: shard 2/2: ") && e.contains("past 2^64"),
        "{e}"
    );
}

/// A fold changes the clocks only: the folded rows count the unfolded ones' tests and
/// pairs, in no fewer clocks; a DOP interval that does not divide k is refused up front.
#[test]
fn folds_cost_clocks_and_nothing_else() {
    let plan = Plan {
        folds: vec![Folds::NONE, Folds::asic(32, 6)],
        ..small_date05("sphere:40")
    };
    let rows = run(&plan, load, Shard::ALL, || ()).unwrap();
    let (a, b) = (&rows[0].sums, &rows[1].sums);
    assert_eq!(
        (rows[0].folds, rows[1].folds),
        (Folds::NONE, Folds::asic(32, 6))
    );
    assert_eq!(
        (a.dop_tests, a.tri_tests, a.uncertain),
        (b.dop_tests, b.tri_tests, b.uncertain)
    );
    assert!(
        a.tri_tests > 0 && b.cycles > a.cycles,
        "{} -> {} clocks",
        a.cycles,
        b.cycles
    );
    let bad = Plan {
        folds: vec![Folds::asic(1, 4)],
        ..plan.clone()
    };
    assert!(run(&bad, load, Shard::ALL, || ())
        .unwrap_err()
        .contains("k = 6, TRI_UNIT interval 1, DOP interval 4"));
    // the ideal memory's bus is not a DDR preset's: refused there, not quietly left out
    let bus = Plan {
        bus_bits: Some(64),
        ..plan
    };
    let e = bus.configs().unwrap_err();
    assert!(e.starts_with("--bus-bits 64 sets the ideal memory's bus (preset rtl's memory); preset date05's memory is DDR SDRAM on a bus of its own (756 bits)"), "{e}");
    let rtl = Plan {
        presets: vec![Preset::Rtl],
        ..bus
    }
    .configs()
    .unwrap();
    assert!(rtl.iter().all(|(_, _, p)| p.memory
        == Memory::Ideal(crate::chip::memory::MemTiming {
            bus_bits: Some(64),
            ..Default::default()
        })));
}

/// Stored DOP precision costs DOP tests and never a pair: at 8 and 2 bits a plane the
/// rows find the full records' exact pairs, with no miss and at least their DOP tests; a
/// preset whose layout cannot store codes is refused, naming the flag.
#[test]
fn stored_dops_cost_tests_never_pairs() {
    let plan = Plan {
        dop_bits: vec![DopBits::Full, DopBits::Bits(8), DopBits::Bits(2)],
        ..small_date05("sphere:60")
    };
    let rows = run(&plan, load, Shard::ALL, || ()).unwrap();
    let full = &rows[0].sums;
    assert_eq!(rows.len(), 3);
    for r in &rows[1..] {
        let s = &r.sums;
        assert_eq!(
            (s.exact_pairs, s.misses, s.extras),
            (full.exact_pairs, 0, 0),
            "{}",
            r.dop_bits
        );
        assert!(s.dop_tests >= full.dop_tests, "{}", r.dop_bits);
    }
    let rtl = Plan {
        presets: vec![Preset::Rtl],
        ..plan
    };
    let e = rtl.configs().unwrap_err();
    assert!(e.starts_with("--dop-bits 8 on preset rtl: dop_bits = 8 stores each node below its treelet root's DOP"), "{e}");
}

/// `--json` with `--area` gives each row the cells of the table's column; without, none.
#[test]
fn json_rows_carry_their_cells() {
    let rows = run(&small_date05("sphere:40"), load, Shard::ALL, || ()).unwrap();
    let units = timing::datapath_units(&rows[0].chip(), rows[0].folds);
    let csv: String = units
        .iter()
        .enumerate()
        .map(|(i, (u, _))| format!("{u},{}\n", 10 * (i + 1)))
        .collect();
    let path = std::env::temp_dir().join(format!("cchip-area-{}.csv", std::process::id()));
    std::fs::write(&path, format!("unit,cells\n{csv}")).unwrap();
    let area = Area::load(&path).unwrap();
    std::fs::remove_file(&path).ok();
    let with: serde_json::Value = serde_json::from_str(&json(&rows, Some(&area))).unwrap();
    assert_eq!(with[0]["cells"], 30, "{units:?}");
    let without: serde_json::Value = serde_json::from_str(&json(&rows, None)).unwrap();
    assert!(without[0].get("cells").is_none());
}

/// The study's default configurations (k = 24 in its four formats, both DOP roundings, on the
/// three memory presets with one node record held, `cchip accuracy`'s defaults) each run on
/// a chip that is built, at that chip's measured period.
#[test]
fn the_default_study_runs_on_measured_chips() {
    let plan = Plan {
        presets: vec![Preset::Rtl, Preset::Date05, Preset::Wscg03],
        ks: vec![24],
        formats: ["binary32", "reduced", "e8m10", "e8m15/binary32"]
            .map(|f| f.parse().unwrap())
            .to_vec(),
        roundings: vec![DopRounding::Outward, DopRounding::NearestEven],
        technology: Technology::Osu018,
        node_cache: NodeCache::Held(1),
        ..small_date05("sphere:40")
    };
    let configs = plan.configs().unwrap();
    assert_eq!(configs.len(), 24);
    for (preset, cfg, p) in configs {
        let folds = Folds::of(&p);
        let c = Clock::of(plan.technology, &cfg, folds, preset).unwrap();
        assert_eq!(
            c.source,
            PeriodSource::Measured,
            "{} k = {} {} {}: {}",
            preset.name(),
            cfg.k,
            cfg.format,
            cfg.dop_rounding,
            c.source()
        );
    }
    // with the presets' own 16 records held, the chip is not built: estimated
    let own = Plan {
        node_cache: NodeCache::Preset,
        ..plan.clone()
    };
    let (preset, cfg, _) = own.configs().unwrap()[8];
    assert_eq!(preset, Preset::Date05);
    let c = Clock::of(own.technology, &cfg, Folds::NONE, preset).unwrap();
    assert_eq!(c.source, PeriodSource::Estimated, "{}", c.source());
}
