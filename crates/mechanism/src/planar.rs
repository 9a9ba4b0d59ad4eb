//! A general planar mechanism: rigid bodies, lower-pair and slot joints, one driver.
//!
//! Coordinates: each moving body k >= 1 has (x_k, y_k, φ_k) in the station frame (m, m,
//! rad); body 0 is the ground and never moves. A point fixed on body k at local offset p
//! sits at P = r_k + R(φ_k) p. Constraint equations Φ(q, t) = 0 (one per scalar condition)
//! are stated below with their Jacobian rows ∂Φ/∂q and their acceleration right-hand sides
//! γ = -(d/dt(Φ_q) q̇) - Φ_tt, all analytic (Haug, *Computer Aided Kinematics and Dynamics
//! of Mechanical Systems*, 1989, ch. 3).

use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

/// Index of a body in [`PlanarModel::bodies`]; 0 is the ground.
pub type BodyIndex = usize;

/// A point fixed on a body.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct BodyPoint {
    /// Body carrying the point.
    pub body: BodyIndex,
    /// Offset in the body frame (m).
    pub local_m: Vector2<f64>,
}

/// A joint between two bodies.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Joint {
    /// Revolute: the two points coincide (2 equations: P_a - P_b = 0).
    Revolute {
        /// Joint name (for reports).
        name: String,
        /// Point on the first body.
        a: BodyPoint,
        /// Point on the second body.
        b: BodyPoint,
    },
    /// Prismatic: no relative rotation, and point `b` stays on the line through `a` along
    /// `axis_local` of body a (2 equations: φ_a - φ_b - φ0 = 0, n_a · (P_b - P_a) = 0).
    Prismatic {
        /// Joint name.
        name: String,
        /// Point on the guide body (a point of the line).
        a: BodyPoint,
        /// Line direction in body a's frame (unit not required).
        axis_local: Vector2<f64>,
        /// Point on the sliding body.
        b: BodyPoint,
        /// φ_a - φ_b in the assembled mechanism (rad).
        angle_offset_rad: f64,
    },
    /// Pin on one body in a circular slot of another (1 equation: ½(|P - C|² - ρ²) = 0).
    PinInCircularSlot {
        /// Joint name.
        name: String,
        /// The pin.
        pin: BodyPoint,
        /// The slot's centre, on the slot body.
        centre: BodyPoint,
        /// Slot radius ρ (m).
        radius_m: f64,
    },
    /// Pin on one body in a straight slot of another (1 equation: n · (P - Q) = 0).
    PinInStraightSlot {
        /// Joint name.
        name: String,
        /// The pin.
        pin: BodyPoint,
        /// A point of the slot's centre line, on the slot body.
        slot_point: BodyPoint,
        /// Slot direction in the slot body's frame.
        axis_local: Vector2<f64>,
    },
}

impl Joint {
    /// Number of scalar equations the joint contributes.
    pub fn equation_count(&self) -> usize {
        match self {
            Self::Revolute { .. } | Self::Prismatic { .. } => 2,
            Self::PinInCircularSlot { .. } | Self::PinInStraightSlot { .. } => 1,
        }
    }

    /// The joint's name.
    pub fn name(&self) -> &str {
        match self {
            Self::Revolute { name, .. }
            | Self::Prismatic { name, .. }
            | Self::PinInCircularSlot { name, .. }
            | Self::PinInStraightSlot { name, .. } => name,
        }
    }
}

/// The single input.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Driver {
    /// Linear stroke: the distance |P_a - P_b| equals the input (m), e.g. a jack between
    /// its two pivots. Equation ½(|P_a - P_b|² - s²) = 0.
    Distance {
        /// First end.
        a: BodyPoint,
        /// Second end.
        b: BodyPoint,
    },
    /// Crank angle: φ_a - φ_b - offset equals the input (rad).
    RelativeAngle {
        /// Driven body.
        a: BodyPoint,
        /// Reference body.
        b: BodyPoint,
        /// Angle offset (rad).
        offset_rad: f64,
    },
}

/// A planar mechanism with one degree of freedom.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlanarModel {
    /// Body names; index 0 is the ground.
    pub bodies: Vec<String>,
    /// Joints.
    pub joints: Vec<Joint>,
    /// The input.
    pub driver: Driver,
}

/// Positions and velocities of the body frames needed to evaluate one constraint.
pub(crate) struct Frames<'a> {
    pub coordinates: &'a [f64],
    pub rates: &'a [f64],
}

impl Frames<'_> {
    /// (origin, angle) of body `body` (ground: zero).
    fn frame(&self, body: BodyIndex) -> (Vector2<f64>, f64, f64) {
        if body == 0 {
            return (Vector2::zeros(), 0.0, 0.0);
        }
        let i = 3 * (body - 1);
        (
            Vector2::new(self.coordinates[i], self.coordinates[i + 1]),
            self.coordinates[i + 2],
            self.rates.get(i + 2).copied().unwrap_or(0.0),
        )
    }

    /// Rotated offset R(φ) p, position P and angular rate of a body point.
    pub fn point(&self, point: &BodyPoint) -> (Vector2<f64>, Vector2<f64>, f64) {
        let (origin, angle, rate) = self.frame(point.body);
        let (s, c) = angle.sin_cos();
        let rotated = Vector2::new(
            c * point.local_m.x - s * point.local_m.y,
            s * point.local_m.x + c * point.local_m.y,
        );
        (rotated, origin + rotated, rate)
    }

    /// Velocity of a body point from the rates.
    pub fn velocity(&self, point: &BodyPoint) -> Vector2<f64> {
        if point.body == 0 {
            return Vector2::zeros();
        }
        let i = 3 * (point.body - 1);
        let (rotated, _, rate) = self.point(point);
        Vector2::new(self.rates[i], self.rates[i + 1]) + perp(rotated) * rate
    }

    /// Rotate a body-frame direction into the station frame.
    pub fn direction(&self, body: BodyIndex, local: Vector2<f64>) -> Vector2<f64> {
        let (_, angle, _) = self.frame(body);
        let (s, c) = angle.sin_cos();
        Vector2::new(c * local.x - s * local.y, s * local.x + c * local.y)
    }
}

/// k × v for the unit normal k: (-v.y, v.x).
pub(crate) fn perp(v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-v.y, v.x)
}
