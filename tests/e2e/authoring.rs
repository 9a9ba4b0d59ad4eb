//! `init`, `kinds` and `schema`: the template designs and passes `check` as written for
//! every kind `init` offers (issue 40), and never replaces a file it was not asked to.

use crate::run_flapwright;

/// The kinds `init` offers, as `flapwright kinds --json` marks them.
fn offered_kinds(dir: &std::path::Path) -> Vec<String> {
    let output = run_flapwright(dir, &["--json", "kinds"]);
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    let kinds: serde_json::Value = serde_json::from_slice(&output.stdout).expect("kinds --json is JSON");
    kinds
        .as_array()
        .expect("an array of kinds")
        .iter()
        .filter(|k| k["synthesised"] == true)
        .map(|k| k["name"].as_str().expect("a name").to_string())
        .collect()
}

#[test]
fn the_template_designs_and_passes_check_for_every_kind_init_offers() {
    let dir = tempfile::tempdir().unwrap();
    let kinds = offered_kinds(dir.path());
    assert_eq!(kinds.len(), 4, "{kinds:?}");
    for kind in &kinds {
        let file = format!("{kind}.toml");
        let init = run_flapwright(dir.path(), &["init", &file, "--kind", kind]);
        assert!(
            init.status.success(),
            "init --kind {kind}: {}",
            String::from_utf8_lossy(&init.stderr)
        );
        let text = std::fs::read_to_string(dir.path().join(&file)).unwrap();
        assert_eq!(text.matches(&format!("kind = \"{kind}\"")).count(), 2, "{text}");
        for command in ["design", "check"] {
            let out = format!("{kind}-{command}");
            let run = run_flapwright(dir.path(), &[command, &file, "--out", &out]);
            assert!(
                run.status.success(),
                "{command} of init --kind {kind}: exit {:?}\n{}",
                run.status.code(),
                String::from_utf8_lossy(&run.stderr)
            );
            let report: serde_json::Value =
                serde_json::from_str(&std::fs::read_to_string(dir.path().join(&out).join("report.json")).unwrap())
                    .unwrap();
            assert_eq!(report["interference"]["passes"], true, "{command} --kind {kind}");
        }
    }
    let schema = std::fs::read_to_string(dir.path().join("scene.schema.json")).expect("the schema beside the scene");
    assert!(schema.contains("\"title\": \"Flapwright scene\""));
}

#[test]
fn init_replaces_neither_a_scene_nor_a_schema_it_did_not_write() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("mine.toml"), "my notes").unwrap();
    std::fs::write(dir.path().join("scene.schema.json"), "{\"mine\": true}").unwrap();
    let refused = run_flapwright(dir.path(), &["init", "mine.toml"]);
    assert_eq!(refused.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&refused.stderr).contains("mine.toml exists"));
    assert_eq!(
        std::fs::read_to_string(dir.path().join("mine.toml")).unwrap(),
        "my notes"
    );

    let written = run_flapwright(dir.path(), &["init", "new.toml"]);
    assert!(written.status.success());
    let stderr = String::from_utf8_lossy(&written.stderr);
    assert!(
        stderr.contains("scene.schema.json exists and Flapwright did not write it"),
        "{stderr}"
    );
    assert_eq!(
        std::fs::read_to_string(dir.path().join("scene.schema.json")).unwrap(),
        "{\"mine\": true}"
    );

    let forced = run_flapwright(dir.path(), &["--force", "init", "mine.toml"]);
    assert!(forced.status.success());
    assert!(std::fs::read_to_string(dir.path().join("mine.toml"))
        .unwrap()
        .starts_with("#:schema"));
}

#[test]
fn init_refuses_a_kind_it_cannot_write_naming_those_it_can() {
    let dir = tempfile::tempdir().unwrap();
    for kind in ["five-bar", "no-such-kind"] {
        let refused = run_flapwright(dir.path(), &["init", "x.toml", "--kind", kind]);
        assert_eq!(refused.status.code(), Some(2), "--kind {kind}");
        let stderr = String::from_utf8_lossy(&refused.stderr);
        assert!(
            stderr.contains(&format!("--kind {kind}")) && stderr.contains("hooked-track"),
            "{stderr}"
        );
        assert!(!dir.path().join("x.toml").exists());
    }
}

#[test]
fn kinds_lists_every_kind_with_its_keys() {
    let dir = tempfile::tempdir().unwrap();
    let output = run_flapwright(dir.path(), &["kinds"]);
    assert!(output.status.success());
    let text = String::from_utf8_lossy(&output.stdout);
    for kind in flapwright::kinds::MechanismScene::KINDS {
        assert!(text.lines().any(|l| l.starts_with(kind)), "{kind} missing:\n{text}");
    }
    // A hand-dimensioned kind lists its dimensions as needed.
    assert!(text.contains("base_distance_m"), "{text}");
}

#[test]
fn schema_prints_the_shipped_schema() {
    let dir = tempfile::tempdir().unwrap();
    let output = run_flapwright(dir.path(), &["schema"]);
    assert!(output.status.success());
    let shipped = std::fs::read_to_string(crate::repo_root().join("docs/scene.schema.json")).unwrap();
    assert_eq!(String::from_utf8_lossy(&output.stdout), shipped);
}
