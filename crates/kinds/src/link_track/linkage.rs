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

use flapwright_mechanism::shared::geometry::{cross, turn_about};

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

    /// A certified bound on |ω|, the flap's rotation rate per unit link rotation, for every
    /// link turn between 0 and `travel` (rad), given `certified_mu`, a certified lower bound
    /// on the transmission angle there (rad, > 0); `None` where the loop cannot be posed at a
    /// sample.
    ///
    /// With u = (C - A) / ℓ, C' = d λ' and λ' = u · A' / (u · d), the rate is
    /// ω = u x (C' - A') / ℓ = |A'| sin∠(A', d) / (ℓ (u · d)), and |u · d| = sin μ. The bound
    /// from μ alone, |A'| (1 + 1 / sin μ) / ℓ, takes the sine as 1 and adds |A'| / ℓ. Here the
    /// deployment is cut into `intervals` pieces of width h; on each, |sin∠(A', d)| is at most
    /// its larger end value plus h / 2 (A' turns with the link, d is fixed) and sin μ at least
    /// its smaller end value less W h / 2 (u turns with the flap, at most at W, the bound from
    /// μ alone, which also caps the result); sine and cosine are 1-Lipschitz.
    pub(super) fn flap_rate_bound(&self, travel: f64, certified_mu: f64, intervals: usize) -> Option<f64> {
        let arm = (self.a - self.o).norm();
        let sine_floor = certified_mu.sin();
        let global = arm * (1.0 + 1.0 / sine_floor) / self.span;
        if !(sine_floor > 0.0 && global.is_finite()) {
            return None;
        }
        let intervals = intervals.max(1);
        let h = travel.abs() / intervals as f64;
        let d = self.d.into_inner();
        // |sin∠(A', d)| and sin μ at link turn `phi`.
        let shape = |phi: f64| -> Option<(f64, f64)> {
            let pose = self.at(phi)?;
            let r = pose.a - self.o;
            let direction = Vector2::new(-r.y, r.x) / arm;
            let u = (pose.c - pose.a) / self.span;
            Some((cross(direction, d).abs(), u.dot(&d).abs()))
        };
        let mut ends = shape(0.0)?;
        let mut bound: f64 = 0.0;
        for k in 1..=intervals {
            let next = shape(travel * k as f64 / intervals as f64)?;
            let turn = (ends.0.max(next.0) + h / 2.0).min(1.0);
            let sine = (ends.1.min(next.1) - global * h / 2.0).max(sine_floor);
            bound = bound.max(arm * turn / (self.span * sine));
            ends = next;
        }
        Some(bound.min(global))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The transport scene's link-track at `ob-outer` (study of that station), rounded.
    fn transport_loop() -> Loop {
        Loop::new(
            Point2::new(0.4192, -0.1744),
            Point2::new(0.3169, -0.1470),
            Point2::new(0.0110, 0.0253),
            Unit::new_normalize(Vector2::new(0.6428, -0.7660)),
        )
        .unwrap()
    }

    #[test]
    fn the_flap_rate_bound_holds_at_every_link_turn_and_beats_the_transmission_angle_alone() {
        let loop_ = transport_loop();
        let travel = -2.083;
        let mut mu_min = f64::INFINITY;
        let mut fastest: f64 = 0.0;
        for k in 0..=20_000 {
            let pose = loop_.at(travel * k as f64 / 20_000.0).unwrap();
            mu_min = mu_min.min(pose.transmission);
            fastest = fastest.max(loop_.rates(&pose).2.abs());
        }
        let certified = 0.9 * mu_min;
        let bound = loop_.flap_rate_bound(travel, certified, 256).unwrap();
        assert!(bound >= fastest, "{bound} against the fastest {fastest}");
        let arm = (loop_.a - loop_.o).norm();
        let from_mu = arm * (1.0 + 1.0 / certified.sin()) / loop_.span;
        assert!(bound < 0.6 * from_mu, "{bound} against {from_mu}");
        assert!(bound < 1.5 * fastest, "{bound} against the fastest {fastest}");
        // Without a certified transmission angle there is no bound.
        assert!(loop_.flap_rate_bound(travel, 0.0, 16).is_none());
    }
}
