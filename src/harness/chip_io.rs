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
use crate::chip::config::ChipConfig;
use crate::chip::config::MemLayout;
use crate::chip::layout::{Dst, RecordMap};
use crate::chip::memory::{MemClocks, MemTiming, Memory};
use crate::chip::params::Params;
use crate::chip::ports::{ChipIn, ChipOut, Clocked};
use crate::chip::reg::{self, Mode, Order};
use crate::chip::rtl::{self as chips, ChipKind, QUEUE_BITS};
use crate::cycle::drive::open_vcd;
pub use crate::cycle::drive::{ChipError, ChipTrace, Drive, Reader};
use crate::dop::Node;
use crate::format::Format;
use crate::golden::host::HostSetup;
use crate::golden::memory::ObjectImage;
use crate::traversal::{QueryResult, Traversal};
use rust_hdl::prelude::*;
use std::fmt::Write as _;

/// What to do with an RTL chip, whichever its rust-hdl type ([`with_chip`]).
pub trait OnChip {
    type Out;
    fn run<C: RtlPorts>(self, chip: C) -> Self::Out;
}

macro_rules! dispatch {
    ($($(#[$doc:meta])* $kind:ident, $name:literal, $module:ident, $cfg:tt, $records:literal, $dop_ii:literal, $ii:literal, $speed:literal;)+) => {
        /// Builds `kind`'s rust-hdl chip with `2^N` queue entries (`NP1 = N + 1`, `NM1 = N -
        /// 1`), ready to simulate, and hands it to `f` (call on a thread with a big stack:
        /// TRI_UNIT and the k = 24 DOP unit are large).
        pub fn with_chip<const N: usize, const NP1: usize, const NM1: usize, F: OnChip>(kind: ChipKind, f: F) -> F::Out {
            let c = kind.config();
            match kind {
                $(ChipKind::$kind => f.run(crate::rtl::$module::chip_top::<N, NP1, NM1>(c.dop_rounding.op(), c.tri_rounding)),)+
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

/// The DOP unit's setup words `(load_addr, load_data)`: lane i's C_i0..2, c_i, and the
/// D.KLMSEL control `j_i0 | j_i1 << 5 | j_i2 << 10` at `8 i + 0..4`.
pub fn dop_unit_setup_words(fmt: Format, setup: &HostSetup) -> Vec<(u64, u64)> {
    let mut out = vec![];
    for (i, (cm, j)) in setup.cmat.iter().zip(&setup.j).enumerate() {
        let jw = j[0] as u64 | (j[1] as u64) << 5 | (j[2] as u64) << 10;
        let fields = [
            fmt.to_bits(cm[0]),
            fmt.to_bits(cm[1]),
            fmt.to_bits(cm[2]),
            fmt.to_bits(setup.cvec[i]),
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

/// Node `n`'s word at bit `at` of `w`: children by their ids ([`ObjectImage::ids`]), a
/// leaf's triangle index and (`records`) its triangle's record.
fn put_node_word(
    w: &mut Word,
    at: usize,
    kind: ChipKind,
    layout: MemLayout,
    obj: &ObjectImage,
    n: u32,
) {
    let (f, k) = (kind.config().format.dop, kind.config().k);
    let w_ = f.width() as usize;
    for (i, &d) in obj.tree.dop(n).iter().enumerate() {
        put(w, at + 1 + i * w_, w_, f.to_bits(d));
    }
    let (leaf, f0, f1) = match obj.tree.node(n) {
        Node::Inner([c0, c1]) => (false, obj.ids[c0 as usize], obj.ids[c1 as usize]),
        Node::Leaf(t) if layout == MemLayout::Records => (true, t, obj.tri_record(t)),
        Node::Leaf(t) => (true, t, 0),
    };
    put(w, at, 1, leaf as u64);
    put(w, at + 1 + k * w_, 32, f0 as u64);
    put(w, at + 33 + k * w_, 32, f1 as u64);
}

/// An object's node records and its triangle records, in `layout` (`chip::layout`): a
/// node record holds its nodes' words in their slots (`records`: slot 1 from bit
/// `node_bits`), a triangle record its triangle's word.
fn object_words(kind: ChipKind, layout: MemLayout, obj: &ObjectImage) -> [Vec<Word>; 2] {
    let f = kind.config().format;
    let node_bits = crate::chip::layout::node_bits(kind.config().k, f.dop.width() as usize);
    let mut nodes = vec![vec![0; kind.word_bits().div_ceil(64)]; obj.node_records() as usize];
    for n in 0..obj.tree.len() as u32 {
        let slot = if layout == MemLayout::Records {
            obj.ids[n as usize] as usize & 1
        } else {
            0
        };
        put_node_word(
            &mut nodes[obj.record(n) as usize],
            slot * node_bits,
            kind,
            layout,
            obj,
            n,
        );
    }
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
    let [na, ta] = object_words(kind, cfg.layout, a);
    let [nb, tb] = object_words(kind, cfg.layout, b);
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
        let mut writes: Vec<(u32, u32)> = dop_unit_setup_words(f.dop, setup)
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

fn bits<const B: usize>(w: &Word) -> Bits<B> {
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
    /// [`crate::chip::probes::PROBES`] as the logic shows them now.
    fn probes(&self) -> Vec<u64>;
}

macro_rules! rtl_ports {
    ($fmt:ident, $kind:expr) => {
        impl<const N: usize, const NP1: usize, const NM1: usize> RtlPorts
            for crate::rtl::$fmt::CollisionChip<N, NP1, NM1>
        {
            type Word = Bits<{ crate::rtl::$fmt::CHIP_WORD_BITS }>;
            const KIND: ChipKind = $kind;

            fn word(w: &Word) -> Self::Word {
                bits(w)
            }

            fn outputs(&self) -> ChipOut {
                let tag = self.res_tag.val().to_u64();
                ChipOut {
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

            fn set_inputs(&mut self, i: &ChipIn, resp: Option<&Self::Word>) {
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
                self.clock.next = Clock { clk: high };
            }

            fn probes(&self) -> Vec<u64> {
                self.probe()
            }
        }
    };
}
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

/// A query of the RTL test set: two meshes, a pose, order, mode and memory timing. The
/// same set runs in rust-hdl (tb/rtl_chip.rs) and, from `vectors/chip/`, in Verilog.
#[derive(Clone, Debug)]
pub struct ChipQuery {
    pub name: &'static str,
    /// Built-in mesh names ([`crate::mesh::builtin`]), or `bunny-patch:N`: the N bunny
    /// triangles whose centroids are nearest to triangle 0's.
    pub a: &'static str,
    pub b: &'static str,
    pub pose: crate::pose::Pose,
    /// The chip that runs it.
    pub chip: ChipKind,
    pub order: Order,
    pub mode: Mode,
    pub timing: MemTiming,
    /// How the host reads results.
    pub reader: Reader,
    /// The memory port (register [`PORT`](crate::chip::reg::PORT)): node pairs prefetched, requests outstanding at
    /// most, clocks between DOP issues (1: the queue's second write port), the credit.
    pub prefetch: u32,
    pub outstanding: u32,
    pub issue_spacing: u32,
    pub credit: u32,
    /// Lines of A's triangle cache (register [`TRI_CACHE`](crate::chip::reg::TRI_CACHE); 1: the single word held).
    pub tri_cache: u32,
    /// The memory layout (register [`MODE`](crate::chip::reg::MODE) bit 2; `records` on a chip that reads it).
    pub layout: MemLayout,
    /// Too long for rust-hdl (more than 500 s at [`ChipKind::rtl_clocks_per_second`]): its
    /// trace comes from the cycle model, and Verilator must reproduce it.
    pub large: bool,
}

/// The triangles of a [`ChipQuery`] mesh spec.
pub fn query_mesh(spec: &str) -> Result<Vec<crate::dop::tree::Tri>, String> {
    if let Some(n) = spec.strip_prefix("bunny-patch:") {
        let n: usize = n
            .parse()
            .map_err(|_| format!("`{spec}`: the patch size is not a number"))?;
        let tris = crate::mesh::builtin("bunny")
            .map_err(|e| e.to_string())?
            .triangles_f64();
        let c = |t: &crate::dop::tree::Tri| (t[0].coords + t[1].coords + t[2].coords) / 3.0;
        let c0 = c(&tris[0]);
        let mut idx: Vec<usize> = (0..tris.len()).collect();
        idx.sort_by(|&i, &j| {
            (c(&tris[i]) - c0)
                .norm()
                .total_cmp(&(c(&tris[j]) - c0).norm())
        });
        return Ok(idx[..n.min(tris.len())].iter().map(|&i| tris[i]).collect());
    }
    Ok(crate::mesh::builtin(spec)
        .map_err(|e| e.to_string())?
        .triangles_f64())
}

/// A query ready to run: the golden model's images and all-pairs answer, and the chip's
/// memory image and register writes.
pub struct PreparedQuery {
    pub chip: crate::query::Chip,
    pub golden_all: QueryResult,
    pub image: QueryImage,
}

impl ChipQuery {
    /// The cycle model's parameters of this query: the RTL chip's, with its memory and port.
    pub fn params(&self) -> crate::chip::params::Params {
        crate::chip::params::Params {
            memory: self.timing.into(),
            prefetch: self.prefetch,
            outstanding: self.outstanding,
            issue_spacing: self.issue_spacing,
            credit: self.credit,
            ..crate::chip::params::Params::of(self.chip)
        }
    }

    pub fn prepare(&self) -> Result<PreparedQuery, String> {
        let cfg = ChipConfig {
            tri_cache: self.tri_cache,
            layout: self.layout,
            ..self.chip.config()
        };
        let chip = crate::query::Chip::new(&query_mesh(self.a)?, &query_mesh(self.b)?, cfg)?;
        let golden_all = chip.query(&self.pose, Mode::All, crate::traversal::Traversal::Fifo);
        let image = QueryImage::new(
            self.chip,
            &chip.a,
            &chip.b,
            &chip.setup(&self.pose),
            self.order,
            self.mode,
            &self.params(),
            &cfg,
        )?;
        Ok(PreparedQuery {
            chip,
            golden_all,
            image,
        })
    }
}

/// The RTL query set. Small (rust-hdl in lockstep with the cycle model, in `cargo test`):
/// both orders and modes, three memory timings, procedural spheres and a bunny patch
/// against a slightly shifted copy of itself (sure hits and many uncertain pairs), and two
/// spheres apart (the root test only). Large (10^4 to 10^5 cycles; the exported Verilog
/// under Verilator in CI against the cycle model's traces): a few hundred triangles, both
/// orders and modes, several memory timings, a host that reads results slowly enough to
/// stall the traversal, sure hits mixed with uncertain pairs.
pub fn queries() -> Vec<ChipQuery> {
    use crate::pose::Pose;
    use Order::{Fifo, Lifo};
    let spheres = Pose::new(10.0, 20.0, 30.0, 0.8, 0.1, 0.0);
    let patch = Pose::new(0.0, 0.0, 0.0, 0.002, 0.001, 0.0);
    let q = |name, a, pose, order, mode, latency, interval| ChipQuery {
        name,
        a,
        b: a,
        pose,
        chip: ChipKind::K6E8m15,
        order,
        mode,
        timing: MemTiming {
            latency,
            interval,
            bus_bits: None,
        },
        reader: Reader::default(),
        prefetch: 0,
        outstanding: 1,
        issue_spacing: 2,
        credit: chips::CREDIT as u32,
        tri_cache: 1,
        layout: MemLayout::Words,
        large: false,
    };
    let big = |name, a, pose, order, mode, latency, interval, period| ChipQuery {
        reader: Reader { period },
        large: true,
        ..q(name, a, pose, order, mode, latency, interval)
    };
    let big_spheres = Pose::new(10.0, 20.0, 30.0, 0.9, 0.1, 0.05);
    vec![
        q(
            "sphere_fifo_all",
            "sphere:12",
            spheres,
            Fifo,
            Mode::All,
            1,
            1,
        ),
        q(
            "sphere_lifo_all",
            "sphere:12",
            spheres,
            Lifo,
            Mode::All,
            3,
            2,
        ),
        q(
            "sphere_fifo_first",
            "sphere:12",
            spheres,
            Fifo,
            Mode::First,
            2,
            1,
        ),
        q(
            "sphere_lifo_first",
            "sphere:12",
            spheres,
            Lifo,
            Mode::First,
            1,
            1,
        ),
        q(
            "bunny_lifo_all",
            "bunny-patch:12",
            patch,
            Lifo,
            Mode::All,
            1,
            1,
        ),
        q(
            "bunny_fifo_first",
            "bunny-patch:12",
            patch,
            Fifo,
            Mode::First,
            1,
            1,
        ),
        q(
            "apart_lifo_first",
            "sphere:12",
            Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0),
            Lifo,
            Mode::First,
            1,
            1,
        ),
        // sure hits and uncertain pairs; the FIFO holds about 1,000 entries at its widest
        big(
            "big_sphere_fifo_all",
            "sphere:200",
            big_spheres,
            Fifo,
            Mode::All,
            1,
            1,
            1,
        ),
        big(
            "big_sphere_lifo_all",
            "sphere:320",
            big_spheres,
            Lifo,
            Mode::All,
            4,
            2,
            1,
        ),
        // the host reads one result in 40 clocks: TRI_UNIT's FIFO fills and the credit
        // stalls the DOP unit
        big(
            "big_patch_lifo_all_slow_host",
            "bunny-patch:300",
            patch,
            Lifo,
            Mode::All,
            2,
            1,
            40,
        ),
        // in e8m15 the first sure hit comes after 180 uncertain results (a long first-hit query)
        big(
            "big_patch_fifo_first",
            "bunny-patch:120",
            patch,
            Fifo,
            Mode::First,
            3,
            1,
            1,
        ),
        big(
            "big_patch_lifo_first",
            "bunny-patch:300",
            patch,
            Lifo,
            Mode::First,
            1,
            1,
            1,
        ),
        // the prefetching memory port (register `reg::PORT`): node words asked for pairs ahead,
        // several requests outstanding, at a memory latency of 8; an issue every clock
        // (both child entries pushed in one) with a credit of 24 to 48 but in the last
        ChipQuery {
            prefetch: 6,
            outstanding: 8,
            issue_spacing: 1,
            credit: 32,
            ..q(
                "sphere_lifo_prefetch",
                "sphere:12",
                spheres,
                Lifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            prefetch: 3,
            outstanding: 4,
            issue_spacing: 1,
            credit: 24,
            ..q(
                "bunny_fifo_prefetch",
                "bunny-patch:12",
                patch,
                Fifo,
                Mode::First,
                8,
                1,
            )
        },
        ChipQuery {
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            ..big(
                "big_sphere_lifo_prefetch",
                "sphere:320",
                big_spheres,
                Lifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
        ChipQuery {
            prefetch: 14,
            outstanding: 16,
            ..big(
                "big_sphere_fifo_prefetch",
                "sphere:200",
                big_spheres,
                Fifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
        // A's triangle cache (register `reg::TRI_CACHE`): 4 lines, so that lines are shared and
        // replaced, at full speed (rust-hdl); 128 lines (WSCG'03) on a bunny patch
        ChipQuery {
            prefetch: 6,
            outstanding: 8,
            issue_spacing: 1,
            credit: 32,
            tri_cache: 4,
            ..q(
                "sphere_fifo_cache",
                "sphere:12",
                spheres,
                Fifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            tri_cache: 128,
            ..big(
                "big_patch_lifo_cache",
                "bunny-patch:300",
                patch,
                Lifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
        // the papers' chip (k = 24, binary32): the root test only (Icarus), a short
        // first-hit query at full speed (rust-hdl), whole queries at full speed and at the
        // reset point
        ChipQuery {
            chip: ChipKind::K24B32,
            ..q(
                "k24_apart_lifo_first",
                "sphere:12",
                Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0),
                Lifo,
                Mode::First,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            prefetch: 3,
            outstanding: 4,
            issue_spacing: 1,
            credit: 24,
            ..q(
                "k24_sphere_lifo_first",
                "sphere:12",
                spheres,
                Lifo,
                Mode::First,
                8,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            ..big(
                "k24_big_sphere_lifo_prefetch",
                "sphere:320",
                big_spheres,
                Lifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 63,
            ..big(
                "k24_big_sphere_fifo_prefetch",
                "sphere:200",
                big_spheres,
                Fifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            ..big(
                "k24_big_patch_lifo_first",
                "bunny-patch:300",
                patch,
                Lifo,
                Mode::First,
                2,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            tri_cache: 128,
            ..big(
                "k24_big_sphere_fifo_cache",
                "sphere:200",
                big_spheres,
                Fifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
        // the papers' chip reading the records layout (register `reg::MODE` bit 2: sibling nodes in
        // one 2,048-bit record, triangles in leaf order, one record held per object): a
        // bunny patch through a 2-line triangle cache at full speed (rust-hdl), whole
        // queries at full speed through the 128-line cache and at the reset point
        ChipQuery {
            chip: ChipKind::K24B32,
            layout: MemLayout::Records,
            prefetch: 3,
            outstanding: 4,
            issue_spacing: 1,
            credit: 24,
            tri_cache: 2,
            ..q(
                "k24_rec_patch_fifo_all",
                "bunny-patch:4",
                patch,
                Fifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            layout: MemLayout::Records,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            tri_cache: 128,
            ..big(
                "k24_big_rec_sphere_fifo_cache",
                "sphere:200",
                big_spheres,
                Fifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            layout: MemLayout::Records,
            ..big(
                "k24_big_rec_patch_lifo_all",
                "bunny-patch:300",
                patch,
                Lifo,
                Mode::All,
                2,
                1,
                1,
            )
        },
        // the papers' chip with an e8m15 DOP unit (k24r: format e8m15/binary32): the root
        // test (Icarus), a few leaf pairs (rust-hdl), whole queries at full speed (the second
        // through the 128-line triangle cache) and at the reset point
        ChipQuery {
            chip: ChipKind::K24E8m15B32,
            ..q(
                "k24r_apart_lifo_first",
                "sphere:12",
                Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0),
                Lifo,
                Mode::First,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24E8m15B32,
            prefetch: 3,
            outstanding: 4,
            issue_spacing: 1,
            credit: 24,
            ..q(
                "k24r_patch_fifo_all",
                "bunny-patch:4",
                patch,
                Fifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24E8m15B32,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 63,
            ..big(
                "k24r_big_sphere_fifo_prefetch",
                "sphere:200",
                big_spheres,
                Fifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24E8m15B32,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            tri_cache: 128,
            ..big(
                "k24r_big_sphere_lifo_cache",
                "sphere:320",
                big_spheres,
                Lifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24E8m15B32,
            ..big(
                "k24r_big_patch_lifo_first",
                "bunny-patch:300",
                patch,
                Lifo,
                Mode::First,
                2,
                1,
                1,
            )
        },
        // the k = 6 chip with TRI_UNIT folded to a pair every 16 clocks (issue 33): the root
        // test (Icarus), a bunny patch whose leaf pairs wait for the unit's slots at full
        // speed (rust-hdl), whole queries at full speed and at the reset point (Verilator;
        // rust-hdl runs this chip ten times faster than `chip_e8m15_k6`, so they are not
        // `large`, but only the first two run in rust-hdl)
        ChipQuery {
            chip: ChipKind::K6E8m15Fold16,
            ..q(
                "fold16_apart_lifo_first",
                "sphere:12",
                Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0),
                Lifo,
                Mode::First,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K6E8m15Fold16,
            prefetch: 3,
            outstanding: 4,
            issue_spacing: 1,
            credit: 24,
            ..q(
                "fold16_patch_fifo_all",
                "bunny-patch:12",
                patch,
                Fifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K6E8m15Fold16,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            ..q(
                "fold16_sphere_lifo_prefetch",
                "sphere:320",
                big_spheres,
                Lifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K6E8m15Fold16,
            ..q(
                "fold16_patch_lifo_first",
                "bunny-patch:300",
                patch,
                Lifo,
                Mode::First,
                1,
                1,
            )
        },
        // the k = 6 chip with both units folded, the DOP unit a pair every 6 clocks and
        // TRI_UNIT every 32 (issue 33; the chip for an LFE5U-85F): the root test (Icarus), a
        // bunny patch at full speed whose pairs wait for both units' slots (rust-hdl), whole
        // queries at full speed and at the reset point (Verilator)
        ChipQuery {
            chip: ChipKind::K6E8m15Dop6Tri32,
            ..q(
                "dop6tri32_apart_lifo_first",
                "sphere:12",
                Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0),
                Lifo,
                Mode::First,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K6E8m15Dop6Tri32,
            prefetch: 3,
            outstanding: 4,
            issue_spacing: 1,
            credit: 24,
            ..q(
                "dop6tri32_patch_fifo_all",
                "bunny-patch:12",
                patch,
                Fifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K6E8m15Dop6Tri32,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            ..q(
                "dop6tri32_sphere_lifo_prefetch",
                "sphere:320",
                big_spheres,
                Lifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K6E8m15Dop6Tri32,
            ..q(
                "dop6tri32_patch_lifo_first",
                "bunny-patch:300",
                patch,
                Lifo,
                Mode::First,
                1,
                1,
            )
        },
    ]
}

/// Writes `<dir>/<query>.mem` and `<dir>/<query>.host` for every query of [`queries`] and
/// `<dir>/queries.txt` (`name latency interval reader-period chip` per line), the inputs of
/// scripts/run-chip.sh. The expected traces (`<query>.expect`) are the rust-hdl chip's,
/// written by `CCHIP_BLESS=1 cargo test --release --test rtl_chip`.
pub fn write_vectors(dir: &std::path::Path) -> Result<Vec<String>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut list = String::new();
    let mut written = vec![];
    for q in queries() {
        let p = q.prepare()?;
        for (ext, text) in [
            ("mem", p.image.memory_hex()),
            ("host", p.image.writes_hex()),
        ] {
            let path = dir.join(format!("{}.{ext}", q.name));
            std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
            written.push(path.display().to_string());
        }
        let _ = writeln!(
            list,
            "{} {} {} {} {}",
            q.name,
            q.timing.latency,
            q.timing.interval,
            q.reader.period,
            q.chip.name()
        );
    }
    let path = dir.join("queries.txt");
    std::fs::write(&path, list).map_err(|e| format!("{}: {e}", path.display()))?;
    written.push(path.display().to_string());
    Ok(written)
}

/// [`run_query`] writing a VCD of the traversal to `path` ([`ProbeVcd`](crate::cycle::drive::ProbeVcd): the signals of
/// [`crate::chip::probes::PROBES`], one scope per unit under `chip`, one time unit per clock). For
/// GTKWave with scripts/gtkw/chip_e8m15_k6.gtkw. (A VCD of every rust-hdl signal would be
/// about 600 kB per clock, mostly T.CHECK's.)
pub fn run_query_vcd<C: RtlPorts>(
    chip: &mut C,
    image: &QueryImage,
    d: &Drive,
    path: &std::path::Path,
) -> Result<ChipTrace, ChipError> {
    let mut vcd = open_vcd(path, &[], 0..u64::MAX)?;
    let trace = crate::cycle::drive::run_query(
        &mut RtlChip::new(chip, image),
        &image.writes,
        d,
        true,
        |t, p| {
            vcd.cycle(t, &p.unwrap_or_default())
                .map_err(|e| format!("{}: {e}", path.display()))
        },
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
            "the RTL chips are built for {}, all with dop_rounding = \"outward\" and T.CHECK to nearest-even; this scene has k = {}, format {}, dop_rounding {}, tri_rounding {:?}: set [chip] to one of them",
            built.join(" or "), cfg.k, cfg.format, cfg.dop_rounding, cfg.tri_rounding
        ));
    }
    let Some(kind) = ChipKind::of(cfg, p.dop_interval, p.tri_interval) else {
        let ii: Vec<String> = ChipKind::built(cfg)
            .map(|k| {
                format!(
                    "{} and {} ({})",
                    k.dop_interval(),
                    k.tri_interval(),
                    k.name()
                )
            })
            .collect();
        return Err(format!(
            "no RTL chip of this configuration takes a DOP pair every {} clocks and a TRI_UNIT pair every {}: its chips have dop_interval and tri_interval {}: set [timing] dop_interval and tri_interval to one of them, or drop cross_check",
            p.dop_interval,
            p.tri_interval,
            ii.join(" or ")
        ));
    };
    kind.reads(cfg)?;
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Words are laid out as `crate::golden::memory` says: a node's leaf bit, distances and fields,
    /// a triangle's 24 values and two flags, most significant hex digit first.
    #[test]
    fn memory_words_and_writes() {
        let q = queries()
            .into_iter()
            .find(|q| q.name == "sphere_fifo_all")
            .unwrap();
        let p = q.prepare().unwrap();
        let a = &p.chip.a;
        assert_eq!(
            p.image.memory.len(),
            2 * a.tree.len() + 2 * a.tri_count(),
            "A and B are the same sphere"
        );
        let f = ChipKind::K6E8m15.config().format.dop;
        let w = &p.image.memory[0];
        let field = |w: &Word, at: usize, bits: usize| {
            (0..bits).fold(0u64, |v, k| {
                v | (w[(at + k) / 64] >> ((at + k) % 64) & 1) << k
            })
        };
        // hand-derived widths: 24-bit words, 1 + 6 * 24 + 64 node bits, 23 * 24 + 2 triangle bits
        const W: usize = 24;
        const NODE_BITS: usize = 209;
        const MEM_BITS: usize = 554;
        assert_eq!(W, f.width() as usize);
        // (the RTL's word widths are checked against the layout at compile time, rtl/mod.rs)
        assert_eq!(ChipKind::K6E8m15.word_bits(), MEM_BITS);
        // the papers' chip: 1 + 24 * 32 + 64 node bits, wider than its 23 * 32 + 2 triangle bits
        // a record: two node words padded to 256 bytes (it also reads the `records` layout)
        assert_eq!(ChipKind::K24B32.word_bits(), 2048);
        // e8m15 nodes, binary32 triangles: 1 + 24 * 24 + 64 = 641 node bits, 23 * 32 + 2 = 738
        assert_eq!(ChipKind::K24E8m15B32.word_bits(), 738);
        assert_eq!(
            crate::chip::layout::Layout::new(&ChipKind::K24E8m15B32.config()).node_bits,
            641
        );
        assert!(p.image.memory[..a.tree.len()]
            .iter()
            .all(|w| field(w, NODE_BITS, 64) == 0
                && field(w, NODE_BITS + 64, MEM_BITS - NODE_BITS - 64) == 0));
        assert_eq!(field(w, 0, 1), 0, "the root is inner");
        assert_eq!(field(w, 1 + 2 * W, W), f.to_bits(a.tree.dop(0)[2]));
        let Node::Inner([c0, c1]) = a.tree.node(0) else {
            panic!()
        };
        assert_eq!(
            (field(w, 145, 32), field(w, 177, 32)),
            (c0 as u64, c1 as u64)
        );
        let t = &p.image.memory[a.tree.len() + 3];
        let l = LeafIn::of(f, &a.tri(3));
        assert_eq!(field(t, 4 * W, W), l.v[1][1]);
        assert_eq!(field(t, 9 * W + 5 * W, W), l.m[5]);
        assert_eq!(field(t, 22 * W, W), l.alpha_f);
        assert_eq!(
            field(t, 23 * W, 2),
            l.v_exact as u64 | (l.degenerate as u64) << 1
        );
        let hex = p.image.memory_hex();
        let line = hex.lines().nth(a.tree.len() + 3).unwrap();
        assert_eq!(line.len(), 139);
        assert_eq!(
            u64::from_str_radix(&line[line.len() - 6..], 16).unwrap(),
            l.v[0][0]
        );
        assert!(p.image.writes.contains(&(reg::MODE, 0)));
        assert!(p.image.writes_hex().lines().all(|l| l.len() == 11));
    }

    #[test]
    fn too_large_a_tree_is_an_error() {
        let big = crate::mesh::builtin("sphere:40000")
            .unwrap()
            .triangles_f64();
        let chip = crate::query::Chip::new(&big, &big[..1], ChipKind::K6E8m15.config()).unwrap();
        let setup = chip.setup(&crate::pose::Pose::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0));
        let e = QueryImage::new(
            ChipKind::K6E8m15,
            &chip.a,
            &chip.b,
            &setup,
            Order::Lifo,
            Mode::All,
            &Params::RTL,
            &chip.cfg,
        )
        .unwrap_err();
        assert!(e.contains("16 bits"), "{e}");
    }
}
