//! The scene file: what the user writes (TOML), read with serde and validated before any
//! work starts.
//!
//! Every quantity carries its unit in its key (`chord_m`, `sweep_deg`). Unknown keys are
//! errors, so a typo cannot pass silently. [`Scene::from_toml`] parses and validates and
//! reports *all* problems at once, each with its path in the file
//! (`wing.sections[2].chord_m = -1: must be > 0`).

mod airfoil_ref;
mod validate;

pub use airfoil_ref::{AirfoilRef, AirfoilSource};
pub use validate::{Problem, SceneError};

use serde::Deserialize;

/// The embedded default scene: the small aircraft of the thesis (`000_...`, Chapter 5).
pub const DEFAULT_SCENE_TOML: &str = include_str!("../../../../data/scenes/small-aircraft.toml");

/// A whole scene as written in the TOML file.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Scene name, used in the report and in output file names.
    pub name: String,
    /// Free text shown in the report.
    #[serde(default)]
    pub description: String,
    /// The wing; absent for a single 2D station scene (the thesis spreadsheet case).
    pub wing: Option<WingScene>,
    /// Flaps of the wing.
    #[serde(default)]
    pub flap: Vec<FlapScene>,
    /// Spars and torque tube.
    #[serde(default)]
    pub structure: StructureScene,
    /// Mechanism support stations.
    #[serde(default)]
    pub station: Vec<StationScene>,
    /// Load cases.
    #[serde(default)]
    pub loads: LoadsScene,
    /// Which outputs the user wants; decides which stages run.
    #[serde(default)]
    pub outputs: OutputsScene,
    /// Mesh and sampling resolution.
    #[serde(default)]
    pub resolution: ResolutionScene,
    /// Sizing choices: materials, gearbox efficiency, tube wall.
    #[serde(default)]
    pub sizing: SizingScene,
    /// Interference check settings.
    #[serde(default)]
    pub interference: InterferenceScene,
    /// Custom materials, referred to by name from `[sizing]`.
    #[serde(default)]
    pub materials: Vec<MaterialScene>,
}

/// `[sizing]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SizingScene {
    /// Material of the screws (sized as rods for strength and buckling): a preset
    /// (`steel-4340`, `aluminium-7075-t6`, `titanium-ti-6al-4v`) or a `[[materials]]` name.
    #[serde(default = "default_screw_material")]
    pub screw_material: String,
    /// Material of the torque tubes.
    #[serde(default = "default_tube_material")]
    pub torque_tube_material: String,
    /// Efficiency of each station gearbox, (0, 1].
    #[serde(default = "default_gearbox_efficiency")]
    pub gearbox_efficiency: f64,
    /// Torque tube inner / outer radius, [0, 1) (0: solid).
    #[serde(default = "default_wall_ratio")]
    pub torque_tube_inner_to_outer_ratio: f64,
    /// Euler end-fixity factor K of the screws (1: pinned-pinned).
    #[serde(default = "default_end_fixity")]
    pub screw_end_fixity_factor: f64,
}

fn default_screw_material() -> String {
    "steel-4340".into()
}
fn default_tube_material() -> String {
    "aluminium-7075-t6".into()
}
fn default_gearbox_efficiency() -> f64 {
    0.9
}
fn default_wall_ratio() -> f64 {
    0.8
}
fn default_end_fixity() -> f64 {
    1.0
}

impl Default for SizingScene {
    fn default() -> Self {
        Self {
            screw_material: default_screw_material(),
            torque_tube_material: default_tube_material(),
            gearbox_efficiency: default_gearbox_efficiency(),
            torque_tube_inner_to_outer_ratio: default_wall_ratio(),
            screw_end_fixity_factor: default_end_fixity(),
        }
    }
}

/// `[interference]`: the clearance check (defaults chosen from the error-vs-time study in
/// the README).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InterferenceScene {
    /// Smallest acceptable clearance between parts, m.
    #[serde(default = "default_clearance")]
    pub required_clearance_m: f64,
    /// Evenly spaced deployment samples before refinement.
    #[serde(default = "default_initial_samples")]
    pub initial_samples: usize,
    /// Refine until the certified bound is within this of the sampled minimum, m.
    #[serde(default = "default_tolerance")]
    pub tolerance_m: f64,
    /// Relative refinement tolerance: a clearance is located to the larger of
    /// `tolerance_m` and this fraction of itself.
    #[serde(default = "default_relative_tolerance")]
    pub relative_tolerance: f64,
    /// Distance evaluations per part pair at most.
    #[serde(default = "default_max_evaluations")]
    pub max_evaluations: usize,
    /// Largest separation allowed between parts joined by design (the nut on its screw,
    /// the fitting at the nut pivot), m.
    #[serde(default = "default_joint_play")]
    pub joint_play_m: f64,
}

/// 0.5 mm: the radial play of a plain trunnion bearing of this size is tenths of a
/// millimetre; a nut that leaves its screw separates by far more.
fn default_joint_play() -> f64 {
    0.0005
}

fn default_clearance() -> f64 {
    0.003
}
fn default_initial_samples() -> usize {
    9
}
fn default_tolerance() -> f64 {
    0.001
}
fn default_relative_tolerance() -> f64 {
    0.01
}
fn default_max_evaluations() -> usize {
    400
}

impl Default for InterferenceScene {
    fn default() -> Self {
        Self {
            required_clearance_m: default_clearance(),
            initial_samples: default_initial_samples(),
            tolerance_m: default_tolerance(),
            relative_tolerance: default_relative_tolerance(),
            max_evaluations: default_max_evaluations(),
            joint_play_m: default_joint_play(),
        }
    }
}

/// `[[materials]]`: a custom material.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialScene {
    /// Name used in `[sizing]`.
    pub name: String,
    /// Density, kg/m^3.
    pub density_kg_m3: f64,
    /// Allowable tensile (and compressive) stress, Pa.
    pub allowable_tensile_pa: f64,
    /// Allowable shear stress, Pa.
    pub allowable_shear_pa: f64,
    /// Young's modulus, Pa.
    pub youngs_modulus_pa: f64,
}

/// Which reference line the panel sweep angles are measured on.
#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "kebab-case")]
pub enum SweepReferenceScene {
    /// Leading-edge sweep.
    #[default]
    LeadingEdge,
    /// Quarter-chord sweep.
    QuarterChord,
}

/// `[wing]`: sections root to tip and the panels between them.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WingScene {
    /// Leading edge of the root section, aircraft frame (x aft, y outboard, z up), m.
    #[serde(default)]
    pub root_leading_edge_m: [f64; 3],
    /// Line on which the panel sweep angles are measured.
    #[serde(default)]
    pub sweep_reference: SweepReferenceScene,
    /// Chord fraction about which sections are twisted (0 = leading edge).
    #[serde(default = "quarter")]
    pub twist_axis_chord_fraction: f64,
    /// Sections, root to tip (at least two).
    pub sections: Vec<WingSectionScene>,
    /// One panel between each pair of consecutive sections.
    pub panels: Vec<PanelScene>,
}

fn quarter() -> f64 {
    0.25
}

/// `[[wing.sections]]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WingSectionScene {
    /// Spanwise position (aircraft y), m.
    pub y_m: f64,
    /// Chord, m.
    pub chord_m: f64,
    /// Twist, positive nose up, deg.
    #[serde(default)]
    pub twist_deg: f64,
    /// `"NACA 2412"`, `"NACA 23012"` or a `.dat` file (Selig or Lednicer).
    pub airfoil: String,
}

/// `[[wing.panels]]`: the part of the wing between two consecutive sections.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PanelScene {
    /// Sweep angle on the wing's sweep reference line, deg.
    #[serde(default)]
    pub sweep_deg: f64,
    /// Dihedral angle, deg (negative: anhedral).
    #[serde(default)]
    pub dihedral_deg: f64,
}

/// `[[flap]]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FlapScene {
    /// Flap name; stations refer to it.
    pub name: String,
    /// Inboard end, aircraft y, m.
    pub y_inboard_m: f64,
    /// Outboard end, aircraft y, m.
    pub y_outboard_m: f64,
    /// Flap chord / local wing chord at the inboard end.
    pub chord_fraction_inboard: f64,
    /// Flap chord / local wing chord at the outboard end.
    pub chord_fraction_outboard: f64,
    /// Own flap section nested in the cove (`"n63212.dat"`); absent: the flap is cut out of
    /// the wing section.
    pub airfoil: Option<String>,
    /// Spanwise gap between each flap side and the wing, m (default: 0.5 % of the local
    /// chord). A hinge line that is not perpendicular to the streamwise flap sides moves
    /// the sides spanwise as the flap deploys.
    pub side_gap_m: Option<f64>,
    /// The flap rotation axis.
    pub hinge: HingeScene,
    /// Flap settings, deg of rotation about the hinge axis (trailing edge down positive).
    #[serde(default)]
    pub settings: SettingsScene,
}

/// `[flap.hinge]`: either two points or a chord fraction and depth.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HingeScene {
    /// Inboard axis point, aircraft frame, m.
    pub inboard_point_m: Option<[f64; 3]>,
    /// Outboard axis point, aircraft frame, m.
    pub outboard_point_m: Option<[f64; 3]>,
    /// Hinge at this fraction of the local wing chord ...
    pub chord_fraction: Option<f64>,
    /// ... and this far below the chord line, as a fraction of the local wing chord.
    pub depth_below_chord_fraction: Option<f64>,
}

/// `[flap.settings]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SettingsScene {
    /// Take-off deflection, deg.
    pub takeoff_deg: f64,
    /// Landing deflection (fully deployed), deg.
    pub landing_deg: f64,
}

impl Default for SettingsScene {
    fn default() -> Self {
        Self {
            takeoff_deg: 15.0,
            landing_deg: 35.0,
        }
    }
}

/// `[structure]`.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct StructureScene {
    /// Spars as plates at a chord fraction.
    #[serde(default)]
    pub spars: Vec<SparScene>,
    /// The flap drive torque tube.
    pub torque_tube: Option<TorqueTubeScene>,
}

/// `[[structure.spars]]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SparScene {
    /// Part name.
    pub name: String,
    /// Chord fraction of the spar's mid-plane.
    pub chord_fraction: f64,
    /// Web thickness, m.
    pub thickness_m: f64,
    /// Inboard end, aircraft y, m.
    pub y_start_m: f64,
    /// Outboard end, aircraft y, m.
    pub y_end_m: f64,
}

/// `[structure.torque_tube]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TorqueTubeScene {
    /// Polyline of the tube axis, aircraft frame, m.
    pub path_m: Vec<[f64; 3]>,
    /// Outer radius, m.
    pub radius_m: f64,
}

/// `[[station]]`: one support mechanism.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StationScene {
    /// Station name.
    pub name: String,
    /// Flap it supports (absent in a 2D-only scene).
    pub flap: Option<String>,
    /// Distance along the hinge axis from the flap's inboard side plane (thesis d1, or d1 + d2), m.
    pub axis_offset_m: Option<f64>,
    /// Mechanism kind and its dimensions.
    pub mechanism: MechanismScene,
}

/// `[station.mechanism]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, tag = "kind", rename_all = "kebab-case")]
pub enum MechanismScene {
    /// Circular-arc track with screw jack (thesis `000_...`, Chapters 3-5).
    CircularArcTrack(CircularArcTrackScene),
}

/// Dimensions of a circular-arc-track mechanism in the station frame (thesis Table 2 names
/// in the doc comments).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CircularArcTrackScene {
    /// a1 = |A0 B0|, m.
    pub base_distance_m: f64,
    /// α0, angle of A0B0 from the station x axis, deg.
    pub base_angle_deg: f64,
    /// a2 = |A0 A|, m.
    pub crank_length_m: f64,
    /// a3, screw length; absent: synthesised (step 9), m.
    pub screw_length_m: Option<f64>,
    /// b1, outer slot radius, m.
    pub outer_slot_radius_m: f64,
    /// c1, inner slot radius, m.
    pub inner_slot_radius_m: f64,
    /// β1, angle of the outer slot's stowed end, deg.
    pub slot_start_angle_deg: f64,
    /// β2, angle between the two slots' stowed ends, deg.
    pub slot_offset_angle_deg: f64,
    /// β3, flap rotation range, deg.
    pub rotation_range_deg: f64,
    /// Flap centre of mass D (stowed), station frame, m.
    pub flap_centre_of_mass_m: [f64; 2],
    /// Flap mass carried by this station, kg.
    pub flap_mass_kg: f64,
    /// Screw lead l, m.
    pub screw_lead_m: f64,
    /// Screw mean radius r, m.
    pub screw_mean_radius_m: f64,
    /// Thread friction coefficient f.
    pub screw_friction: f64,
    /// Nut speed along the screw, m/s.
    #[serde(default = "default_nut_speed")]
    pub nut_speed_mps: f64,
}

fn default_nut_speed() -> f64 {
    0.035
}

/// `[loads]`.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct LoadsScene {
    /// Safety factor on motor torque (CS-25: 1.5).
    pub safety_factor: Option<f64>,
    /// Named load cases.
    #[serde(default)]
    pub cases: Vec<LoadCaseScene>,
}

/// `[[loads.cases]]`: external (aerodynamic) moment about the hinge per station, closing
/// the flap; constant or linear from stowed to fully deployed.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoadCaseScene {
    /// Case name (`cruise`, `landing`).
    pub name: String,
    /// Constant moment per station, N m.
    pub moment_nm: Option<f64>,
    /// Moment at stowed, N m (with `moment_deployed_nm`: linear interpolation).
    pub moment_stowed_nm: Option<f64>,
    /// Moment at fully deployed, N m.
    pub moment_deployed_nm: Option<f64>,
}

/// `[outputs]`: which results to produce; a stage that no requested output needs is skipped.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputsScene {
    /// Binary STL of every part.
    #[serde(default = "yes")]
    pub stl: bool,
    /// Mechanism kinematics and forces.
    #[serde(default = "yes")]
    pub kinematics: bool,
    /// Rods, screw jacks, torque tubes, drive power, masses (needs kinematics).
    #[serde(default = "yes")]
    pub sizing: bool,
    /// Clearance check and fairing depth (needs a wing).
    #[serde(default = "yes")]
    pub interference: bool,
    /// URDF of the wing and its mechanisms, with a trajectory file (needs a wing; writes the
    /// STL files it refers to).
    #[serde(default = "yes")]
    pub urdf: bool,
    /// SVG drawing and plots per station.
    #[serde(default = "yes")]
    pub svg: bool,
}

fn yes() -> bool {
    true
}

impl Default for OutputsScene {
    fn default() -> Self {
        Self {
            stl: true,
            kinematics: true,
            sizing: true,
            interference: true,
            urdf: true,
            svg: true,
        }
    }
}

/// `[resolution]`: discretisation knobs (defaults chosen from the error-vs-time tables in
/// the README).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ResolutionScene {
    /// Airfoil points per side (upper/lower).
    #[serde(default = "default_points_per_side")]
    pub airfoil_points_per_side: usize,
    /// Deployment samples per station sweep.
    #[serde(default = "default_samples")]
    pub deployment_samples: usize,
    /// Flap rotations at which the fairing depth is measured.
    #[serde(default = "default_fairing_samples")]
    pub fairing_samples: usize,
    /// Points along each round solid (capsule axis) at which the fairing depth is measured.
    #[serde(default = "default_fairing_points_per_capsule")]
    pub fairing_points_per_capsule: usize,
}

fn default_points_per_side() -> usize {
    60
}
fn default_samples() -> usize {
    51
}
fn default_fairing_samples() -> usize {
    21
}
fn default_fairing_points_per_capsule() -> usize {
    8
}

impl Default for ResolutionScene {
    fn default() -> Self {
        Self {
            airfoil_points_per_side: default_points_per_side(),
            deployment_samples: default_samples(),
            fairing_samples: default_fairing_samples(),
            fairing_points_per_capsule: default_fairing_points_per_capsule(),
        }
    }
}
