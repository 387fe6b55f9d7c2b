//! The errors of rational constructions: a rational curve's hodograph, projective maps, and the
//! conic arcs (circles from a triangle, ellipses from a center and two axes) — [`super::Error::Conic`].

use super::message::Num;
use std::fmt;

/// What can go wrong in a rational or conic construction: the variants of [`super::Error::Conic`].
#[derive(Debug, Clone, PartialEq)]
// In the wasm build the fields become a thrown Error's `params` (camelCase), as `Error`'s do.
#[cfg_attr(
    all(target_arch = "wasm32", target_os = "unknown"),
    derive(serde::Serialize),
    serde(untagged, rename_all_fields = "camelCase")
)]
pub enum ConicError {
    /// A rational curve has no hodograph of the same form: `rational_curve.hodograph()`.
    RationalHodograph {},
    /// A projective map sends a control point to weight ≤ 0: `projective_map_bezier(&curve, &m)`
    /// with a map whose horizon crosses the control polygon.
    MappedWeight {
        /// The control point's index.
        index: usize,
        /// The weight it is sent to.
        weight: f64,
    },
    /// A singular projective map: `projective_map_bezier(&curve, &DMat3::ZERO)`.
    SingularMap {},
    /// A projective map from JavaScript that is not 9 numbers: `curve.projectiveMap([1, 0, 0])`.
    MatrixSize {
        /// Number of entries given.
        got: usize,
    },
    /// A circular arc from a degenerate triangle:
    /// `circle_arc_from_triangle(p, p, q)` (coincident or collinear points).
    DegenerateTriangle {},
    /// A circular arc from a triangle whose legs differ: `circle_arc_from_triangle(a, b, c)`
    /// with `|P0P1| ≠ |P1P2|`.
    NotIsosceles {
        /// `|P0P1|`.
        first: f64,
        /// `|P1P2|`.
        second: f64,
    },
    /// A circular arc from JavaScript with other than 3 points: `circularArcBezier([0, 0, 1, 1])`.
    ArcPointCount {
        /// Number of points given.
        got: usize,
    },
    /// An ellipse arc with a zero sweep or more than one turn: `ellipse_arc(c, x, y, 0.0, 0.0)`.
    InvalidSweep {
        /// The sweep given (radians).
        sweep: f64,
    },
    /// An ellipse whose axes are parallel or zero: `ellipse_arc(c, x, x, 0.0, 1.0)`.
    ParallelAxes {},
    /// Center and axes of different lengths from JavaScript:
    /// `ellipseArc([0, 0], [1, 0, 0], [0, 1], 0, 1)`.
    AxisLengths {
        /// Length of `center`.
        center: usize,
        /// Length of `axisX`.
        axis_x: usize,
        /// Length of `axisY`.
        axis_y: usize,
    },
}

impl ConicError {
    /// The variant's stable kebab-case code ([`super::Error::code`]).
    pub fn code(&self) -> &'static str {
        match self {
            ConicError::RationalHodograph { .. } => "rational-hodograph",
            ConicError::MappedWeight { .. } => "mapped-weight",
            ConicError::SingularMap { .. } => "singular-map",
            ConicError::MatrixSize { .. } => "matrix-size",
            ConicError::DegenerateTriangle { .. } => "degenerate-triangle",
            ConicError::NotIsosceles { .. } => "not-isosceles",
            ConicError::ArcPointCount { .. } => "arc-point-count",
            ConicError::InvalidSweep { .. } => "invalid-sweep",
            ConicError::ParallelAxes { .. } => "parallel-axes",
            ConicError::AxisLengths { .. } => "axis-lengths",
        }
    }
}

impl fmt::Display for ConicError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ConicError::RationalHodograph {} => f.write_str(
                "the hodograph of a rational curve is not a Bézier curve of degree n − 1; sample derivative(t, 1) instead",
            ),
            ConicError::MappedWeight { index, weight } => write!(
                f,
                "the map sends control point {index} to weight {}; weights must stay > 0 (the point would cross the line at infinity)",
                Num(*weight)
            ),
            ConicError::SingularMap {} => f.write_str("the projective map is singular (determinant 0)"),
            ConicError::MatrixSize { got } => write!(
                f,
                "a projective map is a 3×3 matrix (9 numbers, row by row), got {got}"
            ),
            ConicError::DegenerateTriangle {} => f.write_str(
                "a circular arc needs a proper triangle P0 P1 P2 (no coincident or collinear points)",
            ),
            ConicError::NotIsosceles { first, second } => write!(
                f,
                "a circular arc needs an isosceles triangle: |P0P1| = {} but |P1P2| = {}",
                Num(*first),
                Num(*second)
            ),
            ConicError::ArcPointCount { got } => write!(
                f,
                "a circular arc needs 3 control points (6 numbers), got {got}"
            ),
            ConicError::InvalidSweep { sweep } => write!(
                f,
                "the sweep must be non-zero and at most one full turn (2π), got {}",
                Num(*sweep)
            ),
            ConicError::ParallelAxes {} => {
                f.write_str("the two axes of an ellipse must not be parallel or zero")
            }
            ConicError::AxisLengths {
                center,
                axis_x,
                axis_y,
            } => write!(
                f,
                "center, axisX and axisY need the same length, got {center}, {axis_x}, {axis_y}"
            ),
        }
    }
}
