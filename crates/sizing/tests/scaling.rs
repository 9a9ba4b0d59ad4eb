//! Scaling laws: doubling every load scales torsion-governed tube radii by 2^(1/3) and
//! buckling-governed solid rod radii by 2^(1/4) (relative 1e-12).

use approx::assert_relative_eq;
use flapwright_sizing::{
    size_rod, size_torque_tubes, GoverningCase, Material, RodInput, SectionShape, TorqueTubeInput,
};
use proptest::prelude::*;

fn tubes(torques: &[f64]) -> Vec<TorqueTubeInput> {
    torques
        .iter()
        .enumerate()
        .map(|(i, &t)| TorqueTubeInput {
            station: format!("s{i}"),
            drive_torque_nm: t,
            length_m: 1.5,
            max_outer_radius_m: None,
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(100))]

    #[test]
    fn tube_radii_scale_by_cube_root_of_two(torques in prop::collection::vec(1.0..5e3f64, 1..6),
                                            eta in 0.5..1.0f64, ratio in 0.0..0.9f64) {
        let material = Material::aluminium_7075_t6();
        let shape = SectionShape::try_tube(ratio).unwrap();
        let doubled: Vec<f64> = torques.iter().map(|t| 2.0 * t).collect();
        let base = size_torque_tubes(&tubes(&torques), eta, shape, &material).unwrap();
        let twice = size_torque_tubes(&tubes(&doubled), eta, shape, &material).unwrap();
        for (a, b) in base.iter().zip(&twice) {
            assert_relative_eq!(b.radius_m, a.radius_m * 2f64.cbrt(), max_relative = 1e-12);
        }
    }

    /// Long, lightly loaded pinned rods (L = 0.5..3 m, P_c <= 20 kN): buckling governs.
    #[test]
    fn buckling_radii_scale_by_fourth_root_of_two(length in 0.5..3.0f64, compression in 10.0..2e4f64,
                                                  tension in 0.0..1e3f64, k in 0.5..2.0f64) {
        let material = Material::steel_4340();
        let mut rod = RodInput::new("s", "strut", length, tension, compression);
        rod.end_fixity_factor = k;
        let base = size_rod(&rod, &material).unwrap();
        rod.max_tension_n *= 2.0;
        rod.max_compression_n *= 2.0;
        let twice = size_rod(&rod, &material).unwrap();
        prop_assert_eq!(base.governing, GoverningCase::Buckling);
        prop_assert_eq!(twice.governing, GoverningCase::Buckling);
        assert_relative_eq!(twice.radius_m, base.radius_m * 2f64.powf(0.25), max_relative = 1e-12);
    }
}
