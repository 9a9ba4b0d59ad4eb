//! Mechanism kinds as the scene file gives them: `[station.mechanism]` picks a kind by its
//! `kind` key, and each kind's module holds its table, the checks of its keys and its
//! synthesis into a [`FlapMechanism`] (the seam every other stage uses). Adding a kind adds
//! a module here, a variant, a `KINDS` name (and a `SYNTHESISED_KINDS` one if it is
//! synthesised from the settings) and three match arms in this file (`kind`,
//! `is_synthesised`, the `Deserialize` impl), and its mechanism module in `flapwright-kinds`:
//! nothing that names another kind (`docs/architecture.md`, "Adding a kind";
//! `tests/kinds_named_once.rs` checks it).

mod circular_arc_track;
mod dropped_hinge;
mod five_bar;
mod four_bar;
mod hooked_track;
mod link_track;

use std::sync::Arc;

use flapwright_mechanism::{FlapMechanism, PrecisionPosition, ScrewDrive, StationOutline};
use serde::Deserialize;

pub use circular_arc_track::CircularArcTrackScene;
pub use dropped_hinge::DroppedHingeScene;
pub use five_bar::FiveBarScene;
pub use four_bar::FourBarScene;
pub use hooked_track::HookedTrackScene;
pub use link_track::LinkTrackScene;

use crate::scene::limits::{FLAP_MASS_KG, SCREW_FRICTION, SCREW_MEAN_RADIUS_M};
use crate::scene::KeyChecker;

/// What a kind may synthesise from besides its own table: the station's sections and the
/// flap settings' precision positions in its plane (absent in a scene without a wing).
#[derive(Debug, Clone, Default)]
pub struct SynthesisContext {
    /// The main wing and the stowed flap cut by the station plane.
    pub outline: Option<StationOutline>,
    /// Take-off and landing as displacements of the flap in the station plane (from the
    /// flap's `[flap.settings]` deflection, gap and overlap); None where the settings give
    /// no gap and overlap.
    pub settings: Option<(PrecisionPosition, PrecisionPosition)>,
    /// The downward unit vector of the aircraft frame in the station plane (station frame):
    /// (0, -1) for an upright plane; None without a wing.
    pub down_st: Option<nalgebra::Vector2<f64>>,
    /// The flap attachments of the station synthesised first on the same flap, in the
    /// terms of its section: a kind whose free choices are its flap attachments starts
    /// from them, so that the stations of one rigid flap move it alike (two four-bars
    /// searched apart move it on paths centimetres apart between the settings).
    pub companion: Option<Companion>,
    /// The rigid motion the flap's first synthesised station gives it, as this station's
    /// plane sees it (`pipeline::flap_motion::followed_motion`): a kind whose free choices
    /// shape the flap's path between the settings searches for the mechanism nearest it.
    pub followed: Option<flapwright_mechanism::shared::follow::FollowedMotion>,
    /// The scene's load cases at this station (its share of its flap's flight load; the
    /// flap's weight alone when the scene gives none): the searches weigh the actuator's
    /// load under them.
    pub design_loads: Vec<flapwright_mechanism::LoadCase>,
    /// `[design] actuator_load_weight`: the weight of the actuator's load against the
    /// fairing's depth in the searches.
    pub actuator_load_weight: f64,
    /// `[design] rotary_actuator_load_weight`: the weight of a rotary actuator's torque
    /// against the fairing's depth in the searches.
    pub rotary_actuator_load_weight: f64,
    /// `[design] four_bar_actuator_load_cap`: the four-bar's screw load, in reference
    /// loads, above which its placement trades steeply.
    pub four_bar_actuator_load_cap: f64,
    /// `[design] mechanism_mass_weight` with the scene's materials and safety factor: how
    /// the screw jacks' placements weigh the mass they add; `None` where the weight is 0.
    pub mass_weighing: Option<flapwright_mechanism::shared::objective::MassWeighing>,
    /// The radii the sizing loop found the drawn solids must reach at this station
    /// (`pipeline::sizing_loop`); none on the first synthesis.
    pub sized: SizedHardware,
}

/// Radii the sizing stage asked of a station's drawn solids (m): a synthesised kind draws
/// its links, arms, struts and screw at least this thick, so that no sized member exceeds
/// its drawn solid and the check sees what will be built.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct SizedHardware {
    /// The links' and arms' radius (and the struts' of every kind but the four-bar).
    pub link_radius_m: Option<f64>,
    /// The four-bar's struts' radius.
    pub strut_radius_m: Option<f64>,
    /// The screw's mean radius.
    pub screw_mean_radius_m: Option<f64>,
}

/// The nut and the jack body are drawn at least this many times the screw's mean radius
/// (the thread's depth, 1.25 r, and a wall round it): by default they are 3-6 times a 12 mm
/// screw on a transport flap and need not grow with it.
pub const NUT_TO_SCREW_RADIUS: f64 = 1.5;

/// See [`SynthesisContext::companion`].
#[derive(Debug, Clone)]
pub struct Companion {
    /// The station it comes from.
    pub station: String,
    /// Its moving flap attachments, in its flap section's terms.
    pub attachments: Vec<flapwright_mechanism::shared::outline::FlapPoint>,
    /// Its flap deflection at [`COMPANION_SAMPLES`] + 1 evenly spaced drive fractions (rad).
    pub deflections_rad: Vec<f64>,
}

/// Intervals of the drive fraction a companion's deflection schedule is sampled at.
pub const COMPANION_SAMPLES: usize = 20;

/// Standard gravity (m/s²).
pub const GRAVITY_MPS2: f64 = 9.81;

/// What every kind synthesised from the settings takes from its station: the sections and
/// settings, the flap chord, the flap share's mass properties (centre of mass by default the
/// section's centroid, gravity in the plane) and hardware sized to the flap chord.
pub(crate) struct StationFlap<'a> {
    /// The sections.
    pub outline: &'a StationOutline,
    /// Take-off and landing.
    pub takeoff: PrecisionPosition,
    /// The last precision position.
    pub landing: PrecisionPosition,
    /// The flap chord in the plane (m).
    pub flap_chord_m: f64,
    /// The flap share.
    pub mass: flapwright_mechanism::FlapMass,
    /// Solid sizes.
    pub hardware: flapwright_mechanism::LinkHardware,
}

impl SynthesisContext {
    /// The station's flap for a kind with `mass_kg` and an optional `centre` (station frame).
    pub(crate) fn station_flap(&self, mass_kg: f64, centre: Option<[f64; 2]>) -> Result<StationFlap<'_>, String> {
        let (outline, takeoff, landing) = self.require()?;
        let (_, _, flap_chord_m) = outline.flap_chord().ok_or("the station plane misses the flap")?;
        let centre = match centre {
            Some([x, y]) => nalgebra::Point2::new(x, y),
            None => outline.flap_centroid().ok_or("the flap section has no area")?,
        };
        Ok(StationFlap {
            outline,
            takeoff,
            landing,
            flap_chord_m,
            mass: flapwright_mechanism::FlapMass {
                mass_kg,
                centre_of_mass_stowed_m: centre,
                gravity_mps2: self.gravity_mps2(),
            },
            hardware: self.hardware_for(flap_chord_m),
        })
    }

    /// The drawn solids' sizes for a flap of chord `flap_chord_m`: scaled to the chord
    /// ([`flapwright_mechanism::LinkHardware::for_flap_chord`]), the links as thick as the
    /// sizing loop asked, and the nut and the jack body round a screw it thickened at least
    /// [`NUT_TO_SCREW_RADIUS`] times its mean radius.
    fn hardware_for(&self, flap_chord_m: f64) -> flapwright_mechanism::LinkHardware {
        let mut hardware = flapwright_mechanism::LinkHardware::for_flap_chord(flap_chord_m);
        if let Some(radius) = self.sized.link_radius_m {
            hardware.link_radius_m = hardware.link_radius_m.max(radius);
        }
        if let Some(radius) = self.sized.strut_radius_m {
            hardware.strut_radius_m = hardware.strut_radius_m.max(radius);
        }
        if let Some(radius) = self.sized.screw_mean_radius_m {
            hardware.nut_radius_m = hardware.nut_radius_m.max(NUT_TO_SCREW_RADIUS * radius);
            hardware.jack_body_radius_m = hardware.jack_body_radius_m.max(NUT_TO_SCREW_RADIUS * radius);
        }
        hardware
    }

    /// `drive` with its screw as thick as the sizing loop asked.
    pub(crate) fn screw_drive(&self, drive: ScrewDrive) -> ScrewDrive {
        match self.sized.screw_mean_radius_m {
            Some(radius) if radius > drive.mean_radius_m => ScrewDrive {
                mean_radius_m: radius,
                ..drive
            },
            _ => drive,
        }
    }

    /// Gravity's acceleration in the station plane (m/s²): g along the aircraft's down
    /// direction projected on the plane, or along the station's -y without a wing.
    pub fn gravity_mps2(&self) -> nalgebra::Vector2<f64> {
        self.down_st.unwrap_or(nalgebra::Vector2::new(0.0, -1.0)) * GRAVITY_MPS2
    }

    /// The outline and the settings, or the message a kind that needs them gives.
    pub fn require(&self) -> Result<(&StationOutline, PrecisionPosition, PrecisionPosition), String> {
        let outline = self
            .outline
            .as_ref()
            .ok_or("is synthesised from the flap settings in the station plane, and that plane cuts no flap section (or the scene has no [wing]): place the station on its flap with axis_offset_m")?;
        let (takeoff, landing) = self.settings.ok_or(
            "is synthesised from the flap settings: give takeoff_gap_percent, takeoff_overlap_percent, landing_gap_percent and landing_overlap_percent in the flap's [flap.settings]",
        )?;
        Ok((outline, takeoff, landing))
    }
}

/// `screw = { ... }` of a synthesised kind: the screw jack's thread and the drive shared by
/// every station on one torque tube (each station's lead is its stroke over `turns`).
#[derive(Debug, Clone, Copy, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields, default)]
pub struct ScrewDriveScene {
    /// Mean thread radius, m.
    pub mean_radius_m: f64,
    /// Thread friction coefficient.
    pub friction: f64,
    /// Screw turns over the deployment: the same at every station of one drive.
    pub turns: f64,
    /// Deployment time at the nominal drive speed, s.
    pub deployment_time_s: f64,
}

impl Default for ScrewDriveScene {
    /// A 12 mm mean-radius thread (transport ball-screw actuators are 20-40 mm in
    /// diameter), friction 0.1 as the thesis, 40 turns in 20 s (transport flaps deploy in
    /// 15-30 s).
    fn default() -> Self {
        Self {
            mean_radius_m: 0.012,
            friction: 0.1,
            turns: 40.0,
            deployment_time_s: 20.0,
        }
    }
}

/// Screw turns over a deployment: a few to a thousand.
const SCREW_TURNS: (f64, f64) = (1.0, 1000.0);
/// Deployment time, s.
const DEPLOYMENT_TIME_S: (f64, f64) = (0.1, 600.0);
/// Minimum transmission angle a synthesised kind may be asked for, deg.
const MIN_TRANSMISSION_ANGLE_DEG: (f64, f64) = (5.0, 80.0);

impl ScrewDriveScene {
    fn check(&self, checker: &mut dyn KeyChecker, path: &str) {
        for (key, value, (min, max)) in [
            ("mean_radius_m", self.mean_radius_m, SCREW_MEAN_RADIUS_M),
            ("friction", self.friction, SCREW_FRICTION),
            ("turns", self.turns, SCREW_TURNS),
            ("deployment_time_s", self.deployment_time_s, DEPLOYMENT_TIME_S),
        ] {
            checker.in_range(&format!("{path}.screw.{key}"), value, min, max, false);
        }
    }

    fn drive(&self) -> ScrewDrive {
        ScrewDrive {
            mean_radius_m: self.mean_radius_m,
            friction_coefficient: self.friction,
            turns: self.turns,
            deployment_time_s: self.deployment_time_s,
        }
    }
}

/// `actuator = "..."` of a kind that may take either (`003_...` Fig. 6).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum ActuatorChoice {
    /// A screw jack (linear actuator): `screw = { ... }`.
    #[default]
    ScrewJack,
    /// A geared rotary actuator: `rotary = { ... }`.
    Rotary,
}

/// `rotary = { ... }`: a geared rotary actuator's gearing and the drive it shares with
/// every station on one torque tube (its gear ratio is the shaft's turns over its output's
/// travel, as a screw's lead is its stroke over the turns).
#[derive(Debug, Clone, Copy, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields, default)]
pub struct RotaryDriveScene {
    /// Drive-shaft turns over the deployment: the same at every station of one drive.
    pub turns: f64,
    /// Deployment time at the nominal drive speed, s.
    pub deployment_time_s: f64,
    /// The gearing's mechanical efficiency.
    pub efficiency: f64,
}

impl Default for RotaryDriveScene {
    /// The screw drive's 40 turns in 20 s, so that screw jacks and rotary actuators share
    /// a torque tube by default; 0.9 for a compound planetary gearbox (ASSUMPTION: 003
    /// gives no value; such gearboxes are quoted at 0.85-0.95).
    fn default() -> Self {
        Self {
            turns: 40.0,
            deployment_time_s: 20.0,
            efficiency: 0.9,
        }
    }
}

/// A gearbox's efficiency.
const GEAR_EFFICIENCY: (f64, f64) = (0.1, 1.0);
/// Drive-shaft turns of a rotary actuator over a deployment: from a direct drive (the
/// shaft turns with its output, a fraction of a turn: 0.125 for a crank turned 45 deg) to
/// a thousand.
const ROTARY_TURNS: (f64, f64) = (0.01, 1000.0);

impl RotaryDriveScene {
    /// Checks the keys under `{path}.rotary`.
    pub fn check(&self, checker: &mut dyn KeyChecker, path: &str) {
        for (key, value, (min, max)) in [
            ("turns", self.turns, ROTARY_TURNS),
            ("deployment_time_s", self.deployment_time_s, DEPLOYMENT_TIME_S),
            ("efficiency", self.efficiency, GEAR_EFFICIENCY),
        ] {
            checker.in_range(&format!("{path}.rotary.{key}"), value, min, max, false);
        }
    }

    /// The drive as the mechanism crate takes it.
    pub fn drive(&self) -> flapwright_mechanism::RotaryDrive {
        flapwright_mechanism::RotaryDrive {
            turns: self.turns,
            deployment_time_s: self.deployment_time_s,
            efficiency: self.efficiency,
        }
    }
}

/// `trade_index`, where given, names one of a trade of at most `candidates` (from 0).
fn check_trade_index(checker: &mut dyn KeyChecker, path: &str, index: Option<usize>, candidates: usize) {
    if let Some(index) = index {
        let most = candidates.saturating_sub(1);
        checker.in_range(&format!("{path}.trade_index"), index as f64, 0.0, most as f64, false);
    }
}

/// The keys every kind synthesised from the settings has: flap mass and centre of mass,
/// minimum transmission angle, and the screw drive of a kind that has one.
fn check_synthesised(
    checker: &mut dyn KeyChecker,
    path: &str,
    mass_kg: f64,
    centre: Option<&[f64; 2]>,
    min_transmission_angle_deg: f64,
    screw: Option<&ScrewDriveScene>,
) {
    let (mass_lo, mass_hi) = FLAP_MASS_KG;
    checker.in_range(&format!("{path}.flap_mass_kg"), mass_kg, mass_lo, mass_hi, false);
    if let Some(centre) = centre {
        checker.point_within(&format!("{path}.flap_centre_of_mass_m"), centre);
    }
    let (lo, hi) = MIN_TRANSMISSION_ANGLE_DEG;
    checker.in_range(
        &format!("{path}.min_transmission_angle_deg"),
        min_transmission_angle_deg,
        lo,
        hi,
        false,
    );
    if let Some(screw) = screw {
        screw.check(checker, path);
    }
}

/// What the rest of Flapwright asks of a kind's scene table.
pub trait KindScene {
    /// Checks every key of the table (ranges, cross-key rules), reporting under `path`
    /// (`station[i].mechanism`).
    fn check(&self, checker: &mut dyn KeyChecker, path: &str);

    /// The flap deflection range the table asks for (deg) and the key that sets it: every
    /// station of one rigid flap must agree. None: the flap's landing setting (a kind
    /// synthesised from the settings).
    fn deflection_range(&self) -> Option<(f64, &'static str)>;

    /// Moving solids the interference check builds (an upper bound, for the pre-flight
    /// work estimate).
    fn moving_parts(&self) -> usize;

    /// Upper bound of the seconds one station's synthesis takes on the project's 2-core
    /// machine with `airfoil_points_per_side` points on each side of its sections (the
    /// searches ask the section outline, whose queries are linear in its points), for the
    /// pre-flight time budget (`scene::validate::budget`). Measured, not derived: re-measure
    /// when a search changes (`data/validation/work-budget.md`). 0 for a kind dimensioned
    /// by hand.
    fn synthesis_cost_s(&self, airfoil_points_per_side: usize) -> f64;

    /// The flap mass this station carries (kg): the flap's URDF and glTF mass is the sum
    /// over its stations.
    fn flap_mass_kg(&self) -> f64;

    /// The share of [`KindScene::flap_mass_kg`] on a two-element flap's aft element (kg),
    /// where the kind moves it with a body of its own; 0: the kind does not say, and the
    /// flap's mass is spread through both elements alike.
    fn aft_element_mass_kg(&self) -> f64 {
        0.0
    }

    /// The synthesised mechanism, from the table and `context`; on failure, the message and
    /// the keys to change.
    fn synthesise(&self, context: &SynthesisContext) -> Result<Arc<dyn FlapMechanism>, String>;

    /// The keys that decide the kind's geometry, for messages about degenerate layouts.
    fn geometry_keys(&self) -> &'static str;

    /// True when the kind's statics take a flight condition's normal force on the flap
    /// (false: hinge moments only).
    fn takes_normal_force(&self) -> bool {
        true
    }

    /// True when the kind writes its own equation of motion for `[dynamics]` (its bodies'
    /// masses and inertias are its keys); false: the dynamics stage takes the flap's moment
    /// of inertia from its section in the station plane, which a 2D scene has not.
    fn models_own_dynamics(&self) -> bool {
        false
    }

    /// True when the scene gives the actuator's mount (`actuator_mount_m`), so a message
    /// about how the actuator runs names that key rather than the whole mechanism.
    fn gives_actuator_mount(&self) -> bool {
        false
    }

    /// True when the kind's search weighs [`SynthesisContext::followed`] (its free choices
    /// shape the flap's path between the settings): the flap's first station is then
    /// synthesised again, following its second, so that the two meet between their paths.
    fn follows_motion(&self) -> bool {
        false
    }
}

/// `[station.mechanism]`: `kind` picks the variant, the other keys are its dimensions.
#[derive(Debug, Clone)]
pub enum MechanismScene {
    /// Circular-arc track with screw jack (thesis `000_...`, Chapters 3-5).
    CircularArcTrack(CircularArcTrackScene),
    /// Dropped hinge with screw jack, from the stowed and landing settings (`003_...`).
    DroppedHinge(DroppedHingeScene),
    /// Four-bar with screw jack on the crank, from the three settings (`003_...`).
    FourBar(FourBarScene),
    /// Link-track with a rotary actuator, from the three settings (`003_...`).
    LinkTrack(LinkTrackScene),
    /// Hooked-track with a screw jack along its rail, from the stowed and landing settings
    /// (`003_...`).
    HookedTrack(HookedTrackScene),
    /// Five-bar double-slotted flap driven by a crank, as given (`001_...`).
    FiveBar(FiveBarScene),
}

impl MechanismScene {
    /// The `kind` values, as written in the scene.
    pub const KINDS: &'static [&'static str] = &[
        "circular-arc-track",
        "dropped-hinge",
        "four-bar",
        "link-track",
        "hooked-track",
        "five-bar",
    ];

    /// The kinds synthesised from the flap settings and the station's sections, every other
    /// choice defaulted or searched: the ones the trade study (`flapwright study`) can put
    /// in place of any station's mechanism (the others are given by their dimensions).
    pub const SYNTHESISED_KINDS: &'static [&'static str] = &["dropped-hinge", "four-bar", "link-track", "hooked-track"];

    /// True for a kind synthesised from the flap settings ([`Self::SYNTHESISED_KINDS`]).
    pub fn is_synthesised(&self) -> bool {
        matches!(
            self,
            Self::DroppedHinge(_) | Self::FourBar(_) | Self::LinkTrack(_) | Self::HookedTrack(_)
        )
    }

    /// The kind behind the variant: everything else reaches the kind through it.
    pub fn kind(&self) -> &dyn KindScene {
        match self {
            Self::CircularArcTrack(m) => m,
            Self::DroppedHinge(m) => m,
            Self::FourBar(m) => m,
            Self::LinkTrack(m) => m,
            Self::HookedTrack(m) => m,
            Self::FiveBar(m) => m,
        }
    }
}

/// One mechanism kind as `flapwright kinds` lists it, read from the scene's schema (so the
/// keys listed are the keys the scene accepts).
#[derive(Debug, Clone, serde::Serialize)]
pub struct KindSummary {
    /// The `kind` value.
    pub name: String,
    /// One line: what the mechanism is and where it comes from.
    pub summary: String,
    /// Synthesised from the flap settings (every other key optional).
    pub synthesised: bool,
    /// The keys the kind needs besides `kind`.
    pub required_keys: Vec<String>,
    /// The keys it may take, each with a default or a search behind it.
    pub optional_keys: Vec<String>,
}

impl MechanismScene {
    /// Each kind's table schema with its `kind` value and its one-line summary, in
    /// [`Self::KINDS`] order.
    fn variant_schemas(
        generator: &mut schemars::SchemaGenerator,
    ) -> Vec<(&'static str, &'static str, schemars::Schema)> {
        use schemars::JsonSchema;
        vec![
            (
                "circular-arc-track",
                "circular-arc track and screw jack, dimensioned by hand (000_..., Chapters 3-5)",
                CircularArcTrackScene::json_schema(generator),
            ),
            (
                "dropped-hinge",
                "hinge below the wing, screw jack or rotary actuator; from stowed and landing (003_...)",
                DroppedHingeScene::json_schema(generator),
            ),
            (
                "four-bar",
                "four-bar linkage, screw jack on its crank; from the three settings (003_...)",
                FourBarScene::json_schema(generator),
            ),
            (
                "link-track",
                "link and straight track, rotary actuator on the link; from the three settings (003_...)",
                LinkTrackScene::json_schema(generator),
            ),
            (
                "hooked-track",
                "carriage on a hooked rail, screw jack along it; from stowed and landing (003_...)",
                HookedTrackScene::json_schema(generator),
            ),
            (
                "five-bar",
                "five-bar double-slotted flap, crank-driven, dimensioned by hand (001_...)",
                FiveBarScene::json_schema(generator),
            ),
        ]
    }

    /// Every kind with its summary and keys, in [`Self::KINDS`] order.
    pub fn summaries() -> Vec<KindSummary> {
        let mut generator = schemars::SchemaGenerator::default();
        Self::variant_schemas(&mut generator)
            .into_iter()
            .map(|(name, summary, schema)| {
                let required: Vec<String> = schema
                    .get("required")
                    .and_then(|r| r.as_array())
                    .map(|r| r.iter().filter_map(|k| k.as_str().map(str::to_string)).collect())
                    .unwrap_or_default();
                let optional = schema
                    .get("properties")
                    .and_then(|p| p.as_object())
                    .map(|p| p.keys().filter(|k| !required.contains(k)).cloned().collect())
                    .unwrap_or_default();
                KindSummary {
                    name: name.to_string(),
                    summary: summary.to_string(),
                    synthesised: Self::SYNTHESISED_KINDS.contains(&name),
                    required_keys: required,
                    optional_keys: optional,
                }
            })
            .collect()
    }
}

/// The table of `[station.mechanism]`: one of the kinds' tables, told apart by `kind`
/// (each variant inlined with its `kind` as a constant, so that an editor completes the
/// keys of the kind written).
impl schemars::JsonSchema for MechanismScene {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "MechanismScene".into()
    }

    fn json_schema(generator: &mut schemars::SchemaGenerator) -> schemars::Schema {
        let variants: Vec<serde_json::Value> = Self::variant_schemas(generator)
            .into_iter()
            .map(|(name, summary, mut schema)| {
                schema.insert("description".into(), summary.into());
                if let Some(properties) = schema.get_mut("properties").and_then(|p| p.as_object_mut()) {
                    properties.insert(
                        "kind".into(),
                        serde_json::json!({ "const": name, "description": "The mechanism kind." }),
                    );
                }
                let required = schema
                    .ensure_object()
                    .entry("required")
                    .or_insert_with(|| serde_json::Value::Array(Vec::new()));
                if let Some(required) = required.as_array_mut() {
                    required.insert(0, "kind".into());
                }
                schema.to_value()
            })
            .collect();
        schemars::json_schema!({
            "description": "`[station.mechanism]`: `kind` picks the mechanism, the other keys are its dimensions.",
            "type": "object",
            "required": ["kind"],
            "properties": { "kind": { "enum": Self::KINDS } },
            "oneOf": variants,
        })
    }
}

// By hand rather than `#[serde(tag = "kind")]`: serde buffers an internally tagged enum,
// and an error inside it then names the table, never the key (`[station.mechanism]`
// instead of `station[0].mechanism.flap_mass_kg`). Here the variant is deserialised from
// the table with its own key path, passed up in the message (see `parse::nested_error`).
impl<'de> Deserialize<'de> for MechanismScene {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        use serde::de::Error;
        let mut table = toml::Table::deserialize(deserializer)?;
        let kind = match table.remove("kind") {
            Some(toml::Value::String(kind)) => kind,
            Some(other) => {
                return Err(D::Error::custom(crate::scene::nested_error::deciding_error_at(
                    "kind",
                    &format!("= {other}: must be a string, one of {}", Self::KINDS.join(", ")),
                )))
            }
            None => {
                return Err(D::Error::custom(crate::scene::nested_error::deciding_error_at(
                    "kind",
                    &format!("missing: this key is required, one of {}", Self::KINDS.join(", ")),
                )))
            }
        };
        fn variant<T: serde::de::DeserializeOwned, E: Error>(table: toml::Table) -> Result<T, E> {
            serde_path_to_error::deserialize(toml::Value::Table(table))
                .map_err(|e| E::custom(crate::scene::nested_error::nested_error(e.path(), e.inner().message())))
        }
        match kind.as_str() {
            "circular-arc-track" => variant::<_, D::Error>(table).map(Self::CircularArcTrack),
            "dropped-hinge" => variant::<_, D::Error>(table).map(Self::DroppedHinge),
            "four-bar" => variant::<_, D::Error>(table).map(Self::FourBar),
            "link-track" => variant::<_, D::Error>(table).map(Self::LinkTrack),
            "hooked-track" => variant::<_, D::Error>(table).map(Self::HookedTrack),
            "five-bar" => variant::<_, D::Error>(table).map(Self::FiveBar),
            other => Err(D::Error::custom(crate::scene::nested_error::deciding_error_at(
                "kind",
                &format!(
                    "= \"{other}\": unknown mechanism kind; one of {}",
                    Self::KINDS.join(", ")
                ),
            ))),
        }
    }
}
