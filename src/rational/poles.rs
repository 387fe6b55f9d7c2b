//! Where a rational Bézier curve with weights of any sign runs off to infinity (syllabus §4:
//! why weights <= 0 are refused). A TEACHING function for the negative-weights demo, not a
//! curve constructor: it accepts weights that every curve constructor rejects and never
//! builds a curve object.

use crate::bezier::{de_casteljau_point, split_points, MAX_DEGREE};
use crate::error::{check_coordinate, check_finite, Error, Result};
use crate::geom::{Cartesian, Params, MAX_SAMPLES};

/// Deepest halving of `[0, 1]` when isolating the zeros of `w(t)`: intervals end `2^−52` wide,
/// the spacing of `f64` near 1, so a root is located to about `1e−16`.
pub const MAX_ROOT_DEPTH: usize = 52;

/// Most intervals examined by one root search (a hard bound on the work for any input; a
/// polynomial of degree n has at most n live intervals per depth in exact arithmetic).
pub const MAX_ROOT_INTERVALS: usize = 1 << 14;

/// Zeros of `w(t)` closer than this are reported once (a double zero, where `w` touches 0,
/// is one zero).
pub const ROOT_MERGE_DISTANCE: f64 = 1e-12;

/// What [`rational_poles`] returns.
#[derive(Debug, Clone, PartialEq)]
pub struct RationalPoles<C: Cartesian> {
    /// The homogeneous curve `P^w(t) = Σ B_i^n(t) (w_i P_i, w_i)` at `count` equally spaced
    /// `t ∈ [0, 1]` (ends included): `(x·w, y·w, (z·w,) w)` — not divided.
    pub samples: Vec<C::Homogeneous>,
    /// The `t ∈ [0, 1]` where the weight polynomial `w(t) = Σ w_i B_i^n(t)` is zero, ascending.
    pub roots: Vec<f64>,
    /// For each root `t_0`, the unit direction of the numerator `N(t_0) = Σ B_i^n(t_0) w_i P_i`:
    /// `P(t) = N(t)/w(t)` runs off to infinity along `+N(t_0)` where `w → 0⁺` and along
    /// `−N(t_0)` where `w → 0⁻`. The zero vector when `N(t_0) = 0` too (then `P` may stay finite).
    pub directions: Vec<C>,
}

/// Samples and poles of the rational Bézier curve `P(t) = Σ B_i^n(t) w_i P_i / Σ B_i^n(t) w_i`
/// with weights of ANY sign (a teaching function: curves themselves refuse weights <= 0).
///
/// The zeros of `w(t)` are isolated on its Bernstein coefficients — the weights themselves:
/// an interval whose coefficients show no sign change holds no zero (variation diminishing),
/// one with changes is halved by de Casteljau at its middle, down to [`MAX_ROOT_DEPTH`] halvings
/// and at most [`MAX_ROOT_INTERVALS`] intervals; a zero value met exactly (at `t = 0`, `t = 1`
/// or a midpoint) is a root, and a smallest interval still changing sign gives its middle.
///
/// # Errors
/// [`Error::TooFewPoints`] below 2 points, [`Error::TooLarge`] above degree [`MAX_DEGREE`] or
/// `count` above [`MAX_SAMPLES`], [`Error::NotFinite`] for a coordinate or weight,
/// [`Error::WeightCount`], and [`Error::AllWeightsZero`] when `w(t) ≡ 0`.
pub fn rational_poles<C: Cartesian>(
    points: &[C],
    weights: &[f64],
    count: usize,
) -> Result<RationalPoles<C>> {
    if points.len() < 2 {
        return Err(Error::TooFewPoints {
            needed: 2,
            got: points.len(),
            what: "rational-bezier-curve",
        });
    }
    let n = points.len() - 1;
    if n > MAX_DEGREE {
        return Err(Error::TooLarge {
            what: "degree",
            value: n,
            max: MAX_DEGREE,
        });
    }
    for (i, p) in points.iter().enumerate() {
        for k in 0..C::DIM {
            check_coordinate("coordinate", Some(i * C::DIM + k), p.coord(k))?;
        }
    }
    if weights.len() != points.len() {
        return Err(Error::WeightCount {
            expected: points.len(),
            got: weights.len(),
        });
    }
    for (i, &w) in weights.iter().enumerate() {
        check_finite("weight", Some(i), w)?;
    }
    if weights.iter().all(|&w| w == 0.0) {
        return Err(Error::AllWeightsZero {
            count: weights.len(),
        });
    }
    if count > MAX_SAMPLES {
        return Err(Error::TooLarge {
            what: "count",
            value: count,
            max: MAX_SAMPLES,
        });
    }
    let homogeneous: Vec<C::Homogeneous> = points
        .iter()
        .zip(weights)
        .map(|(p, &w)| p.to_homogeneous(w))
        .collect();
    let mut scratch = Vec::with_capacity(homogeneous.len());
    let params = Params::uniform(0.0, 1.0, count);
    let samples = (0..count)
        .map(|j| de_casteljau_point(&homogeneous, params.get(j), &mut scratch))
        .collect();
    let roots = weight_roots(weights);
    let directions = roots
        .iter()
        .map(|&t| {
            let numerator = C::numerator(de_casteljau_point(&homogeneous, t, &mut scratch));
            let length = numerator.norm();
            if length > 0.0 && length.is_finite() {
                numerator * (1.0 / length)
            } else {
                C::ZERO
            }
        })
        .collect();
    Ok(RationalPoles {
        samples,
        roots,
        directions,
    })
}

/// The zeros in `[0, 1]` of `w(t) = Σ c_i B_i^n(t)` (not all `c_i` zero), ascending.
fn weight_roots(coefficients: &[f64]) -> Vec<f64> {
    let mut roots = Vec::new();
    if coefficients.first() == Some(&0.0) {
        roots.push(0.0);
    }
    let mut budget = MAX_ROOT_INTERVALS;
    isolate(coefficients, 0.0, 1.0, 0, &mut budget, &mut roots);
    if coefficients.last() == Some(&0.0) {
        roots.push(1.0);
    }
    roots.dedup_by(|b, a| *b - *a <= ROOT_MERGE_DISTANCE);
    roots
}

/// Sign changes of the non-zero coefficients.
fn sign_changes(c: &[f64]) -> usize {
    let mut last = 0.0;
    let mut changes = 0;
    for &x in c.iter().filter(|&&x| x != 0.0) {
        if last != 0.0 && (x > 0.0) != (last > 0.0) {
            changes += 1;
        }
        last = x;
    }
    changes
}

/// Zeros of the polynomial with Bernstein coefficients `c` on `[a, b]` strictly inside it
/// (the ends are the caller's), pushed in ascending order.
fn isolate(c: &[f64], a: f64, b: f64, depth: usize, budget: &mut usize, out: &mut Vec<f64>) {
    if *budget == 0 || sign_changes(c) == 0 {
        return;
    }
    *budget -= 1;
    let mid = 0.5 * (a + b);
    if depth >= MAX_ROOT_DEPTH {
        out.push(mid);
        return;
    }
    let (left, right) = split_points(c, 0.5);
    isolate(&left, a, mid, depth + 1, budget, out);
    if right.first() == Some(&0.0) {
        out.push(mid);
    }
    isolate(&right, mid, b, depth + 1, budget, out);
}
