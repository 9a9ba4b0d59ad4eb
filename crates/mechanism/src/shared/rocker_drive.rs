//! A body turning about a fixed pivot, pushed round by a screw jack between a fixed mount
//! and a point of the body: the drive of the dropped hinge (the flap turns about its hinge)
//! and of the four-bar (its crank turns about its ground pivot). It is the thesis's inverted
//! slider-crank ([`InvertedSliderCrank`]: pivot = A0, mount = B0, attachment = A) with the
//! sense of turning kept, so the attachment may lie either side of the line pivot-mount.
//!
//! Frame: the station frame (x towards the nose, y up), angles counter-clockwise positive.
//! The body's rotation from stowed is ψ = σ (γ(s) - γ(s0)), with γ the angle at the pivot
//! between the mount and the attachment (the slider-crank's θ12 in [0, π]) and σ = +1 when
//! the attachment lies counter-clockwise of the mount seen from the pivot. Since
//! s² = a1² + a2² - 2 a1 a2 cos γ, dγ/ds = s / (a1 a2 sin γ) = 1 / (a2 sin μ), μ the
//! transmission angle at the attachment.

use nalgebra::{Isometry2, Point2, Rotation2, Translation2, Unit, Vector2};
use serde::Serialize;

use crate::error::{Error, Result};
use crate::seam::{Body, BodyRole, BodySolid, Joint, JointEnd, JointGeometry, SpeedBound};
use crate::shared::geometry::{cross, turn_about};
use crate::shared::slider_crank::InvertedSliderCrank;

/// A screw jack turning a body about a fixed pivot.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RockerDrive {
    pivot: Point2<f64>,
    mount: Point2<f64>,
    attachment: Point2<f64>,
    linkage: InvertedSliderCrank,
    sense: f64,
    stowed_angle_rad: f64,
}

/// The drive at one stroke.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RockerState {
    /// The body's rotation from stowed about the pivot (rad, counter-clockwise).
    pub rotation_rad: f64,
    /// dψ/ds (rad per metre of stroke).
    pub rotation_per_stroke: f64,
    /// Where the attachment stands (m).
    pub attachment: Point2<f64>,
    /// Transmission angle at the attachment, between pivot-attachment and the screw (rad,
    /// acute): π/2 best, 0 a toggle.
    pub transmission_angle_rad: f64,
    /// Loop-closure residual (m).
    pub closure_residual_m: f64,
    /// Condition number of the loop's position Jacobian.
    pub jacobian_condition_number: f64,
}

/// The angle of `v` (rad).
fn direction(v: Vector2<f64>) -> f64 {
    v.y.atan2(v.x)
}

impl RockerDrive {
    /// The drive with the body's pivot, the screw's fixed mount and the screw's attachment
    /// on the body (stowed). Errors: [`Error::InvalidDimension`] when two of the points
    /// coincide or the three lie on one line (the screw could not turn the body).
    pub fn try_new(pivot: Point2<f64>, mount: Point2<f64>, attachment: Point2<f64>) -> Result<Self> {
        let (to_mount, to_attachment) = (mount - pivot, attachment - pivot);
        let linkage = InvertedSliderCrank::try_new(to_mount.norm(), to_attachment.norm(), direction(to_mount))?;
        let turn = cross(to_mount, to_attachment);
        if turn.is_nan() || turn.abs() <= 1e-9 * to_mount.norm() * to_attachment.norm() {
            return Err(Error::InvalidDimension {
                name: "actuator line (mount, pivot and attachment on one line)",
                value: turn,
            });
        }
        let (stowed_angle_rad, _) = linkage.angles((attachment - mount).norm())?;
        Ok(Self {
            pivot,
            mount,
            attachment,
            linkage,
            sense: turn.signum(),
            stowed_angle_rad,
        })
    }

    /// The pivot (m).
    pub fn pivot(&self) -> Point2<f64> {
        self.pivot
    }

    /// The screw's fixed mount (m).
    pub fn mount(&self) -> Point2<f64> {
        self.mount
    }

    /// The attachment on the body, stowed (m).
    pub fn attachment(&self) -> Point2<f64> {
        self.attachment
    }

    /// The stroke |attachment - mount| with the body turned by `rotation_rad` (m).
    pub fn stroke_at(&self, rotation_rad: f64) -> f64 {
        (turn_about(self.pivot, rotation_rad) * self.attachment - self.mount).norm()
    }

    /// The largest |dψ/ds| (rad/m) while the body turns from 0 to `rotation_rad` and no
    /// toggle lies between: |dγ/ds| = s / (a1 a2 sin γ) with γ linear in ψ, so s is largest
    /// and sin γ smallest (sin is concave on [0, π]) at an end.
    pub fn rotation_rate_bound(&self, rotation_rad: f64) -> f64 {
        let (a1, a2) = (self.linkage.base_distance_m, self.linkage.crank_length_m);
        let end = self.stowed_angle_rad + self.sense * rotation_rad;
        let smallest_sine = self.stowed_angle_rad.sin().min(end.sin());
        let largest_stroke = self.stroke_at(0.0).max(self.stroke_at(rotation_rad));
        largest_stroke / (a1 * a2 * smallest_sine)
    }

    /// The smallest transmission angle (rad) at `samples` + 1 rotations evenly from 0 to
    /// `rotation_rad` (0 where a sample fails: a toggle).
    pub fn min_transmission_rad(&self, rotation_rad: f64, samples: usize) -> f64 {
        (0..=samples)
            .map(|k| {
                let psi = rotation_rad * k as f64 / samples as f64;
                self.state(self.stroke_at(psi))
                    .map_or(0.0, |state| state.transmission_angle_rad)
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// The pressure angles at the two ends of a rotation from 0 to `rotation_rad` (rad):
    /// between the screw's force and the attachment's velocity, π/2 less the transmission
    /// angle (`004_...`'s figure of merit: small and equal at both ends). NaN at an end the
    /// drive cannot reach.
    pub fn end_pressure_angles_rad(&self, rotation_rad: f64) -> [f64; 2] {
        [0.0, rotation_rad].map(|psi| {
            self.state(self.stroke_at(psi)).map_or(f64::NAN, |state| {
                std::f64::consts::FRAC_PI_2 - state.transmission_angle_rad
            })
        })
    }

    /// True when the body turns from 0 to `rotation_rad` without the screw passing through
    /// the pivot's line (a toggle): γ stays inside (0, π) with `margin_rad` to spare.
    pub fn clear_of_toggles(&self, rotation_rad: f64, margin_rad: f64) -> bool {
        let end = self.stowed_angle_rad + self.sense * rotation_rad;
        let (lo, hi) = (self.stowed_angle_rad.min(end), self.stowed_angle_rad.max(end));
        lo >= margin_rad && hi <= std::f64::consts::PI - margin_rad
    }

    /// Why this drive cannot turn its body from 0 to `rotation_rad` with a transmission
    /// angle of at least `min_rad` (sampled `samples` + 1 times), in words for a synthesis
    /// failure naming `holder` (what the screw takes hold of); `None` when it can. A
    /// toggle inside the rotation is named as such: the sampled angles may all pass the
    /// minimum while the screw's line sweeps through the pivot between them.
    pub fn transmission_problem(
        &self,
        rotation_rad: f64,
        min_rad: f64,
        samples: usize,
        holder: &str,
    ) -> Option<String> {
        let smallest = self.min_transmission_rad(rotation_rad, samples);
        if !self.clear_of_toggles(rotation_rad, 1e-3) {
            Some(format!(
                "the screw on the {holder} passes through a toggle (its line through the pivot) within the deployment; move the actuator mount or its attachment"
            ))
        } else if smallest < min_rad {
            Some(format!(
                "the screw's transmission angle on the {holder} falls to {:.1} deg, below the minimum of {:.1} deg; move the actuator mount or its attachment",
                smallest.to_degrees(),
                min_rad.to_degrees()
            ))
        } else {
            None
        }
    }

    /// The drive at stroke `stroke_m`. Errors: [`Error::CannotAssemble`] beyond the
    /// triangle's reach, [`Error::Toggle`] within the toggle tolerance.
    pub fn state(&self, stroke_m: f64) -> Result<RockerState> {
        let state = self.linkage.state(stroke_m, 1.0, 0.0)?;
        let rotation_rad = self.sense * (state.crank_angle_rad - self.stowed_angle_rad);
        let attachment = turn_about(self.pivot, rotation_rad) * self.attachment;
        let closure = ((attachment - self.mount).norm() - stroke_m).abs();
        Ok(RockerState {
            rotation_rad,
            rotation_per_stroke: self.sense * state.crank_rate_per_input_radpm,
            attachment,
            transmission_angle_rad: state.transmission_angle_rad,
            closure_residual_m: closure.max(state.closure_residual_m),
            jacobian_condition_number: state.jacobian_condition_number,
        })
    }

    /// The screw's turn about its mount from stowed (rad) with the attachment at `attachment`.
    pub fn screw_rotation(&self, attachment: Point2<f64>) -> f64 {
        let stowed = self.attachment - self.mount;
        let now = attachment - self.mount;
        Rotation2::rotation_between(&stowed, &now).angle()
    }
}

/// The screw jack of a [`RockerDrive`] as two bodies of a mechanism and their three joints,
/// for every kind that turns a body with one: the screw with its jack body, turning about
/// the mount B0, and the nut at the attachment, pivoting on the driven body and riding
/// along the screw.
pub struct ScrewJackParts<'a> {
    /// The drive.
    pub drive: &'a RockerDrive,
    /// The driven body's rotation over the deployment (rad).
    pub rotation_rad: f64,
    /// The screw's length (m) and outer radius (m).
    pub screw_length_m: f64,
    /// Outer radius of the screw (m).
    pub screw_radius_m: f64,
    /// Nut and jack-body sizes.
    pub hardware: &'a crate::shared::flap_load::LinkHardware,
    /// Indices of the driven body, the screw and the nut in the kind's bodies.
    pub indices: [usize; 3],
    /// The nut's pivot on the driven body: its joint name and the driven body's solid it
    /// sits on.
    pub pivot: (&'a str, &'a str),
}

impl ScrewJackParts<'_> {
    /// The screw and the nut (in that order) and the joints at the nut's pivot, along the
    /// screw and at B0. Speed bounds per metre of stroke: the driven body turns at most at
    /// [`RockerDrive::rotation_rate_bound`], so the attachment moves at most `arm` times
    /// that, and the screw turns at most that speed over the shortest stroke.
    pub fn build(&self) -> (Vec<Body>, Vec<Joint>) {
        let (b0, p) = (self.drive.mount(), self.drive.attachment());
        let [driven, screw, nut] = self.indices;
        let body_rate = self.drive.rotation_rate_bound(self.rotation_rad);
        let attachment_speed = (p - self.drive.pivot()).norm() * body_rate;
        let shortest = self.drive.stroke_at(0.0).min(self.drive.stroke_at(self.rotation_rad));
        let screw_rate = attachment_speed / shortest;
        let direction = (p - b0).normalize();
        let half_body = direction * (0.5 * self.hardware.jack_body_length_m);
        let bodies = vec![
            Body {
                name: "screw".into(),
                role: BodyRole::Actuator,
                solids: vec![
                    BodySolid::capsule("screw", b0, b0 + direction * self.screw_length_m, self.screw_radius_m),
                    BodySolid::capsule(
                        "jack-body",
                        b0 - half_body,
                        b0 + half_body,
                        self.hardware.jack_body_radius_m,
                    ),
                ],
                speed_bound: SpeedBound {
                    reference: b0,
                    linear_per_input: 0.0,
                    angular_per_input: screw_rate,
                },
            },
            Body {
                name: "nut".into(),
                role: BodyRole::Actuator,
                solids: vec![BodySolid::capsule("nut", p, p, self.hardware.nut_radius_m)],
                speed_bound: SpeedBound {
                    reference: p,
                    linear_per_input: attachment_speed,
                    angular_per_input: screw_rate,
                },
            },
        ];
        let (pivot_name, holder) = self.pivot;
        let joints = vec![
            Joint::new(
                pivot_name,
                "nut pivoting on the driven link",
                JointGeometry::Revolute { at: p },
                [JointEnd::Body(nut), JointEnd::Body(driven)],
                &[("nut", holder)],
            ),
            Joint::new(
                "nut-slide",
                "nut riding along the screw",
                JointGeometry::Prismatic {
                    origin: p,
                    direction: Unit::new_normalize(p - b0),
                },
                [JointEnd::Body(screw), JointEnd::Body(nut)],
                &[("screw", "nut")],
            ),
            Joint::new(
                "B0",
                "screw turning in the jack body",
                JointGeometry::Revolute { at: b0 },
                [JointEnd::Ground, JointEnd::Body(screw)],
                &[],
            ),
        ];
        (bodies, joints)
    }
}

impl RockerDrive {
    /// The screw's and the nut's displacements from stowed with the attachment at
    /// `attachment`: the screw turns about the mount, the nut moves with the attachment
    /// and turns with the screw.
    pub fn screw_and_nut(&self, attachment: Point2<f64>) -> (Isometry2<f64>, Isometry2<f64>) {
        let turn = self.screw_rotation(attachment);
        let nut = Translation2::from(attachment.coords)
            * Isometry2::rotation(turn)
            * Translation2::from(-self.attachment.coords);
        (turn_about(self.mount, turn), nut)
    }
}

/// A mount for a screw pushing `attachment` round `pivot` by `rotation_rad`: at `standoff_m`
/// behind the attachment's mid-travel position, along the line of its motion there, so the
/// screw is square to the arm at mid-travel (transmission angle π/2), the transmission angle
/// at both ends is about π/2 - |rotation|/2, and the stroke grows as the body turns.
///
/// This is `004_...`'s closed-form installation (Yastrebov & Polyushkova, eqs. 4-5: the end
/// positions symmetric, ±θ/2, about the position where the rod is tangent to the crank's
/// circle), with the crank the pivot-attachment arm and the pivot distance the
/// pivot-mount one: test `the_square_mount_is_004s_installation` checks the end pressure
/// angles against [`crate::landing_gear::LandingGearSpec::synthesise`].
pub fn mount_square_at_mid_travel(
    pivot: Point2<f64>,
    attachment: Point2<f64>,
    rotation_rad: f64,
    standoff_m: f64,
) -> Point2<f64> {
    let middle = turn_about(pivot, 0.5 * rotation_rad) * attachment;
    let arm = middle - pivot;
    // Velocity direction of the attachment when the body turns by +rotation.
    let motion = Vector2::new(-arm.y, arm.x).normalize() * rotation_rad.signum();
    middle - motion * standoff_m
}

/// How a screw jack stands against `004_...`'s installation: what the report says of a
/// placed jack (issue 37, "actuators placed by rule").
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct JackInstallation {
    /// The pressure angles at stowed and at the end of the rotation (rad,
    /// [`RockerDrive::end_pressure_angles_rad`]): `004_...` makes them small and equal.
    pub end_pressure_angles_rad: [f64; 2],
    /// The mount's turn from `004_...`'s installation at the same distance
    /// ([`mount_turn_from_square`], rad): 0 where the placement kept it.
    pub mount_turn_from_004_rad: f64,
}

impl JackInstallation {
    /// The installation of `drive` turning its body by `rotation_rad`.
    pub fn of(drive: &RockerDrive, rotation_rad: f64) -> Self {
        Self {
            end_pressure_angles_rad: drive.end_pressure_angles_rad(rotation_rad),
            mount_turn_from_004_rad: mount_turn_from_square(drive.pivot, drive.attachment, rotation_rad, drive.mount),
        }
    }
}

/// How far `mount` stands turned about the attachment's mid-travel position from the mount
/// [`mount_square_at_mid_travel`] places at the same distance (rad, counter-clockwise): 0
/// where a placement kept `004_...`'s installation, the turn a placement search gave it to
/// keep the jack clear of the wing or to lower its load otherwise.
pub fn mount_turn_from_square(
    pivot: Point2<f64>,
    attachment: Point2<f64>,
    rotation_rad: f64,
    mount: Point2<f64>,
) -> f64 {
    let middle = turn_about(pivot, 0.5 * rotation_rad) * attachment;
    let square = mount_square_at_mid_travel(pivot, attachment, rotation_rad, 1.0) - middle;
    let actual = mount - middle;
    square.perp(&actual).atan2(square.dot(&actual))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The mount square to the arm at mid-travel is `004_...`'s installation: its end
    /// pressure angles are those of the landing-gear method's closed form
    /// ([`crate::landing_gear::LandingGearSpec::synthesise`]) for the same crank (pivot to attachment),
    /// pivot distance (pivot to mount) and rotation, either sense; and its turn from itself
    /// is zero, a turned mount's the turn.
    #[test]
    fn the_square_mount_is_004s_installation() {
        let (pivot, attachment) = (Point2::new(0.1, -0.2), Point2::new(-0.25, -0.1));
        let (mut compared, mut checked_refusals) = (0, 0);
        for rotation in [0.6_f64, -0.6, 1.1, -1.4] {
            for standoff in [0.3, 0.8, 2.0] {
                let mount = mount_square_at_mid_travel(pivot, attachment, rotation, standoff);
                let drive = RockerDrive::try_new(pivot, mount, attachment).unwrap();
                let ours = drive.end_pressure_angles_rad(rotation);
                let gear = crate::landing_gear::LandingGearSpec {
                    pivot_distance_m: (mount - pivot).norm(),
                    crank_length_m: (attachment - pivot).norm(),
                    rotation_rad: rotation.abs(),
                    stroke_time_s: 1.0,
                }
                .synthesise();
                // 004 refuses an end beyond a toggle (a short standoff for a large turn):
                // the drive then passes through one too.
                let Ok(gear) = gear else {
                    assert!(!drive.clear_of_toggles(rotation, 0.0), "{rotation} {standoff}");
                    checked_refusals += 1;
                    continue;
                };
                compared += 1;
                let theirs = [gear.start_pressure_angle_rad, gear.end_pressure_angle_rad];
                for (a, b) in ours.iter().zip(theirs) {
                    assert!(
                        (a.abs() - b).abs() < 1e-12,
                        "{rotation} {standoff}: {ours:?} against {theirs:?}"
                    );
                }
                let stroke = (drive.stroke_at(rotation) - drive.stroke_at(0.0)).abs();
                assert!(
                    (stroke - gear.stroke_m.abs()).abs() < 1e-12,
                    "{stroke} against {}",
                    gear.stroke_m
                );
                assert!(mount_turn_from_square(pivot, attachment, rotation, mount).abs() < 1e-12);
                let middle = turn_about(pivot, 0.5 * rotation) * attachment;
                let turned = turn_about(middle, 0.3) * mount;
                assert!((mount_turn_from_square(pivot, attachment, rotation, turned) - 0.3).abs() < 1e-12);
            }
        }
        assert!(
            compared >= 10 && checked_refusals >= 1,
            "{compared} compared, {checked_refusals} refused"
        );
    }

    /// The rotation a stroke gives round-trips through `stroke_at`, either sense, and the
    /// rate matches a central difference.
    #[test]
    fn strokes_and_rotations_round_trip_in_both_senses() {
        for attachment in [Point2::new(-0.3, 0.4), Point2::new(-0.3, -0.4)] {
            let (pivot, mount) = (Point2::new(0.0, 0.0), Point2::new(0.5, 0.1));
            let drive = RockerDrive::try_new(pivot, mount, attachment).unwrap();
            for rotation in [-0.4, -0.1, 0.0, 0.2, 0.5] {
                let stroke = drive.stroke_at(rotation);
                let state = drive.state(stroke).unwrap();
                assert!(
                    (state.rotation_rad - rotation).abs() < 1e-12,
                    "{rotation}: {}",
                    state.rotation_rad
                );
                let h = 1e-6;
                let numeric = (drive.state(stroke + h).unwrap().rotation_rad
                    - drive.state(stroke - h).unwrap().rotation_rad)
                    / (2.0 * h);
                assert!((numeric - state.rotation_per_stroke).abs() < 1e-6 * numeric.abs().max(1.0));
                assert!(state.closure_residual_m < 1e-12);
            }
        }
    }

    #[test]
    fn square_mount_gives_a_right_angle_at_mid_travel_and_a_growing_stroke() {
        let (pivot, attachment) = (Point2::new(0.0, -0.5), Point2::new(0.1, 0.0));
        for rotation in [0.6, -0.6] {
            let mount = mount_square_at_mid_travel(pivot, attachment, rotation, 0.4);
            let drive = RockerDrive::try_new(pivot, mount, attachment).unwrap();
            let middle = drive.state(drive.stroke_at(0.5 * rotation)).unwrap();
            assert!((middle.transmission_angle_rad - std::f64::consts::FRAC_PI_2).abs() < 1e-9);
            assert!(drive.stroke_at(rotation) > drive.stroke_at(0.0));
            assert!(drive.clear_of_toggles(rotation, 0.1));
            let bound = drive.rotation_rate_bound(rotation);
            for k in 0..=20 {
                let state = drive.state(drive.stroke_at(rotation * k as f64 / 20.0)).unwrap();
                assert!(state.rotation_per_stroke.abs() <= bound * (1.0 + 1e-12));
            }
        }
    }

    /// Issue 35 item 7: a toggle inside the rotation is named as a toggle (the message
    /// said "falls to 47.0 deg (minimum 30.0 deg)", an angle above its minimum); an angle
    /// below the minimum names both; a drive clear of both has no problem.
    #[test]
    fn a_toggle_is_named_as_a_toggle_and_a_low_angle_as_below_its_minimum() {
        let drive = RockerDrive::try_new(
            Point2::origin(),
            Point2::new(1.0, 0.0),
            Point2::new(0.3, 0.3 * 20f64.to_radians().tan()),
        )
        .unwrap();
        let turn = 30f64.to_radians();
        let (through, clear) = if drive.clear_of_toggles(turn, 1e-3) {
            (-turn, turn)
        } else {
            (turn, -turn)
        };
        let toggle = drive
            .transmission_problem(through, 5f64.to_radians(), 32, "arm")
            .unwrap();
        assert!(toggle.contains("toggle") && !toggle.contains("falls to"), "{toggle}");
        assert_eq!(drive.transmission_problem(clear, 1f64.to_radians(), 32, "arm"), None);
        let low = drive
            .transmission_problem(clear, 89f64.to_radians(), 32, "arm")
            .unwrap();
        assert!(
            low.contains("falls to") && low.contains("below the minimum of 89.0 deg"),
            "{low}"
        );
    }
}
