//! Mechanism parts as files: every solid of every station's mechanism, as the interference
//! check sweeps it (`flapwright_interference::station_parts`: capsules and balls as parry
//! primitives, tracks as tube meshes), tessellated in the aircraft frame with the
//! mechanism stowed, with its mass properties: a member the sizing stage sized carries its
//! sized mass (the drawn envelope's inertia scaled by the mass ratio: exact for the
//! length-dominated part of a slender member, whose sized bar is the drawn one thinner or
//! thicker), in every output (report, URDF, glTF); an unsized solid (fittings, carriages,
//! jack bodies, and every solid when sizing did not run) its drawn envelope at the sizing
//! material's density (the actuator's solids at `sizing.screw_material`, every other solid
//! at `sizing.link_material`), marked [`MassBasis::Drawn`].

use flapwright_geom::TriMesh;
use std::sync::Arc;

use flapwright_interference::{station_parts, Motion, StationParts};
use flapwright_mechanism::seam::BodyRole;
use flapwright_urdf::RigidInertia;

use crate::error::{Error, Result};
use crate::pipeline::record::StationRecord;
use crate::report::{MassBasis, MechanismPartReport};
use crate::scene::{Scene, StlSetting};
use crate::sink::Sink;

/// One solid of one station's mechanism.
pub struct MechanismSolid {
    /// Station.
    pub station: String,
    /// Index of its body in the station's mechanism.
    pub body: usize,
    /// Its body's name.
    pub body_name: String,
    /// Its body's role.
    pub role: BodyRole,
    /// `<station>.<solid>`, as in the interference report.
    pub name: String,
    /// Surface, aircraft frame, where the build put the mechanism (stowed for URDF and
    /// glTF).
    pub mesh_ac: TriMesh,
    /// Mass properties, aircraft frame, there.
    pub inertia: RigidInertia,
    /// Where its mass comes from.
    pub mass_basis: MassBasis,
    /// How it moves with the drive fraction (the check's motion).
    pub motion: Arc<dyn Motion>,
}

/// The drive fraction at which each record's station puts its flap at `setting` (0 for
/// stowed and for a station without a flap).
pub fn setting_fractions(scene: &Scene, records: &[StationRecord], setting: StlSetting) -> Result<Vec<f64>> {
    records
        .iter()
        .map(|record| {
            let flap = record
                .flap
                .as_ref()
                .and_then(|name| scene.flap.iter().find(|f| &f.name == name));
            let deflection_deg = match (setting, flap) {
                (StlSetting::Takeoff, Some(flap)) => flap.settings.takeoff_deg,
                (StlSetting::Landing, Some(flap)) => flap.settings.landing_deg,
                _ => return Ok(0.0),
            };
            let mechanism = record.mechanism.as_ref();
            let input = mechanism
                .input_at_deflection(deflection_deg.to_radians())
                .map_err(|source| Error::SettingInput {
                    station: record.station.clone(),
                    deflection_deg,
                    source,
                })?;
            Ok(mechanism.input_range().fraction(input))
        })
        .collect()
}

/// Every station's solids, each at its station's drive fraction in `fractions` (one per
/// record; mass properties there too); all 0: stowed. A solid that `sized` holds a rod of
/// carries that rod's mass.
pub fn build(
    scene: &Scene,
    records: &[StationRecord],
    fractions: &[f64],
    sized: Option<&flapwright_sizing::SizingReport>,
) -> Result<Vec<MechanismSolid>> {
    let screw = crate::pipeline::sizing::material(scene, &scene.sizing.screw_material)?;
    let link = crate::pipeline::sizing::material(scene, &scene.sizing.link_material)?;
    let mut solids = Vec::new();
    for (record, &fraction) in records.iter().zip(fractions) {
        let placed = record.placed.as_ref().ok_or_else(|| Error::StationNotPlaced {
            station: record.station.clone(),
        })?;
        let parts: StationParts = station_parts(
            &record.station,
            record.flap.as_deref(),
            placed.station.frame.aircraft_from_station(),
            &record.mechanism,
        )?;
        for part in parts.parts {
            let density = if part.role == BodyRole::Actuator {
                screw.density_kg_m3
            } else {
                link.density_kg_m3
            };
            let name = part.part.name.clone();
            let properties = part
                .part
                .compute_mass_properties_ac(density, fraction)?
                .ok_or_else(|| Error::NoVolume { part: name.clone() })?;
            let solid_name = name.strip_prefix(&format!("{}.", record.station)).unwrap_or(&name);
            let sized_mass = sized
                .and_then(|s| {
                    s.rods
                        .iter()
                        .find(|r| r.station == record.station && r.name == solid_name)
                })
                .map(|rod| rod.mass_kg)
                .filter(|m| m.is_finite() && *m > 0.0);
            let (scale, mass_basis) = match sized_mass {
                Some(mass) => (mass / properties.mass_kg, MassBasis::Sized),
                None => (1.0, MassBasis::Drawn),
            };
            solids.push(MechanismSolid {
                station: record.station.clone(),
                body: part.body,
                body_name: record.mechanism.bodies()[part.body].name.clone(),
                role: part.role,
                mesh_ac: part.part.compute_mesh_ac(fraction)?,
                inertia: RigidInertia {
                    mass_kg: properties.mass_kg * scale,
                    centre_of_mass_ac_m: properties.centre_of_mass,
                    inertia_ac_kg_m2: properties.inertia_kg_m2 * scale,
                },
                mass_basis,
                motion: Arc::clone(&part.part.motion),
                name,
            });
        }
    }
    Ok(solids)
}

/// Writes `<station>.<solid>.stl` per solid when `write_stl`; returns the report's records.
pub fn write_stl(solids: &[MechanismSolid], write_stl: bool, out: &dyn Sink) -> Result<Vec<MechanismPartReport>> {
    solids
        .iter()
        .map(|solid| {
            let stl_file = if write_stl {
                Some(crate::pipeline::geometry::write_stl_file(
                    &solid.mesh_ac,
                    &solid.name,
                    out,
                )?)
            } else {
                None
            };
            Ok(MechanismPartReport {
                name: solid.name.clone(),
                station: solid.station.clone(),
                body: solid.body_name.clone(),
                role: solid.role,
                vertices: solid.mesh_ac.vertices.len(),
                triangles: solid.mesh_ac.triangles.len(),
                mass_kg: solid.inertia.mass_kg,
                mass_basis: solid.mass_basis,
                stl_file,
            })
        })
        .collect()
}

/// Rewrites each flap's (and aft element's) STL file with it at its first station's drive
/// fraction in `fractions`, moved as the check moves it; updates the part's bounds in
/// `parts`.
pub fn move_flap_files(
    meshed: &[flapwright_geom::parts::Part],
    records: &[StationRecord],
    fractions: &[f64],
    parts: &mut [crate::report::PartReport],
    out: &dyn Sink,
) -> Result<()> {
    for (part, flap) in meshed.iter().filter_map(|p| Some((p, p.flap_element()?.0))) {
        let Some(first) = records.iter().position(|r| r.flap.as_deref() == Some(flap)) else {
            continue;
        };
        let shape = flapwright_geom::CollisionShape::from_mesh(&part.mesh).map_err(|source| Error::CollisionShape {
            part: part.name.clone(),
            source,
        })?;
        let motion = crate::pipeline::interference::moving_flap(part, shape, records)?.motion;
        let displacement = motion.pose_ac(fractions[first])? * motion.pose_ac(0.0)?.inverse();
        let mesh = part.mesh.transformed(&displacement);
        crate::pipeline::geometry::write_stl_file(&mesh, &part.name, out)?;
        if let (Some(report), Some(bounds)) = (parts.iter_mut().find(|p| p.name == part.name), mesh.compute_aabb()) {
            report.bounds_m = [bounds.min.coords.into(), bounds.max.coords.into()];
        }
    }
    Ok(())
}

/// The STL file of a solid: its name with `.stl` (as `geometry::write_stl_file` names it).
pub fn stl_name(solid: &str) -> String {
    format!("{solid}.stl")
}
