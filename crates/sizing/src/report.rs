//! The `sizing` section of the report (serialised to JSON by the CLI).

use serde::Serialize;

use crate::actuator::ActuatorSizing;
use crate::drive::DriveDemand;
use crate::rod::RodSizing;
use crate::torque_tube::TorqueTubeSizing;
use crate::warning::SizingWarning;
use crate::weights::{MassBreakdown, MassItem};

/// What [`SizingTotals::mass_kg`] covers, in words for the report.
pub const TOTAL_MASS_COVERS: &str =
    "the sized members (rods, links, arms, beams, rails, hooks, struts) and torque tubes; not the screw jacks, gearboxes, fittings, bearings or the flaps";

/// Whole-wing totals.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SizingTotals {
    /// Mass of the sized members and torque tubes, kg ([`TOTAL_MASS_COVERS`]).
    pub mass_kg: f64,
    /// What `mass_kg` covers.
    pub mass_covers: &'static str,
    /// Peak drive power, W (with the safety factor, see [`DriveDemand::peak_power_w`]);
    /// `None` (null) when no drive line was sized (a scene without a torque tube).
    pub peak_power_w: Option<f64>,
    /// Work per deployment of the most demanding load case, J (no safety factor); `None`
    /// (null) when no drive line was sized.
    pub work_per_deployment_j: Option<f64>,
}

/// Sizing results: per rod the governing case, radius and mass; per actuator the peak
/// raise/lower torque and the motor torque; per torque tube the torque carried, radius
/// and mass; masses per station; totals; every warning of every part.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SizingReport {
    /// Sized rods.
    pub rods: Vec<RodSizing>,
    /// Sized actuators (screw jacks and rotary actuators), one per station. Written as
    /// `screw_jacks`, the report's field name from before the rename (issue 36): the wire
    /// name stays.
    #[serde(rename = "screw_jacks")]
    pub actuators: Vec<ActuatorSizing>,
    /// Sized torque tubes, far end first.
    pub torque_tubes: Vec<TorqueTubeSizing>,
    /// Drive motor demand, if a drive line was sized.
    pub drive: Option<DriveDemand>,
    /// Masses per station and in total.
    pub masses: MassBreakdown,
    /// Totals of mass, power and work.
    pub totals: SizingTotals,
    /// All warnings, in part order (rods, actuators, tubes).
    pub warnings: Vec<SizingWarning>,
}

impl SizingReport {
    /// Assembles the report and its totals from the sized parts.
    pub fn assemble(
        rods: Vec<RodSizing>,
        actuators: Vec<ActuatorSizing>,
        torque_tubes: Vec<TorqueTubeSizing>,
        drive: Option<DriveDemand>,
    ) -> Self {
        let mut items: Vec<MassItem> = rods
            .iter()
            .map(|r| MassItem {
                station: r.station.clone(),
                part: r.name.clone(),
                mass_kg: r.mass_kg,
            })
            .collect();
        items.extend(torque_tubes.iter().map(|t| MassItem {
            station: t.station.clone(),
            part: "torque tube".to_owned(),
            mass_kg: t.mass_kg,
        }));
        let masses = MassBreakdown::from_items(&items);
        let warnings = rods
            .iter()
            .flat_map(|r| r.warnings.iter())
            .chain(actuators.iter().flat_map(|s| s.warnings.iter()))
            .chain(torque_tubes.iter().flat_map(|t| t.warnings.iter()))
            .cloned()
            .collect();
        let totals = SizingTotals {
            mass_kg: masses.total_kg,
            mass_covers: TOTAL_MASS_COVERS,
            peak_power_w: drive.as_ref().map(|d| d.peak_power_w),
            work_per_deployment_j: drive
                .as_ref()
                .map(|d| d.work_per_deployment.iter().map(|w| w.work_j).fold(0.0, f64::max)),
        };
        Self {
            rods,
            actuators,
            torque_tubes,
            drive,
            masses,
            totals,
            warnings,
        }
    }
}
