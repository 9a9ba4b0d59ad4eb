//! A strict, independent check of the URDF rules (the acceptance check of issue 7).

use std::collections::{BTreeMap, BTreeSet};

use urdf_rs::{Geometry, JointType, Robot};

use super::layout::is_relative_path;

/// How far a joint axis norm may differ from 1 (-): URDF readers normalise silently, so a
/// non-unit axis usually means a frame mistake upstream.
pub const AXIS_UNIT_TOLERANCE: f64 = 1e-9;

/// Every violation of the URDF rules in `robot`, one readable line each (empty = valid).
///
/// Rules (URDF XML specification, ROS wiki `urdf/XML`, plus flapwright's mesh rule):
/// robot and every link and joint named, link names unique, joint names unique; every
/// joint's parent and child exist and differ; every link has at most one parent joint;
/// exactly one root link, and every link reachable from it (a tree, no cycle); origins
/// finite; revolute, continuous, prismatic and planar axes finite and of unit length
/// (within [`AXIS_UNIT_TOLERANCE`]); revolute and prismatic limits finite with
/// lower <= upper, effort and velocity >= 0; mimic joints exist; mesh filenames relative
/// to the URDF and mesh scales finite and positive.
pub fn check_rules(robot: &Robot) -> Vec<String> {
    let mut violations = Vec::new();
    if robot.name.trim().is_empty() {
        violations.push("robot has no name".to_owned());
    }
    let mut links = BTreeSet::new();
    for link in &robot.links {
        if link.name.trim().is_empty() {
            violations.push("a link has an empty name".to_owned());
        }
        if !links.insert(link.name.as_str()) {
            violations.push(format!("link name `{}` is not unique", link.name));
        }
        check_geometry(&link.name, link, &mut violations);
    }
    let mut joints = BTreeSet::new();
    let mut parent_of: BTreeMap<&str, &str> = BTreeMap::new();
    let mut children: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
    for joint in &robot.joints {
        let name = joint.name.as_str();
        if name.trim().is_empty() {
            violations.push("a joint has an empty name".to_owned());
        }
        if !joints.insert(name) {
            violations.push(format!("joint name `{name}` is not unique"));
        }
        let (parent, child) = (joint.parent.link.as_str(), joint.child.link.as_str());
        for (role, link) in [("parent", parent), ("child", child)] {
            if !links.contains(link) {
                violations.push(format!("joint `{name}`: {role} link `{link}` does not exist"));
            }
        }
        if parent == child {
            violations.push(format!("joint `{name}`: parent and child are both `{child}`"));
        }
        if let Some(previous) = parent_of.insert(child, name) {
            violations.push(format!(
                "link `{child}` is the child of two joints, `{previous}` and `{name}`"
            ));
        }
        children.entry(parent).or_default().push(child);
        let origin = joint.origin.xyz.iter().chain(joint.origin.rpy.iter());
        if origin.into_iter().any(|v| !v.is_finite()) {
            violations.push(format!("joint `{name}`: origin is not finite"));
        }
        check_axis_and_limits(joint, &mut violations);
        if let Some(mimic) = &joint.mimic {
            if !robot.joints.iter().any(|j| j.name == mimic.joint) {
                violations.push(format!("joint `{name}` mimics `{}`, which does not exist", mimic.joint));
            }
        }
    }
    let roots: Vec<&str> = links.iter().copied().filter(|l| !parent_of.contains_key(l)).collect();
    if roots.len() != 1 {
        violations.push(format!(
            "expected exactly one root link, found {}: {roots:?}",
            roots.len()
        ));
    }
    if let Some(root) = roots.first() {
        let mut reached = BTreeSet::from([*root]);
        let mut stack = vec![*root];
        while let Some(link) = stack.pop() {
            for child in children.get(link).into_iter().flatten() {
                if reached.insert(child) {
                    stack.push(child);
                }
            }
        }
        let unreached: Vec<&str> = links.difference(&reached).copied().collect();
        if roots.len() == 1 && !unreached.is_empty() {
            violations.push(format!(
                "links not reachable from root `{root}` (a cycle): {unreached:?}"
            ));
        }
    }
    violations
}

fn check_axis_and_limits(joint: &urdf_rs::Joint, violations: &mut Vec<String>) {
    let name = &joint.name;
    let moving = matches!(
        joint.joint_type,
        JointType::Revolute | JointType::Continuous | JointType::Prismatic | JointType::Planar
    );
    if moving {
        let axis = joint.axis.xyz.0;
        let norm = axis.iter().map(|a| a * a).sum::<f64>().sqrt();
        if norm.is_nan() || (norm - 1.0).abs() > AXIS_UNIT_TOLERANCE {
            violations.push(format!("joint `{name}`: axis {axis:?} has length {norm}, not 1"));
        }
    }
    if matches!(joint.joint_type, JointType::Revolute | JointType::Prismatic) {
        let limit = &joint.limit;
        if !(limit.lower.is_finite() && limit.upper.is_finite()) {
            violations.push(format!(
                "joint `{name}`: limits [{}, {}] are not finite",
                limit.lower, limit.upper
            ));
        } else if limit.lower > limit.upper {
            violations.push(format!(
                "joint `{name}`: lower limit {} > upper limit {}",
                limit.lower, limit.upper
            ));
        }
        for (what, value) in [("effort", limit.effort), ("velocity", limit.velocity)] {
            if value.is_nan() || value < 0.0 {
                violations.push(format!("joint `{name}`: {what} limit {value} is negative"));
            }
        }
    }
}

fn check_geometry(link_name: &str, link: &urdf_rs::Link, violations: &mut Vec<String>) {
    let geometries = link
        .visual
        .iter()
        .map(|v| (&v.geometry, &v.origin))
        .chain(link.collision.iter().map(|c| (&c.geometry, &c.origin)));
    for (geometry, origin) in geometries {
        if origin.xyz.iter().chain(origin.rpy.iter()).any(|v| !v.is_finite()) {
            violations.push(format!("link `{link_name}`: a geometry origin is not finite"));
        }
        if let Geometry::Mesh { filename, scale } = geometry {
            if !is_relative_path(filename) {
                violations.push(format!(
                    "link `{link_name}`: mesh `{filename}` is not relative to the URDF"
                ));
            }
            if let Some(scale) = scale {
                if scale.iter().any(|s| !(s.is_finite() && *s > 0.0)) {
                    violations.push(format!("link `{link_name}`: mesh scale {:?} is not positive", scale.0));
                }
            }
        }
    }
}
