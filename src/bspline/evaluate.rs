//! Points, derivatives, curvature and the de Boor triangle at one parameter.

use super::{
    basis_derivatives, basis_functions, de_boor_alphas, de_boor_triangle, BSplineCurve,
    BasisScratch, DeBoorAlpha,
};
use crate::error::{Error, Result};
use crate::geom::{rational_derivative, Cartesian, Point, MAX_DERIVATIVE_ORDER};
use crate::prelude::*;

impl<C: Cartesian> BSplineCurve<C> {
    /// `C(u)` from the `p + 1` non-zero basis functions (O(p²)).
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::ParameterOutOfRange`] for a bad `u`.
    pub fn evaluate(&self, u: f64) -> Result<C> {
        let u = self.knots.check_parameter(u)?;
        let mut basis = vec![0.0; self.degree() + 1];
        let k = self.knots.span(u);
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
                what: "derivative order of a rational curve",
                value: order,
                max: MAX_DERIVATIVE_ORDER,
            });
        }
        let k = self.knots.span(u);
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
