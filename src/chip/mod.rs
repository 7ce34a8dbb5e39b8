//! The chip's contract: what every level (golden, cycle, rtl, Verilog) agrees on, below all
//! of them. Nothing here computes a value or a clock; the levels import it and it imports
//! none of them.
//!
//! | file | what |
//! |---|---|
//! | [`config`] | a query's chip configuration: k, the formats, the roundings, the triangle cache, with its one [`check`](config::ChipConfig::check) |
//! | [`params`] | the microarchitecture's timing parameters ([`Params`](params::Params), the RTL chip's point [`Params::RTL`](params::Params::RTL)) |
//! | [`memory`] | the memory a query runs against (ideal, DDR SDRAM; WSCG'03's and DATE'05's presets) |
//! | [`preset`] | the papers' chips and the RTL's reset point as whole configurations (`date05`, `wscg03`, `rtl`) |
//! | [`ports`] | the chip's ports per clock and the [`Clocked`](ports::Clocked) interface of every level |
//! | [`probes`] | the traversal signals every level shows (VCDs, lockstep) |
//! | [`reg`] | the host register map, the query's mode and D_CNTR's order, the writes that start a query |
//! | [`layout`] | bit layouts: node and triangle words, the memory image, the port's destinations, D_CNTR's entry |
//! | [`wscg03`] | which paper's chip runs ([`Architecture`](wscg03::Architecture)) and the configuration it runs it in, WSCG'03's timing ([`StackParams`](wscg03::StackParams)) |
//! | [`rtl`] | the RTL chips' sizes and latencies, and the table of the exported chips |
//! | [`timing`] | the clock period of a configuration: the slowest of its RTL units in the timing study's table (OSU 0.18 um, ECP5), or the paper's clock |

pub mod config;
pub mod layout;
pub mod memory;
pub mod params;
pub mod ports;
pub mod preset;
pub mod probes;
pub mod reg;
pub mod rtl;
pub mod timing;
pub mod wscg03;
