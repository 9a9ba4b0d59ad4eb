//! The collision shape: a parry shape with its surface for penetration sampling, built
//! once (a mesh's BVH with it) and posed at query time; what it is made of (its box, its
//! oriented box, its core balls, its mass). The queries between shapes are the parent
//! module's.

use glamx::DVec3;
use nalgebra::{Isometry3, Point3, Vector3};
use parry3d_f64::bounding_volume::Aabb;
use parry3d_f64::math::Pose;
use parry3d_f64::shape::{SharedShape, TriMeshFlags};

use std::sync::{Arc, OnceLock};

use super::{positive, to_glam, to_point, to_pose};
use crate::error::{Error, Result};
use crate::mesh::TriMesh;

/// Angular subdivisions of a ball, capsule or cylinder when its surface is sampled for
/// penetration depth: the edges lie within r (1 - cos(pi/32)) = 0.5 % of the radius of
/// the true surface, the faces within 0.97 % (samples are projected back onto the true
/// surface, which stretches the grid by under 1 %).
const PRIMITIVE_SUBDIVISIONS: u32 = 32;

/// A shape for clearance queries, in its own local frame (placed by a pose at query time).
#[derive(Clone)]
pub struct CollisionShape {
    pub(super) shape: SharedShape,
    /// The surface as triangles in the local frame (primitives tessellated), sampled for
    /// penetration depth.
    pub(super) surface: Arc<Vec<[DVec3; 3]>>,
    /// False for an open surface ([`CollisionShape::from_surface`]): nothing is inside it.
    pub(super) solid: bool,
    /// Where parry's shape sits in the local frame (local from stored). A mesh is stored
    /// in its vertices' principal axes: a wing's or a flap's triangles are slivers along a
    /// swept, dihedral-tilted surface, whose boxes in the aircraft frame are centimetres
    /// thick across the surface where the triangles are not; along the principal axes
    /// they are flat, and the mesh-pair search tests far fewer pairs (`mesh_pair`).
    pub(super) frame: Pose,
    /// A mesh's axis-aligned box in the local frame (what its box at a pose turns, as
    /// parry turns a mesh's own box); `None` for a primitive, whose box parry computes
    /// exactly at any pose.
    pub(super) local_box: Option<Aabb>,
    /// The mesh's slabs ([`Self::slabs`]), built on first use and shared by the shape's
    /// clones.
    slabs: Arc<OnceLock<Vec<Slab>>>,
}

/// Slabs a mesh is cut into ([`CollisionShape::slabs`]). Sweeps bound each slab's speed on
/// its own, so the count trades the tighter bound of a thinner slab against a query per
/// slab. On the transport study's link-track (its flap against the wing, the study's
/// longest pair), the whole flap took 342 samples, 4 slabs 189, 6 slabs 183, 8 and 12
/// slabs 182-183; the study's CPU time was 0.89 s whole and 0.76-0.78 s with 4 to 12 slabs
/// (BENCHMARKS.md). With two, the slower slab is bounded by more than the interference
/// sweep's threshold for slabs (`SLABS_WORTH_IT`), and the whole flap is swept.
pub const SLAB_COUNT: usize = 6;

/// Fewest triangles a slab of a mesh may average ([`CollisionShape::slabs`]): a mesh of a
/// few dozen triangles is queried whole as fast as a slab.
pub const MIN_SLAB_TRIANGLES: usize = 16;

/// One slab of a mesh ([`CollisionShape::slabs`]): an open surface in the mesh's local
/// frame and its vertices there.
#[derive(Debug, Clone)]
pub struct Slab {
    /// The slab's triangles as a sheet (nothing is inside it).
    pub shape: CollisionShape,
    /// Its vertices, local frame (m).
    pub vertices: Vec<Point3<f64>>,
}

impl std::fmt::Debug for CollisionShape {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CollisionShape")
            .field("type", &self.shape.shape_type())
            .finish()
    }
}

/// The principal axes of `points` (local frame): origin at their mean, axes the
/// eigenvectors of their covariance (right-handed); `None` without points.
fn principal_axes(points: &[Vector3<f64>]) -> Option<Isometry3<f64>> {
    if points.is_empty() {
        return None;
    }
    let mean = points.iter().sum::<Vector3<f64>>() / points.len() as f64;
    let covariance = points
        .iter()
        .map(|p| (p - mean) * (p - mean).transpose())
        .sum::<nalgebra::Matrix3<f64>>();
    let mut axes = covariance.symmetric_eigen().eigenvectors;
    if axes.determinant() < 0.0 {
        axes.set_column(2, &-axes.column(2));
    }
    let rotation = nalgebra::Rotation3::from_matrix(&axes);
    Some(Isometry3::from_parts(
        nalgebra::Translation3::from(mean),
        nalgebra::UnitQuaternion::from_rotation_matrix(&rotation),
    ))
}

fn triangles(vertices: &[DVec3], indices: &[[u32; 3]]) -> Arc<Vec<[DVec3; 3]>> {
    Arc::new(indices.iter().map(|t| t.map(|i| vertices[i as usize])).collect())
}

impl CollisionShape {
    /// Wraps a parry primitive (meshes are built by `from_triangles`); its surface is
    /// tessellated once for penetration sampling. Private: parry types stay out of the
    /// public API.
    fn from_shared(shape: SharedShape) -> Self {
        let n = PRIMITIVE_SUBDIVISIONS;
        let (vertices, indices) = if let Some(ball) = shape.as_ball() {
            ball.to_trimesh(n, n / 2)
        } else if let Some(capsule) = shape.as_capsule() {
            capsule.to_trimesh(n, n / 2)
        } else if let Some(cuboid) = shape.as_cuboid() {
            cuboid.to_trimesh()
        } else if let Some(cylinder) = shape.as_cylinder() {
            cylinder.to_trimesh(n)
        } else if let Some(hull) = shape.as_convex_polyhedron() {
            hull.to_trimesh()
        } else {
            (Vec::new(), Vec::new())
        };
        let surface = triangles(&vertices, &indices);
        CollisionShape {
            shape,
            surface,
            solid: true,
            frame: Pose::IDENTITY,
            local_box: None,
            slabs: Arc::default(),
        }
    }
}

impl CollisionShape {
    /// A triangle mesh (its BVH built here, once). The mesh should be closed and outward
    /// oriented for [`Self::contains_point`] to be meaningful.
    pub fn from_mesh(mesh: &TriMesh) -> Result<CollisionShape> {
        Self::from_triangles(mesh, true)
    }

    /// A mesh stored in its vertices' principal axes (`frame`), oriented when `solid` (and
    /// parry accepts it as such), its surface kept as given.
    fn from_triangles(mesh: &TriMesh, solid: bool) -> Result<CollisionShape> {
        let points: Vec<Vector3<f64>> = mesh.vertices.iter().map(|p| p.coords).collect();
        // A mesh with a non-finite vertex keeps its local frame (the frame would spread the
        // NaN to every vertex; mesh validation reports the vertex).
        let frame = principal_axes(&points)
            .filter(|axes| {
                axes.translation
                    .vector
                    .iter()
                    .chain(axes.rotation.coords.iter())
                    .all(|c| c.is_finite())
            })
            .map_or(Pose::IDENTITY, |axes| to_pose(&axes));
        let stored: Vec<DVec3> = mesh
            .vertices
            .iter()
            .map(|p| frame.inverse_transform_point(to_glam(p)))
            .collect();
        let rejected = |e| Error::Collision {
            reason: format!("triangle mesh rejected: {e:?}"),
        };
        let shape = if solid {
            SharedShape::trimesh_with_flags(stored.clone(), mesh.triangles.clone(), TriMeshFlags::ORIENTED)
                .or_else(|_| SharedShape::trimesh(stored, mesh.triangles.clone()))
        } else {
            SharedShape::trimesh(stored, mesh.triangles.clone())
        }
        .map_err(rejected)?;
        let vertices: Vec<DVec3> = mesh.vertices.iter().map(to_glam).collect();
        Ok(CollisionShape {
            shape,
            surface: triangles(&vertices, &mesh.triangles),
            solid,
            frame,
            local_box: Some(Aabb::from_points(vertices.iter().copied())),
            slabs: Arc::default(),
        })
    }

    /// A mesh's surface cut into at most [`SLAB_COUNT`] slabs of equal width across its
    /// middle principal axis (a flap's: chordwise strips along its span), each triangle in
    /// the slab that holds its centroid: every surface point lies in one slab, so the
    /// surface's distance to anything is the smallest of its slabs'. A sweep bounds each
    /// slab's speed by where its own points are (a flap's nose moves slower than its
    /// trailing edge). Fewer slabs where some would be empty; none for a primitive, a mesh
    /// of fewer than [`MIN_SLAB_TRIANGLES`] triangles a slab, or one flat or not finite
    /// across its middle axis. Built once, on first use.
    pub fn slabs(&self) -> &[Slab] {
        self.slabs.get_or_init(|| self.cut_slabs(SLAB_COUNT))
    }

    fn cut_slabs(&self, count: usize) -> Vec<Slab> {
        let Some(mesh) = self.shape.as_trimesh() else {
            return Vec::new();
        };
        if count < 2 || mesh.indices().len() < MIN_SLAB_TRIANGLES * count {
            return Vec::new();
        }
        // Stored coordinates are along the principal axes: the axis of middle extent.
        let stored = mesh.vertices();
        let extent = |axis: usize| {
            let (lo, hi) = stored
                .iter()
                .map(|v| v[axis])
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)));
            (hi - lo, lo)
        };
        let mut axes = [0, 1, 2].map(|axis| (extent(axis), axis));
        axes.sort_by(|x, y| x.0 .0.total_cmp(&y.0 .0));
        let ((width, low), axis) = axes[1];
        if !(width.is_finite() && width > 0.0) {
            return Vec::new();
        }
        // `surface` is in the mesh's triangle order: parry keeps the order and every
        // triangle with the flags `from_triangles` gives it (no merging or deleting).
        debug_assert_eq!(mesh.indices().len(), self.surface.len());
        let mut members: Vec<Vec<usize>> = vec![Vec::new(); count];
        for (index, triangle) in mesh.indices().iter().enumerate() {
            let centroid = triangle.iter().map(|&i| stored[i as usize][axis]).sum::<f64>() / 3.0;
            let slab = (((centroid - low) / width * count as f64) as usize).min(count - 1);
            members[slab].push(index);
        }
        members
            .into_iter()
            .filter(|m| !m.is_empty())
            .map(|m| {
                let mut piece = TriMesh::default();
                let mut renumbered = std::collections::HashMap::new();
                for &index in &m {
                    // The local-frame corners as given (`surface` is in the mesh's order).
                    let corners = self.surface[index];
                    let mut triangle = [0u32; 3];
                    for (k, &i) in mesh.indices()[index].iter().enumerate() {
                        triangle[k] = *renumbered.entry(i).or_insert_with(|| {
                            piece.vertices.push(to_point(corners[k]));
                            (piece.vertices.len() - 1) as u32
                        });
                    }
                    piece.triangles.push(triangle);
                }
                let vertices = piece.vertices.clone();
                Self::from_triangles(&piece, false)
                    .ok()
                    .map(|shape| Slab { shape, vertices })
            })
            // Every slab or none: the slabs must hold the whole surface. (A slab of a mesh
            // parry accepted is accepted: its triangles are the mesh's.)
            .collect::<Option<Vec<Slab>>>()
            .unwrap_or_default()
    }

    /// An open surface (a skin with openings cut in it): a sheet, not a solid. Clearance to
    /// it is the distance to its triangles; a part crossing it touches it, and a part on
    /// either side of it is clear of it (nothing is inside a sheet).
    pub fn from_surface(mesh: &TriMesh) -> Result<CollisionShape> {
        Self::from_triangles(mesh, false)
    }

    /// The pose of parry's shape when the local frame is at `pose`.
    pub(super) fn placed(&self, pose: &Pose) -> Pose {
        *pose * self.frame
    }

    /// The shape's box when the local frame is at `pose` (a mesh's local box turned).
    pub(super) fn aabb_at(&self, pose: &Pose) -> Aabb {
        match &self.local_box {
            Some(local) => local.transform_by(pose),
            None => self.shape.compute_aabb(&self.placed(pose)),
        }
    }

    /// True for a solid, false for an open surface ([`Self::from_surface`]).
    pub fn is_solid(&self) -> bool {
        self.solid
    }

    /// A sphere of `radius_m` centred at the local origin.
    pub fn ball(radius_m: f64) -> Result<CollisionShape> {
        Ok(Self::from_shared(SharedShape::ball(positive(
            "ball radius_m",
            radius_m,
        )?)))
    }

    /// A capsule: segment `a`-`b` (local frame, m) swept by a sphere of `radius_m`.
    pub fn capsule(a: Point3<f64>, b: Point3<f64>, radius_m: f64) -> Result<CollisionShape> {
        Ok(Self::from_shared(SharedShape::capsule(
            to_glam(&a),
            to_glam(&b),
            positive("capsule radius_m", radius_m)?,
        )))
    }

    /// A box centred at the local origin with the given half extents (m) along local x, y, z.
    pub fn cuboid(half_extents_m: Vector3<f64>) -> Result<CollisionShape> {
        let [x, y, z] = [half_extents_m.x, half_extents_m.y, half_extents_m.z];
        Ok(Self::from_shared(SharedShape::cuboid(
            positive("cuboid half extent x (m)", x)?,
            positive("cuboid half extent y (m)", y)?,
            positive("cuboid half extent z (m)", z)?,
        )))
    }

    /// A cylinder centred at the local origin, axis along local **y** (parry's convention).
    pub fn cylinder(half_height_m: f64, radius_m: f64) -> Result<CollisionShape> {
        Ok(Self::from_shared(SharedShape::cylinder(
            positive("cylinder half height (m)", half_height_m)?,
            positive("cylinder radius_m", radius_m)?,
        )))
    }

    /// The convex hull of `points` (local frame, m).
    pub fn convex_hull(points: &[Point3<f64>]) -> Result<CollisionShape> {
        let points: Vec<DVec3> = points.iter().map(to_glam).collect();
        SharedShape::convex_hull(&points)
            .map(Self::from_shared)
            .ok_or_else(|| Error::Collision {
                reason: format!("convex hull of {} points is degenerate", points.len()),
            })
    }

    /// A box holding the shape placed at `pose` (aircraft frame): exact for primitives, the
    /// mesh's own box turned with it for meshes (looser, never smaller).
    pub fn compute_aabb(&self, pose: &Isometry3<f64>) -> crate::mesh::Aabb {
        let aabb = self.aabb_at(&to_pose(pose));
        crate::mesh::Aabb {
            min: to_point(aabb.mins),
            max: to_point(aabb.maxs),
        }
    }

    /// A box aligned with the principal axes of a triangle mesh's vertices that holds the
    /// mesh (local frame): for a long swept part (a flap) far tighter than its axis-aligned
    /// box. `None` for a shape that is not a triangle mesh (a tessellated primitive's
    /// vertices do not bound its round surface).
    pub fn compute_oriented_box(&self) -> Option<OrientedBox> {
        // A mesh is stored in its principal axes (`frame`): its box there is the one.
        let mesh = self.shape.as_trimesh()?;
        let first = mesh.vertices().first()?;
        let (lo, hi) = mesh
            .vertices()
            .iter()
            .fold((*first, *first), |(lo, hi), v| (lo.min(*v), hi.max(*v)));
        let local_from_box = self.frame * Pose::from_translation((lo + hi) / 2.0);
        let half = (hi - lo) / 2.0;
        Some(OrientedBox {
            local_from_box: Isometry3::from(local_from_box),
            half_extents_m: Vector3::new(half.x, half.y, half.z),
        })
    }

    /// Balls the shape is made of, as their centres (local frame, m) and common radius (m):
    /// a ball's own centre, a capsule's two segment ends; `None` for every other shape.
    /// Each ball lies within the shape, so a shape is no farther from anything than the
    /// nearest of its balls.
    pub fn core_balls(&self) -> Option<(Vec<Point3<f64>>, f64)> {
        let local = |p: DVec3| to_point(self.frame.transform_point(p));
        if let Some(ball) = self.shape.as_ball() {
            return Some((vec![local(DVec3::ZERO)], ball.radius));
        }
        self.shape
            .as_capsule()
            .map(|c| (vec![local(c.segment.a), local(c.segment.b)], c.radius))
    }

    /// True when `point_ac` is inside (or on) the shape placed at `pose`.
    pub fn contains_point(&self, pose: &Isometry3<f64>, point_ac: &Point3<f64>) -> bool {
        self.shape
            .contains_point(&self.placed(&to_pose(pose)), to_glam(point_ac))
    }

    /// The surface the check samples, as a mesh in the local frame: a mesh shape's own
    /// triangles, a primitive tessellated with 32 subdivisions (its vertices on the
    /// true surface). Vertices that coincide exactly are shared, so a closed primitive gives
    /// a closed mesh. For files people look at (STL, glTF): the same solid the check uses.
    pub fn compute_surface_mesh(&self) -> TriMesh {
        let mut index: std::collections::HashMap<[u64; 3], u32> = std::collections::HashMap::new();
        let mut mesh = TriMesh::default();
        for triangle in self.surface.iter() {
            let corners = triangle.map(|v| {
                let key = [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()];
                *index.entry(key).or_insert_with(|| {
                    mesh.vertices.push(to_point(v));
                    (mesh.vertices.len() - 1) as u32
                })
            });
            // A primitive's tessellation collapses rows of triangles at its poles.
            if corners[0] != corners[1] && corners[1] != corners[2] && corners[0] != corners[2] {
                mesh.triangles.push(corners);
            }
        }
        mesh
    }

    /// Mass, centre of mass and inertia of the solid at uniform `density_kg_m3`, in the
    /// local frame (parry's mass properties: exact for balls and capsules, the divergence
    /// theorem over the triangles for a closed mesh). `None` for an open surface, which
    /// holds no volume.
    pub fn compute_mass_properties(&self, density_kg_m3: f64) -> Option<MassProperties> {
        if !self.solid {
            return None;
        }
        let properties = self.shape.mass_properties(density_kg_m3);
        let inertia = properties.reconstruct_inertia_matrix();
        let column = |c: glamx::DVec3| Vector3::new(c.x, c.y, c.z);
        // Parry's figures are in the stored frame: the centre of mass moved into the local
        // frame, the tensor turned (I = R I_stored R^T).
        let turn = nalgebra::Matrix3::from_columns(&[
            column(self.frame.transform_vector(DVec3::X)),
            column(self.frame.transform_vector(DVec3::Y)),
            column(self.frame.transform_vector(DVec3::Z)),
        ]);
        let stored =
            nalgebra::Matrix3::from_columns(&[column(inertia.x_axis), column(inertia.y_axis), column(inertia.z_axis)]);
        Some(MassProperties {
            mass_kg: properties.mass(),
            centre_of_mass: to_point(self.frame.transform_point(properties.local_com)),
            inertia_kg_m2: turn * stored * turn.transpose(),
        })
    }
}

/// A box holding a shape, in the shape's local frame ([`CollisionShape::compute_oriented_box`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OrientedBox {
    /// The box's centre and axes in the shape's local frame.
    pub local_from_box: Isometry3<f64>,
    /// Half its edge lengths along its axes (m).
    pub half_extents_m: Vector3<f64>,
}

/// Mass properties of a rigid solid ([`CollisionShape::compute_mass_properties`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassProperties {
    /// Mass, kg.
    pub mass_kg: f64,
    /// Centre of mass, local frame (m).
    pub centre_of_mass: Point3<f64>,
    /// Inertia tensor about the centre of mass, local frame axes (kg m^2).
    pub inertia_kg_m2: nalgebra::Matrix3<f64>,
}
