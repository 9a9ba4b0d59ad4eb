//! Mechanism parts as files: every solid of every station's mechanism, as the interference
//! check sweeps it (`flapwright_interference::station_parts`: capsules and balls as parry
//! primitives, tracks as tube meshes), tessellated in the aircraft frame with the
//! mechanism stowed, with its mass properties at the sizing material's density (the
//! actuator's solids at `sizing.screw_material`, every other solid at
//! `sizing.link_material`: the solids are the drawn envelopes, so these masses are upper
//! bounds of the sized members').

use anyhow::{Context, Result};
use flapwright_geom::TriMesh;
use std::sync::Arc;

use flapwright_interference::{station_parts, Motion, StationParts};
use flapwright_mechanism::seam::BodyRole;
use flapwright_mechanism::urdf::RigidInertia;
use serde::Serialize;

use crate::output::StagedDir;
use crate::pipeline::mechanisms::StationRecord;
use crate::scene::Scene;

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
    /// Surface, aircraft frame, mechanism stowed.
    pub mesh_ac: TriMesh,
    /// Mass properties, aircraft frame, stowed.
    pub inertia: RigidInertia,
    /// How it moves with the drive fraction (the check's motion).
    pub motion: Arc<dyn Motion>,
}

/// The report's record of one mechanism part file.
#[derive(Debug, Clone, Serialize)]
pub struct MechanismPartReport {
    /// `<station>.<solid>`.
    pub name: String,
    /// Station.
    pub station: String,
    /// The body it belongs to (its URDF link is `<station>_<body>`, its trajectory key
    /// points `<station>.<body>.<point>`).
    pub body: String,
    /// Its body's role (`flap`, `link`, `track`, `carriage`, `actuator`, `support`).
    pub role: BodyRole,
    /// Vertex count.
    pub vertices: usize,
    /// Triangle count.
    pub triangles: usize,
    /// Mass at the sizing material's density, kg.
    pub mass_kg: f64,
    /// STL file, aircraft frame, stowed (relative to the output folder).
    pub stl_file: Option<String>,
}

/// Every station's solids, stowed.
pub fn build(scene: &Scene, records: &[StationRecord]) -> Result<Vec<MechanismSolid>> {
    let screw = crate::pipeline::sizing::material(scene, &scene.sizing.screw_material)?;
    let link = crate::pipeline::sizing::material(scene, &scene.sizing.link_material)?;
    let mut solids = Vec::new();
    for record in records {
        let placed = record
            .placed
            .as_ref()
            .with_context(|| format!("station {} is not placed", record.station))?;
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
                .compute_mass_properties_ac(density, 0.0)?
                .with_context(|| format!("{name} holds no volume"))?;
            solids.push(MechanismSolid {
                station: record.station.clone(),
                body: part.body,
                body_name: record.mechanism.bodies()[part.body].name.clone(),
                role: part.role,
                mesh_ac: part.part.compute_mesh_ac(0.0)?,
                inertia: RigidInertia {
                    mass_kg: properties.mass_kg,
                    centre_of_mass_ac_m: properties.centre_of_mass,
                    inertia_ac_kg_m2: properties.inertia_kg_m2,
                },
                motion: Arc::clone(&part.part.motion),
                name,
            });
        }
    }
    Ok(solids)
}

/// Writes `<station>.<solid>.stl` per solid when `write_stl`; returns the report's records.
pub fn write_stl(solids: &[MechanismSolid], write_stl: bool, out: &StagedDir) -> Result<Vec<MechanismPartReport>> {
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
                stl_file,
            })
        })
        .collect()
}

/// The STL file of a solid: its name with `.stl` (as `geometry::write_stl_file` names it).
pub fn stl_name(solid: &str) -> String {
    format!("{solid}.stl")
}
