//! [`fit_bspline`]: one B-spline of a given degree through a stroke.
//!
//! PLACEHOLDER (replaced by the real fitter): least squares with a control point per 8
//! samples, chord-length parameters.

use super::{check_stroke, BSplineFit};
use crate::bspline::{parameterize, Parameterization};
use crate::error::Result;
use crate::geom::Cartesian;
use crate::interp::least_squares::approximate_bspline;

/// Fits a B-spline of degree `degree` to the samples `points` (see the module doc of
/// [`super`]); `closed`: `None` closes it when the stroke ends near its start.
///
/// # Errors
/// Those of [`check_stroke`], then those of the least-squares fit.
pub fn fit_bspline<C: Cartesian>(
    points: &[C],
    degree: usize,
    tolerance: f64,
    closed: Option<bool>,
) -> Result<BSplineFit<C>> {
    check_stroke(points, tolerance)?;
    let params = parameterize(points, Parameterization::Chord)?;
    let count = (points.len() / 8).max(degree + 1).min(points.len());
    let curve = approximate_bspline(points, degree, count, &params, None)?;
    Ok(BSplineFit {
        curve,
        max_error: f64::NAN,
        worst: 0,
        closed: closed.unwrap_or(false),
    })
}
