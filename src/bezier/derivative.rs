//! Derivatives of Bézier curves: the hodograph, derivatives of any order (rational ones by the
//! quotient rule on homogeneous derivatives) and curvature (syllabus §2, §4).

use super::de_casteljau::bernstein_small;
use super::{de_casteljau_point, differences, BezierCurve};
use crate::error::{Error, Result};
use crate::geom::{binomial, Cartesian, Point};
use crate::prelude::*;

use crate::error::ConicError;
use crate::geom::{MAX_DERIVATIVE_ORDER, STACK_DEGREE};

/// The control points of the `k`-th derivative in local parameter `s`: `n!/(n−k)! Δ^k P_i`.
fn derivative_points<P: Point>(points: &[P], k: usize) -> Vec<P> {
    let n = points.len() - 1;
    let mut pts = points.to_vec();
    for j in 0..k {
        pts = differences(&pts)
            .into_iter()
            .map(|d| d * (n - j) as f64)
            .collect();
    }
    pts
}

impl<C: Cartesian> BezierCurve<C> {
    /// The derivative of order `order` at `t` with respect to `t` (order 0 is the point).
    ///
    /// Polynomial: `P^(k)(t) = n!/(n−k)! Σ B_i^{n−k}(s) Δ^k P_i / (b − a)^k`, so
    /// `P'(0) = n(P_1 − P_0)` and `P''(0) = n(n−1)(P_2 − 2P_1 + P_0)` on `[0, 1]`; an order above
    /// the degree gives the zero vector. Rational: with `A(s)` the numerator and `w(s)` the
    /// weight of the homogeneous curve, `C^(k) = (A^(k) − Σ_{i=1..k} C(k,i) w^(i) C^(k−i)) / w`.
    ///
    /// # Errors
    /// A bad `t`; [`Error::TooLarge`] for a rational curve and `order > MAX_DERIVATIVE_ORDER`.
    pub fn derivative(&self, t: f64, order: usize) -> Result<C> {
        let s = self.local_parameter(t)?;
        let n = self.degree();
        let scale = (self.b - self.a).powi(-(order.min(n + MAX_DERIVATIVE_ORDER) as i32));
        if n <= STACK_DEGREE && order <= STACK_DEGREE && (self.rational || order <= n) {
            return Ok(self.derivative_on_stack(s, order) * scale);
        }
        let mut scratch = Vec::new();
        if !self.rational {
            if order > n {
                return Ok(C::ZERO);
            }
            let pts = derivative_points(&self.homogeneous, order);
            return Ok(C::numerator(de_casteljau_point(&pts, s, &mut scratch)) * scale);
        }
        if order > MAX_DERIVATIVE_ORDER {
            return Err(Error::TooLarge {
                what: "rational-derivative-order",
                value: order,
                max: MAX_DERIVATIVE_ORDER,
            });
        }
        // Homogeneous derivatives A^(j), w^(j) for j = 0..=order (zero above the degree).
        let mut homogeneous_derivs = Vec::with_capacity(order + 1);
        let mut pts = self.homogeneous.clone();
        for j in 0..=order {
            if j > n {
                homogeneous_derivs.push(C::Homogeneous::ZERO);
                continue;
            }
            if j > 0 {
                pts = differences(&pts)
                    .into_iter()
                    .map(|d| d * (n + 1 - j) as f64)
                    .collect();
            }
            homogeneous_derivs.push(de_casteljau_point(&pts, s, &mut scratch));
        }
        Ok(crate::geom::rational_derivative::<C>(&homogeneous_derivs) * scale)
    }

    /// The derivative of order `order` in the local parameter `s`, for `n, order ≤
    /// STACK_DEGREE` (and `order ≤ n` when polynomial), allocation-free: the homogeneous
    /// derivative of order `j` is `n!/(n−j)! Σ_i B_i^{n−j}(s) Δ^j P_i` with
    /// `Δ^j P_i = Σ_l (−1)^{j−l} C(j,l) P_{i+l}`, each by [`bernstein_small`]; a rational
    /// curve then takes the quotient rule over the orders `0..=order`.
    fn derivative_on_stack(&self, s: f64, order: usize) -> C {
        let n = self.degree();
        let h = &self.homogeneous;
        let level = |j: usize| -> C::Homogeneous {
            let falling = (n + 1 - j..=n).fold(1.0, |f, m| f * m as f64);
            let delta = |i: usize| match j {
                0 => h[i],
                1 => h[i + 1] - h[i],
                _ => (0..=j).fold(C::Homogeneous::ZERO, |acc, l| {
                    let sign = if (j - l).is_multiple_of(2) { 1.0 } else { -1.0 };
                    acc + h[i + l] * (sign * binomial(j, l))
                }),
            };
            bernstein_small(n - j, s, delta) * falling
        };
        if !self.rational {
            return C::numerator(level(order));
        }
        if order <= 1 {
            let a = [
                level(0),
                if order == 1 {
                    level(1)
                } else {
                    C::Homogeneous::ZERO
                },
            ];
            return crate::geom::rational_derivative::<C>(&a[..=order]);
        }
        let mut a = [C::Homogeneous::ZERO; STACK_DEGREE + 1];
        for (j, aj) in a.iter_mut().enumerate().take(order.min(n) + 1) {
            *aj = level(j);
        }
        crate::geom::rational_derivative::<C>(&a[..=order])
    }

    /// The hodograph: the polynomial curve `P'(t)` of degree `n − 1` with control points
    /// `n (P_{i+1} − P_i)/(b − a)`, on the same interval. A line's hodograph is constant and is
    /// returned as a degree-1 curve with two equal points.
    ///
    /// # Errors
    /// [`ConicError::RationalHodograph`] for a rational curve, whose derivative is not a Bézier
    /// curve of this form (sample `derivative` instead).
    pub fn hodograph(&self) -> Result<Self> {
        if self.rational {
            return Err(Error::Conic(ConicError::RationalHodograph {}));
        }
        let n = self.degree();
        let scale = n as f64 / (self.b - self.a);
        let mut pts: Vec<_> = differences(&self.homogeneous)
            .into_iter()
            .map(|d| C::numerator(d) * scale)
            .collect();
        if pts.len() == 1 {
            pts.push(pts[0]);
        }
        let curve = BezierCurve::new(pts, None)?;
        curve.with_interval(self.a, self.b)
    }
}

impl<C: Cartesian> ParamCurveDeriv for BezierCurve<C> {
    fn derivative(&self, t: f64, order: usize) -> Result<C> {
        BezierCurve::derivative(self, t, order)
    }
}
