//! The drive a prescribed input motion needs: the `001_...` section 3.2 computation, where
//! the crank turns at constant speed (here after the smooth start of its eq. 1) and the
//! motor's torque and voltage follow.
//!
//! Input torque τ = J_e q̈ + ½ J' q̇² - Q (work-energy, [`flapwright_mechanism::generalised`]),
//! J_e = J + n² J_r; motor torque τ / (n η); current τ / (n η K); voltage
//! v = R i + L di/dt + n K q̇ with di/dt = τ̇ / (n η K),
//! τ̇ = J_e q⃛ + 2 J' q̇ q̈ + ½ J'' q̇³ - Q' q̇.

use flapwright_mechanism::OneInputDynamics;
use serde::Serialize;

use crate::drive::{Drive, SmoothStart};
use crate::error::{Error, Result};

/// The drive at one instant of a prescribed motion.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RequiredSample {
    /// Time (s).
    pub time_s: f64,
    /// Input q (rad).
    pub input: f64,
    /// q̇ (rad/s).
    pub rate: f64,
    /// Torque on the input (N m).
    pub input_torque_nm: f64,
    /// Motor torque (N m).
    pub motor_torque_nm: f64,
    /// Armature current (A).
    pub current_a: f64,
    /// Supply voltage (V).
    pub voltage_v: f64,
}

/// `samples` instants, evenly spaced in time, of the motion `law` from the stowed input to
/// the deployed one.
pub fn required_drive(
    system: &dyn OneInputDynamics,
    drive: &Drive,
    law: &SmoothStart,
    samples: usize,
) -> Result<Vec<RequiredSample>> {
    drive.validate()?;
    crate::drive::positive("law.rate_radps", law.rate_radps)?;
    crate::drive::positive("law.smoothing_per_s", law.smoothing_per_s)?;
    let (stowed, deployed) = system.input_travel();
    let direction = (deployed - stowed).signum();
    let duration = law.time_to_travel((deployed - stowed).abs());
    let per_amp = drive.input_torque_per_amp();
    let (r, l) = (drive.motor.resistance_ohm, drive.motor.inductance_h);
    let last = samples.max(2) - 1;
    (0..=last)
        .map(|k| {
            let time_s = duration * k as f64 / last as f64;
            let [travel, rate, accel, jerk] = law.at(time_s).map(|x| x * direction);
            let input = stowed + travel;
            let g = system
                .generalised_at(input)
                .map_err(|source| Error::Mechanism { input, source })?;
            let inertia = g.inertia + drive.reflected_rotor_inertia();
            let torque = inertia * accel + 0.5 * g.inertia_slope * rate * rate - g.force;
            let torque_rate =
                inertia * jerk + 2.0 * g.inertia_slope * rate * accel + 0.5 * g.inertia_curvature * rate * rate * rate
                    - g.force_slope * rate;
            let current_a = torque / per_amp;
            Ok(RequiredSample {
                time_s,
                input,
                rate,
                input_torque_nm: torque,
                motor_torque_nm: torque / (drive.gearbox.ratio * drive.gearbox.efficiency),
                current_a,
                voltage_v: r * current_a + l * torque_rate / per_amp + drive.emf_per_input_rate() * rate,
            })
        })
        .collect()
}
