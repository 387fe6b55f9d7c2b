//! The elementary functions of the expression language on `f64`, with the language's
//! conventions: floor right-continuous, ceil left-continuous, sign(0) = 0, 0⁰ = 1, an
//! undefined value is NaN or ±∞ as IEEE 754 gives it (ln 0 = −∞, √−1 = NaN, 1/0 = ∞).
//!
//! The transcendental functions come from the platform (`platform.rs`): JavaScript's
//! `Math` in the browser build (no second copy of libm in the wasm), Rust's std elsewhere.

use super::ast::Func;
use crate::platform;

/// f(x) for one of the language's functions. `log` is log₁₀; `sign` is −1, 0 or 1 (NaN for
/// NaN); `floor`, `ceil`, `abs`, `sqrt` as IEEE 754 defines them.
pub fn apply(f: Func, x: f64) -> f64 {
    match f {
        Func::Sin => platform::sin_cos(x).0,
        Func::Cos => platform::sin_cos(x).1,
        Func::Tan => platform::tan(x),
        Func::Asin => platform::asin(x),
        Func::Acos => platform::acos(x),
        Func::Atan => platform::atan(x),
        Func::Sinh => platform::sinh(x),
        Func::Cosh => platform::cosh(x),
        Func::Tanh => platform::tanh(x),
        Func::Exp => platform::exp(x),
        Func::Ln => platform::ln(x),
        Func::Log => platform::log10(x),
        Func::Sqrt => x.sqrt(),
        Func::Abs => x.abs(),
        Func::Floor => x.floor(),
        Func::Ceil => x.ceil(),
        Func::Sign => sign(x),
    }
}

/// sign(x): 1 for x > 0, −1 for x < 0, 0 at ±0, NaN for NaN.
pub fn sign(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        x * 0.0
    }
}

/// (sin x, cos x) from the platform.
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    platform::sin_cos(x)
}

/// (sinh x, cosh x) from the platform.
pub(crate) fn sinh_cosh(x: f64) -> (f64, f64) {
    (platform::sinh(x), platform::cosh(x))
}

/// xⁿ for an integer n by repeated squaring (exact sign for a negative base: (−2)³ = −8;
/// x⁰ = 1 for every x, so 0⁰ = 1; x⁻ⁿ = 1/xⁿ, so 0⁻¹ = ∞). At most 2·32 products.
pub fn powi(x: f64, n: i32) -> f64 {
    let acc = powu(x, n.unsigned_abs());
    if n < 0 {
        1.0 / acc
    } else {
        acc
    }
}

/// xᵉ for a natural e by repeated squaring (x⁰ = 1); monotone in x ≥ 0, since every product
/// is.
pub fn powu(x: f64, e: u32) -> f64 {
    let mut e = e;
    let mut base = x;
    let mut acc = 1.0;
    while e > 0 {
        if e & 1 == 1 {
            acc *= base;
        }
        e >>= 1;
        if e > 0 {
            base *= base;
        }
    }
    acc
}

/// The integer that `y` is, if it is one that fits an `i32` (then `x^y` is [`powi`]).
pub fn integer_exponent(y: f64) -> Option<i32> {
    if y.fract() == 0.0 && y.abs() <= i32::MAX as f64 {
        Some(y as i32)
    } else {
        None
    }
}

/// xʸ for an exponent that does not depend on t (a number or a parameter): [`powi`] when y is
/// an integer, else IEEE `pow` (a negative base gives NaN, 0ʸ = 0 for y > 0 and ∞ for y < 0).
pub fn pow_const(x: f64, y: f64) -> f64 {
    match integer_exponent(y) {
        Some(n) => powi(x, n),
        None => platform::pow(x, y),
    }
}

/// xʸ for an exponent that varies with t, read as e^(y ln x): NaN for x < 0 (even where y
/// happens to be an integer, so the value and its derivatives agree), IEEE `pow` for x ≥ 0
/// (0ʸ = 0 for y > 0, 0⁰ = 1, 0ʸ = ∞ for y < 0).
pub fn pow_var(x: f64, y: f64) -> f64 {
    if x < 0.0 {
        f64::NAN
    } else {
        platform::pow(x, y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    #[test]
    fn powi_keeps_the_sign_and_zero_to_the_zero_is_one() {
        assert_eq!(powi(-2.0, 3), -8.0);
        assert_eq!(powi(-2.0, 4), 16.0);
        assert_eq!(powi(2.0, -2), 0.25);
        assert_eq!(powi(0.0, 0), 1.0);
        assert_eq!(powi(f64::NAN, 0), 1.0);
        assert_eq!(powi(0.0, -1), f64::INFINITY);
        assert_eq!(powi(1.5, 10), 57.6650390625);
        assert_eq!(powi(1.0, i32::MIN), 1.0);
    }

    #[test]
    fn powers_with_a_constant_exponent_follow_ieee() {
        assert_eq!(pow_const(-2.0, 3.0), -8.0);
        assert!(pow_const(-2.0, 0.5).is_nan());
        assert_eq!(pow_const(0.0, 0.0), 1.0);
        assert_eq!(pow_const(4.0, 0.5), 2.0);
        assert_eq!(pow_const(0.0, -0.5), f64::INFINITY);
        assert!(pow_var(-2.0, 3.0).is_nan());
        assert_eq!(pow_var(0.0, 2.0), 0.0);
        assert_eq!(pow_var(0.0, 0.0), 1.0);
        assert_eq!(integer_exponent(3.0), Some(3));
        assert_eq!(integer_exponent(3.5), None);
        assert_eq!(integer_exponent(1e10), None);
    }

    #[test]
    fn the_step_functions_follow_the_conventions() {
        assert_eq!(apply(Func::Floor, -0.5), -1.0);
        assert_eq!(apply(Func::Ceil, -0.5), 0.0);
        assert_eq!(apply(Func::Sign, 0.0), 0.0);
        assert_eq!(apply(Func::Sign, -3.0), -1.0);
        assert!(apply(Func::Sign, f64::NAN).is_nan());
        assert_eq!(apply(Func::Log, 1000.0), 3.0);
        assert_eq!(apply(Func::Ln, 0.0), f64::NEG_INFINITY);
        assert!(apply(Func::Sqrt, -1.0).is_nan());
        assert!(apply(Func::Asin, 1.5).is_nan());
        assert_eq!(apply(Func::Exp, 0.0), 1.0);
    }
}
