//! Drive dynamics of a flap mechanism: a DC motor with an R-L armature, through a gearbox,
//! deploying a one-input mechanism under its aerodynamic loads and weights (`001_...`
//! sections 3.1-3.2), integrated by a stiff error-controlled method.
//!
//! # Overview
//!
//! - [`drive`]: [`DcMotor`], [`Gearbox`], [`Drive`], the [`SupplyVoltage`] with a smooth
//!   start, and the crank law [`SmoothStart`] of `001_...` eq. (1).
//! - [`required`]: the motor torque, current and voltage that hold a prescribed input
//!   motion (constant rate after a smooth start), from the work-energy equation.
//! - [`ode`]: the deployment as an initial-value problem (input, rate, current, and the
//!   energy balance's quadratures), with end stops as events, integrated by diffsol's BDF
//!   (default), ESDIRK34, or the explicit Tsit45 for comparison; [`DynamicsRun`] holds the
//!   time history, the solver's counts and the energy balance.
//!
//! The mechanism enters only through
//! [`OneInputDynamics`](flapwright_mechanism::OneInputDynamics) (its generalised inertia
//! and force with their slopes), so any one-input kind can be driven.

pub mod drive;
mod error;
pub mod ode;
pub mod required;

pub use drive::{DcMotor, Drive, Gearbox, SmoothStart, SupplyVoltage};
pub use error::{Error, Result};
pub use ode::{
    integrate, DynamicsRun, DynamicsSample, EnergyBalance, Integration, Method, SolverCounts, MAX_TIME_HISTORY_SAMPLES,
};
pub use required::{required_drive, RequiredSample};
