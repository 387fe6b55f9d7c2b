//! Truncated Taylor series arithmetic: the recurrences that carry the normalised coefficients
//! cₖ (x(t + h) = Σₖ cₖ hᵏ) through each operation, generic over a [`Scalar`].
//!
//! Over normalised coefficients (a, b the operands, y the result, Σⱼ from
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

use super::ast::Func;
use super::jet::Scalar;
use super::MAX_JET_ORDER;

/// The largest series kept: orders 0 ..= MAX_JET_ORDER.
pub(super) const N: usize = MAX_JET_ORDER + 1;

fn k<S: Scalar>(k: usize) -> S {
    S::from_f64(k as f64)
}

/// out = a·b (Cauchy product), to the length of `out`.
pub(super) fn mul_into<S: Scalar>(a: &[S], b: &[S], out: &mut [S]) {
    for i in 0..out.len() {
        let mut s = a[0] * b[i];
        for j in 1..=i {
            s = s + a[j] * b[i - j];
        }
        out[i] = s;
    }
}

/// out = a/b.
pub(super) fn div_into<S: Scalar>(a: &[S], b: &[S], out: &mut [S]) {
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
pub(super) fn exp_into<S: Scalar>(a: &[S], y0: S, out: &mut [S]) {
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
pub(super) fn ln_into<S: Scalar>(a: &[S], y0: S, out: &mut [S]) {
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
pub(super) fn powi_into<S: Scalar>(a: &[S], n: i32, out: &mut [S]) {
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
pub(super) fn powf_into<S: Scalar>(a: &[S], r: f64, out: &mut [S]) {
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
pub(super) fn call_into<S: Scalar>(f: Func, a: &[S], out: &mut [S]) {
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
