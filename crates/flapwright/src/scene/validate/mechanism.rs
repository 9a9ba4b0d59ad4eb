//! Checks of the stations' mechanisms and the load cases.

use super::Checker;
use crate::scene::Scene;

/// The least distance between two stations of one flap along its hinge axis, as a fraction
/// of the flap's span (`y_outboard_m - y_inboard_m`): 5 %, 0.35 m on `transport-flap`'s
/// 7 m inboard flap and 0.1 m on a light aircraft's 2 m flap. Closer stations would carry
/// one stretch of the flap twice, with their fittings in each other's place; the shipped
/// scenes' closest pair stands 33 % of its span apart.
pub const MIN_STATION_SPACING_FRACTION: f64 = 0.05;

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
                        let landing = flap.settings.targets("landing");
                        if station.plane == Some(flapwright_planes::PlaneConstruction::SkewCorrected)
                            && (landing.0.is_none() || landing.1.is_none())
                        {
                            self.fail(
                                format!("{path}.plane"),
                                format!(
                                    "= \"skew-corrected\" follows the flap's landing motion: give flap \"{}\" [flap.settings] landing_gap_percent and landing_overlap_percent, or use \"perpendicular-to-axis\"",
                                    flap.name
                                ),
                            );
                        }
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
            station.mechanism.kind().check(self, &format!("{path}.mechanism"));
        }
        self.one_rotation_per_flap(scene);
        self.stations_apart(scene);
    }

    /// Stations on one flap stand at least [`MIN_STATION_SPACING_FRACTION`] of its span
    /// apart along the hinge axis: two mechanisms closer than that share one stretch of
    /// the flap and their parts each other's place.
    fn stations_apart(&mut self, scene: &Scene) {
        for flap in &scene.flap {
            let span = flap.y_outboard_m - flap.y_inboard_m;
            if !(span.is_finite() && span > 0.0) {
                continue;
            }
            let spacing = MIN_STATION_SPACING_FRACTION * span;
            let mut on_flap: Vec<(usize, f64)> = scene
                .station
                .iter()
                .enumerate()
                .filter(|(_, s)| s.flap.as_deref() == Some(flap.name.as_str()))
                .filter_map(|(i, s)| s.axis_offset_m.filter(|o| o.is_finite()).map(|o| (i, o)))
                .collect();
            on_flap.sort_by(|a, b| a.1.total_cmp(&b.1));
            for pair in on_flap.windows(2) {
                let ((j, first), (i, second)) = (pair[0], pair[1]);
                if second - first < spacing {
                    let (later, earlier) = if i > j { (i, j) } else { (j, i) };
                    let offset = if i > j { second } else { first };
                    self.fail(
                        format!("station[{later}].axis_offset_m"),
                        format!(
                            "= {}: station \"{}\" stands {} m from station \"{}\" (station[{earlier}]) on flap \"{}\"; stations on one flap must be at least {} m apart ({} % of its {} m span)",
                            super::number(offset),
                            scene.station[later].name,
                            super::number(second - first),
                            scene.station[earlier].name,
                            flap.name,
                            super::number(spacing),
                            super::number(100.0 * MIN_STATION_SPACING_FRACTION),
                            super::number(span),
                        ),
                    );
                }
            }
        }
    }

    /// A flap is one rigid body: its stations turn it through the same range, and that
    /// range reaches the landing setting.
    fn one_rotation_per_flap(&mut self, scene: &Scene) {
        for (f, flap) in scene.flap.iter().enumerate() {
            let mut first: Option<(usize, f64, &str)> = None;
            for (i, station) in scene.station.iter().enumerate() {
                if station.flap.as_deref() != Some(flap.name.as_str()) {
                    continue;
                }
                // A kind synthesised from the settings turns the flap to its landing setting.
                let (range, key) = station
                    .mechanism
                    .kind()
                    .deflection_range()
                    .unwrap_or((flap.settings.landing_deg, "kind"));
                match first {
                    None => first = Some((i, range, key)),
                    Some((j, first_range, first_key)) if (range - first_range).abs() > 1e-9 => self.fail(
                        format!("station[{i}].mechanism.{key}"),
                        format!(
                            "= {}: must equal station[{j}].mechanism.{first_key} = {}: both stations turn the one rigid flap \"{}\"",
                            super::number(range),
                            super::number(first_range),
                            flap.name
                        ),
                    ),
                    Some(_) => {}
                }
            }
            if let Some((j, range, key)) = first {
                let landing = flap.settings.landing_deg;
                if landing > range + 1e-9 {
                    self.fail(
                        format!("flap[{f}].settings.landing_deg"),
                        format!(
                            "= {}: beyond the deflection range of its mechanisms, station[{j}].mechanism.{key} = {}",
                            super::number(landing),
                            super::number(range)
                        ),
                    );
                }
            }
        }
    }

    /// A flight-condition case: one form of dynamic pressure, a C_N table, a wing to take
    /// the flap areas from, and kinds whose statics take a normal force.
    fn flight_condition(&mut self, scene: &Scene, case: &crate::scene::LoadCaseScene, path: &str) {
        if case.moment_nm.is_some() || case.moment_stowed_nm.is_some() || case.moment_deployed_nm.is_some() {
            self.fail(path, "give either moments or a flight condition, not both");
        }
        match (case.dynamic_pressure_pa, case.speed_mps, case.density_kgpm3) {
            (Some(q), None, None) => {
                self.in_range(&format!("{path}.dynamic_pressure_pa"), q, 0.0, 1e6, true);
            }
            (None, Some(v), Some(rho)) => {
                self.in_range(&format!("{path}.speed_mps"), v, 0.0, 500.0, true);
                self.in_range(&format!("{path}.density_kgpm3"), rho, 0.0, 2.0, true);
            }
            _ => self.fail(
                path,
                "a flight condition gives dynamic_pressure_pa, or speed_mps and density_kgpm3",
            ),
        }
        if let Some(n) = case.load_factor {
            self.in_range(&format!("{path}.load_factor"), n, -5.0, 10.0, false);
        }
        match &case.normal_force_coefficient {
            None => self.fail(
                format!("{path}.normal_force_coefficient"),
                "is required for a flight condition: rows [deflection_deg, C_N]",
            ),
            Some(rows) if rows.is_empty() || rows.len() > 64 => self.fail(
                format!("{path}.normal_force_coefficient"),
                format!("has {} rows: give 1 to 64 rows [deflection_deg, C_N]", rows.len()),
            ),
            Some(rows) => {
                for (k, [deflection, coefficient]) in rows.iter().enumerate() {
                    let row = format!("{path}.normal_force_coefficient[{k}]");
                    self.in_range(&row, *deflection, -10.0, 90.0, false);
                    self.in_range(&row, *coefficient, -5.0, 5.0, false);
                    if k > 0 && (deflection.is_nan() || *deflection <= rows[k - 1][0]) {
                        self.fail(row, "deflections must increase from row to row");
                    }
                }
            }
        }
        if scene.wing.is_none() {
            self.fail(path, "a flight condition needs a [wing]: the flap areas come from it");
        }
        for (j, station) in scene.station.iter().enumerate() {
            if !station.mechanism.kind().takes_normal_force() {
                self.fail(
                    path,
                    format!(
                        "station[{j}]'s mechanism takes hinge moments only: give this case as moments, or synthesise the station from the flap settings"
                    ),
                );
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
            if case.is_flight_condition() {
                self.flight_condition(scene, case, &path);
                continue;
            }
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
