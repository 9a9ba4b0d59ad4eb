//! Integration tests of flapwright-drawing: one binary, one module per topic.

mod fixtures;
mod plots;
mod raster;
mod station;
mod ticks;
