//! `interpolateBSpline`, `approximateBSpline` and `bsplineInterpolationSystem` for JavaScript:
//! global B-spline interpolation (open with optional end derivatives, or closed) and the
//! least-squares fit with exact ends.

use super::super::{bool_option, numbers, option_entries, optional_numbers, whole, JsBSplineCurve};
use super::ParamArg;
use crate::error::Error;
use crate::geom::{check_dim, check_flat};
use crate::interp::global::{check_data_shape, Setup};
use crate::interp::least_squares::{approximate_flat, check_fit_shape, curve_from};
use crate::interp::InterpolationOptions;
use crate::wasm::ApiError;
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// The option names `interpolateBSpline` and `bsplineInterpolationSystem` accept, and their
/// list as the error message shows it.
const INTERPOLATION_OPTIONS: (&[&str], &str) = (
    &["knots", "startDerivative", "endDerivative", "closed"],
    "\"knots\", \"startDerivative\", \"endDerivative\", \"closed\"",
);

/// The option names `approximateBSpline` accepts, and their list for the message.
const APPROXIMATION_OPTIONS: (&[&str], &str) = (&["knots"], "\"knots\"");

/// The options object as read from JavaScript, before the points are checked.
#[derive(Default)]
struct RawOptions {
    knots: Option<Vec<f64>>,
    start_derivative: Option<Vec<f64>>,
    end_derivative: Option<Vec<f64>>,
    closed: bool,
}

impl RawOptions {
    /// Reads `options` ([`option_entries`]: `undefined`/`null` give the defaults, keys among
    /// `allowed`), each value of its type ([`Error::ArgumentType`]).
    fn read(
        options: &JsValue,
        (allowed, listed): (&[&str], &'static str),
    ) -> Result<Self, ApiError> {
        let mut out = RawOptions::default();
        for (key, value) in option_entries(options, (allowed, listed))? {
            match key.as_str() {
                "knots" => out.knots = optional_numbers("knots", &value)?,
                "startDerivative" => {
                    out.start_derivative = optional_numbers("startDerivative", &value)?
                }
                "endDerivative" => out.end_derivative = optional_numbers("endDerivative", &value)?,
                _ => out.closed = bool_option("closed", &value)?.unwrap_or(false),
            }
        }
        Ok(out)
    }

    fn derivatives(&self) -> usize {
        usize::from(self.start_derivative.is_some()) + usize::from(self.end_derivative.is_some())
    }

    /// The core options for points of dimension `dim`, derivatives flat
    /// ([`Error::ArgumentLength`] for a derivative of another length).
    fn typed(&self, dim: usize) -> Result<InterpolationOptions<Vec<f64>>, Error> {
        Ok(InterpolationOptions {
            knots: self.knots.clone(),
            start_derivative: vector("startDerivative", &self.start_derivative, dim)?,
            end_derivative: vector("endDerivative", &self.end_derivative, dim)?,
            closed: self.closed,
        })
    }
}

/// An optional vector of `dim` numbers.
fn vector(
    name: &'static str,
    values: &Option<Vec<f64>>,
    dim: usize,
) -> Result<Option<Vec<f64>>, Error> {
    match values {
        Some(v) if v.len() != dim => Err(Error::ArgumentLength {
            name,
            expected: dim,
            got: v.len(),
        }),
        _ => Ok(values.clone()),
    }
}

/// The arguments the three functions share, read from JavaScript in one order: the options
/// object (its keys among `allowed`), points, params, dim (checked: 2 or 3) and degree.
struct FitArgs {
    options: RawOptions,
    points: Vec<f64>,
    params: ParamArg,
    dim: usize,
    degree: usize,
}

impl FitArgs {
    fn read(
        points: &JsValue,
        dim: f64,
        degree: f64,
        params: &JsValue,
        options: &JsValue,
        allowed: (&'static [&'static str], &'static str),
    ) -> Result<Self, ApiError> {
        let options = RawOptions::read(options, allowed)?;
        let points = numbers("points", points)?;
        let params = ParamArg::read(params)?;
        let dim = whole("dim", dim)?;
        let degree = whole("degree", degree)?;
        Ok(FitArgs {
            options,
            points,
            params,
            dim: check_dim(dim)?,
            degree,
        })
    }

    /// The interpolation setup, checked in the documented order: points (coordinate count,
    /// finite), degree and number of points, params, options. Written once for both dimensions.
    fn setup(self) -> Result<Setup, Error> {
        let FitArgs {
            options,
            points,
            params,
            dim,
            degree,
        } = self;
        check_flat(&points, dim)?;
        let derivatives = if options.closed {
            0
        } else {
            options.derivatives()
        };
        check_data_shape(points.len() / dim, degree, derivatives, options.closed)?;
        let params = params.resolve_flat(&points, dim)?;
        let typed = options.typed(dim)?;
        Setup::new_flat(&points, dim, degree, &params, &typed)
    }
}

/// `interpolateBSpline(points, dim, degree, params, options?)`: the B-spline of degree 1..10
/// through every point, C(t_i) = p_i. `params`: one per point, strictly increasing (or a kind
/// "uniform" | "chord" | "centripetal", or an exponent α in [0, 1]). `options`: `{ knots?, startDerivative?,
/// endDerivative?, closed? }` — explicit knots (size + degree + 1 of them, checked against
/// Schoenberg–Whitney), C'(t_0) and C'(t_n) (dim numbers each, with respect to the parameter),
/// or a closed periodic curve (last point = first). Default knots: averaging.
#[wasm_bindgen(js_name = interpolateBSpline)]
pub fn interpolate_bspline(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    degree: f64,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[] | string | number")]
    params: JsValue,
    #[wasm_bindgen(
        unchecked_optional_param_type = "{ knots?: Float64Array | number[]; startDerivative?: Float64Array | number[]; endDerivative?: Float64Array | number[]; closed?: boolean }"
    )]
    options: JsValue,
) -> Result<JsBSplineCurve, ApiError> {
    let args = FitArgs::read(
        &points,
        dim,
        degree,
        &params,
        &options,
        INTERPOLATION_OPTIONS,
    )?;
    let dim = args.dim;
    let setup = args.setup()?;
    let solution = setup.solve()?;
    Ok(if dim == 2 {
        JsBSplineCurve::from_2d(setup.curve(&solution)?)
    } else {
        JsBSplineCurve::from_3d(setup.curve(&solution)?)
    })
}

/// `approximateBSpline(points, dim, degree, count, params, options?)`: the least-squares
/// B-spline with `count` control points (in [degree + 1, number of points]) through the first
/// and last point (NURBS Book 9.4.1). `options`: `{ knots? }` (clamped, count + degree + 1).
#[wasm_bindgen(js_name = approximateBSpline)]
pub fn approximate_bspline(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    degree: f64,
    count: f64,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[] | string | number")]
    params: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "{ knots?: Float64Array | number[] }")]
    options: JsValue,
) -> Result<JsBSplineCurve, ApiError> {
    let args = FitArgs::read(
        &points,
        dim,
        degree,
        &params,
        &options,
        APPROXIMATION_OPTIONS,
    )?;
    let count = whole("count", count)?;
    let FitArgs {
        options,
        points,
        params,
        dim,
        degree,
    } = args;
    let points = &*points;
    check_flat(points, dim)?;
    check_fit_shape(points.len() / dim, degree)?;
    let params = params.resolve_flat(points, dim)?;
    let knots = options.knots.as_deref();
    let (control, knots) = approximate_flat(points, dim, degree, count, &params, knots)?;
    Ok(if dim == 2 {
        JsBSplineCurve::from_2d(curve_from(&control, degree, knots)?)
    } else {
        JsBSplineCurve::from_3d(curve_from(&control, degree, knots)?)
    })
}

/// The layout `bsplineInterpolationSystem` returns.
#[derive(Serialize)]
struct SystemJs {
    size: usize,
    matrix: Vec<f64>,
    rhs: Vec<f64>,
    solution: Vec<f64>,
    knots: Vec<f64>,
    rows: Vec<&'static str>,
}

/// `bsplineInterpolationSystem(points, dim, degree, params, options?)`: the system
/// `interpolateBSpline` solves, for display: `{ size, matrix (size² row-major), rhs (size·dim),
/// solution (size·dim, the control points; closed: the distinct ones), knots, rows ("point" |
/// "start-derivative" | "end-derivative" per row) }`. Above 64 unknowns: an Error.
#[wasm_bindgen(
    js_name = bsplineInterpolationSystem,
    unchecked_return_type = "{ size: number; matrix: number[]; rhs: number[]; solution: number[]; knots: number[]; rows: string[] }"
)]
pub fn bspline_interpolation_system(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    degree: f64,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[] | string | number")]
    params: JsValue,
    #[wasm_bindgen(
        unchecked_optional_param_type = "{ knots?: Float64Array | number[]; startDerivative?: Float64Array | number[]; endDerivative?: Float64Array | number[]; closed?: boolean }"
    )]
    options: JsValue,
) -> Result<JsValue, ApiError> {
    let args = FitArgs::read(
        &points,
        dim,
        degree,
        &params,
        &options,
        INTERPOLATION_OPTIONS,
    )?;
    let s = args.setup()?.system()?;
    let s = SystemJs {
        size: s.size,
        matrix: s.matrix,
        rhs: s.rhs,
        solution: s.solution,
        knots: s.knots,
        rows: s.rows.iter().map(|r| r.as_str()).collect(),
    };
    Ok(serde_wasm_bindgen::to_value(&s)?)
}
