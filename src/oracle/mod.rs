//! Exact oracle (placeholder: being written).
