//! Lagrange's interpolating polynomial (syllabus §5) in barycentric form, with Aitken's
//! triangle as teaching data.
//!
//! `P(t) = Σ L_i(t) p_i`, `L_i(t) = Π_{j≠i} (t − t_j)/(t_i − t_j)`. Evaluation uses the second
//! (true) barycentric formula `P(t) = Σ (w_i/(t − t_i)) p_i / Σ w_i/(t − t_i)` with the weights
//! `w_i = 1/Π_{j≠i}(t_i − t_j)`: O(n) per point, exactly `p_i` at a node, and stable even for
//! many points (Berrut & Trefethen 2004). The weights are computed on the parameters scaled to
//! an interval of length 4 (a common factor, which cancels), so they neither overflow nor
//! underflow for the allowed number of points.

use super::params::{check_point_count, ParamChoice};
use crate::error::{check_in_range, Error, Result};
use crate::geom::{check_out_len, check_table_count, Cartesian, Params, MAX_DEGREE};

/// The interpolating polynomial of degree ≤ n through `p_0..p_n` at `t_0 < … < t_n`.
#[derive(Debug, Clone, PartialEq)]
pub struct LagrangeCurve<C: Cartesian> {
    points: Vec<C>,
    params: Vec<f64>,
    weights: Vec<f64>,
    /// Where the parameters came from: a spacing is recomputed when a point moves.
    choice: ParamChoice,
}

/// Largest number of data points of a Lagrange curve (degree [`MAX_DEGREE`]).
pub const MAX_LAGRANGE_POINTS: usize = MAX_DEGREE + 1;

/// The barycentric weights `w_i = 1/Π_{j≠i}(t_i − t_j)`, computed on the parameters scaled to
/// an interval of length 4 (a common factor, which cancels in the barycentric formula).
fn barycentric_weights(params: &[f64]) -> Vec<f64> {
    let n = params.len();
    let scale = 4.0 / (params[n - 1] - params[0]);
    (0..n)
        .map(|i| {
            let product: f64 = (0..n)
                .filter(|&j| j != i)
                .map(|j| (params[i] - params[j]) * scale)
                .product();
            1.0 / product
        })
        .collect()
}

impl<C: Cartesian> LagrangeCurve<C> {
    /// The polynomial through `points` at `params`.
    ///
    /// # Errors
    /// [`Error::TooFewDataPoints`] below 2 points, [`Error::TooLarge`] above
    /// [`MAX_LAGRANGE_POINTS`], [`Error::NotFinite`] or [`Error::CoordinateTooLarge`] for a
    /// coordinate, then as [`check_params`](super::check_params).
    pub fn new(points: Vec<C>, params: &[f64]) -> Result<Self> {
        Self::with_params(points, ParamChoice::Given(params.to_vec()))
    }

    /// The polynomial through `points` at given parameters or at a spacing computed from the
    /// points (then recomputed by [`LagrangeCurve::set_point`]).
    ///
    /// # Errors
    /// As [`LagrangeCurve::new`], and [`Error::CoincidentPoints`] for a spacing with α > 0 and
    /// a repeated point.
    pub fn with_params(points: Vec<C>, choice: ParamChoice) -> Result<Self> {
        check_point_count(points.len(), 2, "lagrange-curve")?;
        if points.len() > MAX_LAGRANGE_POINTS {
            return Err(Error::TooLarge {
                what: "lagrange-point-count",
                value: points.len(),
                max: MAX_LAGRANGE_POINTS,
            });
        }
        super::global::check_points(&points)?;
        let params = choice.resolve(&points)?;
        let weights = barycentric_weights(&params);
        Ok(LagrangeCurve {
            points,
            params,
            weights,
            choice,
        })
    }

    /// The data points.
    pub fn points(&self) -> &[C] {
        &self.points
    }

    /// The parameters `t_0 < … < t_n`.
    pub fn params(&self) -> &[f64] {
        &self.params
    }

    /// The degree bound n (number of points − 1).
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    /// The domain `[t_0, t_n]`.
    pub fn domain(&self) -> (f64, f64) {
        (self.params[0], self.params[self.params.len() - 1])
    }

    /// Moves data point i in place. Given parameters (and so the weights) stay; a spacing is
    /// recomputed from the moved points, with new weights. On an error the curve is unchanged.
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`], [`Error::NotFinite`], [`Error::CoincidentPoints`] for a
    /// spacing with α > 0 and a repeated point.
    pub fn set_point(&mut self, i: usize, p: C) -> Result<()> {
        crate::geom::check::check_point_edit(i, self.points.len(), p)?;
        if let ParamChoice::Spacing(_) = self.choice {
            let mut points = self.points.clone();
            points[i] = p;
            self.params = self.choice.resolve(&points)?;
            self.weights = barycentric_weights(&self.params);
        }
        self.points[i] = p;
        Ok(())
    }

    /// The node index `i` with `t = t_i`, if any.
    fn node(&self, t: f64) -> Option<usize> {
        self.params.binary_search_by(|x| x.total_cmp(&t)).ok()
    }

    /// Every `L_i(t)`, i = 0..n (they sum to 1): `e_i` at the node `t_i`, else
    /// `(w_i/(t − t_i)) / Σ_j w_j/(t − t_j)`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::ParameterOutOfRange`] outside the domain.
    pub fn basis(&self, t: f64) -> Result<Vec<f64>> {
        check_in_range("t", t, self.domain())?;
        let mut out = vec![0.0; self.params.len()];
        self.basis_at(t, &mut out);
        Ok(out)
    }

    /// Every `L_i(t)` into `out` (n + 1 values; t already checked): exactly the unit vector at a
    /// node, else the barycentric form `L_i(t) = (w_i/(t − t_i)) / Σ_j w_j/(t − t_j)`.
    fn basis_at(&self, t: f64, out: &mut [f64]) {
        out.fill(0.0);
        if let Some(i) = self.node(t) {
            out[i] = 1.0;
            return;
        }
        let mut sum = 0.0;
        for ((o, &w), &ti) in out.iter_mut().zip(&self.weights).zip(&self.params) {
            *o = w / (t - ti);
            sum += *o;
        }
        for o in out.iter_mut() {
            *o /= sum;
        }
    }

    /// The point at t by the barycentric formula (exactly `p_i` at a node).
    fn point_at(&self, t: f64) -> C {
        if let Some(i) = self.node(t) {
            return self.points[i];
        }
        let mut numerator = C::ZERO;
        let mut denominator = 0.0;
        for ((&p, &w), &ti) in self.points.iter().zip(&self.weights).zip(&self.params) {
            let c = w / (t - ti);
            numerator = numerator + p * c;
            denominator += c;
        }
        numerator * (1.0 / denominator)
    }

    /// The point `P(t)`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::ParameterOutOfRange`] outside the domain.
    pub fn evaluate(&self, t: f64) -> Result<C> {
        check_in_range("t", t, self.domain())?;
        Ok(self.point_at(t))
    }

    /// Writes `P(t)` for every parameter into `out` (`len·DIM` numbers).
    fn sample_params_into(&self, params: Params, out: &mut [f64]) -> Result<()> {
        check_out_len(out.len(), params.len(), C::DIM, self.degree())?;
        let domain = self.domain();
        for (k, o) in out.chunks_exact_mut(C::DIM).enumerate() {
            let t = check_in_range("t", params.get(k), domain)?;
            self.point_at(t).write_to(o);
        }
        Ok(())
    }

    /// `P(t)` for every t of `ts` into `out`, flat.
    ///
    /// # Errors
    /// [`Error::BufferLength`], then as [`LagrangeCurve::evaluate`] for the first bad t.
    pub fn sample_into(&self, ts: &[f64], out: &mut [f64]) -> Result<()> {
        self.sample_params_into(Params::Slice(ts), out)
    }

    /// `count` points at equally spaced t over the domain (ends included) into `out`.
    ///
    /// # Errors
    /// [`Error::TooLarge`] above the sample cap, [`Error::BufferLength`].
    pub fn sample_uniform_into(&self, count: usize, out: &mut [f64]) -> Result<()> {
        let (a, b) = self.domain();
        self.sample_params_into(Params::uniform(a, b, count), out)
    }

    /// Every basis function `L_i` at `count` equally spaced t over the domain (ends included, the
    /// t of [`LagrangeCurve::sample_uniform_into`]), i-major: `(n + 1)·count` numbers,
    /// `L_i(t_k)` at `i·count + k` — the basis under the curve in one call (as
    /// `BSplineCurve::basis_curves`).
    ///
    /// # Errors
    /// [`Error::TooLarge`] when `(n + 1)·count` exceeds the sample cap.
    pub fn basis_curves(&self, count: usize) -> Result<Vec<f64>> {
        let functions = self.params.len();
        check_table_count(count, functions)?;
        let total = count * functions;
        let (a, b) = self.domain();
        let params = Params::uniform(a, b, count);
        let mut out = vec![0.0; total];
        let mut values = vec![0.0; functions];
        for k in 0..count {
            self.basis_at(params.get(k).clamp(a, b), &mut values);
            for (i, &v) in values.iter().enumerate() {
                out[i * count + k] = v;
            }
        }
        Ok(out)
    }

    /// Aitken's triangle at t: level 0 the points `p_i^0 = p_i`, then for r = 1..n the
    /// `n + 1 − r` points
    /// `p_i^r = (t_{i+r} − t)/(t_{i+r} − t_i) p_i^{r−1} + (t − t_i)/(t_{i+r} − t_i) p_{i+1}^{r−1}`
    /// (the interpolant of `p_i..p_{i+r}` at t), levels concatenated; the last is `P(t) = p_0^n`.
    /// `(n+1)(n+2)/2` points. Unlike de Casteljau's, the weights leave [0, 1]: not convex.
    ///
    /// # Errors
    /// As [`LagrangeCurve::evaluate`].
    pub fn aitken(&self, t: f64) -> Result<Vec<C>> {
        check_in_range("t", t, self.domain())?;
        let n = self.points.len();
        let mut out = Vec::with_capacity(n * (n + 1) / 2);
        out.extend_from_slice(&self.points);
        let mut start = 0;
        for r in 1..n {
            let prev = start;
            start = out.len();
            for i in 0..n - r {
                let (ti, tr) = (self.params[i], self.params[i + r]);
                let a = out[prev + i];
                let b = out[prev + i + 1];
                let d = tr - ti;
                out.push(a * ((tr - t) / d) + b * ((t - ti) / d));
            }
        }
        Ok(out)
    }
}
