//! The link-track's synthesis from three precision positions, and the search over its free
//! choices.
//!
//! - **The carriage on a straight track.** For a track direction d, the carriage point C
//!   of the flap whose three positions lie on one line along d solves two linear equations:
//!   (T_i C - C) x d = 0 for take-off and landing, i.e. ((R_i - I)^T m) · C = -m · t_i with
//!   m = (d_y, -d_x). The free choice is the track's slope.
//! - **The link.** For a fixed pivot O, the flap point A whose three positions lie on a
//!   circle about O solves two linear equations: |T_i A - O|² = |A - O|², i.e.
//!   2 (R_i^T (t_i - O) + O) · A = |O|² - |t_i - O|². The free choice is O.
//!
//! The search takes track directions round the circle and fixed pivots on a grid below
//! the wing, up the rear spar's web and across the trailing-edge bay behind it, keeps the
//! pairs whose carriage and link pivot sit on brackets under the flap or reaching forward
//! of its nose under the cove (a flap that mostly turns about a deep pole puts every
//! collinear carriage point and the link points of pivots in the bay there; the pins, the
//! track beam's line and the link's line are then checked out of the wing section (and the
//! link's out of the spars) over the whole deployment, the solids' radii and the brackets'
//! arms left to the interference check), reach the settings in order, stay above the minimum
//! transmission angle, keep the flap off the wing's trailing edge and the links out of the
//! sections, and picks the least costly: the fairing's depth (as the fairing stage measures
//! it) in flap chords plus, under the spec's load cases, the actuator's peak torque in
//! reference torques ([`flapwright_mechanism::shared::objective`]); without load cases,
//! the shallowest. Every rejection is counted ([`LinkTrackSearch`]).

use nalgebra::{Matrix2, Point2, Unit, Vector2};

use super::linkage::Loop;
use super::{LinkTrackSearch, LinkTrackSpec};
use flapwright_mechanism::shared::feasibility::{check_deployment, DeploymentRules, LoopSample};
use flapwright_mechanism::shared::geometry::turn_angle;
use flapwright_mechanism::shared::objective::LoadWeighing;
use flapwright_mechanism::shared::outline::boundary_distance;
use flapwright_mechanism::shared::precision::PrecisionPosition;
use flapwright_mechanism::SynthesisDefect;

/// Loop samples of the feasibility check over the deployment.
pub(super) const LOOP_SAMPLES: usize = 48;
/// Track directions tried: every 2.5 deg round the circle (the carriage's three positions
/// decide which way it runs; a flap that mostly turns puts the collinear points low
/// under it, running forward, or inside it, running steeply down aft).
const SLOPES: usize = 144;
/// Fixed-pivot grid: columns and rows.
const PIVOT_COLUMNS: usize = 12;
const PIVOT_ROWS: usize = 8;
/// Fixed pivots tried up the rear spar's web.
const WEB_ROWS: usize = 12;
/// Columns of fixed pivots across the trailing-edge bay (the web's the first) and rows in
/// each of the others.
const BAY_COLUMNS: usize = 6;
const BAY_ROWS: usize = 8;
/// Deepest bracket under the flap, fraction of its chord.
const MAX_BRACKET_DEPTH: f64 = 1.0;
/// Farthest a bracket on the flap reaches forward of its stowed nose, under the cove,
/// fraction of its chord. A flap that mostly turns (a deep pole, little Fowler motion per
/// degree) puts every collinear carriage point and most link points for pivots near the
/// rear spar ahead of its nose: on the transport scene with a 9 % shroud, none of the 72
/// track slopes gives a carriage under the flap that runs in order.
const FORWARD_REACH: f64 = 0.5;
/// Largest link rotation (rad).
const MAX_LINK_ROTATION_RAD: f64 = 150.0 * std::f64::consts::PI / 180.0;

/// A link: its fixed pivot O and its flap pin A (stowed).
pub(super) type LinkPair = (Point2<f64>, Point2<f64>);
/// A carriage: the track's direction and the carriage pin C (stowed).
pub(super) type CarriagePair = (Unit<Vector2<f64>>, Point2<f64>);

/// A feasible loop and what it measures.
#[derive(Debug, Clone, Copy)]
pub(super) struct Found {
    pub(super) loop_: Loop,
    /// Link rotation to take-off and landing (rad).
    pub(super) turns: [f64; 2],
    /// Sampled smallest transmission angle (rad).
    pub(super) min_transmission: f64,
    /// How far the actuator, the link pin and the carriage reach below the stowed
    /// sections' lower contour over the deployment (m).
    pub(super) depth: f64,
    /// The search's cost: the depth in flap chords, plus the actuator's peak torque under
    /// the load cases in reference torques when the spec has them
    /// ([`flapwright_mechanism::shared::objective`]).
    pub(super) cost: f64,
    /// The actuator's peak torque under the spec's load cases (N m, by virtual work), 0
    /// without them.
    pub(super) peak_load: f64,
    /// The largest miss from the followed motion (m), 0 without one.
    pub(super) follow_miss: f64,
}

/// The point whose three positions under `positions` lie on one line along `d`.
pub(super) fn carriage_point(positions: &[PrecisionPosition; 2], d: Vector2<f64>) -> Option<Point2<f64>> {
    let m = Vector2::new(d.y, -d.x);
    let mut rows = Matrix2::zeros();
    let mut rhs = Vector2::zeros();
    for (k, position) in positions.iter().enumerate() {
        let r = position.flap.rotation.to_rotation_matrix().into_inner() - Matrix2::identity();
        let row = r.transpose() * m;
        rows[(k, 0)] = row.x;
        rows[(k, 1)] = row.y;
        rhs[k] = -m.dot(&position.flap.translation.vector);
    }
    solve(rows, rhs)
}

/// The point whose three positions under `positions` lie on one circle about `o`.
pub(super) fn link_point(positions: &[PrecisionPosition; 2], o: Point2<f64>) -> Option<Point2<f64>> {
    let mut rows = Matrix2::zeros();
    let mut rhs = Vector2::zeros();
    for (k, position) in positions.iter().enumerate() {
        let r = position.flap.rotation.to_rotation_matrix().into_inner();
        let t = position.flap.translation.vector;
        let row = (r.transpose() * (t - o.coords) + o.coords) * 2.0;
        rows[(k, 0)] = row.x;
        rows[(k, 1)] = row.y;
        rhs[k] = o.coords.norm_squared() - (t - o.coords).norm_squared();
    }
    solve(rows, rhs)
}

fn solve(rows: Matrix2<f64>, rhs: Vector2<f64>) -> Option<Point2<f64>> {
    let scale = rows.abs().max();
    if scale.is_nan() || scale <= 0.0 || rows.determinant().abs() <= 1e-12 * scale * scale {
        return None;
    }
    let p = rows.try_inverse()? * rhs;
    p.iter().all(|v| v.is_finite()).then(|| Point2::from(p))
}

/// True when `p` hangs below the stowed flap on a bracket: within the flap's chord, between
/// 2 % and [`MAX_BRACKET_DEPTH`] of its chord below its lower surface, or on a bracket
/// reaching forward of its nose ([`ahead_of_nose`]).
fn on_bracket(spec: &LinkTrackSpec, p: Point2<f64>, flap_chord: f64) -> bool {
    spec.outline.flap.vertical_span(p.x).is_some_and(|(lo, _)| {
        let depth = lo - p.y;
        depth >= 0.02 * flap_chord && depth <= MAX_BRACKET_DEPTH * flap_chord
    }) || ahead_of_nose(spec, p, flap_chord)
}

/// True when `p` sits on a bracket reaching forward of the stowed flap's nose under the
/// cove (`003_...` Fig. 9: the carriage rides ahead of the flap): at most
/// [`FORWARD_REACH`] of the flap chord ahead of the nose, outside the wing section, between
/// 2 % and [`MAX_BRACKET_DEPTH`] of the flap chord below the wing's lower skin.
fn ahead_of_nose(spec: &LinkTrackSpec, p: Point2<f64>, flap_chord: f64) -> bool {
    let outline = &spec.outline;
    let Some((le, _, _)) = outline.flap_chord() else {
        return false;
    };
    p.x > le
        && p.x <= le + FORWARD_REACH * flap_chord
        && !outline.wing.inside(p)
        && outline.flap.vertical_span(p.x).is_none()
        && outline
            .depth_below(p)
            .is_some_and(|depth| depth >= 0.02 * flap_chord && depth <= MAX_BRACKET_DEPTH * flap_chord)
}

/// True when the carriage pin `p` can sit on the stowed flap: on a bracket under it, or
/// inside its section on a fitting at least 2 % of the chord below the upper surface (the
/// track then enters the flap through a slot in its lower skin, as the tracks of many
/// transport flaps do).
fn carriage_place(spec: &LinkTrackSpec, p: Point2<f64>, flap_chord: f64) -> bool {
    spec.outline
        .flap
        .vertical_span(p.x)
        .is_some_and(|(lo, hi)| p.y <= hi - 0.02 * flap_chord && lo - p.y <= MAX_BRACKET_DEPTH * flap_chord)
        || ahead_of_nose(spec, p, flap_chord)
}

/// Carriage candidates: (track direction, carriage point) for each direction whose carriage
/// can sit on the flap and runs along the track to take-off and further to landing.
pub(super) fn carriages(
    spec: &LinkTrackSpec,
    search: &mut LinkTrackSearch,
    flap_chord: f64,
) -> Vec<(Unit<Vector2<f64>>, Point2<f64>)> {
    let slopes: Vec<f64> = match spec.track_slope_rad {
        Some(slope) => vec![slope],
        None => (0..SLOPES)
            .map(|k| (-180.0 + 360.0 * k as f64 / SLOPES as f64).to_radians())
            .collect(),
    };
    let mut found = Vec::new();
    for slope in slopes {
        search.slopes += 1;
        match carriage(spec, slope, flap_chord) {
            Ok(pair) => found.push(pair),
            Err(Rejection::NoLine) => search.no_line += 1,
            Err(Rejection::OffBracket) => search.carriage_off_bracket += 1,
            Err(Rejection::Order) => search.order_defect += 1,
        }
    }
    found
}

/// Why a track slope or a fixed pivot gives no candidate.
pub(super) enum Rejection {
    /// The linear equations are singular.
    NoLine,
    /// The point is not where a bracket can hold it (or the pivot not where a support can).
    OffBracket,
    /// The carriage does not run aft in order.
    Order,
}

/// The carriage of track slope `slope` (rad): its direction and point, if the point can sit
/// on the flap and runs along the track to take-off and further to landing.
pub(super) fn carriage(
    spec: &LinkTrackSpec,
    slope: f64,
    flap_chord: f64,
) -> Result<(Unit<Vector2<f64>>, Point2<f64>), Rejection> {
    let positions = [spec.takeoff, spec.landing];
    let d = super::track_direction(slope);
    let c = carriage_point(&positions, d.into_inner()).ok_or(Rejection::NoLine)?;
    if !carriage_place(spec, c, flap_chord) {
        return Err(Rejection::OffBracket);
    }
    let travel = positions.map(|p| d.dot(&(p.flap * c - c)));
    if !(travel[0] > 0.0 && travel[1] > travel[0]) {
        return Err(Rejection::Order);
    }
    Ok((d, c))
}

/// The link of fixed pivot `o`: the pivot and its flap point, if the pivot lies below the
/// wing or in the trailing-edge bay and the flap point on a bracket under the flap or
/// ahead of its nose.
pub(super) fn link(
    spec: &LinkTrackSpec,
    o: Point2<f64>,
    flap_chord: f64,
) -> Result<(Point2<f64>, Point2<f64>), Rejection> {
    let outline = &spec.outline;
    let below = !outline.wing.inside(o) && outline.lower_envelope(o.x).is_none_or(|y| o.y < y);
    if !(below || on_web(outline, o)) {
        return Err(Rejection::OffBracket);
    }
    match link_point(&[spec.takeoff, spec.landing], o) {
        Some(a) if on_bracket(spec, a, flap_chord) => Ok((o, a)),
        Some(_) => Err(Rejection::OffBracket),
        None => Err(Rejection::NoLine),
    }
}

/// Fixed-pivot candidates with their link points: the given pivot, or a grid below the
/// wing from the cove lip to a flap chord ahead of it, 5 % to 60 % of the flap chord below
/// the lower surface, and pivots on the rear spar's web and across the trailing-edge bay
/// behind it (inside the skin with the actuator's reach to spare); each link point on a
/// bracket under the flap or reaching forward of its nose.
pub(super) fn links(
    spec: &LinkTrackSpec,
    search: &mut LinkTrackSearch,
    flap_chord: f64,
) -> Vec<(Point2<f64>, Point2<f64>)> {
    let outline = &spec.outline;
    let pivots: Vec<Point2<f64>> = match spec.link_pivot {
        Some(o) => vec![o],
        None => {
            let Some(lip) = outline.cove_lower_lip_x() else {
                return Vec::new();
            };
            let mut grid = Vec::new();
            for i in 0..PIVOT_COLUMNS {
                let x = lip + flap_chord * (-0.3 + 1.3 * i as f64 / (PIVOT_COLUMNS - 1) as f64);
                let Some(bottom) = outline.lower_envelope(x) else {
                    continue;
                };
                for j in 0..PIVOT_ROWS {
                    grid.push(Point2::new(
                        x,
                        bottom - flap_chord * (0.05 + 0.55 * j as f64 / (PIVOT_ROWS - 1) as f64),
                    ));
                }
            }
            // On the rear spar's web (`003_...` Fig. 6), clear of it by the actuator, and on
            // fittings across the trailing-edge bay behind it (ribs carry them as they carry
            // the web's): columns from the web aft to the cove's lower lip, each from the
            // lower to the upper skin less the actuator's reach.
            if let Some((face, _, _)) = outline.rear_web() {
                let inset = spec.hardware.jack_body_radius_m + spec.hardware.link_radius_m;
                let (front, back) = (face - inset, lip + inset);
                let columns = if front > back { BAY_COLUMNS } else { 1 };
                for i in 0..columns {
                    let x = front - (front - back) * i as f64 / (BAY_COLUMNS - 1) as f64;
                    let Some((lo, hi)) = outline.wing.vertical_span(x) else {
                        continue;
                    };
                    // A section too thin for the actuator has no room for it.
                    if hi - lo <= 2.0 * inset {
                        continue;
                    }
                    let rows = if i == 0 { WEB_ROWS } else { BAY_ROWS };
                    for j in 0..rows {
                        let y = lo + inset + (hi - lo - 2.0 * inset) * j as f64 / (rows - 1) as f64;
                        let o = Point2::new(x, y);
                        // Inside the skin with the actuator's reach to spare (not in the
                        // shroud, the lip or against the cove wall over the flap's nose).
                        if outline.wing.inside(o) && boundary_distance(&outline.wing, o) >= inset {
                            grid.push(o);
                        }
                    }
                }
            }
            grid
        }
    };
    let mut found = Vec::new();
    for o in pivots {
        search.pivots += 1;
        match link(spec, o, flap_chord) {
            Ok(pair) => found.push(pair),
            Err(Rejection::NoLine) => search.no_line += 1,
            Err(_) => search.pivot_outside_region += 1,
        }
    }
    found
}

/// Candidates from the followed station's flap attachments
/// ([`flapwright_mechanism::shared::follow::FollowedMotion::attachments`]): each as the
/// link's flap pin (its fixed pivot the centre of the pin's three positions) and as the
/// carriage (the track along its stowed-to-landing chord), where the search is free to
/// choose them. The same link-track scaled to this section moves the flap nearly as the
/// followed one does, and the grid may miss its basin.
pub(super) fn followed_seeds(spec: &LinkTrackSpec, flap_chord: f64) -> (Vec<LinkPair>, Vec<CarriagePair>) {
    let Some(follow) = &spec.follow else {
        return (Vec::new(), Vec::new());
    };
    let (takeoff, landing) = (spec.takeoff.flap, spec.landing.flap);
    let links = follow
        .attachments
        .iter()
        .filter(|_| spec.link_pivot.is_none())
        .filter_map(|&a| flapwright_mechanism::shared::precision::circle_centre(a, takeoff * a, landing * a))
        .filter_map(|o| link(spec, o, flap_chord).ok())
        .collect();
    let carriages = follow
        .attachments
        .iter()
        .filter(|_| spec.track_slope_rad.is_none())
        .filter_map(|&c| {
            // The slope whose carriage point lies nearest c: scanned 20 deg either side of
            // c's chord to landing by 0.05 deg (the point moves fast with the slope).
            let d = landing * c - c;
            let chord_slope = (-d.y).atan2(-d.x);
            let miss = |slope: f64| {
                carriage_point(
                    &[spec.takeoff, spec.landing],
                    super::track_direction(slope).into_inner(),
                )
                .map_or(f64::INFINITY, |p| (p - c).norm())
            };
            let slope = (-400..=400)
                .map(|k| chord_slope + (0.05 * k as f64).to_radians())
                .min_by(|a, b| miss(*a).total_cmp(&miss(*b)))?;
            carriage(spec, slope, flap_chord).ok()
        })
        .collect();
    (links, carriages)
}

/// True when the fixed pivot `o` sits in the trailing-edge bay behind the rear spar's web
/// (inside the wing section, ahead of the cove).
pub(super) fn on_web(outline: &flapwright_mechanism::shared::outline::StationOutline, o: Point2<f64>) -> bool {
    outline.wing.inside(o)
        && outline.rear_web().is_some_and(|(face, _, _)| o.x < face)
        && outline.cove_lower_lip_x().is_some_and(|lip| o.x > lip)
}

/// The loop of a link and a carriage if it moves the flap through the settings in order,
/// above the minimum transmission angle, clear of the trailing edge and the sections; its
/// cost weighs its torque by `weighing` (the spec's, built once per search) when given.
pub(super) fn check(
    spec: &LinkTrackSpec,
    weighing: Option<&LoadWeighing>,
    (o, a): (Point2<f64>, Point2<f64>),
    (d, c): (Unit<Vector2<f64>>, Point2<f64>),
) -> Result<Found, (SynthesisDefect, String)> {
    let loop_ = Loop::new(o, a, c, d).ok_or((
        SynthesisDefect::Toggle,
        "the flap's line from the link to the carriage stands square to the track when stowed".to_string(),
    ))?;
    let turns = [spec.takeoff, spec.landing].map(|p| turn_angle(o, a, p.flap * a));
    let ordered =
        turns[0] * turns[1] > 0.0 && turns[0].abs() < turns[1].abs() && turns[1].abs() <= MAX_LINK_ROTATION_RAD;
    if !ordered {
        return Err((
            SynthesisDefect::BranchOrOrder,
            format!(
                "the link turns {:.1} deg to take-off and {:.1} deg to landing: the settings are not reached in order",
                turns[0].to_degrees(),
                turns[1].to_degrees()
            ),
        ));
    }
    if on_web(&spec.outline, o) && !spec.outline.through_bay_only(o, a, spec.hardware.link_radius_m) {
        return Err((
            SynthesisDefect::PivotOutsideRegion,
            "the link from the spar web crosses the upper skin or the shroud when stowed".into(),
        ));
    }
    // Both settings on the stowed branch: the loop must put the carriage where they do.
    for (position, turn) in [spec.takeoff, spec.landing].iter().zip(turns) {
        let pose = loop_.at(turn).ok_or((
            SynthesisDefect::NoRealSolution,
            "the loop cannot close at a setting".to_string(),
        ))?;
        if (pose.c - position.flap * c).norm() > 1e-6 * loop_.span {
            return Err((
                SynthesisDefect::BranchOrOrder,
                "the loop reaches a setting on the other branch".into(),
            ));
        }
        let link_clear = if on_web(&spec.outline, o) {
            spec.outline.through_bay_only(o, pose.a, spec.hardware.link_radius_m)
        } else {
            !spec.outline.wing.segment_meets(o, pose.a)
        };
        if !link_clear {
            return Err((
                SynthesisDefect::PivotOutsideRegion,
                "the link cuts the wing section".into(),
            ));
        }
    }
    let rules = DeploymentRules {
        outline: &spec.outline,
        min_transmission_rad: spec.min_transmission_angle_rad,
        fixed_pivots: &[o],
        deflection_sense: spec.landing.deflection_rad.signum(),
        turn_sense: turns[1].signum(),
        driver: "link",
        may_dwell: false,
    };
    // The fairing's depth: how far the actuator at O, the link pin and the carriage reach
    // below the stowed sections' lower contour (as the fairing stage measures it).
    let hw = &spec.hardware;
    let below = |p: Point2<f64>, radius: f64| spec.outline.depth_below(p).map_or(0.0, |d| d + radius);
    // The motion first, the sections' queries for the depth only once it closes in order.
    let sampled: Vec<_> = (0..=LOOP_SAMPLES)
        .map(|k| {
            let phi = turns[1] * k as f64 / LOOP_SAMPLES as f64;
            (phi, loop_.at(phi))
        })
        .collect();
    let samples = sampled.iter().map(|&(phi, pose)| {
        pose.map(|pose| LoopSample {
            turn_rad: phi,
            flap: pose.flap,
            transmission_rad: pose.transmission,
            flap_rate: loop_.rates(&pose).2,
        })
    });
    let min_transmission = check_deployment(&rules, samples)?;
    let depth =
        sampled
            .iter()
            .filter_map(|(_, pose)| *pose)
            .fold(below(o, hw.jack_body_radius_m).max(0.0), |depth, pose| {
                depth
                    .max(below(pose.a, hw.link_radius_m))
                    .max(below(pose.c, hw.nut_radius_m))
            });
    // Brackets ahead of the flap's nose ride under the wing's lower skin: the pins (the link
    // pin and the carriage) must stay out of the wing section, the link's line clear of it
    // (or through the bay only, from the web) and of the spars, and the track beam's line
    // (stowed carriage to landing) under it. Lines and points here: the solids' radii and
    // the brackets' arms to the flap are the interference check's (it sweeps every solid).
    let outline = &spec.outline;
    let landing_c = loop_.at(turns[1]).map(|pose| pose.c).unwrap_or(c);
    if outline.wing.segment_meets(c, landing_c) || outline.wing.inside(c) || outline.wing.inside(landing_c) {
        return Err((
            SynthesisDefect::PivotOutsideRegion,
            "the track beam cuts the wing section".into(),
        ));
    }
    for pose in sampled.iter().filter_map(|(_, pose)| pose.as_ref()) {
        let link_clear = if on_web(outline, o) {
            outline.through_bay_only(o, pose.a, hw.link_radius_m)
        } else {
            !outline.wing.segment_meets(o, pose.a)
        } && !outline.structure.segment_meets(o, pose.a);
        if !link_clear || outline.wing.inside(pose.a) || outline.wing.inside(pose.c) {
            return Err((
                SynthesisDefect::PivotOutsideRegion,
                "the link or a bracket enters the wing section part way".into(),
            ));
        }
    }
    let flap_chord = spec.outline.flap_chord().map_or(1.0, |(_, _, chord)| chord);
    let mut peak_load = 0.0;
    let cost = match weighing {
        Some(weighing) => {
            let rotations: Vec<f64> = (0..=LOOP_SAMPLES)
                .map(|k| turns[1] * k as f64 / LOOP_SAMPLES as f64)
                .collect();
            let flap_at = |phi: f64| loop_.at(phi).map(|pose| pose.flap);
            let torques = weighing.body_torques(&rotations, turns[1], &flap_at);
            let peak = torques.iter().map(|t| t.unwrap_or(f64::INFINITY)).fold(0.0, f64::max);
            let poses: Vec<_> = rotations.iter().filter_map(|&phi| flap_at(phi)).collect();
            let reference = weighing.reference_force_n(&poses) * flap_chord;
            peak_load = peak;
            weighing.cost(depth, flap_chord, peak, reference)
        }
        None => depth / flap_chord,
    };
    // The followed station's motion, at the same drive fractions (the link's rotation over
    // its rotation to landing).
    let follow_miss = spec.follow.as_ref().map_or(0.0, |follow| {
        let points = flapwright_mechanism::shared::follow::miss_points(&spec.outline);
        follow.miss(&points, &|s| loop_.at(turns[1] * s).map(|pose| pose.flap))
    });
    let cost = cost + flapwright_mechanism::shared::follow::FOLLOW_WEIGHT * follow_miss / flap_chord;
    Ok(Found {
        loop_,
        turns,
        min_transmission,
        depth,
        cost,
        peak_load,
        follow_miss,
    })
}

/// Steps of the refinement: it halves its steps this many times at most.
const REFINEMENTS: usize = 6;

/// Grid candidates refined, the least costly of each basin (see [`refine_best`]). Twelve
/// find the transport's `ob-inner` a 28.6 kN m link at 35 deg where six found 58.2, at the
/// same study time; searched alone, its outboard neighbour's own choice then moved their
/// flap 2.8 mm from the wing (3 mm required): the stations of one flap now follow each
/// other (`flapwright_mechanism::shared::follow`), and the pair clears.
const REFINED_STARTS: usize = 12;

/// The [`REFINED_STARTS`] least costly grid candidates that lie apart (pivots a tenth of
/// the flap chord or track slopes 5 deg apart), each refined, least costly first: the cost
/// over the free choices has several basins, and the grid's best basin need not hold the
/// best refined mechanism. Empty without a feasible candidate.
pub(super) fn refine_best(
    spec: &LinkTrackSpec,
    weighing: Option<&LoadWeighing>,
    mut feasible: Vec<Found>,
    flap_chord: f64,
) -> Vec<Found> {
    feasible.sort_by(|a, b| a.cost.total_cmp(&b.cost));
    let mut starts: Vec<Found> = Vec::new();
    for found in feasible {
        let apart = starts.iter().all(|s: &Found| {
            (s.loop_.o - found.loop_.o).norm() > 0.1 * flap_chord || s.loop_.d.angle(&found.loop_.d) > 5f64.to_radians()
        });
        if apart {
            starts.push(found);
            if starts.len() == REFINED_STARTS {
                break;
            }
        }
    }
    let mut refined: Vec<Found> = starts
        .into_iter()
        .map(|start| refine(spec, weighing, start, flap_chord))
        .collect();
    refined.sort_by(|a, b| a.cost.total_cmp(&b.cost));
    refined
}

/// The candidates no other beats on both depth and peak load, and the least costly one
/// (`candidates` come least costly first; with a followed motion its cost also weighs the
/// miss): the [`TRADE_CANDIDATES`] least costly of them, shallowest first. The trade
/// between the fairing and the actuator a user may pick from, the chosen one always in it.
pub(super) fn non_dominated(candidates: Vec<Found>) -> Vec<Found> {
    let dominates = |a: &Found, b: &Found| {
        a.depth <= b.depth && a.peak_load <= b.peak_load && (a.depth < b.depth || a.peak_load < b.peak_load)
    };
    let mut front: Vec<Found> = candidates
        .iter()
        .enumerate()
        .filter(|&(k, c)| k == 0 || !candidates.iter().any(|o| dominates(o, c)))
        .map(|(_, c)| *c)
        .collect();
    front.sort_by(|a, b| a.cost.total_cmp(&b.cost));
    front.dedup_by(|a, b| (a.depth - b.depth).abs() < 1e-9 && (a.peak_load - b.peak_load).abs() < 1e-9);
    front.truncate(TRADE_CANDIDATES);
    front.sort_by(|a, b| a.depth.total_cmp(&b.depth));
    front
}

/// Non-dominated candidates kept for the report, at most.
pub const TRADE_CANDIDATES: usize = 8;

/// The best grid candidate refined by a compass search over the free choices (the fixed
/// pivot's two coordinates and the track's slope, each only when searched): a step either
/// way along each is kept when its candidate is feasible and costs less; the steps halve
/// when none is, [`REFINEMENTS`] times. The grid's coarse steps make the chosen mechanism
/// jump between neighbouring inputs (a 0.2 deg change of the landing deflection moved the
/// transport's `ob-inner` link from 184 to 11 kN m); refined, it follows its inputs.
pub(super) fn refine(spec: &LinkTrackSpec, weighing: Option<&LoadWeighing>, best: Found, flap_chord: f64) -> Found {
    let l = &best.loop_;
    let mut x = [l.o.x, l.o.y, (-l.d.y).atan2(-l.d.x)];
    let free = [
        spec.link_pivot.is_none(),
        spec.link_pivot.is_none(),
        spec.track_slope_rad.is_none(),
    ];
    let mut steps = [0.05 * flap_chord, 0.05 * flap_chord, 1.25f64.to_radians()];
    let mut best = best;
    let evaluate = |x: [f64; 3]| -> Option<Found> {
        let pivot = link(spec, Point2::new(x[0], x[1]), flap_chord).ok()?;
        let track = carriage(spec, x[2], flap_chord).ok()?;
        check(spec, weighing, pivot, track).ok()
    };
    for _ in 0..REFINEMENTS {
        loop {
            let mut improved = false;
            for axis in (0..3).filter(|&k| free[k]) {
                for sign in [-1.0, 1.0] {
                    let mut trial = x;
                    trial[axis] += sign * steps[axis];
                    if let Some(found) = evaluate(trial) {
                        if found.cost < best.cost {
                            best = found;
                            x = trial;
                            improved = true;
                        }
                    }
                }
            }
            if !improved {
                break;
            }
        }
        steps = steps.map(|step| 0.5 * step);
    }
    best
}
