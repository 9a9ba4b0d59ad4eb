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

/// Issue 37's magnitudes at `ob-inner` (`003_...` Table 1's station), with its truss-held
/// support: the kind's peak actuator load at most 2.5 times `table_load` (N), its
/// mechanism mass within a factor of 2.5 of `table_mass_kg`, every station's `parts` sized,
/// a truss at every station, the check passing and the sizing loop settled. Returns the
/// peak load.
#[allow(dead_code)] // each test file compiles this module; not every one compares Table 1
pub fn assert_trussed_ob_inner_within_table_1(
    report: &Report,
    parts: &[&str],
    table_load: f64,
    table_mass_kg: f64,
) -> f64 {
    let sizing = report.sizing.as_ref().expect("sized");
    for station in &report.stations {
        let synthesis = &station.mechanism.as_ref().expect("a mechanism").details["synthesis"];
        assert!(synthesis["truss"].is_object(), "{}: a truss", station.name);
        let names: Vec<&str> = sizing
            .rods
            .iter()
            .filter(|rod| rod.station == station.name)
            .map(|rod| rod.name.as_str())
            .collect();
        for part in parts {
            assert!(names.contains(part), "{}: {part} sized in {names:?}", station.name);
        }
    }
    let load = peak_actuator_load(report, "ob-inner");
    let mass = sizing.masses.station_kg("ob-inner");
    assert!(load <= 2.5 * table_load, "ob-inner peak load {load} N");
    assert!(
        (table_mass_kg / 2.5..=2.5 * table_mass_kg).contains(&mass),
        "ob-inner mass {mass} kg"
    );
    assert!(report.interference.as_ref().expect("checked").passes);
    assert!(report.sizing_loop.as_ref().expect("the loop ran").settled);
    load
}
