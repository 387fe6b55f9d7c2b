//! Evaluating a [`CubicSpline`]: points and derivatives of order 0..3, dense sampling that
//! walks the intervals once, and the conversions to Bézier pieces and to a cubic B-spline.
//!
//! On piece i, with `u = t − t_i`, `Δ = Δ_i`, `s = (p_{i+1} − p_i)/Δ`:
//! `C(t) = p_i + m_i u + c u² + d u³`, `c = (3s − 2m_i − m_{i+1})/Δ`, `d = (m_i + m_{i+1} − 2s)/Δ²`
//! (the Hermite form expanded in the global parameter).

use super::cubic_spline::{CubicSpline, TangentRule};
use super::hermite::hermite_to_bezier;
use crate::bezier::{BezierCurve, CompositeCurve};
use crate::bspline::BSplineCurve;
use crate::error::{check_in_range, Result};
use crate::geom::{check_out_len, Cartesian, Params, Point};
use crate::prelude::*;

/// The power form of one piece in `u = t − t_i`: `[a, b, c, d]` with `C = a + bu + cu² + du³`.
#[derive(Clone, Copy)]
struct Piece<C> {
    start: f64,
    end: f64,
    coeffs: [C; 4],
    /// `p_{i+1}`, returned exactly at `t = t_{i+1}`.
    end_point: C,
}

impl<C: Point> Piece<C> {
    /// The derivative of the given order at t (order above 3: zero).
    #[inline]
    fn derivative(&self, t: f64, order: usize) -> C {
        let [a, b, c, d] = self.coeffs;
        let u = t - self.start;
        match order {
            0 if t == self.end => self.end_point,
            0 => a + (b + (c + d * u) * u) * u,
            1 => b + (c * 2.0 + d * (3.0 * u)) * u,
            2 => c * 2.0 + d * (6.0 * u),
            3 => d * 6.0,
            _ => C::ZERO,
        }
    }
}

impl<C: Cartesian> CubicSpline<C> {
    /// The index of the piece that owns t (pieces closed on the left, the last also on the
    /// right; t already checked to lie in the domain).
    fn piece_index(&self, t: f64) -> usize {
        let n = self.params.len() - 1;
        self.params[1..n].partition_point(|&x| x <= t)
    }

    /// The power form of piece i.
    fn piece(&self, i: usize) -> Piece<C> {
        let (t0, t1) = (self.params[i], self.params[i + 1]);
        let h = t1 - t0;
        let (p0, p1) = (self.points[i], self.points[i + 1]);
        let (m0, m1) = (self.tangents[i], self.tangents[i + 1]);
        let s = (p1 - p0) * (1.0 / h);
        let c = (s * 3.0 - m0 * 2.0 - m1) * (1.0 / h);
        let d = (m0 + m1 - s * 2.0) * (1.0 / (h * h));
        Piece {
            start: t0,
            end: t1,
            coeffs: [p0, m0, c, d],
            end_point: p1,
        }
    }

    /// The derivative `C^(order)(t)`: order 0 is the point (exactly `p_i` at every `t_i`),
    /// orders above 3 are zero. At an interior `t_i` the right piece's derivative is returned
    /// (they agree up to order 1, or 2 for a C2 spline).
    ///
    /// # Errors
    /// [`crate::Error::NotFinite`] or [`crate::Error::ParameterOutOfRange`] outside the domain.
    pub fn derivative_at(&self, t: f64, order: usize) -> Result<C> {
        check_in_range("t", t, self.domain())?;
        Ok(self.piece(self.piece_index(t)).derivative(t, order))
    }

    /// The derivative of order `order` at every parameter of `params` into `out` (`DIM` numbers
    /// each), walking the pieces: sorted parameters visit each piece once.
    fn sample_params_into(&self, params: Params, order: usize, out: &mut [f64]) -> Result<()> {
        check_out_len(out.len(), params.len(), C::DIM, self.sample_degree())?;
        let domain = self.domain();
        let last = self.params.len() - 2;
        let mut index = 0;
        let mut piece = self.piece(0);
        for (k, o) in out.chunks_exact_mut(C::DIM).enumerate() {
            let t = check_in_range("t", params.get(k), domain)?;
            let inside = t >= piece.start && (t < piece.end || index == last);
            if !inside {
                // Forward by one interval (the common case for sorted input), else search.
                let next_fits = index < last
                    && t >= piece.end
                    && (index + 1 == last || t < self.params[index + 2]);
                index = if next_fits {
                    index + 1
                } else {
                    self.piece_index(t)
                };
                piece = self.piece(index);
            }
            piece.derivative(t, order).write_to(o);
        }
        Ok(())
    }

    /// The derivative of order `order` at every t of `ts` into `out`, flat.
    ///
    /// # Errors
    /// [`crate::Error::BufferLength`] (or [`crate::Error::TooLarge`] above the sample cap), then
    /// as [`CubicSpline::derivative_at`] for the first bad t (the points before it are written).
    pub fn sample_derivatives_into(&self, ts: &[f64], order: usize, out: &mut [f64]) -> Result<()> {
        self.sample_params_into(Params::Slice(ts), order, out)
    }

    /// The Bézier form: piece i is `[p_i, p_i + Δ_i m_i/3, p_{i+1} − Δ_i m_{i+1}/3, p_{i+1}]` on
    /// `[t_i, t_{i+1}]` (breakpoints = the parameters).
    ///
    /// # Errors
    /// None in practice (the pieces are valid); the errors of [`CompositeCurve::new`].
    pub fn to_bezier(&self) -> Result<CompositeCurve<C>> {
        let q = bezier_points(&self.points, &self.tangents, &self.params);
        let pieces = q
            .chunks_exact(4)
            .map(|piece| BezierCurve::new(piece.to_vec(), None))
            .collect::<Result<Vec<_>>>()?;
        CompositeCurve::new(pieces, &self.params)
    }

    /// The same curve as a clamped cubic B-spline. A C2 spline (`cubicSpline`, any end
    /// condition) gets single interior knots `t_1..t_{n−1}` and `n + 3` control points (the
    /// syllabus' cubic B-spline interpolation): by Farin's relation the inner Bézier points of
    /// piece i divide the control leg `d_{i+1} d_{i+2}` in the ratios `Δ_{i−1} : Δ_i : Δ_{i+1}`
    /// (`Δ_{−1} = Δ_n = 0`), which gives the legs' ends; `d_0 = p_0`, `d_{n+2} = p_n`. Other
    /// rules (only C1) get double interior knots and `2n + 2` control points: `p_0`, the two
    /// inner Bézier points of every piece, `p_n` (each `p_i` divides its two neighbours in the
    /// ratio `Δ_{i−1} : Δ_i`).
    ///
    /// # Errors
    /// The errors of [`BSplineCurve::new`] (none for valid splines).
    pub fn to_bspline(&self) -> Result<BSplineCurve<C>> {
        let c2 = matches!(self.rule(), TangentRule::Spline(_));
        let (control, knots) = bspline_form(&self.points, &self.tangents, &self.params, c2);
        BSplineCurve::new(control, 3, knots, None)
    }
}

/// The Bézier points of every piece of the Hermite spline through `points` (at least 2) with
/// `tangents` at `params`, four per piece: `[p_i, p_i + Δ_i m_i/3, p_{i+1} − Δ_i m_{i+1}/3,
/// p_{i+1}]` ([`CubicSpline::to_bezier`]).
pub(crate) fn bezier_points<C: Cartesian>(points: &[C], tangents: &[C], params: &[f64]) -> Vec<C> {
    let n = points.len() - 1;
    let mut out = Vec::with_capacity(4 * n);
    for i in 0..n {
        let h = params[i + 1] - params[i];
        out.extend_from_slice(&hermite_to_bezier(
            points[i],
            tangents[i],
            points[i + 1],
            tangents[i + 1],
            h,
        ));
    }
    out
}

/// The control points and knots of [`CubicSpline::to_bspline`] for the Hermite spline through
/// `points` with `tangents` at `params`; `c2`: single interior knots (a C2 spline), else
/// double ones.
pub(crate) fn bspline_form<C: Cartesian>(
    points: &[C],
    tangents: &[C],
    t: &[f64],
    c2: bool,
) -> (Vec<C>, Vec<f64>) {
    let n = points.len() - 1;
    let inner = |i: usize| {
        let h = t[i + 1] - t[i];
        let [_, b1, b2, _] =
            hermite_to_bezier(points[i], tangents[i], points[i + 1], tangents[i + 1], h);
        (b1, b2)
    };
    let mut knots = vec![t[0]; 4];
    let mut control = Vec::with_capacity(2 * n + 2);
    control.push(points[0]);
    if c2 {
        knots.extend_from_slice(&t[1..n]);
        let gap = |i: usize| {
            if i < n {
                t[i + 1] - t[i]
            } else {
                0.0
            }
        };
        let mut leg_end = points[0];
        for i in 0..n {
            let (b1, b2) = inner(i);
            let before = if i == 0 { 0.0 } else { gap(i - 1) };
            let total = before + gap(i) + gap(i + 1);
            let alpha = before / total;
            let width = gap(i) / total;
            let leg = (b2 - b1) * (1.0 / width);
            let start = b1 - leg * alpha;
            control.push(start);
            leg_end = start + leg;
        }
        control.push(leg_end);
    } else {
        for &ti in &t[1..n] {
            knots.extend_from_slice(&[ti, ti]);
        }
        for i in 0..n {
            let (b1, b2) = inner(i);
            control.push(b1);
            control.push(b2);
        }
    }
    control.push(points[n]);
    knots.extend_from_slice(&[t[n]; 4]);
    (control, knots)
}

impl<C: Cartesian> ParamCurve for CubicSpline<C> {
    type Point = C;

    fn domain(&self) -> (f64, f64) {
        CubicSpline::domain(self)
    }

    fn sample_degree(&self) -> usize {
        3
    }

    fn evaluate(&self, t: f64) -> Result<C> {
        self.derivative_at(t, 0)
    }

    fn sample_into(&self, ts: &[f64], out: &mut [f64]) -> Result<()> {
        self.sample_params_into(Params::Slice(ts), 0, out)
    }

    fn sample_uniform_into(&self, count: usize, out: &mut [f64]) -> Result<()> {
        let (a, b) = self.domain();
        self.sample_params_into(Params::uniform(a, b, count), 0, out)
    }
}

impl<C: Cartesian> ParamCurveDeriv for CubicSpline<C> {
    fn derivative(&self, t: f64, order: usize) -> Result<C> {
        self.derivative_at(t, order)
    }
}
