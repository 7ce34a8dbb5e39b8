//! Triangle meshes (placeholder: being written).
