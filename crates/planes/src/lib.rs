//! Support stations, mechanism planes with skew correction, station frames and section cuts.
//!
//! # Overview
//!
//! Each flap support mechanism is planar; this crate finds its plane and everything it may
//! touch in that plane.
//!
//! - [`HingeAxis`], [`Plane`]: the flap rotation axis and flap side planes (aircraft frame).
//! - [`thesis_stations`]: planes perpendicular to the axis (thesis `000`, Ch. 4 steps 1-3).
//! - [`FlapDeployment`], [`FlapSetting`]: flap poses from deflection, conical rotations and
//!   gap/overlap translation (Zaccai et al. `003`, section 2, Figs. 2-3, 5);
//!   [`setting_from_section_shifts`] derives θ_o, θ_g from the shifts of two sections.
//! - [`skewed_plane_normal_ac`]: plane normal = skew direction x dihedral vector (`003` Fig. 4).
//! - [`compute_station`] → [`Station`]: frame, skew angle and the out-of-plane residual
//!   of each attachment point over the deployment ([`out_of_plane_residual_m`]).
//! - [`StationFrame`]: the rigid transform between aircraft and station frames.
//! - [`cut_mesh`] → [`Section`]: a part mesh cut by a station plane as closed 2D polygons.
//! - [`FlapBehindWing`] → [`GapOverlap`]: gap and overlap of the flap behind the main
//!   wing's trailing edge at any flap rotation (`003` section 2.1).
//! - [`parse_boundary_csv`], [`boundary_deviation`]: the thesis Fig. 45 boundaries and the
//!   distance of section polygons from them.
//! - [`StationReport`]: the serializable per-station record of report.json.
//!
//! # Units and frames
//!
//! SI (m, rad) everywhere; the Fig. 45 table is in mm as printed ([`BoundaryPoint`]).
//! Aircraft frame: x aft, y outboard (right wing), z up. Station frame: origin A0 on the
//! hinge axis, z along the plane normal (outboard), x in the plane perpendicular to gravity
//! towards the nose, y completing a right-handed frame (up). In-plane coordinates are
//! `Point2` and only come out of a [`StationFrame`] method; 3D station coordinates are a
//! [`StationPoint`], never a `Point3`. Transforms are named after the frames they relate
//! (`aircraft_from_station`, `station_from_aircraft`). Positive angles about station z are
//! counter-clockwise, so trailing-edge-down deflection is positive.
//!
//! # Design notes
//!
//! The core takes only `flapwright_geom::TriMesh` and nalgebra types, so it does not depend
//! on how geom builds the wing. Plane construction is a per-station choice
//! ([`PlaneConstruction`]); the default follows from the flap motion: a pure rotation about
//! a fixed hinge line keeps every flap point in a plane perpendicular to the line (zero
//! residual), anything else gets the skew-corrected plane of `003`. Section cuts classify
//! vertices on the plane as "above" (symbolic perturbation), which makes every crossing
//! unambiguous; crossing points are computed once per mesh edge so loops close exactly.
//!
//! # Limitations
//!
//! In [`FlapDeployment`], gap and overlap enter as a translation of the base point and the
//! conical rotations θ_o, θ_g as given angles; [`FlapBehindWing`] measures the gap and
//! overlap a rotation gives in one plane, but nothing solves for the translation that
//! meets target values (`003` Fig. 3 step 4). The
//! deployment between settings is a linear interpolation of the setting parameters, a
//! stand-in for the synthesised mechanism's path. Only the right wing is modelled.
//!
//! # Pitfalls
//!
//! - `003`'s "dihedral vector" is read as the wing's up vector tilted by the dihedral
//!   ([`dihedral_up_vector_ac`]); crossing with the spanwise dihedral line would give a
//!   plane parallel to the wing.
//! - The skew angle is measured in planform about the vertical ([`skew_angle_rad`]); the
//!   full angle between planes also contains the dihedral tilt
//!   ([`angle_to_streamwise_plane_rad`]).
//! - A station plane whose normal is vertical has no horizontal x axis: error, not NaN.
//! - [`cut_mesh`] needs closed, consistently wound meshes; open meshes give
//!   [`Error::OpenSection`].

pub mod boundary;
pub mod conical;
pub mod error;
pub mod frame;
pub mod gap_overlap;
pub mod motion;
pub mod plane;
pub mod report;
pub mod section;
pub mod skew;
pub mod station;
pub mod thesis;

pub use boundary::{boundary_deviation, distance_to_segment_m, parse_boundary_csv, BoundaryPoint, Deviation};
pub use conical::{setting_from_section_shifts, SectionShift};
pub use error::{Error, Result};
pub use frame::{StationFrame, StationPoint, DIRECTION_TOL, VERTICAL_SINE_TOL};
pub use gap_overlap::{FlapBehindWing, GapOverlap, UPPER_SKIN_MAX_NORMAL_TILT_DEG};
pub use motion::{FlapDeployment, FlapSetting};
pub use plane::{unit_direction, HingeAxis, Plane, AXIS_PLANE_COSINE_TOL};
pub use report::{FrameReport, SectionReport, StationReport};
pub use section::{cut_mesh, polygons_contain, signed_area_m2, Section, SECTION_MERGE_TOL_M};
pub use skew::{
    angle_to_streamwise_plane_rad, dihedral_up_vector_ac, skew_angle_rad, skew_direction_ac, skewed_plane_normal_ac,
};
pub use station::{
    compute_station, out_of_plane_residual_m, PlaneConstruction, Station, PURE_ROTATION_ANGLE_TOL_RAD,
    PURE_ROTATION_LENGTH_TOL_M,
};
pub use thesis::{thesis_stations, ThesisStations};
