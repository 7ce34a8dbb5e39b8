//! collision-chip: the hierarchical k-DOP collision-detection accelerator of Zachmann &
//! Knittel (WSCG'03) and Raabe, Bartyzel, Anlauf & Zachmann (DATE'05) at four levels that
//! give one answer: a bit-exact golden model, a fast cycle-exact model, the RTL in rust-hdl
//! (exported as Verilog for Verilator, Icarus, Yosys and FPGA tools), and scenes that run
//! real meshes through them and report what accuracy costs.
//!
//! The modules in layers, each importing only those below (docs/explanation/architecture.md, "Source
//! map"; `tb/layers.rs` checks it): `format`, `pose`, `measure`, `oracle`, `mesh`; [`chip`],
//! the contract every level agrees on; `dop` (normals, trees); [`golden`] (values, one file
//! per unit); `traversal`, `query`, `hard_cases`; [`cycle`] (when things happen); [`rtl`]
//! (the hardware); [`harness`] (host side, Verilog flows); [`scene`]; [`report`].

// A query's entry points take the host's inputs as the papers name them (two images, B's
// setup, order, mode, timing, configuration): a struct bundling them would only rename them.
#![allow(clippy::too_many_arguments)]
// No function over 150 lines (clippy.toml): a longer one is split into named helpers, a long
// rust-hdl kernel into named parts (`rtl::kernel`).
#![deny(clippy::too_many_lines)]

pub mod chip;
pub mod cycle;
pub mod dop;
pub mod fold;
pub mod format;
pub mod golden;
pub mod hard_cases;
pub mod harness;
pub mod measure;
pub mod mesh;
pub mod oracle;
#[cfg(feature = "parry")]
pub mod peer;
pub mod pose;
pub mod query;
pub mod report;
pub mod rtl;
pub mod scene;
pub mod traversal;
