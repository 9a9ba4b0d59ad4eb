//! Station frames: the rigid transform between the aircraft frame and a mechanism plane.
//!
//! Thesis `000`, Chapter 4 step 2: origin A0 on the flap rotation axis, z along the axis
//! (here: along the plane normal, which is the axis for perpendicular planes), x in the
//! plane perpendicular to gravity (aircraft -z) towards the nose (aircraft -x), y completing
//! a right-handed frame (up-ish).

use nalgebra::{Isometry3, Matrix3, Point2, Point3, Rotation3, Translation3, Unit, UnitQuaternion, Vector2, Vector3};

use crate::error::{finite, Error, Result};

/// Smallest accepted length of a direction before it is normalised (dimensionless or m).
pub const DIRECTION_TOL: f64 = 1e-12;

/// Smallest accepted sine between a plane normal and the vertical (aircraft z); below it
/// the station x axis (perpendicular to gravity) is undefined.
pub const VERTICAL_SINE_TOL: f64 = 1e-9;

/// A point given in a station frame: its in-plane coordinates and its signed distance
/// from the plane along the station z axis (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StationPoint {
    /// In-plane coordinates (station x, y), metres.
    pub in_plane_m: Point2<f64>,
    /// Signed distance from the plane along station z (outboard positive), metres.
    pub normal_offset_m: f64,
}

/// Frame of one mechanism plane (station frame), as a rigid transform from station to
/// aircraft coordinates (`aircraft_from_station * p_station = p_aircraft`).
///
/// Invariants: rotation orthonormal and right-handed; x axis perpendicular to aircraft z
/// with a non-positive aircraft-x component (towards the nose); z axis with a
/// non-negative aircraft-y component (outboard).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StationFrame {
    aircraft_from_station: Isometry3<f64>,
    /// The axes exactly as constructed (columns of the rotation), aircraft frame; the
    /// quaternion in `aircraft_from_station` reproduces them to rounding (~1e-16).
    axes_ac: [Vector3<f64>; 3],
}

impl StationFrame {
    /// Frame of the plane through `origin_ac` with normal `normal_ac` (aircraft frame, m).
    ///
    /// The normal becomes the station z axis, flipped if needed to point outboard
    /// (aircraft +y); x = normalize(e_z x z) flipped to point towards the nose; y = z x x.
    /// Errors: non-finite input, or a normal within [`VERTICAL_SINE_TOL`] of vertical.
    pub fn try_from_origin_and_normal(origin_ac: Point3<f64>, normal_ac: &Unit<Vector3<f64>>) -> Result<Self> {
        for (quantity, value) in [
            ("station origin x", origin_ac.x),
            ("station origin y", origin_ac.y),
            ("station origin z", origin_ac.z),
            ("plane normal x", normal_ac.x),
            ("plane normal y", normal_ac.y),
            ("plane normal z", normal_ac.z),
        ] {
            finite(quantity, value)?;
        }
        let mut z_axis = normal_ac.into_inner();
        if z_axis.y < 0.0 {
            z_axis = -z_axis;
        }
        let horizontal = Vector3::z().cross(&z_axis);
        let sine = horizontal.norm();
        if sine < VERTICAL_SINE_TOL {
            return Err(Error::NormalAlongGravity {
                normal_ac: [z_axis.x, z_axis.y, z_axis.z],
                sine_limit: VERTICAL_SINE_TOL,
            });
        }
        let mut x_axis = horizontal / sine;
        if x_axis.x > 0.0 || (x_axis.x == 0.0 && x_axis.y < 0.0) {
            x_axis = -x_axis;
        }
        // Re-orthogonalise z against x (x is exactly horizontal; z is unit to rounding).
        let y_axis = z_axis.cross(&x_axis).normalize();
        let z_axis = x_axis.cross(&y_axis);
        let rotation = Rotation3::from_matrix_unchecked(Matrix3::from_columns(&[x_axis, y_axis, z_axis]));
        Ok(Self {
            aircraft_from_station: Isometry3::from_parts(
                Translation3::from(origin_ac.coords),
                UnitQuaternion::from_rotation_matrix(&rotation),
            ),
            axes_ac: [x_axis, y_axis, z_axis],
        })
    }

    /// The rigid transform taking station coordinates to aircraft coordinates (m).
    pub fn aircraft_from_station(&self) -> &Isometry3<f64> {
        &self.aircraft_from_station
    }

    /// The rigid transform taking aircraft coordinates to station coordinates (m).
    pub fn station_from_aircraft(&self) -> Isometry3<f64> {
        self.aircraft_from_station.inverse()
    }

    /// Origin (A0) in the aircraft frame, metres.
    pub fn origin_ac(&self) -> Point3<f64> {
        Point3::from(self.aircraft_from_station.translation.vector)
    }

    /// Station x axis (in plane, horizontal, towards the nose) in the aircraft frame.
    pub fn x_axis_ac(&self) -> Unit<Vector3<f64>> {
        Unit::new_unchecked(self.axes_ac[0])
    }

    /// Station y axis (in plane, up-ish) in the aircraft frame.
    pub fn y_axis_ac(&self) -> Unit<Vector3<f64>> {
        Unit::new_unchecked(self.axes_ac[1])
    }

    /// Station z axis (plane normal, outboard) in the aircraft frame.
    pub fn z_axis_ac(&self) -> Unit<Vector3<f64>> {
        Unit::new_unchecked(self.axes_ac[2])
    }

    /// Coordinates in this station frame of a point given in the aircraft frame (m).
    /// Computed as dot products with the constructed axes, so a point exactly on the
    /// plane gets an offset of exactly 0 more often than through the quaternion.
    pub fn station_point_from_aircraft(&self, point_ac: &Point3<f64>) -> StationPoint {
        let d = point_ac - self.origin_ac();
        StationPoint {
            in_plane_m: Point2::new(self.axes_ac[0].dot(&d), self.axes_ac[1].dot(&d)),
            normal_offset_m: self.axes_ac[2].dot(&d),
        }
    }

    /// Aircraft-frame position of an in-plane point given in station coordinates (m).
    pub fn aircraft_point_from_station(&self, point_st: &Point2<f64>) -> Point3<f64> {
        self.aircraft_from_station
            .transform_point(&Point3::new(point_st.x, point_st.y, 0.0))
    }

    /// Aircraft-frame position of a station point (in-plane coordinates plus offset), m.
    pub fn aircraft_point_from_station_point(&self, point: &StationPoint) -> Point3<f64> {
        self.aircraft_from_station.transform_point(&Point3::new(
            point.in_plane_m.x,
            point.in_plane_m.y,
            point.normal_offset_m,
        ))
    }

    /// Aircraft-frame direction of an in-plane vector given in station coordinates.
    pub fn aircraft_vector_from_station(&self, vector_st: &Vector2<f64>) -> Vector3<f64> {
        self.aircraft_from_station.rotation * Vector3::new(vector_st.x, vector_st.y, 0.0)
    }

    /// Signed distance (m) of an aircraft-frame point from this plane, along station z.
    pub fn signed_distance_m(&self, point_ac: &Point3<f64>) -> f64 {
        self.z_axis_ac().dot(&(point_ac - self.origin_ac()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unswept_axis_gives_nose_and_up() {
        let frame = StationFrame::try_from_origin_and_normal(Point3::new(1.0, 2.0, 0.5), &Vector3::y_axis()).unwrap();
        assert!((frame.x_axis_ac().into_inner() - Vector3::new(-1.0, 0.0, 0.0)).norm() < 1e-15);
        assert!((frame.y_axis_ac().into_inner() - Vector3::new(0.0, 0.0, 1.0)).norm() < 1e-15);
        assert!((frame.z_axis_ac().into_inner() - Vector3::new(0.0, 1.0, 0.0)).norm() < 1e-15);
    }

    #[test]
    fn vertical_normal_is_rejected() {
        let err = StationFrame::try_from_origin_and_normal(Point3::origin(), &Vector3::z_axis()).unwrap_err();
        assert!(matches!(err, Error::NormalAlongGravity { .. }));
    }
}
