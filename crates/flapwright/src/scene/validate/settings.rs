//! Checks of the settings tables: sizing and materials, interference, resolution.

use super::limits::{
    AIRFOIL_POINTS_PER_SIDE, ALLOWABLE_PA, DENSITY_KG_M3, DEPLOYMENT_SAMPLES, FAIRING_POINTS_PER_CAPSULE,
    FAIRING_SAMPLES, GEARBOX_EFFICIENCY, INITIAL_SAMPLES, MAX_EVALUATIONS, MAX_MATERIALS, YOUNGS_MODULUS_PA,
};
use super::Checker;
use crate::scene::Scene;

/// Material presets the sizing stage knows by name.
pub const MATERIAL_PRESETS: &[&str] = &["steel-4340", "aluminium-7075-t6", "titanium-ti-6al-4v"];

impl Checker<'_> {
    pub(super) fn sizing(&mut self, scene: &Scene) {
        self.count_in("materials", scene.materials.len(), 0, MAX_MATERIALS);
        self.unique_names("materials", scene.materials.iter().map(|m| m.name.as_str()));
        for (i, material) in scene.materials.iter().enumerate() {
            let path = format!("materials[{i}]");
            if MATERIAL_PRESETS.contains(&material.name.as_str()) {
                self.fail(
                    format!("{path}.name"),
                    format!("= \"{}\": is a preset name; choose another", material.name),
                );
            }
            for (key, value, (min, max)) in [
                ("density_kg_m3", material.density_kg_m3, DENSITY_KG_M3),
                ("allowable_tensile_pa", material.allowable_tensile_pa, ALLOWABLE_PA),
                ("allowable_shear_pa", material.allowable_shear_pa, ALLOWABLE_PA),
                ("youngs_modulus_pa", material.youngs_modulus_pa, YOUNGS_MODULUS_PA),
            ] {
                self.in_range(&format!("{path}.{key}"), value, min, max, false);
            }
        }
        let sizing = &scene.sizing;
        for (key, name) in [
            ("screw_material", &sizing.screw_material),
            ("torque_tube_material", &sizing.torque_tube_material),
            ("link_material", &sizing.link_material),
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
        let (min, max) = GEARBOX_EFFICIENCY;
        self.in_range("sizing.gearbox_efficiency", sizing.gearbox_efficiency, min, max, false);
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
        // 10 reference loads outweigh any fairing: beyond it the depth no longer counts.
        self.in_range(
            "design.actuator_load_weight",
            scene.design.actuator_load_weight,
            0.0,
            10.0,
            false,
        );
        self.in_range(
            "design.rotary_actuator_load_weight",
            scene.design.rotary_actuator_load_weight,
            0.0,
            10.0,
            false,
        );
        // A weight of 10 makes a flap share of mechanism worth ten flap chords of depth.
        self.in_range(
            "design.mechanism_mass_weight",
            scene.design.mechanism_mass_weight,
            0.0,
            10.0,
            false,
        );
        self.in_range(
            "design.four_bar_actuator_load_cap",
            scene.design.four_bar_actuator_load_cap,
            0.05,
            100.0,
            false,
        );
        let interference = &scene.interference;
        self.in_range(
            "interference.required_clearance_m",
            interference.required_clearance_m,
            0.0,
            1.0,
            false,
        );
        self.in_range("interference.tolerance_m", interference.tolerance_m, 1e-7, 1.0, false);
        self.in_range(
            "interference.relative_tolerance",
            interference.relative_tolerance,
            0.0,
            0.5,
            false,
        );
        self.in_range("interference.joint_play_m", interference.joint_play_m, 0.0, 0.1, false);
        if let Some(margin) = interference.opening_margin_m {
            self.in_range("interference.opening_margin_m", margin, 0.0, 1.0, false);
        }
        if let Some(percent) = interference.required_clearance_percent_flap_chord {
            self.in_range(
                "interference.required_clearance_percent_flap_chord",
                percent,
                0.0,
                10.0,
                false,
            );
        }
        let (min, max) = INITIAL_SAMPLES;
        self.count_in("interference.initial_samples", interference.initial_samples, min, max);
        self.count_in(
            "interference.max_evaluations",
            interference.max_evaluations,
            // A bad initial_samples is reported above; bound by its nearest allowed value.
            interference.initial_samples.clamp(min, max),
            MAX_EVALUATIONS,
        );
    }

    pub(super) fn resolution(&mut self, scene: &Scene) {
        let res = &scene.resolution;
        for (key, value, (min, max)) in [
            (
                "airfoil_points_per_side",
                res.airfoil_points_per_side,
                AIRFOIL_POINTS_PER_SIDE,
            ),
            ("deployment_samples", res.deployment_samples, DEPLOYMENT_SAMPLES),
            ("fairing_samples", res.fairing_samples, FAIRING_SAMPLES),
            (
                "fairing_points_per_capsule",
                res.fairing_points_per_capsule,
                FAIRING_POINTS_PER_CAPSULE,
            ),
        ] {
            self.count_in(&format!("resolution.{key}"), value, min, max);
        }
    }
}
