//! Adaptive Gauss–Legendre quadrature of the speed `|P'(s)|`, for any Bézier curve.

use crate::bezier::{de_casteljau_point, differences, power_coefficients, BezierCurve};
use crate::geom::Cartesian;
use std::sync::OnceLock;

/// Number of Gauss–Legendre nodes per interval.
pub(super) const GAUSS_NODES: usize = 16;
/// Deepest bisection of the parameter interval in the adaptive quadrature.
pub(super) const MAX_QUADRATURE_DEPTH: u32 = 40;
/// Most intervals the adaptive quadrature refines for one curve. An accuracy below what
/// rounding allows would otherwise keep every interval halving to the depth cap (2^40 of
/// them: a frozen page); past the budget the remaining intervals keep their two-half
/// estimate.
pub(super) const MAX_QUADRATURE_INTERVALS: usize = 1 << 14;

/// Newton steps for one Gauss–Legendre node: from the asymptotic guess the iteration converges
/// quadratically in ~4 steps for the rule sizes used (≤ 64 points); the loop stops at
/// `|dx| < 1e-16` or after this many.
const LEGENDRE_NEWTON_STEPS: u32 = 100;

/// Node `i` (largest first) and its weight of the `n`-point Gauss–Legendre rule on `[-1, 1]`:
/// Newton's method on the Legendre polynomial `P_n` (three-term recurrence) from the
/// asymptotic guess `cos(π(i + 3/4)/(n + 1/2))`.
pub(super) fn legendre_node(n: usize, i: usize) -> (f64, f64) {
    let mut x = crate::geom::sin_cos(std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).1;
    let mut dp = 1.0;
    for _ in 0..LEGENDRE_NEWTON_STEPS {
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
    (x, 2.0 / ((1.0 - x * x) * dp * dp))
}

/// Gauss–Legendre nodes and weights on `[-1, 1]` for the adaptive method, computed once.
pub(super) fn gauss_legendre() -> &'static [(f64, f64); GAUSS_NODES] {
    static NODES: OnceLock<[(f64, f64); GAUSS_NODES]> = OnceLock::new();
    NODES.get_or_init(|| std::array::from_fn(|i| legendre_node(GAUSS_NODES, i)))
}

/// The speed `|P'(s)|` of a curve in its local parameter, with the hodograph's points computed
/// once: by Horner's rule on the power-basis velocity for polynomial curves, and by the
/// quotient rule `P' = (A' − w' P)/w` on homogeneous de Casteljau for rational ones.
pub(super) struct Speed<'a, C: Cartesian> {
    curve: &'a BezierCurve<C>,
    /// Homogeneous hodograph points `n (P^w_{i+1} − P^w_i)`.
    first: Vec<C::Homogeneous>,
    /// Polynomial curves: `P'(s) = Σ_k velocity[k] s^k`.
    velocity: Vec<C>,
    scratch: Vec<C::Homogeneous>,
    /// Intervals the adaptive quadrature may still refine.
    budget: usize,
}

impl<'a, C: Cartesian> Speed<'a, C> {
    pub(super) fn new(curve: &'a BezierCurve<C>) -> Self {
        let n = curve.degree() as f64;
        let first: Vec<_> = differences(&curve.homogeneous)
            .into_iter()
            .map(|d| d * n)
            .collect();
        let velocity = if curve.rational {
            Vec::new()
        } else {
            power_coefficients(&first)
                .into_iter()
                .map(C::numerator)
                .collect()
        };
        Speed {
            curve,
            first,
            velocity,
            scratch: Vec::new(),
            budget: MAX_QUADRATURE_INTERVALS,
        }
    }

    #[inline]
    pub(super) fn at(&mut self, s: f64) -> f64 {
        if !self.curve.rational {
            return self
                .velocity
                .iter()
                .rev()
                .fold(C::ZERO, |acc, &c| acc * s + c)
                .norm();
        }
        let d1 = de_casteljau_point(&self.first, s, &mut self.scratch);
        let h = de_casteljau_point(&self.curve.homogeneous, s, &mut self.scratch);
        let w = C::weight_of(h);
        let p = C::numerator(h) * (1.0 / w);
        ((C::numerator(d1) - p * C::weight_of(d1)) * (1.0 / w)).norm()
    }

    /// Gauss–Legendre estimate of `∫ |P'| ds` over `[lo, hi]`.
    pub(super) fn gauss(&mut self, lo: f64, hi: f64) -> f64 {
        let (half, mid) = (0.5 * (hi - lo), 0.5 * (hi + lo));
        gauss_legendre()
            .iter()
            .map(|&(x, w)| w * self.at(mid + half * x))
            .sum::<f64>()
            * half
    }

    pub(super) fn adaptive(
        &mut self,
        lo: f64,
        hi: f64,
        whole: f64,
        accuracy: f64,
        depth: u32,
    ) -> f64 {
        let mid = 0.5 * (lo + hi);
        let (left, right) = (self.gauss(lo, mid), self.gauss(mid, hi));
        // Halving cannot resolve differences at the rounding level of the interval's own
        // integral; the budget is the last guard.
        let floor = 16.0 * f64::EPSILON * (left + right);
        if depth >= MAX_QUADRATURE_DEPTH
            || self.budget == 0
            || (left + right - whole).abs() <= accuracy.max(floor)
        {
            return left + right;
        }
        self.budget -= 1;
        self.adaptive(lo, mid, left, 0.5 * accuracy, depth + 1)
            + self.adaptive(mid, hi, right, 0.5 * accuracy, depth + 1)
    }
}
