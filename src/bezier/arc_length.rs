//! Arc length `∫ |P'(t)| dt`: singularity-aware Gauss–Legendre for 2D polynomial curves of
//! degree ≤ 3 (the speed's singularities are known in closed form), and adaptive
//! Gauss–Legendre quadrature of the speed for everything else.

use crate::prelude::*;
mod adaptive;
mod planar;

pub use planar::{FAST_PATH_RELATIVE_ERROR, RULE_RHO, RULE_RHO_BY_ACCURACY};

use super::BezierCurve;
use crate::error::{check_tolerance, Result};
use crate::geom::{check_all_coordinates, Cartesian};
use adaptive::Speed;
use planar::{planar_arc_length, planar_polygon};

/// Default accuracy, relative to the control polygon's length (which bounds the arc length
/// from above).
pub const DEFAULT_RELATIVE_ACCURACY: f64 = 1e-13;

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
    /// the result is within 1e-13 relative. A looser `accuracy` `a` asks for the relative
    /// accuracy `τ = a / L` (`L` the polygon's length, ≥ the arc length) and takes the
    /// thresholds of [`RULE_RHO_BY_ACCURACY`] for the largest tabulated `τ` below it,
    /// calibrated the same way: fewer and shorter rules, the absolute error still ≤ `a`. Random cubics in a square (the benchmark's) take ~70
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
            if let Some(tau) = fast_path_tau(accuracy, p) {
                if let Some(l) = planar_arc_length(p, tau) {
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
        check_all_coordinates(p, "coordinate")?;
        let accuracy = accuracy.map(check_tolerance).transpose()?;
        match fast_path_tau(accuracy, p).and_then(|tau| planar_arc_length(p, tau)) {
            Some(l) => out.push(l),
            None => out.push(BezierCurve::<C>::from_flat(p, None)?.arc_length_adaptive(accuracy)?),
        }
    }
    Ok(out)
}

/// The relative accuracy the fast path must reach for the absolute `accuracy` on the flat 2D
/// curve `p`: `accuracy / L` with `L` the control polygon's length (≥ the arc length, so a
/// relative error ≤ τ is an absolute one ≤ accuracy), the default `FAST_PATH_RELATIVE_ERROR`;
/// `None` when that is tighter than the fast path's floor (the adaptive method then runs).
fn fast_path_tau(accuracy: Option<f64>, p: &[f64]) -> Option<f64> {
    let tau = accuracy.map_or(FAST_PATH_RELATIVE_ERROR, |a| a / planar_polygon(p));
    (tau >= FAST_PATH_RELATIVE_ERROR).then_some(tau)
}

#[cfg(test)]
mod tests {
    use super::adaptive::legendre_node;
    use super::planar::{planar_arc_length_counted, GL12, GL16, GL24, GL8};
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
            if planar_arc_length_counted(&p, &mut evals, &super::RULE_RHO).is_none() {
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
