//! Section cuts: a closed triangle mesh cut by a station plane, as closed 2D polygons in
//! the station frame.
//!
//! Algorithm: vertices are classified by the sign of their station z with the symbolic
//! rule "z >= 0 counts as above", so a vertex exactly on the plane is never ambiguous;
//! every triangle with vertices on both sides gives one segment between the crossing
//! points of its two crossing edges; a crossing point is computed once per mesh edge (from
//! the lower vertex index), so neighbouring triangles share it bit for bit; segments are
//! chained by edge and oriented from the winding so that the outline of a solid is
//! counter-clockwise in station (x, y). Coincident consecutive points (vertices on the
//! plane) are merged.

use std::collections::HashMap;

use flapwright_geom::TriMesh;
use nalgebra::Point2;

use crate::error::{Error, Result};
use crate::frame::StationFrame;

/// Consecutive section points closer than this are merged (m).
pub const SECTION_MERGE_TOL_M: f64 = 1e-12;

/// The cut of one part by one station plane.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Section {
    /// Part name (as geom names it: "wing", "flap", "front-spar", ...).
    pub part_name: String,
    /// Closed polygons (last point not repeated), station frame (x, y), metres;
    /// outlines of solid material counter-clockwise, holes clockwise.
    pub polygons: Vec<Vec<Point2<f64>>>,
}

type EdgeKey = (u32, u32);

fn edge_key(a: u32, b: u32) -> EdgeKey {
    if a < b {
        (a, b)
    } else {
        (b, a)
    }
}

/// Cuts `mesh` (closed, consistently wound, aircraft frame, m) by the plane of `frame`.
/// Errors: a non-finite vertex, a triangle index out of range, or a cut that does not
/// close (open or non-manifold mesh at the plane).
///
/// ```
/// use flapwright_geom::TriMesh;
/// use flapwright_planes::{cut_mesh, signed_area_m2, StationFrame};
/// use nalgebra::{Point3, Vector3};
///
/// // Tetrahedron with outward winding, cut by the plane y = 0.25 (normal outboard).
/// let mesh = TriMesh {
///     vertices: vec![
///         Point3::new(0.0, 0.0, 0.0),
///         Point3::new(1.0, 0.0, 0.0),
///         Point3::new(0.0, 1.0, 0.0),
///         Point3::new(0.0, 0.0, 1.0),
///     ],
///     triangles: vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
/// };
/// let frame = StationFrame::try_from_origin_and_normal(Point3::new(0.0, 0.25, 0.0), &Vector3::y_axis())?;
/// let section = cut_mesh(&mesh, &frame, "tetrahedron")?;
/// assert_eq!(section.polygons.len(), 1);
/// // A right triangle with legs 0.75: area 0.28125 m², counter-clockwise.
/// assert!((signed_area_m2(&section.polygons[0]) - 0.28125).abs() < 1e-15);
/// # Ok::<(), flapwright_planes::Error>(())
/// ```
pub fn cut_mesh(mesh: &TriMesh, frame: &StationFrame, part_name: &str) -> Result<Section> {
    let points: Vec<_> = mesh
        .vertices
        .iter()
        .map(|v| {
            let p = frame.station_point_from_aircraft(v);
            nalgebra::Point3::new(p.in_plane_m.x, p.in_plane_m.y, p.normal_offset_m)
        })
        .collect();
    if let Some(value) = points.iter().flat_map(|p| [p.x, p.y, p.z]).find(|v| !v.is_finite()) {
        return Err(Error::NotFinite {
            quantity: "mesh vertex coordinate (station frame)",
            value,
        });
    }
    let above = |i: u32| points[i as usize].z >= 0.0;
    let mut crossings: HashMap<EdgeKey, Point2<f64>> = HashMap::new();
    let mut segments: Vec<(EdgeKey, EdgeKey)> = Vec::new();
    for (triangle_index, triangle) in mesh.triangles.iter().enumerate() {
        if let Some(&index) = triangle.iter().find(|&&i| i as usize >= points.len()) {
            return Err(Error::VertexIndexOutOfRange {
                part_name: part_name.to_owned(),
                triangle: triangle_index,
                index,
                vertex_count: points.len(),
            });
        }
        let sides = triangle.map(above);
        if sides[0] == sides[1] && sides[1] == sides[2] {
            continue;
        }
        let mut entering = None;
        let mut leaving = None;
        for k in 0..3 {
            let (a, b) = (triangle[k], triangle[(k + 1) % 3]);
            match (sides[k], sides[(k + 1) % 3]) {
                (false, true) => entering = Some(edge_key(a, b)),
                (true, false) => leaving = Some(edge_key(a, b)),
                _ => {}
            }
        }
        let (Some(entering), Some(leaving)) = (entering, leaving) else {
            continue;
        };
        for key in [entering, leaving] {
            crossings.entry(key).or_insert_with(|| {
                let (p, q) = (points[key.0 as usize], points[key.1 as usize]);
                let t = p.z / (p.z - q.z);
                Point2::new(p.x + t * (q.x - p.x), p.y + t * (q.y - p.y))
            });
        }
        segments.push((leaving, entering));
    }
    let mut next_by_start: HashMap<EdgeKey, usize> = HashMap::with_capacity(segments.len());
    for (index, segment) in segments.iter().enumerate() {
        if next_by_start.insert(segment.0, index).is_some() {
            return Err(Error::OpenSection {
                part_name: part_name.to_owned(),
                edge_start: segment.0 .0,
                edge_end: segment.0 .1,
            });
        }
    }
    let mut used = vec![false; segments.len()];
    let mut polygons = Vec::new();
    for first in 0..segments.len() {
        if used[first] {
            continue;
        }
        let mut polygon: Vec<Point2<f64>> = Vec::new();
        let mut current = first;
        loop {
            used[current] = true;
            let (start, end) = segments[current];
            push_merged(&mut polygon, crossings[&start]);
            if end == segments[first].0 {
                break;
            }
            match next_by_start.get(&end) {
                Some(&next) if !used[next] => current = next,
                _ => {
                    return Err(Error::OpenSection {
                        part_name: part_name.to_owned(),
                        edge_start: end.0,
                        edge_end: end.1,
                    })
                }
            }
        }
        while polygon.len() > 1 && (polygon[0] - polygon[polygon.len() - 1]).norm() <= SECTION_MERGE_TOL_M {
            polygon.pop();
        }
        if polygon.len() >= 3 {
            polygons.push(polygon);
        }
    }
    Ok(Section {
        part_name: part_name.to_owned(),
        polygons,
    })
}

fn push_merged(polygon: &mut Vec<Point2<f64>>, point: Point2<f64>) {
    if polygon
        .last()
        .is_none_or(|last| (point - last).norm() > SECTION_MERGE_TOL_M)
    {
        polygon.push(point);
    }
}

/// Signed area of a closed polygon (shoelace formula), m²: positive when counter-clockwise.
pub fn signed_area_m2(polygon: &[Point2<f64>]) -> f64 {
    let n = polygon.len();
    (0..n)
        .map(|i| {
            let (p, q) = (polygon[i], polygon[(i + 1) % n]);
            p.x * q.y - q.x * p.y
        })
        .sum::<f64>()
        / 2.0
}

/// True when `point` lies inside the region the closed `polygons` bound, by the even-odd
/// rule (a hole inside an outline is outside); points on an edge may go either way.
pub fn polygons_contain(polygons: &[Vec<Point2<f64>>], point: &Point2<f64>) -> bool {
    let mut inside = false;
    for polygon in polygons {
        for (a, b) in polygon.iter().zip(polygon.iter().cycle().skip(1)) {
            if (a.y > point.y) != (b.y > point.y) {
                let x = a.x + (point.y - a.y) / (b.y - a.y) * (b.x - a.x);
                if x > point.x {
                    inside = !inside;
                }
            }
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Point3, Vector3};

    /// Unit cube [0,1]^3 with outward winding.
    fn cube() -> TriMesh {
        let vertices = (0..8)
            .map(|i| Point3::new((i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64))
            .collect();
        let quads = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let triangles = quads
            .iter()
            .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
            .collect();
        TriMesh { vertices, triangles }
    }

    #[test]
    fn cube_cut_is_a_counter_clockwise_unit_square() {
        let frame = StationFrame::try_from_origin_and_normal(Point3::new(0.5, 0.3, 0.5), &Vector3::y_axis()).unwrap();
        let section = cut_mesh(&cube(), &frame, "cube").unwrap();
        assert_eq!(section.polygons.len(), 1);
        // 8 points: the crossings of the face diagonals lie on the sides.
        assert_eq!(section.polygons[0].len(), 8);
        assert!((signed_area_m2(&section.polygons[0]) - 1.0).abs() < 1e-14);
    }

    #[test]
    fn plane_through_a_face_of_vertices_still_closes() {
        // Plane y = 0 contains the four vertices of a face: all count as "above".
        let frame = StationFrame::try_from_origin_and_normal(Point3::new(0.5, 0.0, 0.5), &Vector3::y_axis()).unwrap();
        let section = cut_mesh(&cube(), &frame, "cube").unwrap();
        assert!(section.polygons.is_empty());
        // Plane y = 1 through the far face: the cut is the face itself.
        let frame = StationFrame::try_from_origin_and_normal(Point3::new(0.5, 1.0, 0.5), &Vector3::y_axis()).unwrap();
        let section = cut_mesh(&cube(), &frame, "cube").unwrap();
        assert_eq!(section.polygons.len(), 1);
        assert!((signed_area_m2(&section.polygons[0]) - 1.0).abs() < 1e-14);
    }
}
