//! The five-bar double flap of `001_...` (section 2 and the section 4 data): closure, the
//! secondary flap's 60 deg, the derivatives against finite differences and against the
//! document's velocity equations as corrected in `data/validation/001-five-bar-defects.md`,
//! and the required motor torque by work-energy against the document's own kinetic energy.

use flapwright_kinds::{DoubleFlapLoads, FiveBarDoubleFlap, FiveBarPose};
use flapwright_mechanism::generalise;
use flapwright_mechanism::jet::{AngleJet, PointJet};

fn case_study() -> FiveBarDoubleFlap {
    FiveBarDoubleFlap::polimi_case_study().expect("the 001 data assembles")
}

fn crank_samples(mechanism: &FiveBarDoubleFlap, count: usize) -> Vec<f64> {
    let (from, to) = (mechanism.stowed_crank_rad, mechanism.deployed_crank_rad);
    (0..count)
        .map(|i| from + (to - from) * i as f64 / (count - 1) as f64)
        .collect()
}

#[test]
fn the_three_loops_close_to_rounding_over_the_documents_crank_range() {
    let mechanism = case_study();
    let mut worst = 0.0_f64;
    for alpha in crank_samples(&mechanism, 451) {
        let pose = mechanism.pose(alpha).expect("assembles over 275-320 deg");
        worst = worst.max(mechanism.closure_residual(&pose));
        assert!(pose.toggle_sine > 0.05, "near a toggle at {} deg", alpha.to_degrees());
    }
    assert!(worst < 1e-10, "closure residual {worst:e} m");
    assert!(worst > 0.0, "the residual is computed, not assumed");
}

#[test]
fn the_secondary_flap_reaches_60_deg_near_the_end_of_the_crank_range() {
    let mechanism = case_study();
    let theta = |alpha: f64| mechanism.pose(alpha).expect("assembles").secondary_deflection.value;
    let stowed = mechanism.pose(mechanism.stowed_crank_rad).expect("stowed");
    // Stowed: both flaps within a degree of their chords' rest lines (the document's Fig. 8a).
    assert!(stowed.main_deflection.value.to_degrees().abs() < 1.5);
    assert!(stowed.secondary_deflection.value.to_degrees().abs() < 1.5);
    // Both deflections grow monotonically with α.
    let samples = crank_samples(&mechanism, 91);
    for pair in samples.windows(2) {
        let (a, b) = (mechanism.pose(pair[0]).expect("a"), mechanism.pose(pair[1]).expect("b"));
        assert!(b.secondary_deflection.value > a.secondary_deflection.value);
        assert!(b.main_deflection.value > a.main_deflection.value);
    }
    // θ = 60 deg by bisection, inside the range: the document's goal (section 1).
    let target = 60f64.to_radians();
    let (mut lo, mut hi) = (mechanism.stowed_crank_rad, mechanism.deployed_crank_rad);
    assert!(theta(lo) < target && theta(hi) > target);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if theta(mid) > target {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let at_60 = lo.to_degrees();
    assert!((319.0..320.0).contains(&at_60), "θ = 60 deg at α = {at_60} deg");
    let deployed = mechanism.pose(mechanism.deployed_crank_rad).expect("deployed");
    let (delta, theta_end) = (
        deployed.main_deflection.value.to_degrees(),
        deployed.secondary_deflection.value.to_degrees(),
    );
    assert!((30.0..35.0).contains(&delta), "main flap at 320 deg: {delta} deg");
    assert!(
        (60.0..61.5).contains(&theta_end),
        "secondary flap at 320 deg: {theta_end} deg"
    );
}

/// Central differences of the k-th derivative of a jet quantity, compared at `relative`.
fn assert_derivatives(name: &str, value: impl Fn(&FiveBarPose, usize) -> f64, mechanism: &FiveBarDoubleFlap) {
    let step = 1e-5;
    for alpha in crank_samples(mechanism, 12) {
        let at = |x: f64| mechanism.pose(x).expect("assembles");
        let (minus, here, plus) = (at(alpha - step), at(alpha), at(alpha + step));
        for order in 1..=3 {
            let difference = (value(&plus, order - 1) - value(&minus, order - 1)) / (2.0 * step);
            let analytic = value(&here, order);
            let scale = analytic.abs().max(1e-3);
            // Central differences of a smooth function: error ~ step² f''' / 6, about 1e-10
            // relative here; the tolerance is the 1e-6.
            assert!(
                (difference - analytic).abs() < 1e-6 * scale,
                "{name} derivative {order} at {} deg: analytic {analytic}, difference {difference}",
                alpha.to_degrees()
            );
        }
    }
}

fn angle_order(jet: &AngleJet, order: usize) -> f64 {
    [jet.value, jet.d1, jet.d2, jet.d3][order]
}

fn component(jet: &PointJet, order: usize, axis: usize) -> f64 {
    [jet.p, jet.d1, jet.d2, jet.d3][order][axis]
}

#[test]
fn velocities_accelerations_and_jerks_agree_with_finite_differences() {
    let mechanism = case_study();
    assert_derivatives("δ", |pose, k| angle_order(&pose.main_deflection, k), &mechanism);
    assert_derivatives("θ", |pose, k| angle_order(&pose.secondary_deflection, k), &mechanism);
    for axis in 0..2 {
        assert_derivatives("D", |pose, k| component(&pose.d, k, axis), &mechanism);
        assert_derivatives("H", |pose, k| component(&pose.h, k, axis), &mechanism);
        assert_derivatives("L", |pose, k| component(&pose.trailing_edge, k, axis), &mechanism);
    }
}

fn direction(v: nalgebra::Vector2<f64>) -> f64 {
    v.y.atan2(v.x)
}

#[test]
fn the_documents_velocity_equations_hold_as_corrected_and_fail_as_printed() {
    let mechanism = case_study();
    let dims = mechanism.dimensions;
    for alpha in crank_samples(&mechanism, 10) {
        let pose = mechanism.pose(alpha).expect("assembles");
        let delta = pose.main_deflection;
        // Loop 1 (section 2.1, as printed and correct): β' = -a cos(α + δ) / (b cos(β + δ)).
        let beta = direction(pose.g.p - pose.a.p);
        let (g_a, g_a_rate) = (pose.g.p - pose.a.p, pose.g.d1 - pose.a.d1);
        let beta_rate = (g_a.x * g_a_rate.y - g_a.y * g_a_rate.x) / g_a.norm_squared();
        let printed = -dims.a * (alpha + delta.value).cos() / (dims.b * (beta + delta.value).cos());
        assert!((beta_rate - printed).abs() < 1e-9 * printed.abs().max(1.0));
        // Loop 2 (section 2.2), first row: d φ' sin φ + p ψ' sin ψ + c δ' cos δ = 0; printed
        // with sin β in place of sin ψ.
        let (phi, psi) = (
            direction(pose.d.p - mechanism.pivot_b()),
            direction(pose.g.p - pose.d.p),
        );
        let rate = |u: nalgebra::Vector2<f64>, v: nalgebra::Vector2<f64>| (u.x * v.y - u.y * v.x) / u.norm_squared();
        let phi_rate = rate(pose.d.p - mechanism.pivot_b(), pose.d.d1);
        let psi_rate = rate(pose.g.p - pose.d.p, pose.g.d1 - pose.d.d1);
        let row = |sine_of: f64| {
            dims.d * phi_rate * phi.sin() + dims.p * psi_rate * sine_of.sin() + dims.c * delta.d1 * delta.value.cos()
        };
        let scale = dims.c * delta.d1.abs();
        assert!(row(psi).abs() < 1e-9 * scale, "corrected row: {}", row(psi));
        assert!(
            row(beta).abs() > 1e-3 * scale,
            "the printed row holds by accident: {}",
            row(beta)
        );
    }
}

#[test]
fn the_work_energy_torque_equals_the_documents_kinetic_energy_balance_at_every_sample() {
    let mechanism = case_study();
    let dims = mechanism.dimensions;
    let loads = DoubleFlapLoads::polimi_case_study(&dims);
    let (c1, c2) = (dims.main_chord, dims.secondary_chord);
    let omega = 1.0; // rad/s, the document's constant crank speed
    let mut checked = 0;
    for alpha in crank_samples(&mechanism, 101) {
        let pose = mechanism.pose(alpha).expect("assembles");
        let (bodies, surfaces) = mechanism.inertial_model(&pose, &loads);
        let through_seam = generalise(&bodies, &surfaces, loads.gravity_mps2).torque_at_constant_rate(omega);

        // The document's section 3.1 with its typos corrected: T in δ̇, θ̇ with the coupling
        // ½ m c₁ c₂ cos(θ - δ) δ̇ θ̇; the powers of the lifts, moments and weights.
        let (d, t) = (pose.main_deflection, pose.secondary_deflection);
        let (dd, dt) = (d.d1 * omega, t.d1 * omega);
        let (ddd, ddt) = (d.d2 * omega * omega, t.d2 * omega * omega);
        let j11 = loads.main_mass_kg * c1 * c1 / 4.0 + loads.main_inertia_kgm2 + loads.secondary_mass_kg * c1 * c1;
        let j22 = loads.secondary_mass_kg * c2 * c2 / 4.0 + loads.secondary_inertia_kgm2;
        let j12 = 0.5 * loads.secondary_mass_kg * c1 * c2;
        let relative = t.value - d.value;
        let kinetic_rate = j11 * dd * ddd
            + j22 * dt * ddt
            + j12 * (relative.cos() * (ddd * dt + dd * ddt) - relative.sin() * (dt - dd) * dd * dt);
        let (f1, f2) = (
            loads.main_lift_per_rad_n * d.value,
            loads.secondary_lift_per_rad_n * t.value,
        );
        let g = loads.gravity_mps2;
        let (mass_main, mass_secondary) = (loads.main_mass_kg, loads.secondary_mass_kg);
        let loads_power = -f1 * c1 / 4.0 * dd - f2 * (c1 * relative.cos() * dd + c2 / 4.0 * dt)
            + loads.main_moment_nm * dd
            + loads.secondary_moment_nm * dt
            + (mass_main * g * c1 / 2.0 + mass_secondary * g * c1) * d.value.cos() * dd
            + mass_secondary * g * c2 / 2.0 * t.value.cos() * dt;
        let by_kinetic_energy = (kinetic_rate - loads_power) / omega;
        assert!(
            (through_seam - by_kinetic_energy).abs() <= 1e-9 * by_kinetic_energy.abs().max(1.0),
            "α = {} deg: work-energy {through_seam} N m, kinetic-energy balance {by_kinetic_energy} N m",
            alpha.to_degrees()
        );
        checked += 1;
    }
    assert_eq!(checked, 101);
}

#[test]
fn the_generalised_slopes_agree_with_finite_differences() {
    let mechanism = case_study();
    let loads = DoubleFlapLoads::polimi_case_study(&mechanism.dimensions);
    let at = |alpha: f64| {
        let pose = mechanism.pose(alpha).expect("assembles");
        let (bodies, surfaces) = mechanism.inertial_model(&pose, &loads);
        generalise(&bodies, &surfaces, loads.gravity_mps2)
    };
    let step = 1e-5;
    for alpha in crank_samples(&mechanism, 9) {
        let (minus, here, plus) = (at(alpha - step), at(alpha), at(alpha + step));
        let checks = [
            ("J'", here.inertia_slope, (plus.inertia - minus.inertia) / (2.0 * step)),
            (
                "J''",
                here.inertia_curvature,
                (plus.inertia_slope - minus.inertia_slope) / (2.0 * step),
            ),
            ("Q'", here.force_slope, (plus.force - minus.force) / (2.0 * step)),
        ];
        for (name, analytic, difference) in checks {
            assert!(
                (analytic - difference).abs() < 1e-6 * analytic.abs().max(1e-3),
                "{name} at {} deg: {analytic} against {difference}",
                alpha.to_degrees()
            );
        }
    }
}

#[test]
fn matches_the_independent_recomputation() {
    // data/validation/001-five-bar-independent.md (6 significant digits: 1e-5 relative,
    // absolute below 1 deg or unit, where six digits of a small value are its rounding).
    let mechanism = case_study();
    let loads = DoubleFlapLoads::polimi_case_study(&mechanism.dimensions);
    let close = |value: f64, expected: f64, what: &str| {
        assert!(
            (value - expected).abs() <= 1e-5 * expected.abs().max(1.0),
            "{what}: {value} against {expected}"
        )
    };
    for (alpha, delta, theta) in [
        (275.0, 0.953343, 0.0240930),
        (290.0, 11.9925, 21.1607),
        (305.0, 23.0194, 41.5954),
        (320.0, 32.4268, 60.6057),
    ] {
        let pose = mechanism.pose(f64::to_radians(alpha)).expect("assembles");
        close(pose.main_deflection.value.to_degrees(), delta, "δ");
        close(pose.secondary_deflection.value.to_degrees(), theta, "θ");
    }
    let pose = mechanism.pose(300f64.to_radians()).expect("assembles");
    close(pose.secondary_deflection.d1, 1.35713, "θ'");
    close(pose.secondary_deflection.d2, -0.194556, "θ''");
    close(pose.main_deflection.d1, 0.730768, "δ'");
    close(pose.main_deflection.d2, -0.243551, "δ''");
    for (alpha, inertia, slope, force, torque) in [
        (275.0, 17.8785, 2.05751, -1164.69, 1165.72),
        (300.0, 17.4946, -10.6282, -2913.98, 2908.66),
        (320.0, 9.95668, -29.4838, -3055.39, 3040.64),
    ] {
        let pose = mechanism.pose(f64::to_radians(alpha)).expect("assembles");
        let (bodies, surfaces) = mechanism.inertial_model(&pose, &loads);
        let g = generalise(&bodies, &surfaces, loads.gravity_mps2);
        close(g.inertia, inertia, "J");
        close(g.inertia_slope, slope, "J'");
        close(g.force, force, "Q");
        close(g.torque_at_constant_rate(1.0), torque, "T_m");
    }
}

fn kind() -> flapwright_kinds::FiveBarKind {
    let actuator = flapwright_mechanism::seam::Actuator::Rotary {
        gear_ratio: 1.0,
        efficiency: 1.0,
        nominal_speed_radps: 1.0,
    };
    flapwright_kinds::FiveBarKind::new(
        flapwright_kinds::LoadedFiveBar::polimi_case_study().expect("assembles"),
        actuator,
    )
    .expect("the kind builds")
}

#[test]
fn behind_the_seam_bodies_carry_their_stowed_points_and_bounds_hold() {
    use flapwright_mechanism::FlapMechanism;
    let kind = kind();
    crate::seam::joints_name_existing(&kind);
    crate::seam::speed_bounds_hold(&kind, 0.25); // the thesis track's tightness: a link's reference speed and turn rate peak apart
    let stowed = kind.pose(kind.input_range().stowed).expect("stowed");
    for body in &stowed.bodies {
        assert!((body.translation.vector.norm() + body.rotation.angle().abs()) < 1e-12);
    }
    assert!(stowed.deflection_rad.abs() < 1e-15);
    // Every body's displacement carries each stowed named point it holds to where it stands.
    let stowed_points = stowed.points.clone();
    for input in kind.input_range().samples(7) {
        let pose = kind.pose(input).expect("poses");
        for (b, body) in kind.bodies().iter().enumerate() {
            for solid in &body.solids {
                for p in solid.shape.skeleton() {
                    let name = stowed_points
                        .iter()
                        .find(|n| (n.position - p).norm() < 1e-12)
                        .expect("solids end at named points")
                        .name;
                    let now = pose.point(name).expect("named");
                    assert!((pose.bodies[b] * p - now).norm() < 1e-12, "{} {name}", body.name);
                }
            }
        }
    }
    // Deflection and input invert each other.
    let half = 0.5 * kind.deflection_range_rad();
    let input = kind.input_at_deflection(half).expect("inverts");
    assert!((kind.deflection_at_input(input).expect("deflection") - half).abs() < 1e-12);
}

#[test]
fn behind_the_seam_statics_agree_with_virtual_work() {
    use flapwright_mechanism::{FlapMechanism, LoadCase};
    let kind = kind();
    for load in [LoadCase::thesis_cruise(), LoadCase::thesis_landing()] {
        for input in kind.input_range().samples(25) {
            let statics = kind.kinetostatics(input, &load).expect("statics");
            let (a, b) = (statics.actuator_load, statics.actuator_load_virtual_work);
            assert!(
                (a - b).abs() <= 1e-9 * a.abs().max(b.abs()),
                "{} at {} deg: equilibrium {a} N m, virtual work {b} N m",
                load.name,
                input.to_degrees()
            );
            assert!(statics.health.closure_residual_m < 1e-10);
        }
    }
}

#[test]
fn positions_and_rates_alone_are_those_of_the_full_pose() {
    let mechanism = case_study();
    for alpha in crank_samples(&mechanism, 17) {
        let (full, rates) = (
            mechanism.pose(alpha).expect("full"),
            mechanism.pose_and_rates(alpha).expect("rates"),
        );
        for (a, b) in [
            (full.main_deflection, rates.main_deflection),
            (full.secondary_deflection, rates.secondary_deflection),
        ] {
            assert_eq!((a.value, a.d1), (b.value, b.d1));
            assert_eq!((b.d2, b.d3), (0.0, 0.0));
        }
        assert_eq!((full.h.p, full.h.d1), (rates.h.p, rates.h.d1));
    }
}
