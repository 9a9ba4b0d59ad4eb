//! Actuators (a screw jack, or a geared rotary actuator): the motor torque with a safety
//! factor and the self-locking verdict (thesis `000` section 5.2), from the peak torques
//! on the actuator's drive shaft over the deployment. The thread torques themselves (eqs
//! 3.6.9, 3.6.10) belong to the mechanism: `flapwright_mechanism::ScrewJack`, re-exported
//! here. (Named `screw_jack`, `ScrewJackInput`, `ScrewJackSizing` and `size_screw_jack`
//! before issue 36, though they held rotary actuators too.)

use serde::Serialize;

use crate::check::finite;
use crate::warning::SizingWarning;
use crate::{Error, Result};

/// Peak drive-shaft torques of one actuator over the deployment (a screw jack's thread
/// torques, eqs 3.6.9-10, or a rotary actuator's through its gearing).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ActuatorInput {
    /// Station name.
    pub station: String,
    /// Actuator name (`screw-jack`, `rotary-actuator`).
    pub name: String,
    /// Largest raising (deploying) torque over the deployment, N m.
    pub max_raise_torque_nm: f64,
    /// Largest lowering (retracting) torque over the deployment, N m, eq 3.6.10 sign:
    /// positive = self-locking.
    pub max_lower_torque_nm: f64,
    /// Smallest lowering torque over the deployment, N m: decides self-locking.
    pub min_lower_torque_nm: f64,
    /// Whether the thread itself is self-locking (friction angle above lead angle, f >
    /// tan lambda).
    pub thread_self_locking: bool,
}

/// Result of [`size_actuator`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ActuatorSizing {
    /// Station name.
    pub station: String,
    /// Actuator name (`screw-jack`, `rotary-actuator`).
    pub name: String,
    /// Largest raising torque, N m.
    pub max_raise_torque_nm: f64,
    /// Largest lowering torque over the deployment, N m (eq 3.6.10 sign).
    pub max_lower_torque_nm: f64,
    /// Smallest lowering torque over the deployment, N m.
    pub min_lower_torque_nm: f64,
    /// Safety factor applied.
    pub safety_factor: f64,
    /// Motor torque requirement = safety factor x max(|T_R|, |T_L|), N m.
    pub motor_torque_nm: f64,
    /// True when the thread is self-locking and the smallest lowering torque is positive:
    /// no load can back-drive the screw, and none does anywhere in the deployment.
    pub self_locking: bool,
    /// Warnings about this jack (also collected by the report).
    #[serde(skip)]
    pub warnings: Vec<SizingWarning>,
}

/// Motor torque requirement, N m: safety factor x max(|T_R|, |T_L|) (thesis section
/// 5.2: 4.7 N m x 1.5 -> 7.1 N m).
///
/// # Errors
/// [`Error::OutOfRange`] for non-finite torques or a safety factor below 1.
pub fn motor_torque_nm(max_raise_torque_nm: f64, max_lower_torque_nm: f64, safety_factor: f64) -> Result<f64> {
    finite("max_raise_torque_nm", max_raise_torque_nm)?;
    finite("max_lower_torque_nm", max_lower_torque_nm)?;
    if !(safety_factor.is_finite() && safety_factor >= 1.0) {
        return Err(Error::OutOfRange {
            field: "safety_factor".to_owned(),
            value: safety_factor,
            allowed: "[1, inf)",
        });
    }
    Ok(safety_factor * max_raise_torque_nm.abs().max(max_lower_torque_nm.abs()))
}

/// Motor torque and self-locking verdict of one actuator; one that is not
/// self-locking gets a [`SizingWarning::NotSelfLocking`].
///
/// # Errors
/// As [`motor_torque_nm`].
pub fn size_actuator(input: &ActuatorInput, safety_factor: f64) -> Result<ActuatorSizing> {
    finite("min_lower_torque_nm", input.min_lower_torque_nm)?;
    let largest_lower = if input.min_lower_torque_nm.abs() > input.max_lower_torque_nm.abs() {
        input.min_lower_torque_nm
    } else {
        input.max_lower_torque_nm
    };
    let motor = motor_torque_nm(input.max_raise_torque_nm, largest_lower, safety_factor)?;
    let self_locking = input.thread_self_locking && input.min_lower_torque_nm > 0.0;
    let mut warnings = Vec::new();
    if !self_locking {
        warnings.push(SizingWarning::NotSelfLocking {
            station: input.station.clone(),
            actuator: input.name.clone(),
            lower_torque_nm: input.min_lower_torque_nm,
        });
    }
    Ok(ActuatorSizing {
        station: input.station.clone(),
        name: input.name.clone(),
        max_raise_torque_nm: input.max_raise_torque_nm,
        max_lower_torque_nm: input.max_lower_torque_nm,
        min_lower_torque_nm: input.min_lower_torque_nm,
        safety_factor,
        motor_torque_nm: motor,
        self_locking,
        warnings,
    })
}
