//! Default placement of the parts a synthesised kind adds around its kinematic core: the
//! screw jack's mount and attachment, and the struts that hold fixed pivots to the wing's
//! lower skin. Each is searched over a few candidates for the first that keeps clear of
//! the wing, the structure and the flap at sampled poses of the deployment (the
//! interference check then certifies the whole deployment); the designer may give any of
//! them instead.

use nalgebra::{Isometry2, Point2};

use crate::shared::geometry::turn_about;
use crate::shared::objective::LoadWeighing;
use crate::shared::outline::StationOutline;
use crate::shared::rocker_drive::{mount_square_at_mid_travel, RockerDrive};

/// Poses sampled by the placement search.
pub const PLACEMENT_SAMPLES: usize = 16;

/// A screw's attachment on the turning body and its mount (stowed, m).
pub type AttachmentAndMount = (Point2<f64>, Point2<f64>);

/// A clear placement a weighed screw-jack search found: one of the trade between the
/// jack's depth and its load that the report lists (issue 37), so that a designer sees what
/// a deeper or a shallower jack would carry and may pick it by index.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct JackTradeCandidate {
    /// The screw's attachment on the body, stowed (m).
    pub attachment_m: Point2<f64>,
    /// The screw's mount (m).
    pub mount_m: Point2<f64>,
    /// How far the jack body and the screw's free end reach below the body's pivot over
    /// the deployment (m).
    pub depth_below_pivot_m: f64,
    /// The screw's peak force under the load cases (N).
    pub peak_load_n: f64,
    /// The search's cost ([`LoadWeighing::cost`] plus the short-stroke term and
    /// [`LoadWeighing::mass_cost`] of the screw and the horn).
    pub cost: f64,
    /// The search's choice.
    pub chosen: bool,
}

/// Trade candidates kept for the report, at most.
pub const JACK_TRADE_CANDIDATES: usize = 8;

impl PlacedJack {
    /// The jack at candidate `index` of its trade instead of the search's choice (marked
    /// chosen there); itself for `None`. Errors: [`crate::Error::NoSuchTradeCandidate`] of
    /// `kind` where the trade has no such candidate.
    pub fn picked(self, kind: &'static str, index: Option<usize>) -> crate::Result<Self> {
        let Some(index) = index else {
            return Ok(self);
        };
        let picked = *self.trade.get(index).ok_or(crate::Error::NoSuchTradeCandidate {
            kind,
            index,
            count: self.trade.len(),
        })?;
        let trade = self
            .trade
            .iter()
            .enumerate()
            .map(|(k, c)| JackTradeCandidate {
                chosen: k == index,
                ..*c
            })
            .collect();
        Ok(Self {
            attachment: picked.attachment_m,
            mount: picked.mount_m,
            clear: true,
            trade,
        })
    }
}

/// A placed screw jack.
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedJack {
    /// The screw's attachment on the body, stowed (m).
    pub attachment: Point2<f64>,
    /// The screw's mount (m).
    pub mount: Point2<f64>,
    /// False when no candidate kept clear (the first that transmits, or the first).
    pub clear: bool,
    /// The clear placements no other beats on both depth and load, and the chosen one: the
    /// [`JACK_TRADE_CANDIDATES`] least costly, shallowest first; empty without a weighing or
    /// when the designer gives the mount.
    pub trade: Vec<JackTradeCandidate>,
}

/// What the screw jack's solids measure (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JackSize {
    /// Screw outer radius.
    pub screw_radius_m: f64,
    /// Nut radius.
    pub nut_radius_m: f64,
    /// Jack body length.
    pub body_length_m: f64,
    /// Jack body radius.
    pub body_radius_m: f64,
}

/// A screw jack turning a body about `pivot` by `rotation_rad`: of the (attachment, mount)
/// pairs of the attachments at `fractions` of `arm` x `standoffs` (mounts square at
/// mid-travel, turned about the attachment) whose drive keeps the transmission angle above
/// `min_transmission_rad` and whose screw (as long as the longest stroke plus the nut) and
/// jack body keep `margin` clear of `outline` with the flap at `flap_at(ψ)` for sampled
/// body rotations ψ, the one of least cost: the depth its lowest point reaches in flap
/// chords, plus, with `weighing`, its peak screw force under the load cases in reference
/// forces ([`LoadWeighing::cost`]) and the mass of the screw and of a horn beyond the pivot
/// ([`LoadWeighing::mass_cost`]); without, the shallowest. With `weighing`, the grid's best
/// is then refined (a compass search): the attachment's fraction (within the fractions' range), the
/// standoff (within the standoffs') and the mount's turn moved while the cost falls, so
/// that the placement follows its inputs smoothly instead of stepping from one grid point
/// to the next. None when no pair is clear.
#[allow(clippy::too_many_arguments)]
pub fn screw_jack_placement(
    pivot: Point2<f64>,
    rotation_rad: f64,
    arm: (Point2<f64>, Point2<f64>),
    fractions: &[f64],
    standoffs: &[f64],
    min_transmission_rad: f64,
    size: &JackSize,
    margin: f64,
    outline: &StationOutline,
    flap_at: &dyn Fn(f64) -> Option<Isometry2<f64>>,
    weighing: Option<&LoadWeighing>,
) -> Result<(AttachmentAndMount, Vec<JackTradeCandidate>), Option<AttachmentAndMount>> {
    let rotations: Vec<f64> = (0..=PLACEMENT_SAMPLES)
        .map(|k| rotation_rad * k as f64 / PLACEMENT_SAMPLES as f64)
        .collect();
    let flap_poses: Option<Vec<Isometry2<f64>>> = rotations.iter().map(|&psi| flap_at(psi)).collect();
    let flap_poses = flap_poses.ok_or(None)?;
    // What the load asks of the body, the same for every candidate.
    let flap_chord = outline.flap_chord().map_or(1.0, |(_, _, chord)| chord);
    let loading = weighing.map(|w| {
        let torques = w.body_torques(&rotations, rotation_rad, flap_at);
        let peak_torque = torques.iter().flatten().copied().fold(0.0, f64::max);
        (w, torques, w.reference_force_n(&flap_poses), peak_torque)
    });
    let on_arm = |fraction: f64| arm.0 + (arm.1 - arm.0) * fraction;
    // One candidate: None where the drive cannot be built or transmits too little, else
    // the attachment, the mount and the cost where clear (None where not).
    let evaluate = |(fraction, standoff, turn): Placement| -> Option<(AttachmentAndMount, Option<Figures>)> {
        let attachment = on_arm(fraction);
        let square = mount_square_at_mid_travel(pivot, attachment, rotation_rad, standoff);
        let middle = turn_about(pivot, 0.5 * rotation_rad) * attachment;
        let mount = turn_about(middle, turn) * square;
        let drive = RockerDrive::try_new(pivot, mount, attachment).ok()?;
        let length = drive.stroke_at(0.0).max(drive.stroke_at(rotation_rad)) + size.nut_radius_m;
        let transmits = rotations.iter().all(|&psi| {
            drive
                .state(drive.stroke_at(psi))
                .is_ok_and(|state| state.transmission_angle_rad >= min_transmission_rad)
        });
        if !transmits {
            return None;
        }
        let clear = rotations.iter().zip(&flap_poses).all(|(&psi, pose)| {
            let Ok(state) = drive.state(drive.stroke_at(psi)) else {
                return false;
            };
            let along = (state.attachment - mount).normalize();
            let poses = std::slice::from_ref(pose);
            outline.capsule_clear(mount, mount + along * length, size.screw_radius_m, margin, poses)
                && outline.capsule_clear(
                    mount - along * (0.5 * size.body_length_m),
                    mount + along * (0.5 * size.body_length_m),
                    size.body_radius_m,
                    margin,
                    poses,
                )
        });
        if !clear {
            return Some(((attachment, mount), None));
        }
        // The shallowest: the lowest point of the jack body and of the screw's free end
        // over the deployment sets the fairing.
        let lowest = rotations
            .iter()
            .filter_map(|&psi| drive.state(drive.stroke_at(psi)).ok())
            .map(|state| (mount + (state.attachment - mount).normalize() * length).y)
            .fold(mount.y - size.body_radius_m - 0.5 * size.body_length_m, f64::min);
        let depth = pivot.y - lowest;
        let (cost, peak) = match &loading {
            Some((w, torques, reference, peak_torque)) => {
                // The screw's force: the body's torque times dψ/ds.
                let peak = rotations
                    .iter()
                    .zip(torques)
                    .map(|(&psi, torque)| {
                        let rate = drive
                            .state(drive.stroke_at(psi))
                            .map_or(f64::INFINITY, |state| state.rotation_per_stroke.abs());
                        torque.map_or(f64::INFINITY, |t| t * rate)
                    })
                    .fold(0.0, f64::max);
                let stroke = (drive.stroke_at(rotation_rad) - drive.stroke_at(0.0)).abs();
                let added_mass = w.mass.map_or(0.0, |mass| {
                    let horn = horn_length(pivot, arm, attachment);
                    mass.screw_mass_kg(length, peak) + mass.arm_mass_kg(horn, *peak_torque)
                });
                (
                    w.cost(depth, flap_chord, peak, *reference) + short_stroke_cost(stroke) + w.mass_cost(added_mass),
                    peak,
                )
            }
            None => (depth / flap_chord, f64::NAN),
        };
        Some(((attachment, mount), Some(Figures { cost, depth, peak })))
    };
    let candidate_of = |(attachment, mount): AttachmentAndMount, figures: Figures| JackTradeCandidate {
        attachment_m: attachment,
        mount_m: mount,
        depth_below_pivot_m: figures.depth,
        peak_load_n: figures.peak,
        cost: figures.cost,
        chosen: false,
    };
    let mut clear_candidates: Vec<JackTradeCandidate> = Vec::new();
    let mut fallback = None;
    let mut best: Option<(Placement, f64)> = None;
    // The screw square to the arm at mid-travel first, then turned either way about the
    // attachment (the ends' transmission angles shift by the turn) to reach below the wing;
    // up to 1.4 rad (80 deg) either way, where the transmission rule allows.
    for &fraction in fractions {
        for &standoff in standoffs {
            let equal = equal_pressure_turn(pivot, on_arm(fraction), rotation_rad, standoff);
            for turn in TURNS.into_iter().chain(equal) {
                let placement = (fraction, standoff, turn);
                let Some((pair, cost)) = evaluate(placement) else {
                    continue;
                };
                fallback = fallback.or(Some(pair));
                if let Some(figures) = cost {
                    clear_candidates.push(candidate_of(pair, figures));
                    if best.is_none_or(|(_, c)| figures.cost < c) {
                        best = Some((placement, figures.cost));
                    }
                }
            }
        }
    }
    let Some(best) = best else {
        return Err(fallback);
    };
    // Depth alone is not refined: it falls as the screw takes hold nearer the pivot, with a
    // shorter stroke and a larger force, which the grid's coarse steps keep in check.
    if loading.is_none() {
        return evaluate(best.0)
            .and_then(|(pair, cost)| cost.map(|_| (pair, Vec::new())))
            .ok_or(fallback);
    }
    // The refinement stays within the grid's standoffs and turns, and its fraction within
    // the fractions' range and a tenth of the arm of the grid's choice (the arm's far end
    // is the pivot, where a screw has no lever).
    let range = |values: &[f64]| {
        values.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        })
    };
    let (fraction, (low, high)) = (best.0 .0, range(fractions));
    let bounds = [
        (low.max(fraction - 0.1), high.min(fraction + 0.1)),
        range(standoffs),
        (-MAX_TURN, MAX_TURN),
    ];
    let cost_of = |placement: Placement| evaluate(placement).and_then(|(_, figures)| figures.map(|f| f.cost));
    let (placement, _) = refine(best, bounds, &cost_of);
    // The refined placement is clear (the search takes only clear ones).
    let Some((pair, Some(figures))) = evaluate(placement) else {
        return Err(fallback);
    };
    let chosen = JackTradeCandidate {
        chosen: true,
        ..candidate_of(pair, figures)
    };
    Ok((pair, jack_trade(chosen, clear_candidates)))
}

/// Length of the horn a screw attached at `attachment` needs (m): its distance from the
/// body's `pivot` where it lies beyond the pivot on the arm's line, away from the arm's
/// other end; 0 on the arm itself.
fn horn_length(pivot: Point2<f64>, arm: (Point2<f64>, Point2<f64>), attachment: Point2<f64>) -> f64 {
    let far = if (arm.0 - pivot).norm() >= (arm.1 - pivot).norm() {
        arm.0
    } else {
        arm.1
    };
    let out = attachment - pivot;
    if out.dot(&(far - pivot)) < 0.0 {
        out.norm()
    } else {
        0.0
    }
}

/// What a placement costs and measures.
#[derive(Debug, Clone, Copy)]
struct Figures {
    cost: f64,
    /// Below the pivot (m).
    depth: f64,
    /// The screw's peak force (N); NaN without a weighing.
    peak: f64,
}

/// The trade: `chosen` and the `candidates` no other beats on both depth and peak load,
/// the [`JACK_TRADE_CANDIDATES`] least costly, shallowest first.
fn jack_trade(chosen: JackTradeCandidate, candidates: Vec<JackTradeCandidate>) -> Vec<JackTradeCandidate> {
    let all: Vec<JackTradeCandidate> = std::iter::once(chosen).chain(candidates).collect();
    let dominates = |a: &JackTradeCandidate, b: &JackTradeCandidate| {
        a.depth_below_pivot_m <= b.depth_below_pivot_m
            && a.peak_load_n <= b.peak_load_n
            && (a.depth_below_pivot_m < b.depth_below_pivot_m || a.peak_load_n < b.peak_load_n)
    };
    let mut front: Vec<JackTradeCandidate> = all
        .iter()
        .filter(|c| c.chosen || !all.iter().any(|o| dominates(o, c)))
        .copied()
        .collect();
    // The chosen one first among equals, so that the dedup keeps it.
    front.sort_by(|a, b| a.cost.total_cmp(&b.cost).then(b.chosen.cmp(&a.chosen)));
    front.dedup_by(|a, b| {
        (a.depth_below_pivot_m - b.depth_below_pivot_m).abs() < 1e-9 && (a.peak_load_n - b.peak_load_n).abs() < 1e-9
    });
    if let Some(k) = front.iter().position(|c| c.chosen) {
        // The refined choice costs least; keep it whatever the truncation.
        let chosen = front.remove(k);
        front.insert(0, chosen);
    }
    front.truncate(JACK_TRADE_CANDIDATES);
    front.sort_by(|a, b| a.depth_below_pivot_m.total_cmp(&b.depth_below_pivot_m));
    front
}

/// What a weighed placement adds for a stroke shorter than
/// [`crate::shared::objective::MIN_STROKE_M`]: [`crate::shared::objective::CAP_EXCESS_WEIGHT`]
/// per minimum stroke short of it (a stroke of half the minimum costs a flap chord of
/// fairing depth), so that a light load does not let the screw take hold at the hinge.
fn short_stroke_cost(stroke_m: f64) -> f64 {
    use crate::shared::objective::{CAP_EXCESS_WEIGHT, MIN_STROKE_M};
    CAP_EXCESS_WEIGHT * ((MIN_STROKE_M - stroke_m) / MIN_STROKE_M).max(0.0)
}

/// A screw jack's free choices: the attachment's fraction of the arm, the standoff (m) and
/// the mount's turn about the attachment (rad).
type Placement = (f64, f64, f64);

/// The mount's turns the grid tries about the attachment (rad), square first, up to
/// [`MAX_TURN`] either way.
const TURNS: [f64; 9] = [0.0, -0.35, 0.35, -0.7, 0.7, -1.05, 1.05, -MAX_TURN, MAX_TURN];

/// The largest turn of the mount about the attachment either way (rad, 80 deg).
const MAX_TURN: f64 = 1.4;

/// Halvings of the refinement's steps.
const REFINEMENTS: usize = 5;

/// The grid's best placement refined by a compass search: each choice stepped either way
/// (fraction 0.05, standoff a quarter of the start's, turn 0.175 rad, each halved
/// [`REFINEMENTS`] times) within `bounds`, the least costly clear neighbour taken while it
/// costs less; at most eight moves a step size. `cost_of` is None where a placement does
/// not transmit or is not clear.
fn refine(
    start: (Placement, f64),
    bounds: [(f64, f64); 3],
    cost_of: &dyn Fn(Placement) -> Option<f64>,
) -> (Placement, f64) {
    let (mut here, mut cost) = start;
    let mut steps = [0.05, 0.25 * start.0 .1, 0.175];
    for _ in 0..REFINEMENTS {
        for _ in 0..8 {
            let mut next: Option<(Placement, f64)> = None;
            for axis in 0..3 {
                for sign in [-1.0, 1.0] {
                    let mut values = [here.0, here.1, here.2];
                    values[axis] += sign * steps[axis];
                    let (low, high) = bounds[axis];
                    if !(low..=high).contains(&values[axis]) || steps[axis] == 0.0 {
                        continue;
                    }
                    let candidate = (values[0], values[1], values[2]);
                    if let Some(c) = cost_of(candidate) {
                        if c < next.map_or(cost, |(_, best)| best) {
                            next = Some((candidate, c));
                        }
                    }
                }
            }
            match next {
                Some((candidate, c)) => (here, cost) = (candidate, c),
                None => break,
            }
        }
        steps = steps.map(|step| 0.5 * step);
    }
    (here, cost)
}

/// The mount's turn about the attachment's mid-travel position, from the square mount at
/// `standoff_m` ([`mount_square_at_mid_travel`]), that makes the two end pressure angles
/// equal: `004_...`'s exact variant (`LandingGearSpec::synthesise_equal_pressure_angles`),
/// where the square mount is its closed form, equal only as the mount recedes. Bisection
/// within [`MAX_TURN`] either way; `None` where the difference keeps its sign there or a
/// drive cannot be built.
fn equal_pressure_turn(pivot: Point2<f64>, attachment: Point2<f64>, rotation_rad: f64, standoff_m: f64) -> Option<f64> {
    let square = mount_square_at_mid_travel(pivot, attachment, rotation_rad, standoff_m);
    let middle = turn_about(pivot, 0.5 * rotation_rad) * attachment;
    let difference = |turn: f64| -> Option<f64> {
        let drive = RockerDrive::try_new(pivot, turn_about(middle, turn) * square, attachment).ok()?;
        let [start, end] = drive.end_pressure_angles_rad(rotation_rad);
        let difference = start - end;
        difference.is_finite().then_some(difference)
    };
    // A bracket: the first neighbours of 16 turns across the range whose differences have
    // opposite signs (either end may not build: a toggle within the rotation).
    let turns: Vec<f64> = (0..16).map(|k| -MAX_TURN + 2.0 * MAX_TURN * k as f64 / 15.0).collect();
    let values: Vec<Option<f64>> = turns.iter().map(|&turn| difference(turn)).collect();
    let k = (0..15).find(|&k| matches!((values[k], values[k + 1]), (Some(a), Some(b)) if a.signum() != b.signum()))?;
    let (mut low, mut high) = (turns[k], turns[k + 1]);
    let mut at_low = values[k]?;
    // 40 halvings: 0.19 rad to 2e-13 rad.
    for _ in 0..40 {
        let mid = 0.5 * (low + high);
        let at_mid = difference(mid)?;
        if at_mid.signum() == at_low.signum() {
            (low, at_low) = (mid, at_mid);
        } else {
            high = mid;
        }
    }
    Some(0.5 * (low + high))
}

/// The first attachment fraction a screw-jack search tries: the arm's middle.
pub const DEFAULT_ATTACHMENT_FRACTION: f64 = 0.5;

/// How a kind's screw jack is placed: the designer's choices.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScrewJackChoice {
    /// The arm the screw pushes, from its fraction 0 end to its fraction 1 end (stowed).
    pub arm: (Point2<f64>, Point2<f64>),
    /// Where on the arm the screw takes hold: the designer's fraction (the only one
    /// tried), or `None` for a search from [`DEFAULT_ATTACHMENT_FRACTION`] on.
    pub attachment_fraction: Option<f64>,
    /// The search's further candidates when the first is not clear; outside [0, 1] on a
    /// horn beyond an end of the arm (a horn beyond the pivot moves the other way, so its
    /// screw can sit on the other side). Not tried when the designer gives the fraction.
    pub other_fractions: &'static [f64],
    /// The mount, if the designer gives it.
    pub mount: Option<Point2<f64>>,
    /// Base distance from the attachment's mid-travel position to a default mount (m).
    pub standoff_m: f64,
    /// Smallest transmission angle (rad).
    pub min_transmission_rad: f64,
}

/// The screw jack of a body turning by `rotation_rad` about `pivot`: the designer's mount,
/// or the least costly clear candidate of [`screw_jack_placement`] over attachments (the
/// designer's `choice.attachment_fraction` alone, or [`DEFAULT_ATTACHMENT_FRACTION`] then
/// `choice.other_fractions` of the arm) and standoffs 1, 1.6, 2.4 and 0.7 times
/// `choice.standoff_m`; when none is clear, the first that transmits well enough (or the
/// first candidate) and `false`.
#[allow(clippy::too_many_arguments)]
pub fn place_screw_jack(
    pivot: Point2<f64>,
    rotation_rad: f64,
    choice: &ScrewJackChoice,
    size: &JackSize,
    margin: f64,
    outline: &StationOutline,
    flap_at: &dyn Fn(f64) -> Option<Isometry2<f64>>,
    weighing: Option<&LoadWeighing>,
) -> PlacedJack {
    let (from, to) = choice.arm;
    let on_arm = |fraction: f64| from + (to - from) * fraction;
    let first = on_arm(choice.attachment_fraction.unwrap_or(DEFAULT_ATTACHMENT_FRACTION));
    let placed = |attachment, mount, clear, trade| PlacedJack {
        attachment,
        mount,
        clear,
        trade,
    };
    if let Some(mount) = choice.mount {
        return placed(first, mount, true, Vec::new());
    }
    let others: &[f64] = if choice.attachment_fraction.is_some() {
        &[]
    } else {
        choice.other_fractions
    };
    let fractions: Vec<f64> = std::iter::once(choice.attachment_fraction.unwrap_or(DEFAULT_ATTACHMENT_FRACTION))
        .chain(others.iter().copied())
        .collect();
    let standoffs: Vec<f64> = [1.0, 1.6, 2.4, 0.7].iter().map(|k| k * choice.standoff_m).collect();
    match screw_jack_placement(
        pivot,
        rotation_rad,
        choice.arm,
        &fractions,
        &standoffs,
        choice.min_transmission_rad,
        size,
        margin,
        outline,
        flap_at,
        weighing,
    ) {
        Ok(((attachment, mount), trade)) => placed(attachment, mount, true, trade),
        Err(Some((attachment, mount))) => placed(attachment, mount, false, Vec::new()),
        Err(None) => placed(
            first,
            mount_square_at_mid_travel(pivot, first, rotation_rad, choice.standoff_m),
            false,
            Vec::new(),
        ),
    }
}

/// Lower-skin points a strut may go up to, flap chords ahead of the cove's lower lip
/// ([`strut_top`]'s candidates, nearest first), for every kind's struts.
pub const STRUT_TOPS_AHEAD: [f64; 11] = [0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.25, 1.5];

/// A strut from the fixed point `from` up to the wing's lower skin: the first top of the
/// candidates (lower-skin points `ahead` flap chords ahead of the cove, in order) whose
/// strut keeps `margin` clear of the structure and of the flap at every pose of
/// `flap_poses`, and that is not `avoid`. None when no candidate is clear.
pub fn strut_top(
    outline: &StationOutline,
    from: Point2<f64>,
    ahead: &[f64],
    radius: f64,
    margin: f64,
    flap_poses: &[Isometry2<f64>],
    avoid: Option<Point2<f64>>,
) -> Option<Point2<f64>> {
    strut_tops(outline, from, ahead, radius, margin, flap_poses, avoid).next()
}

/// Every top of [`strut_top`]'s candidates whose strut from `from` clears, in the
/// candidates' order (a truss chooses among them, `strut_top` takes the first).
pub fn strut_tops<'a>(
    outline: &'a StationOutline,
    from: Point2<f64>,
    ahead: &'a [f64],
    radius: f64,
    margin: f64,
    flap_poses: &'a [Isometry2<f64>],
    avoid: Option<Point2<f64>>,
) -> impl Iterator<Item = Point2<f64>> + 'a {
    let lip_and_chord = outline
        .cove_lower_lip_x()
        .zip(outline.flap_chord().map(|(_, _, chord)| chord));
    ahead.iter().filter_map(move |&k| {
        let (lip, flap_chord) = lip_and_chord?;
        let top = outline.wing_lower_point(lip + k * flap_chord)?;
        let distinct = avoid.is_none_or(|p| (p - top).norm() > 0.04 * flap_chord);
        // The strut ends on the skin by design: it must not cross the wing short of its top.
        let short = top + (from - top).normalize() * (radius + margin);
        let clear = distinct
            && outline.structure.segment_clear_by(from, top, radius + margin)
            && !outline.wing.segment_meets(from, short)
            && flap_poses.iter().all(|pose| {
                let back = pose.inverse();
                outline.flap.segment_clear_by(back * from, back * top, radius + margin)
            });
        clear.then_some(top)
    })
}

impl JackSize {
    /// The solids of `hardware` with a screw of mean radius `mean_radius_m` (thread depth
    /// a quarter of it).
    pub fn new(hardware: &crate::shared::flap_load::LinkHardware, mean_radius_m: f64) -> Self {
        Self {
            screw_radius_m: 1.25 * mean_radius_m,
            nut_radius_m: hardware.nut_radius_m,
            body_length_m: hardware.jack_body_length_m,
            body_radius_m: hardware.jack_body_radius_m,
        }
    }
}

/// The flap's poses of a turn by `rotation_rad` about `pivot`, sampled.
pub fn turning_flap(pivot: Point2<f64>, rotation_rad: f64) -> Vec<Isometry2<f64>> {
    (0..=PLACEMENT_SAMPLES)
        .map(|k| turn_about(pivot, rotation_rad * k as f64 / PLACEMENT_SAMPLES as f64))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `004_...`'s exact variant: the turned mount's end pressure angles are equal, and
    /// the turn shrinks as the mount recedes (the square mount, the closed form, is equal
    /// only in the limit), either sense of rotation.
    #[test]
    fn the_equal_pressure_turn_equalises_the_end_pressure_angles() {
        let (pivot, attachment) = (Point2::new(0.0, 0.0), Point2::new(-0.3, -0.1));
        for rotation in [0.6_f64, -0.6, 1.2] {
            let mut previous = f64::INFINITY;
            for standoff in [0.4, 0.8, 1.6, 3.2] {
                let turn = equal_pressure_turn(pivot, attachment, rotation, standoff).expect("a turn");
                let middle = turn_about(pivot, 0.5 * rotation) * attachment;
                let mount =
                    turn_about(middle, turn) * mount_square_at_mid_travel(pivot, attachment, rotation, standoff);
                let [start, end] = RockerDrive::try_new(pivot, mount, attachment)
                    .unwrap()
                    .end_pressure_angles_rad(rotation);
                assert!(
                    (start - end).abs() < 1e-9,
                    "{rotation} {standoff}: {start} against {end}"
                );
                assert!(turn.abs() < previous, "{rotation} {standoff}: {turn}");
                previous = turn.abs();
            }
        }
    }

    /// The compass search walks from a grid point into a smooth bowl's minimum to within
    /// its last steps (0.05, a quarter of the standoff and 0.175 rad over 2^5), never
    /// leaves its bounds, never takes a placement it is told is not clear, and never ends
    /// costlier than it started.
    #[test]
    fn the_refinement_finds_a_bowls_minimum_within_its_bounds() {
        let minimum = (0.43, 0.61, -0.52);
        let bowl = |(f, s, t): Placement| {
            // A wall of placements that are not clear across the straight path.
            if (f - 0.5).abs() < 0.01 && t > -0.3 {
                return None;
            }
            Some((f - minimum.0).powi(2) + (s - minimum.1).powi(2) + (t - minimum.2).powi(2))
        };
        let start = (0.52, 0.5, 0.0);
        let bounds = [(0.4, 0.6), (0.35, 1.2), (-MAX_TURN, MAX_TURN)];
        let (end, cost) = refine((start, bowl(start).unwrap()), bounds, &bowl);
        assert!(cost <= bowl(start).unwrap());
        assert_eq!(bowl(end), Some(cost));
        for (axis, (value, target, last_step)) in [
            (end.0, minimum.0, 0.05 / 32.0),
            (end.1, minimum.1, 0.125 / 32.0),
            (end.2, minimum.2, 0.175 / 32.0),
        ]
        .into_iter()
        .enumerate()
        {
            assert!(
                (value - target).abs() <= last_step,
                "axis {axis}: {value} against {target}"
            );
            assert!((bounds[axis].0..=bounds[axis].1).contains(&value));
        }
        // A minimum outside the bounds: the search stops at the bound's side.
        let outside = |(f, _, _): Placement| Some((f - 0.9).powi(2));
        let (end, _) = refine(((0.5, 0.5, 0.0), outside((0.5, 0.5, 0.0)).unwrap()), bounds, &outside);
        assert!(end.0 <= 0.6 && end.0 > 0.6 - 0.05);
    }
}
