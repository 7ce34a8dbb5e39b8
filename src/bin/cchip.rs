//! `cchip`: run collision queries and scenes on the golden model and the cycle model of the
//! collision chip (and, for small meshes, its RTL in rust-hdl).

// The options' doc comments are clap's --help text, written for a terminal: `[chip]` is a
// scene's TOML table and `<unit>` a placeholder, not rustdoc links or HTML.
#![allow(rustdoc::broken_intra_doc_links, rustdoc::invalid_html_tags)]
// No function over 150 lines (clippy.toml), as in the library.
#![deny(clippy::too_many_lines)]

use clap::{Args, Parser, Subcommand};
use collision_chip::chip::config::{ChipConfig, DopBits, DopRounding, Formats};
use collision_chip::chip::memory::Memory;
use collision_chip::chip::preset::Preset;
use collision_chip::chip::reg::Mode;
use collision_chip::chip::timing::{Folds, PeriodSource, Technology};
use collision_chip::chip::wscg03::Architecture;
use collision_chip::harness::units;
use collision_chip::mesh::{self, Mesh};
use collision_chip::pose::Pose;
use collision_chip::pose::Sweep;
use collision_chip::query::{exact_pairs, Accuracy, Chip};
use collision_chip::report::{
    accuracy, figures, memory_table, plot, stack_table, stall_table, summary_table,
};
use collision_chip::scene::graph::Plan;
use collision_chip::scene::run::Prepared;
use collision_chip::scene::{CrossCheck, Flags, Scene, DEFAULT_SCENE};
use collision_chip::traversal::{Counters, Traversal};
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use std::io::IsTerminal;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

const MESH_HELP: &str = "A mesh file (.obj, .stl, .ply) or a built-in name: bunny, teapot, \
dragon-11k, sphere:N, torus:N, soup:N[:SEED]. Triangle indices are the 0-based face order of \
the file; polygons are split into fans (v0, vi, vi+1).";

/// Simulate the hierarchical collision-detection chip of Zachmann & Knittel (WSCG'03) and
/// Raabe et al. (DATE'05) on two meshes: which triangles collide, and what it costs.
///
/// Without a subcommand, runs the built-in default scene (two Stanford bunnies, one
/// tumbling at five distances, checked against the exact oracle, with the chip's clocks
/// from the cycle model).
#[derive(Parser)]
#[command(
    name = "cchip",
    version,
    after_help = "Examples:\n  \
cchip                                         # the default scene\n  \
cchip run vectors/scenes/default.toml --json  # a scene file, machine-readable\n  \
cchip run --vcd target/vcd/bunny               # the default scene with a traversal VCD per pose\n  \
cchip query bunny bunny --pose 10,20,30,0.02,0,0 --oracle --json\n  \
cchip query teapot sphere:2000 --pose 0,0,0,1,0,0 --traversal fifo --k 14"
)]
struct Cli {
    #[command(subcommand)]
    cmd: Option<Cmd>,
}

#[derive(Subcommand)]
enum Cmd {
    /// One query: B placed in A's frame by a pose, all pairs or the first hit.
    Query(QueryArgs),
    /// Run a scene file (TOML: objects, pose or sweep, chip, query, outputs, memory,
    /// timing); without a file, the built-in default scene (vectors/scenes/default.toml).
    ///
    /// With `cycles = true` in [outputs] every pose also runs on the cycle model (any k and
    /// format, fifo or lifo): the chip's clocks, its time at its clock beside the software's,
    /// and where the clocks went (stall causes, occupancy, memory words per clock). Poses run
    /// on every core.
    Run {
        scene: Option<PathBuf>,
        #[command(flatten)]
        opts: RunOpts,
    },
    /// Write the Verilog of every exported RTL unit (rust-hdl's generate_verilog, identical
    /// modules merged), one file per unit, format and rounding: rtl/<unit>.v. Run the files
    /// with scripts/check-rtl.sh.
    ExportVerilog {
        #[arg(long, default_value = "rtl")]
        out: PathBuf,
        /// Instead, the units of the area study: the DOP unit for every k, format and DOP
        /// rounding, and TRI_UNIT per format, each also folded (TRI_UNIT at a pair every 2 to
        /// 32 clocks, the DOP unit at every interval the RTL builds; scripts/area-study.sh
        /// synthesizes them).
        #[arg(long)]
        area: bool,
    },
    /// Write the golden test vectors of every exported RTL unit: vectors/<unit>.hex
    /// (TestFloat style: inputs, then expected outputs, in hex; see scripts/README.md).
    Vectors {
        #[arg(long, default_value = "vectors")]
        out: PathBuf,
    },
    /// What accuracy costs: each mesh tumbling against a copy of itself (both scaled into
    /// [-1,1]^3) at several distances, with each k, number format (the DOP datapath's apart
    /// from T.CHECK's too) and DOP rounding, compared with the exact oracle and run on the
    /// cycle model for its clocks (poses on every core); with --area, the Yosys cells of
    /// each configuration's units. Prints the tables of docs/explanation/accuracy-cost.md; --plot draws them.
    Accuracy(AccuracyArgs),
    /// The papers' figures regenerated (docs/explanation/figures.md): DATE'05 Figs. 6-8 on the `date05`
    /// preset (cycles and queue memory, LIFO vs FIFO; the chip's speed-up, of its time and
    /// end to end) and WSCG'03 Figs. 9-13 (software time, nodes and DOP transforms of the
    /// list and recursive traversals; on the `wscg03` preset the chips' speed-up beside
    /// Eq. 5: WSCG'03's chip clocked as its RTL at its own period, its event model with the
    /// paper's parameters, DATE'05's chip at its period), each as SVG and PNG with its data
    /// as CSV and JSON. Software and the host are
    /// timed one query at a time, the rest runs on every core. Build with `--features parry`
    /// to add the parry3d peer.
    Figures {
        #[arg(long, default_value = "target/figures")]
        out: PathBuf,
        /// A small run for CI: teapot and bunny, 5 distances, 6 orientations.
        #[arg(long)]
        quick: bool,
        /// Run every figure's chips on this preset instead of date05 (DATE'05's figures) and
        /// wscg03 (WSCG'03's Fig. 13).
        #[arg(long, value_enum)]
        preset: Option<Preset>,
        /// The chips' clock period: osu018 (each chip's RTL, or the configuration's slowest
        /// RTL unit, measured on OSU 0.18 um, docs/figures/timing.csv), ecp5 or paper (the
        /// preset's 800 / 266 MHz, assumed).
        #[arg(long, value_enum, default_value = "osu018")]
        technology: Technology,
    },
}

#[derive(Args, Default)]
struct RunOpts {
    /// Print one JSON record per pose instead of the tables.
    #[arg(long)]
    json: bool,
    /// Also run every pose on the RTL chip in rust-hdl, in lockstep with the cycle model
    /// (scene: cross_check = "rtl"; the exported chips' configurations only: the k = 6
    /// e8m15 chip runs 21-29 clocks per second in rust-hdl's simulator, docs/explanation/speed.md;
    /// so small meshes: e.g. vectors/scenes/rtl_spheres.toml). Any difference is an error
    /// naming the pose, the cycle and the signal. For the exported Verilog under Verilator
    /// (meshes of a few hundred triangles), set cross_check = "verilog" in the scene.
    #[arg(long)]
    rtl: bool,
    /// Write a traversal VCD per pose from the cycle model into this directory; open one
    /// with `gtkwave DIR/pose0.vcd scripts/gtkw/chip_e8m15_k6.gtkw` (WSCG'03's chip:
    /// scripts/gtkw/chip_wscg03_b32_k24.gtkw). (A scene's `waveforms` table also picks
    /// scopes and a cycle window.)
    #[arg(long, value_name = "DIR")]
    vcd: Option<PathBuf>,
    /// Print the scene's dataflow graph, pruned to what its outputs need, and what each
    /// unit will do; nothing is run. Units the outputs do not need are listed as skipped.
    #[arg(long)]
    explain: bool,
    /// Like --explain, as Graphviz DOT (skipped units dashed): `cchip run --dot | dot -Tsvg`.
    #[arg(long)]
    dot: bool,
    /// Run the scene on this chip instead of its [chip] preset (its own keys still override):
    /// date05 (DATE'05's k = 24 binary32 chip on its DDR2 memory, the port at full speed),
    /// wscg03 (WSCG'03's DDR SDRAM at 266 MHz, a 128-line triangle cache) or rtl (the RTL's
    /// reset values). --explain prints the values it resolves to.
    #[arg(long, value_enum)]
    preset: Option<Preset>,
    /// The chip's clock instead of the scene's [timing] technology or clock_mhz: osu018 (the
    /// configuration's slowest RTL unit measured on OSU 0.18 um cells, docs/figures/timing.csv;
    /// a scene's default), ecp5 (docs/figures/timing_ecp5.csv) or paper (the preset's clock,
    /// assumed: 800 or 266 MHz).
    #[arg(long, value_enum)]
    technology: Option<Technology>,
    /// Run the scene on this chip instead of its [chip] architecture: date05 (D_CNTR) or
    /// wscg03 (WSCG'03's Stack Engine and list traversal, its units in --explain).
    #[arg(long, value_enum)]
    architecture: Option<Architecture>,
}

#[derive(Args)]
struct AccuracyArgs {
    /// Meshes (files or built-in names), comma separated.
    #[arg(long, value_delimiter = ',', default_value = "bunny,teapot,dragon-11k")]
    meshes: Vec<String>,
    /// Number formats, comma separated (binary32, reduced, eEmF; DOP/T.CHECK such as
    /// e8m15/binary32 for a DOP datapath narrower than the triangle test's).
    #[arg(
        long,
        value_delimiter = ',',
        default_value = "binary32,reduced,e8m10,e8m15/binary32"
    )]
    formats: Vec<Formats>,
    /// k of the k-DOPs, comma separated (6, 14, 18, 24, 26).
    #[arg(long, value_delimiter = ',', default_value = "24")]
    k: Vec<usize>,
    /// Also write the plot of clocks against the uncertain share (and, with --area, against
    /// the cells; one point per configuration, the Pareto front marked) into this
    /// directory, as SVG and PNG with their data (CSV, JSON).
    #[arg(long, value_name = "DIR")]
    plot: Option<PathBuf>,
    /// Centre distances along x, from apart to deeply penetrating.
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        default_value = "2.2,1.6,1.2,0.8,0.4"
    )]
    distances: Vec<f64>,
    /// Seeded random orientations per distance.
    #[arg(long, default_value_t = 8)]
    orientations: usize,
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// The ideal memory's bus in bits (preset rtl's memory; refused with the DDR presets,
    /// whose buses are their own): a memory word takes ceil(its bits / N) clocks, so a
    /// narrower format costs fewer clocks (default: a word per clock whatever its width).
    #[arg(long, value_name = "N")]
    bus_bits: Option<u32>,
    /// Memory systems: the chip presets whose memory, port, caches and layout each
    /// configuration runs on (rtl: the RTL's reset port on a one-clock memory; date05, wscg03:
    /// the papers' DDR memories, the port at full speed; date05-treelets: date05 built for
    /// bandwidth), comma separated.
    #[arg(
        long,
        value_enum,
        value_delimiter = ',',
        default_value = "rtl,date05,wscg03"
    )]
    presets: Vec<Preset>,
    /// The clock period of each configuration: osu018 (its slowest RTL unit measured on OSU
    /// 0.18 um, docs/figures/timing.csv), ecp5 or paper (the preset's 800 / 266 MHz, assumed).
    #[arg(long, value_enum, default_value = "osu018")]
    technology: Technology,
    /// Run only the K-th of N shares of the (mesh, pose) items (1 <= K <= N) and print the
    /// share's sums as JSON, for --merge (a SLURM array job, GNU parallel: docs/guide/study.md).
    #[arg(long, value_name = "K/N", conflicts_with = "merge")]
    shard: Option<accuracy::Shard>,
    /// Combine the shards' JSON files (all N of one study) into the serial run's output:
    /// the study's own arguments are read from the files.
    #[arg(long, value_name = "FILES", num_args = 1..)]
    merge: Vec<PathBuf>,
    /// TRI_UNIT folded: the clocks between the pairs it takes, comma separated (1:
    /// unfolded; 2 to 32, even: one T.CHECK folded for half of it, docs/explanation/architecture.md
    /// "Folded TRI_UNIT"). Each runs with each --dop-intervals: what area costs in time.
    #[arg(long, value_delimiter = ',', default_value = "1")]
    tri_intervals: Vec<u32>,
    /// The DOP unit folded: the clocks between the node pairs it takes, comma separated
    /// (1: unfolded; ii dividing k: k / ii DOPTRF lanes in ii passes).
    #[arg(long, value_delimiter = ',', default_value = "1")]
    dop_intervals: Vec<u32>,
    /// How deep the FP units are cut, comma separated: asic (the standard cells' pipelines)
    /// or fpga (six stages each, T.CHECK's operands registered: more clocks on dependent
    /// paths, a shorter period on an FPGA). fpga needs folded TRI_UNITs (--tri-intervals 2 to
    /// 32). Each runs with each interval.
    #[arg(long, value_delimiter = ',', default_value = "asic")]
    depths: Vec<collision_chip::chip::rtl::Depth>,
    /// Stored DOP precision, comma separated: full, or bits a plane (1 to 16) of the codes a
    /// node record stores below an ancestor's DOP and the chip decodes outward (presets with
    /// the `records` layout: date05, date05-treelets, wscg03). Default: each preset's own
    /// (4 on date05-treelets, full on the others).
    #[arg(long, value_delimiter = ',')]
    dop_bits: Vec<DopBits>,
    /// Node records held per object on every preset: 1, the RTL chips' (each configuration
    /// then runs on a chip that is built, at its measured period); more, the cycle model's
    /// LRU cache of them, whose chip is not built (its period estimated); or `preset`, each
    /// preset's own (16 on date05 and wscg03, 64 on date05-treelets).
    #[arg(long, value_name = "N|preset", default_value = "1")]
    node_cache: accuracy::NodeCache,
    /// Yosys cells per unit (`unit,cells`, as scripts/area-study.sh writes
    /// docs/figures/area_cells.csv): adds each configuration's cells (DOP unit + TRI_UNIT,
    /// and with stored DOPs 2k decode stages) to the table and, with --plot, the plot of
    /// clocks against cells.
    #[arg(long, value_name = "FILE")]
    area: Option<PathBuf>,
    /// Print the rows as JSON instead of the table (with --area, each with its `cells`).
    #[arg(long)]
    json: bool,
}

#[derive(Args)]
struct QueryArgs {
    #[arg(help = MESH_HELP)]
    a: String,
    #[arg(help = MESH_HELP)]
    b: String,
    /// Pose of B in A's frame: rx,ry,rz,tx,ty,tz. x_A = Rz(rz) Ry(ry) Rx(rx) x_B + t,
    /// angles in degrees. Meshes are used unscaled unless --unit-cube.
    #[arg(long, allow_hyphen_values = true, value_parser = Pose::parse)]
    pose: Pose,
    #[arg(long, value_enum, default_value = "all")]
    mode: Mode,
    #[arg(long, value_enum, default_value = "lifo")]
    traversal: Traversal,
    #[command(flatten)]
    chip: ChipConfig,
    /// Scale each mesh uniformly into [-1,1]^3 first (the WSCG'03 benchmark protocol).
    #[arg(long)]
    unit_cube: bool,
    /// Also compute the exact answer (exact predicates on the f64 geometry) and count
    /// misses and extra pairs of the chip.
    #[arg(long)]
    oracle: bool,
    /// Print JSON: pairs, counters, uncertain (how many pairs the host settled) and
    /// uncertain_pairs, and with --oracle exact_pairs and accuracy.
    #[arg(long)]
    json: bool,
}

fn main() -> ExitCode {
    // Like other Unix tools, end quietly when the reader of the output goes away (`cchip |
    // head`): Rust ignores SIGPIPE, and `println!` then panics on the broken pipe.
    #[cfg(unix)]
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    let cli = Cli::parse();
    let res = collision_chip::measure::check_environment().and_then(|()| match cli.cmd {
        Some(Cmd::Query(q)) => query(q),
        Some(Cmd::Run { scene, opts }) => run(scene, opts),
        Some(Cmd::Accuracy(a)) => accuracy(a),
        Some(Cmd::Figures {
            out,
            quick,
            preset,
            technology,
        }) => figures(&out, quick, preset, technology),
        Some(Cmd::ExportVerilog { out, area: false }) => report_written(units::write_verilog(&out)),
        Some(Cmd::ExportVerilog { out, area: true }) => {
            report_written(units::write_area_verilog(&out))
        }
        Some(Cmd::Vectors { out }) => report_written(units::write_vectors(&out)),
        None => run(None, RunOpts::default()),
    });
    match res {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

fn load(spec: &str, unit_cube: bool) -> Result<Mesh, String> {
    let m = mesh::resolve(spec).map_err(|e| e.to_string())?;
    if unit_cube {
        m.scaled_into_unit_cube().map_err(|e| e.to_string())
    } else {
        Ok(m)
    }
}

fn query(q: QueryArgs) -> Result<(), String> {
    let cfg = q.chip;
    let (ma, mb) = mesh::pair(&q.a, &q.b, |spec| load(spec, q.unit_cube))?;
    let (ta, tb) = (ma.triangles_f64(), mb.triangles_f64());
    let chip = Chip::new(&ta, &tb, cfg)?;
    chip.check_pose(&q.pose)?;
    let res = chip.query(&q.pose, q.mode, q.traversal);
    let exact = q.oracle.then(|| exact_pairs(&ta, &tb, &q.pose));
    let acc = exact.as_ref().map(|x| Accuracy::of(q.mode, &res.pairs, x));
    if q.json {
        // Written straight to stdout: a tree of JSON values for millions of (uncertain) pairs
        // took tens of GB.
        let v = QueryJson {
            a: MeshJson {
                mesh: &q.a,
                triangles: ta.len(),
            },
            b: MeshJson {
                mesh: &q.b,
                triangles: tb.len(),
            },
            pose: q.pose,
            mode: q.mode,
            traversal: q.traversal,
            chip: cfg,
            pairs: &res.pairs,
            counters: res.counters,
            uncertain: res.uncertain.len(),
            uncertain_pairs: &res.uncertain,
            exact_pairs: exact.as_deref(),
            accuracy: acc,
        };
        let mut out = std::io::BufWriter::new(std::io::stdout().lock());
        serde_json::to_writer_pretty(&mut out, &v)
            .map_err(|e| format!("cannot write JSON: {e}"))?;
        return writeln!(out)
            .and_then(|()| out.flush())
            .map_err(|e| format!("cannot write JSON: {e}"));
    }
    println!(
        "A: {} ({} triangles, {} DOP nodes)",
        q.a,
        ta.len(),
        chip.a.tree.len()
    );
    println!(
        "B: {} ({} triangles, {} DOP nodes)",
        q.b,
        tb.len(),
        chip.b.tree.len()
    );
    println!(
        "chip: k={} format={} dop-rounding={}; {:?} traversal, {:?} pairs mode",
        cfg.k, cfg.format, cfg.dop_rounding, q.traversal, q.mode
    );
    let c = res.counters;
    println!(
        "intersecting pairs: {} ({} flagged uncertain by T.CHECK and settled by the host with the exact oracle)",
        res.pairs.len(),
        res.uncertain.len()
    );
    for p in res.pairs.iter().take(20) {
        println!("  A#{} x B#{}", p.0, p.1);
    }
    if res.pairs.len() > 20 {
        println!("  ... ({} more; --json lists all)", res.pairs.len() - 20);
    }
    println!(
        "DOP tests {} (overlapping {}), DOP transforms {}, triangle tests {}, node fetches {}, triangle fetches {}, memory {} bytes, max queue depth {}",
        c.dop_tests, c.dop_overlaps, c.dop_transforms, c.tri_tests, c.node_fetches, c.tri_fetches, c.memory_bytes, c.max_queue_depth
    );
    if let (Some(x), Some(a)) = (&exact, acc) {
        println!(
            "exact oracle: {} pairs; chip misses {} and reports {} extra",
            x.len(),
            a.misses,
            a.extras
        );
    }
    Ok(())
}

#[derive(Serialize)]
struct MeshJson<'a> {
    mesh: &'a str,
    triangles: usize,
}

/// `query --json`; `exact_pairs` and `accuracy` only with `--oracle`.
#[derive(Serialize)]
struct QueryJson<'a> {
    a: MeshJson<'a>,
    b: MeshJson<'a>,
    pose: Pose,
    mode: Mode,
    traversal: Traversal,
    chip: ChipConfig,
    pairs: &'a [(u32, u32)],
    counters: Counters,
    uncertain: usize,
    uncertain_pairs: &'a [(u32, u32)],
    #[serde(skip_serializing_if = "Option::is_none")]
    exact_pairs: Option<&'a [(u32, u32)]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    accuracy: Option<Accuracy>,
}

fn report_written(r: std::io::Result<Vec<String>>) -> Result<(), String> {
    let paths = r.map_err(|e| format!("cannot write: {e}"))?;
    for p in &paths {
        println!("wrote {p}");
    }
    Ok(())
}

fn progress_bar(len: u64, hidden: bool) -> ProgressBar {
    let bar = if hidden || !std::io::stderr().is_terminal() {
        ProgressBar::hidden()
    } else {
        ProgressBar::new(len)
    };
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} poses {elapsed} (eta {eta}) {msg}")
            .expect("valid template"),
    );
    bar
}

fn accuracy(a: AccuracyArgs) -> Result<(), String> {
    let area = a.area.as_deref().map(accuracy::Area::load).transpose()?;
    if let Some(dir) = &a.plot {
        plot::output_dir(dir)?;
    }
    let (plan, rows) = if a.merge.is_empty() {
        let plan = accuracy::Plan {
            meshes: a.meshes.clone(),
            presets: a.presets.clone(),
            ks: a.k.clone(),
            formats: a.formats.clone(),
            roundings: vec![DopRounding::Outward, DopRounding::NearestEven],
            sweep: Sweep {
                distances: a.distances.clone(),
                orientations: a.orientations,
                seed: a.seed,
            },
            bus_bits: a.bus_bits,
            technology: a.technology,
            folds: a
                .tri_intervals
                .iter()
                .flat_map(|&tri| a.dop_intervals.iter().map(move |&dop| (tri, dop)))
                .flat_map(|(tri, dop)| a.depths.iter().map(move |&depth| Folds { tri, dop, depth }))
                .collect(),
            dop_bits: a.dop_bits.clone(),
            node_cache: a.node_cache,
        };
        let shard = a.shard.unwrap_or(accuracy::Shard::ALL);
        let items = a
            .meshes
            .len()
            .saturating_mul(a.distances.len())
            .saturating_mul(a.orientations);
        let bar = progress_bar(items.div_ceil(shard.n) as u64, a.json || a.shard.is_some());
        let rows = accuracy::run(
            &plan,
            |m| Ok(load(m, true)?.triangles_f64()),
            shard,
            || bar.inc(1),
        )?;
        bar.finish_and_clear();
        if a.shard.is_some() {
            let file = accuracy::ShardFile { plan, shard, rows };
            println!(
                "{}",
                serde_json::to_string_pretty(&file).expect("serialisable")
            );
            return Ok(());
        }
        (plan, rows)
    } else {
        let files = a.merge.iter().map(|p| {
            let text = std::fs::read_to_string(p).map_err(|e| format!("{}: {e}", p.display()))?;
            accuracy::ShardFile::parse(&text, p)
        });
        accuracy::merge(files.collect::<Result<_, String>>()?)?
    };
    if let Some(dir) = &a.plot {
        for f in accuracy::figures(&rows, area.as_ref()) {
            for p in plot::write_figure(&f, dir)? {
                eprintln!("wrote {}", p.display());
            }
        }
    }
    if a.json {
        println!("{}", accuracy::json(&rows, area.as_ref()));
    } else {
        print!("{}", accuracy::table(&plan, &rows, area.as_ref())?);
        println!("\nhost us = the host's setup per pose and its settling of the uncertain pairs with the exact oracle, measured on this machine (wall clock, the fastest of {} runs, poses on every core: noisy); end to end = host + chip.\nclock periods (measured: the configuration's RTL chip's row; estimated: what stands in for it):\n{}", collision_chip::measure::TIMING_RUNS, accuracy::clocks(&rows));
    }
    Ok(())
}

fn figures(
    out: &std::path::Path,
    quick: bool,
    preset: Option<Preset>,
    technology: Technology,
) -> Result<(), String> {
    let plan = figures::Plan {
        preset,
        technology,
        ..if quick {
            figures::Plan::quick()
        } else {
            figures::Plan::full()
        }
    };
    let bar = progress_bar(0, false);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} {elapsed} (eta {eta}) {msg}")
            .expect("valid template"),
    );
    let t0 = std::time::Instant::now();
    let written = figures::generate(&plan, out, &bar)?;
    bar.finish_and_clear();
    for p in &written {
        println!("wrote {}", p.display());
    }
    println!("figures in {:.1} s", t0.elapsed().as_secs_f64());
    Ok(())
}

fn run(path: Option<PathBuf>, o: RunOpts) -> Result<(), String> {
    let flags = Flags {
        preset: o.preset,
        technology: o.technology,
        architecture: o.architecture,
        waveforms: o.vcd,
        cross_check: o.rtl.then_some(CrossCheck::Rtl),
    };
    let scene = match &path {
        Some(p) => Scene::load_with(p, flags)?,
        None => Scene::parse_with(DEFAULT_SCENE, "built-in default scene", flags)?,
    };
    if o.explain || o.dot {
        let plan = Plan::of(&scene);
        print!(
            "{}",
            if o.dot {
                plan.dot(&scene)
            } else {
                plan.explain(&scene)
            }
        );
        return Ok(());
    }
    let prepared = Prepared::new(&scene, |spec| load(spec, scene.objects.unit_cube))?;
    let (ta, tb) = (prepared.chip.geometry(0), prepared.chip.geometry(1));
    if !o.json {
        println!(
            "scene: {}\n  A = {} ({} triangles), B = {} ({} triangles){}\n  chip: k={} format={} dop-rounding={}; {} traversal, {} mode; {} poses{}",
            scene.name, scene.objects.a, ta.len(), scene.objects.b, tb.len(),
            if scene.objects.unit_cube { ", both scaled into [-1,1]^3" } else { "" },
            scene.cfg.k, scene.cfg.format, scene.cfg.dop_rounding, scene.traversal.name(), format!("{:?}", scene.mode).to_lowercase(), scene.poses.len(),
            scene.clock.as_ref().map_or(String::new(), |c| format!("\n  clock: {}", c.source()))
        );
    }
    let bar = progress_bar(scene.poses.len() as u64, o.json);
    let records = prepared.run(|| bar.inc(1))?.records;
    bar.finish_and_clear();
    if o.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&records).expect("serialisable")
        );
        return Ok(());
    }
    let out = &scene.outputs;
    print!("{}", summary_table(&records, out.cycles));
    if out.accuracy {
        println!("misses = exact pairs the chip did not report; extras = reported pairs that do not intersect.");
    }
    let memory = match scene.params.memory {
        Memory::Ideal(t) => {
            let bus = t
                .bus_bits
                .map(|b| format!(", a bus of {b} bits"))
                .unwrap_or_default();
            format!("memory latency {}, interval {}{bus}", t.latency, t.interval)
        }
        m => format!("memory {m}"),
    };
    if let (true, Some(clock)) = (out.cycles, &scene.clock) {
        let p = &scene.params;
        let how = match clock.source {
            PeriodSource::Measured => String::new(),
            how => format!(
                " (the period {}: so are chip_us, e2e_us, speedup and e2e_x)",
                how.name()
            ),
        };
        let model = match scene.architecture {
            Architecture::Wscg03 => "WSCG'03's chip clocked as its RTL".to_string(),
            Architecture::Date05 => format!("cycle model: {} queue entries", p.queue_entries),
        };
        println!(
            "cycles = the chip's clocks from start to done ({model}, {memory});\nchip_us = cycles x the clock period, {};\nsetup_us, settle_us = the host's setup for the pose and its settling of the uncertain pairs with the exact oracle, measured on this machine (wall clock, the fastest of {runs} runs, one pose at a time: noisy);\ne2e_us = setup_us + chip_us + settle_us; sw_us = the golden model's query on this machine (the fastest of {runs} runs, one pose at a time); speedup = sw_us / chip_us; e2e_x = sw_us / e2e_us{how}.",
            clock.source(), runs = collision_chip::measure::TIMING_RUNS
        );
        if records
            .iter()
            .any(|r| r.cycles.as_ref().is_some_and(|c| c.overflow))
        {
            println!("ovf = poses whose pair queue overflowed (listed below): the chip halted with an incomplete answer, so the cycle columns leave them out (-: every pose of the row overflowed) and their misses and extras are that answer's.");
        }
        if scene.architecture == Architecture::Wscg03 {
            println!("\nWSCG'03's chip: where its clocks went, each once: compare = an aligned bundle into the compare units, load = a tumbled bundle into the DOTADD units, memory = the Memory Controller's head ask waits for its record, transform = for its d' set, list = no ask (the Stack Engine between lists, waiting for flags), drain = the Triangle Unit finishes; dop/c, words/c = DOP tests, memory words per clock; lists = tau, alpha = aligned node pairs per list; clk/list against WSCG'03 Eq. 5's 100 + (alpha - 2) 10:");
            print!("{}", stack_table(&records));
        } else {
            println!("\nwhere the clocks went (share of clocks by what the DOP unit's input did; occupancy = mean units in flight):");
            print!("{}", stall_table(&records));
        }
    }
    if out.memory {
        println!("\n{memory}; busy = a request outstanding, waiting = the DOP unit's input waits for a node word:");
        print!("{}", memory_table(&records));
    }
    for (i, r) in records.iter().enumerate() {
        let Some(c) = &r.cycles else { continue };
        if let Some(v) = &c.vcd {
            let gtkw = scene.architecture.probes().gtkw;
            println!("pose {i}: VCD {v}  (gtkwave {v} {gtkw})");
        }
        if c.overflow {
            println!(
                "pose {i} ({}): the chip's pair queue overflowed ({} entries): its answer is incomplete; raise [timing] queue_entries",
                r.pose.text(), scene.params.queue_entries
            );
        }
    }
    if let Some(level) = records
        .iter()
        .find_map(|r| r.cycles.as_ref()?.cross_checked.as_ref())
    {
        println!("every pose ran on the {level} chip beside the cycle model: equal on every compared signal, every clock.");
    }
    Ok(())
}
