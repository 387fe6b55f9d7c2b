//! Cox–de Boor basis functions `N_{i,p}` and their derivatives (syllabus §3; NURBS Book A2.2,
//! A2.3).
//!
//! `N_{i,0}(u) = 1` on `[u_i, u_{i+1})`, else 0;
//! `N_{i,p}(u) = (u − u_i)/(u_{i+p} − u_i) N_{i,p−1}(u) + (u_{i+p+1} − u)/(u_{i+p+1} − u_{i+1}) N_{i+1,p−1}(u)`
//! with `0/0 := 0`. On the span `[u_k, u_{k+1})` only `N_{k−p,p} … N_{k,p}` are non-zero, and
//! they sum to 1. The triangular scheme below never divides by zero inside a non-empty span.

use super::BSplineCurve;
use crate::error::{Error, Result};
use crate::geom::{check_table_count, Cartesian, MAX_DEGREE};
/// Reusable buffers for [`basis_functions`], so dense evaluation allocates once.
#[derive(Debug, Clone, Default)]
pub struct BasisScratch {
    left: Vec<f64>,
    right: Vec<f64>,
}

impl BasisScratch {
    fn prepare(&mut self, p: usize) {
        self.left.resize(p + 1, 0.0);
        self.right.resize(p + 1, 0.0);
    }
}

/// Writes the `p + 1` non-zero basis functions `N_{k−p,p}(u) … N_{k,p}(u)` into `out[..=p]`
/// (`k` = the span of `u`). O(p²), no allocation after the first call with this `p`.
/// With `levels`, also records the whole triangle: level `r` = `N_{k−r,r} … N_{k,r}`.
pub fn basis_functions(
    knots: &[f64],
    k: usize,
    u: f64,
    p: usize,
    out: &mut [f64],
    scratch: &mut BasisScratch,
    levels: Option<&mut Vec<Vec<f64>>>,
) {
    scratch.prepare(p);
    basis_functions_with(
        knots,
        k,
        u,
        p,
        out,
        &mut scratch.left,
        &mut scratch.right,
        levels,
    );
}

/// [`basis_functions`] with the caller's `left` and `right` buffers (`p + 1` values each), so a
/// single point can keep them on the stack.
#[allow(clippy::too_many_arguments)]
pub(crate) fn basis_functions_with(
    knots: &[f64],
    k: usize,
    u: f64,
    p: usize,
    out: &mut [f64],
    left: &mut [f64],
    right: &mut [f64],
    mut levels: Option<&mut Vec<Vec<f64>>>,
) {
    out[0] = 1.0;
    if let Some(l) = levels.as_deref_mut() {
        l.clear();
        l.push(vec![1.0]);
    }
    for j in 1..=p {
        left[j] = u - knots[k + 1 - j];
        right[j] = knots[k + j] - u;
        let mut saved = 0.0;
        for r in 0..j {
            let denominator = right[r + 1] + left[j - r];
            let temp = if denominator == 0.0 {
                0.0
            } else {
                out[r] / denominator
            };
            out[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        out[j] = saved;
        if let Some(l) = levels.as_deref_mut() {
            l.push(out[..=j].to_vec());
        }
    }
}

/// The non-zero basis functions and their derivatives up to `order` at `u` in span `k`:
/// `ders[d][j] = N_{k−p+j,p}^{(d)}(u)`, `d = 0..=order` (rows above `p` are zero).
/// NURBS Book A2.3, O(p² + order·p²).
pub fn basis_derivatives(knots: &[f64], k: usize, u: f64, p: usize, order: usize) -> Vec<Vec<f64>> {
    let mut ndu = vec![vec![0.0; p + 1]; p + 1];
    let mut left = vec![0.0; p + 1];
    let mut right = vec![0.0; p + 1];
    ndu[0][0] = 1.0;
    for j in 1..=p {
        left[j] = u - knots[k + 1 - j];
        right[j] = knots[k + j] - u;
        let mut saved = 0.0;
        for r in 0..j {
            ndu[j][r] = right[r + 1] + left[j - r];
            let temp = if ndu[j][r] == 0.0 {
                0.0
            } else {
                ndu[r][j - 1] / ndu[j][r]
            };
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    let mut ders = vec![vec![0.0; p + 1]; order + 1];
    for j in 0..=p {
        ders[0][j] = ndu[j][p];
    }
    let top = order.min(p);
    let div = |a: f64, b: f64| if b == 0.0 { 0.0 } else { a / b };
    let mut a = [vec![0.0; p + 1], vec![0.0; p + 1]];
    for r in 0..=p {
        let (mut s1, mut s2) = (0, 1);
        a[0][0] = 1.0;
        for d in 1..=top {
            let mut value = 0.0;
            let rk = r as isize - d as isize;
            let pk = p - d;
            if r >= d {
                a[s2][0] = div(a[s1][0], ndu[pk + 1][r - d]);
                value = a[s2][0] * ndu[r - d][pk];
            }
            let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2 = if r as isize - 1 <= pk as isize {
                d - 1
            } else {
                p - r
            };
            for j in j1..=j2 {
                let idx = (rk + j as isize) as usize;
                a[s2][j] = div(a[s1][j] - a[s1][j - 1], ndu[pk + 1][idx]);
                value += a[s2][j] * ndu[idx][pk];
            }
            if r <= pk {
                a[s2][d] = div(-a[s1][d - 1], ndu[pk + 1][r]);
                value += a[s2][d] * ndu[r][pk];
            }
            ders[d][r] = value;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    let mut factor = p as f64;
    for (d, row) in ders.iter_mut().enumerate().take(top + 1).skip(1) {
        for v in row.iter_mut() {
            *v *= factor;
        }
        factor *= (p - d) as f64;
    }
    ders
}

impl<C: Cartesian> BSplineCurve<C> {
    /// `N_{i,p}(u)` for every `i = 0..=n` (zero outside the span's `p + 1`).
    pub fn basis(&self, u: f64) -> Result<Vec<f64>> {
        let (k, local) = self.basis_non_zero(u)?;
        let p = self.degree();
        let mut all = vec![0.0; self.homogeneous.len()];
        if let Some(slot) = all.get_mut(k - p..=k) {
            slot.copy_from_slice(&local);
        }
        Ok(all)
    }

    /// The span `k` of `u` (`u_k ≤ u < u_{k+1}`, a non-empty span; `u = b` is in the last one)
    /// and the `p + 1` basis functions that can be non-zero there, `N_{k−p,p}(u) … N_{k,p}(u)`
    /// (NURBS Book A2.1 and A2.2; they sum to 1). O(p²) whatever the number of points.
    pub fn basis_non_zero(&self, u: f64) -> Result<(usize, Vec<f64>)> {
        let u = self.knots.check_parameter(u)?;
        let p = self.degree();
        let k = self.knots.span(u);
        let mut local = vec![0.0; p + 1];
        basis_functions(
            self.knots.as_slice(),
            k,
            u,
            p,
            &mut local,
            &mut BasisScratch::default(),
            None,
        );
        Ok((k, local))
    }

    /// The triangular table of the Cox–de Boor recurrence at `u`: level `r = 0..=p` holds
    /// `N_{k−r,r}(u) … N_{k,r}(u)` for the span `k` of `u`. Returns `(k, levels)`.
    pub fn basis_table(&self, u: f64) -> Result<(usize, Vec<Vec<f64>>)> {
        let u = self.knots.check_parameter(u)?;
        let p = self.degree();
        let k = self.knots.span(u);
        let mut local = vec![0.0; p + 1];
        let mut levels = Vec::with_capacity(p + 1);
        basis_functions(
            self.knots.as_slice(),
            k,
            u,
            p,
            &mut local,
            &mut BasisScratch::default(),
            Some(&mut levels),
        );
        Ok((k, levels))
    }

    /// All basis functions sampled at `count` equally spaced parameters over the domain, for
    /// plotting: `N_{i,p}(u_j)` at index `i·count + j` (i-major). One pass over the spans.
    pub fn basis_curves(&self, count: usize) -> Result<Vec<f64>> {
        let n1 = self.homogeneous.len();
        check_table_count(count, n1)?;
        let (a, b) = self.domain();
        let p = self.degree();
        let step = if count > 1 {
            (b - a) / (count - 1) as f64
        } else {
            0.0
        };
        let mut out = vec![0.0; n1 * count];
        let mut local = vec![0.0; p + 1];
        let mut scratch = BasisScratch::default();
        let mut k = p;
        for j in 0..count {
            let u = if j + 1 == count {
                b
            } else {
                a + step * j as f64
            };
            k = self.knots.span_from(u, k);
            basis_functions(
                self.knots.as_slice(),
                k,
                u,
                p,
                &mut local,
                &mut scratch,
                None,
            );
            for (r, &v) in local.iter().enumerate() {
                out[(k - p + r) * count + j] = v;
            }
        }
        Ok(out)
    }

    /// The derivatives of every basis function at `u`: row `d = 0..=order` holds
    /// `N^{(d)}_{i,p}(u)` for `i = 0..=n`, flattened row by row.
    pub fn basis_derivatives_at(&self, u: f64, order: usize) -> Result<Vec<f64>> {
        let u = self.knots.check_parameter(u)?;
        if order > MAX_DEGREE {
            return Err(Error::TooLarge {
                what: "order",
                value: order,
                max: MAX_DEGREE,
            });
        }
        let p = self.degree();
        let n1 = self.homogeneous.len();
        let k = self.knots.span(u);
        let ders = basis_derivatives(self.knots.as_slice(), k, u, p, order);
        let mut out = vec![0.0; (order + 1) * n1];
        for (d, row) in ders.iter().enumerate() {
            out[d * n1 + k - p..=d * n1 + k].copy_from_slice(row);
        }
        Ok(out)
    }
}
