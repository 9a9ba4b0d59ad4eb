//! Certified sweeps of one pair of parts over the deployment: the smallest clearance of
//! parts that must stay apart ([`sweep_pair`]) and the largest separation of parts that
//! must stay joined ([`sweep_contact`]).
//!
//! Between two samples t_i < t_j the distance d(t) between two rigid parts cannot change
//! faster than L, the sum of their speed bounds or the speed of one in the other's frame
//! (`relative_speed`), so on [t_i, t_j]
//! d(t) >= max(d_i - L (t - t_i), d_j - L (t_j - t)) >= (d_i + d_j - L (t_j - t_i)) / 2,
//! and the same with the signs turned for an upper bound. The sweep bisects the interval
//! with the worst such bound until every bound is within `tolerance_m` of the worst sample
//! (`refine` module). The true minimum clearance is then certified to lie in
//! [min_sampled - residual_bound, min_sampled]: a collision between samples cannot be
//! missed once the residual bound is below the clearance.

use std::cell::Cell;

use flapwright_geom::collision::{compute_clearance_near, compute_signed_distance, Clearance, NearHint};
use nalgebra::Point3;
use serde::Serialize;

use crate::error::{Error, Result};
use crate::part::Part;
use crate::refine::{certified_minimum, Minimum, Objective};
use crate::relative_speed::pair_lipschitz;
use crate::slabbed::{slabs_of, SlabbedClearance};

/// Resolution knobs of the sweep (defaults chosen from the error-vs-time study in
/// `docs/report.md`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepSettings {
    /// Evenly spaced samples before any refinement (>= 2).
    pub initial_samples: usize,
    /// Refine until the certified lower bound is within this of the sampled minimum (m),
    /// or within `relative_tolerance` of it, whichever is larger.
    pub tolerance_m: f64,
    /// Relative part of the refinement tolerance: parts a metre apart need not have their
    /// clearance located to the millimetre (the bound is then 1 % of the clearance), while
    /// pairs near any sensible required clearance keep `tolerance_m`.
    pub relative_tolerance: f64,
    /// Stop refining after this many distance evaluations per pair; the residual bound
    /// then says how much is uncertain.
    pub max_evaluations: usize,
    /// Stop refining a pair as soon as its verdict against its required clearance is
    /// certain ([`sweep_pair_for_verdict`]): a sample closer than the requirement (it fails
    /// however the minimum lies), or every interval's certified lower bound at or above it
    /// (it passes). The verdict is the same certified one; `min_clearance_m` is then only
    /// the smallest sample, with `residual_bound_m` saying how much lower the true minimum
    /// may be, rather than the minimum located to the tolerance. For comparisons that read
    /// only the verdict (the trade study of kinds).
    pub stop_at_verdict: bool,
}

impl Default for SweepSettings {
    fn default() -> Self {
        Self {
            initial_samples: 9,
            tolerance_m: 1e-3,
            relative_tolerance: 1e-2,
            max_evaluations: 400,
            stop_at_verdict: false,
        }
    }
}

impl SweepSettings {
    fn validate(&self) -> Result<()> {
        if self.initial_samples < 2 {
            return Err(Error::SettingOutOfRange {
                setting: "initial_samples",
                value: self.initial_samples as f64,
                allowed: "[2, inf)",
            });
        }
        if !(self.tolerance_m.is_finite() && self.tolerance_m > 0.0) {
            return Err(Error::SettingOutOfRange {
                setting: "tolerance_m",
                value: self.tolerance_m,
                allowed: "(0, inf)",
            });
        }
        if !(0.0..1.0).contains(&self.relative_tolerance) {
            return Err(Error::SettingOutOfRange {
                setting: "relative_tolerance",
                value: self.relative_tolerance,
                allowed: "[0, 1)",
            });
        }
        if self.max_evaluations < self.initial_samples {
            return Err(Error::SettingOutOfRange {
                setting: "max_evaluations",
                value: self.max_evaluations as f64,
                allowed: ">= initial_samples",
            });
        }
        Ok(())
    }
}

/// The smallest clearance of a pair over the deployment, where it happens, and how sure
/// we are of it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairClearance {
    /// First part's name.
    pub part_a: String,
    /// Second part's name.
    pub part_b: String,
    /// Smallest sampled distance between the solids (m); 0 when the parts touch or
    /// overlap (a part wholly inside a closed mesh overlaps).
    pub min_clearance_m: f64,
    /// Deployment parameter where it occurs (where the overlap is deepest, when the parts
    /// overlap).
    pub at_parameter: f64,
    /// Closest point on part a, aircraft frame (m); when overlapping, a's end of the
    /// deepest penetration.
    pub point_a_ac: [f64; 3],
    /// Closest point on part b, aircraft frame (m); when overlapping, b's end.
    pub point_b_ac: [f64; 3],
    /// Deepest overlap over the samples (m): how far the deepest surface point of one part
    /// reaches inside the other; 0 when clear.
    pub penetration_m: f64,
    /// The deepest surface point at that sample is at most this much deeper (m): the
    /// surface sampling grid; 0 when clear.
    pub penetration_resolution_m: f64,
    /// The true minimum is at least `min_clearance_m - residual_bound_m` (m); at most the
    /// larger of the tolerance and the relative tolerance times the clearance, unless the
    /// evaluation budget ran out.
    pub residual_bound_m: f64,
    /// Distance evaluations spent.
    pub evaluations: usize,
    /// Every evaluation as (deployment value, signed clearance in m: minus the sampled
    /// penetration depth while the parts overlap), in deployment order. For plots; not
    /// written to the report.
    #[serde(skip)]
    pub trace: Vec<(f64, f64)>,
}

/// The largest separation of two parts joined by design over the deployment.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JointSeparation {
    /// Largest sampled distance between the solids (m); 0 while they stay in contact. Where
    /// a side is round (a ball or a capsule), the largest separation of its nearest core
    /// ball instead: exact for a ball, at least the solids' separation for a capsule.
    pub max_separation_m: f64,
    /// Deployment parameter where it occurs.
    pub at_parameter: f64,
    /// Certified upper bound on the separation over the whole deployment (m); negative
    /// when the parts stay overlapped by at least that much throughout (for a round side:
    /// its ball must move at least that far to come out).
    pub upper_bound_m: f64,
    /// Distance evaluations spent.
    pub evaluations: usize,
}

fn checked_range(start: f64, end: f64, settings: &SweepSettings) -> Result<()> {
    settings.validate()?;
    if !(start.is_finite() && end.is_finite() && start < end) {
        return Err(Error::BadRange { start, end });
    }
    Ok(())
}

pub(crate) fn query_error(a: &Part, b: &Part, t: f64, source: flapwright_geom::Error) -> Error {
    Error::Query {
        part_a: a.name.clone(),
        part_b: b.name.clone(),
        parameter: t,
        source: Box::new(source),
    }
}

/// The clearance of two parts at one deployment value, as solids.
pub(crate) struct Clearances<'p> {
    pub(crate) a: &'p Part,
    pub(crate) b: &'p Part,
    /// Surface grid for penetration depth (m): as fine as the clearance is certified.
    resolution_m: f64,
    /// The closest triangles at the last evaluation, where the next one's search starts
    /// (evaluations follow each other in one thread, so the report does not depend on
    /// scheduling).
    hint: Cell<NearHint>,
}

pub(crate) fn pose_at(part: &Part, t: f64) -> Result<nalgebra::Isometry3<f64>> {
    part.motion.pose_ac(t).map_err(|source| Error::Pose {
        part: part.name.clone(),
        parameter: t,
        source,
    })
}

impl Clearances<'_> {
    pub(crate) fn at(&self, t: f64) -> Result<Clearance> {
        let (a, b) = (self.a, self.b);
        let mut hint = self.hint.get();
        let clearance = compute_clearance_near(
            &a.shape,
            &pose_at(a, t)?,
            &b.shape,
            &pose_at(b, t)?,
            self.resolution_m,
            &mut hint,
        )
        .map_err(|source| query_error(a, b, t, source));
        self.hint.set(hint);
        clearance
    }
}

/// Parts that must stay apart: minimise the distance; among overlaps, the deepest first;
/// once they overlap, refining cannot change the verdict. With `verdict_at` (the required
/// clearance, m), refining also stops once the verdict against it is certain.
struct SmallestClearance<'p> {
    clearances: Clearances<'p>,
    verdict_at: Option<f64>,
}

impl Objective for SmallestClearance<'_> {
    type Sample = Clearance;
    fn evaluate(&self, t: f64, _floors: Option<&[f64]>) -> Result<Clearance> {
        self.clearances.at(t)
    }
    fn value(&self, sample: &Clearance) -> f64 {
        sample.distance_m
    }
    fn rank(&self, sample: &Clearance) -> f64 {
        sample.signed_m()
    }
    fn done(&self, best: &Clearance) -> bool {
        best.distance_m <= 0.0 || self.verdict_at.is_some_and(|required| best.distance_m < required)
    }
    fn bound_suffices(&self, lowest_bound: f64) -> bool {
        self.verdict_at.is_some_and(|required| lowest_bound >= required)
    }
}

/// Surface grid (m) for the overlap of joined parts. Coarse on purpose: any grid keeps the
/// joint's bound certified (a coarser grid reads the overlap shallower, which is the safe
/// side); 5 mm gives up a few mm of a nut's ~17 mm overlap with its screw and samples 25
/// times fewer points than 1 mm (default check's interference stage: 0.43 s at 1 mm,
/// 0.20 s at 5 mm, same verdicts, 33 evaluations per joint either way).
pub const JOINT_PENETRATION_GRID_M: f64 = 0.005;

/// Parts that must stay joined: maximise the signed clearance (minimise its negative).
/// While they overlap, the signed clearance is minus the sampled penetration depth, which
/// is at most the exact deepest-point depth; that depth changes no faster than the speed
/// bounds allow, so the Lipschitz upper bound stays certified, and it is what lets a joint
/// that overlaps deeply be certified with few samples.
/// Refinement stops once the whole deployment is certified within the play.
struct LargestSeparation<'p> {
    clearances: Clearances<'p>,
    play_m: f64,
}

impl Objective for LargestSeparation<'_> {
    type Sample = Clearance;
    fn evaluate(&self, t: f64, _floors: Option<&[f64]>) -> Result<Clearance> {
        self.clearances.at(t)
    }
    fn value(&self, sample: &Clearance) -> f64 {
        -sample.signed_m()
    }
    fn bound_suffices(&self, lowest_bound: f64) -> bool {
        -lowest_bound <= self.play_m
    }
}

/// A ball of a part's core (`CollisionShape::core_balls`: a ball's centre, a capsule's
/// ends) against the other part.
struct CoreBall<'p> {
    part: &'p Part,
    centre: Point3<f64>,
    radius_m: f64,
    other: &'p Part,
}

/// A joint where a part is round (a pin in its track, a nut on its screw, a fitting on its
/// pin): a ball of radius r inside that part is `signed - r` from the other solid, `signed`
/// the signed distance of its centre to that solid's surface (`compute_signed_distance`):
/// the separation when positive; when negative, the ball must move at least that far to
/// come out. The part is no farther from the other than its nearest core ball, so the
/// smallest of these bounds the joint's separation from above (exact for a ball), and it
/// changes no faster than the two parts' points move (a distance to a set of moving
/// points), so the same Lipschitz bound certifies it. A few point queries replace the
/// surface sampling of [`LargestSeparation`]: the default scene's pins in their track tubes
/// took 5 ms an evaluation that way.
struct CoreBallSeparation<'p> {
    balls: Vec<CoreBall<'p>>,
    play_m: f64,
}

impl<'p> CoreBallSeparation<'p> {
    /// The core balls of `a` against `b` and of `b` against `a`; `None` when neither has any.
    fn of(a: &'p Part, b: &'p Part, play_m: f64) -> Option<Self> {
        let balls: Vec<CoreBall<'p>> = [(a, b), (b, a)]
            .into_iter()
            .filter_map(|(part, other)| {
                let (centres, radius_m) = part.shape.core_balls()?;
                Some(centres.into_iter().map(move |centre| CoreBall {
                    part,
                    centre,
                    radius_m,
                    other,
                }))
            })
            .flatten()
            .collect();
        (!balls.is_empty()).then_some(Self { balls, play_m })
    }
}

impl Objective for CoreBallSeparation<'_> {
    /// The smallest signed separation of a core ball (m).
    type Sample = f64;
    fn evaluate(&self, t: f64, _floors: Option<&[f64]>) -> Result<f64> {
        let mut smallest = f64::INFINITY;
        for ball in &self.balls {
            let centre = pose_at(ball.part, t)? * ball.centre;
            let signed = compute_signed_distance(&ball.other.shape, &pose_at(ball.other, t)?, &centre)
                .map_err(|source| query_error(ball.part, ball.other, t, source))?;
            smallest = smallest.min(signed - ball.radius_m);
        }
        Ok(smallest)
    }
    fn value(&self, sample: &f64) -> f64 {
        -sample
    }
    fn bound_suffices(&self, lowest_bound: f64) -> bool {
        -lowest_bound <= self.play_m
    }
}

/// Sweeps the clearance between `a` and `b` for deployment `t` in `[start, end]`, locating
/// its minimum to the tolerance.
pub fn sweep_pair(a: &Part, b: &Part, start: f64, end: f64, settings: &SweepSettings) -> Result<PairClearance> {
    sweep(a, b, start, end, settings, None)
}

/// As [`sweep_pair`] for a pair that needs `required_clearance_m`: with
/// [`SweepSettings::stop_at_verdict`], refining stops once the pair certainly passes
/// (`min_clearance_m - residual_bound_m >= required_clearance_m`) or certainly fails (a
/// sample closer than that).
pub fn sweep_pair_for_verdict(
    a: &Part,
    b: &Part,
    start: f64,
    end: f64,
    settings: &SweepSettings,
    required_clearance_m: f64,
) -> Result<PairClearance> {
    let verdict_at = settings.stop_at_verdict.then_some(required_clearance_m);
    sweep(a, b, start, end, settings, verdict_at)
}

fn sweep(
    a: &Part,
    b: &Part,
    start: f64,
    end: f64,
    settings: &SweepSettings,
    verdict_at: Option<f64>,
) -> Result<PairClearance> {
    checked_range(start, end, settings)?;
    let clearances = Clearances {
        a,
        b,
        resolution_m: settings.tolerance_m,
        hint: Cell::default(),
    };
    let found = if let Some((mover, fixed, mover_is_b, lipschitz)) = slabs_of(a, b) {
        // The parts' speed bounds checked as for any pair (an error for a bad one); with
        // one part fixed, the whole part's bound is the plain one, and caps every slab's.
        pair_lipschitz(a, b, start, end)?;
        let objective = SlabbedClearance {
            mover,
            fixed,
            mover_is_b,
            slabs: mover.shape.slabs(),
            hints: vec![Cell::default(); lipschitz.len()],
            whole: clearances,
            verdict_at,
        };
        let found = certified_minimum(start, end, &lipschitz, settings, &objective)?;
        Minimum {
            t: found.t,
            sample: found.sample.clearance,
            residual: found.residual,
            evaluations: found.evaluations,
            trace: found.trace,
        }
    } else {
        let objective = SmallestClearance { clearances, verdict_at };
        certified_minimum(start, end, &[pair_lipschitz(a, b, start, end)?], settings, &objective)?
    };
    let best = found.sample;
    Ok(PairClearance {
        part_a: a.name.clone(),
        part_b: b.name.clone(),
        min_clearance_m: best.distance_m,
        at_parameter: found.t,
        point_a_ac: best.point_a_ac.coords.into(),
        point_b_ac: best.point_b_ac.coords.into(),
        penetration_m: best.penetration_m,
        penetration_resolution_m: best.penetration_resolution_m,
        residual_bound_m: found.residual,
        evaluations: found.evaluations,
        trace: found.trace,
    })
}

/// Sweeps the separation of `a` and `b`, joined by design, for `t` in `[start, end]`: how
/// far apart they come where the joint should hold them together. Refines until the
/// separation is certified within `play_m` everywhere, or located to `tolerance_m`.
pub fn sweep_contact(
    a: &Part,
    b: &Part,
    start: f64,
    end: f64,
    play_m: f64,
    settings: &SweepSettings,
) -> Result<JointSeparation> {
    checked_range(start, end, settings)?;
    let lipschitz = pair_lipschitz(a, b, start, end)?;
    if let Some(objective) = CoreBallSeparation::of(a, b, play_m) {
        let found = certified_minimum(start, end, &[lipschitz], settings, &objective)?;
        return Ok(JointSeparation {
            max_separation_m: found.sample.max(0.0),
            at_parameter: found.t,
            upper_bound_m: found.sample + found.residual,
            evaluations: found.evaluations,
        });
    }
    let objective = LargestSeparation {
        clearances: Clearances {
            a,
            b,
            resolution_m: JOINT_PENETRATION_GRID_M.max(settings.tolerance_m),
            hint: Cell::default(),
        },
        play_m,
    };
    let found = certified_minimum(start, end, &[lipschitz], settings, &objective)?;
    let largest = found.sample.signed_m();
    Ok(JointSeparation {
        max_separation_m: largest.max(0.0),
        at_parameter: found.t,
        upper_bound_m: largest + found.residual,
        evaluations: found.evaluations,
    })
}
