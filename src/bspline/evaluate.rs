//! Points, derivatives, curvature and the de Boor triangle at one parameter.

use super::basis::basis_functions_with;
use super::de_boor::de_boor_alpha;
use super::{
    basis_derivatives, basis_functions, de_boor_alphas, de_boor_triangle, BSplineCurve,
    BasisScratch, DeBoorAlpha,
};
use crate::error::{Error, Result};
use crate::geom::{rational_derivative, Cartesian, Point, MAX_DERIVATIVE_ORDER, STACK_DEGREE};
use crate::prelude::*;

impl<C: Cartesian> BSplineCurve<C> {
    /// `C(u)` from the `p + 1` non-zero basis functions (O(p²)).
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::ParameterOutOfRange`] for a bad `u`.
    pub fn evaluate(&self, u: f64) -> Result<C> {
        let u = self.knots.check_parameter(u)?;
        let k = self.knots.span_hinted(u);
        let p = self.degree();
        if p <= STACK_DEGREE {
            // de Boor's triangle on a stack copy of the span's p + 1 points: nothing allocated,
            // and its α are independent divisions (the basis recurrence chains them).
            let knots = self.knots.as_slice();
            let h = &self.homogeneous[k - p..=k];
            let mut d: [C::Homogeneous; STACK_DEGREE + 1] =
                std::array::from_fn(|j| h.get(j).copied().unwrap_or(C::Homogeneous::ZERO));
            for r in 1..=p {
                for j in (r..=p).rev() {
                    d[j] = d[j - 1].lerp_to(d[j], de_boor_alpha(knots, p, k, r, j, u));
                }
            }
            return Ok(self.project(d[p]));
        }
        let mut basis = vec![0.0; p + 1];
        Ok(self.evaluate_in_span(k, u, &mut basis, &mut BasisScratch::default()))
    }

    #[inline]
    fn evaluate_in_span(
        &self,
        k: usize,
        u: f64,
        basis: &mut [f64],
        scratch: &mut BasisScratch,
    ) -> C {
        let p = self.degree();
        basis_functions(self.knots.as_slice(), k, u, p, basis, scratch, None);
        let mut h = C::Homogeneous::ZERO;
        for (j, &b) in basis.iter().enumerate() {
            h = h + self.homogeneous[k - p + j] * b;
        }
        self.project(h)
    }

    /// The derivative of order `order` at `u` (order 0 = the point): homogeneous derivatives
    /// `Σ N^{(d)}_{i,p}(u) P^w_i` from the basis derivatives, then the quotient rule for
    /// rational curves. Above the degree a polynomial curve's derivative is zero.
    ///
    /// # Errors
    /// A bad `u`; [`Error::TooLarge`] for a rational curve above order 32.
    pub fn derivative(&self, u: f64, order: usize) -> Result<C> {
        let u = self.knots.check_parameter(u)?;
        let p = self.degree();
        if !self.rational && order > p {
            return Ok(C::ZERO);
        }
        if order > MAX_DERIVATIVE_ORDER {
            return Err(Error::TooLarge {
                what: "rational-derivative-order",
                value: order,
                max: MAX_DERIVATIVE_ORDER,
            });
        }
        let k = self.knots.span_hinted(u);
        if p <= STACK_DEGREE && order == 1 {
            return Ok(self.first_derivative_in_span(k, u));
        }
        if p <= STACK_DEGREE && order <= STACK_DEGREE {
            return Ok(self.derivative_in_span(k, u, order));
        }
        let ders = basis_derivatives(self.knots.as_slice(), k, u, p, order);
        let homogeneous: Vec<C::Homogeneous> = ders
            .iter()
            .map(|row| {
                row.iter()
                    .enumerate()
                    .fold(C::Homogeneous::ZERO, |acc, (j, &b)| {
                        acc + self.homogeneous[k - p + j] * b
                    })
            })
            .collect();
        if self.rational {
            Ok(rational_derivative::<C>(&homogeneous))
        } else {
            Ok(C::numerator(homogeneous[order]))
        }
    }

    /// `C'(u)` in span `k` (degree `1 ≤ p ≤ STACK_DEGREE`) with no buffer beyond three small
    /// arrays of numbers: from the degree `p − 1` basis `N_{i,p−1}` (zero outside
    /// `i = k−p+1 … k`), with `T_i = N_{i,p−1}/(u_{i+p} − u_i)` (never 0/0 in a non-empty span),
    /// `N_{i,p} = (u − u_i) T_i + (u_{i+p+1} − u) T_{i+1}` and
    /// `N'_{i,p} = p (T_i − T_{i+1})` (NURBS Book eq. 2.5, 2.7); then `A = Σ N_{i,p} P^w_i`,
    /// `A' = Σ N'_{i,p} P^w_i` and, for a rational curve, `C' = (A'_num − w' C)/w`.
    fn first_derivative_in_span(&self, k: usize, u: f64) -> C {
        let p = self.degree();
        let knots = self.knots.as_slice();
        let (mut b, mut left, mut right) = (
            [0.0; STACK_DEGREE + 1],
            [0.0; STACK_DEGREE + 1],
            [0.0; STACK_DEGREE + 1],
        );
        // b[t] = N_{k−p+1+t, p−1}(u), t = 0..p−1.
        basis_functions_with(knots, k, u, p - 1, &mut b, &mut left, &mut right, None);
        let term = |t: usize| -> f64 {
            // T_{k−p+t}, t = 0..=p+1 (zero at both ends).
            if t == 0 || t > p {
                return 0.0;
            }
            let i = k - p + t;
            b[t - 1] / (knots[i + p] - knots[i])
        };
        let (mut a0, mut a1) = (C::Homogeneous::ZERO, C::Homogeneous::ZERO);
        let mut t_here = term(0);
        for t in 0..=p {
            let i = k - p + t;
            let t_next = term(t + 1);
            let n0 = (u - knots[i]) * t_here + (knots[i + p + 1] - u) * t_next;
            let n1 = p as f64 * (t_here - t_next);
            let h = self.homogeneous[i];
            a0 = a0 + h * n0;
            a1 = a1 + h * n1;
            t_here = t_next;
        }
        if self.rational {
            rational_derivative::<C>(&[a0, a1])
        } else {
            C::numerator(a1)
        }
    }

    /// The derivative of order `order ≤ STACK_DEGREE` at `u` in span `k` (degree
    /// `p ≤ STACK_DEGREE`), allocation-free: the span's `p + 1` homogeneous points are
    /// differenced in place, `Q^{(j)}_i = (p − j + 1)(Q^{(j−1)}_i − Q^{(j−1)}_{i−1}) /
    /// (u_{i+p−j+1} − u_i)` for `i = k−p+j … k` (never 0/0: `u_{i+p−j+1} − u_i ≥ u_{k+1} − u_k > 0`),
    /// and `A^{(j)}(u) = Σ_i N_{i,p−j}(u) Q^{(j)}_i` (NURBS Book eq. 3.8 and 4.8 restricted to the
    /// span); a rational curve needs every `A^{(j)}`, `j ≤ order`, for the quotient rule.
    /// O(order·p²), the same numbers as A2.3 up to rounding.
    fn derivative_in_span(&self, k: usize, u: f64, order: usize) -> C {
        let p = self.degree();
        let knots = self.knots.as_slice();
        let mut q = [C::Homogeneous::ZERO; STACK_DEGREE + 1];
        for (t, qt) in q.iter_mut().enumerate().take(p + 1) {
            *qt = self.homogeneous[k - p + t];
        }
        let mut a = [C::Homogeneous::ZERO; STACK_DEGREE + 1];
        let (mut b, mut left, mut right) = (
            [0.0; STACK_DEGREE + 1],
            [0.0; STACK_DEGREE + 1],
            [0.0; STACK_DEGREE + 1],
        );
        let top = order.min(p);
        for j in 0..=top {
            if j > 0 {
                let m = (p - j + 1) as f64;
                for t in (j..=p).rev() {
                    let i = k - p + t;
                    q[t] = (q[t] - q[t - 1]) * (m / (knots[i + p - j + 1] - knots[i]));
                }
            }
            if self.rational || j == order {
                let d = p - j;
                basis_functions_with(knots, k, u, d, &mut b, &mut left, &mut right, None);
                let mut h = C::Homogeneous::ZERO;
                for (t, &bt) in b[..=d].iter().enumerate() {
                    h = h + q[j + t] * bt;
                }
                a[j] = h;
            }
        }
        if self.rational {
            rational_derivative::<C>(&a[..=order])
        } else {
            C::numerator(a[order])
        }
    }

    /// The control points of the derivative curves of the homogeneous curve, orders
    /// `0..=order` (NURBS Book eq. 3.8): `P^(k)_i = (p − k + 1)/(u_{i+p+1} − u_{i+k})
    /// (P^(k−1)_{i+1} − P^(k−1)_i)`; the `k`-th is a B-spline of degree `p − k` whose value at `u`
    /// is `Σ_j N_{s−p+k+j, p−k}(u) P^(k)_{s−p+j}` on the original knots (`s` the span of `u`).
    pub(super) fn derivative_points(&self, order: usize) -> Vec<Vec<C::Homogeneous>> {
        let p = self.degree();
        let u = self.knots.as_slice();
        let mut out = vec![self.homogeneous.clone()];
        for k in 1..=order.min(p) {
            let prev = &out[k - 1];
            let next = (0..prev.len() - 1)
                .map(|i| {
                    let d = u[i + p + 1] - u[i + k];
                    if d == 0.0 {
                        C::Homogeneous::ZERO
                    } else {
                        (prev[i + 1] - prev[i]) * ((p - k + 1) as f64 / d)
                    }
                })
                .collect();
            out.push(next);
        }
        out
    }

    /// de Boor's triangle at `u` in Cartesian form (levels concatenated, the `p + 1` active
    /// points first, `C(u)` last). Rational curves run on homogeneous points, then project.
    pub fn de_boor(&self, u: f64) -> Result<Vec<C>> {
        Ok(self
            .de_boor_homogeneous(u)?
            .into_iter()
            .map(|h| self.project(h))
            .collect())
    }

    /// de Boor's triangle on the homogeneous points.
    pub fn de_boor_homogeneous(&self, u: f64) -> Result<Vec<C::Homogeneous>> {
        let u = self.knots.check_parameter(u)?;
        let k = self.knots.span(u);
        Ok(de_boor_triangle(
            &self.homogeneous,
            self.knots.as_slice(),
            self.degree(),
            k,
            u,
        ))
    }

    /// The span `k` of `u` and every α of de Boor's triangle there (see [`de_boor_alphas`]):
    /// `α_j^r = (u − u_{j+k−p}) / (u_{j+1+k−r} − u_{j+k−p})`, levels `r = 1..=p`, `j = r..=p`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::ParameterOutOfRange`] for a bad `u`.
    pub fn de_boor_alphas(&self, u: f64) -> Result<(usize, Vec<DeBoorAlpha>)> {
        let u = self.knots.check_parameter(u)?;
        let k = self.knots.span(u);
        Ok((
            k,
            de_boor_alphas(self.knots.as_slice(), self.degree(), k, u),
        ))
    }
}

impl<C: Cartesian> ParamCurveDeriv for BSplineCurve<C> {
    fn derivative(&self, u: f64, order: usize) -> Result<C> {
        BSplineCurve::derivative(self, u, order)
    }
}
