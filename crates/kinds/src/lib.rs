//! Flapwright's six planar flap mechanism kinds, one module each: every kind implements
//! the seam of `flapwright-mechanism` ([`FlapMechanism`](flapwright_mechanism::seam::FlapMechanism))
//! and names no other kind. The other stages (interference, sizing, dynamics, URDF, glTF,
//! drawings) depend on the seam only, so a change inside a kind rebuilds this crate and
//! the library that holds the kind registry, nothing else.
//!
//! | kind (scene name) | module | source | actuator |
//! |---|---|---|---|
//! | `circular-arc-track` | [`circular_arc_track`] | thesis `000_...` (Arslan 2022) | screw jack |
//! | `dropped-hinge` | [`dropped_hinge`] | `003_...` Figs. 6-7 | screw jack or rotary |
//! | `four-bar` | [`four_bar`] | `003_...` Figs. 6, 8 | screw jack |
//! | `link-track` | [`link_track`] | `003_...` Figs. 6, 9 | rotary |
//! | `hooked-track` | [`hooked_track`] | `003_...` Figs. 6, 10 | screw jack |
//! | `five-bar-double-flap` | [`five_bar`] | `001_...` section 2 | rotary (motor crank) |
//!
//! A kind's folder holds what only that kind uses (its spec, synthesis, loop, bodies,
//! members, search); what two or more kinds use lives in [`flapwright_mechanism::shared`],
//! and what the other stages see of a kind in [`flapwright_mechanism::seam`]. Adding a
//! kind: a folder here, a line below, its re-exports below, and its row in the scene's
//! kind table (`flapwright::kinds`); `docs/architecture.md`'s recipe says each step.
//!
//! Units and frames are the seam's: SI, the station frame (origin A0 = flap hinge, x to
//! the nose, y up, angles counter-clockwise positive).

pub mod circular_arc_track;
pub mod dropped_hinge;
pub mod five_bar;
pub mod four_bar;
pub mod hooked_track;
pub mod link_track;

pub use circular_arc_track::{
    screw_outer_radius_m, thesis_lean_sweep_into, CircularArcTrack, CircularArcTrackSpec, Forces, JointReactions,
    LeanColumn, LeanSweep, PointKinematics, Pose, PoseDiagnostics, Sweep, SweepSample, SweepStop, SynthesisWarning,
    TrackHardware, TrackSynthesis,
};
pub use dropped_hinge::{DroppedHinge, DroppedHingeActuator, DroppedHingeSpec};
pub use five_bar::{DoubleFlapLoads, FiveBarDimensions, FiveBarDoubleFlap, FiveBarKind, FiveBarPose, LoadedFiveBar};
pub use four_bar::{FourBar, FourBarSpec};
pub use hooked_track::{HookedTrack, HookedTrackSpec};
pub use link_track::{LinkTrack, LinkTrackSpec, PivotPlace};
