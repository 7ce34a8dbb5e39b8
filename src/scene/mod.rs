//! Scenes: two objects, one pose or a pose sweep, the query, the chip configuration and
//! the outputs wanted (TOML). Every key, with its default and range: the user guide's
//! "Scene keys" (docs/reference/scene-keys.md).

pub mod graph;
mod keys;
pub mod record;
pub mod run;

use crate::chip::config::{ChipConfig, DopBits};
use crate::chip::layout::Layout;
use crate::chip::memory::{Ddr, MemTiming, Memory};
use crate::chip::params::Params;
use crate::chip::preset::Preset;
use crate::chip::reg::Mode;
use crate::chip::timing::{Clock, Folds, Technology};
use crate::chip::wscg03::Architecture;
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
    /// `[stack_engine]`, read only to be refused (`keys::why_unused`): scenes run WSCG'03's
    /// chip as its RTL.
    #[serde(rename = "stack_engine")]
    _stack_engine: Option<Keys>,
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
        "\"date05\", \"date05-treelets\", \"wscg03\" or \"rtl\"",
    )?;
    let preset = flags.preset.or(named).unwrap_or(Preset::Rtl);
    let arch = flags.architecture.or(arch).unwrap_or(preset.architecture());
    let cfg = over(&preset.chip(), keys, text, "[chip]", &[])?;
    Ok((preset, arch, arch.config(&cfg)))
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
/// (default: measured on OSU 0.18 um; estimated for WSCG'03's chip, which scenes run as its event model).
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
        (None, t) => Ok(Clock::of(t.unwrap_or_default(), cfg, folds, preset)?.for_architecture(arch, cfg)),
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

/// Which traversal VCDs a scene writes: one per pose into `dir`, the chip's traversal signals
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

    /// From the scene's `waveforms`: a directory, or a table `{ dir, scopes, cycles }` of
    /// the chip's traversal signals `probes`.
    fn of(v: toml::Value, probes: &crate::chip::probes::Probes) -> Result<Self, String> {
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
        let known = probes.scopes();
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
        ii => format!(
            "tri_interval {ii} (folded TRI_UNIT, its schedule's latency{})",
            match p.depth {
                crate::chip::rtl::Depth::Asic => String::new(),
                d => format!(", FP units at depth = \"{}\"", d.name()),
            }
        ),
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
    /// The chip the cycle model runs.
    pub architecture: Architecture,
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
        let (c, p) = (&self.cfg, &self.params);
        let (timing, memory_side) = match self.architecture {
            Architecture::Date05 => (
                format!(
                    "timing: queue_entries {}, {}, {}, tri_fifo {}, issue_spacing {}, credit {}, outstanding {}, prefetch {}, tri_prefetch {}",
                    p.queue_entries, dop_timing(p), tri_timing(p), p.tri_fifo, p.issue_spacing, p.credit, p.outstanding, p.prefetch, p.tri_prefetch
                ),
                format!(
                    "tri_cache_b {}, layout {}, node_cache {}, dop_bits {}{}",
                    c.tri_cache_b,
                    c.layout,
                    c.node_cache,
                    c.dop_bits,
                    match c.dop_bits {
                        DopBits::Full => String::new(),
                        _ => format!(" ({} tree levels a record)", Layout::new(c).levels),
                    }
                ),
            ),
            Architecture::Wscg03 => {
                use crate::chip::rtl as r;
                (
                    format!(
                        "timing (its RTL's): list SRAMs of {} pointers (read 1 clock), an aligned DOP in {} bundles of 256 bits, a transform {} clocks, compare latency {}, {} asks and {} records in the Memory Controller, outstanding {}, {}",
                        1 << r::LIST_SRAM_BITS, c.k.div_ceil(8), r::wscg03_transform_clocks(c.k), r::WSCG03_COMPARE_LATENCY, r::MC_ASKS, r::MC_RECORDS, p.outstanding, tri_timing(p)
                    ),
                    "layout records (a node pair per record, one burst)".to_string(),
                )
            }
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
                    .map(|w| Waveforms::of(w, architecture.probes()))
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
            depth: params.depth,
            tri_interval: params.tri_interval,
            ddr,
        };
        written.unused(text, &uses).map_err(at_line)?;
        params.memory = memory.map_err(err)?;
        cfg.check().map_err(|e| {
            // the key the error is about, where the scene wrote it (else the preset's)
            let line = [
                "k",
                "format",
                "tri_cache",
                "tri_cache_b",
                "node_cache",
                "dop_bits",
            ]
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
        let folds = Folds::of(&params);
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
mod tests;
