//! Error against run time of the interference check of the default scene, for the sweep's
//! knobs (initial samples, refinement tolerance) and the mesh resolution (airfoil points
//! per side). The reference is the finest setting. The error is the largest difference of
//! a pair's sampled minimum clearance from it, over the pairs closer than
//! [`DECIDING_CLEARANCE_M`] (those that can decide pass or fail); pairs farther apart are
//! located to the relative tolerance, and their largest relative error is printed apart.
//!
//! `cargo run --release -p flapwright --example interference_study`

use std::time::Instant;

use flapwright::output::StagedDir;
use flapwright::pipeline::{design, Inputs, Mode};
use flapwright::scene::{Scene, DEFAULT_SCENE_TOML};

/// Pairs closer than this (m) are the ones whose clearance can decide the check: 30 times
/// the default required clearance.
const DECIDING_CLEARANCE_M: f64 = 0.1;

/// Per pair (name, sampled minimum clearance, residual bound), and the wall time (s).
fn run(
    points_per_side: usize,
    initial_samples: usize,
    tolerance_m: f64,
    relative_tolerance: f64,
) -> (Vec<(String, f64, f64)>, f64) {
    let mut scene = Scene::from_toml(DEFAULT_SCENE_TOML, None).expect("default scene");
    scene.resolution.airfoil_points_per_side = points_per_side;
    scene.interference.initial_samples = initial_samples;
    scene.interference.tolerance_m = tolerance_m;
    scene.interference.relative_tolerance = relative_tolerance;
    scene.interference.max_evaluations = 100_000;
    let dir = tempfile::tempdir().expect("temp dir");
    let staged = StagedDir::create(&dir.path().join("out")).expect("staging");
    let inputs = Inputs {
        scene: &scene,
        scene_text: DEFAULT_SCENE_TOML,
        scene_dir: None,
    };
    let start = Instant::now();
    let outcome = design(&inputs, Mode::Check, &staged).expect("check runs");
    let seconds = start.elapsed().as_secs_f64();
    let pairs = outcome
        .report
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
    (pairs, seconds)
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
    let (reference, reference_time) = run(100, 33, 1e-5, 1e-4);
    println!("reference: 100 points per side, 33 samples, tolerance 1e-5 m, relative 1e-4: {reference_time:.2} s");
    let (meshed_reference, _) = run(60, 33, 1e-5, 1e-4);
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
        let (pairs, time) = run(60, samples, tolerance, relative);
        let (error, far, bound) = error_against(&meshed_reference, &pairs);
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
        let (pairs, time) = run(points, 9, 1e-3, 1e-2);
        let (error, far, _) = error_against(&reference, &pairs);
        println!("{points:>16} {:>16.3} {far:>14.1e} {time:>10.3}", error * 1e3);
    }
}
