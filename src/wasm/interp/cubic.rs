//! The constructors of `CubicSpline`: `cubicSpline`, `hermiteSpline`, `cardinalSpline`,
//! `catmullRom`, `besselSpline`. Each reads its arguments (types first), then validates in the
//! documented order: dim, coordinate count, finite numbers, number of points, params, options.

use super::spline::{JsCubicSpline, Spline};
use super::{vector_arg, ParamArg};
use crate::error::Error;
use crate::geom::{check_dim, points_from_flat, Cartesian};
use crate::interp::{check_point_count, CubicSpline, EndCondition, ParamChoice};
use crate::wasm::ApiError;
use crate::wasm::{numbers, optional_numbers, string_arg, whole};
use glam::{DVec2, DVec3};
use wasm_bindgen::prelude::*;

/// Points, then at least 2 of them, then the parameters: the checks every constructor starts
/// with.
#[inline(never)]
fn points_and_params<C: Cartesian>(
    coords: &[f64],
    params: ParamArg,
    what: &'static str,
) -> Result<(Vec<C>, ParamChoice), Error> {
    let points: Vec<C> = points_from_flat(coords)?;
    check_point_count(points.len(), 2, what)?;
    let choice = params.choice()?;
    choice.resolve(&points)?;
    Ok((points, choice))
}

/// The 2D or 3D spline from `$build::<DVec2>(args)` or `$build::<DVec3>(args)`, after
/// validating `dim`.
macro_rules! spline_by_dim {
    ($dim:expr, $build:ident($($arg:expr),*)) => {{
        let dim = whole("dim", $dim)?;
        Ok(JsCubicSpline::wrap(match check_dim(dim)? {
            2 => Spline::D2($build::<DVec2>($($arg),*)?),
            _ => Spline::D3($build::<DVec3>($($arg),*)?),
        }))
    }};
}

fn build_cubic<C: Cartesian>(
    coords: &[f64],
    params: ParamArg,
    end: &str,
    start_tangent: Option<&[f64]>,
    end_tangent: Option<&[f64]>,
) -> Result<CubicSpline<C>, Error> {
    let (points, choice) = points_and_params::<C>(coords, params, "cubic-spline")?;
    // Parse the name before reading the tangents, so an unknown name is reported first.
    EndCondition::<C>::parse(end, Some(C::ZERO), Some(C::ZERO))?;
    let start = start_tangent
        .map(|v| vector_arg("startTangent", v))
        .transpose()?;
    let finish = end_tangent
        .map(|v| vector_arg("endTangent", v))
        .transpose()?;
    let condition = EndCondition::parse(end, start, finish)?;
    CubicSpline::interpolate(points, choice, condition)
}

/// `cubicSpline(points, dim, params, end = "natural", startTangent?, endTangent?)`: the C2
/// cubic spline through the points at `params` (strictly increasing, one per point; a kind
/// string or α number computes them). `end`: "natural" | "clamped" (needs both tangents, dim numbers each,
/// `C'(t_0)` and `C'(t_n)` w.r.t. the parameter) | "quadratic" | "bessel" | "not-a-knot" |
/// "periodic" (the last point must equal the first; at least 3 points). At least 2 points;
/// with 2, quadratic, bessel and not-a-knot give the line, with 3 not-a-knot the parabola.
#[wasm_bindgen(js_name = cubicSpline)]
pub fn cubic_spline(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[] | string | number")]
    params: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "string")] end: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "Float64Array | number[]")]
    start_tangent: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "Float64Array | number[]")] end_tangent: JsValue,
) -> Result<JsCubicSpline, ApiError> {
    let points = &*numbers("points", &points)?;
    let params = ParamArg::read(&params)?;
    let end = string_arg("end", &end, Some("natural"))?;
    let start_tangent = optional_numbers("startTangent", &start_tangent)?;
    let end_tangent = optional_numbers("endTangent", &end_tangent)?;
    let (s, e) = (start_tangent.as_deref(), end_tangent.as_deref());
    spline_by_dim!(dim, build_cubic(points, params, &end, s, e))
}

fn build_hermite<C: Cartesian>(
    coords: &[f64],
    params: ParamArg,
    tangents: &[f64],
) -> Result<CubicSpline<C>, Error> {
    let (points, choice) = points_and_params::<C>(coords, params, "hermite-spline")?;
    if tangents.len() != coords.len() {
        return Err(Error::ArgumentLength {
            name: "tangents",
            expected: coords.len(),
            got: tangents.len(),
        });
    }
    let tangents: Vec<C> = tangents.chunks_exact(C::DIM).map(C::from_slice).collect();
    CubicSpline::hermite(points, choice, tangents)
}

/// `hermiteSpline(points, dim, params, tangents)`: the C1 piecewise cubic Hermite curve with
/// the given tangents `C'(t_i)` (w.r.t. the parameter; flat, (n+1)·dim numbers). The only
/// spline whose `setTangent` works.
#[wasm_bindgen(js_name = hermiteSpline)]
pub fn hermite_spline(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[] | string | number")]
    params: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] tangents: JsValue,
) -> Result<JsCubicSpline, ApiError> {
    let points = &*numbers("points", &points)?;
    let params = ParamArg::read(&params)?;
    let tangents = &*numbers("tangents", &tangents)?;
    spline_by_dim!(dim, build_hermite(points, params, tangents))
}

fn build_cardinal<C: Cartesian>(
    coords: &[f64],
    params: ParamArg,
    tension: f64,
) -> Result<CubicSpline<C>, Error> {
    let (points, choice) = points_and_params::<C>(coords, params, "cardinal-spline")?;
    CubicSpline::cardinal(points, choice, tension)
}

/// `cardinalSpline(points, dim, params, tension = 0)`: tangents
/// `m_i = (1 − c)(p_{i+1} − p_{i−1})/(t_{i+1} − t_{i−1})` (c = 0 Catmull–Rom on these params,
/// c = 1 zero tangents); the ends reflect a phantom point, `m_0 = (1 − c)(p_1 − p_0)/Δ_0`,
/// `m_n = (1 − c)(p_n − p_{n−1})/Δ_{n−1}`.
#[wasm_bindgen(js_name = cardinalSpline)]
pub fn cardinal_spline(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[] | string | number")]
    params: JsValue,
    tension: Option<f64>,
) -> Result<JsCubicSpline, ApiError> {
    let points = &*numbers("points", &points)?;
    let params = ParamArg::read(&params)?;
    let c = tension.unwrap_or(0.0);
    spline_by_dim!(dim, build_cardinal(points, params, c))
}

fn build_catmull_rom<C: Cartesian>(
    coords: &[f64],
    alpha: f64,
    closed: bool,
) -> Result<CubicSpline<C>, Error> {
    CubicSpline::catmull_rom(points_from_flat(coords)?, alpha, closed)
}

/// `catmullRom(points, dim, alpha = 0.5, closed = false)`: params `Σ |Δp|^alpha` from 0 (0
/// uniform, 0.5 centripetal, 1 chord) and Barry–Goldman tangents
/// `m_i = (p_i − p_{i−1})/Δ_{i−1} − (p_{i+1} − p_{i−1})/(Δ_{i−1} + Δ_i) + (p_{i+1} − p_i)/Δ_i`;
/// open ends use the phantoms `2p_0 − p_1` and `2p_n − p_{n−1}`. `closed`: the points are a
/// cycle (at least 3): the spline appends the first point, so `points()` has one more point
/// than given and `pieceCount` equals the count given (a cycle that already repeats its first
/// point at the end, with more than 3 points, is taken as it is).
#[wasm_bindgen(js_name = catmullRom)]
pub fn catmull_rom(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    alpha: Option<f64>,
    closed: Option<bool>,
) -> Result<JsCubicSpline, ApiError> {
    let points = &*numbers("points", &points)?;
    let alpha = alpha.unwrap_or(0.5);
    let closed = closed.unwrap_or(false);
    spline_by_dim!(dim, build_catmull_rom(points, alpha, closed))
}

fn build_bessel<C: Cartesian>(coords: &[f64], params: ParamArg) -> Result<CubicSpline<C>, Error> {
    let (points, choice) = points_and_params::<C>(coords, params, "bessel-spline")?;
    CubicSpline::bessel(points, choice)
}

/// `besselSpline(points, dim, params)`: tangents of the parabolas through `p_{i−1}, p_i,
/// p_{i+1}` at `t_i`; at the ends those of the first and last parabola (2 points: the line).
#[wasm_bindgen(js_name = besselSpline)]
pub fn bessel_spline(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[] | string | number")]
    params: JsValue,
) -> Result<JsCubicSpline, ApiError> {
    let points = &*numbers("points", &points)?;
    let params = ParamArg::read(&params)?;
    spline_by_dim!(dim, build_bessel(points, params))
}
