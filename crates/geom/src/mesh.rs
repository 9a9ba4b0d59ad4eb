//! Indexed triangle meshes in the aircraft frame (metres).

use nalgebra::Point3;

/// A closed, consistently oriented triangle mesh: vertices in the aircraft frame (m),
/// triangles as vertex indices wound counter-clockwise seen from outside (outward normals).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TriMesh {
    /// Vertex positions, aircraft frame, metres.
    pub vertices: Vec<Point3<f64>>,
    /// Triangles as indices into `vertices`, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
}
