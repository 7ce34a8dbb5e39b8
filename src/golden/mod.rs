//! The chip's datapath as bit-exact software, operation by operation in pipeline order.
//! Every RTL block is checked against these functions.

pub mod doptrf;
pub mod tcheck;
