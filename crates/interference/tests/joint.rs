//! Joints: parts that touch by design are checked to stay joined within the play.

use flapwright_geom::collision::CollisionShape;
use flapwright_interference::{sweep_contact, Motion, Part, SweepSettings};
use nalgebra::{Isometry3, Point3};

/// A nut (ball) whose centre runs along the x axis at unit speed: x = t.
struct AlongX;
impl Motion for AlongX {
    fn pose_ac(&self, t: f64) -> Result<Isometry3<f64>, flapwright_mechanism::Error> {
        Ok(Isometry3::translation(t, 0.0, 0.0))
    }
    fn speed_bound(&self) -> f64 {
        1.0
    }
}

/// A screw from x = 0 to 1 (radius 0.05) and a nut of radius 0.05 on it.
fn screw_and_nut() -> (Part, Part) {
    let screw = CollisionShape::capsule(Point3::origin(), Point3::new(1.0, 0.0, 0.0), 0.05).unwrap();
    (
        Part::fixed("screw", screw),
        Part::moving("nut", CollisionShape::ball(0.05).unwrap(), AlongX),
    )
}

#[test]
fn a_nut_that_stays_on_its_screw_is_certified_within_the_play() {
    let (screw, nut) = screw_and_nut();
    let play = 5e-4;
    let joint = sweep_contact(&screw, &nut, 0.0, 0.9, play, &SweepSettings::default()).unwrap();
    assert_eq!(joint.max_separation_m, 0.0, "{joint:?}");
    assert!(joint.upper_bound_m <= play, "{joint:?}");
}

#[test]
fn a_nut_running_off_its_screw_is_caught_with_the_analytic_separation() {
    // Beyond the screw's end the surfaces part: separation (x - 1) - 0.05 - 0.05, largest
    // at the end of the travel, x = 1.5: 0.4.
    let (screw, nut) = screw_and_nut();
    let settings = SweepSettings::default();
    let joint = sweep_contact(&screw, &nut, 0.0, 1.5, 5e-4, &settings).unwrap();
    assert!((joint.max_separation_m - 0.4).abs() < 1e-9, "{joint:?}");
    assert_eq!(joint.at_parameter, 1.5);
    assert!(
        joint.upper_bound_m >= 0.4 - 1e-12 && joint.upper_bound_m <= 0.4 + settings.tolerance_m,
        "{joint:?}"
    );
}

#[test]
fn a_nut_that_leaves_between_samples_is_not_missed() {
    // The nut travels out to x = 1.16 at t = 1.1 and back. It parts from the screw only for
    // x > 1.1, i.e. t in (1.04, 1.16), between the default samples t = 1.0 and 1.25
    // (x = 1.06 and 1.01, both still overlapping): only the certified refinement sees it.
    struct Tent;
    impl Motion for Tent {
        fn pose_ac(&self, t: f64) -> Result<Isometry3<f64>, flapwright_mechanism::Error> {
            Ok(Isometry3::translation(1.16 - (t - 1.1).abs(), 0.0, 0.0))
        }
        fn speed_bound(&self) -> f64 {
            1.0
        }
    }
    let screw = CollisionShape::capsule(Point3::origin(), Point3::new(1.0, 0.0, 0.0), 0.05).unwrap();
    let screw = Part::fixed("screw", screw);
    let nut = Part::moving("nut", CollisionShape::ball(0.05).unwrap(), Tent);
    let joint = sweep_contact(&screw, &nut, 0.0, 2.0, 5e-4, &SweepSettings::default()).unwrap();
    // Largest separation 0.16 - 0.1 = 0.06 at t = 1.1.
    assert!(joint.upper_bound_m >= 0.06 - 1e-9, "{joint:?}");
    assert!(joint.max_separation_m > 0.05, "{joint:?}");
    assert!((joint.at_parameter - 1.1).abs() < 0.02, "{joint:?}");
}
