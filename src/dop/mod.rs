//! k-DOPs: the fixed normal sets and the DOP trees the host builds per object (the
//! per-pose setup is [`golden::host`](crate::golden::host)).

pub mod normals;
pub mod tree;
pub mod values;

pub use normals::DopNormals;
pub use tree::{Dop, DopTree, Node};
pub use values::Values;
