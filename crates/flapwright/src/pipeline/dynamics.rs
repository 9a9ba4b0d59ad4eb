//! The dynamics stage (`[dynamics]`): every station deployed by the scene's DC motor
//! (`flapwright-dynamics`). A kind that models its masses and loads itself
//! (`FlapMechanism::dynamics`: the five-bar) gives its equation of motion in its own input;
//! any other is a rigid flap on massless links (`flapwright_mechanism::rigid_flap`) driven
//! through its actuator's shaft, with its flap share's mass, a moment of inertia from the
//! flap section in the station plane (the mass spread like the section's area), and the
//! scene's first load case (weight only without one). Each run's time history goes into the
//! report and onto a plot page, `dynamics-<station>.svg`.

use flapwright_drawing::{Plot, Series};
use flapwright_dynamics::{integrate, DynamicsRun};
use flapwright_mechanism::generalised::OneInputDynamics;
use flapwright_mechanism::RigidFlapDynamics;
use nalgebra::Point2;
use serde::Serialize;

use crate::error::{Error, Result};
use crate::pipeline::flight_loads::{load_cases, weight_only};
use crate::pipeline::record::StationRecord;
use crate::scene::{DynamicsScene, Scene};
use crate::sink::Sink;

/// A station's deployment under the motor.
#[derive(Debug, Clone, Serialize)]
pub struct DynamicsReport {
    /// The equation of motion: the kind's own, or a rigid flap on massless links.
    pub model: EquationOfMotion,
    /// Armature inductance (H) and supply voltage (V) it ran with.
    pub inductance_h: f64,
    /// Supply voltage (V).
    pub supply_volts: f64,
    /// The run: method, tolerance, time history, deployment and breakaway times, peaks,
    /// solver counts, energy balance.
    #[serde(flatten)]
    pub run: DynamicsRun,
}

/// Where a station's equation of motion comes from.
#[derive(Debug, Clone, Serialize)]
#[serde(tag = "type", rename_all = "kebab-case")]
pub enum EquationOfMotion {
    /// The kind models its bodies' masses and its loads; the input is the kind's own.
    Kind,
    /// The flap the one body with mass; the input is the actuator's drive-shaft angle from
    /// stowed (rad).
    RigidFlap {
        /// The flap share's mass (kg).
        mass_kg: f64,
        /// Its moment of inertia about its centre of mass (kg m²).
        inertia_kgm2: f64,
        /// The load case it deploys under.
        load_case: String,
    },
}

/// Runs every station; errors name a station whose equation of motion cannot be written.
pub fn run_all(
    scene: &Scene,
    settings: &DynamicsScene,
    records: &[StationRecord],
) -> Result<Vec<(String, DynamicsReport)>> {
    let (drive, supply, integration) = settings.parts();
    records
        .iter()
        .map(|record| {
            let deploy = |system: &dyn OneInputDynamics, model: EquationOfMotion| -> Result<(String, DynamicsReport)> {
                let run = integrate(system, &drive, &supply, &integration).map_err(|source| Error::Deploying {
                    station: record.station.clone(),
                    source,
                })?;
                Ok((
                    record.station.clone(),
                    DynamicsReport {
                        model,
                        inductance_h: drive.motor.inductance_h,
                        supply_volts: supply.volts,
                        run,
                    },
                ))
            };
            let mechanism = record.mechanism.as_ref();
            if let Some(system) = mechanism.dynamics() {
                return deploy(system, EquationOfMotion::Kind);
            }
            let named = |needs: &'static str| Error::DynamicsNeeds {
                station: record.station.clone(),
                kind: mechanism.kind(),
                needs,
            };
            let mass = mechanism
                .flap_mass()
                .ok_or_else(|| named("a kind that gives its flap's mass"))?;
            let flap = record
                .placed
                .as_ref()
                .and_then(|placed| record.flap.as_deref().map(|flap| placed.flap_polygons(flap)))
                .unwrap_or_default();
            let radius_of_gyration_squared = polar_radius_of_gyration_squared(&flap)
                .ok_or_else(|| named("the flap's section in the station plane (a moment of inertia from its area)"))?;
            let inertia_kgm2 = mass.mass_kg * radius_of_gyration_squared;
            let load = load_cases(scene, record).into_iter().next().unwrap_or_else(weight_only);
            let system = RigidFlapDynamics::new(mechanism, mass, inertia_kgm2, &load).map_err(|source| {
                Error::RigidFlapDynamics {
                    station: record.station.clone(),
                    source,
                }
            })?;
            deploy(
                &system,
                EquationOfMotion::RigidFlap {
                    mass_kg: mass.mass_kg,
                    inertia_kgm2,
                    load_case: load.name.clone(),
                },
            )
        })
        .collect()
}

/// The polar moment of area of `polygons` about their centroid over their area (m²): the
/// squared radius of gyration of a section whose mass is spread like its area. Each
/// polygon counts with its own orientation made positive. None without area.
fn polar_radius_of_gyration_squared(polygons: &[Vec<Point2<f64>>]) -> Option<f64> {
    let (mut area, mut first, mut second) = (0.0, nalgebra::Vector2::zeros(), 0.0);
    for polygon in polygons {
        let (mut a, mut f, mut s) = (0.0, nalgebra::Vector2::zeros(), 0.0);
        for (i, p) in polygon.iter().enumerate() {
            let q = polygon[(i + 1) % polygon.len()];
            let cross = p.x * q.y - q.x * p.y;
            a += 0.5 * cross;
            f += (p.coords + q.coords) * (cross / 6.0);
            s += cross * (p.x * p.x + p.x * q.x + q.x * q.x + p.y * p.y + p.y * q.y + q.y * q.y) / 12.0;
        }
        let sign = a.signum();
        area += a * sign;
        first += f * sign;
        second += s * sign;
    }
    if area.is_nan() || area <= 0.0 {
        return None;
    }
    let centroid = first / area;
    let about_centroid = second - area * centroid.norm_squared();
    (about_centroid > 0.0).then_some(about_centroid / area)
}

/// Writes `dynamics-<station>.svg` for each run; returns the file names.
pub fn write_plots(scene_name: &str, runs: &[(String, DynamicsReport)], out: &dyn Sink) -> Result<Vec<String>> {
    let mut files = Vec::new();
    for (station, report) in runs {
        let samples = &report.run.samples;
        let chart = |title: &str, y_label: &str, y: &dyn Fn(&flapwright_dynamics::DynamicsSample) -> f64| Plot {
            title: title.into(),
            x_label: "time [s]".into(),
            y_label: y_label.into(),
            series: vec![Series {
                name: title.into(),
                points: samples.iter().map(|s| (s.time_s, y(s))).collect(),
            }],
        };
        let plots = [
            chart("input", "input [deg]", &|s| s.input.to_degrees()),
            chart("input rate", "rate [deg/s]", &|s| s.rate.to_degrees()),
            chart("armature current", "current [A]", &|s| s.current_a),
            chart("motor torque", "torque [N m]", &|s| s.motor_torque_nm),
        ];
        let svg = flapwright_drawing::render_plots_svg(
            &format!(
                "{scene_name}: station {station} deployed by its motor ({})",
                report.run.method.name()
            ),
            &plots,
        )
        .map_err(|source| Error::DynamicsPlots {
            station: station.clone(),
            source,
        })?;
        let name = format!("dynamics-{station}.svg");
        out.write(&name, svg.as_bytes()).map_err(|source| Error::Write {
            file: name.clone(),
            source,
        })?;
        files.push(name);
    }
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2 x 0.5 rectangle away from the origin, either way round: (a² + b²) / 12; two
    /// separate squares: each one's own plus the parallel axis to the common centroid.
    #[test]
    fn radius_of_gyration_of_rectangles() {
        let rectangle = |x: f64, y: f64, w: f64, h: f64| {
            vec![
                Point2::new(x, y),
                Point2::new(x + w, y),
                Point2::new(x + w, y + h),
                Point2::new(x, y + h),
            ]
        };
        let expected = (4.0 + 0.25) / 12.0;
        let one = rectangle(3.0, -1.0, 2.0, 0.5);
        let reversed: Vec<_> = one.iter().rev().copied().collect();
        for polygon in [one, reversed] {
            let k2 = polar_radius_of_gyration_squared(&[polygon]).unwrap();
            assert!((k2 - expected).abs() < 1e-12, "{k2}");
        }
        let two = [rectangle(0.0, 0.0, 1.0, 1.0), rectangle(3.0, 0.0, 1.0, 1.0)];
        let k2 = polar_radius_of_gyration_squared(&two).unwrap();
        assert!((k2 - (2.0 / 12.0 + 1.5 * 1.5)).abs() < 1e-12, "{k2}");
        assert!(polar_radius_of_gyration_squared(&[]).is_none());
    }
}
