//! How fast the distance between two parts can change: the Lipschitz constant the sweeps
//! certify with.
//!
//! The plain bound is the sum of the two parts' speed bounds, L_a + L_b. It is loose for a
//! small part next to a large one: a track under a flap's nose is charged with the speed
//! of the flap's trailing edge, a metre aft, and a part of the station at the flap's inner
//! end with the speed of its outer end. The distance does not change with the motion both
//! share, so it is enough to bound how fast a's points move *in b's frame*:
//!
//! d(t) = dist(a(t), b(t)) = dist(b(t)⁻¹ a(t), b stowed), and a point p of a moves in b's
//! frame at |v_a(p) - u_b(p)| <= L_a + |u_b(p)|, u_b being b's rigid velocity field at p
//! (the motion extended to all space). So |d'(t)| <= L_a + F_b, F_b bounding |u_b| wherever
//! a's points can be relative to b ([`Motion::field_speed_bound`]), and the same with a and
//! b turned round.
//!
//! Where a can be relative to b: the deployment is cut into [`SWEPT_BOX_INTERVALS`]
//! intervals of width h as in the broad phase; at each interval's middle, a's box in b's
//! frame, grown by G. If (L_a + F) h / 2 <= G, F being the field bound over those grown
//! boxes, then a stays in them over the whole interval: a point leaving its box's growth
//! must first cover G, moving no faster than L_a + F while inside. G starts at
//! (L_a + L_b) h / 2 and is grown to the new (L_a + F) h / 2 while that is needed (a few
//! rounds at most); when no G holds, the plain sum stands. The field bounds are convex in
//! the point, so a box's corners bound it.

use nalgebra::Point3;

use crate::broad::SWEPT_BOX_INTERVALS;
use crate::error::{Error, Result};
use crate::part::Part;

/// Rounds of growing the region before the plain sum of the speed bounds is kept.
const GROWTH_ROUNDS: usize = 4;

/// The Lipschitz constant (m per unit t) of the distance between `a` and `b` over
/// `[start, end]`: the smallest of L_a + L_b, L_a + F_b and L_b + F_a (module doc).
pub(crate) fn pair_lipschitz(a: &Part, b: &Part, start: f64, end: f64) -> Result<f64> {
    let mut speed = [0.0; 2];
    for (k, part) in [a, b].into_iter().enumerate() {
        let bound = part.motion.speed_bound();
        if !(bound.is_finite() && bound >= 0.0) {
            return Err(Error::BadSpeedBound {
                part: part.name.clone(),
                value: bound,
            });
        }
        speed[k] = bound;
    }
    let plain = speed[0] + speed[1];
    if plain == 0.0 {
        return Ok(0.0);
    }
    // In a fixed part's frame the other moves at its own bound, the plain sum: no need to
    // pose anything.
    let in_frame = |mover: &Part, mover_speed: f64, frame: &Part, frame_speed: f64| {
        if frame_speed == 0.0 {
            Ok(plain)
        } else {
            relative_bound(mover, mover_speed, frame, frame_speed, start, end)
        }
    };
    let a_in_b = in_frame(a, speed[0], b, speed[1])?;
    let b_in_a = in_frame(b, speed[1], a, speed[0])?;
    Ok([plain, a_in_b, b_in_a].into_iter().fold(f64::INFINITY, f64::min))
}

/// L_mover + F_frame where the frame part's field can be bounded over where the mover goes
/// relative to it; infinity where not.
fn relative_bound(mover: &Part, mover_speed: f64, frame: &Part, frame_speed: f64, start: f64, end: f64) -> Result<f64> {
    let width = (end - start) / SWEPT_BOX_INTERVALS as f64;
    let pose = |part: &Part, t: f64| {
        part.motion.pose_ac(t).map_err(|source| Error::Pose {
            part: part.name.clone(),
            parameter: t,
            source,
        })
    };
    // The mover's box in the frame part's local frame at each interval's middle.
    let boxes = (0..SWEPT_BOX_INTERVALS)
        .map(|k| {
            let t = start + (k as f64 + 0.5) * width;
            let relative = pose(frame, t)?.inverse() * pose(mover, t)?;
            Ok(mover.shape.compute_aabb(&relative))
        })
        .collect::<Result<Vec<_>>>()?;
    let mut growth = (mover_speed + frame_speed) * width / 2.0;
    for _ in 0..GROWTH_ROUNDS {
        let corners: Vec<Point3<f64>> = boxes.iter().flat_map(|b| b.inflated(growth).corners()).collect();
        let Some(field) = frame.motion.field_speed_bound(&corners).filter(|f| f.is_finite()) else {
            return Ok(f64::INFINITY);
        };
        let needed = (mover_speed + field) * width / 2.0;
        if needed <= growth {
            return Ok(mover_speed + field);
        }
        growth = needed;
    }
    Ok(f64::INFINITY)
}
