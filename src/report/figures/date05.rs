//! DATE'05's figures: Figs. 6 and 7 (clocks and queue entries, LIFO against FIFO) and Fig. 8
//! (the chip's speed-up over software).

use super::{
    by_distance, key, mode_name, name, opt, panel, ChipRun, Point, Times, DIST, KEY, MODES, ORDERS,
};
use crate::chip::reg::Mode;
use crate::report::plot::{Cell, Figure, Panel, Series, Style, Table};

const ORDER_STYLES: [(&str, Style); 2] = [("LIFO", Style::Solid), ("FIFO", Style::Dashed)];

/// DATE'05 Figs. 6 and 7: clocks and queue entries, LIFO against FIFO, on `run`'s chip.
pub(super) fn queue_figures(points: &[Point], run: &ChipRun) -> Vec<Figure> {
    let mut t6 = Table {
        columns: [
            &KEY[..],
            &[
                "order",
                "mode",
                "pairs",
                "cycles",
                "cycles_max",
                "period_ns",
                "chip_us",
                "words",
            ],
        ]
        .concat(),
        rows: vec![],
    };
    let mut t7 = Table {
        columns: [
            &KEY[..],
            &[
                "order",
                "mode",
                "pairs",
                "max_entries",
                "max_entries_max",
                "queue_bytes",
            ],
        ]
        .concat(),
        rows: vec![],
    };
    for p in points {
        for (oi, &o) in ORDERS.iter().enumerate() {
            for (mi, &m) in MODES.iter().enumerate() {
                let cycles = p.mean(|c| c.cycles[oi][mi] as f64);
                let pairs = Cell::Num(p.mean(|c| c.pairs[oi][mi] as f64));
                let base = |v: Vec<Cell>| {
                    [
                        &key(p)[..],
                        &[
                            Cell::Text(name(o).into()),
                            Cell::Text(mode_name(m).into()),
                            pairs.clone(),
                        ],
                        &v[..],
                    ]
                    .concat()
                };
                t6.rows.push(base(vec![
                    Cell::Num(cycles),
                    Cell::Int(p.max(|c| c.cycles[oi][mi])),
                    Cell::Num(run.clock.period_ns),
                    Cell::Num(run.us(cycles)),
                    Cell::Num(p.mean(|c| c.words[oi][mi] as f64)),
                ]));
                let entries = p.mean(|c| c.entries[oi][mi] as f64);
                // an entry is two node pairs of 16-bit ids and a flip bit each, 67 bits
                let bytes = entries * crate::chip::layout::ENTRY_BITS as f64 / 8.0;
                t7.rows.push(base(vec![
                    Cell::Num(entries),
                    Cell::Int(p.max(|c| c.entries[oi][mi])),
                    Cell::Num(bytes),
                ]));
            }
        }
    }
    let fig6 = Figure {
        stem: "date05_fig6_cycles",
        title: format!(
            "DATE'05 Fig. 6: query time, LIFO vs FIFO (cycle model, {})",
            run.name()
        ),
        panels: MODES
            .iter()
            .enumerate()
            .map(|(mi, &m)| {
                let title = if m == Mode::All {
                    "all intersecting pairs"
                } else {
                    "first hit"
                };
                panel(
                    title,
                    DIST,
                    "clocks per query",
                    by_distance(points, &ORDER_STYLES, |p, oi| {
                        Some(p.mean(|c| c.cycles[oi][mi] as f64))
                    }),
                )
            })
            .collect(),
        table: t6,
    };
    let fig7 = Figure {
        stem: "date05_fig7_queue",
        title: format!(
            "DATE'05 Fig. 7: queue memory, LIFO vs FIFO (cycle model, {})",
            run.name()
        ),
        panels: vec![panel(
            "most queue entries (two node pairs each) at once, all pairs",
            DIST,
            "queue entries",
            by_distance(points, &ORDER_STYLES, |p, oi| {
                Some(p.mean(|c| c.entries[oi][0] as f64))
            }),
        )],
        table: t7,
    };
    vec![fig6, fig7]
}

/// DATE'05 Fig. 8: the chip's speed-up over the golden model and parry3d, of its own time
/// and end to end; the time per query; the speed-up against triangle count.
pub(super) fn fig8(points: &[Point], run: &ChipRun) -> Figure {
    let times = |p: &Point| Times::of(p, run, 0, p.mean(|c| c.cycles[0][0] as f64));
    let mut t8 = Table {
        columns: [
            &KEY[..],
            &[
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
                "e2e_speedup_parry",
            ],
        ]
        .concat(),
        rows: vec![],
    };
    for p in points {
        let t = times(p);
        let h = p.host[0];
        let nums = [
            p.mean(|c| c.pairs[0][0] as f64),
            p.mean(|c| c.cycles[0][0] as f64),
            run.clock.period_ns,
            t.chip_us,
            h.setup_us,
            h.settle_us,
            t.e2e_us,
            p.golden_us,
        ];
        let peers = [
            opt(p.parry_us),
            Cell::Num(p.golden_us / t.chip_us),
            opt(p.parry_us.map(|x| x / t.chip_us)),
            Cell::Num(p.golden_us / t.e2e_us),
            opt(p.parry_us.map(|x| x / t.e2e_us)),
        ];
        t8.rows
            .push([&key(p)[..], &nums.map(Cell::Num)[..], &peers[..]].concat());
    }
    let peers = [
        ("over the golden model", Style::Solid),
        ("over parry3d", Style::Dashed),
    ];
    let over = |p: &Point, v: usize, us: f64| {
        if v == 0 {
            Some(p.golden_us / us)
        } else {
            p.parry_us.map(|x| x / us)
        }
    };
    let time_lines = [
        ("end to end", Style::Solid),
        ("the chip alone", Style::Dashed),
        ("the golden model (software)", Style::Points),
    ];
    let time = |p: &Point, v: usize| Some([times(p).e2e_us, times(p).chip_us, p.golden_us][v]);
    let mut distances: Vec<f64> = points.iter().map(|p| p.distance).collect();
    distances.sort_by(f64::total_cmp);
    distances.dedup();
    let by_tris: Vec<Series> = distances
        .iter()
        .rev()
        .step_by(2)
        .enumerate()
        .map(|(ci, &d)| {
            let mut pts: Vec<(f64, f64)> = points
                .iter()
                .filter(|p| p.distance == d)
                .map(|p| (p.triangles as f64, p.golden_us / times(p).chip_us))
                .collect();
            pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            Series {
                label: format!("d = {d}"),
                color: ci,
                style: Style::Solid,
                points: pts,
                labels: vec![],
            }
        })
        .collect();
    Figure {
        stem: "date05_fig8_speedup",
        title: format!(
            "DATE'05 Fig. 8: the chip ({}) over software on this machine, all pairs",
            run.name()
        ),
        panels: vec![
            panel(
                &format!(
                    "speed-up of the chip's time (LIFO clocks x {})",
                    run.period()
                ),
                DIST,
                "speed-up",
                by_distance(points, &peers, |p, v| over(p, v, times(p).chip_us)),
            ),
            panel(
                "speed-up end to end (host setup + the chip's time + host settling)",
                DIST,
                "speed-up",
                by_distance(points, &peers, |p, v| over(p, v, times(p).e2e_us)),
            ),
            panel(
                "time per query",
                DIST,
                "microseconds per query",
                by_distance(points, &time_lines, time),
            ),
            Panel {
                log_x: true,
                ..panel(
                    "speed-up of the chip's time over the golden model against triangle count",
                    "triangles per object",
                    "speed-up",
                    by_tris,
                )
            },
        ],
        table: t8,
    }
}
