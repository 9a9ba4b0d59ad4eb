//! The kinds synthesised from flap settings on the model section of the tests: a four-bar
//! pose in closed form (issue target <= 100 ns), and the synthesis of one station with its
//! free-choice search (<= 50 ms), and of a dropped hinge.
// criterion_group! generates undocumented public functions.
#![allow(missing_docs)]

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use flapwright_kinds::{DroppedHinge, FourBar};
use flapwright_mechanism::seam::FlapMechanism;

#[path = "../tests/model_section.rs"]
#[allow(dead_code)]
mod model_section;

fn synthesised(c: &mut Criterion) {
    let four_bar = FourBar::synthesise(model_section::four_bar_spec()).expect("synthesises");
    let middle = 0.5 * four_bar.synthesis().crank_rotation_rad[1];
    c.bench_function("four_bar_flap_at_crank_angle", |b| {
        b.iter(|| four_bar.flap_at_crank_angle(black_box(middle)))
    });
    let range = four_bar.input_range();
    let input = 0.5 * (range.stowed + range.deployed);
    c.bench_function("four_bar_pose_at_stroke", |b| {
        b.iter(|| four_bar.pose(black_box(input)))
    });
    c.bench_function("four_bar_synthesis_with_search", |b| {
        b.iter(|| FourBar::synthesise(black_box(model_section::four_bar_spec())))
    });
    c.bench_function("dropped_hinge_synthesis", |b| {
        b.iter(|| DroppedHinge::synthesise(black_box(model_section::dropped_hinge_spec())))
    });
}

criterion_group!(benches, synthesised);
criterion_main!(benches);
