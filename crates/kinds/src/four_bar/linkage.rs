//! The four-bar loop in closed form: the crank turned about O1, the rocker's pivot A2 on
//! the stowed branch of the circles (A1, |A1 A2|) and (O2, |O2 A2|) (one RRR dyad), the
//! flap's displacement from A1 and A2, and the rates of the loop's velocity analysis.

use nalgebra::{Isometry2, Point2, Translation2, Vector2};

use flapwright_mechanism::shared::geometry::{cross, turn_about};

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

    /// Certified bounds on |ω_r| and |ω_f|, the rocker's and the flap's rotation rates per
    /// unit crank rate, for every crank turn between 0 and `travel` (rad), given
    /// `certified_mu`, a certified lower bound on the transmission angle there (rad, > 0);
    /// `None` where the loop cannot be posed at a sample.
    ///
    /// The velocity analysis gives |ω_r| = |r1| |cos∠(c, v1)| / (|r2| sin μ) and
    /// |ω_f| = |r1| |cos∠(r2, v1)| / (|c| sin μ) (v1 = k x r1 the crank pin's velocity per unit
    /// crank rate). The bound from μ alone takes both cosines as 1; where the crank and
    /// rocker stay nearly parallel (a short bracket between pivots close together) that is
    /// ten times the flap's real rate, and every sweep of the flap against the wing pays for
    /// it in distance evaluations. Here the deployment is cut into `intervals` pieces of width
    /// h; on each, the cosines are at most their larger end value plus (1 + W) h / 2 and
    /// sin μ at least its smaller end value less (W_r + W_f) h / 2, since those angles turn
    /// no faster than the crank plus the other link (1 + W_f or 1 + W_r) or the two links
    /// together, and cosine and sine are 1-Lipschitz; W_r, W_f are the bounds from
    /// `certified_mu` alone, which also cap the result.
    pub(super) fn rate_bounds(&self, travel: f64, certified_mu: f64, intervals: usize) -> Option<(f64, f64)> {
        let crank_arm = (self.a1 - self.o1).norm();
        let sine_floor = certified_mu.sin();
        let global = (
            crank_arm / (self.rocker * sine_floor),
            crank_arm / (self.coupler * sine_floor),
        );
        if !(sine_floor > 0.0 && global.0.is_finite() && global.1.is_finite()) {
            return None;
        }
        let intervals = intervals.max(1);
        let h = travel.abs() / intervals as f64;
        // |cos∠(c, v1)|, |cos∠(r2, v1)| and sin μ at crank turn `phi`.
        let shape = |phi: f64| -> Option<(f64, f64, f64)> {
            let pose = self.at(phi)?;
            let r1 = pose.a1 - self.o1;
            let v1 = Vector2::new(-r1.y, r1.x) / crank_arm;
            let (r2, c) = ((pose.a2 - self.o2) / self.rocker, (pose.a2 - pose.a1) / self.coupler);
            Some((c.dot(&v1).abs(), r2.dot(&v1).abs(), cross(c, r2).abs()))
        };
        let mut ends = shape(0.0)?;
        let mut bound: (f64, f64) = (0.0, 0.0);
        for k in 1..=intervals {
            let next = shape(travel * k as f64 / intervals as f64)?;
            let rocker_cos = (ends.0.max(next.0) + (1.0 + global.1) * h / 2.0).min(1.0);
            let flap_cos = (ends.1.max(next.1) + (1.0 + global.0) * h / 2.0).min(1.0);
            let sine = (ends.2.min(next.2) - (global.0 + global.1) * h / 2.0).max(sine_floor);
            bound.0 = bound.0.max(crank_arm * rocker_cos / (self.rocker * sine));
            bound.1 = bound.1.max(crank_arm * flap_cos / (self.coupler * sine));
            ends = next;
        }
        Some((bound.0.min(global.0), bound.1.min(global.1)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A loop whose crank and rocker stay nearly parallel (the transport scene's four-bar at
    /// `ob-outer`, rounded): the flap turns about as fast as the crank, far below the bound
    /// from the transmission angle alone.
    fn parallel_loop() -> Loop {
        Loop::new(
            Point2::new(-0.0733, 0.1117),
            Point2::new(-0.1221, 0.1673),
            Point2::new(-0.7876, 0.3757),
            Point2::new(-0.5923, 0.4709),
        )
    }

    #[test]
    fn rate_bounds_hold_at_every_crank_turn_and_beat_the_transmission_angle_alone() {
        let loop_ = parallel_loop();
        let travel = 0.611;
        let mut mu_min = f64::INFINITY;
        let mut fastest: (f64, f64) = (0.0, 0.0);
        for k in 0..=20_000 {
            let pose = loop_.at(travel * k as f64 / 20_000.0).unwrap();
            mu_min = mu_min.min(pose.transmission);
            let (rocker, flap) = loop_.rates(&pose);
            fastest = (fastest.0.max(rocker.abs()), fastest.1.max(flap.abs()));
        }
        let certified = 0.9 * mu_min;
        let (rocker, flap) = loop_.rate_bounds(travel, certified, 256).unwrap();
        assert!(
            rocker >= fastest.0 && flap >= fastest.1,
            "{rocker} {flap} against {fastest:?}"
        );
        let crank_arm = (loop_.a1 - loop_.o1).norm();
        let flap_from_mu = crank_arm / (loop_.coupler * certified.sin());
        assert!(flap < 0.3 * flap_from_mu, "{flap} against {flap_from_mu}");
        assert!(flap < 1.5 * fastest.1, "{flap} against the fastest {}", fastest.1);
        // A turn the loop cannot make has no bound.
        assert!(loop_.rate_bounds(10.0, certified, 16).is_none());
    }
}
