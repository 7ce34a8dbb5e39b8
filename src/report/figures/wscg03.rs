//! WSCG'03's figures: Figs. 9-12 (the software traversals), Fig. 13 and Eq. 5 (its chip),
//! and its chip beside DATE'05's.

use super::{
    by_distance, eq5_cycles, key, mode_name, name, opt, panel, Point, PoseCounts, Runs, Times,
    DIST, KEY, MODES, SOFTWARE,
};
use crate::chip::reg::Mode;
use crate::report::plot::{Cell, Figure, Panel, Style, Table};

/// WSCG'03 Figs. 9-12: the golden model's list and recursive traversals.
pub(super) fn software_figures(points: &[Point]) -> Vec<Figure> {
    let sw = [
        ("Alg. 2 (list)", Style::Solid),
        ("Alg. 1 (recursive)", Style::Dashed),
    ];
    let mut figs = vec![];
    let mut t9 = Table {
        columns: [
            &KEY[..],
            &[
                "traversal",
                "mode",
                "pairs",
                "software_us",
                "node_fetches",
                "dop_transforms",
            ],
        ]
        .concat(),
        rows: vec![],
    };
    for p in points {
        for (si, &t) in SOFTWARE.iter().enumerate() {
            for (mi, &m) in MODES.iter().enumerate() {
                t9.rows.push(
                    [
                        &key(p)[..],
                        &[
                            Cell::Text(name(t).into()),
                            Cell::Text(mode_name(m).into()),
                            Cell::Num(p.mean(|c| c.sw_pairs[si][mi] as f64)),
                            Cell::Num(p.sw_us[si][mi]),
                            Cell::Num(p.mean(|c| c.sw_fetches[si][mi] as f64)),
                            Cell::Num(p.mean(|c| c.sw_transforms[si][mi] as f64)),
                        ],
                    ]
                    .concat(),
                );
            }
        }
    }
    let modes_panels =
        |y_label: &'static str, f: &dyn Fn(&Point, usize, usize) -> f64| -> Vec<Panel> {
            MODES
                .iter()
                .enumerate()
                .map(|(mi, &m)| {
                    let title = if m == Mode::All {
                        "all pairs"
                    } else {
                        "first witness"
                    };
                    panel(
                        title,
                        DIST,
                        y_label,
                        by_distance(points, &sw, |p, si| Some(f(p, si, mi))),
                    )
                })
                .collect()
        };
    let rows_of = |mode: Mode| Table {
        columns: t9.columns.clone(),
        rows: t9
            .rows
            .iter()
            .filter(|r| r[5] == Cell::Text(mode_name(mode).into()))
            .cloned()
            .collect(),
    };
    let time_panels = modes_panels("microseconds per query (this machine)", &|p, si, mi| {
        p.sw_us[si][mi]
    });
    figs.push(Figure {
        stem: "wscg03_fig9_first_witness",
        title: "WSCG'03 Fig. 9: software time, first witness (golden model, one query at a time)"
            .into(),
        panels: vec![time_panels[1].clone()],
        table: rows_of(Mode::First),
    });
    figs.push(Figure {
        stem: "wscg03_fig10_all_pairs",
        title: "WSCG'03 Fig. 10: software time, all pairs (golden model, one query at a time)"
            .into(),
        panels: vec![time_panels[0].clone()],
        table: rows_of(Mode::All),
    });
    figs.push(Figure {
        stem: "wscg03_fig11_nodes",
        title: "WSCG'03 Fig. 11: node words fetched (both trees; a node held from the last test is not fetched again)".into(),
        panels: modes_panels("node fetches per query", &|p, si, mi| p.mean(|c| c.sw_fetches[si][mi] as f64)),
        table: t9.clone(),
    });
    figs.push(Figure {
        stem: "wscg03_fig12_transforms",
        title: "WSCG'03 Fig. 12: DOP transforms of the tumbled object".into(),
        panels: modes_panels("DOP transforms per query", &|p, si, mi| {
            p.mean(|c| c.sw_transforms[si][mi] as f64)
        }),
        table: t9,
    });

    figs
}

/// WSCG'03 Fig. 13 and Eq. 5 on Fig. 13's preset: WSCG'03's chip clocked as its RTL, its
/// event model with the paper's parameters and Eq. 5, each at WSCG'03's chip's period, and
/// DATE'05's chip at its own; over the golden model's Alg. 2 and parry3d, of the chips'
/// time and end to end.
pub(super) fn fig13(points: &[Point], runs: &Runs) -> Figure {
    let eq5 = |p: &Point| p.mean(|c| eq5_cycles(c.lists, c.list_node_pairs));
    let clocks = |p: &Point, v: usize| match v {
        0 => p.mean(|c| c.stack_cycles as f64),
        1 => p.mean(|c| c.event_cycles as f64),
        2 => eq5(p),
        _ => p.mean(|c| c.wscg_cycles as f64),
    };
    let run = |v: usize| if v < 3 { &runs.stack } else { &runs.wscg };
    let times = |p: &Point, v: usize| Times::of(p, run(v), 1, clocks(p, v));
    const V: [usize; 4] = [0, 1, 2, 3];
    let mut t13 = Table {
        columns: [
            &KEY[..],
            &[
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
            ],
            &[
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
                "e2e_us_date05",
            ],
        ]
        .concat(),
        rows: vec![],
    };
    for p in points {
        let lists = p.mean(|c| c.lists as f64).max(1.0);
        let nums = [p.mean(|c| c.sw_pairs[0][0] as f64), p.sw_us[0][0]];
        let counts = V.map(|v| clocks(p, v));
        let per_list = [0, 1, 2].map(|v| clocks(p, v) / lists);
        let rest = [
            run(0).clock.period_ns,
            run(3).clock.period_ns,
            p.host[1].setup_us,
            p.host[1].settle_us,
        ];
        let golden = V.map(|v| Cell::Num(p.sw_us[0][0] / times(p, v).chip_us));
        let parry = V.map(|v| opt(p.parry_us.map(|x| x / times(p, v).chip_us)));
        let e2e = V.map(|v| Cell::Num(times(p, v).e2e_us));
        let alpha = p.mean(|c| c.list_node_pairs as f64) / lists;
        t13.rows.push(
            [
                &key(p)[..],
                &nums.map(Cell::Num)[..],
                &[opt(p.parry_us)],
                &counts.map(Cell::Num)[..],
                &[Cell::Num(lists), Cell::Num(alpha)],
                &per_list.map(Cell::Num)[..],
                &rest.map(Cell::Num)[..],
                &golden[..],
                &parry[..],
                &e2e[..],
            ]
            .concat(),
        );
    }
    let models = [
        ("WSCG'03's chip (clocked as its RTL)", Style::Solid),
        (
            "WSCG'03's chip, the paper's parameters (event model)",
            Style::Dotted,
        ),
        ("Eq. 5", Style::Dashed),
        ("DATE'05's chip, LIFO (cycle model)", Style::Points),
    ];
    let mut panels = vec![panel(
        &format!(
            "speed-up of the chips' time over the golden model's Alg. 2 (WSCG'03's at {}; DATE'05's at {})",
            run(0).period(),
            run(3).period()
        ),
        DIST,
        "speed-up",
        by_distance(points, &models, |p, v| {
            Some(p.sw_us[0][0] / times(p, v).chip_us)
        }),
    )];
    if points.iter().any(|p| p.parry_us.is_some()) {
        panels.push(panel(
            "speed-up of the chips' time over parry3d",
            DIST,
            "speed-up",
            by_distance(points, &models, |p, v| {
                p.parry_us.map(|x| x / times(p, v).chip_us)
            }),
        ));
    }
    panels.push(panel(
        "end to end (host setup + the chip's time + host settling)",
        DIST,
        "microseconds per query",
        by_distance(points, &models, |p, v| Some(times(p, v).e2e_us)),
    ));
    panels.push(panel(
        "the chips' clocks per query",
        DIST,
        "clocks",
        by_distance(points, &models, |p, v| Some(clocks(p, v))),
    ));
    Figure {
        stem: "wscg03_fig13_speedup",
        title: format!(
            "WSCG'03 Fig. 13: the chips over software on this machine, all pairs, {}",
            run(0).name()
        ),
        panels,
        table: t13,
    }
}

/// The two papers' chips on the same sweep and Fig. 13's preset, all pairs: clocks, time
/// at each one's period, DOP tests and tumbled-DOP transforms per clock (DATE'05's DOPTRF
/// transforms in every test), memory words, and their traversal memory (D_CNTR's queue
/// entries, two node pairs each; the Stack Engine's aligned pointers in its list SRAMs).
pub(super) fn side_by_side(points: &[Point], runs: &Runs) -> Figure {
    let chips = [
        ("WSCG'03's chip", Style::Solid),
        ("DATE'05's chip, LIFO", Style::Dashed),
    ];
    let mut t = Table {
        columns: [
            &KEY[..],
            &[
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
                "date05_queue_entries",
            ],
        ]
        .concat(),
        rows: vec![],
    };
    let per_clock = |p: &Point, f: fn(&PoseCounts) -> u64, clocks: fn(&PoseCounts) -> u64| {
        p.mean(|c| f(c) as f64) / p.mean(|c| clocks(c) as f64).max(1.0)
    };
    // all pairs, both chips test the golden traversal's DOP pairs (tb/wscg03.rs,
    // tb/cycle_chip.rs): one count; DATE'05 transforms in every test
    for p in points {
        let clocks = [
            p.mean(|c| c.stack_cycles as f64),
            p.mean(|c| c.wscg_cycles as f64),
        ];
        let nums = [
            clocks[0],
            clocks[1],
            runs.stack.us(clocks[0]),
            runs.wscg.us(clocks[1]),
            per_clock(p, |c| c.stack_dop_tests, |c| c.stack_cycles),
            per_clock(p, |c| c.stack_dop_tests, |c| c.wscg_cycles),
            per_clock(p, |c| c.stack_transforms, |c| c.stack_cycles),
            per_clock(p, |c| c.stack_dop_tests, |c| c.wscg_cycles),
            p.mean(|c| c.stack_words as f64),
            p.mean(|c| c.wscg_words as f64),
        ];
        let mem = [
            Cell::Int(p.max(|c| c.stack_pointers)),
            Cell::Int(p.max(|c| c.wscg_entries)),
        ];
        t.rows
            .push([&key(p)[..], &nums.map(Cell::Num)[..], &mem[..]].concat());
    }
    let y = |p: &Point, v: usize| {
        Some(p.mean(|c| if v == 0 { c.stack_cycles } else { c.wscg_cycles } as f64))
    };
    Figure {
        stem: "wscg03_vs_date05",
        title: format!(
            "WSCG'03's chip and DATE'05's on the same memory, all pairs ({})",
            runs.stack.name()
        ),
        panels: vec![panel(
            "clocks per query",
            DIST,
            "clocks",
            by_distance(points, &chips, y),
        )],
        table: t,
    }
}
