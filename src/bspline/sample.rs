//! Dense sampling: walk the spans once, evaluate only the `p + 1` non-zero basis functions
//! with per-span reciprocals of the knot differences (no division per point but the
//! homogeneous one), in kernels unrolled for degrees 1–5.

use super::{basis_functions, BSplineCurve, BasisScratch};
use crate::geom::{Cartesian, Point};

/// Reciprocals `1/(u_{k+r+1} − u_{k+1−j+r})` that the triangular scheme divides by on span `k`
/// (`j = 1..N−1`, `r = 0..j`; 0 for a zero difference): they do not depend on `u`.
#[inline]
fn span_reciprocals<const N: usize>(knots: &[f64], k: usize, inv: &mut [[f64; N]; N]) {
    for j in 1..N {
        for r in 0..j {
            let d = knots[k + r + 1] - knots[k + 1 + r - j];
            inv[j][r] = if d == 0.0 { 0.0 } else { 1.0 / d };
        }
    }
}

/// `Σ_j N_{k−p+j,p}(u) P_{k−p+j}` for degree `p = N − 1`, with the reciprocals of span `k`.
#[inline(always)]
fn evaluate_fixed<H: Point, const N: usize>(
    knots: &[f64],
    points: &[H],
    k: usize,
    u: f64,
    inv: &[[f64; N]; N],
) -> H {
    let mut n = [0.0; N];
    let mut left = [0.0; N];
    let mut right = [0.0; N];
    n[0] = 1.0;
    for j in 1..N {
        left[j] = u - knots[k + 1 - j];
        right[j] = knots[k + j] - u;
        let mut saved = 0.0;
        for r in 0..j {
            let temp = n[r] * inv[j][r];
            n[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        n[j] = saved;
    }
    let base = k + 1 - N;
    let mut h = H::ZERO;
    for (j, &b) in n.iter().enumerate() {
        h = h + points[base + j] * b;
    }
    h
}

impl<C: Cartesian> BSplineCurve<C> {
    /// Writes `C(u)` for each parameter of `params` (already checked to lie in the domain)
    /// into `out`, `DIM` numbers per point. Spans are found from the previous one, so sorted
    /// parameters walk the knots once.
    pub(crate) fn sample_params_into(&self, params: impl Iterator<Item = f64>, out: &mut [f64]) {
        match self.degree() {
            1 => self.sample_fixed::<2>(params, out),
            2 => self.sample_fixed::<3>(params, out),
            3 => self.sample_fixed::<4>(params, out),
            4 => self.sample_fixed::<5>(params, out),
            5 => self.sample_fixed::<6>(params, out),
            p => {
                let mut basis = vec![0.0; p + 1];
                let mut scratch = BasisScratch::default();
                let mut k = p;
                for (u, o) in params.zip(out.chunks_exact_mut(C::DIM)) {
                    k = self.knots.span_from(u, k);
                    basis_functions(
                        self.knots.as_slice(),
                        k,
                        u,
                        p,
                        &mut basis,
                        &mut scratch,
                        None,
                    );
                    let mut h = C::Homogeneous::ZERO;
                    for (j, &b) in basis.iter().enumerate() {
                        h = h + self.homogeneous[k - p + j] * b;
                    }
                    self.project(h).write_to(o);
                }
            }
        }
    }

    fn sample_fixed<const N: usize>(&self, params: impl Iterator<Item = f64>, out: &mut [f64]) {
        let knots = self.knots.as_slice();
        let mut inv = [[0.0; N]; N];
        let mut k = usize::MAX;
        for (u, o) in params.zip(out.chunks_exact_mut(C::DIM)) {
            let next = self
                .knots
                .span_from(u, if k == usize::MAX { N - 1 } else { k });
            if next != k {
                k = next;
                span_reciprocals::<N>(knots, k, &mut inv);
            }
            let h = evaluate_fixed::<C::Homogeneous, N>(knots, &self.homogeneous, k, u, &inv);
            self.project(h).write_to(o);
        }
    }
}
