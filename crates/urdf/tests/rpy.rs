//! URDF rpy <-> rotation matrix, gimbal lock included.

use super::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn rpy_round_trips_through_the_matrix(
        roll in -PI..PI,
        pitch_offset in prop_oneof![Just(0.0), -1e-7..1e-7_f64, -1.5..1.5_f64],
        near_lock in any::<bool>(),
        yaw in -PI..PI,
    ) {
        let pitch = if near_lock {
            FRAC_PI_2.copysign(roll) - pitch_offset.abs().copysign(roll)
        } else {
            pitch_offset
        };
        let written = rpy_matrix([roll, pitch, yaw]);
        prop_assert!((rotation_from_rpy([roll, pitch, yaw]).matrix() - written).abs().max() < 1e-15);
        let read = rpy_from_rotation(&Rotation3::from_matrix_unchecked(written));
        prop_assert!((rpy_matrix(read) - written).abs().max() < 1e-14);
        prop_assert!(read[1].abs() <= FRAC_PI_2);
    }

    #[test]
    fn any_rotation_round_trips(axis in prop::array::uniform3(-1.0..1.0_f64), angle in -PI..PI) {
        prop_assume!(Vector3::from(axis).norm() > 1e-3);
        let rotation = Rotation3::from_axis_angle(&Unit::new_normalize(Vector3::from(axis)), angle);
        let read = rpy_from_rotation(&rotation);
        prop_assert!((rpy_matrix(read) - rotation.matrix()).abs().max() < 1e-14);
    }
}
