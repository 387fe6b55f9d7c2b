//! Sketching (syllabus 7) for JavaScript: `fitCurve`, `fitBSpline`, `oversketch`, and their
//! `…Report` forms that also return the fit's decisions (corners, breaks, measured errors).

use super::bezier::JsCompositeBezier;
use super::{bool_option, js_object, numbers, option_entries, set_key, whole, JsBSplineCurve};
use crate::bezier::{BezierCurve, CompositeCurve};
use crate::bspline::BSplineCurve;
use crate::curve::ControlPolygon;
use crate::error::Error;
use crate::fit::{self, FitOptions, FitReport, Smoothness};
use crate::geom::{check_dim, points_from_flat, Cartesian};
use crate::wasm::ApiError;
use glam::{DVec2, DVec3};
use js_sys::{Array, Float64Array, Object, Uint32Array};
use wasm_bindgen::prelude::*;

/// The option names of `fitCurve` and their list as the message shows it.
const CURVE_OPTIONS: (&[&str], &str) = (
    &["closed", "continuity", "corners"],
    "\"closed\", \"continuity\", \"corners\"",
);

/// The option names of `fitBSpline`.
const BSPLINE_OPTIONS: (&[&str], &str) = (&["closed"], "\"closed\"");

/// `{ closed?, continuity?: "G1" | "C1", corners? = true }`.
fn curve_options(options: &JsValue) -> Result<FitOptions, ApiError> {
    let mut out = FitOptions::default();
    for (key, value) in option_entries(options, CURVE_OPTIONS)? {
        match key.as_str() {
            "closed" => out.closed = bool_option("closed", &value)?,
            "corners" => out.corners = bool_option("corners", &value)?.unwrap_or(true),
            _ => {
                out.smoothness = match super::string_arg("continuity", &value, Some("G1"))?.as_str()
                {
                    "G1" => Smoothness::G1,
                    "C1" => Smoothness::C1,
                    other => {
                        return Err(Error::UnknownOption {
                            name: "continuity",
                            value: other.into(),
                            expected: "\"G1\", \"C1\"",
                        }
                        .into())
                    }
                }
            }
        }
    }
    Ok(out)
}

/// The composite fit and its report, in the stroke's dimension.
fn fit_any(
    points: &JsValue,
    dim: f64,
    tolerance: f64,
    options: &JsValue,
) -> Result<(JsCompositeBezier, FitReport), ApiError> {
    let coords = numbers("points", points)?;
    let dim = check_dim(whole("dim", dim)?)?;
    let options = curve_options(options)?;
    let fit = fit::fit_curve(&stroke_3d(&coords, dim)?, tolerance, &options)?;
    Ok(if dim == 2 {
        (
            JsCompositeBezier::from_2d(composite_2d(&fit.curve)?),
            fit.report,
        )
    } else {
        (JsCompositeBezier::from_3d(fit.curve), fit.report)
    })
}

/// `fitCurve(points, dim, tolerance, options?)`: cubic Bézier pieces with every sample within
/// `tolerance` of the curve (measured), as few pieces as the global search finds; corners are
/// G0 joints, every other joint G1 (or C1). Piece `i` lives on `[i, i + 1]`.
#[wasm_bindgen(js_name = fitCurve)]
pub fn fit_curve(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    tolerance: f64,
    #[wasm_bindgen(
        unchecked_optional_param_type = "{ closed?: boolean; continuity?: \"G1\" | \"C1\"; corners?: boolean }"
    )]
    options: JsValue,
) -> Result<JsCompositeBezier, ApiError> {
    Ok(fit_any(&points, dim, tolerance, &options)?.0)
}

/// `fitCurveReport(points, dim, tolerance, options?)`: as `fitCurve`, with the decisions:
/// `{ curve, corners: [{ index, angle, straw }], breaks: Uint32Array (sample indices of the
/// joints), pieces: [{ first, last, maxError, worst }], closed }`.
#[wasm_bindgen(
    js_name = fitCurveReport,
    unchecked_return_type = "{ curve: CompositeBezier; corners: { index: number; angle: number; straw: number }[]; breaks: Uint32Array; pieces: { first: number; last: number; maxError: number; worst: number }[]; closed: boolean }"
)]
pub fn fit_curve_report(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    tolerance: f64,
    #[wasm_bindgen(
        unchecked_optional_param_type = "{ closed?: boolean; continuity?: \"G1\" | \"C1\"; corners?: boolean }"
    )]
    options: JsValue,
) -> Result<JsValue, ApiError> {
    let (curve, report) = fit_any(&points, dim, tolerance, &options)?;
    let out = Object::new();
    set_key(&out, "curve", &curve.into());
    let corners: Array = report
        .corners
        .iter()
        .map(|c| {
            js_object(&[
                ("index", c.index as f64),
                ("angle", c.angle),
                ("straw", c.straw),
            ])
        })
        .collect();
    set_key(&out, "corners", &corners);
    let breaks: Vec<u32> = report.breaks.iter().map(|&b| b as u32).collect();
    set_key(&out, "breaks", &Uint32Array::from(&breaks[..]));
    let pieces: Array = report
        .pieces
        .iter()
        .map(|p| {
            js_object(&[
                ("first", p.first as f64),
                ("last", p.last as f64),
                ("maxError", p.max_error),
                ("worst", p.worst as f64),
            ])
        })
        .collect();
    set_key(&out, "pieces", &pieces);
    set_key(&out, "closed", &report.closed.into());
    Ok(out.into())
}

/// The B-spline fit in the stroke's dimension: the curve, max error, worst sample, closed.
fn fit_bspline_any(
    points: &JsValue,
    dim: f64,
    degree: f64,
    tolerance: f64,
    options: &JsValue,
) -> Result<(JsBSplineCurve, f64, usize, bool), ApiError> {
    let coords = numbers("points", points)?;
    let dim = check_dim(whole("dim", dim)?)?;
    let degree = whole("degree", degree)?;
    let mut closed = None;
    for (_, value) in option_entries(options, BSPLINE_OPTIONS)? {
        closed = bool_option("closed", &value)?;
    }
    let fit = fit::fit_bspline(&stroke_3d(&coords, dim)?, degree, tolerance, closed)?;
    let curve = if dim == 2 {
        let c = &fit.curve;
        let points = c.control_points().iter().map(|p| p.truncate()).collect();
        let knots = c.knots().as_slice().to_vec();
        let flat = BSplineCurve::new(points, c.degree(), knots, None)?.with_wrapped(c.wrapped());
        JsBSplineCurve::from_2d(flat)
    } else {
        JsBSplineCurve::from_3d(fit.curve)
    };
    Ok((curve, fit.max_error, fit.worst, fit.closed))
}

/// `fitBSpline(points, dim, degree, tolerance, options?)`: the B-spline of degree `degree`
/// with the fewest control points that keeps every sample within `tolerance` (clamped, or
/// periodic when `closed`).
#[wasm_bindgen(js_name = fitBSpline)]
pub fn fit_bspline(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    degree: f64,
    tolerance: f64,
    #[wasm_bindgen(unchecked_optional_param_type = "{ closed?: boolean }")] options: JsValue,
) -> Result<JsBSplineCurve, ApiError> {
    Ok(fit_bspline_any(&points, dim, degree, tolerance, &options)?.0)
}

/// `fitBSplineReport(points, dim, degree, tolerance, options?)`: as `fitBSpline`, with
/// `{ curve, maxError, worst, closed }`.
#[wasm_bindgen(
    js_name = fitBSplineReport,
    unchecked_return_type = "{ curve: BSplineCurve; maxError: number; worst: number; closed: boolean }"
)]
pub fn fit_bspline_report(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    degree: f64,
    tolerance: f64,
    #[wasm_bindgen(unchecked_optional_param_type = "{ closed?: boolean }")] options: JsValue,
) -> Result<JsValue, ApiError> {
    let (curve, max_error, worst, closed) =
        fit_bspline_any(&points, dim, degree, tolerance, &options)?;
    let out = js_object(&[("maxError", max_error), ("worst", worst as f64)]);
    set_key(&out, "curve", &curve.into());
    set_key(&out, "closed", &closed.into());
    Ok(out.into())
}

/// The oversketched curve, the old curve's replaced parameters `(t0, t1)` and the new pieces
/// `[first, end)`.
type OversketchParts = (JsCompositeBezier, (f64, f64), (usize, usize));

/// The oversketch in the curve's dimension.
fn oversketch_any(
    curve: &JsCompositeBezier,
    stroke: &JsValue,
    dim: f64,
    tolerance: f64,
) -> Result<OversketchParts, ApiError> {
    let coords = numbers("stroke", stroke)?;
    let dim = check_dim(whole("dim", dim)?)?;
    if dim != curve.dim() {
        return Err(Error::DimensionMismatch {
            left: curve.dim(),
            right: dim,
        }
        .into());
    }
    let lifted;
    let old = match (curve.as_2d(), curve.as_3d()) {
        (Some(c), _) => {
            lifted = composite_3d(c)?;
            &lifted
        }
        (_, Some(c)) => c,
        _ => return Err(ApiError::new("oversketch: the curve is neither 2D nor 3D")),
    };
    let o = fit::oversketch(old, &stroke_3d(&coords, dim)?, tolerance)?;
    let curve = if dim == 2 {
        JsCompositeBezier::from_2d(composite_2d(&o.curve)?)
    } else {
        JsCompositeBezier::from_3d(o.curve)
    };
    Ok((curve, o.replaced, o.new_pieces))
}

// The fitters run in 3D only: a 2D stroke (or curve) is lifted to z = 0 and the result
// projected back. Every sum then only gains exact zeros, so a 2D fit gives the numbers a 2D
// instantiation would, and the wasm holds one copy of the fitting code instead of two.

/// The stroke's samples as 3D points (`z = 0` when `dim` is 2).
fn stroke_3d(coords: &[f64], dim: usize) -> Result<Vec<DVec3>, Error> {
    Ok(if dim == 2 {
        points_from_flat::<DVec2>(coords)?
            .into_iter()
            .map(|p| p.extend(0.0))
            .collect()
    } else {
        points_from_flat::<DVec3>(coords)?
    })
}

/// A composite curve through `f` on every control point, weights and breakpoints kept.
fn map_composite<A: Cartesian, B: Cartesian>(
    curve: &CompositeCurve<A>,
    f: impl Fn(A) -> B,
) -> Result<CompositeCurve<B>, Error> {
    let mut breaks = vec![curve.domain().0];
    let mut pieces = Vec::with_capacity(curve.pieces().len());
    for piece in curve.pieces() {
        let points = piece.control_points().into_iter().map(&f).collect();
        let weights = piece.is_rational().then(|| piece.weights());
        pieces.push(BezierCurve::new(points, weights.as_deref())?);
        breaks.push(piece.interval().1);
    }
    CompositeCurve::new(pieces, &breaks)
}

/// A 2D curve in the plane `z = 0`.
fn composite_3d(curve: &CompositeCurve<DVec2>) -> Result<CompositeCurve<DVec3>, Error> {
    map_composite(curve, |p| p.extend(0.0))
}

/// A curve of the plane `z = 0` as 2D.
fn composite_2d(curve: &CompositeCurve<DVec3>) -> Result<CompositeCurve<DVec2>, Error> {
    map_composite(curve, |p| p.truncate())
}

/// `oversketch(curve, stroke, dim, tolerance)`: `curve` (a `CompositeBezier`) with the part
/// between where `stroke` starts and ends near it replaced by the stroke's fit, joined with G1
/// seams; nothing outside the replaced part moves.
#[wasm_bindgen]
pub fn oversketch(
    curve: &JsCompositeBezier,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] stroke: JsValue,
    dim: f64,
    tolerance: f64,
) -> Result<JsCompositeBezier, ApiError> {
    Ok(oversketch_any(curve, &stroke, dim, tolerance)?.0)
}

/// `oversketchReport(curve, stroke, dim, tolerance)`: as `oversketch`, with
/// `{ curve, replaced: Float64Array [t0, t1] (the old curve's parameters), newPieces:
/// Uint32Array [first, end) }`.
#[wasm_bindgen(
    js_name = oversketchReport,
    unchecked_return_type = "{ curve: CompositeBezier; replaced: Float64Array; newPieces: Uint32Array }"
)]
pub fn oversketch_report(
    curve: &JsCompositeBezier,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] stroke: JsValue,
    dim: f64,
    tolerance: f64,
) -> Result<JsValue, ApiError> {
    let (curve, (t0, t1), (a, b)) = oversketch_any(curve, &stroke, dim, tolerance)?;
    let out = Object::new();
    set_key(&out, "curve", &curve.into());
    set_key(&out, "replaced", &Float64Array::from(&[t0, t1][..]));
    set_key(
        &out,
        "newPieces",
        &Uint32Array::from(&[a as u32, b as u32][..]),
    );
    Ok(out.into())
}
