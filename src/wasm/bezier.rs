//! `BezierCurve` for JavaScript (and `arcLengths`); the Bernstein helpers are in `basis`, the
//! composite curve and the joint helpers in `composite`.

mod basis;
mod composite;

pub use basis::{bernstein, bernstein_basis};
pub use composite::{join_bezier, joint_continuity, JsCompositeBezier};

use super::{numbers, optional_numbers, whole};
use crate::bezier::{self, BezierCurve};
use crate::error::{check_finite, Error};
use crate::geom::{check_dim, Cartesian, Point};
use crate::prelude::*;
use crate::wasm::ApiError;
use glam::{DVec2, DVec3};
use wasm_bindgen::prelude::*;

curve_enum!(BezierCurve);

class_curve_methods!(BezierCurve for JsBezierCurve over BezierCurve, parameter t, parameters ts);

/// Points as one flat array of `P::DIM` numbers each.
pub(crate) fn flatten_points<P: Point>(points: &[P]) -> Vec<f64> {
    let mut out = vec![0.0; points.len() * P::DIM];
    for (p, o) in points.iter().zip(out.chunks_exact_mut(P::DIM)) {
        p.write_to(o);
    }
    out
}

pub(crate) fn point_from<C: Cartesian>(coords: &[f64]) -> Result<C, Error> {
    if coords.len() != C::DIM {
        return Err(Error::PointDimension {
            expected: C::DIM,
            got: coords.len(),
        });
    }
    Ok(C::from_slice(coords))
}

fn build(points: &[f64], dim: usize, weights: Option<&[f64]>) -> Result<Curve, Error> {
    Ok(match check_dim(dim)? {
        2 => Curve::D2(BezierCurve::from_flat(points, weights)?),
        _ => Curve::D3(BezierCurve::from_flat(points, weights)?),
    })
}

#[cfg(feature = "typed-curves")]
impl JsBezierCurve {
    /// A typed polynomial piece's Bézier form (`ParametricCurve.toBezier(i)`).
    pub(crate) fn from_parametric(
        form: &crate::parametric::BezierForm,
        dim: usize,
    ) -> Result<JsBezierCurve, Error> {
        let inner = match dim {
            2 => Curve::D2(form.curve_2d()?),
            _ => Curve::D3(form.curve_3d()?),
        };
        Ok(JsBezierCurve::wrap(inner))
    }
}

/// A polynomial or rational Bézier curve in 2D or 3D (see the README for the conventions).
#[wasm_bindgen(js_name = BezierCurve)]
#[derive(Clone)]
pub struct JsBezierCurve {
    inner: Curve,
    /// The buffer behind the `…View` methods' results.
    view: Vec<f64>,
}

#[wasm_bindgen(js_class = BezierCurve)]
impl JsBezierCurve {
    /// `new BezierCurve(points, dim, weights?)`: flat coordinates `[x0, y0, (z0,) x1, …]`,
    /// `dim` 2 or 3, optional weights (> 0, one per point) for a rational curve, on t ∈ [0, 1].
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
        dim: f64,
        #[wasm_bindgen(unchecked_optional_param_type = "Float64Array | number[]")] weights: JsValue,
    ) -> Result<JsBezierCurve, ApiError> {
        let weights = optional_numbers("weights", &weights)?;
        let points = &*numbers("points", &points)?;
        let dim = whole("dim", dim)?;
        Ok(JsBezierCurve::wrap(build(points, dim, weights.as_deref())?))
    }

    /// `BezierCurve.withInterval(points, dim, a, b, weights?)`: the curve on t ∈ [a, b].
    #[wasm_bindgen(js_name = withInterval)]
    pub fn with_interval(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
        dim: f64,
        a: f64,
        b: f64,
        #[wasm_bindgen(unchecked_optional_param_type = "Float64Array | number[]")] weights: JsValue,
    ) -> Result<JsBezierCurve, ApiError> {
        let weights = optional_numbers("weights", &weights)?;
        let points = &*numbers("points", &points)?;
        let dim = whole("dim", dim)?;
        let curve = build(points, dim, weights.as_deref())?;
        let inner = match curve {
            Curve::D2(c) => Curve::D2(c.with_interval(a, b)?),
            Curve::D3(c) => Curve::D3(c.with_interval(a, b)?),
        };
        Ok(JsBezierCurve::wrap(inner))
    }

    /// `BezierCurve.fromPolynomial(coefficients, dim, a, b)`: the curve on [a, b] equal to
    /// `Σ c_k t^k`; `coefficients` holds `c_0, c_1, …` as flat points of `dim` coordinates.
    #[wasm_bindgen(js_name = fromPolynomial)]
    pub fn from_polynomial(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] coefficients: JsValue,
        dim: f64,
        a: f64,
        b: f64,
    ) -> Result<JsBezierCurve, ApiError> {
        let coefficients = &*numbers("coefficients", &coefficients)?;
        let dim = whole("dim", dim)?;
        let inner = match check_dim(dim)? {
            2 => Curve::D2(bezier::from_polynomial(
                &crate::geom::points_from_flat::<DVec2>(coefficients)?,
                a,
                b,
            )?),
            _ => Curve::D3(bezier::from_polynomial(
                &crate::geom::points_from_flat::<DVec3>(coefficients)?,
                a,
                b,
            )?),
        };
        Ok(JsBezierCurve::wrap(inner))
    }

    /// The parameter interval `[a, b]` (default `[0, 1]`).
    pub fn domain(&self) -> Vec<f64> {
        let (a, b) = with_curve!(&self.inner, c => c.interval());
        vec![a, b]
    }

    /// de Casteljau's triangle at t: every level concatenated, the control points first;
    /// (n+1)(n+2)/2 points, flat. Rational curves give projected points.
    #[wasm_bindgen(js_name = deCasteljau)]
    pub fn de_casteljau(&self, t: f64) -> Result<Vec<f64>, ApiError> {
        Ok(with_curve!(&self.inner, c => flatten_points(&c.de_casteljau(t)?)))
    }

    /// The rational basis at t: `R_i(t) = w_i B_i(t) / Σ_j w_j B_j(t)` for i = 0..n, the share
    /// of each control point in P(t) (the Bernstein values for a polynomial curve).
    #[wasm_bindgen(js_name = rationalBasis)]
    pub fn rational_basis(&self, t: f64) -> Result<Vec<f64>, ApiError> {
        Ok(with_curve!(&self.inner, c => c.rational_basis(t))?)
    }

    /// de Casteljau's triangle on the homogeneous points `(w·x, w·y, (w·z,) w)`, flat with
    /// dim + 1 numbers per point.
    #[wasm_bindgen(js_name = deCasteljauHomogeneous)]
    pub fn de_casteljau_homogeneous(&self, t: f64) -> Result<Vec<f64>, ApiError> {
        Ok(with_curve!(&self.inner, c => flatten_points(&c.de_casteljau_homogeneous(t)?)))
    }

    /// `[left, right]`: the halves at t (top edge and hypotenuse of the triangle), each on [0, 1].
    pub fn split(&self, t: f64) -> Result<Vec<JsBezierCurve>, ApiError> {
        let (l, r) = match &self.inner {
            Curve::D2(c) => {
                let (l, r) = c.split(t)?;
                (Curve::D2(l), Curve::D2(r))
            }
            Curve::D3(c) => {
                let (l, r) = c.split(t)?;
                (Curve::D3(l), Curve::D3(r))
            }
        };
        Ok(vec![JsBezierCurve::wrap(l), JsBezierCurve::wrap(r)])
    }

    /// The same curve with degree n + 1.
    pub fn elevate(&self) -> Result<JsBezierCurve, ApiError> {
        Ok(JsBezierCurve::wrap(
            map_curve!(&self.inner, c => c.elevate()?),
        ))
    }

    /// The same curve traced backwards (control points reversed).
    pub fn reversed(&self) -> JsBezierCurve {
        JsBezierCurve::wrap(map_curve!(&self.inner, c => c.reversed()))
    }

    /// The hodograph P'(t): a Bézier curve of degree n − 1 (polynomial curves only).
    pub fn hodograph(&self) -> Result<JsBezierCurve, ApiError> {
        Ok(JsBezierCurve::wrap(
            map_curve!(&self.inner, c => c.hodograph()?),
        ))
    }

    /// Polyline vertices (flat, both ends included) within `tolerance` of the curve.
    pub fn flatten(&self, tolerance: f64) -> Result<Vec<f64>, ApiError> {
        Ok(with_curve!(&self.inner, c => flatten_points(&c.flatten(tolerance)?)))
    }

    /// Sorted t where the curve meets the infinite line through (x0, y0) and (x1, y1) (2D).
    #[wasm_bindgen(js_name = intersectLine)]
    pub fn intersect_line(
        &self,
        x0: f64,
        y0: f64,
        x1: f64,
        y1: f64,
        tolerance: f64,
    ) -> Result<Vec<f64>, ApiError> {
        Ok(self
            .curve_2d("intersectLine")?
            .intersect_line(DVec2::new(x0, y0), DVec2::new(x1, y1), tolerance)?
            .ts)
    }

    /// The boxes visited by `intersectLine`, 6 numbers each: depth, minX, minY, maxX, maxY,
    /// hit (1 when the line meets the box, 0 when the box was pruned).
    #[wasm_bindgen(js_name = intersectLineBoxes)]
    pub fn intersect_line_boxes(
        &self,
        x0: f64,
        y0: f64,
        x1: f64,
        y1: f64,
        tolerance: f64,
    ) -> Result<Vec<f64>, ApiError> {
        let result = self.curve_2d("intersectLineBoxes")?.intersect_line(
            DVec2::new(x0, y0),
            DVec2::new(x1, y1),
            tolerance,
        )?;
        Ok(result
            .boxes
            .iter()
            .flat_map(|b| {
                [
                    b.depth as f64,
                    b.bounds.min.x,
                    b.bounds.min.y,
                    b.bounds.max.x,
                    b.bounds.max.y,
                    if b.hit { 1.0 } else { 0.0 },
                ]
            })
            .collect())
    }

    /// How many times the line through (x0, y0), (x1, y1) crosses the control polygon (2D).
    #[wasm_bindgen(js_name = polygonLineCrossings)]
    pub fn polygon_line_crossings(
        &self,
        x0: f64,
        y0: f64,
        x1: f64,
        y1: f64,
    ) -> Result<usize, ApiError> {
        for (name, v) in [("x0", x0), ("y0", y0), ("x1", x1), ("y1", y1)] {
            check_finite(name, None, v)?;
        }
        Ok(self
            .curve_2d("polygonLineCrossings")?
            .polygon_line_crossings(DVec2::new(x0, y0), DVec2::new(x1, y1)))
    }

    /// Arc length; `accuracy` (absolute) defaults to 1e-13 × the control polygon's length.
    #[wasm_bindgen(js_name = arcLength)]
    pub fn arc_length(&self, accuracy: Option<f64>) -> Result<f64, ApiError> {
        Ok(with_curve!(&self.inner, c => c.arc_length(accuracy))?)
    }

    /// The tight bounding box of the curve: `[minX, minY, (minZ,) maxX, maxY, (maxZ)]`.
    #[wasm_bindgen(js_name = boundingBox)]
    pub fn bounding_box(&self) -> Vec<f64> {
        with_curve!(&self.inner, c => {
            let b = c.bounding_box();
            flatten_points(&[b.min, b.max])
        })
    }
}

/// `arcLengths(points, dim, degree, accuracy?)`: the arc lengths of many Bézier curves of one
/// degree given back to back (`(degree + 1)·dim` numbers each), in one call. 2D curves of degree
/// ≤ 3 use singularity-aware Gauss–Legendre (relative error ≤ 1e-13), straight from the numbers.
#[wasm_bindgen(js_name = arcLengths)]
pub fn arc_lengths(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    degree: f64,
    accuracy: Option<f64>,
) -> Result<Vec<f64>, ApiError> {
    let points = &*numbers("points", &points)?;
    let dim = whole("dim", dim)?;
    let degree = whole("degree", degree)?;
    Ok(match check_dim(dim)? {
        2 => bezier::arc_lengths::<DVec2>(points, degree, accuracy)?,
        _ => bezier::arc_lengths::<DVec3>(points, degree, accuracy)?,
    })
}
