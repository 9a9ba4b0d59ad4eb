//! Test meshes built here (independent of geom's builders).

use flapwright_geom::TriMesh;
use nalgebra::{Point2, Point3, Vector3};

/// Closed prism: `outline` (counter-clockwise in the (u, v) plane) placed at each of
/// `stations` along `axis`, with u along `u_dir` and v along `v_dir`; capped by fans from
/// the outline centroid. Winding follows the outline orientation; the cut test does not
/// depend on the winding of the caps.
pub fn prism(
    outline: &[Point2<f64>],
    origin: Point3<f64>,
    u_dir: Vector3<f64>,
    v_dir: Vector3<f64>,
    axis: Vector3<f64>,
    stations: &[f64],
) -> TriMesh {
    let n = outline.len() as u32;
    let mut vertices = Vec::new();
    for &s in stations {
        for p in outline {
            vertices.push(origin + u_dir * p.x + v_dir * p.y + axis * s);
        }
    }
    let mut triangles = Vec::new();
    for ring in 0..(stations.len() as u32 - 1) {
        for i in 0..n {
            let j = (i + 1) % n;
            let (a0, b0, a1, b1) = (ring * n + i, ring * n + j, (ring + 1) * n + i, (ring + 1) * n + j);
            triangles.push([a0, b0, b1]);
            triangles.push([a0, b1, a1]);
        }
    }
    let centroid = outline
        .iter()
        .fold(Vector3::zeros(), |acc, p| acc + u_dir * p.x + v_dir * p.y)
        / outline.len() as f64;
    let first = vertices.len() as u32;
    vertices.push(origin + centroid + axis * stations[0]);
    vertices.push(origin + centroid + axis * stations[stations.len() - 1]);
    let last_ring = (stations.len() as u32 - 1) * n;
    for i in 0..n {
        let j = (i + 1) % n;
        triangles.push([first, j, i]);
        triangles.push([first + 1, last_ring + i, last_ring + j]);
    }
    TriMesh { vertices, triangles }
}

/// Circle of `segments` points, counter-clockwise, radius `radius_m`.
pub fn circle(radius_m: f64, segments: usize) -> Vec<Point2<f64>> {
    (0..segments)
        .map(|k| {
            let angle = 2.0 * std::f64::consts::PI * k as f64 / segments as f64;
            Point2::new(radius_m * angle.cos(), radius_m * angle.sin())
        })
        .collect()
}

/// NACA 4-digit airfoil (closed trailing edge, cosine spacing), unit chord, x from the
/// leading edge (aft), starting at the trailing edge over the lower surface: clockwise in
/// (x aft, y up), counter-clockwise once x is flipped to point at the nose.
pub fn naca4(max_camber: f64, camber_position: f64, thickness: f64, points_per_side: usize) -> Vec<Point2<f64>> {
    let surface = |x: f64, upper: bool| {
        let t = 5.0
            * thickness
            * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3) - 0.1036 * x.powi(4));
        let (yc, slope) = if max_camber == 0.0 {
            (0.0, 0.0)
        } else if x < camber_position {
            (
                max_camber / camber_position.powi(2) * (2.0 * camber_position * x - x * x),
                2.0 * max_camber / camber_position.powi(2) * (camber_position - x),
            )
        } else {
            (
                max_camber / (1.0 - camber_position).powi(2)
                    * (1.0 - 2.0 * camber_position + 2.0 * camber_position * x - x * x),
                2.0 * max_camber / (1.0 - camber_position).powi(2) * (camber_position - x),
            )
        };
        let theta = slope.atan();
        let sign = if upper { 1.0 } else { -1.0 };
        Point2::new(x - sign * t * theta.sin(), yc + sign * t * theta.cos())
    };
    let xs: Vec<f64> = (0..=points_per_side)
        .map(|k| 0.5 * (1.0 - (std::f64::consts::PI * k as f64 / points_per_side as f64).cos()))
        .collect();
    let mut points: Vec<Point2<f64>> = xs.iter().rev().map(|&x| surface(x, false)).collect();
    points.pop(); // leading edge once
    points.extend(xs.iter().map(|&x| surface(x, true)));
    points.pop(); // trailing edge once
    points
}
