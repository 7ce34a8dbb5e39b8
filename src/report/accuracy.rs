//! "What accuracy costs": the same tumbling sweep (WSCG'03 protocol) run with several number
//! formats, k and DOP roundings, each query compared with the exact oracle and run on the
//! cycle model (the RTL's microarchitecture) for its clocks.

use crate::config::{ChipConfig, DopRounding};
use crate::cycle::{self, drive::Reader, Params};
use crate::dop::tree::Tri;
use crate::format::Format;
use crate::measure::parallel_map;
use crate::memory::TriWord;
use crate::oracle;
use crate::query::{exact_pairs, place, Accuracy, Chip};
use crate::report::figures::{Cell, Figure, Panel, Series, Style, Table, PALETTE};
use crate::scene::{sweep_poses, Sweep};
use crate::traversal::{Mode, Traversal};
use serde::Serialize;
use std::fmt::Write;

/// One mesh, k, format and rounding over all poses of the sweep.
#[derive(Clone, Debug, Serialize)]
pub struct Row {
    pub mesh: String,
    pub k: usize,
    pub format: Format,
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
    formats: &[Format],
    roundings: &[DopRounding],
    sweep: &Sweep,
    memory: cycle::MemTiming,
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
            let (trace, _) = cycle::run_query(chip, &chip.setup(&sp.pose), true, Mode::All, Params { memory: memory.into(), ..Params::RTL }, Reader::default(), cycle::MAX_CYCLES, Default::default())?;
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

/// The Markdown table of docs/ACCURACY.md.
pub fn table(rows: &[Row]) -> String {
    let mut out = String::from(
        "| mesh | k | format | DOP rounding | queries | exact pairs / query | DOP tests / query | triangle tests / query | DOP false positives | uncertain | uncertain: degenerate / on plane / bound | misses | extra pairs | memory KiB / query | cycles / query |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for row in rows {
        let r = &row.sums;
        let q = r.queries.max(1) as f64;
        let _ = writeln!(
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
    }
    out
}

/// The configurations over all meshes: cycles per query against the share of triangle tests
/// left to the host, one point per (k, format, rounding), the Pareto front of those with no
/// miss marked (no configuration both faster and with a smaller uncertain share).
pub fn figure(rows: &[Row]) -> Figure {
    let mut cfgs: Vec<(usize, Format, DopRounding, Sums)> = vec![];
    for r in rows {
        match cfgs.iter_mut().find(|c| (c.0, c.1, c.2) == (r.k, r.format, r.dop_rounding)) {
            Some(c) => c.3 += r.sums,
            None => cfgs.push((r.k, r.format, r.dop_rounding, r.sums)),
        }
    }
    let point = |s: &Sums| (100.0 * s.uncertain_rate(), s.cycles as f64 / s.queries.max(1) as f64);
    let dominated = |a: &Sums| {
        let (x, y) = point(a);
        cfgs.iter().any(|c| c.3.misses == 0 && point(&c.3).0 <= x && point(&c.3).1 <= y && point(&c.3) != (x, y))
    };
    let mut front: Vec<(f64, f64)> = cfgs.iter().filter(|c| c.3.misses == 0 && !dominated(&c.3)).map(|c| point(&c.3)).collect();
    front.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut series = vec![];
    let mut groups: Vec<(Format, DopRounding)> = vec![];
    for c in &cfgs {
        if !groups.contains(&(c.1, c.2)) {
            groups.push((c.1, c.2));
        }
    }
    for (gi, &(f, r)) in groups.iter().enumerate() {
        let mine: Vec<_> = cfgs.iter().filter(|c| (c.1, c.2) == (f, r)).collect();
        series.push(Series {
            label: format!("{f}, {r} DOP rounding"),
            color: gi,
            style: Style::Points,
            points: mine.iter().map(|c| point(&c.3)).collect(),
            labels: mine.iter().map(|c| format!("  k={}", c.0)).collect(),
        });
    }
    series.push(Series { label: "Pareto front (no misses)".into(), color: PALETTE.len() - 1, style: Style::Dashed, points: front.clone(), labels: vec![] });
    let mut table = Table {
        columns: vec!["k", "format", "dop_rounding", "queries", "uncertain_share", "cycles_per_query", "memory_kib_per_query", "misses", "pareto"],
        rows: vec![],
    };
    for c in &cfgs {
        let (x, y) = point(&c.3);
        table.rows.push(vec![
            Cell::Int(c.0 as u64),
            Cell::Text(c.1.to_string()),
            Cell::Text(c.2.to_string()),
            Cell::Int(c.3.queries),
            Cell::Num(x / 100.0),
            Cell::Num(y),
            Cell::Num(c.3.memory_bytes as f64 / c.3.queries.max(1) as f64 / 1024.0),
            Cell::Int(c.3.misses),
            Cell::Text(front.contains(&(x, y)).to_string()),
        ]);
    }
    let meshes: Vec<&str> = rows.iter().map(|r| r.mesh.as_str()).fold(vec![], |mut v, m| {
        if !v.contains(&m) {
            v.push(m);
        }
        v
    });
    Figure {
        stem: "accuracy_cycles_uncertain",
        title: format!("What accuracy costs: the chip's clocks against the host's share ({})", meshes.join(", ")),
        panels: vec![Panel {
            title: "one point per configuration (cycle model, LIFO, all pairs)".into(),
            x_label: "triangle tests left to the host (uncertain), %",
            y_label: "clocks per query",
            log_x: true,
            log_y: false,
            series,
        }],
        table,
    }
}
