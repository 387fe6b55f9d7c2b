//! Automatic tangents for piecewise cubic Hermite interpolation (syllabus §5): cardinal,
//! Catmull–Rom (Barry–Goldman, any α) and Bessel. Every tangent is `C'(t_i)` with respect to the
//! global parameter; `Δ_i = t_{i+1} − t_i` and `s_i = (p_{i+1} − p_i)/Δ_i` are the gaps and
//! chord slopes of the data.

use crate::geom::Point;

/// Chord slope `(b − a)/Δ`.
fn slope<P: Point>(a: P, b: P, delta: f64) -> P {
    (b - a) * (1.0 / delta)
}

/// Cardinal tangents with tension c:
/// `m_i = (1 − c)(p_{i+1} − p_{i−1})/(t_{i+1} − t_{i−1})` (c = 0: the Catmull–Rom rule on these
/// parameters, c = 1: zero tangents). The ends use phantom points reflected through the end
/// point, `p_{−1} = 2p_0 − p_1` at `t_{−1} = t_0 − Δ_0` and `p_{n+1} = 2p_n − p_{n−1}` at
/// `t_{n+1} = t_n + Δ_{n−1}`, which gives `m_0 = (1 − c)(p_1 − p_0)/Δ_0` and
/// `m_n = (1 − c)(p_n − p_{n−1})/Δ_{n−1}`. Needs at least 2 points.
pub fn cardinal_tangents<P: Point>(points: &[P], params: &[f64], tension: f64) -> Vec<P> {
    let n = points.len() - 1;
    let k = 1.0 - tension;
    (0..=n)
        .map(|i| {
            if i == 0 {
                slope(points[0], points[1], params[1] - params[0]) * k
            } else if i == n {
                slope(points[n - 1], points[n], params[n] - params[n - 1]) * k
            } else {
                slope(points[i - 1], points[i + 1], params[i + 1] - params[i - 1]) * k
            }
        })
        .collect()
}

/// The Barry–Goldman tangent at `p` between `prev` (gap `d0` before) and `next` (gap `d1`
/// after): `m = (p − prev)/d0 − (next − prev)/(d0 + d1) + (next − p)/d1`, the derivative at
/// `p` of the centripetal-style Catmull–Rom construction (the tangent of the parabola through
/// the three points at those parameters).
fn barry_goldman<P: Point>(prev: P, d0: f64, p: P, next: P, d1: f64) -> P {
    slope(prev, p, d0) - slope(prev, next, d0 + d1) + slope(p, next, d1)
}

/// Catmull–Rom tangents on the parameters `t_i` (for catmullRom, `Σ |Δp|^α`): the
/// Barry–Goldman tangent at every point. Open ends use the phantoms `p_{−1} = 2p_0 − p_1` and
/// `p_{n+1} = 2p_n − p_{n−1}` with the same gaps as their neighbours (`|p_0 − p_{−1}| =
/// |p_1 − p_0|`), which gives `m_0 = s_0`, `m_n = s_{n−1}`. A closed curve (`p_n = p_0`)
/// wraps: the neighbours of `p_0 = p_n` are `p_{n−1}` and `p_1`, so `m_0 = m_n`.
pub fn catmull_rom_tangents<P: Point>(points: &[P], params: &[f64], closed: bool) -> Vec<P> {
    let n = points.len() - 1;
    let gap = |i: usize| params[i + 1] - params[i];
    let mut out: Vec<P> = (0..=n)
        .map(|i| {
            if i > 0 && i < n {
                barry_goldman(points[i - 1], gap(i - 1), points[i], points[i + 1], gap(i))
            } else if closed {
                barry_goldman(points[n - 1], gap(n - 1), points[0], points[1], gap(0))
            } else if i == 0 {
                let phantom = points[0] * 2.0 - points[1];
                barry_goldman(phantom, gap(0), points[0], points[1], gap(0))
            } else {
                let phantom = points[n] * 2.0 - points[n - 1];
                barry_goldman(points[n - 1], gap(n - 1), points[n], phantom, gap(n - 1))
            }
        })
        .collect();
    if closed {
        out[n] = out[0];
    }
    out
}

/// The tangent at `t_i` of the parabola through `(t_{i−1}, p_{i−1})`, `(t_i, p_i)`,
/// `(t_{i+1}, p_{i+1})`: `(Δ_i s_{i−1} + Δ_{i−1} s_i)/(Δ_{i−1} + Δ_i)`.
fn parabola_middle<P: Point>(s0: P, d0: f64, s1: P, d1: f64) -> P {
    (s0 * d1 + s1 * d0) * (1.0 / (d0 + d1))
}

/// The tangent at the first of three points `(t_0, p_0), (t_1, p_1), (t_2, p_2)` of the parabola
/// through them: `((2Δ_0 + Δ_1) s_0 − Δ_0 s_1)/(Δ_0 + Δ_1)`.
pub(crate) fn parabola_start<P: Point>(s0: P, d0: f64, s1: P, d1: f64) -> P {
    (s0 * (2.0 * d0 + d1) - s1 * d0) * (1.0 / (d0 + d1))
}

/// The tangent at the last of three points (slopes `s0` over gap `d0`, then `s1` over `d1`):
/// `((2Δ_1 + Δ_0) s_1 − Δ_1 s_0)/(Δ_0 + Δ_1)`.
pub(crate) fn parabola_end<P: Point>(s0: P, d0: f64, s1: P, d1: f64) -> P {
    (s1 * (2.0 * d1 + d0) - s0 * d1) * (1.0 / (d0 + d1))
}

/// The Bessel end tangents `(m_0, m_n)`: those of the parabolas through the first and the last
/// three points (with 2 points, the line's slope `s_0` at both ends).
pub(crate) fn bessel_end_tangents<P: Point>(points: &[P], params: &[f64]) -> (P, P) {
    let n = points.len() - 1;
    let d = |i: usize| params[i + 1] - params[i];
    let s = |i: usize| slope(points[i], points[i + 1], d(i));
    if n == 1 {
        return (s(0), s(0));
    }
    (
        parabola_start(s(0), d(0), s(1), d(1)),
        parabola_end(s(n - 2), d(n - 2), s(n - 1), d(n - 1)),
    )
}

/// Bessel tangents: at every interior `t_i` the tangent of the parabola through
/// `p_{i−1}, p_i, p_{i+1}`, `m_i = (Δ_i s_{i−1} + Δ_{i−1} s_i)/(Δ_{i−1} + Δ_i)`; at the ends that
/// of the first and last parabola (through the first and the last three points); 2 points give
/// the line.
pub fn bessel_tangents<P: Point>(points: &[P], params: &[f64]) -> Vec<P> {
    let n = points.len() - 1;
    let d = |i: usize| params[i + 1] - params[i];
    let s = |i: usize| slope(points[i], points[i + 1], d(i));
    let (start, end) = bessel_end_tangents(points, params);
    (0..=n)
        .map(|i| {
            if i == 0 {
                start
            } else if i == n {
                end
            } else {
                parabola_middle(s(i - 1), d(i - 1), s(i), d(i))
            }
        })
        .collect()
}
