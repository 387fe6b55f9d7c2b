//! `interpolateBSpline`, `approximateBSpline` and `bsplineInterpolationSystem` for JavaScript:
//! global B-spline interpolation (open with optional end derivatives, or closed) and the
//! least-squares fit with exact ends.

use super::super::{numbers, optional_numbers, whole, JsBSplineCurve};
use super::ParamArg;
use crate::error::Error;
use crate::geom::{check_dim, points_from_flat, Cartesian};
use crate::interp::global::check_data;
use crate::interp::least_squares::check_fit_data;
use crate::interp::{self, InterpolationOptions, InterpolationSystem};
use glam::{DVec2, DVec3};
use serde::Serialize;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// The option names `interpolateBSpline` and `bsplineInterpolationSystem` accept.
const INTERPOLATION_OPTIONS: &str = "\"knots\", \"startDerivative\", \"endDerivative\", \"closed\"";

/// The option names `approximateBSpline` accepts.
const APPROXIMATION_OPTIONS: &str = "\"knots\"";

/// The options object as read from JavaScript, before the points are checked.
#[derive(Default)]
struct RawOptions {
    knots: Option<Vec<f64>>,
    start_derivative: Option<Vec<f64>>,
    end_derivative: Option<Vec<f64>>,
    closed: bool,
}

impl RawOptions {
    /// Reads `options`: `undefined`/`null` give the defaults; otherwise a plain object whose
    /// keys are among `allowed` ([`Error::UnknownOption`] naming the first other key), each
    /// value of its type ([`Error::ArgumentType`]).
    fn read(options: &JsValue, allowed: &'static str) -> Result<Self, JsError> {
        let mut out = RawOptions::default();
        if options.is_undefined() || options.is_null() {
            return Ok(out);
        }
        let object = match options.dyn_ref::<js_sys::Object>() {
            Some(o) if options.is_object() && !js_sys::Array::is_array(options) => o,
            _ => {
                return Err(Error::ArgumentType {
                    name: "options",
                    expected: "an object",
                    got: type_name(options),
                }
                .into())
            }
        };
        for key in js_sys::Object::keys(object).iter() {
            let key = key.as_string().unwrap_or_default();
            let quoted = format!("\"{key}\"");
            if !allowed.split(", ").any(|k| k == quoted) {
                return Err(Error::UnknownOption {
                    name: "options",
                    value: key,
                    expected: allowed,
                }
                .into());
            }
            let value = js_sys::Reflect::get(object, &JsValue::from_str(&key))
                .map_err(|_| JsError::new("options: a key could not be read"))?;
            match key.as_str() {
                "knots" => out.knots = optional_numbers("knots", &value)?,
                "startDerivative" => {
                    out.start_derivative = optional_numbers("startDerivative", &value)?
                }
                "endDerivative" => out.end_derivative = optional_numbers("endDerivative", &value)?,
                _ => {
                    out.closed = if value.is_undefined() || value.is_null() {
                        false
                    } else {
                        value.as_bool().ok_or_else(|| Error::ArgumentType {
                            name: "closed",
                            expected: "a boolean",
                            got: type_name(&value),
                        })?
                    }
                }
            }
        }
        Ok(out)
    }

    fn derivatives(&self) -> usize {
        usize::from(self.start_derivative.is_some()) + usize::from(self.end_derivative.is_some())
    }

    /// The core options for points of dimension `C::DIM` ([`Error::ArgumentLength`] for a
    /// derivative of another length).
    fn typed<C: Cartesian>(&self) -> Result<InterpolationOptions<C>, Error> {
        Ok(InterpolationOptions {
            knots: self.knots.clone(),
            start_derivative: vector::<C>("startDerivative", self.start_derivative.as_deref())?,
            end_derivative: vector::<C>("endDerivative", self.end_derivative.as_deref())?,
            closed: self.closed,
        })
    }
}

/// An optional vector of `C::DIM` numbers.
fn vector<C: Cartesian>(name: &'static str, values: Option<&[f64]>) -> Result<Option<C>, Error> {
    match values {
        None => Ok(None),
        Some(v) if v.len() == C::DIM => Ok(Some(C::from_slice(v))),
        Some(v) => Err(Error::ArgumentLength {
            name,
            expected: C::DIM,
            got: v.len(),
        }),
    }
}

/// `typeof value`, with `null` and arrays told apart (for messages).
fn type_name(value: &JsValue) -> String {
    if value.is_null() {
        "null".into()
    } else if js_sys::Array::is_array(value) {
        "an array".into()
    } else {
        value.js_typeof().as_string().unwrap_or_default()
    }
}

/// Points, parameters and core options, checked.
type Prepared<C> = (Vec<C>, Vec<f64>, InterpolationOptions<C>);

/// The inputs shared by the three functions, checked in the documented order for dimension
/// `C`: points (coordinate count, finite), degree and number of points, params, options.
fn prepare<C: Cartesian>(
    points: &[f64],
    degree: usize,
    params: &ParamArg,
    options: &RawOptions,
) -> Result<Prepared<C>, Error> {
    let points: Vec<C> = points_from_flat(points)?;
    let derivatives = if options.closed {
        0
    } else {
        options.derivatives()
    };
    check_data(&points, degree, derivatives, options.closed)?;
    let params = params.resolve(&points)?;
    let typed = options.typed::<C>()?;
    Ok((points, params, typed))
}

fn interpolate<C: Cartesian>(
    points: &[f64],
    degree: usize,
    params: &ParamArg,
    options: &RawOptions,
) -> Result<crate::BSplineCurve<C>, Error> {
    let (points, params, options) = prepare::<C>(points, degree, params, options)?;
    interp::interpolate_bspline(&points, degree, &params, &options)
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
) -> Result<JsBSplineCurve, JsError> {
    let options = RawOptions::read(&options, INTERPOLATION_OPTIONS)?;
    let points = &*numbers("points", &points)?;
    let params = ParamArg::read(&params)?;
    let dim = whole("dim", dim)?;
    let degree = whole("degree", degree)?;
    Ok(match check_dim(dim)? {
        2 => JsBSplineCurve::from_2d(interpolate::<DVec2>(points, degree, &params, &options)?),
        _ => JsBSplineCurve::from_3d(interpolate::<DVec3>(points, degree, &params, &options)?),
    })
}

fn approximate<C: Cartesian>(
    points: &[f64],
    degree: usize,
    count: usize,
    params: &ParamArg,
    options: &RawOptions,
) -> Result<crate::BSplineCurve<C>, Error> {
    let points: Vec<C> = points_from_flat(points)?;
    check_fit_data(&points, degree)?;
    let params = params.resolve(&points)?;
    interp::approximate_bspline(&points, degree, count, &params, options.knots.as_deref())
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
) -> Result<JsBSplineCurve, JsError> {
    let options = RawOptions::read(&options, APPROXIMATION_OPTIONS)?;
    let points = &*numbers("points", &points)?;
    let params = ParamArg::read(&params)?;
    let dim = whole("dim", dim)?;
    let degree = whole("degree", degree)?;
    let count = whole("count", count)?;
    Ok(match check_dim(dim)? {
        2 => JsBSplineCurve::from_2d(approximate::<DVec2>(
            points, degree, count, &params, &options,
        )?),
        _ => JsBSplineCurve::from_3d(approximate::<DVec3>(
            points, degree, count, &params, &options,
        )?),
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

fn system<C: Cartesian>(
    points: &[f64],
    degree: usize,
    params: &ParamArg,
    options: &RawOptions,
) -> Result<SystemJs, Error> {
    let (points, params, options) = prepare::<C>(points, degree, params, options)?;
    let s: InterpolationSystem<C> =
        interp::interpolation_system(&points, degree, &params, &options)?;
    let flat = |v: &[C]| super::super::bezier::flatten_points(v);
    Ok(SystemJs {
        size: s.size,
        matrix: s.matrix,
        rhs: flat(&s.rhs),
        solution: flat(&s.solution),
        knots: s.knots,
        rows: s.rows.iter().map(|r| r.as_str()).collect(),
    })
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
) -> Result<JsValue, JsError> {
    let options = RawOptions::read(&options, INTERPOLATION_OPTIONS)?;
    let points = &*numbers("points", &points)?;
    let params = ParamArg::read(&params)?;
    let dim = whole("dim", dim)?;
    let degree = whole("degree", degree)?;
    let s = match check_dim(dim)? {
        2 => system::<DVec2>(points, degree, &params, &options)?,
        _ => system::<DVec3>(points, degree, &params, &options)?,
    };
    Ok(serde_wasm_bindgen::to_value(&s)?)
}
