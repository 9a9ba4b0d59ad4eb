//! The whole wing model (wing, flaps, spars, torque tube) and its part meshes.
//!
//! Wing skin: one closed shell per spanwise interval: plain intervals carry the full
//! section, flap intervals the section cut at the cove wall. Shells of neighbouring
//! intervals touch along their common cap plane (y = const) but share no vertices, so each
//! shell is watertight on its own and the part's volume is their sum. Each flap body is
//! one closed shell, narrower than its cut-out by the side gaps, so a stowed flap keeps a
//! clearance to the wing everywhere.

use nalgebra::{Point2, Point3};

use crate::airfoil::{Airfoil, Surface, MIN_POINTS_PER_SIDE};
use crate::error::{require_range, Error, Result};
use crate::flap::{cove_chord_fraction, Flap, FlapSpec, COVE_GAP_CHORD_FRACTION};
use crate::loft::loft_closed;
use crate::mesh::TriMesh;
use crate::structure::{SparSpec, TorqueTubeSpec};
use crate::wing::{SectionAt, Wing, WingSpec};

/// Trailing-edge gap (unit chord) given to sections with a sharp trailing edge when they are
/// lofted together with open-trailing-edge sections, so that ring point counts match
/// without degenerate triangles.
pub const MIN_TRAILING_EDGE_GAP_CHORD_FRACTION: f64 = 1e-5;
/// Points closer than this (unit chord) count as coincident trailing-edge points.
const TRAILING_EDGE_CLOSED_TOL: f64 = 1e-12;

/// Mesh fineness.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshResolution {
    /// Airfoil points per side (leading edge shared), cosine spaced; >= 3.
    pub points_per_side: usize,
    /// Spanwise stations per metre of span, in addition to every section and flap end; > 0.
    pub spanwise_stations_per_m: f64,
    /// Points round the torque tube; >= 3.
    pub tube_segments: usize,
}

impl Default for MeshResolution {
    /// 60 points per side, 4 stations per metre, 24 tube segments.
    fn default() -> Self {
        Self { points_per_side: 60, spanwise_stations_per_m: 4.0, tube_segments: 24 }
    }
}

/// Kind of a part.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PartKind {
    /// Main wing skin (a shell: surface queries are right for it).
    WingSkin,
    /// A flap body (stowed).
    Flap,
    /// A spar plate (solid).
    Spar,
    /// The torque tube (solid).
    TorqueTube,
}

/// One meshed part.
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    /// Name: "wing", the flap's name, the spar's name, or "torque-tube".
    pub name: String,
    /// Kind.
    pub kind: PartKind,
    /// Closed, outward-oriented mesh, aircraft frame (m).
    pub mesh: TriMesh,
}

/// A validated wing with its flaps, spars and torque tube.
#[derive(Debug, Clone)]
pub struct WingModel {
    wing: Wing,
    flaps: Vec<Flap>,
    spars: Vec<SparSpec>,
    torque_tube: Option<TorqueTubeSpec>,
}

impl WingModel {
    /// Validates everything: the wing, each flap (inside the span, no overlaps), each spar
    /// (inside the span, ahead of every flap cove it meets) and the torque-tube path.
    pub fn try_new(wing: WingSpec, flaps: Vec<FlapSpec>, spars: Vec<SparSpec>, torque_tube: Option<TorqueTubeSpec>) -> Result<WingModel> {
        let wing = Wing::try_new(wing)?;
        let mut flaps = flaps.into_iter().map(|f| Flap::try_new(f, &wing)).collect::<Result<Vec<_>>>()?;
        flaps.sort_by(|a, b| a.spec().y_inboard_m.total_cmp(&b.spec().y_inboard_m));
        for w in flaps.windows(2) {
            let (a, b) = (w[0].spec(), w[1].spec());
            if b.y_inboard_m < a.y_outboard_m {
                return Err(Error::FlapSpanConflict { flap: b.name.clone(), other: a.name.clone(), y_inboard_m: b.y_inboard_m, y_outboard_m: b.y_outboard_m });
            }
        }
        for spar in &spars {
            spar.validate()?;
            wing.locate(spar.y_start_m, &format!("spar {:?} start", spar.name))?;
            wing.locate(spar.y_end_m, &format!("spar {:?} end", spar.name))?;
            for flap in &flaps {
                let f = flap.spec();
                let (a, b) = (spar.y_start_m.max(f.y_inboard_m), spar.y_end_m.min(f.y_outboard_m));
                if a > b {
                    continue;
                }
                for y in [a, b] {
                    let (_, chord, _) = wing.planform_at(y)?;
                    let cove = 1.0 - flap.chord_fraction_at(y) - COVE_GAP_CHORD_FRACTION;
                    if spar.chord_fraction + 0.5 * spar.thickness_m / chord >= cove {
                        return Err(Error::SparBehindFlap { spar: spar.name.clone(), chord_fraction: spar.chord_fraction, flap: f.name.clone(), cove_chord_fraction: cove });
                    }
                }
            }
        }
        if let Some(tube) = &torque_tube {
            tube.validate()?;
        }
        Ok(WingModel { wing, flaps, spars, torque_tube })
    }

    /// The wing.
    pub fn wing(&self) -> &Wing {
        &self.wing
    }

    /// The flaps, ordered inboard to outboard.
    pub fn flaps(&self) -> &[Flap] {
        &self.flaps
    }

    /// The spars.
    pub fn spars(&self) -> &[SparSpec] {
        &self.spars
    }

    /// The torque tube, if any.
    pub fn torque_tube(&self) -> Option<&TorqueTubeSpec> {
        self.torque_tube.as_ref()
    }

    /// Meshes every part: "wing" (skin), each flap (stowed), each spar, "torque-tube".
    /// Each mesh is checked watertight before it is returned.
    pub fn compute_parts(&self, resolution: MeshResolution) -> Result<Vec<Part>> {
        if resolution.points_per_side < MIN_POINTS_PER_SIDE || resolution.tube_segments < 3 {
            return Err(Error::TooFewPoints { what: "mesh resolution", count: resolution.points_per_side.min(resolution.tube_segments), minimum: 3 });
        }
        require_range("spanwise_stations_per_m", resolution.spanwise_stations_per_m, 1e-9, 1e9)?;
        let mesher = Mesher::new(self, resolution)?;
        let mut parts = vec![Part { name: "wing".to_owned(), kind: PartKind::WingSkin, mesh: mesher.wing_skin()? }];
        for flap in &self.flaps {
            parts.push(Part { name: flap.spec().name.clone(), kind: PartKind::Flap, mesh: mesher.flap(flap)? });
        }
        for spar in &self.spars {
            let stations = mesher.stations(spar.y_start_m, spar.y_end_m);
            let rings = stations
                .iter()
                .map(|&y| {
                    let section = mesher.section(y)?;
                    Ok(mesher.to_ac(&section, &spar.outline(&section.airfoil, section.chord_m)?))
                })
                .collect::<Result<Vec<_>>>()?;
            parts.push(Part { name: spar.name.clone(), kind: PartKind::Spar, mesh: loft_closed(&rings, "spar")? });
        }
        if let Some(tube) = &self.torque_tube {
            let mesh = loft_closed(&tube.rings(resolution.tube_segments)?, "torque tube")?;
            parts.push(Part { name: "torque-tube".to_owned(), kind: PartKind::TorqueTube, mesh });
        }
        for part in &parts {
            let check = part.mesh.compute_topology_check();
            if !check.is_watertight() || !(part.mesh.compute_signed_volume() > 0.0) {
                return Err(Error::MeshNotWatertight {
                    part: part.name.clone(),
                    boundary: check.boundary_edges,
                    non_manifold: check.non_manifold_edges,
                    misoriented: check.misoriented_edges,
                    degenerate: check.degenerate_triangles,
                });
            }
        }
        Ok(parts)
    }
}

/// Meshing context: section airfoils resampled once.
struct Mesher<'a> {
    model: &'a WingModel,
    resolution: MeshResolution,
    airfoils: Vec<Airfoil>,
}

impl<'a> Mesher<'a> {
    fn new(model: &'a WingModel, resolution: MeshResolution) -> Result<Self> {
        let airfoils = model.wing.spec().sections.iter().map(|s| s.airfoil.resampled(resolution.points_per_side)).collect::<Result<_>>()?;
        Ok(Self { model, resolution, airfoils })
    }

    fn section(&self, y_m: f64) -> Result<SectionAt> {
        let (k, t) = self.model.wing.locate(y_m, "mesh station")?;
        let (leading_edge_ac, chord_m, twist_rad) = self.model.wing.planform_at(y_m)?;
        let airfoil = Airfoil::blended(&self.airfoils[k], &self.airfoils[k + 1], t)?;
        Ok(SectionAt { leading_edge_ac, chord_m, twist_rad, airfoil })
    }

    fn to_ac(&self, section: &SectionAt, outline: &[Point2<f64>]) -> Vec<Point3<f64>> {
        outline.iter().map(|p| self.model.wing.section_point_ac(section, *p)).collect()
    }

    /// Stations from `a` to `b`: both ends, every wing section between, and subdivisions.
    fn stations(&self, a: f64, b: f64) -> Vec<f64> {
        let mut breaks = vec![a];
        breaks.extend(self.model.wing.spec().sections.iter().map(|s| s.y_m).filter(|&y| y > a && y < b));
        breaks.push(b);
        let mut stations = vec![a];
        for w in breaks.windows(2) {
            let count = ((w[1] - w[0]) * self.resolution.spanwise_stations_per_m).ceil().max(1.0) as usize;
            stations.extend((1..=count).map(|i| if i == count { w[1] } else { w[0] + (w[1] - w[0]) * i as f64 / count as f64 }));
        }
        stations
    }

    fn wing_skin(&self) -> Result<TriMesh> {
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
                    Some(flap) => {
                        let flap_outline = flap.stowed_outline(y, &section.airfoil, self.resolution.points_per_side)?;
                        truncated_outline(&section.airfoil, cove_chord_fraction(&flap_outline), self.resolution.points_per_side)?
                    }
                };
                outlines.push(outline);
                sections.push(section);
            }
            let outlines = if flap.is_none() { consistent_trailing_edges(outlines) } else { outlines };
            let rings: Vec<_> = sections.iter().zip(&outlines).map(|(s, o)| self.to_ac(s, o)).collect();
            mesh.append(&loft_closed(&rings, "wing skin")?);
        }
        Ok(mesh)
    }

    fn flap(&self, flap: &Flap) -> Result<TriMesh> {
        let (a, b) = flap.body_span_m(&self.model.wing)?;
        let stations = self.stations(a, b);
        let mut sections = Vec::with_capacity(stations.len());
        let mut outlines = Vec::with_capacity(stations.len());
        for &y in &stations {
            let section = self.section(y)?;
            outlines.push(flap.stowed_outline(y, &section.airfoil, self.resolution.points_per_side)?);
            sections.push(section);
        }
        let rings: Vec<_> = sections.iter().zip(&consistent_trailing_edges(outlines)).map(|(s, o)| self.to_ac(s, o)).collect();
        loft_closed(&rings, "flap")
    }
}

/// Wing outline cut at chord fraction `cove_u` with a straight cove wall: upper side from
/// the wall to the leading edge, lower side back to the wall, `2 n - 1` points.
fn truncated_outline(airfoil: &Airfoil, cove_u: f64, points_per_side: usize) -> Result<Vec<Point2<f64>>> {
    let upper = airfoil.surface_line(Surface::Upper);
    let lower = airfoil.surface_line(Surface::Lower);
    let bad = || Error::BadAirfoil { name: airfoil.name.clone(), reason: "flap cove wall lies outside the wing section" };
    let s_upper = upper.arc_at_x(cove_u).ok_or_else(bad)?;
    let s_lower = lower.arc_at_x(cove_u).ok_or_else(bad)?;
    let mut outline: Vec<Point2<f64>> = upper.sample_cosine(0.0, s_upper, points_per_side).into_iter().rev().collect();
    outline.extend(lower.sample_cosine(0.0, s_lower, points_per_side).into_iter().skip(1));
    Ok(outline)
}

/// Makes the trailing edges of a set of outlines (first point = upper TE, last = lower TE)
/// agree: all sharp -> the repeated last point is dropped; all open -> kept; mixed -> the
/// sharp ones are opened by [`MIN_TRAILING_EDGE_GAP_CHORD_FRACTION`].
fn consistent_trailing_edges(mut outlines: Vec<Vec<Point2<f64>>>) -> Vec<Vec<Point2<f64>>> {
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
