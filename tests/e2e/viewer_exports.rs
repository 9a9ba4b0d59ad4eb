//! Files for viewers (issue 18): every mechanism solid in STL, URDF links with geometry,
//! mass and inertia, the animated glTF read back against the solver's key points, and an
//! `export` that runs only the stages its files need.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use nalgebra::{Isometry3, Matrix3, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};

use crate::stl_reader::{check_closed_oriented, read_binary_stl};
use crate::{repo_root, run_flapwright};

fn export(dir: &Path, args: &[&str]) -> serde_json::Value {
    let output = run_flapwright(dir, args);
    assert!(
        output.status.success(),
        "flapwright {args:?}\nstderr:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let out = args[args.iter().position(|a| *a == "--out").unwrap() + 1];
    serde_json::from_str(&std::fs::read_to_string(dir.join(out).join("report.json")).unwrap()).unwrap()
}

fn transport_scene() -> String {
    repo_root()
        .join("data/scenes/transport-flap.toml")
        .display()
        .to_string()
}

#[test]
fn export_stl_runs_no_check_and_writes_every_mechanism_solid_closed() {
    let dir = tempfile::tempdir().unwrap();
    let report = export(dir.path(), &["export", "--stl", "--out", "stl"]);
    let stages = crate::stages(&report);
    for absent in ["interference", "fairing", "gap-overlap", "kinematics", "sizing"] {
        assert!(!stages.contains(&absent), "{absent} ran: {stages:?}");
    }
    assert!(report["interference"].is_null());
    let out = dir.path().join("stl");
    let parts = report["mechanism_parts"].as_array().unwrap();
    // Every solid of both stations' circular-arc tracks.
    let names: BTreeSet<&str> = parts.iter().map(|p| p["name"].as_str().unwrap()).collect();
    for station in ["inner", "outer"] {
        for solid in [
            "screw",
            "nut",
            "jack-body",
            "inner-track",
            "outer-track",
            "fitting-A",
            "fitting-F",
            "fitting-G",
        ] {
            assert!(
                names.contains(format!("{station}.{solid}").as_str()),
                "{station}.{solid} in {names:?}"
            );
        }
    }
    for part in parts {
        let file = part["stl_file"].as_str().unwrap();
        let triangles = read_binary_stl(&std::fs::read(out.join(file)).unwrap());
        let volume = check_closed_oriented(&triangles).unwrap_or_else(|e| panic!("{file}: {e}"));
        // The mass is the solid's at the material density (the default scene's screw and
        // link materials are both steel 4340, 7850 kg/m^3); a capsule's or ball's mesh is
        // inscribed in the round solid, so its volume is within 2 % under the solid's; a
        // track's tube is its mesh (equal to the STL's 32-bit rounding).
        let density = 7850.0;
        let solid_volume = part["mass_kg"].as_f64().unwrap() / density;
        assert!(
            volume < solid_volume * (1.0 + 1e-6) && volume > 0.98 * solid_volume,
            "{file}: mesh {volume} m^3 against the solid's {solid_volume} m^3"
        );
    }
}

/// Symmetric positive definite, principal moments obeying the triangle inequality.
fn valid_inertia(i: &urdf_rs::Inertia) -> Result<(), String> {
    let tensor = Matrix3::new(i.ixx, i.ixy, i.ixz, i.ixy, i.iyy, i.iyz, i.ixz, i.iyz, i.izz);
    let mut moments: Vec<f64> = tensor.symmetric_eigenvalues().iter().copied().collect();
    moments.sort_by(f64::total_cmp);
    if moments[0] <= 0.0 {
        return Err(format!("not positive definite: {moments:?}"));
    }
    if moments[0] + moments[1] < moments[2] * (1.0 - 1e-9) {
        return Err(format!("principal moments break the triangle inequality: {moments:?}"));
    }
    Ok(())
}

#[test]
fn urdf_links_that_move_have_geometry_mass_and_inertia_on_both_scenes() {
    let dir = tempfile::tempdir().unwrap();
    let transport = transport_scene();
    for (scene, out) in [(None, "small"), (Some(transport.as_str()), "transport")] {
        let mut args = vec!["export"];
        args.extend(scene);
        args.extend(["--urdf", "--out", out]);
        let report = export(dir.path(), &args);
        let urdf = report["files"]["urdf"]["file"].as_str().unwrap();
        let xml = std::fs::read_to_string(dir.path().join(out).join(urdf)).unwrap();
        let robot = urdf_rs::read_from_string(&xml).unwrap();
        let link = |name: &str| robot.links.iter().find(|l| l.name == name).unwrap();
        let mut moving = 0;
        for joint in robot
            .joints
            .iter()
            .filter(|j| j.joint_type != urdf_rs::JointType::Fixed)
        {
            let child = link(&joint.child.link);
            assert!(!child.visual.is_empty(), "{out}: {} has no visual", child.name);
            assert_eq!(child.collision.len(), child.visual.len(), "{out}: {}", child.name);
            assert!(child.inertial.mass.value > 0.0, "{out}: {} has no mass", child.name);
            valid_inertia(&child.inertial.inertia).unwrap_or_else(|e| panic!("{out}: {}: {e}", child.name));
            for visual in &child.visual {
                let urdf_rs::Geometry::Mesh { filename, .. } = &visual.geometry else {
                    panic!("{out}: {} shows a primitive", child.name)
                };
                assert!(dir.path().join(out).join(filename).is_file(), "{filename}");
            }
            moving += 1;
        }
        assert!(moving >= 3, "{out}: {moving} movable links");
        // A station's links weigh what its solids weigh.
        let solids: f64 = report["mechanism_parts"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p["mass_kg"].as_f64().unwrap())
            .sum();
        let flap_links: Vec<&str> = report["parts"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|p| p["kind"] == "flap")
            .map(|p| p["name"].as_str().unwrap())
            .collect();
        let links: f64 = robot
            .links
            .iter()
            .filter(|l| !flap_links.contains(&l.name.as_str()))
            .map(|l| l.inertial.mass.value)
            .sum();
        assert!(
            (links - solids).abs() <= 1e-9 * solids,
            "{out}: links {links} kg, solids {solids} kg"
        );
        for flap in flap_links {
            assert!(link(flap).inertial.mass.value > 0.0, "{out}: flap {flap} has its mass");
        }
    }
}

/// One node's keyframes as stored, and its rest translation.
#[derive(Default)]
struct NodeTrack {
    rest: Vector3<f64>,
    translations: Vec<[f32; 3]>,
    rotations: Vec<[f32; 4]>,
}

impl NodeTrack {
    fn pose(&self, k: usize) -> Isometry3<f64> {
        let [x, y, z, w] = self.rotations[k].map(f64::from);
        let rotation = UnitQuaternion::from_quaternion(Quaternion::new(w, x, y, z));
        Isometry3::from_parts(
            Translation3::from(Vector3::from(self.translations[k].map(f64::from))),
            rotation,
        )
    }
}

/// Where part `name` shows the stowed point `p` at keyframe k, composed in 64 bits as a
/// reader does: its pose node's pose (rest translation = the anchor), then its own:
/// p -> pose_k (part_k (p - anchor)).
fn show(tracks: &BTreeMap<String, NodeTrack>, name: &str, k: usize, p: &Point3<f64>) -> Point3<f64> {
    let (pose, part) = (&tracks[&format!("{name}#pose")], &tracks[name]);
    pose.pose(k) * part.pose(k) * Point3::from(p.coords - pose.rest)
}

#[test]
fn gltf_has_a_node_per_part_and_keyframes_that_carry_the_solvers_key_points() {
    let dir = tempfile::tempdir().unwrap();
    let report = export(dir.path(), &["export", "--gltf", "--urdf", "--out", "viewer"]);
    let out = dir.path().join("viewer");
    let gltf_file = report["files"]["gltf"]["file"].as_str().unwrap();
    let document = gltf::Gltf::from_slice(&std::fs::read(out.join(gltf_file)).unwrap()).unwrap();
    let blob = document.blob.as_deref().unwrap();
    let nodes: BTreeSet<&str> = document.nodes().filter_map(|n| n.name()).collect();
    let parts = report["parts"].as_array().unwrap().iter();
    let solids = report["mechanism_parts"].as_array().unwrap().iter();
    for part in parts.chain(solids) {
        assert!(nodes.contains(part["name"].as_str().unwrap()), "node {}", part["name"]);
    }
    let animations: Vec<_> = document.animations().collect();
    assert_eq!(animations.len(), 1);
    let mut tracks: BTreeMap<String, NodeTrack> = BTreeMap::new();
    for channel in animations[0].channels() {
        let node = channel.target().node();
        let [x, y, z] = node.transform().decomposed().0;
        let track = tracks.entry(node.name().unwrap().to_string()).or_default();
        track.rest = Vector3::new(x as f64, y as f64, z as f64);
        match channel.reader(|_| Some(blob)).read_outputs().unwrap() {
            gltf::animation::util::ReadOutputs::Translations(values) => track.translations = values.collect(),
            gltf::animation::util::ReadOutputs::Rotations(values) => track.rotations = values.into_f32().collect(),
            _ => panic!("translation and rotation only"),
        }
    }
    // The solver's own poses: trajectory.json's key points at the same deployment samples.
    let trajectory: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("trajectory.json")).unwrap()).unwrap();
    let samples = trajectory["samples"].as_array().unwrap();
    let point =
        |v: &serde_json::Value| Point3::new(v[0].as_f64().unwrap(), v[1].as_f64().unwrap(), v[2].as_f64().unwrap());
    let mut worst = 0.0_f64;
    let mut checked = 0;
    for key in trajectory["key_points"].as_array().unwrap() {
        let name = key["name"].as_str().unwrap();
        // `<station>.<body>.<point>`: a point a moving body carries.
        let [station, body, _] = name.split('.').collect::<Vec<_>>()[..] else {
            continue;
        };
        let solid = report["mechanism_parts"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["station"] == station && p["body"] == body)
            .unwrap_or_else(|| panic!("a solid of {station}.{body}"));
        let part = solid["name"].as_str().unwrap();
        assert_eq!(tracks[part].translations.len(), samples.len());
        let stowed = point(&samples[0]["key_points_ac_m"][name]);
        for (k, sample) in samples.iter().enumerate() {
            let solver = point(&sample["key_points_ac_m"][name]);
            worst = worst.max((show(&tracks, part, k, &stowed) - solver).norm());
        }
        checked += 1;
    }
    assert!(checked >= 8, "{checked} key points");
    // Keyframes are 32-bit floats (glTF's only choice for animation outputs); a part's
    // pose node and its own node compose to the 64-bit pose.
    assert!(worst < 1e-9, "largest key point error {worst} m");
    eprintln!("glTF keyframes against the solver's key points: largest error {worst:.2e} m over {checked} points");
    let error = report["files"]["gltf"]["max_interpolation_error_m"].as_f64().unwrap();
    assert!(error > 0.0 && error < 1e-3, "interpolation error {error} m");
}

#[test]
fn the_same_scene_gives_the_same_files() {
    let dir = tempfile::tempdir().unwrap();
    for out in ["first", "second"] {
        export(dir.path(), &["export", "--gltf", "--urdf", "--stl", "--out", out]);
    }
    let files: Vec<String> = std::fs::read_dir(dir.path().join("first"))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    assert!(files.len() > 20);
    for file in files {
        let [a, b] = ["first", "second"].map(|out| std::fs::read(dir.path().join(out).join(&file)).unwrap());
        if file == "report.json" || file == flapwright_cli::output::MANIFEST {
            // Apart from the timings (and the manifest's record of the report).
            let strip = |bytes: &[u8]| {
                let mut v: serde_json::Value = serde_json::from_slice(bytes).unwrap();
                v.as_object_mut().unwrap().remove("timings");
                v.as_object_mut()
                    .unwrap()
                    .remove("files")
                    .filter(|_| file != "report.json");
                v
            };
            if file == "report.json" {
                assert_eq!(strip(&a), strip(&b), "{file}");
            }
            continue;
        }
        assert!(a == b, "{file} differs between two runs");
    }
}

#[test]
fn a_failing_pair_is_marked_on_its_station_drawing_and_the_fairing_part_drawn() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("scene.toml"),
        crate::tracks_through_the_upper_skin_scene(),
    )
    .unwrap();
    let report = export(dir.path(), &["export", "scene.toml", "--svg", "--out", "svg"]);
    let failing: Vec<&serde_json::Value> = report["interference"]["pairs"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|p| p["passes"] == false && p["station"] == "inner")
        .collect();
    assert!(!failing.is_empty());
    let svg = std::fs::read_to_string(dir.path().join("svg/station-inner.svg")).unwrap();
    assert_eq!(
        svg.matches("class=\"clash\"").count(),
        failing.len(),
        "one mark per failing pair"
    );
    for pair in failing {
        let label = format!(
            "{} / {}: overlap",
            pair["part_a"].as_str().unwrap(),
            pair["part_b"].as_str().unwrap()
        );
        assert!(svg.contains(&label), "{label}");
    }
    assert!(svg.contains("fails the clearance check"), "legend");
    // The part that sets the fairing depth is drawn where it reaches deepest.
    let fairing_part = report["stations"][0]["fairing"]["part"].as_str().unwrap();
    assert!(
        svg.contains(&format!("{fairing_part}: sets the fairing line")),
        "{fairing_part}"
    );
    // A scene that passes marks nothing.
    let clean = export(dir.path(), &["export", "--svg", "--out", "clean"]);
    assert_eq!(clean["interference"]["passes"], true);
    let svg = std::fs::read_to_string(dir.path().join("clean/station-inner.svg")).unwrap();
    assert!(!svg.contains("class=\"clash\""));
}

/// The rotation angle (deg) of the rigid motion taking `from` onto `to` (same points in
/// the same order; Kabsch, by SVD of the cross-covariance).
fn rotation_angle_deg(from: &[[f32; 3]], to: &[[f32; 3]]) -> f64 {
    let centre = |points: &[[f32; 3]]| {
        points
            .iter()
            .map(|p| Vector3::from(p.map(f64::from)))
            .sum::<Vector3<f64>>()
            / points.len() as f64
    };
    let (a, b) = (centre(from), centre(to));
    let mut covariance = Matrix3::zeros();
    for (p, q) in from.iter().zip(to) {
        covariance += (Vector3::from(p.map(f64::from)) - a) * (Vector3::from(q.map(f64::from)) - b).transpose();
    }
    let svd = covariance.svd(true, true);
    let rotation = svd.v_t.unwrap().transpose() * svd.u.unwrap().transpose();
    (((rotation.trace() - 1.0) / 2.0).clamp(-1.0, 1.0)).acos().to_degrees()
}

#[test]
fn export_at_takeoff_moves_the_flap_and_its_mechanism_and_nothing_else() {
    let dir = tempfile::tempdir().unwrap();
    let stowed = export(dir.path(), &["export", "--stl", "--out", "stowed"]);
    // Take-off: at landing the thesis screw points as it does stowed (collinearity).
    let takeoff = export(dir.path(), &["export", "--stl", "--at", "takeoff", "--out", "takeoff"]);
    assert_eq!(stowed["files"]["stl_setting"], "stowed");
    assert_eq!(takeoff["files"]["stl_setting"], "takeoff");
    let vertices = |out: &str, file: &str| -> Vec<[f32; 3]> {
        read_binary_stl(&std::fs::read(dir.path().join(out).join(file)).unwrap())
            .into_iter()
            .flatten()
            .collect()
    };
    // The flap turns by its take-off deflection (15 deg in the default scene).
    let angle = rotation_angle_deg(&vertices("stowed", "flap.stl"), &vertices("takeoff", "flap.stl"));
    assert!((angle - 15.0).abs() < 0.05, "flap turned {angle} deg");
    for part in ["wing", "front-spar", "rear-spar", "torque-tube"] {
        let file = format!("{part}.stl");
        assert_eq!(vertices("stowed", &file), vertices("takeoff", &file), "{part} stays");
    }
    for solid in stowed["mechanism_parts"].as_array().unwrap() {
        let file = solid["stl_file"].as_str().unwrap();
        let (before, after) = (vertices("stowed", file), vertices("takeoff", file));
        let moved = before != after;
        assert_eq!(moved, solid["role"] != "track", "{file} moved: {moved}");
        if solid["role"] == "flap" {
            // A fitting on the flap turns with it.
            let angle = rotation_angle_deg(&before, &after);
            assert!((angle - 15.0).abs() < 1e-3, "{file} turned {angle} deg");
        }
    }
    let refused = run_flapwright(
        dir.path(),
        &["export", "--urdf", "--stl", "--at", "landing", "--out", "x"],
    );
    assert_eq!(refused.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&refused.stderr).contains("--stl alone"));
}

#[test]
fn track_hardware_sizes_come_from_the_scene() {
    let dir = tempfile::tempdir().unwrap();
    let scene = crate::default_scene_text().replacen(
        "kind = \"circular-arc-track\"",
        "kind = \"circular-arc-track\"\nhardware = { nut_radius_m = 0.03, track_radius_m = 0.010 }",
        1,
    );
    std::fs::write(dir.path().join("scene.toml"), &scene).unwrap();
    let report = export(dir.path(), &["export", "scene.toml", "--stl", "--out", "sized"]);
    let mass = |name: &str| {
        report["mechanism_parts"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["name"] == name)
            .unwrap()["mass_kg"]
            .as_f64()
            .unwrap()
    };
    // A ball of 30 mm against the other station's default 20 mm: (3/2)^3 the mass.
    assert!((mass("inner.nut") / mass("outer.nut") - 3.375).abs() < 1e-9);
    assert!(mass("inner.inner-track") < mass("outer.inner-track"));
    std::fs::write(
        dir.path().join("bad.toml"),
        scene.replace("nut_radius_m = 0.03", "nut_radius_m = -0.03"),
    )
    .unwrap();
    let output = run_flapwright(dir.path(), &["export", "bad.toml", "--stl", "--out", "bad"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("hardware.nut_radius_m"));
}
