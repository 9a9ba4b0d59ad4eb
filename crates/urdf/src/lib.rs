//! URDF model of a wing's posed flap mechanisms (urdf-rs), its trajectory file and a strict
//! check of the URDF rules. The workspace's only crate on urdf-rs: the mechanism crate keeps
//! the kinematic model ([`flapwright_mechanism::seam`]), this crate the file format.
//!
//! One robot per wing. The base link is the wing structure in the aircraft frame (its
//! meshes need no offset). Each [`StationMechanism3d`] adds its mechanism, through the
//! seam ([`flapwright_mechanism::seam::FlapMechanism`]), as a tree (`<s>` = station name):
//!
//! ```text
//! base ──fixed <s>_station_mount (aircraft_from_station)──> <s>_station   (ground, station frame)
//!   <s>_station ──fixed──> <s>_<fixed body>                                 (tracks, supports)
//!   <s>_station ──revolute/prismatic <s>_<joint>──> <s>_<body> ──...        (a spanning tree)
//!     <s>_<flap body> ──fixed <s>_flap_mount──> <flap>                       (owning station only)
//! ```
//!
//! The spanning tree starts at the ground and reaches each moving body by the first
//! revolute or prismatic seam joint (in the kind's order) to a body already placed; for
//! the circular-arc track: `<s>_B0` (screw about B0), `<s>_nut_slide` (nut along the
//! screw), `<s>_A` (flap about the nut pivot A). Joint values are each body's rotation
//! (rad) or slide (m) against its parent since stowed, so every link is stowed at zero.
//!
//! Closed loops are cut because URDF describes trees only ([`CutJoint`], listed in the
//! file's comment by [`to_xml`]): every seam joint outside the tree (the track's pins F
//! and G in their slots) and the rigid attachment of a non-owning station's flap body to
//! the flap. The tree alone poses every body exactly: a loop's other joints close by
//! construction, because the joint values come from the mechanism's own poses.
//!
//! Frames and units: metres and radians; the base link frame is the aircraft frame; each
//! station link frame is the station frame (origin A0, x to the nose, y up, z outboard),
//! placed by `aircraft_from_station`; a body's link frame is its parent joint's frame
//! where the body stands stowed. Revolute axes are the station z; prismatic axes the
//! slide's direction. Origins carry URDF fixed-axis rpy, R = Rz(yaw) Ry(pitch) Rx(roll)
//! ([`rpy_from_rotation`]).
//!
//! ```
//! use flapwright_kinds::{CircularArcTrack, CircularArcTrackSpec};
//! use flapwright_urdf::{self as urdf, BaseLink, StationMechanism3d};
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
//!     mechanism: &track,
//!     flap_name: "flap".into(),
//!     owns_flap: true,
//!     flap_mesh: Some("meshes/flap.stl".into()),
//!     aft_element: None,
//!     flap_inertia: None,
//!     bodies: vec![],
//!     actuator_peak_load: Some(6.2e3),
//! }];
//! let base = BaseLink { name: "wing".into(), meshes: vec![] };
//! let model = urdf::build_robot("right_wing", &base, &stations)?;
//! assert!(urdf::check_rules(&model.robot).is_empty());
//! // The screw's nut slides as the actuator drives it: its joint carries the peak load.
//! let nut = model.robot.joints.iter().find(|j| j.name == "inner_nut_slide").unwrap();
//! assert_eq!(nut.limit.effort, 6.2e3);
//! let xml = urdf::to_xml(&model)?;
//! assert!(xml.starts_with("<?xml"));
//! let trajectory = urdf::trajectory(&stations, 11)?;
//! assert_eq!(trajectory.joint_names, ["inner_B0", "inner_nut_slide", "inner_A"]);
//! let outboard = stations[0].aircraft_from_station * Vector3::z();
//! assert!((outboard - Vector3::y()).norm() < 1e-15);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Geometry and inertia: each body's link shows its solids ([`BodyGeometry`]: mesh files
//! in the aircraft frame, stowed) as visual and collision elements, and carries the body's
//! mass, centre of mass and inertia ([`RigidInertia`], aircraft frame, turned into the
//! link frame here); the flap link its mesh and [`StationMechanism3d::flap_inertia`]; a
//! two-element flap's aft element a link of its own, fixed to the link of the body that
//! moves it ([`StationMechanism3d::aft_element`]). A body without geometry gets an empty
//! link (mass 0).
//!
//! Limits: joint and velocity limits are the extremes of 129 samples of the deployment
//! (widened by half the largest step) at the actuator's nominal speed; the joint the
//! actuator drives has the actuator's peak load as its effort
//! ([`StationMechanism3d::actuator_peak_load`]), the passive joints 0.

mod build;
mod error;
mod layout;
mod rpy;
mod rules;
mod trajectory;

use nalgebra::{Isometry3, Matrix3, Point3};
use serde::Serialize;

use flapwright_mechanism::seam::FlapMechanism;

pub use build::{build_robot, to_xml};
pub use error::{Error, Result};
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
    /// The synthesised mechanism, through the seam.
    pub mechanism: &'a dyn FlapMechanism,
    /// Name of the flap this station drives (the flap link's name).
    pub flap_name: String,
    /// Whether the flap link hangs off this station; exactly one station per flap.
    pub owns_flap: bool,
    /// Flap mesh filename (relative to the URDF), vertices in the aircraft frame with the
    /// flap stowed; only on the owning station.
    pub flap_mesh: Option<String>,
    /// A two-element flap's aft element: its link's mesh and mass properties; only on the
    /// owning station. Its link hangs fixed off the link of the body that moves it
    /// (`seam::aft_flap_body`), or off the flap's where the kind has none.
    pub aft_element: Option<AftElementLink>,
    /// The flap's mass properties (owning station only; stowed, aircraft frame).
    pub flap_inertia: Option<RigidInertia>,
    /// What each body's link shows and weighs; bodies not listed get empty links.
    pub bodies: Vec<BodyGeometry>,
    /// The actuator's peak load over the load cases (N for a screw's stroke, N m for a
    /// rotary input): the `effort` of the joint the actuator drives (the one whose value
    /// moves one for one with the actuator's input); the other joints are passive, effort
    /// 0. None (no load cases, or an export without them): 0 everywhere.
    pub actuator_peak_load: Option<f64>,
}

/// A two-element flap's aft element in the URDF: a link of its own.
#[derive(Debug, Clone, PartialEq)]
pub struct AftElementLink {
    /// The link's name and mesh (vertices in the aircraft frame, stowed).
    pub mesh: MeshRef,
    /// Its mass properties (stowed, aircraft frame).
    pub inertia: Option<RigidInertia>,
}

/// One body's solids and mass properties, for its URDF link.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyGeometry {
    /// Index of the body in the mechanism's bodies.
    pub body: usize,
    /// Its solids' mesh files, vertices in the aircraft frame with the body stowed.
    pub meshes: Vec<MeshRef>,
    /// Its mass properties, stowed, aircraft frame.
    pub inertia: Option<RigidInertia>,
}

/// Mass, centre of mass and inertia of a rigid body (stowed, aircraft frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidInertia {
    /// Mass, kg.
    pub mass_kg: f64,
    /// Centre of mass (m).
    pub centre_of_mass_ac_m: Point3<f64>,
    /// Inertia tensor about the centre of mass, aircraft axes (kg m^2).
    pub inertia_ac_kg_m2: Matrix3<f64>,
}

impl RigidInertia {
    /// The body made of `parts`: masses add, the centre of mass is their weighted mean and
    /// each inertia moves to it by the parallel-axis theorem,
    /// I = sum(I_i + m_i (|d_i|^2 E - d_i d_i^T)) with d_i from the common centre. `None` for
    /// no parts or no mass.
    pub fn combined(parts: &[RigidInertia]) -> Option<RigidInertia> {
        let mass_kg: f64 = parts.iter().map(|p| p.mass_kg).sum();
        if parts.is_empty() || mass_kg <= 0.0 {
            return None;
        }
        let centre = parts
            .iter()
            .map(|p| p.centre_of_mass_ac_m.coords * p.mass_kg)
            .sum::<nalgebra::Vector3<f64>>()
            / mass_kg;
        let inertia = parts
            .iter()
            .map(|p| {
                let d = p.centre_of_mass_ac_m.coords - centre;
                p.inertia_ac_kg_m2 + (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * p.mass_kg
            })
            .sum();
        Some(RigidInertia {
            mass_kg,
            centre_of_mass_ac_m: Point3::from(centre),
            inertia_ac_kg_m2: inertia,
        })
    }
}

/// A joint of the real mechanism left out of the URDF tree to break a closed loop.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CutJoint {
    /// Station name.
    pub station: String,
    /// The seam joint's name (the track's `F`, `G`), or `"flap_attachment"` (a non-owning
    /// station's flap body on the flap).
    pub joint: String,
    /// `"revolute"`, `"prismatic"`, `"pin-in-circular-slot"`, `"pin-in-straight-slot"` or
    /// `"fixed"`.
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
