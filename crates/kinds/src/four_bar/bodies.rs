//! The four-bar's bodies and joints: the flap's bracket between its pivots, the crank
//! (from a horn beyond O1 when the screw sits there), the rocker, the screw jack on the
//! crank ([`ScrewJackParts`]) and the struts that hold O1 and O2 (with a truss's brace and
//! tie), with speed bounds per
//! metre of stroke from the loop's velocity analysis.

use nalgebra::Point2;

use super::linkage::Loop;
use super::{FourBarSpec, FourBarSynthesis};
use flapwright_mechanism::seam::{Body, BodyRole, BodySolid, Joint, JointEnd, JointGeometry, SpeedBound};
use flapwright_mechanism::shared::rocker_drive::{RockerDrive, ScrewJackParts};

const FLAP: usize = 0;
const CRANK: usize = 1;
const ROCKER: usize = 2;
const SCREW: usize = 3;
const NUT: usize = 4;
const SUPPORT: usize = 5;

/// Where the crank O1-A1 starts: at the screw's attachment `c` when it sits on a horn
/// beyond the pivot `o1`, else at the pivot (any pose, m).
pub(super) fn crank_start(o1: Point2<f64>, a1: Point2<f64>, c: Point2<f64>) -> Point2<f64> {
    if (c - o1).dot(&(a1 - o1)) < 0.0 {
        c
    } else {
        o1
    }
}

/// The bodies and joints. The crank turns at most at the drive's bound; the rocker and the
/// flap at most that times `link_rates`, the certified bounds on their rates per unit crank
/// rate ([`Loop::rate_bounds`]).
pub(super) fn bodies_and_joints(
    spec: &FourBarSpec,
    synthesis: &FourBarSynthesis,
    loop_: &Loop,
    drive: &RockerDrive,
    link_rates: (f64, f64),
) -> (Vec<Body>, Vec<Joint>) {
    let hw = &spec.hardware;
    let (o1, o2, a1, a2) = (loop_.o1, loop_.o2, loop_.a1, loop_.a2);
    let c = synthesis.actuator_attachment_m;
    let capsule = |name: &str, from: Point2<f64>, to: Point2<f64>| BodySolid::capsule(name, from, to, hw.link_radius_m);
    let travel = synthesis.crank_rotation_rad[1];
    let crank_rate = drive.rotation_rate_bound(travel);
    let a1_speed = (a1 - o1).norm() * crank_rate;
    let (rocker_rate, flap_rate) = (link_rates.0 * crank_rate, link_rates.1 * crank_rate);
    let moving = |reference, linear_per_input, angular_per_input| SpeedBound {
        reference,
        linear_per_input,
        angular_per_input,
    };
    let (screw_and_nut, jack_joints) = ScrewJackParts {
        drive,
        rotation_rad: travel,
        screw_length_m: synthesis.screw_length_m,
        screw_radius_m: synthesis.screw.mean_radius_m + 0.25 * synthesis.screw.lead_m,
        hardware: hw,
        indices: [CRANK, SCREW, NUT],
        pivot: ("C", "crank"),
    }
    .build();
    let crank_start = crank_start(o1, a1, c);
    let mut bodies = vec![
        Body {
            name: "flap".into(),
            role: BodyRole::Flap,
            solids: vec![capsule("bracket", a1, a2)],
            speed_bound: moving(a1, a1_speed, flap_rate),
        },
        Body {
            name: "crank".into(),
            role: BodyRole::Link,
            solids: vec![capsule("crank", crank_start, a1)],
            speed_bound: moving(o1, 0.0, crank_rate),
        },
        Body {
            name: "rocker".into(),
            role: BodyRole::Link,
            solids: vec![capsule("rocker", o2, a2)],
            speed_bound: moving(o2, 0.0, rocker_rate),
        },
    ];
    bodies.extend(screw_and_nut);
    bodies.push(Body {
        name: "support".into(),
        role: BodyRole::Support,
        solids: [
            BodySolid::capsule(super::STRUTS[0], o1, synthesis.strut_tops_m[0], hw.strut_radius_m),
            BodySolid::capsule(super::STRUTS[1], o2, synthesis.strut_tops_m[1], hw.strut_radius_m),
        ]
        .into_iter()
        .chain(synthesis.truss.iter().flat_map(|truss| {
            let brace = truss.rods[2];
            [
                BodySolid::capsule(super::TRUSS_RODS[2], brace.foot_m, brace.top_m, hw.strut_radius_m),
                BodySolid::capsule(super::TIE, o2, o1, hw.strut_radius_m),
            ]
        }))
        .collect(),
        speed_bound: SpeedBound::FIXED,
    });
    // What meets a link at its fixed pivot: its strut and, with a truss, the tie and the
    // brace where it stands on that pivot.
    let touching_at = |pivot, strut: &'static str, link: &'static str| -> Vec<(&'static str, &'static str)> {
        let mut touching = vec![(strut, link)];
        if let Some(truss) = &synthesis.truss {
            touching.push((super::TIE, link));
            if truss.rods[2].foot_m == pivot {
                touching.push((super::TRUSS_RODS[2], link));
            }
        }
        touching
    };
    let revolute = |name: &str, description: &str, at, ends, touching: &[(&str, &str)]| {
        Joint::new(name, description, JointGeometry::Revolute { at }, ends, touching)
    };
    let mut joints = vec![
        revolute(
            "O1",
            "crank on its support",
            o1,
            [JointEnd::Body(SUPPORT), JointEnd::Body(CRANK)],
            &touching_at(o1, "strut-O1", "crank"),
        ),
        revolute(
            "O2",
            "rocker on its support",
            o2,
            [JointEnd::Body(SUPPORT), JointEnd::Body(ROCKER)],
            &touching_at(o2, "strut-O2", "rocker"),
        ),
        revolute(
            "A1",
            "crank pinned to the flap",
            a1,
            [JointEnd::Body(CRANK), JointEnd::Body(FLAP)],
            &[("crank", "bracket")],
        ),
        revolute(
            "A2",
            "rocker pinned to the flap",
            a2,
            [JointEnd::Body(ROCKER), JointEnd::Body(FLAP)],
            &[("rocker", "bracket")],
        ),
    ];
    joints.extend(jack_joints);
    (bodies, joints)
}
