//! Interpolating curves (syllabus §5): curves through given points `p_0..p_n` at parameters
//! `t_0 < … < t_n`, `C(t_i) = p_i`.
//!
//! Parametrisations (uniform, chord, centripetal, any exponent α), Lagrange's polynomial with
//! Aitken's triangle as teaching data, cubic Hermite pieces with given or automatic tangents
//! (cardinal, Catmull–Rom, Bessel), C2 cubic splines with their end conditions, and global
//! B-spline interpolation and least-squares approximation of any degree. Every interpolant
//! converts to the earlier families (Bézier pieces, a B-spline) so drawing, flattening, arc
//! length and continuity checks reuse them.

mod cubic_eval;
#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
pub(crate) use cubic_eval::{bezier_points, bspline_form};
mod cubic_spline;
mod end_conditions;
mod hermite;
mod lagrange;
mod params;
mod tangents;
mod tridiagonal;

pub use cubic_spline::{CubicSpline, TangentRule};
pub use end_conditions::{spline_system, EndCondition, END_CONDITION_NAMES};
pub use hermite::{hermite_basis, hermite_basis_derivative, hermite_point, hermite_to_bezier};
pub use lagrange::{LagrangeCurve, MAX_LAGRANGE_POINTS};
pub use params::{check_params, check_point_count, ParamChoice};
pub use tangents::{bessel_tangents, cardinal_tangents, catmull_rom_tangents};
pub use tridiagonal::{solve_cyclic, solve_tridiagonal, Tridiagonal};
pub mod banded;
pub mod global;
pub mod least_squares;

pub use global::{
    interpolate_bspline, interpolation_system, InterpolationOptions, InterpolationSystem, RowKind,
    MAX_INTERPOLATION_DEGREE, MAX_INTERPOLATION_POINTS, MAX_SYSTEM_SIZE,
};
pub use least_squares::approximate_bspline;
