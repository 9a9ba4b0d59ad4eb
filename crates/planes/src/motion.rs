//! Flap positions in 3D from deflection, gap/overlap translation and conical rotations
//! (Zaccai et al. `003`, section 2, Figs. 2-3 and 5).

use nalgebra::{Isometry3, Point3, Translation3, Unit, UnitQuaternion, Vector3};

use crate::error::{finite, Error, Result};
use crate::plane::HingeAxis;

/// One flap setting (stowed, take-off, landing), relative to the stowed flap.
///
/// `003` section 2: deflect by δ_f about the hinge line, then rotate by θ_o and θ_g about
/// two axes through the base point (spanwise-varying overlap and gap, i.e. conical
/// deployment, Fig. 2b), then translate to the specified gap and overlap (Fig. 3 step 4).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FlapSetting {
    /// δ_f: deflection about the stowed hinge line, rad, trailing edge down positive.
    pub deflection_rad: f64,
    /// θ_o: rotation about the overlap axis through the base point, rad.
    pub overlap_rotation_rad: f64,
    /// θ_g: rotation about the gap axis through the base point, rad.
    pub gap_rotation_rad: f64,
    /// Translation of the base point giving the gap and overlap, aircraft frame, m.
    pub base_translation_ac: Vector3<f64>,
}

impl FlapSetting {
    /// The stowed setting: no rotation, no translation.
    pub fn stowed() -> Self {
        Self {
            deflection_rad: 0.0,
            overlap_rotation_rad: 0.0,
            gap_rotation_rad: 0.0,
            base_translation_ac: Vector3::zeros(),
        }
    }

    fn interpolated(&self, other: &Self, fraction: f64) -> Self {
        let mix = |a: f64, b: f64| a + (b - a) * fraction;
        Self {
            deflection_rad: mix(self.deflection_rad, other.deflection_rad),
            overlap_rotation_rad: mix(self.overlap_rotation_rad, other.overlap_rotation_rad),
            gap_rotation_rad: mix(self.gap_rotation_rad, other.gap_rotation_rad),
            base_translation_ac: self.base_translation_ac.lerp(&other.base_translation_ac, fraction),
        }
    }
}

/// A flap deployment: the stowed hinge line, the base point and the axes of the conical
/// rotations, and the settings in deployment order (the first is normally stowed).
#[derive(Debug, Clone, PartialEq)]
pub struct FlapDeployment {
    /// Stowed hinge line through the forward attachment points (aircraft frame).
    pub hinge: HingeAxis,
    /// Base point: on the hinge line, η_base from the inboard edge (`003` Fig. 2b), m.
    pub base_point_ac: Point3<f64>,
    /// Axis of θ_o (overlap) through the base point: the wing normal ("dihedral vector").
    pub overlap_axis_ac: Unit<Vector3<f64>>,
    /// Axis of θ_g (gap) through the base point: the streamwise direction (aircraft +x).
    pub gap_axis_ac: Unit<Vector3<f64>>,
    /// Settings in deployment order.
    pub settings: Vec<FlapSetting>,
}

impl FlapDeployment {
    /// Rigid pose of the flap at `setting`: maps stowed flap points (aircraft frame, m) to
    /// their deployed positions. p' = B + t + R_g R_o R_δ (p - B), B the base point
    /// (on the hinge line, so R_δ about the hinge line and about B coincide).
    pub fn pose_ac(&self, setting: &FlapSetting) -> Isometry3<f64> {
        let rotation = UnitQuaternion::from_axis_angle(&self.gap_axis_ac, setting.gap_rotation_rad)
            * UnitQuaternion::from_axis_angle(&self.overlap_axis_ac, setting.overlap_rotation_rad)
            * UnitQuaternion::from_axis_angle(&self.hinge.direction_ac, setting.deflection_rad);
        let base = self.base_point_ac.coords;
        Translation3::from(base + setting.base_translation_ac) * rotation * Translation3::from(-base)
    }

    /// Pose at `deployment` in [0, 1] along the settings (equally spaced, parameters
    /// interpolated linearly between neighbours; clamped outside [0, 1]). A stand-in for
    /// the mechanism's own path until the mechanism is synthesised.
    pub fn pose_at_ac(&self, deployment: f64) -> Result<Isometry3<f64>> {
        finite("deployment", deployment)?;
        let count = self.settings.len();
        if count == 0 {
            return Err(Error::TooFew {
                quantity: "flap settings",
                value: 0,
                minimum: 1,
            });
        }
        if count == 1 {
            return Ok(self.pose_ac(&self.settings[0]));
        }
        let position = deployment.clamp(0.0, 1.0) * (count - 1) as f64;
        let index = (position.floor() as usize).min(count - 2);
        let setting = self.settings[index].interpolated(&self.settings[index + 1], position - index as f64);
        Ok(self.pose_ac(&setting))
    }

    /// `samples` poses equally spaced over the deployment (first stowed, last final).
    pub fn sample_poses_ac(&self, samples: usize) -> Result<Vec<Isometry3<f64>>> {
        if samples < 2 {
            return Err(Error::TooFew {
                quantity: "deployment samples",
                value: samples,
                minimum: 2,
            });
        }
        (0..samples)
            .map(|i| self.pose_at_ac(i as f64 / (samples - 1) as f64))
            .collect()
    }

    /// True when every setting is a pure rotation about the stowed hinge line (no conical
    /// rotation above `angle_tol_rad`, no translation above `length_tol_m`).
    pub fn is_pure_rotation(&self, angle_tol_rad: f64, length_tol_m: f64) -> bool {
        self.settings.iter().all(|s| {
            s.overlap_rotation_rad.abs() <= angle_tol_rad
                && s.gap_rotation_rad.abs() <= angle_tol_rad
                && s.base_translation_ac.norm() <= length_tol_m
        })
    }
}
