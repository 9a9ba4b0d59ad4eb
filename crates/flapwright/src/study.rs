//! `flapwright study`: the trade study of mechanism kinds (`003_...` section 5.2, Table 1
//! and Fig. 17). Each candidate kind replaces the mechanism of every studied station (the
//! flap mass, centre of mass and minimum transmission angle carried over, every other
//! choice the kind's own default or search); the scene is then designed as usual, without
//! STL, URDF or drawings, into one folder per kind, and each station's figures are
//! gathered from the kind's report: fairing depth and length, largest actuator load, peak
//! power, work per deployment, mechanism mass, the misses at the settings, the
//! transmission-angle range and the clearance verdict; with charts of gap and overlap
//! against deflection for every kind and a ranking.
//!
//! The study edits the scene as a TOML table and touches only the `kind` key and the
//! kind-neutral keys above, so it names no kind: a new kind is studied by naming it. The
//! tables are never written out as text: their problems are located in the user's file,
//! with the station and flap indices of that file.

use anyhow::{anyhow, Context, Result};
use flapwright_drawing::{Plot, Series};
use rayon::prelude::*;
use serde::Serialize;
use serde_json::Value;

use crate::pipeline::WingCache;
use crate::pipeline::{self, Inputs, Mode};
use crate::scene::{FileSource, Problem, Scene, SceneError};
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
    /// "stroke" (screw jack: loads in N, power from the nut speed) or "angle" (rotary: N m).
    pub actuator_input: String,
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

/// The ranking rule, as the README states it.
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

/// A studied scene as a table, and where its stations and flaps come from in the user's
/// file (the study keeps only the studied stations and their flaps).
#[derive(Debug, Clone)]
pub struct Variant {
    /// The scene table with the kind in place of each kept station's mechanism.
    pub table: toml::Table,
    /// For each kept station, its index in the user's file.
    pub station_index: Vec<usize>,
    /// For each kept flap, its index in the user's file.
    pub flap_index: Vec<usize>,
}

impl Variant {
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

/// The scene with every studied station's mechanism replaced by `kind` (only the stations
/// named in `stations`, all when empty; the others and flaps left without stations are
/// removed so that the study designs only what it compares), and outputs limited to what
/// the figures need. `scene` is the same file, parsed: it gives the flap mass of a station
/// whose table names it otherwise (the five-bar's two elements).
pub fn variant(text: &str, scene: &Scene, kind: &str, stations: &[String]) -> Result<Variant> {
    let mut table: toml::Table = text.parse().context("parsing the scene as TOML")?;
    let list = table
        .get_mut("station")
        .and_then(|v| v.as_array_mut())
        .ok_or_else(|| anyhow!("the scene has no [[station]] to study"))?;
    let studied = |name: &str| stations.is_empty() || stations.iter().any(|w| w == name);
    let station_index: Vec<usize> = scene
        .station
        .iter()
        .enumerate()
        .filter(|(_, s)| studied(&s.name))
        .map(|(i, _)| i)
        .collect();
    if station_index.is_empty() {
        return Err(anyhow!("no station named {}", stations.join(", ")));
    }
    if list.len() != scene.station.len() {
        return Err(anyhow!(
            "the scene's [[station]] tables are not the scene it was parsed into"
        ));
    }
    let kept: Vec<toml::Value> = station_index.iter().map(|&i| list[i].clone()).collect();
    *list = kept;
    for (station, &i) in list.iter_mut().zip(&station_index) {
        let Some(mechanism) = station.get_mut("mechanism").and_then(|m| m.as_table_mut()) else {
            continue;
        };
        let mut replaced = toml::Table::new();
        replaced.insert("kind".into(), toml::Value::String(kind.into()));
        for key in CARRIED_KEYS {
            if let Some(value) = mechanism.get(key) {
                replaced.insert(key.into(), value.clone());
            }
        }
        if !replaced.contains_key("flap_mass_kg") {
            let mass = scene.station[i].mechanism.kind().flap_mass_kg();
            replaced.insert("flap_mass_kg".into(), toml::Value::Float(mass));
        }
        *mechanism = replaced;
    }
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
    if let Some(flaps) = table.get_mut("flap").and_then(|v| v.as_array_mut()) {
        let kept: Vec<toml::Value> = flap_index.iter().filter_map(|&i| flaps.get(i).cloned()).collect();
        *flaps = kept;
    }
    let mut outputs = toml::Table::new();
    for (key, on) in [
        ("stl", false),
        ("urdf", false),
        ("svg", false),
        ("gltf", false),
        ("kinematics", true),
        ("sizing", true),
        ("interference", true),
    ] {
        outputs.insert(key.into(), toml::Value::Boolean(on));
    }
    table.insert("outputs".into(), toml::Value::Table(outputs));
    // The study reads only each pair's verdict, so its sweeps stop refining a pair once the
    // verdict is certain instead of locating its minimum to the tolerance: the same
    // certified pass or fail (the pair's lower bound still meets the requirement, or a
    // sample already misses it) for a fraction of the distance evaluations. The kinds'
    // reports say so (`interference.stopped_at_verdict`), and their pairs'
    // `min_clearance_m` are the smallest samples, `residual_bound_m` how much lower the
    // true minimum may be.
    let interference = table
        .entry("interference")
        .or_insert_with(|| toml::Value::Table(toml::Table::new()));
    if let Some(interference) = interference.as_table_mut() {
        interference.insert("stop_at_verdict".into(), toml::Value::Boolean(true));
    }
    Ok(Variant {
        table,
        station_index,
        flap_index,
    })
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

/// No kind could be designed: each kind's reason, on one line.
#[derive(Debug)]
pub struct NoKindDesigned {
    /// The scene's name.
    pub scene: String,
    /// Each kind and its reason, as one line.
    pub reasons: Vec<(String, String)>,
    /// Every reason is a problem of the input (the scene), not of Flapwright.
    pub input_problem: bool,
}

impl std::fmt::Display for NoKindDesigned {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let reasons: Vec<String> = self
            .reasons
            .iter()
            .map(|(kind, why)| format!("{kind}: {why}"))
            .collect();
        write!(
            f,
            "study of \"{}\": no kind could be designed; {}",
            self.scene,
            reasons.join("; ")
        )
    }
}

impl std::error::Error for NoKindDesigned {}

/// A kind's failure as one line: a scene's problems joined, any other error's chain.
fn one_line(error: &anyhow::Error) -> String {
    match error.downcast_ref::<SceneError>() {
        Some(scene_error) => scene_error.lines().join("; "),
        None => format!("{error:#}").replace('\n', " "),
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
    // The kinds are independent designs into their own folders: in parallel (rayon), in
    // the order asked. Each design also runs its pairs in parallel; running the kinds side by
    // side lets one kind's serial stages (synthesis searches, a pair that takes long) overlap
    // the others' work.
    let variants = kinds
        .iter()
        .map(|kind| Ok((kind, variant(text, scene, kind, stations)?)))
        .collect::<Result<Vec<_>>>()?;
    // The kinds design the same wing: its meshes, their statistics and their collision
    // shapes are built once for all.
    let cache = WingCache::default();
    let designed: Vec<_> = variants
        .par_iter()
        .map(|(kind, variant)| (*kind, design_kind(variant, text, files, file, kind, out, &cache)))
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
                    error: Some(format!("{error:#}")),
                });
                failures.push((kind.clone(), error));
            }
        }
    }
    if !kinds.is_empty() && failures.len() == kinds.len() {
        return Err(NoKindDesigned {
            scene: scene.name.clone(),
            input_problem: failures.iter().all(|(_, e)| e.downcast_ref::<SceneError>().is_some()),
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
        .with_context(|| format!("drawing the study charts of {station}"))?;
        out.write(&format!("study-{station}.svg"), svg.as_bytes())
            .context("writing the study charts")?;
    }
    let json = serde_json::to_string_pretty(&study).context("serialising the study")?;
    out.write("study.json", (json + "\n").as_bytes())
        .context("writing study.json")?;
    Ok(study)
}

/// Designs one kind's variant into `out/<kind>/` (no folder when it fails) and gathers its
/// stations' figures; its problems are located in the user's file.
fn design_kind(
    variant: &Variant,
    text: &str,
    files: &dyn FileSource,
    file: &str,
    kind: &str,
    out: &dyn Sink,
    cache: &WingCache,
) -> Result<Vec<StationFigures>> {
    let scene = Scene::from_table(&variant.table, files).map_err(|p| variant.locate(p, text, file))?;
    // Designed in memory, written as one folder only when the whole design succeeded (no
    // folder for a kind that could not be designed).
    let written = MemorySink::new();
    let inputs = Inputs {
        scene: &scene,
        scene_text: text,
        files,
        wing_cache: Some(cache),
    };
    let outcome =
        pipeline::design(&inputs, Mode::Design, &written).map_err(|error| match error.downcast::<SceneError>() {
            Ok(SceneError::Invalid(problems)) => anyhow::Error::new(variant.locate(problems, text, file)),
            Ok(other) => anyhow::Error::new(other),
            Err(error) => error,
        })?;
    out.write_folder(kind, &written)
        .with_context(|| format!("writing the {kind} folder"))?;
    let report = serde_json::to_value(&outcome.report).context("reading the kind's report")?;
    let figures = report["stations"]
        .as_array()
        .map(|stations| stations.iter().map(|s| station_figures(&report, s)).collect())
        .unwrap_or_default();
    Ok(figures)
}

fn number(value: &Value) -> f64 {
    value.as_f64().unwrap_or(f64::NAN)
}

/// One station's figures from its kind's report.
fn station_figures(report: &Value, station: &Value) -> StationFigures {
    let name = station["name"].as_str().unwrap_or_default().to_string();
    let mechanism = &station["mechanism"];
    let actuator = &mechanism["actuator"];
    let speed = number(&actuator["nominal_speed_mps"]).max(number(&actuator["nominal_speed_radps"]));
    let speed = if speed.is_finite() { speed } else { 0.0 };
    let empty = Vec::new();
    let cases = mechanism["load_cases"].as_array().unwrap_or(&empty);
    let (mut max_load, mut work, mut mu) = (0.0f64, 0.0f64, [f64::INFINITY, f64::NEG_INFINITY]);
    for case in cases {
        let samples = case["samples"].as_array().unwrap_or(&empty);
        let mut case_work = 0.0;
        for pair in samples.windows(2) {
            let (a, b) = (&pair[0], &pair[1]);
            case_work += 0.5
                * (number(&a["actuator_load"]) + number(&b["actuator_load"]))
                * (number(&b["input"]) - number(&a["input"]));
        }
        work = work.max(case_work.abs());
        for sample in samples {
            max_load = max_load.max(number(&sample["actuator_load"]).abs());
            let angle = number(&sample["transmission_angle_deg"]);
            mu = [mu[0].min(angle), mu[1].max(angle)];
        }
    }
    let gap_overlap = cases
        .first()
        .and_then(|c| c["samples"].as_array())
        .map(|samples| {
            samples
                .iter()
                .filter_map(|s| {
                    let p = &s["flap_position"];
                    Some([
                        s["deflection_deg"].as_f64()?,
                        p["gap_percent_chord"].as_f64()?,
                        p["overlap_percent_chord"].as_f64()?,
                    ])
                })
                .collect()
        })
        .unwrap_or_default();
    let setting_misses = station["flap_position"]["settings"]
        .as_array()
        .unwrap_or(&empty)
        .iter()
        .filter(|s| s["target_gap_percent_chord"].is_number())
        .map(|s| SettingMiss {
            setting: s["setting"].as_str().unwrap_or_default().to_string(),
            deflection_deg: number(&s["deflection_deg"]),
            target_percent_chord: [
                number(&s["target_gap_percent_chord"]),
                number(&s["target_overlap_percent_chord"]),
            ],
            // Against what the setting was built to: a sealed slot's gap against its seal.
            gap_miss_percent_chord: number(&s["gap_miss_percent_chord"]),
            overlap_miss_percent_chord: number(&s["overlap_miss_percent_chord"]),
        })
        .collect();
    let prefix = format!("{name}.");
    // The flap this station moves is the kind's result too: each kind moves it on its own
    // path, so the flap's pairs (against the wing, spars, tube) count with the station's.
    let flap = station["flap"].as_str();
    let interference = &report["interference"];
    let clearance_passes = interference["pairs"]
        .as_array()
        .unwrap_or(&empty)
        .iter()
        .filter(|p| {
            [&p["part_a"], &p["part_b"]]
                .iter()
                .any(|n| n.as_str().is_some_and(|n| n.starts_with(&prefix) || Some(n) == flap))
        })
        .all(|p| p["passes"] == true)
        && interference["declared_contacts"]
            .as_array()
            .unwrap_or(&empty)
            .iter()
            .filter(|c| c["declared"]["station"].as_str() == Some(name.as_str()))
            .all(|c| c["passes"] == true);
    let mass = report["sizing"]["masses"]["per_station"]
        .as_array()
        .unwrap_or(&empty)
        .iter()
        .find(|m| m["station"].as_str() == Some(name.as_str()))
        .map_or(0.0, |m| number(&m["mass_kg"]));
    StationFigures {
        fairing_depth_percent_flap_chord: number(&station["fairing"]["depth_percent_flap_chord"]),
        fairing_length_percent_flap_chord: number(&station["fairing"]["length_percent_flap_chord"]),
        actuator_input: mechanism["input"]["quantity"].as_str().unwrap_or_default().to_string(),
        max_actuator_load: max_load,
        peak_power_w: max_load * speed,
        work_per_deployment_j: work,
        mechanism_mass_kg: mass,
        setting_misses,
        transmission_angle_deg: mu,
        clearance_passes,
        gap_overlap,
        station: name,
    }
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

/// Gap and overlap against deflection for every kind at `station`, targets marked.
fn charts(study: &Study, station: &str) -> Vec<Plot> {
    let figures = at_station(&study.kinds, station);
    let plot = |title: &str, column: usize| {
        let mut series: Vec<Series> = figures
            .iter()
            .filter(|(_, f)| !f.gap_overlap.is_empty())
            .map(|(kind, f)| Series {
                name: kind.to_string(),
                points: f.gap_overlap.iter().map(|row| (row[0], row[column])).collect(),
            })
            .collect();
        // The targets as short marks at their settings' deflections.
        if let Some((_, f)) = figures.first() {
            for miss in &f.setting_misses {
                let value = miss.target_percent_chord[column - 1];
                if value.is_finite() && miss.deflection_deg.is_finite() {
                    series.push(Series {
                        name: format!("{} target", miss.setting),
                        points: vec![(miss.deflection_deg - 0.5, value), (miss.deflection_deg + 0.5, value)],
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
            let load = if f.actuator_input == "angle" {
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
    use super::*;

    #[test]
    fn the_clearance_verdict_counts_the_flap_the_station_moves() {
        let pair = |a: &str, b: &str, passes: bool| serde_json::json!({"part_a": a, "part_b": b, "passes": passes});
        let station = serde_json::json!({"name": "s1", "flap": "outboard"});
        let report = |pairs: Vec<Value>| serde_json::json!({"interference": {"pairs": pairs, "declared_contacts": []}});
        let clear = report(vec![pair("s1.link", "wing", true), pair("outboard", "wing", true)]);
        assert!(station_figures(&clear, &station).clearance_passes);
        let flap_too_close = report(vec![pair("s1.link", "wing", true), pair("outboard", "wing", false)]);
        assert!(!station_figures(&flap_too_close, &station).clearance_passes);
        let other_flap = report(vec![pair("s1.link", "wing", true), pair("inboard", "wing", false)]);
        assert!(station_figures(&other_flap, &station).clearance_passes);
    }

    fn parsed(text: &str) -> Scene {
        crate::scene::parse::typed(&text.parse().unwrap()).unwrap()
    }

    #[test]
    fn a_variant_keeps_the_kind_neutral_keys_and_the_studied_stations_only() {
        let text = crate::scene::DEFAULT_SCENE_TOML;
        let variant = variant(text, &parsed(text), "hooked-track", &["outer".into()]).unwrap();
        let table = &variant.table;
        let stations = table["station"].as_array().unwrap();
        assert_eq!(stations.len(), 1);
        assert_eq!(variant.station_index, [1]);
        assert_eq!(
            variant.user_path("station[0].mechanism.kind"),
            "station[1].mechanism.kind"
        );
        assert_eq!(variant.user_path("flap[0].settings"), "flap[0].settings");
        let mechanism = stations[0]["mechanism"].as_table().unwrap();
        assert_eq!(mechanism["kind"].as_str(), Some("hooked-track"));
        assert_eq!(mechanism["flap_mass_kg"].as_float(), Some(12.0));
        assert!(mechanism.contains_key("flap_centre_of_mass_m"));
        assert!(!mechanism.contains_key("base_distance_m"));
        assert_eq!(table["flap"].as_array().unwrap().len(), 1);
        assert_eq!(table["outputs"]["urdf"].as_bool(), Some(false));
        assert_eq!(table["interference"]["stop_at_verdict"].as_bool(), Some(true));
        assert!(super::variant(text, &parsed(text), "four-bar", &["none".into()]).is_err());
    }

    #[test]
    fn a_variant_carries_the_flap_mass_a_kind_names_otherwise() {
        let text = include_str!("../../../data/scenes/double-slotted-wing.toml");
        let variant = variant(text, &parsed(text), "dropped-hinge", &[]).unwrap();
        for station in variant.table["station"].as_array().unwrap() {
            // The five-bar's main and secondary flap masses.
            assert_eq!(station["mechanism"]["flap_mass_kg"].as_float(), Some(70.0));
        }
    }

    fn figures(clears: bool, miss: f64, depth: f64) -> StationFigures {
        StationFigures {
            station: "one".into(),
            fairing_depth_percent_flap_chord: depth,
            fairing_length_percent_flap_chord: 100.0,
            actuator_input: "stroke".into(),
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
}
