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
    pub mechanism: crate::kinds::MechanismScene,
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
