//! Sizing stage: screw jacks (motor torque, self-locking), screws as rods (strength and
//! Euler buckling), each kind's members (rods, or beams where they bend), the torque-tube
//! line between the stations, drive power and masses.

use flapwright_mechanism::seam::{Actuator, MemberLoad, MemberLoading};
use flapwright_mechanism::DeploymentSample;
use flapwright_sizing::{
    axial_envelope_n, deployment_work_j, drive_demand, size_actuator, size_rod, size_torque_tubes, ActuatorInput,
    ActuatorSizing, BendingLoad, DeploymentWork, Material, RodInput, SectionShape, SizingReport, TorqueTubeInput,
};
use nalgebra::{Point3, Vector3};

use crate::error::{Error, Result};
use crate::pipeline::record::{MechanismReport, StationRecord};
use crate::scene::Scene;

/// The material a scene names: a preset or one of its `[[materials]]`.
pub(crate) fn material(scene: &Scene, name: &str) -> Result<Material> {
    let material = match name {
        "steel-4340" => Material::steel_4340(),
        "aluminium-7075-t6" => Material::aluminium_7075_t6(),
        "titanium-ti-6al-4v" => Material::titanium_ti_6al_4v(),
        custom => {
            let m = scene
                .materials
                .iter()
                .find(|m| m.name == custom)
                .ok_or_else(|| Error::UnknownMaterial {
                    material: custom.to_string(),
                })?;
            Material::try_new(
                m.name.clone(),
                m.density_kg_m3,
                m.allowable_tensile_pa,
                m.allowable_shear_pa,
                m.youngs_modulus_pa,
            )?
        }
    };
    Ok(material)
}

/// Sizes everything the mechanism loads drive, from each record's deployments (a station
/// whose sweeps stopped before any sample is left out with a warning naming it). The
/// stations' planes (origin A0 and normal; none without a wing) and the torque tube's axis
/// `tube_path_ac` give the torque-tube lengths: measured along the tube, between the
/// points where the station planes cross it (where each station's gearbox takes its
/// drive), from the outermost station inboard to the motor at the tube's first point.
pub fn size_all(
    scene: &Scene,
    mechanisms: &[StationRecord],
    tube_path_ac: &[Point3<f64>],
) -> Result<(SizingReport, Vec<String>)> {
    let reports: Vec<Option<&MechanismReport>> = mechanisms.iter().map(|r| r.kinematics.as_ref()).collect();
    let safety_factor = scene
        .loads
        .safety_factor
        .unwrap_or(flapwright_sizing::CS25_SAFETY_FACTOR);
    let screw_material = material(scene, &scene.sizing.screw_material)?;
    let tube_material = material(scene, &scene.sizing.torque_tube_material)?;
    let link_material = material(scene, &scene.sizing.link_material)?;
    let mut rods = Vec::new();
    let mut jacks: Vec<Option<ActuatorSizing>> = Vec::new();
    let mut notes = Vec::new();
    for (mechanism, report) in mechanisms.iter().zip(&reports) {
        // Sizing is written per actuator type, never per kind.
        let actuator = mechanism.mechanism.actuator();
        let samples: Vec<&DeploymentSample> = report
            .iter()
            .flat_map(|r| r.load_cases.iter())
            .flat_map(|case| case.samples.iter())
            .collect();
        if samples.is_empty() {
            notes.push(format!(
                "station {}: not sized: no deployment sample could be computed (see its load cases' `stopped`)",
                mechanism.station
            ));
            jacks.push(None);
            continue;
        }
        let forces: Vec<f64> = samples.iter().map(|s| s.actuator_load).collect();
        // The drive shaft's torques at every sample.
        let torques: Vec<_> = forces.iter().map(|&f| actuator.shaft_torques(f)).collect();
        let max_raise = torques
            .iter()
            .map(|t| t.raise_torque_nm)
            .fold(f64::NEG_INFINITY, f64::max);
        let max_lower = torques
            .iter()
            .map(|t| t.lower_torque_nm)
            .fold(f64::NEG_INFINITY, f64::max);
        // The smallest lowering torque decides self-locking over the whole deployment.
        let min_lower = torques.iter().map(|t| t.lower_torque_nm).fold(f64::INFINITY, f64::min);
        let name = match actuator {
            Actuator::ScrewJack { .. } => "screw-jack",
            Actuator::Rotary { .. } => "rotary-actuator",
        };
        let jack = size_actuator(
            &ActuatorInput {
                station: mechanism.station.clone(),
                name: name.into(),
                max_raise_torque_nm: max_raise,
                max_lower_torque_nm: max_lower,
                min_lower_torque_nm: min_lower,
                thread_self_locking: actuator.self_locking(),
            },
            safety_factor,
        )?;
        jacks.push(Some(jack));
        if let Actuator::ScrewJack {
            screw, screw_length_m, ..
        } = actuator
        {
            // F_input > 0 pushes the nut away from B0: the screw is in compression.
            let axial: Vec<f64> = forces.iter().map(|f| -f * safety_factor).collect();
            let (tension, compression) = axial_envelope_n(&axial)?;
            let mut rod = RodInput::new(mechanism.station.clone(), "screw", screw_length_m, tension, compression);
            rod.end_fixity_factor = scene.sizing.screw_end_fixity_factor;
            rod.max_outer_radius_m = Some(screw.mean_radius_m);
            rods.push(size_rod(&rod, &screw_material)?);
        }
        // Members from their loads (axial tension positive) in every sample: two-force
        // members as rods, the others for axial force and bending together.
        for member in mechanism.mechanism.members() {
            let loads: Vec<&MemberLoad> = samples
                .iter()
                .filter_map(|s| s.member_loads.get(&member.name))
                .collect();
            if loads.is_empty() {
                continue;
            }
            let axial: Vec<f64> = loads.iter().map(|l| l.axial_n * safety_factor).collect();
            let (tension, compression) = axial_envelope_n(&axial)?;
            let mut rod = RodInput::new(
                mechanism.station.clone(),
                member.name,
                member.length_m,
                tension,
                compression,
            );
            rod.max_outer_radius_m = Some(member.radius_m);
            rod.end_fixity_factor = member.end_fixity_factor;
            if member.loading == MemberLoading::Bending {
                rod.bending = loads
                    .iter()
                    .map(|l| BendingLoad {
                        axial_n: l.axial_n * safety_factor,
                        bending_moment_nm: l.bending_moment_nm * safety_factor,
                    })
                    .collect();
            }
            rods.push(size_rod(&rod, &link_material)?);
        }
    }
    let mut tubes = Vec::new();
    let mut drive = None;
    // Stations on the drive line: placed and sized, at their arc length along the tube.
    let on_line: Vec<(usize, f64)> = mechanisms
        .iter()
        .enumerate()
        .filter(|(i, _)| jacks.get(*i).is_some_and(Option::is_some))
        .filter_map(|(i, record)| {
            let frame = &record.placed.as_ref()?.station.frame;
            let (origin, normal): (Point3<f64>, Vector3<f64>) = (frame.origin_ac(), frame.z_axis_ac().into_inner());
            Some((i, arc_length_at_plane(tube_path_ac, &origin, &normal)))
        })
        .collect();
    if tube_path_ac.len() >= 2 && !on_line.is_empty() {
        // Far end first: outboard to inboard along the tube; the motor sits at its start.
        let mut order = on_line;
        order.sort_by(|a, b| b.1.total_cmp(&a.1));
        let motor_torque = |i: usize| jacks[i].as_ref().map_or(0.0, |j| j.motor_torque_nm);
        let inputs: Vec<TorqueTubeInput> = order
            .iter()
            .enumerate()
            .map(|(k, &(i, s))| {
                let next = order.get(k + 1).map_or(0.0, |&(_, s_next)| s_next);
                TorqueTubeInput {
                    station: mechanisms[i].station.clone(),
                    drive_torque_nm: motor_torque(i),
                    length_m: (s - next).max(1e-3),
                    max_outer_radius_m: None,
                }
            })
            .collect();
        let shape = if scene.sizing.torque_tube_inner_to_outer_ratio > 0.0 {
            SectionShape::try_tube(scene.sizing.torque_tube_inner_to_outer_ratio)?
        } else {
            SectionShape::Solid
        };
        tubes = size_torque_tubes(&inputs, scene.sizing.gearbox_efficiency, shape, &tube_material)?;
        // All actuators' drive shafts turn together, at the first one's speed.
        let angular_speed = mechanisms[order[0].0].mechanism.actuator().shaft_speed_radps();
        let ordered_torques: Vec<f64> = order.iter().map(|&(i, _)| motor_torque(i)).collect();
        let work = deployment_work(scene, mechanisms, &reports, &order)?;
        drive = Some(drive_demand(
            &ordered_torques,
            scene.sizing.gearbox_efficiency,
            angular_speed,
            work,
        )?);
    }
    let jacks = jacks.into_iter().flatten().collect();
    Ok((SizingReport::assemble(rods, jacks, tubes, drive), notes))
}

/// A station on the drive line whose actuator input runs backwards over the deployment (a
/// given screw mount that shortens the screw): the torque tube turns every actuator one
/// way, so this is an input problem at the key that placed the actuator. Which way the
/// screw runs is known only once the mechanism is synthesised (the attachment is searched
/// for the first that keeps clear).
fn input_runs_backwards(scene: &Scene, record: &StationRecord) -> crate::scene::SceneError {
    let station = &scene.station[record.index.min(scene.station.len().saturating_sub(1))];
    let given_mount = station.mechanism.kind().gives_actuator_mount();
    let key = if given_mount {
        format!("station[{}].mechanism.actuator_mount_m", record.index)
    } else {
        format!("station[{}].mechanism", record.index)
    };
    crate::scene::SceneError::Invalid(vec![crate::scene::Problem::new(
        key,
        format!(
            "station {}'s actuator runs backwards as the flap deploys (its screw shortens): the torque tube's drive line turns every actuator one way to deploy; give a mount whose screw lengthens, or leave actuator_mount_m out to have it searched",
            record.station
        ),
    )])
}

/// Work per deployment for each load case: the raising torque of every station on the
/// drive line integrated over its drive shaft's rotation (2 pi per lead of nut travel, or
/// the gear ratio per radian of a rotary actuator's output), divided
/// by the gearbox efficiency. A load case counts only where every station's sweep reached
/// the end (a partial integral would understate it).
fn deployment_work(
    scene: &Scene,
    mechanisms: &[StationRecord],
    reports: &[Option<&MechanismReport>],
    order: &[(usize, f64)],
) -> Result<Vec<DeploymentWork>> {
    let mut works = Vec::new();
    for case in &scene.loads.cases {
        let mut total = 0.0;
        let mut complete = true;
        for &(i, _) in order {
            let sweep = reports[i]
                .as_ref()
                .and_then(|r| r.load_cases.iter().find(|s| s.load_case == case.name));
            let Some(sweep) = sweep.filter(|s| s.stopped.is_none() && s.samples.len() >= 2) else {
                complete = false;
                break;
            };
            let actuator = mechanisms[i].mechanism.actuator();
            let per_input = actuator.shaft_angle_per_input();
            if let (Some(first), Some(last)) = (sweep.samples.first(), sweep.samples.last()) {
                if per_input * (last.input - first.input) < 0.0 {
                    return Err(input_runs_backwards(scene, &mechanisms[i]).into());
                }
            }
            let angles: Vec<f64> = sweep
                .samples
                .iter()
                .map(|s| per_input * (s.input - sweep.samples[0].input))
                .collect();
            let torques: Vec<f64> = sweep
                .samples
                .iter()
                .map(|s| actuator.shaft_torques(s.actuator_load).raise_torque_nm)
                .collect();
            total += deployment_work_j(&angles, &torques)?;
        }
        if complete {
            works.push(DeploymentWork {
                load_case: case.name.clone(),
                work_j: total / scene.sizing.gearbox_efficiency,
            });
        }
    }
    Ok(works)
}

/// Arc length, from the first point, where the polyline crosses the plane through
/// `origin` with `normal` (the crossing nearest `origin` when there are several); where
/// the polyline misses the plane, the arc length of its point nearest `origin`.
fn arc_length_at_plane(path: &[Point3<f64>], origin: &Point3<f64>, normal: &Vector3<f64>) -> f64 {
    let mut crossing: Option<(f64, f64)> = None;
    let mut nearest = (f64::INFINITY, 0.0);
    let mut walked = 0.0;
    for pair in path.windows(2) {
        let segment = pair[1] - pair[0];
        let length = segment.norm();
        if length > 0.0 {
            let t_nearest = ((origin - pair[0]).dot(&segment) / (length * length)).clamp(0.0, 1.0);
            let distance = (pair[0] + segment * t_nearest - origin).norm();
            if distance < nearest.0 {
                nearest = (distance, walked + t_nearest * length);
            }
            let along = normal.dot(&segment);
            if along.abs() > 1e-12 * length * normal.norm() {
                let t = normal.dot(&(origin - pair[0])) / along;
                if (0.0..=1.0).contains(&t) {
                    let distance = (pair[0] + segment * t - origin).norm();
                    if crossing.is_none_or(|(d, _)| distance < d) {
                        crossing = Some((distance, walked + t * length));
                    }
                }
            }
        }
        walked += length;
    }
    crossing.map_or(nearest.1, |(_, s)| s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stations_are_placed_by_arc_length_along_the_tube() {
        // An L-shaped tube: 2 m along y, then 1 m along x.
        let path = [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(0.0, 2.0, 0.0),
            Point3::new(1.0, 2.0, 0.0),
        ];
        let y = Vector3::y();
        // A station plane y = 0.5 with its origin 0.4 m off the tube: arc length 0.5 (the
        // old measure, to the origin, gave 0.64 m).
        let s = arc_length_at_plane(&path, &Point3::new(0.4, 0.5, 0.0), &y);
        assert!((s - 0.5).abs() < 1e-12, "{s}");
        // A plane tilted 45 deg about z through (0.3, 0.5): crosses the first leg at y = 0.2.
        let tilted = Vector3::new(1.0, 1.0, 0.0);
        let s = arc_length_at_plane(&path, &Point3::new(0.3, 0.5, 0.0), &tilted);
        assert!((s - 0.8).abs() < 1e-12, "{s}");
        // The plane x = 0.3 crosses the second leg 0.3 m along it.
        let s = arc_length_at_plane(&path, &Point3::new(0.3, 2.5, 0.0), &Vector3::x());
        assert!((s - 2.3).abs() < 1e-12, "{s}");
        // A plane the tube never reaches: the nearest point (clamped to the end).
        let s = arc_length_at_plane(&path, &Point3::new(0.0, -1.0, 0.0), &y);
        assert!(s.abs() < 1e-12, "{s}");
    }
}
