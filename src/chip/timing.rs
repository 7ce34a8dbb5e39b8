//! The chip's clock period per configuration, labelled ([`PeriodSource`]): measured, the
//! row of the configuration's own RTL chip in the timing study's table
//! (`scripts/timing-study.sh`); estimated, where that chip has no row, by the slowest of the
//! RTL units the configuration is built from (a wider format's where its own is not built);
//! or assumed, the papers' clock or a scene's `clock_mhz`. The study's tables are embedded, so the
//! binary needs no file; they are read by column name (the study may add columns), and a unit
//! without a row is "not measured", named beside the period.

use super::config::{ChipConfig, DopBits};
use super::preset::Preset;
use super::rtl::{self, ChipKind, Depth};
use super::wscg03::Architecture;
use crate::format::{Format, Rounding};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Where the period comes from (`[timing] technology`, `cchip run --technology`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum Technology {
    /// OSU 0.18 um standard cells, Yosys + OpenSTA, pre-layout: docs/figures/timing.csv.
    #[default]
    Osu018,
    /// Lattice ECP5 (LFE5U-85F), nextpnr-ecp5: docs/figures/timing_ecp5.csv.
    Ecp5,
    /// The papers' clock (DATE'05 800 MHz, WSCG'03 266 MHz), assumed.
    Paper,
}

impl Technology {
    /// The measured table: (its file, its text, what it measured).
    fn table(self) -> Option<(&'static str, &'static str, &'static str)> {
        match self {
            Technology::Osu018 => Some((
                "docs/figures/timing.csv",
                include_str!("../../docs/figures/timing.csv"),
                "OSU 0.18 um",
            )),
            Technology::Ecp5 => Some((
                "docs/figures/timing_ecp5.csv",
                include_str!("../../docs/figures/timing_ecp5.csv"),
                "ECP5 LFE5U-85F",
            )),
            Technology::Paper => None,
        }
    }
}

/// One timing table: each measured unit's minimum clock period in ns, and its area in um^2
/// where the table gives it.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    periods: BTreeMap<String, f64>,
    areas: BTreeMap<String, f64>,
}

impl Table {
    /// The CSV's `unit` column and its period: `min_period_ns`, or `1000 / fmax_mhz` where the
    /// table gives only Fmax. A row with neither filled is not measured. Errors name the file
    /// and line.
    pub fn parse(text: &str, file: &str) -> Result<Table, String> {
        let mut r = csv::Reader::from_reader(text.as_bytes());
        let head = r.headers().map_err(|e| format!("{file}:1: {e}"))?.clone();
        let col = |name: &str| head.iter().position(|h| h.trim() == name);
        let unit = col("unit").ok_or_else(|| {
            format!("{file}:1: no `unit` column (re-run scripts/timing-study.sh)")
        })?;
        // the ASIC table's period, else the FPGA table's (both exact where Fmax is rounded)
        let (period, fmax, area) = (
            col("min_period_ns").or_else(|| col("period_ns")),
            col("fmax_mhz"),
            col("area_um2"),
        );
        if period.is_none() && fmax.is_none() {
            return Err(format!("{file}:1: neither a `min_period_ns` nor a `fmax_mhz` column (re-run scripts/timing-study.sh)"));
        }
        let (mut periods, mut areas) = (BTreeMap::new(), BTreeMap::new());
        for (i, row) in r.records().enumerate() {
            let line = i + 2;
            let row = row.map_err(|e| format!("{file}:{line}: {e}"))?;
            let num = |c: Option<usize>| -> Result<Option<f64>, String> {
                match c.and_then(|c| row.get(c)).map(str::trim).filter(|s| !s.is_empty()) {
                    None => Ok(None),
                    Some(s) => match s.parse::<f64>() {
                        Ok(x) if x.is_finite() && x > 0.0 => Ok(Some(x)),
                        _ => Err(format!("{file}:{line}: {s:?} is not a positive number (re-run scripts/timing-study.sh)")),
                    },
                }
            };
            let ns = match num(period)? {
                Some(ns) => Some(ns),
                None => num(fmax)?.map(|f| 1000.0 / f),
            };
            let name = row.get(unit).unwrap_or("").trim().to_string();
            if let Some(a) = num(area)? {
                areas.insert(name.clone(), a);
            }
            if let Some(ns) = ns {
                periods.insert(name, ns);
            }
        }
        Ok(Table { periods, areas })
    }

    /// The table of `tech` (none for [`Technology::Paper`]).
    pub fn of(tech: Technology) -> Result<Option<Table>, String> {
        tech.table()
            .map(|(file, text, _)| Table::parse(text, file))
            .transpose()
    }

    /// um^2 of the units a configuration changes ([`datapath_units`], as the area study's
    /// cells); `None` unless each is measured.
    pub fn datapath_area_um2(&self, cfg: &ChipConfig, folds: Folds) -> Option<f64> {
        datapath_units(cfg, folds)
            .iter()
            .map(|(u, n)| Some(self.areas.get(u)? * *n as f64))
            .sum()
    }
}

/// The units a configuration changes, each with its count: its DOP unit and TRI_UNIT,
/// folded as `folds`, and with stored DOP precision the decode stage, one per plane of each
/// node of a pair (2k). D_CNTR, the queue and the memory port are not counted.
pub fn datapath_units(cfg: &ChipConfig, folds: Folds) -> Vec<(String, u32)> {
    let mut units = vec![(dop_unit(cfg, folds), 1), (tri_unit(cfg, folds), 1)];
    if let DopBits::Bits(b) = cfg.dop_bits {
        units.push((rtl::dop_decode_name(cfg.format.dop, b), 2 * cfg.k as u32));
    }
    units
}

/// `cfg`'s DOP unit's name ([`rtl::dop_unit_name_at`]), taking a pair every `folds.dop`
/// clocks at `folds.depth`.
pub fn dop_unit(cfg: &ChipConfig, folds: Folds) -> String {
    rtl::dop_unit_name_at(folds.depth, cfg.k, cfg.format.dop, folds.dop)
}

/// The clocks between the pairs a folded unit takes (1: unfolded): the cycle model's
/// `[timing] tri_interval` and `dop_interval`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Folds {
    pub tri: u32,
    pub dop: u32,
    /// The FP units' depth (written only when it is not the default, `asic`).
    #[serde(default, skip_serializing_if = "Depth::is_asic")]
    pub depth: Depth,
}

impl Folds {
    /// Both units unfolded.
    pub const NONE: Folds = Folds {
        tri: 1,
        dop: 1,
        depth: Depth::Asic,
    };

    /// `tri` and `dop` at ASIC depth.
    pub const fn asic(tri: u32, dop: u32) -> Folds {
        Folds {
            tri,
            dop,
            depth: Depth::Asic,
        }
    }

    /// The folds and depth of the cycle model's `p`.
    pub fn of(p: &super::params::Params) -> Folds {
        Folds {
            tri: p.tri_interval,
            dop: p.dop_interval,
            depth: p.depth,
        }
    }
}

/// `T / D`: TRI_UNIT's and the DOP unit's pair intervals, then `(fpga)` at FPGA depth.
impl std::fmt::Display for Folds {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "{} / {}", self.tri, self.dop)?;
        match self.depth {
            Depth::Asic => Ok(()),
            d => write!(f, " ({})", d.name()),
        }
    }
}

impl Default for Folds {
    fn default() -> Folds {
        Folds::NONE
    }
}

/// `cfg`'s TRI_UNIT's name ([`rtl::tri_unit_name_at`]), taking a pair every `folds.tri`
/// clocks at `folds.depth`.
pub fn tri_unit(cfg: &ChipConfig, folds: Folds) -> String {
    rtl::tri_unit_name_at(folds.depth, cfg.format.tri, cfg.tri_rounding, folds.tri)
}

/// The RTL units a configuration is built from, by their names in `rtl/` and the timing
/// tables (`chains`, parts first), and the whole chip where the RTL builds this
/// configuration. A folded configuration also counts the unfolded chip: the glue the two
/// share (D_CNTR, the memory port, the caches) bounds the folded chip's glue until the folded
/// chip has a row of its own.
pub fn units(cfg: &ChipConfig, folds: Folds) -> Vec<String> {
    let mut u: Vec<String> = vec![];
    for name in chains(cfg, folds)
        .into_iter()
        .flat_map(|c| c.into_iter().rev().flatten())
    {
        if !u.contains(&name) {
            u.push(name);
        }
    }
    if folds != Folds::NONE {
        u.push(chip_name(cfg, folds));
    }
    u
}

/// `cfg`'s units as three chains of blocks, each block before its parts: the DOP datapath
/// (the unfolded chip where the DOP unit is not folded; DOP unit of k lanes: DATE'05 Eq. 10; DOPTRF lane; FP multiplier and adder) in the DOP
/// format and rounding, or the folded DOP unit that takes a pair every `folds.dop` clocks;
/// T.CHECK's (the unfolded chip where TRI_UNIT is not folded; TRI_UNIT, or the folded one at `folds.tri`; T.CHECK; its FP units and the
/// certificate's scaler: §4.2) in T.CHECK's format and rounding; the glue (the unfolded
/// chip; D_CNTR's pair queue, §4.3). A block's row, where measured, stands for its parts: it
/// maps them as it builds them, where a lone part's row only approximates that (ABC maps a
/// lane alone and 24 of them in a DOP unit a few percent apart, either way).
fn chains(cfg: &ChipConfig, folds: Folds) -> [Vec<Vec<String>>; 3] {
    let (d, dr) = (
        rtl::format_tag(cfg.format.dop),
        rtl::rounding_tag(cfg.dop_rounding.op()),
    );
    let (t, tr) = (
        rtl::format_tag(cfg.format.tri),
        rtl::rounding_tag(cfg.tri_rounding),
    );
    let chip = || vec![chip_name(cfg, Folds::NONE)];
    let at = folds.depth.tag();
    let dop_parts = [
        vec![dop_unit(cfg, folds)],
        vec![format!("doptrf{at}_{d}")],
        vec![
            format!("fp_mul{at}_{d}_{dr}"),
            format!("fp_add{at}_{d}_{dr}"),
        ],
    ];
    let dop = (folds.dop == 1)
        .then(chip)
        .into_iter()
        .chain(dop_parts)
        .collect();
    let tcheck = (folds.tri == 1).then(|| vec![format!("tcheck_{t}_{tr}")]);
    let tri_parts = vec![
        format!("fp_mul{at}_{t}_{tr}"),
        format!("fp_add{at}_{t}_{tr}"),
        format!("fp_scale_{t}"),
    ];
    let tri = (folds.tri == 1)
        .then(chip)
        .into_iter()
        .chain([vec![tri_unit(cfg, folds)]])
        .chain(tcheck)
        .chain([tri_parts])
        .collect();
    [
        dop,
        tri,
        vec![chip(), vec![rtl::PAIR_QUEUE_UNIT.to_string()]],
    ]
}

/// What stands in for a folded unit that has no row of its own, best first: a timed chip built
/// on that fold (its whole period, the unit as a chip maps it, and an upper bound for the unit:
/// `chip_e8m15_k6_fold16`'s 7.130 ns is set by its folded T.CHECK), then the unfolded
/// counterpart (the same FP units and stages without the fold's multiplexers and schedule
/// counter, so a lower bound: TRI_UNIT folded at ii 16, binary32, 8.607 ns against 6.944
/// unfolded). A fold then never looks faster for want of a measurement where a chip measured it.
fn stand_in(table: &Table, cfg: &ChipConfig, folds: Folds, unit: &str) -> Option<String> {
    let (tri, dop) = (
        folds.tri > 1 && unit == tri_unit(cfg, folds),
        folds.dop > 1 && unit == dop_unit(cfg, folds),
    );
    let chip = ChipKind::built(cfg).find(|k| {
        ((tri && k.tri_interval() == folds.tri) || (dop && k.dop_interval() == folds.dop))
            && k.depth() == folds.depth
            && table.periods.contains_key(k.name())
    });
    match chip {
        Some(k) => Some(k.name().to_string()),
        None if tri => Some(tri_unit(cfg, Folds::NONE)),
        None if dop => Some(dop_unit(cfg, Folds::NONE)),
        None => None,
    }
}

/// A unit and its measured row: (the row's name, its period) or None.
type UnitRow = (String, Option<(String, f64)>);

/// A chain's levels down to its first with a measured row (a folded unit's stand-in counts),
/// each unit with its row.
fn largest_measured(
    table: &Table,
    cfg: &ChipConfig,
    folds: Folds,
    chain: Vec<Vec<String>>,
) -> Vec<Vec<UnitRow>> {
    let row = |u: &String| {
        let own = table.periods.get(u).map(|&ns| (u.clone(), ns));
        own.or_else(|| {
            stand_in(table, cfg, folds, u).and_then(|s| {
                table
                    .periods
                    .get(&s)
                    .map(|&ns| (format!("{s} (for {u})"), ns))
            })
        })
    };
    let mut levels = vec![];
    for level in chain {
        let rows: Vec<_> = level
            .into_iter()
            .map(|u| {
                let r = row(&u);
                (u, r)
            })
            .collect();
        let found = rows.iter().any(|(_, r)| r.is_some());
        levels.push(rows);
        if found {
            break;
        }
    }
    levels
}

/// The chip's name: the RTL's where it builds `cfg` with `folds`, else as `rtl_chips!`
/// would name it.
fn chip_name(cfg: &ChipConfig, folds: Folds) -> String {
    let tag = folds.depth.tag();
    match (ChipKind::of(cfg, folds.dop, folds.tri, folds.depth), folds) {
        (Some(kind), _) => kind.name().to_string(),
        (None, Folds { dop: 1, tri: 1, .. }) => format!("chip_{}{tag}", cfg_tag(cfg)),
        (None, Folds { dop: 1, tri, .. }) => format!("chip_{}_fold{tri}{tag}", cfg_tag(cfg)),
        (None, Folds { dop, tri, .. }) => format!("chip_{}_dop{dop}_tri{tri}{tag}", cfg_tag(cfg)),
    }
}

/// `cfg`'s DOP datapath (`path` 0) or T.CHECK's (1), parts first: its chain's units
/// ([`chains`]).
fn datapath(cfg: &ChipConfig, folds: Folds, path: usize) -> Vec<String> {
    chains(cfg, folds)[path]
        .iter()
        .rev()
        .flatten()
        .cloned()
        .collect()
}

/// The slowest of its chains' largest measured blocks ([`largest_measured`]), the blocks
/// above them named as not measured, and the formats that stood in: a datapath with no unit
/// measured in its format takes the units of the narrowest measured format at least as wide
/// (an upper bound of its own). Err: the datapath none of whose units is measured in any such
/// format.
fn slowest_unit(
    table: &Table,
    cfg: &ChipConfig,
    folds: Folds,
) -> Result<(String, f64, Vec<String>, Vec<String>), String> {
    let has = |c: &ChipConfig, path: usize| {
        largest_measured(table, c, folds, chains(c, folds)[path].clone())
            .last()
            .is_some_and(|l| l.iter().any(|(_, r)| r.is_some()))
    };
    let wider = |f: Format| {
        MEASURED_FORMATS
            .into_iter()
            .filter(move |w| w.exp_bits() >= f.exp_bits() && w.frac_bits() >= f.frac_bits())
    };
    let mut run = *cfg;
    let mut widened = vec![];
    for (path, name) in [(0, "DOP datapath"), (1, "T.CHECK datapath")] {
        let own = if path == 0 {
            cfg.format.dop
        } else {
            cfg.format.tri
        };
        if has(&run, path) {
            continue;
        }
        let set = |c: &mut ChipConfig, f: Format| {
            if path == 0 {
                c.format.dop = f
            } else {
                c.format.tri = f
            }
        };
        let f = wider(own).find(|&f| {
            has(
                &{
                    let mut c = run;
                    set(&mut c, f);
                    c
                },
                path,
            )
        });
        let f =
            f.ok_or_else(|| format!("{name}'s units ({})", datapath(cfg, folds, path).join(", ")))?;
        set(&mut run, f);
        widened.push(format!(
            "the {name} in {f} stands in for {own} (not built in RTL; a wider format)"
        ));
    }
    let (mut slowest, mut not_measured) = (None::<(String, f64)>, vec![]);
    if folds != Folds::NONE {
        not_measured.push(chip_name(cfg, folds));
    }
    for level in chains(&run, folds)
        .into_iter()
        .flat_map(|c| largest_measured(table, &run, folds, c))
    {
        for (u, row) in level {
            if !table.periods.contains_key(&u) && !not_measured.contains(&u) {
                not_measured.push(u);
            }
            if let Some((name, ns)) = row.filter(|r| slowest.as_ref().is_none_or(|s| r.1 > s.1)) {
                slowest = Some((name, ns));
            }
        }
    }
    let (unit, ns) = slowest.expect("a datapath unit is measured");
    Ok((unit, ns, not_measured, widened))
}

/// A chip's name for a configuration the RTL does not build (as `rtl_chips!` names them; a
/// T.CHECK rounding other than the RTL chips' nearest-even named too, so that no such
/// configuration takes a built chip's row for its own; the DOP lanes round either way).
fn cfg_tag(cfg: &ChipConfig) -> String {
    let (d, t) = (
        rtl::format_tag(cfg.format.dop),
        rtl::format_tag(cfg.format.tri),
    );
    let formats = if d == t {
        format!("{d}_k{}", cfg.k)
    } else {
        format!("{d}_{t}_k{}", cfg.k)
    };
    let tri = if cfg.tri_rounding == Rounding::NearestEven {
        String::new()
    } else {
        format!("_tri_{}", rtl::rounding_tag(cfg.tri_rounding))
    };
    format!("{formats}{tri}")
}

/// How a clock period was obtained (the JSON's `period_source`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum PeriodSource {
    /// The timing table's row of the configuration's own RTL chip, the chip as built.
    Measured,
    /// The configuration's own chip has no row: measured rows stand in for it
    /// ([`Clock::estimate`] says which, and for what).
    Estimated,
    /// Not from a table: the paper's clock or the scene's `clock_mhz`.
    Assumed,
}

impl PeriodSource {
    pub fn name(self) -> &'static str {
        match self {
            PeriodSource::Measured => "measured",
            PeriodSource::Estimated => "estimated",
            PeriodSource::Assumed => "assumed",
        }
    }
}

/// The formats whose units the timing study measures, narrowest first: a format not
/// measured is estimated by the first of these at least as wide in exponent and fraction.
const MEASURED_FORMATS: [Format; 2] = [Format::REDUCED, Format::BINARY32];

/// The clock a report runs at, and where it came from.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Clock {
    pub period_ns: f64,
    pub source: PeriodSource,
    pub technology: Option<Technology>,
    /// From a table: its file, the row that sets the period, the configuration's units with
    /// no row.
    pub table: Option<&'static str>,
    pub slowest: Option<String>,
    pub not_measured: Vec<String>,
    /// Estimated: what stands in for what.
    pub estimate: Option<String>,
    /// Assumed: why (the scene's `clock_mhz`, the preset's paper clock).
    pub assumed: Option<String>,
}

impl Clock {
    pub fn mhz(&self) -> f64 {
        1000.0 / self.period_ns
    }

    /// The period to the picosecond: [`Params::clock_ps`](crate::chip::params::Params::clock_ps),
    /// in whose clocks the models count a DDR memory.
    pub fn ps(&self) -> u64 {
        super::memory::ps(self.period_ns)
    }

    /// An assumed clock of `mhz`, `why`.
    pub fn assumed(mhz: f64, why: String) -> Clock {
        let period_ns = 1000.0 / mhz;
        Clock {
            period_ns,
            source: PeriodSource::Assumed,
            technology: None,
            table: None,
            slowest: None,
            not_measured: vec![],
            estimate: None,
            assumed: Some(why),
        }
    }

    /// The configuration's period in `tech` with its units folded as `folds` ([`measured`](Self::measured)), or the
    /// preset's paper clock. An error if the table measures neither datapath's units nor a wider
    /// format's.
    pub fn of(
        tech: Technology,
        cfg: &ChipConfig,
        folds: Folds,
        preset: Preset,
    ) -> Result<Clock, String> {
        let Some((file, text, what)) = tech.table() else {
            let mut c = Clock::assumed(
                preset.clock_mhz(),
                format!(
                    "the paper's {} MHz (preset {}), assumed",
                    preset.clock_mhz(),
                    preset.name()
                ),
            );
            c.technology = Some(tech);
            return Ok(c);
        };
        let table = Table::parse(text, file)?;
        let mut c = Clock::measured(&table, cfg, folds).map_err(|none| {
            format!("{file} ({what}) measures none of this configuration's {none}, nor of a wider format's: its period would be the other units' alone; run scripts/timing-study.sh, or set [timing] technology = \"paper\" or clock_mhz (assumed)")
        })?;
        (c.technology, c.table) = (Some(tech), Some(file));
        Ok(c)
    }

    /// The configuration's chip's period where `table` measured that chip (its units as it
    /// builds them, the control and the paths between them: the chip as built, whose units a
    /// lone unit's row only approximates, as the flow maps it apart); else the slowest of
    /// `cfg`'s units that `table` measured (`slowest_unit`). Measured if the row is the
    /// configuration's own RTL chip, else estimated. Err: the datapath none of whose units is
    /// measured in its format or a wider one.
    pub fn measured(table: &Table, cfg: &ChipConfig, folds: Folds) -> Result<Clock, String> {
        let chip = chip_name(cfg, folds);
        let (unit, ns, not_measured, widened) = match table.periods.get(&chip) {
            Some(&ns) => (chip, ns, vec![], vec![]),
            None => slowest_unit(table, cfg, folds)?,
        };
        let chip = ChipKind::of(cfg, folds.dop, folds.tri, folds.depth);
        let why = match chip.map(|k| (k, k.reads(cfg))) {
            _ if !widened.is_empty() => widened.join("; "),
            None => format!("{} is not built in RTL", chip_name(cfg, folds)),
            Some((k, Err(_))) if k.config().dop_bits != cfg.dop_bits => format!("{} reads node records of dop_bits = {}; this configuration's decode stage (dop_bits = {}) is not built", k.name(), k.config().dop_bits, cfg.dop_bits),
            Some((_, Err(e))) => e,
            Some((k, Ok(()))) if !table.periods.contains_key(k.name()) => format!("{} has no row", k.name()),
            Some(_) => String::new(),
        };
        let (source, estimate) = if why.is_empty() {
            (PeriodSource::Measured, None)
        } else {
            (
                PeriodSource::Estimated,
                Some(format!(
                    "{unit} stands in for this configuration's chip: {why}"
                )),
            )
        };
        Ok(Clock {
            period_ns: ns,
            source,
            technology: None,
            table: None,
            slowest: Some(unit),
            not_measured,
            estimate,
            assumed: None,
        })
    }

    /// This clock for `arch`'s chip of `cfg`: for WSCG'03's, its RTL chip's row
    /// ([`WSCG03_CHIP`](rtl::WSCG03_CHIP); measured if `cfg` is the configuration it is built
    /// for, else estimated), or where the table has none, DATE'05's chip of the configuration
    /// (estimated).
    pub fn for_architecture(mut self, arch: Architecture, cfg: &ChipConfig) -> Clock {
        if arch != Architecture::Wscg03 || self.source == PeriodSource::Assumed {
            return self;
        }
        let name = rtl::WSCG03_CHIP;
        let row = self
            .technology
            .and_then(Technology::table)
            .and_then(|(file, text, _)| Table::parse(text, file).ok())
            .and_then(|t| t.periods.get(name).copied());
        let Some(ns) = row else {
            let date05 = self
                .estimate
                .take()
                .unwrap_or_else(|| format!("{}, measured", self.slowest.as_deref().unwrap_or("-")));
            (self.source, self.estimate) = (
                PeriodSource::Estimated,
                Some(format!(
                    "{name} has no row; DATE'05's chip of this configuration stands in ({date05})"
                )),
            );
            return self;
        };
        let built = rtl::wscg03_builds(cfg);
        (self.period_ns, self.slowest, self.not_measured) = (ns, Some(name.into()), vec![]);
        (self.source, self.estimate) = match built {
            true => (PeriodSource::Measured, None),
            false => (PeriodSource::Estimated, Some(format!("{name} stands in for this configuration's WSCG'03 chip (k = {}, format {}): its RTL is built for k = 24 in binary32, T.CHECK to nearest-even", cfg.k, cfg.format))),
        };
        self
    }

    /// One line: the period and where it came from.
    pub fn source(&self) -> String {
        let head = format!("{:.3} ns ({:.1} MHz)", self.period_ns, self.mhz());
        if let Some(why) = &self.assumed {
            return format!("{head}: {why}");
        }
        let what = self
            .technology
            .and_then(Technology::table)
            .map_or("", |t| t.2);
        let missing = if self.not_measured.is_empty() {
            "none".into()
        } else {
            self.not_measured.join(", ")
        };
        let how = match &self.estimate {
            Some(e) => format!("estimated: {e}"),
            None => format!(
                "measured, the whole chip {}",
                self.slowest.as_deref().unwrap_or("-")
            ),
        };
        format!(
            "{head}: {how} ({what}, {}); units not measured: {missing}",
            self.table.unwrap_or("a timing table")
        )
    }
}

#[cfg(test)]
mod tests;
