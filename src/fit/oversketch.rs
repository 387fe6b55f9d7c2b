//! [`oversketch`]: a stroke drawn near a curve replaces the part between its ends.
//!
//! 1. The stroke's first and last samples are projected on the curve (each piece sampled at
//!    [`COARSE`] + 1 parameters, the nearest bracketed and refined by golden-section search):
//!    parameters `t0`, `t1`. An end is *near* within `max(10·tol, 2 % of the diagonal of the
//!    curve's control-point box)`.
//! 2. Both ends near: the part between `t0` and `t1` is replaced (the stroke is reversed when
//!    it runs against the curve). One end near: the curve is extended from there — the part
//!    on the side the stroke leaves towards (`[t, end]` if the stroke starts along the
//!    curve's direction, else `[start, t]`) is replaced. Neither near: the stroke extends the
//!    curve from the curve end nearest to one of its ends (a student drawing off the curve
//!    means "continue it here"). On a closed curve both ends attach to their closest points
//!    and the arc replaced is the one the stroke's middle sample lies along (so it may run
//!    through the seam: then `t0 > t1`); the curve stays closed.
//! 3. The new part is a fit of the stroke (as [`super::fit_curve`], G1, corners kept) whose end
//!    samples are replaced by `curve(t0)`, `curve(t1)` and whose end tangents are the curve's
//!    tangents there: G1 seams.
//! 4. The old pieces are split exactly at `t0`, `t1` by de Casteljau subdivision; every other
//!    kept piece is copied unchanged, so nothing outside the replaced part moves.

use super::corners;
use super::cubic::Fitter;
use super::segment::{segment, Layout};
use super::stroke::Stroke;
use super::{check_stroke, Oversketch};
use crate::bezier::{BezierCurve, CompositeCurve};
use crate::error::Result;
use crate::geom::Cartesian;
use crate::prelude::*;

/// Coarse samples per piece for the closest point.
const COARSE: usize = 64;

/// Replaces the part of `curve` between where `stroke` starts and ends near it by a fit of the
/// stroke with G1 seams (see the module doc).
///
/// # Errors
/// Those of [`super::check_stroke`] for the stroke and the tolerance.
pub fn oversketch<C: Cartesian>(
    curve: &CompositeCurve<C>,
    stroke: &[C],
    tolerance: f64,
) -> Result<Oversketch<C>> {
    check_stroke(stroke, tolerance)?;
    let (ta, tb) = curve.domain();
    let pieces = curve.pieces();
    let first = pieces[0].evaluate(ta)?;
    let last = pieces[pieces.len() - 1].evaluate(tb)?;
    let diag = pieces
        .iter()
        .filter_map(|p| p.control_box())
        .map(|b| b.diagonal())
        .fold(0.0, f64::max)
        .max((last - first).norm());
    let scale = 1.0 + first.norm().max(last.norm());
    let closed = (last - first).norm() <= 1e-9 * scale;
    let near = (10.0 * tolerance).max(0.02 * diag);
    let mut samples: Vec<C> = stroke.to_vec();
    let (mut t0, d0) = closest(curve, samples[0])?;
    let (mut t1, d1) = closest(curve, samples[samples.len() - 1])?;
    let replace =
        |samples: Vec<C>, t0: f64, t1: f64| build(curve, &samples, t0, t1, tolerance, (true, true));
    if closed {
        // The arc from t0 forward to t1 (wrapping) should hold the stroke's middle.
        let (tm, _) = closest(curve, samples[samples.len() / 2])?;
        let period = tb - ta;
        let forward = |a: f64, b: f64| (b - a).rem_euclid(period);
        if forward(t0, tm) > forward(t0, t1) {
            samples.reverse();
            std::mem::swap(&mut t0, &mut t1);
        }
        return replace(samples, t0, t1);
    }
    match (d0 <= near, d1 <= near) {
        (true, true) => {
            if t0 > t1 {
                samples.reverse();
                std::mem::swap(&mut t0, &mut t1);
            }
            replace(samples, t0, t1)
        }
        (true, false) => extend(curve, samples, t0, tolerance),
        (false, true) => {
            samples.reverse();
            extend(curve, samples, t1, tolerance)
        }
        (false, false) => {
            // From the curve end nearest to a stroke end.
            let n = samples.len() - 1;
            let options = [
                ((samples[0] - last).norm(), false, tb),
                ((samples[n] - last).norm(), true, tb),
                ((samples[0] - first).norm(), false, ta),
                ((samples[n] - first).norm(), true, ta),
            ];
            let best = options
                .iter()
                .min_by(|a, b| a.0.total_cmp(&b.0))
                .copied()
                .unwrap_or(options[0]);
            if best.1 {
                samples.reverse();
            }
            extend(curve, samples, best.2, tolerance)
        }
    }
}

/// The stroke starts at the curve's parameter `t` and leaves it: at an end of the curve it
/// continues the curve there (nothing replaced); inside, it replaces `[t, end]` when it leaves
/// along the curve's direction, else `[start, t]` (with the stroke reversed).
fn extend<C: Cartesian>(
    curve: &CompositeCurve<C>,
    mut samples: Vec<C>,
    t: f64,
    tol: f64,
) -> Result<Oversketch<C>> {
    let (ta, tb) = curve.domain();
    if t >= tb {
        return build(curve, &samples, tb, tb, tol, (true, false));
    }
    if t <= ta {
        samples.reverse();
        return build(curve, &samples, ta, ta, tol, (false, true));
    }
    let leave = samples[samples.len() - 1] - samples[0];
    if tangent(curve, t, true)?.dot_with(leave) >= 0.0 {
        build(curve, &samples, t, tb, tol, (true, false))
    } else {
        samples.reverse();
        build(curve, &samples, ta, t, tol, (false, true))
    }
}

/// The closest point of `curve` to `q`: its parameter and distance.
fn closest<C: Cartesian>(curve: &CompositeCurve<C>, q: C) -> Result<(f64, f64)> {
    let mut best = (f64::INFINITY, 0.0, 0usize);
    for (i, p) in curve.pieces().iter().enumerate() {
        let (a, b) = p.interval();
        for k in 0..=COARSE {
            let t = a + (b - a) * k as f64 / COARSE as f64;
            let d = (p.evaluate(t)? - q).norm();
            if d < best.0 {
                best = (d, t, i);
            }
        }
    }
    let p = &curve.pieces()[best.2];
    let (a, b) = p.interval();
    let h = (b - a) / COARSE as f64;
    let (mut lo, mut hi) = ((best.1 - h).max(a), (best.1 + h).min(b));
    // Golden-section search for the minimum of |P(t) − q| on the bracket.
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let f = |t: f64| p.evaluate(t).map(|x| (x - q).norm());
    let (mut x1, mut x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
    let (mut f1, mut f2) = (f(x1)?, f(x2)?);
    for _ in 0..80 {
        if f1 <= f2 {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = f(x1)?;
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = f(x2)?;
        }
    }
    let t = 0.5 * (lo + hi);
    let d = f(t)?;
    Ok(if d < best.0 { (t, d) } else { (best.1, best.0) })
}

/// The unit tangent of `curve` at `t`, from the piece on the left of a joint when `left`.
fn tangent<C: Cartesian>(curve: &CompositeCurve<C>, t: f64, left: bool) -> Result<C> {
    let mut i = curve.piece_index(t)?;
    let pieces = curve.pieces();
    if left && i > 0 && t <= pieces[i].interval().0 {
        i -= 1;
    }
    let p = &pieces[i];
    let mut d = p.derivative(t, 1)?;
    if d.norm() == 0.0 {
        // A vanishing velocity (repeated control points): the second derivative's direction.
        d = p.derivative(t, 2)?;
        let (a, b) = p.interval();
        if t >= b || (t > a && t - a > b - t) {
            d = d * -1.0;
        }
    }
    let n = d.norm();
    Ok(if n > 0.0 { d * (1.0 / n) } else { d })
}

/// The curve with the part from `t0` forward to `t1` (through the seam of a closed curve when
/// `t0 > t1`) replaced by a fit of `samples`, whose first / last sample is pinned to
/// `curve(t0)` / `curve(t1)` with the curve's tangent when `pinned.0` / `pinned.1`.
fn build<C: Cartesian>(
    curve: &CompositeCurve<C>,
    samples: &[C],
    t0: f64,
    t1: f64,
    tol: f64,
    pinned: (bool, bool),
) -> Result<Oversketch<C>> {
    let pieces = curve.pieces();
    let k = pieces.len();
    let mut work: Vec<C> = samples.to_vec();
    let n = work.len();
    let mut ends = (None, None);
    if pinned.0 {
        work[0] = curve.evaluate(t0)?;
        ends.0 = Some(tangent(curve, t0, true)?);
    }
    if pinned.1 {
        work[n - 1] = curve.evaluate(t1)?;
        ends.1 = Some(tangent(curve, t1, false)?);
    }
    let indices: Vec<usize> = (0..n).collect();
    let stroke = Stroke::from_parts(&work, &indices);
    let new: Vec<BezierCurve<C>> = if stroke.len() < 2 {
        Vec::new()
    } else {
        let found = corners::find(&stroke, false, tol);
        let m = stroke.len();
        let mut limits = vec![0];
        limits.extend(found.iter().map(|f| f.0).filter(|&i| i > 0 && i < m - 1));
        limits.push(m - 1);
        let layout = Layout {
            limits: &limits,
            seam: None,
            ends,
            c1: false,
        };
        let mut fitter = Fitter::default();
        segment(&stroke, &layout, tol, &mut fitter)
            .iter()
            .map(|p| super::curve::bezier(&p.cubic))
            .collect::<Result<_>>()?
    };
    // The kept parts: before t0 and after t1 (or, through the seam, after t1 then before t0).
    let (i0, i1) = (curve.piece_index(t0)?, curve.piece_index(t1)?);
    let local = |p: &BezierCurve<C>, t: f64| {
        let (a, b) = p.interval();
        ((t - a) / (b - a)).clamp(0.0, 1.0)
    };
    let head = |out: &mut Vec<BezierCurve<C>>| -> Result<()> {
        // Pieces before i0, then piece i0 on [a, t0].
        out.extend(pieces[..i0].iter().cloned());
        let s = local(&pieces[i0], t0);
        if s > 0.0 {
            out.push(pieces[i0].split(t0)?.0);
        }
        Ok(())
    };
    let tail = |out: &mut Vec<BezierCurve<C>>| -> Result<()> {
        // Piece i1 on [t1, b], then the pieces after i1.
        let s = local(&pieces[i1], t1);
        if s <= 0.0 {
            out.push(pieces[i1].clone());
        } else if s < 1.0 {
            out.push(pieces[i1].split(t1)?.1);
        }
        out.extend(pieces[i1 + 1..].iter().cloned());
        Ok(())
    };
    let mut out = Vec::with_capacity(k + new.len() + 2);
    let first_new;
    if t0 <= t1 {
        head(&mut out)?;
        first_new = out.len();
        out.extend(new.iter().cloned());
        let count = new.len();
        tail(&mut out)?;
        let result = finish(out)?;
        return Ok(Oversketch {
            curve: result,
            replaced: (t0, t1),
            new_pieces: (first_new, first_new + count),
        });
    }
    // Through the seam: the kept arc from t1 to the end, then from the start to t0, then new.
    tail(&mut out)?;
    head(&mut out)?;
    first_new = out.len();
    out.extend(new.iter().cloned());
    let count = new.len();
    Ok(Oversketch {
        curve: finish(out)?,
        replaced: (t0, t1),
        new_pieces: (first_new, first_new + count),
    })
}

/// The pieces on `[0, 1], [1, 2], …`.
fn finish<C: Cartesian>(pieces: Vec<BezierCurve<C>>) -> Result<CompositeCurve<C>> {
    let knots: Vec<f64> = (0..=pieces.len()).map(|i| i as f64).collect();
    CompositeCurve::new(pieces, &knots)
}
