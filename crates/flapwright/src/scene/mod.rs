//! The scene file: what the user writes (TOML), read with serde and validated before any
//! work starts.
//!
//! Every quantity carries its unit in its key (`chord_m`, `sweep_deg`). Unknown keys are
//! errors, so a typo cannot pass silently. [`Scene::from_toml`] parses and validates and
//! reports *all* problems at once, each with its path in the file
//! (`wing.sections[2].chord_m = -1: must be > 0`).

mod airfoil_ref;
mod dynamics;
mod files;
mod key_path;
pub(crate) mod nested_error;
pub(crate) mod parse;
mod problem;
mod schema;
mod settings;
mod station;
mod validate;
mod wing;

pub use airfoil_ref::{load_airfoil, AirfoilRef, AirfoilSource, AIRFOIL_COORDINATE_MARGIN};
pub use dynamics::DynamicsScene;
pub use files::{FileSource, Folder, MemoryFiles, NoFiles};
pub use key_path::Location;
pub use schema::{scene_schema, template, template_kinds, SCHEMA_FILE_NAME, SCHEMA_ID};
pub use settings::{
    DesignScene, InterferenceScene, MaterialScene, OutputsScene, ResolutionScene, SizingScene, StlSetting,
};
pub use station::{LoadCaseScene, LoadsScene, StationScene};
pub(crate) use validate::default_tube_end;
pub use validate::{
    limits, number, KeyChecker, LocatedProblem, Problem, SceneError, FRACTION_LIKE_PERCENT, MAX_SCENE_BYTES,
};
pub use wing::{
    FlapScene, HingeScene, PanelScene, SettingsScene, SparScene, StructureScene, SweepReferenceScene, TorqueTubeScene,
    WingScene, WingSectionScene,
};

use serde::Deserialize;

/// The embedded default scene: the small aircraft of the thesis (`000_...`, Chapter 5).
pub const DEFAULT_SCENE_TOML: &str = include_str!("../../../../data/scenes/small-aircraft.toml");

/// A whole scene as written in the TOML file.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
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
    /// What the mechanism searches weigh besides the fairing's depth.
    #[serde(default)]
    pub design: DesignScene,
    /// Custom materials, referred to by name from `[sizing]`.
    #[serde(default)]
    pub materials: Vec<MaterialScene>,
    /// Drive dynamics: a DC motor deploying each station whose kind models its masses.
    pub dynamics: Option<DynamicsScene>,
    /// Values that pass validation but look like slips (a percentage written as a
    /// fraction), each located when the file was read (`file:line:col: key = value: why`):
    /// every run reports them first among its warnings. Not a key of the file.
    #[serde(skip)]
    pub warnings: Vec<String>,
}
