//! URDF export: round trip through urdf-rs, the strict rule check, forward kinematics of
//! the written file against the trajectory's key points, mesh placement, rpy conversion.

mod kinematics;
mod rpy;
mod rules;

use std::collections::HashMap;
use std::f64::consts::{FRAC_PI_2, PI};

use approx::assert_relative_eq;
use flapwright_kinds::{CircularArcTrack, CircularArcTrackSpec};
use flapwright_urdf::Error;
use flapwright_urdf::{
    build_robot, check_rules, rotation_from_rpy, rpy_from_rotation, to_xml, trajectory, BaseLink, BodyGeometry,
    MeshRef, RigidInertia, StationMechanism3d, Trajectory, UrdfModel,
};
use nalgebra::{Isometry3, Matrix3, Point3, Rotation3, Translation3, Unit, UnitQuaternion, Vector3};
use proptest::prelude::*;
use urdf_rs::{JointType, Robot};

/// The thesis case study's track (`000_...`), the URDF tests' mechanism.
fn thesis_track() -> CircularArcTrack {
    CircularArcTrack::synthesise(CircularArcTrackSpec::thesis_case_study()).expect("thesis case synthesises")
}

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

fn two_stations<'a>(inner: &'a CircularArcTrack, outer: &'a CircularArcTrack) -> Vec<StationMechanism3d<'a>> {
    vec![
        StationMechanism3d {
            name: "inner".to_owned(),
            aircraft_from_station: wing_station([3.2, 1.5, 0.4], 27.0, 5.0),
            mechanism: inner,
            flap_name: "flap".to_owned(),
            owns_flap: true,
            flap_mesh: Some("meshes/flap.stl".to_owned()),
            aft_element: None,
            flap_inertia: None,
            bodies: Vec::new(),
            actuator_peak_load: None,
        },
        StationMechanism3d {
            name: "outer".to_owned(),
            aircraft_from_station: wing_station([3.9, 3.0, 0.53], 27.0, 5.0),
            mechanism: outer,
            flap_name: "flap".to_owned(),
            owns_flap: false,
            flap_mesh: None,
            aft_element: None,
            flap_inertia: None,
            bodies: Vec::new(),
            actuator_peak_load: None,
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

/// The model written to XML and read back by urdf-rs.
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
    // The pins in their slots close each station's loop; the outer station's flap body
    // would be a second parent of the flap.
    assert_eq!(
        cuts,
        [
            ("inner", "F"),
            ("inner", "G"),
            ("outer", "F"),
            ("outer", "G"),
            ("outer", "flap_attachment")
        ]
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
fn bad_inputs_are_named_errors() {
    let track = thesis_track();
    let station = |name: &str, owns_flap: bool, flap_mesh: Option<&str>| StationMechanism3d {
        name: name.to_owned(),
        aircraft_from_station: Isometry3::identity(),
        mechanism: &track,
        flap_name: "flap".to_owned(),
        owns_flap,
        flap_mesh: flap_mesh.map(str::to_owned),
        aft_element: None,
        flap_inertia: None,
        bodies: Vec::new(),
        actuator_peak_load: None,
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
            Error::InvalidUrdfName { what: "station", .. }
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
        mechanism: &track,
        flap_name: "flap".to_owned(),
        owns_flap: true,
        flap_mesh: None,
        aft_element: None,
        flap_inertia: None,
        bodies: Vec::new(),
        actuator_peak_load: None,
    }];
    let json = serde_json::to_value(trajectory(&stations, 2).unwrap()).unwrap();
    assert_eq!(
        json["joint_names"],
        serde_json::json!(["inner_B0", "inner_nut_slide", "inner_A"])
    );
    let point = &json["samples"][1]["key_points_ac_m"]["inner.flap.A"];
    assert_eq!(point.as_array().map(Vec::len), Some(3));
}
