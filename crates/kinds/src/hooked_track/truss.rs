//! The hooked-track's support laid out as a truss
//! ([`flapwright_mechanism::shared::support_truss`]): the support is one rigid body in the
//! kinematics, the rail, the hook and the tie between the rail's forward end A and the
//! hook's clamp B (the track beam that joins them), held by the rail's strut from A, the
//! hook's strut from B and a brace; the loads on it are the carriage's, the roller's and
//! the screw jack's pushes (the jack body is mounted on the support, on the rail's line, so
//! together they are the flap's load). The rail and the hook still carry their rollers in
//! bending from A and from B, and the tie carries the rail's side to the hook's: a
//! cantilever from B under the rail's load, the jack's reaction and the pulls of the rods
//! at A (the `members` module). The planar truss leaves out what the spanwise layers add
//! (the parts stand side by side, joined at A and B across them): a moment about the
//! plane's axes that the fittings carry, not sized here.
//!
//! Before this (and where no brace or tie clears, still): each strut clamped to the skin,
//! carrying its rail's root force and couple in bending. On the transport scene's ob-inner
//! station the two struts were 165 of the mechanism's 199 kg (`003_...` Table 1: 43.1 kg
//! for the whole hooked-track), a solid bar being the least efficient section in bending.
//!
//! The tops offered: every lower-skin top a strut may take (`placement::strut_tops`, clear
//! of the structure and of the moving flap with the struts' radius and margin, aft of the
//! rear spar's web) at each foot, and for A also the rear spar's web.

use nalgebra::{Point2, Vector2, Vector3};

use super::clearance::{web_strut_top, Clearance};
use super::HookedTrackSpec;
use flapwright_mechanism::shared::placement::{strut_tops, STRUT_TOPS_AHEAD};
use flapwright_mechanism::shared::support_truss::{resultant, SupportTruss};

/// The rods' names, in [`SupportTruss::rods`]'s order.
pub const ROD_NAMES: [&str; 3] = ["strut-rail", "strut-hook", "brace"];

/// The truss for a support with its rail from `a` and the hook's clamp at `b`, under the
/// support's loads at the sampled poses (`loads`, each the carriage's, the roller's and the
/// screw jack's pushes): the triple of rods of least Σ L_i max|t_i| (see the module doc), or None
/// where the tie does not clear, a foot has no clear top, or no triple holds the body.
pub(super) fn place_truss(
    spec: &HookedTrackSpec,
    clearance: &Clearance,
    a: Point2<f64>,
    b: Point2<f64>,
    loads: &[[(Point2<f64>, Vector2<f64>); 3]],
) -> Option<SupportTruss> {
    let radius = spec.hardware.link_radius_m;
    let outline = &spec.outline;
    let (_, _, chord) = outline.flap_chord()?;
    if loads.is_empty()
        || clearance.clear_of_flap(spec, b, a, radius).is_err()
        || !clearance.clear_of_wing(spec, b, a, radius)
    {
        return None;
    }
    let margin = clearance.margin_m + clearance.allowance_m;
    // Tops in the trailing-edge bay, aft of the rear spar's web: a rod to the skin under
    // the wing box would need a fairing along the box (and, nearly along the skin, meets it
    // in the layers beside the plane where the tapered wing is thinner).
    let web_face = outline.rear_web().map_or(f64::INFINITY, |(face, _, _)| face);
    let tops = |foot: Point2<f64>| -> Vec<Point2<f64>> {
        strut_tops(outline, foot, &STRUT_TOPS_AHEAD, radius, margin, &clearance.poses, None)
            .filter(|top| top.x <= web_face)
            .collect()
    };
    let mut tops_a = tops(a);
    tops_a.extend(web_strut_top(spec, clearance, a));
    let tops_b = tops(b);
    let resultants: Vec<Vector3<f64>> = loads.iter().map(|pair| resultant(pair, a)).collect();
    SupportTruss::lightest(a, b, &tops_a, &tops_b, &resultants, chord)
}
