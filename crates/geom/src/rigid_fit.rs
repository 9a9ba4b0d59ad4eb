//! The rigid motion that best maps one point set onto another, and how fast it can move.
//!
//! A rigid flap held by several planar mechanisms, each in its own plane, cannot follow
//! every one of them exactly when they disagree (a tapered flap moves conically, a planar
//! mechanism only in its plane): the flap's pose is the least-squares rigid motion of the
//! points the mechanisms move ([`fit_rigid_motion`]), and [`FitSpeedGain`] bounds how fast
//! any point of the fitted body moves from how fast the fitted points move.
//!
//! The fit is the SVD solution of the orthogonal Procrustes problem (Kabsch 1976; Arun,
//! Huang & Blostein 1987, with the reflection guard of Umeyama 1991) on nalgebra's SVD: no
//! crate in the dependency set fits rigid motions, and the method is a dozen lines.

use nalgebra::{Isometry3, Matrix3, Matrix6, Point3, Rotation3, Translation3, UnitQuaternion, Vector3};

use crate::error::{Error, Result};

/// The least-squares rigid motion of [`fit_rigid_motion`] and how well it fits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidFit {
    /// Maps each `from` point to near its `to` point.
    pub motion: Isometry3<f64>,
    /// Root-mean-square distance between the moved `from` points and the `to` points, m.
    pub rms_m: f64,
    /// Largest such distance, m.
    pub max_m: f64,
}

/// The rigid motion `m` minimising Σ |m(from_k) - to_k|² (lengths in any one unit, m here).
///
/// Exact (to rounding) when such a motion maps every point; the points may be coplanar but
/// not collinear (the rotation about their line would be free).
///
/// # Errors
/// [`Error::TooFewPoints`] for fewer than three pairs or lists of different lengths,
/// [`Error::NotFinite`] for a non-finite coordinate, [`Error::Degenerate`] when the `from`
/// points are (nearly) collinear.
pub fn fit_rigid_motion(from: &[Point3<f64>], to: &[Point3<f64>]) -> Result<RigidFit> {
    if from.len() < 3 || from.len() != to.len() {
        return Err(Error::TooFewPoints {
            what: "rigid fit point pairs (two equal lists)",
            count: from.len().min(to.len()),
            minimum: 3,
        });
    }
    if let Some(value) = from.iter().chain(to).flat_map(|p| p.iter()).find(|v| !v.is_finite()) {
        return Err(Error::NotFinite {
            what: "rigid fit point coordinate",
            value: *value,
        });
    }
    let centroid =
        |points: &[Point3<f64>]| points.iter().fold(Vector3::zeros(), |sum, p| sum + p.coords) / points.len() as f64;
    let (from_centre, to_centre) = (centroid(from), centroid(to));
    let spread = spread_about(from, &from_centre);
    let covariance = from.iter().zip(to).fold(Matrix3::zeros(), |sum, (p, q)| {
        sum + (q.coords - to_centre) * (p.coords - from_centre).transpose()
    });
    // The from points span at least a plane: the second principal spread is not negligible.
    let principal = spread.symmetric_eigenvalues();
    let mut sorted = [principal[0], principal[1], principal[2]];
    sorted.sort_by(f64::total_cmp);
    if sorted[1] <= 1e-18 * sorted[2].max(f64::MIN_POSITIVE) || sorted[2] <= 0.0 {
        return Err(Error::Degenerate {
            what: "rigid fit: the points to move are collinear",
        });
    }
    let svd = covariance.svd(true, true);
    let (Some(u), Some(v_t)) = (svd.u, svd.v_t) else {
        return Err(Error::Degenerate {
            what: "rigid fit: the SVD did not converge",
        });
    };
    // Umeyama's guard: a reflection is never the answer; flip the weakest direction.
    let sign = (u * v_t).determinant().signum();
    let rotation = u * Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, sign)) * v_t;
    let rotation = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(rotation));
    let translation = to_centre - rotation * from_centre;
    let motion = Isometry3::from_parts(Translation3::from(translation), rotation);
    let (mut sum, mut max) = (0.0, 0.0_f64);
    for (p, q) in from.iter().zip(to) {
        let miss = (motion * p - q).norm();
        sum += miss * miss;
        max = max.max(miss);
    }
    Ok(RigidFit {
        motion,
        rms_m: (sum / from.len() as f64).sqrt(),
        max_m: max,
    })
}

fn spread_about(points: &[Point3<f64>], centre: &Vector3<f64>) -> Matrix3<f64> {
    points.iter().fold(Matrix3::zeros(), |sum, p| {
        let d = p.coords - centre;
        sum + d * d.transpose()
    })
}

/// How much faster a point of a fitted rigid body can move than the fitted points do.
///
/// Linearised, the fit's velocity (v, ω) is the least-squares projection of the fitted
/// points' velocities onto rigid velocity fields u(x) = v + ω × x, so the root mean square
/// of u over the fitted points is at most that of their velocities (a projection does not
/// lengthen). `gain` is the largest ratio of |u(y)| at a query point y to that root mean
/// square over every rigid field: |u(y)| ≤ gain · rms_k |ẋ_k| ≤ gain · max_k |ẋ_k|.
///
/// The exact Procrustes derivative differs from the projection by the fit's residual over
/// the points' spread (zero for an exact fit); callers add a margin for it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitSpeedGain {
    /// The ratio for the query points given, ≥ 1 when a query point is a fitted one.
    pub gain: f64,
}

impl FitSpeedGain {
    /// The gain of a fit over `fitted` (positions at which the fit is evaluated, any pose:
    /// the ratio does not depend on the pose of the whole set) for the `query` points.
    ///
    /// # Errors
    /// [`Error::Degenerate`] when the fitted points are collinear.
    pub fn compute(fitted: &[Point3<f64>], query: &[Point3<f64>]) -> Result<Self> {
        // Frame at the fitted centroid: better conditioned than the aircraft origin.
        let centre = fitted.iter().fold(Vector3::zeros(), |s, p| s + p.coords) / fitted.len().max(1) as f64;
        let field = |x: &Point3<f64>| {
            // u(x) = v + ω × x = [I, -[x]×] (v, ω).
            let d = x.coords - centre;
            let mut a = nalgebra::Matrix3x6::zeros();
            a.fixed_view_mut::<3, 3>(0, 0).copy_from(&Matrix3::identity());
            a.fixed_view_mut::<3, 3>(0, 3).copy_from(&(-d.cross_matrix()));
            a
        };
        let mean = fitted.iter().fold(Matrix6::zeros(), |sum, x| {
            let a = field(x);
            sum + a.transpose() * a
        }) / fitted.len().max(1) as f64;
        let cholesky = mean.cholesky().ok_or(Error::Degenerate {
            what: "fit speed gain: the fitted points are collinear",
        })?;
        let l_inv_t = cholesky
            .l()
            .try_inverse()
            .ok_or(Error::Degenerate {
                what: "fit speed gain: the fitted points are collinear",
            })?
            .transpose();
        let gain = query
            .iter()
            .map(|y| {
                let b = field(y) * l_inv_t;
                (b * b.transpose()).symmetric_eigenvalues().max().max(0.0).sqrt()
            })
            .fold(0.0, f64::max);
        Ok(Self { gain })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square_and_apex() -> Vec<Point3<f64>> {
        vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 2.0, 0.0),
            Point3::new(0.0, 2.0, 0.3),
        ]
    }

    #[test]
    fn recovers_an_exact_motion() {
        let motion = Isometry3::new(Vector3::new(0.3, -1.2, 2.0), Vector3::new(0.4, -0.2, 1.1));
        let from = square_and_apex();
        let to: Vec<_> = from.iter().map(|p| motion * p).collect();
        let fit = fit_rigid_motion(&from, &to).unwrap();
        assert!(fit.max_m < 1e-12, "{}", fit.max_m);
        assert!((fit.motion.translation.vector - motion.translation.vector).norm() < 1e-12);
        assert!(fit.motion.rotation.angle_to(&motion.rotation) < 1e-12);
    }

    #[test]
    fn coplanar_points_are_not_reflected() {
        // All in z = 0: the SVD's third direction is free; the guard keeps a rotation.
        let from: Vec<_> = square_and_apex().iter().map(|p| Point3::new(p.x, p.y, 0.0)).collect();
        let motion = Isometry3::new(Vector3::new(1.0, 0.0, 0.0), Vector3::new(0.0, 0.0, 0.7));
        let to: Vec<_> = from.iter().map(|p| motion * p).collect();
        let fit = fit_rigid_motion(&from, &to).unwrap();
        assert!(fit.max_m < 1e-12);
        assert!(fit.motion.rotation.to_rotation_matrix().matrix().determinant() > 0.0);
    }

    #[test]
    fn a_disagreement_is_split_and_reported() {
        // One point pulled 0.1 off: the fit spreads the miss, its largest below 0.1.
        let from = square_and_apex();
        let mut to = from.clone();
        to[2].x += 0.1;
        let fit = fit_rigid_motion(&from, &to).unwrap();
        assert!(fit.max_m > 0.0 && fit.max_m < 0.1);
        assert!(fit.rms_m <= fit.max_m);
    }

    #[test]
    fn collinear_and_bad_input_are_refused() {
        let line: Vec<_> = (0..4).map(|i| Point3::new(i as f64, 0.0, 0.0)).collect();
        assert!(matches!(fit_rigid_motion(&line, &line), Err(Error::Degenerate { .. })));
        assert!(matches!(
            fit_rigid_motion(&line[..2], &line[..2]),
            Err(Error::TooFewPoints { .. })
        ));
        let mut bad = square_and_apex();
        bad[1].y = f64::NAN;
        assert!(matches!(
            fit_rigid_motion(&bad, &square_and_apex()),
            Err(Error::NotFinite { .. })
        ));
    }

    #[test]
    fn speed_gain_bounds_finite_differences_of_the_fit() {
        // Fitted points moving each along its own path: the fitted body's far point moves
        // no faster than gain x the fastest fitted point (plus the margin for the residual).
        let from = square_and_apex();
        let far = [Point3::new(3.0, 5.0, -1.0), Point3::new(0.5, 1.0, 0.1)];
        let gain = FitSpeedGain::compute(&from, &far).unwrap().gain;
        assert!(gain >= 1.0);
        let path = |t: f64| -> Vec<Point3<f64>> {
            from.iter()
                .enumerate()
                .map(|(k, p)| {
                    let k = k as f64;
                    let rigid = Isometry3::new(
                        Vector3::new(0.2 * t, -0.1 * t, 0.05 * t),
                        Vector3::new(0.0, 0.3 * t, 0.5 * t),
                    );
                    // A small non-rigid part: the fit is not exact.
                    rigid * p + Vector3::new(0.01 * (k * t).sin(), 0.0, 0.01 * k * t)
                })
                .collect()
        };
        let h = 1e-6;
        for i in 0..20 {
            let t = i as f64 / 19.0;
            let (a, b) = (path(t), path(t + h));
            let fastest = a.iter().zip(&b).map(|(p, q)| (q - p).norm() / h).fold(0.0, f64::max);
            let (fa, fb) = (
                fit_rigid_motion(&from, &a).unwrap(),
                fit_rigid_motion(&from, &b).unwrap(),
            );
            for y in &far {
                let speed = (fb.motion * y - fa.motion * y).norm() / h;
                assert!(speed <= 1.05 * gain * fastest, "t {t}: {speed} > {gain} x {fastest}");
            }
        }
    }
}
