//! Interference stage: moving parts (flap, screws, nuts, fittings) against the fixed
//! structure over the deployment, with a certified sampling bound; fairing depth per
//! station.

use flapwright_geom::collision::CollisionShape;
use flapwright_geom::parts::{Part as MeshPart, PartKind};
use flapwright_interference::{
    check_assembly, fairing_depth, flap_part, planar_parts, station_opening, station_parts, Assembly, FlapElement,
    InterferenceReport, Part, Requirements, SweepSettings,
};

use crate::error::{Error, Result};
use crate::pipeline::flap_motion::fitted_flap_motion;
use crate::pipeline::record::{PlacedStation, StationRecord};
use crate::pipeline::WingCache;
use crate::scene::{ResolutionScene, Scene};

#[cfg(test)]
#[path = "interference_agreement.rs"]
mod agreement;

/// Builds the assembly and sweeps every pair, taking the parts' shapes from `cache`.
pub fn check(
    scene: &Scene,
    meshed: &[MeshPart],
    records: &[StationRecord],
    shapes: &WingCache,
) -> Result<InterferenceReport> {
    let (assembly, required, sweep) = assembly(scene, meshed, records, shapes)?;
    // The drive fraction: 0 stowed, 1 deployed at every station.
    Ok(check_assembly(&assembly, 1.0, &required, &sweep)?)
}

/// The assembly the check sweeps (wing parts, flaps, each station's parts with its
/// openings cut), what it requires and how it sweeps.
pub fn assembly(
    scene: &Scene,
    meshed: &[MeshPart],
    records: &[StationRecord],
    shapes: &WingCache,
) -> Result<(Assembly, Requirements, SweepSettings)> {
    fn placed(record: &StationRecord) -> Result<&PlacedStation> {
        record.placed.as_ref().ok_or_else(|| Error::StationNotPlaced {
            station: record.station.clone(),
        })
    }
    let mut fixed = Vec::new();
    let mut skins = Vec::new();
    let mut flaps = Vec::new();
    let mut aft_elements = Vec::new();
    // Meshes the openings are cut in: skins, then each flap (by name).
    let mut skin_meshes: Vec<&flapwright_geom::TriMesh> = Vec::new();
    let mut flap_meshes: Vec<&flapwright_geom::TriMesh> = Vec::new();
    let mut aft_meshes: Vec<&flapwright_geom::TriMesh> = Vec::new();
    for part in meshed {
        let shape = shapes.shape_of(&part.mesh).map_err(|source| Error::CollisionShape {
            part: part.name.clone(),
            source,
        })?;
        match part.kind {
            PartKind::Flap => {
                flaps.push(moving_flap(part, shape, records)?);
                flap_meshes.push(&part.mesh);
            }
            PartKind::AftElement => {
                let flap = part
                    .flap_element()
                    .map(|(flap, _)| flap.to_string())
                    .unwrap_or_default();
                aft_elements.push((flap, moving_flap(part, shape, records)?));
                aft_meshes.push(&part.mesh);
            }
            kind => {
                if kind == PartKind::WingSkin {
                    skins.push(part.name.clone());
                    skin_meshes.push(&part.mesh);
                }
                fixed.push(Part::fixed(part.name.clone(), shape));
            }
        }
    }
    let settings = &scene.interference;
    let skin_parts: Vec<(&Part, &flapwright_geom::TriMesh)> = fixed
        .iter()
        .filter(|p: &&Part| skins.contains(&p.name))
        .zip(skin_meshes)
        .collect();
    let spars: Vec<&str> = meshed
        .iter()
        .filter(|p| p.kind == PartKind::Spar)
        .map(|p| p.name.as_str())
        .collect();
    // Each station's parts and openings are its own: built in parallel (rayon), in order.
    use rayon::prelude::*;
    let stations = records
        .par_iter()
        .map(|r| {
            let station = placed(r)?;
            let frame = station.station.frame.aircraft_from_station();
            let mut parts = station_parts(&r.station, r.flap.as_deref(), frame, &r.mechanism)?;
            // The wing box ahead of the rear spar (the aft-most spar the plane cuts; station
            // x points forward) is never opened.
            let rear_spar_aft_x = station
                .polygons_of(|name| spars.contains(&name))
                .iter()
                .map(|polygon| polygon.iter().map(|p| p.x).fold(f64::INFINITY, f64::min))
                .min_by(f64::total_cmp);
            let wing_section = station.polygons_of(|name| skins.iter().any(|s| s == name));
            let opening = station_opening(
                &r.station,
                r.mechanism.as_ref(),
                rear_spar_aft_x,
                &wing_section,
                settings.opening_margin_m(),
            )?;
            let flap = r.flap.as_deref().and_then(|name| {
                let index = flaps.iter().position(|f| f.name == name)?;
                Some((&flaps[index], flap_meshes[index]))
            });
            let aft_element = r.flap.as_deref().and_then(|name| {
                let index = aft_elements.iter().position(|(flap, _)| flap == name)?;
                Some((&aft_elements[index].1, aft_meshes[index]))
            });
            parts.cut_openings(opening, frame, &skin_parts, flap, aft_element)?;
            Ok(parts)
        })
        .collect::<Result<Vec<_>>>()?;
    let sweep = SweepSettings {
        initial_samples: settings.initial_samples,
        tolerance_m: settings.tolerance_m,
        relative_tolerance: settings.relative_tolerance,
        max_evaluations: settings.max_evaluations,
        stop_at_verdict: settings.stop_at_verdict,
    };
    let assembly = Assembly {
        fixed,
        skins,
        flaps,
        aft_elements,
        stations,
    };
    // A share of each station's local flap chord, where the scene asks for one.
    let clearance_by_station_m = match settings.required_clearance_percent_flap_chord {
        Some(percent) => records
            .iter()
            .filter_map(|r| {
                let placed = r.placed.as_ref()?;
                let flap = r.flap.as_deref()?;
                let chord = local_chord_m(&placed.flap_polygons(flap));
                Some((r.station.clone(), percent / 100.0 * chord))
            })
            .filter(|(_, clearance)| *clearance > settings.required_clearance_m)
            .collect(),
        None => Default::default(),
    };
    let required = Requirements {
        clearance_m: settings.required_clearance_m,
        joint_play_m: settings.joint_play_m,
        clearance_by_station_m,
    };
    Ok((assembly, required, sweep))
}

/// The flap element `part` (a flap or an aft element, its collision `shape`) moving as its
/// stations move it: exactly with the one station's displacement of the body carrying it,
/// or by the rigid motion fitted to several.
pub fn moving_flap(part: &MeshPart, shape: CollisionShape, records: &[StationRecord]) -> Result<Part> {
    let (flap, element) = flap_element(part)?;
    let carriers: Vec<&StationRecord> = records
        .iter()
        .filter(|record| record.flap.as_deref() == Some(flap))
        .collect();
    let Some(first) = carriers.first() else {
        return Err(Error::FlapWithoutStation { flap: flap.to_string() });
    };
    if carriers.len() == 1 {
        let placed = first.placed.as_ref().ok_or_else(|| Error::StationNotPlaced {
            station: first.station.clone(),
        })?;
        // One station: the flap follows its planar displacement exactly.
        Ok(flap_part(
            &part.name,
            element,
            shape,
            &part.mesh.vertices,
            placed.station.frame.aircraft_from_station(),
            &first.mechanism,
        )?)
    } else {
        let motion = fitted_flap_motion(&part.name, element, &carriers, &part.mesh.vertices)?;
        Ok(Part::moving(part.name.clone(), shape, motion))
    }
}

/// The flap a meshed flap element belongs to, and which element it is.
fn flap_element(part: &MeshPart) -> Result<(&str, FlapElement)> {
    match part.flap_element() {
        Some((flap, false)) => Ok((flap, FlapElement::Main)),
        Some((flap, true)) => Ok((flap, FlapElement::Aft)),
        None => Err(Error::NotAFlapElement {
            part: part.name.clone(),
        }),
    }
}

/// The chordwise extent of a section cut (station x, m): the local chord of a flap.
fn local_chord_m(polygons: &[Vec<nalgebra::Point2<f64>>]) -> f64 {
    let (lo, hi) = polygons
        .iter()
        .flatten()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.x), hi.max(p.x))
        });
    (hi - lo).max(0.0)
}

/// Fairing depth of each placed station (each record's `fairing`): the mechanism against
/// the lower contour of the wing and the stowed flap cut by the station plane. Stations in
/// parallel (rayon): each is its own.
pub fn fairing_depths(
    records: &mut [StationRecord],
    flap_names: &[String],
    resolution: &ResolutionScene,
) -> Result<()> {
    use rayon::prelude::*;
    records.par_iter_mut().try_for_each(|record| -> Result<()> {
        let Some(station) = &record.placed else {
            return Ok(());
        };
        // The wing and every flap cut by the plane bound the fairing; the station's own flap
        // gives the chord the depth is a share of.
        let is_flap = |name: &str| flap_names.iter().any(|f| f == name);
        let contour = station.polygons_of(|name| name == "wing" || is_flap(name));
        let flap_chord_m = record
            .flap
            .as_deref()
            .map_or(0.0, |flap| local_chord_m(&station.flap_polygons(flap)));
        let samples = resolution.fairing_samples;
        let parameters: Vec<f64> = (0..samples).map(|i| i as f64 / (samples - 1) as f64).collect();
        let points = resolution.fairing_points_per_capsule;
        let mechanism = record.mechanism.as_ref();
        let depth = fairing_depth(&contour, flap_chord_m, &parameters, points, |t| {
            planar_parts(mechanism, t)
        })
        .map_err(|source| Error::FairingDepth {
            station: record.station.clone(),
            source,
        })?;
        record.fairing = Some(depth);
        Ok(())
    })
}
