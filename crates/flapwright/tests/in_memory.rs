//! The library designs a scene held in a string, its files handed to a `MemorySink`: no
//! folder is made (issue 36).

use flapwright::pipeline::{design, Inputs, Mode};
use flapwright::scene::{FileSource, MemoryFiles, NoFiles, Scene, DEFAULT_SCENE_TOML};
use flapwright::MemorySink;

#[test]
fn the_default_scene_is_designed_in_memory() {
    let scene = Scene::from_toml(DEFAULT_SCENE_TOML, &flapwright::scene::NoFiles).expect("the default scene is valid");
    let inputs = Inputs {
        scene: &scene,
        scene_text: DEFAULT_SCENE_TOML,
        files: &NoFiles,
        wing_cache: None,
    };
    let files = MemorySink::new();
    let outcome = design(&inputs, Mode::Design, &files).expect("the default scene designs");
    let files = files.files();
    // The files the report names were handed to the sink, and the report itself.
    let report: serde_json::Value = serde_json::from_slice(&files["report.json"]).expect("report.json is JSON");
    let mut named = vec![
        report["files"]["urdf"]["file"].as_str().expect("a URDF"),
        report["files"]["urdf"]["trajectory_file"]
            .as_str()
            .expect("a trajectory"),
    ];
    let parts = report["parts"].as_array().expect("parts");
    named.extend(parts.iter().map(|p| p["stl_file"].as_str().expect("an STL per part")));
    for name in named {
        assert!(files.contains_key(name), "{name} not written");
    }
    assert_eq!(outcome.report.stations.len(), 2);
    assert_eq!(outcome.summary.interference_passes, Some(true));
}

/// A scene naming its own airfoil file reads it through the `FileSource` it is given: held
/// in memory here, where the command line reads the scene's folder. The design equals the
/// one on the bundled copy of that section.
#[test]
fn an_airfoil_file_given_in_memory_is_read_from_memory() {
    let bundled = flapwright::scene::AirfoilRef::locate("n63212.dat", &NoFiles).expect("bundled");
    let flapwright::scene::AirfoilSource::Bundled(section) = bundled else {
        panic!("n63212.dat is bundled");
    };
    let text = DEFAULT_SCENE_TOML.replace("airfoil = \"n63212.dat\"", "airfoil = \"my-flap.dat\"");
    assert_ne!(text, DEFAULT_SCENE_TOML, "the default scene names n63212.dat");
    let refused = Scene::from_toml(&text, &NoFiles).expect_err("no file given");
    assert!(refused.to_string().contains("my-flap.dat"), "{refused}");

    let given = MemoryFiles::new().with("my-flap.dat", section);
    let scene = Scene::from_toml(&text, &given).expect("the file is given");
    let design_with = |scene: &Scene, text: &str, files: &dyn FileSource| {
        let inputs = Inputs {
            scene,
            scene_text: text,
            files,
            wing_cache: None,
        };
        design(&inputs, Mode::Check, &MemorySink::new()).expect("designs")
    };
    let from_memory = design_with(&scene, &text, &given);
    let default = Scene::from_toml(DEFAULT_SCENE_TOML, &NoFiles).expect("default scene");
    let from_bundle = design_with(&default, DEFAULT_SCENE_TOML, &NoFiles);
    let clearances = |outcome: &flapwright::pipeline::Outcome| -> Vec<f64> {
        let report = outcome.report.interference.as_ref().expect("checked");
        report.pairs.iter().map(|p| p.clearance.min_clearance_m).collect()
    };
    assert_eq!(clearances(&from_memory), clearances(&from_bundle));
}
