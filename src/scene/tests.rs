use super::*;
use crate::chip::config::MemLayout;
use crate::chip::rtl::Depth;

#[test]
fn default_scene_parses() {
    let s = Scene::parse(DEFAULT_SCENE, "default").unwrap();
    assert!(s.outputs.accuracy);
    assert!(!s.poses.is_empty());
}

/// Every scene shipped in vectors/scenes/ loads (meshes not read).
#[test]
fn shipped_scenes_parse() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/scenes");
    for e in std::fs::read_dir(&dir).unwrap() {
        let p = e.unwrap().path();
        Scene::load(&p).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[test]
fn errors_name_the_line() {
    let text = "[objects]\na = \"bunny\"\nb = \"bunny\"\n[chip]\nk = \"x\"\n";
    let e = Scene::parse(text, "s.toml").unwrap_err();
    assert!(e.starts_with("s.toml:5:"), "{e}");
    let e = Scene::parse(
        "[objects]\na = \"x\"\nb = \"y\"\n[chip]\nk = 8\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n",
        "s.toml",
    )
    .unwrap_err();
    assert!(e.contains("6, 14, 18, 24, 26"), "{e}");
    let e = Scene::parse("[objects]\na = \"x\"\nb = \"y\"\n", "s.toml").unwrap_err();
    assert!(e.contains("no pose"), "{e}");
    let e = Scene::parse("[objects]\na = \"x\"\nb = \"y\"\nbogus = 1\n", "s.toml").unwrap_err();
    assert!(e.starts_with("s.toml:4:"), "{e}");
    // one [pose] table where the key takes a list
    let e = Scene::parse(
        "[objects]\na = \"x\"\nb = \"y\"\n[pose] # one\nrot_deg = [0, 0, 0]\nt = [0, 0, 0]\n",
        "s.toml",
    )
    .unwrap_err();
    assert!(
        e.starts_with("s.toml:4:") && e.contains("write [[pose]]"),
        "{e}"
    );
}

#[test]
fn cycle_outputs_timing_and_memory() {
    use crate::chip::memory::MemTiming;
    use crate::chip::params::Params;
    let base =
        "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n";
    let s = Scene::parse(
        &format!("{base}[outputs]\nwaveforms = \"w\"\n[memory]\nlatency = 3\ninterval = 2\n"),
        "s",
    )
    .unwrap();
    assert_eq!(s.outputs.waveforms, Some(Waveforms::all("w".into())));
    assert!(!s.outputs.cycles, "waveforms alone need no counters");
    assert_eq!(
        s.params,
        Params {
            memory: MemTiming {
                latency: 3,
                interval: 2,
                bus_bits: None
            }
            .into(),
            // the memory counted at the scene's clock
            clock_ps: s.clock.as_ref().unwrap().ps(),
            ..Params::RTL
        }
    );
    let s = Scene::parse(base, "s").unwrap();
    assert!(!s.outputs.cycles);
    assert_eq!((s.params, s.clock), (Params::RTL, None));
    // no output runs the chip: the preset's own clock, and the memory in ns alone
    let w = Scene::parse(&format!("{base}[chip]\npreset = \"wscg03\"\n"), "s").unwrap();
    assert_eq!((w.clock.is_none(), w.params.clock_ps), (true, 3759));
    let c = w.configuration();
    assert!(
        c.contains("miss 75 ns") && !c.contains("at the chip's"),
        "{c}"
    );
    let s = Scene::parse(&format!("{base}[outputs]\ncycles = true\n"), "s").unwrap();
    assert_eq!(s.clock.unwrap().technology, Some(Technology::Osu018));
    let s = Scene::parse(&format!("{base}[outputs]\ncross_check = \"rtl\"\n[chip]\nk = 6\nformat = \"reduced\"\n[timing]\ncredit = 4\nclock_mhz = 266\n"), "s").unwrap();
    assert!(s.outputs.cross_check == Some(CrossCheck::Rtl));
    assert_eq!((s.params.credit, s.clock.unwrap().mhz()), (4, 266.0));
    let e = Scene::parse(
        &format!("{base}[outputs]\ncycles = true\n[memory]\nlatency = 0\ninterval = 1\n"),
        "s",
    )
    .unwrap_err();
    assert!(e.contains("at least 1"), "{e}");
    let e = Scene::parse(
        &format!("{base}[outputs]\ncycles = true\n[timing]\nissue_spacing = 5\n"),
        "s",
    )
    .unwrap_err();
    assert!(e.contains("issue_spacing"), "{e}");
    let e = Scene::parse(
        &format!("{base}[outputs]\nwaveforms = {{ dir = \"w\", scopes = [\"dcntr\"] }}\n"),
        "s",
    )
    .unwrap_err();
    assert!(
        e.contains("no scope \"dcntr\"; the scopes are host, d_cntr"),
        "{e}"
    );
    let e = Scene::parse(
        &format!("{base}[outputs]\nwaveforms = {{ dir = \"w\", cycle = [5, 4] }}\n"),
        "s",
    )
    .unwrap_err();
    assert!(e.contains("unknown key \"cycle\""), "{e}");
    let e = Scene::parse(
        &format!("{base}[outputs]\nwaveforms = {{ dir = \"w\", cycles = [5, 4] }}\n"),
        "s",
    )
    .unwrap_err();
    assert!(e.contains("is empty"), "{e}");
    let s = Scene::parse(
        &format!("{base}[outputs]\nwaveforms = {{ dir = \"w\", cycles = [5, 5] }}\n"),
        "s",
    )
    .unwrap();
    assert_eq!(s.outputs.waveforms.unwrap().window, 5..6);
    let e = Scene::parse(&format!("{base}[memory]\nlatncy = 2\n"), "s").unwrap_err();
    assert!(e.starts_with("s:8:"), "{e}");
}

/// B's triangle cache and the triangle prefetch, which no RTL chip has, are refused for a
/// cross-check, naming what to change.
#[test]
fn rtl_refuses_the_cycle_models_memory_side() {
    let base =
        "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n";
    for (keys, why) in [
        (
            "[chip]\ntri_cache_b = 4\n",
            "the RTL chips hold one triangle word of B; this configuration has tri_cache_b = 4",
        ),
        (
            "[timing]\ntri_prefetch = true\n",
            "the RTL chips ask for a leaf pair's triangle words when it reaches the leaf register",
        ),
    ] {
        let e = Scene::parse(
            &format!("{base}[outputs]\ncross_check = \"rtl\"\n{keys}"),
            "s",
        )
        .unwrap_err();
        assert!(e.contains(why), "{e}");
    }
}

/// Which configurations an RTL chip runs (`rtl_order`), and what the refusals say to change.
#[test]
fn rtl_order_names_what_to_change() {
    use crate::chip::params::Params;
    let base =
        "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n";
    use crate::chip::reg::Order;
    use crate::chip::rtl::ChipKind;
    let rtl = Scene::parse(
        include_str!("../../vectors/scenes/rtl_spheres.toml"),
        "rtl_spheres",
    )
    .unwrap();
    assert_eq!(
        crate::harness::chip_io::rtl_order(&rtl.cfg, rtl.traversal, &rtl.params),
        Ok((ChipKind::K6E8m15, Order::Lifo))
    );
    // the scene itself is refused where its configuration has no RTL chip
    let e = Scene::parse(
        &format!("{base}[outputs]\ncross_check = \"rtl\"\n[chip]\nnode_cache = 16\n"),
        "s",
    )
    .unwrap_err();
    assert!(e.starts_with("s:8: [outputs] cross_check: cross_check = \"rtl\" needs an RTL chip of the configuration: the RTL chips hold one node record per object; this configuration has node_cache = 16"), "{e}");
    // the default configuration is the papers' chip
    assert_eq!(
        crate::harness::chip_io::rtl_order(&ChipConfig::default(), Traversal::Fifo, &rtl.params),
        Ok((ChipKind::K24B32, Order::Fifo))
    );
    let e = crate::harness::chip_io::rtl_order(
        &ChipConfig {
            k: 14,
            ..ChipConfig::default()
        },
        Traversal::Lifo,
        &rtl.params,
    )
    .unwrap_err();
    assert!(e.contains("k = 6, format = \"e8m15\" or k = 24, format = \"binary32\" or k = 24, format = \"e8m15/binary32\"") && e.contains("k = 14"), "{e}");
    // the triangle cache: a power of two; the RTL chips hold one word
    let s = Scene::parse(&format!("{base}[chip]\ntri_cache = 128\n"), "s").unwrap();
    assert_eq!(s.cfg.tri_cache, 128);
    let e = Scene::parse(&format!("{base}[chip]\ntri_cache = 100\n"), "s").unwrap_err();
    assert!(
        e.contains("[chip] tri_cache must be a power of two from 1 to 1024 lines"),
        "{e}"
    );
    assert!(crate::harness::chip_io::rtl_order(
        &ChipConfig {
            tri_cache: 128,
            ..rtl.cfg
        },
        Traversal::Lifo,
        &rtl.params
    )
    .is_ok());
    let e = crate::harness::chip_io::rtl_order(
        &ChipConfig {
            tri_cache: 256,
            ..rtl.cfg
        },
        Traversal::Lifo,
        &rtl.params,
    )
    .unwrap_err();
    assert!(
        e.contains("tri_cache = 256") && e.contains("at most 128"),
        "{e}"
    );
    let e = crate::harness::chip_io::rtl_order(&rtl.cfg, Traversal::List, &rtl.params).unwrap_err();
    assert!(e.contains("fifo or lifo"), "{e}");
    let e = crate::harness::chip_io::rtl_order(
        &rtl.cfg,
        Traversal::Lifo,
        &Params {
            tri_fifo: 4,
            ..rtl.params
        },
    )
    .unwrap_err();
    assert!(e.contains("[timing]"), "{e}");
}

/// The RTL chips' memory port register and memory layouts: what they take, and what the
/// refusals say to change.
#[test]
fn rtl_order_of_port_and_layout() {
    use crate::chip::params::Params;
    use crate::chip::reg::Order;
    use crate::chip::rtl::ChipKind;
    let rtl = Scene::parse(
        include_str!("../../vectors/scenes/rtl_spheres.toml"),
        "rtl_spheres",
    )
    .unwrap();
    // the memory port's register: within its fields, and no further
    let port = Params {
        prefetch: 14,
        outstanding: 16,
        credit: 63,
        issue_spacing: 1,
        ..rtl.params
    };
    assert_eq!(
        crate::harness::chip_io::rtl_order(&rtl.cfg, Traversal::Lifo, &port),
        Ok((ChipKind::K6E8m15, Order::Lifo))
    );
    for p in [
        Params {
            prefetch: 15,
            ..port
        },
        Params {
            outstanding: 17,
            ..port
        },
        Params { credit: 64, ..port },
    ] {
        let e = crate::harness::chip_io::rtl_order(&rtl.cfg, Traversal::Lifo, &p).unwrap_err();
        assert!(
            e.contains(
                "at most 14 pairs with at most 16 requests outstanding and a credit of at most 63"
            ),
            "{e}"
        );
    }
    // the records layout: the k = 24 binary32 chip, one record held, on any memory
    use crate::chip::config::MemLayout;
    let rec = ChipConfig {
        layout: MemLayout::Records,
        ..ChipConfig::default()
    };
    assert_eq!(
        crate::harness::chip_io::rtl_order(&rec, Traversal::Fifo, &rtl.params),
        Ok((ChipKind::K24B32, Order::Fifo))
    );
    let ddr = |banks| Params {
        memory: crate::chip::memory::Memory::Ddr(crate::chip::memory::Ddr {
            banks,
            ..crate::chip::memory::Ddr::DATE05
        }),
        ..rtl.params
    };
    assert!([2, 6, 8]
        .iter()
        .all(|&b| crate::harness::chip_io::rtl_order(&rec, Traversal::Fifo, &ddr(b)).is_ok()));
    let e = crate::harness::chip_io::rtl_order(
        &ChipConfig {
            node_cache: 16,
            ..rec
        },
        Traversal::Fifo,
        &ddr(8),
    )
    .unwrap_err();
    assert!(
        e.contains("this configuration has node_cache = 16: set [chip] node_cache = 1"),
        "{e}"
    );
    let e = crate::harness::chip_io::rtl_order(
        &ChipConfig {
            layout: MemLayout::Records,
            ..rtl.cfg
        },
        Traversal::Fifo,
        &ddr(8),
    )
    .unwrap_err();
    assert!(e.contains("chip_e8m15_k6 reads the `words` layout only (of the RTL chips, chip_b32_k24, chip_e8m15_b32_k24, chip_e8m15_k24, chip_e8m10_k24, chip_b32_k24_q4 also read `records`); this configuration has layout = \"records\""), "{e}");
}

/// Stored DOP precision: the chip of 4-bit codes runs them, the others name it.
#[test]
fn rtl_order_of_stored_dops() {
    use crate::chip::reg::Order;
    use crate::chip::rtl::ChipKind;
    let rtl = Scene::parse(
        include_str!("../../vectors/scenes/rtl_spheres.toml"),
        "rtl_spheres",
    )
    .unwrap();
    let coded = |b| ChipConfig {
        layout: MemLayout::Records,
        dop_bits: crate::chip::config::DopBits::Bits(b),
        ..ChipConfig::default()
    };
    assert_eq!(
        crate::harness::chip_io::rtl_order(&coded(4), Traversal::Fifo, &rtl.params),
        Ok((ChipKind::K24B32Q4, Order::Fifo))
    );
    let e =
        crate::harness::chip_io::rtl_order(&coded(8), Traversal::Fifo, &rtl.params).unwrap_err();
    assert!(e.contains("chip_b32_k24 reads node records of dop_bits = full (of the RTL chips, chip_b32_k24_q4 (dop_bits = 4) read stored DOPs); this configuration has dop_bits = 8: set [chip] dop_bits = \"full\""), "{e}");
}

/// `[memory]` picks the ideal model or DDR SDRAM with a preset and overrides; mixed or
/// unknown keys are errors that say what to write.
/// `[timing] tri_interval`: 1 or even 2 to 32, no tri_latency beside a fold, DATE'05's
/// chip only, and an RTL cross-check only at an interval an RTL chip of the configuration
/// is built with (k = 6 e8m15: dop_interval and tri_interval 1 and 1, 1 and 16, 6 and 32).
#[test]
fn tri_interval_key() {
    let base = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n[outputs]\ncycles = true\n";
    let s = Scene::parse(
        &format!("{base}[chip]\npreset = \"date05\"\n[timing]\ntri_interval = 16\n"),
        "s",
    )
    .unwrap();
    assert_eq!(
        s.params,
        Params {
            tri_interval: 16,
            clock_ps: s.clock.as_ref().unwrap().ps(),
            ..Preset::Date05.params()
        }
    );
    assert!(
        s.configuration()
            .contains("tri_interval 16 (folded TRI_UNIT"),
        "{}",
        s.configuration()
    );
    // the folded TRI_UNIT has a row; the folded chip as a whole has none
    let clock = s.clock.unwrap();
    assert!(
        clock
            .source()
            .contains("units not measured: chip_b32_k24_fold16"),
        "{}",
        clock.source()
    );
    let s8 = Scene::parse(
        &format!("{base}[chip]\npreset = \"date05\"\n[timing]\ntri_interval = 8\n"),
        "s",
    )
    .unwrap()
    .clock
    .unwrap();
    assert!(
        s8.not_measured
            .contains(&"tri_unit_fold8_b32_rne".to_string()),
        "{}",
        s8.source()
    );
    for (keys, want) in [
        ("tri_interval = 3", "tri_interval must be 1 (TRI_UNIT unfolded) or an even number of clocks from 2 to 32"),
        ("tri_interval = 34", "not 34"),
        ("tri_interval = 0", "not 0"),
        ("tri_interval = 4\ntri_latency = 60", "s:11: [timing] tri_latency is the unfolded TRI_UNIT's latency, not used by the folded one (tri_interval 4)"),
        // a key is refused for being there, whatever its value: the default's too
        ("tri_interval = 4\ntri_latency = 54", "s:11: [timing] tri_latency is the unfolded TRI_UNIT's latency"),
        ("dop_interval = 6\ndop_latency = 15", "s:11: [timing] dop_latency is the unfolded DOP unit's latency, not used by the folded one (dop_interval 6), whose latency is its schedule's (20 clocks)"),
        ("dop_latency = 16\ndop_interval = 6", "s:10: [timing] dop_latency is the unfolded DOP unit's latency"),
        ("dop_interval = 5", "dop_interval 5 does not divide k = "),
    ] {
        let e = Scene::parse(&format!("{base}[timing]\n{keys}\n"), "s").unwrap_err();
        assert!(e.contains(want), "{e}");
    }
    let e = Scene::parse(
        &format!("{base}[chip]\npreset = \"wscg03\"\n[timing]\ntri_interval = 2\n"),
        "s",
    )
    .unwrap_err();
    assert!(
        e.contains("[timing] tri_interval is DATE'05's chip's") && e.contains("clocked as its RTL"),
        "{e}"
    );
    // the command line's architecture over a scene's keys: the same refusal as the preset's
    let flags = Flags {
        architecture: Some(Architecture::Wscg03),
        ..Default::default()
    };
    let e =
        Scene::parse_with(&format!("{base}[timing]\ntri_interval = 2\n"), "s", flags).unwrap_err();
    assert!(
        e.starts_with("s:10: [timing] tri_interval is DATE'05's chip's"),
        "{e}"
    );
    let rtl = Scene::parse(
        include_str!("../../vectors/scenes/rtl_spheres.toml"),
        "rtl_spheres",
    )
    .unwrap();
    let order = |dop_interval, tri_interval| {
        crate::harness::chip_io::rtl_order(
            &rtl.cfg,
            rtl.traversal,
            &Params {
                dop_interval,
                tri_interval,
                ..rtl.params
            },
        )
    };
    let e = order(1, 2).unwrap_err();
    assert!(e.contains("every 2") && e.contains("1 and 1 (chip_e8m15_k6) or 1 and 16 (chip_e8m15_k6_fold16) or 6 and 32 (chip_e8m15_k6_dop6_tri32)"), "{e}");
    assert!(order(6, 16).is_err() && order(6, 1).is_err());
    assert_eq!(
        order(1, 16).unwrap().0,
        crate::chip::rtl::ChipKind::K6E8m15Fold16
    );
    assert_eq!(
        order(6, 32).unwrap().0,
        crate::chip::rtl::ChipKind::K6E8m15Dop6Tri32
    );
    let fpga = crate::harness::chip_io::rtl_order(
        &rtl.cfg,
        rtl.traversal,
        &Params {
            dop_interval: 6,
            tri_interval: 32,
            depth: Depth::Fpga,
            ..rtl.params
        },
    );
    assert_eq!(
        fpga.unwrap().0,
        crate::chip::rtl::ChipKind::K6E8m15Dop6Tri32Fpga
    );
    assert!(
        e.contains("6 and 32 at depth = \"fpga\" (chip_e8m15_k6_dop6_tri32_fpga)"),
        "{e}"
    );
}

/// `[timing] depth`: "fpga" gives the folded units their FPGA-depth latencies (the
/// configuration line says so), needs a folded TRI_UNIT and refuses dop_latency.
#[test]
fn depth_key() {
    let base = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n[outputs]\ncycles = true\n[chip]\npreset = \"rtl\"\n[timing]\n";
    let s = Scene::parse(
        &format!("{base}dop_interval = 6\ntri_interval = 32\ndepth = \"fpga\"\n"),
        "s",
    )
    .unwrap();
    assert_eq!(s.params.depth, Depth::Fpga);
    assert_eq!(s.params.dop_unit_latency(), 31);
    assert!(
        s.configuration().contains("depth = \"fpga\""),
        "{}",
        s.configuration()
    );
    for (keys, want) in [
        (
            "depth = \"fpga\"",
            "s:12: [timing] depth = \"fpga\" cuts T.CHECK's units for the folded TRI_UNIT",
        ),
        (
            "tri_interval = 32\ndepth = \"fpga\"\ndop_latency = 15",
            "s:14: [timing] dop_latency is the DOP unit's latency at ASIC depth",
        ),
        ("depth = \"deep\"", "unknown variant `deep`"),
    ] {
        let e = Scene::parse(&format!("{base}{keys}\n"), "s").unwrap_err();
        assert!(e.contains(want), "{keys}: {e}");
    }
}

#[test]
fn memory_models_and_presets() {
    use crate::chip::memory::Ddr;
    use crate::chip::memory::Memory;
    let base = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n[outputs]\ncycles = true\n[memory]\n";
    let mem = |m: &str| Scene::parse(&format!("{base}{m}"), "s").map(|s| s.params.memory);
    assert_eq!(
        mem("model = \"ddr\"\npreset = \"wscg03\""),
        Ok(Memory::Ddr(Ddr::WSCG03))
    );
    assert_eq!(
        mem("model = \"ddr\"\npreset = \"date05\"\nbanks = 4"),
        Ok(Memory::Ddr(Ddr {
            banks: 4,
            ..Ddr::DATE05
        }))
    );
    let own = "model = \"ddr\"\nbanks = 2\npage_bytes = 1024\nbus_bits = 64\nburst = 4\nbeat_ns = 1.5\nhit_ns = 7.5\nmiss_ns = 15.001";
    assert_eq!(
        mem(own),
        Ok(Memory::Ddr(Ddr {
            banks: 2,
            page_bytes: 1024,
            bus_bits: 64,
            burst: 4,
            beat_ps: 1500,
            hit_ps: 7500,
            miss_ps: 15001
        }))
    );
    assert_eq!(
        mem("latency = 8\nbus_bits = 128"),
        Ok(Memory::Ideal(crate::chip::memory::MemTiming {
            latency: 8,
            interval: 1,
            bus_bits: Some(128)
        }))
    );
    for (m, want) in [
        ("model = \"ddr\"", "needs a preset"),
        (
            "model = \"ddr\"\nbanks = 2\npage_bytes = 1024\nbus_bits = 64\nburst = 4\nbeat_ns = 1\nhit_ns = 6",
            "(miss_ns is missing)",
        ),
        (
            "model = \"ddr\"\npreset = \"ddr4\"",
            "preset \"ddr4\" is not known",
        ),
        (
            "model = \"ddr\"\npreset = \"wscg03\"\nlatency = 3",
            "s:12: [memory] latency belongs to the ideal memory, not used by the DDR model",
        ),
        (
            "preset = \"wscg03\"",
            "s:10: [memory] preset belongs to model = \"ddr\", not used by the ideal memory",
        ),
        ("hit_ns = 8", "s:10: [memory] hit_ns belongs to model = \"ddr\""),
        (
            "model = \"ddr\"\npreset = \"wscg03\"\nhit = 8",
            "hit is a number of clocks, which depend on the chip's clock: write hit_ns",
        ),
        (
            "model = \"ddr\"\npreset = \"wscg03\"\nmiss_ns = 0.0001",
            "miss_ns = 0.0001 must be from 0.001 to 1000000 ns, to the picosecond",
        ),
        ("bus_bits = 0", "bus_bits must be at least 1"),
        ("model = \"sram\"", "model \"sram\" is not known"),
        (
            "model = \"ddr\"\npreset = \"wscg03\"\nhit_ns = 29.999",
            "burst x beat_ns <= hit_ns <= miss_ns",
        ),
    ] {
        let e = mem(m).unwrap_err();
        assert!(e.starts_with("s:") && e.contains(want), "{m}: {e}");
    }
    let s = Scene::parse(&format!("{base}model = \"ddr\"\npreset = \"wscg03\""), "s").unwrap();
    let explain = crate::scene::graph::Plan::of(&s).explain(&s);
    assert!(explain.contains("DDR SDRAM: 4 banks, 4096-byte pages, 256-bit bus, bursts of 8 beats of 3.75 ns, page hit 30 ns and miss 75 ns; at the chip's 7.135 ns clock: a burst 5 clock(s), a page hit 5, a miss 11"), "{explain}");
    // model = "ddr" written on a DDR chip preset keeps the preset's DDR values
    let on = |preset: &str, m: &str| {
        Scene::parse(&format!("{base}{m}\n[chip]\npreset = \"{preset}\""), "s")
            .map(|s| s.params.memory)
    };
    assert_eq!(
        on("date05", "model = \"ddr\""),
        Ok(Memory::Ddr(Ddr::DATE05))
    );
    assert_eq!(
        on("wscg03", "model = \"ddr\"\nbanks = 2"),
        Ok(Memory::Ddr(Ddr {
            banks: 2,
            ..Ddr::WSCG03
        }))
    );
    assert_eq!(
        on("wscg03", "model = \"ddr\"\npreset = \"date05\""),
        Ok(Memory::Ddr(Ddr::DATE05))
    );
}

/// The chip for bandwidth: date05's chip, port, memory and clock but for its memory side.
#[test]
fn date05_treelets_is_date05_with_its_memory_side() {
    let base = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n[outputs]\ncycles = true\n";
    let parse = |t: &str| {
        Scene::parse(
            &format!("{base}[chip]\npreset = \"{t}\"\n[timing]\ntechnology = \"paper\""),
            "s",
        )
        .unwrap()
    };
    let (date05, t) = (parse("date05"), parse("date05-treelets"));
    assert_eq!(
        t.cfg,
        ChipConfig {
            dop_bits: crate::chip::config::DopBits::Bits(4),
            node_cache: 64,
            tri_cache: 128,
            tri_cache_b: 128,
            ..date05.cfg
        }
    );
    assert_eq!(
        t.params,
        Params {
            tri_prefetch: true,
            ..date05.params
        }
    );
    assert_eq!(t.clock.as_ref().unwrap().mhz(), 800.0);
}

/// A chip preset is the base of `[chip]`, `[timing]`, `[memory]` and the clock; the
/// scene's keys override each of its values, and `--preset` replaces the scene's.
#[test]
fn chip_presets_and_their_overrides() {
    use crate::chip::memory::Memory;
    let base = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n[outputs]\ncycles = true\n";
    let mhz = |s: &Scene| s.clock.as_ref().unwrap().mhz();
    let parse = |t: &str| Scene::parse(&format!("{base}{t}"), "s");
    // no preset: the RTL's reset values, as before presets
    let rtl = parse("").unwrap();
    assert_eq!(
        (rtl.preset, rtl.cfg, rtl.params),
        (
            Preset::Rtl,
            ChipConfig::default(),
            Params {
                clock_ps: rtl.clock.as_ref().unwrap().ps(),
                ..Params::RTL
            }
        )
    );
    let d = parse("[chip]\npreset = \"date05\"\n[timing]\ntechnology = \"paper\"").unwrap();
    assert_eq!(
        (d.cfg.k, d.params.memory, mhz(&d)),
        (24, Memory::Ddr(Ddr::DATE05), 800.0)
    );
    // DDR2's ns at the paper's 1.25 ns: its 14 and 34 clocks
    assert!(
        d.configuration()
            .contains("at the chip's 1.25 ns clock: a burst 4 clock(s), a page hit 14, a miss 34"),
        "{}",
        d.configuration()
    );
    assert_eq!(
        (
            d.params.issue_spacing,
            d.params.outstanding,
            d.params.prefetch,
            d.params.credit
        ),
        (1, 16, 14, 48)
    );
    // each key over the preset's value, the rest kept
    let o = parse("[chip]\npreset = \"date05\"\nk = 6\n[timing]\ncredit = 32\nclock_mhz = 400\n[memory]\nbanks = 4").unwrap();
    assert_eq!(
        (
            o.cfg.k,
            o.cfg.format,
            o.params.credit,
            o.params.prefetch,
            mhz(&o)
        ),
        (6, d.cfg.format, 32, 14, 400.0)
    );
    assert_eq!(
        o.params.memory,
        Memory::Ddr(Ddr {
            banks: 4,
            ..Ddr::DATE05
        })
    );
    // the same DDR2 at 400 MHz, twice the paper's period: half its clocks
    assert_eq!(o.params.clock_ps, 2500);
    assert!(
        o.configuration()
            .contains("at the chip's 2.5 ns clock: a burst 2 clock(s), a page hit 7, a miss 17"),
        "{}",
        o.configuration()
    );
    // a memory model named replaces the preset's
    let i = parse("[chip]\npreset = \"date05\"\n[memory]\nmodel = \"ideal\"").unwrap();
    assert_eq!(i.params.memory, Memory::Ideal(MemTiming::default()));
    let w = parse("[chip]\npreset = \"wscg03\"\n[timing]\ntechnology = \"paper\"").unwrap();
    assert_eq!(
        (w.cfg.tri_cache, w.params.memory, mhz(&w)),
        (128, Memory::Ddr(Ddr::WSCG03), 266.0)
    );
    // the wscg03 preset runs WSCG'03's chip; a scene's architecture key over any preset
    assert_eq!(
        (w.architecture, d.architecture, rtl.architecture),
        (
            Architecture::Wscg03,
            Architecture::Date05,
            Architecture::Date05
        )
    );
    let a = parse("[chip]\npreset = \"wscg03\"\narchitecture = \"date05\"").unwrap();
    assert_eq!(
        (
            a.architecture,
            a.cfg.tri_cache,
            a.cfg.layout,
            a.cfg.node_cache
        ),
        (Architecture::Date05, 128, MemLayout::Records, 16)
    );
    // WSCG'03's chip reads its own memory side (a node pair per record); no scene uses
    // [stack_engine], the paper's timing of its event model
    assert_eq!((w.cfg.layout, w.cfg.node_cache), (MemLayout::Records, 1));
    for arch in ["date05", "wscg03"] {
        let e = parse(&format!(
            "[chip]\npreset = \"wscg03\"\narchitecture = \"{arch}\"\n[stack_engine]\nword_buffer = 4"
        ))
        .unwrap_err();
        assert!(
            e.starts_with(
                "s:13: [stack_engine] word_buffer is WSCG'03's chip's timing as the paper gives it"
            ),
            "{e}"
        );
    }
    let e = parse("[chip]\narchitecture = \"wscg04\"").unwrap_err();
    assert!(
        e.starts_with("s:10:") && e.contains("\"date05\" or \"wscg03\""),
        "{e}"
    );
    // WSCG'03's chip streams binary32
    let e = parse("[chip]\narchitecture = \"wscg03\"\nformat = \"e8m15\"").unwrap_err();
    assert!(
        e.starts_with("s:11: [chip] format: WSCG'03's chip streams eight binary32 distances"),
        "{e}"
    );
    // --preset replaces the scene's preset, not its keys
    let f = Scene::parse_with(
        &format!("{base}[chip]\npreset = \"date05\"\nk = 6"),
        "s",
        Flags {
            preset: Some(Preset::Rtl),
            ..Default::default()
        },
    )
    .unwrap();
    let clock_ps = f.clock.as_ref().unwrap().ps();
    assert_eq!(
        (f.preset, f.cfg.k, f.params),
        (
            Preset::Rtl,
            6,
            Params {
                clock_ps,
                ..Params::RTL
            }
        )
    );
    let e = parse("[chip]\npreset = \"date06\"").unwrap_err();
    assert!(
        e.starts_with("s:10:")
            && e.contains("\"date05\", \"date05-treelets\", \"wscg03\" or \"rtl\""),
        "{e}"
    );
    let e = parse("[chip]\nkk = 6").unwrap_err();
    assert!(
        e.starts_with("s:10: [chip]") && e.contains("unknown field `kk`"),
        "{e}"
    );
    assert!(graph::Plan::of(&d).explain(&d).contains("preset date05"));
}

/// Mesh paths were resolved against the current directory.
#[test]
fn mesh_paths_are_relative_to_the_scene() {
    let dir = std::env::temp_dir().join(format!("cchip-scene-test-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    std::fs::write(
        dir.join("sub/m.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    )
    .unwrap();
    let scene = dir.join("s.toml");
    let text =
        "[objects]\na = \"sub/m.obj\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n";
    std::fs::write(&scene, text).unwrap();
    let s = Scene::load(&scene).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(Path::new(&s.objects.a), dir.join("sub/m.obj"));
    assert_eq!(s.objects.b, "sphere:12");
}
/// The clock: the configuration's measured period by default, the paper's with
/// `technology = "paper"`, an assumed `clock_mhz`; never both; `--technology` over all.
#[test]
fn clock_technology() {
    let base = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n[chip]\nk = 6\nformat = \"reduced\"\n[outputs]\ncycles = true\n";
    let parse = |t: &str| Scene::parse(&format!("{base}{t}"), "s");
    let mhz = |t: &str| parse(t).unwrap().clock.unwrap().mhz();
    let m = parse("").unwrap();
    assert_eq!(
        m.clock,
        Some(Clock::of(Technology::Osu018, &m.cfg, Folds::NONE, Preset::Rtl).unwrap())
    );
    assert!(
        m.configuration().contains(
            "measured, the whole chip chip_e8m15_k6 (OSU 0.18 um, docs/figures/timing.csv)"
        ),
        "{}",
        m.configuration()
    );
    assert_eq!(mhz("[timing]\ntechnology = \"paper\""), 800.0);
    let e = parse("[timing]\ntechnology = \"paper\"\nclock_mhz = 3").unwrap_err();
    assert!(e.contains("not both"), "{e}");
    let e = parse("[timing]\ntechnology = \"tsmc\"").unwrap_err();
    assert!(
        e.starts_with("s:13:") && e.contains("\"osu018\", \"ecp5\" or \"paper\""),
        "{e}"
    );
    let flags = Flags {
        technology: Some(Technology::Paper),
        ..Default::default()
    };
    assert_eq!(
        Scene::parse_with(&format!("{base}[timing]\nclock_mhz = 3"), "s", flags)
            .unwrap()
            .clock
            .unwrap()
            .mhz(),
        800.0
    );
    // an assumed clock gives a finite time in microseconds to every query the model runs
    assert_eq!(
        (
            mhz("[timing]\nclock_mhz = 0.001"),
            mhz("[timing]\nclock_mhz = 1e5")
        ),
        (0.001, 1e5)
    );
    for bad in ["1e-307", "0.0009", "2e5", "0", "-3", "nan", "inf"] {
        let e = parse(&format!("[timing]\nclock_mhz = {bad}")).unwrap_err();
        assert!(
            e.contains("clock_mhz must be from 0.001 to 100000 MHz"),
            "{bad}: {e}"
        );
    }
    // the number as a user reads it, not 307 zeros
    assert!(parse("[timing]\nclock_mhz = 1e-307")
        .unwrap_err()
        .ends_with("MHz, not 1e-307"));
    // a datapath with no measured unit and no wider format measured: no period to report
    let e = Scene::parse(
        &format!("{base}[chip]\nformat = \"e8m24\"")
            .replace("[chip]\nk = 6\nformat = \"reduced\"\n", ""),
        "s",
    )
    .unwrap_err();
    assert!(
        e.contains("measures none of this configuration's DOP datapath's units (fp_mul_e8m24_ru")
            && e.contains("clock_mhz"),
        "{e}"
    );
    // ... unless no output runs the chip: then there is no clock to refuse
    let golden = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n[chip]\nformat = \"e8m24\"\n";
    assert_eq!(Scene::parse(golden, "s").unwrap().clock, None);
}
