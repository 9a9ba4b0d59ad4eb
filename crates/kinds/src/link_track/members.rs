//! The link-track's members and their loads at a pose: the link, the track beam and the
//! two struts that hold the support to the lower skin.
//!
//! - **link**: clamped to the rotary actuator's output at O, pinned to the flap at A; it
//!   bends under the pin's push.
//! - **track**: clamped at its forward end, where `strut-track` holds it; the carriage at C
//!   pushes it square to itself, -N n.
//! - **strut-O**: clamped to the lower skin, carrying at O the link's pin force and the
//!   actuator's reaction couple.
//! - **strut-track**: clamped to the lower skin, carrying the track's root force and couple.
//!
//! Each is a cantilever under one force and a couple ([`MemberLoad::of_cantilever_line`],
//! the link through the method of sections as before). The two load paths are taken apart
//! (the support is one rigid body in the kinematics; how its parts share load between them
//! is a structural design left open).

use nalgebra::{Point2, Vector2};

use super::LinkTrack;
use flapwright_mechanism::shared::geometry::cross;
use flapwright_mechanism::shared::members::{Member, MemberLoad, MemberLoading};

impl LinkTrack {
    /// The link, the track and the struts (see the module doc).
    pub(super) fn member_list(&self) -> Vec<Member> {
        let s = &self.synthesis;
        let member = |name: &str, length_m: f64| Member::cantilever(name, length_m, self.spec.hardware.link_radius_m);
        vec![
            // Clamped to the actuator's output, its tip held by the flap's pin.
            Member::new(
                "link",
                (self.loop_.a - self.loop_.o).norm(),
                self.spec.hardware.link_radius_m,
                MemberLoading::Bending,
            ),
            member("track", (s.track_ends_m[1] - s.track_ends_m[0]).norm()),
            member("strut-O", (s.strut_tops_m[0] - self.loop_.o).norm()),
            member("strut-track", (s.strut_tops_m[1] - s.track_ends_m[0]).norm()),
        ]
    }

    /// The members' loads when the flap's pivot at `a` takes `pin` from the link and the
    /// carriage at `c` takes `carriage_push` from the track (N; the members take the
    /// opposites).
    pub(super) fn member_loads(
        &self,
        a: Point2<f64>,
        pin: Vector2<f64>,
        c: Point2<f64>,
        carriage_push: Vector2<f64>,
    ) -> Vec<(String, MemberLoad)> {
        let s = &self.synthesis;
        let o = self.loop_.o;
        let track_start = s.track_ends_m[0];
        let on_track = -carriage_push;
        // The actuator's couple on the link balances the pin's moment about O; the support
        // takes the opposite couple and the pin force the link hands on at O.
        let actuator_couple = -cross(a - o, -pin);
        vec![
            (
                "link".into(),
                MemberLoad::of_straight_member(o, a, &[(a, -pin), (o, pin)], actuator_couple),
            ),
            (
                "track".into(),
                MemberLoad::of_cantilever_line(&[track_start, c], on_track, 0.0),
            ),
            (
                "strut-O".into(),
                MemberLoad::of_cantilever_line(&[s.strut_tops_m[0], o], -pin, -actuator_couple),
            ),
            (
                "strut-track".into(),
                MemberLoad::of_cantilever_line(
                    &[s.strut_tops_m[1], track_start],
                    on_track,
                    cross(c - track_start, on_track),
                ),
            ),
        ]
    }
}
