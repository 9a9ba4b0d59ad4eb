//! Collision adapter: the only place parry3d-f64 appears. Shapes are built once (a mesh's
//! BVH with it) and queried at any pose; no parry or glam type is part of the public API.
//!
//! Pitfalls (from parry's design, checked by the crate's tests with parry3d-f64 0.31.1):
//! for a triangle mesh, [`compute_distance`] measures to the *surface*: a part wholly
//! inside a mesh reports a positive distance to the nearest face, while
//! [`compute_intersects`] (meshes are built oriented) reports it as intersecting.
//! [`compute_clearance`] treats every shape as a solid (containment through the mesh
//! orientation, [`CollisionShape::contains_point`]) and measures how deep overlapping
//! shapes reach into each other (`penetration` module). Mesh-against-mesh distances go through
//! `mesh_pair`, not parry's composite-vs-composite query, which is slow for nested meshes
//! (the module says why).
//!
//! A mesh is stored in its vertices' principal axes, not in its local frame: parry's BVH
//! boxes a wing's or a flap's sliver triangles (long spanwise, along a swept surface
//! tilted by dihedral) far more tightly there. The offset is applied inside this module
//! (`CollisionShape::placed`); callers see the local frame only. On the transport scene's
//! trade study, the link-track's flap against its wing (the study's longest pair) went from
//! 1.6 s to 0.8-1.1 s of interference stage with this alone, the same clearances to 1e-14 m.

use glamx::DVec3;
use nalgebra::{Isometry3, Point3, Vector3};
use parry3d_f64::bounding_volume::Aabb;
use parry3d_f64::math::Pose;
use parry3d_f64::query::{self, ClosestPoints};
use parry3d_f64::shape::{SharedShape, TriMeshFlags};

use std::sync::Arc;

use crate::error::{require_range, Error, Result};
use crate::mesh::TriMesh;

mod mesh_pair;
mod penetration;
mod segment_triangle;

pub use penetration::SAMPLE_BUDGET as PENETRATION_SAMPLE_BUDGET;

/// Angular subdivisions of a ball, capsule or cylinder when its surface is sampled for
/// penetration depth: the edges lie within r (1 - cos(pi/32)) = 0.5 % of the radius of
/// the true surface, the faces within 0.97 % (samples are projected back onto the true
/// surface, which stretches the grid by under 1 %).
const PRIMITIVE_SUBDIVISIONS: u32 = 32;

/// A shape for clearance queries, in its own local frame (placed by a pose at query time).
#[derive(Clone)]
pub struct CollisionShape {
    shape: SharedShape,
    /// The surface as triangles in the local frame (primitives tessellated), sampled for
    /// penetration depth.
    surface: Arc<Vec<[DVec3; 3]>>,
    /// False for an open surface ([`CollisionShape::from_surface`]): nothing is inside it.
    solid: bool,
    /// Where parry's shape sits in the local frame (local from stored). A mesh is stored
    /// in its vertices' principal axes: a wing's or a flap's triangles are slivers along a
    /// swept, dihedral-tilted surface, whose boxes in the aircraft frame are centimetres
    /// thick across the surface where the triangles are not; along the principal axes
    /// they are flat, and the mesh-pair search tests far fewer pairs (`mesh_pair`).
    frame: Pose,
    /// A mesh's axis-aligned box in the local frame (what its box at a pose turns, as
    /// parry turns a mesh's own box); `None` for a primitive, whose box parry computes
    /// exactly at any pose.
    local_box: Option<Aabb>,
}

impl std::fmt::Debug for CollisionShape {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CollisionShape")
            .field("type", &self.shape.shape_type())
            .finish()
    }
}

/// Result of [`compute_distance`]: separation and the closest points, aircraft frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Proximity {
    /// Separation (m); 0 when the shapes touch or overlap.
    pub distance_m: f64,
    /// Closest point on shape a (m); for overlapping shapes, a point of a's surface
    /// reported by the contact query.
    pub point_a_ac: Point3<f64>,
    /// Closest point on shape b (m).
    pub point_b_ac: Point3<f64>,
}

fn to_glam(p: &Point3<f64>) -> DVec3 {
    DVec3::new(p.x, p.y, p.z)
}

fn to_point(v: DVec3) -> Point3<f64> {
    Point3::new(v.x, v.y, v.z)
}

fn to_pose(pose: &Isometry3<f64>) -> Pose {
    Pose::from(*pose)
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

fn positive(what: &'static str, value: f64) -> Result<f64> {
    require_range(what, value, f64::MIN_POSITIVE, f64::MAX)
}

fn triangles(vertices: &[DVec3], indices: &[[u32; 3]]) -> Arc<Vec<[DVec3; 3]>> {
    Arc::new(indices.iter().map(|t| t.map(|i| vertices[i as usize])).collect())
}

impl CollisionShape {
    /// Wraps a parry shape; a primitive's surface is tessellated once for penetration
    /// sampling. Private: parry types stay out of the public API.
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
        } else if let Some(mesh) = shape.as_trimesh() {
            (mesh.vertices().to_vec(), mesh.indices().to_vec())
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
        })
    }

    /// An open surface (a skin with openings cut in it): a sheet, not a solid. Clearance to
    /// it is the distance to its triangles; a part crossing it touches it, and a part on
    /// either side of it is clear of it (nothing is inside a sheet).
    pub fn from_surface(mesh: &TriMesh) -> Result<CollisionShape> {
        Self::from_triangles(mesh, false)
    }

    /// The pose of parry's shape when the local frame is at `pose`.
    fn placed(&self, pose: &Pose) -> Pose {
        *pose * self.frame
    }

    /// The shape's box when the local frame is at `pose` (a mesh's local box turned).
    fn aabb_at(&self, pose: &Pose) -> Aabb {
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

/// The separation (m) of the box `oriented` of a shape posed at `pose`, grown by
/// `growth_m` on every side, from shape `b` at `pose_b` as solids: the surfaces' distance,
/// or 0 when they touch, cross or one holds the other. Whatever the box holds is at least
/// this far from `b`: a lower bound on its clearance (the broad phase's, for a moving part
/// against a fixed one).
pub fn compute_box_separation(
    oriented: &OrientedBox,
    pose: &Isometry3<f64>,
    growth_m: f64,
    b: &CollisionShape,
    pose_b: &Isometry3<f64>,
) -> Result<f64> {
    // Degenerate boxes (a flat part) get a hair of thickness: the box only grows.
    let half = oriented.half_extents_m.map(|h| h.max(0.0) + growth_m.max(0.0) + 1e-9);
    let cuboid = CollisionShape::cuboid(half)?;
    let box_pose = pose * oriented.local_from_box;
    let surfaces = compute_distance(&cuboid, &box_pose, b, pose_b)?.distance_m;
    let (pa, pb) = (to_pose(&box_pose), to_pose(pose_b));
    Ok(
        if surfaces > 0.0 && !holds(b, &pb, &cuboid, &pa) && !holds(&cuboid, &pa, b, &pb) {
            surfaces
        } else {
            0.0
        },
    )
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

/// Distance (m) and closest points between shape `a` at `pose_a` and shape `b` at `pose_b`
/// (poses map each shape's local frame to the aircraft frame).
pub fn compute_distance(
    a: &CollisionShape,
    pose_a: &Isometry3<f64>,
    b: &CollisionShape,
    pose_b: &Isometry3<f64>,
) -> Result<Proximity> {
    distance_near(a, pose_a, b, pose_b, &mut NearHint::default())
}

/// Where a query of two meshes starts: the triangles that were closest at the pair's last
/// query ([`compute_clearance_near`]). Only the time changes (the distance is the exact
/// minimum whatever the hint), and a hint from another pair does no harm.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct NearHint(Option<(u32, u32)>);

/// [`compute_distance`], starting from `hint` and leaving the closest triangles in it.
fn distance_near(
    a: &CollisionShape,
    pose_a: &Isometry3<f64>,
    b: &CollisionShape,
    pose_b: &Isometry3<f64>,
    hint: &mut NearHint,
) -> Result<Proximity> {
    let (pa, pb) = (a.placed(&to_pose(pose_a)), b.placed(&to_pose(pose_b)));
    // Meshes, or a convex shape against a mesh: the crate's own searches (`mesh_pair`).
    let searched = match (a.shape.as_trimesh(), b.shape.as_trimesh()) {
        (Some(mesh_a), Some(mesh_b)) => Some(mesh_pair::mesh_pair_distance(mesh_a, &pa, mesh_b, &pb, &mut hint.0)),
        (None, Some(mesh)) if a.shape.is_convex() => Some(mesh_pair::convex_mesh_distance(&*a.shape, &pa, mesh, &pb)),
        (Some(mesh), None) if b.shape.is_convex() => {
            let found = mesh_pair::convex_mesh_distance(&*b.shape, &pb, mesh, &pa);
            Some(mesh_pair::MeshPairProximity {
                point_a: found.point_b,
                point_b: found.point_a,
                ..found
            })
        }
        _ => None,
    };
    // Two capsules: their segments' distance in closed form (`segment_triangle`), less the
    // radii, where parry would iterate GJK on the round support maps.
    let capsules = a.shape.as_capsule().zip(b.shape.as_capsule());
    let searched = searched.or_else(|| {
        let (ca, cb) = capsules?;
        let pair = segment_triangle::segment_segment(
            pa.transform_point(ca.segment.a),
            pa.transform_point(ca.segment.b),
            pb.transform_point(cb.segment.a),
            pb.transform_point(cb.segment.b),
        );
        let (distance, point_a, point_b) = pair.swept(ca.radius, cb.radius)?;
        Some(mesh_pair::MeshPairProximity {
            distance,
            point_a,
            point_b,
        })
    });
    if let Some(closest) = searched {
        if !closest.distance.is_finite() || closest.distance == f64::MAX {
            return Err(Error::NotFinite {
                what: "collision distance (m)",
                value: closest.distance,
            });
        }
        return Ok(Proximity {
            distance_m: closest.distance,
            point_a_ac: to_point(closest.point_a),
            point_b_ac: to_point(closest.point_b),
        });
    }
    let unsupported = |what: &str| Error::Collision {
        reason: format!(
            "{what} not supported between {:?} and {:?}",
            a.shape.shape_type(),
            b.shape.shape_type()
        ),
    };
    // Two capsules that touch or overlap (clear ones were answered above): the contact
    // query says where.
    let distance = if capsules.is_some() {
        0.0
    } else {
        query::distance(&pa, &*a.shape, &pb, &*b.shape)
            .map_err(|_| unsupported("distance"))?
            .distance
    };
    if !distance.is_finite() {
        return Err(Error::NotFinite {
            what: "collision distance (m)",
            value: distance,
        });
    }
    if distance > 0.0 {
        let margin = distance * (1.0 + 1e-9) + 1e-12;
        if let ClosestPoints::WithinMargin(p, q) =
            query::closest_points(&pa, &*a.shape, &pb, &*b.shape, margin).map_err(|_| unsupported("closest points"))?
        {
            return Ok(Proximity {
                distance_m: distance,
                point_a_ac: to_point(p),
                point_b_ac: to_point(q),
            });
        }
    }
    let contact = query::contact(&pa, &*a.shape, &pb, &*b.shape, 0.0).map_err(|_| unsupported("contact"))?;
    // No contact point: each local frame's origin, as the poses place them.
    let (p, q) = contact.map_or(
        (
            to_glam(&pose_a.translation.vector.into()),
            to_glam(&pose_b.translation.vector.into()),
        ),
        |c| (c.point1, c.point2),
    );
    Ok(Proximity {
        distance_m: distance.max(0.0),
        point_a_ac: to_point(p),
        point_b_ac: to_point(q),
    })
}

/// Signed distance (m) from `point_ac` to the surface of `shape` placed at `pose`: its
/// distance to the nearest surface point, negative inside a solid (by
/// [`CollisionShape::contains_point`]; an open surface has no inside). Like any distance to a
/// set it changes no faster than the point and the shape's points move.
///
/// A ball of radius r centred at `point_ac` is then `signed - r` from the solid when that
/// is positive, and overlaps it when it is not: it must move at least `r - signed` to come
/// clear, which is what the interference check certifies for pins and nuts in their joints.
pub fn compute_signed_distance(shape: &CollisionShape, pose: &Isometry3<f64>, point_ac: &Point3<f64>) -> Result<f64> {
    let (pose, point) = (shape.placed(&to_pose(pose)), to_glam(point_ac));
    let distance = shape.shape.distance_to_point(&pose, point, false).abs();
    if !distance.is_finite() {
        return Err(Error::NotFinite {
            what: "signed distance to a point (m)",
            value: distance,
        });
    }
    Ok(if shape.solid && shape.shape.contains_point(&pose, point) {
        -distance
    } else {
        distance
    })
}

/// Result of [`compute_clearance`]: two parts as solids.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Clearance {
    /// Separation of the solids (m); 0 when they touch, cross, or one holds the other.
    pub distance_m: f64,
    /// How deep they overlap (m): the deepest point of either surface inside the other
    /// solid, to its surface (`penetration` module); 0 when clear, and may be 0 or short
    /// by up to the resolution when no sample lands deep inside.
    pub penetration_m: f64,
    /// Grid spacing the penetration was sampled at (m): the deepest surface point is at
    /// most this much deeper than reported (1 % more for balls, capsules and cylinders,
    /// whose grid is stretched onto the true surface). 0 when the solids are clear.
    pub penetration_resolution_m: f64,
    /// When clear, the closest point on a; when overlapping, a's end of the penetration
    /// (its deepest point inside b, or the point of a's surface nearest to b's deepest
    /// point). Aircraft frame, m.
    pub point_a_ac: Point3<f64>,
    /// The same for b.
    pub point_b_ac: Point3<f64>,
}

impl Clearance {
    /// Distance when clear, minus the penetration when overlapping: one number that
    /// orders poses from the most clear to the deepest collision.
    pub fn signed_m(&self) -> f64 {
        if self.distance_m > 0.0 {
            self.distance_m
        } else {
            -self.penetration_m
        }
    }
}

fn surface_ac(shape: &CollisionShape, pose: &Pose) -> Vec<[DVec3; 3]> {
    shape
        .surface
        .iter()
        .map(|t| t.map(|v| pose.transform_point(v)))
        .collect()
}

/// True when some point of `inner`'s surface lies inside `outer` (for a mesh, by its
/// orientation). With the surfaces apart, one such point means `inner` is wholly inside.
fn holds(outer: &CollisionShape, pose_outer: &Pose, inner: &CollisionShape, pose_inner: &Pose) -> bool {
    outer.solid
        && inner.surface.first().is_some_and(|t| {
            outer
                .shape
                .contains_point(&outer.placed(pose_outer), pose_inner.transform_point(t[0]))
        })
}

/// Clearance between shape `a` at `pose_a` and shape `b` at `pose_b` as solids: unlike
/// [`compute_distance`], a part wholly inside a closed, oriented mesh is overlapping, and
/// overlapping parts report how deep they reach into each other, sampled on a surface grid
/// of spacing `resolution_m` (coarser when the overlap is large: see
/// [`PENETRATION_SAMPLE_BUDGET`]).
pub fn compute_clearance(
    a: &CollisionShape,
    pose_a: &Isometry3<f64>,
    b: &CollisionShape,
    pose_b: &Isometry3<f64>,
    resolution_m: f64,
) -> Result<Clearance> {
    compute_clearance_near(a, pose_a, b, pose_b, resolution_m, &mut NearHint::default())
}

/// [`compute_clearance`] for one of a sequence of queries of the same pair at nearby poses
/// (a sweep): two meshes' search starts from the triangles closest at the last query,
/// kept in `hint`, whose distance bounds the search from the start (the transport study's
/// link-track interference stage: 0.8-1.1 s without, 0.42 s with). The same distance as
/// without the hint; where several triangles are equally close, which one's points are
/// reported may differ.
pub fn compute_clearance_near(
    a: &CollisionShape,
    pose_a: &Isometry3<f64>,
    b: &CollisionShape,
    pose_b: &Isometry3<f64>,
    resolution_m: f64,
    hint: &mut NearHint,
) -> Result<Clearance> {
    let resolution_m = positive("penetration resolution_m", resolution_m)?;
    let surfaces = distance_near(a, pose_a, b, pose_b, hint)?;
    let (pa, pb) = (to_pose(pose_a), to_pose(pose_b));
    let clear = Clearance {
        distance_m: surfaces.distance_m,
        penetration_m: 0.0,
        penetration_resolution_m: 0.0,
        point_a_ac: surfaces.point_a_ac,
        point_b_ac: surfaces.point_b_ac,
    };
    if surfaces.distance_m > 0.0 && !holds(b, &pb, a, &pa) && !holds(a, &pa, b, &pb) {
        return Ok(clear);
    }
    let deepest = |intruder: &CollisionShape, intruder_pose: &Pose, host: &CollisionShape, host_pose: &Pose| {
        if !host.solid {
            // Nothing reaches into a sheet; how deep the sheet reaches into the other
            // part is measured the other way round.
            return None;
        }
        let intruder_placed = intruder.placed(intruder_pose);
        let exact_surface = intruder
            .shape
            .as_trimesh()
            .is_none()
            .then_some((&*intruder.shape, &intruder_placed));
        let host_placed = host.placed(host_pose);
        penetration::deepest_inside(
            &surface_ac(intruder, intruder_pose),
            exact_surface,
            &*host.shape,
            &host_placed,
            &host.aabb_at(host_pose),
            resolution_m,
        )
    };
    let (a_in_b, b_in_a) = (deepest(a, &pa, b, &pb), deepest(b, &pb, a, &pa));
    let spacing = [a_in_b, b_in_a]
        .iter()
        .flatten()
        .map(|d| d.spacing)
        .fold(resolution_m, f64::max);
    let overlapping = Clearance {
        distance_m: 0.0,
        penetration_resolution_m: spacing,
        ..clear
    };
    Ok(match (a_in_b, b_in_a) {
        (Some(d), other) if other.is_none_or(|o| d.depth >= o.depth) => Clearance {
            penetration_m: d.depth,
            point_a_ac: to_point(d.inside),
            point_b_ac: to_point(d.surface),
            ..overlapping
        },
        (_, Some(d)) => Clearance {
            penetration_m: d.depth,
            point_a_ac: to_point(d.surface),
            point_b_ac: to_point(d.inside),
            ..overlapping
        },
        _ => overlapping,
    })
}

/// True when shape `a` at `pose_a` and shape `b` at `pose_b` touch or overlap (a shape
/// wholly inside an oriented mesh counts as overlapping: see the module pitfalls).
pub fn compute_intersects(
    a: &CollisionShape,
    pose_a: &Isometry3<f64>,
    b: &CollisionShape,
    pose_b: &Isometry3<f64>,
) -> Result<bool> {
    query::intersection_test(
        &a.placed(&to_pose(pose_a)),
        &*a.shape,
        &b.placed(&to_pose(pose_b)),
        &*b.shape,
    )
    .map(|r| r.intersecting)
    .map_err(|_| Error::Collision {
        reason: format!(
            "intersection test not supported between {:?} and {:?}",
            a.shape.shape_type(),
            b.shape.shape_type()
        ),
    })
}
