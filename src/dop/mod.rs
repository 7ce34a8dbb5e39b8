//! k-DOPs: the fixed normal sets, the DOP trees the host builds per object, and the
//! per-pose host setup (correspondence j, C, c) of DATE'05 Eq. 6 / WSCG'03 Eq. 3.

pub mod host;
pub mod normals;
pub mod tree;

pub use host::{HostSetup, TriSide};
pub use normals::{DopNormals, SUPPORTED_K};
pub use tree::{DopTree, Node};
