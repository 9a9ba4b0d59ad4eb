//! One station's URDF tree, built from the mechanism seam alone: a link per body, a
//! spanning tree over the revolute and prismatic joints from the ground, joint values from
//! the bodies' poses, key points on the links that carry them. Shared by the robot builder
//! and the trajectory so that both always agree.
//!
//! Link frames: the station link is the station frame; a body's link frame is its parent
//! joint's frame (revolute: at the pin, axes of the station; prismatic: at a point of the
//! slide, x along it) where the body stands stowed. A body's stowed points are moved into its
//! link frame by [`TreeLink::frame`]'s inverse. With zero joint values every link is stowed.

use std::collections::BTreeSet;

use nalgebra::{Isometry2, Point2, Point3, Translation2, UnitComplex};

use super::StationMechanism3d;
use crate::error::{Error, Result};
use flapwright_mechanism::seam::{FlapMechanism, JointEnd, JointGeometry, MechanismPose};

/// Samples of the deployment used for the joint limits and velocity limits.
const LIMIT_SAMPLES: usize = 129;

/// A point is carried by a body when the body's displacement moves its stowed position to
/// its posed one within this distance (m) at every probe.
const CARRIED_TOLERANCE_M: f64 = 1e-9;

/// How a tree link hangs off its parent.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum TreeJointType {
    /// Turns about the link frame's z axis.
    Revolute,
    /// Slides along the link frame's x axis.
    Prismatic {
        /// +1 when the child is the joint's second end (the slide), -1 when the first.
        sign: f64,
    },
    /// Rigidly on the station (a fixed body: track, support).
    Fixed,
}

/// One body's link in the tree.
#[derive(Debug, Clone)]
pub(crate) struct TreeLink {
    /// Index of the body in the mechanism.
    pub body: usize,
    /// URDF link name `<station>_<body>`.
    pub name: String,
    /// Parent link name (the station link or another body's link).
    pub parent: String,
    /// Parent's body index (None: the station link).
    pub parent_body: Option<usize>,
    /// URDF joint name `<station>_<joint>` (`<station>_<body>_mount` for a fixed body).
    pub joint_name: String,
    /// Joint type.
    pub joint_type: TreeJointType,
    /// The link frame in the station frame, stowed.
    pub frame: Isometry2<f64>,
}

/// A station's tree: links in parent-first order, and the seam joints left out of it.
pub(crate) struct StationTree {
    /// The station link's name.
    pub station_link: String,
    /// The fixed joint placing the station link on the base.
    pub mount_joint: String,
    /// Links of the bodies, parents first.
    pub links: Vec<TreeLink>,
    /// Indices of the seam joints not in the tree (closed loops, slots).
    pub cut: Vec<usize>,
    /// The link of the flap body.
    pub flap_link: String,
}

/// The link frame of a joint's child: at the pin (revolute), or at the slide's origin with
/// x along it (prismatic).
fn joint_frame(geometry: &JointGeometry) -> Option<Isometry2<f64>> {
    match geometry {
        JointGeometry::Revolute { at } => Some(Isometry2::from_parts(
            Translation2::from(at.coords),
            UnitComplex::identity(),
        )),
        JointGeometry::Prismatic { origin, direction } => Some(Isometry2::from_parts(
            Translation2::from(origin.coords),
            UnitComplex::new(direction.y.atan2(direction.x)),
        )),
        JointGeometry::PinInCircularSlot { .. }
        | JointGeometry::PinInStraightSlot { .. }
        | JointGeometry::PinInHookedSlot { .. } => None,
    }
}

impl StationTree {
    /// The spanning tree of `station`'s mechanism: from the ground, each moving body is
    /// reached by the first revolute or prismatic joint (in the kind's order) to a body
    /// already placed; fixed bodies hang on the station link.
    ///
    /// Errors: [`Error::UrdfTreeIncomplete`] when a moving body is reachable only through
    /// slots.
    pub fn new(station: &StationMechanism3d) -> Result<Self> {
        let mechanism = station.mechanism;
        let bodies = mechanism.bodies();
        let joints = mechanism.joints();
        let name = |suffix: &str| format!("{}_{}", station.name, suffix.replace('-', "_"));
        let station_link = name("station");
        let mut links: Vec<TreeLink> = Vec::new();
        let mut in_tree = BTreeSet::new();
        for (b, body) in bodies.iter().enumerate().filter(|(_, body)| !body.is_moving()) {
            links.push(TreeLink {
                body: b,
                name: name(&body.name),
                parent: station_link.clone(),
                parent_body: None,
                joint_name: name(&format!("{}_mount", body.name)),
                joint_type: TreeJointType::Fixed,
                frame: Isometry2::identity(),
            });
        }
        let placed = |links: &[TreeLink], end: JointEnd| match end {
            JointEnd::Ground => Some((station_link.clone(), None, Isometry2::identity())),
            // A fixed body stands where it is stowed: its link is a parent like the ground.
            JointEnd::Body(b) => links
                .iter()
                .find(|l| l.body == b)
                .map(|l| (l.name.clone(), Some(b), l.frame)),
        };
        loop {
            let mut grew = false;
            for (j, joint) in joints.iter().enumerate() {
                if in_tree.contains(&j) {
                    continue;
                }
                let Some(frame) = joint_frame(&joint.geometry) else {
                    continue;
                };
                for (parent_end, child_end, sign) in [(0, 1, 1.0), (1, 0, -1.0)] {
                    let JointEnd::Body(child) = joint.ends[child_end] else {
                        continue;
                    };
                    let child_placed = links.iter().any(|l| l.body == child);
                    let Some((parent, parent_body, _)) = placed(&links, joint.ends[parent_end]) else {
                        continue;
                    };
                    if child_placed || !bodies[child].is_moving() {
                        continue;
                    }
                    let joint_type = match joint.geometry {
                        JointGeometry::Prismatic { .. } => TreeJointType::Prismatic { sign },
                        _ => TreeJointType::Revolute,
                    };
                    links.push(TreeLink {
                        body: child,
                        name: name(&bodies[child].name),
                        parent,
                        parent_body,
                        joint_name: name(&joint.name),
                        joint_type,
                        frame,
                    });
                    in_tree.insert(j);
                    grew = true;
                    break;
                }
            }
            if !grew {
                break;
            }
        }
        if let Some((_, body)) = bodies
            .iter()
            .enumerate()
            .find(|(b, body)| body.is_moving() && !links.iter().any(|l| l.body == *b))
        {
            return Err(Error::UrdfTreeIncomplete {
                station: station.name.clone(),
                body: body.name.clone(),
            });
        }
        let flap_link = bodies
            .iter()
            .position(|b| b.role == flapwright_mechanism::seam::BodyRole::Flap)
            .and_then(|f| links.iter().find(|l| l.body == f))
            .map(|l| l.name.clone())
            .ok_or_else(|| Error::UrdfTreeIncomplete {
                station: station.name.clone(),
                body: "flap".into(),
            })?;
        Ok(Self {
            mount_joint: name("station_mount"),
            station_link,
            cut: (0..joints.len()).filter(|j| !in_tree.contains(j)).collect(),
            links,
            flap_link,
        })
    }

    /// The movable links (revolute and prismatic), in trajectory order.
    pub fn movable(&self) -> impl Iterator<Item = &TreeLink> {
        self.links.iter().filter(|l| l.joint_type != TreeJointType::Fixed)
    }

    /// The joint value of each movable link at `pose`: the relative rotation (rad) or the
    /// slide (m) of the body against its parent since stowed.
    pub fn joint_values(&self, pose: &MechanismPose) -> Vec<f64> {
        self.movable()
            .map(|link| {
                let parent = link.parent_body.map_or(Isometry2::identity(), |b| pose.bodies[b]);
                let relative = parent.inverse() * pose.bodies[link.body];
                match link.joint_type {
                    TreeJointType::Prismatic { sign } => {
                        let along = link.frame.rotation * nalgebra::Vector2::x();
                        sign * relative.translation.vector.dot(&along)
                    }
                    _ => relative.rotation.angle(),
                }
            })
            .collect()
    }

    /// Lower and upper joint values, the largest rate at the actuator's nominal speed and
    /// whether the actuator drives it (its value moves one for one with the input, to
    /// 1e-9 of the travel at every sample), per movable link, over the deployment (sampled,
    /// widened by the largest step between samples so that every value of the deployment
    /// lies inside).
    pub fn limits(&self, mechanism: &dyn FlapMechanism) -> Result<Vec<MovableLimits>> {
        let range = mechanism.input_range();
        let inputs = range.samples(LIMIT_SAMPLES);
        let values = inputs
            .iter()
            .map(|&q| Ok(self.joint_values(&mechanism.pose(q)?)))
            .collect::<Result<Vec<_>>>()?;
        let nominal_speed = mechanism.actuator().nominal_input_speed();
        let step = range.travel().abs() / (LIMIT_SAMPLES - 1) as f64;
        Ok((0..self.movable().count())
            .map(|k| {
                let column: Vec<f64> = values.iter().map(|v| v[k]).collect();
                let largest_step = column.windows(2).map(|w| (w[1] - w[0]).abs()).fold(0.0, f64::max);
                let lower = column.iter().copied().fold(f64::INFINITY, f64::min) - 0.5 * largest_step;
                let upper = column.iter().copied().fold(f64::NEG_INFINITY, f64::max) + 0.5 * largest_step;
                let tolerance = 1e-9 * range.travel().abs();
                let sense = (column[column.len() - 1] - column[0]).signum();
                let driven = inputs
                    .iter()
                    .zip(&column)
                    .all(|(&q, &value)| ((value - column[0]) - sense * (q - inputs[0])).abs() <= tolerance);
                MovableLimits {
                    range: (lower.min(0.0), upper.max(0.0)),
                    velocity: largest_step / step * nominal_speed.abs(),
                    driven,
                }
            })
            .collect())
    }
}

/// A movable joint's limits over the deployment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct MovableLimits {
    /// Lower and upper joint values (rad or m).
    pub range: (f64, f64),
    /// Largest rate at the actuator's nominal speed (rad/s or m/s).
    pub velocity: f64,
    /// The actuator drives this joint: its value moves one for one with the input.
    pub driven: bool,
}

/// A key point: its name, the link that carries it, where it sits in that link's frame
/// (m) and which named point of the pose it follows.
pub(crate) struct KeyPointLayout {
    pub name: String,
    pub link: String,
    pub position_link_m: Point3<f64>,
    pub follows: String,
}

/// Key points of one station: every named point on every link that carries it (and on the
/// flap link when the station owns the flap).
pub(crate) fn key_points(station: &StationMechanism3d, tree: &StationTree) -> Result<Vec<KeyPointLayout>> {
    let mechanism = station.mechanism;
    let range = mechanism.input_range();
    let stowed = mechanism.pose(range.stowed)?;
    let probes = [
        mechanism.pose(range.at_fraction(0.37))?,
        mechanism.pose(range.deployed)?,
    ];
    let carried = |body: Option<usize>, name: &str, position: Point2<f64>| {
        probes.iter().all(|pose| {
            let moved = body.map_or(position, |b| pose.bodies[b] * position);
            pose.point(name)
                .is_some_and(|p| (p - moved).norm() < CARRIED_TOLERANCE_M)
        })
    };
    let in_plane = |p: Point2<f64>| Point3::new(p.x, p.y, 0.0);
    let mut points = Vec::new();
    for point in &stowed.points {
        if carried(None, point.name, point.position) {
            points.push(KeyPointLayout {
                name: format!("{}.{}", station.name, point.name),
                link: tree.station_link.clone(),
                position_link_m: in_plane(point.position),
                follows: point.name.to_string(),
            });
        }
        for link in tree.movable() {
            if carried(Some(link.body), point.name, point.position) {
                points.push(KeyPointLayout {
                    name: format!("{}.{}.{}", station.name, mechanism.bodies()[link.body].name, point.name),
                    link: link.name.clone(),
                    position_link_m: in_plane(link.frame.inverse() * point.position),
                    follows: point.name.to_string(),
                });
            }
        }
    }
    if station.owns_flap {
        // The flap link frame is the owning station's frame with the flap stowed.
        for point in &stowed.points {
            let on_flap = probes.iter().all(|pose| {
                pose.point(point.name)
                    .is_some_and(|p| (p - pose.flap * point.position).norm() < CARRIED_TOLERANCE_M)
            });
            if on_flap && !carried(None, point.name, point.position) {
                points.push(KeyPointLayout {
                    name: format!("{}.{}", station.flap_name, point.name),
                    link: station.flap_name.clone(),
                    position_link_m: in_plane(point.position),
                    follows: point.name.to_string(),
                });
            }
        }
    }
    Ok(points)
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
        if let Some(aft) = &station.aft_element {
            if !station.owns_flap {
                return Err(Error::FlapMeshOnNonOwningStation {
                    station: station.name.clone(),
                    flap: aft.mesh.name.clone(),
                });
            }
            validate_name("aft element", &aft.mesh.name)?;
            validate_mesh_path(&aft.mesh.filename)?;
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
