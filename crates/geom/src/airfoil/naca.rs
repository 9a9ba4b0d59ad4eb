//! NACA 4-digit and 5-digit (standard and reflexed camber) sections from their analytic
//! definitions.
//!
//! Source: I. H. Abbott, A. E. von Doenhoff, *Theory of Wing Sections* (1959), sections
//! 6.2-6.4 and appendix I; the reflexed 5-digit constants as tabulated by NASA TM-4741
//! (Ladson, Brooks, Hill, Sproles 1996, "Computer program to obtain ordinates for NACA
//! airfoils"). Coordinates: unit chord, x aft from the leading edge, y up. Thickness is
//! applied perpendicular to the mean line (eq. 6.1 of Abbott & von Doenhoff):
//! `x_u = x - y_t sin(theta)`, `y_u = y_c + y_t cos(theta)`, `x_l = x + y_t sin(theta)`,
//! `y_l = y_c - y_t cos(theta)`, `theta = atan(dy_c/dx)`.

use nalgebra::Point2;

use super::{Airfoil, MIN_POINTS_PER_SIDE};
use crate::error::{Error, Result};

/// Trailing-edge shape of a generated NACA section.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TrailingEdge {
    /// The published polynomial: last coefficient -0.1015, finite half-thickness at x = 1,
    /// y_t(1) = 5 t 0.0021 = 0.0105 t.
    #[default]
    Open,
    /// Last coefficient -0.1036 so that y_t(1) = 0: a sharp, closed trailing edge.
    Closed,
}

/// Mean-line family of a NACA section.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NacaCamber {
    /// 4-digit mean line: two parabolas meeting at the maximum camber.
    FourDigit {
        /// Maximum camber m (fraction of chord), first digit / 100.
        max_camber: f64,
        /// Chordwise position p of the maximum camber, second digit / 10.
        max_camber_position: f64,
    },
    /// 5-digit mean line (cubic ahead of r, straight or reflexed cubic behind).
    FiveDigit {
        /// Design lift coefficient c_l,i = 3 L / 20 (first digit L).
        design_lift_coefficient: f64,
        /// r: the mean line's junction station (called m in Abbott & von Doenhoff).
        junction: f64,
        /// k1 at c_l,i = 0.3 (the table value; scaled by c_l,i / 0.3).
        k1: f64,
        /// k2/k1 for the reflexed mean lines (third digit 1), `None` for standard lines.
        k2_over_k1: Option<f64>,
    },
}

/// An analytic NACA section: mean line, thickness ratio and trailing-edge shape.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Naca {
    /// Mean line.
    pub camber: NacaCamber,
    /// Maximum thickness t as a fraction of chord (last two digits / 100).
    pub thickness_ratio: f64,
    /// Open (published polynomial) or closed trailing edge.
    pub trailing_edge: TrailingEdge,
}

/// Standard 5-digit mean lines: (P digit, r, k1) for c_l,i = 0.3 (Abbott & von Doenhoff,
/// section 6.4).
const FIVE_DIGIT_STANDARD: [(u32, f64, f64); 5] = [
    (1, 0.0580, 361.400),
    (2, 0.1260, 51.640),
    (3, 0.2025, 15.957),
    (4, 0.2900, 6.643),
    (5, 0.3910, 3.230),
];

/// Reflexed 5-digit mean lines: (P digit, r, k1, k2/k1) for c_l,i = 0.3 (NASA TM-4741).
#[allow(clippy::approx_constant)] // r = 0.3180 is a table value, not 1/pi
const FIVE_DIGIT_REFLEXED: [(u32, f64, f64, f64); 4] = [
    (2, 0.1300, 51.990, 0.000764),
    (3, 0.2170, 15.793, 0.00677),
    (4, 0.3180, 6.520, 0.0303),
    (5, 0.4410, 3.191, 0.1355),
];

impl Naca {
    /// Parses "2412", "NACA 23012", "naca0012" (4 or 5 digits; 5-digit third digit 0 or 1).
    pub fn parse(designation: &str, trailing_edge: TrailingEdge) -> Result<Naca> {
        let unknown = || Error::UnknownNacaDesignation {
            designation: designation.to_owned(),
        };
        let trimmed = designation.trim();
        let digits_text = trimmed
            .strip_prefix("NACA")
            .or_else(|| trimmed.strip_prefix("naca"))
            .or_else(|| trimmed.strip_prefix("Naca"))
            .unwrap_or(trimmed)
            .trim()
            .trim_start_matches('-')
            .trim();
        let digits: Vec<u32> = digits_text
            .chars()
            .map(|c| c.to_digit(10))
            .collect::<Option<_>>()
            .ok_or_else(unknown)?;
        let thickness_of = |a: u32, b: u32| f64::from(10 * a + b) / 100.0;
        match digits[..] {
            [m, p, t1, t2] => {
                if (m == 0) != (p == 0) || thickness_of(t1, t2) == 0.0 {
                    return Err(unknown());
                }
                Ok(Naca {
                    camber: NacaCamber::FourDigit {
                        max_camber: f64::from(m) / 100.0,
                        max_camber_position: f64::from(p) / 10.0,
                    },
                    thickness_ratio: thickness_of(t1, t2),
                    trailing_edge,
                })
            }
            [l, p, s, t1, t2] => {
                if l == 0 || thickness_of(t1, t2) == 0.0 {
                    return Err(unknown());
                }
                let design_lift_coefficient = 3.0 * f64::from(l) / 20.0;
                let camber = match s {
                    0 => {
                        let &(_, r, k1) = FIVE_DIGIT_STANDARD.iter().find(|e| e.0 == p).ok_or_else(unknown)?;
                        NacaCamber::FiveDigit {
                            design_lift_coefficient,
                            junction: r,
                            k1,
                            k2_over_k1: None,
                        }
                    }
                    1 => {
                        let &(_, r, k1, k21) = FIVE_DIGIT_REFLEXED.iter().find(|e| e.0 == p).ok_or_else(unknown)?;
                        NacaCamber::FiveDigit {
                            design_lift_coefficient,
                            junction: r,
                            k1,
                            k2_over_k1: Some(k21),
                        }
                    }
                    _ => return Err(unknown()),
                };
                Ok(Naca {
                    camber,
                    thickness_ratio: thickness_of(t1, t2),
                    trailing_edge,
                })
            }
            _ => Err(unknown()),
        }
    }

    /// Half-thickness y_t(x) measured perpendicular to the mean line (Abbott & von Doenhoff
    /// eq. 6.2): `y_t = 5 t (0.2969 sqrt(x) - 0.1260 x - 0.3516 x^2 + 0.2843 x^3 - a4 x^4)`,
    /// a4 = 0.1015 (open) or 0.1036 (closed). x in [0, 1], unit chord (values outside are
    /// clamped to the ends).
    pub fn thickness(&self, x: f64) -> f64 {
        let a4 = match self.trailing_edge {
            TrailingEdge::Open => 0.1015,
            TrailingEdge::Closed => 0.1036,
        };
        let x = x.clamp(0.0, 1.0);
        5.0 * self.thickness_ratio
            * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3) - a4 * x.powi(4))
    }

    /// Mean-line height y_c(x), unit chord.
    pub fn camber(&self, x: f64) -> f64 {
        self.camber_and_slope(x.clamp(0.0, 1.0)).0
    }

    /// Mean-line slope dy_c/dx at x.
    pub fn camber_slope(&self, x: f64) -> f64 {
        self.camber_and_slope(x.clamp(0.0, 1.0)).1
    }

    fn camber_and_slope(&self, x: f64) -> (f64, f64) {
        match self.camber {
            NacaCamber::FourDigit {
                max_camber: m,
                max_camber_position: p,
            } => {
                if m == 0.0 {
                    (0.0, 0.0)
                } else if x < p {
                    (m / (p * p) * (2.0 * p * x - x * x), 2.0 * m / (p * p) * (p - x))
                } else {
                    let q = (1.0 - p) * (1.0 - p);
                    (m / q * ((1.0 - 2.0 * p) + 2.0 * p * x - x * x), 2.0 * m / q * (p - x))
                }
            }
            NacaCamber::FiveDigit {
                design_lift_coefficient,
                junction: r,
                k1,
                k2_over_k1,
            } => {
                let scale = design_lift_coefficient / 0.3;
                let (y, dy) = match k2_over_k1 {
                    None if x < r => (
                        k1 / 6.0 * (x.powi(3) - 3.0 * r * x * x + r * r * (3.0 - r) * x),
                        k1 / 6.0 * (3.0 * x * x - 6.0 * r * x + r * r * (3.0 - r)),
                    ),
                    None => (k1 * r.powi(3) / 6.0 * (1.0 - x), -k1 * r.powi(3) / 6.0),
                    Some(k21) => {
                        let c = -k21 * (1.0 - r).powi(3) - r.powi(3);
                        if x < r {
                            (
                                k1 / 6.0 * ((x - r).powi(3) + c * x + r.powi(3)),
                                k1 / 6.0 * (3.0 * (x - r).powi(2) + c),
                            )
                        } else {
                            (
                                k1 / 6.0 * (k21 * (x - r).powi(3) + c * x + r.powi(3)),
                                k1 / 6.0 * (3.0 * k21 * (x - r).powi(2) + c),
                            )
                        }
                    }
                };
                (scale * y, scale * dy)
            }
        }
    }

    /// Upper and lower surface points at mean-line station x (eq. 6.1).
    pub fn surface_points(&self, x: f64) -> (Point2<f64>, Point2<f64>) {
        let (yc, slope) = self.camber_and_slope(x.clamp(0.0, 1.0));
        let yt = if self.trailing_edge == TrailingEdge::Closed && x >= 1.0 {
            0.0
        } else {
            self.thickness(x)
        };
        let (sin, cos) = slope.atan().sin_cos();
        (
            Point2::new(x - yt * sin, yc + yt * cos),
            Point2::new(x + yt * sin, yc - yt * cos),
        )
    }
}

impl Airfoil {
    /// Generates a NACA 4- or 5-digit section with `points_per_side` points on each side
    /// (leading edge shared), cosine spacing of the mean-line station
    /// `x_i = (1 - cos(pi i / (n - 1))) / 2`, in Selig order.
    pub fn naca(designation: &str, points_per_side: usize, trailing_edge: TrailingEdge) -> Result<Airfoil> {
        if points_per_side < MIN_POINTS_PER_SIDE {
            return Err(Error::TooFewPoints {
                what: "NACA points per side",
                count: points_per_side,
                minimum: MIN_POINTS_PER_SIDE,
            });
        }
        let naca = Naca::parse(designation, trailing_edge)?;
        let stations: Vec<(Point2<f64>, Point2<f64>)> = (0..points_per_side)
            .map(|i| {
                let x = if i + 1 == points_per_side {
                    1.0
                } else {
                    0.5 * (1.0 - (std::f64::consts::PI * i as f64 / (points_per_side - 1) as f64).cos())
                };
                naca.surface_points(x)
            })
            .collect();
        let mut points: Vec<Point2<f64>> = stations.iter().rev().map(|s| s.0).collect();
        points.extend(stations.iter().skip(1).map(|s| s.1));
        let digits: String = designation.chars().filter(char::is_ascii_digit).collect();
        Airfoil::try_new(format!("NACA {digits}"), points)
    }
}
