//! Collision adapter: the only place parry3d-f64 appears. Shapes are built once (a mesh's
//! BVH with it) and queried at any pose; no parry or glam type is part of the public API.
//!
//! Pitfalls (from parry's design, checked by the crate's tests with parry3d-f64 0.31.1):
//! for a triangle mesh, [`compute_distance`] measures to the *surface*: a part wholly
//! inside a mesh reports a positive distance to the nearest face, while
//! [`compute_intersects`] (meshes are built oriented) reports it as intersecting. Model solids as convex shapes (capsule, cuboid,
//! cylinder, convex hull) or test containment with [`CollisionShape::contains_point`],
//! which uses the mesh orientation (pseudo-normals). Mesh-against-mesh distances go through
//! `mesh_pair`, not parry's composite-vs-composite query, which is slow for nested meshes
//! (the module says why).

use glamx::DVec3;
use nalgebra::{Isometry3, Point3, Vector3};
use parry3d_f64::math::Pose;
use parry3d_f64::query::{self, ClosestPoints};
use parry3d_f64::shape::{SharedShape, TriMeshFlags};

use crate::error::{require_range, Error, Result};
use crate::mesh::TriMesh;

mod mesh_pair;

/// A shape for clearance queries, in its own local frame (placed by a pose at query time).
#[derive(Clone)]
pub struct CollisionShape {
    shape: SharedShape,
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

fn positive(what: &'static str, value: f64) -> Result<f64> {
    require_range(what, value, f64::MIN_POSITIVE, f64::MAX)
}

impl CollisionShape {
    /// A triangle mesh (its BVH built here, once). The mesh should be closed and outward
    /// oriented for [`Self::contains_point`] to be meaningful.
    pub fn from_mesh(mesh: &TriMesh) -> Result<CollisionShape> {
        let vertices: Vec<DVec3> = mesh.vertices.iter().map(to_glam).collect();
        let shape = SharedShape::trimesh_with_flags(vertices.clone(), mesh.triangles.clone(), TriMeshFlags::ORIENTED)
            .or_else(|_| SharedShape::trimesh(vertices, mesh.triangles.clone()))
            .map_err(|e| Error::Collision {
                reason: format!("triangle mesh rejected: {e:?}"),
            })?;
        Ok(CollisionShape { shape })
    }

    /// A sphere of `radius_m` centred at the local origin.
    pub fn ball(radius_m: f64) -> Result<CollisionShape> {
        Ok(CollisionShape {
            shape: SharedShape::ball(positive("ball radius_m", radius_m)?),
        })
    }

    /// A capsule: segment `a`-`b` (local frame, m) swept by a sphere of `radius_m`.
    pub fn capsule(a: Point3<f64>, b: Point3<f64>, radius_m: f64) -> Result<CollisionShape> {
        Ok(CollisionShape {
            shape: SharedShape::capsule(to_glam(&a), to_glam(&b), positive("capsule radius_m", radius_m)?),
        })
    }

    /// A box centred at the local origin with the given half extents (m) along local x, y, z.
    pub fn cuboid(half_extents_m: Vector3<f64>) -> Result<CollisionShape> {
        let [x, y, z] = [half_extents_m.x, half_extents_m.y, half_extents_m.z];
        Ok(CollisionShape {
            shape: SharedShape::cuboid(
                positive("cuboid half extent x (m)", x)?,
                positive("cuboid half extent y (m)", y)?,
                positive("cuboid half extent z (m)", z)?,
            ),
        })
    }

    /// A cylinder centred at the local origin, axis along local **y** (parry's convention).
    pub fn cylinder(half_height_m: f64, radius_m: f64) -> Result<CollisionShape> {
        Ok(CollisionShape {
            shape: SharedShape::cylinder(
                positive("cylinder half height (m)", half_height_m)?,
                positive("cylinder radius_m", radius_m)?,
            ),
        })
    }

    /// The convex hull of `points` (local frame, m).
    pub fn convex_hull(points: &[Point3<f64>]) -> Result<CollisionShape> {
        let points: Vec<DVec3> = points.iter().map(to_glam).collect();
        SharedShape::convex_hull(&points)
            .map(|shape| CollisionShape { shape })
            .ok_or_else(|| Error::Collision {
                reason: format!("convex hull of {} points is degenerate", points.len()),
            })
    }

    /// True when `point_ac` is inside (or on) the shape placed at `pose`.
    pub fn contains_point(&self, pose: &Isometry3<f64>, point_ac: &Point3<f64>) -> bool {
        self.shape.contains_point(&to_pose(pose), to_glam(point_ac))
    }
}

/// Distance (m) and closest points between shape `a` at `pose_a` and shape `b` at `pose_b`
/// (poses map each shape's local frame to the aircraft frame).
pub fn compute_distance(
    a: &CollisionShape,
    pose_a: &Isometry3<f64>,
    b: &CollisionShape,
    pose_b: &Isometry3<f64>,
) -> Result<Proximity> {
    let (pa, pb) = (to_pose(pose_a), to_pose(pose_b));
    if let (Some(mesh_a), Some(mesh_b)) = (a.shape.as_trimesh(), b.shape.as_trimesh()) {
        let closest = mesh_pair::mesh_pair_distance(mesh_a, &pa, mesh_b, &pb);
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
    let distance = query::distance(&pa, &*a.shape, &pb, &*b.shape)
        .map_err(|_| unsupported("distance"))?
        .distance;
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
    let (p, q) = contact.map_or((pa.translation, pb.translation), |c| (c.point1, c.point2));
    Ok(Proximity {
        distance_m: distance.max(0.0),
        point_a_ac: to_point(p),
        point_b_ac: to_point(q),
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
    query::intersection_test(&to_pose(pose_a), &*a.shape, &to_pose(pose_b), &*b.shape)
        .map(|r| r.intersecting)
        .map_err(|_| Error::Collision {
            reason: format!(
                "intersection test not supported between {:?} and {:?}",
                a.shape.shape_type(),
                b.shape.shape_type()
            ),
        })
}
