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
    // Runs killed during their work (a staging folder left), and after their renames (the
    // earlier output still beside the new one).
    for point in ["staged", "after-renames", "staged"] {
        let killed = run_killed_at(dir.path(), point, &["design", &scene, "--out", "out"]);
        assert!(!killed.status.success(), "the test hook ends the run at {point}");
    }
    assert!(names_in(dir.path()).len() > 4, "{:?}", names_in(dir.path()));
    let output = run_flapwright(dir.path(), &["design", &scene, "--out", "out"]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(names_in(dir.path()), ["out", "thesis.toml"]);
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

/// Issue 35 item 13: the scene file is read no further than the size limit: `/dev/zero`
/// (endless) is refused at once, in little memory (the run gets 1 GB of address space; the
/// earlier code read on until the allocator gave up).
#[cfg(target_os = "linux")]
#[test]
fn an_endless_scene_file_is_read_no_further_than_the_limit() {
    use std::io::Read;
    use wait_timeout::ChildExt;
    let dir = tempfile::tempdir().unwrap();
    let mut child = std::process::Command::new("sh")
        .arg("-c")
        .arg("ulimit -v 1000000 && exec \"$0\" design /dev/zero --out out")
        .arg(env!("CARGO_BIN_EXE_flapwright"))
        .current_dir(dir.path())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let status = match child.wait_timeout(std::time::Duration::from_secs(60)).unwrap() {
        Some(status) => status,
        None => {
            let _ = child.kill();
            let _ = child.wait();
            panic!("reading /dev/zero as a scene ran past 60 s");
        }
    };
    let mut message = String::new();
    child.stderr.take().unwrap().read_to_string(&mut message).unwrap();
    assert_eq!(status.code(), Some(2), "{message}");
    assert!(
        message.contains("/dev/zero") && message.contains("at most 1048576 bytes"),
        "{message}"
    );
    assert!(!dir.path().join("out").exists());
}

/// Issue 35 item 20: every subcommand's default output folder is ignored by git, and none
/// is tracked. The defaults are read from the binary's own `--help`.
#[test]
fn default_output_folders_are_ignored_and_not_tracked() {
    let root = repo_root();
    let ignore = fs::read_to_string(root.join(".gitignore")).unwrap();
    let mut defaults = Vec::new();
    for command in ["design", "export", "study", "check"] {
        let help = run_flapwright(&root, &[command, "--help"]);
        let text = String::from_utf8_lossy(&help.stdout).into_owned();
        let out = text
            .split("--out <OUT>")
            .nth(1)
            .and_then(|rest| rest.split("[default: ").nth(1))
            .and_then(|rest| rest.split(']').next())
            .unwrap_or_else(|| panic!("{command} --help names the default --out: {text}"))
            .to_string();
        defaults.push(out);
    }
    for out in &defaults {
        assert!(
            ignore.lines().any(|line| line.trim() == format!("/{out}")),
            ".gitignore lists /{out}"
        );
        // Only where git and the repository's history are at hand (not in a source archive).
        if let Ok(listed) = std::process::Command::new("git")
            .args(["ls-files", "--", out])
            .current_dir(&root)
            .output()
        {
            if listed.status.success() {
                assert!(
                    listed.stdout.is_empty(),
                    "{out} is tracked: {}",
                    String::from_utf8_lossy(&listed.stdout)
                );
            }
        }
    }
}

/// The names in `dir`, sorted.
fn names_in(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// Issue 35 item 10: `--out ./out/../out` names `out`: it is resolved once, before anything
/// moves, and replaces `out` like `--out out` does.
#[test]
fn an_out_spelled_through_dot_dot_is_the_same_folder() {
    let dir = tempfile::tempdir().unwrap();
    let scene = thesis_scene(dir.path());
    for out in ["out", "./out/../out", "./out/../out"] {
        let output = run_flapwright(dir.path(), &["design", &scene, "--out", out]);
        assert!(output.status.success(), "--out {out}: {}", stderr(&output));
        assert!(dir.path().join("out/report.json").is_file(), "--out {out}");
        assert_eq!(names_in(dir.path()), ["out", "thesis.toml"], "--out {out}");
    }
}

/// Issue 35 item 12: `--out .` (the folder the run is in) is refused before any work, with
/// the reason; nothing is written beside it.
#[test]
fn the_folder_the_run_is_in_is_refused_up_front() {
    let dir = tempfile::tempdir().unwrap();
    thesis_scene(dir.path());
    fs::create_dir(dir.path().join("empty")).unwrap();
    let here = dir.path().join("empty");
    for out in [".", "../empty", "./."] {
        let output = run_flapwright(&here, &["design", "../thesis.toml", "--out", out]);
        assert_eq!(output.status.code(), Some(2), "--out {out}: {}", stderr(&output));
        assert!(
            stderr(&output).contains("the folder this run is in"),
            "{}",
            stderr(&output)
        );
        assert!(names_in(&here).is_empty(), "--out {out}");
        assert_eq!(names_in(dir.path()), ["empty", "thesis.toml"], "--out {out}");
    }
}

/// Issue 35 item 12: `--out out/.` is the folder `out`, replaced as `--out out` is.
#[test]
fn an_out_ending_in_dot_is_the_folder_itself() {
    let dir = tempfile::tempdir().unwrap();
    let scene = thesis_scene(dir.path());
    for out in ["out/.", "out/.", "out"] {
        let output = run_flapwright(dir.path(), &["design", &scene, "--out", out]);
        assert!(output.status.success(), "--out {out}: {}", stderr(&output));
        assert!(dir.path().join("out/report.json").is_file());
        assert_eq!(names_in(dir.path()), ["out", "thesis.toml"], "--out {out}");
    }
}

/// Issue 35 item 12: an earlier output the user made read-only is refused before any work
/// (exit 2, saying so) and left whole; nothing hidden is left beside it. As root, where
/// permissions do not stop a removal, one file is also made immutable (`chattr +i`), which
/// is what stopped the earlier code half-way.
#[cfg(unix)]
#[test]
fn a_read_only_earlier_output_is_refused_and_left_whole() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let scene = thesis_scene(dir.path());
    assert!(run_flapwright(dir.path(), &["design", &scene, "--out", "prev"])
        .status
        .success());
    let prev = dir.path().join("prev");
    let before = names_in(&prev);
    let set_mode = |mode: u32| {
        for entry in fs::read_dir(&prev).unwrap() {
            let path = entry.unwrap().path();
            if path.is_file() {
                fs::set_permissions(&path, fs::Permissions::from_mode(mode & 0o666)).unwrap();
            }
        }
        fs::set_permissions(&prev, fs::Permissions::from_mode(mode)).unwrap();
    };
    set_mode(0o555);
    let immutable = prev.join("report.json");
    let chattr = |flag: &str| {
        std::process::Command::new("chattr")
            .arg(flag)
            .arg(&immutable)
            .output()
            .is_ok_and(|o| o.status.success())
    };
    let made_immutable = chattr("+i");
    let output = run_flapwright(dir.path(), &["design", &scene, "--out", "prev"]);
    if made_immutable {
        chattr("-i");
    }
    set_mode(0o755);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(stderr(&output).contains("read-only"), "{}", stderr(&output));
    assert_eq!(names_in(&prev), before, "the earlier output is left whole");
    assert_eq!(names_in(dir.path()), ["prev", "thesis.toml"], "nothing hidden is left");
    // Writable again, it is replaced.
    let output = run_flapwright(dir.path(), &["design", &scene, "--out", "prev"]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(names_in(dir.path()), ["prev", "thesis.toml"]);
}

/// Runs `flapwright` with `args` in `dir`, the test hook `FLAPWRIGHT_TEST_EXIT_AT` set to
/// `point`: the run ends there at once, as a `kill -9` would end it (no clean-up).
fn run_killed_at(dir: &Path, point: &str, args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_flapwright"))
        .args(args)
        .env("FLAPWRIGHT_TEST_EXIT_AT", point)
        .current_dir(dir)
        .output()
        .expect("flapwright runs")
}

/// Issue 35 item 9: a user's folders whose names look like Flapwright's backups (a
/// hand-made `.results.old`, a dated `.results.old-2024-01-05`, "2024" read as a dead
/// process) are never removed: only folders with a marker Flapwright can verify are.
#[test]
fn hand_made_folders_named_like_backups_are_never_removed() {
    let dir = tempfile::tempdir().unwrap();
    let scene = thesis_scene(dir.path());
    assert!(run_flapwright(dir.path(), &["design", &scene, "--out", "results"])
        .status
        .success());
    let mine = [
        ".results.old",
        ".results.old-2024-01-05",
        ".results.old-0-1",
        ".results.partial-0-2",
        ".results.partial-0",
    ];
    for name in mine {
        fs::create_dir(dir.path().join(name)).unwrap();
        fs::write(dir.path().join(name).join("backup.txt"), name).unwrap();
    }
    let output = run_flapwright(dir.path(), &["design", &scene, "--out", "results"]);
    assert!(output.status.success(), "{}", stderr(&output));
    for name in mine {
        assert_eq!(
            fs::read_to_string(dir.path().join(name).join("backup.txt")).unwrap(),
            name,
            "{name} was the user's"
        );
    }
}

/// Issue 35 item 11: a run killed between the two renames of its commit has moved the
/// earlier output aside; the next run puts it back (here the next run is killed during its
/// work, so the earlier output is what `--out` must hold), and a run that completes leaves
/// nothing hidden.
#[test]
fn a_run_killed_between_its_renames_loses_no_earlier_output() {
    let dir = tempfile::tempdir().unwrap();
    let scene = thesis_scene(dir.path());
    assert!(run_flapwright(dir.path(), &["design", &scene, "--out", "out"])
        .status
        .success());
    let earlier = fs::read_to_string(dir.path().join("out/report.json")).unwrap();
    // A different scene, so the earlier report is told from a later one.
    let text = fs::read_to_string(dir.path().join(&scene)).unwrap();
    let renamed = text.replacen("name = \"", "name = \"other-", 1);
    assert_ne!(renamed, text);
    fs::write(dir.path().join("other.toml"), renamed).unwrap();
    let killed = run_killed_at(dir.path(), "between-renames", &["design", "other.toml", "--out", "out"]);
    assert!(!killed.status.success(), "the test hook ends the run");
    assert!(!dir.path().join("out").exists(), "killed with --out moved aside");
    let killed = run_killed_at(dir.path(), "staged", &["design", "other.toml", "--out", "out"]);
    assert!(!killed.status.success(), "the test hook ends the run");
    assert_eq!(
        fs::read_to_string(dir.path().join("out/report.json")).unwrap(),
        earlier,
        "the earlier output is put back"
    );
    let output = run_flapwright(dir.path(), &["design", "other.toml", "--out", "out"]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_ne!(fs::read_to_string(dir.path().join("out/report.json")).unwrap(), earlier);
    assert_eq!(names_in(dir.path()), ["other.toml", "out", "thesis.toml"]);
}
