//! Surface meshes and mass properties of the solids the check uses, against analytic
//! volumes and inertias.

use approx::assert_relative_eq;
use flapwright_geom::{tube_mesh, CollisionShape};
use nalgebra::{Matrix3, Point3};
use std::f64::consts::PI;

const STEEL_KG_M3: f64 = 7850.0;

#[test]
fn capsule_mass_properties_are_the_cylinder_and_ball_analytic() {
    let (r, h) = (0.02, 0.3);
    let capsule = CollisionShape::capsule(Point3::new(0.0, -h / 2.0, 0.0), Point3::new(0.0, h / 2.0, 0.0), r).unwrap();
    let properties = capsule.compute_mass_properties(STEEL_KG_M3).unwrap();
    // Cylinder plus two half balls (axis y).
    let (m_cyl, m_ball) = (STEEL_KG_M3 * PI * r * r * h, STEEL_KG_M3 * 4.0 / 3.0 * PI * r.powi(3));
    assert_relative_eq!(properties.mass_kg, m_cyl + m_ball, max_relative = 1e-12);
    let axial = m_cyl * r * r / 2.0 + m_ball * 2.0 / 5.0 * r * r;
    // Each half ball's centroid sits 3r/8 from its flat face, which sits h/2 from the centre.
    let half_ball_own = 2.0 / 5.0 * (m_ball / 2.0) * r * r - (m_ball / 2.0) * (3.0 * r / 8.0).powi(2);
    let half_ball = half_ball_own + (m_ball / 2.0) * (h / 2.0 + 3.0 * r / 8.0).powi(2);
    let transverse = m_cyl * (3.0 * r * r + h * h) / 12.0 + 2.0 * half_ball;
    assert_relative_eq!(
        properties.inertia_kg_m2,
        Matrix3::from_diagonal(&nalgebra::Vector3::new(transverse, axial, transverse)),
        max_relative = 1e-9
    );
    assert_relative_eq!(properties.centre_of_mass, Point3::origin(), epsilon = 1e-15);
}

#[test]
fn a_primitive_surface_mesh_is_closed_and_holds_nearly_its_volume() {
    let capsule = CollisionShape::capsule(Point3::new(0.1, 0.0, 0.0), Point3::new(0.4, 0.2, 0.0), 0.03).unwrap();
    let mesh = capsule.compute_surface_mesh();
    assert!(mesh.compute_topology_check().is_watertight());
    let exact = PI * 0.03f64.powi(2) * (0.3f64.hypot(0.2)) + 4.0 / 3.0 * PI * 0.03f64.powi(3);
    let volume = mesh.compute_signed_volume();
    // Inscribed tessellation of 32 sides: a little under the true solid, never over.
    assert!(volume < exact && volume > 0.98 * exact, "{volume} against {exact}");
    let ball = CollisionShape::ball(0.05).unwrap().compute_surface_mesh();
    assert!(ball.compute_topology_check().is_watertight());
    assert!(ball.vertices.iter().all(|v| (v.coords.norm() - 0.05).abs() < 1e-15));
}

#[test]
fn a_tube_mesh_weighs_what_its_polygon_prism_weighs() {
    let (r, length) = (0.01, 0.5);
    let sides = 16;
    let mesh = tube_mesh(&[Point3::origin(), Point3::new(length, 0.0, 0.0)], r, sides, 0.04).unwrap();
    let shape = CollisionShape::from_mesh(&mesh).unwrap();
    let properties = shape.compute_mass_properties(STEEL_KG_M3).unwrap();
    // A regular 16-gon of circumradius r: area n r^2 sin(2 pi / n) / 2.
    let area = sides as f64 * r * r * (2.0 * PI / sides as f64).sin() / 2.0;
    let mass = STEEL_KG_M3 * area * length;
    assert_relative_eq!(properties.mass_kg, mass, max_relative = 1e-9);
    assert_relative_eq!(
        properties.centre_of_mass,
        Point3::new(length / 2.0, 0.0, 0.0),
        epsilon = 1e-12
    );
    // Transverse moment of a slender prism: m L^2 / 12 plus the section's, within 1 %.
    let transverse = mass * length * length / 12.0 + mass * r * r / 4.0;
    assert_relative_eq!(properties.inertia_kg_m2[(1, 1)], transverse, max_relative = 1e-2);
    let open = CollisionShape::from_surface(&mesh).unwrap();
    assert!(open.compute_mass_properties(STEEL_KG_M3).is_none());
}
