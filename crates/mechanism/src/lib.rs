//! Planar flap mechanisms behind one seam: the circular-arc track with screw jack of
//! Arslan (2022), its synthesis, kinematics, kinetostatics and deployment sweeps.
//!
//! # Overview
//!
//! - [`seam`]: [`FlapMechanism`], what every other Flapwright crate sees of a mechanism
//!   kind (input range, poses as body displacements, bodies with roles, solids and
//!   certified speed bounds, joints by name, kinetostatics, the actuator); a kind is a
//!   module implementing it. [`sweep_deployment`] samples any kind kind-neutrally.
//! - [`spanwise`]: where each solid lies along the station's z axis (a kind's own offsets,
//!   or a layout from the seam that puts solids crossing in the plane side by side).
//! - The circular-arc track implements the seam in `track_seam` (bodies: flap, screw,
//!   nut, two tracks; [`TrackHardware`] sizes their solids).
//! - [`CircularArcTrackSpec`] holds the designer's choices (thesis Table 2, yellow cells);
//!   [`CircularArcTrackSpec::thesis_case_study`] is the published case.
//! - [`CircularArcTrack::synthesise`] runs design steps 7-10 (collinearity rule giving
//!   s34,i and Δs; g2, p2, q2, σ, θG, θF) and turns the spreadsheet's red cells (section
//!   5.3) into typed [`Error`]s and [`SynthesisWarning`]s.
//! - [`CircularArcTrack::pose`] gives θ12, θ13, ω12, ω13, α12, α13 and points A, B, D, F,
//!   G with velocities and accelerations, plus [`PoseDiagnostics`].
//! - [`CircularArcTrack::forces`] gives F_input by equilibrium (eq. 3.4.16) and by virtual
//!   work (eq. 3.5.1), the slot reactions G12G, G12F and the screw torques T_R, T_L.
//! - [`CircularArcTrack::sweep`] samples the deployment under a [`LoadCase`].
//! - [`InvertedSliderCrank`] is the driving linkage on its own (toggle detection, condition
//!   number); [`landing_gear`] synthesises it by the landing-gear method of Yastrebov &
//!   Polyushkova (1982, doc 004).
//! - [`five_bar`]: the five-bar double-slotted flap of `001_...` in closed form (three RRR
//!   dyads), with every derivative to third order through [`jet`]; [`generalised`] turns a
//!   one-input mechanism's bodies with mass and its lifting surfaces into the equation of
//!   motion's generalised inertia and force (work-energy, `001_...` section 3.1).
//! - [`rigid_flap`]: the same for any kind from its poses and statics, its flap the one body
//!   with mass, driven through its actuator's shaft ([`RigidFlapDynamics`]).
//! - [`planar`] is a general one-input planar model (bodies; revolute, prismatic,
//!   pin-in-circular-slot and pin-in-straight-slot joints; a distance or angle driver)
//!   solved by Newton with the analytic Jacobian, velocities and accelerations from the
//!   differentiated constraints, the branch tracked from the stowed configuration
//!   ([`planar::PlanarModel::solve`], [`planar::PlanarModel::sweep`]). The thesis track
//!   rebuilt in it agrees with the closed form to 1e-9.
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
//! - The assembly branch is the thesis's (θ12 in [0, π], A counter-clockwise of B0).
//!
//! # Pitfalls
//!
//! - Thesis Table 3 landing "min/max" pairs are column-wise extremes, not one pose.
//! - G12G and G12F are signed radial reactions along θG, θF; negative values mean the
//!   reaction points towards the hinge.
//! - `sweep` never returns NaN: it stops at the first failing input and reports it in
//!   [`Sweep::stopped`].

mod angle;
mod deployment;
pub mod dropped_hinge;
mod error;
mod feasibility;
pub mod five_bar;
pub mod flap_load;
pub mod four_bar;
pub mod generalised;
pub mod hooked_track;
pub mod jet;
mod kinetostatics;
pub mod landing_gear;
pub mod link_track;
mod members;
pub mod outline;
pub mod placement;
pub mod planar;
mod planar_solve;
pub mod precision;
pub mod rigid_flap;
pub mod rocker_drive;
mod rotary_actuator;
mod screw_jack;
pub mod seam;
mod slider_crank;
pub mod spanwise;
mod sweep;
mod track_pose;
mod track_seam;
mod track_spec;
mod track_synthesis;
pub mod urdf;

pub use angle::{four_times_triangle_area, guarded_acos, ACOS_ROUNDING_TOLERANCE, DEFAULT_TOGGLE_TOLERANCE_RAD};
pub use deployment::{
    sweep_deployment, AftElementSample, Deployment, DeploymentSample, DeploymentStop, FlapGapOverlap,
};
pub use dropped_hinge::{DroppedHinge, DroppedHingeActuator, DroppedHingeSpec};
pub use error::{Error, Result, SynthesisDefect};
pub use five_bar::{DoubleFlapLoads, FiveBarDimensions, FiveBarDoubleFlap, FiveBarKind, FiveBarPose, LoadedFiveBar};
pub use flap_load::{FlapMass, LinkHardware};
pub use four_bar::{FourBar, FourBarSpec};
pub use generalised::{generalise, AeroSurface, Generalised, InertialBody, OneInputDynamics};
pub use hooked_track::{HookedTrack, HookedTrackSpec};
pub use kinetostatics::{ExternalMoment, FlapNormalForce, Forces, LoadCase};
pub use link_track::{LinkTrack, LinkTrackSpec};
pub use outline::StationOutline;
pub use planar_solve::PlanarSolution;
pub use precision::PrecisionPosition;
pub use rigid_flap::RigidFlapDynamics;
pub use rotary_actuator::RotaryDrive;
pub use screw_jack::{ScrewDrive, ScrewJack, ScrewTorques};
pub use seam::FlapMechanism;
pub use slider_crank::{InvertedSliderCrank, SliderCrankState};
pub use sweep::{JointReactions, Sweep, SweepSample, SweepStop};
pub use track_pose::{PointKinematics, Pose, PoseDiagnostics};
pub use track_seam::{screw_outer_radius_m, TrackHardware};
pub use track_spec::CircularArcTrackSpec;
pub use track_synthesis::{CircularArcTrack, SynthesisWarning, TrackSynthesis};
