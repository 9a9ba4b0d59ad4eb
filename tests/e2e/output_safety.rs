//! The data-loss and stuck-output reproducers of issue 13: the user's files survive, the
//! run says why it refused (exit 2), and a later run to a proper place succeeds.

use std::fs;
use std::path::Path;

use crate::{repo_root, run_flapwright};

/// The 2D thesis scene: no 3D work, so each run takes milliseconds.
fn thesis_scene(dir: &Path) -> String {
    let text = fs::read_to_string(repo_root().join("data/scenes/thesis-case-study.toml")).unwrap();
    fs::write(dir.join("thesis.toml"), text).unwrap();
    "thesis.toml".into()
}

fn stderr(output: &std::process::Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// A folder of the user's with a `report.json` among other precious files.
fn user_folder(dir: &Path) {
    fs::create_dir_all(dir.join("thesis/data")).unwrap();
    fs::write(dir.join("thesis/report.json"), "{\"mine\": true}").unwrap();
    fs::write(dir.join("thesis/thesis.docx"), "chapter 1").unwrap();
    fs::write(dir.join("thesis/data/table.csv"), "1,2,3").unwrap();
}

fn assert_user_folder_intact(dir: &Path) {
    assert_eq!(
        fs::read_to_string(dir.join("thesis/report.json")).unwrap(),
        "{\"mine\": true}"
    );
    assert_eq!(fs::read_to_string(dir.join("thesis/thesis.docx")).unwrap(), "chapter 1");
    assert_eq!(fs::read_to_string(dir.join("thesis/data/table.csv")).unwrap(), "1,2,3");
}

#[test]
fn a_folder_with_a_report_json_of_the_users_is_not_replaced() {
    let dir = tempfile::tempdir().unwrap();
    let scene = thesis_scene(dir.path());
    user_folder(dir.path());
    let output = run_flapwright(dir.path(), &["design", &scene, "--out", "thesis"]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    let message = stderr(&output);
    assert!(
        message.contains("did not write") && message.contains("thesis.docx"),
        "{message}"
    );
    assert!(message.contains("data/table.csv"), "{message}");
    assert_user_folder_intact(dir.path());
    let later = run_flapwright(dir.path(), &["design", &scene, "--out", "results"]);
    assert!(later.status.success(), "{}", stderr(&later));
}

#[test]
fn the_scenes_own_folder_and_its_parents_are_never_an_output() {
    let dir = tempfile::tempdir().unwrap();
    fs::create_dir(dir.path().join("work")).unwrap();
    let scene = thesis_scene(&dir.path().join("work"));
    fs::write(dir.path().join("work/n63212.dat"), "my airfoil").unwrap();
    // A report.json of an earlier run in the scene folder proves nothing.
    fs::write(dir.path().join("work/report.json"), "{}").unwrap();
    for out in [".", "..", "../work"] {
        let output = run_flapwright(&dir.path().join("work"), &["design", &scene, "--out", out]);
        assert_eq!(output.status.code(), Some(2), "--out {out}: {}", stderr(&output));
        assert!(stderr(&output).contains("holds the scene file"), "{}", stderr(&output));
    }
    assert_eq!(
        fs::read_to_string(dir.path().join("work/n63212.dat")).unwrap(),
        "my airfoil"
    );
    assert!(dir.path().join("work").join(&scene).exists());
}

#[cfg(unix)]
#[test]
fn a_symlinked_report_json_does_not_make_a_folder_ours() {
    let dir = tempfile::tempdir().unwrap();
    let scene = thesis_scene(dir.path());
    user_folder(dir.path());
    fs::remove_file(dir.path().join("thesis/report.json")).unwrap();
    fs::write(dir.path().join("elsewhere.json"), "{}").unwrap();
    std::os::unix::fs::symlink(dir.path().join("elsewhere.json"), dir.path().join("thesis/report.json")).unwrap();
    let output = run_flapwright(dir.path(), &["design", &scene, "--out", "thesis"]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(dir.path().join("thesis/thesis.docx").exists());
}

#[test]
fn a_file_added_to_an_earlier_output_is_kept_and_named() {
    let dir = tempfile::tempdir().unwrap();
    let scene = thesis_scene(dir.path());
    assert!(run_flapwright(dir.path(), &["design", &scene, "--out", "out"])
        .status
        .success());
    // Rerunning over our own output is fine.
    assert!(run_flapwright(dir.path(), &["design", &scene, "--out", "out"])
        .status
        .success());
    fs::write(dir.path().join("out/my-notes.txt"), "notes").unwrap();
    let output = run_flapwright(dir.path(), &["design", &scene, "--out", "out"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(stderr(&output).contains("my-notes.txt"), "{}", stderr(&output));
    assert_eq!(
        fs::read_to_string(dir.path().join("out/my-notes.txt")).unwrap(),
        "notes"
    );
    // --force replaces the folder and says what it removed.
    let forced = run_flapwright(dir.path(), &["--force", "design", &scene, "--out", "out"]);
    assert!(forced.status.success(), "{}", stderr(&forced));
    assert!(stderr(&forced).contains("my-notes.txt"), "{}", stderr(&forced));
    assert!(!dir.path().join("out/my-notes.txt").exists());
}

#[test]
fn leftovers_of_killed_runs_never_block_a_later_run_and_are_cleaned() {
    let dir = tempfile::tempdir().unwrap();
    let scene = thesis_scene(dir.path());
    assert!(run_flapwright(dir.path(), &["design", &scene, "--out", "out"])
        .status
        .success());
    // What a run killed between its renames, or during its work, left behind (the fixed
    // names of earlier versions too); pid 0 is never a user process.
    for leftover in [".out.old", ".out.partial-0", ".out.old-0-1", ".out.partial-0-2"] {
        fs::create_dir(dir.path().join(leftover)).unwrap();
        fs::write(dir.path().join(leftover).join("report.json"), "{}").unwrap();
    }
    let output = run_flapwright(dir.path(), &["design", &scene, "--out", "out"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let mut left: Vec<String> = fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    assert_eq!(left, ["out", "thesis.toml"]);
}

#[cfg(unix)]
#[test]
fn a_symlinked_out_is_followed_and_stays_a_link() {
    let dir = tempfile::tempdir().unwrap();
    let scene = thesis_scene(dir.path());
    fs::create_dir(dir.path().join("real")).unwrap();
    std::os::unix::fs::symlink(dir.path().join("real"), dir.path().join("link")).unwrap();
    for _ in 0..2 {
        let output = run_flapwright(dir.path(), &["design", &scene, "--out", "link"]);
        assert!(output.status.success(), "{}", stderr(&output));
        let link = fs::symlink_metadata(dir.path().join("link")).unwrap();
        assert!(link.file_type().is_symlink(), "--out stays a link");
        assert!(dir.path().join("real/report.json").is_file());
    }
}

#[test]
fn unwritable_or_foreign_junit_paths_are_bad_input() {
    let dir = tempfile::tempdir().unwrap();
    let scene = fs::read_to_string(repo_root().join("data/scenes/small-aircraft.toml")).unwrap();
    fs::write(dir.path().join("scene.toml"), scene).unwrap();
    fs::create_dir(dir.path().join("a-folder")).unwrap();
    fs::write(dir.path().join("mine.xml"), "<notes/>").unwrap();
    for junit in ["no/such/folder/junit.xml", "a-folder", "mine.xml"] {
        let output = run_flapwright(dir.path(), &["check", "scene.toml", "--junit", junit]);
        assert_eq!(output.status.code(), Some(2), "--junit {junit}: {}", stderr(&output));
        assert!(stderr(&output).contains("--junit"), "{}", stderr(&output));
    }
    assert_eq!(fs::read_to_string(dir.path().join("mine.xml")).unwrap(), "<notes/>");
    // Its own JUnit file it may rewrite.
    for _ in 0..2 {
        let output = run_flapwright(dir.path(), &["check", "scene.toml", "--junit", "junit.xml"]);
        assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    }
    // A file it did not write only with --force, and it says so.
    let output = run_flapwright(dir.path(), &["check", "scene.toml", "--junit", "mine.xml", "--force"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert!(stderr(&output).contains("--force: replaced mine.xml, which Flapwright had not written"));
}

#[test]
fn junit_never_replaces_an_input_or_lands_in_the_output_folder() {
    // Found by an independent audit: `--junit scene.toml --force` overwrote the scene.
    let dir = tempfile::tempdir().unwrap();
    let scene = fs::read_to_string(repo_root().join("data/scenes/small-aircraft.toml")).unwrap();
    fs::write(dir.path().join("scene.toml"), &scene).unwrap();
    let airfoil = fs::read_to_string(repo_root().join("data/airfoils/n63215.dat")).unwrap();
    fs::write(dir.path().join("n63215.dat"), &airfoil).unwrap();
    for (junit, what) in [
        ("scene.toml", "is the scene file"),
        ("n63215.dat", "is an airfoil file the scene reads"),
        ("out/junit.xml", "inside --out"),
    ] {
        let output = run_flapwright(
            dir.path(),
            &["check", "scene.toml", "--out", "out", "--junit", junit, "--force"],
        );
        assert_eq!(output.status.code(), Some(2), "--junit {junit}: {}", stderr(&output));
        assert!(
            stderr(&output).contains(&format!("--junit {junit}")),
            "{}",
            stderr(&output)
        );
        assert!(stderr(&output).contains(what), "{}", stderr(&output));
    }
    assert_eq!(fs::read_to_string(dir.path().join("scene.toml")).unwrap(), scene);
    assert_eq!(fs::read_to_string(dir.path().join("n63215.dat")).unwrap(), airfoil);
}

#[test]
fn json_prints_an_error_object_on_every_failure() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("bad.toml"), "name = 3\n").unwrap();
    let output = run_flapwright(dir.path(), &["--json", "design", "bad.toml"]);
    assert_eq!(output.status.code(), Some(2));
    let stdout = String::from_utf8_lossy(&output.stdout);
    let error: serde_json::Value = serde_json::from_str(stdout.trim()).expect("one JSON object on stdout");
    assert_eq!(error["exit_code"], 2);
    let problems = error["problems"].as_array().expect("problems");
    assert!(
        problems
            .iter()
            .any(|p| p["file"] == "bad.toml" && p["line"] == 1 && p["col"] == 1 && p["key"] == "name"),
        "{problems:?}"
    );
    let missing = run_flapwright(dir.path(), &["--json", "design", "missing.toml"]);
    assert_eq!(missing.status.code(), Some(2));
    let error: serde_json::Value = serde_json::from_slice(&missing.stdout).expect("JSON");
    assert!(error["error"].as_str().unwrap().contains("missing.toml"));
}
