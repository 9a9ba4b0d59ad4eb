//! The `001_...` five-bar deployed by its DC motor: the required drive against finite
//! differences, the energy balance, the stiff motor from L = 1e-3 H to 1e-7 H, the explicit
//! method's step count, and the methods against each other.

use flapwright_dynamics::{
    integrate, required_drive, Drive, DynamicsRun, Error, Integration, Method, SmoothStart, SupplyVoltage,
    MAX_TIME_HISTORY_SAMPLES,
};
use flapwright_kinds::LoadedFiveBar;

fn five_bar() -> LoadedFiveBar {
    LoadedFiveBar::polimi_case_study().expect("the 001 data assembles")
}

/// The document's crank law: 1 rad/s after a smooth start (k = 20/s).
const LAW: SmoothStart = SmoothStart {
    rate_radps: 1.0,
    smoothing_per_s: 20.0,
};

/// The supply that holds the document's 1 rad/s at the largest required voltage.
fn supply(system: &LoadedFiveBar) -> SupplyVoltage {
    let required = required_drive(system, &Drive::polimi_case_study(1e-3), &LAW, 201).expect("required drive");
    SupplyVoltage {
        volts: required.iter().map(|s| s.voltage_v).fold(0.0, f64::max),
        rise_time_s: 0.05,
    }
}

fn run(system: &LoadedFiveBar, inductance_h: f64, settings: Integration) -> DynamicsRun {
    integrate(
        system,
        &Drive::polimi_case_study(inductance_h),
        &supply(system),
        &settings,
    )
    .expect("integrates")
}

#[test]
fn the_required_voltage_follows_the_current_by_finite_differences() {
    let system = five_bar();
    let drive = Drive::polimi_case_study(1e-2);
    let samples = required_drive(&system, &drive, &LAW, 2001).expect("required drive");
    let (r, l, k) = (2.0, 1e-2, 20.0);
    for window in samples.windows(3).step_by(97) {
        let (before, here, after) = (&window[0], &window[1], &window[2]);
        let current_rate = (after.current_a - before.current_a) / (after.time_s - before.time_s);
        let voltage = r * here.current_a + l * current_rate + k * here.rate;
        assert!(
            (voltage - here.voltage_v).abs() < 1e-4 * here.voltage_v.abs(),
            "t = {} s: {} V by differences, {} V analytic",
            here.time_s,
            voltage,
            here.voltage_v
        );
    }
    // At constant speed with the inductance neglected, the document's v = R T/K + K ω
    // (section 3.2).
    let without_inductance = required_drive(&system, &Drive::polimi_case_study(1e-9), &LAW, 11).expect("drive");
    let last = without_inductance.last().expect("samples");
    assert!((last.rate - 1.0).abs() < 1e-6);
    let static_voltage = r * last.motor_torque_nm / k + k * last.rate;
    assert!((static_voltage - last.voltage_v).abs() < 1e-3 * last.voltage_v);
}

#[test]
fn the_deployment_balances_its_energy_within_the_tolerance() {
    let system = five_bar();
    for relative_tolerance in [1e-4, 1e-6, 1e-8] {
        let settings = Integration {
            relative_tolerance,
            absolute_tolerance: relative_tolerance * 1e-2,
            ..Integration::default()
        };
        let deployment = run(&system, 1e-3, settings);
        let energy = deployment.energy;
        assert!(deployment.deployment_time_s.is_some(), "deploys");
        assert!(energy.supplied_j > 1e3 && energy.resistive_j > 0.0 && energy.load_work_j < 0.0);
        // The balance is a sum of integrated quantities, each held to the local tolerance
        // per step: the residual is allowed 10x the tolerance of the largest term.
        assert!(
            energy.residual_j.abs() < 10.0 * relative_tolerance * energy.supplied_j,
            "rtol {relative_tolerance:e}: residual {} J of {} J",
            energy.residual_j,
            energy.supplied_j
        );
    }
}

#[test]
fn bdf_finishes_without_step_collapse_as_the_armature_stiffens() {
    let system = five_bar();
    let mut times = Vec::new();
    for inductance_h in [1e-3, 1e-4, 1e-5, 1e-6, 1e-7] {
        let deployment = run(&system, inductance_h, Integration::default());
        let time = deployment.deployment_time_s.expect("deploys");
        // L/R spans 5e-4 s to 5e-8 s; the steps stay those the motion needs.
        assert!(
            deployment.counts.steps < 400,
            "L = {inductance_h:e} H: {:?}",
            deployment.counts
        );
        assert!(deployment.counts.jacobian_evaluations > 0);
        times.push(time);
    }
    // As L -> 0 the electrical lag vanishes: the deployment time converges.
    let spread = (times[3] - times[4]).abs();
    assert!(spread < 1e-4 * times[4], "{times:?}");
}

#[test]
fn the_explicit_method_needs_steps_in_proportion_to_r_over_l() {
    let system = five_bar();
    let explicit = |inductance_h: f64| {
        run(
            &system,
            inductance_h,
            Integration {
                method: Method::Tsit45,
                ..Integration::default()
            },
        )
    };
    let (stiff, stiffer) = (explicit(1e-4), explicit(1e-5));
    let bdf = run(&system, 1e-5, Integration::default());
    assert!(stiff.deployment_time_s.is_some() && stiffer.deployment_time_s.is_some());
    // Stability, not accuracy, sets the explicit step: ten times the stiffness, about ten
    // times the steps.
    let ratio = stiffer.counts.steps as f64 / stiff.counts.steps as f64;
    assert!(
        (6.0..14.0).contains(&ratio),
        "{:?} against {:?}",
        stiff.counts,
        stiffer.counts
    );
    assert!(stiffer.counts.steps > 40 * bdf.counts.steps);
    // And the step limit stops it cleanly on a stiffer motor.
    let limited = run(
        &system,
        1e-7,
        Integration {
            method: Method::Tsit45,
            max_steps: 2000,
            ..Integration::default()
        },
    );
    assert!(limited.hit_step_limit && limited.deployment_time_s.is_none());
}

#[test]
fn the_three_methods_agree_at_tight_tolerance() {
    let system = five_bar();
    let time = |method: Method| {
        run(
            &system,
            1e-3,
            Integration {
                method,
                relative_tolerance: 1e-9,
                absolute_tolerance: 1e-11,
                ..Integration::default()
            },
        )
        .deployment_time_s
        .expect("deploys")
    };
    let reference = time(Method::Tsit45);
    for method in [Method::Bdf, Method::Esdirk34] {
        let t = time(method);
        assert!(
            (t - reference).abs() < 1e-6 * reference,
            "{method:?}: {t} s against {reference} s"
        );
    }
}

#[test]
fn the_flap_waits_on_its_stop_until_the_motor_overcomes_the_loads() {
    let system = five_bar();
    let deployment = run(&system, 1e-3, Integration::default());
    let breakaway = deployment.breakaway_time_s;
    assert!(breakaway > 0.0);
    let held: Vec<_> = deployment.samples.iter().filter(|s| s.time_s < breakaway).collect();
    assert!(!held.is_empty());
    for sample in held {
        assert!(
            (sample.input - 275f64.to_radians()).abs() < 1e-12,
            "{}",
            sample.input - 275f64.to_radians()
        );
        assert!(sample.rate.abs() < 1e-12, "rate {} while held", sample.rate);
    }
    let first_moving = deployment
        .samples
        .iter()
        .find(|s| s.time_s > breakaway)
        .expect("moves after breakaway");
    assert!(first_moving.rate >= 0.0);
}

#[test]
fn parameters_out_of_range_are_named() {
    let system = five_bar();
    let mut drive = Drive::polimi_case_study(0.0);
    let error = integrate(&system, &drive, &supply(&system), &Integration::default()).expect_err("L = 0");
    assert!(
        matches!(
            error,
            Error::OutOfRange {
                name: "motor.inductance_h",
                ..
            }
        ),
        "{error}"
    );
    drive.motor.inductance_h = 1e-3;
    drive.gearbox.efficiency = 1.2;
    let error = integrate(&system, &drive, &supply(&system), &Integration::default()).expect_err("η > 1");
    assert!(error.to_string().contains("gearbox.efficiency"), "{error}");
    let error = integrate(
        &system,
        &Drive::polimi_case_study(1e-3),
        &SupplyVoltage {
            volts: f64::NAN,
            rise_time_s: 0.05,
        },
        &Integration::default(),
    )
    .expect_err("NaN volts");
    assert!(error.to_string().contains("supply.volts"), "{error}");
}

#[test]
fn agrees_with_an_independent_recomputation() {
    // data/validation/001-five-bar-independent.md: scipy's Radau and BDF at rtol 1e-10 on
    // the same equations, written from the document without this code.
    let system = five_bar();
    let supply = SupplyVoltage {
        volts: 343.1,
        rise_time_s: 0.05,
    };
    let deployment = integrate(
        &system,
        &Drive::polimi_case_study(1e-3),
        &supply,
        &Integration {
            relative_tolerance: 1e-9,
            absolute_tolerance: 1e-11,
            ..Integration::default()
        },
    )
    .expect("integrates");
    let time = deployment.deployment_time_s.expect("deploys");
    println!("breakaway {} s, deployed {} s", deployment.breakaway_time_s, time);
    assert!(
        (deployment.breakaway_time_s - 0.0212375).abs() < 1e-7,
        "{}",
        deployment.breakaway_time_s
    );
    assert!((time - 0.315421).abs() < 2e-6, "{time}");
    let end = deployment.samples.last().expect("samples");
    assert!(
        (end.rate - 1.92862).abs() < 1e-4 && (end.current_a - 151.966).abs() < 2e-3,
        "{end:?}"
    );
}

/// Issue 35 item 19: a stiff motor on the explicit method at a large `max_steps` took
/// every accepted step into the report (3.2 GB at 1e7 steps). The time history is thinned
/// to at most `MAX_TIME_HISTORY_SAMPLES`, evenly in steps, from the start to the last step;
/// the peaks still see every step.
#[test]
fn the_time_history_is_bounded_whatever_the_step_limit() {
    let system = five_bar();
    let settings = |max_steps: usize| Integration {
        method: Method::Tsit45,
        max_steps,
        ..Integration::default()
    };
    let long = run(&system, 1e-7, settings(3 * MAX_TIME_HISTORY_SAMPLES));
    assert!(long.hit_step_limit);
    assert!(long.counts.steps >= 3 * MAX_TIME_HISTORY_SAMPLES, "{:?}", long.counts);
    let samples = &long.samples;
    assert!(
        samples.len() <= MAX_TIME_HISTORY_SAMPLES && samples.len() > MAX_TIME_HISTORY_SAMPLES / 4,
        "{} samples",
        samples.len()
    );
    assert_eq!(samples.first().map(|s| s.time_s), Some(0.0));
    assert!(samples.windows(2).all(|w| w[0].time_s <= w[1].time_s));
    // The peak over every step is at least the history's largest.
    let largest = samples.iter().map(|s| s.current_a.abs()).fold(0.0, f64::max);
    assert!(long.peak_current_a >= largest);
    // A short run keeps every step.
    let short = run(&system, 1e-3, Integration::default());
    assert!(
        short.samples.len() >= short.counts.steps,
        "{} {:?}",
        short.samples.len(),
        short.counts
    );
}
