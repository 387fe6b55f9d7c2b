//! Dense grids of points: the fast path that walks spans once and collapses the rows of
//! each u first.

use super::{basis, checked_count, in_element, BSplineSurface};
use crate::bspline::BasisScratch;
use crate::error::Result;
use crate::geom::{result_len, MAX_SAMPLES};
use glam::DVec4;

impl BSplineSurface {
    /// The u direction collapsed at one u of span `ku`: `row[j] = Σ_a weights[a] (wP)_{ku−p+a, j}`
    /// over the `p + 1` rows of the span (with the basis values `N_{ku−p+a,p}(u)`, the
    /// homogeneous curve `A(u, ·)`; with their derivatives, `A_u(u, ·)`).
    pub(super) fn collapse_rows(&self, ku: usize, weights: &[f64], row: &mut [DVec4]) {
        row.fill(DVec4::ZERO);
        let first = ku - self.degree_u();
        for (net_row, &n) in self.net.chunks_exact(self.cols).skip(first).zip(weights) {
            for (r, &h) in row.iter_mut().zip(net_row) {
                *r += n * h;
            }
        }
    }

    /// `S(u_a, v_b)` for every `u_a` of `us` and `v_b` of `vs`, u-major (point `a·len(vs) + b`,
    /// 3 numbers each), into `out` (resized).
    ///
    /// The basis along v is computed once per `v_b`; each `u_a` then collapses the u
    /// direction into one homogeneous curve of `cols` points (`p + 1` rows blended), which is
    /// evaluated at every `v_b` with `q + 1` terms: per point `4(q + 1)` multiply-adds and one
    /// division. The same sums as [`BSplineSurface::evaluate`], grouped differently.
    ///
    /// # Errors
    /// A bad value in `us` or `vs` (named by index), [`crate::Error::ResultTooLarge`] for more
    /// than [`crate::geom::MAX_RESULT_BYTES`] bytes of result, and [`crate::Error::TooLarge`]
    /// for more than [`MAX_SAMPLES`] points.
    pub fn sample_grid_into(&self, us: &[f64], vs: &[f64], out: &mut Vec<f64>) -> Result<()> {
        result_len("sample-grid-result", &[us.len(), vs.len(), 3])?;
        let points = checked_count("grid-points", us.len(), vs.len(), MAX_SAMPLES)?;
        for (i, &u) in us.iter().enumerate() {
            self.knots_u
                .check_named("u", u)
                .map_err(|e| in_element("us", i, e))?;
        }
        for (j, &v) in vs.iter().enumerate() {
            self.knots_v
                .check_named("v", v)
                .map_err(|e| in_element("vs", j, e))?;
        }
        out.clear();
        out.resize(3 * points, 0.0);
        let (p, q) = (self.degree_u(), self.degree_v());
        let mut scratch = BasisScratch::default();
        // The v basis, once: the first column of each span and its q + 1 values.
        let mut first = Vec::with_capacity(vs.len());
        let mut table = vec![0.0; vs.len() * (q + 1)];
        let mut k = q;
        for (&v, values) in vs.iter().zip(table.chunks_exact_mut(q + 1)) {
            k = self.knots_v.span_from(v, k);
            basis(&self.knots_v, k, v, values, &mut scratch);
            first.push(k - q);
        }
        let mut nu = vec![0.0; p + 1];
        let mut row = vec![DVec4::ZERO; self.cols];
        let mut ku = p;
        for (&u, out_row) in us.iter().zip(out.chunks_exact_mut(3 * vs.len().max(1))) {
            ku = self.knots_u.span_from(u, ku);
            basis(&self.knots_u, ku, u, &mut nu, &mut scratch);
            self.collapse_rows(ku, &nu, &mut row);
            // Degrees 1–5 get a kernel whose inner loop the compiler unrolls.
            match q + 1 {
                2 => grid_row::<2>(&row, &first, &table, out_row),
                3 => grid_row::<3>(&row, &first, &table, out_row),
                4 => grid_row::<4>(&row, &first, &table, out_row),
                5 => grid_row::<5>(&row, &first, &table, out_row),
                6 => grid_row::<6>(&row, &first, &table, out_row),
                _ => grid_row_any(q + 1, &row, &first, &table, out_row),
            }
        }
        Ok(())
    }
}

/// One row of a grid: the homogeneous curve `row` (the u direction collapsed) at every v, from
/// the first column `first[b]` of each v's span and its `Q1 = q + 1` basis values in `table`,
/// projected into `out` (3 numbers per v).
#[inline]
fn grid_row<const Q1: usize>(row: &[DVec4], first: &[usize], table: &[f64], out: &mut [f64]) {
    for ((&j0, values), xyz) in first
        .iter()
        .zip(table.chunks_exact(Q1))
        .zip(out.chunks_exact_mut(3))
    {
        let (Some(points), Ok(values)) = (row.get(j0..j0 + Q1), <&[f64; Q1]>::try_from(values))
        else {
            continue;
        };
        let mut h = DVec4::ZERO;
        for b in 0..Q1 {
            h += values[b] * points[b];
        }
        let inv = 1.0 / h.w;
        xyz.copy_from_slice(&[h.x * inv, h.y * inv, h.z * inv]);
    }
}

/// [`grid_row`] for any `q + 1`.
fn grid_row_any(q1: usize, row: &[DVec4], first: &[usize], table: &[f64], out: &mut [f64]) {
    for ((&j0, values), xyz) in first
        .iter()
        .zip(table.chunks_exact(q1))
        .zip(out.chunks_exact_mut(3))
    {
        let h = row
            .get(j0..j0 + q1)
            .unwrap_or(&[])
            .iter()
            .zip(values)
            .fold(DVec4::ZERO, |acc, (&c, &n)| acc + n * c);
        let inv = 1.0 / h.w;
        xyz.copy_from_slice(&[h.x * inv, h.y * inv, h.z * inv]);
    }
}
