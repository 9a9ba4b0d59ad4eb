//! Exact distances between points, segments and triangles by brute force, written out
//! without parry (Ericson, Real-Time Collision Detection, 5.1.5 and 5.1.9): the yardstick
//! the collision adapter and the interference check are tested against. Plain loops, no
//! acceleration structure: for tests and checks, not for the hot path.

use nalgebra::Point3;

/// The point of triangle `[a, b, c]` closest to `p` (Ericson 5.1.5).
pub fn closest_on_triangle(p: &Point3<f64>, [a, b, c]: &[Point3<f64>; 3]) -> Point3<f64> {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(&ap), ac.dot(&ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return *a;
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(&bp), ac.dot(&bp));
    if d3 >= 0.0 && d4 <= d3 {
        return *b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return a + ab * (d1 / (d1 - d3));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(&cp), ac.dot(&cp));
    if d6 >= 0.0 && d5 <= d6 {
        return *c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return a + ac * (d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    let denominator = 1.0 / (va + vb + vc);
    a + ab * (vb * denominator) + ac * (vc * denominator)
}

/// Distance between segments p1-q1 and p2-q2 (Ericson 5.1.9; degenerate segments too).
pub fn segment_segment(p1: &Point3<f64>, q1: &Point3<f64>, p2: &Point3<f64>, q2: &Point3<f64>) -> f64 {
    let (d1, d2, r) = (q1 - p1, q2 - p2, p1 - p2);
    let (a, e, f) = (d1.norm_squared(), d2.norm_squared(), d2.dot(&r));
    let tiny = 1e-30;
    let (s, t) = if a <= tiny && e <= tiny {
        (0.0, 0.0)
    } else if a <= tiny {
        (0.0, (f / e).clamp(0.0, 1.0))
    } else {
        let c = d1.dot(&r);
        if e <= tiny {
            ((-c / a).clamp(0.0, 1.0), 0.0)
        } else {
            let b = d1.dot(&d2);
            let denominator = a * e - b * b;
            let mut s = if denominator > tiny {
                ((b * f - c * e) / denominator).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let mut t = (b * s + f) / e;
            if t < 0.0 {
                t = 0.0;
                s = (-c / a).clamp(0.0, 1.0);
            } else if t > 1.0 {
                t = 1.0;
                s = ((b - c) / a).clamp(0.0, 1.0);
            }
            (s, t)
        }
    };
    ((p1 + d1 * s) - (p2 + d2 * t)).norm()
}

/// True when segment p-q crosses triangle `t` (Möller-Trumbore, parameter in [0, 1]).
pub fn crosses(p: &Point3<f64>, q: &Point3<f64>, [a, b, c]: &[Point3<f64>; 3]) -> bool {
    let direction = q - p;
    let (e1, e2) = (b - a, c - a);
    let h = direction.cross(&e2);
    let det = e1.dot(&h);
    if det.abs() < 1e-300 {
        return false;
    }
    let s = p - a;
    let u = s.dot(&h) / det;
    let qv = s.cross(&e1);
    let v = direction.dot(&qv) / det;
    let t = e2.dot(&qv) / det;
    (0.0..=1.0).contains(&u) && v >= 0.0 && u + v <= 1.0 && (0.0..=1.0).contains(&t)
}

/// Exact distance from segment p-q to triangle `t`.
pub fn segment_triangle(p: &Point3<f64>, q: &Point3<f64>, t: &[Point3<f64>; 3]) -> f64 {
    if crosses(p, q, t) {
        return 0.0;
    }
    let ends = [p, q].map(|x| (x - closest_on_triangle(x, t)).norm());
    let edges = [(0, 1), (1, 2), (2, 0)].map(|(i, j)| segment_segment(p, q, &t[i], &t[j]));
    ends.into_iter().chain(edges).fold(f64::INFINITY, f64::min)
}

/// Exact distance between two triangles: every closest pair involves an edge of one of
/// them (or they cross).
pub fn triangle_triangle(a: &[Point3<f64>; 3], b: &[Point3<f64>; 3]) -> f64 {
    let edges = |t: &[Point3<f64>; 3]| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])];
    let one = edges(a)
        .iter()
        .map(|(p, q)| segment_triangle(p, q, b))
        .fold(f64::INFINITY, f64::min);
    let other = edges(b)
        .iter()
        .map(|(p, q)| segment_triangle(p, q, a))
        .fold(f64::INFINITY, f64::min);
    one.min(other)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_of_simple_configurations() {
        let t = [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
        ];
        // Above the face, beyond an edge, past a vertex.
        let near = |p: Point3<f64>, expected: Point3<f64>| (closest_on_triangle(&p, &t) - expected).norm() < 1e-15;
        assert!(near(Point3::new(0.2, 0.2, 0.5), Point3::new(0.2, 0.2, 0.0)));
        assert!(near(Point3::new(0.5, -1.0, 0.0), Point3::new(0.5, 0.0, 0.0)));
        assert!(near(Point3::new(2.0, -1.0, 0.0), Point3::new(1.0, 0.0, 0.0)));
        // Skew segments one apart; a segment through the face; parallel segments.
        let d = segment_segment(
            &Point3::new(-1.0, 0.0, 0.0),
            &Point3::new(1.0, 0.0, 0.0),
            &Point3::new(0.0, -1.0, 1.0),
            &Point3::new(0.0, 1.0, 1.0),
        );
        assert!((d - 1.0).abs() < 1e-15);
        assert_eq!(
            segment_triangle(&Point3::new(0.2, 0.2, -1.0), &Point3::new(0.2, 0.2, 1.0), &t),
            0.0
        );
        let parallel = segment_segment(
            &Point3::new(0.0, 0.0, 0.0),
            &Point3::new(1.0, 0.0, 0.0),
            &Point3::new(0.5, 0.3, 0.0),
            &Point3::new(1.5, 0.3, 0.0),
        );
        assert!((parallel - 0.3).abs() < 1e-15);
        // Two triangles stacked 0.25 apart.
        let up = t.map(|p| p + nalgebra::Vector3::new(0.1, 0.1, 0.25));
        assert!((triangle_triangle(&t, &up) - 0.25).abs() < 1e-15);
    }
}
