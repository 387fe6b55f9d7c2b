//! A Bézier patch's constructions as teaching data: de Casteljau's algorithm in both orders
//! and the matrix form `S(u, v) = [u^m … u 1] M_m P M_nᵀ [v^n … v 1]ᵀ`.

use super::BSplineSurface;
use crate::bezier::de_casteljau_triangle;
use crate::error::SurfaceError;
use crate::error::{Error, Result};
use crate::geom::binomial;
use glam::{DVec3, DVec4};

/// De Casteljau's construction on a Bézier patch at `(u, v)`: the triangles of the first
/// direction (one per row or column of the net, concatenated) and the triangle of the second
/// direction over their end points. Points projected (Cartesian).
#[derive(Debug, Clone, PartialEq)]
pub struct PatchDeCasteljau {
    /// Rows first: each row's triangle in v, `(n + 1)(n + 2)/2` points each, rows `0..=m` in
    /// order. Columns first: each column's triangle in u, `(m + 1)(m + 2)/2` points each.
    pub first: Vec<DVec3>,
    /// The triangle over the `m + 1` row results in u (rows first), or over the `n + 1`
    /// column results in v (columns first); its last point is `S(u, v)`.
    pub second: Vec<DVec3>,
}

/// The polynomial patch in matrix form, `S(u, v) = [u^m … u 1] · A · [v^n … v 1]ᵀ` with
/// `A = M_m P M_nᵀ`.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchMatrixForm {
    /// `M_m`, `(m + 1)²` numbers row-major: row `r` holds the coefficients of `u^{m−r}` in
    /// `B_0^m … B_m^m`.
    pub basis_u: Vec<f64>,
    /// `M_n`, likewise for v.
    pub basis_v: Vec<f64>,
    /// `A = M_m P M_nᵀ`, `(m + 1) × (n + 1)` points row-major.
    pub coefficients: Vec<DVec3>,
}

/// The Bernstein-to-power matrix `M_n` of the notes (descending powers), row-major:
/// `M[r][i] = (−1)^{k−i} C(n, k) C(k, i)` with `k = n − r` for `i ≤ k`, else 0, so that
/// `B_i^n(t) = Σ_r M[r][i] t^{n−r}`. For `n = 3`: `[−1 3 −3 1; 3 −6 3 0; −3 3 0 0; 1 0 0 0]`.
pub fn bezier_basis_matrix(n: usize) -> Vec<f64> {
    let mut m = vec![0.0; (n + 1) * (n + 1)];
    for r in 0..=n {
        let k = n - r;
        for i in 0..=k {
            let sign = if (k - i).is_multiple_of(2) { 1.0 } else { -1.0 };
            m[r * (n + 1) + i] = sign * binomial(n, k) * binomial(k, i);
        }
    }
    m
}

impl BSplineSurface {
    /// De Casteljau's algorithm on a Bézier patch (as made by [`BSplineSurface::bezier`]) at
    /// `(u, v)`, on the homogeneous points: rows first (`columns_first = false`) runs the
    /// curve algorithm in v on every row `i` of the net, then in u on the `m + 1` row results;
    /// columns first runs it in u on every column, then in v. Both end at `S(u, v)`.
    ///
    /// # Errors
    /// A `u` or `v` outside `[0, 1]` or not finite.
    pub fn de_casteljau_patch(
        &self,
        u: f64,
        v: f64,
        columns_first: bool,
    ) -> Result<PatchDeCasteljau> {
        let (u, v) = self.check_uv(u, v)?;
        let lines: Vec<Vec<DVec4>> = if columns_first {
            (0..self.cols)
                .map(|j| {
                    self.net
                        .iter()
                        .skip(j)
                        .step_by(self.cols)
                        .copied()
                        .collect()
                })
                .collect()
        } else {
            self.net
                .chunks_exact(self.cols)
                .map(<[DVec4]>::to_vec)
                .collect()
        };
        let (s_first, s_second) = if columns_first { (u, v) } else { (v, u) };
        let mut first = Vec::new();
        let mut ends = Vec::with_capacity(lines.len());
        for line in &lines {
            let triangle = de_casteljau_triangle(line, s_first);
            ends.push(triangle.last().copied().unwrap_or(DVec4::ZERO));
            first.extend(triangle.iter().map(project));
        }
        let second = de_casteljau_triangle(&ends, s_second)
            .iter()
            .map(project)
            .collect();
        Ok(PatchDeCasteljau { first, second })
    }

    /// The matrix form of a polynomial Bézier patch: `M_m`, `M_n` ([`bezier_basis_matrix`])
    /// and `A = M_m P M_nᵀ`, so that `S(u, v) = [u^m … u 1] A [v^n … v 1]ᵀ`.
    ///
    /// # Errors
    /// [`SurfaceError::NeedsPolynomial`] for a rational patch (its matrix form has a denominator).
    pub fn matrix_form(&self) -> Result<PatchMatrixForm> {
        if self.rational {
            return Err(Error::Surface(SurfaceError::NeedsPolynomial {
                operation: "matrixForm",
            }));
        }
        let (rows, cols) = (self.rows, self.cols);
        let (mu, mv) = (bezier_basis_matrix(rows - 1), bezier_basis_matrix(cols - 1));
        let points = self.control_points();
        // B = P M_nᵀ: B[i][c] = Σ_j P[i][j] M_n[c][j]; then A = M_m B.
        let mut b = vec![DVec3::ZERO; rows * cols];
        for i in 0..rows {
            for c in 0..cols {
                b[i * cols + c] = (0..cols)
                    .map(|j| points[i * cols + j] * mv[c * cols + j])
                    .sum();
            }
        }
        let mut coefficients = vec![DVec3::ZERO; rows * cols];
        for r in 0..rows {
            for c in 0..cols {
                coefficients[r * cols + c] =
                    (0..rows).map(|i| mu[r * rows + i] * b[i * cols + c]).sum();
            }
        }
        Ok(PatchMatrixForm {
            basis_u: mu,
            basis_v: mv,
            coefficients,
        })
    }
}

/// The Cartesian point of a homogeneous one.
fn project(h: &DVec4) -> DVec3 {
    h.truncate() / h.w
}
