//! The seam of Flapwright's planar flap mechanisms and the toolbox its kinds share: what
//! every stage sees of a mechanism, whatever its kind. The six kinds themselves live in
//! `flapwright-kinds`, one module each; interference, sizing, dynamics, URDF, glTF and
//! drawings depend on this crate alone, so a change inside a kind does not rebuild them.
//!
//! # Overview
//!
//! - [`seam`]: [`FlapMechanism`], what every other Flapwright crate sees of a mechanism
//!   kind (input range, poses as body displacements, bodies with roles, solids and
//!   certified speed bounds, joints by name, kinetostatics, the actuator, members); the
//!   plain data it returns ([`seam::Body`], [`seam::MechanismPose`], [`seam::Kinetostatics`],
//!   [`seam::Actuator`]) is written in roles and actuator types, never in kinds.
//! - [`shared`]: the toolbox the kinds share (its module table says why each sits there):
//!   the load case ([`LoadCase`]) and the flap's wrench ([`shared::flap_load`]), planar
//!   geometry helpers, the inverted slider-crank ([`InvertedSliderCrank`]) and the rocker
//!   drive ([`shared::rocker_drive`]), the actuators ([`ScrewJack`], [`ScrewDrive`],
//!   [`RotaryDrive`]), placement of jacks and struts ([`shared::placement`]), precision
//!   positions ([`PrecisionPosition`]), the station outlines ([`StationOutline`]), the
//!   synthesis searches' loop checks and the members to size.
//! - Kind-neutral consumers of the seam: [`sweep_deployment`] samples any kind's
//!   kinetostatics into a [`Deployment`]; [`spanwise`] lays a station's solids side by side
//!   along its z axis.
//! - Dynamics helpers: [`jet`] (points and angles with three derivatives),
//!   [`generalised`] (a one-input mechanism's bodies with mass and lifting surfaces to the
//!   equation of motion's generalised inertia and force, work-energy, `001_...` section
//!   3.1), [`rigid_flap`] (the same for any kind from its poses and statics, its flap the
//!   one body with mass: [`RigidFlapDynamics`]).
//! - [`planar`]: a general one-input planar model (bodies; revolute, prismatic,
//!   pin-in-circular-slot and pin-in-straight-slot joints; a distance or angle driver)
//!   solved by Newton with the analytic Jacobian, the branch tracked from the stowed
//!   configuration ([`planar::PlanarModel::solve`], [`planar::PlanarModel::sweep`]). No kind
//!   uses it; the thesis track rebuilt in it agrees with the closed form to 1e-9.
//! - [`landing_gear`]: the inverted slider-crank synthesised by the landing-gear method of
//!   Yastrebov & Polyushkova (1982, doc `004_...`), kept for the next design issue.
//! - [`Error`]: the crate's one error type; synthesis defects name the condition
//!   ([`SynthesisDefect`]).
//!
//! # Units and frames
//!
//! SI throughout (m, rad, s, N, N m, kg); the thesis works in mm and N mm, so its
//! tables are converted at the test edge only. Frame: the station frame of the thesis,
//! origin A0 = flap hinge, x towards the nose, y up, angles counter-clockwise positive.
//! Flap deflection θ12 - θ12,i is trailing-edge-down positive (the flap lies aft, x < 0).
//! M12 is positive when it tends to close the flap.
//!
//! # Design notes
//!
//! - A kind's kinematics exist once, in its folder; interference, URDF, glTF, drawings,
//!   sizing and the report consume its poses and solids through the seam. What two kinds
//!   share goes to [`shared`], never into one kind's folder.
//! - Readings that reproduce the thesis numbers (Table 3 within 0.5 %, Appendix C rows):
//!   mm-based tables converted to SI; the aerodynamic moment is halved because two screw
//!   jacks share the flap, but the full flap weight (12 kg) acts on each mechanism;
//!   the landing moment is interpolated linearly over the nut stroke (s34 - s34,i)/Δs,
//!   not over the deflection; Table 3's cruise column is the flap-closed sample.
//! - Slider-crank angles come from `atan2` of Kahan's triangle area (no `acos` near the
//!   toggles); every remaining `acos` goes through [`guarded_acos`], which clamps only
//!   rounding ([`ACOS_ROUNDING_TOLERANCE`]).
//! - Source defects found while checking (also in `data/validation/thesis-defects.md`):
//!   eq. 3.3.3 has the sign of its ṡ term reversed ((ω12 - ω13) must be (ω13 - ω12)),
//!   and the spreadsheet's α12 column (and the a_A, a_D columns built on it) follows the
//!   misprint; eq. 3.3.2's last form writes tan where cot is meant; "tanλ = 1/2πr" is
//!   l/(2πr); θD = atan2(x_D; y_D) uses Excel's argument order.
//!
//! # Limitations
//!
//! - The general [`planar`] model has no closed-form Assur-group (RRR/RRP/RPR dyad)
//!   decomposition yet: it always uses Newton; it has no kinetostatics yet.
//! - Forces are quasi-static by default, as in the thesis (accelerations < 0.1 % g,
//!   Fig. 31); [`LoadCase::include_inertia`] adds m a_D and I_D α12.
//! - Joint friction is neglected except in the screw thread.
//! - The track's assembly branch is the thesis's (θ12 in [0, π], A counter-clockwise of B0).
//!
//! # Pitfalls
//!
//! - Thesis Table 3 landing "min/max" pairs are column-wise extremes, not one pose.
//! - G12G and G12F are signed radial reactions along θG, θF; negative values mean the
//!   reaction points towards the hinge.
//! - Sweeps never return NaN: they stop at the first failing input and report it
//!   (the track's `Sweep::stopped` in `flapwright-kinds`, [`Deployment::stopped`]).

mod deployment;
mod error;
pub mod generalised;
pub mod jet;
pub mod landing_gear;
pub mod planar;
mod planar_solve;
pub mod rigid_flap;
pub mod seam;
pub mod shared;
pub mod spanwise;

pub use deployment::{
    sweep_deployment, AftElementSample, Deployment, DeploymentSample, DeploymentStop, FlapGapOverlap,
};
pub use error::{Error, Result, SynthesisDefect};
pub use generalised::{generalise, AeroSurface, Generalised, InertialBody, OneInputDynamics};
pub use planar_solve::PlanarSolution;
pub use rigid_flap::RigidFlapDynamics;
pub use seam::FlapMechanism;
pub use shared::angle::{
    four_times_triangle_area, guarded_acos, ACOS_ROUNDING_TOLERANCE, DEFAULT_TOGGLE_TOLERANCE_RAD,
};
pub use shared::flap_load::{FlapMass, LinkHardware};
pub use shared::load_case::{ExternalMoment, FlapNormalForce, LoadCase};
pub use shared::outline::StationOutline;
pub use shared::precision::PrecisionPosition;
pub use shared::rotary_actuator::RotaryDrive;
pub use shared::screw_jack::{ScrewDrive, ScrewJack, ScrewTorques};
pub use shared::slider_crank::{InvertedSliderCrank, SliderCrankState};
