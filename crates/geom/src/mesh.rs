//! Indexed triangle meshes in the aircraft frame (metres): topology check, volume, bounds.

use std::collections::HashMap;

use nalgebra::{Isometry3, Point3, Vector3};

/// Relative tolerance for a degenerate triangle: `|e1 x e2| <= DEGENERATE_RELATIVE_TOL * l_max^2`
/// with `l_max` the longest edge (dimensionless, so it works at model and full scale).
pub const DEGENERATE_RELATIVE_TOL: f64 = 1e-12;

/// A closed, consistently oriented triangle mesh: vertices in the aircraft frame (m),
/// triangles as vertex indices wound counter-clockwise seen from outside (outward normals).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TriMesh {
    /// Vertex positions, aircraft frame, metres.
    pub vertices: Vec<Point3<f64>>,
    /// Triangles as indices into `vertices`, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
}

/// Result of [`TriMesh::compute_topology_check`]: counts of everything that keeps a mesh
/// from being a closed, consistently oriented 2-manifold.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct MeshCheck {
    /// Undirected edges used by exactly one triangle (holes).
    pub boundary_edges: usize,
    /// Undirected edges used by three or more triangles.
    pub non_manifold_edges: usize,
    /// Edges shared by two triangles that traverse it in the same direction.
    pub misoriented_edges: usize,
    /// Triangles with (near) zero area or a repeated or out-of-range index.
    pub degenerate_triangles: usize,
}

impl MeshCheck {
    /// True when every edge is shared by exactly two triangles traversing it in opposite
    /// directions and no triangle is degenerate.
    pub fn is_watertight(&self) -> bool {
        *self == MeshCheck::default()
    }
}

/// Axis-aligned bounding box, aircraft frame (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    /// Smallest x, y, z (m).
    pub min: Point3<f64>,
    /// Largest x, y, z (m).
    pub max: Point3<f64>,
}

impl TriMesh {
    /// Counts boundary, non-manifold, misoriented edges and degenerate triangles.
    /// Edges are identified by vertex index (vertices are not merged by position).
    pub fn compute_topology_check(&self) -> MeshCheck {
        let mut check = MeshCheck::default();
        // (min, max) -> (count of min->max uses, count of max->min uses)
        let mut edges: HashMap<(u32, u32), (u32, u32)> = HashMap::with_capacity(self.triangles.len() * 2);
        let count = self.vertices.len();
        for triangle in &self.triangles {
            if triangle.iter().any(|&i| i as usize >= count) || self.triangle_is_degenerate(triangle) {
                check.degenerate_triangles += 1;
                continue;
            }
            for k in 0..3 {
                let (a, b) = (triangle[k], triangle[(k + 1) % 3]);
                let entry = edges.entry((a.min(b), a.max(b))).or_default();
                if a < b {
                    entry.0 += 1;
                } else {
                    entry.1 += 1;
                }
            }
        }
        for &(forward, backward) in edges.values() {
            match forward + backward {
                1 => check.boundary_edges += 1,
                2 if forward != 1 => check.misoriented_edges += 1,
                2 => {}
                _ => check.non_manifold_edges += 1,
            }
        }
        check
    }

    fn triangle_is_degenerate(&self, triangle: &[u32; 3]) -> bool {
        let [a, b, c] = triangle.map(|i| self.vertices[i as usize]);
        if triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[0] == triangle[2] {
            return true;
        }
        let longest = (b - a)
            .norm_squared()
            .max((c - b).norm_squared())
            .max((a - c).norm_squared());
        let doubled_area = (b - a).cross(&(c - a)).norm();
        doubled_area.partial_cmp(&(DEGENERATE_RELATIVE_TOL * longest)) != Some(std::cmp::Ordering::Greater)
    }

    /// Signed enclosed volume (m^3) by the divergence theorem, sum of `a . (b x c) / 6`
    /// over triangles; positive for a closed mesh with outward normals. Only meaningful for
    /// closed meshes; computed about the centroid of the vertices to limit round-off.
    pub fn compute_signed_volume(&self) -> f64 {
        if self.vertices.is_empty() {
            return 0.0;
        }
        let centre = self.vertices.iter().fold(Vector3::zeros(), |s, p| s + p.coords) / self.vertices.len() as f64;
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| self.vertices[i as usize].coords - centre);
                a.dot(&b.cross(&c))
            })
            .sum::<f64>()
            / 6.0
    }

    /// Axis-aligned bounding box of the vertices, `None` for an empty mesh.
    pub fn compute_aabb(&self) -> Option<Aabb> {
        let first = *self.vertices.first()?;
        Some(self.vertices.iter().fold(Aabb { min: first, max: first }, |b, p| Aabb {
            min: b.min.inf(p),
            max: b.max.sup(p),
        }))
    }

    /// Total surface area (m^2).
    pub fn compute_area(&self) -> f64 {
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| self.vertices[i as usize]);
                0.5 * (b - a).cross(&(c - a)).norm()
            })
            .sum()
    }

    /// A copy moved by the rigid motion `pose` (`p_new = pose * p`).
    pub fn transformed(&self, pose: &Isometry3<f64>) -> TriMesh {
        TriMesh {
            vertices: self.vertices.iter().map(|p| pose * p).collect(),
            triangles: self.triangles.clone(),
        }
    }

    /// Unit outward normal of triangle `index` from its winding (right-hand rule), or the
    /// zero vector for a degenerate triangle.
    pub fn triangle_normal(&self, index: usize) -> Vector3<f64> {
        let [a, b, c] = self.triangles[index].map(|i| self.vertices[i as usize]);
        (b - a)
            .cross(&(c - a))
            .try_normalize(0.0)
            .unwrap_or_else(Vector3::zeros)
    }

    /// Appends `other` (its indices shifted), e.g. to gather several closed shells in one part.
    pub fn append(&mut self, other: &TriMesh) {
        let offset = self.vertices.len() as u32;
        self.vertices.extend_from_slice(&other.vertices);
        self.triangles
            .extend(other.triangles.iter().map(|t| t.map(|i| i + offset)));
    }

    /// Reverses the winding of every triangle (turns normals inside out).
    pub fn flip_orientation(&mut self) {
        for t in &mut self.triangles {
            t.swap(1, 2);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tetrahedron() -> TriMesh {
        TriMesh {
            vertices: vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(0.0, 1.0, 0.0),
                Point3::new(0.0, 0.0, 1.0),
            ],
            triangles: vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
        }
    }

    #[test]
    fn tetrahedron_is_watertight_with_volume_one_sixth() {
        let mesh = tetrahedron();
        assert!(mesh.compute_topology_check().is_watertight());
        approx::assert_relative_eq!(mesh.compute_signed_volume(), 1.0 / 6.0, max_relative = 1e-14);
    }

    #[test]
    fn defects_are_counted() {
        let mut mesh = tetrahedron();
        mesh.triangles.pop();
        assert_eq!(mesh.compute_topology_check().boundary_edges, 3);
        let mut mesh = tetrahedron();
        mesh.triangles[0].swap(1, 2);
        assert_eq!(mesh.compute_topology_check().misoriented_edges, 3);
        let mut mesh = tetrahedron();
        mesh.triangles.push([0, 0, 1]);
        assert_eq!(mesh.compute_topology_check().degenerate_triangles, 1);
    }
}
