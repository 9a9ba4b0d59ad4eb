//! The stiff motor + five-bar deployment of `001_...` (L = 1e-6 H, R = 2 Ω: L/R = 5e-7 s)
//! at the default BDF rtol 1e-6 (issue 16: <= 1 ms on the project's 2-core machine), and
//! the same with the explicit Tsit45 on the non-stiff motor (L = 1e-3 H) for comparison;
//! and a kind without an equation of its own, the thesis circular-arc track, deployed as a
//! rigid flap (`flapwright_mechanism::rigid_flap`: its inertia and force from differences of
//! the kind's poses and its statics at every evaluation).
// criterion_group! generates undocumented public functions.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use flapwright_dynamics::{integrate, required_drive, Drive, Integration, Method, SmoothStart, SupplyVoltage};
use flapwright_dynamics::{DcMotor, Gearbox};
use flapwright_kinds::{CircularArcTrack, CircularArcTrackSpec, LoadedFiveBar};
use flapwright_mechanism::seam::FlapMechanism;
use flapwright_mechanism::{LoadCase, RigidFlapDynamics};

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

fn rigid_flap_deployment(c: &mut Criterion) {
    let track = CircularArcTrack::synthesise(CircularArcTrackSpec::thesis_case_study()).expect("synthesises");
    let mass = track.flap_mass().expect("the track gives its flap's mass");
    // ASSUMPTION (a bench, not a design): the default scene's flap inertia and its e2e
    // test's motor, directly on the screw.
    let system = RigidFlapDynamics::new(&track, mass, 0.18, &LoadCase::thesis_landing()).expect("models");
    let drive = Drive {
        motor: DcMotor {
            resistance_ohm: 0.5,
            inductance_h: 1e-3,
            torque_constant_nm_per_a: 0.1,
            rotor_inertia_kgm2: 0.0,
        },
        gearbox: Gearbox {
            ratio: 1.0,
            efficiency: 1.0,
        },
    };
    let supply = SupplyVoltage {
        volts: 28.0,
        rise_time_s: 0.05,
    };
    let run = integrate(&system, &drive, &supply, &Integration::default()).expect("integrates");
    assert!(
        run.deployment_time_s.is_some(),
        "the bench's motor deploys the thesis flap"
    );
    c.bench_function("deployment/rigid flap (thesis track), bdf rtol 1e-6", |b| {
        b.iter(|| integrate(&system, &drive, &supply, &Integration::default()).expect("integrates"))
    });
}

criterion_group!(benches, deployment, rigid_flap_deployment);
criterion_main!(benches);
