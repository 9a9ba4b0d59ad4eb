//! Guarded inverse trigonometry and the numerical tolerances of the crate.

use crate::error::{Error, Result};

/// How far past ±1 a cosine may drift from rounding before `acos` refuses it.
///
/// Cosines computed by the law of cosines from lengths of order 1 m carry a rounding
/// error of a few 1e-16; 1e-12 leaves three orders of margin and still rejects any
/// geometrically impossible triangle.
pub const ACOS_ROUNDING_TOLERANCE: f64 = 1e-12;

/// Default toggle tolerance (rad): a transmission angle below this is reported as
/// [`Error::Toggle`] rather than answered with velocities of order 1/μ.
pub const DEFAULT_TOGGLE_TOLERANCE_RAD: f64 = 1e-5;

/// `acos(cosine)` that clamps only rounding noise.
///
/// Returns the angle in [0, π] (rad). A cosine beyond ±(1 + [`ACOS_ROUNDING_TOLERANCE`])
/// or a NaN gives [`Error::AcosOutOfRange`] naming `quantity`.
pub fn guarded_acos(cosine: f64, quantity: &'static str) -> Result<f64> {
    if !cosine.is_finite() || cosine.abs() > 1.0 + ACOS_ROUNDING_TOLERANCE {
        return Err(Error::AcosOutOfRange {
            quantity,
            cosine,
            tolerance: ACOS_ROUNDING_TOLERANCE,
        });
    }
    Ok(cosine.clamp(-1.0, 1.0).acos())
}

/// Four times the area of a triangle with sides `a`, `b`, `c`, by Kahan's
/// cancellation-free arrangement of Heron's formula ("Miscalculating area and angles of
/// a needle-like triangle", 2014). Units: length² when the sides are lengths.
///
/// Returns `None` when the sides violate the triangle inequality by more than
/// `relative_tolerance * max(a, b, c)`; a violation within the tolerance is rounding
/// and gives a degenerate triangle (area 0).
pub fn four_times_triangle_area(a: f64, b: f64, c: f64, relative_tolerance: f64) -> Option<f64> {
    // Sort so that x >= y >= z.
    let (mut x, mut y, mut z) = (a, b, c);
    if x < y {
        std::mem::swap(&mut x, &mut y);
    }
    if y < z {
        std::mem::swap(&mut y, &mut z);
    }
    if x < y {
        std::mem::swap(&mut x, &mut y);
    }
    let defect = z - (x - y);
    if defect < -relative_tolerance * x {
        return None;
    }
    let product = (x + (y + z)) * defect.max(0.0) * (z + (x - y)) * (x + (y - z));
    Some(product.max(0.0).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn acos_clamps_rounding_only() {
        assert_eq!(guarded_acos(1.0 + 1e-14, "t").unwrap(), 0.0);
        assert!(matches!(
            guarded_acos(1.0 + 1e-9, "t"),
            Err(Error::AcosOutOfRange { .. })
        ));
        assert!(guarded_acos(f64::NAN, "t").is_err());
    }

    #[test]
    fn kahan_area_of_right_triangle() {
        // 3-4-5 triangle: area 6, four times 24.
        let four_area = four_times_triangle_area(3.0, 4.0, 5.0, 0.0).unwrap();
        assert!((four_area - 24.0).abs() < 1e-12);
        assert!(four_times_triangle_area(1.0, 1.0, 3.0, 1e-12).is_none());
        assert_eq!(four_times_triangle_area(1.0, 1.0, 2.0, 1e-12), Some(0.0));
    }
}
