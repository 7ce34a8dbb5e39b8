//! "What accuracy costs": the same tumbling sweep (WSCG'03 protocol) run with several number
//! formats and DOP roundings, each query compared with the exact oracle.

use crate::config::{ChipConfig, DopRounding};
use crate::dop::tree::Tri;
use crate::format::Format;
use crate::oracle;
use crate::query::{place, Accuracy, Chip};
use crate::scene::{sweep_poses, Sweep};
use crate::traversal::{Mode, Traversal};
use serde::Serialize;
use std::fmt::Write;

/// One mesh, format and rounding over all poses of the sweep.
#[derive(Clone, Debug, Serialize)]
pub struct Row {
    pub mesh: String,
    pub format: Format,
    pub dop_rounding: DopRounding,
    pub queries: u64,
    pub exact_pairs: u64,
    pub dop_tests: u64,
    pub tri_tests: u64,
    pub uncertain: u64,
    pub memory_bytes: u64,
    pub misses: u64,
    pub extras: u64,
}

impl Row {
    /// Triangle tests whose pair does not intersect: the DOP hierarchy's false positives at
    /// the leaves (the chip's pairs equal the exact ones, so this is tri_tests - pairs).
    pub fn dop_false_positive_rate(&self) -> f64 {
        ratio(self.tri_tests.saturating_sub(self.exact_pairs - self.misses), self.tri_tests)
    }

    pub fn uncertain_rate(&self) -> f64 {
        ratio(self.uncertain, self.tri_tests)
    }
}

fn ratio(a: u64, b: u64) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}

/// Runs every (format, rounding) on one mesh against a copy of itself; `progress` is called
/// once per pose.
pub fn study(
    mesh: &str,
    tris: &[Tri],
    formats: &[Format],
    roundings: &[DopRounding],
    sweep: &Sweep,
    mut progress: impl FnMut(),
) -> Result<Vec<Row>, String> {
    let poses = sweep_poses(sweep)?;
    let chips: Vec<Chip> = formats
        .iter()
        .flat_map(|&format| roundings.iter().map(move |&dop_rounding| ChipConfig { format, dop_rounding, ..Default::default() }))
        .map(|cfg| Chip::new(tris, tris, cfg))
        .collect::<Result<_, _>>()?;
    if let Some(chip) = chips.first() {
        poses.iter().try_for_each(|sp| chip.check_pose(&sp.pose))?;
    }
    let mut rows: Vec<Row> = chips
        .iter()
        .map(|c| Row {
            mesh: mesh.to_string(),
            format: c.cfg.format,
            dop_rounding: c.cfg.dop_rounding,
            queries: 0,
            exact_pairs: 0,
            dop_tests: 0,
            tri_tests: 0,
            uncertain: 0,
            memory_bytes: 0,
            misses: 0,
            extras: 0,
        })
        .collect();
    for sp in &poses {
        let exact = oracle::intersecting_pairs(tris, &place(tris, &sp.pose));
        for (chip, row) in chips.iter().zip(rows.iter_mut()) {
            let r = chip.query(&sp.pose, Mode::All, Traversal::Lifo);
            let acc = Accuracy::of(Mode::All, &r.pairs, &exact);
            row.queries += 1;
            row.exact_pairs += exact.len() as u64;
            row.dop_tests += r.counters.dop_tests;
            row.tri_tests += r.counters.tri_tests;
            row.uncertain += r.counters.uncertain;
            row.memory_bytes += r.counters.memory_bytes;
            row.misses += acc.misses;
            row.extras += acc.extras;
        }
        progress();
    }
    Ok(rows)
}

/// The Markdown table of docs/ACCURACY.md.
pub fn table(rows: &[Row]) -> String {
    let mut out = String::from(
        "| mesh | format | DOP rounding | queries | exact pairs / query | DOP tests / query | triangle tests / query | DOP false positives | uncertain | misses | extra pairs | memory KiB / query |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let q = r.queries.max(1) as f64;
        let _ = writeln!(
            out,
            "| {} | {} | {} | {} | {:.1} | {:.0} | {:.1} | {:.1}% | {:.2}% | {} | {} | {:.1} |",
            r.mesh,
            r.format,
            match r.dop_rounding {
                DopRounding::Outward => "outward",
                DopRounding::NearestEven => "nearest-even",
            },
            r.queries,
            r.exact_pairs as f64 / q,
            r.dop_tests as f64 / q,
            r.tri_tests as f64 / q,
            100.0 * r.dop_false_positive_rate(),
            100.0 * r.uncertain_rate(),
            r.misses,
            r.extras,
            r.memory_bytes as f64 / q / 1024.0
        );
    }
    out
}
