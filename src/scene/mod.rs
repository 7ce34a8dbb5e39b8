//! Scenes: two objects, one pose or a pose sweep, the query, the chip configuration and
//! the outputs wanted (TOML). Every key, with its default and range: the user guide's
//! "Scene keys" (docs/reference/scene-keys.md).

pub mod graph;
mod keys;
pub mod record;
pub mod run;

use crate::chip::config::{ChipConfig, DopBits, MemLayout};
use crate::chip::memory::{Ddr, MemTiming, Memory};
use crate::chip::params::Params;
use crate::chip::preset::Preset;
use crate::chip::reg::Mode;
use crate::chip::timing::{Clock, Folds, Technology};
use crate::chip::wscg03::{Architecture, StackParams};
use crate::pose::{sweep_poses, Pose, ScenePose, Sweep};
use crate::traversal::Traversal;
use serde::Deserialize;
use std::path::Path;

/// The built-in default scene (`cchip run` without a file).
pub const DEFAULT_SCENE: &str = include_str!("../../vectors/scenes/default.toml");

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    objects: Objects,
    /// A [`Preset`] and [`ChipConfig`]'s keys over it, read in two steps ([`chip`]).
    chip: Option<Keys>,
    #[serde(default)]
    query: QuerySection,
    #[serde(default)]
    pose: Vec<Pose>,
    sweep: Option<Sweep>,
    #[serde(default)]
    outputs: OutputsSection,
    #[serde(default)]
    memory: MemorySection,
    /// [`Params`], `technology` and `clock_mhz`, read in two steps ([`timing`]).
    timing: Option<Keys>,
    #[serde(default)]
    stack_engine: StackParams,
}

/// A section's keys, each with its place in the file.
type Keys = std::collections::BTreeMap<String, toml::Spanned<toml::Value>>;

fn line_of(text: &str, at: usize) -> usize {
    text[..at.min(text.len())].matches('\n').count() + 1
}

/// `value`'s keys with the scene's `keys` over them, as a `T` (a preset's values overridden,
/// `drop` left out). An error names the line of the first key that makes it fail.
fn over<T: serde::Serialize + serde::de::DeserializeOwned>(
    value: &T,
    keys: Keys,
    text: &str,
    section: &str,
    drop: &[&str],
) -> Result<T, String> {
    let mut table = toml::Table::try_from(value).map_err(|e| e.to_string())?;
    for d in drop {
        table.remove(*d);
    }
    let mut keys: Vec<(String, toml::Spanned<toml::Value>)> = keys.into_iter().collect();
    keys.sort_by_key(|(_, v)| v.span().start);
    let mut t = T::deserialize(table.clone()).map_err(|e| e.message().to_string())?;
    for (k, v) in keys {
        let line = line_of(text, v.span().start);
        table.insert(k, v.into_inner());
        t = T::deserialize(table.clone())
            .map_err(|e| format!("{line}: {section}: {}", e.message()))?;
    }
    Ok(t)
}

/// `[chip] key = "name"` taken out of `keys` as a `T`; an unknown name is an error naming
/// its line and the `known` ones.
fn named_key<T: serde::de::DeserializeOwned>(
    keys: &mut Keys,
    key: &str,
    text: &str,
    known: &str,
) -> Result<Option<T>, String> {
    keys.remove(key)
        .map(|v| {
            let line = line_of(text, v.span().start);
            let v = v.into_inner();
            T::deserialize(v.clone())
                .map_err(|_| format!("{line}: [chip] {key} {v} is not known: use {known}"))
        })
        .transpose()
}

/// `[chip]`: the preset (the scene's, or `flags`' over it; none: [`Preset::Rtl`], the RTL's
/// reset point), the architecture (`flags`', else the scene's, else the preset's) and
/// [`ChipConfig`]'s keys over its chip. WSCG'03's chip reads the `words` layout and holds no
/// node records, whatever the preset's (the golden model's counters then count what it
/// reads).
fn chip(
    keys: Option<Keys>,
    text: &str,
    flags: Flags,
) -> Result<(Preset, Architecture, ChipConfig), String> {
    let mut keys = keys.unwrap_or_default();
    let arch: Option<Architecture> =
        named_key(&mut keys, "architecture", text, "\"date05\" or \"wscg03\"")?;
    let named: Option<Preset> = named_key(
        &mut keys,
        "preset",
        text,
        "\"date05\", \"wscg03\" or \"rtl\"",
    )?;
    let preset = flags.preset.or(named).unwrap_or(Preset::Rtl);
    let arch = flags.architecture.or(arch).unwrap_or(preset.architecture());
    let mut cfg = over(&preset.chip(), keys, text, "[chip]", &[])?;
    if arch == Architecture::Wscg03 {
        (cfg.layout, cfg.node_cache, cfg.dop_bits) = (MemLayout::Words, 1, DopBits::Full);
    }
    Ok((preset, arch, cfg))
}

/// `[timing]`: the chip's [`Params`] (each key optional, the preset's by default; the memory
/// is `[memory]`'s), and the clock's `technology` or an assumed `clock_mhz`.
fn timing(
    keys: Option<Keys>,
    text: &str,
    preset: Preset,
) -> Result<(Params, Option<Technology>, Option<f64>), String> {
    let mut keys = keys.unwrap_or_default();
    let clock_mhz = match keys.remove("clock_mhz") {
        None => None,
        Some(v) => match v.get_ref() {
            toml::Value::Float(x) => Some(*x),
            toml::Value::Integer(i) => Some(*i as f64),
            other => {
                return Err(format!(
                    "{}: [timing] clock_mhz must be a number of MHz, not {other}",
                    line_of(text, v.span().start)
                ))
            }
        },
    };
    let technology = match keys.remove("technology") {
        None => None,
        Some(v) => {
            let line = line_of(text, v.span().start);
            let v = v.into_inner();
            Some(Technology::deserialize(v.clone()).map_err(|_| format!("{line}: [timing] technology {v} is not known: use \"osu018\", \"ecp5\" or \"paper\""))?)
        }
    };
    // the memory is [memory]'s; the clock the preset's until the scene's is known ([`clock`])
    let params = over(
        &preset.params(),
        keys,
        text,
        "[timing]",
        &["memory", "clock_ps"],
    )?;
    Ok((
        Params {
            clock_ps: preset.clock_ps(),
            ..params
        },
        technology,
        clock_mhz,
    ))
}

/// Assumed clocks, in MHz, from 1 kHz to 100 GHz: a chip's time at any other is no number
/// a report can print (1e-307 MHz: an infinite period).
const CLOCK_MHZ: std::ops::RangeInclusive<f64> = 1e-3..=1e5;

/// The clock: an assumed `clock_mhz`, else `technology`'s period for the configuration
/// (default: measured on OSU 0.18 um; estimated for WSCG'03's chip, which has no RTL).
fn clock(
    cfg: &ChipConfig,
    folds: Folds,
    preset: Preset,
    arch: Architecture,
    technology: Option<Technology>,
    clock_mhz: Option<f64>,
) -> Result<Clock, String> {
    match (clock_mhz, technology) {
        (Some(_), Some(_)) => Err("[timing] give clock_mhz (an assumed clock) or technology (a period from a timing table, or the paper's), not both".into()),
        (Some(mhz), None) if !CLOCK_MHZ.contains(&mhz) => {
            Err(format!("[timing] clock_mhz must be from {} to {} MHz, not {mhz:?}", CLOCK_MHZ.start(), CLOCK_MHZ.end()))
        }
        (Some(mhz), None) => Ok(Clock::assumed(mhz, format!("the scene's clock_mhz = {mhz}, assumed"))),
        (None, t) => Ok(Clock::of(t.unwrap_or_default(), cfg, folds, preset)?.for_architecture(arch)),
    }
}

/// `[memory]`: the ideal model (`latency`, `interval`, `bus_bits`; the default, 1, 1 and a
/// word per clock) or
/// `model = "ddr"` with a `preset` (`wscg03`, `date05`) and any of its parameters overridden.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct MemorySection {
    model: Option<String>,
    preset: Option<String>,
    latency: Option<u32>,
    interval: Option<u32>,
    banks: Option<u32>,
    page_bytes: Option<u32>,
    bus_bits: Option<u32>,
    burst: Option<u32>,
    beat_ns: Option<f64>,
    hit_ns: Option<f64>,
    miss_ns: Option<f64>,
    /// In clocks once; refused with what to write instead.
    hit: Option<toml::Value>,
    miss: Option<toml::Value>,
}

/// A DDR time of the scene in ns, in picoseconds: from 1 ps to 1 ms, to the picosecond.
fn ddr_ps(key: &str, ns: f64) -> Result<u32, String> {
    let ps = ns * 1000.0;
    if !(1.0..=1e9).contains(&ps) || (ps - ps.round()).abs() > 1e-6 * ps {
        return Err(format!(
            "[memory] {key} = {ns} must be from 0.001 to 1000000 ns, to the picosecond"
        ));
    }
    Ok(crate::chip::memory::ps(ns) as u32)
}

impl MemorySection {
    /// The memory: this section's keys over `preset`'s (the chip preset's memory; its DDR
    /// values under `model = "ddr"` too). Keys of the other model are refused before
    /// ([`keys::Written::unused`]).
    fn memory(&self, preset: Memory) -> Result<Memory, String> {
        let (preset_model, preset_ideal, preset_ddr) = match preset {
            Memory::Ideal(t) => ("ideal", t, None),
            Memory::Ddr(d) => ("ddr", MemTiming::default(), Some(d)),
        };
        match self.model.as_deref().unwrap_or(preset_model) {
            "ideal" => {
                let d = preset_ideal;
                Ok(Memory::Ideal(MemTiming {
                    latency: self.latency.unwrap_or(d.latency),
                    interval: self.interval.unwrap_or(d.interval),
                    bus_bits: self.bus_bits.or(d.bus_bits),
                }))
            }
            "ddr" => {
                if let Some(k) = [("hit", &self.hit), ("miss", &self.miss)]
                    .iter()
                    .find_map(|(k, v)| v.as_ref().map(|_| k))
                {
                    return Err(format!("[memory] {k} is a number of clocks, which depend on the chip's clock: write {k}_ns, the memory's time in ns (the models count it in the chip's clocks at its period)"));
                }
                let base = (self.preset.as_deref())
                    .map(|p| Ddr::preset(p).ok_or_else(|| format!("[memory] preset \"{p}\" is not known: use \"wscg03\" or \"date05\"")))
                    .transpose()?
                    .or(preset_ddr);
                let ns = |k: &str, v: Option<f64>| v.map(|x| ddr_ps(k, x)).transpose();
                // each parameter: the scene's, else the preset's
                let get = |key: &str, own: Option<u32>, preset: fn(&Ddr) -> u32| {
                    own.or(base.as_ref().map(preset)).ok_or_else(|| {
                        format!("[memory] model = \"ddr\" needs a preset (\"wscg03\", \"date05\") or all of banks, page_bytes, bus_bits, burst, beat_ns, hit_ns, miss_ns ({key} is missing)")
                    })
                };
                Ok(Memory::Ddr(Ddr {
                    banks: get("banks", self.banks, |d| d.banks)?,
                    page_bytes: get("page_bytes", self.page_bytes, |d| d.page_bytes)?,
                    bus_bits: get("bus_bits", self.bus_bits, |d| d.bus_bits)?,
                    burst: get("burst", self.burst, |d| d.burst)?,
                    beat_ps: get("beat_ns", ns("beat_ns", self.beat_ns)?, |d| d.beat_ps)?,
                    hit_ps: get("hit_ns", ns("hit_ns", self.hit_ns)?, |d| d.hit_ps)?,
                    miss_ps: get("miss_ns", ns("miss_ns", self.miss_ns)?, |d| d.miss_ps)?,
                }))
            }
            m => Err(format!(
                "[memory] model \"{m}\" is not known: use \"ideal\" or \"ddr\""
            )),
        }
    }
}

/// The level a scene cross-checks the cycle model against.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum CrossCheck {
    /// The rust-hdl chip, in lockstep.
    Rtl,
    /// The exported Verilog under Verilator, every port every clock.
    Verilog,
}

impl std::fmt::Display for CrossCheck {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str(match self {
            CrossCheck::Rtl => "rust-hdl",
            CrossCheck::Verilog => "Verilog (Verilator)",
        })
    }
}

/// Which traversal VCDs a scene writes: one per pose into `dir`, the [`crate::chip::probes::PROBES`]
/// of `scopes` (all if empty) in cycles `window` (the scene's `cycles = [first, last]`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Waveforms {
    pub dir: std::path::PathBuf,
    pub scopes: Vec<String>,
    pub window: std::ops::Range<u64>,
}

impl Waveforms {
    /// Every scope, every cycle.
    pub fn all(dir: std::path::PathBuf) -> Self {
        Waveforms {
            dir,
            scopes: vec![],
            window: 0..u64::MAX,
        }
    }

    /// From the scene's `waveforms`: a directory, or a table `{ dir, scopes, cycles }`.
    fn of(v: toml::Value) -> Result<Self, String> {
        const FORM: &str = "give a directory (waveforms = \"DIR\") or a table (waveforms = { dir = \"DIR\", scopes = [\"d_cntr\", ...], cycles = [first, last] })";
        let bad = |what: &str| format!("[outputs] waveforms: {what}; {FORM}");
        let (dir, scopes, cycles) = match v {
            toml::Value::String(d) => (d, None, None),
            toml::Value::Table(mut t) => {
                let dir = match t.remove("dir") {
                    Some(toml::Value::String(d)) => d,
                    _ => return Err(bad("no dir")),
                };
                let scopes = match t.remove("scopes") {
                    None => None,
                    Some(toml::Value::Array(a)) => Some(
                        a.into_iter()
                            .map(|x| x.as_str().map(str::to_string))
                            .collect::<Option<Vec<_>>>()
                            .ok_or_else(|| bad("scopes must be names"))?,
                    ),
                    Some(_) => return Err(bad("scopes must be a list of names")),
                };
                let cycles = match t.remove("cycles") {
                    None => None,
                    Some(toml::Value::Array(a)) => match a
                        .iter()
                        .map(|x| x.as_integer().and_then(|i| u64::try_from(i).ok()))
                        .collect::<Option<Vec<_>>>()
                        .as_deref()
                    {
                        Some(&[a, b]) => Some([a, b]),
                        _ => return Err(bad("cycles must be [first, last], two cycle numbers")),
                    },
                    Some(_) => return Err(bad("cycles must be [first, last]")),
                };
                if let Some(k) = t.keys().next() {
                    return Err(bad(&format!("unknown key {k:?}")));
                }
                (dir, scopes, cycles)
            }
            _ => return Err(bad("neither a directory nor a table")),
        };
        let dir = std::path::PathBuf::from(dir);
        let known = crate::chip::probes::probe_scopes();
        let scopes = scopes.unwrap_or_default();
        if let Some(s) = scopes.iter().find(|s| !known.contains(&s.as_str())) {
            return Err(format!(
                "[outputs] waveforms: no scope {s:?}; the scopes are {}",
                known.join(", ")
            ));
        }
        let window = match cycles {
            None => 0..u64::MAX,
            Some([a, b]) if a <= b => a..b.saturating_add(1),
            Some([a, b]) => return Err(format!("[outputs] waveforms: cycles = [{a}, {b}] is empty; give [first, last] with first <= last")),
        };
        Ok(Waveforms {
            dir,
            scopes,
            window,
        })
    }

    pub fn scopes_text(&self) -> String {
        if self.scopes.is_empty() {
            "every scope".into()
        } else {
            format!("scopes {}", self.scopes.join(", "))
        }
    }

    pub fn window_text(&self) -> String {
        match (self.window.start, self.window.end) {
            (0, u64::MAX) => "every cycle".into(),
            (a, u64::MAX) => format!("cycles {a} on"),
            (a, b) => format!("cycles {a} to {}", b - 1),
        }
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Objects {
    pub a: String,
    pub b: String,
    #[serde(default)]
    pub unit_cube: bool,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct QuerySection {
    mode: Option<Mode>,
    traversal: Option<Traversal>,
}

#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct OutputsSection {
    #[serde(default)]
    pairs: bool,
    #[serde(default)]
    accuracy: bool,
    #[serde(default)]
    cycles: bool,
    #[serde(default)]
    memory: bool,
    #[serde(default)]
    waveforms: Option<toml::Value>,
    #[serde(default)]
    cross_check: Option<CrossCheck>,
}

/// The outputs a scene asks for; each names a sink of [`graph::Plan`], and only what they
/// need runs.
#[derive(Debug, Clone, Default)]
pub struct Outputs {
    /// List every pose's pairs (the summary table is always printed).
    pub pairs: bool,
    /// The exact oracle: misses and extra pairs.
    pub accuracy: bool,
    /// Every pose on the cycle model: clocks, stalls, time at the clock.
    pub cycles: bool,
    /// The memory model's traffic on the cycle model.
    pub memory: bool,
    /// Traversal VCDs from the cycle model.
    pub waveforms: Option<Waveforms>,
    /// Also every pose at this level, checked against the cycle model clock by clock.
    pub cross_check: Option<CrossCheck>,
}

impl Outputs {
    /// Whether an output runs the cycle model (the chip's units are among the ancestors of
    /// its sink in [`graph::Plan`]; a test keeps the two in step).
    pub fn run_chip(&self) -> bool {
        self.cycles || self.memory || self.waveforms.is_some() || self.cross_check.is_some()
    }
}

/// TRI_UNIT's timing in the configuration line: its latency, and its interval if folded.
fn tri_timing(p: &Params) -> String {
    match p.tri_interval {
        1 => format!("tri_latency {}", p.tri_latency),
        ii => format!("tri_interval {ii} (folded TRI_UNIT, its schedule's latency)"),
    }
}

/// The DOP unit's timing in the configuration line: its latency, and its interval if folded.
fn dop_timing(p: &Params) -> String {
    match p.dop_interval {
        1 => format!("dop_latency {}", p.dop_latency),
        ii => format!(
            "dop_interval {ii} (folded DOP unit, latency {})",
            p.dop_unit_latency()
        ),
    }
}

/// A validated scene.
#[derive(Debug)]
pub struct Scene {
    pub name: String,
    pub objects: Objects,
    /// The configuration the scene's keys override.
    pub preset: Preset,
    /// The chip the cycle model runs, and WSCG'03's timing.
    pub architecture: Architecture,
    pub stack: StackParams,
    pub cfg: ChipConfig,
    pub mode: Mode,
    pub traversal: Traversal,
    pub poses: Vec<ScenePose>,
    pub outputs: Outputs,
    /// The cycle model's microarchitecture and memory model.
    pub params: Params,
    /// The chip's clock, for its time per query, and where it came from: only where an
    /// output runs the cycle model ([`Outputs::run_chip`]).
    pub clock: Option<Clock>,
}

/// What the command line puts over a scene's own keys (`cchip run --preset --technology
/// --architecture --vcd --rtl`), read with them: a scene is refused for the same reasons
/// whichever way it is given.
#[derive(Clone, Debug, Default)]
pub struct Flags {
    pub preset: Option<Preset>,
    pub technology: Option<Technology>,
    pub architecture: Option<Architecture>,
    /// A traversal VCD per pose into this directory (every scope, every cycle).
    pub waveforms: Option<std::path::PathBuf>,
    pub cross_check: Option<CrossCheck>,
}

impl Scene {
    /// The configuration the scene resolved to: its preset and every value it runs with
    /// (WSCG'03's chip: its own units' timing; without an output that runs the chip, no
    /// clock).
    pub fn configuration(&self) -> String {
        let (c, p, w) = (&self.cfg, &self.params, &self.stack);
        let (timing, memory_side) = match self.architecture {
            Architecture::Date05 => (
                format!(
                    "timing: queue_entries {}, {}, {}, tri_fifo {}, issue_spacing {}, credit {}, outstanding {}, prefetch {}",
                    p.queue_entries, dop_timing(p), tri_timing(p), p.tri_fifo, p.issue_spacing, p.credit, p.outstanding, p.prefetch
                ),
                format!("layout {}, node_cache {}", c.layout, c.node_cache),
            ),
            Architecture::Wscg03 => (
                format!(
                    "stack_engine: sram_latency {}, dotadd_stages {}, data_bus_bits {}, compare_latency {}, word_buffer {}, tri_interval {}, tri_latency {}",
                    w.sram_latency, w.dotadd_stages, w.data_bus_bits, w.compare_latency, w.word_buffer, w.tri_interval, w.tri_latency
                ),
                "layout words (a node word per request, no node records held)".to_string(),
            ),
        };
        let clock = self.clock.as_ref().map_or(
            "none (no output runs the cycle model)".to_string(),
            Clock::source,
        );
        format!(
            "configuration (preset {} and the scene's keys):\n  architecture: {}\n  chip: k = {}, format {}, dop_rounding {}, tri_rounding {:?}, tri_cache {}, {memory_side}\n  {timing}\n  memory: {}\n  clock: {clock}",
            self.preset.name(), self.architecture.name(), c.k, c.format, c.dop_rounding, c.tri_rounding, c.tri_cache, self.clock.as_ref().map_or(p.memory.to_string(), |_| p.memory.describe_at(p.clock_ps))
        )
    }

    /// Reads a scene file; its mesh paths are taken relative to its directory (a spec stays a
    /// built-in name only if it is one and no such file is there).
    pub fn load(path: &Path) -> Result<Scene, String> {
        Scene::load_with(path, Flags::default())
    }

    /// [`load`](Self::load) with the command line's `flags` over the scene's own keys.
    pub fn load_with(path: &Path, flags: Flags) -> Result<Scene, String> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("{}: cannot read scene: {e}", path.display()))?;
        let mut scene = Scene::parse_with(&text, &path.display().to_string(), flags)?;
        let dir = path.parent().unwrap_or(Path::new(""));
        for spec in [&mut scene.objects.a, &mut scene.objects.b] {
            let local = dir.join(&*spec);
            if local.exists() || !crate::mesh::is_builtin_name(spec) {
                *spec = local.display().to_string();
            }
        }
        Ok(scene)
    }

    /// `name` is used in error messages (the file name).
    pub fn parse(text: &str, name: &str) -> Result<Scene, String> {
        Scene::parse_with(text, name, Flags::default())
    }

    /// [`parse`](Self::parse) with the command line's `flags` over the scene's own keys.
    /// Every key the configuration does not use, and every output it cannot give, is
    /// refused here (`keys`), before anything is built.
    pub fn parse_with(text: &str, name: &str, flags: Flags) -> Result<Scene, String> {
        let f: File = toml::from_str(text).map_err(|e| toml_error(text, name, &e))?;
        let written: keys::Written =
            toml::from_str(text).map_err(|e| toml_error(text, name, &e))?;
        let err = |m: String| format!("{name}: {m}");
        let at_line = |m: String| format!("{name}:{m}");
        let (preset, architecture, cfg) = chip(f.chip, text, flags.clone()).map_err(at_line)?;
        let outputs = Outputs {
            pairs: f.outputs.pairs,
            accuracy: f.outputs.accuracy,
            cycles: f.outputs.cycles,
            memory: f.outputs.memory,
            waveforms: match flags.waveforms {
                Some(dir) => Some(Waveforms::all(dir)),
                None => f
                    .outputs
                    .waveforms
                    .map(Waveforms::of)
                    .transpose()
                    .map_err(err)?,
            },
            cross_check: flags.cross_check.or(f.outputs.cross_check),
        };
        let (mut params, technology, clock_mhz) =
            timing(f.timing, text, preset).map_err(at_line)?;
        let memory = f.memory.memory(preset.params().memory);
        let ddr = f
            .memory
            .model
            .as_deref()
            .map_or(matches!(preset.params().memory, Memory::Ddr(_)), |m| {
                m == "ddr"
            });
        let uses = keys::Uses {
            architecture,
            chip_runs: outputs.run_chip(),
            dop_interval: params.dop_interval,
            tri_interval: params.tri_interval,
            ddr,
        };
        written.unused(text, &uses).map_err(at_line)?;
        params.memory = memory.map_err(err)?;
        f.stack_engine.check().map_err(err)?;
        cfg.check().map_err(|e| {
            // the key the error is about, where the scene wrote it (else the preset's)
            let line = ["k", "format", "tri_cache", "node_cache", "dop_bits"]
                .into_iter()
                .filter(|k| e.starts_with(&format!("{k} ")))
                .find_map(|k| written.line(text, "chip", k));
            match line {
                Some(l) => at_line(format!("{l}: [chip] {e}")),
                None => err(format!("[chip] {e}")),
            }
        })?;
        let poses = match (&f.sweep, f.pose.is_empty()) {
            (Some(_), false) => {
                return Err(err(
                    "give either [[pose]] entries or a [sweep], not both".into()
                ))
            }
            (None, true) => {
                return Err(err(
                    "no pose: add a [[pose]] (rot_deg, t) or a [sweep]".into()
                ))
            }
            (None, false) => f
                .pose
                .iter()
                .map(|&pose| ScenePose {
                    pose,
                    distance: None,
                })
                .collect(),
            (Some(s), true) => sweep_poses(s).map_err(err)?,
        };
        if let Some(p) = poses.iter().find(|p| {
            !p.pose
                .rot_deg
                .iter()
                .chain(&p.pose.t)
                .all(|x| x.is_finite())
        }) {
            return Err(err(format!(
                "pose {} has a non-finite number",
                p.pose.text()
            )));
        }
        params
            .check()
            .map_err(|e| err(format!("[timing] / [memory]: {e}")))?;
        params
            .check_dop_interval(cfg.k)
            .map_err(|e| err(format!("[timing] {e}")))?;
        // the command line's technology replaces the scene's clock
        let (technology, clock_mhz) = if flags.technology.is_some() {
            (flags.technology, None)
        } else {
            (technology, clock_mhz)
        };
        let folds = Folds {
            tri: params.tri_interval,
            dop: params.dop_interval,
        };
        let clock = outputs
            .run_chip()
            .then(|| clock(&cfg, folds, preset, architecture, technology, clock_mhz))
            .transpose()
            .map_err(err)?;
        // the memory's nanoseconds in the clocks of the chip's own period
        if let Some(c) = &clock {
            params.clock_ps = c.ps();
            params
                .check()
                .map_err(|e| err(format!("[memory] at the chip's clock: {e}")))?;
        }
        let scene = Scene {
            name: name.to_string(),
            objects: f.objects,
            preset,
            architecture,
            stack: f.stack_engine,
            cfg,
            mode: f.query.mode.unwrap_or(Mode::All),
            traversal: f.query.traversal.unwrap_or(Traversal::Lifo),
            poses,
            outputs,
            params,
            clock,
        };
        keys::runnable(&scene, &written, text).map_err(at_line)?;
        Ok(scene)
    }
}

/// A TOML error with its file and line; a table header (`[pose]`) where the key takes a
/// list of tables gets what to write instead (serde's own words, "invalid type: map,
/// expected a sequence", do not say it).
fn toml_error(text: &str, name: &str, e: &toml::de::Error) -> String {
    let Some(span) = e.span() else {
        return format!("{name}: {}", e.message());
    };
    let line = line_of(text, span.start);
    let header = text[span.start..]
        .lines()
        .next()
        .unwrap_or("")
        .split('#')
        .next()
        .unwrap_or("")
        .trim();
    let key = header
        .strip_prefix('[')
        .and_then(|h| h.strip_suffix(']'))
        .filter(|k| !k.starts_with('['));
    match key.filter(|_| e.message().contains("expected a sequence")) {
        Some(k) => format!("{name}:{line}: [{k}] is one table, and {k} takes a list of them: write [[{k}]], one per entry"),
        None => format!("{name}:{line}: {}", e.message()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_scene_parses() {
        let s = Scene::parse(DEFAULT_SCENE, "default").unwrap();
        assert!(s.outputs.accuracy);
        assert!(!s.poses.is_empty());
    }

    /// Every scene shipped in vectors/scenes/ loads (meshes not read).
    #[test]
    fn shipped_scenes_parse() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/scenes");
        for e in std::fs::read_dir(&dir).unwrap() {
            let p = e.unwrap().path();
            Scene::load(&p).unwrap_or_else(|e| panic!("{e}"));
        }
    }

    #[test]
    fn errors_name_the_line() {
        let text = "[objects]\na = \"bunny\"\nb = \"bunny\"\n[chip]\nk = \"x\"\n";
        let e = Scene::parse(text, "s.toml").unwrap_err();
        assert!(e.starts_with("s.toml:5:"), "{e}");
        let e = Scene::parse("[objects]\na = \"x\"\nb = \"y\"\n[chip]\nk = 8\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n", "s.toml").unwrap_err();
        assert!(e.contains("6, 14, 18, 24, 26"), "{e}");
        let e = Scene::parse("[objects]\na = \"x\"\nb = \"y\"\n", "s.toml").unwrap_err();
        assert!(e.contains("no pose"), "{e}");
        let e = Scene::parse("[objects]\na = \"x\"\nb = \"y\"\nbogus = 1\n", "s.toml").unwrap_err();
        assert!(e.starts_with("s.toml:4:"), "{e}");
        // one [pose] table where the key takes a list
        let e = Scene::parse(
            "[objects]\na = \"x\"\nb = \"y\"\n[pose] # one\nrot_deg = [0, 0, 0]\nt = [0, 0, 0]\n",
            "s.toml",
        )
        .unwrap_err();
        assert!(
            e.starts_with("s.toml:4:") && e.contains("write [[pose]]"),
            "{e}"
        );
    }

    #[test]
    fn cycle_outputs_timing_and_memory() {
        use crate::chip::memory::MemTiming;
        use crate::chip::params::Params;
        let base = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n";
        let s = Scene::parse(
            &format!("{base}[outputs]\nwaveforms = \"w\"\n[memory]\nlatency = 3\ninterval = 2\n"),
            "s",
        )
        .unwrap();
        assert_eq!(s.outputs.waveforms, Some(Waveforms::all("w".into())));
        assert!(!s.outputs.cycles, "waveforms alone need no counters");
        assert_eq!(
            s.params,
            Params {
                memory: MemTiming {
                    latency: 3,
                    interval: 2,
                    bus_bits: None
                }
                .into(),
                // the memory counted at the scene's clock
                clock_ps: s.clock.as_ref().unwrap().ps(),
                ..Params::RTL
            }
        );
        let s = Scene::parse(base, "s").unwrap();
        assert!(!s.outputs.cycles);
        assert_eq!((s.params, s.clock), (Params::RTL, None));
        // no output runs the chip: the preset's own clock, and the memory in ns alone
        let w = Scene::parse(&format!("{base}[chip]\npreset = \"wscg03\"\n"), "s").unwrap();
        assert_eq!((w.clock.is_none(), w.params.clock_ps), (true, 3759));
        let c = w.configuration();
        assert!(
            c.contains("miss 75 ns") && !c.contains("at the chip's"),
            "{c}"
        );
        let s = Scene::parse(&format!("{base}[outputs]\ncycles = true\n"), "s").unwrap();
        assert_eq!(s.clock.unwrap().technology, Some(Technology::Osu018));
        let s = Scene::parse(&format!("{base}[outputs]\ncross_check = \"rtl\"\n[chip]\nk = 6\nformat = \"reduced\"\n[timing]\ncredit = 4\nclock_mhz = 266\n"), "s").unwrap();
        assert!(s.outputs.cross_check == Some(CrossCheck::Rtl));
        assert_eq!((s.params.credit, s.clock.unwrap().mhz()), (4, 266.0));
        let e = Scene::parse(
            &format!("{base}[outputs]\ncycles = true\n[memory]\nlatency = 0\ninterval = 1\n"),
            "s",
        )
        .unwrap_err();
        assert!(e.contains("at least 1"), "{e}");
        let e = Scene::parse(
            &format!("{base}[outputs]\ncycles = true\n[timing]\nissue_spacing = 5\n"),
            "s",
        )
        .unwrap_err();
        assert!(e.contains("issue_spacing"), "{e}");
        let e = Scene::parse(
            &format!("{base}[outputs]\nwaveforms = {{ dir = \"w\", scopes = [\"dcntr\"] }}\n"),
            "s",
        )
        .unwrap_err();
        assert!(
            e.contains("no scope \"dcntr\"; the scopes are host, d_cntr"),
            "{e}"
        );
        let e = Scene::parse(
            &format!("{base}[outputs]\nwaveforms = {{ dir = \"w\", cycle = [5, 4] }}\n"),
            "s",
        )
        .unwrap_err();
        assert!(e.contains("unknown key \"cycle\""), "{e}");
        let e = Scene::parse(
            &format!("{base}[outputs]\nwaveforms = {{ dir = \"w\", cycles = [5, 4] }}\n"),
            "s",
        )
        .unwrap_err();
        assert!(e.contains("is empty"), "{e}");
        let s = Scene::parse(
            &format!("{base}[outputs]\nwaveforms = {{ dir = \"w\", cycles = [5, 5] }}\n"),
            "s",
        )
        .unwrap();
        assert_eq!(s.outputs.waveforms.unwrap().window, 5..6);
        let e = Scene::parse(&format!("{base}[memory]\nlatncy = 2\n"), "s").unwrap_err();
        assert!(e.starts_with("s:8:"), "{e}");
        use crate::chip::reg::Order;
        use crate::chip::rtl::ChipKind;
        let rtl = Scene::parse(
            include_str!("../../vectors/scenes/rtl_spheres.toml"),
            "rtl_spheres",
        )
        .unwrap();
        assert_eq!(
            crate::harness::chip_io::rtl_order(&rtl.cfg, rtl.traversal, &rtl.params),
            Ok((ChipKind::K6E8m15, Order::Lifo))
        );
        // the scene itself is refused where its configuration has no RTL chip
        let e = Scene::parse(
            &format!("{base}[outputs]\ncross_check = \"rtl\"\n[chip]\nnode_cache = 16\n"),
            "s",
        )
        .unwrap_err();
        assert!(e.starts_with("s:8: [outputs] cross_check: cross_check = \"rtl\" needs an RTL chip of the configuration: the RTL chips hold one node record per object; this configuration has node_cache = 16"), "{e}");
        // the default configuration is the papers' chip
        assert_eq!(
            crate::harness::chip_io::rtl_order(
                &ChipConfig::default(),
                Traversal::Fifo,
                &rtl.params
            ),
            Ok((ChipKind::K24B32, Order::Fifo))
        );
        let e = crate::harness::chip_io::rtl_order(
            &ChipConfig {
                k: 14,
                ..ChipConfig::default()
            },
            Traversal::Lifo,
            &rtl.params,
        )
        .unwrap_err();
        assert!(e.contains("k = 6, format = \"e8m15\" or k = 24, format = \"binary32\" or k = 24, format = \"e8m15/binary32\"") && e.contains("k = 14"), "{e}");
        // the triangle cache: a power of two; the RTL chips hold one word
        let s = Scene::parse(&format!("{base}[chip]\ntri_cache = 128\n"), "s").unwrap();
        assert_eq!(s.cfg.tri_cache, 128);
        let e = Scene::parse(&format!("{base}[chip]\ntri_cache = 100\n"), "s").unwrap_err();
        assert!(
            e.contains("[chip] tri_cache must be a power of two from 1 to 1024 lines"),
            "{e}"
        );
        assert!(crate::harness::chip_io::rtl_order(
            &ChipConfig {
                tri_cache: 128,
                ..rtl.cfg
            },
            Traversal::Lifo,
            &rtl.params
        )
        .is_ok());
        let e = crate::harness::chip_io::rtl_order(
            &ChipConfig {
                tri_cache: 256,
                ..rtl.cfg
            },
            Traversal::Lifo,
            &rtl.params,
        )
        .unwrap_err();
        assert!(
            e.contains("tri_cache = 256") && e.contains("at most 128"),
            "{e}"
        );
        let e =
            crate::harness::chip_io::rtl_order(&rtl.cfg, Traversal::List, &rtl.params).unwrap_err();
        assert!(e.contains("fifo or lifo"), "{e}");
        let e = crate::harness::chip_io::rtl_order(
            &rtl.cfg,
            Traversal::Lifo,
            &Params {
                tri_fifo: 4,
                ..rtl.params
            },
        )
        .unwrap_err();
        assert!(e.contains("[timing]"), "{e}");
        // the memory port's register: within its fields, and no further
        let port = Params {
            prefetch: 14,
            outstanding: 16,
            credit: 63,
            issue_spacing: 1,
            ..rtl.params
        };
        assert_eq!(
            crate::harness::chip_io::rtl_order(&rtl.cfg, Traversal::Lifo, &port),
            Ok((ChipKind::K6E8m15, Order::Lifo))
        );
        for p in [
            Params {
                prefetch: 15,
                ..port
            },
            Params {
                outstanding: 17,
                ..port
            },
            Params { credit: 64, ..port },
        ] {
            let e = crate::harness::chip_io::rtl_order(&rtl.cfg, Traversal::Lifo, &p).unwrap_err();
            assert!(e.contains("at most 14 pairs with at most 16 requests outstanding and a credit of at most 63"), "{e}");
        }
        // the records layout: the k = 24 binary32 chip, one record held, on any memory
        use crate::chip::config::MemLayout;
        let rec = ChipConfig {
            layout: MemLayout::Records,
            ..ChipConfig::default()
        };
        assert_eq!(
            crate::harness::chip_io::rtl_order(&rec, Traversal::Fifo, &rtl.params),
            Ok((ChipKind::K24B32, Order::Fifo))
        );
        let ddr = |banks| Params {
            memory: crate::chip::memory::Memory::Ddr(crate::chip::memory::Ddr {
                banks,
                ..crate::chip::memory::Ddr::DATE05
            }),
            ..rtl.params
        };
        assert!([2, 6, 8]
            .iter()
            .all(|&b| crate::harness::chip_io::rtl_order(&rec, Traversal::Fifo, &ddr(b)).is_ok()));
        let e = crate::harness::chip_io::rtl_order(
            &ChipConfig {
                node_cache: 16,
                ..rec
            },
            Traversal::Fifo,
            &ddr(8),
        )
        .unwrap_err();
        assert!(
            e.contains("this configuration has node_cache = 16: set [chip] node_cache = 1"),
            "{e}"
        );
        let e = crate::harness::chip_io::rtl_order(
            &ChipConfig {
                layout: MemLayout::Records,
                ..rtl.cfg
            },
            Traversal::Fifo,
            &ddr(8),
        )
        .unwrap_err();
        assert!(e.contains("chip_e8m15_k6 reads the `words` layout only (of the RTL chips, chip_b32_k24 also read `records`); this configuration has layout = \"records\""), "{e}");
    }

    /// `[memory]` picks the ideal model or DDR SDRAM with a preset and overrides; mixed or
    /// unknown keys are errors that say what to write.
    /// `[timing] tri_interval`: 1 or even 2 to 32, no tri_latency beside a fold, DATE'05's
    /// chip only, and an RTL cross-check only at an interval an RTL chip of the configuration
    /// is built with (k = 6 e8m15: dop_interval and tri_interval 1 and 1, 1 and 16, 6 and 32).
    #[test]
    fn tri_interval_key() {
        let base = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n[outputs]\ncycles = true\n";
        let s = Scene::parse(
            &format!("{base}[chip]\npreset = \"date05\"\n[timing]\ntri_interval = 16\n"),
            "s",
        )
        .unwrap();
        assert_eq!(
            s.params,
            Params {
                tri_interval: 16,
                clock_ps: s.clock.as_ref().unwrap().ps(),
                ..Preset::Date05.params()
            }
        );
        assert!(
            s.configuration()
                .contains("tri_interval 16 (folded TRI_UNIT"),
            "{}",
            s.configuration()
        );
        // the folded TRI_UNIT has a row; the folded chip as a whole has none
        let clock = s.clock.unwrap();
        assert!(
            clock
                .source()
                .contains("units not measured: chip_b32_k24_fold16"),
            "{}",
            clock.source()
        );
        let s8 = Scene::parse(
            &format!("{base}[chip]\npreset = \"date05\"\n[timing]\ntri_interval = 8\n"),
            "s",
        )
        .unwrap()
        .clock
        .unwrap();
        assert!(
            s8.not_measured
                .contains(&"tri_unit_fold8_b32_rne".to_string()),
            "{}",
            s8.source()
        );
        for (keys, want) in [
            ("tri_interval = 3", "tri_interval must be 1 (TRI_UNIT unfolded) or an even number of clocks from 2 to 32"),
            ("tri_interval = 34", "not 34"),
            ("tri_interval = 0", "not 0"),
            ("tri_interval = 4\ntri_latency = 60", "s:11: [timing] tri_latency is the unfolded TRI_UNIT's latency, not used by the folded one (tri_interval 4)"),
            // a key is refused for being there, whatever its value: the default's too
            ("tri_interval = 4\ntri_latency = 54", "s:11: [timing] tri_latency is the unfolded TRI_UNIT's latency"),
            ("dop_interval = 6\ndop_latency = 15", "s:11: [timing] dop_latency is the unfolded DOP unit's latency, not used by the folded one (dop_interval 6), whose latency is its schedule's (20 clocks)"),
            ("dop_latency = 16\ndop_interval = 6", "s:10: [timing] dop_latency is the unfolded DOP unit's latency"),
            ("dop_interval = 5", "dop_interval 5 does not divide k = "),
        ] {
            let e = Scene::parse(&format!("{base}[timing]\n{keys}\n"), "s").unwrap_err();
            assert!(e.contains(want), "{e}");
        }
        let e = Scene::parse(
            &format!("{base}[chip]\npreset = \"wscg03\"\n[timing]\ntri_interval = 2\n"),
            "s",
        )
        .unwrap_err();
        assert!(
            e.contains("[timing] tri_interval is DATE'05's chip's") && e.contains("[stack_engine]"),
            "{e}"
        );
        // the command line's architecture over a scene's keys: the same refusal as the preset's
        let flags = Flags {
            architecture: Some(Architecture::Wscg03),
            ..Default::default()
        };
        let e = Scene::parse_with(&format!("{base}[timing]\ntri_interval = 2\n"), "s", flags)
            .unwrap_err();
        assert!(
            e.starts_with("s:10: [timing] tri_interval is DATE'05's chip's"),
            "{e}"
        );
        let rtl = Scene::parse(
            include_str!("../../vectors/scenes/rtl_spheres.toml"),
            "rtl_spheres",
        )
        .unwrap();
        let order = |dop_interval, tri_interval| {
            crate::harness::chip_io::rtl_order(
                &rtl.cfg,
                rtl.traversal,
                &Params {
                    dop_interval,
                    tri_interval,
                    ..rtl.params
                },
            )
        };
        let e = order(1, 2).unwrap_err();
        assert!(e.contains("every 2") && e.contains("1 and 1 (chip_e8m15_k6) or 1 and 16 (chip_e8m15_k6_fold16) or 6 and 32 (chip_e8m15_k6_dop6_tri32)"), "{e}");
        assert!(order(6, 16).is_err() && order(6, 1).is_err());
        assert_eq!(
            order(1, 16).unwrap().0,
            crate::chip::rtl::ChipKind::K6E8m15Fold16
        );
        assert_eq!(
            order(6, 32).unwrap().0,
            crate::chip::rtl::ChipKind::K6E8m15Dop6Tri32
        );
    }

    #[test]
    fn memory_models_and_presets() {
        use crate::chip::memory::Ddr;
        use crate::chip::memory::Memory;
        let base = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n[outputs]\ncycles = true\n[memory]\n";
        let mem = |m: &str| Scene::parse(&format!("{base}{m}"), "s").map(|s| s.params.memory);
        assert_eq!(
            mem("model = \"ddr\"\npreset = \"wscg03\""),
            Ok(Memory::Ddr(Ddr::WSCG03))
        );
        assert_eq!(
            mem("model = \"ddr\"\npreset = \"date05\"\nbanks = 4"),
            Ok(Memory::Ddr(Ddr {
                banks: 4,
                ..Ddr::DATE05
            }))
        );
        let own = "model = \"ddr\"\nbanks = 2\npage_bytes = 1024\nbus_bits = 64\nburst = 4\nbeat_ns = 1.5\nhit_ns = 7.5\nmiss_ns = 15.001";
        assert_eq!(
            mem(own),
            Ok(Memory::Ddr(Ddr {
                banks: 2,
                page_bytes: 1024,
                bus_bits: 64,
                burst: 4,
                beat_ps: 1500,
                hit_ps: 7500,
                miss_ps: 15001
            }))
        );
        assert_eq!(
            mem("latency = 8\nbus_bits = 128"),
            Ok(Memory::Ideal(crate::chip::memory::MemTiming {
                latency: 8,
                interval: 1,
                bus_bits: Some(128)
            }))
        );
        for (m, want) in [
            ("model = \"ddr\"", "needs a preset"),
            (
                "model = \"ddr\"\nbanks = 2\npage_bytes = 1024\nbus_bits = 64\nburst = 4\nbeat_ns = 1\nhit_ns = 6",
                "(miss_ns is missing)",
            ),
            (
                "model = \"ddr\"\npreset = \"ddr4\"",
                "preset \"ddr4\" is not known",
            ),
            (
                "model = \"ddr\"\npreset = \"wscg03\"\nlatency = 3",
                "s:12: [memory] latency belongs to the ideal memory, not used by the DDR model",
            ),
            (
                "preset = \"wscg03\"",
                "s:10: [memory] preset belongs to model = \"ddr\", not used by the ideal memory",
            ),
            ("hit_ns = 8", "s:10: [memory] hit_ns belongs to model = \"ddr\""),
            (
                "model = \"ddr\"\npreset = \"wscg03\"\nhit = 8",
                "hit is a number of clocks, which depend on the chip's clock: write hit_ns",
            ),
            (
                "model = \"ddr\"\npreset = \"wscg03\"\nmiss_ns = 0.0001",
                "miss_ns = 0.0001 must be from 0.001 to 1000000 ns, to the picosecond",
            ),
            ("bus_bits = 0", "bus_bits must be at least 1"),
            ("model = \"sram\"", "model \"sram\" is not known"),
            (
                "model = \"ddr\"\npreset = \"wscg03\"\nhit_ns = 29.999",
                "burst x beat_ns <= hit_ns <= miss_ns",
            ),
        ] {
            let e = mem(m).unwrap_err();
            assert!(e.starts_with("s:") && e.contains(want), "{m}: {e}");
        }
        let s = Scene::parse(&format!("{base}model = \"ddr\"\npreset = \"wscg03\""), "s").unwrap();
        let explain = crate::scene::graph::Plan::of(&s).explain(&s);
        assert!(explain.contains("DDR SDRAM: 4 banks, 4096-byte pages, 256-bit bus, bursts of 8 beats of 3.75 ns, page hit 30 ns and miss 75 ns; at the chip's 6.944 ns clock: a burst 5 clock(s), a page hit 5, a miss 11"), "{explain}");
        // model = "ddr" written on a DDR chip preset keeps the preset's DDR values
        let on = |preset: &str, m: &str| {
            Scene::parse(&format!("{base}{m}\n[chip]\npreset = \"{preset}\""), "s")
                .map(|s| s.params.memory)
        };
        assert_eq!(
            on("date05", "model = \"ddr\""),
            Ok(Memory::Ddr(Ddr::DATE05))
        );
        assert_eq!(
            on("wscg03", "model = \"ddr\"\nbanks = 2"),
            Ok(Memory::Ddr(Ddr {
                banks: 2,
                ..Ddr::WSCG03
            }))
        );
        assert_eq!(
            on("wscg03", "model = \"ddr\"\npreset = \"date05\""),
            Ok(Memory::Ddr(Ddr::DATE05))
        );
    }

    /// A chip preset is the base of `[chip]`, `[timing]`, `[memory]` and the clock; the
    /// scene's keys override each of its values, and `--preset` replaces the scene's.
    #[test]
    fn chip_presets_and_their_overrides() {
        use crate::chip::memory::Memory;
        let base = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n[outputs]\ncycles = true\n";
        let mhz = |s: &Scene| s.clock.as_ref().unwrap().mhz();
        let parse = |t: &str| Scene::parse(&format!("{base}{t}"), "s");
        // no preset: the RTL's reset values, as before presets
        let rtl = parse("").unwrap();
        assert_eq!(
            (rtl.preset, rtl.cfg, rtl.params),
            (
                Preset::Rtl,
                ChipConfig::default(),
                Params {
                    clock_ps: rtl.clock.as_ref().unwrap().ps(),
                    ..Params::RTL
                }
            )
        );
        let d = parse("[chip]\npreset = \"date05\"\n[timing]\ntechnology = \"paper\"").unwrap();
        assert_eq!(
            (d.cfg.k, d.params.memory, mhz(&d)),
            (24, Memory::Ddr(Ddr::DATE05), 800.0)
        );
        // DDR2's ns at the paper's 1.25 ns: its 14 and 34 clocks
        assert!(
            d.configuration().contains(
                "at the chip's 1.25 ns clock: a burst 4 clock(s), a page hit 14, a miss 34"
            ),
            "{}",
            d.configuration()
        );
        assert_eq!(
            (
                d.params.issue_spacing,
                d.params.outstanding,
                d.params.prefetch,
                d.params.credit
            ),
            (1, 16, 14, 48)
        );
        // each key over the preset's value, the rest kept
        let o = parse("[chip]\npreset = \"date05\"\nk = 6\n[timing]\ncredit = 32\nclock_mhz = 400\n[memory]\nbanks = 4").unwrap();
        assert_eq!(
            (
                o.cfg.k,
                o.cfg.format,
                o.params.credit,
                o.params.prefetch,
                mhz(&o)
            ),
            (6, d.cfg.format, 32, 14, 400.0)
        );
        assert_eq!(
            o.params.memory,
            Memory::Ddr(Ddr {
                banks: 4,
                ..Ddr::DATE05
            })
        );
        // the same DDR2 at 400 MHz, twice the paper's period: half its clocks
        assert_eq!(o.params.clock_ps, 2500);
        assert!(
            o.configuration().contains(
                "at the chip's 2.5 ns clock: a burst 2 clock(s), a page hit 7, a miss 17"
            ),
            "{}",
            o.configuration()
        );
        // a memory model named replaces the preset's
        let i = parse("[chip]\npreset = \"date05\"\n[memory]\nmodel = \"ideal\"").unwrap();
        assert_eq!(i.params.memory, Memory::Ideal(MemTiming::default()));
        let w = parse("[chip]\npreset = \"wscg03\"\n[timing]\ntechnology = \"paper\"").unwrap();
        assert_eq!(
            (w.cfg.tri_cache, w.params.memory, mhz(&w)),
            (128, Memory::Ddr(Ddr::WSCG03), 266.0)
        );
        // the wscg03 preset runs WSCG'03's chip; a scene's architecture key over any preset
        assert_eq!(
            (w.architecture, d.architecture, rtl.architecture),
            (
                Architecture::Wscg03,
                Architecture::Date05,
                Architecture::Date05
            )
        );
        let a = parse("[chip]\npreset = \"wscg03\"\narchitecture = \"date05\"").unwrap();
        assert_eq!(
            (
                a.architecture,
                a.cfg.tri_cache,
                a.cfg.layout,
                a.cfg.node_cache
            ),
            (Architecture::Date05, 128, MemLayout::Records, 16)
        );
        // WSCG'03's chip reads its own memory side; DATE'05's has no [stack_engine]
        assert_eq!((w.cfg.layout, w.cfg.node_cache), (MemLayout::Words, 1));
        let e = parse("[chip]\npreset = \"wscg03\"\narchitecture = \"date05\"\n[stack_engine]\nword_buffer = 4").unwrap_err();
        assert!(e.starts_with("s:13: [stack_engine] word_buffer is WSCG'03's chip's timing, not used by DATE'05's chip"), "{e}");
        let e = parse("[chip]\narchitecture = \"wscg04\"").unwrap_err();
        assert!(
            e.starts_with("s:10:") && e.contains("\"date05\" or \"wscg03\""),
            "{e}"
        );
        let e = parse("[chip]\narchitecture = \"wscg03\"\n[stack_engine]\ntri_interval = 0")
            .unwrap_err();
        assert!(
            e.contains("[stack_engine] tri_interval must be at least 1"),
            "{e}"
        );
        // --preset replaces the scene's preset, not its keys
        let f = Scene::parse_with(
            &format!("{base}[chip]\npreset = \"date05\"\nk = 6"),
            "s",
            Flags {
                preset: Some(Preset::Rtl),
                ..Default::default()
            },
        )
        .unwrap();
        let clock_ps = f.clock.as_ref().unwrap().ps();
        assert_eq!(
            (f.preset, f.cfg.k, f.params),
            (
                Preset::Rtl,
                6,
                Params {
                    clock_ps,
                    ..Params::RTL
                }
            )
        );
        let e = parse("[chip]\npreset = \"date06\"").unwrap_err();
        assert!(
            e.starts_with("s:10:") && e.contains("\"date05\", \"wscg03\" or \"rtl\""),
            "{e}"
        );
        let e = parse("[chip]\nkk = 6").unwrap_err();
        assert!(
            e.starts_with("s:10: [chip]") && e.contains("unknown field `kk`"),
            "{e}"
        );
        assert!(graph::Plan::of(&d).explain(&d).contains("preset date05"));
    }

    /// Issue 16: mesh paths were resolved against the current directory.
    #[test]
    fn mesh_paths_are_relative_to_the_scene() {
        let dir = std::env::temp_dir().join(format!("cchip-scene-test-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        std::fs::write(
            dir.join("sub/m.obj"),
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        )
        .unwrap();
        let scene = dir.join("s.toml");
        let text = "[objects]\na = \"sub/m.obj\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n";
        std::fs::write(&scene, text).unwrap();
        let s = Scene::load(&scene).unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(Path::new(&s.objects.a), dir.join("sub/m.obj"));
        assert_eq!(s.objects.b, "sphere:12");
    }
    /// The clock: the configuration's measured period by default, the paper's with
    /// `technology = "paper"`, an assumed `clock_mhz`; never both; `--technology` over all.
    #[test]
    fn clock_technology() {
        let base = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n[chip]\nk = 6\nformat = \"reduced\"\n[outputs]\ncycles = true\n";
        let parse = |t: &str| Scene::parse(&format!("{base}{t}"), "s");
        let mhz = |t: &str| parse(t).unwrap().clock.unwrap().mhz();
        let m = parse("").unwrap();
        assert_eq!(
            m.clock,
            Some(Clock::of(Technology::Osu018, &m.cfg, Folds::NONE, Preset::Rtl).unwrap())
        );
        assert!(
            m.configuration().contains(
                "measured, the whole chip chip_e8m15_k6 (OSU 0.18 um, docs/figures/timing.csv)"
            ),
            "{}",
            m.configuration()
        );
        assert_eq!(mhz("[timing]\ntechnology = \"paper\""), 800.0);
        let e = parse("[timing]\ntechnology = \"paper\"\nclock_mhz = 3").unwrap_err();
        assert!(e.contains("not both"), "{e}");
        let e = parse("[timing]\ntechnology = \"tsmc\"").unwrap_err();
        assert!(
            e.starts_with("s:13:") && e.contains("\"osu018\", \"ecp5\" or \"paper\""),
            "{e}"
        );
        let flags = Flags {
            technology: Some(Technology::Paper),
            ..Default::default()
        };
        assert_eq!(
            Scene::parse_with(&format!("{base}[timing]\nclock_mhz = 3"), "s", flags)
                .unwrap()
                .clock
                .unwrap()
                .mhz(),
            800.0
        );
        // an assumed clock gives a finite time in microseconds to every query the model runs
        assert_eq!(
            (
                mhz("[timing]\nclock_mhz = 0.001"),
                mhz("[timing]\nclock_mhz = 1e5")
            ),
            (0.001, 1e5)
        );
        for bad in ["1e-307", "0.0009", "2e5", "0", "-3", "nan", "inf"] {
            let e = parse(&format!("[timing]\nclock_mhz = {bad}")).unwrap_err();
            assert!(
                e.contains("clock_mhz must be from 0.001 to 100000 MHz"),
                "{bad}: {e}"
            );
        }
        // the number as a user reads it, not 307 zeros
        assert!(parse("[timing]\nclock_mhz = 1e-307")
            .unwrap_err()
            .ends_with("MHz, not 1e-307"));
        // a datapath with no measured unit and no wider format measured: no period to report
        let e = Scene::parse(
            &format!("{base}[chip]\nformat = \"e8m24\"")
                .replace("[chip]\nk = 6\nformat = \"reduced\"\n", ""),
            "s",
        )
        .unwrap_err();
        assert!(
            e.contains(
                "measures none of this configuration's DOP datapath's units (fp_mul_e8m24_ru"
            ) && e.contains("clock_mhz"),
            "{e}"
        );
        // ... unless no output runs the chip: then there is no clock to refuse
        let golden = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg=[0,0,0]\nt=[0,0,0]\n[chip]\nformat = \"e8m24\"\n";
        assert_eq!(Scene::parse(golden, "s").unwrap().clock, None);
    }
}
