//! Checks of the aircraft: airfoils, wing, flaps, spars and torque tube.

use super::limits::{
    MAX_CHORD_M, MAX_FLAPS, MAX_SECTIONS, MAX_SPAN_M, MAX_SPARS, MAX_STATIONS, MAX_TORQUE_TUBE_POINTS, MIN_CHORD_M,
    MIN_LENGTH_M,
};
use super::Checker;
use crate::scene::{load_airfoil, AirfoilRef, FlapScene, Scene, WingScene};

impl Checker<'_> {
    /// A positive overlap target of a flap whose stations are synthesised from its settings
    /// needs the wing's shroud over the flap's nose: without one
    /// the cove is a wall just ahead of the flap, the lip sits at the flap's nose and a
    /// mechanism reaching a positive overlap drives the flap into the wing (97 mm on a
    /// reproducer). The shroud must reach past the largest overlap, with room for the gap:
    /// the value proposed is the largest overlap plus 3 % of the chord (the shipped
    /// transport flap reaches its 3 %c take-off overlap under a 6 %c shroud).
    pub(super) fn overlap_needs_a_shroud(&mut self, path: &str, flap: &crate::scene::FlapScene) {
        if flap.shroud_chord_fraction.is_some_and(|s| s > 0.0) {
            return;
        }
        let settings = &flap.settings;
        let largest = [
            ("takeoff_overlap_percent", settings.takeoff_overlap_percent),
            ("landing_overlap_percent", settings.landing_overlap_percent),
        ]
        .into_iter()
        .filter_map(|(key, value)| Some((key, value?)))
        .filter(|(_, value)| value.is_finite() && *value > 0.0)
        .max_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((key, overlap)) = largest {
            let proposed = ((overlap / 100.0 + 0.03) * 1000.0).ceil() / 1000.0;
            self.fail(
                format!("{path}.settings.{key}"),
                format!(
                    "= {}: a positive overlap needs the wing's shroud over the flap's nose, and {path}.shroud_chord_fraction is {}: the cove wall stands just ahead of the flap, so the flap would be driven into the wing; give {path}.shroud_chord_fraction = {} (the overlap and 3 % of the chord), or an overlap of 0 or less",
                    super::number(overlap),
                    if flap.shroud_chord_fraction.is_some() { "0" } else { "not given" },
                    super::number(proposed),
                ),
            );
        }
    }

    fn airfoil(&mut self, path: &str, text: &str) {
        match AirfoilRef::parse(text) {
            Err(message) => self.fail(path, message),
            Ok(AirfoilRef::File(name)) if AirfoilRef::locate(&name, self.files).is_some() => {
                self.airfoil_loads(path, text);
            }
            Ok(AirfoilRef::File(name)) => {
                self.fail(
                    path,
                    format!(
                        "= \"{name}\": file not found next to the scene nor among the bundled airfoils ({})",
                        crate::scene::airfoil_ref::BUNDLED_AIRFOILS
                            .iter()
                            .map(|(n, _)| *n)
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                );
            }
            Ok(AirfoilRef::Naca(_)) => self.airfoil_loads(path, text),
        }
    }

    /// The airfoil reads and resamples: a `.dat` file that holds no airfoil, or a NACA code
    /// without thickness (`NACA 0000`), is a problem at its key.
    fn airfoil_loads(&mut self, path: &str, text: &str) {
        match load_airfoil(text, self.files, self.airfoil_points_per_side) {
            Err(error) => self.fail(path, format!("= \"{text}\": {}", error.chain_message())),
            Ok(airfoil) => {
                if let Some(reason) = outline_defect(&airfoil.points) {
                    self.fail(path, format!("= \"{text}\": {reason}"));
                }
            }
        }
        if let Ok(AirfoilRef::Naca(digits)) = AirfoilRef::parse(text) {
            let thickness = digits
                .get(digits.len().saturating_sub(2)..)
                .and_then(|t| t.parse::<f64>().ok())
                .unwrap_or(0.0);
            if thickness > MAX_NACA_THICKNESS_PERCENT {
                self.fail(
                    path,
                    format!(
                        "= \"{text}\": {thickness} % thick; NACA sections here may be at most {MAX_NACA_THICKNESS_PERCENT} % thick (a thicker flap does not fit in the wing's cove)"
                    ),
                );
            }
        }
    }

    pub(super) fn wing(&mut self, wing: &WingScene) {
        self.point_within("wing.root_leading_edge_m", &wing.root_leading_edge_m);
        self.in_range(
            "wing.twist_axis_chord_fraction",
            wing.twist_axis_chord_fraction,
            0.0,
            1.0,
            false,
        );
        self.count_in("wing.sections", wing.sections.len(), 2, MAX_SECTIONS);
        if let Some(root) = wing.sections.first() {
            let y = wing.root_leading_edge_m[1];
            if y.is_finite() && root.y_m.is_finite() && (y - root.y_m).abs() > 1e-9 {
                self.fail(
                    "wing.root_leading_edge_m",
                    format!(
                        "has y = {y} m but the first section is at y_m = {} m: the root leading edge lies in the root section",
                        root.y_m
                    ),
                );
            }
        }
        if wing.sections.len() < 2 {
            self.fail(
                "wing.sections",
                format!("has {} section(s): a wing needs at least 2", wing.sections.len()),
            );
        }
        let mut previous_y: Option<f64> = None;
        for (i, section) in wing.sections.iter().enumerate() {
            let path = format!("wing.sections[{i}]");
            if self.in_range(&format!("{path}.y_m"), section.y_m, -MAX_SPAN_M, MAX_SPAN_M, false) {
                if let Some(prev) = previous_y {
                    if section.y_m <= prev {
                        self.fail(
                            format!("{path}.y_m"),
                            format!(
                                "= {}: sections must be in increasing spanwise order (previous y_m = {})",
                                super::number(section.y_m),
                                super::number(prev)
                            ),
                        );
                    }
                }
                previous_y = Some(section.y_m);
            }
            self.in_range(
                &format!("{path}.chord_m"),
                section.chord_m,
                MIN_CHORD_M,
                MAX_CHORD_M,
                false,
            );
            self.in_range(&format!("{path}.twist_deg"), section.twist_deg, -45.0, 45.0, false);
            self.airfoil(&format!("{path}.airfoil"), &section.airfoil);
        }
        if let (Some(first), Some(last)) = (wing.sections.first(), wing.sections.last()) {
            if wing.sections.len() >= 2 && first.y_m.is_finite() && last.y_m == first.y_m {
                self.fail("wing.sections", "zero span: first and last sections have the same y_m");
            }
            // Only for sections inside their own range (reported above): a typo there would
            // otherwise be reported twice.
            let in_range = |y: f64| y.abs() <= MAX_SPAN_M;
            if in_range(first.y_m) && in_range(last.y_m) && last.y_m - first.y_m > MAX_SPAN_M {
                self.fail(
                    format!("wing.sections[{}].y_m", wing.sections.len() - 1),
                    format!(
                        "= {}: the wing spans {} m from root to tip; at most {MAX_SPAN_M} m",
                        super::number(last.y_m),
                        super::number(last.y_m - first.y_m)
                    ),
                );
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

    /// `<path>.shroud_chord_fraction`, where given: the geometry's range.
    fn shroud(&mut self, path: &str, fraction: Option<f64>) {
        if let Some(shroud) = fraction {
            self.in_range(
                &format!("{path}.shroud_chord_fraction"),
                shroud,
                0.0,
                flapwright_geom::flap::MAX_SHROUD_CHORD_FRACTION,
                false,
            );
        }
    }

    /// A shroud over a flap cut out of the wing section: the flap fills the section to
    /// the upper skin at its nose, so no shroud clears it (the shroud's search for a length
    /// that clears ended at none, and the wing skin's outline folded onto itself: "polygon
    /// of 131 points cannot be triangulated" from the meshing stage). The flap needs its own
    /// section nested in the cove.
    fn shroud_needs_a_flap_section(&mut self, path: &str, flap: &FlapScene) {
        let Some(shroud) = flap
            .shroud_chord_fraction
            .filter(|shroud| *shroud > 0.0 && flap.airfoil.is_none())
        else {
            return;
        };
        self.fail(
            format!("{path}.shroud_chord_fraction"),
            format!(
                "= {}: a shroud needs the flap's own section nested in the cove, and {path}.airfoil is not given: a flap cut out of the wing section fills it up to the upper skin, so no shroud clears its nose; give {path}.airfoil (the wing's airfoil will do: it is scaled into the cove), or no shroud and overlaps of 0 or less",
                super::number(shroud)
            ),
        );
    }

    pub(super) fn flap(&mut self, path: &str, flap: &FlapScene, wing: &WingScene) {
        let (root, tip) = span_of(wing);
        let inboard_ok = self.in_range(&format!("{path}.y_inboard_m"), flap.y_inboard_m, root, tip, false);
        let outboard_ok = self.in_range(&format!("{path}.y_outboard_m"), flap.y_outboard_m, root, tip, false);
        if inboard_ok && outboard_ok && flap.y_outboard_m <= flap.y_inboard_m {
            self.fail(
                format!("{path}.y_outboard_m"),
                format!(
                    "= {}: must be greater than y_inboard_m = {}",
                    super::number(flap.y_outboard_m),
                    super::number(flap.y_inboard_m)
                ),
            );
        }
        for (key, value) in [
            ("chord_fraction_inboard", flap.chord_fraction_inboard),
            ("chord_fraction_outboard", flap.chord_fraction_outboard),
        ] {
            // The flap model's own range: below 2 % of the chord there is no flap to cut.
            let (min, max) = flapwright_geom::flap::FLAP_CHORD_FRACTION_RANGE;
            self.in_range(&format!("{path}.{key}"), value, min, max, false);
        }
        self.shroud(path, flap.shroud_chord_fraction);
        self.shroud_needs_a_flap_section(path, flap);
        if let Some(gap) = flap.side_gap_m {
            let quarter_span = 0.25 * (flap.y_outboard_m - flap.y_inboard_m).abs();
            self.in_range(&format!("{path}.side_gap_m"), gap, 0.0, quarter_span, false);
        }
        if let Some(airfoil) = &flap.airfoil {
            self.airfoil(&format!("{path}.airfoil"), airfoil);
        }
        if let Some(aft) = &flap.aft_element {
            let aft_path = format!("{path}.aft_element");
            if flap.airfoil.is_none() {
                self.fail(
                    aft_path.clone(),
                    "needs the flap's own section: give the flap an `airfoil` (a flap cut out of the wing section has no section of its own to nest the aft element in)".to_string(),
                );
            }
            self.airfoil(&format!("{aft_path}.airfoil"), &aft.airfoil);
            let (min, max) = flapwright_geom::flap::AFT_ELEMENT_CHORD_FRACTION_RANGE;
            self.in_range(
                &format!("{aft_path}.chord_fraction"),
                aft.chord_fraction,
                min,
                max,
                false,
            );
            self.shroud(&aft_path, aft.shroud_chord_fraction);
        }
        let hinge = &flap.hinge;
        let hinge_path = format!("{path}.hinge");
        match (hinge.inboard_point_m, hinge.outboard_point_m, hinge.chord_fraction) {
            (Some(a), Some(b), None) => {
                let ok_a = self.point_within(&format!("{hinge_path}.inboard_point_m"), &a);
                let ok_b = self.point_within(&format!("{hinge_path}.outboard_point_m"), &b);
                let length = ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
                if ok_a && ok_b && length < MIN_LENGTH_M {
                    self.fail(
                        hinge_path.clone(),
                        format!(
                            "axis has length {:.3} mm: the two points must be at least {} mm apart",
                            length * 1e3,
                            MIN_LENGTH_M * 1e3
                        ),
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
        for (key, target) in [
            ("takeoff_gap_percent", settings.takeoff_gap_percent),
            ("takeoff_overlap_percent", settings.takeoff_overlap_percent),
            ("landing_gap_percent", settings.landing_gap_percent),
            ("landing_overlap_percent", settings.landing_overlap_percent),
        ] {
            if let Some(value) = target {
                // Slotted flaps: gaps and overlaps of a few % chord (`003_...` 0-3 %).
                self.in_range(&format!("{path}.settings.{key}"), value, -20.0, 20.0, false);
            }
        }
        if let Some(value) = settings.sealed_gap_m {
            // A seal closes millimetres, not centimetres.
            self.in_range(&format!("{path}.settings.sealed_gap_m"), value, 0.0, 0.05, false);
        }
        if takeoff_ok && landing_ok && settings.takeoff_deg > settings.landing_deg {
            self.fail(
                format!("{path}.settings.takeoff_deg"),
                format!(
                    "= {}: must not exceed landing_deg = {}",
                    super::number(settings.takeoff_deg),
                    super::number(settings.landing_deg)
                ),
            );
        }
    }

    pub(super) fn structure(&mut self, scene: &Scene, wing: &WingScene) {
        let (root, tip) = span_of(wing);
        self.count_in("structure.spars", scene.structure.spars.len(), 0, MAX_SPARS);
        self.count_in("flap", scene.flap.len(), 0, MAX_FLAPS);
        self.count_in("station", scene.station.len(), 0, MAX_STATIONS);
        for (i, flap) in scene.flap.iter().enumerate() {
            if !scene
                .station
                .iter()
                .any(|s| s.flap.as_deref() == Some(flap.name.as_str()))
            {
                self.fail(
                    format!("flap[{i}]"),
                    format!(
                        "flap \"{}\" has no [[station]]: a flap needs at least one support station (station.flap = \"{}\")",
                        flap.name, flap.name
                    ),
                );
            }
        }
        let largest_chord = wing.sections.iter().map(|s| s.chord_m).fold(0.0, f64::max);
        for (i, spar) in scene.structure.spars.iter().enumerate() {
            let path = format!("structure.spars[{i}]");
            let fraction_ok = self.in_range(&format!("{path}.chord_fraction"), spar.chord_fraction, 0.0, 1.0, true);
            self.in_range(
                &format!("{path}.thickness_m"),
                spar.thickness_m,
                MIN_LENGTH_M,
                (0.1 * largest_chord).max(MIN_LENGTH_M),
                false,
            );
            let thickness_ok = spar.thickness_m.is_finite() && spar.thickness_m > 0.0;
            if fraction_ok && thickness_ok {
                // The web, centred on the chord fraction, must lie inside every section it
                // crosses; the smallest chord is the tightest.
                let smallest_chord = wing.sections.iter().map(|s| s.chord_m).fold(f64::INFINITY, f64::min);
                let half_web = 0.5 * spar.thickness_m / smallest_chord;
                if spar.chord_fraction - half_web < 0.0 || spar.chord_fraction + half_web > 1.0 {
                    self.fail(
                        format!("{path}.chord_fraction"),
                        format!(
                            "= {}: a {:.1} mm web centred there leaves the {:.3} m section; keep it in [{:.4}, {:.4}]",
                            super::number(spar.chord_fraction),
                            spar.thickness_m * 1e3,
                            smallest_chord,
                            half_web,
                            1.0 - half_web
                        ),
                    );
                }
            }
            let start_ok = self.in_range(&format!("{path}.y_start_m"), spar.y_start_m, root, tip, false);
            let end_ok = self.in_range(&format!("{path}.y_end_m"), spar.y_end_m, root, tip, false);
            if start_ok && end_ok && spar.y_end_m - spar.y_start_m < MIN_LENGTH_M {
                // A web shorter than the shortest length meshes into degenerate triangles.
                self.fail(
                    format!("{path}.y_end_m"),
                    format!(
                        "= {}: must be at least {} mm outboard of y_start_m = {}",
                        super::number(spar.y_end_m),
                        MIN_LENGTH_M * 1e3,
                        super::number(spar.y_start_m)
                    ),
                );
            }
            if !(fraction_ok && start_ok && end_ok && thickness_ok) {
                continue;
            }
            for flap in &scene.flap {
                // The geometry's rule: at both ends of the spar's stretch under the flap, the
                // web's aft face stays ahead of the cove wall, which stands
                // `COVE_GAP_CHORD_FRACTION` ahead of the flap's local chord fraction.
                let (a, b) = (
                    spar.y_start_m.max(flap.y_inboard_m),
                    spar.y_end_m.min(flap.y_outboard_m),
                );
                if a > b || flap.y_outboard_m.partial_cmp(&flap.y_inboard_m) != Some(std::cmp::Ordering::Greater) {
                    continue;
                }
                let mut tightest: Option<(f64, f64)> = None;
                for y in [a, b] {
                    let t = ((y - flap.y_inboard_m) / (flap.y_outboard_m - flap.y_inboard_m)).clamp(0.0, 1.0);
                    let fraction =
                        flap.chord_fraction_inboard + (flap.chord_fraction_outboard - flap.chord_fraction_inboard) * t;
                    let cove = 1.0 - fraction - flapwright_geom::flap::COVE_GAP_CHORD_FRACTION;
                    let Some(chord) = chord_at(wing, y).filter(|c| *c > 0.0) else {
                        continue;
                    };
                    let limit = cove - 0.5 * spar.thickness_m / chord;
                    if tightest.is_none_or(|(l, _)| limit < l) {
                        tightest = Some((limit, cove));
                    }
                }
                if let Some((limit, cove)) = tightest {
                    if spar.chord_fraction >= limit {
                        self.fail(
                            format!("{path}.chord_fraction"),
                            format!(
                                "= {}: the spar's web reaches into the cove of flap \"{}\" (cove wall at chord fraction {cove:.4}); must be < {limit:.4}",
                                super::number(spar.chord_fraction),
                                flap.name
                            ),
                        );
                    }
                }
            }
        }
        self.unique_names("structure.spars", scene.structure.spars.iter().map(|s| s.name.as_str()));
        if let Some(tube) = &scene.structure.torque_tube {
            let path = "structure.torque_tube";
            self.in_range(
                &format!("{path}.radius_m"),
                tube.radius_m,
                MIN_LENGTH_M,
                (0.25 * largest_chord).max(MIN_LENGTH_M),
                false,
            );
            match (&tube.path_m, tube.chord_fraction) {
                (Some(points), None) => self.tube_path(path, points),
                (None, Some(fraction)) => {
                    self.in_range(&format!("{path}.chord_fraction"), fraction, 0.0, 1.0, false);
                    if let Some(depth) = tube.depth_below_chord_fraction {
                        self.in_range(&format!("{path}.depth_below_chord_fraction"), depth, -0.5, 0.5, false);
                    }
                    let (root, tip) = span_of(wing);
                    let start = tube.y_start_m.unwrap_or(root);
                    let end = tube.y_end_m.unwrap_or_else(|| default_tube_end(scene, wing));
                    let start_ok = self.in_range(&format!("{path}.y_start_m"), start, root, tip, false);
                    let end_ok = self.in_range(&format!("{path}.y_end_m"), end, root, tip, false);
                    if start_ok && end_ok && end - start < MIN_LENGTH_M {
                        self.fail(
                            format!("{path}.y_end_m"),
                            format!(
                                "= {}: must lie outboard of the tube's start, y = {}",
                                super::number(end),
                                super::number(start)
                            ),
                        );
                    }
                }
                _ => self.fail(
                    path.to_string(),
                    "give the tube's axis either as path_m (points) or as chord_fraction (with depth_below_chord_fraction, y_start_m, y_end_m), not both",
                ),
            }
            if tube.path_m.is_some()
                && (tube.depth_below_chord_fraction.is_some() || tube.y_start_m.is_some() || tube.y_end_m.is_some())
            {
                self.fail(
                    path.to_string(),
                    "depth_below_chord_fraction, y_start_m and y_end_m go with chord_fraction, not with path_m",
                );
            }
        }
    }

    fn tube_path(&mut self, path: &str, points: &[[f64; 3]]) {
        self.count_in(&format!("{path}.path_m"), points.len(), 0, MAX_TORQUE_TUBE_POINTS);
        if points.len() < 2 {
            self.fail(
                format!("{path}.path_m"),
                format!("has {} point(s): needs at least 2", points.len()),
            );
        }
        for (i, point) in points.iter().enumerate() {
            self.point_within(&format!("{path}.path_m[{i}]"), point);
        }
        for (i, pair) in points.windows(2).enumerate() {
            let length = ((pair[1][0] - pair[0][0]).powi(2)
                + (pair[1][1] - pair[0][1]).powi(2)
                + (pair[1][2] - pair[0][2]).powi(2))
            .sqrt();
            if length < MIN_LENGTH_M {
                self.fail(
                    format!("{path}.path_m[{}]", i + 1),
                    format!(
                        "repeats the previous point: segments must be at least {} mm long",
                        MIN_LENGTH_M * 1e3
                    ),
                );
            }
        }
        // The mesher mitres each bend: a bend beyond the geometry's limit folds the tube.
        let direction = |a: &[f64; 3], b: &[f64; 3]| {
            let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let n = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            (n.is_finite() && n >= MIN_LENGTH_M).then(|| [d[0] / n, d[1] / n, d[2] / n])
        };
        let max_bend = flapwright_geom::structure::MAX_TUBE_BEND_DEG;
        for (i, triple) in points.windows(3).enumerate() {
            let (Some(u), Some(v)) = (direction(&triple[0], &triple[1]), direction(&triple[1], &triple[2])) else {
                continue;
            };
            let bend = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2])
                .clamp(-1.0, 1.0)
                .acos()
                .to_degrees();
            if bend > max_bend {
                self.fail(
                    format!("{path}.path_m[{}]", i + 1),
                    format!("bends the tube by {bend:.1} deg: at most {max_bend} deg at a point"),
                );
            }
        }
    }
}

/// A tube placed by chord fraction ends at the outermost flap's outboard end (the last
/// station it drives lies inside it), or at the tip without flaps.
pub(crate) fn default_tube_end(scene: &Scene, wing: &WingScene) -> f64 {
    scene
        .flap
        .iter()
        .map(|f| f.y_outboard_m)
        .fold(None, |end: Option<f64>, y| Some(end.map_or(y, |e| e.max(y))))
        .unwrap_or_else(|| span_of(wing).1)
}

/// The wing's chord at `y_m`, interpolated between its sections as the geometry does; none
/// outside the span.
fn chord_at(wing: &WingScene, y_m: f64) -> Option<f64> {
    wing.sections.windows(2).find_map(|pair| {
        let (a, b) = (&pair[0], &pair[1]);
        (a.y_m <= y_m && y_m <= b.y_m && b.y_m > a.y_m).then(|| {
            let t = (y_m - a.y_m) / (b.y_m - a.y_m);
            a.chord_m + (b.chord_m - a.chord_m) * t
        })
    })
}

/// Thickest NACA section accepted, % of the chord: the thickest sections flown are about
/// 21 % (NACA 0021), and a section past 40 % is no longer a wing or flap the geometry can
/// nest (`NACA 9999` as a flap cut a wing skin that could not be meshed).
pub const MAX_NACA_THICKNESS_PERCENT: f64 = 40.0;

/// Why an airfoil's outline (unit chord, Selig order) cannot be meshed, if it cannot: two
/// edges that cross (a self-crossing polygon has no triangulation).
fn outline_defect(points: &[nalgebra::Point2<f64>]) -> Option<String> {
    let n = points.len();
    // The outline closes from the last point back to the first unless they coincide.
    let closed = n > 1 && points[0] == points[n - 1];
    let edges: Vec<(usize, usize)> = (0..n.saturating_sub(1))
        .map(|i| (i, i + 1))
        .chain((!closed && n > 2).then_some((n - 1, 0)))
        .collect();
    for (a, &(i0, i1)) in edges.iter().enumerate() {
        for &(j0, j1) in &edges[a + 1..] {
            let shares = |k: usize| points[k] == points[i0] || points[k] == points[i1];
            if shares(j0) || shares(j1) {
                continue;
            }
            if segments_cross(points[i0], points[i1], points[j0], points[j1]) {
                return Some(format!(
                    "the outline crosses itself (the edge from point {} to {} crosses the edge from point {} to {}, resampled): an airfoil must be a simple closed outline",
                    i0 + 1,
                    i1 + 1,
                    j0 + 1,
                    j1 + 1
                ));
            }
        }
    }
    None
}

/// Whether segments ab and cd cross (each one's ends strictly on both sides of the other).
fn segments_cross(
    a: nalgebra::Point2<f64>,
    b: nalgebra::Point2<f64>,
    c: nalgebra::Point2<f64>,
    d: nalgebra::Point2<f64>,
) -> bool {
    let orient = |p: nalgebra::Point2<f64>, q: nalgebra::Point2<f64>, r: nalgebra::Point2<f64>| (q - p).perp(&(r - p));
    let (d1, d2) = (orient(c, d, a), orient(c, d, b));
    let (d3, d4) = (orient(a, b, c), orient(a, b, d));
    (d1 * d2 < 0.0) && (d3 * d4 < 0.0)
}

pub(crate) fn span_of(wing: &WingScene) -> (f64, f64) {
    let root = wing.sections.first().map_or(0.0, |s| s.y_m);
    let tip = wing.sections.last().map_or(0.0, |s| s.y_m);
    (root, tip)
}
