//! Knot vectors for global interpolation and least squares, and the Schoenberg–Whitney check
//! for knots a caller gives.
//!
//! **Averaging** (NURBS Book eq. 9.8, de Boor): for `M + 1` sites `τ_0 ≤ … ≤ τ_M`, `p + 1`
//! copies of `τ_0`, interior knots `u_{j+p} = (1/p) Σ_{i=j}^{j+p−1} τ_i` for `j = 1..=M−p`, and
//! `p + 1` copies of `τ_M`. The sites are the parameters, with `t_0` written twice for a start
//! derivative and `t_n` twice for an end derivative (one site per equation):
//! - no derivative: `τ = (t_0 … t_n)`, eq. 9.8 itself;
//! - both: `τ = (t_0, t_0, t_1 … t_n, t_n)`, which gives eq. 9.22,
//!   `u_{j+p} = (1/p) Σ_{i=j−1}^{j+p−2} t_i`, `j = 1..=n−p+2`;
//! - start only: `τ = (t_0, t_0, t_1 … t_n)`: `u_{j+p} = (1/p) Σ_{i=j−1}^{j+p−2} t_i`,
//!   `j = 1..=n−p+1`;
//! - end only: `τ = (t_0 … t_n, t_n)`: `u_{j+p} = (1/p) Σ_{i=j}^{j+p−1} t_i`, `j = 1..=n−p+1`
//!   (eq. 9.8's knots and one more).
//!
//! These satisfy Schoenberg–Whitney, `u_i < τ_i < u_{i+p+1}` (equal at the clamped ends), for
//! any strictly increasing parameters when `p ≥ 2`: the mean of `p ≥ 2` sites of which at most
//! two are equal lies strictly between its neighbours. For `p = 1` a doubled site would become
//! a triple knot, so degree 1 uses the parameters as knots with the doubled one replaced by the
//! midpoint of its interval (`(t_0 + t_1)/2`, `(t_{n−1} + t_n)/2`; with both derivatives and
//! two points, the thirds of `[t_0, t_1]`).
//!
//! **Least squares** (NURBS Book eq. 9.68–9.69) for `m + 1` data and `n + 1` control points:
//! `d = (m + 1)/(n − p + 1)`; for `j = 1..=n−p`, `i = ⌊j d⌋`, `α = j d − i`,
//! `u_{p+j} = (1 − α) t_{i−1} + α t_i`; clamped at `t_0` and `t_m`. Every knot span then holds
//! a parameter, so the normal equations are positive definite. With `n = m` (as many control
//! points as data) the averaging knots are used instead, so the fit is exactly the default
//! interpolant.
//!
//! **Periodic** (scipy's `_periodic_knots`, so closed curves agree with
//! `make_interp_spline(…, bc_type="periodic")`): the parameters `x_0 … x_n` (for even `p` the
//! inner ones moved to the midpoints `x_i − (x_i − x_{i−1})/2`), extended by `p` knots at each
//! end whose gaps repeat the `n` gaps cyclically: `u_{p−i−1} = u_{p−i} − Δ_{n−1−(i mod n)}`,
//! `u_{n+p+i+1} = u_{n+p+i} + Δ_{i mod n}`.

use crate::error::InterpError;
use crate::error::{Error, Result};

/// Averaging knots for `params` with or without end derivatives (see the module doc).
pub fn averaging_knots(params: &[f64], degree: usize, start: bool, end: bool) -> Vec<f64> {
    let p = degree;
    let n = params.len() - 1;
    let (a, b) = (params[0], params[n]);
    let mut knots =
        Vec::with_capacity(params.len() + usize::from(start) + usize::from(end) + p + 1);
    knots.extend(std::iter::repeat_n(a, p + 1));
    if p == 1 {
        let mut interior: Vec<f64> = params[1..n].to_vec();
        if start && end && n == 1 {
            interior = vec![a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0];
        } else {
            if start {
                interior.insert(0, 0.5 * (params[0] + params[1]));
            }
            if end {
                interior.push(0.5 * (params[n - 1] + params[n]));
            }
        }
        knots.extend(interior);
    } else {
        let mut sites = Vec::with_capacity(params.len() + 2);
        if start {
            sites.push(a);
        }
        sites.extend_from_slice(params);
        if end {
            sites.push(b);
        }
        let m = sites.len() - 1;
        for j in 1..=m.saturating_sub(p) {
            let sum: f64 = sites[j..j + p].iter().sum();
            knots.push(sum / p as f64);
        }
    }
    knots.extend(std::iter::repeat_n(b, p + 1));
    knots
}

/// The least-squares knots of eq. 9.69 for `count` control points (averaging when `count`
/// equals the number of data points; see the module doc).
pub fn least_squares_knots(params: &[f64], degree: usize, count: usize) -> Vec<f64> {
    let (p, m, n) = (degree, params.len() - 1, count - 1);
    if n == m {
        return averaging_knots(params, degree, false, false);
    }
    let d = (m + 1) as f64 / (n - p + 1) as f64;
    let mut knots = Vec::with_capacity(n + p + 2);
    knots.extend(std::iter::repeat_n(params[0], p + 1));
    for j in 1..=n - p {
        let jd = j as f64 * d;
        let i = (jd.floor() as usize).clamp(1, m);
        let alpha = jd - i as f64;
        knots.push((1.0 - alpha) * params[i - 1] + alpha * params[i]);
    }
    knots.extend(std::iter::repeat_n(params[m], p + 1));
    knots
}

/// scipy's periodic knots for the parameters of a closed curve (see the module doc):
/// `n + 2p + 1` knots, domain `[x_0, x_n]`.
pub fn periodic_knots(params: &[f64], degree: usize) -> Vec<f64> {
    let (p, n) = (degree, params.len() - 1);
    let mut x = params.to_vec();
    if p % 2 == 0 {
        for i in 1..n {
            x[i] = params[i] - (params[i] - params[i - 1]) / 2.0;
        }
    }
    let gaps: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
    let mut knots = vec![0.0; n + 1 + 2 * p];
    knots[p..=n + p].copy_from_slice(&x);
    let len = knots.len();
    for i in 0..p {
        knots[p - i - 1] = knots[p - i] - gaps[n - 1 - (i % n)];
        knots[len - p + i] = knots[len - p + i - 1] + gaps[i % n];
    }
    knots
}

/// Whether site `tau` may be matched with basis function `i` (support `[lo, hi]`): strictly
/// inside, or on a clamped end of the domain `[a, b]`.
fn inside(tau: f64, lo: f64, hi: f64, (a, b): (f64, f64)) -> bool {
    (lo < tau || (tau == lo && tau == a)) && (tau < hi || (tau == hi && tau == b))
}

/// Checks the Schoenberg–Whitney condition for interpolation at `sites` (one per control
/// point; a derivative repeats its parameter): `u_i < τ_i < u_{i+p+1}`, equality allowed where
/// `τ_i` is the end of the domain and the knot equals it.
///
/// # Errors
/// [`InterpError::SchoenbergWhitney`] naming the first `i` that fails.
pub fn check_schoenberg_whitney(knots: &[f64], degree: usize, sites: &[f64]) -> Result<()> {
    let p = degree;
    let domain = (knots[p], knots[sites.len()]);
    for (i, &tau) in sites.iter().enumerate() {
        let (lo, hi) = (knots[i], knots[i + p + 1]);
        if !inside(tau, lo, hi, domain) {
            return Err(Error::Interp(InterpError::SchoenbergWhitney {
                index: i,
                param: tau,
                lo,
                hi,
                degree,
            }));
        }
    }
    Ok(())
}

/// The least-squares form of Schoenberg–Whitney: some increasing choice of parameters
/// `t_{k_0} < t_{k_1} < …` has `t_{k_i}` inside the support of `N_{i,p}` for every control point
/// `i`, so the fit's matrix has full column rank. Checked greedily (each basis function takes
/// the first parameter left that fits, which is optimal because the supports' ends increase).
///
/// # Errors
/// [`InterpError::SchoenbergWhitney`] naming the basis function `i` that finds no parameter, with
/// `param` the first parameter still unmatched (or the last parameter when none is left).
pub fn check_schoenberg_whitney_subsequence(
    knots: &[f64],
    degree: usize,
    count: usize,
    params: &[f64],
) -> Result<()> {
    let p = degree;
    let domain = (knots[p], knots[count]);
    let mut k = 0;
    for i in 0..count {
        let (lo, hi) = (knots[i], knots[i + p + 1]);
        while k < params.len() && !inside(params[k], lo, hi, domain) && params[k] < hi {
            k += 1;
        }
        if k >= params.len() || !inside(params[k], lo, hi, domain) {
            let param = params[k.min(params.len() - 1)];
            return Err(Error::Interp(InterpError::SchoenbergWhitney {
                index: i,
                param,
                lo,
                hi,
                degree,
            }));
        }
        k += 1;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    #[test]
    fn averaging_examples() {
        let t = [0.0, 1.0, 2.0, 3.0, 4.0];
        assert_eq!(
            averaging_knots(&t, 2, false, false),
            [0.0, 0.0, 0.0, 1.5, 2.5, 4.0, 4.0, 4.0]
        );
        // Eq. 9.22 for p = 2: the midpoints of every interval.
        assert_eq!(
            averaging_knots(&t, 2, true, true),
            [0.0, 0.0, 0.0, 0.5, 1.5, 2.5, 3.5, 4.0, 4.0, 4.0]
        );
        assert_eq!(
            averaging_knots(&t, 2, true, false),
            [0.0, 0.0, 0.0, 0.5, 1.5, 2.5, 4.0, 4.0, 4.0]
        );
        assert_eq!(
            averaging_knots(&t, 3, false, true),
            [0.0, 0.0, 0.0, 0.0, 2.0, 3.0, 4.0, 4.0, 4.0, 4.0]
        );
        assert_eq!(
            averaging_knots(&t, 1, true, false),
            [0.0, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0, 4.0]
        );
    }

    #[test]
    fn periodic_knots_extend_the_gaps_cyclically() {
        // x = 0, 1, 3, 6 (gaps 1, 2, 3), cubic: three knots either side.
        assert_eq!(
            periodic_knots(&[0.0, 1.0, 3.0, 6.0], 3),
            [-6.0, -5.0, -3.0, 0.0, 1.0, 3.0, 6.0, 7.0, 9.0, 12.0]
        );
    }
}
