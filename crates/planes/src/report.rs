//! Serializable per-station report records (the `stations` entries of report.json).

use crate::section::Section;
use crate::station::{PlaneConstruction, Station};

/// Station frame in the aircraft frame, as written to the report.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FrameReport {
    /// Origin A0, aircraft frame, metres.
    pub origin_m: [f64; 3],
    /// Station x axis (in plane, horizontal, towards the nose), aircraft frame, unit.
    pub x_axis: [f64; 3],
    /// Station y axis (in plane, up-ish), aircraft frame, unit.
    pub y_axis: [f64; 3],
    /// Station z axis (plane normal, outboard), aircraft frame, unit.
    pub z_axis: [f64; 3],
}

/// One section polygon set, as written to the report.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SectionReport {
    /// Part name.
    pub part_name: String,
    /// Closed polygons, station frame (x, y), metres.
    pub polygons: Vec<Vec<[f64; 2]>>,
}

/// Per-station report entry.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct StationReport {
    /// Station name.
    pub name: String,
    /// Plane construction used.
    pub construction: PlaneConstruction,
    /// Station frame in the aircraft frame.
    pub frame: FrameReport,
    /// Skew angle of the plane against the streamwise plane, degrees (planform).
    pub skew_angle_deg: f64,
    /// Largest out-of-plane motion of any attachment point over the deployment, m.
    pub out_of_plane_residual_m: f64,
    /// Per attachment point: its largest out-of-plane motion, m.
    pub attachment_residuals_m: Vec<f64>,
    /// Section cuts of the parts by this station's plane.
    pub sections: Vec<SectionReport>,
}

fn array(v: &nalgebra::Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

impl StationReport {
    /// Builds the report entry of `station` with its `sections`.
    pub fn new(station: &Station, sections: &[Section]) -> Self {
        let frame = &station.frame;
        Self {
            name: station.name.clone(),
            construction: station.construction,
            frame: FrameReport {
                origin_m: array(&frame.origin_ac().coords),
                x_axis: array(&frame.x_axis_ac()),
                y_axis: array(&frame.y_axis_ac()),
                z_axis: array(&frame.z_axis_ac()),
            },
            skew_angle_deg: station.skew_angle_rad.to_degrees(),
            out_of_plane_residual_m: station.max_out_of_plane_residual_m(),
            attachment_residuals_m: station.attachment_residuals_m.clone(),
            sections: sections
                .iter()
                .map(|s| SectionReport {
                    part_name: s.part_name.clone(),
                    polygons: s
                        .polygons
                        .iter()
                        .map(|p| p.iter().map(|q| [q.x, q.y]).collect())
                        .collect(),
                })
                .collect(),
        }
    }
}
