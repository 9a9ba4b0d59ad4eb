//! Airfoils, wing lofting, part meshes, STL writing and the parry3d collision adapter.
//!
//! # Overview
//!
//! [`Airfoil`] sections (analytic [`Naca`] 4/5-digit, or Selig/Lednicer `.dat` files) are
//! placed along the span by a [`WingSpec`] (sections, panels with sweep and dihedral,
//! twist) into a [`Wing`]. A [`WingModel`] adds [`FlapSpec`]s (cut-out or own section,
//! hinge axis, and for a two-element flap an [`AftElementSpec`] nested under the main
//! element's trailing edge), [`SparSpec`]s and a [`TorqueTubeSpec`], and
//! [`WingModel::compute_parts`] meshes every [`Part`] as a closed, outward-oriented
//! [`TriMesh`]; [`WingModel::compute_section_outlines`] gives the same polygons cut at any
//! spanwise station. Meshes are written with [`io::stl::write_binary`] and turned into
//! [`CollisionShape`]s for clearance queries ([`compute_distance`], [`compute_intersects`]).
//! [`reference`](mod@reference) gives exact point, segment and triangle distances by brute force, without
//! parry: the yardstick the adapter and the interference check are tested against.
//!
//! # Units and frames
//!
//! SI throughout (m, rad; `_deg` fields in degrees). Airfoils use unit-chord section
//! coordinates (x aft from the leading edge, y up). 3D points are in the aircraft frame
//! (`_ac`): x aft, y starboard (outboard on the modelled right wing), z up. Sections are
//! streamwise (planes y = const); see [`wing`] for sweep, dihedral and twist rules.
//!
//! # Design notes
//!
//! - Every loft joins rings with equal point counts (airfoils are resampled with cosine
//!   spacing in arc length, see [`Airfoil::resampled`]); caps are ear-clipped (a vertex within
//!   a hair of an ear blocks it, so the collinear runs of finely resampled coarse `.dat`
//!   data are fanned, not left as zero-area remainders); the result is
//!   oriented by its signed volume and checked watertight before it is returned.
//! - A wing with flaps is several closed shells in one mesh (plain spans and flap spans
//!   with a straight cove wall), touching along planes y = const: robust and exact.
//! - parry3d-f64 (glam-based) lives only in [`collision`]; conversions go through glamx.
//!
//! # Limitations
//!
//! - The cove is a straight wall at the flap's foremost point less
//!   [`flap::COVE_GAP_CHORD_FRACTION`], with a shroud over the flap's nose where
//!   [`FlapSpec::shroud_chord_fraction`] asks for one; a two-element flap's main element is
//!   cut for its aft element the same way (so the aft element needs the flap's own section).
//!   The flap is narrower than its cut-out at each side by [`FlapSpec::side_gap_m`], by
//!   default [`flap::SIDE_GAP_CHORD_FRACTION`] of the chord; both elements span the same.
//! - Spars are plates normal to the chord line; the torque tube has mitred joints.
//! - Between stations, surfaces are ruled (straight lines between corresponding points).
//!
//! # Pitfalls
//!
//! - NACA `thickness(x)` is the half-thickness y_t, applied normal to the mean line.
//! - Database airfoils are normalised differently from the analytic NACA definition (see
//!   `data/airfoils/README.md`): never use one as the exact reference for the other.
//! - parry's mesh queries see surfaces only: a part inside a mesh is not "intersecting".
//! - STL is f32 and unitless: these files are in metres.

pub mod airfoil;
pub mod collision;
pub mod error;
pub mod flap;
pub mod io;
mod loft;
pub mod mesh;
mod mesher;
pub mod parts;
pub mod reference;
pub mod rigid_fit;
pub mod structure;
pub mod wing;

pub use airfoil::{Airfoil, Naca, NacaCamber, Surface, TrailingEdge};
pub use collision::{
    compute_box_separation, compute_clearance, compute_clearance_near, compute_distance, compute_distance_near,
    compute_holds, compute_intersects, compute_signed_distance, Clearance, CollisionShape, MassProperties, NearHint,
    OrientedBox, Proximity, Slab, SLAB_COUNT,
};
pub use error::{Error, Result};
pub use flap::{AftElementSpec, Flap, FlapElementOutlines, FlapSectionSpec, FlapSpec, HingeSpec};
pub use mesh::{Aabb, MeshCheck, TriMesh};
pub use parts::{MeshResolution, Part, PartKind, SectionOutline, WingModel};
pub use rigid_fit::{fit_rigid_motion, FitSpeedGain, RigidFit};
pub use structure::{tube_mesh, SparSpec, TorqueTubeSpec};
pub use wing::{PanelSpec, SectionAt, SweepReference, Wing, WingSectionSpec, WingSpec};
