//! The harness around the RTL blocks of [`crate::rtl`] (which holds blocks only, as the
//! Verilog they export): the registry of exported units with their golden vectors
//! ([`units`]), Verilog module merging ([`verilog`]), operand and vector encodings and
//! vector-file drivers ([`tri_io`], [`sim`]), and the chip's host side ([`chip_io`]: memory
//! image, register writes, the rust-hdl chip as a level of the shared driver
//! [`crate::cycle::drive`], the query set).

pub mod chip_io;
pub mod sim;
pub mod tri_io;
pub mod units;
pub mod verilator;
pub mod verilog;
pub mod wscg03_io;
