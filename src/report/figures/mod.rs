//! `cchip figures`: the papers' figures regenerated on this project's models, each as SVG and
//! PNG with its data beside it as CSV and JSON (docs/explanation/figures.md reads them).
//!
//! Protocol (WSCG'03 §5, DATE'05 §5): each mesh against a copy of itself, both scaled into
//! [-1,1]^3, B tumbling through seeded orientations at each centre distance along x, from
//! apart to penetrating; every number is a mean over the orientations at one distance.
//!
//! - DATE'05 Fig. 6 (cycles, LIFO vs FIFO, all pairs and first hit), Fig. 7 (queue entries),
//!   Fig. 8 (speed-up over software on this machine, the chip's time and end to end): the
//!   cycle model of DATE'05's chip on a preset ([`Plan::date_preset`], `date05`: k = 24,
//!   binary32, DATE'05's DDR2, records and node cache, the port at full speed) with a queue
//!   too large to overflow ([`QUEUE_ENTRIES`]), so that FIFO's need shows.
//! - WSCG'03 Figs. 9-10 (software time of Algorithm 2, the list traversal, vs Algorithm 1,
//!   the recursive one; first witness, all pairs), Fig. 11 (node words fetched), Fig. 12 (DOP
//!   transforms): the golden model's traversals on the software's configuration (a node word
//!   per fetch, no cache). Fig. 13: WSCG'03's chip clocked as its RTL
//!   ([`cycle::wscg03::clocked`]) on a preset's memory ([`Plan::wscg_preset`], `wscg03`), its
//!   event model with the paper's parameters and Eq. 5's estimate from the list traversal's
//!   lists, at its RTL chip's period, and DATE'05's chip on the same preset at its own;
//!   beside it the two chips' table (`wscg03_vs_date05`).
//!
//! A chip's time is its clocks x its period ([`Clock`], for its architecture: measured, or
//! the paper's clock, assumed); end to end adds the host's setup and its settling of the
//! uncertain pairs (as `cchip run`). Software and the host are timed one query at a time
//! before anything else runs; the counting work (golden counters, cycle model) then runs on
//! every core.

use super::plot::{write_figure, write_text, Cell, Figure, Panel, Series, Style};
use crate::chip::config::ChipConfig;
use crate::chip::params::Params;
use crate::chip::preset::Preset;
use crate::chip::reg::{Mode, Order};
use crate::chip::timing::{Clock, Folds, PeriodSource, Technology};
use crate::chip::wscg03::{Architecture, StackParams};
use crate::cycle::{self, drive::Reader};
use crate::measure::{interleaved_best, parallel_map};
use crate::mesh;
use crate::pose::Pose;
use crate::pose::{sweep_poses, Sweep};
use crate::query::{Chip, HostTime};
use crate::traversal::Traversal;
use indicatif::ProgressBar;
use serde::Serialize;
use std::path::{Path, PathBuf};

mod date05;
mod wscg03;

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
    /// The chip preset of every figure (`cchip figures --preset`); none: `date05` for
    /// DATE'05's figures, `wscg03` for WSCG'03's Fig. 13.
    pub preset: Option<Preset>,
    /// Where the chips' clock period comes from.
    pub technology: Technology,
}

impl Plan {
    /// The figures of docs/explanation/figures.md.
    pub fn full() -> Plan {
        Plan {
            meshes: vec!["teapot".into(), "bunny".into(), "dragon-11k".into()],
            distances: vec![2.4, 2.2, 2.0, 1.8, 1.6, 1.4, 1.2, 1.0, 0.8],
            orientations: 64,
            seed: 1,
            min_seconds: 0.2,
            preset: None,
            technology: Technology::Osu018,
        }
    }

    /// CI's: the two smaller meshes, fewer distances and orientations.
    pub fn quick() -> Plan {
        Plan {
            meshes: vec!["teapot".into(), "bunny".into()],
            distances: vec![2.2, 1.8, 1.4, 1.2, 1.0],
            orientations: 6,
            seed: 1,
            min_seconds: 0.025,
            preset: None,
            technology: Technology::Osu018,
        }
    }

    /// The chip of DATE'05's Figs. 6-8.
    pub fn date_preset(&self) -> Preset {
        self.preset.unwrap_or(Preset::Date05)
    }

    /// The memory (and DATE'05's chip's port) of WSCG'03's Fig. 13.
    pub fn wscg_preset(&self) -> Preset {
        self.preset.unwrap_or(Preset::Wscg03)
    }
}

/// Queue entries of the figures' chip: no FIFO traversal of these meshes overflows it
/// (the RTL's 1,024 would, and an overflowed query has no complete answer).
pub const QUEUE_ENTRIES: u32 = 1 << 24;

/// A chip the figures run: a preset's configuration as the architecture's chip runs it,
/// its timing with [`QUEUE_ENTRIES`], and its clock ([`Clock::for_architecture`]).
#[derive(Clone, Debug, Serialize)]
pub struct ChipRun {
    pub preset: Preset,
    pub architecture: Architecture,
    pub cfg: ChipConfig,
    pub params: Params,
    pub clock: Clock,
    /// [`Clock::source`]: the period and where it came from.
    pub clock_source: String,
}

impl ChipRun {
    pub fn of(
        preset: Preset,
        architecture: Architecture,
        technology: Technology,
    ) -> Result<ChipRun, String> {
        let cfg = architecture.config(&preset.chip());
        let clock =
            Clock::of(technology, &cfg, Folds::NONE, preset)?.for_architecture(architecture, &cfg);
        let params = Params {
            queue_entries: QUEUE_ENTRIES,
            clock_ps: clock.ps(),
            ..preset.params()
        };
        Ok(ChipRun {
            preset,
            architecture,
            cfg,
            params,
            clock_source: clock.source(),
            clock,
        })
    }

    /// Microseconds of `clocks` at this chip's period.
    pub fn us(&self, clocks: f64) -> f64 {
        clocks * self.clock.period_ns / 1000.0
    }

    /// The period in a title: `9.09 ns (110 MHz, measured: chip_b32_k24)`.
    fn period(&self) -> String {
        let c = &self.clock;
        let from = match (c.source, &c.slowest) {
            (PeriodSource::Assumed, _) => "the paper's clock, assumed".to_string(),
            (how, Some(u)) => format!("{}: {u}", how.name()),
            (how, None) => how.name().to_string(),
        };
        format!("{:.2} ns ({:.0} MHz, {from})", c.period_ns, c.mhz())
    }

    /// The chip in a title: `preset date05: k = 24, binary32, memory DDR ...`.
    fn name(&self) -> String {
        format!(
            "preset {}: k = {}, {}",
            self.preset.name(),
            self.cfg.k,
            self.cfg.format
        )
    }
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
    /// DATE'05's chip, LIFO, all pairs, on Fig. 13's preset ([`Runs::wscg`]): clocks, memory words, most
    /// queue entries (two node pairs each).
    wscg_cycles: u64,
    wscg_words: u64,
    wscg_entries: u64,
    /// WSCG'03's chip clocked as its RTL ([`cycle::wscg03::clocked`]) on the same memory,
    /// all pairs: clocks, memory words, DOP tests, tumbled DOPs transformed, most pointers
    /// its list SRAMs held.
    stack_cycles: u64,
    stack_words: u64,
    stack_dop_tests: u64,
    stack_transforms: u64,
    stack_pointers: u64,
    /// Its event model with the paper's parameters ([`cycle::wscg03::run_query`],
    /// [`StackParams::PAPER`]): clocks.
    event_cycles: u64,
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
    /// The host's share of a query on each chip ([`Runs`]: DATE'05's, WSCG'03 Fig. 13's).
    host: [HostTime; 2],
}

impl Point {
    fn mean(&self, f: impl Fn(&PoseCounts) -> f64) -> f64 {
        self.counts.iter().map(f).sum::<f64>() / self.counts.len().max(1) as f64
    }

    fn max(&self, f: impl Fn(&PoseCounts) -> u64) -> u64 {
        self.counts.iter().map(f).max().unwrap_or(0)
    }
}

/// The chips of a plan: DATE'05's Figs. 6-8; WSCG'03's Fig. 13, its chip (`stack`) and
/// DATE'05's (`wscg`) on its preset.
#[derive(Clone, Debug, Serialize)]
pub struct Runs {
    pub date: ChipRun,
    pub wscg: ChipRun,
    pub stack: ChipRun,
}

impl Runs {
    pub fn of(plan: &Plan) -> Result<Runs, String> {
        let (tech, wscg) = (plan.technology, plan.wscg_preset());
        Ok(Runs {
            date: ChipRun::of(plan.date_preset(), Architecture::Date05, tech)?,
            wscg: ChipRun::of(wscg, Architecture::Date05, tech)?,
            stack: ChipRun::of(wscg, Architecture::Wscg03, tech)?,
        })
    }
}

/// Runs `plan` and writes every figure into `out` (`<stem>.svg`, `.png`, `.csv`, `.json`,
/// and `plan.json`). Returns the paths written.
/// `out` is made first: a path that cannot be a directory is refused before the run.
pub fn generate(plan: &Plan, out: &Path, bar: &ProgressBar) -> Result<Vec<PathBuf>, String> {
    super::plot::output_dir(out)?;
    let runs = Runs::of(plan)?;
    let points = measure(plan, &runs, bar)?;
    let figs = figures(&points, &runs);
    let mut written = vec![];
    let setup = PlanJson {
        plan,
        software: ChipConfig::default(),
        runs: &runs,
        parry: cfg!(feature = "parry"),
    };
    write_text(
        &out.join("plan.json"),
        &(serde_json::to_string_pretty(&setup).expect("serialisable") + "\n"),
    )?;
    written.push(out.join("plan.json"));
    for f in &figs {
        written.extend(write_figure(f, out)?);
    }
    Ok(written)
}

/// `plan.json`: what the figures were made with.
#[derive(Serialize)]
struct PlanJson<'a> {
    plan: &'a Plan,
    /// The golden model's configuration for the software times and Figs. 9-12.
    software: ChipConfig,
    runs: &'a Runs,
    parry: bool,
}

/// One mesh against a copy of itself: the software's image and the two chips' (each
/// preset lays its image out its own way).
struct Object {
    name: String,
    software: Chip,
    date: Chip,
    wscg: Chip,
    stack: Chip,
    #[cfg(feature = "parry")]
    peer: crate::peer::PeerMesh,
}

/// Mean microseconds per call of `f` over `items`, one call at a time: the best of three
/// runs of `seconds / 3` each (other processes on the machine only ever add time).
fn best_us<T>(items: &[T], seconds: f64, f: impl Fn(&T) -> usize) -> f64 {
    1e6 * interleaved_best(items, seconds, 3, [&f])[0]
}

/// The host's share of `chip`'s queries at `poses`, each timed as [`best_us`] for a third of
/// `seconds` (a few microseconds a pose: many runs in that): its setup, and its settling of
/// the pose's uncertain pairs (those of the all-pairs query).
fn host_time(chip: &Chip, poses: &[Pose], seconds: f64) -> HostTime {
    let seconds = seconds / 3.0;
    let items: Vec<(&Pose, Vec<(u32, u32)>)> = poses
        .iter()
        .map(|p| (p, chip.query(p, Mode::All, Traversal::Lifo).uncertain))
        .collect();
    HostTime {
        setup_us: best_us(&items, seconds, |(p, _)| chip.setup(p).cvec.len()),
        settle_us: best_us(&items, seconds, |(p, u)| chip.settle(p, u)),
    }
}

fn measure(plan: &Plan, runs: &Runs, bar: &ProgressBar) -> Result<Vec<Point>, String> {
    let poses: Vec<Pose> = sweep_poses(&Sweep {
        distances: plan.distances.clone(),
        orientations: plan.orientations,
        seed: plan.seed,
    })?
    .iter()
    .map(|p| p.pose)
    .collect();
    // the images on every core (three per mesh)
    let objects: Vec<Object> = parallel_map(&plan.meshes, |_, m| {
        let mesh = mesh::resolve(m)
            .and_then(|x| x.scaled_into_unit_cube())
            .map_err(|e| e.to_string())?;
        let tris = mesh.triangles_f64();
        let chip = |cfg: ChipConfig| Chip::new(&tris, &tris, cfg).map_err(|e| format!("{m}: {e}"));
        let software = chip(ChipConfig::default())?;
        poses
            .iter()
            .try_for_each(|p| software.check_pose(p))
            .map_err(|e| format!("{m}: {e}"))?;
        Ok(Object {
            name: m.clone(),
            software,
            date: chip(runs.date.cfg)?,
            wscg: chip(runs.wscg.cfg)?,
            stack: chip(runs.stack.cfg)?,
            #[cfg(feature = "parry")]
            peer: crate::peer::PeerMesh::new(&mesh),
        })
    })
    .into_iter()
    .collect::<Result<_, String>>()?;
    let n = plan.orientations;
    let groups = plan.meshes.len() * plan.distances.len();
    bar.set_length((groups + poses.len() * objects.len()) as u64);

    // Software and the host first, one query at a time, nothing else running.
    bar.set_message("software and host, one query at a time");
    let mut points = vec![];
    for o in &objects {
        for (di, &distance) in plan.distances.iter().enumerate() {
            let group = &poses[di * n..(di + 1) * n];
            let time = |t: Traversal, m: Mode| {
                best_us(group, plan.min_seconds, |p| {
                    o.software.query(p, m, t).pairs.len()
                })
            };
            let sw_us = SOFTWARE.map(|t| MODES.map(|m| time(t, m)));
            let golden_us = time(Traversal::Lifo, Mode::All);
            #[cfg(feature = "parry")]
            let parry_us = Some(best_us(group, plan.min_seconds, |p| {
                crate::peer::all_pairs(&o.peer, &o.peer, p)
            }));
            #[cfg(not(feature = "parry"))]
            let parry_us = None;
            points.push(Point {
                mesh: o.name.clone(),
                triangles: o.software.a.tri_count(),
                distance,
                queries: n,
                counts: vec![],
                sw_us,
                golden_us,
                parry_us,
                host: {
                    let date = host_time(&o.date, group, plan.min_seconds);
                    // the host's work depends on the arithmetic only: measured once if the same
                    let same = |c: &ChipConfig| (c.k, c.format, c.dop_rounding, c.tri_rounding);
                    [
                        date,
                        if same(&runs.wscg.cfg) == same(&runs.date.cfg) {
                            date
                        } else {
                            host_time(&o.wscg, group, plan.min_seconds)
                        },
                    ]
                },
            });
            bar.inc(1);
        }
    }

    // Counting on every core.
    bar.set_message("golden and cycle model, every core");
    let items: Vec<(usize, usize)> = (0..objects.len())
        .flat_map(|o| (0..poses.len()).map(move |p| (o, p)))
        .collect();
    let counts = parallel_map(&items, |_, &(o, p)| {
        let r = count(&objects[o], runs, &poses[p])
            .map_err(|e| format!("{}, pose {}: {e}", objects[o].name, poses[p].text()));
        bar.inc(1);
        r
    });
    for ((o, p), c) in items.into_iter().zip(counts) {
        points[o * plan.distances.len() + p / n].counts.push(c?);
    }
    Ok(points)
}

/// One pose: the golden traversals' counts and the cycle models' clocks; each cycle model's
/// answer must be the golden model's.
fn count(o: &Object, runs: &Runs, pose: &Pose) -> Result<PoseCounts, String> {
    let mut c = PoseCounts::default();
    let chip = &o.date;
    let all = chip.query(pose, Mode::All, Traversal::Lifo);
    let setup = chip.setup(pose);
    for (oi, &order) in ORDERS.iter().enumerate() {
        for (mi, &mode) in MODES.iter().enumerate() {
            c.pairs[oi][mi] = chip.query(pose, mode, order).pairs.len();
            let (trace, _) = cycle::run_query(
                chip,
                &setup,
                order.order().expect("a D_CNTR order"),
                mode,
                runs.date.params,
                Reader::default(),
                cycle::MAX_CYCLES,
                Default::default(),
            )?;
            trace.check(mode, &all).map_err(|e| {
                format!(
                    "{} {}: the cycle model disagrees with the golden model: {e}",
                    name(order),
                    mode_name(mode)
                )
            })?;
            c.cycles[oi][mi] = trace.cycles;
            c.entries[oi][mi] = trace.max_depth;
            c.words[oi][mi] = trace.node_fetches + trace.tri_fetches;
        }
    }
    for (si, &t) in SOFTWARE.iter().enumerate() {
        for (mi, &mode) in MODES.iter().enumerate() {
            let r = o.software.query(pose, mode, t);
            c.sw_pairs[si][mi] = r.pairs.len();
            c.sw_fetches[si][mi] = r.counters.node_fetches;
            c.sw_transforms[si][mi] = r.counters.dop_transforms;
            if t == Traversal::List && mode == Mode::All {
                (c.lists, c.list_node_pairs) = (r.counters.lists, r.counters.list_node_pairs);
            }
        }
    }
    fig13_counts(o, runs, pose, &mut c)?;
    Ok(c)
}

/// Fig. 13's counts of one pose, on its preset: DATE'05's chip, WSCG'03's chip clocked as
/// its RTL and its event model, each one's answer the golden model's.
fn fig13_counts(o: &Object, runs: &Runs, pose: &Pose, c: &mut PoseCounts) -> Result<(), String> {
    let (chip, params) = (&o.wscg, &runs.wscg.params);
    let (setup, all) = (
        chip.setup(pose),
        chip.query(pose, Mode::All, Traversal::Lifo),
    );
    let (trace, _) = cycle::run_query(
        chip,
        &setup,
        Order::Lifo,
        Mode::All,
        *params,
        Reader::default(),
        cycle::MAX_CYCLES,
        Default::default(),
    )?;
    trace.check(Mode::All, &all).map_err(|e| {
        format!(
            "DATE'05's chip on preset {}: the cycle model disagrees with the golden model: {e}",
            runs.wscg.preset.name()
        )
    })?;
    (c.wscg_cycles, c.wscg_words, c.wscg_entries) = (
        trace.cycles,
        trace.node_fetches + trace.tri_fetches,
        trace.max_depth,
    );
    let (chip, params) = (&o.stack, &runs.stack.params);
    let setup = chip.setup(pose);
    let max = cycle::MAX_CYCLES;
    let run = cycle::wscg03::clocked::run(chip, &setup, (false, params), max, |_, _, _| (), None)?;
    run.trace
        .check(Mode::All, &all)
        .map_err(|e| format!("WSCG'03's chip disagrees with the golden model: {e}"))?;
    let t = &run.trace;
    (c.stack_cycles, c.stack_words, c.stack_dop_tests) =
        (t.cycles, t.node_fetches + t.tri_fetches, t.dop_tests);
    (c.stack_transforms, c.stack_pointers) = (run.transforms, run.max_pointers);
    let event =
        cycle::wscg03::run_query(chip, &setup, Mode::All, params, &StackParams::PAPER, max)?;
    event.trace.check(Mode::All, &all).map_err(|e| {
        format!("WSCG'03's chip's event model disagrees with the golden model: {e}")
    })?;
    c.event_cycles = event.trace.cycles;
    Ok(())
}

/// One series per mesh (colour) and variant (its style) over distance.
fn by_distance(
    points: &[Point],
    variants: &[(&str, Style)],
    y: impl Fn(&Point, usize) -> Option<f64>,
) -> Vec<Series> {
    let meshes = mesh_order(points);
    let mut out = vec![];
    for (ci, m) in meshes.iter().enumerate() {
        for (vi, &(label, style)) in variants.iter().enumerate() {
            let pts: Vec<(f64, f64)> = points
                .iter()
                .filter(|p| &p.mesh == m)
                .filter_map(|p| Some((p.distance, y(p, vi)?)))
                .collect();
            if !pts.is_empty() {
                let tris = points
                    .iter()
                    .find(|p| &p.mesh == m)
                    .map_or(0, |p| p.triangles);
                out.push(Series {
                    label: format!("{m} ({tris} tris) {label}"),
                    color: ci,
                    style,
                    points: pts,
                    labels: vec![],
                });
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
    [
        Cell::Text(p.mesh.clone()),
        Cell::Int(p.triangles as u64),
        Cell::Num(p.distance),
        Cell::Int(p.queries as u64),
    ]
}

const KEY: [&str; 4] = ["mesh", "triangles", "distance", "queries"];

fn panel(title: &str, x_label: &'static str, y_label: &'static str, series: Vec<Series>) -> Panel {
    Panel {
        title: title.into(),
        x_label,
        y_label,
        log_x: false,
        log_y: true,
        series,
    }
}

const DIST: &str = "centre distance (objects in [-1,1]^3)";

/// The figures from the measured points.
fn figures(points: &[Point], runs: &Runs) -> Vec<Figure> {
    let mut figs = date05::queue_figures(points, &runs.date);
    figs.push(date05::fig8(points, &runs.date));
    figs.extend(wscg03::software_figures(points));
    figs.push(wscg03::fig13(points, runs));
    figs.push(wscg03::side_by_side(points, runs));
    figs
}

/// A point's time on a chip, microseconds per query: the chip's clocks at its period, and
/// end to end (the host's setup + the chip + the host's settling, as `cchip run`).
struct Times {
    chip_us: f64,
    e2e_us: f64,
}

impl Times {
    fn of(p: &Point, run: &ChipRun, host: usize, clocks: f64) -> Times {
        let chip_us = run.us(clocks);
        Times {
            chip_us,
            e2e_us: p.host[host].setup_us + chip_us + p.host[host].settle_us,
        }
    }
}

/// `Some(x)` as a number, `None` as an empty cell.
fn opt(x: Option<f64>) -> Cell {
    x.map_or(Cell::None, Cell::Num)
}
