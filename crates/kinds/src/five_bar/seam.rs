//! The five-bar behind the mechanism seam: bodies with roles and solids, joints, poses as
//! body displacements, speed bounds, statics with a virtual-work cross-check.
//!
//! Station frame: origin at the main flap's hinge C (the station's hinge point), x towards
//! the nose, y up, so a point p of `001_...`'s plane (x aft) stands at (C.x - p.x, p.y - C.y)
//! and a rotation by φ there is one by -φ here. The input is the crank angle α (rad) of
//! `001_...`; the flap is the main flap; its deflection is δ(α) - δ(α₀), zero stowed.
//!
//! Speed bounds: each body's largest reference-point speed and rotation rate per unit α over
//! the deployment, sampled at 2001 crank angles from the jets, plus half a sample spacing
//! times the largest second derivative sampled, doubled: the first-order Taylor bound of
//! the derivative between samples, with the second derivative's own variation between
//! samples (its jet's third derivative times the spacing, under 1 % here) covered by the
//! factor two.
//!
//! Statics (quasi-static, the links massless as `001_...` section 1.1 assumes): the links
//! A-G, B-D and E-H carry axial forces only; moments about F on the secondary flap give the
//! E-H force, moments about G on the link D-G-E the B-D force, moments about C on the main
//! flap the A-G force, and the crank's moments about O the actuator torque. The virtual-work
//! cross-check takes the loads' power through the jets' velocities.

use nalgebra::{Isometry2, Point2, Rotation2, Translation2, Vector2};

use super::{FiveBarDoubleFlap, FiveBarPose, LoadedFiveBar};
use flapwright_mechanism::generalised::OneInputDynamics;
use flapwright_mechanism::jet::PointJet;
use flapwright_mechanism::seam::{
    Actuator, Body, BodyRole, BodySolid, DrawingNotes, FlapMechanism, InputQuantity, InputRange, Joint, JointEnd,
    JointGeometry, Kinetostatics, MechanismPose, NamedPoint, PoseHealth, SpeedBound,
};
use flapwright_mechanism::shared::flap_load::{FlapMass, FlapWrench};
use flapwright_mechanism::shared::geometry::cross;
use flapwright_mechanism::shared::load_case::LoadCase;
use flapwright_mechanism::{Error, Result};

const KIND: &str = "five-bar";

/// Radius of the links' and flaps' solids (m): the `001_...` model's scale (1/17).
const SOLID_RADIUS_M: f64 = 0.01;

/// Bodies, in the order of [`FlapMechanism::bodies`].
const MAIN_FLAP: usize = 0;
const SECONDARY_FLAP: usize = 1;
const CRANK: usize = 2;
const DRIVE_LINK: usize = 3;
const ROCKER: usize = 4;
const FLAP_LINK: usize = 5;
const SECONDARY_LINK: usize = 6;

/// A body of the five-bar: name, role, the two named points that define its
/// displacement (the first its speed bound's reference), and its solids as (name, from, to).
type BodyLayout = (
    &'static str,
    BodyRole,
    [&'static str; 2],
    &'static [(&'static str, &'static str, &'static str)],
);

/// The bodies, in the order of the index constants above.
const BODY_POINTS: [BodyLayout; 7] = [
    (
        "main-flap",
        BodyRole::Flap,
        ["C", "F"],
        &[("main-flap-arm", "C", "G"), ("main-flap-chord", "C", "F")],
    ),
    (
        "secondary-flap",
        BodyRole::AftFlap,
        ["F", "L"],
        &[("secondary-arm", "F", "H"), ("secondary-chord", "F", "L")],
    ),
    ("crank", BodyRole::Link, ["O", "A"], &[("crank", "O", "A")]),
    ("drive-link", BodyRole::Link, ["A", "G"], &[("drive-link", "A", "G")]),
    ("rocker", BodyRole::Link, ["B", "D"], &[("rocker", "B", "D")]),
    ("flap-link", BodyRole::Link, ["D", "E"], &[("flap-link", "D", "E")]),
    (
        "secondary-link",
        BodyRole::Link,
        ["E", "H"],
        &[("secondary-link", "E", "H")],
    ),
];

/// The five-bar double flap as a mechanism kind.
#[derive(Debug, Clone)]
pub struct FiveBarKind {
    loaded: LoadedFiveBar,
    bodies: Vec<Body>,
    joints: Vec<Joint>,
    stowed_deflection_rad: f64,
    deployed_deflection_rad: f64,
    stowed: Vec<NamedPoint>,
    actuator: Actuator,
}

impl FiveBarKind {
    /// The kind for `loaded`, driven through `actuator` (a rotary one: the crank is turned).
    pub fn new(loaded: LoadedFiveBar, actuator: Actuator) -> Result<Self> {
        let mechanism = &loaded.mechanism;
        let stowed_pose = mechanism.pose(mechanism.stowed_crank_rad)?;
        let deployed_pose = mechanism.pose(mechanism.deployed_crank_rad)?;
        let stowed = named_points(mechanism, &stowed_pose);
        let at = |name: &str| point_named(&stowed, name);
        let mut bodies = Vec::new();
        for ((name, role, _, solids), speed_bound) in BODY_POINTS.iter().zip(speed_bounds(mechanism)?) {
            bodies.push(Body {
                name: (*name).into(),
                role: *role,
                solids: solids
                    .iter()
                    .map(|(solid, from, to)| BodySolid::capsule(solid, at(from), at(to), SOLID_RADIUS_M))
                    .collect(),
                speed_bound,
            });
        }
        let pin = |name: &str, description: &str, ends: [JointEnd; 2], touching: &[(&str, &str)]| {
            Joint::new(
                name,
                description,
                JointGeometry::Revolute { at: at(&name[..1]) },
                ends,
                touching,
            )
        };
        let body = JointEnd::Body;
        let joints = vec![
            pin("O", "crank on the wing", [body(CRANK), JointEnd::Ground], &[]),
            pin(
                "A",
                "crank to the drive link",
                [body(CRANK), body(DRIVE_LINK)],
                &[("crank", "drive-link")],
            ),
            pin(
                "G1",
                "drive link to the main flap",
                [body(DRIVE_LINK), body(MAIN_FLAP)],
                &[("drive-link", "main-flap-arm")],
            ),
            pin(
                "G2",
                "flap link to the main flap",
                [body(FLAP_LINK), body(MAIN_FLAP)],
                &[("flap-link", "main-flap-arm")],
            ),
            pin(
                "C",
                "main flap hinge on the wing",
                [body(MAIN_FLAP), JointEnd::Ground],
                &[],
            ),
            pin("B", "rocker on the wing", [body(ROCKER), JointEnd::Ground], &[]),
            pin(
                "D",
                "rocker to the flap link",
                [body(ROCKER), body(FLAP_LINK)],
                &[("rocker", "flap-link")],
            ),
            pin(
                "E",
                "flap link to the secondary link",
                [body(FLAP_LINK), body(SECONDARY_LINK)],
                &[("flap-link", "secondary-link")],
            ),
            pin(
                "H",
                "secondary link to the secondary flap",
                [body(SECONDARY_LINK), body(SECONDARY_FLAP)],
                &[("secondary-link", "secondary-arm")],
            ),
            pin(
                "F",
                "secondary flap pivot on the main flap",
                [body(MAIN_FLAP), body(SECONDARY_FLAP)],
                &[("main-flap-chord", "secondary-chord")],
            ),
        ];
        Ok(Self {
            stowed_deflection_rad: stowed_pose.main_deflection.value,
            deployed_deflection_rad: deployed_pose.main_deflection.value,
            loaded,
            bodies,
            joints,
            stowed,
            actuator,
        })
    }

    fn main_flap_mass(&self) -> FlapMass {
        let centre = (point_named(&self.stowed, "C").coords + point_named(&self.stowed, "F").coords) * 0.5;
        FlapMass {
            mass_kg: self.loaded.loads.main_mass_kg,
            centre_of_mass_stowed_m: Point2::from(centre),
            gravity_mps2: Vector2::new(0.0, -self.loaded.loads.gravity_mps2),
        }
    }
}

/// A point of `001_...`'s plane in the station frame (origin C, x towards the nose).
fn to_station(mechanism: &FiveBarDoubleFlap, p: Vector2<f64>) -> Point2<f64> {
    let c = mechanism.hinge_c();
    Point2::new(c.x - p.x, p.y - c.y)
}

/// A velocity (or any difference) of `001_...`'s plane in the station frame.
fn vector_to_station(v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-v.x, v.y)
}

fn named_points(mechanism: &FiveBarDoubleFlap, pose: &FiveBarPose) -> Vec<NamedPoint> {
    let fixed = |name: &'static str, p: Vector2<f64>| NamedPoint {
        name,
        position: to_station(mechanism, p),
        fixed: true,
    };
    let moving = |name: &'static str, jet: &PointJet| NamedPoint {
        name,
        position: to_station(mechanism, jet.p),
        fixed: false,
    };
    vec![
        fixed("O", Vector2::zeros()),
        fixed("B", mechanism.pivot_b()),
        fixed("C", mechanism.hinge_c()),
        moving("A", &pose.a),
        moving("G", &pose.g),
        moving("D", &pose.d),
        moving("E", &pose.e),
        moving("F", &pose.f),
        moving("H", &pose.h),
        moving("L", &pose.trailing_edge),
    ]
}

fn point_named(points: &[NamedPoint], name: &str) -> Point2<f64> {
    points
        .iter()
        .find(|p| p.name == name)
        .map(|p| p.position)
        .unwrap_or_else(Point2::origin)
}

/// The jet of point `name` (001's plane).
fn jet_named(mechanism: &FiveBarDoubleFlap, pose: &FiveBarPose, name: &str) -> PointJet {
    match name {
        "O" => PointJet::fixed(Vector2::zeros()),
        "B" => PointJet::fixed(mechanism.pivot_b()),
        "C" => PointJet::fixed(mechanism.hinge_c()),
        "A" => pose.a,
        "G" => pose.g,
        "D" => pose.d,
        "E" => pose.e,
        "F" => pose.f,
        "H" => pose.h,
        _ => pose.trailing_edge,
    }
}

/// The displacement carrying stowed points `from` to `to` (two points of one rigid body).
fn displacement(from: [Point2<f64>; 2], to: [Point2<f64>; 2]) -> Isometry2<f64> {
    let (u, v) = (from[1] - from[0], to[1] - to[0]);
    let rotation = Rotation2::new(cross(u, v).atan2(u.dot(&v)));
    let translation = to[0].coords - rotation * from[0].coords;
    Isometry2::from_parts(Translation2::from(translation), rotation.into())
}

/// Every body's speed bound (in [`BODY_POINTS`] order), from one pass over the sampled
/// poses.
fn speed_bounds(mechanism: &FiveBarDoubleFlap) -> Result<Vec<SpeedBound>> {
    const SAMPLES: usize = 2001;
    let (from, to) = (mechanism.stowed_crank_rad, mechanism.deployed_crank_rad);
    let spacing = (to - from).abs() / (SAMPLES - 1) as f64;
    // Per body: largest |r'|, |r''|, |ω|, |ω'|.
    let mut largest = vec![[0.0_f64; 4]; BODY_POINTS.len()];
    for k in 0..SAMPLES {
        let pose = mechanism.pose(from + (to - from) * k as f64 / (SAMPLES - 1) as f64)?;
        for ((_, _, [reference, other], _), largest) in BODY_POINTS.iter().zip(&mut largest) {
            let r = jet_named(mechanism, &pose, reference);
            let angle = (jet_named(mechanism, &pose, other) - r).angle();
            let now = [r.d1.norm(), r.d2.norm(), angle.d1.abs(), angle.d2.abs()];
            for (held, value) in largest.iter_mut().zip(now) {
                *held = held.max(value);
            }
        }
    }
    let stowed = mechanism.pose(from)?;
    Ok(BODY_POINTS
        .iter()
        .zip(largest)
        .map(
            |((_, _, [reference, _], _), [speed, speed_change, turn, turn_change])| {
                if speed > 0.0 || turn > 0.0 {
                    SpeedBound {
                        reference: to_station(mechanism, jet_named(mechanism, &stowed, reference).p),
                        linear_per_input: if speed > 0.0 {
                            speed + spacing * speed_change
                        } else {
                            0.0
                        },
                        angular_per_input: turn + spacing * turn_change,
                    }
                } else {
                    SpeedBound::FIXED
                }
            },
        )
        .collect())
}

impl FlapMechanism for FiveBarKind {
    fn kind(&self) -> &'static str {
        KIND
    }

    fn input_range(&self) -> InputRange {
        InputRange {
            quantity: InputQuantity::Angle,
            stowed: self.loaded.mechanism.stowed_crank_rad,
            deployed: self.loaded.mechanism.deployed_crank_rad,
        }
    }

    fn deflection_range_rad(&self) -> f64 {
        self.deployed_deflection_rad - self.stowed_deflection_rad
    }

    fn input_at_deflection(&self, deflection_rad: f64) -> Result<f64> {
        let range = self.input_range();
        let (mut lo, mut hi) = (range.stowed, range.deployed);
        if !(0.0..=self.deflection_range_rad()).contains(&deflection_rad) {
            return Err(Error::ParameterOutOfRange {
                name: "deflection_rad",
                value: deflection_rad,
                min: 0.0,
                max: self.deflection_range_rad(),
            });
        }
        // δ rises monotonically with α over the deployment (tested): bisection.
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if self.deflection_at_input(mid)? < deflection_rad {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Ok(0.5 * (lo + hi))
    }

    fn deflection_at_input(&self, input: f64) -> Result<f64> {
        Ok(self.loaded.mechanism.pose(input)?.main_deflection.value - self.stowed_deflection_rad)
    }

    fn flap_attachments(&self) -> Vec<NamedPoint> {
        self.stowed
            .iter()
            .filter(|p| matches!(p.name, "C" | "G" | "F"))
            .cloned()
            .collect()
    }

    fn bodies(&self) -> &[Body] {
        &self.bodies
    }

    fn joints(&self) -> &[Joint] {
        &self.joints
    }

    fn pose(&self, input: f64) -> Result<MechanismPose> {
        let mechanism = &self.loaded.mechanism;
        let pose = mechanism.pose(input)?;
        let points = named_points(mechanism, &pose);
        let bodies: Vec<Isometry2<f64>> = BODY_POINTS
            .iter()
            .map(|(_, _, [p, q], _)| {
                displacement(
                    [point_named(&self.stowed, p), point_named(&self.stowed, q)],
                    [point_named(&points, p), point_named(&points, q)],
                )
            })
            .collect();
        Ok(MechanismPose {
            deflection_rad: pose.main_deflection.value - self.stowed_deflection_rad,
            input,
            flap: bodies[MAIN_FLAP],
            bodies,
            points,
        })
    }

    fn kinetostatics(&self, input: f64, load: &LoadCase) -> Result<Kinetostatics> {
        let mechanism = &self.loaded.mechanism;
        let jets = mechanism.pose(input)?;
        let pose = self.pose(input)?;
        let at = |name: &str| point_named(&pose.points, name);
        let fraction = self.input_range().fraction(input).clamp(0.0, 1.0);
        let wrench = FlapWrench::new(&self.main_flap_mass(), &pose.flap, load, fraction);
        let secondary_weight =
            Vector2::new(0.0, -self.loaded.loads.gravity_mps2) * self.loaded.loads.secondary_mass_kg * load.load_factor;
        let secondary_centre = Point2::from((at("F").coords + at("L").coords) * 0.5);
        // Secondary flap: moments about F give the E-H link's force along u_eh (on the flap).
        let u_eh = (at("H") - at("E")).normalize();
        let f_eh = -cross(secondary_centre - at("F"), secondary_weight) / cross(at("H") - at("F"), u_eh);
        let pin_f = -(secondary_weight + u_eh * f_eh); // on the secondary flap, from the main flap
                                                       // Link D-G-E: -u_eh f_eh at E, the rocker's f_bd u_bd at D; moments about G.
        let u_bd = (at("D") - at("B")).normalize();
        let f_bd = cross(at("E") - at("G"), u_eh * f_eh) / cross(at("D") - at("G"), u_bd);
        let pin_g2 = u_eh * f_eh - u_bd * f_bd; // on the link D-G-E, from the main flap
                                                // Main flap: its wrench, -pin_f at F, -pin_g2 at G, the drive link's f_ag u_ag at G.
        let u_ag = (at("G") - at("A")).normalize();
        let c = at("C");
        let f_ag = -(wrench.moment_about(c) + cross(at("F") - c, -pin_f) + cross(at("G") - c, -pin_g2))
            / cross(at("G") - c, u_ag);
        let hinge_c = -(wrench.force_n() - pin_f - pin_g2 + u_ag * f_ag);
        // Crank: the drive link pulls it with -f_ag u_ag at A; the actuator's counter-clockwise
        // torque (station frame) balances it. α turns clockwise here (the frame is mirrored).
        let crank_torque_ccw = cross(at("A") - at("O"), u_ag * f_ag);
        let actuator_load = -crank_torque_ccw;
        // Virtual work: the loads' power per unit α through the jets' velocities.
        // The main flap turns about C at -dφ/dα of its chord in 001's plane (mirrored).
        let main_turn = -(jets.f - PointJet::fixed(mechanism.hinge_c())).angle().d1;
        let main_velocity = |point: Point2<f64>| {
            let offset = point - c;
            Vector2::new(-offset.y, offset.x) * main_turn
        };
        let secondary_centre_rate = vector_to_station((jets.f.d1 + jets.trailing_edge.d1) * 0.5);
        let loads_power = wrench.power(main_velocity, main_turn) + secondary_weight.dot(&secondary_centre_rate);
        let sine = jets.toggle_sine;
        Ok(Kinetostatics {
            input,
            deflection_rad: pose.deflection_rad,
            actuator_load,
            actuator_load_virtual_work: -loads_power,
            reactions: vec![
                ("A".into(), f_ag),
                ("G1".into(), f_ag),
                ("G2".into(), pin_g2.norm()),
                ("C".into(), hinge_c.norm()),
                ("B".into(), f_bd),
                ("D".into(), f_bd),
                ("E".into(), f_eh),
                ("H".into(), f_eh),
                ("F".into(), pin_f.norm()),
                ("O".into(), f_ag),
            ],
            transmission_angle_rad: sine.clamp(0.0, 1.0).asin(),
            health: PoseHealth {
                closure_residual_m: mechanism.closure_residual(&jets),
                jacobian_condition_number: 1.0 / sine.max(1e-300),
                distance_to_toggle_rad: sine.clamp(0.0, 1.0).asin(),
            },
            actuator_torques: None,
            members: Vec::new(),
        })
    }

    fn drawing_notes(&self) -> DrawingNotes {
        let range = self.input_range();
        DrawingNotes {
            summary: format!(
                "five-bar double flap: crank {:.1} -> {:.1} deg, main flap {:.1} deg",
                range.stowed.to_degrees(),
                range.deployed.to_degrees(),
                self.deflection_range_rad().to_degrees()
            ),
            dimensions: Vec::new(),
            arcs: Vec::new(),
        }
    }

    fn details(&self) -> serde_json::Value {
        serde_json::json!({
            "dimensions_m": self.loaded.mechanism.dimensions,
            "branches": self.loaded.mechanism.branches,
            "main_deflection_stowed_deg": self.stowed_deflection_rad.to_degrees(),
            "main_deflection_deployed_deg": self.deployed_deflection_rad.to_degrees(),
        })
    }

    fn actuator(&self) -> Actuator {
        self.actuator
    }

    fn warnings(&self) -> Vec<String> {
        Vec::new()
    }

    fn dynamics(&self) -> Option<&dyn OneInputDynamics> {
        Some(&self.loaded)
    }
}
