//! Rigid motions of flap-mechanism parts with certified speed bounds.

use nalgebra::{Isometry3, Point3, Translation3, Unit, UnitQuaternion, Vector3};

use crate::part::Motion;

/// Rotation by `t` (rad) about a fixed axis: the flap of a circular-arc track (and every
/// part rigid with it) turning about the hinge line, aircraft frame.
#[derive(Debug, Clone, Copy)]
pub struct AboutAxis {
    /// A point on the axis, aircraft frame (m).
    pub point_ac: Point3<f64>,
    /// Axis direction; positive `t` turns counter-clockwise about it.
    pub direction_ac: Unit<Vector3<f64>>,
    /// Largest distance of any point of the part from the axis (m): the speed bound per
    /// radian.
    pub max_radius_m: f64,
    /// The part turns up to this angle (rad) and stays there for larger `t`: a flap stops
    /// at its own full deflection while another flap of the wing turns further.
    pub max_angle_rad: f64,
}

impl AboutAxis {
    /// The pose at angle `t` (rad).
    pub fn pose_at(&self, t: f64) -> Isometry3<f64> {
        let p = self.point_ac.coords;
        let angle = t.min(self.max_angle_rad);
        Translation3::from(p) * UnitQuaternion::from_axis_angle(&self.direction_ac, angle) * Translation3::from(-p)
    }

    /// Largest distance from the axis (m) of `points` (aircraft frame).
    pub fn radius_of(point_ac: &Point3<f64>, direction_ac: &Unit<Vector3<f64>>, points: &[Point3<f64>]) -> f64 {
        points
            .iter()
            .map(|q| {
                let r = q - point_ac;
                (r - direction_ac.into_inner() * r.dot(direction_ac)).norm()
            })
            .fold(0.0, f64::max)
    }
}

impl Motion for AboutAxis {
    fn pose_ac(&self, t: f64) -> Result<Isometry3<f64>, flapwright_mechanism::Error> {
        Ok(self.pose_at(t))
    }

    fn speed_bound(&self) -> f64 {
        self.max_radius_m
    }
}
