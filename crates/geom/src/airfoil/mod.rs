//! Airfoil sections: unit-chord point loops in Selig order, NACA generators, `.dat` files.
//!
//! Coordinates are 2D section coordinates: x aft along the chord from the leading edge
//! (unit chord, x in [0, 1] for normalised data), y up (towards the upper surface).

mod dat;
mod naca;
pub(crate) mod surface;

pub use naca::{Naca, NacaCamber, TrailingEdge};

use nalgebra::Point2;

use crate::error::{require_range, Error, Result};
use surface::SurfaceLine;

/// Smallest number of points per side accepted when resampling or generating.
pub const MIN_POINTS_PER_SIDE: usize = 3;

/// How far (unit chord, in x) the middle point of an odd-count airfoil may lie behind the
/// point of smallest x and still be taken as the leading edge.
pub const LEADING_EDGE_MIDDLE_TOL: f64 = 2e-3;

/// How far (unit chord) beyond the end of a side [`Airfoil::surface_y`] still answers.
pub const SURFACE_END_TOL: f64 = 2e-3;

/// Which side of an airfoil.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Surface {
    /// Upper (suction) side, y larger.
    Upper,
    /// Lower (pressure) side.
    Lower,
}

/// An airfoil section: unit chord, Selig order (upper trailing edge -> leading edge ->
/// lower trailing edge), x aft, y up. The leading edge is the point of smallest x.
/// A closed (sharp) trailing edge repeats the same point first and last.
#[derive(Debug, Clone, PartialEq)]
pub struct Airfoil {
    /// Name (file title or NACA designation).
    pub name: String,
    /// Points in Selig order, unit-chord section coordinates.
    pub points: Vec<Point2<f64>>,
}

impl Airfoil {
    /// Checks the points (at least 5, finite, one leading edge with points on both sides)
    /// and returns the airfoil.
    pub fn try_new(name: impl Into<String>, points: Vec<Point2<f64>>) -> Result<Airfoil> {
        let airfoil = Airfoil {
            name: name.into(),
            points,
        };
        airfoil.validate()?;
        Ok(airfoil)
    }

    /// Checks the invariants of [`Airfoil::try_new`] (the fields are public, so a spec may
    /// carry an airfoil built without it).
    pub fn validate(&self) -> Result<()> {
        if self.points.len() < 5 {
            return Err(Error::TooFewPoints {
                what: "airfoil",
                count: self.points.len(),
                minimum: 5,
            });
        }
        if self.points.iter().any(|p| !p.x.is_finite() || !p.y.is_finite()) {
            return Err(self.bad("a coordinate is NaN or infinite"));
        }
        let le = self.leading_edge_index();
        if le == 0 || le + 1 == self.points.len() {
            return Err(self.bad("the leading edge (smallest x) is an end point, not between the two sides"));
        }
        if self.compute_area() <= 0.0 {
            return Err(self.bad("points are not in Selig order (upper TE -> LE -> lower TE) or enclose no area"));
        }
        Ok(())
    }

    fn bad(&self, reason: &'static str) -> Error {
        Error::BadAirfoil {
            name: self.name.clone(),
            reason,
        }
    }

    /// Index of the leading edge. For an odd point count whose middle point lies within
    /// [`LEADING_EDGE_MIDDLE_TOL`] (unit chord) of the smallest x, the middle point (the
    /// convention of generated and resampled sections, whose mean-line leading edge is not
    /// always the point of smallest x: camber applied normal to the mean line moves upper
    /// points slightly ahead of it); otherwise the point of smallest x (first on ties).
    pub fn leading_edge_index(&self) -> usize {
        let mut best = 0;
        for (i, p) in self.points.iter().enumerate() {
            if p.x < self.points[best].x {
                best = i;
            }
        }
        let n = self.points.len();
        if n % 2 == 1 {
            let middle = n / 2;
            let near = self.points[middle].x - self.points[best].x <= LEADING_EDGE_MIDDLE_TOL
                && best.abs_diff(middle) <= n / 10 + 2;
            if near {
                return middle;
            }
        }
        best
    }

    /// Points of one side from the leading edge to the trailing edge.
    pub fn side(&self, surface: Surface) -> Vec<Point2<f64>> {
        let le = self.leading_edge_index();
        match surface {
            Surface::Upper => self.points[..=le].iter().rev().copied().collect(),
            Surface::Lower => self.points[le..].to_vec(),
        }
    }

    pub(crate) fn surface_line(&self, surface: Surface) -> SurfaceLine {
        SurfaceLine::new(self.side(surface))
    }

    /// `Some(n)` when both sides have `n` points (leading edge counted on both).
    pub fn points_per_side(&self) -> Option<usize> {
        let le = self.leading_edge_index();
        (le + 1 == self.points.len() - le).then_some(le + 1)
    }

    /// True when the first and last points coincide (sharp, closed trailing edge).
    pub fn has_closed_trailing_edge(&self) -> bool {
        match (self.points.first(), self.points.last()) {
            (Some(a), Some(b)) => (a - b).norm() <= 1e-12,
            _ => false,
        }
    }

    /// Enclosed area (chord^2 units) of the polygon by the shoelace formula, closing the
    /// trailing-edge gap with a straight line; positive in Selig order (counter-clockwise).
    pub fn compute_area(&self) -> f64 {
        let n = self.points.len();
        0.5 * (0..n)
            .map(|i| {
                let (a, b) = (self.points[i], self.points[(i + 1) % n]);
                a.x * b.y - b.x * a.y
            })
            .sum::<f64>()
    }

    /// The same outline with `points_per_side` points on each side (leading edge shared),
    /// spaced by the cosine rule in arc length along each side, so that sections from
    /// different sources correspond point by point and can be lofted and blended.
    /// Returns a copy unchanged when the airfoil already has that many points per side.
    pub fn resampled(&self, points_per_side: usize) -> Result<Airfoil> {
        if points_per_side < MIN_POINTS_PER_SIDE {
            return Err(Error::TooFewPoints {
                what: "airfoil points per side",
                count: points_per_side,
                minimum: MIN_POINTS_PER_SIDE,
            });
        }
        if self.points_per_side() == Some(points_per_side) {
            return Ok(self.clone());
        }
        let upper = self.surface_line(Surface::Upper);
        let lower = self.surface_line(Surface::Lower);
        let mut points: Vec<Point2<f64>> = upper
            .sample_cosine(0.0, upper.length(), points_per_side)
            .into_iter()
            .rev()
            .collect();
        points.extend(
            lower
                .sample_cosine(0.0, lower.length(), points_per_side)
                .into_iter()
                .skip(1),
        );
        Ok(Airfoil {
            name: self.name.clone(),
            points,
        })
    }

    /// Point-by-point linear blend `(1 - t) a + t b` (both resampled to the larger point
    /// count first when they differ); `t` in [0, 1].
    pub fn blended(a: &Airfoil, b: &Airfoil, t: f64) -> Result<Airfoil> {
        require_range("airfoil blend fraction t", t, 0.0, 1.0)?;
        let (a, b) = match (a.points_per_side(), b.points_per_side()) {
            (Some(na), Some(nb)) if na == nb => (a.clone(), b.clone()),
            _ => {
                let n = a.points.len().max(b.points.len()).div_ceil(2).max(MIN_POINTS_PER_SIDE);
                (a.resampled(n)?, b.resampled(n)?)
            }
        };
        let points = a.points.iter().zip(&b.points).map(|(p, q)| p + (q - p) * t).collect();
        let name = if t == 0.0 {
            a.name.clone()
        } else if t == 1.0 {
            b.name.clone()
        } else {
            format!("{} / {} blend {t:.3}", a.name, b.name)
        };
        Ok(Airfoil { name, points })
    }

    /// y of a surface at chord station `x` by linear interpolation along that side
    /// (unit-chord coordinates). Stations up to [`SURFACE_END_TOL`] beyond the side's ends
    /// take the end value (thickness applied normal to a cambered mean line ends the upper
    /// side slightly ahead of x = 1); further out is an error.
    pub fn surface_y(&self, x: f64, surface: Surface) -> Result<f64> {
        let side = self.side(surface);
        let (first, last) = (side[0].x, side[side.len() - 1].x);
        let (lowest, highest) = (first.min(last), first.max(last));
        require_range(
            "airfoil chord station x/c",
            x,
            lowest - SURFACE_END_TOL,
            highest + SURFACE_END_TOL,
        )?;
        let x = x.clamp(lowest, highest);
        let line = SurfaceLine::new(side);
        let s = line.arc_at_x(x).unwrap_or(0.0);
        Ok(line.point_at_arc(s).y)
    }

    /// Midpoint of the first and last points (the trailing edge, or the middle of its gap).
    pub fn trailing_edge_midpoint(&self) -> Point2<f64> {
        nalgebra::center(&self.points[0], &self.points[self.points.len() - 1])
    }

    /// Camber-line height at `x`: mean of upper and lower surface y.
    pub fn mean_line_y(&self, x: f64) -> Result<f64> {
        Ok(0.5 * (self.surface_y(x, Surface::Upper)? + self.surface_y(x, Surface::Lower)?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resampling_keeps_the_area_of_a_fine_section() {
        let fine = Airfoil::naca("2412", 400, TrailingEdge::Closed).unwrap();
        let coarse = fine.resampled(120).unwrap();
        assert_eq!(coarse.points_per_side(), Some(120));
        approx::assert_relative_eq!(coarse.compute_area(), fine.compute_area(), max_relative = 2e-3);
        assert!(coarse.has_closed_trailing_edge());
    }

    #[test]
    fn blend_end_points_are_the_inputs() {
        let a = Airfoil::naca("0012", 40, TrailingEdge::Closed).unwrap();
        let b = Airfoil::naca("4415", 40, TrailingEdge::Closed).unwrap();
        assert_eq!(Airfoil::blended(&a, &b, 1.0).unwrap().points, b.points);
        assert!(Airfoil::blended(&a, &b, f64::NAN).is_err());
    }
}
