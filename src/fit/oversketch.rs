//! [`oversketch`]: a stroke drawn near a curve replaces the part between its ends.
//!
//! 1. The stroke's first and last samples are projected on the curve ([`project`]). An end is
//!    *near* within `max(10·tol, 2 % of the diagonal of the curve's control box)`.
//! 2. Both ends near: the part between their parameters `t0 < t1` is replaced (a stroke drawn
//!    against the curve's direction is reversed first). On a closed curve the part the stroke
//!    follows is replaced — the one holding the projection of the stroke's middle sample —
//!    across the seam if need be: the new curve then starts at `C(t0)`, its kept part first,
//!    and the report's `replaced` has `t0 > t1`. One end near, on an open curve: the curve is
//!    extended from that point towards its nearer end (the part beyond the point is
//!    replaced). Neither end near (or only one, on a closed curve): [`Error::StrokeFarFromCurve`].
//! 3. The stroke is blended into the curve: every sample moves by the gap `δ = C(t) − Q` at
//!    each joined end, weighted `max(0, 1 − s/F)` by its arc length `s` from that end (`F` a
//!    quarter of the stroke's length), so the ends lie on the curve and the middle keeps its
//!    shape. Its fit (the segmentation of [`super::fit_curve`], corners kept) starts and ends
//!    there with the end handles along the curve's tangents: G1 seams.
//! 4. The pieces around are split at `t0` and `t1` by de Casteljau's algorithm: the kept parts
//!    are exact sub-curves, so nothing outside the replaced part moves.

use super::cubic::Fitter;
use super::curve::finish;
use super::segment::{segment, Layout};
use super::stroke::Stroke;
use super::{check_stroke, Oversketch};
use crate::bezier::{BezierCurve, CompositeCurve};
use crate::curve::ControlPolygon;
use crate::error::{Error, Result};
use crate::geom::{BoundingBox, Cartesian};

/// An end of the stroke is near the curve within this many tolerances…
const NEAR_TOLERANCES: f64 = 10.0;
/// …or this fraction of the diagonal of the curve's control box, whichever is larger.
const NEAR_FRACTION: f64 = 0.02;
/// The blend moves samples up to this fraction of the stroke's length from a joined end.
const BLEND_FRACTION: f64 = 0.25;
/// Parameters per piece of the coarse search of [`project`].
const PROJECT_SAMPLES: usize = 64;
/// A split this close to a piece's end (in its local parameter) keeps or drops it whole.
const SPLIT_EPS: f64 = 1e-9;

/// Replaces the part of `curve` between where `stroke` starts and ends near it by a fit of the
/// stroke with G1 seams (see the module doc). The new curve's piece `i` lives on `[i, i + 1]`.
///
/// # Errors
/// Those of [`super::check_stroke`] for the stroke and the tolerance,
/// [`Error::StrokeFarFromCurve`] when no end of the stroke is near the curve (or only one on a
/// closed curve), [`Error::TooFewDataPoints`] for a stroke of one repeated point.
pub fn oversketch<C: Cartesian>(
    curve: &CompositeCurve<C>,
    stroke: &[C],
    tolerance: f64,
) -> Result<Oversketch<C>> {
    check_stroke(stroke, tolerance)?;
    let pieces = curve.pieces();
    let (a, b) = curve.domain();
    let first = pieces[0].control_points()[0];
    let last = *pieces[pieces.len() - 1]
        .control_points()
        .last()
        .expect("a piece has points");
    let closed = first == last;
    let near = (NEAR_TOLERANCES * tolerance).max(NEAR_FRACTION * control_diagonal(curve));
    let (d0, mut t0) = project(curve, stroke[0])?;
    let (d1, mut t1) = project(curve, stroke[stroke.len() - 1])?;
    let mut samples = stroke.to_vec();
    let (near0, near1) = (d0 <= near, d1 <= near);
    if !(near0 && near1) && (closed || !(near0 || near1)) {
        return Err(Error::StrokeFarFromCurve {
            start_distance: d0,
            end_distance: d1,
            near,
        });
    }
    if near0 && near1 {
        if t0 > t1 {
            samples.reverse();
            std::mem::swap(&mut t0, &mut t1);
        }
        let (_, tm) = project(curve, samples[samples.len() / 2])?;
        if closed && !(t0..=t1).contains(&tm) {
            // Across the seam: keep [t0, t1], then the stroke from C(t1) back to C(t0).
            samples.reverse();
            let kept = between(curve, t0, t1)?;
            let new = fit_between(curve, &samples, (Some(t1), Some(t0)), tolerance)?;
            return assemble(kept, new, Vec::new(), (t1, t0));
        }
        let new = fit_between(curve, &samples, (Some(t0), Some(t1)), tolerance)?;
        return assemble(
            between(curve, a, t0)?,
            new,
            between(curve, t1, b)?,
            (t0, t1),
        );
    }
    // An extension of an open curve from its near point.
    if near1 {
        samples.reverse();
        t0 = t1;
    }
    let t = t0;
    if b - t <= t - a {
        let new = fit_between(curve, &samples, (Some(t), None), tolerance)?;
        assemble(between(curve, a, t)?, new, Vec::new(), (t, b))
    } else {
        samples.reverse();
        let new = fit_between(curve, &samples, (None, Some(t)), tolerance)?;
        assemble(Vec::new(), new, between(curve, t, b)?, (a, t))
    }
}

/// The closest point of `curve` to `q`: `(distance, parameter)`. Every piece is sampled at
/// [`PROJECT_SAMPLES`] + 1 parameters; around the closest sample the root of
/// `g(t) = (C(t) − q)·C'(t)` is found by Newton's method kept inside a shrinking bracket
/// (a step that leaves it is replaced by the midpoint); the bracket's ends are candidates too.
pub(crate) fn project<C: Cartesian>(curve: &CompositeCurve<C>, q: C) -> Result<(f64, f64)> {
    let mut best = (f64::INFINITY, 0.0, 0);
    for (i, piece) in curve.pieces().iter().enumerate() {
        let (a, b) = piece.interval();
        for k in 0..=PROJECT_SAMPLES {
            let t = a + (b - a) * (k as f64 / PROJECT_SAMPLES as f64);
            let d = (piece.evaluate(t)? - q).norm();
            if d < best.0 {
                best = (d, t, i);
            }
        }
    }
    let piece = &curve.pieces()[best.2];
    let (a, b) = piece.interval();
    let h = (b - a) / PROJECT_SAMPLES as f64;
    let (mut lo, mut hi) = ((best.1 - h).max(a), (best.1 + h).min(b));
    let mut t = best.1;
    for _ in 0..60 {
        let r = piece.evaluate(t)? - q;
        let d1 = piece.derivative(t, 1)?;
        let g = r.dot_with(d1);
        if g > 0.0 {
            hi = t;
        } else {
            lo = t;
        }
        let dg = d1.dot_with(d1) + r.dot_with(piece.derivative(t, 2)?);
        let mut next = t - g / dg;
        if !(dg > 0.0 && next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        let done = (next - t).abs() <= 1e-15 * (b - a);
        t = next;
        if done || hi - lo <= 1e-15 * (b - a) {
            break;
        }
    }
    for u in [t, lo, hi] {
        let d = (piece.evaluate(u)? - q).norm();
        if d < best.0 {
            best = (d, u, best.2);
        }
    }
    Ok((best.0, best.1))
}

/// The diagonal of the box around every control point of `curve`.
fn control_diagonal<C: Cartesian>(curve: &CompositeCurve<C>) -> f64 {
    let points: Vec<C> = curve
        .pieces()
        .iter()
        .flat_map(|p| p.control_points())
        .collect();
    BoundingBox::of_points(&points).map_or(0.0, |b| b.diagonal())
}

/// The part of `curve` on `[t0, t1]` as pieces (on `[0, 1]` each): whole pieces inside, the
/// pieces holding `t0` and `t1` split there (a split within [`SPLIT_EPS`] of a piece's end
/// keeps or drops the piece whole). Empty when `t1 − t0` is below that.
fn between<C: Cartesian>(
    curve: &CompositeCurve<C>,
    t0: f64,
    t1: f64,
) -> Result<Vec<BezierCurve<C>>> {
    let mut out = Vec::new();
    for piece in curve.pieces() {
        let (a, b) = piece.interval();
        let eps = SPLIT_EPS * (b - a);
        let (lo, hi) = (t0.max(a), t1.min(b));
        if hi - lo <= eps {
            continue;
        }
        let mut part = piece.clone();
        if hi < b - eps {
            part = part.split(hi)?.0.with_interval(a, hi)?;
        }
        if lo > a + eps {
            part = part.split(lo)?.1;
        }
        out.push(part.with_interval(0.0, 1.0)?);
    }
    Ok(out)
}

/// The fit of `samples` joined to `curve` at the parameters `joins` (start, end): the samples
/// are blended onto `C(t)` at a joined end (module doc, step 3), and the fit's handle there
/// lies along the curve's tangent `C'(t)`.
fn fit_between<C: Cartesian>(
    curve: &CompositeCurve<C>,
    samples: &[C],
    joins: (Option<f64>, Option<f64>),
    tolerance: f64,
) -> Result<Vec<BezierCurve<C>>> {
    let mut blended = samples.to_vec();
    let n = blended.len();
    let mut arc = Vec::with_capacity(n);
    let mut s = 0.0;
    for k in 0..n {
        if k > 0 {
            s += (samples[k] - samples[k - 1]).norm();
        }
        arc.push(s);
    }
    let fade = BLEND_FRACTION * s;
    let mut dirs = (None, None);
    for (end, join) in [(0, joins.0), (1, joins.1)] {
        let Some(t) = join else { continue };
        let on = curve.evaluate(t)?;
        let (k, dir) = if end == 0 {
            (0, &mut dirs.0)
        } else {
            (n - 1, &mut dirs.1)
        };
        let gap = on - samples[k];
        for (q, &sk) in blended.iter_mut().zip(&arc) {
            let from_end = if end == 0 { sk } else { s - sk };
            if fade > 0.0 && from_end < fade {
                *q = *q + gap * (1.0 - from_end / fade);
            }
        }
        blended[k] = on;
        let d = curve.derivative(t, 1)?;
        let len = d.norm();
        *dir = (len > 0.0 && len.is_finite()).then(|| d * (1.0 / len));
    }
    let work = Stroke::new(&blended);
    if work.len() < 2 {
        return Err(Error::TooFewDataPoints {
            needed: 2,
            got: work.len(),
            what: "stroke",
        });
    }
    let found = if work.len() > 2 {
        super::corners::find(&work, false, tolerance)
    } else {
        Vec::new()
    };
    let m = work.len();
    let mut limits = vec![0];
    limits.extend(found.iter().map(|f| f.0).filter(|&i| i > 0 && i < m - 1));
    limits.push(m - 1);
    let layout = Layout {
        limits: &limits,
        seam: None,
        ends: dirs,
        c1: false,
    };
    let pieces = segment(&work, &layout, tolerance, &mut Fitter::default());
    let fit = finish(&work, &pieces, Vec::new(), false)?;
    fit.curve
        .pieces()
        .iter()
        .map(|p| p.clone().with_interval(0.0, 1.0))
        .collect()
}

/// The new curve: `before`, `new`, `after` on `[0, 1], [1, 2], …`, with the report.
fn assemble<C: Cartesian>(
    before: Vec<BezierCurve<C>>,
    new: Vec<BezierCurve<C>>,
    after: Vec<BezierCurve<C>>,
    replaced: (f64, f64),
) -> Result<Oversketch<C>> {
    let first = before.len();
    let end = first + new.len();
    let pieces: Vec<BezierCurve<C>> = before.into_iter().chain(new).chain(after).collect();
    let knots: Vec<f64> = (0..=pieces.len()).map(|i| i as f64).collect();
    Ok(Oversketch {
        curve: CompositeCurve::new(pieces, &knots)?,
        replaced,
        new_pieces: (first, end),
    })
}
