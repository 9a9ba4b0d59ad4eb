//! The hooked-track's members and their loads at a pose: the rail and the hook, each a
//! cantilever from the strut that holds it, and the two struts to the lower skin.
//!
//! `003_...` section 3 models the straight part of the rail and the hook as links; here
//! they are the rails those links stand for (see the kind's module doc), so they carry
//! their rollers' loads in bending:
//!
//! - **rail**: clamped at its forward end, where `strut-rail` holds it; the carriage at F
//!   pushes it square to itself, -N_F n (the screw's push along the rail is the jack's, which
//!   is mounted apart).
//! - **hook**: the roller's lead-in and arc, clamped at its middle, where `strut-hook` holds
//!   it; the roller at G pushes it square to the lead-in or along the hook's radius,
//!   -N_G m, and the part of the hook between the clamp and the roller carries it.
//! - **strut-rail**, **strut-hook**: clamped to the lower skin, each carrying its rail's
//!   root force and couple at its foot.
//!
//! Each is a cantilever under one force and a couple ([`MemberLoad::of_cantilever_line`]):
//! the rail and the hook are sized where they bend most, the struts for what they hand to
//! the skin. The two load paths are taken apart (the support is one rigid body in the
//! kinematics; how its parts share load between them is a structural design left open).

use nalgebra::{Point2, Vector2};

use super::bodies::hook_centre_line;
use super::HookedTrack;
use crate::members::{Member, MemberLoad};
use crate::outline::point_segment_distance;
use crate::rocker_drive::cross;

/// The hook's centre line from its clamp (the strut's foot) to the roller at `g`: the
/// vertices between them, then `g`.
fn hook_from_clamp(line: &[Point2<f64>], foot: usize, g: Point2<f64>) -> Vec<Point2<f64>> {
    // The segment of the centre line nearest to the roller.
    let segment = (0..line.len().saturating_sub(1))
        .map(|i| (i, point_segment_distance(g, line[i], line[i + 1])))
        .fold(
            (0, f64::INFINITY),
            |best, (i, d)| if d < best.1 { (i, d) } else { best },
        )
        .0;
    let mut from_clamp: Vec<Point2<f64>> = if segment < foot {
        (segment + 1..=foot).rev().map(|i| line[i]).collect()
    } else {
        (foot..=segment).map(|i| line[i]).collect()
    };
    from_clamp.push(g);
    from_clamp
}

fn polyline_length(line: &[Point2<f64>]) -> f64 {
    line.windows(2).map(|pair| (pair[1] - pair[0]).norm()).sum()
}

impl HookedTrack {
    fn hook_line(&self) -> Vec<Point2<f64>> {
        hook_centre_line(&self.rail, self.spec.landing.flap * self.rail.g)
    }

    /// The rail, the hook and their struts (see the module doc).
    pub(super) fn member_list(&self) -> Vec<Member> {
        let s = &self.synthesis;
        let member = |name: &str, length_m: f64| Member::bending(name, length_m, self.spec.hardware.link_radius_m);
        vec![
            member("rail", (s.rail_ends_m[1] - s.rail_ends_m[0]).norm()),
            member("hook", polyline_length(&self.hook_line())),
            member("strut-rail", (s.strut_tops_m[0] - s.rail_ends_m[0]).norm()),
            member("strut-hook", (s.strut_tops_m[1] - s.hook_strut_foot_m).norm()),
        ]
    }

    /// The members' loads when the carriage at `f` takes `carriage_push` from the rail and
    /// the roller at `g` takes `roller_push` from the hook (N; the members take the
    /// opposites).
    pub(super) fn member_loads(
        &self,
        f: Point2<f64>,
        carriage_push: Vector2<f64>,
        g: Point2<f64>,
        roller_push: Vector2<f64>,
    ) -> Vec<(String, MemberLoad)> {
        let s = &self.synthesis;
        let rail_start = s.rail_ends_m[0];
        let on_rail = -carriage_push;
        let on_hook = -roller_push;
        let line = self.hook_line();
        let foot = line.len() / 2;
        let clamp = line[foot];
        vec![
            (
                "rail".into(),
                MemberLoad::of_cantilever_line(&[rail_start, f], on_rail, 0.0),
            ),
            (
                "hook".into(),
                MemberLoad::of_cantilever_line(&hook_from_clamp(&line, foot, g), on_hook, 0.0),
            ),
            (
                "strut-rail".into(),
                MemberLoad::of_cantilever_line(
                    &[s.strut_tops_m[0], rail_start],
                    on_rail,
                    cross(f - rail_start, on_rail),
                ),
            ),
            (
                "strut-hook".into(),
                MemberLoad::of_cantilever_line(&[s.strut_tops_m[1], clamp], on_hook, cross(g - clamp, on_hook)),
            ),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point2<f64> {
        Point2::new(x, y)
    }

    /// The part of the hook that carries the roller runs from the clamp towards the roller,
    /// whichever side of the clamp it is on, and ends at the roller.
    #[test]
    fn the_hook_carries_the_roller_from_its_clamp() {
        let line = [p(0.0, 0.0), p(1.0, 0.0), p(2.0, 0.0), p(3.0, 0.0), p(4.0, 0.0)];
        assert_eq!(
            hook_from_clamp(&line, 2, p(0.4, 0.0)),
            vec![p(2.0, 0.0), p(1.0, 0.0), p(0.4, 0.0)]
        );
        assert_eq!(
            hook_from_clamp(&line, 2, p(3.5, 0.0)),
            vec![p(2.0, 0.0), p(3.0, 0.0), p(3.5, 0.0)]
        );
        assert_eq!(hook_from_clamp(&line, 2, p(2.2, 0.0)), vec![p(2.0, 0.0), p(2.2, 0.0)]);
        assert_eq!(polyline_length(&line), 4.0);
    }
}
