//! The C2 cubic spline's tangent system (syllabus §5) and its end conditions.
//!
//! Unknowns: the tangents `m_i = C'(t_i)`. With `Δ_i = t_{i+1} − t_i` and the chord slopes
//! `s_i = (p_{i+1} − p_i)/Δ_i`, C2 continuity at an interior `t_i` (i = 1..n−1) reads
//! `Δ_i m_{i−1} + 2(Δ_{i−1} + Δ_i) m_i + Δ_{i−1} m_{i+1} = 3(Δ_i s_{i−1} + Δ_{i−1} s_i)`
//! (the syllabus' row, with `Δ_i/Δ_{i−1}(p_i − p_{i−1}) = Δ_i s_{i−1}`). The end rows are derived
//! from the piece on `[t_0, t_1]`, `C(t) = p_0 + m_0 u + c u² + d u³` with `u = t − t_0`,
//! `c = (3s_0 − 2m_0 − m_1)/Δ_0`, `d = (m_0 + m_1 − 2s_0)/Δ_0²` (likewise at the end):
//!
//! - natural, `C''(t_0) = 2c = 0`: `2m_0 + m_1 = 3s_0`; at the end `m_{n−1} + 2m_n = 3s_{n−1}`;
//! - quadratic (first/last piece a parabola, `d = 0`): `m_0 + m_1 = 2s_0`,
//!   `m_{n−1} + m_n = 2s_{n−1}`;
//! - clamped: `m_0`, `m_n` given;
//! - Bessel: `m_0`, `m_n` the end tangents of the parabolas through the first and last three
//!   points;
//! - not-a-knot (`C'''` continuous at `t_1` and `t_{n−1}`): `d_0 = d_1`, which involves
//!   `m_0, m_1, m_2`; subtracting the interior row at `t_1` eliminates `m_2` and leaves
//!   `Δ_1 m_0 + (Δ_0 + Δ_1) m_1 = ((Δ_0 + 2(Δ_0 + Δ_1))Δ_1 s_0 + Δ_0² s_1)/(Δ_0 + Δ_1)` and at the
//!   end `(Δ_{n−2} + Δ_{n−1}) m_{n−1} + Δ_{n−2} m_n =
//!   (Δ_{n−1}² s_{n−2} + (2(Δ_{n−2} + Δ_{n−1}) + Δ_{n−1})Δ_{n−2} s_{n−1})/(Δ_{n−2} + Δ_{n−1})`
//!   (scipy's rows). With 3 points it is the one parabola (quadratic rows), with 2 the line;
//! - periodic (`p_n = p_0`): `m_n = m_0` and C2 at the seam: the interior row for every
//!   i = 0..n−1 with indices modulo n, a cyclic system of size n.
//!
//! Quadratic, Bessel and not-a-knot with 2 points give the line (`m_0 = m_1 = s_0`), as scipy.

use super::tangents::bessel_end_tangents;
use super::tridiagonal::Tridiagonal;
use crate::error::{Error, Result};
use crate::geom::Point;

/// The end condition of a C2 cubic spline (see the module documentation for each row).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EndCondition<P> {
    /// `C''(t_0) = C''(t_n) = 0`.
    Natural,
    /// Given end tangents `C'(t_0) = start`, `C'(t_n) = end` (w.r.t. the parameter).
    Clamped {
        /// `C'(t_0)`.
        start: P,
        /// `C'(t_n)`.
        end: P,
    },
    /// The first and last pieces are parabolas.
    Quadratic,
    /// End tangents of the parabolas through the first and last three points.
    Bessel,
    /// `C'''` continuous at `t_1` and `t_{n−1}` (the first two and last two pieces are one cubic).
    NotAKnot,
    /// A closed curve: `p_n = p_0`, C2 at the seam.
    Periodic,
}

/// The accepted names of [`EndCondition::parse`].
pub const END_CONDITION_NAMES: &str =
    "\"natural\", \"clamped\", \"quadratic\", \"bessel\", \"not-a-knot\", \"periodic\"";

impl<P: Point> EndCondition<P> {
    /// Parses `"natural" | "clamped" | "quadratic" | "bessel" | "not-a-knot" | "periodic"`;
    /// "clamped" takes the end tangents (`startTangent`, `endTangent`), which must be given.
    ///
    /// # Errors
    /// [`Error::UnknownOption`] for another name, [`Error::MissingArgument`] for "clamped"
    /// without a tangent.
    pub fn parse(name: &str, start: Option<P>, end: Option<P>) -> Result<Self> {
        Ok(match name {
            "natural" => EndCondition::Natural,
            "quadratic" => EndCondition::Quadratic,
            "bessel" => EndCondition::Bessel,
            "not-a-knot" => EndCondition::NotAKnot,
            "periodic" => EndCondition::Periodic,
            "clamped" => {
                const NEEDED_BY: &str = "clamped-end-condition";
                let start = start.ok_or(Error::MissingArgument {
                    name: "startTangent",
                    needed_by: NEEDED_BY,
                })?;
                let end = end.ok_or(Error::MissingArgument {
                    name: "endTangent",
                    needed_by: NEEDED_BY,
                })?;
                EndCondition::Clamped { start, end }
            }
            _ => {
                return Err(Error::UnknownOption {
                    name: "end",
                    value: name.into(),
                    expected: END_CONDITION_NAMES,
                })
            }
        })
    }

    /// The fewest data points the condition works with: 3 for periodic (two distinct points
    /// and the repeated first), else 2.
    pub fn min_points(&self) -> usize {
        match self {
            EndCondition::Periodic => 3,
            _ => 2,
        }
    }

    /// The name as `parse` takes it.
    pub fn name(&self) -> &'static str {
        match self {
            EndCondition::Natural => "natural",
            EndCondition::Clamped { .. } => "clamped",
            EndCondition::Quadratic => "quadratic",
            EndCondition::Bessel => "bessel",
            EndCondition::NotAKnot => "not-a-knot",
            EndCondition::Periodic => "periodic",
        }
    }
}

/// The tangent system of the C2 spline through `points` at `params` (at least
/// `end.min_points()` points, params strictly increasing): rows in the order of the unknowns,
/// row i for `m_i`; `n + 1` rows, or `n` cyclic rows (m_0..m_{n−1}) for periodic.
pub fn spline_system<P: Point>(
    points: &[P],
    params: &[f64],
    end: &EndCondition<P>,
) -> Tridiagonal<P> {
    let n = points.len() - 1;
    let d: Vec<f64> = params.windows(2).map(|w| w[1] - w[0]).collect();
    let s: Vec<P> = points
        .windows(2)
        .zip(&d)
        .map(|(w, &di)| (w[1] - w[0]) * (1.0 / di))
        .collect();
    let interior = |i: usize, prev: usize| (s[prev] * d[i] + s[i] * d[prev]) * 3.0;
    if let EndCondition::Periodic = end {
        let prev = |i: usize| (i + n - 1) % n;
        return Tridiagonal {
            lower: (1..n).map(|i| d[i]).collect(),
            diagonal: (0..n).map(|i| 2.0 * (d[prev(i)] + d[i])).collect(),
            upper: (0..n - 1).map(|i| d[prev(i)]).collect(),
            rhs: (0..n).map(|i| interior(i, prev(i))).collect(),
            corners: Some([d[0], d[n.saturating_sub(2)]]),
        };
    }
    let mut lower = vec![0.0; n];
    let mut diagonal = vec![0.0; n + 1];
    let mut upper = vec![0.0; n];
    let mut rhs = vec![P::ZERO; n + 1];
    for i in 1..n {
        lower[i - 1] = d[i];
        diagonal[i] = 2.0 * (d[i - 1] + d[i]);
        upper[i] = d[i - 1];
        rhs[i] = interior(i, i - 1);
    }
    // The line through two points, for the conditions that need three.
    let line = n == 1
        && matches!(
            end,
            EndCondition::Quadratic | EndCondition::Bessel | EndCondition::NotAKnot
        );
    let (bessel_start, bessel_end) = match end {
        EndCondition::Bessel => bessel_end_tangents(points, params),
        _ => (P::ZERO, P::ZERO),
    };
    // (diagonal, off-diagonal, rhs) of the first and of the last row.
    let (first, last) = if line {
        ((1.0, 0.0, s[0]), (1.0, 0.0, s[0]))
    } else {
        match *end {
            EndCondition::Natural => ((2.0, 1.0, s[0] * 3.0), (2.0, 1.0, s[n - 1] * 3.0)),
            EndCondition::Clamped { start, end } => ((1.0, 0.0, start), (1.0, 0.0, end)),
            EndCondition::Bessel => ((1.0, 0.0, bessel_start), (1.0, 0.0, bessel_end)),
            EndCondition::Quadratic => ((1.0, 1.0, s[0] * 2.0), (1.0, 1.0, s[n - 1] * 2.0)),
            EndCondition::NotAKnot if n == 2 => ((1.0, 1.0, s[0] * 2.0), (1.0, 1.0, s[1] * 2.0)),
            EndCondition::NotAKnot => {
                let (d0, d1) = (d[0], d[1]);
                let sum = d0 + d1;
                let start_rhs = (s[0] * ((d0 + 2.0 * sum) * d1) + s[1] * (d0 * d0)) * (1.0 / sum);
                let (a, b) = (d[n - 2], d[n - 1]);
                let sum_end = a + b;
                let end_rhs =
                    (s[n - 2] * (b * b) + s[n - 1] * ((2.0 * sum_end + b) * a)) * (1.0 / sum_end);
                ((d1, sum, start_rhs), (a, sum_end, end_rhs))
            }
            // Returned above; these rows are never used.
            EndCondition::Periodic => ((1.0, 0.0, P::ZERO), (1.0, 0.0, P::ZERO)),
        }
    };
    diagonal[0] = first.0;
    upper[0] = first.1;
    rhs[0] = first.2;
    diagonal[n] = last.0;
    lower[n - 1] = last.1;
    rhs[n] = last.2;
    Tridiagonal {
        lower,
        diagonal,
        upper,
        rhs,
        corners: None,
    }
}
