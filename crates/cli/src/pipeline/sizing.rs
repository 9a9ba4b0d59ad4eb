//! Sizing stage: screw jacks (motor torque, self-locking), screws as rods (strength and
//! Euler buckling), the torque-tube line between the stations, drive power and masses.

use anyhow::{Context, Result};
use flapwright_sizing::{
    axial_envelope_n, drive_demand, size_rod, size_screw_jack, size_torque_tubes, Material, RodInput, ScrewJackInput,
    SectionShape, SizingReport, TorqueTubeInput,
};
use nalgebra::Point3;

use crate::pipeline::mechanisms::{MechanismReport, StationMechanism};
use crate::scene::Scene;

/// The material a scene names: a preset or one of its `[[materials]]`.
fn material(scene: &Scene, name: &str) -> Result<Material> {
    let material = match name {
        "steel-4340" => Material::steel_4340(),
        "aluminium-7075-t6" => Material::aluminium_7075_t6(),
        "titanium-ti-6al-4v" => Material::titanium_ti_6al_4v(),
        custom => {
            let m = scene
                .materials
                .iter()
                .find(|m| m.name == custom)
                .with_context(|| format!("material {custom} (validation should have caught this)"))?;
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

/// Sizes everything the mechanism loads drive. `station_origins_ac` (A0 of each station,
/// aircraft frame; empty without a wing) gives the torque-tube lengths: the line runs from
/// the outermost station inboard to the motor at the flap's inboard end.
pub fn size_all(
    scene: &Scene,
    mechanisms: &[StationMechanism],
    reports: &[MechanismReport],
    station_origins_ac: &[Point3<f64>],
    motor_position_ac: Option<Point3<f64>>,
) -> Result<SizingReport> {
    let safety_factor = scene
        .loads
        .safety_factor
        .unwrap_or(flapwright_sizing::CS25_SAFETY_FACTOR);
    let screw_material = material(scene, &scene.sizing.screw_material)?;
    let tube_material = material(scene, &scene.sizing.torque_tube_material)?;
    let mut rods = Vec::new();
    let mut jacks = Vec::new();
    for (mechanism, report) in mechanisms.iter().zip(reports) {
        let samples = report.load_cases.iter().flat_map(|case| case.samples.iter());
        let forces: Vec<f64> = samples.clone().map(|s| s.actuator_force_n).collect();
        if forces.is_empty() {
            continue;
        }
        let max_raise = samples
            .clone()
            .map(|s| s.raise_torque_nm)
            .fold(f64::NEG_INFINITY, f64::max);
        // The smallest lowering torque decides self-locking over the whole deployment.
        let min_lower = samples.map(|s| s.lower_torque_nm).fold(f64::INFINITY, f64::min);
        let jack = size_screw_jack(
            &ScrewJackInput {
                station: mechanism.station.clone(),
                name: "screw-jack".into(),
                max_raise_torque_nm: max_raise,
                max_lower_torque_nm: min_lower,
            },
            safety_factor,
        )?;
        jacks.push(jack);
        // F_input > 0 pushes the nut away from B0: the screw is in compression.
        let axial: Vec<f64> = forces.iter().map(|f| -f * safety_factor).collect();
        let (tension, compression) = axial_envelope_n(&axial)?;
        let spec = mechanism.track.spec();
        let mut rod = RodInput::new(
            mechanism.station.clone(),
            "screw",
            spec.screw_length_m,
            tension,
            compression,
        );
        rod.end_fixity_factor = scene.sizing.screw_end_fixity_factor;
        rod.max_outer_radius_m = Some(spec.screw.mean_radius_m);
        rods.push(size_rod(&rod, &screw_material)?);
    }
    let mut tubes = Vec::new();
    let mut drive = None;
    if !station_origins_ac.is_empty() && !jacks.is_empty() {
        // Far end first: order the stations outboard to inboard (aircraft y).
        let mut order: Vec<usize> = (0..station_origins_ac.len()).collect();
        order.sort_by(|&a, &b| station_origins_ac[b].y.total_cmp(&station_origins_ac[a].y));
        let motor = motor_position_ac.unwrap_or(station_origins_ac[*order.last().unwrap_or(&0)]);
        let inputs: Vec<TorqueTubeInput> = order
            .iter()
            .enumerate()
            .map(|(k, &i)| {
                let next = order.get(k + 1).map_or(motor, |&j| station_origins_ac[j]);
                TorqueTubeInput {
                    station: mechanisms[i].station.clone(),
                    drive_torque_nm: jacks[i].motor_torque_nm,
                    length_m: (station_origins_ac[i] - next).norm().max(1e-3),
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
        // All screws turn together: drive speed = nut speed / lead turns per second.
        let spec = mechanisms[0].track.spec();
        let angular_speed = 2.0 * std::f64::consts::PI * spec.nominal_input_speed_mps / spec.screw.lead_m;
        let deployment_time = mechanisms[0].track.synthesis().stroke_m / spec.nominal_input_speed_mps;
        let ordered_torques: Vec<f64> = order.iter().map(|&i| jacks[i].motor_torque_nm).collect();
        drive = Some(drive_demand(
            &ordered_torques,
            scene.sizing.gearbox_efficiency,
            angular_speed,
            deployment_time,
        )?);
    }
    Ok(SizingReport::assemble(rods, jacks, tubes, drive))
}
