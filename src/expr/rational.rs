//! Exact fractions for polynomial pieces: `6.5` is kept as 13/2, so the Bézier form of a typed
//! polynomial and a joint verdict between polynomial pieces are exact.
//!
//! `i128` numerator and denominator, always reduced, denominator > 0. Every operation is
//! checked: one that would overflow returns `None`, and the caller falls back to f64 (the
//! result is then not marked exact). Coefficients of the polynomials students type stay far
//! inside the range (a degree-10 Bernstein conversion of 4-digit decimals needs ~60 bits).

use std::cmp::Ordering;
use std::fmt;

/// A reduced fraction `num / den` with `den > 0`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Rational {
    num: i128,
    den: i128,
}

#[inline(never)]
fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

impl Rational {
    /// 0.
    pub const ZERO: Rational = Rational { num: 0, den: 1 };
    /// 1.
    pub const ONE: Rational = Rational { num: 1, den: 1 };

    /// `num / den` reduced; `None` when `den` is 0 or the sign cannot be normalised.
    #[inline(never)] // one copy of the i128 arithmetic, not one per call site (wasm size)
    pub fn new(num: i128, den: i128) -> Option<Rational> {
        if den == 0 {
            return None;
        }
        let g = gcd(num, den);
        let (mut n, mut d) = (num / g, den / g);
        if d < 0 {
            n = n.checked_neg()?;
            d = d.checked_neg()?;
        }
        Some(Rational { num: n, den: d })
    }

    /// The integer `n`.
    pub fn integer(n: i128) -> Rational {
        Rational { num: n, den: 1 }
    }

    /// The numerator (sign carried here).
    pub fn numer(self) -> i128 {
        self.num
    }

    /// The denominator (> 0).
    pub fn denom(self) -> i128 {
        self.den
    }

    /// Whether the denominator is 1.
    pub fn is_integer(self) -> bool {
        self.den == 1
    }

    /// Whether it is 0.
    pub fn is_zero(self) -> bool {
        self.num == 0
    }

    /// The nearest f64 (correctly rounded when numerator and denominator are below 2^53,
    /// within an ulp or two otherwise).
    pub fn to_f64(self) -> f64 {
        self.num as f64 / self.den as f64
    }

    /// The exact value of a finite f64 (every f64 is a dyadic fraction), when it fits.
    pub fn from_f64(x: f64) -> Option<Rational> {
        if !x.is_finite() {
            return None;
        }
        if x == 0.0 {
            return Some(Rational::ZERO);
        }
        let bits = x.to_bits();
        let sign: i128 = if bits >> 63 == 1 { -1 } else { 1 };
        let exponent = ((bits >> 52) & 0x7ff) as i32;
        let fraction = (bits & ((1u64 << 52) - 1)) as i128;
        let (mantissa, exp) = if exponent == 0 {
            (fraction, -1074)
        } else {
            (fraction | (1i128 << 52), exponent - 1075)
        };
        // value = sign · mantissa · 2^exp
        let tz = mantissa.trailing_zeros() as i32;
        let (m, e) = (mantissa >> tz, exp + tz);
        if e >= 0 {
            if e > 120 - 53 {
                return None;
            }
            Rational::new(sign * (m << e), 1)
        } else {
            if -e > 125 {
                return None;
            }
            Rational::new(sign * m, 1i128 << (-e))
        }
    }

    /// `self + other`.
    #[inline(never)] // one copy of the i128 arithmetic, not one per call site (wasm size)
    pub fn checked_add(self, other: Rational) -> Option<Rational> {
        let g = gcd(self.den, other.den);
        let a = self.num.checked_mul(other.den / g)?;
        let b = other.num.checked_mul(self.den / g)?;
        Rational::new(a.checked_add(b)?, self.den.checked_mul(other.den / g)?)
    }

    /// `self − other`.
    pub fn checked_sub(self, other: Rational) -> Option<Rational> {
        self.checked_add(other.checked_neg()?)
    }

    /// `−self`.
    pub fn checked_neg(self) -> Option<Rational> {
        Some(Rational {
            num: self.num.checked_neg()?,
            den: self.den,
        })
    }

    /// `self · other`.
    #[inline(never)] // one copy of the i128 arithmetic, not one per call site (wasm size)
    pub fn checked_mul(self, other: Rational) -> Option<Rational> {
        let g1 = gcd(self.num, other.den).max(1);
        let g2 = gcd(other.num, self.den).max(1);
        Rational::new(
            (self.num / g1).checked_mul(other.num / g2)?,
            (self.den / g2).checked_mul(other.den / g1)?,
        )
    }

    /// `self / other`; `None` when `other` is 0.
    #[inline(never)] // one copy of the i128 arithmetic, not one per call site (wasm size)
    pub fn checked_div(self, other: Rational) -> Option<Rational> {
        if other.num == 0 {
            return None;
        }
        self.checked_mul(Rational::new(other.den, other.num)?)
    }

    /// `self^k` for an integer `k` (negative: the reciprocal's power; `None` for 0^negative).
    #[inline(never)] // one copy of the i128 arithmetic, not one per call site (wasm size)
    pub fn pow(self, k: i32) -> Option<Rational> {
        let mut base = if k < 0 {
            Rational::ONE.checked_div(self)?
        } else {
            self
        };
        let mut e = k.unsigned_abs();
        let mut acc = Rational::ONE;
        while e > 0 {
            if e & 1 == 1 {
                acc = acc.checked_mul(base)?;
            }
            e >>= 1;
            if e > 0 {
                base = base.checked_mul(base)?;
            }
        }
        Some(acc)
    }
}

impl PartialOrd for Rational {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Rational {
    fn cmp(&self, other: &Self) -> Ordering {
        // a/b vs c/d with b, d > 0: compare a·d with c·b; on overflow, compare as f64.
        match (
            self.num.checked_mul(other.den),
            other.num.checked_mul(self.den),
        ) {
            (Some(l), Some(r)) => l.cmp(&r),
            _ => self
                .to_f64()
                .partial_cmp(&other.to_f64())
                .unwrap_or(Ordering::Equal),
        }
    }
}

impl fmt::Display for Rational {
    /// `-271/50`, `3`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den == 1 {
            write!(f, "{}", self.num)
        } else {
            write!(f, "{}/{}", self.num, self.den)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    fn r(n: i128, d: i128) -> Rational {
        Rational::new(n, d).unwrap()
    }

    #[test]
    fn fractions_are_reduced_with_a_positive_denominator() {
        assert_eq!(r(6, -4), r(-3, 2));
        assert_eq!(r(-3, 2).numer(), -3);
        assert_eq!(r(-3, 2).denom(), 2);
        assert_eq!(Rational::new(1, 0), None);
    }

    #[test]
    fn arithmetic_is_exact() {
        assert_eq!(r(1, 3).checked_add(r(1, 6)), Some(r(1, 2)));
        assert_eq!(r(1, 3).checked_sub(r(1, 2)), Some(r(-1, 6)));
        assert_eq!(r(2, 3).checked_mul(r(9, 4)), Some(r(3, 2)));
        assert_eq!(r(2, 3).checked_div(r(4, 9)), Some(r(3, 2)));
        assert_eq!(r(2, 3).checked_div(Rational::ZERO), None);
        assert_eq!(r(-2, 3).pow(3), Some(r(-8, 27)));
        assert_eq!(r(2, 3).pow(-2), Some(r(9, 4)));
        assert!(r(1, 3) < r(1, 2));
        assert_eq!(r(-271, 50).to_string(), "-271/50");
    }

    #[test]
    fn overflow_is_reported_not_wrapped() {
        let big = Rational::integer(i128::MAX / 2);
        assert_eq!(big.checked_mul(Rational::integer(4)), None);
        assert_eq!(Rational::integer(i128::MIN).checked_neg(), None);
    }

    #[test]
    fn an_f64_converts_exactly() {
        assert_eq!(Rational::from_f64(0.5), Some(r(1, 2)));
        assert_eq!(Rational::from_f64(-3.0), Some(r(-3, 1)));
        // 0.1 is not 1/10 in binary: its exact value has denominator 2^55.
        assert_eq!(Rational::from_f64(0.1).unwrap().denom(), 1i128 << 55);
        assert_eq!(Rational::from_f64(f64::NAN), None);
    }
}
