//! Station frames: orthonormal, right-handed, horizontal x towards the nose, round trips.

use approx::assert_relative_eq;
use flapwright_planes::{HingeAxis, StationFrame, StationPoint};
use nalgebra::{Point2, Point3, Rotation3, Vector3};
use proptest::prelude::*;

/// Hinge direction for a wing with sweep Λ, dihedral Γ and twist τ (rad): e_y swept back
/// about z, tilted by the twist about y (as a washed-out swept hinge line), then raised by
/// the dihedral about x.
fn hinge_direction(sweep: f64, dihedral: f64, twist: f64) -> Vector3<f64> {
    Rotation3::from_axis_angle(&Vector3::x_axis(), dihedral)
        * Rotation3::from_axis_angle(&Vector3::y_axis(), twist)
        * Rotation3::from_axis_angle(&Vector3::z_axis(), -sweep)
        * Vector3::y()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn frames_are_orthonormal_right_handed_and_round_trip(
        sweep_deg in 0.0f64..=60.0,
        dihedral_deg in -10.0f64..=15.0,
        twist_deg in -10.0f64..=10.0,
        origin in prop::array::uniform3(-20.0f64..20.0),
        point in prop::array::uniform3(-20.0f64..20.0),
    ) {
        let direction = hinge_direction(sweep_deg.to_radians(), dihedral_deg.to_radians(), twist_deg.to_radians());
        let axis = HingeAxis::try_new(Point3::from(origin), direction).unwrap();
        let frame = StationFrame::try_from_origin_and_normal(axis.point_ac, &axis.direction_ac).unwrap();
        let (x, y, z) = (frame.x_axis_ac().into_inner(), frame.y_axis_ac().into_inner(), frame.z_axis_ac().into_inner());
        for (a, b, expected) in [(x, x, 1.0), (y, y, 1.0), (z, z, 1.0), (x, y, 0.0), (y, z, 0.0), (z, x, 0.0)] {
            prop_assert!((a.dot(&b) - expected).abs() < 1e-12);
        }
        prop_assert!((x.cross(&y) - z).norm() < 1e-12, "right-handed");
        prop_assert!(x.z.abs() < 1e-12, "x perpendicular to gravity");
        prop_assert!(x.x < 0.0, "x towards the nose");
        prop_assert!(y.z > 0.0, "y up");
        prop_assert!((z - axis.direction_ac.into_inner()).norm() < 1e-12, "z along the hinge axis");
        // The quaternion agrees with the constructed axes.
        let rotation = frame.aircraft_from_station().rotation;
        prop_assert!((rotation * Vector3::x() - x).norm() < 1e-12);
        prop_assert!((rotation * Vector3::z() - z).norm() < 1e-12);
        // Round trips aircraft -> station -> aircraft, through both APIs.
        let p_ac = Point3::from(point);
        let p_st: StationPoint = frame.station_point_from_aircraft(&p_ac);
        prop_assert!((frame.aircraft_point_from_station_point(&p_st) - p_ac).norm() < 1e-12 * (1.0 + p_ac.coords.norm()));
        let via_isometry = frame.aircraft_from_station() * (frame.station_from_aircraft() * p_ac);
        prop_assert!((via_isometry - p_ac).norm() < 1e-12 * (1.0 + p_ac.coords.norm()));
        // In-plane points land in the plane.
        let q_ac = frame.aircraft_point_from_station(&Point2::new(point[0], point[1]));
        prop_assert!(frame.signed_distance_m(&q_ac).abs() < 1e-12 * (1.0 + q_ac.coords.norm()));
    }
}

#[test]
fn swept_axis_frame_matches_hand_calculation() {
    // Hinge swept back 30 deg, no dihedral: z = (sin30, cos30, 0), x = (-cos30, sin30, 0), y = e_z.
    let sweep = 30f64.to_radians();
    let axis = HingeAxis::try_new(Point3::new(2.0, 3.0, 0.1), Vector3::new(sweep.sin(), sweep.cos(), 0.0)).unwrap();
    let frame = StationFrame::try_from_origin_and_normal(axis.point_ac, &axis.direction_ac).unwrap();
    assert_relative_eq!(
        frame.x_axis_ac().into_inner(),
        Vector3::new(-sweep.cos(), sweep.sin(), 0.0),
        epsilon = 1e-15
    );
    assert_relative_eq!(frame.y_axis_ac().into_inner(), Vector3::z(), epsilon = 1e-15);
}

#[test]
fn inboard_pointing_normal_is_flipped_outboard() {
    let frame = StationFrame::try_from_origin_and_normal(Point3::origin(), &-Vector3::y_axis()).unwrap();
    assert_relative_eq!(frame.z_axis_ac().into_inner(), Vector3::y(), epsilon = 1e-15);
}
