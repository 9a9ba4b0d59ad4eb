//! Gap and overlap of the flap behind the main wing, measured in a station plane.
//!
//! Definitions (Zaccai, Bertels, Vos `003`, section 2.1, Fig. 3 step 4): the overlap comes
//! from the flap section's forward-most point, the gap is the shortest distance from the
//! main-wing trailing edge to the flap. Here, in the station frame (x towards the nose,
//! y up, origin A0 on the hinge line):
//!
//! - overlap = x(flap's forward-most point) - x(main-wing trailing edge): positive while the
//!   flap's nose is still under the wing;
//! - gap = distance from the main-wing trailing edge to the flap outline, negative when the
//!   trailing edge lies inside the flap section (the parts collide in this plane);
//! - both also as % of the local clean chord c = x(wing nose) - x(stowed flap trailing
//!   edge), the chord `003` quotes its settings in (B777 study: take-off 0 %c gap, 3 %c
//!   overlap; landing 2 %c gap, 0 %c overlap).
//!
//! The main-wing trailing edge is the upper lip of the cove, where a shroud would end: the
//! aft-most end of the upper skin, the upper skin being the section's edges whose outward
//! normal points up (within [`UPPER_SKIN_MAX_NORMAL_TILT_DEG`] of the station's y axis). A
//! cove wall faces aft and a lower skin down, so neither can take its place, and the lip is
//! found at any airfoil resolution; a closed trailing edge without a cove is its own lip.
//! A blunt lip (a shroud that ends in a base 0.05 %c thick) is the upper corner and the
//! aft-facing edges below it down to the lower corner ([`FlapBehindWing::lip`]): the gap is
//! measured from the nearest point of it, as the flow sees the slot's throat (measured from
//! the upper corner alone, the slot at `transport-flap`'s ob-outer read 2.8 mm wider than
//! it is). The overlap is still measured from the upper corner, `003_...`'s trailing edge.
//! (An earlier rule took the highest point within 1 % chord of the aft-most point: on a
//! cambered upper skin that is the front of the band, 14-16 mm ahead of the lip in the
//! default scene.)
//!
//! The flap moves rigidly in the station plane: [`FlapBehindWing::at_displacement`] takes
//! any planar displacement (a mechanism's pose of the flap), [`FlapBehindWing::at_rotation`]
//! a turn about A0 (a fixed hinge line, exact in a plane perpendicular to it).

use nalgebra::{Isometry2, Point2};
use serde::Serialize;

use crate::boundary::distance_to_segment_m;
use crate::error::{finite, Error, Result};
use crate::section::{polygons_contain, signed_area_m2};

/// An edge of the wing section belongs to the upper skin when its outward normal leans at
/// most this far (deg) from the station's y axis (up). Upper skins near a trailing edge slope
/// by under 20 deg even with twist and skew; cove walls face aft (about 90 deg).
pub const UPPER_SKIN_MAX_NORMAL_TILT_DEG: f64 = 45.0;

/// Height resolution (m) of [`FlapBehindWing::displacement_for_setting`]: the gap is met
/// to this, well inside the 1e-9 m the mechanisms meet their precision positions to.
pub const SETTING_HEIGHT_TOLERANCE_M: f64 = 1e-12;

/// Gap and overlap at one flap rotation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GapOverlap {
    /// Flap rotation from stowed (rad), trailing edge down positive.
    pub rotation_rad: f64,
    /// Gap (m); negative inside the flap.
    pub gap_m: f64,
    /// Gap, % of the local clean chord.
    pub gap_percent_chord: f64,
    /// Overlap (m); positive while the flap nose is ahead of the trailing edge.
    pub overlap_m: f64,
    /// Overlap, % of the local clean chord.
    pub overlap_percent_chord: f64,
}

/// The main wing's trailing edge and the stowed flap in one station plane, ready to measure
/// gap and overlap at any flap rotation.
#[derive(Debug, Clone, PartialEq)]
pub struct FlapBehindWing {
    trailing_edge: Point2<f64>,
    lip: Vec<Point2<f64>>,
    flap_stowed: Vec<Vec<Point2<f64>>>,
    chord_m: f64,
}

fn extent_x(polygons: &[Vec<Point2<f64>>]) -> Option<(f64, f64)> {
    polygons.iter().flatten().map(|p| p.x).fold(None, |acc, x| match acc {
        None => Some((x, x)),
        Some((lo, hi)) => Some((lo.min(x), hi.max(x))),
    })
}

/// The aft-most (smallest x) end of an upper-skin edge of the wing section: the upper lip of
/// the cove (see the module doc). Ties go to the higher point. `None` when no edge faces up.
fn upper_lip(wing: &[Vec<Point2<f64>>]) -> Option<Point2<f64>> {
    let cos_tilt = UPPER_SKIN_MAX_NORMAL_TILT_DEG.to_radians().cos();
    let mut lip: Option<Point2<f64>> = None;
    for polygon in wing {
        let orientation = signed_area_m2(polygon).signum();
        for (a, b) in polygon.iter().zip(polygon.iter().cycle().skip(1)) {
            let edge = b - a;
            let length = edge.norm();
            // Outward normal of a counter-clockwise polygon: the edge turned clockwise.
            let normal_y = -orientation * edge.x;
            if !(length > 0.0 && normal_y >= cos_tilt * length) {
                continue;
            }
            for p in [a, b] {
                let aft_of_lip = lip.is_none_or(|l| p.x < l.x || (p.x == l.x && p.y > l.y));
                if aft_of_lip {
                    lip = Some(*p);
                }
            }
        }
    }
    lip
}

/// The deepest a blunt trailing edge's base may reach below its upper corner to count as the
/// lip, as a fraction of the local clean chord: a shroud's base is 0.05 %c; a cove wall
/// with no shroud (several %c deep) is the wing's aft face, not its trailing edge.
pub const LIP_MAX_DEPTH_CHORD_FRACTION: f64 = 0.005;

/// The lip from its upper corner `upper` (a vertex of `wing`) down the aft-facing edges that
/// follow it away from the upper skin, while they stay within `max_depth_m` of it: the blunt
/// trailing edge's base, to its lower corner. An edge faces aft when its outward normal
/// leans at most [`UPPER_SKIN_MAX_NORMAL_TILT_DEG`] from the station's -x axis. Just
/// `[upper]` for a sharp edge.
fn lip_from(wing: &[Vec<Point2<f64>>], upper: Point2<f64>, max_depth_m: f64) -> Vec<Point2<f64>> {
    let cos_tilt = UPPER_SKIN_MAX_NORMAL_TILT_DEG.to_radians().cos();
    for polygon in wing {
        let n = polygon.len();
        let Some(start) = polygon.iter().position(|p| *p == upper) else {
            continue;
        };
        let orientation = signed_area_m2(polygon).signum();
        // Outward normal of an edge a -> b of a counter-clockwise polygon: the edge turned
        // clockwise, (edge.y, -edge.x); walked backwards the edge's direction flips.
        let faces_aft = |a: Point2<f64>, b: Point2<f64>, forwards: bool| {
            let edge = if forwards { b - a } else { a - b };
            let normal_x = orientation * edge.y;
            let length = edge.norm();
            length > 0.0 && -normal_x >= cos_tilt * length
        };
        for forwards in [true, false] {
            let step = |i: usize| if forwards { (i + 1) % n } else { (i + n - 1) % n };
            let mut lip = vec![upper];
            let mut at = start;
            while lip.len() < n
                && faces_aft(polygon[at], polygon[step(at)], forwards)
                && (upper - polygon[step(at)]).norm() <= max_depth_m
            {
                at = step(at);
                lip.push(polygon[at]);
            }
            if lip.len() > 1 {
                return lip;
            }
        }
    }
    vec![upper]
}

/// The shortest distance between the segments `a`-`b` and `c`-`d` (0 where they cross).
fn segment_distance(a: Point2<f64>, b: Point2<f64>, c: Point2<f64>, d: Point2<f64>) -> f64 {
    let cross = |o: Point2<f64>, p: Point2<f64>, q: Point2<f64>| (p - o).perp(&(q - o));
    let (d1, d2, d3, d4) = (cross(c, d, a), cross(c, d, b), cross(a, b, c), cross(a, b, d));
    if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
        return 0.0;
    }
    distance_to_segment_m(&a, &c, &d)
        .min(distance_to_segment_m(&b, &c, &d))
        .min(distance_to_segment_m(&c, &a, &b))
        .min(distance_to_segment_m(&d, &a, &b))
}

impl FlapBehindWing {
    /// From the wing section's polygons and the stowed flap section's polygons (station
    /// frame, m; closed, last point not repeated).
    pub fn new(wing: &[Vec<Point2<f64>>], flap_stowed: &[Vec<Point2<f64>>]) -> Result<Self> {
        let empty = |part: &'static str| Error::TooFew {
            quantity: part,
            value: 0,
            minimum: 3,
        };
        for polygon in wing.iter().chain(flap_stowed) {
            for p in polygon {
                finite("section point x (m)", p.x)?;
                finite("section point y (m)", p.y)?;
            }
        }
        let (_, wing_nose) = extent_x(wing).ok_or_else(|| empty("wing section points"))?;
        let (flap_trailing_edge, _) = extent_x(flap_stowed).ok_or_else(|| empty("flap section points"))?;
        if flap_stowed.iter().any(|p| p.len() < 3) || wing.iter().any(|p| p.len() < 3) {
            return Err(empty("points of a section polygon"));
        }
        let chord_m = wing_nose - flap_trailing_edge;
        if chord_m <= 0.0 {
            return Err(Error::FlapNotBehindWing { chord_m });
        }
        let trailing_edge = upper_lip(wing).ok_or_else(|| empty("upper-skin edges of the wing section"))?;
        Ok(Self {
            trailing_edge,
            lip: lip_from(wing, trailing_edge, LIP_MAX_DEPTH_CHORD_FRACTION * chord_m),
            flap_stowed: flap_stowed.to_vec(),
            chord_m,
        })
    }

    /// The same measure with the local clean chord taken to the trailing edge of
    /// `whole_flap` (a two-element flap's sections: the percentages are of the chord to the
    /// aft element's trailing edge, the gap and overlap still the measured element's).
    ///
    /// Errors: [`Error::TooFew`] for no points, [`Error::FlapNotBehindWing`] for a chord that
    /// is not positive.
    pub fn with_chord_to(self, whole_flap: &[Vec<Point2<f64>>]) -> Result<Self> {
        let too_few = Error::TooFew {
            quantity: "flap section points",
            value: 0,
            minimum: 3,
        };
        // Station x points to the nose: a trailing edge is a smallest x.
        let (own_trailing_edge, _) = extent_x(&self.flap_stowed).ok_or(too_few.clone())?;
        let (whole_trailing_edge, _) = extent_x(whole_flap).ok_or(too_few)?;
        let wing_nose = own_trailing_edge + self.chord_m;
        let chord_m = wing_nose - whole_trailing_edge.min(own_trailing_edge);
        if chord_m.is_nan() || chord_m <= 0.0 {
            return Err(Error::FlapNotBehindWing { chord_m });
        }
        Ok(Self { chord_m, ..self })
    }

    /// The main-wing trailing edge used (station frame, m).
    pub fn trailing_edge(&self) -> Point2<f64> {
        self.trailing_edge
    }

    /// The lip the gap is measured from (station frame, m): the upper corner (the
    /// [`Self::trailing_edge`]) first, then down a blunt trailing edge's base to its lower
    /// corner; the upper corner alone for a sharp edge.
    pub fn lip(&self) -> &[Point2<f64>] {
        &self.lip
    }

    /// The local clean chord (m).
    pub fn chord_m(&self) -> f64 {
        self.chord_m
    }

    /// Gap and overlap with the flap turned by `rotation_rad` about A0.
    pub fn at_rotation(&self, rotation_rad: f64) -> GapOverlap {
        self.at_displacement(&Isometry2::rotation(rotation_rad))
    }

    /// The flap's planar displacement from stowed that gives deflection `deflection_rad`,
    /// gap `gap_m` and overlap `overlap_m` (`003_...` Fig. 3: deflect, then translate the
    /// section to the gap and overlap): the precision position of a flap setting in this
    /// plane. The overlap fixes the translation along x in closed form; the gap is then a
    /// continuous function of the height, searched upwards from a flap a chord below the
    /// trailing edge to the first height that closes the gap to `gap_m` (the flap below the
    /// lip, not above it), and bisected to [`SETTING_HEIGHT_TOLERANCE_M`].
    ///
    /// Errors: [`Error::NotFinite`] for a non-finite argument, [`Error::GapUnreachable`]
    /// when no height gives the gap (an overlap so negative that the flap's nose stays
    /// farther than `gap_m` from the lip).
    pub fn displacement_for_setting(&self, deflection_rad: f64, gap_m: f64, overlap_m: f64) -> Result<Isometry2<f64>> {
        finite("flap setting deflection (rad)", deflection_rad)?;
        finite("flap setting gap (m)", gap_m)?;
        finite("flap setting overlap (m)", overlap_m)?;
        let turn = Isometry2::rotation(deflection_rad);
        let nose_x = self
            .flap_stowed
            .iter()
            .flatten()
            .map(|p| (turn * p).x)
            .fold(f64::NEG_INFINITY, f64::max);
        let shift_x = overlap_m - (nose_x - self.trailing_edge.x);
        let placed = |height: f64| Isometry2::new(nalgebra::Vector2::new(shift_x, height), deflection_rad);
        let excess = |height: f64| self.at_displacement(&placed(height)).gap_m - gap_m;
        // Heights from a chord below to a chord above the stowed flap, in 1 %-chord steps:
        // the gap varies by at most the step between neighbours, so no crossing is missed
        // wider than a step, and the first one from below is the flap under the lip.
        let steps = 200;
        let (low, high) = (-self.chord_m, self.chord_m);
        let mut smallest = f64::INFINITY;
        let mut below = low;
        let mut below_excess = excess(low);
        for k in 1..=steps {
            let height = low + (high - low) * k as f64 / steps as f64;
            let here = excess(height);
            smallest = smallest.min(here + gap_m);
            if below_excess > 0.0 && here <= 0.0 {
                let (mut lo, mut hi) = (below, height);
                while hi - lo > SETTING_HEIGHT_TOLERANCE_M {
                    let mid = 0.5 * (lo + hi);
                    if excess(mid) > 0.0 {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                return Ok(placed(0.5 * (lo + hi)));
            }
            below = height;
            below_excess = here;
        }
        Err(Error::GapUnreachable {
            gap_m,
            overlap_m,
            deflection_deg: deflection_rad.to_degrees(),
            smallest_gap_m: smallest,
        })
    }

    /// Gap and overlap with the flap moved by `displacement` from stowed (station frame):
    /// any planar motion, as a mechanism's pose gives it. `rotation_rad` of the result is
    /// the displacement's rotation.
    pub fn at_displacement(&self, displacement: &Isometry2<f64>) -> GapOverlap {
        let turn = displacement;
        let rotation_rad = displacement.rotation.angle();
        let te = self.trailing_edge;
        let mut distance = f64::INFINITY;
        let mut nose_x = f64::NEG_INFINITY;
        let turned: Vec<Vec<Point2<f64>>> = self
            .flap_stowed
            .iter()
            .map(|polygon| polygon.iter().map(|p| turn * p).collect())
            .collect();
        // The lip's corners inside the flap, each with its depth below the flap's outline.
        let mut depth: f64 = 0.0;
        for &corner in &self.lip {
            if polygons_contain(&turned, &corner) {
                let below = turned
                    .iter()
                    .flat_map(|polygon| polygon.iter().zip(polygon.iter().cycle().skip(1)))
                    .map(|(a, b)| distance_to_segment_m(&corner, a, b))
                    .fold(f64::INFINITY, f64::min);
                depth = depth.max(below);
            }
        }
        let lip_segments: Vec<(Point2<f64>, Point2<f64>)> = match self.lip.as_slice() {
            [one] => vec![(*one, *one)],
            lip => lip.windows(2).map(|w| (w[0], w[1])).collect(),
        };
        for polygon in &turned {
            for (a, b) in polygon.iter().zip(polygon.iter().cycle().skip(1)) {
                for &(c, d) in &lip_segments {
                    distance = distance.min(segment_distance(*a, *b, c, d));
                }
                nose_x = nose_x.max(a.x);
            }
        }
        let gap_m = if depth > 0.0 { -depth } else { distance };
        let overlap_m = nose_x - te.x;
        GapOverlap {
            rotation_rad,
            gap_m,
            gap_percent_chord: 100.0 * gap_m / self.chord_m,
            overlap_m,
            overlap_percent_chord: 100.0 * overlap_m / self.chord_m,
        }
    }
}
