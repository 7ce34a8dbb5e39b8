//! The chip configuration a query runs with: k of the k-DOP, the number formats of the DOP
//! and triangle datapaths, and the rounding of the DOP and triangle datapaths.

use crate::format::{Format, Rounding};
use serde::{Deserialize, Serialize};

/// The k of the normal sets there are (`dop::normals`: DATE'05 Fig. 1 and its relatives).
pub const SUPPORTED_K: [usize; 5] = [6, 14, 18, 24, 26];
/// Lines of A's triangle cache at most: WSCG'03 assumes 128 (11 KB at binary32).
pub const TRI_CACHE_MAX_LINES: u32 = 1024;
/// Node records held per object at most.
pub const NODE_CACHE_MAX_LINES: u32 = 256;
/// T.CHECK's format needs this many exponent bits at least: its certificate's object scale
/// S (`golden::memory::object_scale`) is a normal power of two (at least 2^emin = 2^(1 - emax))
/// at most 2^-2 of the format's largest value (2^(emax - 2)), which needs emax >= 2.
pub const TCHECK_MIN_EXP_BITS: u32 = 3;

/// How the DOP datapath and the host round (DATE'05 Eq. 10; docs/explanation/accuracy.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum DopRounding {
    /// Stored distances, C, c and every DOPTRF operation rounded toward +inf, with the
    /// host's residuals padded into c: the computed s_i is an upper bound of the exact
    /// one, so a "separated" verdict is always true. The default.
    Outward,
    /// Everything rounded to nearest-even and no padding: tighter, can miss (counted).
    NearestEven,
}

impl DopRounding {
    /// The rounding of each DOPTRF adder and multiplier.
    pub fn op(self) -> Rounding {
        match self {
            DopRounding::Outward => Rounding::TowardPositive,
            DopRounding::NearestEven => Rounding::NearestEven,
        }
    }
}

/// The name the CLI and scenes use (`outward`, `nearest-even`).
impl std::fmt::Display for DopRounding {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str(match self {
            DopRounding::Outward => "outward",
            DopRounding::NearestEven => "nearest-even",
        })
    }
}

impl std::str::FromStr for DopRounding {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "outward" => Ok(DopRounding::Outward),
            "nearest-even" | "nearest" => Ok(DopRounding::NearestEven),
            _ => Err(format!(
                "DOP rounding `{s}` unknown; use `outward` or `nearest-even`"
            )),
        }
    }
}

/// The number formats of the chip's two datapaths: the DOP words and DOPTRF (`dop`), the
/// triangle words and T.CHECK (`tri`). Written `binary32` (both) or `e8m15/binary32` (DOP
/// format / T.CHECK format): a narrower DOP word saves memory traffic and stays conservative
/// under outward rounding, while the triangle test keeps its precision. Serialized as that
/// string.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(try_from = "String", into = "String")]
pub struct Formats {
    pub dop: Format,
    pub tri: Format,
}

impl From<Format> for Formats {
    /// The same format in both datapaths.
    fn from(f: Format) -> Formats {
        Formats { dop: f, tri: f }
    }
}

impl std::fmt::Display for Formats {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        if self.dop == self.tri {
            write!(f, "{}", self.tri)
        } else {
            write!(f, "{}/{}", self.dop, self.tri)
        }
    }
}

impl std::str::FromStr for Formats {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        let parse = |x: &str| {
            x.trim().parse::<Format>().map_err(|e| {
                format!("{e} (a format, or DOP format/T.CHECK format such as \"e8m15/binary32\")")
            })
        };
        match s.split_once('/') {
            None => parse(s).map(Formats::from),
            Some((d, t)) => Ok(Formats {
                dop: parse(d)?,
                tri: parse(t)?,
            }),
        }
    }
}

impl TryFrom<String> for Formats {
    type Error = String;
    fn try_from(s: String) -> Result<Self, String> {
        s.parse()
    }
}

impl From<Formats> for String {
    fn from(f: Formats) -> String {
        f.to_string()
    }
}

/// How the memory image is laid out (a scene's `[chip] layout`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum MemLayout {
    /// One node word per record, pre-order; a memory word is the wider of a node word and a
    /// triangle word, addresses in order. The RTL chips' layout and the `rtl` preset's.
    #[default]
    Words,
    /// Laid out for the bus (WSCG'03 §4.3 stores a node pair per 256-byte burst): the root
    /// alone, then the two children of every inner node in one record ([`treelet_records`](super::layout::treelet_records):
    /// D_CNTR tests both children of a pair next to each other); a memory word of a power of
    /// two bytes holds a node pair or one triangle word; on DDR the records are spread over
    /// the banks ([`RecordMap`](super::layout::RecordMap)). The papers' presets'.
    Records,
}

/// The name scenes use (`words`, `records`).
impl std::fmt::Display for MemLayout {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str(match self {
            MemLayout::Words => "words",
            MemLayout::Records => "records",
        })
    }
}

/// How node records store the DOPs below the root (a scene's `[chip] dop_bits`): `full`,
/// each distance a value of the DOP format, or `b`-bit codes below the DOP of the node's
/// treelet root, which the chip decodes outward ([`dop::stored`](crate::dop::stored);
/// `records` layout).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DopBits {
    #[default]
    Full,
    Bits(u32),
}

/// The widest code, in bits a plane (also at most the DOP format's significand:
/// [`ChipConfig::check`]).
pub const DOP_BITS_MAX: u32 = 16;

/// `full`, or the bits.
impl std::fmt::Display for DopBits {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self {
            DopBits::Full => f.write_str("full"),
            DopBits::Bits(b) => write!(f, "{b}"),
        }
    }
}

impl std::str::FromStr for DopBits {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "full" => Ok(DopBits::Full),
            _ => match s.parse::<u32>() {
                Ok(b) if (1..=DOP_BITS_MAX).contains(&b) => Ok(DopBits::Bits(b)),
                _ => Err(format!(
                    "dop_bits `{s}` unknown; use \"full\" or bits a plane from 1 to {DOP_BITS_MAX}, such as 8"
                )),
            },
        }
    }
}

/// Scenes write `dop_bits = 8` or `dop_bits = "full"`; the JSON says the same.
impl Serialize for DopBits {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            DopBits::Full => s.serialize_str("full"),
            DopBits::Bits(b) => s.serialize_u32(*b),
        }
    }
}

impl<'de> Deserialize<'de> for DopBits {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Written {
            Bits(i64),
            Word(String),
        }
        let s = match Written::deserialize(d)? {
            Written::Bits(b) => b.to_string(),
            Written::Word(w) => w,
        };
        s.parse().map_err(serde::de::Error::custom)
    }
}

/// A query's chip configuration. Scenes (`[chip]`) and the CLI (`--k`, `--format`, ...) read
/// it directly, each key optional ([`Default`]: the papers' chip), and
/// [`check`](ChipConfig::check) it once.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, clap::Args)]
#[serde(deny_unknown_fields, default)]
pub struct ChipConfig {
    /// k of the k-DOP: 6, 14, 18, 24 or 26.
    #[arg(long, default_value_t = ChipConfig::default().k)]
    pub k: usize,
    /// Number format of the datapaths: binary32, reduced (e8m15) or eEmF; DOP/T.CHECK, such as
    /// e8m15/binary32, gives the DOP words and DOPTRF a format of their own.
    #[arg(long, default_value_t = ChipConfig::default().format)]
    pub format: Formats,
    /// DOP rounding: outward (conservative, never a false "separated") or nearest-even.
    #[arg(long, default_value_t = ChipConfig::default().dop_rounding)]
    pub dop_rounding: DopRounding,
    /// Rounding of every T.CHECK operation (scenes only).
    #[arg(skip = ChipConfig::default().tri_rounding)]
    pub tri_rounding: Rounding,
    /// Lines of A's triangle cache (WSCG'03 §4.3: direct mapped, a power of two; WSCG'03 has
    /// 128); 1: the single word held, as in the RTL chips' reset state.
    #[arg(long, default_value_t = ChipConfig::default().tri_cache)]
    pub tri_cache: u32,
    /// Lines of B's triangle cache, direct mapped as A's; 1: the single word held, as in
    /// the RTL chips (WSCG'03's B side is a two-entry SRAM).
    #[arg(long, default_value_t = ChipConfig::default().tri_cache_b)]
    pub tri_cache_b: u32,
    /// The memory image's layout: `words` (a node word per record, the RTL chips') or
    /// `records` (sibling nodes in one record, records spread over DDR banks; scenes and
    /// presets only).
    #[arg(skip = ChipConfig::default().layout)]
    pub layout: MemLayout,
    /// Node records held per object for the DOP unit, least recently used replaced; 1: the
    /// previous pair's, as in the RTL chips.
    #[arg(long, default_value_t = ChipConfig::default().node_cache)]
    pub node_cache: u32,
    /// Stored DOP precision of the node records below the root: `full` or bits a plane
    /// (`records` layout; scenes, presets and the study).
    #[arg(skip = ChipConfig::default().dop_bits)]
    pub dop_bits: DopBits,
}

/// Errors say which k there are.
pub fn check_k(k: usize) -> Result<(), String> {
    if SUPPORTED_K.contains(&k) {
        Ok(())
    } else {
        Err(format!(
            "k = {k} is not supported; choose one of 6, 14, 18, 24, 26"
        ))
    }
}

impl ChipConfig {
    /// Errors say what a valid k and triangle cache are.
    pub fn check(&self) -> Result<(), String> {
        check_k(self.k)?;
        if self.format.tri.exp_bits() < TCHECK_MIN_EXP_BITS {
            return Err(format!(
                "format {}: T.CHECK's format needs at least {TCHECK_MIN_EXP_BITS} exponent bits (its certificate scales each object by a normal power of two at most a quarter of the format's largest value; docs/explanation/accuracy.md), not {}: use e{TCHECK_MIN_EXP_BITS}m{} or wider, or a format such as \"{}/binary32\" (DOP/T.CHECK)",
                self.format,
                self.format.tri.exp_bits(),
                self.format.tri.frac_bits(),
                self.format.dop
            ));
        }
        for (key, lines) in [
            ("tri_cache", self.tri_cache),
            ("tri_cache_b", self.tri_cache_b),
        ] {
            if !(lines.is_power_of_two() && lines <= TRI_CACHE_MAX_LINES) {
                return Err(format!("{key} must be a power of two from 1 to {TRI_CACHE_MAX_LINES} lines (WSCG'03: 128), not {lines}"));
            }
        }
        self.check_dop_bits()?;
        if !(1..=NODE_CACHE_MAX_LINES).contains(&self.node_cache) {
            return Err(format!(
                "node_cache must be 1 to {NODE_CACHE_MAX_LINES} records per object, not {}",
                self.node_cache
            ));
        }
        Ok(())
    }
}

impl ChipConfig {
    /// Codes fit the DOP format's significand (so `q 2^e` is one of its values), and a node
    /// is stored below the treelet root whose DOP its record holds: the `records` layout.
    fn check_dop_bits(&self) -> Result<(), String> {
        let DopBits::Bits(b) = self.dop_bits else {
            return Ok(());
        };
        let p = self.format.dop.frac_bits() + 1;
        if b > p {
            return Err(format!("dop_bits = {b} is wider than the DOP format {}'s {p}-bit significand: use at most {p}, or \"full\"", self.format.dop));
        }
        if self.layout != MemLayout::Records {
            return Err(format!("dop_bits = {b} stores each node below its treelet root's DOP, which only a `records` record holds beside it; this configuration has layout = \"{}\": set [chip] layout = \"records\" (or a preset such as date05), or dop_bits = \"full\"", self.layout));
        }
        Ok(())
    }
}

impl Default for ChipConfig {
    /// The DATE'05 chip: 24-DOPs, binary32, conservative DOP test.
    fn default() -> Self {
        ChipConfig {
            k: 24,
            format: Format::BINARY32.into(),
            dop_rounding: DopRounding::Outward,
            tri_rounding: Rounding::NearestEven,
            tri_cache: 1,
            tri_cache_b: 1,
            layout: MemLayout::Words,
            node_cache: 1,
            dop_bits: DopBits::Full,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_read_and_print_as_written() {
        let split: Formats = "e8m15/binary32".parse().unwrap();
        assert_eq!((split.dop, split.tri), (Format::REDUCED, Format::BINARY32));
        assert_eq!(split.to_string(), "e8m15/binary32");
        assert_eq!(
            "reduced".parse::<Formats>().unwrap(),
            Formats::from(Format::REDUCED)
        );
        assert_eq!(Formats::from(Format::REDUCED).to_string(), "e8m15");
        let e = "e8m15/float".parse::<Formats>().unwrap_err();
        assert!(e.contains("float") && e.contains("e8m15/binary32"), "{e}");
    }
}
