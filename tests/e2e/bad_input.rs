//! Malformed scenes: each gives exit code 2 and a message naming the field; none panics
//! and none leaves an output folder behind.

use crate::{default_scene_text, run_flapwright};

/// Replaces exactly the first occurrence of `from` (which must exist) in the default scene.
pub(crate) fn default_with(from: &str, to: &str) -> String {
    let text = default_scene_text();
    assert!(text.contains(from), "default scene has `{from}`");
    text.replacen(from, to, 1)
}

/// The default scene with the first `from` in the outer station's block replaced.
fn outer_station_with(from: &str, to: &str) -> String {
    let text = default_scene_text();
    let outer = text.find("name = \"outer\"").expect("outer station");
    let (head, tail) = text.split_at(outer);
    assert!(tail.contains(from), "outer station has `{from}`");
    format!("{head}{}", tail.replacen(from, to, 1))
}

pub(crate) fn assert_rejected(scene: &str, expected_in_message: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), scene).unwrap();
    let output = run_flapwright(dir.path(), &["design", "scene.toml", "--out", "out"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(
        output.status.code(),
        Some(2),
        "exit code 2 for bad input; stderr:\n{stderr}"
    );
    assert!(!stderr.contains("panicked"), "no panic:\n{stderr}");
    for expected in expected_in_message {
        assert!(stderr.contains(expected), "message names `{expected}`:\n{stderr}");
    }
    assert!(!dir.path().join("out").exists(), "no output folder for a failed run");
    let leftovers: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(leftovers.len(), 1, "only the scene file remains: {leftovers:?}");
}

#[test]
fn negative_chord() {
    assert_rejected(
        &default_with("chord_m = 2.1", "chord_m = -1.0"),
        &["wing.sections[0].chord_m", "must be in [0.005, 50]"],
    );
}

#[test]
fn zero_span() {
    assert_rejected(
        &default_with("y_m = 5.5", "y_m = 0.6"),
        &["zero span", "wing.sections[1].y_m"],
    );
}

#[test]
fn sections_out_of_spanwise_order() {
    assert_rejected(
        &default_with("y_m = 5.5", "y_m = 0.3"),
        &["wing.sections[1].y_m", "increasing spanwise order"],
    );
}

#[test]
fn unknown_airfoil_file() {
    assert_rejected(
        &default_with("airfoil = \"n63215.dat\"", "airfoil = \"no-such-file.dat\""),
        &["wing.sections[0].airfoil", "no-such-file.dat", "not found"],
    );
}

#[test]
fn unknown_airfoil_name() {
    assert_rejected(
        &default_with("airfoil = \"n63215.dat\"", "airfoil = \"NACA 99\""),
        &["wing.sections[0].airfoil", "NACA"],
    );
}

#[test]
fn flap_outside_the_wing() {
    assert_rejected(
        &default_with("y_outboard_m = 3.0", "y_outboard_m = 7.0"),
        &["flap[0].y_outboard_m", "[0.6, 5.5]"],
    );
}

#[test]
fn unknown_key() {
    assert_rejected(
        &default_with("chord_m = 2.1", "chrod_m = 2.1"),
        &[
            "scene.toml:27:1: wing.sections[0].chrod_m: unknown key",
            "scene.toml:25:1: wing.sections[0].chord_m: missing",
        ],
    );
}

#[test]
fn nan_value() {
    assert_rejected(
        &default_with("chord_m = 2.1", "chord_m = nan"),
        &["wing.sections[0].chord_m", "NaN"],
    );
}

#[test]
fn infinite_value() {
    assert_rejected(
        &default_with("sweep_deg = 3.0", "sweep_deg = inf"),
        &["wing.panels[0].sweep_deg", "inf"],
    );
}

#[test]
fn wrong_type() {
    assert_rejected(
        &default_with("chord_m = 2.1", "chord_m = \"big\""),
        &["invalid type", "chord_m"],
    );
}

#[test]
fn hinge_axis_of_zero_length() {
    assert_rejected(
        &default_with(
            "outboard_point_m = [1.4530, 3.0, -0.1200]",
            "outboard_point_m = [1.6609, 0.8, -0.3025]",
        ),
        &["flap[0].hinge", "length"],
    );
}

#[test]
fn spar_behind_the_flap_leading_edge() {
    assert_rejected(
        &default_with("chord_fraction = 0.64", "chord_fraction = 0.85"),
        &["structure.spars[1].chord_fraction", "flap"],
    );
}

#[test]
fn station_on_a_missing_flap() {
    assert_rejected(
        &default_with("flap = \"flap\"", "flap = \"aileron\""),
        &["station[0].flap", "aileron"],
    );
}

#[test]
fn inner_slot_not_smaller_than_outer() {
    assert_rejected(
        &default_with("inner_slot_radius_m = 0.300", "inner_slot_radius_m = 0.400"),
        &["station[0].mechanism.inner_slot_radius_m", "outer_slot_radius_m"],
    );
}

#[test]
fn toml_syntax_error() {
    assert_rejected(
        &default_with("[wing]", "[wing"),
        &["scene.toml:20:6: TOML syntax: unclosed table"],
    );
}

#[test]
fn several_problems_reported_at_once() {
    let scene = default_with("chord_m = 2.1", "chord_m = -1.0").replacen("sweep_deg = 3.0", "sweep_deg = 95.0", 1);
    assert_rejected(
        &scene,
        &["2 problem(s)", "wing.sections[0].chord_m", "wing.panels[0].sweep_deg"],
    );
}

#[test]
fn missing_scene_file() {
    let dir = tempfile::tempdir().unwrap();
    let output = run_flapwright(dir.path(), &["design", "absent.toml"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("absent.toml"));
}

#[test]
fn gearbox_efficiency_above_one() {
    let scene = format!("{}\n[sizing]\ngearbox_efficiency = 1.2\n", default_scene_text());
    assert_rejected(&scene, &["sizing.gearbox_efficiency", "[0.05, 1]"]);
}

#[test]
fn custom_material_with_zero_allowable_stress_and_negative_density() {
    let scene = format!(
        "{}\n[sizing]\nscrew_material = \"brittle\"\n\n[[materials]]\nname = \"brittle\"\ndensity_kg_m3 = -10.0\nallowable_tensile_pa = 0.0\nallowable_shear_pa = 1e8\nyoungs_modulus_pa = 7e10\n",
        default_scene_text()
    );
    assert_rejected(
        &scene,
        &[
            "materials[0].density_kg_m3",
            "materials[0].allowable_tensile_pa",
            "must be in [10, 25000]",
        ],
    );
}

#[test]
fn unknown_material() {
    let scene = format!(
        "{}\n[sizing]\ntorque_tube_material = \"unobtainium\"\n",
        default_scene_text()
    );
    assert_rejected(&scene, &["sizing.torque_tube_material", "unobtainium", "steel-4340"]);
}

#[test]
fn mechanism_that_cannot_be_synthesised() {
    // a1 = 0.1 m <= a2 cos(beta3 / 2): the collinearity rule of thesis step 8 has no solution.
    assert_rejected(
        &default_with("base_distance_m = 0.275", "base_distance_m = 0.100"),
        &[
            "station[0].mechanism",
            "no screw line through B0",
            "base distance 100.000 mm",
        ],
    );
}

#[test]
fn negative_joint_play() {
    let scene = format!("{}\n[interference]\njoint_play_m = -0.001\n", default_scene_text());
    assert_rejected(&scene, &["interference.joint_play_m", "[0, 0.1]"]);
}

#[test]
fn fairing_resolution_below_two() {
    let scene = format!(
        "{}\n[resolution]\nfairing_samples = 1\nfairing_points_per_capsule = 0\n",
        default_scene_text()
    );
    assert_rejected(
        &scene,
        &["resolution.fairing_samples", "resolution.fairing_points_per_capsule"],
    );
}

#[test]
fn stations_of_one_flap_with_different_rotation_ranges() {
    // The flap is rigid: the outer station cannot stop at 25 deg while the inner turns
    // the flap to 35 deg (its pins would leave their tracks).
    let scene = outer_station_with("rotation_range_deg = 35.0", "rotation_range_deg = 25.0");
    assert_rejected(
        &scene,
        &[
            "station[1].mechanism.rotation_range_deg",
            "station[0].mechanism.rotation_range_deg = 35",
        ],
    );
}

#[test]
fn landing_setting_beyond_the_mechanism_range() {
    assert_rejected(
        &default_with("landing_deg = 35.0", "landing_deg = 40.0"),
        &["flap[0].settings.landing_deg = 40", "rotation_range_deg = 35"],
    );
}

#[test]
fn nut_starting_on_the_screw_pivot() {
    // a1 = a2: the collinearity rule puts the stowed nut on B0 (s34,i = 0; the issue's
    // reproducer ran with a Jacobian condition number of 4e15).
    assert_rejected(
        &default_with("base_distance_m = 0.275", "base_distance_m = 0.240"),
        &[
            "station[0].mechanism",
            "the nut starts 0.000 mm from the screw pivot B0",
            "base_distance_m",
        ],
    );
    // Slightly shorter: the nut would start behind the pivot.
    assert_rejected(
        &default_with("base_distance_m = 0.275", "base_distance_m = 0.231"),
        &[
            "station[0].mechanism",
            "the nut starts -41.034 mm from the screw pivot B0",
        ],
    );
}

#[test]
fn back_drivable_screw_is_a_readable_warning_and_not_self_locking() {
    let dir = tempfile::tempdir().unwrap();
    // lead 50 mm on a 16 mm mean radius: lead angle 26.4 deg above the friction angle 5.7 deg.
    // Both stations: their screws share one torque tube, so one speed.
    let scene = default_scene_text().replace("screw_lead_m = 0.008", "screw_lead_m = 0.050");
    std::fs::write(dir.path().join("scene.toml"), scene).unwrap();
    let output = crate::run_flapwright(dir.path(), &["design", "scene.toml", "--out", "out"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("out/report.json")).unwrap()).unwrap();
    let warnings = report["warnings"].to_string();
    assert!(
        warnings.contains("not self-locking: lead angle 26.44 deg"),
        "{warnings}"
    );
    assert!(!warnings.contains("ScrewNotSelfLocking"), "no debug text: {warnings}");
    assert_eq!(report["sizing"]["screw_jacks"][0]["self_locking"], false);
}

#[test]
fn station_beyond_its_flap() {
    // The hinge line is about 2.2 m long inside the flap: 2.5 m puts A0 outboard of it.
    assert_rejected(
        &default_with("axis_offset_m = 1.90", "axis_offset_m = 2.5"),
        &[
            "station[1].axis_offset_m",
            "y = 3.320 m",
            "outside flap \"flap\" (y from 0.8 to 3 m)",
        ],
    );
}

#[test]
fn hinge_line_far_ahead_of_the_flap() {
    // 35 deg of sweep with the hinge points left where they were: at the outer station the
    // hinge (and the whole mechanism) stands 1.35 m ahead of the flap.
    assert_rejected(
        &default_with("sweep_deg = 3.0", "sweep_deg = 35.0"),
        &["flap[0].hinge", "station \"outer\"", "ahead of the flap"],
    );
}

#[test]
fn torque_tube_ahead_of_the_leading_edge() {
    assert_rejected(
        &default_with(
            "path_m = [[1.4017, 0.8, 0.0196], [1.2960, 3.0, 0.2594]]",
            "path_m = [[-1.0, 0.8, 0.0196], [-1.0, 3.0, 0.2594]]",
        ),
        &["structure.torque_tube.path_m", "outside the wing and flap section"],
    );
}

#[test]
fn airfoils_that_do_not_load_are_located_input_problems() {
    // A .dat file with text where coordinates belong (exit 1 from the geometry stage before).
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("junk.dat"), "this is not an airfoil\n1 2 3\n").unwrap();
    let scene = default_with("airfoil = \"n63215.dat\"", "airfoil = \"junk.dat\"");
    std::fs::write(dir.path().join("scene.toml"), scene).unwrap();
    let output = crate::run_flapwright(dir.path(), &["design", "scene.toml", "--out", "out"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("scene.toml:29:1: wing.sections[0].airfoil = \"junk.dat\""),
        "{stderr}"
    );
    // A NACA code without thickness, for the wing and for the flap.
    assert_rejected(
        &default_with("airfoil = \"n63215.dat\"", "airfoil = \"NACA 0000\""),
        &["wing.sections[0].airfoil = \"NACA 0000\"", "not a supported"],
    );
    assert_rejected(
        &default_with("airfoil = \"n63212.dat\"", "airfoil = \"NACA 0000\""),
        &["flap[0].airfoil = \"NACA 0000\""],
    );
}

#[test]
fn mechanism_values_have_finite_ranges() {
    // Each once crashed, allocated gigabytes, printed 300-digit numbers or ran with
    // nonsense results (issue 13 audit).
    for (from, to, expected) in [
        (
            "inner_slot_radius_m = 0.300",
            "inner_slot_radius_m = 1e-300",
            "inner_slot_radius_m = 1e-300: must be in [0.001, 20]",
        ),
        (
            "inner_slot_radius_m = 0.300",
            "inner_slot_radius_m = 1e-6",
            "inner_slot_radius_m = 1e-6: must be in [0.001, 20]",
        ),
        (
            "screw_length_m = 0.250",
            "screw_length_m = 1e308",
            "screw_length_m = 1e308: must be in [0.001, 20]",
        ),
        (
            "outer_slot_radius_m = 0.350",
            "outer_slot_radius_m = 1e308",
            "outer_slot_radius_m = 1e308",
        ),
        (
            "screw_lead_m = 0.008",
            "screw_lead_m = 1e-300",
            "screw_lead_m = 1e-300: must be in [0.0001, 0.1]",
        ),
        ("screw_lead_m = 0.008", "screw_lead_m = 1e308", "screw_lead_m = 1e308"),
        (
            "flap_mass_kg = 12.0",
            "flap_mass_kg = 1e308",
            "flap_mass_kg = 1e308: must be in [0, 100000]",
        ),
        (
            "nut_speed_mps = 0.035",
            "nut_speed_mps = 1e-300",
            "nut_speed_mps = 1e-300: must be in [0.0001, 10]",
        ),
        (
            "rotation_range_deg = 35.0",
            "rotation_range_deg = 1e-300",
            "rotation_range_deg = 1e-300: must be in [1, 90]",
        ),
        (
            "nut_speed_mps = 0.035",
            "nut_speed_mps = 1e308",
            "nut_speed_mps = 1e308: must be in [0.0001, 10]",
        ),
        (
            "slot_offset_angle_deg = 20.0",
            "slot_offset_angle_deg = 0",
            "slot_offset_angle_deg = 0: the two slot pins lie on one line",
        ),
        (
            "slot_offset_angle_deg = 20.0",
            "slot_offset_angle_deg = -1e-300",
            "slot_offset_angle_deg = -1e-300: the two slot pins",
        ),
        (
            "slot_offset_angle_deg = 20.0",
            "slot_offset_angle_deg = 180",
            "slot_offset_angle_deg = 180: the two slot pins",
        ),
    ] {
        assert_rejected(&default_with(from, to), &[&format!("station[0].mechanism.{expected}")]);
    }
}

#[test]
fn screws_on_one_torque_tube_turn_at_one_speed() {
    // Halving only the outer station's lead: its screw would have to turn twice as fast
    // as the inner one on the same tube (the report gave the inner speed before).
    let scene = outer_station_with("screw_lead_m = 0.008", "screw_lead_m = 0.004");
    assert_rejected(
        &scene,
        &["station[1].mechanism: its screw turns 8.7500 rev/s at its nominal nut speed, station inner's 4.3750 rev/s"],
    );
}

#[test]
fn names_that_become_file_names_are_checked() {
    // Found by the long fuzz run: a flap named "NACA 0000" failed in the URDF stage (exit 1).
    assert_rejected(
        &default_with("name = \"flap\"", "name = \"NACA 0000\""),
        &["flap[0].name = \"NACA 0000\": names become file and URDF names"],
    );
    // A scene name is the URDF's file name: it must not reach outside the output folder.
    assert_rejected(
        &default_with("name = \"small-aircraft\"", "name = \"../escape\""),
        &["name = \"../escape\""],
    );
    // Each part's STL is named after it: a flap cannot be called "wing", nor a spar "flap".
    assert_rejected(
        &default_with("name = \"front-spar\"", "name = \"flap\""),
        &["structure.spars[0].name = \"flap\": already the name of another part"],
    );
}

#[test]
fn spar_web_outside_the_section() {
    // Found by the long fuzz run: a spar at chord fraction 1e-300 failed in the mesher.
    assert_rejected(
        &default_with("chord_fraction = 0.20", "chord_fraction = 1e-300"),
        &["structure.spars[0].chord_fraction = 1e-300: a 6.0 mm web centred there leaves the 1.200 m section"],
    );
}

#[test]
fn screws_on_one_torque_tube_turn_the_same_number_of_times() {
    // A shorter crank at the outer station gives a shorter stroke for the same lead: on one
    // torque tube the stations would not finish together (found in review: the whole-wing
    // stages pose every station at the same fraction of its stroke).
    let scene = outer_station_with("crank_length_m = 0.240", "crank_length_m = 0.230");
    assert_rejected(
        &scene,
        &["station[1].mechanism: its screw turns", "times over the deployment"],
    );
}

#[test]
fn a_flap_name_cannot_clash_with_a_stations_urdf_links() {
    // Found in review: a flap named after a station's links failed in the URDF stage.
    let scene =
        default_with("name = \"flap\"", "name = \"inner_flap\"").replace("flap = \"flap\"", "flap = \"inner_flap\"");
    assert_rejected(
        &scene,
        &["flap[0].name = \"inner_flap\": clashes with station \"inner\""],
    );
}
