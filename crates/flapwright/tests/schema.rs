//! The scene's JSON Schema (issue 40): the shipped copy is the one the scene types give,
//! every shipped scene and the template validate against it, and a misspelt key does not.

use std::path::{Path, PathBuf};

use flapwright::scene::{scene_schema, template, template_kinds, NoFiles, Scene};

/// The workspace root (this crate sits at `crates/flapwright`).
fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn validator() -> jsonschema::Validator {
    let schema: serde_json::Value = serde_json::from_str(&scene_schema()).expect("the schema is JSON");
    jsonschema::draft202012::new(&schema).expect("the schema is a valid draft 2020-12 schema")
}

/// A TOML scene as the JSON value a schema validator reads.
fn as_json(text: &str) -> serde_json::Value {
    let table: toml::Table = toml::from_str(text).expect("TOML");
    serde_json::to_value(table).expect("TOML converts to JSON")
}

/// The problems the validator finds, as `path: message` lines.
fn problems(validator: &jsonschema::Validator, text: &str) -> Vec<String> {
    validator
        .iter_errors(&as_json(text))
        .map(|e| format!("{}: {e}", e.instance_path()))
        .collect()
}

#[test]
fn the_shipped_schema_is_the_one_the_scene_types_give() {
    let shipped = std::fs::read_to_string(workspace().join("docs/scene.schema.json")).expect("docs/scene.schema.json");
    assert!(
        shipped == scene_schema(),
        "docs/scene.schema.json is stale: regenerate it with `cargo run --release -- schema > docs/scene.schema.json`"
    );
}

#[test]
fn every_shipped_scene_and_the_template_validate() {
    let validator = validator();
    let mut scenes: Vec<(String, String)> = std::fs::read_dir(workspace().join("data/scenes"))
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "toml"))
        .map(|path| (path.display().to_string(), std::fs::read_to_string(&path).unwrap()))
        .collect();
    assert!(scenes.len() >= 8, "{} scenes", scenes.len());
    for kind in template_kinds() {
        scenes.push((
            format!("template --kind {kind}"),
            template(kind).expect("an offered kind"),
        ));
    }
    for (name, text) in &scenes {
        let found = problems(&validator, text);
        assert!(found.is_empty(), "{name}: {found:#?}");
    }
}

#[test]
fn the_template_is_a_scene_for_every_kind_it_offers() {
    for kind in template_kinds() {
        let text = template(kind).expect("an offered kind");
        let scene = Scene::from_file_text(&text, "template", &NoFiles).unwrap_or_else(|e| panic!("{kind}: {e}"));
        assert_eq!(scene.station.len(), 2);
        assert!(scene.station.iter().all(|s| s.mechanism.is_synthesised()));
        assert!(scene.warnings.is_empty(), "{kind}: {:?}", scene.warnings);
    }
    assert!(template("no-such-kind").is_none());
}

#[test]
fn a_misspelt_or_misplaced_key_fails_the_schema() {
    let validator = validator();
    let good = template(template_kinds()[0]).unwrap();
    for (from, to, at) in [
        ("name = \"my-wing\"", "nmae = \"my-wing\"", ""),
        ("chord_m = 2.4", "chord_mm = 2.4", "/wing/sections/0"),
        ("flap_mass_kg = 12.0", "flap_mass = 12.0", "/station/0/mechanism"),
        ("landing_gap_percent = 2.0", "landing_gap = 2.0", "/flap/0/settings"),
        // A key of another kind: the link-track's pivot under a dropped hinge.
        (
            "flap_mass_kg = 12.0",
            "flap_mass_kg = 12.0\nlink_pivot_m = [0.0, 0.0]",
            "/station/0/mechanism",
        ),
        // A type: a number as a string.
        ("safety_factor = 1.5", "safety_factor = \"1.5\"", "/loads/safety_factor"),
    ] {
        let bad = good.replacen(from, to, 1);
        assert_ne!(bad, good, "{from} is in the template");
        let found = problems(&validator, &bad);
        assert!(!found.is_empty(), "{to}: passed the schema");
        assert!(found.iter().any(|p| p.starts_with(at)), "{to}: {found:#?}");
    }
    assert!(problems(&validator, &good).is_empty());
}

#[test]
fn every_kind_has_a_summary_and_its_keys() {
    let kinds = flapwright::kinds::MechanismScene::summaries();
    let names: Vec<&str> = kinds.iter().map(|k| k.name.as_str()).collect();
    assert_eq!(names, flapwright::kinds::MechanismScene::KINDS);
    for kind in &kinds {
        assert!(!kind.summary.is_empty());
        assert!(
            kind.required_keys.iter().any(|k| k.ends_with("mass_kg")),
            "{}",
            kind.name
        );
        if kind.synthesised {
            assert_eq!(kind.required_keys, ["flap_mass_kg"], "{}", kind.name);
        }
    }
}
