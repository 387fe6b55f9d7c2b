//! Interval arithmetic for certified plotting: an [`Interval`] encloses every value an
//! expression takes for t in [lo, hi], and [`IntervalFlags`](super::IntervalFlags) say whether it is proven defined,
//! continuous and C² there.
//!
//! Outward rounding: every arithmetic result (+ − × ÷) is widened by one ulp each way
//! (`next_down`/`next_up`), since the rounded endpoint is within half an ulp of the exact one;
//! every result of a library function (sin, exp, pow, …) by two ulps (fdlibm, and V8's port of
//! it, stay within one ulp of the exact value, and the second ulp covers the rounding of the
//! argument). Exact operations (floor, ceil, sign, abs, negation) are not widened. A register
//! that does not depend on t (a number, a parameter, a function of them) is the point its
//! `f64` evaluation gives, so the enclosure holds every `f64` evaluation of the tape.
//!
//! Sharp ranges: sin and cos check whether the interval holds a maximum (π/2 + 2kπ, 2kπ) or
//! a minimum; monotone functions (exp, ln, atan, asin, …) take their endpoints; even powers,
//! cosh and abs are 0-aware; tan detects its poles π/2 + kπ.
//!
//! The arithmetic and [`Interval::apply`] stay out of line (`#[inline(never)]`): inlined into
//! every series recurrence they cost ~5 KB of gzipped wasm.

use super::ast::Func;
use super::jet::Scalar;
use super::math;
use std::f64::consts::{FRAC_PI_2, PI};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A closed interval [lo, hi] of reals (lo ≤ hi; infinite ends allowed); the empty interval
/// has NaN ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
}

#[inline(never)]
fn widen(lo: f64, hi: f64, ulps: u32) -> Interval {
    if lo.is_nan() || hi.is_nan() {
        return Interval::EMPTY;
    }
    let (mut lo, mut hi) = (lo, hi);
    for _ in 0..ulps {
        lo = lo.next_down();
        hi = hi.next_up();
    }
    Interval { lo, hi }
}

/// A product of ends with 0·∞ = 0 (the limit the enclosure needs).
fn times(x: f64, y: f64) -> f64 {
    if x == 0.0 || y == 0.0 {
        0.0
    } else {
        x * y
    }
}

impl Interval {
    /// Every real and ±∞.
    pub const ENTIRE: Interval = Interval {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };
    /// No value.
    pub const EMPTY: Interval = Interval {
        lo: f64::NAN,
        hi: f64::NAN,
    };

    /// [lo, hi] (empty if lo > hi or either is NaN).
    pub fn new(lo: f64, hi: f64) -> Self {
        if lo <= hi {
            Interval { lo, hi }
        } else {
            Interval::EMPTY
        }
    }

    /// [x, x].
    pub fn point(x: f64) -> Self {
        Interval::new(x, x)
    }

    /// Whether it holds no value.
    pub fn is_empty(self) -> bool {
        self.lo.is_nan() || self.hi.is_nan() || self.lo > self.hi
    }

    /// Whether lo ≤ x ≤ hi.
    pub fn contains(self, x: f64) -> bool {
        self.lo <= x && x <= self.hi
    }

    /// Whether both ends are finite.
    pub fn is_finite(self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }

    /// max(|lo|, |hi|): the largest magnitude in it.
    pub fn mag(self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }

    /// [lo, hi] ∩ [a, b].
    fn clip(self, a: f64, b: f64) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        Interval::new(self.lo.max(a), self.hi.min(b))
    }

    /// Whether some x₀ + kπ·step (k an integer) lies in it, with a slack of a few ulps so a
    /// point at an end is never missed (claiming one too many only loosens the enclosure).
    fn holds_lattice(self, x0: f64, step: f64) -> bool {
        let slack = 4.0 * f64::EPSILON * (1.0 + self.mag());
        let k = ((self.lo - x0) / step).ceil();
        [k - 1.0, k].iter().any(|&k| {
            let x = x0 + k * step;
            x >= self.lo - slack && x <= self.hi + slack
        })
    }

    /// f on a monotone f: [f(lo), f(hi)] or reversed, widened for a library function.
    fn monotone(self, f: impl Fn(f64) -> f64, increasing: bool) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        let (a, b) = (f(self.lo), f(self.hi));
        if increasing {
            widen(a, b, 2)
        } else {
            widen(b, a, 2)
        }
    }

    /// sin or cos: maxima at `top` + 2kπ, minima at `top` + π + 2kπ (exact ±1 when held).
    fn trig(self, f: Func, top: f64) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        if (self.hi - self.lo >= 2.0 * PI) || (self.hi - self.lo).is_nan() {
            return Interval::new(-1.0, 1.0);
        }
        let (a, b) = (math::apply(f, self.lo), math::apply(f, self.hi));
        let mut r = widen(a.min(b), a.max(b), 2);
        if self.holds_lattice(top, 2.0 * PI) {
            r.hi = 1.0;
        }
        if self.holds_lattice(top + PI, 2.0 * PI) {
            r.lo = -1.0;
        }
        r.clip(-1.0, 1.0)
    }

    /// Whether tan has a pole (π/2 + kπ) in it, or it is at least π wide (false if empty).
    pub fn holds_tan_pole(self) -> bool {
        let width = self.hi - self.lo;
        !self.is_empty() && (width.is_nan() || width >= PI || self.holds_lattice(FRAC_PI_2, PI))
    }

    /// An even function decreasing on (−∞, 0] and increasing on [0, ∞) (x², cosh, |x|).
    fn even(self, f: impl Fn(f64) -> f64, ulps: u32) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        let (a, b) = (f(self.lo), f(self.hi));
        if self.lo >= 0.0 {
            widen(a, b, ulps)
        } else if self.hi <= 0.0 {
            widen(b, a, ulps)
        } else {
            widen(f(0.0), a.max(b), ulps)
        }
    }

    /// f(X) for a function of the language, restricted to its domain (ln over [−1, 1] is the
    /// range of ln over (0, 1]; √ over [−2, −1] is empty).
    #[inline(never)]
    pub fn apply(self, f: Func) -> Interval {
        match f {
            Func::Sin => self.trig(Func::Sin, FRAC_PI_2),
            Func::Cos => self.trig(Func::Cos, 0.0),
            Func::Tan if self.holds_tan_pole() => Interval::ENTIRE,
            Func::Tan => self.monotone(|x| math::apply(Func::Tan, x), true),
            Func::Asin => self.clip(-1.0, 1.0).monotone(|x| math::apply(f, x), true),
            Func::Acos => self
                .clip(-1.0, 1.0)
                .monotone(|x| math::apply(f, x), false)
                .clip(0.0, PI),
            Func::Ln | Func::Log => self
                .clip(0.0, f64::INFINITY)
                .monotone(|x| math::apply(f, x), true),
            Func::Sqrt => self
                .clip(0.0, f64::INFINITY)
                .monotone(f64::sqrt, true)
                .clip(0.0, f64::INFINITY),
            Func::Exp => self
                .monotone(|x| math::apply(f, x), true)
                .clip(0.0, f64::INFINITY),
            Func::Atan | Func::Sinh | Func::Tanh => self.monotone(|x| math::apply(f, x), true),
            Func::Cosh => self
                .even(|x| math::apply(Func::Cosh, x), 2)
                .clip(1.0, f64::INFINITY),
            Func::Abs => self.even(f64::abs, 0),
            Func::Floor | Func::Ceil | Func::Sign => {
                let r = Interval::new(math::apply(f, self.lo), math::apply(f, self.hi));
                if self.is_empty() {
                    Interval::EMPTY
                } else {
                    r
                }
            }
        }
    }

    /// Xⁿ for an integer n (even powers are ≥ 0; 0⁰ = 1; a negative power of an interval
    /// holding 0 is the whole line).
    pub fn powi(self, n: i32) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        if n == 0 {
            return Interval::point(1.0);
        }
        let m = n.unsigned_abs();
        let p = |x: f64| math::powu(x, m);
        let pos = if m.is_multiple_of(2) {
            self.even(p, 2).clip(0.0, f64::INFINITY)
        } else {
            self.monotone(p, true)
        };
        if n > 0 {
            pos
        } else {
            Interval::point(1.0) / pos
        }
    }

    /// Xʳ for a real r that is not an integer: IEEE `pow` on the part of X in the domain
    /// (x ≥ 0; 0ʳ = 0 for r > 0, ∞ for r < 0), increasing for r > 0, decreasing for r < 0.
    pub fn powf(self, r: f64) -> Interval {
        let x = self.clip(0.0, f64::INFINITY);
        x.monotone(|x| math::pow_const(x, r), r > 0.0)
            .clip(0.0, f64::INFINITY)
    }

    /// Xᴮ = e^(B ln X) on the part of X where x ≥ 0 (0⁰ = 1, 0ᵇ = 0 for b > 0).
    pub fn pow_var(self, b: Interval) -> Interval {
        let x = self.clip(0.0, f64::INFINITY);
        (b * x.apply(Func::Ln)).apply(Func::Exp)
    }
}

impl Add for Interval {
    type Output = Interval;
    /// [a + c, b + d], widened by an ulp.
    #[inline(never)]
    fn add(self, o: Interval) -> Interval {
        widen(self.lo + o.lo, self.hi + o.hi, 1)
    }
}

impl Sub for Interval {
    type Output = Interval;
    /// [a − d, b − c], widened by an ulp.
    #[inline(never)]
    fn sub(self, o: Interval) -> Interval {
        widen(self.lo - o.hi, self.hi - o.lo, 1)
    }
}

impl Neg for Interval {
    type Output = Interval;
    /// [−b, −a] (exact).
    fn neg(self) -> Interval {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl Mul for Interval {
    type Output = Interval;
    /// The hull of the four products of ends (0·∞ = 0), widened by an ulp.
    #[inline(never)]
    fn mul(self, o: Interval) -> Interval {
        if self.is_empty() || o.is_empty() {
            return Interval::EMPTY;
        }
        let p = [
            times(self.lo, o.lo),
            times(self.lo, o.hi),
            times(self.hi, o.lo),
            times(self.hi, o.hi),
        ];
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        widen(lo, hi, 1)
    }
}

impl Div for Interval {
    type Output = Interval;
    /// The hull of the four quotients of ends when 0 ∉ the divisor, widened by an ulp; the
    /// whole line when the divisor holds 0.
    #[inline(never)]
    fn div(self, o: Interval) -> Interval {
        if self.is_empty() || o.is_empty() {
            return Interval::EMPTY;
        }
        if o.contains(0.0) {
            return Interval::ENTIRE;
        }
        let q = [
            self.lo / o.lo,
            self.lo / o.hi,
            self.hi / o.lo,
            self.hi / o.hi,
        ];
        if q.iter().any(|x| x.is_nan()) {
            return Interval::ENTIRE;
        }
        let lo = q.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = q.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        widen(lo, hi, 1)
    }
}

impl Scalar for Interval {
    fn from_f64(x: f64) -> Self {
        Interval::point(x)
    }
    fn unknown() -> Self {
        Interval::ENTIRE
    }
    fn func(self, f: Func) -> Self {
        self.apply(f)
    }
    fn sin_cos(self) -> (Self, Self) {
        (self.apply(Func::Sin), self.apply(Func::Cos))
    }
    fn sinh_cosh(self) -> (Self, Self) {
        (self.apply(Func::Sinh), self.apply(Func::Cosh))
    }
    fn powi(self, n: i32) -> Self {
        Interval::powi(self, n)
    }
    fn powf(self, r: f64) -> Self {
        Interval::powf(self, r)
    }
    fn pow_var(self, b: Self) -> Self {
        Interval::pow_var(self, b)
    }
    /// ±1 when the value's enclosure keeps one sign, else [−1, 1].
    fn abs_sign(a: &[Self]) -> (Self, usize) {
        let s = match a.first() {
            Some(x) if x.lo > 0.0 => 1.0,
            Some(x) if x.hi < 0.0 => -1.0,
            _ => return (Interval::new(-1.0, 1.0), a.len()),
        };
        (Interval::point(s), a.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    fn iv(lo: f64, hi: f64) -> Interval {
        Interval::new(lo, hi)
    }

    #[test]
    fn arithmetic_rounds_outward_by_one_ulp() {
        assert_eq!(
            iv(1.0, 2.0) + iv(1.0, 1.0),
            iv(2f64.next_down(), 3f64.next_up())
        );
        assert_eq!(
            iv(1.0, 2.0) - iv(0.0, 1.0),
            iv(0f64.next_down(), 2f64.next_up())
        );
        assert_eq!(-iv(1.0, 2.0), iv(-2.0, -1.0));
        let p = iv(-2.0, 3.0) * iv(-1.0, 4.0);
        assert_eq!(p, iv((-8f64).next_down(), 12f64.next_up()));
        assert_eq!(
            iv(0.0, 0.0) * Interval::ENTIRE,
            iv(0f64.next_down(), 0f64.next_up())
        );
        let q = iv(1.0, 2.0) / iv(4.0, 8.0);
        assert_eq!(q, iv(0.125f64.next_down(), 0.5f64.next_up()));
        assert_eq!(iv(1.0, 2.0) / iv(-1.0, 1.0), Interval::ENTIRE);
        assert!((Interval::EMPTY + iv(1.0, 2.0)).is_empty());
        assert!((Interval::EMPTY * iv(1.0, 2.0)).is_empty());
        assert!(iv(2.0, 1.0).is_empty() && !iv(1.0, 1.0).is_empty());
        for f in Func::ALL {
            assert!(Interval::EMPTY.apply(f).is_empty(), "{f:?}");
        }
        assert!(Interval::EMPTY.powi(2).is_empty() && Interval::EMPTY.powf(0.5).is_empty());
    }

    #[test]
    fn powers_know_the_sign() {
        let r = iv(-2.0, 1.0).powi(2);
        assert!(r.lo == 0.0 && r.contains(4.0) && r.hi < 4.0 + 1e-14);
        let r = iv(-2.0, -1.0).powi(3);
        assert!(r.contains(-8.0) && r.contains(-1.0) && r.hi < -1.0 + 1e-14);
        assert_eq!(iv(-5.0, 5.0).powi(0), iv(1.0, 1.0));
        assert_eq!(iv(-1.0, 1.0).powi(-1), Interval::ENTIRE);
        let r = iv(2.0, 4.0).powi(-2);
        assert!(r.contains(1.0 / 16.0) && r.contains(0.25) && r.hi < 0.25 + 1e-15);
        let r = iv(-4.0, 9.0).powf(0.5);
        assert!(r.lo == 0.0 && r.contains(3.0) && r.hi < 3.0 + 1e-14);
        assert!(iv(-4.0, -1.0).powf(0.5).is_empty());
        let r = iv(0.0, 2.0).pow_var(iv(0.0, 1.0));
        assert!(r.contains(0.0) && r.contains(1.0) && r.contains(2.0) && r.hi < 2.0 + 1e-14);
    }

    #[test]
    fn sine_and_cosine_find_their_extrema() {
        let r = iv(0.1, 3.0).apply(Func::Sin);
        assert_eq!(r.hi, 1.0);
        assert!(r.lo <= 0.1f64.sin() && r.lo > 0.1f64.sin() - 1e-15);
        let r = iv(3.0, 3.5).apply(Func::Cos);
        assert_eq!(r.lo, -1.0);
        assert!(r.hi >= 3.5f64.cos().max(3f64.cos()) && r.hi < -0.93);
        // Without an extremum: the endpoints.
        let r = iv(0.2, 0.3).apply(Func::Sin);
        assert!(
            r.contains(0.2f64.sin()) && r.contains(0.3f64.sin()) && r.hi < 0.3f64.sin() + 1e-15
        );
        assert_eq!(iv(0.0, 7.0).apply(Func::Cos), iv(-1.0, 1.0));
        // A maximum just at an end (2π·1000) is not missed.
        let x = 2000.0 * PI;
        assert_eq!(iv(x, x + 0.5).apply(Func::Cos).hi, 1.0);
        assert_eq!(iv(-3.0 * FRAC_PI_2, 0.0).apply(Func::Sin).hi, 1.0);
    }

    #[test]
    fn the_other_functions_respect_domain_and_monotonicity() {
        assert_eq!(iv(1.0, 2.0).apply(Func::Tan), Interval::ENTIRE);
        assert!(iv(-1.0, 1.0).apply(Func::Tan).contains(1f64.tan()));
        assert!(!iv(-1.0, 1.0).holds_tan_pole() && iv(4.0, 5.0).holds_tan_pole());
        let r = iv(-1.0, 1.0).apply(Func::Ln);
        assert!(r.lo == f64::NEG_INFINITY && r.contains(0.0) && r.hi < 1e-15);
        assert!(iv(-3.0, -2.0).apply(Func::Sqrt).is_empty());
        let r = iv(0.5, 2.0).apply(Func::Asin);
        assert!(r.contains(FRAC_PI_2) && r.contains(0.5f64.asin()) && r.hi < FRAC_PI_2 + 1e-15);
        let r = iv(-1.0, 2.0).apply(Func::Cosh);
        assert!(r.lo == 1.0 && r.contains(2f64.cosh()) && r.hi < 2f64.cosh() + 1e-14);
        assert_eq!(iv(-3.0, 2.0).apply(Func::Abs), iv(0.0, 3.0));
        assert_eq!(iv(-0.5, 2.5).apply(Func::Floor), iv(-1.0, 2.0));
        assert_eq!(iv(-0.5, 0.0).apply(Func::Sign), iv(-1.0, 0.0));
        let r = iv(-1.0, 0.0).apply(Func::Acos);
        assert!(r.contains(PI) && r.contains(FRAC_PI_2) && r.lo > FRAC_PI_2 - 1e-15);
    }
}
