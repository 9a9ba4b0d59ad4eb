//! Small input checks shared by the modules (private).

use crate::{Error, Result};

/// `value` finite and strictly positive.
pub(crate) fn positive(field: impl Into<String>, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::OutOfRange {
            field: field.into(),
            value,
            allowed: "(0, inf)",
        })
    }
}

/// `value` finite and not negative.
pub(crate) fn non_negative(field: impl Into<String>, value: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::OutOfRange {
            field: field.into(),
            value,
            allowed: "[0, inf)",
        })
    }
}

/// `value` finite (any sign).
pub(crate) fn finite(field: impl Into<String>, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::OutOfRange {
            field: field.into(),
            value,
            allowed: "finite",
        })
    }
}

/// A mechanical efficiency in (0, 1].
pub(crate) fn efficiency(field: impl Into<String>, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 && value <= 1.0 {
        Ok(value)
    } else {
        Err(Error::EfficiencyOutOfRange {
            field: field.into(),
            value,
        })
    }
}
