//! Precision positions: where the flap must be at its settings, as planar displacements
//! from stowed in the station plane, and the two constructions of planar motion
//! generation that the synthesised kinds stand on (Zaccai, Bertels & Vos `003_...`
//! section 3): the pole of a displacement (the one point it leaves in place: a dropped
//! hinge's hinge) and the centre of the circle through three positions of a point (a
//! four-bar's fixed pivot).

use nalgebra::{Isometry2, Point2};
use serde::Serialize;

use crate::shared::geometry::cross;

/// One flap setting in a station plane.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PrecisionPosition {
    /// "stowed", "takeoff" or "landing".
    pub name: &'static str,
    /// Flap deflection (rad), trailing edge down positive.
    pub deflection_rad: f64,
    /// The flap's displacement from stowed (station frame).
    pub flap: Isometry2<f64>,
}

impl PrecisionPosition {
    /// The stowed flap.
    pub fn stowed() -> Self {
        Self {
            name: "stowed",
            deflection_rad: 0.0,
            flap: Isometry2::identity(),
        }
    }
}

/// Smallest rotation (rad) whose pole is defined: below it the pole runs off to
/// infinity (a pure translation has none).
pub const MIN_POLE_ROTATION_RAD: f64 = 1e-6;

/// The pole of `displacement`: the point p with displacement * p = p, from
/// (I - R) p = t; `None` for a rotation below [`MIN_POLE_ROTATION_RAD`].
pub fn pole(displacement: &Isometry2<f64>) -> Option<Point2<f64>> {
    let angle = displacement.rotation.angle();
    if angle.abs() < MIN_POLE_ROTATION_RAD {
        return None;
    }
    let (s, c) = angle.sin_cos();
    let t = displacement.translation.vector;
    // (I - R) = [[1 - c, s], [-s, 1 - c]], determinant 2 (1 - c).
    let det = (1.0 - c) * (1.0 - c) + s * s;
    Some(Point2::new(
        ((1.0 - c) * t.x - s * t.y) / det,
        (s * t.x + (1.0 - c) * t.y) / det,
    ))
}

/// Centre of the circle through `a`, `b` and `c`; `None` when they lie (within rounding)
/// on one line.
pub fn circle_centre(a: Point2<f64>, b: Point2<f64>, c: Point2<f64>) -> Option<Point2<f64>> {
    let (ab, ac) = (b - a, c - a);
    let det = 2.0 * cross(ab, ac);
    if det.is_nan() || det.abs() <= 1e-12 * ab.norm_squared().max(ac.norm_squared()) {
        return None;
    }
    let (b2, c2) = (ab.norm_squared(), ac.norm_squared());
    let centre = a + nalgebra::Vector2::new(ac.y * b2 - ab.y * c2, ab.x * c2 - ac.x * b2) / det;
    centre.coords.iter().all(|v| v.is_finite()).then_some(centre)
}

/// The planar displacement d minimising Σ |d(from_k) - to_k|² (the 2D orthogonal
/// Procrustes solution in closed form: the rotation angle is atan2(Σ p̃ × q̃, Σ p̃ · q̃) of
/// the points about their centroids); `None` for fewer than two pairs, lists of different
/// lengths, coincident `from` points or a non-finite coordinate.
pub fn fit_displacement(from: &[Point2<f64>], to: &[Point2<f64>]) -> Option<Isometry2<f64>> {
    if from.len() < 2 || from.len() != to.len() {
        return None;
    }
    let n = from.len() as f64;
    let centre = |points: &[Point2<f64>]| points.iter().fold(nalgebra::Vector2::zeros(), |s, p| s + p.coords) / n;
    let (from_centre, to_centre) = (centre(from), centre(to));
    let (mut sin, mut cos, mut spread) = (0.0, 0.0, 0.0);
    for (p, q) in from.iter().zip(to) {
        let (a, b) = (p.coords - from_centre, q.coords - to_centre);
        sin += cross(a, b);
        cos += a.dot(&b);
        spread += a.norm_squared();
    }
    if spread.is_nan()
        || spread <= 0.0
        || !sin.is_finite()
        || !cos.is_finite()
        || !to_centre.iter().all(|v| v.is_finite())
    {
        return None;
    }
    let rotation = nalgebra::UnitComplex::new(sin.atan2(cos));
    Some(Isometry2::from_parts(
        nalgebra::Translation2::from(to_centre - rotation * from_centre),
        rotation,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fit_displacement_recovers_an_exact_displacement_and_refuses_a_point() {
        let displacement = Isometry2::new(nalgebra::Vector2::new(0.4, -0.7), -2.5);
        let from = [Point2::new(0.0, 0.0), Point2::new(1.0, 0.1), Point2::new(0.3, -0.6)];
        let to: Vec<_> = from.iter().map(|p| displacement * p).collect();
        let fit = fit_displacement(&from, &to).unwrap();
        assert!((fit.translation.vector - displacement.translation.vector).norm() < 1e-12);
        assert!((fit.rotation.angle() - displacement.rotation.angle()).abs() < 1e-12);
        assert!(fit_displacement(&[from[0], from[0]], &to[..2]).is_none());
        assert!(fit_displacement(&from[..2], &to).is_none());
    }

    #[test]
    fn the_pole_stays_put_and_the_centre_is_equidistant() {
        let displacement = Isometry2::new(nalgebra::Vector2::new(-0.3, -0.12), 0.6);
        let p = pole(&displacement).unwrap();
        assert!((displacement * p - p).norm() < 1e-14);
        assert!(pole(&Isometry2::translation(1.0, 0.0)).is_none());
        let (a, b, c) = (Point2::new(0.1, 0.2), Point2::new(-0.4, 0.0), Point2::new(0.3, -0.5));
        let o = circle_centre(a, b, c).unwrap();
        let r = (a - o).norm();
        assert!(((b - o).norm() - r).abs() < 1e-14 && ((c - o).norm() - r).abs() < 1e-14);
        assert!(circle_centre(a, a + (b - a) * 2.0, b).is_none());
    }
}
