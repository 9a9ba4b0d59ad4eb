//! Certified minimum of a Lipschitz function of the deployment, by sampling and bisection.
//!
//! If |g(t) - g(t')| <= L |t - t'|, then on [t_i, t_j]
//! g(t) >= max(g_i - L (t - t_i), g_j - L (t_j - t)) >= (g_i + g_j - L (t_j - t_i)) / 2.
//! The interval with the lowest such bound is bisected until every bound is within the
//! tolerance (absolute, or relative to the smallest sample's |g|, whichever is larger) of
//! the smallest sample (or the budget is spent, or `stop` says the answer is
//! already known). The true minimum then lies in [smallest - residual, smallest].
//! Clearances minimise g = distance; joints that must hold maximise the separation by
//! minimising g = -separation (also L-Lipschitz).
//!
//! Where g is the smallest of several components g_k, each L_k-Lipschitz (a moving mesh's
//! slabs, each bounded by its own speed: `slabbed`), the interval's bound is the smallest of
//! the components' bounds, min_k (g_k,i + g_k,j - L_k (t_j - t_i)) / 2, which is far higher
//! than the single bound with the largest L_k where the slowest component is the nearest.
//! A sample's components may be lower bounds rather than values (a component an
//! evaluation skipped because its bound, inherited from the interval's ends, already
//! lies above the others' values): the bounds above hold for lower bounds as well.

use std::cmp::Ordering;
use std::collections::binary_heap::PeekMut;
use std::collections::BinaryHeap;
use std::rc::Rc;

use crate::error::{Error, Result};
use crate::sweep::SweepSettings;

/// A sample's place and its components' lower bounds (shared by the two intervals it ends).
type Ends = (f64, Rc<[f64]>);

/// An interval between two samples with its certified lower bound on g.
struct Interval {
    lower_bound: f64,
    start: Ends,
    end: Ends,
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
            .lower_bound
            .total_cmp(&self.lower_bound)
            .then(other.start.0.total_cmp(&self.start.0))
    }
}

/// What to minimise.
pub(crate) trait Objective {
    /// What one evaluation yields.
    type Sample;
    /// Evaluates at deployment `t`. `floors`, for a sample between two others, are
    /// certified lower bounds on each component there (from the interval's ends), which
    /// the objective may use to skip work.
    fn evaluate(&self, t: f64, floors: Option<&[f64]>) -> Result<Self::Sample>;
    /// The Lipschitz function g being minimised.
    fn value(&self, sample: &Self::Sample) -> f64;
    /// Lower bounds at the sample on the components g is the smallest of, in the order of
    /// [`certified_minimum`]'s Lipschitz constants; by default g alone.
    fn components(&self, sample: &Self::Sample) -> Vec<f64> {
        vec![self.value(sample)]
    }
    /// Ranks samples (ties in g may be broken further, e.g. by penetration depth).
    fn rank(&self, sample: &Self::Sample) -> f64 {
        self.value(sample)
    }
    /// True when the best sample already decides the question (refining cannot change it).
    fn done(&self, _best: &Self::Sample) -> bool {
        false
    }
    /// True when a certified lower bound this high on g answers the question, so the
    /// minimum need not be located any closer.
    fn bound_suffices(&self, _lowest_bound: f64) -> bool {
        false
    }
}

/// The sample with the smallest rank, its parameter, and the certificate.
pub(crate) struct Minimum<S> {
    pub t: f64,
    pub sample: S,
    /// The true minimum of g is at least the best sample's g less this.
    pub residual: f64,
    pub evaluations: usize,
    /// Every evaluation as (t, rank), in t order.
    pub trace: Vec<(f64, f64)>,
}

/// Minimises `objective` over `t` in `[start, end]`, its components having Lipschitz
/// constants `lipschitz` (one for a plain g).
pub(crate) fn certified_minimum<O: Objective>(
    start: f64,
    end: f64,
    lipschitz: &[f64],
    settings: &SweepSettings,
    objective: &O,
) -> Result<Minimum<O::Sample>> {
    let interval = |s: Ends, e: Ends| {
        let width = e.0 - s.0;
        let lower_bound =
            s.1.iter()
                .zip(e.1.iter())
                .zip(lipschitz)
                .map(|((gs, ge), l)| 0.5 * (gs + ge - l * width))
                .fold(f64::INFINITY, f64::min);
        Interval {
            lower_bound,
            start: s,
            end: e,
        }
    };
    let ends = |t: f64, sample: &O::Sample| -> Ends {
        let components = objective.components(sample);
        debug_assert_eq!(components.len(), lipschitz.len(), "one Lipschitz constant a component");
        (t, components.into())
    };
    let moving = lipschitz.iter().any(|l| *l > 0.0);
    // Parts that do not move (a track against a spar) need one evaluation.
    let n = if moving { settings.initial_samples } else { 1 };
    let samples = (0..n)
        .map(|i| {
            let t = if n > 1 {
                start + (end - start) * i as f64 / (n - 1) as f64
            } else {
                start
            };
            objective.evaluate(t, None).map(|s| (t, s))
        })
        .collect::<Result<Vec<_>>>()?;
    let mut trace: Vec<(f64, f64)> = samples.iter().map(|(t, s)| (*t, objective.rank(s))).collect();
    let mut heap: BinaryHeap<Interval> = samples
        .windows(2)
        .map(|w| interval(ends(w[0].0, &w[0].1), ends(w[1].0, &w[1].1)))
        .collect();
    // The smallest rank, ties to the first sample.
    let (mut best_t, mut best) = samples
        .into_iter()
        .reduce(|x, y| {
            if objective.rank(&y.1) < objective.rank(&x.1) {
                y
            } else {
                x
            }
        })
        .ok_or(Error::BadRange { start, end })?;
    let mut evaluations = n;
    if moving {
        loop {
            let Some(worst) = heap.peek_mut() else { break };
            let best_value = objective.value(&best);
            let tolerance = settings.tolerance_m.max(settings.relative_tolerance * best_value.abs());
            let settled = worst.lower_bound >= best_value - tolerance || objective.bound_suffices(worst.lower_bound);
            if settled || evaluations >= settings.max_evaluations || objective.done(&best) {
                break;
            }
            let worst = PeekMut::pop(worst);
            let t = 0.5 * (worst.start.0 + worst.end.0);
            let floors: Vec<f64> = worst
                .start
                .1
                .iter()
                .zip(worst.end.1.iter())
                .zip(lipschitz)
                .map(|((gs, ge), l)| (gs - l * (t - worst.start.0)).max(ge - l * (worst.end.0 - t)))
                .collect();
            let middle = objective.evaluate(t, Some(&floors))?;
            evaluations += 1;
            trace.push((t, objective.rank(&middle)));
            let at_middle = ends(t, &middle);
            heap.push(interval(worst.start, at_middle.clone()));
            heap.push(interval(at_middle, worst.end));
            if objective.rank(&middle) < objective.rank(&best) {
                (best_t, best) = (t, middle);
            }
        }
    }
    let best_value = objective.value(&best);
    let lowest_bound = heap.peek().map_or(best_value, |i| i.lower_bound);
    trace.sort_by(|x, y| x.0.total_cmp(&y.0));
    Ok(Minimum {
        t: best_t,
        sample: best,
        residual: (best_value - lowest_bound).max(0.0),
        evaluations,
        trace,
    })
}
