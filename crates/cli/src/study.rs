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
//! kind-neutral keys above, so it names no kind: a new kind is studied by naming it.

use std::path::Path;

use anyhow::{anyhow, Context, Result};
use flapwright_drawing::{Plot, Series};
use rayon::prelude::*;
use serde::Serialize;
use serde_json::Value;

use crate::output::StagedDir;
use crate::pipeline::WingCache;
use crate::pipeline::{self, Inputs, Mode};
use crate::scene::Scene;

/// The kinds studied when none are named: every kind synthesised from the flap settings.
pub const DEFAULT_KINDS: [&str; 4] = ["dropped-hinge", "four-bar", "link-track", "hooked-track"];

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

/// The scene text with every studied station's mechanism replaced by `kind` (only the
/// stations named in `stations`, all when empty; the others and flaps left without
/// stations are removed so that the study designs only what it compares), and outputs
/// limited to what the figures need.
pub fn variant_text(text: &str, kind: &str, stations: &[String]) -> Result<String> {
    let mut table: toml::Table = text.parse().context("parsing the scene as TOML")?;
    let list = table
        .get_mut("station")
        .and_then(|v| v.as_array_mut())
        .ok_or_else(|| anyhow!("the scene has no [[station]] to study"))?;
    if !stations.is_empty() {
        list.retain(|s| {
            s.get("name")
                .and_then(|n| n.as_str())
                .is_some_and(|n| stations.iter().any(|w| w == n))
        });
        if list.is_empty() {
            return Err(anyhow!("no station named {}", stations.join(", ")));
        }
    }
    let flaps_used: Vec<String> = list
        .iter()
        .filter_map(|s| s.get("flap").and_then(|f| f.as_str()).map(String::from))
        .collect();
    for station in list.iter_mut() {
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
        *mechanism = replaced;
    }
    if let Some(flaps) = table.get_mut("flap").and_then(|v| v.as_array_mut()) {
        flaps.retain(|f| {
            f.get("name")
                .and_then(|n| n.as_str())
                .is_some_and(|n| flaps_used.iter().any(|u| u == n))
        });
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
    toml::to_string(&table).context("writing the study's scene")
}

/// Runs the study: one design per kind into `out/<kind>/`, then `study.json` and the gap
/// and overlap charts (`study-<station>.svg`) into `out`.
pub fn run(
    text: &str,
    scene_dir: Option<&Path>,
    label: &str,
    kinds: &[String],
    stations: &[String],
    out: &StagedDir,
) -> Result<Study> {
    // The kinds are independent designs into their own folders: in parallel (rayon), in
    // the order asked. Each design also runs its pairs in parallel; running the kinds side by
    // side lets one kind's serial stages (synthesis searches, a pair that takes long) overlap
    // the others' work.
    let variants = kinds
        .iter()
        .map(|kind| Ok((kind, variant_text(text, kind, stations)?)))
        .collect::<Result<Vec<_>>>()?;
    // The kinds design the same wing: its meshes, their statistics and their collision
    // shapes are built once for all.
    let cache = WingCache::default();
    let designed: Vec<_> = variants
        .par_iter()
        .map(|(kind, variant)| {
            let label = format!("{label} as {kind}");
            (*kind, design_kind(variant, scene_dir, &label, kind, out, &cache))
        })
        .collect();
    let mut outcomes = Vec::new();
    let mut scene_name = String::new();
    for (kind, outcome) in designed {
        match outcome {
            Ok((name, figures)) => {
                scene_name = name;
                outcomes.push(KindOutcome {
                    kind: kind.clone(),
                    stations: figures,
                    error: None,
                });
            }
            Err(error) => outcomes.push(KindOutcome {
                kind: kind.clone(),
                stations: Vec::new(),
                error: Some(format!("{error:#}")),
            }),
        }
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
        scene: scene_name,
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
        std::fs::write(out.file(&format!("study-{station}.svg")), svg).context("writing the study charts")?;
    }
    let json = serde_json::to_string_pretty(&study).context("serialising the study")?;
    std::fs::write(out.file("study.json"), json + "\n").context("writing study.json")?;
    Ok(study)
}

/// Designs one kind's variant into `out/<kind>/` and gathers its stations' figures.
fn design_kind(
    variant: &str,
    scene_dir: Option<&Path>,
    label: &str,
    kind: &str,
    out: &StagedDir,
    cache: &WingCache,
) -> Result<(String, Vec<StationFigures>)> {
    let scene =
        Scene::from_file_text(variant, label, scene_dir).map_err(|e| anyhow!("{}", e.locate(variant, label)))?;
    let folder = out.file(kind);
    std::fs::create_dir_all(&folder).with_context(|| format!("creating {}", folder.display()))?;
    let staged = StagedDir::create(&folder, None, false)?;
    let inputs = Inputs {
        scene: &scene,
        scene_text: variant,
        scene_dir,
        wing_cache: Some(cache),
    };
    let outcome = pipeline::design(&inputs, Mode::Design, &staged)?;
    staged.commit()?;
    let report = serde_json::to_value(&outcome.report).context("reading the kind's report")?;
    let figures = report["stations"]
        .as_array()
        .map(|stations| stations.iter().map(|s| station_figures(&report, s)).collect())
        .unwrap_or_default();
    Ok((scene.name.clone(), figures))
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
            gap_miss_percent_chord: number(&s["gap_percent_chord"]) - number(&s["target_gap_percent_chord"]),
            overlap_miss_percent_chord: number(&s["overlap_percent_chord"])
                - number(&s["target_overlap_percent_chord"]),
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

    const SCENE: &str = r#"
name = "s"
[[flap]]
name = "a"
[[flap]]
name = "b"
[[station]]
name = "one"
flap = "a"
[station.mechanism]
kind = "four-bar"
flap_mass_kg = 10.0
forward_pivot_m = [0.1, 0.2]
min_transmission_angle_deg = 35.0
[[station]]
name = "two"
flap = "b"
[station.mechanism]
kind = "dropped-hinge"
flap_mass_kg = 12.0
"#;

    #[test]
    fn a_variant_keeps_the_kind_neutral_keys_and_the_studied_stations_only() {
        let text = variant_text(SCENE, "hooked-track", &["one".into()]).unwrap();
        let table: toml::Table = text.parse().unwrap();
        let stations = table["station"].as_array().unwrap();
        assert_eq!(stations.len(), 1);
        let mechanism = stations[0]["mechanism"].as_table().unwrap();
        assert_eq!(mechanism["kind"].as_str(), Some("hooked-track"));
        assert_eq!(mechanism["flap_mass_kg"].as_float(), Some(10.0));
        assert_eq!(mechanism["min_transmission_angle_deg"].as_float(), Some(35.0));
        assert!(!mechanism.contains_key("forward_pivot_m"));
        let flaps = table["flap"].as_array().unwrap();
        assert_eq!(flaps.len(), 1, "the flap without a studied station goes");
        assert_eq!(table["outputs"]["urdf"].as_bool(), Some(false));
        assert_eq!(table["interference"]["stop_at_verdict"].as_bool(), Some(true));
        assert!(variant_text(SCENE, "four-bar", &["none".into()]).is_err());
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
