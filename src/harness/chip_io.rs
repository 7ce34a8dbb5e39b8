//! The host and memory side of the RTL collision chip ([`e8m15::CollisionChip`]): the
//! memory image and register writes of one query, a memory model with configurable
//! timing, the rust-hdl driver that runs a whole query, and the query trace that the
//! Verilog testbench (`scripts/verilog/chip_tb.v`) prints in the same format, so that the
//! two simulations are compared line by line.
//!
//! The chip is k = 6, e8m15 ([`Format::REDUCED`]), DOP lanes rounding outward, T.CHECK to
//! nearest-even: [`CHIP_CONFIG`].

use crate::rtl::e8m15::CollisionChip;
use super::tri_io::{tri_unit_setup_words, LeafIn};
pub use crate::cycle::drive::{ChipError, ChipTrace, Drive, Reader};
use crate::cycle::drive::open_vcd;
use crate::cycle::{ChipIn, ChipOut, Clocked};
pub use crate::cycle::MemTiming;
use crate::config::{ChipConfig, DopRounding, Formats};
use crate::dop::{HostSetup, Node};
use crate::format::{Format, Rounding};
use crate::memory::ObjectImage;
use crate::traversal::{Mode, QueryResult};
use rust_hdl::prelude::*;
use std::fmt::Write as _;

/// The configuration of the RTL chip.
pub const CHIP_CONFIG: ChipConfig =
    ChipConfig { k: 6, format: Formats { dop: Format::REDUCED, tri: Format::REDUCED }, dop_rounding: DopRounding::Outward, tri_rounding: Rounding::NearestEven };
/// Memory word bits (a triangle word; a node word is the low [`NODE_BITS`]).
pub const MEM_BITS: usize = 578;
/// Node word bits: leaf bit, 6 distances, two 32-bit fields.
pub const NODE_BITS: usize = 209;
const W: usize = 24;

/// The host registers' addresses (see [`CollisionChip`]).
pub mod reg {
    pub use crate::cycle::chip::reg::*;
    /// TRI_UNIT's setup words (the DOP unit's are at 0).
    pub const TRI_SETUP: u32 = 0x100;
}

/// The DOP unit's setup words `(load_addr, load_data)`: lane i's C_i0..2, c_i, and the
/// D.KLMSEL control `j_i0 | j_i1 << 5 | j_i2 << 10` at `8 i + 0..4`.
pub fn dop_unit_setup_words(fmt: Format, setup: &HostSetup) -> Vec<(u64, u64)> {
    let mut out = vec![];
    for (i, (cm, j)) in setup.cmat.iter().zip(&setup.j).enumerate() {
        let jw = j[0] as u64 | (j[1] as u64) << 5 | (j[2] as u64) << 10;
        let fields = [fmt.to_bits(cm[0]), fmt.to_bits(cm[1]), fmt.to_bits(cm[2]), fmt.to_bits(setup.cvec[i]), jw];
        out.extend(fields.iter().enumerate().map(|(f, &v)| ((8 * i + f) as u64, v)));
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

fn node_word(obj: &ObjectImage, n: u32) -> Word {
    let f = CHIP_CONFIG.format.dop;
    let mut w = vec![0; MEM_BITS.div_ceil(64)];
    for (i, &d) in obj.tree.dop(n).iter().enumerate() {
        put(&mut w, 1 + i * W, W, f.to_bits(d));
    }
    let (leaf, f0, f1) = match obj.tree.nodes[n as usize] {
        Node::Inner([c0, c1]) => (false, c0, c1),
        Node::Leaf(t) => (true, t, 0),
    };
    put(&mut w, 0, 1, leaf as u64);
    put(&mut w, 1 + 6 * W, 32, f0 as u64);
    put(&mut w, 33 + 6 * W, 32, f1 as u64);
    w
}

fn tri_word(l: &LeafIn) -> Word {
    let mut w = vec![0; MEM_BITS.div_ceil(64)];
    let fields = l.v.iter().flatten().chain(&l.m).chain([&l.e_lin, &l.e_tr, &l.l_norm]);
    for (i, &x) in fields.enumerate() {
        put(&mut w, i * W, W, x);
    }
    put(&mut w, 24 * W, 1, l.v_exact as u64);
    put(&mut w, 24 * W + 1, 1, l.degenerate as u64);
    w
}

/// Everything the host gives the chip for one query: the memory image (A's nodes, A's
/// triangles, B's nodes, B's triangles) and the register writes, mode last.
#[derive(Clone, Debug)]
pub struct QueryImage {
    pub memory: Vec<Word>,
    pub writes: Vec<(u32, u32)>,
}

impl QueryImage {
    /// The memory port's register is written from `p` ([`crate::cycle::chip::control_writes`]).
    /// Errors if a tree has more nodes than the 16-bit node ids of D_CNTR address, or the
    /// image more words than the 24-bit memory address.
    pub fn new(a: &ObjectImage, b: &ObjectImage, setup: &HostSetup, lifo: bool, mode: Mode, p: &crate::cycle::Params) -> Result<Self, String> {
        let f = CHIP_CONFIG.format;
        for (name, o) in [("A", a), ("B", b)] {
            if o.tree.len() > 1 << 16 {
                return Err(format!(
                    "object {name} has {} DOP-tree nodes; the RTL chip's node ids are 16 bits (at most 32,768 triangles)",
                    o.tree.len()
                ));
            }
        }
        let mut memory = vec![];
        for o in [a, b] {
            memory.extend((0..o.tree.len() as u32).map(|n| node_word(o, n)));
            memory.extend(o.tris.iter().map(|t| tri_word(&LeafIn::of(f.tri, t))));
        }
        if memory.len() > 1 << 24 {
            return Err(format!("memory image of {} words; the RTL chip addresses 2^24", memory.len()));
        }
        let mut writes: Vec<(u32, u32)> = dop_unit_setup_words(f.dop, setup).into_iter().map(|(a, d)| (a as u32, d as u32)).collect();
        writes.extend(tri_unit_setup_words(f.tri, setup).into_iter().map(|(a, d)| (reg::TRI_SETUP + a as u32, d as u32)));
        writes.extend(crate::cycle::chip::control_writes(a, b, lifo, mode, p));
        Ok(QueryImage { memory, writes })
    }

    /// `$readmemh` text: one word per line, most significant digit first.
    pub fn memory_hex(&self) -> String {
        let mut s = String::new();
        for w in &self.memory {
            let digits = MEM_BITS.div_ceil(4);
            let hex: String = w.iter().rev().map(|l| format!("{l:016x}")).collect();
            let _ = writeln!(s, "{}", &hex[hex.len() - digits..]);
        }
        s
    }

    /// `$readmemh` text of the register writes: `{addr[10], data[32]}` per line.
    pub fn writes_hex(&self) -> String {
        self.writes.iter().map(|&(a, d)| format!("{:011x}\n", (a as u64) << 32 | d as u64)).collect()
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

/// The rust-hdl chip as a [`Clocked`] level: the memory image's words answer its memory
/// requests; half a clock low (inputs applied, logic settled: what `probe` shows), then the
/// rising edge.
pub struct RtlChip<'c, const N: usize, const NP1: usize, const NM1: usize> {
    pub chip: &'c mut CollisionChip<N, NP1, NM1>,
    words: Vec<Bits<MEM_BITS>>,
    err: Option<String>,
}

impl<'c, const N: usize, const NP1: usize, const NM1: usize> RtlChip<'c, N, NP1, NM1> {
    pub fn new(chip: &'c mut CollisionChip<N, NP1, NM1>, image: &QueryImage) -> Self {
        RtlChip { chip, words: image.memory.iter().map(bits::<MEM_BITS>).collect(), err: None }
    }
}

impl<const N: usize, const NP1: usize, const NM1: usize> Clocked for RtlChip<'_, N, NP1, NM1> {
    fn outputs(&self) -> ChipOut {
        let c = &self.chip;
        let tag = c.res_tag.val().to_u64();
        ChipOut {
            busy: c.busy.val(),
            done: c.done.val(),
            overflow: c.overflow.val(),
            max_depth: c.max_depth.val().to_u64(),
            dop_tests: c.dop_tests.val().to_u64(),
            tri_tests: c.tri_tests.val().to_u64(),
            node_fetches: c.node_fetches.val().to_u64(),
            tri_fetches: c.tri_fetches.val().to_u64(),
            mem_req_valid: c.mem_req_valid.val(),
            mem_req_addr: c.mem_req_addr.val().to_u64() as u32,
            res_valid: c.res_valid.val(),
            res_tag: ((tag & 0xffff) as u32, (tag >> 16) as u32),
            res_uncertain: c.res_uncertain.val(),
        }
    }

    fn step(&mut self, i: &ChipIn, probe: bool) -> Option<Vec<u64>> {
        let c = &mut *self.chip;
        c.host_we.next = i.host_we;
        c.host_addr.next = (i.host_addr as u64).into();
        c.host_data.next = (i.host_data as u64).into();
        c.start.next = i.start;
        c.mem_req_ready.next = i.mem_req_ready;
        c.mem_resp_valid.next = i.mem_resp.is_some();
        if let Some(w) = i.mem_resp.and_then(|a| self.words.get(a as usize)) {
            c.mem_resp_data.next = *w;
        }
        c.res_ready.next = i.res_ready;
        let mut probed = None;
        for high in [false, true] {
            c.clock.next = Clock { clk: high };
            if !simulate(c, 1000) && self.err.is_none() {
                self.err = Some("the rust-hdl logic did not settle".into());
            }
            if !high && probe {
                probed = Some(c.probe());
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
pub fn drive(image: &QueryImage, memory: crate::cycle::Memory, reader: Reader, max_cycles: u64) -> Drive {
    Drive { memory, word_bits: MEM_BITS as u32, reader, words: image.memory.len() as u32, max_cycles }
}

/// Runs one query on the rust-hdl chip (fresh from `chip_top`, or after a finished
/// query) with the shared driver ([`crate::cycle::drive::run_query`]).
pub fn run_query<const N: usize, const NP1: usize, const NM1: usize>(
    chip: &mut CollisionChip<N, NP1, NM1>,
    image: &QueryImage,
    d: &Drive,
) -> Result<ChipTrace, ChipError> {
    crate::cycle::drive::run_query(&mut RtlChip::new(chip, image), &image.writes, d, false, |_, _| Ok(()), None)
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
    pub lifo: bool,
    pub mode: Mode,
    pub timing: MemTiming,
    /// How the host reads results.
    pub reader: Reader,
    /// The memory port (register 0x126): node pairs prefetched, requests outstanding at
    /// most, clocks between DOP issues (1: the queue's second write port), the credit.
    pub prefetch: u32,
    pub outstanding: u32,
    pub issue_spacing: u32,
    pub credit: u32,
    /// Too long for rust-hdl (10^4 cycles and more): its trace comes from the cycle
    /// model, and Verilator must reproduce it.
    pub large: bool,
}

/// The triangles of a [`ChipQuery`] mesh spec.
pub fn query_mesh(spec: &str) -> Result<Vec<crate::dop::tree::Tri>, String> {
    if let Some(n) = spec.strip_prefix("bunny-patch:") {
        let n: usize = n.parse().map_err(|_| format!("`{spec}`: the patch size is not a number"))?;
        let tris = crate::mesh::builtin("bunny").map_err(|e| e.to_string())?.triangles_f64();
        let c = |t: &crate::dop::tree::Tri| (t[0].coords + t[1].coords + t[2].coords) / 3.0;
        let c0 = c(&tris[0]);
        let mut idx: Vec<usize> = (0..tris.len()).collect();
        idx.sort_by(|&i, &j| (c(&tris[i]) - c0).norm().total_cmp(&(c(&tris[j]) - c0).norm()));
        return Ok(idx[..n.min(tris.len())].iter().map(|&i| tris[i]).collect());
    }
    Ok(crate::mesh::builtin(spec).map_err(|e| e.to_string())?.triangles_f64())
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
    pub fn params(&self) -> crate::cycle::Params {
        crate::cycle::Params {
            memory: self.timing.into(),
            prefetch: self.prefetch,
            outstanding: self.outstanding,
            issue_spacing: self.issue_spacing,
            credit: self.credit,
            ..crate::cycle::Params::RTL
        }
    }

    pub fn prepare(&self) -> Result<PreparedQuery, String> {
        let chip = crate::query::Chip::new(&query_mesh(self.a)?, &query_mesh(self.b)?, CHIP_CONFIG)?;
        let golden_all = chip.query(&self.pose, Mode::All, crate::traversal::Traversal::Fifo);
        let image = QueryImage::new(&chip.a, &chip.b, &chip.setup(&self.pose), self.lifo, self.mode, &self.params())?;
        Ok(PreparedQuery { chip, golden_all, image })
    }
}

/// The exported chip's queue: `2^QUEUE_BITS` entries (1,024: a breadth-first (FIFO)
/// traversal of a few hundred triangles needs about that many; LIFO a few dozen).
pub const QUEUE_BITS: usize = 10;
/// The exported chip, and the one every RTL run uses.
pub type ExportedChip = CollisionChip<QUEUE_BITS, { QUEUE_BITS + 1 }, { QUEUE_BITS - 1 }>;
/// The exported chip's file name.
pub const EXPORT_NAME: &str = "chip_e8m15_k6";

/// The exported chip, ready to simulate (inputs claimed; build it on a thread with a big
/// stack: TRI_UNIT is large).
pub fn exported_chip() -> ExportedChip {
    crate::rtl::e8m15::chip_top(CHIP_CONFIG.dop_rounding.op(), CHIP_CONFIG.tri_rounding)
}

/// The chip's Verilog (top module `top`), identical modules merged.
pub fn chip_verilog() -> String {
    std::thread::Builder::new()
        .stack_size(1 << 30)
        .spawn(|| {
            super::verilog::dedup_modules(&crate::rtl::e8m15::verilog_chip::<QUEUE_BITS, { QUEUE_BITS + 1 }, { QUEUE_BITS - 1 }>(
                CHIP_CONFIG.dop_rounding.op(),
                CHIP_CONFIG.tri_rounding,
            ))
        })
        .expect("spawn")
        .join()
        .expect("chip Verilog")
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
    let spheres = Pose::new(10.0, 20.0, 30.0, 0.8, 0.1, 0.0);
    let patch = Pose::new(0.0, 0.0, 0.0, 0.002, 0.001, 0.0);
    let q = |name, a, pose, lifo, mode, latency, interval| ChipQuery {
        name,
        a,
        b: a,
        pose,
        lifo,
        mode,
        timing: MemTiming { latency, interval, bus_bits: None },
        reader: Reader::default(),
        prefetch: 0,
        outstanding: 1,
        issue_spacing: 2,
        credit: crate::rtl::CREDIT as u32,
        large: false,
    };
    let big = |name, a, pose, lifo, mode, latency, interval, period| ChipQuery {
        reader: Reader { period },
        large: true,
        ..q(name, a, pose, lifo, mode, latency, interval)
    };
    let big_spheres = Pose::new(10.0, 20.0, 30.0, 0.9, 0.1, 0.05);
    vec![
        q("sphere_fifo_all", "sphere:12", spheres, false, Mode::All, 1, 1),
        q("sphere_lifo_all", "sphere:12", spheres, true, Mode::All, 3, 2),
        q("sphere_fifo_first", "sphere:12", spheres, false, Mode::First, 2, 1),
        q("sphere_lifo_first", "sphere:12", spheres, true, Mode::First, 1, 1),
        q("bunny_lifo_all", "bunny-patch:12", patch, true, Mode::All, 1, 1),
        q("bunny_fifo_first", "bunny-patch:12", patch, false, Mode::First, 1, 1),
        q("apart_lifo_first", "sphere:12", Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0), true, Mode::First, 1, 1),
        // sure hits and uncertain pairs; the FIFO holds about 1,000 entries at its widest
        big("big_sphere_fifo_all", "sphere:200", big_spheres, false, Mode::All, 1, 1, 1),
        big("big_sphere_lifo_all", "sphere:320", big_spheres, true, Mode::All, 4, 2, 1),
        // the host reads one result in 40 clocks: TRI_UNIT's FIFO fills and the credit
        // stalls the DOP unit
        big("big_patch_lifo_all_slow_host", "bunny-patch:300", patch, true, Mode::All, 2, 1, 40),
        // in e8m15 the first sure hit comes after 180 uncertain results (a long first-hit query)
        big("big_patch_fifo_first", "bunny-patch:120", patch, false, Mode::First, 3, 1, 1),
        big("big_patch_lifo_first", "bunny-patch:300", patch, true, Mode::First, 1, 1, 1),
        // the prefetching memory port (register 0x126): node words asked for pairs ahead,
        // several requests outstanding, at a memory latency of 8; an issue every clock
        // (both child entries pushed in one) with a credit of 24 to 48 but in the last
        ChipQuery { prefetch: 6, outstanding: 8, issue_spacing: 1, credit: 32, ..q("sphere_lifo_prefetch", "sphere:12", spheres, true, Mode::All, 8, 1) },
        ChipQuery { prefetch: 3, outstanding: 4, issue_spacing: 1, credit: 24, ..q("bunny_fifo_prefetch", "bunny-patch:12", patch, false, Mode::First, 8, 1) },
        ChipQuery { prefetch: 14, outstanding: 16, issue_spacing: 1, credit: 48, ..big("big_sphere_lifo_prefetch", "sphere:320", big_spheres, true, Mode::All, 8, 1, 1) },
        ChipQuery { prefetch: 14, outstanding: 16, ..big("big_sphere_fifo_prefetch", "sphere:200", big_spheres, false, Mode::All, 8, 1, 1) },
    ]
}

/// Writes `<dir>/<query>.mem` and `<dir>/<query>.host` for every query of [`queries`] and
/// `<dir>/queries.txt` (`name latency interval reader-period` per line), the inputs of
/// scripts/run-chip.sh. The expected traces (`<query>.expect`) are the rust-hdl chip's,
/// written by `CCHIP_BLESS=1 cargo test --release --test rtl_chip`.
pub fn write_vectors(dir: &std::path::Path) -> Result<Vec<String>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut list = String::new();
    let mut written = vec![];
    for q in queries() {
        let p = q.prepare()?;
        for (ext, text) in [("mem", p.image.memory_hex()), ("host", p.image.writes_hex())] {
            let path = dir.join(format!("{}.{ext}", q.name));
            std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
            written.push(path.display().to_string());
        }
        let _ = writeln!(list, "{} {} {} {}", q.name, q.timing.latency, q.timing.interval, q.reader.period);
    }
    let path = dir.join("queries.txt");
    std::fs::write(&path, list).map_err(|e| format!("{}: {e}", path.display()))?;
    written.push(path.display().to_string());
    Ok(written)
}

/// [`run_query`] writing a VCD of the traversal to `path` ([`ProbeVcd`]: the signals of
/// [`crate::cycle::PROBES`], one scope per unit under `chip`, one time unit per clock). For
/// GTKWave with scripts/gtkw/chip_e8m15_k6.gtkw. (A VCD of every rust-hdl signal would be
/// about 600 kB per clock, mostly T.CHECK's.)
pub fn run_query_vcd<const N: usize, const NP1: usize, const NM1: usize>(
    chip: &mut CollisionChip<N, NP1, NM1>,
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
        |t, p| vcd.cycle(t, &p.unwrap_or_default()).map_err(|e| format!("{}: {e}", path.display())),
        None,
    )?;
    Ok(trace)
}

/// Whether the RTL chip runs a query of this configuration, traversal and cycle-model
/// parameters, and in which order (true: LIFO); otherwise what to change.
pub fn rtl_order(cfg: &ChipConfig, traversal: crate::traversal::Traversal, p: &crate::cycle::Params) -> Result<bool, String> {
    use crate::traversal::Traversal;
    if *cfg != CHIP_CONFIG {
        return Err(format!(
            "the RTL chip is built for k = 6, format reduced (e8m15), outward DOP rounding; this scene has k = {}, format {}, dop_rounding {}: set [chip] k = 6, format = \"reduced\", dop_rounding = \"outward\"",
            cfg.k, cfg.format, cfg.dop_rounding
        ));
    }
    let rtl = crate::cycle::Params {
        memory: p.memory,
        prefetch: p.prefetch,
        outstanding: p.outstanding,
        issue_spacing: p.issue_spacing,
        credit: p.credit,
        ..crate::cycle::Params::RTL
    };
    if *p != rtl {
        return Err("the RTL chip has the [timing] of the default (queue_entries 1024, latencies 15 and 130, tri_fifo 256) but for memory, issue_spacing, credit, prefetch and outstanding: remove the others from the scene's [timing]".into());
    }
    let (pf, out, credit) = (crate::rtl::PORT_PREFETCH as u32, crate::rtl::PORT_OUTSTANDING as u32, crate::rtl::CREDIT_MAX as u32);
    if p.prefetch > pf || p.outstanding > out || p.credit > credit {
        return Err(format!(
            "the RTL chip prefetches at most {pf} pairs with at most {out} requests outstanding and a credit of at most {credit} (this scene: prefetch {}, outstanding {}, credit {}): lower them in [timing]",
            p.prefetch, p.outstanding, p.credit
        ));
    }
    match traversal {
        Traversal::Lifo => Ok(true),
        Traversal::Fifo => Ok(false),
        t => Err(format!("the RTL chip's D_CNTR runs the fifo or lifo traversal, not {t:?}: set [query] traversal")),
    }
}

/// rust-hdl simulates the chip at about this many clocks per second on this project's
/// machine (README, `cargo bench --bench chip_sim`: 13): for estimates before a run.
pub const RTL_CLOCKS_PER_SECOND: f64 = 14.0;

/// Runs one pose on the rust-hdl chip in lockstep with the cycle model (on a thread with
/// the big stack the RTL needs): every output and traversal signal equal after every clock.
/// Errors name the cycle and the signal of the first difference, or what the RTL chip
/// cannot run.
pub fn cross_check(
    chip: &crate::query::Chip,
    pose: &crate::pose::Pose,
    mode: Mode,
    traversal: crate::traversal::Traversal,
    p: crate::cycle::Params,
    max_cycles: u64,
) -> Result<ChipTrace, String> {
    let lifo = rtl_order(&chip.cfg, traversal, &p)?;
    let setup = chip.setup(pose);
    let image = QueryImage::new(&chip.a, &chip.b, &setup, lifo, mode, &p)?;
    let d = drive(&image, p.memory, Reader::default(), max_cycles);
    std::thread::scope(|s| {
        std::thread::Builder::new()
            .stack_size(1 << 30)
            .spawn_scoped(s, || {
                let mut rtl = exported_chip();
                let model = crate::cycle::chip::Chip::new(&chip.cfg, p, &chip.a, &chip.b, &setup, false)?;
                let mut ls = crate::cycle::drive::Lockstep::new(RtlChip::new(&mut rtl, &image), model, ("rust-hdl", "cycle model"));
                crate::cycle::drive::run_query(&mut ls, &image.writes, &d, true, |_, _| Ok(()), None).map_err(|e| e.0)
            })
            .map_err(|e| format!("cannot start the RTL simulation thread: {e}"))?
            .join()
            .map_err(|_| "the RTL simulation thread panicked".to_string())?
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Words are laid out as `crate::memory` says: a node's leaf bit, distances and fields,
    /// a triangle's 24 values and two flags, most significant hex digit first.
    #[test]
    fn memory_words_and_writes() {
        let q = queries().into_iter().find(|q| q.name == "sphere_fifo_all").unwrap();
        let p = q.prepare().unwrap();
        let a = &p.chip.a;
        assert_eq!(p.image.memory.len(), 2 * a.tree.len() + 2 * a.tris.len(), "A and B are the same sphere");
        let f = CHIP_CONFIG.format.dop;
        let w = &p.image.memory[0];
        let field = |w: &Word, at: usize, bits: usize| (0..bits).fold(0u64, |v, k| v | (w[(at + k) / 64] >> ((at + k) % 64) & 1) << k);
        assert_eq!(W, f.width() as usize);
        assert_eq!(NODE_BITS as u32, crate::memory::Layout::new(&CHIP_CONFIG).node_bits);
        assert_eq!(MEM_BITS as u32, crate::memory::Layout::new(&CHIP_CONFIG).tri_bits);
        assert!(p.image.memory[..a.tree.len()].iter().all(|w| field(w, NODE_BITS, 64) == 0 && field(w, NODE_BITS + 64, MEM_BITS - NODE_BITS - 64) == 0));
        assert_eq!(field(w, 0, 1), 0, "the root is inner");
        assert_eq!(field(w, 1 + 2 * W, W), f.to_bits(a.tree.dop(0)[2]));
        let Node::Inner([c0, c1]) = a.tree.nodes[0] else { panic!() };
        assert_eq!((field(w, 145, 32), field(w, 177, 32)), (c0 as u64, c1 as u64));
        let t = &p.image.memory[a.tree.len() + 3];
        let l = LeafIn::of(f, &a.tris[3]);
        assert_eq!(field(t, 4 * W, W), l.v[1][1]);
        assert_eq!(field(t, 9 * W + 5 * W, W), l.m[5]);
        assert_eq!(field(t, 23 * W, W), l.l_norm);
        assert_eq!(field(t, 24 * W, 2), l.v_exact as u64 | (l.degenerate as u64) << 1);
        let hex = p.image.memory_hex();
        let line = hex.lines().nth(a.tree.len() + 3).unwrap();
        assert_eq!(line.len(), 145);
        assert_eq!(u64::from_str_radix(&line[line.len() - 6..], 16).unwrap(), l.v[0][0]);
        assert!(p.image.writes.contains(&(reg::MODE, 0)));
        assert!(p.image.writes_hex().lines().all(|l| l.len() == 11));
    }

    #[test]
    fn too_large_a_tree_is_an_error() {
        let big = crate::mesh::builtin("sphere:40000").unwrap().triangles_f64();
        let chip = crate::query::Chip::new(&big, &big[..1], CHIP_CONFIG).unwrap();
        let setup = chip.setup(&crate::pose::Pose::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0));
        let e = QueryImage::new(&chip.a, &chip.b, &setup, true, Mode::All, &crate::cycle::Params::RTL).unwrap_err();
        assert!(e.contains("16 bits"), "{e}");
    }
}
