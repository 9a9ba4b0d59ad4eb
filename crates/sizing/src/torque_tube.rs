//! Torque tubes: cumulative drive torque along the tube sequence and the radius of each
//! tube from torsional shear (`003_...` section 4.2, eqs 4, 6, 7).

use serde::Serialize;

use crate::check::{efficiency, non_negative, positive};
use crate::material::Material;
use crate::section::SectionShape;
use crate::warning::SizingWarning;
use crate::Result;
use std::f64::consts::PI;

/// One tube of the drive line and the mechanism it feeds.
///
/// Tubes are listed from the far end of the line (the most outboard actuated station,
/// tube 1 of `003_...` Fig. 14) towards the motor: tube n carries the torque of
/// stations 1..=n.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TorqueTubeInput {
    /// Name of the station whose gearbox is at the far end of this tube.
    pub station: String,
    /// Drive torque T_d,i that station's gearbox takes from the line (before gearbox
    /// losses), N m, >= 0 (peak magnitude over the deployment).
    pub drive_torque_nm: f64,
    /// Tube length, m (for the mass).
    pub length_m: f64,
    /// Largest outer radius the structure allows, m (None: unlimited).
    pub max_outer_radius_m: Option<f64>,
}

/// Result of [`size_torque_tubes`] for one tube.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TorqueTubeSizing {
    /// Station at the far end of the tube.
    pub station: String,
    /// Torque carried, sum_{i<=n} T_d,i / eta_gear (eq 7 numerator / 2), N m.
    pub torque_carried_nm: f64,
    /// Outer radius, m.
    pub radius_m: f64,
    /// Inner radius, m (0 for solid).
    pub inner_radius_m: f64,
    /// Length L of this segment (from its station to the next one towards the motor), m.
    pub length_m: f64,
    /// Mass = A L rho, kg.
    pub mass_kg: f64,
    /// Warnings about this tube (also collected by the report).
    #[serde(skip)]
    pub warnings: Vec<SizingWarning>,
}

/// Ideal motor reaction torque T_M,ideal = sum T_d,i (`003_...` eq 4), N m.
pub fn ideal_motor_torque_nm(drive_torques_nm: &[f64]) -> f64 {
    drive_torques_nm.iter().sum()
}

/// Torque carried by each tube, sum_{i<=n} T_d,i / eta (`003_...` eq 7), N m. The
/// gearbox loss is taken only on the branch to each mechanism, as in the paper.
///
/// # Errors
/// [`crate::Error::EfficiencyOutOfRange`] for eta outside (0, 1];
/// [`crate::Error::OutOfRange`] for a negative or non-finite torque.
pub fn cumulative_torques_nm(drive_torques_nm: &[f64], gearbox_efficiency: f64) -> Result<Vec<f64>> {
    let eta = efficiency("gearbox_efficiency", gearbox_efficiency)?;
    let mut running = 0.0;
    drive_torques_nm
        .iter()
        .enumerate()
        .map(|(i, &t)| {
            running += non_negative(format!("drive_torques_nm[{i}]"), t)? / eta;
            Ok(running)
        })
        .collect()
}

/// Outer radius at which torque T gives the allowable shear stress tau at the surface:
/// tau = T r / J, J = pi r^4 (1 - k^4) / 2, so r = (2 T / (pi tau (1 - k^4)))^(1/3), m
/// (`003_...` eq 6 for k = 0). T in N m, tau in Pa.
///
/// # Errors
/// [`crate::Error::OutOfRange`] for a negative torque, a non-positive stress or a bad shape.
///
/// # Examples
/// ```
/// use flapwright_sizing::{torsion_radius_m, SectionShape};
/// // 100 N m at 200 MPa: r = (2 x 100 / (pi x 2e8))^(1/3) = 6.83 mm.
/// let r = torsion_radius_m(100.0, 200e6, SectionShape::Solid)?;
/// assert!((r - 6.827_840_633e-3).abs() < 1e-12);
/// # Ok::<(), flapwright_sizing::Error>(())
/// ```
pub fn torsion_radius_m(torque_nm: f64, allowable_shear_pa: f64, shape: SectionShape) -> Result<f64> {
    non_negative("torque_nm", torque_nm)?;
    positive("allowable_shear_pa", allowable_shear_pa)?;
    shape.validate()?;
    Ok((2.0 * torque_nm / (PI * allowable_shear_pa * shape.inertia_factor())).cbrt())
}

/// Sizes the sequence of tubes (far end first) by `003_...` eq 7, solid or hollow.
///
/// # Errors
/// [`crate::Error::InvalidMaterial`], [`crate::Error::EfficiencyOutOfRange`],
/// [`crate::Error::OutOfRange`] for bad lengths, torques or shape.
pub fn size_torque_tubes(
    tubes: &[TorqueTubeInput],
    gearbox_efficiency: f64,
    shape: SectionShape,
    material: &Material,
) -> Result<Vec<TorqueTubeSizing>> {
    material.validate()?;
    shape.validate()?;
    let torques: Vec<f64> = tubes.iter().map(|t| t.drive_torque_nm).collect();
    let carried = cumulative_torques_nm(&torques, gearbox_efficiency)?;
    tubes
        .iter()
        .zip(carried)
        .enumerate()
        .map(|(i, (tube, torque_carried_nm))| {
            let length_m = positive(format!("tubes[{i}].length_m"), tube.length_m)?;
            let radius_m = torsion_radius_m(torque_carried_nm, material.allowable_shear_pa, shape)?;
            let mut warnings = Vec::new();
            if let Some(limit) = tube.max_outer_radius_m {
                positive(format!("tubes[{i}].max_outer_radius_m"), limit)?;
                if radius_m > limit {
                    warnings.push(SizingWarning::TorqueTubeExceedsEnvelope {
                        station: tube.station.clone(),
                        required_outer_radius_m: radius_m,
                        allowed_outer_radius_m: limit,
                    });
                }
            }
            Ok(TorqueTubeSizing {
                station: tube.station.clone(),
                torque_carried_nm,
                radius_m,
                inner_radius_m: shape.inner_radius_m(radius_m),
                length_m,
                mass_kg: shape.area_m2(radius_m) * length_m * material.density_kg_m3,
                warnings,
            })
        })
        .collect()
}
