//! Circular cross-sections, solid or tubular, described by shape and outer radius.

use serde::Serialize;

use crate::{Error, Result};

/// Shape of a circular cross-section independent of its size: solid, or a tube with a
/// fixed inner-to-outer radius ratio k = r_i / r_o in [0, 1).
///
/// With outer radius r (m): area A = pi r^2 (1 - k^2), second moment of area about a
/// diameter I = pi r^4 (1 - k^4) / 4, polar moment J = pi r^4 (1 - k^4) / 2 (for k = 0
/// these are the solid values `003_...` section 4.1 and eq 6 use).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum SectionShape {
    /// Solid circle (k = 0).
    Solid,
    /// Hollow circle with inner radius = ratio x outer radius.
    Tube {
        /// k = r_inner / r_outer, in [0, 1).
        inner_to_outer_ratio: f64,
    },
}

impl SectionShape {
    /// A tube with the given inner-to-outer radius ratio, checked to lie in [0, 1).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for a ratio outside [0, 1) or not finite.
    pub fn try_tube(inner_to_outer_ratio: f64) -> Result<Self> {
        let shape = Self::Tube { inner_to_outer_ratio };
        shape.validate()?;
        Ok(shape)
    }

    /// Checks the ratio of a tube is in [0, 1).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `inner_to_outer_ratio`.
    pub fn validate(&self) -> Result<()> {
        let k = self.inner_to_outer_ratio();
        if k.is_finite() && (0.0..1.0).contains(&k) {
            Ok(())
        } else {
            Err(Error::OutOfRange {
                field: "inner_to_outer_ratio".to_owned(),
                value: k,
                allowed: "[0, 1)",
            })
        }
    }

    /// k = r_inner / r_outer (0 for solid).
    pub fn inner_to_outer_ratio(&self) -> f64 {
        match *self {
            Self::Solid => 0.0,
            Self::Tube { inner_to_outer_ratio } => inner_to_outer_ratio,
        }
    }

    /// Inner radius r_i = k r, m.
    pub fn inner_radius_m(&self, outer_radius_m: f64) -> f64 {
        self.inner_to_outer_ratio() * outer_radius_m
    }

    /// Factor (1 - k^2) of the area relative to the solid section.
    pub fn area_factor(&self) -> f64 {
        let k = self.inner_to_outer_ratio();
        1.0 - k * k
    }

    /// Factor (1 - k^4) of I and J relative to the solid section.
    pub fn inertia_factor(&self) -> f64 {
        let k2 = self.inner_to_outer_ratio().powi(2);
        1.0 - k2 * k2
    }

    /// Area A = pi r^2 (1 - k^2), m^2, for outer radius r in m.
    pub fn area_m2(&self, outer_radius_m: f64) -> f64 {
        std::f64::consts::PI * outer_radius_m.powi(2) * self.area_factor()
    }

    /// Second moment of area about a diameter I = pi r^4 (1 - k^4) / 4, m^4.
    pub fn second_moment_m4(&self, outer_radius_m: f64) -> f64 {
        std::f64::consts::PI * outer_radius_m.powi(4) * self.inertia_factor() / 4.0
    }

    /// Polar second moment J = pi r^4 (1 - k^4) / 2, m^4.
    pub fn polar_moment_m4(&self, outer_radius_m: f64) -> f64 {
        2.0 * self.second_moment_m4(outer_radius_m)
    }

    /// Radius of gyration rho_g = sqrt(I / A) = r sqrt(1 + k^2) / 2, m.
    pub fn radius_of_gyration_m(&self, outer_radius_m: f64) -> f64 {
        let k = self.inner_to_outer_ratio();
        outer_radius_m * (1.0 + k * k).sqrt() / 2.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gyration_radius_matches_i_over_a() {
        let shape = SectionShape::try_tube(0.8).unwrap();
        let r = 0.03;
        let direct = (shape.second_moment_m4(r) / shape.area_m2(r)).sqrt();
        let relative = (shape.radius_of_gyration_m(r) - direct).abs() / direct;
        assert!(relative < 1e-14);
    }

    #[test]
    fn ratio_one_is_rejected() {
        assert!(SectionShape::try_tube(1.0).is_err());
        assert!(SectionShape::try_tube(-0.1).is_err());
    }
}
