//! Jets: truncated Taylor series x(t + h) = Σₖ cₖ hᵏ + O(h^(n+1)) carried through the tape by
//! the standard recurrences of automatic differentiation (never finite differences); the k-th
//! derivative is k!·cₖ.
//!
//! The recurrences of every operation are in `series.rs` (listed there).
//!
//! The code is generic over a [`Scalar`]: `f64` here, and [`Interval`](super::Interval) for
//! enclosures of the derivatives over an interval of t (see `certify.rs`).

use super::ast::Func;
use super::math;
use super::series::{call_into, div_into, exp_into, ln_into, mul_into, powf_into, powi_into, N};
use super::tape::{Op, Scratch, Tape};
use super::MAX_JET_ORDER;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// The numbers a jet can be computed in: `f64`, or intervals that enclose them.
pub trait Scalar:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The number x (a point interval).
    fn from_f64(x: f64) -> Self;
    /// "Not known": NaN, or the whole line.
    fn unknown() -> Self;
    /// f(x) for a function of the language.
    fn func(self, f: Func) -> Self;
    /// (sin x, cos x).
    fn sin_cos(self) -> (Self, Self);
    /// (sinh x, cosh x).
    fn sinh_cosh(self) -> (Self, Self);
    /// xⁿ, n an integer (0⁰ = 1).
    fn powi(self, n: i32) -> Self;
    /// xʳ, r a real that is not an integer (NaN or empty for x < 0).
    fn powf(self, r: f64) -> Self;
    /// xᵇ = e^(b ln x), for a varying exponent.
    fn pow_var(self, b: Self) -> Self;
    /// For |a| = s·a: the factor s, and the first order whose coefficient is unknown (the
    /// length of `a` if none).
    fn abs_sign(a: &[Self]) -> (Self, usize);
}

impl Scalar for f64 {
    fn from_f64(x: f64) -> Self {
        x
    }
    fn unknown() -> Self {
        f64::NAN
    }
    fn func(self, f: Func) -> Self {
        math::apply(f, self)
    }
    fn sin_cos(self) -> (Self, Self) {
        math::sin_cos(self)
    }
    fn sinh_cosh(self) -> (Self, Self) {
        math::sinh_cosh(self)
    }
    fn powi(self, n: i32) -> Self {
        math::powi(self, n)
    }
    fn powf(self, r: f64) -> Self {
        math::pow_const(self, r)
    }
    fn pow_var(self, b: Self) -> Self {
        math::pow_var(self, b)
    }
    fn abs_sign(a: &[f64]) -> (f64, usize) {
        match a.iter().position(|&x| x != 0.0) {
            None => (0.0, a.len()),
            Some(m) if m % 2 == 0 => (math::sign(a[m]), a.len()),
            // a = aₘ tᵐ + …, m odd: |a| has a kink; below m every coefficient is 0.
            Some(m) => (1.0, m),
        }
    }
}

/// Runs the tape on series of length m (orders 0 ..= m − 1, m ≤ [`MAX_JET_ORDER`] + 1) with
/// t's series `[t, 1, 0, …]`; `fixed` holds the registers that do not depend on t
/// ([`Tape::eval_fixed`]). Register i's series is `buf[i·m .. (i+1)·m]`.
pub(crate) fn run<S: Scalar>(tape: &Tape, t: S, m: usize, fixed: &[f64], buf: &mut Vec<S>) {
    let zero = S::from_f64(0.0);
    buf.clear();
    buf.resize(tape.ops.len() * m, zero);
    for (i, op) in tape.ops.iter().enumerate() {
        let (before, rest) = buf.split_at_mut(i * m);
        let out = &mut rest[..m];
        let reg = |r: u32| &before[r as usize * m..(r as usize + 1) * m];
        if !tape.varies[i] {
            out[0] = S::from_f64(fixed.get(i).copied().unwrap_or(f64::NAN));
            continue;
        }
        match *op {
            Op::T => {
                out[0] = t;
                if m > 1 {
                    out[1] = S::from_f64(1.0);
                }
            }
            Op::Const(_) | Op::Param(_) => out[0] = S::unknown(),
            Op::Neg(a) => {
                for (o, &x) in out.iter_mut().zip(reg(a)) {
                    *o = -x;
                }
            }
            Op::Add(a, b) | Op::Sub(a, b) => {
                let minus = matches!(op, Op::Sub(..));
                for ((o, &x), &y) in out.iter_mut().zip(reg(a)).zip(reg(b)) {
                    *o = if minus { x - y } else { x + y };
                }
            }
            Op::Mul(a, b) => mul_into(reg(a), reg(b), out),
            Op::Div(a, b) => div_into(reg(a), reg(b), out),
            Op::Powi(a, n) => powi_into(reg(a), n, out),
            Op::PowConst(a, b) => {
                let r = fixed.get(b as usize).copied().unwrap_or(f64::NAN);
                match math::integer_exponent(r) {
                    Some(n) => powi_into(reg(a), n, out),
                    None => powf_into(reg(a), r, out),
                }
            }
            Op::PowVar(a, b) => {
                let (a, b) = (reg(a), reg(b));
                let (mut l, mut bl) = ([zero; N], [zero; N]);
                ln_into(a, a[0].func(Func::Ln), &mut l[..m]);
                mul_into(b, &l[..m], &mut bl[..m]);
                exp_into(&bl[..m], a[0].pow_var(b[0]), out);
            }
            Op::Call(f, a) => call_into(f, reg(a), out),
        }
    }
}

/// k! for k ≤ 20 (exact in f64 up to 18!).
pub(crate) fn factorial(k: usize) -> f64 {
    (1..=k).map(|i| i as f64).product()
}

impl Tape {
    /// The derivatives dᵏx/dtᵏ at `t` for k = 0 ..= `order` (capped at [`MAX_JET_ORDER`] and
    /// at `out.len() − 1`) into `out[k]`, by Taylor-mode automatic differentiation
    /// (`out[0]` is the value). Where a derivative does not exist (|t|′ at 0, ln at 0) it is
    /// NaN or ±∞; `out` beyond `order` is left as it was.
    pub fn eval_jet(
        &self,
        t: f64,
        order: usize,
        params: &[f64],
        scratch: &mut Scratch,
        out: &mut [f64],
    ) {
        let m = order.min(MAX_JET_ORDER).min(out.len().saturating_sub(1)) + 1;
        if out.is_empty() || self.ops.is_empty() {
            out.fill(f64::NAN);
            return;
        }
        self.eval_fixed(params, &mut scratch.f);
        run(self, t, m, &scratch.f, &mut scratch.jet);
        let last = &scratch.jet[(self.ops.len() - 1) * m..];
        for (i, (o, &c)) in out.iter_mut().zip(last).enumerate() {
            *o = c * factorial(i);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::ast::Expr;
    use super::super::tape::build::*;
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    fn jet(e: &Expr, t: f64, order: usize, params: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; order + 1];
        Tape::compile(e).eval_jet(t, order, params, &mut Scratch::new(), &mut out);
        out
    }

    /// The trees of the fixture's expressions (tests/fixtures/make_expr_jet_fixtures.py).
    fn fixture_tree(name: &str) -> Option<Expr> {
        let sq = |a: Expr| pow(a, n(2.0));
        Some(match name {
            "cos" => call(Func::Cos, t()),
            "sin" => call(Func::Sin, t()),
            "poly" => notes_polynomial(),
            "lissajous" => call(Func::Sin, mul(n(3.0), t())),
            "tan" => call(Func::Tan, t()),
            "exp_sin_sq" => call(Func::Exp, call(Func::Sin, sq(t()))),
            "sqrt_1_t2" => call(Func::Sqrt, add(n(1.0), sq(t()))),
            "atan_over" => div(call(Func::Atan, t()), add(n(1.0), t())),
            "ln_2_cos" => call(Func::Ln, add(n(2.0), call(Func::Cos, t()))),
            "t_to_t" => pow(t(), t()),
            "asin_half" => call(Func::Asin, div(t(), n(2.0))),
            "tanh_sinh" => add(
                call(Func::Tanh, t()),
                mul(call(Func::Sinh, t()), call(Func::Cosh, div(t(), n(3.0)))),
            ),
            "acos_log" => add(call(Func::Acos, div(t(), n(3.0))), call(Func::Log, t())),
            "pow_real" => add(
                pow(add(n(1.0), sq(t())), n(2.5)),
                pow(add(n(2.0), t()), neg(div(n(1.0), n(3.0)))),
            ),
            _ => return None,
        })
    }

    #[test]
    fn derivatives_match_sympy() {
        let text = include_str!("../../tests/fixtures/expr_jets_sympy.txt");
        let mut rows = 0;
        for line in text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.is_empty())
        {
            let mut words = line.split_whitespace();
            let name = words.next().unwrap_or("");
            let numbers: Vec<f64> = words.map(|w| w.parse().unwrap_or(f64::NAN)).collect();
            let tree = fixture_tree(name).unwrap_or_else(|| panic!("unknown fixture {name}"));
            assert_eq!(numbers.len(), MAX_JET_ORDER + 2, "{line}");
            let got = jet(&tree, numbers[0], MAX_JET_ORDER, &[]);
            for (order, (&g, &e)) in got.iter().zip(&numbers[1..]).enumerate() {
                let tol = 1e-12 * e.abs().max(1.0);
                assert!(
                    (g - e).abs() <= tol,
                    "{name} at {}: d{order} = {g}, sympy {e}",
                    numbers[0]
                );
            }
            rows += 1;
        }
        assert_eq!(rows, 39);
    }

    #[test]
    fn circle_derivatives_cycle() {
        let x = 0.3f64;
        let c = jet(&call(Func::Cos, t()), x, 8, &[]);
        let cycle = [x.cos(), -x.sin(), -x.cos(), x.sin()];
        for (k, d) in c.iter().enumerate() {
            assert!((d - cycle[k % 4]).abs() < 1e-15, "d{k}");
        }
    }

    #[test]
    fn integer_powers_work_at_a_zero_and_a_negative_base() {
        assert_eq!(jet(&pow(t(), n(2.0)), 0.0, 3, &[]), [0.0, 0.0, 2.0, 0.0]);
        assert_eq!(
            jet(&pow(t(), n(3.0)), -2.0, 4, &[]),
            [-8.0, 12.0, -12.0, 6.0, 0.0]
        );
        // The same through a parameter exponent that is an integer at run time.
        assert_eq!(
            jet(&pow(t(), p(0)), -2.0, 4, &[3.0]),
            [-8.0, 12.0, -12.0, 6.0, 0.0]
        );
        // t⁻² at 2: 1/4, −2/8, 6/16, −24/32.
        assert_eq!(
            jet(&pow(t(), n(-2.0)), 2.0, 3, &[]),
            [0.25, -0.25, 0.375, -0.75]
        );
        assert_eq!(jet(&pow(t(), n(0.0)), 0.0, 2, &[]), [1.0, 0.0, 0.0]);
        // A real power at a zero base: the value, then no derivatives.
        let d = jet(&pow(t(), n(0.5)), 0.0, 2, &[]);
        assert_eq!(d[0], 0.0);
        assert!(d[1].is_nan() || d[1].is_infinite());
    }

    #[test]
    fn abs_follows_the_first_nonzero_coefficient() {
        assert_eq!(
            jet(&call(Func::Abs, pow(t(), n(2.0))), 0.0, 3, &[]),
            [0.0, 0.0, 2.0, 0.0]
        );
        assert_eq!(
            jet(&call(Func::Abs, neg(pow(t(), n(2.0)))), 0.0, 2, &[]),
            [0.0, 0.0, 2.0]
        );
        let d = jet(&call(Func::Abs, t()), 0.0, 2, &[]);
        assert_eq!(d[0], 0.0);
        assert!(d[1].is_nan() && d[2].is_nan());
        let d = jet(&call(Func::Abs, pow(t(), n(3.0))), 0.0, 3, &[]);
        assert_eq!(&d[..3], &[0.0, 0.0, 0.0]);
        assert!(d[3].is_nan());
        assert_eq!(jet(&call(Func::Abs, t()), -1.5, 2, &[]), [1.5, -1.0, 0.0]);
    }

    #[test]
    fn steps_have_zero_derivatives_and_their_conventional_values() {
        let three_t = |f| call(f, mul(n(3.0), t()));
        assert_eq!(
            jet(&three_t(Func::Floor), 1.0 / 3.0, 2, &[]),
            [1.0, 0.0, 0.0]
        );
        assert_eq!(jet(&three_t(Func::Ceil), 0.5, 2, &[]), [2.0, 0.0, 0.0]);
        assert_eq!(jet(&three_t(Func::Sign), 0.0, 2, &[]), [0.0, 0.0, 0.0]);
        assert_eq!(jet(&three_t(Func::Sign), -0.1, 1, &[]), [-1.0, 0.0]);
    }

    #[test]
    fn undefined_points_give_nan_or_infinity() {
        let d = jet(&call(Func::Ln, t()), 0.0, 2, &[]);
        assert_eq!(d[0], f64::NEG_INFINITY);
        assert!(!d[1].is_finite());
        assert!(jet(&call(Func::Sqrt, t()), -1.0, 1, &[])
            .iter()
            .all(|x| x.is_nan()));
        assert!(!jet(&call(Func::Asin, t()), 1.0, 1, &[])[1].is_finite());
        assert!(jet(&div(n(1.0), t()), 0.0, 1, &[])
            .iter()
            .all(|x| !x.is_finite()));
    }

    #[test]
    fn order_and_output_length_cap_the_work() {
        let e = call(Func::Exp, t());
        let tape = Tape::compile(&e);
        let mut s = Scratch::new();
        let mut out = [7.0; 12];
        tape.eval_jet(0.0, 20, &[], &mut s, &mut out);
        assert_eq!(&out[..9], &[1.0; 9]);
        assert_eq!(&out[9..], &[7.0; 3]);
        let mut two = [0.0; 2];
        tape.eval_jet(0.0, 8, &[], &mut s, &mut two);
        assert_eq!(two, [1.0, 1.0]);
        tape.eval_jet(0.0, 8, &[], &mut s, &mut []);
        // A constant: value then zeros.
        assert_eq!(jet(&mul(p(0), n(2.0)), 1.0, 2, &[1.5]), [3.0, 0.0, 0.0]);
    }
}
