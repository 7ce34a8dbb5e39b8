//! collision-chip: golden model, number formats and (later) RTL of the hierarchical
//! k-DOP collision-detection accelerator of Zachmann & Knittel (WSCG'03) and
//! Raabe, Bartyzel, Anlauf & Zachmann (DATE'05).
//!
//! Layout: `format` (chip number formats), `mesh` (loaders and procedural meshes),
//! `oracle` (exact triangle intersection), `dop` (k-DOP normals, trees, host setup),
//! `golden` (bit-exact datapath in pipeline order), `traversal` (recursive, list, D_CNTR),
//! `scene` (scene files), `report` (summaries).

pub mod format;
pub mod mesh;
pub mod oracle;
#[cfg(feature = "parry")]
pub mod peer;
pub mod pose;
pub mod chip;
pub mod cycle;
pub mod dop;
pub mod golden;
pub mod harness;
pub mod hard_cases;
pub mod measure;
pub mod query;
pub mod report;
pub mod rtl;
pub mod scene;
pub mod traversal;
