//! The track kinds' members (link-track: link, track, struts; hooked-track: rail, hook,
//! struts, or tie and truss rods) against a hand computation from each pose's pins and
//! reactions.

use flapwright_kinds::hooked_track::HookedTrack;
use flapwright_kinds::link_track::LinkTrack;
use flapwright_mechanism::seam::FlapMechanism;
use nalgebra::Point2;

use crate::synthesised::model_section::{hooked_track_spec, link_track_spec};
use crate::synthesised::{landing_load, member_load};

/// The track kinds' beams and struts against a hand computation from the pose's pins, the
/// reactions and the synthesis's geometry alone (a massless flap under a couple, so the
/// track or rail and the hook carry the flap's pins' pushes square to themselves or along
/// the hook's radius, and the link the track's push). Each member is a cantilever, its
/// moment |N| times the largest lever of the push's line about its sections: for a beam,
/// the carriage's distance from its root; for a strut, the larger of its two ends' (its top
/// on the skin, its foot at the beam's root); for the hook, over the exact lead-in and arc
/// (sampled every 0.01 deg, not the kind's 3 deg polyline) between its clamp and the roller.
/// The link's moment at O is the actuator's torque.
#[test]
fn track_members_carry_the_pins_pushes_as_cantilevers() {
    let load = landing_load();
    let close = |got: f64, want: f64, tolerance: f64, what: &str| {
        assert!(
            (got - want).abs() <= tolerance * want.abs().max(1.0),
            "{what}: {got} against {want}"
        );
    };
    let cross = |a: nalgebra::Vector2<f64>, b: nalgebra::Vector2<f64>| a.perp(&b);
    // Link-track.
    let mut spec = link_track_spec();
    spec.flap_mass.mass_kg = 0.0;
    let link_track = LinkTrack::synthesise(spec).unwrap();
    let s = link_track.synthesis();
    let d = s.track_direction;
    let n = nalgebra::Vector2::new(-d.y, d.x);
    let (start, [top_o, top_track]) = (s.track_ends_m[0], s.strut_tops_m);
    for input in link_track.input_range().samples(9) {
        let pose = link_track.pose(input).unwrap();
        let loads = link_track.kinetostatics(input, &load).unwrap();
        let push = loads.reactions.iter().find(|(r, _)| r == "C").unwrap().1.abs();
        let (a, c) = (pose.point("A").unwrap(), pose.point("C").unwrap());
        let m = |name: &str| member_load(&loads, name).bending_moment_nm;
        let torque = loads.actuator_load.abs();
        close(m("track"), push * (c - start).norm(), 1e-9, "track");
        close(
            m("strut-track"),
            push * (c - start).norm().max(cross(c - top_track, n).abs()),
            1e-9,
            "strut-track",
        );
        close(m("link"), torque, 1e-9, "link");
        close(
            m("strut-O"),
            torque.max(push * cross(a - top_o, n).abs()),
            1e-9,
            "strut-O",
        );
    }
    // Hooked-track, its struts clamped to the skin (no load cases: no truss).
    let mut spec = hooked_track_spec();
    spec.flap_mass.mass_kg = 0.0;
    spec.design_loads.clear();
    let hooked_track = HookedTrack::synthesise(spec).unwrap();
    let s = hooked_track.synthesis();
    assert!(s.truss.is_none());
    let d = s.rail_direction;
    let n = nalgebra::Vector2::new(-d.y, d.x);
    let (start, [top_rail, top_hook], clamp, k) =
        (s.rail_ends_m[0], s.strut_tops_m, s.hook_strut_foot_m, s.hook_centre_m);
    let range = hooked_track.input_range();
    let g_landing = hooked_track.pose(range.deployed).unwrap().point("G").unwrap();
    // The exact centre line: the lead-in, then the arc about K the short way.
    let g1 = s.aft_attachment_m + d * s.lead_m;
    let (from, to) = (g1 - k, g_landing - k);
    let sweep = cross(from, to).atan2(from.dot(&to));
    let mut path: Vec<Point2<f64>> = (0..=2000)
        .map(|i| s.aft_attachment_m + d * (s.lead_m * i as f64 / 2000.0))
        .collect();
    path.extend((1..=(sweep.abs().to_degrees() * 100.0) as usize).map(|i| {
        let angle = sweep * i as f64 / (sweep.abs().to_degrees() * 100.0).floor();
        k + nalgebra::Rotation2::new(angle) * from
    }));
    let nearest = |q: Point2<f64>| {
        (0..path.len())
            .min_by(|&i, &j| (path[i] - q).norm().total_cmp(&(path[j] - q).norm()))
            .unwrap()
    };
    let c = nearest(clamp);
    assert!((path[c] - clamp).norm() < 1e-3, "the clamp lies on the hook");
    let mut on_both_sides = [false, false];
    for input in range.samples(17) {
        let pose = hooked_track.pose(input).unwrap();
        let loads = hooked_track.kinetostatics(input, &load).unwrap();
        let reaction = |name: &str| loads.reactions.iter().find(|(r, _)| r == name).unwrap().1.abs();
        let (f, g) = (pose.point("F").unwrap(), pose.point("G").unwrap());
        let m = |name: &str| member_load(&loads, name).bending_moment_nm;
        let rail_push = reaction("rail");
        close(m("rail"), rail_push * (f - start).norm(), 1e-9, "rail");
        // The strut's top also takes the screw's reaction, on the rail's line through the
        // rail's start (the jack body stands on the support).
        let on_rail = -n * loads.reactions.iter().find(|(r, _)| r == "rail").unwrap().1;
        let on_jack = -d * loads.actuator_load;
        close(
            m("strut-rail"),
            cross(f - start, on_rail)
                .abs()
                .max((cross(f - top_rail, on_rail) + cross(start - top_rail, on_jack)).abs()),
            1e-9,
            "strut-rail",
        );
        let roller = reaction("G");
        let along = if input - range.stowed <= s.lead_m {
            n
        } else {
            (g - k).normalize()
        };
        let r = nearest(g);
        on_both_sides[usize::from(r > c)] = true;
        let (lo, hi) = (r.min(c), r.max(c));
        // The exact clamp and roller, and the samples strictly between them.
        let between = path[(lo + 1).min(hi)..hi].iter().chain([&clamp, &g]);
        let hook = between.map(|&x| cross(g - x, along).abs()).fold(0.0, f64::max);
        close(m("hook"), roller * hook, 1e-6, "hook");
        close(
            m("strut-hook"),
            roller * cross(g - clamp, along).abs().max(cross(g - top_hook, along).abs()),
            1e-9,
            "strut-hook",
        );
        // Its axial force: the push along the centre line's tangent, largest between them.
        let axial = (lo..hi)
            .map(|i| {
                (path[i + 1] - path[i])
                    .try_normalize(0.0)
                    .map_or(0.0, |t| along.dot(&t).abs())
            })
            .fold(0.0, f64::max);
        // The samples' chords turn up to 0.01 deg from the tangent at their ends: within
        // that much of the push.
        let got = member_load(&loads, "hook").axial_n.abs();
        assert!(
            (got - roller * axial).abs() <= roller * 0.02f64.to_radians(),
            "hook axial: {got} against {}",
            roller * axial
        );
    }
    assert_eq!(on_both_sides, [true, true], "the roller passes the clamp");
}

/// The hooked-track's support as a truss (its load cases given): the three rods' axial
/// forces and the carriage's, the roller's and the screw's pushes hold the support (no net
/// force, no net moment about two points; together the pushes are the flap's load), the rods carry no bending, and the tie's largest moment is the
/// larger of its two ends' (the rail's load moved to the rail's start, and that plus the
/// rods there about the hook's clamp): a hand computation from the pose's pins, the signed
/// reactions and the truss's geometry.
#[test]
fn the_hooked_tracks_truss_holds_the_support() {
    let load = landing_load();
    let cross = |a: nalgebra::Vector2<f64>, b: nalgebra::Vector2<f64>| a.perp(&b);
    let track = HookedTrack::synthesise(hooked_track_spec()).unwrap();
    let s = track.synthesis();
    let truss = s.truss.expect("the model section's support is a truss");
    let d = s.rail_direction;
    let n = nalgebra::Vector2::new(-d.y, d.x);
    let range = track.input_range();
    let [b, a] = truss.tie_m;
    assert_eq!(a, s.rail_ends_m[0]);
    assert_eq!(b, s.hook_strut_foot_m);
    for input in range.samples(13) {
        let pose = track.pose(input).unwrap();
        let loads = track.kinetostatics(input, &load).unwrap();
        let reaction = |name: &str| loads.reactions.iter().find(|(r, _)| r == name).unwrap().1;
        let (f, g) = (pose.point("F").unwrap(), pose.point("G").unwrap());
        let along = if input - range.stowed <= s.lead_m {
            n
        } else {
            (g - s.hook_centre_m).normalize()
        };
        // What the support takes: the opposites of the carriage's and the roller's reactions
        // and the screw's reaction at the jack's mount.
        let on_rail = -n * reaction("rail");
        let on_hook = -along * reaction("G");
        let on_jack = -d * loads.actuator_load;
        let scale = on_rail.norm() + on_hook.norm() + on_jack.norm();
        let mut forces = vec![(f, on_rail), (g, on_hook), (s.jack_mount_m, on_jack)];
        let mut at_a = nalgebra::Vector2::zeros();
        for (rod, name) in truss.rods.iter().zip(["strut-rail", "strut-hook", "brace"]) {
            let member = member_load(&loads, name);
            assert_eq!(member.bending_moment_nm, 0.0, "{name} is a two-force rod");
            let pull = (rod.top_m - rod.foot_m).normalize() * member.axial_n;
            forces.push((rod.foot_m, pull));
            if rod.foot_m == a {
                at_a += pull;
            }
        }
        // The three pushes are the flap's load (its weight and air load), which the rods
        // hand to the wing.
        let flap_load = flapwright_mechanism::shared::flap_load::FlapWrench::new(
            &hooked_track_spec().flap_mass,
            &pose.flap,
            &load,
            range.fraction(input),
        )
        .force_n();
        let pushes = on_rail + on_hook + on_jack;
        assert!(
            (pushes - flap_load).norm() <= 1e-9 * scale,
            "{pushes:?} against {flap_load:?}"
        );
        let net: nalgebra::Vector2<f64> = forces.iter().map(|(_, force)| force).sum();
        assert!(net.norm() <= 1e-9 * scale, "net force {net:?}");
        for about in [a, nalgebra::Point2::new(3.0, -2.0)] {
            let moment: f64 = forces.iter().map(|(p, force)| cross(p - about, *force)).sum();
            assert!(
                moment.abs() <= 1e-9 * scale * 4.0,
                "net moment {moment} about {about:?}"
            );
        }
        let tip = cross(f - a, on_rail).abs();
        let root = (cross(f - b, on_rail) + cross(a - b, at_a + on_jack)).abs();
        let tie = member_load(&loads, "tie").bending_moment_nm;
        assert!(
            (tie - tip.max(root)).abs() <= 1e-9 * tie.max(1.0),
            "tie {tie} against {tip} / {root}"
        );
    }
}
