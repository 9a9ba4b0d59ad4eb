//! The default scene's interference check (`flapwright check`), end to end without the
//! process start: geometry, meshing, planes, interference sweep, fairing depth.

use criterion::{criterion_main, Criterion};
use flapwright::output::StagedDir;
use flapwright::pipeline::{design, Inputs, Mode};
use flapwright::scene::{Scene, DEFAULT_SCENE_TOML};

fn default_scene_check(c: &mut Criterion) {
    let scene = Scene::from_toml(DEFAULT_SCENE_TOML, None).expect("default scene");
    let dir = tempfile::tempdir().expect("temp dir");
    let inputs = Inputs {
        scene: &scene,
        scene_text: DEFAULT_SCENE_TOML,
        scene_dir: None,
    };
    let mut group = c.benchmark_group("check");
    group.sample_size(10);
    group.bench_function("default scene", |b| {
        b.iter(|| {
            let staged = StagedDir::create(&dir.path().join("out"), None, false).expect("staging");
            design(&inputs, Mode::Check, &staged).expect("check runs")
        })
    });
    group.bench_function("default scene, full design", |b| {
        b.iter(|| {
            let staged = StagedDir::create(&dir.path().join("out"), None, false).expect("staging");
            design(&inputs, Mode::Design, &staged).expect("design runs")
        })
    });
    group.finish();
}

#[allow(missing_docs)] // criterion_group! generates an undocumented function
mod group {
    criterion::criterion_group!(benches, super::default_scene_check);
}
use group::benches;
criterion_main!(benches);
