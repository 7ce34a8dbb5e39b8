//! Operand generators shared by the RTL testbenches: bit patterns of a format.

use collision_chip::format::Format;
use proptest::prelude::*;

/// A format's bit-pattern fields: `e` exponent bits, `f` fraction bits.
#[derive(Clone, Copy, Debug)]
pub struct Fmt {
    pub fmt: Format,
    pub e: u32,
    pub f: u32,
}

#[allow(dead_code)] // each testbench uses its own subset
impl Fmt {
    pub fn of(fmt: Format) -> Fmt {
        Fmt { fmt, e: fmt.exp_bits(), f: fmt.frac_bits() }
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
            prop::collection::vec(0..t.f, 1..4).prop_map(|v| v.iter().fold(0u64, |a, &i| a | (1 << i))),
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
