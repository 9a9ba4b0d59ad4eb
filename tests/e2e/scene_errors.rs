//! The "validation gaps" of issue 13: every problem a scene file can hold is reported at
//! once, as `file:line:col: key ...`, with exit 2, before any stage runs; values that once
//! panicked, hung or ran out of memory deep inside a stage are refused by their key.

use crate::bad_input::{assert_rejected, default_with};
use crate::default_scene_text;

#[test]
fn a_wrong_type_inside_a_mechanism_names_the_key_and_its_place() {
    let scene = default_with("flap_mass_kg = 12.0", "flap_mass_kg = \"heavy\"");
    assert_rejected(
        &scene,
        &["scene.toml:101:1: station[0].mechanism.flap_mass_kg: invalid type: string \"heavy\", expected a number"],
    );
}

#[test]
fn every_missing_key_is_reported_in_one_run() {
    let scene = default_with("screw_lead_m = 0.008", "")
        .replacen("base_angle_deg = 65.0", "", 2)
        .replacen("y_m = 5.5", "", 1);
    assert_rejected(
        &scene,
        &[
            "4 problem(s)",
            "wing.sections[1].y_m: missing",
            "station[0].mechanism.screw_lead_m: missing",
            "station[0].mechanism.base_angle_deg: missing",
            "station[1].mechanism.base_angle_deg: missing",
        ],
    );
}

#[test]
fn an_unknown_mechanism_kind_is_named_with_the_kinds_there_are() {
    assert_rejected(
        &default_with("kind = \"circular-arc-track\"", "kind = \"four-bar-linkage\""),
        &["scene.toml:90:1: station[0].mechanism.kind = \"four-bar-linkage\": unknown mechanism kind; one of circular-arc-track"],
    );
}

#[test]
fn extra_array_elements_are_refused() {
    assert_rejected(
        &default_with(
            "root_leading_edge_m = [0.0, 0.6, 0.0]",
            "root_leading_edge_m = [0, 0.6, 0, 123, \"x\"]",
        ),
        &["scene.toml:21:1: wing.root_leading_edge_m: invalid length 5"],
    );
    assert_rejected(
        &default_with(
            "flap_centre_of_mass_m = [-0.030, 0.340]",
            "flap_centre_of_mass_m = [-0.030, 0.340, 1.0]",
        ),
        &["station[0].mechanism.flap_centre_of_mass_m: invalid length 3"],
    );
}

#[test]
fn extreme_material_and_drive_values_are_refused_by_key() {
    for value in ["1e-300", "1e308"] {
        let scene = format!(
            "{}\n[sizing]\nscrew_material = \"odd\"\ngearbox_efficiency = {value}\n\n[[materials]]\nname = \"odd\"\n\
             density_kg_m3 = {value}\nallowable_tensile_pa = {value}\nallowable_shear_pa = {value}\nyoungs_modulus_pa = {value}\n",
            default_scene_text()
        );
        assert_rejected(
            &scene,
            &[
                "5 problem(s)",
                "sizing.gearbox_efficiency",
                "materials[0].density_kg_m3",
                "materials[0].allowable_tensile_pa",
                "materials[0].allowable_shear_pa",
                "materials[0].youngs_modulus_pa",
            ],
        );
    }
}

#[test]
fn a_flap_without_stations_is_an_input_error() {
    let text = default_scene_text();
    let first_station = text.find("[[station]]").expect("stations");
    let loads = text.find("[loads]").expect("loads");
    let scene = format!("{}{}", &text[..first_station], &text[loads..]);
    assert_rejected(&scene, &["flap[0]", "has no [[station]]"]);
}

#[test]
fn huge_and_tiny_lengths_are_refused_by_key() {
    for (from, to, key) in [
        ("chord_m = 2.1", "chord_m = 1e308", "wing.sections[0].chord_m"),
        ("y_m = 5.5", "y_m = 1e308", "wing.sections[1].y_m"),
        ("y_m = 5.5", "y_m = 1e5", "wing.sections[1].y_m"),
        ("y_m = 5.5", "y_m = 9223372036854775807", "wing.sections[1].y_m"),
        ("radius_m = 0.020", "radius_m = 1e308", "structure.torque_tube.radius_m"),
        (
            "thickness_m = 0.006",
            "thickness_m = 1e-300",
            "structure.spars[0].thickness_m",
        ),
    ] {
        assert_rejected(&default_with(from, to), &[key]);
    }
}

#[test]
fn work_beyond_the_budget_is_refused_naming_the_knobs() {
    let with = |table: &str| format!("{}\n{table}\n", default_scene_text());
    assert_rejected(
        &with("[resolution]\nfairing_samples = 10001\nfairing_points_per_capsule = 1000"),
        &[
            "resolution.fairing_samples",
            "over the budget",
            "fairing_points_per_capsule",
        ],
    );
    assert_rejected(
        &with("[interference]\ninitial_samples = 10000\nmax_evaluations = 100000"),
        &["interference.max_evaluations", "over the budget"],
    );
    assert_rejected(
        &with("[resolution]\nairfoil_points_per_side = 2000\ndeployment_samples = 100000"),
        &["resolution.deployment_samples", "over the budget"],
    );
    // Out of range outright (the old limits let these through).
    assert_rejected(
        &with("[resolution]\ndeployment_samples = 1000000"),
        &["resolution.deployment_samples = 1000000: must be in [2, 100000]"],
    );
}

#[test]
fn many_stations_are_refused_by_the_budget() {
    let text = default_scene_text();
    let start = text.find("[[station]]\nname = \"outer\"").expect("outer station");
    let end = text.find("[loads]").expect("loads");
    let outer = &text[start..end];
    let mut scene = text[..end].to_string();
    // Stations 0.112 m apart, a little more than the least spacing (5 % of the flap's
    // 2.2 m span), between the shipped two and up to twice the span along the axis.
    for i in 0..28 {
        let offset = if i < 22 {
            2.02 + 0.112 * f64::from(i)
        } else {
            0.35 + 0.112 * f64::from(i - 21)
        };
        scene.push_str(
            &outer
                .replace("name = \"outer\"", &format!("name = \"extra-{i}\""))
                .replace("axis_offset_m = 1.90", &format!("axis_offset_m = {offset:.3}")),
        );
    }
    scene.push_str(&text[end..]);
    // Counting only the pairs of stations near each other (issue 35 item 19), 30 stations
    // fit at the default evaluations; at the largest allowed they do not.
    scene.push_str("\n[interference]\nmax_evaluations = 100000\n");
    assert_rejected(
        &scene,
        &["interference.max_evaluations", "30 stations", "use fewer stations"],
    );
}

#[test]
fn a_huge_scene_file_is_refused_before_parsing() {
    let mut scene = default_scene_text();
    let case = "\n[[loads.cases]]\nname = \"c\"\nmoment_nm = 1.0\n";
    while scene.len() <= 1 << 20 {
        scene.push_str(case);
    }
    assert_rejected(&scene, &["scene.toml", "at most 1048576 bytes"]);
}

/// The hang and memory reproducers of issue 13, with their exact values.
#[test]
fn the_hang_reproducers_are_refused_by_key() {
    let with = |table: &str| format!("{}\n{table}\n", default_scene_text());
    for (scene, key) in [
        (
            with("[resolution]\nfairing_samples = 100000\nfairing_points_per_capsule = 10000"),
            "resolution.fairing_samples = 100000: must be in [2, 10001]",
        ),
        (
            with("[interference]\ninitial_samples = 100000\nmax_evaluations = 10000000"),
            "interference.initial_samples = 100000: must be in [2, 10000]",
        ),
        (
            with("[resolution]\nairfoil_points_per_side = 2000\ndeployment_samples = 1000000"),
            "resolution.deployment_samples = 1000000",
        ),
        (
            default_with("y_m = 5.5", "y_m = 1e6"),
            "wing.sections[1].y_m = 1e6: must be in [-100, 100]",
        ),
        (
            default_with("radius_m = 0.020", "radius_m = 1e308"),
            "structure.torque_tube.radius_m = 1e308: must be in",
        ),
    ] {
        assert_rejected(&scene, &[key]);
    }
}

/// Issue 35 item 19: a scene holding only a name designed nothing and exited 0.
#[test]
fn a_scene_with_only_a_name_is_refused_saying_what_it_lacks() {
    assert_rejected("name = \"x\"\n", &["[[station]]", "[wing]", "nothing to design"]);
}

/// Issue 35 item 19: `transport-flap` with 32 stations (16 dropped hinges a flap, 0.33 m
/// and 0.53 m apart along the hinge axes) was refused at its own `max_evaluations = 1200`,
/// the estimate counting every cross-station pair (29,816). Counting the stations near each
/// other, it passes the budget and `check` gives its verdict (the neighbours at 0.33 m do
/// interfere: exit 1), the broad phase certifying most pairs.
#[test]
fn a_whole_transport_wing_of_32_stations_is_checked() {
    let text = std::fs::read_to_string(crate::repo_root().join("data/scenes/transport-flap.toml")).unwrap();
    let start = text.find("[[station]]").unwrap();
    let end = text.find("[loads]").unwrap();
    let mut scene = text[..start].to_string();
    for (flap, mass, first, last) in [("inboard", 180.0, 0.6, 5.6), ("outboard", 150.0, 0.6, 8.6)] {
        for i in 0..16 {
            let offset = first + (last - first) * f64::from(i) / 15.0;
            scene.push_str(&format!(
                "[[station]]\nname = \"{flap}-{i}\"\nflap = \"{flap}\"\naxis_offset_m = {offset:.3}\n\
                 [station.mechanism]\nkind = \"dropped-hinge\"\nflap_mass_kg = {mass}\n\n"
            ));
        }
    }
    scene.push_str(&text[end..]);
    // At the evaluation cap the test was written at (the shipped scene's is larger for its
    // four-bars' rockers, which these dropped hinges do not have).
    let scene = scene.replace("max_evaluations = 2400", "max_evaluations = 1200");
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), scene).unwrap();
    let output = crate::run_flapwright(dir.path(), &["check", "scene.toml", "--out", "out", "--quiet"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        matches!(output.status.code(), Some(0 | 1)),
        "a verdict, not bad input:\n{stderr}"
    );
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("out/report.json")).unwrap()).unwrap();
    let interference = &report["interference"];
    let swept = interference["pairs"].as_array().unwrap().len();
    let apart = interference["certified_apart"].as_array().unwrap().len();
    assert!(
        swept > 0 && apart > 10 * swept,
        "{swept} swept, {apart} certified apart"
    );
    assert_eq!(report["stations"].as_array().unwrap().len(), 32);
}

/// A shroud over a flap cut out of the wing section once failed in the meshing stage
/// ("wing skin: polygon of 131 points cannot be triangulated", exit 1): the flap fills the
/// section to the upper skin, so no shroud clears it. Now refused at the shroud's key.
#[test]
fn a_shroud_over_a_flap_without_its_own_section_is_refused_at_its_key() {
    let template = flapwright::scene::template("dropped-hinge").expect("the template");
    let scene = template.replacen(
        "airfoil = \"NACA 2412\"                   # the flap's own section",
        "#",
        1,
    );
    assert_ne!(scene, template);
    assert_rejected(
        &scene,
        &["flap[0].shroud_chord_fraction = 0.05: a shroud needs the flap's own section nested in the cove"],
    );
}
