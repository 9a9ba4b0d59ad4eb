//! Motor torque of the thesis (`000_...`) case study screw jack: F_input = 1622.9 N on a
//! square thread r = 16 mm, l = 8 mm, f = 0.1 gives T_R = 4.70 N m; with the CS-25 safety
//! factor 1.5 the motor must deliver 7.05 N m (the thesis rounds to 4.7 and 7.1 N m).
//!
//! Run: `cargo run -p flapwright-sizing --example thesis_screw_jack`

use flapwright_sizing::{size_actuator, ActuatorInput, ScrewJack, CS25_SAFETY_FACTOR};

fn main() -> Result<(), flapwright_sizing::Error> {
    let thread = ScrewJack {
        mean_radius_m: 0.016,
        lead_m: 0.008,
        friction_coefficient: 0.1,
    };
    let input_force_n = 1622.9;
    let jack = ActuatorInput {
        station: "thesis".into(),
        name: "screw jack".into(),
        max_raise_torque_nm: thread.torques(input_force_n).raise_torque_nm,
        max_lower_torque_nm: thread.torques(input_force_n).lower_torque_nm,
        min_lower_torque_nm: thread.torques(input_force_n).lower_torque_nm,
        thread_self_locking: true,
    };
    let sizing = size_actuator(&jack, CS25_SAFETY_FACTOR)?;
    println!(
        "raise {:.4} N m, lower {:.4} N m, motor {:.4} N m, self-locking {}",
        sizing.max_raise_torque_nm, sizing.max_lower_torque_nm, sizing.motor_torque_nm, sizing.self_locking
    );
    assert_eq!((sizing.max_raise_torque_nm * 10.0).round() / 10.0, 4.7);
    assert_eq!((sizing.motor_torque_nm * 10.0).round() / 10.0, 7.1);
    assert!(sizing.self_locking);
    Ok(())
}
