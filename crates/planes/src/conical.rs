//! Flap settings from gap and overlap at two spanwise sections: the conical rotations
//! θ_o, θ_g and the base-point translation (Zaccai et al. `003`, section 2, Figs. 2b, 3).

use nalgebra::{Point3, Vector3};

use crate::error::{finite, Result};
use crate::motion::{FlapDeployment, FlapSetting};
use crate::plane::unit_direction;

/// How the forward attachment (hinge) point of one spanwise section moves from stowed to
/// a setting: `aft_m` along the gap axis (streamwise, = reduction of overlap O_f) and
/// `down_m` against the overlap axis (wing normal, ≈ increase of gap G_f).
///
/// `003` Fig. 3 step 4 measures overlap from the section's forward-most point and gap
/// normal to the main-wing trailing edge on the deflected flap contour; turning those into
/// hinge-point shifts needs the flap and cove contours (geom) and is left to the caller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SectionShift {
    /// Stowed hinge point of the section (on the hinge line), aircraft frame, m.
    pub hinge_point_ac: Point3<f64>,
    /// Shift along the gap axis (streamwise aft), m.
    pub aft_m: f64,
    /// Shift against the overlap axis (down, normal to the wing), m.
    pub down_m: f64,
}

/// The flap setting that deflects by `deflection_rad` and moves the hinge points of two
/// sections by their shifts (conical deployment when the shifts differ).
///
/// The deployed hinge direction a' runs through the shifted points. θ_g, θ_o solve
/// R_g(θ_g) R_o(θ_o) a = a' with the gap axis g ⟂ overlap axis o: a' · R_g(θ_g) o = a · o
/// gives A cos θ_g + B sin θ_g = C (A = a'·o, B = a'·(g×o), C = a·o; the root of smaller
/// |θ_g| is taken), then θ_o is the angle from a to R_g(-θ_g) a' about o. The base point is
/// translated by the shifts interpolated at its arc length, so it stays on the new hinge
/// line; the section points land on that line to within the change of their distance.
pub fn setting_from_section_shifts(
    deployment: &FlapDeployment,
    deflection_rad: f64,
    inboard: &SectionShift,
    outboard: &SectionShift,
) -> Result<FlapSetting> {
    finite("deflection_rad", deflection_rad)?;
    let (gap_axis, overlap_axis) = (
        deployment.gap_axis_ac.into_inner(),
        deployment.overlap_axis_ac.into_inner(),
    );
    let shift = |s: &SectionShift| -> Result<Vector3<f64>> {
        Ok(gap_axis * finite("aft_m", s.aft_m)? - overlap_axis * finite("down_m", s.down_m)?)
    };
    let (shift_in, shift_out) = (shift(inboard)?, shift(outboard)?);
    let span = outboard.hinge_point_ac - inboard.hinge_point_ac;
    let a = deployment.hinge.direction_ac.into_inner();
    let mut a_new = unit_direction("deployed hinge line", span + shift_out - shift_in)?.into_inner();
    if a_new.dot(&a) < 0.0 {
        a_new = -a_new;
    }
    let (o, g) = (overlap_axis, gap_axis);
    let (big_a, big_b, c) = (a_new.dot(&o), a_new.dot(&g.cross(&o)), a.dot(&o));
    let amplitude = big_a.hypot(big_b);
    let phase = big_b.atan2(big_a);
    let spread = (c / amplitude).clamp(-1.0, 1.0).acos();
    let gap_rotation_rad = [phase - spread, phase + spread]
        .into_iter()
        .map(|t| (t + std::f64::consts::PI).rem_euclid(2.0 * std::f64::consts::PI) - std::f64::consts::PI)
        .min_by(|x, y| x.abs().total_cmp(&y.abs()))
        .unwrap_or(0.0);
    let back = nalgebra::Rotation3::from_axis_angle(&deployment.gap_axis_ac, -gap_rotation_rad) * a_new;
    let (a_plane, back_plane) = (a - o * a.dot(&o), back - o * back.dot(&o));
    let overlap_rotation_rad = o.dot(&a_plane.cross(&back_plane)).atan2(a_plane.dot(&back_plane));
    let fraction = (deployment.base_point_ac - inboard.hinge_point_ac).dot(&span) / span.norm_squared();
    Ok(FlapSetting {
        deflection_rad,
        overlap_rotation_rad,
        gap_rotation_rad,
        base_translation_ac: shift_in + (shift_out - shift_in) * fraction,
    })
}
