//! `flapwright sweep` (issue 39): its table against separate `flapwright design` runs read
//! back independently, its shards and its resumption against the whole sweep's bytes, and
//! its refusals.

use super::{repo_root, run_flapwright};

const SCENE: &str = "data/scenes/light-aircraft.toml";
const GAP_LINE: &str = "landing_gap_percent = 2.0";

/// The sweep's arguments: the light aircraft's landing gap at three values.
fn sweep_args(out: &str) -> Vec<String> {
    let scene = repo_root().join(SCENE);
    vec![
        "sweep".into(),
        scene.to_str().unwrap().into(),
        "--vary".into(),
        "flap[*].settings.landing_gap_percent=1.6:2.4:0.4".into(),
        "--out".into(),
        out.into(),
        "--quiet".into(),
    ]
}

fn run(dir: &std::path::Path, args: &[String]) -> std::process::Output {
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    run_flapwright(dir, &args)
}

/// The table's rows as header -> cell maps.
fn rows(text: &str) -> Vec<std::collections::BTreeMap<String, String>> {
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    lines
        .map(|line| {
            // No cell of a designed row holds a comma.
            header
                .iter()
                .map(|h| h.to_string())
                .zip(line.split(',').map(str::to_string))
                .collect()
        })
        .collect()
}

/// Each row's figures equal those read from `report.json` of `flapwright design` run on
/// that variant's scene written by hand (the gap line edited), gathered here: the deepest
/// fairing, the stations' masses summed, the smallest clearance, the largest setting miss.
#[test]
fn a_sweeps_rows_are_the_figures_of_separate_designs() {
    let dir = tempfile::tempdir().unwrap();
    let output = run(dir.path(), &sweep_args("out"));
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    let table = std::fs::read_to_string(dir.path().join("out/sweep.csv")).unwrap();
    let rows = rows(&table);
    assert_eq!(rows.len(), 3);
    let text = std::fs::read_to_string(repo_root().join(SCENE)).unwrap();
    assert!(text.contains(GAP_LINE));
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1.0);
    for (row, gap) in rows.iter().zip(["1.6", "2", "2.4"]) {
        assert_eq!(row["flap[*].settings.landing_gap_percent"], gap);
        assert_eq!(row["verdict"], "pass", "{row:?}");
        let variant = text.replace(GAP_LINE, &format!("landing_gap_percent = {gap}"));
        let file = dir.path().join(format!("variant-{gap}.toml"));
        std::fs::write(&file, variant).unwrap();
        let out = format!("design-{gap}");
        let designed = run_flapwright(
            dir.path(),
            &["design", file.to_str().unwrap(), "--out", &out, "--quiet"],
        );
        assert!(
            designed.status.success(),
            "{}",
            String::from_utf8_lossy(&designed.stderr)
        );
        let report: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.path().join(out).join("report.json")).unwrap()).unwrap();
        let stations = report["stations"].as_array().unwrap();
        let deepest = stations
            .iter()
            .map(|s| s["fairing"]["depth_percent_flap_chord"].as_f64().unwrap())
            .fold(0.0, f64::max);
        let masses: f64 = report["sizing"]["masses"]["per_station"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| s["mass_kg"].as_f64().unwrap())
            .sum();
        let closest = report["interference"]["pairs"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p["min_clearance_m"].as_f64().unwrap())
            .fold(f64::INFINITY, f64::min);
        let cell = |name: &str| row[name].parse::<f64>().unwrap();
        assert!(
            close(cell("fairing_depth_percent_flap_chord"), deepest),
            "{row:?} against {deepest}"
        );
        assert!(close(cell("mechanism_mass_kg"), masses), "{row:?} against {masses}");
        assert!(close(cell("min_clearance_m"), closest), "{row:?} against {closest}");
        assert_eq!(
            row["warnings"].parse::<usize>().unwrap(),
            report["warnings"].as_array().unwrap().len()
        );
    }
}

/// Three shards' tables hold the whole sweep's rows, each once; a table cut short and run
/// again ends as the whole sweep's bytes; a table of another sweep is not replaced.
#[test]
fn shards_and_a_resumed_run_give_the_whole_sweeps_table() {
    let dir = tempfile::tempdir().unwrap();
    assert!(run(dir.path(), &sweep_args("whole")).status.success());
    let whole = std::fs::read_to_string(dir.path().join("whole/sweep.csv")).unwrap();
    let (header, body) = whole.split_once('\n').unwrap();
    let mut gathered: Vec<String> = Vec::new();
    for i in 1..=3 {
        let mut args = sweep_args(&format!("shard-{i}"));
        args.extend(["--shard".into(), format!("{i}/3")]);
        assert!(run(dir.path(), &args).status.success());
        let part = std::fs::read_to_string(dir.path().join(format!("shard-{i}/sweep.csv"))).unwrap();
        let (part_header, part_body) = part.split_once('\n').unwrap();
        assert_eq!(part_header, header);
        gathered.extend(part_body.lines().map(str::to_string));
    }
    gathered.sort_by_key(|line| line.split(',').next().unwrap().parse::<usize>().unwrap());
    assert_eq!(gathered.join("\n") + "\n", body);
    // Cut short after the first row, mid-way through the second: run again.
    let cut = header.len() + 1 + body.find('\n').unwrap() + 20;
    std::fs::write(dir.path().join("whole/sweep.csv"), &whole[..cut]).unwrap();
    assert!(run(dir.path(), &sweep_args("whole")).status.success());
    assert_eq!(
        std::fs::read_to_string(dir.path().join("whole/sweep.csv")).unwrap(),
        whole
    );
    // Not this sweep's table: refused, left as it was.
    std::fs::create_dir_all(dir.path().join("other")).unwrap();
    std::fs::write(dir.path().join("other/sweep.csv"), "name,value\na,1\n").unwrap();
    let refused = run(dir.path(), &sweep_args("other"));
    assert_eq!(refused.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&refused.stderr).contains("not a table of this sweep"));
    assert_eq!(
        std::fs::read_to_string(dir.path().join("other/sweep.csv")).unwrap(),
        "name,value\na,1\n"
    );
}

/// A key the scene has no place for fails the sweep before any design, naming the key.
#[test]
fn a_sweep_of_a_key_the_scene_lacks_is_refused_naming_it() {
    let dir = tempfile::tempdir().unwrap();
    let mut args = sweep_args("out");
    args[3] = "flap[spoiler].settings.landing_deg=30:35:5".into();
    let output = run(dir.path(), &args);
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("flap[spoiler].settings.landing_deg"), "{stderr}");
    assert!(stderr.contains("no element named spoiler"), "{stderr}");
    assert!(!dir.path().join("out").exists(), "nothing written for a refused sweep");
}
