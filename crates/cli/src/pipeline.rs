//! Runs the stages a scene's outputs need, times them, and writes the files.

use std::path::Path;
use std::time::Instant;

use anyhow::{Context, Result};
use serde::Serialize;
use sha2::{Digest, Sha256};

use crate::output::StagedDir;
use crate::report::{PartReport, Report, SceneInfo, StageTiming, StationReport, SCHEMA_VERSION};
use crate::scene::Scene;

mod geometry;
pub mod mechanisms;
mod sizing;
mod stations;

/// What a design run reads.
#[derive(Debug, Clone, Copy)]
pub struct Inputs<'a> {
    /// The validated scene.
    pub scene: &'a Scene,
    /// The scene file's text (hashed into the report).
    pub scene_text: &'a str,
    /// Folder of the scene file, for relative airfoil files.
    pub scene_dir: Option<&'a Path>,
}

/// A one-line, machine-readable summary of a run (`--json`).
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// Scene name.
    pub scene: String,
    /// Parts meshed.
    pub parts: usize,
    /// Stations analysed.
    pub stations: usize,
    /// Warnings raised.
    pub warnings: usize,
}

/// What a run produced.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The report as written.
    pub report: Report,
    /// Its summary.
    pub summary: Summary,
}

/// Times stages and keeps their order.
struct Stages {
    names: Vec<String>,
    timings: Vec<StageTiming>,
}

impl Stages {
    fn run<T>(&mut self, name: &str, work: impl FnOnce() -> Result<T>) -> Result<T> {
        let start = Instant::now();
        let value = work().with_context(|| format!("stage `{name}`"))?;
        self.names.push(name.to_string());
        self.timings.push(StageTiming {
            stage: name.to_string(),
            wall_time_s: start.elapsed().as_secs_f64(),
        });
        Ok(value)
    }
}

/// Designs the scene and writes `report.json` and the requested files into `out`.
pub fn design(inputs: &Inputs<'_>, out: &StagedDir) -> Result<Outcome> {
    let scene = inputs.scene;
    let mut stages = Stages {
        names: Vec::new(),
        timings: Vec::new(),
    };
    let mut parts: Vec<PartReport> = Vec::new();
    let mut warnings: Vec<String> = Vec::new();

    let mechanisms = stages.run("synthesis", || mechanisms::synthesise_all(scene))?;
    let mut planes = vec![None; scene.station.len()];
    let mut station_origins_ac = Vec::new();
    if let Some(wing) = &scene.wing {
        let model = stages.run("geometry", || {
            geometry::build_model(scene, wing, inputs.scene_dir)
        })?;
        let meshed = stages.run("meshing", || {
            geometry::mesh_parts(&model, &scene.resolution)
        })?;
        parts = stages.run("stl", || {
            geometry::write_parts(&meshed, scene.outputs.stl, out)
        })?;
        let placed = stages.run("planes", || {
            stations::place_all(scene, &model, &meshed, &mechanisms)
        })?;
        station_origins_ac = placed.iter().map(|p| p.station.frame.origin_ac()).collect();
        planes = placed
            .iter()
            .map(|p| {
                Some(flapwright_planes::StationReport::new(
                    &p.station,
                    &p.sections,
                ))
            })
            .collect();
    }
    let mut mechanism_reports = vec![None; scene.station.len()];
    if scene.outputs.kinematics {
        let cases = mechanisms::load_cases(scene);
        let samples = scene.resolution.deployment_samples;
        mechanism_reports = stages.run("kinematics", || {
            mechanisms
                .iter()
                .map(|m| mechanisms::sweep_station(m, &cases, samples, &mut warnings).map(Some))
                .collect::<Result<Vec<_>>>()
        })?;
    }
    let mut sizing_report = None;
    if scene.outputs.sizing && scene.outputs.kinematics {
        let reports: Vec<_> = mechanism_reports.iter().flatten().cloned().collect();
        let motor_ac = scene
            .structure
            .torque_tube
            .as_ref()
            .and_then(|t| t.path_m.first())
            .map(|p| nalgebra::Point3::new(p[0], p[1], p[2]));
        let sized = stages.run("sizing", || {
            sizing::size_all(scene, &mechanisms, &reports, &station_origins_ac, motor_ac)
        })?;
        warnings.extend(sized.warnings.iter().map(|w| w.to_string()));
        sizing_report = Some(sized);
    }
    let station_reports: Vec<StationReport> = scene
        .station
        .iter()
        .zip(planes)
        .zip(mechanism_reports)
        .map(|((station, plane), mechanism)| StationReport {
            name: station.name.clone(),
            flap: station.flap.clone(),
            plane,
            mechanism,
        })
        .collect();

    let report = Report {
        schema_version: SCHEMA_VERSION,
        flapwright_version: env!("CARGO_PKG_VERSION").to_string(),
        scene: SceneInfo {
            name: scene.name.clone(),
            description: scene.description.clone(),
            sha256: hex_sha256(inputs.scene_text.as_bytes()),
        },
        stages: stages.names,
        parts,
        stations: station_reports,
        sizing: sizing_report,
        warnings,
        timings: stages.timings,
    };
    let json = serde_json::to_string_pretty(&report).context("serialising the report")?;
    std::fs::write(out.file("report.json"), json + "\n").context("writing report.json")?;
    let summary = Summary {
        scene: scene.name.clone(),
        parts: report.parts.len(),
        stations: report.stations.len(),
        warnings: report.warnings.len(),
    };
    Ok(Outcome { report, summary })
}

fn hex_sha256(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}
