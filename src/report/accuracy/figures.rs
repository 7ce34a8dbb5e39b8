//! The study's figures: end-to-end time per query against the host's share and against the
//! cells, a panel per memory system, each with its Pareto front.

use super::*;

/// Which points are on the Pareto front: present (`Some`), and no other present point is at
/// least as small in both coordinates and different.
fn pareto(points: &[Option<(f64, f64)>]) -> Vec<bool> {
    let beaten = |(x, y): (f64, f64)| {
        points
            .iter()
            .flatten()
            .any(|&(qx, qy)| qx <= x && qy <= y && (qx, qy) != (x, y))
    };
    points
        .iter()
        .map(|p| p.is_some_and(|p| !beaten(p)))
        .collect()
}

/// A point's stored DOP precision, if not full: `, 8 bits`.
fn bits_label(b: DopBits) -> String {
    match b {
        DopBits::Full => String::new(),
        b => format!(", {b} bits"),
    }
}

/// A point's label for its folds: nothing unfolded, else `, ii T/D` (TRI_UNIT's and the DOP
/// unit's pair intervals).
fn fold_label(f: Folds) -> String {
    if f == Folds::NONE {
        String::new()
    } else {
        format!(
            ", ii {}/{}{}",
            f.tri,
            f.dop,
            f.depth.tag().replace('_', " ")
        )
    }
}

/// One panel of end-to-end time per query against `x` for the configurations `mine` (one
/// memory system), a point per configuration that has one, grouped by format and rounding,
/// with the Pareto front (`on`) as a dashed line.
fn front_panel(
    title: String,
    x_label: &'static str,
    log_x: bool,
    cfgs: &[Row],
    mine: &[usize],
    x: &[Option<f64>],
    on: &[bool],
) -> Panel {
    let mut groups: Vec<(Formats, DopRounding)> = vec![];
    for &i in mine {
        if !groups.contains(&(cfgs[i].format, cfgs[i].dop_rounding)) {
            groups.push((cfgs[i].format, cfgs[i].dop_rounding));
        }
    }
    let point = |i: usize| x[i].map(|x| (x, cfgs[i].end_to_end_us()));
    // a fold study has tens of points per group: only the front's are named
    let folded = mine.iter().any(|&i| cfgs[i].folds != Folds::NONE);
    let label = |i: usize| {
        if folded && !on[i] {
            String::new()
        } else {
            format!(
                "  k={}{}{}",
                cfgs[i].k,
                bits_label(cfgs[i].dop_bits),
                fold_label(cfgs[i].folds)
            )
        }
    };
    let mut series = vec![];
    for (gi, &(f, r)) in groups.iter().enumerate() {
        let these: Vec<usize> = mine
            .iter()
            .copied()
            .filter(|&i| (cfgs[i].format, cfgs[i].dop_rounding) == (f, r) && x[i].is_some())
            .collect();
        if !these.is_empty() {
            series.push(Series {
                label: format!("{f}, {r} DOP rounding"),
                color: gi % (PALETTE.len() - 1),
                style: Style::Points,
                points: these.iter().filter_map(|&i| point(i)).collect(),
                labels: these.iter().map(|&i| label(i)).collect(),
            });
        }
    }
    let mut front: Vec<(f64, f64)> = mine
        .iter()
        .copied()
        .filter(|&i| on[i])
        .filter_map(point)
        .collect();
    front.sort_by(|a, b| a.0.total_cmp(&b.0));
    series.push(Series {
        label: "Pareto front (no misses)".into(),
        color: PALETTE.len() - 1,
        style: Style::Dashed,
        points: front,
        labels: vec![],
    });
    Panel {
        title,
        x_label,
        y_label: "end to end per query, us",
        log_x,
        log_y: false,
        series,
    }
}

/// The rows of `rows` summed over meshes: one per memory system, chip and folds.
fn summed(rows: &[Row]) -> Vec<Row> {
    let key = |r: &Row| (r.memory, r.chip(), r.folds);
    let mut cfgs: Vec<Row> = vec![];
    for r in rows {
        match cfgs.iter_mut().find(|c| key(c) == key(r)) {
            Some(c) => {
                (c.sums, c.host) = (
                    {
                        let mut s = c.sums;
                        s += r.sums;
                        s
                    },
                    {
                        let mut h = c.host;
                        h += r.host;
                        h
                    },
                )
            }
            None => cfgs.push(Row {
                mesh: String::new(),
                ..r.clone()
            }),
        }
    }
    cfgs
}

/// The figures' table: a row per configuration, with its fronts' marks.
fn figure_table(
    cfgs: &[Row],
    cells: &[Option<u64>],
    on_uncertain: &[bool],
    on_area: &[bool],
) -> Table {
    let mut table = Table {
        columns: vec![
            "memory",
            "k",
            "format",
            "dop_rounding",
            "queries",
            "uncertain_share",
            "cycles_per_query",
            "period_ns",
            "period_source",
            "chip_us",
            "host_us",
            "end_to_end_us",
            "memory_kib_per_query",
            "misses",
            "pareto",
            "cells",
            "pareto_area",
        ],
        rows: vec![],
    };
    for (i, c) in cfgs.iter().enumerate() {
        let q = c.sums.queries.max(1) as f64;
        table.rows.push(vec![
            Cell::Text(c.memory.name().into()),
            Cell::Int(c.k as u64),
            Cell::Text(c.format.to_string()),
            Cell::Text(c.dop_rounding.to_string()),
            Cell::Int(c.sums.queries),
            Cell::Num(c.sums.uncertain_rate()),
            Cell::Num(c.sums.cycles as f64 / q),
            Cell::Num(c.period_ns),
            Cell::Text(c.period_source.name().into()),
            Cell::Num(c.chip_us()),
            Cell::Num(c.host_us()),
            Cell::Num(c.end_to_end_us()),
            Cell::Num(c.sums.memory_bytes as f64 / q / 1024.0),
            Cell::Int(c.sums.misses),
            Cell::Text(on_uncertain[i].to_string()),
            cells[i].map_or(Cell::None, Cell::Int),
            if cells[i].is_some() {
                Cell::Text(on_area[i].to_string())
            } else {
                Cell::None
            },
        ]);
    }
    table
}

/// The configurations over all meshes, one point each: the end-to-end time per query (the
/// host's measured setup and settling plus the chip's clocks at its period) against the share
/// of triangle tests left to the host, and, with `area`, against the cells of the units the
/// configuration changes (DOP unit + TRI_UNIT); a panel per memory system. Each panel marks
/// its Pareto front among the configurations with no miss (no other is both faster and
/// smaller in its x). Both figures carry the same table. A study with folds draws only the
/// area figure, `fold_cycles_area`: what area costs in time.
pub fn figures(rows: &[Row], area: Option<&Area>) -> Vec<Figure> {
    let cfgs = summed(rows);
    let presets: Vec<Preset> = cfgs.iter().map(|c| c.memory).fold(vec![], |mut v, p| {
        if !v.contains(&p) {
            v.push(p);
        }
        v
    });
    let uncertain: Vec<Option<f64>> = cfgs
        .iter()
        .map(|c| Some(100.0 * c.sums.uncertain_rate()))
        .collect();
    let cells: Vec<Option<u64>> = cfgs
        .iter()
        .map(|c| area.and_then(|a| a.of(&c.chip(), c.folds)))
        .collect();
    let cells_x: Vec<Option<f64>> = cells.iter().map(|c| c.map(|c| c as f64 / 1e6)).collect();
    // the fronts, each among one memory system's configurations
    let front = |x: &[Option<f64>]| -> Vec<bool> {
        let mut on = vec![false; cfgs.len()];
        for &p in &presets {
            let pts: Vec<Option<(f64, f64)>> = cfgs
                .iter()
                .zip(x)
                .map(|(c, x)| {
                    x.filter(|_| c.sums.misses == 0 && c.memory == p)
                        .map(|x| (x, c.end_to_end_us()))
                })
                .collect();
            for (o, f) in on.iter_mut().zip(pareto(&pts)) {
                *o |= f;
            }
        }
        on
    };
    let (on_uncertain, on_area) = (front(&uncertain), front(&cells_x));
    let table = figure_table(&cfgs, &cells, &on_uncertain, &on_area);
    let meshes: Vec<&str> = rows
        .iter()
        .map(|r| r.mesh.as_str())
        .fold(vec![], |mut v, m| {
            if !v.contains(&m) {
                v.push(m);
            }
            v
        });
    let mine =
        |p: Preset| -> Vec<usize> { (0..cfgs.len()).filter(|&i| cfgs[i].memory == p).collect() };
    let what = |p: Preset| {
        format!(
            "memory {}: one point per configuration (cycle model, LIFO, all pairs; host measured)",
            p.name()
        )
    };
    let folded = cfgs.iter().any(|c| c.folds != Folds::NONE);
    let mut out = vec![];
    out.extend((!folded).then(|| {
        Figure {
            stem: "accuracy_cycles_uncertain",
            title: format!(
                "What accuracy costs: the query's time end to end against the host's share ({})",
                meshes.join(", ")
            ),
            panels: presets
                .iter()
                .map(|&p| {
                    front_panel(
                        what(p),
                        "triangle tests left to the host (uncertain), %",
                        true,
                        &cfgs,
                        &mine(p),
                        &uncertain,
                        &on_uncertain,
                    )
                })
                .collect(),
            table: table.clone(),
        }
    }));
    // with folds (`--tri-intervals`, `--dop-intervals`) the area figure alone (a fold leaves
    // the uncertain share as it is), the cells on a log scale (they span a factor of 30)
    if area.is_some() {
        out.push(Figure {
            stem: if folded { "fold_cycles_area" } else { "accuracy_cycles_area" },
            title: if folded {
                format!("What area costs in time: a query end to end against the cells of the folded DOP unit and TRI_UNIT ({})", meshes.join(", "))
            } else {
                format!("What accuracy costs in area: the query's time end to end against the cells of its DOP unit and TRI_UNIT ({})", meshes.join(", "))
            },
            panels: presets.iter().map(|&p| front_panel(format!("{}; Yosys cells, generic gates", what(p)), if folded { "Yosys cells, DOP unit + TRI_UNIT, millions (labels: k, ii TRI_UNIT/DOP unit)" } else { "Yosys cells, DOP unit + TRI_UNIT, millions" }, folded, &cfgs, &mine(p), &cells_x, &on_area)).collect(),
            table,
        });
    }
    out
}
