//! Input checks for a [`StationDrawing`]: finite values, enough points, sane radii.
//!
//! Run before any drawing so that a NaN is refused with its location instead of being
//! written into the SVG.

use crate::error::{Error, Result};
use crate::model::StationDrawing;
use nalgebra::Point2;

/// Fewest points of a closed polygon.
const POLYGON_MIN_POINTS: usize = 3;
/// Fewest points of a polyline.
const POLYLINE_MIN_POINTS: usize = 2;

/// Checks every coordinate and count of `drawing`; returns the first problem found.
pub(crate) fn validate_station(drawing: &StationDrawing) -> Result<()> {
    let is_empty = drawing.sections.is_empty()
        && drawing.settings.is_empty()
        && drawing.slots.is_empty()
        && drawing.envelope.is_empty()
        && drawing.fairing_line.is_none()
        && drawing.dimensions.is_empty()
        && drawing.fairing_parts.is_empty()
        && drawing.clashes.is_empty();
    if is_empty {
        return Err(Error::EmptyDrawing);
    }
    for link in &drawing.fairing_parts {
        check_points(
            &format!("fairing part `{}`", link.name),
            &link.points,
            POLYLINE_MIN_POINTS,
        )?;
    }
    for clash in &drawing.clashes {
        check_points(&format!("clash `{}`", clash.label), std::slice::from_ref(&clash.at), 1)?;
    }
    for section in &drawing.sections {
        for (i, polygon) in section.polygons.iter().enumerate() {
            let what = format!("section `{}` polygon {i}", section.part);
            check_points(&what, polygon, POLYGON_MIN_POINTS)?;
        }
    }
    for (s, setting) in drawing.settings.iter().enumerate() {
        if !setting.deflection_deg.is_finite() {
            return Err(Error::NonFinitePoint {
                what: format!("deflection of setting `{}`", setting.label),
                index: s,
            });
        }
        for (i, polygon) in setting.flap_outline.iter().enumerate() {
            let what = format!("flap outline {i} of setting `{}`", setting.label);
            check_points(&what, polygon, POLYGON_MIN_POINTS)?;
        }
        for link in &setting.links {
            let what = format!("link `{}` of setting `{}`", link.name, setting.label);
            check_points(&what, &link.points, POLYLINE_MIN_POINTS)?;
        }
        for (i, joint) in setting.joints.iter().enumerate() {
            let what = format!("joint `{}` of setting `{}`", joint.name, setting.label);
            check_points(&what, std::slice::from_ref(&joint.at), 1).map_err(|e| match e {
                Error::NonFinitePoint { what, .. } => Error::NonFinitePoint { what, index: i },
                other => other,
            })?;
        }
    }
    for slot in &drawing.slots {
        let what = format!("slot `{}`", slot.name);
        let scalars = [
            slot.centre.x,
            slot.centre.y,
            slot.radius_m,
            slot.start_rad,
            slot.end_rad,
        ];
        if let Some(index) = scalars.iter().position(|v| !v.is_finite()) {
            return Err(Error::NonFinitePoint { what, index });
        }
        if slot.radius_m <= 0.0 {
            return Err(Error::NonPositiveRadius {
                slot: slot.name.clone(),
                radius_m: slot.radius_m,
            });
        }
    }
    for (i, outline) in drawing.envelope.iter().enumerate() {
        check_points(&format!("envelope outline {i}"), outline, POLYGON_MIN_POINTS)?;
    }
    if let Some(line) = &drawing.fairing_line {
        check_points("fairing line", line, POLYLINE_MIN_POINTS)?;
    }
    for dimension in &drawing.dimensions {
        let what = format!("dimension `{}`", dimension.label);
        check_points(&what, &[dimension.from, dimension.to], POLYLINE_MIN_POINTS)?;
        if dimension.length_m() <= f64::EPSILON {
            return Err(Error::ZeroLengthDimension {
                label: dimension.label.clone(),
            });
        }
    }
    Ok(())
}

/// Checks that `points` has at least `minimum` entries, all finite.
fn check_points(what: &str, points: &[Point2<f64>], minimum: usize) -> Result<()> {
    if points.len() < minimum {
        return Err(Error::TooFewPoints {
            what: what.to_owned(),
            count: points.len(),
            minimum,
        });
    }
    match points.iter().position(|p| !(p.x.is_finite() && p.y.is_finite())) {
        Some(index) => Err(Error::NonFinitePoint {
            what: what.to_owned(),
            index,
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Link, MechanismSnapshot};

    #[test]
    fn empty_drawing_is_refused() {
        assert_eq!(validate_station(&StationDrawing::default()), Err(Error::EmptyDrawing));
    }

    #[test]
    fn nan_in_a_link_names_the_link_and_index() {
        let drawing = StationDrawing {
            settings: vec![MechanismSnapshot {
                label: "landing".into(),
                deflection_deg: 35.0,
                flap_outline: vec![],
                links: vec![Link {
                    name: "screw".into(),
                    points: vec![Point2::new(0.0, 0.0), Point2::new(f64::NAN, 1.0)],
                }],
                joints: vec![],
            }],
            ..Default::default()
        };
        assert_eq!(
            validate_station(&drawing),
            Err(Error::NonFinitePoint {
                what: "link `screw` of setting `landing`".into(),
                index: 1
            })
        );
    }
}
