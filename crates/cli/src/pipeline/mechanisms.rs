//! Mechanism stage: synthesise each station's mechanism and sweep it under every load case.

use anyhow::Result;
use std::sync::Arc;

use flapwright_mechanism::seam::{InputQuantity, InputRange};
use flapwright_mechanism::{
    sweep_deployment, CircularArcTrack, CircularArcTrackSpec, Deployment, ExternalMoment, FlapMechanism, LoadCase,
    ScrewJack, DEFAULT_TOGGLE_TOLERANCE_RAD,
};
use nalgebra::Point2;
use serde::Serialize;

use crate::scene::{CircularArcTrackScene, MechanismScene, Problem, Scene, SceneError};

/// Standard gravity used by the mechanism's weight term (m/s²), as the thesis (Table 2).
const GRAVITY_MPS2: f64 = 9.81;

/// Thesis step 9: "select a3 slightly greater than Δs + s34,i"; Table 2 has 250 mm for
/// 224.6 mm, so an unspecified screw is 10 % longer than the full stroke.
const SCREW_LENGTH_MARGIN: f64 = 1.10;

/// A synthesised station mechanism.
#[derive(Debug, Clone)]
pub struct StationMechanism {
    /// Station name.
    pub station: String,
    /// The synthesised mechanism, behind the seam: all the other stages see of it.
    pub mechanism: Arc<dyn FlapMechanism>,
}

/// The report's record of one station's mechanism: kind-neutral apart from `details`.
#[derive(Debug, Clone, Serialize)]
pub struct MechanismReport {
    /// Mechanism kind (the scene's `kind`).
    pub kind: &'static str,
    /// The actuator input: stroke (m) or angle (rad), stowed and deployed.
    pub input: InputRange,
    /// The kind's own record: its dimensions and what synthesis computed.
    pub details: serde_json::Value,
    /// One deployment per load case.
    pub load_cases: Vec<Deployment>,
}

fn spec_from_scene(m: &CircularArcTrackScene, screw_length_m: f64) -> CircularArcTrackSpec {
    CircularArcTrackSpec {
        base_distance_m: m.base_distance_m,
        crank_length_m: m.crank_length_m,
        screw_length_m,
        base_angle_rad: m.base_angle_deg.to_radians(),
        outer_slot_radius_m: m.outer_slot_radius_m,
        inner_slot_radius_m: m.inner_slot_radius_m,
        outer_slot_start_angle_rad: m.slot_start_angle_deg.to_radians(),
        inner_slot_offset_angle_rad: m.slot_offset_angle_deg.to_radians(),
        rotation_range_rad: m.rotation_range_deg.to_radians(),
        centre_of_mass_stowed_m: Point2::new(m.flap_centre_of_mass_m[0], m.flap_centre_of_mass_m[1]),
        flap_mass_kg: m.flap_mass_kg,
        flap_moment_of_inertia_kgm2: 0.0,
        gravity_mps2: GRAVITY_MPS2,
        screw: ScrewJack {
            lead_m: m.screw_lead_m,
            mean_radius_m: m.screw_mean_radius_m,
            friction_coefficient: m.screw_friction,
        },
        nominal_input_speed_mps: m.nut_speed_mps,
        nominal_input_accel_mps2: 0.0,
        toggle_tolerance_rad: DEFAULT_TOGGLE_TOLERANCE_RAD,
    }
}

fn synthesise(m: &CircularArcTrackScene) -> flapwright_mechanism::Result<CircularArcTrack> {
    match m.screw_length_m {
        Some(length) => CircularArcTrack::synthesise(spec_from_scene(m, length)),
        None => {
            // Synthesise once with an unbounded screw to learn the stroke, then size it.
            let probe = CircularArcTrack::synthesise(spec_from_scene(m, f64::MAX))?;
            let length = SCREW_LENGTH_MARGIN * probe.synthesis().stroke_end_m;
            CircularArcTrack::synthesise(spec_from_scene(m, length))
        }
    }
}

/// Synthesises every station; a mechanism that cannot be built from its dimensions is bad
/// input, reported with the station's path like any other scene problem.
pub fn synthesise_all(scene: &Scene) -> Result<Vec<StationMechanism>> {
    let mut problems = Vec::new();
    let mut built = Vec::new();
    for (i, station) in scene.station.iter().enumerate() {
        let MechanismScene::CircularArcTrack(m) = &station.mechanism;
        match synthesise(m) {
            Ok(track) => {
                problems.extend(degeneracies(
                    &track,
                    &format!("station[{i}].mechanism"),
                    SCREW_GEOMETRY_KEYS,
                ));
                built.push(StationMechanism {
                    station: station.name.clone(),
                    mechanism: Arc::new(track),
                })
            }
            Err(error) => problems.push(Problem {
                path: format!("station[{i}].mechanism"),
                message: match error {
                    flapwright_mechanism::Error::NutOnScrewPivot { .. }
                    | flapwright_mechanism::Error::CollinearityImpossible { .. } => {
                        format!("cannot be synthesised: {error}; change {SCREW_GEOMETRY_KEYS}")
                    }
                    _ => format!("cannot be synthesised: {error}"),
                },
            }),
        }
    }
    if problems.is_empty() {
        Ok(built)
    } else {
        Err(SceneError::Invalid(problems).into())
    }
}

/// Largest Jacobian condition number accepted at the stroke ends: beyond it a
/// millimetre of input error moves the flap by kilometres, and the forces are noise (the
/// thesis mechanism stays below 20).
pub const MAX_CONDITION_NUMBER: f64 = 1e8;
/// Smallest distance to a toggle position at the stroke ends, deg.
pub const MIN_DISTANCE_TO_TOGGLE_DEG: f64 = 1.0;
/// The keys that place the screw line and the nut's travel.
const SCREW_GEOMETRY_KEYS: &str = "base_distance_m, base_angle_deg, crank_length_m and rotation_range_deg";

/// Dimensions that synthesise but give a degenerate mechanism, for any kind: a singular or
/// near-toggle position at a stroke end, a deployment that cannot even start. Each names
/// `keys`, the scene keys that decide the kind's geometry, with the numbers in mm and
/// degrees.
fn degeneracies(mechanism: &dyn FlapMechanism, path: &str, keys: &str) -> Vec<Problem> {
    let mut problems = Vec::new();
    let unloaded = LoadCase {
        name: "unloaded".into(),
        external_moment: ExternalMoment::Constant(0.0),
        include_inertia: false,
    };
    let quantity = mechanism.input_range().quantity;
    let probe = match sweep_deployment(mechanism, 2, &unloaded) {
        Ok(probe) => probe,
        Err(error) => {
            problems.push(Problem::new(
                path,
                format!("cannot be posed at its stroke ends: {error}"),
            ));
            return problems;
        }
    };
    if let Some(stop) = &probe.stopped {
        problems.push(Problem::new(
            path,
            format!(
                "cannot be posed at input {}: {}; change {keys}",
                describe_input(quantity, stop.input),
                stop.reason
            ),
        ));
    }
    for (end, sample) in ["stowed", "deployed"].iter().zip(&probe.samples) {
        if sample.jacobian_condition_number.is_nan() || sample.jacobian_condition_number > MAX_CONDITION_NUMBER {
            problems.push(Problem::new(
                path,
                format!(
                    "singular at the {end} end (input {}): Jacobian condition number {:.3e} above {MAX_CONDITION_NUMBER:e}; change {keys}",
                    describe_input(quantity, sample.input),
                    sample.jacobian_condition_number
                ),
            ));
        } else if sample.distance_to_toggle_deg.is_nan() || sample.distance_to_toggle_deg < MIN_DISTANCE_TO_TOGGLE_DEG {
            problems.push(Problem::new(
                path,
                format!(
                    "{:.3} deg from a toggle position at the {end} end (at least {MIN_DISTANCE_TO_TOGGLE_DEG} deg); change {keys}",
                    sample.distance_to_toggle_deg
                ),
            ));
        }
    }
    problems
}

/// The scene's load cases in the mechanism crate's terms.
pub fn load_cases(scene: &Scene) -> Vec<LoadCase> {
    scene
        .loads
        .cases
        .iter()
        .map(|case| LoadCase {
            name: case.name.clone(),
            external_moment: match (case.moment_nm, case.moment_stowed_nm, case.moment_deployed_nm) {
                (Some(moment), _, _) => ExternalMoment::Constant(moment),
                (None, Some(stowed_nm), Some(deployed_nm)) => ExternalMoment::Linear { stowed_nm, deployed_nm },
                // Validation guarantees one of the two forms; no moment is the honest fallback.
                _ => ExternalMoment::Constant(0.0),
            },
            include_inertia: false,
        })
        .collect()
}

/// Sweeps one station under every load case (a weight-only case when the scene has none).
pub fn sweep_station(
    mechanism: &StationMechanism,
    cases: &[LoadCase],
    samples: usize,
    warnings: &mut Vec<String>,
) -> Result<MechanismReport> {
    let weight_only = [LoadCase {
        name: "weight-only".into(),
        external_moment: ExternalMoment::Constant(0.0),
        include_inertia: false,
    }];
    let cases = if cases.is_empty() { &weight_only[..] } else { cases };
    let seam = mechanism.mechanism.as_ref();
    for warning in seam.warnings() {
        warnings.push(format!("station {}: {warning}", mechanism.station));
    }
    let input = seam.input_range();
    let mut deployments = Vec::with_capacity(cases.len());
    for case in cases {
        let deployment = sweep_deployment(seam, samples, case)?;
        if let Some(stop) = &deployment.stopped {
            warnings.push(format!(
                "station {}, load case {}: deployment stopped at sample {} (input {}): {}",
                mechanism.station,
                case.name,
                stop.sample_index,
                describe_input(input.quantity, stop.input),
                stop.reason
            ));
        }
        deployments.push(deployment);
    }
    Ok(MechanismReport {
        kind: seam.kind(),
        input,
        details: seam.details(),
        load_cases: deployments,
    })
}

/// An input value as people read it: a stroke in mm, an angle in degrees.
pub fn describe_input(quantity: InputQuantity, input: f64) -> String {
    match quantity {
        InputQuantity::Stroke => format!("{:.3} mm", input * 1e3),
        InputQuantity::Angle => format!("{:.3} deg", input.to_degrees()),
    }
}
