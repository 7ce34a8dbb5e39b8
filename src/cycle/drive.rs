//! One driver for the chip at every level ([`Clocked`]: the cycle model, the rust-hdl
//! chip): the host's register writes and `start`, the memory model, the host reading
//! results, the query trace the Verilog testbench prints in the same format, two levels
//! in lockstep, and the traversal VCD.

use super::memory::{MemCounters, MemModel};
use crate::chip::memory::MemClocks;
use crate::chip::ports::{ChipIn, ChipOut, Clocked, MemorySide};
use crate::chip::probes::Probes;
use crate::chip::reg::Mode;
use crate::traversal::QueryResult;
use std::fmt::Write as _;

/// How the host reads results: `res_ready` is high in the cycles `c` with
/// `c % period == 0` (1: every cycle; more: a slow host whose results back-pressure the
/// chip). The Verilog testbench reads with the same rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Reader {
    pub period: u32,
}

impl Default for Reader {
    fn default() -> Self {
        Reader { period: 1 }
    }
}

/// A result pair: a triangle id of A and one of B.
pub type TriPair = (u32, u32);

impl Reader {
    pub fn ready(&self, cyc: u64) -> bool {
        // period 1 (every cycle) without a division: this is asked every clock
        self.period <= 1 || cyc.is_multiple_of(self.period as u64)
    }

    /// The first cycle from `cyc` on in which the host reads.
    pub fn next_ready(&self, cyc: u64) -> u64 {
        if self.period <= 1 {
            cyc
        } else {
            cyc.next_multiple_of(self.period as u64)
        }
    }
}

/// What a query did: the chip's outputs, in the trace format the Verilog testbench
/// prints (`vectors/chip/*.expect`).
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
    /// What the memory model did (not in the trace text: the testbench's memory is not the
    /// chip).
    pub memory: MemCounters,
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

    /// The sure hits and the uncertain pairs (triangle ids of A and B), each sorted.
    pub fn pairs(&self) -> (Vec<TriPair>, Vec<TriPair>) {
        let mut hits: Vec<_> = self
            .results
            .iter()
            .filter(|r| !r.3)
            .map(|r| (r.1, r.2))
            .collect();
        let mut unc: Vec<_> = self
            .results
            .iter()
            .filter(|r| r.3)
            .map(|r| (r.1, r.2))
            .collect();
        hits.sort_unstable();
        unc.sort_unstable();
        (hits, unc)
    }

    /// Does this trace answer the query as the golden model does? `all` is the golden
    /// all-pairs result of the same query. All pairs: the chip's sure hits are the golden
    /// pairs that were not uncertain, and its uncertain pairs are the golden uncertain
    /// ones. First hit (docs/explanation/architecture.md, "Cycle semantics", Halt): every pair it
    /// reports is one of those (the sure hit that halted it, and what was in flight), and
    /// it reports a sure hit, or only uncertain pairs, exactly when the golden query has
    /// pairs (the host settles the uncertain ones). An overflow is an error: the answer is
    /// incomplete. Returns what differs.
    pub fn check(&self, mode: Mode, all: &QueryResult) -> Result<(), String> {
        let (hits, unc) = self.pairs();
        let sure: Vec<(u32, u32)> = all
            .pairs
            .iter()
            .copied()
            .filter(|p| all.uncertain.binary_search(p).is_err())
            .collect();
        if self.overflow {
            return Err("the queue overflowed: the answer is incomplete".into());
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

/// How one query is driven.
#[derive(Clone, Copy, Debug)]
pub struct Drive {
    /// The memory in the chip's clocks.
    pub memory: MemClocks,
    /// Bits per memory word (a DDR access moves whole bursts of the bus).
    pub word_bits: u32,
    pub reader: Reader,
    /// Words in the memory image: a request past them is an error.
    pub words: u32,
    /// Cycles after `start` before the query counts as hung.
    pub max_cycles: u64,
}

/// The driver's memory: the model, and the image's size in words (a request past it is an
/// error).
struct Served {
    model: MemModel,
    words: u32,
}

impl MemorySide for Served {
    #[inline]
    fn ready(&self, cyc: u64) -> bool {
        self.model.ready(cyc)
    }

    #[inline]
    fn next_ready(&self) -> u64 {
        self.model.next_ready()
    }

    #[inline]
    fn respond(&mut self, cyc: u64) -> Option<u32> {
        self.model.respond(cyc)
    }

    #[inline]
    fn next_response(&self) -> Option<u64> {
        self.model.next_response()
    }

    #[inline]
    fn request(&mut self, cyc: u64, addr: u32) -> Result<(), String> {
        if addr >= self.words {
            return Err(format!(
                "cycle {cyc}: memory request at word {addr}, past the image ({} words)",
                self.words
            ));
        }
        self.model.request(cyc, addr);
        Ok(())
    }
}

/// Runs one query: the register `writes` one per clock, `start` (cycle 0), then clocks
/// until `done`, the memory model serving requests and the host reading results by
/// `d.reader`. `observe(cycle, probes)` sees every cycle from 0 on with the values of the
/// chip's [`probe_list`](Clocked::probe_list) if `probe` is set (a VCD, a lockstep check). With `skip` and without `probe`,
/// the level runs on its own between the driver's reads of results ([`Clocked::wait`],
/// told the cycle by which the driver has a result to read).
pub fn run_query<C: Clocked>(
    chip: &mut C,
    writes: &[(u32, u32)],
    d: &Drive,
    probe: bool,
    mut observe: impl FnMut(u64, Option<Vec<u64>>) -> Result<(), String>,
    skip: bool,
) -> Result<ChipTrace, ChipError> {
    d.memory.check().map_err(ChipError)?;
    let idle = ChipIn {
        res_ready: true,
        ..Default::default()
    };
    for &(a, v) in writes {
        chip.step(
            &ChipIn {
                host_we: true,
                host_addr: a,
                host_data: v,
                ..idle
            },
            false,
        );
    }
    let p = chip.step(
        &ChipIn {
            start: true,
            ..idle
        },
        probe,
    );
    observe(0, p).map_err(|e| ChipError(format!("cycle 0: {e}")))?;
    fault(chip, 0)?;
    let mut mem = Served {
        model: MemModel::new(d.memory, d.word_bits),
        words: d.words,
    };
    let mut results = vec![];
    let mut cyc = 1u64;
    while cyc <= d.max_cycles {
        let out = chip.outputs();
        if out.done {
            return Ok(ChipTrace {
                results,
                cycles: cyc - 1,
                overflow: out.overflow,
                max_depth: out.max_depth,
                dop_tests: out.dop_tests,
                tri_tests: out.tri_tests,
                node_fetches: out.node_fetches,
                tri_fetches: out.tri_fetches,
                memory: mem.model.counters,
            });
        }
        let ready = mem.ready(cyc);
        let i = ChipIn {
            mem_req_ready: ready,
            mem_resp: mem.model.respond(cyc),
            res_ready: d.reader.ready(cyc),
            ..idle
        };
        if out.mem_req_valid && ready {
            mem.request(cyc, out.mem_req_addr).map_err(ChipError)?;
        }
        if out.res_valid && i.res_ready {
            results.push((cyc, out.res_tag.0, out.res_tag.1, out.res_uncertain));
        }
        // the level on its own: no result read in this cycle, nor before `limit`
        let read = out.res_valid && i.res_ready;
        if skip && !probe && !read {
            let limit = if out.res_valid {
                d.reader.next_ready(cyc)
            } else {
                u64::MAX
            }
            .min(d.max_cycles + 1);
            let n = chip.wait(&i, &mut mem, cyc, limit).map_err(ChipError)?;
            if n > 0 {
                cyc += n;
                continue;
            }
        }
        let p = chip.step(&i, probe);
        observe(cyc, p).map_err(|e| ChipError(format!("cycle {cyc}: {e}")))?;
        fault(chip, cyc)?;
        cyc += 1;
    }
    Err(ChipError(not_finished(d.max_cycles)))
}

/// The error of a query stopped at `max_cycles` (a bound that catches a hung model).
pub fn not_finished(max_cycles: u64) -> String {
    format!("the query did not finish within {max_cycles} cycles")
}

fn fault<C: Clocked>(chip: &C, cyc: u64) -> Result<(), ChipError> {
    match chip.fault() {
        Some(f) => Err(ChipError(format!("cycle {cyc}: {f}"))),
        None => Ok(()),
    }
}

/// Two levels clocked with the same inputs, compared after every clock: every output,
/// and every traversal signal ([`Clocked::probe_list`], the same at both levels) whose value
/// is specified ([`Probes::specified`]). The first
/// difference is the [`fault`](Clocked::fault), naming the signal and both values.
pub struct Lockstep<A, B> {
    pub a: A,
    pub b: B,
    pub names: (&'static str, &'static str),
    diff: Option<String>,
}

impl<A: Clocked, B: Clocked> Lockstep<A, B> {
    pub fn new(a: A, b: B, names: (&'static str, &'static str)) -> Self {
        assert_eq!(
            a.probe_list().gtkw,
            b.probe_list().gtkw,
            "two levels of different chips in lockstep"
        );
        Lockstep {
            a,
            b,
            names,
            diff: None,
        }
    }
}

impl<A: Clocked, B: Clocked> Clocked for Lockstep<A, B> {
    fn outputs(&self) -> ChipOut {
        self.a.outputs()
    }

    fn step(&mut self, i: &ChipIn, _probe: bool) -> Option<Vec<u64>> {
        let (oa, ob) = (self.a.outputs().specified(), self.b.outputs().specified());
        if self.diff.is_none() && oa != ob {
            self.diff = Some(format!(
                "outputs differ: {} {oa:?}, {} {ob:?}",
                self.names.0, self.names.1
            ));
        }
        let (pa, pb) = (self.a.step(i, true), self.b.step(i, true));
        let list = self.a.probe_list();
        if let (None, Some(pa), Some(pb)) = (&self.diff, &pa, &pb) {
            let specified = |k: usize| list.specified(k, pa);
            if let Some(k) = (0..list.signals.len()).find(|&k| specified(k) && pa[k] != pb[k]) {
                let (scope, name, _) = list.signals[k];
                self.diff = Some(format!(
                    "signal chip.{scope}.{name}: {} {}, {} {}",
                    self.names.0, pa[k], self.names.1, pb[k]
                ));
            }
        }
        pa
    }

    fn probe_list(&self) -> &'static Probes {
        self.a.probe_list()
    }

    fn fault(&self) -> Option<String> {
        self.diff.clone()
    }
}

/// A level watched clock by clock: `see(t, outputs, inputs)` in every cycle `t` from the
/// one whose edge takes `start` (cycle 0) on, before its edge, for what a testbench prints
/// of the ports ([`request_line`], `verilator::PortLog`) where a level has
/// no probes.
pub struct Watch<C, F> {
    pub chip: C,
    see: F,
    cycle: Option<u64>,
}

impl<C: Clocked, F: FnMut(u64, &ChipOut, &ChipIn)> Watch<C, F> {
    pub fn new(chip: C, see: F) -> Self {
        Watch {
            chip,
            see,
            cycle: None,
        }
    }
}

/// The memory requests taken in cycle `t` (outputs `o`, inputs `i`) as the Verilog
/// testbench prints them with `+requests` (scripts/verilog/chip_tb.v): `request <cycle>
/// <word address>` lines, from cycle 1.
pub fn request_line(t: u64, o: &ChipOut, i: &ChipIn) -> Option<String> {
    (t > 0 && o.mem_req_valid && i.mem_req_ready)
        .then(|| format!("request {t} {}\n", o.mem_req_addr))
}

impl<C: Clocked, F: FnMut(u64, &ChipOut, &ChipIn)> Clocked for Watch<C, F> {
    fn outputs(&self) -> ChipOut {
        self.chip.outputs()
    }

    fn step(&mut self, i: &ChipIn, probe: bool) -> Option<Vec<u64>> {
        self.cycle = match self.cycle {
            _ if i.start => Some(0),
            c => c.map(|t| t + 1),
        };
        if let Some(t) = self.cycle {
            (self.see)(t, &self.chip.outputs(), i);
        }
        self.chip.step(i, probe)
    }

    fn probe_list(&self) -> &'static Probes {
        self.chip.probe_list()
    }

    fn fault(&self) -> Option<String> {
        self.chip.fault()
    }
}

/// A VCD of a chip's traversal signals (`probes`), one time unit per clock (time t shows
/// every signal in cycle t, cycle 0 the one whose edge takes `start`), one scope per unit
/// under `chip`: for GTKWave with its save file ([`Probes::gtkw`]). `scopes` picks the units
/// (all if empty), `window` the cycles.
pub struct ProbeVcd<W: std::io::Write> {
    w: vcd::Writer<W>,
    probes: &'static Probes,
    /// The VCD id of each probe, if its scope is written.
    ids: Vec<Option<vcd::IdCode>>,
    last: Vec<Option<u64>>,
    window: std::ops::Range<u64>,
}

impl<W: std::io::Write> ProbeVcd<W> {
    pub fn new(
        out: W,
        probes: &'static Probes,
        scopes: &[String],
        window: std::ops::Range<u64>,
    ) -> std::io::Result<Self> {
        let mut w = vcd::Writer::new(out);
        w.timescale(1, vcd::TimescaleUnit::NS)?;
        w.add_module("chip")?;
        let mut ids = vec![];
        let mut scope = "";
        for &(s, name, width) in probes.signals {
            if !scopes.is_empty() && !scopes.iter().any(|x| x == s) {
                ids.push(None);
                continue;
            }
            if s != scope {
                if !scope.is_empty() {
                    w.upscope()?;
                }
                w.add_module(s)?;
                scope = s;
            }
            ids.push(Some(w.add_wire(width, name)?));
        }
        if !scope.is_empty() {
            w.upscope()?;
        }
        w.upscope()?;
        w.enddefinitions()?;
        Ok(ProbeVcd {
            w,
            probes,
            ids,
            last: vec![None; probes.signals.len()],
            window,
        })
    }

    /// The values of cycle `t`.
    pub fn cycle(&mut self, t: u64, values: &[u64]) -> std::io::Result<()> {
        if !self.window.contains(&t) {
            return Ok(());
        }
        let mut stamped = false;
        for (k, &v) in values.iter().enumerate() {
            let Some(id) = self.ids[k] else { continue };
            if self.last[k] == Some(v) {
                continue;
            }
            self.last[k] = Some(v);
            if !stamped {
                self.w.timestamp(t)?;
                stamped = true;
            }
            let width = self.probes.signals[k].2;
            let bits: Vec<vcd::Value> = (0..width)
                .rev()
                .map(|b| {
                    if v >> b & 1 == 1 {
                        vcd::Value::V1
                    } else {
                        vcd::Value::V0
                    }
                })
                .collect();
            self.w.change_vector(id, &bits)?;
        }
        Ok(())
    }
}

/// A traversal VCD written to a file, whose errors name it.
pub struct VcdFile {
    vcd: ProbeVcd<std::io::BufWriter<std::fs::File>>,
    path: std::path::PathBuf,
}

impl VcdFile {
    /// The values of cycle `t`.
    pub fn cycle(&mut self, t: u64, values: &[u64]) -> Result<(), String> {
        (self.vcd.cycle(t, values)).map_err(|e| format!("{}: {e}", self.path.display()))
    }

    /// [`run_query`]'s observer for an optional VCD: cycle `t`'s probed values `v` into
    /// `vcd`, if one is open.
    pub fn observe(vcd: &mut Option<VcdFile>, t: u64, v: Option<Vec<u64>>) -> Result<(), String> {
        match vcd {
            Some(f) => f.cycle(t, &v.unwrap_or_default()),
            None => Ok(()),
        }
    }
}

/// A traversal VCD of `probes` at `path` (its directory made if missing) of `scopes` (all
/// if empty) in cycles `window`. Errors name the path.
pub fn open_vcd(
    path: &std::path::Path,
    probes: &'static Probes,
    scopes: &[String],
    window: std::ops::Range<u64>,
) -> Result<VcdFile, ChipError> {
    let io = |e: std::io::Error| ChipError(format!("{}: {e}", path.display()));
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        if dir.is_file() {
            return Err(ChipError(format!(
                "{}: is a file, not a directory for the VCD files",
                dir.display()
            )));
        }
        std::fs::create_dir_all(dir).map_err(io)?;
    }
    let file = std::io::BufWriter::new(std::fs::File::create(path).map_err(io)?);
    Ok(VcdFile {
        vcd: ProbeVcd::new(file, probes, scopes, window).map_err(io)?,
        path: path.to_path_buf(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chip::config::ChipConfig;
    use crate::chip::params::Params;
    use crate::chip::reg::{Mode, Order};

    /// A chip asking for a word past the memory image stops with an error naming the cycle
    /// and the address, clock by clock (`probe`) and running on its own (`skip`) alike.
    #[test]
    fn a_request_past_the_image_is_an_error() {
        let m = crate::mesh::resolve("sphere:40").unwrap().triangles_f64();
        let q = crate::query::Chip::new(&m, &m, ChipConfig::default()).unwrap();
        let setup = q.setup(&crate::pose::Pose::new(0.0, 0.0, 0.0, 0.5, 0.0, 0.0));
        let p = Params::RTL;
        let span = q.image_span(&p.memory);
        let writes = q.control_writes(Order::Lifo, Mode::All, &p);
        for (words, probe) in [(span, false), (span / 2, false), (span / 2, true)] {
            let mut c =
                crate::cycle::chip::Chip::new(&q.cfg, p, &q.a, &q.b, &setup, false).unwrap();
            let d = Drive {
                memory: p.memory_clocks().unwrap(),
                word_bits: q.layout.word_bits(),
                reader: Reader::default(),
                words,
                max_cycles: 1 << 30,
            };
            let r = run_query(&mut c, &writes, &d, probe, |_, _| Ok(()), !probe);
            match (words == span, r) {
                (true, r) => assert!(r.is_ok(), "the whole image: {:?}", r.err()),
                (false, Ok(_)) => panic!("half the image ({words} of {span} words): no error"),
                (false, Err(e)) => assert!(
                    e.0.contains(&format!("past the image ({words} words)")),
                    "{}",
                    e.0
                ),
            }
        }
    }
}
