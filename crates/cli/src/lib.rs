//! The `flapwright` command line's own parts: the output folder, written beside its place
//! and moved there only on success ([`output`]). Everything that computes is the
//! `flapwright` library.

pub mod output;
