//! File formats written by the geometry crate.

pub mod stl;
