//! The parsed expression: a tree of [`Expr`] nodes, each with the characters it came from.
//!
//! The tree is what every other part of the family reads: the tape compiler (`tape.rs`), the
//! symbolic derivative (`diff.rs`), the TeX echo (`tex.rs`) and the polynomial detector
//! (`poly.rs`). Its depth and size are capped by the parser
//! ([`MAX_NESTING`](super::MAX_NESTING), [`MAX_NODES`](super::MAX_NODES)), so recursion over it
//! is bounded.

use super::rational::Rational;

/// A range of characters in the typed text, in UTF-16 code units (what JavaScript's
/// `String.prototype.slice` counts), `start` inclusive, `end` exclusive.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Span {
    /// First code unit.
    pub start: usize,
    /// One past the last code unit.
    pub end: usize,
}

impl Span {
    /// The span from `start` to `end`.
    pub fn new(start: usize, end: usize) -> Self {
        Span { start, end }
    }

    /// The smallest span covering both.
    pub fn to(self, other: Span) -> Span {
        Span {
            start: self.start.min(other.start),
            end: self.end.max(other.end),
        }
    }
}

/// The named constants.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Constant {
    /// π (`pi` or `π`).
    Pi,
    /// Euler's number e (`e`).
    E,
}

impl Constant {
    /// Its value.
    pub fn value(self) -> f64 {
        match self {
            Constant::Pi => std::f64::consts::PI,
            Constant::E => std::f64::consts::E,
        }
    }
}

/// The functions of one argument, written with parentheses: `sin(t)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Func {
    /// sin
    Sin,
    /// cos
    Cos,
    /// tan
    Tan,
    /// asin (arcsine, values in [−π/2, π/2])
    Asin,
    /// acos (values in [0, π])
    Acos,
    /// atan (values in (−π/2, π/2))
    Atan,
    /// sinh
    Sinh,
    /// cosh
    Cosh,
    /// tanh
    Tanh,
    /// exp
    Exp,
    /// ln: the natural logarithm
    Ln,
    /// log: the logarithm to base 10
    Log,
    /// sqrt
    Sqrt,
    /// abs
    Abs,
    /// floor (right-continuous: jumps up at every integer)
    Floor,
    /// ceil (left-continuous)
    Ceil,
    /// sign: −1, 0 or 1
    Sign,
}

impl Func {
    /// Every function, for lookups and tests.
    pub const ALL: [Func; 17] = [
        Func::Sin,
        Func::Cos,
        Func::Tan,
        Func::Asin,
        Func::Acos,
        Func::Atan,
        Func::Sinh,
        Func::Cosh,
        Func::Tanh,
        Func::Exp,
        Func::Ln,
        Func::Log,
        Func::Sqrt,
        Func::Abs,
        Func::Floor,
        Func::Ceil,
        Func::Sign,
    ];

    /// The name as typed: `"sin"`, `"sqrt"`.
    pub fn name(self) -> &'static str {
        match self {
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Asin => "asin",
            Func::Acos => "acos",
            Func::Atan => "atan",
            Func::Sinh => "sinh",
            Func::Cosh => "cosh",
            Func::Tanh => "tanh",
            Func::Exp => "exp",
            Func::Ln => "ln",
            Func::Log => "log",
            Func::Sqrt => "sqrt",
            Func::Abs => "abs",
            Func::Floor => "floor",
            Func::Ceil => "ceil",
            Func::Sign => "sign",
        }
    }

    /// The function named `name`, if there is one.
    #[inline(never)] // one loop, not unrolled per caller (wasm size)
    pub fn from_name(name: &str) -> Option<Func> {
        let all = Func::ALL
            .get(..super::opaque(Func::ALL.len()))
            .unwrap_or_default();
        all.iter().copied().find(|f| f.name() == name)
    }
}

/// The binary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    /// a + b
    Add,
    /// a − b
    Sub,
    /// a · b (typed `*`, `·`, `×`, or implicit: `2t`, `3(t+1)`, `pi t`)
    Mul,
    /// a / b
    Div,
    /// a ^ b (right-associative; binds tighter than unary minus: `-t^2` = −(t²))
    Pow,
}

/// What a node is.
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    /// A number as typed (`6.5`, `.5`, `2`): its f64 value and its exact value as a fraction
    /// (`6.5` = 13/2; `None` when the digits do not fit the exact type).
    Number {
        /// The nearest f64.
        value: f64,
        /// The exact decimal as a fraction (boxed: a 32-byte fraction inline would more than
        /// double every node, and every tree move in the wasm with it).
        exact: Option<Box<Rational>>,
    },
    /// The curve parameter `t`.
    T,
    /// A named parameter: its index in the curve's parameter list.
    Param(usize),
    /// `pi`, `π` or `e`.
    Constant(Constant),
    /// −a (typed `-` or `−`).
    Neg(Box<Expr>),
    /// a op b.
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// f(a).
    Call(Func, Box<Expr>),
}

/// One node of the tree and the characters it was read from (a whole sub-expression: the span
/// of `3(t+1)` covers all six characters).
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// What it is.
    pub node: Node,
    /// Where it was typed.
    pub span: Span,
}

impl Node {
    /// A number node: `value` and its exact value when there is one.
    pub fn number(value: f64, exact: Option<Rational>) -> Node {
        Node::Number {
            value,
            exact: exact.map(Box::new),
        }
    }
}

/// `Box::new(e)` out of line: one copy of the allocation for every tree builder (the parser,
/// the derivative, the simplifier) instead of one per call site (wasm size).
#[inline(never)]
pub fn boxed(e: Expr) -> Box<Expr> {
    Box::new(e)
}

impl Expr {
    /// A node with its span.
    pub fn new(node: Node, span: Span) -> Self {
        Expr { node, span }
    }

    /// A number node without a place in any text (for trees built by code: derivatives).
    pub fn number(value: f64, exact: Option<Rational>) -> Self {
        Expr::new(Node::number(value, exact), Span::default())
    }

    /// The number of nodes in the tree.
    pub fn count(&self) -> usize {
        1 + match &self.node {
            Node::Number { .. } | Node::T | Node::Param(_) | Node::Constant(_) => 0,
            Node::Neg(a) | Node::Call(_, a) => a.count(),
            Node::Binary(_, a, b) => a.count() + b.count(),
        }
    }
}
