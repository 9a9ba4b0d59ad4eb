//! What the command line says about a scene (issue 35, items 16 and 17): a misspelt kind
//! alone, warnings printed by `check`, one JSON line with located problems, viewer exports
//! of a 2D scene refused, a huge integer named by its key; a scene without loads and a
//! percentage written as a fraction warned about.

use std::process::Output;

use crate::bad_input::{assert_rejected, default_with};
use crate::{repo_root, run_flapwright, tracks_through_the_upper_skin_scene};

fn run_on(scene: &str, args: &[&str]) -> (tempfile::TempDir, Output) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), scene).unwrap();
    let output = run_flapwright(dir.path(), args);
    (dir, output)
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

#[test]
fn a_misspelt_kind_is_reported_alone() {
    // A four-bar station whose kind is misspelt: not the missing keys of another kind.
    let text = std::fs::read_to_string(repo_root().join("data/scenes/transport-flap.toml")).unwrap();
    let scene = text.replacen("kind = \"four-bar\"", "kind = \"fourbar\"", 1);
    assert_rejected(
        &scene,
        &[
            "1 problem(s)",
            "scene.toml:125:1: station[0].mechanism.kind = \"fourbar\": unknown mechanism kind",
        ],
    );
    let (_dir, output) = run_on(&scene, &["design", "scene.toml", "--out", "out"]);
    assert!(!stderr(&output).contains("missing"), "{}", stderr(&output));
}

/// The warning count of `checked "..." ...: N warning(s)` on stdout.
fn counted_warnings(output: &Output) -> usize {
    let stdout = String::from_utf8_lossy(&output.stdout);
    stdout
        .split(" warning(s)")
        .next()
        .and_then(|head| head.rsplit(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("a warning count: {stdout}"))
}

#[test]
fn check_prints_the_warnings_it_counts() {
    // A failed check (its interference warnings among others) and a passing one whose only
    // warning is the scene's.
    let fraction = default_with("landing_deg = 35.0", "landing_deg = 35.0\nlanding_gap_percent = 0.02");
    for (scene, code) in [(tracks_through_the_upper_skin_scene(), 1), (fraction, 0)] {
        let (_dir, output) = run_on(&scene, &["check", "scene.toml"]);
        let text = stderr(&output);
        assert_eq!(output.status.code(), Some(code), "{text}");
        let counted = counted_warnings(&output);
        let printed = text.lines().filter(|l| l.starts_with("warning: ")).count();
        assert!(counted > 0);
        assert_eq!(printed, counted, "every counted warning printed:\n{text}");
    }
}

#[test]
fn json_is_one_line_with_problems_as_objects() {
    // A failed check: one JSON object, not the summary and then the error.
    let (_dir, output) = run_on(
        &tracks_through_the_upper_skin_scene(),
        &["--json", "check", "scene.toml"],
    );
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert_eq!(stdout.lines().count(), 1, "{stdout}");
    let error: serde_json::Value = serde_json::from_str(stdout.trim()).unwrap();
    assert_eq!(error["exit_code"], 1);
    // Problems as objects with file, line, col, key and message.
    let scene = default_with("chord_m = 2.1", "chord_m = -2.1");
    let (_dir, output) = run_on(&scene, &["--json", "design", "scene.toml"]);
    assert_eq!(output.status.code(), Some(2));
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert_eq!(stdout.lines().count(), 1, "{stdout}");
    let error: serde_json::Value = serde_json::from_str(stdout.trim()).unwrap();
    let problem = &error["problems"][0];
    assert_eq!(problem["file"], "scene.toml", "{error}");
    assert_eq!(problem["line"], 27, "{error}");
    assert_eq!(problem["col"], 1, "{error}");
    assert_eq!(problem["key"], "wing.sections[0].chord_m", "{error}");
    assert!(problem["message"].as_str().unwrap().contains("must be in"), "{error}");
}

#[test]
fn viewer_exports_of_a_2d_scene_are_bad_input() {
    let scene = std::fs::read_to_string(repo_root().join("data/scenes/thesis-case-study.toml")).unwrap();
    for flag in ["--urdf", "--stl", "--gltf"] {
        let (dir, output) = run_on(&scene, &["export", "scene.toml", flag, "--out", "out"]);
        assert_eq!(output.status.code(), Some(2), "{flag}: {}", stderr(&output));
        assert!(stderr(&output).contains("[wing]"), "{flag}: {}", stderr(&output));
        assert!(!dir.path().join("out").exists());
    }
}

#[test]
fn a_huge_integer_is_named_by_its_key_and_line() {
    let scene = format!(
        "{}\n[interference]\ninitial_samples = 99999999999999999999\n",
        crate::default_scene_text()
    );
    let lines = scene.lines().count();
    assert_rejected(
        &scene,
        &[
            &format!("scene.toml:{lines}:19: interference.initial_samples = 99999999999999999999: a whole number beyond the 64-bit range"),
        ],
    );
}

#[test]
fn a_scene_without_loads_warns_that_the_flap_weight_alone_loads_it() {
    let text = crate::default_scene_text();
    let loads = text.find("[loads]").unwrap();
    let outputs = text.find("[outputs]").unwrap();
    let scene = format!("{}{}", &text[..loads], &text[outputs..]);
    let (_dir, output) = run_on(&scene, &["design", "scene.toml", "--out", "out"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let text = stderr(&output);
    assert!(
        text.lines()
            .any(|l| l.starts_with("warning: ") && l.contains("[[loads.cases]]") && l.contains("weight")),
        "{text}"
    );
}

#[test]
fn a_percentage_given_as_a_fraction_is_a_warning_naming_its_key() {
    let scene = default_with(
        "landing_deg = 35.0",
        "landing_deg = 35.0\nlanding_gap_percent = 0.02\nlanding_overlap_percent = 0.0",
    );
    let line = scene
        .lines()
        .position(|l| l.starts_with("landing_gap_percent"))
        .unwrap()
        + 1;
    let (_dir, output) = run_on(&scene, &["design", "scene.toml", "--out", "out"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let text = stderr(&output);
    let warning = text
        .lines()
        .find(|l| l.contains("landing_gap_percent"))
        .unwrap_or_else(|| panic!("a warning naming the key:\n{text}"));
    assert!(
        warning.starts_with(&format!(
            "warning: scene.toml:{line}:1: flap[0].settings.landing_gap_percent = 0.02"
        )),
        "{warning}"
    );
    assert!(!text.contains("landing_overlap_percent"), "0 is a real target:\n{text}");
}
