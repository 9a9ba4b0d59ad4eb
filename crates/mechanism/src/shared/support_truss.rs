//! A mechanism's fixed support held to the wing by a truss: `003_...` section 2 "A
//! truss-based support structure is automatically synthesized, connecting the mechanism to
//! the spar and wing box", its links "rigid rods, carrying normal loads only".
//!
//! The support is one rigid body: two feet A and B joined by a tie (the hooked-track's track
//! beam from its rail to its hook, the four-bar's ground link between its fixed pivots).
//! Three rods pinned at both ends hold it to the wing: one from A, one from B and a brace
//! from A or B to a top of its own. Three rods whose lines do not all meet in one point (nor
//! all run parallel) fix a plane body, and each carries an axial force alone, found from the
//! body's equilibrium: Σ t_i u_i = -Σ F_j and Σ (p_i - A) × t_i u_i = -Σ (q_j - A) × F_j
//! (u_i the rod's unit vector from its foot p_i to its top, t_i its tension; F_j the loads
//! on the support at q_j).
//!
//! Where the rods go ([`SupportTruss::lightest`]): of the triples (a top for each foot's
//! rod, the brace at either foot with a top at least 4 % of the flap chord from that foot's
//! rod's), the one with the least Σ L_i max|t_i| over the sampled loads, the rods' volume
//! when strength sizes them (Euler buckling grows it for long rods in compression; the
//! sizing stage finds it). Which tops a kind offers (clear of its parts and of the flap) is
//! the kind's.
//!
//! Used by the hooked-track (where the rail and the hook bend between the feet) and the
//! four-bar (where every load acts at the feet, so the tie is a rod too:
//! [`SupportTruss::tie_tension`]).

use nalgebra::{Matrix3, Point2, Vector2, Vector3};
use serde::Serialize;

use crate::shared::geometry::cross;

/// Least |det| of the rods' equilibrium matrix (unit force columns, moments over the
/// flap chord) a truss may have: below it the three rods' lines nearly meet in one point
/// and their forces grow without bound.
const MIN_DETERMINANT: f64 = 1e-3;

/// Least distance between the brace's top and the top of its foot's other rod, in flap
/// chords: two rods from one foot to one top are one rod.
const BRACE_SPREAD: f64 = 0.04;

/// A rod pinned to the support at `foot_m` and to the wing at `top_m` (station frame, m).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SupportRod {
    /// Where it holds the support: foot A or foot B.
    pub foot_m: Point2<f64>,
    /// Where it meets the wing: the lower skin or the rear spar's web.
    pub top_m: Point2<f64>,
}

impl SupportRod {
    /// Its length between its pins (m).
    pub fn length_m(&self) -> f64 {
        (self.top_m - self.foot_m).norm()
    }

    /// The unit vector from the foot to the top: the rod's pull on the support per newton
    /// of tension.
    pub fn pull(&self) -> Vector2<f64> {
        (self.top_m - self.foot_m) / self.length_m()
    }
}

/// The support's truss (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SupportTruss {
    /// The rod from A, the rod from B and the brace (from A or B).
    pub rods: [SupportRod; 3],
    /// The tie from B to A.
    pub tie_m: [Point2<f64>; 2],
    /// The equilibrium's inverse: tensions from the load's resultant about A.
    #[serde(skip)]
    inverse: Matrix3<f64>,
}

/// The resultant of `loads` (points and forces on the support) about `about`: force x, y
/// and moment.
pub fn resultant(loads: &[(Point2<f64>, Vector2<f64>)], about: Point2<f64>) -> Vector3<f64> {
    loads.iter().fold(Vector3::zeros(), |sum, &(at, force)| {
        sum + Vector3::new(force.x, force.y, cross(at - about, force))
    })
}

impl SupportTruss {
    /// The truss of `rods` with the tie from `b` to `a`, or None where the rods' lines
    /// nearly meet in one point (|det| of the unit-force equilibrium, moments over `length`,
    /// below 1e-3).
    pub fn new(rods: [SupportRod; 3], a: Point2<f64>, b: Point2<f64>, length: f64) -> Option<Self> {
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

    /// Foot A, about which the equilibrium's moments are taken.
    pub fn foot_a(&self) -> Point2<f64> {
        self.tie_m[1]
    }

    /// Foot B.
    pub fn foot_b(&self) -> Point2<f64> {
        self.tie_m[0]
    }

    /// The rods' tensions (N, tension positive) that hold the support under `loads`
    /// (points and forces on it).
    pub fn tensions(&self, loads: &[(Point2<f64>, Vector2<f64>)]) -> [f64; 3] {
        self.tensions_for(&resultant(loads, self.foot_a()))
    }

    /// The rods' tensions under a resultant about A (force x, y and moment).
    fn tensions_for(&self, resultant_about_a: &Vector3<f64>) -> [f64; 3] {
        let t = -(self.inverse * resultant_about_a);
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

    /// The tie's tension (N, tension positive) where every load on the support acts at its
    /// feet, `at_b` the loads at B and `tensions` the rods' ([`Self::tensions`]): pin B's
    /// balance along the tie, -(Σ F_B + Σ t_i u_i) · e with e the unit vector from B to A
    /// (the rods whose foot is B). Its balance across the tie holds by the whole body's.
    pub fn tie_tension(&self, at_b: Vector2<f64>, tensions: &[f64; 3]) -> f64 {
        let b = self.foot_b();
        let e = (self.foot_a() - b).normalize();
        let on_b = (0..3)
            .filter(|&i| self.rods[i].foot_m == b)
            .fold(at_b, |sum, i| sum + self.pull(i, tensions[i]));
        -on_b.dot(&e)
    }

    /// The truss with feet `a` and `b` whose rods go to tops of `tops_a` and `tops_b` (the
    /// brace to either's) with the least Σ L_i max|t_i| under `resultants` (the loads'
    /// resultants about `a`, one per sampled pose and load case); `flap_chord` scales the
    /// moments and the brace's spread. None where no triple holds the body.
    pub fn lightest(
        a: Point2<f64>,
        b: Point2<f64>,
        tops_a: &[Point2<f64>],
        tops_b: &[Point2<f64>],
        resultants: &[Vector3<f64>],
        flap_chord: f64,
    ) -> Option<Self> {
        let rod = |foot, top| SupportRod {
            foot_m: foot,
            top_m: top,
        };
        let apart = |p: Point2<f64>, q: Point2<f64>| (p - q).norm() > BRACE_SPREAD * flap_chord;
        let mut best: Option<(f64, SupportTruss)> = None;
        for &top_a in tops_a {
            for &top_b in tops_b {
                let braces = tops_a
                    .iter()
                    .filter(|&&t| apart(t, top_a))
                    .map(|&t| rod(a, t))
                    .chain(tops_b.iter().filter(|&&t| apart(t, top_b)).map(|&t| rod(b, t)));
                for brace in braces {
                    let Some(truss) = SupportTruss::new([rod(a, top_a), rod(b, top_b), brace], a, b, flap_chord) else {
                        continue;
                    };
                    let mut peak = [0.0_f64; 3];
                    for r in resultants {
                        for (p, t) in peak.iter_mut().zip(truss.tensions_for(r)) {
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
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point2<f64> {
        Point2::new(x, y)
    }

    fn rod(foot: Point2<f64>, top: Point2<f64>) -> SupportRod {
        SupportRod {
            foot_m: foot,
            top_m: top,
        }
    }

    /// The tensions hold the support: with them the rods' pulls and the loads sum to no
    /// force and no moment about any point; a rod's lines through one point are refused.
    #[test]
    fn the_rods_tensions_hold_the_support_in_equilibrium() {
        let (a, b) = (p(0.0, 0.0), p(0.3, 0.1));
        let rods = [rod(a, p(0.2, 0.9)), rod(b, p(0.5, 0.8)), rod(b, p(1.4, 0.7))];
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
        let concurrent = [rod(a, p(0.0, 1.0)), rod(b, p(-0.3, -0.1)), rod(a, p(-0.5, 0.5))];
        assert!(SupportTruss::new(concurrent, a, b, 1.0).is_none());
    }

    /// With every load at the feet, each pin balances: at A the loads, the rods from A and
    /// the tie's pull towards B; at B likewise towards A, in both directions of the plane.
    #[test]
    fn the_ties_tension_balances_both_pins() {
        let (a, b) = (p(0.0, 0.0), p(0.5, -0.1));
        let rods = [rod(a, p(0.1, 0.8)), rod(b, p(0.6, 0.7)), rod(a, p(1.2, 0.6))];
        let truss = SupportTruss::new(rods, a, b, 1.0).expect("a proper truss");
        let (at_a, at_b) = (Vector2::new(12e3, -70e3), Vector2::new(-5e3, 30e3));
        let t = truss.tensions(&[(a, at_a), (b, at_b)]);
        let tie = truss.tie_tension(at_b, &t);
        let e = (a - b).normalize();
        let pin = |foot: Point2<f64>, load: Vector2<f64>, towards: Vector2<f64>| {
            (0..3)
                .filter(|&i| rods[i].foot_m == foot)
                .fold(load + towards * tie, |sum, i| sum + truss.pull(i, t[i]))
        };
        assert!(pin(b, at_b, e).norm() < 1e-9 * 70e3, "{:?}", pin(b, at_b, e));
        assert!(pin(a, at_a, -e).norm() < 1e-9 * 70e3, "{:?}", pin(a, at_a, -e));
    }
}
