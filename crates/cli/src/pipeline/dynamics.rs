//! The dynamics stage (`[dynamics]`): every station whose kind models its masses and loads
//! (`FlapMechanism::dynamics`) deployed by the scene's DC motor (`flapwright-dynamics`);
//! a station whose kind does not is an error that names it. Each run's time history goes
//! into the report and onto a plot page, `dynamics-<station>.svg`.

use anyhow::{anyhow, Context, Result};
use flapwright_drawing::{Plot, Series};
use flapwright_dynamics::{integrate, DynamicsRun};
use serde::Serialize;

use crate::output::StagedDir;
use crate::pipeline::mechanisms::StationRecord;
use crate::scene::DynamicsScene;

/// A station's deployment under the motor.
#[derive(Debug, Clone, Serialize)]
pub struct DynamicsReport {
    /// Armature inductance (H) and supply voltage (V) it ran with.
    pub inductance_h: f64,
    /// Supply voltage (V).
    pub supply_volts: f64,
    /// The run: method, tolerance, time history, deployment and breakaway times, peaks,
    /// solver counts, energy balance.
    #[serde(flatten)]
    pub run: DynamicsRun,
}

/// Runs every station; errors name a station whose kind has no equation of motion.
pub fn run_all(scene: &DynamicsScene, records: &[StationRecord]) -> Result<Vec<(String, DynamicsReport)>> {
    let (drive, supply, integration) = scene.parts();
    records
        .iter()
        .map(|record| {
            let system = record.mechanism.dynamics().ok_or_else(|| {
                anyhow!(
                    "station {} ({}): [dynamics] needs a kind that models its masses and loads; five-bar does, this kind not yet",
                    record.station,
                    record.mechanism.kind()
                )
            })?;
            let run = integrate(system, &drive, &supply, &integration)
                .with_context(|| format!("station {}: deploying under the motor", record.station))?;
            Ok((
                record.station.clone(),
                DynamicsReport {
                    inductance_h: drive.motor.inductance_h,
                    supply_volts: supply.volts,
                    run,
                },
            ))
        })
        .collect()
}

/// Writes `dynamics-<station>.svg` for each run; returns the file names.
pub fn write_plots(scene_name: &str, runs: &[(String, DynamicsReport)], out: &StagedDir) -> Result<Vec<String>> {
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
        .with_context(|| format!("drawing the dynamics plots of {station}"))?;
        let name = format!("dynamics-{station}.svg");
        std::fs::write(out.file(&name), svg).with_context(|| format!("writing {name}"))?;
        files.push(name);
    }
    Ok(files)
}
