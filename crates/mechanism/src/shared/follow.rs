//! The motion a station follows when another station of its rigid flap was synthesised
//! first (issue 37, "one flap, one motion").
//!
//! Two stations carry one rigid flap. Each station's mechanism is synthesised through the
//! same take-off and landing poses (the rigid flap's, cut by its plane), but a kind with
//! free choices (the link-track's pivot and track slope, the four-bar's pivots) moves the
//! flap between them along a path of its own: two link-tracks searched apart on the
//! transport scene moved its inboard flap 39 mm apart from any rigid motion at 44 % of the
//! deployment, and the flap then hit the wing. A follower station is instead searched for
//! the mechanism whose flap poses, at the same drive fractions, stay nearest the lead
//! station's motion as its own plane sees it: the caller (which knows the station frames)
//! computes those poses, this module measures how far a candidate is from them.
//!
//! The miss is measured at two points of the stowed flap section, near its leading and
//! trailing edges ([`FollowedMotion::miss`]); the search adds [`FOLLOW_WEIGHT`] times the
//! miss in flap chords to its cost.

use nalgebra::{Isometry2, Point2};

/// Weight of the largest miss from the followed motion, in flap chords, in a follower's
/// search cost (depth in flap chords plus weighted load, [`crate::shared::objective`]): a
/// miss of 0.5 % of the flap chord costs as much as a fairing one flap chord deeper, so a
/// follower gives up depth and load before it gives up the flap's rigid motion (the
/// attachments' spherical bearings take up millimetres, not centimetres). On the transport
/// scene's inboard flap with link-tracks, weights 20 and 100 left the fitted flap 2.4 mm
/// from the wing (3 mm required); 200 clears it.
pub const FOLLOW_WEIGHT: f64 = 200.0;

/// Chord fractions (from the stowed flap's leading edge) of the two points the miss is
/// measured at.
pub const MISS_CHORD_FRACTIONS: [f64; 2] = [0.05, 0.95];

/// The points a miss is measured at: the stowed flap section's chord line at
/// [`MISS_CHORD_FRACTIONS`] (station frame, m); fewer where the outline has no flap.
pub fn miss_points(outline: &crate::shared::outline::StationOutline) -> Vec<Point2<f64>> {
    MISS_CHORD_FRACTIONS
        .iter()
        .filter_map(|&chord_fraction| {
            outline.flap_point(crate::shared::outline::FlapPoint {
                chord_fraction,
                depth_fraction: 0.0,
            })
        })
        .collect()
}

/// The flap poses a follower station should reach, in its own station frame.
#[derive(Debug, Clone, PartialEq)]
pub struct FollowedMotion {
    /// The station followed (synthesised first on the flap).
    pub station: String,
    /// The flap's displacement from stowed at evenly spaced drive fractions, 0 to 1 (at
    /// least two).
    pub flap_poses: Vec<Isometry2<f64>>,
    /// The followed station's moving flap attachments at the same places of this station's
    /// flap section (the similarity of the two sections' chord lines, station frame, m): a
    /// search may start from them, as the same mechanism scaled to this section moves the
    /// flap nearly alike.
    pub attachments: Vec<Point2<f64>>,
}

/// What a follower's record says of the motion it followed.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FollowedStation {
    /// The station followed.
    pub station: String,
    /// The largest miss from its motion (m, [`FollowedMotion::miss`]).
    pub miss_m: f64,
}

impl FollowedMotion {
    /// What a follower whose largest miss from this motion is `miss_m` reports.
    pub fn followed(&self, miss_m: f64) -> FollowedStation {
        FollowedStation {
            station: self.station.clone(),
            miss_m,
        }
    }

    /// The drive fraction of sample `k`.
    pub fn fraction(&self, k: usize) -> f64 {
        k as f64 / (self.flap_poses.len().max(2) - 1) as f64
    }

    /// The largest distance (m) over the samples between `points` (stowed flap points,
    /// station frame) moved by `pose_at(fraction)` and by the followed pose; infinite where
    /// a candidate cannot be posed.
    pub fn miss(&self, points: &[Point2<f64>], pose_at: &dyn Fn(f64) -> Option<Isometry2<f64>>) -> f64 {
        let mut worst = 0.0_f64;
        for (k, target) in self.flap_poses.iter().enumerate() {
            let Some(pose) = pose_at(self.fraction(k)) else {
                return f64::INFINITY;
            };
            for p in points {
                worst = worst.max((pose * p - target * p).norm());
            }
        }
        worst
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    #[test]
    fn the_miss_is_the_largest_point_distance_over_the_samples() {
        let motion = FollowedMotion {
            station: "lead".into(),
            flap_poses: (0..=4)
                .map(|k| Isometry2::new(Vector2::new(0.1 * k as f64, 0.0), -0.1 * k as f64))
                .collect(),
            attachments: Vec::new(),
        };
        let points = [Point2::new(0.0, 0.0), Point2::new(-1.0, 0.0)];
        // Its own motion misses by nothing.
        let own = |s: f64| Some(Isometry2::new(Vector2::new(0.4 * s, 0.0), -0.4 * s));
        assert!(motion.miss(&points, &own) < 1e-15);
        // Shifted 3 mm up at every sample: 3 mm.
        let shifted = |s: f64| Some(Isometry2::new(Vector2::new(0.4 * s, 0.003), -0.4 * s));
        assert!((motion.miss(&points, &shifted) - 0.003).abs() < 1e-15);
        // Turned 0.01 rad more at the end only: the trailing point, 1 m off the pivot,
        // misses by 2 sin(0.005) m there.
        let turned = |s: f64| Some(Isometry2::new(Vector2::new(0.4 * s, 0.0), -0.4 * s - 0.01 * s.powi(8)));
        assert!((motion.miss(&points, &turned) - 2.0 * 0.005f64.sin()).abs() < 1e-12);
        // A candidate that cannot be posed misses infinitely.
        assert_eq!(motion.miss(&points, &|_| None), f64::INFINITY);
    }
}
