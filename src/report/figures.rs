//! `cchip figures`: the papers' figures regenerated on this project's models, each as SVG and
//! PNG with its data beside it as CSV and JSON (docs/FIGURES.md reads them).
//!
//! Protocol (WSCG'03 §5, DATE'05 §5): each mesh against a copy of itself, both scaled into
//! [-1,1]^3, B tumbling through seeded orientations at each centre distance along x, from
//! apart to penetrating; every number is a mean over the orientations at one distance.
//!
//! - DATE'05 Fig. 6 (cycles, LIFO vs FIFO, all pairs and first hit), Fig. 7 (queue entries),
//!   Fig. 8 (speed-up at 800 MHz over software on this machine): the cycle model of the
//!   chip, k = 24, binary32, outward DOP rounding, [`Params::RTL`] but a queue too large to
//!   overflow, so that FIFO's need shows.
//! - WSCG'03 Figs. 9-10 (software time of Algorithm 2, the list traversal, vs Algorithm 1,
//!   the recursive one; first witness, all pairs), Fig. 11 (node words fetched), Fig. 12 (DOP
//!   transforms): the golden model's traversals. Fig. 13: WSCG'03's chip
//!   ([`cycle::wscg03`]) at 266 MHz on [`WSCG_MEMORY`], Eq. 5's estimate from the list
//!   traversal's lists, and DATE'05's chip on the same memory ([`wscg_params`]); beside it the
//!   two chips' table (`wscg03_vs_date05`).
//!
//! Software is timed one query at a time before anything else runs; the counting work
//! (golden counters, cycle model) then runs on every core.

use crate::chip::config::ChipConfig;
use crate::cycle::{self, drive::Reader};
use crate::chip::memory::Ddr;
use crate::chip::memory::Memory;
use crate::chip::params::Params;
use crate::chip::preset::Preset;
use crate::chip::wscg03::StackParams;
use crate::measure::{mean_seconds, parallel_map};
use crate::mesh;
use crate::pose::Pose;
use crate::query::Chip;
use crate::pose::{sweep_poses, Sweep};
use crate::traversal::Traversal;
use crate::chip::reg::{Mode, Order};
use indicatif::ProgressBar;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;
use serde::ser::SerializeMap;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// What to run.
#[derive(Clone, Debug, Serialize)]
pub struct Plan {
    pub meshes: Vec<String>,
    pub distances: Vec<f64>,
    pub orientations: usize,
    pub seed: u64,
    /// Each software time is the mean over the poses of one distance, repeated until this
    /// many seconds of CPU time have passed (in three runs; the fastest counts).
    pub min_seconds: f64,
}

impl Plan {
    /// The figures of docs/FIGURES.md.
    pub fn full() -> Plan {
        Plan {
            meshes: vec!["teapot".into(), "bunny".into(), "dragon-11k".into()],
            distances: vec![2.4, 2.2, 2.0, 1.8, 1.6, 1.4, 1.2, 1.0, 0.8],
            orientations: 64,
            seed: 1,
            min_seconds: 0.2,
        }
    }

    /// CI's: the two smaller meshes, fewer distances and orientations.
    pub fn quick() -> Plan {
        Plan {
            meshes: vec!["teapot".into(), "bunny".into()],
            distances: vec![2.2, 1.8, 1.4, 1.2, 1.0],
            orientations: 6,
            seed: 1,
            min_seconds: 0.03,
        }
    }
}

/// The chip's clock in DATE'05 (NEC CB-130 UX5).
pub const DATE_MHZ: f64 = 800.0;
/// The chip's clock in WSCG'03 (the burst rate of PC133 DDR SDRAM).
pub const WSCG_MHZ: f64 = 266.0;
/// WSCG'03's memory: its four-bank DDR SDRAM ([`Ddr::WSCG03`]: a page hit 8 clocks, a miss
/// 20).
pub const WSCG_MEMORY: Memory = Memory::Ddr(Ddr::WSCG03);
/// Queue entries of the figures' chip: no FIFO traversal of these meshes overflows it
/// (the RTL's 1,024 would, and an overflowed query has no complete answer).
pub const QUEUE_ENTRIES: u32 = 1 << 24;

/// The chip of the DATE'05 figures: the RTL's, with [`QUEUE_ENTRIES`].
pub fn date_params() -> Params {
    Params { queue_entries: QUEUE_ENTRIES, ..Params::RTL }
}

/// The memory and port of WSCG'03 Fig. 13: the `wscg03` preset's ([`WSCG_MEMORY`];
/// DATE'05's chip with its port at full speed: 16 requests in flight, 14 pairs prefetched),
/// with [`QUEUE_ENTRIES`]. WSCG'03's chip reads only the memory.
pub fn wscg_params() -> Params {
    Params { queue_entries: QUEUE_ENTRIES, ..Preset::Wscg03.params() }
}

/// WSCG'03 Eq. 5 in clocks: sum over lists of 100 + (alpha - 2) * 10, alpha the list's
/// aligned node pairs.
pub fn eq5_cycles(lists: u64, node_pairs: u64) -> f64 {
    100.0 * lists as f64 + 10.0 * (node_pairs as f64 - 2.0 * lists as f64)
}

const ORDERS: [Traversal; 2] = [Traversal::Lifo, Traversal::Fifo];
const MODES: [Mode; 2] = [Mode::All, Mode::First];
/// WSCG'03's software traversals: Algorithm 2, Algorithm 1.
const SOFTWARE: [Traversal; 2] = [Traversal::List, Traversal::Recursive];

fn name(t: Traversal) -> &'static str {
    match t {
        Traversal::Recursive => "recursive",
        Traversal::List => "list",
        Traversal::Fifo => "fifo",
        Traversal::Lifo => "lifo",
    }
}

fn mode_name(m: Mode) -> &'static str {
    match m {
        Mode::All => "all",
        Mode::First => "first",
    }
}

/// One pose's counts (golden model and cycle model).
#[derive(Clone, Debug, Default)]
struct PoseCounts {
    /// [order][mode]: pairs the golden D_CNTR reported, the cycle model's clocks, most
    /// queue entries and memory words (node and triangle words).
    pairs: [[usize; 2]; 2],
    cycles: [[u64; 2]; 2],
    entries: [[u64; 2]; 2],
    words: [[u64; 2]; 2],
    /// [software traversal][mode]: pairs, node words fetched, DOP transforms.
    sw_pairs: [[usize; 2]; 2],
    sw_fetches: [[u64; 2]; 2],
    sw_transforms: [[u64; 2]; 2],
    /// The list traversal's lists and aligned node pairs (all pairs).
    lists: u64,
    list_node_pairs: u64,
    /// DATE'05's chip, LIFO, all pairs, at [`wscg_params`]: clocks, memory words, most
    /// queue entries (two node pairs each).
    wscg_cycles: u64,
    wscg_words: u64,
    wscg_entries: u64,
    /// WSCG'03's chip ([`cycle::wscg03`]) on the same memory, all pairs: clocks, memory
    /// words, DOP tests, tumbled DOPs transformed, most pointers in its list SRAMs.
    stack_cycles: u64,
    stack_words: u64,
    stack_dop_tests: u64,
    stack_transforms: u64,
    stack_pointers: u64,
}

/// Means over the orientations of one mesh at one distance.
#[derive(Clone, Debug)]
struct Point {
    mesh: String,
    triangles: usize,
    distance: f64,
    queries: usize,
    counts: Vec<PoseCounts>,
    /// Software, microseconds per query: [software traversal][mode].
    sw_us: [[f64; 2]; 2],
    /// The golden model's LIFO all-pairs query (DATE'05 Fig. 8's software).
    golden_us: f64,
    /// The parry3d peer (feature `parry`), all pairs.
    parry_us: Option<f64>,
}

impl Point {
    fn mean(&self, f: impl Fn(&PoseCounts) -> f64) -> f64 {
        self.counts.iter().map(f).sum::<f64>() / self.counts.len().max(1) as f64
    }

    fn max(&self, f: impl Fn(&PoseCounts) -> u64) -> u64 {
        self.counts.iter().map(f).max().unwrap_or(0)
    }
}

/// A table cell.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Cell {
    Text(String),
    Int(u64),
    Num(f64),
    /// No value (the parry peer without the feature).
    None,
}

impl Cell {
    fn csv(&self) -> String {
        match self {
            Cell::Text(s) => s.clone(),
            Cell::Int(i) => i.to_string(),
            Cell::Num(x) => format!("{x}"),
            Cell::None => String::new(),
        }
    }
}

/// A figure's data: named columns, one row per plotted point (and series).
#[derive(Clone, Debug, Default)]
pub struct Table {
    pub columns: Vec<&'static str>,
    pub rows: Vec<Vec<Cell>>,
}

impl Table {
    pub fn csv(&self) -> String {
        let mut s = self.columns.join(",") + "\n";
        for r in &self.rows {
            s += &r.iter().map(Cell::csv).collect::<Vec<_>>().join(",");
            s.push('\n');
        }
        s
    }

    /// The rows as JSON objects, keys in column order.
    pub fn json(&self) -> String {
        struct Row<'a>(&'a [&'static str], &'a [Cell]);
        impl Serialize for Row<'_> {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let mut m = s.serialize_map(Some(self.0.len()))?;
                for (k, v) in self.0.iter().zip(self.1) {
                    m.serialize_entry(k, v)?;
                }
                m.end()
            }
        }
        let rows: Vec<Row> = self.rows.iter().map(|r| Row(&self.columns, r)).collect();
        serde_json::to_string_pretty(&rows).expect("serialisable") + "\n"
    }
}

/// One line of a panel.
#[derive(Clone, Debug)]
pub struct Series {
    pub label: String,
    /// Index into the palette (one colour per mesh, or per distance).
    pub color: usize,
    pub style: Style,
    pub points: Vec<(f64, f64)>,
    /// A label beside each point (none if empty).
    pub labels: Vec<String>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    Solid,
    Dashed,
    /// Markers only.
    Points,
}

/// One chart of a figure; a figure's panels are stacked top to bottom.
#[derive(Clone, Debug)]
pub struct Panel {
    pub title: String,
    pub x_label: &'static str,
    pub y_label: &'static str,
    pub log_x: bool,
    pub log_y: bool,
    pub series: Vec<Series>,
}

/// A figure: file stem, title, panels, data.
#[derive(Clone, Debug)]
pub struct Figure {
    pub stem: &'static str,
    pub title: String,
    pub panels: Vec<Panel>,
    pub table: Table,
}

/// Runs `plan` and writes every figure into `out` (`<stem>.svg`, `.png`, `.csv`, `.json`,
/// and `plan.json`). Returns the paths written.
pub fn generate(plan: &Plan, out: &Path, bar: &ProgressBar) -> Result<Vec<PathBuf>, String> {
    let points = measure(plan, bar)?;
    let figs = figures(&points);
    std::fs::create_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
    let mut written = vec![];
    let setup = PlanJson {
        plan,
        chip: ChipConfig::default(),
        date_params: date_params(),
        date_mhz: DATE_MHZ,
        wscg_params: wscg_params(),
        wscg_mhz: WSCG_MHZ,
        parry: cfg!(feature = "parry"),
    };
    write_text(&out.join("plan.json"), &(serde_json::to_string_pretty(&setup).expect("serialisable") + "\n"))?;
    written.push(out.join("plan.json"));
    for f in &figs {
        written.extend(write_figure(f, out)?);
    }
    Ok(written)
}

fn write_text(p: &Path, text: &str) -> Result<(), String> {
    std::fs::write(p, text).map_err(|e| format!("{}: {e}", p.display()))
}

/// Writes `<stem>.csv`, `.json`, `.svg` and `.png` of `f` into `out` (which must exist);
/// returns the paths.
pub fn write_figure(f: &Figure, out: &Path) -> Result<Vec<PathBuf>, String> {
    let p = |ext: &str| out.join(format!("{}.{ext}", f.stem));
    write_text(&p("csv"), &f.table.csv())?;
    write_text(&p("json"), &f.table.json())?;
    draw(f, &p("svg"))?;
    draw(f, &p("png"))?;
    Ok(["csv", "json", "svg", "png"].map(p).to_vec())
}

/// `plan.json`: what the figures were made with.
#[derive(Serialize)]
struct PlanJson<'a> {
    plan: &'a Plan,
    chip: ChipConfig,
    date_params: Params,
    date_mhz: f64,
    wscg_params: Params,
    wscg_mhz: f64,
    parry: bool,
}

struct Object {
    name: String,
    chip: Chip,
    #[cfg(feature = "parry")]
    peer: crate::peer::PeerMesh,
}

fn measure(plan: &Plan, bar: &ProgressBar) -> Result<Vec<Point>, String> {
    let poses: Vec<Pose> = sweep_poses(&Sweep { distances: plan.distances.clone(), orientations: plan.orientations, seed: plan.seed })?
        .iter()
        .map(|p| p.pose)
        .collect();
    let objects: Vec<Object> = plan
        .meshes
        .iter()
        .map(|m| {
            let mesh = mesh::resolve(m).and_then(|x| x.scaled_into_unit_cube()).map_err(|e| e.to_string())?;
            let tris = mesh.triangles_f64();
            let chip = Chip::new(&tris, &tris, ChipConfig::default()).map_err(|e| format!("{m}: {e}"))?;
            poses.iter().try_for_each(|p| chip.check_pose(p)).map_err(|e| format!("{m}: {e}"))?;
            Ok(Object {
                name: m.clone(),
                chip,
                #[cfg(feature = "parry")]
                peer: crate::peer::PeerMesh::new(&mesh),
            })
        })
        .collect::<Result<_, String>>()?;
    let n = plan.orientations;
    let groups = plan.meshes.len() * plan.distances.len();
    bar.set_length((groups + poses.len() * objects.len()) as u64);

    // Software first, one query at a time, nothing else running.
    bar.set_message("software, one query at a time");
    let mut points = vec![];
    for o in &objects {
        for (di, &distance) in plan.distances.iter().enumerate() {
            let group = &poses[di * n..(di + 1) * n];
            // the best of three: other processes on the machine only ever add time (caches)
            let best = |f: &dyn Fn(&Pose) -> usize| 1e6 * (0..3).map(|_| mean_seconds(group, plan.min_seconds / 3.0, f)).fold(f64::INFINITY, f64::min);
            let time = |t: Traversal, m: Mode| best(&|p| o.chip.query(p, m, t).pairs.len());
            let sw_us = SOFTWARE.map(|t| MODES.map(|m| time(t, m)));
            let golden_us = time(Traversal::Lifo, Mode::All);
            #[cfg(feature = "parry")]
            let parry_us = Some(best(&|p| crate::peer::all_pairs(&o.peer, &o.peer, p)));
            #[cfg(not(feature = "parry"))]
            let parry_us = None;
            points.push(Point {
                mesh: o.name.clone(),
                triangles: o.chip.a.tris.len(),
                distance,
                queries: n,
                counts: vec![],
                sw_us,
                golden_us,
                parry_us,
            });
            bar.inc(1);
        }
    }

    // Counting on every core.
    bar.set_message("golden and cycle model, every core");
    let items: Vec<(usize, usize)> = (0..objects.len()).flat_map(|o| (0..poses.len()).map(move |p| (o, p))).collect();
    let counts = parallel_map(&items, |_, &(o, p)| {
        let r = count(&objects[o].chip, &poses[p]).map_err(|e| format!("{}, pose {}: {e}", objects[o].name, poses[p].text()));
        bar.inc(1);
        r
    });
    for ((o, p), c) in items.into_iter().zip(counts) {
        points[o * plan.distances.len() + p / n].counts.push(c?);
    }
    Ok(points)
}

/// One pose: the golden traversals' counts and the cycle model's clocks; the cycle model's
/// answer must be the golden model's.
fn count(chip: &Chip, pose: &Pose) -> Result<PoseCounts, String> {
    let mut c = PoseCounts::default();
    let all = chip.query(pose, Mode::All, Traversal::Lifo);
    let setup = chip.setup(pose);
    for (oi, &order) in ORDERS.iter().enumerate() {
        for (mi, &mode) in MODES.iter().enumerate() {
            c.pairs[oi][mi] = chip.query(pose, mode, order).pairs.len();
            let (trace, _) = cycle::run_query(chip, &setup, order.order().expect("a D_CNTR order"), mode, date_params(), Reader::default(), cycle::MAX_CYCLES, Default::default())?;
            trace.check(mode, &all).map_err(|e| format!("{} {}: the cycle model disagrees with the golden model: {e}", name(order), mode_name(mode)))?;
            c.cycles[oi][mi] = trace.cycles;
            c.entries[oi][mi] = trace.max_depth;
            c.words[oi][mi] = trace.node_fetches + trace.tri_fetches;
        }
    }
    for (si, &t) in SOFTWARE.iter().enumerate() {
        for (mi, &mode) in MODES.iter().enumerate() {
            let r = chip.query(pose, mode, t);
            c.sw_pairs[si][mi] = r.pairs.len();
            c.sw_fetches[si][mi] = r.counters.node_fetches;
            c.sw_transforms[si][mi] = r.counters.dop_transforms;
            if t == Traversal::List && mode == Mode::All {
                (c.lists, c.list_node_pairs) = (r.counters.lists, r.counters.list_node_pairs);
            }
        }
    }
    let (trace, _) = cycle::run_query(chip, &setup, Order::Lifo, Mode::All, wscg_params(), Reader::default(), cycle::MAX_CYCLES, Default::default())?;
    trace.check(Mode::All, &all).map_err(|e| format!("WSCG memory: the cycle model disagrees with the golden model: {e}"))?;
    (c.wscg_cycles, c.wscg_words, c.wscg_entries) = (trace.cycles, trace.node_fetches + trace.tri_fetches, trace.max_depth);
    let run = cycle::wscg03::run_query(chip, &setup, Mode::All, &wscg_params(), &StackParams::PAPER)?;
    run.trace.check(Mode::All, &all).map_err(|e| format!("WSCG'03's chip disagrees with the golden model: {e}"))?;
    let (t, s) = (&run.trace, &run.stats);
    (c.stack_cycles, c.stack_words, c.stack_dop_tests) = (t.cycles, t.node_fetches + t.tri_fetches, s.dop_tests);
    (c.stack_transforms, c.stack_pointers) = (s.transforms, s.max_list_words);
    Ok(c)
}

/// One series per mesh (colour) and variant (solid, dashed) over distance.
fn by_distance(points: &[Point], variants: &[(&str, bool)], y: impl Fn(&Point, usize) -> Option<f64>) -> Vec<Series> {
    let meshes = mesh_order(points);
    let mut out = vec![];
    for (ci, m) in meshes.iter().enumerate() {
        for (vi, (label, dashed)) in variants.iter().enumerate() {
            let pts: Vec<(f64, f64)> = points.iter().filter(|p| &p.mesh == m).filter_map(|p| Some((p.distance, y(p, vi)?))).collect();
            if !pts.is_empty() {
                let tris = points.iter().find(|p| &p.mesh == m).map_or(0, |p| p.triangles);
                let style = if *dashed { Style::Dashed } else { Style::Solid };
                out.push(Series { label: format!("{m} ({tris} tris) {label}"), color: ci, style, points: pts, labels: vec![] });
            }
        }
    }
    out
}

fn mesh_order(points: &[Point]) -> Vec<String> {
    let mut v: Vec<String> = vec![];
    for p in points {
        if !v.contains(&p.mesh) {
            v.push(p.mesh.clone());
        }
    }
    v
}

fn key(p: &Point) -> [Cell; 4] {
    [Cell::Text(p.mesh.clone()), Cell::Int(p.triangles as u64), Cell::Num(p.distance), Cell::Int(p.queries as u64)]
}

const KEY: [&str; 4] = ["mesh", "triangles", "distance", "queries"];

fn panel(title: &str, x_label: &'static str, y_label: &'static str, series: Vec<Series>) -> Panel {
    Panel { title: title.into(), x_label, y_label, log_x: false, log_y: true, series }
}

const DIST: &str = "centre distance (objects in [-1,1]^3)";

/// The figures from the measured points.
fn figures(points: &[Point]) -> Vec<Figure> {
    let orders = [("LIFO", false), ("FIFO", true)];
    let sw = [("Alg. 2 (list)", false), ("Alg. 1 (recursive)", true)];
    let mut figs = vec![];

    // DATE'05 Fig. 6 and 7.
    let mut t6 = Table { columns: [&KEY[..], &["order", "mode", "pairs", "cycles", "cycles_max", "chip_us", "words"]].concat(), rows: vec![] };
    let mut t7 = Table { columns: [&KEY[..], &["order", "mode", "pairs", "max_entries", "max_entries_max", "queue_bytes"]].concat(), rows: vec![] };
    for p in points {
        for (oi, &o) in ORDERS.iter().enumerate() {
            for (mi, &m) in MODES.iter().enumerate() {
                let cycles = p.mean(|c| c.cycles[oi][mi] as f64);
                let pairs = Cell::Num(p.mean(|c| c.pairs[oi][mi] as f64));
                let base = |v: Vec<Cell>| [&key(p)[..], &[Cell::Text(name(o).into()), Cell::Text(mode_name(m).into()), pairs.clone()], &v[..]].concat();
                t6.rows.push(base(vec![
                    Cell::Num(cycles),
                    Cell::Int(p.max(|c| c.cycles[oi][mi])),
                    Cell::Num(cycles / DATE_MHZ),
                    Cell::Num(p.mean(|c| c.words[oi][mi] as f64)),
                ]));
                let entries = p.mean(|c| c.entries[oi][mi] as f64);
                // an entry is two node pairs of 16-bit ids and a flip bit each, 67 bits
                let bytes = entries * crate::chip::layout::ENTRY_BITS as f64 / 8.0;
                t7.rows.push(base(vec![Cell::Num(entries), Cell::Int(p.max(|c| c.entries[oi][mi])), Cell::Num(bytes)]));
            }
        }
    }
    figs.push(Figure {
        stem: "date05_fig6_cycles",
        title: "DATE'05 Fig. 6: query time, LIFO vs FIFO (cycle model, k = 24, binary32)".into(),
        panels: MODES
            .iter()
            .enumerate()
            .map(|(mi, &m)| {
                let title = if m == Mode::All { "all intersecting pairs" } else { "first hit" };
                panel(title, DIST, "clocks per query", by_distance(points, &orders, |p, oi| Some(p.mean(|c| c.cycles[oi][mi] as f64))))
            })
            .collect(),
        table: t6,
    });
    figs.push(Figure {
        stem: "date05_fig7_queue",
        title: "DATE'05 Fig. 7: queue memory, LIFO vs FIFO (cycle model)".into(),
        panels: vec![panel(
            "most queue entries (two node pairs each) at once, all pairs",
            DIST,
            "queue entries",
            by_distance(points, &orders, |p, oi| Some(p.mean(|c| c.entries[oi][0] as f64))),
        )],
        table: t7,
    });

    // DATE'05 Fig. 8.
    let chip_us = |p: &Point| p.mean(|c| c.cycles[0][0] as f64) / DATE_MHZ;
    let mut t8 = Table {
        columns: [&KEY[..], &["pairs", "cycles", "chip_us", "golden_us", "parry_us", "speedup_golden", "speedup_parry"]].concat(),
        rows: vec![],
    };
    for p in points {
        let c = chip_us(p);
        let opt = |x: Option<f64>| x.map_or(Cell::None, Cell::Num);
        t8.rows.push(
            [
                &key(p)[..],
                &[
                    Cell::Num(p.mean(|c| c.pairs[0][0] as f64)),
                    Cell::Num(p.mean(|c| c.cycles[0][0] as f64)),
                    Cell::Num(c),
                    Cell::Num(p.golden_us),
                    opt(p.parry_us),
                    Cell::Num(p.golden_us / c),
                    opt(p.parry_us.map(|x| x / c)),
                ],
            ]
            .concat(),
        );
    }
    let peers = [("over the golden model", false), ("over parry3d", true)];
    let speedup = |p: &Point, v: usize| if v == 0 { Some(p.golden_us / chip_us(p)) } else { p.parry_us.map(|x| x / chip_us(p)) };
    let mut distances: Vec<f64> = points.iter().map(|p| p.distance).collect();
    distances.sort_by(f64::total_cmp);
    distances.dedup();
    let by_tris: Vec<Series> = distances
        .iter()
        .rev()
        .step_by(2)
        .enumerate()
        .map(|(ci, &d)| {
            let mut pts: Vec<(f64, f64)> = points.iter().filter(|p| p.distance == d).map(|p| (p.triangles as f64, p.golden_us / chip_us(p))).collect();
            pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            Series { label: format!("d = {d}"), color: ci, style: Style::Solid, points: pts, labels: vec![] }
        })
        .collect();
    figs.push(Figure {
        stem: "date05_fig8_speedup",
        title: format!("DATE'05 Fig. 8: the chip at {DATE_MHZ} MHz over software on this machine, all pairs"),
        panels: vec![
            panel("speed-up against distance (cycle model, LIFO)", DIST, "speed-up", by_distance(points, &peers, speedup)),
            Panel { log_x: true, ..panel("speed-up over the golden model against triangle count", "triangles per object", "speed-up", by_tris) },
        ],
        table: t8,
    });

    // WSCG'03 Figs. 9-12.
    let mut t9 = Table {
        columns: [&KEY[..], &["traversal", "mode", "pairs", "software_us", "node_fetches", "dop_transforms"]].concat(),
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
    let modes_panels = |y_label: &'static str, f: &dyn Fn(&Point, usize, usize) -> f64| -> Vec<Panel> {
        MODES
            .iter()
            .enumerate()
            .map(|(mi, &m)| {
                let title = if m == Mode::All { "all pairs" } else { "first witness" };
                panel(title, DIST, y_label, by_distance(points, &sw, |p, si| Some(f(p, si, mi))))
            })
            .collect()
    };
    let rows_of = |mode: Mode| Table {
        columns: t9.columns.clone(),
        rows: t9.rows.iter().filter(|r| r[5] == Cell::Text(mode_name(mode).into())).cloned().collect(),
    };
    let time_panels = modes_panels("microseconds per query (this machine)", &|p, si, mi| p.sw_us[si][mi]);
    figs.push(Figure {
        stem: "wscg03_fig9_first_witness",
        title: "WSCG'03 Fig. 9: software time, first witness (golden model, one query at a time)".into(),
        panels: vec![time_panels[1].clone()],
        table: rows_of(Mode::First),
    });
    figs.push(Figure {
        stem: "wscg03_fig10_all_pairs",
        title: "WSCG'03 Fig. 10: software time, all pairs (golden model, one query at a time)".into(),
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
        panels: modes_panels("DOP transforms per query", &|p, si, mi| p.mean(|c| c.sw_transforms[si][mi] as f64)),
        table: t9,
    });

    // WSCG'03 Fig. 13 and Eq. 5: WSCG'03's chip, its Eq. 5, and DATE'05's chip on the same memory.
    let eq5 = |p: &Point| p.mean(|c| eq5_cycles(c.lists, c.list_node_pairs));
    let clocks = |p: &Point, v: usize| match v {
        0 => p.mean(|c| c.stack_cycles as f64),
        1 => eq5(p),
        _ => p.mean(|c| c.wscg_cycles as f64),
    };
    let mut t13 = Table {
        columns: [&KEY[..], &["pairs", "software_us", "wscg03_cycles", "eq5_cycles", "date05_cycles", "lists", "alpha", "wscg03_clocks_per_list", "eq5_clocks_per_list", "speedup_wscg03", "speedup_eq5", "speedup_date05"]].concat(),
        rows: vec![],
    };
    for p in points {
        let lists = p.mean(|c| c.lists as f64).max(1.0);
        let speedup = |v| p.sw_us[0][0] / (clocks(p, v) / WSCG_MHZ);
        let nums = [
            p.mean(|c| c.sw_pairs[0][0] as f64),
            p.sw_us[0][0],
            clocks(p, 0),
            clocks(p, 1),
            clocks(p, 2),
            lists,
            p.mean(|c| c.list_node_pairs as f64) / lists,
            clocks(p, 0) / lists,
            clocks(p, 1) / lists,
            speedup(0),
            speedup(1),
            speedup(2),
        ];
        t13.rows.push([&key(p)[..], &nums.map(Cell::Num)[..]].concat());
    }
    let models = [("WSCG'03's chip (cycle model)", false), ("Eq. 5", true), ("DATE'05's chip, LIFO (cycle model)", true)];
    figs.push(Figure {
        stem: "wscg03_fig13_speedup",
        title: format!("WSCG'03 Fig. 13: the chip at {WSCG_MHZ} MHz over software (Alg. 2) on this machine, all pairs, WSCG'03's memory"),
        panels: vec![
            panel("speed-up", DIST, "speed-up", by_distance(points, &models, |p, v| Some(p.sw_us[0][0] / (clocks(p, v) / WSCG_MHZ)))),
            panel("the chip's clocks per query", DIST, "clocks", by_distance(points, &models, |p, v| Some(clocks(p, v)))),
        ],
        table: t13,
    });
    figs.push(side_by_side(points));
    figs
}

/// The two papers' chips on the same sweep and WSCG'03's memory, all pairs: clocks, DOP
/// tests and tumbled-DOP transforms per clock (DATE'05's DOPTRF transforms in every test),
/// memory words, and their traversal memory (D_CNTR's queue entries, two node pairs each;
/// the Stack Engine's aligned pointers in its list SRAMs).
fn side_by_side(points: &[Point]) -> Figure {
    let chips = [("WSCG'03's chip", false), ("DATE'05's chip, LIFO", true)];
    let mut t = Table {
        columns: [&KEY[..], &["wscg03_clocks", "date05_clocks", "wscg03_dop_per_clock", "date05_dop_per_clock", "wscg03_transforms_per_clock", "date05_transforms_per_clock", "wscg03_words", "date05_words", "wscg03_list_pointers", "date05_queue_entries"]].concat(),
        rows: vec![],
    };
    let per_clock = |p: &Point, f: fn(&PoseCounts) -> u64, clocks: fn(&PoseCounts) -> u64| p.mean(|c| f(c) as f64) / p.mean(|c| clocks(c) as f64).max(1.0);
    // all pairs, both chips test the golden traversal's DOP pairs (tb/wscg03.rs,
    // tb/cycle_chip.rs): one count; DATE'05 transforms in every test
    for p in points {
        let nums = [
            p.mean(|c| c.stack_cycles as f64),
            p.mean(|c| c.wscg_cycles as f64),
            per_clock(p, |c| c.stack_dop_tests, |c| c.stack_cycles),
            per_clock(p, |c| c.stack_dop_tests, |c| c.wscg_cycles),
            per_clock(p, |c| c.stack_transforms, |c| c.stack_cycles),
            per_clock(p, |c| c.stack_dop_tests, |c| c.wscg_cycles),
            p.mean(|c| c.stack_words as f64),
            p.mean(|c| c.wscg_words as f64),
        ];
        let mem = [Cell::Int(p.max(|c| c.stack_pointers)), Cell::Int(p.max(|c| c.wscg_entries))];
        t.rows.push([&key(p)[..], &nums.map(Cell::Num)[..], &mem[..]].concat());
    }
    let y = |p: &Point, v: usize| Some(p.mean(|c| if v == 0 { c.stack_cycles } else { c.wscg_cycles } as f64));
    Figure {
        stem: "wscg03_vs_date05",
        title: format!("WSCG'03's chip and DATE'05's on WSCG'03's memory at {WSCG_MHZ} MHz, all pairs"),
        panels: vec![panel("clocks per query", DIST, "clocks", by_distance(points, &chips, y))],
        table: t,
    }
}

pub const PALETTE: [RGBColor; 9] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(70, 70, 70),
];

/// The embedded font (Liberation Sans, SIL OFL 1.1, assets/fonts/): PNG text needs no font
/// installed on the machine.
fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let bytes: &'static [u8] = include_bytes!("../../assets/fonts/LiberationSans-Regular.ttf");
        plotters::style::register_font("sans-serif", FontStyle::Normal, bytes).unwrap_or_else(|_| panic!("the embedded font is valid"));
    });
}

const WIDTH: u32 = 900;
const PANEL_HEIGHT: u32 = 420;

/// Writes `f` to `path`, SVG or PNG by its extension.
pub fn draw(f: &Figure, path: &Path) -> Result<(), String> {
    register_font();
    let size = (WIDTH, 40 + PANEL_HEIGHT * f.panels.len() as u32);
    let err = |e: String| format!("{}: {e}", path.display());
    if path.extension().is_some_and(|e| e == "svg") {
        return draw_on(SVGBackend::new(path, size).into_drawing_area(), f).map_err(err);
    }
    let mut rgb = vec![0u8; 3 * (size.0 * size.1) as usize];
    draw_on(BitMapBackend::with_buffer(&mut rgb, size).into_drawing_area(), f).map_err(err)?;
    write_png(path, size, &rgb).map_err(|e| err(e.to_string()))
}

/// PNG at the best compression, with a palette where the image has at most 256 colours
/// (the figures are committed to docs/: plotters' own encoder writes them 2-3 times larger).
fn write_png(path: &Path, (w, h): (u32, u32), rgb: &[u8]) -> Result<(), png::EncodingError> {
    let mut palette: Vec<[u8; 3]> = vec![];
    let mut index = std::collections::HashMap::new();
    let mut indexed = Vec::with_capacity(rgb.len() / 3);
    for px in rgb.chunks_exact(3) {
        let c = [px[0], px[1], px[2]];
        let i = *index.entry(c).or_insert_with(|| {
            palette.push(c);
            palette.len() - 1
        });
        indexed.push(i);
    }
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut enc = png::Encoder::new(file, w, h);
    enc.set_compression(png::Compression::Best);
    enc.set_adaptive_filter(png::AdaptiveFilterType::Adaptive);
    if palette.len() <= 256 {
        enc.set_color(png::ColorType::Indexed);
        enc.set_palette(palette.concat());
        let bytes: Vec<u8> = indexed.iter().map(|&i| i as u8).collect();
        enc.write_header()?.write_image_data(&bytes)
    } else {
        enc.set_color(png::ColorType::Rgb);
        enc.write_header()?.write_image_data(rgb)
    }
}

fn draw_on<DB: DrawingBackend>(root: DrawingArea<DB, plotters::coord::Shift>, f: &Figure) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    root.fill(&WHITE).map_err(e)?;
    let root = root.titled(&f.title, ("sans-serif", 18)).map_err(e)?;
    for (area, p) in root.split_evenly((f.panels.len(), 1)).iter().zip(&f.panels) {
        let (xr, yr) = (range(p, |q| q.0, p.log_x, false), range(p, |q| q.1, p.log_y, true));
        match (p.log_x, p.log_y) {
            (false, false) => chart(area, p, xr, yr),
            (false, true) => chart(area, p, xr, yr.log_scale()),
            (true, false) => chart(area, p, xr.log_scale(), yr),
            (true, true) => chart(area, p, xr.log_scale(), yr.log_scale()),
        }?;
    }
    root.present().map_err(e)
}

/// The corner (or top or bottom middle) of the panel with the fewest data points, for the
/// legend.
fn legend_corner(p: &Panel) -> SeriesLabelPosition {
    let axis = |v: fn(&(f64, f64)) -> f64, log: bool, decades: bool| {
        let r = range(p, v, log, decades);
        let t = move |x: f64| if log { x.log10() } else { x };
        let (lo, hi) = (t(r.start), t(r.end));
        move |x: f64| (t(x) - lo) / (hi - lo)
    };
    let (nx, ny) = (axis(|q| q.0, p.log_x, false), axis(|q| q.1, p.log_y, true));
    // the lines' points, and 8 more along each segment
    let pts: Vec<(f64, f64)> = p
        .series
        .iter()
        .flat_map(|s| {
            let n: Vec<(f64, f64)> = s.points.iter().map(|q| (nx(q.0), ny(q.1))).filter(|q| q.0.is_finite() && q.1.is_finite()).collect();
            let segs: Vec<(f64, f64)> = n.windows(2).flat_map(|w| (1..9).map(move |i| {
                let f = i as f64 / 9.0;
                (w[0].0 + f * (w[1].0 - w[0].0), w[0].1 + f * (w[1].1 - w[0].1))
            })).collect();
            n.into_iter().chain(segs)
        })
        .collect();
    // (position, its horizontal span, upper)
    let places = [
        (SeriesLabelPosition::UpperRight, (0.45, 1.0), true),
        (SeriesLabelPosition::UpperLeft, (0.0, 0.55), true),
        (SeriesLabelPosition::LowerRight, (0.45, 1.0), false),
        (SeriesLabelPosition::LowerLeft, (0.0, 0.55), false),
        (SeriesLabelPosition::UpperMiddle, (0.22, 0.78), true),
        (SeriesLabelPosition::LowerMiddle, (0.22, 0.78), false),
    ];
    let inside = |&(x, y): &(f64, f64), (lo, hi): (f64, f64), upper: bool| x > lo && x < hi && (if upper { y > 0.55 } else { y < 0.45 });
    let (pos, ..) = places.into_iter().min_by_key(|&(_, span, u)| pts.iter().filter(|q| inside(q, span, u)).count()).expect("six places");
    pos
}

/// An axis label: no trailing zeros, exponent form from 10^5.
fn tick(v: &f64) -> String {
    match v.abs() {
        a if a >= 1e5 => format!("{v:.0e}"),
        a if a >= 10.0 => format!("{v:.0}"),
        _ => format!("{v:.2}").trim_end_matches('0').trim_end_matches('.').to_string(),
    }
}

/// The axis range of a panel's values, with a margin; positive values only on a log axis,
/// whole decades on a log y axis (plotters labels no value below a log axis's first
/// power of ten).
fn range(p: &Panel, v: impl Fn(&(f64, f64)) -> f64, log: bool, decades: bool) -> std::ops::Range<f64> {
    let vals = p.series.iter().flat_map(|s| s.points.iter().map(&v)).filter(|x| x.is_finite() && (!log || *x > 0.0));
    let (lo, hi) = vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)));
    match (lo.is_finite(), log) {
        (false, _) => 1.0..10.0,
        (true, true) if decades => 10f64.powf(lo.log10().floor())..10f64.powf((hi * 1.01).log10().ceil()),
        (true, true) => lo / 1.5..hi * 1.5,
        (true, false) => {
            let m = ((hi - lo) * 0.05).max(1e-9);
            lo - m..hi + m
        }
    }
}

fn chart<DB: DrawingBackend, X: AsRangedCoord<Value = f64>, Y: AsRangedCoord<Value = f64>>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    p: &Panel,
    x: X,
    y: Y,
) -> Result<(), String>
where
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let mut c = ChartBuilder::on(area)
        .caption(&p.title, ("sans-serif", 16))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x, y)
        .map_err(e)?;
    c.configure_mesh()
        .x_desc(p.x_label)
        .y_desc(p.y_label)
        .label_style(("sans-serif", 13))
        .x_labels(if p.log_x { 4 } else { 10 })
        .y_labels(12)
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .light_line_style(WHITE.mix(0.0))
        .draw()
        .map_err(e)?;
    for s in &p.series {
        let color = PALETTE[s.color % PALETTE.len()];
        let style = color.stroke_width(2);
        let pts = s.points.iter().copied().filter(|q| q.0.is_finite() && q.1.is_finite());
        let ann = match s.style {
            Style::Solid => c.draw_series(LineSeries::new(pts.clone(), style)).map_err(e)?,
            Style::Dashed => c.draw_series(DashedLineSeries::new(pts.clone(), 6, 4, style)).map_err(e)?,
            Style::Points => c.draw_series(pts.clone().map(|q| Circle::new(q, 5, color.filled()))).map_err(e)?,
        };
        // a dashed legend line is two segments
        let gap = if s.style == Style::Dashed { 5 } else { 0 };
        ann.label(&s.label).legend(move |(x, y)| {
            EmptyElement::at((x, y))
                + PathElement::new(vec![(0, 0), (8, 0)], color.stroke_width(2))
                + PathElement::new(vec![(8 + gap, 0), (20, 0)], color.stroke_width(2))
        });
        let font = ("sans-serif", 11).into_font().color(&color);
        c.draw_series(s.points.iter().zip(&s.labels).map(|(&q, l)| Text::new(l.clone(), q, font.clone()))).map_err(e)?;
        c.draw_series(pts.map(|q| Circle::new(q, 3, color.filled()))).map_err(e)?;
    }
    c.configure_series_labels()
        .position(legend_corner(p))
        .label_font(("sans-serif", 12))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.4))
        .draw()
        .map_err(e)?;
    Ok(())
}
