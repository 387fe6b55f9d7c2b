//! [`fit_curve`]: cubic Bézier pieces through a stroke.
//!
//! 1. Repeated consecutive samples are skipped; the stroke is closed when asked, or (with
//!    `closed: None`) when it ends within `max(4·tol, 3 % of its length)` of its start.
//! 2. Corners ([`super::corners`]) become fixed G0 joints; a closed stroke with corners starts
//!    at its first corner, one without has a smooth seam at its first sample.
//! 3. The breaks between fixed joints are chosen by furthest reach ([`super::segment`]),
//!    each piece a least-squares cubic ([`super::cubic`]) checked sample by sample; with C1
//!    each piece starts with the previous piece's end handle.
//! 4. Every piece's error is then measured exactly ([`super::distance`]).

use super::cubic::{Cubic, Fitter};
use super::segment::{segment, tangent, Layout, Piece};
use super::stroke::Stroke;
use super::{check_stroke, Corner, CurveFit, FitOptions, FitReport, PieceReport, Smoothness};
use crate::bezier::{BezierCurve, CompositeCurve};
use crate::error::Result;
use crate::geom::Cartesian;

/// Fits cubic Bézier pieces to the samples `points` (see the module doc of [`super`]).
///
/// Reported indices are the original samples'. On a closed curve that starts at a corner the
/// piece that runs over the stroke's end has `first > last`.
///
/// # Errors
/// Those of [`check_stroke`].
pub fn fit_curve<C: Cartesian>(
    points: &[C],
    tolerance: f64,
    options: &FitOptions,
) -> Result<CurveFit<C>> {
    check_stroke(points, tolerance)?;
    let stroke = Stroke::new(points);
    if stroke.len() == 1 {
        return degenerate(points, options.closed == Some(true));
    }
    let closed = match options.closed {
        Some(c) => c,
        None => super::ends_meet(&stroke.pts, tolerance),
    };
    let mut work = stroke;
    if closed && work.pts[0] != work.pts[work.len() - 1] {
        work.pts.push(work.pts[0]);
        work.orig.push(points.len() - 1);
        work.recompute_arc();
    }
    let mut found = if options.corners && work.len() > 2 {
        super::corners::find(&work, closed, tolerance)
    } else {
        Vec::new()
    };
    if closed && !found.is_empty() && found[0].0 != 0 {
        let c = found[0].0;
        work = rotate(&work, c);
        let period = work.len() - 1;
        for f in &mut found {
            f.0 = (f.0 + period - c) % period;
        }
    }
    let n = work.len();
    let mut limits = vec![0];
    limits.extend(found.iter().map(|f| f.0).filter(|&i| i > 0 && i < n - 1));
    limits.push(n - 1);
    let seam = if closed && found.is_empty() && n > 2 {
        let h = (0.05 * work.length()).max(2.0 * tolerance);
        tangent(&work, 0, h, (0, n - 1), true)
    } else {
        None
    };
    let layout = Layout {
        limits: &limits,
        seam,
        ends: (None, None),
        c1: options.smoothness == Smoothness::C1,
    };
    let mut fitter = Fitter::default();
    let pieces = segment(&work, &layout, tolerance, &mut fitter);
    let corners = found
        .iter()
        .map(|&(i, angle, straw)| Corner {
            index: work.orig[i],
            angle,
            straw,
        })
        .collect();
    finish(&work, &pieces, corners, closed)
}

/// The closed stroke (last sample = first) restarted at sample `c`.
fn rotate<C: Cartesian>(work: &Stroke<C>, c: usize) -> Stroke<C> {
    let period = work.len() - 1;
    let idx: Vec<usize> = (0..=period).map(|k| (c + k) % period).collect();
    let pts: Vec<C> = idx.iter().map(|&k| work.pts[k]).collect();
    let orig: Vec<usize> = idx.iter().map(|&k| work.orig[k]).collect();
    Stroke::from_parts(&pts, orig)
}

/// One piece with four equal points at the only position.
fn degenerate<C: Cartesian>(points: &[C], closed: bool) -> Result<CurveFit<C>> {
    let p = points[0];
    let curve = CompositeCurve::new(vec![BezierCurve::new(vec![p; 4], None)?], &[0.0, 1.0])?;
    Ok(CurveFit {
        curve,
        report: FitReport {
            corners: Vec::new(),
            breaks: Vec::new(),
            pieces: vec![PieceReport {
                first: 0,
                last: points.len() - 1,
                max_error: 0.0,
                worst: 0,
            }],
            closed,
        },
    })
}

/// Builds the composite curve and measures every piece.
pub(crate) fn finish<C: Cartesian>(
    work: &Stroke<C>,
    pieces: &[Piece<C>],
    corners: Vec<Corner>,
    closed: bool,
) -> Result<CurveFit<C>> {
    let mut beziers = Vec::with_capacity(pieces.len());
    let mut reports = Vec::with_capacity(pieces.len());
    for p in pieces {
        let (max_error, worst) = super::distance::measure(&p.cubic, &work.pts[p.a..=p.b]);
        reports.push(PieceReport {
            first: work.orig[p.a],
            last: work.orig[p.b],
            max_error,
            worst: work.orig[p.a + worst],
        });
        beziers.push(bezier(&p.cubic)?);
    }
    let knots: Vec<f64> = (0..=beziers.len()).map(|i| i as f64).collect();
    let curve = CompositeCurve::new(beziers, &knots)?;
    let breaks = pieces[..pieces.len() - 1]
        .iter()
        .map(|p| work.orig[p.b])
        .collect();
    Ok(CurveFit {
        curve,
        report: FitReport {
            corners,
            breaks,
            pieces: reports,
            closed,
        },
    })
}

/// The Bézier curve of a cubic.
pub(crate) fn bezier<C: Cartesian>(c: &Cubic<C>) -> Result<BezierCurve<C>> {
    BezierCurve::new(c.ctrl.to_vec(), None)
}
