//! Checks of the settings tables: sizing and materials, interference, resolution.

use super::Checker;
use crate::scene::Scene;

/// Material presets the sizing stage knows by name.
pub const MATERIAL_PRESETS: &[&str] = &["steel-4340", "aluminium-7075-t6", "titanium-ti-6al-4v"];

impl Checker<'_> {
    pub(super) fn sizing(&mut self, scene: &Scene) {
        self.unique_names("materials", scene.materials.iter().map(|m| m.name.as_str()));
        for (i, material) in scene.materials.iter().enumerate() {
            let path = format!("materials[{i}]");
            if MATERIAL_PRESETS.contains(&material.name.as_str()) {
                self.fail(
                    format!("{path}.name"),
                    format!("= \"{}\": is a preset name; choose another", material.name),
                );
            }
            for (key, value) in [
                ("density_kg_m3", material.density_kg_m3),
                ("allowable_tensile_pa", material.allowable_tensile_pa),
                ("allowable_shear_pa", material.allowable_shear_pa),
                ("youngs_modulus_pa", material.youngs_modulus_pa),
            ] {
                self.positive(&format!("{path}.{key}"), value);
            }
        }
        let sizing = &scene.sizing;
        for (key, name) in [
            ("screw_material", &sizing.screw_material),
            ("torque_tube_material", &sizing.torque_tube_material),
        ] {
            let known = MATERIAL_PRESETS.contains(&name.as_str()) || scene.materials.iter().any(|m| &m.name == name);
            if !known {
                self.fail(
                    format!("sizing.{key}"),
                    format!(
                        "= \"{name}\": unknown material (presets: {}; or define it in [[materials]])",
                        MATERIAL_PRESETS.join(", ")
                    ),
                );
            }
        }
        self.in_range("sizing.gearbox_efficiency", sizing.gearbox_efficiency, 0.0, 1.0, false);
        if sizing.gearbox_efficiency == 0.0 {
            self.fail("sizing.gearbox_efficiency", "= 0: must be > 0");
        }
        self.in_range(
            "sizing.torque_tube_inner_to_outer_ratio",
            sizing.torque_tube_inner_to_outer_ratio,
            0.0,
            0.99,
            false,
        );
        self.in_range(
            "sizing.screw_end_fixity_factor",
            sizing.screw_end_fixity_factor,
            0.5,
            2.1,
            false,
        );
        if scene.outputs.sizing && !scene.outputs.kinematics {
            self.fail(
                "outputs.sizing",
                "needs outputs.kinematics = true (sizing uses the mechanism loads)",
            );
        }
    }

    pub(super) fn interference(&mut self, scene: &Scene) {
        let interference = &scene.interference;
        self.in_range(
            "interference.required_clearance_m",
            interference.required_clearance_m,
            0.0,
            1.0,
            false,
        );
        self.positive("interference.tolerance_m", interference.tolerance_m);
        self.in_range(
            "interference.relative_tolerance",
            interference.relative_tolerance,
            0.0,
            0.5,
            false,
        );
        self.in_range("interference.joint_play_m", interference.joint_play_m, 0.0, 0.1, false);
        self.count_in("interference.initial_samples", interference.initial_samples, 2, 100_000);
        self.count_in(
            "interference.max_evaluations",
            interference.max_evaluations,
            interference.initial_samples.max(2),
            10_000_000,
        );
    }

    pub(super) fn resolution(&mut self, scene: &Scene) {
        let res = &scene.resolution;
        self.count_in(
            "resolution.airfoil_points_per_side",
            res.airfoil_points_per_side,
            8,
            2000,
        );
        self.count_in("resolution.deployment_samples", res.deployment_samples, 2, 1_000_000);
        self.count_in("resolution.fairing_samples", res.fairing_samples, 2, 100_000);
        self.count_in(
            "resolution.fairing_points_per_capsule",
            res.fairing_points_per_capsule,
            2,
            10_000,
        );
    }
}
