//! Fairing depth (thesis `000`, Ch. 5: the figure of merit): how far below the local lower
//! surface of wing and stowed flap the mechanism reaches over the deployment, measured in
//! the station plane; and fairing length (`003_...` Table 1): the chordwise extent of what
//! the fairing must cover, every mechanism point below the lower surface (beyond the
//! sections' ends, below the surface's nearest end) over the deployment.

use nalgebra::Point2;
use serde::Serialize;

/// A round solid of the mechanism in the station plane: a segment swept by a radius
/// (a point when both ends coincide).
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarCapsule {
    /// Part name.
    pub part: String,
    /// One end, station frame (m).
    pub from: Point2<f64>,
    /// Other end (m).
    pub to: Point2<f64>,
    /// Radius (m).
    pub radius_m: f64,
}

/// Fairing depth of one station.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FairingDepth {
    /// Largest depth below the lower surface (m); 0 when nothing protrudes.
    pub depth_m: f64,
    /// The same in % of the local flap chord.
    pub depth_percent_flap_chord: f64,
    /// Part that reaches deepest; `None` when nothing protrudes (then the parameter and
    /// point below are 0).
    pub part: Option<String>,
    /// Flap rotation where it does (rad).
    pub at_parameter: f64,
    /// The deepest point, station frame (m).
    pub point_st: [f64; 2],
    /// Chordwise extent of the mechanism below the lower surface over the deployment (m);
    /// 0 when nothing protrudes.
    pub length_m: f64,
    /// The same in % of the local flap chord.
    pub length_percent_flap_chord: f64,
}

/// Lowest y of the contour at `x` (edges of all `polygons` that span x), if any.
fn lower_surface_y(polygons: &[Vec<Point2<f64>>], x: f64) -> Option<f64> {
    let mut lowest: Option<f64> = None;
    for polygon in polygons {
        for (i, a) in polygon.iter().enumerate() {
            let b = polygon[(i + 1) % polygon.len()];
            if (a.x - x) * (b.x - x) <= 0.0 && a.x != b.x {
                let y = a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
                lowest = Some(lowest.map_or(y, |l: f64| l.min(y)));
            }
        }
    }
    lowest
}

/// The lower surface's y at `x`, or at the nearer end of the contour beyond its ends.
fn lower_surface_or_end_y(polygons: &[Vec<Point2<f64>>], x: f64) -> Option<f64> {
    lower_surface_y(polygons, x).or_else(|| {
        let xs = polygons.iter().flatten().map(|p| p.x);
        let (lo, hi) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
        if lo > hi {
            return None;
        }
        // Just inside the end, where a vertical meets an edge.
        let end = if x < lo {
            lo + 1e-9 * (hi - lo)
        } else {
            hi - 1e-9 * (hi - lo)
        };
        lower_surface_y(polygons, end)
    })
}

/// Fairing depth and length over `parameters` (deployment parameters, e.g. drive fractions) of the
/// capsules `at(t)` gives,
/// against the lower contour of `contour` (wing and stowed flap sections, station frame).
/// Each capsule is sampled at `points_per_capsule` points (>= 2). Errors: the first that
/// `at` returns.
pub fn fairing_depth<E>(
    contour: &[Vec<Point2<f64>>],
    flap_chord_m: f64,
    parameters: &[f64],
    points_per_capsule: usize,
    at: impl Fn(f64) -> Result<Vec<PlanarCapsule>, E>,
) -> Result<FairingDepth, E> {
    let mut deepest = FairingDepth {
        depth_m: 0.0,
        depth_percent_flap_chord: 0.0,
        part: None,
        at_parameter: 0.0,
        point_st: [0.0, 0.0],
        length_m: 0.0,
        length_percent_flap_chord: 0.0,
    };
    let mut extent = (f64::INFINITY, f64::NEG_INFINITY);
    let n = points_per_capsule.max(2);
    for &t in parameters {
        for capsule in at(t)? {
            for k in 0..n {
                let p = capsule.from + (capsule.to - capsule.from) * (k as f64 / (n - 1) as f64);
                if lower_surface_or_end_y(contour, p.x).is_some_and(|y| p.y - capsule.radius_m < y) {
                    extent = (
                        extent.0.min(p.x - capsule.radius_m),
                        extent.1.max(p.x + capsule.radius_m),
                    );
                }
                let Some(surface) = lower_surface_y(contour, p.x) else {
                    continue;
                };
                let depth = surface - (p.y - capsule.radius_m);
                if depth > deepest.depth_m {
                    deepest = FairingDepth {
                        depth_m: depth,
                        depth_percent_flap_chord: 0.0,
                        part: Some(capsule.part.clone()),
                        at_parameter: t,
                        point_st: [p.x, p.y - capsule.radius_m],
                        ..deepest
                    };
                }
            }
        }
    }
    if extent.1 > extent.0 {
        deepest.length_m = extent.1 - extent.0;
    }
    if flap_chord_m > 0.0 {
        deepest.depth_percent_flap_chord = 100.0 * deepest.depth_m / flap_chord_m;
        deepest.length_percent_flap_chord = 100.0 * deepest.length_m / flap_chord_m;
    }
    Ok(deepest)
}

#[cfg(test)]
mod tests {
    use std::convert::Infallible;

    use super::*;

    #[test]
    fn depth_below_a_flat_plate() {
        // A 1 m plate from y = 0 to 0.1; a point capsule of radius 0.01 at y = -0.2.
        let plate = vec![vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 0.0),
            Point2::new(1.0, 0.1),
            Point2::new(0.0, 0.1),
        ]];
        let depth = fairing_depth(&plate, 0.5, &[0.0, 1.0], 2, |t| {
            Ok::<_, Infallible>(vec![PlanarCapsule {
                part: "pin".into(),
                from: Point2::new(0.5, -0.2 * t),
                to: Point2::new(0.5, -0.2 * t),
                radius_m: 0.01,
            }])
        })
        .unwrap();
        assert!((depth.depth_m - 0.21).abs() < 1e-12);
        assert!((depth.depth_percent_flap_chord - 42.0).abs() < 1e-9);
        assert_eq!(depth.at_parameter, 1.0);
        // Outside the contour's x range nothing is measured.
        let outside = fairing_depth(&plate, 0.5, &[1.0], 2, |_| {
            Ok::<_, Infallible>(vec![PlanarCapsule {
                part: "pin".into(),
                from: Point2::new(2.0, -1.0),
                to: Point2::new(2.0, -1.0),
                radius_m: 0.0,
            }])
        })
        .unwrap();
        assert_eq!(outside.depth_m, 0.0);
    }

    #[test]
    fn length_spans_what_hangs_below_including_beyond_the_trailing_edge() {
        // The plate from x = 0 to 1 at y in [0, 0.1]; a rod of radius 0.01 below it from
        // x = 0.2 to x = 1.5 (past the plate's end, below its end's lower surface), and a
        // ball above the plate that does not count: length 1.3 + 2 x 0.01.
        let plate = vec![vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 0.0),
            Point2::new(1.0, 0.1),
            Point2::new(0.0, 0.1),
        ]];
        let fairing = fairing_depth(&plate, 0.5, &[0.0], 8, |_| {
            Ok::<_, Infallible>(vec![
                PlanarCapsule {
                    part: "rod".into(),
                    from: Point2::new(0.2, -0.05),
                    to: Point2::new(1.5, -0.05),
                    radius_m: 0.01,
                },
                PlanarCapsule {
                    part: "ball".into(),
                    from: Point2::new(-0.5, 0.5),
                    to: Point2::new(-0.5, 0.5),
                    radius_m: 0.01,
                },
            ])
        })
        .unwrap();
        assert!((fairing.length_m - 1.32).abs() < 1e-12, "{}", fairing.length_m);
        assert!((fairing.length_percent_flap_chord - 264.0).abs() < 1e-9);
        // Nothing below: no length.
        let none = fairing_depth(&plate, 0.5, &[0.0], 2, |_| {
            Ok::<_, Infallible>(vec![PlanarCapsule {
                part: "ball".into(),
                from: Point2::new(0.5, 0.5),
                to: Point2::new(0.5, 0.5),
                radius_m: 0.01,
            }])
        })
        .unwrap();
        assert_eq!((none.length_m, none.depth_m), (0.0, 0.0));
    }

    #[test]
    fn a_maximum_between_samples_is_missed_by_at_most_rho_dt2_over_8() {
        // A rod of length 0.45 m and radius 0.01 m pivots at the origin under a plate at
        // y = 0, from -60 to -120 deg; deepest at -90 deg: 0.46 m. With the samples
        // straddling -90 deg, the sampled depth falls short by 0.45 (1 - cos(dt / 2)),
        // within `docs/report.md`'s rho dt^2 / 8.
        let plate = vec![vec![
            Point2::new(-1.0, 0.0),
            Point2::new(1.0, 0.0),
            Point2::new(1.0, 0.1),
            Point2::new(-1.0, 0.1),
        ]];
        let (length, radius) = (0.45, 0.01);
        let rod = |t: f64| {
            let angle = (-60f64).to_radians() - t;
            Ok::<_, Infallible>(vec![PlanarCapsule {
                part: "rod".into(),
                from: Point2::origin(),
                to: Point2::new(length * angle.cos(), length * angle.sin()),
                radius_m: radius,
            }])
        };
        let range = 60f64.to_radians();
        for samples in [3, 4, 21, 22] {
            let parameters: Vec<f64> = (0..samples).map(|i| range * i as f64 / (samples - 1) as f64).collect();
            let depth = fairing_depth(&plate, 1.0, &parameters, 2, rod).unwrap().depth_m;
            let step = range / (samples - 1) as f64;
            // The sample nearest -90 deg is at most half a step away.
            let nearest = parameters
                .iter()
                .map(|t| (t - 0.5 * range).abs())
                .fold(f64::INFINITY, f64::min);
            let expected = length * nearest.cos() + radius;
            assert!((depth - expected).abs() < 1e-12, "{samples}: {depth} vs {expected}");
            let shortfall = length + radius - depth;
            assert!(
                shortfall <= length * step * step / 8.0 + 1e-12,
                "{samples}: {shortfall}"
            );
        }
    }
}
