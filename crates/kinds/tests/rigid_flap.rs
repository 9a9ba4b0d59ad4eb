//! The rigid-flap equation of motion (`flapwright_mechanism::rigid_flap`) from a kind's
//! poses and statics, against independent routes.

use flapwright_kinds::dropped_hinge::DroppedHinge;
use flapwright_kinds::four_bar::FourBar;
use flapwright_mechanism::generalised::OneInputDynamics;
use flapwright_mechanism::seam::FlapMechanism;
use flapwright_mechanism::RigidFlapDynamics;
use nalgebra::{Matrix2, Point2};

use crate::synthesised::landing_load;
use crate::synthesised::model_section::{dropped_hinge_spec, four_bar_spec};

/// A dropped hinge turns the flap about one fixed point H, so the analytic special case
/// J = (I + m |D - H|²) θ'² holds, with θ' (per shaft radian) taken from the kind's
/// deflection by its own central difference at a different step; and the generalised
/// force is the statics' actuator load per shaft radian, negated.
#[test]
fn a_flap_turning_about_a_hinge_has_the_inertia_of_the_parallel_axis_theorem() {
    let hinge = DroppedHinge::synthesise(dropped_hinge_spec()).unwrap();
    let mass = hinge.flap_mass().unwrap();
    let inertia = 3.5;
    let load = landing_load();
    let model = RigidFlapDynamics::new(&hinge, mass, inertia, &load).unwrap();
    let range = hinge.input_range();
    let per_input = hinge.actuator().shaft_angle_per_input() * (range.deployed - range.stowed).signum();
    // H: the fixed point of the landing displacement.
    let landing = hinge.pose(range.deployed).unwrap().flap;
    let rotation = landing.rotation.to_rotation_matrix().into_inner();
    let h = Point2::from((Matrix2::identity() - rotation).try_inverse().unwrap() * landing.translation.vector);
    let arm_squared = (mass.centre_of_mass_stowed_m - h).norm_squared();
    let (_, travel) = model.input_travel();
    assert!((travel - (range.deployed - range.stowed) * per_input).abs() < 1e-12 * travel);
    for k in 0..=20 {
        // Ends included: the stencils turn one-sided there.
        let q = travel * k as f64 / 20.0;
        let input = range.stowed + q / per_input;
        let step = 1e-5 * (range.deployed - range.stowed).abs();
        let (lo, hi) = (
            (input - step).max(range.stowed.min(range.deployed)),
            (input + step).min(range.stowed.max(range.deployed)),
        );
        let turn_per_input =
            (hinge.deflection_at_input(hi).unwrap() - hinge.deflection_at_input(lo).unwrap()) / (hi - lo);
        let turn_per_shaft = turn_per_input / per_input;
        let expected = (inertia + mass.mass_kg * arm_squared) * turn_per_shaft * turn_per_shaft;
        let generalised = model.generalised_at(q).unwrap();
        let relative = (generalised.inertia - expected).abs() / expected;
        // The reference's one-sided end difference is first order: 1e-5 of the travel.
        let tolerance = if k == 0 || k == 20 { 1e-4 } else { 1e-7 };
        assert!(
            relative < tolerance,
            "q = {q}: J {} against {expected} ({relative:e})",
            generalised.inertia
        );
        let statics = hinge.kinetostatics(input, &load).unwrap();
        assert!((generalised.force + statics.actuator_load / per_input).abs() <= 1e-12 * statics.actuator_load.abs());
    }
}

/// J' and Q' are the slopes of J and Q: against central differences of the model's own J
/// and Q at 0.2 % and 0.1 % of the travel, Richardson-extrapolated (error ~ h⁴: 2e-8 of J'
/// here), on a
/// four-bar (a flap that turns and translates); and J'' against the same of J'.
#[test]
fn slopes_match_differences_of_the_values() {
    let four_bar = FourBar::synthesise(four_bar_spec()).unwrap();
    let mass = four_bar.flap_mass().unwrap();
    let model = RigidFlapDynamics::new(&four_bar, mass, 2.0, &landing_load()).unwrap();
    let (_, travel) = model.input_travel();
    let h = 0.002 * travel;
    let extrapolated = |q: f64, value: &dyn Fn(f64) -> f64| {
        let difference = |step: f64| (value(q + step) - value(q - step)) / (2.0 * step);
        (4.0 * difference(h / 2.0) - difference(h)) / 3.0
    };
    let at = |q: f64| model.generalised_at(q).unwrap();
    for k in 1..10 {
        let q = travel * k as f64 / 10.0;
        let here = at(q);
        // J'' feeds only the integrator's Jacobian, and differences J twice (rounding ε/h²):
        // 1e-4 of its scale is ample there.
        let close = |slope: f64, difference: f64, scale: f64, what: &str| {
            let tolerance = if what == "J''" { 1e-4 } else { 1e-6 };
            assert!(
                (slope - difference).abs() < tolerance * scale,
                "{what} at q = {q}: {slope} against {difference}"
            );
        };
        let inertia_scale = here.inertia / travel;
        close(
            here.inertia_slope,
            extrapolated(q, &|q| at(q).inertia),
            inertia_scale,
            "J'",
        );
        close(
            here.inertia_curvature,
            extrapolated(q, &|q| at(q).inertia_slope),
            inertia_scale / travel,
            "J''",
        );
        let force_scale = here.force.abs() / travel;
        close(here.force_slope, extrapolated(q, &|q| at(q).force), force_scale, "Q'");
    }
}
