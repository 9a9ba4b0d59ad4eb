//! Checks every kind synthesised from the flap settings makes of a candidate loop over its
//! deployment, and the inverse of a loop's monotone deflection: written once for the
//! four-bar, the link-track and what comes after them.

use nalgebra::{Isometry2, Point2};

use crate::error::SynthesisDefect;
use crate::shared::outline::StationOutline;

/// A candidate loop at one sample of its deployment.
#[derive(Debug, Clone, Copy)]
pub struct LoopSample {
    /// The driving link's turn from stowed (rad): named in messages.
    pub turn_rad: f64,
    /// The flap's displacement from stowed.
    pub flap: Isometry2<f64>,
    /// The loop's transmission angle (rad).
    pub transmission_rad: f64,
    /// The flap's rotation rate per unit turn of the driving link.
    pub flap_rate: f64,
}

/// What the loop must keep over the deployment.
pub struct DeploymentRules<'a> {
    /// The station's sections.
    pub outline: &'a StationOutline,
    /// Smallest transmission angle (rad).
    pub min_transmission_rad: f64,
    /// Fixed pivots the moving flap must not pass over.
    pub fixed_pivots: &'a [Point2<f64>],
    /// Sign of the landing deflection.
    pub deflection_sense: f64,
    /// Sign of the driving link's turn to landing.
    pub turn_sense: f64,
    /// The driving link's name in messages ("crank", "link").
    pub driver: &'static str,
    /// True for a kind that may hold the flap's deflection while it moves it (the
    /// hooked-track's lead-in translates it): a zero rotation rate is then no defect, a
    /// negative one still is.
    pub may_dwell: bool,
}

/// The smallest transmission angle over `samples` (the stowed one first), or the first
/// defect: a loop that cannot close (no real solution), the transmission angle below the
/// minimum (toggle), the flap turning back (order), and only then, once the whole
/// deployment closes in order, the flap through or within the lip clearance of the wing's
/// trailing edge or over a fixed pivot (region).
///
/// The motion's own tests come first because they cost a few comparisons a sample, the
/// section queries of the region test a few hundred edge tests: most candidates a search
/// rejects fail in their motion (on the transport scene's outboard station, 23 000 of the
/// hooked-track's 24 000 sampled rails), and they are rejected without a section query.
pub fn check_deployment(
    rules: &DeploymentRules,
    samples: impl IntoIterator<Item = Option<LoopSample>>,
) -> Result<f64, (SynthesisDefect, String)> {
    let driver = rules.driver;
    let mut min_transmission = f64::INFINITY;
    let mut previous = 0.0;
    let mut closed = Vec::new();
    for (k, sample) in samples.into_iter().enumerate() {
        let Some(sample) = sample else {
            return Err((SynthesisDefect::NoRealSolution, "the loop cannot close part way".into()));
        };
        let at = sample.turn_rad.to_degrees();
        min_transmission = min_transmission.min(sample.transmission_rad);
        if min_transmission < rules.min_transmission_rad {
            return Err((
                SynthesisDefect::Toggle,
                format!(
                    "the transmission angle falls to {:.1} deg at {at:.1} deg of {driver} (minimum {:.1} deg)",
                    sample.transmission_rad.to_degrees(),
                    rules.min_transmission_rad.to_degrees()
                ),
            ));
        }
        // The flap must turn forwards at every sample, the start included: a flap that
        // first turns back reaches its stowed deflection twice.
        let deflection = sample.flap.rotation.angle();
        let rate = sample.flap_rate * rules.turn_sense * rules.deflection_sense;
        let forwards = rate > 0.0 || (rules.may_dwell && rate == 0.0);
        if !forwards || (k > 0 && (deflection - previous) * rules.deflection_sense < 0.0) {
            return Err((SynthesisDefect::BranchOrOrder, "the flap turns back part way".into()));
        }
        previous = deflection;
        closed.push(sample);
    }
    // A zero gap at a setting touches the lip to within rounding (1e-6 of the chord).
    let lip_tolerance = 1e-6 * rules.outline.chord_m().unwrap_or(1.0);
    for sample in &closed {
        let at = sample.turn_rad.to_degrees();
        if rules.outline.flap_near_lip(&sample.flap, lip_tolerance) {
            return Err((
                SynthesisDefect::PivotOutsideRegion,
                format!(
                    "the flap passes through or within {:.1} mm of the wing's trailing edge at {at:.1} deg of {driver}",
                    1e3 * rules.outline.lip_clearance_m,
                ),
            ));
        }
        let back = sample.flap.inverse();
        if rules.fixed_pivots.iter().any(|p| rules.outline.flap.inside(back * p)) {
            return Err((
                SynthesisDefect::PivotOutsideRegion,
                format!("the flap passes over a fixed pivot at {at:.1} deg of {driver}"),
            ));
        }
    }
    Ok(min_transmission)
}

/// The parameter in [0, `end`] where the monotone `deflection` reaches `target` (rad), by
/// bisection to rounding; the nearer end when `target` lies outside the range.
/// `sense` is the sign of the deflection's change from 0 to `end`.
pub fn parameter_at_deflection(end: f64, deflection: impl Fn(f64) -> f64, target: f64, sense: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, end);
    if (target - deflection(hi)) * sense >= 0.0 {
        return hi;
    }
    if (target - deflection(lo)) * sense <= 0.0 {
        return lo;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if (deflection(mid) - target) * sense < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
        if (hi - lo).abs() < 1e-15 {
            break;
        }
    }
    0.5 * (lo + hi)
}

/// The flap chord of a synthesis's station, after checking its settings are finite: the
/// first step of every kind synthesised from the flap settings. Errors: a setting that is
/// not finite, or no flap section, as [`SynthesisDefect::MissingPositions`] with `detail`.
pub fn settings_and_flap_chord(
    positions: &[crate::shared::precision::PrecisionPosition],
    outline: &StationOutline,
) -> Result<f64, (SynthesisDefect, String)> {
    let finite = |p: &crate::shared::precision::PrecisionPosition| {
        p.deflection_rad.is_finite() && p.flap.translation.vector.iter().all(|v| v.is_finite())
    };
    if !positions.iter().all(finite) {
        return Err((SynthesisDefect::MissingPositions, "a setting is not finite".into()));
    }
    outline.flap_chord().map(|(_, _, chord)| chord).ok_or((
        SynthesisDefect::MissingPositions,
        "the station has no flap section".into(),
    ))
}
