//! Checks of the stations' mechanisms and the load cases.

use super::limits::{
    FLAP_MASS_KG, MECHANISM_LENGTH_M, MIN_SLOT_OFFSET_ANGLE_DEG, NUT_SPEED_MPS, SCREW_FRICTION, SCREW_LEAD_M,
    SCREW_MEAN_RADIUS_M,
};
use super::Checker;
use crate::scene::{MechanismScene, Scene};

impl Checker<'_> {
    pub(super) fn stations(&mut self, scene: &Scene) {
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
            let mut lengths = vec![
                ("base_distance_m", m.base_distance_m),
                ("crank_length_m", m.crank_length_m),
                ("outer_slot_radius_m", m.outer_slot_radius_m),
                ("inner_slot_radius_m", m.inner_slot_radius_m),
            ];
            lengths.extend(m.screw_length_m.map(|a3| ("screw_length_m", a3)));
            for (key, value, (min, max)) in lengths
                .into_iter()
                .map(|(key, value)| (key, value, MECHANISM_LENGTH_M))
                .chain([
                    ("flap_mass_kg", m.flap_mass_kg, FLAP_MASS_KG),
                    ("screw_lead_m", m.screw_lead_m, SCREW_LEAD_M),
                    ("screw_mean_radius_m", m.screw_mean_radius_m, SCREW_MEAN_RADIUS_M),
                    ("screw_friction", m.screw_friction, SCREW_FRICTION),
                    ("nut_speed_mps", m.nut_speed_mps, NUT_SPEED_MPS),
                ])
            {
                self.in_range(&format!("{mpath}.{key}"), value, min, max, false);
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
            let offset = m.slot_offset_angle_deg;
            if offset.is_finite() && offset.to_radians().sin().abs() < MIN_SLOT_OFFSET_ANGLE_DEG.to_radians().sin() {
                self.fail(
                    format!("{mpath}.slot_offset_angle_deg"),
                    format!(
                        "= {}: the two slot pins lie on one line through the hinge A0 and cannot hold the flap; keep it at least {MIN_SLOT_OFFSET_ANGLE_DEG} deg away from 0 and +-180 deg",
                        super::number(offset)
                    ),
                );
            }
            self.point_within(&format!("{mpath}.flap_centre_of_mass_m"), &m.flap_centre_of_mass_m);
            if m.inner_slot_radius_m.is_finite() && m.inner_slot_radius_m >= m.outer_slot_radius_m {
                // Thesis section 5.3, red-cell condition 2.
                self.fail(
                    format!("{mpath}.inner_slot_radius_m"),
                    format!(
                        "= {}: must be smaller than outer_slot_radius_m = {} (thesis 5.3, condition 2)",
                        super::number(m.inner_slot_radius_m),
                        super::number(m.outer_slot_radius_m)
                    ),
                );
            }
        }
        self.one_rotation_per_flap(scene);
        self.one_screw_speed(scene);
    }

    /// The torque tube turns every screw jack at one speed, so the stations' screw speeds
    /// 2 pi v / l (nut speed over lead) must agree: otherwise the report's drive speed would
    /// be one station's and the others' nuts would run at speeds the drive cannot give.
    fn one_screw_speed(&mut self, scene: &Scene) {
        if scene.structure.torque_tube.is_none() {
            return;
        }
        let mut first: Option<(usize, f64)> = None;
        for (i, station) in scene.station.iter().enumerate() {
            let MechanismScene::CircularArcTrack(m) = &station.mechanism;
            let turns_per_s = m.nut_speed_mps / m.screw_lead_m;
            if !turns_per_s.is_finite() {
                continue;
            }
            match first {
                None => first = Some((i, turns_per_s)),
                Some((j, first_turns)) if (turns_per_s - first_turns).abs() > 1e-9 * first_turns => self.fail(
                    format!("station[{i}].mechanism.nut_speed_mps"),
                    format!(
                        "= {}: with screw_lead_m = {} its screw turns {:.4} rev/s, but station[{j}]'s turns {:.4} rev/s; one torque tube drives every screw at one speed: make nut_speed_mps / screw_lead_m equal",
                        super::number(m.nut_speed_mps),
                        super::number(m.screw_lead_m),
                        turns_per_s,
                        first_turns
                    ),
                ),
                Some(_) => {}
            }
        }
    }

    /// A flap is one rigid body: its stations turn it through the same range, and that
    /// range reaches the landing setting.
    fn one_rotation_per_flap(&mut self, scene: &Scene) {
        for (f, flap) in scene.flap.iter().enumerate() {
            let mut first: Option<(usize, f64)> = None;
            for (i, station) in scene.station.iter().enumerate() {
                if station.flap.as_deref() != Some(flap.name.as_str()) {
                    continue;
                }
                let MechanismScene::CircularArcTrack(m) = &station.mechanism;
                let range = m.rotation_range_deg;
                match first {
                    None => first = Some((i, range)),
                    Some((j, first_range)) if (range - first_range).abs() > 1e-9 => self.fail(
                        format!("station[{i}].mechanism.rotation_range_deg"),
                        format!(
                            "= {range}: must equal station[{j}].mechanism.rotation_range_deg = {first_range}: both stations turn the one rigid flap \"{}\"",
                            flap.name
                        ),
                    ),
                    Some(_) => {}
                }
            }
            if let Some((j, range)) = first {
                let landing = flap.settings.landing_deg;
                if landing > range + 1e-9 {
                    self.fail(
                        format!("flap[{f}].settings.landing_deg"),
                        format!(
                            "= {landing}: beyond the rotation range of its mechanisms, station[{j}].mechanism.rotation_range_deg = {range}"
                        ),
                    );
                }
            }
        }
    }

    pub(super) fn loads(&mut self, scene: &Scene) {
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
