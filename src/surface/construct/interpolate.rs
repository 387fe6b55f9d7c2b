//! Global interpolation of a grid of points by a B-spline surface (NURBS Book §9.2.5, A9.4).

use crate::bspline::Parameterization;
use crate::error::SurfaceError;
use crate::error::{Error, Result};
use crate::geom::{check_all_coordinates, MAX_SAMPLES};
use crate::interp::global::knots::averaging_knots;
use crate::interp::global::{check_interpolation_degree, Setup};
use crate::interp::InterpolationOptions;
use crate::surface::{checked_count, in_argument, BSplineSurface};
use glam::DVec3;

/// The B-spline surface of degrees `degree_u`, `degree_v` through every point of a
/// `rows × cols` grid (`points` flat xyz, row-major, rows along u): `S(ū_k, v̄_l) = Q_kl`.
///
/// NURBS Book §9.2.5: the parameters `ū_k` are those of `kind` ("uniform" `|Δ|⁰`, "chord"
/// `|Δ|`, "centripetal" `|Δ|^½`) computed along every column `Q_0l … Q_{rows−1,l}`, each
/// normalised to `[0, 1]` by its total and averaged over the columns (a column whose points
/// all coincide is left out); `v̄_l` likewise along the rows. Knots by averaging (eq. 9.8) on
/// both. Then every column is interpolated in u (one banded solve with `cols·3` right sides,
/// `crate::interp::global`), and every row of the resulting control points in v. The
/// domain is `[0, 1]²`.
///
/// # Errors
/// In this order: [`SurfaceError::NetCoordinateCount`] (grid size mismatch), [`Error::TooLarge`]
/// for the grid, [`Error::NotFinite`], [`Error::DegreeOutOfRange`] for a degree of 0 or above 10,
/// [`Error::TooFewDataPoints`] (inside [`Error::InArgument`] `degreeU`/`degreeV`) when `rows <
/// degree_u + 1` or `cols < degree_v + 1` (or below 2), [`Error::CoincidentPoints`] when every
/// column (row) is a single repeated point, [`crate::error::InterpError::ParamsNotIncreasing`] when
/// the averaged parameters repeat.
pub fn interpolate_surface(
    points: &[f64],
    rows: usize,
    cols: usize,
    degree_u: usize,
    degree_v: usize,
    kind: Parameterization,
) -> Result<BSplineSurface> {
    check_grid(points, rows, cols, degree_u, degree_v)?;
    let (params_u, params_v) = grid_params(points, rows, cols, kind)?;
    let knots_u = averaging_knots(&params_u, degree_u, false, false);
    let knots_v = averaging_knots(&params_v, degree_v, false, false);
    // Columns in u: data point k is row k of the grid, cols·3 numbers (row-major already).
    let r = solve(points, 3 * cols, degree_u, &params_u, &knots_u)?;
    // Rows in v: data point l is column l of R, rows·3 numbers.
    let transposed = transpose(&r, rows, cols);
    let net_t = solve(&transposed, 3 * rows, degree_v, &params_v, &knots_v)?;
    let net = transpose(&net_t, cols, rows);
    BSplineSurface::from_flat(&net, rows, cols, degree_u, degree_v, knots_u, knots_v, None)
}

/// The parameters [`interpolate_surface`] gives the grid points: `(ū_0 … ū_{rows−1},
/// v̄_0 … v̄_{cols−1})`, so that `S(ū_k, v̄_l) = Q_kl`. Per column `l`, the cumulative steps
/// `|Q_kl − Q_{k−1,l}|^α` (α = 0 uniform, ½ centripetal, 1 chord) over their total, averaged
/// over the columns that are not one repeated point (NURBS Book eq. 9.5–9.6 with §9.2.5's
/// averaging); `v̄` likewise along the rows. Both run from 0 to 1.
///
/// # Errors
/// [`SurfaceError::NetCoordinateCount`] (grid size mismatch), [`Error::TooLarge`],
/// [`Error::NotFinite`], [`Error::CoincidentPoints`] when every column (row) is a single repeated
/// point.
pub fn grid_params(
    points: &[f64],
    rows: usize,
    cols: usize,
    kind: Parameterization,
) -> Result<(Vec<f64>, Vec<f64>)> {
    check_grid_size(points, rows, cols)?;
    let grid: Vec<DVec3> = points.chunks_exact(3).map(DVec3::from_slice).collect();
    let at = |i: usize, j: usize| grid[i * cols + j];
    let params_u = averaged_params(rows, cols, kind, at)?;
    let params_v = averaged_params(cols, rows, kind, |k, l| at(l, k))?;
    Ok((params_u, params_v))
}

/// The grid's size against its coordinates, and its numbers finite.
fn check_grid_size(points: &[f64], rows: usize, cols: usize) -> Result<()> {
    let count = checked_count("rows·cols", rows, cols, MAX_SAMPLES)?;
    if points.len() != 3 * count {
        return Err(Error::Surface(SurfaceError::NetCoordinateCount {
            rows,
            cols,
            got: points.len(),
        }));
    }
    check_all_coordinates(points, "coordinate")
}

/// The checks of [`interpolate_surface`] before the parameters: the grid's size, its numbers,
/// and the degrees against it (so a caller parsing `kind` can report these first).
///
/// # Errors
/// As [`interpolate_surface`], up to [`Error::TooFewDataPoints`].
pub fn check_grid(
    points: &[f64],
    rows: usize,
    cols: usize,
    degree_u: usize,
    degree_v: usize,
) -> Result<()> {
    check_grid_size(points, rows, cols)?;
    for (name, degree, count) in [("degreeU", degree_u, rows), ("degreeV", degree_v, cols)] {
        check_interpolation_degree(degree).map_err(|e| in_argument(name, e))?;
        let needed = (degree + 1).max(2);
        if count < needed {
            return Err(in_argument(
                name,
                Error::TooFewDataPoints {
                    needed,
                    got: count,
                    what: "interpolating-surface",
                },
            ));
        }
    }
    Ok(())
}

/// Parameters along the `lines` lines of `length` points each (`point(k, l)` is point `k` of
/// line `l`): per line cumulative steps over their total, averaged over the lines that are
/// not a single repeated point.
fn averaged_params(
    length: usize,
    lines: usize,
    kind: Parameterization,
    point: impl Fn(usize, usize) -> DVec3,
) -> Result<Vec<f64>> {
    let alpha = kind.alpha();
    let mut sum = vec![0.0; length];
    let mut used = 0usize;
    let mut steps = vec![0.0; length];
    for l in 0..lines {
        for (k, step) in steps.iter_mut().enumerate().skip(1) {
            let d = (point(k, l) - point(k - 1, l)).length();
            *step = if alpha == 0.0 { 1.0 } else { d.powf(alpha) };
        }
        let total: f64 = steps.iter().sum();
        if total <= 0.0 {
            continue;
        }
        used += 1;
        let mut cumulative = 0.0;
        for (k, s) in sum.iter_mut().enumerate() {
            cumulative += steps[k];
            *s += if k + 1 == length {
                1.0
            } else {
                cumulative / total
            };
        }
    }
    if used == 0 {
        return Err(Error::CoincidentPoints { index: 0, kind });
    }
    Ok(sum.iter().map(|s| s / used as f64).collect())
}

/// The control points of the interpolant of `data` (`dim` numbers per point) at `params`
/// on `knots`, flat.
fn solve(
    data: &[f64],
    dim: usize,
    degree: usize,
    params: &[f64],
    knots: &[f64],
) -> Result<Vec<f64>> {
    let options = InterpolationOptions {
        knots: Some(knots.to_vec()),
        ..Default::default()
    };
    Setup::new_flat(data, dim, degree, params, &options)?.solve()
}

/// A `rows × cols` grid of xyz points (row-major) written column-major.
fn transpose(flat: &[f64], rows: usize, cols: usize) -> Vec<f64> {
    let mut out = vec![0.0; flat.len()];
    for i in 0..rows {
        for j in 0..cols {
            let (from, to) = (3 * (i * cols + j), 3 * (j * rows + i));
            out[to..to + 3].copy_from_slice(&flat[from..from + 3]);
        }
    }
    out
}
