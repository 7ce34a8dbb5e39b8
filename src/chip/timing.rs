//! The chip's clock period per configuration (issue 32): measured, the slowest of the RTL
//! units the configuration is built from, as the timing study (`scripts/timing-study.sh`)
//! measured them; or the papers' clock, assumed. The study's tables are embedded, so the
//! binary needs no file; they are read by column name (the study may add columns), and a unit
//! without a row is "not measured", named beside the period.

use super::config::ChipConfig;
use super::preset::Preset;
use super::rtl::{self, ChipKind};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Where the period comes from (`[timing] technology`, `cchip run --technology`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum Technology {
    /// OSU 0.18 um standard cells, Yosys + OpenSTA, pre-layout: `docs/figures/timing.csv`.
    #[default]
    Osu018,
    /// Lattice ECP5 (LFE5U-85F), nextpnr-ecp5: `docs/figures/timing_ecp5.csv`.
    Ecp5,
    /// The papers' clock (DATE'05 800 MHz, WSCG'03 266 MHz; [`Preset::clock_mhz`]), assumed.
    Paper,
}

impl Technology {
    /// The measured table: (its file, its text, what it measured).
    fn table(self) -> Option<(&'static str, &'static str, &'static str)> {
        match self {
            Technology::Osu018 => Some(("docs/figures/timing.csv", include_str!("../../docs/figures/timing.csv"), "OSU 0.18 um")),
            Technology::Ecp5 => Some(("docs/figures/timing_ecp5.csv", include_str!("../../docs/figures/timing_ecp5.csv"), "ECP5 LFE5U-85F")),
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
        let unit = col("unit").ok_or_else(|| format!("{file}:1: no `unit` column (re-run scripts/timing-study.sh)"))?;
        // the ASIC table's period, else the FPGA table's (both exact where Fmax is rounded)
        let (period, fmax, area) = (col("min_period_ns").or_else(|| col("period_ns")), col("fmax_mhz"), col("area_um2"));
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
        tech.table().map(|(file, text, _)| Table::parse(text, file)).transpose()
    }

    /// um^2 of the units a configuration changes, its DOP unit and TRI_UNIT, folded as
    /// `folds` (as the area study's cells); `None` unless both are measured.
    pub fn datapath_area_um2(&self, cfg: &ChipConfig, folds: Folds) -> Option<f64> {
        Some(self.areas.get(&dop_unit(cfg, folds.dop))? + self.areas.get(&tri_unit(cfg, folds.tri))?)
    }
}

/// `cfg`'s DOP unit's name ([`rtl::dop_unit_name`]), taking a pair every `dop_interval` clocks.
pub fn dop_unit(cfg: &ChipConfig, dop_interval: u32) -> String {
    rtl::dop_unit_name(cfg.k, cfg.format.dop, cfg.dop_rounding.op(), dop_interval)
}

/// The clocks between the pairs a folded unit takes (1: unfolded): the cycle model's
/// `[timing] tri_interval` and `dop_interval`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Folds {
    pub tri: u32,
    pub dop: u32,
}

impl Folds {
    /// Both units unfolded.
    pub const NONE: Folds = Folds { tri: 1, dop: 1 };
}

impl Default for Folds {
    fn default() -> Folds {
        Folds::NONE
    }
}

/// `cfg`'s TRI_UNIT's name ([`rtl::tri_unit_name`]), taking a pair every `tri_interval` clocks.
pub fn tri_unit(cfg: &ChipConfig, tri_interval: u32) -> String {
    rtl::tri_unit_name(cfg.format.tri, cfg.tri_rounding, tri_interval)
}

/// The RTL units a configuration is built from, by their names in `rtl/` and the timing
/// tables: the DOP datapath's (FP multiplier and adder, DOPTRF lane, DOP unit of k lanes:
/// DATE'05 Eq. 10) in the DOP format and rounding; T.CHECK's (its FP units, the certificate's
/// scaler, T.CHECK, TRI_UNIT: §4.2) in T.CHECK's format and rounding, or the folded TRI_UNIT
/// that takes a pair every `folds.tri` clocks (the DOP unit likewise, `folds.dop`); D_CNTR's pair queue (§4.3); and the whole
/// chip where the RTL builds this configuration. A folded configuration also counts the
/// unfolded chip: the glue the two share (D_CNTR, the memory port, the caches) bounds the
/// folded chip's glue until the folded chip has a row of its own.
pub fn units(cfg: &ChipConfig, folds: Folds) -> Vec<String> {
    let tri_interval = folds.tri;
    let (d, dr) = (rtl::format_tag(cfg.format.dop), rtl::rounding_tag(cfg.dop_rounding.op()));
    let (t, tr) = (rtl::format_tag(cfg.format.tri), rtl::rounding_tag(cfg.tri_rounding));
    let mut u = vec![format!("fp_mul_{d}_{dr}"), format!("fp_add_{d}_{dr}"), format!("doptrf_{d}_{dr}"), dop_unit(cfg, folds.dop)];
    let tcheck = (tri_interval == 1).then(|| format!("tcheck_{t}_{tr}"));
    for name in [format!("fp_mul_{t}_{tr}"), format!("fp_add_{t}_{tr}"), format!("fp_scale_{t}")].into_iter().chain(tcheck).chain([tri_unit(cfg, tri_interval)]) {
        if !u.contains(&name) {
            u.push(name);
        }
    }
    u.push(rtl::PAIR_QUEUE_UNIT.to_string());
    u.push(chip_name(cfg, Folds::NONE));
    if folds != Folds::NONE {
        u.push(chip_name(cfg, folds));
    }
    u
}

/// A folded unit's unfolded counterpart, whose period stands in for the folded unit's where
/// that is not measured: the same FP units and stages without the fold's multiplexers and
/// schedule counter, so a lower bound (measured: TRI_UNIT folded at ii 16, binary32, 8.607 ns
/// against 7.163 unfolded). A fold then never looks faster for want of a measurement.
fn stand_in(cfg: &ChipConfig, folds: Folds, unit: &str) -> Option<String> {
    if folds.tri > 1 && unit == tri_unit(cfg, folds.tri) {
        Some(tri_unit(cfg, 1))
    } else if folds.dop > 1 && unit == dop_unit(cfg, folds.dop) {
        Some(dop_unit(cfg, 1))
    } else {
        None
    }
}

/// The chip's name: the RTL's where it builds `cfg` with `folds`, else as `rtl_chips!`
/// would name it.
fn chip_name(cfg: &ChipConfig, folds: Folds) -> String {
    match (ChipKind::of(cfg, folds.dop, folds.tri), folds) {
        (Some(kind), _) => kind.name().to_string(),
        (None, Folds { dop: 1, tri: 1 }) => format!("chip_{}", cfg_tag(cfg)),
        (None, Folds { dop: 1, tri }) => format!("chip_{}_fold{tri}", cfg_tag(cfg)),
        (None, Folds { dop, tri }) => format!("chip_{}_dop{dop}_tri{tri}", cfg_tag(cfg)),
    }
}

/// A chip's name for a configuration the RTL does not build (as `rtl_chips!` names them).
fn cfg_tag(cfg: &ChipConfig) -> String {
    let (d, t) = (rtl::format_tag(cfg.format.dop), rtl::format_tag(cfg.format.tri));
    if d == t { format!("{d}_k{}", cfg.k) } else { format!("{d}_{t}_k{}", cfg.k) }
}

/// The clock a report runs at, and where it came from.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Clock {
    pub period_ns: f64,
    pub technology: Option<Technology>,
    /// Measured: the table's file, the slowest measured unit, the units with no row.
    pub table: Option<&'static str>,
    pub slowest: Option<String>,
    pub not_measured: Vec<String>,
    /// Assumed: why (the scene's `clock_mhz`, the preset's paper clock).
    pub assumed: Option<String>,
}

impl Clock {
    pub fn mhz(&self) -> f64 {
        1000.0 / self.period_ns
    }

    /// An assumed clock of `mhz`, `why`.
    pub fn assumed(mhz: f64, why: String) -> Clock {
        Clock { period_ns: 1000.0 / mhz, technology: None, table: None, slowest: None, not_measured: vec![], assumed: Some(why) }
    }

    /// The configuration's period in `tech` with its units folded as `folds`: the slowest of its measured [`units`] (or the preset's paper clock). An error
    /// if the table measured none of them.
    pub fn of(tech: Technology, cfg: &ChipConfig, folds: Folds, preset: Preset) -> Result<Clock, String> {
        let Some((file, text, what)) = tech.table() else {
            let mut c = Clock::assumed(preset.clock_mhz(), format!("the paper's {} MHz (preset {}), assumed", preset.clock_mhz(), preset.name()));
            c.technology = Some(tech);
            return Ok(c);
        };
        let table = Table::parse(text, file)?;
        let mut c = Clock::measured(&table, cfg, folds).ok_or_else(|| {
            format!("{file} ({what}) measures none of this configuration's units ({}): run scripts/timing-study.sh, or set [timing] technology = \"paper\" or clock_mhz", units(cfg, folds).join(", "))
        })?;
        (c.technology, c.table) = (Some(tech), Some(file));
        Ok(c)
    }

    /// The configuration's chip's period where `table` measured that chip (its units as it
    /// builds them, the control and the paths between them: the chip as built, whose units a
    /// lone unit's row only approximates, as the flow maps it apart); else the slowest of
    /// `cfg`'s units that `table` measured, the others named as not measured.
    pub fn measured(table: &Table, cfg: &ChipConfig, folds: Folds) -> Option<Clock> {
        let chip = chip_name(cfg, folds);
        if let Some(&ns) = table.periods.get(&chip) {
            return Some(Clock { period_ns: ns, technology: None, table: None, slowest: Some(chip), not_measured: vec![], assumed: None });
        }
        let (mut slowest, mut not_measured) = (None::<(String, f64)>, vec![]);
        for u in units(cfg, folds) {
            let own = table.periods.get(&u).map(|&ns| (u.clone(), ns));
            if own.is_none() {
                not_measured.push(u.clone());
            }
            let stood = || stand_in(cfg, folds, &u).and_then(|s| table.periods.get(&s).map(|&ns| (format!("{s} (for {u})"), ns)));
            if let Some((name, ns)) = own.or_else(stood) {
                if slowest.as_ref().is_none_or(|s| ns > s.1) {
                    slowest = Some((name, ns));
                }
            }
        }
        let (unit, ns) = slowest?;
        Some(Clock { period_ns: ns, technology: None, table: None, slowest: Some(unit), not_measured, assumed: None })
    }

    /// One line: the period and where it came from.
    pub fn source(&self) -> String {
        let head = format!("{:.3} ns ({:.1} MHz)", self.period_ns, self.mhz());
        if let Some(why) = &self.assumed {
            return format!("{head}: {why}");
        }
        let what = self.technology.and_then(Technology::table).map_or("", |t| t.2);
        let missing = if self.not_measured.is_empty() { "none".into() } else { self.not_measured.join(", ") };
        format!(
            "{head}: measured, {what}, {}, slowest unit {}; units not measured: {missing}",
            self.table.unwrap_or("a timing table"),
            self.slowest.as_deref().unwrap_or("-")
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chip::config::{DopRounding, Formats};
    use crate::format::Format;

    /// A configuration's period is the largest of its units' in a hand-written table; units of
    /// other formats and roundings do not count; absent ones are named.
    #[test]
    fn period_is_the_slowest_unit_of_the_configuration() {
        let text = "unit,cells,min_period_ns,extra\n\
                    fp_mul_e8m15_ru,1,6.5,x\n\
                    fp_add_e8m15_ru,1,7.0,x\n\
                    fp_mul_e8m15_rne,1,5.0,x\n\
                    fp_add_e8m15_rne,1,8.0,x\n\
                    doptrf_b32_ru,1,30.0,x\n\
                    pair_queue_n4,1,4.0,x\n\
                    tcheck_e8m15_rne,1,,x\n";
        let t = Table::parse(text, "t.csv").unwrap();
        let cfg = ChipConfig { k: 6, format: Formats::from(Format::REDUCED), dop_rounding: DopRounding::Outward, ..Default::default() };
        let c = Clock::measured(&t, &cfg, Folds::NONE).unwrap();
        // DOP: mul 6.5, add 7.0 (ru); T.CHECK: add 8.0 (rne); queue 4.0; b32's 30 not ours
        assert_eq!((c.period_ns, c.slowest.as_deref()), (8.0, Some("fp_add_e8m15_rne")));
        assert!(c.not_measured.contains(&"tcheck_e8m15_rne".to_string()) && c.not_measured.contains(&"chip_e8m15_k6".to_string()));
        assert!(!c.not_measured.iter().any(|u| u.starts_with("fp_mul") || u.starts_with("fp_add")), "{:?}", c.not_measured);
        // columns found by name, in any order; Fmax where no period is given
        let t = Table::parse("fmax_mhz,unit\n125,pair_queue_n4\n", "t.csv").unwrap();
        assert_eq!(Clock::measured(&t, &cfg, Folds::NONE).unwrap().period_ns, 8.0);
        // the FPGA table's `period_ns` where there is no `min_period_ns`: exact, its Fmax rounded
        let t = Table::parse("unit,fmax_mhz,period_ns\npair_queue_n4,23.1,43.214\n", "t.csv").unwrap();
        assert_eq!(Clock::measured(&t, &cfg, Folds::NONE).unwrap().period_ns, 43.214);
        assert!(Clock::measured(&Table::parse("unit,min_period_ns\nfp_mul_b32_ru,3\n", "t").unwrap(), &cfg, Folds::NONE).is_none());
        // the whole chip, where measured, is the period, slower or faster than a lone unit
        // (the chip maps its units as it builds them): its control and the paths between
        // units count
        for chip_ns in [9.0, 7.0] {
            let t = Table::parse(&format!("unit,min_period_ns\nfp_add_e8m15_rne,8\nchip_e8m15_k6,{chip_ns}\n"), "t").unwrap();
            let c = Clock::measured(&t, &cfg, Folds::NONE).unwrap();
            assert_eq!((c.period_ns, c.slowest.as_deref()), (chip_ns, Some("chip_e8m15_k6")));
        }
    }

    #[test]
    fn bad_tables_name_file_and_line() {
        assert!(Table::parse("name,min_period_ns\n", "t.csv").unwrap_err().starts_with("t.csv:1:"));
        assert!(Table::parse("unit,cells\n", "t.csv").unwrap_err().contains("min_period_ns"));
        assert!(Table::parse("unit,min_period_ns\na,1\nb,-3\n", "t.csv").unwrap_err().starts_with("t.csv:3:"));
    }

    /// A folded configuration counts the folded TRI_UNIT, not T.CHECK or the unfolded
    /// TRI_UNIT, and both the unfolded chip (its glue) and the folded one.
    #[test]
    fn a_folded_configuration_counts_the_folded_unit_and_both_chips() {
        let cfg = ChipConfig { k: 6, format: Formats::from(Format::REDUCED), dop_rounding: DopRounding::Outward, ..Default::default() };
        let u = units(&cfg, Folds { tri: 16, dop: 1 });
        for name in ["tri_unit_fold16_e8m15_rne", "chip_e8m15_k6", "chip_e8m15_k6_fold16"] {
            assert!(u.contains(&name.to_string()), "{name} not in {u:?}");
        }
        assert!(!u.iter().any(|n| n == "tcheck_e8m15_rne" || n == "tri_unit_e8m15_rne"), "{u:?}");
        let t = Table::parse("unit,min_period_ns
tri_unit_e8m15_rne,20
tri_unit_fold16_e8m15_rne,9
chip_e8m15_k6,8
", "t").unwrap();
        let c = Clock::measured(&t, &cfg, Folds { tri: 16, dop: 1 }).unwrap();
        assert_eq!((c.period_ns, c.slowest.as_deref()), (9.0, Some("tri_unit_fold16_e8m15_rne")));
        assert!(c.not_measured.contains(&"chip_e8m15_k6_fold16".to_string()), "{:?}", c.not_measured);
        // the folded unit not measured: the unfolded one's period stands in, a lower bound
        let t = Table::parse("unit,min_period_ns\ntri_unit_e8m15_rne,20\nchip_e8m15_k6,8\n", "t").unwrap();
        let c = Clock::measured(&t, &cfg, Folds { tri: 16, dop: 1 }).unwrap();
        assert_eq!((c.period_ns, c.slowest.as_deref()), (20.0, Some("tri_unit_e8m15_rne (for tri_unit_fold16_e8m15_rne)")));
        assert!(c.not_measured.contains(&"tri_unit_fold16_e8m15_rne".to_string()), "{:?}", c.not_measured);
        assert!(units(&cfg, Folds { tri: 1, dop: 6 }).contains(&"dop_unit_fold6_k6_e8m15_ru".to_string()));
        assert_eq!(units(&cfg, Folds { tri: 8, dop: 1 }).iter().filter(|n| n.starts_with("chip_")).collect::<Vec<_>>(), ["chip_e8m15_k6", "chip_e8m15_k6_fold8"]);
        let both = units(&cfg, Folds { tri: 32, dop: 6 });
        assert_eq!(both.iter().filter(|n| n.starts_with("chip_")).collect::<Vec<_>>(), ["chip_e8m15_k6", "chip_e8m15_k6_dop6_tri32"]);
        assert!(both.contains(&"dop_unit_fold6_k6_e8m15_ru".to_string()) && both.contains(&"tri_unit_fold32_e8m15_rne".to_string()), "{both:?}");
    }

    /// The checked-in tables parse, and the paper clock is the preset's.
    #[test]
    fn technologies() {
        let cfg = ChipConfig::default();
        let osu = Clock::of(Technology::Osu018, &cfg, Folds::NONE, Preset::Rtl).unwrap();
        assert!(osu.source().contains("docs/figures/timing.csv"), "{}", osu.source());
        // the routed ECP5 chip's row is its configuration's clock
        let (k6, folds) = (ChipKind::K6E8m15Dop6Tri32.config(), Folds { dop: 6, tri: 32 });
        let ecp5 = Clock::of(Technology::Ecp5, &k6, folds, Preset::Rtl).unwrap();
        assert_eq!(ecp5.slowest.as_deref(), Some("chip_e8m15_k6_dop6_tri32"));
        let paper = Clock::of(Technology::Paper, &cfg, Folds::NONE, Preset::Wscg03).unwrap();
        assert_eq!(paper.mhz(), 266.0);
        assert!(paper.source().contains("assumed"));
    }
}
