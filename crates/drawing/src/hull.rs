//! Convex hull of points, for the swept envelope of a mechanism.

use nalgebra::Point2;

/// Convex hull (Andrew's monotone chain), counter-clockwise, without repeated points.
/// Fewer than three distinct points are returned as they are.
pub fn convex_hull(mut points: Vec<Point2<f64>>) -> Vec<Point2<f64>> {
    points.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    points.dedup();
    if points.len() < 3 {
        return points;
    }
    let cross = |o: &Point2<f64>, a: &Point2<f64>, b: &Point2<f64>| (a - o).perp(&(b - o));
    let mut hull: Vec<Point2<f64>> = Vec::with_capacity(points.len() * 2);
    for reverse in [false, true] {
        let start = hull.len();
        let pass: Box<dyn Iterator<Item = &Point2<f64>>> = if reverse {
            Box::new(points.iter().rev())
        } else {
            Box::new(points.iter())
        };
        for p in pass {
            while hull.len() >= start + 2 && cross(&hull[hull.len() - 2], &hull[hull.len() - 1], p) <= 0.0 {
                hull.pop();
            }
            hull.push(*p);
        }
        hull.pop();
    }
    hull
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_with_inner_and_repeated_points() {
        let p = |x, y| Point2::new(x, y);
        let hull = convex_hull(vec![
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(1.0, 1.0),
            p(0.0, 1.0),
            p(0.5, 0.5),
            p(1.0, 1.0),
        ]);
        assert_eq!(hull, vec![p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)]);
    }
}
