//! The dropped hinge (Zaccai, Bertels & Vos `003_...` section 3, Figs. 6-7): the flap turns
//! about one fixed hinge below the wing, carried by a hinged structure (two arms from the
//! hinge to the flap's forward and aft attachments), the hinge held by a truss to the lower
//! skin, and either a screw jack from a mount in the wing pushes the forward arm round or
//! a geared rotary actuator on the hinge turns the hinged structure (`003_...` Fig. 6:
//! "can be fitted with a linear actuator or a rotary actuator").
//!
//! Synthesis from two precision positions: the hinge is the pole of the flap's planar
//! displacement stowed -> landing ([`pole`]), so both are met exactly; take-off is then
//! wherever the turn about the hinge puts the flap at the take-off deflection, and its miss
//! is reported ([`DroppedHingeSynthesis::takeoff_miss_m`]; gap and overlap misses by the
//! caller that measures them).
//!
//! Kinematics: the flap turns by ψ(s) about the hinge H, the drive being a
//! [`RockerDrive`] (pivot H, mount B0, attachment P on the forward arm). Statics of the flap:
//! moments about H give the screw force F (along B0 -> P, positive pushing the flap):
//! F = -M_H / ((P - H) x u), u = (P - B0)/|P - B0|, M_H the applied wrench's moment about H;
//! the hinge carries R_H = -(F u + W). Virtual work, independently: F = -(W · dD/ds + C dψ/ds)
//! with dψ/ds from the drive's triangle (not from the cross product above). With the rotary
//! actuator the input is ψ itself: its torque is T = -M_H by moments about H, and
//! T = -(W · dD/dψ + C) by virtual work.

use nalgebra::{Isometry2, Point2, Vector2};
use serde::Serialize;

use flapwright_mechanism::seam::{
    Actuator, Body, DrawingNotes, FlapMechanism, InputQuantity, InputRange, Joint, Kinetostatics, MechanismPose,
    Member, NamedPoint, PoseHealth,
};
use flapwright_mechanism::shared::flap_load::{FlapMass, FlapWrench, LinkHardware};
use flapwright_mechanism::shared::geometry::{cross, turn_about};
use flapwright_mechanism::shared::load_case::LoadCase;
use flapwright_mechanism::shared::outline::StationOutline;
use flapwright_mechanism::shared::placement::{strut_top, turning_flap, ScrewJackChoice};
use flapwright_mechanism::shared::precision::{pole, PrecisionPosition};
use flapwright_mechanism::shared::rocker_drive::RockerDrive;
use flapwright_mechanism::shared::rotary_actuator::RotaryDrive;
use flapwright_mechanism::shared::screw_jack::ScrewDrive;
use flapwright_mechanism::{Error, Result, SynthesisDefect};

mod bodies;
mod members;
mod screw_jack;

use bodies::{bodies_and_joints, FLAP};
use screw_jack::screw_jack_layout;
pub use screw_jack::DroppedHingeScrewJack;

const KIND: &str = "dropped-hinge";

/// The designer's choices for a dropped hinge at one station (station frame, m).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DroppedHingeSpec {
    /// The landing setting (the second precision position; stowed is the first).
    pub landing: PrecisionPosition,
    /// The take-off setting, to report its miss (not a precision position).
    pub takeoff: Option<PrecisionPosition>,
    /// The hinged structure's attachments on the flap, forward and aft (stowed).
    pub flap_attachments: [Point2<f64>; 2],
    /// The actuator and its free choices.
    pub actuator: DroppedHingeActuator,
    /// The truss's two attachments on the wing (stowed, on the lower skin); `None`: the
    /// first lower-skin points ahead of the cove whose members keep clear of the structure
    /// and the turning flap ([`strut_top`]).
    pub support_points: Option<[Point2<f64>; 2]>,
    /// The flap share this station carries.
    pub flap_mass: FlapMass,
    /// Smallest transmission angle of the screw jack over the deployment (rad).
    pub min_transmission_angle_rad: f64,
    /// Solid sizes.
    pub hardware: LinkHardware,
    /// The station's sections: the hinge must lie outside the wing.
    pub outline: StationOutline,
    /// The station's load cases, under which the screw jack's placement weighs its force
    /// against the fairing's depth ([`flapwright_mechanism::shared::objective`]); empty: the
    /// shallowest clear placement.
    #[serde(skip)]
    pub design_loads: Vec<flapwright_mechanism::LoadCase>,
    /// Weight of the actuator's peak load against the fairing's depth.
    #[serde(skip)]
    pub load_weight: f64,
    /// How the jack's placement weighs the mass it adds (the screw and a horn below the
    /// hinge); `None`: not at all.
    #[serde(skip)]
    pub mass_weighing: Option<flapwright_mechanism::shared::objective::MassWeighing>,
}

impl DroppedHingeSpec {
    /// How the jack's placement weighs its load: under [`Self::design_loads`] with
    /// [`Self::load_weight`], or not at all without them.
    pub fn weighing(&self) -> Option<flapwright_mechanism::shared::objective::LoadWeighing> {
        (!self.design_loads.is_empty()).then(|| flapwright_mechanism::shared::objective::LoadWeighing {
            loads: self.design_loads.clone(),
            flap_mass: self.flap_mass,
            weight: self.load_weight,
            load_cap: None,
            mass: self.mass_weighing,
        })
    }
}

/// The share of the in-plane margin the screw jack's placement keeps from the sections
/// (see its use in [`DroppedHinge::synthesise`]).
const JACK_MARGIN_SHARE: f64 = 0.25;

/// Where the truss's members may meet the lower skin, in flap chords ahead of the cove's
/// lower lip, in the order the forward member tries them (the aft one the other way).
const SUPPORT_AHEAD: [f64; 10] = [0.3, 0.25, 0.2, 0.15, 0.1, 0.05, 0.4, 0.5, 0.7, 1.0];

/// What drives a dropped hinge (`003_...` Fig. 6).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "type", rename_all = "kebab-case")]
pub enum DroppedHingeActuator {
    /// A screw jack from a mount in the wing to the forward arm (or a horn below the hinge).
    ScrewJack {
        /// Where the screw takes hold of the forward arm: 0 at the forward attachment, 1 at
        /// the hinge (`003_...`: "between the forward flap attachment and the lower
        /// mechanism hinge"); `None`: searched ([`flapwright_mechanism::shared::placement::place_screw_jack`]).
        attachment_fraction: Option<f64>,
        /// The screw's mount; `None`: square to the arm at mid-travel, at the first of a
        /// few standoffs from `standoff_m` and attachments from `attachment_fraction` whose
        /// screw and jack body keep clear of the wing, the structure and the turning flap
        /// ([`flapwright_mechanism::shared::placement::screw_jack_placement`]).
        mount: Option<Point2<f64>>,
        /// Distance from the attachment's mid-travel position to a default mount (m).
        standoff_m: f64,
        /// The screw's thread and the shared drive.
        drive: ScrewDrive,
        /// Take this candidate of the placement's trade (the report's `trade`, from 0)
        /// instead of the one the weights choose; `None`: theirs.
        trade_index: Option<usize>,
    },
    /// A geared rotary actuator on the hinge, fixed to the support truss, its output the
    /// hinged structure: the input is the flap's turn about the hinge.
    Rotary(RotaryDrive),
}

/// What synthesis computed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DroppedHingeSynthesis {
    /// The hinge H: the pole of stowed -> landing (m).
    pub hinge_m: Point2<f64>,
    /// The truss's attachments on the wing (m).
    pub support_points_m: [Point2<f64>; 2],
    /// False when no default place of the support truss kept clear of the structure and
    /// the flap at the sampled poses (the interference check says where).
    pub placement_clear: bool,
    /// The screw jack's layout, when a screw jack drives the hinge.
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub screw_jack: Option<DroppedHingeScrewJack>,
    /// The geared rotary actuator on the hinge, when one drives it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rotary_actuator: Option<Actuator>,
    /// Largest distance (m) between where the turn about H puts a flap attachment at the
    /// take-off deflection and where the take-off setting wants it (None without one).
    pub takeoff_miss_m: Option<f64>,
    /// Largest distance (m) between the turn about H and the landing setting at the flap
    /// attachments: rounding only, the hinge being the pole.
    pub landing_miss_m: f64,
    /// The first deflection (rad) where the turn about the hinge takes the flap through the
    /// wing's trailing edge (sampled; None when it stays clear): the two precision positions
    /// leave no choice, so it is a warning, and the interference check says how deep.
    pub flap_through_lip_at_rad: Option<f64>,
}

/// A dropped hinge synthesised for one station.
#[derive(Debug, Clone)]
pub struct DroppedHinge {
    spec: DroppedHingeSpec,
    synthesis: DroppedHingeSynthesis,
    drive: Drive,
    actuator: Actuator,
    bodies: Vec<Body>,
    joints: Vec<Joint>,
}

/// How the input turns the flap.
#[derive(Debug, Clone)]
enum Drive {
    /// The screw's stroke through the drive's triangle.
    Screw(RockerDrive),
    /// The rotary actuator's output angle is the turn.
    Rotary,
}

/// Samples of the transmission-angle check over the deployment.
const TRANSMISSION_SAMPLES: usize = 64;

fn failure(defect: SynthesisDefect, detail: String) -> Error {
    Error::Synthesis {
        kind: KIND,
        defect,
        detail,
    }
}

/// A rotary actuator's input angle, checked finite.
fn finite_angle(input: f64) -> Result<f64> {
    if input.is_finite() {
        Ok(input)
    } else {
        Err(Error::NonFinite {
            quantity: "rotary actuator angle",
            input_m: input,
        })
    }
}

fn mm(p: Point2<f64>) -> String {
    format!("({:.1}, {:.1}) mm", p.x * 1e3, p.y * 1e3)
}

impl DroppedHinge {
    /// Synthesises the hinge, drive and solids. Errors ([`Error::Synthesis`]): a landing
    /// rotation too small for a pole (no real solution), a hinge inside the wing section
    /// (pivot outside the region), a drive that passes a toggle or drops below the
    /// minimum transmission angle (toggle).
    pub fn synthesise(spec: DroppedHingeSpec) -> Result<Self> {
        let landing = spec.landing;
        if landing.deflection_rad.abs() < 1f64.to_radians() || landing.deflection_rad.is_nan() {
            return Err(failure(
                SynthesisDefect::NoRealSolution,
                format!(
                    "a landing deflection of {:.3} deg has no hinge to turn about",
                    landing.deflection_rad.to_degrees()
                ),
            ));
        }
        let hinge = pole(&landing.flap).ok_or_else(|| {
            failure(
                SynthesisDefect::NoRealSolution,
                "the landing displacement has no pole".into(),
            )
        })?;
        if spec.outline.wing.inside(hinge) {
            return Err(failure(
                SynthesisDefect::PivotOutsideRegion,
                format!(
                    "the landing setting's pole {} lies inside the wing section: these deflection, gap and overlap need a hinge inside the wing box",
                    mm(hinge)
                ),
            ));
        }
        let turn = landing.deflection_rad;
        let at_landing = turn_about(hinge, turn);
        let landing_miss_m = spec
            .flap_attachments
            .iter()
            .map(|p| (at_landing * p - landing.flap * p).norm())
            .fold(0.0, f64::max);
        let takeoff_miss_m = spec.takeoff.map(|takeoff| {
            let at = turn_about(hinge, takeoff.deflection_rad);
            spec.flap_attachments
                .iter()
                .map(|p| (at * p - takeoff.flap * p).norm())
                .fold(0.0, f64::max)
        });
        let hw = spec.hardware;
        // In-plane margin for the 3D check's clearance and the flap's taper across a part's width.
        let margin = hw.link_radius_m;
        let (drive, screw_jack, rotary_actuator, actuator) = match spec.actuator {
            DroppedHingeActuator::ScrewJack {
                attachment_fraction,
                mount,
                standoff_m,
                drive,
                trade_index,
            } => {
                let choice = ScrewJackChoice {
                    arm: (spec.flap_attachments[0], hinge),
                    attachment_fraction,
                    // On the arm (towards the forward attachment the screw's lever grows),
                    // then on a horn below the hinge.
                    other_fractions: &[0.65, 0.8, 0.4, 0.35, 0.3, 0.25, 0.2, 0.15, 0.1, 1.4, 1.8],
                    mount,
                    standoff_m,
                    min_transmission_rad: spec.min_transmission_angle_rad,
                };
                // The jack stands a layer aside of the arms (the spanwise layout), so the
                // in-plane margin that keeps the arms and the truss clear of the flap's taper
                // across their width need not keep it: a quarter of it (13 mm on the
                // transport's outboard flap, the check requiring 3 mm) let the screw take
                // hold nearer the forward attachment (ob-inner 87.1 -> 65.1 kN, ob-outer
                // 79.4 -> 54.6 kN), every station of the four aircraft scenes still clear.
                let (rocker, layout) =
                    screw_jack_layout(&spec, hinge, &choice, &drive, JACK_MARGIN_SHARE * margin, trade_index)?;
                let actuator = Actuator::ScrewJack {
                    screw: layout.screw,
                    screw_length_m: layout.screw_length_m,
                    nominal_speed_mps: layout.nominal_speed_mps,
                };
                (Drive::Screw(rocker), Some(layout), None, actuator)
            }
            DroppedHingeActuator::Rotary(drive) => {
                let actuator = drive.actuator_for(turn);
                (Drive::Rotary, None, Some(actuator), actuator)
            }
        };
        let mut placement_clear = true;
        let support_points = match spec.support_points {
            Some(points) => points,
            None => {
                let poses = turning_flap(hinge, turn);
                let flap_chord = spec.outline.flap_chord().map_or(0.0, |(_, _, c)| c);
                let ahead = SUPPORT_AHEAD;
                let first = strut_top(&spec.outline, hinge, &ahead, hw.link_radius_m, margin, &poses, None);
                let behind: Vec<f64> = ahead.iter().rev().copied().collect();
                let second = strut_top(&spec.outline, hinge, &behind, hw.link_radius_m, margin, &poses, first);
                match (first, second) {
                    (Some(a), Some(b)) => [a, b],
                    _ => {
                        placement_clear = false;
                        let lip = spec.outline.cove_lower_lip_x().unwrap_or(hinge.x);
                        let skin = |k: f64| {
                            let x = lip + k * flap_chord;
                            spec.outline.wing_lower_point(x).unwrap_or(Point2::new(x, hinge.y))
                        };
                        [skin(0.3), skin(0.1)]
                    }
                }
            }
        };
        let lip_tolerance = 1e-6 * spec.outline.chord_m().unwrap_or(1.0);
        let flap_through_lip_at_rad = (1..TRANSMISSION_SAMPLES)
            .map(|k| turn * k as f64 / TRANSMISSION_SAMPLES as f64)
            .find(|&psi| spec.outline.flap_near_lip(&turn_about(hinge, psi), lip_tolerance));
        let synthesis = DroppedHingeSynthesis {
            flap_through_lip_at_rad,
            hinge_m: hinge,
            support_points_m: support_points,
            placement_clear,
            screw_jack,
            rotary_actuator,
            takeoff_miss_m,
            landing_miss_m,
        };
        let (bodies, joints) = bodies_and_joints(&spec, &synthesis, &drive);
        Ok(Self {
            spec,
            synthesis,
            drive,
            actuator,
            bodies,
            joints,
        })
    }

    /// The designer's choices.
    pub fn spec(&self) -> &DroppedHingeSpec {
        &self.spec
    }

    /// What synthesis computed.
    pub fn synthesis(&self) -> &DroppedHingeSynthesis {
        &self.synthesis
    }
}

impl DroppedHinge {
    /// The screw jack's drive triangle and layout, when a screw jack drives the hinge.
    fn screw_jack(&self) -> Option<(&RockerDrive, &DroppedHingeScrewJack)> {
        match (&self.drive, &self.synthesis.screw_jack) {
            (Drive::Screw(rocker), Some(jack)) => Some((rocker, jack)),
            _ => None,
        }
    }

    /// The rotary actuator's input range: its output angle, stowed to landing.
    fn angle_range(&self) -> InputRange {
        InputRange {
            quantity: InputQuantity::Angle,
            stowed: 0.0,
            deployed: self.spec.landing.deflection_rad,
        }
    }
}

impl FlapMechanism for DroppedHinge {
    fn kind(&self) -> &'static str {
        KIND
    }

    fn input_range(&self) -> InputRange {
        match self.screw_jack() {
            Some((_, jack)) => InputRange {
                quantity: InputQuantity::Stroke,
                stowed: jack.stroke_m[0],
                deployed: jack.stroke_m[1],
            },
            None => self.angle_range(),
        }
    }

    fn deflection_range_rad(&self) -> f64 {
        self.spec.landing.deflection_rad
    }

    fn input_at_deflection(&self, deflection_rad: f64) -> Result<f64> {
        Ok(match self.screw_jack() {
            Some((rocker, _)) => rocker.stroke_at(deflection_rad),
            None => deflection_rad,
        })
    }

    fn deflection_at_input(&self, input: f64) -> Result<f64> {
        match self.screw_jack() {
            Some((rocker, _)) => Ok(rocker.state(input)?.rotation_rad),
            None => finite_angle(input),
        }
    }

    /// The forward and aft attachments of the hinged structure.
    fn flap_attachments(&self) -> Vec<NamedPoint> {
        let [forward, aft] = self.spec.flap_attachments;
        vec![
            NamedPoint {
                name: "F1",
                position: forward,
                fixed: false,
            },
            NamedPoint {
                name: "F2",
                position: aft,
                fixed: false,
            },
        ]
    }

    fn bodies(&self) -> &[Body] {
        &self.bodies
    }

    fn joints(&self) -> &[Joint] {
        &self.joints
    }

    fn pose(&self, input: f64) -> Result<MechanismPose> {
        let h = self.synthesis.hinge_m;
        let [forward, aft] = self.spec.flap_attachments;
        let mut points = vec![
            ("H", h, true),
            ("S1", self.synthesis.support_points_m[0], true),
            ("S2", self.synthesis.support_points_m[1], true),
        ];
        let (rotation_rad, mut bodies) = match self.screw_jack() {
            Some((rocker, jack)) => {
                let state = rocker.state(input)?;
                let (screw, nut) = rocker.screw_and_nut(state.attachment);
                points.extend([("B0", jack.actuator_mount_m, true), ("P", state.attachment, false)]);
                (state.rotation_rad, vec![screw, nut])
            }
            None => (finite_angle(input)?, Vec::new()),
        };
        let flap = turn_about(h, rotation_rad);
        points.extend([
            ("F1", flap * forward, false),
            ("F2", flap * aft, false),
            ("D", flap * self.spec.flap_mass.centre_of_mass_stowed_m, false),
        ]);
        bodies.insert(FLAP, flap);
        bodies.push(Isometry2::identity());
        Ok(MechanismPose {
            deflection_rad: rotation_rad,
            input,
            bodies,
            flap,
            points: points
                .into_iter()
                .map(|(name, position, fixed)| NamedPoint { name, position, fixed })
                .collect(),
        })
    }

    fn kinetostatics(&self, input: f64, load: &LoadCase) -> Result<Kinetostatics> {
        let h = self.synthesis.hinge_m;
        let fraction = self.input_range().fraction(input).clamp(0.0, 1.0);
        // The actuator's load by moments about H, the hinge's reaction, dψ/dq, and the
        // actuator's own reactions, transmission and health.
        let (
            rotation_rad,
            load_n,
            hinge_reaction,
            rate,
            drive_reactions,
            transmission,
            health,
            screw_torques,
            screw_push,
        ) = match self.screw_jack() {
            Some((rocker, jack)) => {
                let state = rocker.state(input)?;
                let flap = turn_about(h, state.rotation_rad);
                let wrench = FlapWrench::new(&self.spec.flap_mass, &flap, load, fraction);
                let p = state.attachment;
                let u = (p - jack.actuator_mount_m).normalize();
                let force = -wrench.moment_about(h) / cross(p - h, u);
                let hinge_reaction: Vector2<f64> = -(u * force + wrench.force_n());
                (
                    state.rotation_rad,
                    force,
                    hinge_reaction,
                    // dψ/ds from the drive's triangle.
                    state.rotation_per_stroke,
                    vec![("B0".to_string(), force), ("P".to_string(), force)],
                    state.transmission_angle_rad,
                    PoseHealth {
                        closure_residual_m: state.closure_residual_m,
                        jacobian_condition_number: state.jacobian_condition_number,
                        distance_to_toggle_rad: state.transmission_angle_rad,
                    },
                    Some(jack.screw.torques(force)),
                    Some((p, u * force)),
                )
            }
            None => {
                // The rotary actuator turns the arms about H directly: no toggle, no
                // closure; its torque balances the applied moment about H.
                let rotation_rad = finite_angle(input)?;
                let flap = turn_about(h, rotation_rad);
                let wrench = FlapWrench::new(&self.spec.flap_mass, &flap, load, fraction);
                let right_angle = std::f64::consts::FRAC_PI_2;
                (
                    rotation_rad,
                    -wrench.moment_about(h),
                    -wrench.force_n(),
                    1.0,
                    Vec::new(),
                    right_angle,
                    PoseHealth {
                        closure_residual_m: 0.0,
                        jacobian_condition_number: 1.0,
                        distance_to_toggle_rad: right_angle,
                    },
                    None,
                    None,
                )
            }
        };
        // Virtual work, independently of the moments: Q dq + Σ f · dp + C dψ = 0.
        let flap = turn_about(h, rotation_rad);
        let wrench = FlapWrench::new(&self.spec.flap_mass, &flap, load, fraction);
        let velocity_of = |point: Point2<f64>| {
            let r = point - h;
            Vector2::new(-r.y, r.x) * rate
        };
        let load_virtual_work = -wrench.power(velocity_of, rate);
        let mut reactions = drive_reactions;
        reactions.push(("H".to_string(), hinge_reaction.norm()));
        reactions.sort_by(|a, b| a.0.cmp(&b.0));
        Ok(Kinetostatics {
            input,
            deflection_rad: rotation_rad,
            actuator_load: load_n,
            actuator_load_virtual_work: load_virtual_work,
            reactions,
            transmission_angle_rad: transmission,
            health,
            actuator_torques: screw_torques,
            members: members::member_loads(self, &flap, &wrench, screw_push, hinge_reaction),
        })
    }

    fn drawing_notes(&self) -> DrawingNotes {
        let s = &self.synthesis;
        let h = s.hinge_m;
        let forward = self.spec.flap_attachments[0];
        let radius = (forward - h).norm();
        let start = (forward - h).y.atan2((forward - h).x);
        let (summary, dimensions) = match self.screw_jack() {
            Some((_, jack)) => (
                format!(
                    "dropped hinge with screw jack; stroke {:.1} -> {:.1} mm",
                    jack.stroke_m[0] * 1e3,
                    jack.stroke_m[1] * 1e3
                ),
                vec![
                    ("H-P".into(), h, jack.actuator_attachment_m),
                    ("B0-P".into(), jack.actuator_mount_m, jack.actuator_attachment_m),
                ],
            ),
            None => (
                format!(
                    "dropped hinge with geared rotary actuator on the hinge; gear ratio {:.0}:1",
                    self.actuator().shaft_angle_per_input()
                ),
                vec![("H-F1".into(), h, forward)],
            ),
        };
        DrawingNotes {
            summary,
            dimensions,
            arcs: vec![(
                "F1 about H".into(),
                h,
                radius,
                start,
                start + self.spec.landing.deflection_rad,
            )],
        }
    }

    fn details(&self) -> serde_json::Value {
        serde_json::json!({
            "flap_attachments_m": self.spec.flap_attachments,
            "hardware": self.spec.hardware,
            "synthesis": self.synthesis,
        })
    }

    fn actuator(&self) -> Actuator {
        self.actuator
    }

    /// The support truss's two members, pinned at both ends, and the hinged structure's
    /// arms (and horn), cantilevered from the hinge (see the `members` module).
    fn members(&self) -> Vec<Member> {
        members::members(self)
    }

    fn flap_mass(&self) -> Option<FlapMass> {
        Some(self.spec.flap_mass)
    }

    fn warnings(&self) -> Vec<String> {
        let mut warnings = Vec::new();
        if let Some(at) = self.synthesis.flap_through_lip_at_rad {
            warnings.push(format!(
                "the turn about the hinge takes the flap through or within {:.1} mm of the wing's trailing edge at {:.1} deg: a dropped hinge meets stowed and landing only",
                1e3 * self.spec.outline.lip_clearance_m,
                at.to_degrees()
            ));
        }
        if self.screw_jack().is_some_and(|(_, jack)| !jack.actuator_clear) {
            warnings.push("no default place of the screw jack kept clear of the wing, the structure and the flap at the sampled poses; give actuator_mount_m".into());
        }
        if !self.synthesis.placement_clear {
            warnings.push("no default place of the support truss kept clear of the structure and the flap at the sampled poses; give support_points_m".into());
        }
        warnings
    }
}
