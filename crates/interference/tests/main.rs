//! Integration tests of the clearance sweep.

mod brute_force;
mod joint;
mod opening;
mod planar;
mod relative_speed;
mod same_station;
mod slabs;
mod sweep;

use flapwright_interference::Motion;
use nalgebra::{Isometry3, Vector3};

/// Rotation about the aircraft z axis through the origin by angle `t` (rad); points within
/// `max_radius_m` of the axis move at most `max_radius_m` per radian.
pub struct TurnAboutZ {
    /// Largest distance of the part from the z axis (m).
    pub max_radius_m: f64,
}

impl Motion for TurnAboutZ {
    fn pose_ac(&self, t: f64) -> Result<Isometry3<f64>, flapwright_mechanism::Error> {
        Ok(Isometry3::rotation(Vector3::z() * t))
    }

    fn speed_bound(&self) -> f64 {
        self.max_radius_m
    }
}
