//! Sketching (syllabus 7): "a curve more or less like this". A freehand stroke — the pointer's
//! samples `Q_0 … Q_m` in model units — becomes a curve the user can edit:
//!
//! - [`fit_curve`]: cubic Bézier pieces with every sample within `tolerance` of the curve
//!   (measured), as few pieces as a global search over the breaks finds, corners kept as G0
//!   joints and every other joint G1 (or C1); closed strokes give closed curves.
//! - [`fit_bspline`]: one B-spline of a given degree with the fewest control points that keep
//!   every sample within the tolerance (clamped, or periodic when closed).
//! - [`oversketch`]: a stroke drawn near a curve replaces the part between its ends; nothing
//!   outside that part moves.
//!
//! Each returns, besides the curve, the decisions a teacher wants to show: the corners found
//! and why, where the pieces split, each piece's measured maximum error and its worst sample.
//!
//! Composite results are parametrised by piece: piece `i` lives on `[i, i + 1]`.

mod bspline;
mod corners;
mod cubic;
mod curve;
mod distance;
mod oversketch;
mod periodic;
mod project;
mod segment;
mod stroke;
mod weighted;

pub use bspline::{fit_bspline, MAX_BSPLINE_FIT_SAMPLES};
pub use curve::fit_curve;
pub use oversketch::oversketch;

use crate::bezier::CompositeCurve;
use crate::bspline::BSplineCurve;
use crate::error::{Error, Result};
use crate::geom::Point;

/// The most samples a stroke may have (a pointer at 240 Hz for over an hour).
pub const MAX_STROKE_SAMPLES: usize = 1_000_000;

/// How smooth the joints between pieces that are not corners are.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Smoothness {
    /// Tangent directions agree (the pieces' end tangents are parallel, lengths free).
    #[default]
    G1,
    /// The first derivatives with respect to the global parameter agree.
    C1,
}

/// Options of [`fit_curve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitOptions {
    /// `Some(true)`: a closed curve; `Some(false)`: open; `None`: closed when the stroke ends
    /// within a few tolerances of where it began.
    pub closed: Option<bool>,
    /// The joints that are not corners.
    pub smoothness: Smoothness,
    /// Detect corners (G0 joints); `false` makes every joint smooth.
    pub corners: bool,
}

impl Default for FitOptions {
    fn default() -> Self {
        FitOptions {
            closed: None,
            smoothness: Smoothness::G1,
            corners: true,
        }
    }
}

/// A corner found in the stroke: the sample where the direction turns sharply.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Corner {
    /// Index of the sample at the corner.
    pub index: usize,
    /// The turning angle there in radians (0 straight on, π a reversal).
    pub angle: f64,
    /// The detector's measure that made it a corner (e.g. the straw length relative to the
    /// window: small means sharp), for the demo to show.
    pub straw: f64,
}

/// What the fit measured for one piece.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PieceReport {
    /// First sample the piece covers.
    pub first: usize,
    /// Last sample the piece covers (the next piece starts here).
    pub last: usize,
    /// The largest distance from a covered sample to the piece.
    pub max_error: f64,
    /// The sample at that distance.
    pub worst: usize,
}

/// The decisions of a fit, for teaching.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FitReport {
    /// The corners found (G0 joints), in stroke order.
    pub corners: Vec<Corner>,
    /// Sample index of every joint, corners included, in stroke order.
    pub breaks: Vec<usize>,
    /// One entry per piece.
    pub pieces: Vec<PieceReport>,
    /// Whether the curve was closed.
    pub closed: bool,
}

/// A composite cubic Bézier curve and how it was found.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveFit<C: crate::geom::Cartesian> {
    /// The curve: piece `i` on `[i, i + 1]`.
    pub curve: CompositeCurve<C>,
    /// The decisions.
    pub report: FitReport,
}

/// A B-spline fitted to a stroke and how well.
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineFit<C: crate::geom::Cartesian> {
    /// The curve (clamped, or periodic when closed).
    pub curve: BSplineCurve<C>,
    /// The largest distance from a sample to the curve.
    pub max_error: f64,
    /// The sample at that distance.
    pub worst: usize,
    /// Whether the curve was closed.
    pub closed: bool,
}

/// An oversketched curve: the old curve with the part between the stroke's ends replaced.
#[derive(Debug, Clone, PartialEq)]
pub struct Oversketch<C: crate::geom::Cartesian> {
    /// The new curve: piece `i` on `[i, i + 1]`.
    pub curve: CompositeCurve<C>,
    /// The old curve's parameters `(t0, t1)` of the replaced part: `t0 ≤ t1`, except on a
    /// closed curve whose replaced part runs across the seam (from `t0` past the end, round to
    /// `t1`); an extension gives the curve's end parameter on its side (`(t, b)` or `(a, t)`).
    pub replaced: (f64, f64),
    /// The new pieces `[first, last)` that come from the stroke.
    pub new_pieces: (usize, usize),
}

/// A stroke closes itself (with `closed: None`) when its ends are within this many
/// tolerances…
const CLOSE_TOLERANCES: f64 = 4.0;
/// …or within this fraction of its length.
const CLOSE_FRACTION: f64 = 0.03;

/// Whether a stroke ends near where it began, for both fitters: within
/// `max(4·tol, 3 % of its polyline length)`, with at least 4 samples and a length above 8
/// tolerances (a dab is not a loop).
pub(crate) fn ends_meet<C: crate::geom::Cartesian>(points: &[C], tol: f64) -> bool {
    let length: f64 = points.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
    let gap = (points[points.len() - 1] - points[0]).norm();
    points.len() >= 4
        && length > 8.0 * tol
        && gap <= (CLOSE_TOLERANCES * tol).max(CLOSE_FRACTION * length)
}

/// `x` wrapped into `[0, period)` for a closed stroke's arc length or a periodic parameter:
/// `f64::rem_euclid` exactly for `−period < x < 2·period` (one addition or subtraction, the
/// only cases the fitters meet), `x − ⌊x / period⌋·period` beyond. Not `rem_euclid` itself:
/// its `fmod` adds ~1.2 KB to the wasm.
#[inline(never)]
pub(crate) fn wrap(x: f64, period: f64) -> f64 {
    if x < 0.0 && x > -period {
        x + period
    } else if x >= period && x < 2.0 * period {
        x - period
    } else if (0.0..period).contains(&x) {
        x
    } else {
        x - (x / period).floor() * period
    }
}

/// Checks a stroke and a tolerance, in the order of the API: finite coordinates, enough
/// samples, not too many, a finite positive tolerance.
///
/// # Errors
/// [`Error::NotFinite`] (coordinate), [`Error::TooFewDataPoints`] below 2 samples,
/// [`Error::TooLarge`] above [`MAX_STROKE_SAMPLES`], [`Error::InvalidTolerance`].
pub(crate) fn check_stroke<P: Point>(points: &[P], tolerance: f64) -> Result<()> {
    for (i, p) in points.iter().enumerate() {
        if let Some(k) = (0..P::DIM).find(|&k| !p.coord(k).is_finite()) {
            return Err(Error::NotFinite {
                what: "coordinate",
                index: Some(i * P::DIM + k),
                value: p.coord(k),
            });
        }
    }
    if points.len() < 2 {
        return Err(Error::TooFewDataPoints {
            needed: 2,
            got: points.len(),
            what: "stroke",
        });
    }
    if points.len() > MAX_STROKE_SAMPLES {
        return Err(Error::TooLarge {
            what: "stroke",
            value: points.len(),
            max: MAX_STROKE_SAMPLES,
        });
    }
    crate::error::check_tolerance(tolerance)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    #[test]
    fn wrap_is_rem_euclid() {
        for period in [1.0, 0.37, 250.5] {
            for k in -300..=600 {
                let x = k as f64 * period / 97.0 + 1e-3;
                let (got, want) = (super::wrap(x, period), x.rem_euclid(period));
                if x > -period && x < 2.0 * period {
                    assert_eq!(got, want, "{x} mod {period}");
                } else {
                    // Beyond, within rounding of it.
                    assert!((got - want).abs() <= 1e-14 * x.abs(), "{x} mod {period}");
                }
            }
        }
    }
}
