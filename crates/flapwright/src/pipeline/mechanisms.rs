//! Mechanism stage: synthesise each station's mechanism and sweep it under every load case.

use std::f64::consts::TAU;

use rayon::prelude::*;

use flapwright_mechanism::seam::{Actuator, InputQuantity};
use flapwright_mechanism::{sweep_deployment, ExternalMoment, FlapMechanism, LoadCase};

use crate::error::Result;
use crate::kinds::SynthesisContext;
use crate::pipeline::flap_position;
use crate::pipeline::flight_loads::{self, weight_only};
use crate::pipeline::record::{
    flaps_on_several_stations, FlapMotionMiss, MechanismReport, PlacedStation, StationRecord,
};
use crate::scene::{Problem, Scene, SceneError};
use flapwright_geom::parts::WingModel;

/// Synthesises every station, each with its placed plane where the scene has a wing
/// (`placed`, in station order; empty without one); a mechanism that cannot be built from
/// its dimensions or the flap settings is bad input, reported with the station's path like
/// any other scene problem.
///
/// `sized` gives per station (scene order; missing entries are none) the radii the sizing
/// loop asked of its drawn solids (`pipeline::sizing_loop`).
pub fn synthesise_all(
    scene: &Scene,
    model: Option<&WingModel>,
    placed: Vec<PlacedStation>,
    sized: &[crate::kinds::SizedHardware],
) -> Result<Vec<StationRecord>> {
    let mut problems = Vec::new();
    // Each station's share of its flap's flight load, before synthesis: the searches weigh
    // the actuator's load under the scene's load cases.
    let shares = match model {
        Some(model) if scene.loads.cases.iter().any(|c| c.is_flight_condition()) => {
            let stations: Vec<(Option<&str>, Option<&PlacedStation>)> = scene
                .station
                .iter()
                .enumerate()
                .map(|(i, s)| (s.flap.as_deref(), placed.get(i)))
                .collect();
            flight_loads::station_shares(scene, model, &stations)?
        }
        _ => vec![None; scene.station.len()],
    };
    let mass_weighing = mass_weighing(scene)?;
    // The synthesis inputs of every station first: the stations of one flap share its
    // rigid poses at the settings.
    let mut placed = placed.into_iter();
    let mut inputs = Vec::new();
    for (i, station) in scene.station.iter().enumerate() {
        let path = format!("station[{i}].mechanism");
        let placed = placed.next();
        let flap = station
            .flap
            .as_ref()
            .and_then(|name| scene.flap.iter().find(|f| &f.name == name));
        let (context, flap_behind_wing) = match (&placed, flap) {
            (Some(placed), Some(flap)) => match flap_position::synthesis_context(
                flap,
                &scene.flap,
                placed,
                scene.interference.required_clearance_m,
            ) {
                Ok(found) => found,
                Err(error) => {
                    problems.push(Problem::new(path, error.chain_message()));
                    (SynthesisContext::default(), None)
                }
            },
            _ => (SynthesisContext::default(), None),
        };
        let mut context = context;
        let share = shares.get(i).copied().flatten();
        context.design_loads = if scene.loads.cases.is_empty() {
            vec![weight_only()]
        } else {
            scene
                .loads
                .cases
                .iter()
                .map(|case| flight_loads::load_case_on(case, share))
                .collect()
        };
        context.actuator_load_weight = scene.design.actuator_load_weight;
        context.rotary_actuator_load_weight = scene.design.rotary_actuator_load_weight;
        context.four_bar_actuator_load_cap = scene.design.four_bar_actuator_load_cap;
        context.mass_weighing = mass_weighing;
        context.sized = sized.get(i).copied().unwrap_or_default();
        inputs.push((placed, context, flap_behind_wing, Vec::new()));
    }
    if !problems.is_empty() {
        return Err(SceneError::Invalid(problems).into());
    }
    for flap in &scene.flap {
        let mut carriers: Vec<(usize, &PlacedStation, &mut SynthesisContext)> = Vec::new();
        for (i, (placed, context, _, _)) in inputs.iter_mut().enumerate() {
            if let (Some(placed), true) = (placed.as_ref(), scene.station[i].flap.as_ref() == Some(&flap.name)) {
                carriers.push((i, placed, context));
            }
        }
        let indices: Vec<usize> = carriers.iter().map(|(i, _, _)| *i).collect();
        let mut pairs: Vec<(&PlacedStation, &mut SynthesisContext)> =
            carriers.into_iter().map(|(_, p, c)| (p, c)).collect();
        let changes = flap_position::rigid_flap_settings(&flap.name, &mut pairs)?;
        for (i, change) in indices.into_iter().zip(changes) {
            inputs[i].3 = change;
        }
    }
    // The stations of one flap are synthesised in order (the first leads, the others follow
    // it); the flaps in parallel, the results put back in station order.
    let mut groups: Vec<(Option<String>, FlapGroup)> = Vec::new();
    for (i, input) in inputs.into_iter().enumerate() {
        let flap = scene.station[i].flap.clone();
        match groups.iter_mut().find(|(f, _)| flap.is_some() && *f == flap) {
            Some((_, group)) => group.push((i, input)),
            None => groups.push((flap, vec![(i, input)])),
        }
    }
    let mut synthesised: Vec<(usize, Vec<Problem>, Option<StationRecord>)> = groups
        .into_par_iter()
        .flat_map_iter(|(_, group)| synthesise_flap(scene, &shares, group))
        .collect();
    synthesised.sort_by_key(|(i, _, _)| *i);
    let mut built = Vec::new();
    for (_, station_problems, record) in synthesised {
        problems.extend(station_problems);
        built.extend(record);
    }
    if problems.is_empty() && scene.structure.torque_tube.is_some() {
        problems.extend(one_drive_speed(&built));
    }
    if problems.is_empty() {
        Ok(built)
    } else {
        Err(SceneError::Invalid(problems).into())
    }
}

/// What a station's synthesis starts from: its placed plane, its context, the flap behind
/// the wing it measured and how the rigid flap moved its settings.
type StationInput = (
    Option<PlacedStation>,
    SynthesisContext,
    Option<flapwright_planes::FlapBehindWing>,
    Vec<crate::pipeline::record::RigidFlapSetting>,
);

/// The stations of one flap, in station order, with their indices.
type FlapGroup = Vec<(usize, StationInput)>;

/// Synthesises the stations of one flap (`group`, in station order, with their indices):
/// the first one searched alone, the others following it (`SynthesisContext::companion`,
/// `SynthesisContext::followed`). Per station its index, its problems and its record.
fn synthesise_flap(
    scene: &Scene,
    shares: &[Option<crate::pipeline::record::FlapLoadShare>],
    group: FlapGroup,
) -> Vec<(usize, Vec<Problem>, Option<StationRecord>)> {
    let mut results: Vec<(usize, Vec<Problem>, Option<StationRecord>)> = Vec::new();
    let mut companion: Option<crate::kinds::Companion> = None;
    // The station synthesised first (its place in `results`) and its take-off.
    let mut lead: Option<(usize, flapwright_mechanism::PrecisionPosition)> = None;
    // The first station's context, to synthesise it again following the second.
    let mut lead_context: Option<SynthesisContext> = None;
    // Each station's take-off, in the order of `results`.
    let mut takeoffs: Vec<Option<flapwright_mechanism::PrecisionPosition>> = Vec::new();
    for (i, (placed, mut context, flap_behind_wing, rigid_flap)) in group {
        let station = &scene.station[i];
        let path = format!("station[{i}].mechanism");
        let kind = station.mechanism.kind();
        let flap = station.flap.clone().unwrap_or_default();
        let mut problems = Vec::new();
        context.companion = companion.clone();
        context.followed = match (&lead, &placed) {
            (Some((index, takeoff)), Some(placed)) => results[*index]
                .2
                .as_ref()
                .and_then(|record| crate::pipeline::flap_motion::followed_motion(record, takeoff, placed, &flap)),
            _ => None,
        };
        let record = match kind.synthesise(&context) {
            Ok(mechanism) => {
                if let (None, Some((takeoff, _)), false) = (&lead, context.settings, flap.is_empty()) {
                    lead = Some((results.len(), takeoff));
                    lead_context = Some(context.clone());
                }
                if context.companion.is_none() {
                    if let Some(outline) = &context.outline {
                        let attachments = mechanism
                            .flap_attachments()
                            .iter()
                            .filter(|a| !a.fixed)
                            .filter_map(|a| outline.to_flap_point(a.position))
                            .collect();
                        let range = mechanism.input_range();
                        let samples = crate::kinds::COMPANION_SAMPLES;
                        let deflections_rad = (0..=samples)
                            .map(|k| mechanism.deflection_at_input(range.at_fraction(k as f64 / samples as f64)))
                            .collect::<Result<Vec<_>, _>>();
                        if let Ok(deflections_rad) = deflections_rad {
                            companion = Some(crate::kinds::Companion {
                                station: station.name.clone(),
                                attachments,
                                deflections_rad,
                            });
                        }
                    }
                }
                problems.extend(degeneracies(mechanism.as_ref(), &path, kind.geometry_keys()));
                problems.extend(short_of_landing(
                    scene,
                    i,
                    mechanism.as_ref(),
                    &path,
                    kind.geometry_keys(),
                ));
                Some(StationRecord {
                    station: station.name.clone(),
                    index: i,
                    flap: station.flap.clone(),
                    mechanism,
                    placed,
                    flap_behind_wing,
                    flap_position: None,
                    rigid_flap,
                    fairing: None,
                    kinematics: None,
                    flap_load_share: shares.get(i).copied().flatten(),
                    flap_motion_miss: None,
                })
            }
            Err(message) => {
                problems.push(Problem { path, message });
                None
            }
        };
        takeoffs.push(context.settings.map(|(takeoff, _)| takeoff));
        results.push((i, problems, record));
    }
    // The first station searched alone chose the flap's path; the second came as near it as
    // its own free choices allow. Where the kind follows motions, the first is searched
    // again following the second, so that the two meet between their paths (on
    // `transport-flap`'s inboard flap on link-tracks the second alone could not come within
    // 8 mm of the first's path, and the fitted flap passed 2.4 mm from the wing).
    if let (Some((first, _)), Some(context)) = (lead, lead_context) {
        let second = results
            .iter()
            .enumerate()
            .skip(first + 1)
            .find_map(|(k, (_, _, record))| record.as_ref().map(|r| (k, r)));
        let kind = scene.station[results[first].0].mechanism.kind();
        if let (Some((k, second)), true) = (second, kind.follows_motion()) {
            let flap = second.flap.clone().unwrap_or_default();
            let takeoff = takeoffs[k];
            let followed = match (takeoff, results[first].2.as_ref().and_then(|r| r.placed.as_ref())) {
                (Some(takeoff), Some(placed)) => {
                    crate::pipeline::flap_motion::followed_motion(second, &takeoff, placed, &flap)
                }
                _ => None,
            };
            if let Some(followed) = followed {
                let context = SynthesisContext {
                    followed: Some(followed),
                    ..context
                };
                if let (Ok(mechanism), Some(record)) = (kind.synthesise(&context), results[first].2.as_mut()) {
                    record.mechanism = mechanism;
                }
            }
        }
    }
    results
}

/// How the screw jacks' placements weigh the mass they add: `[design]
/// mechanism_mass_weight` with the `[sizing]` link and screw materials and the safety factor
/// the sizing stage applies; `None` where the weight is 0.
fn mass_weighing(scene: &Scene) -> Result<Option<flapwright_mechanism::shared::objective::MassWeighing>> {
    use flapwright_mechanism::shared::objective::{MassWeighing, MemberMaterial};
    if scene.design.mechanism_mass_weight <= 0.0 {
        return Ok(None);
    }
    let member = |name: &str| -> Result<MemberMaterial> {
        let m = crate::pipeline::sizing::material(scene, name)?;
        Ok(MemberMaterial {
            density_kg_m3: m.density_kg_m3,
            allowable_pa: m.allowable_tensile_pa,
            youngs_modulus_pa: m.youngs_modulus_pa,
        })
    };
    Ok(Some(MassWeighing {
        weight: scene.design.mechanism_mass_weight,
        link: member(&scene.sizing.link_material)?,
        screw: member(&scene.sizing.screw_material)?,
        safety_factor: scene
            .loads
            .safety_factor
            .unwrap_or(flapwright_sizing::CS25_SAFETY_FACTOR),
        screw_end_fixity_factor: scene.sizing.screw_end_fixity_factor,
    }))
}

/// A kind given by its dimensions (the five-bar: its range is known once it is assembled)
/// that cannot turn its flap to the flap's landing setting, as a problem naming the
/// station's mechanism and the setting (the gap-overlap stage poses the flap there).
fn short_of_landing(
    scene: &Scene,
    i: usize,
    mechanism: &dyn FlapMechanism,
    path: &str,
    geometry_keys: &str,
) -> Option<Problem> {
    let station = &scene.station[i];
    if station.mechanism.is_synthesised() {
        return None;
    }
    let name = station.flap.as_ref()?;
    let (f, flap) = scene.flap.iter().enumerate().find(|(_, f)| &f.name == name)?;
    let range_deg = mechanism.deflection_range_rad().to_degrees();
    let landing_deg = flap.settings.landing_deg;
    (range_deg + 1e-9 < landing_deg).then(|| {
        Problem::new(
            path.to_string(),
            format!(
                "turns the flap through {} deg at most, short of its landing setting flap[{f}].settings.landing_deg = {}: change {geometry_keys}, or the setting",
                crate::scene::number(range_deg),
                crate::scene::number(landing_deg)
            ),
        )
    })
}

/// Largest Jacobian condition number accepted at the stroke ends: beyond it a
/// millimetre of input error moves the flap by kilometres, and the forces are noise (the
/// thesis mechanism stays below 20).
pub const MAX_CONDITION_NUMBER: f64 = 1e8;
/// Smallest distance to a toggle position at the stroke ends, deg.
pub const MIN_DISTANCE_TO_TOGGLE_DEG: f64 = 1.0;

/// One torque tube turns every actuator together, so the stations' deployments must run
/// in step: every drive shaft turns at one speed (for a screw jack nut speed / lead, for a
/// rotary actuator output speed x gear ratio) and the same number of turns over the
/// deployment, so that every station is at the same fraction of its input at every shaft
/// angle, as the whole-wing stages assume (the drive fraction of
/// `flapwright_mechanism::seam`).
fn one_drive_speed(mechanisms: &[StationRecord]) -> Vec<Problem> {
    let screw = |m: &StationRecord| {
        let actuator = m.mechanism.actuator();
        let turns = m.mechanism.input_range().travel().abs() * actuator.shaft_angle_per_input() / TAU;
        let what = match actuator {
            Actuator::ScrewJack { .. } => "its screw turns {} rev/s at its nominal nut speed",
            Actuator::Rotary { .. } => "its rotary actuator's drive shaft turns {} rev/s at its nominal speed",
        };
        (actuator.shaft_speed_radps() / TAU, turns, what)
    };
    let Some(first) = mechanisms.first() else {
        return Vec::new();
    };
    let (first_speed, first_turns, _) = screw(first);
    let differ = |a: f64, b: f64| (a - b).abs() > 1e-6 * b.abs();
    let mut problems = Vec::new();
    for m in &mechanisms[1..] {
        let (speed, turns, what) = screw(m);
        let path = format!("station[{}].mechanism", m.index);
        if differ(speed, first_speed) {
            problems.push(Problem::new(
                path.clone(),
                format!(
                    "{}, station {}'s {first_speed:.4} rev/s; one torque tube drives every screw at one speed: make nut_speed_mps / screw_lead_m equal (synthesised kinds: the same turns / deployment_time_s in screw or rotary)",
                    what.replace("{}", &format!("{speed:.4}")),
                    first.station
                ),
            ));
        }
        if differ(turns, first_turns) {
            problems.push(Problem::new(
                path,
                format!(
                    "its screw turns {turns:.3} times over the deployment, station {}'s {first_turns:.3}; one torque tube turns every screw together, so the stations would not finish together: make the nut stroke / screw_lead_m equal (synthesised kinds: the same turns in screw or rotary)",
                    first.station
                ),
            ));
        }
    }
    problems
}

/// Largest miss (m) of the rigid flap's fitted motion at any of its stations' section
/// points that passes without a warning, as a fraction of the flap chord there: the
/// attachments' spherical bearings and the flap's flexibility take up millimetres.
pub const FLAP_FIT_WARNING_CHORD_FRACTION: f64 = 0.005;

/// Drive fractions the fitted flap motion is sampled at for [`flap_agreement`].
const FLAP_FIT_SAMPLES: usize = 32;

/// Measures, per station of a flap carried by several, how far it moves the flap off the
/// rigid motion fitted to them all (`StationRecord::flap_motion_miss`), and warns where
/// they move it more than [`FLAP_FIT_WARNING_CHORD_FRACTION`] of the local chord apart:
/// the flap moves by the fitted motion (the interference check's,
/// `flapwright_interference::FittedFlapMotion`), and the stations' attachments take up
/// the rest.
pub fn flap_agreement(records: &mut [StationRecord]) -> Vec<String> {
    let mut warnings = Vec::new();
    let mut misses: Vec<(usize, FlapMotionMiss)> = Vec::new();
    for (flap, carriers) in flaps_on_several_stations(records) {
        let Ok(motion) = crate::pipeline::flap_motion::fitted_flap_motion(
            flap,
            flapwright_interference::FlapElement::Main,
            &carriers,
            &[],
        ) else {
            continue;
        };
        let mut largest = vec![(0.0_f64, 0.0_f64); carriers.len()];
        let (mut worst, mut at) = (0.0_f64, 0.0);
        for k in 0..=FLAP_FIT_SAMPLES {
            let fraction = k as f64 / FLAP_FIT_SAMPLES as f64;
            if let Ok((fit, station_misses)) = motion.carrier_misses_at(fraction) {
                if fit.max_m > worst {
                    (worst, at) = (fit.max_m, fraction);
                }
                for (l, miss) in largest.iter_mut().zip(station_misses) {
                    if miss > l.0 {
                        *l = (miss, fraction);
                    }
                }
            }
        }
        let chord_of = |r: &StationRecord| r.flap_behind_wing.as_ref().map(|m| m.chord_m());
        for (record, (largest_m, at_fraction)) in carriers.iter().zip(largest) {
            if let Some(chord) = chord_of(record) {
                misses.push((
                    record.index,
                    FlapMotionMiss {
                        largest_m,
                        at_fraction,
                        percent_local_chord: 100.0 * largest_m / chord,
                    },
                ));
            }
        }
        let chord = carriers
            .iter()
            .filter_map(|r| chord_of(r))
            .fold(f64::INFINITY, f64::min);
        if worst > chord * FLAP_FIT_WARNING_CHORD_FRACTION {
            let names: Vec<&str> = carriers.iter().map(|r| r.station.as_str()).collect();
            warnings.push(format!(
                "flap {flap}: its stations {} move it up to {:.1} mm apart from any rigid motion (at {:.1} % of the deployment; more than {} % of the local chord): the rigid flap follows the motion fitted to them all, and their attachments must take up the rest",
                names.join(", "),
                worst * 1e3,
                at * 100.0,
                FLAP_FIT_WARNING_CHORD_FRACTION * 100.0
            ));
        }
    }
    for (index, miss) in misses {
        if let Some(record) = records.iter_mut().find(|r| r.index == index) {
            record.flap_motion_miss = Some(miss);
        }
    }
    warnings
}

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
        flap_normal_force: None,
        load_factor: 1.0,
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

/// Sweeps one station under every load case (a weight-only case when the scene has none).
pub fn sweep_station(
    mechanism: &StationRecord,
    cases: &[LoadCase],
    samples: usize,
    warnings: &mut Vec<String>,
) -> Result<MechanismReport> {
    let weight_only = [weight_only()];
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
        actuator: seam.actuator(),
        details: seam.details(),
        load_cases: deployments,
        flap_load_share: mechanism
            .flap_load_share
            .filter(|_| cases.iter().any(|c| c.flap_normal_force.is_some())),
    })
}

/// An input value as people read it: a stroke in mm, an angle in degrees.
pub fn describe_input(quantity: InputQuantity, input: f64) -> String {
    match quantity {
        InputQuantity::Stroke => format!("{:.3} mm", input * 1e3),
        InputQuantity::Angle => format!("{:.3} deg", input.to_degrees()),
    }
}
