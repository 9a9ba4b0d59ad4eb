//! Cut of geom's lofted wing: an untwisted, unswept wing reproduces the airfoil polygon
//! scaled by the chord.

use flapwright_geom::{
    Airfoil, MeshResolution, PanelSpec, SweepReference, TrailingEdge, WingModel, WingSectionSpec, WingSpec,
};
use flapwright_planes::{boundary_deviation, cut_mesh, signed_area_m2, StationFrame};
use nalgebra::{Point2, Point3, Vector3};

#[test]
fn untwisted_unswept_wing_cut_is_the_scaled_airfoil() {
    let points_per_side = 40;
    let airfoil = Airfoil::naca("2412", points_per_side, TrailingEdge::Closed).unwrap();
    let chord = 1.4;
    let section = |y_m: f64| WingSectionSpec {
        y_m,
        chord_m: chord,
        twist_deg: 0.0,
        airfoil: airfoil.clone(),
    };
    let leading_edge = Point3::new(2.0, 0.5, 0.1);
    let spec = WingSpec {
        root_leading_edge_ac: leading_edge,
        sections: vec![section(0.5), section(4.0)],
        panels: vec![PanelSpec {
            sweep_deg: 0.0,
            dihedral_deg: 0.0,
        }],
        sweep_reference: SweepReference::LeadingEdge,
        twist_axis_chord_fraction: 0.25,
    };
    let model = WingModel::try_new(spec, vec![], vec![], None).unwrap();
    let resolution = MeshResolution {
        points_per_side,
        ..MeshResolution::default()
    };
    let parts = model.compute_parts(resolution).unwrap();
    let wing = parts.iter().find(|p| p.name == "wing").expect("wing part");
    for y in [1.3, 2.0, 3.37] {
        let frame = StationFrame::try_from_origin_and_normal(
            Point3::new(leading_edge.x, y, leading_edge.z),
            &Vector3::y_axis(),
        )
        .unwrap();
        let cut = cut_mesh(&wing.mesh, &frame, "wing").unwrap();
        assert_eq!(cut.polygons.len(), 1, "y = {y}");
        // Airfoil (u aft, v up, unit chord) -> station (x to the nose, y up): (-c u, c v).
        let mut expected: Vec<Point2<f64>> = airfoil
            .points
            .iter()
            .map(|p| Point2::new(-chord * p.x, chord * p.y))
            .collect();
        expected.dedup_by(|a, b| (*a - *b).norm() < 1e-15);
        let to_cut = boundary_deviation(&cut.polygons, &expected).unwrap();
        let to_airfoil = boundary_deviation(&[expected.clone()], &cut.polygons[0]).unwrap();
        assert!(
            to_cut.max_m < 1e-12,
            "y = {y}: airfoil off the cut by {} m",
            to_cut.max_m
        );
        assert!(
            to_airfoil.max_m < 1e-12,
            "y = {y}: cut off the airfoil by {} m",
            to_airfoil.max_m
        );
        let area = signed_area_m2(&cut.polygons[0]);
        assert!(area > 0.0, "outline counter-clockwise in the station frame");
        assert!((area - signed_area_m2(&expected).abs()).abs() < 1e-12);
    }
}
