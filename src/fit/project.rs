//! Distances from samples to a fitted B-spline, and Newton parameter correction.
//!
//! The distance of sample `Q_k` (at parameter `t_k`) to the curve is measured near its
//! parameter: a coarse bracket (the curve at nine parameters evenly over `[t_{k−2}, t_{k+2}]`,
//! plus `t_k`), then Newton's method on `f(t) = C'(t)·(C(t) − Q_k)`,
//! `t ← t − f/f'` with `f' = C''·(C − Q_k) + |C'|²`, clamped to the window, keeping the closest
//! point met. It is the distance to a point of the curve, so it is never below the true
//! closest-point distance: a tolerance it meets is met.
//!
//! The largest distance over all samples is found without projecting every sample: each
//! `|C(t_k) − Q_k|` bounds its sample's distance from above, so a sample is projected only when
//! its bound exceeds the largest distance found so far (after a parameter correction the
//! bounds are tight, so few are).
//!
//! For a periodic curve (domain `[0, 1]`) parameters wrap: `t` and `t ± 1` are one point.

use crate::bspline::BSplineCurve;
use crate::error::Result;
use crate::geom::Cartesian;

/// Newton steps in a measurement and in a parameter correction.
const MEASURE_STEPS: usize = 4;
const CORRECT_STEPS: usize = 3;
/// Bracket points of a measurement.
const BRACKET: usize = 8;

/// A fitted curve and how its parameters behave.
pub(super) struct Fitted<'a, C: Cartesian> {
    pub curve: &'a BSplineCurve<C>,
    /// Domain `[0, 1]`, wrapping.
    pub periodic: bool,
}

impl<C: Cartesian> Fitted<'_, C> {
    /// `t` in the domain (wrapped when periodic, clamped otherwise).
    fn wrap(&self, t: f64) -> f64 {
        if self.periodic {
            super::wrap(t, 1.0)
        } else {
            t.clamp(0.0, 1.0)
        }
    }

    fn point(&self, t: f64) -> Result<C> {
        self.curve.evaluate(self.wrap(t))
    }

    /// One Newton step from `t` toward the foot of the perpendicular from `q`, clamped to
    /// `[lo, hi]`; `None` when `f' ≤ 0` (no minimum nearby along the step).
    fn newton_step(&self, q: C, t: f64, lo: f64, hi: f64) -> Result<Option<f64>> {
        let u = self.wrap(t);
        let c = self.curve.evaluate(u)?;
        let d1 = self.curve.derivative(u, 1)?;
        let d2 = self.curve.derivative(u, 2)?;
        let r = c - q;
        let f = d1.dot_with(r);
        let fp = d2.dot_with(r) + d1.dot_with(d1);
        if fp <= 0.0 || !fp.is_finite() {
            return Ok(None);
        }
        Ok(Some((t - f / fp).clamp(lo, hi)))
    }

    /// The window of sample `k`: its neighbours' parameters two samples away (unwrapped
    /// around `t_k` when periodic).
    fn window(&self, params: &[f64], k: usize) -> (f64, f64) {
        let m = params.len();
        let t = params[k];
        if self.periodic {
            let back = super::wrap(t - params[(k + m - 2.min(m - 1)) % m], 1.0);
            let ahead = super::wrap(params[(k + 2) % m] - t, 1.0);
            (t - back, t + ahead)
        } else {
            (params[k.saturating_sub(2)], params[(k + 2).min(m - 1)])
        }
    }

    /// The distance of `q` to the curve near `params[k]` (bracket, then Newton).
    pub fn distance(&self, q: C, params: &[f64], k: usize) -> Result<f64> {
        let (lo, hi) = self.window(params, k);
        let mut best_t = params[k];
        let mut best = (self.point(best_t)? - q).norm();
        for i in 0..=BRACKET {
            let t = lo + (hi - lo) * i as f64 / BRACKET as f64;
            let d = (self.point(t)? - q).norm();
            if d < best {
                (best, best_t) = (d, t);
            }
        }
        let mut t = best_t;
        for _ in 0..MEASURE_STEPS {
            let Some(next) = self.newton_step(q, t, lo, hi)? else {
                break;
            };
            let d = (self.point(next)? - q).norm();
            if d < best {
                best = d;
            }
            if next == t {
                break;
            }
            t = next;
        }
        Ok(best)
    }

    /// The largest distance of a sample to the curve and its index (see the module doc):
    /// `bounds[k]` is `|C(t_k) − Q_k|` (from [`Fitted::correct`]); a sample is projected only
    /// when its bound exceeds the largest distance found so far.
    pub fn max_distance(
        &self,
        samples: &[C],
        params: &[f64],
        bounds: &[f64],
    ) -> Result<(f64, usize)> {
        let (mut max, mut worst) = (0.0, 0);
        for (k, &bound) in bounds.iter().enumerate() {
            if bound <= max {
                continue;
            }
            let d = self.distance(samples[k], params, k)?.min(bound);
            if d > max {
                (max, worst) = (d, k);
            }
        }
        Ok((max, worst))
    }

    /// Moves every parameter toward its sample's foot point (Newton steps that bring the
    /// curve point closer) and returns the sum of the squared distances met; `dists[k]`
    /// receives `|C(t_k) − Q_k|` at the new parameter. An open curve's parameters stay
    /// strictly increasing with the ends fixed; `None` (parameters unchanged) if that cannot
    /// be kept.
    pub fn correct(
        &self,
        samples: &[C],
        params: &mut [f64],
        scratch: &mut Vec<f64>,
        dists: &mut Vec<f64>,
    ) -> Result<Option<f64>> {
        let m = params.len();
        dists.clear();
        dists.resize(m, 0.0);
        let mut sum = 0.0;
        scratch.clear();
        scratch.extend_from_slice(params);
        let old = &*scratch;
        for k in 0..m {
            if !self.periodic && (k == 0 || k == m - 1) {
                dists[k] = (self.point(old[k])? - samples[k]).norm();
                continue;
            }
            let (lo, hi) = if self.periodic {
                (old[k] - 0.5, old[k] + 0.5)
            } else {
                (0.0, 1.0)
            };
            let q = samples[k];
            let mut t = old[k];
            let mut d = (self.point(t)? - q).norm();
            for _ in 0..CORRECT_STEPS {
                let Some(next) = self.newton_step(q, t, lo, hi)? else {
                    break;
                };
                let dn = (self.point(next)? - q).norm();
                if dn >= d {
                    break;
                }
                (t, d) = (next, dn);
            }
            sum += d * d;
            dists[k] = d;
            params[k] = if self.periodic {
                super::wrap(t, 1.0)
            } else {
                t
            };
        }
        if self.periodic {
            return Ok(Some(sum));
        }
        // Strictly increasing, ends fixed: push each parameter just past its predecessor.
        let step = (params[m - 1] - params[0]) * 1e-9 / m as f64;
        for k in 1..m - 1 {
            if params[k] <= params[k - 1] {
                params[k] = params[k - 1] + step;
                dists[k] = (self.point(params[k])? - samples[k]).norm();
            }
        }
        if params[m - 2] >= params[m - 1] {
            params.copy_from_slice(&scratch[..]);
            return Ok(None);
        }
        Ok(Some(sum))
    }

    /// The squared-distance metric of every sample at `params` with tangential weight `weight`
    /// (see [`super::weighted`]),
    /// `dim²` numbers each, into `out`.
    pub fn metrics(&self, params: &[f64], weight: f64, out: &mut Vec<f64>) -> Result<()> {
        let d2 = C::DIM * C::DIM;
        out.clear();
        out.resize(params.len() * d2, 0.0);
        for (k, &t) in params.iter().enumerate() {
            let tangent = self.curve.derivative(self.wrap(t), 1)?;
            super::weighted::metric(tangent, weight, &mut out[k * d2..(k + 1) * d2]);
        }
        Ok(())
    }
}
