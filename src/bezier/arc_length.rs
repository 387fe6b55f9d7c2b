//! Arc length `∫ |P'(t)| dt`: singularity-aware Gauss–Legendre for 2D polynomial curves of
//! degree ≤ 3 (the speed's singularities are known in closed form), and adaptive
//! Gauss–Legendre quadrature of the speed for everything else.

use super::{de_casteljau_point, differences, power_coefficients, BezierCurve};
use crate::error::{check_tolerance, Result};
use crate::geom::check_all_finite;
use crate::geom::Cartesian;
use glam::DVec2;
use std::sync::OnceLock;

/// Number of Gauss–Legendre nodes per interval.
const GAUSS_NODES: usize = 16;
/// Deepest bisection of the parameter interval in the adaptive quadrature.
const MAX_QUADRATURE_DEPTH: u32 = 40;
/// Most intervals the adaptive quadrature refines for one curve. An accuracy below what
/// rounding allows would otherwise keep every interval halving to the depth cap (2^40 of
/// them: a frozen page); past the budget the remaining intervals keep their two-half
/// estimate.
const MAX_QUADRATURE_INTERVALS: usize = 1 << 14;
/// Default accuracy, relative to the control polygon's length (which bounds the arc length
/// from above).
pub const DEFAULT_RELATIVE_ACCURACY: f64 = 1e-13;

/// Node `i` (largest first) and its weight of the `n`-point Gauss–Legendre rule on `[-1, 1]`:
/// Newton's method on the Legendre polynomial `P_n` (three-term recurrence) from the
/// asymptotic guess `cos(π(i + 3/4)/(n + 1/2))`.
fn legendre_node(n: usize, i: usize) -> (f64, f64) {
    let mut x = crate::geom::sin_cos(std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).1;
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
    (x, 2.0 / ((1.0 - x * x) * dp * dp))
}

/// Gauss–Legendre nodes and weights on `[-1, 1]` for the adaptive method, computed once.
fn gauss_legendre() -> &'static [(f64, f64); GAUSS_NODES] {
    static NODES: OnceLock<[(f64, f64); GAUSS_NODES]> = OnceLock::new();
    NODES.get_or_init(|| std::array::from_fn(|i| legendre_node(GAUSS_NODES, i)))
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
    /// Intervals the adaptive quadrature may still refine.
    budget: usize,
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
            budget: MAX_QUADRATURE_INTERVALS,
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

// ---- 2D polynomial curves of degree ≤ 3: singularity-aware Gauss–Legendre ----------------------

/// Relative error guaranteed by the fast path for 2D polynomial curves of degree ≤ 3 (see
/// [`BezierCurve::arc_length`]). The arc length is at most the control polygon's length, so the
/// fast path is used when the caller's absolute accuracy is at least this times the polygon's
/// length (the default accuracy is exactly that).
pub const FAST_PATH_RELATIVE_ERROR: f64 = DEFAULT_RELATIVE_ACCURACY;

/// Positive halves of the symmetric Gauss–Legendre rules on `[−1, 1]`: `(x_i, w_i)` with
/// `x_i > 0`; the node `−x_i` has the same weight. Newton's method on `P_n` in 40-digit
/// arithmetic (tests/fixtures/arc_length_thresholds.py), rounded to double; checked in the
/// tests against the f64 Newton iteration above and against exact integrals of monomials.
const GL8: [(f64, f64); 4] = [
    (0.9602898564975363, 0.10122853629037626),
    (0.7966664774136267, 0.22238103445337448),
    (0.525532409916329, 0.31370664587788727),
    (0.1834346424956498, 0.362683783378362),
];
const GL12: [(f64, f64); 6] = [
    (0.9815606342467192, 0.04717533638651183),
    (0.9041172563704749, 0.10693932599531843),
    (0.7699026741943047, 0.16007832854334622),
    (0.5873179542866175, 0.20316742672306592),
    (0.3678314989981802, 0.2334925365383548),
    (0.1252334085114689, 0.24914704581340277),
];
const GL16: [(f64, f64); 8] = [
    (0.9894009349916499, 0.027152459411754096),
    (0.9445750230732326, 0.062253523938647894),
    (0.8656312023878318, 0.09515851168249279),
    (0.755404408355003, 0.12462897125553388),
    (0.6178762444026438, 0.14959598881657674),
    (0.45801677765722737, 0.16915651939500254),
    (0.2816035507792589, 0.18260341504492358),
    (0.09501250983763744, 0.1894506104550685),
];
const GL24: [(f64, f64); 12] = [
    (0.9951872199970213, 0.0123412297999872),
    (0.9747285559713095, 0.028531388628933663),
    (0.9382745520027328, 0.04427743881741981),
    (0.8864155270044011, 0.05929858491543678),
    (0.820001985973903, 0.0733464814110803),
    (0.7401241915785544, 0.08619016153195327),
    (0.6480936519369755, 0.09761865210411388),
    (0.5454214713888396, 0.10744427011596563),
    (0.4337935076260451, 0.1155056680537256),
    (0.3150426796961634, 0.12167047292780339),
    (0.1911188674736163, 0.1258374563468283),
    (0.06405689286260563, 0.12793819534675216),
];

/// Smallest Bernstein-ellipse parameter `ρ` of the nearest singularity for which GL8, GL12,
/// GL16 and GL24 are used on a piece. `n`-point Gauss–Legendre errs like `C ρ^(−2n)`;
/// tests/fixtures/arc_length_thresholds.py measures the worst relative error over integrands
/// `|t − ζ|`, `|t − ζ|(1 + t)` and `|t − ζ1||t − ζ2|` (ζ on the ellipses `E_ρ`, `E_ρ2`, `ρ2 ≥ ρ`,
/// at 48 angles each) and finds it ≤ 1e-14 from ρ = 6.70, 3.44, 2.47 and 1.77 on. These are
/// those values times 1.1, which divides the error by `1.1^(2n)` (≥ 4.5 for GL8, 98 for GL24).
pub const RULE_RHO: [f64; 4] = [7.4, 3.8, 2.75, 1.95];

/// A root with `|Im r| ≤ NEAR_REAL` (in units of the curve's local parameter on `[0, 1]`) is
/// treated as real: `|t − r| = √((t − x)² + y²)` is replaced by `|t − x|`, which is linear on
/// either side of `x`. The pieces are split exactly at `x`, so the root sits at a piece's end
/// (or outside it) and is no singularity of the piece's integrand. The neglected part is at most
/// `y²/(2|t − x|)` pointwise and `~ y² (1 + ln(1/y))` integrated, `< 1e-16` relative to the
/// arc length (the factor `|t − r2|` of the other root appears in both).
const NEAR_REAL: f64 = 1e-9;
/// Roots further than this from the origin (in local-parameter units) are ignored: their `ρ`
/// on any piece of `[0, 1]` exceeds `10^6`, far above every threshold.
const FAR_ROOT: f64 = 1e6;
/// Capacity of the explicit stack of pending pieces.
const MAX_STACK: usize = 64;
/// Most pieces integrated for one curve before giving up and using the adaptive method. A
/// root at distance `d` from `[0, 1]` costs about `log4(1/d)` pieces of geometric grading on
/// each side, and `d ≥ NEAR_REAL` unless the root is treated as real, so ~40 pieces is the
/// worst case in exact arithmetic.
const MAX_PIECES: usize = 200;

#[inline]
fn cmul(a: DVec2, b: DVec2) -> DVec2 {
    DVec2::new(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x)
}

#[inline]
fn cdiv(a: DVec2, b: DVec2) -> DVec2 {
    DVec2::new(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / b.length_squared()
}

/// Principal square root of a complex number (real part ≥ 0), without cancellation.
#[inline]
fn csqrt(z: DVec2) -> DVec2 {
    let m = z.length();
    if m == 0.0 {
        DVec2::ZERO
    } else if z.x >= 0.0 {
        let re = (0.5 * (m + z.x)).sqrt();
        DVec2::new(re, z.y / (2.0 * re))
    } else {
        let im = (0.5 * (m - z.x)).sqrt().copysign(z.y);
        DVec2::new(z.y / (2.0 * im), im)
    }
}

/// `max(|re|, |im|) > FAR_ROOT · (|re| + |im|)` of `den`: the quotient `num/den` is farther than
/// `FAR_ROOT` (or infinite).
#[inline]
fn far_quotient(num: DVec2, den: DVec2) -> bool {
    num.x.abs().max(num.y.abs()) > FAR_ROOT * (den.x.abs() + den.y.abs())
}

/// The hodograph of a 2D polynomial Bézier curve of degree ≤ 3 as a complex polynomial
/// `z'(s) = x'(s) + i y'(s) = scale · (c0 + c1 s + c2 s²)`, scaled so that its largest
/// coefficient component is 1 (so the root finding can neither overflow nor underflow).
struct PlanarSpeed {
    c0: DVec2,
    c1: DVec2,
    c2: DVec2,
    scale: f64,
}

/// Outcome of setting up a [`PlanarSpeed`].
enum Planar {
    /// The hodograph vanishes: every control point is the same, the length is 0.
    Zero,
    /// Differences of the coordinates overflow; left to the adaptive method.
    Overflow,
    /// The scaled hodograph.
    Speed(PlanarSpeed),
}

impl PlanarSpeed {
    /// From flat control points `[x0, y0, x1, y1, …]` of degree 1, 2 or 3 (finite numbers).
    /// With `D_i = P_{i+1} − P_i`, the hodograph `n Σ B_i^{n−1}(s) D_i` has the power-basis
    /// coefficients `c0 = 3D0, c1 = 6(D1 − D0), c2 = 3(D0 − 2D1 + D2)` (cubic),
    /// `c0 = 2D0, c1 = 2(D1 − D0)` (quadratic) and `c0 = D0` (line).
    fn from_flat(p: &[f64]) -> Planar {
        let point = |i: usize| match p.get(2 * i..2 * i + 2) {
            Some(&[x, y]) => DVec2::new(x, y),
            _ => DVec2::ZERO,
        };
        let d = |i: usize| point(i + 1) - point(i);
        let (c0, c1, c2) = match p.len() / 2 {
            4 => (
                3.0 * d(0),
                6.0 * (d(1) - d(0)),
                3.0 * (d(0) - 2.0 * d(1) + d(2)),
            ),
            3 => (2.0 * d(0), 2.0 * (d(1) - d(0)), DVec2::ZERO),
            _ => (d(0), DVec2::ZERO, DVec2::ZERO),
        };
        let scale = c0.abs().max(c1.abs()).max(c2.abs()).max_element();
        if !scale.is_finite() {
            return Planar::Overflow;
        }
        if scale == 0.0 {
            return Planar::Zero;
        }
        Planar::Speed(PlanarSpeed {
            c0: c0 / scale,
            c1: c1 / scale,
            c2: c2 / scale,
            scale,
        })
    }

    /// The scaled speed `|c0 + c1 s + c2 s²|` by Horner's rule.
    #[inline(always)]
    fn at(&self, s: f64) -> f64 {
        (self.c0 + s * (self.c1 + s * self.c2)).length()
    }

    /// The complex roots of `c2 s² + c1 s + c0` that are nearer than [`FAR_ROOT`]: the stable
    /// quadratic formula `q = −(c1 + σ√(c1² − 4 c2 c0))/2`, the sign σ making `Re(conj(c1)·σ√…)
    /// ≥ 0` (no cancellation), roots `q/c2` and `c0/q`. `c2 = 0` (a quadratic curve, or a cubic
    /// whose hodograph is linear) leaves the one root `c0/q = −c0/c1`; `q = 0` means `c1 = 0`
    /// and `c2 c0 = 0`: a double root at 0 (`c0 = 0`) or a constant hodograph (no root).
    fn roots(&self) -> ([DVec2; 2], usize) {
        let (c0, c1, c2) = (self.c0, self.c1, self.c2);
        let mut sq = csqrt(cmul(c1, c1) - 4.0 * cmul(c2, c0));
        if c1.dot(sq) < 0.0 {
            sq = -sq;
        }
        let q = -0.5 * (c1 + sq);
        let mut roots = [DVec2::ZERO; 2];
        let mut count = 0;
        if q == DVec2::ZERO {
            if c2 != DVec2::ZERO {
                count = 2;
            }
            return (roots, count);
        }
        for (num, den) in [(q, c2), (c0, q)] {
            if !far_quotient(num, den) {
                let r = cdiv(num, den);
                if r.is_finite() {
                    roots[count] = r;
                    count += 1;
                }
            }
        }
        (roots, count)
    }

    /// `∫ |c0 + c1 s + c2 s²| ds` over `[lo, hi]` by the Gauss–Legendre rule `nodes`.
    #[inline(always)]
    fn gauss<const N: usize>(&self, lo: f64, hi: f64, nodes: &[(f64, f64); N]) -> f64 {
        let (half, mid) = (0.5 * (hi - lo), 0.5 * (hi + lo));
        let mut sum = 0.0;
        for &(x, w) in nodes {
            sum += w * (self.at(mid - half * x) + self.at(mid + half * x));
        }
        sum * half
    }

    /// `∫_0^1 |z'(s)| ds`, or `None` when a safety limit is hit (the caller then uses the
    /// adaptive method). See [`BezierCurve::arc_length`] for the method. `evals` counts the
    /// speed evaluations (for the tests; optimised away otherwise).
    #[inline(always)]
    fn arc_length(&self, evals: &mut usize) -> Option<f64> {
        let (roots, count) = self.roots();
        let roots = roots.get(..count).unwrap_or(&[]);
        let mut stack = [(0.0, 0.0); MAX_STACK];
        stack[0] = (0.0, 1.0);
        let mut len = 1;
        let mut total = 0.0;
        for _ in 0..MAX_PIECES {
            if len == 0 {
                return Some(total * self.scale);
            }
            len -= 1;
            let (lo, hi) = stack[len];
            let h = hi - lo;
            // The nearest singularity by `|r − lo| + |r − hi| = h (ρ + 1/ρ)/2` (the ellipse
            // with foci lo, hi through r), skipping roots treated as real that are not
            // inside the piece.
            let mut nearest: Option<(f64, DVec2)> = None;
            for &r in roots {
                if r.y.abs() <= NEAR_REAL && (r.x <= lo || r.x >= hi) {
                    continue;
                }
                let sum = (r - DVec2::new(lo, 0.0)).length() + (r - DVec2::new(hi, 0.0)).length();
                if nearest.is_none_or(|(s, _)| sum < s) {
                    nearest = Some((sum, r));
                }
            }
            let foci_sum = nearest.map_or(f64::INFINITY, |(s, _)| s);
            let meets = |rho: f64| foci_sum >= 0.5 * (rho + 1.0 / rho) * h;
            if meets(RULE_RHO[0]) {
                total += self.gauss(lo, hi, &GL8);
                *evals += 8;
            } else if meets(RULE_RHO[1]) {
                total += self.gauss(lo, hi, &GL12);
                *evals += 12;
            } else if meets(RULE_RHO[2]) {
                total += self.gauss(lo, hi, &GL16);
                *evals += 16;
            } else if meets(RULE_RHO[3]) {
                total += self.gauss(lo, hi, &GL24);
                *evals += 24;
            } else {
                let (_, r) = nearest?;
                let m = if r.y.abs() <= NEAR_REAL {
                    r.x
                } else {
                    r.x.max(lo + 0.25 * h).min(hi - 0.25 * h)
                };
                if !(lo < m && m < hi) || len + 2 > MAX_STACK {
                    return None;
                }
                stack[len] = (m, hi);
                stack[len + 1] = (lo, m);
                len += 2;
            }
        }
        None
    }
}

/// Arc length of the 2D polynomial Bézier curve with flat finite control points `p` (degree
/// 1–3): `Some(0)` for a zero hodograph, `None` when the fast path gives up.
fn planar_arc_length(p: &[f64]) -> Option<f64> {
    planar_arc_length_counted(p, &mut 0)
}

#[inline(always)]
fn planar_arc_length_counted(p: &[f64], evals: &mut usize) -> Option<f64> {
    match PlanarSpeed::from_flat(p) {
        Planar::Zero => Some(0.0),
        Planar::Overflow => None,
        Planar::Speed(s) if p.len() == 4 => Some(s.c0.length() * s.scale),
        Planar::Speed(s) => s.arc_length(evals),
    }
}

/// Length of the control polygon of flat 2D points.
fn planar_polygon(p: &[f64]) -> f64 {
    p.windows(4)
        .step_by(2)
        .map(|w| match w {
            &[x0, y0, x1, y1] => ((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0)).sqrt(),
            _ => 0.0,
        })
        .sum()
}

impl<C: Cartesian> BezierCurve<C> {
    /// The arc length `∫ |P'(t)| dt` over the curve's interval, with absolute error at most
    /// `accuracy` (default `1e-13 ×` the control polygon's length, which is never less than
    /// the arc length).
    ///
    /// **2D polynomial curves of degree ≤ 3** (when `accuracy` is at least
    /// [`FAST_PATH_RELATIVE_ERROR`] × the polygon's length, as the default is): singularity-aware
    /// Gauss–Legendre. The hodograph as a complex polynomial `z'(s) = x'(s) + i y'(s) =
    /// a Π (s − r_k)` has degree ≤ 2, so for real `s` the speed is `|a| Π |s − r_k|`, analytic
    /// except at the roots `r_k` and their conjugates (for a cubic, from one complex quadratic
    /// formula). `n`-point Gauss–Legendre on a piece `[lo, hi]` converges like `ρ^(−2n)`, `ρ`
    /// the Bernstein-ellipse parameter of the nearest root: with `ζ = (r − mid)/half`,
    /// `ρ = s + √(s² − 1)` where `s = (|ζ − 1| + |ζ + 1|)/2`. Starting from `[0, 1]`, a piece is
    /// integrated by the cheapest of GL8, GL12, GL16, GL24 whose threshold [`RULE_RHO`] `ρ`
    /// meets (calibrated to a relative error ≤ 1e-14 per piece, with margin); otherwise it is
    /// split at the nearest root's real part `x`, clamped to `[lo + h/4, hi − h/4]`, which grades
    /// the pieces geometrically toward a root near an end (a piece `[d, 4d]` away from a real
    /// root has `ρ ≥ 3`). A root with `|Im r| ≤ 1e-9` is treated as real: the split is exactly at
    /// `x` and the root is then no singularity of either side, so an exact cusp costs two pieces.
    /// Relative errors of the pieces bound the relative error of their sum (all positive), so
    /// the result is within 1e-13 relative. Random cubics in a square (the benchmark's) take ~70
    /// speed evaluations in ~6 pieces: their nearest root is typically close to `[0, 1]`;
    /// the work is bounded (at most 200 pieces, a stack of 64), and the adaptive method below
    /// takes over if a limit is reached.
    ///
    /// **Other curves** (3D, rational, degree ≥ 4, or a tighter accuracy):
    /// [`BezierCurve::arc_length_adaptive`].
    ///
    /// # Errors
    /// [`crate::Error::InvalidTolerance`] for an accuracy that is not finite and > 0.
    pub fn arc_length(&self, accuracy: Option<f64>) -> Result<f64> {
        let accuracy = accuracy.map(check_tolerance).transpose()?;
        if let Some((flat, len)) = self.planar_flat() {
            let p = flat.get(..len).unwrap_or(&[]);
            if accuracy.is_none_or(|a| a >= FAST_PATH_RELATIVE_ERROR * planar_polygon(p)) {
                if let Some(l) = planar_arc_length(p) {
                    return Ok(l);
                }
            }
        }
        self.arc_length_adaptive(accuracy)
    }

    /// Flat control points of a 2D polynomial curve of degree ≤ 3 and their count.
    fn planar_flat(&self) -> Option<([f64; 8], usize)> {
        let n = self.degree();
        if C::DIM != 2 || self.rational || n > 3 {
            return None;
        }
        let mut flat = [0.0; 8];
        for (i, p) in self.control_points().iter().enumerate() {
            if let Some(xy) = flat.get_mut(2 * i..2 * i + 2) {
                xy.copy_from_slice(&[p.coord(0), p.coord(1)]);
            }
        }
        Some((flat, 2 * (n + 1)))
    }

    /// The arc length by the general method, for any curve: adaptive 16-point Gauss–Legendre
    /// quadrature of the speed, with absolute error at most `accuracy` (default as
    /// [`BezierCurve::arc_length`]).
    ///
    /// An interval is halved until the two halves agree with the whole to the interval's share
    /// of the accuracy, at most 40 levels deep. At a cusp `|P'|` has a kink; the intervals
    /// around it keep halving, and the error of a kinked interval shrinks with the square of its
    /// width, so the depth cap is reached with an error far below the accuracy (checked against
    /// the closed form of `(t², t³)`). Polynomial curves evaluate the speed by Horner's rule on
    /// the power-basis velocity, rational ones by the quotient rule on homogeneous de Casteljau.
    ///
    /// # Errors
    /// [`crate::Error::InvalidTolerance`] for an accuracy that is not finite and > 0.
    pub fn arc_length_adaptive(&self, accuracy: Option<f64>) -> Result<f64> {
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
/// [`BezierCurve::arc_length`]). One call for a whole batch.
///
/// 2D curves of degree ≤ 3 take the fast path of [`BezierCurve::arc_length`] straight from the
/// numbers (no curve object, no allocation per curve); the results are identical to
/// `BezierCurve::arc_length` on each curve.
///
/// # Errors
/// [`crate::Error::CurveBatchLength`] when the coordinates do not split into whole curves, and the
/// errors of [`BezierCurve::from_flat`] and [`BezierCurve::arc_length`] for the first bad curve
/// (a coordinate is named by its index within its curve, as `from_flat` does).
pub fn arc_lengths<C: Cartesian>(
    coords: &[f64],
    degree: usize,
    accuracy: Option<f64>,
) -> Result<Vec<f64>> {
    let per_curve = (degree + 1) * C::DIM;
    if degree == 0 || coords.is_empty() || !coords.len().is_multiple_of(per_curve) {
        return Err(crate::Error::CurveBatchLength {
            count: coords.len(),
            degree,
            per_curve,
        });
    }
    if C::DIM != 2 || degree > 3 {
        return coords
            .chunks_exact(per_curve)
            .map(|c| BezierCurve::<C>::from_flat(c, None)?.arc_length(accuracy))
            .collect();
    }
    let mut out = Vec::with_capacity(coords.len() / per_curve);
    for p in coords.chunks_exact(per_curve) {
        // The checks of `from_flat` then `arc_length`, in their order.
        check_all_finite(p, "coordinate")?;
        let accuracy = accuracy.map(check_tolerance).transpose()?;
        let fast = accuracy.is_none_or(|a| a >= FAST_PATH_RELATIVE_ERROR * planar_polygon(p));
        match if fast { planar_arc_length(p) } else { None } {
            Some(l) => out.push(l),
            None => out.push(BezierCurve::<C>::from_flat(p, None)?.arc_length_adaptive(accuracy)?),
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    /// Gauss–Legendre by Newton's method on `P_n` in f64 (as `gauss_legendre` above), sorted
    /// like the tables: positive nodes, largest first.
    fn newton(n: usize) -> Vec<(f64, f64)> {
        (0..n / 2).map(|i| legendre_node(n, i)).collect()
    }

    #[test]
    fn gauss_legendre_tables_are_right() {
        // Abramowitz & Stegun, table 25.4, n = 8 (15 digits).
        let published = [
            (0.960289856497536, 0.101228536290376),
            (0.796666477413627, 0.222381034453374),
            (0.525532409916329, 0.313706645877887),
            (0.183434642495650, 0.362683783378362),
        ];
        for (&(x, w), (px, pw)) in GL8.iter().zip(published) {
            assert!((x - px).abs() < 1e-15 && (w - pw).abs() < 1e-15, "{x} {w}");
        }
        let tables: [&[(f64, f64)]; 4] = [&GL8, &GL12, &GL16, &GL24];
        for (table, n) in tables.into_iter().zip([8, 12, 16, 24]) {
            assert_eq!(table.len(), n / 2);
            for (&(x, w), (nx, nw)) in table.iter().zip(newton(n)) {
                assert!((x - nx).abs() <= 4e-16, "GL{n} node {x} vs {nx}");
                assert!((w - nw).abs() <= 3e-14 * w, "GL{n} weight {w} vs {nw}");
            }
            // Exact for every monomial of degree < 2n: ∫ x^k over [−1, 1] = 2/(k + 1) for even
            // k (odd ones vanish by symmetry).
            for k in (0..2 * n).step_by(2) {
                let q: f64 = table.iter().map(|&(x, w)| 2.0 * w * x.powi(k as i32)).sum();
                let exact = 2.0 / (k + 1) as f64;
                assert!(
                    (q - exact).abs() <= 1e-14 * exact,
                    "GL{n}, x^{k}: {q} vs {exact}"
                );
            }
        }
    }

    /// mulberry32 as in bench/inputs.mjs.
    fn mulberry32(seed: u32) -> impl FnMut() -> f64 {
        let mut a = seed;
        move || {
            a = a.wrapping_add(0x6d2b_79f5);
            let mut t = a;
            t = (t ^ (t >> 15)).wrapping_mul(t | 1);
            t ^= t.wrapping_add((t ^ (t >> 7)).wrapping_mul(t | 61));
            (t ^ (t >> 14)) as f64 / 4_294_967_296.0
        }
    }

    #[test]
    fn the_benchmark_cubics_cost_few_speed_evaluations() {
        // bench/inputs.mjs randomCubics(10_000): seed SEED + 4, SEED = 20260505.
        let mut random = mulberry32(20_260_505 + 4);
        let count = 10_000;
        let (mut evals, mut fallbacks) = (0, 0);
        for _ in 0..count {
            let p: [f64; 8] = std::array::from_fn(|_| random());
            if planar_arc_length_counted(&p, &mut evals).is_none() {
                fallbacks += 1;
            }
        }
        let mean = evals as f64 / count as f64;
        println!("benchmark cubics: {mean:.2} speed evaluations per curve, {fallbacks} fallbacks");
        assert_eq!(fallbacks, 0);
        // Measured 69.8 (their nearest hodograph root has a median ρ of 1.2 on [0, 1]); a
        // regression guard, not a target.
        assert!(mean < 80.0, "{mean} evaluations per curve");
    }
}
