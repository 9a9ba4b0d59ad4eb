//! Demo geometry: flap and wing outlines (station frame, m) and small 2D helpers.

use nalgebra::{Point2, Rotation2, Vector2};

/// A station-frame point, metres.
pub type P = Point2<f64>;

/// Millimetres to a station-frame point in metres.
pub fn mm(x: f64, y: f64) -> P {
    P::new(x / 1000.0, y / 1000.0)
}

/// Rotation about A0 (the origin) by `deg`, counter-clockwise (trailing edge down).
pub fn rotate(p: &P, deg: f64) -> P {
    Rotation2::new(deg.to_radians()) * p
}

/// NACA 2412-like flap outline: chord 560 mm, leading edge at x = 160 mm, trailing edge
/// at x = -400 mm, chord line at y = 330 mm (station frame, x towards the nose).
pub fn flap_outline() -> Vec<P> {
    let (chord, thickness, camber, camber_at) = (560.0, 0.12, 0.02, 0.4);
    let stations: Vec<f64> = (0..=24)
        .map(|i| 0.5 * (1.0 - (std::f64::consts::PI * i as f64 / 24.0).cos()))
        .collect();
    let half_thickness = |t: f64| {
        5.0 * thickness * (0.2969 * t.sqrt() - 0.1260 * t - 0.3516 * t * t + 0.2843 * t.powi(3) - 0.1036 * t.powi(4))
    };
    let camber_line = |t: f64| {
        if t < camber_at {
            camber / (camber_at * camber_at) * (2.0 * camber_at * t - t * t)
        } else {
            camber / ((1.0 - camber_at).powi(2)) * (1.0 - 2.0 * camber_at + 2.0 * camber_at * t - t * t)
        }
    };
    let point = |t: f64, sign: f64| {
        mm(
            160.0 - chord * t,
            330.0 + chord * (camber_line(t) + sign * half_thickness(t)),
        )
    };
    let mut outline: Vec<P> = stations.iter().rev().map(|t| point(*t, 1.0)).collect(); // TE -> LE, upper
    outline.extend(stations.iter().skip(1).map(|t| point(*t, -1.0))); // LE -> TE, lower
    outline.pop(); // trailing edge closes onto the first point
    outline
}

/// Rear part of the wing with the cove around the flap leading edge (illustrative).
pub fn wing_skin() -> Vec<P> {
    [
        (750.0, 446.0),
        (600.0, 440.0),
        (300.0, 421.0),
        (150.0, 402.0),
        (60.0, 384.0),
        (52.0, 378.0),
        (150.0, 386.0),
        (205.0, 378.0),
        (232.0, 350.0),
        (238.0, 318.0),
        (255.0, 292.0),
        (400.0, 284.0),
        (750.0, 281.0),
    ]
    .iter()
    .map(|(x, y)| mm(*x, *y))
    .collect()
}

/// A circle as a polygon (station frame, m).
pub fn circle(centre: P, radius_m: f64) -> Vec<P> {
    (0..32)
        .map(|i| {
            centre
                + radius_m
                    * Vector2::new(
                        (i as f64 / 32.0 * std::f64::consts::TAU).cos(),
                        (i as f64 / 32.0 * std::f64::consts::TAU).sin(),
                    )
        })
        .collect()
}

/// Distance from `p` to segment `a`-`b`, metres.
pub fn segment_distance(p: &P, a: &P, b: &P) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
    (p - (a + t * ab)).norm()
}

/// Smallest vertex-to-edge distance between two closed polygons, metres.
pub fn clearance(first: &[P], second: &[P]) -> f64 {
    let one_way = |from: &[P], to: &[P]| {
        from.iter()
            .flat_map(|p| (0..to.len()).map(move |i| segment_distance(p, &to[i], &to[(i + 1) % to.len()])))
            .fold(f64::INFINITY, f64::min)
    };
    one_way(first, second).min(one_way(second, first))
}
