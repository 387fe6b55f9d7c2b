//! Checks of single numbers shared by every family.

use super::{Error, Result};

/// Checks that `value` is finite; `what` names it in the error.
pub(crate) fn check_finite(what: impl FnOnce() -> String, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NotFinite {
            what: what(),
            value,
        })
    }
}

/// Checks a tolerance: finite and > 0.
pub(crate) fn check_tolerance(value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::InvalidTolerance { value })
    }
}

/// Checks that the parameter called `name` is finite and in the closed interval `[min, max]`
/// ([`Error::NotFinite`] or [`Error::ParameterOutOfRange`] naming it); gives it back.
pub(crate) fn check_in_range(
    name: &'static str,
    value: f64,
    (min, max): (f64, f64),
) -> Result<f64> {
    check_finite(|| name.into(), value)?;
    if value < min || value > max {
        return Err(Error::ParameterOutOfRange {
            name,
            value,
            min,
            max,
        });
    }
    Ok(value)
}
