//! Sweeps of a moving mesh slab by slab (`CollisionShape::slabs`): the same clearance as
//! the whole mesh's sweep, certified against a dense sampling, in fewer samples where the
//! nearest slab moves slower than the mesh's far end; overlap and containment reported as
//! for the whole mesh.

use flapwright_geom::collision::{compute_clearance, CollisionShape};
use flapwright_geom::{tube_mesh, TriMesh};
use flapwright_interference::{sweep_pair, sweep_pair_for_verdict, Motion, Part, SweepSettings};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};

use crate::TurnAboutZ;

/// Rotation about the aircraft z axis by `t` (rad), with its field: a point at radius r
/// from the axis moves at r per radian.
struct TurnWithField {
    max_radius_m: f64,
}

impl Motion for TurnWithField {
    fn pose_ac(&self, t: f64) -> Result<Isometry3<f64>, flapwright_mechanism::Error> {
        Ok(Isometry3::rotation(Vector3::z() * t))
    }

    fn speed_bound(&self) -> f64 {
        self.max_radius_m
    }

    fn field_speed_bound(&self, local_points: &[Point3<f64>]) -> Option<f64> {
        Some(local_points.iter().map(|p| p.x.hypot(p.y)).fold(0.0, f64::max))
    }
}

/// A flat plank 4 m along z, from 0.1 m to 2 m from the z axis along x, 95 mm thick: a
/// flap-like mesh whose inner edge moves a twentieth as fast as its outer one when it
/// turns about z. A tube flattened into an ellipse: 48 points round, rings 0.1 m apart.
fn plank() -> TriMesh {
    let tube = tube_mesh(
        &[Point3::new(1.05, 0.0, -2.0), Point3::new(1.05, 0.0, 2.0)],
        0.95,
        48,
        0.1,
    )
    .unwrap();
    TriMesh {
        vertices: tube
            .vertices
            .iter()
            .map(|p| Point3::new(p.x, p.y * 0.05, p.z))
            .collect(),
        triangles: tube.triangles,
    }
}

/// A 40 mm cube placed near the plank's inner edge as the plank turns through 0.5 rad.
fn cube_near_the_inner_edge() -> Part {
    let cube = CollisionShape::cuboid(Vector3::new(0.02, 0.02, 0.02)).unwrap();
    let angle: f64 = 0.75;
    Part::fixed_at(
        "cube",
        cube,
        Isometry3::from_parts(
            Translation3::new(0.3 * angle.cos(), 0.3 * angle.sin(), 0.5),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), angle),
        ),
    )
}

const END_RAD: f64 = 0.5;

/// The smallest clearance over `samples` even samples of [0, END_RAD] (no sweep).
fn densely_sampled(mover: &Part, fixed: &Part, samples: usize) -> f64 {
    (0..=samples)
        .map(|k| {
            let t = END_RAD * k as f64 / samples as f64;
            compute_clearance(
                &mover.shape,
                &mover.motion.pose_ac(t).unwrap(),
                &fixed.shape,
                &fixed.motion.pose_ac(t).unwrap(),
                1e-3,
            )
            .unwrap()
            .distance_m
        })
        .fold(f64::INFINITY, f64::min)
}

fn planks() -> (Part, Part) {
    let shape = CollisionShape::from_mesh(&plank()).unwrap();
    assert!(shape.slabs().len() >= 4, "{} slabs", shape.slabs().len());
    (
        Part::moving("slabbed", shape.clone(), TurnWithField { max_radius_m: 2.0 }),
        // The same motion, without its field: swept whole.
        Part::moving("whole", shape, TurnAboutZ { max_radius_m: 2.0 }),
    )
}

#[test]
fn the_slabs_bound_the_inner_edge_by_its_own_speed() {
    let (slabbed, whole) = planks();
    let bounds = slabbed.slab_speed_bounds().unwrap();
    assert!(whole.slab_speed_bounds().is_none(), "no field, no slab bounds");
    // Slabs across the plank's width (x), each bounded by its outermost point.
    let slowest = bounds.iter().copied().fold(f64::INFINITY, f64::min);
    assert!(slowest < 0.5, "{bounds:?}");
    assert!(bounds.iter().all(|b| *b <= 2.0 + 1e-12), "{bounds:?}");
}

#[test]
fn a_slabbed_sweep_finds_the_whole_meshs_clearance_in_fewer_samples() {
    let (slabbed, whole) = planks();
    let cube = cube_near_the_inner_edge();
    let settings = SweepSettings::default();
    let by_slabs = sweep_pair(&slabbed, &cube, 0.0, END_RAD, &settings).unwrap();
    let by_whole = sweep_pair(&whole, &cube, 0.0, END_RAD, &settings).unwrap();
    // The cube passes about 2 cm from the plank's face.
    let dense = densely_sampled(&whole, &cube, 4000);
    assert!(dense > 0.01 && dense < 0.05, "{dense}");
    for found in [&by_slabs, &by_whole] {
        // Certified: no lower than the bound, and a sampled distance is never below the
        // dense minimum by more than the plank's inner edge moves in half a dense step.
        assert!(
            found.min_clearance_m - found.residual_bound_m <= dense + 1e-12,
            "{found:?}"
        );
        assert!(
            found.min_clearance_m >= dense - 0.5 * 2.0 * END_RAD / 4000.0,
            "{found:?}"
        );
        assert_eq!(found.penetration_m, 0.0);
    }
    assert!(
        by_slabs.evaluations * 2 < by_whole.evaluations,
        "{} samples slab by slab against {} whole",
        by_slabs.evaluations,
        by_whole.evaluations
    );
    // Points in the pair's order: the plank's point is a's, at the plank's inner part.
    let a = Point3::from(by_slabs.point_a_ac);
    assert!(a.x.hypot(a.y) < 0.5, "{a}");

    // The other way round, the same clearance with the points swapped.
    let swapped = sweep_pair(&cube, &slabbed, 0.0, END_RAD, &settings).unwrap();
    assert_eq!(swapped.min_clearance_m, by_slabs.min_clearance_m);
    assert_eq!(swapped.point_b_ac, by_slabs.point_a_ac);

    // For the verdict alone, the same verdict either way.
    let required = dense - 0.01;
    let verdict = SweepSettings {
        stop_at_verdict: true,
        ..settings
    };
    let pass_slabbed = sweep_pair_for_verdict(&slabbed, &cube, 0.0, END_RAD, &verdict, required).unwrap();
    let pass_whole = sweep_pair_for_verdict(&whole, &cube, 0.0, END_RAD, &verdict, required).unwrap();
    for found in [&pass_slabbed, &pass_whole] {
        assert!(found.min_clearance_m - found.residual_bound_m >= required, "{found:?}");
    }
    assert!(pass_slabbed.evaluations < pass_whole.evaluations);
}

#[test]
fn a_slabbed_mesh_inside_a_solid_or_through_it_overlaps() {
    let (slabbed, whole) = planks();
    // A 6 m box round the axis holds the plank at every turn: no surface is crossed.
    let room = Part::fixed("room", CollisionShape::cuboid(Vector3::new(3.0, 3.0, 3.0)).unwrap());
    // A post the plank's outer part runs through.
    let post = Part::fixed_at(
        "post",
        CollisionShape::cuboid(Vector3::new(0.02, 0.02, 1.0)).unwrap(),
        Isometry3::translation(1.5 * 0.3_f64.cos(), 1.5 * 0.3_f64.sin(), 0.0),
    );
    let settings = SweepSettings::default();
    for fixed in [&room, &post] {
        let by_slabs = sweep_pair(&slabbed, fixed, 0.0, END_RAD, &settings).unwrap();
        let by_whole = sweep_pair(&whole, fixed, 0.0, END_RAD, &settings).unwrap();
        assert_eq!(by_slabs.min_clearance_m, 0.0, "{by_slabs:?}");
        assert_eq!(by_whole.min_clearance_m, 0.0, "{by_whole:?}");
        assert!(by_slabs.penetration_m > 0.0, "{by_slabs:?}");
    }
    // Inside the room, every sample is the whole plank's overlap: the same answer.
    let in_room = sweep_pair(&slabbed, &room, 0.0, END_RAD, &settings).unwrap();
    let whole_in_room = sweep_pair(&whole, &room, 0.0, END_RAD, &settings).unwrap();
    assert_eq!(in_room.penetration_m, whole_in_room.penetration_m);
}

#[test]
fn a_part_given_another_shape_bounds_the_new_shapes_slabs() {
    // The slab bounds are found once for the part's shape; a shape put in afterwards (the
    // field is public) has other slabs, and its bounds must be its own.
    let (mut slabbed, _) = planks();
    let cube = cube_near_the_inner_edge();
    let settings = SweepSettings::default();
    sweep_pair(&slabbed, &cube, 0.0, END_RAD, &settings).unwrap();
    let before = slabbed.slab_speed_bounds().unwrap();
    // A plank half as wide, from 0.1 to 1.05 m: its slabs are slower.
    let narrower = TriMesh {
        vertices: plank()
            .vertices
            .iter()
            .map(|p| Point3::new(0.1 + (p.x - 0.1) * 0.5, p.y, p.z))
            .collect(),
        triangles: plank().triangles,
    };
    slabbed.shape = CollisionShape::from_mesh(&narrower).unwrap();
    let after = slabbed.slab_speed_bounds().unwrap();
    assert_eq!(after.len(), slabbed.shape.slabs().len());
    // The fastest slab: the outer edge, at 2 m before and at 1.05 m now.
    let fastest = |bounds: &[f64]| bounds.iter().fold(0.0_f64, |m, b| m.max(*b));
    assert!(
        fastest(&before) > 1.9 && fastest(&after) < 1.1,
        "{before:?} then {after:?}"
    );
    let found = sweep_pair(&slabbed, &cube, 0.0, END_RAD, &settings).unwrap();
    let dense = densely_sampled(&slabbed, &cube, 4000);
    assert!(
        found.min_clearance_m - found.residual_bound_m <= dense + 1e-12,
        "{found:?} against {dense}"
    );
}
