//! Error against run time of the interference check of the default scene, for the sweep's
//! knobs (initial samples, refinement tolerance) and the mesh resolution (airfoil points
//! per side), and of the fairing depth for its two knobs (flap rotations, points per
//! capsule). The reference is the finest setting. The error is the largest difference of
//! a pair's sampled minimum clearance from it, over the pairs closer than
//! [`DECIDING_CLEARANCE_M`] (those that can decide pass or fail); pairs farther apart are
//! located to the relative tolerance, and their largest relative error is printed apart.
//!
//! `cargo run --release -p flapwright --example interference_study`

use std::time::Instant;

use flapwright::pipeline::{design, Inputs, Mode};
use flapwright::scene::{Scene, DEFAULT_SCENE_TOML};
use flapwright::MemorySink;

/// Pairs closer than this (m) are the ones whose clearance can decide the check: 30 times
/// the default required clearance.
const DECIDING_CLEARANCE_M: f64 = 0.1;

/// What one check run gives.
struct Run {
    /// Per pair: name, sampled minimum clearance, residual bound.
    pairs: Vec<(String, f64, f64)>,
    /// Wall time of the whole check (s).
    seconds: f64,
    /// Fairing depth per station (m).
    fairing_depths_m: Vec<f64>,
    /// Where each station's deepest point is: part and flap rotation (rad).
    fairing_deepest: Vec<(String, f64)>,
    /// Wall time of the fairing stage (s).
    fairing_seconds: f64,
}

/// Runs `flapwright check` on the default scene as `configure` changes it.
fn run(configure: impl FnOnce(&mut Scene)) -> Run {
    let mut scene = Scene::from_toml(DEFAULT_SCENE_TOML, &flapwright::scene::NoFiles).expect("default scene");
    scene.interference.max_evaluations = 100_000;
    configure(&mut scene);
    let staged = MemorySink::new();
    let inputs = Inputs {
        scene: &scene,
        scene_text: DEFAULT_SCENE_TOML,
        files: &flapwright::scene::NoFiles,
        wing_cache: None,
    };
    let start = Instant::now();
    let outcome = design(&inputs, Mode::Check, &staged).expect("check runs");
    let seconds = start.elapsed().as_secs_f64();
    let report = outcome.report;
    let fairing_depths_m = report
        .stations
        .iter()
        .map(|s| s.fairing.as_ref().expect("fairing measured").depth_m)
        .collect();
    let fairing_deepest = report
        .stations
        .iter()
        .flat_map(|s| &s.fairing)
        .map(|f| (f.part.clone().unwrap_or_default(), f.at_parameter))
        .collect();
    let fairing_seconds = report
        .timings
        .iter()
        .find(|t| t.stage == "fairing")
        .expect("fairing stage timed")
        .wall_time_s;
    let pairs = report
        .interference
        .expect("interference ran")
        .pairs
        .into_iter()
        .map(|p| {
            (
                format!("{} vs {}", p.clearance.part_a, p.clearance.part_b),
                p.clearance.min_clearance_m,
                p.clearance.residual_bound_m,
            )
        })
        .collect();
    Run {
        pairs,
        seconds,
        fairing_depths_m,
        fairing_deepest,
        fairing_seconds,
    }
}

/// A check with the given mesh resolution and sweep settings.
fn sweep(points_per_side: usize, initial_samples: usize, tolerance_m: f64, relative_tolerance: f64) -> Run {
    run(|scene| {
        scene.resolution.airfoil_points_per_side = points_per_side;
        scene.interference.initial_samples = initial_samples;
        scene.interference.tolerance_m = tolerance_m;
        scene.interference.relative_tolerance = relative_tolerance;
    })
}

/// A check with the given fairing resolution (sweep at its defaults).
fn fairing(samples: usize, points_per_capsule: usize) -> Run {
    run(|scene| {
        scene.resolution.fairing_samples = samples;
        scene.resolution.fairing_points_per_capsule = points_per_capsule;
    })
}

/// Largest absolute error over the deciding pairs, largest relative error over the rest,
/// and the largest residual bound of the deciding pairs.
fn error_against(reference: &[(String, f64, f64)], pairs: &[(String, f64, f64)]) -> (f64, f64, f64) {
    let (mut near, mut far, mut bound) = (0.0_f64, 0.0_f64, 0.0_f64);
    for (r, p) in reference.iter().zip(pairs) {
        assert_eq!(r.0, p.0, "same pairs in the same order");
        if r.1 < DECIDING_CLEARANCE_M {
            near = near.max((r.1 - p.1).abs());
            bound = bound.max(p.2);
        } else {
            far = far.max((r.1 - p.1).abs() / r.1);
        }
    }
    (near, far, bound)
}

fn main() {
    let reference = sweep(100, 33, 1e-5, 1e-4);
    println!(
        "reference: 100 points per side, 33 samples, tolerance 1e-5 m, relative 1e-4: {:.2} s",
        reference.seconds
    );
    let meshed_reference = sweep(60, 33, 1e-5, 1e-4).pairs;
    println!(
        "\nsweep knobs (60 points per side, against the same mesh at 33 samples, 1e-5 m, 1e-4);\n\
         error over pairs closer than {} mm, relative error over the rest:",
        DECIDING_CLEARANCE_M * 1e3
    );
    println!(
        "{:>8} {:>12} {:>10} {:>16} {:>14} {:>18} {:>10}",
        "samples", "tolerance_m", "relative", "max |error| mm", "far rel. err", "max residual mm", "time s"
    );
    let mut rows: Vec<(usize, f64, f64)> = Vec::new();
    for samples in [3, 9, 17] {
        for tolerance in [1e-2, 3e-3, 1e-3, 1e-4] {
            rows.push((samples, tolerance, 1e-2));
        }
    }
    for relative in [1e-1, 3e-2, 1e-3] {
        rows.push((9, 1e-3, relative));
    }
    for (samples, tolerance, relative) in rows {
        let result = sweep(60, samples, tolerance, relative);
        let (error, far, bound) = error_against(&meshed_reference, &result.pairs);
        let time = result.seconds;
        println!(
            "{samples:>8} {tolerance:>12.0e} {relative:>10.0e} {:>16.3} {far:>14.1e} {:>18.3} {time:>10.3}",
            error * 1e3,
            bound * 1e3
        );
        assert!(
            bound <= tolerance.max(relative * DECIDING_CLEARANCE_M) + 1e-12,
            "the certified bound meets the tolerance"
        );
    }
    println!("\nmesh resolution (9 samples, tolerance 1e-3 m, relative 1e-2):");
    println!(
        "{:>16} {:>16} {:>14} {:>10}",
        "points per side", "max |error| mm", "far rel. err", "time s"
    );
    for points in [20, 30, 60, 100] {
        let result = sweep(points, 9, 1e-3, 1e-2);
        let (error, far, _) = error_against(&reference.pairs, &result.pairs);
        println!(
            "{points:>16} {:>16.3} {far:>14.1e} {:>10.3}",
            error * 1e3,
            result.seconds
        );
    }

    let fine = fairing(801, 256);
    println!(
        "\nfairing depth against 801 flap rotations x 256 points per capsule (depths {} mm):",
        fine.fairing_depths_m
            .iter()
            .map(|d| format!("{:.2}", d * 1e3))
            .collect::<Vec<_>>()
            .join(", ")
    );
    for (depth, (part, at)) in fine.fairing_depths_m.iter().zip(&fine.fairing_deepest) {
        println!(
            "  {:.2} mm: {part} at flap rotation {:.1} deg",
            depth * 1e3,
            at.to_degrees()
        );
    }
    println!(
        "{:>10} {:>18} {:>16} {:>16}",
        "rotations", "points per capsule", "max |error| mm", "stage time ms"
    );
    for (samples, points) in [
        (11, 4),
        (11, 16),
        (21, 8),
        (21, 16),
        (41, 4),
        (41, 16),
        (81, 16),
        (41, 32),
    ] {
        let result = fairing(samples, points);
        let error = fine
            .fairing_depths_m
            .iter()
            .zip(&result.fairing_depths_m)
            .map(|(f, r)| (f - r).abs())
            .fold(0.0, f64::max);
        println!(
            "{samples:>10} {points:>18} {:>16.3} {:>16.1}",
            error * 1e3,
            result.fairing_seconds * 1e3
        );
    }
}
