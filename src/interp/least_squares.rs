//! Least-squares B-spline approximation with the ends interpolated (NURBS Book §9.4.1): the
//! curve of degree `p` with `n + 1` control points that passes through the first and last data
//! point and comes closest to the others in the sum of squared distances.
//!
//! With data `Q_0 … Q_m` at parameters `t_0 … t_m`, `P_0 = Q_0` and `P_n = Q_m` (clamped knots),
//! `R_k = Q_k − N_{0,p}(t_k) Q_0 − N_{n,p}(t_k) Q_m` for `k = 1..m−1`, and the interior control
//! points `P_1 … P_{n−1}` minimise `Σ_k |R_k − Σ_i N_{i,p}(t_k) P_i|²`: the normal equations
//! `(Nᵀ N) P = Nᵀ R` with `N_{ki} = N_{i,p}(t_k)` (`k = 1..m−1`, `i = 1..n−1`). `Nᵀ N` is
//! symmetric, banded (`|i − j| ≤ p`) and positive definite when the Schoenberg–Whitney
//! condition holds for some subsequence of the parameters, so banded Cholesky solves it in
//! O(m·p² + n·p²). Default knots by eq. 9.68–9.69 ([`super::global::knots`]).

use super::banded::SymmetricBanded;
use super::global::knots::{check_schoenberg_whitney_subsequence, least_squares_knots};
use super::global::{check_interpolation_degree, check_params, check_point_cap, check_points};
use crate::bspline::{basis_functions, BSplineCurve, BasisScratch, KnotVector};
use crate::error::InterpError;
use crate::error::{Error, Result};
use crate::geom::Cartesian;

/// The least-squares B-spline with `count` control points through the first and last of
/// `points` (see the module doc); `knots` (optional) must be clamped at `t_0` and `t_m`.
/// With `count` equal to the number of points it is the interpolant with averaging knots.
///
/// # Errors
/// In this order: [`Error::NotFinite`], [`Error::CoordinateTooLarge`] (coordinates),
/// [`Error::DegreeOutOfRange`], [`Error::TooLarge`] above [`super::MAX_INTERPOLATION_POINTS`]
/// points, [`Error::TooFewDataPoints`] (`max(2, p + 1)`), the parameter errors
/// ([`InterpError::ParamCount`], [`Error::NotFinite`], [`InterpError::ParamsNotIncreasing`]),
/// [`InterpError::ControlCountOutOfRange`] (`count` outside `[p + 1, m + 1]`), the errors of
/// [`KnotVector::new`] for `count` control points, [`InterpError::KnotsNotClamped`],
/// [`InterpError::SchoenbergWhitney`] (no parameter for some basis function), and
/// [`Error::SingularSystem`] from Cholesky.
pub fn approximate_bspline<C: Cartesian>(
    points: &[C],
    degree: usize,
    count: usize,
    params: &[f64],
    knots: Option<&[f64]>,
) -> Result<BSplineCurve<C>> {
    check_fit_data(points, degree)?;
    let coords = super::global::flatten(points);
    let (control, knots) = approximate_flat(&coords, C::DIM, degree, count, params, knots)?;
    curve_from(&control, degree, knots)
}

/// The B-spline with the flat control points `control` (dimension `C::DIM`).
pub(crate) fn curve_from<C: Cartesian>(
    control: &[f64],
    degree: usize,
    knots: Vec<f64>,
) -> Result<BSplineCurve<C>> {
    let control = control.chunks_exact(C::DIM).map(C::from_slice).collect();
    BSplineCurve::new(control, degree, knots, None)
}

/// [`approximate_bspline`] on flat coordinates of dimension `dim` (after [`check_fit_data`]),
/// written once for every dimension: the control points (flat) and the knots.
#[inline(never)]
pub(crate) fn approximate_flat(
    coords: &[f64],
    dim: usize,
    degree: usize,
    count: usize,
    params: &[f64],
    knots: Option<&[f64]>,
) -> Result<(Vec<f64>, Vec<f64>)> {
    let points = coords.len() / dim;
    let p = degree;
    check_params(params, points)?;
    if count < p + 1 || count > points {
        return Err(Error::Interp(InterpError::ControlCountOutOfRange {
            count,
            min: p + 1,
            max: points,
        }));
    }
    let m = points - 1;
    let n = count - 1;
    let knots = match knots {
        Some(k) => {
            let knots = KnotVector::new(k.to_vec(), p, count)?;
            check_clamped(knots.as_slice(), p, params[0], params[m])?;
            check_schoenberg_whitney_subsequence(knots.as_slice(), p, count, params)?;
            knots
        }
        None => KnotVector::new(least_squares_knots(params, p, count), p, count)?,
    };
    let first = &coords[..dim];
    let last = &coords[m * dim..];
    let mut control = vec![0.0; count * dim];
    control[..dim].copy_from_slice(first);
    control[n * dim..].copy_from_slice(last);
    if n >= 2 {
        let unknowns = n - 1;
        let mut normal = SymmetricBanded::new(unknowns, p);
        let mut rhs = vec![0.0; unknowns * dim];
        let mut basis = vec![0.0; p + 1];
        let mut scratch = BasisScratch::default();
        let mut span = p;
        let mut r = [0.0; 3];
        for k in 1..m {
            let t = params[k];
            span = knots.span_from(t, span);
            basis_functions(knots.as_slice(), span, t, p, &mut basis, &mut scratch, None);
            let lo = span - p;
            // R_k = Q_k − N_0(t_k) Q_0 − N_n(t_k) Q_m.
            let r = &mut r[..dim];
            r.copy_from_slice(&coords[k * dim..(k + 1) * dim]);
            for (j, &b) in basis.iter().enumerate() {
                if lo + j == 0 {
                    for (rc, &q) in r.iter_mut().zip(first) {
                        *rc -= q * b;
                    }
                } else if lo + j == n {
                    for (rc, &q) in r.iter_mut().zip(last) {
                        *rc -= q * b;
                    }
                }
            }
            for (a, &ba) in basis.iter().enumerate() {
                let i = lo + a;
                if i == 0 || i == n || ba == 0.0 {
                    continue;
                }
                for (c, &rc) in r.iter().enumerate() {
                    rhs[(i - 1) * dim + c] += ba * rc;
                }
                for (b, &bb) in basis.iter().enumerate().skip(a) {
                    let j = lo + b;
                    if j != 0 && j != n {
                        normal.add(i - 1, j - 1, ba * bb);
                    }
                }
            }
        }
        normal.solve_cholesky(&mut rhs, dim, "least-squares-system")?;
        control[dim..n * dim].copy_from_slice(&rhs);
    }
    Ok((control, knots.as_slice().to_vec()))
}

/// The checks on the data before the parameters: finite coordinates, the degree, the number
/// of points (at most [`super::MAX_INTERPOLATION_POINTS`], at least `max(2, p + 1)`).
pub(crate) fn check_fit_data<C: Cartesian>(points: &[C], degree: usize) -> Result<()> {
    check_points(points)?;
    check_fit_shape(points.len(), degree)
}

/// [`check_fit_data`] after the coordinates: the degree, then the number of points `count`.
pub(crate) fn check_fit_shape(count: usize, degree: usize) -> Result<()> {
    check_interpolation_degree(degree)?;
    check_point_cap(count)?;
    let needed = 2.max(degree + 1);
    if count < needed {
        return Err(Error::TooFewDataPoints {
            needed,
            got: count,
            what: "least-squares-bspline",
        });
    }
    Ok(())
}

/// Checks the first `p + 1` knots equal `a = t_0` and the last `p + 1` equal `b = t_m`.
fn check_clamped(knots: &[f64], p: usize, a: f64, b: f64) -> Result<()> {
    if knots[..=p].iter().any(|&u| u != a) {
        return Err(Error::Interp(InterpError::KnotsNotClamped {
            end: "first",
            param: a,
            degree: p,
        }));
    }
    if knots[knots.len() - p - 1..].iter().any(|&u| u != b) {
        return Err(Error::Interp(InterpError::KnotsNotClamped {
            end: "last",
            param: b,
            degree: p,
        }));
    }
    Ok(())
}
