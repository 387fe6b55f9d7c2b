//! Typed expressions (syllabus 1): the text a student types for x(t), y(t), z(t), read by our
//! own parser into a tree ([`ast`]), with exact fractions for polynomial pieces ([`rational`])
//! and coded errors that say where and why ([`error`]).
//!
//! The language: numbers with a decimal point (`6.5`, `.5`), `t`, declared parameters (one
//! letter other than `t` and `e`, or a letter with a subscript: `a`, `ω`, `a_1`), `pi` or `π`,
//! `e`; `+ − * / ^` (`^` right-associative and binding tighter than unary minus: `-t^2` is
//! −(t²), `2^3^2` is 512); implicit products (`2t`, `3(t+1)`, `2pi`, `pi t`); the functions
//! sin cos tan asin acos atan sinh cosh tanh exp ln (natural) log (base 10) sqrt abs floor ceil
//! sign, written with parentheses. The README's syntax table lists what is accepted and what
//! is refused with a hint (`sin t`, `1/2t`, `t2`).

pub mod ast;
pub mod certify;
pub mod diff;
pub mod error;
pub mod interval;
pub mod jet;
pub mod lex;
pub mod math;
pub mod parse;
pub mod poly;
pub mod rational;
mod series;
pub mod simplify;
pub mod tape;
pub mod tex;

pub use ast::{BinOp, Constant, Expr, Func, Node, Span};
pub use certify::{Defined, IntervalFlags, IntervalResult};
pub use diff::{derivative, MAX_DERIVATIVE_NODES};
pub use error::{ExprError, Problem};
pub use interval::Interval;
pub use jet::Scalar;
pub use parse::{is_parameter_name, parameter_names, parse};
pub use poly::{bernstein_exact, bernstein_f64, Polynomial, MAX_POLY_DEGREE};
pub use rational::Rational;
pub use simplify::simplify;
pub use tape::{Op, Scratch, Tape};
pub use tex::tex;

/// Longest expression text accepted, in UTF-16 code units.
pub const MAX_LENGTH: usize = 1000;

/// Deepest nesting of parentheses, powers, unary minus and function calls (it bounds every
/// recursion over the tree).
pub const MAX_NESTING: usize = 64;

/// Most nodes (numbers, names, operations) in one expression.
pub const MAX_NODES: usize = 1000;

/// `x` unchanged, hidden from the optimiser: a loop over `0..opaque(n)` in cold code is not
/// unrolled or vectorised (wasm size), where a constant trip count would be.
pub(crate) fn opaque<T>(x: T) -> T {
    std::hint::black_box(x)
}

/// Highest derivative order of the jets (truncated Taylor series).
pub const MAX_JET_ORDER: usize = 8;
