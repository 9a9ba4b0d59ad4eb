//! Part meshes of the representative wing: watertight, positive volume, no overlap, STL.

use approx::assert_relative_eq;
use flapwright_geom::{
    compute_distance, io::stl, CollisionShape, Error, FlapSectionSpec, FlapSpec, HingeSpec, MeshResolution, PartKind, SparSpec, WingModel,
};
use nalgebra::{Isometry3, Point3};

use crate::fixture::{model, wing_spec};

const RESOLUTION: MeshResolution = MeshResolution { points_per_side: 30, spanwise_stations_per_m: 2.0, tube_segments: 16 };

#[test]
fn every_part_is_watertight_with_positive_volume() {
    let parts = model().compute_parts(RESOLUTION).unwrap();
    let names: Vec<&str> = parts.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["wing", "inboard-flap", "outboard-flap", "front-spar", "rear-spar", "torque-tube"]);
    for part in &parts {
        let check = part.mesh.compute_topology_check();
        assert!(check.is_watertight(), "{}: {check:?}", part.name);
        assert!(part.mesh.compute_signed_volume() > 0.0, "{}", part.name);
    }
    let kinds: Vec<PartKind> = parts.iter().map(|p| p.kind).collect();
    assert_eq!(kinds[0], PartKind::WingSkin);
    assert_eq!(kinds[5], PartKind::TorqueTube);
}

#[test]
fn torque_tube_volume_is_cylinder_volume() {
    // A mitred tube has exactly the volume of its polygonal cross-section times the path length.
    let parts = model().compute_parts(RESOLUTION).unwrap();
    let tube = model().torque_tube().unwrap().clone();
    let length: f64 = tube.path_ac.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
    let n = RESOLUTION.tube_segments as f64;
    let polygon_area = 0.5 * n * tube.radius_m.powi(2) * (std::f64::consts::TAU / n).sin();
    assert_relative_eq!(parts[5].mesh.compute_signed_volume(), polygon_area * length, max_relative = 1e-9);
}

#[test]
fn stowed_flaps_do_not_overlap_the_wing() {
    let model = model();
    let parts = model.compute_parts(RESOLUTION).unwrap();
    let wing = CollisionShape::from_mesh(&parts[0].mesh).unwrap();
    let identity = Isometry3::identity();
    for flap_part in &parts[1..3] {
        // No flap vertex inside the wing solid, and the surfaces keep a gap.
        for p in flap_part.mesh.vertices.iter().step_by(7) {
            assert!(!wing.contains_point(&identity, p), "{}: {p} inside the wing", flap_part.name);
        }
        let flap = CollisionShape::from_mesh(&flap_part.mesh).unwrap();
        let proximity = compute_distance(&wing, &identity, &flap, &identity).unwrap();
        assert!(proximity.distance_m > 1e-3, "{}: {proximity:?}", flap_part.name);
    }
    // The flap centroid region is outside the wing, a point ahead of the rear spar is inside.
    let inside = model.wing().chord_point_ac(1.0, 0.4).unwrap();
    assert!(wing.contains_point(&identity, &inside));
    let hinge = model.flaps()[0].hinge_axis_ac();
    assert!(hinge.1.y > 0.0);
}

#[test]
fn stl_round_trip_keeps_triangles_and_outward_normals() {
    let parts = model().compute_parts(RESOLUTION).unwrap();
    let mesh = &parts[2].mesh;
    let mut bytes = Vec::new();
    stl::write_binary(mesh, "outboard-flap", &mut bytes).unwrap();
    assert_eq!(bytes.len(), 84 + 50 * mesh.triangles.len());
    assert!(bytes.starts_with(b"flapwright outboard-flap"));
    let read = stl_io::read_stl(&mut std::io::Cursor::new(bytes)).unwrap();
    assert_eq!(read.faces.len(), mesh.triangles.len());
    for (face, i) in read.faces.iter().zip(0..) {
        let n = mesh.triangle_normal(i);
        assert_relative_eq!(f64::from(face.normal[0]), n.x, epsilon = 1e-6);
        assert_relative_eq!(f64::from(face.normal[2]), n.z, epsilon = 1e-6);
    }
}

fn with_flaps_and_spars(flaps: Vec<FlapSpec>, spars: Vec<SparSpec>) -> Result<WingModel, Error> {
    WingModel::try_new(wing_spec(), flaps, spars, None)
}

fn flap(y_inboard_m: f64, y_outboard_m: f64) -> FlapSpec {
    FlapSpec {
        name: format!("flap {y_inboard_m}"),
        y_inboard_m,
        y_outboard_m,
        chord_fraction_inboard: 0.3,
        chord_fraction_outboard: 0.3,
        hinge: HingeSpec::ChordFraction { chord_fraction: 0.75, depth_below_chord_fraction: 0.05 },
        section: FlapSectionSpec::CutOut,
    }
}

#[test]
fn bad_models_are_errors() {
    assert!(matches!(with_flaps_and_spars(vec![flap(1.0, 3.0), flap(2.0, 4.0)], vec![]), Err(Error::FlapSpanConflict { .. })));
    assert!(matches!(with_flaps_and_spars(vec![flap(5.0, 7.0)], vec![]), Err(Error::OutsideSpan { .. })));
    assert!(matches!(with_flaps_and_spars(vec![flap(2.0, 2.0)], vec![]), Err(Error::FlapSpanConflict { .. })));
    let mut zero_axis = flap(1.0, 2.0);
    zero_axis.hinge = HingeSpec::Points { inboard_ac: Point3::new(1.0, 1.0, 0.0), outboard_ac: Point3::new(1.0, 1.0, 0.0) };
    assert!(matches!(with_flaps_and_spars(vec![zero_axis], vec![]), Err(Error::DegenerateHingeAxis { .. })));
    let behind = SparSpec { name: "rear".into(), chord_fraction: 0.72, thickness_m: 0.01, y_start_m: 0.0, y_end_m: 5.0 };
    assert!(matches!(with_flaps_and_spars(vec![flap(1.0, 2.0)], vec![behind]), Err(Error::SparBehindFlap { .. })));
    let thin = SparSpec { name: "s".into(), chord_fraction: 0.3, thickness_m: 0.0, y_start_m: 0.0, y_end_m: 5.0 };
    assert!(with_flaps_and_spars(vec![], vec![thin]).is_err());
    let mut nan_flap = flap(1.0, 2.0);
    nan_flap.chord_fraction_outboard = f64::NAN;
    assert!(matches!(with_flaps_and_spars(vec![nan_flap], vec![]), Err(Error::NotFinite { .. })));
    assert!(model().compute_parts(MeshResolution { points_per_side: 2, ..RESOLUTION }).is_err());
}
