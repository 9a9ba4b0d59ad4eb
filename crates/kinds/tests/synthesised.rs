//! The kinds synthesised from flap settings (dropped hinge, four-bar) on a model section:
//! a box wing with a cove and an elliptic flap nested in it (`model_section.rs`).

use flapwright_kinds::dropped_hinge::DroppedHinge;
use flapwright_kinds::four_bar::FourBar;
use flapwright_kinds::hooked_track::HookedTrack;
use flapwright_kinds::link_track::LinkTrack;
use flapwright_mechanism::seam::{FlapMechanism, MemberLoad, MemberLoading};
use flapwright_mechanism::{Error, ExternalMoment, FlapNormalForce, LoadCase, PrecisionPosition, SynthesisDefect};
use nalgebra::{Isometry2, Point2, Vector2};

#[path = "model_section.rs"]
pub(crate) mod model_section;

use model_section::{dropped_hinge_spec, four_bar_spec, hooked_track_spec, link_track_spec, rotary_dropped_hinge_spec};

pub(crate) fn landing_load() -> LoadCase {
    LoadCase {
        name: "landing".into(),
        external_moment: ExternalMoment::Linear {
            stowed_nm: 500.0,
            deployed_nm: 2000.0,
        },
        include_inertia: false,
        flap_normal_force: None,
        load_factor: 1.0,
    }
}

/// The synthesised kinds on the model section: both dropped hinges, the four-bar, the
/// link-track and the hooked-track.
pub(crate) fn synthesised_mechanisms() -> Vec<Box<dyn FlapMechanism>> {
    vec![
        Box::new(DroppedHinge::synthesise(dropped_hinge_spec()).unwrap()),
        Box::new(DroppedHinge::synthesise(rotary_dropped_hinge_spec()).unwrap()),
        Box::new(FourBar::synthesise(four_bar_spec()).unwrap()),
        Box::new(LinkTrack::synthesise(link_track_spec()).unwrap()),
        Box::new(HookedTrack::synthesise(hooked_track_spec()).unwrap()),
    ]
}

/// A flight condition's normal force at the quarter chord, C_N rising with deflection,
/// normal to a chord with 5 deg of incidence, at a load factor of 2.5.
pub(crate) fn flight_load() -> LoadCase {
    LoadCase {
        flap_normal_force: Some(FlapNormalForce {
            coefficients: vec![(0.0, 0.3), (20f64.to_radians(), 0.9), (35f64.to_radians(), 1.3)],
            newtons_per_coefficient: 8000.0,
            at_stowed_m: Point2::new(-0.12, 0.1),
            normal_stowed: Vector2::new(5f64.to_radians().sin(), 5f64.to_radians().cos()),
        }),
        load_factor: 2.5,
        ..landing_load()
    }
}

/// A member's loads at a pose, by name.
pub(crate) fn member_load(loads: &flapwright_mechanism::seam::Kinetostatics, name: &str) -> MemberLoad {
    loads
        .members
        .iter()
        .find(|(n, _)| n == name)
        .unwrap_or_else(|| panic!("no member {name}"))
        .1
}

/// Where the mechanism puts the flap attachments at a setting's deflection, against the
/// setting's displacement: the largest distance (m).
pub(crate) fn miss(mechanism: &dyn FlapMechanism, position: &PrecisionPosition) -> f64 {
    let pose = mechanism
        .pose(mechanism.input_at_deflection(position.deflection_rad).unwrap())
        .unwrap();
    mechanism
        .flap_attachments()
        .iter()
        .map(|p| (pose.flap * p.position - position.flap * p.position).norm())
        .fold(0.0, f64::max)
}

#[test]
fn dropped_hinge_meets_stowed_and_landing_and_reports_the_takeoff_miss() {
    let spec = dropped_hinge_spec();
    let (takeoff, landing) = (spec.takeoff.unwrap(), spec.landing);
    let hinge = DroppedHinge::synthesise(spec).unwrap();
    assert!(miss(&hinge, &PrecisionPosition::stowed()) < 1e-9);
    assert!(miss(&hinge, &landing) < 1e-9, "{}", miss(&hinge, &landing));
    let reported = hinge.synthesis().takeoff_miss_m.unwrap();
    assert!((miss(&hinge, &takeoff) - reported).abs() < 1e-9);
    // Two precision positions cannot meet a third in general.
    assert!(reported > 1e-4, "take-off miss {reported}");
    let range = hinge.input_range();
    assert!(range.deployed > range.stowed, "the screw pushes");
    assert!((hinge.deflection_at_input(range.deployed).unwrap() - landing.deflection_rad).abs() < 1e-9);
}

#[test]
fn four_bar_meets_its_three_precision_positions() {
    let spec = four_bar_spec();
    let (takeoff, landing) = (spec.takeoff, spec.landing);
    let four_bar = FourBar::synthesise(spec).unwrap();
    for position in [PrecisionPosition::stowed(), takeoff, landing] {
        let m = miss(&four_bar, &position);
        assert!(m < 1e-9, "{}: {m}", position.name);
    }
    let s = four_bar.synthesis();
    assert!(s.precision_miss_m < 1e-9);
    assert!(s.min_transmission_angle_rad >= 30f64.to_radians());
    assert!(s.certified_min_transmission_angle_rad <= s.min_transmission_angle_rad);
    assert!(s.search.feasible > 0 && s.search.candidates > s.search.feasible);
    let range = four_bar.input_range();
    assert!((four_bar.deflection_at_input(range.deployed).unwrap() - landing.deflection_rad).abs() < 1e-9);
}

/// Actuator force by statics equals the virtual-work value at every sample, for both kinds
/// (two independent routes: moments of the bodies, and the velocity analysis).
#[test]
fn statics_and_virtual_work_agree() {
    let kinds = synthesised_mechanisms();
    let flight = flight_load();
    for mechanism in &kinds {
        for (input, load) in mechanism
            .input_range()
            .samples(25)
            .into_iter()
            .flat_map(|q| [(q, landing_load()), (q, flight.clone())])
        {
            let loads = mechanism.kinetostatics(input, &load).unwrap();
            let relative = (loads.actuator_load - loads.actuator_load_virtual_work).abs() / loads.actuator_load.abs();
            assert!(relative < 1e-9, "{}: {relative}", mechanism.kind());
            assert!(loads.health.closure_residual_m < 1e-12);
        }
    }
}

/// The rates the virtual work uses against finite differences of the pose: the flap's
/// rotation per metre of stroke, and the transmission angle along the deployment.
#[test]
fn rates_and_transmission_angle_match_finite_differences() {
    let four_bar = FourBar::synthesise(four_bar_spec()).unwrap();
    let range = four_bar.input_range();
    let h = 1e-6;
    for input in range.samples(9).into_iter().skip(1).take(7) {
        let deflection = |q: f64| four_bar.deflection_at_input(q).unwrap();
        let numeric = (deflection(input + h) - deflection(input - h)) / (2.0 * h);
        // The virtual work with a pure couple isolates dθ/ds: F = -C dθ/ds.
        let couple = LoadCase {
            name: "couple".into(),
            external_moment: ExternalMoment::Constant(-1.0),
            include_inertia: false,
            flap_normal_force: None,
            load_factor: 1.0,
        };
        let mut massless = four_bar_spec();
        massless.flap_mass.mass_kg = 0.0;
        let four_bar_massless = FourBar::synthesise(massless).unwrap();
        let loads = four_bar_massless.kinetostatics(input, &couple).unwrap();
        assert!(
            (-loads.actuator_load_virtual_work - numeric).abs() < 1e-6 * numeric.abs(),
            "dθ/ds {numeric} vs {}",
            -loads.actuator_load_virtual_work
        );
        // The transmission angle from the pose's points.
        let pose = four_bar.pose(input).unwrap();
        let (a1, a2, o2) = (
            pose.point("A1").unwrap(),
            pose.point("A2").unwrap(),
            pose.point("O2").unwrap(),
        );
        let (c, r) = (a2 - a1, a2 - o2);
        let mu = (c.perp(&r).abs() / (c.norm() * r.norm())).asin();
        let reported = four_bar
            .kinetostatics(input, &landing_load())
            .unwrap()
            .transmission_angle_rad;
        assert!(reported <= mu + 1e-12);
    }
}

#[test]
fn given_pivots_that_cannot_work_are_typed_failures() {
    let mut spec = four_bar_spec();
    // A moving pivot high inside the wing at take-off.
    spec.forward_pivot = Some(Point2::new(0.05, 0.16));
    let error = FourBar::synthesise(spec).unwrap_err();
    assert!(matches!(error, Error::Synthesis { .. }), "{error}");
    let mut spec = dropped_hinge_spec();
    spec.landing.flap = Isometry2::translation(-0.2, -0.05);
    spec.landing.deflection_rad = 0.0;
    assert!(matches!(
        DroppedHinge::synthesise(spec),
        Err(Error::Synthesis {
            defect: SynthesisDefect::NoRealSolution,
            ..
        })
    ));
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 48, ..Default::default() })]

    /// Random three-position sets: an exact four-bar (through every position to 1e-9 m,
    /// finite poses and loads over the deployment) or a typed failure, never NaN.
    #[test]
    fn random_positions_give_an_exact_four_bar_or_a_typed_failure(
        takeoff_deg in 3.0..25.0f64,
        extra_deg in 3.0..30.0f64,
        takeoff_shift in (-0.15..0.05f64, -0.12..0.05f64),
        landing_shift in (-0.3..0.05f64, -0.3..0.05f64),
    ) {
        let mut spec = four_bar_spec();
        spec.takeoff = PrecisionPosition {
            name: "takeoff",
            deflection_rad: takeoff_deg.to_radians(),
            flap: Isometry2::new(nalgebra::Vector2::new(takeoff_shift.0, takeoff_shift.1), takeoff_deg.to_radians()),
        };
        let landing_rad = (takeoff_deg + extra_deg).to_radians();
        spec.landing = PrecisionPosition {
            name: "landing",
            deflection_rad: landing_rad,
            flap: Isometry2::new(nalgebra::Vector2::new(landing_shift.0, landing_shift.1), landing_rad),
        };
        let positions = [PrecisionPosition::stowed(), spec.takeoff, spec.landing];
        match FourBar::synthesise(spec) {
            Ok(four_bar) => {
                for position in &positions {
                    let m = miss(&four_bar, position);
                    proptest::prop_assert!(m < 1e-9, "{}: {}", position.name, m);
                }
                for input in four_bar.input_range().samples(16) {
                    let loads = four_bar.kinetostatics(input, &landing_load()).unwrap();
                    proptest::prop_assert!(loads.actuator_load.is_finite() && loads.transmission_angle_rad.is_finite());
                    for (name, member) in &loads.members {
                        proptest::prop_assert!(
                            member.axial_n.is_finite() && member.bending_moment_nm.is_finite(),
                            "{}: {:?}", name, member
                        );
                    }
                    let relative = (loads.actuator_load - loads.actuator_load_virtual_work).abs()
                        / loads.actuator_load.abs().max(1.0);
                    proptest::prop_assert!(relative < 1e-8, "{}", relative);
                }
            }
            Err(error) => proptest::prop_assert!(matches!(error, Error::Synthesis { .. }), "{}", error),
        }
    }
}

/// The dropped hinge's truss forces, checked by the whole mechanism's equilibrium (an
/// independent balance: the ground holds it only at the truss ends S1, S2 and the screw
/// mount B0): the weight, the couple, and the ground forces t_i u_i at S_i and F u at B0
/// sum to zero in force and in moment.
#[test]
fn dropped_hinge_truss_forces_balance_the_whole_mechanism() {
    let hinge = DroppedHinge::synthesise(dropped_hinge_spec()).unwrap();
    let load = landing_load();
    let mass = dropped_hinge_spec().flap_mass;
    let range = hinge.input_range();
    for input in range.samples(9) {
        let pose = hinge.pose(input).unwrap();
        let loads = hinge.kinetostatics(input, &load).unwrap();
        let reaction = |name: &str| loads.reactions.iter().find(|(n, _)| n == name).unwrap().1;
        let axial = |name: &str| member_load(&loads, name).axial_n;
        let point = |name: &str| pose.point(name).unwrap();
        let (h, s1, s2, b0, p, d) = (
            point("H"),
            point("S1"),
            point("S2"),
            point("B0"),
            point("P"),
            point("D"),
        );
        let weight = mass.gravity_mps2 * mass.mass_kg;
        let couple = -load.external_moment.at(range.fraction(input));
        let u = (p - b0).normalize();
        let forces = [
            (d, weight),
            (s1, (s1 - h).normalize() * axial("truss-forward")),
            (s2, (s2 - h).normalize() * axial("truss-aft")),
            (b0, u * reaction("B0")),
        ];
        let net: nalgebra::Vector2<f64> = forces.iter().map(|(_, f)| f).sum();
        let moment: f64 = forces.iter().map(|(at, f)| at.coords.perp(f)).sum::<f64>() + couple;
        let scale = reaction("B0").abs().max(1.0);
        assert!(net.norm() < 1e-9 * scale, "net force {net}");
        assert!(moment.abs() < 1e-9 * scale, "net moment {moment}");
    }
}

/// With a geared rotary actuator on the hinge the dropped hinge is the same hinge (the
/// pole), its input the turn itself: stowed and landing met, no screw or nut; its torque
/// and the truss forces hold the flap in force and in moment (the torque a couple on the
/// flap, the truss forces at their wing ends), and the drive shaft turns `turns` times.
#[test]
fn rotary_dropped_hinge_turns_about_the_same_hinge_and_balances() {
    let screw = DroppedHinge::synthesise(dropped_hinge_spec()).unwrap();
    let rotary = DroppedHinge::synthesise(rotary_dropped_hinge_spec()).unwrap();
    assert_eq!(screw.synthesis().hinge_m, rotary.synthesis().hinge_m);
    let landing = rotary_dropped_hinge_spec().landing;
    assert!(miss(&rotary, &PrecisionPosition::stowed()) < 1e-9);
    assert!(miss(&rotary, &landing) < 1e-9);
    let range = rotary.input_range();
    assert_eq!(range.quantity, flapwright_mechanism::seam::InputQuantity::Angle);
    assert!((range.deployed - landing.deflection_rad).abs() < 1e-15);
    let actuator = rotary.actuator();
    let shaft_turns = range.travel() * actuator.shaft_angle_per_input() / std::f64::consts::TAU;
    assert!((shaft_turns - 30.0).abs() < 1e-9, "{shaft_turns}");
    assert_eq!(rotary.bodies().len(), 2, "flap and support only");
    let load = landing_load();
    let mass = rotary_dropped_hinge_spec().flap_mass;
    for input in range.samples(9) {
        let pose = rotary.pose(input).unwrap();
        assert!(pose.point("B0").is_none() && pose.point("P").is_none());
        let loads = rotary.kinetostatics(input, &load).unwrap();
        assert!(loads.actuator_torques.is_none());
        let axial = |name: &str| member_load(&loads, name).axial_n;
        let point = |name: &str| pose.point(name).unwrap();
        let (h, s1, s2, d) = (point("H"), point("S1"), point("S2"), point("D"));
        let weight = mass.gravity_mps2 * mass.mass_kg;
        let couple = -load.external_moment.at(range.fraction(input)) + loads.actuator_load;
        let forces = [
            (d, weight),
            (s1, (s1 - h).normalize() * axial("truss-forward")),
            (s2, (s2 - h).normalize() * axial("truss-aft")),
        ];
        let net: nalgebra::Vector2<f64> = forces.iter().map(|(_, f)| f).sum();
        let moment: f64 = forces.iter().map(|(at, f)| at.coords.perp(f)).sum::<f64>() + couple;
        let scale = loads.actuator_load.abs().max(1.0);
        assert!(net.norm() < 1e-9 * scale, "net force {net}");
        assert!(moment.abs() < 1e-9 * scale, "net moment {moment}");
    }
}

/// A four-bar driven towards a toggle is reported with the input where it happens: the
/// search's own pivots, given back with a minimum transmission angle above the loop's
/// smallest, fail as a toggle at a named crank angle inside the deployment.
#[test]
fn a_four_bar_driven_into_a_toggle_is_reported_with_its_input() {
    let found = FourBar::synthesise(four_bar_spec()).unwrap();
    let [a1, a2] = found.synthesis().moving_pivots_m;
    let smallest = found.synthesis().min_transmission_angle_rad;
    let mut spec = four_bar_spec();
    spec.forward_pivot = Some(a1);
    spec.aft_pivot = Some(a2);
    spec.min_transmission_angle_rad = smallest + 1f64.to_radians();
    match FourBar::synthesise(spec) {
        Err(Error::Synthesis {
            defect: SynthesisDefect::Toggle,
            detail,
            ..
        }) => assert!(detail.contains("deg of crank"), "{detail}"),
        other => panic!("expected a toggle, got {other:?}"),
    }
}

/// The seam's promises for both kinds: certified speed bounds (never below the fastest
/// finite-difference speed of any solid's point, and within a factor of four of it), and
/// joints that name existing bodies and solids.
#[test]
fn synthesised_kinds_keep_the_seams_promises() {
    let kinds = synthesised_mechanisms();
    for mechanism in &kinds {
        crate::seam::speed_bounds_hold(mechanism.as_ref(), 0.25);
        crate::seam::joints_name_existing(mechanism.as_ref());
    }
}

/// The four-bar's crank bends as a beam pinned at O1 and A1 under the screw's push at C on
/// the line between them: only the push's component square to the crank bends it, so the
/// largest moment is F_n a (L - a) / L at C (a = |C - O1|, L = |A1 - O1|), or F_n |C - O1|
/// at O1 when C sits on a horn beyond O1. This uses the screw force and the geometry only;
/// the kind's own figure comes from the pin force at A1 and the method of sections.
#[test]
fn the_four_bar_crank_bends_under_the_screws_push() {
    let four_bar = FourBar::synthesise(four_bar_spec()).unwrap();
    let declared = four_bar.members();
    let crank = declared.iter().find(|m| m.name == "crank").unwrap();
    assert_eq!(crank.loading, MemberLoading::Bending);
    assert_eq!(
        declared.iter().find(|m| m.name == "rocker").unwrap().loading,
        MemberLoading::TwoForce
    );
    let load = landing_load();
    let mut largest = 0.0_f64;
    for input in four_bar.input_range().samples(9) {
        let pose = four_bar.pose(input).unwrap();
        let loads = four_bar.kinetostatics(input, &load).unwrap();
        let point = |name: &str| pose.point(name).unwrap();
        let (o1, a1, c, b0) = (point("O1"), point("A1"), point("C"), point("B0"));
        let along = (a1 - o1).normalize();
        assert!((c - o1).perp(&along).abs() < 1e-12, "C lies on the crank's line");
        let push = (c - b0).normalize() * loads.actuator_load;
        let square = push.perp(&along).abs();
        let (a, l) = ((c - o1).dot(&along), (a1 - o1).norm());
        let expected = if a < 0.0 { square * -a } else { square * a * (l - a) / l };
        let moment = member_load(&loads, "crank").bending_moment_nm;
        assert!(
            (moment - expected).abs() < 1e-9 * expected.max(1.0),
            "{moment} against {expected}"
        );
        largest = largest.max(moment);
    }
    assert!(largest > 1.0, "the crank is loaded: {largest} N m");
}

/// The rotary actuator's torque reaches the flap through the two arms cantilevered from
/// the hub: their root moments add up to it (the arms' largest moments are at their roots,
/// each carrying one tip force), whatever the split between the attachments.
#[test]
fn the_rotary_actuators_torque_is_the_sum_of_the_arms_root_moments() {
    let rotary = DroppedHinge::synthesise(rotary_dropped_hinge_spec()).unwrap();
    let names: Vec<_> = rotary.members().iter().map(|m| (m.name.clone(), m.loading)).collect();
    assert!(
        names.contains(&("arm-forward".into(), MemberLoading::Bending)),
        "{names:?}"
    );
    assert!(
        names.contains(&("truss-aft".into(), MemberLoading::TwoForce)),
        "{names:?}"
    );
    let load = landing_load();
    for input in rotary.input_range().samples(9) {
        let loads = rotary.kinetostatics(input, &load).unwrap();
        let (forward, aft) = (
            member_load(&loads, "arm-forward").bending_moment_nm,
            member_load(&loads, "arm-aft").bending_moment_nm,
        );
        let torque = loads.actuator_load.abs();
        let nearest = [forward + aft, (forward - aft).abs()]
            .iter()
            .map(|m| (m - torque).abs())
            .fold(f64::INFINITY, f64::min);
        assert!(nearest < 1e-9 * torque.max(1.0), "{forward} and {aft} against {torque}");
    }
}

/// The link-track meets its three precision positions at the link's pivot and the
/// carriage; its carriage runs on a straight line; statics and virtual work agree; the
/// transmission angle stays above the minimum.
#[test]
fn link_track_meets_its_three_precision_positions() {
    let link_track = LinkTrack::synthesise(link_track_spec()).unwrap();
    let spec = link_track_spec();
    for position in [PrecisionPosition::stowed(), spec.takeoff, spec.landing] {
        let m = miss(&link_track, &position);
        assert!(m < 1e-9, "{}: {m}", position.name);
    }
    let synthesis = link_track.synthesis();
    assert!(synthesis.precision_miss_m < 1e-9);
    assert!(synthesis.search.feasible > 0, "{:?}", synthesis.search);
    let d = synthesis.track_direction;
    let c0 = synthesis.carriage_m;
    let load = landing_load();
    for input in link_track.input_range().samples(17) {
        let pose = link_track.pose(input).unwrap();
        let c = pose.point("C").unwrap();
        assert!((c - c0).perp(&d).abs() < 1e-9, "the carriage leaves its track");
        let loads = link_track.kinetostatics(input, &load).unwrap();
        let relative =
            (loads.actuator_load - loads.actuator_load_virtual_work).abs() / loads.actuator_load.abs().max(1.0);
        assert!(relative < 1e-8, "{relative}");
        assert!(loads.transmission_angle_rad >= 30f64.to_radians() - 1e-9);
        let link = member_load(&loads, "link");
        assert!(link.bending_moment_nm.is_finite() && link.bending_moment_nm > 0.0);
    }
    assert!(synthesis.certified_min_transmission_angle_rad > 0.0);
    assert!(synthesis.certified_min_transmission_angle_rad <= synthesis.min_transmission_angle_rad);
}

/// The link-track's free choices given back reproduce the searched mechanism; a fixed pivot
/// inside the wing is refused with its defect, and one the flap's settings cannot use is a
/// typed failure, never a panic.
#[test]
fn link_track_choices_given_back_or_refused() {
    let found = LinkTrack::synthesise(link_track_spec()).unwrap();
    let s = found.synthesis();
    let mut spec = link_track_spec();
    spec.link_pivot = Some(s.link_pivot_m);
    spec.track_slope_rad = Some(s.track_slope_rad);
    let again = LinkTrack::synthesise(spec).unwrap();
    assert!((again.synthesis().carriage_m - s.carriage_m).norm() < 1e-9);
    assert!((again.synthesis().link_flap_pivot_m - s.link_flap_pivot_m).norm() < 1e-9);
    let mut inside = link_track_spec();
    inside.link_pivot = Some(Point2::new(1.0, 0.1));
    match LinkTrack::synthesise(inside) {
        Err(Error::Synthesis { defect, .. }) => assert_eq!(defect, SynthesisDefect::PivotOutsideRegion),
        other => panic!("{other:?}"),
    }
    for slope_deg in [-10.0, 0.0, 20.0, 45.0, 80.0] {
        let mut spec = link_track_spec();
        spec.track_slope_rad = Some(f64::to_radians(slope_deg));
        match LinkTrack::synthesise(spec) {
            Ok(link_track) => assert!(link_track.synthesis().precision_miss_m < 1e-9),
            Err(error) => assert!(matches!(error, Error::Synthesis { .. }), "{error}"),
        }
    }
}

/// The link-track's certified smallest transmission angle holds between the synthesis's
/// 48 samples: 4001 evenly spaced poses never fall below it, and its sampled figure is
/// what those poses find to within the sampling.
#[test]
fn link_track_certified_transmission_holds_between_samples() {
    let link_track = LinkTrack::synthesise(link_track_spec()).unwrap();
    let s = link_track.synthesis();
    let load = landing_load();
    let dense = link_track
        .input_range()
        .samples(4001)
        .into_iter()
        .map(|input| link_track.kinetostatics(input, &load).unwrap().transmission_angle_rad)
        .fold(f64::INFINITY, f64::min);
    assert!(
        dense >= s.certified_min_transmission_angle_rad,
        "{dense} < {}",
        s.certified_min_transmission_angle_rad
    );
    assert!(dense <= s.min_transmission_angle_rad + 1e-12);
    assert!(
        s.min_transmission_angle_rad - dense < 0.01,
        "{dense} against {}",
        s.min_transmission_angle_rad
    );
}
