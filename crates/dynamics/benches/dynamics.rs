//! The stiff motor + five-bar deployment of `001_...` (L = 1e-6 H, R = 2 Ω: L/R = 5e-7 s)
//! at the default BDF rtol 1e-6 (issue 16: <= 1 ms on the project's 2-core machine), and
//! the same with the explicit Tsit45 on the non-stiff motor (L = 1e-3 H) for comparison.
// criterion_group! generates undocumented public functions.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use flapwright_dynamics::{integrate, required_drive, Drive, Integration, Method, SmoothStart, SupplyVoltage};
use flapwright_mechanism::LoadedFiveBar;

fn deployment(c: &mut Criterion) {
    let system = LoadedFiveBar::polimi_case_study().expect("assembles");
    let law = SmoothStart {
        rate_radps: 1.0,
        smoothing_per_s: 20.0,
    };
    let required = required_drive(&system, &Drive::polimi_case_study(1e-3), &law, 201).expect("required drive");
    let supply = SupplyVoltage {
        volts: required.iter().map(|s| s.voltage_v).fold(0.0, f64::max),
        rise_time_s: 0.05,
    };
    let stiff = Drive::polimi_case_study(1e-6);
    c.bench_function("deployment/bdf rtol 1e-6, L = 1e-6 H", |b| {
        b.iter(|| integrate(&system, &stiff, &supply, &Integration::default()).expect("integrates"))
    });
    let soft = Drive::polimi_case_study(1e-3);
    let explicit = Integration {
        method: Method::Tsit45,
        ..Integration::default()
    };
    c.bench_function("deployment/tsit45 rtol 1e-6, L = 1e-3 H", |b| {
        b.iter(|| integrate(&system, &soft, &supply, &explicit).expect("integrates"))
    });
}

criterion_group!(benches, deployment);
criterion_main!(benches);
