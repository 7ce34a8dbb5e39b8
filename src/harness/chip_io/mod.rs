//! The host and memory side of the RTL collision chips (`CollisionChip` of
//! [`crate::rtl::e8m15`], [`crate::rtl::b32`] and [`crate::rtl::e8m15_b32`]): the memory
//! image and register writes of
//! one query, a memory model with configurable timing, the rust-hdl driver that runs a
//! whole query, and the query trace that the Verilog testbench (`scripts/verilog/chip_tb.v`)
//! prints in the same format, so that the two simulations are compared line by line.
//!
//! The chips are the rows of [`rtl_chips!`](crate::rtl_chips) ([`ChipKind`]): from that one
//! table come the port adapters ([`RtlPorts`]) and the dispatcher over their rust-hdl types
//! ([`with_chip`]).

use super::tri_io::{tri_unit_setup_words, LeafIn};
use crate::chip::config::{ChipConfig, DopBits, MemLayout};
use crate::chip::layout::{
    exp_field_bits, exp_range, record_nodes, slot_bits, treelet_records, Dst, Layout, RecordMap,
};
use crate::chip::memory::{MemClocks, Memory};
use crate::chip::params::Params;
use crate::chip::ports::{ChipIn, ChipOut, Clocked};
use crate::chip::reg::{self, Mode, Order};
use crate::chip::rtl::{self as chips, ChipKind, Depth, QUEUE_BITS};
use crate::cycle::drive::open_vcd;
pub use crate::cycle::drive::{ChipError, ChipTrace, Drive, Reader};
use crate::dop::tree::StoredFields;
use crate::dop::Node;
use crate::format::{Format, Rounding};
use crate::golden::host::HostSetup;
use crate::golden::memory::ObjectImage;
use crate::traversal::Traversal;
use rust_hdl::prelude::*;
use std::fmt::Write as _;

mod query_lists;
mod query_set;
pub use query_lists::{queries, write_vectors};
pub use query_set::{query_mesh, ChipQuery, PreparedQuery};
#[cfg(test)]
mod tests;

/// What to do with an RTL chip, whichever its rust-hdl type ([`with_chip`]).
pub trait OnChip {
    type Out;
    fn run<C: RtlPorts>(self, chip: C) -> Self::Out;
}

macro_rules! dispatch {
    ($($(#[$doc:meta])* $kind:ident, $name:literal, $module:ident, $cfg:tt, $records:literal, $dop_ii:literal, $ii:literal, $depth:ident, $speed:literal;)+) => {
        /// Builds `kind`'s rust-hdl chip with `2^N` queue entries (`NP1 = N + 1`, `NM1 = N -
        /// 1`), ready to simulate, and hands it to `f` (call on a thread with a big stack:
        /// TRI_UNIT and the k = 24 DOP unit are large).
        pub fn with_chip<const N: usize, const NP1: usize, const NM1: usize, F: OnChip>(kind: ChipKind, f: F) -> F::Out {
            let c = kind.config();
            match kind {
                $(ChipKind::$kind => f.run(crate::rtl::$module::chip_top::<N, NP1, NM1>(c.tri_rounding)),)+
            }
        }
        $(rtl_ports!($module, ChipKind::$kind);)+
    };
}

/// The chip's Verilog (top module `top`) with the exported queue of `2^QUEUE_BITS`
/// entries, identical modules merged.
pub fn verilog(kind: ChipKind) -> String {
    struct Gen;
    impl OnChip for Gen {
        type Out = String;
        fn run<C: RtlPorts>(self, chip: C) -> String {
            super::verilog::dedup_modules(&generate_verilog(&chip))
        }
    }
    big_stack(move || with_chip::<QUEUE_BITS, { QUEUE_BITS + 1 }, { QUEUE_BITS - 1 }, _>(kind, Gen))
}

/// Runs `f` on a thread with the 1 GiB stack the RTL chips need to be built.
pub fn big_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new()
        .stack_size(1 << 30)
        .spawn(f)
        .expect("spawn")
        .join()
        .expect("the RTL thread")
}

/// The DOP unit's setup words `(load_addr, load_data)` for `setup`'s lanes
/// ([`dop_setup_words`]).
pub fn dop_unit_setup_words(fmt: Format, rounding: Rounding, setup: &HostSetup) -> Vec<(u64, u64)> {
    dop_setup_words(fmt, rounding, &setup.j, &setup.cmat, &setup.cvec)
}

/// The DOP unit's setup words `(load_addr, load_data)`: lane i's C_i0..2, c_i, and the
/// D.KLMSEL control and the lane's rounding `j_i0 | j_i1 << 5 | j_i2 << 10 | round_up << 15`
/// (`rounding`: 1 TowardPositive, 0 NearestEven) at `8 i + 0..4`.
pub fn dop_setup_words(
    fmt: Format,
    rounding: Rounding,
    j: &[[u8; 3]],
    cmat: &[[f64; 3]],
    cvec: &[f64],
) -> Vec<(u64, u64)> {
    let up = crate::rtl::round_up(rounding, "the DOP unit") as u64;
    let mut out = vec![];
    for (i, (cm, j)) in cmat.iter().zip(j).enumerate() {
        let jw = j[0] as u64 | (j[1] as u64) << 5 | (j[2] as u64) << 10 | up << 15;
        let fields = [
            fmt.to_bits(cm[0]),
            fmt.to_bits(cm[1]),
            fmt.to_bits(cm[2]),
            fmt.to_bits(cvec[i]),
            jw,
        ];
        out.extend(
            fields
                .iter()
                .enumerate()
                .map(|(f, &v)| ((8 * i + f) as u64, v)),
        );
    }
    out
}

/// One memory word as little-endian 64-bit limbs.
pub type Word = Vec<u64>;

fn put(w: &mut Word, at: usize, bits: usize, v: u64) {
    for b in 0..bits {
        if v >> b & 1 == 1 {
            w[(at + b) / 64] |= 1 << ((at + b) % 64);
        }
    }
}

/// Node `n`'s word at bit `at` of `w`: its distances (or, `codes`, its codes of
/// [`Layout::node_bits`]' plane width), children by their ids ([`ObjectImage::ids`]), a
/// leaf's triangle index and (`records`) its triangle's record.
fn put_node_word(
    w: &mut Word,
    at: usize,
    cfg: &ChipConfig,
    obj: &ObjectImage,
    n: u32,
    codes: Option<&[u32]>,
) {
    let (f, k) = (cfg.format.dop, cfg.k);
    let plane = match codes {
        Some(_) => (Layout::new(cfg).node_bits as usize - 65) / k,
        None => f.width() as usize,
    };
    let values: Vec<u64> = match codes {
        Some(q) => q[..k].iter().map(|&c| c as u64).collect(),
        None => obj.tree.dop(n).iter().map(|&d| f.to_bits(d)).collect(),
    };
    let (leaf, f0, f1) = match obj.tree.node(n) {
        Node::Inner([c0, c1]) => (false, obj.ids[c0 as usize], obj.ids[c1 as usize]),
        Node::Leaf(t) if cfg.layout == MemLayout::Records => (true, t, obj.tri_record(t)),
        Node::Leaf(t) => (true, t, 0),
    };
    put_node(w, at, plane, &values, leaf, [f0, f1]);
}

/// A node word at bit `at` of `w`: the leaf bit, then `values` of `plane` bits each, then
/// the two 32-bit fields `f`.
fn put_node(w: &mut Word, at: usize, plane: usize, values: &[u64], leaf: bool, f: [u32; 2]) {
    put(w, at, 1, leaf as u64);
    for (i, &v) in values.iter().enumerate() {
        put(w, at + 1 + i * plane, plane, v);
    }
    let end = at + 1 + values.len() * plane;
    put(w, end, 32, f[0] as u64);
    put(w, end + 32, 32, f[1] as u64);
}

/// A record's shared fields after its node words (stored DOP precision): the treelet
/// root's distances, then each plane's exponent as `e - e_lo` ([`crate::chip::layout`]).
fn put_shared(w: &mut Word, cfg: &ChipConfig, s: &StoredFields) {
    let (f, k, l) = (cfg.format.dop, cfg.k, Layout::new(cfg));
    let DopBits::Bits(bits) = cfg.dop_bits else {
        unreachable!("shared fields come with stored DOP precision")
    };
    let (lo, x) = (exp_range(f, bits).0, exp_field_bits(f, bits) as usize);
    let (at, wd) = (
        (record_nodes(l.levels) * l.node_bits) as usize,
        f.width() as usize,
    );
    for i in 0..k {
        put(w, at + i * wd, wd, f.to_bits(s.r[i]));
        put(w, at + k * wd + i * x, x, (s.e[i] as i32 - lo) as u64);
    }
}

/// An object's node records and its triangle records, in `cfg`'s layout (`chip::layout`):
/// a node record holds its nodes' words in their slots (`records`: slot s from bit
/// `s node_bits`) and, with stored DOP precision, the shared fields; a triangle record its
/// triangle's word.
fn object_words(kind: ChipKind, cfg: &ChipConfig, obj: &ObjectImage) -> [Vec<Word>; 2] {
    let l = Layout::new(cfg);
    let mut nodes = vec![vec![0; kind.word_bits().div_ceil(64)]; obj.node_records() as usize];
    let roots = treelet_records(&obj.tree.children(), l.levels).root;
    for n in 0..obj.tree.len() as u32 {
        let slot = match cfg.layout {
            MemLayout::Records => obj.ids[n as usize] & ((1 << slot_bits(l.levels)) - 1),
            MemLayout::Words => 0,
        };
        let w = &mut nodes[obj.record(n) as usize];
        let fields = obj.tree.stored_fields(n, roots[n as usize]);
        if let Some(s) = &fields {
            put_shared(w, cfg, s);
        }
        let at = (slot * l.node_bits) as usize;
        put_node_word(w, at, cfg, obj, n, fields.as_ref().map(|s| &s.q[..]));
    }
    let f = kind.config().format;
    let mut tris = vec![vec![]; obj.tri_count()];
    for (t, tri) in obj.tris().enumerate() {
        tris[obj.tri_record(t as u32) as usize] = tri_word(kind, &LeafIn::of(f.tri, &tri));
    }
    [nodes, tris]
}

/// The memory image of `a` and `b` for `cfg` on `memory`: every record where
/// [`RecordMap`] puts it, the words between zero.
fn image_words(
    kind: ChipKind,
    a: &ObjectImage,
    b: &ObjectImage,
    cfg: &ChipConfig,
    memory: &Memory,
) -> Vec<Word> {
    let map = RecordMap::new(&crate::chip::layout::Layout::new(cfg), memory);
    let [na, ta] = object_words(kind, cfg, a);
    let [nb, tb] = object_words(kind, cfg, b);
    let regions = [na, nb, ta, tb];
    let base = map.bases(crate::golden::memory::image_bases(a, b));
    let mut words = vec![
        vec![0; kind.word_bits().div_ceil(64)];
        map.extent(regions.each_ref().map(|r| r.len() as u32)) as usize
    ];
    for (d, region) in [Dst::NodeA, Dst::NodeB, Dst::TriA, Dst::TriB]
        .into_iter()
        .zip(regions)
    {
        for (i, w) in (0..).zip(region) {
            words[map.addr(d, base[d as usize], i) as usize] = w;
        }
    }
    words
}

fn tri_word(kind: ChipKind, l: &LeafIn) -> Word {
    let w_ = kind.config().format.tri.width() as usize;
    let mut w = vec![0; kind.word_bits().div_ceil(64)];
    let fields =
        l.v.iter()
            .flatten()
            .chain(&l.m)
            .chain([&l.alpha_m, &l.alpha_f]);
    for (i, &x) in fields.enumerate() {
        put(&mut w, i * w_, w_, x);
    }
    put(&mut w, 23 * w_, 1, l.v_exact as u64);
    put(&mut w, 23 * w_ + 1, 1, l.degenerate as u64);
    w
}

/// Everything the host gives the chip for one query: the memory image (A's node records,
/// A's triangles, B's node records, B's triangles) and the register writes, mode last.
#[derive(Clone, Debug)]
pub struct QueryImage {
    pub kind: ChipKind,
    pub memory: Vec<Word>,
    pub writes: Vec<(u32, u32)>,
    /// The layout's memory word ([`Layout::word_bits`](crate::chip::layout::Layout::word_bits)):
    /// what the memory model moves per request.
    pub word_bits: u32,
}

impl QueryImage {
    /// The memory port's register is written from `p`, the triangle cache's and the layout's
    /// from `cfg` ([`reg::control_writes`]; `a` and `b` built in `cfg`'s layout).
    /// Errors if a tree has more nodes than the 16-bit node ids of D_CNTR address, or the
    /// image more words than the 24-bit memory address.
    pub fn new(
        kind: ChipKind,
        a: &ObjectImage,
        b: &ObjectImage,
        setup: &HostSetup,
        order: Order,
        mode: Mode,
        p: &Params,
        cfg: &ChipConfig,
    ) -> Result<Self, String> {
        let f = kind.config().format;
        for (name, o) in [("A", a), ("B", b)] {
            if o.tree.len() > 1 << 16 {
                return Err(format!(
                    "object {name} has {} DOP-tree nodes; the RTL chip's node ids are 16 bits (at most 32,768 triangles)",
                    o.tree.len()
                ));
            }
        }
        let memory = image_words(kind, a, b, cfg, &p.memory);
        if memory.len() > 1 << 24 {
            return Err(format!(
                "memory image of {} words; the RTL chip addresses 2^24",
                memory.len()
            ));
        }
        let mut writes: Vec<(u32, u32)> = dop_unit_setup_words(f.dop, cfg.dop_rounding.op(), setup)
            .into_iter()
            .map(|(a, d)| (a as u32, d as u32))
            .collect();
        writes.extend(
            tri_unit_setup_words(f.tri, setup)
                .into_iter()
                .map(|(a, d)| (reg::TRI_SETUP + a as u32, d as u32)),
        );
        writes.extend(reg::control_writes(
            crate::golden::memory::image_bases(a, b),
            order,
            mode,
            p,
            cfg,
        ));
        Ok(QueryImage {
            kind,
            memory,
            writes,
            word_bits: crate::chip::layout::Layout::new(cfg).word_bits(),
        })
    }

    /// `$readmemh` text: one word per line, most significant digit first.
    pub fn memory_hex(&self) -> String {
        let mut s = String::new();
        for w in &self.memory {
            let digits = self.kind.word_bits().div_ceil(4);
            let hex: String = w.iter().rev().map(|l| format!("{l:016x}")).collect();
            let _ = writeln!(s, "{}", &hex[hex.len() - digits..]);
        }
        s
    }

    /// `$readmemh` text of the register writes: `{addr[10], data[32]}` per line.
    pub fn writes_hex(&self) -> String {
        self.writes
            .iter()
            .map(|&(a, d)| format!("{:011x}\n", (a as u64) << 32 | d as u64))
            .collect()
    }
}

pub(crate) fn bits<const B: usize>(w: &Word) -> Bits<B> {
    let mut x = Bits::<B>::default();
    for (i, &l) in w.iter().enumerate() {
        if (i + 1) * 64 <= B {
            x.set_bits::<64>(i * 64, l.into());
        } else {
            for b in 0..B - i * 64 {
                x = x.replace_bit(i * 64 + b, l >> b & 1 == 1);
            }
        }
    }
    x
}

/// What the harness drives and reads of an RTL chip (either [`ChipKind`]'s
/// `CollisionChip`: the same ports, memory words of their own width).
pub trait RtlPorts: Block {
    type Word: Copy;
    const KIND: ChipKind;
    fn word(w: &Word) -> Self::Word;
    fn outputs(&self) -> ChipOut;
    /// The inputs of one clock; the memory response's data if one is valid.
    fn set_inputs(&mut self, i: &ChipIn, resp: Option<&Self::Word>);
    fn set_clock(&mut self, high: bool);
    /// Its traversal signals.
    const PROBES: &'static crate::chip::probes::Probes;
    /// [`Self::PROBES`] as the logic shows them now.
    fn probes(&self) -> Vec<u64>;
}

/// `RtlPorts` for DATE'05's chip of format module `fmt` (its probes [`DATE05`](crate::chip::probes::DATE05)), or for
/// a block `ty` (generics `[..]`) with the same ports, memory words of `W` bits, read from
/// images of chip `kind`, its traversal signals `probes` given by `probe` (a function of the block).
macro_rules! rtl_ports {
    ($fmt:ident, $kind:expr) => {
        $crate::harness::chip_io::rtl_ports!(
            [const N: usize, const NP1: usize, const NM1: usize]
            crate::rtl::$fmt::CollisionChip<N, NP1, NM1>,
            { crate::rtl::$fmt::CHIP_WORD_BITS }, $kind, crate::chip::probes::DATE05, Self::probe
        );
    };
    ([$($g:tt)*] $ty:ty, $W:tt, $kind:expr, $probes:path, $probe:expr) => {
        impl<$($g)*> $crate::harness::chip_io::RtlPorts for $ty {
            type Word = rust_hdl::prelude::Bits<$W>;
            const KIND: $crate::chip::rtl::ChipKind = $kind;
            const PROBES: &'static $crate::chip::probes::Probes = &$probes;

            fn word(w: &$crate::harness::chip_io::Word) -> Self::Word {
                $crate::harness::chip_io::bits(w)
            }

            fn outputs(&self) -> $crate::chip::ports::ChipOut {
                let tag = self.res_tag.val().to_u64();
                $crate::chip::ports::ChipOut {
                    busy: self.busy.val(),
                    done: self.done.val(),
                    overflow: self.overflow.val(),
                    max_depth: self.max_depth.val().to_u64(),
                    dop_tests: self.dop_tests.val().to_u64(),
                    tri_tests: self.tri_tests.val().to_u64(),
                    node_fetches: self.node_fetches.val().to_u64(),
                    tri_fetches: self.tri_fetches.val().to_u64(),
                    mem_req_valid: self.mem_req_valid.val(),
                    mem_req_addr: self.mem_req_addr.val().to_u64() as u32,
                    res_valid: self.res_valid.val(),
                    res_tag: ((tag & 0xffff) as u32, (tag >> 16) as u32),
                    res_uncertain: self.res_uncertain.val(),
                }
            }

            fn set_inputs(&mut self, i: &$crate::chip::ports::ChipIn, resp: Option<&Self::Word>) {
                self.host_we.next = i.host_we;
                self.host_addr.next = (i.host_addr as u64).into();
                self.host_data.next = (i.host_data as u64).into();
                self.start.next = i.start;
                self.mem_req_ready.next = i.mem_req_ready;
                self.mem_resp_valid.next = i.mem_resp.is_some();
                if let Some(w) = resp {
                    self.mem_resp_data.next = *w;
                }
                self.res_ready.next = i.res_ready;
            }

            fn set_clock(&mut self, high: bool) {
                self.clock.next = rust_hdl::prelude::Clock { clk: high };
            }

            fn probes(&self) -> Vec<u64> {
                ($probe)(self)
            }
        }
    };
}
pub(crate) use rtl_ports;
crate::rtl_chips!(dispatch);

/// The rust-hdl chip as a [`Clocked`] level: the memory image's words answer its memory
/// requests; half a clock low (inputs applied, logic settled: what `probe` shows), then the
/// rising edge.
pub struct RtlChip<'c, C: RtlPorts> {
    pub chip: &'c mut C,
    words: Vec<C::Word>,
    err: Option<String>,
}

impl<'c, C: RtlPorts> RtlChip<'c, C> {
    pub fn new(chip: &'c mut C, image: &QueryImage) -> Self {
        assert_eq!(
            image.kind,
            C::KIND,
            "a memory image of one chip run on another"
        );
        RtlChip {
            chip,
            words: image.memory.iter().map(C::word).collect(),
            err: None,
        }
    }
}

impl<C: RtlPorts> Clocked for RtlChip<'_, C> {
    fn outputs(&self) -> ChipOut {
        self.chip.outputs()
    }

    fn step(&mut self, i: &ChipIn, probe: bool) -> Option<Vec<u64>> {
        let resp = i.mem_resp.and_then(|a| self.words.get(a as usize));
        self.chip.set_inputs(i, resp);
        let mut probed = None;
        for high in [false, true] {
            self.chip.set_clock(high);
            if !simulate(self.chip, 1000) && self.err.is_none() {
                self.err = Some("the rust-hdl logic did not settle".into());
            }
            if !high && probe {
                probed = Some(self.chip.probes());
            }
        }
        probed
    }

    fn probe_list(&self) -> &'static crate::chip::probes::Probes {
        C::PROBES
    }

    fn fault(&self) -> Option<String> {
        self.err.clone()
    }
}

/// How a query of `image` is driven: every result read at once unless `reader` says
/// otherwise.
pub fn drive(image: &QueryImage, memory: MemClocks, reader: Reader, max_cycles: u64) -> Drive {
    Drive {
        memory,
        word_bits: image.word_bits,
        reader,
        words: image.memory.len() as u32,
        max_cycles,
    }
}

/// Runs one query on the rust-hdl chip (fresh from `chip_top`, or after a finished
/// query) with the shared driver ([`crate::cycle::drive::run_query`]).
pub fn run_query<C: RtlPorts>(
    chip: &mut C,
    image: &QueryImage,
    d: &Drive,
) -> Result<ChipTrace, ChipError> {
    crate::cycle::drive::run_query(
        &mut RtlChip::new(chip, image),
        &image.writes,
        d,
        false,
        |_, _| Ok(()),
        false,
    )
}

/// [`run_query`] writing a VCD of the traversal to `path` ([`ProbeVcd`](crate::cycle::drive::ProbeVcd): the signals of
/// the chip's probes, one scope per unit under `chip`, one time unit per clock). For
/// GTKWave with its save file ([`Probes::gtkw`](crate::chip::probes::Probes::gtkw)). (A VCD of every rust-hdl signal would be
/// about 600 kB per clock, mostly T.CHECK's.)
pub fn run_query_vcd<C: RtlPorts>(
    chip: &mut C,
    image: &QueryImage,
    d: &Drive,
    path: &std::path::Path,
) -> Result<ChipTrace, ChipError> {
    let mut vcd = open_vcd(path, C::PROBES, &[], 0..u64::MAX)?;
    let trace = crate::cycle::drive::run_query(
        &mut RtlChip::new(chip, image),
        &image.writes,
        d,
        true,
        |t, p| vcd.cycle(t, &p.unwrap_or_default()),
        false,
    )?;
    Ok(trace)
}

/// Which RTL chip runs a query of this configuration, traversal and cycle-model
/// parameters, and in which order; otherwise what to change.
pub fn rtl_order(
    cfg: &ChipConfig,
    traversal: Traversal,
    p: &Params,
) -> Result<(ChipKind, Order), String> {
    if ChipKind::built(cfg).next().is_none() {
        let mut built: Vec<String> = vec![];
        for k in ChipKind::ALL {
            let c = format!("k = {}, format = \"{}\"", k.config().k, k.config().format);
            if !built.contains(&c) {
                built.push(c);
            }
        }
        return Err(format!(
            "the RTL chips are built for {}, all with T.CHECK to nearest-even (the DOP lanes round either way); this scene has k = {}, format {}, tri_rounding {:?}: set [chip] to one of them",
            built.join(" or "), cfg.k, cfg.format, cfg.tri_rounding
        ));
    }
    let Some(kind) = ChipKind::of(cfg, p.dop_interval, p.tri_interval, p.depth) else {
        let ii: Vec<String> = ChipKind::built(cfg)
            .map(|k| {
                let depth = match k.depth() {
                    Depth::Asic => String::new(),
                    d => format!(" at depth = \"{}\"", d.name()),
                };
                format!(
                    "{} and {}{depth} ({})",
                    k.dop_interval(),
                    k.tri_interval(),
                    k.name()
                )
            })
            .collect();
        return Err(format!(
            "no RTL chip of this configuration takes a DOP pair every {} clocks and a TRI_UNIT pair every {} at depth = \"{}\": its chips have dop_interval and tri_interval {}: set [timing] dop_interval, tri_interval and depth to one of them, or drop cross_check",
            p.dop_interval,
            p.tri_interval,
            p.depth.name(),
            ii.join(" or ")
        ));
    };
    kind.reads(cfg)?;
    if p.tri_prefetch {
        return Err("the RTL chips ask for a leaf pair's triangle words when it reaches the leaf register; this scene has [timing] tri_prefetch = true: remove it".into());
    }
    let rtl = Params {
        memory: p.memory,
        prefetch: p.prefetch,
        outstanding: p.outstanding,
        issue_spacing: p.issue_spacing,
        credit: p.credit,
        clock_ps: p.clock_ps,
        ..Params::of(kind)
    };
    if *p != rtl {
        let r = Params::RTL;
        return Err(format!(
            "the RTL chip has the [timing] of the default (queue_entries {}, dop_latency {}, tri_latency {}, tri_fifo {}) but for memory, issue_spacing, credit, prefetch and outstanding: remove the others from the scene's [timing]",
            r.queue_entries, r.dop_latency, r.tri_latency, r.tri_fifo
        ));
    }
    let (pf, out, credit) = (
        chips::PORT_PREFETCH as u32,
        chips::PORT_OUTSTANDING as u32,
        chips::CREDIT_MAX as u32,
    );
    if p.prefetch > pf || p.outstanding > out || p.credit > credit {
        return Err(format!(
            "the RTL chip prefetches at most {pf} pairs with at most {out} requests outstanding and a credit of at most {credit} (this scene: prefetch {}, outstanding {}, credit {}): lower them in [timing]",
            p.prefetch, p.outstanding, p.credit
        ));
    }
    match traversal.order() {
        Some(order) => Ok((kind, order)),
        None => Err(format!(
            "the RTL chip's D_CNTR runs the fifo or lifo traversal, not {}: set [query] traversal",
            traversal.name()
        )),
    }
}

/// Runs one pose on the rust-hdl chip in lockstep with the cycle model (on a thread with
/// the big stack the RTL needs): every output and traversal signal equal after every clock.
/// Errors name the cycle and the signal of the first difference, or what the RTL chip
/// cannot run.
pub fn cross_check(
    chip: &crate::query::Chip,
    pose: &crate::pose::Pose,
    mode: Mode,
    traversal: Traversal,
    p: Params,
    max_cycles: u64,
) -> Result<ChipTrace, String> {
    let (kind, order) = rtl_order(&chip.cfg, traversal, &p)?;
    let setup = chip.setup(pose);
    let image = QueryImage::new(kind, &chip.a, &chip.b, &setup, order, mode, &p, &chip.cfg)?;
    let d = drive(&image, p.memory_clocks()?, Reader::default(), max_cycles);
    struct Lockstep<'q> {
        model: crate::cycle::chip::Chip<'q>,
        image: &'q QueryImage,
        d: &'q Drive,
    }
    impl OnChip for Lockstep<'_> {
        type Out = Result<ChipTrace, String>;
        fn run<C: RtlPorts>(self, mut rtl: C) -> Self::Out {
            let mut ls = crate::cycle::drive::Lockstep::new(
                RtlChip::new(&mut rtl, self.image),
                self.model,
                ("rust-hdl", "cycle model"),
            );
            crate::cycle::drive::run_query(
                &mut ls,
                &self.image.writes,
                self.d,
                true,
                |_, _| Ok(()),
                false,
            )
            .map_err(|e| e.0)
        }
    }
    std::thread::scope(|s| {
        std::thread::Builder::new()
            .stack_size(1 << 30)
            .spawn_scoped(s, || {
                let model =
                    crate::cycle::chip::Chip::new(&chip.cfg, p, &chip.a, &chip.b, &setup, false)?;
                with_chip::<QUEUE_BITS, { QUEUE_BITS + 1 }, { QUEUE_BITS - 1 }, _>(
                    kind,
                    Lockstep {
                        model,
                        image: &image,
                        d: &d,
                    },
                )
            })
            .map_err(|e| format!("cannot start the RTL simulation thread: {e}"))?
            .join()
            .map_err(|_| "the RTL simulation thread panicked".to_string())?
    })
}
