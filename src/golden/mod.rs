//! The chip's values as bit-exact software, operation by operation in pipeline order, and
//! the host's part: the per-pose setup and the memory image. Every RTL block is checked
//! against these functions; the cycle model takes its values from them.
//!
//! | file | unit |
//! |---|---|
//! | [`host`] | the host's setup per pose (DATE'05 Eq. 6, WSCG'03 Eq. 3) |
//! | [`certificate`] | T.CHECK's certificate constants |
//! | [`enclosure`] | f64 upper bounds of the certificate's rounded values; the check mode of the fast paths |
//! | [`memory`] | the memory image: node and triangle words, A's triangle cache |
//! | [`doptrf`] | the DOPTRF lane (DATE'05 Eq. 10) |
//! | [`klmsel`] | D.KLMSEL, the lanes' operand selection |
//! | [`dop_unit`] | the DOP unit: k lanes, NOR-reduced |
//! | [`tcheck`] | T.CHECK with its certificate (DATE'05 §4.2) |
//! | [`tri_unit`] | TRI_UNIT: two T.CHECKs |
//! | [`d_cntr`] | D_CNTR's order of node pairs (DATE'05 §4.3) |

pub mod certificate;
pub mod d_cntr;
pub mod dop_unit;
pub mod doptrf;
pub mod enclosure;
pub mod host;
pub mod klmsel;
pub mod memory;
pub mod tcheck;
pub mod tri_unit;
