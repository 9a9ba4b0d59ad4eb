//! The hooked-track's bodies and joints: the flap with its fitting from the carriage's pin
//! F to the roller G, the carriage sliding on the rail, and the fixed support (the rail,
//! the hook, the screw jack on the rail's line and struts to the lower skin), with speed
//! bounds per metre of stroke.

use nalgebra::{Point2, Vector2};

use super::rail::Rail;
use super::{HookedTrackSpec, HookedTrackSynthesis};
use flapwright_mechanism::seam::{Body, BodyRole, BodySolid, Joint, JointEnd, JointGeometry, PlanarShape, SpeedBound};

const FLAP: usize = 0;
const CARRIAGE: usize = 1;
const SUPPORT: usize = 2;

/// Points along the hook's centre line: the lead-in from G to G1, then the arc about K to
/// the roller's landing place, every few degrees.
pub(super) fn hook_centre_line(rail: &Rail, g_landing: Point2<f64>) -> Vec<Point2<f64>> {
    let g1 = rail.g + rail.d.into_inner() * rail.lead_m;
    let (from, to) = (g1 - rail.k, g_landing - rail.k);
    let sweep = from.perp(&to).atan2(from.dot(&to));
    let steps = ((sweep.abs().to_degrees() / 3.0).ceil() as usize).max(2);
    let mut line = vec![rail.g];
    if rail.lead_m > 0.0 {
        line.push(g1);
    }
    line.extend((1..=steps).map(|k| {
        let angle = sweep * k as f64 / steps as f64;
        let (sin, cos) = angle.sin_cos();
        rail.k + Vector2::new(cos * from.x - sin * from.y, sin * from.x + cos * from.y)
    }));
    line
}

/// The bodies and joints. The carriage moves one metre per metre of stroke without
/// turning; the flap's pin F moves with it, and the flap turns at most 1 / (ℓ sin μ) per
/// metre with μ the certified smallest transmission angle: with r = F - G, β the angle of r
/// to d and the rates of `rail`, |r x d| = ℓ |sin β| and |r x G'| = ℓ |cos β| cot μ, so
/// |ω| = |r x (d - G')| / ℓ² <= (|sin β| + |cos β| cot μ) / ℓ <= 1 / (ℓ sin μ) (0 in the
/// lead-in).
pub(super) fn bodies_and_joints(
    spec: &HookedTrackSpec,
    synthesis: &HookedTrackSynthesis,
    rail: &Rail,
    certified_transmission: f64,
) -> (Vec<Body>, Vec<Joint>) {
    let hw = &spec.hardware;
    let (f, g) = (rail.f, rail.g);
    let capsule = |name: &str, from: Point2<f64>, to: Point2<f64>| BodySolid::capsule(name, from, to, hw.link_radius_m);
    let sine = certified_transmission.sin().max(1e-9);
    let [rail_start, rail_end] = synthesis.rail_ends_m;
    let d = rail.d.into_inner();
    // The screw runs from the jack over the carriage's whole travel.
    let mount = synthesis.jack_mount_m;
    let screw_end = if (rail_end - mount).norm() > (rail_start - mount).norm() {
        rail_end
    } else {
        rail_start
    };
    let jack_half = 0.5 * hw.jack_body_length_m;
    let hook = BodySolid {
        name: "hook".into(),
        shape: PlanarShape::Tube {
            centre_line: hook_centre_line(rail, spec.landing.flap * g),
            radius_m: hw.link_radius_m,
        },
        width_m: 0.0,
        offset_m: 0.0,
    };
    let mut bodies = vec![
        Body {
            name: "flap".into(),
            role: BodyRole::Flap,
            solids: vec![
                capsule("fitting", f, g),
                BodySolid::capsule("roller", g, g, hw.nut_radius_m),
            ],
            speed_bound: SpeedBound {
                reference: f,
                linear_per_input: 1.0,
                angular_per_input: 1.0 / (sine * rail.span),
            },
        },
        Body {
            name: "carriage".into(),
            role: BodyRole::Carriage,
            solids: vec![BodySolid::capsule("carriage", f, f, hw.nut_radius_m)],
            speed_bound: SpeedBound {
                reference: f,
                linear_per_input: 1.0,
                angular_per_input: 0.0,
            },
        },
        Body {
            name: "support".into(),
            role: BodyRole::Support,
            solids: vec![
                capsule("rail", rail_start, rail_end),
                hook,
                BodySolid::capsule("screw", synthesis.jack_mount_m, screw_end, 0.5 * hw.link_radius_m),
                BodySolid::capsule(
                    "jack-body",
                    synthesis.jack_mount_m - d * jack_half,
                    synthesis.jack_mount_m + d * jack_half,
                    hw.jack_body_radius_m,
                ),
                capsule("strut-rail", rail_start, synthesis.strut_tops_m[0]),
                capsule("strut-hook", synthesis.hook_strut_foot_m, synthesis.strut_tops_m[1]),
            ]
            .into_iter()
            .chain(synthesis.truss.iter().flat_map(|truss| {
                let brace = truss.rods[2];
                [
                    capsule("tie", truss.tie_m[0], truss.tie_m[1]),
                    capsule("brace", brace.foot_m, brace.top_m),
                ]
            }))
            .collect(),
            speed_bound: SpeedBound::FIXED,
        },
    ];
    let joints = vec![
        Joint::new(
            "rail",
            "the carriage on the straight rail, driven along it by the screw jack",
            JointGeometry::Prismatic {
                origin: f,
                direction: rail.d,
            },
            [JointEnd::Body(SUPPORT), JointEnd::Body(CARRIAGE)],
            &[("carriage", "rail"), ("carriage", "screw")],
        ),
        Joint::new(
            "F",
            "the flap's fitting pinned to the carriage",
            JointGeometry::Revolute { at: f },
            [JointEnd::Body(CARRIAGE), JointEnd::Body(FLAP)],
            &[("carriage", "fitting")],
        ),
        Joint::new(
            "G",
            "the flap's roller in the lead-in (stowed: straight along the rail) and then the hook",
            JointGeometry::PinInHookedSlot {
                pin: g,
                direction: rail.d,
                lead_m: rail.lead_m,
                centre: rail.k,
            },
            [JointEnd::Body(FLAP), JointEnd::Body(SUPPORT)],
            &[("roller", "hook"), ("fitting", "hook")],
        ),
    ];
    // Spanwise, side by side (`flapwright_mechanism::spanwise`'s spacing: layers 3 r_max apart clear each
    // other by r_max): the roller, its fitting and the hook in the station plane; the rail
    // with its carriage and screw beside them; the jack body and the rail's strut beside
    // those, each next to what it holds (the screw, the rail's forward end); the hook's
    // strut on the hook's other side. The layout from the joints alone would part the
    // fitting from the rail but put the jack and the strut two layers from what they hold,
    // across the fitting's layer.
    let r_max = [hw.link_radius_m, hw.nut_radius_m, hw.jack_body_radius_m]
        .into_iter()
        .fold(0.0, f64::max);
    let spacing = 3.0 * r_max;
    let brace_at_rail_start = synthesis
        .truss
        .is_some_and(|truss| truss.rods[2].foot_m == truss.foot_a());
    for solid in bodies.iter_mut().flat_map(|body| body.solids.iter_mut()) {
        solid.offset_m = spacing
            * match solid.name.as_str() {
                "carriage" | "rail" | "screw" => -1.0,
                "jack-body" | "strut-rail" => -2.0,
                "strut-hook" | "tie" => 1.0,
                // Beside the strut whose foot it shares.
                "brace" if brace_at_rail_start => -2.0,
                "brace" => 1.0,
                _ => 0.0,
            };
    }
    (bodies, joints)
}
