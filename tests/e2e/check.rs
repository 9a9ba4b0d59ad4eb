//! `flapwright check`: exit codes 0 (clear), 1 (interference), 2 (bad input) and the JUnit
//! file CI reads.

use crate::{default_scene_text, run_flapwright};

fn check(scene: &str) -> (tempfile::TempDir, std::process::Output) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), scene).unwrap();
    let output = run_flapwright(dir.path(), &["check", "scene.toml", "--junit", "junit.xml"]);
    (dir, output)
}

#[test]
fn default_scene_passes() {
    let (dir, output) = check(&default_scene_text());
    assert_eq!(
        output.status.code(),
        Some(0),
        "stderr:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let junit = std::fs::read_to_string(dir.path().join("junit.xml")).unwrap();
    assert!(junit.contains("failures=\"0\""), "{junit}");
    assert!(junit.contains("inner.screw vs torque-tube"), "one test case per pair");
    // Every swept pair's and joint's case carries the time its sweep took (s); the pairs
    // their swept boxes certify were not swept and carry none.
    let cases: Vec<&str> = junit
        .split("<testcase ")
        .skip(1)
        .map(|c| c.split('>').next().unwrap())
        .collect();
    let timed: Vec<f64> = cases
        .iter()
        .filter_map(|c| c.split("time=\"").nth(1))
        .map(|t| t.split('"').next().unwrap().parse::<f64>().expect("a time in seconds"))
        .collect();
    assert!(timed.iter().all(|t| t.is_finite() && *t >= 0.0), "{timed:?}");
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("flapwright-check/report.json")).unwrap())
            .unwrap();
    let interference = &report["interference"];
    assert_eq!(interference["passes"], true);
    for pair in interference["pairs"].as_array().unwrap() {
        // Default tolerances: 1 mm, or 1 % of the clearance for parts far apart. A part
        // pinned to the flap moves with it, but the certificate adds both parts' speed
        // bounds (the flap's is its trailing edge's), so the 400 evaluations may run out
        // before the 1 %: then the bound is what was reached, and it must still certify.
        let clearance = pair["min_clearance_m"].as_f64().unwrap();
        let residual = pair["residual_bound_m"].as_f64().unwrap();
        let budget_spent = pair["evaluations"] == 400;
        assert!(
            residual <= f64::max(1e-3, 1e-2 * clearance) + 1e-12 || (budget_spent && clearance - residual >= 0.003),
            "refined to the tolerance: {pair}"
        );
    }
    // Pairs certified by their swept boxes are farther apart than required.
    let apart = interference["certified_apart"].as_array().unwrap();
    assert!(!apart.is_empty(), "the two stations' parts are a span apart");
    let swept =
        interference["pairs"].as_array().unwrap().len() + interference["declared_contacts"].as_array().unwrap().len();
    assert_eq!(
        timed.len(),
        swept,
        "a time on each swept case, none on the {} certified apart",
        apart.len()
    );
    assert_eq!(cases.len(), swept + apart.len());
    assert!(apart.iter().all(|p| p["lower_bound_m"].as_f64().unwrap() > 0.003));
    // Joints are checked to stay joined, per station: nut, fitting and screw at A, the
    // pins F and G in their tracks (the screw and its jack body are one rigid body).
    let joints = interference["declared_contacts"].as_array().unwrap();
    assert_eq!(joints.len(), 10, "{joints:?}");
    let play = interference["joint_play_m"].as_f64().unwrap();
    for joint in joints {
        assert_eq!(joint["passes"], true, "{joint}");
        assert!(joint["upper_bound_m"].as_f64().unwrap() <= play, "{joint}");
        let name = format!(
            "{} joined to {}",
            joint["part_a"].as_str().unwrap(),
            joint["part_b"].as_str().unwrap()
        );
        assert!(junit.contains(&name), "a test case for {name}");
    }
    // No pair is left out: the parts of one station are checked against each other, each
    // in its spanwise layer.
    let unchecked = interference["unchecked_pairs"].as_array().unwrap();
    assert!(unchecked.is_empty(), "{unchecked:?}");
    let checked_or_listed = |a: &str, b: &str| {
        let named =
            |p: &serde_json::Value| (p["part_a"] == a && p["part_b"] == b) || (p["part_a"] == b && p["part_b"] == a);
        interference["pairs"].as_array().unwrap().iter().any(named)
            || apart.iter().any(named)
            || joints.iter().any(named)
            || unchecked.iter().any(named)
    };
    assert!(junit.contains("skipped=\"0\""), "{junit}");
    for (a, b) in [
        ("inner.screw", "inner.inner-track"),
        ("inner.fitting-F", "inner.inner-track"),
        ("inner.jack-body", "inner.fitting-G"),
        ("outer.nut", "outer.outer-track"),
    ] {
        assert!(checked_or_listed(a, b), "{a} vs {b}: same-station parts are checked");
        assert!(!joints.iter().any(|j| j["part_a"] == a && j["part_b"] == b));
    }
    // The skin is checked against every part, with the station's opening cut in it.
    let swept = interference["pairs"].as_array().unwrap();
    assert!(swept
        .iter()
        .any(|p| p["part_a"] == "inner.outer-track" && p["part_b"] == "wing"));
    let openings = interference["openings"].as_array().unwrap();
    assert_eq!(openings.len(), 2);
    for opening in openings {
        assert!(opening["skin_area_m2"].as_f64().unwrap() > 0.0, "{opening}");
        assert!(opening["flap_area_m2"].as_f64().unwrap() > 0.0, "{opening}");
        assert_eq!(opening["margin_m"], 0.006, "twice the required clearance");
    }
    for station in ["inner", "outer"] {
        for part in [
            "screw",
            "jack-body",
            "nut",
            "fitting-A",
            "fitting-F",
            "fitting-G",
            "outer-track",
            "inner-track",
        ] {
            let part = format!("{station}.{part}");
            for other in ["wing", "front-spar", "rear-spar", "torque-tube"] {
                assert!(
                    checked_or_listed(&part, other),
                    "{part} vs {other} is checked or listed"
                );
            }
            // Every part of one station against every part of the other station.
            let far_station = if station == "inner" { "outer" } else { "inner" };
            for other in ["screw", "nut", "outer-track", "jack-body"] {
                let other = format!("{far_station}.{other}");
                assert!(checked_or_listed(&part, &other), "{part} vs {other} is checked");
            }
        }
    }
    // The check runs only what it needs.
    let stages = crate::stages(&report);
    assert!(
        !stages.contains(&"kinematics") && !stages.contains(&"sizing") && !stages.contains(&"stl"),
        "{stages:?}"
    );
    for station in report["stations"].as_array().unwrap() {
        let depth = station["fairing"]["depth_m"].as_f64().unwrap();
        assert!(depth > 0.0 && depth < 0.5, "fairing depth {depth} m");
    }
}

#[test]
fn torque_tube_in_the_screw_path_fails_and_junit_names_the_pair() {
    // The tube moved to 245 mm above A0 on the station y axis, where the screws swing.
    let scene = default_scene_text().replacen(
        "path_m = [[1.4017, 0.8, 0.0196], [1.2960, 3.0, 0.2594]]",
        "path_m = [[1.6627, 0.8, -0.0567], [1.4530, 3.0, 0.1258]]",
        1,
    );
    assert_ne!(scene, default_scene_text());
    let (dir, output) = check(&scene);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "stderr:\n{stderr}");
    assert!(stderr.contains("screw") && stderr.contains("torque-tube"), "{stderr}");
    let junit = std::fs::read_to_string(dir.path().join("junit.xml")).unwrap();
    let failing = junit
        .split("<testcase")
        .filter(|case| case.contains("<failure"))
        .collect::<Vec<_>>();
    assert!(
        failing.iter().any(|case| case.contains("screw vs torque-tube")),
        "a failing test case names the screw and the torque tube:\n{junit}"
    );
    assert!(failing
        .iter()
        .all(|case| case.contains("clearance") && case.contains("% of the deployment")));
    // Overlapping pairs say how deep: the screw crosses the tube (radius 20 mm, 24 facets)
    // so its surface reaches the tube's axis, about the inradius deep.
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("flapwright-check/report.json")).unwrap())
            .unwrap();
    let screw_tube = report["interference"]["pairs"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["part_a"] == "inner.screw" && p["part_b"] == "torque-tube")
        .expect("the inner screw against the tube is checked");
    assert_eq!(screw_tube["min_clearance_m"], 0.0);
    let depth = screw_tube["penetration_m"].as_f64().unwrap();
    let resolution = screw_tube["penetration_resolution_m"].as_f64().unwrap();
    assert!(resolution > 0.0 && resolution <= 1e-3, "{screw_tube}");
    assert!(depth > 0.015 && depth <= 0.020, "{screw_tube}");
    assert!(failing
        .iter()
        .any(|case| case.contains("overlap") && case.contains("deepest")));
}

#[test]
fn tracks_standing_through_the_upper_skin_fail_and_strict_fails_on_skipped_pairs() {
    // Issue 17's false pass: the check must name the tracks and the skin.
    let (dir, output) = check(&crate::tracks_through_the_upper_skin_scene());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "stderr:\n{stderr}");
    for track in [
        "inner.outer-track",
        "inner.inner-track",
        "outer.outer-track",
        "outer.inner-track",
    ] {
        assert!(
            stderr.contains(&format!("{track} and wing overlap")),
            "{track}: {stderr}"
        );
    }
    let junit = std::fs::read_to_string(dir.path().join("junit.xml")).unwrap();
    assert!(junit
        .split("<testcase")
        .any(|case| case.contains("inner.outer-track vs wing") && case.contains("<failure")));

    // --strict: the default scene leaves no pair out, so it passes.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), default_scene_text()).unwrap();
    let output = run_flapwright(dir.path(), &["check", "scene.toml", "--strict"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
}

#[test]
fn bad_input_exits_2() {
    let (_dir, output) = check(&default_scene_text().replacen("radius_m = 0.020", "radius_m = -0.020", 1));
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("structure.torque_tube.radius_m"));
}

#[test]
fn a_second_flap_is_checked_against_the_first_and_against_the_other_stations() {
    // The default wing with an outboard flap on its own station (found in review: flaps
    // were never checked against each other, and a station's waivers for its own flap
    // covered every flap).
    let text = default_scene_text();
    let spars = text.find("[[structure.spars]]").unwrap();
    let flap = "[[flap]]\nname = \"outboard-flap\"\ny_inboard_m = 3.1\ny_outboard_m = 4.6\n\
                chord_fraction_inboard = 0.27\nchord_fraction_outboard = 0.27\nside_gap_m = 0.040\n\n\
                [flap.hinge]\nchord_fraction = 0.80\ndepth_below_chord_fraction = 0.17\n\n";
    let text = format!("{}{flap}{}", &text[..spars], &text[spars..]);
    let loads = text.find("[loads]").unwrap();
    let outer = text.find("[[station]]\nname = \"outer\"").unwrap();
    let station = text[outer..loads]
        .replace("name = \"outer\"", "name = \"outboard\"")
        .replace("flap = \"flap\"", "flap = \"outboard-flap\"")
        .replace("axis_offset_m = 1.90", "axis_offset_m = 0.60");
    let scene = format!("{}{station}{}", &text[..loads], &text[loads..]);
    let (dir, output) = check(&scene);
    assert!(
        matches!(output.status.code(), Some(0 | 1)),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("flapwright-check/report.json")).unwrap())
            .unwrap();
    let interference = &report["interference"];
    let pairs: Vec<&serde_json::Value> = interference["pairs"]
        .as_array()
        .unwrap()
        .iter()
        .chain(interference["certified_apart"].as_array().unwrap())
        .collect();
    let checked = |a: &str, b: &str| pairs.iter().any(|p| p["part_a"] == a && p["part_b"] == b);
    assert!(checked("flap", "outboard-flap"), "the flaps against each other");
    for part in ["outer.fitting-F", "outer.nut", "outer.outer-track"] {
        assert!(checked(part, "outboard-flap"), "{part} against the other flap");
    }
    // Against its own flap: the fitting is the flap; the nut pinned to it and the track
    // through it are checked against the flap with its slot cut.
    assert!(!checked("outer.fitting-F", "flap"));
    assert!(checked("outer.nut", "flap") && checked("outer.outer-track", "flap"));
    assert!(checked("outboard.screw", "outboard-flap") && checked("outboard.screw", "flap"));
}

#[test]
fn clearance_relative_to_the_local_flap_chord_raises_each_stations_requirement() {
    let with_percent = |percent: f64| {
        let text = default_scene_text();
        match text.contains("[interference]") {
            true => text.replacen(
                "[interference]",
                &format!("[interference]\nrequired_clearance_percent_flap_chord = {percent}"),
                1,
            ),
            false => format!("{text}\n[interference]\nrequired_clearance_percent_flap_chord = {percent}\n"),
        }
    };
    let (dir, output) = check(&with_percent(4.0));
    assert_eq!(
        output.status.code(),
        Some(1),
        "4 % of the chord is more than the tracks keep"
    );
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("flapwright-check/report.json")).unwrap())
            .unwrap();
    let interference = &report["interference"];
    let by_station = &interference["required_clearance_by_station_m"];
    for station in report["stations"].as_array().unwrap() {
        // The fairing gives the local flap chord: depth over its share of the chord.
        let fairing = &station["fairing"];
        let chord =
            fairing["depth_m"].as_f64().unwrap() / (fairing["depth_percent_flap_chord"].as_f64().unwrap() / 100.0);
        let name = station["name"].as_str().unwrap();
        let required = by_station[name].as_f64().unwrap();
        assert!(
            (required - 0.04 * chord).abs() < 1e-9,
            "{name}: {required} m for a {chord} m chord"
        );
        for pair in interference["pairs"].as_array().unwrap() {
            if pair["station"] == name {
                assert_eq!(pair["required_clearance_m"], by_station[name]);
            }
        }
    }
    let junit = std::fs::read_to_string(dir.path().join("junit.xml")).unwrap();
    assert!(
        junit.contains("is below the required 22."),
        "the station's requirement in the message"
    );
    // A share below the global requirement changes nothing; one beyond 10 % is refused.
    let (dir, output) = check(&with_percent(0.1));
    assert_eq!(output.status.code(), Some(0));
    let report = std::fs::read_to_string(dir.path().join("flapwright-check/report.json")).unwrap();
    assert!(!report.contains("required_clearance_by_station_m"));
    let (_dir, output) = check(&with_percent(20.0));
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("interference.required_clearance_percent_flap_chord"));
}
