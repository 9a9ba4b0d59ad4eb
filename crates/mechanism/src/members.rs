//! Members a kind declares for sizing, and their internal loads at a pose.
//!
//! `003_...` section 4.1 sizes the links as rods "loaded in axial direction only": a
//! two-force member (pinned at both ends, loaded only there) carries its load along the
//! line of its pins. Not every link is one: a crank that a screw jack turns from the middle
//! carries three forces, and an arm cantilevered from a hinge carries its tip load in
//! bending. A kind declares each member with how it carries load ([`MemberLoading`]), and
//! its kinetostatics give each member's [`MemberLoad`] at every pose; the sizing stage
//! sizes rods from the axial force and beams from axial force and bending moment together.
//!
//! [`MemberLoad::of_straight_member`] gets both from the forces on a straight member by
//! the method of sections: cut the member just beyond each point where a force acts, and
//! the part beyond the cut holds the axial force and the bending moment there. The bending
//! moment of a member loaded by point forces is piecewise linear between them, so its
//! largest magnitude is at one of those cuts.

use nalgebra::{Point2, Vector2};
use serde::Serialize;

use crate::rocker_drive::cross;

/// How a member carries its load.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum MemberLoading {
    /// Along the line of its two pins only: sized for strength and Euler buckling
    /// (`003_...` 4.1).
    TwoForce,
    /// Axial force and bending moment together: sized for the combined stress.
    Bending,
}

/// A member to size: a link, an arm, a strut.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Member {
    /// The member's solid name (and its key in [`crate::seam::Kinetostatics::members`]).
    pub name: String,
    /// Length between its end pins (m): its mass and its buckling length.
    pub length_m: f64,
    /// Radius of the solid that stands for it (m): what the interference check uses, and
    /// what the sized radius is compared with.
    pub radius_m: f64,
    /// How it carries its load.
    pub loading: MemberLoading,
}

/// A member's internal loads at one pose (N, N m).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MemberLoad {
    /// The axial force of largest magnitude along the member, tension positive (N).
    pub axial_n: f64,
    /// The largest bending moment magnitude along the member (N m); zero for a two-force
    /// member.
    pub bending_moment_nm: f64,
}

impl MemberLoad {
    /// A two-force member's load: its axial force (N, tension positive), no bending.
    pub fn axial(axial_n: f64) -> Self {
        Self {
            axial_n,
            bending_moment_nm: 0.0,
        }
    }

    /// The loads in a straight member along `from` -> `to` under `forces` (each a point of
    /// application and a force, N), which must hold the member in equilibrium by themselves
    /// and `root_moment_nm` (a couple at `from`, N m, counter-clockwise positive: a clamped
    /// root's moment; 0 for a member pinned at its ends).
    ///
    /// Method of sections: for a cut at arc length s along e = (to - from) / |to - from|,
    /// the part beyond it holds the axial force N(s) = Σ_{s_i > s} F_i · e (tension positive)
    /// and the moment M(s) = Σ_{s_i > s} (p_i - x(s)) x F_i. Cuts are made at every point of
    /// application; a point off the line contributes its force's moment about the cut.
    pub fn of_straight_member(
        from: Point2<f64>,
        to: Point2<f64>,
        forces: &[(Point2<f64>, Vector2<f64>)],
        root_moment_nm: f64,
    ) -> Self {
        let axis = to - from;
        let length = axis.norm();
        let e = if length > 0.0 { axis / length } else { Vector2::x() };
        let along = |p: Point2<f64>| (p - from).dot(&e);
        let mut load = Self::axial(0.0);
        for &(cut_point, _) in forces {
            let s = along(cut_point);
            let cut = from + e * s;
            let (mut axial, mut moment) = (0.0, 0.0);
            for &(p, f) in forces {
                if along(p) > s {
                    axial += f.dot(&e);
                    moment += cross(p - cut, f);
                }
            }
            // A root couple acts at s = 0: beyond every cut made before the root.
            if s < 0.0 {
                moment += root_moment_nm;
            }
            if axial.abs() > load.axial_n.abs() {
                load.axial_n = axial;
            }
            load.bending_moment_nm = load.bending_moment_nm.max(moment.abs());
        }
        load
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point2<f64> {
        Point2::new(x, y)
    }

    /// A simply supported beam of span L with a load P at a from one end: reactions
    /// P (L - a) / L and P a / L, largest moment P a (L - a) / L under the load.
    #[test]
    fn a_simply_supported_beam_bends_most_under_its_load() {
        let (l, a, load) = (2.0, 0.5, 1000.0);
        let forces = [
            (p(0.0, 0.0), Vector2::new(0.0, load * (l - a) / l)),
            (p(a, 0.0), Vector2::new(0.0, -load)),
            (p(l, 0.0), Vector2::new(0.0, load * a / l)),
        ];
        let m = MemberLoad::of_straight_member(p(0.0, 0.0), p(l, 0.0), &forces, 0.0);
        assert!((m.bending_moment_nm - load * a * (l - a) / l).abs() < 1e-9);
        assert_eq!(m.axial_n, 0.0);
    }

    /// A cantilever of length L clamped at its root with a tip force: moment |F x L| at
    /// the root whatever the direction, axial force the component along the arm.
    #[test]
    fn a_cantilever_carries_its_tip_load_to_the_root() {
        let (root, tip) = (p(1.0, 1.0), p(1.6, 1.8)); // L = 1 m
        let f = Vector2::new(300.0, -400.0);
        let root_moment = -cross(tip - root, f);
        let forces = [(root, -f), (tip, f)];
        let m = MemberLoad::of_straight_member(root, tip, &forces, root_moment);
        let e = (tip - root).normalize();
        assert!((m.bending_moment_nm - cross(tip - root, f).abs()).abs() < 1e-9);
        assert!((m.axial_n - f.dot(&e)).abs() < 1e-9);
    }

    /// A crank with a horn: the screw's force on the horn beyond the pivot, the pin load at
    /// the far end; the moment is largest at the pivot and zero at both ends.
    #[test]
    fn a_crank_on_a_horn_bends_most_at_its_pivot() {
        let (c, o, a) = (p(-0.1, 0.0), p(0.0, 0.0), p(0.3, 0.0));
        let pin = Vector2::new(50.0, 200.0);
        // Moments about O: horn force F_y with -0.1 F_y + 0.3 * 200 = 0.
        let screw = Vector2::new(0.0, 600.0);
        let pivot = -(pin + screw);
        let forces = [(c, screw), (o, pivot), (a, pin)];
        let m = MemberLoad::of_straight_member(c, a, &forces, 0.0);
        assert!((m.bending_moment_nm - 60.0).abs() < 1e-9, "{m:?}");
        // Between O and A the part beyond carries the pin's 50 N outward: tension.
        assert!((m.axial_n - 50.0).abs() < 1e-9, "{m:?}");
    }
}
