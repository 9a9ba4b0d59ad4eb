//! What the in-memory design tests share: a scene's text designed in memory, and a
//! station's peak actuator load.

use flapwright::pipeline::{design, Inputs, Mode};
use flapwright::report::Report;
use flapwright::scene::{NoFiles, Scene};
use flapwright::MemorySink;

/// The report of `text` (a scene with no files of its own) designed in memory.
pub fn designed(text: &str) -> Report {
    let scene = Scene::from_toml(text, &NoFiles).expect("a valid scene");
    let inputs = Inputs {
        scene: &scene,
        scene_text: text,
        files: &NoFiles,
        wing_cache: None,
    };
    design(&inputs, Mode::Design, &MemorySink::new())
        .expect("designs")
        .report
}

/// The largest actuator load (N, or N m) of `station` over its load cases' samples; NaN
/// where a sample's is (so that a test comparing it fails).
#[allow(dead_code)] // each test file compiles this module; not every one compares loads
pub fn peak_actuator_load(report: &Report, station: &str) -> f64 {
    report
        .stations
        .iter()
        .find(|s| s.name == station)
        .unwrap_or_else(|| panic!("station {station}"))
        .mechanism
        .as_ref()
        .expect("a mechanism")
        .peak_actuator_load()
}
