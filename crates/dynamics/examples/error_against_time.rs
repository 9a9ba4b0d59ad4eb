//! Error against run time of the deployment integration (issue 16): the `001_...` five-bar
//! driven by its DC motor, for relative tolerances 1e-3 to 1e-10 and each method, against
//! a reference from Tsit45 at rtol 1e-13 (non-stiff motor, L = 1e-3 H), and the stiff motor
//! (L = 1e-6 H) for the implicit methods, whose reference is BDF at rtol 1e-12.
//!
//! `cargo run --release -p flapwright-dynamics --example error_against_time` prints a
//! Markdown table; `docs/dynamics.md` quotes it. Errors are those of the deployment time and of the
//! input at half that time; wall time is the median of repeated runs.

use std::time::Instant;

use flapwright_dynamics::{
    integrate, required_drive, Drive, DynamicsRun, Integration, Method, SmoothStart, SupplyVoltage,
};
use flapwright_kinds::LoadedFiveBar;

fn input_at(run: &DynamicsRun, time_s: f64) -> f64 {
    let samples = &run.samples;
    let after = samples
        .iter()
        .position(|s| s.time_s >= time_s)
        .unwrap_or(samples.len() - 1)
        .max(1);
    let (a, b) = (&samples[after - 1], &samples[after]);
    // Cubic Hermite between the two steps around `time_s` (the samples carry the rate).
    let h = b.time_s - a.time_s;
    let s = (time_s - a.time_s) / h;
    let (h00, h10, h01, h11) = (
        2.0 * s.powi(3) - 3.0 * s * s + 1.0,
        s.powi(3) - 2.0 * s * s + s,
        -2.0 * s.powi(3) + 3.0 * s * s,
        s.powi(3) - s * s,
    );
    h00 * a.input + h10 * h * a.rate + h01 * b.input + h11 * h * b.rate
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let system = LoadedFiveBar::polimi_case_study()?;
    let law = SmoothStart {
        rate_radps: 1.0,
        smoothing_per_s: 20.0,
    };
    let required = required_drive(&system, &Drive::polimi_case_study(1e-3), &law, 201)?;
    let supply = SupplyVoltage {
        volts: required.iter().map(|s| s.voltage_v).fold(0.0, f64::max),
        rise_time_s: 0.05,
    };
    println!(
        "supply {:.1} V (the largest voltage the 1 rad/s crank law needs)\n",
        supply.volts
    );
    println!("| L (H) | method | rtol | steps | rejected | Jacobians | wall (us) | deployment time error (s) | input error at half time (rad) | energy residual / supplied |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for (inductance_h, methods, reference_method, reference_tolerance) in [
        (
            1e-3,
            vec![Method::Bdf, Method::Esdirk34, Method::Tsit45],
            Method::Tsit45,
            1e-13,
        ),
        (1e-6, vec![Method::Bdf, Method::Esdirk34], Method::Bdf, 1e-12),
    ] {
        let drive = Drive::polimi_case_study(inductance_h);
        let settings = |method: Method, rtol: f64| Integration {
            method,
            relative_tolerance: rtol,
            absolute_tolerance: rtol * 1e-2,
            max_steps: 2_000_000,
            ..Integration::default()
        };
        let reference = integrate(
            &system,
            &drive,
            &supply,
            &settings(reference_method, reference_tolerance),
        )?;
        let reference_time = reference.deployment_time_s.ok_or("the reference did not deploy")?;
        let half = 0.5 * reference_time;
        let reference_half = input_at(&reference, half);
        for method in &methods {
            for exponent in 3..=10 {
                let rtol = 10f64.powi(-exponent);
                let mut walls = Vec::new();
                let mut last = None;
                for _ in 0..15 {
                    let start = Instant::now();
                    let run = integrate(&system, &drive, &supply, &settings(*method, rtol))?;
                    walls.push(start.elapsed().as_secs_f64());
                    last = Some(run);
                }
                walls.sort_by(f64::total_cmp);
                let run = last.ok_or("no run")?;
                let time = run.deployment_time_s.ok_or("did not deploy")?;
                println!(
                    "| {inductance_h:.0e} | {} | {rtol:.0e} | {} | {} | {} | {:.0} | {:.1e} | {:.1e} | {:.1e} |",
                    method.name(),
                    run.counts.steps,
                    run.counts.rejected_steps,
                    run.counts.jacobian_evaluations,
                    walls[walls.len() / 2] * 1e6,
                    (time - reference_time).abs(),
                    (input_at(&run, half) - reference_half).abs(),
                    (run.energy.residual_j / run.energy.supplied_j).abs(),
                );
            }
        }
    }
    Ok(())
}
