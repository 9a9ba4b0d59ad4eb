//! Binary STL export (stl_io): metres, f32, normals from the winding.
//!
//! stl_io stores the normal it is given; each normal here is the unit normal of the
//! triangle's counter-clockwise winding (outward for the crate's meshes). stl_io's own
//! `validate()` is not used: its absolute area epsilon rejects valid sub-millimetre faces
//! in metre units; use [`crate::TriMesh::compute_topology_check`] instead.

use std::io::Write;

use crate::error::Result;
use crate::mesh::TriMesh;

/// Writes `mesh` as binary STL (coordinates in metres, as f32). STL has no units field;
/// the 80-byte header holds `flapwright <name> (m)` (truncated, never starting with
/// "solid", which readers would take for ASCII STL).
pub fn write_binary(mesh: &TriMesh, name: &str, mut writer: impl Write) -> Result<()> {
    let to_vertex = |p: &nalgebra::Point3<f64>| stl_io::Vertex::new([p.x as f32, p.y as f32, p.z as f32]);
    let triangles: Vec<stl_io::Triangle> = (0..mesh.triangles.len())
        .map(|i| {
            let n = mesh.triangle_normal(i);
            let [a, b, c] = mesh.triangles[i].map(|v| to_vertex(&mesh.vertices[v as usize]));
            stl_io::Triangle {
                normal: stl_io::Normal::new([n.x as f32, n.y as f32, n.z as f32]),
                vertices: [a, b, c],
            }
        })
        .collect();
    let mut bytes = Vec::with_capacity(84 + 50 * triangles.len());
    stl_io::write_stl(&mut bytes, triangles.iter())?;
    let header = format!("flapwright {name} (m)");
    let header = header.as_bytes();
    let length = header.len().min(80);
    bytes[..length].copy_from_slice(&header[..length]);
    writer.write_all(&bytes)?;
    Ok(())
}
