//! Closed meshes from a sequence of rings (lofting) and polygon triangulation for the caps.

use nalgebra::{Point2, Point3, Vector3};

use crate::error::{Error, Result};
use crate::mesh::TriMesh;

/// A vertex closer than this (fraction of the polygon's bounding-box diagonal) to an ear's
/// triangle counts as inside it and blocks the ear. Resampled airfoils have long runs of
/// collinear points (straight segments of coarse `.dat` data); rounding puts some of them a
/// hair outside the long diagonal of a fan over the run, and clipping that ear would leave
/// the run as a zero-area remainder that no ear can clip (and T-junctions in the cap).
const EAR_BLOCK_DISTANCE_FRACTION: f64 = 1e-10;

/// Triangulates a simple polygon by ear clipping, always clipping the best-shaped ear
/// (largest `2 area / longest edge^2`), so that runs of nearly collinear points (flat parts
/// of resampled airfoils) are fanned from the opposite side instead of being left as a
/// sliver at the end. An ear is blocked by any other live vertex inside its triangle or
/// within [`EAR_BLOCK_DISTANCE_FRACTION`] of its boundary. Triangles have the polygon's
/// orientation. O(n^2) typically, O(n^3) when blocked ears force a full re-scoring.
pub(crate) fn triangulate_polygon(polygon: &[Point2<f64>], what: &'static str) -> Result<Vec<[usize; 3]>> {
    let n = polygon.len();
    let fail = || Error::Triangulation { what, count: n };
    if n < 3 {
        return Err(fail());
    }
    let signed_area: f64 = (0..n)
        .map(|i| polygon[i].coords.perp(&polygon[(i + 1) % n].coords))
        .sum::<f64>()
        * 0.5;
    if signed_area.abs().partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return Err(fail());
    }
    let sign = signed_area.signum();
    let (low, high) = polygon
        .iter()
        .fold((polygon[0].coords, polygon[0].coords), |(low, high), p| {
            (low.inf(&p.coords), high.sup(&p.coords))
        });
    let block_distance = EAR_BLOCK_DISTANCE_FRACTION * (high - low).norm();
    // Doubly linked list of remaining vertices.
    let mut next: Vec<usize> = (0..n).map(|i| (i + 1) % n).collect();
    let mut prev: Vec<usize> = (0..n).map(|i| (i + n - 1) % n).collect();
    let mut alive = vec![true; n];
    let quality = |prev: &[usize], next: &[usize], alive: &[bool], b: usize| -> Option<f64> {
        let (ia, ic) = (prev[b], next[b]);
        let (a, bp, c) = (polygon[ia], polygon[b], polygon[ic]);
        let cross = (bp - a).perp(&(c - a)) * sign;
        let longest = (bp - a)
            .norm_squared()
            .max((c - bp).norm_squared())
            .max((a - c).norm_squared());
        if cross.partial_cmp(&(1e-13 * longest)) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let blocked = (0..n).any(|j| {
            if !alive[j] || j == ia || j == b || j == ic {
                return false;
            }
            let p = polygon[j];
            // p lies inside (or within the tolerance of) the line of edge from -> to.
            let inside = |from: Point2<f64>, to: Point2<f64>| {
                let edge = to - from;
                edge.perp(&(p - from)) * sign >= -block_distance * edge.norm()
            };
            inside(a, bp) && inside(bp, c) && inside(c, a)
        });
        (!blocked).then_some(cross / longest)
    };
    let mut scores: Vec<Option<f64>> = (0..n).map(|b| quality(&prev, &next, &alive, b)).collect();
    let mut triangles = Vec::with_capacity(n - 2);
    for _ in 0..n - 3 {
        let pick = |scores: &[Option<f64>]| {
            (0..n)
                .filter(|&b| alive[b])
                .filter_map(|b| scores[b].map(|q| (b, q)))
                .max_by(|x, y| x.1.total_cmp(&y.1))
                .map(|(b, _)| b)
        };
        let best = match pick(&scores) {
            Some(best) => best,
            None => {
                // An ear blocked by an already clipped vertex is only re-scored here.
                for b in 0..n {
                    scores[b] = if alive[b] {
                        quality(&prev, &next, &alive, b)
                    } else {
                        None
                    };
                }
                pick(&scores).ok_or_else(fail)?
            }
        };
        let (a, c) = (prev[best], next[best]);
        triangles.push([a, best, c]);
        alive[best] = false;
        next[a] = c;
        prev[c] = a;
        scores[a] = quality(&prev, &next, &alive, a);
        scores[c] = quality(&prev, &next, &alive, c);
    }
    let b = (0..n).find(|&b| alive[b]).ok_or_else(fail)?;
    quality(&prev, &next, &alive, b).ok_or_else(fail)?;
    triangles.push([prev[b], b, next[b]]);
    Ok(triangles)
}

/// Projects a planar (or nearly planar) 3D ring onto its best-fit plane (Newell normal).
fn project_ring(ring: &[Point3<f64>]) -> Vec<Point2<f64>> {
    let n = ring.len();
    let mut normal = Vector3::zeros();
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        normal += Vector3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    let normal = normal.try_normalize(0.0).unwrap_or_else(Vector3::y);
    let helper = if normal.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::z()
    };
    let e1 = normal.cross(&helper).normalize();
    let e2 = normal.cross(&e1);
    ring.iter()
        .map(|p| Point2::new(p.coords.dot(&e1), p.coords.dot(&e2)))
        .collect()
}

/// Builds a closed mesh through `rings` (each a closed polygon, all with the same number of
/// points, point i of one ring joined to point i of the next) with flat caps on the first
/// and last ring. The result is oriented outward (positive volume).
pub(crate) fn loft_closed(rings: &[Vec<Point3<f64>>], what: &'static str) -> Result<TriMesh> {
    let m = rings.first().map_or(0, Vec::len);
    if rings.len() < 2 || m < 3 || rings.iter().any(|r| r.len() != m) {
        return Err(Error::Triangulation { what, count: m });
    }
    let mut mesh = TriMesh {
        vertices: rings.iter().flatten().copied().collect(),
        triangles: Vec::new(),
    };
    let index = |ring: usize, i: usize| (ring * m + i % m) as u32;
    for k in 0..rings.len() - 1 {
        for i in 0..m {
            let (a, b, c, d) = (index(k, i), index(k, i + 1), index(k + 1, i + 1), index(k + 1, i));
            // Split the quad along its shorter diagonal.
            let ac = (mesh.vertices[c as usize] - mesh.vertices[a as usize]).norm_squared();
            let bd = (mesh.vertices[d as usize] - mesh.vertices[b as usize]).norm_squared();
            if ac <= bd {
                mesh.triangles.extend([[a, b, c], [a, c, d]]);
            } else {
                mesh.triangles.extend([[a, b, d], [b, c, d]]);
            }
        }
    }
    let first = triangulate_polygon(&project_ring(&rings[0]), what)?;
    let last_ring = rings.len() - 1;
    let last = triangulate_polygon(&project_ring(&rings[last_ring]), what)?;
    // Cap orientation must oppose the side strips along the shared ring edges: the first
    // ring's edges are used i -> i+1 by the sides, so its cap runs i+1 -> i; the last
    // ring's edges are used i+1 -> i, so its cap runs i -> i+1. The projection may mirror
    // the ring, so orient each cap by its projected winding relative to the ring order.
    let first_area = signed_area_3d(&rings[0]);
    let last_area = signed_area_3d(&rings[last_ring]);
    for t in first {
        let tri = [index(0, t[0]), index(0, t[1]), index(0, t[2])];
        mesh.triangles.push(orient(&mesh, tri, -first_area));
    }
    for t in last {
        let tri = [index(last_ring, t[0]), index(last_ring, t[1]), index(last_ring, t[2])];
        mesh.triangles.push(orient(&mesh, tri, last_area));
    }
    if mesh.compute_signed_volume() < 0.0 {
        mesh.flip_orientation();
    }
    Ok(mesh)
}

/// Vector area (Newell) of a ring: its direction follows the ring order by the right-hand rule.
fn signed_area_3d(ring: &[Point3<f64>]) -> Vector3<f64> {
    let n = ring.len();
    (0..n)
        .map(|i| ring[i].coords.cross(&ring[(i + 1) % n].coords))
        .sum::<Vector3<f64>>()
        * 0.5
}

/// Returns `tri` wound so that its normal points along `direction`.
fn orient(mesh: &TriMesh, tri: [u32; 3], direction: Vector3<f64>) -> [u32; 3] {
    let [a, b, c] = tri.map(|i| mesh.vertices[i as usize]);
    if (b - a).cross(&(c - a)).dot(&direction) >= 0.0 {
        tri
    } else {
        [tri[0], tri[2], tri[1]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_loft_is_watertight_with_exact_volume() {
        let square = |y: f64| {
            vec![
                Point3::new(0.0, y, 0.0),
                Point3::new(2.0, y, 0.0),
                Point3::new(2.0, y, 1.0),
                Point3::new(0.0, y, 1.0),
            ]
        };
        let mesh = loft_closed(&[square(0.0), square(1.5), square(3.0)], "box").unwrap();
        assert!(mesh.compute_topology_check().is_watertight());
        approx::assert_relative_eq!(mesh.compute_signed_volume(), 6.0, max_relative = 1e-12);
    }

    #[test]
    fn concave_polygon_triangulates() {
        let l_shape =
            [(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0), (1.0, 2.0), (0.0, 2.0)].map(|(x, y)| Point2::new(x, y));
        let triangles = triangulate_polygon(&l_shape, "L").unwrap();
        let area: f64 = triangles
            .iter()
            .map(|t| 0.5 * (l_shape[t[1]] - l_shape[t[0]]).perp(&(l_shape[t[2]] - l_shape[t[0]])))
            .sum();
        approx::assert_relative_eq!(area, 3.0, max_relative = 1e-12);
    }

    /// Regression: NACA 63-215 from its coarse `.dat` file (long straight segments) resampled
    /// finely has runs of collinear points; rounding (here from rotation and scaling, as in
    /// the projected 3D caps) once let an ear fan over a run, leaving a zero-area remainder.
    #[test]
    fn resampled_dat_airfoil_with_collinear_runs_triangulates_exactly() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/airfoils/n63215.dat");
        let airfoil = crate::Airfoil::from_dat(std::fs::File::open(path).unwrap()).unwrap();
        let area = |p: &[Point2<f64>], t: &[usize; 3]| 0.5 * (p[t[1]] - p[t[0]]).perp(&(p[t[2]] - p[t[0]]));
        for points_per_side in [20, 60, 110, 120, 160, 200, 240, 300] {
            let mut points = airfoil.resampled(points_per_side).unwrap().points;
            points.pop(); // sharp trailing edge: drop the repeated point
            for (angle, scale) in [(0.0, 1.0), (-0.035, 2.1), (0.3, 1.2), (1.7, 0.01)] {
                let rotation = nalgebra::Rotation2::new(angle);
                let polygon: Vec<Point2<f64>> = points
                    .iter()
                    .map(|p| Point2::from(rotation * p.coords * scale) + nalgebra::Vector2::new(1.3, -0.2))
                    .collect();
                let triangles = triangulate_polygon(&polygon, "airfoil")
                    .unwrap_or_else(|e| panic!("{points_per_side} per side, angle {angle}: {e}"));
                assert_eq!(triangles.len(), polygon.len() - 2);
                let n = polygon.len();
                let polygon_area: f64 = (0..n)
                    .map(|i| 0.5 * polygon[i].coords.perp(&polygon[(i + 1) % n].coords))
                    .sum();
                let mut sum = 0.0;
                for t in &triangles {
                    let a = area(&polygon, t);
                    assert!(
                        a > 0.0,
                        "{points_per_side} per side, angle {angle}: triangle {t:?} area {a}"
                    );
                    sum += a;
                }
                approx::assert_relative_eq!(sum, polygon_area, max_relative = 1e-9);
            }
        }
    }
}
