//! The dropped hinge (Zaccai, Bertels & Vos `003_...` section 3, Figs. 6-7): the flap turns
//! about one fixed hinge below the wing, carried by a hinged structure (two arms from the
//! hinge to the flap's forward and aft attachments), the hinge held by a truss to the lower
//! skin, and a screw jack from a mount in the wing pushes the forward arm round.
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
//! with dψ/ds from the drive's triangle (not from the cross product above).

use nalgebra::{Isometry2, Point2, Vector2};
use serde::Serialize;

use crate::error::{Error, Result, SynthesisDefect};
use crate::flap_load::{FlapMass, FlapWrench, LinkHardware};
use crate::kinetostatics::LoadCase;
use crate::outline::{inside, StationOutline};
use crate::placement::{place_screw_jack, strut_top, turning_flap, JackSize, ScrewJackChoice};
use crate::precision::{pole, PrecisionPosition};
use crate::rocker_drive::{cross, turn_about, RockerDrive, ScrewJackParts};
use crate::screw_jack::{ScrewDrive, ScrewJack};
use crate::seam::{
    Actuator, Body, BodyRole, BodySolid, DrawingNotes, FlapMechanism, InputQuantity, InputRange, Joint, JointEnd,
    JointGeometry, Kinetostatics, MechanismPose, NamedPoint, PoseHealth, SpeedBound, TwoForceMember,
};

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
    /// Where the screw takes hold of the forward arm: 0 at the forward attachment, 1 at the
    /// hinge (`003_...`: "between the forward flap attachment and the lower mechanism hinge").
    pub actuator_attachment_fraction: f64,
    /// The screw's mount; `None`: square to the arm at mid-travel, at the first of a few
    /// standoffs from `actuator_standoff_m` and attachments from
    /// `actuator_attachment_fraction` whose screw and jack body keep clear of the wing, the
    /// structure and the turning flap ([`crate::placement::screw_jack_placement`]).
    pub actuator_mount: Option<Point2<f64>>,
    /// Distance from the attachment's mid-travel position to a default mount (m).
    pub actuator_standoff_m: f64,
    /// The truss's two attachments on the wing (stowed, on the lower skin); `None`: the
    /// first lower-skin points ahead of the cove whose members keep clear of the structure
    /// and the turning flap ([`strut_top`]).
    pub support_points: Option<[Point2<f64>; 2]>,
    /// The flap share this station carries.
    pub flap_mass: FlapMass,
    /// The screw's thread and the shared drive.
    pub screw_drive: ScrewDrive,
    /// Smallest transmission angle of the drive over the deployment (rad).
    pub min_transmission_angle_rad: f64,
    /// Solid sizes.
    pub hardware: LinkHardware,
    /// The station's sections: the hinge must lie outside the wing.
    pub outline: StationOutline,
}

/// What synthesis computed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DroppedHingeSynthesis {
    /// The hinge H: the pole of stowed -> landing (m).
    pub hinge_m: Point2<f64>,
    /// The screw's mount B0 (m).
    pub actuator_mount_m: Point2<f64>,
    /// The truss's attachments on the wing (m).
    pub support_points_m: [Point2<f64>; 2],
    /// False when no default place of the screw jack kept clear of the wing, the structure
    /// and the flap at the sampled poses (the interference check says where).
    pub actuator_clear: bool,
    /// False when no default place of the support truss kept clear of the structure and
    /// the flap at the sampled poses (the interference check says where).
    pub placement_clear: bool,
    /// The screw's attachment P on the forward arm, stowed (m).
    pub actuator_attachment_m: Point2<f64>,
    /// Stroke |P - B0| stowed and at landing (m).
    pub stroke_m: [f64; 2],
    /// Smallest transmission angle of the drive over the deployment (rad, sampled).
    pub min_transmission_angle_rad: f64,
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
    /// The screw chosen from the drive: lead, radius, friction.
    pub screw: ScrewJack,
    /// Screw length (m): the longest stroke and the nut.
    pub screw_length_m: f64,
    /// Nominal nut speed (m/s).
    pub nominal_speed_mps: f64,
}

/// A dropped hinge synthesised for one station.
#[derive(Debug, Clone)]
pub struct DroppedHinge {
    spec: DroppedHingeSpec,
    synthesis: DroppedHingeSynthesis,
    drive: RockerDrive,
    bodies: Vec<Body>,
    joints: Vec<Joint>,
}

const FLAP: usize = 0;
const SCREW: usize = 1;
const NUT: usize = 2;
const SUPPORT: usize = 3;

/// Samples of the transmission-angle check over the deployment.
const TRANSMISSION_SAMPLES: usize = 64;

fn failure(defect: SynthesisDefect, detail: String) -> Error {
    Error::Synthesis {
        kind: KIND,
        defect,
        detail,
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
        if inside(&spec.outline.wing, hinge) {
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
        let choice = ScrewJackChoice {
            arm: (spec.flap_attachments[0], hinge),
            attachment_fraction: spec.actuator_attachment_fraction,
            // On the arm, then on a horn below the hinge.
            other_fractions: &[0.65, 0.8, 0.35, 1.4, 1.8],
            mount: spec.actuator_mount,
            standoff_m: spec.actuator_standoff_m,
            min_transmission_rad: spec.min_transmission_angle_rad,
        };
        let size = JackSize::new(&hw, spec.screw_drive.mean_radius_m);
        let flap_at = |psi: f64| Some(turn_about(hinge, psi));
        let (attachment, mount, actuator_clear) =
            place_screw_jack(hinge, turn, &choice, &size, margin, &spec.outline, &flap_at);
        let mut placement_clear = true;
        let support_points = match spec.support_points {
            Some(points) => points,
            None => {
                let poses = turning_flap(hinge, turn);
                let flap_chord = spec.outline.flap_chord().map_or(0.0, |(_, _, c)| c);
                let ahead = [0.3, 0.25, 0.2, 0.15, 0.1, 0.05, 0.4, 0.5, 0.7, 1.0];
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
        let drive = RockerDrive::try_new(hinge, mount, attachment).map_err(|_| {
            failure(
                SynthesisDefect::Toggle,
                format!(
                    "the screw mount {}, the hinge {} and the screw's attachment {} lie on one line",
                    mm(mount),
                    mm(hinge),
                    mm(attachment)
                ),
            )
        })?;
        let min_transmission = (0..=TRANSMISSION_SAMPLES)
            .map(|k| {
                let psi = turn * k as f64 / TRANSMISSION_SAMPLES as f64;
                drive
                    .state(drive.stroke_at(psi))
                    .map_or(0.0, |state| state.transmission_angle_rad)
            })
            .fold(f64::INFINITY, f64::min);
        if !drive.clear_of_toggles(turn, 1e-3) || min_transmission < spec.min_transmission_angle_rad {
            return Err(failure(
                SynthesisDefect::Toggle,
                format!(
                    "the screw's transmission angle falls to {:.1} deg (minimum {:.1} deg); move the actuator mount or its attachment",
                    min_transmission.to_degrees(),
                    spec.min_transmission_angle_rad.to_degrees()
                ),
            ));
        }
        let stroke_m = [drive.stroke_at(0.0), drive.stroke_at(turn)];
        let (screw, nominal_speed_mps) = spec.screw_drive.screw_for(stroke_m[1] - stroke_m[0]);
        // Long enough to carry the nut at the longest stroke, no longer: a screw's free end
        // beyond the nut would sweep into the flap.
        let screw_length_m = stroke_m[0].max(stroke_m[1]) + hw.nut_radius_m;
        let lip_tolerance = 1e-6 * spec.outline.chord_m().unwrap_or(1.0);
        let flap_through_lip_at_rad = (1..TRANSMISSION_SAMPLES)
            .map(|k| turn * k as f64 / TRANSMISSION_SAMPLES as f64)
            .find(|&psi| spec.outline.flap_near_lip(&turn_about(hinge, psi), lip_tolerance));
        let synthesis = DroppedHingeSynthesis {
            flap_through_lip_at_rad,
            hinge_m: hinge,
            actuator_mount_m: mount,
            support_points_m: support_points,
            actuator_clear,
            placement_clear,
            actuator_attachment_m: attachment,
            stroke_m,
            min_transmission_angle_rad: min_transmission,
            takeoff_miss_m,
            landing_miss_m,
            screw,
            screw_length_m,
            nominal_speed_mps,
        };
        let (bodies, joints) = bodies_and_joints(&spec, &synthesis, &drive);
        Ok(Self {
            spec,
            synthesis,
            drive,
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

fn bodies_and_joints(
    spec: &DroppedHingeSpec,
    synthesis: &DroppedHingeSynthesis,
    drive: &RockerDrive,
) -> (Vec<Body>, Vec<Joint>) {
    let hw = &spec.hardware;
    let (h, p) = (synthesis.hinge_m, synthesis.actuator_attachment_m);
    let [forward, aft] = spec.flap_attachments;
    let turn = spec.landing.deflection_rad;
    let capsule = |name: &str, from, to| BodySolid::capsule(name, from, to, hw.link_radius_m);
    // The screw takes hold of the forward arm, or of a horn below the hinge.
    let on_horn = (p - forward).dot(&(h - forward)) > (h - forward).norm_squared();
    let holder = if on_horn { "horn" } else { "arm-forward" };
    let mut flap_solids = vec![capsule("arm-forward", h, forward), capsule("arm-aft", h, aft)];
    if on_horn {
        flap_solids.push(capsule("horn", h, p));
    }
    let (screw_and_nut, jack_joints) = ScrewJackParts {
        drive,
        rotation_rad: turn,
        screw_length_m: synthesis.screw_length_m,
        screw_radius_m: synthesis.screw.mean_radius_m + 0.25 * synthesis.screw.lead_m,
        hardware: hw,
        indices: [FLAP, SCREW, NUT],
        pivot: ("P", holder),
    }
    .build();
    let mut bodies = vec![Body {
        name: "flap".into(),
        role: BodyRole::Flap,
        solids: flap_solids,
        speed_bound: SpeedBound {
            reference: h,
            linear_per_input: 0.0,
            // Per metre of stroke (RockerDrive::rotation_rate_bound).
            angular_per_input: drive.rotation_rate_bound(turn),
        },
    }];
    bodies.extend(screw_and_nut);
    bodies.push(Body {
        name: "support".into(),
        role: BodyRole::Support,
        solids: vec![
            capsule("truss-forward", h, synthesis.support_points_m[0]),
            capsule("truss-aft", h, synthesis.support_points_m[1]),
        ],
        speed_bound: SpeedBound::FIXED,
    });
    let mut joints = vec![Joint::new(
        "H",
        "the flap's hinge on the support truss",
        JointGeometry::Revolute { at: h },
        [JointEnd::Body(SUPPORT), JointEnd::Body(FLAP)],
        &[("truss-forward", "arm-forward"), ("truss-aft", "arm-aft")],
    )];
    joints.extend(jack_joints);
    (bodies, joints)
}

impl FlapMechanism for DroppedHinge {
    fn kind(&self) -> &'static str {
        KIND
    }

    fn input_range(&self) -> InputRange {
        InputRange {
            quantity: InputQuantity::Stroke,
            stowed: self.synthesis.stroke_m[0],
            deployed: self.synthesis.stroke_m[1],
        }
    }

    fn deflection_range_rad(&self) -> f64 {
        self.spec.landing.deflection_rad
    }

    fn input_at_deflection(&self, deflection_rad: f64) -> Result<f64> {
        Ok(self.drive.stroke_at(deflection_rad))
    }

    fn deflection_at_input(&self, input: f64) -> Result<f64> {
        Ok(self.drive.state(input)?.rotation_rad)
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
        let state = self.drive.state(input)?;
        let (h, b0) = (self.synthesis.hinge_m, self.synthesis.actuator_mount_m);
        let flap = turn_about(h, state.rotation_rad);
        let (screw, nut) = self.drive.screw_and_nut(state.attachment);
        let [forward, aft] = self.spec.flap_attachments;
        let points = [
            ("H", h, true),
            ("B0", b0, true),
            ("S1", self.synthesis.support_points_m[0], true),
            ("S2", self.synthesis.support_points_m[1], true),
            ("P", state.attachment, false),
            ("F1", flap * forward, false),
            ("F2", flap * aft, false),
            ("D", flap * self.spec.flap_mass.centre_of_mass_stowed_m, false),
        ]
        .into_iter()
        .map(|(name, position, fixed)| NamedPoint { name, position, fixed })
        .collect();
        Ok(MechanismPose {
            deflection_rad: state.rotation_rad,
            input,
            bodies: vec![flap, screw, nut, Isometry2::identity()],
            flap,
            points,
        })
    }

    fn kinetostatics(&self, input: f64, load: &LoadCase) -> Result<Kinetostatics> {
        let state = self.drive.state(input)?;
        let h = self.synthesis.hinge_m;
        let flap = turn_about(h, state.rotation_rad);
        let fraction = self.input_range().fraction(input).clamp(0.0, 1.0);
        let wrench = FlapWrench::new(&self.spec.flap_mass, &flap, load, fraction);
        let p = state.attachment;
        let u = (p - self.synthesis.actuator_mount_m).normalize();
        let force = -wrench.moment_about(h) / cross(p - h, u);
        let hinge_reaction: Vector2<f64> = -(u * force + wrench.force_n());
        // Virtual work: F ds + Σ f · dp + C dψ = 0 with dψ/ds from the drive's triangle.
        let rate = state.rotation_per_stroke;
        let velocity_of = |point: Point2<f64>| {
            let r = point - h;
            Vector2::new(-r.y, r.x) * rate
        };
        let force_virtual_work = -wrench.power(velocity_of, rate);
        Ok(Kinetostatics {
            input,
            deflection_rad: state.rotation_rad,
            actuator_load: force,
            actuator_load_virtual_work: force_virtual_work,
            reactions: {
                // The truss members' axial forces (tension positive): at the hinge node they
                // balance the flap's push, sum t_i u_i = R_H with u_i towards each member's
                // wing end.
                let [s1, s2] = self.synthesis.support_points_m;
                let (u1, u2) = ((s1 - h).normalize(), (s2 - h).normalize());
                let det = cross(u1, u2);
                let (t1, t2) = (cross(hinge_reaction, u2) / det, cross(u1, hinge_reaction) / det);
                vec![
                    ("B0".into(), force),
                    ("H".into(), hinge_reaction.norm()),
                    ("P".into(), force),
                    ("truss-aft".into(), t2),
                    ("truss-forward".into(), t1),
                ]
            },
            transmission_angle_rad: state.transmission_angle_rad,
            health: PoseHealth {
                closure_residual_m: state.closure_residual_m,
                jacobian_condition_number: state.jacobian_condition_number,
                distance_to_toggle_rad: state.transmission_angle_rad,
            },
            screw_torques: Some(self.synthesis.screw.torques(force)),
        })
    }

    fn drawing_notes(&self) -> DrawingNotes {
        let s = &self.synthesis;
        let h = s.hinge_m;
        let forward = self.spec.flap_attachments[0];
        let radius = (forward - h).norm();
        let start = (forward - h).y.atan2((forward - h).x);
        DrawingNotes {
            summary: format!(
                "dropped hinge with screw jack; stroke {:.1} -> {:.1} mm",
                s.stroke_m[0] * 1e3,
                s.stroke_m[1] * 1e3
            ),
            dimensions: vec![
                ("H-P".into(), h, s.actuator_attachment_m),
                ("B0-P".into(), s.actuator_mount_m, s.actuator_attachment_m),
            ],
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
        Actuator::ScrewJack {
            screw: self.synthesis.screw,
            screw_length_m: self.synthesis.screw_length_m,
            nominal_speed_mps: self.synthesis.nominal_speed_mps,
        }
    }

    /// The support truss's two members (the arms are part of the flap's hinged structure).
    fn members(&self) -> Vec<TwoForceMember> {
        let h = self.synthesis.hinge_m;
        ["truss-forward", "truss-aft"]
            .iter()
            .zip(self.synthesis.support_points_m)
            .map(|(name, end)| TwoForceMember {
                name: name.to_string(),
                length_m: (end - h).norm(),
                radius_m: self.spec.hardware.link_radius_m,
            })
            .collect()
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
        if !self.synthesis.actuator_clear {
            warnings.push("no default place of the screw jack kept clear of the wing, the structure and the flap at the sampled poses; give actuator_mount_m".into());
        }
        if !self.synthesis.placement_clear {
            warnings.push("no default place of the support truss kept clear of the structure and the flap at the sampled poses; give support_points_m".into());
        }
        warnings
    }
}
