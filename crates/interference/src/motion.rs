//! Rigid motions of flap-mechanism parts with certified speed bounds.

use nalgebra::{Isometry3, Point2, Point3, Translation3, Unit, UnitQuaternion, Vector3};

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
}

impl AboutAxis {
    /// The pose at angle `t` (rad).
    pub fn pose_at(&self, t: f64) -> Isometry3<f64> {
        let p = self.point_ac.coords;
        Translation3::from(p) * UnitQuaternion::from_axis_angle(&self.direction_ac, t) * Translation3::from(-p)
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
    fn pose_ac(&self, t: f64) -> Isometry3<f64> {
        self.pose_at(t)
    }

    fn speed_bound(&self) -> f64 {
        self.max_radius_m
    }
}

/// The screw of a circular-arc track: it turns about its mount B0 (station frame) so that
/// it always points at the nut pivot A, which turns with the flap about A0 by `t` (rad).
///
/// |dφ/dt| = |dA/dt|⊥ / |A - B0| <= a2 / s34,min, so a point at distance ρ from B0 moves
/// at most ρ a2 / s34,min per radian of flap rotation.
#[derive(Debug, Clone, Copy)]
pub struct ScrewAboutMount {
    /// Station frame in the aircraft frame.
    pub aircraft_from_station: Isometry3<f64>,
    /// B0, station frame (m).
    pub mount_st: Point2<f64>,
    /// A stowed, station frame (m); A turns about the station origin A0.
    pub nut_pivot_stowed_st: Point2<f64>,
    /// Largest distance of a screw point from B0 (m): screw length plus radius.
    pub max_reach_m: f64,
    /// Smallest |A - B0| over the deployment (m): s34,i for the thesis track.
    pub min_extension_m: f64,
}

impl ScrewAboutMount {
    fn screw_angle(&self, t: f64) -> f64 {
        let (s, c) = t.sin_cos();
        let a = self.nut_pivot_stowed_st;
        let rotated = Point2::new(c * a.x - s * a.y, s * a.x + c * a.y);
        let d = rotated - self.mount_st;
        d.y.atan2(d.x)
    }
}

impl Motion for ScrewAboutMount {
    fn pose_ac(&self, t: f64) -> Isometry3<f64> {
        let turn = self.screw_angle(t) - self.screw_angle(0.0);
        let b0 = Vector3::new(self.mount_st.x, self.mount_st.y, 0.0);
        let in_station = Translation3::from(b0)
            * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), turn)
            * Translation3::from(-b0);
        self.aircraft_from_station * in_station * self.aircraft_from_station.inverse()
    }

    fn speed_bound(&self) -> f64 {
        // |A| = a2: the nut pivot's speed per radian.
        let crank = self.nut_pivot_stowed_st.coords.norm();
        self.max_reach_m * crank / self.min_extension_m
    }
}
