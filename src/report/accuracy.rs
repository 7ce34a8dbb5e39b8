//! "What accuracy costs": the same tumbling sweep (WSCG'03 protocol) run with several number
//! formats, k and DOP roundings, each query compared with the exact oracle and run on the
//! cycle model (the RTL's microarchitecture) for its clocks.

use crate::chip::config::{ChipConfig, DopRounding, Formats};
use crate::cycle::{self, drive::Reader};
use crate::chip::params::Params;
use crate::dop::tree::Tri;
use crate::measure::parallel_map;
use crate::golden::memory::TriWord;
use crate::oracle;
use crate::query::{exact_pairs, place, Accuracy, Chip};
use crate::report::figures::{Cell, Figure, Panel, Series, Style, Table, PALETTE};
use crate::pose::{sweep_poses, Sweep};
use crate::traversal::Traversal;
use crate::chip::reg::{Mode, Order};
use serde::Serialize;
use std::fmt::Write;

/// One mesh, k, format and rounding over all poses of the sweep.
#[derive(Clone, Debug, Serialize)]
pub struct Row {
    pub mesh: String,
    pub k: usize,
    pub format: Formats,
    pub dop_rounding: DopRounding,
    #[serde(flatten)]
    pub sums: Sums,
}

/// Sums over the queries.
#[derive(Clone, Copy, Debug, Default, Serialize)]
pub struct Sums {
    pub queries: u64,
    pub exact_pairs: u64,
    pub dop_tests: u64,
    pub tri_tests: u64,
    pub uncertain: u64,
    /// Uncertain by cause ([`Cause`]), each pair counted once, in this order.
    pub uncertain_degenerate: u64,
    pub uncertain_on_plane: u64,
    pub uncertain_bound: u64,
    pub memory_bytes: u64,
    pub misses: u64,
    pub extras: u64,
    /// The cycle model's clocks (LIFO, all pairs, [`Params::RTL`] with the study's ideal
    /// memory).
    pub cycles: u64,
}

impl std::ops::AddAssign for Sums {
    fn add_assign(&mut self, q: Sums) {
        self.queries += q.queries;
        self.exact_pairs += q.exact_pairs;
        self.dop_tests += q.dop_tests;
        self.tri_tests += q.tri_tests;
        self.uncertain += q.uncertain;
        self.uncertain_degenerate += q.uncertain_degenerate;
        self.uncertain_on_plane += q.uncertain_on_plane;
        self.uncertain_bound += q.uncertain_bound;
        self.memory_bytes += q.memory_bytes;
        self.misses += q.misses;
        self.extras += q.extras;
        self.cycles += q.cycles;
    }
}

impl Sums {
    /// Triangle tests whose pair does not intersect: the DOP hierarchy's false positives at
    /// the leaves (the chip's pairs equal the exact ones, so this is tri_tests - pairs).
    pub fn dop_false_positive_rate(&self) -> f64 {
        ratio(self.tri_tests.saturating_sub(self.exact_pairs - self.misses), self.tri_tests)
    }

    pub fn uncertain_rate(&self) -> f64 {
        ratio(self.uncertain, self.tri_tests)
    }
}

/// Why TRI_UNIT left a pair to the host, first cause that applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cause {
    /// A leaf has no unit-triangle map (zero area, or too ill-conditioned for the format):
    /// its direction of TRI_UNIT cannot decide.
    Degenerate,
    /// A vertex of one triangle lies exactly on the other's plane in the oracle's geometry
    /// (touching, coplanar): a deciding value is exactly 0, no bound can decide it.
    OnPlane,
    /// Every deciding value is non-zero, but some sign lies inside its error bound.
    Bound,
}

impl Cause {
    /// The cause for the uncertain pair of words `wa`, `wb` whose triangles are `ta` of A and
    /// `tb` of B as the oracle places them.
    pub fn of(wa: &TriWord, wb: &TriWord, ta: &Tri, tb: &Tri) -> Cause {
        if wa.degenerate || wb.degenerate {
            Cause::Degenerate
        } else if oracle::vertex_on_plane(ta, tb) {
            Cause::OnPlane
        } else {
            Cause::Bound
        }
    }
}

fn ratio(a: u64, b: u64) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}

/// Runs every (k, format, rounding) on one mesh against a copy of itself, the poses on every
/// core, the cycle model against the ideal `memory`; `progress` is called once per pose.
pub fn study(
    mesh: &str,
    tris: &[Tri],
    ks: &[usize],
    formats: &[Formats],
    roundings: &[DopRounding],
    sweep: &Sweep,
    memory: crate::chip::memory::MemTiming,
    progress: impl Fn() + Sync,
) -> Result<Vec<Row>, String> {
    let poses = sweep_poses(sweep)?;
    let mut cfgs = vec![];
    for &k in ks {
        for &format in formats {
            for &dop_rounding in roundings {
                cfgs.push(ChipConfig { k, format, dop_rounding, ..Default::default() });
            }
        }
    }
    let chips: Vec<Chip> = cfgs.iter().map(|&cfg| Chip::new(tris, tris, cfg)).collect::<Result<_, _>>()?;
    if let Some(chip) = chips.first() {
        poses.iter().try_for_each(|sp| chip.check_pose(&sp.pose))?;
    }
    let per_pose = parallel_map(&poses, |_, sp| {
        let exact = exact_pairs(tris, tris, &sp.pose);
        let placed = place(tris, &sp.pose);
        let rows = chips.iter().map(|chip| {
            let r = chip.query(&sp.pose, Mode::All, Traversal::Lifo);
            let acc = Accuracy::of(Mode::All, &r.pairs, &exact);
            let (trace, _) = cycle::run_query(chip, &chip.setup(&sp.pose), Order::Lifo, Mode::All, Params { memory: memory.into(), ..Params::RTL }, Reader::default(), cycle::MAX_CYCLES, Default::default())?;
            trace.check(Mode::All, &r).map_err(|e| format!("{mesh} k={} {} at {}: the cycle model disagrees with the golden model: {e}", chip.cfg.k, chip.cfg.format, sp.pose.text()))?;
            let mut causes = [0u64; 3];
            for &(a, b) in &r.uncertain {
                let (a, b) = (a as usize, b as usize);
                causes[Cause::of(&chip.a.tris[a], &chip.b.tris[b], &tris[a], &placed[b]) as usize] += 1;
            }
            Ok(Sums {
                queries: 1,
                uncertain_degenerate: causes[Cause::Degenerate as usize],
                uncertain_on_plane: causes[Cause::OnPlane as usize],
                uncertain_bound: causes[Cause::Bound as usize],
                exact_pairs: exact.len() as u64,
                dop_tests: r.counters.dop_tests,
                tri_tests: r.counters.tri_tests,
                uncertain: r.counters.uncertain,
                memory_bytes: r.counters.memory_bytes,
                misses: acc.misses,
                extras: acc.extras,
                cycles: trace.cycles,
            })
        });
        let rows = rows.collect::<Result<Vec<Sums>, String>>();
        progress();
        rows
    });
    let mut rows: Vec<Row> = chips
        .iter()
        .map(|c| Row { mesh: mesh.to_string(), k: c.cfg.k, format: c.cfg.format, dop_rounding: c.cfg.dop_rounding, sums: Sums::default() })
        .collect();
    for pose_rows in per_pose {
        for (row, q) in rows.iter_mut().zip(pose_rows?) {
            row.sums += q;
        }
    }
    Ok(rows)
}

/// The Markdown table of docs/ACCURACY.md; with `area`, the cells of each configuration's
/// DOP unit and TRI_UNIT ("-" where the RTL is not built in its format).
pub fn table(rows: &[Row], area: Option<&Area>) -> String {
    let mut columns = vec!["mesh", "k", "format", "DOP rounding", "queries", "exact pairs / query", "DOP tests / query", "triangle tests / query", "DOP false positives", "uncertain", "uncertain: degenerate / on plane / bound", "misses", "extra pairs", "memory KiB / query", "cycles / query"];
    if area.is_some() {
        columns.push("cells: DOP unit + TRI_UNIT");
    }
    let mut out = format!("| {} |\n|{}\n", columns.join(" | "), "---|".repeat(columns.len()));
    for row in rows {
        let r = &row.sums;
        let q = r.queries.max(1) as f64;
        let _ = write!(
            out,
            "| {} | {} | {} | {} | {} | {:.1} | {:.0} | {:.1} | {:.1}% | {:.2}% | {} / {} / {} | {} | {} | {:.1} | {:.0} |",
            row.mesh,
            row.k,
            row.format,
            row.dop_rounding,
            r.queries,
            r.exact_pairs as f64 / q,
            r.dop_tests as f64 / q,
            r.tri_tests as f64 / q,
            100.0 * r.dop_false_positive_rate(),
            100.0 * r.uncertain_rate(),
            r.uncertain_degenerate,
            r.uncertain_on_plane,
            r.uncertain_bound,
            r.misses,
            r.extras,
            r.memory_bytes as f64 / q / 1024.0,
            r.cycles as f64 / q
        );
        if let Some(a) = area {
            let _ = write!(out, " {} |", a.of(row.k, row.format, row.dop_rounding).map_or("-".into(), |c| c.to_string()));
        }
        out.push('\n');
    }
    out
}

/// Yosys cells per unit: the file scripts/area-study.sh writes (`unit,cells`, one row per
/// unit, names as in rtl/).
pub struct Area {
    cells: std::collections::HashMap<String, u64>,
}

#[derive(serde::Deserialize)]
struct AreaRow {
    unit: String,
    cells: u64,
}

impl Area {
    pub fn load(path: &std::path::Path) -> Result<Area, String> {
        let what = "write it with scripts/area-study.sh";
        let mut r = csv::Reader::from_path(path).map_err(|e| format!("{}: {e} ({what})", path.display()))?;
        let mut cells = std::collections::HashMap::new();
        for (i, row) in r.deserialize::<AreaRow>().enumerate() {
            let row = row.map_err(|e| format!("{}:{}: {e}: each row is `unit,cells` ({what})", path.display(), i + 2))?;
            cells.insert(row.unit, row.cells);
        }
        Ok(Area { cells })
    }

    /// Cells of the units a configuration changes: its DOP unit (k lanes, the DOP format and
    /// rounding) and TRI_UNIT (T.CHECK's format). D_CNTR, the queue and the memory port are
    /// not counted. `None` where the RTL is not built in a format (e8m10).
    pub fn of(&self, k: usize, f: Formats, r: DopRounding) -> Option<u64> {
        use crate::harness::units::{dop_unit_name, tri_unit_name};
        Some(self.cells.get(&dop_unit_name(k, f.dop, r.op())?)? + self.cells.get(&tri_unit_name(f.tri)?)?)
    }
}

/// Which points are on the Pareto front: present (`Some`), and no other present point is at
/// least as small in both coordinates and different.
fn pareto(points: &[Option<(f64, f64)>]) -> Vec<bool> {
    let beaten = |(x, y): (f64, f64)| points.iter().flatten().any(|&(qx, qy)| qx <= x && qy <= y && (qx, qy) != (x, y));
    points.iter().map(|p| p.is_some_and(|p| !beaten(p))).collect()
}

/// One panel of clocks per query against `x`, a point per configuration that has one, grouped
/// by format and rounding, with the Pareto front (`on`) as a dashed line.
fn front_panel(title: &str, x_label: &'static str, log_x: bool, cfgs: &[Config], x: &[Option<f64>], on: &[bool]) -> Panel {
    let mut groups: Vec<(Formats, DopRounding)> = vec![];
    for c in cfgs {
        if !groups.contains(&(c.1, c.2)) {
            groups.push((c.1, c.2));
        }
    }
    let point = |i: usize| x[i].map(|x| (x, cfgs[i].3.cycles as f64 / cfgs[i].3.queries.max(1) as f64));
    let mut series = vec![];
    for (gi, &(f, r)) in groups.iter().enumerate() {
        let mine: Vec<usize> = (0..cfgs.len()).filter(|&i| (cfgs[i].1, cfgs[i].2) == (f, r) && x[i].is_some()).collect();
        if !mine.is_empty() {
            series.push(Series {
                label: format!("{f}, {r} DOP rounding"),
                color: gi,
                style: Style::Points,
                points: mine.iter().filter_map(|&i| point(i)).collect(),
                labels: mine.iter().map(|&i| format!("  k={}", cfgs[i].0)).collect(),
            });
        }
    }
    let mut front: Vec<(f64, f64)> = (0..cfgs.len()).filter(|&i| on[i]).filter_map(point).collect();
    front.sort_by(|a, b| a.0.total_cmp(&b.0));
    series.push(Series { label: "Pareto front (no misses)".into(), color: PALETTE.len() - 1, style: Style::Dashed, points: front, labels: vec![] });
    Panel { title: title.into(), x_label, y_label: "clocks per query", log_x, log_y: false, series }
}

/// (k, formats, DOP rounding, sums over the meshes)
type Config = (usize, Formats, DopRounding, Sums);

/// The configurations over all meshes, one point each: cycles per query against the share of
/// triangle tests left to the host, and, with `area`, against the cells of the units the
/// configuration changes (DOP unit + TRI_UNIT). Each plot marks its Pareto front among the
/// configurations with no miss (no other is both faster and smaller in its x). Both figures
/// carry the same table.
pub fn figures(rows: &[Row], area: Option<&Area>) -> Vec<Figure> {
    let mut cfgs: Vec<Config> = vec![];
    for r in rows {
        match cfgs.iter_mut().find(|c| (c.0, c.1, c.2) == (r.k, r.format, r.dop_rounding)) {
            Some(c) => c.3 += r.sums,
            None => cfgs.push((r.k, r.format, r.dop_rounding, r.sums)),
        }
    }
    let cycles = |s: &Sums| s.cycles as f64 / s.queries.max(1) as f64;
    let uncertain: Vec<Option<f64>> = cfgs.iter().map(|c| Some(100.0 * c.3.uncertain_rate())).collect();
    let cells: Vec<Option<u64>> = cfgs.iter().map(|c| area.and_then(|a| a.of(c.0, c.1, c.2))).collect();
    let eligible = |x: &[Option<f64>]| -> Vec<Option<(f64, f64)>> {
        cfgs.iter().zip(x).map(|(c, x)| x.filter(|_| c.3.misses == 0).map(|x| (x, cycles(&c.3)))).collect()
    };
    let on_uncertain = pareto(&eligible(&uncertain));
    let cells_x: Vec<Option<f64>> = cells.iter().map(|c| c.map(|c| c as f64 / 1e6)).collect();
    let on_area = pareto(&eligible(&cells_x));
    let mut table = Table {
        columns: vec!["k", "format", "dop_rounding", "queries", "uncertain_share", "cycles_per_query", "memory_kib_per_query", "misses", "pareto", "cells", "pareto_area"],
        rows: vec![],
    };
    for (i, c) in cfgs.iter().enumerate() {
        table.rows.push(vec![
            Cell::Int(c.0 as u64),
            Cell::Text(c.1.to_string()),
            Cell::Text(c.2.to_string()),
            Cell::Int(c.3.queries),
            Cell::Num(c.3.uncertain_rate()),
            Cell::Num(cycles(&c.3)),
            Cell::Num(c.3.memory_bytes as f64 / c.3.queries.max(1) as f64 / 1024.0),
            Cell::Int(c.3.misses),
            Cell::Text(on_uncertain[i].to_string()),
            cells[i].map_or(Cell::None, Cell::Int),
            if cells[i].is_some() { Cell::Text(on_area[i].to_string()) } else { Cell::None },
        ]);
    }
    let meshes: Vec<&str> = rows.iter().map(|r| r.mesh.as_str()).fold(vec![], |mut v, m| {
        if !v.contains(&m) {
            v.push(m);
        }
        v
    });
    let what = "one point per configuration (cycle model, LIFO, all pairs)";
    let mut out = vec![Figure {
        stem: "accuracy_cycles_uncertain",
        title: format!("What accuracy costs: the chip's clocks against the host's share ({})", meshes.join(", ")),
        panels: vec![front_panel(what, "triangle tests left to the host (uncertain), %", true, &cfgs, &uncertain, &on_uncertain)],
        table: table.clone(),
    }];
    if area.is_some() {
        out.push(Figure {
            stem: "accuracy_cycles_area",
            title: format!("What accuracy costs in area: the chip's clocks against the cells of its DOP unit and TRI_UNIT ({})", meshes.join(", ")),
            panels: vec![front_panel(&format!("{what}; Yosys cells, generic gates"), "Yosys cells, DOP unit + TRI_UNIT, millions", false, &cfgs, &cells_x, &on_area)],
            table,
        });
    }
    out
}
