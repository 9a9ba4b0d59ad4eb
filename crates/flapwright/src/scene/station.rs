//! Mechanisms and their loads: `[[station]]`, `[loads]`.

use serde::Deserialize;

/// `[[station]]`: one support mechanism.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct StationScene {
    /// Station name.
    pub name: String,
    /// Flap it supports (absent in a 2D-only scene).
    pub flap: Option<String>,
    /// Distance along the hinge axis from the flap's inboard side plane (thesis d1, or d1 + d2), m.
    pub axis_offset_m: Option<f64>,
    /// The mechanism plane: `perpendicular-to-axis` (default: the thesis construction) or
    /// `skew-corrected` (`003_...` Fig. 4: the flap's landing motion x the dihedral vector).
    pub plane: Option<flapwright_planes::PlaneConstruction>,
    /// Mechanism kind and its dimensions.
    pub mechanism: crate::kinds::MechanismScene,
}

/// `[loads]`.
#[derive(Debug, Clone, Deserialize, Default, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LoadsScene {
    /// Safety factor on motor torque (CS-25: 1.5).
    pub safety_factor: Option<f64>,
    /// Named load cases.
    #[serde(default)]
    pub cases: Vec<LoadCaseScene>,
}

/// `[[loads.cases]]`: external (aerodynamic) moment about the hinge per station, closing
/// the flap, constant or linear from stowed to fully deployed; or a flight condition (the
/// dynamic pressure, or speed and density, and the flap normal-force coefficient against
/// deflection), whose flap load is shared among the stations by statics.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
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
    /// Flight condition: dynamic pressure, Pa.
    pub dynamic_pressure_pa: Option<f64>,
    /// Flight condition: true air speed, m/s (with `density_kgpm3`).
    pub speed_mps: Option<f64>,
    /// Flight condition: air density, kg/m^3.
    pub density_kgpm3: Option<f64>,
    /// Flight condition: load factor on the normal force (CS-25 flaps extended: 2.0).
    pub load_factor: Option<f64>,
    /// Flight condition: flap normal-force coefficient C_N against deflection, rows
    /// `[deflection_deg, C_N]` in increasing deflection (`003_...` eq. 1; ESDU F.05.01.01).
    pub normal_force_coefficient: Option<Vec<[f64; 2]>>,
}

impl LoadCaseScene {
    /// The dynamic pressure of a flight-condition case (Pa), if it is one.
    pub fn dynamic_pressure(&self) -> Option<f64> {
        let from_speed = match (self.speed_mps, self.density_kgpm3) {
            (Some(v), Some(rho)) => Some(0.5 * rho * v * v),
            _ => None,
        };
        self.dynamic_pressure_pa.or(from_speed)
    }

    /// True for a flight-condition case.
    pub fn is_flight_condition(&self) -> bool {
        self.normal_force_coefficient.is_some()
            || self.dynamic_pressure_pa.is_some()
            || self.speed_mps.is_some()
            || self.density_kgpm3.is_some()
    }
}
