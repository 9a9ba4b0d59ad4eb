//! Geared rotary actuators (Zaccai, Bertels & Vos `003_...` section 3, Fig. 6): the drive
//! shaft turns a gearbox whose output turns a link of the mechanism; `003_...` computes the
//! gear ratio from the drive, as it computes a screw's lead for a linear actuator.

use serde::{Deserialize, Serialize};

use crate::seam::Actuator;

/// How a geared rotary actuator is chosen from the drive it shares with the wing's other
/// stations: every drive shaft on one torque tube turns together, so each station's gear
/// ratio is the shaft's turns over its output's travel, N = 2π turns / Δθ, and its nominal
/// output speed Δθ over the common deployment time.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RotaryDrive {
    /// Drive-shaft turns over the deployment.
    pub turns: f64,
    /// Deployment time at the nominal drive speed (s).
    pub deployment_time_s: f64,
    /// The gearing's mechanical efficiency, in (0, 1].
    pub efficiency: f64,
}

impl RotaryDrive {
    /// The actuator for an output travel of `travel_rad`.
    pub fn actuator_for(&self, travel_rad: f64) -> Actuator {
        let travel = travel_rad.abs();
        Actuator::Rotary {
            gear_ratio: 2.0 * std::f64::consts::PI * self.turns / travel,
            efficiency: self.efficiency,
            nominal_speed_radps: travel / self.deployment_time_s,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The shaft turns `turns` times over the travel, in the deployment time; without loss
    /// the shaft's work equals the output's (virtual work), with loss it exceeds it by 1/η
    /// deploying against the load and falls short by η when the load back-drives.
    #[test]
    fn gear_ratio_and_shaft_torques_balance_work() {
        let drive = RotaryDrive {
            turns: 40.0,
            deployment_time_s: 20.0,
            efficiency: 0.9,
        };
        let travel = 35f64.to_radians();
        let actuator = drive.actuator_for(travel);
        let shaft_travel = travel * actuator.shaft_angle_per_input();
        assert!((shaft_travel - 2.0 * std::f64::consts::PI * 40.0).abs() < 1e-9);
        assert!((actuator.shaft_speed_radps() * 20.0 - shaft_travel).abs() < 1e-9);
        let load_nm = 1500.0;
        let torques = actuator.shaft_torques(load_nm);
        assert!((torques.raise_torque_nm * shaft_travel - load_nm * travel / 0.9).abs() < 1e-9);
        assert!((-torques.lower_torque_nm * shaft_travel - load_nm * travel * 0.9).abs() < 1e-9);
        let lossless = RotaryDrive {
            efficiency: 1.0,
            ..drive
        }
        .actuator_for(travel);
        let ideal = lossless.shaft_torques(-load_nm);
        assert!((ideal.raise_torque_nm * shaft_travel + load_nm * travel).abs() < 1e-9);
        assert_eq!(ideal.raise_torque_nm, -ideal.lower_torque_nm);
        assert!(!actuator.self_locking());
    }
}
