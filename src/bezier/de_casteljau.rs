//! de Casteljau's algorithm on any point type (Cartesian or homogeneous), Bernstein
//! polynomials, subdivision and degree elevation (syllabus §2).

use crate::geom::{binomial, Params, Point, STACK_DEGREE};
use std::ops::Range;

/// The Bernstein polynomial `B_i^n(t) = C(n, i) t^i (1 − t)^(n − i)`; 0 when `i > n`.
///
/// Partition of unity: `Σ_i B_i^n(t) = 1`; symmetry `B_i^n(t) = B_{n−i}^n(1 − t)`; on `[0, 1]`
/// it has its single maximum at `t = i/n`.
///
/// ```
/// assert_eq!(splinelab::bezier::bernstein(2, 1, 0.5), 0.5);
/// ```
pub fn bernstein(n: usize, i: usize, t: f64) -> f64 {
    if i > n {
        return 0.0;
    }
    binomial(n, i) * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32)
}

/// The point `p_0^n(s)` of de Casteljau's recurrence `p_i^r = (1 − s) p_i^{r−1} + s p_{i+1}^{r−1}`,
/// computed in `scratch` (resized to the number of points, reused between calls so dense
/// sampling allocates once). O(n²) per point. `points` must not be empty.
#[inline]
pub fn de_casteljau_point<P: Point>(points: &[P], s: f64, scratch: &mut Vec<P>) -> P {
    scratch.clear();
    scratch.extend_from_slice(points);
    let n = points.len() - 1;
    for r in 1..=n {
        for i in 0..=n - r {
            scratch[i] = scratch[i].lerp_to(scratch[i + 1], s);
        }
    }
    scratch[0]
}

/// `Σ_{i=0..m} B_i^m(s) c_i` for `m ≤ STACK_DEGREE`, with the coefficients given by `c(i)`,
/// straight from the Bernstein form: `B_i^m(s) = C(m,i) s^i (1 − s)^{m−i}`, the powers of
/// `1 − s` in a stack array and those of `s` running. Every basis value is a product of
/// non-negative numbers (no cancellation), so the sum is as accurate as de Casteljau's (a few
/// ulps of `Σ |c_i| B_i^m(s)`), and exact where de Casteljau is (small dyadic data: the worked
/// example's `P(1/4) = (29/16, 23/16)`); `s = 0` and `s = 1` give `c_0` and `c_m` exactly. One
/// point of a low degree: `m + 1` multiply-adds per coordinate, nothing allocated or copied (`c`
/// may compute the points, e.g. the differences of a derivative).
#[inline]
pub fn bernstein_small<P: Point>(m: usize, s: f64, c: impl Fn(usize) -> P) -> P {
    let m = m.min(STACK_DEGREE);
    let r = 1.0 - s;
    let mut r_pow = [1.0; STACK_DEGREE + 1];
    for k in 1..=m {
        r_pow[k] = r_pow[k - 1] * r;
    }
    // The binomials from a table: a running C(m, i+1) = C(m, i)(m − i)/(i + 1) would chain
    // m divisions, most of this function's time.
    let binom = &PASCAL[m];
    let (mut sum, mut s_pow) = (P::ZERO, 1.0);
    for i in 0..=m {
        sum = sum + c(i) * (binom[i] * s_pow * r_pow[m - i]);
        s_pow *= s;
    }
    sum
}

/// `PASCAL[m][i] = C(m, i)` for `m ≤ STACK_DEGREE` (Pascal's triangle, exact in f64).
const PASCAL: [[f64; STACK_DEGREE + 1]; STACK_DEGREE + 1] = {
    let mut t = [[0.0; STACK_DEGREE + 1]; STACK_DEGREE + 1];
    let mut m = 0;
    while m <= STACK_DEGREE {
        t[m][0] = 1.0;
        let mut i = 1;
        while i <= m {
            t[m][i] = t[m - 1][i - 1] + t[m - 1][i];
            i += 1;
        }
        m += 1;
    }
    t
};

/// All levels of de Casteljau's triangle, concatenated: level 0 (the `n + 1` control points)
/// first, then level `r` with its `n + 1 − r` points; `(n + 1)(n + 2)/2` points in all, the last
/// one being the point on the curve.
pub fn de_casteljau_triangle<P: Point>(points: &[P], s: f64) -> Vec<P> {
    let n = points.len() - 1;
    let mut out = Vec::with_capacity((n + 1) * (n + 2) / 2);
    out.extend_from_slice(points);
    let mut start = 0;
    for r in 1..=n {
        let len = n + 2 - r; // length of level r − 1
        for i in 0..len - 1 {
            let p = out[start + i].lerp_to(out[start + i + 1], s);
            out.push(p);
        }
        start += len;
    }
    out
}

/// Splits the control polygon at `s`: the left half's points are the top edge of the
/// triangle `l_i = p_0^i(s)`, the right half's the hypotenuse `r_i = p_{i}^{n−i}(s)`.
/// Both halves are Bézier curves of the same degree that together trace the original curve.
pub fn split_points<P: Point>(points: &[P], s: f64) -> (Vec<P>, Vec<P>) {
    let n = points.len() - 1;
    let mut work = points.to_vec();
    let mut left = Vec::with_capacity(n + 1);
    let mut right = vec![P::ZERO; n + 1];
    left.push(work[0]);
    right[n] = work[n];
    for r in 1..=n {
        for i in 0..=n - r {
            work[i] = work[i].lerp_to(work[i + 1], s);
        }
        left.push(work[0]);
        right[n - r] = work[n - r];
    }
    (left, right)
}

/// Control points of the piece of the curve between local parameters `s0 < s1` (both in
/// `[0, 1]`), as a Bézier curve of the same degree on `[0, 1]`.
pub fn subsegment_points<P: Point>(points: &[P], s0: f64, s1: f64) -> Vec<P> {
    if s0 <= 0.0 {
        if s1 >= 1.0 {
            return points.to_vec();
        }
        return split_points(points, s1).0;
    }
    let (_, right) = split_points(points, s0);
    if s1 >= 1.0 {
        return right;
    }
    split_points(&right, (s1 - s0) / (1.0 - s0)).0
}

/// Degree elevation by one: `Q_i = i/(n+1) P_{i−1} + (1 − i/(n+1)) P_i`, `i = 0..=n+1`.
/// The curve does not change; the new polygon lies closer to it.
pub fn elevate_points<P: Point>(points: &[P]) -> Vec<P> {
    let n = points.len() - 1;
    let m = (n + 1) as f64;
    let mut out = Vec::with_capacity(n + 2);
    out.push(points[0]);
    for i in 1..=n {
        let a = i as f64 / m;
        out.push(points[i - 1] * a + points[i] * (1.0 - a));
    }
    out.push(points[n]);
    out
}

/// The hodograph's control points without the factor `n`: the forward differences
/// `P_{i+1} − P_i`. The derivative of the curve is `n Σ B_i^{n−1}(s) (P_{i+1} − P_i)`.
pub fn differences<P: Point>(points: &[P]) -> Vec<P> {
    points.windows(2).map(|w| w[1] - w[0]).collect()
}

/// Power-basis coefficients `c_k` of `Σ_i B_i^m(s) Q_i = Σ_k c_k s^k`:
/// `c_k = C(m,k) Σ_{i<=k} (−1)^{k−i} C(k,i) Q_i`. Evaluating them by Horner's rule costs `m`
/// multiply-adds per coordinate instead of de Casteljau's `m(m+1)/2` lerps; for the low degrees
/// where it is used the rounding stays at the level of a few ulps of the coefficients.
pub fn power_coefficients<P: Point>(points: &[P]) -> Vec<P> {
    let m = points.len() - 1;
    (0..=m)
        .map(|k| {
            let sum = (0..=k).fold(P::ZERO, |acc, i| {
                let sign = if (k - i) % 2 == 0 { 1.0 } else { -1.0 };
                acc + points[i] * (sign * binomial(k, i))
            });
            sum * binomial(m, k)
        })
        .collect()
}

/// [`power_coefficients`] in place, by the forward-difference table: after pass `r`
/// (`q_i ← q_i − q_{i−1}` for `i = m … r`) entry `k ≤ r` holds `Δ^k Q_0`, and
/// `c_k = C(m, k) Δ^k Q_0`. No allocation: for the per-span set-up of dense kernels.
pub fn to_power_form<P: Point>(points: &mut [P]) {
    let m = points.len().saturating_sub(1);
    for r in 1..=m {
        for i in (r..=m).rev() {
            points[i] = points[i] - points[i - 1];
        }
    }
    for (k, c) in points.iter_mut().enumerate() {
        *c = *c * binomial(m, k);
    }
}

/// Highest degree the dense Horner kernel takes (power-form coefficients on the stack).
pub const DENSE_MAX_DEGREE: usize = 5;

/// A polynomial piece in power form, `Σ_{j≤degree} c_j s^j` in the local parameter
/// `s = (u − start)·scale`: what the dense kernels evaluate.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PowerForm<P> {
    /// `c_0 … c_degree` (the rest unused).
    pub c: [P; DENSE_MAX_DEGREE + 1],
    /// At most [`DENSE_MAX_DEGREE`].
    pub degree: usize,
    /// The parameter where `s = 0`.
    pub start: f64,
    /// `ds/du`.
    pub scale: f64,
}

impl<P: Point> PowerForm<P> {
    /// Whether every coefficient is finite. The power form's coefficients reach `2^degree`
    /// times the control points' size (binomials times alternating differences), so control
    /// points near `f64::MAX` can overflow here where de Casteljau and de Boor (convex
    /// combinations) stay finite; the dense paths then take those.
    pub fn is_finite(&self) -> bool {
        self.c[..=self.degree]
            .iter()
            .all(|q| (0..P::DIM).all(|i| q.coord(i).is_finite()))
    }

    /// The same piece with `f` applied to each coefficient (e.g. dropping the weight).
    pub fn map<Q: Point>(&self, f: impl Fn(P) -> Q) -> PowerForm<Q> {
        PowerForm {
            c: self.c.map(f),
            degree: self.degree,
            start: self.start,
            scale: self.scale,
        }
    }
}

/// The dense kernel shared by Bézier and B-spline sampling: writes `finish(piece(u))` for the
/// parameters `run` of `params` into `out` (`C::DIM` numbers each). `ends`, when given,
/// replace the values at `s = 0` and `s = 1` (exact end points; the sum of the coefficients is
/// the end only up to rounding). The loop is unrolled for a fixed length: a loop over the
/// runtime degree measured 3–4× slower.
pub(crate) fn horner_run<Q: Point, C: Point>(
    piece: &PowerForm<Q>,
    params: Params,
    run: Range<usize>,
    finish: impl Fn(Q) -> C + Copy,
    ends: Option<(C, C)>,
    out: &mut [f64],
) {
    if run.is_empty() {
        // `sampleUniform(0)`: nothing to write (the uniform loop below assumes a last point).
        return;
    }
    // Two unrolled lengths: degrees 1–3 as cubics and 4–5 as quintics, the unused leading
    // coefficients zero (Horner's rule then performs exactly the operations of the shorter
    // loop: 0·s + c = c), so the results are bit-identical and the wasm keeps two copies.
    if piece.degree <= 3 {
        horner_run_fixed::<Q, C, 4>(piece, params, run, finish, ends, out);
    } else {
        horner_run_fixed::<Q, C, 6>(piece, params, run, finish, ends, out);
    }
}

/// [`horner_run`] for degree `N − 1`, unrolled.
#[inline(never)]
fn horner_run_fixed<Q: Point, C: Point, const N: usize>(
    piece: &PowerForm<Q>,
    params: Params,
    run: Range<usize>,
    finish: impl Fn(Q) -> C,
    ends: Option<(C, C)>,
    out: &mut [f64],
) {
    let mut c = [Q::ZERO; N];
    c.copy_from_slice(&piece.c[..N]);
    let (start, scale) = (piece.start, piece.scale);
    let value = |s: f64| match ends {
        Some((first, _)) if s == 0.0 => first,
        Some((_, last)) if s == 1.0 => last,
        _ => finish(horner_fixed(&c, s)),
    };
    let outs = out.chunks_exact_mut(C::DIM);
    match params {
        Params::Slice(us) => {
            for (&u, o) in us[run].iter().zip(outs) {
                value((u - start) * scale).write_to(o);
            }
        }
        Params::Uniform {
            start: u0,
            step,
            end,
            count,
        } => {
            // s = (u0 + step·i − start)·scale, with the two products folded out of the loop;
            // the grid's last value is exact, so the run's last point is done apart, and the
            // loop in between is Horner's rule alone (s = 0 and s = 1 lie only at the ends).
            let (s0, ds) = ((u0 - start) * scale, step * scale);
            let ends_here = run.end == count;
            let inner = run.start..if ends_here { run.end - 1 } else { run.end };
            let mut outs = outs;
            for (i, o) in inner.zip(&mut outs) {
                finish(horner_fixed(&c, s0 + ds * i as f64)).write_to(o);
            }
            if ends_here {
                if let Some(o) = outs.next() {
                    value((end - start) * scale).write_to(o);
                }
            }
            if run.start == 0 && s0 == 0.0 {
                if let (Some((first, _)), Some(o)) = (ends, out.get_mut(..C::DIM)) {
                    first.write_to(o);
                }
            }
        }
    }
}

/// `Σ_k coeffs[k] s^k` by Horner's rule, unrolled for a fixed number of coefficients.
#[inline(always)]
pub fn horner_fixed<P: Point, const N: usize>(coeffs: &[P; N], s: f64) -> P {
    let mut h = coeffs[N - 1];
    for j in (0..N - 1).rev() {
        h = h * s + coeffs[j];
    }
    h
}

/// The value and first derivative (with respect to `s`) of `Σ_k coeffs[k] s^k`, by Horner's
/// rule run twice in one loop: `d ← d·s + h`, `h ← h·s + c_k`.
#[inline(always)]
pub fn horner_with_derivative_fixed<P: Point, const N: usize>(coeffs: &[P; N], s: f64) -> (P, P) {
    let mut h = coeffs[N - 1];
    let mut d = P::ZERO;
    for j in (0..N - 1).rev() {
        d = d * s + h;
        h = h * s + coeffs[j];
    }
    (h, d)
}

/// `Σ_k coeffs[k] s^k` by Horner's rule.
#[inline]
pub fn horner<P: Point>(coeffs: &[P], s: f64) -> P {
    coeffs.iter().rev().fold(P::ZERO, |acc, &c| acc * s + c)
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;
    use glam::DVec2;

    #[test]
    fn triangle_has_all_levels() {
        let p = [DVec2::ZERO, DVec2::X, DVec2::ONE];
        let tri = de_casteljau_triangle(&p, 0.5);
        assert_eq!(tri.len(), 6);
        assert_eq!(tri[5], DVec2::new(0.75, 0.25));
    }

    #[test]
    fn subsegment_of_whole_is_identity() {
        let p = [DVec2::ZERO, DVec2::X, DVec2::ONE];
        assert_eq!(subsegment_points(&p, 0.0, 1.0), p.to_vec());
    }
}
