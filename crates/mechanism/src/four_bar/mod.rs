//! The four-bar (Zaccai, Bertels & Vos `003_...` section 3, Figs. 6 and 8): the flap is the
//! coupler of a four-bar linkage, held at pivot A1 by the crank O1-A1 and at pivot A2 by
//! the rocker O2-A2 (the crank is the link that turns less); a screw jack from a mount B0 turns the crank about O1 (a
//! [`RockerDrive`]); struts hold O1 and O2 to the wing's lower skin.
//!
//! Synthesis is motion generation for three precision positions (stowed, take-off,
//! landing): for a moving pivot p, the fixed pivot is the centre of the circle through its
//! three positions ([`crate::precision::circle_centre`]). The moving pivots are free choices: fixed by the
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

use nalgebra::{Isometry2, Point2, Translation2, Unit, Vector2};
use serde::Serialize;

mod linkage;
mod search;

use linkage::{turn_angle, Loop, LoopPose};
use search::{candidate, candidates, check_pair, search_failure};

use crate::error::{Error, Result, SynthesisDefect};
use crate::flap_load::{FlapMass, FlapWrench, LinkHardware};
use crate::kinetostatics::LoadCase;
use crate::outline::StationOutline;
use crate::placement::{place_screw_jack, strut_top, JackSize, ScrewJackChoice, PLACEMENT_SAMPLES};
use crate::precision::PrecisionPosition;
use crate::rocker_drive::{cross, turn_about, RockerDrive};
use crate::screw_jack::{ScrewDrive, ScrewJack};
use crate::seam::{
    Actuator, Body, BodyRole, BodySolid, DrawingNotes, FlapMechanism, InputQuantity, InputRange, Joint, JointEnd,
    JointGeometry, Kinetostatics, MechanismPose, NamedPoint, PlanarShape, PoseHealth, SpeedBound, TwoForceMember,
};

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
    /// Smallest transmission angle over the deployment, of the loop and of the drive (rad).
    pub min_transmission_angle_rad: f64,
    /// Where the screw takes hold of the crank: 0 at O1, 1 at A1.
    pub actuator_attachment_fraction: f64,
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
    /// False when no default place of the screw jack kept clear of the wing, the structure
    /// and the flap at the sampled poses (the interference check says where).
    pub actuator_clear: bool,
    /// False when no default place of a strut kept clear of the structure and the flap
    /// at the sampled poses (the interference check says where).
    pub placement_clear: bool,
    /// What the search rejected (all zero when both moving pivots were given).
    pub search: FourBarSearch,
}

/// A four-bar synthesised for one station.
#[derive(Debug, Clone)]
pub struct FourBar {
    spec: FourBarSpec,
    synthesis: FourBarSynthesis,
    loop_: Loop,
    drive: RockerDrive,
    bodies: Vec<Body>,
    joints: Vec<Joint>,
}

const FLAP: usize = 0;
const CRANK: usize = 1;
const ROCKER: usize = 2;
const SCREW: usize = 3;
const NUT: usize = 4;
const SUPPORT: usize = 5;

/// Crank samples of the feasibility check over the deployment.
pub(super) const LOOP_SAMPLES: usize = 48;
/// Loops, shallowest pivots first, whose screw and struts are placed to pick the shallowest
/// whole mechanism: at most this many, and no more than [`CLEAR_FINALISTS`] once one is
/// placed clear of the sections (each placement costs about 4 ms).
const FINALISTS: usize = 24;
/// See [`FINALISTS`].
const CLEAR_FINALISTS: usize = 4;
pub(super) fn failure(defect: SynthesisDefect, detail: String) -> Error {
    Error::Synthesis {
        kind: KIND,
        defect,
        detail,
    }
}

impl FourBar {
    /// Synthesises the four-bar (searching the moving pivots the spec leaves free), its
    /// drive and solids. Errors: [`Error::Synthesis`] with the defect.
    pub fn synthesise(spec: FourBarSpec) -> Result<Self> {
        for position in [spec.takeoff, spec.landing] {
            let t = position.flap.translation.vector;
            if !(t.x.is_finite() && t.y.is_finite() && position.deflection_rad.is_finite()) {
                return Err(failure(
                    SynthesisDefect::MissingPositions,
                    "a precision position is not finite".into(),
                ));
            }
        }
        let Some((_, _, flap_chord)) = spec.outline.flap_chord() else {
            return Err(failure(
                SynthesisDefect::MissingPositions,
                "the station has no flap section".into(),
            ));
        };
        let chord = spec.outline.chord_m().unwrap_or(flap_chord);
        let mut search = FourBarSearch::default();
        let given = |p: Point2<f64>, which: &str| {
            candidate(&spec, p, chord)
                .map_err(|(defect, why)| failure(defect, format!("{which} pivot {}: {why}", mm(p))))
        };
        let grid = if spec.forward_pivot.is_none() || spec.aft_pivot.is_none() {
            candidates(&spec, &mut search, chord)
        } else {
            Vec::new()
        };
        let forward = match spec.forward_pivot {
            Some(p) => vec![given(p, "forward")?],
            None => grid.clone(),
        };
        let aft = match spec.aft_pivot {
            Some(p) => vec![given(p, "aft")?],
            None => grid,
        };
        let fixed_pair = spec.forward_pivot.is_some() && spec.aft_pivot.is_some();
        let section_bottom = spec
            .outline
            .wing
            .iter()
            .chain(&spec.outline.flap)
            .flatten()
            .map(|p| p.y)
            .fold(f64::INFINITY, f64::min);
        let mut feasible: Vec<(f64, f64, Loop)> = Vec::new();
        let mut last_defect = None;
        for first in &forward {
            for second in &aft {
                // Each unordered pair once.
                if spec.forward_pivot.is_none() && spec.aft_pivot.is_none() && first.moving.x <= second.moving.x {
                    continue;
                }
                if (first.moving - second.moving).norm() < 0.1 * flap_chord
                    || (first.fixed - second.fixed).norm() < 0.02 * flap_chord
                {
                    if fixed_pair {
                        last_defect = Some((SynthesisDefect::NoRealSolution, "the two links coincide".to_string()));
                    }
                    continue;
                }
                search.pairs += 1;
                // The screw drives the link that turns less (a square mount keeps it above
                // the minimum transmission angle over up to pi - 2 mu_min of rotation).
                let (crank, rocker) = if first.turns[1].abs() <= second.turns[1].abs() {
                    (first, second)
                } else {
                    (second, first)
                };
                match check_pair(&spec, crank, rocker) {
                    Ok((loop_, transmission)) => {
                        search.feasible += 1;
                        let lowest = [loop_.o1, loop_.o2, loop_.a1, loop_.a2]
                            .iter()
                            .map(|p| p.y)
                            .fold(f64::INFINITY, f64::min);
                        let depth = (section_bottom - lowest).max(0.0);
                        feasible.push((depth, transmission, loop_));
                    }
                    Err((defect, why)) => {
                        match defect {
                            SynthesisDefect::BranchOrOrder => search.branch_change += 1,
                            SynthesisDefect::Toggle => search.toggle += 1,
                            _ => search.link_in_wing += 1,
                        }
                        last_defect = Some((defect, why));
                    }
                }
            }
        }
        if feasible.is_empty() {
            if fixed_pair {
                let (defect, why) = last_defect.unwrap_or((SynthesisDefect::NoRealSolution, "no pair".into()));
                return Err(failure(defect, why));
            }
            return Err(search_failure(&search));
        }
        // The shallowest loops by their pivots, then the shallowest whole mechanism once the
        // screw and the struts are placed (they set the fairing as often as the pivots do).
        feasible.sort_by(|a, b| a.0.total_cmp(&b.0).then(b.1.total_cmp(&a.1)));
        // A mechanism whose screw and struts are placed clear ranks before one that is not.
        let mut best: Option<((bool, f64), Self)> = None;
        let mut first_error = None;
        for (examined, &(_, _, loop_)) in feasible.iter().take(FINALISTS).enumerate() {
            // Enough once a clear mechanism is in hand and the shallowest few were seen.
            if examined >= CLEAR_FINALISTS && best.as_ref().is_some_and(|((blocked, _), _)| !blocked) {
                break;
            }
            match Self::build(spec.clone(), loop_, search) {
                Ok(four_bar) => {
                    let s = &four_bar.synthesis;
                    let rank = (!(s.actuator_clear && s.placement_clear), s.depth_below_section_m);
                    let better = best
                        .as_ref()
                        .is_none_or(|((blocked, d), _)| (rank.0, rank.1 + 1e-9) < (*blocked, *d));
                    if better {
                        best = Some((rank, four_bar));
                    }
                }
                Err(error) => {
                    first_error.get_or_insert(error);
                }
            }
        }
        match (best, first_error) {
            (Some((_, four_bar)), _) => Ok(four_bar),
            (None, Some(error)) => Err(error),
            (None, None) => Err(search_failure(&search)),
        }
    }

    /// Depth of every solid of the mechanism over the deployment below the stowed section's
    /// lowest point (m).
    fn whole_depth(&self) -> Result<f64> {
        let section_bottom = self
            .spec
            .outline
            .wing
            .iter()
            .chain(&self.spec.outline.flap)
            .flatten()
            .map(|p| p.y)
            .fold(f64::INFINITY, f64::min);
        let mut lowest = f64::INFINITY;
        for input in self.input_range().samples(PLACEMENT_SAMPLES + 1) {
            let pose = FlapMechanism::pose(self, input)?;
            for (body, placement) in self.bodies.iter().zip(&pose.bodies) {
                for solid in &body.solids {
                    let posed = crate::seam::posed_shape(&solid.shape, placement);
                    let low = posed.skeleton().iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
                    lowest = lowest.min(low - posed.radius_m());
                }
            }
        }
        Ok((section_bottom - lowest).max(0.0))
    }

    fn build(spec: FourBarSpec, loop_: Loop, search: FourBarSearch) -> Result<Self> {
        let turns = [
            turn_angle(loop_.o1, loop_.a1, spec.takeoff.flap * loop_.a1),
            turn_angle(loop_.o1, loop_.a1, spec.landing.flap * loop_.a1),
        ];
        let travel = turns[1];
        let mut min_transmission = f64::INFINITY;
        let mut max_crank_ratio = 0.0_f64;
        for k in 0..=LOOP_SAMPLES {
            let phi = travel * k as f64 / LOOP_SAMPLES as f64;
            let pose = loop_.at(phi).ok_or_else(|| {
                failure(
                    SynthesisDefect::NoRealSolution,
                    "the loop breaks inside the deployment".into(),
                )
            })?;
            min_transmission = min_transmission.min(pose.transmission);
            let (rocker, flap) = loop_.rates(&pose);
            max_crank_ratio = max_crank_ratio.max(rocker.abs()).max(flap.abs());
        }
        // Between samples the transmission angle changes at most as fast as the coupler and
        // rocker turn: |dμ/dφ| <= |ω_r| + |ω_f| per unit crank rate, bounded by the rates at
        // half the sampled minimum (they grow as 1/sin μ).
        let step = travel.abs() / LOOP_SAMPLES as f64;
        let crank_arm = (loop_.a1 - loop_.o1).norm();
        let rate_bound = |mu: f64| crank_arm / (loop_.rocker * mu.sin()) + crank_arm / (loop_.coupler * mu.sin());
        let certified = (min_transmission - 0.5 * step * rate_bound(0.5 * min_transmission)).max(0.0);
        let hw = spec.hardware;
        // In-plane margin for the 3D check's clearance and the flap's taper across a part's width.
        let margin = hw.link_radius_m;
        let choice = ScrewJackChoice {
            arm: (loop_.o1, loop_.a1),
            attachment_fraction: spec.actuator_attachment_fraction,
            // On the crank, then on a horn beyond its fixed pivot.
            other_fractions: &[0.35, 0.7, 0.9, -0.4, -0.7],
            mount: spec.actuator_mount,
            standoff_m: spec.actuator_standoff_m,
            min_transmission_rad: spec.min_transmission_angle_rad,
        };
        let size = JackSize::new(&hw, spec.screw_drive.mean_radius_m);
        let flap_at = |phi: f64| loop_.at(phi).map(|p| p.flap);
        let (attachment, mount, actuator_clear) =
            place_screw_jack(loop_.o1, travel, &choice, &size, margin, &spec.outline, &flap_at);
        let mut placement_clear = true;
        let flap_poses: Vec<Isometry2<f64>> = (0..=PLACEMENT_SAMPLES)
            .filter_map(|k| loop_.at(travel * k as f64 / PLACEMENT_SAMPLES as f64).map(|p| p.flap))
            .collect();
        let ahead = [0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.25, 1.5];
        let strut =
            |from: Point2<f64>| strut_top(&spec.outline, from, &ahead, hw.link_radius_m, margin, &flap_poses, None);
        // A pivot whose strut to the skin would cross the flap's path is held by a beam to
        // the other pivot instead (one support beam carrying both), if that beam is clear.
        let beam_clear = |from: Point2<f64>, to: Point2<f64>| {
            flap_poses.iter().all(|pose| {
                let back = pose.inverse();
                crate::outline::segment_distance(&spec.outline.flap, back * from, back * to) > hw.link_radius_m + margin
            }) && !crate::outline::segment_meets(&spec.outline.wing, from, to)
        };
        let (first, second) = (strut(loop_.o1), strut(loop_.o2));
        let (first, second) = match (first, second) {
            (Some(a), None) if beam_clear(loop_.o2, loop_.o1) => (Some(a), Some(loop_.o1)),
            (None, Some(b)) if beam_clear(loop_.o1, loop_.o2) => (Some(loop_.o2), Some(b)),
            other => other,
        };
        let strut_tops = match (first, second) {
            (Some(a), Some(b)) => [a, b],
            (a, b) => {
                placement_clear = false;
                let straight_up = |o: Point2<f64>| {
                    spec.outline
                        .wing_lower_point(o.x)
                        .unwrap_or(Point2::new(o.x, o.y + hw.link_radius_m))
                };
                [
                    a.unwrap_or_else(|| straight_up(loop_.o1)),
                    b.unwrap_or_else(|| straight_up(loop_.o2)),
                ]
            }
        };
        let drive = RockerDrive::try_new(loop_.o1, mount, attachment).map_err(|_| {
            failure(
                SynthesisDefect::Toggle,
                format!(
                    "the screw mount {}, O1 and the crank attachment lie on one line",
                    mm(mount)
                ),
            )
        })?;
        let drive_min = (0..=LOOP_SAMPLES)
            .map(|k| {
                let phi = travel * k as f64 / LOOP_SAMPLES as f64;
                drive
                    .state(drive.stroke_at(phi))
                    .map_or(0.0, |s| s.transmission_angle_rad)
            })
            .fold(f64::INFINITY, f64::min);
        if !drive.clear_of_toggles(travel, 1e-3) || drive_min < spec.min_transmission_angle_rad {
            return Err(failure(
                SynthesisDefect::Toggle,
                format!(
                    "the screw's transmission angle on the crank falls to {:.1} deg (minimum {:.1} deg); move the actuator mount or its attachment",
                    drive_min.to_degrees(),
                    spec.min_transmission_angle_rad.to_degrees()
                ),
            ));
        }
        let stroke_m = [drive.stroke_at(0.0), drive.stroke_at(travel)];
        let (screw, nominal_speed_mps) = spec.screw_drive.screw_for(stroke_m[1] - stroke_m[0]);
        let miss = [(turns[0], spec.takeoff), (turns[1], spec.landing)]
            .iter()
            .filter_map(|(phi, position)| {
                let pose = loop_.at(*phi)?;
                Some(
                    (pose.a1 - position.flap * loop_.a1)
                        .norm()
                        .max((pose.a2 - position.flap * loop_.a2).norm()),
                )
            })
            .fold(0.0, f64::max);
        let synthesis = FourBarSynthesis {
            crank_pivot_m: loop_.o1,
            rocker_pivot_m: loop_.o2,
            moving_pivots_m: [loop_.a1, loop_.a2],
            crank_rotation_rad: turns,
            min_transmission_angle_rad: min_transmission,
            drive_min_transmission_angle_rad: drive_min,
            certified_min_transmission_angle_rad: certified,
            depth_below_section_m: 0.0,
            precision_miss_m: miss,
            actuator_mount_m: mount,
            actuator_attachment_m: attachment,
            stroke_m,
            screw,
            // Long enough to carry the nut at the longest stroke: a free end would sweep.
            screw_length_m: stroke_m[0].max(stroke_m[1]) + hw.nut_radius_m,
            strut_tops_m: strut_tops,
            actuator_clear,
            placement_clear,
            nominal_speed_mps,
            search,
        };
        let (bodies, joints) = bodies_and_joints(&spec, &synthesis, &loop_, &drive, certified);
        let mut four_bar = Self {
            spec,
            synthesis,
            loop_,
            drive,
            bodies,
            joints,
        };
        four_bar.synthesis.depth_below_section_m = four_bar.whole_depth()?;
        Ok(four_bar)
    }

    /// The designer's choices.
    pub fn spec(&self) -> &FourBarSpec {
        &self.spec
    }

    /// What synthesis computed.
    pub fn synthesis(&self) -> &FourBarSynthesis {
        &self.synthesis
    }

    /// The flap's displacement and the loop's transmission angle at crank angle `phi`: the
    /// closed-form pose (benchmarked).
    pub fn flap_at_crank_angle(&self, phi: f64) -> Option<(Isometry2<f64>, f64)> {
        self.loop_.at(phi).map(|p| (p.flap, p.transmission))
    }

    fn loop_pose(&self, input: f64) -> Result<(crate::rocker_drive::RockerState, LoopPose)> {
        let state = self.drive.state(input)?;
        let pose = self.loop_.at(state.rotation_rad).ok_or(Error::CannotAssemble {
            input_m: input,
            min_input_m: self.synthesis.stroke_m[0].min(self.synthesis.stroke_m[1]),
            max_input_m: self.synthesis.stroke_m[0].max(self.synthesis.stroke_m[1]),
        })?;
        Ok((state, pose))
    }
}

pub(super) fn mm(p: Point2<f64>) -> String {
    format!("({:.1}, {:.1}) mm", p.x * 1e3, p.y * 1e3)
}

fn bodies_and_joints(
    spec: &FourBarSpec,
    synthesis: &FourBarSynthesis,
    loop_: &Loop,
    drive: &RockerDrive,
    certified_transmission: f64,
) -> (Vec<Body>, Vec<Joint>) {
    let hw = &spec.hardware;
    let (o1, o2, a1, a2) = (loop_.o1, loop_.o2, loop_.a1, loop_.a2);
    let (b0, c) = (synthesis.actuator_mount_m, synthesis.actuator_attachment_m);
    let capsule = |name: &str, from, to, radius_m| BodySolid {
        name: name.into(),
        shape: PlanarShape::Capsule { from, to, radius_m },
        width_m: 0.0,
        offset_m: 0.0,
    };
    let travel = synthesis.crank_rotation_rad[1];
    let crank_rate = drive.rotation_rate_bound(travel);
    let crank_arm = (a1 - o1).norm();
    let sine = certified_transmission.sin().max(1e-9);
    let rocker_rate = crank_arm * crank_rate / (loop_.rocker * sine);
    let flap_rate = crank_arm * crank_rate / (loop_.coupler * sine);
    let shortest = synthesis.stroke_m[0].min(synthesis.stroke_m[1]);
    let c_arm = (c - o1).norm();
    let screw_rate = c_arm * crank_rate / shortest;
    let direction = (c - b0).normalize();
    let half_body = direction * (0.5 * hw.jack_body_length_m);
    let screw_radius = synthesis.screw.mean_radius_m + 0.25 * synthesis.screw.lead_m;
    let bodies = vec![
        Body {
            name: "flap".into(),
            role: BodyRole::Flap,
            solids: vec![capsule("bracket", a1, a2, hw.link_radius_m)],
            speed_bound: SpeedBound {
                reference: a1,
                linear_per_input: crank_arm * crank_rate,
                angular_per_input: flap_rate,
            },
        },
        Body {
            name: "crank".into(),
            role: BodyRole::Link,
            // From the screw's attachment when it sits on a horn beyond O1.
            solids: vec![capsule(
                "crank",
                if (c - o1).dot(&(a1 - o1)) < 0.0 { c } else { o1 },
                a1,
                hw.link_radius_m,
            )],
            speed_bound: SpeedBound {
                reference: o1,
                linear_per_input: 0.0,
                angular_per_input: crank_rate,
            },
        },
        Body {
            name: "rocker".into(),
            role: BodyRole::Link,
            solids: vec![capsule("rocker", o2, a2, hw.link_radius_m)],
            speed_bound: SpeedBound {
                reference: o2,
                linear_per_input: 0.0,
                angular_per_input: rocker_rate,
            },
        },
        Body {
            name: "screw".into(),
            role: BodyRole::Actuator,
            solids: vec![
                capsule("screw", b0, b0 + direction * synthesis.screw_length_m, screw_radius),
                capsule("jack-body", b0 - half_body, b0 + half_body, hw.jack_body_radius_m),
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
            solids: vec![capsule("nut", c, c, hw.nut_radius_m)],
            speed_bound: SpeedBound {
                reference: c,
                linear_per_input: c_arm * crank_rate,
                angular_per_input: screw_rate,
            },
        },
        Body {
            name: "support".into(),
            role: BodyRole::Support,
            solids: vec![
                capsule("strut-O1", o1, synthesis.strut_tops_m[0], hw.link_radius_m),
                capsule("strut-O2", o2, synthesis.strut_tops_m[1], hw.link_radius_m),
            ],
            speed_bound: SpeedBound::FIXED,
        },
    ];
    let joint = |name: &str, description: &str, geometry, ends, touching: &[(&str, &str)]| Joint {
        name: name.into(),
        description: description.into(),
        geometry,
        ends,
        touching_solids: touching.iter().map(|(x, y)| (x.to_string(), y.to_string())).collect(),
    };
    let joints = vec![
        joint(
            "O1",
            "crank on its support",
            JointGeometry::Revolute { at: o1 },
            [JointEnd::Body(SUPPORT), JointEnd::Body(CRANK)],
            &[("strut-O1", "crank")],
        ),
        joint(
            "O2",
            "rocker on its support",
            JointGeometry::Revolute { at: o2 },
            [JointEnd::Body(SUPPORT), JointEnd::Body(ROCKER)],
            &[("strut-O2", "rocker")],
        ),
        joint(
            "A1",
            "crank pinned to the flap",
            JointGeometry::Revolute { at: a1 },
            [JointEnd::Body(CRANK), JointEnd::Body(FLAP)],
            &[("crank", "bracket")],
        ),
        joint(
            "A2",
            "rocker pinned to the flap",
            JointGeometry::Revolute { at: a2 },
            [JointEnd::Body(ROCKER), JointEnd::Body(FLAP)],
            &[("rocker", "bracket")],
        ),
        joint(
            "C",
            "nut pivoting on the crank",
            JointGeometry::Revolute { at: c },
            [JointEnd::Body(NUT), JointEnd::Body(CRANK)],
            &[("nut", "crank")],
        ),
        joint(
            "nut-slide",
            "nut riding along the screw",
            JointGeometry::Prismatic {
                origin: c,
                direction: Unit::new_normalize(c - b0),
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
    ];
    (bodies, joints)
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
        let target = deflection_rad;
        let sense = self.spec.landing.deflection_rad.signum();
        let (mut lo, mut hi) = (0.0, travel);
        if (target - deflection(hi)) * sense >= 0.0 {
            return Ok(self.drive.stroke_at(hi));
        }
        if (target - deflection(lo)) * sense <= 0.0 {
            return Ok(self.drive.stroke_at(lo));
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if (deflection(mid) - target) * sense < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
            if (hi - lo).abs() < 1e-15 {
                break;
            }
        }
        Ok(self.drive.stroke_at(0.5 * (lo + hi)))
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
        let screw_turn = self.drive.screw_rotation(state.attachment);
        let c_stowed = self.synthesis.actuator_attachment_m;
        let nut = Translation2::from(state.attachment.coords)
            * Isometry2::rotation(screw_turn)
            * Translation2::from(-c_stowed.coords);
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
            bodies: vec![
                pose.flap,
                crank,
                rocker,
                turn_about(b0, screw_turn),
                nut,
                Isometry2::identity(),
            ],
            flap: pose.flap,
            points,
        })
    }

    fn kinetostatics(&self, input: f64, load: &LoadCase) -> Result<Kinetostatics> {
        let (state, pose) = self.loop_pose(input)?;
        let l = &self.loop_;
        let fraction = self.input_range().fraction(input).clamp(0.0, 1.0);
        let wrench = FlapWrench::new(&self.spec.flap_mass, &pose.flap, load, fraction);
        // Rocker force on the flap f e2 (two-force member), moments about A1.
        let e2 = (pose.a2 - l.o2) / l.rocker;
        let rocker_force = -wrench.moment_about(pose.a1) / cross(pose.a2 - pose.a1, e2);
        let pin_a1: Vector2<f64> = -(e2 * rocker_force + wrench.force_n());
        // Crank: the flap pushes it with -R1 at A1, the screw with F u at C; moments about O1.
        let c = state.attachment;
        let u = (c - self.synthesis.actuator_mount_m).normalize();
        let force = cross(pose.a1 - l.o1, pin_a1) / cross(c - l.o1, u);
        let crank_ground: Vector2<f64> = pin_a1 - u * force;
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
                // The rocker's axial force, tension positive (f pushes the flap away from O2).
                ("rocker".into(), -rocker_force),
            ],
            transmission_angle_rad: pose.transmission.min(state.transmission_angle_rad),
            health: PoseHealth {
                closure_residual_m: state.closure_residual_m.max(((pose.a2 - l.o2).norm() - l.rocker).abs()),
                jacobian_condition_number: conditioning,
                distance_to_toggle_rad: pose.transmission.min(state.transmission_angle_rad),
            },
            screw_torques: Some(self.synthesis.screw.torques(force)),
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

    /// The rocker (the crank carries the screw as well: three forces, not sized here).
    fn members(&self) -> Vec<TwoForceMember> {
        vec![TwoForceMember {
            name: "rocker".into(),
            length_m: self.loop_.rocker,
            radius_m: self.spec.hardware.link_radius_m,
        }]
    }

    fn warnings(&self) -> Vec<String> {
        let mut warnings = Vec::new();
        if !self.synthesis.actuator_clear {
            warnings.push("no default place of the screw jack kept clear of the wing, the structure and the flap at the sampled poses; give actuator_mount_m".into());
        }
        if !self.synthesis.placement_clear {
            warnings.push("no default place of a strut from a fixed pivot to the wing's lower skin, or of a beam between the pivots, kept clear of the structure and the flap at the sampled poses".into());
        }
        warnings
    }
}
