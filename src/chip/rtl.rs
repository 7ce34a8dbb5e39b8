//! The RTL chips: the sizes and latencies their blocks are built with, and the table of the
//! chips exported to `rtl/` ([`rtl_chips!`](crate::rtl_chips)), from which the contract makes [`ChipKind`]
//! and the harness makes the port adapters and the dispatcher over the rust-hdl types.
//! The RTL checks its own numbers against these at compile time (`src/rtl/mod.rs`).

use super::config::{ChipConfig, DopRounding, Formats};
use crate::format::{Format, Rounding};

/// The floating-point units' pipelines: `FpMul`, `FpAdd`, `FpScale` (the folded units'
/// scheduler, `fold::schedule`, places operations by these).
pub const FP_MUL_LATENCY: usize = 4;
pub const FP_ADD_LATENCY: usize = 3;
pub const FP_SCALE_LATENCY: usize = 4;
/// WSCG'03's compare unit, `FpCmp` (`a + b < 0` by a comparison: its output register).
pub const FP_CMP_LATENCY: usize = 1;
/// WSCG'03's DOTADD unit (`rtl::*::Dotadd`): the DOPTRF lane's stages up to its transformed
/// distance u, input register + `FpMul` + two `FpAdd`s + output register.
pub const DOTADD_LATENCY: usize = 1 + FP_MUL_LATENCY + 2 * FP_ADD_LATENCY + 1;
/// WSCG'03's compare bank (`rtl::b32::CompareBank`): the compare units, then the flags ORed
/// over a DOP's bundles; a bundle's verdicts so far two clocks after it.
pub const COMPARE_BANK_LATENCY: usize = FP_CMP_LATENCY + 1;
/// WSCG'03's d' memory (`rtl::b32::DprimeMemory`): a read address to its entry (synchronous
/// RAMs).
pub const DPRIME_READ_LATENCY: usize = 1;
/// WSCG'03's DOP Unit (`rtl::b32::Wscg03DopUnit`): an aligned DOP's bundle to its verdicts so
/// far, the d' memory's read, then the compare bank.
pub const WSCG03_COMPARE_LATENCY: usize = DPRIME_READ_LATENCY + COMPARE_BANK_LATENCY;

/// WSCG'03's Stack Engine's list SRAMs (`rtl::wscg03::stack_engine::ListStack`): address
/// bits of each (left, right): 4,096 node pointers.
pub const LIST_SRAM_BITS: usize = 12;
/// The Stack Engine's levels (its level register, 5 bits): level 0 holds the root's list
/// (the host's), so lists reach level 31 and trees 30 levels below B's root.
pub const LIST_LEVELS: usize = 32;
/// WSCG'03's Memory Controller (§4.4: an input register of a node pair): node records held
/// or asked for beyond the one it streams into the DOP Unit.
pub const MC_RECORDS: usize = 2;
/// WSCG'03's Memory Controller: the asks (tumbled loads, aligned DOPs) its list holds.
pub const MC_ASKS: usize = 8;

/// WSCG'03's Stack Engine's sequencer: aligned nodes read and not yet flagged (a read waits
/// while this many are).
pub const SEQ_READS: usize = 8;
/// The sequencer's action queue: a read waits while 4 actions do, and a read node's flags
/// add at most 4 (its two children onto both members' lists), so at most
/// 3 + 4 [`SEQ_READS`] wait.
pub const SEQ_ACTIONS: usize = 3 + 4 * SEQ_READS;

/// WSCG'03's DOP Unit: clocks from a tumbled pair's last bundle to the first clock its `k`
/// pairs of d' are all in the d' memory (its set no longer busy), when the address generator
/// is free: the generator's counter (1), the MMM's read (1), the DOTADD units, a lane a
/// clock, the d' memory's write (1).
pub const fn wscg03_transform_clocks(k: usize) -> usize {
    1 + 1 + DOTADD_LATENCY + (k - 1) + 1
}

/// How deep the floating-point units are cut, per target. The values are the same bit for
/// bit at every depth; only the latencies differ.
#[derive(
    Clone,
    Copy,
    Debug,
    Default,
    PartialEq,
    Eq,
    Hash,
    serde::Serialize,
    serde::Deserialize,
    clap::ValueEnum,
)]
#[serde(rename_all = "lowercase")]
pub enum Depth {
    /// For standard cells (OSU 0.18 um: a stage of 5-7 ns): `FpMul`, `FpAdd`.
    #[default]
    Asic,
    /// For an FPGA (ECP5: a stage of a few LUT levels and one carry chain, where a LUT level
    /// and its routing cost about 1 ns): `FpMulFpga`, `FpAddFpga`.
    Fpga,
}

impl Depth {
    /// Whether this is the standard cells' depth (the default).
    pub fn is_asic(&self) -> bool {
        *self == Depth::Asic
    }

    /// Both depths.
    pub const ALL: [Depth; 2] = [Depth::Asic, Depth::Fpga];

    /// The multiplier's latency in clocks.
    pub const fn fp_mul_latency(self) -> usize {
        match self {
            Depth::Asic => FP_MUL_LATENCY,
            Depth::Fpga => 6,
        }
    }

    /// The adder's latency in clocks.
    pub const fn fp_add_latency(self) -> usize {
        match self {
            Depth::Asic => FP_ADD_LATENCY,
            Depth::Fpga => 6,
        }
    }

    /// The DOPTRF lane's latency: its input register, a product, three sums in a tree of
    /// two levels and then `+ e`, its sign test.
    pub const fn lane_latency(self) -> usize {
        1 + self.fp_mul_latency() + 3 * self.fp_add_latency() + 1
    }

    /// The folded DOP unit's latency at a pair every `ii` clocks: its last pass's lanes
    /// ([`dop_fold_latency`]).
    pub const fn dop_fold_latency(self, ii: usize) -> usize {
        self.lane_latency() + ii - 1
    }

    /// Registers between a folded unit's operand multiplexers and its FP units: none for
    /// standard cells; one at FPGA depth, where a multiplexer of 16 registers and the decode
    /// of its select would fill a stage of their own (`rtl::tcheck_fold`).
    pub const fn operand_registers(self) -> usize {
        match self {
            Depth::Asic => 0,
            Depth::Fpga => 1,
        }
    }

    /// Its name in scenes and on the command line (`[timing] depth`, `--depths`).
    pub fn name(self) -> &'static str {
        match self {
            Depth::Asic => "asic",
            Depth::Fpga => "fpga",
        }
    }

    /// What an exported unit's name carries after its operation (`fp_add_fpga_b32_rne`).
    pub fn tag(self) -> &'static str {
        match self {
            Depth::Asic => "",
            Depth::Fpga => "_fpga",
        }
    }
}
/// Clocks from a DOP test's issue to its result: the DOPTRF lane's pipeline (D.KLMSEL and
/// the NOR add no register).
pub const DOP_LATENCY: usize = 15;

/// The decode stage of stored DOP precision ([`dop::stored`](crate::dop::stored)) ahead of
/// D.KLMSEL: per plane, one subtraction `r ⊖ q 2^e` of the DOP format for each node of the
/// pair, an adder's pipeline behind a rank of input registers on the unit's path
/// (`rtl::b32::DopDecode`, in front of the DOP unit of `chip_b32_k24_q4`).
pub const DOP_DECODE_LATENCY: usize = 1 + FP_ADD_LATENCY;

/// Clocks a configuration's DOP unit adds ahead of its lanes: the decode stage with stored
/// DOP precision, else none.
pub fn dop_decode_latency(cfg: &ChipConfig) -> u32 {
    match cfg.dop_bits {
        super::config::DopBits::Full => 0,
        super::config::DopBits::Bits(_) => DOP_DECODE_LATENCY as u32,
    }
}

/// The folded DOP unit (`rtl::*::DopUnit<k>Fold<ii>`, a pair every `ii` clocks in `ii` passes
/// of its lanes): a pair taken in cycle t has its verdict in cycle t + this, the last pass's
/// lane latency (its pass starts ii - 1 clocks after the first).
pub const fn dop_fold_latency(ii: usize) -> usize {
    Depth::Asic.dop_fold_latency(ii)
}
/// T.CHECK's pipeline: a pair in, its verdict 52 clocks later (DATE'05's budget).
pub const TCHECK_LATENCY: usize = 52;
/// TRI_UNIT: a pair taken at its input shows at the output port this many clocks later
/// (T.CHECK's, the pair register before it and the result FIFO's write after it).
pub const TRI_LATENCY: usize = TCHECK_LATENCY + 2;
/// TRI_UNIT's result FIFO: `2^TRI_FIFO_BITS` pairs taken and not yet given out.
pub const TRI_FIFO_BITS: usize = 8;
pub const TRI_FIFO: usize = 1 << TRI_FIFO_BITS;
/// Clocks from a write into rust-hdl's synchronous FIFO (`declare_sync_fifo!`) to the
/// entry at its head: the write pointer reaches the read side through one more register.
pub const FIFO_WRITE_TO_HEAD: u32 = 2;
/// The pair queue: `2^QUEUE_BITS` entries (1,024: a breadth-first (FIFO) traversal of a few
/// hundred triangles needs about that many; LIFO a few dozen).
pub const QUEUE_BITS: usize = 10;
/// The chip's leaf FIFO: overlapping leaf pairs waiting for TRI_UNIT.
pub const LEAF_FIFO: usize = 64;
/// The credit (DOP tests in flight plus waiting leaf pairs, which keeps the leaf FIFO from
/// overflowing) after reset ([`PORT`](super::reg::PORT)`[14:9]` = 0), and the most the register's 6 bits give.
pub const CREDIT: usize = 16;
pub const CREDIT_MAX: usize = 63;
const _: () = assert!(CREDIT_MAX < LEAF_FIFO);

/// The memory port's limits, set per query in host register [`super::reg::PORT`]
/// (which also holds the issue spacing and the credit): node pairs
/// prefetched at most ([`super::params::Params::prefetch`]; larger values act as this) and
/// memory requests outstanding at most. The chip's pair buffer holds `PAIR_BUF =
/// PORT_PREFETCH + 2` pairs (as many entries), each node-word FIFO as many words, the list
/// of node words to ask for `ASK_LIST`, the response tag FIFO `PORT_OUTSTANDING`
/// destinations.
pub const PORT_PREFETCH: usize = 14;
pub const PORT_OUTSTANDING: usize = 16;
/// Pairs (and entries, and node words per destination) the chip holds ahead of its DOP unit.
pub const PAIR_BUF: usize = PORT_PREFETCH + 2;
/// Node words the chip holds to ask for (two per pair).
pub const ASK_LIST: usize = 2 * PAIR_BUF;
// the chip's pointers into these buffers are 4 bits (5 for the ask list)
const _: () = assert!(PAIR_BUF == 16 && PORT_OUTSTANDING == 16);
/// A's triangle cache (WSCG'03 §4.3): `TRI_CACHE_LINES` lines of RAM in the chip, of which
/// host register [`TRI_CACHE`](super::reg::TRI_CACHE) uses the first `lines` (a power of two;
/// reset: one, the single word held).
pub const TRI_CACHE_BITS: usize = 7;
pub const TRI_CACHE_LINES: usize = 1 << TRI_CACHE_BITS;
// the chip's line index and valid bits are 7 and 128 bits wide
const _: () = assert!(TRI_CACHE_LINES == 128);

/// The exported unit of D_CNTR's pair queue (16 entries) in `rtl/` and the timing tables.
pub const PAIR_QUEUE_UNIT: &str = "pair_queue_n4";

/// A format's tag in the RTL's file names: `b32` for binary32, else `eEmF` (`e8m15`).
pub fn format_tag(fmt: Format) -> String {
    if fmt == Format::BINARY32 {
        "b32".into()
    } else {
        fmt.to_string()
    }
}

/// `fold<ii>_` in a folded unit's name (`ii` clocks between its pairs), nothing unfolded.
fn fold_tag(ii: u32) -> String {
    if ii > 1 {
        format!("fold{ii}_")
    } else {
        String::new()
    }
}

/// The DOP unit's name in `rtl/`, the area study and the timing tables: k DOPTRF lanes in
/// `fmt` (`dop_unit_k<k>_<format>`; their rounding is a setup word's), or (`ii` > 1) k/ii lanes
/// taking a pair every `ii` clocks (`dop_unit_fold<ii>_k<k>_...`, `rtl::*::DopUnit<k>Fold<ii>`).
pub fn dop_unit_name(k: usize, fmt: Format, ii: u32) -> String {
    dop_unit_name_at(Depth::Asic, k, fmt, ii)
}

/// [`dop_unit_name`] at `depth` (`dop_unit_fpga_fold6_k6_e8m15`).
pub fn dop_unit_name_at(depth: Depth, k: usize, fmt: Format, ii: u32) -> String {
    format!(
        "dop_unit{}_{}k{k}_{}",
        depth.tag(),
        fold_tag(ii),
        format_tag(fmt)
    )
}

/// TRI_UNIT's name there: two T.CHECKs in `fmt` rounding with `r` (`tri_unit_<format>_<rounding>`),
/// or (`ii` > 1) one folded T.CHECK taking a pair every `ii` clocks (`tri_unit_fold<ii>_...`,
/// `rtl::*::TriUnitFold`).
pub fn tri_unit_name(fmt: Format, r: Rounding, ii: u32) -> String {
    tri_unit_name_at(Depth::Asic, fmt, r, ii)
}

/// [`tri_unit_name`] at `depth` (`tri_unit_fpga_fold32_e8m15_rne`).
pub fn tri_unit_name_at(depth: Depth, fmt: Format, r: Rounding, ii: u32) -> String {
    format!(
        "tri_unit{}_{}{}_{}",
        depth.tag(),
        fold_tag(ii),
        format_tag(fmt),
        rounding_tag(r)
    )
}

/// The decode stage's name for `bits`-bit stored DOPs in `fmt` (`dop_decode_q4_b32`:
/// `rtl::b32::DopDecode`; its rounding an input, the DOP lanes').
pub fn dop_decode_name(fmt: Format, bits: u32) -> String {
    format!("dop_decode_q{bits}_{}", format_tag(fmt))
}

/// A rounding's tag in the RTL's file names.
pub fn rounding_tag(r: Rounding) -> &'static str {
    match r {
        Rounding::NearestEven => "rne",
        Rounding::TowardPositive => "ru",
        Rounding::TowardNegative => "rd",
    }
}

/// WSCG'03's chip in RTL (`rtl::wscg03::chip::CollisionChip`, binary32, k = 24): its
/// exported Verilog's name in rtl/, without `.v`.
pub const WSCG03_CHIP: &str = "chip_wscg03_b32_k24";

/// rust-hdl's speed on WSCG'03's chip, clocks per second on this project's machine (the
/// three queries of tb/wscg03.rs `chip_rtl_lockstep`: 3,025 clocks in 64 s): for estimates.
pub const WSCG03_RTL_CLOCKS_PER_SECOND: f64 = 45.0;

/// Whether WSCG'03's RTL chip is built for `cfg` (binary32, k = 24, T.CHECK to
/// nearest-even: the configuration of [`ChipKind::K24B32`], whose memory image it reads).
pub fn wscg03_builds(cfg: &ChipConfig) -> bool {
    ChipKind::of(cfg, 1, 1, Depth::Asic) == Some(ChipKind::K24B32)
}

/// The RTL chips, one row each: the kind's name, the exported file's name in `rtl/`, the
/// module of `crate::rtl` that stamps it out, its configuration, whether it also reads the
/// `records` layout (host register [`MODE`](super::reg::MODE) bit 2; its memory word then a record), the clocks
/// between the DOP unit's pairs (1: `DopUnit<k>`; ii dividing k: `DopUnit<k>Fold<ii>`, the
/// cycle model's `dop_interval`) and between TRI_UNIT's (1: `TriUnit`; an even ii:
/// `TriUnitFold`, the cycle model's `tri_interval`), the FP units' [`Depth`], and rust-hdl's speed on
/// it in clocks per second on this project's machine (docs/explanation/speed.md, `cargo bench --bench
/// chip_sim`: for estimates before a run). Every chip's DOP lanes round as the host's setup
/// words say (`dop_rounding`: outward or nearest-even; [`config`](ChipKind::config) says
/// outward), T.CHECK to nearest-even, and every chip has a triangle cache of [`TRI_CACHE_LINES`] lines (host register
/// [`TRI_CACHE`](super::reg::TRI_CACHE) picks how many are used). Calls `$m!` with the rows, so that each layer makes
/// what it needs of one table: the contract [`ChipKind`], the harness its adapters.
#[macro_export]
macro_rules! rtl_chips {
    ($m:ident) => {
        $m! {
            /// k = 6 in e8m15: small and fast to simulate.
            K6E8m15, "chip_e8m15_k6", e8m15, (6, REDUCED, REDUCED), false, 1, 1, Asic, 14.0;
            /// The papers' chip (DATE'05 §4): k = 24 in binary32.
            K24B32, "chip_b32_k24", b32, (24, BINARY32, BINARY32), true, 1, 1, Asic, 4.0;
            /// The papers' chip with its DOP datapath in e8m15 (format `e8m15/binary32`).
            K24E8m15B32, "chip_e8m15_b32_k24", e8m15_b32, (24, REDUCED, BINARY32), true, 1, 1, Asic, 4.0;
            /// The papers' chip (k = 24) in e8m15 throughout (format `reduced`). (rust-hdl's
            /// speed assumed to be `chip_e8m15_b32_k24`'s.)
            K24E8m15, "chip_e8m15_k24", e8m15_k24, (24, REDUCED, REDUCED), true, 1, 1, Asic, 4.0;
            /// The papers' chip (k = 24) in e8m10 throughout, the study's narrowest format.
            /// (rust-hdl's speed assumed to be `chip_e8m15_b32_k24`'s.)
            K24E8m10, "chip_e8m10_k24", e8m10, (24, E8M10, E8M10), true, 1, 1, Asic, 4.0;
            /// k = 6 in e8m15 with TRI_UNIT folded: a pair every 16 clocks.
            /// (rust-hdl's speed from `fold16_patch_fifo_all` in lockstep, tb/rtl_chip.rs: 1,498
            /// clocks in 10.4 s; the folded TRI_UNIT simulates far faster than two T.CHECKs.)
            K6E8m15Fold16, "chip_e8m15_k6_fold16", e8m15_fold16, (6, REDUCED, REDUCED), false, 1, 16, Asic, 140.0;
            /// k = 6 in e8m15 with both units folded, for an ECP5 LFE5U-85F: the DOP
            /// unit on one DOPTRF lane, a pair every 6 clocks; TRI_UNIT a pair every 32.
            /// (rust-hdl's speed from `dop6tri32_patch_fifo_all` in lockstep: 2,882 clocks in 7.2 s.)
            K6E8m15Dop6Tri32, "chip_e8m15_k6_dop6_tri32", e8m15_dop6_tri32, (6, REDUCED, REDUCED), false, 6, 32, Asic, 400.0;
            /// The same at FPGA depth (`Depth::Fpga`): FP units of six stages, T.CHECK's operands
            /// registered, each of its units on its own copy of the schedule counter.
            /// (rust-hdl's speed assumed to be `chip_e8m15_k6_dop6_tri32`'s.)
            K6E8m15Dop6Tri32Fpga, "chip_e8m15_k6_dop6_tri32_fpga", e8m15_dop6_tri32_fpga, (6, REDUCED, REDUCED), false, 6, 32, Fpga, 400.0;
            /// The papers' chip reading records of 4-bit stored DOPs (`dop_bits = 4`, the
            /// `records` layout only), its DOP unit behind the decode stage.
            K24B32Q4, "chip_b32_k24_q4", b32_q4, (24, BINARY32, BINARY32, 4), true, 1, 1, Asic, 3.0;
        }
    };
}

macro_rules! chip_kinds {
    // a chip with stored DOP precision (its code's bits) reads `records` of it; else full
    // records or words (`records` then says which)
    (@bits) => { super::config::DopBits::Full };
    (@bits $b:literal) => { super::config::DopBits::Bits($b) };
    (@layout) => { super::config::MemLayout::Words };
    (@layout $b:literal) => { super::config::MemLayout::Records };
    ($($(#[$doc:meta])* $kind:ident, $name:literal, $module:ident, ($k:literal, $dop:ident, $tri:ident $(, $bits:literal)?), $records:literal, $dop_ii:literal, $ii:literal, $depth:ident, $speed:literal;)+) => {
        /// The RTL chips: one `CollisionChip` per configuration, exported to `rtl/<name>.v`.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum ChipKind {
            $($(#[$doc])* $kind,)+
        }

        impl ChipKind {
            pub const ALL: &'static [ChipKind] = &[$(ChipKind::$kind),+];

            pub const fn config(self) -> ChipConfig {
                match self {
                    $(ChipKind::$kind => ChipConfig {
                        k: $k,
                        format: Formats { dop: Format::$dop, tri: Format::$tri },
                        dop_rounding: DopRounding::Outward,
                        tri_rounding: Rounding::NearestEven,
                        tri_cache: 1,
                        tri_cache_b: 1,
                        layout: chip_kinds!(@layout $($bits)?),
                        node_cache: 1,
                        dop_bits: chip_kinds!(@bits $($bits)?),
                    },)+
                }
            }

            /// The exported Verilog's file name in rtl/, without `.v`.
            pub const fn name(self) -> &'static str {
                match self {
                    $(ChipKind::$kind => $name,)+
                }
            }

            /// Whether the chip also reads the `records` layout (with one node record held per
            /// object).
            pub const fn records(self) -> bool {
                match self {
                    $(ChipKind::$kind => $records,)+
                }
            }

            /// Clocks between the DOP unit's pairs: 1 (unfolded), or the folded unit's ii (the
            /// cycle model's [`dop_interval`](super::params::Params::dop_interval)).
            pub const fn dop_interval(self) -> u32 {
                match self {
                    $(ChipKind::$kind => $dop_ii,)+
                }
            }

            /// Clocks between TRI_UNIT's pairs: 1 (unfolded), or the folded unit's ii (the
            /// cycle model's [`tri_interval`](super::params::Params::tri_interval)).
            pub const fn tri_interval(self) -> u32 {
                match self {
                    $(ChipKind::$kind => $ii,)+
                }
            }

            /// How deep its FP units are cut (the cycle model's [`depth`](super::params::Params::depth)).
            pub const fn depth(self) -> Depth {
                match self {
                    $(ChipKind::$kind => Depth::$depth,)+
                }
            }

            /// rust-hdl's clocks per second on this chip, for estimates before a run.
            pub const fn rtl_clocks_per_second(self) -> f64 {
                match self {
                    $(ChipKind::$kind => $speed,)+
                }
            }
        }
    };
}
rtl_chips!(chip_kinds);

impl ChipKind {
    /// The chip built for `cfg`'s k, formats and roundings with the DOP unit taking a pair
    /// every `dop_interval` clocks and TRI_UNIT every `tri_interval`, its FP units at `depth`, if any (its triangle
    /// cache and memory layout aside: every chip has [`TRI_CACHE_LINES`] lines, host register
    /// [`TRI_CACHE`](super::reg::TRI_CACHE) picks how many are used; [`records`](Self::records) says which layouts it reads).
    pub fn of(
        cfg: &ChipConfig,
        dop_interval: u32,
        tri_interval: u32,
        depth: Depth,
    ) -> Option<ChipKind> {
        let mut at = ChipKind::built(cfg).filter(|k| {
            (k.dop_interval(), k.tri_interval(), k.depth()) == (dop_interval, tri_interval, depth)
        });
        let first = at.next()?;
        // the chip of the configuration's stored precision, if one is built
        Some(
            std::iter::once(first)
                .chain(at)
                .find(|k| k.config().dop_bits == cfg.dop_bits)
                .unwrap_or(first),
        )
    }

    /// Whether this chip holds `cfg`'s memory side: one node record per object, the `words`
    /// layout (the chips of [`records`](Self::records) also `records`, on any memory: the port
    /// computes `RecordMap`'s addresses) and at most [`TRI_CACHE_LINES`] lines of A's
    /// triangle cache; otherwise what to change.
    pub fn reads(self, cfg: &ChipConfig) -> Result<(), String> {
        use super::config::MemLayout;
        if cfg.node_cache != 1 {
            return Err(format!("the RTL chips hold one node record per object; this configuration has node_cache = {}: set [chip] node_cache = 1", cfg.node_cache));
        }
        if cfg.dop_bits != self.config().dop_bits {
            let coded: Vec<String> = ChipKind::ALL
                .iter()
                .filter(|k| k.config().dop_bits != super::config::DopBits::Full)
                .map(|k| format!("{} (dop_bits = {})", k.name(), k.config().dop_bits))
                .collect();
            return Err(format!("{} reads node records of dop_bits = {} (of the RTL chips, {} read stored DOPs); this configuration has dop_bits = {}: set [chip] dop_bits = \"{}\"", self.name(), self.config().dop_bits, coded.join(", "), cfg.dop_bits, self.config().dop_bits));
        }
        if cfg.layout == MemLayout::Records && !self.records() {
            let records: Vec<&str> = ChipKind::ALL
                .iter()
                .filter(|k| k.records())
                .map(|k| k.name())
                .collect();
            return Err(format!(
                "{} reads the `words` layout only (of the RTL chips, {} also read `records`); this configuration has layout = \"records\": set [chip] layout = \"words\"",
                self.name(),
                records.join(", ")
            ));
        }
        if cfg.tri_cache_b != 1 {
            return Err(format!("the RTL chips hold one triangle word of B; this configuration has tri_cache_b = {}: set [chip] tri_cache_b = 1", cfg.tri_cache_b));
        }
        if cfg.tri_cache > TRI_CACHE_LINES as u32 {
            return Err(format!("the RTL chips' triangle cache has {TRI_CACHE_LINES} lines; this configuration has tri_cache = {}: set [chip] tri_cache to at most {TRI_CACHE_LINES}", cfg.tri_cache));
        }
        Ok(())
    }

    /// The chips built for `cfg`'s k, formats and roundings, at any TRI_UNIT interval and
    /// stored DOP precision ([`of`](Self::of) picks `cfg`'s).
    pub fn built(cfg: &ChipConfig) -> impl Iterator<Item = ChipKind> {
        let base = |c: &ChipConfig| ChipConfig {
            tri_cache: 1,
            tri_cache_b: 1,
            layout: super::config::MemLayout::Words,
            node_cache: 1,
            dop_bits: super::config::DopBits::Full,
            // either DOP rounding: the host's setup words set the lanes'
            dop_rounding: super::config::DopRounding::Outward,
            ..*c
        };
        let want = base(cfg);
        ChipKind::ALL
            .iter()
            .copied()
            .filter(move |k| base(&k.config()) == want)
    }

    /// Memory word bits: a record ([`record_bits`](super::layout::record_bits)) on a chip
    /// that reads the `records` layout, else the wider of a node word and a triangle word
    /// (in either layout a word's or record's bits from bit 0, the rest zero).
    pub const fn word_bits(self) -> usize {
        let c = self.config();
        let (dop_w, tri_w) = (c.format.dop.width() as usize, c.format.tri.width() as usize);
        if self.records() {
            super::layout::record_bits(c.k, dop_w, tri_w)
        } else {
            super::layout::word_bits(c.k, dop_w, tri_w)
        }
    }
}
