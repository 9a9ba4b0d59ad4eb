//! `flapwright study`: the trade study of mechanism kinds (`003_...` section 5.2, Table 1
//! and Fig. 17). Each candidate kind replaces the mechanism of every studied station (the
//! flap mass, centre of mass and minimum transmission angle carried over, every other
//! choice the kind's own default or search); the scene is then designed as usual, without
//! STL, URDF or drawings, into one folder per kind, and each station's figures are read
//! from the kind's typed [`Report`]: fairing depth and length, largest actuator load, peak
//! power, work per deployment, mechanism mass, the misses at the settings, the
//! transmission-angle range and the clearance verdict; with charts of gap and overlap
//! against deflection for every kind and a ranking.
//!
//! Each variant is a typed [`Scene`]: the user's scene, parsed once, keeps the studied
//! stations and their flaps ([`StudiedScene`]), and per kind each kept station's
//! `mechanism` becomes the kind's table (its `kind` and the kind-neutral keys above as the
//! user wrote them), deserialised and validated like any scene's. The kind's table is the
//! one place the study still writes TOML: the kinds' tables are their only constructors,
//! and a key the user did not write must stay the kind's own default. So the study names
//! no kind: a new kind is studied by naming it. Every problem a variant meets is located in
//! the user's file, with the station and flap indices of that file.

use flapwright_drawing::{Plot, Series};
use flapwright_interference::InterferenceReport;
use flapwright_mechanism::seam::InputQuantity;
use flapwright_mechanism::Deployment;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

pub use crate::error::{MissingSection, NoKindDesigned};

use crate::error::{Error, Result};
use crate::kinds::MechanismScene;
use crate::pipeline::record::FlapPositionReport;
use crate::pipeline::WingCache;
use crate::pipeline::{self, Inputs, Mode};
use crate::report::{Report, StationReport};
use crate::scene::{FileSource, OutputsScene, Problem, Scene, SceneError, StlSetting};
use crate::sink::{MemorySink, Sink};

/// The kinds studied when none are named: every kind synthesised from the flap settings.
pub const DEFAULT_KINDS: &[&str] = crate::kinds::MechanismScene::SYNTHESISED_KINDS;

/// Keys of a station's mechanism table every kind synthesised from the settings takes.
const CARRIED_KEYS: [&str; 3] = ["flap_mass_kg", "flap_centre_of_mass_m", "min_transmission_angle_deg"];

/// A setting missed by more than this (% of the local chord) counts as missed.
const MISS_TOLERANCE_PERCENT_CHORD: f64 = 0.5;

/// One station's figures for one kind.
#[derive(Debug, Clone, Serialize)]
pub struct StationFigures {
    /// Station name.
    pub station: String,
    /// Fairing depth below the local lower surface, % of the flap chord.
    pub fairing_depth_percent_flap_chord: f64,
    /// Fairing length, % of the flap chord.
    pub fairing_length_percent_flap_chord: f64,
    /// `stroke` (screw jack: loads in N, power from the nut speed) or `angle` (rotary: N m).
    pub actuator_input: InputQuantity,
    /// Largest actuator load over every load case and sample (N or N m).
    pub max_actuator_load: f64,
    /// Largest |load x nominal input speed| (W).
    pub peak_power_w: f64,
    /// Largest work of one deployment over the load cases, the trapezoidal integral of
    /// load over input (J).
    pub work_per_deployment_j: f64,
    /// The station's sized mechanism mass (kg).
    pub mechanism_mass_kg: f64,
    /// Per setting: gap and overlap minus their targets (% of the local chord).
    pub setting_misses: Vec<SettingMiss>,
    /// Smallest and largest transmission angle over the deployment (deg).
    pub transmission_angle_deg: [f64; 2],
    /// Every checked pair of the station's parts, and of the flap it moves, keeps the
    /// required clearance.
    pub clearance_passes: bool,
    /// Gap and overlap (% of the local chord) against deflection (deg), first load case.
    pub gap_overlap: Vec<[f64; 3]>,
    /// The mechanism's arrangement where the kind states one (the hooked-track's and the
    /// link-track's `details.synthesis.topology`): two designs that differ in it are
    /// different mechanisms, whose figures may differ by several times.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub topology: Option<serde_json::Value>,
}

/// A setting's misses.
#[derive(Debug, Clone, Serialize)]
pub struct SettingMiss {
    /// "takeoff" or "landing".
    pub setting: String,
    /// The setting's deflection (deg).
    pub deflection_deg: f64,
    /// Target gap and overlap (% chord).
    pub target_percent_chord: [f64; 2],
    /// Measured gap minus target (% chord).
    pub gap_miss_percent_chord: f64,
    /// Measured overlap minus target (% chord).
    pub overlap_miss_percent_chord: f64,
}

/// One kind's outcome.
#[derive(Debug, Clone, Serialize)]
pub struct KindOutcome {
    /// Mechanism kind.
    pub kind: String,
    /// Its stations' figures (empty when it could not be designed).
    pub stations: Vec<StationFigures>,
    /// Why the kind could not be designed here.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

/// A station's kinds, best first, by [`RANKING_RULE`].
#[derive(Debug, Clone, Serialize)]
pub struct StationRanking {
    /// Station name.
    pub station: String,
    /// Kinds, best first.
    pub kinds: Vec<String>,
}

/// The whole study.
#[derive(Debug, Clone, Serialize)]
pub struct Study {
    /// Scene name.
    pub scene: String,
    /// Kinds studied, in the order asked.
    pub kinds: Vec<KindOutcome>,
    /// Ranking per station.
    pub ranking: Vec<StationRanking>,
    /// The rule the ranking follows.
    pub ranking_rule: &'static str,
}

/// The ranking rule, as `docs/commands.md` states it.
pub const RANKING_RULE: &str = "clears the wing first; then fewer settings missed by more than 0.5 % of the chord; then the shallower fairing; then the lighter mechanism";

/// The sort key of [`RANKING_RULE`].
fn rank(figures: &StationFigures) -> (bool, usize, f64, f64) {
    let missed = figures
        .setting_misses
        .iter()
        .filter(|m| {
            m.gap_miss_percent_chord.abs() > MISS_TOLERANCE_PERCENT_CHORD
                || m.overlap_miss_percent_chord.abs() > MISS_TOLERANCE_PERCENT_CHORD
        })
        .count();
    (
        !figures.clearance_passes,
        missed,
        figures.fairing_depth_percent_flap_chord,
        figures.mechanism_mass_kg,
    )
}

/// The part of the user's scene every kind's variant shares: the studied stations and the
/// flaps they carry (the others are removed so that the study designs only what it
/// compares), the outputs the figures need, and where each kept station and flap comes
/// from in the user's file.
#[derive(Debug, Clone)]
pub struct StudiedScene {
    /// The user's scene, its stations and flaps limited to the studied ones and its outputs
    /// to what the figures need; its stations' mechanisms are still the user's.
    pub scene: Scene,
    /// For each kept station, its index in the user's file.
    pub station_index: Vec<usize>,
    /// For each kept flap, its index in the user's file.
    pub flap_index: Vec<usize>,
    /// For each kept station, the kind-neutral keys of its mechanism table as the user
    /// wrote them ([`CARRIED_KEYS`]), and its flap mass where the table names it otherwise.
    carried: Vec<toml::Table>,
}

/// Each kept station's `mechanism` as a kind's table, read with the scene's own paths
/// (`station[0].mechanism.flap_mass_kg`) so that its problems read as a whole scene's.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct KindTables {
    station: Vec<KindTable>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct KindTable {
    mechanism: MechanismScene,
}

impl StudiedScene {
    /// The stations named in `stations` (all when empty) of `scene`, parsed from `text`;
    /// `text` gives the keys each station's mechanism table carries over as written, and
    /// `scene` the flap mass of a station whose table names it otherwise (the five-bar's
    /// two elements).
    pub fn new(text: &str, scene: &Scene, stations: &[String]) -> Result<Self> {
        let table: toml::Table = text.parse().map_err(Error::StudySceneToml)?;
        let written = table
            .get("station")
            .and_then(|v| v.as_array())
            .ok_or(Error::NoStationToStudy)?;
        let studied = |name: &str| stations.is_empty() || stations.iter().any(|w| w == name);
        let station_index: Vec<usize> = scene
            .station
            .iter()
            .enumerate()
            .filter(|(_, s)| studied(&s.name))
            .map(|(i, _)| i)
            .collect();
        if station_index.is_empty() {
            return Err(Error::NoSuchStation {
                names: stations.to_vec(),
            });
        }
        if written.len() != scene.station.len() {
            return Err(Error::StudyStationsMismatch);
        }
        let carried = station_index
            .iter()
            .map(|&i| {
                let mechanism = written[i].get("mechanism").and_then(|m| m.as_table());
                let mut carried = toml::Table::new();
                for key in CARRIED_KEYS {
                    if let Some(value) = mechanism.and_then(|m| m.get(key)) {
                        carried.insert(key.into(), value.clone());
                    }
                }
                if !carried.contains_key("flap_mass_kg") {
                    let mass = scene.station[i].mechanism.kind().flap_mass_kg();
                    carried.insert("flap_mass_kg".into(), toml::Value::Float(mass));
                }
                carried
            })
            .collect();
        let flaps_used: Vec<&str> = station_index
            .iter()
            .filter_map(|&i| scene.station[i].flap.as_deref())
            .collect();
        let flap_index: Vec<usize> = scene
            .flap
            .iter()
            .enumerate()
            .filter(|(_, f)| flaps_used.contains(&f.name.as_str()))
            .map(|(i, _)| i)
            .collect();
        let mut kept = scene.clone();
        kept.station = station_index.iter().map(|&i| scene.station[i].clone()).collect();
        kept.flap = flap_index.iter().map(|&i| scene.flap[i].clone()).collect();
        // Every field named: an output added later is a choice the study must make.
        kept.outputs = OutputsScene {
            stl: false,
            urdf: false,
            svg: false,
            gltf: false,
            kinematics: true,
            sizing: true,
            interference: true,
            stl_setting: StlSetting::Stowed,
        };
        // The study reads only each pair's verdict, so its sweeps stop refining a pair once
        // the verdict is certain instead of locating its minimum to the tolerance: the same
        // certified pass or fail (the pair's lower bound still meets the requirement, or a
        // sample already misses it) for a fraction of the distance evaluations. The kinds'
        // reports say so (`interference.stopped_at_verdict`), and their pairs'
        // `min_clearance_m` are the smallest samples, `residual_bound_m` how much lower the
        // true minimum may be.
        kept.interference.stop_at_verdict = true;
        // The file's own warnings were the user's to read when it was parsed; the kinds'
        // reports carry only what their designs find.
        kept.warnings = Vec::new();
        Ok(Self {
            scene: kept,
            station_index,
            flap_index,
            carried,
        })
    }

    /// The scene with `kind` in place of every kept station's mechanism (the carried keys
    /// and the kind's defaults), validated as [`Scene::from_table`] validates a file's;
    /// problems by the variant's key paths (see [`StudiedScene::user_path`]).
    pub fn variant(&self, kind: &str, files: &dyn FileSource) -> Result<Scene, Vec<Problem>> {
        let stations = self
            .carried
            .iter()
            .map(|carried| {
                let mut mechanism = toml::Table::new();
                mechanism.insert("kind".into(), toml::Value::String(kind.into()));
                mechanism.extend(carried.iter().map(|(key, value)| (key.clone(), value.clone())));
                toml::Value::Table(toml::Table::from_iter([(
                    "mechanism".into(),
                    toml::Value::Table(mechanism),
                )]))
            })
            .collect();
        let tables = toml::Table::from_iter([("station".into(), toml::Value::Array(stations))]);
        let kind_tables: KindTables = crate::scene::parse::typed(&tables)?;
        let mut scene = self.scene.clone();
        for (station, table) in scene.station.iter_mut().zip(kind_tables.station) {
            station.mechanism = table.mechanism;
        }
        let problems = scene.validate(files);
        if problems.is_empty() {
            Ok(scene)
        } else {
            Err(problems)
        }
    }

    /// `path` (`station[0].mechanism`) with the station and flap indices of the user's file.
    pub fn user_path(&self, path: &str) -> String {
        for (table, map) in [("station[", &self.station_index), ("flap[", &self.flap_index)] {
            let Some(rest) = path.strip_prefix(table) else { continue };
            let Some((index, tail)) = rest.split_once(']') else {
                continue;
            };
            if let Some(original) = index.parse::<usize>().ok().and_then(|i| map.get(i)) {
                return format!("{table}{original}]{tail}");
            }
        }
        path.to_string()
    }

    /// Problems by key path, located in the user's file (`text`, named `file`).
    fn locate(&self, problems: Vec<Problem>, text: &str, file: &str) -> SceneError {
        let problems = problems
            .into_iter()
            .map(|p| Problem::new(self.user_path(&p.path), p.message))
            .collect();
        SceneError::Invalid(problems).locate(text, file)
    }
}

/// A scene the study cannot compare kinds on: its problems, located in the file, shown on
/// one line.
#[derive(Debug)]
pub struct Unstudiable(pub SceneError);

impl std::fmt::Display for Unstudiable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.0.lines().join("; "))
    }
}

impl std::error::Error for Unstudiable {}

/// What a study needs of its scene before any kind is designed: a `[wing]` (the kinds are
/// synthesised in the stations' sections) and, on every studied station's flap, the four
/// gap and overlap targets its settings are synthesised to.
pub fn requirements(scene: &Scene, text: &str, file: &str, stations: &[String]) -> Result<(), Unstudiable> {
    let unstudiable = |problem: Problem| Unstudiable(SceneError::Invalid(vec![problem]).locate(text, file));
    if scene.wing.is_none() {
        return Err(unstudiable(Problem::new(
            "wing",
            format!(
                "`study` needs a scene with a [wing]: its kinds are synthesised from the flap settings in each station's sections, and \"{}\" is a 2D station",
                scene.name
            ),
        )));
    }
    let studied = |name: &str| stations.is_empty() || stations.iter().any(|w| w == name);
    for (i, flap) in scene.flap.iter().enumerate() {
        let carried = scene
            .station
            .iter()
            .any(|s| studied(&s.name) && s.flap.as_deref() == Some(flap.name.as_str()));
        let settings = &flap.settings;
        let missing: Vec<&str> = [
            ("takeoff_gap_percent", settings.takeoff_gap_percent),
            ("takeoff_overlap_percent", settings.takeoff_overlap_percent),
            ("landing_gap_percent", settings.landing_gap_percent),
            ("landing_overlap_percent", settings.landing_overlap_percent),
        ]
        .iter()
        .filter(|(_, value)| value.is_none())
        .map(|(key, _)| *key)
        .collect();
        if carried && !missing.is_empty() {
            return Err(unstudiable(Problem::new(
                format!("flap[{i}].settings"),
                format!(
                    "the study's kinds are synthesised to the flap's gap and overlap targets: give {} (% of the local chord)",
                    missing.join(", ")
                ),
            )));
        }
    }
    Ok(())
}

/// A kind's failure as one line: a scene's problems joined, any other error's chain.
fn one_line(error: &Error) -> String {
    match error.scene_error() {
        Some(scene_error) => scene_error.lines().join("; "),
        None => error.chain_message().replace('\n', " "),
    }
}

/// Runs the study of `scene` (read from `text`, the file named `file`): one design per kind
/// into `out/<kind>/`, then `study.json` and the gap and overlap charts
/// (`study-<station>.svg`) into `out`. Every problem a kind meets is located in the user's
/// file. A study in which no kind designs is an error ([`NoKindDesigned`]).
pub fn run(
    scene: &Scene,
    text: &str,
    files: &dyn FileSource,
    file: &str,
    kinds: &[String],
    stations: &[String],
    out: &dyn Sink,
) -> Result<Study> {
    // A problem of the whole study (no such station) stops it before any kind; a kind's
    // own problems (its variant's, its design's) are its outcome.
    let studied = StudiedScene::new(text, scene, stations)?;
    // The kinds design the same wing: its meshes, their statistics and their collision
    // shapes are built once for all.
    let cache = WingCache::default();
    // The kinds are independent designs into their own folders: in parallel (rayon), in
    // the order asked. Each design also runs its pairs in parallel; running the kinds side by
    // side lets one kind's serial stages (synthesis searches, a pair that takes long) overlap
    // the others' work.
    let designed: Vec<_> = kinds
        .par_iter()
        .map(|kind| (kind, design_kind(&studied, text, files, file, kind, out, &cache)))
        .collect();
    let mut outcomes = Vec::new();
    let mut failures = Vec::new();
    for (kind, outcome) in designed {
        match outcome {
            Ok(figures) => outcomes.push(KindOutcome {
                kind: kind.clone(),
                stations: figures,
                error: None,
            }),
            Err(error) => {
                outcomes.push(KindOutcome {
                    kind: kind.clone(),
                    stations: Vec::new(),
                    error: Some(error.chain_message()),
                });
                failures.push((kind.clone(), error));
            }
        }
    }
    if !kinds.is_empty() && failures.len() == kinds.len() {
        return Err(NoKindDesigned {
            scene: scene.name.clone(),
            input_problem: failures.iter().all(|(_, e)| e.scene_error().is_some()),
            reasons: failures.iter().map(|(kind, e)| (kind.clone(), one_line(e))).collect(),
        }
        .into());
    }
    let mut station_names: Vec<String> = Vec::new();
    for figures in outcomes.iter().flat_map(|o| &o.stations) {
        if !station_names.contains(&figures.station) {
            station_names.push(figures.station.clone());
        }
    }
    let ranking = station_names
        .iter()
        .map(|station| {
            let mut ranked = at_station(&outcomes, station);
            ranked.sort_by(|a, b| rank(a.1).partial_cmp(&rank(b.1)).unwrap_or(std::cmp::Ordering::Equal));
            StationRanking {
                station: station.clone(),
                kinds: ranked.into_iter().map(|(k, _)| k.to_string()).collect(),
            }
        })
        .collect();
    let study = Study {
        scene: scene.name.clone(),
        kinds: outcomes,
        ranking,
        ranking_rule: RANKING_RULE,
    };
    for station in &station_names {
        let svg = flapwright_drawing::render_plots_svg(
            &format!("{}: kinds at {station}", study.scene),
            &charts(&study, station),
        )
        .map_err(|source| Error::StudyCharts {
            station: station.clone(),
            source,
        })?;
        let file = format!("study-{station}.svg");
        out.write(&file, svg.as_bytes())
            .map_err(|source| Error::WritingStudyCharts { file, source })?;
    }
    let json = serde_json::to_string_pretty(&study).map_err(Error::SerialisingStudy)?;
    out.write("study.json", (json + "\n").as_bytes())
        .map_err(|source| Error::Write {
            file: "study.json".into(),
            source,
        })?;
    Ok(study)
}

/// Designs one kind's variant into `out/<kind>/` (no folder when it fails) and gathers its
/// stations' figures; its problems are located in the user's file.
fn design_kind(
    studied: &StudiedScene,
    text: &str,
    files: &dyn FileSource,
    file: &str,
    kind: &str,
    out: &dyn Sink,
    cache: &WingCache,
) -> Result<Vec<StationFigures>> {
    let scene = studied
        .variant(kind, files)
        .map_err(|problems| studied.locate(problems, text, file))?;
    // Designed in memory, written as one folder only when the whole design succeeded and
    // its figures were read (no folder for a kind that could not be designed).
    let written = MemorySink::new();
    let inputs = Inputs {
        scene: &scene,
        scene_text: text,
        files,
        wing_cache: Some(cache),
    };
    // The scene's problems are the kind's outcome, located in the user's file without the
    // stage that met them.
    let outcome =
        pipeline::design(&inputs, Mode::Design, &written).map_err(|error| match error.into_scene_error() {
            Ok(SceneError::Invalid(problems)) => Error::Scene(studied.locate(problems, text, file)),
            Ok(other) => Error::Scene(other),
            Err(error) => error,
        })?;
    let report = &outcome.report;
    let figures = report
        .stations
        .iter()
        .map(|station| station_figures(report, station))
        .collect::<Result<Vec<_>, _>>()?;
    out.write_folder(kind, &written)
        .map_err(|source| Error::WritingKindFolder {
            kind: kind.to_string(),
            source,
        })?;
    Ok(figures)
}

/// One station's figures from its kind's report.
pub(crate) fn station_figures(report: &Report, station: &StationReport) -> Result<StationFigures, MissingSection> {
    let missing = |section| MissingSection {
        station: station.name.clone(),
        section,
    };
    let mechanism = station.mechanism.as_ref().ok_or_else(|| missing("mechanism"))?;
    let fairing = station.fairing.as_ref().ok_or_else(|| missing("fairing"))?;
    let flap_position = station.flap_position.as_ref().ok_or_else(|| missing("flap_position"))?;
    let interference = report.interference.as_ref().ok_or_else(|| missing("interference"))?;
    let sizing = report.sizing.as_ref().ok_or_else(|| missing("sizing"))?;
    let loads = ActuatorLoads::over(&mechanism.load_cases);
    // The masses list the stations that have sized parts: a station without one weighs
    // nothing here.
    let mechanism_mass_kg = sizing.masses.station_kg(&station.name);
    Ok(StationFigures {
        station: station.name.clone(),
        fairing_depth_percent_flap_chord: fairing.depth_percent_flap_chord,
        fairing_length_percent_flap_chord: fairing.length_percent_flap_chord,
        actuator_input: mechanism.input.quantity,
        max_actuator_load: loads.max_load,
        peak_power_w: loads.max_load * mechanism.actuator.nominal_input_speed(),
        work_per_deployment_j: loads.work,
        mechanism_mass_kg,
        setting_misses: setting_misses(flap_position),
        transmission_angle_deg: loads.transmission_angle_deg,
        clearance_passes: clearance_passes(interference, &station.name, station.flap.as_deref()),
        gap_overlap: gap_overlap(&mechanism.load_cases),
        topology: mechanism
            .details
            .get("synthesis")
            .and_then(|synthesis| synthesis.get("topology"))
            .cloned(),
    })
}

/// What the actuator does over every load case and sample.
struct ActuatorLoads {
    /// Largest |load| (N or N m).
    max_load: f64,
    /// Largest |work| of one deployment (J).
    work: f64,
    /// Smallest and largest transmission angle (deg); infinite, the wrong way round, with
    /// no sample.
    transmission_angle_deg: [f64; 2],
}

impl ActuatorLoads {
    fn over(cases: &[Deployment]) -> Self {
        let mut loads = Self {
            max_load: 0.0,
            work: 0.0,
            transmission_angle_deg: [f64::INFINITY, f64::NEG_INFINITY],
        };
        for case in cases {
            // The trapezoidal integral of load over input.
            let mut case_work = 0.0;
            for pair in case.samples.windows(2) {
                let (a, b) = (&pair[0], &pair[1]);
                case_work += 0.5 * (a.actuator_load + b.actuator_load) * (b.input - a.input);
            }
            loads.work = loads.work.max(case_work.abs());
            for sample in &case.samples {
                loads.max_load = loads.max_load.max(sample.actuator_load.abs());
                let [low, high] = loads.transmission_angle_deg;
                let angle = sample.transmission_angle_deg;
                loads.transmission_angle_deg = [low.min(angle), high.max(angle)];
            }
        }
        loads
    }
}

/// Gap and overlap (% chord) against deflection (deg) over the first load case's samples.
fn gap_overlap(cases: &[Deployment]) -> Vec<[f64; 3]> {
    // A sample's gap and overlap are absent only at a station with no flap section to
    // measure them by, where no kind the study puts in is synthesised.
    cases.first().map_or_else(Vec::new, |case| {
        case.samples
            .iter()
            .filter_map(|s| {
                let at = s.flap_position?;
                Some([s.deflection_deg, at.gap_percent_chord, at.overlap_percent_chord])
            })
            .collect()
    })
}

/// The misses at each setting the scene gives a gap target for (`stowed` has none).
fn setting_misses(flap_position: &FlapPositionReport) -> Vec<SettingMiss> {
    flap_position
        .settings
        .iter()
        .filter_map(|s| {
            let target_gap = s.target_gap_percent_chord?;
            // A setting with a gap target has a gap miss; an overlap target (and its miss)
            // may be absent in a scene the study's requirements did not vet: NaN then
            // (`null` in study.json), never a miss of zero.
            Some(SettingMiss {
                setting: s.setting.clone(),
                deflection_deg: s.deflection_deg,
                target_percent_chord: [target_gap, s.target_overlap_percent_chord.unwrap_or(f64::NAN)],
                // Against what the setting was built to: a sealed slot's gap against its seal.
                gap_miss_percent_chord: s.gap_miss_percent_chord.unwrap_or(f64::NAN),
                overlap_miss_percent_chord: s.overlap_miss_percent_chord.unwrap_or(f64::NAN),
            })
        })
        .collect()
}

/// Every checked pair of `station`'s parts (named `<station>.<solid>`), and of the flap
/// it moves, and every joint of the station keeps its requirement.
fn clearance_passes(interference: &InterferenceReport, station: &str, flap: Option<&str>) -> bool {
    let prefix = format!("{station}.");
    // The flap this station moves is the kind's result too: each kind moves it on its own
    // path, so the flap's pairs (against the wing, spars, tube) count with the station's.
    let concerns = |part: &str| part.starts_with(&prefix) || Some(part) == flap;
    interference
        .pairs
        .iter()
        .filter(|p| concerns(&p.clearance.part_a) || concerns(&p.clearance.part_b))
        .all(|p| p.passes)
        && interference
            .declared_contacts
            .iter()
            .filter(|c| c.declared.station == station)
            .all(|c| c.passes)
}

/// Each kind's figures at `station`, in the order of `outcomes`.
fn at_station<'a>(outcomes: &'a [KindOutcome], station: &str) -> Vec<(&'a str, &'a StationFigures)> {
    outcomes
        .iter()
        .filter_map(|o| {
            o.stations
                .iter()
                .find(|f| f.station == station)
                .map(|f| (o.kind.as_str(), f))
        })
        .collect()
}

/// Gap and overlap against deflection for every kind at `station`, targets marked. Each
/// kind keeps its place, so its colour and dash, in every chart of the study: one that was
/// not designed here is a legend entry only, "<kind> (failed)".
fn charts(study: &Study, station: &str) -> Vec<Plot> {
    let figures = at_station(&study.kinds, station);
    let plot = |title: &str, column: usize| {
        let mut series: Vec<Series> = study
            .kinds
            .iter()
            .map(|outcome| {
                let rows = outcome
                    .stations
                    .iter()
                    .find(|f| f.station == station)
                    .map_or(&[][..], |f| &f.gap_overlap[..]);
                Series {
                    name: if rows.is_empty() {
                        format!("{} (failed)", outcome.kind)
                    } else {
                        outcome.kind.clone()
                    },
                    points: rows.iter().map(|row| (row[0], row[column])).collect(),
                }
            })
            .collect();
        // The targets as markers (a one-point series) at their settings' deflections.
        if let Some((_, f)) = figures.first() {
            for miss in &f.setting_misses {
                let value = miss.target_percent_chord[column - 1];
                if value.is_finite() && miss.deflection_deg.is_finite() {
                    series.push(Series {
                        name: format!("{} target", miss.setting),
                        points: vec![(miss.deflection_deg, value)],
                    });
                }
            }
        }
        Plot {
            title: title.into(),
            x_label: "flap deflection [deg]".into(),
            y_label: "% of local chord".into(),
            series,
        }
    };
    vec![plot("Gap against deflection", 1), plot("Overlap against deflection", 2)]
}

/// The study as a plain-text table, one row per station and kind, and the ranking.
pub fn table(study: &Study) -> String {
    let mut lines = vec![format!(
        "{:<12} {:<14} {:>6} {:>7} {:>12} {:>9} {:>9} {:>8} {:>11} {:>11} {:>11} {}",
        "station",
        "kind",
        "depth%",
        "length%",
        "max load",
        "power kW",
        "work kJ",
        "mass kg",
        "TO miss %c",
        "LD miss %c",
        "mu deg",
        "clears"
    )];
    for outcome in &study.kinds {
        if let Some(error) = &outcome.error {
            lines.push(format!("{:<12} {:<14} {error}", "-", outcome.kind));
        }
        for f in &outcome.stations {
            let miss = |setting: &str| {
                f.setting_misses
                    .iter()
                    .find(|m| m.setting == setting)
                    .map_or("-".into(), |m| {
                        format!("{:+.1}/{:+.1}", m.gap_miss_percent_chord, m.overlap_miss_percent_chord)
                    })
            };
            let load = if f.actuator_input == InputQuantity::Angle {
                format!("{:.1} kN m", f.max_actuator_load / 1e3)
            } else {
                format!("{:.1} kN", f.max_actuator_load / 1e3)
            };
            lines.push(format!(
                "{:<12} {:<14} {:>6.1} {:>7.1} {:>12} {:>9.2} {:>9.2} {:>8.1} {:>11} {:>11} {:>5.0}-{:<5.0} {}",
                f.station,
                outcome.kind,
                f.fairing_depth_percent_flap_chord,
                f.fairing_length_percent_flap_chord,
                load,
                f.peak_power_w / 1e3,
                f.work_per_deployment_j / 1e3,
                f.mechanism_mass_kg,
                miss("takeoff"),
                miss("landing"),
                f.transmission_angle_deg[0],
                f.transmission_angle_deg[1],
                if f.clearance_passes { "yes" } else { "no" }
            ));
        }
    }
    for ranking in &study.ranking {
        lines.push(format!("{}: {}", ranking.station, ranking.kinds.join(" > ")));
    }
    lines.push(format!("ranking: {}", study.ranking_rule));
    lines.join("\n")
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use flapwright_interference::{
        ContactResult, DeclaredContact, FairingDepth, JointSeparation, PairClearance, PairResult,
    };
    use flapwright_mechanism::seam::{Actuator, InputRange};
    use flapwright_mechanism::{DeploymentSample, FlapGapOverlap};
    use flapwright_sizing::{MassBreakdown, MassItem, SizingReport};

    use super::*;
    use crate::pipeline::record::MechanismReport;
    use crate::pipeline::record::SettingPosition;
    use crate::report::{Exports, SceneInfo, SCHEMA_VERSION};

    /// A sample at `input` (rad) under `load` (N m), the flap at `deflection_deg` with
    /// `gap_percent` and an overlap of 1 %.
    fn sample(input: f64, load: f64, angle_deg: f64, deflection_deg: f64, gap_percent: f64) -> DeploymentSample {
        DeploymentSample {
            input,
            deflection_deg,
            transmission_angle_deg: angle_deg,
            actuator_load: load,
            actuator_load_cross_check_relative: 0.0,
            reactions_n: BTreeMap::new(),
            closure_residual_m: 0.0,
            jacobian_condition_number: 1.0,
            distance_to_toggle_deg: 90.0,
            actuator_torques_nm: None,
            member_loads: BTreeMap::new(),
            flap_position: Some(FlapGapOverlap {
                gap_m: gap_percent / 100.0,
                gap_percent_chord: gap_percent,
                overlap_m: 0.01,
                overlap_percent_chord: 1.0,
            }),
            aft_element: None,
        }
    }

    /// A setting at `deflection_deg` measured at `gap_percent` and 1 % overlap, against
    /// `targets` (gap, overlap; % of a 1 m chord).
    fn setting(
        name: &str,
        deflection_deg: f64,
        gap_percent: f64,
        targets: (Option<f64>, Option<f64>),
    ) -> SettingPosition {
        let measured = flapwright_planes::GapOverlap {
            rotation_rad: deflection_deg.to_radians(),
            gap_m: gap_percent / 100.0,
            gap_percent_chord: gap_percent,
            overlap_m: 0.01,
            overlap_percent_chord: 1.0,
        };
        SettingPosition::new(name, deflection_deg, measured, targets, None, 1.0)
    }

    /// Station `name` on flap `flap` as a kind designs it: a rotary actuator turning at
    /// 0.1 rad/s through 0.5 rad, two load cases, the take-off setting aimed at 2 % gap and
    /// 0 % overlap, a fairing 10 % deep and 30 % long.
    fn designed_station(name: &str, flap: &str) -> StationReport {
        let case = |name: &str, samples| Deployment {
            load_case: name.into(),
            samples,
            stopped: None,
        };
        StationReport {
            name: name.into(),
            flap: Some(flap.into()),
            plane: None,
            flap_motion_miss: None,
            flap_position: Some(FlapPositionReport {
                trailing_edge_st_m: [0.0, 0.0],
                local_chord_m: 1.0,
                settings: vec![
                    setting("stowed", 0.0, 0.0, (None, None)),
                    setting("takeoff", 20.0, 2.5, (Some(2.0), Some(0.0))),
                ],
                rigid_flap: Vec::new(),
                aft_slot: None,
            }),
            mechanism: Some(MechanismReport {
                kind: "link-track",
                input: InputRange {
                    quantity: InputQuantity::Angle,
                    stowed: 0.0,
                    deployed: 0.5,
                },
                actuator: Actuator::Rotary {
                    gear_ratio: 100.0,
                    efficiency: 0.9,
                    nominal_speed_radps: 0.1,
                },
                details: serde_json::Value::Null,
                load_cases: vec![
                    case(
                        "cruise",
                        vec![
                            sample(0.0, 100.0, 60.0, 0.0, 0.0),
                            sample(0.25, 300.0, 40.0, 20.0, 2.5),
                            sample(0.5, -500.0, 70.0, 40.0, 3.0),
                        ],
                    ),
                    case(
                        "landing",
                        vec![
                            sample(0.0, 1000.0, 50.0, 0.0, 0.0),
                            sample(0.5, 1000.0, 30.0, 40.0, 3.0),
                        ],
                    ),
                ],
                flap_load_share: None,
            }),
            fairing: Some(FairingDepth {
                depth_m: 0.1,
                depth_percent_flap_chord: 10.0,
                part: Some(format!("{name}.link")),
                at_parameter: 0.5,
                point_st: [0.0, -0.1],
                length_m: 0.3,
                length_percent_flap_chord: 30.0,
            }),
            dynamics: None,
        }
    }

    /// A pair of parts `a` and `b`, passing or not.
    fn pair(a: &str, b: &str, passes: bool) -> PairResult {
        PairResult {
            station: None,
            clearance: PairClearance {
                part_a: a.into(),
                part_b: b.into(),
                min_clearance_m: if passes { 0.01 } else { 0.0 },
                at_parameter: 0.5,
                point_a_ac: [0.0; 3],
                point_b_ac: [0.0; 3],
                penetration_m: 0.0,
                penetration_resolution_m: 0.0,
                residual_bound_m: 0.0,
                evaluations: 1,
                trace: Vec::new(),
            },
            required_clearance_m: 0.005,
            passes,
            sweep_time_s: 0.0,
        }
    }

    /// A joint of `station`, holding or not.
    fn joint(station: &str, passes: bool) -> ContactResult {
        ContactResult {
            declared: DeclaredContact {
                station: station.into(),
                part_a: format!("{station}.link"),
                part_b: format!("{station}.carriage"),
                joint: "B".into(),
            },
            separation: JointSeparation {
                max_separation_m: 0.0,
                at_parameter: 0.0,
                upper_bound_m: 0.0,
                evaluations: 1,
            },
            passes,
            sweep_time_s: 0.0,
        }
    }

    fn interference(pairs: Vec<PairResult>, declared_contacts: Vec<ContactResult>) -> InterferenceReport {
        InterferenceReport {
            deployment_range: [0.0, 1.0],
            required_clearance_m: 0.005,
            required_clearance_by_station_m: BTreeMap::new(),
            joint_play_m: 0.001,
            passes: pairs.iter().all(|p| p.passes) && declared_contacts.iter().all(|c| c.passes),
            pairs,
            swept_box_intervals: 0,
            certified_apart: Vec::new(),
            declared_contacts,
            openings: Vec::new(),
            unchecked_pairs: Vec::new(),
            stopped_at_verdict: true,
        }
    }

    /// A kind's report of `station`, with no pairs and no sized parts.
    fn report_of(station: StationReport) -> Report {
        Report {
            schema_version: SCHEMA_VERSION,
            flapwright_version: String::new(),
            scene: SceneInfo {
                name: "wing".into(),
                description: String::new(),
                sha256: String::new(),
            },
            stages: Vec::new(),
            parts: Vec::new(),
            mechanism_parts: Vec::new(),
            stations: vec![station],
            interference: Some(interference(Vec::new(), Vec::new())),
            sizing: Some(SizingReport::assemble(Vec::new(), Vec::new(), Vec::new(), None)),
            sizing_loop: None,
            files: Exports::default(),
            warnings: Vec::new(),
            timings: Vec::new(),
        }
    }

    fn figures_of(report: &Report) -> Result<StationFigures, MissingSection> {
        station_figures(report, &report.stations[0])
    }

    #[test]
    fn the_figures_are_read_from_the_kinds_report() {
        let mut report = report_of(designed_station("s1", "outboard"));
        report.sizing.as_mut().unwrap().masses = MassBreakdown::from_items(&[
            MassItem {
                station: "s0".into(),
                part: "link".into(),
                mass_kg: 9.0,
            },
            MassItem {
                station: "s1".into(),
                part: "link".into(),
                mass_kg: 2.5,
            },
        ]);
        let f = figures_of(&report).unwrap();
        assert_eq!(f.station, "s1");
        assert_eq!(f.actuator_input, InputQuantity::Angle);
        assert_eq!(
            [f.fairing_depth_percent_flap_chord, f.fairing_length_percent_flap_chord],
            [10.0, 30.0]
        );
        // The largest |load| of any case, times the nominal input speed.
        assert_eq!(f.max_actuator_load, 1000.0);
        assert!((f.peak_power_w - 100.0).abs() < 1e-12, "{}", f.peak_power_w);
        // The landing case's 1000 N m over 0.5 rad outworks the cruise case's
        // 0.5 (100 + 300) 0.25 + 0.5 (300 - 500) 0.25 = 25 J.
        assert!(
            (f.work_per_deployment_j - 500.0).abs() < 1e-12,
            "{}",
            f.work_per_deployment_j
        );
        assert_eq!(f.transmission_angle_deg, [30.0, 70.0]);
        assert_eq!(f.mechanism_mass_kg, 2.5, "the station's own entry");
        // The first case's samples, in order.
        assert_eq!(f.gap_overlap, [[0.0, 0.0, 1.0], [20.0, 2.5, 1.0], [40.0, 3.0, 1.0]]);
        // Only the setting with targets; its misses against them.
        assert_eq!(f.setting_misses.len(), 1, "{:?}", f.setting_misses);
        let takeoff = &f.setting_misses[0];
        assert_eq!(takeoff.setting, "takeoff");
        assert_eq!(takeoff.deflection_deg, 20.0);
        assert_eq!(takeoff.target_percent_chord, [2.0, 0.0]);
        assert!((takeoff.gap_miss_percent_chord - 0.5).abs() < 1e-12);
        assert!((takeoff.overlap_miss_percent_chord - 1.0).abs() < 1e-12);
        assert!(f.clearance_passes, "no pair, no joint");
    }

    #[test]
    fn the_documented_values_stand_where_a_figure_is_absent() {
        // No sized part at the station: no entry in the masses, and 0 kg.
        let mut station = designed_station("s1", "outboard");
        // A take-off target without an overlap target: NaN, not a miss of zero.
        station.flap_position.as_mut().unwrap().settings[1] = setting("takeoff", 20.0, 2.5, (Some(2.0), None));
        let f = figures_of(&report_of(station)).unwrap();
        assert_eq!(f.mechanism_mass_kg, 0.0);
        let takeoff = &f.setting_misses[0];
        assert!((takeoff.gap_miss_percent_chord - 0.5).abs() < 1e-12);
        assert!(takeoff.target_percent_chord[1].is_nan() && takeoff.overlap_miss_percent_chord.is_nan());
    }

    #[test]
    fn a_report_without_a_section_the_figures_need_is_an_error_naming_it() {
        let designed = || report_of(designed_station("s1", "outboard"));
        /// Takes one section out of a designed report.
        type TakeOut = fn(&mut Report);
        let cases: [(&str, TakeOut); 5] = [
            ("mechanism", |r| r.stations[0].mechanism = None),
            ("fairing", |r| r.stations[0].fairing = None),
            ("flap_position", |r| r.stations[0].flap_position = None),
            ("interference", |r| r.interference = None),
            ("sizing", |r| r.sizing = None),
        ];
        for (section, take_out) in cases {
            let mut report = designed();
            take_out(&mut report);
            let error = figures_of(&report).unwrap_err();
            assert_eq!(
                error,
                MissingSection {
                    station: "s1".into(),
                    section
                }
            );
            let message = error.to_string();
            assert!(
                message.contains("station s1") && message.contains(&format!("`{section}`")),
                "{message}"
            );
        }
    }

    #[test]
    fn the_clearance_verdict_counts_the_flap_the_station_moves_and_its_joints() {
        let verdict = |pairs, joints| clearance_passes(&interference(pairs, joints), "s1", Some("outboard"));
        assert!(verdict(
            vec![pair("s1.link", "wing", true), pair("outboard", "wing", true)],
            vec![]
        ));
        assert!(!verdict(
            vec![pair("s1.link", "wing", true), pair("outboard", "wing", false)],
            vec![]
        ));
        assert!(!verdict(vec![pair("wing", "s1.link", false)], vec![]));
        // Another flap's pairs, another station's parts and joints are theirs.
        assert!(verdict(
            vec![pair("inboard", "wing", false), pair("s10.link", "wing", false)],
            vec![joint("s2", false)]
        ));
        assert!(!verdict(vec![], vec![joint("s1", false)]));
    }

    fn parsed(text: &str) -> Scene {
        crate::scene::parse::typed(&text.parse().unwrap()).unwrap()
    }

    #[test]
    fn a_variant_keeps_the_kind_neutral_keys_and_the_studied_stations_only() {
        let text = crate::scene::DEFAULT_SCENE_TOML;
        let studied = StudiedScene::new(text, &parsed(text), &["outer".into()]).unwrap();
        assert_eq!(studied.station_index, [1]);
        assert_eq!(
            studied.user_path("station[0].mechanism.kind"),
            "station[1].mechanism.kind"
        );
        assert_eq!(studied.user_path("flap[0].settings"), "flap[0].settings");
        let scene = studied.variant("hooked-track", &crate::scene::NoFiles).unwrap();
        assert_eq!(scene.station.len(), 1);
        assert_eq!(scene.station[0].name, "outer");
        let MechanismScene::HookedTrack(mechanism) = &scene.station[0].mechanism else {
            panic!("the kind in place: {:?}", scene.station[0].mechanism);
        };
        assert_eq!(mechanism.flap_mass_kg, 12.0);
        assert!(mechanism.flap_centre_of_mass_m.is_some(), "carried over");
        assert_eq!(scene.flap.len(), 1);
        assert!(!scene.outputs.urdf && !scene.outputs.stl && scene.outputs.sizing);
        assert!(scene.interference.stop_at_verdict);
        assert!(StudiedScene::new(text, &parsed(text), &["none".into()]).is_err());
    }

    #[test]
    fn a_variant_carries_the_flap_mass_a_kind_names_otherwise() {
        let text = include_str!("../../../data/scenes/double-slotted-wing.toml");
        let studied = StudiedScene::new(text, &parsed(text), &[]).unwrap();
        let scene = studied.variant("dropped-hinge", &crate::scene::NoFiles).unwrap();
        for station in &scene.station {
            // The five-bar's main and secondary flap masses.
            assert_eq!(station.mechanism.kind().flap_mass_kg(), 70.0);
        }
    }

    #[test]
    fn a_variants_problems_name_the_users_station() {
        // A kind whose table needs keys the study does not carry: its problems are at the
        // kept station's index in the user's file.
        let text = crate::scene::DEFAULT_SCENE_TOML;
        let studied = StudiedScene::new(text, &parsed(text), &["outer".into()]).unwrap();
        let problems = studied.variant("five-bar", &crate::scene::NoFiles).unwrap_err();
        let located = studied.locate(problems, text, "scene.toml").lines().join("\n");
        assert!(located.contains("station[1].mechanism"), "{located}");
        assert!(!located.contains("station[0]"), "{located}");
        assert!(located.contains("scene.toml:"), "{located}");
    }

    fn figures(clears: bool, miss: f64, depth: f64) -> StationFigures {
        StationFigures {
            station: "one".into(),
            fairing_depth_percent_flap_chord: depth,
            fairing_length_percent_flap_chord: 100.0,
            actuator_input: InputQuantity::Stroke,
            max_actuator_load: 1.0,
            peak_power_w: 1.0,
            work_per_deployment_j: 1.0,
            mechanism_mass_kg: 1.0,
            setting_misses: vec![SettingMiss {
                setting: "takeoff".into(),
                deflection_deg: 15.0,
                target_percent_chord: [0.0, 3.0],
                gap_miss_percent_chord: miss,
                overlap_miss_percent_chord: 0.0,
            }],
            transmission_angle_deg: [40.0, 80.0],
            clearance_passes: clears,
            gap_overlap: Vec::new(),
            topology: None,
        }
    }

    #[test]
    fn the_ranking_puts_clearance_then_settings_then_depth_first() {
        let shallow_but_interfering = figures(false, 0.0, 10.0);
        let deep_and_exact = figures(true, 0.0, 60.0);
        let shallow_but_missing = figures(true, 2.0, 10.0);
        assert!(rank(&deep_and_exact) < rank(&shallow_but_missing));
        assert!(rank(&shallow_but_missing) < rank(&shallow_but_interfering));
        assert!(rank(&figures(true, 0.0, 20.0)) < rank(&deep_and_exact));
    }

    /// A kind keeps its place, so its style, in the study's charts whichever kinds fail:
    /// one that failed is a legend entry "<kind> (failed)" with nothing drawn; the targets
    /// come after the kinds.
    #[test]
    fn a_failed_kind_keeps_its_place_in_the_charts_legend() {
        let designed = StationFigures {
            gap_overlap: vec![[0.0, 1.0, 6.0], [15.0, 2.0, 4.0]],
            ..figures(true, 0.0, 30.0)
        };
        let outcome = |kind: &str, stations: Vec<StationFigures>| KindOutcome {
            kind: kind.into(),
            error: stations.is_empty().then(|| "cannot be synthesised".into()),
            stations,
        };
        let study = Study {
            scene: "s".into(),
            kinds: vec![
                outcome("dropped-hinge", Vec::new()),
                outcome("four-bar", vec![designed]),
            ],
            ranking: Vec::new(),
            ranking_rule: RANKING_RULE,
        };
        for plot in charts(&study, "one") {
            let names: Vec<&str> = plot.series.iter().map(|s| s.name.as_str()).collect();
            assert_eq!(
                names,
                ["dropped-hinge (failed)", "four-bar", "takeoff target"],
                "{}",
                plot.title
            );
            assert!(plot.series[0].points.is_empty());
            assert_eq!(plot.series[1].points.len(), 2);
            assert_eq!(
                plot.series[2].points,
                [(15.0, plot.series[2].points[0].1)],
                "a marker at the target's deflection"
            );
        }
        let svg = flapwright_drawing::render_plots_svg("s", &charts(&study, "one")).unwrap();
        assert!(svg.contains("dropped-hinge (failed)"), "the legend lists it");
    }
}
