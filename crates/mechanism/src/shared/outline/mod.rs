//! The station's section outlines as a synthesising kind sees them: the main wing and the
//! stowed flap cut by the station plane (station frame, m; closed polygons, last point not
//! repeated). Kinds place pivots, supports and actuators against them; the planar queries
//! here are small enough that a geometry crate would add more than it saves (parry works in
//! convex pieces and would need the polygons decomposed first). The plain functions scan
//! every edge; [`Polygons`] (the outline's own sections) files the edges by x and y so the
//! searches' millions of queries meet only the few edges near them, with the same answers.

use nalgebra::Point2;
use serde::Serialize;

mod polygons;

pub use polygons::Polygons;

/// The main wing and the stowed flap in one station plane.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct StationOutline {
    /// Main-wing section polygons.
    pub wing: Polygons,
    /// Stowed flap section polygons.
    pub flap: Polygons,
    /// Fixed structure the mechanism must keep clear of: spars, torque tube.
    pub structure: Polygons,
    /// The main wing's trailing edge the gap is measured from: the cove's upper lip, then
    /// down a blunt edge's base to its lower corner (`flapwright_planes`'s
    /// `FlapBehindWing::lip`); empty without one. The flap must not pass through it
    /// between the settings.
    pub lip: Vec<Point2<f64>>,
    /// The clearance the flap keeps from the lip between the settings (m; the scene's
    /// required clearance; 0: it may touch).
    pub lip_clearance_m: f64,
}

fn edges(polygons: &[Vec<Point2<f64>>]) -> impl Iterator<Item = (Point2<f64>, Point2<f64>)> + '_ {
    polygons
        .iter()
        .flat_map(|p| p.iter().zip(p.iter().cycle().skip(1)).map(|(a, b)| (*a, *b)))
}

/// True when `test` holds for an edge of `polygons` (the same edges as [`edges`], each
/// polygon's closing edge first). A plain loop for the queries the synthesis searches call
/// most (the iterator chain of [`edges`] took a fifth of the hooked-track search); each
/// query's answer does not depend on the order of the edges.
fn any_edge(polygons: &[Vec<Point2<f64>>], mut test: impl FnMut(Point2<f64>, Point2<f64>) -> bool) -> bool {
    for polygon in polygons {
        let Some(&last) = polygon.last() else { continue };
        let mut a = last;
        for &b in polygon {
            if test(a, b) {
                return true;
            }
            a = b;
        }
    }
    false
}

/// True when `p` lies inside `polygons` (even-odd rule).
pub fn inside(polygons: &[Vec<Point2<f64>>], p: Point2<f64>) -> bool {
    let mut crossings = 0;
    any_edge(polygons, |a, b| {
        crossings += usize::from(ray_crosses(p, a, b));
        false
    });
    crossings % 2 == 1
}

/// True when the ray from `p` towards +x crosses the edge `a`-`b` (the even-odd rule's
/// count, half-open in y so a vertex is counted once).
fn ray_crosses(p: Point2<f64>, a: Point2<f64>, b: Point2<f64>) -> bool {
    (a.y > p.y) != (b.y > p.y) && a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) > p.x
}

/// Lowest and highest y where the vertical line at `x` crosses `polygons`.
pub fn vertical_span(polygons: &[Vec<Point2<f64>>], x: f64) -> Option<(f64, f64)> {
    let mut span: Option<(f64, f64)> = None;
    any_edge(polygons, |a, b| {
        if let Some(y) = crossing_at(a, b, x) {
            span = Some(span.map_or((y, y), |(lo, hi)| (lo.min(y), hi.max(y))));
        }
        false
    });
    span
}

/// True when the segment `a`-`b` crosses an edge of `polygons` or lies inside them.
///
/// One pass over the edges (the searches call it millions of times): an edge crossed ends
/// it; otherwise the even-odd counts of both ends say whether either lies inside. An edge
/// whose box misses the segment's cannot cross it, and is only counted.
pub fn segment_meets(polygons: &[Vec<Point2<f64>>], a: Point2<f64>, b: Point2<f64>) -> bool {
    let (mut from_a, mut from_b) = (0usize, 0usize);
    let crosses = any_edge(polygons, |c, d| {
        from_a += usize::from(ray_crosses(a, c, d));
        from_b += usize::from(ray_crosses(b, c, d));
        segments_cross(a, b, c, d)
    });
    crosses || from_a % 2 == 1 || from_b % 2 == 1
}

/// True when the segments `a`-`b` and `c`-`d` cross (each one's ends on either side of the
/// other's line); an edge whose box misses the segment's cannot, and is let go first.
fn segments_cross(a: Point2<f64>, b: Point2<f64>, c: Point2<f64>, d: Point2<f64>) -> bool {
    let (low, high) = (a.inf(&b), a.sup(&b));
    if c.x.max(d.x) < low.x || c.x.min(d.x) > high.x || c.y.max(d.y) < low.y || c.y.min(d.y) > high.y {
        return false;
    }
    let orient = |p: Point2<f64>, q: Point2<f64>, r: Point2<f64>| (q - p).perp(&(r - p));
    let (d1, d2) = (orient(a, b, c), orient(a, b, d));
    let (d3, d4) = (orient(c, d, a), orient(c, d, b));
    (d1 > 0.0) != (d2 > 0.0) && (d3 > 0.0) != (d4 > 0.0)
}

/// True when `p` is nearer than `near` to the edge `a`-`b` (an edge whose box is already
/// that far is let go first).
fn edge_nearer_than(p: Point2<f64>, a: Point2<f64>, b: Point2<f64>, near: f64) -> bool {
    let off_x = (a.x.min(b.x) - p.x).max(p.x - a.x.max(b.x));
    let off_y = (a.y.min(b.y) - p.y).max(p.y - a.y.max(b.y));
    off_x < near && off_y < near && point_segment_distance(p, a, b) < near
}

/// The y where the edge `a`-`b` crosses the vertical line at `x`, if it does (half-open in
/// x, so a vertex is met once).
fn crossing_at(a: Point2<f64>, b: Point2<f64>, x: f64) -> Option<f64> {
    ((a.x > x) != (b.x > x)).then(|| a.y + (x - a.x) / (b.x - a.x) * (b.y - a.y))
}

/// Distance from `p` to the segment `a`-`b`.
pub fn point_segment_distance(p: Point2<f64>, a: Point2<f64>, b: Point2<f64>) -> f64 {
    let ab = b - a;
    let t = if ab.norm_squared() > 0.0 {
        ((p - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + ab * t - p).norm()
}

/// Distance from `p` to the nearest edge of `polygons`, inside or out.
pub fn boundary_distance(polygons: &[Vec<Point2<f64>>], p: Point2<f64>) -> f64 {
    let mut nearest = f64::INFINITY;
    any_edge(polygons, |a, b| {
        nearest = nearest.min(point_segment_distance(p, a, b));
        false
    });
    nearest
}

/// Distance from the segment `a`-`b` to `polygons` (0 where it meets or lies inside them).
pub fn segment_distance(polygons: &[Vec<Point2<f64>>], a: Point2<f64>, b: Point2<f64>) -> f64 {
    if polygons.is_empty() {
        return f64::INFINITY;
    }
    if segment_meets(polygons, a, b) {
        return 0.0;
    }
    edges(polygons)
        .map(|(c, d)| edge_segment_distance(c, d, a, b))
        .fold(f64::INFINITY, f64::min)
}

/// Distance between the edge `c`-`d` and the segment `a`-`b` that do not cross: the
/// nearest of the four ends to the other segment.
fn edge_segment_distance(c: Point2<f64>, d: Point2<f64>, a: Point2<f64>, b: Point2<f64>) -> f64 {
    point_segment_distance(c, a, b)
        .min(point_segment_distance(d, a, b))
        .min(point_segment_distance(a, c, d))
        .min(point_segment_distance(b, c, d))
}

/// Smallest and largest x of `polygons`.
pub fn extent_x(polygons: &[Vec<Point2<f64>>]) -> Option<(f64, f64)> {
    polygons.iter().flatten().fold(None, |acc, p| match acc {
        None => Some((p.x, p.x)),
        Some((lo, hi)) => Some((lo.min(p.x), hi.max(p.x))),
    })
}

/// A point on (or on a bracket of) the flap in terms of its section, so that it names the
/// corresponding point at another station of the same flap: `chord_fraction` of the flap
/// chord aft of its leading edge, `depth_fraction` of the flap chord below the lower
/// surface there (negative: above it).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlapPoint {
    /// Aft of the flap's leading edge, fraction of its chord.
    pub chord_fraction: f64,
    /// Below its lower surface, fraction of its chord.
    pub depth_fraction: f64,
}

impl StationOutline {
    /// True when the capsule `a`-`b` of `radius` keeps `margin` clear of the wing and the
    /// structure, and of the flap moved by each of `flap_poses`.
    pub fn capsule_clear(
        &self,
        a: Point2<f64>,
        b: Point2<f64>,
        radius: f64,
        margin: f64,
        flap_poses: &[nalgebra::Isometry2<f64>],
    ) -> bool {
        let reach = radius + margin;
        self.wing.segment_clear_by(a, b, reach)
            && self.structure.segment_clear_by(a, b, reach)
            && flap_poses.iter().all(|pose| {
                let back = pose.inverse();
                self.flap.segment_clear_by(back * a, back * b, reach)
            })
    }

    /// True when the flap moved by `flap` passes through the wing's trailing edge (the lip)
    /// or closer to it than [`Self::lip_clearance_m`], less `tolerance_m` (a gap of exactly
    /// the clearance at a setting passes within rounding). False without a lip. The lip's
    /// corners are checked, not the base between them: on a base of height h the nearest
    /// point may lie between them, at most h²/(8 clearance) nearer (0.09 mm for a 2.5 mm
    /// base and a 9 mm slot).
    ///
    /// One pass over the flap's edges (every deployment sample of every candidate calls it):
    /// an edge nearer than the clearance ends it, else the even-odd count says inside.
    pub fn flap_near_lip(&self, flap: &nalgebra::Isometry2<f64>, tolerance_m: f64) -> bool {
        let back = flap.inverse();
        self.lip.iter().any(|&lip| {
            let at = back * lip;
            self.flap.nearer_than(at, self.lip_clearance_m - tolerance_m) || self.flap.inside(at)
        })
    }

    /// The flap's leading (largest x) and trailing (smallest x) edge x and its chord.
    pub fn flap_chord(&self) -> Option<(f64, f64, f64)> {
        let (te, le) = extent_x(&self.flap)?;
        Some((le, te, le - te))
    }

    /// The area centroid of the stowed flap section (m): a flap's centre of mass when its
    /// skin and ribs are spread like its area.
    pub fn flap_centroid(&self) -> Option<Point2<f64>> {
        let (mut area, mut moment) = (0.0, nalgebra::Vector2::zeros());
        for (a, b) in edges(&self.flap) {
            let twice = a.coords.perp(&b.coords);
            area += 0.5 * twice;
            moment += (a.coords + b.coords) * twice / 6.0;
        }
        (area.abs() > 0.0).then(|| Point2::from(moment / area))
    }

    /// `point` of the stowed flap section in chord terms ([`FlapPoint`]); `None` where no
    /// vertical through it meets the flap.
    pub fn to_flap_point(&self, point: Point2<f64>) -> Option<FlapPoint> {
        let (le, _, chord) = self.flap_chord()?;
        let (lo, _) = self.flap.vertical_span(point.x)?;
        Some(FlapPoint {
            chord_fraction: (le - point.x) / chord,
            depth_fraction: (lo - point.y) / chord,
        })
    }

    /// The point `at` names on this station's stowed flap section (m); `None` where its
    /// chord fraction misses the section.
    pub fn flap_point(&self, at: FlapPoint) -> Option<Point2<f64>> {
        let (le, _, chord) = self.flap_chord()?;
        let x = le - at.chord_fraction * chord;
        let (lo, _) = self.flap.vertical_span(x)?;
        Some(Point2::new(x, lo - at.depth_fraction * chord))
    }

    /// The lowest y of the stowed wing and flap sections (m): what a mechanism's depth below
    /// the section is measured from.
    pub fn section_bottom(&self) -> f64 {
        self.wing
            .iter()
            .chain(self.flap.iter())
            .flatten()
            .map(|p| p.y)
            .fold(f64::INFINITY, f64::min)
    }

    /// The local clean chord: wing nose to stowed flap trailing edge (m).
    pub fn chord_m(&self) -> Option<f64> {
        let (_, nose) = extent_x(&self.wing)?;
        let (_, te, _) = self.flap_chord()?;
        Some(nose - te)
    }

    /// The point of the flap's lower surface at `fraction` of its chord from the leading
    /// edge (stowed).
    pub fn flap_lower_point(&self, fraction: f64) -> Option<Point2<f64>> {
        let (le, _, chord) = self.flap_chord()?;
        let x = le - fraction * chord;
        let (lo, _) = self.flap.vertical_span(x)?;
        Some(Point2::new(x, lo))
    }

    /// The point of the wing's lower surface at `x`.
    pub fn wing_lower_point(&self, x: f64) -> Option<Point2<f64>> {
        self.wing.vertical_span(x).map(|(lo, _)| Point2::new(x, lo))
    }

    /// Lowest y of the stowed wing and flap where the vertical at `x` crosses them.
    pub fn lower_envelope(&self, x: f64) -> Option<f64> {
        let wing = self.wing.vertical_span(x).map(|s| s.0);
        let flap = self.flap.vertical_span(x).map(|s| s.0);
        match (wing, flap) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    /// The rear spar's web in this plane, the aft-most tall structure section ahead of the
    /// cove: its aft face x and the wing's lower and upper skin there (m). The trailing-edge
    /// bay behind it is open (skins, ribs and the mechanism), so an actuator may sit on the
    /// web (`003_...` Fig. 6). `None` without such a web.
    pub fn rear_web(&self) -> Option<(f64, f64, f64)> {
        let lip = self.cove_lower_lip_x()?;
        self.structure
            .iter()
            .filter_map(|polygon| {
                let (aft, fore) = extent_x(std::slice::from_ref(polygon))?;
                let (lo, hi) = polygon.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                    (lo.min(p.y), hi.max(p.y))
                });
                (hi - lo >= 3.0 * (fore - aft) && aft > lip).then_some(aft)
            })
            .min_by(f64::total_cmp)
            .and_then(|aft| self.wing.vertical_span(aft).map(|(lo, hi)| (aft, lo, hi)))
    }

    /// True when the segment `a`-`b` may pass where it does through the wing section: every
    /// sampled point inside the wing lies in the trailing-edge bay (ahead of the cove's
    /// lower lip, at least `margin` below the upper skin), so the segment crosses only the
    /// lower skin or the cove wall, never the upper skin or the shroud over the flap.
    pub fn through_bay_only(&self, a: Point2<f64>, b: Point2<f64>, margin: f64) -> bool {
        let Some(lip) = self.cove_lower_lip_x() else {
            return false;
        };
        const SAMPLES: usize = 32;
        (0..=SAMPLES).all(|k| {
            let p = a + (b - a) * (k as f64 / SAMPLES as f64);
            !self.wing.inside(p)
                || (p.x >= lip && self.wing.vertical_span(p.x).is_some_and(|(_, hi)| p.y <= hi - margin))
        })
    }

    /// How far `p` lies below the stowed wing's and flap's lower contour at its x (m;
    /// negative above it); `None` beyond the sections' chord.
    pub fn depth_below(&self, p: Point2<f64>) -> Option<f64> {
        self.lower_envelope(p.x).map(|y| y - p.y)
    }

    /// Where the wing's lower skin ends at the cove (m): the flap's leading edge x or the
    /// wing's aft end, whichever lies further forward. Supports fixed to the lower skin are
    /// placed ahead of it.
    pub fn cove_lower_lip_x(&self) -> Option<f64> {
        let (wing_aft, _) = extent_x(&self.wing)?;
        let (le, _, _) = self.flap_chord()?;
        Some(le.max(wing_aft))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_queries() {
        let square = vec![vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(0.0, 1.0),
        ]];
        assert!(inside(&square, Point2::new(0.5, 0.5)));
        assert!(!inside(&square, Point2::new(1.5, 0.5)));
        assert_eq!(vertical_span(&square, 0.25), Some((0.0, 1.0)));
        assert!(vertical_span(&square, 2.0).is_none());
        assert!(segment_meets(&square, Point2::new(-1.0, 0.5), Point2::new(2.0, 0.5)));
        assert!(!segment_meets(&square, Point2::new(-1.0, 1.5), Point2::new(2.0, 1.5)));
        // A lip at the square's top edge: touching is not passing through, 0.1 deeper is
        // (no clearance asked).
        let outline = StationOutline {
            flap: square.clone().into(),
            lip: vec![Point2::new(0.5, 1.0)],
            ..Default::default()
        };
        let shifted = |d: f64| nalgebra::Isometry2::translation(0.0, d);
        assert!(!outline.flap_near_lip(&shifted(0.0), 1e-9));
        assert!(outline.flap_near_lip(&shifted(0.1), 1e-9));
        assert!(!outline.flap_near_lip(&shifted(-0.1), 1e-9));
        // With a clearance of 0.05: 0.1 below passes, 0.04 below does not.
        let kept = StationOutline {
            lip_clearance_m: 0.05,
            ..outline.clone()
        };
        assert!(!kept.flap_near_lip(&shifted(-0.1), 1e-9));
        assert!(kept.flap_near_lip(&shifted(-0.04), 1e-9));
        assert!(!kept.flap_near_lip(&shifted(-0.05), 1e-9));
        assert!((boundary_distance(&square, Point2::new(0.5, 0.9)) - 0.1).abs() < 1e-12);
    }

    #[test]
    fn flap_points_name_the_same_place_on_a_scaled_section() {
        let square = |scale: f64| {
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 0.3], [0.0, 0.3]]
                .into_iter()
                .map(|[x, y]| Point2::new(scale * x, scale * y))
                .collect::<Vec<_>>()
        };
        let (small, large) = (
            StationOutline {
                flap: vec![square(1.0)].into(),
                ..Default::default()
            },
            StationOutline {
                flap: vec![square(2.0)].into(),
                ..Default::default()
            },
        );
        let bracket = Point2::new(0.7, -0.2);
        let at = small.to_flap_point(bracket).unwrap();
        assert!((at.chord_fraction - 0.3).abs() < 1e-12 && (at.depth_fraction - 0.2).abs() < 1e-12);
        let there = large.flap_point(at).unwrap();
        assert!((there - Point2::new(1.4, -0.4)).norm() < 1e-12);
        assert!(small
            .flap_point(FlapPoint {
                chord_fraction: 1.5,
                depth_fraction: 0.0
            })
            .is_none());
    }
}
