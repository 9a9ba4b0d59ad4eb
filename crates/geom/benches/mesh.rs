//! Building every part mesh of the representative wing (wing skin with two flap coves, two
//! flaps, two spars, torque tube) at a few resolutions, and the mesh-against-mesh distance
//! of a flap nested in its cove, and the penetration depth of a screw through the torque
//! tube at a few surface-grid spacings. Run:
//! `cargo bench -p flapwright-geom --bench mesh`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use flapwright_geom::{compute_clearance, compute_distance, CollisionShape, MeshResolution};
use nalgebra::Point3;
use nalgebra::{Isometry3, Translation3, UnitQuaternion};

#[path = "../tests/fixture.rs"]
mod fixture;

fn build_parts(c: &mut Criterion) {
    let model = fixture::model();
    let mut group = c.benchmark_group("compute_parts");
    for points_per_side in [30, 60, 120] {
        let resolution = MeshResolution {
            points_per_side,
            spanwise_stations_per_m: 4.0,
            tube_segments: 24,
        };
        group.bench_with_input(BenchmarkId::from_parameter(points_per_side), &resolution, |b, r| {
            b.iter(|| model.compute_parts(*r).unwrap());
        });
    }
    group.finish();
    let parts = model.compute_parts(MeshResolution::default()).unwrap();
    c.bench_function("collision_shape_from_wing_mesh", |b| {
        b.iter(|| CollisionShape::from_mesh(&parts[0].mesh).unwrap())
    });

    let flap = &model.flaps()[0];
    let (hinge_point, hinge_direction) = flap.hinge_axis_ac();
    let shape_of = |name: &str| {
        let part = parts.iter().find(|p| p.name == name).unwrap();
        CollisionShape::from_mesh(&part.mesh).unwrap()
    };
    let (flap_shape, wing_shape) = (shape_of(&flap.spec().name), shape_of("wing"));
    let turn = UnitQuaternion::from_axis_angle(&hinge_direction, 5f64.to_radians());
    let pose = Translation3::from(hinge_point.coords) * turn * Translation3::from(-hinge_point.coords);
    c.bench_function("distance_flap_to_wing_skin_nested", |b| {
        b.iter(|| compute_distance(&flap_shape, &pose, &wing_shape, &Isometry3::identity()).unwrap())
    });
    // The same query through parry's composite-against-composite distance, for comparison.
    let parry_mesh = |name: &str| {
        let part = parts.iter().find(|p| p.name == name).unwrap();
        let vertices = part
            .mesh
            .vertices
            .iter()
            .map(|p| glamx::DVec3::new(p.x, p.y, p.z))
            .collect();
        parry3d_f64::shape::TriMesh::new(vertices, part.mesh.triangles.clone()).unwrap()
    };
    let (flap_mesh, wing_mesh) = (parry_mesh(&flap.spec().name), parry_mesh("wing"));
    let parry_pose = parry3d_f64::math::Pose::from(pose);
    c.bench_function("clearance_flap_to_wing_skin_nested", |b| {
        b.iter(|| compute_clearance(&flap_shape, &pose, &wing_shape, &Isometry3::identity(), 1e-3).unwrap())
    });

    // A screw (capsule, r = 8 mm) straight through the torque tube's axis at its bend
    // (the fixture's middle path point, 2.5 m outboard, where a ring of vertices sits).
    let tube = parts.iter().find(|p| p.name == "torque-tube").unwrap();
    let ring: Vec<&Point3<f64>> = tube.mesh.vertices.iter().filter(|v| (v.y - 2.5).abs() < 0.05).collect();
    let centre = ring.iter().fold(Point3::origin(), |sum, v| sum + v.coords) / ring.len() as f64;
    let screw = CollisionShape::capsule(
        centre - nalgebra::Vector3::z() * 0.1,
        centre + nalgebra::Vector3::z() * 0.1,
        0.008,
    )
    .unwrap();
    let tube_shape = CollisionShape::from_mesh(&tube.mesh).unwrap();
    let mut group = c.benchmark_group("penetration_screw_through_tube");
    for spacing_mm in [4.0, 1.0, 0.25] {
        let depth = compute_clearance(
            &screw,
            &Isometry3::identity(),
            &tube_shape,
            &Isometry3::identity(),
            spacing_mm * 1e-3,
        )
        .unwrap()
        .penetration_m;
        eprintln!("penetration at {spacing_mm} mm spacing: {:.4} mm", depth * 1e3);
        group.bench_with_input(BenchmarkId::from_parameter(spacing_mm), &spacing_mm, |b, h| {
            b.iter(|| {
                compute_clearance(
                    &screw,
                    &Isometry3::identity(),
                    &tube_shape,
                    &Isometry3::identity(),
                    h * 1e-3,
                )
                .unwrap()
            })
        });
    }
    group.finish();
    c.bench_function("distance_flap_to_wing_skin_nested_parry_query", |b| {
        b.iter(|| {
            parry3d_f64::query::distance(&parry_pose, &flap_mesh, &parry3d_f64::math::Pose::IDENTITY, &wing_mesh)
                .unwrap()
        })
    });
}

#[allow(missing_docs)] // criterion_group! generates an undocumented function
mod group {
    use super::*;
    criterion_group!(benches, build_parts);
}
use group::benches;
criterion_main!(benches);
