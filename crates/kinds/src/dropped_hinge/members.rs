//! The dropped hinge's members and their loads at a pose.
//!
//! - The support truss's two members, pinned at the hinge and on the lower skin, are
//!   two-force members: at the hinge node they balance the hinge's reaction,
//!   Σ t_i u_i = R_H with u_i towards each member's wing end (tension positive).
//! - The hinged structure's arms are cantilevered from the hub on the hinge pin. How the
//!   flap shares its load between the two attachments is statically indeterminate for a
//!   flap fixed at both; it is made determinate the way flap fittings usually are: the
//!   forward attachment F1 a pin, the aft one F2 a link that holds the flap only square to
//!   F1-F2 (so the flap's chordwise load and its expansion go to F1). Moments of the flap
//!   about F1 give the force at F2, the flap's balance the force at F1; each arm carries
//!   its attachment's force, and the forward arm (or a horn below the hinge) the screw's
//!   push as well, to the hub.

use nalgebra::{Isometry2, Point2, Vector2};

use super::bodies::on_horn;
use super::DroppedHinge;
use flapwright_mechanism::seam::{Member, MemberLoad, MemberLoading};
use flapwright_mechanism::shared::flap_load::FlapWrench;
use flapwright_mechanism::shared::geometry::cross;

/// The truss members and the arms (and the horn, when the screw takes hold below the
/// hinge).
pub(super) fn members(hinge: &DroppedHinge) -> Vec<Member> {
    let h = hinge.synthesis.hinge_m;
    let radius_m = hinge.spec.hardware.link_radius_m;
    let member = |name: &str, end: Point2<f64>, loading| Member::new(name, (end - h).norm(), radius_m, loading);
    let [s1, s2] = hinge.synthesis.support_points_m;
    let [f1, f2] = hinge.spec.flap_attachments;
    let mut members = vec![
        member("truss-forward", s1, MemberLoading::TwoForce),
        member("truss-aft", s2, MemberLoading::TwoForce),
        member("arm-forward", f1, MemberLoading::Bending),
        member("arm-aft", f2, MemberLoading::Bending),
    ];
    if let Some(p) = horn_end(hinge) {
        members.push(member("horn", p, MemberLoading::Bending));
    }
    members
}

/// The screw's attachment, stowed, when it sits on a horn below the hinge.
fn horn_end(hinge: &DroppedHinge) -> Option<Point2<f64>> {
    let jack = hinge.synthesis.screw_jack.as_ref()?;
    let p = jack.actuator_attachment_m;
    on_horn(hinge.spec.flap_attachments[0], hinge.synthesis.hinge_m, p).then_some(p)
}

/// Each member's loads with the flap at `flap` under `wrench`, the screw pushing the
/// hinged structure with `screw_push` (where, and the force) and the hinge holding it with
/// `hinge_reaction` (N).
pub(super) fn member_loads(
    hinge: &DroppedHinge,
    flap: &Isometry2<f64>,
    wrench: &FlapWrench,
    screw_push: Option<(Point2<f64>, Vector2<f64>)>,
    hinge_reaction: Vector2<f64>,
) -> Vec<(String, MemberLoad)> {
    let h = hinge.synthesis.hinge_m;
    // The truss.
    let [s1, s2] = hinge.synthesis.support_points_m;
    let (u1, u2) = ((s1 - h).normalize(), (s2 - h).normalize());
    let det = cross(u1, u2);
    let (t1, t2) = (cross(hinge_reaction, u2) / det, cross(u1, hinge_reaction) / det);
    // The flap on its attachments: F1 a pin, F2 square to F1-F2.
    let [f1, f2] = hinge.spec.flap_attachments.map(|p| flap * p);
    let along = (f2 - f1).normalize();
    let square = Vector2::new(-along.y, along.x);
    let at_f2 = square * (-wrench.moment_about(f1) / cross(f2 - f1, square));
    let at_f1 = -(at_f2 + wrench.force_n());
    // A cantilever from the hub carrying `loads` (the flap's push on the arm is minus its
    // push on the flap).
    let cantilever = |tip: Point2<f64>, loads: &[(Point2<f64>, Vector2<f64>)]| {
        let net: Vector2<f64> = loads.iter().map(|(_, f)| f).sum();
        let root_moment = -loads.iter().map(|(p, f)| cross(p - h, *f)).sum::<f64>();
        let mut forces = loads.to_vec();
        forces.push((h, -net));
        MemberLoad::of_straight_member(h, tip, &forces, root_moment)
    };
    let horn = horn_end(hinge).is_some();
    let mut forward_loads = vec![(f1, -at_f1)];
    if let (Some(push), false) = (screw_push, horn) {
        forward_loads.push(push);
    }
    let mut loads = vec![
        ("arm-aft".to_string(), cantilever(f2, &[(f2, -at_f2)])),
        ("arm-forward".to_string(), cantilever(f1, &forward_loads)),
    ];
    if let (Some((p, push)), true) = (screw_push, horn) {
        loads.push(("horn".to_string(), cantilever(p, &[(p, push)])));
    }
    loads.extend([
        ("truss-aft".to_string(), MemberLoad::axial(t2)),
        ("truss-forward".to_string(), MemberLoad::axial(t1)),
    ]);
    loads.sort_by(|a, b| a.0.cmp(&b.0));
    loads
}
