//! Arc length by adaptive Gauss–Legendre quadrature of the speed `|P'|`, split at cusps.

use super::{de_casteljau_point, differences, BezierCurve};
use crate::error::{check_tolerance, Result};
use crate::geom::{Cartesian, Point};
use std::sync::OnceLock;

/// Number of Gauss–Legendre nodes per interval.
const GAUSS_NODES: usize = 16;
/// Deepest bisection of the parameter interval in the adaptive quadrature.
const MAX_QUADRATURE_DEPTH: u32 = 40;
/// Samples of `P'·P''` used to bracket the minima of the speed (cusp candidates).
const CUSP_SCAN: usize = 64;
/// Default accuracy, relative to the control polygon's length (which bounds the arc length
/// from above).
pub const DEFAULT_RELATIVE_ACCURACY: f64 = 1e-13;

/// Gauss–Legendre nodes and weights on `[-1, 1]`, computed once by Newton's method on the
/// Legendre polynomial `P_N` (three-term recurrence).
fn gauss_legendre() -> &'static [(f64, f64); GAUSS_NODES] {
    static NODES: OnceLock<[(f64, f64); GAUSS_NODES]> = OnceLock::new();
    NODES.get_or_init(|| {
        let n = GAUSS_NODES;
        let mut out = [(0.0, 0.0); GAUSS_NODES];
        for (i, slot) in out.iter_mut().enumerate() {
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            *slot = (x, 2.0 / ((1.0 - x * x) * dp * dp));
        }
        out
    })
}

/// The velocity and acceleration of a curve in its local parameter, with the difference
/// points computed once.
struct Kinematics<'a, C: Cartesian> {
    curve: &'a BezierCurve<C>,
    first: Vec<C::Homogeneous>,
    second: Vec<C::Homogeneous>,
    scratch: Vec<C::Homogeneous>,
}

impl<'a, C: Cartesian> Kinematics<'a, C> {
    fn new(curve: &'a BezierCurve<C>) -> Self {
        let n = curve.degree() as f64;
        let first: Vec<_> = differences(&curve.homogeneous)
            .into_iter()
            .map(|d| d * n)
            .collect();
        let second: Vec<_> = if first.len() > 1 {
            differences(&first)
                .into_iter()
                .map(|d| d * (n - 1.0))
                .collect()
        } else {
            vec![C::Homogeneous::ZERO]
        };
        Kinematics {
            curve,
            first,
            second,
            scratch: Vec::new(),
        }
    }

    /// `(P'(s), P''(s))` with respect to the local parameter.
    fn eval(&mut self, s: f64) -> (C, C) {
        let d1 = de_casteljau_point(&self.first, s, &mut self.scratch);
        let d2 = de_casteljau_point(&self.second, s, &mut self.scratch);
        if !self.curve.rational {
            return (C::numerator(d1), C::numerator(d2));
        }
        let h = de_casteljau_point(&self.curve.homogeneous, s, &mut self.scratch);
        let w = C::weight_of(h);
        let p = C::numerator(h) * (1.0 / w);
        let v = (C::numerator(d1) - p * C::weight_of(d1)) * (1.0 / w);
        let a =
            (C::numerator(d2) - v * (2.0 * C::weight_of(d1)) - p * C::weight_of(d2)) * (1.0 / w);
        (v, a)
    }

    fn speed(&mut self, s: f64) -> f64 {
        self.eval(s).0.norm()
    }

    /// Gauss–Legendre estimate of `∫ |P'| ds` over `[lo, hi]`.
    fn gauss(&mut self, lo: f64, hi: f64) -> f64 {
        let (half, mid) = (0.5 * (hi - lo), 0.5 * (hi + lo));
        gauss_legendre()
            .iter()
            .map(|&(x, w)| w * self.speed(mid + half * x))
            .sum::<f64>()
            * half
    }

    fn adaptive(&mut self, lo: f64, hi: f64, whole: f64, accuracy: f64, depth: u32) -> f64 {
        let mid = 0.5 * (lo + hi);
        let (left, right) = (self.gauss(lo, mid), self.gauss(mid, hi));
        if depth >= MAX_QUADRATURE_DEPTH || (left + right - whole).abs() <= accuracy {
            return left + right;
        }
        self.adaptive(lo, mid, left, 0.5 * accuracy, depth + 1)
            + self.adaptive(mid, hi, right, 0.5 * accuracy, depth + 1)
    }

    /// Parameters in `(0, 1)` where the speed has a local minimum: they include the cusps,
    /// where `|P'|` has a kink that quadrature must not straddle (splitting at a harmless
    /// minimum costs nothing). Found as sign changes from − to + of `P'·P''` (half the
    /// derivative of the squared speed), bisected to machine precision.
    fn speed_minima(&mut self) -> Vec<f64> {
        let mut out = Vec::new();
        let f = |k: &mut Self, s: f64| {
            let (v, a) = k.eval(s);
            v.dot_with(a)
        };
        let mut prev = (0.0, f(self, 0.0));
        for i in 1..=CUSP_SCAN {
            let s = i as f64 / CUSP_SCAN as f64;
            let cur = (s, f(self, s));
            if prev.1 < 0.0 && cur.1 >= 0.0 {
                let (mut a, mut b) = (prev.0, cur.0);
                while 0.5 * (a + b) > a && 0.5 * (a + b) < b {
                    let m = 0.5 * (a + b);
                    if f(self, m) < 0.0 {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                let s_min = if self.speed(a) <= self.speed(b) { a } else { b };
                if s_min > 0.0 && s_min < 1.0 {
                    out.push(s_min);
                }
            }
            prev = cur;
        }
        out
    }
}

impl<C: Cartesian> BezierCurve<C> {
    /// The arc length `∫ |P'(t)| dt` over the curve's interval, with absolute error at most
    /// `accuracy` (default `1e-13 ×` the control polygon's length, which is never less than
    /// the arc length).
    ///
    /// Adaptive 16-point Gauss–Legendre quadrature: an interval is halved until the two halves
    /// agree with the whole to the interval's share of the accuracy (depth at most 40). The
    /// minima of the speed are located first and become interval ends, since at a cusp `|P'|`
    /// has a kink that would otherwise stall the convergence.
    ///
    /// # Errors
    /// [`crate::Error::InvalidTolerance`] for an accuracy that is not finite and > 0.
    pub fn arc_length(&self, accuracy: Option<f64>) -> Result<f64> {
        let cps = self.control_points();
        let polygon: f64 = cps.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
        let accuracy = match accuracy {
            Some(a) => check_tolerance(a)?,
            None => DEFAULT_RELATIVE_ACCURACY * polygon,
        };
        if polygon == 0.0 {
            return Ok(0.0);
        }
        let mut k = Kinematics::new(self);
        let mut breaks = vec![0.0];
        breaks.extend(k.speed_minima());
        breaks.push(1.0);
        let mut total = 0.0;
        for w in breaks.windows(2) {
            let share = accuracy * (w[1] - w[0]);
            let whole = k.gauss(w[0], w[1]);
            total += k.adaptive(w[0], w[1], whole, share, 0);
        }
        Ok(total)
    }
}
