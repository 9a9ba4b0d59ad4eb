//! Quasi-static forces of the circular-arc track: actuator force by equilibrium
//! (thesis eq. 3.4.16) and by virtual work (eq. 3.5.1), slot reactions (eqs. 3.4.8/3.4.9 by
//! Cramer's rule) and screw torques (eqs. 3.6.9/3.6.10).

use serde::Serialize;

use super::pose::Pose;
use super::synthesis::CircularArcTrack;
use flapwright_mechanism::shared::load_case::LoadCase;
use flapwright_mechanism::shared::screw_jack::ScrewTorques;
use flapwright_mechanism::{Error, Result};

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
    /// Forces at `pose` under `load`: quasi-static as in the thesis (which shows
    /// accelerations below 0.1 % g, Fig. 31) unless `load.include_inertia`, which adds the
    /// d'Alembert force m a_D and moment I_D α12 + D × m a_D.
    ///
    /// Errors: [`Error::SlotReactionsIndeterminate`] when sin(θF - θG) vanishes,
    /// [`Error::NonFinite`] if anything overflows.
    pub fn forces(&self, pose: &Pose, load: &LoadCase) -> Result<Forces> {
        let spec = &self.spec;
        let synthesis = &self.synthesis;
        let input_m = pose.linkage.input_m;
        let fraction = (input_m - synthesis.stroke_start_m) / synthesis.stroke_m;
        let moment = load.external_moment.at(fraction);
        let weight = load.load_factor * spec.flap_mass_kg * spec.gravity_mps2;
        let d = pose.centre_of_mass_d.position_m;
        // r_D cos θD = x_D and r_D sin(3π/2 - θD) = -x_D: no trigonometry needed.
        let weight_moment = weight * d.x;
        // d'Alembert terms (zero unless asked for): m a_D and I_D α12 + m (D × a_D) about A0.
        let (inertia_force, inertia_moment) = if load.include_inertia {
            let a_d = pose.centre_of_mass_d.acceleration_mps2 * spec.flap_mass_kg;
            (
                a_d,
                spec.flap_moment_of_inertia_kgm2 * pose.linkage.crank_accel_radps2 + d.coords.perp(&a_d),
            )
        } else {
            (nalgebra::Vector2::zeros(), 0.0)
        };

        // Eq. 3.4.16: F42 = (M12 - m g r_D sin(3π/2 - θD)) / (a2 sin(θ13 - θ12))
        //                 = (M12 + m g r_D cos θD) / (a2 sin(θ13 - θ12)), plus inertia.
        let rate_per_input = pose.linkage.crank_rate_per_input_radpm;
        let actuator = (moment + weight_moment + inertia_moment) * rate_per_input;

        // Eq. 3.5.1 from total power -M12 ω12 - m g ẏD + F ṡ = 0 (plus the inertia power
        // m a_D·v_D + I_D α12 ω12), with the pose's velocities, or unit virtual velocities
        // at ṡ = 0.
        let speed = pose.linkage.input_speed_mps;
        let velocity_d = pose.centre_of_mass_d.velocity_mps;
        let inertia_power = inertia_force.dot(&velocity_d)
            + if load.include_inertia {
                spec.flap_moment_of_inertia_kgm2 * pose.linkage.crank_accel_radps2 * pose.linkage.crank_rate_radps
            } else {
                0.0
            };
        let virtual_work = if speed != 0.0 {
            (moment * pose.linkage.crank_rate_radps + weight * velocity_d.y + inertia_power) / speed
        } else {
            let virtual_d = nalgebra::Vector2::new(-d.y, d.x) * rate_per_input;
            let inertia_virtual = inertia_force.dot(&virtual_d)
                + if load.include_inertia {
                    spec.flap_moment_of_inertia_kgm2 * pose.linkage.crank_accel_radps2 * rate_per_input
                } else {
                    0.0
                };
            moment * rate_per_input + weight * virtual_d.y + inertia_virtual
        };

        // Eqs. 3.4.8/3.4.9 by Cramer's rule, with the angles' sines and cosines read off the
        // posed pins and screw (and m a_D on the right when inertia is included):
        // G12G = (R_x sinθF - R_y cosθF) / sin(θF - θG), G12F = (R_y cosθG - R_x sinθG) / sin(θF - θG),
        // R = (-F42 cos c + m a_x, m g + m a_y - F42 sin c), c = α0 + θ13.
        // The pins ride on their slots, so their unit radial directions are position / radius.
        let g_dir = pose.inner_pin_g.position_m.coords / spec.inner_slot_radius_m;
        let f_dir = pose.outer_pin_f.position_m.coords / spec.outer_slot_radius_m;
        let screw = (pose.screw_end_b.position_m - synthesis.screw_mount_m) / spec.screw_length_m;
        let determinant = g_dir.perp(&f_dir);
        if determinant.abs() < 1e-12 {
            return Err(Error::SlotReactionsIndeterminate { determinant });
        }
        let rhs = inertia_force - screw * actuator + nalgebra::Vector2::new(0.0, weight);
        let inner = rhs.perp(&f_dir) / determinant;
        let outer = g_dir.perp(&rhs) / determinant;

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
