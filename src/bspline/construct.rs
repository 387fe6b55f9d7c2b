//! Parametrisations and knot vectors made from points (syllabus §3, §5; the Greek notes'
//! formulas in our convention), and phantom end points.

use crate::error::InterpError;
use crate::error::{Error, Result};
use crate::geom::Point;

/// How parameter values (or knot gaps) are spaced: steps `|P_{i+1} − P_i|^α`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Parameterization {
    /// Equal steps: 0, 1, 2, … (α = 0; repeated points allowed).
    Uniform,
    /// Steps equal to the distances `|P_{i+1} − P_i|` (α = 1).
    Chord,
    /// Steps equal to `sqrt|P_{i+1} − P_i|` (α = 1/2).
    Centripetal,
    /// Steps `|P_{i+1} − P_i|^α` for an exponent α strictly between 0 and 1 other than 1/2
    /// (build it with [`Parameterization::from_alpha`], which names the three classic ones).
    Alpha(f64),
}

impl std::fmt::Display for Parameterization {
    /// `Uniform`, `Chord`, `Centripetal` (as in messages so far), or `alpha = 0.3`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Parameterization::Uniform => f.write_str("Uniform"),
            Parameterization::Chord => f.write_str("Chord"),
            Parameterization::Centripetal => f.write_str("Centripetal"),
            Parameterization::Alpha(a) => {
                write!(f, "alpha = {}", crate::platform::number_text(*a))
            }
        }
    }
}

impl Parameterization {
    /// Parses `"uniform" | "chord" | "centripetal"`.
    pub fn parse(s: &str) -> Result<Self> {
        match s {
            "uniform" => Ok(Parameterization::Uniform),
            "chord" => Ok(Parameterization::Chord),
            "centripetal" => Ok(Parameterization::Centripetal),
            _ => Err(Error::UnknownOption {
                name: "kind",
                value: s.into(),
                expected: "\"uniform\", \"chord\", \"centripetal\" (or a number alpha in [0, 1])",
            }),
        }
    }

    /// The spacing with exponent α ∈ [0, 1]: 0 is [`Parameterization::Uniform`], 1/2
    /// [`Parameterization::Centripetal`], 1 [`Parameterization::Chord`], anything between
    /// [`Parameterization::Alpha`].
    ///
    /// # Errors
    /// [`InterpError::AlphaOutOfRange`] for α outside `[0, 1]` or not a number.
    pub fn from_alpha(alpha: f64) -> Result<Self> {
        if !(0.0..=1.0).contains(&alpha) {
            return Err(Error::Interp(InterpError::AlphaOutOfRange { value: alpha }));
        }
        Ok(if alpha == 0.0 {
            Parameterization::Uniform
        } else if alpha == 0.5 {
            Parameterization::Centripetal
        } else if alpha == 1.0 {
            Parameterization::Chord
        } else {
            Parameterization::Alpha(alpha)
        })
    }

    /// The exponent α of the steps `|ΔP|^α`.
    pub fn alpha(self) -> f64 {
        match self {
            Parameterization::Uniform => 0.0,
            Parameterization::Chord => 1.0,
            Parameterization::Centripetal => 0.5,
            Parameterization::Alpha(a) => a,
        }
    }

    /// The step between `a` and `b` (`None` for a zero chord, which chord and centripetal
    /// spacing cannot use).
    pub(crate) fn step<P: Point>(self, a: P, b: P) -> Option<f64> {
        let d = (b - a).norm();
        match self {
            Parameterization::Uniform => Some(1.0),
            _ if d == 0.0 => None,
            Parameterization::Chord => Some(d),
            Parameterization::Centripetal => Some(d.sqrt()),
            Parameterization::Alpha(a) => Some(d.powf(a)),
        }
    }
}

/// The kind of knot vector [`knot_vector`] builds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KnotKind {
    /// Unclamped uniform: `u_i = i`.
    Uniform,
    /// Clamped (open) uniform: `p + 1` zeros, `1 … n − p`, `p + 1` copies of `n − p + 1`.
    Clamped,
    /// Clamped, interior knots at the cumulative lengths of the control polygon's legs.
    Chord,
    /// Clamped, interior knots at the cumulative square roots of the legs' lengths.
    Centripetal,
}

impl KnotKind {
    /// Parses `"uniform" | "clamped" | "chord" | "centripetal"`.
    pub fn parse(s: &str) -> Result<Self> {
        match s {
            "uniform" => Ok(KnotKind::Uniform),
            "clamped" => Ok(KnotKind::Clamped),
            "chord" => Ok(KnotKind::Chord),
            "centripetal" => Ok(KnotKind::Centripetal),
            _ => Err(Error::UnknownOption {
                name: "kind",
                value: s.into(),
                expected: "\"uniform\", \"clamped\", \"chord\", \"centripetal\"",
            }),
        }
    }
}

/// Cumulative parameters for the points, starting at 0: uniform `0, 1, 2, …`; chord: sums of
/// `|P_{i+1} − P_i|`; centripetal: sums of their square roots; in general sums of
/// `|P_{i+1} − P_i|^α`.
///
/// # Errors
/// [`Error::TooFewPoints`] for fewer than 2 points; [`Error::CoincidentPoints`] naming the pair of
/// repeated consecutive points for chord and centripetal spacing.
pub fn parameterize<P: Point>(points: &[P], kind: Parameterization) -> Result<Vec<f64>> {
    if points.len() < 2 {
        return Err(Error::TooFewPoints {
            needed: 2,
            got: points.len(),
            what: "parametrisation",
        });
    }
    let mut out = Vec::with_capacity(points.len());
    out.push(0.0);
    for i in 0..points.len() - 1 {
        let step = kind
            .step(points[i], points[i + 1])
            .ok_or(Error::CoincidentPoints { index: i, kind })?;
        out.push(out[i] + step);
    }
    Ok(out)
}

/// A knot vector for `n + 1` control points of degree `p` (the Greek notes' formulas with one
/// more knot at each end): "uniform" `u_i = i`, `i = 0..=n+p+1`; "clamped" `p + 1` zeros,
/// `1, …, n − p`, `p + 1` copies of `n − p + 1`; "chord"/"centripetal" clamped, with interior
/// knot `j` (`j = 1..=n−p`) at the cumulative length (or square-root length) of the first `j`
/// legs of the control polygon and end knots at the total over the first `n − p + 1` legs.
///
/// # Errors
/// [`Error::DegreeZero`] or [`Error::TooFewPointsForDegree`], and as [`parameterize`].
pub fn knot_vector<P: Point>(points: &[P], degree: usize, kind: KnotKind) -> Result<Vec<f64>> {
    super::check_degree(degree, points.len())?;
    let (n, p) = (points.len() - 1, degree);
    let clamped = |interior: &[f64], end: f64| {
        let mut k = vec![0.0; p + 1];
        k.extend_from_slice(interior);
        k.extend(std::iter::repeat_n(end, p + 1));
        k
    };
    Ok(match kind {
        KnotKind::Uniform => (0..=n + p + 1).map(|i| i as f64).collect(),
        KnotKind::Clamped => {
            let interior: Vec<f64> = (1..=n - p).map(|j| j as f64).collect();
            clamped(&interior, (n - p + 1) as f64)
        }
        KnotKind::Chord | KnotKind::Centripetal => {
            let spacing = if kind == KnotKind::Chord {
                Parameterization::Chord
            } else {
                Parameterization::Centripetal
            };
            let sums = parameterize(&points[..=n - p + 1], spacing)?;
            clamped(&sums[1..=n - p], sums[n - p + 1])
        }
    })
}

/// Phantom (ghost) end points for an unclamped uniform B-spline of odd degree `p`: the
/// `(p − 1)/2` points `P_{−j} = 2P_0 − P_j` before the first point and `2P_n − P_{n−j}` after the
/// last, so that (by the symmetry of the uniform basis at a knot) the curve starts at `P_0`
/// and ends at `P_n`. For a cubic: one point each, collinear with `P_0 P_1` (the Croatian notes).
///
/// # Errors
/// [`Error::PhantomEvenDegree`] for an even degree (no symmetric choice exists) or too few points.
pub fn phantom_points<P: Point>(points: &[P], degree: usize) -> Result<Vec<P>> {
    if degree.is_multiple_of(2) {
        return Err(Error::PhantomEvenDegree { degree });
    }
    let extra = (degree - 1) / 2;
    if points.len() < extra + 2 {
        return Err(Error::TooFewPoints {
            needed: extra + 2,
            got: points.len(),
            what: "phantom-points",
        });
    }
    let n = points.len() - 1;
    let mut out = Vec::with_capacity(points.len() + 2 * extra);
    out.extend((1..=extra).rev().map(|j| points[0] * 2.0 - points[j]));
    out.extend_from_slice(points);
    out.extend((1..=extra).map(|j| points[n] * 2.0 - points[n - j]));
    Ok(out)
}
