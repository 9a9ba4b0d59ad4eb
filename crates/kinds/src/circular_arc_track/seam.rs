//! The circular-arc track with screw jack behind the mechanism seam ([`FlapMechanism`]):
//! its bodies, solids, joints and speed bounds, its pose at a flap deflection, and its
//! loads with reactions keyed by joint name. The kinematics are the track's own
//! ([`CircularArcTrack::pose`], [`CircularArcTrack::forces`]); this module only presents
//! them.
//!
//! Bodies (thesis Fig. 10 numbering in brackets): the flap [2] with its fittings A-D, F-D
//! and G-D; the screw [3] with the jack body round B0, turning about B0; the nut [4] at A,
//! sliding on the screw and pivoting on the flap; the outer and inner tracks, fixed,
//! round tubes along the arcs of pins F and G about A0.
//!
//! Speed bounds per metre of nut stroke s34, with μ the transmission angle at A, which
//! stays in [μ_min, π/2] over the deployment (μ_min = (π - β3)/2 at both ends by
//! collinearity, π/2 where B0A is tangent to A's circle about A0): A moves at a2 θ̇12
//! perpendicular to A0A, whose component along the screw is the stroke rate ṡ = a2 θ̇12
//! sin μ and across it s ψ̇ = a2 θ̇12 cos μ. So the flap turns about A0 at |dθ12/ds| =
//! 1/(a2 sin μ) <= 1/(a2 sin μ_min); A moves at 1/sin μ <= 1/sin μ_min; the screw (and the
//! nut with it) turns about B0 at |dψ/ds| = cot μ / s <= cot μ_min / s34,i.

use nalgebra::{Isometry2, Point2, Rotation2, Translation2, Unit, Vector2};
use serde::Serialize;

use super::synthesis::CircularArcTrack;
use flapwright_mechanism::seam::{
    Actuator, Body, BodyRole, BodySolid, DrawingNotes, FlapMechanism, InputQuantity, InputRange, Joint, JointEnd,
    JointGeometry, Kinetostatics, MechanismPose, NamedPoint, PlanarShape, PoseHealth, SpeedBound,
};
use flapwright_mechanism::shared::load_case::LoadCase;
use flapwright_mechanism::Result;

/// Sizes of the solids that stand for the track's hardware (m). The defaults are
/// representative of the thesis's small-aircraft flap; the sizing stage does not feed
/// them back yet.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TrackHardware {
    /// Radius of the fitting capsules A-D, F-D, G-D.
    pub fitting_radius_m: f64,
    /// Radius of the nut ball at A.
    pub nut_radius_m: f64,
    /// Radius of a slot track's swept solid (pin radius plus the track's wall).
    pub track_radius_m: f64,
    /// Length of the jack body (gearbox housing) centred on B0 along the screw.
    pub jack_body_length_m: f64,
    /// Radius of the jack body.
    pub jack_body_radius_m: f64,
}

impl Default for TrackHardware {
    fn default() -> Self {
        Self {
            fitting_radius_m: 0.008,
            nut_radius_m: 0.020,
            // An 8 mm pin in a track with a 4 mm wall.
            track_radius_m: 0.012,
            // Reaches 55 mm from B0: clear of the nut (20 mm) at the shortest stroke, 80 mm.
            jack_body_length_m: 0.060,
            jack_body_radius_m: 0.025,
        }
    }
}

/// Largest angle (rad) between points of a track's centre line: 2 degrees keeps the
/// chord within R (1 - cos 1°) = 0.015 % of the radius of the arc.
const TRACK_STEP_RAD: f64 = std::f64::consts::PI / 90.0;

/// Indices of the bodies in [`FlapMechanism::bodies`].
const FLAP: usize = 0;
const SCREW: usize = 1;
const NUT: usize = 2;

/// Points round the track of a pin at `radius_m` about A0 from `start_rad` over
/// `range_rad`, extended by `extra_m` of arc at both ends so the pin's end positions sit
/// inside the track.
fn track_centre_line(radius_m: f64, start_rad: f64, range_rad: f64, extra_m: f64) -> Vec<Point2<f64>> {
    // The extension covers the pin's end caps; on a slot radius smaller than the pin it
    // would wind round many times (1e-300 m asked for 1e300 steps), and a quarter turn
    // already encloses the pin there.
    let extra_rad = (extra_m / radius_m).min(std::f64::consts::FRAC_PI_2);
    let (from, to) = (start_rad - extra_rad, start_rad + range_rad + extra_rad);
    let steps = (((to - from) / TRACK_STEP_RAD).ceil() as usize).max(1);
    (0..=steps)
        .map(|i| {
            let angle = from + (to - from) * i as f64 / steps as f64;
            Point2::new(radius_m * angle.cos(), radius_m * angle.sin())
        })
        .collect()
}

/// Outer radius of a square thread of mean radius r and lead l: r + l/4 (thread depth l/2).
pub fn screw_outer_radius_m(track: &CircularArcTrack) -> f64 {
    let screw = &track.spec().screw;
    screw.mean_radius_m + 0.25 * screw.lead_m
}

/// The bodies and joints of `track` with solids of `hardware`.
pub(crate) fn bodies_and_joints(track: &CircularArcTrack, hardware: &TrackHardware) -> (Vec<Body>, Vec<Joint>) {
    let synthesis = track.synthesis();
    let spec = track.spec();
    let (a, b0, d) = (
        synthesis.nut_pivot_stowed_m,
        synthesis.screw_mount_m,
        spec.centre_of_mass_stowed_m,
    );
    let (f, g) = (synthesis.outer_pin_stowed_m, synthesis.inner_pin_stowed_m);
    let direction = (a - b0).normalize();
    let half_body = direction * (0.5 * hardware.jack_body_length_m);
    let solid = |name: &str, shape: PlanarShape| BodySolid {
        name: name.into(),
        shape,
        width_m: 0.0,
        offset_m: 0.0,
    };
    let capsule = |from, to, radius_m| PlanarShape::Capsule { from, to, radius_m };
    // Per metre of stroke (module doc).
    let mu_min = synthesis.minimum_transmission_angle_rad;
    let flap_turn_rate = 1.0 / (spec.crank_length_m * mu_min.sin());
    let screw_turn_rate = 1.0 / (mu_min.tan() * synthesis.stroke_start_m);
    let nut_pivot_speed = 1.0 / mu_min.sin();
    let track_body = |name: &str, radius_m: f64, start_rad: f64| Body {
        name: name.into(),
        role: BodyRole::Track,
        solids: vec![solid(
            name,
            PlanarShape::Tube {
                centre_line: track_centre_line(radius_m, start_rad, spec.rotation_range_rad, hardware.track_radius_m),
                radius_m: hardware.track_radius_m,
            },
        )],
        speed_bound: SpeedBound::FIXED,
    };
    let bodies = vec![
        Body {
            name: "flap".into(),
            role: BodyRole::Flap,
            solids: [("fitting-A", a), ("fitting-F", f), ("fitting-G", g)]
                .into_iter()
                .map(|(name, pin)| solid(name, capsule(pin, d, hardware.fitting_radius_m)))
                .collect(),
            speed_bound: SpeedBound {
                reference: Point2::origin(),
                linear_per_input: 0.0,
                angular_per_input: flap_turn_rate,
            },
        },
        Body {
            name: "screw".into(),
            role: BodyRole::Actuator,
            solids: vec![
                solid(
                    "screw",
                    capsule(b0, b0 + direction * spec.screw_length_m, screw_outer_radius_m(track)),
                ),
                solid(
                    "jack-body",
                    capsule(b0 - half_body, b0 + half_body, hardware.jack_body_radius_m),
                ),
            ],
            speed_bound: SpeedBound {
                reference: b0,
                linear_per_input: 0.0,
                angular_per_input: screw_turn_rate,
            },
        },
        Body {
            name: "nut".into(),
            role: BodyRole::Actuator,
            solids: vec![solid("nut", capsule(a, a, hardware.nut_radius_m))],
            speed_bound: SpeedBound {
                reference: a,
                linear_per_input: nut_pivot_speed,
                angular_per_input: screw_turn_rate,
            },
        },
        track_body("outer-track", spec.outer_slot_radius_m, spec.outer_slot_start_angle_rad),
        track_body(
            "inner-track",
            spec.inner_slot_radius_m,
            spec.outer_slot_start_angle_rad + spec.inner_slot_offset_angle_rad,
        ),
    ];
    let joint = Joint::new;
    let joints = vec![
        joint(
            "A",
            "nut on the screw, pivoting on the flap",
            JointGeometry::Revolute { at: a },
            [JointEnd::Body(NUT), JointEnd::Body(FLAP)],
            &[("screw", "fitting-A"), ("nut", "fitting-A")],
        ),
        joint(
            "nut-slide",
            "nut riding along the screw",
            JointGeometry::Prismatic {
                origin: a,
                direction: Unit::new_normalize(a - b0),
            },
            [JointEnd::Body(SCREW), JointEnd::Body(NUT)],
            &[("screw", "nut")],
        ),
        joint(
            "B0",
            "screw turning in the jack body",
            JointGeometry::Revolute { at: b0 },
            [JointEnd::Ground, JointEnd::Body(SCREW)],
            &[],
        ),
        joint(
            "F",
            "pin in the outer slot",
            JointGeometry::PinInCircularSlot {
                pin: f,
                centre: Point2::origin(),
            },
            [JointEnd::Body(FLAP), JointEnd::Body(3)],
            &[("fitting-F", "outer-track")],
        ),
        joint(
            "G",
            "pin in the inner slot",
            JointGeometry::PinInCircularSlot {
                pin: g,
                centre: Point2::origin(),
            },
            [JointEnd::Body(FLAP), JointEnd::Body(4)],
            &[("fitting-G", "inner-track")],
        ),
    ];
    (bodies, joints)
}

/// Direction angle of `v` (rad).
fn angle_of(v: Vector2<f64>) -> f64 {
    v.y.atan2(v.x)
}

impl FlapMechanism for CircularArcTrack {
    fn kind(&self) -> &'static str {
        "circular-arc-track"
    }

    fn input_range(&self) -> InputRange {
        let synthesis = self.synthesis();
        InputRange {
            quantity: InputQuantity::Stroke,
            stowed: synthesis.stroke_start_m,
            deployed: synthesis.stroke_end_m,
        }
    }

    fn deflection_range_rad(&self) -> f64 {
        self.spec().rotation_range_rad
    }

    /// s34 = |A(δ) - B0| with A(δ) the stowed nut pivot turned by δ about A0.
    fn input_at_deflection(&self, deflection_rad: f64) -> Result<f64> {
        let synthesis = self.synthesis();
        let a = Rotation2::new(deflection_rad) * synthesis.nut_pivot_stowed_m;
        Ok((a - synthesis.screw_mount_m).norm())
    }

    fn deflection_at_input(&self, input: f64) -> Result<f64> {
        Ok(self.pose(input, 0.0, 0.0)?.deflection_rad)
    }

    /// The nut pivot A and the slot pins F and G.
    fn flap_attachments(&self) -> Vec<NamedPoint> {
        let synthesis = self.synthesis();
        [
            ("A", synthesis.nut_pivot_stowed_m),
            ("F", synthesis.outer_pin_stowed_m),
            ("G", synthesis.inner_pin_stowed_m),
        ]
        .into_iter()
        .map(|(name, position)| NamedPoint {
            name,
            position,
            fixed: false,
        })
        .collect()
    }

    fn bodies(&self) -> &[Body] {
        &self.bodies
    }

    fn joints(&self) -> &[Joint] {
        &self.joints
    }

    fn pose(&self, input: f64) -> Result<MechanismPose> {
        let pose = CircularArcTrack::pose(self, input, 0.0, 0.0)?;
        let synthesis = self.synthesis();
        let b0 = synthesis.screw_mount_m;
        let a_stowed = synthesis.nut_pivot_stowed_m;
        let a = pose.nut_pivot_a.position_m;
        let flap = Isometry2::rotation(pose.deflection_rad);
        let screw_turn = angle_of(a - b0) - angle_of(a_stowed - b0);
        let about = |point: Point2<f64>, angle: f64| {
            Translation2::from(point.coords) * Isometry2::rotation(angle) * Translation2::from(-point.coords)
        };
        let nut = Translation2::from(a.coords) * Isometry2::rotation(screw_turn) * Translation2::from(-a_stowed.coords);
        let points = [
            ("A0", Point2::origin(), true),
            ("B0", b0, true),
            ("A", a, false),
            ("B", pose.screw_end_b.position_m, false),
            ("D", pose.centre_of_mass_d.position_m, false),
            ("F", pose.outer_pin_f.position_m, false),
            ("G", pose.inner_pin_g.position_m, false),
        ]
        .into_iter()
        .map(|(name, position, fixed)| NamedPoint { name, position, fixed })
        .collect();
        Ok(MechanismPose {
            deflection_rad: pose.deflection_rad,
            input,
            bodies: vec![
                flap,
                about(b0, screw_turn),
                nut,
                Isometry2::identity(),
                Isometry2::identity(),
            ],
            flap,
            points,
        })
    }

    fn kinetostatics(&self, input: f64, load: &LoadCase) -> Result<Kinetostatics> {
        if load.flap_normal_force.is_some() {
            return Err(flapwright_mechanism::Error::LoadNotSupported {
                kind: "circular-arc-track",
                load: "a flight condition's normal force (its statics, thesis eqs. 3.4.x, take a hinge moment and the weight only): give the case as moments",
            });
        }
        let spec = self.spec();
        let pose = CircularArcTrack::pose(self, input, spec.nominal_input_speed_mps, spec.nominal_input_accel_mps2)?;
        let forces = self.forces(&pose, load)?;
        Ok(Kinetostatics {
            input,
            deflection_rad: pose.deflection_rad,
            actuator_load: forces.actuator_force_n,
            actuator_load_virtual_work: forces.actuator_force_virtual_work_n,
            // Thesis signs: F42 along the screw at A, G13 axial at B0 (= F_input, eq.
            // 3.4.14), the slot reactions radial along θG and θF.
            reactions: vec![
                ("A".into(), forces.actuator_force_n),
                ("B0".into(), forces.actuator_force_n),
                ("G".into(), forces.inner_slot_reaction_n),
                ("F".into(), forces.outer_slot_reaction_n),
            ],
            transmission_angle_rad: pose.diagnostics.transmission_angle_rad,
            health: PoseHealth {
                closure_residual_m: pose.diagnostics.closure_residual_m,
                jacobian_condition_number: pose.diagnostics.jacobian_condition_number,
                distance_to_toggle_rad: pose.diagnostics.distance_to_toggle_rad,
            },
            actuator_torques: Some(forces.screw),
            members: Vec::new(),
        })
    }

    fn actuator(&self) -> Actuator {
        let spec = self.spec();
        Actuator::ScrewJack {
            screw: spec.screw,
            screw_length_m: spec.screw_length_m,
            nominal_speed_mps: spec.nominal_input_speed_mps,
        }
    }

    fn flap_mass(&self) -> Option<flapwright_mechanism::shared::flap_load::FlapMass> {
        let spec = self.spec();
        Some(flapwright_mechanism::shared::flap_load::FlapMass {
            mass_kg: spec.flap_mass_kg,
            centre_of_mass_stowed_m: spec.centre_of_mass_stowed_m,
            gravity_mps2: nalgebra::Vector2::new(0.0, -spec.gravity_mps2),
        })
    }

    fn warnings(&self) -> Vec<String> {
        self.synthesis().warnings.iter().map(|w| w.to_string()).collect()
    }

    /// `dimensions` (thesis Table 2, SI) and `synthesis` (s34,i, Δs, g2, p2, q2, ...).
    fn details(&self) -> serde_json::Value {
        serde_json::json!({
            "dimensions": self.spec(),
            "synthesis": self.synthesis(),
        })
    }

    fn drawing_notes(&self) -> DrawingNotes {
        let synthesis = self.synthesis();
        let spec = self.spec();
        let b0 = synthesis.screw_mount_m;
        let a = synthesis.nut_pivot_stowed_m;
        let inner_start = spec.outer_slot_start_angle_rad + spec.inner_slot_offset_angle_rad;
        DrawingNotes {
            summary: format!(
                "circular-arc track with screw jack; s34 {:.1} -> {:.1} mm",
                synthesis.stroke_start_m * 1e3,
                synthesis.stroke_end_m * 1e3
            ),
            dimensions: vec![
                ("a1".into(), Point2::origin(), b0),
                ("a2".into(), Point2::origin(), a),
                ("a3".into(), b0, b0 + (a - b0).normalize() * spec.screw_length_m),
            ],
            arcs: vec![
                (
                    "outer slot b1".into(),
                    Point2::origin(),
                    spec.outer_slot_radius_m,
                    spec.outer_slot_start_angle_rad,
                    spec.outer_slot_start_angle_rad + spec.rotation_range_rad,
                ),
                (
                    "inner slot c1".into(),
                    Point2::origin(),
                    spec.inner_slot_radius_m,
                    inner_start,
                    inner_start + spec.rotation_range_rad,
                ),
            ],
        }
    }
}
