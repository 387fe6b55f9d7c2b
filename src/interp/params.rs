//! Interpolation parameters `t_0 < … < t_n`: their validation, and the choice between given
//! values and a spacing computed from the points (`Σ |Δp|^α`, see
//! [`crate::bspline::parameterize`]).

use crate::bspline::{parameterize, Parameterization};
use crate::error::InterpError;
use crate::error::{check_finite, Error, Result};
use crate::geom::Point;

/// Where the parameters of an interpolant come from.
#[derive(Debug, Clone, PartialEq)]
pub enum ParamChoice {
    /// Given values, one per point, strictly increasing.
    Given(Vec<f64>),
    /// Computed from the points: cumulative `|p_{i+1} − p_i|^α` from 0. Moving a point
    /// recomputes them.
    Spacing(Parameterization),
}

impl From<Vec<f64>> for ParamChoice {
    fn from(values: Vec<f64>) -> Self {
        ParamChoice::Given(values)
    }
}

impl From<&[f64]> for ParamChoice {
    fn from(values: &[f64]) -> Self {
        ParamChoice::Given(values.to_vec())
    }
}

impl From<Parameterization> for ParamChoice {
    fn from(kind: Parameterization) -> Self {
        ParamChoice::Spacing(kind)
    }
}

impl ParamChoice {
    /// The parameters for `points`: the given ones checked by [`check_params`], or the spacing
    /// computed.
    ///
    /// # Errors
    /// As [`check_params`], or [`Error::CoincidentPoints`] for a spacing with α > 0 and a
    /// repeated point.
    #[inline(never)]
    pub fn resolve<P: Point>(&self, points: &[P]) -> Result<Vec<f64>> {
        match self {
            ParamChoice::Given(values) => {
                check_params(values, points.len())?;
                Ok(values.clone())
            }
            ParamChoice::Spacing(kind) => parameterize(points, *kind),
        }
    }
}

/// Checks interpolation parameters for `points` data points, in the documented order: count
/// ([`InterpError::ParamCount`]), every value finite ([`Error::NotFinite`] naming `param i`), then
/// strictly increasing ([`InterpError::ParamsNotIncreasing`] naming the first `t_i ≤ t_{i−1}`).
pub fn check_params(params: &[f64], points: usize) -> Result<()> {
    if params.len() != points {
        return Err(Error::Interp(InterpError::ParamCount {
            params: params.len(),
            points,
        }));
    }
    for (i, &t) in params.iter().enumerate() {
        check_finite("parameter", Some(i), t)?;
    }
    for (i, w) in params.windows(2).enumerate() {
        if w[1] <= w[0] {
            return Err(Error::Interp(InterpError::ParamsNotIncreasing {
                index: i + 1,
                value: w[1],
                previous: w[0],
            }));
        }
    }
    Ok(())
}

/// Checks there are at least `needed` data points for `what` ([`Error::TooFewDataPoints`]).
pub fn check_point_count(got: usize, needed: usize, what: &'static str) -> Result<()> {
    if got < needed {
        return Err(Error::TooFewDataPoints { needed, got, what });
    }
    Ok(())
}
