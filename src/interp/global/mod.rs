//! Global B-spline interpolation (NURBS Book §9.2.1–9.2.2, the Croatian notes' "interpolacijska
//! B-krivulja"): the curve `C(u) = Σ N_{i,p}(u) P_i` of degree `p` through every data point,
//! `C(t_i) = p_i`, optionally with end derivatives `C'(t_0) = D_0`, `C'(t_n) = D_n` (with respect
//! to the parameter), or closed (periodic, `C^{p−1}` across the seam).
//!
//! One equation per row, one unknown control point per column: `n + 1` point rows plus one row
//! per end derivative, each derivative row next to its end's point row (the Croatian notes'
//! order: `C(t_0)`, `C'(t_0)`, `C(t_1)`, …). The collocation matrix is banded (at most `p + 1`
//! non-zeros per row) and solved in O(n·p²) by LU with partial pivoting on the band (see
//! [`super::banded`]); knots are chosen by averaging ([`knots`]) unless given, and given knots
//! are checked against the Schoenberg–Whitney condition, without which the system is singular.
//!
//! ```
//! use splinelab::interp::{interpolation_system, InterpolationOptions, RowKind};
//! use splinelab::DVec2;
//! // The Croatian notes' example: five points at 0..4, degree 2, C'(0) given, knots 0 0 0 1 2 3 4 4 4.
//! let points = [(0., 0.), (2., 4.), (4., 2.), (6., 6.), (8., 0.)].map(|(x, y)| DVec2::new(x, y));
//! let options = InterpolationOptions {
//!     knots: Some(vec![0., 0., 0., 1., 2., 3., 4., 4., 4.]),
//!     start_derivative: Some(DVec2::new(2.0, 8.0)),
//!     ..Default::default()
//! };
//! let s = interpolation_system(&points, 2, &[0., 1., 2., 3., 4.], &options).unwrap();
//! assert_eq!(&s.matrix[6..12], &[-2.0, 2.0, 0.0, 0.0, 0.0, 0.0]); // −2 r_0 + 2 r_1 = D_0
//! assert_eq!(&s.matrix[12..18], &[0.0, 0.5, 0.5, 0.0, 0.0, 0.0]); // (r_1 + r_2)/2 = p_1
//! assert_eq!(s.rows[1], RowKind::StartDerivative);
//! assert_eq!(s.solution[4], DVec2::new(7.0, 12.0));
//! ```

mod closed;
pub mod knots;
mod system;

pub use system::RowKind;

use crate::bspline::{BSplineCurve, BasisScratch, KnotVector};
use crate::error::{check_coordinate, check_coordinate_of, Error, Result};
use crate::geom::Cartesian;
use system::Collocation;

/// The highest degree interpolation and least squares accept (the syllabus' 1–10).
pub const MAX_INTERPOLATION_DEGREE: usize = 10;

/// The most data points interpolation and least squares accept: the banded factor takes up to
/// `(3p + 1)·8` bytes per row (248 MB at this cap for `p = 10`), inside wasm's 4 GB.
pub const MAX_INTERPOLATION_POINTS: usize = 1 << 20;

/// The largest system [`interpolation_system`] writes out dense.
pub const MAX_SYSTEM_SIZE: usize = 64;

/// How [`interpolate_bspline`] builds the curve; `Default` is plain interpolation with averaging
/// knots.
#[derive(Debug, Clone, PartialEq)]
pub struct InterpolationOptions<C> {
    /// Explicit knots, `size + p + 1` of them for `size` = points + derivatives (not with
    /// `closed`).
    pub knots: Option<Vec<f64>>,
    /// `C'(t_0)`, with respect to the parameter (adds one control point).
    pub start_derivative: Option<C>,
    /// `C'(t_n)`, with respect to the parameter (adds one control point).
    pub end_derivative: Option<C>,
    /// Periodic interpolation: the last point must equal the first.
    pub closed: bool,
}

impl<C> Default for InterpolationOptions<C> {
    fn default() -> Self {
        InterpolationOptions {
            knots: None,
            start_derivative: None,
            end_derivative: None,
            closed: false,
        }
    }
}

/// The solved interpolation system, for display: `matrix · solution = rhs`.
#[derive(Debug, Clone, PartialEq)]
pub struct InterpolationSystem<C> {
    /// Number of unknowns (= rows).
    pub size: usize,
    /// The matrix, row-major `size × size`: the rows the banded solver solved, written dense.
    pub matrix: Vec<f64>,
    /// One right side per row: a data point or a derivative.
    pub rhs: Vec<C>,
    /// The control points found (for a closed curve, the `size` distinct ones).
    pub solution: Vec<C>,
    /// The knot vector of the curve.
    pub knots: Vec<f64>,
    /// What each row states.
    pub rows: Vec<RowKind>,
}

/// The system's name in [`Error::SingularSystem`].
const WHAT: &str = "bspline-interpolation-system";

/// The B-spline of degree `degree` (1..=10) through `points` at `params`, `C(t_i) = p_i`.
///
/// Default knots by averaging (NURBS Book eq. 9.8; with end derivatives the rule of eq. 9.22 and
/// its one-sided forms, see [`knots`]); degree 1 gives the polyline. With `closed`, the
/// periodic spline of scipy's `make_interp_spline(…, bc_type="periodic")`: `p` control points
/// wrap ([`BSplineCurve::wrapped`]), the domain is `[t_0, t_n]`.
///
/// # Errors
/// In this order: [`Error::NotFinite`], [`Error::CoordinateTooLarge`] (coordinates),
/// [`Error::DegreeOutOfRange`], [`Error::TooLarge`] above [`MAX_INTERPOLATION_POINTS`] points,
/// [`Error::TooFewDataPoints`] (`max(2, p + 1 − derivatives)` points, closed `max(3, p + 1)`),
/// [`crate::error::InterpError::ParamCount`], [`Error::NotFinite`] (params),
/// [`crate::error::InterpError::ParamsNotIncreasing`], [`Error::ConflictingOptions`] (closed with
/// derivatives or knots), [`Error::NotFinite`] (derivatives),
/// [`crate::error::InterpError::NotClosed`], the knot errors of [`KnotVector::new`], a parameter
/// outside the knots' domain ([`Error::InArgument`] `params[i]`),
/// [`crate::error::InterpError::SchoenbergWhitney`], and [`Error::SingularSystem`] if elimination
/// still meets a zero pivot.
pub fn interpolate_bspline<C: Cartesian>(
    points: &[C],
    degree: usize,
    params: &[f64],
    options: &InterpolationOptions<C>,
) -> Result<BSplineCurve<C>> {
    let setup = Setup::new(points, degree, params, options)?;
    let solution = setup.solve()?;
    setup.curve(&solution)
}

/// The system [`interpolate_bspline`] solves, solved and written out dense for display (the
/// Croatian notes' 6 × 6 matrix for their example).
///
/// # Errors
/// As [`interpolate_bspline`], then [`Error::TooLarge`] above [`MAX_SYSTEM_SIZE`] unknowns.
pub fn interpolation_system<C: Cartesian>(
    points: &[C],
    degree: usize,
    params: &[f64],
    options: &InterpolationOptions<C>,
) -> Result<InterpolationSystem<C>> {
    let s = Setup::new(points, degree, params, options)?.system()?;
    Ok(InterpolationSystem {
        size: s.size,
        matrix: s.matrix,
        rhs: s.rhs.chunks(C::DIM).map(C::from_slice).collect(),
        solution: s.solution.chunks(C::DIM).map(C::from_slice).collect(),
        knots: s.knots,
        rows: s.rows,
    })
}

/// The checks on the data before the parameters (see [`interpolate_bspline`]'s order): finite
/// coordinates, the degree, then the number of points, `max(2, p + 1 − derivatives)` (closed:
/// `max(3, p + 1)`).
pub(crate) fn check_data<C: Cartesian>(
    points: &[C],
    degree: usize,
    derivatives: usize,
    closed: bool,
) -> Result<()> {
    check_points(points)?;
    check_data_shape(points.len(), degree, derivatives, closed)
}

/// [`check_data`] after the coordinates: the degree, then the number of points `count`.
pub(crate) fn check_data_shape(
    count: usize,
    degree: usize,
    derivatives: usize,
    closed: bool,
) -> Result<()> {
    check_interpolation_degree(degree)?;
    check_point_cap(count)?;
    let (needed, what) = if closed {
        (3.max(degree + 1), "closed-interpolating-bspline")
    } else {
        (
            2.max((degree + 1).saturating_sub(derivatives)),
            "interpolating-bspline",
        )
    };
    if count < needed {
        return Err(Error::TooFewDataPoints {
            needed,
            got: count,
            what,
        });
    }
    Ok(())
}

/// Checks the number of data points against [`MAX_INTERPOLATION_POINTS`] ([`Error::TooLarge`]).
pub(crate) fn check_point_cap(count: usize) -> Result<()> {
    if count > MAX_INTERPOLATION_POINTS {
        return Err(Error::TooLarge {
            what: "data-point-count",
            value: count,
            max: MAX_INTERPOLATION_POINTS,
        });
    }
    Ok(())
}

/// Checks a degree for interpolation or least squares: `1..=MAX_INTERPOLATION_DEGREE`.
pub(crate) fn check_interpolation_degree(degree: usize) -> Result<()> {
    if degree == 0 || degree > MAX_INTERPOLATION_DEGREE {
        return Err(Error::DegreeOutOfRange {
            degree,
            max: MAX_INTERPOLATION_DEGREE,
        });
    }
    Ok(())
}

/// Checks every coordinate is finite and not too large ([`Error::NotFinite`],
/// [`Error::CoordinateTooLarge`] naming `coordinate i·dim + k`).
pub(crate) fn check_points<C: Cartesian>(points: &[C]) -> Result<()> {
    for (i, p) in points.iter().enumerate() {
        for k in 0..C::DIM {
            check_coordinate("coordinate", Some(i * C::DIM + k), p.coord(k))?;
        }
    }
    Ok(())
}

pub(crate) use super::params::check_params;

/// Checks every parameter lies in the knots' domain ([`Error::InArgument`] `params[i]` around
/// [`Error::ParameterOutOfRange`]).
pub(crate) fn check_params_in_domain(params: &[f64], knots: &KnotVector) -> Result<()> {
    let (a, b) = knots.domain();
    for (i, &t) in params.iter().enumerate() {
        if t < a || t > b {
            return Err(Error::InArgument {
                name: "params",
                index: Some(i),
                source: Box::new(Error::ParameterOutOfRange {
                    name: "t",
                    value: t,
                    min: a,
                    max: b,
                }),
            });
        }
    }
    Ok(())
}

/// The first option `closed` excludes, with the reason.
fn conflict_with_closed<C>(
    options: &InterpolationOptions<C>,
) -> Option<(&'static str, &'static str)> {
    const NO_ENDS: &str = "closed-has-no-ends";
    if options.start_derivative.is_some() {
        Some(("startDerivative", NO_ENDS))
    } else if options.end_derivative.is_some() {
        Some(("endDerivative", NO_ENDS))
    } else if options.knots.is_some() {
        Some(("knots", "closed-knots-computed"))
    } else {
        None
    }
}

/// A validated interpolation problem: knots, rows and right sides.
pub(crate) struct Setup {
    knots: KnotVector,
    rows: Collocation,
    rhs: Vec<f64>,
    dim: usize,
}

impl Setup {
    fn new<C: Cartesian>(
        points: &[C],
        degree: usize,
        params: &[f64],
        options: &InterpolationOptions<C>,
    ) -> Result<Self> {
        let derivatives = usize::from(options.start_derivative.is_some())
            + usize::from(options.end_derivative.is_some());
        check_data(points, degree, derivatives, options.closed)?;
        let flat_vector = |d: &Option<C>| d.map(|v| flatten(&[v]));
        let options = InterpolationOptions {
            knots: options.knots.clone(),
            start_derivative: flat_vector(&options.start_derivative),
            end_derivative: flat_vector(&options.end_derivative),
            closed: options.closed,
        };
        Setup::new_flat(&flatten(points), C::DIM, degree, params, &options)
    }

    /// [`Setup::new`] after [`check_data`], on flat coordinates of dimension `dim` (the
    /// derivatives `dim` numbers each): written once for every dimension.
    #[inline(never)]
    pub(crate) fn new_flat(
        coords: &[f64],
        dim: usize,
        degree: usize,
        params: &[f64],
        options: &InterpolationOptions<Vec<f64>>,
    ) -> Result<Self> {
        let count = coords.len() / dim;
        check_params(params, count)?;
        if options.closed {
            if let Some((first, reason)) = conflict_with_closed(options) {
                return Err(Error::ConflictingOptions {
                    first,
                    second: "closed",
                    reason,
                });
            }
            return closed::setup(coords, dim, degree, params);
        }
        for (name, d) in [
            ("startDerivative", &options.start_derivative),
            ("endDerivative", &options.end_derivative),
        ] {
            if let Some(d) = d {
                for (k, &v) in d.iter().enumerate() {
                    check_coordinate_of(name, k, v)?;
                }
            }
        }
        let (start, end) = (&options.start_derivative, &options.end_derivative);
        let size = count + usize::from(start.is_some()) + usize::from(end.is_some());
        let knots = match &options.knots {
            Some(k) => k.clone(),
            None => knots::averaging_knots(params, degree, start.is_some(), end.is_some()),
        };
        let knots = KnotVector::new(knots, degree, size)?;
        check_params_in_domain(params, &knots)?;
        let n = count - 1;
        let mut sites: Vec<(f64, RowKind)> = Vec::with_capacity(size);
        let mut rhs: Vec<f64> = Vec::with_capacity(size * dim);
        for (i, (&t, p)) in params.iter().zip(coords.chunks_exact(dim)).enumerate() {
            if i == n {
                if let Some(d) = end {
                    sites.push((t, RowKind::EndDerivative));
                    rhs.extend_from_slice(d);
                }
            }
            sites.push((t, RowKind::Point));
            rhs.extend_from_slice(p);
            if i == 0 {
                if let Some(d) = start {
                    sites.push((t, RowKind::StartDerivative));
                    rhs.extend_from_slice(d);
                }
            }
        }
        let taus: Vec<f64> = sites.iter().map(|s| s.0).collect();
        knots::check_schoenberg_whitney(knots.as_slice(), degree, &taus)?;
        let mut rows = Collocation::new(degree, size, false);
        let mut scratch = BasisScratch::default();
        for &(t, kind) in &sites {
            rows.push(&knots, t, kind, &mut scratch);
        }
        Ok(Setup {
            knots,
            rows,
            rhs,
            dim,
        })
    }

    /// The system solved and written out dense, right sides and solution flat
    /// ([`Error::TooLarge`] above [`MAX_SYSTEM_SIZE`] unknowns).
    #[inline(never)]
    pub(crate) fn system(&self) -> Result<InterpolationSystem<f64>> {
        let size = self.rows.size;
        if size > MAX_SYSTEM_SIZE {
            return Err(Error::TooLarge {
                what: "interpolation-system-size",
                value: size,
                max: MAX_SYSTEM_SIZE,
            });
        }
        let solution = self.solve()?;
        Ok(InterpolationSystem {
            size,
            matrix: self.rows.dense(),
            rhs: self.rhs.clone(),
            solution,
            knots: self.knots.as_slice().to_vec(),
            rows: self.rows.kinds.clone(),
        })
    }

    /// The control points (the distinct ones for a closed curve), flat.
    pub(crate) fn solve(&self) -> Result<Vec<f64>> {
        let mut x = self.rhs.clone();
        self.rows.solve(&mut x, self.dim, WHAT)?;
        Ok(x)
    }

    /// The curve with the solved control points (wrapped for a closed curve).
    pub(crate) fn curve<C: Cartesian>(&self, solution: &[f64]) -> Result<BSplineCurve<C>> {
        let distinct: Vec<C> = solution.chunks(C::DIM).map(C::from_slice).collect();
        let p = self.rows.degree;
        let knots = self.knots.as_slice().to_vec();
        if self.rows.cyclic {
            let n = distinct.len();
            let all: Vec<C> = (0..n + p).map(|j| distinct[j % n]).collect();
            Ok(BSplineCurve::new(all, p, knots, None)?.with_wrapped(p))
        } else {
            BSplineCurve::new(distinct, p, knots, None)
        }
    }
}

/// Flat coordinates of points.
pub(crate) fn flatten<C: Cartesian>(points: &[C]) -> Vec<f64> {
    let mut out = vec![0.0; points.len() * C::DIM];
    for (p, slot) in points.iter().zip(out.chunks_mut(C::DIM)) {
        p.write_to(slot);
    }
    out
}
