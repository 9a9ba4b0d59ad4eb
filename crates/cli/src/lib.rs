//! The `flapwright` command line: reads a scene, runs the stages its outputs need, writes
//! the report and files.
//!
//! # Overview
//! - [`scene`]: the TOML scene format, parsed with serde and validated with paths.
//! - [`kinds`]: each mechanism kind's scene table, its checks and its synthesis into the
//!   mechanism seam (`flapwright_mechanism::seam::FlapMechanism`).
//! - [`pipeline`]: runs the stages (geometry, planes, mechanisms) and times them.
//! - [`report`]: the `report.json` schema (documented in the README).
//! - [`junit`]: JUnit XML of the interference check, for CI.
//! - [`output`]: writes into a temporary folder and moves it into place only on success.
//! - [`study`]: the trade study of mechanism kinds at the scene's stations.
//!
//! Libraries below return typed errors; this crate alone decides wording and exit codes.

pub mod junit;
pub mod kinds;
pub mod output;
pub mod pipeline;
pub mod report;
pub mod scene;
pub mod study;
