//! The link-track's loop in closed form: the forward link turned about its fixed pivot O
//! carries the flap's pivot A on a circle; the carriage point C of the flap runs on a
//! straight track through its stowed place along d. With ℓ = |C - A| (the flap is rigid),
//! C = C0 + λ d where λ solves |C0 + λ d - A|² = ℓ²:
//! λ = -b + σ sqrt(b² - c), b = d · (C0 - A), c = |C0 - A|² - ℓ², σ the stowed branch (λ = 0
//! at the stowed pose). The flap's displacement follows from A and C.
//!
//! Transmission: the track takes only forces square to it, so the loop locks where the
//! flap's line A-C stands square to the track; μ = asin(|d · (C - A)| / ℓ), π/2 best.
//!
//! Velocity per unit link rotation: A' = k x (A - O), λ' = (C - A) · A' / ((C - A) · d)
//! (from d/dφ |C - A|² = 0), the flap's rotation rate ω = (C - A) x (C' - A') / ℓ².

use nalgebra::{Isometry2, Point2, Translation2, Unit, Vector2};

use crate::rocker_drive::{cross, turn_about};

/// The link-track loop: the link's fixed and moving pivots, the carriage and its track.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Loop {
    /// The link's fixed pivot O (m).
    pub(super) o: Point2<f64>,
    /// The link's pivot on the flap A, stowed (m).
    pub(super) a: Point2<f64>,
    /// The carriage's pin on the flap C, stowed (m).
    pub(super) c: Point2<f64>,
    /// The track's direction, towards deployment.
    pub(super) d: Unit<Vector2<f64>>,
    /// |C - A| (m).
    pub(super) span: f64,
    /// The stowed branch σ = ±1.
    pub(super) branch: f64,
}

/// The loop at one link rotation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct LoopPose {
    pub(super) a: Point2<f64>,
    pub(super) c: Point2<f64>,
    /// Carriage travel along the track from stowed (m).
    pub(super) travel: f64,
    pub(super) flap: Isometry2<f64>,
    /// μ (rad).
    pub(super) transmission: f64,
}

impl Loop {
    /// The loop through the given points; None where the stowed flap line stands square
    /// to the track (a toggle at the start).
    pub(super) fn new(o: Point2<f64>, a: Point2<f64>, c: Point2<f64>, d: Unit<Vector2<f64>>) -> Option<Self> {
        let b = d.dot(&(c - a));
        let span = (c - a).norm();
        (b.abs() > 1e-9 * span && span > 0.0).then_some(Self {
            o,
            a,
            c,
            d,
            span,
            branch: b.signum(),
        })
    }

    /// The loop with the link turned by `phi` (rad, counter-clockwise); None where the flap
    /// cannot reach the track.
    pub(super) fn at(&self, phi: f64) -> Option<LoopPose> {
        let a = turn_about(self.o, phi) * self.a;
        let to_c = self.c - a;
        let b = self.d.dot(&to_c);
        let discriminant = b * b - (to_c.norm_squared() - self.span * self.span);
        if discriminant.is_nan() || discriminant < 0.0 {
            return None;
        }
        let root = discriminant.sqrt();
        let travel = -b + self.branch * root;
        let c = self.c + self.d.into_inner() * travel;
        let (stowed, now) = (self.c - self.a, c - a);
        let rotation = Isometry2::rotation(cross(stowed, now).atan2(stowed.dot(&now)));
        let flap = Translation2::from(a.coords - (rotation * self.a).coords) * rotation;
        Some(LoopPose {
            a,
            c,
            travel,
            flap,
            transmission: (root / self.span).clamp(0.0, 1.0).asin(),
        })
    }

    /// Velocity of A, the carriage's rate along the track and the flap's rotation rate,
    /// per unit link rotation, at `pose`.
    pub(super) fn rates(&self, pose: &LoopPose) -> (Vector2<f64>, f64, f64) {
        let r = pose.a - self.o;
        let v_a = Vector2::new(-r.y, r.x);
        let line = pose.c - pose.a;
        let travel_rate = line.dot(&v_a) / line.dot(&self.d);
        let v_c = self.d.into_inner() * travel_rate;
        let flap_rate = cross(line, v_c - v_a) / (self.span * self.span);
        (v_a, travel_rate, flap_rate)
    }
}
