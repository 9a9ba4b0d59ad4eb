//! The trade study of the four kinds at one station (issue 15's benchmark:
//! `flapwright study data/scenes/transport-flap.toml --station ob-outer`), end to end
//! without the process start: for each of dropped hinge, four-bar, link-track and
//! hooked-track, the variant scene, geometry, meshing, planes, synthesis, gap and overlap,
//! the certified interference check, fairing, kinematics, sizing and the kind's report,
//! then `study.json` and the charts. Figures in BENCHMARKS.md.

use std::path::Path;

use criterion::{criterion_main, Criterion};
use flapwright::study::{self, DEFAULT_KINDS};
use flapwright::MemorySink;

fn study_one_station(c: &mut Criterion) {
    let scene_dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/scenes");
    let text = std::fs::read_to_string(scene_dir.join("transport-flap.toml")).expect("the transport scene");
    let files = flapwright::scene::Folder::new(&scene_dir);
    let scene = flapwright::scene::Scene::from_file_text(&text, "transport-flap.toml", &files)
        .expect("the transport scene is valid");
    let kinds: Vec<String> = DEFAULT_KINDS.iter().map(|k| k.to_string()).collect();
    let stations = ["ob-outer".to_string()];
    let mut group = c.benchmark_group("study");
    // Seconds an iteration: criterion's smallest sample.
    group.sample_size(10);
    group.bench_function("four kinds at ob-outer of transport-flap", |b| {
        b.iter(|| {
            let written = MemorySink::new();
            study::run(
                &scene,
                &text,
                &files,
                "transport-flap.toml",
                &kinds,
                &stations,
                &written,
            )
            .expect("the study runs")
        })
    });
    group.finish();
}

#[allow(missing_docs)] // criterion_group! generates an undocumented function
mod group {
    criterion::criterion_group!(benches, super::study_one_station);
}
use group::benches;
criterion_main!(benches);
