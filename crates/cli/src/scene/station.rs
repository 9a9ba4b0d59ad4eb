//! Mechanisms and their loads: `[[station]]`, `[loads]`.

use serde::Deserialize;

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

/// `[station.mechanism]`: `kind` picks the variant, the other keys are its dimensions.
#[derive(Debug, Clone)]
pub enum MechanismScene {
    /// Circular-arc track with screw jack (thesis `000_...`, Chapters 3-5).
    CircularArcTrack(CircularArcTrackScene),
}

impl MechanismScene {
    /// The `kind` values, as written in the scene.
    pub const KINDS: &'static [&'static str] = &["circular-arc-track"];

    /// Moving solids the interference check builds for this mechanism (an upper bound, for
    /// the pre-flight work estimate): screw, jack body, two tracks and the flap fittings.
    pub fn moving_parts(&self) -> usize {
        match self {
            Self::CircularArcTrack(_) => 7,
        }
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
                return Err(D::Error::custom(super::parse::nested_error_at(
                    "kind",
                    &format!("= {other}: must be a string, one of {}", Self::KINDS.join(", ")),
                )))
            }
            None => return Err(D::Error::missing_field("kind")),
        };
        let variant = |table: toml::Table| {
            serde_path_to_error::deserialize(toml::Value::Table(table))
                .map_err(|e| D::Error::custom(super::parse::nested_error(e.path(), e.inner().message())))
        };
        match kind.as_str() {
            "circular-arc-track" => variant(table).map(Self::CircularArcTrack),
            other => Err(D::Error::custom(super::parse::nested_error_at(
                "kind",
                &format!(
                    "= \"{other}\": unknown mechanism kind; one of {}",
                    Self::KINDS.join(", ")
                ),
            ))),
        }
    }
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
