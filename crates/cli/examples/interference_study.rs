//! Error against run time of the interference check of the default scene, for the sweep's
//! knobs (initial samples, refinement tolerance) and the mesh resolution (airfoil points
//! per side). The reference is the finest setting; the error is the largest difference of
//! any pair's certified minimum clearance from it.
//!
//! `cargo run --release -p flapwright --example interference_study`

use std::time::Instant;

use flapwright::output::StagedDir;
use flapwright::pipeline::{design, Inputs, Mode};
use flapwright::scene::{Scene, DEFAULT_SCENE_TOML};

/// Per pair (name, sampled minimum clearance, residual bound), and the wall time (s).
fn run(points_per_side: usize, initial_samples: usize, tolerance_m: f64) -> (Vec<(String, f64, f64)>, f64) {
    let mut scene = Scene::from_toml(DEFAULT_SCENE_TOML, None).expect("default scene");
    scene.resolution.airfoil_points_per_side = points_per_side;
    scene.interference.initial_samples = initial_samples;
    scene.interference.tolerance_m = tolerance_m;
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

fn error_against(reference: &[(String, f64, f64)], pairs: &[(String, f64, f64)]) -> (f64, f64) {
    let worst_error = reference
        .iter()
        .zip(pairs)
        .map(|(r, p)| (r.1 - p.1).abs())
        .fold(0.0, f64::max);
    let worst_bound = pairs.iter().map(|p| p.2).fold(0.0, f64::max);
    (worst_error, worst_bound)
}

fn main() {
    let (reference, reference_time) = run(100, 33, 1e-5);
    println!("reference: 100 points per side, 33 samples, tolerance 1e-5 m: {reference_time:.2} s");
    let (meshed_reference, _) = run(60, 33, 1e-5);
    println!("\nsweep knobs (60 points per side, against 60 points per side, 33 samples, 1e-5 m):");
    println!(
        "{:>8} {:>12} {:>16} {:>18} {:>10}",
        "samples", "tolerance_m", "max |error| mm", "max residual mm", "time s"
    );
    for samples in [3, 5, 9, 17] {
        for tolerance in [1e-2, 3e-3, 1e-3, 1e-4] {
            let (pairs, time) = run(60, samples, tolerance);
            let (error, bound) = error_against(&meshed_reference, &pairs);
            println!(
                "{samples:>8} {tolerance:>12.0e} {:>16.3} {:>18.3} {time:>10.3}",
                error * 1e3,
                bound * 1e3
            );
            assert!(bound <= tolerance + 1e-12, "the certified bound meets the tolerance");
        }
    }
    println!("\nmesh resolution (9 samples, tolerance 1e-3 m):");
    println!("{:>16} {:>16} {:>10}", "points per side", "max |error| mm", "time s");
    for points in [20, 30, 60, 100] {
        let (pairs, time) = run(points, 9, 1e-3);
        let (error, _) = error_against(&reference, &pairs);
        println!("{points:>16} {:>16.3} {time:>10.3}", error * 1e3);
    }
}
