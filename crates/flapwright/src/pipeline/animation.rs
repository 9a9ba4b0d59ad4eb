//! The animated glTF export (`<scene>.glb`, `flapwright-gltf`): the wing's parts and every
//! mechanism solid, one node each named as in the report, keyframed at the drive
//! fractions of the report's deployment samples with the motions the interference check
//! sweeps (each solid with its body's pose from the seam; a flap with its one station's
//! flap displacement, or the rigid motion fitted to its stations).

use flapwright_geom::parts::{Part as MeshPart, PartKind};
use flapwright_geom::{CollisionShape, TriMesh};
use flapwright_gltf::{interpolated_displacement, to_glb, Body, Material, Model};
use flapwright_interference::Motion;
use flapwright_mechanism::seam::BodyRole;
use nalgebra::Isometry3;

use crate::error::{Error, Result};
use crate::pipeline::mechanism_parts::MechanismSolid;
use crate::pipeline::record::StationRecord;
use crate::report::GltfExport;
use crate::scene::Scene;
use crate::sink::Sink;

/// Seconds the animation takes from stowed to deployed (its clock is the drive fraction
/// times this; the real deployment time is the actuator's).
pub const ANIMATION_DURATION_S: f64 = 4.0;

/// A surface colour per part kind and body role: the same role, the same colour at every
/// station.
fn materials() -> Vec<Material> {
    let colour = |name: &str, rgba: [f32; 4]| Material {
        name: name.into(),
        rgba,
    };
    vec![
        colour("wing-skin", [0.72, 0.75, 0.80, 0.35]),
        colour("spar", [0.35, 0.37, 0.40, 1.0]),
        colour("torque-tube", [0.25, 0.35, 0.55, 1.0]),
        colour("flap", [0.55, 0.70, 0.85, 1.0]),
        colour("flap-fitting", [0.90, 0.45, 0.10, 1.0]),
        colour("link", [0.20, 0.65, 0.30, 1.0]),
        colour("track", [0.65, 0.15, 0.15, 1.0]),
        colour("carriage", [0.55, 0.25, 0.65, 1.0]),
        colour("actuator", [0.95, 0.80, 0.15, 1.0]),
        colour("support", [0.45, 0.30, 0.20, 1.0]),
        colour("flap-aft-element", [0.55, 0.68, 0.85, 1.0]),
        colour("aft-flap-fitting", [0.85, 0.55, 0.20, 1.0]),
    ]
}

fn material_of_kind(kind: PartKind) -> usize {
    match kind {
        PartKind::WingSkin => 0,
        PartKind::Spar => 1,
        PartKind::TorqueTube => 2,
        PartKind::Flap => 3,
        PartKind::AftElement => 10,
    }
}

fn material_of_role(role: BodyRole) -> usize {
    match role {
        BodyRole::Flap => 4,
        BodyRole::AftFlap => 11,
        BodyRole::Link => 5,
        BodyRole::Track => 6,
        BodyRole::Carriage => 7,
        BodyRole::Actuator => 8,
        BodyRole::Support => 9,
    }
}

/// A body's displacement from stowed at each drive fraction: its local frame's pose there
/// times the inverse of its stowed pose.
fn displacements(motion: &dyn Motion, fractions: &[f64]) -> flapwright_mechanism::Result<Vec<Isometry3<f64>>> {
    let stowed_inverse = motion.pose_ac(0.0)?.inverse();
    fractions
        .iter()
        .map(|&t| Ok(motion.pose_ac(t)? * stowed_inverse))
        .collect()
}

/// Largest vertex error of the viewer's interpolation at the middle of each step (m).
fn interpolation_error(
    mesh: &TriMesh,
    anchor: &nalgebra::Point3<f64>,
    motion: &dyn Motion,
    fractions: &[f64],
    keys: &[Isometry3<f64>],
) -> Result<f64> {
    let stowed_inverse = motion.pose_ac(0.0)?.inverse();
    let mut worst = 0.0_f64;
    for (k, pair) in keys.windows(2).enumerate() {
        let middle = 0.5 * (fractions[k] + fractions[k + 1]);
        let exact = motion.pose_ac(middle)? * stowed_inverse;
        let shown = interpolated_displacement(&pair[0], &pair[1], anchor, 0.5);
        for vertex in &mesh.vertices {
            worst = worst.max((exact * vertex - shown * vertex).norm());
        }
    }
    Ok(worst)
}

/// Writes `<scene>.glb`.
pub fn write_gltf(
    scene: &Scene,
    meshed: &[MeshPart],
    solids: &[MechanismSolid],
    records: &[StationRecord],
    out: &dyn Sink,
) -> Result<GltfExport> {
    let samples = scene.resolution.deployment_samples;
    let fractions: Vec<f64> = (0..samples).map(|k| k as f64 / (samples - 1) as f64).collect();
    let mut bodies = Vec::new();
    let mut motions: Vec<Option<std::sync::Arc<dyn Motion>>> = Vec::new();
    for part in meshed {
        let motion: Option<std::sync::Arc<dyn Motion>> = if part.flap_element().is_some() {
            let shape = CollisionShape::from_mesh(&part.mesh).map_err(|source| Error::CollisionShape {
                part: part.name.clone(),
                source,
            })?;
            let flap = crate::pipeline::interference::moving_flap(part, shape, records)?;
            Some(flap.motion)
        } else {
            None
        };
        bodies.push(Body {
            name: part.name.clone(),
            mesh: part.mesh.clone(),
            material: material_of_kind(part.kind),
            displacements: None,
        });
        motions.push(motion);
    }
    for solid in solids {
        let moving = solid.motion.speed_bound() > 0.0;
        bodies.push(Body {
            name: solid.name.clone(),
            mesh: solid.mesh_ac.clone(),
            material: material_of_role(solid.role),
            displacements: None,
        });
        motions.push(moving.then(|| std::sync::Arc::clone(&solid.motion)));
    }
    let mut worst = (0.0_f64, String::new());
    for (body, motion) in bodies.iter_mut().zip(&motions) {
        let Some(motion) = motion else { continue };
        let keys = displacements(motion.as_ref(), &fractions).map_err(|source| Error::Posing {
            part: body.name.clone(),
            source,
        })?;
        let error = interpolation_error(&body.mesh, &body.anchor(), motion.as_ref(), &fractions, &keys)?;
        if error > worst.0 {
            worst = (error, body.name.clone());
        }
        body.displacements = Some(keys);
    }
    let model = Model {
        times_s: fractions.iter().map(|f| f * ANIMATION_DURATION_S).collect(),
        materials: materials(),
        bodies,
    };
    let nodes = model.bodies.len();
    let glb = to_glb(&model)?;
    let file = format!("{}.glb", scene.name);
    out.write(&file, &glb).map_err(|source| Error::Write {
        file: file.clone(),
        source,
    })?;
    Ok(GltfExport {
        file,
        nodes,
        samples,
        duration_s: ANIMATION_DURATION_S,
        max_interpolation_error_m: worst.0,
        max_interpolation_error_part: worst.1,
    })
}
