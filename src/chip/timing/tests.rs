use super::*;
use crate::chip::config::{DopRounding, Formats};

/// A configuration's period is the largest of its units' in a hand-written table; units of
/// other formats and roundings do not count; absent ones are named.
#[test]
fn period_is_the_slowest_unit_of_the_configuration() {
    let text = "unit,cells,min_period_ns,extra\n\
                fp_mul_e8m15_ru,1,6.5,x\n\
                fp_add_e8m15_ru,1,7.0,x\n\
                fp_mul_e8m15_rne,1,5.0,x\n\
                fp_add_e8m15_rne,1,8.0,x\n\
                doptrf_b32,1,30.0,x\n\
                pair_queue_n4,1,4.0,x\n\
                tcheck_e8m15_rne,1,,x\n";
    let t = Table::parse(text, "t.csv").unwrap();
    let cfg = ChipConfig {
        k: 6,
        format: Formats::from(Format::REDUCED),
        dop_rounding: DopRounding::Outward,
        ..Default::default()
    };
    let c = Clock::measured(&t, &cfg, Folds::NONE).unwrap();
    // DOP: mul 6.5, add 7.0 (ru); T.CHECK: add 8.0 (rne); queue 4.0; b32's 30 not ours
    assert_eq!(
        (c.period_ns, c.slowest.as_deref()),
        (8.0, Some("fp_add_e8m15_rne"))
    );
    assert!(
        c.not_measured.contains(&"tcheck_e8m15_rne".to_string())
            && c.not_measured.contains(&"chip_e8m15_k6".to_string())
    );
    assert!(
        !c.not_measured
            .iter()
            .any(|u| u.starts_with("fp_mul") || u.starts_with("fp_add")),
        "{:?}",
        c.not_measured
    );
    assert_eq!(c.source, PeriodSource::Estimated);
    assert!(c.source().contains("estimated: fp_add_e8m15_rne stands in for this configuration's chip: chip_e8m15_k6 has no row"), "{}", c.source());
    // columns found by name, in any order; Fmax where no period is given
    let t = Table::parse(
        "fmax_mhz,unit\n125,pair_queue_n4\n200,fp_mul_e8m15_ru\n150,tcheck_e8m15_rne\n",
        "t.csv",
    )
    .unwrap();
    assert_eq!(
        Clock::measured(&t, &cfg, Folds::NONE).unwrap().period_ns,
        8.0
    );
    // the FPGA table's `period_ns` where there is no `min_period_ns`: exact, its Fmax rounded
    let t = Table::parse("unit,fmax_mhz,period_ns\npair_queue_n4,23.1,43.214\ndop_unit_k6_e8m15,30,33.3\ntri_unit_e8m15_rne,30,33.3\n", "t.csv").unwrap();
    assert_eq!(
        Clock::measured(&t, &cfg, Folds::NONE).unwrap().period_ns,
        43.214
    );
    // a block's row stands for its parts': the DOP unit's 6, not its lone lane's 7.5
    let t = Table::parse("unit,min_period_ns\ndop_unit_k6_e8m15,6\ndoptrf_e8m15,7.5\ntri_unit_e8m15_rne,5\npair_queue_n4,1\n", "t").unwrap();
    let c = Clock::measured(&t, &cfg, Folds::NONE).unwrap();
    assert_eq!(
        (c.period_ns, c.slowest.as_deref()),
        (6.0, Some("dop_unit_k6_e8m15"))
    );
    assert!(
        !c.not_measured
            .iter()
            .any(|u| u.starts_with("doptrf") || (u.ends_with("_ru") && u.starts_with("fp_"))),
        "{:?}",
        c.not_measured
    );
    // the whole chip, where measured, is the period, slower or faster than a lone unit
    // (the chip maps its units as it builds them): its control and the paths between
    // units count; its row makes the period measured
    for chip_ns in [9.0, 7.0] {
        let t = Table::parse(&format!("unit,min_period_ns\nfp_add_e8m15_rne,8\nfp_add_e8m15_ru,7\nchip_e8m15_k6,{chip_ns}\n"), "t").unwrap();
        let c = Clock::measured(&t, &cfg, Folds::NONE).unwrap();
        assert_eq!(
            (c.period_ns, c.slowest.as_deref(), c.source, c.estimate),
            (chip_ns, Some("chip_e8m15_k6"), PeriodSource::Measured, None)
        );
    }
    let t = Table::parse(
        "unit,min_period_ns\nfp_add_e8m15_rne,8\nfp_add_e8m15_ru,7\nchip_e8m15_k6,9\n",
        "t",
    )
    .unwrap();
    // the DOP lanes round either way (a setup word): nearest-even runs on the built chip
    let t2 = Table::parse(
        "unit,min_period_ns\nfp_add_e8m15_ru,8\nchip_e8m15_k6,9\n",
        "t",
    )
    .unwrap();
    let ne = ChipConfig {
        dop_rounding: DopRounding::NearestEven,
        ..cfg
    };
    let c = Clock::measured(&t2, &ne, Folds::NONE).unwrap();
    assert_eq!((c.period_ns, c.source), (9.0, PeriodSource::Measured));
    // a T.CHECK rounding the RTL chips are not built with has a chip of its own name,
    // not measured
    let tri_up = ChipConfig {
        tri_rounding: Rounding::TowardPositive,
        ..cfg
    };
    let c = Clock::measured(&t2, &tri_up, Folds::NONE).unwrap();
    assert_eq!((c.period_ns, c.source), (8.0, PeriodSource::Estimated));
    assert!(
        c.not_measured.contains(&"chip_e8m15_k6_tri_ru".to_string()),
        "{:?}",
        c.not_measured
    );
    // the RTL chip with another memory side stands in (estimated)
    let cached = ChipConfig {
        node_cache: 16,
        ..cfg
    };
    let c = Clock::measured(&t, &cached, Folds::NONE).unwrap();
    assert_eq!((c.period_ns, c.source), (9.0, PeriodSource::Estimated));
    assert!(
        c.source().contains(
            "the RTL chips hold one node record per object; this configuration has node_cache = 16"
        ),
        "{}",
        c.source()
    );
}

/// A datapath none of whose units is measured does not leave the period to the others
/// (the pair queue's 3.4 ns for an e8m24 chip): the narrowest measured format at least as
/// wide stands in (estimated), and with none the configuration has no period.
#[test]
fn an_unmeasured_datapath_is_estimated_by_a_wider_format_or_refused() {
    let t = Table::parse("unit,min_period_ns\npair_queue_n4,3.4\nfp_mul_b32_ru,3\ntri_unit_b32_rne,7\ntri_unit_e8m15_rne,6\n", "t").unwrap();
    let cfg = |dop, tri| ChipConfig {
        k: 6,
        format: Formats { dop, tri },
        ..Default::default()
    };
    let b32 = Format::BINARY32;
    let e = Clock::measured(&t, &cfg(Format::new(8, 24).unwrap(), b32), Folds::NONE).unwrap_err();
    assert!(
        e.starts_with("DOP datapath's units (fp_mul_e8m24_ru"),
        "{e}"
    );
    assert!(
        Clock::measured(&t, &cfg(b32, Format::new(8, 24).unwrap()), Folds::NONE)
            .unwrap_err()
            .starts_with("T.CHECK datapath's units")
    );
    let e8m10 = Format::new(8, 10).unwrap();
    let c = Clock::measured(&t, &cfg(e8m10, e8m10), Folds::NONE).unwrap();
    // the DOP datapath has only binary32 measured, T.CHECK e8m15 (the narrowest)
    assert_eq!(
        (c.period_ns, c.source, c.slowest.as_deref()),
        (6.0, PeriodSource::Estimated, Some("tri_unit_e8m15_rne"))
    );
    let why = c.estimate.unwrap();
    assert!(
        why.contains("the DOP datapath in binary32 stands in for e8m10")
            && why.contains("the T.CHECK datapath in e8m15 stands in for e8m10"),
        "{why}"
    );
    // WSCG'03's chip: its own row, measured for the configuration it is built for,
    // estimated for another; without a row DATE'05's chip's, estimated
    let cfg = ChipConfig::default();
    let osu = Clock::of(Technology::Osu018, &cfg, Folds::NONE, Preset::Rtl).unwrap();
    assert_eq!(osu.source, PeriodSource::Measured);
    let w = osu.clone().for_architecture(Architecture::Wscg03, &cfg);
    let (file, text, _) = Technology::Osu018.table().unwrap();
    let row = Table::parse(text, file).unwrap();
    assert_eq!(
        (w.period_ns, w.source, w.slowest.as_deref()),
        (
            row.periods[rtl::WSCG03_CHIP],
            PeriodSource::Measured,
            Some(rtl::WSCG03_CHIP)
        )
    );
    let k14 = ChipConfig { k: 14, ..cfg };
    let w = osu.clone().for_architecture(Architecture::Wscg03, &k14);
    assert_eq!(w.source, PeriodSource::Estimated);
    assert!(
        w.source().contains(
            "chip_wscg03_b32_k24 stands in for this configuration's WSCG'03 chip (k = 14"
        ),
        "{}",
        w.source()
    );
    let ecp5 = Clock::of(Technology::Ecp5, &cfg, Folds::NONE, Preset::Rtl).unwrap();
    let w = ecp5.clone().for_architecture(Architecture::Wscg03, &cfg);
    assert_eq!(
        (w.period_ns, w.source),
        (ecp5.period_ns, PeriodSource::Estimated)
    );
    assert!(
        w.source().contains(
            "chip_wscg03_b32_k24 has no row; DATE'05's chip of this configuration stands in"
        ),
        "{}",
        w.source()
    );
    let paper = Clock::of(
        Technology::Paper,
        &ChipConfig::default(),
        Folds::NONE,
        Preset::Wscg03,
    )
    .unwrap();
    assert_eq!(
        paper.clone().for_architecture(Architecture::Wscg03, &cfg),
        paper
    );
}

#[test]
fn bad_tables_name_file_and_line() {
    assert!(Table::parse("name,min_period_ns\n", "t.csv")
        .unwrap_err()
        .starts_with("t.csv:1:"));
    assert!(Table::parse("unit,cells\n", "t.csv")
        .unwrap_err()
        .contains("min_period_ns"));
    assert!(Table::parse("unit,min_period_ns\na,1\nb,-3\n", "t.csv")
        .unwrap_err()
        .starts_with("t.csv:3:"));
}

/// A folded configuration counts the folded TRI_UNIT, not T.CHECK or the unfolded
/// TRI_UNIT, and both the unfolded chip (its glue) and the folded one.
#[test]
fn a_folded_configuration_counts_the_folded_unit_and_both_chips() {
    let cfg = ChipConfig {
        k: 6,
        format: Formats::from(Format::REDUCED),
        dop_rounding: DopRounding::Outward,
        ..Default::default()
    };
    let u = units(&cfg, Folds::asic(16, 1));
    for name in [
        "tri_unit_fold16_e8m15_rne",
        "chip_e8m15_k6",
        "chip_e8m15_k6_fold16",
    ] {
        assert!(u.contains(&name.to_string()), "{name} not in {u:?}");
    }
    assert!(
        !u.iter()
            .any(|n| n == "tcheck_e8m15_rne" || n == "tri_unit_e8m15_rne"),
        "{u:?}"
    );
    let t = Table::parse(
        "unit,min_period_ns
dop_unit_k6_e8m15,5
tri_unit_e8m15_rne,20
tri_unit_fold16_e8m15_rne,9
chip_e8m15_k6,8
",
        "t",
    )
    .unwrap();
    let c = Clock::measured(&t, &cfg, Folds::asic(16, 1)).unwrap();
    assert_eq!(
        (c.period_ns, c.slowest.as_deref(), c.source),
        (
            9.0,
            Some("tri_unit_fold16_e8m15_rne"),
            PeriodSource::Estimated
        )
    );
    assert!(
        c.source().contains("chip_e8m15_k6_fold16 has no row"),
        "{}",
        c.source()
    );
    // the unfolded chip stands for the DOP datapath it shares, not a lone lane's row
    let t = Table::parse(
        "unit,min_period_ns\ntri_unit_fold16_e8m15_rne,9\nchip_e8m15_k6,8\ndoptrf_e8m15,30\n",
        "t",
    )
    .unwrap();
    assert_eq!(
        Clock::measured(&t, &cfg, Folds::asic(16, 1))
            .unwrap()
            .period_ns,
        9.0
    );
    assert!(
        c.not_measured.contains(&"chip_e8m15_k6_fold16".to_string()),
        "{:?}",
        c.not_measured
    );
    // the folded unit not measured: the unfolded one's period stands in, a lower bound
    let t = Table::parse(
        "unit,min_period_ns\ndop_unit_k6_e8m15,5\ntri_unit_e8m15_rne,20\nchip_e8m15_k6,8\n",
        "t",
    )
    .unwrap();
    let c = Clock::measured(&t, &cfg, Folds::asic(16, 1)).unwrap();
    assert_eq!(
        (c.period_ns, c.slowest.as_deref()),
        (
            20.0,
            Some("tri_unit_e8m15_rne (for tri_unit_fold16_e8m15_rne)")
        )
    );
    assert!(
        c.not_measured
            .contains(&"tri_unit_fold16_e8m15_rne".to_string()),
        "{:?}",
        c.not_measured
    );
    // ... unless a timed chip is built on that fold: its row stands in (the DOP unit at
    // ii = 2 with TRI_UNIT at 16: chip_e8m15_k6_fold16's row, TRI_UNIT at 16 in a chip)
    let t = Table::parse(
        "unit,min_period_ns\ndop_unit_fold2_k6_e8m15,5\ntri_unit_e8m15_rne,6\nchip_e8m15_k6,8\nchip_e8m15_k6_fold16,11\n",
        "t",
    )
    .unwrap();
    let c = Clock::measured(&t, &cfg, Folds::asic(16, 2)).unwrap();
    assert_eq!(
        (c.period_ns, c.slowest.as_deref()),
        (
            11.0,
            Some("chip_e8m15_k6_fold16 (for tri_unit_fold16_e8m15_rne)")
        )
    );
    assert!(units(&cfg, Folds::asic(1, 6)).contains(&"dop_unit_fold6_k6_e8m15".to_string()));
    assert_eq!(
        units(&cfg, Folds::asic(8, 1))
            .iter()
            .filter(|n| n.starts_with("chip_"))
            .collect::<Vec<_>>(),
        ["chip_e8m15_k6", "chip_e8m15_k6_fold8"]
    );
    let both = units(&cfg, Folds::asic(32, 6));
    assert_eq!(
        both.iter()
            .filter(|n| n.starts_with("chip_"))
            .collect::<Vec<_>>(),
        ["chip_e8m15_k6", "chip_e8m15_k6_dop6_tri32"]
    );
    assert!(
        both.contains(&"dop_unit_fold6_k6_e8m15".to_string())
            && both.contains(&"tri_unit_fold32_e8m15_rne".to_string()),
        "{both:?}"
    );
}

/// The checked-in tables parse, and the paper clock is the preset's.
#[test]
fn technologies() {
    let cfg = ChipConfig::default();
    let osu = Clock::of(Technology::Osu018, &cfg, Folds::NONE, Preset::Rtl).unwrap();
    assert!(
        osu.source().contains("docs/figures/timing.csv"),
        "{}",
        osu.source()
    );
    // the ECP5 table clocks the ECP5 chip's configuration from a measured row (the
    // chip's own once it is placed on the current Verilog again)
    let (k6, folds) = (ChipKind::K6E8m15Dop6Tri32.config(), Folds::asic(32, 6));
    let ecp5 = Clock::of(Technology::Ecp5, &k6, folds, Preset::Rtl).unwrap();
    assert!(
        ecp5.slowest.is_some() && ecp5.source().contains("docs/figures/timing_ecp5.csv"),
        "{}",
        ecp5.source()
    );
    let paper = Clock::of(Technology::Paper, &cfg, Folds::NONE, Preset::Wscg03).unwrap();
    assert_eq!(paper.mhz(), 266.0);
    assert!(paper.source().contains("assumed"));
}
