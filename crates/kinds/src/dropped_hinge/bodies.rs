//! The dropped hinge's bodies and joints: the flap with its hinged structure (two arms from
//! the hinge to the flap's attachments, and a horn when the screw takes hold below the
//! hinge), the screw jack or the rotary actuator's housing, and the support truss to the
//! lower skin, with the flap's speed bound per unit input.

use nalgebra::Point2;

use super::{Drive, DroppedHingeSpec, DroppedHingeSynthesis};
use flapwright_mechanism::seam::{Body, BodyRole, BodySolid, Joint, JointEnd, JointGeometry, SpeedBound};
use flapwright_mechanism::shared::rocker_drive::ScrewJackParts;

pub(super) const FLAP: usize = 0;
const SCREW: usize = 1;
const NUT: usize = 2;
/// The support's index after the flap and, with a screw jack, the screw and the nut.
fn support_index(drive: &Drive) -> usize {
    match drive {
        Drive::Screw(_) => 3,
        Drive::Rotary => 1,
    }
}

/// True when the screw's attachment `p` lies beyond the hinge `h` seen from the forward
/// attachment `forward`: on a horn below the hinge, not on the forward arm (stowed, m).
pub(super) fn on_horn(forward: Point2<f64>, h: Point2<f64>, p: Point2<f64>) -> bool {
    (p - forward).dot(&(h - forward)) > (h - forward).norm_squared()
}

pub(super) fn bodies_and_joints(
    spec: &DroppedHingeSpec,
    synthesis: &DroppedHingeSynthesis,
    drive: &Drive,
) -> (Vec<Body>, Vec<Joint>) {
    let hw = &spec.hardware;
    let h = synthesis.hinge_m;
    let [forward, aft] = spec.flap_attachments;
    let turn = spec.landing.deflection_rad;
    let capsule = |name: &str, from, to| BodySolid::capsule(name, from, to, hw.link_radius_m);
    let mut flap_solids = vec![capsule("arm-forward", h, forward), capsule("arm-aft", h, aft)];
    let mut support_solids = vec![
        capsule("truss-forward", h, synthesis.support_points_m[0]),
        capsule("truss-aft", h, synthesis.support_points_m[1]),
    ];
    // Every arm and truss member meets the others at the hinge, the pin spanning them: they
    // may share a layer where nothing else crosses them, rather than one truss member
    // standing aside (a truss member the spanwise layout moved aside ended on the lower
    // skin where the station plane cuts it, and on a swept, tapered wing went 3-8 mm into
    // the skin in its own layer).
    let mut hinge_contacts = vec![
        ("truss-forward", "arm-forward"),
        ("truss-aft", "arm-aft"),
        ("truss-forward", "arm-aft"),
        ("truss-aft", "arm-forward"),
        ("arm-forward", "arm-aft"),
        ("truss-forward", "truss-aft"),
    ];
    let support = support_index(drive);
    let mut actuator_bodies = Vec::new();
    let mut actuator_joints = Vec::new();
    let angular_per_input = match (drive, &synthesis.screw_jack) {
        (Drive::Screw(rocker), Some(jack)) => {
            // The screw takes hold of the forward arm, or of a horn below the hinge.
            let p = jack.actuator_attachment_m;
            let on_horn = on_horn(forward, h, p);
            let holder = if on_horn { "horn" } else { "arm-forward" };
            if on_horn {
                flap_solids.push(capsule("horn", h, p));
            }
            (actuator_bodies, actuator_joints) = ScrewJackParts {
                drive: rocker,
                rotation_rad: turn,
                screw_length_m: jack.screw_length_m,
                screw_radius_m: jack.screw.mean_radius_m + 0.25 * jack.screw.lead_m,
                hardware: hw,
                indices: [FLAP, SCREW, NUT],
                pivot: ("P", holder),
            }
            .build();
            // Per metre of stroke (RockerDrive::rotation_rate_bound).
            rocker.rotation_rate_bound(turn)
        }
        _ => {
            // The geared rotary actuator's housing on the hinge, fixed to the truss; its
            // output turns the arms by the input angle itself.
            support_solids.push(BodySolid::capsule("rotary-actuator", h, h, hw.jack_body_radius_m));
            hinge_contacts.extend([("rotary-actuator", "arm-forward"), ("rotary-actuator", "arm-aft")]);
            1.0
        }
    };
    let mut bodies = vec![Body {
        name: "flap".into(),
        role: BodyRole::Flap,
        solids: flap_solids,
        speed_bound: SpeedBound {
            reference: h,
            linear_per_input: 0.0,
            angular_per_input,
        },
    }];
    bodies.extend(actuator_bodies);
    bodies.push(Body {
        name: "support".into(),
        role: BodyRole::Support,
        solids: support_solids,
        speed_bound: SpeedBound::FIXED,
    });
    let mut joints = vec![Joint::new(
        "H",
        "the flap's hinge on the support truss",
        JointGeometry::Revolute { at: h },
        [JointEnd::Body(support), JointEnd::Body(FLAP)],
        &hinge_contacts,
    )];
    joints.extend(actuator_joints);
    (bodies, joints)
}
