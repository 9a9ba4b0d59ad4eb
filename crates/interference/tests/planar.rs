//! The fairing's planar solids are the interference check's 3D parts cut by the station
//! plane: same places, same radii, at every flap rotation.

use std::sync::Arc;

use flapwright_interference::{planar_parts, station_parts, PlanarCapsule, StationParts};
use flapwright_kinds::{CircularArcTrack, CircularArcTrackSpec};
use flapwright_mechanism::FlapMechanism;
use nalgebra::{Isometry3, Point2, Point3, Vector2};

fn thesis_parts() -> (Arc<dyn FlapMechanism>, StationParts) {
    let track: Arc<dyn FlapMechanism> =
        Arc::new(CircularArcTrack::synthesise(CircularArcTrackSpec::thesis_case_study()).unwrap());
    // Station frame = aircraft frame, so the plane is z = 0.
    let parts = station_parts("st", Some("flap"), &Isometry3::identity(), &track).unwrap();
    (track, parts)
}

/// Points across the middle of a planar capsule at `fraction` of its radius from its axis.
fn across_the_middle(capsule: &PlanarCapsule, fraction: f64) -> [Point3<f64>; 2] {
    let middle = capsule.from + (capsule.to - capsule.from) * 0.5;
    let along = capsule.to - capsule.from;
    let normal = if along.norm() > 0.0 {
        Vector2::new(-along.y, along.x).normalize()
    } else {
        Vector2::x()
    };
    let at = |p: Point2<f64>| Point3::new(p.x, p.y, 0.0);
    let offset = normal * (fraction * capsule.radius_m);
    [at(middle + offset), at(middle - offset)]
}

#[test]
fn planar_parts_are_the_3d_parts_in_the_station_plane() {
    let (track, parts) = thesis_parts();
    let mut named = std::collections::BTreeSet::new();
    // Drive fractions: stowed, part way, deployed.
    for t in [0.0, 0.3, 1.0] {
        for capsule in planar_parts(track.as_ref(), t).unwrap() {
            named.insert(capsule.part.clone());
            let name = format!("st.{}", capsule.part);
            // The fairing's solids are the parts in the station plane (each part proper
            // lies in its spanwise layer, the same solid moved along z).
            let part = parts
                .parts
                .iter()
                .map(|p| &p.in_plane)
                .find(|p| p.name == name)
                .unwrap_or_else(|| panic!("{name}"));
            let pose = part.motion.pose_ac(t).unwrap();
            // Inside at 90 % of the radius, outside at 110 % (the track tubes have 16
            // facets: inradius cos(pi/16) = 98 % of the radius).
            for point in across_the_middle(&capsule, 0.9) {
                assert!(part.shape.contains_point(&pose, &point), "{name} at t = {t}: {point}");
            }
            for point in across_the_middle(&capsule, 1.1) {
                assert!(!part.shape.contains_point(&pose, &point), "{name} at t = {t}: {point}");
            }
        }
    }
    let every_part: std::collections::BTreeSet<_> = parts
        .parts()
        .map(|p| p.name.trim_start_matches("st.").to_string())
        .collect();
    assert_eq!(named, every_part, "every 3D part has its planar solids");
}

#[test]
fn the_drive_fraction_spans_each_stations_own_input_travel() {
    // At τ = 1 every moving part stands where the mechanism's deployed pose puts it, and
    // its speed bound per unit τ is the bound per unit input times the travel.
    let (track, parts) = thesis_parts();
    let range = track.input_range();
    let deployed = track.pose(range.deployed).unwrap();
    let stowed = track.pose(range.stowed).unwrap();
    let screw = parts.parts().find(|p| p.name == "st.screw").unwrap();
    // The screw capsule's local frame is the aircraft frame: its displacement moves B0 not.
    let at_one = screw.motion.pose_ac(1.0).unwrap();
    let b0 = deployed.point("B0").unwrap();
    let moved = at_one.transform_point(&Point3::new(b0.x, b0.y, 0.0));
    assert!((moved - Point3::new(b0.x, b0.y, 0.0)).norm() < 1e-12);
    let tip_stowed = stowed.point("B").unwrap();
    let tip = at_one.transform_point(&Point3::new(tip_stowed.x, tip_stowed.y, 0.0));
    let expected = deployed.point("B").unwrap();
    assert!((tip - Point3::new(expected.x, expected.y, 0.0)).norm() < 1e-12, "{tip}");
    let body = &track.bodies()[1];
    let solid = &body.solids[0];
    assert!((screw.motion.speed_bound() - body.speed_bound.for_shape(&solid.shape) * range.travel()).abs() < 1e-15);
}

#[test]
fn a_flap_mesh_bound_counts_the_distance_from_the_axis_not_the_span() {
    // Flap points at the station and 2 m outboard along its z axis move alike: the bound
    // holds against finite differences and is not loosened by the spanwise offset.
    let (track, _) = thesis_parts();
    let near = [Point3::new(-0.35, 0.33, 0.0), Point3::new(0.1, 0.3, 0.0)];
    let far: Vec<Point3<f64>> = near.iter().map(|p| p + nalgebra::Vector3::new(0.0, 0.0, 2.0)).collect();
    let shape = || flapwright_geom::collision::CollisionShape::ball(0.01).unwrap();
    let at_station = flapwright_interference::flap_part(
        "flap",
        flapwright_interference::FlapElement::Main,
        shape(),
        &near,
        &Isometry3::identity(),
        &track,
    )
    .unwrap();
    let spanwise = flapwright_interference::flap_part(
        "flap",
        flapwright_interference::FlapElement::Main,
        shape(),
        &[near.as_slice(), far.as_slice()].concat(),
        &Isometry3::identity(),
        &track,
    )
    .unwrap();
    assert!((spanwise.motion.speed_bound() - at_station.motion.speed_bound()).abs() < 1e-12);
    let steps = 2000;
    let mut fastest: f64 = 0.0;
    for k in 0..steps {
        let (t0, t1) = (k as f64 / steps as f64, (k + 1) as f64 / steps as f64);
        let (a, b) = (
            spanwise.motion.pose_ac(t0).unwrap(),
            spanwise.motion.pose_ac(t1).unwrap(),
        );
        for p in near.iter().chain(&far) {
            fastest = fastest.max((b * p - a * p).norm() * steps as f64);
        }
    }
    let bound = spanwise.motion.speed_bound();
    assert!(fastest <= bound * (1.0 + 1e-9), "{fastest} > {bound}");
    assert!(fastest > 0.5 * bound, "{fastest} vs {bound}");
}
