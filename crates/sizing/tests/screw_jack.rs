//! Screw jack torques and motor torque against the thesis (`000_...`) case study.

use crate::data::{number, rows};
use approx::assert_relative_eq;
use flapwright_sizing::{motor_torque_nm, size_actuator, ActuatorInput, ScrewJack};

fn thesis_thread() -> ScrewJack {
    // Thesis section 5.2: r = 16 mm, l = 8 mm, f = 0.1.
    ScrewJack {
        mean_radius_m: 0.016,
        lead_m: 0.008,
        friction_coefficient: 0.1,
    }
}

/// Thesis Table 3: T_R and T_L from F_input by eqs 3.6.9 / 3.6.10.
#[test]
fn table_3_raise_and_lower_torques() {
    let table = rows("arslan2022_table3_screw_torques.csv");
    assert!(table.len() >= 4, "validation table read {} rows", table.len());
    let thread = thesis_thread();
    for row in &table {
        let force_n = number(&row[1]);
        let tolerance_nm = number(&row[4]) * 1e-3;
        let raise_nm = thread.torques(force_n).raise_torque_nm;
        let lower_nm = thread.torques(force_n).lower_torque_nm;
        assert!(
            (raise_nm - number(&row[2]) * 1e-3).abs() <= tolerance_nm,
            "{}: T_R {raise_nm}",
            row[0]
        );
        assert!(
            (lower_nm - number(&row[3]) * 1e-3).abs() <= tolerance_nm,
            "{}: T_L {lower_nm}",
            row[0]
        );
    }
}

/// Thesis section 5.2: max raise torque 4700.38 N mm -> 4.7 N m; x 1.5 -> 7.1 N m.
/// Rounding: the thesis reports one decimal; 1.5 x 4.70038 = 7.05058 rounds to 7.1.
#[test]
fn section_5_2_motor_torque() {
    let table = rows("arslan2022_sec5_2_motor_torque.csv");
    assert_eq!(table.len(), 1);
    let row = &table[0];
    let raise_nm = number(&row[0]) * 1e-3;
    let safety_factor = number(&row[1]);
    let scale = 10f64.powf(number(&row[4]));
    let round = |x: f64| (x * scale).round() / scale;
    // Raise torque recomputed from the spreadsheet input force 1622.9 N:
    let recomputed = thesis_thread().torques(1622.9).raise_torque_nm;
    assert_relative_eq!(recomputed, raise_nm, max_relative = 1e-5);
    let sizing = size_actuator(
        &ActuatorInput {
            station: "thesis".into(),
            name: "screw jack".into(),
            max_raise_torque_nm: recomputed,
            max_lower_torque_nm: thesis_thread().torques(1622.9).lower_torque_nm,
            min_lower_torque_nm: thesis_thread().torques(1622.9).lower_torque_nm,
            thread_self_locking: true,
        },
        safety_factor,
    )
    .unwrap();
    assert_eq!(round(sizing.max_raise_torque_nm), number(&row[2]));
    assert_eq!(round(sizing.motor_torque_nm), number(&row[3]));
    assert_relative_eq!(
        sizing.motor_torque_nm,
        1.5 * 4.700_384_931_968_569,
        max_relative = 1e-12
    );
    assert!(sizing.self_locking, "thesis screw: f = 0.1 > l / (2 pi r) = 0.0796");
    assert!(sizing.warnings.is_empty());
}

#[test]
fn back_drivable_screw_warns() {
    // Steep lead: l = 20 mm, r = 16 mm, f = 0.1: tan(lambda) = 0.199 > f.
    let thread = ScrewJack {
        mean_radius_m: 0.016,
        lead_m: 0.020,
        friction_coefficient: 0.1,
    };
    assert!(!thread.is_self_locking());
    let lower = thread.torques(1000.0).lower_torque_nm;
    assert!(lower < 0.0);
    let input = ActuatorInput {
        station: "s1".into(),
        name: "jack".into(),
        max_raise_torque_nm: thread.torques(1000.0).raise_torque_nm,
        max_lower_torque_nm: lower,
        min_lower_torque_nm: lower,
        thread_self_locking: thread.is_self_locking(),
    };
    let sizing = size_actuator(&input, 1.5).unwrap();
    assert!(!sizing.self_locking);
    assert_eq!(sizing.warnings.len(), 1);
    assert_relative_eq!(motor_torque_nm(2.0, -3.0, 1.5).unwrap(), 4.5, max_relative = 1e-15);
}
