//! Report assembly and JSON shape.

use approx::assert_relative_eq;
use flapwright_sizing::{
    drive_demand, size_actuator, size_rod, size_torque_tubes, ActuatorInput, DeploymentWork, Material, RodInput,
    SectionShape, SizingReport, TorqueTubeInput,
};

#[test]
fn report_totals_and_json() {
    let steel = Material::steel_4340();
    let mut fat = RodInput::new("inboard", "fat link", 0.05, 5e6, 0.0);
    fat.max_outer_radius_m = Some(0.01);
    let rods = vec![
        size_rod(&RodInput::new("inboard", "link", 0.5, 1e4, 5e3), &steel).unwrap(),
        size_rod(&RodInput::new("outboard", "link", 0.5, 1e4, 5e3), &steel).unwrap(),
        size_rod(&fat, &steel).unwrap(),
    ];
    let jacks = vec![size_actuator(
        &ActuatorInput {
            station: "inboard".into(),
            name: "jack".into(),
            max_raise_torque_nm: 4.7,
            max_lower_torque_nm: 0.53,
            min_lower_torque_nm: 0.53,
            thread_self_locking: true,
        },
        1.5,
    )
    .unwrap()];
    let tubes: Vec<TorqueTubeInput> = ["outboard", "inboard"]
        .iter()
        .map(|s| TorqueTubeInput {
            station: (*s).into(),
            drive_torque_nm: 50.0,
            length_m: 3.0,
            max_outer_radius_m: None,
        })
        .collect();
    let tubes = size_torque_tubes(&tubes, 0.95, SectionShape::Solid, &steel).unwrap();
    let drive = drive_demand(
        &[50.0, 50.0],
        0.95,
        20.0,
        vec![DeploymentWork {
            load_case: "cruise".into(),
            work_j: 120.0,
        }],
    )
    .unwrap();
    let expected_mass: f64 = rods.iter().map(|r| r.mass_kg).sum::<f64>() + tubes.iter().map(|t| t.mass_kg).sum::<f64>();
    let report = SizingReport::assemble(rods, jacks, tubes, Some(drive));
    assert_relative_eq!(report.totals.mass_kg, expected_mass, max_relative = 1e-12);
    assert_eq!(report.masses.per_station.len(), 2);
    assert_eq!(report.warnings.len(), 2, "fat link: envelope + not slender");
    let json = serde_json::to_value(&report).unwrap();
    // r_t = sqrt(1e4 / (pi 710e6)) = 2.1 mm < r_b = (4 x 5e3 x 0.25 / (pi^3 x 205e9))^(1/4) = 5.3 mm.
    assert_eq!(json["rods"][0]["governing"], "buckling");
    assert!(json["rods"][0]["radius_m"].is_f64());
    assert!(json["screw_jacks"][0]["motor_torque_nm"].is_f64());
    assert!(json["torque_tubes"][1]["torque_carried_nm"].is_f64());
    assert_eq!(json["warnings"][0]["kind"], "rod_exceeds_envelope");
    assert_eq!(json["totals"]["work_per_deployment_j"], 120.0);
    assert!(json["rods"][0].get("warnings").is_none());
    assert!(json["totals"]["mass_covers"].as_str().unwrap().contains("torque tubes"));
}

/// Without a drive line (no torque tube) the drive's power and work are unknown: null in
/// the report, not 0 (issue 35 item 5).
#[test]
fn totals_without_a_drive_line_are_null_not_zero() {
    let report = SizingReport::assemble(Vec::new(), Vec::new(), Vec::new(), None);
    let json = serde_json::to_value(report).unwrap();
    assert!(json["totals"]["peak_power_w"].is_null(), "{json}");
    assert!(json["totals"]["work_per_deployment_j"].is_null(), "{json}");
    assert_eq!(json["totals"]["mass_kg"], 0.0);
}
