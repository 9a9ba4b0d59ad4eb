//! Integration tests of flapwright-sizing, one module per topic.

mod data;
mod distribution;
mod errors;
mod report;
mod rod;
mod scaling;
mod screw_jack;
mod torque_tube;
