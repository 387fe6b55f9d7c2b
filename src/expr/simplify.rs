//! Light simplification of an expression tree, so a derivative reads as a textbook writes it:
//! x(t) = cos t gives x′(t) = −sin t, not −1·sin(t)·1.
//!
//! The rules, applied bottom-up (each constructor assumes its operands are already simple):
//! - numbers fold under + − × ÷ and integer powers, exactly when both have exact values
//!   (5 · 6.5 = 32.5 = 65/2), in f64 otherwise (a fold that would give ±∞ or NaN is not done);
//!   a negative result is written −(number), as the parser writes a typed one;
//! - 0 + a → a, a − 0 → a, 0 − a → −a, a + (−b) → a − b, a − (−b) → a + b, −(−a) → a;
//! - a product's numeric factors (and signs) are collected into one coefficient in front:
//!   2·(3·t) → 6t, (−a)·b → −(a·b), 0·a → 0, 1·a → a;
//! - a / 1 → a, 0 / a → 0, (−a)/b → −(a/b), a/(−b) → −(a/b);
//! - a^1 → a, a^0 → 1 (0^0 = 1, the language's convention).
//!
//! Constants (π, e), parameters and functions of numbers are not folded: ln 2 stays ln 2.

use super::ast::{boxed, BinOp, Expr, Func, Node};
use super::rational::Rational;

/// How deep the recursions over a tree in the symbolic family (simplification, derivative,
/// TeX, polynomial detection) go before giving up (derivative and polynomial: `None`; TeX:
/// `\cdots` below it; simplification: the sub-tree as it is). A sum or product chain adds one
/// level per term, so this is a sum of ~100 terms, beyond what a student types, while the
/// stack stays well inside wasm's 1 MB even in a debug build (a depth-100 derivative, its
/// TeX and the second derivative ran in a 400 KB native debug stack; ~2 KB per level).
pub(crate) const MAX_DEPTH: usize = 100;

/// How far the product rules look into a product (deeper factors are treated as opaque).
const MAX_SPLIT_DEPTH: usize = 64;

/// A number node's value: the f64 and, when known, the exact fraction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Num {
    /// The nearest f64 (the exact value rounded, when there is one).
    pub value: f64,
    /// The exact value.
    pub exact: Option<Rational>,
}

impl Num {
    /// The exact number `r`.
    pub fn rational(r: Rational) -> Num {
        Num {
            value: r.to_f64(),
            exact: Some(r),
        }
    }

    /// The integer `n`, exactly.
    pub fn integer(n: i128) -> Num {
        Num::rational(Rational::integer(n))
    }

    /// The value of a number node or of the negation of one.
    pub fn of(e: &Expr) -> Option<Num> {
        match &e.node {
            Node::Number { value, exact } => Some(Num {
                value: *value,
                exact: exact.as_deref().copied(),
            }),
            Node::Neg(a) => match &a.node {
                Node::Number { .. } => Num::of(a)?.neg(),
                _ => None,
            },
            _ => None,
        }
    }

    /// Whether it is 0.
    pub fn is_zero(self) -> bool {
        match self.exact {
            Some(r) => r.is_zero(),
            None => self.value == 0.0,
        }
    }

    /// Whether it is 1.
    pub fn is_one(self) -> bool {
        match self.exact {
            Some(r) => r == Rational::ONE,
            None => self.value == 1.0,
        }
    }

    /// Whether it is below 0.
    pub fn is_negative(self) -> bool {
        match self.exact {
            Some(r) => r < Rational::ZERO,
            None => self.value < 0.0,
        }
    }

    /// `op` on two numbers: exact when both are and `exact` succeeds, else in f64; `None`
    /// when the f64 result is not finite (1/0, overflow).
    fn combine(
        self,
        other: Num,
        float: fn(f64, f64) -> f64,
        exact: fn(Rational, Rational) -> Option<Rational>,
    ) -> Option<Num> {
        if let (Some(a), Some(b)) = (self.exact, other.exact) {
            if let Some(r) = exact(a, b) {
                return Some(Num::rational(r));
            }
        }
        let value = float(self.value, other.value);
        value.is_finite().then_some(Num { value, exact: None })
    }

    /// `self + other`.
    pub fn add(self, other: Num) -> Option<Num> {
        self.combine(other, |a, b| a + b, Rational::checked_add)
    }

    /// `self − other`.
    pub fn sub(self, other: Num) -> Option<Num> {
        self.combine(other, |a, b| a - b, Rational::checked_sub)
    }

    /// `self · other`.
    pub fn mul(self, other: Num) -> Option<Num> {
        self.combine(other, |a, b| a * b, Rational::checked_mul)
    }

    /// `self / other` (`None` for a zero divisor).
    pub fn div(self, other: Num) -> Option<Num> {
        if other.is_zero() {
            return None;
        }
        self.combine(other, |a, b| a / b, Rational::checked_div)
    }

    /// `−self`.
    pub fn neg(self) -> Option<Num> {
        Num::integer(0).sub(self)
    }

    /// `|self|`.
    fn abs(self) -> Num {
        if self.is_negative() {
            self.neg().unwrap_or(self)
        } else {
            self
        }
    }

    /// The tree: a number node, under a [`Node::Neg`] when negative.
    pub fn expr(self) -> Expr {
        let magnitude = self.abs();
        let number = Expr::number(magnitude.value, magnitude.exact);
        if self.is_negative() {
            Expr::new(Node::Neg(boxed(number)), Default::default())
        } else {
            number
        }
    }
}

fn node(node: Node) -> Expr {
    Expr::new(node, Default::default())
}

#[inline(never)] // the tree builders stay out of line (wasm size)
fn binary(op: BinOp, a: Expr, b: Expr) -> Expr {
    node(Node::Binary(op, boxed(a), boxed(b)))
}

/// a + b, simplified.
pub(crate) fn add(a: Expr, b: Expr) -> Expr {
    let (x, y) = (Num::of(&a), Num::of(&b));
    if let Some(r) = x.zip(y).and_then(|(x, y)| x.add(y)) {
        return r.expr();
    }
    if x.is_some_and(Num::is_zero) {
        return b;
    }
    if y.is_some_and(Num::is_zero) {
        return a;
    }
    match b.node {
        Node::Neg(inner) => sub(a, *inner),
        other => binary(BinOp::Add, a, node(other)),
    }
}

/// a − b, simplified.
pub(crate) fn sub(a: Expr, b: Expr) -> Expr {
    let (x, y) = (Num::of(&a), Num::of(&b));
    if let Some(r) = x.zip(y).and_then(|(x, y)| x.sub(y)) {
        return r.expr();
    }
    if y.is_some_and(Num::is_zero) {
        return a;
    }
    if x.is_some_and(Num::is_zero) {
        return neg(b);
    }
    match b.node {
        Node::Neg(inner) => add(a, *inner),
        other => binary(BinOp::Sub, a, node(other)),
    }
}

/// −a, simplified.
pub(crate) fn neg(a: Expr) -> Expr {
    if let Some(r) = Num::of(&a).and_then(Num::neg) {
        return r.expr();
    }
    match a.node {
        Node::Neg(inner) => *inner,
        other => node(Node::Neg(boxed(node(other)))),
    }
}

/// A product split into its numeric coefficient and the rest (`None`: no rest), looking
/// through products and negations: 2·(−(3·t)) → (−6, t).
fn split(e: Expr, depth: usize) -> Option<(Num, Option<Expr>)> {
    if let Some(n) = Num::of(&e) {
        return Some((n, None));
    }
    if depth > MAX_SPLIT_DEPTH {
        return Some((Num::integer(1), Some(e)));
    }
    match e.node {
        Node::Neg(a) => {
            let (c, rest) = split(*a, depth + 1)?;
            Some((c.neg()?, rest))
        }
        Node::Binary(BinOp::Mul, a, b) => {
            let (ca, ra) = split(*a, depth + 1)?;
            let (cb, rb) = split(*b, depth + 1)?;
            let rest = match (ra, rb) {
                (Some(x), Some(y)) => Some(binary(BinOp::Mul, x, y)),
                (x, y) => x.or(y),
            };
            Some((ca.mul(cb)?, rest))
        }
        other => Some((Num::integer(1), Some(node(other)))),
    }
}

/// `c · e` with `c` (positive, not 1) placed as the leftmost factor of the product `e`, so
/// 3 · (t · cos t) reads 3t cos t: Mul(Mul(3, t), cos t).
fn attach(c: Num, e: Expr, depth: usize) -> Expr {
    match e.node {
        Node::Binary(BinOp::Mul, a, b) if depth <= MAX_SPLIT_DEPTH => {
            binary(BinOp::Mul, attach(c, *a, depth + 1), *b)
        }
        other => binary(BinOp::Mul, c.expr(), node(other)),
    }
}

/// a · b, simplified: the numeric factors and signs collected into one coefficient in front.
pub(crate) fn mul(a: Expr, b: Expr) -> Expr {
    let Some(((ca, ra), (cb, rb))) = split(a.clone(), 0).zip(split(b.clone(), 0)) else {
        return binary(BinOp::Mul, a, b);
    };
    let Some(c) = ca.mul(cb) else {
        return binary(BinOp::Mul, a, b);
    };
    let rest = match (ra, rb) {
        (Some(x), Some(y)) => binary(BinOp::Mul, x, y),
        (Some(x), None) | (None, Some(x)) => x,
        (None, None) => return c.expr(),
    };
    if c.is_zero() {
        return Num::integer(0).expr();
    }
    let magnitude = c.abs();
    let product = if magnitude.is_one() {
        rest
    } else {
        attach(magnitude, rest, 0)
    };
    if c.is_negative() {
        node(Node::Neg(boxed(product)))
    } else {
        product
    }
}

/// a / b, simplified.
pub(crate) fn div(a: Expr, b: Expr) -> Expr {
    let (x, y) = (Num::of(&a), Num::of(&b));
    if let Some(r) = x.zip(y).and_then(|(x, y)| x.div(y)) {
        return r.expr();
    }
    if y.is_some_and(Num::is_one) {
        return a;
    }
    if x.is_some_and(Num::is_zero) && !y.is_some_and(Num::is_zero) {
        return a;
    }
    match (a.node, b.node) {
        (Node::Neg(p), q) => neg(div(*p, node(q))),
        (p, Node::Neg(q)) => neg(div(node(p), *q)),
        (p, q) => binary(BinOp::Div, node(p), node(q)),
    }
}

/// Largest exponent folded exactly for a number base (2^64 still fits the exact type).
const MAX_FOLDED_EXPONENT: i128 = 64;

/// a ^ b, simplified.
pub(crate) fn pow(a: Expr, b: Expr) -> Expr {
    if let Some(y) = Num::of(&b) {
        if y.is_one() {
            return a;
        }
        if y.is_zero() {
            return Num::integer(1).expr();
        }
        let base = Num::of(&a).and_then(|x| x.exact);
        let exponent = y.exact.filter(|k| k.is_integer());
        if let (Some(x), Some(k)) = (base, exponent) {
            if k.numer().abs() <= MAX_FOLDED_EXPONENT {
                if let Some(r) = x.pow(k.numer() as i32) {
                    return Num::rational(r).expr();
                }
            }
        }
    }
    binary(BinOp::Pow, a, b)
}

/// f(a) (functions are not folded).
#[inline(never)]
pub(crate) fn call(f: Func, a: Expr) -> Expr {
    node(Node::Call(f, boxed(a)))
}

/// The tree simplified by the rules above, bottom-up; sub-trees deeper than the recursion cap
/// are kept as they are. Spans are dropped where a node is rebuilt.
pub fn simplify(expr: Expr) -> Expr {
    simplify_at(expr, 0)
}

fn simplify_at(expr: Expr, depth: usize) -> Expr {
    if depth > MAX_DEPTH {
        return expr;
    }
    let d = depth + 1;
    match expr.node {
        Node::Neg(a) => neg(simplify_at(*a, d)),
        Node::Call(f, a) => call(f, simplify_at(*a, d)),
        Node::Binary(op, a, b) => {
            let (a, b) = (simplify_at(*a, d), simplify_at(*b, d));
            match op {
                BinOp::Add => add(a, b),
                BinOp::Sub => sub(a, b),
                BinOp::Mul => mul(a, b),
                BinOp::Div => div(a, b),
                BinOp::Pow => pow(a, b),
            }
        }
        Node::Number { .. } | Node::T | Node::Param(_) | Node::Constant(_) => expr,
    }
}

#[cfg(test)]
mod tests {
    use super::super::diff::build as b;
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    fn r(num: i128, den: i128) -> Rational {
        Rational::new(num, den).unwrap()
    }

    #[test]
    fn numbers_fold_exactly() {
        // 5 · 6.5 = 65/2, and its f64 is the rounded fraction.
        let e = simplify(b::mul(b::n(5.0), b::n(6.5)));
        assert_eq!(e, Expr::number(32.5, Some(r(65, 2))));
        // 7.2 · 3 = 108/5: the f64 is 21.6 (7.2 * 3.0 in f64 is 21.599999999999998).
        let e = simplify(b::mul(b::n(7.2), b::n(3.0)));
        assert_eq!(e, Expr::number(21.6, Some(r(108, 5))));
        // 1/3 stays a fraction; 2 − 5 is −(3).
        assert_eq!(simplify(b::div(b::n(1.0), b::n(3.0))), b::q(1, 3));
        assert_eq!(simplify(b::sub(b::n(2.0), b::n(5.0))), b::ng(b::n(3.0)));
        assert_eq!(simplify(b::pow(b::n(2.0), b::ng(b::n(2.0)))), b::q(1, 4));
        // An inexact number folds in f64, and the result is inexact.
        assert_eq!(
            simplify(b::add(b::inexact(0.5), b::n(1.0))),
            Expr::number(1.5, None)
        );
        // 1/0 is not folded.
        let e = b::div(b::n(1.0), b::n(0.0));
        assert_eq!(simplify(e.clone()), e);
    }

    #[test]
    fn identities_drop_out() {
        let t = b::t;
        assert_eq!(simplify(b::add(b::n(0.0), t())), t());
        assert_eq!(simplify(b::sub(t(), b::n(0.0))), t());
        assert_eq!(simplify(b::sub(b::n(0.0), t())), b::ng(t()));
        assert_eq!(simplify(b::mul(b::n(1.0), t())), t());
        assert_eq!(simplify(b::mul(t(), b::n(0.0))), b::n(0.0));
        assert_eq!(simplify(b::pow(t(), b::n(1.0))), t());
        assert_eq!(simplify(b::pow(t(), b::n(0.0))), b::n(1.0));
        assert_eq!(simplify(b::div(t(), b::n(1.0))), t());
        assert_eq!(simplify(b::ng(b::ng(t()))), t());
        assert_eq!(simplify(b::add(t(), b::ng(b::p(0)))), b::sub(t(), b::p(0)));
        assert_eq!(simplify(b::sub(t(), b::ng(b::p(0)))), b::add(t(), b::p(0)));
    }

    #[test]
    fn numeric_factors_go_to_the_front() {
        let t = b::t;
        // 2·(3·t) → 6t
        let e = simplify(b::mul(b::n(2.0), b::mul(b::n(3.0), t())));
        assert_eq!(e, b::mul(b::n(6.0), t()));
        // (t·cos t)·3 → 3·t·cos t, the 3 leftmost
        let cos = b::call(Func::Cos, t());
        let e = simplify(b::mul(b::mul(t(), cos.clone()), b::n(3.0)));
        assert_eq!(e, b::mul(b::mul(b::n(3.0), t()), cos));
        // (−a)·b → −(a·b); a·(−2) → −(2a)
        let e = simplify(b::mul(b::ng(b::p(0)), t()));
        assert_eq!(e, b::ng(b::mul(b::p(0), t())));
        let e = simplify(b::mul(b::p(0), b::ng(b::n(2.0))));
        assert_eq!(e, b::ng(b::mul(b::n(2.0), b::p(0))));
        // (−2)·(−t) → 2t
        let e = simplify(b::mul(b::ng(b::n(2.0)), b::ng(t())));
        assert_eq!(e, b::mul(b::n(2.0), t()));
        // π is not a number to fold: 2·π·3 → 6π
        let e = simplify(b::mul(b::mul(b::n(2.0), b::pi()), b::n(3.0)));
        assert_eq!(e, b::mul(b::n(6.0), b::pi()));
    }

    #[test]
    fn quotients_take_the_sign_out() {
        let t = b::t;
        let e = simplify(b::div(b::ng(t()), b::p(0)));
        assert_eq!(e, b::ng(b::div(t(), b::p(0))));
        let e = simplify(b::div(t(), b::ng(b::p(0))));
        assert_eq!(e, b::ng(b::div(t(), b::p(0))));
        assert_eq!(simplify(b::div(b::n(0.0), t())), b::n(0.0));
    }

    #[test]
    fn functions_of_numbers_are_kept() {
        let e = b::call(Func::Ln, b::n(2.0));
        assert_eq!(simplify(e.clone()), e);
        let e = b::pow(b::n(2.0), b::n(0.5));
        assert_eq!(simplify(e.clone()), e);
    }

    #[test]
    fn a_long_chain_does_not_overflow_the_stack() {
        let mut e = b::t();
        for _ in 0..999 {
            e = b::add(e, b::t());
        }
        let s = simplify(e.clone());
        assert_eq!(s.count(), e.count());
        // a long product: the coefficient still goes in front within the split depth
        let mut e = b::t();
        for _ in 0..50 {
            e = b::mul(e, b::t());
        }
        let s = simplify(b::mul(e.clone(), b::n(2.0)));
        assert_eq!(s.count(), e.count() + 2);
    }
}
