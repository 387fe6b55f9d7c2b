//! The symbolic derivative with respect to `t`, for teaching: the formula panel shows x′(t) and
//! x″(t) as a textbook writes them. (Numbers come from the jets, not from this tree.)
//!
//! The rules (u, v sub-expressions, u′ their derivatives; a constant is anything whose
//! derivative is 0: numbers, π, e, parameters):
//! - t′ = 1, c′ = 0; (u ± v)′ = u′ ± v′; (−u)′ = −u′;
//! - (uv)′ = u′v + uv′ (c·v: c·v′); (u/v)′ = (u′v − uv′)/v² (u/c: u′/c; c/v: −c·v′/v²);
//! - (u^c)′ = c·u^(c−1)·u′; (c^v)′ = c^v·ln c·v′ (e^v: e^v·v′);
//!   (u^v)′ = u^v·(v′ ln u + v·u′/u);
//! - chain rule f(u)′ = u′·f′(u), written with u′ in front (sin(t²)′ = 2t·cos(t²)):
//!   sin → cos, cos → −sin, tan → 1/cos², asin → 1/√(1−u²), acos → −1/√(1−u²),
//!   atan → 1/(1+u²), sinh → cosh, cosh → sinh, tanh → 1/cosh², exp → exp, ln → 1/u,
//!   log → 1/(u ln 10), sqrt → 1/(2√u), abs → sign(u), and floor, ceil, sign → 0 (their
//!   derivative wherever they are differentiable).
//!
//! Every node is built through the constructors of [`mod@super::simplify`], so the result is
//! already light-simplified. Copies of the input's sub-expressions keep their spans; new nodes have
//! [`Span::default`](super::Span).

use super::ast::{BinOp, Expr, Func, Node};
use super::simplify::{self as s, Num, MAX_DEPTH};
use super::MAX_NODES;

/// Most nodes in a derivative tree: a larger one is not shown (`None`).
pub const MAX_DERIVATIVE_NODES: usize = 4 * MAX_NODES;

/// The derivative of `expr` with respect to `t`, light-simplified (x(t) = cos t gives −sin t;
/// the rules are in the module documentation); `None` when it would have more than
/// [`MAX_DERIVATIVE_NODES`] nodes or the tree is deeper than the recursion cap.
pub fn derivative(expr: &Expr) -> Option<Expr> {
    d(expr, 0)
}

/// The number of nodes of `e`, counting stops once past `limit` (no recursion).
fn size_within(e: &Expr, limit: usize) -> bool {
    let mut stack = vec![e];
    let mut count = 0usize;
    while let Some(x) = stack.pop() {
        count += 1;
        if count > limit {
            return false;
        }
        match &x.node {
            Node::Neg(a) | Node::Call(_, a) => stack.push(a),
            Node::Binary(_, a, b) => {
                stack.push(a);
                stack.push(b);
            }
            Node::Number { .. } | Node::T | Node::Param(_) | Node::Constant(_) => {}
        }
    }
    true
}

#[inline(never)]
fn capped(e: Expr) -> Option<Expr> {
    size_within(&e, MAX_DERIVATIVE_NODES).then_some(e)
}

fn is_zero(e: &Expr) -> bool {
    Num::of(e).is_some_and(Num::is_zero)
}

#[inline(never)]
fn int(n: i128) -> Expr {
    Num::integer(n).expr()
}

fn d(e: &Expr, depth: usize) -> Option<Expr> {
    if depth > MAX_DEPTH {
        return None;
    }
    let depth = depth + 1;
    let result = match &e.node {
        Node::Number { .. } | Node::Param(_) | Node::Constant(_) => int(0),
        Node::T => int(1),
        Node::Neg(a) => s::neg(d(a, depth)?),
        Node::Binary(op, a, b) => {
            let da = d(a, depth)?;
            let db = d(b, depth)?;
            binary(*op, a, b, da, db)
        }
        Node::Call(f, a) => chain(*f, a, d(a, depth)?),
    };
    capped(result)
}

/// f(u)′ = u′ · f′(u) from `u′ = du`. (Kept out of [`d`], as is [`binary`], so the
/// recursion's stack frame stays small.)
#[inline(never)]
fn chain(f: Func, u: &Expr, du: Expr) -> Expr {
    if is_zero(&du) {
        int(0)
    } else {
        s::mul(du, outer(f, u))
    }
}

/// The derivative of `a op b` from `a′ = da`, `b′ = db`.
#[inline(never)]
fn binary(op: BinOp, a: &Expr, b: &Expr, da: Expr, db: Expr) -> Expr {
    let (ca, cb) = (is_zero(&da), is_zero(&db));
    let (a, b) = (a.clone(), b.clone());
    match op {
        BinOp::Add => s::add(da, db),
        BinOp::Sub => s::sub(da, db),
        BinOp::Mul => match (ca, cb) {
            (true, _) => s::mul(a, db),
            (_, true) => s::mul(da, b),
            _ => s::add(s::mul(da, b), s::mul(a, db)),
        },
        BinOp::Div => match (ca, cb) {
            (_, true) => s::div(da, b),
            (true, _) => s::neg(s::div(s::mul(a, db), square(b))),
            _ => s::div(s::sub(s::mul(da, b.clone()), s::mul(a, db)), square(b)),
        },
        BinOp::Pow => match (ca, cb) {
            (true, true) => int(0),
            // (u^c)′ = u′ · c · u^(c−1)
            (false, true) => s::mul(da, s::mul(b.clone(), s::pow(a, s::sub(b, int(1))))),
            // (c^v)′ = v′ · c^v · ln c (ln e = 1 is left out)
            (true, false) => {
                let power = s::pow(a.clone(), b);
                let factor = match a.node {
                    Node::Constant(super::Constant::E) => power,
                    _ => s::mul(power, s::call(Func::Ln, a)),
                };
                s::mul(db, factor)
            }
            // (u^v)′ = u^v · (v′ ln u + v u′/u)
            (false, false) => {
                let inner = s::add(
                    s::mul(db, s::call(Func::Ln, a.clone())),
                    s::div(s::mul(b.clone(), da), a.clone()),
                );
                s::mul(s::pow(a, b), inner)
            }
        },
    }
}

#[inline(never)]
fn square(e: Expr) -> Expr {
    s::pow(e, int(2))
}

/// f′(u) for the chain rule f(u)′ = u′ · f′(u).
fn outer(f: Func, u: &Expr) -> Expr {
    let u = u.clone();
    let one_minus_square = || s::sub(int(1), square(u.clone()));
    match f {
        Func::Sin => s::call(Func::Cos, u),
        Func::Cos => s::neg(s::call(Func::Sin, u)),
        Func::Tan => s::div(int(1), square(s::call(Func::Cos, u))),
        Func::Asin => s::div(int(1), s::call(Func::Sqrt, one_minus_square())),
        Func::Acos => s::neg(s::div(int(1), s::call(Func::Sqrt, one_minus_square()))),
        Func::Atan => s::div(int(1), s::add(int(1), square(u))),
        Func::Sinh => s::call(Func::Cosh, u),
        Func::Cosh => s::call(Func::Sinh, u),
        Func::Tanh => s::div(int(1), square(s::call(Func::Cosh, u))),
        Func::Exp => s::call(Func::Exp, u),
        Func::Ln => s::div(int(1), u),
        Func::Log => s::div(int(1), s::mul(u, s::call(Func::Ln, int(10)))),
        Func::Sqrt => s::div(int(1), s::mul(int(2), s::call(Func::Sqrt, u))),
        Func::Abs => s::call(Func::Sign, u),
        Func::Floor | Func::Ceil | Func::Sign => int(0),
    }
}

/// Tree builders for the family's tests (the parser is not needed to write a tree).
#[cfg(test)]
pub(crate) mod build {
    use super::super::ast::{BinOp, Constant, Expr, Func, Node};
    use super::super::rational::Rational;

    fn node(node: Node) -> Expr {
        Expr::new(node, Default::default())
    }
    fn bin(op: BinOp, a: Expr, b: Expr) -> Expr {
        node(Node::Binary(op, Box::new(a), Box::new(b)))
    }

    /// A number as the parser reads it: `n(6.5)` is 6.5 with exact value 13/2 (the shortest
    /// decimal of the f64, so write the literal as typed).
    pub fn n(x: f64) -> Expr {
        let text = format!("{x}");
        let (int, frac) = text.split_once('.').unwrap_or((&text, ""));
        let den = 10i128.pow(frac.len() as u32);
        let num: i128 = format!("{int}{frac}").parse().unwrap();
        Expr::number(x, Rational::new(num, den))
    }
    /// A number with no exact value.
    pub fn inexact(x: f64) -> Expr {
        Expr::number(x, None)
    }
    /// The exact number `num / den` (value rounded).
    pub fn q(num: i128, den: i128) -> Expr {
        let r = Rational::new(num, den).unwrap();
        Expr::number(r.to_f64(), Some(r))
    }
    /// `t`.
    pub fn t() -> Expr {
        node(Node::T)
    }
    /// Parameter `i`.
    pub fn p(i: usize) -> Expr {
        node(Node::Param(i))
    }
    /// π.
    pub fn pi() -> Expr {
        node(Node::Constant(Constant::Pi))
    }
    /// e.
    pub fn e() -> Expr {
        node(Node::Constant(Constant::E))
    }
    /// −a.
    pub fn ng(a: Expr) -> Expr {
        node(Node::Neg(Box::new(a)))
    }
    /// a + b.
    pub fn add(a: Expr, b: Expr) -> Expr {
        bin(BinOp::Add, a, b)
    }
    /// a − b.
    pub fn sub(a: Expr, b: Expr) -> Expr {
        bin(BinOp::Sub, a, b)
    }
    /// a · b.
    pub fn mul(a: Expr, b: Expr) -> Expr {
        bin(BinOp::Mul, a, b)
    }
    /// a / b.
    pub fn div(a: Expr, b: Expr) -> Expr {
        bin(BinOp::Div, a, b)
    }
    /// a ^ b.
    pub fn pow(a: Expr, b: Expr) -> Expr {
        bin(BinOp::Pow, a, b)
    }
    /// f(a).
    pub fn call(f: Func, a: Expr) -> Expr {
        node(Node::Call(f, Box::new(a)))
    }
    /// The notes' polynomial 6.5t^5 − 7.2t^3 + 3t^2 − 2.1t − 5, as the parser reads it.
    pub fn notes_polynomial() -> Expr {
        let a = sub(mul(n(6.5), pow(t(), n(5.0))), mul(n(7.2), pow(t(), n(3.0))));
        let b = add(a, mul(n(3.0), pow(t(), n(2.0))));
        sub(sub(b, mul(n(2.1), t())), n(5.0))
    }
}

#[cfg(test)]
mod tests {
    use super::super::ast::Constant;
    use super::build::*;
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    /// A plain evaluator for the tests (the tape is another file's): t and the parameters.
    fn eval(e: &Expr, t: f64, params: &[f64]) -> f64 {
        match &e.node {
            Node::Number { value, .. } => *value,
            Node::T => t,
            Node::Param(i) => params[*i],
            Node::Constant(Constant::Pi) => std::f64::consts::PI,
            Node::Constant(Constant::E) => std::f64::consts::E,
            Node::Neg(a) => -eval(a, t, params),
            Node::Binary(op, a, b) => {
                let (x, y) = (eval(a, t, params), eval(b, t, params));
                match op {
                    BinOp::Add => x + y,
                    BinOp::Sub => x - y,
                    BinOp::Mul => x * y,
                    BinOp::Div => x / y,
                    BinOp::Pow => crate::expr::math::pow_const(x, y),
                }
            }
            Node::Call(f, a) => {
                let x = eval(a, t, params);
                match f {
                    Func::Sin => x.sin(),
                    Func::Cos => x.cos(),
                    Func::Tan => x.tan(),
                    Func::Asin => x.asin(),
                    Func::Acos => x.acos(),
                    Func::Atan => x.atan(),
                    Func::Sinh => x.sinh(),
                    Func::Cosh => x.cosh(),
                    Func::Tanh => x.tanh(),
                    Func::Exp => x.exp(),
                    Func::Ln => x.ln(),
                    Func::Log => x.log10(),
                    Func::Sqrt => x.sqrt(),
                    Func::Abs => x.abs(),
                    Func::Floor => x.floor(),
                    Func::Ceil => x.ceil(),
                    Func::Sign => {
                        if x == 0.0 {
                            0.0
                        } else {
                            x.signum()
                        }
                    }
                }
            }
        }
    }

    fn dt(e: Expr) -> Expr {
        derivative(&e).unwrap()
    }

    #[test]
    fn textbook_derivatives() {
        // cos t → −sin t
        assert_eq!(dt(call(Func::Cos, t())), ng(call(Func::Sin, t())));
        // the notes' polynomial → 32.5t^4 − 21.6t^2 + 6t − 2.1
        let expected = sub(
            add(
                sub(
                    mul(q(65, 2), pow(t(), n(4.0))),
                    mul(q(108, 5), pow(t(), n(2.0))),
                ),
                mul(n(6.0), t()),
            ),
            q(21, 10),
        );
        assert_eq!(dt(notes_polynomial()), expected);
        // sin(t²) → 2t·cos(t²)
        let t2 = || pow(t(), n(2.0));
        let expected = mul(mul(n(2.0), t()), call(Func::Cos, t2()));
        assert_eq!(dt(call(Func::Sin, t2())), expected);
        // e^t → e^t, exp(t) → exp(t)
        assert_eq!(dt(pow(e(), t())), pow(e(), t()));
        assert_eq!(dt(call(Func::Exp, t())), call(Func::Exp, t()));
        // ln t → 1/t; sqrt t → 1/(2 sqrt t); abs t → sign t
        assert_eq!(dt(call(Func::Ln, t())), div(n(1.0), t()));
        let expected = div(n(1.0), mul(n(2.0), call(Func::Sqrt, t())));
        assert_eq!(dt(call(Func::Sqrt, t())), expected);
        assert_eq!(dt(call(Func::Abs, t())), call(Func::Sign, t()));
        for f in [Func::Floor, Func::Ceil, Func::Sign] {
            assert_eq!(dt(call(f, t())), n(0.0), "{}", f.name());
        }
        // constants and parameters
        assert_eq!(dt(p(0)), n(0.0));
        assert_eq!(dt(mul(n(2.0), pi())), n(0.0));
        assert_eq!(dt(call(Func::Sin, p(1))), n(0.0));
    }

    #[test]
    fn more_exact_trees() {
        // a·t → a; t^a → a·t^(a−1)
        assert_eq!(dt(mul(p(0), t())), p(0));
        assert_eq!(dt(pow(t(), p(0))), mul(p(0), pow(t(), sub(p(0), n(1.0)))));
        // cos(2t) → −2 sin(2t)
        let two_t = || mul(n(2.0), t());
        let expected = ng(mul(n(2.0), call(Func::Sin, two_t())));
        assert_eq!(dt(call(Func::Cos, two_t())), expected);
        // t sin t → sin t + t cos t
        let expected = add(call(Func::Sin, t()), mul(t(), call(Func::Cos, t())));
        assert_eq!(dt(mul(t(), call(Func::Sin, t()))), expected);
        // 2^t → 2^t ln 2
        let expected = mul(pow(n(2.0), t()), call(Func::Ln, n(2.0)));
        assert_eq!(dt(pow(n(2.0), t())), expected);
        // 1/t → −1/t²
        let expected = ng(div(n(1.0), pow(t(), n(2.0))));
        assert_eq!(dt(div(n(1.0), t())), expected);
        // t/3 → 1/3, exactly
        assert_eq!(dt(div(t(), n(3.0))), q(1, 3));
        // second derivative of the notes' polynomial: 130t^3 − 43.2t + 6
        let expected = add(
            sub(mul(n(130.0), pow(t(), n(3.0))), mul(q(216, 5), t())),
            n(6.0),
        );
        assert_eq!(dt(dt(notes_polynomial())), expected);
    }

    /// Every function, nested in sums, products, quotients and powers, against a central
    /// difference (a sanity check only: the exact trees above are the real tests).
    #[test]
    fn derivatives_agree_with_a_central_difference() {
        let u = || add(mul(n(0.3), t()), n(0.2)); // in (0, 1) for t in (0, 2)
        let mut cases: Vec<Expr> = Func::ALL
            .iter()
            .filter(|f| !matches!(f, Func::Floor | Func::Ceil | Func::Sign))
            .map(|&f| mul(call(f, u()), add(t(), p(0))))
            .collect();
        cases.push(div(call(Func::Sin, t()), add(pow(t(), n(2.0)), n(1.0))));
        cases.push(pow(t(), t()));
        cases.push(pow(u(), ng(n(1.5))));
        cases.push(pow(pi(), call(Func::Cos, t())));
        cases.push(sub(div(p(0), t()), ng(call(Func::Abs, sub(t(), n(1.0))))));
        let params = [0.7];
        for e in &cases {
            let de = dt(e.clone());
            for &x in &[0.3, 0.8, 1.45] {
                let h = 1e-6;
                let fd = (eval(e, x + h, &params) - eval(e, x - h, &params)) / (2.0 * h);
                let got = eval(&de, x, &params);
                assert!((got - fd).abs() < 1e-6 * (1.0 + fd.abs()), "{e:?} at {x}");
            }
        }
    }

    #[test]
    fn a_huge_derivative_is_refused() {
        // sin t · sin t · … (100 factors, 201 nodes): the product rule copies the product
        // once per factor, ~10⁴ nodes.
        let mut e = call(Func::Sin, t());
        for _ in 0..99 {
            e = mul(e, call(Func::Sin, t()));
        }
        assert!(derivative(&e).is_none());
        // 30 factors (~10³ nodes) are shown.
        let mut e = call(Func::Sin, t());
        for _ in 0..29 {
            e = mul(e, call(Func::Sin, t()));
        }
        assert!(derivative(&e).is_some());
        // A deep tree is refused instead of overflowing the stack.
        let mut e = t();
        for _ in 0..(MAX_DEPTH + 5) {
            e = ng(e);
        }
        assert!(derivative(&e).is_none());
        // A long chain within the cap is fine.
        let mut e = t();
        for _ in 0..(MAX_DEPTH - 2) {
            e = add(e, mul(n(2.0), t()));
        }
        assert!(derivative(&e).is_some());
    }
}
