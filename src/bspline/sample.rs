//! Dense sampling. The parameters are cut into runs that fall in one knot span (sorted input
//! walks the knots once). A long run converts its span to the power form once — the span's
//! Bézier points by blossoming, then `Σ c_j s^j` in the local `s = (u − u_k)/(u_{k+1} − u_k)`
//! — and costs `p` multiply-adds per coordinate per point by Horner's rule. A short run
//! evaluates the `p + 1` non-zero basis functions with per-span reciprocals of the knot
//! differences (no division per point but the homogeneous one). Both kernels are unrolled for
//! degrees 1–5; other degrees take the general Cox–de Boor path.

use super::{basis_functions, BSplineCurve, BasisScratch};
use crate::bezier::{horner_fixed, horner_with_derivative_fixed, power_coefficients_fixed};
use crate::geom::{Cartesian, Point};
use std::ops::Range;

/// Points per run from which converting the span to the power form pays for itself: the
/// conversion costs about as much as `p + 1` evaluations by basis functions.
pub(crate) const POWER_FORM_MIN_RUN: usize = 8;

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

/// The Bézier control points of the non-empty span `k` (`u_k < u_{k+1}`) of a B-spline of
/// degree `p = N − 1`: `b_i = f(u_k, …, u_k, u_{k+1}, …, u_{k+1})` (`p − i` times `u_k`, `i`
/// times `u_{k+1}`), each blossom value by de Boor's triangle with one argument per level
/// (`α = (x_r − u_i)/(u_{i+p+1−r} − u_i)`, `i = k − p + j`; every denominator spans the
/// non-empty span, so none is zero).
#[inline]
pub(crate) fn span_bezier_points<H: Point, const N: usize>(
    knots: &[f64],
    points: &[H],
    k: usize,
) -> [H; N] {
    let p = N - 1;
    let (a, b) = (knots[k], knots[k + 1]);
    let mut bezier = [H::ZERO; N];
    for (i, slot) in bezier.iter_mut().enumerate() {
        let mut q = [H::ZERO; N];
        q.copy_from_slice(&points[k - p..=k]);
        for r in 1..N {
            let x = if r <= p - i { a } else { b };
            for j in (r..N).rev() {
                let lo = knots[k - p + j];
                let hi = knots[k + j - r + 1];
                q[j] = q[j - 1].lerp_to(q[j], (x - lo) / (hi - lo));
            }
        }
        *slot = q[p];
    }
    bezier
}

impl<C: Cartesian> BSplineCurve<C> {
    /// Cuts the parameters `param(0) … param(count − 1)` (each already checked to lie in the
    /// domain) into maximal runs of consecutive parameters in one span and calls `f(k, run)`
    /// for each, `k` the span.
    #[inline(always)]
    fn for_each_run(
        &self,
        count: usize,
        param: impl Fn(usize) -> f64,
        mut f: impl FnMut(usize, Range<usize>),
    ) {
        let knots = self.knots.as_slice();
        let last = self.knots.last_span();
        let mut k = self.degree();
        let mut i = 0;
        while i < count {
            k = self.knots.span_from(param(i), k);
            let (a, b) = (knots[k], knots[k + 1]);
            let mut end = i + 1;
            while end < count {
                let u = param(end);
                if u < a || u > b || (u == b && k != last) {
                    break;
                }
                end += 1;
            }
            f(k, i..end);
            i = end;
        }
    }

    /// Writes `C(param(i))` for `i < count` (each checked to lie in the domain) into `out`,
    /// `DIM` numbers per point.
    pub(crate) fn sample_params_into(
        &self,
        count: usize,
        param: impl Fn(usize) -> f64 + Copy,
        out: &mut [f64],
    ) {
        match self.degree() {
            1 => self.sample_fixed::<2>(count, param, out),
            2 => self.sample_fixed::<3>(count, param, out),
            3 => self.sample_fixed::<4>(count, param, out),
            4 => self.sample_fixed::<5>(count, param, out),
            5 => self.sample_fixed::<6>(count, param, out),
            p => {
                let mut basis = vec![0.0; p + 1];
                let mut scratch = BasisScratch::default();
                let knots = self.knots.as_slice();
                self.for_each_run(count, param, |k, run| {
                    let outs = &mut out[run.start * C::DIM..run.end * C::DIM];
                    for (i, o) in run.zip(outs.chunks_exact_mut(C::DIM)) {
                        let u = param(i);
                        basis_functions(knots, k, u, p, &mut basis, &mut scratch, None);
                        let mut h = C::Homogeneous::ZERO;
                        for (j, &b) in basis.iter().enumerate() {
                            h = h + self.homogeneous[k - p + j] * b;
                        }
                        self.project(h).write_to(o);
                    }
                });
            }
        }
    }

    /// [`Self::sample_params_into`] for degree `N − 1`: the power form on long runs, the basis
    /// functions with per-span reciprocals on short ones.
    fn sample_fixed<const N: usize>(
        &self,
        count: usize,
        param: impl Fn(usize) -> f64 + Copy,
        out: &mut [f64],
    ) {
        let knots = self.knots.as_slice();
        let mut inv = [[0.0; N]; N];
        self.for_each_run(count, param, |k, run| {
            let outs = &mut out[run.start * C::DIM..run.end * C::DIM];
            if run.len() >= POWER_FORM_MIN_RUN {
                let (a, b) = (knots[k], knots[k + 1]);
                let scale = 1.0 / (b - a);
                let local = |i: usize| (param(i) - a) * scale;
                let bezier = span_bezier_points::<_, N>(knots, &self.homogeneous, k);
                if self.rational {
                    let c = power_coefficients_fixed(&bezier);
                    for (i, o) in run.zip(outs.chunks_exact_mut(C::DIM)) {
                        C::project(horner_fixed(&c, local(i))).write_to(o);
                    }
                } else {
                    let c = power_coefficients_fixed(&bezier.map(C::numerator));
                    for (i, o) in run.zip(outs.chunks_exact_mut(C::DIM)) {
                        horner_fixed(&c, local(i)).write_to(o);
                    }
                }
            } else {
                span_reciprocals::<N>(knots, k, &mut inv);
                for (i, o) in run.zip(outs.chunks_exact_mut(C::DIM)) {
                    let h = evaluate_fixed::<C::Homogeneous, N>(
                        knots,
                        &self.homogeneous,
                        k,
                        param(i),
                        &inv,
                    );
                    self.project(h).write_to(o);
                }
            }
        });
    }

    /// First derivatives `C'(u)` at `us` (checked) into `out`, for degree `N − 1`, on the runs
    /// long enough for the power form: value and derivative by one Horner loop,
    /// `dC/du = (dC/ds)/(u_{k+1} − u_k)`, and for a rational curve the quotient rule
    /// `C' = (A' − w' C)/w`. Returns the runs it left to the caller (too short), in order.
    pub(crate) fn first_derivatives_power_form<const N: usize>(
        &self,
        us: &[f64],
        out: &mut [f64],
        mut short: impl FnMut(usize, Range<usize>, &mut [f64]),
    ) {
        let knots = self.knots.as_slice();
        self.for_each_run(
            us.len(),
            |i| us[i],
            |k, run| {
                let outs = &mut out[run.start * C::DIM..run.end * C::DIM];
                if run.len() < POWER_FORM_MIN_RUN {
                    short(k, run, outs);
                    return;
                }
                let (a, b) = (knots[k], knots[k + 1]);
                let scale = 1.0 / (b - a);
                let bezier = span_bezier_points::<_, N>(knots, &self.homogeneous, k);
                let params = us[run].iter().zip(outs.chunks_exact_mut(C::DIM));
                if self.rational {
                    let c = power_coefficients_fixed(&bezier);
                    for (&u, o) in params {
                        let (h, d) = horner_with_derivative_fixed(&c, (u - a) * scale);
                        let w = 1.0 / C::weight_of(h);
                        let point = C::numerator(h) * w;
                        ((C::numerator(d) - point * C::weight_of(d)) * (w * scale)).write_to(o);
                    }
                } else {
                    let c = power_coefficients_fixed(&bezier.map(C::numerator));
                    for (&u, o) in params {
                        let (_, d) = horner_with_derivative_fixed(&c, (u - a) * scale);
                        (d * scale).write_to(o);
                    }
                }
            },
        );
    }
}
