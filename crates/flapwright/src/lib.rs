//! Flapwright, the library: designs the support and drive mechanisms of a wing's
//! trailing-edge flaps from a scene, in memory. The command line (`flapwright-cli`, binary
//! `flapwright`) reads files, writes output folders and decides exit codes; this crate
//! computes and renders bytes.
//!
//! # Overview
//! - [`scene`]: the TOML scene format, parsed with serde and validated with paths
//!   (`file:line:col` problems).
//! - [`kinds`]: each mechanism kind's scene table, its checks and its synthesis into the
//!   mechanism seam (`flapwright_mechanism::seam::FlapMechanism`).
//! - [`pipeline`]: runs the stages (geometry, planes, mechanisms, interference, sizing,
//!   ...) a scene's outputs need, times them, and hands the rendered files to a [`Sink`].
//! - [`sink`]: where files go ([`Sink`]; [`MemorySink`] keeps them in memory).
//! - [`report`]: the `report.json` schema (documented in `docs/report.md`).
//! - [`junit`]: JUnit XML of the interference check, for CI.
//! - [`study`]: the trade study of mechanism kinds at the scene's stations.
//! - [`sweep`]: many variants of a scene designed in parallel, one table out.
//! - [`error`]: the crate's one error type ([`Error`], [`Result`]): each variant names what
//!   failed and wraps the lower crate's error, so the command line prints the chain.
//!
//! Libraries below return typed errors; the command line alone decides wording and exit
//! codes.

pub mod error;
pub mod junit;
pub mod kinds;
pub mod pipeline;
pub mod report;
pub mod scene;
pub mod sink;
pub mod study;
pub mod sweep;

pub use error::{Error, Result};
pub use sink::{MemorySink, Sink};
