//! The thesis track behind the mechanism seam: poses agree with the track's own kinematics,
//! speed bounds hold against finite differences, input and deflection invert each other,
//! and the loads cross-check by virtual work.

use flapwright_kinds::CircularArcTrack;
use flapwright_mechanism::seam::{posed_shape, FlapMechanism, JointEnd, PlanarShape};
use flapwright_mechanism::LoadCase;
use nalgebra::Point2;

use crate::common::thesis_track;

fn inputs(track: &CircularArcTrack, samples: usize) -> Vec<f64> {
    track.input_range().samples(samples)
}

#[test]
fn body_displacements_carry_the_stowed_points_to_the_tracks_own_pose() {
    let track = thesis_track();
    let stowed = FlapMechanism::pose(&track, track.input_range().stowed).unwrap();
    for bodies in &stowed.bodies {
        assert!((bodies.translation.vector.norm() + bodies.rotation.angle().abs()) < 1e-12);
    }
    let at_stowed = |name: &str| stowed.point(name).unwrap();
    for input in inputs(&track, 41) {
        let pose = FlapMechanism::pose(&track, input).unwrap();
        assert_eq!(pose.input, input);
        let own = CircularArcTrack::pose(&track, input, 0.0, 0.0).unwrap();
        assert_eq!(pose.deflection_rad, own.deflection_rad);
        let deflection = own.deflection_rad;
        let close = |a: Point2<f64>, b: Point2<f64>, what: &str| {
            assert!((a - b).norm() < 1e-12, "{what} at {deflection}: {a} vs {b}");
        };
        // The flap (body 0) carries D, F, G; the nut (body 2) carries A; the screw (body
        // 1) carries B; the flap's displacement is body 0's.
        close(pose.bodies[0] * at_stowed("D"), own.centre_of_mass_d.position_m, "D");
        close(pose.bodies[0] * at_stowed("F"), own.outer_pin_f.position_m, "F");
        close(pose.bodies[0] * at_stowed("G"), own.inner_pin_g.position_m, "G");
        close(pose.bodies[2] * at_stowed("A"), own.nut_pivot_a.position_m, "A");
        close(pose.bodies[1] * at_stowed("B"), own.screw_end_b.position_m, "B");
        close(pose.bodies[1] * at_stowed("B0"), at_stowed("B0"), "B0 fixed");
        assert_eq!(pose.flap, pose.bodies[0]);
        // The screw still points at the nut pivot.
        let screw = &track.bodies()[1].solids[0].shape;
        let PlanarShape::Capsule { from, to, .. } = posed_shape(screw, &pose.bodies[1]) else {
            panic!("the screw is a capsule");
        };
        let a = own.nut_pivot_a.position_m;
        assert!((to - from).perp(&(a - from)).abs() < 1e-12 * (to - from).norm() * (a - from).norm());
    }
}

#[test]
fn input_and_deflection_invert_each_other() {
    let track = thesis_track();
    let range = track.input_range();
    assert_eq!(range.stowed, track.synthesis().stroke_start_m);
    assert_eq!(range.deployed, track.synthesis().stroke_end_m);
    for input in range.samples(33) {
        let deflection = track.deflection_at_input(input).unwrap();
        let back = track.input_at_deflection(deflection).unwrap();
        assert!((back - input).abs() < 1e-12, "{input} -> {deflection} -> {back}");
    }
    assert!(track.deflection_at_input(range.deployed).unwrap() - track.deflection_range_rad() < 1e-12);
}

#[test]
fn speed_bounds_hold_against_finite_differences() {
    speed_bounds_hold(&thesis_track(), 0.25);
}

/// Every skeleton point of every solid of `mechanism`, at 2001 inputs: the finite-difference
/// speed (m per unit input) stays within the body's bound for that solid, which is also not
/// loose by more than a factor of `1 / tightness` for the moving bodies; fixed bodies do
/// not move. Shared by every kind's tests.
pub fn speed_bounds_hold(mechanism: &dyn FlapMechanism, tightness: f64) {
    let steps = mechanism.input_range().samples(2001);
    let h = (steps[1] - steps[0]).abs();
    for (b, body) in mechanism.bodies().iter().enumerate() {
        for solid in &body.solids {
            let bound = body.speed_bound.for_shape(&solid.shape);
            let mut fastest: f64 = 0.0;
            let mut previous: Option<Vec<Point2<f64>>> = None;
            for &input in &steps {
                let pose = mechanism.pose(input).unwrap();
                let points: Vec<Point2<f64>> = solid.shape.skeleton().iter().map(|p| pose.bodies[b] * p).collect();
                if let Some(before) = &previous {
                    for (p, q) in points.iter().zip(before) {
                        fastest = fastest.max((p - q).norm() / h);
                    }
                }
                previous = Some(points);
            }
            assert!(
                fastest <= bound * (1.0 + 1e-9),
                "{} {}: {fastest} > bound {bound}",
                mechanism.kind(),
                solid.name
            );
            if body.is_moving() {
                assert!(
                    fastest > tightness * bound,
                    "{} {}: bound {bound} loose (fastest {fastest})",
                    mechanism.kind(),
                    solid.name
                );
            } else {
                assert_eq!(fastest, 0.0, "{} is fixed", solid.name);
            }
        }
    }
}

#[test]
fn joints_name_existing_bodies_and_solids() {
    joints_name_existing(&thesis_track());
}

/// Every joint's ends are bodies of `mechanism` and its touching solids exist.
pub fn joints_name_existing(mechanism: &dyn FlapMechanism) {
    let solids: Vec<&str> = mechanism
        .bodies()
        .iter()
        .flat_map(|b| b.solids.iter().map(|s| s.name.as_str()))
        .collect();
    for joint in mechanism.joints() {
        for end in joint.ends {
            if let JointEnd::Body(i) = end {
                assert!(i < mechanism.bodies().len(), "{}", joint.name);
            }
        }
        for (x, y) in &joint.touching_solids {
            assert!(
                solids.contains(&x.as_str()) && solids.contains(&y.as_str()),
                "{} {}: {x} or {y}",
                mechanism.kind(),
                joint.name
            );
        }
    }
}

#[test]
fn loads_cross_check_by_virtual_work_and_key_reactions_by_joint() {
    let track = thesis_track();
    let joint_names: Vec<&str> = track.joints().iter().map(|j| j.name.as_str()).collect();
    for load in [LoadCase::thesis_cruise(), LoadCase::thesis_landing()] {
        for input in track.input_range().samples(21) {
            let loads = track.kinetostatics(input, &load).unwrap();
            let scale = loads.actuator_load.abs().max(1.0);
            assert!(
                (loads.actuator_load - loads.actuator_load_virtual_work).abs() < 1e-9 * scale,
                "{input}: {} vs {}",
                loads.actuator_load,
                loads.actuator_load_virtual_work
            );
            for (joint, reaction) in &loads.reactions {
                assert!(joint_names.contains(&joint.as_str()), "{joint}");
                assert!(reaction.is_finite());
            }
            assert!(loads.transmission_angle_rad > 0.0);
        }
    }
}

#[test]
fn flap_attachments_move_with_the_flap() {
    let track = thesis_track();
    let attachments = track.flap_attachments();
    assert_eq!(attachments.len(), 3);
    for input in inputs(&track, 9) {
        let pose = FlapMechanism::pose(&track, input).unwrap();
        for attachment in &attachments {
            let moved = pose.flap * attachment.position;
            let named = pose.point(attachment.name).unwrap();
            assert!((moved - named).norm() < 1e-12, "{} at {input}", attachment.name);
        }
    }
}

#[test]
fn a_deployment_through_the_seam_is_the_tracks_own_sweep() {
    // The kind-neutral sweep gives the thesis track's own numbers, sample for sample.
    let track = thesis_track();
    for load in [LoadCase::thesis_cruise(), LoadCase::thesis_landing()] {
        let seam = flapwright_mechanism::sweep_deployment(&track, 51, &load).unwrap();
        // The same inputs as the track's own sweep, to rounding (stowed + i (deployed -
        // stowed) / 50 against s34,i + i Δs / 50); then exactly the same samples.
        let reference = track.sweep(51, &load).unwrap();
        for (s, o) in seam.samples.iter().zip(&reference.samples) {
            assert!((s.input - o.input_m).abs() <= 1e-15, "{} vs {}", s.input, o.input_m);
        }
        let own = track.sweep_at(seam.samples.iter().map(|s| s.input), &load);
        assert_eq!(seam.samples.len(), own.samples.len());
        assert!(seam.stopped.is_none() && own.stopped.is_none());
        for (s, o) in seam.samples.iter().zip(&own.samples) {
            assert_eq!(s.input, o.input_m);
            assert_eq!(s.deflection_deg, o.deflection_deg);
            assert_eq!(s.actuator_load, o.actuator_force_n);
            assert_eq!(s.actuator_load_cross_check_relative, o.force_cross_check_relative);
            assert_eq!(s.reactions_n["A"], o.joint_reactions_n.nut_pivot_a_n);
            assert_eq!(s.reactions_n["B0"], o.joint_reactions_n.screw_mount_b0_n);
            assert_eq!(s.reactions_n["F"], o.joint_reactions_n.outer_pin_f_n);
            assert_eq!(s.reactions_n["G"], o.joint_reactions_n.inner_pin_g_n);
            let screw = s.actuator_torques_nm.unwrap();
            assert_eq!(screw.raise_torque_nm, o.raise_torque_nm);
            assert_eq!(screw.lower_torque_nm, o.lower_torque_nm);
            assert_eq!(s.jacobian_condition_number, o.jacobian_condition_number);
            assert_eq!(s.distance_to_toggle_deg, o.distance_to_toggle_deg);
        }
    }
}
