//! Where a link-track's struts stand: from the link's fixed pivot and from the track's
//! forward end up to the wing's lower skin, each clear of the structure and of the flap at
//! the sampled poses (`shared::placement::strut_top`). The search passes over a mechanism
//! whose struts cannot be placed clear when another's can.

use nalgebra::{Isometry2, Point2};

use super::{search, LinkTrackSpec};

/// Where a link-track's two struts meet the wing's lower skin: from the link's fixed pivot
/// and from the track's forward end, each kept clear of the structure and of the flap at
/// the sampled poses (`shared::placement::strut_top`); `None` where no top clears.
pub(super) struct StrutPlacement {
    pub(super) tops: [Option<Point2<f64>>; 2],
    /// The track's forward and aft ends, a nut's radius beyond the carriage's travel.
    pub(super) track_ends: [Point2<f64>; 2],
}

impl StrutPlacement {
    pub(super) fn of(spec: &LinkTrackSpec, found: &search::Found) -> Self {
        let loop_ = &found.loop_;
        let travel = found.turns[1];
        let samples = flapwright_mechanism::shared::placement::PLACEMENT_SAMPLES;
        let flap_poses: Vec<Isometry2<f64>> = (0..=samples)
            .filter_map(|k| loop_.at(travel * k as f64 / samples as f64).map(|p| p.flap))
            .collect();
        let landing_c = loop_.c + loop_.d.into_inner() * loop_.at(travel).map_or(0.0, |p| p.travel);
        let extra = spec.hardware.nut_radius_m;
        let track_ends = [
            loop_.c - loop_.d.into_inner() * extra,
            landing_c + loop_.d.into_inner() * extra,
        ];
        let margin = spec.hardware.link_radius_m;
        let strut = |from: Point2<f64>, avoid| {
            flapwright_mechanism::shared::placement::strut_top(
                &spec.outline,
                from,
                &flapwright_mechanism::shared::placement::STRUT_TOPS_AHEAD,
                margin,
                margin,
                &flap_poses,
                avoid,
            )
        };
        let first = strut(loop_.o, None);
        let second = strut(track_ends[0], first);
        Self {
            tops: [first, second],
            track_ends,
        }
    }

    pub(super) fn clear(&self) -> bool {
        self.tops.iter().all(Option::is_some)
    }
}
