//! Geometry stages: scene -> `flapwright_geom` model -> meshes -> STL files.

use flapwright_geom::flap::{AftElementSpec, FlapSectionSpec, FlapSpec, HingeSpec};
use flapwright_geom::parts::{MeshResolution, Part, PartKind, WingModel};
use flapwright_geom::structure::{SparSpec, TorqueTubeSpec};
use flapwright_geom::wing::{PanelSpec, SweepReference, WingSectionSpec, WingSpec};
use nalgebra::Point3;

use crate::error::{Error, Result};
use crate::report::PartReport;
use crate::scene::{FileSource, ResolutionScene, Scene, SweepReferenceScene, WingScene};
use crate::sink::Sink;

fn point(p: [f64; 3]) -> Point3<f64> {
    Point3::new(p[0], p[1], p[2])
}

/// Builds the 3D wing model (wing, flaps, spars, torque tube) from a validated scene.
pub fn build_model(scene: &Scene, wing: &WingScene, files: &dyn FileSource) -> Result<WingModel> {
    let pps = scene.resolution.airfoil_points_per_side;
    let sections = wing
        .sections
        .iter()
        .enumerate()
        .map(|(i, s)| {
            Ok(WingSectionSpec {
                y_m: s.y_m,
                chord_m: s.chord_m,
                twist_deg: s.twist_deg,
                airfoil: crate::scene::load_airfoil(&s.airfoil, files, pps).map_err(|source| Error::SceneAirfoil {
                    key: format!("wing.sections[{i}].airfoil"),
                    source: Box::new(source),
                })?,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let wing_spec = WingSpec {
        root_leading_edge_ac: point(wing.root_leading_edge_m),
        sections,
        panels: wing
            .panels
            .iter()
            .map(|p| PanelSpec {
                sweep_deg: p.sweep_deg,
                dihedral_deg: p.dihedral_deg,
            })
            .collect(),
        sweep_reference: match wing.sweep_reference {
            SweepReferenceScene::LeadingEdge => SweepReference::LeadingEdge,
            SweepReferenceScene::QuarterChord => SweepReference::QuarterChord,
        },
        twist_axis_chord_fraction: wing.twist_axis_chord_fraction,
    };
    let flaps = scene
        .flap
        .iter()
        .enumerate()
        .map(|(i, f)| {
            let hinge = match (
                f.hinge.inboard_point_m,
                f.hinge.outboard_point_m,
                f.hinge.chord_fraction,
            ) {
                (Some(a), Some(b), _) => HingeSpec::Points {
                    inboard_ac: point(a),
                    outboard_ac: point(b),
                },
                (_, _, Some(fraction)) => HingeSpec::ChordFraction {
                    chord_fraction: fraction,
                    depth_below_chord_fraction: f.hinge.depth_below_chord_fraction.unwrap_or(0.0),
                },
                _ => {
                    return Err(Error::Unvalidated {
                        key: format!("flap[{i}].hinge"),
                        problem: "incomplete",
                    })
                }
            };
            let section = match &f.airfoil {
                None => FlapSectionSpec::CutOut,
                Some(text) => FlapSectionSpec::OwnSection {
                    airfoil: crate::scene::load_airfoil(text, files, pps).map_err(|source| Error::SceneAirfoil {
                        key: format!("flap[{i}].airfoil"),
                        source: Box::new(source),
                    })?,
                },
            };
            let aft_element = match &f.aft_element {
                None => None,
                Some(aft) => Some(AftElementSpec {
                    airfoil: crate::scene::load_airfoil(&aft.airfoil, files, pps).map_err(|source| {
                        Error::SceneAirfoil {
                            key: format!("flap[{i}].aft_element.airfoil"),
                            source: Box::new(source),
                        }
                    })?,
                    chord_fraction: aft.chord_fraction,
                    shroud_chord_fraction: aft.shroud_chord_fraction.unwrap_or(0.0),
                }),
            };
            Ok(FlapSpec {
                aft_element,
                name: f.name.clone(),
                y_inboard_m: f.y_inboard_m,
                y_outboard_m: f.y_outboard_m,
                chord_fraction_inboard: f.chord_fraction_inboard,
                chord_fraction_outboard: f.chord_fraction_outboard,
                hinge,
                section,
                side_gap_m: f.side_gap_m,
                shroud_chord_fraction: f.shroud_chord_fraction.unwrap_or(0.0),
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let spars = scene
        .structure
        .spars
        .iter()
        .map(|s| SparSpec {
            name: s.name.clone(),
            chord_fraction: s.chord_fraction,
            thickness_m: s.thickness_m,
            y_start_m: s.y_start_m,
            y_end_m: s.y_end_m,
        })
        .collect();
    let torque_tube = match &scene.structure.torque_tube {
        None => None,
        Some(t) => Some(TorqueTubeSpec {
            path_ac: match (&t.path_m, t.chord_fraction) {
                (Some(points), _) => points.iter().copied().map(point).collect(),
                (None, Some(fraction)) => tube_path_on_the_wing(scene, wing, &wing_spec, t, fraction)?,
                (None, None) => {
                    return Err(Error::Unvalidated {
                        key: "structure.torque_tube".into(),
                        problem: "no axis",
                    })
                }
            },
            radius_m: t.radius_m,
        }),
    };
    WingModel::try_new(wing_spec, flaps, spars, torque_tube).map_err(Error::BuildingWingModel)
}

/// The torque tube's axis through chord fraction `fraction` (and its depth below the chord
/// line) of the wing's sections, from its start to its end and at every section between:
/// straight segments between the sections follow the wing's panels, so a change of sweep,
/// dihedral or twist carries the tube along.
/// The shortest tube segment, m (the scene's `MIN_LENGTH_M`).
const MIN_LENGTH_M: f64 = crate::scene::limits::MIN_LENGTH_M;

fn tube_path_on_the_wing(
    scene: &Scene,
    wing: &WingScene,
    wing_spec: &WingSpec,
    tube: &crate::scene::TorqueTubeScene,
    fraction: f64,
) -> Result<Vec<Point3<f64>>> {
    let model = flapwright_geom::wing::Wing::try_new(wing_spec.clone()).map_err(Error::BuildingWing)?;
    let start = tube.y_start_m.unwrap_or(wing.sections[0].y_m);
    let end = tube
        .y_end_m
        .unwrap_or_else(|| crate::scene::default_tube_end(scene, wing));
    let depth = tube.depth_below_chord_fraction.unwrap_or(0.0);
    // Sections closer to an end than the shortest segment would give a sliver the tube's
    // mesher rejects: the end stands for them.
    let inside = |y: f64| y > start + MIN_LENGTH_M && y < end - MIN_LENGTH_M;
    let ys = std::iter::once(start)
        .chain(wing.sections.iter().map(|s| s.y_m).filter(|&y| inside(y)))
        .chain(std::iter::once(end));
    ys.map(|y| {
        let section = model.section_at(y)?;
        Ok(model.section_point_ac(&section, nalgebra::Point2::new(fraction, -depth)))
    })
    .collect::<flapwright_geom::Result<Vec<_>>>()
    .map_err(Error::PlacingTorqueTube)
}

/// Meshes every part once.
pub fn mesh_parts(model: &WingModel, resolution: &ResolutionScene) -> Result<Vec<Part>> {
    let resolution = MeshResolution {
        points_per_side: resolution.airfoil_points_per_side,
        ..MeshResolution::default()
    };
    model.compute_parts(resolution).map_err(Error::MeshingParts)
}

/// Writes one binary STL per part (when asked) and returns the parts' report entries.
pub fn write_parts(parts: &[Part], write_stl: bool, out: &dyn Sink) -> Result<Vec<PartReport>> {
    parts
        .iter()
        .map(|part| {
            let stl_file = if write_stl {
                Some(write_stl_file(&part.mesh, &part.name, out)?)
            } else {
                None
            };
            Ok(PartReport {
                stl_file,
                ..part_report(part)
            })
        })
        .collect()
}

/// The parts' report entries without files.
pub fn part_statistics(parts: &[Part]) -> Vec<PartReport> {
    parts.iter().map(part_report).collect()
}

fn part_report(part: &Part) -> PartReport {
    let check = part.mesh.compute_topology_check();
    let bounds = part.mesh.compute_aabb();
    PartReport {
        name: part.name.clone(),
        kind: kind_name(part.kind).to_string(),
        vertices: part.mesh.vertices.len(),
        triangles: part.mesh.triangles.len(),
        volume_m3: part.mesh.compute_signed_volume(),
        bounds_m: bounds.map_or([[0.0; 3]; 2], |b| [b.min.coords.into(), b.max.coords.into()]),
        watertight: check.is_watertight(),
        stl_file: None,
    }
}

/// Writes `mesh` as the binary STL `<name>.stl` (the solid named `name`); returns the
/// file name.
pub(crate) fn write_stl_file(mesh: &flapwright_geom::TriMesh, name: &str, out: &dyn Sink) -> Result<String> {
    let file_name = format!("{name}.stl");
    let mut bytes = Vec::new();
    flapwright_geom::io::stl::write_binary(mesh, name, &mut bytes).map_err(|source| Error::EncodingStl {
        file: file_name.clone(),
        source,
    })?;
    out.write(&file_name, &bytes).map_err(|source| Error::Write {
        file: file_name.clone(),
        source,
    })?;
    Ok(file_name)
}

/// The report's name for a part kind (stable: tools match on it).
fn kind_name(kind: PartKind) -> &'static str {
    match kind {
        PartKind::WingSkin => "wing-skin",
        PartKind::Flap => "flap",
        PartKind::AftElement => "flap-aft-element",
        PartKind::Spar => "spar",
        PartKind::TorqueTube => "torque-tube",
    }
}
