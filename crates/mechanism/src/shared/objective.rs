//! What a synthesis search weighs besides the fairing's depth: the actuator's load under
//! the station's load cases, so that a search does not pick a mechanism with almost no
//! mechanical advantage because its fairing is a few millimetres shallower (issue 37).
//!
//! A candidate's cost is
//!
//! ```text
//! cost = depth / c_f + w · L_peak / L_ref
//! ```
//!
//! with the fairing's depth below the stowed sections, the flap chord c_f, the actuator's
//! peak load L_peak over the deployment and the load cases, and the reference L_ref: the
//! largest force the load cases put on the flap (N) for a linear actuator, that force
//! times the flap chord (N m) for a rotary one. `003_...` Table 1's mechanisms carry
//! 0.3-0.55 of the air load in their actuators; the weight [`DEFAULT_LOAD_WEIGHT`] = 0.2
//! makes a fairing one tenth of the flap chord deeper worth half the air load off the
//! actuator (a judgement: a deeper fairing costs drag in cruise, a heavier actuator and
//! structure cost weight; both of the order of each other on a transport flap).
//!
//! With a [`MassWeighing`] the cost also counts the mass the actuator's placement adds:
//!
//! ```text
//! cost += w_m · (m_screw + m_horn) / m_flap
//! ```
//!
//! the screw and the horn (the arm beyond the body's pivot that a screw takes hold of)
//! sized as the sizing stage sizes them (solid round rods of the scene's materials under
//! the design loads times the safety factor: the screw for strength and Euler buckling, the
//! horn for its bending moment at the pivot, which is the body's torque), against the
//! flap share the station carries, m_flap. Weighed by load alone, a placement took a horn
//! half again as long for a screw a fifth less loaded and the crank that carried it grew
//! from 56 to 89 kg between neighbouring landing deflections (`transport-flap`'s four-bar).
//!
//! The load a body needs is found by virtual work from the flap's poses alone, whatever
//! the kind: the torque about the body's pivot is minus the power of the flap's wrench
//! ([`FlapWrench`]) per unit body rotation, the flap's velocity by central differences of
//! its pose. It is independent of each kind's own statics, which the tests compare it
//! with.

use nalgebra::{Isometry2, Point2, Vector2};

use crate::shared::flap_load::{FlapMass, FlapWrench};
use crate::shared::load_case::LoadCase;

/// Default weight of the actuator's peak load, in reference loads, against the fairing's
/// depth in flap chords (see the module's docs).
pub const DEFAULT_LOAD_WEIGHT: f64 = 0.2;

/// Default weight of a rotary actuator's peak torque, in reference torques (the largest
/// force times the flap chord), against the depth in flap chords: five times
/// [`DEFAULT_LOAD_WEIGHT`], since a rotary actuator carries about a fifth as many of its
/// reference loads as a screw jack does of its own (`003_...` Table 1 at `ob-inner`: the
/// link-track's 12.1 kN m is 0.09 of 86 kN times the flap chord, the screw jacks carry
/// 0.29-0.55 of 86 kN). At 0.2 the torque hardly counted: on `transport-flap`'s outboard
/// flap the link-track's choice jumped between links turning 40 and 150 deg as the landing
/// gap moved by 0.05 %c, its torque by up to 7.6x (`data/validation/continuity/`).
pub const DEFAULT_ROTARY_LOAD_WEIGHT: f64 = 1.0;

/// Relative step of the central differences of the flap's pose (of the body's rotation
/// range): the truncation error is of the step squared, the rounding of 1e-16 over it.
const DIFFERENCE_STEP: f64 = 1e-4;

/// The load cases a search weighs its actuator under, and how much.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadWeighing {
    /// The station's load cases (the flap's weight alone when the scene gives none).
    pub loads: Vec<LoadCase>,
    /// The flap share the station carries.
    pub flap_mass: FlapMass,
    /// Weight of the peak load in reference loads against the depth in flap chords.
    pub weight: f64,
    /// A load (reference loads) above which every further reference load costs
    /// [`CAP_EXCESS_WEIGHT`] more: a search then takes the shallowest candidate whose
    /// actuator carries at most this, and trades steeply beyond it. `None`: no cap.
    pub load_cap: Option<f64>,
    /// How the mass a placement adds is weighed; `None`: not at all.
    pub mass: Option<MassWeighing>,
}

/// Default weight of the mass a placement adds, in the station's flap shares, against the
/// depth in flap chords: a kilogram is worth about 5 mm of fairing depth on
/// `transport-flap`'s 1.6-1.8 m flaps, whose stations carry 150-180 kg each. The order of it:
/// a fairing 0.1 m deeper adds of the order of 0.1-0.2 drag counts on a single-aisle
/// transport, and a count is worth about 200 kg of weight at a lift-to-drag ratio of 17
/// (q S 1e-4 L/D / g with q = 10 kPa in cruise and S = 122 m^2); so 1 kg is worth 2.5-5 mm.
pub const DEFAULT_MASS_WEIGHT: f64 = 0.5;

/// A structural material as the searches' mass estimate needs it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MemberMaterial {
    /// Density (kg/m^3).
    pub density_kg_m3: f64,
    /// Allowable normal stress (Pa).
    pub allowable_pa: f64,
    /// Young's modulus (Pa).
    pub youngs_modulus_pa: f64,
}

/// How a search weighs the mass a placement adds ([`LoadWeighing::mass`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassWeighing {
    /// Weight of the mass in the station's flap shares against the depth in flap chords.
    pub weight: f64,
    /// The links' and arms' material.
    pub link: MemberMaterial,
    /// The screw's material.
    pub screw: MemberMaterial,
    /// The factor on the load cases' loads the sizing applies.
    pub safety_factor: f64,
    /// Euler's effective-length factor of the screw.
    pub screw_end_fixity_factor: f64,
}

impl MassWeighing {
    /// Mass of a solid round rod of `length_m` carrying `force_n` along it (kg): the larger
    /// of the strength radius, sqrt(F / (pi sigma)), and Euler's, (4 F (K L)^2 / (pi^3 E))^(1/4),
    /// with the force times the safety factor (the sizing stage's rods, `flapwright_sizing::rod`).
    pub fn screw_mass_kg(&self, length_m: f64, force_n: f64) -> f64 {
        use std::f64::consts::PI;
        let (m, f) = (&self.screw, force_n.abs() * self.safety_factor);
        let strength = (f / (PI * m.allowable_pa)).sqrt();
        let effective = self.screw_end_fixity_factor * length_m;
        let buckling = (4.0 * f * effective * effective / (PI.powi(3) * m.youngs_modulus_pa)).powf(0.25);
        let r = strength.max(buckling);
        m.density_kg_m3 * PI * r * r * length_m
    }

    /// Mass of a solid round arm of `length_m` whose bending moment reaches `moment_nm`
    /// (kg): radius (4 M / (pi sigma))^(1/3) with the moment times the safety factor.
    pub fn arm_mass_kg(&self, length_m: f64, moment_nm: f64) -> f64 {
        use std::f64::consts::PI;
        let m = &self.link;
        let r = (4.0 * moment_nm.abs() * self.safety_factor / (PI * m.allowable_pa)).cbrt();
        m.density_kg_m3 * PI * r * r * length_m
    }
}

/// The cost of each reference load above [`LoadWeighing::load_cap`], against the depth in
/// flap chords: a fairing half a flap chord deeper is worth a quarter of the reference load
/// over the cap.
pub const CAP_EXCESS_WEIGHT: f64 = 2.0;

/// The shortest stroke a weighed screw-jack placement takes without a penalty (m): flap
/// ball-screw actuators of a business jet and a turboprop stroke 220 and 400 mm
/// (rosner-tdl.de, "Landing flaps drive system"); this is half the shorter. A placement
/// weighed by a light load alone took hold of a dropped hinge's arm at the hinge, with
/// strokes of 32-44 mm and leads under 1.1 mm on the light aircraft.
pub const MIN_STROKE_M: f64 = 0.1;

impl LoadWeighing {
    /// The torque (N m, magnitude, the largest over the load cases) that the body turning
    /// the flap needs about its pivot at each rotation of `rotations` (rad, from 0 to
    /// `range_rad`), where `flap_at(ψ)` is the flap's displacement with the body turned by
    /// ψ. `None` where the flap cannot be posed round a rotation.
    pub fn body_torques(
        &self,
        rotations: &[f64],
        range_rad: f64,
        flap_at: &dyn Fn(f64) -> Option<Isometry2<f64>>,
    ) -> Vec<Option<f64>> {
        let h = DIFFERENCE_STEP * range_rad.abs().max(1e-9);
        rotations
            .iter()
            .map(|&psi| {
                let here = flap_at(psi)?;
                let (before, after, span) = match (flap_at(psi - h), flap_at(psi + h)) {
                    (Some(b), Some(a)) => (b, a, 2.0 * h),
                    (None, Some(a)) => (here, a, h),
                    (Some(b), None) => (b, here, h),
                    (None, None) => return None,
                };
                let to_stowed = here.inverse();
                let velocity_of = |p: Point2<f64>| -> Vector2<f64> {
                    let stowed = to_stowed * p;
                    (after * stowed - before * stowed) / span
                };
                let angular = (after.rotation.angle() - before.rotation.angle()) / span;
                let fraction = if range_rad == 0.0 {
                    0.0
                } else {
                    (psi / range_rad).clamp(0.0, 1.0)
                };
                let torque = self
                    .loads
                    .iter()
                    .map(|load| {
                        FlapWrench::new(&self.flap_mass, &here, load, fraction)
                            .power(velocity_of, angular)
                            .abs()
                    })
                    .fold(0.0, f64::max);
                Some(torque)
            })
            .collect()
    }

    /// The largest force the load cases put on the flap over `flap_poses` (N): the weight
    /// times the load factor plus the air load, the reference of a linear actuator's load.
    pub fn reference_force_n(&self, flap_poses: &[Isometry2<f64>]) -> f64 {
        flap_poses
            .iter()
            .enumerate()
            .flat_map(|(k, pose)| {
                let fraction = k as f64 / (flap_poses.len().max(2) - 1) as f64;
                self.loads
                    .iter()
                    .map(move |load| FlapWrench::new(&self.flap_mass, pose, load, fraction).force_n().norm())
            })
            .fold(0.0, f64::max)
    }

    /// The cost of a candidate: `depth_m / flap_chord_m + weight · peak / reference`.
    pub fn cost(&self, depth_m: f64, flap_chord_m: f64, peak: f64, reference: f64) -> f64 {
        let load = if reference > 0.0 && peak.is_finite() {
            peak / reference
        } else {
            0.0
        };
        let excess = self
            .load_cap
            .map_or(0.0, |cap| CAP_EXCESS_WEIGHT * (load - cap).max(0.0));
        depth_m / flap_chord_m.max(1e-9) + self.weight * load + excess
    }

    /// What `mass_kg` of mechanism costs: [`MassWeighing::weight`] times it in the station's
    /// flap shares; 0 without a mass weighing or a flap mass.
    pub fn mass_cost(&self, mass_kg: f64) -> f64 {
        match self.mass {
            Some(mass) if self.flap_mass.mass_kg > 0.0 && mass_kg.is_finite() => {
                mass.weight * mass_kg / self.flap_mass.mass_kg
            }
            _ => 0.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shared::geometry::turn_about;
    use crate::shared::load_case::{ExternalMoment, FlapNormalForce};

    fn weighing(loads: Vec<LoadCase>) -> LoadWeighing {
        LoadWeighing {
            loads,
            flap_mass: FlapMass {
                mass_kg: 50.0,
                centre_of_mass_stowed_m: Point2::new(-0.4, 0.05),
                gravity_mps2: Vector2::new(0.0, -9.81),
            },
            weight: DEFAULT_LOAD_WEIGHT,
            load_cap: None,
            mass: None,
        }
    }

    /// A flap turning about a fixed hinge: the torque is the wrench's moment about the
    /// hinge (an analytic case), for a normal force that turns with the flap and its weight.
    #[test]
    fn the_torque_of_a_hinged_flap_is_the_moment_about_its_hinge() {
        let hinge = Point2::new(-0.1, -0.2);
        let load = LoadCase {
            name: "landing".into(),
            external_moment: ExternalMoment::Constant(150.0),
            include_inertia: false,
            flap_normal_force: Some(FlapNormalForce {
                coefficients: vec![(0.0, 0.5), (0.7, 1.3)],
                newtons_per_coefficient: 20_000.0,
                at_stowed_m: Point2::new(-0.35, 0.02),
                normal_stowed: Vector2::new(0.05, 1.0).normalize(),
            }),
            load_factor: 2.0,
        };
        let w = weighing(vec![load.clone()]);
        let range = -0.6;
        let rotations: Vec<f64> = (0..=6).map(|k| range * k as f64 / 6.0).collect();
        let flap_at = |psi: f64| Some(turn_about(hinge, psi));
        let torques = w.body_torques(&rotations, range, &flap_at);
        for (&psi, torque) in rotations.iter().zip(torques) {
            let pose = turn_about(hinge, psi);
            let fraction = psi / range;
            let moment = FlapWrench::new(&w.flap_mass, &pose, &load, fraction).moment_about(hinge);
            let torque = torque.unwrap();
            assert!(
                (torque - moment.abs()).abs() <= 1e-6 * moment.abs(),
                "{torque} against {moment}"
            );
        }
    }

    #[test]
    fn the_cost_adds_depth_in_chords_and_load_in_reference_loads() {
        let w = weighing(Vec::new());
        assert!((w.cost(0.2, 1.0, 50.0, 100.0) - (0.2 + 0.5 * DEFAULT_LOAD_WEIGHT)).abs() < 1e-15);
        // No reference (no load at all): depth alone.
        assert_eq!(w.cost(0.3, 1.0, 0.0, 0.0), 0.3);
        let poses = [Isometry2::identity()];
        assert_eq!(w.reference_force_n(&poses), 0.0, "no load cases, no force");
    }
}
