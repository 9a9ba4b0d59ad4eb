//! Quasi-static forces of the circular-arc track: actuator force by equilibrium
//! (thesis eq. 3.4.16) and by virtual work (eq. 3.5.1), slot reactions (eqs. 3.4.8/3.4.9 by
//! Cramer's rule) and screw torques (eqs. 3.6.9/3.6.10).

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::screw_jack::ScrewTorques;
use crate::track_pose::Pose;
use crate::track_synthesis::CircularArcTrack;

/// The external (aerodynamic) moment M12 on the flap about the hinge A0, positive when it
/// tends to close the flap (clockwise in the station frame), N m.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum ExternalMoment {
    /// Same moment at every deflection (thesis cruise scenario).
    Constant(f64),
    /// Linear between the stowed and the fully deployed value, interpolated over the nut
    /// stroke fraction (s34 - s34,i)/Δs. This is the reading that reproduces the thesis
    /// spreadsheet (Appendix C, Fig. 48): its M12 column steps by ΔM·10 mm/Δs per 10 mm
    /// row (14 895.6 N mm), not by ΔM·Δθ12/β3.
    Linear {
        /// M12 with the flap closed (N m).
        stowed_nm: f64,
        /// M12 with the flap fully deployed (N m).
        deployed_nm: f64,
    },
}

impl ExternalMoment {
    /// M12 (N m) at stroke fraction `stroke_fraction` = (s34 - s34,i)/Δs in [0, 1].
    pub fn at(&self, stroke_fraction: f64) -> f64 {
        match *self {
            Self::Constant(moment) => moment,
            Self::Linear {
                stowed_nm,
                deployed_nm,
            } => stowed_nm + (deployed_nm - stowed_nm) * stroke_fraction.clamp(0.0, 1.0),
        }
    }
}

/// A named load case for one mechanism.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LoadCase {
    /// Name, e.g. `cruise` or `landing`.
    pub name: String,
    /// External moment on the flap share this mechanism carries.
    pub external_moment: ExternalMoment,
}

impl LoadCase {
    /// Thesis cruise scenario (section 5.2): 750 N m on the flap, shared by its two screw
    /// jacks, so M12 = 375 N m per mechanism. The thesis halves the aerodynamic moment but
    /// NOT the flap weight (each mechanism carries the full 12 kg in Appendix C): that is
    /// the reading that reproduces Table 3.
    pub fn thesis_cruise() -> Self {
        Self {
            name: "cruise".to_owned(),
            external_moment: ExternalMoment::Constant(0.5 * 750.0),
        }
    }

    /// Thesis landing scenario (section 5.2): 220 N m closed, 650 N m fully deployed,
    /// halved for two jacks (110 N m → 325 N m), linear over the stroke.
    pub fn thesis_landing() -> Self {
        Self {
            name: "landing".to_owned(),
            external_moment: ExternalMoment::Linear {
                stowed_nm: 0.5 * 220.0,
                deployed_nm: 0.5 * 650.0,
            },
        }
    }
}

/// Forces on the track at one pose under one load case (N, N m; thesis signs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Forces {
    /// M12 (N m) at this pose.
    pub external_moment_nm: f64,
    /// m g r_D cos θD (N m): moment of the weight about A0 with the sign of eq. 3.5.1.
    pub weight_moment_nm: f64,
    /// F_input = F42 (N) by equilibrium, eq. 3.4.16; positive pushes A away from B0.
    pub actuator_force_n: f64,
    /// F_input (N) by virtual work / total power, eq. 3.5.1, from the pose's velocities.
    pub actuator_force_virtual_work_n: f64,
    /// G12G (N): radial reaction of the inner slot on pin G along θG (eq. 3.4.8/9).
    pub inner_slot_reaction_n: f64,
    /// G12F (N): radial reaction of the outer slot on pin F along θF (eq. 3.4.8/9).
    pub outer_slot_reaction_n: f64,
    /// Screw torques for L = F_input.
    pub screw: ScrewTorques,
}

impl CircularArcTrack {
    /// Quasi-static forces at `pose` under `load` (inertia neglected, as the thesis shows
    /// accelerations below 0.1 % g, Fig. 31).
    ///
    /// Errors: [`Error::SlotReactionsIndeterminate`] when sin(θF - θG) vanishes,
    /// [`Error::NonFinite`] if anything overflows.
    pub fn forces(&self, pose: &Pose, load: &LoadCase) -> Result<Forces> {
        let spec = &self.spec;
        let synthesis = &self.synthesis;
        let input_m = pose.linkage.input_m;
        let fraction = (input_m - synthesis.stroke_start_m) / synthesis.stroke_m;
        let moment = load.external_moment.at(fraction);
        let weight = spec.flap_mass_kg * spec.gravity_mps2;
        let d = pose.centre_of_mass_d.position_m;
        let (r_d, theta_d) = (d.coords.norm(), d.y.atan2(d.x));
        let weight_moment = weight * r_d * theta_d.cos();

        // Eq. 3.4.16, literally: F42 = (M12 - m g r_D sin(3π/2 - θD)) / (a2 sin(θ13 - θ12)).
        let delta = pose.linkage.slider_angle_rad - pose.linkage.crank_angle_rad;
        let actuator = (moment - weight * r_d * (1.5 * PI - theta_d).sin())
            / (spec.crank_length_m * delta.sin());

        // Eq. 3.5.1 from total power -M12 ω12 - m g ẏD + F ṡ = 0, with the pose's (or unit
        // virtual) velocities.
        let speed = pose.linkage.input_speed_mps;
        let virtual_work = if speed != 0.0 {
            (moment * pose.linkage.crank_rate_radps + weight * pose.centre_of_mass_d.velocity_mps.y)
                / speed
        } else {
            let rate = pose.linkage.crank_rate_per_input_radpm;
            moment * rate + weight * d.x * rate
        };

        // Eqs. 3.4.8/3.4.9 by Cramer's rule (the thesis's closed forms).
        let theta_g = synthesis.inner_pin_angle_stowed_rad + pose.deflection_rad;
        let theta_f = synthesis.outer_pin_angle_stowed_rad + pose.deflection_rad;
        let screw_dir = spec.base_angle_rad + pose.linkage.slider_angle_rad;
        let determinant = (theta_f - theta_g).sin();
        if determinant.abs() < 1e-12 {
            return Err(Error::SlotReactionsIndeterminate { determinant });
        }
        let inner = (actuator * (screw_dir - theta_f).sin() - weight * theta_f.cos()) / determinant;
        let outer = (weight * theta_g.cos() - actuator * (screw_dir - theta_g).sin()) / determinant;

        let forces = Forces {
            external_moment_nm: moment,
            weight_moment_nm: weight_moment,
            actuator_force_n: actuator,
            actuator_force_virtual_work_n: virtual_work,
            inner_slot_reaction_n: inner,
            outer_slot_reaction_n: outer,
            screw: spec.screw.torques(actuator),
        };
        for (quantity, value) in [
            ("actuator_force_n", forces.actuator_force_n),
            ("actuator_force_virtual_work_n", forces.actuator_force_virtual_work_n),
            ("inner_slot_reaction_n", forces.inner_slot_reaction_n),
            ("outer_slot_reaction_n", forces.outer_slot_reaction_n),
            ("raise_torque_nm", forces.screw.raise_torque_nm),
        ] {
            if !value.is_finite() {
                return Err(Error::NonFinite { quantity, input_m });
            }
        }
        Ok(forces)
    }
}
