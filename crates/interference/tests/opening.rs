//! Openings: a part crossing the skin passes only through the opening cut for it, never
//! through the upper skin, nor the lower skin outside the opening; a part joined to the
//! flap crosses it only through the slot in its lower side.

use flapwright_geom::collision::CollisionShape;
use flapwright_geom::TriMesh;
use flapwright_interference::{cut_opening, sweep_pair, OpenedSurface, Opening, Part, SweepSettings};
use nalgebra::{Isometry3, Point3};

/// A closed, outward box standing for a wing's trailing-edge bay, station frame = aircraft
/// frame: x from -1 (aft) to 1 (forward), y (up) from -0.1 to 0.1, z (span) from -1 to 1;
/// split into a grid so that its faces are triangles of 0.25 m like a coarse skin mesh.
fn bay() -> TriMesh {
    let mut mesh = TriMesh::default();
    // Each face as a 8 x 8 grid of quads: (origin, u, v), u x v outward.
    let faces = [
        (Point3::new(-1.0, -0.1, -1.0), [2.0, 0.0, 0.0], [0.0, 0.0, 2.0]), // lower, -y
        (Point3::new(-1.0, 0.1, 1.0), [2.0, 0.0, 0.0], [0.0, 0.0, -2.0]),  // upper, +y
        (Point3::new(-1.0, -0.1, -1.0), [0.0, 0.0, 2.0], [0.0, 0.2, 0.0]), // aft, -x
        (Point3::new(1.0, -0.1, -1.0), [0.0, 0.2, 0.0], [0.0, 0.0, 2.0]),  // forward, +x
        (Point3::new(-1.0, -0.1, -1.0), [0.0, 0.2, 0.0], [2.0, 0.0, 0.0]), // inboard, -z
        (Point3::new(-1.0, -0.1, 1.0), [2.0, 0.0, 0.0], [0.0, 0.2, 0.0]),  // outboard, +z
    ];
    for (origin, u, v) in faces {
        let (u, v) = (nalgebra::Vector3::from(u), nalgebra::Vector3::from(v));
        let n = 8;
        let first = mesh.vertices.len() as u32;
        for i in 0..=n {
            for j in 0..=n {
                mesh.vertices
                    .push(origin + u * (i as f64 / n as f64) + v * (j as f64 / n as f64));
            }
        }
        let at = |i: u32, j: u32| first + i * (n + 1) + j;
        for i in 0..n {
            for j in 0..n {
                mesh.triangles.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                mesh.triangles.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
            }
        }
    }
    mesh
}

/// The opening of a station at z = 0 whose parts sweep x in [-0.6, -0.2] (station x points
/// forward), 20 mm wide with a 6 mm margin, the rear spar's aft face at x = 0.
fn opening() -> Opening {
    Opening {
        station: "s".into(),
        half_width_m: 0.016,
        slot_half_width_m: 0.016,
        chordwise_x_m: [-0.606, -0.194],
        pads_x_m: Vec::new(),
        margin_m: 0.006,
        skin_area_m2: 0.0,
        flap_area_m2: 0.0,
    }
}

/// The smallest clearance of a 10 mm capsule from `from` to `to` against `sheet`.
fn clearance(sheet: &Part, from: [f64; 3], to: [f64; 3]) -> f64 {
    let rod = CollisionShape::capsule(Point3::from(from), Point3::from(to), 0.010).unwrap();
    let rod = Part::fixed("rod", rod);
    sweep_pair(&rod, sheet, 0.0, 1.0, &SweepSettings::default())
        .unwrap()
        .min_clearance_m
}

#[test]
fn the_bay_helper_faces_outward() {
    // Outward normals give the box's volume 2 x 0.2 x 2 (the faces' grids meet without
    // sharing vertices, so the divergence sum still holds).
    approx::assert_relative_eq!(bay().compute_signed_volume(), 0.8, max_relative = 1e-12);
}

fn opened(surface: OpenedSurface) -> Part {
    let (left, removed_m2) = cut_opening(&bay(), &Isometry3::identity(), &opening(), surface);
    assert!(removed_m2 > 0.0);
    assert!(left.compute_topology_check().boundary_edges > 0, "an opening is a hole");
    Part::fixed("wing", CollisionShape::from_surface(&left).unwrap())
}

#[test]
fn a_part_through_its_opening_passes_and_one_elsewhere_fails() {
    let skin = opened(OpenedSurface::WingSkin);
    // Down through the lower skin inside the opening, from inside the bay into the
    // fairing: clear of the skin by the margin less the rod's radius... and more.
    let through_opening = clearance(&skin, [-0.4, 0.0, 0.0], [-0.4, -0.3, 0.0]);
    assert!(through_opening >= 0.005, "{through_opening}");
    // The same rod up through the upper skin: never cut.
    assert_eq!(clearance(&skin, [-0.4, 0.0, 0.0], [-0.4, 0.3, 0.0]), 0.0);
    // Through the lower skin ahead of the opening (in the wing box, x > 0).
    assert_eq!(clearance(&skin, [0.3, 0.0, 0.0], [0.3, -0.3, 0.0]), 0.0);
    // Through the lower skin beside the opening, spanwise.
    assert_eq!(clearance(&skin, [-0.4, 0.0, 0.05], [-0.4, -0.3, 0.05]), 0.0);
    // Inside the bay and clear of the skin: its distance to the nearest skin.
    let inside = clearance(&skin, [-0.4, 0.0, 0.0], [-0.2, 0.0, 0.0]);
    approx::assert_relative_eq!(inside, 0.09, max_relative = 1e-9);
}

#[test]
fn a_part_joined_to_the_flap_crosses_it_only_through_its_slot() {
    let flap = opened(OpenedSurface::Flap);
    // Up into the flap through its lower side, within the slot, anywhere along the chord.
    assert!(clearance(&flap, [0.7, -0.3, 0.0], [0.7, 0.0, 0.0]) >= 0.005);
    // Out through the flap's upper side: a track through the flap outside its slot.
    assert_eq!(clearance(&flap, [0.7, -0.3, 0.0], [0.7, 0.3, 0.0]), 0.0);
    // Through the lower side beside the slot.
    assert_eq!(clearance(&flap, [0.7, -0.3, 0.1], [0.7, 0.0, 0.1]), 0.0);
}
