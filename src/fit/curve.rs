//! [`fit_curve`]: cubic Bézier pieces through a stroke.
//!
//! PLACEHOLDER (replaced by the real fitter): pieces between every 8th sample with
//! Catmull–Rom tangents, errors measured against the pieces.

use super::{check_stroke, CurveFit, FitOptions, FitReport, PieceReport};
use crate::bezier::{BezierCurve, CompositeCurve};
use crate::error::Result;
use crate::geom::Cartesian;

/// Fits cubic Bézier pieces to the samples `points` (see the module doc of [`super`]).
///
/// # Errors
/// Those of [`check_stroke`].
pub fn fit_curve<C: Cartesian>(
    points: &[C],
    tolerance: f64,
    options: &FitOptions,
) -> Result<CurveFit<C>> {
    check_stroke(points, tolerance)?;
    let last = points.len() - 1;
    let mut breaks: Vec<usize> = (0..last).step_by(8).collect();
    breaks.push(last);
    let tangent = |i: usize| {
        let a = points[i.saturating_sub(1)];
        let b = points[(i + 1).min(last)];
        (b - a) * 0.5
    };
    let mut pieces = Vec::new();
    let mut reports = Vec::new();
    for w in breaks.windows(2) {
        let (i, j) = (w[0], w[1]);
        let scale = (j - i) as f64 / 3.0;
        let p0 = points[i];
        let p3 = points[j];
        let piece = BezierCurve::new(
            vec![p0, p0 + tangent(i) * scale, p3 - tangent(j) * scale, p3],
            None,
        )?;
        let (max_error, worst) = measured_error(&piece, &points[i..=j]);
        reports.push(PieceReport {
            first: i,
            last: j,
            max_error,
            worst: i + worst,
        });
        pieces.push(piece);
    }
    let knots: Vec<f64> = (0..=pieces.len()).map(|i| i as f64).collect();
    let curve = CompositeCurve::new(pieces, &knots)?;
    Ok(CurveFit {
        curve,
        report: FitReport {
            corners: Vec::new(),
            breaks: breaks[1..breaks.len() - 1].to_vec(),
            pieces: reports,
            closed: options.closed.unwrap_or(false),
        },
    })
}

/// The largest distance from a sample to the piece's 64-segment polyline, and its index.
fn measured_error<C: Cartesian>(piece: &BezierCurve<C>, samples: &[C]) -> (f64, usize) {
    let polyline: Vec<C> = (0..=64)
        .filter_map(|k| piece.evaluate(k as f64 / 64.0).ok())
        .collect();
    let mut worst = (0.0, 0);
    for (k, &q) in samples.iter().enumerate() {
        let d = polyline
            .windows(2)
            .map(|s| q.distance_to_segment(s[0], s[1]))
            .fold(f64::INFINITY, f64::min);
        if d > worst.0 {
            worst = (d, k);
        }
    }
    worst
}
