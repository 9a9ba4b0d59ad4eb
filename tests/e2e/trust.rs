//! Loads, checks and messages a user can trust (issue 35): the reproducers of the
//! defects an independent recomputation found, each kept as a test.

use serde_json::Value;

use crate::repo_root;
use crate::synthesised_kinds::{design, designed};

fn transport() -> String {
    std::fs::read_to_string(repo_root().join("data/scenes/transport-flap.toml")).unwrap()
}

/// Writes `scene` (the transport scene's airfoils beside it) and runs `args` on it.
fn run_on(scene: &str, args: &[&str]) -> (tempfile::TempDir, std::process::Output) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), scene).unwrap();
    let mut all = vec![args[0], "scene.toml"];
    all.extend(&args[1..]);
    let output = crate::run_flapwright(dir.path(), &all);
    (dir, output)
}

fn station<'a>(report: &'a Value, name: &str) -> &'a Value {
    report["stations"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["name"] == name)
        .unwrap_or_else(|| panic!("station {name}"))
}

fn point(value: &Value) -> [f64; 2] {
    [value[0].as_f64().unwrap(), value[1].as_f64().unwrap()]
}

/// Item 2: two stations 1 mm apart on one flap are refused at validation, the message
/// naming both (the rigid overhang rule gave them +-39,775 m² of a 13.4 m² flap).
#[test]
fn stations_closer_than_the_stated_spacing_are_refused_naming_both() {
    let scene = transport().replacen("axis_offset_m = 5.0", "axis_offset_m = 1.201", 1);
    let (_dir, output) = run_on(&scene, &["check"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("scene.toml:131:"), "{stderr}");
    assert!(stderr.contains("station[1].axis_offset_m"), "{stderr}");
    assert!(
        stderr.contains("\"ib-outer\"") && stderr.contains("\"ib-inner\""),
        "{stderr}"
    );
}

/// Item 2: the shares follow the lever rule `docs/scene.md` states: on the shipped inboard
/// flap each station's share is what the tributary rule gives from the flap's planform,
/// and the shares add up to the flap's area.
#[test]
fn flap_area_shares_are_bounded_and_add_up() {
    let (_dir, report) = designed(&transport());
    for (flap, stations) in [
        ("inboard", ["ib-inner", "ib-outer"]),
        ("outboard", ["ob-inner", "ob-outer"]),
    ] {
        let shares: Vec<f64> = stations
            .iter()
            .map(|s| {
                station(&report, s)["mechanism"]["flap_load_share"]["flap_area_share_m2"]
                    .as_f64()
                    .unwrap()
            })
            .collect();
        let total: f64 = shares.iter().sum();
        for share in &shares {
            assert!(*share > 0.1 * total && *share < 0.9 * total, "{flap}: {shares:?}");
        }
        assert!(total > 5.0 && total < 30.0, "{flap}: {total} m²");
    }
}

/// Item 3: a given `actuator_attachment_fraction` is the attachment used (the search put
/// it at 0.8 of the arm at ob-inner, where 0.5 was given in the docs' default).
#[test]
fn a_given_actuator_attachment_fraction_is_honoured() {
    let scene = transport().replacen(
        "kind = \"dropped-hinge\"\nflap_mass_kg = 150.0   # ASSUMPTION: half of a 300 kg outboard flap",
        "kind = \"dropped-hinge\"\nflap_mass_kg = 150.0\nactuator_attachment_fraction = 0.5",
        1,
    );
    assert_ne!(scene, transport());
    let (dir, output) = design(&scene);
    let text = std::fs::read_to_string(dir.path().join("out/report.json"))
        .unwrap_or_else(|_| panic!("{}", String::from_utf8_lossy(&output.stderr)));
    let report: Value = serde_json::from_str(&text).unwrap();
    let details = &station(&report, "ob-inner")["mechanism"]["details"];
    let forward = point(&details["flap_attachments_m"][0]);
    let hinge = point(&details["synthesis"]["hinge_m"]);
    let attachment = point(&details["synthesis"]["actuator_attachment_m"]);
    let fraction = (attachment[1] - forward[1]) / (hinge[1] - forward[1]);
    let along_x = (attachment[0] - forward[0]) / (hinge[0] - forward[0]);
    assert!(
        (fraction - 0.5).abs() < 1e-9 && (along_x - 0.5).abs() < 1e-9,
        "{fraction}, {along_x}"
    );
}

/// Item 8: the hooked-track's wing-fixed jack body is checked against the whole flap, not
/// its slot (the slot is cut only for the solids joined to the flap; it used to pass with
/// the jack body inside the flap at landing, reported 5.8 mm clear). Its search now keeps
/// the jack body, the rail, the screw and the struts clear of the moving flap, so the
/// pair is swept, not left out, and passes with the required clearance.
#[test]
fn a_fixed_part_is_checked_against_the_whole_flap() {
    let scene = transport().replace("kind = \"dropped-hinge\"", "kind = \"hooked-track\"");
    let (dir, output) = run_on(&scene, &["check", "--out", "out"]);
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    assert_eq!(output.status.code(), Some(0), "{text}");
    let report: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("out/report.json")).unwrap()).unwrap();
    let interference = &report["interference"];
    let of = |list: &str, name: &str| {
        interference[list]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["part_a"] == name && p["part_b"] == "outboard")
            .cloned()
    };
    let required = interference["required_clearance_m"].as_f64().unwrap();
    for station in ["ob-inner", "ob-outer"] {
        for part in ["jack-body", "rail", "screw", "strut-rail", "strut-hook"] {
            let name = format!("{station}.{part}");
            // Swept, or certified apart by the broad phase's swept boxes.
            match (of("pairs", &name), of("certified_apart", &name)) {
                (Some(pair), _) => {
                    assert_eq!(pair["passes"], true, "{pair}");
                    assert!(pair["min_clearance_m"].as_f64().unwrap() >= required, "{pair}");
                }
                (None, Some(apart)) => assert!(apart["lower_bound_m"].as_f64().unwrap() >= required, "{apart}"),
                (None, None) => panic!("{name} is not checked against the whole flap"),
            }
        }
    }
}

/// Item 7: a sealed take-off slot's gap miss is measured against the sealed gap, not the
/// 0 % target.
#[test]
fn a_sealed_slot_misses_against_its_sealed_gap() {
    let (_dir, report) = designed(&transport());
    let settings = station(&report, "ib-inner")["flap_position"]["settings"]
        .as_array()
        .unwrap();
    let takeoff = settings.iter().find(|s| s["setting"] == "takeoff").unwrap();
    let sealed = takeoff["sealed_gap_m"].as_f64().expect("the take-off slot is sealed");
    let chord = station(&report, "ib-inner")["flap_position"]["local_chord_m"]
        .as_f64()
        .unwrap();
    let gap = takeoff["gap_percent_chord"].as_f64().unwrap();
    let miss = takeoff["gap_miss_percent_chord"].as_f64().unwrap();
    assert!((miss - (gap - 100.0 * sealed / chord)).abs() < 1e-12, "{takeoff}");
    assert!(miss.abs() < 0.01, "a four-bar meets its sealed take-off gap: {takeoff}");
}

/// Item 5: one mass per member: a sized member's part carries its sized mass in the report's
/// parts, the URDF and the glTF's node extras; unsized parts are marked `drawn`; the
/// totals say what they cover.
#[test]
fn sized_members_carry_their_sized_mass_in_every_output() {
    let scene = transport().replace("[outputs]\n", "[outputs]\nurdf = true\n");
    let (dir, report) = designed(&scene);
    let rods = report["sizing"]["rods"].as_array().unwrap();
    let parts = report["mechanism_parts"].as_array().unwrap();
    assert!(!rods.is_empty());
    for rod in rods {
        let name = format!("{}.{}", rod["station"].as_str().unwrap(), rod["name"].as_str().unwrap());
        let part = parts
            .iter()
            .find(|p| p["name"] == name.as_str())
            .unwrap_or_else(|| panic!("{name}"));
        assert_eq!(part["mass_basis"], "sized", "{part}");
        let (sized, drawn) = (rod["mass_kg"].as_f64().unwrap(), part["mass_kg"].as_f64().unwrap());
        assert!((sized - drawn).abs() <= 1e-9 * sized, "{name}: {sized} against {drawn}");
    }
    assert!(
        parts.iter().any(|p| p["mass_basis"] == "drawn"),
        "fittings are not sized"
    );
    assert!(report["sizing"]["totals"]["mass_covers"].is_string());
    // The URDF's links weigh what their parts weigh.
    let urdf = report["files"]["urdf"]["file"].as_str().unwrap();
    let robot = urdf_rs::read_file(dir.path().join("out").join(urdf)).unwrap();
    for station in ["ib-inner", "ob-outer"] {
        for link in robot
            .links
            .iter()
            .filter(|l| l.name.starts_with(&format!("{station}_")))
        {
            let body = &link.name[station.len() + 1..];
            if body == "flap" {
                continue;
            }
            let expected: f64 = parts
                .iter()
                .filter(|p| p["station"] == station && p["body"] == body)
                .map(|p| p["mass_kg"].as_f64().unwrap())
                .sum();
            if expected > 0.0 {
                let mass = link.inertial.mass.value;
                assert!(
                    (mass - expected).abs() <= 1e-6 * expected,
                    "{}: {mass} against {expected}",
                    link.name
                );
            }
        }
    }
}

/// Item 6: the five-bar's secondary flap: each sample gives its deflection (absolute and
/// relative to the main flap) and, on a wing, the second slot's gap and overlap; at the
/// stroke's end of `001_...`'s flap the secondary flap stands 60 deg down (read off the
/// drawing before), and the second slot at the stowed sample equals the setting's.
#[test]
fn the_five_bars_aft_element_is_reported_at_every_sample() {
    let (_dir, report) = crate::run_on_scene("design", "data/scenes/double-slotted-flap.toml", &[]);
    let samples = report["stations"][0]["mechanism"]["load_cases"][0]["samples"]
        .as_array()
        .unwrap();
    let mut previous = -1.0;
    for sample in samples {
        let aft = &sample["aft_element"];
        let (main, total, relative) = (
            sample["deflection_deg"].as_f64().unwrap(),
            aft["deflection_deg"].as_f64().unwrap(),
            aft["relative_deflection_deg"].as_f64().unwrap(),
        );
        assert!((total - main - relative).abs() < 1e-9, "{sample}");
        assert!(
            relative > previous,
            "the secondary flap turns on: {relative} after {previous}"
        );
        previous = relative;
    }
    let last = samples.last().unwrap()["aft_element"]["deflection_deg"]
        .as_f64()
        .unwrap();
    assert!((last - 60.0).abs() < 1.0, "{last}");
    let (_dir, report) = crate::run_on_scene("design", "data/scenes/double-slotted-wing.toml", &[]);
    let station = &report["stations"][0];
    let samples = station["mechanism"]["load_cases"][0]["samples"].as_array().unwrap();
    assert!(samples.iter().all(|s| s["aft_element"]["slot"]["gap_m"].is_f64()));
    let stowed = &station["flap_position"]["aft_slot"]["settings"][0];
    assert_eq!(stowed["setting"], "stowed");
    for key in ["gap_m", "overlap_m"] {
        let (per_sample, setting) = (
            samples[0]["aft_element"]["slot"][key].as_f64().unwrap(),
            stowed[key].as_f64().unwrap(),
        );
        assert!(
            (per_sample - setting).abs() < 1e-9,
            "{key}: {per_sample} against {setting}"
        );
    }
}

/// Item 15: a positive overlap target with no shroud is refused at its key, proposing a
/// shroud (the mechanism drove the flap 97 mm into the wing).
#[test]
fn a_positive_overlap_without_a_shroud_is_refused_proposing_one() {
    let scene = transport().replace("shroud_chord_fraction = 0.06\n", "");
    let (_dir, output) = run_on(&scene, &["check"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("scene.toml:73:"), "{stderr}");
    assert!(stderr.contains("flap[0].settings.takeoff_overlap_percent"), "{stderr}");
    assert!(stderr.contains("flap[0].shroud_chord_fraction = 0.06"), "{stderr}");
}

/// Item 15: on a swept wing the default side gap lets the flaps' sides pass into the wing
/// as they deploy; the failing check names `side_gap_m` and a value for each flap. The
/// value is a lower bound (the depth at the first penetrating sample, and a wider gap moves
/// the flap's share of the load and with it the mechanisms), so a user may need a second
/// hint: following them, the check passes within three rounds, each hint larger than the
/// gap it replaces.
#[test]
fn a_side_gap_too_small_for_the_flaps_spanwise_motion_names_the_gap_that_clears() {
    let mut scene = transport().replace("side_gap_m = 0.40\n", "");
    let mut gaps: [Option<f64>; 2] = [None, None];
    for round in 0..3 {
        let (_dir, output) = run_on(&scene, &["check"]);
        let stderr = String::from_utf8_lossy(&output.stderr);
        if output.status.code() == Some(0) {
            assert!(round > 0, "the default side gap cannot clear: {stderr}");
            return;
        }
        assert_eq!(output.status.code(), Some(1), "{stderr}");
        let mut hinted = false;
        for (f, name) in ["inboard", "outboard"].iter().enumerate() {
            let key = format!("flap[{f}].side_gap_m = ");
            let Some(at) = stderr.find(&key) else {
                assert!(round > 0, "{key}: {stderr}");
                continue;
            };
            let value: f64 = stderr[at + key.len()..]
                .split_whitespace()
                .next()
                .unwrap()
                .parse()
                .unwrap();
            assert!(gaps[f].is_none_or(|gap| value > gap), "{key}{value} after {gaps:?}");
            scene = match gaps[f] {
                Some(gap) => scene.replacen(&format!("side_gap_m = {gap}\n"), &format!("side_gap_m = {value}\n"), 1),
                None => scene.replacen(
                    &format!("name = \"{name}\"\n"),
                    &format!("name = \"{name}\"\nside_gap_m = {value}\n"),
                    1,
                ),
            };
            gaps[f] = Some(value);
            hinted = true;
        }
        assert!(hinted, "a failing check without a side-gap hint: {stderr}");
    }
    panic!("three rounds of side-gap hints did not clear: {gaps:?}");
}

/// A command that needs a wing, on a 2D scene, is bad input located like every scene
/// problem (`file:line:col: wing`), found by the key fuzzer.
#[test]
fn a_2d_scene_refused_by_check_and_the_viewer_exports_is_located() {
    let dir = tempfile::tempdir().unwrap();
    let scene = repo_root().join("data/scenes/double-slotted-flap.toml");
    let scene = scene.to_str().unwrap();
    for args in [vec!["check", scene], vec!["export", scene, "--urdf"]] {
        let output = crate::run_flapwright(dir.path(), &args);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.contains("double-slotted-flap.toml:1:1: wing"),
            "{args:?}: {stderr}"
        );
    }
}
