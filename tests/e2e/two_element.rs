//! A two-element (double-slotted) flap in 3D, `data/scenes/double-slotted-wing.toml`: the
//! aft element as a part of its own, moved by the five-bar's secondary flap in the check, the
//! STL files, the URDF and the drawings, and the second slot's gap and overlap.

use nalgebra::{Matrix3, Point3, Rotation3, Vector3};
use serde_json::Value;

use crate::repo_root;
use crate::stl_reader::read_binary_stl;

const SCENE: &str = "data/scenes/double-slotted-wing.toml";

/// The vertices of a binary STL file, in file order.
fn vertices(path: &std::path::Path) -> Vec<Point3<f64>> {
    read_binary_stl(&std::fs::read(path).unwrap())
        .iter()
        .flatten()
        .map(|v| Point3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2])))
        .collect()
}

/// The rotation of the least-squares rigid motion taking `from` to `to` (Kabsch, by SVD)
/// and its largest residual (m).
fn rigid_rotation(from: &[Point3<f64>], to: &[Point3<f64>]) -> (Rotation3<f64>, f64) {
    let centre = |points: &[Point3<f64>]| points.iter().map(|p| p.coords).sum::<Vector3<f64>>() / points.len() as f64;
    let (a, b) = (centre(from), centre(to));
    let mut covariance = Matrix3::zeros();
    for (p, q) in from.iter().zip(to) {
        covariance += (q.coords - b) * (p.coords - a).transpose();
    }
    let svd = covariance.svd(true, true);
    let (u, v_t) = (svd.u.unwrap(), svd.v_t.unwrap());
    let mut correction = Matrix3::identity();
    correction[(2, 2)] = (u * v_t).determinant().signum();
    let rotation = Rotation3::from_matrix_unchecked(u * correction * v_t);
    let residual = from
        .iter()
        .zip(to)
        .map(|(p, q)| (rotation * (p.coords - a) + b - q.coords).norm())
        .fold(0.0, f64::max);
    (rotation, residual)
}

#[test]
fn the_aft_element_is_a_part_checked_drawn_and_measured_in_its_own_slot() {
    let (dir, report) = crate::run_on_scene("design", SCENE, &[]);
    let out = dir.path().join("out");
    let part = report["parts"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["name"] == "flap-aft")
        .expect("the aft element is a part");
    assert_eq!(part["kind"], "flap-aft-element");
    assert_eq!(part["watertight"], true);
    assert!(out.join(part["stl_file"].as_str().unwrap()).is_file());

    // The check: the aft element against the wing and the main element, and every station
    // part against it, checked or certified apart; nothing left out.
    let interference = &report["interference"];
    let pairs = interference["pairs"].as_array().unwrap();
    let apart = interference["certified_apart"].as_array().unwrap();
    let has = |list: &[Value], a: &str, b: &str| {
        list.iter()
            .any(|p| (p["part_a"] == a && p["part_b"] == b) || (p["part_a"] == b && p["part_b"] == a))
    };
    for structure in ["wing", "flap"] {
        assert!(has(pairs, "flap-aft", structure), "flap-aft against {structure}");
    }
    // The secondary flap's own solids are rigid with the aft element: listed, with the
    // reason, and nothing else is left out.
    let unchecked = interference["unchecked_pairs"].as_array().unwrap();
    for solid in report["mechanism_parts"].as_array().unwrap() {
        let name = solid["name"].as_str().unwrap();
        let listed = has(pairs, name, "flap-aft") || has(apart, name, "flap-aft");
        let left_out = has(unchecked, name, "flap-aft");
        assert!(listed != left_out, "{name} against flap-aft: checked or listed, once");
        assert_eq!(left_out, solid["role"] == "aft-flap", "{name}");
    }
    for pair in unchecked {
        assert!(
            pair["reason"].as_str().unwrap().contains("rigid with it by design"),
            "{pair}"
        );
    }
    // The scene's five-bars were laid out to clear (its header says how): every pair and
    // joint passes, the slot between the elements included.
    assert_eq!(interference["passes"], true);

    // The second slot at each setting, in the main element's frame: stowed nested with a
    // slot of a few millimetres under the main element's shroud; the secondary flap turns
    // further than the main one as it deploys.
    for station in report["stations"].as_array().unwrap() {
        let slot = &station["flap_position"]["aft_slot"];
        let settings = slot["settings"].as_array().unwrap();
        let names: Vec<&str> = settings.iter().map(|s| s["setting"].as_str().unwrap()).collect();
        assert_eq!(names, ["stowed", "takeoff", "landing"]);
        let field = |k: usize, key: &str| settings[k][key].as_f64().unwrap();
        let chord = slot["flap_chord_m"].as_f64().unwrap();
        assert!(field(0, "relative_deflection_deg").abs() < 1e-9);
        assert!(field(0, "gap_m") > 0.0 && field(0, "gap_m") < 0.05 * chord, "{slot}");
        assert!(
            field(0, "overlap_m") > 0.0,
            "stowed, the shroud covers the aft nose: {slot}"
        );
        assert!(
            0.0 < field(1, "relative_deflection_deg")
                && field(1, "relative_deflection_deg") < field(2, "relative_deflection_deg"),
            "{slot}"
        );
    }

    // The five-bar's own equation of motion deploys each station.
    for station in report["stations"].as_array().unwrap() {
        assert_eq!(station["dynamics"]["model"]["type"], "kind", "{}", station["name"]);
        assert!(station["dynamics"]["deployment_time_s"].as_f64().is_some());
    }

    // Drawn at stowed, take-off and landing: both elements' outlines at each.
    let svg = std::fs::read_to_string(out.join("station-inner.svg")).unwrap();
    assert_eq!(svg.matches("class=\"flap-outline\"").count(), 6);

    // URDF: the aft element's link hangs fixed off the secondary flap's link.
    let xml = std::fs::read_to_string(out.join(report["files"]["urdf"]["file"].as_str().unwrap())).unwrap();
    let robot = urdf_rs::read_from_string(&xml).expect("urdf-rs reads the file back");
    assert!(flapwright_urdf::check_rules(&robot).is_empty());
    assert!(robot.links.iter().any(|l| l.name == "flap-aft"));
    let mount = robot
        .joints
        .iter()
        .find(|j| j.child.link == "flap-aft")
        .expect("the aft element's mount");
    assert_eq!(mount.joint_type, urdf_rs::JointType::Fixed);
    assert_eq!(mount.parent.link, "inner_secondary_flap");
    // Each element weighs what its stations' five-bars give it: 2 x 20 kg on the aft
    // element, 2 x 50 kg on the main one.
    let mass = |link: &str| robot.links.iter().find(|l| l.name == link).unwrap().inertial.mass.value;
    assert!((mass("flap-aft") - 40.0).abs() < 1e-9, "{}", mass("flap-aft"));
    assert!((mass("flap") - 100.0).abs() < 1e-9, "{}", mass("flap"));
    // The main slot's percentages are of the clean chord, to the aft element's trailing
    // edge: the wing's 4.5 m chord (the sections are streamwise, the wing straight).
    let local_chord = report["stations"][0]["flap_position"]["local_chord_m"]
        .as_f64()
        .unwrap();
    assert!((local_chord - 4.5).abs() < 1e-3, "{local_chord}");
}

/// The STL files at landing against the stowed ones: each element moved rigidly, turned
/// about the span, the main element by the landing setting and the aft element further by
/// what the report's second slot gives (an independent route: the check's 3D motion fitted
/// to the stations against the planar poses the gap and overlap stage measures).
#[test]
fn at_landing_the_aft_element_turns_by_the_second_slots_relative_deflection() {
    let (stowed_dir, report) = crate::run_on_scene("design", SCENE, &[]);
    let (landing_dir, _) = crate::run_on_scene("export", SCENE, &["--stl", "--at", "landing"]);
    let turn = |part: &str| {
        let file = format!("out/{part}.stl");
        let (rotation, residual) = rigid_rotation(
            &vertices(&stowed_dir.path().join(&file)),
            &vertices(&landing_dir.path().join(&file)),
        );
        assert!(
            residual < 1e-5,
            "{part} moves rigidly (residual {residual} m, f32 files)"
        );
        let axis = rotation.axis().expect("a turn");
        // Trailing edge down on the right wing: a turn about +y (x aft, z up).
        assert!(axis.y.abs() > 1.0 - 1e-6, "{part} turns about the span: {axis:?}");
        rotation.angle().to_degrees() * axis.y.signum()
    };
    let (main, aft) = (turn("flap"), turn("flap-aft"));
    let landing = &report["stations"][0]["flap_position"];
    let main_expected = landing["settings"][2]["deflection_deg"].as_f64().unwrap();
    let relative_expected = landing["aft_slot"]["settings"][2]["relative_deflection_deg"]
        .as_f64()
        .unwrap();
    assert!(
        (main - main_expected).abs() < 1e-3,
        "main {main} deg, landing {main_expected} deg"
    );
    assert!(
        (aft - main - relative_expected).abs() < 1e-3,
        "aft {aft} deg - main {main} deg against the slot's {relative_expected} deg"
    );
}

/// A spar may not take the aft element's part name.
#[test]
fn a_part_named_like_an_aft_element_is_rejected() {
    let text = std::fs::read_to_string(repo_root().join(SCENE)).unwrap();
    let clash = text.replacen("name = \"rear-spar\"", "name = \"flap-aft\"", 1);
    assert_ne!(clash, text);
    crate::bad_input::assert_rejected(&clash, &["structure.spars[0].name", "aft element"]);
}

/// An aft element needs the flap's own section and a chord share in range: input errors
/// naming the key (and its line for the range).
#[test]
fn an_aft_element_without_the_flaps_section_or_out_of_range_is_rejected() {
    let text = std::fs::read_to_string(repo_root().join(SCENE)).unwrap();
    let flap = text.find("[[flap]]").unwrap();
    let own_section = flap
        + text[flap..]
            .find("airfoil = \"n63212.dat\"\n")
            .expect("the flap's own section");
    let mut cut_out = text.clone();
    cut_out.replace_range(own_section..own_section + "airfoil = \"n63212.dat\"\n".len(), "");
    crate::bad_input::assert_rejected(&cut_out, &["flap[0].aft_element", "needs the flap's own section"]);
    let aft = text.find("[flap.aft_element]").unwrap();
    let chord = aft + text[aft..].find("chord_fraction = ").unwrap();
    let end = chord + text[chord..].find('\n').unwrap();
    let mut tiny = text.clone();
    tiny.replace_range(chord..end, "chord_fraction = 0.05");
    let line = text[..chord].matches('\n').count() + 1;
    crate::bad_input::assert_rejected(
        &tiny,
        &[
            &format!("scene.toml:{line}:"),
            "flap[0].aft_element.chord_fraction",
            "[0.1, 0.7]",
        ],
    );
}

/// A kind without an aft-flap body carries the aft element fixed to the main one: the
/// transport scene's outboard flap made two-element at one dropped-hinge station. The
/// second slot keeps its stowed shape at every setting, the flap's own fittings are swept
/// against the aft element (nothing left out), and the main slot's chord runs to the aft
/// element's trailing edge as before.
#[test]
fn without_an_aft_flap_body_the_aft_element_moves_with_the_main_one() {
    let text = std::fs::read_to_string(repo_root().join("data/scenes/transport-flap.toml")).unwrap();
    // The outboard flap only, with an aft element, and its outer station only.
    let inboard = text.find("[[flap]]\nname = \"inboard\"").unwrap();
    let outboard = text.find("[[flap]]\nname = \"outboard\"").unwrap();
    let mut scene = format!("{}{}", &text[..inboard], &text[outboard..]);
    let hinge = scene.find("[flap.hinge]").unwrap();
    scene.insert_str(
        hinge,
        "[flap.aft_element]\nairfoil = \"NACA 0009\"\nchord_fraction = 0.3\nshroud_chord_fraction = 0.04\n\n",
    );
    let stations = scene.find("[[station]]").unwrap();
    let loads = scene.find("[loads]").unwrap();
    scene.replace_range(
        stations..loads,
        "[[station]]\nname = \"ob-outer\"\nflap = \"outboard\"\naxis_offset_m = 7.0\n[station.mechanism]\nkind = \"dropped-hinge\"\nflap_mass_kg = 150.0\n\n",
    );
    // Only what the test reads (and a check that stops at its verdicts).
    let outputs = scene.find("[outputs]").unwrap();
    scene.truncate(outputs);
    scene.push_str("[outputs]\nstl = false\nurdf = false\nsvg = false\ngltf = false\nsizing = false\n");
    scene = scene.replacen("[interference]\n", "[interference]\nstop_at_verdict = true\n", 1);
    let (_dir, report) = crate::synthesised_kinds::designed(&scene);
    let station = &report["stations"][0];
    let slot = &station["flap_position"]["aft_slot"]["settings"];
    let stowed = (
        slot[0]["gap_m"].as_f64().unwrap(),
        slot[0]["overlap_m"].as_f64().unwrap(),
    );
    for setting in slot.as_array().unwrap() {
        assert!(
            setting["relative_deflection_deg"].as_f64().unwrap().abs() < 1e-9,
            "{setting}"
        );
        assert!(
            (setting["gap_m"].as_f64().unwrap() - stowed.0).abs() < 1e-9,
            "{setting}"
        );
        assert!(
            (setting["overlap_m"].as_f64().unwrap() - stowed.1).abs() < 1e-9,
            "{setting}"
        );
    }
    let interference = &report["interference"];
    assert!(interference["unchecked_pairs"].as_array().unwrap().is_empty());
    let checked = |part: &str| {
        ["pairs", "certified_apart"].iter().any(|list| {
            interference[list]
                .as_array()
                .unwrap()
                .iter()
                .any(|p| p["part_a"] == part && p["part_b"] == "outboard-aft")
        })
    };
    for solid in report["mechanism_parts"].as_array().unwrap() {
        let name = solid["name"].as_str().unwrap();
        assert!(checked(name), "{name} against the aft element");
    }
    // The clean chord runs from the wing's nose to the aft element's trailing edge (the
    // flap's): read here off the station's section cuts (station x to the nose).
    let extent = |part: &str| {
        station["plane"]["sections"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|s| s["part_name"] == part)
            .flat_map(|s| {
                s["polygons"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .flat_map(|p| p.as_array().unwrap())
            })
            .map(|point| point[0].as_f64().unwrap())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)))
    };
    let expected = extent("wing").1 - extent("outboard-aft").0;
    let chord = station["flap_position"]["local_chord_m"].as_f64().unwrap();
    assert!((chord - expected).abs() < 1e-12, "{chord} against the cuts' {expected}");
    assert!(
        extent("outboard-aft").0 < extent("outboard").0,
        "the aft element ends the flap"
    );
}
