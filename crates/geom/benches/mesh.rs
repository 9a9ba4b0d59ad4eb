//! Building every part mesh of the representative wing (wing skin with two flap coves, two
//! flaps, two spars, torque tube) at a few resolutions. Run:
//! `cargo bench -p flapwright-geom --bench mesh`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use flapwright_geom::{CollisionShape, MeshResolution};

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
}

#[allow(missing_docs)] // criterion_group! generates an undocumented function
mod group {
    use super::*;
    criterion_group!(benches, build_parts);
}
use group::benches;
criterion_main!(benches);
