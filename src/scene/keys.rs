//! One rule for a scene's keys: a key that the scene's configuration does not use is refused,
//! naming its line and why ([`unused`]), and so is an output the configuration cannot give
//! ([`runnable`]). `cchip run`, `--explain` and `--dot` read a scene through both, so they
//! refuse the same scenes.

use super::graph::{Plan, Unit};
use super::{line_of, CrossCheck, Keys, Scene};
use crate::chip::rtl;
use crate::chip::wscg03::Architecture;
use serde::Deserialize;

/// The keys a scene wrote in the sections whose keys depend on the configuration, each with
/// its place in the file (the sections are read again: their own types keep no places).
#[derive(Debug, Default, Deserialize)]
pub(super) struct Written {
    #[serde(default)]
    chip: Keys,
    #[serde(default)]
    timing: Keys,
    #[serde(default)]
    memory: Keys,
    #[serde(default)]
    stack_engine: Keys,
    #[serde(default)]
    query: Keys,
    #[serde(default)]
    outputs: Keys,
}

/// What [`unused`] judges a key by: the resolved configuration.
pub(super) struct Uses {
    pub architecture: Architecture,
    /// Whether an output runs the cycle model ([`Outputs::run_chip`](super::Outputs::run_chip)).
    pub chip_runs: bool,
    pub dop_interval: u32,
    pub tri_interval: u32,
    pub depth: rtl::Depth,
    /// The memory model is DDR SDRAM (else the ideal one).
    pub ddr: bool,
}

impl Written {
    /// `[section] key`'s line, if the scene wrote it.
    pub fn line(&self, text: &str, section: &str, key: &str) -> Option<usize> {
        let keys = match section {
            "chip" => &self.chip,
            "timing" => &self.timing,
            "memory" => &self.memory,
            "stack_engine" => &self.stack_engine,
            "query" => &self.query,
            _ => &self.outputs,
        };
        keys.get(key).map(|v| line_of(text, v.span().start))
    }

    /// The first key (in the file's order) that `uses` does not use: `LINE: [section] key
    /// why`.
    pub fn unused(&self, text: &str, uses: &Uses) -> Result<(), String> {
        let mut keys: Vec<(usize, &str, &str)> = [
            ("chip", &self.chip),
            ("timing", &self.timing),
            ("memory", &self.memory),
            ("stack_engine", &self.stack_engine),
        ]
        .into_iter()
        .flat_map(|(section, keys)| {
            keys.iter()
                .map(move |(k, v)| (v.span().start, section, k.as_str()))
        })
        .collect();
        keys.sort_unstable();
        match keys.into_iter().find_map(|(at, section, key)| {
            why_unused(uses, section, key).map(|why| (at, section, key, why))
        }) {
            Some((at, section, key, why)) => {
                Err(format!("{}: [{section}] {key} {why}", line_of(text, at)))
            }
            None => Ok(()),
        }
    }
}

/// Why `[section] key` does nothing in the configuration `u`, if it does nothing.
fn why_unused(u: &Uses, section: &str, key: &str) -> Option<String> {
    let wscg03 = u.architecture == Architecture::Wscg03;
    let ddr = u.ddr;
    Some(match (section, key) {
        ("timing" | "memory" | "stack_engine", _) | ("chip", "architecture") if !u.chip_runs => {
            "sets the chip the cycle model runs, and this scene's outputs run only the golden model: add cycles = true (or memory, waveforms, cross_check) to [outputs], or remove it".into()
        }
        ("chip", "layout" | "node_cache" | "dop_bits") if wscg03 => {
            "is not used by WSCG'03's chip, whose memory holds a node pair per record (the `records` layout of one level, full distances) and which holds its records in its Memory Controller: remove it, or set [chip] architecture = \"date05\"".into()
        }
        ("chip", "tri_cache_b") if wscg03 => {
            "is not used by WSCG'03's chip, whose B side holds its triangle words in a two-entry SRAM: remove it, or set [chip] architecture = \"date05\"".into()
        }
        ("timing", k) if wscg03 && k != "technology" && k != "clock_mhz" => {
            "is DATE'05's chip's (D_CNTR, its DOP unit, TRI_UNIT, the memory port), not used by WSCG'03's chip, which runs clocked as its RTL (its units' latencies are the RTL's): remove it, or set [chip] architecture = \"date05\"".into()
        }
        ("stack_engine", _) => "is WSCG'03's chip's timing as the paper gives it (its event model, Fig. 13 of `cchip figures`), not used by scenes: DATE'05's chip has none, and scenes run WSCG'03's clocked as its RTL, whose latencies are the RTL's (docs/explanation/architecture.md, \"WSCG'03's chip\"): remove it".into(),
        ("timing", "dop_latency") if u.dop_interval > 1 => format!(
            "is the unfolded DOP unit's latency, not used by the folded one (dop_interval {}), whose latency is its schedule's ({} clocks): remove dop_latency, or set dop_interval = 1",
            u.dop_interval,
            u.depth.dop_fold_latency(u.dop_interval as usize)
        ),
        ("timing", "depth") if u.depth == rtl::Depth::Fpga && u.tri_interval == 1 => {
            "= \"fpga\" cuts T.CHECK's units for the folded TRI_UNIT, not used by the unfolded one (tri_interval 1): set tri_interval to an even number of clocks from 2 to 32, or remove depth".into()
        }
        ("timing", "dop_latency") if u.depth == rtl::Depth::Fpga => format!(
            "is the DOP unit's latency at ASIC depth, not used at depth = \"fpga\", where its latency is its lanes' ({} clocks unfolded): remove dop_latency, or depth",
            u.depth.lane_latency()
        ),
        ("timing", "tri_latency") if u.tri_interval > 1 => format!(
            "is the unfolded TRI_UNIT's latency, not used by the folded one (tri_interval {}), whose latency is its schedule's: remove tri_latency, or set tri_interval = 1",
            u.tri_interval
        ),
        ("memory", "latency" | "interval") if ddr => {
            "belongs to the ideal memory, not used by the DDR model, whose timing is its beat_ns, hit_ns and miss_ns: remove it, or set model = \"ideal\"".into()
        }
        ("memory", "preset" | "banks" | "page_bytes" | "burst" | "beat_ns" | "hit_ns" | "miss_ns" | "hit" | "miss") if !ddr => {
            "belongs to model = \"ddr\", not used by the ideal memory (latency, interval, bus_bits): remove it, or set model = \"ddr\"".into()
        }
        _ => return None,
    })
}

/// Refuses what the scene's outputs ask of a configuration that cannot give it, before
/// anything runs: WSCG'03's chip streams binary32; D_CNTR runs the fifo and lifo
/// traversals only; a cross-check needs an RTL chip of the configuration
/// ([`rtl_order`](crate::harness::chip_io::rtl_order)). Errors name the key's line, or the
/// command line's flag.
pub(super) fn runnable(s: &Scene, w: &Written, text: &str) -> Result<(), String> {
    let plan = Plan::of(s);
    let at = |section: &str, key: &str, flag: &str| match w.line(text, section, key) {
        Some(line) => format!("{line}: [{section}] {key}"),
        None => format!(" {flag}"),
    };
    let cross = |c: CrossCheck| {
        format!(
            "cross_check = \"{}\"",
            if c == CrossCheck::Rtl {
                "rtl"
            } else {
                "verilog"
            }
        )
    };
    if let Some(w) = s.outputs.waveforms.as_ref().filter(|w| w.dir.is_file()) {
        return Err(format!(
            "{}: {} is a file; give a directory for the VCD files",
            at("outputs", "waveforms", "--vcd"),
            w.dir.display()
        ));
    }
    if s.architecture == Architecture::Wscg03 {
        if plan.runs(Unit::DCntr) && s.cfg.format.dop != crate::format::Format::BINARY32 {
            return Err(format!("{}: WSCG'03's chip streams eight binary32 distances a clock on its 256-bit bus (its RTL), so its clocks are binary32's: set format = \"binary32\", or run DATE'05's chip ([chip] architecture = \"date05\") for other formats", at("chip", "format", "[chip] format")));
        }
        return Ok(());
    }
    if plan.runs(Unit::DCntr) && s.traversal.order().is_none() {
        return Err(format!(
            "{}: cycles, memory, waveforms and cross-checks come from DATE'05's D_CNTR, which runs the fifo or lifo traversal, not {}: set traversal = \"fifo\" or \"lifo\", or [chip] architecture = \"wscg03\" (the list traversal in hardware)",
            at("query", "traversal", "[query] traversal"),
            s.traversal.name()
        ));
    }
    if let Some(c) = plan.cross_check {
        crate::harness::chip_io::rtl_order(&s.cfg, s.traversal, &s.params).map_err(|e| {
            format!(
                "{}: {} needs an RTL chip of the configuration: {e}",
                at("outputs", "cross_check", "--rtl"),
                cross(c)
            )
        })?;
    }
    Ok(())
}
