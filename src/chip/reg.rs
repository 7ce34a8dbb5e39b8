//! The host registers: their addresses, fields and the writes that set up one query. The
//! DOP unit's setup words are at `0x000 + a` (lane i's C_i0..2, c_i and D.KLMSEL control at
//! `8 i + 0..4`), TRI_UNIT's at [`TRI_SETUP`]` + a`; the traversal's from [`MODE`] on.

use super::config::{ChipConfig, MemLayout};
use super::layout::{slot_bits, Layout};
use super::params::Params;
use super::rtl;
use serde::{Deserialize, Serialize};

/// The register map, written once: `register_map!([m] { args })` expands to `m! { args`
/// and each register as `NAME = address;` with its doc `}`. It defines the constants
/// below, and gives the RTL chip's kernel the addresses as literal tokens
/// (`crate::rtl::chip`'s `host_kernel!`: `#[hdl_gen]` translates a path such as
/// `reg::MODE` into a Verilog signal's name, not into its value).
macro_rules! register_map {
    ([$($m:tt)*] { $($args:tt)* }) => {
        $($m)*! { $($args)*
            /// TRI_UNIT's setup words (frame maps, bounds, eta).
            TRI_SETUP = 0x100;
            /// The query: bit 0 the order ([`Order::Lifo`]), bit 1 first hit ([`Mode::First`]), bit
            /// 2 the memory layout ([`MemLayout::Records`]), bits 5:3 the bits of a node id's slot
            /// field in it ([`slot_bits`]: 1 for a node pair, 3 for a treelet of two levels; 0 in
            /// `words`). The cycle model takes the layout from its configuration.
            MODE = 0x120;
            /// The root pair: A's node in bits 15:0, B's in 31:16.
            ROOT = 0x121;
            /// Word addresses of A's nodes, B's nodes, A's triangles, B's triangles (24 bits each).
            BASE_NA = 0x122;
            BASE_NB = 0x123;
            BASE_TA = 0x124;
            BASE_TB = 0x125;
            /// The memory port: bits 3:0 the pairs prefetched, 7:4 the requests outstanding at
            /// most, less one; bit 8 an issue every clock (issue spacing 1); bits 14:9 the credit
            /// (0: [`rtl::CREDIT`]). Zero after reset: the RTL's default point ([`Params::RTL`]).
            /// The cycle model takes these from its [`Params`]; [`control_writes`] writes them for
            /// the RTL.
            PORT = 0x126;
            /// A's triangle cache: bits 6:0 its lines less one (`ChipConfig::tri_cache`, at most
            /// [`rtl::TRI_CACHE_LINES`] in the RTL). Zero after reset: one line.
            TRI_CACHE = 0x127;
            /// Where the records lie ([`RecordMap::word`](super::layout::RecordMap::word)): the
            /// log2 of each region's banks, of a page's records and of the banks. Zero after reset:
            /// the image in order, record `i` of a region at its base plus `i`.
            MAP = 0x128;
        }
    };
}
pub(crate) use register_map;

/// `pub const NAME: u32 = address;` for each register of the map.
macro_rules! constants {
    ($($(#[$doc:meta])* $name:ident = $addr:literal;)*) => {
        $($(#[$doc])* pub const $name: u32 = $addr;)*
    };
}
register_map!([constants] {});

/// What a query looks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum Mode {
    /// Every intersecting triangle pair.
    All,
    /// Stop at the first intersecting pair ("do they touch?").
    First,
}

/// D_CNTR's order (DATE'05 §4.3): pairs wait in a FIFO (breadth first) or a LIFO (depth
/// first). Bit 0 of [`MODE`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Order {
    #[default]
    Fifo,
    Lifo,
}

/// The [`MODE`] word.
pub fn mode_word(order: Order, mode: Mode, layout: &Layout) -> u32 {
    let records = layout.kind == MemLayout::Records;
    let slot = if records { slot_bits(layout.levels) } else { 0 };
    (order == Order::Lifo) as u32
        | ((mode == Mode::First) as u32) << 1
        | (records as u32) << 2
        | slot << 3
}

/// The fields of a [`MODE`] word.
pub fn mode_fields(w: u32) -> (Order, Mode) {
    let order = if w & 1 == 1 { Order::Lifo } else { Order::Fifo };
    (order, if w & 2 == 2 { Mode::First } else { Mode::All })
}

/// The [`PORT`] word of `p`, in the RTL's fields (the cycle model runs larger values from
/// `p` itself; `harness::chip_io::rtl_order` keeps the RTL's queries within them).
pub fn port_word(p: &Params) -> u32 {
    let credit = if p.credit == rtl::CREDIT as u32 {
        0
    } else {
        p.credit.min(rtl::CREDIT_MAX as u32)
    };
    let outstanding = p.outstanding.clamp(1, rtl::PORT_OUTSTANDING as u32);
    p.prefetch.min(0xf)
        | (outstanding - 1) << 4
        | ((p.issue_spacing == 1) as u32) << 8
        | credit << 9
}

/// The register writes that start a query after the setup words: the memory image's
/// regions' first words (by [`Dst`](super::layout::Dst), of `image`, the
/// [`image_bases`](super::layout::image_bases), where `cfg`'s layout puts them on `p`'s
/// memory: [`RecordMap::bases`](super::layout::RecordMap::bases)), the root, the port, `cfg`'s triangle cache and the
/// record map if not at their reset values, the mode (with `cfg`'s layout) last.
pub fn control_writes(
    image: [u32; 4],
    order: Order,
    mode: Mode,
    p: &Params,
    cfg: &ChipConfig,
) -> Vec<(u32, u32)> {
    let map = super::layout::RecordMap::new(&Layout::new(cfg), &p.memory);
    let word = map.spread().then(|| map.word());
    query_writes(map.bases(image), word, order, mode, p, cfg)
}

/// [`control_writes`] with the regions at the words `base` (by
/// [`Dst`](super::layout::Dst)) and the record map `map` written if any (WSCG'03's chip
/// reads the image in order: none).
pub fn query_writes(
    base: [u32; 4],
    map: Option<u32>,
    order: Order,
    mode: Mode,
    p: &Params,
    cfg: &ChipConfig,
) -> Vec<(u32, u32)> {
    use super::layout::Dst;
    let tri_cache = cfg.tri_cache;
    let mut w = vec![
        (BASE_NA, base[Dst::NodeA as usize]),
        (BASE_TA, base[Dst::TriA as usize]),
        (BASE_NB, base[Dst::NodeB as usize]),
        (BASE_TB, base[Dst::TriB as usize]),
        (ROOT, 0),
    ];
    let port = port_word(p);
    if port != 0 {
        w.push((PORT, port));
    }
    if tri_cache > 1 {
        w.push((
            TRI_CACHE,
            (tri_cache - 1).min(rtl::TRI_CACHE_LINES as u32 - 1),
        ));
    }
    if let Some(m) = map {
        w.push((MAP, m));
    }
    w.push((MODE, mode_word(order, mode, &Layout::new(cfg))));
    w
}
