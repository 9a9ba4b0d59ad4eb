//! The drive: a DC motor with an R-L armature (`001_...` section 3.2), a gearbox, the supply
//! voltage, and the smooth-start crank law of `001_...` eq. (1).
//!
//! Motor (`001_...` 3.2): v = R i + L di/dt + e_b, e_b = K ω_m, T_m = K i, with ω_m = n q̇
//! the motor's speed for a gearbox of ratio n (motor turns per input turn). The gearbox
//! passes n η T_m to the mechanism; η is taken as a constant torque factor, which is its
//! loss when the motor drives the load (power flowing from motor to flap, as it does over a
//! deployment against air loads); the energy balance books the loss (1 - η) T_m ω_m.

use serde::Serialize;

use crate::error::{Error, Result};

/// A brushed DC motor.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DcMotor {
    /// Armature resistance R (Ω).
    pub resistance_ohm: f64,
    /// Armature inductance L (H).
    pub inductance_h: f64,
    /// Torque constant K (N m/A, equal to the back-emf constant in V s/rad).
    pub torque_constant_nm_per_a: f64,
    /// Rotor inertia (kg m², on the motor shaft).
    pub rotor_inertia_kgm2: f64,
}

/// The reduction between the motor and the mechanism's input.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Gearbox {
    /// Motor angle per input angle n.
    pub ratio: f64,
    /// Mechanical efficiency η in (0, 1].
    pub efficiency: f64,
}

/// Motor and gearbox.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Drive {
    /// The motor.
    pub motor: DcMotor,
    /// The gearbox.
    pub gearbox: Gearbox,
}

impl Drive {
    /// The `001_...` motor (R = 2 Ω, K = 20 N m/A) coupled directly to the crank (n = 1,
    /// η = 1, rotor inertia neglected, as the document does), with armature inductance
    /// `inductance_h` (the document gives none).
    pub fn polimi_case_study(inductance_h: f64) -> Self {
        Self {
            motor: DcMotor {
                resistance_ohm: 2.0,
                inductance_h,
                torque_constant_nm_per_a: 20.0,
                rotor_inertia_kgm2: 0.0,
            },
            gearbox: Gearbox {
                ratio: 1.0,
                efficiency: 1.0,
            },
        }
    }

    /// Checks every parameter's range.
    pub fn validate(&self) -> Result<()> {
        let m = &self.motor;
        positive("motor.resistance_ohm", m.resistance_ohm)?;
        positive("motor.inductance_h", m.inductance_h)?;
        positive("motor.torque_constant_nm_per_a", m.torque_constant_nm_per_a)?;
        if !(m.rotor_inertia_kgm2.is_finite() && m.rotor_inertia_kgm2 >= 0.0) {
            return Err(Error::OutOfRange {
                name: "motor.rotor_inertia_kgm2",
                value: m.rotor_inertia_kgm2,
                min: 0.0,
                max: f64::INFINITY,
            });
        }
        positive("gearbox.ratio", self.gearbox.ratio)?;
        let eta = self.gearbox.efficiency;
        if !(eta.is_finite() && eta > 0.0 && eta <= 1.0) {
            return Err(Error::OutOfRange {
                name: "gearbox.efficiency",
                value: eta,
                min: 0.0,
                max: 1.0,
            });
        }
        Ok(())
    }

    /// Torque on the input per ampere, n η K (N m/A).
    pub fn input_torque_per_amp(&self) -> f64 {
        self.gearbox.ratio * self.gearbox.efficiency * self.motor.torque_constant_nm_per_a
    }

    /// Back-emf per unit input rate, n K (V s/rad).
    pub fn emf_per_input_rate(&self) -> f64 {
        self.gearbox.ratio * self.motor.torque_constant_nm_per_a
    }

    /// The rotor's inertia seen at the input, n² J_r (kg m²).
    pub fn reflected_rotor_inertia(&self) -> f64 {
        self.gearbox.ratio * self.gearbox.ratio * self.motor.rotor_inertia_kgm2
    }
}

pub(crate) fn positive(name: &'static str, value: f64) -> Result<()> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(Error::OutOfRange {
            name,
            value,
            min: 0.0,
            max: f64::INFINITY,
        })
    }
}

/// The supply voltage: a step to `volts` smoothed over `rise_time_s`,
/// v(t) = V (1 - exp(-t / t_r)), so that the current starts without a jump (the supply's
/// analogue of `001_...` eq. 1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SupplyVoltage {
    /// Final voltage V (V).
    pub volts: f64,
    /// Rise time t_r (s).
    pub rise_time_s: f64,
}

impl SupplyVoltage {
    /// v(t) (V).
    pub fn at(&self, time_s: f64) -> f64 {
        self.volts * (1.0 - (-time_s / self.rise_time_s).exp())
    }

    /// Checks the parameters.
    pub fn validate(&self) -> Result<()> {
        positive("supply.volts", self.volts)?;
        positive("supply.rise_time_s", self.rise_time_s)
    }
}

/// The crank law of `001_...` eq. (1): the input rate rises smoothly to ω,
/// Δq(t) = ω [t + (exp(-k t) - 1)/k], so q̇ = ω (1 - e^{-kt}) starts at zero.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SmoothStart {
    /// Final input rate ω (rad/s).
    pub rate_radps: f64,
    /// Smoothing rate k (1/s).
    pub smoothing_per_s: f64,
}

impl SmoothStart {
    /// Δq, q̇, q̈ and the third derivative at time `t` (s).
    pub fn at(&self, t: f64) -> [f64; 4] {
        let (w, k) = (self.rate_radps, self.smoothing_per_s);
        let decay = (-k * t).exp();
        [
            w * (t + (decay - 1.0) / k),
            w * (1.0 - decay),
            w * k * decay,
            -w * k * k * decay,
        ]
    }

    /// The time at which the input has travelled `travel` (Newton on Δq(t) = travel, from
    /// the constant-rate time plus the lag 1/k).
    pub fn time_to_travel(&self, travel: f64) -> f64 {
        let mut t = travel / self.rate_radps + 1.0 / self.smoothing_per_s;
        for _ in 0..50 {
            let [q, rate, ..] = self.at(t);
            let step = (q - travel) / rate;
            t -= step;
            if step.abs() <= 1e-15 * t.abs() {
                break;
            }
        }
        t
    }
}
