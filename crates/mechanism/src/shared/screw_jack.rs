//! Square-thread screw jack torques (thesis section 3.6, eqs. 3.6.9 and 3.6.10).

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

/// A square-threaded power screw (thesis Fig. 17; Shigley 8th ed. §8-2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ScrewJack {
    /// Lead l (m): axial advance per revolution.
    pub lead_m: f64,
    /// Mean thread radius r (m).
    pub mean_radius_m: f64,
    /// Thread friction coefficient f (-).
    pub friction_coefficient: f64,
}

/// Raise and lower torques for one axial load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ScrewTorques {
    /// T_R (N m), thesis eq. 3.6.9: torque to move the nut against the load (deploy).
    pub raise_torque_nm: f64,
    /// T_L (N m), thesis eq. 3.6.10: torque to move the nut with the load (retract).
    /// Positive means the screw must be driven to lower: it is self-locking.
    pub lower_torque_nm: f64,
}

impl ScrewJack {
    /// Checks lead and radius (finite, > 0), friction (finite, >= 0) and that the screw can
    /// raise at all (2πr - f l > 0, else [`Error::ScrewJammed`]).
    pub fn validate(&self) -> Result<()> {
        for (name, value) in [("lead_m", self.lead_m), ("mean_radius_m", self.mean_radius_m)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(Error::InvalidDimension { name, value });
            }
        }
        if !(self.friction_coefficient.is_finite() && self.friction_coefficient >= 0.0) {
            return Err(Error::ParameterOutOfRange {
                name: "friction_coefficient",
                value: self.friction_coefficient,
                min: 0.0,
                max: f64::INFINITY,
            });
        }
        let denominator_m = 2.0 * std::f64::consts::PI * self.mean_radius_m - self.friction_coefficient * self.lead_m;
        if denominator_m <= 0.0 {
            return Err(Error::ScrewJammed { denominator_m });
        }
        Ok(())
    }

    /// Lead angle λ (rad): tan λ = l / (2π r). (The thesis prints "tanλ = 1/2πr", a typo
    /// for l/(2πr).)
    pub fn lead_angle_rad(&self) -> f64 {
        (self.lead_m / (2.0 * std::f64::consts::PI * self.mean_radius_m)).atan()
    }

    /// True when the screw holds its load without a brake: f > tan λ, i.e. T_L > 0 for a
    /// positive load.
    pub fn is_self_locking(&self) -> bool {
        self.friction_coefficient > self.lead_angle_rad().tan()
    }

    /// Torques for axial load `load_n` (N), signed as the thesis uses it (L = F_input).
    ///
    /// T_R = (2π r f + l)/(2π r - f l) r L (eq. 3.6.9);
    /// T_L = (2π r f - l)/(2π r + f l) r L (eq. 3.6.10). Units: N m for r in m.
    /// Call [`ScrewJack::validate`] first: with 2πr - f l <= 0 the raise torque is meaningless.
    pub fn torques(&self, load_n: f64) -> ScrewTorques {
        let circumference = 2.0 * std::f64::consts::PI * self.mean_radius_m;
        let friction_arc = circumference * self.friction_coefficient;
        let (l, f, r) = (self.lead_m, self.friction_coefficient, self.mean_radius_m);
        ScrewTorques {
            raise_torque_nm: (friction_arc + l) / (circumference - f * l) * r * load_n,
            lower_torque_nm: (friction_arc - l) / (circumference + f * l) * r * load_n,
        }
    }
}

/// How a synthesised kind's screw jack is chosen: its thread's radius and friction, and the
/// drive it shares with the wing's other stations. Every screw on one torque tube turns
/// together, so each station's lead is its stroke over the common number of turns and its
/// nut speed its stroke over the common deployment time (`003_...` section 3: "a screw
/// pitch (linear actuator) is computed"); the screws then all turn at turns / time.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ScrewDrive {
    /// Mean thread radius (m).
    pub mean_radius_m: f64,
    /// Thread friction coefficient.
    pub friction_coefficient: f64,
    /// Screw turns over the deployment.
    pub turns: f64,
    /// Deployment time at the nominal drive speed (s).
    pub deployment_time_s: f64,
}

impl ScrewDrive {
    /// The screw and nominal nut speed (m/s) for a stroke of `travel_m`.
    pub fn screw_for(&self, travel_m: f64) -> (ScrewJack, f64) {
        (
            ScrewJack {
                lead_m: travel_m.abs() / self.turns,
                mean_radius_m: self.mean_radius_m,
                friction_coefficient: self.friction_coefficient,
            },
            travel_m.abs() / self.deployment_time_s,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn torques_match_inclined_plane_form() {
        // Eqs. 3.6.4/3.6.8 (tan λ form) against 3.6.9/3.6.10 (lead form).
        let screw = ScrewJack {
            lead_m: 0.008,
            mean_radius_m: 0.016,
            friction_coefficient: 0.1,
        };
        let tan_lead = screw.lead_angle_rad().tan();
        let load = 1000.0;
        let torques = screw.torques(load);
        let raise = 0.016 * (0.1 + tan_lead) / (1.0 - 0.1 * tan_lead) * load;
        let lower = 0.016 * (0.1 - tan_lead) / (1.0 + 0.1 * tan_lead) * load;
        assert!((torques.raise_torque_nm - raise).abs() < 1e-12 * raise);
        assert!((torques.lower_torque_nm - lower).abs() < 1e-12 * lower);
        assert!(screw.is_self_locking());
        let steep = ScrewJack { lead_m: 0.05, ..screw };
        assert!(!steep.is_self_locking());
        assert!(steep.torques(load).lower_torque_nm < 0.0);
    }

    /// Virtual work: without friction one turn of T_R lifts L by one lead, 2π T_R = L l,
    /// and lowering returns it, T_L = -T_R; with friction the efficiency drops below 1.
    #[test]
    fn frictionless_thread_conserves_work() {
        let frictionless = ScrewJack {
            lead_m: 0.008,
            mean_radius_m: 0.016,
            friction_coefficient: 0.0,
        };
        let torques = frictionless.torques(1000.0);
        let turn = 2.0 * std::f64::consts::PI;
        assert!((turn * torques.raise_torque_nm - 1000.0 * 0.008).abs() < 1e-12);
        assert!((torques.lower_torque_nm + torques.raise_torque_nm).abs() < 1e-12);
        let rough = ScrewJack {
            friction_coefficient: 0.1,
            ..frictionless
        };
        assert!(1000.0 * 0.008 / (turn * rough.torques(1000.0).raise_torque_nm) < 1.0);
    }
}
