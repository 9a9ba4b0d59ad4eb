//! Whether a station's actuator lies in the ranges real flap actuators have (issue 37): a
//! mechanism whose arithmetic is right can still need an actuator nobody builds. Each rule
//! compares one figure with public data and warns naming the figure; none fails the design.
//!
//! | figure | warned when | source |
//! |---|---|---|
//! | linear actuator's peak load / the station's air load | above [`MAX_LINEAR_LOAD_PER_AIR_LOAD`] | `003_...` Table 1's linear actuators carry 25.3-47.2 kN, 0.29-0.55 of the 86 kN air load `transport-flap` puts on its `ob-inner` (Table 1's case) |
//! | rotary actuator's peak torque / (air load x flap chord) | above [`MAX_ROTARY_TORQUE_PER_AIR_MOMENT`] | Table 1's link-track 12.1 kN m, 0.10 of 86 kN x 1.44 m; Rudolph's B767 six-bar 12.2-22.8 kN m (`003_...` section 5.1) |
//! | screw jack's stroke | below [`MIN_STROKE_M`] | flap ball-screw actuators of a business jet and a turboprop stroke 220 and 400 mm (rosner-tdl.de, "Landing flaps drive system", 12 kN and 4 kN each) |
//! | screw lead | below [`MIN_SCREW_LEAD_M`] | ball screws carrying kilonewtons have leads of a few millimetres and up; a finer lead turns the drive shaft hundreds of times a deployment |
//!
//! The air load is the largest normal force the scene's flight cases put on the station's
//! share of the flap (C_N q n S, `003_...` eq. 1); scenes without flight cases get no load
//! rule.

use flapwright_mechanism::seam::Actuator;
use flapwright_mechanism::LoadCase;

use crate::pipeline::record::MechanismReport;

/// See the module's table.
pub const MAX_LINEAR_LOAD_PER_AIR_LOAD: f64 = 1.0;
/// See the module's table (2.5 times Table 1's link-track).
pub const MAX_ROTARY_TORQUE_PER_AIR_MOMENT: f64 = 0.25;
/// See the module's table (half the shorter public stroke, m); the weighed screw-jack
/// placements take no shorter stroke without a penalty.
pub const MIN_STROKE_M: f64 = flapwright_mechanism::shared::objective::MIN_STROKE_M;
/// See the module's table (m).
pub const MIN_SCREW_LEAD_M: f64 = 0.002;

/// The largest normal force the flight cases put on the station's share of its flap (N):
/// the largest C_N of each case times its newtons per unit C_N. None without flight cases.
pub fn air_load_n(cases: &[LoadCase]) -> Option<f64> {
    cases
        .iter()
        .filter_map(|case| case.flap_normal_force.as_ref())
        .map(|force| {
            let largest = force.coefficients.iter().map(|(_, c)| c.abs()).fold(0.0, f64::max);
            largest * force.newtons_per_coefficient
        })
        .filter(|load| *load > 0.0)
        .reduce(f64::max)
}

/// Warnings for `station`'s actuator outside the ranges of the module's table, given its
/// load cases and the local flap chord (m, where known).
pub fn warnings(station: &str, report: &MechanismReport, cases: &[LoadCase], flap_chord_m: Option<f64>) -> Vec<String> {
    let mut found = Vec::new();
    let peak = report.peak_actuator_load();
    let air = air_load_n(cases);
    match &report.actuator {
        Actuator::ScrewJack { screw, .. } => {
            if let Some(air) = air {
                let ratio = peak / air;
                if ratio > MAX_LINEAR_LOAD_PER_AIR_LOAD {
                    found.push(format!(
                        "station {station}: the screw jack's peak load {:.1} kN is {ratio:.2} times the station's air load {:.1} kN (real flap actuators: 0.3-0.55, `003_...` Table 1; warned above {MAX_LINEAR_LOAD_PER_AIR_LOAD}): the mechanism has little mechanical advantage",
                        peak / 1e3,
                        air / 1e3
                    ));
                }
            }
            let stroke = (report.input.deployed - report.input.stowed).abs();
            if stroke < MIN_STROKE_M {
                found.push(format!(
                    "station {station}: the screw jack's stroke is {:.0} mm (real flap ball-screw actuators: 220-400 mm; warned below {:.0} mm): its nut's tolerances are a large share of the flap's travel",
                    stroke * 1e3,
                    MIN_STROKE_M * 1e3
                ));
            }
            if screw.lead_m < MIN_SCREW_LEAD_M {
                found.push(format!(
                    "station {station}: the screw's lead is {:.2} mm (warned below {:.0} mm, finer than ball screws carrying kilonewtons): give the screw fewer turns (`screw.turns`)",
                    screw.lead_m * 1e3,
                    MIN_SCREW_LEAD_M * 1e3
                ));
            }
        }
        Actuator::Rotary { .. } => {
            if let (Some(air), Some(chord)) = (air, flap_chord_m.filter(|c| *c > 0.0)) {
                let ratio = peak / (air * chord);
                if ratio > MAX_ROTARY_TORQUE_PER_AIR_MOMENT {
                    found.push(format!(
                        "station {station}: the rotary actuator's peak torque {:.1} kN m is {ratio:.2} times the station's air load times its flap chord ({:.1} kN x {chord:.2} m; `003_...` Table 1's link-track: 0.10; warned above {MAX_ROTARY_TORQUE_PER_AIR_MOMENT}): the mechanism has little mechanical advantage",
                        peak / 1e3,
                        air / 1e3
                    ));
                }
            }
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use flapwright_mechanism::shared::load_case::{ExternalMoment, FlapNormalForce};

    fn flight(rows: Vec<(f64, f64)>, newtons_per_coefficient: f64) -> LoadCase {
        LoadCase {
            name: "placard".into(),
            external_moment: ExternalMoment::Constant(0.0),
            include_inertia: false,
            flap_normal_force: Some(FlapNormalForce {
                coefficients: rows,
                newtons_per_coefficient,
                at_stowed_m: nalgebra::Point2::new(-0.4, 0.0),
                normal_stowed: nalgebra::Vector2::new(0.0, 1.0),
            }),
            load_factor: 2.0,
        }
    }

    /// `transport-flap`'s placard case at `ib-inner` by hand: q = 0.5 x 1.225 x 87² =
    /// 4,636 Pa, n = 2, S = 7.51 m² (its share), C_N 1.3 at 35 deg: 90.5 kN
    /// (`docs/transport-flap-figures.md`). The largest C_N of the table counts, whatever
    /// its row; a moment case has none.
    #[test]
    fn the_air_load_is_the_largest_normal_force_c_n_q_n_s() {
        let q = 0.5 * 1.225 * 87.0_f64.powi(2);
        let per_coefficient = q * 2.0 * 7.51;
        let rows = vec![(0.0, 0.3), (15f64.to_radians(), 0.8), (35f64.to_radians(), 1.3)];
        let air = air_load_n(&[flight(rows, per_coefficient)]).expect("a flight case");
        assert!((air - 90.5e3).abs() < 0.05e3, "{air}");
        let moment = LoadCase {
            flap_normal_force: None,
            ..flight(Vec::new(), 0.0)
        };
        assert_eq!(air_load_n(&[moment]), None);
    }
}
