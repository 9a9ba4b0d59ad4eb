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

/// Grid steps along each edge of a piece of a triangle's grid with its own depth bound: a
/// piece holds up to 8 x 8 samples for one point query of its centre.
const PIECE_STEPS: usize = 8;

/// The last column of row `i` of a triangle's grid with `n1` x `n2` steps (points with
/// u + v <= 1, u = i / n1, v = j / n2).
fn row_length(i: usize, n1: usize, n2: usize) -> usize {
    ((1.0 - i as f64 / n1 as f64) * n2 as f64 + 1e-9).floor() as usize
}

/// Rows and columns (inclusive ranges) of a triangle's sampling grid: corner + e1 i / n1 +
/// e2 j / n2 for the (i, j) in range with u + v <= 1.
struct Piece {
    corner: DVec3,
    e1: DVec3,
    e2: DVec3,
    n1: usize,
    n2: usize,
    rows: (usize, usize),
    columns: (usize, usize),
}

impl Piece {
    /// Rows and columns of a triangle's grid (`grid`: corner, e1, e2, n1, n2).
    fn of(
        (corner, e1, e2, n1, n2): (DVec3, DVec3, DVec3, usize, usize),
        rows: (usize, usize),
        columns: (usize, usize),
    ) -> Self {
        Piece {
            corner,
            e1,
            e2,
            n1,
            n2,
            rows,
            columns,
        }
    }

    /// The centre of the parallelogram the piece's rows and columns span, and the largest
    /// distance from it to the parallelogram's corners (its points are no farther).
    fn centre_and_reach(&self) -> (DVec3, f64) {
        let at = |i: usize, j: usize| {
            self.corner + self.e1 * (i as f64 / self.n1 as f64) + self.e2 * (j as f64 / self.n2 as f64)
        };
        let corners = [
            at(self.rows.0, self.columns.0),
            at(self.rows.1, self.columns.0),
            at(self.rows.0, self.columns.1),
            at(self.rows.1, self.columns.1),
        ];
        let centre = (corners[0] + corners[1] + corners[2] + corners[3]) / 4.0;
        let reach = corners.iter().map(|c| (*c - centre).length()).fold(0.0, f64::max);
        (centre, reach)
    }
}

/// A bound that is NaN (a point with no nearest surface point, such as a ball's centre)
/// bounds nothing.
fn finite_or_infinite(bound: f64) -> f64 {
    if bound.is_nan() {
        f64::INFINITY
    } else {
        bound
    }
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
    // A triangle with more than `PIECE_STEPS` grid steps along an edge is cut into pieces
    // of its grid, each with its own bound (`Piece`): a primitive's tessellation has strips
    // as long as a capsule, whose one bound would reach the whole length.
    let reach_factor = if exact_surface.is_some() { 2.0 } else { 1.0 };
    let depth_at = |point: DVec3| {
        let projection = host.project_point(host_pose, point, false);
        let distance = (projection.point - point).length();
        if projection.is_inside {
            distance
        } else {
            -distance
        }
    };
    let mut bounded: Vec<(f64, Piece)> = Vec::new();
    for tri in candidates {
        let tri_grid = grid(tri, h);
        let (_, _, _, n1, n2) = tri_grid;
        if n1 < PIECE_STEPS && n2 < PIECE_STEPS {
            let centroid = (tri[0] + tri[1] + tri[2]) / 3.0;
            let reach = tri.iter().map(|v| (*v - centroid).length()).fold(0.0, f64::max);
            let piece = Piece::of(tri_grid, (0, n1), (0, n2));
            bounded.push((finite_or_infinite(depth_at(centroid) + reach_factor * reach), piece));
            continue;
        }
        for first_row in (0..=n1).step_by(PIECE_STEPS) {
            // The longest row of the piece is its first (points with u + v <= 1).
            let columns = row_length(first_row, n1, n2);
            for first_column in (0..=columns).step_by(PIECE_STEPS) {
                let piece = Piece::of(
                    tri_grid,
                    (first_row, (first_row + PIECE_STEPS - 1).min(n1)),
                    (first_column, (first_column + PIECE_STEPS - 1).min(n2)),
                );
                // The piece's samples lie in the parallelogram its row and column ranges
                // span; after projection onto a primitive's surface, a sample q moves by
                // its distance to that surface, at most the centre's plus |q - centre|.
                let (centre, reach) = piece.centre_and_reach();
                let moved = exact_surface.map_or(0.0, |(shape, pose)| {
                    (shape.project_point(pose, centre, false).point - centre).length()
                });
                let bound = depth_at(centre) + moved + reach_factor * reach;
                bounded.push((finite_or_infinite(bound), piece));
            }
        }
    }
    bounded.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut deepest: Option<Deepest> = None;
    for (bound, piece) in bounded {
        if bound < 0.0 || deepest.is_some_and(|d| bound <= d.depth) {
            break;
        }
        for i in piece.rows.0..=piece.rows.1 {
            let u = i as f64 / piece.n1 as f64;
            let last_column = row_length(i, piece.n1, piece.n2).min(piece.columns.1);
            for j in piece.columns.0..=last_column {
                let mut point = piece.corner + piece.e1 * u + piece.e2 * (j as f64 / piece.n2 as f64);
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
    use parry3d_f64::shape::{Ball, Capsule, Cuboid};

    /// The deepest of every grid sample, none skipped: what the bounds must not change.
    fn deepest_of_every_sample(
        intruder: &[[DVec3; 3]],
        exact_surface: Option<(&dyn Shape, &Pose)>,
        host: &dyn Shape,
        host_pose: &Pose,
        h: f64,
    ) -> f64 {
        let mut deepest = f64::MIN;
        for tri in intruder {
            let (corner, e1, e2, n1, n2) = grid(tri, h);
            for i in 0..=n1 {
                for j in 0..=row_length(i, n1, n2) {
                    let mut point = corner + e1 * (i as f64 / n1 as f64) + e2 * (j as f64 / n2 as f64);
                    if let Some((shape, pose)) = exact_surface {
                        point = shape.project_point(pose, point, false).point;
                    }
                    let projection = host.project_point(host_pose, point, false);
                    if projection.is_inside {
                        deepest = deepest.max((projection.point - point).length());
                    }
                }
            }
        }
        deepest
    }

    #[test]
    fn pieces_of_long_triangles_keep_the_deepest_sample() {
        // A long capsule (its tessellation's strips 0.4 m long, 50 pieces at 1 mm) through
        // a turned box, and one large triangle through a ball: the bounds of the pieces skip
        // most samples, and the deepest is the deepest of them all.
        let capsule = Capsule::new(DVec3::new(-0.2, 0.0, 0.0), DVec3::new(0.2, 0.0, 0.0), 0.012);
        let (vertices, indices) = capsule.to_trimesh(32, 16);
        let strips: Vec<[DVec3; 3]> = indices.iter().map(|t| t.map(|i| vertices[i as usize])).collect();
        let capsule_pose = Pose::rotation(DVec3::new(0.1, 0.2, 0.3));
        let strips_ac: Vec<[DVec3; 3]> = strips
            .iter()
            .map(|t| t.map(|v| capsule_pose.transform_point(v)))
            .collect();
        let cuboid = Cuboid::new(DVec3::new(0.03, 0.05, 0.05));
        let cuboid_pose = Pose::from_parts(DVec3::new(0.05, 0.008, 0.0), glamx::DQuat::from_rotation_z(0.4));
        let h = 1e-3;
        let longest = strips_ac
            .iter()
            .map(|t| {
                let (_, _, _, n1, n2) = grid(t, h);
                n1.max(n2)
            })
            .max();
        assert!(longest > Some(4 * PIECE_STEPS), "strips of {longest:?} steps");
        let found = deepest_inside(
            &strips_ac,
            Some((&capsule, &capsule_pose)),
            &cuboid,
            &cuboid_pose,
            &cuboid.compute_aabb(&cuboid_pose),
            h,
        )
        .expect("the capsule crosses the box");
        let every = deepest_of_every_sample(&strips_ac, Some((&capsule, &capsule_pose)), &cuboid, &cuboid_pose, h);
        assert_eq!(found.depth, every);
        assert!(found.depth > 0.005, "{found:?}");

        let triangle = [[
            DVec3::new(-1.0, -0.5, 0.1),
            DVec3::new(1.0, -0.4, 0.0),
            DVec3::new(0.1, 0.9, -0.1),
        ]];
        let ball = Ball::new(0.3);
        let ball_pose = Pose::translation(0.2, 0.1, 0.05);
        let found = deepest_inside(&triangle, None, &ball, &ball_pose, &ball.compute_aabb(&ball_pose), 0.01)
            .expect("the triangle crosses the ball");
        let every = deepest_of_every_sample(&triangle, None, &ball, &ball_pose, 0.01);
        assert_eq!(found.depth, every);
        assert!(found.depth > 0.2, "{found:?}");
    }

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
