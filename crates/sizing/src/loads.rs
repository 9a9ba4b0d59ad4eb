//! Flap normal load by spanwise elements (`003_...` eq 1) with load and safety factors.

use serde::Serialize;

use crate::check::{finite, non_negative, positive};
use crate::{Error, Result};

/// Normal-force coefficient C_N of the flap against flap deflection, linearly
/// interpolated (as `003_...` section 4.1 does with the ESDU F.05.01.01 data).
/// No extrapolation: a deflection outside the table is an error.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NormalForceTable {
    deflections_rad: Vec<f64>,
    coefficients: Vec<f64>,
}

impl NormalForceTable {
    /// Builds a table from deflections (rad, strictly increasing) and C_N values.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`], [`Error::TableTooShort`], [`Error::TableNotIncreasing`],
    /// [`Error::OutOfRange`] for a non-finite entry.
    pub fn try_new(deflections_rad: Vec<f64>, coefficients: Vec<f64>) -> Result<Self> {
        if deflections_rad.len() != coefficients.len() {
            return Err(Error::LengthMismatch {
                what: "normal-force table deflections and coefficients",
                first: deflections_rad.len(),
                second: coefficients.len(),
            });
        }
        if deflections_rad.len() < 2 {
            return Err(Error::TableTooShort {
                rows: deflections_rad.len(),
            });
        }
        for (row, (&d, &c)) in deflections_rad.iter().zip(&coefficients).enumerate() {
            finite(format!("normal_force_table[{row}].deflection_rad"), d)?;
            finite(format!("normal_force_table[{row}].coefficient"), c)?;
            if row > 0 && d <= deflections_rad[row - 1] {
                return Err(Error::TableNotIncreasing { row });
            }
        }
        Ok(Self {
            deflections_rad,
            coefficients,
        })
    }

    /// C_N at the given deflection (rad), by linear interpolation.
    ///
    /// # Errors
    /// [`Error::DeflectionOutsideTable`] outside the first..last deflection.
    pub fn coefficient_at(&self, deflection_rad: f64) -> Result<f64> {
        let d = &self.deflections_rad;
        let (min_rad, max_rad) = (d[0], d[d.len() - 1]);
        if !(deflection_rad >= min_rad && deflection_rad <= max_rad) {
            return Err(Error::DeflectionOutsideTable {
                deflection_rad,
                min_rad,
                max_rad,
            });
        }
        let upper = d.partition_point(|&x| x < deflection_rad).clamp(1, d.len() - 1);
        let (x0, x1) = (d[upper - 1], d[upper]);
        let (y0, y1) = (self.coefficients[upper - 1], self.coefficients[upper]);
        Ok(y0 + (y1 - y0) * (deflection_rad - x0) / (x1 - x0))
    }
}

/// Load factor n and safety factor applied to the aerodynamic loads.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LoadCase {
    /// Load factor n multiplying the aerodynamic load, in (0, inf).
    pub load_factor: f64,
    /// Factor of safety, in [1, inf); CS-25.303 prescribes 1.5 (used by `003_...` 5.1).
    pub safety_factor: f64,
}

impl Default for LoadCase {
    /// n = 1, safety factor 1.5 (CS-25.303).
    fn default() -> Self {
        Self {
            load_factor: 1.0,
            safety_factor: CS25_SAFETY_FACTOR,
        }
    }
}

/// CS-25.303 factor of safety, 1.5.
pub const CS25_SAFETY_FACTOR: f64 = 1.5;

impl LoadCase {
    /// The `003_...` section 4.1 sizing case: flaps fully deployed at the placard speed
    /// V_F with load factor 2.0 (CS-25.345), safety factor 1.5.
    pub fn cs25_flaps_extended() -> Self {
        Self {
            load_factor: 2.0,
            safety_factor: CS25_SAFETY_FACTOR,
        }
    }

    /// Checked constructor.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for a load factor not in (0, inf) or a safety factor below 1.
    pub fn try_new(load_factor: f64, safety_factor: f64) -> Result<Self> {
        let case = Self {
            load_factor,
            safety_factor,
        };
        case.validate()?;
        Ok(case)
    }

    /// Checks both factors.
    ///
    /// # Errors
    /// As [`LoadCase::try_new`].
    pub fn validate(&self) -> Result<()> {
        positive("load_factor", self.load_factor)?;
        if !(self.safety_factor.is_finite() && self.safety_factor >= 1.0) {
            return Err(Error::OutOfRange {
                field: "safety_factor".to_owned(),
                value: self.safety_factor,
                allowed: "[1, inf)",
            });
        }
        Ok(())
    }

    /// Product n x safety factor that turns an aerodynamic load into a design load.
    pub fn design_factor(&self) -> f64 {
        self.load_factor * self.safety_factor
    }
}

/// One spanwise flap element of `003_...` eq 1.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlapElement {
    /// Spanwise start along the hinge line, m (any origin shared with the stations).
    pub span_start_m: f64,
    /// Spanwise end, m, greater than the start; element span b_f,i = end - start.
    pub span_end_m: f64,
    /// Element flap chord c_f,i, m.
    pub chord_m: f64,
    /// Chordwise position of the quarter chord (where eq 1's load acts, `003_...` 4.1)
    /// measured aft of the forward-attachment (hinge) line, m; negative = ahead of it.
    pub quarter_chord_aft_of_hinge_m: f64,
    /// Quarter-chord pitching-moment coefficient C_m (nose-up positive); ESDU gives none,
    /// so 0 unless the designer supplies one. M = C_m q c^2 b.
    pub moment_coefficient: f64,
}

/// Load of one element: normal force and pitching moment at its spanwise midpoint.
///
/// Frame: normal force positive along the flap normal towards the upper surface (the
/// lift side); moment about the spanwise axis, nose-up positive; chordwise positions
/// measured aft of the forward-attachment line.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ElementLoad {
    /// Spanwise position of the load (element midpoint), m.
    pub span_position_m: f64,
    /// Normal force N, N.
    pub normal_force_n: f64,
    /// Chordwise position of the force aft of the forward-attachment line, m.
    pub chordwise_position_m: f64,
    /// Pitching moment about that point, N m, nose-up positive.
    pub pitching_moment_nm: f64,
}

/// Element normal load N_f,i = C_Nf,i c_f,i b_f,i q (`003_...` eq 1), N.
///
/// Units: chord and span in m, dynamic pressure q in Pa. Eq 1 is dimensionally
/// consistent (Pa x m^2 = N).
pub fn element_normal_force_n(coefficient: f64, chord_m: f64, span_m: f64, dynamic_pressure_pa: f64) -> f64 {
    coefficient * chord_m * span_m * dynamic_pressure_pa
}

/// Design loads of every element at one flap deflection: eq 1 with C_N from the table,
/// multiplied by the load case's n x safety factor.
///
/// # Errors
/// [`Error::OutOfRange`] for a bad element, dynamic pressure or load case;
/// [`Error::DeflectionOutsideTable`].
pub fn element_loads(
    elements: &[FlapElement],
    table: &NormalForceTable,
    deflection_rad: f64,
    dynamic_pressure_pa: f64,
    load_case: &LoadCase,
) -> Result<Vec<ElementLoad>> {
    load_case.validate()?;
    non_negative("dynamic_pressure_pa", dynamic_pressure_pa)?;
    let coefficient = table.coefficient_at(deflection_rad)?;
    let factor = load_case.design_factor();
    elements
        .iter()
        .enumerate()
        .map(|(i, e)| {
            finite(format!("elements[{i}].span_start_m"), e.span_start_m)?;
            let span_m = positive(format!("elements[{i}].span_m"), e.span_end_m - e.span_start_m)?;
            positive(format!("elements[{i}].chord_m"), e.chord_m)?;
            finite(
                format!("elements[{i}].quarter_chord_aft_of_hinge_m"),
                e.quarter_chord_aft_of_hinge_m,
            )?;
            finite(format!("elements[{i}].moment_coefficient"), e.moment_coefficient)?;
            let normal = element_normal_force_n(coefficient, e.chord_m, span_m, dynamic_pressure_pa);
            let moment = e.moment_coefficient * dynamic_pressure_pa * e.chord_m.powi(2) * span_m;
            Ok(ElementLoad {
                span_position_m: 0.5 * (e.span_start_m + e.span_end_m),
                normal_force_n: factor * normal,
                chordwise_position_m: e.quarter_chord_aft_of_hinge_m,
                pitching_moment_nm: factor * moment,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolation_hits_rows_and_midpoints() {
        let t = NormalForceTable::try_new(vec![0.0, 0.2, 0.6], vec![0.1, 0.5, 0.9]).unwrap();
        assert!((t.coefficient_at(0.2).unwrap() - 0.5).abs() < 1e-15);
        assert_eq!(t.coefficient_at(0.0).unwrap(), 0.1);
        assert!((t.coefficient_at(0.4).unwrap() - 0.7).abs() < 1e-15);
        assert!((t.coefficient_at(0.6).unwrap() - 0.9).abs() < 1e-15);
        assert!(t.coefficient_at(0.7).is_err());
        assert!(t.coefficient_at(f64::NAN).is_err());
    }

    #[test]
    fn non_increasing_table_is_rejected() {
        let e = NormalForceTable::try_new(vec![0.0, 0.0], vec![1.0, 1.0]).unwrap_err();
        assert_eq!(e, Error::TableNotIncreasing { row: 1 });
    }
}
