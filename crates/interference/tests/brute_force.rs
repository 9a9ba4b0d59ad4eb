//! Mesh clearances from the sweep against an independent brute-force distance: every
//! vertex of each mesh to every triangle of the other (`flapwright_geom::reference`,
//! Ericson, Real-Time Collision Detection, 5.1.5), without parry.

use approx::assert_relative_eq;
use flapwright_geom::collision::CollisionShape;
use flapwright_geom::reference::closest_on_triangle;
use flapwright_geom::TriMesh;
use flapwright_interference::{sweep_pair, Motion, Part, SweepSettings};
use nalgebra::{Isometry3, Point3, UnitQuaternion, Vector3};

use crate::TurnAboutZ;

fn vertices_to_triangles(from: &TriMesh, to: &TriMesh) -> f64 {
    let mut best = f64::INFINITY;
    for p in &from.vertices {
        for t in &to.triangles {
            let [a, b, c] = t.map(|i| to.vertices[i as usize]);
            best = best.min((p - closest_on_triangle(p, &[a, b, c])).norm());
        }
    }
    best
}

/// Brute-force mesh-to-mesh distance (vertex-face both ways; exact when the closest
/// features are a vertex and a face, an upper bound otherwise).
pub fn brute_force_distance(a: &TriMesh, b: &TriMesh) -> f64 {
    vertices_to_triangles(a, b).min(vertices_to_triangles(b, a))
}

fn box_mesh(min: Point3<f64>, max: Point3<f64>) -> TriMesh {
    let corner = |i: usize| {
        Point3::new(
            if i & 1 == 0 { min.x } else { max.x },
            if i & 2 == 0 { min.y } else { max.y },
            if i & 4 == 0 { min.z } else { max.z },
        )
    };
    // Outward-wound faces of the unit-cube corner numbering (bit 0 = x, 1 = y, 2 = z).
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    TriMesh {
        vertices: (0..8).map(corner).collect(),
        triangles: quads
            .iter()
            .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
            .collect(),
    }
}

#[test]
fn box_mesh_helper_is_closed_and_outward() {
    let mesh = box_mesh(Point3::new(0.0, 0.0, 0.0), Point3::new(1.0, 2.0, 3.0));
    assert!(mesh.compute_topology_check().is_watertight());
    assert_relative_eq!(mesh.compute_signed_volume(), 6.0, max_relative = 1e-12);
}

#[test]
fn sweep_clearance_matches_brute_force_on_meshes() {
    // A 0.2 m cube, turned 45 deg so a corner leads, orbiting the z axis at radius 0.7 m,
    // against a slab whose face is at x = 1.0.
    let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_4);
    let cube_local = box_mesh(Point3::new(-0.1, -0.1, -0.1), Point3::new(0.1, 0.1, 0.1))
        .transformed(&Isometry3::from_parts(nalgebra::Translation3::new(0.7, 0.0, 0.0), turn));
    let slab = box_mesh(Point3::new(1.0, -1.0, -1.0), Point3::new(1.2, 1.0, 1.0));
    let motion = TurnAboutZ { max_radius_m: 0.85 };
    let moving = Part::moving(
        "cube",
        CollisionShape::from_mesh(&cube_local).unwrap(),
        TurnAboutZ { max_radius_m: 0.85 },
    );
    let fixed = Part::fixed("slab", CollisionShape::from_mesh(&slab).unwrap());
    let result = sweep_pair(&moving, &fixed, -0.5, 0.4, &SweepSettings::default()).unwrap();

    // At the reported parameter, the independent distance agrees.
    let posed = cube_local.transformed(&motion.pose_ac(result.at_parameter).unwrap());
    let brute = brute_force_distance(&posed, &slab);
    assert_relative_eq!(result.min_clearance_m, brute, epsilon = 1e-9);
    // The corner at radius 0.7 + 0.1 sqrt(2) reaches x = 0.8414 at t = 0: clearance 0.1586.
    assert_relative_eq!(result.min_clearance_m, 1.0 - (0.7 + 0.1 * 2f64.sqrt()), epsilon = 1e-3);

    // Dense brute-force sampling never undercuts the certified lower bound.
    let certified_floor = result.min_clearance_m - result.residual_bound_m;
    for i in 0..=400 {
        let t = -0.5 + 0.9 * f64::from(i) / 400.0;
        let d = brute_force_distance(&cube_local.transformed(&motion.pose_ac(t).unwrap()), &slab);
        assert!(
            d >= certified_floor - 1e-12,
            "t = {t}: brute force {d} < certified {certified_floor}"
        );
    }
}
