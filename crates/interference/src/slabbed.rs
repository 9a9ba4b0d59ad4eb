//! A moving mesh swept against a fixed part slab by slab (`CollisionShape::slabs`): each
//! slab's distance bounded by the mesh's own speed over that slab, so that near a flap's
//! nose, slower than its trailing edge, the samples may lie farther apart (`refine` bounds
//! an interval by each component's constant). The sweep (`sweep`) uses it where it pays.

use std::cell::Cell;

use flapwright_geom::collision::{compute_distance_near, compute_holds, Clearance, NearHint, Proximity, Slab};

use crate::error::Result;
use crate::part::Part;
use crate::refine::Objective;
use crate::sweep::{pose_at, query_error, Clearances};

/// A moving mesh against a fixed part, slab by slab (`CollisionShape::slabs`): the mesh's
/// surface distance is the smallest of its slabs', and each slab's changes no faster than
/// the mesh's rigid field over that slab ([`Motion::field_speed_bound`](crate::Motion)),
/// which for a flap's nose is a fraction of its trailing edge's (`refine` bounds each
/// interval by the slabs' own constants). A sample asks a slab only while its bound from
/// the interval's ends lies below the nearest slab found so far, nearest bound first: the
/// distance is the same exact minimum. Where the slabs find the surfaces touching, or one
/// part holds the other ([`compute_holds`]), the sample is the whole parts' clearance (with
/// its penetration), and every slab's bound is 0.
pub(crate) struct SlabbedClearance<'p> {
    pub(crate) mover: &'p Part,
    pub(crate) fixed: &'p Part,
    /// The mover is the pair's b (points are reported in the pair's order).
    pub(crate) mover_is_b: bool,
    pub(crate) slabs: &'p [Slab],
    pub(crate) hints: Vec<Cell<NearHint>>,
    /// The pair as given, for samples where the parts overlap.
    pub(crate) whole: Clearances<'p>,
    pub(crate) verdict_at: Option<f64>,
}

/// A sample of [`SlabbedClearance`]: the pair's clearance and each slab's lower bound (its
/// distance where the sample asked it).
pub(crate) struct SlabbedSample {
    pub(crate) clearance: Clearance,
    slab_bounds: Vec<f64>,
}

impl SlabbedClearance<'_> {
    /// The nearest slab at `t` asking only the slabs that may be nearer; each slab's
    /// bound updated to its distance where asked.
    fn nearest(
        &self,
        t: f64,
        pose_mover: &nalgebra::Isometry3<f64>,
        pose_fixed: &nalgebra::Isometry3<f64>,
        bounds: &mut [f64],
    ) -> Result<Option<Proximity>> {
        let mut order: Vec<usize> = (0..self.slabs.len()).collect();
        order.sort_by(|&i, &j| bounds[i].total_cmp(&bounds[j]).then(i.cmp(&j)));
        let mut nearest: Option<Proximity> = None;
        for k in order {
            if nearest.is_some_and(|p| bounds[k] >= p.distance_m) {
                break;
            }
            let mut hint = self.hints[k].get();
            let found = compute_distance_near(
                &self.slabs[k].shape,
                pose_mover,
                &self.fixed.shape,
                pose_fixed,
                &mut hint,
            )
            .map_err(|source| query_error(self.whole.a, self.whole.b, t, source))?;
            self.hints[k].set(hint);
            bounds[k] = found.distance_m;
            if nearest.is_none_or(|p| found.distance_m < p.distance_m) {
                nearest = Some(found);
            }
        }
        Ok(nearest)
    }
}

impl Objective for SlabbedClearance<'_> {
    type Sample = SlabbedSample;
    fn evaluate(&self, t: f64, floors: Option<&[f64]>) -> Result<SlabbedSample> {
        let (pose_mover, pose_fixed) = (pose_at(self.mover, t)?, pose_at(self.fixed, t)?);
        let mut bounds = floors.map_or_else(|| vec![f64::NEG_INFINITY; self.slabs.len()], <[f64]>::to_vec);
        let nearest = self.nearest(t, &pose_mover, &pose_fixed, &mut bounds)?;
        let apart = nearest.filter(|p| {
            p.distance_m > 0.0 && !compute_holds(&self.mover.shape, &pose_mover, &self.fixed.shape, &pose_fixed)
        });
        let clearance = match apart {
            Some(p) => {
                let (point_a_ac, point_b_ac) = if self.mover_is_b {
                    (p.point_b_ac, p.point_a_ac)
                } else {
                    (p.point_a_ac, p.point_b_ac)
                };
                Clearance {
                    distance_m: p.distance_m,
                    penetration_m: 0.0,
                    penetration_resolution_m: 0.0,
                    point_a_ac,
                    point_b_ac,
                }
            }
            None => {
                let whole = self.whole.at(t)?;
                if whole.distance_m <= 0.0 {
                    bounds.fill(0.0);
                }
                whole
            }
        };
        Ok(SlabbedSample {
            clearance,
            slab_bounds: bounds,
        })
    }
    fn value(&self, sample: &SlabbedSample) -> f64 {
        sample.clearance.distance_m
    }
    fn components(&self, sample: &SlabbedSample) -> Vec<f64> {
        sample.slab_bounds.clone()
    }
    fn rank(&self, sample: &SlabbedSample) -> f64 {
        sample.clearance.signed_m()
    }
    fn done(&self, best: &SlabbedSample) -> bool {
        let distance = best.clearance.distance_m;
        distance <= 0.0 || self.verdict_at.is_some_and(|required| distance < required)
    }
    fn bound_suffices(&self, lowest_bound: f64) -> bool {
        self.verdict_at.is_some_and(|required| lowest_bound >= required)
    }
}

/// Slabs are swept where the slowest is bounded by at most this share of the whole part's
/// bound. A sample asks every slab that may be the nearest, so where several slabs are
/// about as near and as fast as the whole, they cost queries and save no samples. Measured
/// (interference stage of `design`, medians of 5, BENCHMARKS.md): the double-slotted wing,
/// whose flap's end faces stand 22.5 mm from the wing across the whole chord (slowest slab
/// 86 %), 0.51 s with slabs against 0.25 s without; the transport wing's flaps fitted to two
/// stations (78-79 %) 0.76 s with against 1.01 s without; the small aircraft's (77 %) 0.15 s
/// against 0.13 s; one station's mechanisms in the study (37-55 %) half the samples.
pub const SLABS_WORTH_IT: f64 = 0.8;

/// The slabs of the moving part of a pair whose other part is fixed, with each slab's
/// speed bound (m per unit t); `None` where neither or both move, the mover is not a mesh
/// big enough to cut, or its motion cannot bound its field.
pub(crate) fn slabs_of<'p>(a: &'p Part, b: &'p Part) -> Option<(&'p Part, &'p Part, bool, Vec<f64>)> {
    let (mover, fixed, mover_is_b) = match (a.is_moving(), b.is_moving()) {
        (true, false) => (a, b, false),
        (false, true) => (b, a, true),
        _ => return None,
    };
    let bounds = mover.slab_speed_bounds()?;
    // One bound a slab (the bounds are found for the shape's own slabs).
    if bounds.len() != mover.shape.slabs().len() {
        return None;
    }
    let whole = mover.motion.speed_bound();
    let slowest = bounds.iter().copied().fold(f64::INFINITY, f64::min);
    (slowest <= SLABS_WORTH_IT * whole).then(|| (mover, fixed, mover_is_b, bounds.to_vec()))
}
