//! Work that designs of the same wing share: its parts' meshes, their statistics and their
//! collision shapes. The trade study designs the wing once per kind; every kind's wing
//! skin, flaps and spars are the same meshes (meshing the transport wing and checking its
//! topology takes 12-20 ms, its statistics 5-8 ms, a 27 000-triangle skin's BVH a few
//! milliseconds, each per design). Each is reused only for an equal model, resolution or
//! mesh, so a design reads the same meshes and shapes either way.

use std::sync::{Mutex, MutexGuard};

use flapwright_geom::collision::CollisionShape;
use flapwright_geom::parts::Part as MeshPart;
use flapwright_geom::{TriMesh, WingModel};

use crate::error::Result;
use crate::pipeline::geometry;
use crate::report::PartReport;
use crate::scene::ResolutionScene;

/// A meshed wing and, once asked, its parts' statistics.
struct MeshedWing {
    model: WingModel,
    airfoil_points_per_side: usize,
    parts: Vec<MeshPart>,
    statistics: Option<Vec<PartReport>>,
}

/// Meshes, statistics and collision shapes kept for other designs of the same wing.
#[derive(Default)]
pub struct WingCache {
    wings: Mutex<Vec<MeshedWing>>,
    shapes: Mutex<Vec<(TriMesh, CollisionShape)>>,
}

impl std::fmt::Debug for WingCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("WingCache")
            .field("wings", &lock(&self.wings).len())
            .field("shapes", &lock(&self.shapes).len())
            .finish()
    }
}

/// A poisoned lock only means another design failed part way: what it kept is whole.
fn lock<T>(mutex: &Mutex<T>) -> MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(|e| e.into_inner())
}

impl WingCache {
    /// The parts of `model` meshed at `resolution` (as a design meshes them), meshed once.
    /// The lock is held while meshing: a design asking for the same wing meanwhile waits
    /// for it rather than meshing it again.
    pub fn meshes_of(&self, model: &WingModel, resolution: &ResolutionScene) -> Result<Vec<MeshPart>> {
        let mut wings = lock(&self.wings);
        let points = resolution.airfoil_points_per_side;
        if let Some(wing) = wings
            .iter()
            .find(|w| w.airfoil_points_per_side == points && w.model == *model)
        {
            return Ok(wing.parts.clone());
        }
        let parts = geometry::mesh_parts(model, resolution)?;
        wings.push(MeshedWing {
            model: model.clone(),
            airfoil_points_per_side: points,
            parts: parts.clone(),
            statistics: None,
        });
        Ok(parts)
    }

    /// The statistics of `parts` (the report's part entries), computed once for parts
    /// this cache meshed; others' are computed each time.
    pub fn statistics_of(&self, parts: &[MeshPart]) -> Vec<PartReport> {
        let mut wings = lock(&self.wings);
        let Some(wing) = wings.iter_mut().find(|w| w.parts == parts) else {
            return geometry::part_statistics(parts);
        };
        wing.statistics
            .get_or_insert_with(|| geometry::part_statistics(parts))
            .clone()
    }

    /// The solid shape of `mesh` ([`CollisionShape::from_mesh`]), built once.
    pub fn shape_of(&self, mesh: &TriMesh) -> flapwright_geom::Result<CollisionShape> {
        let kept = |shapes: &Vec<(TriMesh, CollisionShape)>| {
            shapes.iter().find(|(m, _)| m == mesh).map(|(_, shape)| shape.clone())
        };
        if let Some(shape) = kept(&lock(&self.shapes)) {
            return Ok(shape);
        }
        let shape = CollisionShape::from_mesh(mesh)?;
        let mut shapes = lock(&self.shapes);
        if kept(&shapes).is_none() {
            shapes.push((mesh.clone(), shape.clone()));
        }
        Ok(shape)
    }
}

#[cfg(test)]
mod tests {
    use super::WingCache;
    use flapwright_geom::collision::{compute_distance, CollisionShape};
    use flapwright_geom::TriMesh;
    use nalgebra::{Isometry3, Point3};

    fn tetrahedron(offset: f64) -> TriMesh {
        TriMesh {
            vertices: vec![
                Point3::new(offset, 0.0, 0.0),
                Point3::new(offset + 1.0, 0.0, 0.0),
                Point3::new(offset, 1.0, 0.0),
                Point3::new(offset, 0.0, 1.0),
            ],
            triangles: vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
        }
    }

    #[test]
    fn a_mesh_is_built_once_and_only_an_equal_mesh_reuses_it() {
        let cache = WingCache::default();
        let (near, far) = (tetrahedron(0.0), tetrahedron(3.0));
        let first = cache.shape_of(&near).unwrap();
        let again = cache.shape_of(&near.clone()).unwrap();
        assert_eq!(format!("{cache:?}"), "WingCache { wings: 0, shapes: 1 }");
        let other = cache.shape_of(&far).unwrap();
        assert_eq!(format!("{cache:?}"), "WingCache { wings: 0, shapes: 2 }");
        // Each answers as a shape built afresh from its own mesh.
        let identity = Isometry3::identity();
        let direct = compute_distance(
            &CollisionShape::from_mesh(&near).unwrap(),
            &identity,
            &CollisionShape::from_mesh(&far).unwrap(),
            &identity,
        )
        .unwrap();
        for shape in [&first, &again] {
            let cached = compute_distance(shape, &identity, &other, &identity).unwrap();
            assert_eq!(cached.distance_m, direct.distance_m);
        }
        assert!((direct.distance_m - 2.0).abs() < 1e-12, "{}", direct.distance_m);
    }

    #[test]
    fn a_wing_is_meshed_once_and_only_an_equal_model_reuses_its_meshes() {
        use crate::pipeline::geometry;
        use crate::scene::{Scene, DEFAULT_SCENE_TOML};
        let scene = Scene::from_file_text(DEFAULT_SCENE_TOML, "default", &crate::scene::NoFiles).unwrap();
        let wing = scene.wing.as_ref().unwrap();
        let model = geometry::build_model(&scene, wing, &crate::scene::NoFiles).unwrap();
        let cache = WingCache::default();
        let first = cache.meshes_of(&model, &scene.resolution).unwrap();
        let again = cache
            .meshes_of(
                &geometry::build_model(&scene, wing, &crate::scene::NoFiles).unwrap(),
                &scene.resolution,
            )
            .unwrap();
        assert_eq!(format!("{cache:?}"), "WingCache { wings: 1, shapes: 0 }");
        assert_eq!(first, again);
        assert_eq!(first, geometry::mesh_parts(&model, &scene.resolution).unwrap());
        // Another resolution, or another wing, is meshed on its own.
        let mut finer = scene.resolution.clone();
        finer.airfoil_points_per_side += 8;
        let fine = cache.meshes_of(&model, &finer).unwrap();
        assert_ne!(fine, first);
        let mut other = scene.clone();
        other.flap[0].chord_fraction_outboard *= 0.9;
        let other_model = geometry::build_model(&other, other.wing.as_ref().unwrap(), &crate::scene::NoFiles).unwrap();
        assert!(other_model != model);
        cache.meshes_of(&other_model, &scene.resolution).unwrap();
        assert_eq!(format!("{cache:?}"), "WingCache { wings: 3, shapes: 0 }");
        // Statistics as computed afresh, for the cache's meshes and for others'.
        let fresh = serde_json::to_value(geometry::part_statistics(&first)).unwrap();
        assert_eq!(serde_json::to_value(cache.statistics_of(&first)).unwrap(), fresh);
        assert_eq!(serde_json::to_value(cache.statistics_of(&again)).unwrap(), fresh);
        let unknown = &first[..1];
        assert_eq!(
            serde_json::to_value(cache.statistics_of(unknown)).unwrap(),
            serde_json::to_value(geometry::part_statistics(unknown)).unwrap()
        );
    }
}
