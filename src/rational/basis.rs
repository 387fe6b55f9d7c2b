//! The rational basis functions (syllabus §4): `R_i(t) = w_i B_i(t) / Σ_j w_j B_j(t)`, the
//! coefficients of the control points in a rational curve `P(t) = Σ R_i(t) P_i`.

use crate::bezier::{bernstein, BezierCurve};
use crate::error::Result;
use crate::geom::Cartesian;
use crate::prelude::*;

/// `R_i = w_i b_i / Σ_j w_j b_j` for polynomial basis values `b` (Bernstein or B-spline) and
/// weights `w` of the same length. With positive weights and a partition of unity `b` the
/// `R_i` lie in `[0, 1]` and sum to 1 (the convex hull property of rational curves); all
/// weights equal gives `R_i = b_i`. A zero denominator (only possible with weights <= 0,
/// which curves refuse) gives zeros.
pub fn rational_basis(basis: &[f64], weights: &[f64]) -> Vec<f64> {
    let products: Vec<f64> = basis.iter().zip(weights).map(|(b, w)| b * w).collect();
    let denominator: f64 = products.iter().sum();
    if denominator == 0.0 {
        return vec![0.0; products.len()];
    }
    products.into_iter().map(|x| x / denominator).collect()
}

impl<C: Cartesian> BezierCurve<C> {
    /// The rational Bernstein basis at `t`: `R_i(t) = w_i B_i^n(s) / Σ_j w_j B_j^n(s)` for
    /// `i = 0..=n`, with `s` the local parameter of `t` (`s = t` on `[0, 1]`). For a polynomial
    /// curve (all weights 1) these are the Bernstein values `B_i^n(s)`.
    ///
    /// # Errors
    /// [`crate::Error::NotFinite`] or [`crate::Error::ParameterOutOfRange`] for a bad `t`.
    pub fn rational_basis(&self, t: f64) -> Result<Vec<f64>> {
        let s = self.local_parameter(t)?;
        let n = self.degree();
        let basis: Vec<f64> = (0..=n).map(|i| bernstein(n, i, s)).collect();
        Ok(rational_basis(&basis, &self.weights()))
    }
}
