//! Reference boundary polylines (thesis `000`, Appendix C, Fig. 45) and the deviation of a
//! set of section polygons from them.
//!
//! The data file `data/validation/thesis-fig45-boundaries.csv` is read through
//! [`parse_boundary_csv`] from any `impl BufRead`; this crate opens no files.

use std::io::BufRead;

use nalgebra::Point2;

use crate::error::{Error, Result};

/// One row of the Fig. 45 boundary table: a point in a station frame, in mm as printed.
#[derive(Debug, Clone, PartialEq)]
pub struct BoundaryPoint {
    /// Which mechanism plane: "inner" or "outer".
    pub plane: String,
    /// Boundary id ("flap", "spar-front", "wing-top", ...).
    pub boundary: String,
    /// Index of the point along its boundary.
    pub point: usize,
    /// Polar radius about A0 as printed, mm (None when the source gives none).
    pub r_mm: Option<f64>,
    /// Polar angle as printed, degrees, counter-clockwise from station x.
    pub theta_deg: Option<f64>,
    /// Polar angle as printed, rad.
    pub theta_rad: Option<f64>,
    /// Station x (towards the nose), mm.
    pub x_mm: f64,
    /// Station y (up), mm.
    pub y_mm: f64,
    /// False for rows whose printed polar and cartesian values disagree in the source.
    pub polar_consistent: bool,
}

impl BoundaryPoint {
    /// The point in metres (station frame).
    pub fn position_m(&self) -> Point2<f64> {
        Point2::new(self.x_mm * 1e-3, self.y_mm * 1e-3)
    }
}

/// Splits a CSV line on commas outside double quotes.
fn split_csv(line: &str) -> Vec<&str> {
    let mut fields = Vec::new();
    let mut start = 0;
    let mut quoted = false;
    for (i, c) in line.char_indices() {
        match c {
            '"' => quoted = !quoted,
            ',' if !quoted => {
                fields.push(&line[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    fields.push(&line[start..]);
    fields
}

/// Reads the boundary table: lines starting with `#` are comments, the first other line
/// is the header `plane,boundary,label_in_source,point,r_mm,theta_deg,theta_rad,x_mm,y_mm,
/// polar_consistent,...`. Errors name the line and column that could not be read.
pub fn parse_boundary_csv(reader: impl BufRead) -> Result<Vec<BoundaryPoint>> {
    let mut points = Vec::new();
    let mut header_seen = false;
    for (index, line) in reader.lines().enumerate() {
        let line_number = index + 1;
        let line = line.map_err(|_| Error::BoundaryCsvField {
            line: line_number,
            column: "(unreadable line)",
        })?;
        let trimmed = line.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        if !header_seen {
            header_seen = true;
            continue;
        }
        let fields = split_csv(trimmed);
        let field = |i: usize, column: &'static str| {
            fields.get(i).map(|s| s.trim()).ok_or(Error::BoundaryCsvField {
                line: line_number,
                column,
            })
        };
        let number = |i: usize, column: &'static str| -> Result<f64> {
            let value: f64 = field(i, column)?.parse().map_err(|_| Error::BoundaryCsvField {
                line: line_number,
                column,
            })?;
            if value.is_finite() {
                Ok(value)
            } else {
                Err(Error::BoundaryCsvField {
                    line: line_number,
                    column,
                })
            }
        };
        let optional = |i: usize, column: &'static str| -> Result<Option<f64>> {
            if field(i, column)?.is_empty() {
                Ok(None)
            } else {
                number(i, column).map(Some)
            }
        };
        points.push(BoundaryPoint {
            plane: field(0, "plane")?.to_owned(),
            boundary: field(1, "boundary")?.to_owned(),
            point: field(3, "point")?.parse().map_err(|_| Error::BoundaryCsvField {
                line: line_number,
                column: "point",
            })?,
            r_mm: optional(4, "r_mm")?,
            theta_deg: optional(5, "theta_deg")?,
            theta_rad: optional(6, "theta_rad")?,
            x_mm: number(7, "x_mm")?,
            y_mm: number(8, "y_mm")?,
            polar_consistent: match field(9, "polar_consistent")? {
                "true" => true,
                "false" => false,
                _ => {
                    return Err(Error::BoundaryCsvField {
                        line: line_number,
                        column: "polar_consistent",
                    })
                }
            },
        });
    }
    Ok(points)
}

/// The points (station frame, m) of one boundary of one plane, in table order, e.g.
/// `boundary_points_m(&rows, "outer", "flap")`.
pub fn boundary_points_m(rows: &[BoundaryPoint], plane: &str, boundary: &str) -> Vec<Point2<f64>> {
    rows.iter()
        .filter(|r| r.plane == plane && r.boundary == boundary)
        .map(BoundaryPoint::position_m)
        .collect()
}

/// Distance statistics of reference points to a set of polygons, metres.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Deviation {
    /// Largest distance of a reference point to the nearest polygon edge, m.
    pub max_m: f64,
    /// Mean of those distances, m.
    pub mean_m: f64,
    /// Number of reference points.
    pub point_count: usize,
}

/// Distance (m) from `point` to the segment `a`-`b`.
pub fn distance_to_segment_m(point: &Point2<f64>, a: &Point2<f64>, b: &Point2<f64>) -> f64 {
    let ab = b - a;
    let length_squared = ab.norm_squared();
    let t = if length_squared > 0.0 {
        ((point - a).dot(&ab) / length_squared).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (point - (a + ab * t)).norm()
}

/// For every reference point, the distance to the nearest edge of any closed polygon in
/// `polygons` (station frame, m); returns max and mean, or `None` when there is no point
/// or no edge to measure against.
pub fn boundary_deviation(polygons: &[Vec<Point2<f64>>], reference_points: &[Point2<f64>]) -> Option<Deviation> {
    let edges: Vec<(Point2<f64>, Point2<f64>)> = polygons
        .iter()
        .filter(|p| p.len() >= 2)
        .flat_map(|p| (0..p.len()).map(move |i| (p[i], p[(i + 1) % p.len()])))
        .collect();
    if edges.is_empty() || reference_points.is_empty() {
        return None;
    }
    let distances: Vec<f64> = reference_points
        .iter()
        .map(|q| {
            edges
                .iter()
                .map(|(a, b)| distance_to_segment_m(q, a, b))
                .fold(f64::INFINITY, f64::min)
        })
        .collect();
    Some(Deviation {
        max_m: distances.iter().copied().fold(0.0, f64::max),
        mean_m: distances.iter().sum::<f64>() / distances.len() as f64,
        point_count: distances.len(),
    })
}
