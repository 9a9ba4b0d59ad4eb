//! Names, joint placements, limits, joint values and key points of one station's tree,
//! shared by the robot builder and the trajectory so that both always agree.

use std::collections::BTreeSet;

use nalgebra::{Point2, Point3};

use super::StationMechanism3d;
use crate::error::{Error, Result};
use crate::track_pose::Pose;
use crate::track_synthesis::{wrap, CircularArcTrack};

/// Samples used to find the largest joint rates for the URDF velocity limits.
const VELOCITY_LIMIT_SAMPLES: usize = 33;

/// Link and joint names of one station.
pub(crate) struct StationNames {
    pub station_link: String,
    pub fitting_link: String,
    pub screw_link: String,
    pub nut_link: String,
    pub mount_joint: String,
    pub hinge_joint: String,
    pub flap_mount_joint: String,
    pub screw_joint: String,
    pub nut_joint: String,
}

impl StationNames {
    pub fn new(station: &str) -> Self {
        let name = |suffix: &str| format!("{station}_{suffix}");
        Self {
            station_link: name("station"),
            fitting_link: name("flap_fitting"),
            screw_link: name("screw"),
            nut_link: name("nut"),
            mount_joint: name("station_mount"),
            hinge_joint: name("flap_hinge"),
            flap_mount_joint: name("flap_mount"),
            screw_joint: name("screw_pivot"),
            nut_joint: name("nut_slide"),
        }
    }

    /// The movable joints, in trajectory order.
    pub fn movable_joints(&self) -> [String; 3] {
        [
            self.hinge_joint.clone(),
            self.screw_joint.clone(),
            self.nut_joint.clone(),
        ]
    }
}

/// Joint limits (lower, upper) in trajectory order: hinge (rad), screw (rad), nut (m).
pub(crate) fn joint_limits(track: &CircularArcTrack) -> Result<[(f64, f64); 3]> {
    let synthesis = track.synthesis();
    let linkage = track.linkage();
    let (start, end) = (synthesis.stroke_start_m, synthesis.stroke_end_m);
    let stowed = synthesis.end_slider_angle_rad;
    // The screw direction is the same at both stroke ends (collinearity, thesis step 8), so
    // its extreme lies inside the stroke where B0A is tangent to A's circle about A0:
    // s = sqrt(a1² - a2²) (right angle at A).
    let (a1, a2) = (linkage.base_distance_m, linkage.crank_length_m);
    let tangent = ((a1 - a2) * (a1 + a2)).sqrt();
    let mut candidates = vec![start, end];
    if tangent.is_finite() && tangent > start && tangent < end {
        candidates.push(tangent);
    }
    let (mut lower, mut upper) = (0.0_f64, 0.0_f64);
    for input in candidates {
        let (_, slider) = linkage.angles(input)?;
        let relative = wrap(slider - stowed);
        lower = lower.min(relative);
        upper = upper.max(relative);
    }
    Ok([(0.0, track.spec().rotation_range_rad), (lower, upper), (start, end)])
}

/// Largest |rate| over the stroke at the spec's nominal nut speed, trajectory order:
/// hinge (rad/s), screw (rad/s), nut (m/s).
pub(crate) fn velocity_limits(track: &CircularArcTrack) -> Result<[f64; 3]> {
    let speed = track.spec().nominal_input_speed_mps;
    let mut limits = [0.0, 0.0, speed.abs()];
    for input in stroke_inputs(track, VELOCITY_LIMIT_SAMPLES) {
        let pose = track.pose(input, speed, 0.0)?;
        limits[0] = f64::max(limits[0], pose.linkage.crank_rate_radps.abs());
        limits[1] = f64::max(limits[1], pose.linkage.slider_rate_radps.abs());
    }
    Ok(limits)
}

/// `samples` evenly spaced nut positions from s34,i to s34,f, both ends exact.
pub(crate) fn stroke_inputs(track: &CircularArcTrack, samples: usize) -> Vec<f64> {
    // The seam's spacing, so trajectory samples are the report's deployment samples.
    crate::FlapMechanism::input_range(track).samples(samples)
}

/// Joint values of a pose, trajectory order: deflection (rad), θ13 - θ13,i (rad), s34 (m).
pub(crate) fn joint_values(track: &CircularArcTrack, pose: &Pose) -> [f64; 3] {
    let stowed = track.synthesis().end_slider_angle_rad;
    [
        pose.deflection_rad,
        wrap(pose.linkage.slider_angle_rad - stowed),
        pose.linkage.input_m,
    ]
}

/// Absolute direction of the stowed screw in the station plane (rad from +x): α0 + θ13,i.
pub(crate) fn screw_stowed_direction_rad(track: &CircularArcTrack) -> f64 {
    wrap(track.spec().base_angle_rad + track.synthesis().end_slider_angle_rad)
}

/// Which point of a pose a key point follows.
#[derive(Clone, Copy)]
pub(crate) enum PosePoint {
    Hinge,
    ScrewMount,
    ScrewEnd,
    NutPivot,
    CentreOfMass,
    OuterPin,
    InnerPin,
}

impl PosePoint {
    /// The point's position in the station frame (m) at `pose`.
    pub fn at(self, track: &CircularArcTrack, pose: &Pose) -> Point2<f64> {
        match self {
            Self::Hinge => Point2::origin(),
            Self::ScrewMount => track.synthesis().screw_mount_m,
            Self::ScrewEnd => pose.screw_end_b.position_m,
            Self::NutPivot => pose.nut_pivot_a.position_m,
            Self::CentreOfMass => pose.centre_of_mass_d.position_m,
            Self::OuterPin => pose.outer_pin_f.position_m,
            Self::InnerPin => pose.inner_pin_g.position_m,
        }
    }
}

/// A key point: its name, the link that carries it, where it sits in that link's frame
/// (m) and which pose point it must follow.
pub(crate) struct KeyPointLayout {
    pub name: String,
    pub link: String,
    pub position_link_m: Point3<f64>,
    pub follows: PosePoint,
}

/// Key points of one station (and of its flap link when it owns the flap).
pub(crate) fn key_points(station: &StationMechanism3d) -> Vec<KeyPointLayout> {
    let names = StationNames::new(&station.name);
    let track = station.track;
    let synthesis = track.synthesis();
    let in_plane = |p: Point2<f64>| Point3::new(p.x, p.y, 0.0);
    let on_flap = [
        ("A", synthesis.nut_pivot_stowed_m, PosePoint::NutPivot),
        ("D", track.spec().centre_of_mass_stowed_m, PosePoint::CentreOfMass),
        ("F", synthesis.outer_pin_stowed_m, PosePoint::OuterPin),
        ("G", synthesis.inner_pin_stowed_m, PosePoint::InnerPin),
    ];
    let point = |group: &str, label: &str, link: &str, local: Point3<f64>, follows| KeyPointLayout {
        name: format!("{group}.{label}"),
        link: link.to_owned(),
        position_link_m: local,
        follows,
    };
    let s = station.name.as_str();
    let mut points = vec![
        point(s, "A0", &names.station_link, Point3::origin(), PosePoint::Hinge),
        point(s, "B0", &names.screw_link, Point3::origin(), PosePoint::ScrewMount),
        point(
            s,
            "B",
            &names.screw_link,
            Point3::new(track.spec().screw_length_m, 0.0, 0.0),
            PosePoint::ScrewEnd,
        ),
        point(s, "A_nut", &names.nut_link, Point3::origin(), PosePoint::NutPivot),
    ];
    for (label, stowed, follows) in on_flap {
        points.push(point(s, label, &names.fitting_link, in_plane(stowed), follows));
    }
    if station.owns_flap {
        // The flap link frame is the owning station's frame with the flap stowed.
        for (label, stowed, follows) in &on_flap[1..] {
            points.push(point(
                &station.flap_name,
                label,
                &station.flap_name,
                in_plane(*stowed),
                *follows,
            ));
        }
    }
    points
}

/// Checks names, flap ownership, placements and mesh paths of a set of stations.
pub(crate) fn validate_stations(stations: &[StationMechanism3d]) -> Result<()> {
    if stations.is_empty() {
        return Err(Error::NoStations);
    }
    let mut groups = BTreeSet::new();
    for station in stations {
        validate_name("station", &station.name)?;
        validate_name("flap", &station.flap_name)?;
        if !groups.insert(station.name.clone()) {
            return Err(Error::DuplicateUrdfName {
                name: station.name.clone(),
            });
        }
        let matrix = station.aircraft_from_station.to_homogeneous();
        if matrix.iter().any(|v| !v.is_finite()) {
            return Err(Error::NonFinitePlacement {
                station: station.name.clone(),
            });
        }
        if let Some(mesh) = &station.flap_mesh {
            if !station.owns_flap {
                return Err(Error::FlapMeshOnNonOwningStation {
                    station: station.name.clone(),
                    flap: station.flap_name.clone(),
                });
            }
            validate_mesh_path(mesh)?;
        }
    }
    let flaps: BTreeSet<&str> = stations.iter().map(|s| s.flap_name.as_str()).collect();
    for flap in flaps {
        if groups.contains(flap) {
            return Err(Error::DuplicateUrdfName { name: flap.to_owned() });
        }
        let owners = stations.iter().filter(|s| s.flap_name == flap && s.owns_flap).count();
        if owners != 1 {
            return Err(Error::FlapOwnership {
                flap: flap.to_owned(),
                owners,
            });
        }
    }
    Ok(())
}

/// Names are ASCII letters, digits, `_` and `-`, non-empty, without `--` (XML comments).
pub(crate) fn validate_name(what: &'static str, name: &str) -> Result<()> {
    let allowed = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '-';
    if name.is_empty() || !name.chars().all(allowed) || name.contains("--") {
        return Err(Error::InvalidUrdfName {
            what,
            name: name.to_owned(),
        });
    }
    Ok(())
}

/// A mesh path must be relative to the URDF: not empty, not absolute, not a URI.
pub(crate) fn validate_mesh_path(filename: &str) -> Result<()> {
    if !is_relative_path(filename) {
        return Err(Error::MeshPathNotRelative {
            filename: filename.to_owned(),
        });
    }
    Ok(())
}

/// True for a non-empty relative path (no leading `/` or `\`, no drive letter, no URI).
pub(crate) fn is_relative_path(filename: &str) -> bool {
    let bytes = filename.as_bytes();
    let drive = bytes.len() >= 2 && bytes[0].is_ascii_alphabetic() && bytes[1] == b':';
    !(filename.trim().is_empty()
        || filename.starts_with('/')
        || filename.starts_with('\\')
        || filename.contains("://")
        || drive)
}
