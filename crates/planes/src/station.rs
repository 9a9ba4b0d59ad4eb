//! Support stations: the plane construction chosen for a station, its frame, skew angle
//! and the out-of-plane motion of the flap attachment points over the deployment.

use nalgebra::{Isometry3, Point3, Unit, Vector3};

use crate::error::Result;
use crate::frame::StationFrame;
use crate::motion::FlapDeployment;
use crate::skew::{dihedral_up_vector_ac, skew_angle_rad, skew_direction_ac, skewed_plane_normal_ac};

/// Conical rotations below this count as none when choosing the default construction, rad.
pub const PURE_ROTATION_ANGLE_TOL_RAD: f64 = 1e-12;
/// Translations below this count as none when choosing the default construction, m.
pub const PURE_ROTATION_LENGTH_TOL_M: f64 = 1e-12;

/// How a station's mechanism plane is built.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum PlaneConstruction {
    /// Perpendicular to the hinge axis (thesis `000`, Ch. 4 step 2).
    PerpendicularToAxis,
    /// Normal = skew direction x dihedral vector (Zaccai et al. `003`, Fig. 4).
    SkewCorrected,
}

impl PlaneConstruction {
    /// Default for a deployment: a pure rotation about the hinge line keeps every point in
    /// a plane perpendicular to the axis, so that plane is exact; otherwise skew-correct.
    pub fn default_for(deployment: &FlapDeployment) -> Self {
        if deployment.is_pure_rotation(PURE_ROTATION_ANGLE_TOL_RAD, PURE_ROTATION_LENGTH_TOL_M) {
            Self::PerpendicularToAxis
        } else {
            Self::SkewCorrected
        }
    }
}

/// One support station: its plane, frame, skew and attachment residuals.
#[derive(Debug, Clone, PartialEq)]
pub struct Station {
    /// Station name (from the scene).
    pub name: String,
    /// Construction used for the plane.
    pub construction: PlaneConstruction,
    /// Station frame (origin at the forward attachment / hinge point A0).
    pub frame: StationFrame,
    /// Skew angle against the streamwise plane, rad (see [`skew_angle_rad`]).
    pub skew_angle_rad: f64,
    /// Per attachment point: largest out-of-plane motion over the deployment, m.
    pub attachment_residuals_m: Vec<f64>,
}

impl Station {
    /// Largest out-of-plane motion of any attachment point over the deployment, m
    /// (0 when there are no attachment points).
    pub fn max_out_of_plane_residual_m(&self) -> f64 {
        self.attachment_residuals_m.iter().copied().fold(0.0, f64::max)
    }
}

impl Station {
    /// A station at `origin_ac` whose plane has normal `normal_ac` (aircraft frame), built
    /// by `construction`, with no attachment residuals yet: for a plane whose normal comes
    /// from a motion known outside this crate (a flap's fitted 3D pose; see
    /// [`crate::skew::skewed_plane_normal_ac`]).
    pub fn try_with_normal(
        name: &str,
        construction: PlaneConstruction,
        origin_ac: Point3<f64>,
        normal_ac: &Unit<Vector3<f64>>,
    ) -> Result<Self> {
        let frame = StationFrame::try_from_origin_and_normal(origin_ac, normal_ac)?;
        Ok(Station {
            name: name.to_owned(),
            construction,
            frame,
            skew_angle_rad: skew_angle_rad(&frame.z_axis_ac()),
            attachment_residuals_m: Vec::new(),
        })
    }
}

/// Largest motion (m) of a flap point normal to the plane of `frame`, over `poses`
/// (stowed-to-deployed rigid flap poses, aircraft frame): max_i |n · (T_i p - p)|.
/// This is what the spherical or bearing joint at that point must absorb (`003` Fig. 13).
pub fn out_of_plane_residual_m(
    frame: &StationFrame,
    point_stowed_ac: &Point3<f64>,
    poses_ac: &[Isometry3<f64>],
) -> f64 {
    let normal = frame.z_axis_ac();
    poses_ac
        .iter()
        .map(|pose| {
            normal
                .dot(&(pose.transform_point(point_stowed_ac) - point_stowed_ac))
                .abs()
        })
        .fold(0.0, f64::max)
}

/// Builds a station at `origin_ac` (stowed forward attachment point on the hinge line,
/// aircraft frame, m). The plane is perpendicular to the hinge axis, or skew-corrected
/// from the displacement of `origin_ac` between the first and the last setting and the
/// dihedral vector for `dihedral_rad`; `construction = None` picks
/// [`PlaneConstruction::default_for`]. Residuals of `attachments_ac` (stowed, aircraft
/// frame) over `samples` deployment poses.
pub fn compute_station(
    name: &str,
    deployment: &FlapDeployment,
    origin_ac: Point3<f64>,
    attachments_ac: &[Point3<f64>],
    construction: Option<PlaneConstruction>,
    dihedral_rad: f64,
    samples: usize,
) -> Result<Station> {
    let construction = construction.unwrap_or_else(|| PlaneConstruction::default_for(deployment));
    let normal = match construction {
        PlaneConstruction::PerpendicularToAxis => deployment.hinge.direction_ac,
        PlaneConstruction::SkewCorrected => {
            let stowed = deployment.pose_at_ac(0.0)?.transform_point(&origin_ac);
            let deployed = deployment.pose_at_ac(1.0)?.transform_point(&origin_ac);
            let skew = skew_direction_ac(&stowed, &deployed)?;
            skewed_plane_normal_ac(&skew, &dihedral_up_vector_ac(dihedral_rad))?
        }
    };
    let mut station = Station::try_with_normal(name, construction, origin_ac, &normal)?;
    let poses = deployment.sample_poses_ac(samples)?;
    station.attachment_residuals_m = attachments_ac
        .iter()
        .map(|p| out_of_plane_residual_m(&station.frame, p, &poses))
        .collect();
    Ok(station)
}
