//! The four-bar's free-choice search: moving-pivot candidates on a grid under the flap,
//! each with the fixed pivot through its three positions, and the pairs that move the flap
//! through the precision positions on one branch, in order, above the minimum transmission
//! angle and clear of the sections. Every rejection is counted ([`FourBarSearch`]).

use nalgebra::Point2;

use super::linkage::Loop;
use super::{failure, mm, FourBarSearch, FourBarSpec, LOOP_SAMPLES};
use flapwright_mechanism::shared::feasibility::{check_deployment, DeploymentRules, LoopSample};
use flapwright_mechanism::shared::geometry::cross;
use flapwright_mechanism::shared::geometry::turn_angle;
use flapwright_mechanism::shared::precision::{circle_centre, PrecisionPosition};
use flapwright_mechanism::{Error, SynthesisDefect};

/// Grid of moving-pivot candidates: columns along the flap chord, rows below it.
const GRID_COLUMNS: usize = 14;
const GRID_ROWS: usize = 9;
/// Largest link rotation between stowed and landing (rad).
const MAX_LINK_ROTATION_RAD: f64 = 150.0 * std::f64::consts::PI / 180.0;

/// One moving-pivot candidate with its fixed pivot and its link's turns.
#[derive(Debug, Clone, Copy)]
pub(super) struct Candidate {
    pub(super) moving: Point2<f64>,
    pub(super) fixed: Point2<f64>,
    pub(super) turns: [f64; 2],
}

pub(super) fn search_failure(search: &FourBarSearch) -> Error {
    let detail = format!(
        "no four-bar found: of {} moving-pivot candidates under the flap, {} have no circle, {} a fixed pivot outside the region (inside a section or above its lower surface), {} turn back or too far; of {} pairs, {} change branch, {} fall below the minimum transmission angle, {} cut the wing",
        search.candidates,
        search.no_circle,
        search.pivot_outside_region,
        search.order_defect,
        search.pairs,
        search.branch_change,
        search.toggle,
        search.link_in_wing
    );
    let defect = if search.pairs == 0 {
        if search.pivot_outside_region >= search.no_circle.max(search.order_defect) {
            SynthesisDefect::PivotOutsideRegion
        } else if search.order_defect >= search.no_circle {
            SynthesisDefect::BranchOrOrder
        } else {
            SynthesisDefect::NoRealSolution
        }
    } else if search.toggle >= search.branch_change {
        SynthesisDefect::Toggle
    } else {
        SynthesisDefect::BranchOrOrder
    };
    failure(defect, detail)
}

/// The moving-pivot grid: columns from the flap's leading edge to 90 % of its chord, rows
/// from 4 % to 60 % of the flap chord below its lower surface.
pub(super) fn candidates(spec: &FourBarSpec, search: &mut FourBarSearch, chord: f64) -> Vec<Candidate> {
    let Some((le, _, flap_chord)) = spec.outline.flap_chord() else {
        return Vec::new();
    };
    let mut found = Vec::new();
    for i in 0..GRID_COLUMNS {
        let x = le - flap_chord * (0.02 + 0.88 * i as f64 / (GRID_COLUMNS - 1) as f64);
        let Some((lo, _)) = spec.outline.flap.vertical_span(x) else {
            continue;
        };
        for j in 0..GRID_ROWS {
            // Below the flap's lower surface, on brackets: a pivot inside the flap would
            // put its link and the screw's nut through the flap.
            let y = lo - flap_chord * (0.04 + 0.56 * j as f64 / (GRID_ROWS - 1) as f64);
            search.candidates += 1;
            match candidate(spec, Point2::new(x, y), chord) {
                Ok(c) => found.push(c),
                Err((SynthesisDefect::NoRealSolution, _)) => search.no_circle += 1,
                Err((SynthesisDefect::BranchOrOrder, _)) => search.order_defect += 1,
                Err(_) => search.pivot_outside_region += 1,
            }
        }
    }
    found
}

/// A moving pivot's fixed pivot and turns, or why it cannot be one.
pub(super) fn candidate(
    spec: &FourBarSpec,
    moving: Point2<f64>,
    chord: f64,
) -> std::result::Result<Candidate, (SynthesisDefect, String)> {
    let outline = &spec.outline;
    let positions = [moving, spec.takeoff.flap * moving, spec.landing.flap * moving];
    if positions.iter().any(|p| outline.wing.inside(*p)) {
        return Err((
            SynthesisDefect::PivotOutsideRegion,
            "the moving pivot enters the wing section".into(),
        ));
    }
    let fixed = circle_centre(positions[0], positions[1], positions[2])
        .filter(|o| (o - moving).norm() <= 3.0 * chord)
        .ok_or((
            SynthesisDefect::NoRealSolution,
            "its three positions lie on a line or a circle larger than three chords".to_string(),
        ))?;
    let below = outline.lower_envelope(fixed.x).is_some_and(|y| fixed.y < y);
    let clear = !outline.wing.inside(fixed)
        && [PrecisionPosition::stowed(), spec.takeoff, spec.landing]
            .iter()
            .all(|position| !outline.flap.inside(position.flap.inverse() * fixed));
    if !(below && clear) {
        return Err((
            SynthesisDefect::PivotOutsideRegion,
            format!(
                "its fixed pivot {} is not below the wing and clear of the flap",
                mm(fixed)
            ),
        ));
    }
    let turns = [
        turn_angle(fixed, positions[0], positions[1]),
        turn_angle(fixed, positions[0], positions[2]),
    ];
    let ordered =
        turns[0] * turns[1] > 0.0 && turns[0].abs() < turns[1].abs() && turns[1].abs() <= MAX_LINK_ROTATION_RAD;
    if !ordered {
        return Err((
            SynthesisDefect::BranchOrOrder,
            format!(
                "its link turns {:.1} deg to take-off and {:.1} deg to landing: the settings are not reached in order",
                turns[0].to_degrees(),
                turns[1].to_degrees()
            ),
        ));
    }
    Ok(Candidate { moving, fixed, turns })
}

/// The loop of two candidates if it moves through the three positions on one branch, above
/// the minimum transmission angle, with links clear of the wing at the settings; with its
/// sampled minimum transmission angle.
pub(super) fn check_pair(
    spec: &FourBarSpec,
    crank: &Candidate,
    rocker: &Candidate,
) -> std::result::Result<(Loop, f64), (SynthesisDefect, String)> {
    // A square mount at a finite distance loses a few degrees at the ends: keep 10 deg.
    let drivable = std::f64::consts::PI - 2.0 * spec.min_transmission_angle_rad - 10f64.to_radians();
    if crank.turns[1].abs() > drivable {
        return Err((
            SynthesisDefect::Toggle,
            format!(
                "its crank turns {:.1} deg: a screw cannot turn it that far above the minimum transmission angle ({:.1} deg at most)",
                crank.turns[1].abs().to_degrees(),
                drivable.to_degrees()
            ),
        ));
    }
    let loop_ = Loop::new(crank.fixed, rocker.fixed, crank.moving, rocker.moving);
    let positions = [spec.takeoff, spec.landing];
    for position in positions {
        let (a1, a2) = (position.flap * loop_.a1, position.flap * loop_.a2);
        if cross(loop_.o2 - a1, a2 - a1).signum() != loop_.branch {
            return Err((
                SynthesisDefect::BranchOrOrder,
                "the loop changes branch between settings".into(),
            ));
        }
        for (fixed, moving) in [(loop_.o1, a1), (loop_.o2, a2)] {
            if spec.outline.wing.segment_meets(fixed, moving) {
                return Err((
                    SynthesisDefect::PivotOutsideRegion,
                    "a link cuts the wing section".into(),
                ));
            }
        }
    }
    let rules = DeploymentRules {
        outline: &spec.outline,
        min_transmission_rad: spec.min_transmission_angle_rad,
        fixed_pivots: &[loop_.o1, loop_.o2],
        deflection_sense: spec.landing.deflection_rad.signum(),
        turn_sense: crank.turns[1].signum(),
        driver: "crank",
        may_dwell: false,
    };
    let samples = (0..=LOOP_SAMPLES).map(|k| {
        let phi = crank.turns[1] * k as f64 / LOOP_SAMPLES as f64;
        loop_.at(phi).map(|pose| LoopSample {
            turn_rad: phi,
            flap: pose.flap,
            transmission_rad: pose.transmission,
            flap_rate: loop_.rates(&pose).1,
        })
    });
    let min_transmission = check_deployment(&rules, samples)?;
    Ok((loop_, min_transmission))
}
