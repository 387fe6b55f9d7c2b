//! The fast path for 2D polynomial curves of degree ≤ 3: singularity-aware Gauss–Legendre on
//! the complex hodograph (see `BezierCurve::arc_length`).

use super::DEFAULT_RELATIVE_ACCURACY;
use glam::DVec2;

/// Relative error guaranteed by the fast path for 2D polynomial curves of degree ≤ 3 (see
/// [`crate::BezierCurve::arc_length`]). The arc length is at most the control polygon's length, so the
/// fast path is used when the caller's absolute accuracy is at least this times the polygon's
/// length (the default accuracy is exactly that).
pub const FAST_PATH_RELATIVE_ERROR: f64 = DEFAULT_RELATIVE_ACCURACY;

/// Positive halves of the symmetric Gauss–Legendre rules on `[−1, 1]`: `(x_i, w_i)` with
/// `x_i > 0`; the node `−x_i` has the same weight. Newton's method on `P_n` in 40-digit
/// arithmetic (tests/fixtures/arc_length_thresholds.py), rounded to double; checked in the
/// tests against the f64 Newton iteration above and against exact integrals of monomials.
pub(super) const GL8: [(f64, f64); 4] = [
    (0.9602898564975363, 0.10122853629037626),
    (0.7966664774136267, 0.22238103445337448),
    (0.525532409916329, 0.31370664587788727),
    (0.1834346424956498, 0.362683783378362),
];
pub(super) const GL12: [(f64, f64); 6] = [
    (0.9815606342467192, 0.04717533638651183),
    (0.9041172563704749, 0.10693932599531843),
    (0.7699026741943047, 0.16007832854334622),
    (0.5873179542866175, 0.20316742672306592),
    (0.3678314989981802, 0.2334925365383548),
    (0.1252334085114689, 0.24914704581340277),
];
pub(super) const GL16: [(f64, f64); 8] = [
    (0.9894009349916499, 0.027152459411754096),
    (0.9445750230732326, 0.062253523938647894),
    (0.8656312023878318, 0.09515851168249279),
    (0.755404408355003, 0.12462897125553388),
    (0.6178762444026438, 0.14959598881657674),
    (0.45801677765722737, 0.16915651939500254),
    (0.2816035507792589, 0.18260341504492358),
    (0.09501250983763744, 0.1894506104550685),
];
pub(super) const GL24: [(f64, f64); 12] = [
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

/// [`RULE_RHO`] for looser accuracies: `(τ, thresholds)`, loosest first. The same script and
/// the same worst cases (`python3 tests/fixtures/arc_length_thresholds.py --loose`: ρ scanned
/// from 1.01, the reference on 128 pieces) give the smallest ρ from which each rule's worst relative error is ≤ τ per
/// piece; these are those values times the same safety factor 1.1. A caller asking for an
/// absolute accuracy `a` on a curve whose control polygon has length `L` (≥ the arc length)
/// gets the row of the largest `τ ≤ a/L`: per-piece relative errors ≤ τ bound the relative
/// error of the sum of positive pieces, so the absolute error is ≤ τ·length ≤ a. Looser rows
/// take fewer and shorter rules: on the benchmark's random cubics, accuracy 1e-3 runs ~1.5×
/// as fast as the default (measured error 4e-5 relative; the thresholds cover the worst
/// placement of the singularity on each ellipse, which these curves rarely have).
pub const RULE_RHO_BY_ACCURACY: [(f64, [f64; 4]); 7] = [
    (1e-3, [1.448, 1.302, 1.235, 1.141]),
    (1e-4, [1.697, 1.448, 1.338, 1.202]),
    (1e-5, [1.937, 1.568, 1.410, 1.268]),
    (1e-6, [2.211, 1.742, 1.527, 1.338]),
    (1e-8, [2.958, 2.097, 1.742, 1.486]),
    (1e-10, [3.958, 2.523, 2.043, 1.609]),
    (1e-12, [5.295, 3.037, 2.331, 1.789]),
];

/// The thresholds for a relative accuracy `tau` (≥ [`FAST_PATH_RELATIVE_ERROR`]).
pub(super) fn rule_rho(tau: f64) -> &'static [f64; 4] {
    RULE_RHO_BY_ACCURACY
        .iter()
        .find(|(t, _)| *t <= tau)
        .map_or(&RULE_RHO, |(_, rho)| rho)
}

/// A root with `|Im r| ≤ NEAR_REAL` (in units of the curve's local parameter on `[0, 1]`) is
/// treated as real: `|t − r| = √((t − x)² + y²)` is replaced by `|t − x|`, which is linear on
/// either side of `x`. The pieces are split exactly at `x`, so the root sits at a piece's end
/// (or outside it) and is no singularity of the piece's integrand. The neglected part is at most
/// `y²/(2|t − x|)` pointwise and `~ y² (1 + ln(1/y))` integrated, `< 1e-16` relative to the
/// arc length (the factor `|t − r2|` of the other root appears in both).
pub(super) const NEAR_REAL: f64 = 1e-9;
/// Roots further than this from the origin (in local-parameter units) are ignored: their `ρ`
/// on any piece of `[0, 1]` exceeds `10^6`, far above every threshold.
pub(super) const FAR_ROOT: f64 = 1e6;
/// Capacity of the explicit stack of pending pieces.
pub(super) const MAX_STACK: usize = 64;
/// Most pieces integrated for one curve before giving up and using the adaptive method. A
/// root at distance `d` from `[0, 1]` costs about `log4(1/d)` pieces of geometric grading on
/// each side, and `d ≥ NEAR_REAL` unless the root is treated as real, so ~40 pieces is the
/// worst case in exact arithmetic.
pub(super) const MAX_PIECES: usize = 200;

#[inline]
pub(super) fn cmul(a: DVec2, b: DVec2) -> DVec2 {
    DVec2::new(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x)
}

#[inline]
pub(super) fn cdiv(a: DVec2, b: DVec2) -> DVec2 {
    DVec2::new(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / b.length_squared()
}

/// Principal square root of a complex number (real part ≥ 0), without cancellation.
#[inline]
pub(super) fn csqrt(z: DVec2) -> DVec2 {
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
pub(super) fn far_quotient(num: DVec2, den: DVec2) -> bool {
    num.x.abs().max(num.y.abs()) > FAR_ROOT * (den.x.abs() + den.y.abs())
}

/// The hodograph of a 2D polynomial Bézier curve of degree ≤ 3 as a complex polynomial
/// `z'(s) = x'(s) + i y'(s) = scale · (c0 + c1 s + c2 s²)`, scaled so that its largest
/// coefficient component is 1 (so the root finding can neither overflow nor underflow).
pub(super) struct PlanarSpeed {
    c0: DVec2,
    c1: DVec2,
    c2: DVec2,
    scale: f64,
}

/// Outcome of setting up a [`PlanarSpeed`].
pub(super) enum Planar {
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
    pub(super) fn from_flat(p: &[f64]) -> Planar {
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
    pub(super) fn at(&self, s: f64) -> f64 {
        (self.c0 + s * (self.c1 + s * self.c2)).length()
    }

    /// The complex roots of `c2 s² + c1 s + c0` that are nearer than [`FAR_ROOT`]: the stable
    /// quadratic formula `q = −(c1 + σ√(c1² − 4 c2 c0))/2`, the sign σ making `Re(conj(c1)·σ√…)
    /// ≥ 0` (no cancellation), roots `q/c2` and `c0/q`. `c2 = 0` (a quadratic curve, or a cubic
    /// whose hodograph is linear) leaves the one root `c0/q = −c0/c1`; `q = 0` means `c1 = 0`
    /// and `c2 c0 = 0`: a double root at 0 (`c0 = 0`) or a constant hodograph (no root).
    pub(super) fn roots(&self) -> ([DVec2; 2], usize) {
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
    pub(super) fn gauss<const N: usize>(&self, lo: f64, hi: f64, nodes: &[(f64, f64); N]) -> f64 {
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
    pub(super) fn arc_length(&self, evals: &mut usize, rule_rho: &[f64; 4]) -> Option<f64> {
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
            if meets(rule_rho[0]) {
                total += self.gauss(lo, hi, &GL8);
                *evals += 8;
            } else if meets(rule_rho[1]) {
                total += self.gauss(lo, hi, &GL12);
                *evals += 12;
            } else if meets(rule_rho[2]) {
                total += self.gauss(lo, hi, &GL16);
                *evals += 16;
            } else if meets(rule_rho[3]) {
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
/// 1–3) to the relative accuracy `tau` (≥ [`FAST_PATH_RELATIVE_ERROR`]; see
/// [`RULE_RHO_BY_ACCURACY`]): `Some(0)` for a zero hodograph, `None` when the fast path gives up.
pub(super) fn planar_arc_length(p: &[f64], tau: f64) -> Option<f64> {
    planar_arc_length_counted(p, &mut 0, rule_rho(tau))
}

#[inline(always)]
pub(super) fn planar_arc_length_counted(
    p: &[f64],
    evals: &mut usize,
    rule_rho: &[f64; 4],
) -> Option<f64> {
    match PlanarSpeed::from_flat(p) {
        Planar::Zero => Some(0.0),
        Planar::Overflow => None,
        Planar::Speed(s) if p.len() == 4 => Some(s.c0.length() * s.scale),
        Planar::Speed(s) => s.arc_length(evals, rule_rho),
    }
}

/// Length of the control polygon of flat 2D points.
pub(super) fn planar_polygon(p: &[f64]) -> f64 {
    p.windows(4)
        .step_by(2)
        .map(|w| match w {
            &[x0, y0, x1, y1] => ((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0)).sqrt(),
            _ => 0.0,
        })
        .sum()
}
