//! The general planar model (Newton + analytic Jacobian) against the closed-form track.

use approx::assert_relative_eq;
use flapwright_kinds::CircularArcTrack;
use flapwright_mechanism::planar::{BodyPoint, Driver, Joint, PlanarModel};
use flapwright_mechanism::Error;
use nalgebra::Vector2;

use crate::common::thesis_track;

fn point(body: usize, x: f64, y: f64) -> BodyPoint {
    BodyPoint {
        body,
        local_m: Vector2::new(x, y),
    }
}

/// Bodies: 1 flap (frame at A0, angle = deflection), 2 screw (frame at B0 along the
/// screw), 3 nut (frame at A along the screw). Stowed coordinates returned beside it.
fn thesis_as_general_model(track: &CircularArcTrack) -> (PlanarModel, Vec<f64>) {
    let spec = track.spec();
    let synthesis = track.synthesis();
    let (a, b0) = (synthesis.nut_pivot_stowed_m, synthesis.screw_mount_m);
    let (g, f) = (synthesis.inner_pin_stowed_m, synthesis.outer_pin_stowed_m);
    let screw_angle = spec.base_angle_rad + synthesis.end_slider_angle_rad;
    let model = PlanarModel {
        bodies: ["ground", "flap", "screw", "nut"].map(String::from).to_vec(),
        joints: vec![
            Joint::Revolute {
                name: "B0".into(),
                a: point(0, b0.x, b0.y),
                b: point(2, 0.0, 0.0),
            },
            Joint::Revolute {
                name: "A".into(),
                a: point(1, a.x, a.y),
                b: point(3, 0.0, 0.0),
            },
            Joint::Prismatic {
                name: "nut".into(),
                a: point(2, 0.0, 0.0),
                axis_local: Vector2::x(),
                b: point(3, 0.0, 0.0),
                angle_offset_rad: 0.0,
            },
            Joint::PinInCircularSlot {
                name: "G".into(),
                pin: point(1, g.x, g.y),
                centre: point(0, 0.0, 0.0),
                radius_m: spec.inner_slot_radius_m,
            },
            Joint::PinInCircularSlot {
                name: "F".into(),
                pin: point(1, f.x, f.y),
                centre: point(0, 0.0, 0.0),
                radius_m: spec.outer_slot_radius_m,
            },
        ],
        driver: Driver::Distance {
            a: point(0, b0.x, b0.y),
            b: point(3, 0.0, 0.0),
        },
    };
    let stowed = vec![0.0, 0.0, 0.0, b0.x, b0.y, screw_angle, a.x, a.y, screw_angle];
    (model, stowed)
}

#[test]
fn general_model_reproduces_the_closed_form_track() {
    let track = thesis_track();
    let (model, stowed) = thesis_as_general_model(&track);
    let synthesis = track.synthesis();
    let inputs: Vec<f64> = (0..=30)
        .map(|i| synthesis.stroke_start_m + synthesis.stroke_m * f64::from(i) / 30.0)
        .collect();
    let (rate, accel) = (0.035, 0.02);
    let (solutions, stop) = model.sweep(&inputs, rate, accel, &stowed);
    assert!(stop.is_none(), "{stop:?}");
    assert_eq!(solutions.len(), inputs.len());
    let base = track.spec().base_angle_rad;
    for solution in &solutions {
        let pose = track.pose(solution.input, rate, accel).unwrap();
        let l = pose.linkage;
        assert!(solution.closure_residual < 1e-12);
        assert!(solution.jacobian_condition_number.is_finite());
        assert_relative_eq!(solution.coordinates[2], pose.deflection_rad, epsilon = 1e-12);
        assert_relative_eq!(solution.coordinates[5], base + l.slider_angle_rad, max_relative = 1e-12);
        assert_relative_eq!(solution.rates[2], l.crank_rate_radps, max_relative = 1e-9);
        assert_relative_eq!(
            solution.rates[5],
            l.slider_rate_radps,
            max_relative = 1e-9,
            epsilon = 1e-12
        );
        assert_relative_eq!(
            solution.accelerations[2],
            l.crank_accel_radps2,
            max_relative = 1e-9,
            epsilon = 1e-12
        );
        assert_relative_eq!(
            solution.accelerations[5],
            l.slider_accel_radps2,
            max_relative = 1e-9,
            epsilon = 1e-12
        );
        // Flap stays on its hinge: the frame origin of body 1 does not move.
        assert!(solution.coordinates[0].abs() < 1e-12 && solution.coordinates[1].abs() < 1e-12);
    }
}

#[test]
fn general_model_reports_unreachable_input_and_bad_counts() {
    let track = thesis_track();
    let (model, stowed) = thesis_as_general_model(&track);
    // Far beyond a1 + a2 the nut cannot reach: Newton fails and names the input.
    let (solutions, stop) = model.sweep(&[0.1, 0.9], 0.0, 0.0, &stowed);
    assert_eq!(solutions.len(), 1);
    assert!(
        matches!(stop, Some(Error::NotConverged { input, .. } | Error::SingularJacobian { input, .. }) if input == 0.9)
    );
    let mut broken = model.clone();
    broken.joints.pop();
    assert!(matches!(broken.validate(), Err(Error::ConstraintCountMismatch { .. })));
}
