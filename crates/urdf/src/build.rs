//! Building the urdf-rs robot of a wing and writing it as XML.

use std::collections::BTreeSet;
use std::fmt::Write as _;

use nalgebra::{Isometry2, Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use urdf_rs::{
    Axis, Collision, Geometry, Inertia, Inertial, Joint, JointLimit, JointType, Link, LinkName, Mass, Robot, Vec3,
    Visual,
};

use super::layout::{validate_mesh_path, validate_name, validate_stations, MovableLimits, StationTree, TreeJointType};
use super::rpy::origin_from_isometry;
use super::{BaseLink, CutJoint, MeshRef, RigidInertia, StationMechanism3d, UrdfModel};
use crate::error::{Error, Result};
use flapwright_mechanism::seam::{JointEnd, JointGeometry};

/// The URDF version written (`<robot version>`); 1.0 keeps every reader happy.
const URDF_VERSION: &str = "1.0";

/// Builds the wing's robot: `base` as the root link in the aircraft frame and every
/// station's track as a tree (see the [module docs](super)), with the flap link on the
/// station that owns it. Joint limits come from the deployment range: hinge [0, β3] (rad),
/// screw the extreme directions over the stroke (rad), nut [s34,i, s34,f] (m).
///
/// Meshes: the base meshes are in the aircraft frame (identity visual origin); the flap
/// mesh, in the aircraft frame with the flap stowed, gets the visual origin
/// station_from_aircraft of its owning station, so that it shows where it is at zero
/// joint values.
///
/// Errors: [`Error::NoStations`], [`Error::InvalidUrdfName`], [`Error::DuplicateUrdfName`],
/// [`Error::FlapOwnership`], [`Error::FlapMeshOnNonOwningStation`],
/// [`Error::MeshPathNotRelative`], [`Error::NonFinitePlacement`], and pose errors of a
/// track that cannot run its own stroke.
pub fn build_robot(robot_name: &str, base: &BaseLink, stations: &[StationMechanism3d]) -> Result<UrdfModel> {
    validate_name("robot", robot_name)?;
    validate_name("base link", &base.name)?;
    validate_stations(stations)?;
    let mut base_link = empty_link(&base.name);
    dress(&mut base_link, &base.meshes, None, &Isometry3::identity())?;
    let mut robot = Robot {
        name: robot_name.to_owned(),
        version: Some(URDF_VERSION.to_owned()),
        links: vec![base_link],
        joints: Vec::new(),
        materials: Vec::new(),
    };
    let mut cut_joints = Vec::new();
    for station in stations {
        add_station(&mut robot, &mut cut_joints, &base.name, station)?;
    }
    let mut names = BTreeSet::new();
    for name in robot.links.iter().map(|l| &l.name) {
        if !names.insert(name.clone()) {
            return Err(Error::DuplicateUrdfName { name: name.clone() });
        }
    }
    names.clear();
    for name in robot.joints.iter().map(|j| &j.name) {
        if !names.insert(name.clone()) {
            return Err(Error::DuplicateUrdfName { name: name.clone() });
        }
    }
    Ok(UrdfModel { robot, cut_joints })
}

/// The robot as URDF XML: an XML declaration, a comment naming the frames and every cut
/// joint, then urdf-rs's `write_to_string` (which writes no declaration itself).
///
/// Errors: [`Error::UrdfWrite`] when urdf-rs cannot serialise the robot.
pub fn to_xml(model: &UrdfModel) -> Result<String> {
    let body = urdf_rs::write_to_string(&model.robot).map_err(|e| Error::UrdfWrite { message: e.to_string() })?;
    let mut text = String::from("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<!--\n");
    // Writing to a String cannot fail.
    let _ = writeln!(
        text,
        "  Robot `{}` written by flapwright-mechanism (urdf module).\n  \
         Units: metres, radians. Base link frame = aircraft frame (x aft, y starboard, z up).\n  \
         Station links: station frame (origin A0, x to the nose, y up, z outboard); a body's\n  \
         link frame is its parent joint's frame where the body stands stowed.\n  \
         Joint values per deployment sample are in the trajectory file beside this one.\n  \
         URDF describes trees only: these closed-loop joints are cut (not in this file):",
        model.robot.name
    );
    for cut in &model.cut_joints {
        let [x, y, z] = cut.location_stowed_ac_m;
        let [ax, ay, az] = cut.axis_ac;
        let _ = writeln!(
            text,
            "    - station {}: {} joint {} between links {} and {}, at ({x:.6}, {y:.6}, {z:.6}) m \
             stowed, axis ({ax:.6}, {ay:.6}, {az:.6}) (aircraft frame)",
            cut.station, cut.kind, cut.joint, cut.between.0, cut.between.1
        );
    }
    text.push_str("-->\n");
    text.push_str(&body);
    if !text.ends_with('\n') {
        text.push('\n');
    }
    Ok(text)
}

fn add_station(
    robot: &mut Robot,
    cut_joints: &mut Vec<CutJoint>,
    base_name: &str,
    station: &StationMechanism3d,
) -> Result<()> {
    let tree = StationTree::new(station)?;
    let limits = tree.limits(station.mechanism)?;
    let z = Vector3::z();
    let placement = &station.aircraft_from_station;
    robot.links.push(empty_link(&tree.station_link));
    robot.joints.push(joint(
        &tree.mount_joint,
        JointType::Fixed,
        (base_name, &tree.station_link),
        placement,
        z,
        None,
    ));
    let frame_of = |body: Option<usize>| {
        body.and_then(|b| tree.links.iter().find(|l| l.body == b))
            .map_or(Isometry2::identity(), |l| l.frame)
    };
    let mut movable_limits = limits.iter();
    for link in &tree.links {
        let mut urdf_link = empty_link(&link.name);
        if let Some(geometry) = station.bodies.iter().find(|g| g.body == link.body) {
            let link_from_aircraft = (placement * lift(&link.frame)).inverse();
            dress(
                &mut urdf_link,
                &geometry.meshes,
                geometry.inertia.as_ref(),
                &link_from_aircraft,
            )?;
        }
        robot.links.push(urdf_link);
        let parent_from_child = lift(&(frame_of(link.parent_body).inverse() * link.frame));
        // The joint the actuator drives carries its peak load as its effort; the passive
        // ones 0.
        let effort_of = |limits: &MovableLimits| {
            let effort = if limits.driven {
                station
                    .actuator_peak_load
                    .filter(|l| l.is_finite())
                    .map_or(0.0, f64::abs)
            } else {
                0.0
            };
            (limits.range, limits.velocity, effort)
        };
        let (joint_type, axis, limit) = match link.joint_type {
            TreeJointType::Fixed => (JointType::Fixed, z, None),
            TreeJointType::Revolute => (JointType::Revolute, z, movable_limits.next().map(effort_of)),
            TreeJointType::Prismatic { sign } => (
                JointType::Prismatic,
                Vector3::x() * sign,
                movable_limits.next().map(effort_of),
            ),
        };
        robot.joints.push(joint(
            &link.joint_name,
            joint_type,
            (&link.parent, &link.name),
            &parent_from_child,
            axis,
            limit,
        ));
    }
    let axis_ac = placement * z;
    let to_array = |p: Point3<f64>| [p.x, p.y, p.z];
    let link_of = |end: JointEnd| match end {
        JointEnd::Ground => tree.station_link.clone(),
        JointEnd::Body(b) => tree
            .links
            .iter()
            .find(|l| l.body == b)
            .map_or_else(|| tree.station_link.clone(), |l| l.name.clone()),
    };
    for &j in &tree.cut {
        let seam_joint = &station.mechanism.joints()[j];
        let (kind, at) = match seam_joint.geometry {
            JointGeometry::Revolute { at } => ("revolute", at),
            JointGeometry::Prismatic { origin, .. } => ("prismatic", origin),
            JointGeometry::PinInCircularSlot { pin, .. } => ("pin-in-circular-slot", pin),
            JointGeometry::PinInStraightSlot { pin, .. } => ("pin-in-straight-slot", pin),
            JointGeometry::PinInHookedSlot { pin, .. } => ("pin-in-hooked-slot", pin),
        };
        cut_joints.push(CutJoint {
            station: station.name.clone(),
            joint: seam_joint.name.clone(),
            kind,
            between: (link_of(seam_joint.ends[0]), link_of(seam_joint.ends[1])),
            location_stowed_ac_m: to_array(placement * Point3::new(at.x, at.y, 0.0)),
            axis_ac: [axis_ac.x, axis_ac.y, axis_ac.z],
        });
    }
    let flap_frame = tree
        .links
        .iter()
        .find(|l| l.name == tree.flap_link)
        .map_or(Isometry2::identity(), |l| l.frame);
    if station.owns_flap {
        // The flap link frame = this station's frame with the flap stowed, so a mesh given
        // in the aircraft frame needs the visual origin station_from_aircraft.
        let mut flap = empty_link(&station.flap_name);
        let meshes: Vec<MeshRef> = station
            .flap_mesh
            .iter()
            .map(|filename| MeshRef {
                name: station.flap_name.clone(),
                filename: filename.clone(),
            })
            .collect();
        dress(&mut flap, &meshes, station.flap_inertia.as_ref(), &placement.inverse())?;
        robot.links.push(flap);
        robot.joints.push(joint(
            &format!("{}_flap_mount", station.name),
            JointType::Fixed,
            (&tree.flap_link, &station.flap_name),
            &lift(&flap_frame.inverse()),
            z,
            None,
        ));
        if let Some(aft) = &station.aft_element {
            // Same rule as the flap: the link frame is the station frame with the flap
            // stowed, hung off the link of the body that moves the aft element.
            let (carrier_link, carrier_frame) =
                match flapwright_mechanism::seam::aft_flap_body(station.mechanism.bodies()) {
                    None => (tree.flap_link.as_str(), flap_frame),
                    Some(body) => tree
                        .links
                        .iter()
                        .find(|l| l.body == body)
                        .map(|l| (l.name.as_str(), l.frame))
                        .ok_or_else(|| Error::UrdfTreeIncomplete {
                            station: station.name.clone(),
                            body: station.mechanism.bodies()[body].name.clone(),
                        })?,
                };
            let mut link = empty_link(&aft.mesh.name);
            dress(
                &mut link,
                std::slice::from_ref(&aft.mesh),
                aft.inertia.as_ref(),
                &placement.inverse(),
            )?;
            robot.links.push(link);
            robot.joints.push(joint(
                &format!("{}_aft_element_mount", station.name),
                JointType::Fixed,
                (carrier_link, &aft.mesh.name),
                &lift(&carrier_frame.inverse()),
                z,
                None,
            ));
        }
    } else {
        cut_joints.push(CutJoint {
            station: station.name.clone(),
            joint: "flap_attachment".to_owned(),
            kind: "fixed",
            between: (tree.flap_link.clone(), station.flap_name.clone()),
            location_stowed_ac_m: to_array(placement * Point3::origin()),
            axis_ac: [axis_ac.x, axis_ac.y, axis_ac.z],
        });
    }
    Ok(())
}

/// A planar placement as a rigid motion of the station frame (about its z axis).
pub(crate) fn lift(placement: &Isometry2<f64>) -> Isometry3<f64> {
    let t = placement.translation.vector;
    Isometry3::from_parts(
        Translation3::new(t.x, t.y, 0.0),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), placement.rotation.angle()),
    )
}

fn empty_link(name: &str) -> Link {
    Link {
        name: name.to_owned(),
        inertial: Default::default(),
        visual: Vec::new(),
        collision: Vec::new(),
    }
}

/// Gives `link` the meshes (aircraft frame) as visual and collision elements and the
/// inertia (aircraft frame) as its inertial element, both turned into the link frame by
/// `link_from_aircraft`: the centre of mass is mapped, the tensor turned, I_link = R I R^T.
fn dress(
    link: &mut Link,
    meshes: &[MeshRef],
    inertia: Option<&RigidInertia>,
    link_from_aircraft: &Isometry3<f64>,
) -> Result<()> {
    for mesh in meshes {
        let visual = mesh_visual(&mesh.name, &mesh.filename, link_from_aircraft)?;
        link.collision.push(Collision {
            name: visual.name.clone(),
            origin: visual.origin.clone(),
            geometry: visual.geometry.clone(),
        });
        link.visual.push(visual);
    }
    if let Some(inertia) = inertia {
        let centre = link_from_aircraft * inertia.centre_of_mass_ac_m;
        let turn = link_from_aircraft.rotation.to_rotation_matrix();
        let tensor = turn.matrix() * inertia.inertia_ac_kg_m2 * turn.matrix().transpose();
        // Symmetric by construction; the mean of the two off-diagonal terms keeps it so
        // through rounding.
        let off = |i: usize, j: usize| 0.5 * (tensor[(i, j)] + tensor[(j, i)]);
        link.inertial = Inertial {
            origin: urdf_rs::Pose {
                xyz: Vec3([centre.x, centre.y, centre.z]),
                rpy: Vec3([0.0; 3]),
            },
            mass: Mass { value: inertia.mass_kg },
            inertia: Inertia {
                ixx: tensor[(0, 0)],
                ixy: off(0, 1),
                ixz: off(0, 2),
                iyy: tensor[(1, 1)],
                iyz: off(1, 2),
                izz: tensor[(2, 2)],
            },
        };
    }
    Ok(())
}

fn mesh_visual(name: &str, filename: &str, link_from_mesh: &Isometry3<f64>) -> Result<Visual> {
    validate_name("mesh", name)?;
    validate_mesh_path(filename)?;
    let (xyz, rpy) = origin_from_isometry(link_from_mesh);
    Ok(Visual {
        name: Some(name.to_owned()),
        origin: urdf_rs::Pose {
            xyz: Vec3(xyz),
            rpy: Vec3(rpy),
        },
        geometry: Geometry::Mesh {
            filename: filename.to_owned(),
            scale: None,
        },
        material: None,
    })
}

fn joint(
    name: &str,
    joint_type: JointType,
    (parent, child): (&str, &str),
    parent_from_child: &Isometry3<f64>,
    axis: Vector3<f64>,
    limit: Option<((f64, f64), f64, f64)>,
) -> Joint {
    let (xyz, rpy) = origin_from_isometry(parent_from_child);
    let limit = limit.map_or_else(JointLimit::default, |((lower, upper), velocity, effort)| JointLimit {
        lower,
        upper,
        effort,
        velocity,
        ..JointLimit::default()
    });
    Joint {
        name: name.to_owned(),
        joint_type,
        origin: urdf_rs::Pose {
            xyz: Vec3(xyz),
            rpy: Vec3(rpy),
        },
        parent: LinkName {
            link: parent.to_owned(),
        },
        child: LinkName { link: child.to_owned() },
        axis: Axis {
            xyz: Vec3([axis.x, axis.y, axis.z]),
        },
        limit,
        calibration: None,
        dynamics: None,
        mimic: None,
        safety_controller: None,
    }
}
