//! Dense sampling. The parameters are cut into runs that fall in one knot span (sorted input
//! walks the knots once). A long run converts its span to the power form once — the span's
//! Bézier points by blossoming, then `Σ c_j s^j` in the local `s = (u − u_k)/(u_{k+1} − u_k)`
//! — and costs `p` multiply-adds per coordinate per point by Horner's rule. A short run
//! evaluates the `p + 1` non-zero basis functions with per-span reciprocals of the knot
//! differences (no division per point but the homogeneous one). The basis kernel is unrolled
//! for each degree 1–5, the Horner kernel for cubics and quintics (lower degrees with zero
//! leading coefficients); other degrees take the general Cox–de Boor path.

use super::{basis_functions, BSplineCurve, BasisScratch};
use crate::bezier::{horner_run, horner_with_derivative_fixed, to_power_form, PowerForm};
use crate::error::{Error, Result};
use crate::geom::{check_out_len, check_work, rational_derivative, MAX_DERIVATIVE_ORDER};
use crate::geom::{Cartesian, Params, Point};
use crate::prelude::*;
use std::ops::Range;

/// Points per run from which converting the span to the power form pays for itself: the
/// conversion costs about as much as `p + 1` evaluations by basis functions.
const POWER_FORM_MIN_RUN: usize = 8;

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

/// Highest degree with unrolled kernels.
const MAX_FAST_DEGREE: usize = crate::bezier::HORNER_MAX_DEGREE;

/// The power form of the non-empty span `k` (`u_k < u_{k+1}`) of a B-spline of degree `p`:
/// writes `c_0 … c_p` into `out[..=p]` with `C(u) = Σ_j c_j s^j`, `s = (u − u_k)/(u_{k+1} − u_k)`.
/// First the span's Bézier points `b_i = f(u_k, …, u_k, u_{k+1}, …, u_{k+1})` (`p − i` times
/// `u_k`, `i` times `u_{k+1}`), each blossom value by de Boor's triangle with one argument per
/// level (`α = (x_r − u_i)/(u_{i+p+1−r} − u_i)`, `i = k − p + j`; every denominator spans the
/// non-empty span, so none is zero), then [`to_power_form`].
fn span_power_form<H: Point>(knots: &[f64], points: &[H], k: usize, p: usize, out: &mut [H]) {
    let (a, b) = (knots[k], knots[k + 1]);
    let mut q = [H::ZERO; MAX_FAST_DEGREE + 1];
    for (i, slot) in out.iter_mut().take(p + 1).enumerate() {
        q[..=p].copy_from_slice(&points[k - p..=k]);
        for r in 1..=p {
            let x = if r <= p - i { a } else { b };
            for j in (r..=p).rev() {
                let lo = knots[k - p + j];
                let hi = knots[k + j - r + 1];
                q[j] = q[j - 1].lerp_to(q[j], (x - lo) / (hi - lo));
            }
        }
        *slot = q[p];
    }
    to_power_form(&mut out[..=p]);
}

/// Writes `d/du Σ_j c_j s^j`, `s = (u − a)·scale`, for the parameters `run` into `out`: value
/// and derivative by one Horner loop, `dC/du = (dC/ds)·scale`, and for homogeneous
/// coefficients the quotient rule `C' = (A' − w' C)/w`.
#[inline(never)]
fn derivative_run<C: Cartesian, const N: usize, const RATIONAL: bool>(
    c: &[C::Homogeneous],
    (a, scale): (f64, f64),
    us: &[f64],
    out: &mut [f64],
) {
    if RATIONAL {
        let mut coeffs = [C::Homogeneous::ZERO; N];
        coeffs.copy_from_slice(&c[..N]);
        for (&u, o) in us.iter().zip(out.chunks_exact_mut(C::DIM)) {
            let (h, d) = horner_with_derivative_fixed(&coeffs, (u - a) * scale);
            let w = 1.0 / C::weight_of(h);
            let point = C::numerator(h) * w;
            ((C::numerator(d) - point * C::weight_of(d)) * (w * scale)).write_to(o);
        }
    } else {
        let mut coeffs = [C::ZERO; N];
        for (x, &h) in coeffs.iter_mut().zip(c) {
            *x = C::numerator(h);
        }
        for (&u, o) in us.iter().zip(out.chunks_exact_mut(C::DIM)) {
            let (_, d) = horner_with_derivative_fixed(&coeffs, (u - a) * scale);
            (d * scale).write_to(o);
        }
    }
}

impl<C: Cartesian> BSplineCurve<C> {
    /// Cuts `params` (each already checked to lie in the domain) into maximal runs of
    /// consecutive parameters in one span and calls `f(k, run)` for each, `k` the span.
    fn for_each_run(&self, params: Params, mut f: impl FnMut(usize, Range<usize>)) {
        let knots = self.knots.as_slice();
        let last = self.knots.last_span();
        let count = params.len();
        let mut k = self.degree();
        let mut i = 0;
        while i < count {
            k = self.knots.span_from(params.get(i), k);
            let (a, b) = (knots[k], knots[k + 1]);
            let mut end = i + 1;
            while end < count {
                let u = params.get(end);
                if u < a || u > b || (u == b && k != last) {
                    break;
                }
                end += 1;
            }
            f(k, i..end);
            i = end;
        }
    }

    /// The power form of span `k` (see [`span_power_form`]), in `s = (u − u_k)/(u_{k+1} − u_k)`;
    /// `None` when a coefficient overflows (see [`PowerForm::is_finite`]).
    fn power_form(&self, k: usize) -> Option<PowerForm<C::Homogeneous>> {
        let knots = self.knots.as_slice();
        let mut c = [C::Homogeneous::ZERO; MAX_FAST_DEGREE + 1];
        span_power_form(knots, &self.homogeneous, k, self.degree(), &mut c);
        let piece = PowerForm {
            c,
            degree: self.degree(),
            start: knots[k],
            scale: 1.0 / (knots[k + 1] - knots[k]),
        };
        piece.is_finite().then_some(piece)
    }

    /// Writes `C(u)` for every `u` of `params` (each checked to lie in the domain) into `out`,
    /// `DIM` numbers per point: the power form on runs of at least [`POWER_FORM_MIN_RUN`]
    /// parameters in one span, the basis functions otherwise.
    pub(crate) fn sample_params_into(&self, params: Params, out: &mut [f64]) {
        let p = self.degree();
        let knots = self.knots.as_slice();
        let mut basis = vec![0.0; p + 1];
        let mut scratch = BasisScratch::default();
        self.for_each_run(params, |k, run| {
            let outs = &mut out[run.start * C::DIM..run.end * C::DIM];
            let dense = p <= MAX_FAST_DEGREE && run.len() >= POWER_FORM_MIN_RUN;
            if let Some(piece) = dense.then(|| self.power_form(k)).flatten() {
                if self.rational {
                    horner_run(&piece, params, run, C::project, None, outs);
                } else {
                    horner_run(&piece.map(C::numerator), params, run, |q| q, None, outs);
                }
                return;
            }
            match p {
                1 => self.basis_run::<2>(k, params, run, outs),
                2 => self.basis_run::<3>(k, params, run, outs),
                3 => self.basis_run::<4>(k, params, run, outs),
                4 => self.basis_run::<5>(k, params, run, outs),
                5 => self.basis_run::<6>(k, params, run, outs),
                _ => {
                    for (i, o) in run.zip(outs.chunks_exact_mut(C::DIM)) {
                        let u = params.get(i);
                        basis_functions(knots, k, u, p, &mut basis, &mut scratch, None);
                        let mut h = C::Homogeneous::ZERO;
                        for (j, &b) in basis.iter().enumerate() {
                            h = h + self.homogeneous[k - p + j] * b;
                        }
                        self.project(h).write_to(o);
                    }
                }
            }
        });
    }

    /// The points at `run` of `params`, all in span `k`, from the `N` non-zero basis functions
    /// of degree `N − 1` with the span's reciprocals.
    #[inline(never)]
    fn basis_run<const N: usize>(
        &self,
        k: usize,
        params: Params,
        run: Range<usize>,
        out: &mut [f64],
    ) {
        let knots = self.knots.as_slice();
        let mut inv = [[0.0; N]; N];
        span_reciprocals::<N>(knots, k, &mut inv);
        for (i, o) in run.zip(out.chunks_exact_mut(C::DIM)) {
            let h = evaluate_fixed::<C::Homogeneous, N>(
                knots,
                &self.homogeneous,
                k,
                params.get(i),
                &inv,
            );
            self.project(h).write_to(o);
        }
    }

    /// First derivatives `C'(u)` at `us` (checked) into `out` for degrees up to 5: the power
    /// form on runs of at least [`POWER_FORM_MIN_RUN`] parameters in one span (see
    /// [`derivative_run`]); `short(run, out)` computes the other runs.
    pub(crate) fn first_derivatives_into(
        &self,
        us: &[f64],
        out: &mut [f64],
        mut short: impl FnMut(Range<usize>, &mut [f64]),
    ) {
        let p = self.degree();
        self.for_each_run(Params::Slice(us), |k, run| {
            let outs = &mut out[run.start * C::DIM..run.end * C::DIM];
            let dense = p <= MAX_FAST_DEGREE && run.len() >= POWER_FORM_MIN_RUN;
            let Some(piece) = dense.then(|| self.power_form(k)).flatten() else {
                short(run, outs);
                return;
            };
            let (c, local) = (&piece.c, (piece.start, piece.scale));
            let us = &us[run];
            // Degrees 1–3 as cubics, 4–5 as quintics (zero leading coefficients; see
            // `horner_run`).
            match (p <= 3, self.rational) {
                (true, true) => derivative_run::<C, 4, true>(c, local, us, outs),
                (false, true) => derivative_run::<C, 6, true>(c, local, us, outs),
                (true, false) => derivative_run::<C, 4, false>(c, local, us, outs),
                (false, false) => derivative_run::<C, 6, false>(c, local, us, outs),
            }
        });
    }
}

impl<C: Cartesian> BSplineCurve<C> {
    /// Writes `C(u)` for every `u` of `us` into `out` (point-major). All parameters are checked
    /// first; spans are found from the previous one (sorted input walks the knots once), and
    /// one set of buffers serves every point.
    pub fn sample_into(&self, us: &[f64], out: &mut [f64]) -> Result<()> {
        check_out_len(out.len(), us.len(), C::DIM, self.degree())?;
        for &u in us {
            self.knots.check_parameter(u)?;
        }
        self.sample_params_into(Params::Slice(us), out);
        Ok(())
    }

    /// Writes `count` points at equally spaced parameters over the domain (ends included;
    /// `count = 1` gives the start point, as for Bézier curves).
    pub fn sample_uniform_into(&self, count: usize, out: &mut [f64]) -> Result<()> {
        check_out_len(out.len(), count, C::DIM, self.degree())?;
        let (a, b) = self.domain();
        self.sample_params_into(Params::uniform(a, b, count), out);
        Ok(())
    }

    /// Writes the derivative of order `order` at every `u` of `us` into `out` (point-major),
    /// walking the spans once for sorted input: the derivative control points are computed
    /// once, then each point costs `order + 1` basis evaluations and no allocation (the
    /// quotient rule for rational curves runs on the stack).
    ///
    /// # Errors
    /// [`Error::TooLarge`] above [`MAX_DERIVATIVE_ORDER`] or the work budget
    /// [`crate::geom::MAX_SAMPLE_WORK`], a wrong `out` length, a bad parameter.
    pub fn sample_derivatives_into(&self, us: &[f64], order: usize, out: &mut [f64]) -> Result<()> {
        if order > MAX_DERIVATIVE_ORDER {
            return Err(Error::TooLarge {
                what: "derivative-order",
                value: order,
                max: MAX_DERIVATIVE_ORDER,
            });
        }
        let p = self.degree();
        let orders = if self.rational { order } else { order.min(p) } + 1;
        let units = (p + 1).pow(2) * orders + 16 * orders * orders + 64;
        check_work("sample-work", us.len(), units)?;
        check_out_len(out.len(), us.len(), C::DIM, p)?;
        for &u in us {
            self.knots.check_parameter(u)?;
        }
        if !self.rational && order > p {
            out.fill(0.0);
            return Ok(());
        }
        // The derivative control points serve the per-point path only: made on first use, so
        // a first derivative sampled densely (every run in the power form) never builds them.
        let mut points: Option<Vec<Vec<C::Homogeneous>>> = None;
        let mut basis = vec![0.0; p + 1];
        let mut scratch = BasisScratch::default();
        let mut homogeneous = vec![C::Homogeneous::ZERO; order + 1];
        let knots = self.knots.as_slice();
        let mut general = |us: &[f64], out: &mut [f64]| {
            let points = points.get_or_insert_with(|| self.derivative_points(order));
            let mut s = p;
            for (&u, o) in us.iter().zip(out.chunks_exact_mut(C::DIM)) {
                s = self.knots.span_from(u, s);
                for (k, h) in homogeneous.iter_mut().enumerate() {
                    *h = C::Homogeneous::ZERO;
                    if k > p {
                        continue;
                    }
                    let q = p - k;
                    basis_functions(knots, s, u, q, &mut basis[..=q], &mut scratch, None);
                    for (j, &b) in basis[..=q].iter().enumerate() {
                        *h = *h + points[k][s - p + j] * b;
                    }
                }
                let d = if self.rational {
                    rational_derivative::<C>(&homogeneous)
                } else {
                    C::numerator(homogeneous[order])
                };
                d.write_to(o);
            }
        };
        if order == 1 {
            self.first_derivatives_into(us, out, |run, o| general(&us[run], o));
        } else {
            general(us, out);
        }
        Ok(())
    }
}
