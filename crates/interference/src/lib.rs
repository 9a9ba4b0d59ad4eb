//! Certified clearance sweeps of moving flap-mechanism parts against the wing structure.
//!
//! # Overview
//! - [`Part`]: a collision shape (from `flapwright_geom::collision`) and its [`Motion`]
//!   over the deployment parameter `t` (pose and a certified speed bound).
//! - [`sweep_pair`] → [`PairClearance`]: smallest clearance of a pair over the deployment,
//!   where it occurs, the closest points, and a residual bound.
//! - [`station_parts`]: a station's mechanism as parts, from the mechanism seam alone
//!   (`flapwright_mechanism::seam::FlapMechanism`): every solid of every body, moving with
//!   its body's pose under the body's certified speed bound, with its role; the joints'
//!   touching solids as [`DeclaredContact`]s. No mechanism kind is named here.
//! - [`sweep_contact`] → [`JointSeparation`]: largest separation of parts joined by design.
//! - [`check_assembly`] → [`InterferenceReport`]: every station part against the fixed
//!   structure, parts not on or pinned to the flap against the flap, the flap against the
//!   structure, a two-element flap's aft element ([`FlapElement::Aft`]) against the
//!   structure, its main element and the station parts likewise, and the parts of
//!   different stations against each other (the policy is
//!   written in roles and joints); joints must stay within the joint's play
//!   ([`Requirements`]); pairs left out are listed with the reason.
//! - [`fairing_depth`]: how far the mechanism reaches below the lower wing/flap contour;
//!   [`planar_parts`] gives a station's solids in its plane for it.
//!
//! # Units and frames
//! Metres, aircraft frame (x aft, y outboard, z up). `t` is whatever the caller's motions
//! take; Flapwright's mechanism parts and flaps take the drive fraction τ in [0, 1]
//! (`station_parts`, `flap_part`), and speed bounds are in m per unit `t`.
//!
//! # Design notes
//! Sampling alone can miss a thin part passing between two samples. Distances between
//! rigid parts are Lipschitz in `t` with constant L = sum of the parts' speed bounds (or
//! the speed of one in the other's frame, `relative_speed`), which gives a lower bound of
//! the distance on every interval between samples; the sweep refines where that bound
//! could undercut the smallest sample. A flap against a fixed part may be swept slab by
//! slab, each slab's distance with its own constant (`slabbed`, `refine`). No time-of-impact
//! query is needed, and the guarantee holds for any motion whose speed bound is honest.
//!
//! # Limitations
//! Parts are solids through `flapwright_geom::collision::compute_clearance`: closed meshes
//! must be outward oriented for a part wholly inside one to count as overlapping. The
//! penetration depth is the deepest of the sampled poses, not refined between samples.
//! Parts of one station are checked against each other in the spanwise layers of
//! `flapwright_mechanism::spanwise` (a layout drawn from the seam unless the kind gives
//! one); joints are checked in the station plane.
//!
//! # Pitfalls
//! A speed bound that is too small voids the guarantee silently; derive it from the
//! mechanism's geometry (largest radius times largest angular rate), never from samples.

mod broad;
mod check;
mod error;
mod fairing;
mod flap_motion;
mod opening;
mod part;
mod refine;
mod relative_speed;
mod slabbed;
mod station;
mod sweep;

pub use broad::{ApartPair, SWEPT_BOX_INTERVALS};
pub use check::{check_assembly, Assembly, ContactResult, InterferenceReport, PairResult, Requirements, UncheckedPair};
pub use error::{Error, Result};
pub use fairing::{fairing_depth, FairingDepth, PlanarCapsule};
pub use flap_motion::{fit_points, FittedFlapMotion, FlapCarrier, FIT_POINTS_PER_CARRIER, FIT_SPEED_MARGIN};
pub use opening::{cut_opening, station_opening, OpenedSurface, Opening, OPENING_SAMPLES, UPWARD_FACE_COS};
pub use part::{Fixed, Motion, Part};
pub use slabbed::SLABS_WORTH_IT;
pub use station::{
    flap_part, joined_solids, planar_parts, station_parts, DeclaredContact, FlapElement, StationPart, StationParts,
};
pub use sweep::{
    sweep_contact, sweep_pair, sweep_pair_for_verdict, JointSeparation, PairClearance, SweepSettings,
    JOINT_PENETRATION_GRID_M,
};
