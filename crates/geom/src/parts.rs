//! The whole wing model (wing, flaps, spars, torque tube) and its part meshes.
//!
//! Wing skin: one closed shell per spanwise interval: plain intervals carry the full
//! section, flap intervals the section cut at the cove wall. Shells of neighbouring
//! intervals touch along their common cap plane (y = const) but share no vertices, so each
//! shell is watertight on its own and the part's volume is their sum. Each flap body is
//! one closed shell, narrower than its cut-out by the side gaps, so a stowed flap keeps a
//! clearance to the wing everywhere.

use nalgebra::Point3;

use crate::airfoil::MIN_POINTS_PER_SIDE;
use crate::error::{require_range, Error, Result};
use crate::flap::{Flap, FlapSpec, COVE_GAP_CHORD_FRACTION};
use crate::loft::loft_closed;
use crate::mesh::TriMesh;
pub use crate::mesher::MIN_TRAILING_EDGE_GAP_CHORD_FRACTION;
use crate::mesher::{consistent_trailing_edges, Mesher};
use crate::structure::{SparSpec, TorqueTubeSpec};
use crate::wing::{Wing, WingSpec};

/// Mesh fineness.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshResolution {
    /// Airfoil points per side (leading edge shared), cosine spaced; >= 3.
    pub points_per_side: usize,
    /// Spanwise stations per metre of span, in addition to every section and flap end; > 0.
    /// The torque tube gets rings at the same spacing along its path.
    pub spanwise_stations_per_m: f64,
    /// Points round the torque tube; >= 3.
    pub tube_segments: usize,
}

impl Default for MeshResolution {
    /// 60 points per side, 4 stations per metre, 24 tube segments.
    fn default() -> Self {
        Self {
            points_per_side: 60,
            spanwise_stations_per_m: 4.0,
            tube_segments: 24,
        }
    }
}

/// Kind of a part.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PartKind {
    /// Main wing skin (a shell: surface queries are right for it).
    WingSkin,
    /// A flap body (stowed): a two-element flap's main element.
    Flap,
    /// The aft element of a two-element flap (stowed), named `<flap>-aft`
    /// ([`aft_element_name`]).
    AftElement,
    /// A spar plate (solid).
    Spar,
    /// The torque tube (solid).
    TorqueTube,
}

/// The part name of the aft element of the flap called `flap`.
pub fn aft_element_name(flap: &str) -> String {
    format!("{flap}{AFT_ELEMENT_SUFFIX}")
}

/// What [`aft_element_name`] appends to the flap's name.
const AFT_ELEMENT_SUFFIX: &str = "-aft";

impl Part {
    /// The flap this part is an element of, and whether it is the aft element: the flap's
    /// own name for a [`PartKind::Flap`], the name [`aft_element_name`] was given for a
    /// [`PartKind::AftElement`]; None for the wing's structure.
    pub fn flap_element(&self) -> Option<(&str, bool)> {
        match self.kind {
            PartKind::Flap => Some((self.name.as_str(), false)),
            PartKind::AftElement => self.name.strip_suffix(AFT_ELEMENT_SUFFIX).map(|flap| (flap, true)),
            PartKind::WingSkin | PartKind::Spar | PartKind::TorqueTube => None,
        }
    }
}

/// One meshed part.
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    /// Name: "wing", the flap's name, its aft element's ([`aft_element_name`]), the spar's
    /// name, or "torque-tube".
    pub name: String,
    /// Kind.
    pub kind: PartKind,
    /// Closed, outward-oriented mesh, aircraft frame (m).
    pub mesh: TriMesh,
}

/// A validated wing with its flaps, spars and torque tube.
#[derive(Debug, Clone)]
pub struct WingModel {
    pub(crate) wing: Wing,
    pub(crate) flaps: Vec<Flap>,
    spars: Vec<SparSpec>,
    torque_tube: Option<TorqueTubeSpec>,
}

/// Two models are equal when they were built from equal specifications (a model is
/// determined by them): what lets designs of the same wing share its meshes.
impl PartialEq for WingModel {
    fn eq(&self, other: &Self) -> bool {
        self.wing.spec() == other.wing.spec()
            && self.flaps.len() == other.flaps.len()
            && self.flaps.iter().zip(&other.flaps).all(|(a, b)| a.spec() == b.spec())
            && self.spars == other.spars
            && self.torque_tube == other.torque_tube
    }
}

impl WingModel {
    /// Validates everything: the wing, each flap (inside the span, no overlaps), each spar
    /// (inside the span, ahead of every flap cove it meets) and the torque-tube path.
    pub fn try_new(
        wing: WingSpec,
        flaps: Vec<FlapSpec>,
        spars: Vec<SparSpec>,
        torque_tube: Option<TorqueTubeSpec>,
    ) -> Result<WingModel> {
        let wing = Wing::try_new(wing)?;
        let mut flaps = flaps
            .into_iter()
            .map(|f| Flap::try_new(f, &wing))
            .collect::<Result<Vec<_>>>()?;
        flaps.sort_by(|a, b| a.spec().y_inboard_m.total_cmp(&b.spec().y_inboard_m));
        for w in flaps.windows(2) {
            let (a, b) = (w[0].spec(), w[1].spec());
            if b.y_inboard_m < a.y_outboard_m {
                return Err(Error::FlapSpanConflict {
                    flap: b.name.clone(),
                    other: a.name.clone(),
                    y_inboard_m: b.y_inboard_m,
                    y_outboard_m: b.y_outboard_m,
                });
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
                        return Err(Error::SparBehindFlap {
                            spar: spar.name.clone(),
                            chord_fraction: spar.chord_fraction,
                            flap: f.name.clone(),
                            cove_chord_fraction: cove,
                        });
                    }
                }
            }
        }
        if let Some(tube) = &torque_tube {
            tube.validate()?;
        }
        Ok(WingModel {
            wing,
            flaps,
            spars,
            torque_tube,
        })
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
            return Err(Error::TooFewPoints {
                what: "mesh resolution",
                count: resolution.points_per_side.min(resolution.tube_segments),
                minimum: 3,
            });
        }
        require_range("spanwise_stations_per_m", resolution.spanwise_stations_per_m, 1e-9, 1e9)?;
        let mesher = Mesher::new(self, resolution)?;
        let mut parts = vec![Part {
            name: "wing".to_owned(),
            kind: PartKind::WingSkin,
            mesh: mesher.wing_skin()?,
        }];
        for flap in &self.flaps {
            let (main, aft) = mesher.flap(flap)?;
            parts.push(Part {
                name: flap.spec().name.clone(),
                kind: PartKind::Flap,
                mesh: main,
            });
            if let Some(mesh) = aft {
                parts.push(Part {
                    name: aft_element_name(&flap.spec().name),
                    kind: PartKind::AftElement,
                    mesh,
                });
            }
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
            parts.push(Part {
                name: spar.name.clone(),
                kind: PartKind::Spar,
                mesh: loft_closed(&rings, "spar")?,
            });
        }
        if let Some(tube) = &self.torque_tube {
            let spacing_m = 1.0 / resolution.spanwise_stations_per_m;
            let mesh = loft_closed(&tube.rings(resolution.tube_segments, spacing_m)?, "torque tube")?;
            parts.push(Part {
                name: "torque-tube".to_owned(),
                kind: PartKind::TorqueTube,
                mesh,
            });
        }
        for part in &parts {
            let check = part.mesh.compute_topology_check();
            if !check.is_watertight()
                || part.mesh.compute_signed_volume().partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater)
            {
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

/// One part's outline in a streamwise cut (plane y = const), aircraft frame (m): a closed
/// polygon (last point joins the first).
#[derive(Debug, Clone, PartialEq)]
pub struct SectionOutline {
    /// Part name (as in [`Part::name`]).
    pub name: String,
    /// Part kind.
    pub kind: PartKind,
    /// Polygon vertices, aircraft frame (m).
    pub points_ac: Vec<Point3<f64>>,
}

impl WingModel {
    /// Outlines of the wing skin, each stowed flap (and aft element) and each spar cut by the plane y = `y_m`
    /// (the torque tube is not included), with `points_per_side` airfoil points per side:
    /// the same polygons the meshes are lofted through at that station.
    pub fn compute_section_outlines(&self, y_m: f64, points_per_side: usize) -> Result<Vec<SectionOutline>> {
        let resolution = MeshResolution {
            points_per_side,
            ..MeshResolution::default()
        };
        if points_per_side < MIN_POINTS_PER_SIDE {
            return Err(Error::TooFewPoints {
                what: "airfoil points per side",
                count: points_per_side,
                minimum: MIN_POINTS_PER_SIDE,
            });
        }
        let mesher = Mesher::new(self, resolution)?;
        let section = mesher.section(y_m)?;
        let cut_by = self
            .flaps
            .iter()
            .find(|f| y_m >= f.spec().y_inboard_m && y_m <= f.spec().y_outboard_m);
        let wing_outline = match cut_by {
            Some(flap) => crate::flap::cut_wing_outline(flap, y_m, &section.airfoil, points_per_side)?,
            None => consistent_trailing_edges(vec![section.airfoil.points.clone()]).remove(0),
        };
        let mut outlines = vec![SectionOutline {
            name: "wing".to_owned(),
            kind: PartKind::WingSkin,
            points_ac: mesher.to_ac(&section, &wing_outline),
        }];
        for flap in &self.flaps {
            let (a, b) = flap.body_span_m(&self.wing)?;
            if y_m >= a && y_m <= b {
                let elements = flap.element_outlines(y_m, &section.airfoil, points_per_side)?;
                let main = consistent_trailing_edges(vec![elements.main]).remove(0);
                outlines.push(SectionOutline {
                    name: flap.spec().name.clone(),
                    kind: PartKind::Flap,
                    points_ac: mesher.to_ac(&section, &main),
                });
                if let Some(aft) = elements.aft {
                    let aft = consistent_trailing_edges(vec![aft]).remove(0);
                    outlines.push(SectionOutline {
                        name: aft_element_name(&flap.spec().name),
                        kind: PartKind::AftElement,
                        points_ac: mesher.to_ac(&section, &aft),
                    });
                }
            }
        }
        for spar in &self.spars {
            if y_m >= spar.y_start_m && y_m <= spar.y_end_m {
                let outline = spar.outline(&section.airfoil, section.chord_m)?;
                outlines.push(SectionOutline {
                    name: spar.name.clone(),
                    kind: PartKind::Spar,
                    points_ac: mesher.to_ac(&section, &outline),
                });
            }
        }
        Ok(outlines)
    }
}
