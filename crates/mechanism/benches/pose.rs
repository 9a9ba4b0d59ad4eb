//! One pose (position, velocity, acceleration, forces) of the thesis screw-jack track, and a
//! 1000-sample deployment sweep.
// criterion_group! generates undocumented public functions.
#![allow(missing_docs)]

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use flapwright_mechanism::{CircularArcTrack, CircularArcTrackSpec, LoadCase};

fn pose_and_sweep(c: &mut Criterion) {
    let track =
        CircularArcTrack::synthesise(CircularArcTrackSpec::thesis_case_study()).expect("thesis case synthesises");
    let landing = LoadCase::thesis_landing();
    let input = 0.5 * (track.synthesis().stroke_start_m + track.synthesis().stroke_end_m);
    c.bench_function("pose_with_forces", |b| {
        b.iter(|| {
            let pose = track.pose(black_box(input), 0.035, 0.0).expect("poses");
            track.forces(&pose, &landing).expect("forces")
        })
    });
    c.bench_function("sweep_1000", |b| {
        b.iter(|| track.sweep(black_box(1000), &landing).expect("sweeps"))
    });
}

criterion_group!(benches, pose_and_sweep);
criterion_main!(benches);
