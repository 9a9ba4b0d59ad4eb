//! Scene validation: every bad value reported with its path in the file, all at once.

use std::fmt;
use std::path::Path;

use super::{AirfoilRef, FlapScene, MechanismScene, Scene, WingScene};

/// One problem in a scene file: where (`wing.sections[2].chord_m`) and what.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    /// Path of the offending key in the file.
    pub path: String,
    /// What is wrong and what is allowed.
    pub message: String,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // `path = value: rule` reads like the file; other messages follow a colon.
        if self.message.starts_with('=') {
            write!(f, "{} {}", self.path, self.message)
        } else {
            write!(f, "{}: {}", self.path, self.message)
        }
    }
}

/// Why a scene could not be read.
#[derive(Debug)]
pub enum SceneError {
    /// The TOML does not parse into the scene structure (syntax, wrong type, unknown key).
    Parse(String),
    /// The scene parsed but has invalid values.
    Invalid(Vec<Problem>),
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Parse(message) => write!(f, "{}", message.trim_end()),
            Self::Invalid(problems) => {
                write!(f, "{} problem(s) in the scene:", problems.len())?;
                for problem in problems {
                    write!(f, "\n  - {problem}")?;
                }
                Ok(())
            }
        }
    }
}

impl std::error::Error for SceneError {}

impl Scene {
    /// Parses and validates a scene. `scene_dir` is where relative airfoil files are
    /// looked up (bundled airfoils are found by name otherwise).
    pub fn from_toml(text: &str, scene_dir: Option<&Path>) -> Result<Self, SceneError> {
        let scene: Scene = toml::from_str(text).map_err(|e| SceneError::Parse(e.to_string()))?;
        let problems = scene.validate(scene_dir);
        if problems.is_empty() {
            Ok(scene)
        } else {
            Err(SceneError::Invalid(problems))
        }
    }

    /// All problems of the scene (empty when valid).
    pub fn validate(&self, scene_dir: Option<&Path>) -> Vec<Problem> {
        let mut check = Checker {
            problems: Vec::new(),
            scene_dir,
        };
        if self.name.trim().is_empty() {
            check.fail("name", "\"\": must not be empty");
        }
        if let Some(wing) = &self.wing {
            check.wing(wing);
            for (i, flap) in self.flap.iter().enumerate() {
                check.flap(&format!("flap[{i}]"), flap, wing);
            }
            check.unique_names("flap", self.flap.iter().map(|f| f.name.as_str()));
            check.structure(self, wing);
        } else if !self.flap.is_empty() {
            check.fail("flap", "a flap needs a [wing]");
        }
        check.stations(self);
        check.loads(self);
        check.sizing(self);
        let res = &self.resolution;
        check.count_in(
            "resolution.airfoil_points_per_side",
            res.airfoil_points_per_side,
            8,
            2000,
        );
        check.count_in("resolution.deployment_samples", res.deployment_samples, 2, 1_000_000);
        check.count_in("resolution.fairing_samples", res.fairing_samples, 2, 100_000);
        check.count_in(
            "resolution.fairing_points_per_capsule",
            res.fairing_points_per_capsule,
            2,
            10_000,
        );
        check.problems
    }
}

struct Checker<'a> {
    problems: Vec<Problem>,
    scene_dir: Option<&'a Path>,
}

impl Checker<'_> {
    fn fail(&mut self, path: impl Into<String>, message: impl Into<String>) {
        self.problems.push(Problem {
            path: path.into(),
            message: message.into(),
        });
    }

    /// Finite and inside `[min, max]` (or open bounds where `open`); true when fine.
    fn in_range(&mut self, path: &str, value: f64, min: f64, max: f64, open: bool) -> bool {
        let ok = value.is_finite()
            && if open {
                value > min && value < max
            } else {
                value >= min && value <= max
            };
        if !ok {
            let (lo, hi) = if open { ("(", ")") } else { ("[", "]") };
            let bound = |b: f64| {
                if b.is_infinite() {
                    "inf".to_string()
                } else {
                    format!("{b}")
                }
            };
            self.fail(
                path,
                format!("= {value}: must be in {lo}{}, {}{hi}", bound(min), bound(max)),
            );
        }
        ok
    }

    fn positive(&mut self, path: &str, value: f64) -> bool {
        let ok = value.is_finite() && value > 0.0;
        if !ok {
            self.fail(path, format!("= {value}: must be > 0 and finite"));
        }
        ok
    }

    fn finite_point(&mut self, path: &str, point: &[f64]) -> bool {
        let ok = point.iter().all(|v| v.is_finite());
        if !ok {
            self.fail(path, format!("= {point:?}: every coordinate must be finite"));
        }
        ok
    }

    fn count_in(&mut self, path: &str, value: usize, min: usize, max: usize) {
        if value < min || value > max {
            self.fail(path, format!("= {value}: must be in [{min}, {max}]"));
        }
    }

    fn unique_names<'n>(&mut self, table: &str, names: impl Iterator<Item = &'n str>) {
        let mut seen = std::collections::BTreeSet::new();
        for (i, name) in names.enumerate() {
            if name.trim().is_empty() {
                self.fail(format!("{table}[{i}].name"), "must not be empty");
            } else if !seen.insert(name) {
                self.fail(
                    format!("{table}[{i}].name"),
                    format!("= \"{name}\": used twice; names must be unique"),
                );
            }
        }
    }

    fn airfoil(&mut self, path: &str, text: &str) {
        match AirfoilRef::parse(text) {
            Err(message) => self.fail(path, message),
            Ok(AirfoilRef::File(name)) => {
                if AirfoilRef::locate(&name, self.scene_dir).is_none() {
                    self.fail(
                        path,
                        format!(
                            "= \"{name}\": file not found next to the scene nor among the bundled airfoils ({})",
                            super::airfoil_ref::BUNDLED_AIRFOILS
                                .iter()
                                .map(|(n, _)| *n)
                                .collect::<Vec<_>>()
                                .join(", ")
                        ),
                    );
                }
            }
            Ok(AirfoilRef::Naca(_)) => {}
        }
    }

    fn wing(&mut self, wing: &WingScene) {
        self.finite_point("wing.root_leading_edge_m", &wing.root_leading_edge_m);
        self.in_range(
            "wing.twist_axis_chord_fraction",
            wing.twist_axis_chord_fraction,
            0.0,
            1.0,
            false,
        );
        if wing.sections.len() < 2 {
            self.fail(
                "wing.sections",
                format!("has {} section(s): a wing needs at least 2", wing.sections.len()),
            );
        }
        let mut previous_y: Option<f64> = None;
        for (i, section) in wing.sections.iter().enumerate() {
            let path = format!("wing.sections[{i}]");
            if self.in_range(
                &format!("{path}.y_m"),
                section.y_m,
                f64::NEG_INFINITY,
                f64::INFINITY,
                true,
            ) {
                if let Some(prev) = previous_y {
                    if section.y_m <= prev {
                        self.fail(
                            format!("{path}.y_m"),
                            format!(
                                "= {}: sections must be in increasing spanwise order (previous y_m = {prev})",
                                section.y_m
                            ),
                        );
                    }
                }
                previous_y = Some(section.y_m);
            }
            self.positive(&format!("{path}.chord_m"), section.chord_m);
            self.in_range(&format!("{path}.twist_deg"), section.twist_deg, -45.0, 45.0, false);
            self.airfoil(&format!("{path}.airfoil"), &section.airfoil);
        }
        if let (Some(first), Some(last)) = (wing.sections.first(), wing.sections.last()) {
            if wing.sections.len() >= 2 && first.y_m.is_finite() && last.y_m == first.y_m {
                self.fail("wing.sections", "zero span: first and last sections have the same y_m");
            }
        }
        let expected_panels = wing.sections.len().saturating_sub(1);
        if wing.panels.len() != expected_panels {
            self.fail(
                "wing.panels",
                format!(
                    "has {} panel(s): must have one per gap between sections ({expected_panels})",
                    wing.panels.len()
                ),
            );
        }
        for (i, panel) in wing.panels.iter().enumerate() {
            self.in_range(
                &format!("wing.panels[{i}].sweep_deg"),
                panel.sweep_deg,
                -80.0,
                80.0,
                true,
            );
            self.in_range(
                &format!("wing.panels[{i}].dihedral_deg"),
                panel.dihedral_deg,
                -45.0,
                45.0,
                true,
            );
        }
    }

    fn flap(&mut self, path: &str, flap: &FlapScene, wing: &WingScene) {
        let (root, tip) = span_of(wing);
        let inboard_ok = self.in_range(&format!("{path}.y_inboard_m"), flap.y_inboard_m, root, tip, false);
        let outboard_ok = self.in_range(&format!("{path}.y_outboard_m"), flap.y_outboard_m, root, tip, false);
        if inboard_ok && outboard_ok && flap.y_outboard_m <= flap.y_inboard_m {
            self.fail(
                format!("{path}.y_outboard_m"),
                format!(
                    "= {}: must be greater than y_inboard_m = {}",
                    flap.y_outboard_m, flap.y_inboard_m
                ),
            );
        }
        for (key, value) in [
            ("chord_fraction_inboard", flap.chord_fraction_inboard),
            ("chord_fraction_outboard", flap.chord_fraction_outboard),
        ] {
            self.in_range(&format!("{path}.{key}"), value, 0.0, 0.8, true);
        }
        if let Some(gap) = flap.side_gap_m {
            let quarter_span = 0.25 * (flap.y_outboard_m - flap.y_inboard_m).abs();
            self.in_range(&format!("{path}.side_gap_m"), gap, 0.0, quarter_span, false);
        }
        if let Some(airfoil) = &flap.airfoil {
            self.airfoil(&format!("{path}.airfoil"), airfoil);
        }
        let hinge = &flap.hinge;
        let hinge_path = format!("{path}.hinge");
        match (hinge.inboard_point_m, hinge.outboard_point_m, hinge.chord_fraction) {
            (Some(a), Some(b), None) => {
                let ok_a = self.finite_point(&format!("{hinge_path}.inboard_point_m"), &a);
                let ok_b = self.finite_point(&format!("{hinge_path}.outboard_point_m"), &b);
                let length = ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
                if ok_a && ok_b && length < 1e-6 {
                    self.fail(
                        hinge_path.clone(),
                        format!("axis has length {length} m: the two points must be distinct (>= 1e-6 m)"),
                    );
                } else if ok_a && ok_b && (b[1] - a[1]) <= 0.0 {
                    self.fail(
                        format!("{hinge_path}.outboard_point_m"),
                        "must be further outboard (larger y) than inboard_point_m",
                    );
                }
                if hinge.depth_below_chord_fraction.is_some() {
                    self.fail(
                        format!("{hinge_path}.depth_below_chord_fraction"),
                        "goes with chord_fraction, not with axis points",
                    );
                }
            }
            (None, None, Some(fraction)) => {
                self.in_range(&format!("{hinge_path}.chord_fraction"), fraction, 0.0, 1.5, false);
                if let Some(depth) = hinge.depth_below_chord_fraction {
                    self.in_range(
                        &format!("{hinge_path}.depth_below_chord_fraction"),
                        depth,
                        -0.5,
                        1.0,
                        false,
                    );
                }
            }
            _ => self.fail(
                hinge_path,
                "give either inboard_point_m and outboard_point_m, or chord_fraction (with optional depth_below_chord_fraction)",
            ),
        }
        let settings = &flap.settings;
        let takeoff_ok = self.in_range(
            &format!("{path}.settings.takeoff_deg"),
            settings.takeoff_deg,
            0.0,
            90.0,
            false,
        );
        let landing_ok = self.in_range(
            &format!("{path}.settings.landing_deg"),
            settings.landing_deg,
            0.0,
            90.0,
            true,
        );
        if takeoff_ok && landing_ok && settings.takeoff_deg > settings.landing_deg {
            self.fail(
                format!("{path}.settings.takeoff_deg"),
                format!(
                    "= {}: must not exceed landing_deg = {}",
                    settings.takeoff_deg, settings.landing_deg
                ),
            );
        }
    }

    fn structure(&mut self, scene: &Scene, wing: &WingScene) {
        let (root, tip) = span_of(wing);
        for (i, spar) in scene.structure.spars.iter().enumerate() {
            let path = format!("structure.spars[{i}]");
            let fraction_ok = self.in_range(&format!("{path}.chord_fraction"), spar.chord_fraction, 0.0, 1.0, true);
            self.positive(&format!("{path}.thickness_m"), spar.thickness_m);
            let start_ok = self.in_range(&format!("{path}.y_start_m"), spar.y_start_m, root, tip, false);
            let end_ok = self.in_range(&format!("{path}.y_end_m"), spar.y_end_m, root, tip, false);
            if start_ok && end_ok && spar.y_end_m <= spar.y_start_m {
                self.fail(
                    format!("{path}.y_end_m"),
                    format!("= {}: must be greater than y_start_m", spar.y_end_m),
                );
            }
            if !(fraction_ok && start_ok && end_ok) {
                continue;
            }
            for flap in &scene.flap {
                let overlaps = spar.y_start_m < flap.y_outboard_m && spar.y_end_m > flap.y_inboard_m;
                let flap_front = 1.0 - flap.chord_fraction_inboard.max(flap.chord_fraction_outboard);
                if overlaps && spar.chord_fraction >= flap_front {
                    self.fail(
                        format!("{path}.chord_fraction"),
                        format!(
                            "= {}: the spar lies in flap \"{}\" (flap starts at chord fraction {flap_front:.3}); must be < {flap_front:.3}",
                            spar.chord_fraction, flap.name
                        ),
                    );
                }
            }
        }
        self.unique_names("structure.spars", scene.structure.spars.iter().map(|s| s.name.as_str()));
        if let Some(tube) = &scene.structure.torque_tube {
            let path = "structure.torque_tube";
            self.positive(&format!("{path}.radius_m"), tube.radius_m);
            if tube.path_m.len() < 2 {
                self.fail(
                    format!("{path}.path_m"),
                    format!("has {} point(s): needs at least 2", tube.path_m.len()),
                );
            }
            for (i, point) in tube.path_m.iter().enumerate() {
                self.finite_point(&format!("{path}.path_m[{i}]"), point);
            }
            for (i, pair) in tube.path_m.windows(2).enumerate() {
                let length = ((pair[1][0] - pair[0][0]).powi(2)
                    + (pair[1][1] - pair[0][1]).powi(2)
                    + (pair[1][2] - pair[0][2]).powi(2))
                .sqrt();
                if length < 1e-6 {
                    self.fail(
                        format!("{path}.path_m[{}]", i + 1),
                        "repeats the previous point: segments must be longer than 1e-6 m",
                    );
                }
            }
        }
    }

    fn stations(&mut self, scene: &Scene) {
        self.unique_names("station", scene.station.iter().map(|s| s.name.as_str()));
        for (i, station) in scene.station.iter().enumerate() {
            let path = format!("station[{i}]");
            match (&station.flap, &scene.wing) {
                (Some(name), Some(_)) => match scene.flap.iter().find(|f| &f.name == name) {
                    None => self.fail(
                        format!("{path}.flap"),
                        format!(
                            "= \"{name}\": no flap of that name (flaps: {})",
                            scene
                                .flap
                                .iter()
                                .map(|f| f.name.as_str())
                                .collect::<Vec<_>>()
                                .join(", ")
                        ),
                    ),
                    Some(flap) => {
                        let span = flap.y_outboard_m - flap.y_inboard_m;
                        match station.axis_offset_m {
                            None => self.fail(format!("{path}.axis_offset_m"), "is required for a station on a flap"),
                            Some(offset) => {
                                if span.is_finite() && span > 0.0 {
                                    self.in_range(&format!("{path}.axis_offset_m"), offset, 0.0, 2.0 * span, false);
                                }
                            }
                        }
                    }
                },
                (None, Some(_)) => self.fail(format!("{path}.flap"), "is required when the scene has a wing"),
                (Some(_), None) => self.fail(
                    format!("{path}.flap"),
                    "a 2D-only scene (no [wing]) has no flaps to name",
                ),
                (None, None) => {}
            }
            let MechanismScene::CircularArcTrack(m) = &station.mechanism;
            let mpath = format!("{path}.mechanism");
            for (key, value) in [
                ("base_distance_m", m.base_distance_m),
                ("crank_length_m", m.crank_length_m),
                ("outer_slot_radius_m", m.outer_slot_radius_m),
                ("inner_slot_radius_m", m.inner_slot_radius_m),
                ("flap_mass_kg", m.flap_mass_kg),
                ("screw_lead_m", m.screw_lead_m),
                ("screw_mean_radius_m", m.screw_mean_radius_m),
                ("nut_speed_mps", m.nut_speed_mps),
            ] {
                self.positive(&format!("{mpath}.{key}"), value);
            }
            if let Some(a3) = m.screw_length_m {
                self.positive(&format!("{mpath}.screw_length_m"), a3);
            }
            self.in_range(
                &format!("{mpath}.base_angle_deg"),
                m.base_angle_deg,
                -360.0,
                360.0,
                false,
            );
            self.in_range(
                &format!("{mpath}.slot_start_angle_deg"),
                m.slot_start_angle_deg,
                -360.0,
                360.0,
                false,
            );
            self.in_range(
                &format!("{mpath}.slot_offset_angle_deg"),
                m.slot_offset_angle_deg,
                -360.0,
                360.0,
                false,
            );
            self.in_range(
                &format!("{mpath}.rotation_range_deg"),
                m.rotation_range_deg,
                0.0,
                180.0,
                true,
            );
            self.in_range(&format!("{mpath}.screw_friction"), m.screw_friction, 0.0, 1.0, false);
            self.finite_point(&format!("{mpath}.flap_centre_of_mass_m"), &m.flap_centre_of_mass_m);
            if m.inner_slot_radius_m.is_finite() && m.inner_slot_radius_m >= m.outer_slot_radius_m {
                // Thesis section 5.3, red-cell condition 2.
                self.fail(
                    format!("{mpath}.inner_slot_radius_m"),
                    format!(
                        "= {}: must be smaller than outer_slot_radius_m = {} (thesis 5.3, condition 2)",
                        m.inner_slot_radius_m, m.outer_slot_radius_m
                    ),
                );
            }
        }
    }

    fn loads(&mut self, scene: &Scene) {
        if let Some(factor) = scene.loads.safety_factor {
            self.in_range("loads.safety_factor", factor, 1.0, 10.0, false);
        }
        self.unique_names("loads.cases", scene.loads.cases.iter().map(|c| c.name.as_str()));
        for (i, case) in scene.loads.cases.iter().enumerate() {
            let path = format!("loads.cases[{i}]");
            match (case.moment_nm, case.moment_stowed_nm, case.moment_deployed_nm) {
                (Some(m), None, None) => {
                    self.in_range(&format!("{path}.moment_nm"), m, -1e9, 1e9, false);
                }
                (None, Some(a), Some(b)) => {
                    self.in_range(&format!("{path}.moment_stowed_nm"), a, -1e9, 1e9, false);
                    self.in_range(&format!("{path}.moment_deployed_nm"), b, -1e9, 1e9, false);
                }
                _ => self.fail(
                    path,
                    "give either moment_nm, or moment_stowed_nm and moment_deployed_nm",
                ),
            }
        }
    }
}

/// Material presets the sizing stage knows by name.
pub const MATERIAL_PRESETS: &[&str] = &["steel-4340", "aluminium-7075-t6", "titanium-ti-6al-4v"];

impl Checker<'_> {
    fn sizing(&mut self, scene: &Scene) {
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
        if scene.outputs.sizing && !scene.outputs.kinematics {
            self.fail(
                "outputs.sizing",
                "needs outputs.kinematics = true (sizing uses the mechanism loads)",
            );
        }
    }
}

fn span_of(wing: &WingScene) -> (f64, f64) {
    let root = wing.sections.first().map_or(0.0, |s| s.y_m);
    let tip = wing.sections.last().map_or(0.0, |s| s.y_m);
    (root, tip)
}
