//! The host and memory side of the RTL collision chip ([`e8m15::CollisionChip`]): the
//! memory image and register writes of one query, a memory model with configurable
//! timing, the rust-hdl driver that runs a whole query, and the query trace that the
//! Verilog testbench (`scripts/verilog/chip_tb.v`) prints in the same format, so that the
//! two simulations are compared line by line.
//!
//! The chip is k = 6, e8m15 ([`Format::REDUCED`]), DOP lanes rounding outward, T.CHECK to
//! nearest-even: [`CHIP_CONFIG`].

use super::e8m15::CollisionChip;
use super::tri_io::{tri_unit_setup_words, LeafIn};
use crate::config::{ChipConfig, DopRounding};
use crate::dop::{HostSetup, Node};
use crate::format::{Format, Rounding};
use crate::memory::ObjectImage;
use crate::traversal::{Mode, QueryResult};
use rust_hdl::prelude::*;
use std::fmt::Write as _;

/// The configuration of the RTL chip.
pub const CHIP_CONFIG: ChipConfig =
    ChipConfig { k: 6, format: Format::REDUCED, dop_rounding: DopRounding::Outward, tri_rounding: Rounding::NearestEven };
/// Memory word bits (a triangle word; a node word is the low [`NODE_BITS`]).
pub const MEM_BITS: usize = 578;
/// Node word bits: leaf bit, 6 distances, two 32-bit fields.
pub const NODE_BITS: usize = 209;
const W: usize = 24;

/// The memory model: a request accepted at rising edge `t` is answered in the cycle that
/// ends with edge `t + latency` (`mem_resp_valid` high, the chip takes it at that edge);
/// after an accepted request the next is accepted `interval` edges later at the earliest
/// (the memory's throughput is `1 / interval` words per clock). Responses come in request
/// order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MemTiming {
    pub latency: u32,
    pub interval: u32,
}

impl Default for MemTiming {
    fn default() -> Self {
        MemTiming { latency: 1, interval: 1 }
    }
}

/// The host registers' addresses (see [`CollisionChip`]).
pub mod reg {
    pub const TRI_SETUP: u32 = 0x100;
    pub const MODE: u32 = 0x120;
    pub const ROOT: u32 = 0x121;
    pub const BASE_NA: u32 = 0x122;
    pub const BASE_NB: u32 = 0x123;
    pub const BASE_TA: u32 = 0x124;
    pub const BASE_TB: u32 = 0x125;
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
    let f = CHIP_CONFIG.format;
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
    /// Errors if a tree has more nodes than the 16-bit node ids of D_CNTR address, or the
    /// image more words than the 24-bit memory address.
    pub fn new(a: &ObjectImage, b: &ObjectImage, setup: &HostSetup, lifo: bool, mode: Mode) -> Result<Self, String> {
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
        let mut base = [0u32; 4];
        for (i, o) in [a, b].into_iter().enumerate() {
            base[2 * i] = memory.len() as u32;
            memory.extend((0..o.tree.len() as u32).map(|n| node_word(o, n)));
            base[2 * i + 1] = memory.len() as u32;
            memory.extend(o.tris.iter().map(|t| tri_word(&LeafIn::of(f, t))));
        }
        if memory.len() > 1 << 24 {
            return Err(format!("memory image of {} words; the RTL chip addresses 2^24", memory.len()));
        }
        let mut writes: Vec<(u32, u32)> = dop_unit_setup_words(f, setup).into_iter().map(|(a, d)| (a as u32, d as u32)).collect();
        writes.extend(tri_unit_setup_words(f, setup).into_iter().map(|(a, d)| (reg::TRI_SETUP + a as u32, d as u32)));
        writes.extend([
            (reg::BASE_NA, base[0]),
            (reg::BASE_TA, base[1]),
            (reg::BASE_NB, base[2]),
            (reg::BASE_TB, base[3]),
            (reg::ROOT, 0),
            (reg::MODE, lifo as u32 | ((mode == Mode::First) as u32) << 1),
        ]);
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

/// What a query did on the RTL chip: the chip's outputs, in the trace format the Verilog
/// testbench prints.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ChipTrace {
    /// `(cycle, A's triangle, B's triangle, uncertain)` in the order the host read them;
    /// cycle 1 is the one after the edge that took `start`.
    pub results: Vec<(u64, u32, u32, bool)>,
    /// Rising edges from the one that took `start` to the one after which `done` is high.
    pub cycles: u64,
    pub overflow: bool,
    pub max_depth: u64,
    pub dop_tests: u64,
    pub tri_tests: u64,
    pub node_fetches: u64,
    pub tri_fetches: u64,
}

impl ChipTrace {
    /// One line per result, then a summary line (the Verilog testbench prints the same).
    pub fn text(&self) -> String {
        let mut s = String::new();
        for &(c, a, b, u) in &self.results {
            let _ = writeln!(s, "result {c} {a} {b} {}", u as u8);
        }
        let _ = writeln!(
            s,
            "done {} overflow {} max_depth {} dop_tests {} tri_tests {} node_fetches {} tri_fetches {}",
            self.cycles, self.overflow as u8, self.max_depth, self.dop_tests, self.tri_tests, self.node_fetches, self.tri_fetches
        );
        s
    }

    /// The sure hits and the uncertain pairs, each sorted.
    pub fn pairs(&self) -> (Vec<(u32, u32)>, Vec<(u32, u32)>) {
        let mut hits: Vec<_> = self.results.iter().filter(|r| !r.3).map(|r| (r.1, r.2)).collect();
        let mut unc: Vec<_> = self.results.iter().filter(|r| r.3).map(|r| (r.1, r.2)).collect();
        hits.sort_unstable();
        unc.sort_unstable();
        (hits, unc)
    }

    /// Does this trace answer the query as the golden model does? `all` is the golden
    /// all-pairs result of the same query. All pairs: the chip's sure hits are the golden
    /// pairs that were not uncertain, and its uncertain pairs are the golden uncertain ones.
    /// First hit: every pair it reports is one of those, and it reports a sure hit, or only
    /// uncertain pairs, exactly when the golden query has pairs (the host settles the
    /// uncertain ones). Returns what differs.
    pub fn check(&self, mode: Mode, all: &QueryResult) -> Result<(), String> {
        let (hits, unc) = self.pairs();
        let sure: Vec<(u32, u32)> = all.pairs.iter().copied().filter(|p| all.uncertain.binary_search(p).is_err()).collect();
        if self.overflow {
            return Err("the queue overflowed".into());
        }
        match mode {
            Mode::All if hits != sure || unc != all.uncertain => Err(format!(
                "all pairs: chip hits {hits:?} uncertain {unc:?}; golden hits {sure:?} uncertain {:?}",
                all.uncertain
            )),
            Mode::First => {
                if let Some(p) = hits.iter().find(|p| sure.binary_search(p).is_err()) {
                    return Err(format!("first hit: chip hit {p:?} is not a golden sure hit"));
                }
                if let Some(p) = unc.iter().find(|p| all.uncertain.binary_search(p).is_err()) {
                    return Err(format!("first hit: chip uncertain {p:?} is not golden uncertain"));
                }
                let settled = unc.iter().any(|p| all.pairs.binary_search(p).is_ok());
                if (hits.is_empty() && !settled) != all.pairs.is_empty() {
                    return Err(format!("first hit: chip hits {hits:?} uncertain {unc:?}; golden pairs {:?}", all.pairs));
                }
                Ok(())
            }
            _ => Ok(()),
        }
    }
}

/// Why a simulated query did not finish.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ChipError(pub String);

impl std::fmt::Display for ChipError {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str(&self.0)
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

/// Runs one query on the rust-hdl chip (a chip fresh from `chip_top`, or after a finished
/// query): the register writes one per clock, `start`, then clocks until `done`, with
/// the memory model serving `image.memory` and the host reading every result at once.
/// `max_cycles` bounds the query; `after_edge(chip, time)` is called after every half
/// clock (time in units of 5 per half period), e.g. to write a VCD.
pub fn run_query<const N: usize, const NP1: usize>(
    chip: &mut CollisionChip<N, NP1>,
    image: &QueryImage,
    timing: MemTiming,
    max_cycles: u64,
    mut after_edge: impl FnMut(&CollisionChip<N, NP1>, u64),
) -> Result<ChipTrace, ChipError> {
    if timing.latency == 0 || timing.interval == 0 {
        return Err(ChipError(format!("memory latency and interval must be at least 1 (got {timing:?})")));
    }
    let words: Vec<Bits<MEM_BITS>> = image.memory.iter().map(bits::<MEM_BITS>).collect();
    let mut time = 0u64;
    let mut step = |chip: &mut CollisionChip<N, NP1>| -> Result<(), ChipError> {
        for high in [false, true] {
            chip.clock.next = Clock { clk: high };
            if !simulate(chip, 1000) {
                return Err(ChipError("the logic did not settle".into()));
            }
            after_edge(chip, time);
            time += 5;
        }
        Ok(())
    };
    chip.res_ready.next = true;
    chip.mem_req_ready.next = false;
    chip.mem_resp_valid.next = false;
    for &(a, d) in &image.writes {
        chip.host_we.next = true;
        chip.host_addr.next = (a as u64).into();
        chip.host_data.next = (d as u64).into();
        step(chip)?;
    }
    chip.host_we.next = false;
    chip.start.next = true;
    step(chip)?;
    chip.start.next = false;
    // memory: (due cycle, address) in request order; the earliest cycle of the next accept
    let mut pending: std::collections::VecDeque<(u64, usize)> = Default::default();
    let mut next_accept = 0u64;
    let mut results = vec![];
    for cyc in 1..=max_cycles {
        if chip.done.val() {
            return Ok(ChipTrace {
                results,
                cycles: cyc - 1,
                overflow: chip.overflow.val(),
                max_depth: chip.max_depth.val().to_u64(),
                dop_tests: chip.dop_tests.val().to_u64(),
                tri_tests: chip.tri_tests.val().to_u64(),
                node_fetches: chip.node_fetches.val().to_u64(),
                tri_fetches: chip.tri_fetches.val().to_u64(),
            });
        }
        let ready = cyc >= next_accept;
        chip.mem_req_ready.next = ready;
        let resp = pending.front().filter(|p| p.0 <= cyc).map(|p| p.1);
        chip.mem_resp_valid.next = resp.is_some();
        if let Some(a) = resp {
            chip.mem_resp_data.next = words[a];
            pending.pop_front();
        }
        // the chip's request and result outputs depend on its registers only
        if chip.mem_req_valid.val() && ready {
            let a = chip.mem_req_addr.val().to_u64() as usize;
            if a >= words.len() {
                return Err(ChipError(format!("cycle {cyc}: memory request at word {a}, past the image ({} words)", words.len())));
            }
            pending.push_back((cyc + timing.latency as u64, a));
            next_accept = cyc + timing.interval as u64;
        }
        if chip.res_valid.val() {
            let t = chip.res_tag.val().to_u64();
            results.push((cyc, (t & 0xffff) as u32, (t >> 16) as u32, chip.res_uncertain.val()));
        }
        step(chip)?;
    }
    Err(ChipError(format!("the query did not finish within {max_cycles} cycles")))
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
    pub fn prepare(&self) -> Result<PreparedQuery, String> {
        let chip = crate::query::Chip::new(&query_mesh(self.a)?, &query_mesh(self.b)?, CHIP_CONFIG)?;
        let golden_all = chip.query(&self.pose, Mode::All, crate::traversal::Traversal::Fifo);
        let image = QueryImage::new(&chip.a, &chip.b, &chip.setup(&self.pose), self.lifo, self.mode)?;
        Ok(PreparedQuery { chip, golden_all, image })
    }
}

/// The exported chip: `2^8` queue entries.
pub const EXPORT_NAME: &str = "chip_e8m15_k6";

/// The chip's Verilog (top module `top`), identical modules merged.
pub fn chip_verilog() -> String {
    std::thread::Builder::new()
        .stack_size(1 << 30)
        .spawn(|| {
            super::verilog::dedup_modules(&super::e8m15::verilog_chip::<8, 9>(
                CHIP_CONFIG.dop_rounding.op(),
                CHIP_CONFIG.tri_rounding,
            ))
        })
        .expect("spawn")
        .join()
        .expect("chip Verilog")
}

/// The RTL query set: both orders and modes, three memory timings, procedural spheres and a
/// bunny patch against a slightly shifted copy of itself (sure hits and many uncertain
/// pairs), and two spheres apart (the root test only).
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
        timing: MemTiming { latency, interval },
    };
    vec![
        q("sphere_fifo_all", "sphere:12", spheres, false, Mode::All, 1, 1),
        q("sphere_lifo_all", "sphere:12", spheres, true, Mode::All, 3, 2),
        q("sphere_fifo_first", "sphere:12", spheres, false, Mode::First, 2, 1),
        q("sphere_lifo_first", "sphere:12", spheres, true, Mode::First, 1, 1),
        q("bunny_lifo_all", "bunny-patch:12", patch, true, Mode::All, 1, 1),
        q("bunny_fifo_first", "bunny-patch:12", patch, false, Mode::First, 1, 1),
        q("apart_lifo_first", "sphere:12", Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0), true, Mode::First, 1, 1),
    ]
}

/// Writes `<dir>/<query>.mem` and `<dir>/<query>.host` for every query of [`queries`] and
/// `<dir>/queries.txt` (`name latency interval` per line), the inputs of
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
        let _ = writeln!(list, "{} {} {}", q.name, q.timing.latency, q.timing.interval);
    }
    let path = dir.join("queries.txt");
    std::fs::write(&path, list).map_err(|e| format!("{}: {e}", path.display()))?;
    written.push(path.display().to_string());
    Ok(written)
}

/// [`run_query`] writing a VCD of the traversal to `path`: the signals of
/// [`CollisionChip::probe`] (host, D_CNTR, memory port, DOP unit, leaf pairs, TRI_UNIT,
/// results, counters; one scope each under `chip`), one time unit per clock: time t shows
/// every signal in cycle t (inputs, registers and logic before the edge that ends it;
/// cycle 0 is the one whose edge takes `start`, the numbering of [`ChipTrace`]). For GTKWave with
/// scripts/gtkw/chip_e8m15_k6.gtkw. (A VCD of every rust-hdl signal would be about 600 kB
/// per clock, mostly T.CHECK's.)
pub fn run_query_vcd<const N: usize, const NP1: usize>(
    chip: &mut CollisionChip<N, NP1>,
    image: &QueryImage,
    timing: MemTiming,
    max_cycles: u64,
    path: &std::path::Path,
) -> Result<ChipTrace, ChipError> {
    use vcd::{TimescaleUnit, Value};
    let io = |e: std::io::Error| ChipError(format!("{}: {e}", path.display()));
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(io)?;
    }
    let file = std::io::BufWriter::new(std::fs::File::create(path).map_err(io)?);
    let mut w = vcd::Writer::new(file);
    w.timescale(1, TimescaleUnit::NS).map_err(io)?;
    w.add_module("chip").map_err(io)?;
    let names = chip.probe();
    let mut ids = vec![];
    let mut scope = "";
    for &(s, name, width, _) in &names {
        if s != scope {
            if !scope.is_empty() {
                w.upscope().map_err(io)?;
            }
            w.add_module(s).map_err(io)?;
            scope = s;
        }
        ids.push(w.add_wire(width, name).map_err(io)?);
    }
    w.upscope().map_err(io)?;
    w.upscope().map_err(io)?;
    w.enddefinitions().map_err(io)?;
    let mut last: Vec<Option<u64>> = vec![None; names.len()];
    let writes = image.writes.len() as u64;
    let mut err = None;
    let trace = run_query(chip, image, timing, max_cycles, |c, time| {
        // in the low half of each clock, the cycle's inputs applied and settled: every
        // signal shows its value in that cycle; the register writes are left out
        let step = time / 10;
        if time % 10 != 0 || step < writes || err.is_some() {
            return;
        }
        let t = step - writes;
        let mut stamped = false;
        for (i, (_, _, width, v)) in c.probe().into_iter().enumerate() {
            if last[i] == Some(v) {
                continue;
            }
            last[i] = Some(v);
            let bits: Vec<Value> = (0..width).rev().map(|b| if v >> b & 1 == 1 { Value::V1 } else { Value::V0 }).collect();
            let r = (if stamped { Ok(()) } else { w.timestamp(t) }).and_then(|_| w.change_vector(ids[i], &bits));
            stamped = true;
            if let Err(e) = r {
                err = Some(e);
                return;
            }
        }
    })?;
    if let Some(e) = err {
        return Err(io(e));
    }
    Ok(trace)
}

/// One pose of a scene on the RTL chip.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct RtlRecord {
    pub cycles: u64,
    /// Pairs the chip reported intersecting, and uncertain (for the host to settle).
    pub hits: usize,
    pub uncertain: usize,
    pub dop_tests: u64,
    pub tri_tests: u64,
    pub node_fetches: u64,
    pub tri_fetches: u64,
    /// Most queue entries (two node pairs each) waiting at once.
    pub max_depth: u64,
    pub overflow: bool,
    /// The chip's pairs agree with the golden model's ([`ChipTrace::check`]); otherwise why not.
    pub golden_mismatch: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vcd: Option<String>,
}

/// Whether the RTL chip runs a query of this configuration and traversal, and in which
/// order (true: LIFO); otherwise what to change.
pub fn rtl_order(cfg: &ChipConfig, traversal: crate::traversal::Traversal) -> Result<bool, String> {
    use crate::traversal::Traversal;
    if *cfg != CHIP_CONFIG {
        return Err(format!(
            "the RTL chip is built for k = 6, format reduced (e8m15), outward DOP rounding; this scene has k = {}, format {}, {:?}: set [chip] k = 6, format = \"reduced\", dop_rounding = \"outward\"",
            cfg.k, cfg.format, cfg.dop_rounding
        ));
    }
    match traversal {
        Traversal::Lifo => Ok(true),
        Traversal::Fifo => Ok(false),
        t => Err(format!("the RTL chip's D_CNTR runs the fifo or lifo traversal, not {t:?}: set [query] traversal")),
    }
}

/// Runs `poses` on the rust-hdl chip (one chip, queries back to back; on a thread with the
/// big stack it needs), each checked against the golden model; with `vcd_dir`, writes
/// `<vcd_dir>/pose<i>.vcd`. `tick` is called after each pose. Errors name what the RTL
/// chip cannot run (another configuration, a recursive or list traversal, too large a tree).
pub fn run_poses(
    chip: &crate::query::Chip,
    poses: &[crate::pose::Pose],
    mode: Mode,
    traversal: crate::traversal::Traversal,
    timing: MemTiming,
    vcd_dir: Option<&std::path::Path>,
    max_cycles: u64,
    mut tick: impl FnMut() + Send,
) -> Result<Vec<RtlRecord>, String> {
    let lifo = rtl_order(&chip.cfg, traversal)?;
    let images = poses
        .iter()
        .map(|p| QueryImage::new(&chip.a, &chip.b, &chip.setup(p), lifo, mode))
        .collect::<Result<Vec<_>, _>>()?;
    let golden: Vec<QueryResult> = poses.iter().map(|p| chip.query(p, Mode::All, traversal)).collect();
    std::thread::scope(|s| {
        std::thread::Builder::new()
            .stack_size(1 << 30)
            .spawn_scoped(s, || {
                let mut c = super::e8m15::chip_top::<8, 9>(CHIP_CONFIG.dop_rounding.op(), CHIP_CONFIG.tri_rounding);
                let mut out = vec![];
                for (i, (img, g)) in images.iter().zip(&golden).enumerate() {
                    let path = vcd_dir.map(|d| d.join(format!("pose{i}.vcd")));
                    let tr = match &path {
                        Some(p) => run_query_vcd(&mut c, img, timing, max_cycles, p),
                        None => run_query(&mut c, img, timing, max_cycles, |_, _| {}),
                    }
                    .map_err(|e| format!("pose {i}: {e}"))?;
                    let (hits, unc) = tr.pairs();
                    out.push(RtlRecord {
                        cycles: tr.cycles,
                        hits: hits.len(),
                        uncertain: unc.len(),
                        dop_tests: tr.dop_tests,
                        tri_tests: tr.tri_tests,
                        node_fetches: tr.node_fetches,
                        tri_fetches: tr.tri_fetches,
                        max_depth: tr.max_depth,
                        overflow: tr.overflow,
                        golden_mismatch: tr.check(mode, g).err(),
                        vcd: path.map(|p| p.display().to_string()),
                    });
                    tick();
                }
                Ok(out)
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
        let (a, b) = (&p.chip.a, &p.chip.b);
        assert_eq!(p.image.memory.len(), 2 * a.tree.len() + 2 * a.tris.len());
        let f = CHIP_CONFIG.format;
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
        let e = QueryImage::new(&chip.a, &chip.b, &setup, true, Mode::All).unwrap_err();
        assert!(e.contains("16 bits"), "{e}");
    }
}
