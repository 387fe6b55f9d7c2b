//! [`oversketch`]: a stroke drawn near a curve replaces the part between its ends.
//!
//! PLACEHOLDER (replaced by the real one): gives the stroke's own fit.

use super::{fit_curve, FitOptions, Oversketch};
use crate::bezier::CompositeCurve;
use crate::error::Result;
use crate::geom::Cartesian;

/// Replaces the part of `curve` between where `stroke` starts and ends near it by a fit of the
/// stroke with G1 seams (see the module doc of [`super`]).
///
/// # Errors
/// Those of [`super::check_stroke`] for the stroke and the tolerance.
pub fn oversketch<C: Cartesian>(
    curve: &CompositeCurve<C>,
    stroke: &[C],
    tolerance: f64,
) -> Result<Oversketch<C>> {
    let fit = fit_curve(stroke, tolerance, &FitOptions::default())?;
    let pieces = fit.curve.pieces().len();
    let domain = curve.domain();
    Ok(Oversketch {
        curve: fit.curve,
        replaced: domain,
        new_pieces: (0, pieces),
    })
}
