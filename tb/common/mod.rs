//! Operand generators shared by the RTL testbenches: bit patterns of a format.
#![allow(dead_code)] // each testbench uses its own subset

use collision_chip::format::Format;
use proptest::prelude::*;

pub mod families;
pub mod vcd_file;

/// A format's bit-pattern fields: `e` exponent bits, `f` fraction bits.
#[derive(Clone, Copy, Debug)]
pub struct Fmt {
    pub fmt: Format,
    pub e: u32,
    pub f: u32,
}

impl Fmt {
    pub fn of(fmt: Format) -> Fmt {
        Fmt {
            fmt,
            e: fmt.exp_bits(),
            f: fmt.frac_bits(),
        }
    }
    /// The all-ones exponent field.
    pub fn ones(self) -> u64 {
        (1 << self.e) - 1
    }
    pub fn bias(self) -> u64 {
        self.fmt.bias() as u64
    }
    pub fn pack(self, s: bool, exp: u64, frac: u64) -> u64 {
        self.fmt.pack(s, exp, frac)
    }
    pub fn specials(self) -> Vec<u64> {
        self.fmt.special_patterns()
    }
}

/// One operand: random bits, the format's special patterns, subnormals, extreme exponents,
/// sparse and dense fractions (exact products, ties), and moderate values (where sums
/// cancel and round).
pub fn operand(t: Fmt) -> BoxedStrategy<u64> {
    let mask = (1u64 << (t.e + t.f + 1)) - 1;
    let frac = move || {
        prop_oneof![
            0u64..(1 << t.f),
            prop::collection::vec(0..t.f, 1..4)
                .prop_map(|v| v.iter().fold(0u64, |a, &i| a | (1 << i))),
            (0..t.f).prop_map(move |i| ((1u64 << t.f) - 1) ^ (1 << i)),
        ]
    };
    prop_oneof![
        3 => any::<u64>().prop_map(move |x| x & mask),
        2 => prop::sample::select(t.specials()),
        2 => (any::<bool>(), frac()).prop_map(move |(s, f)| t.pack(s, 0, f)),
        3 => (any::<bool>(), prop_oneof![0..4u64, (t.ones() - 4)..=t.ones()], frac()).prop_map(move |(s, e, f)| t.pack(s, e, f)),
        2 => (any::<bool>(), 0..=t.ones(), frac()).prop_map(move |(s, e, f)| t.pack(s, e, f)),
        4 => (any::<bool>(), (t.bias() - 8)..(t.bias() + 8), frac()).prop_map(move |(s, e, f)| t.pack(s, e, f)),
    ]
    .boxed()
}

/// A pipelined unit as the testbenches drive it: one input per cycle with a valid bit, a
/// fixed latency.
pub trait Pipelined: rust_hdl::prelude::Block {
    type In: Copy + Default;
    type Out;
    const LATENCY: usize;
    fn set(&mut self, x: Self::In, valid: bool);
    fn out(&self) -> (bool, Self::Out);
    fn clock(&mut self, high: bool);
}

/// Half a clock period: settle the combinational logic.
pub fn settle<B: rust_hdl::prelude::Block>(uut: &mut B) {
    assert!(
        rust_hdl::prelude::simulate(uut, 1000),
        "logic did not settle"
    );
}

/// Drives `ops` one per cycle (valid high), then flushes. Returns the outputs in order and
/// checks that each appears exactly `LATENCY` rising edges after its inputs were presented
/// (inputs before edge 1, output right after edge `LATENCY`).
pub fn run<U: Pipelined>(uut: &mut U, ops: &[U::In]) -> Vec<U::Out> {
    run_traced(uut, ops, |_, _| {})
}

/// [`run`], calling `after_edge(uut, time)` after every clock edge (time in half periods of
/// 5 units), e.g. to write a VCD.
pub fn run_traced<U: Pipelined>(
    uut: &mut U,
    ops: &[U::In],
    mut after_edge: impl FnMut(&U, u64),
) -> Vec<U::Out> {
    let n = ops.len();
    let mut outs = Vec::with_capacity(n);
    let mut time = 0;
    for cyc in 0..n + U::LATENCY + 1 {
        let (valid, x) = match ops.get(cyc) {
            Some(&x) => (true, x),
            None => (false, U::In::default()),
        };
        uut.set(x, valid);
        for high in [false, true] {
            uut.clock(high);
            settle(uut);
            after_edge(uut, time);
            time += 5;
        }
        let (v, y) = uut.out();
        if v {
            assert_eq!(
                cyc + 1,
                outs.len() + U::LATENCY,
                "output {} at the wrong edge",
                outs.len()
            );
            outs.push(y);
        }
    }
    assert_eq!(outs.len(), n, "valid outputs lost");
    outs
}

/// The VCD file of run `name`: `target/rtl-vcd/<name>.vcd`.
pub fn vcd_path(name: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("target")
        .join("rtl-vcd");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(format!("{name}.vcd"))
}

/// [`run`] with a VCD of every signal, written to [`vcd_path`]`(name)` with the root
/// scope named `root` (rust-hdl calls it `uut`), for GTKWave.
pub fn run_vcd<U: Pipelined>(uut: &mut U, ops: &[U::In], name: &str, root: &str) -> Vec<U::Out> {
    use rust_hdl::prelude::{write_vcd_change, write_vcd_dump, write_vcd_header};
    let mut buf = vec![];
    let outs = {
        let mut vcd = Some(write_vcd_dump(write_vcd_header(&mut buf, &*uut), &*uut));
        run_traced(uut, ops, |u, time| {
            let mut v = vcd.take().unwrap();
            v.timestamp(time).unwrap();
            vcd = Some(write_vcd_change(v, u));
        })
    };
    let text = String::from_utf8(buf).unwrap().replacen(
        "$scope module uut $end",
        &format!("$scope module {root} $end"),
        1,
    );
    let path = vcd_path(name);
    std::fs::write(&path, text).unwrap();
    println!("wrote {}", path.display());
    outs
}

/// The values of signal `data` of the VCD's scope `root` after every rising edge (the
/// testbenches write a timestamp every half cycle: 0, 5, 10, ..., the edges at 5, 15, ...)
/// at which its signal `valid` is 1: the outputs as a waveform viewer shows them.
pub fn vcd_outputs(path: &std::path::Path, root: &str, valid: &str, data: &str) -> Vec<u64> {
    use vcd::{Command, Value};
    let mut p = vcd::Parser::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let header = p.parse_header().unwrap();
    let code = |name: &str| {
        header
            .find_var(&[root, name])
            .unwrap_or_else(|| panic!("{}: no signal {root}.{name}", path.display()))
            .code
    };
    let (v, d) = (code(valid), code(data));
    let bits = |x: &[Value]| {
        x.iter()
            .fold(0u64, |a, b| a << 1 | (*b == Value::V1) as u64)
    };
    let (mut now, mut is_valid, mut value, mut out) = (None::<u64>, false, 0u64, vec![]);
    let mut sample = |now: Option<u64>, is_valid: bool, value: u64| {
        if is_valid && now.is_some_and(|t| t % 10 == 5) {
            out.push(value);
        }
    };
    for c in p {
        match c.unwrap() {
            Command::Timestamp(t) => {
                sample(now, is_valid, value);
                now = Some(t);
            }
            Command::ChangeScalar(c, x) if c == v => is_valid = x == Value::V1,
            Command::ChangeScalar(c, x) if c == d => value = (x == Value::V1) as u64,
            Command::ChangeVector(c, x) if c == d => value = bits(&x),
            _ => {}
        }
    }
    sample(now, is_valid, value);
    out
}
