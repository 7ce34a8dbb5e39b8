//! WSCG'03's CollisionChip (§4, Fig. 4) in the contract: which of the two papers' chips a
//! query runs ([`Architecture`]), and the timing of WSCG'03's Stack Engine, DOP Unit and
//! Triangle Unit ([`StackParams`]). Its memory is [`Params::memory`](super::params::Params),
//! shared with DATE'05's chip; the cycle model is [`cycle::wscg03`](crate::cycle).

use super::config::{ChipConfig, DopBits, MemLayout};
use serde::{Deserialize, Serialize};

/// The chip a query runs on: DATE'05's (D_CNTR, one DOP test per clock) or WSCG'03's
/// (the Stack Engine's lists, a tumbled sibling pair transformed once per list).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum Architecture {
    #[default]
    Date05,
    Wscg03,
}

impl Architecture {
    /// The traversal signals its chip shows (VCDs, lockstep checks).
    pub fn probes(self) -> &'static super::probes::Probes {
        match self {
            Architecture::Date05 => &super::probes::DATE05,
            Architecture::Wscg03 => &super::probes::WSCG03,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Architecture::Date05 => "date05",
            Architecture::Wscg03 => "wscg03",
        }
    }

    /// `cfg` as this chip runs it: WSCG'03's memory holds a node pair per record (the
    /// `records` layout of one level, full-precision DOPs) and it has no node cache and one
    /// B triangle line per leaf; DATE'05's runs `cfg` as it is.
    pub fn config(self, cfg: &ChipConfig) -> ChipConfig {
        match self {
            Architecture::Date05 => *cfg,
            Architecture::Wscg03 => ChipConfig {
                layout: MemLayout::Records,
                node_cache: 1,
                dop_bits: DopBits::Full,
                tri_cache_b: 1,
                ..*cfg
            },
        }
    }
}

/// WSCG'03's timing. The paper gives the DOTADD pipeline (§5.2: 6 stages), the on-chip
/// data bus (§4.1: 256 bits, so an aligned DOP against the tumbled pair takes 4 clocks at
/// k = 24, binary32), the Memory Controller's buffer (§4.4: a node pair) and the Triangle
/// Unit's rate (§4.3: a pair every 3 clocks); the RTL's compare bank gives the compare
/// latency, its lists and Memory Controller the SRAM latency; the rest is our assumption (docs/explanation/architecture.md, "WSCG'03's chip").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct StackParams {
    /// Clocks from the Stack Engine's read of a list SRAM to the pointer at the Memory
    /// Controller (the RTL's 2: `ListStack`'s synchronous read, then the ask list's register).
    pub sram_latency: u32,
    /// DOTADD pipeline stages (§5.2: 6); a DOTADD unit writes one transformed d' per clock,
    /// so a tumbled DOP is transformed k + `dotadd_stages` clocks after its word is present.
    pub dotadd_stages: u32,
    /// The DOP Unit's data bus (§4.1: 256 bits): an aligned node word streams through the
    /// 16 compare units in `ceil(node bits / data_bus_bits)` clocks.
    pub data_bus_bits: u32,
    /// Clocks from an aligned DOP's last bundle to its overlap flags at the Stack Engine: the
    /// RTL's compare bank's ([`COMPARE_BANK_LATENCY`](super::rtl::COMPARE_BANK_LATENCY), 2:
    /// the compare units' register, then the flags').
    pub compare_latency: u32,
    /// Node words the Memory Controller asks for ahead of the compare units (§4.4: a node
    /// pair, 2 of our words).
    pub word_buffer: u32,
    /// Clocks between two triangle pairs entering the Triangle Unit (§4.3: 3).
    pub tri_interval: u32,
    /// Clocks from a triangle pair entering the Triangle Unit to its verdict (assumed: 24,
    /// two DOTADD rows of 6 stages each fed for 3 clocks, the ITU's 2 clocks to the first
    /// edge, 3 edges and a verdict register).
    pub tri_latency: u32,
}

impl Default for StackParams {
    fn default() -> Self {
        StackParams::PAPER
    }
}

impl StackParams {
    /// WSCG'03's numbers and our assumptions where it is silent.
    pub const PAPER: StackParams = StackParams {
        sram_latency: 2,
        dotadd_stages: 6,
        data_bus_bits: 256,
        compare_latency: super::rtl::COMPARE_BANK_LATENCY as u32,
        word_buffer: 2,
        tri_interval: 3,
        tri_latency: 24,
    };

    /// Errors name the parameter out of range.
    pub fn check(&self) -> Result<(), String> {
        let at_least_one = [
            ("data_bus_bits", self.data_bus_bits),
            ("compare_latency", self.compare_latency),
            ("word_buffer", self.word_buffer),
            ("tri_interval", self.tri_interval),
            ("tri_latency", self.tri_latency),
        ];
        match at_least_one.iter().find(|(_, v)| *v == 0) {
            Some((n, _)) => Err(format!("[stack_engine] {n} must be at least 1")),
            None => Ok(()),
        }
    }
}
