//! Meshing context shared by the part meshes and the section outlines: section airfoils
//! resampled once, spanwise stations, cove cuts and trailing-edge handling.

use nalgebra::{Point2, Point3};

use crate::airfoil::{Airfoil, Surface};
use crate::error::{Error, Result};
use crate::flap::{cut_wing_outline, Flap};
use crate::loft::loft_closed;
use crate::mesh::TriMesh;
use crate::parts::{MeshResolution, WingModel};
use crate::wing::SectionAt;

/// Trailing-edge gap (unit chord) given to sections with a sharp trailing edge when they are
/// lofted together with open-trailing-edge sections, so that ring point counts match
/// without degenerate triangles.
pub const MIN_TRAILING_EDGE_GAP_CHORD_FRACTION: f64 = 1e-5;
/// Points closer than this (unit chord) count as coincident trailing-edge points.
const TRAILING_EDGE_CLOSED_TOL: f64 = 1e-12;

/// Meshing context: section airfoils resampled once.
pub(crate) struct Mesher<'a> {
    model: &'a WingModel,
    resolution: MeshResolution,
    airfoils: Vec<Airfoil>,
}

impl<'a> Mesher<'a> {
    pub(crate) fn new(model: &'a WingModel, resolution: MeshResolution) -> Result<Self> {
        let airfoils = model
            .wing
            .spec()
            .sections
            .iter()
            .map(|s| s.airfoil.resampled(resolution.points_per_side))
            .collect::<Result<_>>()?;
        Ok(Self {
            model,
            resolution,
            airfoils,
        })
    }

    pub(crate) fn section(&self, y_m: f64) -> Result<SectionAt> {
        let (k, t) = self.model.wing.locate(y_m, "mesh station")?;
        let (leading_edge_ac, chord_m, twist_rad) = self.model.wing.planform_at(y_m)?;
        let airfoil = Airfoil::blended(&self.airfoils[k], &self.airfoils[k + 1], t)?;
        Ok(SectionAt {
            leading_edge_ac,
            chord_m,
            twist_rad,
            airfoil,
        })
    }

    pub(crate) fn to_ac(&self, section: &SectionAt, outline: &[Point2<f64>]) -> Vec<Point3<f64>> {
        outline
            .iter()
            .map(|p| self.model.wing.section_point_ac(section, *p))
            .collect()
    }

    /// Stations from `a` to `b`: both ends, every wing section between, and subdivisions.
    pub(crate) fn stations(&self, a: f64, b: f64) -> Vec<f64> {
        let mut breaks = vec![a];
        breaks.extend(
            self.model
                .wing
                .spec()
                .sections
                .iter()
                .map(|s| s.y_m)
                .filter(|&y| y > a && y < b),
        );
        breaks.push(b);
        let mut stations = vec![a];
        for w in breaks.windows(2) {
            let count = ((w[1] - w[0]) * self.resolution.spanwise_stations_per_m)
                .ceil()
                .max(1.0) as usize;
            stations.extend((1..=count).map(|i| {
                if i == count {
                    w[1]
                } else {
                    w[0] + (w[1] - w[0]) * i as f64 / count as f64
                }
            }));
        }
        stations
    }

    pub(crate) fn wing_skin(&self) -> Result<TriMesh> {
        let (root, tip) = self.model.wing.span_range_m();
        let mut mesh = TriMesh::default();
        let mut y = root;
        let mut intervals = Vec::new();
        for flap in &self.model.flaps {
            let f = flap.spec();
            intervals.push((y, f.y_inboard_m, None));
            intervals.push((f.y_inboard_m, f.y_outboard_m, Some(flap)));
            y = f.y_outboard_m;
        }
        intervals.push((y, tip, None));
        for (a, b, flap) in intervals {
            if b - a <= 1e-9 * (1.0 + b.abs()) {
                continue;
            }
            let stations = self.stations(a, b);
            let mut sections = Vec::with_capacity(stations.len());
            let mut outlines = Vec::with_capacity(stations.len());
            for &y in &stations {
                let section = self.section(y)?;
                let outline = match flap {
                    None => section.airfoil.points.clone(),
                    Some(flap) => cut_wing_outline(flap, y, &section.airfoil, self.resolution.points_per_side)?,
                };
                outlines.push(outline);
                sections.push(section);
            }
            let outlines = if flap.is_none() {
                consistent_trailing_edges(outlines)
            } else {
                outlines
            };
            let rings: Vec<_> = sections.iter().zip(&outlines).map(|(s, o)| self.to_ac(s, o)).collect();
            mesh.append(&loft_closed(&rings, "wing skin")?);
        }
        Ok(mesh)
    }

    /// The flap's main element (the whole flap for a single-element one) and its aft
    /// element, if it has one.
    pub(crate) fn flap(&self, flap: &Flap) -> Result<(TriMesh, Option<TriMesh>)> {
        let (a, b) = flap.body_span_m(&self.model.wing)?;
        let stations = self.stations(a, b);
        let mut sections = Vec::with_capacity(stations.len());
        let mut mains = Vec::with_capacity(stations.len());
        let mut afts = Vec::with_capacity(stations.len());
        for &y in &stations {
            let section = self.section(y)?;
            let elements = flap.element_outlines(y, &section.airfoil, self.resolution.points_per_side)?;
            mains.push(elements.main);
            afts.extend(elements.aft);
            sections.push(section);
        }
        let loft = |outlines: Vec<Vec<Point2<f64>>>, what: &'static str| {
            let rings: Vec<_> = sections
                .iter()
                .zip(&consistent_trailing_edges(outlines))
                .map(|(s, o)| self.to_ac(s, o))
                .collect();
            loft_closed(&rings, what)
        };
        let aft = if afts.is_empty() {
            None
        } else {
            Some(loft(afts, "flap aft element")?)
        };
        Ok((loft(mains, "flap")?, aft))
    }
}

/// Wing outline cut at chord fraction `cove_u` with a straight cove wall: upper side from
/// the wall to the leading edge, lower side back to the wall, `2 n - 1` points.
pub(crate) fn truncated_outline(airfoil: &Airfoil, cove_u: f64, points_per_side: usize) -> Result<Vec<Point2<f64>>> {
    let upper = airfoil.surface_line(Surface::Upper);
    let lower = airfoil.surface_line(Surface::Lower);
    let bad = || Error::BadAirfoil {
        name: airfoil.name.clone(),
        reason: "flap cove wall lies outside the wing section",
    };
    let s_upper = upper.arc_at_x(cove_u).ok_or_else(bad)?;
    let s_lower = lower.arc_at_x(cove_u).ok_or_else(bad)?;
    let mut outline: Vec<Point2<f64>> = upper
        .sample_cosine(0.0, s_upper, points_per_side)
        .into_iter()
        .rev()
        .collect();
    outline.extend(lower.sample_cosine(0.0, s_lower, points_per_side).into_iter().skip(1));
    Ok(outline)
}

/// Makes the trailing edges of a set of outlines (first point = upper TE, last = lower TE)
/// agree: all sharp -> the repeated last point is dropped; all open -> kept; mixed -> the
/// sharp ones are opened by [`MIN_TRAILING_EDGE_GAP_CHORD_FRACTION`].
pub(crate) fn consistent_trailing_edges(mut outlines: Vec<Vec<Point2<f64>>>) -> Vec<Vec<Point2<f64>>> {
    let is_closed = |o: &Vec<Point2<f64>>| (o[0] - o[o.len() - 1]).norm() <= TRAILING_EDGE_CLOSED_TOL;
    let closed_count = outlines.iter().filter(|o| is_closed(o)).count();
    if closed_count == outlines.len() {
        for o in &mut outlines {
            o.pop();
        }
    } else if closed_count > 0 {
        let half = 0.5 * MIN_TRAILING_EDGE_GAP_CHORD_FRACTION;
        for o in outlines.iter_mut().filter(|o| is_closed(o)) {
            let last = o.len() - 1;
            o[0].y += half;
            o[last].y -= half;
        }
    }
    outlines
}
