//! The basis functions of one span as polynomials, and the matrix form of a segment
//! `C(x) = [x^p … x 1] M [P_{k−p} … P_k]^T` (the Croatian notes, syllabus §3).

use super::BSplineCurve;
use crate::error::{check_in_range, Error, Result};
use crate::geom::{Cartesian, Point};
use crate::prelude::*;

/// Coefficients (ascending powers) of the `p + 1` basis functions `N_{k−p,p} … N_{k,p}` on the
/// span `k`, as polynomials in `x` where `u = offset + scale·x`, by running the Cox–de Boor
/// recurrence on polynomials (`0/0 := 0`).
fn span_polynomials(knots: &[f64], p: usize, k: usize, offset: f64, scale: f64) -> Vec<Vec<f64>> {
    // level[j] = N_{k−r+j, r} for the current r; polynomials of degree <= r.
    let mut level: Vec<Vec<f64>> = vec![vec![1.0]];
    for r in 1..=p {
        let mut next = Vec::with_capacity(r + 1);
        for j in 0..=r {
            let i = k + j - r; // index of N_{i,r}
            let mut poly = vec![0.0; r + 1];
            // (u − u_i)/(u_{i+r} − u_i) · N_{i,r−1}: N_{i,r−1} is level[j − 1] when j >= 1.
            if j >= 1 {
                let d = knots[i + r] - knots[i];
                if d != 0.0 {
                    let (c0, c1) = ((offset - knots[i]) / d, scale / d);
                    for (e, &c) in level[j - 1].iter().enumerate() {
                        poly[e] += c0 * c;
                        poly[e + 1] += c1 * c;
                    }
                }
            }
            // (u_{i+r+1} − u)/(u_{i+r+1} − u_{i+1}) · N_{i+1,r−1}: level[j] when j < r.
            if j < r {
                let d = knots[i + r + 1] - knots[i + 1];
                if d != 0.0 {
                    let (c0, c1) = ((knots[i + r + 1] - offset) / d, -scale / d);
                    for (e, &c) in level[j].iter().enumerate() {
                        poly[e] += c0 * c;
                        poly[e + 1] += c1 * c;
                    }
                }
            }
            next.push(poly);
        }
        level = next;
    }
    level
}

/// Arranges basis polynomials as the notes' matrix: row `r` holds the coefficients of
/// `x^{p−r}`, column `j` belongs to `P_{k−p+j}`.
fn as_matrix(polys: &[Vec<f64>], p: usize) -> Vec<Vec<f64>> {
    (0..=p)
        .map(|r| polys.iter().map(|poly| poly[p - r]).collect())
        .collect()
}

impl<C: Cartesian> BSplineCurve<C> {
    /// The matrix `M` of the segment on span `k` (`u_k < u_{k+1}`): with `local`, in
    /// `t ∈ [0, 1]` where `u = u_k + (u_{k+1} − u_k) t`, else in the global `u`; so that the
    /// segment is `[x^p … x 1] M [P_{k−p} … P_k]^T`. Column `j` is the basis function
    /// `N_{k−p+j,p}` restricted to the span, highest power first.
    ///
    /// # Errors
    /// [`Error::NotASpan`] unless `k` is a non-empty span of the domain.
    pub fn segment_matrix(&self, k: usize, local: bool) -> Result<Vec<Vec<f64>>> {
        let knots = self.knots.as_slice();
        if !self.knots.spans().any(|s| s == k) {
            return Err(Error::NotASpan {
                span: k,
                valid: self.knots.spans().collect(),
            });
        }
        let p = self.degree();
        let (offset, scale) = if local {
            (knots[k], knots[k + 1] - knots[k])
        } else {
            (0.0, 1.0)
        };
        Ok(as_matrix(&span_polynomials(knots, p, k, offset, scale), p))
    }
}

/// The matrix form of one segment evaluated at a local `t`: what the lecture view writes out.
#[derive(Debug, Clone, PartialEq)]
pub struct MatrixFormPoint<C> {
    /// The monomial row `[t^p … t 1]`.
    pub monomials: Vec<f64>,
    /// `[t^p … t 1] M`: the weight of each active point `P_{k−p+j}`, `j = 0..=p` (these are
    /// the basis values `N_{k−p+j,p}(u)` at `u = u_k + (u_{k+1} − u_k) t`).
    pub basis: Vec<f64>,
    /// `[t^p … t 1] M [P_{k−p} … P_k]^T` (on the homogeneous points, projected, for a rational
    /// curve).
    pub point: C,
}

impl<C: Cartesian> BSplineCurve<C> {
    /// The segment on span `k` in matrix form at the local parameter `t ∈ [0, 1]`
    /// (`u = u_k + (u_{k+1} − u_k) t`): the monomials `[t^p … 1]`, the row `[t^p … 1] M` with
    /// `M` = [`BSplineCurve::segment_matrix`]`(k, true)`, and the point
    /// `C(u) = Σ_j ([t^p … 1] M)_j P_{k−p+j}`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN or infinite `t`, [`Error::ParameterOutOfRange`] outside
    /// `[0, 1]`, and the errors of `segment_matrix` for a bad `k`.
    pub fn evaluate_matrix_form(&self, k: usize, t: f64) -> Result<MatrixFormPoint<C>> {
        check_in_range("t", t, (0.0, 1.0))?;
        let m = self.segment_matrix(k, true)?;
        let p = self.degree();
        let monomials: Vec<f64> = (0..=p).map(|r| t.powi((p - r) as i32)).collect();
        let basis: Vec<f64> = (0..=p)
            .map(|j| {
                monomials
                    .iter()
                    .zip(&m)
                    .fold(0.0, |acc, (x, row)| acc + x * row[j])
            })
            .collect();
        let h = basis
            .iter()
            .enumerate()
            .fold(C::Homogeneous::ZERO, |acc, (j, &b)| {
                acc + self.homogeneous[k - p + j] * b
            });
        Ok(MatrixFormPoint {
            monomials,
            basis,
            point: self.project(h),
        })
    }
}

/// The matrix of every interior segment of a uniform B-spline of degree `p` in `t ∈ [0, 1]`
/// (identical for all such "periodic" segments): quadratic `[[1/2, −1, 1/2], [−1, 1, 0],
/// [1/2, 1/2, 0]]`, cubic `1/6 [[−1, 3, −3, 1], [3, −6, 3, 0], [−3, 0, 3, 0], [1, 4, 1, 0]]`.
pub fn uniform_segment_matrix(p: usize) -> Vec<Vec<f64>> {
    let knots: Vec<f64> = (0..=2 * p + 1).map(|i| i as f64).collect();
    as_matrix(&span_polynomials(&knots, p, p, p as f64, 1.0), p)
}
