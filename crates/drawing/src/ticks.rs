//! "Nice" axis ticks: steps of 1, 2 or 5 times a power of ten.
//!
//! The classic rule (Heckbert, "Nice numbers for graph labels", Graphics Gems, 1990):
//! divide the span by the wanted tick count and round the quotient up to the next
//! 1/2/5 x 10^k, so there are never more ticks than asked for (plus one).

/// Tick positions along one axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Ticks {
    /// Lower end of the axis (a multiple of `step`, <= the data minimum).
    pub axis_min: f64,
    /// Upper end of the axis (a multiple of `step`, >= the data maximum).
    pub axis_max: f64,
    /// Distance between ticks (1, 2 or 5 times a power of ten).
    pub step: f64,
    /// Tick values from `axis_min` to `axis_max` inclusive.
    pub values: Vec<f64>,
}

/// The smallest step of the form {1, 2, 5} x 10^k that is >= `span / target_count`.
///
/// `span` must be finite and > 0 and `target_count` >= 1; otherwise 1.0 is returned
/// (a safe default for degenerate axes, which [`nice_ticks`] widens first).
///
/// ```
/// assert_eq!(flapwright_drawing::nice_step(144.3, 6), 50.0);
/// assert_eq!(flapwright_drawing::nice_step(1.0, 5), 0.2);
/// ```
pub fn nice_step(span: f64, target_count: usize) -> f64 {
    if !(span.is_finite() && span > 0.0) || target_count == 0 {
        return 1.0;
    }
    let raw = span / target_count as f64;
    let magnitude = 10f64.powf(raw.log10().floor());
    let normalised = raw / magnitude;
    // A little slack so that e.g. 0.2 / 1 does not round up to 0.5 by representation error.
    let slack = 1.0 + 1e-9;
    let factor = if normalised <= slack {
        1.0
    } else if normalised <= 2.0 * slack {
        2.0
    } else if normalised <= 5.0 * slack {
        5.0
    } else {
        10.0
    };
    factor * magnitude
}

/// Nice ticks covering `[min, max]` with about `target_count` intervals.
///
/// A zero span (constant data) is widened to +-10 % of the value (or +-1 around zero)
/// so that the axis still has ticks. Non-finite input gives the axis 0..1.
pub fn nice_ticks(min: f64, max: f64, target_count: usize) -> Ticks {
    let (mut low, mut high) = if min.is_finite() && max.is_finite() {
        (min.min(max), min.max(max))
    } else {
        (0.0, 1.0)
    };
    if high - low <= f64::EPSILON * high.abs().max(low.abs()).max(1.0) {
        let pad = if low.abs() > 0.0 { 0.1 * low.abs() } else { 1.0 };
        low -= pad;
        high += pad;
    }
    let step = nice_step(high - low, target_count.max(1));
    // The tolerance keeps a value that is a multiple of the step up to rounding (0.0,
    // 35.000000001) from gaining an extra, empty interval.
    let axis_min = (low / step + 1e-9).floor() * step;
    let axis_max = (high / step - 1e-9).ceil() * step;
    let count = ((axis_max - axis_min) / step).round() as usize;
    let values = (0..=count)
        .map(|i| {
            let v = axis_min + i as f64 * step;
            // Snap values that are zero up to rounding to an exact zero ("-0.0" never shows).
            if v.abs() < step * 1e-9 {
                0.0
            } else {
                v
            }
        })
        .collect();
    Ticks {
        axis_min,
        axis_max,
        step,
        values,
    }
}

/// Ticks for a chart axis: the axis spans the data plus `pad_fraction` of its span on
/// each side (so no line runs along the frame), and the ticks are the multiples of a
/// nice step (1/2/5 x 10^k, the one giving the interval count closest to
/// `target_count`) inside that range, at least two of them.
///
/// Degenerate and non-finite data are handled as in [`nice_ticks`].
pub fn padded_ticks(min: f64, max: f64, target_count: usize, pad_fraction: f64) -> Ticks {
    let widened = nice_ticks(min, max, target_count);
    let (low, high) = if min.is_finite() && max.is_finite() && (max - min).abs() > 0.0 {
        (min.min(max), min.max(max))
    } else {
        // Constant or invalid data: keep the widened nice range.
        return widened;
    };
    let pad = pad_fraction.max(0.0) * (high - low);
    let (axis_min, axis_max) = (low - pad, high + pad);
    let target = target_count.max(1) as f64;
    let mut step = nice_step(axis_max - axis_min, target_count.max(1));
    // The 1-2-5 rule can leave far fewer intervals than wanted (2.5 instead of 6 when
    // it jumps from 200 to 500): take the next smaller step when it comes closer.
    let smaller = smaller_nice_step(step);
    let span = axis_max - axis_min;
    if span / smaller - target < target - span / step {
        step = smaller;
    }
    let inside = |step: f64| {
        let first = (axis_min / step - 1e-9).ceil() as i64;
        let last = (axis_max / step + 1e-9).floor() as i64;
        (first..=last)
            .map(|i| {
                let v = i as f64 * step;
                if v.abs() < step * 1e-9 {
                    0.0
                } else {
                    v
                }
            })
            .collect::<Vec<f64>>()
    };
    let mut values = inside(step);
    if values.len() < 2 {
        // Too few ticks inside: step down 1 -> 0.5 -> 0.2 ... until there are two.
        for _ in 0..6 {
            step = smaller_nice_step(step);
            values = inside(step);
            if values.len() >= 2 {
                break;
            }
        }
    }
    Ticks {
        axis_min,
        axis_max,
        step,
        values,
    }
}

/// The next nice step below `step`: 10 -> 5 -> 2 -> 1 (times a power of ten).
fn smaller_nice_step(step: f64) -> f64 {
    let mantissa = step / 10f64.powf(step.log10().floor());
    if (mantissa - 5.0).abs() < 1e-6 {
        step * 0.4
    } else {
        step * 0.5
    }
}

/// Formats a tick value with just enough decimals for `step` (e.g. step 0.2 -> "1.4").
pub fn format_tick(value: f64, step: f64) -> String {
    let decimals = if step > 0.0 && step.is_finite() {
        (-step.log10() - 1e-9).ceil().max(0.0) as usize
    } else {
        0
    };
    let text = format!("{value:.decimals$}");
    // "-0" / "-0.0" after rounding reads as a typo.
    if text.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
        text.trim_start_matches('-').to_owned()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nice_step_table() {
        // (span, target count, expected step)
        let table = [
            (10.0, 5, 2.0),
            (1.0, 5, 0.2),
            (35.0, 5, 10.0),
            (35.0, 7, 5.0),
            (100.0, 5, 20.0),
            (0.37, 5, 0.1),
            (3.0, 5, 1.0),
            (144.3, 6, 50.0),
            (1e-3, 4, 5e-4),
            (7.0, 1, 10.0),
            (2500.0, 5, 500.0),
        ];
        for (span, count, expected) in table {
            let step = nice_step(span, count);
            assert!(
                (step - expected).abs() <= 1e-12 * expected,
                "span {span}, count {count}: got {step}, expected {expected}"
            );
        }
    }

    #[test]
    fn degenerate_step_is_one() {
        assert_eq!(nice_step(0.0, 5), 1.0);
        assert_eq!(nice_step(f64::NAN, 5), 1.0);
        assert_eq!(nice_step(1.0, 0), 1.0);
    }

    #[test]
    fn ticks_cover_data_and_are_multiples_of_step() {
        let ticks = nice_ticks(80.3, 224.6, 6);
        assert_eq!(ticks.step, 50.0);
        assert_eq!(ticks.values, vec![50.0, 100.0, 150.0, 200.0, 250.0]);
        assert!(ticks.axis_min <= 80.3 && ticks.axis_max >= 224.6);
    }

    #[test]
    fn ticks_through_zero_have_exact_zero() {
        let ticks = nice_ticks(-0.3, 0.7, 5);
        assert!(ticks.values.contains(&0.0));
        assert_eq!(format_tick(ticks.values[1], ticks.step), "-0.2");
    }

    #[test]
    fn multiples_of_the_step_are_axis_ends() {
        let ticks = nice_ticks(0.0, 35.0, 5);
        assert_eq!((ticks.axis_min, ticks.axis_max, ticks.step), (0.0, 40.0, 10.0));
        let exact = nice_ticks(0.0, 30.000000000001, 5);
        assert_eq!(exact.axis_max, 30.0);
    }

    #[test]
    fn padded_ticks_stay_inside_the_padded_range() {
        let ticks = padded_ticks(80.3, 224.6, 8, 0.04);
        assert!(ticks.axis_min < 80.3 && ticks.axis_max > 224.6);
        assert_eq!(ticks.step, 20.0);
        assert_eq!(ticks.values.first(), Some(&80.0));
        assert_eq!(ticks.values.last(), Some(&220.0));
        let deflection = padded_ticks(0.0, 35.0, 5, 0.04);
        assert_eq!(deflection.values, vec![0.0, 10.0, 20.0, 30.0]);
        // 1253 / 6: 200 gives 6.3 intervals, 500 only 2.5.
        assert_eq!(padded_ticks(480.0, 1640.0, 6, 0.04).step, 200.0);
        assert!(padded_ticks(5.0, 5.0, 5, 0.04).values.len() >= 2);
    }

    #[test]
    fn constant_data_gets_an_axis() {
        let ticks = nice_ticks(5.0, 5.0, 5);
        assert!(ticks.axis_min < 5.0 && ticks.axis_max > 5.0);
        let zero = nice_ticks(0.0, 0.0, 5);
        assert!(zero.axis_min < 0.0 && zero.axis_max > 0.0);
    }

    #[test]
    fn tick_labels_have_step_decimals() {
        assert_eq!(format_tick(1.4000000000000001, 0.2), "1.4");
        assert_eq!(format_tick(150.0, 50.0), "150");
        assert_eq!(format_tick(-0.0000001, 0.5), "0.0");
        assert_eq!(format_tick(0.0015, 0.0005), "0.0015");
    }
}
