//! Polynomial pieces, exactly: a typed expression that is a polynomial in `t` becomes its
//! coefficients in the power basis, as fractions when every number in it is typed, so the
//! Bézier form of 6.5t⁵ − 7.2t³ + 3t² − 2.1t − 5 on [0, 1] is −5, −271/50, −277/50, −152/25,
//! −194/25, −24/5 exactly (syllabus 1), and a joint between polynomial pieces can be judged in
//! exact arithmetic.
//!
//! Power → Bernstein on [a, b]: substitute t = a + (b − a)s (a Taylor shift by a, then the
//! j-th coefficient times (b − a)^j) to get p(t) = Σ c′_j s^j, then
//! b_i = Σ_{j ≤ i} C(i, j)/C(n, j) · c′_j (the control values of the degree-n Bézier form on
//! [a, b]).

use super::ast::{BinOp, Expr, Node};
use super::rational::Rational;
use super::simplify::MAX_DEPTH;

/// Highest degree recognised as a polynomial: a higher one (t^40) is left to the general
/// evaluator.
pub const MAX_POLY_DEGREE: usize = 32;

/// A polynomial in `t` in the power basis: p(t) = Σ_k c_k t^k, `c_0` first, trailing zero
/// coefficients trimmed (the zero polynomial is `[0]`, so there is always one coefficient).
#[derive(Clone, Debug, PartialEq)]
pub struct Polynomial {
    /// c_0, c_1, …, c_n as f64 (the exact ones rounded, when there are exact ones).
    pub coefficients: Vec<f64>,
    /// The same coefficients as fractions, when every coefficient is built from typed numbers
    /// with + − × ÷ and integer powers (`None` as soon as a parameter, π, e or a function
    /// enters a coefficient, or a fraction would overflow).
    pub exact: Option<Vec<Rational>>,
}

/// Construction: the f64 and exact coefficients side by side, trimmed after each step.
impl Polynomial {
    fn constant(value: f64, exact: Option<Rational>) -> Polynomial {
        Polynomial {
            coefficients: vec![value],
            exact: exact.map(|r| vec![r]),
        }
    }

    /// Trailing zeros dropped (at least one coefficient kept).
    fn trim(mut self) -> Polynomial {
        if let Some(q) = &mut self.exact {
            while q.len() > 1 && q.last().is_some_and(|r| r.is_zero()) {
                q.pop();
            }
            self.coefficients = q.iter().map(|r| r.to_f64()).collect();
        } else {
            while self.coefficients.len() > 1 && self.coefficients.last() == Some(&0.0) {
                self.coefficients.pop();
            }
        }
        self
    }

    /// The constant value, when the polynomial is a constant.
    fn as_constant(&self) -> Option<(f64, Option<Rational>)> {
        let [x] = self.coefficients[..] else {
            return None;
        };
        Some((x, self.exact.as_ref().and_then(|q| q.first().copied())))
    }
}

/// a + b (`sign` 1) or a − b (`sign` −1).
fn plus(a: Polynomial, b: Polynomial, sign: f64) -> Polynomial {
    let (p, q) = (&a.coefficients, &b.coefficients);
    let at = |v: &[f64], i: usize| v.get(i).copied().unwrap_or(0.0);
    let f = (0..p.len().max(q.len())).map(|i| at(p, i) + sign * at(q, i));
    let exact = a.exact.as_ref().zip(b.exact.as_ref()).and_then(|(p, q)| {
        let at = |v: &[Rational], i: usize| v.get(i).copied().unwrap_or(Rational::ZERO);
        let op = |x: Rational, y| match sign > 0.0 {
            true => x.checked_add(y),
            false => x.checked_sub(y),
        };
        (0..p.len().max(q.len()))
            .map(|i| op(at(p, i), at(q, i)))
            .collect()
    });
    Polynomial {
        coefficients: f.collect(),
        exact,
    }
    .trim()
}

fn times(a: &Polynomial, b: &Polynomial) -> Option<Polynomial> {
    if a.degree() + b.degree() > MAX_POLY_DEGREE {
        return None;
    }
    let mut f = vec![0.0; (a.coefficients.len() + b.coefficients.len()).saturating_sub(1)];
    for (i, x) in a.coefficients.iter().enumerate() {
        for (j, y) in b.coefficients.iter().enumerate() {
            f[i + j] += x * y;
        }
    }
    let q = a.exact.as_ref().zip(b.exact.as_ref()).and_then(|(qa, qb)| {
        let mut q = vec![Rational::ZERO; (qa.len() + qb.len()).saturating_sub(1)];
        for (i, x) in qa.iter().enumerate() {
            for (j, y) in qb.iter().enumerate() {
                q[i + j] = q[i + j].checked_add(x.checked_mul(*y)?)?;
            }
        }
        Some(q)
    });
    Some(
        Polynomial {
            coefficients: f,
            exact: q,
        }
        .trim(),
    )
}

fn build(e: &Expr, params: &[f64], depth: usize) -> Option<Polynomial> {
    if depth > MAX_DEPTH {
        return None;
    }
    let depth = depth + 1;
    let w = match &e.node {
        Node::Number { value, exact } => Polynomial::constant(*value, exact.as_deref().copied()),
        Node::T => Polynomial {
            coefficients: vec![0.0, 1.0],
            exact: Some(vec![Rational::ZERO, Rational::ONE]),
        },
        Node::Param(i) => Polynomial::constant(*params.get(*i)?, None),
        Node::Constant(c) => Polynomial::constant(c.value(), None),
        Node::Neg(a) => plus(
            Polynomial::constant(0.0, Some(Rational::ZERO)),
            build(a, params, depth)?,
            -1.0,
        ),
        Node::Call(f, a) => {
            let (x, _) = build(a, params, depth)?.as_constant()?;
            Polynomial::constant(super::math::apply(*f, x), None)
        }
        Node::Binary(op, a, b) => {
            let (a, b) = (build(a, params, depth)?, build(b, params, depth)?);
            match op {
                BinOp::Add => plus(a, b, 1.0),
                BinOp::Sub => plus(a, b, -1.0),
                BinOp::Mul => times(&a, &b)?,
                BinOp::Div => {
                    let (y, exact) = b.as_constant()?;
                    if y == 0.0 {
                        return None;
                    }
                    // Loops, not `collect::<Option<_>>()`: smaller in the wasm.
                    let q = a.exact.as_ref().zip(exact).and_then(|(q, r)| {
                        let mut out = Vec::with_capacity(q.len());
                        for x in q {
                            out.push(x.checked_div(r)?);
                        }
                        Some(out)
                    });
                    Polynomial {
                        coefficients: a.coefficients.iter().map(|x| x / y).collect(),
                        exact: q,
                    }
                    .trim()
                }
                BinOp::Pow => raise(a, b)?,
            }
        }
    };
    w.coefficients.iter().all(|x| x.is_finite()).then_some(w)
}

/// `a^b` with a constant exponent: a whole number ≤ [`MAX_POLY_DEGREE`] for a polynomial
/// base; any value for a constant base (an integer one exactly, else folded in f64).
fn raise(a: Polynomial, b: Polynomial) -> Option<Polynomial> {
    let (y, exact_y) = b.as_constant()?;
    if let Some((x, exact_x)) = a.as_constant() {
        let k = exact_y.filter(|k| k.is_integer() && k.numer().abs() <= 1 << 20);
        let q = exact_x
            .zip(k)
            .and_then(|(x, k)| x.pow(k.numer() as i32))
            .map(|r| vec![r]);
        let value = match &q {
            Some(r) => r[0].to_f64(),
            None => super::math::pow_const(x, y),
        };
        return Some(Polynomial {
            coefficients: vec![value],
            exact: q,
        });
    }
    if !(0.0..=MAX_POLY_DEGREE as f64).contains(&y) || y.fract() != 0.0 {
        return None;
    }
    if exact_y.is_some_and(|k| !k.is_integer()) {
        return None;
    }
    let mut w = Polynomial::constant(1.0, Some(Rational::ONE));
    for _ in 0..y as u32 {
        w = times(&w, &a)?;
    }
    if exact_y.is_none() {
        w.exact = None;
    }
    Some(w.trim())
}

impl Polynomial {
    /// `expr` as a polynomial in `t`, with `params[i]` the value of parameter `i`: `Some` when
    /// it is built from t, numbers, constants and parameters with + − ×, ÷ by a non-zero
    /// constant and ^ by a whole-number constant (the degree staying ≤ [`MAX_POLY_DEGREE`]);
    /// constant sub-expressions are folded (sin(2)·t is a polynomial). `None` otherwise, or
    /// when a coefficient is not finite. `exact` is described on the field.
    pub fn from_expr(expr: &Expr, params: &[f64]) -> Option<Polynomial> {
        Some(build(expr, params, 0)?.trim())
    }

    /// The degree n (the number of coefficients minus one; 0 for the zero polynomial).
    pub fn degree(&self) -> usize {
        self.coefficients.len().saturating_sub(1)
    }

    /// p′(t) = Σ_{k≥1} k c_k t^(k−1) (exact when `self` is and no product overflows).
    pub fn derivative(&self) -> Polynomial {
        let k = |k: usize| Rational::integer(k as i128);
        let exact = self.exact.as_ref().and_then(|q| {
            let mut d = Vec::with_capacity(q.len());
            for (i, c) in q.iter().enumerate().skip(1) {
                d.push(c.checked_mul(k(i))?);
            }
            d.push(Rational::ZERO);
            Some(d)
        });
        let f = self.coefficients.iter().enumerate().skip(1);
        let f = f.map(|(i, c)| i as f64 * c).chain([0.0]).collect();
        Polynomial {
            coefficients: f,
            exact,
        }
        .trim()
    }

    /// p(t) by Horner's rule in f64.
    pub fn evaluate(&self, t: f64) -> f64 {
        self.coefficients
            .iter()
            .rev()
            .fold(0.0, |acc, c| acc * t + c)
    }

    /// p(t) exactly (`None` when the coefficients are not exact or a product overflows).
    pub fn evaluate_exact(&self, t: Rational) -> Option<Rational> {
        self.exact
            .as_ref()?
            .iter()
            .rev()
            .try_fold(Rational::ZERO, |acc, c| acc.checked_mul(t)?.checked_add(*c))
    }
}

/// C(n, k) for k ≤ n as a fraction (`None` on overflow).
fn binomial(n: usize, k: usize) -> Option<Rational> {
    let mut c = Rational::ONE;
    for i in 0..k.min(n - k) {
        c = c
            .checked_mul(Rational::integer((n - i) as i128))?
            .checked_div(Rational::integer(i as i128 + 1))?;
    }
    Some(c)
}

/// The Bézier control values b_0..b_n on [a, b] of p(t) = Σ c_k t^k, exactly: with
/// t = a + (b − a)s, p = Σ c′_j s^j and b_i = Σ_{j≤i} C(i,j)/C(n,j) · c′_j. `None` when a
/// fraction overflows. An empty list gives an empty list.
pub fn bernstein_exact(c: &[Rational], a: Rational, b: Rational) -> Option<Vec<Rational>> {
    let n = c.len().saturating_sub(1);
    let h = b.checked_sub(a)?;
    // Taylor shift: coefficients of p(a + u), then scale u = h s.
    let mut p = c.to_vec();
    for i in 0..n {
        for k in (i..n).rev() {
            p[k] = p[k].checked_add(a.checked_mul(p[k + 1])?)?;
        }
    }
    let mut scale = Rational::ONE;
    for x in p.iter_mut() {
        *x = x.checked_mul(scale)?;
        scale = scale.checked_mul(h)?;
    }
    let mut out = Vec::with_capacity(c.len());
    for i in 0..c.len() {
        let mut acc = Rational::ZERO;
        for (j, pj) in p.iter().enumerate().take(i + 1) {
            let w = binomial(i, j)?.checked_div(binomial(n, j)?)?;
            acc = acc.checked_add(w.checked_mul(*pj)?)?;
        }
        out.push(acc);
    }
    Some(out)
}

/// [`bernstein_exact`] in f64 (the same steps: Taylor shift, scaling, the binomial sums).
pub fn bernstein_f64(c: &[f64], a: f64, b: f64) -> Vec<f64> {
    let n = c.len().saturating_sub(1);
    let h = b - a;
    let mut p = c.to_vec();
    for i in 0..n {
        for k in (i..n).rev() {
            p[k] += a * p[k + 1];
        }
    }
    let mut scale = 1.0;
    for x in p.iter_mut() {
        *x *= scale;
        scale *= h;
    }
    let choose = |n: usize, k: usize| -> f64 {
        (0..k.min(n - k)).fold(1.0, |c, i| c * (n - i) as f64 / (i + 1) as f64)
    };
    (0..c.len())
        .map(|i| (0..=i).map(|j| choose(i, j) / choose(n, j) * p[j]).sum())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::super::diff::build::*;
    use super::*;
    use crate::expr::Func;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    /// Fractions written as text: `"-5 -271/50 3"`.
    fn fr(s: &str) -> Vec<Rational> {
        let int = |x: &str| x.parse::<i128>().unwrap();
        let one = |x: &str| match x.split_once('/') {
            Some((n, d)) => Rational::new(int(n), int(d)).unwrap(),
            None => Rational::integer(int(x)),
        };
        s.split_whitespace().map(one).collect()
    }

    fn poly(e: &Expr) -> Polynomial {
        Polynomial::from_expr(e, &[]).unwrap()
    }

    #[test]
    fn the_notes_polynomial_is_exact() {
        let p = poly(&notes_polynomial());
        let c = fr("-5 -21/10 3 -36/5 0 13/2");
        assert_eq!(p.exact.as_ref(), Some(&c));
        assert_eq!(p.coefficients, vec![-5.0, -2.1, 3.0, -7.2, 0.0, 6.5]);
        assert_eq!(p.degree(), 5);
        // Its Bézier control values on [0, 1] (syllabus 1).
        let expected = fr("-5 -271/50 -277/50 -152/25 -194/25 -24/5");
        let b = bernstein_exact(&c, Rational::ZERO, Rational::ONE);
        assert_eq!(b.as_ref(), Some(&expected));
        for (x, y) in bernstein_f64(&p.coefficients, 0.0, 1.0)
            .iter()
            .zip(expected)
        {
            assert!((x - y.to_f64()).abs() < 1e-14, "{x} vs {y}");
        }
    }

    /// Control values on other intervals, from sympy solving the Bernstein system
    /// (tests/fixtures/make_poly_fixtures.py).
    #[test]
    fn bernstein_forms_agree_with_sympy() {
        let text = include_str!("../../tests/fixtures/poly_sympy.txt");
        let lines: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty()).collect();
        assert_eq!(lines.len(), 6);
        for line in lines {
            let parts: Vec<Vec<Rational>> = line.split('|').map(fr).collect();
            let (c, ab, expected) = (&parts[0], &parts[1], &parts[2]);
            let got = bernstein_exact(c, ab[0], ab[1]);
            assert_eq!(got.as_ref(), Some(expected), "{line}");
            let cf: Vec<f64> = c.iter().map(|x| x.to_f64()).collect();
            let f = bernstein_f64(&cf, ab[0].to_f64(), ab[1].to_f64());
            for (x, y) in f.iter().zip(expected) {
                assert!(
                    (x - y.to_f64()).abs() < 1e-11 * (1.0 + y.to_f64().abs()),
                    "{line}"
                );
            }
        }
    }

    #[test]
    fn products_powers_and_division_by_a_constant() {
        let cases = [
            // t·(t − 1)² = t − 2t² + t³
            (mul(t(), pow(sub(t(), n(1.0)), n(2.0))), "0 1 -2 1"),
            // (t + 1)(t − 1) − t² = −1: trailing zeros trimmed; t − t = [0]
            (
                sub(mul(add(t(), n(1.0)), sub(t(), n(1.0))), pow(t(), n(2.0))),
                "-1",
            ),
            (sub(t(), t()), "0"),
            (ng(pow(t(), n(2.0))), "0 0 -1"),
            (mul(pow(n(2.0), ng(n(1.0))), t()), "0 1/2"),
            // (t² + 1)/3, and 0.1t/0.3 = t/3 exactly (not in f64)
            (div(add(pow(t(), n(2.0)), n(1.0)), n(3.0)), "1/3 0 1/3"),
            (div(mul(n(0.1), t()), n(0.3)), "0 1/3"),
        ];
        for (e, expected) in &cases {
            let p = poly(e);
            let exact = fr(expected);
            let f: Vec<f64> = exact.iter().map(|x| x.to_f64()).collect();
            assert_eq!((p.exact, p.coefficients), (Some(exact), f), "{e:?}");
        }
        // Degree 32 itself is fine: (t + 1)^32 has C(32, 16) in the middle.
        let p = poly(&pow(add(t(), n(1.0)), n(32.0)));
        assert_eq!(p.degree(), 32);
        assert_eq!(p.exact.unwrap()[16], Rational::integer(601_080_390));
    }

    #[test]
    fn parameters_and_constants_make_it_inexact() {
        // a t^2 + π t with a = 1.5: coefficients right in f64, no exact form.
        let e = add(mul(p(0), pow(t(), n(2.0))), mul(pi(), t()));
        let a = Polynomial::from_expr(&e, &[1.5]).unwrap();
        assert_eq!(a.exact, None);
        assert_eq!(a.coefficients, vec![0.0, std::f64::consts::PI, 1.5]);
        assert_eq!(a.evaluate_exact(Rational::ONE), None);
        assert_eq!(a.derivative().coefficients, vec![std::f64::consts::PI, 3.0]);
        // sin(2)·t: a function of a constant folds (in f64).
        let s = poly(&mul(call(Func::Sin, n(2.0)), t()));
        assert_eq!((s.exact, s.coefficients), (None, vec![0.0, 2f64.sin()]));
        // An unknown parameter index is not a polynomial.
        assert_eq!(Polynomial::from_expr(&p(3), &[1.0]), None);
    }

    #[test]
    fn non_polynomials_are_refused() {
        let cases = [
            call(Func::Sin, t()),
            pow(t(), n(0.5)),
            pow(t(), ng(n(1.0))),
            pow(n(2.0), t()),
            pow(t(), n(33.0)),
            mul(pow(t(), n(20.0)), pow(t(), n(20.0))),
            call(Func::Ln, n(0.0)),
            div(n(1.0), t()),
            div(t(), sub(n(2.0), n(2.0))),
        ];
        for e in &cases {
            assert_eq!(Polynomial::from_expr(e, &[]), None, "{e:?}");
        }
    }

    #[test]
    fn a_long_sum_is_recognised_and_a_too_deep_one_refused() {
        // t + t + … + t (60 terms) = 60t
        let mut e = t();
        for _ in 0..59 {
            e = add(e, t());
        }
        assert_eq!(poly(&e).exact, Some(fr("0 60")));
        for _ in 0..MAX_DEPTH {
            e = add(e, t());
        }
        assert_eq!(Polynomial::from_expr(&e, &[]), None);
    }

    #[test]
    fn derivative_and_evaluation() {
        let p = poly(&notes_polynomial());
        // 32.5t^4 − 21.6t^2 + 6t − 2.1
        assert_eq!(p.derivative().exact, Some(fr("-21/10 6 -108/5 0 65/2")));
        // p(1) = 6.5 − 7.2 + 3 − 2.1 − 5 = −24/5 (the last control value);
        // p(1/2) = 13/64 − 9/10 + 3/4 − 21/20 − 5 = −1919/320
        assert_eq!(p.evaluate_exact(Rational::ONE), Some(fr("-24/5")[0]));
        assert_eq!(p.evaluate_exact(fr("1/2")[0]), Some(fr("-1919/320")[0]));
        assert!((p.evaluate(0.5) - (-1919.0 / 320.0)).abs() < 1e-14);
        // A constant's derivative is [0].
        let c = poly(&n(7.0)).derivative();
        assert_eq!((c.coefficients, c.exact), (vec![0.0], Some(fr("0"))));
    }
}
