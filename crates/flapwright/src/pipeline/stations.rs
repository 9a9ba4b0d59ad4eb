//! Planes stage: a mechanism plane and station frame per station (thesis construction:
//! perpendicular to the hinge axis at A0 = P + d), its skew and residuals, and the section
//! cut of every part in it.

use flapwright_geom::parts::{Part, WingModel};
use flapwright_planes::{
    compute_station, cut_mesh, dihedral_up_vector_ac, out_of_plane_residual_m, skew_direction_ac,
    skewed_plane_normal_ac, thesis_stations, FlapDeployment, FlapSetting, HingeAxis, Plane, PlaneConstruction, Section,
    Station,
};
use nalgebra::{Isometry3, Point3, Vector3};

use crate::error::{Error, Result};
use crate::pipeline::flap_position;
use crate::pipeline::record::{PlacedStation, StationRecord};
use crate::scene::Scene;

/// Deployment samples for the out-of-plane residual of the attachment points.
const RESIDUAL_SAMPLES: usize = 64;

/// Places every station of the scene on its flap and cuts every part by its plane, in the
/// scene's station order (before synthesis: kinds synthesised from the flap settings need
/// the sections).
pub fn place_all(scene: &Scene, model: &WingModel, parts: &[Part]) -> Result<Vec<PlacedStation>> {
    let dihedral_rad = 0.0; // Only the skew-corrected construction uses it; see below.
    (0..scene.station.len())
        .map(|index| place(scene, model, parts, index, dihedral_rad))
        .collect()
}

/// The out-of-plane residual of each record's flap attachments (its mechanism's) over the
/// flap's 3D motion: where several stations carry the flap, the rigid motion fitted to
/// all of them as their mechanisms move them (the motion the interference check uses);
/// where one station does, the turn about the hinge line, which a plane perpendicular to
/// it holds exactly.
pub fn attachment_residuals(records: &mut [StationRecord]) -> Result<()> {
    let mut poses_by_record: Vec<Option<Vec<Isometry3<f64>>>> = vec![None; records.len()];
    for (flap, carriers) in crate::pipeline::record::flaps_on_several_stations(records) {
        let attachments_ac: Vec<Point3<f64>> = carriers
            .iter()
            .filter_map(|r| r.placed.as_ref().map(|p| (r, p.station.frame)))
            .flat_map(|(r, frame)| {
                r.mechanism
                    .flap_attachments()
                    .into_iter()
                    .map(move |a| frame.aircraft_point_from_station(&a.position))
            })
            .collect();
        let motion = crate::pipeline::flap_motion::fitted_flap_motion(
            flap,
            flapwright_interference::FlapElement::Main,
            &carriers,
            &attachments_ac,
        )
        .map_err(|source| Error::FittedFlapMotion {
            flap: flap.to_string(),
            source: Box::new(source),
        })?;
        let poses = (0..=RESIDUAL_SAMPLES)
            .map(|k| Ok(motion.fit_at(k as f64 / RESIDUAL_SAMPLES as f64)?.motion))
            .collect::<Result<Vec<_>>>()?;
        for (index, record) in records.iter().enumerate() {
            if record.flap.as_deref() == Some(flap) && record.placed.is_some() {
                poses_by_record[index] = Some(poses.clone());
            }
        }
    }
    for (record, fitted) in records.iter_mut().zip(poses_by_record) {
        let attachments = record.mechanism.flap_attachments();
        let Some(placed) = record.placed.as_mut() else {
            continue;
        };
        let frame = placed.station.frame;
        let poses = match fitted {
            Some(poses) => poses,
            None => placed.deployment.sample_poses_ac(RESIDUAL_SAMPLES)?,
        };
        placed.station.attachment_residuals_m = attachments
            .iter()
            .map(|p| out_of_plane_residual_m(&frame, &frame.aircraft_point_from_station(&p.position), &poses))
            .collect();
    }
    Ok(())
}

fn place(scene: &Scene, model: &WingModel, parts: &[Part], index: usize, dihedral_rad: f64) -> Result<PlacedStation> {
    let station = &scene.station[index];
    let flap_name = station.flap.as_deref().ok_or_else(|| Error::StationWithoutFlap {
        station: station.name.clone(),
    })?;
    let flap_index = scene
        .flap
        .iter()
        .position(|f| f.name == flap_name)
        .ok_or_else(|| Error::UnknownFlap {
            station: station.name.clone(),
            flap: flap_name.to_string(),
        })?;
    let flap_scene = &scene.flap[flap_index];
    let flap = &model.flaps()[flap_index];
    let (point_ac, direction_ac) = flap.hinge_axis_ac();
    let axis = HingeAxis::try_new(point_ac, direction_ac.into_inner())?;
    // Thesis step 1: P is where the inner flap side plane (streamwise, at the flap body's
    // inboard end) meets the axis; step 2: A0 = P + d along it.
    let (inboard_y, _) = flap.body_span_m(model.wing())?;
    let inner_side = Plane::try_new(Point3::new(0.0, inboard_y, 0.0), Vector3::y())?;
    let offset = station.axis_offset_m.unwrap_or(0.0);
    let constructed = thesis_stations(&axis, &inner_side, offset, &[0.0]).map_err(|source| Error::PlacingStation {
        station: station.name.clone(),
        source,
    })?;
    let a0_ac = constructed.a0_ac;
    let settings = [0.0, flap_scene.settings.takeoff_deg, flap_scene.settings.landing_deg]
        .map(|deg| FlapSetting {
            deflection_rad: deg.to_radians(),
            ..FlapSetting::stowed()
        })
        .to_vec();
    let deployment = FlapDeployment {
        hinge: axis,
        base_point_ac: a0_ac,
        overlap_axis_ac: nalgebra::Vector3::z_axis(),
        gap_axis_ac: nalgebra::Vector3::x_axis(),
        settings,
    };
    // The plane perpendicular to the hinge axis (the thesis construction); the flap's
    // motion-derived plane of `003_...` Fig. 4 is not offered yet, so the dihedral does not
    // enter.
    let placed = compute_station(
        &station.name,
        &deployment,
        a0_ac,
        &[],
        None,
        dihedral_rad,
        RESIDUAL_SAMPLES,
    )
    .map_err(|source| Error::ComputingStation {
        station: station.name.clone(),
        source,
    })?;
    Ok(PlacedStation {
        sections: cut_parts(parts, &placed)?,
        station: placed,
        deployment,
        setting_poses_ac: None,
    })
}

/// Every part's section cut by the station's plane (parts the plane misses left out).
fn cut_parts(parts: &[Part], station: &Station) -> Result<Vec<Section>> {
    parts
        .iter()
        .map(|part| cut_mesh(&part.mesh, &station.frame, &part.name))
        .filter(|cut| !matches!(cut, Ok(section) if section.polygons.is_empty()))
        .collect::<flapwright_planes::Result<Vec<_>>>()
        .map_err(|source| Error::CuttingParts {
            station: station.name.clone(),
            source,
        })
}

/// Gives every station the 3D poses its flap's settings ask for
/// ([`flap_position::setting_poses`], fitted on the planes perpendicular to the hinge line,
/// where the settings are measured), and re-places the stations whose scene asks for the
/// skew-corrected plane (`plane = "skew-corrected"`): normal = skew direction x dihedral
/// vector (`003_...` section 2, Fig. 4), the skew direction being how the flap's landing
/// pose moves the station origin (the forward attachment point on the hinge line) and
/// the dihedral vector the wing's up direction tilted by the local panel dihedral. As in
/// `003_...`, the poses come first and the planes from them, once: each station's
/// precision positions are then those poses as its plane sees them.
pub fn apply_flap_motion(
    scene: &Scene,
    model: &WingModel,
    parts: &[Part],
    mut placed: Vec<PlacedStation>,
) -> Result<Vec<PlacedStation>> {
    let poses = flap_position::setting_poses(scene, &placed)?;
    for (i, (station, poses)) in placed.iter_mut().zip(poses).enumerate() {
        station.setting_poses_ac = poses;
        if scene.station[i].plane != Some(PlaneConstruction::SkewCorrected) {
            continue;
        }
        let name = &scene.station[i].name;
        let [_, landing] = poses.ok_or_else(|| Error::SkewWithoutSettings { station: name.clone() })?;
        let origin = station.station.frame.origin_ac();
        let dihedral_rad = model.wing().dihedral_rad_at(origin.y)?;
        let skew = skew_direction_ac(&origin, &(landing * origin)).map_err(|source| Error::SkewDirection {
            station: name.clone(),
            source,
        })?;
        let normal = skewed_plane_normal_ac(&skew, &dihedral_up_vector_ac(dihedral_rad)).map_err(|source| {
            Error::SkewCorrectedPlane {
                station: name.clone(),
                source,
            }
        })?;
        let moved = Station::try_with_normal(name, PlaneConstruction::SkewCorrected, origin, &normal)?;
        station.sections = cut_parts(parts, &moved)?;
        station.station = moved;
    }
    Ok(placed)
}
