//! Torque tubes (`003_...` eqs 4-7), drive power and work.

use approx::assert_relative_eq;
use flapwright_sizing::{
    deployment_work_j, drive_demand, size_torque_tubes, torsion_radius_m, Material, SectionShape, SizingWarning,
    TorqueTubeInput,
};
use std::f64::consts::PI;

/// Eq 6 hand case: T = 100 N m, tau = 200 MPa:
/// 2 T / (pi tau) = 200 / 6.283185307e8 = 3.183098862e-7 m^3, r = cbrt = 6.827840633e-3 m.
#[test]
fn solid_torsion_radius_hand_case() {
    let r = torsion_radius_m(100.0, 200e6, SectionShape::Solid).unwrap();
    assert_relative_eq!(r, 6.827_840_632_552_959e-3, max_relative = 1e-12);
    // Back-substitution into tau = T r / J:
    let tau = 100.0 * r / SectionShape::Solid.polar_moment_m4(r);
    assert_relative_eq!(tau, 200e6, max_relative = 1e-12);
}

/// Hollow hand case: k = 0.8, 1 - k^4 = 0.5904:
/// r = (3.183098862e-7 / 0.5904)^(1/3) = 8.138941486e-3 m.
#[test]
fn hollow_torsion_radius_hand_case() {
    let shape = SectionShape::try_tube(0.8).unwrap();
    let r = torsion_radius_m(100.0, 200e6, shape).unwrap();
    assert_relative_eq!(r, 8.138_941_485_667_19e-3, max_relative = 1e-12);
    assert_relative_eq!(100.0 * r / shape.polar_moment_m4(r), 200e6, max_relative = 1e-12);
}

fn three_stations() -> Vec<TorqueTubeInput> {
    [("outboard", 100.0), ("middle", 200.0), ("inboard", 300.0)]
        .into_iter()
        .map(|(s, t)| TorqueTubeInput {
            station: s.into(),
            drive_torque_nm: t,
            length_m: 2.0,
            max_outer_radius_m: None,
        })
        .collect()
}

/// Eqs 4-7 for three stations, T_d = 100, 200, 300 N m, eta = 0.9, tau = 300 MPa:
/// tube 1 carries 100 / 0.9 = 111.111 N m, r_1 = (2 x 111.111 / (pi 3e8))^(1/3) = 6.177870e-3 m;
/// tube 2 carries 300 / 0.9 = 333.333 N m, r_2 = 8.910031e-3 m;
/// tube 3 carries 600 / 0.9 = 666.667 N m, r_3 = 1.122594e-2 m.
/// Mass of tube 3 = pi r_3^2 x 2 m x 2810 kg/m^3.
/// Eq 4: T_M,ideal = 600 N m; eq 5 with omega = 10 rad/s: P = 6666.67 W; 20 s: 133333 J.
#[test]
fn cumulative_three_stations() {
    let material = Material::try_new("al", 2810.0, 500e6, 300e6, 70e9).unwrap();
    let sized = size_torque_tubes(&three_stations(), 0.9, SectionShape::Solid, &material).unwrap();
    let expected = [
        (111.111_111_111_111_11, 6.177_870_298_768_088e-3),
        (333.333_333_333_333_4, 8.910_030_783_813_175e-3),
        (666.666_666_666_666_7, 1.122_593_533_973_753_4e-2),
    ];
    for (tube, (torque, radius)) in sized.iter().zip(expected) {
        assert_relative_eq!(tube.torque_carried_nm, torque, max_relative = 1e-12);
        assert_relative_eq!(tube.radius_m, radius, max_relative = 1e-12);
    }
    assert_relative_eq!(
        sized[2].mass_kg,
        PI * expected[2].1.powi(2) * 2.0 * 2810.0,
        max_relative = 1e-12
    );
    let drive = drive_demand(&[100.0, 200.0, 300.0], 0.9, 10.0, Vec::new()).unwrap();
    assert_relative_eq!(drive.ideal_motor_torque_nm, 600.0, max_relative = 1e-15);
    assert_relative_eq!(drive.peak_power_w, 6_666.666_666_666_667, max_relative = 1e-12);
}

#[test]
fn envelope_warning_for_tubes() {
    let mut tubes = three_stations();
    tubes[2].max_outer_radius_m = Some(0.01);
    let sized = size_torque_tubes(&tubes, 0.9, SectionShape::Solid, &Material::aluminium_7075_t6()).unwrap();
    assert!(matches!(
        sized[2].warnings[0],
        SizingWarning::TorqueTubeExceedsEnvelope { .. }
    ));
}

/// Work: torque rising linearly 0 -> 100 N m over one turn: W = 100 x 2 pi / 2 = 100 pi J.
#[test]
fn work_of_linear_torque() {
    let angles: Vec<f64> = (0..=10).map(|i| 2.0 * PI * f64::from(i) / 10.0).collect();
    let torques: Vec<f64> = (0..=10).map(|i| 10.0 * f64::from(i)).collect();
    assert_relative_eq!(
        deployment_work_j(&angles, &torques).unwrap(),
        100.0 * PI,
        max_relative = 1e-12
    );
}
