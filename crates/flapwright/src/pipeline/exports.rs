//! Exports for viewers and people: URDF + trajectory (mechanism crate's `urdf` module),
//! SVG drawings and plots per station (drawing crate).

use flapwright_drawing::{
    convex_hull, render_plots_svg, render_station_svg, Clash, Dimension, Joint, Link, MechanismSnapshot, PartStyle,
    SectionOutline, SlotArc, StationDrawing,
};
use flapwright_geom::CollisionShape;
use flapwright_interference::{FairingDepth, InterferenceReport};
use flapwright_mechanism::seam::BodyRole;
use flapwright_mechanism::FlapMechanism;
use flapwright_urdf::{
    build_robot, to_xml, trajectory, AftElementLink, BaseLink, BodyGeometry, MeshRef, RigidInertia, StationMechanism3d,
};
use nalgebra::Point2;

use crate::error::{Error, Result};
use crate::pipeline::mechanism_parts::MechanismSolid;
use crate::pipeline::plots::{station_plots, SettingTarget};
use crate::pipeline::record::StationRecord;
use crate::report::PartReport;
use crate::report::UrdfExport;
use crate::scene::Scene;
use crate::sink::Sink;

/// Writes `<scene>.urdf` and `trajectory.json`; meshes are the part STL files beside them
/// (`solids`: the mechanism's, with their mass properties; `meshed`: the wing's, for the
/// flap's inertia).
pub fn write_urdf(
    scene: &Scene,
    parts: &[PartReport],
    meshed: &[flapwright_geom::parts::Part],
    solids: &[MechanismSolid],
    records: &[StationRecord],
    out: &dyn Sink,
) -> Result<UrdfExport> {
    let flap_names: Vec<String> = scene.flap.iter().flat_map(|f| f.part_names()).collect();
    let mesh = |p: &PartReport| {
        p.stl_file.clone().map(|filename| MeshRef {
            name: p.name.clone(),
            filename,
        })
    };
    let base = BaseLink {
        name: "wing_structure".into(),
        meshes: parts
            .iter()
            .filter(|p| !flap_names.contains(&p.name))
            .filter_map(mesh)
            .collect(),
    };
    let mut owner_seen = Vec::new();
    let stations: Vec<StationMechanism3d> = records
        .iter()
        .map(|record| {
            let place = record.placed.as_ref().ok_or_else(|| Error::StationNotPlaced {
                station: record.station.clone(),
            })?;
            let flap_name = record.flap.clone().unwrap_or_default();
            let owns_flap = !owner_seen.contains(&flap_name);
            owner_seen.push(flap_name.clone());
            let (flap_inertia, aft_inertia) = if owns_flap {
                flap_inertia(scene, meshed, records, &flap_name)?
            } else {
                (None, None)
            };
            Ok(StationMechanism3d {
                name: record.station.clone(),
                aircraft_from_station: *place.station.frame.aircraft_from_station(),
                mechanism: record.mechanism.as_ref(),
                flap_mesh: if owns_flap {
                    parts
                        .iter()
                        .find(|p| p.name == flap_name)
                        .and_then(|p| p.stl_file.clone())
                } else {
                    None
                },
                aft_element: if owns_flap {
                    let aft = flapwright_geom::parts::aft_element_name(&flap_name);
                    parts.iter().find(|p| p.name == aft).and_then(|p| {
                        p.stl_file.clone().map(|filename| AftElementLink {
                            mesh: MeshRef {
                                name: aft.clone(),
                                filename,
                            },
                            inertia: aft_inertia,
                        })
                    })
                } else {
                    None
                },
                flap_name,
                owns_flap,
                flap_inertia,
                bodies: body_geometry(record, solids),
                // The kinematics' peak over the load cases, where the stage ran (not in
                // `export` alone: efforts 0 there).
                actuator_peak_load: record.kinematics.as_ref().and_then(|k| {
                    k.load_cases
                        .iter()
                        .flat_map(|case| &case.samples)
                        .map(|sample| sample.actuator_load.abs())
                        .filter(|load| load.is_finite())
                        .reduce(f64::max)
                }),
            })
        })
        .collect::<Result<_>>()?;
    let robot_name = scene
        .name
        .replace(|c: char| !c.is_ascii_alphanumeric() && c != '_', "_");
    let model = build_robot(&robot_name, &base, &stations)?;
    let file = format!("{}.urdf", scene.name);
    out.write(&file, to_xml(&model)?.as_bytes())
        .map_err(|source| Error::Write {
            file: file.clone(),
            source,
        })?;
    // The report's deployment samples, so each trajectory sample is a report sample.
    let trajectory = trajectory(&stations, scene.resolution.deployment_samples)?;
    let trajectory_file = "trajectory.json".to_string();
    out.write(
        &trajectory_file,
        (serde_json::to_string_pretty(&trajectory)? + "\n").as_bytes(),
    )
    .map_err(|source| Error::Write {
        file: trajectory_file.clone(),
        source,
    })?;
    Ok(UrdfExport {
        file,
        trajectory_file,
        cut_joints: model.cut_joints,
    })
}

/// Each body's solids of `record`'s station as URDF link geometry: the STL files and the
/// solids' mass properties combined.
fn body_geometry(record: &StationRecord, solids: &[MechanismSolid]) -> Vec<BodyGeometry> {
    let mut bodies: Vec<BodyGeometry> = Vec::new();
    let mut inertias: Vec<Vec<RigidInertia>> = Vec::new();
    for solid in solids.iter().filter(|s| s.station == record.station) {
        let index = match bodies.iter().position(|b| b.body == solid.body) {
            Some(index) => index,
            None => {
                bodies.push(BodyGeometry {
                    body: solid.body,
                    meshes: Vec::new(),
                    inertia: None,
                });
                inertias.push(Vec::new());
                bodies.len() - 1
            }
        };
        bodies[index].meshes.push(MeshRef {
            // URDF names take no dots.
            name: solid.name.replace('.', "_"),
            filename: crate::pipeline::mechanism_parts::stl_name(&solid.name),
        });
        inertias[index].push(solid.inertia);
    }
    for (body, parts) in bodies.iter_mut().zip(&inertias) {
        body.inertia = RigidInertia::combined(parts);
    }
    bodies
}

/// The flap's mass properties: the sum of `flap_mass_kg` over the stations that carry it,
/// spread uniformly through its closed mesh (stowed, aircraft frame); `None` for a flap
/// without mass.
/// The mass properties of a flap's elements (main, aft), from the masses its stations
/// carry spread uniformly through each element's mesh: the kinds' aft-element shares on
/// the aft element, the rest on the main one; where no kind gives a share, the whole mass
/// through both alike.
fn flap_inertia(
    scene: &Scene,
    meshed: &[flapwright_geom::parts::Part],
    records: &[StationRecord],
    flap: &str,
) -> Result<(Option<RigidInertia>, Option<RigidInertia>)> {
    let kinds = || {
        records
            .iter()
            .filter(|r| r.flap.as_deref() == Some(flap))
            .map(|r| scene.station[r.index].mechanism.kind())
    };
    let mass_kg: f64 = kinds().map(|k| k.flap_mass_kg()).sum();
    let aft_share_kg: f64 = kinds().map(|k| k.aft_element_mass_kg()).sum();
    // Each element's mass properties at density 1 (the mass is then the volume).
    let unit = |name: &str| -> Result<Option<flapwright_geom::MassProperties>> {
        let Some(part) = meshed.iter().find(|p| p.name == name) else {
            return Ok(None);
        };
        let shape = CollisionShape::from_mesh(&part.mesh).map_err(|source| Error::FlapMesh {
            part: name.to_string(),
            source,
        })?;
        Ok(shape.compute_mass_properties(1.0).filter(|u| u.mass_kg > 0.0))
    };
    let scaled = |unit: Option<flapwright_geom::MassProperties>, mass_kg: f64| {
        unit.filter(|_| mass_kg > 0.0).map(|u| RigidInertia {
            mass_kg,
            centre_of_mass_ac_m: u.centre_of_mass,
            inertia_ac_kg_m2: u.inertia_kg_m2 * (mass_kg / u.mass_kg),
        })
    };
    let main = unit(flap)?;
    let aft = unit(&flapwright_geom::parts::aft_element_name(flap))?;
    Ok(match (main, aft) {
        (main, None) => (scaled(main, mass_kg), None),
        (Some(m), Some(a)) if aft_share_kg <= 0.0 => {
            let volume = m.mass_kg + a.mass_kg;
            (
                scaled(Some(m), mass_kg * m.mass_kg / volume),
                scaled(Some(a), mass_kg * a.mass_kg / volume),
            )
        }
        (main, aft) => (scaled(main, mass_kg - aft_share_kg), scaled(aft, aft_share_kg)),
    })
}

fn style_of(part: &str, flap_names: &[String]) -> PartStyle {
    if part == "wing" {
        PartStyle::WingSkin
    } else if flap_names.iter().any(|f| f == part) {
        PartStyle::Flap
    } else if part.contains("spar") {
        PartStyle::Spar
    } else if part == "torque-tube" {
        PartStyle::TorqueTube
    } else {
        PartStyle::Other
    }
}

/// A station's own flap section, stowed (station frame, m): the main element's polygons
/// and the aft element's, each moved by the body that carries it.
#[derive(Default)]
struct FlapOutlines {
    main: Vec<Vec<Point2<f64>>>,
    aft: Vec<Vec<Point2<f64>>>,
}

/// The mechanism at actuator input `input`, from the seam: each moving body's solids as
/// links (skeletons), its named points as joints, the flap outline displaced with the flap.
/// The stowed snapshot also draws the fixed support structure (struts, trusses); fixed
/// tracks are drawn as their slot arcs.
fn snapshot(
    mechanism: &dyn FlapMechanism,
    label: &str,
    input: f64,
    flap_outline: &FlapOutlines,
) -> Result<MechanismSnapshot> {
    let pose = mechanism.pose(input)?;
    let aft = pose.aft_flap(flapwright_mechanism::seam::aft_flap_body(mechanism.bodies()));
    let with_supports = label == "stowed";
    let links = mechanism
        .bodies()
        .iter()
        .zip(&pose.bodies)
        .filter(|(body, _)| body.is_moving() || (with_supports && body.role == BodyRole::Support))
        .flat_map(|(body, placement)| {
            body.solids.iter().map(move |solid| Link {
                name: solid.name.clone(),
                points: solid.shape.skeleton().iter().map(|p| placement * p).collect(),
            })
        })
        .collect();
    Ok(MechanismSnapshot {
        label: label.into(),
        deflection_deg: pose.deflection_rad.to_degrees(),
        flap_outline: flap_outline
            .main
            .iter()
            .map(|polygon| polygon.iter().map(|p| pose.flap * p).collect())
            .chain(
                flap_outline
                    .aft
                    .iter()
                    .map(|polygon| polygon.iter().map(|p| aft * p).collect()),
            )
            .collect(),
        links,
        joints: pose
            .points
            .iter()
            .map(|p| Joint {
                name: p.name.to_string(),
                at: p.position,
                fixed: p.fixed,
            })
            .collect(),
    })
}

/// Writes `station-<name>.svg` and `plots-<name>.svg` per station; returns the file names.
pub fn write_svgs(
    scene: &Scene,
    records: &[StationRecord],
    interference: Option<&InterferenceReport>,
    out: &dyn Sink,
) -> Result<Vec<String>> {
    let flap_names: Vec<String> = scene.flap.iter().flat_map(|f| f.part_names()).collect();
    let mut files = Vec::new();
    for record in records {
        let mechanism = record.mechanism.as_ref();
        let notes = mechanism.drawing_notes();
        let range = mechanism.deflection_range_rad();
        let sections: Vec<SectionOutline> = record
            .placed
            .as_ref()
            .map(|p| {
                p.sections
                    .iter()
                    .map(|s| SectionOutline {
                        part: s.part_name.clone(),
                        kind: style_of(&s.part_name, &flap_names),
                        polygons: s.polygons.clone(),
                    })
                    .collect()
            })
            .unwrap_or_default();
        // Show the rear of the wing only, as the thesis figures do: up to a margin ahead of
        // the furthest-forward mechanism point or slot end, so the mechanism stays legible.
        let stowed = mechanism.pose(mechanism.input_range().stowed)?;
        // The station's own flap is shown whole: its nose lies ahead of the mechanism of a
        // kind whose pivots hang below the flap.
        let own_flap_nose = sections
            .iter()
            .filter(|s| record.flap.as_deref() == Some(s.part.as_str()))
            .flat_map(|s| s.polygons.iter().flatten())
            .map(|p| p.x);
        // Every link over the whole deployment too: a strut's top on the skin, a jack's
        // mount (the links drawn at 21 drive fractions).
        let input = mechanism.input_range();
        let mut swept = Vec::new();
        for k in 0..=20 {
            let s = snapshot(
                mechanism,
                "",
                input.at_fraction(k as f64 / 20.0),
                &FlapOutlines::default(),
            )?;
            swept.extend(s.links.into_iter().flat_map(|l| l.points));
        }
        let reach = notes
            .arcs
            .iter()
            .map(|(_, centre, radius, _, _)| centre.x + radius)
            .chain(stowed.points.iter().map(|p| p.position.x))
            .chain(swept.iter().map(|p| p.x))
            .chain(own_flap_nose)
            .fold(0.0, f64::max);
        let x_limit = reach + VIEW_MARGIN_M;
        let mut breaks = Vec::new();
        let sections: Vec<SectionOutline> = sections
            .into_iter()
            .filter_map(|mut s| {
                s.polygons = s
                    .polygons
                    .iter()
                    .map(|p| clip_x_below(p, x_limit))
                    .filter(|p| p.len() >= 3)
                    .collect();
                breaks.extend(s.polygons.iter().filter_map(|p| cut_at(p, x_limit)));
                (!s.polygons.is_empty()).then_some(s)
            })
            .collect();
        // The station's own flap moves with its mechanism (a two-element flap's aft element
        // with the body that carries it); a neighbouring flap the plane cuts stays drawn
        // where it is stowed.
        let own = |part: &str| record.flap.as_deref() == Some(part);
        let own_aft = |part: &str| {
            record
                .flap
                .as_deref()
                .is_some_and(|flap| part == flapwright_geom::parts::aft_element_name(flap))
        };
        let outline_of = |wanted: &dyn Fn(&str) -> bool| -> Vec<Vec<Point2<f64>>> {
            sections
                .iter()
                .filter(|s| matches!(s.kind, PartStyle::Flap) && wanted(&s.part))
                .flat_map(|s| s.polygons.clone())
                .collect()
        };
        let flap_outline = FlapOutlines {
            main: outline_of(&own),
            aft: outline_of(&own_aft),
        };
        // The flap's settings (validation keeps them within the rotation range); a station
        // without a flap shows the middle and the end of its range.
        let (takeoff, landing) = record
            .flap
            .as_ref()
            .and_then(|name| scene.flap.iter().find(|f| &f.name == name))
            .map_or((range / 2.0, range), |f| {
                (
                    f.settings.takeoff_deg.to_radians().min(range),
                    f.settings.landing_deg.to_radians().min(range),
                )
            });
        let settings = vec![
            snapshot(mechanism, "stowed", input.stowed, &flap_outline)?,
            snapshot(
                mechanism,
                "takeoff",
                mechanism.input_at_deflection(takeoff)?,
                &flap_outline,
            )?,
            snapshot(
                mechanism,
                "landing",
                mechanism.input_at_deflection(landing)?,
                &flap_outline,
            )?,
        ];
        let envelope = vec![convex_hull(swept)];
        let fairing_line = record.fairing.as_ref().filter(|f| f.depth_m > 0.0).map(|f| {
            let y = f.point_st[1];
            let xs = envelope[0].iter().map(|p| p.x);
            let (lo, hi) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)));
            vec![Point2::new(lo, y), Point2::new(hi, y)]
        });
        let slots = notes
            .arcs
            .iter()
            .map(|(name, centre, radius_m, start_rad, end_rad)| SlotArc {
                name: name.clone(),
                centre: *centre,
                radius_m: *radius_m,
                start_rad: *start_rad,
                end_rad: *end_rad,
            })
            .collect();
        let dimensions = notes
            .dimensions
            .iter()
            .map(|(label, from, to)| Dimension::new(label, *from, *to))
            .collect();
        let fairing_text = record
            .fairing
            .as_ref()
            .map(|f| {
                format!(
                    ", fairing depth {:.0} mm ({:.1} % flap chord), length {:.0} mm ({:.0} %)",
                    f.depth_m * 1e3,
                    f.depth_percent_flap_chord,
                    f.length_m * 1e3,
                    f.length_percent_flap_chord
                )
            })
            .unwrap_or_default();
        // The solid that sets the fairing depth, where it reaches deepest.
        let fairing_parts = match record.fairing.as_ref() {
            Some(FairingDepth {
                part: Some(part),
                at_parameter,
                ..
            }) => snapshot(
                mechanism,
                "",
                input.at_fraction(*at_parameter),
                &FlapOutlines::default(),
            )?
            .links
            .into_iter()
            .filter(|link| &link.name == part)
            .collect(),
            _ => Vec::new(),
        };
        let station_from_aircraft = record
            .placed
            .as_ref()
            .map(|p| p.station.frame.aircraft_from_station().inverse());
        let clashes = match (interference, station_from_aircraft) {
            (Some(report), Some(station_from_aircraft)) => clashes(report, &record.station, &station_from_aircraft),
            _ => Vec::new(),
        };
        let drawing = StationDrawing {
            title: format!("{}: station {}", scene.name, record.station),
            subtitle: format!("{}{fairing_text}", notes.summary),
            sections,
            settings,
            slots,
            envelope,
            fairing_line,
            dimensions,
            fairing_parts,
            clashes,
            breaks,
        };
        let name = format!("station-{}.svg", record.station);
        let svg = render_station_svg(&drawing).map_err(|source| Error::DrawingStation {
            station: record.station.clone(),
            source,
        })?;
        out.write(&name, svg.as_bytes()).map_err(|source| Error::Write {
            file: name.clone(),
            source,
        })?;
        files.push(name);
        if let Some(cases) = record.kinematics.as_ref().map(|k| k.load_cases.as_slice()) {
            let name = format!("plots-{}.svg", record.station);
            let targets = record
                .flap
                .as_ref()
                .and_then(|name| scene.flap.iter().find(|f| &f.name == name))
                .map(|f| {
                    [("takeoff", f.settings.takeoff_deg), ("landing", f.settings.landing_deg)]
                        .into_iter()
                        .filter_map(|(setting, deg)| {
                            let (gap, overlap) = f.settings.targets(setting);
                            let input = mechanism.input_at_deflection(deg.to_radians()).ok()?;
                            (gap.is_some() || overlap.is_some()).then(|| SettingTarget {
                                setting: setting.into(),
                                input,
                                gap_percent_chord: gap,
                                overlap_percent_chord: overlap,
                            })
                        })
                        .collect::<Vec<_>>()
                })
                .unwrap_or_default();
            let plots = station_plots(
                cases,
                mechanism.input_range().quantity,
                &targets,
                interference,
                &record.station,
            );
            // A station whose every sweep stopped at once has nothing to plot.
            if !plots.is_empty() {
                let svg = render_plots_svg(&format!("{}: station {}", scene.name, record.station), &plots).map_err(
                    |source| Error::PlottingStation {
                        station: record.station.clone(),
                        source,
                    },
                )?;
                out.write(&name, svg.as_bytes()).map_err(|source| Error::Write {
                    file: name.clone(),
                    source,
                })?;
                files.push(name);
            }
        }
    }
    Ok(files)
}

/// The pairs of `station` that fail the check, marked where they come closest (the first
/// part's point, in the station plane), with the clearance or overlap and where in the
/// deployment.
fn clashes(report: &InterferenceReport, station: &str, station_from_aircraft: &nalgebra::Isometry3<f64>) -> Vec<Clash> {
    report
        .pairs
        .iter()
        .filter(|pair| !pair.passes)
        .filter(|pair| {
            pair.station
                .as_deref()
                .is_some_and(|s| s.split('/').any(|name| name == station))
        })
        .map(|pair| {
            let c = &pair.clearance;
            let [x, y, z] = c.point_a_ac;
            let at = station_from_aircraft * nalgebra::Point3::new(x, y, z);
            let how = if c.penetration_m > 0.0 {
                format!("overlap {:.1} mm", c.penetration_m * 1e3)
            } else {
                format!("clearance {:.1} mm", c.min_clearance_m * 1e3)
            };
            Clash {
                label: format!("{} / {}: {how} at {:.0} %", c.part_a, c.part_b, c.at_parameter * 100.0),
                at: Point2::new(at.x, at.y),
            }
        })
        .collect()
}

/// How far ahead of the mechanism the station drawing shows the wing (m).
const VIEW_MARGIN_M: f64 = 0.15;

/// The part of `polygon` with x <= `limit` (Sutherland-Hodgman against one half-plane).
/// Where [`clip_x_below`] cut `polygon` at `limit`: the segment across the cut, from the
/// lowest to the highest point on it; None where the polygon did not reach the limit.
fn cut_at(polygon: &[Point2<f64>], limit: f64) -> Option<[Point2<f64>; 2]> {
    let on_cut = polygon.iter().filter(|p| p.x == limit).map(|p| p.y);
    let (low, high) = on_cut.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), y| (lo.min(y), hi.max(y)));
    (high > low).then(|| [Point2::new(limit, low), Point2::new(limit, high)])
}

fn clip_x_below(polygon: &[Point2<f64>], limit: f64) -> Vec<Point2<f64>> {
    let mut clipped = Vec::with_capacity(polygon.len() + 2);
    for (i, a) in polygon.iter().enumerate() {
        let b = polygon[(i + 1) % polygon.len()];
        let (a_in, b_in) = (a.x <= limit, b.x <= limit);
        if a_in {
            clipped.push(*a);
        }
        if a_in != b_in {
            let t = (limit - a.x) / (b.x - a.x);
            clipped.push(Point2::new(limit, a.y + t * (b.y - a.y)));
        }
    }
    clipped
}
