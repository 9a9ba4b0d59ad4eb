//! Property tests over random dimensions: no NaN, no panic, tiny residuals.

use flapwright_kinds::{CircularArcTrack, CircularArcTrackSpec};
use flapwright_mechanism::{InvertedSliderCrank, LoadCase};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn slider_crank_is_finite_and_closes(
        a1 in 0.01f64..3.0,
        a2 in 0.01f64..3.0,
        alpha0 in -3.2f64..3.2,
        fraction in -0.2f64..1.2,
        speed in -2.0f64..2.0,
        accel in -5.0f64..5.0,
    ) {
        let linkage = InvertedSliderCrank::try_new(a1, a2, alpha0).unwrap();
        let (low, high) = linkage.assembly_range_m();
        let input = low + (high - low) * fraction;
        if let Ok(state) = linkage.state(input, speed, accel) {
            prop_assert!(state.closure_residual_m < 1e-10, "residual {}", state.closure_residual_m);
            for value in [
                state.crank_angle_rad, state.slider_angle_rad, state.crank_rate_radps,
                state.slider_rate_radps, state.crank_accel_radps2, state.slider_accel_radps2,
                state.jacobian_condition_number, state.transmission_angle_rad,
            ] {
                prop_assert!(value.is_finite());
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn random_tracks_synthesise_or_fail_cleanly(
        a1 in 0.05f64..0.6,
        a2 in 0.05f64..0.6,
        alpha0_deg in -180.0f64..180.0,
        beta3_deg in 1.0f64..90.0,
        c1 in 0.1f64..0.5,
        b_extra in -0.05f64..0.2,
        dx in -0.5f64..0.2,
        dy in -0.2f64..0.5,
    ) {
        let spec = CircularArcTrackSpec {
            base_distance_m: a1,
            crank_length_m: a2,
            screw_length_m: 2.0 * (a1 + a2),
            base_angle_rad: alpha0_deg.to_radians(),
            inner_slot_radius_m: c1,
            outer_slot_radius_m: c1 + b_extra,
            rotation_range_rad: beta3_deg.to_radians(),
            centre_of_mass_stowed_m: nalgebra::Point2::new(dx, dy),
            ..CircularArcTrackSpec::thesis_case_study()
        };
        if let Ok(track) = CircularArcTrack::synthesise(spec) {
            let sweep = track.sweep(16, &LoadCase::thesis_landing()).unwrap();
            for sample in &sweep.samples {
                prop_assert!(sample.closure_residual_m < 1e-10);
                let json = [
                    sample.deflection_deg, sample.transmission_angle_deg, sample.actuator_force_n,
                    sample.raise_torque_nm, sample.lower_torque_nm,
                    sample.joint_reactions_n.inner_pin_g_n, sample.joint_reactions_n.outer_pin_f_n,
                ];
                for value in json {
                    prop_assert!(value.is_finite());
                }
            }
        }
    }
}
