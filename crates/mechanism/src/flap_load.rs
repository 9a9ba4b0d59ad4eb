//! The load a flap puts on its mechanism at a pose, for any kind: its weight at its centre
//! of mass and the external moment of the load case (`M12`, positive closing, thesis
//! convention) as a couple. Kinds balance it with their own joints; a kind's virtual-work
//! cross-check uses the same wrench through the flap's velocity.

use nalgebra::{Isometry2, Point2, Vector2};
use serde::Serialize;

use crate::kinetostatics::LoadCase;
use crate::rocker_drive::cross;

/// The flap share a station carries.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlapMass {
    /// Mass (kg).
    pub mass_kg: f64,
    /// Centre of mass, stowed (station frame, m).
    pub centre_of_mass_stowed_m: Point2<f64>,
    /// Gravity along the station's -y (m/s²).
    pub gravity_mps2: f64,
}

/// The wrench on the flap at one pose (station frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlapWrench {
    /// Weight (N).
    pub force_n: Vector2<f64>,
    /// Where it acts: the centre of mass (m).
    pub at: Point2<f64>,
    /// Couple, counter-clockwise positive (N m): minus the closing moment M12.
    pub couple_nm: f64,
}

impl FlapWrench {
    /// The wrench for `mass` with the flap at `flap` (displacement from stowed), under
    /// `load` at drive fraction `fraction` (the external moment's interpolation variable).
    pub fn new(mass: &FlapMass, flap: &Isometry2<f64>, load: &LoadCase, fraction: f64) -> Self {
        Self {
            force_n: Vector2::new(0.0, -mass.mass_kg * mass.gravity_mps2),
            at: flap * mass.centre_of_mass_stowed_m,
            couple_nm: -load.external_moment.at(fraction),
        }
    }

    /// Its moment about `point` (N m, counter-clockwise).
    pub fn moment_about(&self, point: Point2<f64>) -> f64 {
        cross(self.at - point, self.force_n) + self.couple_nm
    }

    /// Its power per unit input when the flap turns at `angular` (rad per unit input) and
    /// its centre of mass moves at `velocity` (m per unit input).
    pub fn power(&self, velocity: Vector2<f64>, angular: f64) -> f64 {
        self.force_n.dot(&velocity) + self.couple_nm * angular
    }
}

/// Sizes of the solids that stand for a synthesised kind's hardware (m), scaled with the
/// local flap chord so that a model flap and a transport flap both get plausible parts.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LinkHardware {
    /// Radius of links, arms and struts.
    pub link_radius_m: f64,
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
            nut_radius_m: 0.035 * flap_chord_m,
            jack_body_length_m: 0.10 * flap_chord_m,
            jack_body_radius_m: 0.035 * flap_chord_m,
        }
    }
}
