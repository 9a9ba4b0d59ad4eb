//! Closed meshes from a sequence of rings (lofting) and polygon triangulation for the caps.

use nalgebra::{Point2, Point3, Vector3};

use crate::error::{Error, Result};
use crate::mesh::TriMesh;

/// Triangulates a simple polygon by ear clipping; triangles have the polygon's orientation.
/// O(n^2) for the airfoil-like polygons used here.
pub(crate) fn triangulate_polygon(polygon: &[Point2<f64>], what: &'static str) -> Result<Vec<[usize; 3]>> {
    let n = polygon.len();
    let fail = || Error::Triangulation { what, count: n };
    if n < 3 {
        return Err(fail());
    }
    let signed_area: f64 = (0..n).map(|i| polygon[i].coords.perp(&polygon[(i + 1) % n].coords)).sum::<f64>() * 0.5;
    if !(signed_area.abs() > 0.0) {
        return Err(fail());
    }
    let sign = signed_area.signum();
    let scale = polygon.iter().fold(0.0_f64, |m, p| m.max(p.coords.norm())).max(f64::MIN_POSITIVE);
    let area_tol = 1e-14 * scale * scale;
    let mut remaining: Vec<usize> = (0..n).collect();
    let mut triangles = Vec::with_capacity(n - 2);
    let mut cursor = 0;
    let mut misses = 0;
    while remaining.len() > 3 {
        let m = remaining.len();
        let (ia, ib, ic) = (remaining[(cursor + m - 1) % m], remaining[cursor % m], remaining[(cursor + 1) % m]);
        let (a, b, c) = (polygon[ia], polygon[ib], polygon[ic]);
        let cross = (b - a).perp(&(c - a)) * sign;
        let is_ear = cross > area_tol
            && remaining.iter().all(|&j| {
                if j == ia || j == ib || j == ic {
                    return true;
                }
                let p = polygon[j];
                let d1 = (b - a).perp(&(p - a)) * sign;
                let d2 = (c - b).perp(&(p - b)) * sign;
                let d3 = (a - c).perp(&(p - c)) * sign;
                !(d1 >= 0.0 && d2 >= 0.0 && d3 >= 0.0)
            });
        if is_ear {
            triangles.push([ia, ib, ic]);
            remaining.remove(cursor % m);
            misses = 0;
            if cursor >= remaining.len() {
                cursor = 0;
            }
        } else {
            cursor = (cursor + 1) % m;
            misses += 1;
            if misses > m {
                return Err(fail());
            }
        }
    }
    let [a, b, c] = [remaining[0], remaining[1], remaining[2]];
    if (polygon[b] - polygon[a]).perp(&(polygon[c] - polygon[a])) * sign <= area_tol {
        return Err(fail());
    }
    triangles.push([a, b, c]);
    Ok(triangles)
}

/// Projects a planar (or nearly planar) 3D ring onto its best-fit plane (Newell normal).
fn project_ring(ring: &[Point3<f64>]) -> Vec<Point2<f64>> {
    let n = ring.len();
    let mut normal = Vector3::zeros();
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        normal += Vector3::new((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    let normal = normal.try_normalize(0.0).unwrap_or_else(Vector3::y);
    let helper = if normal.x.abs() < 0.9 { Vector3::x() } else { Vector3::z() };
    let e1 = normal.cross(&helper).normalize();
    let e2 = normal.cross(&e1);
    ring.iter().map(|p| Point2::new(p.coords.dot(&e1), p.coords.dot(&e2))).collect()
}

/// Builds a closed mesh through `rings` (each a closed polygon, all with the same number of
/// points, point i of one ring joined to point i of the next) with flat caps on the first
/// and last ring. The result is oriented outward (positive volume).
pub(crate) fn loft_closed(rings: &[Vec<Point3<f64>>], what: &'static str) -> Result<TriMesh> {
    let m = rings.first().map_or(0, Vec::len);
    if rings.len() < 2 || m < 3 || rings.iter().any(|r| r.len() != m) {
        return Err(Error::Triangulation { what, count: m });
    }
    let mut mesh = TriMesh { vertices: rings.iter().flatten().copied().collect(), triangles: Vec::new() };
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
    (0..n).map(|i| ring[i].coords.cross(&ring[(i + 1) % n].coords)).sum::<Vector3<f64>>() * 0.5
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
        let square = |y: f64| vec![Point3::new(0.0, y, 0.0), Point3::new(2.0, y, 0.0), Point3::new(2.0, y, 1.0), Point3::new(0.0, y, 1.0)];
        let mesh = loft_closed(&[square(0.0), square(1.5), square(3.0)], "box").unwrap();
        assert!(mesh.compute_topology_check().is_watertight());
        approx::assert_relative_eq!(mesh.compute_signed_volume(), 6.0, max_relative = 1e-12);
    }

    #[test]
    fn concave_polygon_triangulates() {
        let l_shape = [(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0), (1.0, 2.0), (0.0, 2.0)].map(|(x, y)| Point2::new(x, y));
        let triangles = triangulate_polygon(&l_shape, "L").unwrap();
        let area: f64 = triangles
            .iter()
            .map(|t| 0.5 * (l_shape[t[1]] - l_shape[t[0]]).perp(&(l_shape[t[2]] - l_shape[t[0]])))
            .sum();
        approx::assert_relative_eq!(area, 3.0, max_relative = 1e-12);
    }
}
