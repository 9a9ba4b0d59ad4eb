//! URDF export: round trip through urdf-rs, the strict rule check, forward kinematics of
//! the written file against the trajectory's key points, mesh placement, rpy conversion.

use std::collections::HashMap;

use approx::assert_relative_eq;
use flapwright_mechanism::urdf::{
    build_robot, check_rules, rotation_from_rpy, rpy_from_rotation, to_xml, trajectory, BaseLink,
    MeshRef, StationMechanism3d, Trajectory, UrdfModel,
};
use flapwright_mechanism::{CircularArcTrack, CircularArcTrackSpec, Error};
use nalgebra::{
    Isometry3, Matrix3, Point3, Rotation3, Translation3, Unit, UnitQuaternion, Vector3,
};
use proptest::prelude::*;
use urdf_rs::{JointType, Robot};

use crate::common::thesis_track;

/// Acceptance tolerance of issue 7 (m).
const KEY_POINT_TOLERANCE_M: f64 = 1e-6;
/// Deployment samples of the trajectory under test.
const SAMPLES: usize = 41;

/// The thesis track with every length scaled by `factor` (angles unchanged).
fn scaled_track(factor: f64) -> CircularArcTrack {
    let mut spec = CircularArcTrackSpec::thesis_case_study();
    spec.base_distance_m *= factor;
    spec.crank_length_m *= factor;
    spec.screw_length_m *= factor;
    spec.outer_slot_radius_m *= factor;
    spec.inner_slot_radius_m *= factor;
    spec.centre_of_mass_stowed_m *= factor;
    CircularArcTrack::synthesise(spec).expect("scaled thesis track synthesises")
}

/// A right-wing station frame: x to the nose (-x_ac), y up (z_ac), z outboard (y_ac),
/// then swept back by `sweep_deg` about z_ac and tilted by `dihedral_deg` about x_ac.
fn wing_station(origin_ac: [f64; 3], sweep_deg: f64, dihedral_deg: f64) -> Isometry3<f64> {
    let base = Matrix3::new(-1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0);
    let sweep = Rotation3::from_axis_angle(&Vector3::z_axis(), -sweep_deg.to_radians());
    let dihedral = Rotation3::from_axis_angle(&Vector3::x_axis(), dihedral_deg.to_radians());
    let rotation = dihedral * sweep * Rotation3::from_matrix_unchecked(base);
    Isometry3::from_parts(
        Translation3::new(origin_ac[0], origin_ac[1], origin_ac[2]),
        UnitQuaternion::from_rotation_matrix(&rotation),
    )
}

fn base_link() -> BaseLink {
    BaseLink {
        name: "wing".to_owned(),
        meshes: vec![
            MeshRef {
                name: "skin".to_owned(),
                filename: "meshes/skin.stl".to_owned(),
            },
            MeshRef {
                name: "front_spar".to_owned(),
                filename: "meshes/front_spar.stl".to_owned(),
            },
        ],
    }
}

fn two_stations<'a>(
    inner: &'a CircularArcTrack,
    outer: &'a CircularArcTrack,
) -> Vec<StationMechanism3d<'a>> {
    vec![
        StationMechanism3d {
            name: "inner".to_owned(),
            aircraft_from_station: wing_station([3.2, 1.5, 0.4], 27.0, 5.0),
            track: inner,
            flap_name: "flap".to_owned(),
            owns_flap: true,
            flap_mesh: Some("meshes/flap.stl".to_owned()),
        },
        StationMechanism3d {
            name: "outer".to_owned(),
            aircraft_from_station: wing_station([3.9, 3.0, 0.53], 27.0, 5.0),
            track: outer,
            flap_name: "flap".to_owned(),
            owns_flap: false,
            flap_mesh: None,
        },
    ]
}

/// URDF rpy written out independently: R = Rz(yaw) Ry(pitch) Rx(roll).
fn rpy_matrix([roll, pitch, yaw]: [f64; 3]) -> Matrix3<f64> {
    let (sr, cr) = roll.sin_cos();
    let (sp, cp) = pitch.sin_cos();
    let (sy, cy) = yaw.sin_cos();
    let rz = Matrix3::new(cy, -sy, 0.0, sy, cy, 0.0, 0.0, 0.0, 1.0);
    let ry = Matrix3::new(cp, 0.0, sp, 0.0, 1.0, 0.0, -sp, 0.0, cp);
    let rx = Matrix3::new(1.0, 0.0, 0.0, 0.0, cr, -sr, 0.0, sr, cr);
    rz * ry * rx
}

fn pose_isometry(pose: &urdf_rs::Pose) -> Isometry3<f64> {
    let rotation = Rotation3::from_matrix_unchecked(rpy_matrix(pose.rpy.0));
    Isometry3::from_parts(
        Translation3::new(pose.xyz[0], pose.xyz[1], pose.xyz[2]),
        UnitQuaternion::from_rotation_matrix(&rotation),
    )
}

/// Forward kinematics written in the test: walks the tree from the root, composing each
/// joint's origin and motion (revolute: turn about the axis; prismatic: slide along it).
fn forward_kinematics(
    robot: &Robot,
    values: &HashMap<&str, f64>,
) -> HashMap<String, Isometry3<f64>> {
    let children: Vec<&str> = robot.joints.iter().map(|j| j.child.link.as_str()).collect();
    let root = robot
        .links
        .iter()
        .find(|l| !children.contains(&l.name.as_str()))
        .expect("a root link");
    let mut poses = HashMap::from([(root.name.clone(), Isometry3::identity())]);
    let mut changed = true;
    while changed {
        changed = false;
        for joint in &robot.joints {
            let Some(parent) = poses.get(&joint.parent.link).copied() else {
                continue;
            };
            if poses.contains_key(&joint.child.link) {
                continue;
            }
            let axis = Vector3::from(joint.axis.xyz.0);
            let q = values.get(joint.name.as_str()).copied().unwrap_or(0.0);
            let motion = match joint.joint_type {
                JointType::Revolute | JointType::Continuous => Isometry3::rotation(axis * q),
                JointType::Prismatic => Isometry3::translation(axis.x * q, axis.y * q, axis.z * q),
                JointType::Fixed => Isometry3::identity(),
                ref other => panic!("unexpected joint type {other:?}"),
            };
            poses.insert(
                joint.child.link.clone(),
                parent * pose_isometry(&joint.origin) * motion,
            );
            changed = true;
        }
    }
    assert_eq!(poses.len(), robot.links.len(), "every link reached");
    poses
}

/// Largest key-point error (m) of the URDF read back from XML, over all samples.
fn key_point_error(robot: &Robot, trajectory: &Trajectory) -> f64 {
    let mut worst = 0.0_f64;
    for sample in &trajectory.samples {
        let values: HashMap<&str, f64> = trajectory
            .joint_names
            .iter()
            .map(String::as_str)
            .zip(sample.joint_values.iter().copied())
            .collect();
        let poses = forward_kinematics(robot, &values);
        for key in &trajectory.key_points {
            let computed = poses[&key.link] * Point3::from(key.position_link_m);
            let expected = Point3::from(sample.key_points_ac_m[&key.name]);
            worst = worst.max((computed - expected).norm());
        }
    }
    worst
}

fn read_back(model: &UrdfModel) -> Robot {
    urdf_rs::read_from_string(&to_xml(model).expect("writes")).expect("urdf-rs reads it back")
}

#[test]
fn round_trip_keeps_names_joints_and_numbers() {
    let (inner, outer) = (thesis_track(), scaled_track(0.8));
    let model = build_robot("right_wing", &base_link(), &two_stations(&inner, &outer)).unwrap();
    let back = read_back(&model);
    assert_eq!(back.name, model.robot.name);
    let names = |r: &Robot| r.links.iter().map(|l| l.name.clone()).collect::<Vec<_>>();
    assert_eq!(names(&back), names(&model.robot));
    assert_eq!(back.joints.len(), model.robot.joints.len());
    for (read, written) in back.joints.iter().zip(&model.robot.joints) {
        assert_eq!(read.name, written.name);
        assert_eq!(read.joint_type, written.joint_type);
        assert_eq!(read.parent.link, written.parent.link);
        assert_eq!(read.child.link, written.child.link);
        // Rust prints f64 in its shortest round-trip form, so numbers come back exactly.
        assert_eq!(read.origin.xyz, written.origin.xyz);
        assert_eq!(read.origin.rpy, written.origin.rpy);
        assert_eq!(read.axis.xyz, written.axis.xyz);
        assert_eq!(
            (read.limit.lower, read.limit.upper),
            (written.limit.lower, written.limit.upper)
        );
    }
    let flap = back.links.iter().find(|l| l.name == "flap").unwrap();
    match &flap.visual[0].geometry {
        urdf_rs::Geometry::Mesh { filename, .. } => assert_eq!(filename, "meshes/flap.stl"),
        other => panic!("flap visual is {other:?}"),
    }
}

#[test]
fn xml_has_declaration_and_names_the_cut_joints() {
    let (inner, outer) = (thesis_track(), scaled_track(0.8));
    let model = build_robot("right_wing", &base_link(), &two_stations(&inner, &outer)).unwrap();
    let xml = to_xml(&model).unwrap();
    assert!(xml.starts_with("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<!--"));
    let cuts: Vec<_> = model
        .cut_joints
        .iter()
        .map(|c| (c.station.as_str(), c.joint.as_str()))
        .collect();
    assert_eq!(
        cuts,
        [("inner", "A"), ("outer", "A"), ("outer", "flap_attachment")]
    );
    for cut in &model.cut_joints {
        let line = format!(
            "station {}: {} joint {} between links {} and {}",
            cut.station, cut.kind, cut.joint, cut.between.0, cut.between.1
        );
        assert!(xml.contains(&line), "comment lacks `{line}`");
    }
}

#[test]
fn built_and_read_back_robots_pass_the_rule_check() {
    let (inner, outer) = (thesis_track(), scaled_track(0.8));
    let model = build_robot("right_wing", &base_link(), &two_stations(&inner, &outer)).unwrap();
    assert_eq!(check_rules(&model.robot), Vec::<String>::new());
    assert_eq!(check_rules(&read_back(&model)), Vec::<String>::new());
}

#[test]
fn rule_check_catches_broken_robots() {
    let (inner, outer) = (thesis_track(), scaled_track(0.8));
    let good = build_robot("right_wing", &base_link(), &two_stations(&inner, &outer))
        .unwrap()
        .robot;
    type Breaker = fn(&mut Robot);
    let cases: [(&str, Breaker); 9] = [
        ("link name `inner_screw` is not unique", |r| {
            r.links[2].name = "inner_screw".to_owned()
        }),
        ("joint name `inner_flap_hinge` is not unique", |r| {
            r.joints[2].name = "inner_flap_hinge".to_owned()
        }),
        ("parent link `nowhere` does not exist", |r| {
            r.joints[1].parent.link = "nowhere".to_owned()
        }),
        ("expected exactly one root link, found 2", |r| {
            r.links.push(r.links[0].clone());
            r.links.last_mut().unwrap().name = "loose".to_owned();
        }),
        ("is the child of two joints", |r| {
            let mut extra = r.joints[1].clone();
            extra.name = "extra".to_owned();
            extra.parent.link = "outer_station".to_owned();
            r.joints.push(extra);
        }),
        ("has length", |r| r.joints[1].axis.xyz.0 = [0.0, 0.0, 1.1]),
        ("lower limit", |r| {
            let limit = &mut r.joints[1].limit;
            std::mem::swap(&mut limit.lower, &mut limit.upper);
        }),
        ("not reachable from root", |r| {
            // inner_station's mount now hangs off its own screw: a cycle.
            r.joints[0].parent.link = "inner_screw".to_owned();
            r.links.push(r.links[0].clone());
            r.links.last_mut().unwrap().name = "spare".to_owned();
            let mut spare = r.joints[0].clone();
            spare.name = "spare_mount".to_owned();
            spare.parent.link = "wing".to_owned();
            spare.child.link = "spare".to_owned();
            r.joints.push(spare);
        }),
        ("is not relative to the URDF", |r| {
            if let urdf_rs::Geometry::Mesh { filename, .. } = &mut r.links[0].visual[0].geometry {
                *filename = "/abs/skin.stl".to_owned();
            }
        }),
    ];
    for (expected, breaker) in cases {
        let mut broken = good.clone();
        breaker(&mut broken);
        let violations = check_rules(&broken);
        assert!(
            violations.iter().any(|v| v.contains(expected)),
            "expected a violation containing `{expected}`, got {violations:?}"
        );
    }
}

#[test]
fn forward_kinematics_of_the_file_reproduces_every_key_point() {
    let (inner, outer) = (thesis_track(), scaled_track(0.8));
    let stations = two_stations(&inner, &outer);
    let model = build_robot("right_wing", &base_link(), &stations).unwrap();
    let trajectory = trajectory(&stations, SAMPLES).unwrap();
    assert_eq!(trajectory.samples.len(), SAMPLES);
    assert_eq!(trajectory.key_points.len(), 2 * 8 + 3);
    let error = key_point_error(&read_back(&model), &trajectory);
    assert!(error <= KEY_POINT_TOLERANCE_M, "key point error {error} m");
    // In fact it is rounding: 1e-12 m holds with a wide margin.
    assert!(error <= 1e-12, "key point error {error} m");
}

#[test]
fn placements_at_gimbal_lock_survive_the_file() {
    let track = thesis_track();
    for pitch in [
        std::f64::consts::FRAC_PI_2,
        -std::f64::consts::FRAC_PI_2,
        1.5707963,
    ] {
        let rotation = UnitQuaternion::from_euler_angles(0.4, pitch, -2.1);
        let station = StationMechanism3d {
            name: "only".to_owned(),
            aircraft_from_station: Isometry3::from_parts(
                Translation3::new(1.0, -2.0, 0.5),
                rotation,
            ),
            track: &track,
            flap_name: "flap".to_owned(),
            owns_flap: true,
            flap_mesh: None,
        };
        let stations = [station];
        let model = build_robot("gimbal", &base_link(), &stations).unwrap();
        let error = key_point_error(&read_back(&model), &trajectory(&stations, 9).unwrap());
        assert!(error <= 1e-12, "pitch {pitch}: key point error {error} m");
    }
}

#[test]
fn meshes_appear_where_they_are_given_at_stowed() {
    let (inner, outer) = (thesis_track(), scaled_track(0.8));
    let stations = two_stations(&inner, &outer);
    let robot = read_back(&build_robot("right_wing", &base_link(), &stations).unwrap());
    let trajectory = trajectory(&stations, 3).unwrap();
    let stowed = &trajectory.samples[0];
    let values = trajectory
        .joint_names
        .iter()
        .map(String::as_str)
        .zip(stowed.joint_values.iter().copied())
        .collect();
    let poses = forward_kinematics(&robot, &values);
    let vertex_ac = Point3::new(3.05, 1.62, 0.37);
    for link in &robot.links {
        for visual in &link.visual {
            let shown = poses[&link.name] * pose_isometry(&visual.origin) * vertex_ac;
            assert_relative_eq!(shown, vertex_ac, epsilon = 1e-12);
        }
    }
    assert_eq!(robot.links.iter().map(|l| l.visual.len()).sum::<usize>(), 3);
}

#[test]
fn joint_values_start_stowed_and_stay_within_limits() {
    let (inner, outer) = (thesis_track(), scaled_track(0.8));
    let stations = two_stations(&inner, &outer);
    let robot = build_robot("right_wing", &base_link(), &stations)
        .unwrap()
        .robot;
    let trajectory = trajectory(&stations, SAMPLES).unwrap();
    let synthesis = inner.synthesis();
    let first = &trajectory.samples[0].joint_values;
    assert!(
        first[0].abs() <= 1e-15 && first[1].abs() <= 1e-15,
        "stowed: {first:?}"
    );
    assert_relative_eq!(first[2], synthesis.stroke_start_m, max_relative = 1e-15);
    let last = &trajectory.samples[SAMPLES - 1].joint_values;
    assert_relative_eq!(last[0], 35f64.to_radians(), max_relative = 1e-12);
    assert_relative_eq!(last[2], synthesis.stroke_end_m, max_relative = 1e-15);
    let limit = |name: &str| {
        let joint = robot.joints.iter().find(|j| j.name == name).unwrap();
        (joint.limit.lower, joint.limit.upper)
    };
    let mut screw_range = (0.0_f64, 0.0_f64);
    for sample in &trajectory.samples {
        for (name, value) in trajectory.joint_names.iter().zip(&sample.joint_values) {
            let (lower, upper) = limit(name);
            assert!(
                *value >= lower - 1e-12 && *value <= upper + 1e-12,
                "{name} = {value} outside [{lower}, {upper}]"
            );
        }
        screw_range.0 = screw_range.0.min(sample.joint_values[1]);
        screw_range.1 = screw_range.1.max(sample.joint_values[1]);
    }
    // The analytic screw extreme (B0A tangent to A's circle) bounds the sampled one
    // closely: 41 samples miss the peak by a second-order amount only.
    let (lower, upper) = limit("inner_screw_pivot");
    assert!(lower < 0.0 || upper > 0.0, "the screw swings");
    let extreme = if upper > 0.0 {
        (upper, screw_range.1)
    } else {
        (lower, screw_range.0)
    };
    assert_relative_eq!(extreme.0, extreme.1, max_relative = 1e-2);
}

#[test]
fn bad_inputs_are_named_errors() {
    let track = thesis_track();
    let station = |name: &str, owns_flap: bool, flap_mesh: Option<&str>| StationMechanism3d {
        name: name.to_owned(),
        aircraft_from_station: Isometry3::identity(),
        track: &track,
        flap_name: "flap".to_owned(),
        owns_flap,
        flap_mesh: flap_mesh.map(str::to_owned),
    };
    let base = base_link();
    let error = |stations: &[StationMechanism3d]| build_robot("w", &base, stations).unwrap_err();
    assert_eq!(error(&[]), Error::NoStations);
    assert!(matches!(
        error(&[station("a", true, None), station("a", false, None)]),
        Error::DuplicateUrdfName { .. }
    ));
    assert!(matches!(
        error(&[station("a", false, None)]),
        Error::FlapOwnership { owners: 0, .. }
    ));
    assert!(matches!(
        error(&[station("a", true, None), station("b", true, None)]),
        Error::FlapOwnership { owners: 2, .. }
    ));
    for path in ["/meshes/flap.stl", "C:\\flap.stl", "file:///flap.stl", ""] {
        assert!(matches!(
            error(&[station("a", true, Some(path))]),
            Error::MeshPathNotRelative { .. }
        ));
    }
    assert!(matches!(
        error(&[station("a", true, None), station("b", false, Some("m.stl"))]),
        Error::FlapMeshOnNonOwningStation { .. }
    ));
    for name in ["", "in ner", "a.b", "a--b"] {
        assert!(matches!(
            error(&[station(name, true, None)]),
            Error::InvalidUrdfName {
                what: "station",
                ..
            }
        ));
    }
    let mut nan = station("a", true, None);
    nan.aircraft_from_station.translation.x = f64::NAN;
    assert!(matches!(error(&[nan]), Error::NonFinitePlacement { .. }));
    assert!(matches!(
        trajectory(&[station("a", true, None)], 1),
        Err(Error::TooFewSamples { samples: 1 })
    ));
}

#[test]
fn trajectory_serialises_with_its_documented_keys() {
    let track = thesis_track();
    let stations = [StationMechanism3d {
        name: "inner".to_owned(),
        aircraft_from_station: wing_station([3.2, 1.5, 0.4], 27.0, 5.0),
        track: &track,
        flap_name: "flap".to_owned(),
        owns_flap: true,
        flap_mesh: None,
    }];
    let json = serde_json::to_value(trajectory(&stations, 2).unwrap()).unwrap();
    assert_eq!(
        json["joint_names"],
        serde_json::json!(["inner_flap_hinge", "inner_screw_pivot", "inner_nut_slide"])
    );
    let point = &json["samples"][1]["key_points_ac_m"]["inner.A"];
    assert_eq!(point.as_array().map(Vec::len), Some(3));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn rpy_round_trips_through_the_matrix(
        roll in -3.14159..3.14159_f64,
        pitch_offset in prop_oneof![Just(0.0), -1e-7..1e-7_f64, -1.5..1.5_f64],
        near_lock in any::<bool>(),
        yaw in -3.14159..3.14159_f64,
    ) {
        let pitch = if near_lock {
            std::f64::consts::FRAC_PI_2.copysign(roll) - pitch_offset.abs().copysign(roll)
        } else {
            pitch_offset
        };
        let written = rpy_matrix([roll, pitch, yaw]);
        prop_assert!((rotation_from_rpy([roll, pitch, yaw]).matrix() - written).abs().max() < 1e-15);
        let read = rpy_from_rotation(&Rotation3::from_matrix_unchecked(written));
        prop_assert!((rpy_matrix(read) - written).abs().max() < 1e-14);
        prop_assert!(read[1].abs() <= std::f64::consts::FRAC_PI_2);
    }

    #[test]
    fn any_rotation_round_trips(axis in prop::array::uniform3(-1.0..1.0_f64), angle in -3.14..3.14_f64) {
        prop_assume!(Vector3::from(axis).norm() > 1e-3);
        let rotation = Rotation3::from_axis_angle(&Unit::new_normalize(Vector3::from(axis)), angle);
        let read = rpy_from_rotation(&rotation);
        prop_assert!((rpy_matrix(read) - rotation.matrix()).abs().max() < 1e-14);
    }
}
