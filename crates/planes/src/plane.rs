//! Lines and planes in the aircraft frame: the flap hinge axis and flap side planes.

use nalgebra::{Point3, Unit, Vector3};

use crate::error::{finite, Error, Result};
use crate::frame::DIRECTION_TOL;

/// Smallest accepted |cos| between the hinge axis and a plane normal it must cross.
pub const AXIS_PLANE_COSINE_TOL: f64 = 1e-6;

/// Builds a unit vector from `vector`, or [`Error::ZeroLengthDirection`] / [`Error::NotFinite`].
pub fn unit_direction(quantity: &'static str, vector: Vector3<f64>) -> Result<Unit<Vector3<f64>>> {
    let norm = finite(quantity, vector.norm())?;
    if norm < DIRECTION_TOL {
        return Err(Error::ZeroLengthDirection {
            quantity,
            norm,
            limit: DIRECTION_TOL,
        });
    }
    Ok(Unit::new_unchecked(vector / norm))
}

/// The flap rotation axis (hinge line) in the aircraft frame: a point on it (m) and its
/// direction, oriented outboard (aircraft +y component non-negative).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HingeAxis {
    /// A point on the axis, aircraft frame, metres.
    pub point_ac: Point3<f64>,
    /// Unit direction, aircraft frame, pointing outboard.
    pub direction_ac: Unit<Vector3<f64>>,
}

impl HingeAxis {
    /// Axis through `point_ac` along `direction_ac` (any length; flipped to point outboard).
    pub fn try_new(point_ac: Point3<f64>, direction_ac: Vector3<f64>) -> Result<Self> {
        for (quantity, value) in [
            ("hinge point x", point_ac.x),
            ("hinge point y", point_ac.y),
            ("hinge point z", point_ac.z),
        ] {
            finite(quantity, value)?;
        }
        let mut direction = unit_direction("hinge axis", direction_ac)?;
        if direction.y < 0.0 {
            direction = -direction;
        }
        Ok(Self {
            point_ac,
            direction_ac: direction,
        })
    }

    /// Axis through two points (aircraft frame, m), e.g. the forward attachment points.
    pub fn try_through(first_ac: Point3<f64>, second_ac: Point3<f64>) -> Result<Self> {
        Self::try_new(first_ac, second_ac - first_ac)
    }

    /// The point at signed distance `distance_m` from `point_ac` along the axis (outboard +).
    pub fn point_at(&self, distance_m: f64) -> Point3<f64> {
        self.point_ac + self.direction_ac.into_inner() * distance_m
    }
}

/// A plane in the aircraft frame: a point on it (m) and its unit normal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plane {
    /// A point on the plane, aircraft frame, metres.
    pub point_ac: Point3<f64>,
    /// Unit normal, aircraft frame.
    pub normal_ac: Unit<Vector3<f64>>,
}

impl Plane {
    /// Plane through `point_ac` with normal along `normal_ac` (any length).
    pub fn try_new(point_ac: Point3<f64>, normal_ac: Vector3<f64>) -> Result<Self> {
        Ok(Self {
            point_ac,
            normal_ac: unit_direction("plane normal", normal_ac)?,
        })
    }

    /// Signed distance (m) of `point_ac` from the plane, along its normal.
    pub fn signed_distance_m(&self, point_ac: &Point3<f64>) -> f64 {
        self.normal_ac.dot(&(point_ac - self.point_ac))
    }

    /// Where `axis` crosses this plane (thesis `000` Ch. 4 step 1: point P).
    /// Errors when the axis is within [`AXIS_PLANE_COSINE_TOL`] of parallel to the plane.
    pub fn intersect_axis(&self, axis: &HingeAxis, plane: &'static str) -> Result<Point3<f64>> {
        let cosine = self.normal_ac.dot(&axis.direction_ac);
        if cosine.abs() < AXIS_PLANE_COSINE_TOL {
            return Err(Error::AxisParallelToPlane {
                plane,
                cosine: cosine.abs(),
                limit: AXIS_PLANE_COSINE_TOL,
            });
        }
        let distance_m = -self.signed_distance_m(&axis.point_ac) / cosine;
        Ok(axis.point_at(distance_m))
    }
}
