//! The load a flap puts on its mechanism at a pose, for any kind: its weight at its centre
//! of mass and the external moment of the load case (`M12`, positive closing, thesis
//! convention) as a couple. Kinds balance it with their own joints; a kind's virtual-work
//! cross-check uses the same wrench through the flap's velocity.

use nalgebra::{Isometry2, Point2, Vector2};
use serde::Serialize;

use crate::shared::geometry::cross;
use crate::shared::load_case::LoadCase;

/// The flap share a station carries.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlapMass {
    /// Mass (kg).
    pub mass_kg: f64,
    /// Centre of mass, stowed (station frame, m).
    pub centre_of_mass_stowed_m: Point2<f64>,
    /// Gravity's acceleration in the station plane (station frame, m/s²): the aircraft's
    /// downward g projected on the plane's axes, (0, -9.81) in an upright plane; the
    /// component normal to the plane goes to the joints' out-of-plane play, not modelled.
    pub gravity_mps2: Vector2<f64>,
}

/// The wrench on the flap at one pose (station frame): its weight at the centre of mass,
/// the flight condition's normal force at its point, and the external couple.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlapWrench {
    /// Weight (N).
    pub weight_n: Vector2<f64>,
    /// The centre of mass where it stands (m).
    pub centre_of_mass: Point2<f64>,
    /// Aerodynamic normal force (N; zero without a flight condition).
    pub aero_n: Vector2<f64>,
    /// Where it acts (m).
    pub aero_at: Point2<f64>,
    /// Couple, counter-clockwise positive (N m): minus the closing moment M12.
    pub couple_nm: f64,
}

impl FlapWrench {
    /// The wrench for `mass` with the flap at `flap` (displacement from stowed), under
    /// `load` at drive fraction `fraction` (the external moment's interpolation variable);
    /// the normal force at the flap's deflection (its displacement's rotation), along the
    /// stowed chord's normal turned with the flap; the weight times the load factor.
    pub fn new(mass: &FlapMass, flap: &Isometry2<f64>, load: &LoadCase, fraction: f64) -> Self {
        let (aero_n, aero_at) = match &load.flap_normal_force {
            Some(normal) => (
                flap.rotation * normal.normal_stowed * normal.at(flap.rotation.angle()),
                flap * normal.at_stowed_m,
            ),
            None => (Vector2::zeros(), flap * mass.centre_of_mass_stowed_m),
        };
        Self {
            weight_n: mass.gravity_mps2 * mass.mass_kg * load.load_factor,
            centre_of_mass: flap * mass.centre_of_mass_stowed_m,
            aero_n,
            aero_at,
            couple_nm: -load.external_moment.at(fraction),
        }
    }

    /// The resultant force (N).
    pub fn force_n(&self) -> Vector2<f64> {
        self.weight_n + self.aero_n
    }

    /// Its moment about `point` (N m, counter-clockwise).
    pub fn moment_about(&self, point: Point2<f64>) -> f64 {
        cross(self.centre_of_mass - point, self.weight_n) + cross(self.aero_at - point, self.aero_n) + self.couple_nm
    }

    /// Its power per unit input when the flap turns at `angular` (rad per unit input) and
    /// its points move at `velocity_of(point)` (m per unit input).
    pub fn power(&self, velocity_of: impl Fn(Point2<f64>) -> Vector2<f64>, angular: f64) -> f64 {
        self.weight_n.dot(&velocity_of(self.centre_of_mass))
            + self.aero_n.dot(&velocity_of(self.aero_at))
            + self.couple_nm * angular
    }
}

/// Sizes of the solids that stand for a synthesised kind's hardware (m), scaled with the
/// local flap chord so that a model flap and a transport flap both get plausible parts.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LinkHardware {
    /// Radius of links, arms and struts.
    pub link_radius_m: f64,
    /// Radius of the struts that hold a four-bar's fixed pivots to the wing (the other
    /// kinds' struts take `link_radius_m`): the sizing loop thickens it alone where they
    /// need more, so that a strut does not thicken the links and move the loop.
    pub strut_radius_m: f64,
    /// Radius of the nut and of pin bosses.
    pub nut_radius_m: f64,
    /// Length of the jack body centred on the screw's mount.
    pub jack_body_length_m: f64,
    /// Radius of the jack body.
    pub jack_body_radius_m: f64,
}

impl LinkHardware {
    /// Hardware for a flap of chord `flap_chord_m`: links 3 %, nut 3.5 %, jack body 10 % long
    /// and 3.5 % in radius of the flap chord (a 1.6 m transport flap gets 48 mm links; the
    /// thesis's 0.56 m flap 17 mm, near its 8-20 mm hardware).
    pub fn for_flap_chord(flap_chord_m: f64) -> Self {
        Self {
            link_radius_m: 0.03 * flap_chord_m,
            strut_radius_m: 0.03 * flap_chord_m,
            nut_radius_m: 0.035 * flap_chord_m,
            jack_body_length_m: 0.10 * flap_chord_m,
            jack_body_radius_m: 0.035 * flap_chord_m,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shared::load_case::{ExternalMoment, FlapNormalForce};

    /// `003_...` eq. 1's normal force stays square to the flap's chord at every deflection,
    /// whatever the chord's incidence in the station plane; the weight takes the load factor.
    #[test]
    fn the_normal_force_is_square_to_the_chord_and_the_weight_takes_the_load_factor() {
        let incidence = 5.6f64.to_radians();
        // The stowed chord from the trailing edge to the leading edge, nose down by the incidence.
        let chord = Vector2::new(incidence.cos(), -incidence.sin());
        let mass = FlapMass {
            mass_kg: 100.0,
            centre_of_mass_stowed_m: Point2::new(-0.3, 0.0),
            gravity_mps2: Vector2::new(0.0, -9.81),
        };
        let load = LoadCase {
            name: "manoeuvre".into(),
            external_moment: ExternalMoment::Constant(0.0),
            include_inertia: false,
            flap_normal_force: Some(FlapNormalForce {
                coefficients: vec![(0.0, 1.0)],
                newtons_per_coefficient: 1000.0,
                at_stowed_m: Point2::new(-0.2, 0.0),
                normal_stowed: Vector2::new(-chord.y, chord.x),
            }),
            load_factor: 2.5,
        };
        for deg in [0.0, 15.0, 40.0] {
            let flap = Isometry2::new(Vector2::new(-0.1, -0.05), -f64::to_radians(deg));
            let wrench = FlapWrench::new(&mass, &flap, &load, 0.5);
            let turned_chord = flap.rotation * chord;
            assert!(wrench.aero_n.dot(&turned_chord).abs() < 1e-9, "{deg} deg");
            assert!((wrench.aero_n.norm() - 1000.0).abs() < 1e-9);
            assert!((wrench.weight_n.y + 2.5 * 100.0 * 9.81).abs() < 1e-9);
        }
    }
}
