//! Planes stage: a mechanism plane and station frame per station (thesis construction:
//! perpendicular to the hinge axis at A0 = P + d), its skew and residuals, and the section
//! cut of every part in it.

use anyhow::{Context, Result};
use flapwright_geom::parts::{Part, WingModel};
use flapwright_planes::{
    compute_station, cut_mesh, out_of_plane_residual_m, thesis_stations, FlapDeployment, FlapSetting, HingeAxis, Plane,
    Section, Station,
};
use nalgebra::{Point2, Point3, Vector3};

use crate::pipeline::mechanisms::StationRecord;
use crate::scene::Scene;

/// Deployment samples for the out-of-plane residual of the attachment points.
const RESIDUAL_SAMPLES: usize = 64;

/// A station placed in 3D.
#[derive(Debug, Clone)]
pub struct PlacedStation {
    /// The plane, frame, skew and residuals (the residuals once the mechanism is known:
    /// [`attachment_residuals`]).
    pub station: Station,
    /// Section cuts of every part in the station plane.
    pub sections: Vec<Section>,
    /// The flap's 3D motion the residuals are measured over.
    pub deployment: FlapDeployment,
}

impl PlacedStation {
    /// The section polygons (station frame) of the parts `wanted` accepts by name.
    pub fn polygons_of(&self, wanted: impl Fn(&str) -> bool) -> Vec<Vec<Point2<f64>>> {
        self.sections
            .iter()
            .filter(|s| wanted(&s.part_name))
            .flat_map(|s| s.polygons.iter().cloned())
            .collect()
    }
}

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
/// flap's 3D motion.
pub fn attachment_residuals(records: &mut [StationRecord]) -> Result<()> {
    for record in records.iter_mut() {
        let attachments = record.mechanism.flap_attachments();
        let Some(placed) = record.placed.as_mut() else {
            continue;
        };
        let frame = placed.station.frame;
        let poses = placed.deployment.sample_poses_ac(RESIDUAL_SAMPLES)?;
        placed.station.attachment_residuals_m = attachments
            .iter()
            .map(|p| out_of_plane_residual_m(&frame, &frame.aircraft_point_from_station(&p.position), &poses))
            .collect();
    }
    Ok(())
}

fn place(scene: &Scene, model: &WingModel, parts: &[Part], index: usize, dihedral_rad: f64) -> Result<PlacedStation> {
    let station = &scene.station[index];
    let flap_name = station.flap.as_deref().context("station has no flap")?;
    let flap_index = scene
        .flap
        .iter()
        .position(|f| f.name == flap_name)
        .context("station names an unknown flap")?;
    let flap_scene = &scene.flap[flap_index];
    let flap = &model.flaps()[flap_index];
    let (point_ac, direction_ac) = flap.hinge_axis_ac();
    let axis = HingeAxis::try_new(point_ac, direction_ac.into_inner())?;
    // Thesis step 1: P is where the inner flap side plane (streamwise, at the flap body's
    // inboard end) meets the axis; step 2: A0 = P + d along it.
    let (inboard_y, _) = flap.body_span_m(model.wing())?;
    let inner_side = Plane::try_new(Point3::new(0.0, inboard_y, 0.0), Vector3::y())?;
    let offset = station.axis_offset_m.unwrap_or(0.0);
    let constructed = thesis_stations(&axis, &inner_side, offset, &[0.0])
        .with_context(|| format!("placing station {}", station.name))?;
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
    .with_context(|| format!("station {}", station.name))?;
    let sections = parts
        .iter()
        .map(|part| cut_mesh(&part.mesh, &placed.frame, &part.name))
        .filter(|cut| !matches!(cut, Ok(section) if section.polygons.is_empty()))
        .collect::<flapwright_planes::Result<Vec<_>>>()
        .with_context(|| format!("cutting the parts at station {}", station.name))?;
    Ok(PlacedStation {
        station: placed,
        sections,
        deployment,
    })
}
