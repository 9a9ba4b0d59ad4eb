//! Screw jacks: raise and lower torque of a square thread (thesis `000` section 3.6),
//! self-locking, and the motor torque with a safety factor (thesis section 5.2).

use serde::Serialize;

use crate::check::{finite, non_negative, positive};
use crate::warning::SizingWarning;
use crate::{Error, Result};
use std::f64::consts::PI;

/// Square-thread screw geometry (thesis `000` Fig. 17-18).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ScrewThread {
    /// Mean thread radius r, m (thesis case study: 16 mm).
    pub mean_radius_m: f64,
    /// Lead l (axial advance per turn), m (thesis: 8 mm).
    pub lead_m: f64,
    /// Thread friction coefficient f (thesis: 0.1).
    pub friction_coefficient: f64,
}

impl ScrewThread {
    fn validate(&self) -> Result<()> {
        positive("mean_radius_m", self.mean_radius_m)?;
        positive("lead_m", self.lead_m)?;
        non_negative("friction_coefficient", self.friction_coefficient)?;
        Ok(())
    }

    /// Lead angle lambda = atan(l / (2 pi r)), rad. (The thesis text prints
    /// "tan lambda = 1/2 pi r" before eq 3.6.9: an extraction typo for l / (2 pi r).)
    pub fn lead_angle_rad(&self) -> f64 {
        (self.lead_m / (2.0 * PI * self.mean_radius_m)).atan()
    }

    /// Self-locking by geometry: f > tan(lambda) = l / (2 pi r), i.e. the lowering torque
    /// of eq 3.6.10 is positive for a positive load.
    pub fn is_self_locking(&self) -> bool {
        2.0 * PI * self.mean_radius_m * self.friction_coefficient > self.lead_m
    }

    /// Raising torque T_R = (2 pi r f + l) / (2 pi r - f l) r L (thesis eq 3.6.9), N m,
    /// for axial load L in N (the mechanism's input force F_input).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for bad geometry or load; [`Error::ScrewJamsWhenRaising`]
    /// when 2 pi r - f l <= 0.
    pub fn raise_torque_nm(&self, axial_load_n: f64) -> Result<f64> {
        self.validate()?;
        finite("axial_load_n", axial_load_n)?;
        let (r, l, f) = (self.mean_radius_m, self.lead_m, self.friction_coefficient);
        let denominator_m = 2.0 * PI * r - f * l;
        if denominator_m <= 0.0 {
            return Err(Error::ScrewJamsWhenRaising { denominator_m });
        }
        Ok((2.0 * PI * r * f + l) / denominator_m * r * axial_load_n)
    }

    /// Lowering torque T_L = (2 pi r f - l) / (2 pi r + f l) r L (thesis eq 3.6.10), N m.
    /// Positive: torque must be applied to lower (self-locking); negative: the load
    /// back-drives the screw.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for bad geometry or load.
    pub fn lower_torque_nm(&self, axial_load_n: f64) -> Result<f64> {
        self.validate()?;
        finite("axial_load_n", axial_load_n)?;
        let (r, l, f) = (self.mean_radius_m, self.lead_m, self.friction_coefficient);
        Ok((2.0 * PI * r * f - l) / (2.0 * PI * r + f * l) * r * axial_load_n)
    }
}

/// Peak screw torques of one screw jack over the deployment.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ScrewJackInput {
    /// Station name.
    pub station: String,
    /// Screw jack name.
    pub name: String,
    /// Largest raising (deploying) torque over the deployment, N m.
    pub max_raise_torque_nm: f64,
    /// Lowering (retracting) torque, N m, eq 3.6.10 sign: positive = self-locking. Pass
    /// the smallest value over the deployment to check self-locking everywhere.
    pub max_lower_torque_nm: f64,
}

/// Result of [`size_screw_jack`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ScrewJackSizing {
    /// Station name.
    pub station: String,
    /// Screw jack name.
    pub name: String,
    /// Largest raising torque, N m.
    pub max_raise_torque_nm: f64,
    /// Lowering torque, N m (eq 3.6.10 sign).
    pub max_lower_torque_nm: f64,
    /// Safety factor applied.
    pub safety_factor: f64,
    /// Motor torque requirement = safety factor x max(|T_R|, |T_L|), N m.
    pub motor_torque_nm: f64,
    /// True when the lowering torque is positive (the load cannot back-drive the screw).
    pub self_locking: bool,
    /// Warnings about this jack (also collected by the report).
    #[serde(skip)]
    pub warnings: Vec<SizingWarning>,
}

/// Motor torque requirement, N m: safety factor x max(|T_R|, |T_L|) (thesis section
/// 5.2: 4.7 N m x 1.5 -> 7.1 N m).
///
/// # Errors
/// [`Error::OutOfRange`] for non-finite torques or a safety factor below 1.
pub fn motor_torque_nm(
    max_raise_torque_nm: f64,
    max_lower_torque_nm: f64,
    safety_factor: f64,
) -> Result<f64> {
    finite("max_raise_torque_nm", max_raise_torque_nm)?;
    finite("max_lower_torque_nm", max_lower_torque_nm)?;
    if !(safety_factor.is_finite() && safety_factor >= 1.0) {
        return Err(Error::OutOfRange {
            field: "safety_factor".to_owned(),
            value: safety_factor,
            allowed: "[1, inf)",
        });
    }
    Ok(safety_factor * max_raise_torque_nm.abs().max(max_lower_torque_nm.abs()))
}

/// Motor torque and self-locking verdict of one screw jack; a jack that is not
/// self-locking gets a [`SizingWarning::NotSelfLocking`].
///
/// # Errors
/// As [`motor_torque_nm`].
pub fn size_screw_jack(input: &ScrewJackInput, safety_factor: f64) -> Result<ScrewJackSizing> {
    let motor = motor_torque_nm(
        input.max_raise_torque_nm,
        input.max_lower_torque_nm,
        safety_factor,
    )?;
    let self_locking = input.max_lower_torque_nm > 0.0;
    let mut warnings = Vec::new();
    if !self_locking {
        warnings.push(SizingWarning::NotSelfLocking {
            station: input.station.clone(),
            screw_jack: input.name.clone(),
            lower_torque_nm: input.max_lower_torque_nm,
        });
    }
    Ok(ScrewJackSizing {
        station: input.station.clone(),
        name: input.name.clone(),
        max_raise_torque_nm: input.max_raise_torque_nm,
        max_lower_torque_nm: input.max_lower_torque_nm,
        safety_factor,
        motor_torque_nm: motor,
        self_locking,
        warnings,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Eq 3.6.9/3.6.10 against the tan-form eqs 3.6.4/3.6.8 they were rewritten from.
    #[test]
    fn lead_form_matches_tan_form() {
        let t = ScrewThread {
            mean_radius_m: 0.016,
            lead_m: 0.008,
            friction_coefficient: 0.1,
        };
        let (r, f, tan) = (0.016, 0.1, t.lead_angle_rad().tan());
        let raise = r * (f + tan) / (1.0 - f * tan) * 1000.0;
        let lower = r * (f - tan) / (1.0 + f * tan) * 1000.0;
        assert!((t.raise_torque_nm(1000.0).unwrap() - raise).abs() < 1e-12);
        assert!((t.lower_torque_nm(1000.0).unwrap() - lower).abs() < 1e-12);
        assert!(t.is_self_locking());
    }

    /// Virtual work: without friction one turn of torque T_R lifts L by one lead,
    /// 2 pi T_R = L l, and lowering returns it, T_L = -T_R.
    #[test]
    fn frictionless_thread_conserves_work() {
        let t = ScrewThread {
            mean_radius_m: 0.016,
            lead_m: 0.008,
            friction_coefficient: 0.0,
        };
        let raise = t.raise_torque_nm(1000.0).unwrap();
        assert!((2.0 * PI * raise - 1000.0 * 0.008).abs() < 1e-12);
        assert!((t.lower_torque_nm(1000.0).unwrap() + raise).abs() < 1e-12);
        // With friction the efficiency L l / (2 pi T_R) drops below 1.
        let t = ScrewThread {
            friction_coefficient: 0.1,
            ..t
        };
        assert!(1000.0 * 0.008 / (2.0 * PI * t.raise_torque_nm(1000.0).unwrap()) < 1.0);
    }
}
