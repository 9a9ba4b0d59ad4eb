//! The default scene's interference check (`flapwright check`), end to end without the
//! process start: geometry, meshing, planes, interference sweep, fairing depth; against
//! the full design and `export --stl` (no check); and the same wing with 2 and 16 stations
//! spread along its flap, for how the check scales.

use criterion::{criterion_main, Criterion};
use flapwright::pipeline::{design, Inputs, Mode};
use flapwright::scene::{Scene, DEFAULT_SCENE_TOML};
use flapwright::MemorySink;

fn default_scene_check(c: &mut Criterion) {
    let scene = Scene::from_toml(DEFAULT_SCENE_TOML, &flapwright::scene::NoFiles).expect("default scene");
    let inputs = Inputs {
        scene: &scene,
        scene_text: DEFAULT_SCENE_TOML,
        files: &flapwright::scene::NoFiles,
        wing_cache: None,
    };
    let mut group = c.benchmark_group("check");
    group.sample_size(10);
    group.bench_function("default scene", |b| {
        b.iter(|| {
            let staged = MemorySink::new();
            design(&inputs, Mode::Check, &staged).expect("check runs")
        })
    });
    group.bench_function("default scene, full design", |b| {
        b.iter(|| {
            let staged = MemorySink::new();
            design(&inputs, Mode::Design, &staged).expect("design runs")
        })
    });
    // `flapwright export --stl`: the STL files need no check, sweep or sizing.
    let mut stl_only = scene.clone();
    let outputs = &mut stl_only.outputs;
    (
        outputs.urdf,
        outputs.svg,
        outputs.gltf,
        outputs.interference,
        outputs.kinematics,
        outputs.sizing,
    ) = (false, false, false, false, false, false);
    let stl_inputs = Inputs {
        scene: &stl_only,
        ..inputs
    };
    group.bench_function("default scene, export --stl", |b| {
        b.iter(|| {
            let staged = MemorySink::new();
            design(&stl_inputs, Mode::Export, &staged).expect("export runs")
        })
    });
    group.finish();
}

/// The default scene with `count` copies of its inner station spread evenly along the
/// flap between the two stations' places (axis offsets 0.35 to 1.90 m).
fn with_stations(count: usize) -> String {
    let text = DEFAULT_SCENE_TOML;
    let first = text.find("[[station]]").expect("a station");
    let second = first + 1 + text[first + 1..].find("[[station]]").expect("two stations");
    let loads = text.find("[loads]").expect("loads after the stations");
    let block = &text[first..second];
    let stations: String = (0..count)
        .map(|k| {
            let offset = 0.35 + (1.90 - 0.35) * k as f64 / (count - 1) as f64;
            block
                .replace("name = \"inner\"", &format!("name = \"s{k}\""))
                .replace("axis_offset_m = 0.35", &format!("axis_offset_m = {offset:.4}"))
        })
        .collect();
    format!("{}{stations}{}", &text[..first], &text[loads..])
}

fn stations_scaling(c: &mut Criterion) {
    let mut group = c.benchmark_group("check stations");
    group.sample_size(10);
    for count in [2, 16] {
        let text = with_stations(count);
        let scene = Scene::from_toml(&text, &flapwright::scene::NoFiles).expect("scene with stations");
        assert_eq!(scene.station.len(), count);
        let inputs = Inputs {
            scene: &scene,
            scene_text: &text,
            files: &flapwright::scene::NoFiles,
            wing_cache: None,
        };
        group.bench_function(format!("{count} stations"), |b| {
            b.iter(|| {
                let staged = MemorySink::new();
                design(&inputs, Mode::Check, &staged).expect("check runs")
            })
        });
    }
    group.finish();
}

#[allow(missing_docs)] // criterion_group! generates an undocumented function
mod group {
    criterion::criterion_group!(benches, super::default_scene_check, super::stations_scaling);
}
use group::benches;
criterion_main!(benches);
