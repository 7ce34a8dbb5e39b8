//! Chip number formats (placeholder: being written).
