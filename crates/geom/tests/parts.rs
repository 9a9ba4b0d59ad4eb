//! Part meshes of the representative wing: watertight, positive volume, no overlap, STL.

use approx::assert_relative_eq;
use flapwright_geom::{
    compute_distance, io::stl, CollisionShape, Error, FlapSectionSpec, FlapSpec, HingeSpec, MeshResolution, PartKind,
    SparSpec, WingModel,
};
use nalgebra::{Isometry3, Point3};

use crate::fixture::{model, wing_spec};

const RESOLUTION: MeshResolution = MeshResolution {
    points_per_side: 30,
    spanwise_stations_per_m: 2.0,
    tube_segments: 16,
};

#[test]
fn every_part_is_watertight_with_positive_volume() {
    let parts = model().compute_parts(RESOLUTION).unwrap();
    let names: Vec<&str> = parts.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "wing",
            "inboard-flap",
            "outboard-flap",
            "front-spar",
            "rear-spar",
            "torque-tube"
        ]
    );
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
    assert_relative_eq!(
        parts[5].mesh.compute_signed_volume(),
        polygon_area * length,
        max_relative = 1e-9
    );
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
            assert!(
                !wing.contains_point(&identity, p),
                "{}: {p} inside the wing",
                flap_part.name
            );
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
        hinge: HingeSpec::ChordFraction {
            chord_fraction: 0.75,
            depth_below_chord_fraction: 0.05,
        },
        section: FlapSectionSpec::CutOut,
        side_gap_m: None,
        shroud_chord_fraction: 0.0,
        aft_element: None,
    }
}

#[test]
fn bad_models_are_errors() {
    assert!(matches!(
        with_flaps_and_spars(vec![flap(1.0, 3.0), flap(2.0, 4.0)], vec![]),
        Err(Error::FlapSpanConflict { .. })
    ));
    assert!(matches!(
        with_flaps_and_spars(vec![flap(5.0, 7.0)], vec![]),
        Err(Error::OutsideSpan { .. })
    ));
    assert!(matches!(
        with_flaps_and_spars(vec![flap(2.0, 2.0)], vec![]),
        Err(Error::FlapSpanConflict { .. })
    ));
    let mut zero_axis = flap(1.0, 2.0);
    zero_axis.hinge = HingeSpec::Points {
        inboard_ac: Point3::new(1.0, 1.0, 0.0),
        outboard_ac: Point3::new(1.0, 1.0, 0.0),
    };
    assert!(matches!(
        with_flaps_and_spars(vec![zero_axis], vec![]),
        Err(Error::DegenerateHingeAxis { .. })
    ));
    let behind = SparSpec {
        name: "rear".into(),
        chord_fraction: 0.72,
        thickness_m: 0.01,
        y_start_m: 0.0,
        y_end_m: 5.0,
    };
    assert!(matches!(
        with_flaps_and_spars(vec![flap(1.0, 2.0)], vec![behind]),
        Err(Error::SparBehindFlap { .. })
    ));
    let thin = SparSpec {
        name: "s".into(),
        chord_fraction: 0.3,
        thickness_m: 0.0,
        y_start_m: 0.0,
        y_end_m: 5.0,
    };
    assert!(with_flaps_and_spars(vec![], vec![thin]).is_err());
    let mut nan_flap = flap(1.0, 2.0);
    nan_flap.chord_fraction_outboard = f64::NAN;
    assert!(matches!(
        with_flaps_and_spars(vec![nan_flap], vec![]),
        Err(Error::NotFinite { .. })
    ));
    assert!(model()
        .compute_parts(MeshResolution {
            points_per_side: 2,
            ..RESOLUTION
        })
        .is_err());
}

mod random_wings {
    use flapwright_geom::{
        Airfoil, FlapSectionSpec, FlapSpec, HingeSpec, MeshResolution, PanelSpec, SparSpec, SweepReference,
        TrailingEdge, WingModel, WingSectionSpec, WingSpec,
    };
    use nalgebra::Point3;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]
        /// Extreme but valid wings: sweep to 60 deg, negative dihedral, large twist, model
        /// scale (0.05 m chord) to full scale (8 m chord): every part stays watertight.
        #[test]
        fn extreme_wings_mesh_watertight(
            scale in prop_oneof![Just(0.05), Just(1.0), Just(8.0)],
            sweep_deg in -20.0..60.0f64,
            dihedral_deg in -15.0..15.0f64,
            twist_root_deg in -20.0..20.0f64,
            twist_tip_deg in -20.0..20.0f64,
            taper in 0.2..1.0f64,
            chord_fraction in 0.15..0.4f64,
            own_section in any::<bool>(),
            quarter_chord in any::<bool>(),
        ) {
            let root = Airfoil::naca("4415", 24, TrailingEdge::Open).unwrap();
            let tip = crate::fixture::n63212();
            let spec = WingSpec {
                root_leading_edge_ac: Point3::new(0.1 * scale, 0.2 * scale, 0.0),
                sections: vec![
                    WingSectionSpec { y_m: 0.2 * scale, chord_m: scale, twist_deg: twist_root_deg, airfoil: root },
                    WingSectionSpec { y_m: 4.0 * scale, chord_m: scale * taper, twist_deg: twist_tip_deg, airfoil: tip.clone() },
                ],
                panels: vec![PanelSpec { sweep_deg, dihedral_deg }],
                sweep_reference: if quarter_chord { SweepReference::QuarterChord } else { SweepReference::LeadingEdge },
                twist_axis_chord_fraction: 0.4,
            };
            let flap = FlapSpec {
                name: "flap".into(),
                y_inboard_m: 0.8 * scale,
                y_outboard_m: 3.0 * scale,
                chord_fraction_inboard: chord_fraction,
                chord_fraction_outboard: chord_fraction * 0.9,
                hinge: HingeSpec::ChordFraction { chord_fraction: 0.8, depth_below_chord_fraction: 0.05 },
                section: if own_section { FlapSectionSpec::OwnSection { airfoil: tip } } else { FlapSectionSpec::CutOut },
                side_gap_m: None,
            shroud_chord_fraction: 0.0,
            aft_element: None,
            };
            let spar = SparSpec { name: "spar".into(), chord_fraction: 0.2, thickness_m: 0.01 * scale * taper, y_start_m: 0.2 * scale, y_end_m: 4.0 * scale };
            let model = WingModel::try_new(spec, vec![flap], vec![spar], None).unwrap();
            let parts = model.compute_parts(MeshResolution { points_per_side: 20, spanwise_stations_per_m: 2.0 / scale, tube_segments: 8 }).unwrap();
            for part in &parts {
                prop_assert!(part.mesh.compute_topology_check().is_watertight(), "{}", part.name);
                prop_assert!(part.mesh.compute_signed_volume() > 0.0);
                prop_assert!(part.mesh.vertices.iter().all(|p| p.coords.iter().all(|v| v.is_finite())));
            }
        }
    }
}

#[test]
fn section_outlines_match_the_meshes_and_keep_the_flap_clear() {
    let model = model();
    let outlines = model.compute_section_outlines(1.5, 30).unwrap();
    let names: Vec<&str> = outlines.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["wing", "inboard-flap", "front-spar", "rear-spar"]);
    for outline in &outlines {
        assert!(outline.points_ac.iter().all(|p| (p.y - 1.5).abs() < 1e-12));
    }
    // In the cut, the flap lies wholly behind the wing's cove wall (along the local chord).
    let chord_direction =
        (model.wing().chord_point_ac(1.5, 1.0).unwrap() - model.wing().chord_point_ac(1.5, 0.0).unwrap()).normalize();
    let along = |p: &Point3<f64>| p.coords.dot(&chord_direction);
    let wing_aft = outlines[0].points_ac.iter().map(along).fold(f64::MIN, f64::max);
    let flap_fore = outlines[1].points_ac.iter().map(along).fold(f64::MAX, f64::min);
    assert!(flap_fore - wing_aft > 0.009 * 1.75, "gap {}", flap_fore - wing_aft);
    assert!(model.compute_section_outlines(7.0, 30).is_err());
}
