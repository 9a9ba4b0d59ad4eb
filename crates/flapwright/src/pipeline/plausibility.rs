//! Plausibility of the placed stations: inputs that pass every per-key rule but put a
//! station, the hinge line or the torque tube where no flap mechanism can be. Each is an
//! input problem naming the keys that decide it (exit 2), found as soon as the planes are
//! cut and before any costly stage runs.
//!
//! The rules, in the station frame (x towards the nose, y up, origin A0 on the hinge line):
//! - A0 lies within its flap's span (`[[flap]] y_inboard_m..y_outboard_m`);
//! - the station plane cuts its flap;
//! - A0 lies within [`MAX_HINGE_DISTANCE_FLAP_CHORDS`] flap chords of the stowed flap
//!   section's bounding box: a dropped hinge sits below the flap, not metres ahead of it;
//! - where the torque tube crosses the plane, its centre lies within the same distance of the
//!   wing and flap section's bounding box (a tube may run in the cove or below the flap's
//!   nose, not ahead of the leading edge or above the wing).

use nalgebra::Point2;

use crate::pipeline::record::StationRecord;
use crate::scene::{Problem, Scene};

/// Largest distance from A0 (the hinge point) to the stowed flap section's bounding box, in
/// local flap chords. Dropped hinges and virtual hinges of tracks lie within about half a
/// flap chord of the flap (thesis Fig. 45: 0.6 c_f below the flap chord line); one chord
/// leaves room for unusual layouts and rejects hinges ahead of the wing box.
pub const MAX_HINGE_DISTANCE_FLAP_CHORDS: f64 = 1.0;

/// Bounding box (min, max) of `polygons`, or `None` when they hold no point.
fn bounds(polygons: &[Vec<Point2<f64>>]) -> Option<(Point2<f64>, Point2<f64>)> {
    polygons.iter().flatten().fold(None, |acc, p| {
        Some(match acc {
            None => (*p, *p),
            Some((lo, hi)) => (lo.inf(p), hi.sup(p)),
        })
    })
}

/// The problems of every placed station (empty when all are plausible).
pub fn station_problems(scene: &Scene, records: &[StationRecord]) -> Vec<Problem> {
    let mut problems = Vec::new();
    for record in records {
        let (i, station) = (record.index, record);
        let Some(place) = &record.placed else {
            continue;
        };
        let Some((k, flap)) = scene
            .flap
            .iter()
            .enumerate()
            .find(|(_, f)| Some(&f.name) == record.flap.as_ref())
        else {
            continue;
        };
        let offset_key = format!("station[{i}].axis_offset_m");
        let a0_y = place.station.frame.origin_ac().y;
        if !(flap.y_inboard_m..=flap.y_outboard_m).contains(&a0_y) {
            let other = scene
                .flap
                .iter()
                .find(|f| (f.y_inboard_m..=f.y_outboard_m).contains(&a0_y))
                .map_or(String::new(), |f| format!(" (on flap \"{}\")", f.name));
            problems.push(Problem::new(
                offset_key,
                format!(
                    "puts the station's hinge point A0 at y = {a0_y:.3} m{other}, outside flap \"{}\" (y from {} to {} m): the offset is measured along the hinge line from the flap's inboard end",
                    flap.name, flap.y_inboard_m, flap.y_outboard_m
                ),
            ));
            continue;
        }
        let flap_section = place.flap_polygons(&flap.name);
        let Some((lo, hi)) = bounds(&flap_section) else {
            problems.push(Problem::new(
                offset_key,
                format!(
                    "the plane of station \"{}\" does not cut flap \"{}\"",
                    station.station, flap.name
                ),
            ));
            continue;
        };
        let flap_chord_m = hi.x - lo.x;
        // Distance from A0 (the origin) to the box: per axis, how far the box lies beyond it.
        let hinge_distance_m = (Point2::origin().sup(&lo) - Point2::origin().inf(&hi)).norm();
        if hinge_distance_m > MAX_HINGE_DISTANCE_FLAP_CHORDS * flap_chord_m {
            problems.push(Problem::new(
                format!("flap[{k}].hinge"),
                format!(
                    "the hinge line passes {:.0} mm from flap \"{}\" at station \"{}\" (at most {MAX_HINGE_DISTANCE_FLAP_CHORDS} flap chord, {:.0} mm): the mechanism would stand {}",
                    hinge_distance_m * 1e3,
                    flap.name,
                    station.station,
                    MAX_HINGE_DISTANCE_FLAP_CHORDS * flap_chord_m * 1e3,
                    if lo.x > 0.0 {
                        "behind the flap"
                    } else if hi.x < 0.0 {
                        "ahead of the flap"
                    } else {
                        "far above or below the flap"
                    }
                ),
            ));
        }
        let tube = place.polygons_of(|name| name == "torque-tube");
        let section = place.polygons_of(|name| name == "wing" || name == flap.name);
        if let (Some((tube_lo, tube_hi)), Some((lo, hi))) = (bounds(&tube), bounds(&section)) {
            let centre = nalgebra::center(&tube_lo, &tube_hi);
            let distance_m = (centre.sup(&lo) - centre.inf(&hi)).norm();
            if distance_m > MAX_HINGE_DISTANCE_FLAP_CHORDS * flap_chord_m {
                problems.push(Problem::new(
                    "structure.torque_tube.path_m",
                    format!(
                        "the torque tube crosses the plane of station \"{}\" {:.0} mm outside the wing and flap section (at most {MAX_HINGE_DISTANCE_FLAP_CHORDS} flap chord, {:.0} mm), at {:.0} mm ahead of and {:.0} mm above A0",
                        station.station,
                        distance_m * 1e3,
                        MAX_HINGE_DISTANCE_FLAP_CHORDS * flap_chord_m * 1e3,
                        centre.x * 1e3,
                        centre.y * 1e3
                    ),
                ));
            }
        }
    }
    problems
}

/// A fairing deeper than this share of the local flap chord is warned about: deeper
/// fairings cost more drag than the flap gains (`003_...` Table 1: 9-26 % of the flap chord).
pub const MAX_PLAUSIBLE_FAIRING_PERCENT_FLAP_CHORD: f64 = 50.0;

/// Gap and overlap of slotted flaps lie within this band, % of the local chord (`003_...`
/// section 2.1: B777 settings 0-3 %; VFW-614 likewise).
pub const PLAUSIBLE_GAP_OVERLAP_PERCENT_CHORD: (f64, f64) = (0.0, 3.0);

/// A take-off or landing gap or overlap farther than this outside
/// [`PLAUSIBLE_GAP_OVERLAP_PERCENT_CHORD`] is warned about, % of the local chord.
pub const GAP_OVERLAP_WARNING_MARGIN_PERCENT_CHORD: f64 = 5.0;

/// Warnings for a fairing deeper than [`MAX_PLAUSIBLE_FAIRING_PERCENT_FLAP_CHORD`].
pub fn fairing_warning(station: &str, fairing: &flapwright_interference::FairingDepth) -> Option<String> {
    (fairing.depth_percent_flap_chord > MAX_PLAUSIBLE_FAIRING_PERCENT_FLAP_CHORD).then(|| {
        format!(
            "station {station}: fairing {:.0} mm deep ({:.0} % of the flap chord, more than {MAX_PLAUSIBLE_FAIRING_PERCENT_FLAP_CHORD} %), set by {} at {:.1} % of the deployment",
            fairing.depth_m * 1e3,
            fairing.depth_percent_flap_chord,
            fairing.part.as_deref().unwrap_or("?"),
            100.0 * fairing.at_parameter
        )
    })
}

/// A take-off or landing gap or overlap that misses the scene's target by more than this,
/// % of the local chord, is warned about (half a per cent of the chord: about what a
/// rigging tolerance allows, a sixth of the 0-3 % band of `003_...`).
pub const TARGET_TOLERANCE_PERCENT_CHORD: f64 = 0.5;

/// Warnings for take-off and landing gaps and overlaps that miss the scene's targets, or
/// without targets lie far outside the usual settings.
pub fn gap_overlap_warnings(station: &str, position: &crate::pipeline::record::FlapPositionReport) -> Vec<String> {
    let (low, high) = PLAUSIBLE_GAP_OVERLAP_PERCENT_CHORD;
    let margin = GAP_OVERLAP_WARNING_MARGIN_PERCENT_CHORD;
    let mut warnings = Vec::new();
    for setting in position.settings.iter().filter(|s| s.setting != "stowed") {
        let (gap, overlap) = (
            setting.position.gap_percent_chord,
            setting.position.overlap_percent_chord,
        );
        let (gap_miss, overlap_miss) = setting.misses();
        if gap_miss.is_some() || overlap_miss.is_some() {
            let missed = |miss: Option<f64>| miss.is_some_and(|m| m.abs() > TARGET_TOLERANCE_PERCENT_CHORD);
            if missed(gap_miss) || missed(overlap_miss) {
                let describe = |what: &str, value: f64, target: Option<f64>| {
                    target.map_or(format!("{what} {value:.1} %"), |t| {
                        format!("{what} {value:.1} % (target {t:.1} %)")
                    })
                };
                warnings.push(format!(
                    "station {station}: {} at {:.1} deg misses its targets by more than {TARGET_TOLERANCE_PERCENT_CHORD} % of the local chord: {}, {}",
                    setting.setting,
                    setting.deflection_deg,
                    describe("gap", gap, setting.target_gap_percent_chord),
                    describe("overlap", overlap, setting.target_overlap_percent_chord)
                ));
            }
            continue;
        }
        let far = |value: f64| value < low - margin || value > high + margin;
        if far(gap) || far(overlap) {
            warnings.push(format!(
                "station {station}: {} at {:.1} deg has gap {gap:.1} % and overlap {overlap:.1} % of the local chord, more than {margin} % outside the usual {low}-{high} % of slotted flaps",
                setting.setting, setting.deflection_deg
            ));
        }
    }
    warnings
}

/// Where a failing pair is a flap against the wing at one of the flap's sides (the contact
/// on the wing within the overlap's depth and a centimetre of the flap's cut-out
/// `y_inboard_m` or `y_outboard_m`): the flap's side moved spanwise past its side gap as it
/// deployed (a hinge line not square to the streamwise sides, or a conical motion, moves
/// them). Says which side and the `side_gap_m` that would keep the required clearance
/// there: the gap now plus the depth (below the certified clearance, the smallest found
/// less the check's residual bound) plus the clearance, rounded up to the millimetre.
pub fn side_gap_hints(
    scene: &Scene,
    model: &flapwright_geom::parts::WingModel,
    pairs: &[flapwright_interference::PairResult],
) -> Vec<String> {
    let mut hints = Vec::new();
    for pair in pairs.iter().filter(|p| !p.passes) {
        let c = &pair.clearance;
        let (flap_name, wing_point) = match (c.part_a.as_str(), c.part_b.as_str()) {
            (a, "wing") => (a, c.point_b_ac),
            ("wing", b) => (b, c.point_a_ac),
            _ => continue,
        };
        let Some((f, flap)) = scene.flap.iter().enumerate().find(|(_, f)| f.name == flap_name) else {
            continue;
        };
        // What the check can certify: the smallest clearance found less what may lie
        // between its evaluations (a pair left uncertain fails too).
        let certified = (c.min_clearance_m - c.residual_bound_m).max(0.0);
        let depth = c.penetration_m.max(0.0) + (pair.required_clearance_m - certified).max(0.0);
        let reach = depth + 0.01;
        let y = wing_point[1];
        let side = if (y - flap.y_inboard_m).abs() <= reach {
            Some(("inboard", flap.y_inboard_m))
        } else if (y - flap.y_outboard_m).abs() <= reach {
            Some(("outboard", flap.y_outboard_m))
        } else {
            None
        };
        let Some((side, cut_y)) = side else {
            continue;
        };
        let gap_now = match flap.side_gap_m {
            Some(gap) => gap,
            None => match model.wing().planform_at(cut_y) {
                Ok((_, chord, _)) => flapwright_geom::flap::SIDE_GAP_CHORD_FRACTION * chord,
                Err(_) => continue,
            },
        };
        let needed = ((gap_now + depth + pair.required_clearance_m) * 1e3).ceil() / 1e3;
        hints.push(format!(
            "flap \"{}\": its {side} side comes {:.1} mm past the required clearance at its cut-out (y = {:.3} m) as it deploys, the side gap of {:.3} m{} being too small for how far the flap moves spanwise; give flap[{f}].side_gap_m = {needed:.3} or more",
            flap.name,
            1e3 * depth,
            cut_y,
            gap_now,
            if flap.side_gap_m.is_none() { " (the default, 0.5 % of the local chord)" } else { "" },
        ));
    }
    hints
}

#[cfg(test)]
mod tests {
    use super::*;
    use flapwright_interference::FairingDepth;

    fn fairing(depth_percent_flap_chord: f64) -> FairingDepth {
        FairingDepth {
            depth_m: 0.005 * depth_percent_flap_chord,
            depth_percent_flap_chord,
            part: Some("inner.screw".into()),
            at_parameter: 0.5,
            point_st: [0.0, -0.1],
            length_m: 0.6,
            length_percent_flap_chord: 120.0,
        }
    }

    #[test]
    fn a_fairing_deeper_than_half_the_flap_chord_is_warned_about_with_its_numbers() {
        assert_eq!(fairing_warning("inner", &fairing(49.9)), None);
        let warning = fairing_warning("inner", &fairing(110.0)).unwrap();
        assert!(
            warning.contains("station inner: fairing 550 mm deep (110 % of the flap chord")
                && warning.contains("inner.screw at 50.0 % of the deployment"),
            "{warning}"
        );
    }
}
