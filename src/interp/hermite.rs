//! Cubic Hermite pieces (syllabus §5): the four basis functions on `[0, 1]` and the Bézier
//! form of a piece on an interval of length `Δ`.
//!
//! `H(s) = H0(s) p0 + H1(s) p1 + H2(s) m0 + H3(s) m1`, `s ∈ [0, 1]`, with
//! `H0 = 2s³ − 3s² + 1`, `H1 = −2s³ + 3s²`, `H2 = s³ − 2s² + s`, `H3 = s³ − s²`:
//! `H(0) = p0`, `H(1) = p1`, `H'(0) = m0`, `H'(1) = m1`. On `[t_i, t_{i+1}]` with
//! `Δ = t_{i+1} − t_i` and tangents `m` with respect to the global `t`, the local tangents are
//! `Δ·m` (chain rule, `dt = Δ ds`).

use crate::geom::Point;

/// `[H0, H1, H2, H3](s)`; `H0 + H1 = 1` for every s.
pub fn hermite_basis(s: f64) -> [f64; 4] {
    let s2 = s * s;
    let s3 = s2 * s;
    [
        2.0 * s3 - 3.0 * s2 + 1.0,
        -2.0 * s3 + 3.0 * s2,
        s3 - 2.0 * s2 + s,
        s3 - s2,
    ]
}

/// The derivatives `[H0', H1', H2', H3'](s)`: `6s² − 6s`, `−6s² + 6s`, `3s² − 4s + 1`, `3s² − 2s`.
pub fn hermite_basis_derivative(s: f64) -> [f64; 4] {
    let s2 = s * s;
    [
        6.0 * s2 - 6.0 * s,
        -6.0 * s2 + 6.0 * s,
        3.0 * s2 - 4.0 * s + 1.0,
        3.0 * s2 - 2.0 * s,
    ]
}

/// The Bézier control points of the Hermite piece from `p0` to `p1` with tangents `m0`, `m1`
/// (with respect to a parameter running over an interval of length `delta`):
/// `[p0, p0 + Δ·m0/3, p1 − Δ·m1/3, p1]` (`B'(0) = 3(q1 − q0)` in the local parameter).
pub fn hermite_to_bezier<P: Point>(p0: P, m0: P, p1: P, m1: P, delta: f64) -> [P; 4] {
    let third = delta / 3.0;
    [p0, p0 + m0 * third, p1 - m1 * third, p1]
}

/// The Hermite piece at the local `s ∈ [0, 1]` on an interval of length `delta` (tangents
/// `m0`, `m1` with respect to the global parameter): `H0 p0 + H1 p1 + Δ(H2 m0 + H3 m1)`.
pub fn hermite_point<P: Point>(p0: P, m0: P, p1: P, m1: P, delta: f64, s: f64) -> P {
    let [h0, h1, h2, h3] = hermite_basis(s);
    p0 * h0 + p1 * h1 + (m0 * h2 + m1 * h3) * delta
}
