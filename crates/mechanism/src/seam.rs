//! The mechanism seam: what every stage outside this crate sees of a mechanism kind.
//!
//! A kind (circular-arc track with screw jack, dropped hinge, four-bar, ...) is one module
//! of the `flapwright-kinds` crate that implements [`FlapMechanism`]; interference, fairing, URDF and
//! trajectory, drawings, plots, sizing and the report consume only this trait and the plain
//! data below, as parry's queries see a `Shape`. A new kind touches its own module and the
//! scene's kind enum, nothing that names another kind.
//!
//! # Parameters
//!
//! A mechanism moves with the **input** of its actuator ([`InputRange`]): a stroke (m) or
//! an angle (rad), from stowed to deployed. Everything is a function of it: poses, loads,
//! speed bounds (per unit input). Flap deflection is an output, not a parameter: a hooked
//! track moves its flap aft before it turns it, and a double flap has two deflections.
//!
//! Every station of a wing is driven by one shaft, each through its own ratio, so they
//! start and finish together (`003_...` section 3): the common parameter of the whole-wing
//! stages (interference, fairing) is the **drive fraction** τ in [0, 1], with
//! input = stowed + τ (deployed - stowed) at every station ([`InputRange::at_fraction`]).

//! # Frames
//!
//! The station frame (origin A0 on the hinge line, x towards the nose, y up, z spanwise
//! out of the plane). Bodies and their solids are given where they stand stowed; a
//! [`MechanismPose`] holds each body's planar displacement from there (an `Isometry2`), so
//! a stowed point `p` of body `b` stands at `pose.bodies[b] * p`.

use nalgebra::{Isometry2, Point2, Unit, Vector2};
use serde::Serialize;

use crate::error::Result;
use crate::shared::load_case::LoadCase;
pub use crate::shared::members::{DrawnRadius, Member, MemberLoad, MemberLoading};
use crate::shared::screw_jack::{ScrewJack, ScrewTorques};

/// What the actuator moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum InputQuantity {
    /// A linear actuator's stroke (m): screw jack nut, hydraulic rod.
    Stroke,
    /// A rotary actuator's angle (rad).
    Angle,
}

/// The actuator input over the deployment.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct InputRange {
    /// Stroke (m) or angle (rad).
    pub quantity: InputQuantity,
    /// Input with the flap stowed.
    pub stowed: f64,
    /// Input with the flap fully deployed.
    pub deployed: f64,
}

impl InputRange {
    /// `samples` evenly spaced inputs from stowed to deployed, both ends exact.
    pub fn samples(&self, samples: usize) -> Vec<f64> {
        let last = samples.saturating_sub(1).max(1) as f64;
        (0..samples)
            .map(|i| {
                if i + 1 == samples {
                    self.deployed
                } else {
                    self.stowed + (self.deployed - self.stowed) * i as f64 / last
                }
            })
            .collect()
    }

    /// Where `input` lies between stowed (0) and deployed (1).
    pub fn fraction(&self, input: f64) -> f64 {
        (input - self.stowed) / (self.deployed - self.stowed)
    }

    /// The input at drive fraction `fraction` (0 stowed, 1 deployed).
    pub fn at_fraction(&self, fraction: f64) -> f64 {
        self.stowed + fraction * (self.deployed - self.stowed)
    }

    /// The input travel, deployed - stowed (m or rad; its magnitude turns a speed bound
    /// per unit input into one per unit drive fraction).
    pub fn travel(&self) -> f64 {
        self.deployed - self.stowed
    }
}

/// The actuator a mechanism drives its flap with: sizing and the drive are written in
/// actuator types, never in mechanism kinds (a dropped hinge or a four-bar may take any).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "type", rename_all = "kebab-case")]
pub enum Actuator {
    /// A screw turned by the drive shaft moves a nut along it (thesis section 3.6); the
    /// input is the nut's stroke.
    ScrewJack {
        /// Lead, mean radius and thread friction.
        screw: ScrewJack,
        /// Screw length (m): the rod sized for buckling.
        screw_length_m: f64,
        /// Nominal nut speed (m/s): with the lead, the drive shaft's speed.
        nominal_speed_mps: f64,
    },
    /// A geared rotary actuator (`003_...` Fig. 6): the drive shaft turns `gear_ratio`
    /// times the output; the input is the output's angle (rad).
    Rotary {
        /// Drive-shaft angle per output angle.
        gear_ratio: f64,
        /// The gearing's mechanical efficiency, in (0, 1].
        efficiency: f64,
        /// Nominal output speed (rad/s).
        nominal_speed_radps: f64,
    },
}

/// Torques on an actuator's drive shaft for one actuator load: the drive stage's view of
/// every actuator type.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ShaftTorques {
    /// Torque to deploy against the load (N m).
    pub raise_torque_nm: f64,
    /// Torque to retract with the load (N m); positive: the actuator must be driven to
    /// retract (it holds its load by itself), negative: the load back-drives it.
    pub lower_torque_nm: f64,
}

impl Actuator {
    /// Drive-shaft angle per unit input (rad per m of stroke, or per rad of output).
    pub fn shaft_angle_per_input(&self) -> f64 {
        match self {
            Actuator::ScrewJack { screw, .. } => 2.0 * std::f64::consts::PI / screw.lead_m,
            Actuator::Rotary { gear_ratio, .. } => *gear_ratio,
        }
    }

    /// Nominal input speed (m/s or rad/s).
    pub fn nominal_input_speed(&self) -> f64 {
        match self {
            Actuator::ScrewJack { nominal_speed_mps, .. } => *nominal_speed_mps,
            Actuator::Rotary {
                nominal_speed_radps, ..
            } => *nominal_speed_radps,
        }
    }

    /// Nominal drive-shaft speed (rad/s).
    pub fn shaft_speed_radps(&self) -> f64 {
        self.nominal_input_speed() * self.shaft_angle_per_input()
    }

    /// The drive-shaft torques for actuator load `load` (N along the stroke, or N m about
    /// the output; positive resisting deployment). A screw jack: thesis eqs. 3.6.9-10. A
    /// geared rotary actuator of ratio N and efficiency η: power flows from the shaft when
    /// the load resists the motion, T/(N η), and back from the load when it aids it,
    /// T η / N, so deploying takes T/(N η) for T > 0 and retracting -T η / N.
    pub fn shaft_torques(&self, load: f64) -> ShaftTorques {
        match self {
            Actuator::ScrewJack { screw, .. } => {
                let torques = screw.torques(load);
                ShaftTorques {
                    raise_torque_nm: torques.raise_torque_nm,
                    lower_torque_nm: torques.lower_torque_nm,
                }
            }
            Actuator::Rotary {
                gear_ratio, efficiency, ..
            } => {
                let through = |driving: f64| if driving > 0.0 { 1.0 / efficiency } else { *efficiency };
                ShaftTorques {
                    raise_torque_nm: load * through(load) / gear_ratio,
                    lower_torque_nm: -load * through(-load) / gear_ratio,
                }
            }
        }
    }

    /// True when the actuator holds any load by itself: a screw whose friction exceeds its
    /// lead angle; a geared rotary actuator is taken as reversible (it needs a no-back
    /// brake).
    pub fn self_locking(&self) -> bool {
        match self {
            Actuator::ScrewJack { screw, .. } => screw.is_self_locking(),
            Actuator::Rotary { .. } => false,
        }
    }
}

/// What a body is for: the interference check's pair policy, the drawings' styles and the
/// viewers' materials are written in roles, never in kinds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum BodyRole {
    /// The flap and what is rigid with it (fittings, pins, brackets): a two-element flap's
    /// main element.
    Flap,
    /// The aft element of a two-element flap (second flap or vane) and what is rigid with
    /// it, where the mechanism moves it relative to the main element; a kind without such
    /// a body carries the aft element fixed to the main one.
    AftFlap,
    /// A link between pivots.
    Link,
    /// A track or slot fixed to the wing.
    Track,
    /// A carriage running on a track.
    Carriage,
    /// An actuator's moving part: screw, nut, rod.
    Actuator,
    /// Support structure fixed to the wing: hinge brackets, truss, actuator mounts.
    Support,
}

/// A solid in the station plane, where its body stands stowed (station frame, m).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "shape", rename_all = "kebab-case")]
pub enum PlanarShape {
    /// All points within `radius_m` of the segment `from`-`to` (a ball when they coincide).
    Capsule {
        /// One end (m).
        from: Point2<f64>,
        /// Other end (m).
        to: Point2<f64>,
        /// Radius (m).
        radius_m: f64,
    },
    /// A round tube along a polyline: a track swept along a pin's path.
    Tube {
        /// Centre line (m), at least two points.
        centre_line: Vec<Point2<f64>>,
        /// Radius (m).
        radius_m: f64,
    },
}

impl PlanarShape {
    /// The points that, thickened by [`PlanarShape::radius_m`], make the solid.
    pub fn skeleton(&self) -> Vec<Point2<f64>> {
        match self {
            Self::Capsule { from, to, .. } => vec![*from, *to],
            Self::Tube { centre_line, .. } => centre_line.clone(),
        }
    }

    /// The thickness about the skeleton (m).
    pub fn radius_m(&self) -> f64 {
        match self {
            Self::Capsule { radius_m, .. } | Self::Tube { radius_m, .. } => *radius_m,
        }
    }

    /// Largest distance of a point of the solid from `point` (m).
    pub fn reach_from(&self, point: &Point2<f64>) -> f64 {
        self.skeleton().iter().map(|p| (p - point).norm()).fold(0.0, f64::max) + self.radius_m()
    }
}

/// One named solid of a body: its shape in the plane and its spanwise extent.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodySolid {
    /// Part name within the station ("screw", "outer-track"): the report and JUnit name
    /// it `<station>.<name>`.
    pub name: String,
    /// Shape in the station plane, stowed.
    pub shape: PlanarShape,
    /// Spanwise width (m), along the station z axis; 0: as thick as the shape's radius
    /// suggests (a round solid).
    pub width_m: f64,
    /// Spanwise offset of the solid's mid-plane from the station plane (m).
    pub offset_m: f64,
}

impl BodySolid {
    /// A round solid (spanwise as thick as its radius, in the station plane): a capsule of
    /// `radius_m` about `from`-`to`, a ball when they coincide.
    pub fn capsule(name: &str, from: Point2<f64>, to: Point2<f64>, radius_m: f64) -> Self {
        Self {
            name: name.into(),
            shape: PlanarShape::Capsule { from, to, radius_m },
            width_m: 0.0,
            offset_m: 0.0,
        }
    }
}

/// A certified bound on how fast a body's points move per unit of the actuator input:
/// |dp/dq| <= `linear_per_input` + `angular_per_input` * |p - `reference`| for every point p
/// of the body, over the whole deployment (stowed coordinates: the distance to the
/// reference is the same in every pose of a rigid body). Finite wherever the transmission
/// angles stay away from a toggle, which synthesis guarantees over the deployment.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SpeedBound {
    /// A point of the body, stowed (m).
    pub reference: Point2<f64>,
    /// Largest speed of the reference point (m per unit input).
    pub linear_per_input: f64,
    /// Largest rotation rate of the body (rad per unit input).
    pub angular_per_input: f64,
}

impl SpeedBound {
    /// A body that does not move.
    pub const FIXED: Self = Self {
        reference: Point2::new(0.0, 0.0),
        linear_per_input: 0.0,
        angular_per_input: 0.0,
    };

    /// The bound for the points of `shape` (m per unit input).
    pub fn for_shape(&self, shape: &PlanarShape) -> f64 {
        self.linear_per_input + self.angular_per_input * shape.reach_from(&self.reference)
    }

    /// The bound for points within `reach_m` of the reference (m per unit input).
    pub fn within(&self, reach_m: f64) -> f64 {
        self.linear_per_input + self.angular_per_input * reach_m
    }
}

/// A rigid body of the mechanism (the ground is not one: fixed bodies are bodies whose
/// speed bound is zero).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Body {
    /// Name, unique within the mechanism ("flap", "screw", "outer-track").
    pub name: String,
    /// What it is for.
    pub role: BodyRole,
    /// Its solids, stowed.
    pub solids: Vec<BodySolid>,
    /// How fast its points can move per unit input.
    pub speed_bound: SpeedBound,
}

impl Body {
    /// True when the body moves with the deployment.
    pub fn is_moving(&self) -> bool {
        self.speed_bound != SpeedBound::FIXED
    }
}

/// How a joint constrains its two bodies, and where (stowed, station frame, m).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum JointGeometry {
    /// A pin: the bodies turn about a common point.
    Revolute {
        /// The pin's centre.
        at: Point2<f64>,
    },
    /// A slide: the second end translates along the first without turning.
    Prismatic {
        /// A point on the line of the slide.
        origin: Point2<f64>,
        /// Direction of the slide (unit).
        direction: Unit<Vector2<f64>>,
    },
    /// A pin of the first end in a circular slot of the second.
    PinInCircularSlot {
        /// The pin's centre.
        pin: Point2<f64>,
        /// The slot's centre of curvature.
        centre: Point2<f64>,
    },
    /// A pin of the first end in a straight slot of the second.
    PinInStraightSlot {
        /// The pin's centre.
        pin: Point2<f64>,
        /// Direction of the slot (unit).
        direction: Unit<Vector2<f64>>,
    },
    /// A pin of the first end in a hooked slot of the second: straight along `direction`
    /// for `lead_m` from the pin (stowed), then on the circular arc about `centre` tangent
    /// to it (the hooked-track's lead-in and hook, `003_...` Fig. 10).
    PinInHookedSlot {
        /// The pin's centre (stowed).
        pin: Point2<f64>,
        /// Direction of the straight lead-in (unit).
        direction: Unit<Vector2<f64>>,
        /// Length of the lead-in (m).
        lead_m: f64,
        /// The hook's centre of curvature.
        centre: Point2<f64>,
    },
}

/// One end of a joint: a body, or the wing (ground).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum JointEnd {
    /// The wing structure (ground).
    Ground,
    /// The body with this index in [`FlapMechanism::bodies`].
    Body(usize),
}

/// A joint between two bodies, by name (reactions are keyed by it).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Joint {
    /// Name, unique within the mechanism ("A", "B0", "F").
    pub name: String,
    /// What it is, in words for reports ("nut on the screw, pivoting on the flap").
    pub description: String,
    /// Its kind and where it is.
    pub geometry: JointGeometry,
    /// The two ends.
    pub ends: [JointEnd; 2],
    /// The solids of the two ends that touch by design (body solid names), checked to
    /// stay joined instead of clear.
    pub touching_solids: Vec<(String, String)>,
}

impl Joint {
    /// A joint named `name` between `ends`, whose `touching` solid pairs (end 0's, end 1's)
    /// are checked to stay joined.
    pub fn new(
        name: &str,
        description: &str,
        geometry: JointGeometry,
        ends: [JointEnd; 2],
        touching: &[(&str, &str)],
    ) -> Self {
        Self {
            name: name.into(),
            description: description.into(),
            geometry,
            ends,
            touching_solids: touching.iter().map(|(a, b)| (a.to_string(), b.to_string())).collect(),
        }
    }
}

/// A named point of a pose (station frame, m): a pivot, a pin, the centre of mass.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NamedPoint {
    /// Name ("A0", "B0", "A"): static, so that posing allocates no strings (the
    /// interference sweep poses a mechanism thousands of times).
    pub name: &'static str,
    /// Where it stands (m).
    pub position: Point2<f64>,
    /// True for a point fixed to the wing.
    pub fixed: bool,
}

/// What a station drawing shows of a kind besides its bodies (station frame, m, rad).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct DrawingNotes {
    /// One line: the kind and its input travel.
    pub summary: String,
    /// Dimension lines: label, from, to (stowed).
    pub dimensions: Vec<(String, Point2<f64>, Point2<f64>)>,
    /// Arcs of slots and tracks: name, centre, radius, start and end angle.
    pub arcs: Vec<(String, Point2<f64>, f64, f64, f64)>,
}

/// The mechanism at one input.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MechanismPose {
    /// Flap deflection (rad) of the main flap element.
    pub deflection_rad: f64,
    /// Actuator input.
    pub input: f64,
    /// Each body's displacement from stowed, in the order of [`FlapMechanism::bodies`].
    pub bodies: Vec<Isometry2<f64>>,
    /// The flap's planar displacement from stowed (general: not only a turn about A0).
    pub flap: Isometry2<f64>,
    /// Named points where they stand: pivots, pins, the centre of mass.
    pub points: Vec<NamedPoint>,
}

impl MechanismPose {
    /// The point called `name`, if the kind names one.
    pub fn point(&self, name: &str) -> Option<Point2<f64>> {
        self.points.iter().find(|p| p.name == name).map(|p| p.position)
    }

    /// The displacement of a two-element flap's aft element: that of the body
    /// [`aft_flap_body`] found, or the main element's ([`MechanismPose::flap`]) where there
    /// is none (the aft element fixed to the main one).
    pub fn aft_flap(&self, aft_body: Option<usize>) -> Isometry2<f64> {
        aft_body.map_or(self.flap, |k| self.bodies[k])
    }
}

/// The index of the body that moves a two-element flap's aft element (the one with
/// [`BodyRole::AftFlap`]), None where the kind has none: the aft element then stays fixed
/// to the main element.
pub fn aft_flap_body(bodies: &[Body]) -> Option<usize> {
    bodies.iter().position(|b| b.role == BodyRole::AftFlap)
}

/// How far a pose is from failing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PoseHealth {
    /// Loop-closure residual (m).
    pub closure_residual_m: f64,
    /// Condition number of the position Jacobian of the loop equations.
    pub jacobian_condition_number: f64,
    /// Angular distance to the nearest toggle (rad).
    pub distance_to_toggle_rad: f64,
}

/// Loads at one input under one load case (quasi-static unless the case asks for inertia).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Kinetostatics {
    /// Actuator input.
    pub input: f64,
    /// Flap deflection (rad).
    pub deflection_rad: f64,
    /// Actuator force (N, stroke inputs) or torque (N m, angle inputs) by equilibrium.
    pub actuator_load: f64,
    /// The same by virtual work (total power): an independent cross-check.
    pub actuator_load_virtual_work: f64,
    /// Reaction at each joint (N), by joint name, signed along the joint's line of action.
    pub reactions: Vec<(String, f64)>,
    /// Transmission angle (rad): the acute angle between the driving link and the driven
    /// one, pi/2 best, 0 a toggle.
    pub transmission_angle_rad: f64,
    /// Closure residual, condition number, distance to toggle.
    pub health: PoseHealth,
    /// Raise and lower torque of the actuator for this load where a screw thread gives
    /// them (a screw jack, thesis eqs. 3.6.9-10); None for other actuators, whose
    /// drive-shaft torques [`Actuator::shaft_torques`] gives. (Called `screw_torques`
    /// before issue 36: an actuator's name in the seam every kind implements.)
    pub actuator_torques: Option<ScrewTorques>,
    /// The internal loads of each member of [`FlapMechanism::members`], by member name.
    pub members: Vec<(String, MemberLoad)>,
}

/// A mechanism kind, synthesised for one station: everything the other stages use.
pub trait FlapMechanism: std::fmt::Debug + Send + Sync {
    /// The kind's scene name ("circular-arc-track").
    fn kind(&self) -> &'static str;

    /// The actuator input over the deployment.
    fn input_range(&self) -> InputRange;

    /// Flap deflection when fully deployed (rad); stowed is 0.
    fn deflection_range_rad(&self) -> f64;

    /// The smallest input that gives `deflection_rad` (a flap setting): unique for kinds
    /// that turn the flap from the start, the first one for a kind that moves the flap aft
    /// before turning it.
    fn input_at_deflection(&self, deflection_rad: f64) -> Result<f64>;

    /// The deflection `input` gives (rad).
    fn deflection_at_input(&self, input: f64) -> Result<f64>;

    /// Where the mechanism holds the flap, stowed (station frame, m): pins and pivots on the
    /// flap. The planes stage measures how far the flap's 3D motion takes them out of the
    /// station plane; precision positions are met there.
    fn flap_attachments(&self) -> Vec<NamedPoint>;

    /// The rigid bodies, each with its solids and speed bound.
    fn bodies(&self) -> &[Body];

    /// The joints.
    fn joints(&self) -> &[Joint];

    /// The pose at actuator input `input`.
    fn pose(&self, input: f64) -> Result<MechanismPose>;

    /// Loads at `input` under `load`.
    fn kinetostatics(&self, input: f64, load: &LoadCase) -> Result<Kinetostatics>;

    /// Dimension lines, slot arcs and a summary for the station drawing.
    fn drawing_notes(&self) -> DrawingNotes;

    /// The kind's own record for the report: its dimensions and what synthesis computed.
    fn details(&self) -> serde_json::Value;

    /// The actuator.
    fn actuator(&self) -> Actuator;

    /// Conditions worth a designer's look that do not stop the design, in words.
    fn warnings(&self) -> Vec<String>;

    /// The members to size: links, arms and struts (their loads at each pose are in
    /// [`Kinetostatics::members`]).
    fn members(&self) -> Vec<Member> {
        Vec::new()
    }

    /// The equation of motion in the input, when the kind models its bodies' masses and
    /// its loads itself (the dynamics stage drives it with a motor); None for a kind that
    /// leaves it to [`crate::rigid_flap`], from its flap's mass and its own poses and statics.
    fn dynamics(&self) -> Option<&dyn crate::generalised::OneInputDynamics> {
        None
    }

    /// The flap share this station carries, whose weight the statics hold: what
    /// [`crate::rigid_flap`] needs besides the poses. None for a kind that does not say.
    fn flap_mass(&self) -> Option<crate::shared::flap_load::FlapMass> {
        None
    }
}

/// A solid where it stands at `pose` (station frame).
pub fn posed_shape(shape: &PlanarShape, placement: &Isometry2<f64>) -> PlanarShape {
    match shape {
        PlanarShape::Capsule { from, to, radius_m } => PlanarShape::Capsule {
            from: placement * from,
            to: placement * to,
            radius_m: *radius_m,
        },
        PlanarShape::Tube { centre_line, radius_m } => PlanarShape::Tube {
            centre_line: centre_line.iter().map(|p| placement * p).collect(),
            radius_m: *radius_m,
        },
    }
}
