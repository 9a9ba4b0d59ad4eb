//! `compute_clearance`: parts as solids, and how deep overlapping parts reach into each
//! other, against analytic depths.

use std::f64::consts::PI;

use approx::assert_relative_eq;
use flapwright_geom::{compute_clearance, compute_distance, CollisionShape, TriMesh};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion};

fn at(x: f64, y: f64, z: f64) -> Isometry3<f64> {
    Isometry3::from_parts(Translation3::new(x, y, z), UnitQuaternion::identity())
}

/// Closed, outward prism: a regular `n`-gon of circumradius `radius` about the y axis,
/// from y = -`half_length` to +`half_length`, capped by fans.
fn prism(n: usize, radius: f64, half_length: f64) -> TriMesh {
    let mut vertices = Vec::new();
    for y in [-half_length, half_length] {
        for k in 0..n {
            let angle = 2.0 * PI * k as f64 / n as f64;
            vertices.push(Point3::new(radius * angle.cos(), y, radius * angle.sin()));
        }
    }
    vertices.push(Point3::new(0.0, -half_length, 0.0));
    vertices.push(Point3::new(0.0, half_length, 0.0));
    let (low, high) = (2 * n, 2 * n + 1);
    let mut triangles = Vec::new();
    for k in 0..n {
        let next = (k + 1) % n;
        let (a, b, c, d) = (k, next, n + k, n + next);
        triangles.push([a as u32, c as u32, b as u32]);
        triangles.push([b as u32, c as u32, d as u32]);
        triangles.push([low as u32, a as u32, b as u32]);
        triangles.push([high as u32, d as u32, c as u32]);
    }
    TriMesh { vertices, triangles }
}

#[test]
fn prism_helper_is_closed_and_outward() {
    let mesh = prism(16, 0.02, 0.5);
    assert!(mesh.compute_topology_check().is_watertight());
    let area = 0.5 * 16.0 * 0.02f64.powi(2) * (2.0 * PI / 16.0).sin();
    assert_relative_eq!(mesh.compute_signed_volume(), area * 1.0, max_relative = 1e-12);
}

#[test]
fn clear_shapes_match_the_surface_distance() {
    let (a, b) = (CollisionShape::ball(0.5).unwrap(), CollisionShape::ball(0.25).unwrap());
    let clearance = compute_clearance(&a, &at(0.0, 0.0, 0.0), &b, &at(1.0, 0.0, 0.0), 1e-3).unwrap();
    let distance = compute_distance(&a, &at(0.0, 0.0, 0.0), &b, &at(1.0, 0.0, 0.0)).unwrap();
    assert_relative_eq!(clearance.distance_m, 0.25, max_relative = 1e-12);
    assert_eq!(clearance.point_a_ac, distance.point_a_ac);
    assert_eq!(
        (clearance.penetration_m, clearance.penetration_resolution_m),
        (0.0, 0.0)
    );
    assert_eq!(clearance.signed_m(), 0.25);
}

/// Two unit balls 1.5 apart: the deepest point of either surface inside the other is the
/// pole facing it, 0.5 deep (which is also the distance they must move apart).
#[test]
fn overlapping_balls_report_the_analytic_depth() {
    let ball = CollisionShape::ball(1.0).unwrap();
    let h = 1e-2;
    let clearance = compute_clearance(&ball, &at(0.0, 0.0, 0.0), &ball, &at(1.5, 0.0, 0.0), h).unwrap();
    assert_eq!(clearance.distance_m, 0.0);
    // Sampled depth is a lower bound, within the grid spacing (stretched by under 1 % where
    // the tessellation's grid is projected onto the sphere).
    assert!(clearance.penetration_m <= 0.5 + 1e-9, "{}", clearance.penetration_m);
    assert!(clearance.penetration_m >= 0.5 - 1.01 * h, "{}", clearance.penetration_m);
    assert_eq!(clearance.penetration_resolution_m, h);
    assert_relative_eq!(clearance.signed_m(), -clearance.penetration_m);
    let gap = (clearance.point_a_ac - clearance.point_b_ac).norm();
    assert_relative_eq!(gap, clearance.penetration_m, max_relative = 1e-9);
}

/// A ball wholly inside a cube mesh: the surface distance is positive, the solids overlap.
/// Deepest ball point: along a cube diagonal from the centre, 0.5 - 0.2/sqrt(3) deep.
#[test]
fn a_ball_inside_a_closed_mesh_overlaps() {
    let cube = CollisionShape::from_mesh(&prism(4, 0.5f64.sqrt(), 0.5)).unwrap();
    // The square prism's faces are at |x| = |z| = 0.5 once turned 45 degrees about y.
    let turned = Isometry3::from_parts(
        Translation3::identity(),
        UnitQuaternion::from_axis_angle(&nalgebra::Vector3::y_axis(), PI / 4.0),
    );
    let ball = CollisionShape::ball(0.2).unwrap();
    let surfaces = compute_distance(&cube, &turned, &ball, &at(0.0, 0.0, 0.0)).unwrap();
    assert_relative_eq!(surfaces.distance_m, 0.3, max_relative = 1e-9);
    let h = 2e-3;
    let clearance = compute_clearance(&cube, &turned, &ball, &at(0.0, 0.0, 0.0), h).unwrap();
    assert_eq!(clearance.distance_m, 0.0);
    let expected = 0.5 - 0.2 / 3f64.sqrt();
    assert!(
        clearance.penetration_m <= expected + 1e-9,
        "{}",
        clearance.penetration_m
    );
    assert!(
        clearance.penetration_m >= expected - 1.01 * h,
        "{}",
        clearance.penetration_m
    );
    // b (the ball) intrudes: its end of the penetration is inside the cube.
    assert!(cube.contains_point(&turned, &clearance.point_b_ac));
}

/// A screw (capsule) through a torque tube (16-gon prism of circumradius R): the screw's
/// surface crosses the tube's axis, where the depth is the prism's inradius R cos(pi/16).
#[test]
fn a_capsule_through_a_tube_reaches_its_inradius() {
    let radius = 0.02;
    let tube = CollisionShape::from_mesh(&prism(16, radius, 0.5)).unwrap();
    let screw = CollisionShape::capsule(Point3::new(-0.15, 0.1, 0.0), Point3::new(0.15, 0.1, 0.0), 0.008).unwrap();
    let h = 1e-3;
    let clearance = compute_clearance(&screw, &at(0.0, 0.0, 0.0), &tube, &at(0.0, 0.0, 0.0), h).unwrap();
    let expected = radius * (PI / 16.0).cos();
    assert_eq!(clearance.distance_m, 0.0);
    assert!(
        clearance.penetration_m <= expected + 1e-9,
        "{}",
        clearance.penetration_m
    );
    assert!(clearance.penetration_m >= expected - h, "{}", clearance.penetration_m);
    // The deepest screw point is on the tube's axis.
    let deepest = clearance.point_a_ac;
    assert!(deepest.x.hypot(deepest.z) <= h, "{deepest}");
}

/// A large overlap at a fine requested resolution: the grid coarsens to the sample budget
/// and says so, and the depth is still within the spacing it reports.
#[test]
fn a_large_overlap_coarsens_the_grid_and_reports_it() {
    let big = CollisionShape::from_mesh(&prism(64, 1.0, 1.0)).unwrap();
    let h = 1e-4;
    let clearance = compute_clearance(&big, &at(0.0, 0.0, 0.0), &big, &at(0.5, 0.0, 0.0), h).unwrap();
    assert!(clearance.penetration_resolution_m > h);
    // Two unit cylinders 0.5 apart, same ends: a lateral point (cos t, y, sin t) of one is
    // 1 - sqrt(1.25 - cos t) inside the other, deepest at t = 0: 0.5, less the 64-gon's
    // faceting (1 - cos(pi/64)).
    let faceting = 1.0 - (PI / 64.0).cos();
    assert!(clearance.penetration_m <= 0.5 + 1e-9, "{}", clearance.penetration_m);
    assert!(
        clearance.penetration_m >= 0.5 - faceting - clearance.penetration_resolution_m,
        "{} at spacing {}",
        clearance.penetration_m,
        clearance.penetration_resolution_m
    );
    assert!(compute_clearance(&big, &at(0.0, 0.0, 0.0), &big, &at(0.5, 0.0, 0.0), 0.0).is_err());
}

#[test]
fn an_open_surface_holds_nothing_and_is_crossed_or_cleared() {
    // A prism of circumradius 0.2 as a solid holds a small ball at its centre; as a sheet
    // it does not, and the ball is 0.2 cos(pi/16) - 0.01 from its nearest face.
    let mesh = prism(16, 0.2, 0.5);
    let (solid, sheet) = (
        CollisionShape::from_mesh(&mesh).unwrap(),
        CollisionShape::from_surface(&mesh).unwrap(),
    );
    assert!(solid.is_solid() && !sheet.is_solid());
    let ball = CollisionShape::ball(0.01).unwrap();
    let origin = at(0.0, 0.0, 0.0);
    let inside_solid = compute_clearance(&solid, &origin, &ball, &origin, 1e-3).unwrap();
    assert_eq!(inside_solid.distance_m, 0.0);
    let inside_sheet = compute_clearance(&sheet, &origin, &ball, &origin, 1e-3).unwrap();
    assert_relative_eq!(
        inside_sheet.distance_m,
        0.2 * (PI / 16.0).cos() - 0.01,
        max_relative = 1e-9
    );
    // A ball of radius 0.05 centred on the wall (x = 0.2 cos(pi/16) at the face's middle,
    // z = 0): it crosses the sheet, which reaches 0.05 deep into it (its centre lies on
    // the face).
    let wall_x = 0.2 * (PI / 16.0).cos();
    let big = CollisionShape::ball(0.05).unwrap();
    let rotated = Isometry3::from_parts(
        Translation3::new(0.0, 0.0, 0.0),
        UnitQuaternion::from_axis_angle(&nalgebra::Vector3::y_axis(), PI / 16.0),
    );
    let crossing = compute_clearance(&sheet, &rotated, &big, &at(wall_x, 0.0, 0.0), 1e-3).unwrap();
    assert_eq!(crossing.distance_m, 0.0);
    assert!(
        crossing.penetration_m > 0.05 - 2e-3 && crossing.penetration_m <= 0.05 + 1e-9,
        "{}",
        crossing.penetration_m
    );
}
