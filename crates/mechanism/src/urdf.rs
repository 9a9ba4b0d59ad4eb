//! URDF model of a wing's posed flap mechanisms (urdf-rs), its trajectory file and a strict
//! check of the URDF rules.
//!
//! One robot per wing. The base link is the wing structure in the aircraft frame (its
//! meshes need no offset). Each [`StationMechanism3d`] adds the circular-arc track of
//! thesis Chapter 3 as a tree (`<s>` = station name):
//!
//! ```text
//! base ──fixed <s>_station_mount (aircraft_from_station)──> <s>_station        (ground, station frame)
//!   <s>_station ──revolute <s>_flap_hinge (about z at A0)──> <s>_flap_fitting  (flap side: A, D, F, G)
//!     <s>_flap_fitting ──fixed <s>_flap_mount──> <flap>                         (owning station only)
//!   <s>_station ──revolute <s>_screw_pivot (about z at B0)──> <s>_screw        (B0, B)
//!     <s>_screw ──prismatic <s>_nut_slide (along the screw)──> <s>_nut         (A)
//! ```
//!
//! Joint values: `<s>_flap_hinge` = deflection θ12 - θ12,i in [0, β3] (rad);
//! `<s>_screw_pivot` = θ13 - θ13,i (rad), limits the extremes over the stroke;
//! `<s>_nut_slide` = s34 in [s34,i, s34,f] (m), the nut's distance from B0. At zero hinge
//! and screw values every link is stowed; the nut sits at B0 until its joint reads s34.
//!
//! Closed loops are cut because URDF describes trees only ([`CutJoint`], listed in the
//! file's comment by [`to_xml`]): the nut-on-flap revolute A at every station, and the
//! rigid attachment of a non-owning station's flap fitting to the flap. The two
//! pin-in-slot joints F and G are not cut but represented exactly by the hinge revolute
//! at A0, since both slots are circular arcs centred at A0 (thesis Fig. 12).
//!
//! Frames and units: metres and radians; the base link frame is the aircraft frame; each
//! station link frame is the thesis station frame (origin A0, x to the nose, y up, z
//! outboard along the hinge axis), placed by `aircraft_from_station`. Every joint axis is
//! the station z (or, for the nut, the screw direction) mapped into the aircraft frame
//! by the joint origins; origins carry URDF fixed-axis rpy, R = Rz(yaw) Ry(pitch) Rx(roll)
//! ([`rpy_from_rotation`]).
//!
//! ```
//! use flapwright_mechanism::urdf::{self, BaseLink, StationMechanism3d};
//! use flapwright_mechanism::{CircularArcTrack, CircularArcTrackSpec};
//! use nalgebra::{Isometry3, Vector3};
//!
//! let track = CircularArcTrack::synthesise(CircularArcTrackSpec::thesis_case_study())?;
//! let stations = [StationMechanism3d {
//!     name: "inner".into(),
//!     // Station x to the nose (-x_ac), y up (z_ac), z outboard (y_ac): a half turn
//!     // about (0, 1, 1)/√2.
//!     aircraft_from_station: Isometry3::new(
//!         Vector3::new(3.2, 1.5, 0.4),
//!         Vector3::new(0.0, 1.0, 1.0).normalize() * std::f64::consts::PI,
//!     ),
//!     track: &track,
//!     flap_name: "flap".into(),
//!     owns_flap: true,
//!     flap_mesh: Some("meshes/flap.stl".into()),
//! }];
//! let base = BaseLink { name: "wing".into(), meshes: vec![] };
//! let model = urdf::build_robot("right_wing", &base, &stations)?;
//! assert!(urdf::check_rules(&model.robot).is_empty());
//! let xml = urdf::to_xml(&model)?;
//! assert!(xml.starts_with("<?xml"));
//! let trajectory = urdf::trajectory(&stations, 11)?;
//! assert_eq!(trajectory.joint_names[0], "inner_flap_hinge");
//! let outboard = stations[0].aircraft_from_station * Vector3::z();
//! assert!((outboard - Vector3::y()).norm() < 1e-15);
//! # Ok::<(), flapwright_mechanism::Error>(())
//! ```
//!
//! Limitations: links carry no inertia (mass 0: the file is for viewers and checks, not
//! for dynamics); joint efforts are 0 (unknown here); velocity limits are the largest
//! rates sampled at the spec's nominal nut speed.

mod build;
mod layout;
mod rpy;
mod rules;
mod trajectory;

use nalgebra::Isometry3;
use serde::Serialize;

use crate::track_synthesis::CircularArcTrack;

pub use build::{build_robot, to_xml};
pub use rpy::{isometry_from_origin, origin_from_isometry, rotation_from_rpy, rpy_from_rotation};
pub use rules::{check_rules, AXIS_UNIT_TOLERANCE};
pub use trajectory::{trajectory, KeyPoint, Trajectory, TrajectorySample};

/// A mesh file shown on a link.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeshRef {
    /// Visual element name (ASCII letters, digits, `_`, `-`).
    pub name: String,
    /// Path of the mesh file relative to the URDF file (e.g. `meshes/skin.stl`), metres.
    pub filename: String,
}

/// The wing structure: the robot's root link, in the aircraft frame.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BaseLink {
    /// Link name (ASCII letters, digits, `_`, `-`).
    pub name: String,
    /// Meshes in aircraft-frame coordinates (skin, spars, torque tube).
    pub meshes: Vec<MeshRef>,
}

/// One station's mechanism placed in 3D.
#[derive(Debug, Clone)]
pub struct StationMechanism3d<'a> {
    /// Station name, prefix of its links, joints and key points.
    pub name: String,
    /// Rigid placement of the station frame (origin A0, x to the nose, y up, z outboard)
    /// in the aircraft frame (x aft, y starboard, z up): p_ac = aircraft_from_station p_st.
    pub aircraft_from_station: Isometry3<f64>,
    /// The synthesised mechanism.
    pub track: &'a CircularArcTrack,
    /// Name of the flap this station drives (the flap link's name).
    pub flap_name: String,
    /// Whether the flap link hangs off this station; exactly one station per flap.
    pub owns_flap: bool,
    /// Flap mesh filename (relative to the URDF), vertices in the aircraft frame with the
    /// flap stowed; only on the owning station.
    pub flap_mesh: Option<String>,
}

/// A joint of the real mechanism left out of the URDF tree to break a closed loop.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CutJoint {
    /// Station name.
    pub station: String,
    /// Joint name: `"A"` (nut on flap) or `"flap_attachment"` (fitting on flap).
    pub joint: String,
    /// `"revolute"` (A, about `axis_ac`) or `"fixed"` (rigid attachment).
    pub kind: &'static str,
    /// The two URDF links the cut joint would connect.
    pub between: (String, String),
    /// Joint position with the flap stowed, aircraft frame (m).
    pub location_stowed_ac_m: [f64; 3],
    /// Joint axis (unit), aircraft frame: the station z axis.
    pub axis_ac: [f64; 3],
}

/// The URDF robot and the loop cuts it needed.
#[derive(Debug, Clone)]
pub struct UrdfModel {
    /// The robot as urdf-rs writes it.
    pub robot: urdf_rs::Robot,
    /// Joints cut to make the mechanism a tree (also in [`to_xml`]'s comment).
    pub cut_joints: Vec<CutJoint>,
}
