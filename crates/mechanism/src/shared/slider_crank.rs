//! The inverted slider-crank A0 B0 A driven by its slider length s34 (thesis section 3.1, 3.3).
//!
//! Frame: the station frame of the thesis (x towards the nose, y up, origin at the fixed
//! crank pivot A0, angles counter-clockwise positive). B0 is the fixed slider pivot at
//! distance a1 and direction α0; A is the crank end at distance a2; s34 = |B0 A|.
//! θ12 = ∠B0 A0 A, and π - θ13 = ∠A0 B0 A, so the absolute directions of A0A and B0A are
//! α0 + θ12 and α0 + θ13 (loop closure a2 e^{i(α0+θ12)} = a1 e^{iα0} + s34 e^{i(α0+θ13)}).
//! The branch is θ12 in [0, π] (A counter-clockwise of B0 seen from A0), as in thesis
//! eq. 3.1.1.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::shared::angle::{four_times_triangle_area, DEFAULT_TOGGLE_TOLERANCE_RAD};

/// Relative slack on the triangle inequality that is attributed to rounding.
const TRIANGLE_ROUNDING_TOLERANCE: f64 = 1e-14;

/// An inverted slider-crank (thesis Fig. 11; doc 004 Fig. 1 with O2 = A0, O1 = B0).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct InvertedSliderCrank {
    /// a1 = |A0 B0| (m), thesis eq. 3.1.1.
    pub base_distance_m: f64,
    /// a2 = |A0 A| (m), thesis eq. 3.1.1.
    pub crank_length_m: f64,
    /// α0 = ∠x A0 B0 (rad, counter-clockwise from +x).
    pub base_angle_rad: f64,
    /// Transmission angles below this (rad) are reported as [`Error::Toggle`].
    pub toggle_tolerance_rad: f64,
}

/// Position, velocity and acceleration of the inverted slider-crank at one input.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SliderCrankState {
    /// s34 (m).
    pub input_m: f64,
    /// ds34/dt (m/s).
    pub input_speed_mps: f64,
    /// d²s34/dt² (m/s²).
    pub input_accel_mps2: f64,
    /// θ12 (rad), thesis eq. 3.1.1.
    pub crank_angle_rad: f64,
    /// θ13 (rad), thesis eq. 3.1.2.
    pub slider_angle_rad: f64,
    /// ω12 (rad/s), thesis eq. 3.3.1.
    pub crank_rate_radps: f64,
    /// ω13 (rad/s), thesis eq. 3.3.2 (its last form corrected: cot, not tan).
    pub slider_rate_radps: f64,
    /// α12 (rad/s²); thesis eq. 3.3.3 has a sign error, see `crate` docs.
    pub crank_accel_radps2: f64,
    /// α13 (rad/s²), thesis eq. 3.3.4.
    pub slider_accel_radps2: f64,
    /// dθ12/ds34 (rad/m): the angular-velocity analogue of doc 004 eq. 20.
    pub crank_rate_per_input_radpm: f64,
    /// Transmission angle μ in [0, π/2] (rad): the acute angle between A0A and B0A.
    pub transmission_angle_rad: f64,
    /// |a2 e^{i(α0+θ12)} - a1 e^{iα0} - s34 e^{i(α0+θ13)}| (m).
    pub closure_residual_m: f64,
    /// 2-norm condition number of ∂(loop)/∂(θ12, θ13).
    pub jacobian_condition_number: f64,
}

impl InvertedSliderCrank {
    /// Checks the dimensions (finite, > 0) and builds the linkage with the default toggle
    /// tolerance [`DEFAULT_TOGGLE_TOLERANCE_RAD`].
    pub fn try_new(base_distance_m: f64, crank_length_m: f64, base_angle_rad: f64) -> Result<Self> {
        positive("base_distance_m", base_distance_m)?;
        positive("crank_length_m", crank_length_m)?;
        if !base_angle_rad.is_finite() {
            return Err(Error::InvalidDimension {
                name: "base_angle_rad",
                value: base_angle_rad,
            });
        }
        Ok(Self {
            base_distance_m,
            crank_length_m,
            base_angle_rad,
            toggle_tolerance_rad: DEFAULT_TOGGLE_TOLERANCE_RAD,
        })
    }

    /// Inputs that assemble: [|a1 - a2|, a1 + a2] (m). Both ends are toggles.
    pub fn assembly_range_m(&self) -> (f64, f64) {
        let (a1, a2) = (self.base_distance_m, self.crank_length_m);
        ((a1 - a2).abs(), a1 + a2)
    }

    /// Crank angle θ12 (rad) and slider angle θ13 (rad) at input `input_m` (m).
    ///
    /// Angles come from `atan2` of Kahan's triangle area and the law-of-cosines numerator,
    /// which is equivalent to thesis eqs. 3.1.1/3.1.2 but keeps full accuracy near the
    /// toggles where `acos` loses half the digits.
    pub fn angles(&self, input_m: f64) -> Result<(f64, f64)> {
        self.triangle(input_m).map(|(_, crank, slider)| (crank, slider))
    }

    /// (4 × area of A0 B0 A (m²), θ12 (rad), θ13 (rad)) at input `input_m` (m).
    fn triangle(&self, input_m: f64) -> Result<(f64, f64, f64)> {
        let (a1, a2, s) = (self.base_distance_m, self.crank_length_m, input_m);
        let (min_input_m, max_input_m) = self.assembly_range_m();
        let cannot = Error::CannotAssemble {
            input_m,
            min_input_m,
            max_input_m,
        };
        if !s.is_finite() || s <= 0.0 {
            return Err(cannot);
        }
        let four_area = four_times_triangle_area(a1, a2, s, TRIANGLE_ROUNDING_TOLERANCE).ok_or(cannot)?;
        let crank = four_area.atan2(a1 * a1 + a2 * a2 - s * s);
        let at_base = four_area.atan2(a1 * a1 + s * s - a2 * a2);
        Ok((four_area, crank, std::f64::consts::PI - at_base))
    }

    /// Full kinematic state at input s34 = `input_m` (m), speed (m/s) and acceleration (m/s²).
    ///
    /// Velocities from the differentiated loop (thesis 3.3.1, 3.3.2), accelerations from its
    /// second derivative:
    /// α12 = (s̈ - s ω13² + a2 ω12² cos δ) / (a2 sin δ),
    /// α13 = (a2 α12 cos δ + a2 ω12² sin δ - 2 ṡ ω13) / s, with δ = θ13 - θ12.
    /// Errors: [`Error::CannotAssemble`] outside the assembly range, [`Error::Toggle`] when
    /// the transmission angle is below `toggle_tolerance_rad`.
    pub fn state(&self, input_m: f64, input_speed_mps: f64, input_accel_mps2: f64) -> Result<SliderCrankState> {
        let (four_area, crank, slider) = self.triangle(input_m)?;
        let (a1, a2, s) = (self.base_distance_m, self.crank_length_m, input_m);
        let delta = slider - crank;
        let transmission = delta.min(std::f64::consts::PI - delta);
        if transmission < self.toggle_tolerance_rad {
            return Err(Error::Toggle {
                input_m,
                transmission_angle_rad: transmission,
                tolerance_rad: self.toggle_tolerance_rad,
            });
        }
        // sin δ and cos δ of the triangle's angle at A, algebraically (no trigonometry).
        let sin_d = four_area / (2.0 * a2 * s);
        let cos_d = (a2 * a2 + s * s - a1 * a1) / (2.0 * a2 * s);
        let rate_per_input = 1.0 / (a2 * sin_d);
        let crank_rate = input_speed_mps * rate_per_input;
        let slider_rate = input_speed_mps * cos_d / (s * sin_d);
        let crank_accel =
            (input_accel_mps2 - s * slider_rate * slider_rate + a2 * crank_rate * crank_rate * cos_d) / (a2 * sin_d);
        let slider_accel =
            (a2 * crank_accel * cos_d + a2 * crank_rate * crank_rate * sin_d - 2.0 * input_speed_mps * slider_rate) / s;

        // Loop residual in the frame turned by α0 (its length does not depend on α0).
        let (sin12, cos12) = crank.sin_cos();
        let (sin13, cos13) = slider.sin_cos();
        let residual_x = a2 * cos12 - a1 - s * cos13;
        let residual_y = a2 * sin12 - s * sin13;

        // Jacobian columns i a2 e^{iφ12} and -i s e^{iφ13}: JᵀJ = [[a2², -a2 s cosδ], [., s²]].
        let trace = a2 * a2 + s * s;
        let det = (a2 * s * sin_d).powi(2);
        let largest = 0.5 * trace + (0.25 * trace * trace - det).max(0.0).sqrt();
        let condition = (largest * largest / det).sqrt();

        let state = SliderCrankState {
            input_m,
            input_speed_mps,
            input_accel_mps2,
            crank_angle_rad: crank,
            slider_angle_rad: slider,
            crank_rate_radps: crank_rate,
            slider_rate_radps: slider_rate,
            crank_accel_radps2: crank_accel,
            slider_accel_radps2: slider_accel,
            crank_rate_per_input_radpm: rate_per_input,
            transmission_angle_rad: transmission,
            closure_residual_m: residual_x.hypot(residual_y),
            jacobian_condition_number: condition,
        };
        finite_state(&state)?;
        Ok(state)
    }
}

fn positive(name: &'static str, value: f64) -> Result<()> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(Error::InvalidDimension { name, value })
    }
}

fn finite_state(state: &SliderCrankState) -> Result<()> {
    let fields = [
        ("crank_rate_radps", state.crank_rate_radps),
        ("slider_rate_radps", state.slider_rate_radps),
        ("crank_accel_radps2", state.crank_accel_radps2),
        ("slider_accel_radps2", state.slider_accel_radps2),
        ("jacobian_condition_number", state.jacobian_condition_number),
    ];
    for (quantity, value) in fields {
        if !value.is_finite() {
            return Err(Error::NonFinite {
                quantity,
                input_m: state.input_m,
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn right_angle_at_tangent_position() {
        // a1 = 5, a2 = 3, s = 4: right angle at A, transmission 90°, condition = max/min side.
        let linkage = InvertedSliderCrank::try_new(5.0, 3.0, 0.3).unwrap();
        let state = linkage.state(4.0, 1.0, 0.0).unwrap();
        assert!((state.transmission_angle_rad - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        assert!((state.jacobian_condition_number - 4.0 / 3.0).abs() < 1e-12);
        assert!(state.closure_residual_m < 1e-14);
    }

    #[test]
    fn beyond_reach_cannot_assemble() {
        let linkage = InvertedSliderCrank::try_new(5.0, 3.0, 0.0).unwrap();
        assert!(matches!(
            linkage.state(8.5, 0.0, 0.0),
            Err(Error::CannotAssemble { .. })
        ));
        assert!(matches!(
            linkage.state(0.0, 0.0, 0.0),
            Err(Error::CannotAssemble { .. })
        ));
    }
}
