//! The sweep finds what plain sampling misses, and agrees with analytic clearances.

use approx::assert_relative_eq;
use flapwright_geom::collision::CollisionShape;
use flapwright_interference::{sweep_pair, sweep_pair_for_verdict, Part, SweepSettings};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};

use crate::TurnAboutZ;

const PLATE_ANGLE_RAD: f64 = 0.123;

/// A 1 mm thin plate at radius 1.5 m, angle 0.123 rad; a 2 m rod turning about z from
/// -1 to +1 rad hits it only near t = 0.123, between the coarse samples -1, 0, +1.
fn rod_and_thin_plate() -> (Part, Part) {
    let rod = CollisionShape::capsule(Point3::origin(), Point3::new(2.0, 0.0, 0.0), 0.002).unwrap();
    let plate = CollisionShape::cuboid(Vector3::new(0.05, 0.0005, 0.05)).unwrap();
    let plate_pose_at_angle = Isometry3::from_parts(
        Translation3::new(1.5 * PLATE_ANGLE_RAD.cos(), 1.5 * PLATE_ANGLE_RAD.sin(), 0.0),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), PLATE_ANGLE_RAD),
    );
    (
        Part::moving("rod", rod, TurnAboutZ { max_radius_m: 2.002 }),
        Part::moving("plate", plate, At(plate_pose_at_angle)),
    )
}

#[test]
fn thin_part_between_coarse_samples_is_found_with_default_settings() {
    let (rod, plate) = rod_and_thin_plate();
    let settings = SweepSettings {
        initial_samples: 3,
        ..SweepSettings::default()
    };
    let found = sweep_pair(&rod, &plate, -1.0, 1.0, &settings).unwrap();
    assert_eq!(found.min_clearance_m, 0.0, "{found:?}");
    // The rod touches the 1 mm plate within ±(0.5 mm + 2 mm) / 1.5 m of its angle.
    assert!(
        (found.at_parameter - PLATE_ANGLE_RAD).abs() < 0.0025 / 1.45,
        "{found:?}"
    );

    let defaults = sweep_pair(&rod, &plate, -1.0, 1.0, &SweepSettings::default()).unwrap();
    assert_eq!(
        defaults.min_clearance_m, 0.0,
        "default settings find it too: {defaults:?}"
    );
}

#[test]
fn plain_sampling_misses_it_and_says_so() {
    let (rod, plate) = rod_and_thin_plate();
    let coarse = SweepSettings {
        initial_samples: 3,
        max_evaluations: 3,
        ..SweepSettings::default()
    };
    let missed = sweep_pair(&rod, &plate, -1.0, 1.0, &coarse).unwrap();
    assert!(
        missed.min_clearance_m > 0.1,
        "three samples see a clear rod: {missed:?}"
    );
    // ... but the residual bound admits that a collision cannot be excluded.
    assert!(missed.residual_bound_m >= missed.min_clearance_m, "{missed:?}");
}

/// A point of the part's frame on the unit circle about z at angle t (speed 1, bound 1.1).
struct Orbit;
impl flapwright_interference::Motion for Orbit {
    fn pose_ac(&self, t: f64) -> Result<Isometry3<f64>, flapwright_mechanism::Error> {
        Ok(Isometry3::translation(t.cos(), t.sin(), 0.0))
    }
    fn speed_bound(&self) -> f64 {
        1.1
    }
}

/// Placed once, not moving.
struct At(Isometry3<f64>);
impl flapwright_interference::Motion for At {
    fn pose_ac(&self, _t: f64) -> Result<Isometry3<f64>, flapwright_mechanism::Error> {
        Ok(self.0)
    }
    fn speed_bound(&self) -> f64 {
        0.0
    }
}

#[test]
fn orbiting_ball_matches_the_analytic_clearance() {
    // Moving ball r = 0.1 on a unit circle, fixed ball r = 0.1 at (1, 0, 0); for
    // t in [0.3, 2] the closest approach is at t = 0.3: 2 sin(0.15) - 0.2.
    let moving = CollisionShape::ball(0.1).unwrap();
    let a = Part::moving("ball", moving, Orbit);
    let b = Part::fixed("fixed", CollisionShape::ball(0.1).unwrap());
    let b_pose = Isometry3::translation(1.0, 0.0, 0.0);
    let b = Part::moving(b.name, b.shape, At(b_pose));
    let result = sweep_pair(&a, &b, 0.3, 2.0, &SweepSettings::default()).unwrap();
    let expected = 2.0 * 0.15f64.sin() - 0.2;
    assert_relative_eq!(result.min_clearance_m, expected, max_relative = 1e-9);
    assert_relative_eq!(result.at_parameter, 0.3, epsilon = 1e-12);
    assert!(result.residual_bound_m <= SweepSettings::default().tolerance_m);
    // Every evaluation is traced, in deployment order, and each is the analytic clearance.
    assert_eq!(result.trace.len(), result.evaluations);
    assert!(result.trace.windows(2).all(|w| w[0].0 < w[1].0), "{:?}", result.trace);
    for &(t, clearance) in &result.trace {
        assert_relative_eq!(clearance, 2.0 * (0.5 * t).sin() - 0.2, max_relative = 1e-9);
    }
}

/// A ball r = 0.1 on the unit-circle orbit, and a fixed ball of `radius_m` at (x_m, 0, 0).
fn orbiting_ball_and_fixed_ball(radius_m: f64, x_m: f64) -> (Part, Part) {
    (
        Part::moving("ball", CollisionShape::ball(0.1).unwrap(), Orbit),
        Part::moving(
            "fixed",
            CollisionShape::ball(radius_m).unwrap(),
            At(Isometry3::translation(x_m, 0.0, 0.0)),
        ),
    )
}

#[test]
fn far_pairs_stop_at_the_relative_tolerance_with_a_true_bound() {
    // Ball r = 0.1 orbiting the unit circle, fixed ball r = 0.1 at (-3, 0, 0); over
    // t in [-1, 2.5] the closest approach is at t = 2.5: |(cos 2.5 + 3, sin 2.5)| - 0.2,
    // about 2.26 m. Absolute 1e-5 would refine to 10 um; relative 1e-2 stops near 23 mm.
    let (a, b) = orbiting_ball_and_fixed_ball(0.1, -3.0);
    let expected = (2.5f64.cos() + 3.0).hypot(2.5f64.sin()) - 0.2;
    let run = |relative_tolerance| {
        let settings = SweepSettings {
            initial_samples: 3,
            tolerance_m: 1e-5,
            relative_tolerance,
            ..SweepSettings::default()
        };
        sweep_pair(&a, &b, -1.0, 2.5, &settings).unwrap()
    };
    let fine = run(0.0);
    let relative = run(1e-2);
    for result in [&fine, &relative] {
        // The certificate holds either way: the true minimum is within the bound below.
        assert!(result.min_clearance_m >= expected - 1e-12, "{result:?}");
        assert!(
            result.min_clearance_m - result.residual_bound_m <= expected + 1e-12,
            "{result:?}"
        );
    }
    assert!(fine.residual_bound_m <= 1e-5, "{fine:?}");
    assert!(
        relative.residual_bound_m <= 1e-2 * relative.min_clearance_m,
        "{relative:?}"
    );
    assert!(relative.evaluations < fine.evaluations, "{relative:?} vs {fine:?}");
}

#[test]
fn a_collision_reports_its_deepest_sample() {
    // Ball r = 0.1 orbiting the unit circle through a fixed ball r = 0.3 at (1, 0, 0): at
    // t = 0 (a sample of the default 9 over [-1, 1]) the centres meet and the moving ball's
    // surface is 0.3 - 0.1 = 0.2 inside the fixed one; at t = +-0.25 only 0.151.
    let (a, b) = orbiting_ball_and_fixed_ball(0.3, 1.0);
    let settings = SweepSettings::default();
    let result = sweep_pair(&a, &b, -1.0, 1.0, &settings).unwrap();
    assert_eq!(result.min_clearance_m, 0.0);
    assert_eq!(result.at_parameter, 0.0, "{result:?}");
    // A lower bound within the surface grid, whose spacing is the sweep's tolerance.
    assert!(result.penetration_m <= 0.2 + 1e-9, "{result:?}");
    assert!(result.penetration_m >= 0.2 - 1.01 * settings.tolerance_m, "{result:?}");
    assert_eq!(result.penetration_resolution_m, settings.tolerance_m);
    // The trace reads the overlap as negative clearance: minus the depth at t = 0.
    assert!(
        result.trace.contains(&(0.0, -result.penetration_m)),
        "{:?}",
        result.trace
    );
}

#[test]
fn bad_settings_are_typed_errors() {
    let (rod, plate) = rod_and_thin_plate();
    let bad = SweepSettings {
        initial_samples: 1,
        ..SweepSettings::default()
    };
    assert!(sweep_pair(&rod, &plate, -1.0, 1.0, &bad).is_err());
    assert!(sweep_pair(&rod, &plate, 1.0, -1.0, &SweepSettings::default()).is_err());
    assert!(sweep_pair(&rod, &plate, f64::NAN, 1.0, &SweepSettings::default()).is_err());
    let bad_relative = SweepSettings {
        relative_tolerance: 1.0,
        ..SweepSettings::default()
    };
    assert!(sweep_pair(&rod, &plate, -1.0, 1.0, &bad_relative).is_err());
}

#[test]
fn stopping_at_the_verdict_keeps_it_certified_and_spends_fewer_evaluations() {
    // Ball r = 0.1 orbiting the unit circle, fixed ball r = 0.1 at (1.5, 0, 0): over
    // t in [-1, 1] the closest approach is at t = 0, 1.5 - 1 - 0.2 = 0.3 m.
    let (a, b) = orbiting_ball_and_fixed_ball(0.1, 1.5);
    let expected = 0.3;
    let located = SweepSettings {
        tolerance_m: 1e-5,
        relative_tolerance: 0.0,
        max_evaluations: 100_000,
        ..SweepSettings::default()
    };
    let at_verdict = SweepSettings {
        stop_at_verdict: true,
        ..located
    };
    let full = sweep_pair(&a, &b, -1.0, 1.0, &located).unwrap();
    // Without the flag the required clearance changes nothing.
    assert_eq!(sweep_pair_for_verdict(&a, &b, -1.0, 1.0, &located, 0.1).unwrap(), full);
    for required in [0.1, 0.29] {
        // Passes: the certified lower bound meets the requirement, sooner than the minimum
        // is located to 10 um, and the true minimum still lies within the bound.
        let pass = sweep_pair_for_verdict(&a, &b, -1.0, 1.0, &at_verdict, required).unwrap();
        assert!(pass.min_clearance_m - pass.residual_bound_m >= required, "{pass:?}");
        assert!(
            pass.min_clearance_m - pass.residual_bound_m <= expected + 1e-12,
            "{pass:?}"
        );
        assert!(pass.evaluations < full.evaluations, "{pass:?} vs {full:?}");
    }
    // Fails: a sample below the requirement decides it at once (the 9 initial samples
    // include t = 0); the full sweep fails it too.
    let fail = sweep_pair_for_verdict(&a, &b, -1.0, 1.0, &at_verdict, 0.35).unwrap();
    assert!(fail.min_clearance_m < 0.35, "{fail:?}");
    assert_eq!(fail.evaluations, 9, "{fail:?}");
    assert!(full.min_clearance_m - full.residual_bound_m < 0.35, "{full:?}");
}
