//! `BSplineCurve`, `knotVector` and `parameterize` for JavaScript.

use super::bezier::{flatten_points, JsBezierCurve};
use super::{numbers, optional_numbers, string_arg, whole};
use crate::bspline::{self, BSplineCurve, KnotKind, Parameterization};
use crate::error::Error;
use crate::geom::{check_dim, points_from_flat, Cartesian};
use crate::prelude::*;
use crate::wasm::ApiError;
use glam::{DVec2, DVec3};
use serde::Serialize;
use wasm_bindgen::prelude::*;

curve_enum!(BSplineCurve);

class_curve_methods!(BSplineCurve for JsBSplineCurve over BSplineCurve, parameter u, parameters us);

/// A polynomial or rational (NURBS) B-spline curve in 2D or 3D on its domain `[u_p, u_{n+1}]`.
#[wasm_bindgen(js_name = BSplineCurve)]
#[derive(Clone)]
pub struct JsBSplineCurve {
    inner: Curve,
    /// The buffer behind the `…View` methods' results.
    view: Vec<f64>,
}

#[derive(Serialize)]
struct BasisTableJs {
    span: usize,
    levels: Vec<Vec<f64>>,
}

#[derive(Serialize)]
struct InsertionAlphasJs {
    span: usize,
    alphas: Vec<f64>,
}

#[derive(Serialize)]
struct KnotContinuityJs {
    knot: f64,
    multiplicity: usize,
    continuity: i32,
}

#[wasm_bindgen(js_class = BSplineCurve)]
impl JsBSplineCurve {
    /// `new BSplineCurve(points, dim, degree, knots, weights?)`: n + 1 points (flat), n + p + 2
    /// non-decreasing knots, optional weights (> 0) for a NURBS.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
        dim: f64,
        degree: f64,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] knots: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Float64Array | number[]")] weights: JsValue,
    ) -> Result<JsBSplineCurve, ApiError> {
        let weights = optional_numbers("weights", &weights)?;
        let points = &*numbers("points", &points)?;
        let knots = &*numbers("knots", &knots)?;
        let dim = whole("dim", dim)?;
        let degree = whole("degree", degree)?;
        let w = weights.as_deref();
        let inner = match check_dim(dim)? {
            2 => Curve::D2(BSplineCurve::from_flat(points, degree, knots.to_vec(), w)?),
            _ => Curve::D3(BSplineCurve::from_flat(points, degree, knots.to_vec(), w)?),
        };
        Ok(JsBSplineCurve::wrap(inner))
    }

    /// `BSplineCurve.closed(points, dim, degree, weights?)`: a closed curve through the cycle of
    /// points (the first p repeated at the end, uniform knots), joined with C^(p−1).
    pub fn closed(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
        dim: f64,
        degree: f64,
        #[wasm_bindgen(unchecked_optional_param_type = "Float64Array | number[]")] weights: JsValue,
    ) -> Result<JsBSplineCurve, ApiError> {
        let weights = optional_numbers("weights", &weights)?;
        let points = &*numbers("points", &points)?;
        let dim = whole("dim", dim)?;
        let degree = whole("degree", degree)?;
        let w = weights.as_deref();
        let inner = match check_dim(dim)? {
            2 => Curve::D2(BSplineCurve::closed(points_from_flat(points)?, degree, w)?),
            _ => Curve::D3(BSplineCurve::closed(points_from_flat(points)?, degree, w)?),
        };
        Ok(JsBSplineCurve::wrap(inner))
    }

    /// For a closed curve, how many trailing control points repeat the first ones (0 if open).
    #[wasm_bindgen(getter)]
    pub fn wrapped(&self) -> usize {
        with_curve!(&self.inner, c => c.wrapped())
    }

    /// The domain `[u_p, u_{n+1}]`.
    pub fn domain(&self) -> Vec<f64> {
        let (a, b) = with_curve!(&self.inner, c => c.domain());
        vec![a, b]
    }

    /// The knot vector.
    pub fn knots(&self) -> Vec<f64> {
        with_curve!(&self.inner, c => c.knots().as_slice().to_vec())
    }

    /// Indices k of the non-empty spans `[u_k, u_{k+1})` of the domain, in order.
    pub fn spans(&self) -> Vec<u32> {
        with_curve!(&self.inner, c => c.knots().spans().map(|k| k as u32).collect())
    }

    /// The span index k of u: `u_k ≤ u < u_{k+1}` with `u_k < u_{k+1}` (u at the end of the
    /// domain is in the last non-empty span); `basisNonZero(u)` holds `N_{k−p,p} … N_{k,p}`.
    pub fn span(&self, u: f64) -> Result<usize, ApiError> {
        Ok(with_curve!(&self.inner, c => c.span(u))?)
    }

    /// The derivative of the given order at every u of `us`, flat (us.length·dim numbers), in
    /// one pass: the batched form of `derivative(u, order)`.
    #[wasm_bindgen(js_name = sampleDerivatives)]
    pub fn sample_derivatives(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] us: JsValue,
        order: f64,
    ) -> Result<Vec<f64>, ApiError> {
        let us = &*numbers("us", &us)?;
        let order = whole("order", order)?;
        let len = crate::geom::result_len("sample-derivatives-result", &[us.len(), self.dim()])?;
        let mut out = vec![0.0; len];
        with_curve!(&self.inner, c => c.sample_derivatives_into(us, order, &mut out))?;
        Ok(out)
    }

    /// `N_{i,p}(u)` for i = 0..n.
    pub fn basis(&self, u: f64) -> Result<Vec<f64>, ApiError> {
        Ok(with_curve!(&self.inner, c => c.basis(u))?)
    }

    /// The p + 1 basis functions that can be non-zero at u, `N_{k−p,p}(u) … N_{k,p}(u)` with
    /// `k = span(u)`: what `basis(u)` holds at indices k − p … k, without the n − p zeros.
    #[wasm_bindgen(js_name = basisNonZero)]
    pub fn basis_non_zero(&self, u: f64) -> Result<Vec<f64>, ApiError> {
        Ok(with_curve!(&self.inner, c => c.basis_non_zero(u))?.1)
    }

    /// Every basis function at `count` equally spaced u over the domain, i-major:
    /// `N_{i,p}(u_j)` at index `i·count + j`.
    #[wasm_bindgen(js_name = basisCurves)]
    pub fn basis_curves(&self, count: f64) -> Result<Vec<f64>, ApiError> {
        let count = whole("count", count)?;
        Ok(with_curve!(&self.inner, c => c.basis_curves(count))?)
    }

    /// Derivatives of every basis function at u: row d = 0..=order holds `N^{(d)}_{i,p}(u)`,
    /// i = 0..n, rows concatenated.
    #[wasm_bindgen(js_name = basisDerivatives)]
    pub fn basis_derivatives(&self, u: f64, order: f64) -> Result<Vec<f64>, ApiError> {
        let order = whole("order", order)?;
        Ok(with_curve!(&self.inner, c => c.basis_derivatives_at(u, order))?)
    }

    /// The Cox–de Boor triangle at u: `{ span: k, levels }` where `levels[r]` holds
    /// `N_{k−r,r}(u) … N_{k,r}(u)`.
    #[wasm_bindgen(js_name = basisTable, unchecked_return_type = "{ span: number; levels: number[][] }")]
    pub fn basis_table(&self, u: f64) -> Result<JsValue, ApiError> {
        let (span, levels) = with_curve!(&self.inner, c => c.basis_table(u))?;
        Ok(serde_wasm_bindgen::to_value(&BasisTableJs {
            span,
            levels,
        })?)
    }

    /// de Boor's triangle at u: levels concatenated, the p + 1 active points first, C(u) last;
    /// (p+1)(p+2)/2 points, flat. Rational curves give projected points.
    #[wasm_bindgen(js_name = deBoor)]
    pub fn de_boor(&self, u: f64) -> Result<Vec<f64>, ApiError> {
        Ok(with_curve!(&self.inner, c => flatten_points(&c.de_boor(u)?)))
    }

    /// Every α of de Boor's triangle at u, six numbers each `[r, j, lo, hi, u_hi − u_lo, α]`:
    /// `α_j^r = (u − u_lo)/(u_hi − u_lo)` with `lo = j + k − p`, `hi = j + 1 + k − r`
    /// (k = span(u)); levels r = 1..p in order, j = r..p ascending (the order of `deBoor(u)`'s
    /// points after level 0), p(p+1)/2 alphas.
    #[wasm_bindgen(js_name = deBoorAlphas)]
    pub fn de_boor_alphas(&self, u: f64) -> Result<Vec<f64>, ApiError> {
        let (_, alphas) = with_curve!(&self.inner, c => c.de_boor_alphas(u))?;
        Ok(alphas
            .iter()
            .flat_map(|a| {
                [
                    a.level as f64,
                    a.j as f64,
                    a.lo as f64,
                    a.hi as f64,
                    a.denominator,
                    a.value,
                ]
            })
            .collect())
    }

    /// de Boor's triangle on the homogeneous points, dim + 1 numbers each.
    #[wasm_bindgen(js_name = deBoorHomogeneous)]
    pub fn de_boor_homogeneous(&self, u: f64) -> Result<Vec<f64>, ApiError> {
        Ok(with_curve!(&self.inner, c => flatten_points(&c.de_boor_homogeneous(u)?)))
    }

    /// A new curve with knot u inserted `times` times (default 1): same shape, more points.
    #[wasm_bindgen(js_name = insertKnot)]
    pub fn insert_knot(&self, u: f64, times: Option<f64>) -> Result<JsBSplineCurve, ApiError> {
        let times = times.map(|v| whole("times", v)).transpose()?;
        let times = times.unwrap_or(1);
        Ok(JsBSplineCurve::wrap(
            map_curve!(&self.inner, c => c.insert_knot(u, times)?),
        ))
    }

    /// Boehm's rule for inserting u once: `{ span: k, alphas }` with `alphas[m]` =
    /// `α_i = (u − u_i)/(u_{i+p} − u_i)` for i = k − p + 1 + m (m = 0..p−1).
    #[wasm_bindgen(js_name = insertionAlphas, unchecked_return_type = "{ span: number; alphas: number[] }")]
    pub fn insertion_alphas(&self, u: f64) -> Result<JsValue, ApiError> {
        let (span, alphas) = with_curve!(&self.inner, c => c.insertion_alphas(u))?;
        Ok(serde_wasm_bindgen::to_value(&InsertionAlphasJs {
            span,
            alphas,
        })?)
    }

    /// A new curve with every knot of `us` inserted (knot refinement).
    pub fn refine(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] us: JsValue,
    ) -> Result<JsBSplineCurve, ApiError> {
        let us = &*numbers("us", &us)?;
        Ok(JsBSplineCurve::wrap(
            map_curve!(&self.inner, c => c.refine(us)?),
        ))
    }

    /// The Bézier segments, one per non-empty span, in span order, each on t ∈ [0, 1].
    #[wasm_bindgen(js_name = toBezier)]
    pub fn to_bezier(&self) -> Result<Vec<JsBezierCurve>, ApiError> {
        Ok(match &self.inner {
            Curve::D2(c) => c
                .to_bezier()?
                .into_iter()
                .map(JsBezierCurve::from_2d)
                .collect(),
            Curve::D3(c) => c
                .to_bezier()?
                .into_iter()
                .map(JsBezierCurve::from_3d)
                .collect(),
        })
    }

    /// `[{ knot, multiplicity, continuity }]` for each distinct interior knot: C^(p − r)
    /// (continuity −1 where the curve may break).
    #[wasm_bindgen(js_name = knotContinuity, unchecked_return_type = "{ knot: number; multiplicity: number; continuity: number }[]")]
    pub fn knot_continuity(&self) -> Result<JsValue, ApiError> {
        let list: Vec<KnotContinuityJs> = with_curve!(&self.inner, c => c.knot_continuity())
            .into_iter()
            .map(|k| KnotContinuityJs {
                knot: k.knot,
                multiplicity: k.multiplicity,
                continuity: k.continuity,
            })
            .collect();
        Ok(serde_wasm_bindgen::to_value(&list)?)
    }

    /// The segment matrix of span k, row-major (p+1)×(p+1): `[x^p … 1] M [P_{k−p} … P_k]`, in
    /// the local t ∈ [0, 1] when `local` (default) or in the global u.
    #[wasm_bindgen(js_name = segmentMatrix)]
    pub fn segment_matrix(&self, k: f64, local: Option<bool>) -> Result<Vec<f64>, ApiError> {
        let k = whole("k", k)?;
        let m = with_curve!(&self.inner, c => c.segment_matrix(k, local.unwrap_or(true)))?;
        Ok(m.concat())
    }

    /// The segment of span k in matrix form at the local t ∈ [0, 1], flat: the monomials
    /// `[t^p … t 1]` (p + 1), the row `[t^p … 1] M` with M = segmentMatrix(k, true) (p + 1, the
    /// weights of P_{k−p} … P_k), then the point `[t^p … 1] M [P_{k−p} … P_k]^T` (dim).
    #[wasm_bindgen(js_name = evaluateMatrixForm)]
    pub fn evaluate_matrix_form(&self, k: f64, t: f64) -> Result<Vec<f64>, ApiError> {
        let k = whole("k", k)?;
        Ok(with_curve!(&self.inner, c => {
            let form = c.evaluate_matrix_form(k, t)?;
            let mut out = form.monomials;
            out.extend_from_slice(&form.basis);
            out.extend(flatten_points(&[form.point]));
            out
        }))
    }
}

fn flat_points<C: Cartesian>(points: &[f64]) -> Result<Vec<C>, Error> {
    points_from_flat(points)
}

/// `knotVector(points, dim, degree, kind)`: kind "uniform" | "clamped" | "chord" | "centripetal"
/// (the Greek notes' formulas in our convention, n + p + 2 knots).
#[wasm_bindgen(js_name = knotVector)]
pub fn knot_vector(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    degree: f64,
    #[wasm_bindgen(unchecked_param_type = "string")] kind: JsValue,
) -> Result<Vec<f64>, ApiError> {
    let points = &*numbers("points", &points)?;
    let kind = &*string_arg("kind", &kind, None)?;
    let dim = whole("dim", dim)?;
    let degree = whole("degree", degree)?;
    let kind = KnotKind::parse(kind)?;
    Ok(match check_dim(dim)? {
        2 => bspline::knot_vector(&flat_points::<DVec2>(points)?, degree, kind)?,
        _ => bspline::knot_vector(&flat_points::<DVec3>(points)?, degree, kind)?,
    })
}

/// `parameterize(points, dim, kind)`: cumulative parameters from 0; kind "uniform" | "chord" |
/// "centripetal" or a number α in [0, 1]: sums of `|P_{i+1} − P_i|^α` (0 uniform, 0.5
/// centripetal, 1 chord; repeated consecutive points are an error for α > 0).
#[wasm_bindgen]
pub fn parameterize(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    #[wasm_bindgen(unchecked_param_type = "string | number")] kind: JsValue,
) -> Result<Vec<f64>, ApiError> {
    let points = &*numbers("points", &points)?;
    let alpha = kind.as_f64();
    let kind = match alpha {
        Some(_) => String::new(),
        None => string_arg("kind", &kind, None)?,
    };
    let dim = whole("dim", dim)?;
    let kind = match alpha {
        Some(a) => Parameterization::from_alpha(a)?,
        None => Parameterization::parse(&kind)?,
    };
    Ok(match check_dim(dim)? {
        2 => bspline::parameterize(&flat_points::<DVec2>(points)?, kind)?,
        _ => bspline::parameterize(&flat_points::<DVec3>(points)?, kind)?,
    })
}

/// `phantomPoints(points, dim, degree)`: the points with `(p − 1)/2` reflected phantom points at
/// each end, so a uniform B-spline of odd degree p passes through the first and last point.
#[wasm_bindgen(js_name = phantomPoints)]
pub fn phantom_points(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    degree: f64,
) -> Result<Vec<f64>, ApiError> {
    let points = &*numbers("points", &points)?;
    let dim = whole("dim", dim)?;
    let degree = whole("degree", degree)?;
    Ok(match check_dim(dim)? {
        2 => flatten_points(&bspline::phantom_points(
            &flat_points::<DVec2>(points)?,
            degree,
        )?),
        _ => flatten_points(&bspline::phantom_points(
            &flat_points::<DVec3>(points)?,
            degree,
        )?),
    })
}

/// `uniformSegmentMatrix(p)`: the matrix of every interior segment of a uniform B-spline of
/// degree p (row-major, (p+1)², highest power first), e.g. 1/6·[[−1,3,−3,1],…] for p = 3.
#[wasm_bindgen(js_name = uniformSegmentMatrix)]
pub fn uniform_segment_matrix(p: f64) -> Result<Vec<f64>, ApiError> {
    let p = whole("p", p)?;
    if p == 0 || p > crate::geom::MAX_DEGREE {
        return Err(Error::DegreeOutOfRange {
            degree: p,
            max: crate::geom::MAX_DEGREE,
        }
        .into());
    }
    Ok(bspline::uniform_segment_matrix(p).concat())
}
