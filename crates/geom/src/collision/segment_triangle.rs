//! Exact distance between a segment and a triangle (and between two segments), in closed
//! form: the core of capsule-against-mesh and capsule-against-capsule distances.
//!
//! Why: a capsule is a segment swept by a ball of its radius r, so its distance to a
//! triangle is the segment's distance less r (0 when that is negative), and its closest
//! point lies r from the segment's closest point towards the triangle's. parry 0.31 has no
//! capsule-triangle or capsule-capsule case: its dispatcher hands both to GJK on the two
//! support maps, which iterates on the capsule's round support until the gap between its
//! bounds is within sqrt(10 eps) = 4.7e-8 of the distance (so it reads up to that fraction
//! long), and which was 35 % of the 16-station check's profile. The closed form below takes
//! a few dozen flops and is exact to rounding.
//!
//! Method (Ericson, *Real-Time Collision Detection*, 2005, §5.1.9 for two segments; the
//! segment-triangle case as in Eberly, *Distance Between a Segment and a Triangle*, by
//! the same argument): the squared distance between a point of the segment and a point of
//! the triangle is a convex quadratic on the product of the two sets. If the segment
//! crosses the triangle it is 0. Otherwise at a minimum where both points are interior
//! the gradient vanishes, so the connecting vector is normal to the triangle and to the
//! segment: the segment is parallel to the plane, and both points can slide together along
//! it, at the same distance, until one reaches its boundary. So some closest pair has the
//! segment's point at one of its ends or the triangle's point on one of its edges, and the
//! distance is the smallest of: the three segment-edge distances, and each end's distance to
//! the plane where the end projects inside the triangle. A degenerate triangle (no normal)
//! is the union of its edges. Each candidate is the distance of an actual pair of points
//! (never below the true minimum but by rounding), and the minimising pair is among them.
//! Two triangles are the same argument applied to both: an edge of one through the other's
//! face, the nine edge-edge pairs, or a corner over the other's face.
//!
//! Conditioning: the face terms use the triangle's normal, whose direction carries rounding
//! of about eps |v - u| |w - u| / |n|; for a sliver (corners nearly on a line) that is
//! large, as it is for any method (parry's GJK included). A triangle whose corners are
//! exactly on a line is its edges.

use glamx::DVec3;

/// Closest points of two sets and their squared distance (m^2, in the frame of the
/// inputs): candidates are compared squared, and one square root taken at the end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct ClosestPair {
    /// The squared distance between the two points.
    pub distance_squared: f64,
    /// The point of the first set (the segment).
    pub on_first: DVec3,
    /// The point of the second set (the triangle, or the second segment).
    pub on_second: DVec3,
}

impl ClosestPair {
    fn between(on_first: DVec3, on_second: DVec3) -> Self {
        ClosestPair {
            distance_squared: (on_second - on_first).length_squared(),
            on_first,
            on_second,
        }
    }

    /// The distance between the two points (m).
    pub fn distance(&self) -> f64 {
        self.distance_squared.sqrt()
    }

    /// The pair with its two points exchanged.
    fn swapped(self) -> ClosestPair {
        ClosestPair {
            on_first: self.on_second,
            on_second: self.on_first,
            ..self
        }
    }

    fn nearer(self, other: ClosestPair) -> ClosestPair {
        if other.distance_squared < self.distance_squared {
            other
        } else {
            self
        }
    }
}

/// The point of segment `a`-`b` nearest `point` (a zero-length segment is its end).
fn nearest_on_segment(point: DVec3, a: DVec3, b: DVec3) -> DVec3 {
    let direction = b - a;
    let length_squared = direction.length_squared();
    if length_squared == 0.0 {
        return a;
    }
    let fraction = ((point - a).dot(direction) / length_squared).clamp(0.0, 1.0);
    a + direction * fraction
}

/// Closest points of segment `p0`-`p1` (first) and segment `q0`-`q1` (second): the
/// smallest of the four end-to-segment distances and, when the segments are not
/// parallel, the lines' common perpendicular if its feet lie on both segments.
pub(super) fn segment_segment(p0: DVec3, p1: DVec3, q0: DVec3, q1: DVec3) -> ClosestPair {
    let ends = ClosestPair::between(p0, nearest_on_segment(p0, q0, q1))
        .nearer(ClosestPair::between(p1, nearest_on_segment(p1, q0, q1)))
        .nearer(ClosestPair::between(nearest_on_segment(q0, p0, p1), q0))
        .nearer(ClosestPair::between(nearest_on_segment(q1, p0, p1), q1));
    common_perpendicular(p0, p1, q0, q1).map_or(ends, |interior| ends.nearer(interior))
}

/// The feet of the common perpendicular of two segments' lines when the lines are not
/// parallel and both feet lie on the segments (Ericson §5.1.9: s and t solve the 2 x 2
/// normal equations).
fn common_perpendicular(p0: DVec3, p1: DVec3, q0: DVec3, q1: DVec3) -> Option<ClosestPair> {
    let (d1, d2, r) = (p1 - p0, q1 - q0, p0 - q0);
    let (a, e, b) = (d1.dot(d1), d2.dot(d2), d1.dot(d2));
    let (c, f) = (d1.dot(r), d2.dot(r));
    let denominator = a * e - b * b;
    if denominator <= 0.0 {
        return None;
    }
    let s = (b * f - c * e) / denominator;
    let t = (a * f - b * c) / denominator;
    ((0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&t)).then(|| ClosestPair::between(p0 + d1 * s, q0 + d2 * t))
}

/// True when `point` (in the triangle's plane, up to rounding) lies inside the triangle
/// `corners` with normal `normal` (not normalised): on the inner side of all three edges.
fn inside(point: DVec3, corners: &[DVec3; 3], normal: DVec3) -> bool {
    (0..3).all(|i| {
        let (from, to) = (corners[i], corners[(i + 1) % 3]);
        (to - from).cross(point - from).dot(normal) >= 0.0
    })
}

/// The face's part of the module's method for a polyline (a segment, or a triangle's
/// boundary) against the solid triangle `corners`: 0 where an edge (`ends[k]`-`ends[k+1]`,
/// closing the loop for three ends) crosses the face, else each end's distance to its foot
/// on the plane where the foot falls inside, whichever is nearer than `best`. The first
/// point of a pair is the end's. A degenerate triangle has no face: `best` stands.
///
/// # Panics
///
/// With more than three ends (the callers pass two or three).
fn nearer_on_face(ends: &[DVec3], corners: &[DVec3; 3], mut best: ClosestPair) -> ClosestPair {
    let [u, v, w] = *corners;
    let normal = (v - u).cross(w - u);
    let normal_squared = normal.length_squared();
    if normal_squared == 0.0 {
        return best;
    }
    // Two or three ends (no allocation on this hot path).
    let mut heights = [0.0; 3];
    for (height, end) in heights.iter_mut().zip(ends) {
        *height = normal.dot(*end - u);
    }
    let edges = if ends.len() > 2 { ends.len() } else { ends.len() - 1 };
    for k in 0..edges {
        let next = (k + 1) % ends.len();
        let (from, to) = (heights[k], heights[next]);
        if (from < 0.0 && to > 0.0) || (from > 0.0 && to < 0.0) {
            // The edge crosses the plane; where it does may be inside the triangle.
            let crossing = ends[k] + (ends[next] - ends[k]) * (from / (from - to));
            if inside(crossing, corners, normal) {
                return ClosestPair {
                    distance_squared: 0.0,
                    on_first: crossing,
                    on_second: crossing,
                };
            }
        }
    }
    for (end, height) in ends.iter().zip(heights) {
        // An end no nearer the plane than the best pair cannot improve on it.
        if height * height >= best.distance_squared * normal_squared {
            continue;
        }
        let foot = *end - normal * (height / normal_squared);
        if inside(foot, corners, normal) {
            best = best.nearer(ClosestPair::between(*end, foot));
        }
    }
    best
}

/// Closest points of segment `a`-`b` (first) and the solid triangle `corners` (second):
/// the module's method. Exact to rounding for every configuration: a segment parallel to
/// the triangle or in its plane, a zero-length segment, a degenerate triangle.
pub(super) fn segment_triangle(a: DVec3, b: DVec3, corners: &[DVec3; 3]) -> ClosestPair {
    let [u, v, w] = *corners;
    let edges = segment_segment(a, b, u, v)
        .nearer(segment_segment(a, b, v, w))
        .nearer(segment_segment(a, b, w, u));
    nearer_on_face(&[a, b], corners, edges)
}

/// Closest points of the solid triangles `first` and `second`, by the module's argument
/// applied to both: 0 where an edge of one crosses the other's face; otherwise the smallest
/// of the nine edge-edge distances and of each corner's distance to the other's face where
/// its foot falls inside. (Two triangles that meet have an edge of one through the other's
/// face, or meet edge to edge, or one's corner lies on the other's face.)
pub(super) fn triangle_triangle(first: &[DVec3; 3], second: &[DVec3; 3]) -> ClosestPair {
    // The nine edge-edge distances, each corner's distance to the other's edges taken once
    // (a corner ends two edges) rather than in each of its edges' pairs.
    let mut edges = ClosestPair::between(first[0], second[0]);
    for i in 0..3 {
        let (corner, next) = (first[i], first[(i + 1) % 3]);
        for j in 0..3 {
            let (other_corner, other_next) = (second[j], second[(j + 1) % 3]);
            edges = edges
                .nearer(ClosestPair::between(
                    corner,
                    nearest_on_segment(corner, other_corner, other_next),
                ))
                .nearer(ClosestPair::between(
                    nearest_on_segment(other_corner, corner, next),
                    other_corner,
                ));
            if let Some(interior) = common_perpendicular(corner, next, other_corner, other_next) {
                edges = edges.nearer(interior);
            }
        }
    }
    let on_second = nearer_on_face(first, second, edges);
    if on_second.distance_squared == 0.0 {
        return on_second;
    }
    nearer_on_face(second, first, on_second.swapped()).swapped()
}

/// A lower bound on the distance between the convex hull of `points` and the triangle
/// `corners`: how far the points all lie to one side of the triangle's plane (0 when they
/// straddle it or the triangle is degenerate). A few flops against the method's few
/// hundred, for searches that only need to know whether a triangle can beat a bound.
/// Rounding: a height n . (p - u) is off by at most a few eps |v - u| |w - u| |p - u|, which
/// for a sliver (|n| much smaller than |v - u| |w - u|) is a large part of it; that much
/// (8 eps, generously) is taken off the gap, so the bound holds for slivers too.
pub(super) fn plane_gap(points: &[DVec3], corners: &[DVec3; 3]) -> f64 {
    let [u, v, w] = *corners;
    let normal = (v - u).cross(w - u);
    let length = normal.length();
    if length == 0.0 {
        return 0.0;
    }
    let (low, high, reach) = points
        .iter()
        .fold((f64::MAX, f64::MIN, 0.0_f64), |(low, high, reach), point| {
            let height = normal.dot(*point - u);
            (low.min(height), high.max(height), reach.max((*point - u).length()))
        });
    let rounding = 8.0 * f64::EPSILON * (v - u).length() * (w - u).length() * reach;
    let gap = if low > 0.0 {
        low
    } else if high < 0.0 {
        -high
    } else {
        0.0
    };
    ((gap - rounding) / length).max(0.0)
}

impl ClosestPair {
    /// The same pair with the first set swept by a ball of `radius` (a capsule, when the
    /// first set is a segment) and the second by a ball of `second_radius`: the distance
    /// less both radii and the points moved that far towards each other along the pair.
    /// `None` when the swept sets touch or overlap (the distance is then 0 and the pair's
    /// direction says nothing of where they cross).
    pub fn swept(&self, radius: f64, second_radius: f64) -> Option<(f64, DVec3, DVec3)> {
        let distance = self.distance();
        let gap = distance - radius - second_radius;
        if gap <= 0.0 {
            return None;
        }
        let direction = (self.on_second - self.on_first) / distance;
        Some((
            gap,
            self.on_first + direction * radius,
            self.on_second - direction * second_radius,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use parry3d_f64::math::Pose;
    use parry3d_f64::query::{self, PointQuery};
    use parry3d_f64::shape::{Segment, Triangle};

    /// A fixed-seed generator (xorshift64*) of coordinates in [-1, 1).
    struct Coordinates(u64);

    impl Coordinates {
        fn next(&mut self) -> f64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            let bits = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11;
            2.0 * bits as f64 / (1u64 << 53) as f64 - 1.0
        }

        fn point(&mut self) -> DVec3 {
            DVec3::new(self.next(), self.next(), self.next())
        }
    }

    /// parry's segment-triangle distance: GJK on two polytopes, which ends on the exact
    /// minimum (no round support map to creep towards).
    fn parry_segment_triangle(a: DVec3, b: DVec3, corners: &[DVec3; 3]) -> f64 {
        let [u, v, w] = *corners;
        query::distance(
            &Pose::IDENTITY,
            &Segment::new(a, b),
            &Pose::IDENTITY,
            &Triangle::new(u, v, w),
        )
        .unwrap()
        .distance
    }

    /// The pair's points lie on their sets, and the distance is theirs.
    fn assert_points_on_sets(pair: &ClosestPair, a: DVec3, b: DVec3, corners: &[DVec3; 3]) {
        let gap = (pair.on_second - pair.on_first).length();
        assert!((gap - pair.distance()).abs() <= 1e-14, "{pair:?}");
        assert!(
            (nearest_on_segment(pair.on_first, a, b) - pair.on_first).length() <= 1e-14,
            "{pair:?}"
        );
        let [u, v, w] = *corners;
        let on_triangle = Triangle::new(u, v, w).project_local_point(pair.on_second, true).point;
        assert!((on_triangle - pair.on_second).length() <= 1e-14, "{pair:?}");
    }

    #[test]
    fn random_segments_and_triangles_match_parry_to_a_picometre() {
        let mut random = Coordinates(0x5eed_0017);
        let (mut clear, mut crossing) = (0, 0);
        for case in 0..20_000 {
            let (a, b) = (random.point(), random.point());
            let corners = [random.point(), random.point(), random.point()];
            // One case in eight has the segment parallel to the triangle's plane and one in
            // eight has it in the plane: the cases where interior points tie.
            let normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalize();
            let b = match case % 8 {
                0 => b - normal * normal.dot(b - a),
                4 => {
                    let in_plane = |p: DVec3| p - normal * normal.dot(p - corners[0]);
                    check_in_plane(in_plane(a), in_plane(b), &corners, &mut crossing);
                    continue;
                }
                _ => b,
            };
            let ours = segment_triangle(a, b, &corners);
            let reference = parry_segment_triangle(a, b, &corners);
            assert!(
                (ours.distance() - reference).abs() <= 1e-12,
                "case {case}: {} vs parry {reference}",
                ours.distance()
            );
            assert_points_on_sets(&ours, a, b, &corners);
            if reference > 0.0 {
                clear += 1;
            } else {
                crossing += 1;
            }
        }
        assert!(clear > 10_000 && crossing > 1_000, "{clear} clear, {crossing} crossing");
    }

    /// A segment in the triangle's plane: it crosses the triangle (distance 0) or lies
    /// beside it, as parry says.
    fn check_in_plane(a: DVec3, b: DVec3, corners: &[DVec3; 3], crossing: &mut usize) {
        let ours = segment_triangle(a, b, corners);
        let reference = parry_segment_triangle(a, b, corners);
        assert!(
            (ours.distance() - reference).abs() <= 1e-12,
            "{} vs parry {reference}",
            ours.distance()
        );
        assert_points_on_sets(&ours, a, b, corners);
        if ours.distance() == 0.0 {
            *crossing += 1;
        }
    }

    #[test]
    fn special_cases_have_their_analytic_distance() {
        let corners = [DVec3::ZERO, DVec3::X, DVec3::Y];
        let height = DVec3::new(0.0, 0.0, 0.3);
        // Parallel to the face above its inside: the height, a tie along the whole segment.
        let above = segment_triangle(DVec3::new(0.1, 0.1, 0.3), DVec3::new(0.3, 0.2, 0.3), &corners);
        assert_eq!(above.distance(), 0.3);
        // Through the face: 0 at the crossing.
        let through = segment_triangle(DVec3::new(0.2, 0.2, -1.0), DVec3::new(0.2, 0.2, 1.0), &corners);
        assert_eq!(through.distance(), 0.0);
        assert!((through.on_first - DVec3::new(0.2, 0.2, 0.0)).length() <= 1e-15);
        // A point (zero-length segment) beyond the hypotenuse, above the plane.
        let point = DVec3::new(1.0, 1.0, 0.3);
        let single = segment_triangle(point, point, &corners);
        assert!((single.distance() - (0.5f64 + 0.09).sqrt()).abs() <= 1e-15);
        // Parallel to an edge, beside it in the plane: a tie along the overlap.
        let beside = segment_triangle(DVec3::new(-0.5, -0.2, 0.0), DVec3::new(0.5, -0.2, 0.0), &corners);
        assert!((beside.distance() - 0.2).abs() <= 1e-15);
        // In the plane, crossing an edge.
        let across = segment_triangle(DVec3::new(0.2, -0.5, 0.0), DVec3::new(0.2, 0.5, 0.0), &corners);
        assert_eq!(across.distance(), 0.0);
        // A degenerate triangle (its corners on a line) is its edges.
        let flat = [DVec3::ZERO, DVec3::X, DVec3::X * 2.0];
        let over = segment_triangle(DVec3::new(0.5, -1.0, 0.4), DVec3::new(0.5, 1.0, 0.4), &flat);
        assert!((over.distance() - 0.4).abs() <= 1e-15);
        // The segment's end right above a corner, pointing away.
        let away = segment_triangle(height, height * 2.0, &corners);
        assert!((away.distance() - 0.3).abs() <= 1e-15);
    }

    #[test]
    fn random_segment_pairs_match_parry_including_parallel_and_degenerate() {
        let mut random = Coordinates(0x0017_5e9e);
        for case in 0..20_000 {
            let (p0, p1, q0) = (random.point(), random.point(), random.point());
            let q1 = match case % 4 {
                // Parallel, and (every fourth) the second segment a point.
                0 => q0 + (p1 - p0) * random.next(),
                1 => q0,
                _ => random.point(),
            };
            let ours = segment_segment(p0, p1, q0, q1);
            let reference =
                query::details::distance_segment_segment(&Pose::IDENTITY, &Segment::new(p0, p1), &Segment::new(q0, q1));
            assert!(
                (ours.distance() - reference).abs() <= 1e-12,
                "case {case}: {} vs parry {reference}",
                ours.distance()
            );
            assert!((nearest_on_segment(ours.on_first, p0, p1) - ours.on_first).length() <= 1e-14);
            assert!((nearest_on_segment(ours.on_second, q0, q1) - ours.on_second).length() <= 1e-14);
        }
    }

    #[test]
    fn random_triangle_pairs_match_parry_and_planes_bound_them_from_below() {
        let mut random = Coordinates(0x7417_0017);
        let (mut clear, mut crossing, mut culled) = (0, 0, 0);
        for case in 0..20_000 {
            let first = [random.point(), random.point(), random.point()];
            let mut second = [random.point(), random.point(), random.point()];
            let normal = (first[1] - first[0]).cross(first[2] - first[0]).normalize();
            match case % 8 {
                // Parallel to the first (the faces tie), and coplanar with it.
                0 => second = second.map(|p| p - normal * normal.dot(p - second[0])),
                4 => second = second.map(|p| p - normal * normal.dot(p - first[0])),
                // A degenerate second triangle: its corners on a line, exactly (the
                // coordinates on a 2^-10 grid, steps of 2^-3: every sum exact).
                6 => {
                    let start = (second[0] * 1024.0).round() / 1024.0;
                    let step = DVec3::new(0.25, -0.5, 0.125);
                    second = [start, start + step, start + step * 3.0];
                }
                _ => {}
            }
            let ours = triangle_triangle(&first, &second);
            let [u, v, w] = second;
            let reference = query::distance(
                &Pose::IDENTITY,
                &Triangle::new(first[0], first[1], first[2]),
                &Pose::IDENTITY,
                &Triangle::new(u, v, w),
            )
            .unwrap()
            .distance;
            assert!(
                (ours.distance() - reference).abs() <= 1e-12,
                "case {case}: {} vs parry {reference}",
                ours.distance()
            );
            let gap = (ours.on_second - ours.on_first).length();
            assert!((gap - ours.distance()).abs() <= 1e-14, "case {case}: {ours:?}");
            // The points lie on their triangles (a degenerate one's edges, where parry's
            // projection onto its face says nothing).
            for (point, corners) in [(ours.on_first, &first), (ours.on_second, &second)] {
                let [a, b, c] = *corners;
                let off_face = (Triangle::new(a, b, c).project_local_point(point, true).point - point).length();
                let off_edges = (0..3)
                    .map(|i| (nearest_on_segment(point, corners[i], corners[(i + 1) % 3]) - point).length())
                    .fold(f64::MAX, f64::min);
                assert!(off_face.min(off_edges) <= 1e-14, "case {case}: {ours:?}");
            }
            // Either plane's gap is a lower bound.
            let bound = plane_gap(&first, &second).max(plane_gap(&second, &first));
            assert!(
                bound <= ours.distance() + 1e-15,
                "case {case}: {bound} > {}",
                ours.distance()
            );
            if bound > 0.0 {
                culled += 1;
            }
            if reference > 0.0 {
                clear += 1;
            } else {
                crossing += 1;
            }
        }
        assert!(
            clear > 10_000 && crossing > 500 && culled > 5_000,
            "{clear} clear, {crossing} crossing, {culled} with a plane between"
        );
    }

    #[test]
    fn swept_pair_is_capsule_distance_with_points_on_the_surfaces() {
        let pair = segment_segment(
            DVec3::ZERO,
            DVec3::X,
            DVec3::new(0.5, 1.0, 0.0),
            DVec3::new(0.5, 1.0, 1.0),
        );
        let (gap, p, q) = pair.swept(0.25, 0.125).unwrap();
        assert!((gap - 0.625).abs() <= 1e-15);
        assert!((p - DVec3::new(0.5, 0.25, 0.0)).length() <= 1e-15);
        assert!((q - DVec3::new(0.5, 0.875, 0.0)).length() <= 1e-15);
        assert_eq!(pair.swept(0.5, 0.5), None);
    }
}
