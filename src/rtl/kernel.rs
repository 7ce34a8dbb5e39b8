//! A long kernel written as named parts.
//!
//! rust-hdl's `#[hdl_gen]` translates one `update` body into one `always @(*)` block and
//! allows no calls to other functions inside it. A block whose kernel would be long writes
//! it in parts instead: each part is an `#[hdl_gen] fn update` in `impl
//! crate::rtl::kernel::Kernel<Part> for Block` (the trait by its path, never imported: the
//! `LogicBlock` derive calls `self.update()`, which must find `Logic`'s alone), `Part` a
//! marker type named after what that part decides, and
//! `kernel!([generics] Block: PartA, PartB, ...)` implements `Logic` by running the parts
//! in that order and joining their statements into the one block a single kernel would
//! give. The exported Verilog is the same as the unsplit kernel's, byte for byte.

use rust_hdl::prelude::*;

/// One part of a block's kernel; `#[hdl_gen]` on its `update` writes `connect` and `hdl`.
pub(crate) trait Kernel<Part> {
    fn update(&mut self);
    fn connect(&mut self);
    fn hdl(&self) -> Verilog;
}

/// The parts' statements in order, as one combinational block.
pub(crate) fn join(parts: Vec<Verilog>) -> Verilog {
    let mut all = Vec::new();
    for part in parts {
        match part {
            Verilog::Combinatorial(block) => all.extend(block),
            _ => unreachable!("#[hdl_gen] writes a combinational block"),
        }
    }
    Verilog::Combinatorial(all)
}

/// `impl Logic` for a block whose kernel is the listed parts, run in order.
macro_rules! kernel {
    ([$($g:tt)*] $block:ty: $($part:ty),+ $(,)?) => {
        impl<$($g)*> Logic for $block {
            fn update(&mut self) {
                $(<Self as $crate::rtl::kernel::Kernel<$part>>::update(self);)+
            }
            fn connect(&mut self) {
                $(<Self as $crate::rtl::kernel::Kernel<$part>>::connect(self);)+
            }
            fn hdl(&self) -> Verilog {
                $crate::rtl::kernel::join(vec![
                    $(<Self as $crate::rtl::kernel::Kernel<$part>>::hdl(self)),+
                ])
            }
        }
    };
}
pub(crate) use kernel;
