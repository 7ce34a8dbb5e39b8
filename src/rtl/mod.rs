//! RTL of the chip's datapath in rust-hdl 0.46 (integer logic only; Verilog by
//! `generate_verilog`).
//!
//! Pipelined floating-point units and the DOP datapath built from them, one concrete set of
//! types per number format (stable Rust has no const-generic arithmetic, so the blocks are
//! stamped out by macros with literal widths):
//!
//! | module | format | units |
//! |---|---|---|
//! | [`b32`] | `binary32` (e8m23, [`Format::BINARY32`](crate::format::Format::BINARY32)) | [`b32::FpMul`] (latency 4), [`b32::FpAdd`] (latency 3), [`b32::FpScale`] (by a constant, latency 4), [`b32::FpCmp`] (WSCG'03's compare unit, latency 1), [`b32::Doptrf`] (latency 15), [`b32::Dotadd`] (WSCG'03's DOTADD unit, latency 12), [`b32::KlmSel`], [`b32::DopUnit6`] ... [`b32::DopUnit26`] (k = 6, 14, 18, 24, 26; latency 15), the folded [`b32::DopUnit6Fold2`] ... [`b32::DopUnit24Fold24`] (a pair every ii clocks; latency 14 + ii); in binary32 only, WSCG'03's compare bank [`b32::CompareBank`] (latency 2), d' memory [`b32::DprimeMemory`] and DOP Unit [`b32::Wscg03DopUnit`] |
//! | [`e8m15`] | e8m15 ([`Format::REDUCED`](crate::format::Format::REDUCED)) | the same |
//! | [`e8m15_b32`] | e8m15 DOP unit, binary32 TRI_UNIT | the k = 24 chip only |
//! | [`e8m10`] | e8m10 ([`Format::E8M10`](crate::format::Format::E8M10)) | the same, and the k = 24 chip |
//! | [`e8m15_k24`] | e8m15 DOP unit and TRI_UNIT | the k = 24 chip only |
//! | [`e8m15_fold16`] | e8m15, TRI_UNIT folded (a pair every 16 clocks) | the k = 6 chip only |
//! | [`e8m15_dop6_tri32`] | e8m15, the DOP unit folded (a pair every 6 clocks) and TRI_UNIT (every 32) | the k = 6 chip only |
//!
//! [`b32`] and [`e8m15`] also hold the folded units, built from `crate::fold`'s
//! plans: `TCheckFold` and `TriUnitFold` (both directions on one `TCheckFold`).
//!
//! Each unit takes one operation per clock with a `valid` bit travelling alongside and
//! is bit-exact with the golden [`Format`](crate::format::Format) operations in its
//! rounding (NearestEven or TowardPositive: fixed at construction, or in the DOP lanes an
//! input that travels with each operation, [`RoundUp`]), including subnormals, infinities,
//! canonical NaN, IEEE overflow and zero signs.
//!
//! Ports (`W` = 32 for `b32`, 24 for `e8m15`):
//!
//! * `FpMul`: in `clock`, `a[W]`, `b[W]`, `valid_in`; out `y[W]`, `valid_out`.
//! * `FpAdd`: in `clock`, `a[W]`, `b[W]`, `sub` (1: `a - b`), `valid_in`;
//!   out `y[W]`, `valid_out`.
//!
//! Signal naming inside a unit: `sK_*` are the registers closing pipeline stage K (as
//! `DFF`s, `sK_x$q` in Verilog / VCD), `cK_*` the combinational signals of stage K, and
//! sub-blocks by role (`unpack_a`, `norm_a`, `sig_mul`, `round`).

/// A block ready to simulate as a top level: its inputs claimed (`connect`), then
/// `connect_all`.
macro_rules! top_level {
    ($uut:expr; $($port:ident),+) => {{
        let mut uut = $uut;
        $(uut.$port.connect();)+
        uut.connect_all();
        uut
    }};
}

mod chip;
mod common;
pub use common::{round_up, RoundUp};
pub mod d_cntr;
pub mod delay;
mod dop_decode;
mod dop_unit;
mod dop_unit_fold;
mod doptrf;
mod event_counter;
mod fp_add;
mod fp_add_fpga;
mod fp_cmp;
mod fp_mul;
mod fp_mul_fpga;
mod fp_scale;
mod kernel;
mod klmsel;
mod lzc;
pub use lzc::Lzc;
mod memory_port;
mod reg_ring;
mod tcheck;
mod tcheck_fold;
mod tri_cache;
mod tri_unit;
mod tri_unit_fold;
pub mod wscg03;
/// The result port, TRI_UNIT's read side in the chip (format-free: not stamped per format).
pub use tri_unit::ResultPort;

/// Stamps out one format's units plus constructors and Verilog export.
macro_rules! fp_format {
    ($fmt:expr, $W:tt, $WM1:tt, $E:tt, $F:tt, $P:tt, $P2:tt, $P3:tt, $P4:tt, $PP:tt, $S:tt,
     norm_p($($np:tt),*), norm_p3($($nq:tt),*), mul_split($PM2:tt, $H:tt, $HH:tt, $H2:tt)) => {
        use crate::format::{Format, Rounding};

        $crate::rtl::common::fp_common!($W, $WM1, $E, $F, $P, $P2, $P3, $P4, $PP, norm_p($($np),*), norm_p3($($nq),*));
        $crate::rtl::fp_mul::fp_mul!($W, $E, $F, $P, $P2);
        $crate::rtl::fp_add::fp_add!($W, $WM1, $E, $F, $P, $P2, $P3, $P4);
        $crate::rtl::fp_mul_fpga::fp_mul_fpga!($W, $E, $F, $P, $P2, $PP, $PM2, $H, $HH, $H2);
        $crate::rtl::fp_add_fpga::fp_add_fpga!($W, $WM1, $E, $F, $P, $P2, $P3, $P4);
        $crate::rtl::fp_scale::fp_scale!($W, $E, $F, $S);
        $crate::rtl::fp_cmp::fp_cmp!($W, $WM1, $E, $F);
        $crate::rtl::doptrf::doptrf!($W, $WM1, $E, $F);
        $crate::rtl::klmsel::klmsel!($W);
        $crate::rtl::dop_unit::dop_unit!($W);
        $crate::rtl::dop_unit_fold::dop_unit_fold!($W);
        $crate::rtl::tcheck::tcheck!($W, $WM1, $E, $F);
        $crate::rtl::tri_unit::tri_unit!($W);

        /// The golden format these units implement.
        pub const FORMAT: Format = $fmt;
        /// Word width in bits.
        pub const WIDTH: usize = $W;

        /// A multiplier ready to simulate as a top-level block (inputs claimed, connected).
        pub fn fp_mul_top(rounding: Rounding) -> FpMul {
            top_level!(FpMul::new(rounding); clock, a, b, valid_in)
        }

        /// An adder ready to simulate as a top-level block (inputs claimed, connected).
        pub fn fp_add_top(rounding: Rounding) -> FpAdd {
            top_level!(FpAdd::new(rounding); clock, a, b, sub, valid_in)
        }

        /// A constant multiplier ready to simulate as a top-level block: T.CHECK's C_V
        /// for rounded (`sel` 0) and exact (`sel` 1) vertices.
        pub fn fp_scale_top() -> FpScale {
            let cert = $crate::golden::certificate::Certificate::new(FORMAT, Rounding::NearestEven);
            top_level!(FpScale::new(cert.c_e[0], cert.c_e[1]); clock, a, sel)
        }

        /// Verilog of [`fp_scale_top`] (top module `top`).
        pub fn verilog_fp_scale() -> String {
            generate_verilog(&fp_scale_top())
        }

        /// A compare unit ready to simulate as a top-level block (inputs claimed, connected).
        pub fn fp_cmp_top() -> FpCmp {
            top_level!(FpCmp::new(); clock, a, b, valid_in)
        }

        /// Verilog of [`fp_cmp_top`] (top module `top`).
        pub fn verilog_fp_cmp() -> String {
            generate_verilog(&fp_cmp_top())
        }

        /// Verilog of the multiplier (top module `top`).
        pub fn verilog_fp_mul(rounding: Rounding) -> String {
            generate_verilog(&fp_mul_top(rounding))
        }

        /// Verilog of the adder (top module `top`).
        pub fn verilog_fp_add(rounding: Rounding) -> String {
            generate_verilog(&fp_add_top(rounding))
        }

        /// The multiplier at FPGA depth ready to simulate as a top-level block.
        pub fn fp_mul_fpga_top(rounding: Rounding) -> FpMulFpga {
            top_level!(FpMulFpga::new(rounding); clock, a, b, valid_in)
        }

        /// The adder at FPGA depth ready to simulate as a top-level block.
        pub fn fp_add_fpga_top(rounding: Rounding) -> FpAddFpga {
            top_level!(FpAddFpga::new(rounding); clock, a, b, sub, valid_in)
        }

        /// Verilog of the multiplier at FPGA depth (top module `top`).
        pub fn verilog_fp_mul_fpga(rounding: Rounding) -> String {
            generate_verilog(&fp_mul_fpga_top(rounding))
        }

        /// Verilog of the adder at FPGA depth (top module `top`).
        pub fn verilog_fp_add_fpga(rounding: Rounding) -> String {
            generate_verilog(&fp_add_fpga_top(rounding))
        }
    };
}

/// Units for `binary32` (e8m23).
pub mod b32 {
    fp_format!(
        Format::BINARY32,
        32,
        31,
        8,
        23,
        24,
        26,
        27,
        28,
        48,
        50,
        norm_p(8, 16, 20, 22, 23),
        norm_p3(11, 19, 23, 25, 26),
        mul_split(22, 12, 12, 24)
    );
    // the papers' chip: node word 1 + 24 * 32 + 64 bits (wider than a triangle word, 23 * 32 + 2)
    crate::rtl::chip::chip!(
        24,
        DopUnit24 = DopUnit24::new,
        TriUnit = TriUnit::new,
        32,
        32,
        32,
        833,
        738,
        2048,
        1666,
        2
    );
    crate::rtl::tcheck_fold::tcheck_fold!(32, 31, 8, 23);
    crate::rtl::tri_unit_fold::tri_unit_fold!(32);
    // WSCG'03's chip is binary32 (its 256-bit bus: bundles of eight coefficients)
    crate::rtl::wscg03::dop_unit::compare_bank!(32, 256;
        (cmp_l0 cmp_r0 0 0) (cmp_l1 cmp_r1 1 32) (cmp_l2 cmp_r2 2 64) (cmp_l3 cmp_r3 3 96)
        (cmp_l4 cmp_r4 4 128) (cmp_l5 cmp_r5 5 160) (cmp_l6 cmp_r6 6 192) (cmp_l7 cmp_r7 7 224));
    crate::rtl::wscg03::dop_unit::dprime_memory!(32, 256;
        (ram_l0 ram_r0 0 0) (ram_l1 ram_r1 1 32) (ram_l2 ram_r2 2 64) (ram_l3 ram_r3 3 96)
        (ram_l4 ram_r4 4 128) (ram_l5 ram_r5 5 160) (ram_l6 ram_r6 6 192) (ram_l7 ram_r7 7 224));
    crate::rtl::wscg03::dop_unit::wscg03_dop_unit!(32, 256;
        (0 0) (1 32) (2 64) (3 96) (4 128) (5 160) (6 192) (7 224));
    // WSCG'03's Triangle Unit's input stage, on the chip's triangle cache (`TriCache`)
    crate::rtl::wscg03::tri_unit::tri_input!(738);
    // WSCG'03's Memory Controller: records of two node words of 1 + 24 * 32 + 64 bits
    crate::rtl::wscg03::memory_controller::memory_controller!(2048, 833, 738, 769);
    const _: () = assert!(
        crate::chip::layout::record_bits(24, 32, 32) == 2048
            && crate::chip::layout::node_bits(24, 32) == 833
            && crate::chip::layout::tri_bits(32) == 738
    );
    // the decode stage of 4-bit stored DOPs (`date05-treelets`): exponents -149 ..= 124, 9 bits
    crate::rtl::dop_decode::dop_decode!(32, 23, 4, 9);
    crate::rtl::dop_decode::dop_unit_coded!(32, 4, 9);
}

/// The papers' chip reading records of 4-bit stored DOPs (`dop_bits = 4`): binary32, k = 24,
/// its DOP unit behind the decode stage (`DopUnitCoded24`). A record: two tree levels, 6 node
/// words of 1 + 24 * 4 + 64 bits, then the treelet root's 24 distances (32 bits) and
/// exponents (9 bits): 1,950 bits of a 2,048-bit word.
pub mod b32_q4 {
    use super::b32::{DopUnitCoded24, TriUnit};
    use crate::format::Rounding;
    use rust_hdl::prelude::*;
    crate::rtl::chip::chip!(
        24,
        DopUnitCoded24 = DopUnitCoded24::new,
        TriUnit = TriUnit::new,
        32,
        32,
        4,
        161,
        738,
        2048,
        1950,
        6;
        coded 9, 984
    );
}

/// Units for e8m15 (`Format::REDUCED`).
pub mod e8m15 {
    fp_format!(
        Format::REDUCED,
        24,
        23,
        8,
        15,
        16,
        18,
        19,
        20,
        32,
        34,
        norm_p(0, 8, 12, 14, 15),
        norm_p3(3, 11, 15, 17, 18),
        mul_split(14, 8, 8, 16)
    );
    // node word 1 + 6 * 24 + 64 bits, triangle word 23 * 24 + 2
    crate::rtl::chip::chip!(
        6,
        DopUnit6 = DopUnit6::new,
        TriUnit = TriUnit::new,
        24,
        24,
        24,
        209,
        554,
        554,
        209,
        1
    );
    crate::rtl::tcheck_fold::tcheck_fold!(24, 23, 8, 15);
    crate::rtl::tri_unit_fold::tri_unit_fold!(24);
    crate::rtl::tcheck_fold::tcheck_fold!(fpga 24, 23, 8, 15);
    crate::rtl::tri_unit_fold::tri_unit_fold!(fpga 24);
}

/// Units for e8m10 ([`Format::E8M10`](crate::format::Format::E8M10)), the narrowest format
/// of the study: significands of 11 bits, so the normalisers shift in four steps.
pub mod e8m10 {
    fp_format!(
        Format::E8M10,
        19,
        18,
        8,
        10,
        11,
        13,
        14,
        15,
        22,
        24,
        norm_p(3, 7, 9, 10),
        norm_p3(6, 10, 12, 13),
        mul_split(9, 6, 5, 12)
    );
    // the papers' chip (k = 24) in e8m10: node word 1 + 24 * 19 + 64 bits (wider than a
    // triangle word, 23 * 19 + 2); a memory word holds a record of two (the `records`
    // layout), 1,042 bits padded to 2,048
    crate::rtl::chip::chip!(
        24,
        DopUnit24 = DopUnit24::new,
        TriUnit = TriUnit::new,
        19,
        19,
        19,
        521,
        439,
        2048,
        1042,
        2
    );
}

/// The papers' chip (k = 24) in e8m15 throughout (format `reduced`): e8m15's k = 24 DOP unit
/// and TRI_UNIT. A node word is 641 bits, a triangle word 554 (25% less than binary32's).
pub mod e8m15_k24 {
    use super::e8m15::{DopUnit24, TriUnit};
    use crate::format::Rounding;
    use rust_hdl::prelude::*;
    // node word 1 + 24 * 24 + 64 bits (wider than a triangle word, 23 * 24 + 2); a memory
    // word holds a record of two (the `records` layout), 2,048 bits
    crate::rtl::chip::chip!(
        24,
        DopUnit24 = DopUnit24::new,
        TriUnit = TriUnit::new,
        24,
        24,
        24,
        641,
        554,
        2048,
        1282,
        2
    );
}

/// The papers' chip with the DOP datapath in e8m15 and T.CHECK in binary32 (format
/// `e8m15/binary32`): e8m15's k = 24 DOP unit, binary32's TRI_UNIT. A node word is 641 bits
/// instead of 833 (23% less node traffic); the DOP test stays conservative (outward
/// rounding), the triangle test keeps binary32's verdicts.
pub mod e8m15_b32 {
    use super::b32::TriUnit;
    use super::e8m15::DopUnit24;
    use crate::format::Rounding;
    use rust_hdl::prelude::*;
    // node word 1 + 24 * 24 + 64 bits, triangle word 23 * 32 + 2; a memory word holds a
    // record of two node words, 2,048 bits
    crate::rtl::chip::chip!(
        24,
        DopUnit24 = DopUnit24::new,
        TriUnit = TriUnit::new,
        24,
        32,
        24,
        641,
        738,
        2048,
        1282,
        2
    );
}

/// The k = 6 e8m15 chip with its TRI_UNIT folded: e8m15's DOP unit and e8m15's
/// `TriUnitFold`, a pair every `ChipKind::K6E8m15Fold16.tri_interval()` = 16 clocks on one
/// T.CHECK folded for 8 (docs/explanation/architecture.md, "Folded TRI_UNIT").
pub mod e8m15_fold16 {
    use super::e8m15::{DopUnit6, TriUnitFold};
    use crate::chip::rtl::ChipKind;
    use crate::format::Rounding;
    use rust_hdl::prelude::*;

    /// TRI_UNIT folded to the chip's interval, T.CHECK rounding with `r`.
    fn tri_unit(r: Rounding) -> TriUnitFold {
        let ii = ChipKind::K6E8m15Fold16.tri_interval() as usize;
        TriUnitFold::new(
            crate::fold::tri_unit_plan(
                ii,
                crate::fold::plan::Binding::Shared,
                crate::chip::rtl::Depth::Asic,
            )
            .expect("the chip's interval is even"),
            r,
        )
    }
    // node word 1 + 6 * 24 + 64 bits, triangle word 23 * 24 + 2
    crate::rtl::chip::chip!(
        6,
        DopUnit6 = DopUnit6::new,
        TriUnitFold = tri_unit,
        24,
        24,
        24,
        209,
        554,
        554,
        209,
        1
    );
}

/// The k = 6 e8m15 chip with both units folded, small enough for an ECP5
/// LFE5U-85F: the DOP unit on one DOPTRF lane, a pair every
/// `ChipKind::K6E8m15Dop6Tri32.dop_interval()` = 6 clocks (`DopUnit6Fold6`, its `in_ready`
/// gating D_CNTR's issue), and TRI_UNIT a pair every `tri_interval()` = 32 clocks on one
/// T.CHECK folded for 16 (docs/explanation/architecture.md, "A chip on the folded DOP unit").
pub mod e8m15_dop6_tri32 {
    use super::e8m15::{DopFold, FoldedDop, TriUnitFold};
    use crate::chip::rtl::ChipKind;
    use crate::format::Rounding;
    use rust_hdl::prelude::*;

    const KIND: ChipKind = ChipKind::K6E8m15Dop6Tri32;
    /// The DOP unit folded to the chip's interval.
    pub type DopUnit = <DopFold<6, { KIND.dop_interval() as usize }> as FoldedDop>::Unit;

    /// TRI_UNIT folded to the chip's interval, T.CHECK rounding with `r`, its registers
    /// bound per reader (`Binding::PerReader`: for the FPGA's router).
    fn tri_unit(r: Rounding) -> TriUnitFold {
        let plan = crate::fold::tri_unit_plan(
            KIND.tri_interval() as usize,
            crate::fold::plan::Binding::PerReader,
            crate::chip::rtl::Depth::Asic,
        );
        TriUnitFold::new(plan.expect("the chip's interval is even"), r)
    }
    // node word 1 + 6 * 24 + 64 bits, triangle word 23 * 24 + 2
    crate::rtl::chip::chip!(6, DopUnit = DopUnit::new => in_ready, TriUnitFold = tri_unit, 24, 24, 24, 209, 554, 554, 209, 1);
}

/// The FPGA chip: `e8m15_dop6_tri32` at FPGA depth (`Depth::Fpga`), for an ECP5 LFE5U-85F:
/// the DOP unit on one DOPTRF lane of `FpMulFpga` and `FpAddFpga` (`DopUnit6Fold6Fpga`),
/// TRI_UNIT on one T.CHECK folded for 16 at FPGA depth (`TriUnitFoldFpga`: its operands
/// registered, each unit on its own copy of the counter, its registers per reader).
pub mod e8m15_dop6_tri32_fpga {
    use super::e8m15::{DopUnit6Fold6Fpga, TriUnitFoldFpga};
    use crate::chip::rtl::ChipKind;
    use crate::format::Rounding;
    use rust_hdl::prelude::*;

    const KIND: ChipKind = ChipKind::K6E8m15Dop6Tri32Fpga;

    /// TRI_UNIT folded to the chip's interval at its depth, T.CHECK rounding with `r`.
    fn tri_unit(r: Rounding) -> TriUnitFoldFpga {
        let plan = crate::fold::tri_unit_plan(
            KIND.tri_interval() as usize,
            crate::fold::plan::Binding::PerReader,
            KIND.depth(),
        );
        TriUnitFoldFpga::new(plan.expect("the chip's interval is even"), r)
    }
    // node word 1 + 6 * 24 + 64 bits, triangle word 23 * 24 + 2
    crate::rtl::chip::chip!(6, DopUnit6Fold6Fpga = DopUnit6Fold6Fpga::new => in_ready, TriUnitFoldFpga = tri_unit, 24, 24, 24, 209, 554, 554, 209, 1);
}

// The contract's widths and latencies (`crate::chip`) are what the blocks are built with: the
// chip! macros take literals, so each is checked here.
/// The RTL's widths are the contract's: the memory word (`ChipKind::word_bits`), the
/// triangle word, and the node record the node-word FIFOs hold (on a chip that reads the
/// `records` layout the layout's record: its node words and shared fields).
macro_rules! check_widths {
    ($m:ident, $kind:ident) => {
        const _: () = {
            use crate::chip::{layout, rtl::ChipKind};
            let c = ChipKind::$kind.config();
            let l = layout::Layout::new(&c);
            let slots = if ChipKind::$kind.records() {
                layout::record_nodes(l.levels) as usize
            } else {
                1
            };
            assert!($m::CHIP_WORD_BITS == ChipKind::$kind.word_bits());
            assert!($m::TRI_WORD_BITS == layout::tri_bits(c.format.tri.width() as usize));
            assert!($m::NODE_BITS == l.node_bits as usize && $m::SLOTS == slots);
            assert!($m::RECORD_BITS == slots * $m::NODE_BITS + l.shared_bits as usize);
        };
    };
}
check_widths!(e8m15, K6E8m15);
check_widths!(b32, K24B32);
check_widths!(e8m15_b32, K24E8m15B32);
check_widths!(e8m15_k24, K24E8m15);
check_widths!(e8m10, K24E8m10);
check_widths!(e8m15_fold16, K6E8m15Fold16);
check_widths!(e8m15_dop6_tri32, K6E8m15Dop6Tri32);
check_widths!(e8m15_dop6_tri32_fpga, K6E8m15Dop6Tri32Fpga);
check_widths!(b32_q4, K24B32Q4);
const _: () = assert!(
    b32::TCheck::LATENCY == crate::chip::rtl::TCHECK_LATENCY
        && e8m15::TCheck::LATENCY == crate::chip::rtl::TCHECK_LATENCY
);
const _: () = assert!(
    b32::FpMul::LATENCY == crate::chip::rtl::FP_MUL_LATENCY
        && b32::FpAdd::LATENCY == crate::chip::rtl::FP_ADD_LATENCY
);
const _: () = assert!(
    b32::FpMulFpga::LATENCY == crate::chip::rtl::Depth::Fpga.fp_mul_latency()
        && b32::FpAddFpga::LATENCY == crate::chip::rtl::Depth::Fpga.fp_add_latency()
);
const _: () = assert!(
    b32::Doptrf::LATENCY == crate::chip::rtl::DOP_LATENCY
        && e8m15::Doptrf::LATENCY == crate::chip::rtl::DOP_LATENCY
        && e8m10::Doptrf::LATENCY == crate::chip::rtl::DOP_LATENCY
        && b32::DoptrfFpga::LATENCY == crate::chip::rtl::Depth::Fpga.lane_latency()
        && e8m15::DoptrfFpga::LATENCY == crate::chip::rtl::Depth::Fpga.lane_latency()
        && e8m10::DoptrfFpga::LATENCY == crate::chip::rtl::Depth::Fpga.lane_latency()
        && crate::chip::rtl::Depth::Asic.lane_latency() == crate::chip::rtl::DOP_LATENCY
);
const _: () = assert!(
    e8m15::DopUnit6Fold6::LATENCY == crate::chip::rtl::Depth::Asic.dop_fold_latency(6)
        && e8m15::DopUnit6Fold6Fpga::LATENCY == crate::chip::rtl::Depth::Fpga.dop_fold_latency(6)
);
const _: () = {
    use crate::chip::rtl::ChipKind;
    let fpga = ChipKind::K6E8m15Dop6Tri32Fpga;
    assert!(
        e8m15::DopUnit6Fold6Fpga::LATENCY
            == fpga.depth().dop_fold_latency(fpga.dop_interval() as usize)
    );
};
const _: () = assert!(b32::FpScale::LATENCY == crate::chip::rtl::FP_SCALE_LATENCY);
const _: () = assert!(b32::FpCmp::LATENCY == crate::chip::rtl::FP_CMP_LATENCY);
const _: () = assert!(b32::Dotadd::LATENCY == crate::chip::rtl::DOTADD_LATENCY);
const _: () = assert!(b32::CompareBank::LATENCY == crate::chip::rtl::COMPARE_BANK_LATENCY);
const _: () = assert!(b32::DopDecode::LATENCY == crate::chip::rtl::DOP_DECODE_LATENCY);
const _: () = assert!(
    b32::TriUnit::LATENCY == crate::chip::rtl::TRI_LATENCY
        && e8m15::TriUnit::LATENCY == crate::chip::rtl::TRI_LATENCY
);
