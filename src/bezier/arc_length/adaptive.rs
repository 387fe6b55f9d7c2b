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
/// Fewest intervals the budget allows, whatever the degree.
const MIN_QUADRATURE_INTERVALS: usize = 1 << 8;
/// The work budget behind the interval budget, in units of one control-point operation per
/// speed evaluation: a speed evaluation costs `n + 1` of them for a polynomial curve (Horner)
/// and `(n + 1)²` for a rational one (de Casteljau), so a rational cubic keeps all
/// [`MAX_QUADRATURE_INTERVALS`] and a degree-40 rational curve 256 (the API fuzz found one
/// spending 12 s on an accuracy below its rounding).
const QUADRATURE_WORK: usize = MAX_QUADRATURE_INTERVALS * 16;

/// The interval budget of a curve of degree `n`: [`QUADRATURE_WORK`] over the cost of one speed
/// evaluation, between [`MIN_QUADRATURE_INTERVALS`] and [`MAX_QUADRATURE_INTERVALS`].
pub(super) fn interval_budget(n: usize, rational: bool) -> usize {
    let cost = if rational {
        (n + 1).saturating_mul(n + 1)
    } else {
        n + 1
    };
    (QUADRATURE_WORK / cost.max(1)).clamp(MIN_QUADRATURE_INTERVALS, MAX_QUADRATURE_INTERVALS)
}

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
            budget: interval_budget(curve.degree(), curve.rational),
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
        // A NaN or infinite estimate (coordinates near f64::MAX overflow the speed) never
        // converges: refining it would only spend the whole budget to return the same.
        if !(left + right).is_finite()
            || depth >= MAX_QUADRATURE_DEPTH
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

#[cfg(test)]
mod tests {
    use super::{interval_budget, Speed, MAX_QUADRATURE_INTERVALS};
    use crate::bezier::BezierCurve;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;
    use glam::DVec2;

    #[test]
    fn an_overflowing_speed_does_not_spend_the_refinement_budget() {
        // Finite control points and weights whose homogeneous products overflow (coordinates
        // within MAX_COORDINATE, a weight of 1e200): the speed is infinite, the estimates NaN or
        // ∞, and no halving can make them agree (the API fuzz found this spending all 2^14
        // intervals of a degree-23 rational curve: 2 s for a NaN).
        let curve = BezierCurve::new(
            vec![
                DVec2::new(-1e120, 0.0),
                DVec2::new(1e120, 1.0),
                DVec2::new(-1e120, 2.0),
                DVec2::new(1e120, 0.0),
            ],
            Some(&[1.0, 1e200, 0.5, 1.0]),
        )
        .unwrap();
        let mut speed = Speed::new(&curve);
        let whole = speed.gauss(0.0, 1.0);
        let length = speed.adaptive(0.0, 1.0, whole, 1e-9, 0);
        assert!(!length.is_finite(), "{length}");
        assert_eq!(speed.budget, interval_budget(3, true), "intervals refined");
    }

    #[test]
    fn the_interval_budget_shrinks_with_the_cost_of_a_speed_evaluation() {
        // A degree-40 rational curve (3D, coordinates up to 1e17) with an absolute accuracy of
        // 1e-3, far below its rounding: every interval keeps halving until the budget is spent.
        let points: Vec<glam::DVec3> = (0..41)
            .map(|i| {
                let x = i as f64;
                let big = if i % 7 == 3 { 8e16 } else { 0.0 };
                glam::DVec3::new(60.0 * (x * 1.3).sin() + big, 50.0 * (x * 0.7).cos(), x)
            })
            .collect();
        let weights: Vec<f64> = (0..41).map(|i| 1.0 + 0.8 * f64::from(i % 3 == 1)).collect();
        let curve = BezierCurve::new(points, Some(&weights)).unwrap();
        let mut speed = Speed::new(&curve);
        let budget = speed.budget;
        let whole = speed.gauss(0.0, 1.0);
        let length = speed.adaptive(0.0, 1.0, whole, 1e-3, 0);
        assert!(length.is_finite() && length > 8e16, "{length}");
        // Refined at most 256 intervals (16 384 before: 12 s in Node), and the work budget
        // (intervals × control-point operations per speed evaluation) holds for every degree.
        assert!(
            budget - speed.budget <= 256,
            "{} intervals",
            budget - speed.budget
        );
        for n in 1..=64 {
            for (rational, cost) in [(false, n + 1), (true, (n + 1) * (n + 1))] {
                let b = interval_budget(n, rational);
                assert!(b == 256 || b * cost <= (1 << 18), "degree {n}: {b}");
                assert!(
                    b == MAX_QUADRATURE_INTERVALS || b * cost > (1 << 17),
                    "degree {n}: {b}"
                );
            }
        }
        assert_eq!(interval_budget(3, true), MAX_QUADRATURE_INTERVALS);
    }
}
