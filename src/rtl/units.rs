//! The exported units: for each, its Verilog (`rtl/<name>.v`, by `generate_verilog`) and its
//! golden test vectors (`vectors/<name>.hex`, TestFloat style, see scripts/README.md),
//! written by `cchip export-verilog` and `cchip vectors` and checked in. CI regenerates both
//! and fails if they differ from the checked-in files, then runs every unit against its
//! vectors under Icarus Verilog and Verilator (`scripts/check-rtl.sh`).

use crate::format::{Format, Rounding};
use rand::{Rng, SeedableRng};
use std::fmt::Write;
use std::path::Path;

/// Vector cases per floating-point unit: every pair of the format's special values, then
/// random operands.
const RANDOM_CASES: usize = 3000;

/// One exported unit.
pub struct Unit {
    /// `<unit>_<format>_<rounding>`, the file stem in rtl/ and vectors/.
    pub name: String,
    pub latency: u32,
    verilog: Box<dyn Fn() -> String>,
    vectors: Box<dyn Fn() -> String>,
}

impl Unit {
    pub fn verilog(&self) -> String {
        (self.verilog)()
    }

    pub fn vectors(&self) -> String {
        (self.vectors)()
    }
}

fn rounding_tag(r: Rounding) -> &'static str {
    match r {
        Rounding::NearestEven => "rne",
        Rounding::TowardPositive => "ru",
        Rounding::TowardNegative => "rd",
    }
}

/// Every exported unit, in a fixed order.
pub fn all() -> Vec<Unit> {
    let mut units = vec![];
    for r in [Rounding::NearestEven, Rounding::TowardPositive] {
        for (tag, fmt) in [("b32", Format::BINARY32), ("e8m15", Format::REDUCED)] {
            let (vm, va): (fn(Rounding) -> String, fn(Rounding) -> String) = match tag {
                "b32" => (super::b32::verilog_fp_mul, super::b32::verilog_fp_add),
                _ => (super::e8m15::verilog_fp_mul, super::e8m15::verilog_fp_add),
            };
            let name = format!("fp_mul_{tag}_{}", rounding_tag(r));
            let n2 = name.clone();
            units.push(Unit {
                name,
                latency: 4,
                verilog: Box::new(move || vm(r)),
                vectors: Box::new(move || fp_vectors(&n2, fmt, r, false, 4)),
            });
            let name = format!("fp_add_{tag}_{}", rounding_tag(r));
            let n2 = name.clone();
            units.push(Unit {
                name,
                latency: 3,
                verilog: Box::new(move || va(r)),
                vectors: Box::new(move || fp_vectors(&n2, fmt, r, true, 3)),
            });
        }
    }
    units
}

/// Special and boundary values of a format (bit patterns).
fn specials(fmt: Format) -> Vec<u64> {
    let (e, f) = (fmt.exp_bits(), fmt.frac_bits());
    let pack = |s: u64, ex: u64, fr: u64| (s << (e + f)) | (ex << f) | fr;
    let top = (1u64 << e) - 1;
    let fmax = (1u64 << f) - 1;
    let mut v = vec![];
    for s in 0..2 {
        v.extend([
            pack(s, 0, 0),            // zero
            pack(s, 0, 1),            // smallest subnormal
            pack(s, 0, fmax),         // largest subnormal
            pack(s, 1, 0),            // smallest normal
            pack(s, top - 1, fmax),   // largest finite
            pack(s, fmt.bias() as u64, 0),     // 1
            pack(s, fmt.bias() as u64, 1),     // 1 + ulp
            pack(s, fmt.bias() as u64 - 1, fmax), // 1 - ulp/2
            pack(s, top, 0),          // infinity
        ]);
    }
    v.push(pack(0, top, 1 << (f - 1))); // NaN
    v
}

/// A random operand: any bit pattern, or a value near 1 (many ties and cancellations).
fn operand(rng: &mut impl Rng, fmt: Format) -> u64 {
    let w = fmt.width();
    match rng.random_range(0..4) {
        0 | 1 => rng.random_range(0..(1u64 << w)),
        _ => {
            let (e, f) = (fmt.exp_bits(), fmt.frac_bits());
            let ex = fmt.bias() as u64 + rng.random_range(0..4) - 2;
            let fr = rng.random_range(0..(1u64 << f)) & !((1u64 << rng.random_range(0..f)) - 1);
            ((rng.random_range(0..2u64)) << (e + f)) | (ex << f) | fr
        }
    }
}

/// Vectors `a b [sub] y` of an adder or multiplier, from the golden `Format` ops.
fn fp_vectors(name: &str, fmt: Format, r: Rounding, add: bool, latency: u32) -> String {
    let digits = (fmt.width() as usize).div_ceil(4);
    let mut out = String::new();
    let _ = writeln!(out, "// a b{} y", if add { " sub" } else { "" });
    let _ = writeln!(out, "// latency: {latency}");
    let _ = writeln!(
        out,
        "// {name}: y = a {} b in {fmt}, rounding {r:?}; golden: collision_chip::format::Format::{}",
        if add { "+ (or - when sub)" } else { "*" },
        if add { "add / sub" } else { "mul" }
    );
    let sp = specials(fmt);
    let mut cases: Vec<(u64, u64, bool)> = sp.iter().flat_map(|&a| sp.iter().map(move |&b| (a, b, false))).collect();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0x5eed ^ name.len() as u64);
    cases.extend((0..RANDOM_CASES).map(|i| (operand(&mut rng, fmt), operand(&mut rng, fmt), add && i % 2 == 1)));
    for (a, b, sub) in cases {
        let (x, y) = (fmt.from_bits(a), fmt.from_bits(b));
        let z = match (add, sub) {
            (false, _) => fmt.mul(x, y, r),
            (true, false) => fmt.add(x, y, r),
            (true, true) => fmt.sub(x, y, r),
        };
        let z = fmt.to_bits(z);
        if add {
            let _ = writeln!(out, "{a:0digits$x} {b:0digits$x} {} {z:0digits$x}", sub as u8);
        } else {
            let _ = writeln!(out, "{a:0digits$x} {b:0digits$x} {z:0digits$x}");
        }
    }
    out
}

/// Writes `<dir>/<unit>.v` for every unit; returns the paths written.
pub fn write_verilog(dir: &Path) -> std::io::Result<Vec<String>> {
    write_all(dir, "v", Unit::verilog)
}

/// Writes `<dir>/<unit>.hex` for every unit; returns the paths written.
pub fn write_vectors(dir: &Path) -> std::io::Result<Vec<String>> {
    write_all(dir, "hex", Unit::vectors)
}

fn write_all(dir: &Path, ext: &str, text: fn(&Unit) -> String) -> std::io::Result<Vec<String>> {
    std::fs::create_dir_all(dir)?;
    all()
        .iter()
        .map(|u| {
            let p = dir.join(format!("{}.{ext}", u.name));
            std::fs::write(&p, text(u))?;
            Ok(p.display().to_string())
        })
        .collect()
}
