//! The hooked-track's support laid out as a truss: `003_...` section 2 "A truss-based
//! support structure is automatically synthesized, connecting the mechanism to the spar and
//! wing box", its links "rigid rods, carrying normal loads only".
//!
//! The support is one rigid body in the kinematics: the rail, the hook and the tie between
//! the rail's forward end A and the hook's clamp B (the track beam that joins them). Three
//! rods pinned at both ends hold it to the wing: the rail's strut from A, the hook's strut
//! from B and a brace from A or B to a top of its own. Three rods whose lines do not all
//! meet in one point (nor all run parallel) fix a plane body, and each carries an axial
//! force alone, found from the body's equilibrium: Σ t_i u_i = -Σ F_j and
//! Σ (p_i - A) × t_i u_i = -Σ (q_j - A) × F_j (u_i the rod's unit vector from its foot p_i
//! to its top, t_i its tension; F_j the carriage's, the roller's and the screw jack's pushes
//! on the support at q_j: the jack body is mounted on the support, on the rail's line, so
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
//! Where the rods go: every lower-skin top a strut may take (`placement::strut_tops`,
//! clear of the structure and of the moving flap with the struts' radius and margin; for
//! A also the rear spar's web) at each foot; of the triples (a top for each strut, the
//! brace at either foot with a top at least 4 % of the flap chord from that foot's strut's),
//! the one with the least Σ L_i max|t_i| over the sampled deployment and the load cases,
//! the rods' volume when strength sizes them (Euler buckling grows it for long rods in
//! compression; the sizing stage finds it).

use nalgebra::{Matrix3, Point2, Vector2, Vector3};
use serde::Serialize;

use super::clearance::{web_strut_top, Clearance, STRUT_TOPS_AHEAD};
use super::HookedTrackSpec;
use flapwright_mechanism::shared::geometry::cross;
use flapwright_mechanism::shared::placement::strut_tops;

/// The rods' names, in [`SupportTruss::rods`]'s order.
pub const ROD_NAMES: [&str; 3] = ["strut-rail", "strut-hook", "brace"];

/// Least |det| of the rods' equilibrium matrix (unit force columns, moments over the
/// flap chord) a truss may have: below it the three rods' lines nearly meet in one point
/// and their forces grow without bound.
const MIN_DETERMINANT: f64 = 1e-3;

/// A rod pinned to the support at `foot_m` and to the wing at `top_m` (station frame, m).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SupportRod {
    /// Where it holds the support: the rail's forward end or the hook's clamp.
    pub foot_m: Point2<f64>,
    /// Where it meets the wing: the lower skin or the rear spar's web.
    pub top_m: Point2<f64>,
}

impl SupportRod {
    fn length_m(&self) -> f64 {
        (self.top_m - self.foot_m).norm()
    }

    /// The unit vector from the foot to the top: the rod's pull on the support per newton
    /// of tension.
    fn pull(&self) -> Vector2<f64> {
        (self.top_m - self.foot_m) / self.length_m()
    }
}

/// The support's truss (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SupportTruss {
    /// The rail's strut (from A), the hook's strut (from B) and the brace (from A or B).
    pub rods: [SupportRod; 3],
    /// The tie from the hook's clamp B to the rail's forward end A.
    pub tie_m: [Point2<f64>; 2],
    /// The equilibrium's inverse: tensions from the load's resultant about A.
    #[serde(skip)]
    inverse: Matrix3<f64>,
}

/// The resultant of `loads` (points and forces on the support) about `about`: force x, y
/// and moment.
fn resultant(loads: &[(Point2<f64>, Vector2<f64>)], about: Point2<f64>) -> Vector3<f64> {
    loads.iter().fold(Vector3::zeros(), |sum, &(at, force)| {
        sum + Vector3::new(force.x, force.y, cross(at - about, force))
    })
}

impl SupportTruss {
    /// The truss of `rods` with the tie from `b` to `a`, or None where the rods' lines
    /// nearly meet in one point (see [`MIN_DETERMINANT`]; `length` scales the moments).
    fn new(rods: [SupportRod; 3], a: Point2<f64>, b: Point2<f64>, length: f64) -> Option<Self> {
        let column = |rod: &SupportRod| {
            let u = rod.pull();
            Vector3::new(u.x, u.y, cross(rod.foot_m - a, u) / length)
        };
        let scaled = Matrix3::from_columns(&[column(&rods[0]), column(&rods[1]), column(&rods[2])]);
        if scaled.determinant().abs() < MIN_DETERMINANT {
            return None;
        }
        let unscale = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 1.0 / length));
        let inverse = scaled.try_inverse()? * unscale;
        Some(Self {
            rods,
            tie_m: [b, a],
            inverse,
        })
    }

    /// The rail's forward end A.
    pub fn rail_start(&self) -> Point2<f64> {
        self.tie_m[1]
    }

    /// The rods' tensions (N, tension positive) that hold the support under `loads`
    /// (points and forces on it).
    pub fn tensions(&self, loads: &[(Point2<f64>, Vector2<f64>)]) -> [f64; 3] {
        let t = -(self.inverse * resultant(loads, self.rail_start()));
        [t.x, t.y, t.z]
    }

    /// The pull of rod `i` on the support at tension `t` (N).
    pub fn pull(&self, i: usize, tension: f64) -> Vector2<f64> {
        self.rods[i].pull() * tension
    }

    /// The rods' lengths (m).
    pub fn lengths_m(&self) -> [f64; 3] {
        self.rods.map(|rod| rod.length_m())
    }
}

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
    let rod = |foot, top| SupportRod {
        foot_m: foot,
        top_m: top,
    };
    let apart = |p: Point2<f64>, q: Point2<f64>| (p - q).norm() > 0.04 * chord;
    let mut best: Option<(f64, SupportTruss)> = None;
    for &top_a in &tops_a {
        for &top_b in &tops_b {
            let braces = tops_a
                .iter()
                .filter(|&&t| apart(t, top_a))
                .map(|&t| rod(a, t))
                .chain(tops_b.iter().filter(|&&t| apart(t, top_b)).map(|&t| rod(b, t)));
            for brace in braces {
                let Some(truss) = SupportTruss::new([rod(a, top_a), rod(b, top_b), brace], a, b, chord) else {
                    continue;
                };
                let mut peak = [0.0_f64; 3];
                for r in &resultants {
                    let t = -(truss.inverse * r);
                    for (p, t) in peak.iter_mut().zip([t.x, t.y, t.z]) {
                        *p = p.max(t.abs());
                    }
                }
                let cost: f64 = peak.iter().zip(truss.lengths_m()).map(|(p, l)| p * l).sum();
                if cost.is_finite() && best.as_ref().is_none_or(|(c, _)| cost < *c) {
                    best = Some((cost, truss));
                }
            }
        }
    }
    best.map(|(_, truss)| truss)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point2<f64> {
        Point2::new(x, y)
    }

    /// The tensions hold the support: with them the rods' pulls and the loads sum to no
    /// force and no moment about any point; a rod's lines through one point are refused.
    #[test]
    fn the_rods_tensions_hold_the_support_in_equilibrium() {
        let (a, b) = (p(0.0, 0.0), p(0.3, 0.1));
        let rods = [
            SupportRod {
                foot_m: a,
                top_m: p(0.2, 0.9),
            },
            SupportRod {
                foot_m: b,
                top_m: p(0.5, 0.8),
            },
            SupportRod {
                foot_m: b,
                top_m: p(1.4, 0.7),
            },
        ];
        let truss = SupportTruss::new(rods, a, b, 1.0).expect("a proper truss");
        let loads = [
            (p(-0.2, -0.3), Vector2::new(3e3, -40e3)),
            (p(0.4, -0.1), Vector2::new(-8e3, 25e3)),
        ];
        let t = truss.tensions(&loads);
        for about in [p(0.0, 0.0), p(7.0, -3.0)] {
            let mut all: Vec<(Point2<f64>, Vector2<f64>)> = loads.to_vec();
            all.extend((0..3).map(|i| (rods[i].foot_m, truss.pull(i, t[i]))));
            let sum = resultant(&all, about);
            assert!(sum.norm() < 1e-9 * 40e3, "{sum:?}");
        }
        // Three rods through one point hold no moment about it.
        let concurrent = [
            SupportRod {
                foot_m: a,
                top_m: p(0.0, 1.0),
            },
            SupportRod {
                foot_m: b,
                top_m: p(-0.3, -0.1),
            },
            SupportRod {
                foot_m: a,
                top_m: p(-0.5, 0.5),
            },
        ];
        assert!(SupportTruss::new(concurrent, a, b, 1.0).is_none());
    }
}
