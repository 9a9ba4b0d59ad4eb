//! Synthesis of the inverted slider-crank by the landing-gear method of Yastrebov &
//! Polyushkova (1982, doc 004, "Analytical study of the aircraft landing-gear linkage").
//!
//! Doc 004's notation mapped onto the thesis frame ([`crate::InvertedSliderCrank`]):
//! O2 (leg pivot) = A0, O1 (cylinder pivot) = B0, l_{O1O2} = a1, l3 = l_{O2A} = a2 (crank),
//! l2 = l_{O1A} = s34 (rod length, the input), θ (leg rotation) = β3, φ3 = α0 + θ12 and
//! φ2 = α0 + θ13 + π (the rod vector points from A to O1). The pressure angle is the angle
//! between the rod force and the velocity of A: π/2 - μ with μ the transmission angle.

use std::f64::consts::{FRAC_PI_2, PI};

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::shared::angle::guarded_acos;
use crate::shared::slider_crank::InvertedSliderCrank;

/// Bisection stops when the bracket is narrower than this (rad).
const BISECTION_TOLERANCE_RAD: f64 = 1e-15;

/// Inputs of the landing-gear method (doc 004, "Исходные данные").
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LandingGearSpec {
    /// l_{O1O2} = a1 (m), eq. 3.
    pub pivot_distance_m: f64,
    /// l3 = l_{O2A} = a2 (m): crank on the leg. Must be shorter than the pivot distance.
    pub crank_length_m: f64,
    /// θ (rad): leg (flap) rotation between the end positions, in (0, π).
    pub rotation_rad: f64,
    /// t_ys (s): retraction time; the rod speed is H / t_ys (eq. 1).
    pub stroke_time_s: f64,
}

/// Result of the landing-gear synthesis (doc 004 eqs. 1-8).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LandingGearSynthesis {
    /// μ = acos(l3 / l_{O1O2}) (rad), eq. 4: crank angle ∠B0 A0 A at which the rod is
    /// tangent to A's circle (pressure angle zero).
    pub tangent_crank_angle_rad: f64,
    /// Crank angle ∠B0 A0 A at the first end position, μ - θ/2 (rad). Its absolute
    /// direction α0 + (μ - θ/2) is the installation angle; doc 004 eq. 5 writes the same
    /// as ψ = 180° + μ - (β0 + θ/2) relative to the leg axis.
    pub start_crank_angle_rad: f64,
    /// Crank angle at the second end position, μ + θ/2 (rad).
    pub end_crank_angle_rad: f64,
    /// l20 (m), eq. 7: rod length at the first end.
    pub start_input_m: f64,
    /// l2n (m), eq. 8: rod length at the second end.
    pub end_input_m: f64,
    /// H = l2n - l20 (m), eq. 6.
    pub stroke_m: f64,
    /// V = H / t_ys (m/s), eq. 1.
    pub rod_speed_mps: f64,
    /// Exact pressure angle at the first end (rad).
    pub start_pressure_angle_rad: f64,
    /// Exact pressure angle at the second end (rad).
    pub end_pressure_angle_rad: f64,
}

/// Angular-velocity and angular-acceleration analogues (derivatives with respect to the
/// rod length l2), doc 004 eqs. 20, 21, 24, 25. Units rad/m and rad/m².
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Analogues {
    /// (ω3)_l2 = dφ3/dl2 = 1 / (l3 sin(φ3 - φ2)) (eq. 20): crank (leg).
    pub crank_rate_per_input_radpm: f64,
    /// (ω2)_l2 = dφ2/dl2 = -l3 (ω3)_l2 cos(φ3 - φ2) / l2 (eq. 21): rod.
    pub rod_rate_per_input_radpm: f64,
    /// (ε3)_l2 = -[l2 (ω2)² + l3 (ω3)² cos(φ3 - φ2)] / (l3 sin(φ3 - φ2)) (eq. 24 with the
    /// minus sign of the Fortran listing; the printed eq. 24 drops it).
    pub crank_accel_per_input_radpm2: f64,
    /// (ε2)_l2 = [l3 (ω3)² sin(φ3 - φ2) - l3 (ε3) cos(φ3 - φ2) - 2 (ω2)] / l2 (eq. 25).
    pub rod_accel_per_input_radpm2: f64,
}

impl LandingGearSpec {
    fn validate(&self) -> Result<()> {
        for (name, value) in [
            ("pivot_distance_m", self.pivot_distance_m),
            ("crank_length_m", self.crank_length_m),
            ("stroke_time_s", self.stroke_time_s),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(Error::InvalidDimension { name, value });
            }
        }
        if !(self.rotation_rad > 0.0 && self.rotation_rad < PI) {
            return Err(Error::ParameterOutOfRange {
                name: "rotation_rad",
                value: self.rotation_rad,
                min: 0.0,
                max: PI,
            });
        }
        if self.crank_length_m >= self.pivot_distance_m {
            return Err(Error::ParameterOutOfRange {
                name: "crank_length_m",
                value: self.crank_length_m,
                min: 0.0,
                max: self.pivot_distance_m,
            });
        }
        Ok(())
    }

    fn linkage(&self) -> Result<InvertedSliderCrank> {
        InvertedSliderCrank::try_new(self.pivot_distance_m, self.crank_length_m, 0.0)
    }

    /// Doc 004's closed-form synthesis: end positions symmetric (±θ/2) about the tangent
    /// position, which makes the pressure angles small and nearly equal (exactly equal,
    /// θ/2, as l_{O1O2}/l3 → ∞).
    ///
    /// Errors: [`Error::InvalidDimension`], [`Error::ParameterOutOfRange`] (θ outside
    /// (0, π), l3 >= l_{O1O2}, or an end position beyond a toggle).
    pub fn synthesise(&self) -> Result<LandingGearSynthesis> {
        self.validate()?;
        let mu = guarded_acos(self.crank_length_m / self.pivot_distance_m, "tangent_crank_angle")?;
        self.synthesis_from_start(mu, mu - 0.5 * self.rotation_rad)
    }

    /// The variant that makes the two end pressure angles exactly equal (and opposite):
    /// the first-end crank angle x solves δ(x) + δ(x + θ) = π by bisection, δ being the
    /// angle at A. For the thesis dimensions this is the thesis's collinearity rule
    /// (step 8), so it reproduces s34,i and Δs.
    pub fn synthesise_equal_pressure_angles(&self) -> Result<LandingGearSynthesis> {
        self.validate()?;
        let mu = guarded_acos(self.crank_length_m / self.pivot_distance_m, "tangent_crank_angle")?;
        let theta = self.rotation_rad;
        let (a1, a2) = (self.pivot_distance_m, self.crank_length_m);
        let excess = |x: f64| angle_at_crank_end(a1, a2, x) + angle_at_crank_end(a1, a2, x + theta) - PI;
        // excess(0) = δ(θ) > 0 and excess(π - θ) = δ(π - θ) - π < 0 for a1 > a2.
        let (mut low, mut high) = (0.0, PI - theta);
        while high - low > BISECTION_TOLERANCE_RAD {
            let mid = 0.5 * (low + high);
            if mid <= low || mid >= high {
                break;
            }
            if excess(mid) > 0.0 {
                low = mid;
            } else {
                high = mid;
            }
        }
        self.synthesis_from_start(mu, 0.5 * (low + high))
    }

    fn synthesis_from_start(&self, mu: f64, start: f64) -> Result<LandingGearSynthesis> {
        let (a1, a2) = (self.pivot_distance_m, self.crank_length_m);
        let end = start + self.rotation_rad;
        if start <= 0.0 || end >= PI {
            return Err(Error::ParameterOutOfRange {
                name: "start_crank_angle_rad",
                value: start,
                min: 0.0,
                max: PI - self.rotation_rad,
            });
        }
        let rod = |crank: f64| (a2 * a2 + a1 * a1 - 2.0 * a2 * a1 * crank.cos()).sqrt();
        let (start_input_m, end_input_m) = (rod(start), rod(end));
        let stroke_m = end_input_m - start_input_m;
        Ok(LandingGearSynthesis {
            tangent_crank_angle_rad: mu,
            start_crank_angle_rad: start,
            end_crank_angle_rad: end,
            start_input_m,
            end_input_m,
            stroke_m,
            rod_speed_mps: stroke_m / self.stroke_time_s,
            start_pressure_angle_rad: (FRAC_PI_2 - angle_at_crank_end(a1, a2, start)).abs(),
            end_pressure_angle_rad: (FRAC_PI_2 - angle_at_crank_end(a1, a2, end)).abs(),
        })
    }

    /// Analogues at rod length `input_m` (m) by doc 004 eqs. 20-25, with φ2, φ3 from the
    /// slider-crank position (eqs. 26-28 are the same triangle).
    pub fn analogues(&self, input_m: f64) -> Result<Analogues> {
        let linkage = self.linkage()?;
        let (crank, slider) = linkage.angles(input_m)?;
        let (l2, l3) = (input_m, self.crank_length_m);
        let phi3 = crank;
        let phi2 = slider + PI;
        let (sin_d, cos_d) = (phi3 - phi2).sin_cos();
        if sin_d.abs() < linkage.toggle_tolerance_rad {
            return Err(Error::Toggle {
                input_m,
                transmission_angle_rad: sin_d.abs().asin(),
                tolerance_rad: linkage.toggle_tolerance_rad,
            });
        }
        let w3 = 1.0 / (l3 * sin_d);
        let w2 = -l3 * w3 * cos_d / l2;
        let e3 = -(l2 * w2 * w2 + l3 * w3 * w3 * cos_d) / (l3 * sin_d);
        let e2 = (l3 * w3 * w3 * sin_d - l3 * e3 * cos_d - 2.0 * w2) / l2;
        Ok(Analogues {
            crank_rate_per_input_radpm: w3,
            rod_rate_per_input_radpm: w2,
            crank_accel_per_input_radpm2: e3,
            rod_accel_per_input_radpm2: e2,
        })
    }
}

/// Angle at A (rad) of the triangle A0 B0 A for crank angle `crank` = ∠B0 A0 A.
fn angle_at_crank_end(a1: f64, a2: f64, crank: f64) -> f64 {
    let rod_squared = a1 * a1 + a2 * a2 - 2.0 * a1 * a2 * crank.cos();
    // atan2(4·area, a2² + s² - a1²), with 4·area = 2 a1 a2 sin(crank).
    (2.0 * a1 * a2 * crank.sin()).atan2(a2 * a2 + rod_squared - a1 * a1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angle_at_end_is_right_at_tangent() {
        let mu = (3.0f64 / 5.0).acos();
        assert!((angle_at_crank_end(5.0, 3.0, mu) - FRAC_PI_2).abs() < 1e-14);
    }
}
