//! Collision adapter against analytic distances.

use approx::assert_relative_eq;
use flapwright_geom::{
    compute_clearance, compute_clearance_near, compute_distance, compute_distance_near, compute_holds,
    compute_intersects, compute_signed_distance, CollisionShape, NearHint, TriMesh,
};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};

fn at(x: f64, y: f64, z: f64) -> Isometry3<f64> {
    Isometry3::from_parts(Translation3::new(x, y, z), UnitQuaternion::identity())
}

#[test]
fn sphere_sphere_distance_is_analytic() {
    let a = CollisionShape::ball(0.5).unwrap();
    let b = CollisionShape::ball(0.25).unwrap();
    let (ca, cb) = (Point3::new(1.0, 2.0, -1.0), Point3::new(3.0, 0.5, 0.0));
    let d = (cb - ca).norm();
    let proximity = compute_distance(&a, &at(ca.x, ca.y, ca.z), &b, &at(cb.x, cb.y, cb.z)).unwrap();
    assert_relative_eq!(proximity.distance_m, d - 0.75, max_relative = 1e-12);
    assert_relative_eq!(proximity.point_a_ac, ca + (cb - ca) * (0.5 / d), epsilon = 1e-12);
    assert_relative_eq!(proximity.point_b_ac, cb - (cb - ca) * (0.25 / d), epsilon = 1e-12);
    assert!(!compute_intersects(&a, &at(ca.x, ca.y, ca.z), &b, &at(cb.x, cb.y, cb.z)).unwrap());
    assert!(compute_intersects(&a, &at(0.0, 0.0, 0.0), &b, &at(0.7, 0.0, 0.0)).unwrap());
    assert_eq!(
        compute_distance(&a, &at(0.0, 0.0, 0.0), &b, &at(0.7, 0.0, 0.0))
            .unwrap()
            .distance_m,
        0.0
    );
}

#[test]
fn box_box_distance_is_analytic_including_a_rotated_corner() {
    let a = CollisionShape::cuboid(Vector3::new(0.5, 1.0, 1.0)).unwrap();
    let b = CollisionShape::cuboid(Vector3::new(0.25, 0.25, 0.25)).unwrap();
    let proximity = compute_distance(&a, &at(0.0, 0.0, 0.0), &b, &at(2.0, 0.1, 0.0)).unwrap();
    assert_relative_eq!(proximity.distance_m, 2.0 - 0.5 - 0.25, max_relative = 1e-12);
    // b turned 45 deg about z points a vertical edge at a: distance 2 - 0.5 - 0.25 sqrt(2).
    let turned = Isometry3::from_parts(
        Translation3::new(2.0, 0.0, 0.0),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_4),
    );
    let proximity = compute_distance(&a, &at(0.0, 0.0, 0.0), &b, &turned).unwrap();
    assert_relative_eq!(proximity.distance_m, 1.5 - 0.25 * 2f64.sqrt(), max_relative = 1e-9);
    assert_relative_eq!(proximity.point_b_ac.x, 2.0 - 0.25 * 2f64.sqrt(), max_relative = 1e-9);
}

/// The unit cube [0, 1]^3 as a mesh (12 triangles, outward).
fn unit_cube() -> TriMesh {
    let vertices = (0..8)
        .map(|i| Point3::new(f64::from(i & 1), f64::from((i >> 1) & 1), f64::from((i >> 2) & 1)))
        .collect();
    let triangles = vec![
        [0, 2, 1],
        [1, 2, 3],
        [4, 5, 6],
        [5, 7, 6],
        [0, 1, 4],
        [1, 5, 4],
        [2, 6, 3],
        [3, 6, 7],
        [0, 4, 2],
        [2, 4, 6],
        [1, 3, 5],
        [3, 7, 5],
    ];
    TriMesh { vertices, triangles }
}

#[test]
fn mesh_cube_against_ball_and_containment() {
    let mesh = unit_cube();
    assert!(mesh.compute_topology_check().is_watertight());
    assert_relative_eq!(mesh.compute_signed_volume(), 1.0, max_relative = 1e-14);
    let cube = CollisionShape::from_mesh(&mesh).unwrap();
    let ball = CollisionShape::ball(0.2).unwrap();
    let proximity = compute_distance(&cube, &at(0.0, 0.0, 0.0), &ball, &at(0.5, 0.5, 1.7)).unwrap();
    assert_relative_eq!(proximity.distance_m, 0.5, max_relative = 1e-9);
    assert!(cube.contains_point(&at(0.0, 0.0, 0.0), &Point3::new(0.5, 0.5, 0.5)));
    assert!(!cube.contains_point(&at(0.0, 0.0, 0.0), &Point3::new(1.5, 0.5, 0.5)));
    // A ball wholly inside the (oriented) cube mesh: the distance query sees the surface
    // (0.5 - 0.2 to the nearest face), the intersection test treats the inside as solid.
    // Recorded here so a parry upgrade that changes either is noticed.
    let inside = compute_distance(&cube, &at(0.0, 0.0, 0.0), &ball, &at(0.5, 0.5, 0.5)).unwrap();
    assert_relative_eq!(inside.distance_m, 0.3, max_relative = 1e-9);
    assert!(compute_intersects(&cube, &at(0.0, 0.0, 0.0), &ball, &at(0.5, 0.5, 0.5)).unwrap());
    assert!(CollisionShape::ball(-1.0).is_err());
    assert!(CollisionShape::convex_hull(&[Point3::origin(); 3]).is_err());
    assert_eq!(ball.core_balls(), Some((vec![Point3::origin()], 0.2)));
    assert_eq!(cube.core_balls(), None);
}

#[test]
fn signed_distance_to_a_point_is_negative_inside_a_solid_only() {
    let mesh = unit_cube();
    let (solid, sheet) = (
        CollisionShape::from_mesh(&mesh).unwrap(),
        CollisionShape::from_surface(&mesh).unwrap(),
    );
    // The cube shifted by (1, 0, 0): a point 0.2 inside its x = 1 face, one 0.3 outside
    // its corner edge (distance to the edge x = 2, y = 0 is 0.3 sqrt 2).
    let pose = at(1.0, 0.0, 0.0);
    let inside = Point3::new(1.2, 0.5, 0.5);
    let outside = Point3::new(2.3, -0.3, 0.5);
    assert_relative_eq!(
        compute_signed_distance(&solid, &pose, &inside).unwrap(),
        -0.2,
        epsilon = 1e-12
    );
    assert_relative_eq!(
        compute_signed_distance(&solid, &pose, &outside).unwrap(),
        0.3 * 2f64.sqrt(),
        epsilon = 1e-12
    );
    // An open sheet has no inside.
    assert_relative_eq!(
        compute_signed_distance(&sheet, &pose, &inside).unwrap(),
        0.2,
        epsilon = 1e-12
    );
    // A capsule of radius 0.1 along x: inside by 0.1 - 0.04 on its axis side.
    let capsule = CollisionShape::capsule(Point3::origin(), Point3::new(1.0, 0.0, 0.0), 0.1).unwrap();
    assert_eq!(
        capsule.core_balls(),
        Some((vec![Point3::origin(), Point3::new(1.0, 0.0, 0.0)], 0.1))
    );
    let near_axis = Point3::new(0.5, 0.04, 0.0);
    assert_relative_eq!(
        compute_signed_distance(&capsule, &Isometry3::identity(), &near_axis).unwrap(),
        -0.06,
        epsilon = 1e-12
    );
    assert_relative_eq!(
        compute_signed_distance(&capsule, &Isometry3::identity(), &Point3::new(1.5, 0.0, 0.0)).unwrap(),
        0.4,
        epsilon = 1e-12
    );
}

/// parry's own composite-vs-composite distance, the reference for the crate's mesh-pair
/// search (which must find the same minimum over triangle pairs, only faster).
fn parry_mesh_distance(a: &TriMesh, pose_a: &Isometry3<f64>, b: &TriMesh, pose_b: &Isometry3<f64>) -> f64 {
    use parry3d_f64::shape::TriMesh as ParryMesh;
    let to_parry = |m: &TriMesh| {
        let vertices = m.vertices.iter().map(|p| glamx::DVec3::new(p.x, p.y, p.z)).collect();
        ParryMesh::new(vertices, m.triangles.clone()).unwrap()
    };
    let pose = |p: &Isometry3<f64>| parry3d_f64::math::Pose::from(*p);
    parry3d_f64::query::distance(&pose(pose_a), &to_parry(a), &pose(pose_b), &to_parry(b))
        .unwrap()
        .distance
}

/// The fixture's wing model and its part meshes at a coarse resolution.
fn coarse_fixture() -> (flapwright_geom::WingModel, Vec<flapwright_geom::Part>) {
    let model = super::fixture::model();
    let resolution = flapwright_geom::MeshResolution {
        points_per_side: 16,
        spanwise_stations_per_m: 2.0,
        tube_segments: 8,
    };
    let parts = model.compute_parts(resolution).unwrap();
    (model, parts)
}

/// The coarse fixture's first flap, its mesh and shape, and the other parts.
struct FixtureFlap {
    parts: Vec<flapwright_geom::Part>,
    name: String,
    mesh: TriMesh,
    shape: CollisionShape,
    hinge_point: Point3<f64>,
    hinge_direction: nalgebra::Unit<Vector3<f64>>,
}

impl FixtureFlap {
    fn new() -> Self {
        let (model, parts) = coarse_fixture();
        let flap = &model.flaps()[0];
        let (hinge_point, hinge_direction) = flap.hinge_axis_ac();
        let name = flap.spec().name.clone();
        let mesh = parts.iter().find(|p| p.name == name).unwrap().mesh.clone();
        let shape = CollisionShape::from_mesh(&mesh).unwrap();
        Self {
            parts,
            name,
            mesh,
            shape,
            hinge_point,
            hinge_direction,
        }
    }

    /// The flap turned by `angle_deg` about its hinge line.
    fn turned(&self, angle_deg: f64) -> Isometry3<f64> {
        let turn = UnitQuaternion::from_axis_angle(&self.hinge_direction, f64::to_radians(angle_deg));
        Translation3::from(self.hinge_point.coords) * turn * Translation3::from(-self.hinge_point.coords)
    }

    /// Each other part with its shape, against the flap stowed (nested in the cove),
    /// deployed (12 and 40 deg) and turned the wrong way into the wing (-25 deg): the part,
    /// its shape, the angle and the flap's pose.
    fn poses_against_others(&self) -> Vec<(&flapwright_geom::Part, CollisionShape, f64, Isometry3<f64>)> {
        let mut cases = Vec::new();
        for other in self.parts.iter().filter(|p| p.name != self.name) {
            let shape = CollisionShape::from_mesh(&other.mesh).unwrap();
            for angle_deg in [0.0, 12.0, 40.0, -25.0] {
                cases.push((other, shape.clone(), angle_deg, self.turned(angle_deg)));
            }
        }
        cases
    }
}

#[test]
fn mesh_pair_distance_equals_parry_for_nested_and_crossing_meshes() {
    let fixture = FixtureFlap::new();
    let (flap_mesh, flap_shape) = (&fixture.mesh, &fixture.shape);
    let identity = Isometry3::identity();
    let mut checked = 0;
    for (other, other_shape, angle_deg, pose) in fixture.poses_against_others() {
        let ours = compute_distance(flap_shape, &pose, &other_shape, &identity).unwrap();
        let swapped = compute_distance(&other_shape, &identity, flap_shape, &pose).unwrap();
        let reference = parry_mesh_distance(flap_mesh, &pose, &other.mesh, &identity);
        let what = format!("flap at {angle_deg} deg vs {}", other.name);
        assert!(
            (ours.distance_m - reference).abs() <= 1e-12,
            "{what}: {} vs parry {reference}",
            ours.distance_m
        );
        assert!((swapped.distance_m - reference).abs() <= 1e-12, "{what} (swapped)");
        // Clear: the reported points are that far apart. Crossing: they are a contact's
        // points, apart by a penetration depth. Either way each pair mirrors the other.
        let gap = (ours.point_a_ac - ours.point_b_ac).norm();
        if reference > 0.0 {
            assert!((gap - ours.distance_m).abs() <= 1e-9, "{what}: points {gap} apart");
        }
        assert_relative_eq!(ours.point_a_ac, swapped.point_b_ac, epsilon = 1e-9);
        checked += usize::from(reference > 0.0);
    }
    // Some poses must be clear and some crossing for the comparison to cover both branches.
    assert!(
        checked > 0 && checked < 4 * (fixture.parts.len() - 1),
        "{checked} clear cases"
    );
}

#[test]
fn a_sweep_started_from_the_last_closest_triangles_gives_the_same_clearances() {
    // The flap turned through its deployment in small steps against every other part, as a
    // sweep queries it: each query starts from the triangles closest at the one before (and
    // the first from another pair's, which must do no harm). Same minimum every time.
    let fixture = FixtureFlap::new();
    let identity = Isometry3::identity();
    let mut hint = NearHint::default();
    let mut started_from_a_hint = 0;
    for other in fixture.parts.iter().filter(|p| p.name != fixture.name) {
        let other_shape = CollisionShape::from_mesh(&other.mesh).unwrap();
        for step in 0..=20 {
            let pose = fixture.turned(-5.0 + 2.5 * step as f64);
            let plain = compute_clearance(&fixture.shape, &pose, &other_shape, &identity, 1e-3).unwrap();
            started_from_a_hint += usize::from(hint != NearHint::default());
            let near = compute_clearance_near(&fixture.shape, &pose, &other_shape, &identity, 1e-3, &mut hint).unwrap();
            assert_eq!(near.distance_m, plain.distance_m, "{} at step {step}", other.name);
            assert_eq!(near.penetration_m, plain.penetration_m, "{} at step {step}", other.name);
            if near.distance_m > 0.0 {
                let gap = (near.point_a_ac - near.point_b_ac).norm();
                assert!(
                    (gap - near.distance_m).abs() <= 1e-9,
                    "{}: points {gap} apart",
                    other.name
                );
            }
        }
    }
    assert!(started_from_a_hint > 20, "{started_from_a_hint} queries had a hint");
}

#[test]
fn a_meshs_slabs_share_its_surface_and_its_distances() {
    let fixture = FixtureFlap::new();
    let slabs = fixture.shape.slabs();
    assert!(slabs.len() >= 4, "{} slabs", slabs.len());
    // Every triangle in one slab: the same count and area.
    let whole_area = fixture.mesh.compute_area();
    let (mut triangles, mut area) = (0, 0.0);
    for slab in slabs {
        let mesh = slab.shape.compute_surface_mesh();
        triangles += mesh.triangles.len();
        area += mesh.compute_area();
        assert!(!slab.shape.is_solid(), "a slab is a sheet");
        assert_eq!(slab.vertices.len(), mesh.vertices.len());
    }
    assert_eq!(triangles, fixture.mesh.triangles.len());
    assert_relative_eq!(area, whole_area, max_relative = 1e-12);
    // Slabs across the chord: each spans the flap's span, much narrower across.
    let extent = |slab: &flapwright_geom::collision::Slab| {
        let local = slab.shape.compute_aabb(&Isometry3::identity());
        local.max - local.min
    };
    let whole_box = fixture.shape.compute_aabb(&Isometry3::identity());
    let whole_extent = whole_box.max - whole_box.min;
    let span_axis = whole_extent.imax();
    assert!(
        slabs
            .iter()
            .all(|s| extent(s)[span_axis] > 0.9 * whole_extent[span_axis]),
        "each slab spans the flap"
    );
    // The smallest of the slabs' distances is the whole flap's, turned against every part.
    let identity = Isometry3::identity();
    let mut hints = vec![NearHint::default(); slabs.len()];
    let mut apart = 0;
    for (other, other_shape, angle_deg, pose) in fixture.poses_against_others() {
        let whole = compute_distance(&fixture.shape, &pose, &other_shape, &identity).unwrap();
        let nearest = slabs
            .iter()
            .zip(&mut hints)
            .map(|(slab, hint)| {
                compute_distance_near(&slab.shape, &pose, &other_shape, &identity, hint)
                    .unwrap()
                    .distance_m
            })
            .fold(f64::INFINITY, f64::min);
        assert!(
            (nearest - whole.distance_m).abs() <= 1e-12,
            "flap at {angle_deg} deg vs {}: {nearest} against {}",
            other.name,
            whole.distance_m
        );
        apart += usize::from(whole.distance_m > 0.0);
    }
    assert!(apart > 0);
    // A primitive has no slabs; a ball inside the flap's solid (at its vertices' mean) is
    // held by it, either way round; a ball far off is not.
    assert!(CollisionShape::ball(0.1).unwrap().slabs().is_empty());
    let inside =
        fixture.mesh.vertices.iter().fold(Vector3::zeros(), |s, v| s + v.coords) / fixture.mesh.vertices.len() as f64;
    let ball = CollisionShape::ball(1e-3).unwrap();
    let at_inside = Isometry3::translation(inside.x, inside.y, inside.z);
    assert!(fixture.shape.contains_point(&identity, &Point3::from(inside)));
    assert!(compute_holds(&fixture.shape, &identity, &ball, &at_inside));
    assert!(compute_holds(&ball, &at_inside, &fixture.shape, &identity));
    assert!(!compute_holds(&fixture.shape, &identity, &ball, &at(100.0, 0.0, 0.0)));
}

#[test]
fn convex_against_mesh_distance_equals_parry() {
    // A capsule and a ball at many places around and inside the fixture's flap mesh: the
    // crate's best-first search finds parry's own shape-against-mesh minimum.
    let (model, parts) = coarse_fixture();
    let flap_mesh = &parts
        .iter()
        .find(|p| p.name == model.flaps()[0].spec().name)
        .unwrap()
        .mesh;
    let flap = CollisionShape::from_mesh(flap_mesh).unwrap();
    let parry_flap = {
        let vertices = flap_mesh
            .vertices
            .iter()
            .map(|p| glamx::DVec3::new(p.x, p.y, p.z))
            .collect();
        parry3d_f64::shape::TriMesh::new(vertices, flap_mesh.triangles.clone()).unwrap()
    };
    let box_ = flap_mesh.vertices.iter().fold(
        (
            Point3::new(f64::MAX, f64::MAX, f64::MAX),
            Point3::new(f64::MIN, f64::MIN, f64::MIN),
        ),
        |(lo, hi), p| (lo.inf(p), hi.sup(p)),
    );
    let (capsule_end, radius) = (Point3::new(0.15, 0.05, -0.02), 0.012);
    let capsule = CollisionShape::capsule(Point3::origin(), capsule_end, radius).unwrap();
    let parry_segment = parry3d_f64::shape::Segment::new(
        glamx::DVec3::ZERO,
        glamx::DVec3::new(capsule_end.x, capsule_end.y, capsule_end.z),
    );
    let parry_capsule = parry3d_f64::shape::Capsule::new(parry_segment.a, parry_segment.b, radius);
    let ball = CollisionShape::ball(0.02).unwrap();
    let parry_ball = parry3d_f64::shape::Ball::new(0.02);
    let (mut clear, mut touching) = (0, 0);
    for i in 0..7 {
        for j in 0..5 {
            for k in 0..4 {
                let at = |f: f64, lo: f64, hi: f64| lo - 0.1 + (hi - lo + 0.2) * f;
                let centre = Point3::new(
                    at(i as f64 / 6.0, box_.0.x, box_.1.x),
                    at(j as f64 / 4.0, box_.0.y, box_.1.y),
                    at(k as f64 / 3.0, box_.0.z, box_.1.z),
                );
                let pose = Isometry3::from_parts(
                    Translation3::from(centre.coords),
                    UnitQuaternion::from_euler_angles(0.3 * i as f64, 0.5 * j as f64, 0.7 * k as f64),
                );
                let parry_pose = parry3d_f64::math::Pose::from(pose);
                let identity = parry3d_f64::math::Pose::IDENTITY;
                // The capsule's reference is its segment's distance less the radius: parry's
                // capsule query iterates GJK on the round support map and stops when its
                // bounds agree to 4.7e-8 of the distance, reading up to that much long (never
                // short: its points are points of the two shapes); the segment is a polytope,
                // on which GJK ends on the exact minimum.
                let segment_reference =
                    parry3d_f64::query::distance(&parry_pose, &parry_segment, &identity, &parry_flap)
                        .unwrap()
                        .distance;
                let capsule_gjk = parry3d_f64::query::distance(&parry_pose, &parry_capsule, &identity, &parry_flap)
                    .unwrap()
                    .distance;
                assert!(
                    capsule_gjk >= (segment_reference - radius).max(0.0) - 1e-12
                        && capsule_gjk <= (segment_reference - radius).max(0.0) * (1.0 + 1e-7) + 1e-12,
                    "{centre}: parry's capsule {capsule_gjk}, its segment less the radius {}",
                    segment_reference - radius
                );
                for (shape, reference) in [
                    (&capsule, Ok((segment_reference - radius).max(0.0))),
                    (
                        &ball,
                        parry3d_f64::query::distance(&parry_pose, &parry_ball, &identity, &parry_flap)
                            .map(|d| d.distance),
                    ),
                ] {
                    let reference = reference.unwrap();
                    let ours = compute_distance(shape, &pose, &flap, &Isometry3::identity()).unwrap();
                    let swapped = compute_distance(&flap, &Isometry3::identity(), shape, &pose).unwrap();
                    assert!(
                        (ours.distance_m - reference).abs() <= 1e-12,
                        "{centre}: {} vs {reference}",
                        ours.distance_m
                    );
                    assert_eq!(ours.distance_m, swapped.distance_m);
                    assert_relative_eq!(ours.point_a_ac, swapped.point_b_ac, epsilon = 1e-12);
                    if reference > 0.0 {
                        let gap = (ours.point_a_ac - ours.point_b_ac).norm();
                        assert!((gap - reference).abs() <= 1e-9, "{centre}: points {gap} apart");
                        clear += 1;
                    } else {
                        touching += 1;
                    }
                }
            }
        }
    }
    assert!(clear > 100 && touching > 0, "{clear} clear, {touching} touching");
}

/// The flap's principal-axes box holds every vertex, is smaller than its axis-aligned box
/// (the fixture's flap is swept and tapered), and its separation from each other part, at
/// poses of the flap turned about its hinge, never exceeds the flap's own clearance (a
/// lower bound, as the broad phase uses it), and is 0 where the flap crosses the part.
#[test]
fn an_oriented_box_bounds_its_mesh_and_its_separation_bounds_the_clearance() {
    let fixture = FixtureFlap::new();
    let (flap_mesh, flap_shape) = (&fixture.mesh, &fixture.shape);
    let oriented = flap_shape.compute_oriented_box().unwrap();
    let box_from_local = oriented.local_from_box.inverse();
    for v in &flap_mesh.vertices {
        let q = box_from_local * v;
        for k in 0..3 {
            assert!(q[k].abs() <= oriented.half_extents_m[k] + 1e-12, "{v} outside the box");
        }
    }
    let aabb = flap_shape.compute_aabb(&Isometry3::identity());
    let extent = aabb.max - aabb.min;
    let volume = |e: Vector3<f64>| e.x * e.y * e.z;
    assert!(volume(oriented.half_extents_m * 2.0) < volume(extent));
    assert!(CollisionShape::ball(0.1).unwrap().compute_oriented_box().is_none());
    let identity = Isometry3::identity();
    let mut positive = 0;
    for (other, other_shape, angle_deg, pose) in fixture.poses_against_others() {
        let clearance = flapwright_geom::compute_clearance(flap_shape, &pose, &other_shape, &identity, 0.01)
            .unwrap()
            .distance_m;
        for growth in [0.0, 0.05] {
            let bound =
                flapwright_geom::compute_box_separation(&oriented, &pose, growth, &other_shape, &identity).unwrap();
            assert!(
                bound <= clearance + 1e-12,
                "{} at {angle_deg} deg: {bound} > {clearance}",
                other.name
            );
            assert!(bound >= 0.0);
            if clearance == 0.0 {
                assert_eq!(bound, 0.0);
            }
            positive += usize::from(bound > 0.0);
        }
    }
    // The bound must certify something for the test to mean anything.
    assert!(positive > 0, "no pose certified apart");
    // A box wholly inside a closed mesh, and a closed mesh wholly inside a box: both
    // overlap as solids though their surfaces are apart.
    let cube = CollisionShape::from_mesh(&unit_cube()).unwrap();
    let small_mesh = TriMesh {
        vertices: unit_cube()
            .vertices
            .iter()
            .map(|v| Point3::new(0.45, 0.45, 0.45) + v.coords * 0.1)
            .collect(),
        ..unit_cube()
    };
    let small_box = CollisionShape::from_mesh(&small_mesh)
        .unwrap()
        .compute_oriented_box()
        .unwrap();
    assert_eq!(
        flapwright_geom::compute_box_separation(&small_box, &identity, 0.0, &cube, &identity).unwrap(),
        0.0
    );
    let cube_box = cube.compute_oriented_box().unwrap();
    let small_shape = CollisionShape::from_mesh(&small_mesh).unwrap();
    assert_eq!(
        flapwright_geom::compute_box_separation(&cube_box, &identity, 0.0, &small_shape, &identity).unwrap(),
        0.0
    );
    // Apart: the box's separation is the cubes' gap.
    let apart = flapwright_geom::compute_box_separation(&cube_box, &at(3.0, 0.0, 0.0), 0.0, &cube, &identity).unwrap();
    assert!((apart - 2.0).abs() < 1e-6, "{apart}");
}
