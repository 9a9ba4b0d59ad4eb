//! Bad inputs give typed errors naming the field and the allowed range.

use flapwright_sizing::{
    cumulative_torques_nm, distribute_to_stations, size_rod, size_torque_tubes, Error, LoadCase, Material, RodInput,
    SectionShape, TorqueTubeInput,
};

#[test]
fn zero_allowable_stress() {
    let e = Material::try_new("bad", 2800.0, 0.0, 100e6, 70e9).unwrap_err();
    assert_eq!(
        e,
        Error::InvalidMaterial {
            material: "bad".into(),
            field: "allowable_tensile_pa",
            value: 0.0,
            allowed: "(0, inf) Pa"
        }
    );
    assert!(e.to_string().contains("allowable_tensile_pa = 0"), "{e}");
    let e = Material::try_new("bad", 2800.0, 100e6, 0.0, 70e9).unwrap_err();
    assert!(matches!(
        e,
        Error::InvalidMaterial {
            field: "allowable_shear_pa",
            ..
        }
    ));
}

#[test]
fn negative_density() {
    let e = Material::try_new("bad", -1.0, 100e6, 60e6, 70e9).unwrap_err();
    assert!(matches!(e, Error::InvalidMaterial { field: "density_kg_m3", value, .. } if value == -1.0));
}

#[test]
fn hand_edited_material_is_caught_by_sizing() {
    let mut m = Material::steel_4340();
    m.allowable_tensile_pa = 0.0;
    let e = size_rod(&RodInput::new("s", "r", 1.0, 1.0, 1.0), &m).unwrap_err();
    assert!(matches!(
        e,
        Error::InvalidMaterial {
            field: "allowable_tensile_pa",
            ..
        }
    ));
}

#[test]
fn efficiency_above_one() {
    let e = cumulative_torques_nm(&[10.0], 1.05).unwrap_err();
    assert_eq!(
        e,
        Error::EfficiencyOutOfRange {
            field: "gearbox_efficiency".into(),
            value: 1.05
        }
    );
    assert!(e.to_string().contains("(0, 1]"));
    let tube = TorqueTubeInput {
        station: "s".into(),
        drive_torque_nm: 1.0,
        length_m: 1.0,
        max_outer_radius_m: None,
    };
    assert!(size_torque_tubes(&[tube], 0.0, SectionShape::Solid, &Material::steel_4340()).is_err());
}

#[test]
fn other_bad_inputs() {
    let m = Material::steel_4340();
    assert!(matches!(
        size_rod(&RodInput::new("s", "r", 0.0, 1.0, 1.0), &m),
        Err(Error::OutOfRange { .. })
    ));
    assert!(matches!(
        size_rod(&RodInput::new("s", "r", 1.0, f64::NAN, 1.0), &m),
        Err(Error::OutOfRange { .. })
    ));
    assert!(matches!(
        size_rod(&RodInput::new("s", "r", 1.0, -1.0, 1.0), &m),
        Err(Error::OutOfRange { .. })
    ));
    assert!(matches!(LoadCase::try_new(1.0, 0.9), Err(Error::OutOfRange { .. })));
    assert!(matches!(
        distribute_to_stations(&[], &[1.0]),
        Err(Error::TooFewStations { required: 2, found: 1 })
    ));
    assert!(matches!(
        distribute_to_stations(&[], &[1.0, 1.0]),
        Err(Error::NotIncreasing { index: 1, .. })
    ));
}
