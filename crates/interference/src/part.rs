//! Parts as the sweep sees them: a collision shape and how it moves with deployment.

use flapwright_geom::collision::{CollisionShape, MassProperties};
use flapwright_geom::TriMesh;
use std::sync::{Arc, Mutex};

use nalgebra::{Isometry3, Point3};

/// How a rigid part moves with the deployment parameter `t` (e.g. flap deflection, rad).
pub trait Motion: Send + Sync {
    /// Pose of the part's local frame in the aircraft frame at deployment `t`; an error
    /// when the mechanism cannot be posed there.
    fn pose_ac(&self, t: f64) -> Result<Isometry3<f64>, flapwright_mechanism::Error>;

    /// A certified upper bound on the speed of any point of the part, in metres per unit
    /// of `t`, over the whole deployment range. The sweep's guarantee rests on it:
    /// |d(t) - d(t')| <= (L_a + L_b) |t - t'| for the distance d between two parts.
    fn speed_bound(&self) -> f64;

    /// A certified upper bound on the speed (m per unit of `t`) of the part's rigid
    /// velocity field (the motion extended to all space) at every point of the convex hull
    /// of `local_points`, given in the part's local frame; `None` when the motion cannot
    /// say. Unlike [`Motion::speed_bound`], the points need not belong to the part: the
    /// sweep bounds how fast another part moves *relative to this one* from it, which is
    /// far tighter than the sum of the two speed bounds for a small part near a large one
    /// (a track under a flap's nose, against the flap's trailing edge a metre aft).
    fn field_speed_bound(&self, _local_points: &[Point3<f64>]) -> Option<f64> {
        None
    }
}

/// A part that does not move (wing skin, spars, torque tube, fixed tracks): its local
/// frame stays at this pose in the aircraft frame.
#[derive(Debug, Clone, Copy)]
pub struct Fixed(pub Isometry3<f64>);

impl Motion for Fixed {
    fn pose_ac(&self, _t: f64) -> Result<Isometry3<f64>, flapwright_mechanism::Error> {
        Ok(self.0)
    }

    fn speed_bound(&self) -> f64 {
        0.0
    }

    fn field_speed_bound(&self, _local_points: &[Point3<f64>]) -> Option<f64> {
        Some(0.0)
    }
}

/// One speed bound a slab ([`Part::slab_speed_bounds`]), or none.
type SlabBounds = Option<Arc<[f64]>>;

/// A part for the sweep: name, shape in its local frame, motion.
pub struct Part {
    /// Part name (as in the report and JUnit file).
    pub name: String,
    /// Shape in the part's local frame.
    pub shape: CollisionShape,
    /// How the local frame moves.
    pub motion: Arc<dyn Motion>,
    /// Each of the shape's slabs' speed bound ([`Part::slab_speed_bounds`]), found on
    /// first use, with the shape they were found for (`shape` is public: a shape put in
    /// later has its own slabs, and its bounds are found again).
    slab_speed_bounds: Mutex<Option<(CollisionShape, SlabBounds)>>,
}

impl std::fmt::Debug for Part {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Part")
            .field("name", &self.name)
            .field("speed_bound", &self.motion.speed_bound())
            .finish()
    }
}

impl Part {
    /// A part that does not move (its shape given in the aircraft frame).
    pub fn fixed(name: impl Into<String>, shape: CollisionShape) -> Self {
        Self::fixed_at(name, shape, Isometry3::identity())
    }

    /// A part that does not move, its shape's local frame at `pose_ac`.
    pub fn fixed_at(name: impl Into<String>, shape: CollisionShape, pose_ac: Isometry3<f64>) -> Self {
        Self {
            name: name.into(),
            shape,
            motion: Arc::new(Fixed(pose_ac)),
            slab_speed_bounds: Mutex::new(None),
        }
    }

    /// A moving part.
    pub fn moving(name: impl Into<String>, shape: CollisionShape, motion: impl Motion + 'static) -> Self {
        Self {
            name: name.into(),
            shape,
            motion: Arc::new(motion),
            slab_speed_bounds: Mutex::new(None),
        }
    }

    /// The same part (name and motion) with another shape: the surface left of a skin or a
    /// flap once an opening is cut in it.
    pub fn reshaped(&self, shape: CollisionShape) -> Self {
        Self {
            name: self.name.clone(),
            shape,
            motion: Arc::clone(&self.motion),
            slab_speed_bounds: Mutex::new(None),
        }
    }

    /// The part's surface in the aircraft frame at deployment `t`: the solid the check
    /// sweeps, tessellated, for files people look at (STL, glTF).
    pub fn compute_mesh_ac(&self, t: f64) -> Result<TriMesh, flapwright_mechanism::Error> {
        Ok(self.shape.compute_surface_mesh().transformed(&self.motion.pose_ac(t)?))
    }

    /// Mass, centre of mass and inertia at uniform `density_kg_m3`, aircraft frame, at
    /// deployment `t` (the local tensor turned, I = R I_local R^T); `None` for an open
    /// surface.
    pub fn compute_mass_properties_ac(
        &self,
        density_kg_m3: f64,
        t: f64,
    ) -> Result<Option<MassProperties>, flapwright_mechanism::Error> {
        let pose = self.motion.pose_ac(t)?;
        Ok(self.shape.compute_mass_properties(density_kg_m3).map(|local| {
            let turn = pose.rotation.to_rotation_matrix();
            MassProperties {
                mass_kg: local.mass_kg,
                centre_of_mass: pose * local.centre_of_mass,
                inertia_kg_m2: turn.matrix() * local.inertia_kg_m2 * turn.matrix().transpose(),
            }
        }))
    }

    /// A speed bound (m per unit t) for each of the shape's slabs
    /// ([`CollisionShape::slabs`], in their order): the motion's field over the slab's
    /// points, capped by the part's own bound; `None` for a part that does not move, a
    /// shape without slabs, or a motion that cannot bound its field. Found once for every
    /// pair of the part, and again if its shape is replaced.
    pub fn slab_speed_bounds(&self) -> SlabBounds {
        let slabs = self.shape.slabs();
        // A poisoned lock only means another sweep failed part way: what it kept is whole.
        let mut kept = self.slab_speed_bounds.lock().unwrap_or_else(|e| e.into_inner());
        // The slabs' address names them: a shape's slabs are built once and never moved,
        // and the shape kept here keeps them alive, so no other slabs can take their
        // address (a shape's clones share its slabs, and their bounds).
        if let Some((shape, bounds)) = kept.as_ref() {
            if std::ptr::eq(shape.slabs().as_ptr(), slabs.as_ptr()) {
                return bounds.clone();
            }
        }
        let bounds = self.compute_slab_speed_bounds(slabs);
        *kept = Some((self.shape.clone(), bounds.clone()));
        bounds
    }

    fn compute_slab_speed_bounds(&self, slabs: &[flapwright_geom::collision::Slab]) -> SlabBounds {
        let whole = self.motion.speed_bound();
        if !(whole.is_finite() && whole > 0.0) || slabs.is_empty() {
            return None;
        }
        slabs
            .iter()
            .map(|slab| {
                let field = self.motion.field_speed_bound(&slab.vertices)?;
                (field.is_finite() && field >= 0.0).then_some(field.min(whole))
            })
            .collect()
    }

    /// True when the part moves (non-zero speed bound).
    pub fn is_moving(&self) -> bool {
        self.motion.speed_bound() > 0.0
    }
}
