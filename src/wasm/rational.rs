//! Conics, circles, ellipses and projective maps for JavaScript.

use super::bezier::flatten_points;
use super::bezier::JsBezierCurve;
use super::bspline::JsBSplineCurve;
use super::{numbers, object_of, whole};
use crate::bspline::BSplineCurve;
use crate::error::ConicError;
use crate::error::Error;
use crate::geom::{check_dim, points_from_flat, Cartesian};
use crate::rational;
use crate::wasm::ApiError;
use glam::{DMat3, DVec2, DVec3};
use wasm_bindgen::prelude::*;

/// `circle(cx, cy, r)`: the full circle as the 9-point NURBS of degree 2 (knots
/// 0,0,0,¼,¼,½,½,¾,¾,1,1,1), starting at angle 0 and running counter-clockwise.
#[wasm_bindgen]
pub fn circle(cx: f64, cy: f64, r: f64) -> Result<JsBSplineCurve, ApiError> {
    circular_arc(cx, cy, r, 0.0, std::f64::consts::TAU)
}

/// `circularArc(cx, cy, r, startAngle, sweep)`: an exact arc (radians; a negative sweep runs
/// clockwise), cut into pieces of at most 90°.
#[wasm_bindgen(js_name = circularArc)]
pub fn circular_arc(
    cx: f64,
    cy: f64,
    r: f64,
    start_angle: f64,
    sweep: f64,
) -> Result<JsBSplineCurve, ApiError> {
    let c = rational::circular_arc(DVec2::new(cx, cy), r, start_angle, sweep)?;
    Ok(JsBSplineCurve::from_2d(c))
}

/// `ellipse(cx, cy, rx, ry, rotation = 0)`: the full ellipse with semi-axes rx, ry, the first
/// axis turned by `rotation` radians, as an exact NURBS.
#[wasm_bindgen]
pub fn ellipse(
    cx: f64,
    cy: f64,
    rx: f64,
    ry: f64,
    rotation: Option<f64>,
) -> Result<JsBSplineCurve, ApiError> {
    let c = rational::ellipse(DVec2::new(cx, cy), rx, ry, rotation.unwrap_or(0.0))?;
    Ok(JsBSplineCurve::from_2d(c))
}

/// `ellipseArc(center, axisX, axisY, start, sweep)`: `center + cos θ·axisX + sin θ·axisY` for θ
/// from start to start + sweep, in 2D or 3D (the length of `center`), as an exact NURBS.
#[wasm_bindgen(js_name = ellipseArc)]
pub fn ellipse_arc(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] center: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] axis_x: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] axis_y: JsValue,
    start: f64,
    sweep: f64,
) -> Result<JsBSplineCurve, ApiError> {
    let center = &*numbers("center", &center)?;
    let axis_x = &*numbers("axisX", &axis_x)?;
    let axis_y = &*numbers("axisY", &axis_y)?;
    if axis_x.len() != center.len() || axis_y.len() != center.len() {
        return Err(Error::Conic(ConicError::AxisLengths {
            center: center.len(),
            axis_x: axis_x.len(),
            axis_y: axis_y.len(),
        })
        .into());
    }
    Ok(match crate::geom::check_dim(center.len())? {
        2 => JsBSplineCurve::from_2d(ellipse_arc_flat(center, axis_x, axis_y, start, sweep)?),
        _ => JsBSplineCurve::from_3d(ellipse_arc_flat(center, axis_x, axis_y, start, sweep)?),
    })
}

/// [`rational::ellipse_arc`] on the center and axes given flat (`C::DIM` numbers each).
// Inlined into both arms: a call here measured 100 bytes more in the optimised wasm.
#[inline(always)]
fn ellipse_arc_flat<C: Cartesian>(
    center: &[f64],
    axis_x: &[f64],
    axis_y: &[f64],
    start: f64,
    sweep: f64,
) -> Result<BSplineCurve<C>, Error> {
    rational::ellipse_arc(
        C::from_slice(center),
        C::from_slice(axis_x),
        C::from_slice(axis_y),
        start,
        sweep,
    )
}

/// `circularArcBezier(points)`: the rational quadratic Bézier of an isosceles control
/// triangle `[x0, y0, x1, y1, x2, y2]` (`|P0P1| = |P1P2|`) with weights 1, sin θ, 1 (θ half the
/// angle at P1): an exact circular arc.
#[wasm_bindgen(js_name = circularArcBezier)]
pub fn circular_arc_bezier(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
) -> Result<JsBezierCurve, ApiError> {
    let points = &*numbers("points", &points)?;
    let pts: Vec<DVec2> = crate::geom::points_from_flat(points)?;
    match pts.as_slice() {
        [p0, p1, p2] => Ok(JsBezierCurve::from_2d(rational::circle_arc_from_triangle(
            *p0, *p1, *p2,
        )?)),
        _ => Err(Error::Conic(ConicError::ArcPointCount { got: pts.len() }).into()),
    }
}

/// `conicKind(w0, w1, w2)`: "ellipse" | "parabola" | "hyperbola" for a rational quadratic with
/// these weights (by the shape factor w1²/(w0·w2) against 1).
#[wasm_bindgen(js_name = conicKind)]
pub fn conic_kind(w0: f64, w1: f64, w2: f64) -> Result<String, ApiError> {
    Ok(rational::conic_kind(w0, w1, w2)?.name().into())
}

/// A row-major 3×3 matrix from JS.
fn matrix(m: &[f64]) -> Result<DMat3, Error> {
    let rows: &[f64; 9] = m
        .try_into()
        .map_err(|_| Error::Conic(ConicError::MatrixSize { got: m.len() }))?;
    crate::geom::check_all_finite(rows, "matrix-entry")?;
    Ok(DMat3::from_cols_array(rows).transpose())
}

/// `projectiveMap(matrix)` on each JS class `$js` (Rust `$ty`): the 2D curve mapped by `$map`.
macro_rules! projective_map_method {
    ($($(#[doc = $doc:literal])* $js:ident for $ty:ident by $map:path;)*) => {$(
        #[wasm_bindgen(js_class = $js)]
        impl $ty {
            $(#[doc = $doc])*
            #[wasm_bindgen(js_name = projectiveMap)]
            pub fn projective_map(
                &self,
                #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] m: JsValue,
            ) -> Result<$ty, ApiError> {
                let m = matrix(&numbers("m", &m)?)?;
                Ok($ty::from_2d($map(self.curve_2d("projectiveMap")?, &m)?))
            }
        }
    )*};
}

projective_map_method! {
    /// `projectiveMap(matrix)`: the image under the projective map given as 9 numbers row by
    /// row, acting on homogeneous (x, y, 1) (2D curves); a rational curve with new weights.
    BezierCurve for JsBezierCurve by rational::projective_map_bezier;
    /// `projectiveMap(matrix)`: as `BezierCurve.projectiveMap`, same knots.
    BSplineCurve for JsBSplineCurve by rational::projective_map_bspline;
}

/// `rationalPoles(points, dim, weights, count)`: a TEACHING function for the negative-weights
/// demo, not a curve constructor — it accepts weights of any sign (curves refuse weights <= 0)
/// and builds no curve. For the rational Bézier `P(t) = Σ B_i w_i P_i / Σ B_i w_i` it returns
/// `{ samples, roots, directions }` (Float64Arrays): the homogeneous points `(x·w, y·w, (z·w,) w)`
/// at `count` equally spaced t in [0, 1], not divided; the t where `w(t) = Σ w_i B_i(t)` is 0,
/// ascending; and per root the unit direction (dim numbers) of `Σ B_i w_i P_i` there, along
/// which P(t) runs off to infinity (zeros when that numerator vanishes too).
#[wasm_bindgen(
    js_name = rationalPoles,
    unchecked_return_type = "{ samples: Float64Array; roots: Float64Array; directions: Float64Array }"
)]
pub fn rational_poles(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] weights: JsValue,
    count: f64,
) -> Result<JsValue, ApiError> {
    let points = &*numbers("points", &points)?;
    let weights = &*numbers("weights", &weights)?;
    let dim = whole("dim", dim)?;
    let count = whole("count", count)?;
    let (samples, roots, directions) = match check_dim(dim)? {
        2 => {
            let poles =
                rational::rational_poles::<DVec2>(&points_from_flat(points)?, weights, count)?;
            (
                flatten_points(&poles.samples),
                poles.roots,
                flatten_points(&poles.directions),
            )
        }
        _ => {
            let poles =
                rational::rational_poles::<DVec3>(&points_from_flat(points)?, weights, count)?;
            (
                flatten_points(&poles.samples),
                poles.roots,
                flatten_points(&poles.directions),
            )
        }
    };
    object_of(&[
        ("samples", &samples),
        ("roots", &roots),
        ("directions", &directions),
    ])
}
