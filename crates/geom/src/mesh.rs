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

impl Aabb {
    /// The box grown by `margin` (m) on every side.
    pub fn inflated(&self, margin: f64) -> Aabb {
        let grow = Vector3::repeat(margin);
        Aabb {
            min: self.min - grow,
            max: self.max + grow,
        }
    }

    /// The eight corners (m).
    pub fn corners(&self) -> [Point3<f64>; 8] {
        std::array::from_fn(|k| {
            Point3::new(
                if k & 1 == 0 { self.min.x } else { self.max.x },
                if k & 2 == 0 { self.min.y } else { self.max.y },
                if k & 4 == 0 { self.min.z } else { self.max.z },
            )
        })
    }

    /// The smallest box holding both.
    pub fn merged(&self, other: &Aabb) -> Aabb {
        Aabb {
            min: self.min.inf(&other.min),
            max: self.max.sup(&other.max),
        }
    }

    /// Distance between the boxes (0 when they touch or overlap): a lower bound on the
    /// distance between anything inside them.
    pub fn distance(&self, other: &Aabb) -> f64 {
        let gap = (other.min - self.max)
            .sup(&(self.min - other.max))
            .sup(&Vector3::zeros());
        gap.norm()
    }
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

    /// Splits the surface by the plane through `point` with normal `normal`: the pieces on
    /// the side `normal` points away from, then the pieces on the side it points to. Each
    /// triangle is clipped on its own (its pieces fan-triangulated, winding kept), so the
    /// pieces share no vertices; closed meshes come apart open. Clipping by hand rather than
    /// with parry's `TriMesh::split`, which builds a BVH per piece and caps oriented meshes:
    /// an opening cut by four planes needs neither.
    pub fn split_by_plane(&self, point: &Point3<f64>, normal: &Vector3<f64>) -> [TriMesh; 2] {
        let mut sides = [TriMesh::default(), TriMesh::default()];
        let height = |p: &Point3<f64>| (p - point).dot(normal);
        for triangle in &self.triangles {
            let corners = triangle.map(|i| self.vertices[i as usize]);
            let heights = corners.map(|p| height(&p));
            for (side, keep) in [(0, -1.0), (1, 1.0)] {
                // Sutherland-Hodgman against one half-space; points on the plane go to both.
                let mut polygon: Vec<Point3<f64>> = Vec::with_capacity(4);
                for i in 0..3 {
                    let (p, q) = (corners[i], corners[(i + 1) % 3]);
                    let (hp, hq) = (keep * heights[i], keep * heights[(i + 1) % 3]);
                    if hp >= 0.0 {
                        polygon.push(p);
                    }
                    if (hp > 0.0 && hq < 0.0) || (hp < 0.0 && hq > 0.0) {
                        polygon.push(p + (q - p) * (hp / (hp - hq)));
                    }
                }
                if polygon.len() >= 3 {
                    let mesh = &mut sides[side];
                    let first = mesh.vertices.len() as u32;
                    mesh.vertices.extend_from_slice(&polygon);
                    mesh.triangles
                        .extend((1..polygon.len() as u32 - 1).map(|k| [first, first + k, first + k + 1]));
                }
            }
        }
        sides.map(|mut mesh| {
            // Slivers of a triangle touching the plane at a corner or an edge.
            let vertices = &mesh.vertices;
            mesh.triangles.retain(|t| {
                let [a, b, c] = t.map(|i| vertices[i as usize]);
                let longest = (b - a).norm().max((c - b).norm()).max((a - c).norm());
                (b - a).cross(&(c - a)).norm() > DEGENERATE_RELATIVE_TOL * longest * longest
            });
            mesh
        })
    }

    /// The triangles whose index `keep` accepts, in order, with only the vertices they use
    /// (renumbered in the order first used).
    pub fn select_triangles(&self, keep: impl Fn(usize) -> bool) -> TriMesh {
        let mut index = vec![u32::MAX; self.vertices.len()];
        let mut vertices = Vec::new();
        let triangles = self
            .triangles
            .iter()
            .enumerate()
            .filter(|(k, _)| keep(*k))
            .map(|(_, t)| {
                t.map(|i| {
                    let slot = &mut index[i as usize];
                    if *slot == u32::MAX {
                        *slot = vertices.len() as u32;
                        vertices.push(self.vertices[i as usize]);
                    }
                    *slot
                })
            })
            .collect();
        TriMesh { vertices, triangles }
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
    fn a_split_keeps_every_bit_of_area_on_its_side() {
        let mesh = tetrahedron();
        let normal = Vector3::new(1.0, 0.3, -0.2).normalize();
        let point = Point3::new(0.3, 0.2, 0.1);
        let [below, above] = mesh.split_by_plane(&point, &normal);
        approx::assert_relative_eq!(
            below.compute_area() + above.compute_area(),
            mesh.compute_area(),
            max_relative = 1e-13
        );
        assert!(below.compute_area() > 0.1 && above.compute_area() > 0.1);
        let side = |m: &TriMesh| {
            m.vertices
                .iter()
                .map(|p| (p - point).dot(&normal))
                .fold((f64::MAX, f64::MIN), |(lo, hi), h| (lo.min(h), hi.max(h)))
        };
        assert!(side(&below).1 <= 1e-15 && side(&above).0 >= -1e-15);
        // Windings kept: every piece faces the way its triangle did.
        for piece in [&below, &above] {
            for (i, _) in piece.triangles.iter().enumerate() {
                let n = piece.triangle_normal(i);
                assert!((0..4).any(|j| (mesh.triangle_normal(j) - n).norm() < 1e-12), "{n}");
            }
        }
        // A plane missing the mesh leaves it whole on one side.
        let [below, above] = mesh.split_by_plane(&Point3::new(5.0, 0.0, 0.0), &Vector3::x());
        assert_eq!((below.triangles.len(), above.triangles.len()), (4, 0));
    }

    #[test]
    fn box_distance_is_the_gap_between_boxes() {
        let unit = Aabb {
            min: Point3::origin(),
            max: Point3::new(1.0, 1.0, 1.0),
        };
        let moved = Aabb {
            min: Point3::new(4.0, 5.0, 0.5),
            max: Point3::new(6.0, 6.0, 0.7),
        };
        assert_eq!(unit.distance(&moved), 5.0);
        assert_eq!(moved.distance(&unit), 5.0);
        assert_eq!(unit.distance(&unit.inflated(-0.25)), 0.0);
        approx::assert_relative_eq!(
            unit.inflated(1.5).distance(&moved),
            1.5f64.hypot(2.5),
            max_relative = 1e-15
        );
        assert_eq!(unit.merged(&moved).max, Point3::new(6.0, 6.0, 1.0));
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
    #[test]
    fn a_selection_keeps_the_chosen_triangles_and_only_their_vertices() {
        let mesh = tetrahedron();
        let picked = mesh.select_triangles(|k| k == 1 || k == 3);
        assert_eq!(picked.triangles.len(), 2);
        for (kept, k) in picked.triangles.iter().zip([1, 3]) {
            let corners = |m: &TriMesh, t: &[u32; 3]| t.map(|i| m.vertices[i as usize]);
            assert_eq!(corners(&picked, kept), corners(&mesh, &mesh.triangles[k]));
        }
        // Every vertex kept is used.
        let used: std::collections::HashSet<u32> = picked.triangles.iter().flatten().copied().collect();
        assert_eq!(used.len(), picked.vertices.len());
        assert!(mesh.select_triangles(|_| false).vertices.is_empty());
        assert_eq!(mesh.select_triangles(|_| true).compute_area(), mesh.compute_area());
    }
}
