//! The link-track's bodies and joints: the flap with its fitting from the link's pivot to
//! the carriage, the link, and the fixed support (the track beam, the rotary actuator at
//! the link's pivot, and struts to the lower skin), with speed bounds per radian of link.

use nalgebra::Point2;

use super::linkage::Loop;
use super::{LinkTrackSpec, LinkTrackSynthesis};
use flapwright_mechanism::seam::{Body, BodyRole, BodySolid, Joint, JointEnd, JointGeometry, SpeedBound};

const FLAP: usize = 0;
const LINK: usize = 1;
const SUPPORT: usize = 2;

/// The bodies and joints. The link turns one radian per radian of input; the flap's pivot
/// A moves at |A - O| per radian, and the flap turns at most `flap_rate` per radian
/// ([`Loop::flap_rate_bound`]).
pub(super) fn bodies_and_joints(
    spec: &LinkTrackSpec,
    synthesis: &LinkTrackSynthesis,
    loop_: &Loop,
    flap_rate: f64,
) -> (Vec<Body>, Vec<Joint>) {
    let hw = &spec.hardware;
    let (o, a, c) = (loop_.o, loop_.a, loop_.c);
    let capsule = |name: &str, from: Point2<f64>, to: Point2<f64>| BodySolid::capsule(name, from, to, hw.link_radius_m);
    let arm = (a - o).norm();
    let [track_start, track_end] = synthesis.track_ends_m;
    let bodies = vec![
        Body {
            name: "flap".into(),
            role: BodyRole::Flap,
            solids: vec![
                capsule("fitting", a, c),
                BodySolid::capsule("carriage", c, c, hw.nut_radius_m),
            ],
            speed_bound: SpeedBound {
                reference: a,
                linear_per_input: arm,
                angular_per_input: flap_rate,
            },
        },
        Body {
            name: "link".into(),
            role: BodyRole::Link,
            solids: vec![capsule("link", o, a)],
            speed_bound: SpeedBound {
                reference: o,
                linear_per_input: 0.0,
                angular_per_input: 1.0,
            },
        },
        Body {
            name: "support".into(),
            role: BodyRole::Support,
            solids: vec![
                capsule("track", track_start, track_end),
                BodySolid::capsule("rotary-actuator", o, o, hw.jack_body_radius_m),
                capsule("strut-O", o, synthesis.strut_tops_m[0]),
                capsule("strut-track", track_start, synthesis.strut_tops_m[1]),
            ],
            speed_bound: SpeedBound::FIXED,
        },
    ];
    let joints = vec![
        Joint::new(
            "O",
            "the link on the rotary actuator's output",
            JointGeometry::Revolute { at: o },
            [JointEnd::Body(SUPPORT), JointEnd::Body(LINK)],
            &[("rotary-actuator", "link"), ("strut-O", "link")],
        ),
        Joint::new(
            "A",
            "the link pinned to the flap's fitting",
            JointGeometry::Revolute { at: a },
            [JointEnd::Body(LINK), JointEnd::Body(FLAP)],
            &[("link", "fitting")],
        ),
        Joint::new(
            "C",
            "the flap's carriage on the track",
            JointGeometry::PinInStraightSlot {
                pin: c,
                direction: loop_.d,
            },
            [JointEnd::Body(FLAP), JointEnd::Body(SUPPORT)],
            &[("carriage", "track"), ("fitting", "track")],
        ),
    ];
    (bodies, joints)
}
