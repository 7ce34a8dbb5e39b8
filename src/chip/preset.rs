//! The papers' configurations and the RTL's reset point, each a whole chip: its
//! configuration, timing parameters, memory and clock. A scene names one (`[chip] preset`)
//! and overrides any of its keys; `cchip run --preset` overrides the scene's.

use super::config::ChipConfig;
use super::config::{DopBits, MemLayout};
use super::memory::{Ddr, Memory};
use super::params::Params;
use super::rtl;
use super::wscg03::Architecture;
use serde::{Deserialize, Serialize};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum Preset {
    /// DATE'05's chip: k = 24, binary32, DATE'05's 756-bit DDR2 (its timing our assumption:
    /// DDR2-800 at 5-5-5), the image laid out for the bus (layout "records", 16 node
    /// records held per object) and the memory port at full speed (an issue every clock, 16
    /// requests in flight, 14 pairs prefetched, a credit of 48); the paper's 800 MHz.
    Date05,
    /// DATE'05's chip for bandwidth, as `date05` (k = 24, binary32, its DDR2, the port at full
    /// speed, 800 MHz) but for its memory side: node records of 4-bit codes in treelets of
    /// two levels (`dop_bits = 4`), 64 node records held per object, 128-line triangle caches
    /// on both sides and a leaf pair's triangle words asked for as it enters the leaf FIFO
    /// (`tri_prefetch`): the values measured best on DATE'05's DDR2 at 800 MHz
    /// (docs/explanation/architecture.md, "The chip for bandwidth"). Cycle level only: the RTL
    /// chip of 4-bit codes (`chip_b32_k24_q4`) holds one node record per object, one triangle
    /// word of B and no triangle prefetch.
    Date05Treelets,
    /// WSCG'03's chip (its Stack Engine: architecture "wscg03") on its 4-bank DDR SDRAM on a
    /// 256-bit bus at 266 MHz, A's 128-line triangle cache (§4.3), k = 24 binary32; with
    /// architecture "date05", DATE'05's chip (its port, records and node records as date05's)
    /// on the same memory.
    Wscg03,
    /// The RTL chips' reset values, which the checked-in traces use: the "words" layout, one
    /// request outstanding, issues two clocks apart, a memory word every clock after one
    /// clock; 800 MHz. (The k = 24 binary32 chip also reads layout "records" with one node
    /// record held, on any memory.)
    Rtl,
}

impl Preset {
    /// The memory port at full speed: what the RTL's register `reg::PORT` allows at most but the
    /// credit.
    fn full_port(memory: Memory) -> Params {
        let outstanding = rtl::PORT_OUTSTANDING as u32;
        Params {
            issue_spacing: 1,
            outstanding,
            credit: 48,
            prefetch: rtl::PORT_PREFETCH as u32,
            memory,
            ..Params::RTL
        }
    }

    pub fn chip(self) -> ChipConfig {
        match self {
            Preset::Date05 => ChipConfig {
                layout: MemLayout::Records,
                node_cache: 16,
                ..ChipConfig::default()
            },
            Preset::Date05Treelets => ChipConfig {
                layout: MemLayout::Records,
                node_cache: 64,
                tri_cache: 128,
                tri_cache_b: 128,
                dop_bits: DopBits::Bits(4),
                ..ChipConfig::default()
            },
            Preset::Wscg03 => ChipConfig {
                tri_cache: 128,
                layout: MemLayout::Records,
                node_cache: 16,
                ..ChipConfig::default()
            },
            Preset::Rtl => ChipConfig::default(),
        }
    }

    /// The preset's timing and memory, the memory counted at the paper's clock
    /// ([`clock_ps`](Self::clock_ps)) until a scene or the study sets its own.
    pub fn params(self) -> Params {
        let p = match self {
            Preset::Date05 => Preset::full_port(Memory::Ddr(Ddr::DATE05)),
            Preset::Date05Treelets => Params {
                tri_prefetch: true,
                ..Preset::full_port(Memory::Ddr(Ddr::DATE05))
            },
            Preset::Wscg03 => Preset::full_port(Memory::Ddr(Ddr::WSCG03)),
            Preset::Rtl => Params::RTL,
        };
        Params {
            clock_ps: self.clock_ps(),
            ..p
        }
    }

    /// The chip the preset runs: WSCG'03's Stack Engine for `wscg03`, else DATE'05's D_CNTR.
    pub fn architecture(self) -> Architecture {
        match self {
            Preset::Wscg03 => Architecture::Wscg03,
            Preset::Date05 | Preset::Date05Treelets | Preset::Rtl => Architecture::Date05,
        }
    }

    /// The papers' clocks (DATE'05's target, WSCG'03's memory clock): assumed, not measured.
    pub fn clock_mhz(self) -> f64 {
        match self {
            Preset::Date05 | Preset::Date05Treelets | Preset::Rtl => 800.0,
            Preset::Wscg03 => 266.0,
        }
    }

    /// The paper's clock period in picoseconds, to the picosecond.
    pub fn clock_ps(self) -> u64 {
        super::memory::ps(1000.0 / self.clock_mhz())
    }

    /// The name scenes and the CLI use.
    pub fn name(self) -> &'static str {
        match self {
            Preset::Date05 => "date05",
            Preset::Date05Treelets => "date05-treelets",
            Preset::Wscg03 => "wscg03",
            Preset::Rtl => "rtl",
        }
    }
}
