//! Velocities and accelerations against central finite differences of positions, and the
//! virtual-work force against the equilibrium force.

use approx::assert_relative_eq;
use flapwright_kinds::{CircularArcTrack, Pose};
use flapwright_mechanism::LoadCase;
use nalgebra::{Point2, Vector2};

use crate::common::thesis_track;

/// Nut speed (m/s) and acceleration (m/s²) for the check: large enough that accelerations
/// dwarf rounding in the second difference, non-zero s̈ so that no α crosses zero.
const SPEED: f64 = 1.0;
const ACCEL: f64 = 3.0;
/// Time step of the central differences (s).
const STEP_S: f64 = 2e-4;

fn points(pose: &Pose) -> [Point2<f64>; 5] {
    [
        pose.nut_pivot_a.position_m,
        pose.screw_end_b.position_m,
        pose.centre_of_mass_d.position_m,
        pose.outer_pin_f.position_m,
        pose.inner_pin_g.position_m,
    ]
}

fn pose_at_time(track: &CircularArcTrack, start: f64, t: f64) -> Pose {
    let input = start + SPEED * t + 0.5 * ACCEL * t * t;
    track.pose(input, SPEED + ACCEL * t, ACCEL).unwrap()
}

/// Fourth-order central differences (first and second derivative) of samples at -2h..2h.
fn derivatives(values: [f64; 5], h: f64) -> (f64, f64) {
    let [m2, m1, c, p1, p2] = values;
    let first = (m2 - 8.0 * m1 + 8.0 * p1 - p2) / (12.0 * h);
    let second = (-m2 + 16.0 * m1 - 30.0 * c + 16.0 * p1 - p2) / (12.0 * h * h);
    (first, second)
}

#[test]
fn rates_match_finite_differences_at_every_sample() {
    let track = thesis_track();
    let synthesis = track.synthesis();
    let margin = 1e-3;
    let samples = 41;
    for i in 0..samples {
        let start =
            synthesis.stroke_start_m + margin + (synthesis.stroke_m - 2.0 * margin) * i as f64 / (samples - 1) as f64;
        let poses: Vec<Pose> = (-2..=2)
            .map(|k| pose_at_time(&track, start, k as f64 * STEP_S))
            .collect();
        let centre = &poses[2];
        let l = centre.linkage;
        let angle = |f: fn(&Pose) -> f64| derivatives([0, 1, 2, 3, 4].map(|k| f(&poses[k])), STEP_S);
        let (w12, a12) = angle(|p| p.linkage.crank_angle_rad);
        let (w13, a13) = angle(|p| p.linkage.slider_angle_rad);
        assert_relative_eq!(l.crank_rate_radps, w12, max_relative = 1e-6);
        assert_relative_eq!(l.slider_rate_radps, w13, max_relative = 1e-6);
        assert_relative_eq!(l.crank_accel_radps2, a12, max_relative = 1e-6);
        assert_relative_eq!(l.slider_accel_radps2, a13, max_relative = 1e-6);

        let analytic = [
            centre.nut_pivot_a,
            centre.screw_end_b,
            centre.centre_of_mass_d,
            centre.outer_pin_f,
            centre.inner_pin_g,
        ];
        for (index, kinematics) in analytic.iter().enumerate() {
            for axis in 0..2 {
                let values = [0, 1, 2, 3, 4].map(|k| points(&poses[k])[index][axis]);
                let (velocity, acceleration) = derivatives(values, STEP_S);
                let v = Vector2::new(kinematics.velocity_mps[axis], 0.0);
                let a = Vector2::new(kinematics.acceleration_mps2[axis], 0.0);
                // Relative to the point's speed / acceleration magnitude, so a component
                // passing through zero is still held to 1e-6.
                let v_scale = kinematics.velocity_mps.norm();
                let a_scale = kinematics.acceleration_mps2.norm();
                assert!((v.x - velocity).abs() <= 1e-6 * v_scale, "point {index} axis {axis} v");
                assert!(
                    (a.x - acceleration).abs() <= 1e-6 * a_scale,
                    "point {index} axis {axis} a"
                );
            }
        }
    }
}

#[test]
fn virtual_work_equals_equilibrium() {
    let track = thesis_track();
    for load in [LoadCase::thesis_cruise(), LoadCase::thesis_landing()] {
        let sweep = track.sweep(200, &load).unwrap();
        assert_eq!(sweep.samples.len(), 200);
        for sample in &sweep.samples {
            assert!(sample.force_cross_check_relative <= 1e-9, "{sample:?}");
        }
        // Also through the zero-speed (unit virtual velocity) path.
        for sample in sweep.samples.iter().step_by(17) {
            let pose = track.pose(sample.input_m, 0.0, 0.0).unwrap();
            let forces = track.forces(&pose, &load).unwrap();
            assert_relative_eq!(
                forces.actuator_force_virtual_work_n,
                forces.actuator_force_n,
                max_relative = 1e-9
            );
        }
    }
}

#[test]
fn slot_reactions_balance_the_flap() {
    // Sum of forces on the flap (eqs. 3.4.8/3.4.9) and moments about A0 (eq. 3.4.7) vanish.
    let track = thesis_track();
    let spec = *track.spec();
    let weight = spec.flap_mass_kg * spec.gravity_mps2;
    for sample in track.sweep(25, &LoadCase::thesis_landing()).unwrap().samples {
        let pose = track.pose(sample.input_m, 0.0, 0.0).unwrap();
        let forces = track.forces(&pose, &LoadCase::thesis_landing()).unwrap();
        let radial = |p: Point2<f64>| p.coords.normalize();
        let screw = spec.base_angle_rad + pose.linkage.slider_angle_rad;
        let along_screw = Vector2::new(screw.cos(), screw.sin()) * forces.actuator_force_n;
        let total = radial(pose.inner_pin_g.position_m) * forces.inner_slot_reaction_n
            + radial(pose.outer_pin_f.position_m) * forces.outer_slot_reaction_n
            + along_screw
            + Vector2::new(0.0, -weight);
        assert!(total.norm() <= 1e-9 * forces.outer_slot_reaction_n.abs(), "{total}");
        let a = pose.nut_pivot_a.position_m.coords;
        let d = pose.centre_of_mass_d.position_m.coords;
        let moment = a.perp(&along_screw) + d.perp(&Vector2::new(0.0, -weight)) - forces.external_moment_nm;
        assert!(moment.abs() <= 1e-9 * forces.external_moment_nm.abs(), "{moment}");
    }
}

#[test]
fn inertia_balances_by_virtual_work_and_by_newton_euler() {
    use flapwright_kinds::CircularArcTrackSpec;
    use flapwright_mechanism::ExternalMoment;
    let spec = CircularArcTrackSpec {
        flap_moment_of_inertia_kgm2: 0.8,
        ..CircularArcTrackSpec::thesis_case_study()
    };
    let track = CircularArcTrack::synthesise(spec).unwrap();
    let load = LoadCase {
        name: "fast".into(),
        external_moment: ExternalMoment::Linear {
            stowed_nm: 110.0,
            deployed_nm: 325.0,
        },
        include_inertia: true,
        flap_normal_force: None,
        load_factor: 1.0,
    };
    let weight = spec.flap_mass_kg * spec.gravity_mps2;
    let synthesis = track.synthesis();
    for i in 0..=12 {
        let input = synthesis.stroke_start_m + synthesis.stroke_m * f64::from(i) / 12.0;
        let pose = track.pose(input, 0.5, 2.0).unwrap();
        let forces = track.forces(&pose, &load).unwrap();
        assert_relative_eq!(
            forces.actuator_force_virtual_work_n,
            forces.actuator_force_n,
            max_relative = 1e-9
        );
        // Newton-Euler on the flap: ΣF = m a_D, ΣM_A0 = I_D α12 + D × m a_D.
        let a_d = pose.centre_of_mass_d.acceleration_mps2 * spec.flap_mass_kg;
        let screw = spec.base_angle_rad + pose.linkage.slider_angle_rad;
        let push = Vector2::new(screw.cos(), screw.sin()) * forces.actuator_force_n;
        let total = pose.inner_pin_g.position_m.coords.normalize() * forces.inner_slot_reaction_n
            + pose.outer_pin_f.position_m.coords.normalize() * forces.outer_slot_reaction_n
            + push
            + Vector2::new(0.0, -weight);
        assert!((total - a_d).norm() <= 1e-9 * forces.outer_slot_reaction_n.abs());
        let d = pose.centre_of_mass_d.position_m.coords;
        let moment = pose.nut_pivot_a.position_m.coords.perp(&push) + d.perp(&Vector2::new(0.0, -weight))
            - forces.external_moment_nm;
        let expected = spec.flap_moment_of_inertia_kgm2 * pose.linkage.crank_accel_radps2 + d.perp(&a_d);
        assert!((moment - expected).abs() <= 1e-9 * forces.external_moment_nm.abs());
    }
    // At the thesis's 35 mm/s the inertia changes F_input by far less than 0.1 % (Fig. 31).
    let slow = LoadCase {
        include_inertia: true,
        flap_normal_force: None,
        ..LoadCase::thesis_landing()
    };
    for i in 0..=12 {
        let input = synthesis.stroke_start_m + synthesis.stroke_m * f64::from(i) / 12.0;
        let pose = track.pose(input, 0.035, 0.0).unwrap();
        let with = track.forces(&pose, &slow).unwrap().actuator_force_n;
        let without = track
            .forces(&pose, &LoadCase::thesis_landing())
            .unwrap()
            .actuator_force_n;
        assert_relative_eq!(with, without, max_relative = 1e-3);
    }
}
