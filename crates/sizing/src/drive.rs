//! Drive motor demand: torque, power (`003_...` eq 5) and work per deployment.

use serde::Serialize;

use crate::check::{finite, non_negative};
use crate::torque_tube::{cumulative_torques_nm, ideal_motor_torque_nm};
use crate::{Error, Result};

/// Work the drive line delivers over one deployment under one load case.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DeploymentWork {
    /// Load case name.
    pub load_case: String,
    /// Work, J: the raising torque integrated over the screw rotation of every station,
    /// divided by the gearbox efficiency; no safety factor (a physical energy).
    pub work_j: f64,
}

/// What the drive motor must deliver.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DriveDemand {
    /// Ideal motor torque sum T_d,i (eq 4), N m.
    pub ideal_motor_torque_nm: f64,
    /// Motor torque with gearbox losses, sum T_d,i / eta, N m.
    pub motor_torque_nm: f64,
    /// Drive-line angular speed omega_d, rad/s.
    pub angular_speed_rad_s: f64,
    /// Peak power P_M = omega_d sum T_d,i / eta (eq 5), W. The station torques T_d,i are
    /// the motor torque requirements, so this includes the safety factor.
    pub peak_power_w: f64,
    /// Work per deployment for each load case (integrated, no safety factor).
    pub work_per_deployment: Vec<DeploymentWork>,
}

/// Drive demand from the motor torque requirements of the stations (N m, >= 0, with
/// the safety factor), the gearbox efficiency, the drive-line speed (rad/s) and the work
/// per deployment of each load case (from [`deployment_work_j`]).
///
/// # Errors
/// [`Error::EfficiencyOutOfRange`], [`Error::OutOfRange`].
pub fn drive_demand(
    drive_torques_nm: &[f64],
    gearbox_efficiency: f64,
    angular_speed_rad_s: f64,
    work_per_deployment: Vec<DeploymentWork>,
) -> Result<DriveDemand> {
    let carried = cumulative_torques_nm(drive_torques_nm, gearbox_efficiency)?;
    let omega = non_negative("angular_speed_rad_s", angular_speed_rad_s)?;
    for work in &work_per_deployment {
        finite("work_j", work.work_j)?;
    }
    let motor_torque_nm = carried.last().copied().unwrap_or(0.0);
    let peak_power_w = drive_power_w(motor_torque_nm, omega)?;
    Ok(DriveDemand {
        ideal_motor_torque_nm: ideal_motor_torque_nm(drive_torques_nm),
        motor_torque_nm,
        angular_speed_rad_s: omega,
        peak_power_w,
        work_per_deployment,
    })
}

/// Power P = T omega, W (N m, rad/s; `003_...` eq 5 with T = sum T_d,i / eta).
///
/// # Errors
/// [`Error::OutOfRange`] for non-finite values.
pub fn drive_power_w(motor_torque_nm: f64, angular_speed_rad_s: f64) -> Result<f64> {
    finite("motor_torque_nm", motor_torque_nm)?;
    finite("angular_speed_rad_s", angular_speed_rad_s)?;
    Ok(motor_torque_nm * angular_speed_rad_s)
}

/// Work per deployment W = integral T d(theta), J, by the trapezoid rule over samples
/// of the motor angle (rad, non-decreasing) and motor torque (N m). Exact for a torque
/// linear in angle between samples.
///
/// # Errors
/// [`Error::LengthMismatch`], [`Error::Empty`], [`Error::NotIncreasing`] for a
/// decreasing angle, [`Error::OutOfRange`] for non-finite samples.
pub fn deployment_work_j(motor_angles_rad: &[f64], motor_torques_nm: &[f64]) -> Result<f64> {
    if motor_angles_rad.len() != motor_torques_nm.len() {
        return Err(Error::LengthMismatch {
            what: "motor angles and torques",
            first: motor_angles_rad.len(),
            second: motor_torques_nm.len(),
        });
    }
    if motor_angles_rad.is_empty() {
        return Err(Error::Empty {
            what: "motor torque history",
        });
    }
    let mut work = 0.0;
    for i in 0..motor_angles_rad.len() {
        finite(format!("motor_angles_rad[{i}]"), motor_angles_rad[i])?;
        finite(format!("motor_torques_nm[{i}]"), motor_torques_nm[i])?;
        if i > 0 {
            let step = motor_angles_rad[i] - motor_angles_rad[i - 1];
            if step < 0.0 {
                return Err(Error::NotIncreasing {
                    what: "motor angles",
                    index: i,
                    value: motor_angles_rad[i],
                });
            }
            work += 0.5 * (motor_torques_nm[i] + motor_torques_nm[i - 1]) * step;
        }
    }
    Ok(work)
}
