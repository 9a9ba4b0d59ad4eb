//! Skew-corrected mechanism planes (Zaccai et al. `003`, section 2, Fig. 4) and the skew
//! angle of any plane against the streamwise plane.

use nalgebra::{Point3, Unit, Vector3};

use crate::error::Result;
use crate::plane::unit_direction;

/// The wing "dihedral vector" of `003` Fig. 4b: the wing's up direction tilted by the
/// dihedral Γ (rad), (0, -sin Γ, cos Γ) in the aircraft frame (right wing).
///
/// `003` crosses the skew direction with "the main wing dihedral vector" and says this
/// makes the plane "perpendicular to the wing surface" instead of vertical: so the vector
/// replaces the vertical, i.e. it is the wing normal, not the spanwise dihedral line
/// (crossing with the spanwise line would give a plane parallel to the wing).
pub fn dihedral_up_vector_ac(dihedral_rad: f64) -> Unit<Vector3<f64>> {
    Unit::new_normalize(Vector3::new(0.0, -dihedral_rad.sin(), dihedral_rad.cos()))
}

/// Skew direction of a forward attachment point: unit vector from its stowed to its
/// deployed position (`003` Fig. 4a), aircraft frame. Errors when it does not move.
pub fn skew_direction_ac(stowed_ac: &Point3<f64>, deployed_ac: &Point3<f64>) -> Result<Unit<Vector3<f64>>> {
    unit_direction("skew direction (attachment displacement, m)", deployed_ac - stowed_ac)
}

/// Mechanism plane normal = skew direction x dihedral vector (`003` Fig. 4b), oriented
/// outboard (aircraft +y), unit, aircraft frame.
pub fn skewed_plane_normal_ac(
    skew_direction: &Unit<Vector3<f64>>,
    dihedral_up: &Unit<Vector3<f64>>,
) -> Result<Unit<Vector3<f64>>> {
    let normal = unit_direction("skew direction x dihedral vector", skew_direction.cross(dihedral_up))?;
    Ok(if normal.y < 0.0 { -normal } else { normal })
}

/// Skew angle (rad) of a plane with normal `normal_ac` against the streamwise plane
/// (aircraft x-z), measured in planform about the vertical: atan2(n_x, n_y) with n
/// oriented outboard. Positive when the plane's trace turns like a swept-back hinge
/// (a plane perpendicular to a hinge line swept back by Λ has skew angle Λ).
/// Dihedral tilt does not count as skew; see [`angle_to_streamwise_plane_rad`].
pub fn skew_angle_rad(normal_ac: &Unit<Vector3<f64>>) -> f64 {
    let n = if normal_ac.y < 0.0 {
        -normal_ac.into_inner()
    } else {
        normal_ac.into_inner()
    };
    n.x.atan2(n.y)
}

/// Full angle (rad, in [0, π/2]) between a plane with normal `normal_ac` and the
/// streamwise plane (aircraft x-z): acos |n_y|, computed as atan2 for accuracy near 0.
pub fn angle_to_streamwise_plane_rad(normal_ac: &Unit<Vector3<f64>>) -> f64 {
    (normal_ac.x.hypot(normal_ac.z)).atan2(normal_ac.y.abs())
}
