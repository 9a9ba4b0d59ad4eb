//! The link-track (Zaccai, Bertels & Vos `003_...` section 3, Figs. 6 and 9): a forward
//! link, turned about its fixed pivot O by a geared rotary actuator, sets the flap's
//! rotation through its pivot A on the flap, while a carriage at C on the flap runs on a
//! straight track beam and constrains the flap's translation.
//!
//! Synthesis is motion generation for three precision positions (stowed, take-off,
//! landing), both constructions linear (the `search` module): the carriage point whose three
//! positions lie on a line along a chosen track slope, and the link point whose three
//! positions lie on a circle about a chosen fixed pivot. The free choices, the track slope
//! and the link's fixed pivot, are the designer's or searched for the shallowest mechanism.
//!
//! The rotary actuator sits at the link's fixed pivot, searched below the lower skin, up
//! the rear spar's web and across the trailing-edge bay behind it (`003_...` Fig. 6); from
//! there the link crosses the bay and leaves it through the lower skin or the cove wall,
//! never the upper skin. The carriage and the link pin sit on brackets under the flap or
//! reaching forward of its nose under the lower skin (`search`).
//!
//! Pose in closed form (the `linkage` module). Statics: the track pushes the flap only square to
//! itself (N n at C); moments of the flap about A give N = -M_A / ((C - A) · d), the flap's
//! balance the link's pin force P at A, the link's moments about O the actuator torque
//! T = (A - O) x P. Virtual work, independently, from the loop's velocity analysis.

use nalgebra::{Isometry2, Point2, Unit, Vector2};
use serde::Serialize;

mod bodies;
mod linkage;
mod members;
mod search;
mod struts;

pub use search::TRADE_CANDIDATES;

use linkage::{Loop, LoopPose};
use struts::StrutPlacement;

use flapwright_mechanism::seam::{
    Actuator, Body, DrawingNotes, FlapMechanism, InputQuantity, InputRange, Joint, Kinetostatics, MechanismPose,
    Member, NamedPoint, PoseHealth,
};
use flapwright_mechanism::shared::flap_load::{FlapMass, FlapWrench, LinkHardware};
use flapwright_mechanism::shared::geometry::{cross, turn_about};
use flapwright_mechanism::shared::load_case::LoadCase;
use flapwright_mechanism::shared::outline::StationOutline;
use flapwright_mechanism::shared::precision::PrecisionPosition;
use flapwright_mechanism::shared::rotary_actuator::RotaryDrive;
use flapwright_mechanism::{Error, Result, SynthesisDefect};

const KIND: &str = "link-track";

/// Pieces of the deployment on which the flap's rate is certified
/// (`linkage::Loop::flap_rate_bound`): 256 closed-form poses a build. On the transport
/// scene's link-track at `ob-outer` (study of that station) the flap mesh's speed bound
/// falls from 3.3 to 1.5 m per unit drive fraction.
const RATE_INTERVALS: usize = 256;

/// The designer's choices for a link-track at one station (station frame, m).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LinkTrackSpec {
    /// Take-off (the second precision position).
    pub takeoff: PrecisionPosition,
    /// Landing, where the deployment ends.
    pub landing: PrecisionPosition,
    /// The link's fixed pivot O (where the rotary actuator sits); `None`: searched.
    pub link_pivot: Option<Point2<f64>>,
    /// The track's slope below the aft direction (rad); `None`: searched.
    pub track_slope_rad: Option<f64>,
    /// Smallest transmission angle of the loop over the deployment (rad).
    pub min_transmission_angle_rad: f64,
    /// The flap share this station carries.
    pub flap_mass: FlapMass,
    /// The rotary actuator's drive.
    pub rotary: RotaryDrive,
    /// Solid sizes.
    pub hardware: LinkHardware,
    /// The station's sections.
    pub outline: StationOutline,
    /// The station's load cases, under which the search weighs the actuator's load against
    /// the fairing's depth ([`flapwright_mechanism::shared::objective`]); empty: the
    /// shallowest candidate.
    #[serde(skip)]
    pub design_loads: Vec<flapwright_mechanism::LoadCase>,
    /// Weight of the actuator's peak load against the fairing's depth
    /// ([`flapwright_mechanism::shared::objective::LoadWeighing::weight`]).
    #[serde(skip)]
    pub load_weight: f64,
    /// The motion of the station of the same flap synthesised first, as this station's
    /// plane sees it: the search adds its miss from it to the cost
    /// ([`flapwright_mechanism::shared::follow`]); `None`: searched alone.
    #[serde(skip)]
    pub follow: Option<flapwright_mechanism::shared::follow::FollowedMotion>,
    /// Take this candidate of the search's trade (its index in
    /// [`LinkTrackSynthesis::trade`]) instead of the one of least cost; `None`: the least.
    pub trade_index: Option<usize>,
}

/// Counts of what the search rejected.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct LinkTrackSearch {
    /// Track slopes tried.
    pub slopes: usize,
    /// Fixed pivots tried.
    pub pivots: usize,
    /// ... with no carriage or link point (the linear equations are singular).
    pub no_line: usize,
    /// ... whose carriage is not on a bracket under the flap or ahead of its nose.
    pub carriage_off_bracket: usize,
    /// ... whose carriage does not run aft in order.
    pub order_defect: usize,
    /// ... whose pivot lies in the wing or above its lower surface, or whose link point is
    /// not on a bracket under the flap or ahead of its nose.
    pub pivot_outside_region: usize,
    /// Pairs of a carriage and a link tried.
    pub pairs: usize,
    /// ... that failed the loop check, by defect: toggle, branch or order, region.
    pub toggle: usize,
    /// See [`Self::toggle`].
    pub branch_or_order: usize,
    /// See [`Self::toggle`].
    pub region: usize,
    /// ... feasible.
    pub feasible: usize,
}

/// Where a link-track's fixed pivot stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PivotPlace {
    /// In the wing's trailing-edge bay behind the rear spar (`003_...` Fig. 6): the link
    /// reaches down through the lower skin and turns far (100-150 deg).
    TrailingEdgeBay,
    /// Outside the wing section, on a strut: below its lower skin, or aft of its lower lip
    /// under the cove; the link hangs in the fairing.
    OutsideWing,
}

/// The link-track's arrangement, the discrete choices its search spans: neighbouring
/// inputs whose designs differ in it are different mechanisms, whose figures may differ by
/// several times (issue 37's continuity: the link turning 100-150 deg with a small torque
/// or 40-60 deg with a large one; `data/validation/continuity`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct LinkTrackTopology {
    /// Which way the link turns to landing.
    pub turning: TurningSense,
    /// Whether it turns past a quarter turn.
    pub sweep: LinkSweep,
    /// Where its fixed pivot stands.
    pub pivot: PivotPlace,
    /// Which way the carriage runs along the track as the flap deploys.
    pub track: TrackRun,
}

/// Which way a link-track's carriage runs along its track as the flap deploys (station
/// frame, x to the nose): aft and up from a carriage near the flap's middle, or forward and
/// down from one near its nose, whose track and strut are longer (on `transport-flap`'s
/// `ob-outer`, from a landing gap of 1.60 to 1.65 %c: the track's strut 4.6 -> 19 kg for
/// the same torque).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum TrackRun {
    /// Towards -x: aft.
    Aft,
    /// Towards +x: forward.
    Forward,
}

/// Which way a link turns (station frame, +z out of the plane).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum TurningSense {
    /// Counter-clockwise: a positive rotation.
    CounterClockwise,
    /// Clockwise.
    Clockwise,
}

/// How far a link turns from stowed to landing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum LinkSweep {
    /// Up to a quarter turn.
    WithinQuarterTurn,
    /// Beyond a quarter turn.
    PastQuarterTurn,
}

impl LinkTrackTopology {
    fn of(landing_rotation_rad: f64, pivot: PivotPlace, track_direction: Vector2<f64>) -> Self {
        Self {
            turning: if landing_rotation_rad >= 0.0 {
                TurningSense::CounterClockwise
            } else {
                TurningSense::Clockwise
            },
            sweep: if landing_rotation_rad.abs() > std::f64::consts::FRAC_PI_2 {
                LinkSweep::PastQuarterTurn
            } else {
                LinkSweep::WithinQuarterTurn
            },
            pivot,
            track: if track_direction.x > 0.0 {
                TrackRun::Forward
            } else {
                TrackRun::Aft
            },
        }
    }
}

/// What synthesis computed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LinkTrackSynthesis {
    /// The link's fixed pivot O (m).
    pub link_pivot_m: Point2<f64>,
    /// Where the fixed pivot stands: the mechanism's topology, which a change of input may
    /// switch (and with it the actuator's load, by several times).
    pub link_pivot_place: PivotPlace,
    /// The link's pivot A on the flap, stowed (m).
    pub link_flap_pivot_m: Point2<f64>,
    /// The carriage's pin C on the flap, stowed (m).
    pub carriage_m: Point2<f64>,
    /// The track's direction (unit, towards deployment).
    pub track_direction: Vector2<f64>,
    /// The track's slope below the aft direction (rad).
    pub track_slope_rad: f64,
    /// The carriage's travel along the track at take-off and landing (m).
    pub carriage_travel_m: [f64; 2],
    /// The link's rotation at take-off and landing (rad).
    pub link_rotation_rad: [f64; 2],
    /// The arrangement chosen (see [`LinkTrackTopology`]).
    pub topology: LinkTrackTopology,
    /// Smallest transmission angle over the deployment (rad, sampled).
    pub min_transmission_angle_rad: f64,
    /// A certified lower bound on it between samples (rad).
    pub certified_min_transmission_angle_rad: f64,
    /// How far the actuator, the link pin and the carriage reach below the stowed
    /// sections' lower contour over the deployment (m): the fairing's depth.
    pub depth_below_section_m: f64,
    /// Largest distance between the mechanism's flap and each precision position at A and
    /// C (m).
    pub precision_miss_m: f64,
    /// The track beam's ends (m), stowed carriage first.
    pub track_ends_m: [Point2<f64>; 2],
    /// Where the struts from O and from the track's forward end meet the lower skin (m).
    pub strut_tops_m: [Point2<f64>; 2],
    /// False when no default strut kept clear of the structure and the flap.
    pub placement_clear: bool,
    /// The rotary actuator at O.
    pub actuator: Actuator,
    /// What the search rejected.
    pub search: LinkTrackSearch,
    /// The station of the same flap whose motion this one followed, and the largest
    /// distance (m) of this station's flap from it over the deployment, at points near the
    /// flap's leading and trailing edges ([`flapwright_mechanism::shared::follow`]).
    pub followed: Option<flapwright_mechanism::shared::follow::FollowedStation>,
    /// The refined candidates no other beats on both the fairing's depth and the
    /// actuator's peak torque, shallowest first (at most eight; empty without load cases):
    /// the trade the weight `[design] actuator_load_weight` chose from.
    pub trade: Vec<LinkTrackCandidate>,
}

/// One of the non-dominated candidates of the link-track's search.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LinkTrackCandidate {
    /// The link's fixed pivot O (m).
    pub link_pivot_m: Point2<f64>,
    /// The track's slope below the aft direction (rad).
    pub track_slope_rad: f64,
    /// The link's rotation to landing (rad).
    pub link_rotation_rad: f64,
    /// Depth below the stowed sections (m).
    pub depth_below_section_m: f64,
    /// The actuator's peak torque under the station's load cases, by virtual work (N m).
    pub peak_torque_nm: f64,
    /// Its largest miss from the followed station's motion (m); 0 when searched alone.
    pub follow_miss_m: f64,
    /// The search's cost (depth in flap chords plus the weighted load).
    pub cost: f64,
    /// True for the candidate synthesis chose (the least cost).
    pub chosen: bool,
}

impl LinkTrackCandidate {
    fn of(candidate: &search::Found, chosen: &search::Found) -> Self {
        let l = &candidate.loop_;
        Self {
            link_pivot_m: l.o,
            track_slope_rad: (-l.d.y).atan2(-l.d.x),
            link_rotation_rad: candidate.turns[1],
            depth_below_section_m: candidate.depth,
            peak_torque_nm: candidate.peak_load,
            follow_miss_m: candidate.follow_miss,
            cost: candidate.cost,
            chosen: candidate.cost == chosen.cost && candidate.loop_.o == chosen.loop_.o,
        }
    }
}

/// A link-track synthesised for one station.
#[derive(Debug, Clone)]
pub struct LinkTrack {
    spec: LinkTrackSpec,
    synthesis: LinkTrackSynthesis,
    loop_: Loop,
    /// The link's turning sense towards deployment (±1): input = sense x rotation.
    sense: f64,
    bodies: Vec<Body>,
    joints: Vec<Joint>,
}

fn failure(defect: SynthesisDefect, detail: String) -> Error {
    Error::Synthesis {
        kind: KIND,
        defect,
        detail,
    }
}

impl LinkTrack {
    /// Synthesises the link and the track through the three precision positions. Errors
    /// ([`Error::Synthesis`]): no feasible pair, with the dominant defect and the counts;
    /// given choices that fail, with their defect.
    pub fn synthesise(spec: LinkTrackSpec) -> Result<Self> {
        let flap_chord = flapwright_mechanism::shared::feasibility::settings_and_flap_chord(
            &[spec.takeoff, spec.landing],
            &spec.outline,
        )
        .map_err(|(defect, detail)| failure(defect, detail))?;
        let mut counts = LinkTrackSearch::default();
        let mut carriages = search::carriages(&spec, &mut counts, flap_chord);
        let mut links = search::links(&spec, &mut counts, flap_chord);
        let (seed_links, seed_carriages) = search::followed_seeds(&spec, flap_chord);
        links.extend(seed_links);
        carriages.extend(seed_carriages);
        // Built once: each candidate's cost weighs its torque under the same load cases.
        let weighing = spec.weighing();
        let mut feasible: Vec<search::Found> = Vec::new();
        let mut last_failure = None;
        for link in &links {
            for carriage in &carriages {
                counts.pairs += 1;
                match search::check(&spec, weighing.as_ref(), *link, *carriage) {
                    Ok(found) => {
                        counts.feasible += 1;
                        feasible.push(found);
                    }
                    Err((defect, detail)) => {
                        match defect {
                            SynthesisDefect::Toggle => counts.toggle += 1,
                            SynthesisDefect::BranchOrOrder => counts.branch_or_order += 1,
                            _ => counts.region += 1,
                        }
                        last_failure = Some((defect, detail));
                    }
                }
            }
        }
        let refined = search::refine_best(&spec, weighing.as_ref(), feasible, flap_chord);
        if refined.is_empty() {
            return Err(match (last_failure, counts.pairs) {
                (Some((defect, detail)), 1) => failure(defect, detail),
                _ => failure(dominant(&counts), describe(&counts)),
            });
        }
        // The refined mechanisms whose struts place clear of the wing and the flap, or all
        // of them where none does (the report then says no strut clears): at landing
        // deflections of 35.6-36 deg the outboard flap's least costly link hung from a pivot
        // in the cove, 0.4 m shallower, with no strut to the wing that clears.
        let clear: Vec<search::Found> = refined
            .iter()
            .filter(|found| StrutPlacement::of(&spec, found).clear())
            .copied()
            .collect();
        let buildable = if clear.is_empty() { refined } else { clear };
        let found = buildable[0];
        let trade = if weighing.is_some() {
            search::non_dominated(buildable)
        } else {
            Vec::new()
        };
        let found = match spec.trade_index {
            None => found,
            Some(index) => *trade.get(index).ok_or(Error::NoSuchTradeCandidate {
                kind: KIND,
                index,
                count: trade.len(),
            })?,
        };
        let trade = trade.iter().map(|c| LinkTrackCandidate::of(c, &found)).collect();
        Self::build(spec, found, counts, trade)
    }

    fn build(
        spec: LinkTrackSpec,
        found: search::Found,
        counts: LinkTrackSearch,
        trade: Vec<LinkTrackCandidate>,
    ) -> Result<Self> {
        let loop_ = found.loop_;
        let travel = found.turns[1];
        let sense = travel.signum();
        let miss = [spec.takeoff, spec.landing]
            .iter()
            .zip(found.turns)
            .filter_map(|(position, turn)| {
                let pose = loop_.at(turn)?;
                Some(
                    [loop_.a, loop_.c]
                        .iter()
                        .map(|p| (pose.flap * p - position.flap * p).norm())
                        .fold(0.0, f64::max),
                )
            })
            .fold(0.0, f64::max);
        // Certified transmission: between samples h apart, sin μ falls at most at
        // |A'| (1 + 1 / sin μ) / ℓ per radian of link (d/dφ of |d · (C - A)|, see `linkage`).
        let arm = (loop_.a - loop_.o).norm();
        let step = travel.abs() / search::LOOP_SAMPLES as f64;
        let sine = found.min_transmission.sin();
        let floor = (0.5 * found.min_transmission).sin();
        let certified_sine = sine - 0.5 * step * arm * (1.0 + 1.0 / floor) / loop_.span;
        let certified = if certified_sine >= floor {
            certified_sine.asin()
        } else {
            0.0
        };
        let struts = StrutPlacement::of(&spec, &found);
        let track_ends = struts.track_ends;
        let [first, second] = struts.tops;
        let placement_clear = struts.clear();
        let fallback = |p: Point2<f64>| {
            spec.outline
                .wing_lower_point(p.x)
                .unwrap_or(Point2::new(p.x, p.y + 0.1))
        };
        let strut_tops = [
            first.unwrap_or_else(|| fallback(loop_.o)),
            second.unwrap_or_else(|| fallback(track_ends[0])),
        ];
        let carriage_travel = found.turns.map(|t| loop_.at(t).map_or(f64::NAN, |p| p.travel));
        let link_pivot_place = if search::on_web(&spec.outline, loop_.o) {
            PivotPlace::TrailingEdgeBay
        } else {
            PivotPlace::OutsideWing
        };
        let synthesis = LinkTrackSynthesis {
            link_pivot_m: loop_.o,
            link_pivot_place,
            topology: LinkTrackTopology::of(found.turns[1], link_pivot_place, loop_.d.into_inner()),
            link_flap_pivot_m: loop_.a,
            carriage_m: loop_.c,
            track_direction: loop_.d.into_inner(),
            track_slope_rad: (-loop_.d.y).atan2(-loop_.d.x),
            carriage_travel_m: carriage_travel,
            link_rotation_rad: found.turns,
            min_transmission_angle_rad: found.min_transmission,
            certified_min_transmission_angle_rad: certified,
            depth_below_section_m: found.depth,
            precision_miss_m: miss,
            track_ends_m: track_ends,
            strut_tops_m: strut_tops,
            placement_clear,
            actuator: spec.rotary.actuator_for(travel),
            search: counts,
            trade,
            followed: spec.follow.as_ref().map(|f| f.followed(found.follow_miss)),
        };
        // The flap's rate: certified on RATE_INTERVALS pieces of the deployment, or from the
        // transmission angle alone.
        let flap_rate = loop_
            .flap_rate_bound(travel, certified, RATE_INTERVALS)
            .unwrap_or_else(|| arm * (1.0 + 1.0 / certified.sin().max(1e-9)) / loop_.span);
        let (bodies, joints) = bodies::bodies_and_joints(&spec, &synthesis, &loop_, flap_rate);
        Ok(Self {
            spec,
            synthesis,
            loop_,
            sense,
            bodies,
            joints,
        })
    }

    /// The designer's choices.
    pub fn spec(&self) -> &LinkTrackSpec {
        &self.spec
    }

    /// What synthesis computed.
    pub fn synthesis(&self) -> &LinkTrackSynthesis {
        &self.synthesis
    }

    /// The loop at actuator input `input` (the link's turn towards deployment, rad).
    fn loop_pose(&self, input: f64) -> Result<LoopPose> {
        if !input.is_finite() {
            return Err(Error::NonFinite {
                quantity: "link-track link angle",
                input_m: input,
            });
        }
        self.loop_.at(self.sense * input).ok_or(Error::Synthesis {
            kind: KIND,
            defect: SynthesisDefect::NoRealSolution,
            detail: format!(
                "the flap cannot reach the track at {:.2} deg of link",
                input.to_degrees()
            ),
        })
    }
}

/// The defect most rejections had.
fn dominant(counts: &LinkTrackSearch) -> SynthesisDefect {
    if counts.pairs == 0 {
        if counts.carriage_off_bracket + counts.pivot_outside_region >= counts.no_line.max(counts.order_defect) {
            SynthesisDefect::PivotOutsideRegion
        } else if counts.order_defect >= counts.no_line {
            SynthesisDefect::BranchOrOrder
        } else {
            SynthesisDefect::NoRealSolution
        }
    } else if counts.toggle >= counts.branch_or_order.max(counts.region) {
        SynthesisDefect::Toggle
    } else if counts.branch_or_order >= counts.region {
        SynthesisDefect::BranchOrOrder
    } else {
        SynthesisDefect::PivotOutsideRegion
    }
}

fn describe(c: &LinkTrackSearch) -> String {
    format!(
        "no link-track found: of {} track slopes, {} put the carriage off a bracket under the flap and {} run it out of order; of {} link pivots, {} lie outside the region or give a link point off the flap; {} had no solution; of {} pairs, {} fall below the minimum transmission angle, {} change branch or turn back, {} cut a section or the trailing edge",
        c.slopes, c.carriage_off_bracket, c.order_defect, c.pivots, c.pivot_outside_region, c.no_line, c.pairs, c.toggle, c.branch_or_order, c.region
    )
}

impl FlapMechanism for LinkTrack {
    fn kind(&self) -> &'static str {
        KIND
    }

    fn input_range(&self) -> InputRange {
        InputRange {
            quantity: InputQuantity::Angle,
            stowed: 0.0,
            deployed: self.synthesis.link_rotation_rad[1].abs(),
        }
    }

    fn deflection_range_rad(&self) -> f64 {
        self.spec.landing.deflection_rad
    }

    /// Bisection on the link's turn (the flap turns monotonically with it, checked at
    /// synthesis).
    fn input_at_deflection(&self, deflection_rad: f64) -> Result<f64> {
        let travel = self.input_range().deployed;
        let deflection = |input: f64| self.loop_pose(input).map_or(f64::NAN, |p| p.flap.rotation.angle());
        let sense = self.spec.landing.deflection_rad.signum();
        Ok(flapwright_mechanism::shared::feasibility::parameter_at_deflection(
            travel,
            deflection,
            deflection_rad,
            sense,
        ))
    }

    fn deflection_at_input(&self, input: f64) -> Result<f64> {
        Ok(self.loop_pose(input)?.flap.rotation.angle())
    }

    /// The link's pivot A and the carriage's pin C.
    fn flap_attachments(&self) -> Vec<NamedPoint> {
        [("A", self.loop_.a), ("C", self.loop_.c)]
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
        let pose = self.loop_pose(input)?;
        let link = turn_about(self.loop_.o, self.sense * input);
        let points = [
            ("O", self.loop_.o, true),
            ("A", pose.a, false),
            ("C", pose.c, false),
            ("D", pose.flap * self.spec.flap_mass.centre_of_mass_stowed_m, false),
        ]
        .into_iter()
        .map(|(name, position, fixed)| NamedPoint { name, position, fixed })
        .collect();
        Ok(MechanismPose {
            deflection_rad: pose.flap.rotation.angle(),
            input,
            bodies: vec![pose.flap, link, Isometry2::identity()],
            flap: pose.flap,
            points,
        })
    }

    fn kinetostatics(&self, input: f64, load: &LoadCase) -> Result<Kinetostatics> {
        let pose = self.loop_pose(input)?;
        let l = &self.loop_;
        let fraction = self.input_range().fraction(input).clamp(0.0, 1.0);
        let wrench = FlapWrench::new(&self.spec.flap_mass, &pose.flap, load, fraction);
        // The track's push N n at C, square to the track; moments about A.
        let d = l.d.into_inner();
        let n = Vector2::new(-d.y, d.x);
        let line = pose.c - pose.a;
        let track_force = -wrench.moment_about(pose.a) / line.dot(&d);
        let pin: Vector2<f64> = -(n * track_force + wrench.force_n());
        // The link: the actuator's torque balances the pin's push about O, along the input.
        let torque = self.sense * cross(pose.a - l.o, pin);
        let (v_a, _, flap_rate) = l.rates(&pose);
        let (v_a, flap_rate) = (v_a * self.sense, flap_rate * self.sense);
        let velocity_of = |point: Point2<f64>| {
            let r = point - pose.a;
            v_a + Vector2::new(-r.y, r.x) * flap_rate
        };
        let torque_virtual_work = -wrench.power(velocity_of, flap_rate);
        Ok(Kinetostatics {
            input,
            deflection_rad: pose.flap.rotation.angle(),
            actuator_load: torque,
            actuator_load_virtual_work: torque_virtual_work,
            reactions: vec![
                ("A".into(), pin.norm()),
                ("C".into(), track_force),
                ("O".into(), pin.norm()),
            ],
            transmission_angle_rad: pose.transmission,
            health: PoseHealth {
                closure_residual_m: ((pose.c - pose.a).norm() - l.span).abs(),
                jacobian_condition_number: 1.0 / pose.transmission.sin().max(1e-300),
                distance_to_toggle_rad: pose.transmission,
            },
            actuator_torques: None,
            members: self.member_loads(pose.a, pin, pose.c, n * track_force),
        })
    }

    fn drawing_notes(&self) -> DrawingNotes {
        let s = &self.synthesis;
        let r = s.link_flap_pivot_m - s.link_pivot_m;
        let start = r.y.atan2(r.x);
        DrawingNotes {
            summary: format!(
                "link-track with rotary actuator at the link's pivot; link turns {:.1} deg, carriage runs {:.1} mm at {:.1} deg",
                s.link_rotation_rad[1].abs().to_degrees(),
                s.carriage_travel_m[1] * 1e3,
                s.track_slope_rad.to_degrees()
            ),
            dimensions: vec![
                ("O-A".into(), s.link_pivot_m, s.link_flap_pivot_m),
                ("track".into(), s.track_ends_m[0], s.track_ends_m[1]),
            ],
            arcs: vec![(
                "A about O".into(),
                s.link_pivot_m,
                r.norm(),
                start,
                start + s.link_rotation_rad[1],
            )],
        }
    }

    fn details(&self) -> serde_json::Value {
        serde_json::json!({
            "hardware": self.spec.hardware,
            "synthesis": self.synthesis,
        })
    }

    fn actuator(&self) -> Actuator {
        self.synthesis.actuator
    }

    /// The link, clamped to the rotary actuator's output at O, the track beam and the
    /// struts (see the `members` module).
    fn members(&self) -> Vec<Member> {
        self.member_list()
    }

    fn flap_mass(&self) -> Option<FlapMass> {
        Some(self.spec.flap_mass)
    }

    fn warnings(&self) -> Vec<String> {
        let mut warnings = Vec::new();
        if !self.synthesis.placement_clear {
            warnings.push("no default strut from the link's pivot or the track to the wing's lower skin kept clear of the structure and the flap at the sampled poses".into());
        }
        warnings
    }
}

/// The track's direction at a slope below the aft direction (station frame: x forward).
pub fn track_direction(slope_rad: f64) -> Unit<Vector2<f64>> {
    Unit::new_normalize(Vector2::new(-slope_rad.cos(), -slope_rad.sin()))
}

impl LinkTrackSpec {
    /// How the search weighs the actuator's load: under [`Self::design_loads`] with
    /// [`Self::load_weight`], or not at all without them.
    pub fn weighing(&self) -> Option<flapwright_mechanism::shared::objective::LoadWeighing> {
        (!self.design_loads.is_empty()).then(|| flapwright_mechanism::shared::objective::LoadWeighing {
            loads: self.design_loads.clone(),
            flap_mass: self.flap_mass,
            weight: self.load_weight,
            load_cap: None,
            mass: None,
        })
    }
}

#[cfg(test)]
mod topology_tests {
    use super::*;

    #[test]
    fn the_topology_names_the_links_sense_and_whether_it_turns_past_a_quarter_turn() {
        let t = LinkTrackTopology::of(-2.0, PivotPlace::TrailingEdgeBay, Vector2::new(-0.3, -0.9));
        assert_eq!(
            (t.turning, t.sweep, t.pivot, t.track),
            (
                TurningSense::Clockwise,
                LinkSweep::PastQuarterTurn,
                PivotPlace::TrailingEdgeBay,
                TrackRun::Aft
            )
        );
        let t = LinkTrackTopology::of(0.7, PivotPlace::OutsideWing, Vector2::new(0.4, 0.9));
        assert_eq!(
            (t.turning, t.sweep, t.track),
            (
                TurningSense::CounterClockwise,
                LinkSweep::WithinQuarterTurn,
                TrackRun::Forward
            )
        );
        assert_eq!(
            serde_json::to_value(t).unwrap(),
            serde_json::json!({"turning": "counter-clockwise", "sweep": "within-quarter-turn", "pivot": "outside-wing", "track": "forward"})
        );
    }
}
