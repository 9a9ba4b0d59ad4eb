//! Landing-gear method (doc 004) against an analytic special case and the thesis kinematics.

use approx::assert_relative_eq;
use flapwright_mechanism::landing_gear::LandingGearSpec;
use flapwright_mechanism::InvertedSliderCrank;

use crate::common::thesis_track;

fn thesis_equivalent() -> LandingGearSpec {
    let track = thesis_track();
    let spec = track.spec();
    LandingGearSpec {
        pivot_distance_m: spec.base_distance_m,
        crank_length_m: spec.crank_length_m,
        rotation_rad: spec.rotation_range_rad,
        stroke_time_s: 144.3387837620511e-3 / 0.035,
    }
}

#[test]
fn equal_pressure_angles_reproduce_the_thesis_collinearity_rule() {
    let track = thesis_track();
    let synthesis = track.synthesis();
    let gear = thesis_equivalent().synthesise_equal_pressure_angles().unwrap();
    assert_relative_eq!(
        gear.start_crank_angle_rad,
        synthesis.stowed_crank_angle_rad,
        max_relative = 1e-12
    );
    assert_relative_eq!(gear.start_input_m, synthesis.stroke_start_m, max_relative = 1e-12);
    assert_relative_eq!(gear.stroke_m, synthesis.stroke_m, max_relative = 1e-12);
    assert_relative_eq!(
        gear.start_pressure_angle_rad,
        gear.end_pressure_angle_rad,
        max_relative = 1e-12
    );
    // Both ends at pressure angle β3/2, i.e. transmission angle (π - β3)/2.
    assert_relative_eq!(
        gear.start_pressure_angle_rad,
        0.5 * track.spec().rotation_range_rad,
        max_relative = 1e-12
    );
    // Rod speed H / t = the thesis's 35 mm/s for the matching stroke time.
    assert_relative_eq!(gear.rod_speed_mps, 0.035, max_relative = 1e-12);
}

#[test]
fn closed_form_is_exact_when_the_cylinder_pivot_is_far_away() {
    // a1 → ∞: the rod direction no longer turns, so the pressure angle equals the crank's
    // rotation away from the tangent position: θ/2 at both ends.
    let theta = 0.6;
    let spec = LandingGearSpec {
        pivot_distance_m: 1e6,
        crank_length_m: 1.0,
        rotation_rad: theta,
        stroke_time_s: 1.0,
    };
    let gear = spec.synthesise().unwrap();
    assert_relative_eq!(gear.start_pressure_angle_rad, 0.5 * theta, max_relative = 1e-5);
    assert_relative_eq!(gear.end_pressure_angle_rad, 0.5 * theta, max_relative = 1e-5);
    // Stroke = chord projected on the rod: 2 l3 sin(θ/2).
    assert_relative_eq!(gear.stroke_m, 2.0 * (0.5 * theta).sin(), max_relative = 1e-5);
    // Tangent position: zero pressure angle, rod² = a1² - a2² (eq. 4).
    let mu = gear.tangent_crank_angle_rad;
    assert_relative_eq!(mu.cos(), 1e-6, max_relative = 1e-12);
}

#[test]
fn closed_form_end_lengths_match_the_linkage() {
    // Eqs. 7 and 8 against the thesis slider-crank angles for the same dimensions.
    let spec = thesis_equivalent();
    let gear = spec.synthesise().unwrap();
    let linkage = InvertedSliderCrank::try_new(spec.pivot_distance_m, spec.crank_length_m, 0.0).unwrap();
    let (start_crank, _) = linkage.angles(gear.start_input_m).unwrap();
    let (end_crank, _) = linkage.angles(gear.end_input_m).unwrap();
    assert_relative_eq!(start_crank, gear.start_crank_angle_rad, max_relative = 1e-12);
    assert_relative_eq!(end_crank, gear.end_crank_angle_rad, max_relative = 1e-12);
    assert_relative_eq!(end_crank - start_crank, spec.rotation_rad, max_relative = 1e-12);
    // For a finite a1 doc 004's symmetric construction does NOT give equal end pressure
    // angles: 27.6° and 14.4° for the thesis dimensions, against 17.5° at both ends for the
    // equal-pressure (thesis collinearity) solution, which has the smaller maximum.
    assert_relative_eq!(
        gear.start_pressure_angle_rad.to_degrees(),
        27.643290281904616,
        max_relative = 1e-9
    );
    assert_relative_eq!(
        gear.end_pressure_angle_rad.to_degrees(),
        14.419852533017869,
        max_relative = 1e-9
    );
    let equal = spec.synthesise_equal_pressure_angles().unwrap();
    assert!(equal.start_pressure_angle_rad < gear.start_pressure_angle_rad.max(gear.end_pressure_angle_rad));
}

#[test]
fn analogues_match_the_thesis_kinematics() {
    // With ṡ = 1 m/s and s̈ = 0, ω = analogue and α = acceleration analogue.
    let spec = thesis_equivalent();
    let track = thesis_track();
    let synthesis = track.synthesis();
    for i in 0..=20 {
        let input = synthesis.stroke_start_m + synthesis.stroke_m * f64::from(i) / 20.0;
        let analogues = spec.analogues(input).unwrap();
        let state = track.linkage().state(input, 1.0, 0.0).unwrap();
        assert_relative_eq!(
            analogues.crank_rate_per_input_radpm,
            state.crank_rate_radps,
            max_relative = 1e-12
        );
        assert_relative_eq!(
            analogues.rod_rate_per_input_radpm,
            state.slider_rate_radps,
            max_relative = 1e-10,
            epsilon = 1e-12
        );
        assert_relative_eq!(
            analogues.crank_accel_per_input_radpm2,
            state.crank_accel_radps2,
            max_relative = 1e-10,
            epsilon = 1e-12
        );
        assert_relative_eq!(
            analogues.rod_accel_per_input_radpm2,
            state.slider_accel_radps2,
            max_relative = 1e-10,
            epsilon = 1e-12
        );
    }
}
