//! The four-bar's struts and bracket against a hand computation from the whole mechanism's
//! balance: with a massless flap under a couple, what the links put on the wing at O1 is
//! what the rocker (along O2-A2) and the screw (along B0-C) do not, so each strut's moment
//! at its top is that force's moment about the top, and the bracket's halves carry the
//! rocker's pull and its opposite at A2 and A1.

use flapwright_kinds::four_bar::FourBar;
use flapwright_mechanism::seam::FlapMechanism;

use crate::synthesised::model_section::four_bar_spec;
use crate::synthesised::{landing_load, member_load};

#[test]
fn the_four_bars_struts_and_bracket_carry_what_the_mechanism_puts_on_them() {
    let mut spec = four_bar_spec();
    spec.flap_mass.mass_kg = 0.0;
    let four_bar = FourBar::synthesise(spec).unwrap();
    let s = four_bar.synthesis();
    let [top1, top2] = s.strut_tops_m;
    // The model section's struts go to the skin, not to the other pivot (the beam case).
    assert!(top1 != s.rocker_pivot_m && top2 != s.crank_pivot_m);
    let load = landing_load();
    let members: Vec<String> = four_bar.members().iter().map(|m| m.name.clone()).collect();
    for name in ["crank", "rocker", "bracket", "strut-O1", "strut-O2"] {
        assert!(members.iter().any(|m| m == name), "{name} in {members:?}");
    }
    let close = |got: f64, want: f64, what: &str| {
        assert!(
            (got - want).abs() <= 1e-9 * want.abs().max(1.0),
            "{what}: {got} against {want}"
        );
    };
    for input in four_bar.input_range().samples(9) {
        let pose = four_bar.pose(input).unwrap();
        let loads = four_bar.kinetostatics(input, &load).unwrap();
        let reaction = |name: &str| loads.reactions.iter().find(|(r, _)| r == name).unwrap().1;
        let point = |name: &str| pose.point(name).unwrap();
        let (o1, o2, a1, a2, b0, c) = (
            point("O1"),
            point("O2"),
            point("A1"),
            point("A2"),
            point("B0"),
            point("C"),
        );
        // The rocker pulls the flap with f e2 and the wing at O2 with -f e2; the screw pushes
        // the crank with F u at C and the wing at B0 with -F u. Balance of the whole: the
        // wing takes f e2 + F u at O1 (the couple on the flap moves nothing else).
        let e2 = (a2 - o2).normalize();
        let u = (c - b0).normalize();
        let (f, screw) = (reaction("O2"), loads.actuator_load);
        let at_o1 = e2 * f + u * screw;
        let at_o2 = -e2 * f;
        close(reaction("O1"), at_o1.norm(), "O1's reaction");
        close(
            member_load(&loads, "strut-O1").bending_moment_nm,
            (o1 - top1).perp(&at_o1).abs(),
            "strut-O1",
        );
        close(
            member_load(&loads, "strut-O2").bending_moment_nm,
            (o2 - top2).perp(&at_o2).abs(),
            "strut-O2",
        );
        // The bracket's halves: -f e2 at A1 and f e2 at A2, each about the middle.
        close(
            member_load(&loads, "bracket").bending_moment_nm,
            (0.5 * (a2 - a1)).perp(&(e2 * f)).abs(),
            "bracket",
        );
    }
}
