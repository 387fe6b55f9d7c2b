//! Arc length by adaptive Gauss–Legendre quadrature of the speed `|P'|`, split at cusps.

use super::{de_casteljau_point, differences, power_coefficients, BezierCurve};
use crate::error::{check_tolerance, Result};
use crate::geom::Cartesian;
use std::sync::OnceLock;

/// Number of Gauss–Legendre nodes per interval.
const GAUSS_NODES: usize = 16;
/// Deepest bisection of the parameter interval in the adaptive quadrature.
const MAX_QUADRATURE_DEPTH: u32 = 40;
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

/// The speed `|P'(s)|` of a curve in its local parameter, with the hodograph's points computed
/// once: by Horner's rule on the power-basis velocity for polynomial curves, and by the
/// quotient rule `P' = (A' − w' P)/w` on homogeneous de Casteljau for rational ones.
struct Speed<'a, C: Cartesian> {
    curve: &'a BezierCurve<C>,
    /// Homogeneous hodograph points `n (P^w_{i+1} − P^w_i)`.
    first: Vec<C::Homogeneous>,
    /// Polynomial curves: `P'(s) = Σ_k velocity[k] s^k`.
    velocity: Vec<C>,
    scratch: Vec<C::Homogeneous>,
}

impl<'a, C: Cartesian> Speed<'a, C> {
    fn new(curve: &'a BezierCurve<C>) -> Self {
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
        }
    }

    #[inline]
    fn at(&mut self, s: f64) -> f64 {
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
    fn gauss(&mut self, lo: f64, hi: f64) -> f64 {
        let (half, mid) = (0.5 * (hi - lo), 0.5 * (hi + lo));
        gauss_legendre()
            .iter()
            .map(|&(x, w)| w * self.at(mid + half * x))
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
}

impl<C: Cartesian> BezierCurve<C> {
    /// The arc length `∫ |P'(t)| dt` over the curve's interval, with absolute error at most
    /// `accuracy` (default `1e-13 ×` the control polygon's length, which is never less than
    /// the arc length).
    ///
    /// Adaptive 16-point Gauss–Legendre quadrature: an interval is halved until the two halves
    /// agree with the whole to the interval's share of the accuracy, at most 40 levels deep. At
    /// a cusp `|P'|` has a kink; the intervals around it keep halving, and the error of a kinked
    /// interval shrinks with the square of its width, so the depth cap is reached with an
    /// error far below the accuracy (checked against the closed form of `(t², t³)`). Polynomial
    /// curves evaluate the speed by Horner's rule on the power-basis velocity.
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
        let mut k = Speed::new(self);
        let whole = k.gauss(0.0, 1.0);
        Ok(k.adaptive(0.0, 1.0, whole, accuracy, 0))
    }
}

/// Arc lengths of many Bézier curves of one degree, given back to back as flat coordinates
/// (`(degree + 1)·DIM` numbers per curve), each to `accuracy` (default as
/// [`BezierCurve::arc_length`]). One call for a whole batch; the scratch buffers are shared.
///
/// # Errors
/// [`crate::Error::Mismatch`] when the coordinates do not split into whole curves, and the
/// errors of [`BezierCurve::new`] naming the first bad curve.
pub fn arc_lengths<C: Cartesian>(
    coords: &[f64],
    degree: usize,
    accuracy: Option<f64>,
) -> Result<Vec<f64>> {
    let per_curve = (degree + 1) * C::DIM;
    if degree == 0 || coords.is_empty() || !coords.len().is_multiple_of(per_curve) {
        return Err(crate::Error::Mismatch {
            message: format!(
                "{} coordinates do not split into curves of degree {degree} ((degree + 1)·dim = {per_curve} numbers each)",
                coords.len()
            ),
        });
    }
    coords
        .chunks_exact(per_curve)
        .map(|c| BezierCurve::<C>::from_flat(c, None)?.arc_length(accuracy))
        .collect()
}
