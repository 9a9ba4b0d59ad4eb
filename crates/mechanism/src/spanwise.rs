//! Spanwise layout of a station's solids: where, along the station's z axis, each solid's
//! mid-plane lies, so that solids that cross in the station plane over the deployment sit
//! side by side (side plates, clevises, a jack between two tracks), and the check can test
//! the parts of one station against each other.
//!
//! A kind that gives its solids' offsets ([`crate::seam::BodySolid::offset_m`], any of them
//! non-zero) keeps them. Otherwise [`spanwise_layout`] lays them out from the seam alone:
//! - a group shares one layer: every solid of an actuator, a link or a carriage (a compact
//!   rigid part stands where it stands; the flap's fittings, brackets along a long body,
//!   and the struts of a support or a track may each stand at their own place), joined with the solids a prismatic joint or a pin in a slot holds on one
//!   axis (a nut on its screw, a pin in its track); solids at a revolute joint may sit on
//!   two layers, the pin spanning them (joints are checked in the station plane);
//! - two groups conflict when a solid of one comes within the sum of the radii plus
//!   r_max / 4 of a solid of the other in any of [`LAYOUT_SAMPLES`] poses of the
//!   deployment, unless the two touch by design; solids of one group that come close are
//!   left to the check to judge;
//! - groups are coloured greedily, the flap's first, then links, carriages, tracks, the
//!   actuator and the support structure (the first lies in the station plane), each on
//!   the layer of a group it touches at a revolute joint where no conflict forbids it; layer
//!   k lies at 0, -s, +s, -2s, +2s, ... with the spacing s = 2 r_max + gap and gap = r_max
//!   (r_max the largest radius of the station's solids): neighbouring layers clear each
//!   other by at least r_max.
//!
//! The layout is the smallest that separates what would cross; a real design's side
//! plates may sit wider. Hand-written: a few dozen solids, no crate does this job.

use nalgebra::Point2;

use crate::error::Result;
use crate::seam::{posed_shape, BodyRole, FlapMechanism, JointGeometry};

/// Poses of the deployment sampled for crossings.
pub const LAYOUT_SAMPLES: usize = 33;

/// Distance between segments a0-a1 and b0-b1 in the plane.
fn segment_distance(a0: Point2<f64>, a1: Point2<f64>, b0: Point2<f64>, b1: Point2<f64>) -> f64 {
    let to_segment = |p: Point2<f64>, s0: Point2<f64>, s1: Point2<f64>| {
        let d = s1 - s0;
        let length2 = d.norm_squared();
        let t = if length2 > 0.0 {
            ((p - s0).dot(&d) / length2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (p - (s0 + d * t)).norm()
    };
    let cross = |o: Point2<f64>, p: Point2<f64>, q: Point2<f64>| (p - o).perp(&(q - o));
    let (d1, d2) = (cross(b0, b1, a0), cross(b0, b1, a1));
    let (d3, d4) = (cross(a0, a1, b0), cross(a0, a1, b1));
    if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
        return 0.0;
    }
    [
        to_segment(a0, b0, b1),
        to_segment(a1, b0, b1),
        to_segment(b0, a0, a1),
        to_segment(b1, a0, a1),
    ]
    .into_iter()
    .fold(f64::INFINITY, f64::min)
}

/// Distance between two polylines (a single point is a polyline of one segment).
pub fn polyline_distance(a: &[Point2<f64>], b: &[Point2<f64>]) -> f64 {
    let segments = |p: &[Point2<f64>]| -> Vec<(Point2<f64>, Point2<f64>)> {
        match p {
            [only] => vec![(*only, *only)],
            many => many.windows(2).map(|w| (w[0], w[1])).collect(),
        }
    };
    let (a, b) = (segments(a), segments(b));
    a.iter()
        .flat_map(|(a0, a1)| b.iter().map(move |(b0, b1)| segment_distance(*a0, *a1, *b0, *b1)))
        .fold(f64::INFINITY, f64::min)
}

/// The spanwise offset of every solid (m, along the station z axis), per body in
/// [`FlapMechanism::bodies`] order, per solid in the body's order: the kind's own when it
/// gives any, else the layout of the [module docs](self).
///
/// Errors: pose errors of a mechanism that cannot run its own deployment.
pub fn spanwise_layout(mechanism: &dyn FlapMechanism) -> Result<Vec<Vec<f64>>> {
    let bodies = mechanism.bodies();
    let given: Vec<Vec<f64>> = bodies
        .iter()
        .map(|b| b.solids.iter().map(|s| s.offset_m).collect())
        .collect();
    if given.iter().flatten().any(|&o| o != 0.0) {
        return Ok(given);
    }
    // Every solid with its body, by a flat index.
    // In the order they claim the station plane: what carries the flap first (its
    // fittings, links, carriages, tracks), then the actuator, then the support structure.
    let mut solids: Vec<(usize, usize)> = bodies
        .iter()
        .enumerate()
        .flat_map(|(b, body)| (0..body.solids.len()).map(move |s| (b, s)))
        .collect();
    let priority = |role: BodyRole| match role {
        BodyRole::Flap | BodyRole::AftFlap => 0,
        BodyRole::Link => 1,
        BodyRole::Carriage => 2,
        BodyRole::Track => 3,
        BodyRole::Actuator => 4,
        BodyRole::Support => 5,
    };
    solids.sort_by_key(|&(b, _)| priority(bodies[b].role));
    let name = |(b, s): (usize, usize)| bodies[b].solids[s].name.as_str();
    let index_of = |solid: &str| solids.iter().position(|&k| name(k) == solid);
    // Groups that share a layer: every solid of one body (a rigid part stands where it
    // stands), and the solids a prismatic joint or a pin in a slot holds on one axis (a
    // nut on its screw, a pin in its track). Solids of a revolute joint may sit on two
    // layers: a pin spans them.
    let mut group: Vec<usize> = (0..solids.len()).collect();
    fn root(group: &mut [usize], mut i: usize) -> usize {
        while group[i] != i {
            group[i] = group[group[i]];
            i = group[i];
        }
        i
    }
    let join = |group: &mut Vec<usize>, i: usize, j: usize| {
        let (ri, rj) = (root(group, i), root(group, j));
        group[ri.max(rj)] = ri.min(rj);
    };
    for i in 0..solids.len() {
        for j in i + 1..solids.len() {
            // A compact rigid part (an actuator with its housing, a link, a carriage)
            // stands on one layer; the flap's fittings (brackets along a long body) and
            // the struts of a support or a track each may stand at their own place.
            let (bi, bj) = (solids[i].0, solids[j].0);
            let compact = matches!(
                bodies[bi].role,
                BodyRole::Actuator | BodyRole::Link | BodyRole::Carriage
            );
            if bi == bj && compact {
                join(&mut group, i, j);
            }
        }
    }
    for joint in mechanism.joints() {
        if matches!(joint.geometry, JointGeometry::Revolute { .. }) {
            continue;
        }
        for (a, b) in &joint.touching_solids {
            if let (Some(i), Some(j)) = (index_of(a), index_of(b)) {
                join(&mut group, i, j);
            }
        }
    }
    let group: Vec<usize> = (0..solids.len()).map(|i| root(&mut group, i)).collect();
    // Solids touching by design meet at their joint whatever their layers (a pin spans
    // them): they never conflict.
    let touching = |i: usize, j: usize| {
        mechanism.joints().iter().any(|joint| {
            joint.touching_solids.iter().any(|(a, b)| {
                (a == name(solids[i]) && b == name(solids[j])) || (b == name(solids[i]) && a == name(solids[j]))
            })
        })
    };
    let r_max = bodies
        .iter()
        .flat_map(|b| b.solids.iter().map(|s| s.shape.radius_m()))
        .fold(0.0, f64::max);
    // Layers clear each other by r_max; solids closer than a quarter of it in the plane
    // go on different layers.
    let (gap, near) = (r_max, r_max / 4.0);
    // Conflicts between groups: solids of different groups that come within their radii
    // plus `near` in some pose (what one group holds, the check judges).
    let range = mechanism.input_range();
    let mut conflicts = vec![vec![false; solids.len()]; solids.len()];
    for input in range.samples(LAYOUT_SAMPLES) {
        let pose = mechanism.pose(input)?;
        let posed: Vec<Vec<Point2<f64>>> = solids
            .iter()
            .map(|&(b, s)| posed_shape(&bodies[b].solids[s].shape, &pose.bodies[b]).skeleton())
            .collect();
        for i in 0..solids.len() {
            for j in i + 1..solids.len() {
                let (gi, gj) = (group[i], group[j]);
                if gi == gj || conflicts[gi][gj] || touching(i, j) {
                    continue;
                }
                let reach = bodies[solids[i].0].solids[solids[i].1].shape.radius_m()
                    + bodies[solids[j].0].solids[solids[j].1].shape.radius_m()
                    + near;
                if polyline_distance(&posed[i], &posed[j]) < reach {
                    conflicts[gi][gj] = true;
                    conflicts[gj][gi] = true;
                }
            }
        }
    }
    // Greedy colouring of the groups in solid order, each on the layer of a group it
    // touches where it can; colour k at 0, -s, +s, -2s, +2s, ...
    let mut colour: Vec<Option<usize>> = vec![None; solids.len()];
    for i in 0..solids.len() {
        let g = group[i];
        if colour[g].is_some() {
            continue;
        }
        let taken: Vec<usize> = (0..solids.len())
            .filter(|&other| conflicts[g][other])
            .filter_map(|other| colour[other])
            .collect();
        // A group that touches an already placed group (at a revolute joint) joins its
        // layer where it can: the pin is then shortest.
        let members: Vec<usize> = (0..solids.len()).filter(|&m| group[m] == g).collect();
        let partner = (0..solids.len())
            .filter(|&other| group[other] != g && members.iter().any(|&m| touching(m, other)))
            .filter_map(|other| colour[group[other]])
            .find(|k| !taken.contains(k));
        colour[g] = partner.or_else(|| (0..).find(|k| !taken.contains(k)));
    }
    let spacing = 2.0 * r_max + gap;
    let offset = |k: usize| {
        let step = k.div_ceil(2) as f64 * spacing;
        match k {
            0 => 0.0,
            odd if odd % 2 == 1 => -step,
            _ => step,
        }
    };
    let mut offsets = given;
    for (i, &(b, s)) in solids.iter().enumerate() {
        offsets[b][s] = colour[group[i]].map_or(0.0, offset);
    }
    Ok(offsets)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segments_that_cross_touch_and_parallel_ones_keep_their_gap() {
        let p = Point2::new;
        assert_eq!(
            segment_distance(p(0.0, 0.0), p(1.0, 1.0), p(0.0, 1.0), p(1.0, 0.0)),
            0.0
        );
        assert!((segment_distance(p(0.0, 0.0), p(1.0, 0.0), p(0.0, 0.5), p(1.0, 0.5)) - 0.5).abs() < 1e-15);
        assert!((polyline_distance(&[p(2.0, 0.0)], &[p(0.0, 0.0), p(1.0, 0.0)]) - 1.0).abs() < 1e-15);
    }
}
