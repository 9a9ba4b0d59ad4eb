//! `[dynamics]`: the DC motor, gearbox, supply voltage and integration settings of the
//! dynamics stage (`001_...` section 3.2; `flapwright-dynamics`).

use flapwright_dynamics::{DcMotor, Drive, Gearbox, Integration, Method, SupplyVoltage};
use serde::Deserialize;

use super::KeyChecker;

/// `[dynamics]`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct DynamicsScene {
    /// The motor.
    pub motor: MotorScene,
    /// Between the motor and the mechanism's input.
    #[serde(default)]
    pub gearbox: GearboxScene,
    /// The supply voltage.
    pub supply: SupplyScene,
    /// `bdf` (default), `esdirk34` or `tsit45` (explicit, for comparison).
    #[serde(default)]
    pub method: MethodScene,
    /// Relative tolerance of the local error (default 1e-6: the knee, see `docs/dynamics.md`).
    #[serde(default = "default_relative_tolerance")]
    pub relative_tolerance: f64,
    /// Absolute tolerance (default 1e-8).
    #[serde(default = "default_absolute_tolerance")]
    pub absolute_tolerance: f64,
    /// Give up at this time if the flap has not deployed, s (default 60).
    #[serde(default = "default_max_time_s")]
    pub max_time_s: f64,
    /// Give up after this many steps (default 200 000).
    #[serde(default = "default_max_steps")]
    pub max_steps: usize,
}

/// `motor = { ... }`.
#[derive(Debug, Clone, Copy, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MotorScene {
    /// Armature resistance, Ω.
    pub resistance_ohm: f64,
    /// Armature inductance, H.
    pub inductance_h: f64,
    /// Torque constant, N m/A.
    pub torque_constant_nm_per_a: f64,
    /// Rotor inertia, kg m² (default 0).
    #[serde(default)]
    pub rotor_inertia_kgm2: f64,
}

/// `gearbox = { ... }`.
#[derive(Debug, Clone, Copy, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields, default)]
pub struct GearboxScene {
    /// Motor turns per input turn.
    pub ratio: f64,
    /// Efficiency.
    pub efficiency: f64,
}

impl Default for GearboxScene {
    /// A direct drive (`001_...`).
    fn default() -> Self {
        Self {
            ratio: 1.0,
            efficiency: 1.0,
        }
    }
}

/// `supply = { ... }`.
#[derive(Debug, Clone, Copy, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SupplyScene {
    /// Final voltage, V.
    pub volts: f64,
    /// Rise time of the smooth start, s (default 0.05).
    #[serde(default = "default_rise_time_s")]
    pub rise_time_s: f64,
}

/// `method = "..."`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum MethodScene {
    /// BDF.
    #[default]
    Bdf,
    /// ESDIRK34.
    Esdirk34,
    /// Tsit45 (explicit).
    Tsit45,
}

/// Smallest relative tolerance the integrators are asked for. Measured (issue 35 item 18)
/// with `absolute_tolerance` at its floor, 1e-15: BDF deploys the shipped dynamics
/// problems down to 1e-10, while at 1e-11 (and 1e-12, 1e-13) the rigid-flap runs of
/// `transport-flap` with a `[dynamics]` table stop with "Exceeded maximum number of
/// nonlinear solver failures", and at 1e-15 the five-bar of `double-slotted-flap` with
/// "Step size is too small" (exit 1 from the dynamics stage). With the default
/// `absolute_tolerance` (1e-8) every run passed down to 1e-17, but the range has to hold
/// for every absolute tolerance it allows.
pub const MIN_RELATIVE_TOLERANCE: f64 = 1e-10;

fn default_relative_tolerance() -> f64 {
    1e-6
}
fn default_absolute_tolerance() -> f64 {
    1e-8
}
fn default_max_time_s() -> f64 {
    60.0
}
fn default_max_steps() -> usize {
    200_000
}
fn default_rise_time_s() -> f64 {
    0.05
}

impl DynamicsScene {
    /// Checks every key's range.
    pub fn check(&self, checker: &mut dyn KeyChecker) {
        let m = &self.motor;
        for (key, value, min, max) in [
            ("motor.resistance_ohm", m.resistance_ohm, 1e-6, 1e4),
            ("motor.inductance_h", m.inductance_h, 1e-9, 10.0),
            ("motor.torque_constant_nm_per_a", m.torque_constant_nm_per_a, 1e-6, 1e4),
            ("motor.rotor_inertia_kgm2", m.rotor_inertia_kgm2, 0.0, 1e3),
            ("gearbox.ratio", self.gearbox.ratio, 1e-3, 1e5),
            ("gearbox.efficiency", self.gearbox.efficiency, 0.01, 1.0),
            ("supply.volts", self.supply.volts, 1e-3, 1e5),
            ("supply.rise_time_s", self.supply.rise_time_s, 1e-6, 100.0),
            (
                "relative_tolerance",
                self.relative_tolerance,
                MIN_RELATIVE_TOLERANCE,
                1e-1,
            ),
            ("absolute_tolerance", self.absolute_tolerance, 1e-15, 1.0),
            ("max_time_s", self.max_time_s, 1e-3, 3600.0),
            ("max_steps", self.max_steps as f64, 10.0, 1e7),
        ] {
            checker.in_range(&format!("dynamics.{key}"), value, min, max, false);
        }
    }

    /// The drive, supply and settings as `flapwright-dynamics` takes them.
    pub fn parts(&self) -> (Drive, SupplyVoltage, Integration) {
        let drive = Drive {
            motor: DcMotor {
                resistance_ohm: self.motor.resistance_ohm,
                inductance_h: self.motor.inductance_h,
                torque_constant_nm_per_a: self.motor.torque_constant_nm_per_a,
                rotor_inertia_kgm2: self.motor.rotor_inertia_kgm2,
            },
            gearbox: Gearbox {
                ratio: self.gearbox.ratio,
                efficiency: self.gearbox.efficiency,
            },
        };
        let supply = SupplyVoltage {
            volts: self.supply.volts,
            rise_time_s: self.supply.rise_time_s,
        };
        let integration = Integration {
            method: match self.method {
                MethodScene::Bdf => Method::Bdf,
                MethodScene::Esdirk34 => Method::Esdirk34,
                MethodScene::Tsit45 => Method::Tsit45,
            },
            relative_tolerance: self.relative_tolerance,
            absolute_tolerance: self.absolute_tolerance,
            max_steps: self.max_steps,
            max_time_s: self.max_time_s,
        };
        (drive, supply, integration)
    }
}
