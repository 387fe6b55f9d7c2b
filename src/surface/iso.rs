//! Iso-parametric curves: the curves of constant u or constant v on a surface.

use super::{basis, BSplineSurface};
use crate::bspline::{BSplineCurve, BasisScratch, KnotVector};
use crate::error::Result;
use glam::{DVec3, DVec4};

impl BSplineSurface {
    /// The curve `C(v) = S(u, v)` at constant `u`, running in v: a B-spline of degree `q` on
    /// the v knots whose homogeneous control points are `Q_j = Σ_i N_{i,p}(u) (w P)_ij`, the
    /// columns of the net blended by the u basis at `u` (rational when the surface is).
    ///
    /// # Errors
    /// A `u` outside the domain or not finite (the message names `u` and the range).
    pub fn iso_curve_u(&self, u: f64) -> Result<BSplineCurve<DVec3>> {
        let u = self.knots_u.check_named("u", u)?;
        let (first_row, basis) = blend(&self.knots_u, u);
        // Column j: the points (first_row + k, j), k = 0..=p, a stride of one row apart.
        let points = (0..self.cols)
            .map(|j| self.combine(first_row * self.cols + j, self.cols, &basis))
            .collect();
        self.iso_curve(points, &self.knots_v)
    }

    /// The curve `C(u) = S(u, v)` at constant `v`, running in u: a B-spline of degree `p` on
    /// the u knots with homogeneous control points `Q_i = Σ_j N_{j,q}(v) (w P)_ij`, the rows
    /// blended by the v basis at `v` (rational when the surface is).
    ///
    /// # Errors
    /// A `v` outside the domain or not finite.
    pub fn iso_curve_v(&self, v: f64) -> Result<BSplineCurve<DVec3>> {
        let v = self.knots_v.check_named("v", v)?;
        let (first_col, basis) = blend(&self.knots_v, v);
        // Row i: the points (i, first_col + k), k = 0..=q, side by side.
        let points = (0..self.rows)
            .map(|i| self.combine(i * self.cols + first_col, 1, &basis))
            .collect();
        self.iso_curve(points, &self.knots_u)
    }

    /// `Σ_k b_k h[first + k·stride]` over the homogeneous net.
    fn combine(&self, first: usize, stride: usize, blend: &[f64]) -> DVec4 {
        blend.iter().enumerate().fold(DVec4::ZERO, |acc, (k, &b)| {
            acc + b * self
                .net
                .get(first + k * stride)
                .copied()
                .unwrap_or(DVec4::ZERO)
        })
    }

    /// The curve of homogeneous control points `points` on `knots`.
    fn iso_curve(&self, points: Vec<DVec4>, knots: &KnotVector) -> Result<BSplineCurve<DVec3>> {
        let weights: Vec<f64> = points.iter().map(|h| h.w).collect();
        let cartesian = points.iter().map(|h| h.truncate() / h.w).collect();
        BSplineCurve::new(
            cartesian,
            knots.degree(),
            knots.as_slice().to_vec(),
            self.rational.then_some(&weights[..]),
        )
    }
}

/// The first index and the `degree + 1` values of the basis functions non-zero at `t`.
fn blend(knots: &KnotVector, t: f64) -> (usize, Vec<f64>) {
    let p = knots.degree();
    let k = knots.span(t);
    let mut values = vec![0.0; p + 1];
    basis(knots, k, t, &mut values, &mut BasisScratch::default());
    (k - p, values)
}
