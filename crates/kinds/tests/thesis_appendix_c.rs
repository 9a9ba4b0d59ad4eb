//! Thesis Appendix C spreadsheet rows (Figs. 46 and 48), data-driven.

use flapwright_mechanism::LoadCase;

use crate::common::{assert_matches_print, load_table, spreadsheet_input_m, thesis_track, MM};

/// Thesis eq. 3.3.3 exactly as printed (with its sign defect), in rad/s².
fn alpha12_as_printed(a2: f64, delta: f64, speed: f64, accel: f64, w12: f64, w13: f64) -> f64 {
    (delta.tan() * accel - (w12 - w13) * speed) / (a2 * delta.sin() * delta.tan())
}

#[test]
fn kinematics_rows_match_the_spreadsheet() {
    let table = load_table("thesis-appendix-c-kinematics.csv");
    let track = thesis_track();
    let a2 = track.spec().crank_length_m;
    let mut rows_checked = 0;
    for row in 0..table.rows.len() {
        let index = table.number(row, "row") as usize;
        let input = spreadsheet_input_m(&track, index);
        assert_matches_print(
            input * MM,
            table.number(row, "s34_mm"),
            table.resolution(row, "s34_mm"),
            "s34",
        );
        let pose = track.pose(input, 0.035, 0.0).unwrap();
        let l = pose.linkage;
        let check = |ours: f64, column: &str| {
            assert_matches_print(
                ours,
                table.number(row, column),
                table.resolution(row, column),
                &format!("row {index} {column}"),
            );
        };
        check(l.crank_angle_rad, "theta12_rad");
        check(l.slider_angle_rad, "theta13_rad");
        check(l.crank_rate_radps, "omega12_radps");
        check(l.slider_rate_radps, "omega13_radps");
        check(l.slider_accel_radps2, "alpha13_radps2");
        // The printed α12 column is the misprinted eq. 3.3.3: it is reproduced by the
        // misprint, and the corrected value is its negative (s̈34 = 0).
        let delta = l.slider_angle_rad - l.crank_angle_rad;
        let misprint = alpha12_as_printed(a2, delta, 0.035, 0.0, l.crank_rate_radps, l.slider_rate_radps);
        check(misprint, "alpha12_printed_radps2");
        check(-l.crank_accel_radps2, "alpha12_printed_radps2");
        rows_checked += 1;
    }
    assert!(rows_checked >= 1);
    assert_eq!(rows_checked, 16);
}

#[test]
fn force_rows_match_the_spreadsheet() {
    let table = load_table("thesis-appendix-c-forces.csv");
    let track = thesis_track();
    let (cruise, landing) = (LoadCase::thesis_cruise(), LoadCase::thesis_landing());
    let mut rows_checked = 0;
    for row in 0..table.rows.len() {
        let index = table.number(row, "row") as usize;
        let pose = track.pose(spreadsheet_input_m(&track, index), 0.035, 0.0).unwrap();
        let c = track.forces(&pose, &cruise).unwrap();
        let l = track.forces(&pose, &landing).unwrap();
        let check = |ours: f64, column: &str| {
            assert_matches_print(
                ours,
                table.number(row, column),
                table.resolution(row, column),
                &format!("row {index} {column}"),
            );
        };
        check(c.actuator_force_n, "cruise_F42_N");
        check(c.inner_slot_reaction_n, "cruise_G12G_N");
        check(c.outer_slot_reaction_n, "cruise_G12F_N");
        check(l.external_moment_nm * MM, "landing_M12_Nmm");
        check(l.actuator_force_n, "landing_Finput_N");
        check(l.screw.raise_torque_nm * MM, "landing_TR_Nmm");
        check(l.screw.lower_torque_nm * MM, "landing_TL_Nmm");
        check(l.inner_slot_reaction_n, "landing_G12G_N");
        check(l.outer_slot_reaction_n, "landing_G12F_N");
        rows_checked += 1;
    }
    assert!(rows_checked >= 1);
}
