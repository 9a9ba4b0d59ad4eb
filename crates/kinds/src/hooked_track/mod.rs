//! The hooked-track (Zaccai, Bertels & Vos `003_...` section 3, Figs. 6 and 10): a carriage
//! at the flap's forward pin F slides on a straight rail, driven along it by a screw jack
//! parallel to the rail; the flap's aft roller G runs first in a straight lead-in parallel to
//! the rail (the flap translates, `003_...` Fig. 17) and then in a hook, a circular arc that
//! turns the flap to its landing deflection. `003_...` models the straight part and the
//! hook as links; here they are the rails those links stand for, which give the same motion
//! and keep the roller's lead-in.
//!
//! Synthesis is motion generation for two precision positions, stowed and landing (the
//! `search` module): the rail runs from F to its landing place and the hook is the one circle
//! tangent to the lead-in through G's landing place. Take-off is not a precision position:
//! its miss is reported ([`HookedTrackSynthesis::takeoff_miss_m`]). The free choices, F, G
//! and the lead-in's share of the stroke, are the designer's or searched for the shallowest
//! mechanism plus take-off miss. Only mechanisms whose wing-fixed solids (the rail, the
//! screw, the jack body and the struts, with their radii) keep clear of the moving flap at
//! every sampled pose are kept (the `clearance` module: the interference check holds them
//! against the whole flap, not its slot); where none does, synthesis fails naming what
//! blocked.
//!
//! Pose in closed form (the `rail` module). Statics: the rail holds the carriage square to
//! itself and the screw pushes it along (Q d + N_F n at F); the lead-in holds G square to the
//! rail (N_G n), the hook along its radius (N_G u, u = (G - K) / |G - K|). Moments of the
//! flap about F give N_G = -M_F / ((G - F) x m) with m = n or u, then the force balance
//! Q = -(P + N_G m) · d and N_F = -(P + N_G m) · n. Virtual work, independently, from the
//! rail's velocity analysis.
//!
//! The support (rail and hook, fixed to the wing) is held by a truss of three pinned rods
//! and a tie where they clear (the `truss` module), else by two struts clamped to the skin;
//! the members and their loads are in the `members` module.

use nalgebra::{Isometry2, Point2, Vector2};
use serde::Serialize;

mod bodies;
mod clearance;
mod members;
mod rail;
mod search;
mod truss;

pub use flapwright_mechanism::shared::support_truss::{SupportRod, SupportTruss};

use rail::{Rail, RailPose};

use flapwright_mechanism::seam::{
    Actuator, Body, DrawingNotes, FlapMechanism, InputQuantity, InputRange, Joint, Kinetostatics, MechanismPose,
    NamedPoint, PoseHealth,
};
use flapwright_mechanism::shared::flap_load::{FlapMass, FlapWrench, LinkHardware};
use flapwright_mechanism::shared::geometry::cross;
use flapwright_mechanism::shared::load_case::LoadCase;
use flapwright_mechanism::shared::outline::StationOutline;
use flapwright_mechanism::shared::precision::PrecisionPosition;
use flapwright_mechanism::shared::screw_jack::{ScrewDrive, ScrewJack};
use flapwright_mechanism::{Error, Result, SynthesisDefect};

const KIND: &str = "hooked-track";

/// Rails checked in full at a time (in parallel) between updates of the search's bound:
/// large enough to keep two cores busy, small enough to stop soon after the best is found.
const SEARCH_BATCH: usize = 32;

/// The designer's choices for a hooked-track at one station (station frame, m).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HookedTrackSpec {
    /// Take-off: not a precision position; its miss is reported.
    pub takeoff: PrecisionPosition,
    /// Landing, where the deployment ends.
    pub landing: PrecisionPosition,
    /// The carriage's pin F on the flap, stowed; `None`: searched.
    pub forward_attachment: Option<Point2<f64>>,
    /// The roller's pin G on the flap, stowed; `None`: searched.
    pub aft_attachment: Option<Point2<f64>>,
    /// The lead-in's share of the stroke, in [0, 1); `None`: searched.
    pub lead_fraction: Option<f64>,
    /// Smallest transmission angle over the deployment (rad).
    pub min_transmission_angle_rad: f64,
    /// The flap share this station carries.
    pub flap_mass: FlapMass,
    /// The screw's thread and the shared drive.
    pub screw_drive: ScrewDrive,
    /// Solid sizes.
    pub hardware: LinkHardware,
    /// The station's sections.
    pub outline: StationOutline,
    /// The station's load cases, under which the support's truss is laid out (the `truss`
    /// module); empty: the rail and the hook on cantilevered struts.
    #[serde(skip)]
    pub design_loads: Vec<LoadCase>,
    /// The motion of the flap's station synthesised first, which this one follows: the
    /// search weighs its flap's miss from it (`flapwright_mechanism::shared::follow`).
    #[serde(skip)]
    pub follow: Option<flapwright_mechanism::shared::follow::FollowedMotion>,
}

/// The hooked-track's arrangement, the discrete choices its search spans: neighbouring
/// inputs whose designs differ in it are different mechanisms, whose figures may differ by
/// several times (issue 37's continuity: a jump the report must state).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct HookedTrackTopology {
    /// Which side of the rail's line the roller G runs, seen from the station's up.
    pub roller: RollerSide,
    /// Whether the screw jack pushes the carriage (mounted ahead of it) or pulls it (behind
    /// the rail's aft end).
    pub jack: JackSense,
}

/// Which side of the rail's line the hooked-track's roller runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum RollerSide {
    /// On the side of the rail's normal that points up (+y of the station frame).
    AboveRail,
    /// On the other side.
    BelowRail,
}

/// How a screw jack on the rail's line moves the carriage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum JackSense {
    /// Mounted ahead of the stowed carriage: the screw pushes it to landing.
    Pushing,
    /// Mounted behind the rail's aft end: the screw pulls it.
    Pulling,
}

impl HookedTrackTopology {
    /// The arrangement of a rail along `d` from `rail_start` with the carriage at `f`, the
    /// roller at `g` (stowed) and the jack at `mount`.
    fn of(d: Vector2<f64>, rail_start: Point2<f64>, f: Point2<f64>, g: Point2<f64>, mount: Point2<f64>) -> Self {
        // The rail's normal with a non-negative y (d's left normal when d points forward).
        let up = if d.x >= 0.0 {
            Vector2::new(-d.y, d.x)
        } else {
            Vector2::new(d.y, -d.x)
        };
        Self {
            roller: if (g - f).dot(&up) > 0.0 {
                RollerSide::AboveRail
            } else {
                RollerSide::BelowRail
            },
            jack: if (mount - rail_start).dot(&d) < 0.0 {
                JackSense::Pushing
            } else {
                JackSense::Pulling
            },
        }
    }
}

/// Counts of what the search rejected.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct HookedTrackSearch {
    /// Carriage, roller and lead-in triples tried.
    pub candidates: usize,
    /// ... with no rail or hook (the flap's line square to the rail, no hook needed, or
    /// the carriage and roller too close).
    pub no_hook: usize,
    /// ... whose hook is too tight or too flat.
    pub hook_radius: usize,
    /// ... whose rail or hook cuts the wing, the structure or the stowed flap.
    pub rail_through_section: usize,
    /// ... whose rail, screw or jack body (ahead of the carriage and behind the rail) comes
    /// nearer to the moving flap than its radius and the margin, or whose jack body or
    /// screw meets the structure or the upper skin (see the `clearance` module).
    pub flap_clearance: usize,
    /// ... with no strut from the rail or from the hook clear of the structure and the
    /// moving flap.
    pub struts: usize,
    /// ... that failed the deployment check, by defect: toggle, branch or order, region.
    pub toggle: usize,
    /// See [`Self::toggle`].
    pub branch_or_order: usize,
    /// See [`Self::toggle`].
    pub region: usize,
    /// ... not checked further: the depth of their rail's ends and roller and their
    /// take-off miss, known before the deployment check, already cost more than the best
    /// rail found (branch and bound: the choice is the exhaustive search's).
    pub pruned: usize,
    /// ... feasible.
    pub feasible: usize,
}

impl HookedTrackSearch {
    /// Adds another search's counts to these.
    fn add(&mut self, other: &Self) {
        self.candidates += other.candidates;
        self.no_hook += other.no_hook;
        self.hook_radius += other.hook_radius;
        self.rail_through_section += other.rail_through_section;
        self.flap_clearance += other.flap_clearance;
        self.struts += other.struts;
        self.toggle += other.toggle;
        self.branch_or_order += other.branch_or_order;
        self.region += other.region;
        self.pruned += other.pruned;
        self.feasible += other.feasible;
    }
}

/// What synthesis computed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HookedTrackSynthesis {
    /// The carriage's pin F on the flap, stowed (m).
    pub forward_attachment_m: Point2<f64>,
    /// The roller's pin G on the flap, stowed (m).
    pub aft_attachment_m: Point2<f64>,
    /// The rail's direction (unit, towards deployment).
    pub rail_direction: Vector2<f64>,
    /// The rail's slope below the aft direction (rad).
    pub rail_slope_rad: f64,
    /// The screw's stroke to landing (m).
    pub stroke_m: f64,
    /// The lead-in's stroke (m): the flap translates over it.
    pub lead_m: f64,
    /// The hook's centre K (m).
    pub hook_centre_m: Point2<f64>,
    /// The hook's radius (m).
    pub hook_radius_m: f64,
    /// Smallest transmission angle over the deployment (rad, sampled).
    pub min_transmission_angle_rad: f64,
    /// A certified lower bound on it between samples (rad).
    pub certified_min_transmission_angle_rad: f64,
    /// How far the mechanism reaches below the stowed sections' lower contour (m).
    pub depth_below_section_m: f64,
    /// Largest distance between the mechanism's flap and the landing position at F and G
    /// (m).
    pub precision_miss_m: f64,
    /// The stroke where the flap reaches the take-off deflection (m).
    pub takeoff_stroke_m: f64,
    /// Largest distance at F and G between the flap there and the take-off setting (m).
    pub takeoff_miss_m: f64,
    /// The rail's ends (m), stowed carriage first.
    pub rail_ends_m: [Point2<f64>; 2],
    /// The screw jack's mount on the rail's line (m): ahead of the stowed carriage
    /// (pushing) or behind the rail's aft end (pulling) where the flap would pass through
    /// a jack ahead.
    pub jack_mount_m: Point2<f64>,
    /// The screw, its length (m) and nominal nut speed (m/s).
    pub screw: ScrewJack,
    /// Screw length, the mount to the far end of the rail (m).
    pub screw_length_m: f64,
    /// Nominal nut speed (m/s).
    pub nominal_speed_mps: f64,
    /// Where the hook's strut leaves it (m).
    pub hook_strut_foot_m: Point2<f64>,
    /// Where the struts from the rail's forward end and from the hook meet the lower skin
    /// (the rail's, where none to the skin keeps clear, the rear spar's web) (m).
    pub strut_tops_m: [Point2<f64>; 2],
    /// The support's truss: its rods pinned at both ends, with a brace and a tie (the
    /// `truss` module; `strut_tops_m` are its struts' tops); None: the struts clamped to the
    /// skin, holding the rail and the hook as cantilevers (no brace or tie cleared, or no
    /// load cases were given).
    pub truss: Option<SupportTruss>,
    /// The arrangement chosen (see [`HookedTrackTopology`]).
    pub topology: HookedTrackTopology,
    /// What the search rejected.
    pub search: HookedTrackSearch,
    /// The station of the same flap whose motion this one followed, and the largest miss
    /// from it; `None` for the flap's first station.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub followed: Option<flapwright_mechanism::shared::follow::FollowedStation>,
}

/// A hooked-track synthesised for one station.
#[derive(Debug, Clone)]
pub struct HookedTrack {
    spec: HookedTrackSpec,
    synthesis: HookedTrackSynthesis,
    rail: Rail,
    /// The hook's centre line (`bodies::hook_centre_line`), found once: the members' loads
    /// ask for it at every sample.
    hook_line: Vec<Point2<f64>>,
    /// The vertex of `hook_line` where the hook's strut clamps it.
    hook_foot: usize,
    bodies: Vec<Body>,
    joints: Vec<Joint>,
}

/// What the flap's wrench needs at one pose (see the module doc's statics): the screw's
/// push Q along the rail, the rail's N_F square to it and the roller's N_G along m (N).
#[derive(Debug, Clone, Copy)]
struct Pushes {
    screw_n: f64,
    rail_n: f64,
    roller_n: f64,
    /// m: the rail's normal on the lead-in, the hook's radius on the hook.
    roller_direction: Vector2<f64>,
}

impl Pushes {
    fn at(rail: &Rail, pose: &RailPose, wrench: &FlapWrench) -> Self {
        let d = rail.d.into_inner();
        let n = rail.normal();
        // The roller's reaction: square to the lead-in, or along the hook's radius.
        let m = if pose.on_hook {
            (pose.g - rail.k) / rail.radius_m
        } else {
            n
        };
        let roller = -wrench.moment_about(pose.f) / cross(pose.g - pose.f, m);
        let rest = wrench.force_n() + m * roller;
        Self {
            screw_n: -rest.dot(&d),
            rail_n: -rest.dot(&n),
            roller_n: roller,
            roller_direction: m,
        }
    }

    /// The forces on the wing-fixed support: the carriage's on the rail at F, the
    /// roller's on the hook at G and the screw's reaction at the jack's `mount` (the jack
    /// body is mounted on the support, on the rail's line): together the flap's load.
    fn on_support(&self, rail: &Rail, pose: &RailPose, mount: Point2<f64>) -> [(Point2<f64>, Vector2<f64>); 3] {
        [
            (pose.f, -rail.normal() * self.rail_n),
            (pose.g, -self.roller_direction * self.roller_n),
            (mount, -rail.d.into_inner() * self.screw_n),
        ]
    }
}

fn failure(defect: SynthesisDefect, detail: String) -> Error {
    Error::Synthesis {
        kind: KIND,
        defect,
        detail,
    }
}

impl HookedTrack {
    /// Synthesises the rail and the hook through stowed and landing. Errors
    /// ([`Error::Synthesis`]): no feasible rail, with the dominant defect and the counts;
    /// given choices that fail, with their defect.
    pub fn synthesise(spec: HookedTrackSpec) -> Result<Self> {
        let flap_chord = flapwright_mechanism::shared::feasibility::settings_and_flap_chord(
            &[spec.takeoff, spec.landing],
            &spec.outline,
        )
        .map_err(|(defect, detail)| failure(defect, detail))?;
        use rayon::prelude::*;
        let mut counts = HookedTrackSearch::default();
        let candidates = search::Candidates::of(&spec);
        counts.candidates = candidates.len();
        // The quick tests of every candidate, in parallel, each with its own counts.
        let prepared: Vec<_> = (0..candidates.len())
            .into_par_iter()
            .map(|index| {
                let mut own = HookedTrackSearch::default();
                let outcome = search::prepare(&spec, &candidates, index, flap_chord, &mut own);
                (own, outcome)
            })
            .collect();
        let mut last_failure = None;
        // The last candidate the flap or the structure blocked, to show where.
        let mut last_clearance: Option<String> = None;
        let mut open = Vec::new();
        for (index, (own, outcome)) in prepared.into_iter().enumerate() {
            counts.add(&own);
            match outcome {
                Ok(rail) => open.push((index, rail)),
                Err(failure) => last_failure = Some(failure),
            }
        }
        // Branch and bound: the survivors checked in full in order of their cost's lower
        // bound, a batch at a time in parallel, until the next bound cannot beat the best
        // rail (the least cost, the first candidate among equal ones: the exhaustive
        // search's choice, whatever the threads and batches).
        // (The order of the candidates by their bound and index, sorted as indices into
        // `open`: a total order, so the unstable sort gives the one order.)
        let mut order: Vec<usize> = (0..open.len()).collect();
        order.sort_unstable_by(|&a, &b| {
            let ((i, x), (j, y)) = (&open[a], &open[b]);
            x.lower_bound.total_cmp(&y.lower_bound).then(i.cmp(j))
        });
        let mut best: Option<(usize, search::Found)> = None;
        let beats_best = |best: &Option<(usize, search::Found)>, index: usize, cost: f64| {
            best.as_ref()
                .is_none_or(|(b, found)| cost < found.cost() || (cost == found.cost() && index < *b))
        };
        let mut next = 0;
        while next < open.len() {
            let batch: Vec<&(usize, search::Prepared)> = order[next..]
                .iter()
                .map(|&k| &open[k])
                .take(SEARCH_BATCH)
                .take_while(|(index, rail)| beats_best(&best, *index, rail.lower_bound))
                .collect();
            if batch.is_empty() {
                break;
            }
            next += batch.len();
            let outcomes: Vec<_> = batch
                .par_iter()
                .map(|(index, rail)| {
                    let mut own = HookedTrackSearch::default();
                    (*index, search::check(&spec, rail, &mut own), own)
                })
                .collect();
            for (index, outcome, own) in outcomes {
                counts.add(&own);
                if own.flap_clearance + own.struts > 0 {
                    last_clearance = outcome.as_ref().err().map(|(_, detail)| detail.clone());
                }
                match outcome {
                    Ok(found) => {
                        counts.feasible += 1;
                        if beats_best(&best, index, found.cost()) {
                            best = Some((index, found));
                        }
                    }
                    Err(failure) => last_failure = Some(failure),
                }
            }
        }
        counts.pruned = open.len() - next;
        let best = best.map(|(_, found)| found);
        let Some(found) = best else {
            return Err(match (last_failure, counts.candidates) {
                (Some((defect, detail)), 1) => failure(defect, detail),
                _ => failure(
                    dominant(&counts),
                    match last_clearance {
                        Some(detail) => format!("{} (the last so blocked: {detail})", describe(&counts)),
                        None => describe(&counts),
                    },
                ),
            });
        };
        Self::build(spec, found, counts)
    }

    fn build(spec: HookedTrackSpec, found: search::Found, counts: HookedTrackSearch) -> Result<Self> {
        let rail = found.rail;
        let hw = &spec.hardware;
        let d = rail.d.into_inner();
        let attachments = [rail.f, rail.g];
        let miss_at = |pose: &RailPose, target: &Isometry2<f64>| {
            attachments
                .iter()
                .map(|p| (pose.flap * p - target * p).norm())
                .fold(0.0, f64::max)
        };
        let landing_pose = rail
            .at(rail.stroke_m)
            .ok_or_else(|| failure(SynthesisDefect::NoRealSolution, "the flap cannot reach landing".into()))?;
        let (takeoff_stroke, takeoff_miss) = search::takeoff(&spec, &rail);
        // Certified transmission: between samples h apart, sin μ falls at most at
        // (1 + 1 / sin μ) / ℓ + 1 / (|ρ| sin μ) per metre (d/ds of |(G - F) x (G - K)| / (ℓ |ρ|)
        // with |F'| = 1, |G'| <= 1 / sin μ; see `rail`).
        let step = rail.stroke_m / search::RAIL_SAMPLES as f64;
        let floor = (0.5 * found.min_transmission).sin();
        let rate = (1.0 + 1.0 / floor) / rail.span + 1.0 / (rail.radius_m * floor);
        let certified_sine = found.min_transmission.sin() - 0.5 * step * rate;
        let certified = if certified_sine >= floor {
            certified_sine.asin()
        } else {
            0.0
        };
        let rail_ends = [
            rail.f - d * hw.nut_radius_m,
            rail.f + d * (rail.stroke_m + hw.nut_radius_m),
        ];
        let hook_line = bodies::hook_centre_line(&rail, spec.landing.flap * rail.g);
        let hook_foot = found.struts.hook_foot;
        let truss = Self::lay_out_truss(&spec, &rail, rail_ends[0], hook_line[hook_foot], found.mount);
        let strut_tops_m = truss.map_or([found.struts.rail_top, found.struts.hook_top], |t| {
            [t.rods[0].top_m, t.rods[1].top_m]
        });
        let (screw, nominal_speed_mps) = spec.screw_drive.screw_for(rail.stroke_m);
        let synthesis = HookedTrackSynthesis {
            forward_attachment_m: rail.f,
            aft_attachment_m: rail.g,
            rail_direction: d,
            rail_slope_rad: (-d.y).atan2(-d.x),
            stroke_m: rail.stroke_m,
            lead_m: rail.lead_m,
            hook_centre_m: rail.k,
            hook_radius_m: rail.radius_m,
            min_transmission_angle_rad: found.min_transmission,
            certified_min_transmission_angle_rad: certified,
            depth_below_section_m: found.depth,
            precision_miss_m: miss_at(&landing_pose, &spec.landing.flap),
            takeoff_stroke_m: takeoff_stroke,
            takeoff_miss_m: takeoff_miss,
            rail_ends_m: rail_ends,
            jack_mount_m: found.mount,
            screw,
            screw_length_m: rail_ends
                .iter()
                .map(|end| (end - found.mount).norm())
                .fold(0.0, f64::max),
            nominal_speed_mps,
            hook_strut_foot_m: hook_line[hook_foot],
            strut_tops_m,
            truss,
            topology: HookedTrackTopology::of(d, rail_ends[0], rail.f, rail.g, found.mount),
            search: counts,
            followed: spec.follow.as_ref().map(|f| f.followed(found.follow_miss)),
        };
        let (bodies, joints) = bodies::bodies_and_joints(&spec, &synthesis, &rail, certified);
        Ok(Self {
            spec,
            synthesis,
            rail,
            hook_line,
            hook_foot,
            bodies,
            joints,
        })
    }

    /// The support's truss for the rail from `a` and the hook's clamp at `b` with the jack
    /// at `mount`, under the spec's load cases over the sampled deployment (the `truss`
    /// module).
    fn lay_out_truss(
        spec: &HookedTrackSpec,
        rail: &Rail,
        a: Point2<f64>,
        b: Point2<f64>,
        mount: Point2<f64>,
    ) -> Option<SupportTruss> {
        let poses: Vec<(f64, RailPose)> = search::stroke_samples(rail)
            .into_iter()
            .filter_map(|s| rail.at(s).map(|pose| (s, pose)))
            .collect();
        let loads: Vec<_> = spec
            .design_loads
            .iter()
            .flat_map(|load| {
                poses.iter().map(move |(s, pose)| {
                    let fraction = (s / rail.stroke_m).clamp(0.0, 1.0);
                    let wrench = FlapWrench::new(&spec.flap_mass, &pose.flap, load, fraction);
                    Pushes::at(rail, pose, &wrench).on_support(rail, pose, mount)
                })
            })
            .collect();
        let clearance = clearance::Clearance::new(spec, poses.iter().map(|(_, pose)| pose.flap).collect());
        truss::place_truss(spec, &clearance, a, b, &loads)
    }

    /// The designer's choices.
    pub fn spec(&self) -> &HookedTrackSpec {
        &self.spec
    }

    /// What synthesis computed.
    pub fn synthesis(&self) -> &HookedTrackSynthesis {
        &self.synthesis
    }

    /// The rail at stroke `input` (m).
    fn rail_pose(&self, input: f64) -> Result<RailPose> {
        if !input.is_finite() {
            return Err(Error::NonFinite {
                quantity: "hooked-track stroke",
                input_m: input,
            });
        }
        self.rail.at(input).ok_or(Error::Synthesis {
            kind: KIND,
            defect: SynthesisDefect::NoRealSolution,
            detail: format!("the roller cannot reach the hook at {:.1} mm of stroke", input * 1e3),
        })
    }
}

/// The defect most rejections had.
fn dominant(c: &HookedTrackSearch) -> SynthesisDefect {
    let region = c.hook_radius + c.rail_through_section + c.flap_clearance + c.struts + c.region;
    if c.no_hook >= region.max(c.toggle).max(c.branch_or_order) {
        SynthesisDefect::NoRealSolution
    } else if c.toggle >= region.max(c.branch_or_order) {
        SynthesisDefect::Toggle
    } else if c.branch_or_order >= region {
        SynthesisDefect::BranchOrOrder
    } else {
        SynthesisDefect::PivotOutsideRegion
    }
}

fn describe(c: &HookedTrackSearch) -> String {
    format!(
        "no hooked-track found: of {} carriage, roller and lead-in choices, {} have no rail or hook, {} a hook too tight or too flat, {} a rail or hook through a section; {} fall below the minimum transmission angle, {} change branch or turn back, {} pass the trailing edge or a pivot; {} keep their rail, screw or jack body too near the moving flap (or the jack in the structure), {} find no strut clear of the structure and the flap",
        c.candidates, c.no_hook, c.hook_radius, c.rail_through_section, c.toggle, c.branch_or_order, c.region, c.flap_clearance, c.struts
    )
}

impl FlapMechanism for HookedTrack {
    fn kind(&self) -> &'static str {
        KIND
    }

    fn input_range(&self) -> InputRange {
        InputRange {
            quantity: InputQuantity::Stroke,
            stowed: 0.0,
            deployed: self.rail.stroke_m,
        }
    }

    fn deflection_range_rad(&self) -> f64 {
        self.spec.landing.deflection_rad
    }

    /// The first stroke where the flap reaches `deflection_rad`, in closed form on the hook
    /// (the flap holds its deflection over the lead-in and turns forwards on the hook,
    /// checked at synthesis).
    fn input_at_deflection(&self, deflection_rad: f64) -> Result<f64> {
        Ok(search::stroke_at_deflection(&self.spec, &self.rail, deflection_rad))
    }

    fn deflection_at_input(&self, input: f64) -> Result<f64> {
        Ok(self.rail_pose(input)?.flap.rotation.angle())
    }

    /// The carriage's pin F and the roller G.
    fn flap_attachments(&self) -> Vec<NamedPoint> {
        [("F", self.rail.f), ("G", self.rail.g)]
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
        let pose = self.rail_pose(input)?;
        let carriage = Isometry2::translation(pose.f.x - self.rail.f.x, pose.f.y - self.rail.f.y);
        let points = [
            ("K", self.rail.k, true),
            ("F", pose.f, false),
            ("G", pose.g, false),
            ("D", pose.flap * self.spec.flap_mass.centre_of_mass_stowed_m, false),
        ]
        .into_iter()
        .map(|(name, position, fixed)| NamedPoint { name, position, fixed })
        .collect();
        Ok(MechanismPose {
            deflection_rad: pose.flap.rotation.angle(),
            input,
            bodies: vec![pose.flap, carriage, Isometry2::identity()],
            flap: pose.flap,
            points,
        })
    }

    fn kinetostatics(&self, input: f64, load: &LoadCase) -> Result<Kinetostatics> {
        let pose = self.rail_pose(input)?;
        let rail = &self.rail;
        let fraction = self.input_range().fraction(input).clamp(0.0, 1.0);
        let wrench = FlapWrench::new(&self.spec.flap_mass, &pose.flap, load, fraction);
        let d = rail.d.into_inner();
        let n = rail.normal();
        let Pushes {
            screw_n: screw_force,
            rail_n: rail_force,
            roller_n: roller,
            roller_direction: m,
        } = Pushes::at(rail, &pose, &wrench);
        // Virtual work: the screw's power balances the flap's wrench.
        let (_, flap_rate) = rail.rates(&pose);
        let velocity_of = |point: Point2<f64>| {
            let r = point - pose.f;
            d + Vector2::new(-r.y, r.x) * flap_rate
        };
        let force_virtual_work = -wrench.power(velocity_of, flap_rate);
        let closure = if pose.on_hook {
            ((pose.g - pose.f).norm() - rail.span)
                .abs()
                .max(((pose.g - rail.k).norm() - rail.radius_m).abs())
        } else {
            ((pose.g - pose.f).norm() - rail.span).abs()
        };
        Ok(Kinetostatics {
            input,
            deflection_rad: pose.flap.rotation.angle(),
            actuator_load: screw_force,
            actuator_load_virtual_work: force_virtual_work,
            reactions: vec![
                ("rail".into(), rail_force),
                ("F".into(), (d * screw_force + n * rail_force).norm()),
                ("G".into(), roller),
            ],
            transmission_angle_rad: pose.transmission,
            health: PoseHealth {
                closure_residual_m: closure,
                jacobian_condition_number: 1.0 / pose.transmission.sin().max(1e-300),
                distance_to_toggle_rad: pose.transmission,
            },
            actuator_torques: Some(self.synthesis.screw.torques(screw_force)),
            members: self.member_loads(pose.f, n * rail_force + d * screw_force, pose.g, m * roller),
        })
    }

    fn drawing_notes(&self) -> DrawingNotes {
        let s = &self.synthesis;
        let g1 = s.aft_attachment_m + s.rail_direction * s.lead_m;
        let (from, to) = (
            g1 - s.hook_centre_m,
            self.spec.landing.flap * s.aft_attachment_m - s.hook_centre_m,
        );
        let start = from.y.atan2(from.x);
        DrawingNotes {
            summary: format!(
                "hooked-track with screw jack along the rail; stroke {:.1} mm ({:.1} mm lead-in) at {:.1} deg, hook radius {:.1} mm",
                s.stroke_m * 1e3,
                s.lead_m * 1e3,
                s.rail_slope_rad.to_degrees(),
                s.hook_radius_m * 1e3
            ),
            dimensions: vec![
                ("rail".into(), s.rail_ends_m[0], s.rail_ends_m[1]),
                ("F-G".into(), s.forward_attachment_m, s.aft_attachment_m),
            ],
            arcs: vec![(
                "hook about K".into(),
                s.hook_centre_m,
                s.hook_radius_m,
                start,
                start + cross(from, to).atan2(from.dot(&to)),
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
        Actuator::ScrewJack {
            screw: self.synthesis.screw,
            screw_length_m: self.synthesis.screw_length_m,
            nominal_speed_mps: self.synthesis.nominal_speed_mps,
        }
    }

    /// The rail and the hook, each a cantilever, and the truss's tie and rods or the
    /// clamped struts (see the `members` module).
    fn members(&self) -> Vec<flapwright_mechanism::seam::Member> {
        self.member_list()
    }

    fn flap_mass(&self) -> Option<FlapMass> {
        Some(self.spec.flap_mass)
    }

    /// None: a strut that cannot be placed clear of the flap and the structure fails
    /// synthesis instead (it used to be a warning and a strut through the flap).
    fn warnings(&self) -> Vec<String> {
        Vec::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The roller's side is seen from the station's up whichever way the rail runs, and the
    /// jack pushes from ahead of the rail's start, pulls from behind it.
    #[test]
    fn the_topology_names_the_rollers_side_and_the_jacks_sense() {
        let p = Point2::new;
        let (f, start) = (p(0.0, 0.0), p(-0.01, 0.0));
        for d in [Vector2::new(0.8, -0.6), Vector2::new(-0.8, -0.6)] {
            let above = HookedTrackTopology::of(d, start, f, p(0.0, 0.3), start - d);
            assert_eq!(above.roller, RollerSide::AboveRail, "{d:?}");
            assert_eq!(above.jack, JackSense::Pushing);
            let below = HookedTrackTopology::of(d, start, f, p(0.0, -0.3), start + 2.0 * d);
            assert_eq!(below.roller, RollerSide::BelowRail, "{d:?}");
            assert_eq!(below.jack, JackSense::Pulling);
        }
    }
}
