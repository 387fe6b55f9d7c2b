//! Typed parametric curves (syllabus 1): `P(t) = (x(t), y(t))` or `(x, y, z)` from text, in
//! pieces that join in t.
//!
//! A piece is four or five texts (`x`, `y`, `z?`, `from`, `to`) read by [`crate::expr`]'s
//! parser; piece i is used on `[from_i, to_i)` and the last one on its closed interval, so at a
//! joint the curve takes the right piece's value (as B-splines do). Named parameters are
//! values read at evaluation ([`ParametricCurve::set_parameter`] changes one in place, no
//! re-parse). What the curve offers:
//! - points and derivatives to order [`crate::expr::MAX_JET_ORDER`] by automatic
//!   differentiation (truncated Taylor series: exact to rounding, never finite differences);
//! - a certified plot ([`ParametricCurve::plot`]): interval arithmetic decides where a piece is
//!   defined and continuous, a bound on x″ where the chords are within the tolerance;
//! - joint verdicts ([`ParametricCurve::joints`]): C^k and G^k per joint, proven in exact
//!   arithmetic between polynomial pieces with rational coefficients at a rational joint;
//! - the exact Bézier form of a polynomial piece, the Frenet frame, and the typed formulas and
//!   their symbolic derivatives as TeX.

mod curve;
mod eval;
mod frame;
mod joints;
mod plot;
mod teaching;

pub use curve::{ParametricCurve, PieceSource};
pub use frame::Frame;
pub use joints::Joint;
pub use plot::Plot;
pub use teaching::{BezierForm, CoordinateTex, PieceTex};

/// Most pieces one curve may have.
pub const MAX_PIECES: usize = 64;
