//! Toggle and assembly failures are typed and name the input value.

use flapwright_mechanism::{Error, InvertedSliderCrank, LoadCase};

use crate::common::thesis_track;

#[test]
fn slider_crank_within_a_microradian_of_toggle_reports_it() {
    let (a1, a2) = (0.3, 0.2);
    let linkage = InvertedSliderCrank::try_new(a1, a2, 0.4).unwrap();
    // Crank nearly stretched out: θ12 = π - ε puts A almost on the far side of A0 from B0;
    // the transmission angle at A is then about ε a1 / s = 0.6 ε < 1e-6 rad.
    for epsilon in [1.6e-6, 1e-6, 1e-7] {
        let crank: f64 = std::f64::consts::PI - epsilon;
        let input = (a1 * a1 + a2 * a2 - 2.0 * a1 * a2 * crank.cos()).sqrt();
        match linkage.state(input, 0.01, 0.0) {
            Err(Error::Toggle {
                input_m,
                transmission_angle_rad,
                ..
            }) => {
                assert_eq!(input_m, input);
                assert!(transmission_angle_rad < 1e-6);
            }
            other => panic!("expected a toggle at {input}, got {other:?}"),
        }
    }
    // Away from the toggle it assembles with a tiny residual.
    let state = linkage.state(0.45, 0.01, 0.0).unwrap();
    assert!(state.closure_residual_m < 1e-15);
    // Beyond the reach it cannot assemble, and says where.
    assert!(matches!(
        linkage.state(0.5 + 1e-9, 0.0, 0.0),
        Err(Error::CannotAssemble { input_m, .. }) if input_m == 0.5 + 1e-9
    ));
    // The toggle message names the input value.
    let message = linkage.state(0.5, 0.0, 0.0).unwrap_err().to_string();
    assert!(message.contains("500.000 mm"), "{message}");
}

#[test]
fn track_sweep_stops_and_names_the_input_out_of_slot() {
    let track = thesis_track();
    let end = track.synthesis().stroke_end_m;
    let inputs = [end - 0.02, end - 0.01, end + 0.01, end + 0.02];
    let sweep = track.sweep_at(inputs, &LoadCase::thesis_cruise());
    assert_eq!(sweep.samples.len(), 2);
    let stop = sweep.stopped.expect("stops");
    assert_eq!(stop.sample_index, 2);
    assert_eq!(stop.input_m, end + 0.01);
    assert!(matches!(stop.reason, Error::OutOfSlot { input_m, .. } if input_m == end + 0.01));
    assert!(matches!(
        track.sweep(1, &LoadCase::thesis_cruise()),
        Err(Error::TooFewSamples { samples: 1 })
    ));
}

#[test]
fn red_cells_are_typed_errors() {
    use flapwright_kinds::{CircularArcTrack, CircularArcTrackSpec};
    let spec = CircularArcTrackSpec::thesis_case_study();
    // Red cell 2: c1 >= b1.
    let swapped = CircularArcTrackSpec {
        inner_slot_radius_m: 0.36,
        ..spec
    };
    assert!(matches!(
        CircularArcTrack::synthesise(swapped),
        Err(Error::SlotRadiiOrder { .. })
    ));
    // Red cell 3: a3 < s34,f.
    let short = CircularArcTrackSpec {
        screw_length_m: 0.2,
        ..spec
    };
    assert!(matches!(
        CircularArcTrack::synthesise(short),
        Err(Error::ScrewTooShort { .. })
    ));
    // Red cell 1: s34 < s34,i.
    let track = CircularArcTrack::synthesise(spec).unwrap();
    assert!(matches!(track.pose(0.07, 0.0, 0.0), Err(Error::OutOfSlot { .. })));
    // No collinear screw line when B0 is too close to the hinge.
    let close = CircularArcTrackSpec {
        base_distance_m: 0.2,
        ..spec
    };
    assert!(matches!(
        CircularArcTrack::synthesise(close),
        Err(Error::CollinearityImpossible { .. })
    ));
}

#[test]
fn sweep_serialises_with_the_report_field_names() {
    let track = thesis_track();
    let sweep = track.sweep(3, &LoadCase::thesis_landing()).unwrap();
    let json = serde_json::to_value(&sweep).unwrap();
    let sample = &json["samples"][0];
    for key in [
        "input_m",
        "deflection_deg",
        "transmission_angle_deg",
        "actuator_force_n",
        "raise_torque_nm",
        "lower_torque_nm",
        "closure_residual_m",
    ] {
        assert!(sample[key].is_number(), "{key} missing in {sample}");
    }
    for joint in ["A", "B0", "G", "F"] {
        assert!(sample["joint_reactions_n"][joint].is_number(), "joint {joint}");
    }
    assert_eq!(json["load_case"], "landing");
    assert!(json["stopped"].is_null());
}
