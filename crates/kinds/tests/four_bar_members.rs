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

/// With load cases the support is a truss: the struts, the brace and the tie are rods
/// pinned at both ends, and their axial forces are what the method of joints gives, solved
/// here by hand from the drawn geometry: at O1 and at O2 the rods' pulls, the tie's and what
/// the links put on the pin (the whole mechanism's balance, as above) sum to nothing, four
/// equations in the four tensions (the body's balance the kind uses is another route).
#[test]
fn the_four_bars_support_truss_carries_its_pivots_loads_by_its_rods_alone() {
    use flapwright_mechanism::seam::MemberLoading;
    use nalgebra::{Matrix4, Vector2, Vector4};
    let mut spec = four_bar_spec();
    spec.flap_mass.mass_kg = 0.0;
    spec.design_loads = vec![landing_load()];
    let four_bar = FourBar::synthesise(spec).unwrap();
    let s = four_bar.synthesis();
    let truss = s.truss.expect("the model section's support clears as a truss");
    let members = four_bar.members();
    for name in ["strut-O1", "strut-O2", "brace", "tie"] {
        let member = members
            .iter()
            .find(|m| m.name == name)
            .unwrap_or_else(|| panic!("{name}"));
        assert_eq!(member.loading, MemberLoading::TwoForce, "{name}");
    }
    let (o1, o2) = (s.crank_pivot_m, s.rocker_pivot_m);
    assert_eq!(truss.tie_m, [o2, o1]);
    let load = landing_load();
    for input in four_bar.input_range().samples(7) {
        let pose = four_bar.pose(input).unwrap();
        let loads = four_bar.kinetostatics(input, &load).unwrap();
        let reaction = |name: &str| loads.reactions.iter().find(|(r, _)| r == name).unwrap().1;
        let point = |name: &str| pose.point(name).unwrap();
        let e2 = (point("A2") - o2).normalize();
        let u = (point("C") - point("B0")).normalize();
        let (f, screw) = (reaction("O2"), loads.actuator_load);
        let on_pin = [e2 * f + u * screw, -e2 * f];
        // Columns: strut-O1, strut-O2, brace, tie; rows: O1 x, y, O2 x, y. A rod's pull on
        // a pin at its foot is its tension along the unit vector towards its other end.
        let toward = |from: nalgebra::Point2<f64>, to: nalgebra::Point2<f64>| (to - from).normalize();
        let mut m = Matrix4::zeros();
        let mut put = |column: usize, pin: usize, pull: Vector2<f64>| {
            m[(2 * pin, column)] = pull.x;
            m[(2 * pin + 1, column)] = pull.y;
        };
        put(0, 0, toward(o1, s.strut_tops_m[0]));
        put(1, 1, toward(o2, s.strut_tops_m[1]));
        let brace = truss.rods[2];
        put(
            2,
            if brace.foot_m == o1 { 0 } else { 1 },
            toward(brace.foot_m, brace.top_m),
        );
        put(3, 0, toward(o1, o2));
        put(3, 1, toward(o2, o1));
        let rhs = -Vector4::new(on_pin[0].x, on_pin[0].y, on_pin[1].x, on_pin[1].y);
        let tensions = m.lu().solve(&rhs).expect("a proper truss");
        for (k, name) in ["strut-O1", "strut-O2", "brace", "tie"].iter().enumerate() {
            let member = member_load(&loads, name);
            assert_eq!(member.bending_moment_nm, 0.0, "{name}");
            let want = tensions[k];
            assert!(
                (member.axial_n - want).abs() <= 1e-7 * on_pin[0].norm().max(1.0),
                "{name}: {} N against {want} N",
                member.axial_n
            );
        }
    }
}
