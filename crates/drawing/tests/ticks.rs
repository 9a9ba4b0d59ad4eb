//! Nice ticks: properties over random ranges.

use flapwright_drawing::{nice_step, nice_ticks, padded_ticks};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn ticks_cover_the_data_with_round_steps(low in -1e4f64..1e4, span in 1e-3f64..1e4, target in 2usize..10) {
        let high = low + span;
        let ticks = nice_ticks(low, high, target);
        prop_assert!(ticks.axis_min <= low && ticks.axis_max >= high);
        // Never more intervals than asked for, plus the two partial ends.
        prop_assert!(ticks.values.len() <= target + 3, "{} ticks for target {}", ticks.values.len(), target);
        let mantissa = ticks.step / 10f64.powf(ticks.step.log10().floor());
        prop_assert!([1.0, 2.0, 5.0, 10.0].iter().any(|m| (mantissa - m).abs() < 1e-9), "step {}", ticks.step);
        prop_assert!(ticks.values.iter().all(|v| v.is_finite()));
    }

    #[test]
    fn step_is_at_least_the_raw_interval(span in 1e-6f64..1e6, target in 1usize..12) {
        let step = nice_step(span, target);
        prop_assert!(step * (1.0 + 1e-9) >= span / target as f64);
        prop_assert!(step <= 10.0 * span / target as f64 * (1.0 + 1e-9));
    }

    #[test]
    fn padded_ticks_lie_inside_and_are_at_least_two(low in -1e4f64..1e4, span in 1e-3f64..1e4, target in 2usize..10) {
        let high = low + span;
        let ticks = padded_ticks(low, high, target, 0.04);
        prop_assert!(ticks.axis_min < low && ticks.axis_max > high);
        prop_assert!(ticks.values.len() >= 2, "{:?}", ticks);
        prop_assert!(ticks.values.iter().all(|v| *v >= ticks.axis_min - 1e-9 * span && *v <= ticks.axis_max + 1e-9 * span));
    }
}
