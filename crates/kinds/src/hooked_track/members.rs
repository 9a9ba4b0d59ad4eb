//! The hooked-track's members and their loads at a pose: the rail and the hook, each a
//! cantilever from where the support holds it, and what holds the support to the wing.
//!
//! `003_...` section 3 models the straight part of the rail and the hook as links; here
//! they are the rails those links stand for (see the kind's module doc), so they carry
//! their rollers' loads in bending:
//!
//! - **rail**: clamped at its forward end A; the carriage at F pushes it square to itself,
//!   -N_F n; the screw's reaction -Q d acts at the jack's mount on the rail's line (the jack
//!   body is on the support): a jack behind the rail (pulling) loads the rail along itself,
//!   one ahead of the carriage (pushing) hands its reaction to A directly.
//! - **hook**: the roller's lead-in and arc, clamped at the middle vertex of its centre
//!   line (every 3 deg of arc), B; the roller at G pushes it square to the lead-in or along
//!   the hook's radius, -N_G m, and the part of the hook between the clamp and the roller
//!   carries it.
//!
//! What holds them, with a truss (the `truss` module, `003_...` section 2's "truss-based
//! support structure"):
//! - **tie**: from B to A, a cantilever from B carrying the rail's side: the rail's load
//!   moved to A (a force and a couple), the jack's reaction and the pulls of the rods whose
//!   foot is A;
//! - **strut-rail**, **strut-hook**, **brace**: rods pinned at both ends, their axial forces
//!   from the support's equilibrium.
//!
//! Without one (no brace or tie clears, or no load cases): **strut-rail** and
//! **strut-hook** clamped to the lower skin (the rail's, where none to the skin keeps clear,
//! to the rear spar's web), each carrying its rail's root force and couple at its foot (the
//! rail's with the jack's reaction), the two load paths taken apart.
//!
//! Each bending member is a cantilever under one force and a couple
//! ([`MemberLoad::of_cantilever_line`]; the hook through [`MemberLoad::of_cantilever_curve`]
//! with its exact tangents and the arc's points farthest from the push's line): sized where
//! it bends most.

use nalgebra::{Point2, Vector2};

use super::truss::ROD_NAMES;
use super::HookedTrack;
use flapwright_mechanism::shared::geometry::cross;
use flapwright_mechanism::shared::members::{Member, MemberLoad, MemberLoading};
use flapwright_mechanism::shared::outline::point_segment_distance;

/// The hook's centre line from its clamp (the strut's foot, vertex `foot`) to the roller
/// at `g`: the vertices between them, then `g`, each with the line's unit tangent there
/// pointing from the clamp towards the roller: along the lead-in (the first segment of
/// `line` when `lead_in`), square to the radius from the hook's centre `k` on the arc.
fn hook_from_clamp(
    line: &[Point2<f64>],
    foot: usize,
    g: Point2<f64>,
    k: Point2<f64>,
    lead_in: bool,
) -> Vec<(Point2<f64>, Vector2<f64>)> {
    // The segment of the centre line nearest to the roller.
    let segment = (0..line.len().saturating_sub(1))
        .map(|i| (i, point_segment_distance(g, line[i], line[i + 1])))
        .fold(
            (0, f64::INFINITY),
            |best, (i, d)| if d < best.1 { (i, d) } else { best },
        )
        .0;
    let mut points: Vec<Point2<f64>> = if segment < foot {
        (segment + 1..=foot).rev().map(|i| line[i]).collect()
    } else {
        (foot..=segment).map(|i| line[i]).collect()
    };
    points.push(g);
    // Which way along the line the roller lies from the clamp, and which way the arc turns
    // about k as the line runs (its last segment is on the arc).
    let towards_roller = if segment < foot { -1.0 } else { 1.0 };
    let n = line.len();
    let turning = if n > 1 {
        cross(line[n - 2] - k, line[n - 1] - k).signum()
    } else {
        0.0
    };
    let lead = if n > 1 { line[1] - line[0] } else { Vector2::zeros() };
    let scale = lead.norm().max(1.0);
    points
        .iter()
        .map(|&p| {
            let on_lead_in = lead_in && n > 1 && point_segment_distance(p, line[0], line[1]) <= 1e-12 * scale;
            let along_line = if on_lead_in {
                lead
            } else {
                let r = p - k;
                Vector2::new(-r.y, r.x) * turning
            };
            (
                p,
                along_line.try_normalize(0.0).unwrap_or_else(Vector2::zeros) * towards_roller,
            )
        })
        .collect()
}

/// `curve` (from [`hook_from_clamp`]) with the points of its arc pieces where the radius
/// from `k` stands square to `force`, where they fall between two of its points on the arc:
/// there the arc stands farthest from the force's line through any point and runs along
/// the force, so the cantilever's largest moment and axial force are at its points.
fn with_arc_extremes(
    curve: &[(Point2<f64>, Vector2<f64>)],
    k: Point2<f64>,
    force: Vector2<f64>,
) -> Vec<(Point2<f64>, Vector2<f64>)> {
    let Some(square) = Vector2::new(-force.y, force.x).try_normalize(0.0) else {
        return curve.to_vec();
    };
    let mut out = Vec::with_capacity(curve.len() + 2);
    for pair in curve.windows(2) {
        out.push(pair[0]);
        let ((a, ta), (b, _)) = (pair[0], pair[1]);
        let (ra, rb) = (a - k, b - k);
        let radius = ra.norm();
        // An arc piece: both ends on the circle, tangents square to the radius.
        let on_arc = radius > 0.0 && (rb.norm() - radius).abs() <= 1e-9 * radius && ta.dot(&ra).abs() <= 1e-9;
        if !on_arc {
            continue;
        }
        let piece = cross(ra, rb).atan2(ra.dot(&rb));
        for direction in [square, -square] {
            let to = cross(ra, direction).atan2(ra.dot(&direction));
            if to * piece > 0.0 && to.abs() < piece.abs() {
                let r = direction * radius;
                // The tangent turns with the radius from a's.
                let tangent = nalgebra::Rotation2::new(to) * ta;
                out.push((k + r, tangent));
            }
        }
    }
    out.extend(curve.last().copied());
    out
}

fn polyline_length(line: &[Point2<f64>]) -> f64 {
    line.windows(2).map(|pair| (pair[1] - pair[0]).norm()).sum()
}

impl HookedTrack {
    /// The rail and the hook, and the struts clamped to the skin or, with a truss, the tie
    /// and the three rods (see the module doc).
    pub(super) fn member_list(&self) -> Vec<Member> {
        let s = &self.synthesis;
        let radius = self.spec.hardware.link_radius_m;
        let member = |name: &str, length_m: f64| Member::cantilever(name, length_m, radius);
        let mut members = vec![
            member("rail", (s.rail_ends_m[1] - s.rail_ends_m[0]).norm()),
            member("hook", polyline_length(&self.hook_line)),
        ];
        match &s.truss {
            Some(truss) => {
                let [b, a] = truss.tie_m;
                members.push(Member::new("tie", (a - b).norm(), radius, MemberLoading::Bending));
                members.extend(
                    ROD_NAMES
                        .iter()
                        .zip(truss.lengths_m())
                        .map(|(name, length)| Member::new(name, length, radius, MemberLoading::TwoForce)),
                );
            }
            None => members.extend([
                member("strut-rail", (s.strut_tops_m[0] - s.rail_ends_m[0]).norm()),
                member("strut-hook", (s.strut_tops_m[1] - s.hook_strut_foot_m).norm()),
            ]),
        }
        members
    }

    /// The members' loads when the carriage at `f` takes `carriage_push` from the rail and
    /// the screw (the screw's part along the rail, the rail's square to it) and the roller at
    /// `g` takes `roller_push` from the hook (N; the members take the opposites: the jack's
    /// mount, on the support on the rail's line, takes the screw's reaction).
    pub(super) fn member_loads(
        &self,
        f: Point2<f64>,
        carriage_push: Vector2<f64>,
        g: Point2<f64>,
        roller_push: Vector2<f64>,
    ) -> Vec<(String, MemberLoad)> {
        let s = &self.synthesis;
        let rail_start = s.rail_ends_m[0];
        let d = s.rail_direction;
        // The screw's reaction at the jack's mount, on the rail's line through A: it adds no
        // moment about A. A jack behind the rail (pulling) hands it to A along the rail.
        let on_jack = -d * carriage_push.dot(&d);
        let on_rail = -carriage_push - on_jack;
        let on_hook = -roller_push;
        let jack_behind = (s.jack_mount_m - rail_start).dot(&d) > 0.0;
        let mut rail = MemberLoad::of_cantilever_line(&[rail_start, f], on_rail, 0.0);
        if jack_behind {
            rail.axial_n = on_jack.dot(&d);
        }
        let line = &self.hook_line;
        let foot = self.hook_foot;
        let clamp = line[foot];
        let mut loads = vec![
            ("rail".into(), rail),
            (
                "hook".into(),
                MemberLoad::of_cantilever_curve(
                    &with_arc_extremes(
                        &hook_from_clamp(line, foot, g, self.rail.k, self.rail.lead_m > 0.0),
                        self.rail.k,
                        on_hook,
                    ),
                    on_hook,
                    0.0,
                ),
            ),
        ];
        match &s.truss {
            Some(truss) => {
                let tensions = truss.tensions(&[(f, on_rail), (g, on_hook), (s.jack_mount_m, on_jack)]);
                // The tie from the hook's clamp carries the rail's side: the carriage's push,
                // the jack's reaction and the pulls of the rods whose foot is the rail's start.
                let at_rail_start: Vector2<f64> = (0..3)
                    .filter(|&i| truss.rods[i].foot_m == rail_start)
                    .map(|i| truss.pull(i, tensions[i]))
                    .sum();
                loads.push((
                    "tie".into(),
                    MemberLoad::of_cantilever_line(
                        &truss.tie_m,
                        on_rail + on_jack + at_rail_start,
                        cross(f - rail_start, on_rail),
                    ),
                ));
                loads.extend(
                    ROD_NAMES
                        .iter()
                        .zip(tensions)
                        .map(|(name, t)| ((*name).to_owned(), MemberLoad::axial(t))),
                );
            }
            None => loads.extend([
                (
                    "strut-rail".into(),
                    MemberLoad::of_cantilever_line(
                        &[s.strut_tops_m[0], rail_start],
                        on_rail + on_jack,
                        cross(f - rail_start, on_rail),
                    ),
                ),
                (
                    "strut-hook".into(),
                    MemberLoad::of_cantilever_line(&[s.strut_tops_m[1], clamp], on_hook, cross(g - clamp, on_hook)),
                ),
            ]),
        }
        loads
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point2<f64> {
        Point2::new(x, y)
    }

    /// The part of the hook that carries the roller runs from the clamp towards the roller,
    /// whichever side of the clamp it is on, and ends at the roller; its tangents point
    /// that way, along the lead-in there and square to the radius on the arc.
    #[test]
    fn the_hook_carries_the_roller_from_its_clamp() {
        // A lead-in up x = 1 to (1, 0), then a half circle about the origin to (-1, 0).
        let mut line = vec![p(1.0, -1.0)];
        line.extend((0..=6).map(|i| {
            let a = std::f64::consts::PI * i as f64 / 6.0;
            p(a.cos(), a.sin())
        }));
        let foot = line.len() / 2; // (0, 1)
        let k = p(0.0, 0.0);
        let close = |a: Vector2<f64>, b: Vector2<f64>| (a - b).norm() < 1e-12;
        // The roller on the lead-in: back down the arc, then along the lead-in downwards.
        let down = hook_from_clamp(&line, foot, p(1.0, -0.5), k, true);
        assert_eq!(down.len(), 5);
        assert!((down[0].0 - p(0.0, 1.0)).norm() < 1e-12);
        assert!(close(down[0].1, Vector2::new(1.0, 0.0)), "{:?}", down[0]);
        assert_eq!(down[4].0, p(1.0, -0.5));
        assert!(close(down[4].1, Vector2::new(0.0, -1.0)), "{:?}", down[4]);
        // The roller past the clamp on the arc: on round it, anticlockwise.
        let on = hook_from_clamp(&line, foot, p(-1.0, 0.0), k, true);
        assert_eq!(on.len(), 4);
        assert!(close(on[0].1, Vector2::new(-1.0, 0.0)), "{:?}", on[0]);
        assert!(close(on[3].1, Vector2::new(0.0, -1.0)), "{:?}", on[3]);
        // At the clamp itself: the clamp and the roller.
        assert_eq!(hook_from_clamp(&line, foot, line[foot], k, true).len(), 2);
        let straight = [p(0.0, 0.0), p(1.0, 0.0), p(2.0, 0.0)];
        assert_eq!(polyline_length(&straight), 2.0);
    }
}
