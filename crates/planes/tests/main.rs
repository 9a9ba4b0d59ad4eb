//! Integration tests of flapwright-planes (one binary, one module per topic).

mod boundaries;
mod frames;
mod gap_overlap;
mod meshes;
mod report;
mod sections;
mod stations;
mod wing_cut;
