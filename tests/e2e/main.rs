//! End-to-end tests: run the real `flapwright` binary and re-read what it wrote with
//! independent readers.

mod authoring;
mod bad_input;
mod check;
mod default_scene;
mod exports;
mod fuzz;
mod messages;
mod output_safety;
mod pictures;
mod scene_errors;
mod sizing_figures;
mod stage_failures;
mod stations;
mod stl_reader;
mod study;
mod sweep;
mod synthesised_kinds;
mod trust;
mod two_element;
mod viewer_exports;

use std::path::{Path, PathBuf};
use std::process::Output;

/// The repository root (`data/` lives there).
pub fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The default scene's text, as shipped in `data/scenes/`.
pub fn default_scene_text() -> String {
    std::fs::read_to_string(repo_root().join("data/scenes/small-aircraft.toml")).expect("default scene")
}

/// The default scene with larger slots that stand the tracks 61-165 mm through the upper
/// skin (rear spar at 40 % chord, no torque tube): issue 17's false pass, a scene that
/// fails the clearance check.
pub fn tracks_through_the_upper_skin_scene() -> String {
    let mut scene = default_scene_text()
        .replace("outer_slot_radius_m = 0.350", "outer_slot_radius_m = 0.55")
        .replace("inner_slot_radius_m = 0.300", "inner_slot_radius_m = 0.50")
        .replacen("chord_fraction = 0.64", "chord_fraction = 0.40", 1);
    let tube = scene.find("[structure.torque_tube]").expect("a torque tube");
    let station = scene.find("[[station]]").expect("a station");
    scene.replace_range(tube..station, "");
    scene
}

/// The report's `stages`, in order.
pub fn stages(report: &serde_json::Value) -> Vec<&str> {
    report["stages"]
        .as_array()
        .expect("stages")
        .iter()
        .map(|s| s.as_str().expect("a stage name"))
        .collect()
}

/// Runs `flapwright <command> <scene> <rest> --out out` on the repository's `scene` (a path
/// under the repository root) in a fresh folder, asserts success, and returns the folder
/// and the report it wrote.
pub fn run_on_scene(command: &str, scene: &str, rest: &[&str]) -> (tempfile::TempDir, serde_json::Value) {
    let dir = tempfile::tempdir().unwrap();
    let scene_path = repo_root().join(scene);
    let mut args = vec![command, scene_path.to_str().unwrap()];
    args.extend(rest);
    args.extend(["--out", "out"]);
    let output = run_flapwright(dir.path(), &args);
    assert!(
        output.status.success(),
        "stderr:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let text = std::fs::read_to_string(dir.path().join("out/report.json")).unwrap();
    (dir, serde_json::from_str(&text).unwrap())
}

/// Runs `flapwright` with `args` in `dir`.
pub fn run_flapwright(dir: &Path, args: &[&str]) -> Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_flapwright"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("flapwright runs")
}
