//! Adding a kind, worked once (`docs/architecture.md`, "Adding a kind", step 1): a **plain hinge**
//! defined here, in the test, with nothing but the public seam and toolbox of
//! `flapwright-mechanism` (what a folder `crates/kinds/src/plain_hinge/` would use), then fed
//! unchanged through the kind-neutral consumers the other stages use: the deployment sweep,
//! the spanwise layout, the URDF model, its rule check and trajectory, the rigid-flap
//! equation of motion and the sizing of members and actuator.
//!
//! The plain hinge: the flap pinned to a fixed hinge H below the wing, on a fitting from H
//! to its attachment F on the flap, the hinge carried by a bracket from the wing's lower
//! skin, and turned by a geared rotary actuator on the hinge axis; the input is the hinge
//! angle (rad), so the flap's deflection is the input itself. Statics: moments about H give
//! the actuator torque T = -M_H (M_H the load's moment about H, counter-clockwise positive),
//! the hinge carries the load's resultant. The physics asserted: T equals the hinge moment
//! of a pure moment and of a normal force at a known arm, and T dθ equals the work done
//! against the load over a small turn (finite difference of the poses).

use std::f64::consts::PI;

use flapwright_mechanism::generalised::OneInputDynamics;
use flapwright_mechanism::seam::{FlapMechanism, Kinetostatics, MemberLoad};
use flapwright_mechanism::shared::flap_load::{FlapMass, LinkHardware};
use flapwright_mechanism::spanwise::spanwise_layout;
use flapwright_mechanism::{
    sweep_deployment, ExternalMoment, FlapNormalForce, LoadCase, RigidFlapDynamics, RotaryDrive,
};
use nalgebra::{Isometry3, Point2, Point3, Vector2, Vector3};

use plain_hinge::{PlainHinge, PlainHingeSpec};

/// The kind as it would stand in `crates/kinds/src/plain_hinge/mod.rs` (with
/// `pub mod plain_hinge;` and its re-exports in `crates/kinds/src/lib.rs`).
mod plain_hinge {
    use nalgebra::{Isometry2, Point2, Vector2};
    use serde::Serialize;

    use flapwright_mechanism::seam::{
        Actuator, Body, BodyRole, BodySolid, DrawingNotes, FlapMechanism, InputQuantity, InputRange, Joint, JointEnd,
        JointGeometry, Kinetostatics, MechanismPose, Member, MemberLoad, NamedPoint, PoseHealth, SpeedBound,
    };
    use flapwright_mechanism::shared::flap_load::{FlapMass, FlapWrench, LinkHardware};
    use flapwright_mechanism::shared::geometry::{cross, turn_about};
    use flapwright_mechanism::{Error, LoadCase, Result, RotaryDrive};

    /// The kind's scene name.
    const KIND: &str = "plain-hinge";
    /// Body indices in [`FlapMechanism::bodies`].
    pub const FLAP: usize = 0;
    /// The support: bracket and actuator housing, fixed to the wing.
    pub const SUPPORT: usize = 1;

    /// The designer's choices (station frame, m, rad).
    #[derive(Debug, Clone, PartialEq, Serialize)]
    pub struct PlainHingeSpec {
        /// The hinge H, below the wing.
        pub hinge_m: Point2<f64>,
        /// The fitting's attachment F on the flap, stowed.
        pub fitting_m: Point2<f64>,
        /// The bracket's attachment S on the wing's lower skin.
        pub bracket_m: Point2<f64>,
        /// Flap deflection fully deployed (rad), trailing edge down positive.
        pub deflection_range_rad: f64,
        /// The flap share this station carries.
        pub flap_mass: FlapMass,
        /// The rotary actuator's drive, shared with the wing's other stations.
        pub drive: RotaryDrive,
        /// Solid sizes.
        pub hardware: LinkHardware,
    }

    /// A plain hinge for one station.
    #[derive(Debug, Clone)]
    pub struct PlainHinge {
        spec: PlainHingeSpec,
        actuator: Actuator,
        bodies: Vec<Body>,
        joints: Vec<Joint>,
    }

    impl PlainHinge {
        /// The hinge, its actuator (gear ratio from the drive) and its solids.
        ///
        /// Errors: [`Error::ParameterOutOfRange`] for a deflection range outside (0, π);
        /// [`Error::InvalidDimension`] for a fitting or bracket of no length.
        pub fn synthesise(spec: PlainHingeSpec) -> Result<Self> {
            let range = spec.deflection_range_rad;
            if !(range > 0.0 && range < std::f64::consts::PI) {
                return Err(Error::ParameterOutOfRange {
                    name: "deflection_range_rad",
                    value: range,
                    min: 0.0,
                    max: std::f64::consts::PI,
                });
            }
            let h = spec.hinge_m;
            for (name, end) in [("fitting length", spec.fitting_m), ("bracket length", spec.bracket_m)] {
                let length = (end - h).norm();
                if !(length.is_finite() && length > 0.0) {
                    return Err(Error::InvalidDimension { name, value: length });
                }
            }
            let actuator = spec.drive.actuator_for(range);
            let hw = spec.hardware;
            let flap = Body {
                name: "flap".into(),
                role: BodyRole::Flap,
                solids: vec![BodySolid::capsule("fitting", h, spec.fitting_m, hw.link_radius_m)],
                // A turn about H at one radian per radian of input: a point r from H moves
                // at exactly r per unit input.
                speed_bound: SpeedBound {
                    reference: h,
                    linear_per_input: 0.0,
                    angular_per_input: 1.0,
                },
            };
            let support = Body {
                name: "support".into(),
                role: BodyRole::Support,
                solids: vec![
                    BodySolid::capsule("bracket", spec.bracket_m, h, hw.link_radius_m),
                    BodySolid::capsule("rotary-actuator", h, h, hw.jack_body_radius_m),
                ],
                speed_bound: SpeedBound::FIXED,
            };
            let joints = vec![Joint::new(
                "H",
                "the flap's fitting on the hinge pin, turned by the rotary actuator on its axis",
                JointGeometry::Revolute { at: h },
                [JointEnd::Body(SUPPORT), JointEnd::Body(FLAP)],
                &[("bracket", "fitting"), ("rotary-actuator", "fitting")],
            )];
            Ok(Self {
                spec,
                actuator,
                bodies: vec![flap, support],
                joints,
            })
        }

        /// The designer's choices.
        pub fn spec(&self) -> &PlainHingeSpec {
            &self.spec
        }

        /// The flap's displacement at hinge angle `input` (rad), checked finite.
        fn flap_at(&self, input: f64) -> Result<Isometry2<f64>> {
            if input.is_finite() {
                Ok(turn_about(self.spec.hinge_m, input))
            } else {
                Err(Error::NonFinite {
                    quantity: "hinge angle",
                    input_m: input,
                })
            }
        }

        /// The loads on the flap at `flap` under `load` at drive fraction `fraction`: the
        /// resultant (N) and a function giving the moment about a point (N m,
        /// counter-clockwise). With `load.include_inertia`, the d'Alembert force of the
        /// flap turning at the actuator's nominal speed ω, held constant (α = 0): m ω²
        /// (D - H), through H (no moment about it, no power).
        fn flap_load(
            &self,
            flap: &Isometry2<f64>,
            load: &LoadCase,
            fraction: f64,
        ) -> (FlapWrench, Vector2<f64>, impl Fn(Point2<f64>) -> f64) {
            let wrench = FlapWrench::new(&self.spec.flap_mass, flap, load, fraction);
            let h = self.spec.hinge_m;
            let inertia = if load.include_inertia {
                let omega = self.actuator.nominal_input_speed();
                (wrench.centre_of_mass - h) * self.spec.flap_mass.mass_kg * omega * omega
            } else {
                Vector2::zeros()
            };
            let moment_about = move |p: Point2<f64>| wrench.moment_about(p) + cross(wrench.centre_of_mass - p, inertia);
            (wrench, wrench.force_n() + inertia, moment_about)
        }
    }

    impl FlapMechanism for PlainHinge {
        fn kind(&self) -> &'static str {
            KIND
        }

        /// The hinge angle, 0 to the deflection range.
        fn input_range(&self) -> InputRange {
            InputRange {
                quantity: InputQuantity::Angle,
                stowed: 0.0,
                deployed: self.spec.deflection_range_rad,
            }
        }

        fn deflection_range_rad(&self) -> f64 {
            self.spec.deflection_range_rad
        }

        /// The hinge angle is the deflection.
        fn input_at_deflection(&self, deflection_rad: f64) -> Result<f64> {
            self.flap_at(deflection_rad).map(|_| deflection_rad)
        }

        fn deflection_at_input(&self, input: f64) -> Result<f64> {
            self.flap_at(input).map(|_| input)
        }

        /// The fitting's attachment F.
        fn flap_attachments(&self) -> Vec<NamedPoint> {
            vec![NamedPoint {
                name: "F",
                position: self.spec.fitting_m,
                fixed: false,
            }]
        }

        fn bodies(&self) -> &[Body] {
            &self.bodies
        }

        fn joints(&self) -> &[Joint] {
            &self.joints
        }

        fn pose(&self, input: f64) -> Result<MechanismPose> {
            let flap = self.flap_at(input)?;
            let spec = &self.spec;
            let point = |name, position, fixed| NamedPoint { name, position, fixed };
            Ok(MechanismPose {
                deflection_rad: input,
                input,
                bodies: vec![flap, Isometry2::identity()],
                flap,
                points: vec![
                    point("H", spec.hinge_m, true),
                    point("S", spec.bracket_m, true),
                    point("F", flap * spec.fitting_m, false),
                    point("D", flap * spec.flap_mass.centre_of_mass_stowed_m, false),
                ],
            })
        }

        /// Moments about H: T = -M_H; the hinge carries the load's resultant, |R_H|. By
        /// virtual work, independently: T = -(Σ f · v_p + C ω) with the points' virtual
        /// velocities v_p = ω (p - H)⊥ at ω = 1 rad per rad. The actuator's output drives
        /// the hinge directly: no loop to close, no toggle (transmission π/2).
        fn kinetostatics(&self, input: f64, load: &LoadCase) -> Result<Kinetostatics> {
            let flap = self.flap_at(input)?;
            let h = self.spec.hinge_m;
            let fraction = self.input_range().fraction(input).clamp(0.0, 1.0);
            let (wrench, resultant, moment_about) = self.flap_load(&flap, load, fraction);
            let torque = -moment_about(h);
            let hinge_reaction = -resultant;
            let velocity_of = |p: Point2<f64>| {
                let r = p - h;
                Vector2::new(-r.y, r.x)
            };
            // The d'Alembert force runs through H, square to every virtual velocity of D.
            let virtual_work = -wrench.power(velocity_of, 1.0);
            if !(torque.is_finite() && virtual_work.is_finite() && hinge_reaction.norm().is_finite()) {
                return Err(Error::NonFinite {
                    quantity: "actuator torque",
                    input_m: input,
                });
            }
            // The fitting: clamped at the hub on H, the flap's load entering at F. The
            // bracket: clamped on the wing at S, the hinge pin pushing it with the flap's
            // resultant at H and the actuator housing with the reaction -T.
            let f = flap * self.spec.fitting_m;
            let mut members = vec![
                (
                    "bracket".to_string(),
                    MemberLoad::of_cantilever_line(&[self.spec.bracket_m, h], resultant, -torque),
                ),
                (
                    "fitting".to_string(),
                    MemberLoad::of_cantilever_line(&[h, f], resultant, moment_about(f)),
                ),
            ];
            members.sort_by(|a, b| a.0.cmp(&b.0));
            let right_angle = std::f64::consts::FRAC_PI_2;
            Ok(Kinetostatics {
                input,
                deflection_rad: input,
                actuator_load: torque,
                actuator_load_virtual_work: virtual_work,
                reactions: vec![("H".to_string(), hinge_reaction.norm())],
                transmission_angle_rad: right_angle,
                health: PoseHealth {
                    closure_residual_m: 0.0,
                    jacobian_condition_number: 1.0,
                    distance_to_toggle_rad: right_angle,
                },
                actuator_torques: None,
                members,
            })
        }

        fn drawing_notes(&self) -> DrawingNotes {
            let (h, f) = (self.spec.hinge_m, self.spec.fitting_m);
            let start = (f - h).y.atan2((f - h).x);
            DrawingNotes {
                summary: format!(
                    "plain hinge with geared rotary actuator on the hinge; gear ratio {:.0}:1, {:.1} deg",
                    self.actuator.shaft_angle_per_input(),
                    self.spec.deflection_range_rad.to_degrees()
                ),
                dimensions: vec![("H-F".into(), h, f), ("S-H".into(), self.spec.bracket_m, h)],
                arcs: vec![(
                    "F about H".into(),
                    h,
                    (f - h).norm(),
                    start,
                    start + self.spec.deflection_range_rad,
                )],
            }
        }

        fn details(&self) -> serde_json::Value {
            serde_json::json!({
                "spec": self.spec,
                "actuator": self.actuator,
                "fitting_length_m": (self.spec.fitting_m - self.spec.hinge_m).norm(),
            })
        }

        fn actuator(&self) -> Actuator {
            self.actuator
        }

        /// One design choice only a designer can judge: a geared rotary actuator is
        /// reversible, so a flap load that aids deployment back-drives it.
        fn warnings(&self) -> Vec<String> {
            if self.actuator.self_locking() {
                Vec::new()
            } else {
                vec!["the geared rotary actuator is reversible: fit a no-back brake".into()]
            }
        }

        /// The fitting (clamped at the hub, its tip held by the flap: K = 1) and the bracket
        /// (a cantilever from the skin, its tip free to sway: K = 2); both bend.
        fn members(&self) -> Vec<Member> {
            let (h, radius) = (self.spec.hinge_m, self.spec.hardware.link_radius_m);
            vec![
                Member::new(
                    "fitting",
                    (self.spec.fitting_m - h).norm(),
                    radius,
                    flapwright_mechanism::seam::MemberLoading::Bending,
                ),
                Member::cantilever("bracket", (self.spec.bracket_m - h).norm(), radius),
            ]
        }

        fn flap_mass(&self) -> Option<FlapMass> {
            Some(self.spec.flap_mass)
        }
    }
}

/// Relative tolerance of closed forms evaluated in floating point.
const CLOSED_FORM_TOL: f64 = 1e-12;
/// Deflection range of the example (rad).
const RANGE_RAD: f64 = 40.0 * PI / 180.0;
/// The hinge H, below the wing (station frame, m).
const HINGE: [f64; 2] = [-0.05, -0.12];
/// The chordwise arm of the normal force's point from H (m): the force acts at
/// H + (-0.30, 0.10), square to the chord (along +y stowed), so its moment about H is
/// -0.30 N at every deflection (point and force turn together).
const NORMAL_FORCE_ARM_M: f64 = 0.30;

/// A 0.8 m flap of 20 kg on a plain hinge, 40 deg, driven through 40 shaft turns in 20 s.
fn spec() -> PlainHingeSpec {
    PlainHingeSpec {
        hinge_m: Point2::new(HINGE[0], HINGE[1]),
        fitting_m: Point2::new(-0.15, -0.04),
        bracket_m: Point2::new(0.10, -0.06),
        deflection_range_rad: RANGE_RAD,
        flap_mass: FlapMass {
            mass_kg: 20.0,
            centre_of_mass_stowed_m: Point2::new(-0.30, -0.01),
            gravity_mps2: Vector2::new(0.0, -9.81),
        },
        drive: RotaryDrive {
            turns: 40.0,
            deployment_time_s: 20.0,
            efficiency: 0.9,
        },
        hardware: LinkHardware::for_flap_chord(0.8),
    }
}

/// The example hinge.
fn hinge() -> PlainHinge {
    PlainHinge::synthesise(spec()).expect("the example hinge")
}

/// The example with a weightless flap (same mass, no gravity): loads from the case alone.
fn weightless_hinge() -> PlainHinge {
    let mut spec = spec();
    spec.flap_mass.gravity_mps2 = Vector2::zeros();
    PlainHinge::synthesise(spec).expect("the weightless hinge")
}

/// A load case of external moment `moment` and optional normal force.
fn load(moment: ExternalMoment, normal: Option<FlapNormalForce>, load_factor: f64) -> LoadCase {
    LoadCase {
        name: "plain".into(),
        external_moment: moment,
        include_inertia: false,
        flap_normal_force: normal,
        load_factor,
    }
}

/// C_N 0.5 stowed to 1.3 at 40 deg, 10 kN per unit C_N, at H + (-0.30, 0.10), normal +y.
fn normal_force() -> FlapNormalForce {
    FlapNormalForce {
        coefficients: vec![(0.0, 0.5), (RANGE_RAD, 1.3)],
        newtons_per_coefficient: 10_000.0,
        at_stowed_m: Point2::new(HINGE[0] - NORMAL_FORCE_ARM_M, HINGE[1] + 0.10),
        normal_stowed: Vector2::new(0.0, 1.0),
    }
}

/// Everything at once: the weight at n = 2.5, a moment 200 -> 800 N m, the normal force.
fn full_load() -> LoadCase {
    load(
        ExternalMoment::Linear {
            stowed_nm: 200.0,
            deployed_nm: 800.0,
        },
        Some(normal_force()),
        2.5,
    )
}

fn reaction(loads: &Kinetostatics, joint: &str) -> f64 {
    loads.reactions.iter().find(|(j, _)| j == joint).expect("reaction").1
}

fn member(loads: &Kinetostatics, name: &str) -> MemberLoad {
    loads.members.iter().find(|(m, _)| m == name).expect("member").1
}

fn close(a: f64, b: f64, tolerance: f64, what: &str) {
    assert!((a - b).abs() <= tolerance * b.abs().max(1.0), "{what}: {a} against {b}");
}

#[test]
fn the_pose_turns_the_flap_about_the_hinge_by_the_input() {
    let hinge = hinge();
    let h = hinge.spec().hinge_m;
    for input in hinge.input_range().samples(17) {
        let pose = hinge.pose(input).unwrap();
        assert_eq!(pose.deflection_rad, input);
        close(pose.flap.rotation.angle(), input, CLOSED_FORM_TOL, "flap rotation");
        assert!((pose.flap * h - h).norm() < 1e-15, "H stays put at {input}");
        assert_eq!(pose.bodies[plain_hinge::FLAP], pose.flap);
        assert_eq!(pose.bodies[plain_hinge::SUPPORT], nalgebra::Isometry2::identity());
        for attachment in hinge.flap_attachments() {
            assert!((pose.point(attachment.name).unwrap() - pose.flap * attachment.position).norm() < 1e-15);
        }
        assert_eq!(
            hinge
                .input_at_deflection(hinge.deflection_at_input(input).unwrap())
                .unwrap(),
            input
        );
    }
    assert_eq!(
        hinge.deflection_at_input(hinge.input_range().deployed).unwrap(),
        hinge.deflection_range_rad()
    );
    assert!(hinge.pose(f64::NAN).is_err());
    // The shared checks every kind passes: bounds hold, and are as tight as a pure turn
    // about H allows (the bound covers the fitting's 24 mm radius beyond its 128 mm
    // skeleton the check samples: 128 / 152 = 0.84); joints name what exists.
    crate::seam::speed_bounds_hold(&hinge, 0.84);
    crate::seam::joints_name_existing(&hinge);
}

#[test]
fn the_actuator_torque_balances_a_pure_moment() {
    // M12 = 500 N m closing: T = 500 N m at every angle; nothing pushes the hinge; the
    // fitting and the bracket carry the couple alone.
    let hinge = weightless_hinge();
    for input in hinge.input_range().samples(9) {
        let loads = hinge
            .kinetostatics(input, &load(ExternalMoment::Constant(500.0), None, 1.0))
            .unwrap();
        close(loads.actuator_load, 500.0, CLOSED_FORM_TOL, "T");
        close(
            loads.actuator_load_virtual_work,
            500.0,
            CLOSED_FORM_TOL,
            "T by virtual work",
        );
        assert!(reaction(&loads, "H") < 1e-12);
        for name in ["fitting", "bracket"] {
            close(member(&loads, name).bending_moment_nm, 500.0, CLOSED_FORM_TOL, name);
            assert!(member(&loads, name).axial_n.abs() < 1e-12);
        }
    }
    // A moment linear over the travel, 200 -> 800 N m: 500 N m half way.
    let linear = load(
        ExternalMoment::Linear {
            stowed_nm: 200.0,
            deployed_nm: 800.0,
        },
        None,
        1.0,
    );
    let half = hinge.kinetostatics(0.5 * RANGE_RAD, &linear).unwrap();
    close(half.actuator_load, 500.0, CLOSED_FORM_TOL, "T half way");
}

#[test]
fn the_actuator_torque_is_the_normal_force_times_its_arm() {
    // N = C_N(δ) 10 kN at 0.30 m from H, square to the chord: T = 0.30 N (closing), the
    // hinge carries N. C_N: 0.5, 0.9, 1.3 at 0, 20, 40 deg: T = 1500, 2700, 3900 N m.
    let hinge = weightless_hinge();
    let case = load(ExternalMoment::Constant(0.0), Some(normal_force()), 1.0);
    for (deg, torque_nm, normal_n) in [(0.0, 1500.0, 5000.0), (20.0, 2700.0, 9000.0), (40.0, 3900.0, 13_000.0)] {
        let loads = hinge.kinetostatics(f64::to_radians(deg), &case).unwrap();
        close(loads.actuator_load, torque_nm, CLOSED_FORM_TOL, "T");
        close(
            loads.actuator_load,
            NORMAL_FORCE_ARM_M * normal_n,
            CLOSED_FORM_TOL,
            "N x arm",
        );
        close(
            loads.actuator_load_virtual_work,
            torque_nm,
            CLOSED_FORM_TOL,
            "T by virtual work",
        );
        close(reaction(&loads, "H"), normal_n, CLOSED_FORM_TOL, "hinge reaction");
    }
    // The flap's inertia at the nominal speed (40 deg in 20 s) pulls on the hinge, not on
    // the actuator: m ω² |D - H| = 20 kg (0.0349 rad/s)² 0.273 m = 6.7 mN.
    let mut inertial = load(ExternalMoment::Constant(500.0), None, 1.0);
    inertial.include_inertia = true;
    let loads = hinge.kinetostatics(0.3, &inertial).unwrap();
    let omega = RANGE_RAD / 20.0;
    let arm = (hinge.spec().flap_mass.centre_of_mass_stowed_m - hinge.spec().hinge_m).norm();
    close(loads.actuator_load, 500.0, CLOSED_FORM_TOL, "T with inertia");
    close(
        reaction(&loads, "H"),
        20.0 * omega * omega * arm,
        1e-9,
        "centripetal pull",
    );
}

#[test]
fn torque_times_a_small_turn_is_the_work_done_against_the_load() {
    // The load's work over θ ± h, from the poses' points and the load case written out
    // here (not through the kind's wrench): W = W_g · ΔD + N(θ) n(θ) · ΔP - M12 2h, midpoint
    // rule (error O(h³)); the actuator supplies T 2h = -W.
    let hinge = hinge();
    let case = full_load();
    let spec = hinge.spec();
    let normal = normal_force();
    let weight = spec.flap_mass.gravity_mps2 * spec.flap_mass.mass_kg * case.load_factor;
    let step = 1e-5;
    for theta in [0.05, 0.2, 0.4, 0.6] {
        let at = |q: f64| {
            let pose = hinge.pose(q).unwrap();
            (pose.point("D").unwrap(), pose.flap * normal.at_stowed_m)
        };
        let ((d0, p0), (d1, p1)) = (at(theta - step), at(theta + step));
        let flap = hinge.pose(theta).unwrap().flap;
        let aero = flap.rotation * normal.normal_stowed * normal.at(theta);
        let moment = case.external_moment.at(theta / RANGE_RAD);
        let work = weight.dot(&(d1 - d0)) + aero.dot(&(p1 - p0)) - moment * 2.0 * step;
        let loads = hinge.kinetostatics(theta, &case).unwrap();
        close(
            loads.actuator_load * 2.0 * step,
            -work,
            1e-9,
            "T dθ against the load's work",
        );
        close(
            loads.actuator_load_virtual_work,
            loads.actuator_load,
            CLOSED_FORM_TOL,
            "cross-check",
        );
    }
}

/// The station frame in the aircraft frame: x to the nose (-x_ac), y up (z_ac), z outboard
/// (y_ac), at (3.2, 1.5, 0.4) m.
fn station_placement() -> Isometry3<f64> {
    Isometry3::new(
        Vector3::new(3.2, 1.5, 0.4),
        Vector3::new(0.0, 1.0, 1.0).normalize() * PI,
    )
}

#[test]
fn the_new_kind_runs_unchanged_through_the_kind_neutral_stages() {
    let hinge = hinge();
    let range = hinge.input_range();

    // The deployment sweep: to the end without stopping, 0 -> 40 deg.
    let deployment = sweep_deployment(&hinge, 41, &full_load()).unwrap();
    assert!(deployment.stopped.is_none(), "{:?}", deployment.stopped);
    assert_eq!(deployment.samples.len(), 41);
    assert_eq!(deployment.samples[0].deflection_deg, 0.0);
    close(deployment.samples[40].deflection_deg, 40.0, CLOSED_FORM_TOL, "deployed");
    for sample in &deployment.samples {
        assert!(sample.actuator_load_cross_check_relative < CLOSED_FORM_TOL);
        assert_eq!(sample.reactions_n.keys().collect::<Vec<_>>(), ["H"]);
        assert_eq!(sample.member_loads.keys().collect::<Vec<_>>(), ["bracket", "fitting"]);
        assert!(sample.actuator_torques_nm.is_none() && sample.aft_element.is_none());
        assert_eq!(sample.transmission_angle_deg, 90.0);
    }

    // The spanwise layout: the fitting and the bracket in the station plane (they meet at
    // the pin), the actuator housing, which the bracket would cross at H, one layer aside:
    // 3 r_max = 84 mm (r_max the housing's 28 mm).
    let offsets = spanwise_layout(&hinge).unwrap();
    let r_max = hinge.spec().hardware.jack_body_radius_m;
    assert_eq!(offsets.len(), 2);
    assert_eq!(offsets[plain_hinge::FLAP], [0.0]);
    assert_eq!(offsets[plain_hinge::SUPPORT][0], 0.0);
    close(
        offsets[plain_hinge::SUPPORT][1],
        -3.0 * r_max,
        CLOSED_FORM_TOL,
        "housing layer",
    );

    // The URDF: a tree without cuts (one revolute joint H from the fixed support to the
    // flap), passing the rule check; the trajectory's joint value is the input.
    let stations = [flapwright_urdf::StationMechanism3d {
        name: "inner".into(),
        aircraft_from_station: station_placement(),
        mechanism: &hinge,
        flap_name: "flap".into(),
        owns_flap: true,
        flap_mesh: Some("meshes/flap.stl".into()),
        aft_element: None,
        flap_inertia: None,
        bodies: Vec::new(),
        actuator_peak_load: None,
    }];
    let base = flapwright_urdf::BaseLink {
        name: "wing".into(),
        meshes: Vec::new(),
    };
    let model = flapwright_urdf::build_robot("plain_hinge_wing", &base, &stations).unwrap();
    assert_eq!(flapwright_urdf::check_rules(&model.robot), Vec::<String>::new());
    assert!(model.cut_joints.is_empty());
    let names: Vec<&str> = model.robot.joints.iter().map(|j| j.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "inner_station_mount",
            "inner_support_mount",
            "inner_H",
            "inner_flap_mount"
        ]
    );
    let joint_h = &model.robot.joints[2];
    assert_eq!(
        (joint_h.parent.link.as_str(), joint_h.child.link.as_str()),
        ("inner_support", "inner_flap")
    );
    assert_eq!(joint_h.origin.xyz.0, [HINGE[0], HINGE[1], 0.0]);
    // Limits: the travel widened by half a step of the 129 samples; velocity the nominal
    // 40 deg in 20 s.
    let half_step = 0.5 * RANGE_RAD / 128.0;
    close(joint_h.limit.lower, -half_step, 1e-9, "lower limit");
    close(joint_h.limit.upper, RANGE_RAD + half_step, 1e-9, "upper limit");
    close(joint_h.limit.velocity, RANGE_RAD / 20.0, 1e-9, "velocity limit");
    let xml = flapwright_urdf::to_xml(&model).unwrap();
    assert!(xml.contains("revolute") && !xml.contains("prismatic"));
    let trajectory = flapwright_urdf::trajectory(&stations, 21).unwrap();
    assert_eq!(trajectory.joint_names, ["inner_H"]);
    // Forward kinematics of the written tree: F on the flap's link (frame at H) turned by
    // the joint value lands where the kind's pose puts it.
    let key = trajectory.key_points.iter().find(|k| k.name == "inner.flap.F").unwrap();
    for (sample, input) in trajectory.samples.iter().zip(range.samples(21)) {
        assert_eq!(sample.input_m, [input]);
        close(sample.joint_values[0], input, CLOSED_FORM_TOL, "joint value");
        let [x, y, _] = key.position_link_m;
        let (s, c) = sample.joint_values[0].sin_cos();
        let f_station = Point3::new(HINGE[0] + c * x - s * y, HINGE[1] + s * x + c * y, 0.0);
        let f_ac = station_placement() * f_station;
        let expected = sample.key_points_ac_m["inner.flap.F"];
        assert!(
            (f_ac - Point3::from(expected)).norm() < 1e-12,
            "{f_ac} against {expected:?}"
        );
    }

    // The rigid-flap equation of motion (the dynamics stage's model of kinds without
    // their own): turning about H, J = (I_D + m |D - H|²) / N² per shaft radian² and
    // Q = -T / N, N the gear ratio (360: 40 turns over 40 deg).
    let mass = hinge.flap_mass().unwrap();
    let inertia_kgm2 = 1.2;
    let case = full_load();
    let dynamics = RigidFlapDynamics::new(&hinge, mass, inertia_kgm2, &case).unwrap();
    let ratio = hinge.actuator().shaft_angle_per_input();
    close(ratio, 360.0, CLOSED_FORM_TOL, "gear ratio");
    let arm_squared = (mass.centre_of_mass_stowed_m - hinge.spec().hinge_m).norm_squared();
    for fraction in [0.25, 0.5, 0.75] {
        let q = fraction * dynamics.input_travel().1;
        let generalised = dynamics.generalised_at(q).unwrap();
        let expected = (inertia_kgm2 + mass.mass_kg * arm_squared) / (ratio * ratio);
        close(generalised.inertia, expected, 1e-9, "J");
        let torque = hinge.kinetostatics(q / ratio, &case).unwrap().actuator_load;
        close(generalised.force, -torque / ratio, 1e-9, "Q");
    }
}

#[test]
fn the_sizing_stage_sizes_its_members_and_its_actuator() {
    // Under M12 = 500 N m alone the fitting bends by 500 N m with no axial force: in 7075-T6
    // (503 MPa) a solid round bar of r = (4 M / (π σ))^(1/3) = 10.8 mm, inside the 24 mm
    // solid; the shaft torque to deploy 500 / (360 x 0.9) = 1.54 N m, 2.31 N m with the
    // safety factor 1.5.
    let hinge = weightless_hinge();
    let deployment = sweep_deployment(&hinge, 21, &load(ExternalMoment::Constant(500.0), None, 1.0)).unwrap();
    assert!(deployment.stopped.is_none());
    let material = flapwright_sizing::Material::aluminium_7075_t6();
    for member in hinge.members() {
        let loads: Vec<MemberLoad> = deployment
            .samples
            .iter()
            .map(|s| s.member_loads[&member.name])
            .collect();
        let axial: Vec<f64> = loads.iter().map(|l| l.axial_n).collect();
        let (tension, compression) = flapwright_sizing::axial_envelope_n(&axial).unwrap();
        let mut rod =
            flapwright_sizing::RodInput::new("inner", member.name.clone(), member.length_m, tension, compression);
        rod.max_outer_radius_m = Some(member.radius_m);
        rod.end_fixity_factor = member.end_fixity_factor;
        rod.bending = loads
            .iter()
            .map(|l| flapwright_sizing::BendingLoad {
                axial_n: l.axial_n,
                bending_moment_nm: l.bending_moment_nm,
            })
            .collect();
        let sized = flapwright_sizing::size_rod(&rod, &material).unwrap();
        let expected = (4.0 * 500.0 / (PI * material.allowable_tensile_pa)).cbrt();
        assert_eq!(
            sized.governing,
            flapwright_sizing::GoverningCase::Bending,
            "{}",
            member.name
        );
        close(sized.radius_m, expected, 1e-9, &member.name);
        assert!((sized.radius_m - 0.0108).abs() < 1e-4 && sized.radius_m < member.radius_m);
    }
    let torques: Vec<_> = deployment
        .samples
        .iter()
        .map(|s| hinge.actuator().shaft_torques(s.actuator_load))
        .collect();
    let raise = torques.iter().map(|t| t.raise_torque_nm);
    let lower = torques.iter().map(|t| t.lower_torque_nm);
    let sizing = flapwright_sizing::size_actuator(
        &flapwright_sizing::ActuatorInput {
            station: "inner".into(),
            name: "rotary-actuator".into(),
            max_raise_torque_nm: raise.fold(f64::NEG_INFINITY, f64::max),
            max_lower_torque_nm: lower.clone().fold(f64::NEG_INFINITY, f64::max),
            min_lower_torque_nm: lower.fold(f64::INFINITY, f64::min),
            thread_self_locking: hinge.actuator().self_locking(),
        },
        1.5,
    )
    .unwrap();
    close(
        sizing.max_raise_torque_nm,
        500.0 / (360.0 * 0.9),
        CLOSED_FORM_TOL,
        "raise torque",
    );
    close(
        sizing.motor_torque_nm,
        1.5 * 500.0 / (360.0 * 0.9),
        CLOSED_FORM_TOL,
        "motor torque",
    );
    assert!(!sizing.self_locking);
    // The report's view: the kind's record and drawing notes, the reversible actuator's
    // warning.
    assert!(hinge.drawing_notes().summary.contains("gear ratio 360:1"));
    let fitting_length = hinge.details()["fitting_length_m"].as_f64().unwrap();
    close(fitting_length, 0.1f64.hypot(0.08), CLOSED_FORM_TOL, "fitting length");
    assert_eq!(hinge.warnings().len(), 1);
    assert_eq!(hinge.kind(), "plain-hinge");
}
