//! The library designs a scene held in a string, its files handed to a `MemorySink`: no
//! folder is made (issue 36).

use flapwright::pipeline::{design, Inputs, Mode};
use flapwright::scene::{Scene, DEFAULT_SCENE_TOML};
use flapwright::MemorySink;

#[test]
fn the_default_scene_is_designed_in_memory() {
    let scene = Scene::from_toml(DEFAULT_SCENE_TOML, None).expect("the default scene is valid");
    let inputs = Inputs {
        scene: &scene,
        scene_text: DEFAULT_SCENE_TOML,
        scene_dir: None,
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
