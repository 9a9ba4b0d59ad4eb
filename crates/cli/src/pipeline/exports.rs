//! Exports for viewers and people: URDF + trajectory (mechanism crate's `urdf` module),
//! SVG drawings and plots per station (drawing crate).

use anyhow::{Context, Result};
use flapwright_drawing::{
    convex_hull, render_plots_svg, render_station_svg, Dimension, Joint, Link, MechanismSnapshot, PartStyle,
    SectionOutline, SlotArc, StationDrawing,
};
use flapwright_interference::{FairingDepth, InterferenceReport};
use flapwright_mechanism::urdf::{build_robot, to_xml, trajectory, BaseLink, CutJoint, MeshRef, StationMechanism3d};
use flapwright_mechanism::Sweep;
use nalgebra::{Point2, Rotation2};
use serde::Serialize;

use crate::output::StagedDir;
use crate::pipeline::flap_position::flap_behind_wing;
use crate::pipeline::mechanisms::StationMechanism;
use crate::pipeline::plots::station_plots;
use crate::pipeline::stations::PlacedStation;
use crate::report::PartReport;
use crate::scene::Scene;

/// What the URDF export wrote.
#[derive(Debug, Clone, Serialize)]
pub struct UrdfExport {
    /// The URDF file.
    pub file: String,
    /// Joint values and key points per deployment sample.
    pub trajectory_file: String,
    /// Where the closed loops were cut (URDF is a tree).
    pub cut_joints: Vec<CutJoint>,
}

/// Writes `<scene>.urdf` and `trajectory.json`; meshes are the part STL files beside them.
pub fn write_urdf(
    scene: &Scene,
    parts: &[PartReport],
    mechanisms: &[StationMechanism],
    placed: &[PlacedStation],
    out: &StagedDir,
) -> Result<UrdfExport> {
    let flap_names: Vec<&str> = scene.flap.iter().map(|f| f.name.as_str()).collect();
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
            .filter(|p| !flap_names.contains(&p.name.as_str()))
            .filter_map(mesh)
            .collect(),
    };
    let mut owner_seen = Vec::new();
    let stations: Vec<StationMechanism3d> = scene
        .station
        .iter()
        .zip(mechanisms)
        .zip(placed)
        .map(|((station, mechanism), place)| {
            let flap_name = station.flap.clone().unwrap_or_default();
            let owns_flap = !owner_seen.contains(&flap_name);
            owner_seen.push(flap_name.clone());
            StationMechanism3d {
                name: station.name.clone(),
                aircraft_from_station: *place.station.frame.aircraft_from_station(),
                track: &mechanism.track,
                flap_mesh: if owns_flap {
                    parts
                        .iter()
                        .find(|p| p.name == flap_name)
                        .and_then(|p| p.stl_file.clone())
                } else {
                    None
                },
                flap_name,
                owns_flap,
            }
        })
        .collect();
    let robot_name = scene
        .name
        .replace(|c: char| !c.is_ascii_alphanumeric() && c != '_', "_");
    let model = build_robot(&robot_name, &base, &stations)?;
    let file = format!("{}.urdf", scene.name);
    std::fs::write(out.file(&file), to_xml(&model)?).with_context(|| format!("writing {file}"))?;
    // The report's deployment samples, so each trajectory sample is a report sample.
    let trajectory = trajectory(&stations, scene.resolution.deployment_samples)?;
    let trajectory_file = "trajectory.json".to_string();
    std::fs::write(
        out.file(&trajectory_file),
        serde_json::to_string_pretty(&trajectory)? + "\n",
    )
    .context("writing trajectory.json")?;
    Ok(UrdfExport {
        file,
        trajectory_file,
        cut_joints: model.cut_joints,
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

/// The mechanism at flap rotation `t` (rad): links and joints, station frame.
fn snapshot(
    mechanism: &StationMechanism,
    label: &str,
    t: f64,
    flap_outline: Vec<Vec<Point2<f64>>>,
) -> MechanismSnapshot {
    let synthesis = mechanism.track.synthesis();
    let spec = mechanism.track.spec();
    let turn = Rotation2::new(t);
    let a = turn * synthesis.nut_pivot_stowed_m;
    let d = turn * spec.centre_of_mass_stowed_m;
    let f = turn * synthesis.outer_pin_stowed_m;
    let g = turn * synthesis.inner_pin_stowed_m;
    let b0 = synthesis.screw_mount_m;
    let b = b0 + (a - b0).normalize() * spec.screw_length_m;
    let link = |name: &str, points: Vec<Point2<f64>>| Link {
        name: name.into(),
        points,
    };
    let joint = |name: &str, at: Point2<f64>, fixed: bool| Joint {
        name: name.into(),
        at,
        fixed,
    };
    MechanismSnapshot {
        label: label.into(),
        deflection_deg: t.to_degrees(),
        flap_outline: flap_outline
            .iter()
            .map(|polygon| polygon.iter().map(|p| turn * p).collect())
            .collect(),
        links: vec![link("screw", vec![b0, b]), link("flap link", vec![a, d, f, d, g])],
        joints: vec![
            joint("A0", Point2::origin(), true),
            joint("B0", b0, true),
            joint("A", a, false),
            joint("B", b, false),
            joint("D", d, false),
            joint("F", f, false),
            joint("G", g, false),
        ],
    }
}

/// Writes `station-<name>.svg` and `plots-<name>.svg` per station; returns the file names.
pub fn write_svgs(
    scene: &Scene,
    mechanisms: &[StationMechanism],
    placed: &[Option<&PlacedStation>],
    sweeps: &[Option<&[Sweep]>],
    fairings: &[Option<FairingDepth>],
    interference: Option<&InterferenceReport>,
    out: &StagedDir,
) -> Result<Vec<String>> {
    let flap_names: Vec<String> = scene.flap.iter().map(|f| f.name.clone()).collect();
    let mut files = Vec::new();
    for (i, (station, mechanism)) in scene.station.iter().zip(mechanisms).enumerate() {
        let spec = mechanism.track.spec();
        let synthesis = mechanism.track.synthesis();
        let sections: Vec<SectionOutline> = placed[i]
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
        let reach = [spec.outer_slot_radius_m, synthesis.screw_mount_m.x]
            .into_iter()
            .fold(0.0, f64::max);
        let x_limit = reach + VIEW_MARGIN_M;
        let sections: Vec<SectionOutline> = sections
            .into_iter()
            .filter_map(|mut s| {
                s.polygons = s
                    .polygons
                    .iter()
                    .map(|p| clip_x_below(p, x_limit))
                    .filter(|p| p.len() >= 3)
                    .collect();
                (!s.polygons.is_empty()).then_some(s)
            })
            .collect();
        let flap_outline: Vec<Vec<Point2<f64>>> = sections
            .iter()
            .filter(|s| matches!(s.kind, PartStyle::Flap))
            .flat_map(|s| s.polygons.clone())
            .collect();
        // The flap's settings (validation keeps them within the rotation range); a station
        // without a flap shows the middle and the end of its range.
        let (takeoff, landing) = station
            .flap
            .as_ref()
            .and_then(|name| scene.flap.iter().find(|f| &f.name == name))
            .map_or((spec.rotation_range_rad / 2.0, spec.rotation_range_rad), |f| {
                (
                    f.settings.takeoff_deg.to_radians().min(spec.rotation_range_rad),
                    f.settings.landing_deg.to_radians().min(spec.rotation_range_rad),
                )
            });
        let settings = vec![
            snapshot(mechanism, "stowed", 0.0, flap_outline.clone()),
            snapshot(mechanism, "takeoff", takeoff, flap_outline.clone()),
            snapshot(mechanism, "landing", landing, flap_outline.clone()),
        ];
        let envelope = vec![convex_hull(
            (0..=20)
                .flat_map(|k| {
                    let s = snapshot(mechanism, "", spec.rotation_range_rad * k as f64 / 20.0, Vec::new());
                    s.links.into_iter().flat_map(|l| l.points)
                })
                .collect(),
        )];
        let fairing_line = fairings[i].as_ref().filter(|f| f.depth_m > 0.0).map(|f| {
            let y = f.point_st[1];
            let xs = envelope[0].iter().map(|p| p.x);
            let (lo, hi) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)));
            vec![Point2::new(lo, y), Point2::new(hi, y)]
        });
        let slots = vec![
            SlotArc {
                name: "outer slot b1".into(),
                centre: Point2::origin(),
                radius_m: spec.outer_slot_radius_m,
                start_rad: spec.outer_slot_start_angle_rad,
                end_rad: spec.outer_slot_start_angle_rad + spec.rotation_range_rad,
            },
            SlotArc {
                name: "inner slot c1".into(),
                centre: Point2::origin(),
                radius_m: spec.inner_slot_radius_m,
                start_rad: spec.outer_slot_start_angle_rad + spec.inner_slot_offset_angle_rad,
                end_rad: spec.outer_slot_start_angle_rad + spec.inner_slot_offset_angle_rad + spec.rotation_range_rad,
            },
        ];
        let dimensions = vec![
            Dimension::new("a1", Point2::origin(), synthesis.screw_mount_m),
            Dimension::new("a2", Point2::origin(), synthesis.nut_pivot_stowed_m),
            Dimension::new(
                "a3",
                synthesis.screw_mount_m,
                synthesis.screw_mount_m
                    + (synthesis.nut_pivot_stowed_m - synthesis.screw_mount_m).normalize() * spec.screw_length_m,
            ),
        ];
        let fairing_text = fairings[i]
            .as_ref()
            .map(|f| {
                format!(
                    ", fairing depth {:.0} mm ({:.1} % flap chord)",
                    f.depth_m * 1e3,
                    f.depth_percent_flap_chord
                )
            })
            .unwrap_or_default();
        let drawing = StationDrawing {
            title: format!("{}: station {}", scene.name, station.name),
            subtitle: format!(
                "circular-arc track with screw jack; s34 {:.1} -> {:.1} mm{fairing_text}",
                synthesis.stroke_start_m * 1e3,
                synthesis.stroke_end_m * 1e3
            ),
            sections,
            settings,
            slots,
            envelope,
            fairing_line,
            dimensions,
        };
        let name = format!("station-{}.svg", station.name);
        let svg = render_station_svg(&drawing).with_context(|| format!("drawing station {}", station.name))?;
        std::fs::write(out.file(&name), svg).with_context(|| format!("writing {name}"))?;
        files.push(name);
        if let Some(cases) = sweeps[i] {
            let name = format!("plots-{}.svg", station.name);
            let flap_behind_wing = match (placed[i], station.flap.as_deref()) {
                (Some(p), Some(flap_name)) => flap_behind_wing(p, flap_name)?,
                _ => None,
            };
            let plots = station_plots(cases, flap_behind_wing.as_ref(), interference, &station.name);
            // A station whose every sweep stopped at once has nothing to plot.
            if !plots.is_empty() {
                let svg = render_plots_svg(&format!("{}: station {}", scene.name, station.name), &plots)
                    .with_context(|| format!("plotting station {}", station.name))?;
                std::fs::write(out.file(&name), svg).with_context(|| format!("writing {name}"))?;
                files.push(name);
            }
        }
    }
    Ok(files)
}

/// How far ahead of the mechanism the station drawing shows the wing (m).
const VIEW_MARGIN_M: f64 = 0.15;

/// The part of `polygon` with x <= `limit` (Sutherland-Hodgman against one half-plane).
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
