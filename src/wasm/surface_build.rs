//! `revolve`, `extrude`, `ruled` and `interpolateSurface` for JavaScript: surfaces built from
//! curves or from a grid of points.

use super::surface::JsBSplineSurface;
use super::{numbers, object_of, string_arg, whole};
use crate::bspline::{BSplineCurve, Parameterization};
use crate::error::Error;
use crate::geom::points_from_flat;
use crate::surface;
use crate::wasm::ApiError;
use glam::DVec3;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

#[wasm_bindgen]
extern "C" {
    /// A `BSplineCurve` or `BezierCurve` object, read through its public methods (a wasm-bindgen
    /// class cannot be borrowed from a `JsValue` without taking it from its owner).
    type CurveObject;

    #[wasm_bindgen(method, structural, catch, getter)]
    fn dim(this: &CurveObject) -> Result<f64, JsValue>;

    #[wasm_bindgen(method, structural, catch, getter)]
    fn degree(this: &CurveObject) -> Result<f64, JsValue>;

    #[wasm_bindgen(method, structural, catch, js_name = controlPoints)]
    fn control_points(this: &CurveObject) -> Result<Vec<f64>, JsValue>;

    #[wasm_bindgen(method, structural, catch)]
    fn weights(this: &CurveObject) -> Result<Vec<f64>, JsValue>;

    #[wasm_bindgen(method, structural, catch)]
    fn domain(this: &CurveObject) -> Result<Vec<f64>, JsValue>;

    #[wasm_bindgen(method, structural, catch)]
    fn knots(this: &CurveObject) -> Result<Vec<f64>, JsValue>;
}

/// What a curve argument must be.
const CURVE: &str = "curve";

/// The curve argument `name` as a core 3D B-spline: a `BSplineCurve` as it is, a
/// `BezierCurve` on `[a, b]` with knots `a…a b…b` (n + 1 of each). Errors: not one of the two
/// classes (or freed), then [`Error::Needs3D`] for a 2D curve (naming `operation`).
fn curve_arg(
    name: &'static str,
    operation: &'static str,
    value: &JsValue,
) -> Result<BSplineCurve<DVec3>, ApiError> {
    let class = js_sys::Reflect::get(value, &JsValue::from_str("constructor"))
        .and_then(|c| js_sys::Reflect::get(&c, &JsValue::from_str("name")))
        .ok()
        .and_then(|n| n.as_string())
        .filter(|_| value.is_object());
    let is_bspline = match class.as_deref() {
        Some("BSplineCurve") => true,
        Some("BezierCurve") => false,
        _ => return Err(not_a_curve(name, value)),
    };
    let curve: &CurveObject = value.unchecked_ref();
    let read = |_| not_a_curve(name, value);
    let dim = whole("dim", curve.dim().map_err(read)?)?;
    if dim != 3 {
        return Err(Error::InArgument {
            name,
            index: None,
            source: Box::new(Error::Needs3D { operation, dim }),
        }
        .into());
    }
    let degree = whole("degree", curve.degree().map_err(read)?)?;
    let points = points_from_flat::<DVec3>(&curve.control_points().map_err(read)?)?;
    let weights = curve.weights().map_err(read)?;
    let knots = if is_bspline {
        curve.knots().map_err(read)?
    } else {
        let domain = curve.domain().map_err(read)?;
        let (a, b) = (domain.first().copied(), domain.get(1).copied());
        let (a, b) = a.zip(b).ok_or_else(|| not_a_curve(name, value))?;
        let n = points.len();
        (0..2 * n).map(|i| if i < n { a } else { b }).collect()
    };
    let rational = weights.iter().any(|&w| w != 1.0);
    let c = BSplineCurve::new(points, degree, knots, rational.then_some(&weights[..]))?;
    Ok(c)
}

/// The error for a curve argument that is neither class (or a freed one).
fn not_a_curve(name: &'static str, value: &JsValue) -> ApiError {
    let got = if value.is_null() {
        "null".into()
    } else {
        value.js_typeof().as_string().unwrap_or_default()
    };
    Error::ArgumentType {
        name,
        expected: CURVE,
        got,
    }
    .into()
}

/// A 3-number vector argument.
fn vector_arg(name: &'static str, value: &JsValue) -> Result<DVec3, ApiError> {
    let v = numbers(name, value)?;
    match v.as_slice() {
        &[x, y, z] => Ok(DVec3::new(x, y, z)),
        _ => Err(Error::ArgumentLength {
            name,
            expected: 3,
            got: v.len(),
        }
        .into()),
    }
}

/// `revolve(profile, axisPoint, axisDirection, angle = 2π)`: the exact NURBS surface swept by
/// a 3D `BSplineCurve` or `BezierCurve` turning about the axis (counter-clockwise seen from the
/// tip of the direction). u runs around the axis on [0, 1] (degree 2, 1 arc up to 90°, 2 up to
/// 180°, 3 up to 270°, else 4), v along the profile (its degree and knots). A circle profile
/// gives a torus exactly.
#[wasm_bindgen]
pub fn revolve(
    #[wasm_bindgen(unchecked_param_type = "BSplineCurve | BezierCurve")] profile: JsValue,
    #[wasm_bindgen(js_name = axisPoint, unchecked_param_type = "Float64Array | number[]")]
    axis_point: JsValue,
    #[wasm_bindgen(js_name = axisDirection, unchecked_param_type = "Float64Array | number[]")]
    axis_direction: JsValue,
    angle: Option<f64>,
) -> Result<JsBSplineSurface, ApiError> {
    let profile = curve_arg("profile", "revolve", &profile)?;
    let axis_point = vector_arg("axisPoint", &axis_point)?;
    let axis_direction = vector_arg("axisDirection", &axis_direction)?;
    let angle = angle.unwrap_or(std::f64::consts::TAU);
    Ok(JsBSplineSurface::wrap(surface::revolve(
        &profile,
        axis_point,
        axis_direction,
        angle,
    )?))
}

/// `extrude(curve, direction)`: S(u, v) = C(u) + v·direction, u along the curve (its degree
/// and knots), v in [0, 1] (degree 1).
#[wasm_bindgen]
pub fn extrude(
    #[wasm_bindgen(unchecked_param_type = "BSplineCurve | BezierCurve")] curve: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] direction: JsValue,
) -> Result<JsBSplineSurface, ApiError> {
    let curve = curve_arg("curve", "extrude", &curve)?;
    let direction = vector_arg("direction", &direction)?;
    Ok(JsBSplineSurface::wrap(surface::extrude(&curve, direction)?))
}

/// `ruled(curveA, curveB)`: S(u, v) = (1 − v) A(u) + v B(u) on [0, 1]², after making the
/// curves compatible (both clamped onto [0, 1], the lower degree raised, knots merged).
#[wasm_bindgen]
pub fn ruled(
    #[wasm_bindgen(js_name = curveA, unchecked_param_type = "BSplineCurve | BezierCurve")]
    curve_a: JsValue,
    #[wasm_bindgen(js_name = curveB, unchecked_param_type = "BSplineCurve | BezierCurve")]
    curve_b: JsValue,
) -> Result<JsBSplineSurface, ApiError> {
    let a = curve_arg("curveA", "ruled", &curve_a)?;
    let b = curve_arg("curveB", "ruled", &curve_b)?;
    Ok(JsBSplineSurface::wrap(surface::ruled(&a, &b)?))
}

/// `interpolateSurface(points, rows, cols, degreeU, degreeV, kind = "chord")`: the B-spline
/// surface on [0, 1]² through every point of the grid (flat xyz, row-major, rows along u),
/// parameters by `kind` ("uniform" | "chord" | "centripetal") averaged over the columns (u)
/// and rows (v), averaging knots; columns interpolated in u, then the rows in v.
#[wasm_bindgen(js_name = interpolateSurface)]
pub fn interpolate_surface(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    rows: f64,
    cols: f64,
    #[wasm_bindgen(js_name = degreeU)] degree_u: f64,
    #[wasm_bindgen(js_name = degreeV)] degree_v: f64,
    #[wasm_bindgen(unchecked_optional_param_type = "\"uniform\" | \"chord\" | \"centripetal\"")]
    kind: JsValue,
) -> Result<JsBSplineSurface, ApiError> {
    let points = numbers("points", &points)?;
    let (rows, cols) = (whole("rows", rows)?, whole("cols", cols)?);
    let (degree_u, degree_v) = (whole("degreeU", degree_u)?, whole("degreeV", degree_v)?);
    // The grid's errors come before the option's (the documented validation order).
    surface::construct::check_grid(&points, rows, cols, degree_u, degree_v)?;
    let kind = Parameterization::parse(&string_arg("kind", &kind, Some("chord"))?)?;
    Ok(JsBSplineSurface::wrap(surface::interpolate_surface(
        &points, rows, cols, degree_u, degree_v, kind,
    )?))
}

/// `interpolateSurfaceParams(points, rows, cols, kind = "chord")` → `{ u: Float64Array, v:
/// Float64Array }`: the parameters `interpolateSurface` gives the grid (rows along u), so that
/// `S(u[k], v[l])` is point `(k, l)` — per column the cumulative `|Δ|^α` steps over their
/// total, averaged over the columns (rows for v).
#[wasm_bindgen(
    js_name = interpolateSurfaceParams,
    unchecked_return_type = "{ u: Float64Array; v: Float64Array }"
)]
pub fn interpolate_surface_params(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    rows: f64,
    cols: f64,
    #[wasm_bindgen(unchecked_optional_param_type = "\"uniform\" | \"chord\" | \"centripetal\"")]
    kind: JsValue,
) -> Result<JsValue, ApiError> {
    let points = numbers("points", &points)?;
    let (rows, cols) = (whole("rows", rows)?, whole("cols", cols)?);
    let kind = Parameterization::parse(&string_arg("kind", &kind, Some("chord"))?)?;
    let (u, v) = surface::grid_params(&points, rows, cols, kind)?;
    object_of(&[("u", &u), ("v", &v)])
}
