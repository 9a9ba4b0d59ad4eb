//! The four-bar (Zaccai, Bertels & Vos `003_...` section 3, Figs. 6 and 8): the flap is the
//! coupler of a four-bar linkage, held at pivot A1 by the crank O1-A1 and at pivot A2 by
//! the rocker O2-A2 (the crank is the link that turns less); a screw jack from a mount B0 turns the crank about O1 (a
//! [`RockerDrive`]); struts hold O1 and O2 to the wing's lower skin.
//!
//! Synthesis is motion generation for three precision positions (stowed, take-off,
//! landing): for a moving pivot p, the fixed pivot is the centre of the circle through its
//! three positions ([`flapwright_mechanism::shared::precision::circle_centre`]). The moving pivots are free choices: fixed by the
//! designer, or searched on a grid under the flap for the smallest depth of the stowed
//! mechanism below the section (a proxy for the fairing depth), subject to a minimum
//! transmission angle, no branch change and the positions reached in order, fixed pivots
//! below the wing and flap and outside them at every setting, and links that stay out of
//! the wing section at the settings ([`FourBarSearch`] counts every rejection; a failed
//! search reports the dominant one).
//!
//! Pose in closed form: the crank angle φ from the stroke (triangle B0 O1 C), A1 turned by φ
//! about O1, A2 the intersection of the circles (A1, |A1A2|) and (O2, |O2A2|) on the stowed
//! branch (the sign of (O2 - A1) x (A2 - A1)), the flap's displacement from A1 and A2.
//!
//! The loop's closed form lives in `linkage`, the free-choice search in `search`; this
//! module synthesises, places the screw and the struts, and presents the kind through the
//! seam.
//!
//! Statics: the rocker is a two-force member (force f along O2 -> A2 on the flap); moments
//! of the flap about A1 give f, the flap's balance the pin force R1 at A1, the crank's
//! moments about O1 the screw force F. Virtual work, independently, from the velocity
//! analysis of the loop: ω_r k x (A2 - O2) - ω_f k x (A2 - A1) = v_A1.

use nalgebra::{Isometry2, Point2, Vector2};
use serde::Serialize;

mod bodies;
mod linkage;
mod members;
mod search;
mod support;
mod synthesis;

use flapwright_mechanism::shared::geometry::turn_angle;
use linkage::Loop;

use flapwright_mechanism::seam::{
    Actuator, Body, DrawingNotes, FlapMechanism, InputQuantity, InputRange, Joint, Kinetostatics, MechanismPose,
    Member, MemberLoad, MemberLoading, NamedPoint, PoseHealth,
};
use flapwright_mechanism::shared::flap_load::{FlapMass, FlapWrench, LinkHardware};
use flapwright_mechanism::shared::geometry::{cross, turn_about};
use flapwright_mechanism::shared::load_case::LoadCase;
use flapwright_mechanism::shared::members::DrawnRadius;
use flapwright_mechanism::shared::outline::StationOutline;
use flapwright_mechanism::shared::precision::PrecisionPosition;
use flapwright_mechanism::shared::rocker_drive::RockerDrive;
use flapwright_mechanism::shared::screw_jack::{ScrewDrive, ScrewJack};
use flapwright_mechanism::shared::support_truss::SupportTruss;
use flapwright_mechanism::{Error, Result, SynthesisDefect};

const KIND: &str = "four-bar";

/// The designer's choices for a four-bar at one station (station frame, m).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FourBarSpec {
    /// Take-off and landing (stowed is the identity).
    pub takeoff: PrecisionPosition,
    /// The last precision position, where the deployment ends.
    pub landing: PrecisionPosition,
    /// Forward moving pivot A1 on the flap (stowed); `None`: searched.
    pub forward_pivot: Option<Point2<f64>>,
    /// Aft moving pivot A2 on the flap (stowed); `None`: searched.
    pub aft_pivot: Option<Point2<f64>>,
    /// Another station of the same rigid flap to move it alike, when both moving pivots
    /// are searched: the search first tries a small grid about its pivots and keeps, of
    /// the mechanisms whose motion (or deflection schedule) is near its, the least costly;
    /// only when none builds clear does it search the whole region.
    pub follow: Option<FollowStation>,
    /// Smallest transmission angle over the deployment, of the loop and of the drive (rad).
    pub min_transmission_angle_rad: f64,
    /// Where the screw takes hold of the crank: 0 at O1, 1 at A1; `None`: searched
    /// ([`flapwright_mechanism::shared::placement::place_screw_jack`]).
    pub actuator_attachment_fraction: Option<f64>,
    /// The screw's mount; `None`: square to the crank at mid-travel.
    pub actuator_mount: Option<Point2<f64>>,
    /// Distance from the attachment's mid-travel position to a default mount (m).
    pub actuator_standoff_m: f64,
    /// The flap share this station carries.
    pub flap_mass: FlapMass,
    /// The screw's thread and the shared drive.
    pub screw_drive: ScrewDrive,
    /// Solid sizes.
    pub hardware: LinkHardware,
    /// The station's sections: the search region and the fixed pivots' region.
    pub outline: StationOutline,
    /// The station's load cases, under which the screw jack's placement weighs its force
    /// ([`FourBarSpec::weighing`]); empty: the shallowest clear placement.
    #[serde(skip)]
    pub design_loads: Vec<flapwright_mechanism::LoadCase>,
    /// Weight of the screw's peak load against the fairing's depth.
    #[serde(skip)]
    pub load_weight: f64,
    /// The screw's load (reference loads) above which the placement trades steeply.
    #[serde(skip)]
    pub load_cap: f64,
    /// How the jack's placement weighs the mass it adds (the screw and a horn beyond O1);
    /// `None`: not at all.
    #[serde(skip)]
    pub mass_weighing: Option<flapwright_mechanism::shared::objective::MassWeighing>,
    /// Take this candidate of the jack placement's trade (the report's `jack_trade`, from
    /// 0) instead of the one the weights choose, for every linkage the search builds (of
    /// those whose trade has it, the usual choice); `None`: theirs.
    pub trade_index: Option<usize>,
}

impl FourBarSpec {
    /// How the jack's placement weighs its load: the least depth in flap chords plus
    /// [`Self::load_weight`] times the peak screw force in reference loads, each reference
    /// load above [`Self::load_cap`] costing
    /// [`flapwright_mechanism::shared::objective::CAP_EXCESS_WEIGHT`] more; `None` without
    /// load cases (the shallowest clear placement).
    pub fn weighing(&self) -> Option<flapwright_mechanism::shared::objective::LoadWeighing> {
        (!self.design_loads.is_empty()).then(|| flapwright_mechanism::shared::objective::LoadWeighing {
            loads: self.design_loads.clone(),
            flap_mass: self.flap_mass,
            weight: self.load_weight,
            load_cap: Some(self.load_cap),
            mass: self.mass_weighing,
        })
    }
}

/// The default of [`FourBarSpec::load_cap`]: the four-bar's screw carries at most the
/// largest force the load cases put on the flap where a clear placement allows. Unweighed,
/// the shallowest placement took hold of the crank near its pivot and carried 1.1-2.0
/// times it on `transport-flap` (`003_...` Table 1's four-bar: 0.55), its load jumping 2x
/// between neighbouring settings as the grid's lever changed.
pub const DEFAULT_JACK_LOAD_CAP: f64 = 1.0;

/// What a four-bar follows of another station of its flap ([`FourBarSpec::follow`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FollowStation {
    /// Its moving pivots as the corresponding points of this station's flap section
    /// (forward, aft; stowed, m).
    pub pivots: [Point2<f64>; 2],
    /// Its flap deflection at evenly spaced drive fractions from 0 to 1 (rad).
    pub deflections_rad: Vec<f64>,
    /// Its flap's rigid motion as this station's plane sees it, where the caller knows
    /// it: the candidates are then ranked by their flap's largest distance from it
    /// ([`flapwright_mechanism::shared::follow::FollowedMotion::miss`]) instead of by the
    /// deflection schedule alone, which left the transport's inboard flap 8-10 mm from a
    /// rigid motion at landing gaps of 2.1-2.5 %c.
    #[serde(skip)]
    pub motion: Option<flapwright_mechanism::shared::follow::FollowedMotion>,
}

/// Counts of what the free-choice search rejected, for the report and for a failure's
/// message.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct FourBarSearch {
    /// Moving-pivot candidates tried.
    pub candidates: usize,
    /// ... whose three positions lie on one line, or on a circle larger than 3 chords.
    pub no_circle: usize,
    /// ... whose fixed pivot lies outside the region (inside a section, above the lower
    /// surface, or ahead of or behind the section).
    pub pivot_outside_region: usize,
    /// ... whose link turns back between positions or turns more than 150 deg.
    pub order_defect: usize,
    /// Pairs of valid candidates tried.
    pub pairs: usize,
    /// ... that change branch between positions.
    pub branch_change: usize,
    /// ... whose transmission angle falls below the minimum (or whose drive does).
    pub toggle: usize,
    /// ... whose links cut the wing section at a setting.
    pub link_in_wing: usize,
    /// ... feasible.
    pub feasible: usize,
}

/// What synthesis computed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FourBarSynthesis {
    /// Fixed pivot of the crank O1 (m).
    pub crank_pivot_m: Point2<f64>,
    /// Fixed pivot of the rocker O2 (m).
    pub rocker_pivot_m: Point2<f64>,
    /// Moving pivots A1 (crank) and A2 (rocker), stowed (m).
    pub moving_pivots_m: [Point2<f64>; 2],
    /// Crank rotation at take-off and landing (rad).
    pub crank_rotation_rad: [f64; 2],
    /// Smallest transmission angle of the loop over the deployment (rad, sampled).
    pub min_transmission_angle_rad: f64,
    /// Smallest transmission angle of the screw on the crank over the deployment (rad,
    /// sampled): the deployment samples report the smaller of the two.
    pub drive_min_transmission_angle_rad: f64,
    /// The screw's end pressure angles and its mount's turn from `004_...`'s installation.
    pub jack_installation: flapwright_mechanism::shared::rocker_drive::JackInstallation,
    /// The jack placement's trade between its depth and its load, the chosen one marked
    /// ([`flapwright_mechanism::shared::placement::PlacedJack::trade`]).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub jack_trade: Vec<flapwright_mechanism::shared::placement::JackTradeCandidate>,
    /// A certified lower bound on it between samples (rad).
    pub certified_min_transmission_angle_rad: f64,
    /// Depth of the whole mechanism (every solid, over the deployment) below the stowed
    /// section's lowest point (m): what the search minimises.
    pub depth_below_section_m: f64,
    /// Largest distance between the mechanism's flap and each precision position at the
    /// moving pivots (m).
    pub precision_miss_m: f64,
    /// The screw's mount B0 and its attachment C on the crank, stowed (m).
    pub actuator_mount_m: Point2<f64>,
    /// The screw's attachment C on the crank, stowed (m).
    pub actuator_attachment_m: Point2<f64>,
    /// Stroke stowed and at landing (m).
    pub stroke_m: [f64; 2],
    /// The screw chosen from the drive.
    pub screw: ScrewJack,
    /// Screw length (m).
    pub screw_length_m: f64,
    /// Nominal nut speed (m/s).
    pub nominal_speed_mps: f64,
    /// Where the struts from O1 and O2 end (m): on the wing's lower skin, or at the other
    /// pivot (a beam carrying both).
    pub strut_tops_m: [Point2<f64>; 2],
    /// The support's truss where its rods and tie clear (the `support` module): the struts
    /// pinned at both ends, a brace and the tie O2-O1, every one a rod; `None`: the struts
    /// clamped to the skin, in bending.
    pub truss: Option<SupportTruss>,
    /// False when no default place of the screw jack kept clear of the wing, the structure
    /// and the flap at the sampled poses (the interference check says where).
    pub actuator_clear: bool,
    /// False when no default place of a strut kept clear of the structure and the flap
    /// at the sampled poses, or the crank or the rocker came within a quarter of its radius
    /// of the flap (the interference check says where).
    pub placement_clear: bool,
    /// What the search rejected (all zero when both moving pivots were given).
    pub search: FourBarSearch,
    /// The arrangement the search chose (its discrete choices).
    pub topology: FourBarTopology,
    /// The station of the same flap whose motion this one's last search followed, and the
    /// largest distance (m) of this station's flap from it over the deployment, at points
    /// near the flap's leading and trailing edges ([`flapwright_mechanism::shared::follow`]).
    pub followed: Option<flapwright_mechanism::shared::follow::FollowedStation>,
}

/// The four-bar's arrangement, the discrete choices its search spans: neighbouring inputs
/// whose designs differ in it are different mechanisms, whose figures may differ by
/// several times (issue 37's continuity: a jump the report must state).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct FourBarTopology {
    /// Which of the two links the screw turns: the one whose moving pivot is forward on the
    /// flap, or the aft one.
    pub crank: CrankLink,
    /// Where the screw takes hold of the crank: between its pivots, or on a horn beyond its
    /// fixed pivot (which turns the other way about it).
    pub attachment: ScrewAttachment,
    /// Where the screw's mount stands, stowed: ahead of its attachment or behind it.
    pub mount: MountSide,
}

/// The link a four-bar's screw turns ([`FourBarTopology::crank`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum CrankLink {
    /// The link whose moving pivot is the forward one on the flap.
    Forward,
    /// The link whose moving pivot is the aft one.
    Aft,
}

/// Where a screw takes hold of the arm it turns.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ScrewAttachment {
    /// Between the arm's fixed and moving pivots.
    OnArm,
    /// On a horn beyond the fixed pivot.
    Horn,
}

/// Where a screw's mount stands against its attachment, stowed, along the station's
/// forward direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum MountSide {
    /// Ahead of the attachment.
    Ahead,
    /// Behind it.
    Behind,
}

impl FourBarTopology {
    /// The arrangement of a crank O1-A1 with the other moving pivot at `a2`, the screw
    /// taking hold at `attachment` with its mount at `mount` (stowed; x forward).
    pub fn of(o1: Point2<f64>, a1: Point2<f64>, a2: Point2<f64>, attachment: Point2<f64>, mount: Point2<f64>) -> Self {
        Self {
            crank: if a1.x >= a2.x {
                CrankLink::Forward
            } else {
                CrankLink::Aft
            },
            attachment: if (attachment - o1).dot(&(a1 - o1)) >= 0.0 {
                ScrewAttachment::OnArm
            } else {
                ScrewAttachment::Horn
            },
            mount: if mount.x >= attachment.x {
                MountSide::Ahead
            } else {
                MountSide::Behind
            },
        }
    }
}

/// A four-bar synthesised for one station.
#[derive(Debug, Clone)]
pub struct FourBar {
    spec: FourBarSpec,
    synthesis: FourBarSynthesis,
    loop_: Loop,
    drive: RockerDrive,
    /// The rocker's and the flap's certified rate bounds per unit crank rate (the bodies'
    /// speed bounds).
    link_rates: (f64, f64),
    bodies: Vec<Body>,
    joints: Vec<Joint>,
}

/// Crank samples of the feasibility check over the deployment.
pub(super) const LOOP_SAMPLES: usize = 48;

/// Pieces of the deployment on which the rocker's and the flap's rates are certified
/// (`linkage::Loop::rate_bounds`): 256 closed-form poses, a few microseconds a build. On the
/// transport scene's four-bar at `ob-outer` (study of that station) the flap mesh's speed
/// bound falls from 19.8 to 2.8 m per unit drive fraction, and the sweep of the flap against
/// the wing from 1200 distance evaluations (the budget, uncertified) to 334 (certified).
pub(super) const RATE_INTERVALS: usize = 256;
/// Loops, shallowest pivots first, whose screw and struts are placed to pick the shallowest
/// whole mechanism: at most this many, and no more than [`CLEAR_FINALISTS`] once one is
/// placed clear of the sections (each placement costs about 4 ms).
const FINALISTS: usize = 24;
/// See [`FINALISTS`].
const CLEAR_FINALISTS: usize = 4;
/// The solids (and members) holding O1 and O2 to the wing.
const STRUTS: [&str; 2] = ["strut-O1", "strut-O2"];
/// The support truss's rods, in [`SupportTruss::rods`]'s order: the struts from O1 and O2
/// and the brace.
const TRUSS_RODS: [&str; 3] = ["strut-O1", "strut-O2", "brace"];
/// The truss's tie between O2 and O1 (the loop's ground link).
const TIE: &str = "tie";
pub(super) fn failure(defect: SynthesisDefect, detail: String) -> Error {
    Error::Synthesis {
        kind: KIND,
        defect,
        detail,
    }
}

pub(super) fn mm(p: Point2<f64>) -> String {
    format!("({:.1}, {:.1}) mm", p.x * 1e3, p.y * 1e3)
}

/// The loop's statics at a pose: the rocker a two-force member (force f along O2 -> A2 on
/// the flap), moments of the flap about A1 give f, the flap's balance the pin force R1 at
/// A1, the crank's moments about O1 the screw force F.
struct LoopStatics {
    /// Unit vector O2 -> A2.
    e2: Vector2<f64>,
    /// f (N): the rocker's push on the flap along `e2`.
    rocker_force: f64,
    /// R1, the crank's force on the flap at A1 (N).
    pin_a1: Vector2<f64>,
    /// The screw's direction, mount -> attachment.
    u: Vector2<f64>,
    /// F, the screw's force (N, along `u` on the crank).
    force: f64,
    /// The support's force on the crank at O1 (N).
    crank_ground: Vector2<f64>,
}

impl FourBar {
    fn statics(
        &self,
        state: &flapwright_mechanism::shared::rocker_drive::RockerState,
        pose: &linkage::LoopPose,
        wrench: &FlapWrench,
    ) -> LoopStatics {
        let l = &self.loop_;
        let e2 = (pose.a2 - l.o2) / l.rocker;
        let rocker_force = -wrench.moment_about(pose.a1) / cross(pose.a2 - pose.a1, e2);
        let pin_a1: Vector2<f64> = -(e2 * rocker_force + wrench.force_n());
        // Crank: the flap pushes it with -R1 at A1, the screw with F u at C; moments about O1.
        let c = state.attachment;
        let u = (c - self.synthesis.actuator_mount_m).normalize();
        let force = cross(pose.a1 - l.o1, pin_a1) / cross(c - l.o1, u);
        let crank_ground: Vector2<f64> = pin_a1 - u * force;
        LoopStatics {
            e2,
            rocker_force,
            pin_a1,
            u,
            force,
            crank_ground,
        }
    }

    /// What the crank and the rocker put on the support at O1 and O2 at `input` under
    /// `load` (N).
    pub(super) fn support_forces(&self, input: f64, load: &LoadCase) -> Result<[Vector2<f64>; 2]> {
        let (state, pose) = self.loop_pose(input)?;
        let fraction = self.input_range().fraction(input).clamp(0.0, 1.0);
        let wrench = FlapWrench::new(&self.spec.flap_mass, &pose.flap, load, fraction);
        let statics = self.statics(&state, &pose, &wrench);
        Ok([-statics.crank_ground, -statics.e2 * statics.rocker_force])
    }
}

impl FlapMechanism for FourBar {
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

    /// Bisection on the crank angle (the flap turns monotonically with it, checked at
    /// synthesis), then the stroke for that angle.
    fn input_at_deflection(&self, deflection_rad: f64) -> Result<f64> {
        let travel = self.synthesis.crank_rotation_rad[1];
        let deflection = |phi: f64| self.loop_.at(phi).map_or(f64::NAN, |p| p.flap.rotation.angle());
        let sense = self.spec.landing.deflection_rad.signum();
        let phi = flapwright_mechanism::shared::feasibility::parameter_at_deflection(
            travel,
            deflection,
            deflection_rad,
            sense,
        );
        Ok(self.drive.stroke_at(phi))
    }

    fn deflection_at_input(&self, input: f64) -> Result<f64> {
        Ok(self.loop_pose(input)?.1.flap.rotation.angle())
    }

    /// The moving pivots A1 and A2.
    fn flap_attachments(&self) -> Vec<NamedPoint> {
        vec![
            NamedPoint {
                name: "A1",
                position: self.loop_.a1,
                fixed: false,
            },
            NamedPoint {
                name: "A2",
                position: self.loop_.a2,
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
        let (state, pose) = self.loop_pose(input)?;
        let l = &self.loop_;
        let crank = turn_about(l.o1, state.rotation_rad);
        let rocker = turn_about(l.o2, turn_angle(l.o2, l.a2, pose.a2));
        let b0 = self.synthesis.actuator_mount_m;
        let (screw, nut) = self.drive.screw_and_nut(state.attachment);
        let points = [
            ("O1", l.o1, true),
            ("O2", l.o2, true),
            ("B0", b0, true),
            ("A1", pose.a1, false),
            ("A2", pose.a2, false),
            ("C", state.attachment, false),
            ("D", pose.flap * self.spec.flap_mass.centre_of_mass_stowed_m, false),
        ]
        .into_iter()
        .map(|(name, position, fixed)| NamedPoint { name, position, fixed })
        .collect();
        Ok(MechanismPose {
            deflection_rad: pose.flap.rotation.angle(),
            input,
            bodies: vec![pose.flap, crank, rocker, screw, nut, Isometry2::identity()],
            flap: pose.flap,
            points,
        })
    }

    fn kinetostatics(&self, input: f64, load: &LoadCase) -> Result<Kinetostatics> {
        let (state, pose) = self.loop_pose(input)?;
        let l = &self.loop_;
        let fraction = self.input_range().fraction(input).clamp(0.0, 1.0);
        let wrench = FlapWrench::new(&self.spec.flap_mass, &pose.flap, load, fraction);
        let LoopStatics {
            e2,
            rocker_force,
            pin_a1,
            u,
            force,
            crank_ground,
        } = self.statics(&state, &pose, &wrench);
        let c = state.attachment;
        // Virtual work with the loop's velocities per metre of stroke.
        let crank_rate = state.rotation_per_stroke;
        let (_, flap_per_crank) = l.rates(&pose);
        let flap_rate = flap_per_crank * crank_rate;
        let r1 = pose.a1 - l.o1;
        let v_a1 = Vector2::new(-r1.y, r1.x) * crank_rate;
        let velocity_of = |point: Point2<f64>| {
            let d = point - pose.a1;
            v_a1 + Vector2::new(-d.y, d.x) * flap_rate
        };
        let force_virtual_work = -wrench.power(velocity_of, flap_rate);
        let conditioning = state
            .jacobian_condition_number
            .max(l.coupler.max(l.rocker) / (l.coupler.min(l.rocker) * pose.transmission.sin()));
        Ok(Kinetostatics {
            input,
            deflection_rad: pose.flap.rotation.angle(),
            actuator_load: force,
            actuator_load_virtual_work: force_virtual_work,
            reactions: vec![
                ("A1".into(), pin_a1.norm()),
                ("A2".into(), rocker_force),
                ("B0".into(), force),
                ("C".into(), force),
                ("O1".into(), crank_ground.norm()),
                ("O2".into(), rocker_force),
            ],
            transmission_angle_rad: pose.transmission.min(state.transmission_angle_rad),
            health: PoseHealth {
                closure_residual_m: state.closure_residual_m.max(((pose.a2 - l.o2).norm() - l.rocker).abs()),
                jacobian_condition_number: conditioning,
                distance_to_toggle_rad: pose.transmission.min(state.transmission_angle_rad),
            },
            actuator_torques: Some(self.synthesis.screw.torques(force)),
            members: vec![
                // Three forces on the crank: the flap's pin, the screw, the ground at O1.
                (
                    "crank".into(),
                    MemberLoad::of_straight_member(
                        bodies::crank_start(l.o1, pose.a1, c),
                        pose.a1,
                        &[(pose.a1, -pin_a1), (c, u * force), (l.o1, crank_ground)],
                        0.0,
                    ),
                ),
                // The rocker's axial force, tension positive (f pushes the flap away from O2).
                ("rocker".into(), MemberLoad::axial(-rocker_force)),
                // The flap's bracket: the crank's pin force at A1, the rocker's at A2.
                members::bracket_load(pose.a1, pin_a1, pose.a2, e2 * rocker_force),
            ]
            .into_iter()
            // What the crank and the rocker put on their struts at O1 and O2.
            .chain(self.support_loads(-crank_ground, -e2 * rocker_force))
            .collect(),
        })
    }

    fn drawing_notes(&self) -> DrawingNotes {
        let s = &self.synthesis;
        DrawingNotes {
            summary: format!(
                "four-bar with screw jack on the crank; stroke {:.1} -> {:.1} mm",
                s.stroke_m[0] * 1e3,
                s.stroke_m[1] * 1e3
            ),
            dimensions: vec![
                ("O1-A1".into(), s.crank_pivot_m, s.moving_pivots_m[0]),
                ("O2-A2".into(), s.rocker_pivot_m, s.moving_pivots_m[1]),
            ],
            arcs: [
                (s.crank_pivot_m, s.moving_pivots_m[0], "A1 about O1"),
                (s.rocker_pivot_m, s.moving_pivots_m[1], "A2 about O2"),
            ]
            .iter()
            .map(|(centre, moving, name)| {
                let r = moving - centre;
                let start = r.y.atan2(r.x);
                let turn = turn_angle(*centre, *moving, self.spec.landing.flap * moving);
                (name.to_string(), *centre, r.norm(), start, start + turn)
            })
            .collect(),
        }
    }

    fn details(&self) -> serde_json::Value {
        serde_json::json!({
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

    /// The rocker, a two-force member; the crank, which the screw turns from between its
    /// pins (or from a horn beyond O1): three forces, so it bends; the flap's bracket
    /// between A1 and A2 and the struts holding O1 and O2, which bend too (`members`).
    fn members(&self) -> Vec<Member> {
        let hw = &self.spec.hardware;
        let l = &self.loop_;
        let crank_start = bodies::crank_start(l.o1, l.a1, self.synthesis.actuator_attachment_m);
        let [top1, top2] = self.synthesis.strut_tops_m;
        let mut members = vec![
            Member::new(
                "crank",
                (l.a1 - crank_start).norm(),
                hw.link_radius_m,
                MemberLoading::Bending,
            ),
            Member::new("rocker", l.rocker, hw.link_radius_m, MemberLoading::TwoForce),
            Member::new("bracket", l.coupler, hw.link_radius_m, MemberLoading::Bending),
        ];
        match &self.synthesis.truss {
            // Pinned rods of the support's truss, drawn at the struts' radius.
            Some(truss) => {
                let rod = |name: &str, length_m: f64| Member {
                    drawn: DrawnRadius::Strut,
                    ..Member::new(name, length_m, hw.strut_radius_m, MemberLoading::TwoForce)
                };
                let lengths = truss.lengths_m();
                members.extend(TRUSS_RODS.iter().zip(lengths).map(|(name, length)| rod(name, length)));
                members.push(rod(TIE, (l.o1 - l.o2).norm()));
            }
            None => members.extend([
                Member::strut(STRUTS[0], (top1 - l.o1).norm(), hw.strut_radius_m),
                Member::strut(STRUTS[1], (top2 - l.o2).norm(), hw.strut_radius_m),
            ]),
        }
        members
    }

    fn flap_mass(&self) -> Option<FlapMass> {
        Some(self.spec.flap_mass)
    }

    fn warnings(&self) -> Vec<String> {
        let mut warnings = Vec::new();
        if !self.synthesis.actuator_clear {
            warnings.push("no default place of the screw jack kept clear of the wing, the structure and the flap at the sampled poses; give actuator_mount_m".into());
        }
        if !self.synthesis.placement_clear {
            warnings.push("no default place of a strut from a fixed pivot to the wing's lower skin, or of a beam between the pivots, kept clear of the structure and the flap at the sampled poses, or the crank or the rocker came within a quarter of its radius of the flap".into());
        }
        warnings
    }
}

#[cfg(test)]
mod topology_tests {
    use super::*;

    /// The crank is named by its moving pivot's place on the flap, the screw's hold by the
    /// side of the fixed pivot it lies on, the mount by its side of the hold.
    #[test]
    fn the_topology_names_the_crank_the_screws_hold_and_the_mounts_side() {
        let p = Point2::new;
        let (o1, a1) = (p(0.0, 0.0), p(-0.2, 0.4));
        let on_arm = FourBarTopology::of(o1, a1, p(-0.6, 0.5), p(-0.1, 0.2), p(0.3, 0.1));
        assert_eq!(on_arm.crank, CrankLink::Forward);
        assert_eq!(on_arm.attachment, ScrewAttachment::OnArm);
        assert_eq!(on_arm.mount, MountSide::Ahead);
        let horn = FourBarTopology::of(o1, a1, p(0.3, 0.5), p(0.1, -0.2), p(-0.3, -0.3));
        assert_eq!(horn.crank, CrankLink::Aft);
        assert_eq!(horn.attachment, ScrewAttachment::Horn);
        assert_eq!(horn.mount, MountSide::Behind);
    }
}
