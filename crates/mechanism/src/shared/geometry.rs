//! Planar geometry helpers every kind uses: the 2D cross product, the signed turn between
//! two points about a centre, and the isometry turning the plane about a point (station
//! frame, rad counter-clockwise positive). They lived in `rocker_drive.rs` until issue 36,
//! though the five-bar, the tracks, the flap's loads and the jets use them without a rocker.

use nalgebra::{Isometry2, Point2, Translation2, Vector2};

/// 2D cross product.
pub fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Signed angle (rad) that turns `from - centre` onto `to - centre`.
pub fn turn_angle(centre: Point2<f64>, from: Point2<f64>, to: Point2<f64>) -> f64 {
    let (a, b) = (from - centre, to - centre);
    cross(a, b).atan2(a.dot(&b))
}

/// The isometry turning the plane by `angle` about `centre`.
pub fn turn_about(centre: Point2<f64>, angle: f64) -> Isometry2<f64> {
    Translation2::from(centre.coords) * Isometry2::rotation(angle) * Translation2::from(-centre.coords)
}
