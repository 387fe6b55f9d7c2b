//! [`fit_bspline`]: one B-spline of a given degree through a stroke, with the fewest control
//! points that keep every sample within the tolerance.
//!
//! **Parameters.** Repeated consecutive samples are merged; the others get chord-length
//! parameters scaled to `[0, 1]` (closed: the closing chord back to the first sample counts,
//! so the samples lie in `[0, 1)` with period 1).
//!
//! **One count `n`.** Open: the least-squares curve of section 5 ([`approximate_flat`], ends
//! interpolated, knots by NURBS Book eq. 9.69 from the parameters). Closed: the periodic
//! least-squares curve ([`super::periodic`] knots). Then rounds of parameter correction (Newton
//! projection of each sample onto the curve) and the squared-distance fit of
//! [`super::weighted`] (see [`Problem::fit`]); the error is measured as in [`super::project`]:
//! the largest distance from a sample to the curve.
//!
//! **The search.** The error falls roughly monotonically with `n`, so `n` doubles from `p + 1`
//! until a fit meets the tolerance (at worst `n` = the number of samples, an interpolant: error
//! 0), then bisection finds the boundary, then the few counts just below it are tried too (the
//! error is not exactly monotone). Strokes of more than [`SEARCH_SAMPLES`] samples are searched
//! on every `s`-th sample; the curve found is measured on all samples (their parameters spread
//! from the subset's), and the count raised by a quarter until it holds (at most
//! [`FULL_TRIES`] counts; the reported error is then the measured one, which can exceed the
//! tolerance when the samples between carry more noise than the subset).
//!
//! **Budget.** About 20 ms for 500 samples, 0.4 s for 5 000 and 1 s for 100 000 (native,
//! release); strokes above [`MAX_BSPLINE_FIT_SAMPLES`] are refused ([`Error::TooLarge`]): the
//! measurement alone costs about 1.5 µs a sample.
//!
//! **Closed.** `Some(true)`, or `None` when the stroke ends near where it began (the rule
//! [`super::fit_curve`] follows too, `super::ends_meet`): a periodic curve
//! ([`BSplineCurve::wrapped`] `= p`), `C^{p−1}` at the seam. It needs `max(3, p + 1)` distinct
//! samples.
//!
//! **Tame curves only.** A fit whose control points leave the samples' bounding box grown by
//! its diagonal is no fit (near interpolation, a least-squares curve can pass every sample and
//! swing far away between them), whatever its error at the samples.
//!
//! **Degenerate strokes.** Identical samples give the constant curve (`p + 1` equal control
//! points). An open stroke of fewer distinct samples than `p + 1` gets the one polynomial piece
//! through them: the interpolating polynomial of degree (samples − 1) at the chord parameters,
//! degree-elevated to `p` (a Bézier curve, `p + 1` control points, error 0). Collinear samples
//! are no special case (the fit is a straight curve).

use super::periodic::periodic_knots;
use super::project::Fitted;
use super::weighted::weighted_fit;
use super::{check_stroke, BSplineFit};
use crate::bspline::BSplineCurve;
use crate::curve::ControlPolygon;
use crate::error::{Error, Result};
use crate::geom::Cartesian;
use crate::interp::global::knots::least_squares_knots;
use crate::interp::least_squares::{approximate_flat, curve_from};

/// Newton parameter corrections per count.
const CORRECTIONS: usize = 8;
/// The tangential weight of the first squared-distance round, and its floor.
const FIRST_WEIGHT: f64 = 0.02;
const MIN_WEIGHT: f64 = 1e-3;
/// A round that lowers the sum of squared distances by less than this fraction ends the fit.
const STALL: f64 = 1e-3;
/// Counts below the bisection's boundary tried as well.
const BELOW: usize = 2;
/// Above this many samples the count is searched on a subset.
pub(crate) const SEARCH_SAMPLES: usize = 8192;
/// Counts (each checked on all samples) tried on a long stroke's subset.
const FULL_TRIES: usize = 3;
/// The most samples [`fit_bspline`] takes (about a second natively; see the module doc).
pub const MAX_BSPLINE_FIT_SAMPLES: usize = 100_000;

/// Fits a B-spline of degree `degree` to the samples `points` with the fewest control points
/// that keep every sample within `tolerance` (see the module doc); `closed`: `None` closes it
/// when the stroke ends near its start.
///
/// # Errors
/// Those of [`check_stroke`]; [`Error::TooLarge`] (`"stroke"`) above
/// [`MAX_BSPLINE_FIT_SAMPLES`]; [`Error::DegreeOutOfRange`] outside `1..=10`;
/// [`Error::TooFewDataPoints`] (`"stroke"`) for a closed curve from fewer than `max(3, p + 1)`
/// distinct samples; [`Error::SingularSystem`] if no count gives a solvable system.
pub fn fit_bspline<C: Cartesian>(
    points: &[C],
    degree: usize,
    tolerance: f64,
    closed: Option<bool>,
) -> Result<BSplineFit<C>> {
    check_stroke(points, tolerance)?;
    if points.len() > MAX_BSPLINE_FIT_SAMPLES {
        return Err(Error::TooLarge {
            what: "stroke",
            value: points.len(),
            max: MAX_BSPLINE_FIT_SAMPLES,
        });
    }
    crate::interp::global::check_interpolation_degree(degree)?;
    let p = degree;
    // Distinct consecutive samples and the original index of each.
    let mut kept: Vec<usize> = Vec::with_capacity(points.len());
    for (i, q) in points.iter().enumerate() {
        if kept.last().is_none_or(|&j| points[j] != *q) {
            kept.push(i);
        }
    }
    let first = points[0];
    // A loop's samples: the last is dropped when it repeats the first.
    let mut loop_len = kept.len();
    if loop_len > 1 && points[kept[loop_len - 1]] == first {
        loop_len -= 1;
    }
    let needed = 3.max(p + 1);
    let closed = match closed {
        Some(c) => c,
        None => super::ends_meet(points, tolerance) && loop_len >= needed,
    };
    let samples: Vec<C> = kept.iter().map(|&i| points[i]).collect();
    if closed {
        if loop_len < needed {
            return Err(Error::TooFewDataPoints {
                needed,
                got: loop_len,
                what: "stroke",
            });
        }
        kept.truncate(loop_len);
        let samples = &samples[..loop_len];
        let problem = Problem::new(samples, p, tolerance, true);
        let fit = problem.search()?;
        return Ok(BSplineFit {
            curve: fit.curve,
            max_error: fit.error,
            worst: kept[fit.worst],
            closed: true,
        });
    }
    if samples.len() == 1 {
        let knots = [vec![0.0; p + 1], vec![1.0; p + 1]].concat();
        return Ok(BSplineFit {
            curve: BSplineCurve::new(vec![first; p + 1], p, knots, None)?,
            max_error: 0.0,
            worst: 0,
            closed: false,
        });
    }
    let problem = Problem::new(&samples, p, tolerance, false);
    let fit = if samples.len() < p + 1 {
        problem.short()?
    } else {
        problem.search()?
    };
    Ok(BSplineFit {
        curve: fit.curve,
        max_error: fit.error,
        worst: kept[fit.worst],
        closed: false,
    })
}

/// One fit with a given count.
struct Attempt<C: Cartesian> {
    count: usize,
    curve: BSplineCurve<C>,
    error: f64,
    worst: usize,
    /// The samples' foot parameters on the curve.
    params: Vec<f64>,
}

/// Distinct samples, their chord parameters, and what to fit.
struct Problem<'a, C: Cartesian> {
    samples: std::borrow::Cow<'a, [C]>,
    chord: Vec<f64>,
    degree: usize,
    tolerance: f64,
    periodic: bool,
    /// The samples' bounding box grown by its diagonal (see [`Problem::tame`]).
    fence: (C, C),
}

impl<'a, C: Cartesian> Problem<'a, C> {
    /// Whether every control point lies inside the fence: the samples' bounding box grown by
    /// its diagonal. A least-squares curve with nearly as many control points as samples can
    /// pass every sample and still swing far away between them (a span the corrected
    /// parameters left empty); such a curve is no fit, whatever its error at the samples.
    fn tame(&self, curve: &BSplineCurve<C>) -> bool {
        let (lo, hi) = self.fence;
        curve
            .control_points()
            .iter()
            .all(|&q| q.max_by_coord(lo) == q && q.min_by_coord(hi) == q)
    }

    fn new(samples: &'a [C], degree: usize, tolerance: f64, periodic: bool) -> Self {
        let mut chord = Vec::with_capacity(samples.len());
        let mut s = 0.0;
        chord.push(0.0);
        for w in samples.windows(2) {
            s += (w[1] - w[0]).norm();
            chord.push(s);
        }
        let total = if periodic {
            s + (samples[0] - samples[samples.len() - 1]).norm()
        } else {
            s
        };
        for t in &mut chord {
            *t /= total;
        }
        if !periodic {
            let last = chord.len() - 1;
            chord[last] = 1.0;
        }
        let (mut lo, mut hi) = (samples[0], samples[0]);
        for &q in samples {
            (lo, hi) = (lo.min_by_coord(q), hi.max_by_coord(q));
        }
        let grow = (hi - lo).norm().max(tolerance);
        let margin = C::from_slice(&[grow; 3]);
        Problem {
            samples: std::borrow::Cow::Borrowed(samples),
            chord,
            degree,
            tolerance,
            periodic,
            fence: (lo - margin, hi + margin),
        }
    }

    /// The indices of every `step`-th sample (and the last when open).
    fn subset_indices(&self, step: usize) -> Vec<usize> {
        let m = self.samples.len();
        let mut idx: Vec<usize> = (0..m).step_by(step).collect();
        if !self.periodic && idx.last() != Some(&(m - 1)) {
            idx.push(m - 1);
        }
        idx
    }

    /// Parameters for every sample from those of the subset `idx`: linear in the sample index
    /// between subset samples (across the seam when periodic).
    fn spread(&self, idx: &[usize], sub_params: &[f64]) -> Vec<f64> {
        let m = self.samples.len();
        let mut out = vec![0.0; m];
        for (j, &i) in idx.iter().enumerate() {
            let (next, b) = match idx.get(j + 1) {
                Some(&n) => (n, sub_params[j + 1]),
                None if self.periodic => (m, sub_params[0] + 1.0),
                None => (i + 1, sub_params[j]),
            };
            let a = sub_params[j];
            // Periodic: the representative of `b` nearest `a`.
            let b = if self.periodic {
                a + super::wrap(b - a + 0.5, 1.0) - 0.5
            } else {
                b
            };
            for (k, slot) in out.iter_mut().enumerate().take(next.min(m)).skip(i) {
                let t = a + (b - a) * (k - i) as f64 / (next - i) as f64;
                *slot = if self.periodic {
                    super::wrap(t, 1.0)
                } else {
                    t
                };
            }
        }
        out
    }

    /// The samples `idx`, with the same parameters.
    fn subset(&self, idx: &[usize]) -> Problem<'a, C> {
        Problem {
            samples: std::borrow::Cow::Owned(idx.iter().map(|&i| self.samples[i]).collect()),
            chord: idx.iter().map(|&i| self.chord[i]).collect(),
            degree: self.degree,
            tolerance: self.tolerance,
            periodic: self.periodic,
            fence: self.fence,
        }
    }

    /// The samples' coordinates, flat.
    fn flat(&self) -> Vec<f64> {
        let mut coords = Vec::with_capacity(self.samples.len() * C::DIM);
        for q in self.samples.iter() {
            coords.extend((0..C::DIM).map(|k| q.coord(k)));
        }
        coords
    }

    /// The least-squares curve for `params`: plain (section 5's engine when open) without
    /// `metrics`, else weighted by them ([`weighted_fit`]).
    fn solve(
        &self,
        count: usize,
        knots: &[f64],
        params: &[f64],
        metrics: Option<&[f64]>,
    ) -> Result<BSplineCurve<C>> {
        let p = self.degree;
        if self.periodic || metrics.is_some() {
            return weighted_fit(
                &self.samples,
                params,
                metrics,
                p,
                count,
                knots,
                self.periodic,
            );
        }
        let coords = self.flat();
        let (control, knots) = approximate_flat(&coords, C::DIM, p, count, params, Some(knots))?;
        curve_from(&control, p, knots)
    }

    /// The fit with `count` control points from the parameters `start`: the plain
    /// least-squares curve there, then at most [`CORRECTIONS`] rounds of the squared-distance
    /// fit ([`weighted_fit`]) at the samples' foot points, damped like Levenberg–Marquardt: a
    /// round that does not lower the sum of squared distances is dropped and the tangential
    /// weight `w` raised (toward plain point distances), one that does lowers it. Stops once
    /// the tolerance is met or a round gains less than [`STALL`]; returns the best curve met.
    fn fit(&self, count: usize, start: &[f64]) -> Result<Attempt<C>> {
        let p = self.degree;
        // Knots from the chord parameters, fixed for the count (corrected parameters bunch
        // up where the curve rounds a corner, and knots placed from them would too).
        let knots = if self.periodic {
            periodic_knots(&self.chord, p, count)
        } else {
            least_squares_knots(&self.chord, p, count)
        };
        let (mut dists, mut scratch) = (Vec::new(), Vec::new());
        let mut metrics: Vec<f64> = Vec::new();
        let mut params = start.to_vec();
        let curve = self.solve(count, &knots, &params, None)?;
        let fitted = Fitted {
            curve: &curve,
            periodic: self.periodic,
        };
        let mut best_sum = fitted
            .correct(&self.samples, &mut params, &mut scratch, &mut dists)?
            .unwrap_or(f64::INFINITY);
        let (mut error, worst) = fitted.max_distance(&self.samples, &params, &dists)?;
        if !self.tame(&curve) {
            (error, best_sum) = (f64::INFINITY, f64::INFINITY);
        }
        let mut best = Attempt {
            count,
            curve,
            error,
            worst,
            params: params.clone(),
        };
        let mut weight = FIRST_WEIGHT;
        for _ in 0..CORRECTIONS {
            if best.error <= self.tolerance {
                break;
            }
            Fitted {
                curve: &best.curve,
                periodic: self.periodic,
            }
            .metrics(&best.params, weight, &mut metrics)?;
            let curve = match self.solve(count, &knots, &best.params, Some(&metrics)) {
                Ok(c) if self.tame(&c) => c,
                _ => {
                    weight = (weight * 8.0).min(1.0);
                    continue;
                }
            };
            let fitted = Fitted {
                curve: &curve,
                periodic: self.periodic,
            };
            params.copy_from_slice(&best.params);
            match fitted.correct(&self.samples, &mut params, &mut scratch, &mut dists)? {
                Some(sum) if sum < best_sum => {
                    let (error, worst) = fitted.max_distance(&self.samples, &params, &dists)?;
                    let gain = 1.0 - sum / best_sum;
                    best_sum = sum;
                    best.params.copy_from_slice(&params);
                    (best.curve, best.error, best.worst) = (curve, error, worst);
                    weight = (weight * 0.25).max(MIN_WEIGHT);
                    if gain < STALL {
                        break;
                    }
                }
                _ => weight = (weight * 8.0).min(1.0),
            }
        }
        Ok(best)
    }

    /// The smallest count in `p + 1 ..= samples` that meets the tolerance (see the module
    /// doc), or the best fit met when none does.
    fn search(&self) -> Result<Attempt<C>> {
        let m = self.samples.len();
        if m <= SEARCH_SAMPLES {
            return self.search_counts(self.degree + 1, m);
        }
        let idx = self.subset_indices(m.div_ceil(SEARCH_SAMPLES));
        let sub = self.subset(&idx);
        let mut fit = sub.search()?;
        let mut best: Option<Attempt<C>> = None;
        for _ in 0..FULL_TRIES {
            // Every sample's foot parameter on the subset's curve, and the largest distance.
            let mut params = self.spread(&idx, &fit.params);
            let fitted = Fitted {
                curve: &fit.curve,
                periodic: self.periodic,
            };
            let mut dists = Vec::new();
            fitted.correct(&self.samples, &mut params, &mut Vec::new(), &mut dists)?;
            let (error, worst) = fitted.max_distance(&self.samples, &params, &dists)?;
            let count = fit.count;
            let attempt = Attempt {
                error,
                worst,
                params,
                ..fit
            };
            let ok = error <= self.tolerance;
            if ok || best.as_ref().is_none_or(|b| error < b.error) {
                best = Some(attempt);
            }
            if ok || count >= sub.samples.len() {
                break;
            }
            fit = sub.fit(
                (count + count.div_ceil(4)).min(sub.samples.len()),
                &sub.chord,
            )?;
        }
        best.ok_or(Error::SingularSystem {
            what: "least-squares-system",
            row: 0,
        })
    }

    /// Doubling from `min`, bisection, then a few counts below (see the module doc); each fit
    /// starts from the chord parameters.
    fn search_counts(&self, min: usize, max: usize) -> Result<Attempt<C>> {
        let tol = self.tolerance;
        let mut closest: Option<Attempt<C>> = None;
        let mut good: Option<Attempt<C>> = None;
        let mut lo = min - 1; // the largest count known to fail (none yet: min − 1)
        let mut count = min;
        loop {
            if let Ok(a) = self.fit(count, &self.chord) {
                if a.error <= tol {
                    good = Some(a);
                    break;
                }
                if closest.as_ref().is_none_or(|b| a.error < b.error) {
                    closest = Some(a);
                }
            }
            lo = count;
            if count >= max {
                break;
            }
            count = (count * 2).min(max);
        }
        let Some(mut good) = good else {
            return closest.ok_or(Error::SingularSystem {
                what: "least-squares-system",
                row: 0,
            });
        };
        let tries = |count: usize, good: &mut Attempt<C>| -> bool {
            match self.fit(count, &self.chord) {
                Ok(a) if a.error <= tol => {
                    *good = a;
                    true
                }
                _ => false,
            }
        };
        // Bisection between the last failure and the first success.
        while good.count - lo > 1 {
            let mid = lo + (good.count - lo) / 2;
            if !tries(mid, &mut good) {
                lo = mid;
            }
        }
        // A little below the boundary (the error is not exactly monotone in the count).
        let floor = min.max(good.count.saturating_sub(BELOW + 1));
        for count in (floor..good.count.saturating_sub(1)).rev() {
            tries(count, &mut good);
        }
        Ok(good)
    }

    /// Fewer distinct samples than `p + 1` (open): the interpolating polynomial through them at
    /// the chord parameters, as a Bézier curve degree-elevated to `p` (see the module doc).
    fn short(&self) -> Result<Attempt<C>> {
        let q = self.samples.len() - 1;
        let p = self.degree;
        let coords = self.flat();
        let (flat, _) = approximate_flat(&coords, C::DIM, q, q + 1, &self.chord, None)?;
        // Bézier degree elevation r → r + 1: R_i = (i/(r+1)) P_{i−1} + (1 − i/(r+1)) P_i.
        let mut control: Vec<C> = flat.chunks_exact(C::DIM).map(C::from_slice).collect();
        for r in q..p {
            let next: Vec<C> = (0..=r + 1)
                .map(|i| {
                    let a = i as f64 / (r + 1) as f64;
                    let left = if i > 0 { control[i - 1] } else { C::ZERO };
                    let right = if i <= r { control[i] } else { C::ZERO };
                    left * a + right * (1.0 - a)
                })
                .collect();
            control = next;
        }
        let knots = [vec![0.0; p + 1], vec![1.0; p + 1]].concat();
        let curve = BSplineCurve::new(control, p, knots, None)?;
        let fitted = Fitted {
            curve: &curve,
            periodic: false,
        };
        let mut params = self.chord.clone();
        let mut dists = Vec::new();
        fitted.correct(&self.samples, &mut params, &mut Vec::new(), &mut dists)?;
        let (error, worst) = fitted.max_distance(&self.samples, &params, &dists)?;
        Ok(Attempt {
            count: p + 1,
            curve,
            error,
            worst,
            params,
        })
    }
}
