//! Broad phase: where each part can be over the deployment, bounded by boxes, so that pairs
//! that stay far apart are certified without a sweep.
//!
//! The deployment [0, end] is cut into [`SWEPT_BOX_INTERVALS`] equal intervals. On each, a
//! part's points stay within L h / 2 of where they are at the interval's middle (L its speed
//! bound, h the interval's width), so its box at the middle grown by L h / 2 holds the part
//! over the whole interval. Two parts whose boxes stay at least the required clearance
//! apart on every interval are at least that far apart over the whole deployment: the
//! smallest of those box distances is a certified lower bound on their clearance. A fixed
//! part has one box. Where the boxes do not certify a moving triangle mesh (a flap)
//! against a fixed part, the mesh's principal-axes box, posed at each interval's middle and
//! grown alike, is measured against the fixed part's shape itself (as solids:
//! `flapwright_geom::compute_box_separation`): a swept flap's axis-aligned box reaches the
//! spars metres away, its own box does not. Parts of different stations a span apart, and a station's parts
//! against flaps elsewhere on the wing, are certified this way, which keeps the check's
//! cost about linear in the number of stations.

use flapwright_geom::{compute_box_separation, Aabb, OrientedBox};
use nalgebra::Isometry3;
use serde::Serialize;

use crate::error::{Error, Result};
use crate::part::Part;

/// Intervals the deployment is cut into for the swept boxes: 16 keeps a flap's boxes
/// within a few centimetres of its sweep (growth L / 32 per side) for 16 poses per part.
pub const SWEPT_BOX_INTERVALS: usize = 16;

/// Boxes holding a part over each interval of the deployment (one for a fixed part), and
/// for a moving triangle mesh its principal-axes box posed at each interval's middle.
#[derive(Debug, Clone)]
pub(crate) struct SweptBoxes(Vec<Aabb>, Option<SweptOrientedBox>);

/// A moving mesh's principal-axes box at each interval's middle and how much it grows to
/// hold the part over the interval (the same growth as the axis-aligned boxes'). A long
/// swept part (a flap) is far from filling its axis-aligned box, which then reaches the
/// spars; its own box does not.
#[derive(Debug, Clone)]
struct SweptOrientedBox {
    shape_box: OrientedBox,
    poses: Vec<Isometry3<f64>>,
    growth_m: f64,
}

impl SweptBoxes {
    /// The boxes of `part` over the deployment [0, `end`].
    pub(crate) fn of(part: &Part, end: f64) -> Result<Self> {
        let pose_at = |t: f64| {
            part.motion.pose_ac(t).map_err(|source| Error::Pose {
                part: part.name.clone(),
                parameter: t,
                source,
            })
        };
        if !part.is_moving() {
            return Ok(Self(vec![part.shape.compute_aabb(&pose_at(0.0)?)], None));
        }
        let width = end / SWEPT_BOX_INTERVALS as f64;
        let growth = part.motion.speed_bound() * width / 2.0;
        // Each interval's middle posed once, for both kinds of box.
        let poses = (0..SWEPT_BOX_INTERVALS)
            .map(|k| pose_at((k as f64 + 0.5) * width))
            .collect::<Result<Vec<_>>>()?;
        let boxes = poses
            .iter()
            .map(|pose| part.shape.compute_aabb(pose).inflated(growth))
            .collect();
        let oriented = part.shape.compute_oriented_box().map(|shape_box| SweptOrientedBox {
            shape_box,
            poses,
            growth_m: growth,
        });
        Ok(Self(boxes, oriented))
    }

    /// For a moving mesh against `fixed`, a lower bound on their distance from the mesh's
    /// own boxes (each interval's, grown to hold it) against `fixed`'s shape itself, not
    /// its box; `None` for other parts.
    pub(crate) fn lower_bound_to_fixed(&self, fixed: &Part) -> Result<Option<f64>> {
        let Some(oriented) = &self.1 else {
            return Ok(None);
        };
        let fixed_pose = fixed.motion.pose_ac(0.0).map_err(|source| Error::Pose {
            part: fixed.name.clone(),
            parameter: 0.0,
            source,
        })?;
        let mut bound = f64::INFINITY;
        for pose in &oriented.poses {
            let separation =
                compute_box_separation(&oriented.shape_box, pose, oriented.growth_m, &fixed.shape, &fixed_pose)
                    .map_err(|source| Error::Query {
                        part_a: format!("{} (box)", fixed.name),
                        part_b: String::new(),
                        parameter: 0.0,
                        source: Box::new(source),
                    })?;
            bound = bound.min(separation);
            if bound == 0.0 {
                break;
            }
        }
        Ok(Some(bound))
    }

    /// A certified lower bound on the distance between the two parts over the deployment.
    pub(crate) fn lower_bound(&self, other: &SweptBoxes) -> f64 {
        let at = |boxes: &SweptBoxes, k: usize| boxes.0[k.min(boxes.0.len() - 1)];
        (0..self.0.len().max(other.0.len()))
            .map(|k| at(self, k).distance(&at(other, k)))
            .fold(f64::INFINITY, f64::min)
    }
}

/// A pair certified by the broad phase alone.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ApartPair {
    /// Station of the parts, as for a swept pair.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub station: Option<String>,
    /// First part.
    pub part_a: String,
    /// Second part.
    pub part_b: String,
    /// The parts stay at least this far apart over the whole deployment (m).
    pub lower_bound_m: f64,
}
