//! The hooked-track's motion in closed form, per metre of stroke s of the forward
//! carriage F along the straight rail (direction d, towards deployment).
//!
//! - **Lead-in** (0 <= s <= s1): the aft roller G runs in a straight lead-in parallel to the
//!   rail, so the flap translates by s d without turning (`003_...` Fig. 17: gap and
//!   overlap change before the flap deflects).
//! - **Hook** (s1 < s <= s_L): G runs on a circular arc of radius ρ about K, tangent to the
//!   lead-in at G1 = G + s1 d (K = G1 + ρ n, n = d turned +90 deg, ρ signed). With F(s) =
//!   F + s d on the rail and |G - F| = ℓ (the flap is rigid), G is an intersection of the
//!   circle about F(s) of radius ℓ with the hook: with e = K - F(s), D = |e|,
//!   a = (ℓ² - ρ² + D²) / (2 D), h = σ sqrt(ℓ² - a²), G = F(s) + (a e + h e⊥) / D, σ the
//!   branch through G1. The flap's displacement follows from F and G.
//!
//! Transmission: in the lead-in the flap's line F-G against the rail's normal,
//! sin μ = |d · (G - F)| / ℓ (two parallel slots hold the flap's rotation only while its line
//! is not square to them); on the hook the coupler F-G against the hook's radius K-G,
//! sin μ = |(G - F) x (G - K)| / (ℓ |ρ|), the same value at G1 (the arc is tangent to d).
//!
//! Rates per metre of stroke: F' = d; on the hook G' = g (G - K)⊥ with
//! g = d · (F - G) / ((G - K)⊥ · (F - G)) (from d/ds |F - G|² = 0), the flap's rotation
//! rate ω = (F - G) x (F' - G') / ℓ². At G1 g ρ = 1 in magnitude and ω = 0: the motion has
//! no velocity jump where the hook begins.

use nalgebra::{Isometry2, Point2, Translation2, Unit, Vector2};

use flapwright_mechanism::shared::feasibility::parameter_at_deflection;
use flapwright_mechanism::shared::geometry::cross;

/// The rail, the lead-in and the hook.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Rail {
    /// The carriage's pin F on the flap, stowed (m).
    pub(super) f: Point2<f64>,
    /// The roller's pin G on the flap, stowed (m).
    pub(super) g: Point2<f64>,
    /// The rail's direction, towards deployment.
    pub(super) d: Unit<Vector2<f64>>,
    /// Stroke of the lead-in s1 (m).
    pub(super) lead_m: f64,
    /// Stroke to landing s_L (m).
    pub(super) stroke_m: f64,
    /// The hook's centre K (m).
    pub(super) k: Point2<f64>,
    /// The hook's radius |ρ| (m).
    pub(super) radius_m: f64,
    /// |G - F| (m).
    pub(super) span: f64,
    /// The branch σ of the circle intersection through G1.
    branch: f64,
}

/// The rail at one stroke.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct RailPose {
    pub(super) f: Point2<f64>,
    pub(super) g: Point2<f64>,
    pub(super) flap: Isometry2<f64>,
    /// μ (rad).
    pub(super) transmission: f64,
    /// True on the hook (past the lead-in).
    pub(super) on_hook: bool,
}

impl Rail {
    /// The rail through F, G and their landing places `f_landing`, `g_landing` with a
    /// lead-in of `lead_m`; None where the flap's line lies along the rail's normal, the
    /// landing roller needs no hook (it lies on the lead-in's line), or the lead-in is not
    /// shorter than the stroke.
    pub(super) fn new(
        f: Point2<f64>,
        g: Point2<f64>,
        f_landing: Point2<f64>,
        g_landing: Point2<f64>,
        lead_m: f64,
    ) -> Option<Self> {
        let run = f_landing - f;
        let stroke_m = run.norm();
        let span = (g - f).norm();
        if !(stroke_m > 0.0 && span > 0.0 && lead_m >= 0.0 && lead_m < stroke_m) {
            return None;
        }
        let d = Unit::new_normalize(run);
        let n = Vector2::new(-d.y, d.x);
        let g1 = g + d.into_inner() * lead_m;
        let w = g_landing - g1;
        let across = w.dot(&n);
        if across.abs() <= 1e-9 * span {
            return None;
        }
        let rho = w.norm_squared() / (2.0 * across);
        let k = g1 + n * rho;
        let f1 = f + d.into_inner() * lead_m;
        let branch = cross(k - f1, g1 - f1).signum();
        let rail = Self {
            f,
            g,
            d,
            lead_m,
            stroke_m,
            k,
            radius_m: rho.abs(),
            span,
            branch,
        };
        (rail.d.dot(&(g - f)).abs() > 1e-9 * span && branch != 0.0).then_some(rail)
    }

    /// The rail's normal n (d turned +90 deg).
    pub(super) fn normal(&self) -> Vector2<f64> {
        Vector2::new(-self.d.y, self.d.x)
    }

    /// Where G is at stroke `s` on the hook; None where the flap cannot reach it.
    fn roller_on_hook(&self, f: Point2<f64>) -> Option<Point2<f64>> {
        let e = self.k - f;
        let distance = e.norm();
        if distance <= 0.0 {
            return None;
        }
        let along = (self.span * self.span - self.radius_m * self.radius_m + distance * distance) / (2.0 * distance);
        let h2 = self.span * self.span - along * along;
        if h2.is_nan() || h2 < 0.0 {
            return None;
        }
        let e_perp = Vector2::new(-e.y, e.x);
        Some(f + (e * along + e_perp * (self.branch * h2.sqrt())) / distance)
    }

    /// The rail at stroke `s` (m from stowed); None where the flap cannot reach the hook.
    pub(super) fn at(&self, s: f64) -> Option<RailPose> {
        let f = self.f + self.d.into_inner() * s;
        if s <= self.lead_m {
            let flap = Isometry2::from(Translation2::from(self.d.into_inner() * s));
            return Some(RailPose {
                f,
                g: self.g + self.d.into_inner() * s,
                flap,
                transmission: (self.d.dot(&(self.g - self.f)).abs() / self.span)
                    .clamp(0.0, 1.0)
                    .asin(),
                on_hook: false,
            });
        }
        let g = self.roller_on_hook(f)?;
        let (stowed, now) = (self.g - self.f, g - f);
        let rotation = Isometry2::rotation(cross(stowed, now).atan2(stowed.dot(&now)));
        let flap = Translation2::from(f.coords - (rotation * self.f).coords) * rotation;
        let sine = cross(g - f, g - self.k).abs() / (self.span * self.radius_m);
        Some(RailPose {
            f,
            g,
            flap,
            transmission: sine.clamp(0.0, 1.0).asin(),
            on_hook: true,
        })
    }

    /// The stroke on the hook where the flap has turned by `deflection_rad`, in closed
    /// form: the flap's line F-G then runs along u = R(θ) (G - F) (stowed), so the roller at
    /// F + s d + u lies on the hook where |w + s d|² = ρ² with w = F + u - K, a quadratic in
    /// s. The first root on the hook whose pose (on the rail's branch) has that deflection
    /// to 1e-9 rad; None where none has (the deflection lies outside the hook's range).
    pub(super) fn stroke_on_hook_at(&self, deflection_rad: f64) -> Option<f64> {
        let w = self.f + Isometry2::rotation(deflection_rad) * (self.g - self.f) - self.k;
        let b = self.d.dot(&w);
        let c = w.norm_squared() - self.radius_m * self.radius_m;
        let discriminant = b * b - c;
        if discriminant.is_nan() || discriminant < 0.0 {
            return None;
        }
        // The roots -b ± sqrt(b² - c), the smaller magnitude one as c / q (no cancellation).
        let q = -(b + b.signum() * discriminant.sqrt());
        let mut roots = [q, if q != 0.0 { c / q } else { q }];
        roots.sort_by(f64::total_cmp);
        roots.into_iter().find(|&s| {
            s > self.lead_m
                && s <= self.stroke_m
                && self.at(s).is_some_and(|pose| {
                    let turned = pose.flap.rotation.angle() - deflection_rad;
                    turned.sin().abs() < 1e-9 && turned.cos() > 0.0
                })
        })
    }

    /// The first stroke where the flap reaches `deflection_rad` (`sense`: the sign of the
    /// landing deflection), as the bisection of the sampled motion answers it: landing at or
    /// beyond the landing deflection, stowed at or short of the stowed one (0: the lead-in
    /// holds it; the hook is tangent to the lead-in there, so the quadratic's double root
    /// would land at the lead-in's end), between them [`Self::stroke_on_hook_at`], the
    /// bisection where that finds none.
    pub(super) fn stroke_at_deflection(&self, deflection_rad: f64, sense: f64) -> f64 {
        let deflection = |s: f64| self.at(s).map_or(f64::NAN, |p| p.flap.rotation.angle());
        if (deflection_rad - deflection(self.stroke_m)) * sense >= 0.0 {
            return self.stroke_m;
        }
        if deflection_rad * sense <= 0.0 {
            return 0.0;
        }
        self.stroke_on_hook_at(deflection_rad)
            .unwrap_or_else(|| parameter_at_deflection(self.stroke_m, deflection, deflection_rad, sense))
    }

    /// Velocity of G and the flap's rotation rate per metre of stroke at `pose` (F moves
    /// at d).
    pub(super) fn rates(&self, pose: &RailPose) -> (Vector2<f64>, f64) {
        if !pose.on_hook {
            return (self.d.into_inner(), 0.0);
        }
        let r = pose.f - pose.g;
        let radial = pose.g - self.k;
        let tangent = Vector2::new(-radial.y, radial.x);
        let v_g = tangent * (self.d.dot(&r) / tangent.dot(&r));
        let flap_rate = cross(r, self.d.into_inner() - v_g) / (self.span * self.span);
        (v_g, flap_rate)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use flapwright_mechanism::shared::feasibility::parameter_at_deflection;

    /// The closed form of the stroke at a deflection lands where the bisection of the
    /// sampled motion does, and the pose there has that deflection; outside the hook's
    /// range it answers none.
    #[test]
    fn the_stroke_at_a_deflection_in_closed_form_is_the_bisections() {
        let (f, g) = (Point2::new(0.0, 0.0), Point2::new(0.6, 0.05));
        let landing = Translation2::new(0.35, -0.2) * Isometry2::rotation(-35f64.to_radians());
        for lead in [0.0, 0.03, 0.1] {
            let rail = Rail::new(f, g, landing * f, landing * g, lead).expect("a rail");
            let deflection = |s: f64| rail.at(s).map_or(f64::NAN, |p| p.flap.rotation.angle());
            assert!((deflection(rail.stroke_m) + 35f64.to_radians()).abs() < 1e-9);
            for degrees in [-0.5, -10.0, -20.0, -34.9] {
                let target = f64::to_radians(degrees);
                let closed = rail.stroke_on_hook_at(target).expect("on the hook");
                let bisected = parameter_at_deflection(rail.stroke_m, deflection, target, -1.0);
                assert!((closed - bisected).abs() < 1e-12, "{closed} vs {bisected}");
                assert!((deflection(closed) - target).abs() < 1e-12);
            }
            assert_eq!(rail.stroke_on_hook_at(f64::to_radians(-40.0)), None);
            assert_eq!(rail.stroke_on_hook_at(f64::to_radians(5.0)), None);
        }
    }

    /// At the ends the stroke is the bisection's to the bit: stowed (0) at no deflection
    /// and short of it, landing beyond the landing deflection (at it, to rounding), on rails of several
    /// roller places and lead-ins (the quadratic's double root where the hook meets the
    /// lead-in falls a rounding either side of the lead-in's end).
    #[test]
    fn the_stroke_at_the_ends_is_the_bisections() {
        let landing = Translation2::new(0.35, -0.2) * Isometry2::rotation(-35f64.to_radians());
        let f = Point2::new(0.0, 0.0);
        let mut rails = 0;
        for k in 0..40 {
            let g = Point2::new(0.4 + 0.01 * k as f64, 0.05 - 0.003 * k as f64);
            for lead in [0.0, 0.013, 0.03, 0.071, 0.1] {
                let Some(rail) = Rail::new(f, g, landing * f, landing * g, lead) else {
                    continue;
                };
                rails += 1;
                let deflection = |s: f64| rail.at(s).map_or(f64::NAN, |p| p.flap.rotation.angle());
                for target in [0.0, 0.1, -40f64.to_radians()] {
                    let bisected = parameter_at_deflection(rail.stroke_m, deflection, target, -1.0);
                    assert_eq!(
                        rail.stroke_at_deflection(target, -1.0),
                        bisected,
                        "lead {lead}, {target}"
                    );
                }
                // At the landing deflection itself, landing to rounding.
                let at_landing = rail.stroke_at_deflection(-35f64.to_radians(), -1.0);
                assert!(
                    (at_landing - rail.stroke_m).abs() < 1e-12 * rail.stroke_m,
                    "{at_landing}"
                );
                let half = rail.stroke_at_deflection(-17.5f64.to_radians(), -1.0);
                assert!((deflection(half) + 17.5f64.to_radians()).abs() < 1e-12);
            }
        }
        assert!(rails > 100, "{rails} rails");
    }
}
