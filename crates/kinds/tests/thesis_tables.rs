//! Thesis Table 2 (synthesis, steps 7-10) and Table 3 (force analysis).

use approx::assert_relative_eq;
use flapwright_kinds::CircularArcTrackSpec;
use flapwright_mechanism::LoadCase;

use crate::common::{load_table, thesis_track, MM};

#[test]
fn table2_inputs_are_the_case_study_constructor() {
    let table = load_table("thesis-table2.csv");
    let rows = table.by_key();
    let value = |symbol: &str| -> f64 { rows[symbol][2].parse().unwrap() };
    let spec = CircularArcTrackSpec::thesis_case_study();
    let pairs = [
        (spec.base_distance_m * MM, value("a1")),
        (spec.crank_length_m * MM, value("a2")),
        (spec.screw_length_m * MM, value("a3")),
        (spec.base_angle_rad.to_degrees(), value("alpha0")),
        (spec.outer_slot_radius_m * MM, value("b1")),
        (spec.inner_slot_radius_m * MM, value("c1")),
        (spec.outer_slot_start_angle_rad.to_degrees(), value("beta1")),
        (spec.inner_slot_offset_angle_rad.to_degrees(), value("beta2")),
        (spec.rotation_range_rad.to_degrees(), value("beta3")),
        (spec.centre_of_mass_stowed_m.x * MM, value("xD")),
        (spec.centre_of_mass_stowed_m.y * MM, value("yD")),
        (spec.flap_mass_kg, value("m_flap")),
        (spec.gravity_mps2, value("g")),
        (spec.screw.mean_radius_m * MM, value("r")),
        (spec.screw.lead_m * MM, value("l")),
        (spec.screw.friction_coefficient, value("f")),
        (spec.nominal_input_speed_mps * MM, value("s34_dot")),
        (spec.nominal_input_accel_mps2 * MM, value("s34_ddot")),
    ];
    for (ours, printed) in pairs {
        assert_relative_eq!(ours, printed, max_relative = 1e-12, epsilon = 1e-12);
    }
}

#[test]
fn table2_computed_cells_reproduced_to_printed_digits() {
    let table = load_table("thesis-table2.csv");
    let track = thesis_track();
    let synthesis = track.synthesis();
    let computed = [
        ("s34_i", synthesis.stroke_start_m * MM),
        ("delta_s", synthesis.stroke_m * MM),
        ("g2", synthesis.crank_to_centre_of_mass_m * MM),
        ("p2", synthesis.centre_of_mass_to_inner_pin_m * MM),
        ("q2", synthesis.centre_of_mass_to_outer_pin_m * MM),
        ("alpha2", synthesis.centre_of_mass_offset_angle_rad.to_degrees()),
    ];
    let mut checked = 0;
    for (row, cells) in table.rows.iter().enumerate() {
        let Some((_, ours)) = computed.iter().find(|(symbol, _)| *symbol == cells[0]) else {
            continue;
        };
        let printed = table.number(row, "value");
        let half_digit = table.resolution(row, "value");
        assert!(
            (ours - printed).abs() <= half_digit,
            "{}: computed {ours}, printed {printed} (±{half_digit})",
            cells[0]
        );
        checked += 1;
    }
    assert_eq!(checked, computed.len());
    // The headline numbers of step 8.
    assert!((synthesis.stroke_start_m * MM - 80.3).abs() < 0.05);
    assert!((synthesis.stroke_m * MM - 144.3).abs() < 0.05);
    assert_eq!(synthesis.centre_of_mass_side, 1);
    assert!(synthesis.warnings.is_empty(), "{:?}", synthesis.warnings);
}

#[test]
fn collinearity_gives_same_screw_direction_and_full_rotation_at_both_ends() {
    let track = thesis_track();
    let synthesis = track.synthesis();
    let spec = track.spec();
    let end = track.pose(synthesis.stroke_end_m, 0.0, 0.0).unwrap();
    assert_relative_eq!(
        end.linkage.slider_angle_rad,
        synthesis.end_slider_angle_rad,
        max_relative = 1e-12
    );
    assert_relative_eq!(end.deflection_rad, spec.rotation_range_rad, max_relative = 1e-12);
    // Transmission angle at both ends is (π - β3)/2 (step 8).
    let start = track.pose(synthesis.stroke_start_m, 0.0, 0.0).unwrap();
    for pose in [start, end] {
        assert_relative_eq!(
            pose.diagnostics.transmission_angle_rad,
            synthesis.minimum_transmission_angle_rad,
            max_relative = 1e-12
        );
    }
    // θD = α0 + θ12,i + σ α2 (thesis 3.4.4) and θG = θD - β5, θF = θD - β6 (thesis 3.4).
    let theta_d = spec.base_angle_rad
        + synthesis.stowed_crank_angle_rad
        + f64::from(synthesis.centre_of_mass_side) * synthesis.centre_of_mass_offset_angle_rad;
    assert_relative_eq!(theta_d, synthesis.centre_of_mass_angle_stowed_rad, max_relative = 1e-12);
    assert_relative_eq!(
        theta_d - synthesis.inner_pin_offset_angle_rad,
        synthesis.inner_pin_angle_stowed_rad,
        max_relative = 1e-12
    );
    assert_relative_eq!(
        theta_d - synthesis.outer_pin_offset_angle_rad,
        synthesis.outer_pin_angle_stowed_rad,
        max_relative = 1e-12
    );
}

/// Reads one column of a sweep sample.
type Column = fn(&flapwright_kinds::SweepSample) -> f64;

fn table3_value(quantity: &str, scenario: &str, statistic: &str) -> f64 {
    let table = load_table("thesis-table3.csv");
    let row = table
        .rows
        .iter()
        .position(|r| r[0] == quantity && r[1] == scenario && r[2] == statistic)
        .unwrap_or_else(|| panic!("{quantity} {scenario} {statistic} missing"));
    table.number(row, "value")
}

#[test]
fn table3_cruise_reproduced_within_half_percent() {
    let track = thesis_track();
    let pose = track.pose(track.synthesis().stroke_start_m, 0.035, 0.0).unwrap();
    let forces = track.forces(&pose, &LoadCase::thesis_cruise()).unwrap();
    let pairs = [
        ("F_input", forces.actuator_force_n),
        ("G12G", forces.inner_slot_reaction_n),
        ("G12F", forces.outer_slot_reaction_n),
        ("T_R", forces.screw.raise_torque_nm * MM),
        ("T_L", forces.screw.lower_torque_nm * MM),
    ];
    for (quantity, ours) in pairs {
        assert_relative_eq!(ours, table3_value(quantity, "cruise", "stowed"), max_relative = 5e-3);
    }
}

#[test]
fn table3_landing_min_max_reproduced_within_half_percent() {
    let track = thesis_track();
    let sweep = track.sweep(401, &LoadCase::thesis_landing()).unwrap();
    assert!(sweep.stopped.is_none());
    let columns: [(&str, Column); 5] = [
        ("F_input", |s| s.actuator_force_n),
        ("G12G", |s| s.joint_reactions_n.inner_pin_g_n),
        ("G12F", |s| s.joint_reactions_n.outer_pin_f_n),
        ("T_R", |s| s.raise_torque_nm * MM),
        ("T_L", |s| s.lower_torque_nm * MM),
    ];
    for (quantity, column) in columns {
        let values: Vec<f64> = sweep.samples.iter().map(column).collect();
        let min = values.iter().copied().fold(f64::INFINITY, f64::min);
        let max = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        assert_relative_eq!(min, table3_value(quantity, "landing", "min"), max_relative = 5e-3);
        assert_relative_eq!(max, table3_value(quantity, "landing", "max"), max_relative = 5e-3);
    }
}
