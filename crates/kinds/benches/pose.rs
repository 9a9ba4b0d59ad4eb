//! One pose (position, velocity, acceleration, forces) of the thesis screw-jack track, and a
//! 1000-sample deployment sweep, full and lean; and a 1000-sample sweep of the `001_...` five-bar double
//! flap's positions and rates (issue 16: <= 0.2 ms).
// criterion_group! generates undocumented public functions.
#![allow(missing_docs)]

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use flapwright_kinds::{CircularArcTrack, CircularArcTrackSpec, FiveBarDoubleFlap};
use flapwright_mechanism::LoadCase;

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
    // The same deployment's 21 columns of `../shared/bench/thesis_sweep_numpy.py` (issue 39):
    // positions, rates, accelerations, F_input and the screw torques.
    c.bench_function("lean_sweep_1000", |b| {
        b.iter(|| track.lean_sweep(black_box(1000), &landing).expect("sweeps"))
    });
}

fn five_bar_sweep(c: &mut Criterion) {
    let five_bar = FiveBarDoubleFlap::polimi_case_study().expect("assembles");
    let (from, to) = (five_bar.stowed_crank_rad, five_bar.deployed_crank_rad);
    c.bench_function("five_bar_sweep_1000_to_third_order", |b| {
        b.iter(|| {
            let mut secondary_jerk_sum = 0.0;
            for i in 0..1000 {
                let alpha = from + (to - from) * i as f64 / 999.0;
                secondary_jerk_sum += five_bar.pose(black_box(alpha)).expect("poses").secondary_deflection.d3;
            }
            secondary_jerk_sum
        })
    });
    c.bench_function("five_bar_sweep_1000", |b| {
        b.iter(|| {
            let mut secondary_rate_sum = 0.0;
            for i in 0..1000 {
                let alpha = from + (to - from) * i as f64 / 999.0;
                let pose = five_bar.pose_and_rates(black_box(alpha)).expect("poses");
                secondary_rate_sum += pose.secondary_deflection.d1;
            }
            secondary_rate_sum
        })
    });
}

criterion_group!(benches, pose_and_sweep, five_bar_sweep);
criterion_main!(benches);
