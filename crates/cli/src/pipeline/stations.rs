//! Planes stage: a mechanism plane and station frame per station (thesis construction:
//! perpendicular to the hinge axis at A0 = P + d), its skew and residuals, and the section
//! cut of every part in it.

use anyhow::{Context, Result};
use flapwright_geom::parts::{Part, WingModel};
use flapwright_planes::{
    compute_station, cut_mesh, thesis_stations, FlapDeployment, FlapSetting, HingeAxis, Plane, Section, Station,
    StationFrame,
};
use nalgebra::{Point2, Point3, Vector3};

use crate::pipeline::mechanisms::StationRecord;
use crate::scene::Scene;

/// Deployment samples for the out-of-plane residual of the attachment points.
const RESIDUAL_SAMPLES: usize = 64;

/// A station placed in 3D.
#[derive(Debug, Clone)]
pub struct PlacedStation {
    /// The plane, frame, skew and residuals.
    pub station: Station,
    /// Section cuts of every part in the station plane.
    pub sections: Vec<Section>,
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

/// Places every station on its flap and cuts every part by its plane (each record's
/// `placed`). The mechanisms give the flap attachments whose residuals are reported.
pub fn place_all(scene: &Scene, model: &WingModel, parts: &[Part], records: &mut [StationRecord]) -> Result<()> {
    let dihedral_rad = 0.0; // Only the skew-corrected construction uses it; see below.
    for record in records.iter_mut() {
        record.placed = Some(place(scene, model, parts, record, dihedral_rad)?);
    }
    Ok(())
}

fn place(
    scene: &Scene,
    model: &WingModel,
    parts: &[Part],
    record: &StationRecord,
    dihedral_rad: f64,
) -> Result<PlacedStation> {
    let station = &scene.station[record.index];
    let flap_name = record.flap.as_deref().context("station has no flap")?;
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
        .with_context(|| format!("placing station {}", record.station))?;
    let a0_ac = constructed.a0_ac;
    let frame = StationFrame::try_from_origin_and_normal(a0_ac, &axis.direction_ac)?;
    let attachments_ac: Vec<Point3<f64>> = record
        .mechanism
        .flap_attachments()
        .iter()
        .map(|p| frame.aircraft_point_from_station(&p.position))
        .collect();
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
    // The circular-arc track turns the flap about the fixed hinge line: a pure rotation,
    // so the default construction is the plane perpendicular to the axis and the dihedral
    // does not enter.
    let placed = compute_station(
        &record.station,
        &deployment,
        a0_ac,
        &attachments_ac,
        None,
        dihedral_rad,
        RESIDUAL_SAMPLES,
    )
    .with_context(|| format!("station {}", record.station))?;
    let sections = parts
        .iter()
        .map(|part| cut_mesh(&part.mesh, &placed.frame, &part.name))
        .filter(|cut| !matches!(cut, Ok(section) if section.polygons.is_empty()))
        .collect::<flapwright_planes::Result<Vec<_>>>()
        .with_context(|| format!("cutting the parts at station {}", record.station))?;
    Ok(PlacedStation {
        station: placed,
        sections,
    })
}
