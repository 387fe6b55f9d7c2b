//! Jets: truncated Taylor series x(t + h) = Σₖ cₖ hᵏ + O(h^(n+1)) carried through the tape by
//! the standard recurrences of automatic differentiation (never finite differences); the k-th
//! derivative is k!·cₖ.
//!
//! The recurrences, over normalised coefficients (a, b the operands, y the result, Σⱼ from
//! j = 1 unless written):
//! - a·b: yₖ = Σ_{j=0..k} aⱼ bₖ₋ⱼ; a/b: yₖ = (aₖ − Σⱼ bⱼ yₖ₋ⱼ)/b₀;
//! - aⁿ (integer n): repeated squaring of the series (so t² at t = 0 is fine), 1/aⁿ for n < 0;
//! - aʳ (real r, a₀ ≠ 0): yₖ = 1/(k a₀) Σⱼ (r j − (k − j)) aⱼ yₖ₋ⱼ; aᵇ (b varying) = e^(b ln a);
//! - eᵃ: yₖ = (1/k) Σⱼ j aⱼ yₖ₋ⱼ; ln a: yₖ = (aₖ − (1/k) Σ_{j<k} j yⱼ aₖ₋ⱼ)/a₀; log = ln / ln 10;
//! - √a: yₖ = (aₖ − Σ_{0<j<k} yⱼ yₖ₋ⱼ)/(2y₀);
//! - sin/cos as a pair: sₖ = (1/k) Σⱼ j aⱼ cₖ₋ⱼ, cₖ = −(1/k) Σⱼ j aⱼ sₖ₋ⱼ (sinh/cosh: +);
//! - tan: y′ = (1 + y²) a′, tanh: y′ = (1 − y²) a′, with u = 1 ± y² built alongside;
//! - asin, acos, atan: the series of y′ = ±a′/√(1 − a²), a′/(1 + a²), then integrated:
//!   yₖ = y′ₖ₋₁/k;
//! - |a| = s·a with s the sign of the first non-zero coefficient; when that is of odd order m
//!   (|t| at 0) the derivatives of order ≥ m do not exist: NaN;
//! - floor, ceil, sign: the value, then zeros.
//!
//! The code is generic over a [`Scalar`]: `f64` here, and [`Interval`](super::Interval) for
//! enclosures of the derivatives over an interval of t (see `certify.rs`).

use super::ast::Func;
use super::math;
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

/// The largest series kept: orders 0 ..= MAX_JET_ORDER.
const N: usize = MAX_JET_ORDER + 1;

fn k<S: Scalar>(k: usize) -> S {
    S::from_f64(k as f64)
}

/// out = a·b (Cauchy product), to the length of `out`.
fn mul_into<S: Scalar>(a: &[S], b: &[S], out: &mut [S]) {
    for i in 0..out.len() {
        let mut s = a[0] * b[i];
        for j in 1..=i {
            s = s + a[j] * b[i - j];
        }
        out[i] = s;
    }
}

/// out = a/b.
fn div_into<S: Scalar>(a: &[S], b: &[S], out: &mut [S]) {
    for i in 0..out.len() {
        let mut s = a[i];
        for j in 1..=i {
            s = s - b[j] * out[i - j];
        }
        out[i] = s / b[0];
    }
}

/// out = √a with out₀ = y0.
fn sqrt_into<S: Scalar>(a: &[S], y0: S, out: &mut [S]) {
    out[0] = y0;
    for i in 1..out.len() {
        let mut s = a[i];
        for j in 1..i {
            s = s - out[j] * out[i - j];
        }
        out[i] = s / (k::<S>(2) * y0);
    }
}

/// out = e^a with out₀ = y0.
fn exp_into<S: Scalar>(a: &[S], y0: S, out: &mut [S]) {
    out[0] = y0;
    for i in 1..out.len() {
        let mut s = a[1] * out[i - 1];
        for j in 2..=i {
            s = s + k::<S>(j) * a[j] * out[i - j];
        }
        out[i] = s / k(i);
    }
}

/// out = ln a with out₀ = y0.
fn ln_into<S: Scalar>(a: &[S], y0: S, out: &mut [S]) {
    out[0] = y0;
    for i in 1..out.len() {
        let mut s = k::<S>(i) * a[i];
        for j in 1..i {
            s = s - k::<S>(j) * out[j] * a[i - j];
        }
        out[i] = s / (k::<S>(i) * a[0]);
    }
}

/// out = aⁿ by repeated squaring of the series; out₀ = a₀ⁿ as the scalar computes it.
fn powi_into<S: Scalar>(a: &[S], n: i32, out: &mut [S]) {
    let m = out.len();
    let zero = S::from_f64(0.0);
    let (mut base, mut acc, mut tmp) = ([zero; N], [zero; N], [zero; N]);
    base[..m].copy_from_slice(&a[..m]);
    acc[0] = S::from_f64(1.0);
    let mut e = n.unsigned_abs();
    while e > 0 {
        if e & 1 == 1 {
            mul_into(&acc[..m], &base[..m], &mut tmp[..m]);
            acc = tmp;
        }
        e >>= 1;
        if e > 0 {
            mul_into(&base[..m], &base[..m], &mut tmp[..m]);
            base = tmp;
        }
    }
    if n < 0 {
        acc[0] = a[0].powi(n.checked_neg().unwrap_or(i32::MAX));
        let mut one = [zero; N];
        one[0] = S::from_f64(1.0);
        div_into(&one[..m], &acc[..m], out);
    } else {
        out.copy_from_slice(&acc[..m]);
    }
    out[0] = a[0].powi(n);
}

/// out = aʳ for a real r (a₀ ≠ 0 for the derivatives).
fn powf_into<S: Scalar>(a: &[S], r: f64, out: &mut [S]) {
    out[0] = a[0].powf(r);
    for i in 1..out.len() {
        let mut s = S::from_f64(0.0);
        for j in 1..=i {
            s = s + S::from_f64(r * j as f64 - (i - j) as f64) * a[j] * out[i - j];
        }
        out[i] = s / (k::<S>(i) * a[0]);
    }
}

/// out = ∫ (a′ / w) with out₀ = y0 and the sign `sign` (asin, acos, atan).
fn integrate_quotient<S: Scalar>(a: &[S], w: &[S], y0: S, sign: f64, out: &mut [S]) {
    let m = out.len();
    let zero = S::from_f64(0.0);
    let (mut da, mut q) = ([zero; N], [zero; N]);
    for i in 0..m - 1 {
        da[i] = k::<S>(i + 1) * a[i + 1];
    }
    div_into(&da[..m - 1], &w[..m - 1], &mut q[..m - 1]);
    out[0] = y0;
    for i in 1..m {
        out[i] = S::from_f64(sign) * q[i - 1] / k(i);
    }
}

/// out = f(a).
fn call_into<S: Scalar>(f: Func, a: &[S], out: &mut [S]) {
    let m = out.len();
    let zero = S::from_f64(0.0);
    let a0 = a[0];
    match f {
        Func::Sin | Func::Cos | Func::Sinh | Func::Cosh => {
            let hyperbolic = matches!(f, Func::Sinh | Func::Cosh);
            let (mut s, mut c) = ([zero; N], [zero; N]);
            (s[0], c[0]) = if hyperbolic {
                a0.sinh_cosh()
            } else {
                a0.sin_cos()
            };
            for i in 1..m {
                let (mut ss, mut cc) = (zero, zero);
                for j in 1..=i {
                    ss = ss + k::<S>(j) * a[j] * c[i - j];
                    cc = cc + k::<S>(j) * a[j] * s[i - j];
                }
                s[i] = ss / k(i);
                c[i] = if hyperbolic { cc / k(i) } else { -cc / k(i) };
            }
            let pick = if matches!(f, Func::Sin | Func::Sinh) {
                s
            } else {
                c
            };
            out.copy_from_slice(&pick[..m]);
            out[0] = a0.func(f);
        }
        Func::Tan | Func::Tanh => {
            // y′ = u a′ with u = 1 + y² (tan) or 1 − y² (tanh).
            let sign = if f == Func::Tan { 1.0 } else { -1.0 };
            let mut u = [zero; N];
            out[0] = a0.func(f);
            u[0] = S::from_f64(1.0) + S::from_f64(sign) * out[0].powi(2);
            for i in 1..m {
                let mut s = zero;
                for j in 1..=i {
                    s = s + k::<S>(j) * a[j] * u[i - j];
                }
                out[i] = s / k(i);
                let mut y2 = zero;
                for j in 0..=i {
                    y2 = y2 + out[j] * out[i - j];
                }
                u[i] = S::from_f64(sign) * y2;
            }
        }
        Func::Asin | Func::Acos | Func::Atan => {
            let (mut sq, mut w, mut root) = ([zero; N], [zero; N], [zero; N]);
            mul_into(a, a, &mut sq[..m]);
            let sign = if f == Func::Atan { 1.0 } else { -1.0 };
            for i in 0..m {
                w[i] = S::from_f64(sign) * sq[i];
            }
            w[0] = S::from_f64(1.0) + S::from_f64(sign) * a0.powi(2);
            if f != Func::Atan {
                sqrt_into(&w[..m], w[0].func(Func::Sqrt), &mut root[..m]);
                w = root;
            }
            let dir = if f == Func::Acos { -1.0 } else { 1.0 };
            integrate_quotient(a, &w, a0.func(f), dir, out);
        }
        Func::Exp => exp_into(a, a0.func(f), out),
        Func::Ln => ln_into(a, a0.func(f), out),
        Func::Log => {
            ln_into(a, a0.func(Func::Ln), out);
            for y in out.iter_mut().skip(1) {
                *y = *y / S::from_f64(std::f64::consts::LN_10);
            }
            out[0] = a0.func(f);
        }
        Func::Sqrt => sqrt_into(a, a0.func(f), out),
        Func::Abs => {
            let (s, unknown_from) = S::abs_sign(&a[..m]);
            for i in 0..m {
                out[i] = if i >= unknown_from {
                    S::unknown()
                } else {
                    s * a[i]
                };
            }
            out[0] = a0.func(f);
        }
        Func::Floor | Func::Ceil | Func::Sign => {
            out.fill(zero);
            out[0] = a0.func(f);
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
