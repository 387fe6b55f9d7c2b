//! The errors of interpolation and fitting by parameters: parameter lists, closed data,
//! parametrisation exponents, least-squares control counts, the Schoenberg–Whitney condition
//! ([`super::Error::Interp`]).

use super::message::Num;
use std::fmt;

/// What can go wrong in interpolation or a least-squares fit: the variants of
/// [`super::Error::Interp`].
#[derive(Debug, Clone, PartialEq)]
// In the wasm build the fields become a thrown Error's `params` (camelCase), as `Error`'s do.
#[cfg_attr(
    all(target_arch = "wasm32", target_os = "unknown"),
    derive(serde::Serialize),
    serde(untagged, rename_all_fields = "camelCase")
)]
pub enum InterpError {
    /// Interpolation parameters and data points of different counts:
    /// `interp::lagrange(&three_points, &[0.0, 1.0])`.
    ParamCount {
        /// Number of parameters given.
        params: usize,
        /// Number of data points.
        points: usize,
    },
    /// Interpolation parameters that do not strictly increase (`t_i ≤ t_{i−1}`):
    /// `interp::lagrange(&points, &[0.0, 1.0, 1.0])`.
    ParamsNotIncreasing {
        /// Index `i` of the first parameter not above its predecessor.
        index: usize,
        /// `t_i`.
        value: f64,
        /// `t_{i−1}`.
        previous: f64,
    },
    /// Periodic interpolation needs the last data point equal to the first (as scipy's
    /// `CubicSpline(bc_type="periodic")`).
    NotClosed {
        /// Index of the last point.
        last: usize,
    },
    /// The exponent α of a parametrisation `|Δp|^α` or of Catmull–Rom outside `[0, 1]`.
    AlphaOutOfRange {
        /// The value given.
        value: f64,
    },
    /// A least-squares fit asked for a number of control points outside
    /// `[degree + 1, number of data points]`.
    ControlCountOutOfRange {
        /// The count asked for.
        count: usize,
        /// The smallest count allowed (`p + 1`).
        min: usize,
        /// The largest count allowed (the number of data points).
        max: usize,
    },
    /// Explicit knots that break the Schoenberg–Whitney condition, so the interpolation system
    /// is singular: parameter `t_index` must lie where basis function `N_{index,p}` is non-zero,
    /// `u_index < t_index < u_{index+p+1}` (or equal at a clamped end).
    SchoenbergWhitney {
        /// Index of the parameter (and of the basis function).
        index: usize,
        /// The parameter `t_index`.
        param: f64,
        /// `u_index`.
        lo: f64,
        /// `u_{index+p+1}`.
        hi: f64,
        /// The degree `p`.
        degree: usize,
    },
    /// An operation that only splines of one construction support: `setTangent` on a spline
    /// whose tangents are computed (`cubicSpline`, `catmullRom`, …), or `system()` on one that
    /// solved no system.
    SplineKind {
        /// The operation ("setTangent").
        operation: &'static str,
        /// The construction that supports it ("hermiteSpline").
        needs: &'static str,
        /// The construction of this spline ("cubicSpline").
        got: &'static str,
    },
    /// A least-squares fit whose ends are interpolated needs clamped knots: the first `p + 1`
    /// knots equal to `t_0` and the last `p + 1` equal to `t_m`
    /// (`interp::approximate_bspline` with explicit knots `0 0 1 2 …` for degree 2).
    KnotsNotClamped {
        /// `"first"` or `"last"`.
        end: &'static str,
        /// The end parameter the knots must equal (`t_0` or `t_m`).
        param: f64,
        /// The degree `p`.
        degree: usize,
    },
}

impl InterpError {
    /// The variant's stable kebab-case code ([`super::Error::code`]).
    pub fn code(&self) -> &'static str {
        match self {
            InterpError::ParamCount { .. } => "param-count",
            InterpError::ParamsNotIncreasing { .. } => "params-not-increasing",
            InterpError::NotClosed { .. } => "not-closed",
            InterpError::AlphaOutOfRange { .. } => "alpha-out-of-range",
            InterpError::ControlCountOutOfRange { .. } => "control-count-out-of-range",
            InterpError::SchoenbergWhitney { .. } => "schoenberg-whitney",
            InterpError::SplineKind { .. } => "spline-kind",
            InterpError::KnotsNotClamped { .. } => "knots-not-clamped",
        }
    }
}

impl fmt::Display for InterpError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            InterpError::ParamCount { params, points } => write!(
                f,
                "params must have one value per point ({points}), got {params}"
            ),
            InterpError::ParamsNotIncreasing {
                index,
                value,
                previous,
            } => write!(
                f,
                "params must increase strictly: t_{index} = {} is not above t_{} = {}",
                Num(*value),
                index - 1,
                Num(*previous)
            ),
            InterpError::NotClosed { last } => write!(
                f,
                "periodic interpolation needs the last point (point {last}) equal to the first"
            ),
            InterpError::AlphaOutOfRange { value } => write!(
                f,
                "alpha = {} is outside [0, 1] (0 uniform, 0.5 centripetal, 1 chord)",
                Num(*value)
            ),
            InterpError::ControlCountOutOfRange { count, min, max } => write!(
                f,
                "count = {count} control points is outside [degree + 1, number of points] = [{min}, {max}]"
            ),
            InterpError::SchoenbergWhitney {
                index,
                param,
                lo,
                hi,
                degree,
            } => write!(
                f,
                "the interpolation system is singular: t_{index} = {} must lie inside the support (u_{index}, u_{}) = ({}, {}) of N_{index},{degree} (Schoenberg–Whitney condition)",
                Num(*param),
                index + degree + 1,
                Num(*lo),
                Num(*hi)
            ),
            InterpError::SplineKind {
                operation,
                needs,
                got,
            } => write!(
                f,
                "{operation} works on splines built by {needs}; this one was built by {got}"
            ),
            InterpError::KnotsNotClamped { end, param, degree } => write!(
                f,
                "a least-squares fit with exact ends needs clamped knots: the {end} p+1 = {} knots must equal {}",
                degree + 1,
                Num(*param)
            ),
        }
    }
}
