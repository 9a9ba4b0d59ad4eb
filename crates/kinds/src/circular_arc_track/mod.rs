//! The circular-arc track with screw jack of Arslan (2022, thesis `000_...`): the flap
//! hangs on two pins running in circular slots about the hinge A0 and is pushed round by a
//! screw jack pivoting at B0, the inverted slider-crank A0-B0-A of thesis Fig. 10.
//!
//! - [`CircularArcTrackSpec`] (`spec`) holds the designer's choices (thesis Table 2,
//!   yellow cells); [`CircularArcTrackSpec::thesis_case_study`] is the published case.
//! - [`CircularArcTrack::synthesise`] (`synthesis`) runs design steps 7-10 (collinearity
//!   rule giving s34,i and Δs; g2, p2, q2, σ, θG, θF) and turns the spreadsheet's red cells
//!   (section 5.3) into typed [`Error`](flapwright_mechanism::Error)s and [`SynthesisWarning`]s.
//! - [`CircularArcTrack::pose`] (`pose`) gives θ12, θ13, ω12, ω13, α12, α13 and points A,
//!   B, D, F, G with velocities and accelerations, plus [`PoseDiagnostics`].
//! - [`CircularArcTrack::forces`] (`kinetostatics`) gives F_input by equilibrium (eq.
//!   3.4.16) and by virtual work (eq. 3.5.1), the slot reactions G12G, G12F and the screw
//!   torques T_R, T_L.
//! - [`CircularArcTrack::sweep`] (`sweep`) samples the deployment under a
//!   [`LoadCase`](flapwright_mechanism::LoadCase), in the thesis's own columns ([`SweepSample`]).
//! - [`CircularArcTrack::lean_sweep`] (`lean`) samples the same deployment for a trade study:
//!   positions, rates and the actuator's load only, a column per quantity ([`LeanSweep`]).
//! - `seam` presents all of it behind [`FlapMechanism`](flapwright_mechanism::FlapMechanism): bodies
//!   flap, screw, nut and two tracks ([`TrackHardware`] sizes their solids), joints, poses
//!   and loads keyed by joint name.
//!
//! What the track shares with other kinds is not here: the inverted slider-crank
//! ([`InvertedSliderCrank`](flapwright_mechanism::InvertedSliderCrank), also the rocker drive's and the
//! landing gear's), the screw thread ([`ScrewJack`](flapwright_mechanism::ScrewJack)), the guarded angle
//! functions and the load case live in [`flapwright_mechanism::shared`].

mod kinetostatics;
mod lean;
mod pose;
mod seam;
mod spec;
mod sweep;
mod synthesis;

pub use kinetostatics::Forces;
pub use lean::{thesis_lean_sweep_into, LeanColumn, LeanSweep};
pub use pose::{PointKinematics, Pose, PoseDiagnostics};
pub use seam::{screw_outer_radius_m, TrackHardware};
pub use spec::CircularArcTrackSpec;
pub use sweep::{JointReactions, Sweep, SweepSample, SweepStop};
pub use synthesis::{CircularArcTrack, SynthesisWarning, TrackSynthesis};
