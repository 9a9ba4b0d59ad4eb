//! Airfoils, wing lofting, part meshes, STL writing and the parry3d collision adapter.
//!
//! (Being filled: see issue 2.)
pub mod mesh;
pub use mesh::TriMesh;
