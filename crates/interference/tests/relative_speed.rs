//! The relative-motion Lipschitz bound: each motion's field bound holds at points that are
//! not its own (finite differences), and a sweep certified with the relative bound never
//! reports more than a dense brute-force minimum.

use std::sync::Arc;

use flapwright_geom::collision::{compute_distance, CollisionShape};
use flapwright_interference::{
    flap_part, station_parts, sweep_pair, FittedFlapMotion, FlapCarrier, FlapElement, Motion, Part, SweepSettings,
};
use flapwright_kinds::{CircularArcTrack, CircularArcTrackSpec};
use flapwright_mechanism::FlapMechanism;
use nalgebra::{Isometry3, Point2, Point3, Vector3};

use crate::TurnAboutZ;

fn thesis_track() -> Arc<dyn FlapMechanism> {
    Arc::new(CircularArcTrack::synthesise(CircularArcTrackSpec::thesis_case_study()).unwrap())
}

/// Points on a grid over a box a metre across around `centre` (local frame).
fn grid_around(centre: Point3<f64>) -> Vec<Point3<f64>> {
    let steps = [-0.5, -0.2, 0.0, 0.3, 0.5];
    let mut points = Vec::new();
    for x in steps {
        for y in steps {
            for z in [-0.4, 0.0, 0.4] {
                points.push(centre + Vector3::new(x, y, z));
            }
        }
    }
    points
}

/// The fastest any of `points` (local frame) moves under `motion` over [0, 1], by finite
/// differences on `steps` intervals.
fn fastest(motion: &dyn Motion, points: &[Point3<f64>], steps: usize) -> f64 {
    let mut fastest: f64 = 0.0;
    let mut before = motion.pose_ac(0.0).unwrap();
    for k in 1..=steps {
        let after = motion.pose_ac(k as f64 / steps as f64).unwrap();
        for p in points {
            fastest = fastest.max((after * p - before * p).norm() * steps as f64);
        }
        before = after;
    }
    fastest
}

/// Every point's own field bound against its finite-difference speed (to rounding: a body
/// that hardly turns moves its points by 1e-14 m), and the bound over all of them against
/// the fastest, at least `tightness` of it.
fn assert_field_bound_holds(name: &str, motion: &dyn Motion, points: &[Point3<f64>], tightness: f64) {
    for p in points {
        let bound = motion.field_speed_bound(std::slice::from_ref(p)).unwrap();
        let speed = fastest(motion, std::slice::from_ref(p), 400);
        assert!(
            speed <= bound * (1.0 + 1e-9) + 1e-12,
            "{name} at {p}: {speed} > {bound}"
        );
    }
    let bound = motion.field_speed_bound(points).unwrap();
    let speed = fastest(motion, points, 400);
    assert!(
        speed >= tightness * bound,
        "{name}: the bound {bound} is loose against {speed}"
    );
}

#[test]
fn a_mechanism_bodys_field_bound_holds_off_the_body() {
    let track = thesis_track();
    let parts = station_parts("st", Some("flap"), &Isometry3::identity(), &track).unwrap();
    let mut checked = 0;
    for part in parts.parts.iter().filter(|p| p.moving) {
        let local_centre = part.part.shape.compute_aabb(&Isometry3::identity());
        let centre = nalgebra::center(&local_centre.min, &local_centre.max);
        if part.part.motion.speed_bound() < 1e-9 {
            continue; // a body that hardly moves (the jack body on its pivot, stowed)
        }
        assert_field_bound_holds(&part.part.name, part.part.motion.as_ref(), &grid_around(centre), 0.3);
        checked += 1;
    }
    assert!(checked >= 4, "{checked} moving parts");
    // The flap mesh's motion too.
    let shape = CollisionShape::ball(0.01).unwrap();
    let flap = flap_part(
        "flap",
        FlapElement::Main,
        shape,
        &[Point3::new(-0.3, 0.3, 0.0)],
        &Isometry3::identity(),
        &track,
    )
    .unwrap();
    assert_field_bound_holds(
        "flap",
        flap.motion.as_ref(),
        &grid_around(Point3::new(-0.3, 0.3, 0.0)),
        0.3,
    );
}

#[test]
fn a_fitted_flaps_field_bound_holds_off_the_flap() {
    // One flap on two thesis tracks 2 m apart along the span (their planes parallel).
    let track = thesis_track();
    let section: Vec<Point2<f64>> = (0..12)
        .map(|k| {
            let s = k as f64 / 11.0;
            Point2::new(-0.1 - 0.5 * s, 0.32 + 0.04 * (std::f64::consts::PI * s).sin())
        })
        .collect();
    let carrier = |z: f64| FlapCarrier {
        station: format!("z{z}"),
        aircraft_from_station: Isometry3::translation(0.0, 0.0, z),
        mechanism: Arc::clone(&track),
        section_st: section.clone(),
    };
    let vertices: Vec<Point3<f64>> = [0.0, 2.0]
        .iter()
        .flat_map(|&z| section.iter().map(move |p| Point3::new(p.x, p.y, z)))
        .collect();
    let motion =
        FittedFlapMotion::try_new("flap", FlapElement::Main, vec![carrier(0.0), carrier(2.0)], &vertices).unwrap();
    // Near the first station's plane, where its parts are, and beyond the flap's far end.
    let mut points = grid_around(Point3::new(-0.3, 0.2, 0.0));
    points.extend(grid_around(Point3::new(-0.3, 0.2, 2.5)));
    // The gain bounds every rigid field whose fitted points move at that root mean square
    // (and the margin covers the fit's residual), so it stands well above the one field
    // the tracks give: 2.35 against 0.67 m per unit here.
    assert_field_bound_holds("fitted flap", &motion, &points, 0.25);
    // Amid the fitted points (mid-span, mid-chord) the field is slower than at the flap's
    // fastest vertex, at a corner.
    let near = motion.field_speed_bound(&[Point3::new(-0.35, 0.33, 1.0)]).unwrap();
    assert!(near < motion.speed_bound(), "{near} vs {}", motion.speed_bound());
}

#[test]
fn a_small_part_near_the_axis_of_a_long_turning_bar_is_swept_with_the_relative_bound() {
    // A bar 2 m long turning about z (its far end at 2 m/rad) and a ball fixed 0.3 m from
    // the axis, 0.05 m above the bar's path: the distance changes only as fast as the bar's
    // points pass under the ball (0.3 m/rad), so the relative bound needs far fewer
    // evaluations than the plain sum and finds the same minimum.
    struct Turning {
        speed: f64,
    }
    impl Motion for Turning {
        fn pose_ac(&self, t: f64) -> Result<Isometry3<f64>, flapwright_mechanism::Error> {
            TurnAboutZ {
                max_radius_m: self.speed,
            }
            .pose_ac(t)
        }
        fn speed_bound(&self) -> f64 {
            self.speed
        }
        fn field_speed_bound(&self, local_points: &[Point3<f64>]) -> Option<f64> {
            Some(local_points.iter().map(|p| p.x.hypot(p.y)).fold(0.0, f64::max))
        }
    }
    let bar = CollisionShape::capsule(Point3::origin(), Point3::new(2.0, 0.0, 0.0), 0.02).unwrap();
    let bar = Part::moving("bar", bar, Turning { speed: 2.02 });
    let ball = Part::fixed_at(
        "ball",
        CollisionShape::ball(0.03).unwrap(),
        Isometry3::translation(0.3, 0.0, 0.1),
    );
    // Without the field bound (the plain sum of the speed bounds).
    let plain_bar = Part::moving(
        "bar",
        CollisionShape::capsule(Point3::origin(), Point3::new(2.0, 0.0, 0.0), 0.02).unwrap(),
        TurnAboutZ { max_radius_m: 2.02 },
    );
    let settings = SweepSettings::default();
    let relative = sweep_pair(&ball, &bar, -0.5, 0.5, &settings).unwrap();
    let plain = sweep_pair(&ball, &plain_bar, -0.5, 0.5, &settings).unwrap();
    assert!((relative.min_clearance_m - 0.05).abs() < 1e-9, "{relative:?}");
    assert!(
        relative.evaluations * 3 < plain.evaluations,
        "{} vs {}",
        relative.evaluations,
        plain.evaluations
    );
    // Never above a dense brute-force minimum, and certified below it by the residual.
    let dense = (0..=2000)
        .map(|k| {
            let t = -0.5 + k as f64 / 2000.0;
            let pose = Isometry3::rotation(Vector3::z() * t);
            compute_distance(&bar.shape, &pose, &ball.shape, &Isometry3::translation(0.3, 0.0, 0.1))
                .unwrap()
                .distance_m
        })
        .fold(f64::INFINITY, f64::min);
    assert!(relative.min_clearance_m >= dense - 1e-12);
    assert!(relative.min_clearance_m - relative.residual_bound_m <= dense + 1e-12);
}
