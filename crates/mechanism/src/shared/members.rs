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

use crate::shared::geometry::cross;

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

/// Which of a kind's drawn radii a member's solid takes ([`crate::LinkHardware`]): the
/// sizing loop thickens that one where the member needs more.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum DrawnRadius {
    /// The links' and arms' radius (`link_radius_m`).
    Link,
    /// The struts' radius (`strut_radius_m`): a strut holding a fixed pivot to the wing,
    /// which no link shares.
    Strut,
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
    /// Euler's effective-length factor K for its buckling: 1 pinned at both ends (or held
    /// square to itself at both), 2 a cantilever whose tip is free to sway.
    pub end_fixity_factor: f64,
    /// The drawn radius its solid takes.
    pub drawn: DrawnRadius,
}

impl Member {
    /// A member whose ends are both held square to it (K = 1): pinned at both, or clamped
    /// at its root with a tip the mechanism holds (where K = 0.7 would do; 1 is on the safe
    /// side).
    pub fn new(name: &str, length_m: f64, radius_m: f64, loading: MemberLoading) -> Self {
        Self {
            name: name.into(),
            length_m,
            radius_m,
            loading,
            end_fixity_factor: 1.0,
            drawn: DrawnRadius::Link,
        }
    }

    /// A cantilever clamped at one end, its tip free to sway (K = 2): a strut from the skin
    /// holding a beam that nothing else steadies, or the beam itself. It bends.
    pub fn cantilever(name: &str, length_m: f64, radius_m: f64) -> Self {
        Self {
            end_fixity_factor: 2.0,
            ..Self::new(name, length_m, radius_m, MemberLoading::Bending)
        }
    }

    /// A strut from the skin holding a fixed pivot, drawn at the struts' radius: a
    /// [`Member::cantilever`] whose tip the pivot's links do not steady.
    pub fn strut(name: &str, length_m: f64, radius_m: f64) -> Self {
        Self {
            drawn: DrawnRadius::Strut,
            ..Self::cantilever(name, length_m, radius_m)
        }
    }
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

    /// The loads in a straight or polygonal cantilever clamped at `line[0]`, with a force
    /// `tip_force` (N) and a couple `tip_couple_nm` (N m, counter-clockwise positive) at
    /// `line.last()`: [`MemberLoad::of_cantilever_curve`] with each segment's direction as
    /// the tangent at its vertices.
    pub fn of_cantilever_line(line: &[Point2<f64>], tip_force: Vector2<f64>, tip_couple_nm: f64) -> Self {
        let curve: Vec<(Point2<f64>, Vector2<f64>)> = if line.len() < 2 {
            line.iter().map(|&p| (p, Vector2::zeros())).collect()
        } else {
            line.windows(2)
                .flat_map(|pair| {
                    let along = (pair[1] - pair[0]).try_normalize(0.0).unwrap_or_else(Vector2::zeros);
                    [(pair[0], along), (pair[1], along)]
                })
                .collect()
        };
        Self::of_cantilever_curve(&curve, tip_force, tip_couple_nm)
    }

    /// The loads in a cantilever clamped at the first of `curve`'s points whose centre
    /// line runs through them to the last, where a force `tip_force` (N) and a couple
    /// `tip_couple_nm` (N m, counter-clockwise positive) act; each point comes with the
    /// centre line's unit tangent there, pointing from the clamp towards the tip (a
    /// curved rail gives its exact tangents).
    ///
    /// For a section at x, the part beyond it holds the moment M(x) = C + (p - x) x F and
    /// the axial force F · t(x) (tension positive). Between points on a straight piece |M|
    /// is linear, so its largest value is at a point; on a curved piece sampled every δ of
    /// turn, the points miss at most a share 1 - cos(δ/2) of the largest (3.4e-4 at 3 deg).
    /// A non-finite input gives a non-finite load (never a silent 0). No points: the couple
    /// alone.
    pub fn of_cantilever_curve(
        curve: &[(Point2<f64>, Vector2<f64>)],
        tip_force: Vector2<f64>,
        tip_couple_nm: f64,
    ) -> Self {
        let Some(&(tip, _)) = curve.last() else {
            return Self {
                axial_n: 0.0,
                bending_moment_nm: tip_couple_nm.abs(),
            };
        };
        // Largest magnitude, NaN-propagating (f64::max would drop a NaN).
        let largest = |values: &mut dyn Iterator<Item = f64>| {
            values.fold(0.0, |best: f64, v| {
                if best.is_nan() || v.is_nan() {
                    f64::NAN
                } else if v.abs() > best.abs() {
                    v
                } else {
                    best
                }
            })
        };
        let bending_moment_nm = largest(
            &mut curve
                .iter()
                .map(|&(x, _)| (tip_couple_nm + cross(tip - x, tip_force)).abs()),
        );
        let axial_n = largest(&mut curve.iter().map(|&(_, t)| tip_force.dot(&t)));
        Self {
            axial_n,
            bending_moment_nm,
        }
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

    /// A straight cantilever through [`MemberLoad::of_cantilever_line`] gives what the
    /// method of sections gives for the same member, and a tip couple adds to the moment
    /// all along it.
    #[test]
    fn a_cantilever_line_agrees_with_the_method_of_sections() {
        let (root, tip) = (p(0.2, -0.1), p(1.0, 0.5));
        let f = Vector2::new(-700.0, 1200.0);
        let root_moment = -cross(tip - root, f);
        let sections = MemberLoad::of_straight_member(root, tip, &[(root, -f), (tip, f)], root_moment);
        let line = MemberLoad::of_cantilever_line(&[root, p(0.6, 0.2), tip], f, 0.0);
        assert!(
            (line.bending_moment_nm - sections.bending_moment_nm).abs() < 1e-9,
            "{line:?} {sections:?}"
        );
        assert!((line.axial_n - sections.axial_n).abs() < 1e-9, "{line:?} {sections:?}");
        // A couple of 100 N m at the tip against the force's moment at the root.
        let with_couple = MemberLoad::of_cantilever_line(&[root, tip], f, 100.0);
        let at_root = (100.0 + cross(tip - root, f)).abs();
        assert!((with_couple.bending_moment_nm - at_root.max(100.0)).abs() < 1e-9);
    }

    /// A half-circle cantilever of radius R clamped at one end of its diameter, loaded at
    /// the other along the diameter: the force's line passes through both ends, so the
    /// moment is 0 at the root and largest, F R, at the top of the arc, where the force also
    /// compresses the arc most (its whole magnitude along the tangent there).
    #[test]
    fn a_curved_cantilever_bends_most_where_it_stands_farthest_from_the_load_line() {
        let (r, load) = (0.5, 800.0);
        // Root (R, 0), over the top (0, R) to the tip (-R, 0); the tip's force along +x.
        let arc: Vec<Point2<f64>> = (0..=180)
            .map(|k| {
                let a = (k as f64).to_radians();
                p(r * a.cos(), r * a.sin())
            })
            .collect();
        let m = MemberLoad::of_cantilever_line(&arc, Vector2::new(load, 0.0), 0.0);
        assert!((m.bending_moment_nm - load * r).abs() < 1e-9, "{m:?}");
        assert!((m.axial_n + load).abs() < 1e-3 * load, "{m:?}");
        let at_root = (cross(arc[180] - arc[0], Vector2::new(load, 0.0))).abs();
        assert!(at_root < 1e-9);
    }

    /// A non-finite force gives a non-finite load, not a silent zero that would size a
    /// member to nothing.
    #[test]
    fn a_nan_push_is_not_lost() {
        let m = MemberLoad::of_cantilever_line(&[p(0.0, 0.0), p(1.0, 0.0)], Vector2::new(f64::NAN, 1.0), 0.0);
        assert!(m.bending_moment_nm.is_nan() && m.axial_n.is_nan(), "{m:?}");
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
