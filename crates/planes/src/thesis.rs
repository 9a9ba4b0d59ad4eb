//! Mechanism planes perpendicular to the flap rotation axis (thesis `000`, Chapter 4,
//! steps 1-3, Appendix B).

use nalgebra::Point3;

use crate::error::{finite, Result};
use crate::frame::StationFrame;
use crate::plane::{HingeAxis, Plane};

/// Result of the thesis construction, all in the aircraft frame (m).
#[derive(Debug, Clone, PartialEq)]
pub struct ThesisStations {
    /// Step 1: P, where the inner flap side plane meets the rotation axis.
    pub p_ac: Point3<f64>,
    /// Step 2: A0 = P + d1 along the axis (outboard): origin of the outer mechanism plane.
    pub a0_ac: Point3<f64>,
    /// One frame per requested offset (step 3), in the order given; all planes are
    /// perpendicular to the axis.
    pub frames: Vec<StationFrame>,
}

/// Thesis steps 1-3: P = inner flap side plane ∩ axis; A0 = P + `d1_m` along the axis
/// towards the outer side; one station plane perpendicular to the axis at A0 +
/// `offset` along the axis for every entry of `offsets_from_a0_m` (m, outboard positive).
///
/// The thesis' outer plane is offset 0; its inner plane A1 is "A0 translated by d2"
/// towards the inboard side, i.e. offset `-d2`. The thesis states d2 < flap span and
/// leaves the numbers to the designer (Appendix B shows orientations only).
pub fn thesis_stations(
    axis: &HingeAxis,
    inner_side_plane: &Plane,
    d1_m: f64,
    offsets_from_a0_m: &[f64],
) -> Result<ThesisStations> {
    finite("d1_m", d1_m)?;
    let p_ac = inner_side_plane.intersect_axis(axis, "inner flap side")?;
    let a0_ac = p_ac + axis.direction_ac.into_inner() * d1_m;
    let frames = offsets_from_a0_m
        .iter()
        .map(|&offset| {
            finite("station offset from A0 (m)", offset)?;
            StationFrame::try_from_origin_and_normal(
                a0_ac + axis.direction_ac.into_inner() * offset,
                &axis.direction_ac,
            )
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(ThesisStations { p_ac, a0_ac, frames })
}
