//! The parsed expression echoed as TeX (for KaTeX), so a student sees what was understood:
//! `6.5t^5-7.2t^3` → `6.5t^{5}-7.2t^{3}`, `sin(t)^2` → `\sin^{2} t`, `1/2t` is refused by the
//! parser but `(1/2)t` → `\frac{1}{2}t`.
//!
//! Conventions:
//! - parentheses only where precedence needs them (+ − below × below unary minus's operand
//!   below ^); a/b is `\frac{a}{b}`, which needs none inside; the right operand of + or − that
//!   starts with a minus sign, and a negative factor after the first or a negative power base,
//!   get `\left(…\right)`;
//! - products juxtapose (`2t`, `6.5t^{5}`, `at`, `2\pi`, `3\left(t+1\right)`, `t\sin t`) except
//!   before a factor starting with a digit (`2\cdot 3`, `t\cdot 2^{t}`), before a fraction
//!   (`2\cdot\frac{1}{t}`) and after a function written without parentheses when another
//!   kind of factor follows (`\sin t\cdot t`; but `\sin t\cos t`);
//! - `\sin t` when the argument is t, a parameter, a constant or a number written as a
//!   decimal, else `\sin\left(2t\right)`; (sin t)² is `\sin^{2} t` (sin cos tan sinh cosh tanh
//!   ln, with a non-negative number as exponent); asin → `\arcsin`, log → `\log_{10}`,
//!   sign → `\operatorname{sign}`, exp(x) → `e^{x}`, sqrt → `\sqrt{…}`, abs → `\left|…\right|`,
//!   floor → `\lfloor … \rfloor`, ceil → `\lceil … \rceil`;
//! - numbers: the exact value as a decimal when it is one (6.5, 32.5, 21.6), else a fraction
//!   (`\frac{1}{3}`); a number without an exact value prints its shortest round-trip digits
//!   (`1.5\cdot 10^{21}` for JavaScript's `1.5e+21`);
//! - names: Greek letters as commands (`\omega`), `a_1` → `a_{1}`, `a_max` → `a_{\mathrm{max}}`.

use super::ast::{BinOp, Constant, Expr, Func, Node};
use super::rational::Rational;
use super::simplify::MAX_DEPTH;

/// `expr` as TeX, `names[i]` the name of parameter `i` (an index without a name prints `?`).
/// A tree deeper than the recursion cap prints `\cdots` for the part below it.
pub fn tex(expr: &Expr, names: &[String]) -> String {
    Tex { names }.render(expr, 0)
}

struct Tex<'a> {
    names: &'a [String],
}

fn paren(s: &str) -> String {
    format!("\\left({s}\\right)")
}

/// Whether the text ends with a control word (`\pi`), so a letter after it needs a space.
fn ends_with_control_word(s: &str) -> bool {
    let letters = s.len() - s.trim_end_matches(|c: char| c.is_ascii_alphabetic()).len();
    letters > 0
        && s.get(..s.len() - letters)
            .is_some_and(|head| head.ends_with('\\'))
}

/// `a` then `b`, with a space when `b` would otherwise extend a control word at the end of `a`.
fn juxtapose(out: &mut String, b: &str) {
    if ends_with_control_word(out) && b.starts_with(|c: char| c.is_ascii_alphabetic()) {
        out.push(' ');
    }
    out.push_str(b);
}

/// The functions written as an operator before a bare argument (`\sin t`), with their TeX.
fn operator(f: Func) -> Option<&'static str> {
    Some(match f {
        Func::Sin => "\\sin",
        Func::Cos => "\\cos",
        Func::Tan => "\\tan",
        Func::Asin => "\\arcsin",
        Func::Acos => "\\arccos",
        Func::Atan => "\\arctan",
        Func::Sinh => "\\sinh",
        Func::Cosh => "\\cosh",
        Func::Tanh => "\\tanh",
        Func::Ln => "\\ln",
        Func::Log => "\\log_{10}",
        Func::Sign => "\\operatorname{sign}",
        Func::Exp | Func::Sqrt | Func::Abs | Func::Floor | Func::Ceil => return None,
    })
}

/// The functions whose power is written `\sin^{2} t`.
fn takes_power_prefix(f: Func) -> bool {
    use Func::*;
    matches!(f, Sin | Cos | Tan | Sinh | Cosh | Tanh | Ln)
}

/// The exact value as a decimal, when its denominator is 2^a·5^b (and the digits fit).
fn decimal(r: Rational) -> Option<String> {
    let (num, den) = (r.numer(), r.denom());
    let (mut rest, mut twos, mut fives) = (den, 0u32, 0u32);
    while rest % 2 == 0 {
        rest /= 2;
        twos += 1;
    }
    while rest % 5 == 0 {
        rest /= 5;
        fives += 1;
    }
    if rest != 1 {
        return None;
    }
    let magnitude = num.checked_abs()?;
    let mut out = String::new();
    if num < 0 {
        out.push('-');
    }
    out.push_str(&(magnitude / den).to_string());
    let mut remainder = magnitude % den;
    if remainder != 0 {
        out.push('.');
    }
    for _ in 0..twos.max(fives) {
        remainder = remainder.checked_mul(10)?;
        out.push(char::from(b'0' + (remainder / den) as u8));
        remainder %= den;
    }
    Some(out)
}

/// A number: decimal, fraction, or shortest round-trip digits.
fn number(value: f64, exact: Option<Rational>) -> String {
    if let Some(r) = exact {
        if let Some(s) = decimal(r) {
            return s;
        }
        if let Some(n) = r.numer().checked_abs() {
            let sign = if r.numer() < 0 { "-" } else { "" };
            return format!("{sign}\\frac{{{n}}}{{{}}}", r.denom());
        }
    }
    if !value.is_finite() {
        return match value {
            v if v > 0.0 => "\\infty".into(),
            v if v < 0.0 => "-\\infty".into(),
            _ => "\\mathrm{NaN}".into(),
        };
    }
    let text = crate::platform::number_text(value);
    match text.split_once('e') {
        Some((mantissa, exponent)) => {
            format!(
                "{mantissa}\\cdot 10^{{{}}}",
                exponent.trim_start_matches('+')
            )
        }
        None => text,
    }
}

/// The Greek letters with a TeX command, and the commands (without the backslash).
const GREEK: &str = "αβγδεζηθικλμνξρσςτυφϕχψωΓΔΘΛΞΣΦΨΩ";
const GREEK_TEX: &str = "alpha beta gamma delta varepsilon zeta eta theta iota kappa lambda mu nu \
    xi rho sigma varsigma tau upsilon varphi phi chi psi omega \
    Gamma Delta Theta Lambda Xi Sigma Phi Psi Omega";

fn greek(c: char) -> Option<String> {
    let i = GREEK.chars().position(|g| g == c)?;
    GREEK_TEX
        .split_whitespace()
        .nth(i)
        .map(|g| format!("\\{g}"))
}

/// A parameter name: `ω` → `\omega`, `a_1` → `a_{1}`, `a_max` → `a_{\mathrm{max}}`. Characters
/// that are neither letters nor digits are dropped (TeX's specials never reach the output).
fn name(s: &str) -> String {
    let (base, subscript) = s.split_once('_').unwrap_or((s, ""));
    let mut out = String::new();
    for c in base.chars() {
        match greek(c) {
            Some(g) => juxtapose(&mut out, &g),
            // Other letters (ο, the Latin-looking capitals) as they are: KaTeX shows them.
            None if c.is_alphanumeric() => juxtapose(&mut out, &c.to_string()),
            None => {}
        }
    }
    let sub: String = subscript
        .chars()
        .filter(char::is_ascii_alphanumeric)
        .collect();
    if sub.chars().count() > 1 && !sub.chars().all(|c| c.is_ascii_digit()) {
        out.push_str(&format!("_{{\\mathrm{{{sub}}}}}"));
    } else if !sub.is_empty() {
        out.push_str(&format!("_{{{sub}}}"));
    }
    if out.is_empty() {
        out.push('?');
    }
    out
}

fn is_sum(e: &Expr) -> bool {
    matches!(e.node, Node::Binary(BinOp::Add | BinOp::Sub, _, _))
}

/// Whether the argument may follow an operator bare: `\sin t`, `\sin 2`, `\sin\omega`.
fn bare_argument(e: &Expr) -> bool {
    match &e.node {
        Node::T | Node::Param(_) | Node::Constant(_) => true,
        Node::Number { value, exact } => {
            *value >= 0.0 && exact.as_deref().is_none_or(|r| decimal(*r).is_some())
        }
        _ => false,
    }
}

/// Whether the text of `e` ends with a function's bare argument (`\sin t`), so a following
/// factor other than another function needs `\cdot`.
fn bare_tail(e: &Expr, depth: usize) -> bool {
    if depth > MAX_DEPTH {
        return false;
    }
    match &e.node {
        Node::Call(f, a) => operator(*f).is_some() && bare_argument(a),
        Node::Binary(BinOp::Pow, base, exponent) => {
            power_prefix(base, exponent).is_some_and(|(_, a)| bare_argument(a))
        }
        Node::Neg(a) => bare_tail(a, depth + 1),
        Node::Binary(BinOp::Mul, _, b) => bare_tail(b, depth + 1),
        _ => false,
    }
}

/// Whether `e` is written starting with a function name (`\cos t`, `\sin^{2} t`).
fn starts_with_operator(e: &Expr) -> bool {
    match &e.node {
        Node::Call(f, _) => operator(*f).is_some(),
        Node::Binary(BinOp::Pow, a, b) => power_prefix(a, b).is_some(),
        _ => false,
    }
}

/// For (f(a))^n written `\sin^{n} a`: the function and its argument.
fn power_prefix<'e>(base: &'e Expr, exponent: &Expr) -> Option<(Func, &'e Expr)> {
    match (&base.node, &exponent.node) {
        (Node::Call(f, a), Node::Number { .. }) if takes_power_prefix(*f) => {
            bare_argument(exponent).then_some((*f, a))
        }
        _ => None,
    }
}

impl Tex<'_> {
    fn render(&self, e: &Expr, depth: usize) -> String {
        if depth > MAX_DEPTH {
            return "\\cdots".into();
        }
        let d = depth + 1;
        match &e.node {
            Node::Number { value, exact } => number(*value, exact.as_deref().copied()),
            Node::T => "t".into(),
            Node::Param(i) => self.names.get(*i).map_or("?".into(), |s| name(s)),
            Node::Constant(Constant::Pi) => "\\pi".into(),
            Node::Constant(Constant::E) => "e".into(),
            Node::Neg(a) => {
                let inner = self.render(a, d);
                if is_sum(a) || inner.starts_with('-') {
                    format!("-{}", paren(&inner))
                } else {
                    format!("-{inner}")
                }
            }
            Node::Binary(op, a, b) => self.binary(*op, a, b, e, d),
            Node::Call(f, a) => self.call(*f, a, None, d),
        }
    }

    fn binary(&self, op: BinOp, a: &Expr, b: &Expr, e: &Expr, d: usize) -> String {
        match op {
            BinOp::Add | BinOp::Sub => {
                let right = self.render(b, d);
                let wrap = right.starts_with('-') || (op == BinOp::Sub && is_sum(b));
                let right = if wrap { paren(&right) } else { right };
                let sign = if op == BinOp::Add { '+' } else { '-' };
                format!("{}{sign}{right}", self.render(a, d))
            }
            BinOp::Mul => self.product(e, d),
            BinOp::Div => format!("\\frac{{{}}}{{{}}}", self.render(a, d), self.render(b, d)),
            BinOp::Pow => {
                let exponent = self.render(b, d);
                if let Some((f, arg)) = power_prefix(a, b) {
                    return self.call(f, arg, Some(&exponent), d);
                }
                let base = self.render(a, d);
                let atomic = match &a.node {
                    Node::T | Node::Param(_) | Node::Constant(_) => true,
                    Node::Number { .. } => bare_argument(a),
                    Node::Call(f, _) => {
                        matches!(f, Func::Sqrt | Func::Abs | Func::Floor | Func::Ceil)
                    }
                    _ => false,
                };
                let base = if atomic { base } else { paren(&base) };
                format!("{base}^{{{exponent}}}")
            }
        }
    }

    /// f(a), or f^{power}(a) for `\sin^{2} t`.
    fn call(&self, f: Func, a: &Expr, power: Option<&str>, d: usize) -> String {
        let arg = self.render(a, d);
        match operator(f) {
            Some(op) => {
                let head = match power {
                    Some(p) => format!("{op}^{{{p}}}"),
                    None => op.to_string(),
                };
                if bare_argument(a) {
                    format!("{head} {arg}")
                } else {
                    format!("{head}{}", paren(&arg))
                }
            }
            None => match f {
                Func::Exp => format!("e^{{{arg}}}"),
                Func::Sqrt => format!("\\sqrt{{{arg}}}"),
                Func::Abs => format!("\\left|{arg}\\right|"),
                Func::Floor => format!("\\lfloor {arg}\\rfloor"),
                _ => format!("\\lceil {arg}\\rceil"),
            },
        }
    }

    /// A product: its factors (both sides flattened, × being associative) joined.
    fn product(&self, e: &Expr, d: usize) -> String {
        let mut factors = Vec::new();
        collect_factors(e, d, &mut factors);
        let mut out = String::new();
        let mut previous: Option<&Expr> = None;
        for (i, f) in factors.iter().enumerate() {
            let mut text = self.render(f, d + 1);
            if is_sum(f) || (i > 0 && text.starts_with('-')) {
                text = paren(&text);
            }
            if let Some(p) = previous {
                let dot = text.starts_with(|c: char| c.is_ascii_digit())
                    || text.starts_with("\\frac")
                    || (bare_tail(p, d) && !starts_with_operator(f));
                if dot {
                    out.push_str("\\cdot");
                    if !text.starts_with('\\') {
                        out.push(' ');
                    }
                }
            }
            juxtapose(&mut out, &text);
            previous = Some(f);
        }
        out
    }
}

/// The factors of a product tree, left to right (depth-capped: a deeper product is one factor).
fn collect_factors<'e>(e: &'e Expr, depth: usize, out: &mut Vec<&'e Expr>) {
    match &e.node {
        Node::Binary(BinOp::Mul, a, b) if depth <= MAX_DEPTH => {
            collect_factors(a, depth + 1, out);
            collect_factors(b, depth + 1, out);
        }
        _ => out.push(e),
    }
}

#[cfg(test)]
mod tests {
    use super::super::diff::build::*;
    use super::super::diff::derivative;
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;
    use Func::*;

    fn check(cases: &[(Expr, &str)], params: &[&str]) {
        let params: Vec<String> = params.iter().map(|s| s.to_string()).collect();
        for (e, expected) in cases {
            assert_eq!(tex(e, &params), *expected, "{e:?}");
        }
    }

    #[test]
    fn products_numbers_and_parentheses() {
        let cases = [
            (mul(n(2.0), t()), "2t"),
            (mul(n(3.0), add(t(), n(1.0))), r"3\left(t+1\right)"),
            (mul(n(2.0), pi()), r"2\pi"),
            (mul(pi(), t()), r"\pi t"),
            (pow(t(), n(2.0)), "t^{2}"),
            (ng(pow(t(), n(2.0))), "-t^{2}"),
            (div(n(1.0), n(2.0)), r"\frac{1}{2}"),
            (mul(n(2.0), n(3.0)), r"2\cdot 3"),
            (mul(t(), ng(n(2.0))), r"t\left(-2\right)"),
            (mul(ng(n(2.0)), t()), "-2t"),
            (pow(ng(t()), n(2.0)), r"\left(-t\right)^{2}"),
            (pow(n(2.0), ng(n(1.0))), "2^{-1}"),
            (mul(q(1, 3), t()), r"\frac{1}{3}t"),
            (mul(n(2.0), div(n(1.0), t())), r"2\cdot\frac{1}{t}"),
            (
                pow(div(t(), n(2.0)), n(2.0)),
                r"\left(\frac{t}{2}\right)^{2}",
            ),
            (pow(q(1, 3), t()), r"\left(\frac{1}{3}\right)^{t}"),
            (div(add(t(), n(1.0)), sub(t(), n(1.0))), r"\frac{t+1}{t-1}"),
            (sub(t(), add(p(0), t())), r"t-\left(a+t\right)"),
            (add(t(), ng(p(0))), r"t+\left(-a\right)"),
            (add(t(), sub(p(0), t())), "t+a-t"),
            (ng(add(t(), n(1.0))), r"-\left(t+1\right)"),
            (ng(ng(t())), r"-\left(-t\right)"),
            (mul(p(0), t()), "at"),
            (mul(t(), pow(n(2.0), t())), r"t\cdot 2^{t}"),
            (mul(mul(t(), t()), mul(n(0.5), t())), r"tt\cdot 0.5t"),
            (pow(e(), t()), "e^{t}"),
            (pow(pow(t(), n(2.0)), n(3.0)), r"\left(t^{2}\right)^{3}"),
            (pow(t(), pow(n(2.0), n(3.0))), "t^{2^{3}}"),
            // numbers as typed
            (n(6.5), "6.5"),
            (n(0.5), "0.5"),
            (q(-21, 10), "-2.1"),
            (q(3, 20), "0.15"),
            (q(-1, 3), r"-\frac{1}{3}"),
            (n(1234567.0), "1234567"),
            (inexact(0.1), "0.1"),
            (inexact(1e40), r"1\cdot 10^{40}"),
            (inexact(1.5e-7), r"1.5\cdot 10^{-7}"),
        ];
        check(&cases, &["a"]);
    }

    #[test]
    fn functions() {
        let two_t = || mul(n(2.0), t());
        let cases = [
            (call(Sin, t()), r"\sin t"),
            (call(Sin, two_t()), r"\sin\left(2t\right)"),
            (call(Cos, n(2.0)), r"\cos 2"),
            (call(Cos, p(0)), r"\cos \omega"),
            (call(Cos, q(1, 3)), r"\cos\left(\frac{1}{3}\right)"),
            (pow(call(Sin, t()), n(2.0)), r"\sin^{2} t"),
            (pow(call(Cos, two_t()), n(3.0)), r"\cos^{3}\left(2t\right)"),
            (pow(call(Sin, t()), ng(n(1.0))), r"\left(\sin t\right)^{-1}"),
            (call(Sqrt, add(t(), n(1.0))), r"\sqrt{t+1}"),
            (call(Abs, t()), r"\left|t\right|"),
            (call(Exp, two_t()), "e^{2t}"),
            (pow(call(Exp, t()), n(2.0)), r"\left(e^{t}\right)^{2}"),
            (call(Ln, t()), r"\ln t"),
            (call(Log, t()), r"\log_{10} t"),
            (call(Asin, t()), r"\arcsin t"),
            (call(Atan, two_t()), r"\arctan\left(2t\right)"),
            (call(Tanh, t()), r"\tanh t"),
            (call(Floor, t()), r"\lfloor t\rfloor"),
            (call(Ceil, two_t()), r"\lceil 2t\rceil"),
            (call(Sign, t()), r"\operatorname{sign} t"),
            // names
            (mul(p(0), t()), r"\omega t"),
            (p(1), "a_{1}"),
            (mul(p(2), t()), r"a_{\mathrm{max}}t"),
            (mul(p(3), p(0)), r"\Delta\omega"),
            (p(4), "x_{i}"),
            (p(5), r"\Omega"),
            (p(9), "?"),
            (mul(t(), call(Sin, t())), r"t\sin t"),
            (mul(call(Sin, t()), t()), r"\sin t\cdot t"),
            (mul(call(Sin, t()), call(Cos, t())), r"\sin t\cos t"),
            (mul(mul(n(3.0), p(0)), call(Cos, t())), r"3\omega\cos t"),
        ];
        check(&cases, &["ω", "a_1", "a_max", "Δ", "x_i", "Ω"]);
    }

    #[test]
    fn the_notes_polynomial_and_the_derivatives() {
        let show = |e: Expr| tex(&e, &[]);
        let d = |e: Expr| show(derivative(&e).unwrap());
        assert_eq!(show(notes_polynomial()), "6.5t^{5}-7.2t^{3}+3t^{2}-2.1t-5");
        assert_eq!(d(notes_polynomial()), "32.5t^{4}-21.6t^{2}+6t-2.1");
        assert_eq!(d(call(Cos, t())), r"-\sin t");
        let t2 = pow(t(), n(2.0));
        assert_eq!(d(call(Sin, t2)), r"2t\cos\left(t^{2}\right)");
        assert_eq!(d(pow(e(), t())), "e^{t}");
        assert_eq!(d(call(Ln, t())), r"\frac{1}{t}");
        assert_eq!(d(call(Sqrt, t())), r"\frac{1}{2\sqrt{t}}");
        assert_eq!(d(call(Abs, t())), r"\operatorname{sign} t");
        assert_eq!(d(call(Floor, t())), "0");
        assert_eq!(d(call(Tan, t())), r"\frac{1}{\cos^{2} t}");
        assert_eq!(d(pow(n(2.0), t())), r"2^{t}\ln 2");
        assert_eq!(d(call(Cos, mul(n(2.0), t()))), r"-2\sin\left(2t\right)");
    }

    #[test]
    fn every_greek_letter_has_its_command() {
        assert_eq!(GREEK.chars().count(), GREEK_TEX.split_whitespace().count());
        assert_eq!(greek('ψ').as_deref(), Some(r"\psi"));
    }

    #[test]
    fn a_deep_tree_is_cut_not_overflowed() {
        let mut e = t();
        for _ in 0..(MAX_DEPTH + 50) {
            e = call(Sqrt, e);
        }
        let s = tex(&e, &[]);
        assert!(s.starts_with(r"\sqrt{\sqrt{"), "{s}");
        assert!(s.contains(r"\cdots"), "{s}");
    }
}
