//! What each fuzz target does with one input: what `cchip` does with the same file, up to
//! the first query. An `Err` is a clear error and fine; a panic, an abort or a hang is the
//! bug. The afl program (`src/main.rs`) and the main crate's corpus replay
//! (`tb/fuzz_inputs.rs`, which includes this file) run these same functions.

use collision_chip::chip::config::ChipConfig;
use collision_chip::chip::preset::Preset;
use collision_chip::chip::reg::Mode;
use collision_chip::chip::timing::Technology;
use collision_chip::chip::wscg03::Architecture;
use collision_chip::mesh;
use collision_chip::pose::Pose;
use collision_chip::query::Chip;
use collision_chip::report::accuracy::{self, ShardFile};
use collision_chip::report::plot;
use collision_chip::scene::graph::Plan;
use collision_chip::scene::run::Prepared;
use collision_chip::scene::{CrossCheck, Flags, Scene};
use collision_chip::traversal::Traversal;
use std::path::{Path, PathBuf};

/// The targets, each a directory of `fuzz/corpus/` and `fuzz/regressions/`.
pub const TARGETS: &[&str] = &["mesh_obj", "mesh_stl", "mesh_ply", "scene", "merge"];

/// One input of `target` (one of [`TARGETS`]).
pub fn run(target: &str, bytes: &[u8]) -> Result<(), String> {
    match target {
        "scene" => scene(bytes),
        "merge" => merge(bytes),
        t => match t.strip_prefix("mesh_") {
            Some(ext) => mesh(ext, bytes),
            None => panic!("no fuzz target {t}: one of {TARGETS:?}"),
        },
    }
}

/// Inputs longer than this are skipped: the work a loader does grows with the file, and
/// afl learns more from many small files than from a few large ones.
pub const MAX_INPUT: usize = 64 * 1024;

/// Meshes of more triangles are loaded but not queried (a query of n triangles against
/// themselves costs up to n^2 triangle tests: slow, not wrong).
const MAX_QUERIED_TRIANGLES: usize = 2000;

/// `cchip query F F --pose 1,2,3,0.1,0,0` (and with `--unit-cube`) on `bytes` as the file
/// `case.EXT`: the loader by its extension, the chip's images, the pose's check, the query.
pub fn mesh(ext: &str, bytes: &[u8]) -> Result<(), String> {
    if bytes.len() > MAX_INPUT {
        return Ok(());
    }
    let m = mesh::parse(Path::new(&format!("case.{ext}")), bytes).map_err(|e| e.to_string())?;
    let unit = m.scaled_into_unit_cube().map_err(|e| e.to_string())?;
    if m.len() > MAX_QUERIED_TRIANGLES {
        return Ok(());
    }
    let pose = Pose::parse("1,2,3,0.1,0,0")?;
    for m in [m, unit] {
        let t = m.triangles_f64();
        let chip = Chip::new(&t, &t, ChipConfig::default())?;
        chip.check_pose(&pose)?;
        chip.query(&pose, Mode::All, Traversal::Lifo);
    }
    Ok(())
}

/// `cchip run SCENE --explain` and `--dot` on `bytes` as a scene file, with each of the
/// command line's flags in turn (the scene's own keys; each preset; each architecture and
/// technology; `--rtl`; `--vcd`): the parse and every check before a run, the plan. Then,
/// for the scene as written, `cchip run SCENE` on its first pose with small stand-in
/// objects, no files written and no cross-check: its chip, memory and timing as the scene
/// sets them, on a query that takes milliseconds.
pub fn scene(bytes: &[u8]) -> Result<(), String> {
    if bytes.len() > MAX_INPUT {
        return Ok(());
    }
    // `cchip run` reads the file as UTF-8 text.
    let text = std::str::from_utf8(bytes).map_err(|e| e.to_string())?;
    let mut scenes = flag_sets()
        .into_iter()
        .map(|flags| {
            let s = Scene::parse_with(text, "case.toml", flags)?;
            let plan = Plan::of(&s);
            plan.explain(&s);
            plan.dot(&s);
            s.configuration();
            Ok(s)
        })
        .collect::<Vec<Result<Scene, String>>>();
    let mut s = scenes.swap_remove(0)?;
    s.poses.truncate(1);
    s.outputs.waveforms = None;
    s.outputs.cross_check = None;
    let stand_in = |_: &str| mesh::builtin(STAND_IN).map_err(|e| e.to_string());
    Prepared::new(&s, stand_in)?.run(|| {})?;
    Ok(())
}

/// `cchip accuracy --merge F1 F2 ... --plot DIR` on `bytes` cut at each NUL byte into the
/// files (a shard's JSON has none): each read as `--merge` reads it, the shards merged, then
/// the table, its footnote and each figure's data and SVG (into the temporary directory).
pub fn merge(bytes: &[u8]) -> Result<(), String> {
    if bytes.len() > MAX_INPUT {
        return Ok(());
    }
    let files = bytes
        .split(|&b| b == 0)
        .enumerate()
        .map(|(i, b)| {
            let path = PathBuf::from(format!("shard{i}.json"));
            // `--merge` reads each file as UTF-8 text
            let text = std::str::from_utf8(b).map_err(|e| format!("{}: {e}", path.display()))?;
            ShardFile::parse(text, &path)
        })
        .collect::<Result<Vec<_>, String>>()?;
    let (plan, rows) = accuracy::merge(files)?;
    accuracy::table(&plan, &rows, None)?;
    accuracy::clocks(&rows);
    let svg = std::env::temp_dir().join(format!("cchip-fuzz-merge-{}.svg", std::process::id()));
    let drawn = accuracy::figures(&rows, None).iter().try_for_each(|f| {
        f.table.csv();
        f.table.json();
        plot::draw(f, &svg)
    });
    let _ = std::fs::remove_file(&svg);
    drawn
}

/// The objects of a scene's run: a sphere of at least 80 triangles.
const STAND_IN: &str = "sphere:80";

fn flag_sets() -> Vec<Flags> {
    use clap::ValueEnum;
    let mut sets = vec![Flags::default()];
    sets.extend(Preset::value_variants().iter().map(|&p| Flags {
        preset: Some(p),
        ..Flags::default()
    }));
    sets.extend(Architecture::value_variants().iter().map(|&a| Flags {
        architecture: Some(a),
        ..Flags::default()
    }));
    sets.extend(Technology::value_variants().iter().map(|&t| Flags {
        technology: Some(t),
        ..Flags::default()
    }));
    sets.push(Flags {
        cross_check: Some(CrossCheck::Rtl),
        ..Flags::default()
    });
    sets.push(Flags {
        waveforms: Some("vcd".into()),
        ..Flags::default()
    });
    sets
}
