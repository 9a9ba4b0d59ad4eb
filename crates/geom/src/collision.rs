//! Collision adapter: the only place parry3d-f64 appears. Shapes (`shape` module) are built
//! once (a mesh's BVH with it) and queried here at any pose; no parry or glam type is part
//! of the public API.
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
//! tilted by dihedral) far more tightly there. The offset is applied inside this module and
//! its `shape` module (`CollisionShape::placed`); callers see the local frame only. On the transport scene's
//! trade study, the link-track's flap against its wing (the study's longest pair) went from
//! 1.6 s to 0.8-1.1 s of interference stage with this alone, the same clearances to 1e-14 m.

use glamx::DVec3;
use nalgebra::{Isometry3, Point3};
use parry3d_f64::math::Pose;
use parry3d_f64::query::{self, ClosestPoints};

use crate::error::{require_range, Error, Result};

mod mesh_pair;
mod penetration;
mod segment_triangle;
mod shape;

pub use penetration::SAMPLE_BUDGET as PENETRATION_SAMPLE_BUDGET;
pub use shape::{CollisionShape, MassProperties, OrientedBox, Slab, MIN_SLAB_TRIANGLES, SLAB_COUNT};

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

/// Distance (m) and closest points between shape `a` at `pose_a` and shape `b` at `pose_b`
/// (poses map each shape's local frame to the aircraft frame).
pub fn compute_distance(
    a: &CollisionShape,
    pose_a: &Isometry3<f64>,
    b: &CollisionShape,
    pose_b: &Isometry3<f64>,
) -> Result<Proximity> {
    compute_distance_near(a, pose_a, b, pose_b, &mut NearHint::default())
}

/// Where a query of two meshes starts: the triangles that were closest at the pair's last
/// query ([`compute_clearance_near`]). Only the time changes (the distance is the exact
/// minimum whatever the hint), and a hint from another pair does no harm.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct NearHint(Option<(u32, u32)>);

/// True when one of the shapes, a solid, holds a point of the other's surface: with the
/// surfaces apart, one wholly inside the other ([`compute_clearance`] then reports them
/// overlapping). A point query or two: cheap beside a distance.
pub fn compute_holds(a: &CollisionShape, pose_a: &Isometry3<f64>, b: &CollisionShape, pose_b: &Isometry3<f64>) -> bool {
    let (pa, pb) = (to_pose(pose_a), to_pose(pose_b));
    holds(b, &pb, a, &pa) || holds(a, &pa, b, &pb)
}

/// [`compute_distance`] for one of a sequence of queries of the same pair at nearby poses:
/// two meshes' search starts from the triangles closest at the last query, kept in `hint`
/// (the same distance as without it).
pub fn compute_distance_near(
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
    let surfaces = compute_distance_near(a, pose_a, b, pose_b, hint)?;
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
