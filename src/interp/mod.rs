//! Interpolating curves (syllabus §5): curves through given points `p_0..p_n` at parameters
//! `t_0 < … < t_n`, `C(t_i) = p_i`.
//!
//! Parametrisations (uniform, chord, centripetal, any exponent α), Lagrange's polynomial with
//! Aitken's triangle as teaching data, cubic Hermite pieces with given or automatic tangents
//! (cardinal, Catmull–Rom, Bessel), C2 cubic splines with their end conditions, and global
//! B-spline interpolation and least-squares approximation of any degree. Every interpolant
//! converts to the earlier families (Bézier pieces, a B-spline) so drawing, flattening, arc
//! length and continuity checks reuse them.

pub mod banded;
pub mod global;
pub mod least_squares;

pub use global::{
    interpolate_bspline, interpolation_system, InterpolationOptions, InterpolationSystem, RowKind,
    MAX_INTERPOLATION_DEGREE, MAX_INTERPOLATION_POINTS, MAX_SYSTEM_SIZE,
};
pub use least_squares::approximate_bspline;
