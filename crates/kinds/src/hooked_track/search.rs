//! The hooked-track's synthesis from two precision positions (stowed, landing) and the
//! search over its free choices.
//!
//! For a forward carriage point F and an aft roller point G on brackets under the flap and
//! a lead-in fraction of the stroke, the rail is the line from F to its landing place
//! (d = (T F - F) / |T F - F|) and the hook the circle tangent to the lead-in at
//! G1 = G + s1 d through T G: with w = T G - G1 and n the rail's normal,
//! |G1 + ρ n - T G|² = ρ² gives ρ = |w|² / (2 w · n), linear in the one unknown. Both
//! settings are then met exactly (landing at F on the rail and at G on the hook); take-off
//! is not a precision position and its miss is reported.
//!
//! The search takes F and G on grids of brackets and the lead-in on a grid of fractions,
//! keeps the rails that stay out of the sections and reach landing on one branch with the
//! flap turning forwards only, above the minimum transmission angle and off the wing's
//! trailing edge, whose wing-fixed solids keep clear of the moving flap (the rail, the screw
//! and the jack body, placed ahead of the carriage or behind the rail, set back along the
//! rail's line as far as four jack lengths; the struts placed where they clear: the
//! `clearance` module), and picks the one with the least fairing depth (as the fairing stage
//! measures it) plus take-off miss ([`Found::cost`]). Every rejection is counted ([`HookedTrackSearch`]).
//!
//! Branch and bound: [`prepare`] runs the quick tests and bounds a rail's cost from below
//! by what it knows before the deployment is sampled (the depth of the rail's ends and of
//! the roller stowed and at landing, all part of the final depth, plus the exact take-off
//! miss); [`check`] samples the deployment only for rails whose bound can still beat the
//! best found, so the choice is the exhaustive search's (on the transport scene's
//! outboard station 26 100 of the 65 500 candidates that pass the quick tests are
//! checked; 23 900 of them fail in their motion, most at their landing pose, found before
//! the sections are queried).

use nalgebra::Point2;

use super::bodies::hook_centre_line;
use super::clearance::{place_struts, Clearance, Struts};
use super::rail::Rail;
use super::{HookedTrackSearch, HookedTrackSpec};
use flapwright_mechanism::shared::feasibility::{check_deployment, DeploymentRules, LoopSample};
use flapwright_mechanism::shared::follow::FOLLOW_WEIGHT;
use flapwright_mechanism::shared::outline::FlapPoint;
use flapwright_mechanism::SynthesisDefect;

/// Samples of the deployment in the feasibility check.
pub(super) const RAIL_SAMPLES: usize = 48;
/// Forward carriage: chord fractions from the flap's leading edge.
const FORWARD_FRACTIONS: [f64; 8] = [0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4];
/// Aft roller: chord fractions.
const AFT_FRACTIONS: [f64; 12] = [0.35, 0.4, 0.45, 0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9];
/// Bracket depths below the flap's lower surface, fractions of its chord, for the carriage
/// and the roller alike (their fitting's line sets the transmission). The rail runs through
/// the carriage and must stay under the turning flap (see the `clearance` module): its aft
/// part lies under the flap's aft part, which comes down onto it as the flap turns, so on
/// the shipped scenes only brackets a third to two thirds of a chord deep keep it clear.
const DEPTHS: [f64; 9] = [0.02, 0.05, 0.1, 0.15, 0.25, 0.35, 0.45, 0.55, 0.7];
/// Places for the screw jack on the rail's line each way: next to the carriage (ahead) or
/// to the rail's aft end (behind), then set back by one jack-body length at a time.
const JACK_SETBACKS: usize = 5;
/// Lead-in fractions of the stroke.
const LEADS: [f64; 9] = [0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.5];
/// The shortest fitting from the carriage to the roller, fraction of the flap chord: a
/// shorter one turns the flap fast for its stroke and holds it with little lever.
const MIN_SPAN: f64 = 0.2;
/// How close the sampled roller must come to its landing place, fraction of the rail's
/// span (the fitting from the carriage to the roller).
const LANDING_MATCH: f64 = 1e-6;
/// The hook's radius, fractions of the flap chord.
const HOOK_RADIUS: (f64, f64) = (0.05, 20.0);

/// A feasible rail and what it measures.
#[derive(Debug, Clone, Copy)]
pub(super) struct Found {
    pub(super) rail: Rail,
    /// The screw jack's mount on the rail's line (m): ahead of the stowed carriage,
    /// pushing, or behind the rail's aft end, pulling, where the flap would pass through a
    /// jack ahead.
    pub(super) mount: Point2<f64>,
    /// Sampled smallest transmission angle (rad).
    pub(super) min_transmission: f64,
    /// How far the rail, the hook, the pins and the jack reach below the stowed sections'
    /// lower contour (m).
    pub(super) depth: f64,
    /// Largest distance at F and G between the flap at the take-off deflection and the
    /// take-off setting (m).
    pub(super) takeoff_miss: f64,
    /// The largest miss from the followed station's motion (m), 0 without one.
    pub(super) follow_miss: f64,
    /// Where the struts stand, clear of the flap.
    pub(super) struts: Struts,
}

impl Found {
    /// What the search minimises: the fairing's depth plus the take-off miss, a metre of
    /// either as bad as a metre of the other (the lead-in is the one choice that moves
    /// the take-off pose; F and G mostly set the depth), plus the miss from a followed
    /// station's motion at [`FOLLOW_WEIGHT`] (in flap chords against the depth in flap
    /// chords, as the link-track's and the four-bar's searches weigh it).
    pub(super) fn cost(&self) -> f64 {
        self.depth + self.takeoff_miss + FOLLOW_WEIGHT * self.follow_miss
    }
}

/// The largest miss (m) of `rail`'s flap from the followed motion of `spec`, at the same
/// fractions of the stroke; 0 without one.
fn follow_miss(spec: &HookedTrackSpec, rail: &Rail, points: &[Point2<f64>]) -> f64 {
    spec.follow.as_ref().map_or(0.0, |follow| {
        follow.miss(points, &|fraction| {
            rail.at(fraction * rail.stroke_m).map(|pose| pose.flap)
        })
    })
}

/// The first stroke of `rail` where the flap reaches `deflection_rad` (the flap holds its
/// deflection over the lead-in and turns forwards on the hook).
pub(super) fn stroke_at_deflection(spec: &HookedTrackSpec, rail: &Rail, deflection_rad: f64) -> f64 {
    rail.stroke_at_deflection(deflection_rad, spec.landing.deflection_rad.signum())
}

/// The first stroke of `rail` where the flap reaches the take-off deflection, and the miss
/// there at F and G.
pub(super) fn takeoff(spec: &HookedTrackSpec, rail: &Rail) -> (f64, f64) {
    let stroke = stroke_at_deflection(spec, rail, spec.takeoff.deflection_rad);
    let miss = rail.at(stroke).map_or(f64::INFINITY, |pose| {
        [rail.f, rail.g]
            .iter()
            .map(|p| (pose.flap * p - spec.takeoff.flap * p).norm())
            .fold(0.0, f64::max)
    });
    (stroke, miss)
}

/// Attachment candidates: the given point, or a grid of brackets at `fractions`.
fn attachments(
    spec: &HookedTrackSpec,
    given: Option<Point2<f64>>,
    fractions: &[f64],
    depths: &'static [f64],
) -> Vec<Point2<f64>> {
    match given {
        Some(p) => vec![p],
        None => fractions
            .iter()
            .flat_map(|&chord_fraction| {
                depths.iter().filter_map(move |&depth_fraction| {
                    spec.outline.flap_point(FlapPoint {
                        chord_fraction,
                        depth_fraction,
                    })
                })
            })
            .collect(),
    }
}

/// Every (F, G, lead-in fraction) the search tries: each carriage point with each roller
/// point and each lead-in, with what the depth of each point alone gives the bound (the
/// rail's ends depend on F alone, the roller's stowed and landing places on G alone: worked
/// out once per point, not once per triple).
pub(super) struct Candidates {
    forward: Vec<Attachment>,
    aft: Vec<Attachment>,
    leads: Vec<f64>,
    /// Where a follower's miss from the followed motion is measured (stowed flap points).
    miss_points: Vec<Point2<f64>>,
}

/// A bracket's pin (m) and the depth below the sections (m) it alone gives a rail.
type Attachment = (Point2<f64>, f64);

impl Candidates {
    pub(super) fn of(spec: &HookedTrackSpec) -> Self {
        let hw = &spec.hardware;
        let landing = spec.landing.flap;
        let below = |p: Point2<f64>, radius: f64| spec.outline.depth_below(p).map_or(0.0, |depth| depth + radius);
        // A follower also tries the followed station's carriage and roller where the same
        // places of this flap section are: the same rail scaled to this section moves the flap
        // nearly as the followed one does, and the grid may miss it.
        let seeds = |given: Option<Point2<f64>>, which: usize| -> Vec<Point2<f64>> {
            match (&spec.follow, given) {
                (Some(follow), None) => follow.attachments.get(which).copied().into_iter().collect(),
                _ => Vec::new(),
            }
        };
        let forward = attachments(spec, spec.forward_attachment, &FORWARD_FRACTIONS, &DEPTHS)
            .into_iter()
            .chain(seeds(spec.forward_attachment, 0))
            .map(|f| {
                let [start, end] = rail_ends_of(f, landing * f, hw.nut_radius_m);
                (f, below(start, hw.link_radius_m).max(below(end, hw.link_radius_m)))
            })
            .collect();
        let aft = attachments(spec, spec.aft_attachment, &AFT_FRACTIONS, &DEPTHS)
            .into_iter()
            .chain(seeds(spec.aft_attachment, 1))
            .map(|g| (g, below(g, hw.nut_radius_m).max(below(landing * g, hw.nut_radius_m))))
            .collect();
        let leads = spec.lead_fraction.map_or(LEADS.to_vec(), |l| vec![l]);
        let miss_points = if spec.follow.is_some() {
            flapwright_mechanism::shared::follow::miss_points(&spec.outline)
        } else {
            Vec::new()
        };
        Self {
            forward,
            aft,
            leads,
            miss_points,
        }
    }

    pub(super) fn len(&self) -> usize {
        self.forward.len() * self.aft.len() * self.leads.len()
    }

    /// The `index`-th triple (F outermost, the lead-in innermost) with its two depths.
    fn at(&self, index: usize) -> (Attachment, Attachment, f64) {
        let per_forward = self.aft.len() * self.leads.len();
        let (fi, rest) = (index / per_forward, index % per_forward);
        let (gi, li) = (rest / self.leads.len(), rest % self.leads.len());
        (self.forward[fi], self.aft[gi], self.leads[li])
    }
}

/// A rail through the quick tests, and a lower bound of its cost: what the search checks
/// in full only while the bound can still beat the best rail found.
#[derive(Debug, Clone, Copy)]
pub(super) struct Prepared {
    rail: Rail,
    /// The take-off miss (m), part of the bound and of the cost.
    takeoff_miss: f64,
    /// The miss from the followed motion (m), part of the bound and of the cost.
    follow_miss: f64,
    /// The depth of the rail's ends and of the roller stowed and at landing below the
    /// sections (all part of [`Found::depth`]) plus the take-off miss: at most
    /// [`Found::cost`].
    pub(super) lower_bound: f64,
}

/// The quick tests of the `index`-th candidate's rail (through F and G with its lead-in):
/// the span, the rail and its hook.
pub(super) fn prepare(
    spec: &HookedTrackSpec,
    candidates: &Candidates,
    index: usize,
    flap_chord: f64,
    search: &mut HookedTrackSearch,
) -> Result<Prepared, (SynthesisDefect, String)> {
    let ((f, forward_depth), (g, aft_depth), lead) = candidates.at(index);
    if (g - f).norm() < MIN_SPAN * flap_chord {
        search.no_hook += 1;
        return Err((
            SynthesisDefect::PivotOutsideRegion,
            format!(
                "the carriage and the roller are {:.0} mm apart, less than {:.0} % of the flap chord",
                (g - f).norm() * 1e3,
                MIN_SPAN * 100.0
            ),
        ));
    }
    let landing = spec.landing.flap;
    let stroke = (landing * f - f).norm();
    let rail = Rail::new(f, g, landing * f, landing * g, lead * stroke).ok_or_else(|| {
        search.no_hook += 1;
        (
            SynthesisDefect::NoRealSolution,
            "no rail: the flap's line stands square to the rail, or the roller needs no hook".to_string(),
        )
    })?;
    if rail.radius_m < HOOK_RADIUS.0 * flap_chord || rail.radius_m > HOOK_RADIUS.1 * flap_chord {
        search.hook_radius += 1;
        return Err((
            SynthesisDefect::PivotOutsideRegion,
            format!(
                "the hook's radius {:.0} mm lies outside {:.0}-{:.0} mm",
                rail.radius_m * 1e3,
                HOOK_RADIUS.0 * flap_chord * 1e3,
                HOOK_RADIUS.1 * flap_chord * 1e3
            ),
        ));
    }
    // Whether the rail cuts the sections is left to `check`: a long segment's test costs
    // more than the bound, and most rails are pruned by their bound before it matters.
    // The depth of the rail's ends (padded by the link's radius) and of the roller stowed
    // and at landing (by the nut's), worked out per point by `Candidates`.
    let depth = forward_depth.max(aft_depth).max(0.0);
    // The deployment check takes the roller's landing place from the sampled pose, which
    // meets the exact one to 1e-6 of the span (its `reached` test): the bound gives that
    // much away, so that it stays at most the cost.
    let takeoff_miss = takeoff(spec, &rail).1;
    let follow_miss = follow_miss(spec, &rail, &candidates.miss_points);
    Ok(Prepared {
        rail,
        takeoff_miss,
        follow_miss,
        lower_bound: depth + takeoff_miss + FOLLOW_WEIGHT * follow_miss - LANDING_MATCH * rail.span,
    })
}

/// The rail's ends, padded by the nut: from the stowed carriage to its landing place.
fn rail_ends(spec: &HookedTrackSpec, rail: &Rail) -> [Point2<f64>; 2] {
    padded(rail.f, rail.d.into_inner(), rail.stroke_m, spec.hardware.nut_radius_m)
}

/// The ends of the rail from `f` to `f_landing`, padded by `nut_m` at each end: those of
/// [`Rail::new`]'s rail through them, to the bit.
fn rail_ends_of(f: Point2<f64>, f_landing: Point2<f64>, nut_m: f64) -> [Point2<f64>; 2] {
    let run = f_landing - f;
    padded(f, nalgebra::Unit::new_normalize(run).into_inner(), run.norm(), nut_m)
}

fn padded(f: Point2<f64>, d: nalgebra::Vector2<f64>, stroke_m: f64, nut_m: f64) -> [Point2<f64>; 2] {
    [f - d * nut_m, f + d * (stroke_m + nut_m)]
}

/// True where the segment `a`-`b` cuts the wing, the structure or the stowed flap.
fn fixed_blocked(spec: &HookedTrackSpec, a: Point2<f64>, b: Point2<f64>) -> bool {
    let outline = &spec.outline;
    outline.wing.segment_meets(a, b) || outline.structure.segment_meets(a, b) || outline.flap.segment_meets(a, b)
}

/// The rest of the check of a rail `prepare` let through: the rail clear of the sections,
/// the deployment sampled (branch,
/// order, transmission, trailing edge), the hook clear of the sections, the rail, the screw
/// jack and the struts clear of the moving flap (`clearance`), the depth.
pub(super) fn check(
    spec: &HookedTrackSpec,
    prepared: &Prepared,
    search: &mut HookedTrackSearch,
) -> Result<Found, (SynthesisDefect, String)> {
    let rail = prepared.rail;
    let (f, g) = (rail.f, rail.g);
    let landing = spec.landing.flap;
    let stroke = rail.stroke_m;
    let hw = &spec.hardware;
    let d = rail.d.into_inner();
    let outline = &spec.outline;
    let rail_ends = rail_ends(spec, &rail);
    // The landing pose first: one pose rejects most rails (the other branch), before the
    // rail's own section test.
    let reached = rail
        .at(stroke)
        .is_none_or(|pose| (pose.g - landing * g).norm() <= LANDING_MATCH * rail.span);
    if !reached {
        search.branch_or_order += 1;
        return Err((
            SynthesisDefect::BranchOrOrder,
            "the roller reaches landing on the hook's other branch".into(),
        ));
    }
    if fixed_blocked(spec, rail_ends[0], rail_ends[1]) {
        search.rail_through_section += 1;
        return Err((
            SynthesisDefect::PivotOutsideRegion,
            "the rail cuts the wing, the structure or the stowed flap".into(),
        ));
    }
    let jack_offset = 0.5 * hw.jack_body_length_m + hw.nut_radius_m;
    let ahead = f - d * jack_offset;
    let behind = f + d * (stroke + jack_offset);
    let fixed_blocked = |a: Point2<f64>, b: Point2<f64>| fixed_blocked(spec, a, b);
    let rules = DeploymentRules {
        outline,
        min_transmission_rad: spec.min_transmission_angle_rad,
        // The jack sits ahead of the carriage on the rail's line: the interference check
        // keeps the flap off its body.
        fixed_pivots: &[],
        deflection_sense: spec.landing.deflection_rad.signum(),
        turn_sense: 1.0,
        driver: "stroke",
        may_dwell: true,
    };
    let below = |p: Point2<f64>, radius: f64| outline.depth_below(p).map_or(0.0, |depth| depth + radius);
    let mut depth = below(rail_ends[0], hw.link_radius_m)
        .max(below(rail_ends[1], hw.link_radius_m))
        .max(0.0);
    // The motion first (a few comparisons a sample), the sections' queries only for a rail
    // whose motion closes in order and reaches landing on the hook's right branch: most
    // rails fail in their motion.
    let strokes = stroke_samples(&rail);
    let sampled: Vec<_> = strokes.iter().map(|&s| rail.at(s)).collect();
    let samples = strokes.iter().zip(&sampled).map(|(&s, pose)| {
        pose.map(|pose| LoopSample {
            turn_rad: s,
            flap: pose.flap,
            transmission_rad: pose.transmission,
            flap_rate: rail.rates(&pose).1,
        })
    });
    let min_transmission = check_deployment(&rules, samples).inspect_err(|(defect, _)| match defect {
        SynthesisDefect::Toggle => search.toggle += 1,
        SynthesisDefect::BranchOrOrder => search.branch_or_order += 1,
        _ => search.region += 1,
    })?;
    // Every sample closed (the deployment check refuses a rail with a gap).
    let sampled: Vec<_> = sampled.into_iter().flatten().collect();
    let mut previous_g = g;
    let mut hook_blocked = false;
    for pose in &sampled {
        depth = depth.max(below(pose.g, hw.nut_radius_m));
        if pose.on_hook {
            hook_blocked |= fixed_blocked(previous_g, pose.g);
        }
        previous_g = pose.g;
    }
    if hook_blocked {
        search.rail_through_section += 1;
        return Err((
            SynthesisDefect::PivotOutsideRegion,
            "the hook cuts the wing, the structure or the stowed flap".into(),
        ));
    }
    let poses: Vec<_> = sampled.iter().map(|pose| pose.flap).collect();
    // The wing-fixed solids, with their radii, clear of the moving flap (see `clearance`).
    let clearance = Clearance::new(spec, poses);
    let mut blocked = |part: &str, (k, distance): (usize, f64), radius: f64| {
        search.flap_clearance += 1;
        (
            SynthesisDefect::PivotOutsideRegion,
            format!(
                "the {part} (radius {:.0} mm) comes {:.0} mm from the flap at {:.0} mm of the {:.0} mm stroke; it must keep {:.0} mm",
                radius * 1e3,
                (distance - radius).max(0.0) * 1e3,
                strokes[k] * 1e3,
                stroke * 1e3,
                (clearance.reach_m(radius) - radius) * 1e3,
            ),
        )
    };
    clearance
        .clear_of_flap(spec, rail_ends[0], rail_ends[1], hw.link_radius_m)
        .map_err(|at| blocked("rail", at, hw.link_radius_m))?;
    // The screw jack on the rail's line, pushing from ahead of the carriage or pulling from
    // behind the rail: the screw from the jack over the carriage's travel and the jack body
    // clear of the flap, the structure and the upper skin.
    let half = d * (0.5 * hw.jack_body_length_m);
    let screw_radius = 0.5 * hw.link_radius_m;
    type JackBlock = (&'static str, Option<(usize, f64)>, f64);
    let jack_clear = |mount: Point2<f64>| -> Result<(), JackBlock> {
        let far = if (rail_ends[1] - mount).norm() > (rail_ends[0] - mount).norm() {
            rail_ends[1]
        } else {
            rail_ends[0]
        };
        let (a, b) = (mount - half, mount + half);
        if !clearance.clear_of_wing(spec, a, b, hw.jack_body_radius_m) {
            return Err(("jack body", None, hw.jack_body_radius_m));
        }
        if !clearance.clear_of_wing(spec, mount, far, screw_radius) {
            return Err(("screw", None, screw_radius));
        }
        clearance
            .clear_of_flap(spec, a, b, hw.jack_body_radius_m)
            .map_err(|at| ("jack body", Some(at), hw.jack_body_radius_m))?;
        clearance
            .clear_of_flap(spec, mount, far, screw_radius)
            .map_err(|at| ("screw", Some(at), screw_radius))
    };
    // Ahead of the carriage, pushing, then behind the rail, pulling, each set back along
    // the line by whole jack-body lengths: the first where the flap's nose (ahead) or its
    // aft part (behind) passes the jack with room; of those clear, the shallowest.
    let setback = |k: usize| d * (k as f64 * hw.jack_body_length_m);
    let mut first_blocks: Vec<JackBlock> = Vec::new();
    let mut mount: Option<(Point2<f64>, f64)> = None;
    for place in (0..JACK_SETBACKS)
        .map(|k| ahead - setback(k))
        .chain((0..JACK_SETBACKS).map(|k| behind + setback(k)))
    {
        match jack_clear(place) {
            Ok(()) => {
                let lowest = below(place - half, hw.jack_body_radius_m).max(below(place + half, hw.jack_body_radius_m));
                if mount.is_none_or(|(_, best)| lowest < best) {
                    mount = Some((place, lowest));
                }
            }
            Err(block) => {
                if first_blocks.len() < 2 && (place == ahead || place == behind) {
                    first_blocks.push(block);
                }
            }
        }
    }
    let Some((mount, _)) = mount else {
        search.flap_clearance += 1;
        let say = |(part, at, radius): &JackBlock| match at {
            None => format!("its {part} comes within its radius and the margin of the structure or the upper skin"),
            Some((k, distance)) => format!(
                "its {part} comes {:.0} mm from the flap at {:.0} mm of stroke (must keep {:.0} mm)",
                (distance - radius).max(0.0) * 1e3,
                strokes[*k] * 1e3,
                (clearance.reach_m(*radius) - radius) * 1e3
            ),
        };
        let said: Vec<String> = first_blocks.iter().map(say).collect();
        return Err((
            SynthesisDefect::PivotOutsideRegion,
            format!(
                "no clear place for the screw jack on the rail's line, up to {} jack lengths ahead of the carriage or behind the rail: next to the carriage {}; next to the rail's aft end {}",
                JACK_SETBACKS - 1,
                said.first().map_or("-", String::as_str),
                said.get(1).map_or("-", String::as_str)
            ),
        ));
    };
    depth = depth
        .max(below(mount - half, hw.jack_body_radius_m))
        .max(below(mount + half, hw.jack_body_radius_m));
    let hook_line = hook_centre_line(&rail, landing * g);
    let struts = place_struts(spec, &clearance, rail_ends[0], &hook_line).map_err(|strut| {
        search.struts += 1;
        (
            SynthesisDefect::PivotOutsideRegion,
            format!(
                "no {strut} to the wing's lower skin{} keeps {:.0} mm beyond its radius from the structure and from the flap at every sampled pose",
                if strut == "strut-rail" { " or the rear spar's web" } else { "" },
                (clearance.reach_m(0.0)) * 1e3
            ),
        )
    })?;
    let found = Found {
        rail,
        mount,
        struts,
        min_transmission,
        depth,
        takeoff_miss: prepared.takeoff_miss,
        follow_miss: prepared.follow_miss,
    };
    // The branch and bound's premise, checked on every rail of every debug run (the
    // tests'): the bound never exceeds the cost.
    debug_assert!(
        found.cost() >= prepared.lower_bound,
        "bound {} above cost {}",
        prepared.lower_bound,
        found.cost()
    );
    Ok(found)
}

/// The strokes the deployment is sampled at: evenly from stowed to landing, with the end
/// of the lead-in among them.
pub(super) fn stroke_samples(rail: &Rail) -> Vec<f64> {
    let mut strokes: Vec<f64> = (0..=RAIL_SAMPLES)
        .map(|k| rail.stroke_m * k as f64 / RAIL_SAMPLES as f64)
        .collect();
    strokes.push(rail.lead_m);
    strokes.sort_by(f64::total_cmp);
    strokes
}
