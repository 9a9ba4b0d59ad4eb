//! Runs the stages a scene's outputs need, times them, and writes the files.

use std::time::Instant;

use serde::Serialize;
use sha2::{Digest, Sha256};

use crate::error::{Error, Result};
use crate::report::{Exports, PartReport, Report, SceneInfo, StageTiming, StationReport, SCHEMA_VERSION};
use crate::scene::{FileSource, Scene};
use crate::sink::Sink;

mod actuator_ranges;
pub mod animation;
pub mod dynamics;
pub mod exports;
pub mod flap_motion;
pub mod flap_position;
pub mod flight_loads;
pub(crate) mod geometry;
pub(crate) mod interference;
pub mod mechanism_parts;
pub mod mechanisms;
mod plausibility;
mod plots;
pub mod record;
pub(crate) mod sizing;
pub mod sizing_loop;
pub mod stations;
mod wing_cache;

pub use wing_cache::WingCache;

/// What a design run reads.
#[derive(Debug, Clone, Copy)]
pub struct Inputs<'a> {
    /// The validated scene.
    pub scene: &'a Scene,
    /// The scene file's text (hashed into the report).
    pub scene_text: &'a str,
    /// The airfoil files the scene names (the scene file's folder, or files in memory).
    pub files: &'a dyn FileSource,
    /// Meshes, statistics and collision shapes shared with other designs of the same wing
    /// (the study's kinds); `None`: this design's own.
    pub wing_cache: Option<&'a WingCache>,
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
    /// Every clearance met (absent when no interference check ran).
    pub interference_passes: Option<bool>,
    /// Pairs the interference check left out, each with its reason in the report (absent
    /// when no check ran).
    pub unchecked_pairs: Option<usize>,
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
struct Stages<'p> {
    names: Vec<String>,
    timings: Vec<StageTiming>,
    on_stage: &'p dyn Fn(&str),
}

impl Stages<'_> {
    fn run<T>(&mut self, name: &str, work: impl FnOnce() -> Result<T>) -> Result<T> {
        (self.on_stage)(name);
        let start = Instant::now();
        let value = work().map_err(|source| Error::Stage {
            stage: name.to_string(),
            source: Box::new(source),
        })?;
        self.names.push(name.to_string());
        self.timings.push(StageTiming {
            stage: name.to_string(),
            wall_time_s: start.elapsed().as_secs_f64(),
        });
        Ok(value)
    }
}

/// Which job a run does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Everything the scene's outputs ask for.
    Design,
    /// Only what the interference check needs (no STL, sweeps or sizing).
    Check,
    /// Only what the requested files need (the scene's outputs as `export` set them): no
    /// gap and overlap unless the drawings or sweeps ask for them.
    Export,
}

/// Designs the scene and writes `report.json` and the requested files into `out`.
pub fn design(inputs: &Inputs<'_>, mode: Mode, out: &dyn Sink) -> Result<Outcome> {
    design_with_progress(inputs, mode, out, &|_| {})
}

/// As [`design`], calling `on_stage` with each stage's name as it starts (for a progress
/// display; libraries below never print).
pub fn design_with_progress(
    inputs: &Inputs<'_>,
    mode: Mode,
    out: &dyn Sink,
    on_stage: &dyn Fn(&str),
) -> Result<Outcome> {
    let scene = inputs.scene;
    let outputs = &scene.outputs;
    let full = mode != Mode::Check;
    let mut stages = Stages {
        names: Vec::new(),
        timings: Vec::new(),
        on_stage,
    };
    let mut parts: Vec<PartReport> = Vec::new();
    // The file's own warnings first (values that pass but are likely slips), located.
    let mut warnings: Vec<String> = scene.warnings.clone();
    let mut interference_report = None;
    let mut mechanism_part_reports = Vec::new();

    let mut meshed = Vec::new();
    let mut tube_path_ac: Vec<nalgebra::Point3<f64>> = Vec::new();
    let mut placed = Vec::new();
    let mut wing_model = None;
    if let Some(wing) = &scene.wing {
        let model = stages.run("geometry", || geometry::build_model(scene, wing, inputs.files))?;
        tube_path_ac = model.torque_tube().map(|t| t.path_ac.clone()).unwrap_or_default();
        meshed = stages.run("meshing", || match inputs.wing_cache {
            Some(cache) => cache.meshes_of(&model, &scene.resolution),
            None => geometry::mesh_parts(&model, &scene.resolution),
        })?;
        // URDF meshes are the STL files: writing a URDF writes them too.
        let write_stl = full && (outputs.stl || outputs.urdf);
        let stage = if write_stl { "stl" } else { "part-statistics" };
        parts = stages.run(stage, || match inputs.wing_cache {
            Some(cache) if !write_stl => Ok(cache.statistics_of(&meshed)),
            _ => geometry::write_parts(&meshed, write_stl, out),
        })?;
        placed = stages.run("planes", || {
            let placed = stations::place_all(scene, &model, &meshed)?;
            stations::apply_flap_motion(scene, &model, &meshed, placed)
        })?;
        wing_model = Some(model);
    }
    // After the planes: kinds synthesised from the flap settings need the sections.
    let (mut records, sizing_loop, loop_warnings) = stages.run("synthesis", || {
        sizing_loop::synthesise_sized(scene, wing_model.as_ref(), placed, &tube_path_ac)
    })?;
    warnings.extend(loop_warnings);
    warnings.extend(mechanisms::flap_agreement(&mut records));
    if wing_model.is_some() {
        stations::attachment_residuals(&mut records)?;
        let implausible = plausibility::station_problems(scene, &records);
        if !implausible.is_empty() {
            return Err(crate::scene::SceneError::Invalid(implausible).into());
        }
        // A design reports gap and overlap; an export needs them for the sweeps' samples
        // and the drawings' plots only.
        if mode == Mode::Design || (full && (outputs.kinematics || outputs.svg)) {
            stages.run("gap-overlap", || {
                flap_position::flap_positions(&scene.flap, &mut records, scene.interference.required_clearance_m)
            })?;
            for record in &records {
                if let Some(position) = &record.flap_position {
                    warnings.extend(plausibility::gap_overlap_warnings(&record.station, position));
                }
            }
        }
        if outputs.interference || !full {
            let own = WingCache::default();
            let shapes = inputs.wing_cache.unwrap_or(&own);
            let checked = stages.run("interference", || interference::check(scene, &meshed, &records, shapes))?;
            for pair in checked.pairs.iter().filter(|p| !p.passes) {
                warnings.push(format!(
                    "interference: {}",
                    crate::junit::describe_failure(&pair.clearance, pair.required_clearance_m)
                ));
            }
            if let Some(model) = &wing_model {
                warnings.extend(plausibility::side_gap_hints(scene, model, &checked.pairs));
            }
            for contact in checked.declared_contacts.iter().filter(|c| !c.passes) {
                warnings.push(format!(
                    "joint: {}",
                    crate::junit::describe_joint_failure(contact, checked.joint_play_m)
                ));
            }
            interference_report = Some(checked);
            let flap_names: Vec<String> = scene.flap.iter().flat_map(|f| f.part_names()).collect();
            stages.run("fairing", || {
                interference::fairing_depths(&mut records, &flap_names, &scene.resolution)
            })?;
            for record in &records {
                if let Some(fairing) = &record.fairing {
                    warnings.extend(plausibility::fairing_warning(&record.station, fairing));
                }
            }
        }
    }
    if full && outputs.kinematics {
        let samples = scene.resolution.deployment_samples;
        if scene.loads.cases.is_empty() && !records.is_empty() {
            warnings.push(format!(
                "loads: the scene gives no [[loads.cases]]: each mechanism is loaded by its flap's weight alone (case \"{}\"); give the air loads as [[loads.cases]] (moments or flight conditions)",
                flight_loads::weight_only().name
            ));
        }
        stages.run("kinematics", || {
            for record in &mut records {
                let cases = flight_loads::load_cases(scene, record);
                let mut report = mechanisms::sweep_station(record, &cases, samples, &mut warnings)?;
                if let Some(measure) = &record.flap_behind_wing {
                    flap_position::annotate_samples(record, measure, &mut report, &scene.flap)?;
                }
                record.kinematics = Some(report);
            }
            Ok(())
        })?;
        for record in &records {
            if let Some(report) = &record.kinematics {
                let cases = flight_loads::load_cases(scene, record);
                // The local flap chord, which the fairing's length is measured in.
                let flap_chord_m = record
                    .fairing
                    .as_ref()
                    .filter(|f| f.length_percent_flap_chord > 0.0)
                    .map(|f| f.length_m / (0.01 * f.length_percent_flap_chord));
                warnings.extend(actuator_ranges::warnings(&record.station, report, &cases, flap_chord_m));
            }
        }
    }
    let mut dynamics_runs = Vec::new();
    if let (true, Some(settings)) = (full, &scene.dynamics) {
        dynamics_runs = stages.run("dynamics", || dynamics::run_all(scene, settings, &records))?;
        for (station, run) in &dynamics_runs {
            if run.run.deployment_time_s.is_none() {
                warnings.push(format!(
                    "dynamics: station {station} did not deploy within {} s or {} steps",
                    settings.max_time_s, settings.max_steps
                ));
            }
        }
    }
    let mut sizing_report = None;
    if full && outputs.sizing && outputs.kinematics {
        let (sized, notes) = stages.run("sizing", || sizing::size_all(scene, &records, &tube_path_ac))?;
        warnings.extend(notes);
        warnings.extend(sized.warnings.iter().map(|w| w.to_string()));
        sizing_report = Some(sized);
    }
    let mut exported = Exports::default();
    // A robot needs a placed station (a wing without flaps has none: its STL is the export).
    let placed = !records.is_empty() && records.iter().all(|r| r.placed.is_some());
    let mut solids = Vec::new();
    if full && placed && (outputs.stl || outputs.urdf || outputs.gltf) {
        let fractions = mechanism_parts::setting_fractions(scene, &records, outputs.stl_setting)?;
        solids = stages.run("mechanism-parts", || {
            mechanism_parts::build(scene, &records, &fractions, sizing_report.as_ref())
        })?;
        // URDF meshes are the STL files: writing a URDF writes them too.
        mechanism_part_reports = mechanism_parts::write_stl(&solids, outputs.stl || outputs.urdf, out)?;
        if outputs.stl {
            exported.stl_setting = Some(outputs.stl_setting);
        }
        if outputs.stl_setting != crate::scene::StlSetting::Stowed {
            mechanism_parts::move_flap_files(&meshed, &records, &fractions, &mut parts, out)?;
        }
    }
    if full && outputs.gltf && placed {
        exported.gltf = Some(stages.run("gltf", || animation::write_gltf(scene, &meshed, &solids, &records, out))?);
    }
    if full && outputs.urdf && placed {
        exported.urdf = Some(stages.run("urdf", || {
            exports::write_urdf(scene, &parts, &meshed, &solids, &records, out)
        })?);
    }
    if full && outputs.svg {
        exported.svg = stages.run("svg", || {
            let mut files = exports::write_svgs(scene, &records, interference_report.as_ref(), out)?;
            files.extend(dynamics::write_plots(&scene.name, &dynamics_runs, out)?);
            Ok(files)
        })?;
    }
    drop(meshed);
    let station_reports: Vec<StationReport> = records
        .into_iter()
        .map(|record| {
            let dynamics = dynamics_runs
                .iter()
                .position(|(station, _)| *station == record.station)
                .map(|i| dynamics_runs.swap_remove(i).1);
            StationReport {
                plane: record
                    .placed
                    .as_ref()
                    .map(|p| flapwright_planes::StationReport::new(&p.station, &p.sections)),
                name: record.station,
                flap: record.flap,
                flap_position: record.flap_position,
                flap_motion_miss: record.flap_motion_miss,
                mechanism: record.kinematics,
                fairing: record.fairing,
                dynamics,
            }
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
        mechanism_parts: mechanism_part_reports,
        stations: station_reports,
        interference: interference_report,
        sizing: sizing_report,
        sizing_loop,
        files: exported,
        warnings,
        timings: stages.timings,
    };
    let json = serde_json::to_string_pretty(&report).map_err(Error::SerialisingReport)?;
    out.write("report.json", (json + "\n").as_bytes())
        .map_err(|source| Error::Write {
            file: "report.json".into(),
            source,
        })?;
    let summary = Summary {
        scene: scene.name.clone(),
        parts: report.parts.len(),
        stations: report.stations.len(),
        warnings: report.warnings.len(),
        interference_passes: report.interference.as_ref().map(|i| i.passes),
        unchecked_pairs: report.interference.as_ref().map(|i| i.unchecked_pairs.len()),
    };
    Ok(Outcome { report, summary })
}

fn hex_sha256(bytes: &[u8]) -> String {
    Sha256::digest(bytes).iter().map(|b| format!("{b:02x}")).collect()
}
