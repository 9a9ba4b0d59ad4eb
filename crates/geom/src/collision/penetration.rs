//! How deep two overlapping solids reach into each other.
//!
//! The measure: the deepest point of either part's surface that lies inside the other
//! solid, and its distance to that solid's surface. Any translation shorter than this
//! leaves that point inside, so it is a lower bound on the distance the parts must move
//! apart (the minimum translation distance), and it is what an engineer reads as "the
//! screw reaches 20 mm into the tube". The surface is sampled on a grid of spacing `h`
//! over each triangle (primitives through their tessellation); depth is 1-Lipschitz in the
//! point, so the true deepest surface point is at most `h` deeper than the deepest sample
//! (primitives: their tessellation's grid points are projected onto the true surface,
//! which stretches the grid by under 1 %: the faces of a 32-segment tessellation lie up to
//! 0.97 % of the radius inside the surface).
//!
//! Only triangles inside the other part's bounding box are sampled; when that would take
//! more than [`SAMPLE_BUDGET`] points the spacing grows to fit, up to the longest edge
//! (corners only), and the spacing used is returned with the result (a flap driven wholly
//! into the wing stays fast to report).

use glamx::DVec3;
use parry3d_f64::bounding_volume::Aabb;
use parry3d_f64::math::Pose;
use parry3d_f64::shape::Shape;

/// Largest number of surface samples per direction (part a in b, b in a).
pub const SAMPLE_BUDGET: usize = 200_000;

/// The deepest surface point of one part inside the other.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Deepest {
    /// Distance from the inside point to the other surface (m).
    pub depth: f64,
    /// The inside point, on the intruding part's surface (world frame).
    pub inside: DVec3,
    /// Its nearest point on the other part's surface (world frame).
    pub surface: DVec3,
    /// Grid spacing actually used (m): the depth is known to within this.
    pub spacing: f64,
}

/// Grid steps along the two shortest edges of a triangle for spacing `h`, and the corner
/// they start from.
fn grid(tri: &[DVec3; 3], h: f64) -> (DVec3, DVec3, DVec3, usize, usize) {
    // The corner shared by the two shortest edges is opposite the longest edge.
    let edge = |i: usize| (tri[(i + 2) % 3] - tri[(i + 1) % 3]).length();
    let longest = (0..3).max_by(|&i, &j| edge(i).total_cmp(&edge(j))).unwrap_or(0);
    let corner = tri[longest];
    let (e1, e2) = (tri[(longest + 1) % 3] - corner, tri[(longest + 2) % 3] - corner);
    let steps = |e: DVec3| ((e.length() / h).ceil() as usize).max(1);
    (corner, e1, e2, steps(e1), steps(e2))
}

/// Upper bound on the points of a triangle's grid: sum over i of ((1 - i/n1) n2 + 1).
fn grid_points(n1: usize, n2: usize) -> usize {
    (n1 + 1) * (n2 + 2) / 2
}

/// Deepest sample of `intruder`'s surface triangles (world frame) inside `host` at
/// `host_pose`, or `None` when no sample is inside. `exact_surface` is the intruder itself
/// when the triangles only tessellate it (a primitive): samples are then projected onto
/// its true surface, since a chord's points lie inside it and would read too deep.
pub(super) fn deepest_inside(
    intruder: &[[DVec3; 3]],
    exact_surface: Option<(&dyn Shape, &Pose)>,
    host: &dyn Shape,
    host_pose: &Pose,
    host_box: &Aabb,
    spacing: f64,
) -> Option<Deepest> {
    let overlaps = |tri: &[DVec3; 3]| {
        let (lo, hi) = (tri[0].min(tri[1]).min(tri[2]), tri[0].max(tri[1]).max(tri[2]));
        lo.cmple(host_box.maxs).all() && hi.cmpge(host_box.mins).all()
    };
    let candidates: Vec<&[DVec3; 3]> = intruder.iter().filter(|t| overlaps(t)).collect();
    let count = |h: f64| -> usize {
        candidates
            .iter()
            .map(|t| {
                let (_, _, _, n1, n2) = grid(t, h);
                grid_points(n1, n2)
            })
            .sum()
    };
    // Once h reaches the longest edge every triangle is sampled at its corners alone (and
    // every surface point is within h of one); growing h further cannot cut the count, so
    // a mesh with more than a third of the budget in triangles is sampled at its corners.
    let longest_edge = candidates
        .iter()
        .flat_map(|t| (0..3).map(move |i| (t[(i + 1) % 3] - t[i]).length()))
        .fold(0.0, f64::max);
    let mut h = spacing;
    // Grow the spacing until the samples fit the budget; points scale as 1/h^2.
    loop {
        let points = count(h);
        if points <= SAMPLE_BUDGET || h >= longest_edge {
            break;
        }
        h = (h * (points as f64 / SAMPLE_BUDGET as f64).sqrt().max(1.1)).min(longest_edge);
    }
    // Depth is 1-Lipschitz, so no point of a triangle lies deeper than its centroid's depth
    // (negative outside) plus the triangle's reach from it (twice that for a primitive:
    // its samples move onto the true surface by less than the triangle's size). Triangles
    // are sampled deepest bound first and skipped once their bound cannot beat the deepest
    // sample: the same deepest sample, without sampling the shallow part of the overlap.
    let reach_factor = if exact_surface.is_some() { 2.0 } else { 1.0 };
    let mut bounded: Vec<(f64, &[DVec3; 3])> = candidates
        .into_iter()
        .map(|tri| {
            let centroid = (tri[0] + tri[1] + tri[2]) / 3.0;
            let reach = tri.iter().map(|v| (*v - centroid).length()).fold(0.0, f64::max);
            let projection = host.project_point(host_pose, centroid, false);
            let distance = (projection.point - centroid).length();
            let depth = if projection.is_inside { distance } else { -distance };
            // A point with no nearest surface point (a ball's centre) bounds nothing.
            let bound = depth + reach_factor * reach;
            (if bound.is_nan() { f64::INFINITY } else { bound }, tri)
        })
        .collect();
    bounded.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut deepest: Option<Deepest> = None;
    for (bound, tri) in bounded {
        if bound < 0.0 || deepest.is_some_and(|d| bound <= d.depth) {
            break;
        }
        let (corner, e1, e2, n1, n2) = grid(tri, h);
        for i in 0..=n1 {
            let u = i as f64 / n1 as f64;
            // Points with u + v <= 1 lie in the triangle.
            let j_max = ((1.0 - u) * n2 as f64 + 1e-9).floor() as usize;
            for j in 0..=j_max {
                let mut point = corner + e1 * u + e2 * (j as f64 / n2 as f64);
                if let Some((shape, pose)) = exact_surface {
                    point = shape.project_point(pose, point, false).point;
                }
                if point.cmplt(host_box.mins).any() || point.cmpgt(host_box.maxs).any() {
                    continue;
                }
                let projection = host.project_point(host_pose, point, false);
                if !projection.is_inside {
                    continue;
                }
                let depth = (projection.point - point).length();
                // parry projects a ball's centre to NaN: its neighbours within h stand in.
                if depth.is_nan() {
                    continue;
                }
                if deepest.is_none_or(|d| depth > d.depth) {
                    deepest = Some(Deepest {
                        depth,
                        inside: point,
                        surface: projection.point,
                        spacing: h,
                    });
                }
            }
        }
    }
    deepest
}

#[cfg(test)]
mod tests {
    use super::*;
    use parry3d_f64::shape::Ball;

    #[test]
    fn more_triangles_than_the_budget_allows_are_sampled_at_their_corners() {
        // 80 000 tiny triangles (3 corner points each: 240 000 > the budget) inside a ball
        // of radius 1: the spacing stops at the longest edge instead of growing forever.
        let size = 1e-3;
        let triangles: Vec<[DVec3; 3]> = (0..80_000)
            .map(|i| {
                let x = -0.4 + 0.8 * (i % 400) as f64 / 400.0;
                let y = -0.4 + 0.8 * (i / 400) as f64 / 200.0;
                let p = DVec3::new(x, y, 0.0);
                [p, p + DVec3::new(size, 0.0, 0.0), p + DVec3::new(0.0, size, 0.0)]
            })
            .collect();
        let ball = Ball::new(1.0);
        let pose = Pose::identity();
        let host_box = ball.compute_aabb(&pose);
        let deepest = deepest_inside(&triangles, None, &ball, &pose, &host_box, 1e-5).expect("inside");
        let longest = size * 2f64.sqrt();
        assert!((deepest.spacing - longest).abs() < 1e-15, "{deepest:?}");
        // The deepest surface point (the centre, depth 1) is at most one spacing deeper
        // than the deepest sample.
        assert!(
            deepest.depth <= 1.0 && deepest.depth >= 1.0 - deepest.spacing,
            "{deepest:?}"
        );
    }
}
