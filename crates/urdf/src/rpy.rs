//! URDF orientation: fixed-axis roll-pitch-yaw, R = Rz(yaw) Ry(pitch) Rx(roll).

use nalgebra::{Isometry3, Rotation3, Translation3, UnitQuaternion, Vector3};

/// The rotation of URDF's `rpy="roll pitch yaw"` (rad): R = Rz(yaw) Ry(pitch) Rx(roll),
/// i.e. roll about the fixed x axis first, then pitch about fixed y, then yaw about fixed z
/// (URDF XML specification, `<origin>`; the same order as nalgebra's `from_euler_angles`).
pub fn rotation_from_rpy(rpy: [f64; 3]) -> Rotation3<f64> {
    Rotation3::from_euler_angles(rpy[0], rpy[1], rpy[2])
}

/// Roll, pitch, yaw (rad) of a rotation, with R = Rz(yaw) Ry(pitch) Rx(roll); pitch in
/// [-π/2, π/2], roll and yaw in [-π, π].
///
/// Accurate everywhere, gimbal lock included: roll comes from atan2(r21, r22) (0 when
/// both vanish); pitch and yaw are then read from M = R Rx(roll)ᵀ = Rz(yaw) Ry(pitch),
/// whose entries m20 = -sin p, m22 = cos p, m01 = -sin y, m11 = cos y stay well
/// conditioned. Near pitch = ±π/2 roll is poorly determined, but the error it carries
/// into M is cos(pitch) × (roll error) = rounding, so `rotation_from_rpy` of the result
/// reproduces R to a few ulps (tested in `tests/urdf.rs`).
pub fn rpy_from_rotation(rotation: &Rotation3<f64>) -> [f64; 3] {
    let r = rotation.matrix();
    let (r21, r22) = (r[(2, 1)], r[(2, 2)]);
    let roll = if r21 == 0.0 && r22 == 0.0 { 0.0 } else { r21.atan2(r22) };
    let m = r * Rotation3::from_axis_angle(&Vector3::x_axis(), roll)
        .matrix()
        .transpose();
    let pitch = (-m[(2, 0)]).atan2(m[(2, 2)]);
    let yaw = (-m[(0, 1)]).atan2(m[(1, 1)]);
    [roll, pitch, yaw]
}

/// The transform of a URDF `<origin xyz rpy>`: parent_from_child = (xyz, R(rpy)).
pub fn isometry_from_origin(xyz: [f64; 3], rpy: [f64; 3]) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(xyz[0], xyz[1], xyz[2]),
        UnitQuaternion::from_rotation_matrix(&rotation_from_rpy(rpy)),
    )
}

/// (xyz (m), rpy (rad)) of a URDF `<origin>` for the transform parent_from_child.
pub fn origin_from_isometry(parent_from_child: &Isometry3<f64>) -> ([f64; 3], [f64; 3]) {
    // `+ 0.0` turns -0 into 0, so files do not print "-0".
    let t = parent_from_child.translation.vector;
    let rpy = rpy_from_rotation(&parent_from_child.rotation.to_rotation_matrix());
    ([t.x + 0.0, t.y + 0.0, t.z + 0.0], rpy.map(|angle| angle + 0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gimbal_lock_round_trips() {
        for pitch in [
            std::f64::consts::FRAC_PI_2,
            -std::f64::consts::FRAC_PI_2,
            std::f64::consts::FRAC_PI_2 - 1e-9,
        ] {
            let rotation = rotation_from_rpy([0.3, pitch, -1.2]);
            let back = rotation_from_rpy(rpy_from_rotation(&rotation));
            let error = (back.matrix() - rotation.matrix()).abs().max();
            assert!(error < 1e-14, "pitch {pitch}: error {error}");
        }
    }

    #[test]
    fn identity_is_zero() {
        assert_eq!(rpy_from_rotation(&Rotation3::identity()), [0.0, 0.0, 0.0]);
    }
}
