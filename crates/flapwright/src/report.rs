//! `report.json`: the stable, documented interface other tools read (schema in `docs/report.md`).
//!
//! Everything but [`Report::timings`] is a pure function of the scene, so the same scene
//! gives byte-identical reports apart from that one section.

use flapwright_mechanism::seam::BodyRole;
use flapwright_urdf::CutJoint;
use serde::Serialize;

/// Version of the report schema; bumped on any incompatible change.
pub const SCHEMA_VERSION: u32 = 2;

/// The whole report.
#[derive(Debug, Clone, Serialize)]
pub struct Report {
    /// Schema version ([`SCHEMA_VERSION`]).
    pub schema_version: u32,
    /// Flapwright version that wrote the report.
    pub flapwright_version: String,
    /// Which scene was designed.
    pub scene: SceneInfo,
    /// Names of the stages that ran, in order.
    pub stages: Vec<String>,
    /// Meshed parts (empty when no geometry stage ran).
    pub parts: Vec<PartReport>,
    /// Every solid of every station's mechanism (with STL or URDF output): the solids the
    /// interference check sweeps, stowed, their STL files and masses.
    pub mechanism_parts: Vec<MechanismPartReport>,
    /// Per support station.
    pub stations: Vec<StationReport>,
    /// Clearance of every moving/fixed part pair over the deployment (when checked).
    pub interference: Option<flapwright_interference::InterferenceReport>,
    /// Rods, screw jacks, torque tubes, drive and masses (when sizing ran).
    pub sizing: Option<flapwright_sizing::SizingReport>,
    /// The sizing loop: how many syntheses it took until no sized member of a synthesised
    /// kind exceeded its drawn solid (absent without a wing or a synthesised station).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sizing_loop: Option<crate::pipeline::sizing_loop::SizingLoopReport>,
    /// Files written besides the report and the STL files.
    pub files: Exports,
    /// Warnings (near-toggle, self-locking lost, ...), each naming where.
    pub warnings: Vec<String>,
    /// Wall time per stage, s. The only part of the report that changes between runs.
    pub timings: Vec<StageTiming>,
}

/// Scene identity.
#[derive(Debug, Clone, Serialize)]
pub struct SceneInfo {
    /// Scene name.
    pub name: String,
    /// Scene description.
    pub description: String,
    /// SHA-256 of the scene file's bytes, hex.
    pub sha256: String,
}

/// A meshed part and its mesh statistics.
#[derive(Debug, Clone, Serialize)]
pub struct PartReport {
    /// Part name (also the STL file stem).
    pub name: String,
    /// `wing-skin`, `flap`, `spar` or `torque-tube`.
    pub kind: String,
    /// Vertex count.
    pub vertices: usize,
    /// Triangle count.
    pub triangles: usize,
    /// Enclosed volume, m^3.
    pub volume_m3: f64,
    /// Axis-aligned bounds in the aircraft frame, m: `[min, max]`.
    pub bounds_m: [[f64; 3]; 2],
    /// Every edge shared by exactly two consistently oriented triangles.
    pub watertight: bool,
    /// STL file written, relative to the output folder.
    pub stl_file: Option<String>,
}

/// One support station: where it is and what its mechanism does.
#[derive(Debug, Clone, Serialize)]
pub struct StationReport {
    /// Station name.
    pub name: String,
    /// Flap it supports (absent in a 2D-only scene).
    pub flap: Option<String>,
    /// Plane, frame, skew, residuals and section cuts (absent without a wing).
    pub plane: Option<flapwright_planes::StationReport>,
    /// Gap and overlap behind the main wing at the flap settings (design only).
    pub flap_position: Option<crate::pipeline::record::FlapPositionReport>,
    /// How far this station moves its flap off the rigid motion fitted to all the flap's
    /// stations over the deployment (absent for a flap on one station).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub flap_motion_miss: Option<crate::pipeline::record::FlapMotionMiss>,
    /// Mechanism dimensions, synthesis and one sweep per load case.
    pub mechanism: Option<crate::pipeline::record::MechanismReport>,
    /// Fairing depth: how far the mechanism reaches below the lower wing/flap contour.
    pub fairing: Option<flapwright_interference::FairingDepth>,
    /// The deployment under the `[dynamics]` motor (absent without `[dynamics]`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dynamics: Option<crate::pipeline::dynamics::DynamicsReport>,
}

/// Export files, relative to the output folder.
#[derive(Debug, Clone, Default, Serialize)]
pub struct Exports {
    /// The URDF, its trajectory file and where loops were cut.
    pub urdf: Option<UrdfExport>,
    /// SVG drawings (`station-<name>.svg`) and plots (`plots-<name>.svg`).
    pub svg: Vec<String>,
    /// The animated glTF of the deployment.
    pub gltf: Option<GltfExport>,
    /// Where the STL files show the flaps and mechanisms (`stowed`, `takeoff`, `landing`;
    /// absent without STL files).
    pub stl_setting: Option<crate::scene::StlSetting>,
}

/// Wall time of one stage.
#[derive(Debug, Clone, Serialize)]
pub struct StageTiming {
    /// Stage name.
    pub stage: String,
    /// Wall time, s.
    pub wall_time_s: f64,
}

/// Where a solid's mass comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum MassBasis {
    /// The sizing stage's mass of the member (`sizing.rods`).
    Sized,
    /// The drawn envelope at the material's density: not sized.
    Drawn,
}

/// The report's record of one mechanism part file.
#[derive(Debug, Clone, Serialize)]
pub struct MechanismPartReport {
    /// `<station>.<solid>`.
    pub name: String,
    /// Station.
    pub station: String,
    /// The body it belongs to (its URDF link is `<station>_<body>`, its trajectory key
    /// points `<station>.<body>.<point>`).
    pub body: String,
    /// Its body's role (`flap`, `link`, `track`, `carriage`, `actuator`, `support`).
    pub role: BodyRole,
    /// Vertex count.
    pub vertices: usize,
    /// Triangle count.
    pub triangles: usize,
    /// Mass, kg: the sized member's, or the drawn envelope's ([`Self::mass_basis`]).
    pub mass_kg: f64,
    /// Where the mass comes from: `sized` or `drawn`.
    pub mass_basis: MassBasis,
    /// STL file, aircraft frame, stowed (relative to the output folder).
    pub stl_file: Option<String>,
}

/// What the URDF export wrote.
#[derive(Debug, Clone, Serialize)]
pub struct UrdfExport {
    /// The URDF file.
    pub file: String,
    /// Joint values and key points per deployment sample.
    pub trajectory_file: String,
    /// Where the closed loops were cut (URDF is a tree).
    pub cut_joints: Vec<CutJoint>,
}

/// What the glTF export wrote.
#[derive(Debug, Clone, Serialize)]
pub struct GltfExport {
    /// The file.
    pub file: String,
    /// Nodes (one per part and solid), named as the report's parts.
    pub nodes: usize,
    /// Keyframes per moving node: the report's deployment samples.
    pub samples: usize,
    /// Animation length (s).
    pub duration_s: f64,
    /// Largest distance between where a viewer's interpolation puts a vertex and where the
    /// motion puts it, at the middle of every step between samples (m).
    pub max_interpolation_error_m: f64,
    /// The part where that largest error occurs.
    pub max_interpolation_error_part: String,
}
