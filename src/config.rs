//! The chip configuration a query runs with: k of the k-DOP, the number format of every
//! datapath word, and the rounding of the DOP and triangle datapaths.

use crate::format::{Format, Rounding};
use serde::{Deserialize, Serialize};

/// How the DOP datapath and the host round (DESIGN.md 1.1, 3).
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
            _ => Err(format!("DOP rounding `{s}` unknown; use `outward` or `nearest-even`")),
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ChipConfig {
    pub k: usize,
    pub format: Format,
    pub dop_rounding: DopRounding,
    /// Rounding of every T.CHECK operation.
    pub tri_rounding: Rounding,
}

impl Default for ChipConfig {
    /// The DATE'05 chip: 24-DOPs, binary32, conservative DOP test.
    fn default() -> Self {
        ChipConfig {
            k: 24,
            format: Format::BINARY32,
            dop_rounding: DopRounding::Outward,
            tri_rounding: Rounding::NearestEven,
        }
    }
}
