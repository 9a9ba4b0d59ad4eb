//! Certified clearance sweep of one pair of parts over the deployment.
//!
//! Between two samples t_i < t_j the distance d(t) between two rigid parts cannot change
//! faster than the sum L of their speed bounds, so on [t_i, t_j]
//! d(t) >= max(d_i - L (t - t_i), d_j - L (t_j - t)) >= (d_i + d_j - L (t_j - t_i)) / 2.
//! The sweep bisects the interval with the lowest such bound until every interval's bound
//! is within `tolerance_m` of the smallest sampled distance. The true minimum clearance is
//! then certified to lie in [min_sampled - residual_bound, min_sampled]: a collision
//! between samples cannot be missed once the residual bound is below the clearance.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use flapwright_geom::collision::{compute_clearance, Clearance};
use nalgebra::Point3;
use serde::Serialize;

use crate::error::{Error, Result};
use crate::part::Part;

/// Resolution knobs of the sweep (defaults chosen from the error-vs-time study in the
/// README).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepSettings {
    /// Evenly spaced samples before any refinement (>= 2).
    pub initial_samples: usize,
    /// Refine until the certified lower bound is within this of the sampled minimum (m).
    pub tolerance_m: f64,
    /// Stop refining after this many distance evaluations per pair; the residual bound
    /// then says how much is uncertain.
    pub max_evaluations: usize,
}

impl Default for SweepSettings {
    fn default() -> Self {
        Self {
            initial_samples: 9,
            tolerance_m: 1e-3,
            max_evaluations: 400,
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
    /// The true minimum is at least `min_clearance_m - residual_bound_m` (m).
    pub residual_bound_m: f64,
    /// Distance evaluations spent.
    pub evaluations: usize,
}

/// An interval between two samples with its certified lower bound on the distance.
struct Interval {
    lower_bound_m: f64,
    start: (f64, f64),
    end: (f64, f64),
}

impl PartialEq for Interval {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Interval {}
impl PartialOrd for Interval {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Interval {
    /// Max-heap on the *lowest* bound (reversed), ties by position for determinism.
    fn cmp(&self, other: &Self) -> Ordering {
        other
            .lower_bound_m
            .total_cmp(&self.lower_bound_m)
            .then(other.start.0.total_cmp(&self.start.0))
    }
}

struct Sample {
    t: f64,
    clearance: Clearance,
}

impl Sample {
    /// An interval end: only its parameter and distance matter.
    fn end(t: f64, distance_m: f64) -> Self {
        Sample {
            t,
            clearance: Clearance {
                distance_m,
                penetration_m: 0.0,
                penetration_resolution_m: 0.0,
                point_a_ac: Point3::origin(),
                point_b_ac: Point3::origin(),
            },
        }
    }

    fn distance_m(&self) -> f64 {
        self.clearance.distance_m
    }
}

/// Sweeps the clearance between `a` and `b` for deployment `t` in `[start, end]`.
pub fn sweep_pair(a: &Part, b: &Part, start: f64, end: f64, settings: &SweepSettings) -> Result<PairClearance> {
    settings.validate()?;
    if !(start.is_finite() && end.is_finite() && start < end) {
        return Err(Error::BadRange { start, end });
    }
    let mut speed = 0.0;
    for part in [a, b] {
        let bound = part.motion.speed_bound();
        if !(bound.is_finite() && bound >= 0.0) {
            return Err(Error::BadSpeedBound {
                part: part.name.clone(),
                value: bound,
            });
        }
        speed += bound;
    }
    let evaluate = |t: f64| -> Result<Sample> {
        // Penetration is sampled as finely as the clearance is certified.
        let clearance = compute_clearance(
            &a.shape,
            &a.motion.pose_ac(t),
            &b.shape,
            &b.motion.pose_ac(t),
            settings.tolerance_m,
        )
        .map_err(|source| Error::Query {
            part_a: a.name.clone(),
            part_b: b.name.clone(),
            parameter: t,
            source: Box::new(source),
        })?;
        Ok(Sample { t, clearance })
    };
    let interval = |s: &Sample, e: &Sample| Interval {
        lower_bound_m: 0.5 * (s.distance_m() + e.distance_m() - speed * (e.t - s.t)),
        start: (s.t, s.distance_m()),
        end: (e.t, e.distance_m()),
    };

    let n = settings.initial_samples;
    let samples = (0..n)
        .map(|i| evaluate(start + (end - start) * i as f64 / (n - 1) as f64))
        .collect::<Result<Vec<_>>>()?;
    let mut evaluations = n;
    // The deepest overlap if any, else the smallest clearance; ties to the first.
    let mut best = samples
        .iter()
        .min_by(|x, y| {
            (x.clearance.signed_m())
                .total_cmp(&y.clearance.signed_m())
                .then(x.t.total_cmp(&y.t))
        })
        .map(|s| Sample { ..*s })
        .ok_or(Error::BadRange { start, end })?;
    let mut heap: BinaryHeap<Interval> = samples.windows(2).map(|w| interval(&w[0], &w[1])).collect();

    if speed > 0.0 {
        while let Some(worst) = heap.peek() {
            let settled = worst.lower_bound_m >= best.distance_m() - settings.tolerance_m;
            if settled || evaluations >= settings.max_evaluations || best.distance_m() <= 0.0 {
                break;
            }
            let worst = heap.pop().expect("peeked");
            let middle = evaluate(0.5 * (worst.start.0 + worst.end.0))?;
            evaluations += 1;
            let (left, right) = (
                Sample::end(worst.start.0, worst.start.1),
                Sample::end(worst.end.0, worst.end.1),
            );
            heap.push(interval(&left, &middle));
            heap.push(interval(&middle, &right));
            if middle.clearance.signed_m() < best.clearance.signed_m() {
                best = middle;
            }
        }
    }
    let lowest_bound = heap.peek().map_or(best.distance_m(), |i| i.lower_bound_m);
    let found = best.clearance;
    Ok(PairClearance {
        part_a: a.name.clone(),
        part_b: b.name.clone(),
        min_clearance_m: found.distance_m,
        at_parameter: best.t,
        point_a_ac: found.point_a_ac.coords.into(),
        point_b_ac: found.point_b_ac.coords.into(),
        penetration_m: found.penetration_m,
        penetration_resolution_m: found.penetration_resolution_m,
        residual_bound_m: (found.distance_m - lowest_bound).max(0.0),
        evaluations,
    })
}
