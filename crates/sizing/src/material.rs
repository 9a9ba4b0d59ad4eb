//! Isotropic structural materials with allowable stresses, and a few named presets.

use serde::Serialize;

use crate::{Error, Result};

/// An isotropic, homogeneous material as `003_...` section 4.1 assumes: density for the
/// masses, allowable normal and shear stress for strength, Young's modulus for buckling.
///
/// Fields are public for reading; build through [`Material::try_new`] (or a preset) so the
/// ranges are checked. Sizing functions call [`Material::validate`] again, so a value
/// edited by hand cannot slip through.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Material {
    /// Name shown in reports.
    pub name: String,
    /// Density rho, kg/m^3, in (0, inf).
    pub density_kg_m3: f64,
    /// Allowable normal stress sigma_allow (tension and compression strength), Pa, in (0, inf).
    pub allowable_tensile_pa: f64,
    /// Allowable shear stress tau_allow (torsion), Pa, in (0, inf).
    pub allowable_shear_pa: f64,
    /// Young's modulus E, Pa, in (0, inf).
    pub youngs_modulus_pa: f64,
}

impl Material {
    /// Builds a material after checking every property is finite and strictly positive.
    ///
    /// # Errors
    /// [`Error::InvalidMaterial`] naming the first field out of range.
    pub fn try_new(
        name: impl Into<String>,
        density_kg_m3: f64,
        allowable_tensile_pa: f64,
        allowable_shear_pa: f64,
        youngs_modulus_pa: f64,
    ) -> Result<Self> {
        let material = Self {
            name: name.into(),
            density_kg_m3,
            allowable_tensile_pa,
            allowable_shear_pa,
            youngs_modulus_pa,
        };
        material.validate()?;
        Ok(material)
    }

    /// Checks every property is finite and strictly positive.
    ///
    /// # Errors
    /// [`Error::InvalidMaterial`] naming the first field out of range.
    pub fn validate(&self) -> Result<()> {
        let fields = [
            ("density_kg_m3", self.density_kg_m3, "(0, inf) kg/m^3"),
            ("allowable_tensile_pa", self.allowable_tensile_pa, "(0, inf) Pa"),
            ("allowable_shear_pa", self.allowable_shear_pa, "(0, inf) Pa"),
            ("youngs_modulus_pa", self.youngs_modulus_pa, "(0, inf) Pa"),
        ];
        for (field, value, allowed) in fields {
            if !(value.is_finite() && value > 0.0) {
                return Err(Error::InvalidMaterial {
                    material: self.name.clone(),
                    field,
                    value,
                    allowed,
                });
            }
        }
        Ok(())
    }

    /// Aluminium 7075-T6 (plate/bar, typical values).
    ///
    /// Source: ASM Aerospace Specification Metals / MatWeb data sheet "Aluminum 7075-T6;
    /// 7075-T651": density 2810 kg/m^3, tensile yield 503 MPa, E 71.7 GPa. Allowables are
    /// the static yield stress, shear allowable = sigma_y / sqrt(3) (distortion energy,
    /// 290.4 MPa). Not the fatigue allowables `003_...` section 5.1 used (250 MPa).
    pub fn aluminium_7075_t6() -> Self {
        Self::preset("aluminium 7075-T6", 2810.0, 503.0e6, 71.7e9)
    }

    /// Titanium Ti-6Al-4V (grade 5, annealed, typical values).
    ///
    /// Source: ASM Aerospace Specification Metals / MatWeb data sheet "Titanium
    /// Ti-6Al-4V (Grade 5), Annealed": density 4430 kg/m^3, tensile yield 880 MPa,
    /// E 113.8 GPa; shear allowable = sigma_y / sqrt(3) (508.1 MPa).
    pub fn titanium_ti_6al_4v() -> Self {
        Self::preset("titanium Ti-6Al-4V", 4430.0, 880.0e6, 113.8e9)
    }

    /// Steel AISI 4340 (normalized, typical values).
    ///
    /// Source: MatWeb data sheet "AISI 4340 Steel, normalized": density 7850 kg/m^3,
    /// tensile yield 710 MPa, E 205 GPa; shear allowable = sigma_y / sqrt(3) (409.9 MPa).
    pub fn steel_4340() -> Self {
        Self::preset("steel 4340", 7850.0, 710.0e6, 205.0e9)
    }

    fn preset(name: &str, density_kg_m3: f64, yield_pa: f64, youngs_modulus_pa: f64) -> Self {
        Self {
            name: name.to_owned(),
            density_kg_m3,
            allowable_tensile_pa: yield_pa,
            allowable_shear_pa: yield_pa / 3.0_f64.sqrt(),
            youngs_modulus_pa,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_are_valid() {
        for m in [
            Material::aluminium_7075_t6(),
            Material::titanium_ti_6al_4v(),
            Material::steel_4340(),
        ] {
            assert!(m.validate().is_ok(), "{}", m.name);
        }
    }

    #[test]
    fn nan_modulus_is_rejected() {
        let e = Material::try_new("x", 1.0, 1.0, 1.0, f64::NAN).unwrap_err();
        assert!(matches!(
            e,
            Error::InvalidMaterial {
                field: "youngs_modulus_pa",
                ..
            }
        ));
    }
}
