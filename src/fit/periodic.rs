//! Periodic least squares, the knots: the closed B-spline of degree `p` with `N` distinct control points
//! nearest, in the sum of squared distances, to samples `Q_0 … Q_{M−1}` of a loop at parameters
//! `t_k ∈ [0, 1)` (period 1).
//!
//! **Knots** (the periodic form of NURBS Book eq. 9.69): with `d = M/N`, knot `u_{p+j}`,
//! `j = 0..=N`, sits at the fractional sample index `j·d` (`t` interpolated linearly, `t_M = 1`),
//! so every span holds about `d ≥ 1` samples; `p` more knots at each end repeat the gaps with
//! the period, `u_{p−i−1} = u_{p−i} − Δ_{N−1−(i mod N)}`, `u_{N+p+i+1} = u_{N+p+i} + Δ_{i mod N}`
//! (as scipy's periodic knots). The domain is `[u_p, u_{N+p}] = [0, 1]`.
//!
//! **Control points**: `P_0 … P_{N−1}`, then `P_0 … P_{p−1}` again (`N + p` in all, the last
//! `p` marked as copies). Repeated gaps and repeated points make the curve and its first
//! `p − 1` derivatives agree at `0` and `1`: it closes `C^{p−1}`.
//!
//! **System**: `C(t_k) = Σ_a N_{s−p+a,p}(t_k) P_{(s−p+a) mod N}` (`s` the span of `t_k`): the
//! normal equations form a symmetric cyclic band, solved in [`super::weighted`].

/// The periodic knots for `count` distinct control points (see the module doc); `params`
/// increasing in `[0, 1)`.
pub(super) fn periodic_knots(params: &[f64], degree: usize, count: usize) -> Vec<f64> {
    let (p, n, m) = (degree, count, params.len());
    let d = m as f64 / n as f64;
    let at = |i: usize| if i >= m { 1.0 } else { params[i] };
    let mut knots = vec![0.0; n + 2 * p + 1];
    for j in 0..=n {
        knots[p + j] = if j == 0 {
            0.0
        } else if j == n {
            1.0
        } else {
            let x = j as f64 * d;
            let i = x.floor() as usize;
            let alpha = x - i as f64;
            (1.0 - alpha) * at(i) + alpha * at(i + 1)
        };
    }
    let gaps: Vec<f64> = knots[p..=n + p].windows(2).map(|w| w[1] - w[0]).collect();
    let len = knots.len();
    for i in 0..p {
        knots[p - i - 1] = knots[p - i] - gaps[n - 1 - (i % n)];
        knots[len - p + i] = knots[len - p + i - 1] + gaps[i % n];
    }
    knots
}
