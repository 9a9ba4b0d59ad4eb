//! The four-bar loop in closed form: the crank turned about O1, the rocker's pivot A2 on
//! the stowed branch of the circles (A1, |A1 A2|) and (O2, |O2 A2|) (one RRR dyad), the
//! flap's displacement from A1 and A2, and the rates of the loop's velocity analysis.

use nalgebra::{Isometry2, Point2, Translation2, Vector2};

use crate::rocker_drive::{cross, turn_about};

/// The four-bar loop: fixed pivots, stowed moving pivots, the branch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Loop {
    pub(super) o1: Point2<f64>,
    pub(super) o2: Point2<f64>,
    pub(super) a1: Point2<f64>,
    pub(super) a2: Point2<f64>,
    pub(super) coupler: f64,
    pub(super) rocker: f64,
    pub(super) branch: f64,
}

/// The loop at one crank angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct LoopPose {
    pub(super) a1: Point2<f64>,
    pub(super) a2: Point2<f64>,
    pub(super) flap: Isometry2<f64>,
    /// Acute angle between coupler and rocker (rad).
    pub(super) transmission: f64,
}

impl Loop {
    pub(super) fn new(o1: Point2<f64>, o2: Point2<f64>, a1: Point2<f64>, a2: Point2<f64>) -> Self {
        Self {
            o1,
            o2,
            a1,
            a2,
            coupler: (a2 - a1).norm(),
            rocker: (a2 - o2).norm(),
            branch: cross(o2 - a1, a2 - a1).signum(),
        }
    }

    /// The loop with the crank turned by `phi` (closed form: one RRR dyad).
    pub(super) fn at(&self, phi: f64) -> Option<LoopPose> {
        let a1 = turn_about(self.o1, phi) * self.a1;
        let to_o2 = self.o2 - a1;
        let d = to_o2.norm();
        if d.is_nan() || d <= 0.0 {
            return None;
        }
        let e = to_o2 / d;
        let along = (self.coupler * self.coupler - self.rocker * self.rocker + d * d) / (2.0 * d);
        let h2 = self.coupler * self.coupler - along * along;
        if h2.is_nan() || h2 < 0.0 {
            return None;
        }
        // The point on the stowed branch: cross(e, perp) = 1 with perp = (-e.y, e.x), so
        // cross(o2 - a1, a2 - a1) = d branch h has the branch's sign.
        let perp = Vector2::new(-e.y, e.x);
        let a2 = a1 + e * along + perp * (self.branch * h2.sqrt());
        let stowed = self.a2 - self.a1;
        let now = a2 - a1;
        let angle = cross(stowed, now).atan2(stowed.dot(&now));
        let rotation = Isometry2::rotation(angle);
        let flap = Translation2::from(a1.coords - (rotation * self.a1).coords) * rotation;
        let sine = cross(now, a2 - self.o2).abs() / (self.coupler * self.rocker);
        Some(LoopPose {
            a1,
            a2,
            flap,
            transmission: sine.clamp(0.0, 1.0).asin(),
        })
    }

    /// Rocker and flap rotation rates per unit crank rate at `pose` (velocity analysis).
    pub(super) fn rates(&self, pose: &LoopPose) -> (f64, f64) {
        let r1 = pose.a1 - self.o1;
        let v1 = Vector2::new(-r1.y, r1.x);
        let (r2, c) = (pose.a2 - self.o2, pose.a2 - pose.a1);
        // ω_r k x r2 - ω_f k x c = v1; dotted with c and with r2 (k x a · a = 0):
        // ω_r (k x r2) · c = v1 · c and -ω_f (k x c) · r2 = v1 · r2, (k x c) · r2 = c x r2.
        let det = cross(c, r2);
        let rocker = -c.dot(&v1) / det;
        let flap = -r2.dot(&v1) / det;
        (rocker, flap)
    }
}
