//! The four-bar's members that hold it to the wing and to the flap, and their loads at a
//! pose (the crank and the rocker are loaded in the kinetostatics beside the actuator).
//!
//! - With a support truss (the `support` module), the struts, the brace and the tie are
//!   rods pinned at both ends: their tensions hold the support
//!   ([`flapwright_mechanism::shared::support_truss`]), each an axial force alone.
//! - Without one, each strut is clamped where it meets the wing's lower skin and carries its pivot's
//!   load at its tip: a cantilever ([`MemberLoad::of_cantilever_line`]). Where a strut ends
//!   at the other pivot (a beam carrying both, `strut_tops_m`), it is clamped there, and
//!   the other pivot's strut carries its load as well: the force and its moment about that
//!   pivot. `003_...` (section 4) sizes a mechanism as a truss of rods between fixed pivots
//!   on the wing and leaves their supports out; here the struts are drawn, so they are
//!   sized, and a pivot hung deep below the wing costs what its strut weighs. They take
//!   their own drawn radius (`strut_radius_m`), which the sizing loop thickens without
//!   thickening the links.
//! - The flap's bracket between A1 and A2 is held by the flap's fitting, which spreads the
//!   pins' loads into the flap's structure; taken as clamped to the flap at its middle,
//!   each half a cantilever carrying its pin's force (the larger of the two governs). A
//!   fitting fixed along its length bends less, so this errs heavy.

use nalgebra::{Point2, Vector2};

use super::{FourBar, STRUTS, TIE, TRUSS_RODS};
use flapwright_mechanism::seam::MemberLoad;
use flapwright_mechanism::shared::geometry::cross;

/// Where two points count as one (m): a strut ending at the other pivot.
const SAME_POINT_M: f64 = 1e-9;

impl FourBar {
    /// The struts' loads, `at_o1` and `at_o2` the forces the crank and the rocker put on
    /// the support at their pivots (N).
    pub(super) fn support_loads(&self, at_o1: Vector2<f64>, at_o2: Vector2<f64>) -> Vec<(String, MemberLoad)> {
        let pivots = [self.loop_.o1, self.loop_.o2];
        if let Some(truss) = &self.synthesis.truss {
            let tensions = truss.tensions(&[(pivots[0], at_o1), (pivots[1], at_o2)]);
            let tie = truss.tie_tension(at_o2, &tensions);
            return TRUSS_RODS
                .iter()
                .zip(tensions)
                .chain([(&TIE, tie)])
                .map(|(name, tension)| (name.to_string(), MemberLoad::axial(tension)))
                .collect();
        }
        let at = [at_o1, at_o2];
        let tops = self.synthesis.strut_tops_m;
        (0..2)
            .map(|k| {
                let (pivot, other) = (pivots[k], pivots[1 - k]);
                // A strut ending at this pivot (a beam from the other) hands it its force
                // and that force's moment about this pivot.
                let (handed, couple) = if (tops[1 - k] - pivot).norm() <= SAME_POINT_M {
                    (at[1 - k], cross(other - pivot, at[1 - k]))
                } else {
                    (Vector2::zeros(), 0.0)
                };
                let load = MemberLoad::of_cantilever_line(&[tops[k], pivot], at[k] + handed, couple);
                (STRUTS[k].to_string(), load)
            })
            .collect()
    }
}

/// The bracket's load: the flap's pins at `a1` and `a2` pushed by the crank and the rocker
/// with `at_a1` and `at_a2` (N), each half clamped at the middle.
pub(super) fn bracket_load(
    a1: Point2<f64>,
    at_a1: Vector2<f64>,
    a2: Point2<f64>,
    at_a2: Vector2<f64>,
) -> (String, MemberLoad) {
    let middle = Point2::from((a1.coords + a2.coords) * 0.5);
    let halves = [
        MemberLoad::of_cantilever_line(&[middle, a1], at_a1, 0.0),
        MemberLoad::of_cantilever_line(&[middle, a2], at_a2, 0.0),
    ];
    let axial_n = if halves[0].axial_n.abs() >= halves[1].axial_n.abs() {
        halves[0].axial_n
    } else {
        halves[1].axial_n
    };
    let bending_moment_nm = halves[0].bending_moment_nm.max(halves[1].bending_moment_nm);
    (
        "bracket".into(),
        MemberLoad {
            axial_n,
            bending_moment_nm,
        },
    )
}
