//! Checks of single numbers shared by every family.

use super::{Error, Result};

/// Checks that `value` is finite; `what` (a subject: an argument's name or a phrase key, see
/// `phrase.rs`) and `index` name it in the error: `("coordinate", Some(3))` gives "coordinate 3".
pub(crate) fn check_finite(what: &'static str, index: Option<usize>, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NotFinite { what, index, value })
    }
}

/// Checks a coordinate: finite ([`Error::NotFinite`]), then at most
/// [`crate::geom::MAX_COORDINATE`] in magnitude ([`Error::CoordinateTooLarge`]); `what` and
/// `index` name it as in [`check_finite`].
pub(crate) fn check_coordinate(
    what: &'static str,
    index: Option<usize>,
    value: f64,
) -> Result<f64> {
    check_finite(what, index, value)?;
    let max = crate::geom::MAX_COORDINATE;
    if value.abs() > max {
        return Err(Error::CoordinateTooLarge {
            what,
            index,
            value,
            max,
        });
    }
    Ok(value)
}

/// Checks coordinate `k` of the vector argument `name` as [`check_coordinate`] does: the error
/// is "center: coordinate 1 is NaN; …" ([`Error::InArgument`] around [`Error::NotFinite`] or
/// [`Error::CoordinateTooLarge`]).
pub(crate) fn check_coordinate_of(name: &'static str, k: usize, value: f64) -> Result<f64> {
    check_coordinate("coordinate", Some(k), value).map_err(|source| in_argument(name, source))
}

/// An error about the argument `name`, keeping its cause (the message says `name: cause`).
pub(crate) fn in_argument(name: &'static str, err: Error) -> Error {
    Error::InArgument {
        name,
        index: None,
        source: Box::new(err),
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
    check_finite(name, None, value)?;
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
