//! The hooked-track's wing-fixed solids kept clear of the moving flap: the rail, the screw,
//! the jack body and the two struts, with their radii, at every sampled pose of the
//! deployment (and, where the support is a truss, its tie and brace: the `truss` module
//! places them with the same [`Clearance`]).
//!
//! Why the search has to: the interference check cuts the flap's slot only for the solids
//! a joint names in touch with the flap (`flapwright_interference`'s `joined_solids`: the
//! hook, which carries the roller, and the carriage, pinned to the fitting). The rail, the
//! screw, the jack body and the struts it checks against the whole flap, each in its own
//! spanwise layer. A centre line out of the flap's section is not enough: on the transport
//! scene the rail, the screw, the jack body and the struts, whose centre lines the search
//! kept out of the flap, entered it by 5-152 mm.
//!
//! Each solid is checked in the station plane as a capsule against the flap's section
//! moved by every sampled pose, keeping `radius + margin + allowance` from it:
//! - the margin ([`Clearance::margin_m`], [`MARGIN_CHORD_FRACTION`] of the flap chord)
//!   stands for the check's required clearance, which the kind is not told (3 mm on every
//!   shipped scene, 0.1-0.7 % of their flap chords of 0.44-2.6 m), and for what the plane
//!   does not see: each solid stands in a layer beside the plane, where the tapered flap's
//!   section differs, and the check moves the flap by the rigid motion fitted to all its
//!   stations (up to 20 mm, 0.8 % of the chord, from this station's on the transport's
//!   inboard flap: the report's `flap_motion_miss`);
//! - the allowance is half the farthest any point of the flap moves between two samples:
//!   a rigid displacement moves the points of a box farthest at its corners (|t + (R - I) p|
//!   is convex in p), so half the largest corner travel of the flap section's box bounds
//!   how much nearer the flap can come between samples than at the nearer one, for motion
//!   close to linear over a step.

use nalgebra::{Isometry2, Point2};

use super::HookedTrackSpec;
use flapwright_mechanism::shared::outline::{extent_x, segment_distance};

/// The margin every wing-fixed solid keeps from the flap beyond its radius and the
/// sampling allowance, fraction of the flap chord (see the module doc). A judgement: with
/// the link radius (3 %), the placement's margin for struts, the search found the same
/// clear mechanisms or deeper ones (transport ib-outer 65.7 % of the chord deep against
/// 60.8 %, its screw load 62 kN against 30 kN).
pub(super) const MARGIN_CHORD_FRACTION: f64 = 0.01;

/// The moving flap's sampled poses and what a fixed solid must keep from it.
#[derive(Debug, Clone)]
pub(super) struct Clearance {
    /// The flap's poses (station frame from stowed flap).
    pub(super) poses: Vec<Isometry2<f64>>,
    /// Their inverses: a fixed point in the stowed flap's terms.
    backs: Vec<Isometry2<f64>>,
    /// The stowed flap section's box, lower and upper corners (m).
    flap_box: (Point2<f64>, Point2<f64>),
    /// Half the farthest a flap point moves between two poses (m).
    pub(super) allowance_m: f64,
    /// What every solid keeps beyond its radius besides the allowance (m).
    pub(super) margin_m: f64,
}

impl Clearance {
    /// The clearance of the flap of `spec` at `poses` (in deployment order).
    pub(super) fn new(spec: &HookedTrackSpec, poses: Vec<Isometry2<f64>>) -> Self {
        let flap = &spec.outline.flap;
        let (x_low, x_high) = extent_x(flap).unwrap_or((0.0, 0.0));
        let flap_chord = x_high - x_low;
        let (y_low, y_high) = flap
            .iter()
            .flatten()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p.y), hi.max(p.y))
            });
        let corners = [
            Point2::new(x_low, y_low),
            Point2::new(x_low, y_high),
            Point2::new(x_high, y_low),
            Point2::new(x_high, y_high),
        ];
        let allowance_m = 0.5
            * poses
                .windows(2)
                .flat_map(|pair| corners.iter().map(move |&c| (pair[1] * c - pair[0] * c).norm()))
                .fold(0.0, f64::max);
        Self {
            backs: poses.iter().map(Isometry2::inverse).collect(),
            poses,
            flap_box: (Point2::new(x_low, y_low.min(y_high)), Point2::new(x_high, y_high)),
            allowance_m,
            margin_m: MARGIN_CHORD_FRACTION * flap_chord,
        }
    }

    /// What a solid of `radius_m` keeps from the flap's section at the samples (m).
    pub(super) fn reach_m(&self, radius_m: f64) -> f64 {
        radius_m + self.margin_m + self.allowance_m
    }

    /// `Ok` when the fixed capsule `a`-`b` of `radius_m` keeps [`Self::reach_m`] from the
    /// flap at every pose; else the first pose (its index) where it does not and the
    /// distance of its centre line from the flap's section there (m).
    pub(super) fn clear_of_flap(
        &self,
        spec: &HookedTrackSpec,
        a: Point2<f64>,
        b: Point2<f64>,
        radius_m: f64,
    ) -> Result<(), (usize, f64)> {
        let reach = self.reach_m(radius_m);
        let (low, high) = self.flap_box;
        for (k, back) in self.backs.iter().enumerate() {
            let (p, q) = (back * a, back * b);
            // A segment whose box, widened by the reach, misses the flap's box keeps
            // more than the reach from it.
            let apart = p.x.max(q.x) + reach < low.x
                || p.x.min(q.x) - reach > high.x
                || p.y.max(q.y) + reach < low.y
                || p.y.min(q.y) - reach > high.y;
            if !apart && !spec.outline.flap.segment_clear_by(p, q, reach) {
                return Err((k, segment_distance(&spec.outline.flap, p, q)));
            }
        }
        Ok(())
    }

    /// True when the fixed capsule `a`-`b` of `radius_m` keeps `radius_m` plus the margin
    /// from the structure (spars, a torque tube) and its centre line crosses the wing only
    /// through the trailing-edge bay, `radius_m` plus the margin below the upper skin
    /// ([`flapwright_mechanism::shared::outline::StationOutline::through_bay_only`]): the
    /// skin there is opened for the mechanism, the upper skin and the shroud are not.
    pub(super) fn clear_of_wing(&self, spec: &HookedTrackSpec, a: Point2<f64>, b: Point2<f64>, radius_m: f64) -> bool {
        let outline = &spec.outline;
        let reach = radius_m + self.margin_m;
        outline.structure.segment_clear_by(a, b, reach)
            && (!outline.wing.segment_meets(a, b) || outline.through_bay_only(a, b, reach))
    }
}

/// Where the two struts stand: from the rail's forward end to `rail_top`, and from the
/// hook's centre line at vertex `hook_foot` to `hook_top` (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Struts {
    /// The rail's strut's top: on the lower skin, or at the rear spar's web.
    pub(super) rail_top: Point2<f64>,
    /// The vertex of the hook's centre line (`bodies::hook_centre_line`) where its strut
    /// holds it.
    pub(super) hook_foot: usize,
    /// The hook's strut's top, on the lower skin.
    pub(super) hook_top: Point2<f64>,
}

/// The struts of a rail starting at `rail_start` and a hook along `hook_line`, each clear of
/// the structure and, with [`Clearance::reach_m`], of the flap at every sampled pose:
/// the rail's strut up to the lower skin (`placement::strut_top`, the nearest top ahead of
/// the cove that clears), else forward to the rear spar's web ([`web_strut_top`]); the
/// hook's strut from the hook's middle vertex, else from the vertex nearest to it that has
/// a clear strut to the lower skin (its own top, not the rail's). `Err` names the strut
/// none of whose candidates clears.
pub(super) fn place_struts(
    spec: &HookedTrackSpec,
    clearance: &Clearance,
    rail_start: Point2<f64>,
    hook_line: &[Point2<f64>],
) -> Result<Struts, &'static str> {
    let radius = spec.hardware.link_radius_m;
    let margin = clearance.margin_m + clearance.allowance_m;
    let strut = |from: Point2<f64>, avoid: Option<Point2<f64>>| {
        flapwright_mechanism::shared::placement::strut_top(
            &spec.outline,
            from,
            &flapwright_mechanism::shared::placement::STRUT_TOPS_AHEAD,
            radius,
            margin,
            &clearance.poses,
            avoid,
        )
    };
    let rail_top = strut(rail_start, None)
        .or_else(|| web_strut_top(spec, clearance, rail_start))
        .ok_or("strut-rail")?;
    // The hook's vertices from the middle outwards: the middle first, the clamp that
    // leaves the shortest cantilever to either end.
    let middle = hook_line.len() / 2;
    let feet = (0..hook_line.len()).map(|k| {
        let step = k.div_ceil(2);
        if k % 2 == 1 {
            middle.checked_sub(step)
        } else {
            Some(middle + step).filter(|&i| i < hook_line.len())
        }
    });
    feet.flatten()
        .find_map(|foot| {
            strut(hook_line[foot], Some(rail_top)).map(|hook_top| Struts {
                rail_top,
                hook_foot: foot,
                hook_top,
            })
        })
        .ok_or("strut-hook")
}

/// Where the rail's strut meets the rear spar's web when no strut to the lower skin keeps
/// clear: the rail starts at the stowed carriage under the flap, in the cove, where the
/// flap's nose may leave no room for a strut up or forward to the skin; this one runs
/// forward at the rail's height (within the web's, two strut radii from either skin)
/// through the cove wall into the trailing-edge bay, as a track beam does, and stops short
/// of the web by one and a half strut radii (its end fitting, bolted to the web by design).
/// Taken when the whole strut, with its radius, keeps [`Clearance::reach_m`] from the flap
/// at every sampled pose, its centre line crosses the wing only through the bay with its
/// radius and the margin below the upper skin, and it keeps its radius and the margin
/// from other structure (a torque tube, an intermediate spar) short of its end fitting.
pub(super) fn web_strut_top(
    spec: &HookedTrackSpec,
    clearance: &Clearance,
    rail_start: Point2<f64>,
) -> Option<Point2<f64>> {
    let outline = &spec.outline;
    let radius = spec.hardware.link_radius_m;
    let (face, lo, hi) = outline.rear_web()?;
    if hi - lo <= 4.0 * radius || face <= rail_start.x {
        return None;
    }
    let top = Point2::new(
        face - 1.5 * radius,
        rail_start.y.clamp(lo + 2.0 * radius, hi - 2.0 * radius),
    );
    let reach = radius + clearance.margin_m;
    let length = (top - rail_start).norm();
    if length <= reach {
        return None;
    }
    let short = top + (rail_start - top) * (reach / length);
    let clear = clearance.clear_of_flap(spec, rail_start, top, radius).is_ok()
        && outline.structure.segment_clear_by(rail_start, short, reach)
        && outline.through_bay_only(rail_start, top, reach);
    clear.then_some(top)
}
