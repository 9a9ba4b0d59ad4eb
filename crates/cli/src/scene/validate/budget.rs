//! Pre-flight estimate of the work a scene asks for, refused beyond a documented budget
//! before any stage starts (a run must not take hours or fill the disk because two knobs
//! were each set near their limit).
//!
//! The estimates are upper bounds of counts, not timings: report samples written, fairing
//! point queries, clearance-sweep evaluations, and wing-mesh triangles. Each budget is
//! about a hundred times what the default scene needs (`data/scenes/small-aircraft.toml`:
//! 2 stations, 2 load cases x 51 samples, 120 part pairs x 400 evaluations), so real
//! whole-wing scenes fit and a mistake is stopped in milliseconds.

use super::Checker;
use crate::scene::Scene;

/// Report samples (stations x load cases x deployment samples): about 0.7 kB of JSON
/// each, so the report stays under about 70 MB.
pub const MAX_REPORT_SAMPLES: usize = 100_000;
/// Fairing point queries (stations x moving parts x fairing samples x points per capsule).
pub const MAX_FAIRING_QUERIES: usize = 20_000_000;
/// Clearance evaluations (part pairs x `interference.max_evaluations`).
pub const MAX_CLEARANCE_EVALUATIONS: usize = 5_000_000;
/// Wing-mesh triangles (2 x points per side x spanwise stations at 4 per metre, doubled
/// for the flap).
pub const MAX_MESH_TRIANGLES: usize = 5_000_000;

/// Fixed (non-moving) parts counted per scene in the pair estimate: skin pieces, spars,
/// torque tube.
const FIXED_PARTS_ESTIMATE: usize = 8;
/// Spanwise mesh stations per metre (`geom::PartResolution` default).
const SPANWISE_STATIONS_PER_M: f64 = 4.0;

impl Checker<'_> {
    pub(super) fn budget(&mut self, scene: &Scene) {
        let stations = scene.station.len();
        let cases = scene.loads.cases.len().max(1);
        let res = &scene.resolution;
        let samples = stations * cases * res.deployment_samples;
        if scene.outputs.kinematics && samples > MAX_REPORT_SAMPLES {
            self.fail(
                "resolution.deployment_samples",
                format!(
                    "= {}: {stations} station(s) x {cases} load case(s) x {} samples = {samples} report samples, \
                     over the budget of {MAX_REPORT_SAMPLES}; lower resolution.deployment_samples or the number of load cases",
                    res.deployment_samples, res.deployment_samples
                ),
            );
        }
        if scene.wing.is_none() {
            return;
        }
        let moving: usize = scene.station.iter().map(|s| s.mechanism.kind().moving_parts()).sum();
        let fairing = moving * res.fairing_samples * res.fairing_points_per_capsule;
        if fairing > MAX_FAIRING_QUERIES {
            self.fail(
                "resolution.fairing_samples",
                format!(
                    "= {}: {moving} moving part(s) x {} samples x {} points per capsule = {fairing} point queries, \
                     over the budget of {MAX_FAIRING_QUERIES}; lower resolution.fairing_samples or resolution.fairing_points_per_capsule",
                    res.fairing_samples, res.fairing_samples, res.fairing_points_per_capsule
                ),
            );
        }
        if scene.outputs.interference {
            // Every moving part against the fixed parts and against every moving part of
            // the other stations (see `flapwright_interference::check`).
            let cross: usize = scene
                .station
                .iter()
                .enumerate()
                .map(|(i, a)| {
                    let others: usize = scene.station[i + 1..]
                        .iter()
                        .map(|b| b.mechanism.kind().moving_parts())
                        .sum();
                    a.mechanism.kind().moving_parts() * others
                })
                .sum();
            let pairs = moving * FIXED_PARTS_ESTIMATE + cross;
            let max_evaluations = scene.interference.max_evaluations;
            let evaluations = pairs.saturating_mul(max_evaluations);
            if evaluations > MAX_CLEARANCE_EVALUATIONS {
                self.fail(
                    "interference.max_evaluations",
                    format!(
                        "= {max_evaluations}: about {pairs} part pairs ({stations} stations) x {max_evaluations} evaluations = {evaluations}, \
                         over the budget of {MAX_CLEARANCE_EVALUATIONS}; lower interference.max_evaluations (and initial_samples), \
                         use fewer stations, or set outputs.interference = false"
                    ),
                );
            }
        }
        if let Some(wing) = &scene.wing {
            let span = match (wing.sections.first(), wing.sections.last()) {
                (Some(root), Some(tip)) => tip.y_m - root.y_m,
                _ => 0.0,
            };
            let rings = (span * SPANWISE_STATIONS_PER_M).ceil().max(1.0) as usize + wing.sections.len();
            let triangles = 2 * 2 * res.airfoil_points_per_side * rings * 2;
            if triangles > MAX_MESH_TRIANGLES {
                self.fail(
                    "resolution.airfoil_points_per_side",
                    format!(
                        "= {}: a {span} m span at {} points per side makes about {triangles} triangles, over the budget of \
                         {MAX_MESH_TRIANGLES}; lower resolution.airfoil_points_per_side",
                        res.airfoil_points_per_side, res.airfoil_points_per_side
                    ),
                );
            }
        }
    }
}
