//! Section cuts of test meshes built here: oblique cylinder -> ellipse, airfoil prism ->
//! the airfoil polygon, vertices exactly on the plane.

use approx::assert_relative_eq;
use flapwright_planes::{boundary_deviation, cut_mesh, signed_area_m2, StationFrame};
use nalgebra::{Point2, Point3, Unit, Vector3};

use crate::meshes::{circle, naca4, prism};

#[test]
fn oblique_cut_of_a_tube_is_the_expected_ellipse() {
    // Torque tube along aircraft y, radius 25 mm, 256 segments; plane tilted by `angle`
    // about the vertical (a swept station plane): semi-axes r (station y) and r / cos(angle)
    // (station x).
    let (radius, segments) = (0.025, 256);
    let tube = prism(
        &circle(radius, segments),
        Point3::new(3.0, 0.0, 0.2),
        Vector3::z(),
        Vector3::x(),
        Vector3::y(),
        &[0.0, 4.0],
    );
    for angle_deg in [0.0f64, 20.0, 45.0, 60.0] {
        let angle = angle_deg.to_radians();
        let normal = Unit::new_normalize(Vector3::new(angle.sin(), angle.cos(), 0.0));
        let frame = StationFrame::try_from_origin_and_normal(Point3::new(3.0, 2.0, 0.2), &normal).unwrap();
        let section = cut_mesh(&tube, &frame, "torque-tube").unwrap();
        assert_eq!(section.polygons.len(), 1);
        let polygon = &section.polygons[0];
        let semi_x = radius / angle.cos();
        // Every point lies between the inscribed polygon and the ellipse; points on the
        // tube's generators lie on the ellipse itself.
        let rho: Vec<f64> = polygon
            .iter()
            .map(|p| ((p.x / semi_x).powi(2) + (p.y / radius).powi(2)).sqrt())
            .collect();
        let floor = (std::f64::consts::PI / segments as f64).cos();
        for r in &rho {
            assert!(*r > floor - 1e-12 && *r < 1.0 + 1e-12, "rho {r}");
        }
        assert_relative_eq!(rho.iter().copied().fold(0.0, f64::max), 1.0, epsilon = 1e-12);
        // Area of the inscribed 256-gon mapped to the ellipse: (n/2) sin(2π/n) r (r/cos).
        let expected_area =
            0.5 * segments as f64 * (2.0 * std::f64::consts::PI / segments as f64).sin() * radius * semi_x;
        assert_relative_eq!(signed_area_m2(polygon), expected_area, max_relative = 1e-9);
        let max_x = polygon.iter().map(|p| p.x.abs()).fold(0.0, f64::max);
        assert_relative_eq!(max_x, semi_x, max_relative = 1e-12);
    }
}

#[test]
fn perpendicular_cut_of_an_airfoil_prism_reproduces_the_polygon() {
    let chord = 1.3;
    let airfoil: Vec<Point2<f64>> = naca4(0.02, 0.4, 0.12, 60)
        .iter()
        .map(|p| Point2::new(p.x * chord, p.y * chord))
        .collect();
    let leading_edge = Point3::new(2.0, 0.5, 0.1);
    // Extruded along y with a ring at y = 1.5: the cut at y = 1.5 goes exactly through
    // ring vertices (vertices on the plane); the cut at y = 1.2 crosses edges.
    let wing = prism(
        &airfoil,
        leading_edge,
        Vector3::x(),
        Vector3::z(),
        Vector3::y(),
        &[0.0, 1.0, 2.0],
    );
    for y in [1.5, 1.2] {
        let frame = StationFrame::try_from_origin_and_normal(
            Point3::new(leading_edge.x, y, leading_edge.z),
            &Vector3::y_axis(),
        )
        .unwrap();
        let section = cut_mesh(&wing, &frame, "wing").unwrap();
        assert_eq!(section.polygons.len(), 1);
        // Station x points to the nose: station point = (-x_aft, z).
        let expected: Vec<Point2<f64>> = airfoil.iter().map(|p| Point2::new(-p.x, p.y)).collect();
        let cut = &section.polygons[0];
        let expected_polygon = vec![expected.clone()];
        let to_cut = boundary_deviation(&section.polygons, &expected).unwrap();
        let to_expected = boundary_deviation(&expected_polygon, cut).unwrap();
        assert!(to_cut.max_m < 1e-12, "airfoil points off the cut by {} m", to_cut.max_m);
        assert!(
            to_expected.max_m < 1e-12,
            "cut points off the airfoil by {} m",
            to_expected.max_m
        );
        assert_relative_eq!(
            signed_area_m2(cut).abs(),
            signed_area_m2(&expected).abs(),
            max_relative = 1e-12
        );
        if y == 1.5 {
            // Through vertices: exactly the airfoil points, duplicates merged.
            assert_eq!(cut.len(), expected.len());
        }
    }
}

#[test]
fn cut_missing_the_mesh_is_empty_and_bad_indices_are_errors() {
    let tube = prism(
        &circle(0.02, 16),
        Point3::origin(),
        Vector3::z(),
        Vector3::x(),
        Vector3::y(),
        &[0.0, 1.0],
    );
    let frame = StationFrame::try_from_origin_and_normal(Point3::new(0.0, 5.0, 0.0), &Vector3::y_axis()).unwrap();
    assert!(cut_mesh(&tube, &frame, "tube").unwrap().polygons.is_empty());
    let mut broken = tube.clone();
    broken.triangles.push([0, 1, 999]);
    assert!(cut_mesh(&broken, &frame, "tube").is_err());
    // An open mesh (one side triangle removed) does not close where the plane crosses it.
    let mut open = tube;
    open.triangles.remove(0);
    let frame = StationFrame::try_from_origin_and_normal(Point3::new(0.0, 0.5, 0.0), &Vector3::y_axis()).unwrap();
    assert!(cut_mesh(&open, &frame, "tube").is_err());
}
