//! Piecewise (composite) Bézier curves: joining rules and a continuity checker (syllabus §1–2).

use super::BezierCurve;
use crate::error::JoinError;
use crate::error::{check_tolerance, Error, Result};
use crate::geom::{binomial, Cartesian, MAX_DEGREE};
use crate::prelude::*;

/// How two Bézier pieces `P` (degree n, on `[a0, b0]`) and `Q` (degree m, on `[a1, b1]`)
/// are joined at `P(b0) = Q(a1)`. With `h0 = b0 − a0`, `h1 = b1 − a1` (both 1 in the syllabus):
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JoinRule {
    /// `Q_0 = P_n`.
    C0,
    /// C0 and `n/h0 (P_n − P_{n−1}) = m/h1 (Q_1 − Q_0)`.
    C1,
    /// C1 and `n(n−1)/h0² (P_n − 2P_{n−1} + P_{n−2}) = m(m−1)/h1² (Q_2 − 2Q_1 + Q_0)`.
    C2,
    /// C0 and `Q_1` on the ray from `P_{n−1}` through `P_n`, beyond `P_n`, keeping its distance
    /// from `Q_0` (same tangent line, the speed may jump).
    G1,
}

impl JoinRule {
    /// Parses `"C0" | "C1" | "C2" | "G1"` (case-insensitive).
    pub fn parse(s: &str) -> Result<Self> {
        match s.to_ascii_uppercase().as_str() {
            "C0" => Ok(JoinRule::C0),
            "C1" => Ok(JoinRule::C1),
            "C2" => Ok(JoinRule::C2),
            "G1" => Ok(JoinRule::G1),
            _ => Err(Error::UnknownOption {
                name: "rule",
                value: s.into(),
                expected: "\"C0\", \"C1\", \"C2\", \"G1\"",
            }),
        }
    }
}

/// The continuity found at a joint: `c` is the largest k with `C^k` (−1 when the pieces do not
/// meet, [`Continuity::INFINITE`] when they are pieces of one polynomial), `g` the largest k
/// with `G^k` (checked up to `G^2`; 0 when the velocity vanishes at the joint, where the
/// tangent is undefined even if the derivatives agree).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Continuity {
    /// Parametric continuity order.
    pub c: i32,
    /// Geometric continuity order.
    pub g: i32,
}

impl Continuity {
    /// Stands for `C^∞`: all derivatives agree.
    pub const INFINITE: i32 = i32::MAX;
}

/// Moves the constrained points of one piece so that the joint obeys `rule`: with
/// `adjust_right` the right piece's first points follow the left piece (the syllabus form),
/// otherwise the left piece's last points follow the right one. Returns both pieces.
///
/// # Errors
/// [`JoinError::RationalJoin`] for rational pieces, [`JoinError::JoinDegree`] for a piece of too
/// low degree for the rule (C2 needs degree >= 2 on both sides), or pieces too short to leave the
/// constrained points free of each other.
pub fn join<C: Cartesian>(
    left: &BezierCurve<C>,
    right: &BezierCurve<C>,
    rule: JoinRule,
    adjust_right: bool,
) -> Result<(BezierCurve<C>, BezierCurve<C>)> {
    if left.is_rational() || right.is_rational() {
        return Err(Error::Join(JoinError::RationalJoin {}));
    }
    if !adjust_right {
        let (r, l) = join(
            &right.reversed_interval(),
            &left.reversed_interval(),
            rule,
            true,
        )?;
        return Ok((l.reversed_interval(), r.reversed_interval()));
    }
    let p = left.control_points();
    let mut q = right.control_points();
    let (n, m) = (left.degree(), right.degree());
    let h0 = left.b - left.a;
    let h1 = right.b - right.a;
    let needed = match rule {
        JoinRule::C0 => 0,
        JoinRule::C1 | JoinRule::G1 => 1,
        JoinRule::C2 => 2,
    };
    if n < needed || m < needed || (m < needed + 1 && needed > 0) {
        return Err(Error::Join(JoinError::JoinDegree {
            rule,
            left: n,
            right: m,
            needed: needed + 1,
        }));
    }
    q[0] = p[n];
    match rule {
        JoinRule::C0 => {}
        JoinRule::C1 | JoinRule::C2 => {
            let ratio = (n as f64 / h0) / (m as f64 / h1);
            q[1] = q[0] + (p[n] - p[n - 1]) * ratio;
            if rule == JoinRule::C2 {
                let ratio2 = (n as f64 * (n - 1) as f64 / (h0 * h0))
                    / (m as f64 * (m - 1) as f64 / (h1 * h1));
                let second = (p[n] - p[n - 1] * 2.0 + p[n - 2]) * ratio2;
                q[2] = second + q[1] * 2.0 - q[0];
            }
        }
        JoinRule::G1 => {
            let dir = p[n] - p[n - 1];
            let len = dir.norm();
            if len == 0.0 {
                return Err(Error::Join(JoinError::NoJointTangent {}));
            }
            let old = (right.control_points()[1] - right.control_points()[0]).norm();
            let dist = if old > 0.0 { old } else { len };
            q[1] = q[0] + dir * (dist / len);
        }
    }
    let new_right = BezierCurve::new(q, None)?.with_interval(right.a, right.b)?;
    Ok((left.clone(), new_right))
}

impl<C: Cartesian> BezierCurve<C> {
    /// The reversed curve on the mirrored interval `[−b, −a]`, so that joints keep their
    /// derivative magnitudes (used to apply a joining rule from the other side).
    fn reversed_interval(&self) -> Self {
        let mut r = self.reversed();
        r.a = -self.b;
        r.b = -self.a;
        r
    }
}

/// Relative tolerance of the continuity checks ([`check_continuity`],
/// [`CompositeCurve::continuity`]) when the caller gives none.
pub const DEFAULT_CONTINUITY_TOLERANCE: f64 = 1e-9;

/// Largest derivative order compared by [`check_continuity`] before declaring `C^∞`.
const MAX_CHECKED_ORDER: usize = 2 * super::MAX_DEGREE + 1;

/// The continuity at the joint between `left` (at the end of its interval) and `right` (at the
/// start of its interval), with derivatives taken with respect to each piece's own parameter
/// `t` (so pieces on `[0, 1)` and `[1, 2]` behave as one function of `t`).
///
/// `C^k`: derivatives of orders `0..=k` agree to within `tolerance × (1 + |value|)`. `G^1`:
/// the unit tangents agree; `G^2`: also the curvature vectors `(P'' − (P''·T)T)/|P'|²`.
/// Comparing up to the higher degree decides `C^∞`, since derivatives above it are zero.
///
/// Answers the exercise of the Italian notes (004): `1 − t²` then `2 − t²` is not C0;
/// `t² − 4t + 3`: C1; `t² − 2t + 1`: C0 but not C1.
///
/// # Errors
/// [`Error::InvalidTolerance`].
pub fn check_continuity<C: Cartesian>(
    left: &BezierCurve<C>,
    right: &BezierCurve<C>,
    tolerance: f64,
) -> Result<Continuity> {
    check_tolerance(tolerance)?;
    let same = |a: C, b: C| (a - b).norm() <= tolerance * (1.0 + a.norm().max(b.norm()));
    let top = left.degree().max(right.degree()).min(MAX_CHECKED_ORDER);
    let mut c = -1;
    for k in 0..=top {
        let l = left.derivative(left.b, k)?;
        let r = right.derivative(right.a, k)?;
        if !same(l, r) {
            break;
        }
        c = k as i32;
    }
    let polynomial = !left.is_rational() && !right.is_rational();
    if c == top as i32 && polynomial {
        c = Continuity::INFINITE;
    }
    // Geometric continuity is measured directly: with zero velocity at the joint the tangent
    // is undefined, so C^k does not imply G^1 there (a triple control point makes a corner).
    let mut g = c.min(0);
    if c >= 0 {
        let d1 = (left.derivative(left.b, 1)?, right.derivative(right.a, 1)?);
        let d2 = (left.derivative(left.b, 2)?, right.derivative(right.a, 2)?);
        let moving = !same(d1.0, C::ZERO) && !same(d1.1, C::ZERO);
        if moving {
            let (tl, tr) = (d1.0 * (1.0 / d1.0.norm()), d1.1 * (1.0 / d1.1.norm()));
            if same(tl, tr) {
                g = 1;
                let kappa =
                    |d1: C, d2: C, t: C| (d2 - t * d2.dot_with(t)) * (1.0 / d1.dot_with(d1));
                if same(kappa(d1.0, d2.0, tl), kappa(d1.1, d2.1, tr)) {
                    g = 2;
                }
            }
        }
    }
    Ok(Continuity { c, g })
}

/// A Bézier curve on `[a, b]` equal to the polynomial `Σ_k c_k t^k` in the global parameter
/// `t`, from power-basis coefficients given point by point (`coeffs[k]` multiplies `t^k`).
/// Substitutes `t = a + (b − a)s`, then converts to Bernstein form:
/// `b_i = Σ_{j<=i} C(i,j)/C(n,j) d_j` where `d_j` are the coefficients in `s`. A constant
/// becomes a degree-1 curve with equal points.
///
/// # Errors
/// [`Error::TooFewPoints`] without coefficients, plus the errors of [`BezierCurve::new`] and
/// [`BezierCurve::with_interval`].
pub fn from_polynomial<C: Cartesian>(coeffs: &[C], a: f64, b: f64) -> Result<BezierCurve<C>> {
    if coeffs.is_empty() {
        return Err(Error::TooFewPoints {
            needed: 1,
            got: 0,
            what: "polynomial",
        });
    }
    // The degree first: the conversion below is O(n²) (a 2000-coefficient call took 10 s
    // before BezierCurve::new refused it).
    if coeffs.len() - 1 > MAX_DEGREE {
        return Err(Error::TooLarge {
            what: "degree",
            value: coeffs.len() - 1,
            max: MAX_DEGREE,
        });
    }
    BezierCurve::new(vec![C::ZERO, C::ZERO], None)?.with_interval(a, b)?;
    let mut c = coeffs.to_vec();
    if c.len() == 1 {
        c.push(C::ZERO);
    }
    let n = c.len() - 1;
    let h = b - a;
    // d_j = Σ_{k>=j} c_k C(k, j) a^{k−j} h^j
    let d: Vec<C> = (0..=n)
        .map(|j| {
            (j..=n).fold(C::ZERO, |acc, k| {
                acc + c[k] * (binomial(k, j) * a.powi((k - j) as i32) * h.powi(j as i32))
            })
        })
        .collect();
    let points = (0..=n)
        .map(|i| {
            (0..=i).fold(C::ZERO, |acc, j| {
                acc + d[j] * (binomial(i, j) / binomial(n, j))
            })
        })
        .collect();
    BezierCurve::new(points, None)?.with_interval(a, b)
}

/// A piecewise Bézier curve: pieces on consecutive intervals `[t_0, t_1], [t_1, t_2], …`
/// (the breakpoints), evaluated with the global parameter. The pieces need not meet: the
/// continuity at each joint is what [`CompositeCurve::continuity`] reports.
#[derive(Debug, Clone, PartialEq)]
pub struct CompositeCurve<C: Cartesian> {
    pieces: Vec<BezierCurve<C>>,
}

impl<C: Cartesian> CompositeCurve<C> {
    /// Pieces from their control points and the breakpoints `t_0 < t_1 < … < t_k` (one more
    /// than the pieces); piece `i` is re-parametrised onto `[t_i, t_{i+1}]`.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] without pieces, [`JoinError::BreakpointCount`] for a wrong number of
    /// breakpoints, the errors of [`BezierCurve::with_interval`] for breakpoints out of order.
    pub fn new(pieces: Vec<BezierCurve<C>>, breaks: &[f64]) -> Result<Self> {
        if pieces.is_empty() {
            return Err(Error::TooFewPoints {
                needed: 1,
                got: 0,
                what: "composite-curve",
            });
        }
        if breaks.len() != pieces.len() + 1 {
            return Err(Error::Join(JoinError::BreakpointCount {
                pieces: pieces.len(),
                got: breaks.len(),
            }));
        }
        let pieces = pieces
            .into_iter()
            .zip(breaks.windows(2))
            .map(|(p, w)| p.with_interval(w[0], w[1]))
            .collect::<Result<Vec<_>>>()?;
        Ok(CompositeCurve { pieces })
    }

    /// Pieces given back to back as flat coordinates (`n_i + 1` points of `C::DIM` numbers for
    /// piece `i` of degree `degrees[i]`), on the breakpoints `breaks` (default `0, 1, …, k`).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for a piece of degree 0, the errors of
    /// [`crate::geom::points_from_flat`], [`JoinError::PiecePointCount`] when the degrees need
    /// `Σ (n_i + 1)` points and another number is given, then those of [`CompositeCurve::new`].
    ///
    /// ```
    /// use splinelab::{bezier::CompositeCurve, DVec2};
    /// // A line then a quadratic: 2 + 3 points.
    /// let coords = [0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 2.0, 2.0, 3.0, 1.0];
    /// let c = CompositeCurve::<DVec2>::from_flat(&coords, &[1, 2], None).unwrap();
    /// assert_eq!(c.domain(), (0.0, 2.0));
    /// ```
    pub fn from_flat(coords: &[f64], degrees: &[usize], breaks: Option<&[f64]>) -> Result<Self> {
        if let Some(&d) = degrees.iter().find(|&&d| d == 0) {
            return Err(Error::TooFewPoints {
                needed: 2,
                got: d + 1,
                what: "every-piece",
            });
        }
        let pts: Vec<C> = crate::geom::points_from_flat(coords)?;
        let needed: usize = degrees
            .iter()
            .map(|&d| d.saturating_add(1))
            .fold(0, usize::saturating_add);
        if needed != pts.len() {
            return Err(Error::Join(JoinError::PiecePointCount {
                degrees: degrees.to_vec(),
                needed,
                got: pts.len(),
            }));
        }
        let mut rest = pts.as_slice();
        let mut pieces = Vec::with_capacity(degrees.len());
        for &d in degrees {
            let (piece, tail) = rest.split_at(d + 1);
            pieces.push(BezierCurve::new(piece.to_vec(), None)?);
            rest = tail;
        }
        match breaks {
            Some(breaks) => CompositeCurve::new(pieces, breaks),
            None => {
                let breaks: Vec<f64> = (0..=degrees.len()).map(|i| i as f64).collect();
                CompositeCurve::new(pieces, &breaks)
            }
        }
    }

    /// The pieces, each on its own interval.
    pub fn pieces(&self) -> &[BezierCurve<C>] {
        &self.pieces
    }

    /// Moves control point `i` of piece `piece` to `p`, in place. The neighbours do not
    /// follow: keeping a joint is the caller's choice (move both pieces' shared points).
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`] for a piece past the last, then those of
    /// [`BezierCurve::set_control_point`].
    pub fn set_control_point(&mut self, piece: usize, i: usize, p: C) -> Result<()> {
        let count = self.pieces.len();
        match self.pieces.get_mut(piece) {
            Some(b) => b.set_control_point(i, p),
            None => Err(Error::IndexOutOfRange {
                index: piece,
                count,
            }),
        }
    }

    /// The global domain `[t_0, t_k]`.
    pub fn domain(&self) -> (f64, f64) {
        (self.pieces[0].a, self.pieces[self.pieces.len() - 1].b)
    }

    /// Index of the piece that owns `t`: pieces are closed on the left, so at a joint the
    /// right piece is used (right-continuity), except at the very end.
    pub fn piece_index(&self, t: f64) -> Result<usize> {
        crate::error::check_in_range("t", t, self.domain())?;
        Ok(self
            .pieces
            .partition_point(|p| p.b <= t)
            .min(self.pieces.len() - 1))
    }

    /// The point at the global parameter `t`.
    pub fn evaluate(&self, t: f64) -> Result<C> {
        self.pieces[self.piece_index(t)?].evaluate(t)
    }

    /// The derivative of the given order at `t` (the right piece's at a joint).
    pub fn derivative(&self, t: f64, order: usize) -> Result<C> {
        self.pieces[self.piece_index(t)?].derivative(t, order)
    }

    /// The continuity at each of the `k − 1` joints (see [`check_continuity`]).
    pub fn continuity(&self, tolerance: f64) -> Result<Vec<Continuity>> {
        self.pieces
            .windows(2)
            .map(|w| check_continuity(&w[0], &w[1], tolerance))
            .collect()
    }
}

/// Dense sampling and curvature come from the trait defaults (piece by piece).
impl<C: Cartesian> ParamCurve for CompositeCurve<C> {
    type Point = C;

    fn domain(&self) -> (f64, f64) {
        CompositeCurve::domain(self)
    }

    fn sample_degree(&self) -> usize {
        self.pieces
            .iter()
            .map(BezierCurve::degree)
            .max()
            .unwrap_or(0)
    }

    fn evaluate(&self, t: f64) -> Result<C> {
        CompositeCurve::evaluate(self, t)
    }
}

impl<C: Cartesian> ParamCurveDeriv for CompositeCurve<C> {
    fn derivative(&self, t: f64, order: usize) -> Result<C> {
        CompositeCurve::derivative(self, t, order)
    }
}
