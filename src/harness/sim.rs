//! Runs a DOP-unit vector file through the rust-hdl model, in rust-hdl's own simulator.
//!
//! The vector text is the one `cchip vectors` writes for `dop_unit_k<k>_<fmt>_<rounding>`
//! ([`units`](super::units), format in scripts/README.md):
//!
//! ```text
//! // preload: load_en load_addr load_data
//! // d$0 .. d$<k-1> e$0 .. e$<k-1> tag overlap tag_out
//! // latency: 15
//! @ 1 00 3dfef52a                       <- one preload cycle (the host setup), valid_in low
//! 3f800000 .. 0000 1 0000               <- one case (node pair) per cycle
//! ```
//!
//! A folded unit's file (`dop_unit_fold<ii>_k<k>_...`) also has `// interval: ii` (a case
//! every ii cycles) and a last column `in_ready`, its value in the cycle the case's result is
//! out.
//!
//! [`parse_dop_vectors`] reads it (checking the headers against the unit's k), and
//! [`run_dop_vectors`] drives a unit the same way the Verilog testbench of
//! `scripts/verilog/prepare.py` does: one cycle per `@` line with `valid_in` low, then one
//! case per interval with `valid_in` high, then `latency + 1` idle cycles to flush the pipeline.
//! Each half cycle is settled with rust-hdl's [`simulate`]. It returns the unit's outputs per
//! case (in case order; a `valid_out` at the wrong edge, or lost, is an error) and the number
//! of clock cycles simulated, so a caller can compare them with the expected fields and time
//! the simulator in cycles per second (`benches/rtl_sim.rs`).
//!
//! The driver is generic over [`DopUnitSim`], implemented for the stamped DOP units
//! [`b32::DopUnit6`], [`b32::DopUnit24`], [`e8m15::DopUnit6`], [`e8m15::DopUnit24`],
//! [`e8m15::DopUnit14`], [`b32::DopUnit18`] and [`e8m15::DopUnit26`], and the folded ones
//! (`DopUnit6Fold2` .. `DopUnit24Fold24`, both formats).
//! The k = 24 units are about 2 MB values built on the stack: construct and run them in a
//! thread with a big stack (e.g. `std::thread::Builder::new().stack_size(512 << 20)`).

use crate::rtl::{b32, e8m15};
use rust_hdl::prelude::*;

/// A DOP unit as the vector driver sees it: its ports, as plain integers.
pub trait DopUnitSim: Block {
    /// Number of lanes (DOP directions).
    const K: usize;
    /// Word width of `d`, `e`, `load_data` in bits.
    const WIDTH: usize;
    /// Clocks between pairs taken (1 unless folded).
    const INTERVAL: usize = 1;
    /// Clocks from a pair taken to its verdict.
    const LATENCY: usize;
    /// Drives the setup write port (`load_en`, `load_addr`, `load_data`).
    fn set_load(&mut self, en: bool, addr: u64, data: u64);
    /// Drives one node pair (`d[K]`, `e[K]` as bit patterns, `tag`) and `valid_in`.
    fn set_pair(&mut self, d: &[u64], e: &[u64], tag: u16, valid: bool);
    /// Reads `valid_out`, `overlap`, `tag_out`.
    fn out(&self) -> (bool, bool, u16);
    /// Drives the clock level.
    fn set_clock(&mut self, high: bool);
    /// Whether a pair driven now is taken (`in_ready`; always, unless folded).
    fn in_ready(&self) -> bool {
        true
    }
}

macro_rules! impl_dop_unit_sim {
    ($t:ty, $k:expr, $w:expr) => {
        impl_dop_unit_sim!($t, $k, $w, {});
    };
    // a folded unit: its interval and `in_ready`
    ($t:ty, $k:expr, $w:expr, fold) => {
        impl_dop_unit_sim!($t, $k, $w, {
            const INTERVAL: usize = <$t>::INTERVAL;
            fn in_ready(&self) -> bool {
                self.in_ready.val()
            }
        });
    };
    ($t:ty, $k:expr, $w:expr, { $($extra:tt)* }) => {
        impl DopUnitSim for $t {
            const K: usize = $k;
            const WIDTH: usize = $w;
            const LATENCY: usize = <$t>::LATENCY;
            $($extra)*
            fn set_load(&mut self, en: bool, addr: u64, data: u64) {
                self.load_en.next = en;
                self.load_addr.next = addr.into();
                self.load_data.next = data.into();
            }
            fn set_pair(&mut self, d: &[u64], e: &[u64], tag: u16, valid: bool) {
                for i in 0..$k {
                    self.d[i].next = d[i].into();
                    self.e[i].next = e[i].into();
                }
                self.tag.next = (tag as u64).into();
                self.valid_in.next = valid;
            }
            fn out(&self) -> (bool, bool, u16) {
                (self.valid_out.val(), self.overlap.val(), self.tag_out.val().to_u64() as u16)
            }
            fn set_clock(&mut self, high: bool) {
                self.clock.next = Clock { clk: high };
            }
        }
    };
}
impl_dop_unit_sim!(b32::DopUnit6, 6, b32::WIDTH);
impl_dop_unit_sim!(b32::DopUnit24, 24, b32::WIDTH);
impl_dop_unit_sim!(e8m15::DopUnit6, 6, e8m15::WIDTH);
impl_dop_unit_sim!(e8m15::DopUnit24, 24, e8m15::WIDTH);
// The other k, each in one format: the same macro (the area study synthesizes every one).
impl_dop_unit_sim!(e8m15::DopUnit14, 14, e8m15::WIDTH);
impl_dop_unit_sim!(b32::DopUnit18, 18, b32::WIDTH);
impl_dop_unit_sim!(e8m15::DopUnit26, 26, e8m15::WIDTH);
impl_dop_unit_sim!(b32::DopUnit6Fold2, 6, b32::WIDTH, fold);
impl_dop_unit_sim!(b32::DopUnit6Fold3, 6, b32::WIDTH, fold);
impl_dop_unit_sim!(b32::DopUnit6Fold6, 6, b32::WIDTH, fold);
impl_dop_unit_sim!(e8m15::DopUnit6Fold2, 6, e8m15::WIDTH, fold);
impl_dop_unit_sim!(e8m15::DopUnit6Fold3, 6, e8m15::WIDTH, fold);
impl_dop_unit_sim!(e8m15::DopUnit6Fold6, 6, e8m15::WIDTH, fold);
impl_dop_unit_sim!(e8m15::DopUnit6Fold6Fpga, 6, e8m15::WIDTH, fold);
impl_dop_unit_sim!(b32::DopUnit24Fold4, 24, b32::WIDTH, fold);
impl_dop_unit_sim!(b32::DopUnit24Fold6, 24, b32::WIDTH, fold);
impl_dop_unit_sim!(b32::DopUnit24Fold8, 24, b32::WIDTH, fold);
impl_dop_unit_sim!(b32::DopUnit24Fold12, 24, b32::WIDTH, fold);
impl_dop_unit_sim!(b32::DopUnit24Fold24, 24, b32::WIDTH, fold);
impl_dop_unit_sim!(e8m15::DopUnit24Fold4, 24, e8m15::WIDTH, fold);
impl_dop_unit_sim!(e8m15::DopUnit24Fold6, 24, e8m15::WIDTH, fold);
impl_dop_unit_sim!(e8m15::DopUnit24Fold8, 24, e8m15::WIDTH, fold);
impl_dop_unit_sim!(e8m15::DopUnit24Fold12, 24, e8m15::WIDTH, fold);
impl_dop_unit_sim!(e8m15::DopUnit24Fold24, 24, e8m15::WIDTH, fold);

/// One preload cycle (an `@ en addr data` line).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Preload {
    pub en: bool,
    pub addr: u64,
    pub data: u64,
}

/// One case: the inputs of a node pair and the expected outputs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DopCase {
    /// Line number in the vector text (1-based).
    pub line: usize,
    /// B's DOP `d[k]` and A's DOP `e[k]`, bit patterns.
    pub d: Vec<u64>,
    pub e: Vec<u64>,
    pub tag: u16,
    /// Expected `overlap` and `tag_out`, and `in_ready` if the file has the column.
    pub overlap: bool,
    pub tag_out: u16,
    pub in_ready: Option<bool>,
}

/// A parsed DOP-unit vector file.
#[derive(Clone, Debug, Default)]
pub struct DopVectors {
    /// k, from the header.
    pub k: usize,
    /// The `// latency: N` line.
    pub latency: usize,
    /// The `// interval: N` line (clocks between cases; 1 if absent).
    pub interval: usize,
    pub preload: Vec<Preload>,
    pub cases: Vec<DopCase>,
}

/// What the unit produced for one case.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DopOut {
    pub overlap: bool,
    pub in_ready: bool,
    pub tag: u16,
}

/// A finished run: outputs in case order and clock cycles simulated (preload + cases +
/// latency + 1, as in the Verilog testbench).
#[derive(Clone, Debug)]
pub struct DopRun {
    pub outputs: Vec<DopOut>,
    pub cycles: u64,
}

impl DopRun {
    /// The cases whose outputs differ from the expected fields: (case index, got).
    pub fn mismatches<'a>(
        &'a self,
        v: &'a DopVectors,
    ) -> impl Iterator<Item = (usize, DopOut)> + 'a {
        self.outputs
            .iter()
            .zip(&v.cases)
            .enumerate()
            .filter(|(_, (o, c))| {
                o.overlap != c.overlap
                    || o.tag != c.tag_out
                    || c.in_ready.is_some_and(|r| r != o.in_ready)
            })
            .map(|(i, (o, _))| (i, *o))
    }
}

/// A malformed vector file or a unit that misbehaved (valid out of step).
#[derive(Debug, thiserror::Error)]
pub enum SimError {
    #[error("line {line}: {msg}")]
    Vector { line: usize, msg: String },
    #[error("{0}")]
    Unit(String),
}

fn verr(line: usize, msg: impl Into<String>) -> SimError {
    SimError::Vector {
        line,
        msg: msg.into(),
    }
}

fn hex_field(line: usize, name: &str, tok: &str, bits: usize) -> Result<u64, SimError> {
    let v = u64::from_str_radix(tok, 16)
        .map_err(|_| verr(line, format!("field {name} = {tok:?} is not hex")))?;
    if tok.len() != bits.div_ceil(4) || (bits < 64 && v >> bits != 0) {
        return Err(verr(
            line,
            format!(
                "field {name} = {tok:?}: expected {} hex digits, {bits} bits",
                bits.div_ceil(4)
            ),
        ));
    }
    Ok(v)
}

/// Parses a DOP-unit vector text (`vectors/dop_unit_k<k>_<fmt>_<rounding>.hex`) for words of
/// `width` bits. The case header must be `d$0 .. d$<k-1> e$0 .. e$<k-1> tag overlap tag_out`,
/// `in_ready` optional after it (k taken from it), the preload header `load_en load_addr load_data` (required if there are
/// `@` lines, which must come before the first case); `// interval: N` optional. Other `//` and `#` lines, blank lines
/// and `//` comments after the fields are ignored.
pub fn parse_dop_vectors(text: &str, width: usize) -> Result<DopVectors, SimError> {
    let mut v = DopVectors::default();
    let mut have_header = false;
    let mut have_preload_header = false;
    let mut latency = None;
    let mut ready_column = false;
    v.interval = 1;
    for (no, raw) in text.lines().enumerate() {
        let no = no + 1;
        let s = raw.trim();
        if s.is_empty() {
            continue;
        }
        if let Some(body) = s.strip_prefix("//").or_else(|| s.strip_prefix('#')) {
            let body = body.trim_start_matches(['/', '#']).trim();
            if let Some(rest) = body.strip_prefix("latency") {
                if let Some(n) = rest.trim_start().strip_prefix([':', '=']) {
                    latency = Some(n.trim().parse().map_err(|_| verr(no, "bad latency"))?);
                    continue;
                }
            }
            if let Some(rest) = body.strip_prefix("interval") {
                if let Some(n) = rest.trim_start().strip_prefix([':', '=']) {
                    v.interval = n.trim().parse().ok().filter(|&n| n >= 1).ok_or_else(|| {
                        verr(no, "bad interval (a whole number of clocks, at least 1)")
                    })?;
                    continue;
                }
            }
            if let Some(rest) = body.strip_prefix("preload:") {
                let names: Vec<&str> = rest
                    .split([' ', '\t', ','])
                    .filter(|t| !t.is_empty())
                    .collect();
                if names != ["load_en", "load_addr", "load_data"] {
                    return Err(verr(
                        no,
                        format!("preload header {names:?}, expected load_en load_addr load_data"),
                    ));
                }
                have_preload_header = true;
                continue;
            }
            if !have_header && v.cases.is_empty() && body.starts_with("d$0") {
                let names: Vec<&str> = body
                    .split_whitespace()
                    .filter(|t| !matches!(*t, "->" | "|" | "=" | ":"))
                    .collect();
                let k = names.iter().take_while(|n| n.starts_with("d$")).count();
                let want: Vec<String> = (0..k)
                    .map(|i| format!("d${i}"))
                    .chain((0..k).map(|i| format!("e${i}")))
                    .chain(["tag", "overlap", "tag_out"].map(String::from))
                    .collect();
                ready_column = names.len() == want.len() + 1 && names.last() == Some(&"in_ready");
                if names[..names.len() - ready_column as usize] != want[..] {
                    return Err(verr(no, format!("case header is not `d$0 .. d${} e$0 .. e${} tag overlap tag_out [in_ready]`", k - 1, k - 1)));
                }
                v.k = k;
                have_header = true;
            }
            continue;
        }
        let fields = s.split("//").next().unwrap_or("");
        if let Some(rest) = fields.strip_prefix('@') {
            if !have_preload_header {
                return Err(verr(
                    no,
                    "preload line (`@ ...`) without a `// preload:` header",
                ));
            }
            if !v.cases.is_empty() {
                return Err(verr(no, "preload line after the first case"));
            }
            let t: Vec<&str> = rest.split_whitespace().collect();
            if t.len() != 3 {
                return Err(verr(no, format!("{} preload fields, expected 3", t.len())));
            }
            v.preload.push(Preload {
                en: hex_field(no, "load_en", t[0], 1)? != 0,
                addr: hex_field(no, "load_addr", t[1], 8)?,
                data: hex_field(no, "load_data", t[2], width)?,
            });
            continue;
        }
        if !have_header {
            return Err(verr(
                no,
                "case before the `// d$0 .. tag overlap tag_out` header",
            ));
        }
        let k = v.k;
        let t: Vec<&str> = fields.split_whitespace().collect();
        if t.len() != 2 * k + 3 + ready_column as usize {
            return Err(verr(
                no,
                format!(
                    "{} fields, expected {}",
                    t.len(),
                    2 * k + 3 + ready_column as usize
                ),
            ));
        }
        let word = |i: usize| hex_field(no, if i < k { "d" } else { "e" }, t[i], width);
        v.cases.push(DopCase {
            line: no,
            d: (0..k).map(word).collect::<Result<_, _>>()?,
            e: (k..2 * k).map(word).collect::<Result<_, _>>()?,
            tag: hex_field(no, "tag", t[2 * k], 16)? as u16,
            overlap: hex_field(no, "overlap", t[2 * k + 1], 1)? != 0,
            tag_out: hex_field(no, "tag_out", t[2 * k + 2], 16)? as u16,
            in_ready: if ready_column {
                Some(hex_field(no, "in_ready", t[2 * k + 3], 1)? != 0)
            } else {
                None
            },
        });
    }
    if !have_header {
        return Err(verr(0, "no `// d$0 .. tag overlap tag_out` header"));
    }
    v.latency = latency.ok_or_else(|| verr(0, "no `// latency: N` line"))?;
    Ok(v)
}

/// One clock cycle: low half, then the rising edge, each settled.
fn cycle<U: DopUnitSim>(uut: &mut U) -> Result<(), SimError> {
    for high in [false, true] {
        uut.set_clock(high);
        if !simulate(uut, 1000) {
            return Err(SimError::Unit("logic did not settle".into()));
        }
    }
    Ok(())
}

/// Runs `v` through `uut` (a unit fresh from its `*_top` constructor): the preload cycles
/// with `valid_in` low, then one case every `interval` cycles (`in_ready` high then), then
/// `latency + 1` idle cycles. Checks that `valid_out` is high exactly `latency` rising edges
/// after each case and low otherwise;
/// does not compare the outputs with the expected fields (see [`DopRun::mismatches`]).
pub fn run_dop_vectors<U: DopUnitSim>(uut: &mut U, v: &DopVectors) -> Result<DopRun, SimError> {
    if v.k != U::K {
        return Err(SimError::Unit(format!(
            "vectors for k = {}, unit has k = {}",
            v.k,
            U::K
        )));
    }
    if v.interval != U::INTERVAL {
        return Err(SimError::Unit(format!(
            "vectors for a pair every {} clocks, the unit takes one every {}",
            v.interval,
            U::INTERVAL
        )));
    }
    let lat = v.latency;
    if lat == 0 {
        return Err(SimError::Unit(
            "latency 0: the DOP unit is pipelined".into(),
        ));
    }
    let zero = vec![0u64; U::K];
    let mut cycles = 0u64;
    uut.set_pair(&zero, &zero, 0, false);
    for p in &v.preload {
        uut.set_load(p.en, p.addr, p.data);
        cycle(uut)?;
        cycles += 1;
        if uut.out().0 {
            return Err(SimError::Unit(format!(
                "valid_out high in preload cycle {cycles}"
            )));
        }
    }
    uut.set_load(false, 0, 0);
    let n = v.cases.len();
    let mut outputs = Vec::with_capacity(n);
    let ii = v.interval;
    for cyc in 0..n * ii + lat + 1 {
        match v.cases.get(cyc / ii).filter(|_| cyc % ii == 0) {
            Some(_) if !uut.in_ready() => {
                return Err(SimError::Unit(format!(
                    "in_ready low when case {} was driven (cycle {cyc})",
                    cyc / ii
                )))
            }
            Some(c) => uut.set_pair(&c.d, &c.e, c.tag, true),
            None => uut.set_pair(&zero, &zero, 0, false),
        }
        cycle(uut)?;
        cycles += 1;
        let (valid, overlap, tag) = uut.out();
        // the case driven in cycle c is out after its `lat`-th rising edge, i.e. in cycle c + lat - 1
        let due = (cyc + 1)
            .checked_sub(lat)
            .filter(|&t| t % ii == 0)
            .map(|t| t / ii)
            .filter(|&i| i < n);
        match (valid, due) {
            (true, Some(i)) if i == outputs.len() => outputs.push(DopOut {
                overlap,
                tag,
                in_ready: uut.in_ready(),
            }),
            (false, None) => {}
            (true, _) => {
                return Err(SimError::Unit(format!(
                    "spurious valid_out in cycle {cyc} of the case stream"
                )))
            }
            (false, Some(i)) => {
                return Err(SimError::Unit(format!(
                    "valid_out low when case {i} was due (cycle {cyc})"
                )))
            }
        }
    }
    Ok(DopRun { outputs, cycles })
}
