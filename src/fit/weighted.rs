//! Least squares with a metric per sample: the control points minimising
//! `Σ_k (C(t_k) − Q_k)ᵀ M_k (C(t_k) − Q_k)`, `C(t) = Σ_i N_{i,p}(t) P_i`.
//!
//! With every `M_k = I` this is the plain least squares of section 5 (the sum of squared
//! distances). The fitter uses the *squared-distance* metric `M_k = I − (1 − w) T_k T_kᵀ`
//! (`T_k` the unit tangent of the current curve at the sample's foot point, `w` small): the
//! squared distance to the tangent line plus `w` times the squared offset along it, a
//! second-order model of the squared distance to the curve (Wang, Pottmann & Liu, "Fitting
//! B-spline curves to point clouds by curvature-based squared distance minimization", 2006).
//! Plain point-distance minimisation with parameter correction creeps (each round moves the
//! parameters along the curve only a little); this metric lets the curve slide along itself, so
//! a few rounds reach what many would not.
//!
//! Setting the gradient with respect to `P_a` to zero gives the normal equations
//! `Σ_b (Σ_k B_a(t_k) B_b(t_k) M_k) P_b = Σ_k B_a(t_k) M_k Q_k`: a symmetric system in the
//! `dim·count` coordinates, banded in blocks of `dim` (block half-width `p`).
//!
//! - **Open**: `P_0 = Q_0`, `P_n = Q_m` as in section 5 (their terms move to the right side);
//!   the unknowns `P_1 … P_{n−1}`; block band LU, O(m·p²·dim²).
//! - **Periodic**: `N` distinct control points, index `i mod N` (see [`super::periodic`]); the
//!   cyclic band is kept as a band plus a dense border after renumbering the columns by `p`
//!   blocks, as closed interpolation does; small systems are solved dense.

use crate::bspline::{basis_functions, BSplineCurve, BasisScratch, KnotVector};
use crate::error::Result;
use crate::geom::Cartesian;
use crate::interp::banded::AlmostBanded;

/// The metric of one sample: `I − (1 − w) T Tᵀ` (`w = weight`) for the tangent `tangent` (row-major
/// `dim × dim` into `out`); the identity when the tangent is zero.
pub(super) fn metric<C: Cartesian>(tangent: C, weight: f64, out: &mut [f64]) {
    let dim = C::DIM;
    let len = tangent.dot_with(tangent).sqrt();
    for r in 0..dim {
        for c in 0..dim {
            let mut v = if r == c { 1.0 } else { 0.0 };
            if len > 0.0 {
                v -= (1.0 - weight) * tangent.coord(r) * tangent.coord(c) / (len * len);
            }
            out[r * dim + c] = v;
        }
    }
}

/// The curve minimising the weighted sum (see the module doc) with `count` control points
/// (distinct ones when `periodic`) on `knots`; `metrics` holds `dim²` numbers per sample
/// (`None`: the identity). Periodic knots come from [`super::periodic::periodic_knots`].
///
/// # Errors
/// [`crate::error::Error::SingularSystem`] (`"least-squares-system"`), the knot errors of
/// [`KnotVector::new`].
pub(super) fn weighted_fit<C: Cartesian>(
    samples: &[C],
    params: &[f64],
    metrics: Option<&[f64]>,
    degree: usize,
    count: usize,
    knots: &[f64],
    periodic: bool,
) -> Result<BSplineCurve<C>> {
    let (p, dim) = (degree, C::DIM);
    let total = if periodic { count + p } else { count };
    let vector = KnotVector::new(knots.to_vec(), p, total)?;
    let m = samples.len();
    // Unknown blocks: periodic 0..N (index mod N); open 1..n−1 (block i − 1).
    let blocks = if periodic { count } else { count - 2 };
    let first = samples[0];
    let last = samples[m - 1];
    let mut control: Vec<C> = vec![first; total];
    if !periodic {
        control[count - 1] = last;
    }
    if blocks > 0 {
        let size = blocks * dim;
        let (mut a, shift) = if periodic {
            let border = (2 * p + 1) * dim;
            if (4 * p + 3) * dim <= size {
                let lower = 2 * p * dim + dim - 1;
                (AlmostBanded::new(size, lower, dim - 1, border), p * dim)
            } else {
                (AlmostBanded::new(size, 0, 0, size), p * dim)
            }
        } else {
            let band = (p + 1) * dim - 1;
            (AlmostBanded::new(size, band, band, 0), 0)
        };
        let column = |col: usize| (col + size - shift % size) % size;
        let mut rhs = vec![0.0; size];
        let mut basis = vec![0.0; p + 1];
        let mut scratch = BasisScratch::default();
        let mut span = p;
        let identity: Vec<f64> = (0..dim * dim)
            .map(|i| if i % (dim + 1) == 0 { 1.0 } else { 0.0 })
            .collect();
        let mut r = [0.0; 3];
        for k in 0..m {
            let t = params[k].clamp(0.0, 1.0);
            span = vector.span_from(t, span);
            basis_functions(knots, span, t, p, &mut basis, &mut scratch, None);
            let mk = metrics.map_or(&identity[..], |ms| &ms[k * dim * dim..(k + 1) * dim * dim]);
            // The sample less the fixed ends' share (open).
            let r = &mut r[..dim];
            for (c, rc) in r.iter_mut().enumerate() {
                *rc = samples[k].coord(c);
            }
            let lo = span - p;
            if !periodic {
                for (j, &b) in basis.iter().enumerate() {
                    let fixed = match lo + j {
                        0 => Some(first),
                        i if i == count - 1 => Some(last),
                        _ => None,
                    };
                    if let Some(f) = fixed {
                        for (c, rc) in r.iter_mut().enumerate() {
                            *rc -= b * f.coord(c);
                        }
                    }
                }
            }
            let block = |i: usize| -> Option<usize> {
                if periodic {
                    Some(i % count)
                } else if i == 0 || i == count - 1 {
                    None
                } else {
                    Some(i - 1)
                }
            };
            for (ia, &ba) in basis.iter().enumerate() {
                let Some(bi) = block(lo + ia) else { continue };
                if ba == 0.0 {
                    continue;
                }
                for c in 0..dim {
                    let mr: f64 = (0..dim).map(|d| mk[c * dim + d] * r[d]).sum();
                    rhs[bi * dim + c] += ba * mr;
                }
                for (ib, &bb) in basis.iter().enumerate() {
                    let Some(bj) = block(lo + ib) else { continue };
                    let w = ba * bb;
                    if w == 0.0 {
                        continue;
                    }
                    for c in 0..dim {
                        for d in 0..dim {
                            a.add(bi * dim + c, column(bj * dim + d), w * mk[c * dim + d]);
                        }
                    }
                }
            }
        }
        a.solve(&mut rhs, 1, "least-squares-system")?;
        // Row `x` of the solution is unknown `(x + shift) mod size`.
        rhs.rotate_right(shift % size);
        let offset = usize::from(!periodic);
        for (b, chunk) in rhs.chunks_exact(dim).enumerate() {
            control[b + offset] = C::from_slice(chunk);
        }
    }
    if periodic {
        for j in 0..p {
            control[count + j] = control[j % count];
        }
        return Ok(BSplineCurve::new(control, p, knots.to_vec(), None)?.with_wrapped(p));
    }
    BSplineCurve::new(control, p, knots.to_vec(), None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::ControlPolygon;
    use crate::interp::global::knots::least_squares_knots;
    use crate::interp::least_squares::approximate_bspline;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;
    use glam::DVec2;

    #[test]
    fn the_identity_metric_is_section_5s_least_squares() {
        let samples: Vec<DVec2> = (0..40)
            .map(|i| {
                let s = i as f64 / 39.0;
                DVec2::new(100.0 * s, 30.0 * (7.0 * s).sin() + 5.0 * (i % 3) as f64)
            })
            .collect();
        let params: Vec<f64> = (0..40).map(|i| (i as f64 / 39.0).powf(1.2)).collect();
        for (p, count) in [(2, 5), (3, 9), (3, 4)] {
            let knots = least_squares_knots(&params, p, count);
            let want = approximate_bspline(&samples, p, count, &params, Some(&knots)).unwrap();
            let identity = [1.0, 0.0, 0.0, 1.0].repeat(samples.len());
            let got =
                weighted_fit(&samples, &params, Some(&identity), p, count, &knots, false).unwrap();
            for (a, b) in got.control_points().iter().zip(want.control_points()) {
                assert!((*a - b).length() < 1e-9, "{a} vs {b}");
            }
        }
    }
}
